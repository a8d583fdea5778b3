# Sourced by the tests/tools/*.sh scripts after they set `script` (their
# path, for Unity-style result lines): a temporary folder $tmp removed on
# exit, pass/fail counters, and summary, the closing line tests/run.sh reads.
set -u
tmp=$(mktemp -d)
trap 'rm -rf "$tmp"' EXIT INT TERM
tests=0; failures=0

pass() { tests=$((tests + 1)); echo "$script:0:$1:PASS"; }
fail() { tests=$((tests + 1)); failures=$((failures + 1)); echo "$script:0:$1:FAIL: $2"; }

# prints "N Tests F Failures 0 Ignored"; the status says whether all passed
summary() {
    echo
    echo "-----------------------"
    echo "$tests Tests $failures Failures 0 Ignored"
    [ "$failures" -eq 0 ]
}
