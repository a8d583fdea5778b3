#!/bin/sh
# mote-bake's command line, checked on its exit status and messages: sizes
# it must refuse (spaces, past int, past MOTE_MAX_SIZE), an option without
# its value named, and why an output cannot be written. Ends with a
# Unity-style line "N Tests F Failures I Ignored" for tests/run.sh.
#
#   BIN=build/bin sh tests/tools/mote_bake.sh      (make test does this)
script=tests/tools/mote_bake.sh
. "$(dirname "$0")/common.sh"
B=${BIN:-build/bin}/mote-bake
scene=$(dirname "$0")/../data/ortho_camera.babylon

# refused NAME PATTERN ARGS...: mote-bake ARGS must exit 2 saying PATTERN
refused() {
    name=$1; pattern=$2; shift 2
    "$B" "$@" >"$tmp/out" 2>&1
    status=$?
    if [ $status -ne 2 ]; then
        fail "$name" "exit status $status, expected 2: $(cat "$tmp/out")"
    elif ! grep -q -- "$pattern" "$tmp/out"; then
        fail "$name" "no \"$pattern\" in: $(cat "$tmp/out")"
    else
        pass "$name"
    fi
}

refused size_with_spaces_should_be_refused "--size wants WxH" "$scene" -o "$tmp/a.h" --size " 12x 3"
refused size_past_int_should_be_refused "--size wants WxH" "$scene" -o "$tmp/a.h" --size 99999999999x2
refused size_past_the_limit_should_be_refused "--size wants WxH" "$scene" -o "$tmp/a.h" --size 4097x2
refused a_missing_value_should_be_named "--size needs a value" "$scene" -o "$tmp/a.h" --size

name=an_unwritable_output_should_say_why
if "$B" "$scene" -o "$tmp/no/such/folder.h" >"$tmp/out" 2>&1; then
    fail $name "exit status 0, expected an error"
elif ! grep -q "cannot write: No such file or directory" "$tmp/out"; then
    fail $name "no reason given: $(cat "$tmp/out")"
else
    pass $name
fi
name=a_plain_size_should_bake
if "$B" "$scene" -o "$tmp/ok.h" --size 12x3 >"$tmp/out" 2>&1 && grep -q "WIDTH 12" "$tmp/ok.h"; then
    pass $name
else
    fail $name "$(cat "$tmp/out")"
fi

summary
