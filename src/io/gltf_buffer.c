/*
 * gltf_buffer.c - a glTF file's bytes: buffers (a .glb's BIN chunk,
 * base64 data: URIs, files beside the scene), buffer views and accessors,
 * every range checked before anything is read or allocated for it.
 */
#include "gltf.h"

#include <math.h>
#include <stdio.h>
#include <string.h>

/* ---- buffers ----------------------------------------------------------- */

/* The base64 data: URI uri decoded into buf (at least byteLength bytes). */
static mote_result mote__gltf_data_uri(mote__gltf *gl, const char *uri, const char *at,
                                       mote__gltf_buffer *buf)
{
    const char *comma = strchr(uri, ',');
    if (!comma || comma - uri < 7 || strncmp(comma - 7, ";base64", 7) != 0)
        return mote__fail(gl->load, MOTE_ERR_PARSE, "%s.uri: a data: URI without \";base64,\" "
                          "(only base64 data is read)", at);
    const char *b64 = comma + 1;
    size_t len = strlen(b64), cap = len / 4 * 3 + 2;
    if (cap - 2 > gl->load->lim.max_file_bytes)
        return mote__fail(gl->load, MOTE_ERR_LIMIT, "%s.uri: about %zu bytes, more than the "
                          "limit of %zu", at, cap - 2, gl->load->lim.max_file_bytes);
    unsigned char *data = mote__store_alloc(&gl->load->tmp, cap, 1);
    if (!data)
        return mote__oom(gl->load, at);
    size_t n = 0, bad = 0;
    if (!mote__io_base64_decode(b64, len, data, &n, &bad))
        return mote__fail(gl->load, MOTE_ERR_PARSE, "%s.uri: invalid base64 at character %zu "
                          "of %zu", at, bad, len);
    if (n < buf->size)
        return mote__fail(gl->load, MOTE_ERR_PARSE, "%s.uri: %zu bytes of data, fewer than its "
                          "byteLength %zu", at, n, buf->size);
    buf->data = data;
    return MOTE_OK;
}

/* The file uri names beside the scene, under the path rules of textures
 * (limits.allow_any_texture_path), into buf. */
static mote_result mote__gltf_file_uri(mote__gltf *gl, const char *uri, const char *at,
                                       mote__gltf_buffer *buf)
{
    mote__loader *ld = gl->load;
    if (!ld->base_dir)
        return mote__fail(ld, MOTE_ERR_IO, "%s.uri: \"%s\" is a file, and the scene was read "
                          "from memory without a folder", at, mote__quote(uri).s);
    const char *scheme = strstr(uri, "://");
    if (scheme && scheme != uri)
        return mote__fail(ld, MOTE_ERR_IO, "%s.uri: \"%s\" is a web address, which mote does "
                          "not download", at, mote__quote(uri).s);
    /* a URI: "%20" is a space; the name decoded is checked again */
    char *decoded;
    MOTE__TRY(mote__url_decoded_name(ld, at, uri, &decoded));
    const char *name = decoded ? decoded : uri;
    char why[256];
    mote__io_file file;
    mote_result r = mote__io_open_in_folder(ld->base_dir, name, ld->lim.allow_any_texture_path,
                                            &file, why, sizeof why);
    if (r == MOTE_ERR_RANGE)
        return mote__fail(ld, r, "%s.uri: %s (files must be inside the scene's folder; see "
                          "limits.allow_any_texture_path)", at, why);
    if (r != MOTE_OK)
        return mote__fail(ld, r, "%s.uri: %s", at, why);
    char *data;
    size_t size;
    r = mote__io_read_open(&file, ld->lim.max_file_bytes, &data, &size, why, sizeof why);
    if (r != MOTE_OK)
        return mote__fail(ld, r, "%s.uri: %s", at, why);
    buf->data = (const unsigned char *)data;
    buf->owned = data;
    if (size < buf->size)
        return mote__fail(ld, MOTE_ERR_PARSE, "%s.uri: \"%s\" has %zu bytes, fewer than its "
                          "byteLength %zu", at, mote__quote(uri).s, size, buf->size);
    return MOTE_OK;
}

/* buffers[] (gl->buffer_count of them): their lengths now, their bytes when an accessor or an image
 * first reads them (mote__gltf_buffer_data). */
mote_result mote__gltf_buffers(mote__gltf *gl)
{
    const cJSON *list = mote__json_get(gl->root, "buffers");
    gl->buffers = mote__store_alloc(&gl->load->tmp, (size_t)gl->buffer_count,
                                    sizeof *gl->buffers);
    if (!gl->buffers)
        return mote__oom(gl->load, "buffers");
    int i = 0;
    for (const cJSON *b = list ? list->child : NULL; b; b = b->next, i++) {
        char at[48];
        snprintf(at, sizeof at, "buffers[%d]", i);
        MOTE__TRY(mote__json_object(gl->load, b, at));
        const cJSON *len = mote__json_get(b, "byteLength");
        if (!len)
            return mote__fail(gl->load, MOTE_ERR_PARSE, "%s: missing \"byteLength\"", at);
        uint32_t bytes;
        char at2[64];
        snprintf(at2, sizeof at2, "%s.byteLength", at);
        MOTE__TRY(mote__json_uint(gl->load, len, at2, 1, 4294967295.0, &bytes));
        if (bytes > gl->load->lim.max_file_bytes)
            return mote__fail(gl->load, MOTE_ERR_LIMIT, "%s: %u bytes, more than the limit of "
                              "%zu", at2, (unsigned)bytes, gl->load->lim.max_file_bytes);
        gl->buffers[i].size = bytes;
        gl->buffers[i].json = b;
    }
    return MOTE_OK;
}

void mote__gltf_free_buffers(mote__gltf *gl)
{
    for (int i = 0; gl->buffers && i < gl->buffer_count; i++) {
        mote__io_free(gl->buffers[i].owned);
        gl->buffers[i].owned = NULL;
    }
}

/* buffers[index]'s bytes, read on first use. */
static mote_result mote__gltf_buffer_data(mote__gltf *gl, int index, mote__gltf_buffer **out)
{
    mote__gltf_buffer *buf = &gl->buffers[index];
    *out = buf;
    if (buf->data)
        return MOTE_OK;
    char at[48];
    snprintf(at, sizeof at, "buffers[%d]", index);
    const char *uri;
    MOTE__TRY(mote__json_string(gl->load, buf->json, "uri", at, &uri));
    if (!uri) {
        /* only the first buffer of a .glb may be its BIN chunk */
        if (index != 0 || !gl->bin)
            return mote__fail(gl->load, MOTE_ERR_PARSE, "%s: no \"uri\", and no GLB BIN chunk "
                              "holds it", at);
        if (buf->size > gl->bin_size)
            return mote__fail(gl->load, MOTE_ERR_PARSE, "%s.byteLength: %zu, more than the GLB "
                              "BIN chunk's %zu bytes", at, buf->size, gl->bin_size);
        buf->data = gl->bin;
        return MOTE_OK;
    }
    if (mote__io_is_data_url(uri))
        return mote__gltf_data_uri(gl, uri, at, buf);
    return mote__gltf_file_uri(gl, uri, at, buf);
}

/* ---- buffer views ------------------------------------------------------ */

typedef struct mote__gltf_view {
    const unsigned char *data;
    size_t length, stride;        /* stride 0: packed */
} mote__gltf_view;

static mote_result mote__gltf_view_get(mote__gltf *gl, int index, mote__gltf_view *out)
{
    const cJSON *v;
    char at[MOTE__GLTF_AT];
    MOTE__TRY(mote__gltf_item(gl, "bufferViews", index, &v, at));
    int buffer = -1;
    MOTE__TRY(mote__gltf_index(gl, v, "buffer", at, gl->buffer_count, "buffer", &buffer));
    if (buffer < 0)
        return mote__fail(gl->load, MOTE_ERR_PARSE, "%s: missing \"buffer\"", at);
    uint32_t offset = 0, length = 0, stride = 0;
    MOTE__TRY(mote__json_uint_member(gl->load, v, "byteOffset", at, UINT32_MAX, &offset));
    if (!mote__json_get(v, "byteLength"))
        return mote__fail(gl->load, MOTE_ERR_PARSE, "%s: missing \"byteLength\"", at);
    MOTE__TRY(mote__json_uint_member(gl->load, v, "byteLength", at, UINT32_MAX, &length));
    MOTE__TRY(mote__json_uint_member(gl->load, v, "byteStride", at, 252, &stride));
    if (mote__json_get(v, "byteStride") && (stride < 4 || stride % 4))
        return mote__fail(gl->load, MOTE_ERR_RANGE, "%s.byteStride: %u, expected a multiple of "
                          "4 from 4 to 252", at, (unsigned)stride);
    mote__gltf_buffer *buf;
    MOTE__TRY(mote__gltf_buffer_data(gl, buffer, &buf));
    if ((uint64_t)offset + length > buf->size)
        return mote__fail(gl->load, MOTE_ERR_RANGE, "%s: bytes %u to %llu, past the end of "
                          "buffers[%d] (%zu bytes)", at, (unsigned)offset,
                          (unsigned long long)offset + length, buffer, buf->size);
    out->data = buf->data + offset;
    out->length = length;
    out->stride = stride;
    return MOTE_OK;
}

mote_result mote__gltf_view_bytes(mote__gltf *gl, int index, const char *use,
                                  const unsigned char **data, size_t *size)
{
    (void)use;
    mote__gltf_view v;
    MOTE__TRY(mote__gltf_view_get(gl, index, &v));
    *data = v.data;
    *size = v.length;
    return MOTE_OK;
}

/* ---- accessors --------------------------------------------------------- */

static size_t mote__gltf_component_size(uint32_t ctype)
{
    switch (ctype) {
    case 5120: case 5121: return 1;
    case 5122: case 5123: return 2;
    case 5125: case 5126: return 4;
    default: return 0;
    }
}

/* The components of a type ("VEC3": 3), 0 for none; *columns for MATn. */
static int mote__gltf_type_comps(const char *type, int *columns)
{
    static const struct { const char *name; int comps, columns; } types[] = {
        {"SCALAR", 1, 1}, {"VEC2", 2, 1}, {"VEC3", 3, 1}, {"VEC4", 4, 1},
        {"MAT2", 4, 2}, {"MAT3", 9, 3}, {"MAT4", 16, 4},
    };
    for (size_t i = 0; i < sizeof types / sizeof types[0]; i++)
        if (strcmp(type, types[i].name) == 0) {
            *columns = types[i].columns;
            return types[i].comps;
        }
    return 0;
}

/* Whether bytes [offset, offset + (count - 1) * stride + size) fit in
 * length (count 0: nothing to fit). */
static bool mote__gltf_fits(uint64_t offset, uint64_t count, uint64_t stride, uint64_t size,
                            uint64_t length)
{
    return count == 0 || offset + (count - 1) * stride + size <= length;
}

/* The sparse part of accessor at: indices strictly increasing below the
 * accessor's count, indices and values inside their views. */
static mote_result mote__gltf_sparse(mote__gltf *gl, const cJSON *sparse, const char *at,
                                     size_t elem, mote__gltf_accessor *a)
{
    char at2[96], at3[112];
    snprintf(at2, sizeof at2, "%s.sparse", at);
    MOTE__TRY(mote__json_object(gl->load, sparse, at2));
    uint32_t count = 0;
    if (!mote__json_get(sparse, "count"))
        return mote__fail(gl->load, MOTE_ERR_PARSE, "%s: missing \"count\"", at2);
    MOTE__TRY(mote__json_uint_member(gl->load, sparse, "count", at2, a->count, &count));
    const char *keys[2] = {"indices", "values"};
    for (int k = 0; k < 2; k++) {
        const cJSON *part = mote__json_get(sparse, keys[k]);
        snprintf(at3, sizeof at3, "%s.%s", at2, keys[k]);
        if (!part)
            return mote__fail(gl->load, MOTE_ERR_PARSE, "%s: missing", at3);
        MOTE__TRY(mote__json_object(gl->load, part, at3));
        int view = -1;
        uint32_t offset = 0, ctype = 0;
        MOTE__TRY(mote__gltf_index(gl, part, "bufferView", at3, gl->view_count, "buffer view",
                                   &view));
        if (view < 0)
            return mote__fail(gl->load, MOTE_ERR_PARSE, "%s: missing \"bufferView\"", at3);
        MOTE__TRY(mote__json_uint_member(gl->load, part, "byteOffset", at3, UINT32_MAX, &offset));
        size_t size = elem;
        if (k == 0) {
            MOTE__TRY(mote__json_uint_member(gl->load, part, "componentType", at3, 5125, &ctype));
            if (ctype != 5121 && ctype != 5123 && ctype != 5125)
                return mote__fail(gl->load, MOTE_ERR_RANGE, "%s.componentType: %u, expected "
                                  "5121, 5123 or 5125 (an unsigned integer)", at3,
                                  (unsigned)ctype);
            size = mote__gltf_component_size(ctype);
        }
        mote__gltf_view v;
        MOTE__TRY(mote__gltf_view_get(gl, view, &v));
        if (!mote__gltf_fits(offset, count, size, size, v.length))
            return mote__fail(gl->load, MOTE_ERR_RANGE, "%s: %u entries of %zu bytes from byte "
                              "%u, past the end of bufferViews[%d] (%zu bytes)", at3,
                              (unsigned)count, size, (unsigned)offset, view, v.length);
        if (k == 0) {
            a->sparse_indices = v.data + offset;
            a->sparse_index_type = ctype;
        } else {
            a->sparse_values = v.data + offset;
        }
    }
    a->sparse_count = count;
    mote__gltf_accessor probe = {.count = count, .comps = 1, .ctype = a->sparse_index_type,
                                 .data = a->sparse_indices,
                                 .stride = mote__gltf_component_size(a->sparse_index_type)};
    for (uint32_t i = 0; i < count; i++) {
        uint32_t s = mote__gltf_read_uint(&probe, i);
        uint32_t prev = i ? mote__gltf_read_uint(&probe, i - 1) : 0;
        if (s >= a->count || (i && s <= prev))
            return mote__fail(gl->load, MOTE_ERR_RANGE, "%s.indices[%u]: %u, expected an index "
                              "below %u%s", at2, (unsigned)i, (unsigned)s, (unsigned)a->count,
                              i ? " greater than the one before" : "");
    }
    return MOTE_OK;
}

mote_result mote__gltf_resolve(mote__gltf *gl, int index, const char *use,
                                mote__gltf_accessor *out)
{
    memset(out, 0, sizeof *out);
    if (index < 0 || index >= gl->accessor_count)
        return mote__fail(gl->load, MOTE_ERR_RANGE, "%s: %d names no accessor (there are %d)",
                          use, index, gl->accessor_count);
    const cJSON *acc;
    char at[MOTE__GLTF_AT];
    MOTE__TRY(mote__gltf_item(gl, "accessors", index, &acc, at));
    uint32_t ctype = 0, count = 0, offset = 0;
    const char *type;
    if (!mote__json_get(acc, "componentType") || !mote__json_get(acc, "count"))
        return mote__fail(gl->load, MOTE_ERR_PARSE, "%s: missing \"%s\"", at,
                          mote__json_get(acc, "count") ? "componentType" : "count");
    MOTE__TRY(mote__json_uint_member(gl->load, acc, "componentType", at, 65535, &ctype));
    size_t csize = mote__gltf_component_size(ctype);
    if (!csize)
        return mote__fail(gl->load, MOTE_ERR_RANGE, "%s.componentType: %u, expected 5120 to "
                          "5123, 5125 or 5126", at, (unsigned)ctype);
    MOTE__TRY(mote__json_uint_member(gl->load, acc, "count", at, UINT32_MAX, &count));
    MOTE__TRY(mote__json_string(gl->load, acc, "type", at, &type));
    int columns = 1;
    int comps = type ? mote__gltf_type_comps(type, &columns) : 0;
    if (!comps)
        return mote__fail(gl->load, MOTE_ERR_PARSE, "%s.type: expected \"SCALAR\", \"VEC2\", "
                          "\"VEC3\", \"VEC4\", \"MAT2\", \"MAT3\" or \"MAT4\"", at);
    MOTE__TRY(mote__json_flag(gl->load, acc, "normalized", at, &out->normalized));
    out->count = count;
    out->comps = comps;
    out->ctype = ctype;
    /* a matrix's columns start on 4-byte boundaries */
    size_t rows = (size_t)(comps / columns);
    size_t elem = columns > 1 ? (size_t)columns * ((rows * csize + 3) & ~(size_t)3)
                              : (size_t)comps * csize;
    int view = -1;
    MOTE__TRY(mote__gltf_index(gl, acc, "bufferView", at, gl->view_count, "buffer view", &view));
    MOTE__TRY(mote__json_uint_member(gl->load, acc, "byteOffset", at, UINT32_MAX, &offset));
    if (view >= 0) {
        mote__gltf_view v;
        MOTE__TRY(mote__gltf_view_get(gl, view, &v));
        size_t stride = v.stride ? v.stride : elem;
        if (stride < elem)
            return mote__fail(gl->load, MOTE_ERR_RANGE, "%s: elements of %zu bytes, more than "
                              "bufferViews[%d].byteStride %zu", at, elem, view, stride);
        if (!mote__gltf_fits(offset, count, stride, elem, v.length))
            return mote__fail(gl->load, MOTE_ERR_RANGE, "%s: %u elements of %zu bytes every %zu "
                              "from byte %u, past the end of bufferViews[%d] (%zu bytes)", at,
                              (unsigned)count, elem, stride, (unsigned)offset, view, v.length);
        out->data = v.data + offset;
        out->stride = stride;
    }
    const cJSON *sparse = mote__json_get(acc, "sparse");
    if (sparse)
        MOTE__TRY(mote__gltf_sparse(gl, sparse, at, elem, out));
    return MOTE_OK;
}

/* Component k of the element at p, as a float. */
static float mote__gltf_component(const unsigned char *p, uint32_t ctype, bool normalized)
{
    switch (ctype) {
    case 5120: {
        float c = (float)(signed char)p[0];
        return normalized ? (c / 127.0f < -1.0f ? -1.0f : c / 127.0f) : c;
    }
    case 5121:
        return normalized ? (float)p[0] / 255.0f : (float)p[0];
    case 5122: {
        int16_t v;
        memcpy(&v, p, 2);
        float c = (float)v;
        return normalized ? (c / 32767.0f < -1.0f ? -1.0f : c / 32767.0f) : c;
    }
    case 5123: {
        uint16_t v;
        memcpy(&v, p, 2);
        return normalized ? (float)v / 65535.0f : (float)v;
    }
    case 5125: {
        uint32_t v;
        memcpy(&v, p, 4);
        return (float)v;
    }
    default: {
        float v;
        memcpy(&v, p, 4);
        return v;
    }
    }
}

/* Where element i's sparse value is, or NULL: it has none. */
static const unsigned char *mote__gltf_sparse_value(const mote__gltf_accessor *a, uint32_t i)
{
    if (!a->sparse_count)
        return NULL;
    mote__gltf_accessor idx = {.count = a->sparse_count, .comps = 1,
                               .ctype = a->sparse_index_type, .data = a->sparse_indices,
                               .stride = mote__gltf_component_size(a->sparse_index_type)};
    uint32_t lo = 0, hi = a->sparse_count;
    while (lo < hi) {
        uint32_t mid = lo + (hi - lo) / 2;
        uint32_t s = mote__gltf_read_uint(&idx, mid);
        if (s == i)
            return a->sparse_values + (size_t)mid * (size_t)a->comps *
                                          mote__gltf_component_size(a->ctype);
        if (s < i)
            lo = mid + 1;
        else
            hi = mid;
    }
    return NULL;
}

void mote__gltf_read_floats(const mote__gltf_accessor *a, uint32_t i, int n, float *out)
{
    size_t csize = mote__gltf_component_size(a->ctype);
    const unsigned char *p = mote__gltf_sparse_value(a, i);
    if (!p && a->data)
        p = a->data + (size_t)i * a->stride;
    for (int k = 0; k < n; k++)
        out[k] = p && k < a->comps ? mote__gltf_component(p + (size_t)k * csize, a->ctype,
                                                          a->normalized)
                                   : 0.0f;
}

uint32_t mote__gltf_read_uint(const mote__gltf_accessor *a, uint32_t i)
{
    const unsigned char *p = mote__gltf_sparse_value(a, i);
    if (!p && a->data)
        p = a->data + (size_t)i * a->stride;
    if (!p)
        return 0;
    switch (a->ctype) {
    case 5121:
        return p[0];
    case 5123: {
        uint16_t v;
        memcpy(&v, p, 2);
        return v;
    }
    default: {
        uint32_t v;
        memcpy(&v, p, 4);
        return v;
    }
    }
}
