#!/bin/sh
# mote-render's options, checked on what the tool writes and says: each case
# runs it on a small scene written here and looks at its exit status, its
# messages and the pixels of the PPM it wrote; and hostile input (links out
# of the scene's folder, outputs over the scene's own files or onto a full
# device, 2,000 instances under an address-space limit). Ends with a
# Unity-style line
# "N Tests F Failures I Ignored" for tests/run.sh.
#
#   BIN=build/bin sh tests/tools/mote_render.sh      (make test does this)
script=tests/tools/mote_render.sh
. "$(dirname "$0")/common.sh"
R=${BIN:-build/bin}/mote-render
here=$(cd "$(dirname "$0")" && pwd)

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
{"materials":[{"id":"red","diffuse":[1,0,0],"specular":[0,0,0],"diffuseTexture":{"name":"no-such-image.png"}}],
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

fails a_missing_texture_should_name_the_option_that_downgrades_it any \
    "no-such-image.png.*(--allow-missing-textures draws its material untextured)" \
    "$R" "$tmp/missing.babylon" -o "$tmp/missing.ppm" --size 16x16 --threads 1

# ---- --camera, --near, --far on a scene without a camera --------------------------
# The framing camera's planes hold the scene from its own eye; --camera
# fits them again from the eye given: a red quad seen from 50 away (past
# the framing far plane, through a narrow field of view) and from 0.5 away
# (inside its near plane) fills the view both times. --far 1 from 50 away
# leaves it out.
cat >"$tmp/nocam.babylon" <<'JSON'
{"materials":[{"id":"red","disableLighting":true,"emissive":[1,0,0],"backFaceCulling":false}],
 "meshes":[{"id":"q","materialId":"red",
  "positions":[-1,-1,0, 1,-1,0, 1,1,0, -1,1,0],"indices":[0,1,2, 0,2,3]}]}
JSON
for view in 50:0.03 0.5:0.8; do
    eye=${view%:*}
    name=camera_from_${eye}_away_should_fit_the_planes_to_the_scene
    if "$R" "$tmp/nocam.babylon" -o "$tmp/nocam.ppm" --size 16x16 --threads 1 \
            --camera 0,0,-$eye:0,0,0 --fov ${view#*:} >"$tmp/out" 2>&1; then
        centre=$(pixel "$tmp/nocam.ppm" 8 8)
        if [ "$centre" = "255 0 0" ]; then pass $name; else fail $name "centre \"$centre\", expected red"; fi
    else
        fail $name "exit status $?: $(cat "$tmp/out")"
    fi
done
name=far_should_set_the_far_plane
if "$R" "$tmp/nocam.babylon" -o "$tmp/nocam.ppm" --size 16x16 --threads 1 \
        --camera 0,0,-50:0,0,0 --fov 0.03 --far 1 --near 0.5 >"$tmp/out" 2>&1; then
    centre=$(pixel "$tmp/nocam.ppm" 8 8)
    if [ "$centre" = "0 0 0" ]; then pass $name; else fail $name "centre \"$centre\", expected black"; fi
else
    fail $name "exit status $?: $(cat "$tmp/out")"
fi
fails near_beyond_far_should_be_refused any "near must be below far" \
    "$R" "$tmp/nocam.babylon" -o "$tmp/nocam.ppm" --near 2 --far 1

# ---- options and warnings ------------------------------------------------------
fails an_unknown_option_should_be_named_as_unknown any "unknown option --bogus" \
    "$R" "$tmp/nocam.babylon" -o "$tmp/nocam.ppm" --bogus
fails an_unknown_option_with_a_value_should_be_named_as_unknown any "unknown option --bogus" \
    "$R" "$tmp/nocam.babylon" -o "$tmp/nocam.ppm" --bogus 3
fails a_known_option_without_its_value_should_say_so any "\-\-size needs a value" \
    "$R" "$tmp/nocam.babylon" -o "$tmp/nocam.ppm" --size
# 30 meshes naming 30 missing materials: one line shows what fits and
# points at --warnings, which prints each on a line of its own
awk 'BEGIN { printf "{\"meshes\":["
    for (i = 0; i < 30; i++) printf "%s{\"id\":\"m%d\",\"materialId\":\"x%d\"}", (i ? "," : ""), i, i
    printf "]}" }' >"$tmp/warn.babylon"
name=warnings_should_list_every_warning
if "$R" "$tmp/warn.babylon" -o "$tmp/warn.ppm" --size 8x8 --threads 1 >"$tmp/out" 2>&1 &&
        "$R" "$tmp/warn.babylon" -o "$tmp/warn.ppm" --size 8x8 --threads 1 --warnings \
            >"$tmp/all" 2>&1 && "$R" "$tmp/warn.babylon" -o "$tmp/warn.ppm" --size 8x8 -v \
            >"$tmp/v" 2>&1; then
    lines=$(grep -c "^mote-render: warning: meshes\[[0-9]*\].materialId: \"x[0-9]*\" names no material$" "$tmp/all")
    if ! grep -q "more warnings (--warnings lists them all)" "$tmp/out"; then
        fail $name "the line does not point at --warnings: $(cat "$tmp/out")"
    elif [ "$lines" -ne 30 ] || ! grep -q '"x29"' "$tmp/all" || ! cmp -s "$tmp/all" "$tmp/v"; then
        fail $name "$lines lines of 30 with --warnings (-v the same): $(cat "$tmp/all")"
    else
        pass $name
    fi
else
    fail $name "exit status $?: $(cat "$tmp/out" "$tmp/all")"
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

# ---- hostile input --------------------------------------------------------------
# A texture linked from outside the scene's folder is not drawn: the load
# fails, naming the link (it was opened and drawn).
mkdir -p "$tmp/scene" "$tmp/outside"
cp "$here/../../assets/checker.png" "$tmp/outside/outside.png"
ln -s ../outside/outside.png "$tmp/scene/link.png"
sed 's/no-such-image.png/link.png/' "$tmp/missing.babylon" >"$tmp/scene/link.babylon"
fails a_texture_linked_from_outside_should_not_be_read any "\"link.png\" leads out of the scene's folder" \
    "$R" "$tmp/scene/link.babylon" -o "$tmp/link.ppm" --size 16x16 --threads 1

# The output never overwrites the scene or its textures, whatever the name.
cp "$here/../../assets/checker.png" "$tmp/scene/tex.png"
sed 's/no-such-image.png/tex.png/' "$tmp/missing.babylon" >"$tmp/scene/tex.babylon"
fails the_output_should_not_overwrite_a_texture any "one of its textures: not overwritten" \
    "$R" "$tmp/scene/tex.babylon" -o "$tmp/scene/./tex.png" --size 16x16
name=the_texture_should_be_unchanged
if cmp -s "$tmp/scene/tex.png" "$here/../../assets/checker.png"; then pass $name; else fail $name "changed"; fi

# A failed write says why and removes nothing it did not create.
if [ -c /dev/full ]; then
    ln -s /dev/full "$tmp/full.ppm"
    fails a_full_device_should_say_why any "write error: No space left on device" \
        "$R" "$tmp/far.babylon" -o "$tmp/full.ppm" --size 16x16
    name=the_link_to_the_full_device_should_stay
    if [ -L "$tmp/full.ppm" ]; then pass $name; else fail $name "removed"; fi
fi

# 2,000 instances of a 968-triangle mesh: the binning arena was sized for
# every triangle twice over (1.2 GB here, and "out of memory" for larger
# scenes); capped, the frame is drawn under a 1 GB address-space limit.
# ASan reserves terabytes of address space: no limit then. Its 1.9
# million triangles pass the default limit of the triangles drawn.
awk 'BEGIN {
    n = 22
    printf "{\"cameras\":[{\"id\":\"c\",\"position\":[0,0,-2000],\"target\":[0,0,0]}],"
    printf "\"materials\":[{\"id\":\"w\",\"disableLighting\":true,\"emissive\":[1,1,1]}],"
    printf "\"meshes\":[{\"id\":\"g\",\"materialId\":\"w\",\"positions\":["
    for (y = 0; y <= n; y++) for (x = 0; x <= n; x++) printf "%s%d,%d,0", (x + y ? "," : ""), x, y
    printf "],\"indices\":["
    for (y = 0; y < n; y++) for (x = 0; x < n; x++) {
        a = y * (n + 1) + x; b = a + n + 1
        printf "%s%d,%d,%d,%d,%d,%d", (x + y ? "," : ""), a, a + 1, b, a + 1, b + 1, b
    }
    printf "],\"instances\":["
    for (i = 1; i < 2000; i++)
        printf "%s{\"name\":\"i%d\",\"position\":[%d,%d,0]}", (i > 1 ? "," : ""), i,
            (i % 50) * 30 - 750, int(i / 50) * 30 - 600
    printf "]}]}"
}' >"$tmp/many.babylon"
name=two_thousand_instances_should_render_in_a_bounded_arena
if grep -q __asan_init "$R" 2>/dev/null; then limit=unlimited; else limit=1000000; fi
if (ulimit -v $limit && "$R" "$tmp/many.babylon" -o "$tmp/many.ppm" --size 160x120 --threads 1 \
        --max-triangles 2000000) \
        >"$tmp/out" 2>&1; then
    # past the 15-byte header "P6\n160 120\n255\n", some byte not 0
    if [ "$(od -An -tu1 -j 15 "$tmp/many.ppm" | tr -d ' 0\n' | wc -c)" -gt 0 ]; then
        pass $name
    else
        fail $name "nothing drawn"
    fi
else
    fail $name "$(cat "$tmp/out")"
fi

fails the_triangle_limit_should_be_named any "1936000 triangles in its 2000 meshes (instances count), more than the limit of 1048576 (max_triangles)" \
    "$R" "$tmp/many.babylon" -o "$tmp/many.ppm" --size 160x120 --threads 1
fails max_triangles_should_be_a_count any "\-\-max-triangles \"0\": expected a count" \
    "$R" "$tmp/many.babylon" -o "$tmp/many.ppm" --max-triangles 0

# ---- --scene ----------------------------------------------------------------
printf '{"asset":{"version":"2.0"},"scenes":[{"nodes":[]},{"nodes":[]}]}' >"$tmp/two.gltf"
fails a_scene_past_the_last_should_be_named any "limits.gltf_scene: 3 asks for scenes\[2\], but the file has 2 scenes" \
    "$R" "$tmp/two.gltf" -o "$tmp/two.ppm" --scene 2
fails scene_should_be_an_index any "\-\-scene \"x\": expected a scene's index from 0" \
    "$R" "$tmp/two.gltf" -o "$tmp/two.ppm" --scene x

# ---- threads --------------------------------------------------------------
# The tiles on the pool's threads, the caller among them: the same bytes as
# on the calling thread alone, and timed frames in between change nothing.
name=threads_should_draw_the_bytes_of_one_thread
if "$R" assets/demo.babylon -o "$tmp/t1.ppm" --size 200x150 --threads 1 >"$tmp/out" 2>&1 &&
        "$R" assets/demo.babylon -o "$tmp/t3.ppm" --size 200x150 --threads 3 --frames 3 >>"$tmp/out" 2>&1; then
    if cmp -s "$tmp/t1.ppm" "$tmp/t3.ppm"; then pass $name; else fail $name "the images differ"; fi
else
    fail $name "$(cat "$tmp/out")"
fi

summary
