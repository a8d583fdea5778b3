#!/bin/sh
# Prints, as a markdown table, the flash each MOTE_ENABLE_* switch of
# include/mote/mote.h saves: src/core/*.c compiled once with every feature
# and once per switch at 0, each time with the compiler and flags given
# (`make switch-sizes`: those of libmote.a for Cortex-M0+ in `make cross`),
# .text (code and read-only data) summed by size -t. Two last rows set
# several at 0 together: the three texture-layer switches (the layer code
# goes only with all three) and every switch.
# usage: switch-sizes.sh DIR CC [CFLAG...]   (objects go under DIR; flags
# without spaces)
set -eu
dir=$1; cc=$2; shift 2
cflags=$*
command -v "$cc" >/dev/null 2>&1 || {
    echo "switch-sizes: $cc is not installed (apt-get install gcc-arm-none-eabi)" >&2
    exit 1
}
switches=$(sed -n 's/^#define \(MOTE_ENABLE_[A-Z_]*\) 1$/\1/p' include/mote/mote.h)
layers="MOTE_ENABLE_EMISSIVE_MAP MOTE_ENABLE_OPACITY_MAP MOTE_ENABLE_SPECULAR_MAP"

# .text of the core with the switches named after the first argument (a
# name for its folder) at 0.
core_text() {
    out=$dir/$1; shift
    off=""
    for s in "$@"; do off="$off -D$s=0"; done
    rm -rf "$out" && mkdir -p "$out"
    for src in src/core/*.c; do
        # shellcheck disable=SC2086  # one word per flag
        "$cc" $cflags $off -c "$src" -o "$out/$(basename "$src" .c).o" || exit 1
    done
    "${cc%gcc}size" -t "$out"/*.o | awk 'END { print $1 }'
}

# A row of the table: its label, the folder's name, the switches at 0.
row() {
    label=$1; shift
    text=$(core_text "$@")
    echo "| $label | $((all - text)) |"
}

all=$(core_text all)
echo "core .text with every feature: $all bytes"
echo
echo "| switch at 0 | saves |"
echo "|---|---:|"
for s in $switches; do
    row "\`$s\`" "$s" "$s"
done
# shellcheck disable=SC2086  # one word per switch
row "the three \`_MAP\` switches" maps $layers
# shellcheck disable=SC2086
row "every switch" none $switches
