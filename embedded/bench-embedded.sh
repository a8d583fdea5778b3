#!/bin/sh
# make bench-embedded: the firmware example (embedded/firmware/main.c, the
# firmware profile, -Os) on the emulated boards (embedded/boards.sh),
# 320x240 RGB565 + 16-bit depth, for each variant given (SCENE-ROWS: ROWS a
# band, 240 the whole frame), counted in executed instructions per frame by
# embedded/qemu/insn_count.c: mote_begin, the draws and mote_end, less the
# flush callback (the display's share). Beside each count:
#   fps       at 133 and 168 MHz, one instruction a cycle
#   RAM       colour and depth buffers, mote_device and binning arena as
#             the firmware allocates them (the sizes of its symbols
#             fw_color, fw_depth, fw_device, fw_bins), and the worst-case
#             stack (embedded/stack-usage.sh); ram_bytes is their sum
#   flash     the core, libgcc and the whole firmware, from the link map
#   hash      the frame's, which must equal the host build's (of the
#             target's vertex stage: embedded/boards.sh's board_host)
# Writes the rows to $MOTE_BUILD/bench-embedded.csv. A target whose tools
# cannot be installed is skipped, saying so; Suzanne without
# ../shared/assets too. Exit status 1 when a hash differs or a run fails.
# usage: bench-embedded.sh VARIANT...
set -u
cd "$(dirname "$0")/.." || exit 1
export MOTE_BUILD=${MOTE_BUILD:-build}
. embedded/boards.sh
dir=$MOTE_BUILD/cross
csv=$MOTE_BUILD/bench-embedded.csv
targets="cortex-m0plus cortex-m4f rv32imac"

# (make passes the path it looked for Suzanne at)
[ -z "${MOTE_SUZANNE:-}" ] || [ -f "$MOTE_SUZANNE" ] ||
    echo "bench-embedded: Suzanne skipped: $MOTE_SUZANNE is not there"
boards_install $targets
ready=""
for t in $targets; do
    why=$(board_missing "$t")
    if [ -n "$why" ]; then echo "bench-embedded: $t skipped: $why"; else ready="$ready $t"; fi
done

# Everything built first, by one make (the variants' ELFs, the host
# references, the counter).
files="$MOTE_BUILD/qemu/libinsn_count.so"
for v in "$@"; do
    for t in $ready; do files="$files $dir/$t/$v/mote-firmware.elf $dir/$(board_host "$t")/$v/mote-firmware"; done
done
env -u MAKEFLAGS -u MAKELEVEL -u MFLAGS make -j2 -s --no-print-directory BUILD="$MOTE_BUILD" $files || {
    echo "bench-embedded: the build failed"
    exit 1
}

# the size of a symbol in ELF (0 when it has none)
symbol_size() {
    s=$("$(board_tools "$1")nm" -S "$2" | awk -v n="$3" '$4 == n { print $2 }')
    echo $((0x${s:-0}))
}

echo "target,scene,band_rows,instructions_per_frame,ram_bytes,stack_bytes,flash_core_bytes,flash_libgcc_bytes,hash" >"$csv"
printf '%-13s %-8s %4s %13s %7s %7s | %7s %6s %5s %6s %7s | %6s %6s %6s | %s\n' \
    target scene rows instr/frame fps@133 fps@168 buffers device bins stack RAM core libgcc flash hash
failures=0
for t in $ready; do
    tools=$(board_tools "$t")
    for v in "$@"; do
        # scene-rows[-tag...]: the scene column keeps the tags (suzanne-replay)
        scene=$(echo "$v" | cut -d- -f1); rows=$(echo "$v" | cut -d- -f2)
        tags=$(echo "$v" | cut -s -d- -f3-); [ -z "$tags" ] || scene="$scene-$tags"
        elf=$dir/$t/$v/mote-firmware.elf
        want=$("$dir/$(board_host "$t")/$v/mote-firmware" | sed -n 's/.*frame fnv1a //p')
        out=$(board_run "$t" "$elf" count)
        rc=$?
        count=$(echo "$out" | sed -n 's/^insn_count: counted \([0-9]*\) .*/\1/p')
        got=$(echo "$out" | sed -n 's/.*frame fnv1a //p')
        if [ "$rc" -ne 0 ] || [ -z "$count" ] || [ -z "$got" ]; then
            echo "$out" | sed "s|^|  $t $v: |"
            echo "bench-embedded: $t $v: the run failed (exit $rc)"
            failures=$((failures + 1))
            continue
        fi
        verdict="= host"
        [ "$got" = "$want" ] || { verdict="DIFFERS from the host's $want"; failures=$((failures + 1)); }
        buffers=$(( $(symbol_size "$t" "$elf" fw_color) + $(symbol_size "$t" "$elf" fw_color_back) \
                    + $(symbol_size "$t" "$elf" fw_depth) ))
        device=$(symbol_size "$t" "$elf" fw_device)
        bins=$(symbol_size "$t" "$elf" fw_bins)
        stack=$(sh embedded/stack-usage.sh "$tools" "$elf" "$dir/$t/core-fw" "$dir/$t/fw" "$dir/$t/$v") || stack=0
        stack=${stack%% *}
        ram=$((buffers + device + bins + stack))
        sizes=$(sh embedded/map-sizes.sh "$dir/$t/$v/mote-firmware.map")
        core=$(echo "$sizes" | awk '$1 == "core" { print $2 }')
        libgcc=$(echo "$sizes" | awk '$1 == "libgcc" { print $2 }')
        flash=$("${tools}size" "$elf" | awk 'NR == 2 { print $1 + $2 }')
        echo "$t,$scene,$rows,$count,$ram,$stack,$core,$libgcc,$got" >>"$csv"
        awk -v t="$t" -v s="$scene" -v r="$rows" -v n="$count" -v b="$buffers" -v d="$device" -v bi="$bins" \
            -v st="$stack" -v ram="$ram" -v c="$core" -v l="$libgcc" -v f="$flash" -v h="$got $verdict" 'BEGIN {
            printf "%-13s %-8s %4s %11.2f M %7.2f %7.2f | %7d %6d %5d %6d %7d | %6d %6d %6d | %s\n",
                   t, s, r, n / 1e6, 133e6 / n, 168e6 / n, b, d, bi, st, ram, c, l, f, h }'
    done
done
echo "bench-embedded: wrote $csv"
[ "$failures" -eq 0 ] || { echo "bench-embedded: $failures run(s) failed or differ from the host"; exit 1; }
