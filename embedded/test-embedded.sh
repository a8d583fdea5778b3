#!/bin/sh
# Renders the firmware example on emulated Cortex-M boards and checks that
# its frame hash equals the host's (same source, same baked scene), and that
# the Cortex-M0+ firmware-profile core keeps within its 16 KB flash budget.
#   - the Cortex-M0+ build (soft float) on mps2-an385: qemu has no M0+
#     board, so it runs on the AN385's Cortex-M3 (ARMv6-M code is ARMv7-M
#     code); the instructions and float routines are the M0+ build's.
#   - the Cortex-M4F build (hard float) on mps2-an386 (Cortex-M4 with FPU).
# Output goes through semihosting. Ends with a Unity-style summary line;
# ignored (not failed) when the cross compiler or qemu cannot be had.
# Installs gcc-arm-none-eabi and qemu-system-arm through third_party/setup.sh
# when they are missing and root with apt-get is available.
set -u
cd "$(dirname "$0")/.." || exit 1
build=${MOTE_BUILD:-build}
dir=$build/cross

ignore() {
    echo "embedded/test-embedded.sh:0:firmware_hash_should_match_host:IGNORE: $1"
    echo "-----------------------"
    echo "1 Tests 0 Failures 1 Ignored"
    exit 0
}
fail() {
    echo "embedded/test-embedded.sh:0:firmware_hash_should_match_host:FAIL: $1"
    echo "-----------------------"
    echo "1 Tests 1 Failures 0 Ignored"
    echo "FAIL"
    exit 1
}

# Root with apt-get installs what is missing (CI's clean machine: without
# it this test was ignored there, and the freestanding core went unchecked).
missing=""
command -v arm-none-eabi-gcc >/dev/null 2>&1 || missing="$missing gcc-arm-none-eabi"
command -v qemu-system-arm >/dev/null 2>&1 || missing="$missing qemu-system-arm"
if [ -n "$missing" ] && [ "$(id -u)" -eq 0 ] && command -v apt-get >/dev/null 2>&1; then
    MOTE_EXTRA_PACKAGES="$missing" sh third_party/setup.sh >/dev/null 2>&1
fi
command -v arm-none-eabi-gcc >/dev/null 2>&1 ||
    ignore "arm-none-eabi-gcc is not installed (apt-get install gcc-arm-none-eabi)"
command -v qemu-system-arm >/dev/null 2>&1 ||
    ignore "qemu-system-arm is not installed (apt-get install qemu-system-arm)"

# A make of our own: not part of an outer make's job server.
env -u MAKEFLAGS -u MAKELEVEL -u MFLAGS make -s --no-print-directory BUILD="$build" embedded-firmware ||
    fail "building the firmware example failed"

want=$("$dir/host/mote-firmware" | sed -n 's/.*frame fnv1a //p')
[ -n "$want" ] || fail "the host build printed no hash"
echo "host:                        fnv1a $want"

failures=0
for run in mps2-an385:cortex-m0plus mps2-an386:cortex-m4f; do
    board=${run%%:*}; target=${run#*:}
    out=$(timeout 60 qemu-system-arm -M "$board" -nographic -monitor none -serial none \
              -semihosting-config enable=on,target=native \
              -kernel "$dir/$target/mote-firmware.elf" 2>&1)
    rc=$?
    echo "$out" | sed "s/^/  $target on $board: /"
    got=$(echo "$out" | sed -n 's/.*frame fnv1a //p')
    if [ "$rc" -ne 0 ] || [ "$got" != "$want" ]; then
        echo "  $target on $board: exit $rc, fnv1a '$got', want '$want'"
        failures=$((failures + 1))
    else
        echo "$target on $board: fnv1a $got, the same as the host"
    fi
done
result=0
if [ "$failures" -eq 0 ]; then
    echo "embedded/test-embedded.sh:0:firmware_hash_should_match_host:PASS"
else
    echo "embedded/test-embedded.sh:0:firmware_hash_should_match_host:FAIL: $failures emulated run(s) differ from the host"
    result=1
fi

# The flash budget of issue 5: the core as the firmware profile builds it
# (the MOTE_ENABLE_* features the example does not use left out) stays under
# 16 KB of .text on Cortex-M0+; `make cross` prints the same figure.
budget=16384
used=$(arm-none-eabi-size -t "$dir/cortex-m0plus/libmote-fw.a" | awk 'END { print $1 }')
if [ -n "$used" ] && [ "$used" -le "$budget" ]; then
    echo "embedded/test-embedded.sh:0:firmware_profile_core_should_fit_16k_on_m0plus:PASS ($used bytes)"
else
    echo "embedded/test-embedded.sh:0:firmware_profile_core_should_fit_16k_on_m0plus:FAIL: '$used' bytes, budget $budget"
    result=$((result + 2))
fi
echo "-----------------------"
case $result in
    0) echo "2 Tests 0 Failures 0 Ignored"; echo "OK" ;;
    3) echo "2 Tests 2 Failures 0 Ignored"; echo "FAIL" ;;
    *) echo "2 Tests 1 Failures 0 Ignored"; echo "FAIL" ;;
esac
[ "$result" -eq 0 ]
