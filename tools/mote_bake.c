/*
 * mote-bake - turns a .babylon or glTF scene into a C header that firmware
 * compiles in: const vertex, vertex colour and index arrays, textures
 * already in the target pixel format, the meshes as mote_mesh
 * (material.texture pointing at the baked texture), each mesh's draw
 * options and the order to draw them in, the frame (camera, lights,
 * ambient, fog) and the clear colour. The
 * firmware then renders with no file system, no JSON and no heap.
 *
 *   mote-bake SCENE -o scene.h [--format rgb565|rgba8888|grey8]
 *             [--name NAME] [--size WxH] [--texture-size WxH] [--max-bytes N]
 *             [--compact] [--normal-bits 8|16] [--scene I] [--keep-order]
 *
 * Floats are written as C99 hexadecimal literals, so the baked values are
 * the loaded ones bit for bit. Each mesh's triangles, and its vertices
 * where no other index array shares them, are reordered by meshoptimizer
 * so that the firmware's direct-mapped vertex cache transforms fewer
 * vertices (the header's comment above each mesh says how many); a mesh
 * it would not help keeps the file's order, as do points, lines and
 * meshes without indices. --keep-order keeps the file's order throughout,
 * so that the baked scene is the loaded one bit for bit. --size is the
 * frame the camera's aspect is made for (default 320x240); the header
 * repeats it as NAME_WIDTH/NAME_HEIGHT.
 * A mesh with levels of detail is baked at the level chosen for the baked
 * camera (the others hidden), with a warning: the header has no camera
 * of its own to choose by. --texture-size resamples every texture to WxH
 * with a box filter, so that a large image fits a small chip's flash.
 * --compact writes each mesh's vertices as integers (mote_compact): int16
 * positions and uvs with a per-mesh scale and offset per axis (the box of
 * the mesh's values in 65535 steps), normals as int8 (--normal-bits 16:
 * int16) and 16-bit indices; the header's comment above each mesh gives
 * the largest error of its positions, uvs and normals. A mesh with a
 * non-finite coordinate stays in floats, and one of more than 65536
 * vertices keeps 32-bit indices.
 *
 * The header always compiles as C99: each texture is an array of its
 * texel type as long as its texels, in a union with a uint32_t so that it
 * is aligned as the core reads it on any target; names whose macros
 * <limits.h> or <stdint.h> define (INT_WIDTH, SIZE_WIDTH...) are refused;
 * the scene's path is escaped in the header's comment. The header is
 * built in memory, at most --max-bytes (default 64 MiB: textures are
 * refused from their image headers when they cannot fit), and written as
 * mote_write_file writes (never over the scene's own files).
 */
#include <mote/mote.h>
#include <mote/mote_io.h>

#include <meshoptimizer.h>

#include <ctype.h>
#include <errno.h>
#include <limits.h>
#include <math.h>
#include <stdarg.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>

/* --max-bytes by default: larger than any texture a microcontroller holds
 * (a 1024 x 1024 RGB565 texture bakes to 7.3 MB of text). */
#define DEFAULT_MAX_BYTES ((size_t)64 << 20)

typedef struct baker {
    char *text;                   /* the header so far */
    size_t size, cap;
    size_t max_bytes;             /* --max-bytes */
    bool too_big, out_of_memory;  /* put() stopped */
    const char *name;             /* C identifier prefix */
    mote_format format;           /* of the baked textures */
    int texture_width, texture_height; /* --texture-size; 0: as loaded */
    const mote_scene *scene;
    const mote_mesh *meshes;      /* written: the scene's, or copies with reordered arrays */
    int *texture_slot;            /* per scene texture: index in the baked array, or -1 */
    int *vertex_array;            /* per mesh: which vertices array it uses, or -1 */
    int *index_array;             /* per mesh: which indices array it uses, or -1 */
    int *color_array;             /* per mesh: which colors array it uses, or -1 */
    bool compact;                 /* --compact */
    int normal_bits;              /* --normal-bits: 8 or 16 */
    /* per mesh whose triangles were reordered: the vertices a direct-mapped
     * cache of 32 and of 16 entries transforms, in the file's order and
     * after (0: not reordered) */
    uint32_t (*transforms)[4];
} baker;

static void usage(FILE *out)
{
    fprintf(out,
            "usage: mote-bake SCENE -o OUT.h [--format rgb565|rgba8888|grey8]\n"
            "                 [--name NAME] [--size WxH] [--texture-size WxH] [--max-bytes N]\n"
            "                 [--compact] [--normal-bits 8|16] [--scene I] [--keep-order]\n"
            "Writes a C header with the scene's meshes, textures (in FORMAT, default\n"
            "rgb565), camera and lights as const mote structs (identifiers NAME_*,\n"
            "default scene) for a frame of WxH pixels (default 320x240), of at most\n"
            "N bytes (default %zu). --texture-size resamples every texture to WxH\n"
            "(a box filter). --compact writes int16 positions and uvs, int8 normals\n"
            "(--normal-bits 16: int16) and 16-bit indices. --scene bakes a glTF file's\n"
            "scene I, counted from 0 (default: the file's scene, else its first).\n"
            "Triangles and vertices are reordered for the firmware's vertex cache;\n"
            "--keep-order keeps the file's order.\n",
            (size_t)DEFAULT_MAX_BYTES);
}

/* Appends printf output to the header, up to b->max_bytes. */
static void put(baker *b, const char *fmt, ...)
#if defined(__GNUC__)
    __attribute__((format(printf, 2, 3)))
#endif
    ;
static void put(baker *b, const char *fmt, ...)
{
    if (b->too_big || b->out_of_memory)
        return;
    char small[128];
    va_list ap;
    va_start(ap, fmt);
    int n = vsnprintf(small, sizeof small, fmt, ap);
    va_end(ap);
    if (n < 0) {
        b->out_of_memory = true;
        return;
    }
    if ((size_t)n > b->max_bytes - b->size) {
        b->too_big = true;
        return;
    }
    if (b->size + (size_t)n + 1 > b->cap) {
        size_t cap = b->cap ? b->cap : 65536;
        while (cap < b->size + (size_t)n + 1)
            cap *= 2;
        char *grown = realloc(b->text, cap);
        if (!grown) {
            b->out_of_memory = true;
            return;
        }
        b->text = grown;
        b->cap = cap;
    }
    if ((size_t)n < sizeof small) {
        memcpy(b->text + b->size, small, (size_t)n + 1);
    } else {
        va_start(ap, fmt);
        vsnprintf(b->text + b->size, (size_t)n + 1, fmt, ap);
        va_end(ap);
    }
    b->size += (size_t)n;
}

/* A float as a C expression that gives exactly the same bits. */
static const char *flt(char buf[40], float v)
{
    if (isnan(v))
        return "MOTE_BAKE_NAN";
    if (isinf(v))
        return v > 0 ? "MOTE_BAKE_INF" : "(-MOTE_BAKE_INF)";
    snprintf(buf, 40, "%af", (double)v);
    return buf;
}

static void put_floats(baker *b, const float *v, int n)
{
    char buf[40];
    put(b, "{");
    for (int i = 0; i < n; i++)
        put(b, "%s%s", i ? ", " : "", flt(buf, v[i]));
    put(b, "}");
}

/* The enumerator of a texture format: MOTE_FORMAT_ and its name in capitals. */
static const char *format_name(mote_format f)
{
    static char id[64];
    const char *n = mote_format_name(f);
    snprintf(id, sizeof id, "MOTE_FORMAT_%s", n ? n : "RGBA8888");
    for (char *c = id; *c; c++)
        *c = (char)toupper((unsigned char)*c);
    return id;
}

/* The texture format of that name (mote_format_name), or DEFAULT. */
static mote_format texture_format(const char *name)
{
    for (int f = MOTE_FORMAT_DEFAULT + 1; f < MOTE_FORMAT_COUNT; f++)
        if (mote_format_is_texture((mote_format)f) && !strcmp(name, mote_format_name((mote_format)f)))
            return (mote_format)f;
    return MOTE_FORMAT_DEFAULT;
}

static const char *wrap_name(mote_wrap w)
{
    static const char *const names[] = {"MOTE_WRAP_DEFAULT", "MOTE_WRAP_REPEAT", "MOTE_WRAP_CLAMP",
                                        "MOTE_WRAP_MIRROR"};
    return (int)w >= 0 && w < MOTE_WRAP_COUNT ? names[w] : "MOTE_WRAP_DEFAULT";
}

static const char *light_name(mote_light_type t)
{
    static const char *const names[] = {"MOTE_LIGHT_NONE", "MOTE_LIGHT_POINT", "MOTE_LIGHT_DIRECTIONAL",
                                        "MOTE_LIGHT_HEMISPHERIC", "MOTE_LIGHT_SPOT"};
    return (int)t >= 0 && t < MOTE_LIGHT_TYPE_COUNT ? names[t] : "MOTE_LIGHT_NONE";
}

static const char *tf(bool v)
{
    return v ? "true" : "false";
}

/* whether a material has an emissive colour (the loader's sum of emissive
 * and ambient x the scene's ambient colour) */
static bool glows(const mote_material *mat)
{
    return (mat->emissive.r | mat->emissive.g | mat->emissive.b) != 0;
}

/* The texture resampled to width x height as RGBA8888 by a box filter:
 * each texel is the rounded mean of the whole source texels under it
 * (exact for a size that divides the source's, as 512 to 128; a larger
 * size repeats texels). NULL when out of memory. */
static uint8_t *box_filter(const mote_texture *t, int width, int height)
{
    int src_stride = t->stride ? t->stride : t->width * mote_format_bytes(t->format);
    uint8_t *out = malloc((size_t)width * (size_t)height * 4);
    uint8_t *src = malloc((size_t)t->width * (size_t)t->height * 4);
    if (!out || !src) {
        free(out);
        free(src);
        return NULL;
    }
    for (int y = 0; y < t->height; y++)
        mote_convert_row((const unsigned char *)t->pixels + (size_t)y * (size_t)src_stride, t->format,
                         src + (size_t)y * (size_t)t->width * 4, MOTE_FORMAT_RGBA8888, t->width);
    for (int y = 0; y < height; y++) {
        int y0 = (int)((int64_t)y * t->height / height);
        int y1 = (int)((int64_t)(y + 1) * t->height / height);
        y1 = y1 > y0 ? y1 : y0 + 1;
        for (int x = 0; x < width; x++) {
            int x0 = (int)((int64_t)x * t->width / width);
            int x1 = (int)((int64_t)(x + 1) * t->width / width);
            x1 = x1 > x0 ? x1 : x0 + 1;
            uint64_t sum[4] = {0, 0, 0, 0}, n = (uint64_t)(x1 - x0) * (uint64_t)(y1 - y0);
            for (int sy = y0; sy < y1; sy++)
                for (int sx = x0; sx < x1; sx++)
                    for (int c = 0; c < 4; c++)
                        sum[c] += src[((size_t)sy * (size_t)t->width + (size_t)sx) * 4 + (size_t)c];
            for (int c = 0; c < 4; c++)
                out[((size_t)y * (size_t)width + (size_t)x) * 4 + (size_t)c] = (uint8_t)((sum[c] + n / 2) / n);
        }
    }
    free(src);
    return out;
}

/* One texture converted to the target format (resampled first with
 * --texture-size), row by row. */
static void write_texture(baker *b, const mote_texture *loaded, int slot)
{
    mote_texture resized = *loaded;
    uint8_t *resized_pixels = NULL;
    if (b->texture_width) {
        resized_pixels = box_filter(loaded, b->texture_width, b->texture_height);
        if (!resized_pixels) {
            b->out_of_memory = true;
            return;
        }
        resized = (mote_texture){b->texture_width, b->texture_height, MOTE_FORMAT_RGBA8888, 0,
                                 resized_pixels};
    }
    const mote_texture *t = &resized;
    int bpp = mote_format_bytes(b->format);
    int src_stride = t->stride ? t->stride : t->width * mote_format_bytes(t->format);
    unsigned char *row = malloc((size_t)t->width * (size_t)bpp);
    if (!row) {
        free(resized_pixels);
        b->out_of_memory = true;
        return;
    }
    /* the union aligns the texels to 4 bytes, as the core reads RGBA8888
     * (an array of bytes alone may be placed at any address) */
    put(b, "static const union {\n    %s pixels[%d * %d%s];\n    uint32_t align;\n} "
           "%s_texture%d = {{\n", bpp == 2 ? "uint16_t" : "uint8_t", t->width, t->height,
        bpp == 4 ? " * 4" : "", b->name, slot);
    for (int y = 0; y < t->height && !b->too_big; y++) {
        mote_convert_row((const unsigned char *)t->pixels + (size_t)y * (size_t)src_stride, t->format,
                         row, b->format, t->width);
        for (int x = 0; x < t->width * (bpp == 2 ? 1 : bpp); x++) {
            if (bpp == 2) {
                uint16_t v;
                memcpy(&v, row + 2 * x, 2);
                put(b, "0x%04x,", v);
            } else {
                put(b, "%u,", row[x]);
            }
            if (x % 16 == 15)
                put(b, "\n");
        }
        put(b, "\n");
    }
    put(b, "}};\n\n");
    free(row);
    free(resized_pixels);
}

static void write_vertices(baker *b, const mote_mesh *m, int array)
{
    put(b, "static const mote_vertex %s_vertices%d[%u] = {\n", b->name, array,
            (unsigned)m->vertex_count);
    for (uint32_t i = 0; i < m->vertex_count; i++) {
        const mote_vertex *v = &m->vertices[i];
        put(b, "{");
        put_floats(b, v->position, 3);
        put(b, ", ");
        put_floats(b, v->normal, 3);
        put(b, ", ");
        put_floats(b, v->uv, 2);
        put(b, "},\n");
    }
    put(b, "};\n\n");
}

/* Whether mesh m's vertices bake as integers: --compact, and every
 * coordinate finite. */
static bool compactable(const baker *b, const mote_mesh *m)
{
    if (!b->compact || !m->vertices)
        return false;
    for (uint32_t i = 0; i < m->vertex_count; i++) {
        const mote_vertex *v = &m->vertices[i];
        for (int k = 0; k < 8; k++)
            if (!isfinite((&v->position[0])[k]))
                return false;
    }
    return true;
}

/* The scale and offset that put the values v[i * stride] (i < n) on
 * -32767..32767 steps: the box's centre and half its size in 32767ths. */
static void quantiser(const float *v, uint32_t n, int stride, float *scale, float *offset)
{
    double lo = 0, hi = 0;
    for (uint32_t i = 0; i < n; i++) {
        double x = v[(size_t)i * (size_t)stride];
        if (i == 0 || x < lo) lo = x;
        if (i == 0 || x > hi) hi = x;
    }
    *offset = (float)(0.5 * (lo + hi));
    /* a hair more than half the box, so that rounding the offset keeps
     * every value within 32767 steps */
    double half = hi - lo > 0 ? 0.5 * (hi - lo) * (1.0 + 1e-6) + fabs((double)*offset - 0.5 * (lo + hi)) : 0;
    *scale = (float)(half / 32767.0);
}

/* round((x - offset) / scale) within int16's symmetric range */
static long quantise(float x, float scale, float offset)
{
    if (scale == 0.0f)
        return 0;
    double q = floor(((double)x - offset) / scale + 0.5);
    return q > 32767 ? 32767 : q < -32767 ? -32767 : (long)q;
}

/* A compactable mesh's vertices as mote_compact's arrays (positions,
 * normals, uvs), with the largest errors they make in the comment. */
static void write_compact_vertices(baker *b, const mote_mesh *m, int array)
{
    const uint32_t n = m->vertex_count;
    float scale[3], offset[3], uv_scale[2], uv_offset[2];
    for (int k = 0; k < 3; k++)
        quantiser(&m->vertices[0].position[k], n, 8, &scale[k], &offset[k]);
    for (int k = 0; k < 2; k++)
        quantiser(&m->vertices[0].uv[k], n, 8, &uv_scale[k], &uv_offset[k]);
    const double nmax = b->normal_bits == 16 ? 32767.0 : 127.0;
    double perr = 0, uverr = 0, nerr = 0;
    put(b, "static const int16_t %s_positions%d[%u] = {\n", b->name, array, (unsigned)(3 * n));
    for (uint32_t i = 0; i < n; i++) {
        for (int k = 0; k < 3; k++) {
            long q = quantise(m->vertices[i].position[k], scale[k], offset[k]);
            double back = (double)q * scale[k] + offset[k], e = fabs(back - m->vertices[i].position[k]);
            perr = e > perr ? e : perr;
            put(b, "%ld,", q);
        }
        put(b, "%s", i % 8 == 7 ? "\n" : " ");
    }
    put(b, "\n};\n\nstatic const int%d_t %s_normals%d[%u] = {\n", b->normal_bits, b->name, array,
        (unsigned)(3 * n));
    for (uint32_t i = 0; i < n; i++) {
        const float *nv = m->vertices[i].normal;
        double len = sqrt((double)nv[0] * nv[0] + (double)nv[1] * nv[1] + (double)nv[2] * nv[2]);
        long q[3] = {0, 0, 0};
        if (len > 0) {
            double dot = 0, qlen = 0;
            for (int k = 0; k < 3; k++) {
                q[k] = (long)floor(nv[k] / len * nmax + 0.5);
                dot += (double)q[k] * nv[k] / len;
                qlen += (double)q[k] * q[k];
            }
            double c = qlen > 0 ? dot / sqrt(qlen) : -1;
            double angle = acos(c > 1 ? 1 : c < -1 ? -1 : c);
            nerr = angle > nerr ? angle : nerr;
        }
        put(b, "%ld,%ld,%ld,%s", q[0], q[1], q[2], i % 8 == 7 ? "\n" : " ");
    }
    put(b, "\n};\n\nstatic const int16_t %s_uvs%d[%u] = {\n", b->name, array, (unsigned)(2 * n));
    for (uint32_t i = 0; i < n; i++) {
        for (int k = 0; k < 2; k++) {
            long q = quantise(m->vertices[i].uv[k], uv_scale[k], uv_offset[k]);
            double e = fabs((double)q * uv_scale[k] + uv_offset[k] - m->vertices[i].uv[k]);
            uverr = e > uverr ? e : uverr;
            put(b, "%ld,", q);
        }
        put(b, "%s", i % 8 == 7 ? "\n" : " ");
    }
    put(b, "\n};\n\n/* compact vertices %d: positions within %.3g units of the loaded ones, uvs "
           "within %.3g, normals within %.3g degrees */\n", array, perr, uverr, nerr * 57.29577951308232);
    put(b, "#define %s_COMPACT%d_SCALES \\\n    .scale = ", b->name, array);
    put_floats(b, scale, 3);
    put(b, ", .offset = ");
    put_floats(b, offset, 3);
    put(b, ", \\\n    .uv_scale = ");
    put_floats(b, uv_scale, 2);
    put(b, ", .uv_offset = ");
    put_floats(b, uv_offset, 2);
    put(b, "\n\n");
}

/* The mote_compact of mesh i: its vertex array's integers and, where they
 * fit, its indices in 16 bits. */
static void write_compact(baker *b, int i)
{
    const mote_mesh *m = &b->meshes[i];
    int va = b->vertex_array[i], ia = b->index_array[i];
    put(b, "static const mote_compact %s_compact%d = {\n    .positions = %s_positions%d,\n"
           "    .normals%d = %s_normals%d,\n    .uvs = %s_uvs%d,\n", b->name, i, b->name, va,
        b->normal_bits, b->name, va, b->name, va);
    if (ia >= 0 && m->vertex_count <= 65536)
        put(b, "    .indices = %s_indices%d,\n", b->name, ia);
    put(b, "    %s_COMPACT%d_SCALES,\n};\n\n", b->name, va);
}

static void write_colors(baker *b, const mote_mesh *m, int array)
{
    put(b, "static const mote_rgba %s_colors%d[%u] = {\n", b->name, array,
            (unsigned)m->vertex_count);
    for (uint32_t i = 0; i < m->vertex_count; i++) {
        const mote_rgba *c = &m->colors[i];
        put(b, "%s{%u, %u, %u, %u},", i % 8 ? " " : "", c->r, c->g, c->b, c->a);
        if (i % 8 == 7)
            put(b, "\n");
    }
    put(b, "%s};\n\n", m->vertex_count % 8 ? "\n" : "");
}

static void write_indices(baker *b, const mote_mesh *m, int array)
{
    /* compact meshes sharing the array all have its vertex count */
    const bool short_indices = compactable(b, m) && m->vertex_count <= 65536;
    put(b, "static const uint%d_t %s_indices%d[%u] = {\n", short_indices ? 16 : 32, b->name, array,
        (unsigned)m->index_count);
    for (uint32_t i = 0; i < m->index_count; i++)
        put(b, "%u,%s", (unsigned)m->indices[i], i % 16 == 15 ? "\n" : "");
    put(b, "\n};\n\n");
}

static void write_mesh(baker *b, int i)
{
    const mote_scene *s = b->scene;
    const mote_mesh *m = &b->meshes[i];   /* a copy: its parent is the scene's mesh */
    const mote_material *mat = &m->material;
    char buf[40];
    const bool compact = b->vertex_array[i] >= 0 && compactable(b, m);
    const uint32_t *tr = b->transforms[i];
    if (tr[1]) {
        const double tris = (double)(m->index_count / 3);
        put(b, "    /* vertex cache: %.2f -> %.2f transforms a triangle (direct-mapped, 32 entries: "
               "%u -> %u vertices; 16 entries: %u -> %u) */\n", tr[0] / tris, tr[1] / tris,
            (unsigned)tr[0], (unsigned)tr[1], (unsigned)tr[2], (unsigned)tr[3]);
    }
    put(b, "    { /* %d */\n", i);
    if (compact)
        put(b, "        .compact = &%s_compact%d,\n", b->name, i);
    else if (b->vertex_array[i] >= 0)
        put(b, "        .vertices = %s_vertices%d,\n", b->name, b->vertex_array[i]);
    put(b, "        .vertex_count = %u,\n", (unsigned)m->vertex_count);
    if (b->index_array[i] >= 0 && !(compact && m->vertex_count <= 65536))
        put(b, "        .indices = %s_indices%d,\n", b->name, b->index_array[i]);
    put(b, "        .index_count = %u,\n", (unsigned)m->index_count);
    put(b, "        .position = ");
    put_floats(b, m->position, 3);
    put(b, ",\n        .rotation = ");
    put_floats(b, m->rotation, 3);
    put(b, ",\n        .rotation_quaternion = ");
    put_floats(b, m->rotation_quaternion, 4);
    put(b, ",\n        .use_quaternion = %s,\n", tf(m->use_quaternion));
    /* isVisible false, a disabled parent, a camera or light in the tree:
     * written only when set, so headers of scenes without any stay as
     * they were */
    if (m->hidden)
        put(b, "        .hidden = true,\n");
    put(b, "        .scaling = ");
    put_floats(b, m->scaling, 3);
    put(b, ",\n");
    if (m->parent && m->parent >= s->meshes && m->parent < s->meshes + s->mesh_count)
        put(b, "        .parent = &%s_meshes[%d],\n", b->name, (int)(m->parent - s->meshes));
    put(b, "        .material = {\n            .color = {%u, %u, %u, %u},\n"
               "            .color_set = %s,\n",
            mat->color.r, mat->color.g, mat->color.b, mat->color.a, tf(mat->color_set));
    if (mat->texture) {
        int t = (int)(mat->texture - s->textures);
        put(b, "            .texture = &%s_textures[%d],\n", b->name, b->texture_slot[t]);
    }
    put(b, "            .wrap_u = %s,\n            .wrap_v = %s,\n", wrap_name(mat->wrap_u),
            wrap_name(mat->wrap_v));
    put(b, "            .u_scale = %s,\n", flt(buf, mat->u_scale));
    put(b, "            .v_scale = %s,\n", flt(buf, mat->v_scale));
    put(b, "            .u_offset = %s,\n", flt(buf, mat->u_offset));
    put(b, "            .v_offset = %s,\n", flt(buf, mat->v_offset));
    put(b, "            .v_origin_bottom = %s,\n", tf(mat->v_origin_bottom));
    /* written only when set, as .hidden */
    if (glows(mat))
        put(b, "            .emissive = {%u, %u, %u, %u},\n", mat->emissive.r, mat->emissive.g,
                mat->emissive.b, mat->emissive.a);
    /* highlights and alpha, written only when set (the firmware profile
     * leaves them out: it draws without and counts them) */
    if (mat->specular.r | mat->specular.g | mat->specular.b)
        put(b, "            .specular = {%u, %u, %u, %u},\n            .specular_power = %s,\n",
            mat->specular.r, mat->specular.g, mat->specular.b, mat->specular.a, flt(buf, mat->specular_power));
    if (mat->alpha_mode > MOTE_ALPHA_OPAQUE && mat->alpha_mode < MOTE_ALPHA_COUNT) {
        static const char *const modes[MOTE_ALPHA_COUNT] = {"", "", "MOTE_ALPHA_TEST", "MOTE_ALPHA_BLEND",
                                                            "MOTE_ALPHA_TEST_AND_BLEND"};
        put(b, "            .alpha_mode = %s,\n            .alpha = %s,\n            .alpha_set = %s,\n",
            modes[mat->alpha_mode], flt(buf, mat->alpha), tf(mat->alpha_set));
        put(b, "            .use_texture_alpha = %s,\n            .alpha_cutoff = %s,\n",
            tf(mat->use_texture_alpha), flt(buf, mat->alpha_cutoff));
    }
    put(b, "        },\n");
    put(b, "        .bounds_center = ");
    put_floats(b, m->bounds_center, 3);
    put(b, ",\n        .bounds_radius = %s,\n", flt(buf, m->bounds_radius));
    if (b->color_array[i] >= 0)
        put(b, "        .colors = %s_colors%d,\n", b->name, b->color_array[i]);
    put(b, "    },\n");
}

/* A per-mesh flag of the scene's as an array NAME_WHAT (all 0 when the
 * scene has none) */
static void write_mesh_flags(baker *b, const char *what, const char *comment, const bool *flags)
{
    const int n = b->scene->mesh_count;
    put(b, "/* per mesh: %s */\n", comment);
    put(b, "static const bool %s_%s[%d] = {", b->name, what, n);
    for (int i = 0; i < n; i++)
        put(b, "%s%d", i ? ", " : "", flags && flags[i] ? 1 : 0);
    put(b, "};\n\n");
}

/* A number per mesh as an array NAME_WHAT of TYPE */
static void write_mesh_numbers(baker *b, const char *type, const char *what, const char *comment,
                               const long long *values)
{
    const int n = b->scene->mesh_count;
    put(b, "/* %s */\n", comment);
    put(b, "static const %s %s_%s[%d] = {", type, b->name, what, n);
    for (int i = 0; i < n; i++)
        put(b, "%s%lld", i ? ", " : "", values[i]);
    put(b, "};\n\n");
}

/* The scene's per-mesh draw modes as NAME_modes (all MOTE_MODE_DEFAULT,
 * triangles, when the scene has none) */
static void write_mesh_modes(baker *b, const mote_mode *modes)
{
    static const char *const names[MOTE_MODE_COUNT] = {
        "MOTE_MODE_DEFAULT", "MOTE_MODE_POINTS", "MOTE_MODE_WIREFRAME", "MOTE_MODE_FLAT",
        "MOTE_MODE_GOURAUD", "MOTE_MODE_TEXTURED"};
    const int n = b->scene->mesh_count;
    put(b, "/* per mesh: triangles (MOTE_MODE_DEFAULT: any mode), or points or lines, drawn "
           "in this mode (lines with cull = MOTE_CULL_NONE) */\n");
    put(b, "static const mote_mode %s_modes[%d] = {", b->name, n);
    for (int i = 0; i < n; i++) {
        mote_mode m = modes ? modes[i] : MOTE_MODE_DEFAULT;
        put(b, "%s%s", i ? ", " : "", names[m >= 0 && m < MOTE_MODE_COUNT ? m : 0]);
    }
    put(b, "};\n\n");
}

/* The draw options mote_scene_draw_desc and mote_scene_draw take from the
 * scene, and the order to draw in for the baked camera (blended meshes
 * back to front), so that firmware draws as mote_scene_draw would. */
static void write_draw_options(baker *b, const mote_camera *camera)
{
    const mote_scene *s = b->scene;
    const int n = s->mesh_count;
    write_mesh_flags(b, "two_sided", "draw with cull = MOTE_CULL_NONE (backFaceCulling false)",
                     s->two_sided);
    write_mesh_flags(b, "unlit", "draw with unlit = true (disableLighting)", s->unlit);
    write_mesh_modes(b, s->modes);
    write_mesh_flags(b, "no_depth_write", "draw with no_depth_write = true (disableDepthWrite)",
                     s->no_depth_write);
    write_mesh_flags(b, "no_fog", "draw with no_fog = true (applyFog or fogEnabled false)", s->no_fog);
    write_mesh_flags(b, "depth_pre_pass", "draw twice: with no_color_write = true, then with "
                     "depth_less_equal = true (needDepthPrePass)", s->depth_pre_pass);
    /* calloc: under -fsanitize GCC warns that malloc's values may be read unset */
    long long *values = calloc((size_t)n, sizeof *values);
    int *order = malloc((size_t)n * sizeof *order);
    if (!values || !order) {
        b->out_of_memory = true;
    } else {
        for (int i = 0; i < n; i++)
            values[i] = s->lights_off ? (long long)s->lights_off[i] : 0;
        write_mesh_numbers(b, "uint32_t", "lights_off", "per mesh: draw with lights_off = this "
                           "(a bit for each light that does not light it)", values);
        if (mote_scene_draw_order(s, s->meshes, camera, order) != n)
            b->out_of_memory = true;
        for (int i = 0; i < n; i++)
            values[i] = order[i];
        write_mesh_numbers(b, "int", "draw_order", "the meshes in the order to draw them for the "
                           "frame's camera: opaque, alpha-tested, then blended back to front",
                           values);
    }
    free(values);
    free(order);
}

/* The header's one call for drawing: the meshes as mote_scene_draw draws
 * them, from the options above, so that firmware and the tests share it
 * ('@' in the text stands for the header's name). */
static void write_draw_function(baker *b)
{
    static const char *const text =
        "/* Draws the meshes as mote_scene_draw draws them, in @_draw_order (a\n"
        " * mesh with a depth pre-pass twice), between mote_begin and mote_end. */\n"
        "static inline mote_result @_draw(mote_device *dev)\n"
        "{\n"
        "    for (int k = 0; k < (int)(sizeof @_draw_order / sizeof @_draw_order[0]); k++) {\n"
        "        const int i = @_draw_order[k];\n"
        "        const mote_mesh *m = &@_meshes[i];\n"
        "        mote_draw_desc d = {0};\n"
        "        d.mode = @_modes[i];\n"
        "        if (@_two_sided[i] || d.mode == MOTE_MODE_WIREFRAME)\n"
        "            d.cull = MOTE_CULL_NONE;\n"
        "        d.unlit = @_unlit[i];\n"
        "        d.no_depth_write = @_no_depth_write[i];\n"
        "        d.no_fog = @_no_fog[i];\n"
        "        d.lights_off = @_lights_off[i];\n"
        "        mote_result r;\n"
        "        /* a pre-pass for blended meshes, where blending is built in */\n"
        "        if (MOTE_ENABLE_BLEND && @_depth_pre_pass[i]\n"
        "            && (m->material.alpha_mode == MOTE_ALPHA_BLEND\n"
        "                || m->material.alpha_mode == MOTE_ALPHA_TEST_AND_BLEND)) {\n"
        "            mote_draw_desc depth_only = d;\n"
        "            depth_only.no_color_write = true;\n"
        "            if ((r = mote_draw(dev, m, &depth_only)) != MOTE_OK)\n"
        "                return r;\n"
        "            d.depth_less_equal = true;\n"
        "        }\n"
        "        if ((r = mote_draw(dev, m, &d)) != MOTE_OK)\n"
        "            return r;\n"
        "    }\n"
        "    return MOTE_OK;\n"
        "}\n\n";
    for (const char *p = text; *p;) {
        const char *at = strchr(p, '@');
        const int n = at ? (int)(at - p) : (int)strlen(p);
        put(b, "%.*s%s", n, p, at ? b->name : "");
        p += n + (at != NULL);
    }
}

static void write_frame(baker *b, const mote_frame_desc *fr)
{
    char buf[40];
    put(b, "static const mote_frame_desc %s_frame = {\n    .camera = {\n        .position = ", b->name);
    put_floats(b, fr->camera.position, 3);
    put(b, ",\n        .target = ");
    put_floats(b, fr->camera.target, 3);
    put(b, ",\n        .up = ");
    put_floats(b, fr->camera.up, 3);
    put(b, ",\n        .fov = %s,\n", flt(buf, fr->camera.fov));
    put(b, "        .znear = %s,\n", flt(buf, fr->camera.znear));
    put(b, "        .zfar = %s,\n", flt(buf, fr->camera.zfar));
    if (fr->camera.projection == MOTE_PROJECTION_ORTHOGRAPHIC) {
        put(b, "        .projection = MOTE_PROJECTION_ORTHOGRAPHIC,\n        .ortho = ");
        put_floats(b, fr->camera.ortho, 4);
        put(b, ",\n");
    }
    put(b, "    },\n    .lights = {\n");
    for (int i = 0; i < fr->light_count && i < MOTE_MAX_LIGHTS; i++) {
        const mote_light *l = &fr->lights[i];
        put(b, "        {\n            .type = %s,\n            .position = ", light_name(l->type));
        put_floats(b, l->position, 3);
        put(b, ",\n            .direction = ");
        put_floats(b, l->direction, 3);
        put(b, ",\n            .color = ");
        put_floats(b, l->color, 3);
        put(b, ",\n            .ground_color = ");
        put_floats(b, l->ground_color, 3);
        put(b, ",\n            .intensity = %s,\n", flt(buf, l->intensity));
        put(b, "            .range = %s,\n", flt(buf, l->range));
        put(b, "            .spot_angle = %s,\n", flt(buf, l->spot_angle));
        put(b, "            .spot_exponent = %s,\n", flt(buf, l->spot_exponent));
        put(b, "            .specular = ");
        put_floats(b, l->specular, 3);
        put(b, ",\n        },\n");
    }
    put(b, "    },\n    .light_count = %d,\n    .ambient = ", fr->light_count);
    put_floats(b, fr->ambient, 3);
    if (fr->fog.mode > MOTE_FOG_NONE && fr->fog.mode < MOTE_FOG_COUNT) {
        static const char *const fogs[MOTE_FOG_COUNT] = {"", "MOTE_FOG_LINEAR", "MOTE_FOG_EXP", "MOTE_FOG_EXP2"};
        put(b, ",\n    .fog = {%s, ", fogs[fr->fog.mode]);
        put_floats(b, fr->fog.color, 3);
        put(b, ", %s", flt(buf, fr->fog.density));
        put(b, ", %s", flt(buf, fr->fog.start));
        put(b, ", %s}", flt(buf, fr->fog.end));
    }
    put(b, ",\n    .keep_color = %s,\n    .keep_depth = %s,\n};\n\n", tf(fr->keep_color),
            tf(fr->keep_depth));
}

/* The per-mesh arrays a header holds. */
typedef enum array_kind { ARRAY_VERTICES, ARRAY_INDICES, ARRAY_COLORS } array_kind;

/* A mesh's array of that kind, and its length in elements. */
static const void *mesh_array(const mote_mesh *m, array_kind kind, uint32_t *count)
{
    *count = kind == ARRAY_INDICES ? m->index_count : m->vertex_count;
    return kind == ARRAY_VERTICES ? (const void *)m->vertices
         : kind == ARRAY_INDICES ? (const void *)m->indices : (const void *)m->colors;
}

/* Meshes split from one file share vertex, colour and index arrays: bake
 * each array once. Returns the number of distinct arrays. */
static int share_arrays(const mote_mesh *meshes, int mesh_count, int *which, array_kind kind)
{
    int n = 0;
    for (int i = 0; i < mesh_count; i++) {
        uint32_t count, cj;
        const void *p = mesh_array(&meshes[i], kind, &count);
        which[i] = -1;
        if (!p || count == 0)
            continue;
        for (int j = 0; j < i && which[i] < 0; j++) {
            const void *q = mesh_array(&meshes[j], kind, &cj);
            if (q == p && cj == count)
                which[i] = which[j];
        }
        if (which[i] < 0)
            which[i] = n++;
    }
    return n;
}

/* The vertices a direct-mapped vertex cache of `entries` (a power of two,
 * at most 32) transforms drawing these indices, as the core's integer
 * vertex stage keeps it (vertex_fixed.c): slot index & (entries - 1),
 * empty at the start of a draw. */
static uint32_t cache_transforms(const uint32_t *indices, uint32_t count, uint32_t entries)
{
    uint32_t tag[32], n = 0;
    for (uint32_t k = 0; k < entries; k++)
        tag[k] = UINT32_MAX;
    for (uint32_t i = 0; i < count; i++) {
        uint32_t *t = &tag[indices[i] & (entries - 1)];
        if (*t != indices[i]) {
            *t = indices[i];
            n++;
        }
    }
    return n;
}

/* The meshes a header is written from: copies of the scene's, pointing
 * at the scene's arrays or at reordered ones owned here. */
typedef struct reordered {
    mote_mesh *meshes;
    void **owned;                 /* the arrays allocated for them */
    int owned_count;
    uint32_t (*transforms)[4];    /* baker.transforms */
} reordered;

static void *own(reordered *r, size_t bytes)
{
    void *p = malloc(bytes ? bytes : 1);
    if (p)
        r->owned[r->owned_count++] = p;
    return p;
}

static void reordered_free(reordered *r)
{
    for (int k = 0; k < r->owned_count; k++)
        free(r->owned[k]);
    free(r->owned);
    free(r->meshes);
    free(r->transforms);
}

/* meshoptimizer does not check its allocations: stop here rather than
 * let it write through NULL */
static void *meshopt_alloc(size_t bytes)
{
    void *p = malloc(bytes);
    if (!p) {
        fprintf(stderr, "mote-bake: out of memory (in meshoptimizer)\n");
        exit(1);
    }
    return p;
}

/* Whether mesh i is drawn as triangles from indices, all within its
 * vertices (else it keeps the file's order, with a warning when an index
 * is past them). */
static bool reorderable(const mote_scene *s, int i)
{
    const mote_mesh *m = &s->meshes[i];
    if (!m->vertices || !m->indices || m->vertex_count == 0 || m->index_count < 3 || m->compact)
        return false;
    if (s->modes && (s->modes[i] == MOTE_MODE_POINTS || s->modes[i] == MOTE_MODE_WIREFRAME))
        return false;
    for (uint32_t k = 0; k < m->index_count; k++)
        if (m->indices[k] >= m->vertex_count) {
            fprintf(stderr, "mote-bake: warning: mesh %d: index %u is past its %u vertices: its "
                            "triangles keep the file's order\n", i, (unsigned)m->indices[k],
                    (unsigned)m->vertex_count);
            return false;
        }
    return true;
}

/* Copies of the scene's meshes into r; unless keep_order, each (vertex
 * array, index array) pair drawn as triangles reordered for the
 * firmware's vertex cache: the triangles by meshoptimizer's cache
 * optimiser, then, where no other index array or mesh uses the vertex
 * array, the vertices (and their colours) numbered in order of first use,
 * so that a direct-mapped cache behaves as a FIFO. Instances keep sharing
 * the arrays. A pair that a 32-entry cache would not draw with fewer
 * transforms (a small mesh, a grid already in rows) keeps the file's
 * order. False when out of memory. */
static bool reorder(const mote_scene *s, bool keep_order, reordered *r)
{
    const int n = s->mesh_count;
    const size_t nn = (size_t)(n > 0 ? n : 1);
    r->meshes = malloc(nn * sizeof *r->meshes);
    r->owned = calloc(3 * nn, sizeof *r->owned);
    r->transforms = calloc(nn, sizeof *r->transforms);
    int *va = malloc(nn * sizeof *va), *ia = malloc(nn * sizeof *ia), *first = malloc(nn * sizeof *first);
    bool *ok = calloc(nn, sizeof *ok), *done = calloc(nn, sizeof *done), *solo = calloc(nn, sizeof *solo);
    uint32_t *order = NULL, *remap = NULL;
    bool fine = false;
    if (!r->meshes || !r->owned || !r->transforms || !va || !ia || !first || !ok || !done || !solo)
        goto out;
    if (n > 0)
        memcpy(r->meshes, s->meshes, (size_t)n * sizeof *r->meshes);
    if (keep_order) {
        fine = true;
        goto out;
    }
    meshopt_setAllocator(meshopt_alloc, free);
    const int nv = share_arrays(s->meshes, n, va, ARRAY_VERTICES);
    share_arrays(s->meshes, n, ia, ARRAY_INDICES);
    for (int a = 0; a < nv; a++) {
        first[a] = -1;
        solo[a] = true;
    }
    /* a vertex array is renumbered only when one index array alone uses
     * it, and only as triangles */
    for (int i = 0; i < n; i++) {
        ok[i] = va[i] >= 0 && ia[i] >= 0 && reorderable(s, i);
        if (va[i] < 0)
            continue;
        if (first[va[i]] < 0)
            first[va[i]] = i;
        const int f = first[va[i]];
        if (!ok[i] || !ok[f] || ia[i] != ia[f])
            solo[va[i]] = false;
    }
    for (int f = 0; f < n; f++) {
        if (!ok[f] || done[f])
            continue;
        const mote_mesh *m = &s->meshes[f];
        const uint32_t vc = m->vertex_count, ic = m->index_count, k = ic / 3 * 3;
        uint32_t *indices = own(r, ic * sizeof *indices);
        mote_vertex *vertices = solo[va[f]] ? own(r, vc * sizeof *vertices) : NULL;
        order = malloc(ic * sizeof *order);
        if (!indices || !order || (solo[va[f]] && !vertices))
            goto out;
        /* the indices past the last whole triangle (drawn by none) stay last */
        meshopt_optimizeVertexCache(order, m->indices, k, vc);
        memcpy(order + k, m->indices + k, (ic - k) * sizeof *order);
        if (vertices) {
            remap = malloc(vc * sizeof *remap);
            if (!remap)
                goto out;
            size_t used = meshopt_optimizeVertexFetchRemap(remap, order, k, vc);
            /* vertices no triangle uses after the others, in the file's
             * order: the header keeps every vertex */
            for (uint32_t v = 0; v < vc; v++)
                if (remap[v] == ~0u)
                    remap[v] = (unsigned)used++;
            meshopt_remapIndexBuffer(indices, order, ic, remap);
            meshopt_remapVertexBuffer(vertices, m->vertices, vc, sizeof *vertices, remap);
        } else {
            memcpy(indices, order, ic * sizeof *indices);
        }
        const uint32_t t[4] = {cache_transforms(m->indices, k, 32), cache_transforms(indices, k, 32),
                               cache_transforms(m->indices, k, 16), cache_transforms(indices, k, 16)};
        for (int i = f; i < n; i++) {
            if (!ok[i] || va[i] != va[f] || ia[i] != ia[f])
                continue;
            done[i] = true;
            if (t[1] >= t[0])
                continue;
            memcpy(r->transforms[i], t, sizeof t);
            r->meshes[i].indices = indices;
            if (!vertices)
                continue;
            r->meshes[i].vertices = vertices;
            const mote_rgba *colors = s->meshes[i].colors;
            if (colors) {
                r->meshes[i].colors = NULL;
                for (int j = f; j < i && !r->meshes[i].colors; j++)
                    if (done[j] && va[j] == va[f] && s->meshes[j].colors == colors)
                        r->meshes[i].colors = r->meshes[j].colors;
                if (!r->meshes[i].colors) {
                    mote_rgba *c = own(r, vc * sizeof *c);
                    if (!c)
                        goto out;
                    meshopt_remapVertexBuffer(c, colors, vc, sizeof *c, remap);
                    r->meshes[i].colors = c;
                }
            }
        }
        free(order);
        free(remap);
        order = remap = NULL;
    }
    fine = true;
out:
    free(order);
    free(remap);
    free(va);
    free(ia);
    free(first);
    free(ok);
    free(done);
    free(solo);
    return fine;
}

/* s as text for a comment: printable ASCII but '*' (no end of the
 * comment), '\\' and '?' (no line splice, no trigraph), the other bytes
 * as \xNN. */
static char *comment_text(const char *s)
{
    size_t n = strlen(s);
    char *out = malloc(4 * n + 1), *o = out;
    if (!out)
        return NULL;
    for (; *s; s++) {
        unsigned char c = (unsigned char)*s;
        if (c >= 0x20 && c < 0x7f && c != '*' && c != '\\' && c != '?')
            *o++ = (char)c;
        else
            o += sprintf(o, "\\x%02x", c);
    }
    *o = '\0';
    return out;
}

/* The header, into b->text. */
static void bake(baker *b, int width, int height, const char *source)
{
    const mote_scene *s = b->scene;
    /* macros are NAME_WIDTH...: the name in capitals */
    char upper[72];
    size_t k = 0;
    for (const char *c = b->name; *c && k < sizeof upper - 1; c++)
        upper[k++] = (char)toupper((unsigned char)*c);
    upper[k] = '\0';
    mote_frame_desc frame;
    memset(&frame, 0, sizeof frame);
    mote_scene_frame(s, (float)width / (float)height, &frame);

    char *from = comment_text(source);
    if (!from) {
        b->out_of_memory = true;
        return;
    }
    put(b, "/* %s.h - baked by mote-bake from %s: do not edit. */\n", b->name, from);
    free(from);
    /* the guard keeps the name's case: "a" and "A" are two headers */
    put(b, "#ifndef MOTE_BAKED_%s_H\n#define MOTE_BAKED_%s_H\n\n#include <mote/mote.h>\n\n",
        b->name, b->name);
    put(b, "#ifndef MOTE_BAKE_NAN\n#define MOTE_BAKE_NAN (__builtin_nanf(\"\"))\n"
               "#define MOTE_BAKE_INF (__builtin_inff())\n#endif\n\n");
    unsigned long triangles = 0;
    for (int i = 0; i < s->mesh_count; i++)
        triangles += s->meshes[i].index_count / 3;
    put(b, "#define %s_WIDTH %d\n#define %s_HEIGHT %d\n#define %s_MESH_COUNT %d\n"
           "#define %s_TRIANGLE_COUNT %lu\n\n", upper, width, upper, height, upper, s->mesh_count, upper,
        triangles);

    /* only the textures some mesh uses: an unused static const would warn */
    int slots = 0;
    for (int t = 0; t < s->texture_count; t++) {
        b->texture_slot[t] = -1;
        for (int i = 0; i < s->mesh_count; i++)
            if (s->meshes[i].material.texture == &s->textures[t])
                b->texture_slot[t] = slots;
        if (b->texture_slot[t] < 0)
            continue;
        write_texture(b, &s->textures[t], slots);
        slots++;
    }
    if (slots > 0) {
        put(b, "static const mote_texture %s_textures[%d] = {\n", b->name, slots);
        for (int t = 0; t < s->texture_count; t++) {
            const mote_texture *tx = &s->textures[t];
            const int w = b->texture_width ? b->texture_width : tx->width;
            const int h = b->texture_width ? b->texture_height : tx->height;
            if (b->texture_slot[t] >= 0)
                put(b, "    {%d, %d, %s, %d, %s_texture%d.pixels},\n", w, h, format_name(b->format),
                    w * mote_format_bytes(b->format), b->name, b->texture_slot[t]);
        }
        put(b, "};\n\n");
    }

    const mote_mesh *meshes = b->meshes;
    int nv = share_arrays(meshes, s->mesh_count, b->vertex_array, ARRAY_VERTICES);
    int ni = share_arrays(meshes, s->mesh_count, b->index_array, ARRAY_INDICES);
    int nc = share_arrays(meshes, s->mesh_count, b->color_array, ARRAY_COLORS);
    for (int a = 0; a < nv; a++)
        for (int i = 0; i < s->mesh_count; i++)
            if (b->vertex_array[i] == a) {
                if (compactable(b, &meshes[i]))
                    write_compact_vertices(b, &meshes[i], a);
                else
                    write_vertices(b, &meshes[i], a);
                break;
            }
    for (int a = 0; a < nc; a++)
        for (int i = 0; i < s->mesh_count; i++)
            if (b->color_array[i] == a) {
                write_colors(b, &meshes[i], a);
                break;
            }
    for (int a = 0; a < ni; a++)
        for (int i = 0; i < s->mesh_count; i++)
            if (b->index_array[i] == a) {
                write_indices(b, &meshes[i], a);
                break;
            }
    for (int i = 0; i < s->mesh_count; i++)
        if (b->vertex_array[i] >= 0 && compactable(b, &meshes[i]))
            write_compact(b, i);
    if (s->mesh_count > 0) {
        put(b, "static const mote_mesh %s_meshes[%d] = {\n", b->name, s->mesh_count);
        for (int i = 0; i < s->mesh_count; i++)
            write_mesh(b, i);
        put(b, "};\n\n");
        /* culling, lighting, modes, fog and the order are draw options, not
         * mesh fields: the firmware reads these to draw as mote_scene_draw */
        write_draw_options(b, &frame.camera);
        write_draw_function(b);
    }
    write_frame(b, &frame);
    put(b, "static const mote_rgba %s_clear_color = {%u, %u, %u, %u};\n\n", b->name, s->clear_color.r,
            s->clear_color.g, s->clear_color.b, s->clear_color.a);
    put(b, "#endif\n");
}

/* Whether the macro NAME_WIDTH is one of C23's <limits.h> or <stdint.h>
 * widths (INT_WIDTH, SIZE_WIDTH, UINT8_WIDTH, INT_LEAST16_WIDTH...), upper
 * being NAME in capitals. */
static bool standard_width(const char *upper)
{
    static const char *const names[] = {"CHAR", "SCHAR", "UCHAR", "SHRT", "USHRT", "INT",
                                        "UINT", "LONG", "ULONG", "LLONG", "ULLONG", "BOOL",
                                        "INTPTR", "UINTPTR", "INTMAX", "UINTMAX", "PTRDIFF",
                                        "SIG_ATOMIC", "SIZE", "WCHAR", "WINT", NULL};
    for (int i = 0; names[i]; i++)
        if (!strcmp(upper, names[i]))
            return true;
    const char *p = upper + (upper[0] == 'U');   /* (U)INTn, (U)INT_LEASTn, (U)INT_FASTn */
    if (strncmp(p, "INT", 3) != 0)
        return false;
    p += 3;
    if (!strncmp(p, "_LEAST", 6))
        p += 6;
    else if (!strncmp(p, "_FAST", 5))
        p += 5;
    if (!isdigit((unsigned char)*p))
        return false;
    while (isdigit((unsigned char)*p))
        p++;
    return *p == '\0';
}

/* Why --name cannot prefix the header's identifiers and macros, or NULL. */
static const char *name_problem(const char *s)
{
    if (!*s || strlen(s) > 64 || !(isalpha((unsigned char)*s) || *s == '_'))
        return "is not a C identifier (a letter or '_', then letters, digits, '_'; 64 at most)";
    char upper[72];
    size_t k = 0;
    for (const char *c = s; *c; c++) {
        if (!(isalnum((unsigned char)*c) || *c == '_'))
            return "is not a C identifier (a letter or '_', then letters, digits, '_'; 64 at "
                   "most)";
        upper[k++] = (char)toupper((unsigned char)*c);
    }
    upper[k] = '\0';
    if (s[0] == '_')
        return "starts with '_', as names the C library reserves do";
    if (!strcmp(upper, "MOTE") || !strncmp(upper, "MOTE_", 5))
        return "is mote's own prefix";
    if (standard_width(upper))
        return "makes a macro NAME_WIDTH that <limits.h> or <stdint.h> defines";
    return NULL;
}

/* The fewest characters a texel takes in the header: "0x0000," in
 * RGB565, "0," a byte otherwise. */
static size_t texel_chars(mote_format format)
{
    return mote_format_bytes(format) == 2 ? 7 : 2 * (size_t)mote_format_bytes(format);
}

/* "WxH", each 1..MOTE_MAX_SIZE, nothing else (sscanf's %d was undefined
 * past INT_MAX and took spaces) */
static bool parse_size(const char *s, int *width, int *height)
{
    long v[2];
    for (int k = 0; k < 2; k++) {
        char *end;
        if (!isdigit((unsigned char)*s))
            return false;
        errno = 0;
        v[k] = strtol(s, &end, 10);
        if (errno != 0 || v[k] < 1 || v[k] > MOTE_MAX_SIZE || *end != (k == 0 ? 'x' : '\0'))
            return false;
        s = end + 1;
    }
    *width = (int)v[0];
    *height = (int)v[1];
    return true;
}

int main(int argc, char **argv)
{
    const char *in = NULL, *out = NULL, *name = "scene";
    mote_format format = MOTE_FORMAT_RGB565;
    int width = 320, height = 240, texture_width = 0, texture_height = 0;
    size_t max_bytes = DEFAULT_MAX_BYTES;
    bool compact = false, keep_order = false;
    int normal_bits = 8;
    int gltf_scene = 0;           /* --scene I: I + 1; 0: the file's default */
    for (int i = 1; i < argc; i++) {
        const char *a = argv[i];
        bool has_value = i + 1 < argc;
        if (!strcmp(a, "-h") || !strcmp(a, "--help")) {
            usage(stdout);
            return 0;
        } else if (!strcmp(a, "-o") && has_value) {
            out = argv[++i];
        } else if (!strcmp(a, "--name") && has_value) {
            name = argv[++i];
        } else if (!strcmp(a, "--format") && has_value) {
            const char *v = argv[++i];
            format = texture_format(v);
            if (format == MOTE_FORMAT_DEFAULT) {
                fprintf(stderr, "mote-bake: unknown texture format '%s' (rgb565, rgba8888, grey8)\n", v);
                return 2;
            }
        } else if (!strcmp(a, "--size") && has_value) {
            if (!parse_size(argv[++i], &width, &height)) {
                fprintf(stderr, "mote-bake: --size wants WxH within 1..%d, got '%s'\n", MOTE_MAX_SIZE,
                        argv[i]);
                return 2;
            }
        } else if (!strcmp(a, "--texture-size") && has_value) {
            if (!parse_size(argv[++i], &texture_width, &texture_height)) {
                fprintf(stderr, "mote-bake: --texture-size wants WxH within 1..%d, got '%s'\n",
                        MOTE_MAX_SIZE, argv[i]);
                return 2;
            }
        } else if (!strcmp(a, "--compact")) {
            compact = true;
        } else if (!strcmp(a, "--keep-order")) {
            keep_order = true;
        } else if (!strcmp(a, "--normal-bits") && has_value) {
            const char *v = argv[++i];
            if (strcmp(v, "8") && strcmp(v, "16")) {
                fprintf(stderr, "mote-bake: --normal-bits wants 8 or 16, got '%s'\n", v);
                return 2;
            }
            normal_bits = atoi(v);
        } else if (!strcmp(a, "--max-bytes") && has_value) {
            const char *v = argv[++i];
            char *end;
            errno = 0;
            unsigned long long m = strtoull(v, &end, 10);
            if (!isdigit((unsigned char)*v) || *end || errno || m < 1 || m > SIZE_MAX / 2) {
                fprintf(stderr, "mote-bake: --max-bytes wants a count of bytes, got '%s'\n", v);
                return 2;
            }
            max_bytes = (size_t)m;
        } else if (!strcmp(a, "--scene") && has_value) {
            const char *v = argv[++i];
            char *end;
            errno = 0;
            long k = strtol(v, &end, 10);
            if (!isdigit((unsigned char)*v) || *end || errno || k >= INT_MAX) {
                fprintf(stderr, "mote-bake: --scene wants a glTF scene's index from 0, got '%s'\n", v);
                return 2;
            }
            gltf_scene = (int)k + 1;
        } else if (a[0] != '-' && !in) {
            in = a;
        } else {
            if (a[0] == '-' && !has_value && (!strcmp(a, "-o") || !strcmp(a, "--name")
                                              || !strcmp(a, "--format") || !strcmp(a, "--size")
                                              || !strcmp(a, "--texture-size") || !strcmp(a, "--max-bytes")
                                              || !strcmp(a, "--normal-bits") || !strcmp(a, "--scene")))
                fprintf(stderr, "mote-bake: %s needs a value\n", a);
            else if (a[0] == '-')
                fprintf(stderr, "mote-bake: unknown option %s\n", a);
            else
                fprintf(stderr, "mote-bake: unexpected argument '%s'\n", a);
            usage(stderr);
            return 2;
        }
    }
    if (!in || !out) {
        usage(stderr);
        return 2;
    }
    const char *problem = name_problem(name);
    if (problem) {
        fprintf(stderr, "mote-bake: --name '%s' %s; choose another\n", name, problem);
        return 2;
    }

    /* textures that cannot fit in max_bytes are refused from their image
     * headers, before they are decoded */
    mote_limits limits = mote_limits_default();
    limits.gltf_scene = gltf_scene;
    size_t texels = max_bytes / texel_chars(format);
    if (texels < limits.max_total_texture_bytes / 4)
        limits.max_total_texture_bytes = texels ? texels * 4 : 1;
    mote_scene scene;
    char message[512] = "";
    mote_result r = mote_scene_load(in, &limits, &scene, message, sizeof message);
    if (r != MOTE_OK) {
        fprintf(stderr, "mote-bake: %s\n", message[0] ? message : mote_result_string(r));
        if (r == MOTE_ERR_LIMIT && texels < mote_limits_default().max_total_texture_bytes / 4)
            fprintf(stderr, "mote-bake: a header of at most %zu bytes (--max-bytes) holds %zu "
                            "texels\n", max_bytes, texels);
        return 1;
    }
    if (mote_scene_reads_file(&scene, out)) {
        fprintf(stderr, "mote-bake: -o '%s' is the scene's own file or one of its textures: not "
                        "overwritten\n", out);
        mote_scene_free(&scene);
        return 1;
    }
    if (scene.warning[0])
        fprintf(stderr, "mote-bake: warning: %s\n", scene.warning);
    /* baked scenes go to small builds, which may leave the falloff out */
    for (int i = 0; i < scene.light_count; i++)
        if (scene.lights[i].type == MOTE_LIGHT_SPOT || scene.lights[i].range > 0.0f) {
            fprintf(stderr, "mote-bake: warning: the scene's spot lights and light ranges need "
                            "MOTE_ENABLE_LIGHT_FALLOFF; a build without it (the firmware profile) "
                            "lights nothing by a spot light and ignores ranges\n");
            break;
        }
    for (int i = 0; i < scene.mesh_count; i++)
        if (glows(&scene.meshes[i].material)) {
            fprintf(stderr, "mote-bake: warning: the scene's emissive and ambient colours need "
                            "MOTE_ENABLE_EMISSIVE; a build without it (the firmware profile) "
                            "ignores them\n");
            break;
        }
    /* a header holds one frame's meshes: the levels of detail chosen for
     * its camera (the one bake() writes), hidden flags and all */
    if (scene.lod_count > 0) {
        mote_frame_desc frame;
        mote_scene_frame(&scene, (float)width / (float)height, &frame);
        mote_scene_choose_lod(&scene, scene.meshes, &frame.camera);
        fprintf(stderr, "mote-bake: warning: %d meshes and instances have levels of detail: "
                        "each is baked at the level chosen for the scene's camera, which the "
                        "firmware draws whatever camera it draws with\n", scene.lod_count);
    }
    if (scene.has_camera && scene.camera.projection == MOTE_PROJECTION_ORTHOGRAPHIC)
        fprintf(stderr, "mote-bake: warning: the scene's orthographic camera needs "
                        "MOTE_ENABLE_ORTHOGRAPHIC; mote_begin refuses it in a build without it "
                        "(the firmware profile)\n");

    int status = 1;
    size_t n = (size_t)(scene.mesh_count > 0 ? scene.mesh_count : 1);
    size_t nt = (size_t)(scene.texture_count > 0 ? scene.texture_count : 1);
    reordered meshes = {NULL, NULL, 0, NULL};
    const bool reordered_ok = reorder(&scene, keep_order, &meshes);
    baker b = {NULL, 0, 0, max_bytes, false, false, name, format, texture_width, texture_height, &scene,
               meshes.meshes, calloc(nt, sizeof(int)),
               calloc(n, sizeof(int)), calloc(n, sizeof(int)), calloc(n, sizeof(int)), compact, normal_bits,
               meshes.transforms};
    if (reordered_ok && b.texture_slot && b.vertex_array && b.index_array && b.color_array)
        bake(&b, width, height, in);
    else
        b.out_of_memory = true;
    if (b.out_of_memory) {
        fprintf(stderr, "mote-bake: out of memory\n");
    } else if (b.too_big) {
        fprintf(stderr, "mote-bake: %s: the header would be larger than --max-bytes %zu; "
                        "not written\n", out, max_bytes);
    } else if ((r = mote_write_file(out, b.text, b.size, message, sizeof message)) != MOTE_OK) {
        fprintf(stderr, "mote-bake: %s\n", message[0] ? message : mote_result_string(r));
    } else {
        status = 0;
    }
    free(b.text);
    free(b.texture_slot);
    free(b.vertex_array);
    free(b.index_array);
    free(b.color_array);
    reordered_free(&meshes);
    mote_scene_free(&scene);
    return status;
}
