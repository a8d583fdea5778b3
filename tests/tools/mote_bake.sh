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

fails size_with_spaces_should_be_refused 2 "--size wants WxH" "$B" "$scene" -o "$tmp/a.h" --size " 12x 3"
fails size_past_int_should_be_refused 2 "--size wants WxH" "$B" "$scene" -o "$tmp/a.h" --size 99999999999x2
fails size_past_the_limit_should_be_refused 2 "--size wants WxH" "$B" "$scene" -o "$tmp/a.h" --size 4097x2
fails a_missing_value_should_be_named 2 "--size needs a value" "$B" "$scene" -o "$tmp/a.h" --size

fails an_unwritable_output_should_say_why any "cannot write: No such file or directory" \
    "$B" "$scene" -o "$tmp/no/such/folder.h"
name=a_plain_size_should_bake
if "$B" "$scene" -o "$tmp/ok.h" --size 12x3 >"$tmp/out" 2>&1 && grep -q "WIDTH 12" "$tmp/ok.h"; then
    pass $name
else
    fail $name "$(cat "$tmp/out")"
fi

# a scene with levels of detail is baked as its camera sees it, saying so:
# the camera 5 away draws the base, the level (past 10) is baked hidden
cat >"$tmp/lod.babylon" <<'JSON'
{"cameras":[{"id":"c","position":[0,0,-5],"target":[0,0,0]}],
 "meshes":[{"id":"q","lodMeshIds":["g"],"lodDistances":[10],
  "positions":[-1,-1,0, 1,-1,0, 1,1,0],"indices":[0,1,2]},
  {"id":"g","positions":[-1,-1,0, 1,-1,0, 1,1,0],"indices":[0,1,2]}]}
JSON
name=levels_of_detail_should_be_baked_as_the_camera_sees_them_with_a_warning
if "$B" "$tmp/lod.babylon" -o "$tmp/lod.h" >"$tmp/out" 2>&1 &&
        grep -q "warning: 1 meshes and instances have levels of detail" "$tmp/out" &&
        [ "$(grep -c '\.hidden = true' "$tmp/lod.h")" = 1 ] &&
        grep -A12 '{ /\* 1 \*/' "$tmp/lod.h" | grep -q '\.hidden = true'; then
    pass $name
else
    fail $name "$(cat "$tmp/out")"
fi

summary
