/*
 * testutil.c - see testutil.h.
 */
#include "support/testutil.h"

#include <math.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>

/* ---- PRNG ------------------------------------------------------------------ */

tu_rng tu_rng_seed(uint64_t seed)
{
    tu_rng r = {seed};
    return r;
}

uint64_t tu_rand_u64(tu_rng *r)
{
    uint64_t z = (r->s += 0x9e3779b97f4a7c15ull);
    z = (z ^ (z >> 30)) * 0xbf58476d1ce4e5b9ull;
    z = (z ^ (z >> 27)) * 0x94d049bb133111ebull;
    return z ^ (z >> 31);
}

double tu_rand01(tu_rng *r)
{
    return (double)(tu_rand_u64(r) >> 11) * (1.0 / 9007199254740992.0);
}

double tu_rand_range(tu_rng *r, double lo, double hi)
{
    return lo + (hi - lo) * tu_rand01(r);
}

int64_t tu_rand_int(tu_rng *r, int64_t lo, int64_t hi)
{
    uint64_t span = (uint64_t)(hi - lo) + 1u;
    return lo + (int64_t)(span ? tu_rand_u64(r) % span : tu_rand_u64(r));
}

/* ---- capture ------------------------------------------------------------------ */

void tu_capture_hook(void *user, const int32_t x[3], const int32_t y[3], const float z[3],
                     const float w[3])
{
    tu_capture *c = (tu_capture *)user;
    if (c->count == c->capacity) {
        size_t cap = c->capacity ? c->capacity * 2 : 64;
        tu_tri *t = (tu_tri *)realloc(c->tris, cap * sizeof *t);
        if (!t)
            return;   /* the test then sees fewer triangles and fails */
        c->tris = t;
        c->capacity = cap;
    }
    tu_tri *t = &c->tris[c->count++];
    for (int i = 0; i < 3; i++) {
        t->X[i] = x[i];
        t->Y[i] = y[i];
        t->z[i] = z[i];
        t->w[i] = w[i];
    }
}

void tu_capture_reset(tu_capture *c)
{
    c->count = 0;
}

void tu_capture_free(tu_capture *c)
{
    free(c->tris);
    memset(c, 0, sizeof *c);
}

/* ---- screen-space device -------------------------------------------------------- */

bool tu_screen_init(tu_screen *s, int width, int height, int subpixel_bits, bool with_depth)
{
    memset(s, 0, sizeof *s);
    s->width = width;
    s->height = height;
    s->subpixel_bits = subpixel_bits;
    s->color = (uint8_t *)calloc((size_t)width * (size_t)height, 1);
    if (with_depth)
        s->depth = (uint32_t *)calloc((size_t)width * (size_t)height, sizeof(uint32_t));
    if (!s->color || (with_depth && !s->depth)) {
        tu_screen_free(s);
        return false;
    }
    mote_device_desc d;
    memset(&d, 0, sizeof d);
    d.width = width;
    d.height = height;
    d.color_format = MOTE_FORMAT_GREY8;
    d.color = s->color;
    d.depth_format = with_depth ? MOTE_DEPTH_FORMAT_32 : MOTE_DEPTH_FORMAT_NONE;
    d.depth = s->depth;
    d.subpixel_bits = subpixel_bits;
    d.triangle_hook = tu_capture_hook;
    d.triangle_hook_user = &s->cap;
    if (mote_device_init(&s->dev, &d) != MOTE_OK) {
        tu_screen_free(s);
        return false;
    }
    mote_camera *cam = &s->frame.camera;
    cam->target[2] = 1.0f;
    cam->up[1] = 1.0f;
    cam->fov = 1.0f;
    cam->znear = 0.01f;
    cam->zfar = 1000.0f;
    mote_camera_projection_matrix(cam, (float)width / (float)height, s->proj);
    return true;
}

void tu_screen_free(tu_screen *s)
{
    free(s->color);
    free(s->depth);
    tu_capture_free(&s->cap);
    memset(s, 0, sizeof *s);
}

void tu_screen_vertex(const tu_screen *s, double sx, double sy, double w, float out[3])
{
    /* sx = (x_ndc + 1) W / 2, sy = (1 - y_ndc) H / 2, x_ndc = proj[0] x / w */
    double nx = 2.0 * sx / s->width - 1.0, ny = 1.0 - 2.0 * sy / s->height;
    out[0] = (float)(nx * w / (double)s->proj[0]);
    out[1] = (float)(ny * w / (double)s->proj[5]);
    out[2] = (float)w;
}

double tu_grid(const tu_screen *s, int64_t fixed)
{
    return (double)fixed / (double)(1 << s->subpixel_bits);
}

static mote_vertex *scratch_v;
static uint32_t *scratch_i;
static int scratch_n;

mote_result tu_screen_draw(tu_screen *s, const double *sx, const double *sy, const double *w, int n)
{
    if (n > scratch_n) {
        free(scratch_v);
        free(scratch_i);
        scratch_v = (mote_vertex *)calloc((size_t)n * 3, sizeof *scratch_v);
        scratch_i = (uint32_t *)calloc((size_t)n * 3, sizeof *scratch_i);
        scratch_n = (scratch_v && scratch_i) ? n : 0;
        if (!scratch_n)
            return MOTE_ERR_OUT_OF_MEMORY;
    }
    for (int i = 0; i < 3 * n; i++) {
        memset(&scratch_v[i], 0, sizeof scratch_v[i]);
        tu_screen_vertex(s, sx[i], sy[i], w ? w[i] : 1.0, scratch_v[i].position);
        scratch_i[i] = (uint32_t)i;
    }
    mote_mesh m;
    memset(&m, 0, sizeof m);
    m.vertices = scratch_v;
    m.vertex_count = (uint32_t)(3 * n);
    m.indices = scratch_i;
    m.index_count = (uint32_t)(3 * n);
    return tu_screen_draw_mesh(s, &m, NULL);
}

mote_result tu_screen_draw_mesh(tu_screen *s, const mote_mesh *mesh, const mote_draw_desc *d)
{
    mote_draw_desc dd;
    memset(&dd, 0, sizeof dd);
    dd.mode = MOTE_MODE_FLAT;
    dd.unlit = true;
    dd.cull = MOTE_CULL_NONE;
    tu_capture_reset(&s->cap);
    mote_result r = mote_begin(&s->dev, &s->frame);
    if (r != MOTE_OK)
        return r;
    mote_result rd = mote_draw(&s->dev, mesh, d ? d : &dd);
    r = mote_end(&s->dev);
    return rd != MOTE_OK ? rd : r;
}

void tu_screen_coverage(const tu_screen *s, uint8_t *out)
{
    size_t n = (size_t)s->width * (size_t)s->height;
    for (size_t i = 0; i < n; i++)
        out[i] = s->color[i] != 0;
}

/* ---- guarded buffers -------------------------------------------------------------- */

#define TU_GUARD 64
#define TU_CANARY 0xA5

void *tu_guard_alloc(size_t size)
{
    uint8_t *p = (uint8_t *)malloc(size + 2 * TU_GUARD);
    if (!p)
        return NULL;
    memset(p, TU_CANARY, TU_GUARD);
    memset(p + TU_GUARD, 0, size);
    memset(p + TU_GUARD + size, TU_CANARY, TU_GUARD);
    return p + TU_GUARD;
}

bool tu_guard_ok(const void *q, size_t size)
{
    const uint8_t *p = (const uint8_t *)q - TU_GUARD;
    for (size_t i = 0; i < TU_GUARD; i++)
        if (p[i] != TU_CANARY || p[TU_GUARD + size + i] != TU_CANARY)
            return false;
    return true;
}

void tu_guard_free(void *q)
{
    if (q)
        free((uint8_t *)q - TU_GUARD);
}

/* ---- images ------------------------------------------------------------------------ */

void tu_read_rgba(const mote_device *dev, uint8_t *rgba)
{
    for (int y = 0; y < dev->desc.height; y++)
        for (int x = 0; x < dev->desc.width; x++) {
            mote_rgba c = mote_read_pixel(dev, x, y);
            uint8_t *o = &rgba[4 * ((size_t)y * (size_t)dev->desc.width + (size_t)x)];
            o[0] = c.r;
            o[1] = c.g;
            o[2] = c.b;
            o[3] = c.a;
        }
}

void tu_write_ppm(const char *path, const uint8_t *rgba, int width, int height)
{
    FILE *f = fopen(path, "wb");
    if (!f)
        return;
    fprintf(f, "P6\n%d %d\n255\n", width, height);
    for (long i = 0; i < (long)width * height; i++)
        fwrite(&rgba[4 * i], 1, 3, f);
    fclose(f);
}

/* ---- mote against the reference ---------------------------------------------------- */

static bool render_mote(const tu_vs_opts *o, const mote_frame_desc *frame, const mote_mesh *meshes, int n,
                        const mote_draw_desc *draws, bool one_desc, mote_rgba clear, uint8_t *rgba)
{
    size_t px = (size_t)o->width * (size_t)o->height;
    uint8_t *color = (uint8_t *)malloc(px * 4);
    uint32_t *depth = (uint32_t *)malloc(px * 4);
    bool ok = color && depth;
    if (ok) {
        mote_device dev;
        mote_device_desc d;
        memset(&d, 0, sizeof d);
        d.width = o->width;
        d.height = o->height;
        d.color = color;
        d.depth = depth;
        d.depth_format = o->depth;
        d.subpixel_bits = o->subpixel_bits;
        d.clear_color = clear;
        ok = mote_device_init(&dev, &d) == MOTE_OK && mote_begin(&dev, frame) == MOTE_OK;
        for (int i = 0; ok && i < n; i++)
            ok = mote_draw(&dev, &meshes[i], draws ? &draws[one_desc ? 0 : i] : NULL) == MOTE_OK;
        ok = ok && mote_end(&dev) == MOTE_OK;
        if (ok)
            tu_read_rgba(&dev, rgba);
    }
    free(color);
    free(depth);
    return ok;
}

bool tu_vs_ref(const tu_vs_opts *o, const mote_frame_desc *frame, const mote_mesh *meshes, int n,
               const mote_draw_desc *draws, bool one_desc, tu_vs_result *out, uint8_t *mote_image,
               uint8_t *ref_rgba)
{
    memset(out, 0, sizeof *out);
    int w = o->width, h = o->height;
    size_t px = (size_t)w * (size_t)h;
    uint8_t *black = (uint8_t *)malloc(px * 4), *white = (uint8_t *)malloc(px * 4);
    uint8_t *cov = (uint8_t *)malloc(px), *rcov = (uint8_t *)malloc(px);
    ref_target t;
    memset(&t, 0, sizeof t);
    bool ok = black && white && cov && rcov && ref_target_init(&t, w, h, o->subpixel_bits);
    mote_rgba k = {0, 0, 0, 255}, wh = {255, 255, 255, 255};
    ok = ok && render_mote(o, frame, meshes, n, draws, one_desc, k, black)
         && render_mote(o, frame, meshes, n, draws, one_desc, wh, white);
    if (ok) {
        for (size_t i = 0; i < px; i++)
            cov[i] = memcmp(&black[4 * i], &white[4 * i], 3) == 0;
        ref_begin(&t, frame, k);
        for (int i = 0; i < n; i++)
            ref_draw(&t, &meshes[i], draws ? &draws[one_desc ? 0 : i] : NULL);
        for (size_t i = 0; i < px; i++)
            rcov[i] = t.cov[i] != 0;
        out->m = ref_compare(black, cov, t.rgba, rcov, w, h);
        for (int y = 0; y < h; y++)
            for (int x = 0; x < w; x++) {
                size_t i = (size_t)y * (size_t)w + (size_t)x;
                if (cov[i] == rcov[i])
                    continue;
                bool edge = false;
                for (int dy = -1; dy <= 1; dy++)
                    for (int dx = -1; dx <= 1; dx++) {
                        int xx = x + dx, yy = y + dy;
                        if (xx >= 0 && yy >= 0 && xx < w && yy < h && rcov[(size_t)yy * (size_t)w + (size_t)xx] != rcov[i])
                            edge = true;
                    }
                out->unexplained += !edge;
            }
        if (mote_image)
            memcpy(mote_image, black, px * 4);
        if (ref_rgba)
            memcpy(ref_rgba, t.rgba, px * 4);
    }
    if (t.rgba)
        ref_target_free(&t);
    free(black);
    free(white);
    free(cov);
    free(rcov);
    return ok;
}
