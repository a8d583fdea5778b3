#!/bin/sh
# Prints .text/.data/.bss of each cross target: the core archive as
# compiled with every feature (libmote.a) and in the firmware profile
# (libmote-fw.a, MOTE_ENABLE_* features the example does not use left
# out), and the linked firmware example split by where the bytes come from
# (embedded/map-sizes.sh: core, libgcc, example), then the example's
# worst-case stack (embedded/stack-usage.sh) beside the stack it has, and
# the deepest call path.
# .text here is everything in flash (code and read-only data).
# usage: cross-sizes.sh CROSS_DIR VARIANT TARGET...
set -eu
dir=$1; variant=$2; shift 2

printf '%-14s %-28s %7s %6s %6s\n' target part .text .data .bss
for t in "$@"; do
    case $t in
        rv32*) tools=riscv64-unknown-elf- ;;
        *) tools=arm-none-eabi- ;;
    esac
    fw=$dir/$t/$variant/mote-firmware
    ${tools}size -t "$dir/$t/libmote.a" | awk -v t="$t" 'END { printf "%-14s %-28s %7d %6d %6d\n", t, "core, all of libmote.a", $1, $2, $3 }'
    ${tools}size -t "$dir/$t/libmote-fw.a" | awk -v t="$t" 'END { printf "%-14s %-28s %7d %6d %6d\n", t, "core, firmware profile (.a)", $1, $2, $3 }'
    sh embedded/map-sizes.sh "$fw.map" | while read -r part text data bss; do
        printf '%-14s %-28s %7d %6d %6d\n' "$t" "firmware: $part" "$text" "$data" "$bss"
    done
    ${tools}size "$fw.elf" | awk -v t="$t" 'NR == 2 { printf "%-14s %-28s %7d %6d %6d\n", t, "firmware: total (ELF)", $1, $2, $3 }'
    stack=$(sh embedded/stack-usage.sh "$tools" "$fw.elf" "$dir/$t/core-fw" "$dir/$t/fw" "$dir/$t/$variant")
    region=$(${tools}nm "$fw.elf" | awk '$3 == "__stack_top" { t = $1 } $3 == "__stack_bottom" { b = $1 } END { print t, b }')
    printf '%-14s %-28s %7d bytes worst case, of %d\n' "$t" "firmware: stack" "${stack%% *}" \
        $((0x${region% *} - 0x${region#* }))
    echo "    deepest: ${stack#*: }"
done
