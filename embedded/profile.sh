#!/bin/sh
# Where a firmware's instructions go: runs a variant built by `make
# bench-embedded` (or make BUILD/cross/TARGET/VARIANT/mote-firmware.elf)
# on its emulated board with the instruction counter's profile
# (embedded/qemu/insn_count.c, profile=FILE), and prints the functions that
# executed the most instructions over the whole run (the frame, plus
# start-up, the flush callback and the frame hash), with their share.
# usage: embedded/profile.sh TARGET VARIANT [LINES]
#   e.g. sh embedded/profile.sh cortex-m0plus suzanne-30 25
set -u
cd "$(dirname "$0")/.." || exit 1
export MOTE_BUILD=${MOTE_BUILD:-build}
. embedded/boards.sh
[ $# -ge 2 ] || { echo "usage: embedded/profile.sh TARGET VARIANT [LINES]"; exit 2; }
t=$1; v=$2; lines=${3:-30}
elf=$MOTE_BUILD/cross/$t/$v/mote-firmware.elf
[ -f "$elf" ] && [ -f "$MOTE_BUILD/qemu/libinsn_count.so" ] ||
    { echo "profile: build $elf and $MOTE_BUILD/qemu/libinsn_count.so first (make bench-embedded)"; exit 1; }
prof=$(mktemp)
BOARD_PROFILE=$prof board_run "$t" "$elf" count | grep -E 'insn_count|fnv1a'
# function symbols by address, then each block's count to the function
# holding its address (Thumb symbols carry bit 0)
"$(board_tools "$t")nm" -n --defined-only "$elf" | awk '$2 ~ /^[tTwW]$/ { print "S", $1, $3 }' >"$prof.sym"
sort -k1,1 "$prof" | awk '{ print "P", $1, $2 }' | cat "$prof.sym" - |
    awk '{ a = 0; h = $2; n = length(h)
           for (i = 1; i <= n; i++) a = a * 16 + index("0123456789abcdef", substr(h, i, 1)) - 1
           if ($1 == "S") a -= a % 2
           print a, ($1 == "S" ? 0 : 1), $3 }' |
    sort -k1,1n -k2,2n |
    awk '$2 == 0 { f = $3; next } { c[f] += $3; all += $3 }
         END { for (f in c) printf "%d %.1f%% %s\n", c[f], 100 * c[f] / all, f }' |
    sort -k1,1nr | head -n "$lines"
rm -f "$prof" "$prof.sym"
