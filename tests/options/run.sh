#!/bin/sh
# Runs the MOTE_ENABLE_* variants built by tests/options/options.mk: first
# the full build, whose frame hash every other variant must reproduce, then
# each variant; ends with one Unity-style summary for tests/run.sh.
cd "$(dirname "$0")/../.." || exit 1
dir=${MOTE_BUILD:-build}/tests/options
hash=$("$dir/test_options_full" | sed -n 's/^options: plain textured frame hash //p')
tests=0; failures=0
for v in full lines binning bilinear subspan vertex_colors falloff orthographic emissive_map opacity_map specular_map none; do
    out=$(MOTE_OPTIONS_HASH=$hash "$dir/test_options_$v" 2>&1)
    echo "$out" | sed "s/^/[$v] /"
    line=$(echo "$out" | grep -E '^[0-9]+ Tests [0-9]+ Failures' | tail -n 1)
    if [ -z "$line" ]; then
        tests=$((tests + 1)); failures=$((failures + 1)); continue
    fi
    tests=$((tests + $(echo "$line" | cut -d' ' -f1)))
    failures=$((failures + $(echo "$line" | cut -d' ' -f3)))
done
[ -n "$hash" ] || { tests=$((tests + 1)); failures=$((failures + 1)); echo "no hash from the full build"; }
echo "-----------------------"
echo "$tests Tests $failures Failures 0 Ignored"
[ "$failures" -eq 0 ]
