/*
 * common.c - the allocator, messages, limits and file reading shared by
 * src/io. The counters below exist for the failing-allocator tests; they are
 * updated with atomic builtins where the compiler has them, so that loading
 * scenes on several threads stays well defined.
 */
#include "io_internal.h"

#include <errno.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>

#if defined(__unix__) || defined(__APPLE__)
#include <sys/stat.h>
#endif

static long mote__fail_after = -1;
static long mote__live;

#if defined(__GNUC__)
#define MOTE__ADD(p, v) __atomic_add_fetch((p), (v), __ATOMIC_RELAXED)
#define MOTE__LOAD(p) __atomic_load_n((p), __ATOMIC_RELAXED)
#define MOTE__STORE(p, v) __atomic_store_n((p), (v), __ATOMIC_RELAXED)
#else
#define MOTE__ADD(p, v) (*(p) += (v))
#define MOTE__LOAD(p) (*(p))
#define MOTE__STORE(p, v) (*(p) = (v))
#endif

void mote__io_set_alloc_failure_after(int n)
{
    MOTE__STORE(&mote__fail_after, (long)(n < 0 ? -1 : n));
}

int mote__io_failure_pending(void)
{
    return MOTE__LOAD(&mote__fail_after) >= 0;
}

long mote__io_live_allocations(void)
{
    return MOTE__LOAD(&mote__live);
}

int mote__io_should_fail(void)
{
    if (MOTE__LOAD(&mote__fail_after) < 0)
        return 0;
    /* one-shot: the n-th request fails, later ones succeed again */
    return MOTE__ADD(&mote__fail_after, -1) == -1;
}

void mote__io_track(int delta)
{
    MOTE__ADD(&mote__live, (long)delta);
}

void *mote__io_malloc(size_t size)
{
    if (mote__io_should_fail())
        return NULL;
    void *p = malloc(size ? size : 1);
    if (p)
        mote__io_track(1);
    return p;
}

void *mote__io_calloc(size_t count, size_t size)
{
    if (mote__io_should_fail())
        return NULL;
    if (count == 0 || size == 0)
        count = size = 1;
    void *p = calloc(count, size);
    if (p)
        mote__io_track(1);
    return p;
}

void mote__io_free(void *ptr)
{
    if (ptr) {
        free(ptr);
        mote__io_track(-1);
    }
}

mote_result mote__io_verror(char *message, size_t message_size, mote_result code,
                            const char *fmt, va_list ap)
{
    if (message && message_size > 0)
        vsnprintf(message, message_size, fmt, ap);
    return code;
}

mote_result mote__io_error(char *message, size_t message_size, mote_result code,
                           const char *fmt, ...)
{
    va_list ap;
    va_start(ap, fmt);
    mote__io_verror(message, message_size, code, fmt, ap);
    va_end(ap);
    return code;
}

mote_limits mote_limits_default(void)
{
    mote_limits l;
    memset(&l, 0, sizeof l);
    l.max_file_bytes = (size_t)256 << 20;
    l.max_vertices = 16u << 20;
    l.max_indices = 48u << 20;
    l.max_meshes = 65536;
    l.max_texture_width = 16384;
    l.max_texture_height = 16384;
    l.max_texture_bytes = (size_t)256 << 20;
    l.max_json_depth = 64;
    return l;
}

mote_limits mote__io_limits(const mote_limits *limits)
{
    mote_limits d = mote_limits_default();
    if (!limits)
        return d;
    mote_limits l = *limits;
    if (l.max_file_bytes == 0) l.max_file_bytes = d.max_file_bytes;
    if (l.max_vertices == 0) l.max_vertices = d.max_vertices;
    if (l.max_indices == 0) l.max_indices = d.max_indices;
    if (l.max_meshes == 0) l.max_meshes = d.max_meshes;
    if (l.max_texture_width <= 0) l.max_texture_width = d.max_texture_width;
    if (l.max_texture_height <= 0) l.max_texture_height = d.max_texture_height;
    if (l.max_texture_bytes == 0) l.max_texture_bytes = d.max_texture_bytes;
    if (l.max_json_depth <= 0) l.max_json_depth = d.max_json_depth;
    return l;
}

void mote__io_clean_name(char *dst, size_t n, const char *s)
{
    if (n == 0)
        return;
    size_t len = s ? strlen(s) : 0, i = 0;
    for (; i < len && i + 1 < n; i++) {
        unsigned char c = (unsigned char)s[i];
        dst[i] = (c < 0x20 || c == 0x7f) ? '?' : (char)c;
    }
    dst[i] = '\0';
    if (i < len && n >= 4)
        memcpy(dst + n - 4, "...", 4);
}

/* Refuses a path that names something other than a regular file, before
 * it is opened: opening a FIFO waits for a writer that may never come, and
 * a device such as /dev/zero reads on until the size limit. A path that
 * cannot be examined is left to fopen to report. Plain C cannot tell;
 * there the size limit is the only guard. */
static mote_result mote__io_check_regular_file(const char *path, const char *name,
                                               char *message, size_t message_size)
{
#if defined(__unix__) || defined(__APPLE__)
    struct stat st;
    if (stat(path, &st) != 0 || S_ISREG(st.st_mode))
        return MOTE_OK;
    const char *what = "something else";
    if (S_ISDIR(st.st_mode))
        what = "a directory";
    else if (S_ISFIFO(st.st_mode))
        what = "a FIFO";
    else if (S_ISCHR(st.st_mode) || S_ISBLK(st.st_mode))
        what = "a device";
    return mote__io_error(message, message_size, MOTE_ERR_IO,
                          "%s: cannot open: %s, not a regular file", name, what);
#else
    (void)path;
    (void)name;
    (void)message;
    (void)message_size;
    return MOTE_OK;
#endif
}

mote_result mote__io_read_file(const char *path, size_t max_bytes, char **data,
                               size_t *size, char *message, size_t message_size)
{
    *data = NULL;
    *size = 0;
    char name[160];
    mote__io_clean_name(name, sizeof name, path);
    mote_result checked = mote__io_check_regular_file(path, name, message, message_size);
    if (checked != MOTE_OK)
        return checked;
    FILE *f = fopen(path, "rb");
    if (!f)
        return mote__io_error(message, message_size, MOTE_ERR_IO, "%s: cannot open: %s",
                              name, strerror(errno));
    /* Read in chunks rather than trusting ftell: works for pipes, and the
     * limit is enforced on the bytes actually read. */
    size_t cap = 0, len = 0;
    char *buf = NULL;
    mote_result r = MOTE_OK;
    for (;;) {
        if (len == cap) {
            if (cap > max_bytes) {
                r = mote__io_error(message, message_size, MOTE_ERR_LIMIT,
                                   "%s: file is larger than the limit of %zu bytes", name,
                                   max_bytes);
                break;
            }
            /* one byte past the limit tells a file over it; a limit of
             * SIZE_MAX (no limit) must not wrap that to 0 */
            size_t ncap = cap ? cap * 2 : 65536;
            if (max_bytes < SIZE_MAX - 1 && ncap > max_bytes + 1)
                ncap = max_bytes + 1;
            char *nb = cap <= SIZE_MAX / 4 ? mote__io_malloc(ncap + 1) : NULL;
            if (!nb) {
                r = mote__io_error(message, message_size, MOTE_ERR_OUT_OF_MEMORY,
                                   "%s: out of memory reading %zu bytes", name, ncap);
                break;
            }
            if (len)
                memcpy(nb, buf, len);
            mote__io_free(buf);
            buf = nb;
            cap = ncap;
        }
        size_t got = fread(buf + len, 1, cap - len, f);
        len += got;
        if (got == 0) {
            if (ferror(f))
                r = mote__io_error(message, message_size, MOTE_ERR_IO, "%s: read error", name);
            break;
        }
    }
    fclose(f);
    if (r == MOTE_OK && len > max_bytes)
        r = mote__io_error(message, message_size, MOTE_ERR_LIMIT,
                           "%s: file is larger than the limit of %zu bytes", name, max_bytes);
    if (r != MOTE_OK) {
        mote__io_free(buf);
        return r;
    }
    if (!buf) {
        buf = mote__io_malloc(1);
        if (!buf)
            return mote__io_error(message, message_size, MOTE_ERR_OUT_OF_MEMORY,
                                  "%s: out of memory", name);
    }
    buf[len] = '\0';
    *data = buf;
    *size = len;
    return MOTE_OK;
}
