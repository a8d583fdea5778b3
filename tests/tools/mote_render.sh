#!/bin/sh
# mote-render's options, checked on what the tool writes and says: each case
# runs it on a small scene written here and looks at its exit status, its
# messages and the pixels of the PPM it wrote. Ends with a Unity-style line
# "N Tests F Failures I Ignored" for tests/run.sh.
#
#   BIN=build/bin sh tests/tools/mote_render.sh      (make test does this)
set -u
R=${BIN:-build/bin}/mote-render
tmp=$(mktemp -d)
trap 'rm -rf "$tmp"' EXIT INT TERM
tests=0; failures=0

pass() { tests=$((tests + 1)); echo "tests/tools/mote_render.sh:0:$1:PASS"; }
fail() { tests=$((tests + 1)); failures=$((failures + 1)); echo "tests/tools/mote_render.sh:0:$1:FAIL: $2"; }

# pixel FILE X Y: "r g b" of a binary PPM (P6) as mote writes it: a
# three-line header "P6", "W H", "255", then rows of RGB
pixel() {
    w=$(sed -n 2p "$1" | cut -d' ' -f1)
    header=$(head -n 3 "$1" | wc -c)
    od -An -tu1 -j $((header + ($3 * w + $2) * 3)) -N3 "$1" | tr -s ' ' | sed 's/^ //'
}

# ---- --camera in a right-handed scene ---------------------------------------
# A right-handed scene is loaded mirrored in z; --camera is given in the
# file's coordinates and mirrored with it. A red quad at x = +2 seen from
# (0, 0, 5): Babylon.js's LookAtRH puts it in the right half.
cat >"$tmp/rh.babylon" <<'JSON'
{"useRightHandedSystem":true,
 "materials":[{"id":"red","diffuse":[1,0,0],"backFaceCulling":false}],
 "lights":[{"type":3,"id":"sky","direction":[0,0,1],"groundColor":[1,1,1]}],
 "meshes":[{"id":"q","materialId":"red","position":[2,0,0],
  "positions":[-1,-1,0, 1,-1,0, 1,1,0, -1,1,0],"normals":[0,0,1, 0,0,1, 0,0,1, 0,0,1],
  "indices":[0,2,1, 0,3,2]}]}
JSON
name=camera_should_be_read_in_a_right_handed_files_coordinates
if "$R" "$tmp/rh.babylon" -o "$tmp/rh.ppm" --size 32x16 --camera 0,0,5:0,0,0 --threads 1 \
        >"$tmp/out" 2>&1; then
    right=$(pixel "$tmp/rh.ppm" 24 8); left=$(pixel "$tmp/rh.ppm" 8 8)
    if [ "${right%% *}" -gt 0 ] && [ "$left" = "0 0 0" ]; then
        pass $name
    else
        fail $name "expected red on the right and black on the left, got \"$right\" and \"$left\""
    fi
else
    fail $name "exit status $?: $(cat "$tmp/out")"
fi

echo
echo "-----------------------"
echo "$tests Tests $failures Failures 0 Ignored"
[ "$failures" -eq 0 ]
