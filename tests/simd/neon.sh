#!/bin/sh
# The NEON pixel loops (src/core/span_neon.c) against the scalar ones,
# frame by frame: tests/core/render_matrix.c cross-built for AArch64 at
# -O3 and run under qemu-aarch64 must print the hashes that the host's
# scalar build (MOTE_SIMD=0) prints. Needs gcc-aarch64-linux-gnu and
# qemu-user, which it installs when missing (third_party/setup.sh, as
# root with apt-get); without them the test is reported as ignored,
# saying which is missing. Ends with a Unity-style
# summary for tests/run.sh. BUILD names the build folder (default build).
cd "$(dirname "$0")/../.." || exit 1
dir=${BUILD:-build}/tests/simd
name=the_neon_pixel_loops_should_draw_the_scalar_bytes
for tool in aarch64-linux-gnu-gcc:gcc-aarch64-linux-gnu qemu-aarch64:qemu-user; do
    command -v "${tool%%:*}" >/dev/null 2>&1 || MOTE_EXTRA_PACKAGES="${tool#*:}" sh third_party/setup.sh >/dev/null 2>&1
done
missing=""
command -v aarch64-linux-gnu-gcc >/dev/null 2>&1 || missing="$missing gcc-aarch64-linux-gnu"
command -v qemu-aarch64 >/dev/null 2>&1 || missing="$missing qemu-user"
if [ -n "$missing" ]; then
    echo "$name: IGNORE: not installed:$missing (apt-get install$missing, as root)"
    echo "-----------------------"
    echo "1 Tests 0 Failures 1 Ignored"
    exit 0
fi
mkdir -p "$dir"
src="tests/core/render_matrix.c tests/support/scenes.c $(ls src/core/*.c)"
flags="-std=c99 -O3 -ffp-contract=off -Wall -Wextra -Wpedantic -Wshadow -Wstrict-prototypes -Werror -Iinclude -Isrc -Itests"
fail=""
# the two builds side by side (a minute and a half each, mostly span.c)
# shellcheck disable=SC2086
${CC:-cc} $flags -DMOTE_SIMD=0 $src -lm -o "$dir/render_matrix_scalar" & scalar=$!
# shellcheck disable=SC2086
aarch64-linux-gnu-gcc $flags -static $src -lm -o "$dir/render_matrix_neon" || fail="the AArch64 build failed"
wait $scalar || fail="the scalar build failed"
if [ -z "$fail" ]; then
    "$dir/render_matrix_scalar" O3 > "$dir/scalar.txt" && qemu-aarch64 "$dir/render_matrix_neon" O3 > "$dir/neon.txt" \
        || fail="a render matrix did not run"
fi
if [ -z "$fail" ] && ! cmp -s "$dir/scalar.txt" "$dir/neon.txt"; then
    diff "$dir/scalar.txt" "$dir/neon.txt" | head -n 10
    fail="$(diff "$dir/scalar.txt" "$dir/neon.txt" | grep -c '^>') of $(wc -l < "$dir/scalar.txt") configurations differ"
fi
if [ -n "$fail" ]; then echo "$name: FAIL: $fail"; else echo "$name: PASS ($(wc -l < "$dir/neon.txt") configurations)"; fi
echo "-----------------------"
echo "1 Tests $([ -n "$fail" ] && echo 1 || echo 0) Failures 0 Ignored"
[ -z "$fail" ]
