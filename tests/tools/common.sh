# Sourced by the tests/tools/*.sh scripts after they set `script` (their
# path, for Unity-style result lines): a temporary folder $tmp removed on
# exit, pass/fail counters, and summary, the closing line tests/run.sh reads.
set -u
tmp=$(mktemp -d)
trap 'rm -rf "$tmp"' EXIT INT TERM
tests=0; failures=0; ignored=0

pass() { tests=$((tests + 1)); echo "$script:0:$1:PASS"; }
fail() { tests=$((tests + 1)); failures=$((failures + 1)); echo "$script:0:$1:FAIL: $2"; }
ignore() { tests=$((tests + 1)); ignored=$((ignored + 1)); echo "$script:0:$1:IGNORE: $2"; }

# fails NAME STATUS PATTERN CMD...: passes NAME when CMD exits with STATUS
# ("any": any but 0) and its output says PATTERN
fails() {
    name=$1; want=$2; pattern=$3; shift 3
    "$@" >"$tmp/out" 2>&1
    status=$?
    if [ $status -eq 0 ] || { [ "$want" != any ] && [ $status -ne "$want" ]; }; then
        fail "$name" "exit status $status, expected $want: $(cat "$tmp/out")"
    elif ! grep -q -- "$pattern" "$tmp/out"; then
        fail "$name" "no \"$pattern\" in: $(cat "$tmp/out")"
    else
        pass "$name"
    fi
}

# prints "N Tests F Failures I Ignored"; the status says whether all passed
summary() {
    echo
    echo "-----------------------"
    echo "$tests Tests $failures Failures $ignored Ignored"
    [ "$failures" -eq 0 ]
}
