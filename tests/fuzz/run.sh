#!/bin/sh
# Runs libFuzzer targets for FUZZ_SECONDS each and prints how many inputs
# each ran.   usage: tests/fuzz/run.sh DIR_WITH_BINARIES target...
# Seeds: tests/fuzz/seeds/<target>/, tests/fuzz/regressions/<target>/, and
# for the loaders the scenes and images of assets/, ../shared/assets/ (when
# present), tests/data/ (the exporters' layouts too) and tests/data/bad/. What the fuzzer learns is kept in
# $FUZZ_BUILD/corpus/<target>/, crashes go to $FUZZ_BUILD/crashes/<target>/.
set -u
bindir=$1
shift
secs=${FUZZ_SECONDS:-60}
build=${FUZZ_BUILD:-build-fuzz}
failed=0
report=""

for t in "$@"; do
    corpus=$build/corpus/$t
    seeds=$build/seeds/$t
    crashes=$build/crashes/$t
    mkdir -p "$corpus" "$seeds" "$crashes"
    for f in assets/* ../shared/assets/* tests/data/bad/* tests/data/*.babylon tests/data/exporters/*; do
        [ -f "$f" ] || continue
        case "$t:$f" in
            scene:*.babylon|scene:*.json) cp "$f" "$seeds/" ;;
            gltf:*.gltf|gltf:*.glb) cp "$f" "$seeds/" ;;
            texture:*.png|texture:*.jpg|texture:*.jpeg|texture:*.bmp|texture:*.tga|texture:*.gif|texture:*.ppm|texture:*.pgm|texture:*.psd|texture:*.hdr|texture:*.pic)
                cp "$f" "$seeds/" ;;
        esac
    done
    dirs="$corpus $seeds"
    for d in tests/fuzz/seeds/$t tests/fuzz/regressions/$t; do
        [ -d "$d" ] && dirs="$dirs $d"
    done
    dict=""
    [ -f "tests/fuzz/$t.dict" ] && dict="-dict=tests/fuzz/$t.dict"
    log=$build/fuzz-$t.log
    echo "== fuzz_$t: $secs s (log: $log)"
    # shellcheck disable=SC2086
    # A fixed seed (FUZZ_SEED, default 1) makes a CI run repeatable: what it
    # finds, a local run with the same seed finds too. FUZZ_SEED=0 is random.
    "$bindir/fuzz_$t" -seed="${FUZZ_SEED:-1}" -max_total_time="$secs" -print_final_stats=1 -timeout=10 \
        -rss_limit_mb=2048 -artifact_prefix="$crashes/" $dict $dirs >"$log" 2>&1
    rc=$?
    execs=$(sed -n 's/^stat::number_of_executed_units: *//p' "$log" | tail -n 1)
    rate=$(sed -n 's/^stat::average_exec_per_sec: *//p' "$log" | tail -n 1)
    cov=$(grep -E '^#[0-9]+' "$log" | tail -n 1 | sed -n 's/.*cov: \([0-9]*\).*/\1/p')
    if [ "$rc" -ne 0 ]; then
        failed=$((failed + 1))
        echo "!! fuzz_$t found a problem (exit $rc):"
        grep -E 'ERROR|runtime error|invariant broken|SUMMARY|Test unit written' "$log" | head -n 8
        line="fuzz_$t: FAILED after ${execs:-?} executions"
    else
        line="fuzz_$t: ${execs:-?} executions in $secs s (${rate:-?}/s), coverage ${cov:-?}, no crash"
    fi
    echo "$line"
    report="$report$line
"
done
echo
printf '%s' "$report"
[ "$failed" -eq 0 ]
