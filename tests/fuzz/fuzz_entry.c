/*
 * fuzz_entry.c - what the fuzz targets do with one input, shared with the
 * corpus replay test. See fuzz_entry.h.
 *
 * The draw-path input is read front to back by a byte reader that returns
 * zeros once the data runs out, so every input is valid and short inputs
 * mean "defaults". Floats come one byte at a time (small values, with 16
 * codes for NaN, infinities, huge and tiny values, raw bits), so that the
 * fuzzer reaches drawn triangles quickly and still tries the hostile ones.
 */
#ifndef _POSIX_C_SOURCE
#define _POSIX_C_SOURCE 200809L   /* mkdtemp; this file must come before any system header */
#endif
#include "fuzz_entry.h"

#include <mote/mote.h>
#include <mote/mote_io.h>
#include <io/io_internal.h>

#include <float.h>
#include <math.h>
#include <stdbool.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>

/* ---- byte reader -------------------------------------------------------- */

typedef struct fz_reader {
    const uint8_t *p;
    size_t n;
} fz_reader;

static uint8_t fz_u8(fz_reader *r)
{
    if (r->n == 0)
        return 0;
    r->n--;
    return *r->p++;
}

static uint16_t fz_u16(fz_reader *r)
{
    uint16_t lo = fz_u8(r);
    return (uint16_t)(lo | (uint16_t)fz_u8(r) << 8);
}

static uint32_t fz_u32(fz_reader *r)
{
    uint32_t lo = fz_u16(r);
    return lo | (uint32_t)fz_u16(r) << 16;
}

/* An integer in [lo, hi]. */
static int fz_range(fz_reader *r, int lo, int hi)
{
    return lo + (int)(fz_u16(r) % (uint32_t)(hi - lo + 1));
}

static float fz_float(fz_reader *r)
{
    uint8_t b = fz_u8(r);
    if (b < 240)
        return ((float)b - 120.0f) / 30.0f;     /* [-4, 4) in steps of 1/30 */
    switch (b) {
    case 240: return NAN;
    case 241: return INFINITY;
    case 242: return -INFINITY;
    case 243: return FLT_MAX;
    case 244: return -FLT_MAX;
    case 245: return 1e20f;
    case 246: return -1e20f;
    case 247: return 1e-30f;
    case 248: return -0.0f;
    case 249: return 1e6f;
    case 250: return -1e6f;
    case 251: return 4096.5f;
    case 252: return 1e-3f;
    case 253: return (float)fz_range(r, -300, 300);
    case 254: return FLT_MIN / 4.0f;           /* denormal */
    default: {
        uint32_t bits = fz_u32(r);
        float f;
        memcpy(&f, &bits, sizeof f);
        return f;
    }
    }
}

static void fz_vec3(fz_reader *r, float v[3])
{
    for (int i = 0; i < 3; i++)
        v[i] = fz_float(r);
}

/* ---- guarded buffers ---------------------------------------------------- */

#define FZ_GUARD 64

/* size payload bytes with FZ_GUARD canary bytes on each side; the payload
 * is 16-byte aligned (malloc) so an arena can be 8-byte aligned or not. */
typedef struct fz_buf {
    uint8_t *block;
    uint8_t *p;
    size_t size;
} fz_buf;

static uint8_t fz_canary(size_t i) { return (uint8_t)(0xa5u ^ (i * 37u)); }

static bool fz_buf_alloc(fz_buf *b, size_t size)
{
    b->size = size;
    b->block = (uint8_t *)malloc(size + 2 * FZ_GUARD);
    if (!b->block)
        return false;
    b->p = b->block + FZ_GUARD;
    for (size_t i = 0; i < FZ_GUARD; i++) {
        b->block[i] = fz_canary(i);
        b->p[size + i] = fz_canary(i + 1000);
    }
    memset(b->p, 0x5a, size);
    return true;
}

static bool fz_buf_intact(const fz_buf *b)
{
    if (!b->block)
        return true;
    for (size_t i = 0; i < FZ_GUARD; i++)
        if (b->block[i] != fz_canary(i) || b->p[b->size + i] != fz_canary(i + 1000))
            return false;
    return true;
}

static void fz_buf_free(fz_buf *b)
{
    free(b->block);
    b->block = b->p = NULL;
}

/* ---- the decoded draw input --------------------------------------------- */

#define FZ_MAX_TEX 3
#define FZ_MAX_MESH 4
#define FZ_MAX_VERT 64
#define FZ_MAX_IDX (3 * 48 + 2)
#define FZ_MAX_DRAWS (MOTE_MAX_DRAWS + 6)

typedef struct fz_scene {
    mote_texture tex[FZ_MAX_TEX];          /* as fuzzed: stride 0, tight or padded */
    mote_texture tex_canon[FZ_MAX_TEX];    /* the same pixels, tight explicit stride */
    void *tex_mem[FZ_MAX_TEX], *tex_canon_mem[FZ_MAX_TEX];
    int tex_count;
    mote_vertex vert[FZ_MAX_MESH][FZ_MAX_VERT];
    uint32_t idx[FZ_MAX_MESH][FZ_MAX_IDX];
    mote_mesh mesh[FZ_MAX_MESH];
    mote_mesh mesh_canon[FZ_MAX_MESH];     /* pointing at tex_canon */
    int tex_of_mesh[FZ_MAX_MESH];          /* -1: none */
    int mesh_count;
    int draw_mesh[FZ_MAX_DRAWS];
    mote_draw_desc draw[FZ_MAX_DRAWS];
    bool draw_null_desc[FZ_MAX_DRAWS];
    int draw_count;
    mote_frame_desc frame;
} fz_scene;

/* The device configuration, apart from the buffers. */
typedef struct fz_config {
    int width, height;
    mote_format color_format;
    mote_depth_format depth_format;
    int stride_pad;                       /* bytes after each row */
    int subpixel_bits;                    /* 0 = default */
    int band_height;                      /* 0 = full frame */
    int tile_size;                        /* 0 = default */
    int arena_kind;                       /* 0 none, 1 roomy, 2 tiny (forces flushes) */
    int parallel;                         /* 0 none, 1 in order, 2 reversed, 3 interleaved */
    bool clear_drawn_only;                /* desc.clear_drawn_tiles_only, after a frame from elsewhere */
    mote_rgba clear_color;
    float clear_depth;
    int broken;                           /* > 0: one field made invalid, init must fail */
    bool canonical_textures;
} fz_config;

static void fz_texture(fz_reader *r, fz_scene *s, int i)
{
    mote_texture *t = &s->tex[i];
    uint8_t big = fz_u8(r);
    t->width = big == 255 ? 1 + fz_range(r, 0, 700) : 1 + fz_u8(r) % 40;
    t->height = big == 254 ? 1 + fz_range(r, 0, 700) : 1 + fz_u8(r) % 40;
    /* mostly the three texture formats, now and then one the core must refuse */
    static const mote_format bad[] = {MOTE_FORMAT_RGB565_SWAPPED, MOTE_FORMAT_DEFAULT,
                                      MOTE_FORMAT_COUNT};
    uint8_t f = fz_u8(r);
    t->format = f % 8 < 3 ? MOTE_FORMAT_RGBA8888 : f % 8 < 5 ? MOTE_FORMAT_RGB565
              : f % 8 < 7 ? MOTE_FORMAT_GREY8 : bad[(f >> 3) % 3];
    int bpp = mote_format_bytes(t->format);
    if (bpp == 0)
        bpp = 4;
    int tight = t->width * bpp;
    uint8_t sm = fz_u8(r);
    /* padded strides stay a multiple of the pixel size (uint16_t rows) */
    t->stride = sm % 3 == 0 ? 0 : sm % 3 == 1 ? tight : tight + bpp * (1 + (sm >> 2) % 8);
    int stride = t->stride ? t->stride : tight;
    /* exactly what the texture covers: the last row has no padding */
    size_t bytes = (size_t)stride * (size_t)(t->height - 1) + (size_t)tight;
    uint8_t *px = (uint8_t *)malloc(bytes);
    uint8_t *canon = (uint8_t *)malloc((size_t)tight * (size_t)t->height);
    if (!px || !canon) {
        free(px);
        free(canon);
        t->pixels = NULL;
        return;
    }
    for (size_t k = 0; k < bytes; k++)
        px[k] = r->n ? fz_u8(r) : (uint8_t)(k * 131u + 17u);
    for (int y = 0; y < t->height; y++)
        memcpy(canon + (size_t)y * (size_t)tight, px + (size_t)y * (size_t)stride, (size_t)tight);
    t->pixels = px;
    s->tex_mem[i] = px;
    s->tex_canon_mem[i] = canon;
    s->tex_canon[i] = *t;
    s->tex_canon[i].stride = tight;
    s->tex_canon[i].pixels = canon;
}

static void fz_mesh(fz_reader *r, fz_scene *s, int i)
{
    mote_mesh *m = &s->mesh[i];
    memset(m, 0, sizeof *m);
    uint32_t vc = fz_u8(r) % (FZ_MAX_VERT + 1);
    for (uint32_t v = 0; v < vc; v++) {
        mote_vertex *vx = &s->vert[i][v];
        fz_vec3(r, vx->position);
        uint8_t attrs = fz_u8(r);
        if (attrs & 1)
            fz_vec3(r, vx->normal);
        else
            memcpy(vx->normal, vx->position, sizeof vx->normal);
        if (attrs & 2) {
            vx->uv[0] = fz_float(r);
            vx->uv[1] = fz_float(r);
        } else {
            vx->uv[0] = (float)(v & 1);
            vx->uv[1] = (float)((v >> 1) & 1);
        }
    }
    uint32_t ic = 3u * (fz_u8(r) % 49u);
    uint8_t extra = fz_u8(r);
    if (extra >= 250)
        ic += extra - 249u > 2 ? 2 : extra - 249u;   /* not a multiple of 3 */
    if (ic > FZ_MAX_IDX)
        ic = FZ_MAX_IDX;
    for (uint32_t k = 0; k < ic; k++) {
        uint8_t b = fz_u8(r);
        uint32_t v;
        if (b < 250)
            v = b % (vc + 1);                         /* vc itself is one past the end */
        else if (b == 250)
            v = 0xffffffffu;
        else if (b == 251)
            v = vc + 1;
        else if (b == 252)
            v = 0x7fffffffu;
        else if (b == 253)
            v = 0x80000000u;
        else
            v = fz_u32(r);
        s->idx[i][k] = v;
    }
    m->vertices = vc ? s->vert[i] : NULL;
    m->vertex_count = vc;
    m->indices = ic ? s->idx[i] : NULL;
    m->index_count = ic;
    uint8_t tf = fz_u8(r);
    if (tf & 1)
        fz_vec3(r, m->position);
    if (tf & 2)
        fz_vec3(r, m->rotation);
    if (tf & 4) {
        m->use_quaternion = true;
        for (int k = 0; k < 4; k++)
            m->rotation_quaternion[k] = fz_float(r);
    }
    if (tf & 8)
        fz_vec3(r, m->scaling);
    if ((tf & 16) && i > 0)
        m->parent = &s->mesh[fz_u8(r) % i];       /* earlier meshes only: no cycles */
    uint8_t mf = fz_u8(r);
    mote_material *mat = &m->material;
    if (mf & 1) {
        mat->color_set = true;
        mat->color.r = fz_u8(r);
        mat->color.g = fz_u8(r);
        mat->color.b = fz_u8(r);
    }
    s->tex_of_mesh[i] = -1;
    if ((mf & 2) && s->tex_count > 0) {
        int t = fz_u8(r) % s->tex_count;
        if (s->tex[t].pixels) {
            s->tex_of_mesh[i] = t;
            mat->texture = &s->tex[t];
        }
    }
    if (mf & 4) {
        mat->wrap_u = (mote_wrap)(fz_u8(r) % (MOTE_WRAP_COUNT + 1));
        mat->wrap_v = (mote_wrap)(fz_u8(r) % (MOTE_WRAP_COUNT + 1));
    }
    if (mf & 8) {
        mat->u_scale = fz_float(r);
        mat->v_scale = fz_float(r);
        mat->u_offset = fz_float(r);
        mat->v_offset = fz_float(r);
    }
    mat->v_origin_bottom = (mf & 16) != 0;
    /* parents' bounds do not matter: bounds are in the mesh's own space */
    switch ((mf >> 5) & 3) {
    case 0:
    case 1: mote_mesh_update_bounds(m); break;
    case 2: break;                                /* radius 0: never rejected */
    default:
        fz_vec3(r, m->bounds_center);
        m->bounds_radius = fz_float(r);
        break;
    }
}

static void fz_draw_desc(fz_reader *r, mote_draw_desc *d)
{
    memset(d, 0, sizeof *d);
    const uint8_t m = fz_u8(r);
    d->mode = (mote_mode)(m % (MOTE_MODE_COUNT + 1));
    /* the depth pre-pass's two halves, from bits the mode leaves over */
    d->depth_less_equal = (m & 0x40) != 0;
    d->no_color_write = (m & 0x80) != 0;
    uint8_t o = fz_u8(r);
    d->cull = (mote_cull)(o % (MOTE_CULL_COUNT + 1));
    d->front_face = (o & 0x08) ? MOTE_FRONT_CW : MOTE_FRONT_CCW;
    d->no_depth_test = (o & 0x10) != 0;
    d->no_depth_write = (o & 0x20) != 0;
    d->unlit = (o & 0x40) != 0;
    uint8_t p = fz_u8(r);
    d->perspective = (mote_perspective)(p % (MOTE_PERSPECTIVE_COUNT + 1));
    d->subspan_log2 = (int)((p >> 3) % 9) - 1;    /* -1..7: out of range both ways */
    d->filter = (mote_filter)((p >> 6) % (MOTE_FILTER_COUNT + 1));
    if (o & 0x80) {
        d->point_color.r = fz_u8(r);
        d->point_color.g = fz_u8(r);
        d->point_color.b = fz_u8(r);
        d->point_color.a = fz_u8(r);
    }
}

static void fz_frame(fz_reader *r, mote_frame_desc *f)
{
    memset(f, 0, sizeof *f);
    uint8_t cf = fz_u8(r);
    mote_camera *c = &f->camera;
    /* a camera that sees the origin unless the fuzzer asks otherwise */
    c->position[2] = -6.0f;
    if (cf & 1)
        fz_vec3(r, c->position);
    if (cf & 2)
        fz_vec3(r, c->target);
    if (cf & 4)
        fz_vec3(r, c->up);
    if (cf & 8)
        c->fov = fz_float(r);
    if (cf & 16) {
        c->znear = fz_float(r);
        c->zfar = fz_float(r);
    }
    f->keep_color = (cf & 32) != 0;
    f->keep_depth = (cf & 64) != 0;
    if (cf & 128) {               /* orthographic, any box (empty, inverted, NaN) */
        c->projection = MOTE_PROJECTION_ORTHOGRAPHIC;
        for (int k = 0; k < 4; k++)
            c->ortho[k] = fz_float(r);
    }
    uint8_t lf = fz_u8(r);
    f->light_count = (int)(lf % 8) - 1;           /* -1..6: out of range both ways */
    for (int i = 0; i < MOTE_MAX_LIGHTS && i < f->light_count; i++) {
        mote_light *l = &f->lights[i];
        l->type = (mote_light_type)(fz_u8(r) % (MOTE_LIGHT_TYPE_COUNT + 1));
        fz_vec3(r, l->position);
        fz_vec3(r, l->direction);
        uint8_t e = fz_u8(r);
        if (e & 1)
            fz_vec3(r, l->color);
        if (e & 2)
            fz_vec3(r, l->ground_color);
        if (e & 4)
            l->intensity = fz_float(r);
        if (e & 8)
            l->range = fz_float(r);
        if (e & 16) {
            l->spot_angle = fz_float(r);
            l->spot_exponent = fz_float(r);
        }
    }
    if (lf & 8)
        fz_vec3(r, f->ambient);
}

static void fz_config_read(fz_reader *r, fz_config *c)
{
    memset(c, 0, sizeof *c);
    c->width = 1 + fz_range(r, 0, 299);
    c->height = 1 + fz_range(r, 0, 299);
    uint8_t fm = fz_u8(r);
    c->color_format = (mote_format)((fm & 7) % MOTE_FORMAT_COUNT);
    c->depth_format = (mote_depth_format)((fm >> 3) % MOTE_DEPTH_FORMAT_COUNT);
    /* a multiple of the pixel size: RGB565 rows are uint16_t arrays */
    c->stride_pad = (fm & 0x80) ? (1 + fz_u8(r) % 8) * mote_format_bytes(c->color_format) : 0;
    uint8_t sb = fz_u8(r);
    c->subpixel_bits = sb % 6 == 5 ? 0 : 4 + sb % 6;
    uint8_t bm = fz_u8(r);
    if (bm & 1)
        c->band_height = 1 + fz_range(r, 0, c->height - 1);
    uint8_t tm = fz_u8(r);
    c->tile_size = tm % 7 == 6 ? 0 : 8 << (tm % 6);  /* 8..256 */
    c->arena_kind = (bm >> 1) % 3;
    c->parallel = (bm >> 3) % 4;
    c->clear_drawn_only = (bm & 0x40) != 0;
    uint8_t cc = fz_u8(r);
    if (cc & 1) {
        c->clear_color.r = fz_u8(r);
        c->clear_color.g = fz_u8(r);
        c->clear_color.b = fz_u8(r);
        c->clear_color.a = fz_u8(r);
    }
    if (cc & 2)
        c->clear_depth = fz_float(r);

    /* now and then a broken description: init must refuse it */
    uint8_t br = fz_u8(r);
    c->broken = br >= 240 ? 1 + (br - 240) : 0;
}

static void fz_scene_free(fz_scene *s)
{
    for (int i = 0; i < FZ_MAX_TEX; i++) {
        free(s->tex_mem[i]);
        free(s->tex_canon_mem[i]);
    }
}

/* ---- one render ----------------------------------------------------------- */

typedef struct fz_flush_state {
    const fz_config *cfg;
    const mote_device_desc *desc;
    uint8_t *image;                       /* assembled rows, width * bpp each */
    int next_y;
    const char *error;
} fz_flush_state;

static void fz_flush(void *user, int y0, int rows, const void *color, int stride)
{
    fz_flush_state *st = (fz_flush_state *)user;
    const mote_device_desc *d = st->desc;
    int expect = d->height - st->next_y < d->band_height ? d->height - st->next_y : d->band_height;
    if (y0 != st->next_y || rows != expect || rows <= 0 || color != d->color
        || stride != d->color_stride) {
        if (!st->error)
            st->error = "flush: bands out of order or with wrong rows, buffer or stride";
        return;
    }
    size_t row_bytes = (size_t)d->width * (size_t)mote_format_bytes(d->color_format);
    for (int y = 0; y < rows; y++)
        memcpy(st->image + (size_t)(y0 + y) * row_bytes,
               (const uint8_t *)color + (size_t)y * (size_t)stride, row_bytes);
    st->next_y = y0 + rows;
}

typedef struct fz_hook_state {
    int subpixel_bits, width, height;
    const char *error;
} fz_hook_state;

/* Triangles reaching the rasteriser are inside the bound snapping enforces,
 * |x|, |y| < 2^(MOTE_GUARD_BITS + 1) pixels (mote.h: LIMITS), with depth in
 * [0, 1] and positive w (mote.h: Clipping). */
static void fz_hook(void *user, const int32_t x[3], const int32_t y[3], const float z[3],
                    const float w[3])
{
    fz_hook_state *h = (fz_hook_state *)user;
    int64_t lim = (int64_t)1 << (MOTE_GUARD_BITS + 1 + h->subpixel_bits);
    for (int i = 0; i < 3; i++) {
        if (x[i] >= lim || -(int64_t)x[i] >= lim || y[i] >= lim || -(int64_t)y[i] >= lim) {
            if (!h->error)
                h->error = "triangle hook: snapped vertex outside the guard band";
        }
        if (!(z[i] >= -1e-4f && z[i] <= 1.0001f) || !(w[i] > 0.0f) || !isfinite(w[i])) {
            if (!h->error)
                h->error = "triangle hook: depth outside [0,1] or w not positive";
        }
    }
}

static void fz_parallel(void *user, int count, mote_task_fn fn, void *task_arg)
{
    int kind = *(const int *)user;
    if (kind == 2) {
        for (int i = count - 1; i >= 0; i--)
            fn(task_arg, i);
    } else if (kind == 3) {
        for (int start = 0; start < 3; start++)
            for (int i = start; i < count; i += 3)
                fn(task_arg, i);
    } else {
        for (int i = 0; i < count; i++)
            fn(task_arg, i);
    }
}

typedef struct fz_output {
    uint8_t *image;                       /* width * bpp per row, height rows */
    uint8_t *depth;                       /* full frame only, else NULL */
    bool all_ok;                          /* init, begin, every draw and end OK */
    bool band;
} fz_output;

static const char *fz_render(const fz_config *c, const fz_scene *s, bool canon, fz_output *out)
{
    const char *err = NULL;
    memset(out, 0, sizeof *out);
    mote_device *dev = (mote_device *)malloc(sizeof *dev);
    fz_buf color = {0}, depth = {0}, arena = {0};
    fz_flush_state fl;
    fz_hook_state hk;
    memset(&fl, 0, sizeof fl);
    memset(&hk, 0, sizeof hk);
    int parallel_kind = c->parallel;
    if (!dev)
        return NULL;

    mote_device_desc d;
    memset(&d, 0, sizeof d);
    d.width = c->width;
    d.height = c->height;
    d.color_format = c->color_format;
    d.depth_format = c->depth_format;
    int bpp = mote_format_bytes(c->color_format);
    int dbpp = mote_depth_format_bytes(c->depth_format);
    size_t row_bytes = (size_t)c->width * (size_t)bpp;
    int rows = c->band_height > 0 ? c->band_height : c->height;
    int stride = (int)row_bytes + c->stride_pad;
    d.color_stride = c->stride_pad ? stride : 0;
    d.clear_color = c->clear_color;
    d.clear_depth = c->clear_depth;
    d.subpixel_bits = c->subpixel_bits;
    d.band_height = c->band_height;
    d.tile_size = c->tile_size;
    d.clear_drawn_tiles_only = c->clear_drawn_only;
    if (!fz_buf_alloc(&color, (size_t)stride * (size_t)rows))
        goto done;
    d.color = color.p;
    if (dbpp > 0) {
        if (!fz_buf_alloc(&depth, (size_t)c->width * (size_t)rows * (size_t)dbpp))
            goto done;
        d.depth = depth.p;
    }
    out->band = c->band_height > 0 && c->band_height < c->height;
    out->image = (uint8_t *)calloc(row_bytes ? row_bytes * (size_t)c->height : 1, 1);
    if (!out->image)
        goto done;
    fl.image = out->image;
    if (out->band) {
        d.flush = fz_flush;
        d.flush_user = &fl;
    }
    if (c->arena_kind && !out->band) {
        int ts = c->tile_size ? c->tile_size : 64;
        size_t tiles = (size_t)((c->width + ts - 1) / ts) * (size_t)((c->height + ts - 1) / ts);
        /* the least mote_device_init bins with, plus a little: fills up often */
        size_t tiny = tiles * 16u + 64u * mote_arena_bytes_per_triangle() + 4096u + 64u;
        size_t size = c->arena_kind == 2 ? tiny : tiny + 4096u * mote_arena_bytes_per_triangle();
        if (!fz_buf_alloc(&arena, size))
            goto done;
        d.arena = arena.p;
        d.arena_size = size;
    }
    if (parallel_kind) {
        d.parallel_for = fz_parallel;
        d.parallel_user = &parallel_kind;
    }
    if (!canon) {
        hk.subpixel_bits = c->subpixel_bits ? c->subpixel_bits : 8;
        hk.width = c->width;
        hk.height = c->height;
        d.triangle_hook = fz_hook;
        d.triangle_hook_user = &hk;
    }

    switch (c->broken) {
    case 0: break;
    case 1: d.width = 0; break;
    case 2: d.height = -3; break;
    case 3: d.width = MOTE_MAX_SIZE + 1; break;
    case 4: d.color_format = MOTE_FORMAT_COUNT; break;
    case 5: d.depth_format = (mote_depth_format)(MOTE_DEPTH_FORMAT_COUNT + 2); break;
    case 6: d.color = NULL; break;
    case 7: d.depth_format = MOTE_DEPTH_FORMAT_16; d.depth = NULL; break;
    case 8: d.color_stride = (int)row_bytes - 1; if (d.color_stride == 0) d.color_stride = -1; break;
    case 9: d.subpixel_bits = 3; break;
    case 10: d.subpixel_bits = 9; break;
    case 11: d.tile_size = 48; break;
    case 12: d.tile_size = 512; break;
    case 13: d.height = c->height + 1; d.band_height = c->height; d.flush = NULL; break;
    case 14: d.height = c->height + 1; d.band_height = c->height; d.flush = fz_flush;
             d.flush_user = &fl; d.arena = arena.p ? (void *)arena.p : (void *)color.p;
             d.arena_size = 1 << 20; break;
    default: d.arena = arena.p ? (void *)(arena.p + 4) : (void *)(color.p + 4);
             d.arena_size = 1 << 16; break;
    }
    fl.cfg = c;
    fl.desc = &dev->desc;

    mote_result r = mote_device_init(dev, &d);
    out->all_ok = r == MOTE_OK;
    if (c->broken) {
        if (r != MOTE_ERR_INVALID_ARGUMENT) {
            err = "device init accepted (or refused oddly) an invalid description";
            goto done;
        }
    } else if (r != MOTE_OK) {
        err = "device init refused a valid description";
        goto done;
    } else if (!(dev->desc.clear_depth > 0.0f && dev->desc.clear_depth <= 1.0f)) {
        /* mote.h: clear_depth 0 = 1.0; anything else is cleared as a depth */
        err = "device init kept a clear_depth outside (0, 1]";
        goto done;
    }

    /* clear_drawn_tiles_only: first a frame from another viewpoint, whose
     * pixels the frames below must clear where they do not draw (the plain
     * render they are compared with never saw it) */
    if (c->clear_drawn_only && !c->broken && !out->band) {
        mote_frame_desc elsewhere = s->frame;
        elsewhere.camera.position[0] += 0.75f;
        elsewhere.camera.position[1] -= 0.5f;
        elsewhere.keep_color = elsewhere.keep_depth = false;
        if (mote_begin(dev, &elsewhere) != MOTE_OK) {
            err = "mote_begin: unexpected result";
            goto done;
        }
        for (int i = 0; i < s->draw_count; i++)
            (void)mote_draw(dev, canon ? &s->mesh_canon[s->draw_mesh[i]] : &s->mesh[s->draw_mesh[i]],
                            s->draw_null_desc[i] ? NULL : &s->draw[i]);
        if (mote_end(dev) != MOTE_OK) {
            err = "mote_end: unexpected result";
            goto done;
        }
    }
    for (int frame = 0; frame < 2; frame++) {
        r = mote_begin(dev, &s->frame);
        if (r != (c->broken ? MOTE_ERR_STATE : MOTE_OK)) {
            err = "mote_begin: unexpected result";
            goto done;
        }
        for (int i = 0; i < s->draw_count; i++) {
            const mote_mesh *m = canon ? &s->mesh_canon[s->draw_mesh[i]] : &s->mesh[s->draw_mesh[i]];
            r = mote_draw(dev, m, s->draw_null_desc[i] ? NULL : &s->draw[i]);
            if (r != MOTE_OK) {
                out->all_ok = false;
                bool expected = c->broken ? r == MOTE_ERR_STATE
                                          : out->band && i >= MOTE_MAX_DRAWS && r == MOTE_ERR_TOO_MANY_DRAWS;
                if (!expected) {
                    err = "mote_draw: unexpected result";
                    goto done;
                }
            }
        }
        fl.next_y = 0;
        r = mote_end(dev);
        if (r != (c->broken ? MOTE_ERR_STATE : MOTE_OK)) {
            err = "mote_end: unexpected result";
            goto done;
        }
        if (fl.error) {
            err = fl.error;
            goto done;
        }
        if (hk.error) {
            err = hk.error;
            goto done;
        }
        if (!c->broken && out->band && fl.next_y != c->height) {
            err = "flush: the bands do not cover the frame";
            goto done;
        }
        /* the second frame only when the first kept something: that is
         * what keep_color / keep_depth exercise */
        if (!s->frame.keep_color && !s->frame.keep_depth)
            break;
    }
    if (!c->broken && !out->band) {
        for (int y = 0; y < c->height; y++)
            memcpy(out->image + (size_t)y * row_bytes, color.p + (size_t)y * (size_t)stride, row_bytes);
        if (dbpp > 0) {
            size_t db = (size_t)c->width * (size_t)c->height * (size_t)dbpp;
            out->depth = (uint8_t *)malloc(db);
            if (out->depth)
                memcpy(out->depth, depth.p, db);
        }
    }
    /* the bytes between a row's pixels and the next row are the caller's */
    for (int y = 0; y < rows && !err; y++)
        for (int k = 0; k < c->stride_pad; k++)
            if (color.p[(size_t)y * (size_t)stride + row_bytes + (size_t)k] != 0x5a)
                err = "colour buffer: a write into the stride padding";
    if (c->broken && !err) {
        for (size_t k = 0; k < color.size; k++)
            if (color.p[k] != 0x5a) {
                err = "a device that failed to initialise wrote pixels";
                break;
            }
    }
#ifdef MOTE_FUZZ_DEBUG
    {
        const mote_stats *st = mote_device_stats(dev);
        fprintf(stderr, "%dx%d fmt %d/%d band %d arena %d: tris in %u drawn %u invalid %u "
                "clipped %u back %u degenerate %u, pixels %llu, flushes %u\n",
                c->width, c->height, (int)c->color_format, (int)c->depth_format, c->band_height,
                c->arena_kind, st->triangles_in, st->triangles_drawn, st->triangles_invalid,
                st->triangles_clipped_away, st->triangles_backface, st->triangles_degenerate,
                (unsigned long long)st->pixels_written, st->arena_flushes);
    }
#endif
    /* reading pixels anywhere, in range or not, is harmless */
    for (int k = 0; k < 4; k++)
        (void)mote_read_pixel(dev, k * c->width / 2 - 1, k * c->height / 2 - 1);

done:
    if (!err && (!fz_buf_intact(&color) || !fz_buf_intact(&depth) || !fz_buf_intact(&arena)))
        err = "canary bytes around the colour, depth or arena buffer were overwritten";
    fz_buf_free(&color);
    fz_buf_free(&depth);
    fz_buf_free(&arena);
    free(dev);
    return err;
}

static void fz_output_free(fz_output *o)
{
    free(o->image);
    free(o->depth);
    o->image = o->depth = NULL;
}

static void fz_convert_rows(fz_reader *r)
{
    uint8_t src[64 * 4], dst[64 * 4];
    int n = fz_u8(r) % 65;
    for (int i = 0; i < n * 4; i++)
        src[i] = fz_u8(r);
    mote_format sf = (mote_format)(fz_u8(r) % MOTE_FORMAT_COUNT);
    mote_format df = (mote_format)(fz_u8(r) % MOTE_FORMAT_COUNT);
    mote_convert_row(src, sf, dst, df, n);
}

const char *mote_fuzz_draw(const uint8_t *data, size_t size)
{
    fz_reader rd = {data, size};
    fz_config cfg;
    fz_config_read(&rd, &cfg);
    fz_scene *s = (fz_scene *)calloc(1, sizeof *s);
    if (!s)
        return NULL;
    fz_frame(&rd, &s->frame);
    s->tex_count = fz_u8(&rd) % (FZ_MAX_TEX + 1);
    /* meshes before texture pixels: the pixels eat the rest of the input */
    uint8_t counts = fz_u8(&rd);
    s->mesh_count = 1 + counts % FZ_MAX_MESH;
    uint8_t dc = fz_u8(&rd);
    s->draw_count = dc == 255 ? FZ_MAX_DRAWS : 1 + dc % 8;
    uint8_t dtex[FZ_MAX_TEX][6];
    for (int i = 0; i < s->tex_count; i++)
        for (int k = 0; k < 6; k++)
            dtex[i][k] = fz_u8(&rd);
    for (int i = 0; i < s->draw_count; i++) {
        s->draw_mesh[i] = i < 8 ? fz_u8(&rd) % s->mesh_count : i % s->mesh_count;
        if (i < 8) {
            s->draw_null_desc[i] = fz_u8(&rd) == 0xff;
            fz_draw_desc(&rd, &s->draw[i]);
        } else {
            s->draw[i] = s->draw[i % 8];
            s->draw_null_desc[i] = s->draw_null_desc[i % 8];
        }
    }
    /* textures exist before meshes point at them; their size bytes came
     * early, their pixels come from the end of the input */
    for (int i = 0; i < s->tex_count; i++) {
        fz_reader tr = {dtex[i], 6};
        fz_texture(&tr, s, i);
    }
    for (int i = 0; i < s->mesh_count; i++)
        fz_mesh(&rd, s, i);
    fz_convert_rows(&rd);
    /* the rest of the input is texel data */
    for (int i = 0; i < s->tex_count; i++) {
        mote_texture *t = &s->tex[i];
        if (!t->pixels)
            continue;
        uint8_t *px = (uint8_t *)s->tex_mem[i];
        int bpp = mote_format_bytes(t->format) ? mote_format_bytes(t->format) : 4;
        size_t tight = (size_t)t->width * (size_t)bpp;
        size_t stride = t->stride ? (size_t)t->stride : tight;
        for (int y = 0; y < t->height && rd.n; y++)
            for (size_t k = 0; k < tight && rd.n; k++)
                px[(size_t)y * stride + k] = fz_u8(&rd);
        for (int y = 0; y < t->height; y++)
            memcpy((uint8_t *)s->tex_canon_mem[i] + (size_t)y * tight, px + (size_t)y * stride, tight);
    }
    for (int i = 0; i < s->mesh_count; i++) {
        s->mesh_canon[i] = s->mesh[i];
        if (s->tex_of_mesh[i] >= 0)
            s->mesh_canon[i].material.texture = &s->tex_canon[s->tex_of_mesh[i]];
        if (s->mesh[i].parent)
            s->mesh_canon[i].parent = &s->mesh_canon[s->mesh[i].parent - s->mesh];
    }

    fz_output a, b;
    memset(&b, 0, sizeof b);
    const char *err = fz_render(&cfg, s, false, &a);
    if (!err && !cfg.broken && a.all_ok && !s->frame.keep_color && !s->frame.keep_depth) {
        /* the same frame the plain way: full frame, no arena, tight stride,
         * tiles in order, textures with explicit tight strides */
        fz_config ref = cfg;
        ref.band_height = 0;
        ref.arena_kind = 0;
        ref.parallel = 0;
        ref.stride_pad = 0;
        ref.clear_drawn_only = false;
        err = fz_render(&ref, s, true, &b);
        if (!err && b.all_ok) {
            size_t bytes = (size_t)cfg.width * (size_t)cfg.height
                         * (size_t)mote_format_bytes(cfg.color_format);
            if (memcmp(a.image, b.image, bytes) != 0)
                err = "determinism: colour differs from a plain full-frame render";
            else if (a.depth && b.depth
                     && memcmp(a.depth, b.depth, (size_t)cfg.width * (size_t)cfg.height
                                   * (size_t)mote_depth_format_bytes(cfg.depth_format)) != 0)
                err = "determinism: depth differs from a plain full-frame render";
        }
    }
    fz_output_free(&a);
    fz_output_free(&b);
    fz_scene_free(s);
    free(s);
    return err;
}

/* ---- loaders ---------------------------------------------------------------- */

/* A failing loader leaves a message that is terminated, not empty, and
 * within the buffer. */
static const char *fz_check_message(const char *msg, size_t size)
{
    if (memchr(msg, '\0', size) == NULL)
        return "error message not terminated inside its buffer";
    if (msg[0] == '\0')
        return "error without a message";
    return NULL;
}

/* Draws a loaded texture on a quad, every filter and wrap. */
static void fz_draw_texture(const mote_texture *t)
{
    static uint8_t color[24 * 20 * 4];
    static uint32_t depth[24 * 20];
    mote_device dev;
    mote_device_desc d;
    memset(&d, 0, sizeof d);
    d.width = 24;
    d.height = 20;
    d.color = color;
    d.depth = depth;
    if (mote_device_init(&dev, &d) != MOTE_OK)
        return;
    static const mote_vertex quad[4] = {
        {{-1, -1, 0}, {0, 0, -1}, {-0.3f, 1.2f}}, {{-1, 1, 0}, {0, 0, -1}, {-0.3f, -0.4f}},
        {{1, 1, 0}, {0, 0, -1}, {1.7f, -0.4f}},   {{1, -1, 0}, {0, 0, -1}, {1.7f, 1.2f}}};
    static const uint32_t idx[6] = {0, 1, 2, 0, 2, 3};
    mote_mesh m;
    memset(&m, 0, sizeof m);
    m.vertices = quad;
    m.vertex_count = 4;
    m.indices = idx;
    m.index_count = 6;
    m.material.texture = t;
    m.rotation[0] = 0.5f;
    mote_frame_desc f;
    memset(&f, 0, sizeof f);
    f.camera.position[2] = -3.0f;
    mote_begin(&dev, &f);
    for (int k = 0; k < 6; k++) {
        mote_draw_desc dd;
        memset(&dd, 0, sizeof dd);
        dd.mode = MOTE_MODE_TEXTURED;
        dd.cull = MOTE_CULL_NONE;
        dd.unlit = true;
        dd.filter = k & 1 ? MOTE_FILTER_BILINEAR : MOTE_FILTER_NEAREST;
        m.material.wrap_u = m.material.wrap_v = (mote_wrap)(1 + k / 2);
        mote_draw(&dev, &m, &dd);
    }
    mote_end(&dev);
}

const char *mote_fuzz_texture(const uint8_t *data, size_t size)
{
    mote_limits lim = mote_limits_default();
    /* small enough that the fuzzer stays fast; the checks are the same */
    lim.max_texture_width = 2048;
    lim.max_texture_height = 2048;
    lim.max_texture_bytes = (size_t)16 << 20;
    long live = mote__io_live_allocations();
    mote_texture t;
    char msg[200];
    memset(msg, 'x', sizeof msg);
    mote_result r = mote_texture_load_memory(data, size, &lim, &t, msg, sizeof msg);
    const char *err = NULL;
    if (r == MOTE_OK) {
        if (t.width < 1 || t.height < 1 || t.width > lim.max_texture_width
            || t.height > lim.max_texture_height || t.format != MOTE_FORMAT_RGBA8888
            || t.stride < t.width * 4 || !t.pixels)
            err = "texture: loaded with an impossible size, format, stride or no pixels";
        else if ((size_t)t.width * (size_t)t.height * 4u > lim.max_texture_bytes)
            err = "texture: loaded past max_texture_bytes";
        if (!err) {
            /* every byte readable (ASan checks the extent) */
            const uint8_t *p = (const uint8_t *)t.pixels;
            unsigned sum = 0;
            for (int y = 0; y < t.height; y++)
                for (int x = 0; x < t.width * 4; x++)
                    sum += p[(size_t)y * (size_t)t.stride + (size_t)x];
            volatile unsigned sink = sum;
            (void)sink;
            fz_draw_texture(&t);
        }
        mote_texture_free(&t);
        if (t.pixels || t.width || t.height)
            err = err ? err : "texture: mote_texture_free did not zero the texture";
        if (!err) {
            /* the same image with the decode's allocation failing */
            mote__io_set_alloc_failure_after(0);
            r = mote_texture_load_memory(data, size, &lim, &t, msg, sizeof msg);
            mote__io_set_alloc_failure_after(-1);
            if (r == MOTE_OK)
                mote_texture_free(&t);
            else if (r != MOTE_ERR_OUT_OF_MEMORY)
                err = "texture: a failed allocation reported as something else";
        }
    } else {
        if ((int)r <= 0 || r >= MOTE_RESULT_COUNT)
            err = "texture: result out of range";
        else if (t.pixels || t.width || t.height)
            err = "texture: failed load left a texture behind";
        else
            err = fz_check_message(msg, sizeof msg);
        if (!err) {
            /* a short message buffer is never overrun */
            char small[12];
            memset(small, 'x', sizeof small);
            mote_texture_load_memory(data, size, &lim, &t, small, 5);
            if (small[4] != '\0' || small[5] != 'x')
                err = "texture: message overran a short buffer or was not terminated";
        }
    }
    /* an input that reads as a data: URL is also an embedded image: the
     * base64 decoder in front of the same checks */
    if (!err && size >= 5 && size < ((size_t)1 << 24)) {
        char *url = (char *)malloc(size + 1);
        if (url) {
            memcpy(url, data, size);
            url[size] = '\0';
            if (mote__io_is_data_url(url)) {
                memset(&t, 0, sizeof t);
                r = mote__io_texture_load_data_url(url, &lim, &t, msg, sizeof msg);
                if (r == MOTE_OK) {
                    if (t.width < 1 || t.height < 1 || t.width > lim.max_texture_width
                        || t.height > lim.max_texture_height || !t.pixels)
                        err = "data URL: loaded with an impossible size or no pixels";
                    mote_texture_free(&t);
                } else if ((int)r <= 0 || r >= MOTE_RESULT_COUNT) {
                    err = "data URL: result out of range";
                } else if (t.pixels || t.width || t.height) {
                    err = "data URL: failed load left a texture behind";
                } else {
                    err = fz_check_message(msg, sizeof msg);
                }
            }
            free(url);
        }
    }
    if (!err && mote__io_live_allocations() != live)
        err = "texture: allocations leaked (mote__io_live_allocations)";
    return err;
}

#ifndef MOTE_FUZZ_NO_SCENE

#include <unistd.h>

/* A folder with a small texture under the names the seeds use, made once
 * per process, for scenes that name textures; removed at exit. */
static char fz_dir[64];
static const char *const fz_tex_names[] = {"tex.png", "checker.png"};

static void fz_dir_remove(void)
{
    char path[128];
    for (size_t i = 0; i < sizeof fz_tex_names / sizeof fz_tex_names[0]; i++) {
        snprintf(path, sizeof path, "%s/%s", fz_dir, fz_tex_names[i]);
        remove(path);
    }
    rmdir(fz_dir);
}

static const char *fz_texture_dir(void)
{
    if (fz_dir[0])
        return fz_dir;
    char tmpl[] = "/tmp/mote-fuzz-XXXXXX";
    if (!mkdtemp(tmpl))
        return NULL;
    snprintf(fz_dir, sizeof fz_dir, "%s", tmpl);
    uint8_t rgba[5 * 3 * 4];
    for (size_t i = 0; i < sizeof rgba; i++)
        rgba[i] = (uint8_t)(i * 53u + 7u);
    for (size_t i = 0; i < sizeof fz_tex_names / sizeof fz_tex_names[0]; i++) {
        char path[128], msg[128];
        snprintf(path, sizeof path, "%s/%s", fz_dir, fz_tex_names[i]);
        mote_write_rgba(path, rgba, 5, 3, 5 * 4, msg, sizeof msg);
    }
    atexit(fz_dir_remove);
    return fz_dir;
}

static const char *fz_check_scene(const mote_scene *sc)
{
    if (sc->mesh_count < 0 || (sc->mesh_count > 0 && !sc->meshes))
        return "scene: mesh count or mesh array wrong";
    if (sc->texture_count < 0 || (sc->texture_count > 0 && !sc->textures))
        return "scene: texture count or texture array wrong";
    if (sc->light_count < 0 || sc->light_count > MOTE_MAX_LIGHTS)
        return "scene: light count out of range";
    if (!memchr(sc->warning, '\0', sizeof sc->warning))
        return "scene: warning not terminated";
    for (int i = 0; i < sc->mesh_count; i++) {
        const mote_mesh *m = &sc->meshes[i];
        if ((m->vertex_count > 0 && !m->vertices) || (m->index_count > 0 && !m->indices))
            return "scene: mesh with counts but no arrays";
        for (uint32_t k = 0; k < m->index_count; k++)
            if (m->indices[k] >= m->vertex_count)
                return "scene: index out of range accepted";
        /* touch every vertex (ASan checks the extent) */
        float sum = 0.0f;
        for (uint32_t k = 0; k < m->vertex_count; k++)
            sum += m->vertices[k].position[0] + m->vertices[k].uv[1] + m->vertices[k].normal[2];
        volatile float sink = sum;
        (void)sink;
        const mote_texture *t = m->material.texture;
        if (t && (t < sc->textures || t >= sc->textures + sc->texture_count))
            return "scene: material texture not one of the scene's textures";
        const mote_mesh *p = m->parent;
        for (int depth = 0; p; depth++) {
            if (p < sc->meshes || p >= sc->meshes + sc->mesh_count)
                return "scene: parent not one of the scene's meshes";
            if (depth > sc->mesh_count)
                return "scene: parent cycle";
            p = p->parent;
        }
    }
    for (int i = 0; i < sc->texture_count; i++) {
        const mote_texture *t = &sc->textures[i];
        if (t->pixels && (t->width < 1 || t->height < 1 || t->stride < t->width * 4))
            return "scene: texture with an impossible size";
    }
    return NULL;
}

/* Draws the scene full frame and in bands of 7 rows: same bytes. */
static const char *fz_draw_scene(const mote_scene *sc)
{
    enum { W = 40, H = 30, BAND = 7 };
    static uint8_t color[W * H * 4], band_color[W * BAND * 4], assembled[W * H * 4];
    static uint32_t depth[W * H], band_depth[W * BAND];
    mote_frame_desc f;
    mote_scene_frame(sc, (float)W / (float)H, &f);
    const char *err = NULL;
    for (int pass = 0; pass < 2 && !err; pass++) {
        mote_device dev;
        mote_device_desc d;
        memset(&d, 0, sizeof d);
        d.width = W;
        d.height = H;
        d.clear_color = sc->clear_color;
        fz_flush_state fl;
        memset(&fl, 0, sizeof fl);
        fl.desc = &dev.desc;
        fl.image = assembled;
        if (pass == 0) {
            d.color = color;
            d.depth = depth;
        } else {
            d.color = band_color;
            d.depth = band_depth;
            d.band_height = BAND;
            d.flush = fz_flush;
            d.flush_user = &fl;
        }
        if (mote_device_init(&dev, &d) != MOTE_OK)
            return "scene: device init failed";
        mote_begin(&dev, &f);
        bool ok = true;
        /* band mode records at most MOTE_MAX_DRAWS draws, and a mesh with
         * a depth pre-pass takes two */
        int n = sc->mesh_count < MOTE_MAX_DRAWS / 2 ? sc->mesh_count : MOTE_MAX_DRAWS / 2;
        for (int i = 0; i < n; i++)
            if (mote_scene_draw(&dev, sc, sc->meshes, i, NULL) != MOTE_OK)
                ok = false;
        if (mote_end(&dev) != MOTE_OK)
            ok = false;
        if (!ok)
            err = "scene: drawing a loaded scene failed";
        else if (fl.error)
            err = fl.error;
    }
    if (!err && memcmp(color, assembled, sizeof color) != 0)
        err = "scene: bands and full frame differ";
    return err;
}

static uint32_t fz_hash(const uint8_t *data, size_t size)
{
    uint32_t h = 2166136261u;
    for (size_t i = 0; i < size; i++)
        h = (h ^ data[i]) * 16777619u;
    return h;
}

const char *mote_fuzz_scene(const uint8_t *data, size_t size)
{
    mote_limits lim = mote_limits_default();
    lim.max_texture_width = 1024;
    lim.max_texture_height = 1024;
    lim.max_texture_bytes = (size_t)8 << 20;
    lim.missing_texture_is_warning = (size & 1) != 0;
    long live = mote__io_live_allocations();
    const char *err = NULL;
    bool loaded = false;
    for (int pass = 0; pass < 2 && !err; pass++) {
        const char *base = pass == 0 ? NULL : fz_texture_dir();
        mote_scene sc;
        char msg[256];
        memset(msg, 'x', sizeof msg);
        mote_result r = mote_scene_load_memory((const char *)data, size, "fuzz.babylon", base,
                                               &lim, &sc, msg, sizeof msg);
        if (r == MOTE_OK) {
            loaded = true;
            err = fz_check_scene(&sc);
            if (!err)
                err = fz_draw_scene(&sc);
            mote_scene_free(&sc);
        } else if ((int)r <= 0 || r >= MOTE_RESULT_COUNT) {
            err = "scene: result out of range";
        } else {
            err = fz_check_message(msg, sizeof msg);
        }
        if (!err && mote__io_live_allocations() != live)
            err = "scene: allocations leaked (mote__io_live_allocations)";
    }
    if (!err && loaded) {
        /* again, with one allocation failing part-way */
        mote_scene sc;
        char msg[256];
        mote__io_set_alloc_failure_after((int)(fz_hash(data, size) % 24u));
        mote_result r = mote_scene_load_memory((const char *)data, size, "fuzz.babylon", NULL,
                                               &lim, &sc, msg, sizeof msg);
        mote__io_set_alloc_failure_after(-1);
        if (r == MOTE_OK)
            mote_scene_free(&sc);
        else if (r != MOTE_ERR_OUT_OF_MEMORY)
            err = "scene: a failed allocation reported as something else";
        else
            err = fz_check_message(msg, sizeof msg);
        if (!err && mote__io_live_allocations() != live)
            err = "scene: allocations leaked after a failed allocation";
    }
    return err;
}

static void fz_le32(uint8_t *p, uint32_t v)
{
    p[0] = (uint8_t)v, p[1] = (uint8_t)(v >> 8), p[2] = (uint8_t)(v >> 16), p[3] = (uint8_t)(v >> 24);
}

const char *mote_fuzz_gltf(const uint8_t *data, size_t size)
{
    if (size == 0 || data[0] != 1)
        return mote_fuzz_scene(data, size);
    const uint8_t *json = data + 1;
    size_t rest = size - 1;
    const uint8_t *nul = memchr(json, 0, rest);
    size_t jn = nul ? (size_t)(nul - json) : rest;
    const uint8_t *bin = nul ? nul + 1 : NULL;
    size_t bn = nul ? rest - jn - 1 : 0;
    size_t jp = (jn + 3) & ~(size_t)3, bp = (bn + 3) & ~(size_t)3;
    size_t total = 12 + 8 + jp + (bin ? 8 + bp : 0);
    uint8_t *glb = calloc(total, 1);
    if (!glb)
        return NULL;
    memcpy(glb, "glTF", 4);
    fz_le32(glb + 4, 2);
    fz_le32(glb + 8, (uint32_t)total);
    fz_le32(glb + 12, (uint32_t)jp);
    memcpy(glb + 16, "JSON", 4);
    memcpy(glb + 20, json, jn);
    memset(glb + 20 + jn, ' ', jp - jn);
    if (bin) {
        uint8_t *c = glb + 20 + jp;
        fz_le32(c, (uint32_t)bp);
        memcpy(c + 4, "BIN", 4);
        memcpy(c + 8, bin, bn);
    }
    const char *err = mote_fuzz_scene(glb, total);
    free(glb);
    return err;
}

/* ---- a scene's folder with links (mote_fuzz_folder) --------------------- */

#include <dirent.h>
#include <fcntl.h>
#include <sys/stat.h>

/* Removes name in dirfd, and what it holds when it is a real folder: links
 * are removed, never followed. */
static void fz_remove_at(int dirfd, const char *name)
{
    struct stat st;
    if (fstatat(dirfd, name, &st, AT_SYMLINK_NOFOLLOW) != 0)
        return;
    if (S_ISDIR(st.st_mode)) {
        int fd = openat(dirfd, name, O_RDONLY | O_DIRECTORY | O_NOFOLLOW);
        DIR *d = fd >= 0 ? fdopendir(fd) : NULL;
        if (d) {
            struct dirent *e;
            while ((e = readdir(d)) != NULL)
                if (strcmp(e->d_name, ".") != 0 && strcmp(e->d_name, "..") != 0)
                    fz_remove_at(fd, e->d_name);
            closedir(d);
        } else if (fd >= 0) {
            close(fd);
        }
        unlinkat(dirfd, name, AT_REMOVEDIR);
    } else {
        unlinkat(dirfd, name, 0);
    }
}

/* The regular files beneath dirfd, links not followed. */
typedef struct fz_files {
    mote__io_file_id id[256];
    int count;
} fz_files;

static void fz_collect(int dirfd, fz_files *files, int depth)
{
    DIR *d = fdopendir(dup(dirfd));
    if (!d)
        return;
    struct dirent *e;
    while ((e = readdir(d)) != NULL) {
        struct stat st;
        if (!strcmp(e->d_name, ".") || !strcmp(e->d_name, "..") ||
            fstatat(dirfd, e->d_name, &st, AT_SYMLINK_NOFOLLOW) != 0)
            continue;
        if (S_ISREG(st.st_mode) && files->count < 256) {
            files->id[files->count].device = (uint64_t)st.st_dev;
            files->id[files->count++].inode = (uint64_t)st.st_ino;
        } else if (S_ISDIR(st.st_mode) && depth < 16) {
            int fd = openat(dirfd, e->d_name, O_RDONLY | O_DIRECTORY | O_NOFOLLOW);
            if (fd >= 0) {
                fz_collect(fd, files, depth + 1);
                close(fd);
            }
        }
    }
    closedir(d);
}

/* The folder that will hold path's last component, beneath dirfd through
 * real folders only (the harness itself must not write through a link);
 * -1 when path is absolute, has "." or ".." or goes through a link. */
static int fz_parent(int dirfd, const char *path, const char **leaf)
{
    int fd = dup(dirfd);
    const char *p = path;
    for (;;) {
        size_t n = strcspn(p, "/");
        char part[128];
        if (fd < 0 || n == 0 || n >= sizeof part || (n == 1 && p[0] == '.') ||
            (n == 2 && p[0] == '.' && p[1] == '.')) {
            if (fd >= 0)
                close(fd);
            return -1;
        }
        if (!p[n]) {
            *leaf = p;
            return fd;
        }
        memcpy(part, p, n);
        part[n] = '\0';
        int next = openat(fd, part, O_RDONLY | O_DIRECTORY | O_NOFOLLOW);
        close(fd);
        fd = next;
        p += n + 1;
    }
}

/* A 1 x 1 PNG of one colour, through mote's own writer. */
static void fz_png_at(const char *path, uint8_t r, uint8_t g)
{
    const uint8_t px[4] = {r, g, 0, 255};
    char msg[160];
    mote_write_rgba(path, px, 1, 1, 4, msg, sizeof msg);
}

/* Whether id is one of files. */
static bool fz_inside(const fz_files *files, mote__io_file_id id)
{
    for (int i = 0; i < files->count; i++)
        if (mote__io_same_file(files->id[i], id))
            return true;
    return false;
}

/* s into out (size n), each '@' replaced by root. */
static void fz_expand_root(char *out, size_t n, const char *s, const char *root)
{
    size_t k = 0, rn = strlen(root);
    for (; *s && k + rn + 1 < n; s++) {
        if (*s == '@') {
            memcpy(out + k, root, rn);
            k += rn;
        } else {
            out[k++] = *s;
        }
    }
    out[k] = '\0';
}

const char *mote_fuzz_folder(const uint8_t *data, size_t size)
{
    char root[64] = "/tmp/mote-fuzz-folder-XXXXXX";
    if (!mkdtemp(root))
        return NULL;
    char scene[96], path[400];
    snprintf(scene, sizeof scene, "%s/scene", root);
    snprintf(path, sizeof path, "%s/outside", root);
    mkdir(scene, 0700);
    mkdir(path, 0700);
    snprintf(path, sizeof path, "%s/outside/outside.png", root);
    fz_png_at(path, 200, 0);                   /* red: what must never be read */
    int dirfd = open(scene, O_RDONLY | O_DIRECTORY);
    char name[400] = "in.png";
    int ops = 0;
    /* the input, line by line: "d PATH" a folder, "f PATH" an inside
     * (green) texture, "p PATH" a FIFO, "l PATH TARGET" a link, "t NAME"
     * the texture name the scene gives; '@' in TARGET and NAME is the
     * temporary root's path, where outside/ is */
    for (size_t at = 0; at < size && ops < 64 && dirfd >= 0; ops++) {
        const uint8_t *nl = memchr(data + at, '\n', size - at);
        size_t len = nl ? (size_t)(nl - (data + at)) : size - at;
        char line[300];
        if (len >= 2 && len < sizeof line && !memchr(data + at, '\0', len)) {
            memcpy(line, data + at, len);
            line[len] = '\0';
            char *arg = line + 2, *second = NULL;
            const char *leaf;
            int parent = -1;
            if (line[0] == 't') {
                fz_expand_root(name, sizeof name, arg, root);   /* spaces and all */
            } else {
                second = strchr(arg, ' ');
                if (second)
                    *second++ = '\0';
                parent = fz_parent(dirfd, arg, &leaf);
            }
            if (parent >= 0) {
                if (line[0] == 'd') {
                    mkdirat(parent, leaf, 0700);
                } else if (line[0] == 'p') {
                    mkfifoat(parent, leaf, 0600);
                } else if (line[0] == 'l' && second) {
                    char target[400];
                    fz_expand_root(target, sizeof target, second, root);
                    symlinkat(target, parent, leaf);
                } else if (line[0] == 'f') {
                    int fd = openat(parent, leaf, O_WRONLY | O_CREAT | O_EXCL | O_NOFOLLOW, 0600);
                    if (fd >= 0) {
                        close(fd);
                        char full[700];
                        snprintf(full, sizeof full, "%s/%s", scene, arg);
                        fz_png_at(full, 0, 200);
                    }
                }
                close(parent);
            }
        }
        at += len + 1;
    }
    const char *err = NULL;
    fz_files inside;
    inside.count = 0;
    if (dirfd >= 0)
        fz_collect(dirfd, &inside, 0);
    /* the opener, by openat2 and by the walk: nothing outside, the same
     * file both ways */
    mote__io_file_id got[2];
    mote_result r[2];
    for (int walk = 0; walk < 2 && !err; walk++) {
        mote__io_file file;
        char msg[256];
        mote__io_resolve_by_walk(walk);
        r[walk] = mote__io_open_in_folder(scene, name, false, &file, msg, sizeof msg);
        mote__io_resolve_by_walk(0);
        memset(&got[walk], 0, sizeof got[walk]);
        if (r[walk] == MOTE_OK) {
            got[walk] = file.id;
            mote__io_close(&file);
            if (!fz_inside(&inside, got[walk]))
                err = "folder: a file outside the scene's folder was opened";
        } else {
            err = fz_check_message(msg, sizeof msg);
        }
    }
    if (!err && (r[0] == MOTE_OK) != (r[1] == MOTE_OK))
        err = "folder: openat2 and the walk disagree on whether the name opens";
    else if (!err && r[0] == MOTE_OK && !mote__io_same_file(got[0], got[1]))
        err = "folder: openat2 and the walk opened different files";
    /* the scene: a texture loaded is never the red one outside */
    if (!err) {
        char json[2600], quoted[2400], *o = quoted;
        for (const char *c = name; *c; c++) {
            if (*c == '"' || *c == '\\' || (unsigned char)*c < 0x20)
                o += sprintf(o, "\\u%04x", (unsigned char)*c);
            else
                *o++ = *c;
        }
        *o = '\0';
        snprintf(json, sizeof json, "{\"materials\":[{\"id\":\"m\",\"diffuseTexture\":{\"name\":"
                 "\"%s\"}}]}", quoted);
        mote_scene sc;
        char msg[256];
        if (mote_scene_load_memory(json, strlen(json), "f", scene, NULL, &sc, msg, sizeof msg) ==
            MOTE_OK) {
            if (sc.texture_count > 0 && ((const uint8_t *)sc.textures[0].pixels)[0] == 200)
                err = "folder: the texture outside the scene's folder was loaded";
            mote_scene_free(&sc);
        }
    }
    if (dirfd >= 0)
        close(dirfd);
    int rootfd = open("/tmp", O_RDONLY | O_DIRECTORY);
    if (rootfd >= 0) {
        fz_remove_at(rootfd, root + 5);
        close(rootfd);
    }
    return err;
}

#endif /* MOTE_FUZZ_NO_SCENE */
