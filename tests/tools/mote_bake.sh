#!/bin/sh
# mote-bake's command line, checked on its exit status and messages: sizes
# it must refuse (spaces, past int, past MOTE_MAX_SIZE), an option without
# its value named, and why an output cannot be written; --keep-order
# leaving the vertex cache's order out. Hostile input: the
# header of every texture format compiles with -Werror (and for Cortex-M0+
# and M4, aligned, where arm-none-eabi-gcc is installed), names that clash
# with <stdint.h> and <limits.h> are refused, "a" and "A" get two include
# guards, a path that closes the header's comment is escaped, a tiny JPEG
# claiming 8192 x 8192 is refused by --max-bytes, and outputs that are
# devices, FIFOs or the scene's own files are never removed or
# overwritten. Ends with a Unity-style line "N Tests F Failures I
# Ignored" for tests/run.sh.
#
#   BIN=build/bin sh tests/tools/mote_bake.sh      (make test does this)
script=tests/tools/mote_bake.sh
. "$(dirname "$0")/common.sh"
B=${BIN:-build/bin}/mote-bake
here=$(cd "$(dirname "$0")" && pwd)
scene=$here/../data/ortho_camera.babylon
cube=$here/../../assets/cube.babylon          # textured: assets/checker.png
include=$here/../../include
CC=${CC:-cc}

fails size_with_spaces_should_be_refused 2 "--size wants WxH" "$B" "$scene" -o "$tmp/a.h" --size " 12x 3"
fails size_past_int_should_be_refused 2 "--size wants WxH" "$B" "$scene" -o "$tmp/a.h" --size 99999999999x2
fails size_past_the_limit_should_be_refused 2 "--size wants WxH" "$B" "$scene" -o "$tmp/a.h" --size 4097x2
fails a_missing_value_should_be_named 2 "--size needs a value" "$B" "$scene" -o "$tmp/a.h" --size
fails an_unknown_option_should_be_named_as_unknown 2 "unknown option --bogus" "$B" "$scene" -o "$tmp/a.h" --bogus
fails scene_should_be_an_index 2 "--scene wants a glTF scene's index" "$B" "$scene" -o "$tmp/a.h" --scene -1
printf '{"asset":{"version":"2.0"},"scenes":[{"nodes":[]}]}' >"$tmp/one.gltf"
fails a_scene_past_the_last_should_be_named 1 "limits.gltf_scene: 2 asks for scenes\[1\], but the file has 1 scene" \
    "$B" "$tmp/one.gltf" -o "$tmp/a.h" --scene 1

fails an_unwritable_output_should_say_why any "cannot create (a new file beside it): No such file or directory" \
    "$B" "$scene" -o "$tmp/no/such/folder.h"
name=a_plain_size_should_bake
if "$B" "$scene" -o "$tmp/ok.h" --size 12x3 >"$tmp/out" 2>&1 && grep -q "WIDTH 12" "$tmp/ok.h"; then
    pass $name
else
    fail $name "$(cat "$tmp/out")"
fi

# the torus's triangles reordered for the vertex cache, saying by how much;
# with --keep-order, as in the file, said nowhere, and no other change
torus=$here/../../assets/torus.babylon
name=keep_order_should_leave_the_files_order
if "$B" "$torus" -o "$tmp/order.h" >"$tmp/out" 2>&1 &&
        "$B" "$torus" -o "$tmp/kept.h" --keep-order >>"$tmp/out" 2>&1 &&
        grep -q "vertex cache: 1.02 -> 0\.[0-9]* transforms a triangle" "$tmp/order.h" &&
        ! grep -q "vertex cache" "$tmp/kept.h" &&
        [ "$(grep -v 'vertex cache' "$tmp/order.h" | grep -c .)" = "$(grep -c . "$tmp/kept.h")" ] &&
        ! cmp -s "$tmp/order.h" "$tmp/kept.h"; then
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

# ---- headers that compile ------------------------------------------------------
# compiles NAME CC FLAGS...: $tmp/use.c, including the headers it names
compiles() {
    name=$1; shift
    if "$@" -std=c99 -Wall -Wextra -Wpedantic -Werror -I"$include" -I"$tmp" -c "$tmp/use.c" \
            -o "$tmp/use.o" >"$tmp/out" 2>&1; then
        pass "$name"
    else
        fail "$name" "$(head -c 600 "$tmp/out")"
    fi
}
# the textures of each format, declared as long as they are and aligned
# to 4 bytes (an RGBA8888 texture was declared w * h bytes long, holding
# w * h * 4, and byte-aligned on Cortex-M0+, where the core refuses it)
: >"$tmp/use.c"
ok=1
for f in rgb565:2 rgba8888:4 grey8:1; do
    bytes=${f#*:}; f=${f%:*}
    "$B" "$cube" -o "$tmp/cube_$f.h" --name "cube_$f" --format "$f" >"$tmp/out" 2>&1 || ok=0
    cat >>"$tmp/use.c" <<EOF
#include "cube_$f.h"
typedef char cube_${f}_aligned[__alignof__(cube_${f}_texture0) >= 4 ? 1 : -1];
typedef char cube_${f}_long[sizeof cube_${f}_texture0.pixels == 256 * 128 * $bytes ? 1 : -1];
const mote_mesh *cube_${f}_first(void);
const mote_mesh *cube_${f}_first(void) { return &cube_${f}_meshes[0]; }
EOF
done
if [ $ok = 1 ]; then
    compiles textured_headers_of_every_format_should_compile_with_werror "$CC"
    for cpu in cortex-m0plus cortex-m4; do
        if command -v arm-none-eabi-gcc >/dev/null 2>&1; then
            compiles "textured_headers_should_compile_aligned_for_$cpu" arm-none-eabi-gcc \
                -mcpu=$cpu -mthumb -ffreestanding
        else
            ignore "textured_headers_should_compile_aligned_for_$cpu" "no arm-none-eabi-gcc"
        fi
    done
else
    fail textured_headers_of_every_format_should_compile_with_werror "$(cat "$tmp/out")"
fi

# ---- names ----------------------------------------------------------------------
for n in INT SIZE UINT8 uint_least16 mote _x; do
    fails "the_name_${n}_should_be_refused" 2 "--name '$n'" "$B" "$scene" -o "$tmp/n.h" --name "$n"
done
"$B" "$scene" -o "$tmp/a.h" --name a >/dev/null 2>&1 && "$B" "$scene" -o "$tmp/A.h" --name A \
    >/dev/null 2>&1
printf '#include "a.h"\n#include "A.h"\nint both(void);\nint both(void) { return a_meshes[0].vertex_count + A_meshes[0].vertex_count > 0; }\n' >"$tmp/use.c"
compiles a_and_A_should_have_two_include_guards "$CC"

# ---- the scene's path in the header's comment -------------------------------
evil="$tmp/x*/
#error injected
"
mkdir -p "$evil" && cp "$scene" "$evil/s.babylon"
if "$B" "$evil/s.babylon" -o "$tmp/evil.h" --name evil >"$tmp/out" 2>&1; then
    printf '#include "evil.h"\nint evil(void);\nint evil(void) { return EVIL_MESH_COUNT; }\n' >"$tmp/use.c"
    compiles a_path_closing_the_comment_should_be_escaped "$CC"
else
    fail a_path_closing_the_comment_should_be_escaped "$(cat "$tmp/out")"
fi

# ---- the size of the header --------------------------------------------------
# a 144-byte JPEG claiming 8192 x 8192 that decodes (every block from zero
# bits): it made a header of 474 MB; refused from its image header
ones() { i=0; while [ $i -lt "$1" ]; do printf '\001'; i=$((i + 1)); done; }
zeros() { i=0; while [ $i -lt "$1" ]; do printf '\000'; i=$((i + 1)); done; }
{ printf '\377\330\377\333\000\103\000'; ones 64
  printf '\377\300\000\013\010\040\000\040\000\001\001\021\000'
  printf '\377\304\000\024\000\001'; zeros 16
  printf '\377\304\000\024\020\001'; zeros 16
  printf '\377\332\000\010\001\001\000\000\077\000'; zeros 4; printf '\377\331'; } >"$tmp/huge.jpg"
cat >"$tmp/huge.babylon" <<'JSON'
{"materials":[{"id":"m","diffuseTexture":{"name":"huge.jpg"}}],
 "meshes":[{"id":"q","materialId":"m","positions":[0,0,0, 1,0,0, 0,1,0],"uvs":[0,0, 1,0, 0,1],
  "indices":[0,1,2]}]}
JSON
fails a_tiny_jpeg_claiming_a_huge_size_should_be_refused any \
    "a header of at most 67108864 bytes (--max-bytes) holds" "$B" "$tmp/huge.babylon" -o "$tmp/huge.h"
name=a_refused_header_should_not_be_written
if [ -e "$tmp/huge.h" ]; then fail $name "huge.h was written"; else pass $name; fi
fails a_header_past_max_bytes_should_be_refused any "larger than --max-bytes 5000" \
    "$B" "$scene" -o "$tmp/small.h" --max-bytes 5000

# ---- outputs ---------------------------------------------------------------------
# a link to /dev/full: the write fails, saying why, and neither the link
# nor the device is removed (the link was, and as root -o /dev/full
# removed the device itself)
if [ -c /dev/full ]; then
    ln -s /dev/full "$tmp/full.h"
    fails a_full_device_should_say_why any "No space left on device" "$B" "$scene" -o "$tmp/full.h"
    name=a_full_device_and_its_link_should_stay
    if [ -L "$tmp/full.h" ] && [ -c /dev/full ]; then pass $name; else fail $name "removed"; fi
    if mknod "$tmp/full_node" c 1 7 2>/dev/null; then
        "$B" "$scene" -o "$tmp/full_node" >/dev/null 2>&1
        name=a_device_node_should_not_be_removed
        if [ -c "$tmp/full_node" ]; then pass $name; else fail $name "the device node was removed"; fi
    fi
fi
mkfifo "$tmp/fifo.h"
fails a_fifo_no_one_reads_should_be_refused_at_once any "a FIFO that no one reads" \
    timeout 20 "$B" "$scene" -o "$tmp/fifo.h"
name=the_fifo_should_stay
if [ -p "$tmp/fifo.h" ]; then pass $name; else fail $name "removed"; fi
# the scene's own files, under other names
mkdir -p "$tmp/own" && cp "$cube" "$here/../../assets/checker.png" "$tmp/own/"
fails the_scene_itself_should_not_be_overwritten any "the scene's own file" \
    "$B" "$tmp/own/cube.babylon" -o "$tmp/own/./cube.babylon"
fails a_texture_should_not_be_overwritten any "one of its textures" \
    "$B" "$tmp/own/cube.babylon" -o "$tmp/own/../own/checker.png"
name=the_texture_should_be_unchanged
if cmp -s "$tmp/own/checker.png" "$here/../../assets/checker.png"; then pass $name; else fail $name "changed"; fi

summary
