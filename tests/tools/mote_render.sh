#!/bin/sh
# mote-render's options, checked on what the tool writes and says: each case
# runs it on a small scene written here and looks at its exit status, its
# messages and the pixels of the PPM it wrote. Ends with a Unity-style line
# "N Tests F Failures I Ignored" for tests/run.sh.
#
#   BIN=build/bin sh tests/tools/mote_render.sh      (make test does this)
script=tests/tools/mote_render.sh
. "$(dirname "$0")/common.sh"
R=${BIN:-build/bin}/mote-render

# pixel FILE X Y: "r g b" of a binary PPM (P6) as mote writes it: a
# three-line header "P6", "W H", "255", then rows of RGB
pixel() {
    w=$(sed -n 2p "$1" | cut -d' ' -f1)
    header=$(head -n 3 "$1" | wc -c)
    od -An -tu1 -j $((header + ($3 * w + $2) * 3)) -N3 "$1" | tr -s ' ' | sed 's/^ //'
}

# red_and_black NAME PPM X Y X2 Y2: passes NAME when pixel (X, Y) has red
# and (X2, Y2) is black
red_and_black() {
    red=$(pixel "$2" "$3" "$4"); black=$(pixel "$2" "$5" "$6")
    if [ "${red%% *}" -gt 0 ] && [ "$black" = "0 0 0" ]; then
        pass "$1"
    else
        fail "$1" "expected red at ($3, $4) and black at ($5, $6), got \"$red\" and \"$black\""
    fi
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
    red_and_black $name "$tmp/rh.ppm" 24 8 8 8
else
    fail $name "exit status $?: $(cat "$tmp/out")"
fi

# ---- --allow-missing-textures ---------------------------------------------------
# A red material whose texture file is not there: the load fails, naming the
# file; with --allow-missing-textures the quad is drawn in the material's
# red (no texture to modulate it), with the loader's warning.
cat >"$tmp/missing.babylon" <<'JSON'
{"materials":[{"id":"red","diffuse":[1,0,0],"diffuseTexture":{"name":"no-such-image.png"}}],
 "cameras":[{"id":"c","position":[0,0,-3],"target":[0,0,0]}],
 "lights":[{"type":3,"id":"sky","direction":[0,0,-1],"groundColor":[1,1,1]}],
 "meshes":[{"id":"q","materialId":"red",
  "positions":[-1,-1,0, 1,-1,0, 1,1,0, -1,1,0],"normals":[0,0,-1, 0,0,-1, 0,0,-1, 0,0,-1],
  "uvs":[0,0, 1,0, 1,1, 0,1],"indices":[0,1,2, 0,2,3]}]}
JSON
fails a_missing_texture_should_fail_the_load_by_default any "no-such-image.png" \
    "$R" "$tmp/missing.babylon" -o "$tmp/missing.ppm" --size 16x16 --threads 1
name=allow_missing_textures_should_draw_the_material_colour_with_a_warning
if "$R" "$tmp/missing.babylon" -o "$tmp/missing.ppm" --size 16x16 --threads 1 \
        --allow-missing-textures >"$tmp/out" 2>&1; then
    centre=$(pixel "$tmp/missing.ppm" 8 8)
    if ! grep -q "warning: .*no-such-image.png.*(drawn untextured)" "$tmp/out"; then
        fail $name "no warning naming the file: $(cat "$tmp/out")"
    elif [ "$centre" != "255 0 0" ]; then
        fail $name "the centre pixel is \"$centre\", expected the material's \"255 0 0\""
    else
        pass $name
    fi
else
    fail $name "exit status $?: $(cat "$tmp/out")"
fi

# ---- --ortho -------------------------------------------------------------------
# A 2 x 2 red quad 20 units ahead: --ortho 4 draws it half the image wide,
# whatever its distance (from the scene's camera perspective would draw it
# a few pixels wide); with --fov as well, a usage error.
cat >"$tmp/far.babylon" <<'JSON'
{"materials":[{"id":"red","diffuse":[1,0,0]}],
 "cameras":[{"id":"c","position":[0,0,-20],"target":[0,0,0]}],
 "lights":[{"type":3,"id":"sky","direction":[0,0,-1],"groundColor":[1,1,1]}],
 "meshes":[{"id":"q","materialId":"red",
  "positions":[-1,-1,0, 1,-1,0, 1,1,0, -1,1,0],"normals":[0,0,-1, 0,0,-1, 0,0,-1, 0,0,-1],
  "indices":[0,1,2, 0,2,3]}]}
JSON
name=ortho_should_draw_a_far_quad_at_its_size_in_world_units
if "$R" "$tmp/far.babylon" -o "$tmp/far.ppm" --size 32x32 --ortho 4 --threads 1 >"$tmp/out" 2>&1; then
    red_and_black $name "$tmp/far.ppm" 8 16 7 16
else
    fail $name "exit status $?: $(cat "$tmp/out")"
fi
fails ortho_and_fov_together_should_be_refused any "--fov and --ortho" \
    "$R" "$tmp/far.babylon" -o "$tmp/far.ppm" --ortho 4 --fov 1

# ---- levels of detail follow --camera -------------------------------------------
# A red quad with a green level of detail past 10 (which stands elsewhere in
# the file: a level is drawn in its base's place): from 5 away the red one
# is drawn, from 15 away (--camera) the green one, in the same place.
cat >"$tmp/lod.babylon" <<'JSON'
{"materials":[{"id":"red","disableLighting":true,"emissive":[1,0,0],"backFaceCulling":false},
  {"id":"green","disableLighting":true,"emissive":[0,1,0],"backFaceCulling":false}],
 "cameras":[{"id":"c","position":[0,0,-5],"target":[0,0,0]}],
 "meshes":[{"id":"q","materialId":"red","lodMeshIds":["g"],"lodDistances":[10],
  "positions":[-1,-1,0, 1,-1,0, 1,1,0, -1,1,0],"indices":[0,1,2, 0,2,3]},
  {"id":"g","materialId":"green","position":[4,0,0],
  "positions":[-1,-1,0, 1,-1,0, 1,1,0, -1,1,0],"indices":[0,1,2, 0,2,3]}]}
JSON
name=the_level_of_detail_drawn_should_be_the_one_for_the_camera
if "$R" "$tmp/lod.babylon" -o "$tmp/near.ppm" --size 32x32 --threads 1 >"$tmp/out" 2>&1 &&
        "$R" "$tmp/lod.babylon" -o "$tmp/far.ppm" --size 32x32 --threads 1 \
            --camera 0,0,-15:0,0,0 >>"$tmp/out" 2>&1; then
    near=$(pixel "$tmp/near.ppm" 16 16); far=$(pixel "$tmp/far.ppm" 16 16)
    if [ "$near" = "255 0 0" ] && [ "$far" = "0 255 0" ]; then
        pass $name
    else
        fail $name "the centre is \"$near\" from 5 away and \"$far\" from 15, expected red and green"
    fi
else
    fail $name "exit status $?: $(cat "$tmp/out")"
fi

summary
