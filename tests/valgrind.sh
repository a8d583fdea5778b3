#!/bin/sh
# Runs the chapter examples and mote-render under valgrind memcheck, on good
# input and on error paths (missing file, malformed scenes, bad arguments),
# and ends with a Unity-style line "N Tests F Failures I Ignored" so that
# tests/run.sh can count it. A case fails when memcheck reports an error or
# a leak (--leak-check=full), or when the program's exit status is not the
# expected one (0 for good input, non-zero for an error).
#
#   BIN=build/bin sh tests/valgrind.sh        (make valgrind does this)
#
# Without valgrind, or with binaries built with ASan (SAN=1), every case is
# ignored with a message.
set -u
BIN=${BIN:-build/bin}
VALGRIND=${VALGRIND:-valgrind}
tmp=$(mktemp -d)
trap 'rm -rf "$tmp"' EXIT INT TERM
tests=0; failures=0; ignored=0
skip_all=""

if ! command -v "$VALGRIND" >/dev/null 2>&1; then
    skip_all="valgrind is not installed (apt-get install valgrind)"
elif [ ! -x "$BIN/mote-render" ]; then
    skip_all="$BIN/mote-render is not built (make examples)"
elif grep -q __asan_init "$BIN/mote-render" 2>/dev/null; then
    skip_all="$BIN holds ASan binaries (SAN=1); valgrind cannot run them"
fi

ignore() {  # name why
    tests=$((tests + 1)); ignored=$((ignored + 1))
    echo "tests/valgrind.sh:0:$1:IGNORE: $2"
}

# check NAME EXPECT CMD...   EXPECT: ok (exit 0), fail (exit non-zero), any
check() {
    name=$1; expect=$2; shift 2
    tests=$((tests + 1))
    if [ -n "$skip_all" ]; then
        ignored=$((ignored + 1))
        echo "tests/valgrind.sh:0:$name:IGNORE: $skip_all"
        return
    fi
    log=$tmp/$name.vg
    # --error-exitcode=1 for good input; on error paths the program itself
    # exits 1, so memcheck's verdict is read from its log in every case.
    code=1
    [ "$expect" = ok ] || code=97
    "$VALGRIND" --tool=memcheck --error-exitcode=$code --leak-check=full \
        --suppressions=tests/valgrind.supp \
        --errors-for-leak-kinds=definite,indirect,possible --show-leak-kinds=definite,indirect,possible \
        --log-file="$log" "$@" >"$tmp/$name.out" 2>&1
    rc=$?
    why=""
    if ! grep -q "ERROR SUMMARY: 0 errors" "$log"; then
        why="memcheck: $(grep 'ERROR SUMMARY' "$log" | head -n 1 | sed 's/^==[0-9]*== //')"
    elif [ "$expect" = ok ] && [ "$rc" -ne 0 ]; then
        why="exit status $rc, expected 0: $(tail -n 1 "$tmp/$name.out")"
    elif [ "$expect" = fail ] && [ "$rc" -eq 0 ]; then
        why="exit status 0, expected an error"
    elif [ "$rc" -eq 97 ]; then
        why="memcheck reported errors"
    fi
    if [ -n "$why" ]; then
        failures=$((failures + 1))
        echo "tests/valgrind.sh:0:$name:FAIL: $why ($*)"
        grep -E 'Invalid|uninitialised|definitely|indirectly|possibly|at 0x|by 0x' "$log" | head -n 20 | sed 's/^/    /'
    else
        echo "tests/valgrind.sh:0:$name:PASS"
    fi
}

R=$BIN/mote-render

# ---- good input --------------------------------------------------------------
for e in "$BIN"/[0-9][0-9]_*; do
    [ -x "$e" ] || continue
    check "example_${e##*/}_should_run_clean" ok "$e" "$tmp"
done
check mote_render_should_render_the_cube_clean ok \
    "$R" assets/cube.babylon -o "$tmp/cube.png" --size 64x48 --threads 1
check mote_render_should_render_a_legacy_layout_scene_clean ok \
    "$R" assets/sphere.legacy.babylon -o "$tmp/sphere.ppm" --size 80x60 --mode gouraud --threads 1
check mote_render_should_render_every_mode_option_clean ok \
    "$R" assets/demo.babylon -o "$tmp/demo.png" --size 96x72 --mode textured --perspective subspan \
    --filter bilinear --subpixel-bits 4 --no-cull --threads 1
check mote_render_should_time_frames_on_threads_clean ok \
    "$R" assets/torus.babylon -o "$tmp/torus.png" --size 64x64 --frames 2 --spin 30 --threads 2
if [ -f ../shared/assets/monkey.babylon ]; then
    check mote_render_should_render_the_monkey_clean ok \
        "$R" ../shared/assets/monkey.babylon -o "$tmp/monkey.png" --size 64x48 --threads 1
else
    ignore mote_render_should_render_the_monkey_clean "../shared/assets/monkey.babylon is absent"
fi
# glTF: gen_gltf's demo (a .glb with an embedded image) and a .gltf with
# its buffer in a file, and every glTF file of assimp-testmodels
if [ -x "$BIN/gen_gltf" ] && "$BIN/gen_gltf" "$tmp" >/dev/null 2>&1; then
    check mote_render_should_render_a_glb_clean ok \
        "$R" "$tmp/demo.glb" -o "$tmp/glb.png" --size 64x48 --threads 1
    check mote_render_should_render_a_gltf_with_a_bin_file_clean ok \
        "$R" "$tmp/materials.gltf" -o "$tmp/gltf.png" --size 64x48 --threads 1
else
    ignore mote_render_should_render_a_glb_clean "$BIN/gen_gltf is not built (make tools)"
fi
for f in /usr/share/assimp/models/glTF2/*/*.gl* /usr/share/assimp/models/glTF/*/*.gl*; do
    [ -f "$f" ] || continue
    n=$(echo "$f" | sed 's|/usr/share/assimp/models/||' | tr -c 'A-Za-z0-9_\n' '_')
    check "mote_render_should_handle_${n}_clean" any "$R" "$f" -o "$tmp/g.png" --size 16x12 --threads 1
done
check mote_render_should_print_help_clean ok "$R" --help
check mote_render_should_draw_a_scene_missing_a_texture_when_allowed_clean ok \
    "$R" tests/data/bad/texture_missing.babylon -o "$tmp/missing.png" --size 16x12 --threads 1 \
    --allow-missing-textures
check mote_render_should_list_every_warning_clean ok \
    "$R" tests/data/bad/texture_missing.babylon -o "$tmp/missing.png" --size 16x12 --threads 1 \
    --allow-missing-textures --warnings --camera 0,0,-9:0,0,0 --near 0.5

# ---- error paths -------------------------------------------------------------
check mote_render_should_refuse_a_missing_file_clean fail \
    "$R" "$tmp/no-such-scene.babylon" -o "$tmp/x.png"
check mote_render_should_refuse_an_unwritable_output_clean fail \
    "$R" assets/cube.babylon -o "$tmp/no-such-dir/x.png" --size 16x16 --threads 1
check mote_render_should_refuse_no_arguments_clean fail "$R"
check mote_render_should_refuse_an_unknown_option_clean fail "$R" assets/cube.babylon -o "$tmp/x.png" --bogus
check mote_render_should_refuse_a_bad_size_clean fail "$R" assets/cube.babylon -o "$tmp/x.png" --size 0x99999
check mote_render_should_refuse_a_missing_value_clean fail "$R" assets/cube.babylon -o
check mote_render_should_refuse_a_bad_mode_clean fail "$R" assets/cube.babylon -o "$tmp/x.png" --mode plaid
check mote_render_should_refuse_a_bad_camera_clean fail "$R" assets/cube.babylon -o "$tmp/x.png" --camera 1,2
# Every malformed scene of the loader's corpus: some load with a warning,
# so only memcheck's verdict counts here.
for f in tests/data/bad/*.babylon; do
    [ -f "$f" ] || continue
    n=$(basename "$f" .babylon | tr -c 'A-Za-z0-9_\n' '_')
    check "mote_render_should_handle_bad_${n}_clean" any "$R" "$f" -o "$tmp/bad.png" --size 16x12 --threads 1
done

echo
echo "-----------------------"
echo "$tests Tests $failures Failures $ignored Ignored"
[ "$failures" -eq 0 ] && echo "OK" || echo "FAIL"
[ "$failures" -eq 0 ]
