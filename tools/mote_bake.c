/*
 * mote-bake - turns a .babylon scene into a C header that firmware compiles
 * in: const vertex, vertex colour and index arrays, textures already in the
 * target pixel format, the meshes as mote_mesh (material.texture pointing at the baked
 * texture), which of them are drawn two-sided, the frame (camera, lights,
 * ambient) and the clear colour. The
 * firmware then renders with no file system, no JSON and no heap.
 *
 *   mote-bake SCENE.babylon -o scene.h [--format rgb565|rgba8888|grey8]
 *             [--name NAME] [--size WxH] [--texture-size WxH]
 *
 * Floats are written as C99 hexadecimal literals, so the baked scene is the
 * loaded one bit for bit. --size is the frame the camera's aspect is made
 * for (default 320x240); the header repeats it as NAME_WIDTH/NAME_HEIGHT.
 * A mesh with levels of detail is baked at the level chosen for the baked
 * camera (the others hidden), with a warning: the header has no camera
 * of its own to choose by. --texture-size resamples every texture to WxH
 * with a box filter, so that a large image fits a small chip's flash.
 */
#include <mote/mote.h>
#include <mote/mote_io.h>

#include <ctype.h>
#include <errno.h>
#include <math.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>

#define MOTE_BAKE_MAX(a, b) ((a) > (b) ? (a) : (b))

typedef struct baker {
    FILE *f;
    const char *name;             /* C identifier prefix */
    mote_format format;           /* of the baked textures */
    int texture_width, texture_height; /* --texture-size; 0: as loaded */
    const mote_scene *scene;
    int *texture_slot;            /* per scene texture: index in the baked array, or -1 */
    int *vertex_array;            /* per mesh: which vertices array it uses, or -1 */
    int *index_array;             /* per mesh: which indices array it uses, or -1 */
    int *color_array;             /* per mesh: which colors array it uses, or -1 */
} baker;

static void usage(FILE *out)
{
    fprintf(out,
            "usage: mote-bake SCENE.babylon -o OUT.h [--format rgb565|rgba8888|grey8]\n"
            "                 [--name NAME] [--size WxH] [--texture-size WxH]\n"
            "Writes a C header with the scene's meshes, textures (in FORMAT, default\n"
            "rgb565), camera and lights as const mote structs (identifiers NAME_*,\n"
            "default scene) for a frame of WxH pixels (default 320x240).\n"
            "--texture-size resamples every texture to WxH (a box filter).\n");
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
    fputc('{', b->f);
    for (int i = 0; i < n; i++)
        fprintf(b->f, "%s%s", i ? ", " : "", flt(buf, v[i]));
    fputc('}', b->f);
}

static const char *format_name(mote_format f)
{
    switch (f) {
    case MOTE_FORMAT_RGB565: return "MOTE_FORMAT_RGB565";
    case MOTE_FORMAT_GREY8: return "MOTE_FORMAT_GREY8";
    default: return "MOTE_FORMAT_RGBA8888";
    }
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
        int y1 = MOTE_BAKE_MAX(y0 + 1, (int)((int64_t)(y + 1) * t->height / height));
        for (int x = 0; x < width; x++) {
            int x0 = (int)((int64_t)x * t->width / width);
            int x1 = MOTE_BAKE_MAX(x0 + 1, (int)((int64_t)(x + 1) * t->width / width));
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
static int write_texture(baker *b, const mote_texture *loaded, int slot)
{
    mote_texture resized = *loaded;
    uint8_t *resized_pixels = NULL;
    if (b->texture_width) {
        resized_pixels = box_filter(loaded, b->texture_width, b->texture_height);
        if (!resized_pixels)
            return -1;
        resized = (mote_texture){b->texture_width, b->texture_height, MOTE_FORMAT_RGBA8888, 0,
                                 resized_pixels};
    }
    const mote_texture *t = &resized;
    int bpp = mote_format_bytes(b->format);
    int src_stride = t->stride ? t->stride : t->width * mote_format_bytes(t->format);
    unsigned char *row = malloc((size_t)t->width * (size_t)bpp);
    if (!row) {
        free(resized_pixels);
        return -1;
    }
    /* RGB565 in uint16_t, one a texel; the others in bytes, bpp a texel */
    fprintf(b->f, "static const %s %s_texture%d_pixels[%d * %d * %d] = {\n",
            bpp == 2 ? "uint16_t" : "uint8_t", b->name, slot, t->width, t->height, bpp == 2 ? 1 : bpp);
    for (int y = 0; y < t->height; y++) {
        mote_convert_row((const unsigned char *)t->pixels + (size_t)y * (size_t)src_stride, t->format,
                         row, b->format, t->width);
        for (int x = 0; x < t->width * (bpp == 2 ? 1 : bpp); x++) {
            if (bpp == 2) {
                uint16_t v;
                memcpy(&v, row + 2 * x, 2);
                fprintf(b->f, "0x%04x,", v);
            } else {
                fprintf(b->f, "%u,", row[x]);
            }
            if (x % 16 == 15)
                fputc('\n', b->f);
        }
        fputc('\n', b->f);
    }
    fprintf(b->f, "};\n\n");
    free(row);
    free(resized_pixels);
    return 0;
}

static void write_vertices(baker *b, const mote_mesh *m, int array)
{
    fprintf(b->f, "static const mote_vertex %s_vertices%d[%u] = {\n", b->name, array,
            (unsigned)m->vertex_count);
    for (uint32_t i = 0; i < m->vertex_count; i++) {
        const mote_vertex *v = &m->vertices[i];
        fputc('{', b->f);
        put_floats(b, v->position, 3);
        fputs(", ", b->f);
        put_floats(b, v->normal, 3);
        fputs(", ", b->f);
        put_floats(b, v->uv, 2);
        fputs("},\n", b->f);
    }
    fprintf(b->f, "};\n\n");
}

static void write_colors(baker *b, const mote_mesh *m, int array)
{
    fprintf(b->f, "static const mote_rgba %s_colors%d[%u] = {\n", b->name, array,
            (unsigned)m->vertex_count);
    for (uint32_t i = 0; i < m->vertex_count; i++) {
        const mote_rgba *c = &m->colors[i];
        fprintf(b->f, "%s{%u, %u, %u, %u},", i % 8 ? " " : "", c->r, c->g, c->b, c->a);
        if (i % 8 == 7)
            fputc('\n', b->f);
    }
    fprintf(b->f, "%s};\n\n", m->vertex_count % 8 ? "\n" : "");
}

static void write_indices(baker *b, const mote_mesh *m, int array)
{
    fprintf(b->f, "static const uint32_t %s_indices%d[%u] = {\n", b->name, array, (unsigned)m->index_count);
    for (uint32_t i = 0; i < m->index_count; i++)
        fprintf(b->f, "%u,%s", (unsigned)m->indices[i], i % 16 == 15 ? "\n" : "");
    fprintf(b->f, "\n};\n\n");
}

static void write_mesh(baker *b, int i)
{
    const mote_scene *s = b->scene;
    const mote_mesh *m = &s->meshes[i];
    const mote_material *mat = &m->material;
    char buf[40];
    FILE *f = b->f;
    fprintf(f, "    { /* %d */\n", i);
    if (b->vertex_array[i] >= 0)
        fprintf(f, "        .vertices = %s_vertices%d,\n", b->name, b->vertex_array[i]);
    fprintf(f, "        .vertex_count = %u,\n", (unsigned)m->vertex_count);
    if (b->index_array[i] >= 0)
        fprintf(f, "        .indices = %s_indices%d,\n", b->name, b->index_array[i]);
    fprintf(f, "        .index_count = %u,\n", (unsigned)m->index_count);
    fputs("        .position = ", f);
    put_floats(b, m->position, 3);
    fputs(",\n        .rotation = ", f);
    put_floats(b, m->rotation, 3);
    fputs(",\n        .rotation_quaternion = ", f);
    put_floats(b, m->rotation_quaternion, 4);
    fprintf(f, ",\n        .use_quaternion = %s,\n", tf(m->use_quaternion));
    /* isVisible false, a disabled parent, a camera or light in the tree:
     * written only when set, so headers of scenes without any stay as
     * they were */
    if (m->hidden)
        fputs("        .hidden = true,\n", f);
    fputs("        .scaling = ", f);
    put_floats(b, m->scaling, 3);
    fputs(",\n", f);
    if (m->parent && m->parent >= s->meshes && m->parent < s->meshes + s->mesh_count)
        fprintf(f, "        .parent = &%s_meshes[%d],\n", b->name, (int)(m->parent - s->meshes));
    fprintf(f, "        .material = {\n            .color = {%u, %u, %u, %u},\n"
               "            .color_set = %s,\n",
            mat->color.r, mat->color.g, mat->color.b, mat->color.a, tf(mat->color_set));
    if (mat->texture) {
        int t = (int)(mat->texture - s->textures);
        fprintf(f, "            .texture = &%s_textures[%d],\n", b->name, b->texture_slot[t]);
    }
    fprintf(f, "            .wrap_u = %s,\n            .wrap_v = %s,\n", wrap_name(mat->wrap_u),
            wrap_name(mat->wrap_v));
    fprintf(f, "            .u_scale = %s,\n", flt(buf, mat->u_scale));
    fprintf(f, "            .v_scale = %s,\n", flt(buf, mat->v_scale));
    fprintf(f, "            .u_offset = %s,\n", flt(buf, mat->u_offset));
    fprintf(f, "            .v_offset = %s,\n", flt(buf, mat->v_offset));
    fprintf(f, "            .v_origin_bottom = %s,\n", tf(mat->v_origin_bottom));
    /* written only when set, as .hidden */
    if (glows(mat))
        fprintf(f, "            .emissive = {%u, %u, %u, %u},\n", mat->emissive.r, mat->emissive.g,
                mat->emissive.b, mat->emissive.a);
    fputs("        },\n", f);
    fputs("        .bounds_center = ", f);
    put_floats(b, m->bounds_center, 3);
    fprintf(f, ",\n        .bounds_radius = %s,\n", flt(buf, m->bounds_radius));
    if (b->color_array[i] >= 0)
        fprintf(f, "        .colors = %s_colors%d,\n", b->name, b->color_array[i]);
    fputs("    },\n", f);
}

/* A per-mesh flag of the scene's as an array NAME_WHAT (all 0 when the
 * scene has none) */
static void write_mesh_flags(baker *b, const char *what, const char *comment, const bool *flags)
{
    const int n = b->scene->mesh_count;
    fprintf(b->f, "/* per mesh: %s */\n", comment);
    fprintf(b->f, "static const bool %s_%s[%d] = {", b->name, what, n);
    for (int i = 0; i < n; i++)
        fprintf(b->f, "%s%d", i ? ", " : "", flags && flags[i] ? 1 : 0);
    fprintf(b->f, "};\n\n");
}

static void write_frame(baker *b, const mote_frame_desc *fr)
{
    FILE *f = b->f;
    char buf[40];
    fprintf(f, "static const mote_frame_desc %s_frame = {\n    .camera = {\n        .position = ", b->name);
    put_floats(b, fr->camera.position, 3);
    fputs(",\n        .target = ", f);
    put_floats(b, fr->camera.target, 3);
    fputs(",\n        .up = ", f);
    put_floats(b, fr->camera.up, 3);
    fprintf(f, ",\n        .fov = %s,\n", flt(buf, fr->camera.fov));
    fprintf(f, "        .znear = %s,\n", flt(buf, fr->camera.znear));
    fprintf(f, "        .zfar = %s,\n", flt(buf, fr->camera.zfar));
    if (fr->camera.projection == MOTE_PROJECTION_ORTHOGRAPHIC) {
        fputs("        .projection = MOTE_PROJECTION_ORTHOGRAPHIC,\n        .ortho = ", f);
        put_floats(b, fr->camera.ortho, 4);
        fputs(",\n", f);
    }
    fputs("    },\n    .lights = {\n", f);
    for (int i = 0; i < fr->light_count && i < MOTE_MAX_LIGHTS; i++) {
        const mote_light *l = &fr->lights[i];
        fprintf(f, "        {\n            .type = %s,\n            .position = ", light_name(l->type));
        put_floats(b, l->position, 3);
        fputs(",\n            .direction = ", f);
        put_floats(b, l->direction, 3);
        fputs(",\n            .color = ", f);
        put_floats(b, l->color, 3);
        fputs(",\n            .ground_color = ", f);
        put_floats(b, l->ground_color, 3);
        fprintf(f, ",\n            .intensity = %s,\n", flt(buf, l->intensity));
        fprintf(f, "            .range = %s,\n", flt(buf, l->range));
        fprintf(f, "            .spot_angle = %s,\n", flt(buf, l->spot_angle));
        fprintf(f, "            .spot_exponent = %s,\n        },\n", flt(buf, l->spot_exponent));
    }
    fprintf(f, "    },\n    .light_count = %d,\n    .ambient = ", fr->light_count);
    put_floats(b, fr->ambient, 3);
    fprintf(f, ",\n    .keep_color = %s,\n    .keep_depth = %s,\n};\n\n", tf(fr->keep_color),
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
static int share_arrays(const mote_scene *s, int *which, array_kind kind)
{
    int n = 0;
    for (int i = 0; i < s->mesh_count; i++) {
        uint32_t count, cj;
        const void *p = mesh_array(&s->meshes[i], kind, &count);
        which[i] = -1;
        if (!p || count == 0)
            continue;
        for (int j = 0; j < i && which[i] < 0; j++) {
            const void *q = mesh_array(&s->meshes[j], kind, &cj);
            if (q == p && cj == count)
                which[i] = which[j];
        }
        if (which[i] < 0)
            which[i] = n++;
    }
    return n;
}

static int bake(baker *b, int width, int height, const char *source)
{
    const mote_scene *s = b->scene;
    FILE *f = b->f;
    char guard[128];
    size_t k = 0;
    for (const char *c = b->name; *c && k < sizeof guard - 12; c++)
        guard[k++] = (char)toupper((unsigned char)*c);
    guard[k] = '\0';

    fprintf(f, "/* %s.h - baked by mote-bake from %s: do not edit. */\n", b->name, source);
    fprintf(f, "#ifndef %s_BAKED_H\n#define %s_BAKED_H\n\n#include <mote/mote.h>\n\n", guard, guard);
    fprintf(f, "#ifndef MOTE_BAKE_NAN\n#define MOTE_BAKE_NAN (__builtin_nanf(\"\"))\n"
               "#define MOTE_BAKE_INF (__builtin_inff())\n#endif\n\n");
    fprintf(f, "#define %s_WIDTH %d\n#define %s_HEIGHT %d\n#define %s_MESH_COUNT %d\n\n", guard, width,
            guard, height, guard, s->mesh_count);

    /* only the textures some mesh uses: an unused static const would warn */
    int slots = 0;
    for (int t = 0; t < s->texture_count; t++) {
        b->texture_slot[t] = -1;
        for (int i = 0; i < s->mesh_count; i++)
            if (s->meshes[i].material.texture == &s->textures[t])
                b->texture_slot[t] = slots;
        if (b->texture_slot[t] < 0)
            continue;
        if (write_texture(b, &s->textures[t], slots) != 0)
            return -1;
        slots++;
    }
    if (slots > 0) {
        fprintf(f, "static const mote_texture %s_textures[%d] = {\n", b->name, slots);
        for (int t = 0; t < s->texture_count; t++) {
            const mote_texture *tx = &s->textures[t];
            if (b->texture_slot[t] >= 0) {
                int w = b->texture_width ? b->texture_width : tx->width;
                int h = b->texture_width ? b->texture_height : tx->height;
                fprintf(f, "    {%d, %d, %s, %d, %s_texture%d_pixels},\n", w, h, format_name(b->format),
                        w * mote_format_bytes(b->format), b->name, b->texture_slot[t]);
            }
        }
        fprintf(f, "};\n\n");
    }

    int nv = share_arrays(s, b->vertex_array, ARRAY_VERTICES);
    int ni = share_arrays(s, b->index_array, ARRAY_INDICES);
    int nc = share_arrays(s, b->color_array, ARRAY_COLORS);
    for (int a = 0; a < nv; a++)
        for (int i = 0; i < s->mesh_count; i++)
            if (b->vertex_array[i] == a) {
                write_vertices(b, &s->meshes[i], a);
                break;
            }
    for (int a = 0; a < nc; a++)
        for (int i = 0; i < s->mesh_count; i++)
            if (b->color_array[i] == a) {
                write_colors(b, &s->meshes[i], a);
                break;
            }
    for (int a = 0; a < ni; a++)
        for (int i = 0; i < s->mesh_count; i++)
            if (b->index_array[i] == a) {
                write_indices(b, &s->meshes[i], a);
                break;
            }
    if (s->mesh_count > 0) {
        fprintf(f, "static const mote_mesh %s_meshes[%d] = {\n", b->name, s->mesh_count);
        for (int i = 0; i < s->mesh_count; i++)
            write_mesh(b, i);
        fprintf(f, "};\n\n");
        /* culling and lighting are draw options, not mesh fields: the
         * firmware reads these to draw a mesh as mote_scene_draw_desc would */
        write_mesh_flags(b, "two_sided", "draw with cull = MOTE_CULL_NONE (backFaceCulling false)",
                         s->two_sided);
        write_mesh_flags(b, "unlit", "draw with unlit = true (disableLighting)", s->unlit);
    }

    mote_frame_desc frame;
    memset(&frame, 0, sizeof frame);
    mote_scene_frame(s, (float)width / (float)height, &frame);
    write_frame(b, &frame);
    fprintf(f, "static const mote_rgba %s_clear_color = {%u, %u, %u, %u};\n\n", b->name, s->clear_color.r,
            s->clear_color.g, s->clear_color.b, s->clear_color.a);
    fprintf(f, "#endif\n");
    return ferror(f) ? -1 : 0;
}

static bool valid_name(const char *s)
{
    if (!*s || strlen(s) > 64 || !(isalpha((unsigned char)*s) || *s == '_'))
        return false;
    for (; *s; s++)
        if (!(isalnum((unsigned char)*s) || *s == '_'))
            return false;
    return true;
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
    int width = 320, height = 240;
    int texture_width = 0, texture_height = 0;
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
            if (!strcmp(v, "rgb565"))
                format = MOTE_FORMAT_RGB565;
            else if (!strcmp(v, "rgba8888"))
                format = MOTE_FORMAT_RGBA8888;
            else if (!strcmp(v, "grey8"))
                format = MOTE_FORMAT_GREY8;
            else {
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
        } else if (a[0] != '-' && !in) {
            in = a;
        } else {
            if (a[0] == '-' && !has_value && (!strcmp(a, "-o") || !strcmp(a, "--name")
                                              || !strcmp(a, "--format") || !strcmp(a, "--size")
                                              || !strcmp(a, "--texture-size")))
                fprintf(stderr, "mote-bake: %s needs a value\n", a);
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
    if (!valid_name(name)) {
        fprintf(stderr, "mote-bake: --name '%s' is not a C identifier\n", name);
        return 2;
    }

    mote_scene scene;
    char message[512] = "";
    mote_result r = mote_scene_load(in, NULL, &scene, message, sizeof message);
    if (r != MOTE_OK) {
        fprintf(stderr, "mote-bake: %s\n", message[0] ? message : mote_result_string(r));
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
    baker b = {NULL, name, format, texture_width, texture_height, &scene, calloc(nt, sizeof(int)),
               calloc(n, sizeof(int)), calloc(n, sizeof(int)), calloc(n, sizeof(int))};
    if (!b.texture_slot || !b.vertex_array || !b.index_array || !b.color_array) {
        fprintf(stderr, "mote-bake: out of memory\n");
        goto done;
    }
    b.f = fopen(out, "w");
    if (!b.f) {
        fprintf(stderr, "mote-bake: %s: cannot write: %s\n", out, strerror(errno));
        goto done;
    }
    int w = bake(&b, width, height, in);
    if (fclose(b.f) != 0 || w != 0) {
        fprintf(stderr, "mote-bake: %s: write failed\n", out);
        remove(out);
        goto done;
    }
    status = 0;
done:
    free(b.texture_slot);
    free(b.vertex_array);
    free(b.index_array);
    free(b.color_array);
    mote_scene_free(&scene);
    return status;
}
