#!/bin/sh
# Runs each test executable (or script) given, from the repository root,
# shows its output, and ends with the total line "N passed, M failed".
# Unity ends each run with "T Tests F Failures I Ignored".
passed=0; failed=0; ignored=0; crashed=0
for t in "$@"; do
    echo "== $t"
    log=$(mktemp)
    if [ "${t%.sh}" != "$t" ]; then sh "$t" >"$log" 2>&1; rc=$?; else "$t" >"$log" 2>&1; rc=$?; fi
    cat "$log"
    line=$(grep -E '^[0-9]+ Tests [0-9]+ Failures [0-9]+ Ignored' "$log" | tail -n 1)
    rm -f "$log"
    if [ -z "$line" ]; then
        echo "!! $t ended without a Unity summary (exit $rc)"
        failed=$((failed + 1)); crashed=$((crashed + 1)); continue
    fi
    n=$(echo "$line" | cut -d' ' -f1); f=$(echo "$line" | cut -d' ' -f3); i=$(echo "$line" | cut -d' ' -f5)
    passed=$((passed + n - f - i)); failed=$((failed + f)); ignored=$((ignored + i))
    if [ "$rc" -ne 0 ] && [ "$f" -eq 0 ]; then
        echo "!! $t exited $rc"; failed=$((failed + 1))
    fi
done
echo
echo "$passed passed, $failed failed, $ignored skipped"
[ "$failed" -eq 0 ]
