/*
 * io_internal.h - private helpers shared by the host I/O files: one
 * allocator (with a failure-injection hook for tests), message formatting,
 * files in and out, and the textures a scene gathers. Not API.
 */
#ifndef MOTE_IO_INTERNAL_H
#define MOTE_IO_INTERNAL_H

#include <mote/mote_io.h>

#include <stdarg.h>
#include <stddef.h>
#include <stdint.h>
#include <stdio.h>

/* Process-wide counters and flags (tests' failure injection, cJSON's
 * hooks) are touched with atomic builtins where the compiler has them, so
 * that loading scenes on several threads stays well defined.
 * mote__io_claim turns *p from 0 to 1 and says whether this call did. */
#if defined(__GNUC__)
#define MOTE__IO_ADD(p, v) __atomic_add_fetch((p), (v), __ATOMIC_RELAXED)
#define MOTE__IO_LOAD(p) __atomic_load_n((p), __ATOMIC_RELAXED)
#define MOTE__IO_STORE(p, v) __atomic_store_n((p), (v), __ATOMIC_RELAXED)
#define MOTE__IO_EXCHANGE(p, v) __atomic_exchange_n((p), (v), __ATOMIC_RELAXED)
#define MOTE__IO_LOAD_ACQUIRE(p) __atomic_load_n((p), __ATOMIC_ACQUIRE)
#define MOTE__IO_STORE_RELEASE(p, v) __atomic_store_n((p), (v), __ATOMIC_RELEASE)
static inline bool mote__io_claim(int *p)
{
    int expected = 0;
    return __atomic_compare_exchange_n(p, &expected, 1, false, __ATOMIC_ACQ_REL,
                                       __ATOMIC_ACQUIRE);
}
#else
#define MOTE__IO_ADD(p, v) (*(p) += (v))
#define MOTE__IO_LOAD(p) (*(p))
#define MOTE__IO_STORE(p, v) (*(p) = (v))
#define MOTE__IO_EXCHANGE(p, v) mote__io_exchange((p), (v))
#define MOTE__IO_LOAD_ACQUIRE(p) (*(p))
#define MOTE__IO_STORE_RELEASE(p, v) (*(p) = (v))
static inline bool mote__io_claim(int *p)
{
    return *p == 0 ? (*p = 1, true) : false;
}
static inline int mote__io_exchange(int *p, int v)
{
    int old = *p;
    *p = v;
    return old;
}
#endif

/* Every allocation of src/io goes through these, so that tests can make
 * the n-th one fail and check that nothing leaks. */
void *mote__io_malloc(size_t size);
void *mote__io_calloc(size_t count, size_t size);
void mote__io_free(void *ptr);

/* Test hooks: after n more successful allocations (or decodes), the next
 * one fails; n < 0 turns failure injection off. */
void mote__io_set_alloc_failure_after(int n);
/* True while the countdown has not yet made an allocation fail. */
int mote__io_failure_pending(void);
/* Allocations (and decoded images) not yet freed, over the process. */
long mote__io_live_allocations(void);
/* Consumes one step of the failure countdown; true: pretend to fail. */
int mote__io_should_fail(void);
/* Book-keeping for buffers allocated by stb_image (freed with stbi_image_free). */
void mote__io_track(int delta);

/* snprintf into message (if any); returns code so callers can
 * `return mote__io_error(...)`. */
mote_result mote__io_error(char *message, size_t message_size, mote_result code,
                           const char *fmt, ...)
#if defined(__GNUC__)
    __attribute__((format(printf, 4, 5)))
#endif
    ;
mote_result mote__io_verror(char *message, size_t message_size, mote_result code,
                            const char *fmt, va_list ap);

/* Fills zero fields of *limits (or all, when NULL) with the defaults. */
mote_limits mote__io_limits(const mote_limits *limits);

/* ---- files (file.c) ---------------------------------------------------- */

/* Which file a name reached, whatever the name: device and inode where
 * the system has them, both 0 where it cannot tell. */
typedef struct mote__io_file_id {
    uint64_t device, inode;
} mote__io_file_id;

/* Whether a and b are known and the same file. */
bool mote__io_same_file(mote__io_file_id a, mote__io_file_id b);
/* The file path names now (links followed); unknown when there is none. */
mote__io_file_id mote__io_file_id_of(const char *path);

/* A regular file opened to be read. */
typedef struct mote__io_file {
    FILE *stream;
    mote__io_file_id id;
    char name[160];               /* its path in messages, control bytes replaced */
} mote__io_file;

/* Opens path to read. What it is, is checked on the opened descriptor,
 * never on the name beforehand: a FIFO, a directory or a device is
 * refused (MOTE_ERR_IO, "not a regular file"), and opening never waits on
 * a FIFO's writer, whatever is swapped in under the name meanwhile. */
mote_result mote__io_open(const char *path, mote__io_file *out, char *message,
                          size_t message_size);

/* Opens the file a scene in folder names (NULL or "": the current folder),
 * as mote__io_open does, under the path rules of a scene's files:
 * mote__io_name_escapes refuses the name as written (MOTE_ERR_RANGE, the
 * name quoted and why), '\\' is read as '/', and the name is resolved
 * beneath the folder as the system resolves it: a symbolic link (or a
 * link in a folder on the way) that leads outside, an absolute link and
 * /proc's magic links are refused (MOTE_ERR_RANGE), links that stay
 * inside are followed. anywhere (limits.allow_any_texture_path): any
 * name, relative ones from the folder. Other failures are MOTE_ERR_IO,
 * "folder/name: cannot open: why". */
mote_result mote__io_open_in_folder(const char *folder, const char *name, bool anywhere,
                                    mote__io_file *out, char *message, size_t message_size);

/* Whether a scene's name for a file breaks the path rules before it is
 * looked up: empty, absolute (also "C:..." and "\\..."), or a ".."
 * component; *why says which, to follow the quoted name in a message. */
bool mote__io_name_escapes(const char *name, const char **why);

/* Reads the whole of an open file (at most max_bytes) into a buffer from
 * mote__io_malloc, with one extra NUL byte after the data, and closes it. */
mote_result mote__io_read_open(mote__io_file *file, size_t max_bytes, char **data, size_t *size,
                               char *message, size_t message_size);
void mote__io_close(mote__io_file *file);

/* mote__io_open, then mote__io_read_open. */
mote_result mote__io_read_file(const char *path, size_t max_bytes, char **data,
                               size_t *size, char *message, size_t message_size);

/* Test hook: nonzero resolves scene files by the walk, one component at a
 * time, where openat2 would be used (both must refuse the same names). */
void mote__io_resolve_by_walk(int on);

/* A file being written: a new file beside the target (temp), renamed
 * over it when complete; or, for a terminal, /dev/null or a pipe (a
 * character device or a FIFO someone reads), the target itself, written
 * in place. */
typedef struct mote__io_output {
    FILE *stream;
    char *temp;                   /* NULL: written in place */
    char *target;                 /* what temp replaces (a link's file, not the link) */
} mote__io_output;

/* Opens path for writing as above. A directory, a block device, a FIFO
 * no one reads, a link to nothing: refused, MOTE_ERR_IO with why. */
mote_result mote__io_output_open(const char *path, mote__io_output *out, char *message,
                                 size_t message_size);
/* Closes out: written completely (ok, and the close succeeds), the new
 * file takes the target's place; else it is removed (never the target)
 * and the message says why ("write error: No space left on device"). */
mote_result mote__io_output_close(mote__io_output *out, bool ok, const char *path,
                                  char *message, size_t message_size);
/* Closes out and removes the new file, the target left as it was. */
void mote__io_output_discard(mote__io_output *out);

/* What a loader keeps of the files a scene was read from, for
 * mote_scene_reads_file (mote_scene.files_). */
typedef struct mote__scene_files {
    mote__io_file_id scene;       /* the scene file (mote_scene_load) */
    const mote__io_file_id *textures; /* per scene texture (unknown: embedded) */
} mote__scene_files;

/* Copies s into dst (size n) replacing control bytes with '?', and
 * shortening with "..." past n - 1 bytes: names from files are quoted in
 * messages and must not carry terminal escapes. */
void mote__io_clean_name(char *dst, size_t n, const char *s);

/* Whether s starts with "data:" (any case): an embedded image, not a file. */
bool mote__io_is_data_url(const char *s);
/* Strict base64 (RFC 4648, no line breaks or spaces): '=' only as the last
 * one or two characters of a 4-character group, padding optional (some
 * writers omit it), no lone final character. Bytes go to out (room for
 * len / 4 * 3 + 2); *bad: the offending offset on failure. */
bool mote__io_base64_decode(const char *in, size_t len, unsigned char *out, size_t *out_len,
                            size_t *bad);
/* Decodes a base64 data: URL ("data:image/png;base64,...") with strict
 * validation (decoded size within limits->max_file_bytes) and loads the
 * image as mote_texture_load_memory does. */
mote_result mote__io_texture_load_data_url(const char *url, const mote_limits *limits,
                                           mote_texture *out, char *message,
                                           size_t message_size);

/* ---- the textures of a scene (texture.c) ------------------------------- */

/* The textures a loader gathers for one scene: each file (by device and
 * inode, so "b.png", "./b.png" and a link to it are one) and each data:
 * URL decoded once, and all of them together held to
 * limits->max_total_texture_bytes, checked from each image's header
 * before it is decoded. The arrays are the loader's, room for cap. */
typedef struct mote__texture_set {
    mote_texture *textures;       /* the scene's */
    mote__io_file_id *files;      /* per texture: the file it was read from (unknown: embedded) */
    const char **urls;            /* per texture: the data: URL it was decoded from, or NULL */
    int count, cap;
    size_t bytes;                 /* decoded bytes of all of them */
} mote__texture_set;

/* The texture in the file `name` in folder (mote__io_open_in_folder, under
 * the path rules of limits->allow_any_texture_path): *index, the set's
 * texture already read from that file, or a new one. Messages as
 * mote__io_open_in_folder's and mote_texture_load's ("folder/name: why");
 * MOTE_ERR_RANGE only for a name that breaks the path rules. */
mote_result mote__texture_set_file(mote__texture_set *set, const char *folder, const char *name,
                                   const mote_limits *limits, int *index, char *message,
                                   size_t message_size);
/* The same for an image embedded as a data: URL. */
mote_result mote__texture_set_data_url(mote__texture_set *set, const char *url,
                                       const mote_limits *limits, int *index, char *message,
                                       size_t message_size);

/* The same for size bytes of an image held in memory (a glTF buffer
 * view), decoded each time: its caller names each image once. */
mote_result mote__texture_set_memory(mote__texture_set *set, const void *data, size_t size,
                                     const mote_limits *limits, int *index, char *message,
                                     size_t message_size);

/* Whether w x h pixels are more than *limits allow: the decode refuses
 * every such image by its size, before stb_image decodes it. */
bool mote__texture_over_limits(const mote_limits *limits, size_t w, size_t h);

/* The image format stb_image takes size bytes for: its tests in its order
 * (PNG, BMP, GIF, PSD, PIC, JPEG, PNM, HDR, TGA), the first that passes
 * (stb_guard.c). */
typedef enum mote__image_format {
    MOTE__IMAGE_NONE, MOTE__IMAGE_PNG, MOTE__IMAGE_BMP, MOTE__IMAGE_GIF, MOTE__IMAGE_PSD,
    MOTE__IMAGE_PIC, MOTE__IMAGE_JPEG, MOTE__IMAGE_PNM, MOTE__IMAGE_HDR, MOTE__IMAGE_TGA
} mote__image_format;

mote__image_format mote__stb_image_format(const unsigned char *data, size_t size);

/* The guard of the system stb_image (stb_guard.c): looks at an image's
 * bytes as stb_image will read them, before it does, and refuses those
 * that reach its known faults (MOTE_ERR_PARSE with a message); where its
 * palette lookups would read uninitialised memory, makes a copy padded
 * with black entries (*fixed, from mote__io_malloc, *fixed_size bytes;
 * NULL when the bytes are fine as they are) to be decoded in their place.
 * An image larger than *limits allow (mote__texture_over_limits) is
 * passed unlooked-at: the decode refuses it by its size, and its scans
 * could take long to walk. */
mote_result mote__stb_guard(const unsigned char *data, size_t size, const mote_limits *limits,
                            unsigned char **fixed, size_t *fixed_size, char *message,
                            size_t message_size);

#endif
