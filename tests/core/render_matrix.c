/*
 * render_matrix.c - one hash per rendering configuration, so that a change
 * meant to move code and not pixels can be checked to move none.
 *
 * Each line is a configuration (device mode, colour and depth format,
 * scene, mode, filter, perspective, texture format and wrap) and the FNV-1a
 * hashes of the colour buffer, the depth buffer and the frame's statistics
 * after two frames (the second clears what the first drew). The program
 * uses the core alone; tests/core/core.mk builds it against the core
 * compiled at -O3, -O2, -Os and as the firmware profile, and `make
 * render-matrix RENDER_MATRIX_REF=file` compares the lines with a saved
 * run. A feature a build leaves out prints the result code instead.
 */
#include <mote/mote.h>
#include "support/scenes.h"

#include <stdio.h>
#include <string.h>

#define W 96
#define H 72
#define BAND 7

static uint8_t color[W * H * 4];
static uint32_t depth[W * H];
static uint64_t arena[1 << 15];   /* 256 KB, 8-byte aligned */

/* ---- textures in every texel format --------------------------------------- */

static uint16_t tex565[64 * 64];
static uint8_t texgrey[64 * 64];
static mote_texture textures[5];
enum { TEX_RGBA, TEX_565, TEX_GREY, TEX_NPOT, TEX_STRIDE, TEX_KINDS };
static const char *const tex_names[TEX_KINDS] = {"rgba", "rgb565", "grey", "npot", "stride"};

static void make_textures(void)
{
    const mote_texture *rgba = tu_scene_texture();
    const uint8_t *px = (const uint8_t *)rgba->pixels;
    for (int y = 0; y < 64; y++) {
        mote_convert_row(px + y * 256, MOTE_FORMAT_RGBA8888, tex565 + y * 64, MOTE_FORMAT_RGB565, 64);
        mote_convert_row(px + y * 256, MOTE_FORMAT_RGBA8888, texgrey + y * 64, MOTE_FORMAT_GREY8, 64);
    }
    textures[TEX_RGBA] = *rgba;
    textures[TEX_565] = (mote_texture){64, 64, MOTE_FORMAT_RGB565, 0, tex565};
    textures[TEX_GREY] = (mote_texture){64, 64, MOTE_FORMAT_GREY8, 0, texgrey};
    /* not a power of two, and a power of two with a wider stride */
    textures[TEX_NPOT] = (mote_texture){48, 40, MOTE_FORMAT_RGBA8888, 256, px};
    textures[TEX_STRIDE] = (mote_texture){32, 64, MOTE_FORMAT_RGBA8888, 256, px + 16};
}

/* ---- scenes ------------------------------------------------------------- */

/* SC_ALPHA, past the scenes every mode draws: the textured scene with a
 * cut-out and a blended mesh (the alpha/ configurations) */
enum { SC_TEXTURED, SC_GOURAUD, SC_DEPTH, SC_COLORS, SC_LIGHTS, SC_ORTHO, SC_COUNT, SC_ALPHA = SC_COUNT, SC_LOOK,
       SC_MIP };
static const char *const scene_names[SC_COUNT] = {"textured", "gouraud", "depth", "colors", "lights", "ortho"};

/* The Gouraud spheres under every light type, with ranges, a spot cone
 * and an emissive colour. */
static void lights_scene(tu_scene *s)
{
    tu_scene_build(TU_SCENE_GOURAUD, MOTE_WRAP_REPEAT, s);
    mote_frame_desc *f = &s->frame;
    f->light_count = 4;
    f->lights[0].range = 7.0f;
    f->lights[2] = (mote_light){.type = MOTE_LIGHT_HEMISPHERIC, .direction = {0, 1, 0.2f},
                                .color = {0.3f, 0.35f, 0.5f}, .ground_color = {0.2f, 0.1f, 0.05f}};
    f->lights[3] = (mote_light){.type = MOTE_LIGHT_SPOT, .position = {-1, 3, -3}, .direction = {0.3f, -1, 0.8f},
                                .color = {1, 0.5f, 0.2f}, .intensity = 1.5f, .range = 9.0f,
                                .spot_angle = 0.9f, .spot_exponent = 2.0f};
    s->meshes[1].material.emissive = (mote_rgba){30, 10, 0, 255};
}

/* The textured scene's texture with an alpha ramp, for the alpha scene. */
static uint8_t texalpha_px[64 * 64 * 4];
static mote_texture texalpha;

static void alpha_scene(tu_scene *s)
{
    tu_scene_build(TU_SCENE_TEXTURED, MOTE_WRAP_REPEAT, s);
    const uint8_t *px = (const uint8_t *)tu_scene_texture()->pixels;
    for (int i = 0; i < 64 * 64; i++) {
        memcpy(&texalpha_px[4 * i], &px[4 * i], 3);
        texalpha_px[4 * i + 3] = (uint8_t)((i % 64) * 4 + (i / 64) % 3);
    }
    texalpha = (mote_texture){64, 64, MOTE_FORMAT_RGBA8888, 0, texalpha_px};
    s->meshes[0].material.alpha_mode = MOTE_ALPHA_TEST;
    s->meshes[1].material.alpha_mode = MOTE_ALPHA_TEST_AND_BLEND;
    s->meshes[1].material.alpha = 0.6f;
    s->meshes[1].material.alpha_set = true;
    s->meshes[1].material.use_texture_alpha = true;
}

/* The textured scene with highlights and fog (SC_LOOK), or with its
 * texture's mip chain (SC_MIP, the mip/ configurations). */
static uint8_t mip_memory[64 * 64 * 4];
static mote_mipmaps mips;

static void look_scene(tu_scene *s, bool mip)
{
    tu_scene_build(TU_SCENE_TEXTURED, MOTE_WRAP_REPEAT, s);
    for (int i = 0; i < s->mesh_count; i++) {
        if (mip) {
            mote_mipmaps_build(s->meshes[i].material.texture, mip_memory, sizeof mip_memory, &mips);
            s->meshes[i].material.mipmaps = &mips;
            continue;
        }
        s->meshes[i].material.specular = (mote_rgba){255, 230, 200, 255};
        s->meshes[i].material.specular_power = 20.0f;
    }
    if (!mip)
        s->frame.fog = (mote_fog){MOTE_FOG_EXP2, {0.5f, 0.6f, 0.7f}, 0.08f, 0, 0};
}

static void build_scene(int which, mote_wrap wrap, int texkind, tu_scene *s)
{
    switch (which) {
    case SC_ALPHA: alpha_scene(s); break;
    case SC_LOOK: look_scene(s, false); break;
    case SC_MIP: look_scene(s, true); break;
    case SC_GOURAUD: tu_scene_build(TU_SCENE_GOURAUD, wrap, s); break;
    case SC_DEPTH: tu_scene_build(TU_SCENE_DEPTH, wrap, s); break;
    case SC_COLORS: tu_scene_build(TU_SCENE_COLORS, wrap, s); break;
    case SC_LIGHTS: lights_scene(s); break;
    case SC_ORTHO:
        tu_scene_build(TU_SCENE_TEXTURED, wrap, s);
        s->frame.camera.projection = MOTE_PROJECTION_ORTHOGRAPHIC;
        s->frame.camera.ortho[0] = -5;
        s->frame.camera.ortho[1] = 5;
        s->frame.camera.ortho[2] = -3;
        s->frame.camera.ortho[3] = 4;
        s->frame.camera.znear = -2;
        break;
    default: tu_scene_build(TU_SCENE_TEXTURED, wrap, s); break;
    }
    for (int i = 0; i < s->mesh_count; i++) {
        if (s->meshes[i].material.texture)
            s->meshes[i].material.texture = which == SC_ALPHA ? &texalpha
                                          : which >= SC_LOOK ? s->meshes[i].material.texture : &textures[texkind];
        mote_mesh_update_bounds(&s->meshes[i]);
    }
}

/* ---- devices --------------------------------------------------------------- */

enum { DEV_DIRECT, DEV_SUB4, DEV_BAND, DEV_BIN, DEV_BIN_PAR, DEV_BIN_SMALL, DEV_BIN_SMALL_PAR, DEV_BIN_CLEAR,
       DEV_HOOK, DEV_COUNT };
static const char *const dev_names[DEV_COUNT] = {"direct", "sub4", "band", "bin", "bin-par", "bin-small",
                                                 "bin-small-par", "bin-clear", "bin-hook"};

/* A parallel_for that runs the tasks on this thread, last first: the
 * groups must not depend on their order. */
static void backwards_for(void *user, int count, mote_task_fn fn, void *arg)
{
    (void)user;
    for (int i = count - 1; i >= 0; i--)
        fn(arg, i);
}

static uint64_t hooked;

static void hook(void *user, const int32_t x[3], const int32_t y[3], const float z[3], const float w[3])
{
    (void)user;
    (void)z;
    (void)w;
    hooked = hooked * 31u + (uint64_t)(uint32_t)(x[0] ^ y[1] ^ x[2]);
}

static uint64_t fnv(uint64_t h, const void *p, size_t n)
{
    const uint8_t *b = (const uint8_t *)p;
    for (size_t i = 0; i < n; i++)
        h = (h ^ b[i]) * 1099511628211u;
    return h;
}

static const mote_format formats[] = {MOTE_FORMAT_RGBA8888, MOTE_FORMAT_RGB565, MOTE_FORMAT_RGB565_SWAPPED,
                                      MOTE_FORMAT_GREY8};
static const char *const format_names[] = {"rgba8888", "rgb565", "rgb565s", "grey8"};
static const mote_depth_format depths[] = {MOTE_DEPTH_FORMAT_32, MOTE_DEPTH_FORMAT_16, MOTE_DEPTH_FORMAT_NONE};
static const char *const depth_names[] = {"d32", "d16", "none"};

static uint64_t band_hash;

static void flush(void *user, int y0, int rows, const void *c, int stride)
{
    (void)user;
    band_hash = fnv(band_hash, &y0, sizeof y0);
    band_hash = fnv(band_hash, c, (size_t)rows * (size_t)stride);
}

typedef struct draw_config {
    const char *name;
    int scene;
    mote_draw_desc desc;
    int tex;
    mote_wrap wrap;
} draw_config;

static int init_device(mote_device *dev, int devmode, mote_format f, mote_depth_format d)
{
    mote_device_desc desc = {.width = W, .height = H, .color_format = f, .color = color, .depth_format = d,
                             .depth = d == MOTE_DEPTH_FORMAT_NONE ? NULL : depth,
                             .clear_color = {20, 30, 40, 200}, .tile_size = 16};
    switch (devmode) {
    case DEV_SUB4: desc.subpixel_bits = 4; break;
    case DEV_BAND:
        desc.band_height = BAND;
        desc.flush = flush;
        break;
    case DEV_BIN_SMALL:
    case DEV_BIN_SMALL_PAR:
        /* room for the tile table and a little more than binning's minimum:
         * the arena fills up, and the groups' slices overflow */
        desc.arena_size = 6 * 5 * 8 + 64 * mote_arena_bytes_per_triangle() + 4096 + 8192;
        desc.arena = arena;
        desc.parallel_for = devmode == DEV_BIN_SMALL_PAR ? backwards_for : NULL;
        break;
    case DEV_BIN:
    case DEV_BIN_PAR:
    case DEV_BIN_CLEAR:
    case DEV_HOOK:
        desc.arena = arena;
        desc.arena_size = sizeof arena;
        desc.parallel_for = devmode == DEV_BIN ? NULL : backwards_for;
        desc.clear_drawn_tiles_only = devmode == DEV_BIN_CLEAR;
        desc.triangle_hook = devmode == DEV_HOOK ? hook : NULL;
        break;
    default: break;
    }
    return (int)mote_device_init(dev, &desc);
}

static void run(const char *variant, const draw_config *dc, int devmode, int fi, int di)
{
    static mote_device dev;
    static tu_scene scene;
    memset(color, 0xa5, sizeof color);
    memset(depth, 0x5a, sizeof depth);
    printf("%s %s %s %s %s", variant, dev_names[devmode], format_names[fi], depth_names[di], dc->name);
    int r = init_device(&dev, devmode, formats[fi], depths[di]);
    if (r != MOTE_OK) {
        printf(" init=%s\n", mote_result_string((mote_result)r));
        return;
    }
    build_scene(dc->scene, dc->wrap, dc->tex, &scene);
    band_hash = 14695981039346656037u;
    hooked = 0;
    int result = MOTE_OK;
    for (int frame = 0; frame < 2; frame++) {
        if ((r = mote_begin(&dev, &scene.frame)) != MOTE_OK) {
            printf(" begin=%s\n", mote_result_string((mote_result)r));
            return;
        }
        for (int i = 0; i < scene.mesh_count; i++)
            if ((r = mote_draw(&dev, &scene.meshes[i], &dc->desc)) != MOTE_OK)
                result = r;
        if ((r = mote_end(&dev)) != MOTE_OK)
            result = r;
    }
    if (result != MOTE_OK) {
        printf(" draw=%s\n", mote_result_string((mote_result)result));
        return;
    }
    const mote_stats *st = mote_device_stats(&dev);
    uint64_t h0 = 14695981039346656037u;
    uint64_t hc = devmode == DEV_BAND ? band_hash : fnv(h0, color, sizeof color);
    uint64_t hd = fnv(h0, depth, sizeof depth);
    /* the counters that say what was drawn; the tile counters follow the device */
    const uint64_t counts[] = {st->draws, st->meshes_culled, st->triangles_in, st->triangles_invalid,
                               st->triangles_clipped_away, st->triangles_backface, st->triangles_degenerate,
                               st->triangles_drawn, st->triangles_black, st->tiles_empty, st->tiles_drawn,
                               st->tiles_clear_skipped, st->arena_flushes, st->pixels_tested,
                               st->pixels_written, hooked};
    printf(" color=%016llx depth=%016llx stats=%016llx\n", (unsigned long long)hc, (unsigned long long)hd,
           (unsigned long long)fnv(h0, counts, sizeof counts));
}

#define D(...) ((mote_draw_desc){__VA_ARGS__})

int main(int argc, char **argv)
{
    const char *variant = argc > 1 ? argv[1] : "core";
    make_textures();
    static draw_config configs[128];
    int n = 0;
    /* every mode on every scene */
    static const char *const mode_names[] = {"", "points", "wire", "flat", "gouraud", "textured"};
    static char names[128][64];
    for (int s = 0; s < SC_COUNT; s++)
        for (int m = MOTE_MODE_POINTS; m <= MOTE_MODE_TEXTURED; m++) {
            snprintf(names[n], sizeof names[n], "%s/%s", scene_names[s], mode_names[m]);
            configs[n] = (draw_config){names[n], s, D(.mode = (mote_mode)m), TEX_RGBA, MOTE_WRAP_REPEAT};
            n++;
        }
    /* textures: filter x perspective x texel format */
    static const char *const filter_names[] = {"", "nearest", "bilinear"};
    static const char *const persp_names[] = {"", "correct", "affine", "subspan"};
    for (int f = MOTE_FILTER_NEAREST; f <= MOTE_FILTER_BILINEAR; f++)
        for (int p = MOTE_PERSPECTIVE_CORRECT; p <= MOTE_PERSPECTIVE_SUBSPAN; p++)
            for (int t = 0; t < TEX_KINDS; t++) {
                snprintf(names[n], sizeof names[n], "tex/%s/%s/%s", filter_names[f], persp_names[p], tex_names[t]);
                configs[n] = (draw_config){names[n], SC_TEXTURED,
                                           D(.mode = MOTE_MODE_TEXTURED, .filter = (mote_filter)f,
                                             .perspective = (mote_perspective)p, .subspan_log2 = p == 3 ? 2 : 0),
                                           t, MOTE_WRAP_REPEAT};
                n++;
            }
    /* wraps, both filters */
    static const char *const wrap_names[] = {"", "repeat", "clamp", "mirror"};
    for (int w = MOTE_WRAP_CLAMP; w <= MOTE_WRAP_MIRROR; w++)
        for (int f = MOTE_FILTER_NEAREST; f <= MOTE_FILTER_BILINEAR; f++)
            for (int t = TEX_RGBA; t <= TEX_NPOT; t += TEX_NPOT) {
                snprintf(names[n], sizeof names[n], "wrap/%s/%s/%s", wrap_names[w], filter_names[f], tex_names[t]);
                configs[n] = (draw_config){names[n], SC_TEXTURED, D(.mode = MOTE_MODE_TEXTURED, .filter = (mote_filter)f),
                                           t, (mote_wrap)w};
                n++;
            }
    /* unlit, culling, winding and depth switches */
    const struct { const char *name; int scene; mote_draw_desc d; } extra[] = {
        {"unlit/textured", SC_TEXTURED, D(.mode = MOTE_MODE_TEXTURED, .unlit = true)},
        {"unlit/colors-flat", SC_COLORS, D(.mode = MOTE_MODE_FLAT, .unlit = true)},
        {"unlit/colors-gouraud", SC_COLORS, D(.mode = MOTE_MODE_GOURAUD, .unlit = true)},
        {"cull-none/gouraud", SC_GOURAUD, D(.mode = MOTE_MODE_GOURAUD, .cull = MOTE_CULL_NONE)},
        {"cull-front/textured", SC_TEXTURED, D(.mode = MOTE_MODE_TEXTURED, .cull = MOTE_CULL_FRONT)},
        {"front-cw/wire", SC_GOURAUD, D(.mode = MOTE_MODE_WIREFRAME, .front_face = MOTE_FRONT_CW)},
        {"no-depth-test/depth", SC_DEPTH, D(.mode = MOTE_MODE_GOURAUD, .no_depth_test = true)},
        {"no-depth-write/depth", SC_DEPTH, D(.mode = MOTE_MODE_GOURAUD, .no_depth_write = true)},
        {"points-color/lights", SC_LIGHTS, D(.mode = MOTE_MODE_POINTS, .point_color = {200, 100, 50, 255})},
        {"flat-affine/lights", SC_LIGHTS, D(.mode = MOTE_MODE_FLAT, .perspective = MOTE_PERSPECTIVE_AFFINE)},
        {"alpha/nearest", SC_ALPHA, D(.mode = MOTE_MODE_TEXTURED)},
        {"alpha/bilinear", SC_ALPHA, D(.mode = MOTE_MODE_TEXTURED, .filter = MOTE_FILTER_BILINEAR)},
        {"alpha/gouraud", SC_ALPHA, D(.mode = MOTE_MODE_GOURAUD)},
        {"look/textured", SC_LOOK, D(.mode = MOTE_MODE_TEXTURED)},
        {"look/gouraud", SC_LOOK, D(.mode = MOTE_MODE_GOURAUD)},
        {"look/flat", SC_LOOK, D(.mode = MOTE_MODE_FLAT)},
        {"mip/triangle", SC_MIP, D(.mode = MOTE_MODE_TEXTURED, .mip = MOTE_MIP_TRIANGLE)},
        {"mip/pixel", SC_MIP, D(.mode = MOTE_MODE_TEXTURED, .mip = MOTE_MIP_PIXEL)},
        {"mip/pixel-bilinear", SC_MIP, D(.mode = MOTE_MODE_TEXTURED, .mip = MOTE_MIP_PIXEL,
                                         .filter = MOTE_FILTER_BILINEAR)},
    };
    for (size_t i = 0; i < sizeof extra / sizeof extra[0]; i++)
        configs[n++] = (draw_config){extra[i].name, extra[i].scene, extra[i].d, TEX_RGBA, MOTE_WRAP_REPEAT};

    for (int devmode = 0; devmode < DEV_COUNT; devmode++)
        for (int fi = 0; fi < 4; fi++)
            for (int di = 0; di < 3; di++)
                for (int i = 0; i < n; i++)
                    run(variant, &configs[i], devmode, fi, di);
    return 0;
}
