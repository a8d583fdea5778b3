/*
 * loader.h - what every scene loader shares: the scene being built (the
 * allocations it keeps and the load's temporaries), the limits, the
 * message of a failure and the warnings, and the textures a scene names.
 * Not API.
 *
 * src/io, by concern:
 *   scene.c               mote_scene_load*: tells the format by the bytes and
 *                         hands them to its loader (or says what they are);
 *                         framing, draw options, levels of detail
 *   loader.[ch]           the scene being built: stores, limits, messages,
 *                         warnings, freeing
 *   scene_texture.c       the textures a scene names: path rules, URL-encoded
 *                         names, data: URLs, one decode per file
 *   json.[ch]             cJSON getters that name the JSON path in messages,
 *                         number checks, the nesting limit
 *   matrix_fold.[ch]      right-handed files mirrored in z; a node's affine
 *                         matrix folded into the core's T R S
 *   babylon*.[ch]         the .babylon loader (docs/babylon.md)
 *   texture.c             images through the system stb_image
 *   stb_guard*.[ch]       stb_image's known faults kept from it (PNG and
 *                         JPEG in files of their own)
 *   image_write.c         PNG and PPM output
 *   common.c, io_internal.h  allocator, messages, limits, file reading
 *
 * A loader of another format includes loader.h, json.h when it reads JSON,
 * and matrix_fold.h, and is called from scene.c.
 */
#ifndef MOTE_IO_LOADER_H
#define MOTE_IO_LOADER_H

#include "io_internal.h"

#include <stdint.h>

/* Returns from the calling function with expr's result unless it is MOTE_OK. */
#define MOTE__TRY(expr)               \
    do {                              \
        mote_result r__ = (expr);     \
        if (r__ != MOTE_OK)           \
            return r__;               \
    } while (0)

/* ---- allocations ------------------------------------------------------- */

/* Allocations released together: a scene's (scene->storage_) or a load's
 * temporaries. */
typedef struct mote__store {
    void **ptrs;
    size_t count, cap;
} mote__store;

/* Zeroed memory recorded in s; NULL when out of memory or when count x
 * size overflows (nothing leaks). */
void *mote__store_alloc(mote__store *s, size_t count, size_t size);
void mote__store_release(mote__store *s);

/* ---- a load in progress ------------------------------------------------ */

/* The distinct warnings a scene keeps (mote_scene_warning); those past
 * them are counted. A file that warns once per mesh keeps them all up to
 * here, in 12 bytes each plus their text. */
#define MOTE__MAX_WARNINGS 4096

/* Every distinct warning of a load, in the order first given, and how
 * many times each was given: the texts and both arrays in the scene's
 * store (what mote_scene.warnings_ points to), the lookup in the load's
 * temporaries; allocated at the first warning. */
typedef struct mote__warnings {
    const char **text;
    unsigned *count;
    int n;
    unsigned dropped;             /* distinct ones given past MOTE__MAX_WARNINGS, or
                                     that could not be allocated */
    int *slots;                   /* by the text's hash: index + 1, 0 empty */
} mote__warnings;

typedef struct mote__loader {
    char name[128];               /* the file's name, first in every message */
    const char *base_dir;         /* texture files resolve here; NULL: none are loaded */
    mote_limits lim;              /* the caller's, zero fields filled with the defaults */
    char *msg;                    /* the caller's message buffer */
    size_t msg_size;
    mote_scene *scene;            /* what is built; zeroed again when the load fails */
    mote__store *keep;            /* becomes scene->storage_ */
    mote__store tmp;              /* released when the load ends */
    mote__texture_set textures;   /* scene->textures, each file or data: URL decoded once
                                     (mote__texture_slots) */
    mote__warnings *warnings;     /* NULL until the first warning */
    bool warning_lost;            /* out of memory for a warning: the load fails so */
} mote__loader;

/* Starts loading size bytes into *out (zeroed): the name cleaned for
 * messages, the limits filled in, the size checked against them, the
 * scene's store made. A failure here leaves nothing to free. */
mote_result mote__loader_begin(mote__loader *ld, const char *name, const char *base_dir,
                               const mote_limits *limits, size_t size, mote_scene *out,
                               char *message, size_t message_size);
/* Ends the load whose result is r: the scene's triangles checked against
 * limits.max_triangles, the temporaries released and, when that leaves
 * an error, the scene freed and zeroed. Returns the result. */
mote_result mote__loader_end(mote__loader *ld, mote_result r);

/* The message "NAME: what" (printf-style); returns code. */
mote_result mote__fail(mote__loader *ld, mote_result code, const char *fmt, ...)
#if defined(__GNUC__)
    __attribute__((format(printf, 3, 4)))
#endif
    ;
/* "NAME: at: out of memory", MOTE_ERR_OUT_OF_MEMORY. */
mote_result mote__oom(mote__loader *ld, const char *at);
/* MOTE_ERR_LIMIT, "NAME: at: COUNT WHAT, more than the limit of LIMIT",
 * when count is over limit or past what an int counts: counts are checked
 * so before anything is allocated for them. */
mote_result mote__check_count(mote__loader *ld, const char *at, size_t count,
                              const char *what, size_t limit);

/* A non-fatal note, kept for mote_scene_warning and shown in
 * scene->warning: each distinct one once, " (xN)" when given N times,
 * "; N more warnings" for those that do not fit. */
void mote__warn(mote__loader *ld, const char *fmt, ...)
#if defined(__GNUC__)
    __attribute__((format(printf, 2, 3)))
#endif
    ;

/* A name from the file, safe to print (no control bytes, bounded). */
typedef struct mote__quoted {
    char s[72];
} mote__quoted;

mote__quoted mote__quote(const char *s);

/* Widens sc->bounds_min/max to m's vertices in world space (non-finite
 * ones skipped); *any: whether the box holds a point yet. */
void mote__scene_bounds_add(mote_scene *sc, const mote_mesh *m, bool *any);

/* A 0..1 colour channel as a byte, rounded, clamped (NaN: 0). */
uint8_t mote__unit_byte(float c);

/* A metallic-roughness material as mote approximates it, for every
 * loader's PBR materials (docs/babylon.md): the colour (its bytes as
 * given, white when unset) x (1 - metallic) lit diffusely, highlights of
 * colour 0.04 (1 - metallic) + colour x metallic and the Blinn-Phong
 * power 2 / roughness^4 - 2 of a GGX lobe that rough. metallic is
 * clamped to [0, 1], roughness to [0.05, 1]. */
void mote__metallic_roughness(mote_material *mat, float metallic, float roughness);

/* ---- textures (scene_texture.c) ---------------------------------------- */

/* Room for n textures in scene->textures, allocated once so that the
 * pointers materials keep stay valid; at names the place in messages. */
mote_result mote__texture_slots(mote__loader *ld, size_t n, const char *at);

/* The texture a material names into m->texture: `embedded`, a base64
 * data: URL, or else `name`, a file in the scene's folder (as written,
 * else read as a URL: "?query" dropped, %XX decoded), under the path rules
 * (limits.allow_any_texture_path); a web address is never downloaded.
 * Each path or URL is decoded once however many materials name it. at and
 * key name the place in messages; with no base_dir, nothing is loaded. A
 * texture that cannot be loaded fails the load, or with
 * limits.missing_texture_is_warning leaves m untextured with a warning. */
mote_result mote__scene_texture(mote__loader *ld, const char *at, const char *key,
                                const char *name, const char *embedded, mote_material *m);

/* The same for an image held in the scene file itself (size bytes of
 * data: a glTF buffer view), decoded each time it is named: the caller
 * names each one once. */
mote_result mote__scene_texture_bytes(mote__loader *ld, const char *at, const char *key,
                                      const void *data, size_t size, mote_material *m);

/* A file name written as a URL ("my%20tex.png?v=2", as web exporters
 * write them) read as a file name: the "?query" dropped and %XX escapes
 * decoded. An invalid escape, or %00, leaves the escapes as written.
 * *out NULL: the same as name; else in the temporary store. */
mote_result mote__url_decoded_name(mote__loader *ld, const char *at, const char *name,
                                   char **out);

/* ---- the loaded scene (scene.c) ---------------------------------------- */

/* Shows lods[g]'s base (chosen -1) or its level `chosen` in meshes, and
 * hides the rest of the group (all of it when the group is hidden). */
void mote__lod_show(const mote_scene *sc, mote_mesh *meshes, int g, int chosen);

#endif
