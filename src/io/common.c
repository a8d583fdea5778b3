/*
 * common.c - the allocator, messages and limits shared by src/io (files
 * are file.c's). The counters below exist for the failing-allocator tests
 * (atomic: io_internal.h).
 */
#include "io_internal.h"

#include <stdio.h>
#include <stdlib.h>
#include <string.h>


static long mote__fail_after = -1;
static long mote__live;

void mote__io_set_alloc_failure_after(int n)
{
    MOTE__IO_STORE(&mote__fail_after, (long)(n < 0 ? -1 : n));
}

int mote__io_failure_pending(void)
{
    return MOTE__IO_LOAD(&mote__fail_after) >= 0;
}

long mote__io_live_allocations(void)
{
    return MOTE__IO_LOAD(&mote__live);
}

int mote__io_should_fail(void)
{
    if (MOTE__IO_LOAD(&mote__fail_after) < 0)
        return 0;
    /* one-shot: the n-th request fails, later ones succeed again */
    return MOTE__IO_ADD(&mote__fail_after, -1) == -1;
}

void mote__io_track(int delta)
{
    MOTE__IO_ADD(&mote__live, (long)delta);
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
    l.max_total_texture_bytes = (size_t)512 << 20;
    l.max_json_depth = 64;
    l.max_json_bytes = (size_t)512 << 20;
    l.max_triangles = 1u << 20;
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
    if (l.max_total_texture_bytes == 0) l.max_total_texture_bytes = d.max_total_texture_bytes;
    if (l.max_json_depth <= 0) l.max_json_depth = d.max_json_depth;
    if (l.max_json_bytes == 0) l.max_json_bytes = d.max_json_bytes;
    if (l.max_triangles == 0) l.max_triangles = d.max_triangles;
    if (l.gltf_scene < 0) l.gltf_scene = 0;
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
