/*
 * fuzz_entry.h - the entry points shared by the libFuzzer targets
 * (tests/fuzz/fuzz_*.c, clang) and the corpus replay in `make test`
 * (tests/test_fuzz_regressions.c, any compiler). Plain C99, no libFuzzer.
 *
 * Each function consumes one arbitrary input and returns NULL when every
 * invariant held, or a short description of the one that broke. Memory
 * errors and undefined behaviour are left to the sanitizers (ASan, UBSan)
 * the caller was built with; canary bytes around every buffer the renderer
 * writes catch stray writes even without them.
 */
#ifndef MOTE_FUZZ_ENTRY_H
#define MOTE_FUZZ_ENTRY_H

#include <stddef.h>
#include <stdint.h>

/* The draw path: device, frame, meshes, textures and draw options decoded
 * from the bytes; checks canaries, flush order and that full frame, bands,
 * arena (large or tiny) and tile order all give the same bytes. */
const char *mote_fuzz_draw(const uint8_t *data, size_t size);

/* mote_texture_load_memory on the bytes; a decoded image is drawn. */
const char *mote_fuzz_texture(const uint8_t *data, size_t size);

/* mote_scene_load_memory on the bytes (without textures, then with a
 * folder holding a texture); a loaded scene is drawn, and loaded again
 * with an allocation failing part-way. */
const char *mote_fuzz_scene(const uint8_t *data, size_t size);

/* glTF through mote_fuzz_scene: the bytes as they are (a .gltf's JSON or
 * a .glb), or, when the first byte is 1, a .glb made of the rest: its
 * JSON up to the first NUL byte, its BIN chunk after it (so that mutations
 * reach the JSON and the binary data behind a valid container). */
const char *mote_fuzz_gltf(const uint8_t *data, size_t size);

/* A folder tree built from the input's lines (folders, inside textures,
 * FIFOs, links to anywhere, outside/ included) and a texture name: the
 * name is opened beneath the scene's folder by openat2 and by the walk,
 * which must open the same file, one of the folder's own; a scene naming
 * it never loads the texture outside. */
const char *mote_fuzz_folder(const uint8_t *data, size_t size);

#endif
