#!/bin/sh
# Tests that behave like the chips: the firmware example and the harness's
# self-test on the emulated boards of embedded/boards.sh (Cortex-M0+ and
# M4F, RV32IMAC), each checked against the host:
#   firmware_hash_should_match_host           the example (cube, 30-row
#       bands, RGB565) renders the host's frame, the host built with the
#       target's vertex stage (board_host: integer on M0+ and RV32IMAC)
#   lcd_image_should_match_frame_and_host     the same through the LCD
#       driver (16-row bands, RGB565_SWAPPED) into the fake panel, which
#       must find the driver's commands by the rules and receive the frame
#   stack_bound_should_cover_measured_stack   embedded/stack-usage.sh's
#       worst case is at least what the runs used, and fits the stack
#   insn_count_should_count_exactly           the instruction counter
#       counts the self-test's known stretch (embedded/tests/selftest.c)
#   unaligned_access_should_fault_only_on_m0plus  the M0+ build faults on
#       an unaligned load, as an M0+ does; the M4F reads it
#   firmware_core_and_libgcc_should_fit_31k_on_m0plus  the flash budget
# A fault prints "fault at pc ..." and fails the run. Ends with a
# Unity-style summary; a target whose compiler or emulator cannot be
# installed (third_party/setup.sh, as root with apt-get) is ignored, not
# failed, with the reason.
set -u
cd "$(dirname "$0")/.." || exit 1
export MOTE_BUILD=${MOTE_BUILD:-build}
. embedded/boards.sh
dir=$MOTE_BUILD/cross
targets="cortex-m0plus cortex-m4f rv32imac"
tests=0; failures=0; ignored=0

pass() { tests=$((tests + 1)); echo "embedded/test-embedded.sh:0:$1:PASS${2:+ ($2)}"; }
fail() { tests=$((tests + 1)); failures=$((failures + 1)); echo "embedded/test-embedded.sh:0:$1:FAIL: $2"; }
ignore() { tests=$((tests + 1)); ignored=$((ignored + 1)); echo "embedded/test-embedded.sh:0:$1:IGNORE: $2"; }
check() { if [ "$2" = ok ]; then pass "$1" "$3"; else fail "$1" "$2"; fi; }
finish() {
    echo "-----------------------"
    echo "$tests Tests $failures Failures $ignored Ignored"
    if [ "$failures" -eq 0 ]; then echo OK; exit 0; else echo FAIL; exit 1; fi
}

# The tests each target runs.
target_tests() {
    for name in firmware_hash_should_match_host lcd_image_should_match_frame_and_host \
                stack_bound_should_cover_measured_stack insn_count_should_count_exactly; do
        echo "${name}_on_$1"
    done
    case $1 in
        cortex-m0plus) echo unaligned_access_should_fault_only_on_m0plus firmware_core_and_libgcc_should_fit_31k_on_m0plus ;;
        cortex-m4f) echo unaligned_access_should_fault_only_on_m0plus_not_m4f ;;
    esac
}

boards_install $targets
ready=""
for t in $targets; do
    why=$(board_missing "$t")
    if [ -n "$why" ]; then
        for name in $(target_tests "$t"); do ignore "$name" "$why"; done
    else
        ready="$ready $t"
    fi
done
[ -n "$ready" ] || finish

# A make of our own (not part of an outer make's job server), on every core.
env -u MAKEFLAGS -u MAKELEVEL -u MFLAGS make -s --no-print-directory -j"$(nproc 2>/dev/null || echo 1)" BUILD="$MOTE_BUILD" \
    fw-test-host insn-count-plugin $(for t in $ready; do echo "fw-test-$t"; done) || {
    fail firmware_should_build "building the firmware failed"
    finish
}

host_hash() { "$dir/$1/$2/mote-firmware" | sed -n 's/.*frame fnv1a //p'; }
for h in host host-fixed; do
    echo "$h: fnv1a $(host_hash $h cube-30) (RGB565), $(host_hash $h cube-16-lcd) (RGB565_SWAPPED)"
done

for t in $ready; do
    want=$(host_hash "$(board_host "$t")" cube-30)
    want_lcd=$(host_hash "$(board_host "$t")" cube-16-lcd)
    tools=$(board_tools "$t")
    stack_result=ok; stack_note=""
    for v in cube-30 cube-16-lcd; do
        out=$(board_run "$t" "$dir/$t/$v/mote-firmware.elf")
        rc=$?
        echo "$out" | sed "s/^/  $t $v: /"
        got=$(echo "$out" | sed -n 's/.*frame fnv1a //p')
        if [ "$v" = cube-30 ]; then name=firmware_hash_should_match_host; expect=$want
        else name=lcd_image_should_match_frame_and_host; expect=$want_lcd; fi
        # the LCD run itself fails when the panel saw a broken protocol or
        # an image other than the frame
        if [ "$rc" -ne 0 ] || [ -z "$got" ] || [ "$got" != "$expect" ]; then
            fail "${name}_on_$t" "exit $rc, fnv1a '$got', the host's '$expect'"
        else
            pass "${name}_on_$t" "fnv1a $got"
        fi
        # the run's stack high-water mark against the static bound of its ELF
        used=$(echo "$out" | sed -n 's/.*stack used \([0-9]*\) bytes/\1/p')
        e=$dir/$t/$v/mote-firmware.elf
        bound=$(sh embedded/stack-usage.sh "$tools" "$e" "$dir/$t/core-fw" "$dir/$t/fw" "$dir/$t/$v") || bound=""
        bound=${bound%% *}
        region=$("${tools}nm" "$e" | awk '$3 == "__stack_top" { t = $1 } $3 == "__stack_bottom" { b = $1 } END { print t, b }')
        region=$((0x${region% *} - 0x${region#* }))
        if [ -z "$bound" ]; then r="$v: no bound (embedded/stack-usage.sh)"
        elif [ -z "$used" ] || [ "$bound" -lt "$used" ]; then r="$v: bound $bound bytes, '$used' measured"
        elif [ "$bound" -gt "$region" ]; then r="$v: bound $bound bytes, over the $region-byte stack"
        else r=ok; fi
        [ "$r" = ok ] || stack_result=$r
        stack_note="$stack_note${stack_note:+, }$v $used <= $bound of $region"
    done
    check "stack_bound_should_cover_measured_stack_on_$t" "$stack_result" "$stack_note"

    out=$(board_run "$t" "$dir/$t/selftest/selftest.elf" count)
    rc=$?
    echo "$out" | sed "s/^/  $t selftest: /"
    want_count=$(echo "$out" | sed -n 's/^selftest: counted stretch of \([0-9]*\) .*/\1/p')
    count=$(echo "$out" | sed -n 's/^insn_count: counted \([0-9]*\) instructions in 1 intervals.*/\1/p')
    if [ -n "$count" ] && [ "$count" = "$want_count" ]; then r=ok
    else r="counted '$count', the stretch is '$want_count' instructions"; fi
    check "insn_count_should_count_exactly_on_$t" "$r" "$count"

    case $t in
        cortex-m0plus)
            if [ "$rc" -ne 0 ] && echo "$out" | grep -q "fault at pc"; then r=ok
            else r="the unaligned load did not fault (exit $rc)"; fi
            check unaligned_access_should_fault_only_on_m0plus "$r" "faulted" ;;
        cortex-m4f)
            if [ "$rc" -eq 0 ] && echo "$out" | grep -q "unaligned load read .*, right"; then r=ok
            else r="the unaligned load did not read the word (exit $rc)"; fi
            check unaligned_access_should_fault_only_on_m0plus_not_m4f "$r" "read" ;;
    esac

    # The flash budget: the core the firmware example links (the firmware
    # profile, after --gc-sections) and the libgcc routines it pulls in
    # stay within 31 KB on Cortex-M0+ (docs/embedded.md says what fills
    # them); `make cross` prints the figures.
    if [ "$t" = cortex-m0plus ]; then
        budget=31744
        size=$(sh embedded/map-sizes.sh "$dir/cortex-m0plus/cube-30/mote-firmware.map" |
               awk '$1 == "core" || $1 == "libgcc" { n += $2 } END { print n }')
        if [ -n "$size" ] && [ "$size" -le "$budget" ]; then r=ok; else r="'$size' bytes, budget $budget"; fi
        check firmware_core_and_libgcc_should_fit_31k_on_m0plus "$r" "$size bytes"
    fi
done
finish
