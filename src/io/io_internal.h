/*
 * io_internal.h - private helpers shared by the host I/O files: one
 * allocator (with a failure-injection hook for tests), message formatting
 * and file reading. Not API.
 */
#ifndef MOTE_IO_INTERNAL_H
#define MOTE_IO_INTERNAL_H

#include <mote/mote_io.h>

#include <stdarg.h>
#include <stddef.h>

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

/* Reads a whole file (at most max_bytes) into a buffer from mote__io_malloc,
 * with one extra NUL byte after the data. */
mote_result mote__io_read_file(const char *path, size_t max_bytes, char **data,
                               size_t *size, char *message, size_t message_size);

/* Copies s into dst (size n) replacing control bytes with '?', and
 * shortening with "..." past n - 1 bytes: names from files are quoted in
 * messages and must not carry terminal escapes. */
void mote__io_clean_name(char *dst, size_t n, const char *s);

/* Whether s starts with "data:" (any case): an embedded image, not a file. */
bool mote__io_is_data_url(const char *s);
/* Decodes a base64 data: URL ("data:image/png;base64,...") with strict
 * validation (decoded size within limits->max_file_bytes) and loads the
 * image as mote_texture_load_memory does. */
mote_result mote__io_texture_load_data_url(const char *url, const mote_limits *limits,
                                           mote_texture *out, char *message,
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
