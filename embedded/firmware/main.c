/*
 * main.c - the mote firmware example: renders a baked scene (a header made
 * by mote-bake, no files, no JSON, no heap) at its baked size in RGB565 with
 * a 16-bit depth buffer, FW_BAND rows at a time, and prints the FNV-1a hash
 * of the assembled frame. The same source built for the host gives the
 * reference hash (embedded/test-embedded.sh compares them).
 *
 * RAM for the library: the two band buffers and the device, all static
 * (30 rows: 38400 + 800 bytes on a 32-bit target, MOTE_MAX_DRAWS=8):
 *   mote_band_bytes(W, FW_BAND, RGB565, DEPTH16) + sizeof(mote_device).
 */
#include <mote/mote.h>

#include "platform.h"
#include "scene.h"

#ifndef FW_BAND
#define FW_BAND 30
#endif

#define W SCENE_WIDTH
#define H SCENE_HEIGHT

static uint16_t band_color[W * FW_BAND];
static uint16_t band_depth[W * FW_BAND];
static mote_device dev;

/* What the flush callback saw: the hash so far and the next row expected. */
typedef struct frame_check {
    uint32_t hash;
    int next_row;
    bool out_of_order;
} frame_check;

/* A display driver would send the rows to the panel here; the example
 * hashes them (FNV-1a 32 over the frame's bytes, top row first). */
static void flush(void *user, int y0, int rows, const void *color, int stride)
{
    frame_check *fc = user;
    if (y0 != fc->next_row)
        fc->out_of_order = true;
    for (int y = 0; y < rows; y++) {
        const uint8_t *row = (const uint8_t *)color + y * stride;
        for (int i = 0; i < W * 2; i++)
            fc->hash = (fc->hash ^ row[i]) * 16777619u;
    }
    fc->next_row = y0 + rows;
}

static void put_uint(const char *label, uint32_t v, int base)
{
    char buf[16];
    int n = sizeof buf - 1;
    buf[n] = '\0';
    do {
        buf[--n] = "0123456789abcdef"[v % (uint32_t)base];
        v /= (uint32_t)base;
    } while ((v || (base == 16 && n > (int)sizeof buf - 9)) && n > 0); /* hex: 8 digits */
    fw_puts(label);
    if (base == 16)
        fw_puts("0x");
    fw_puts(buf + n);
}

static void fail(const char *what, mote_result r)
{
    fw_puts("mote-firmware: ");
    fw_puts(what);
    fw_puts(" failed: ");
    fw_puts(mote_result_string(r));
    fw_puts("\n");
    fw_exit(1);
}

int main(void)
{
    fw_stack_paint();
    frame_check fc = {2166136261u, 0, false};
    mote_device_desc desc = {0};
    desc.width = W;
    desc.height = H;
    desc.color_format = MOTE_FORMAT_RGB565;
    desc.color = band_color;
    desc.depth_format = MOTE_DEPTH_FORMAT_16;
    desc.depth = band_depth;
    desc.band_height = FW_BAND;
    desc.clear_color = scene_clear_color;
    desc.flush = flush;
    desc.flush_user = &fc;
    mote_result r = mote_device_init(&dev, &desc);
    if (r != MOTE_OK)
        fail("mote_device_init", r);
    if ((r = mote_begin(&dev, &scene_frame)) != MOTE_OK)
        fail("mote_begin", r);
    for (int i = 0; i < SCENE_MESH_COUNT; i++) {
        mote_draw_desc draw = {0};
        draw.cull = scene_two_sided[i] ? MOTE_CULL_NONE : MOTE_CULL_DEFAULT;
        draw.unlit = scene_unlit[i];
        if ((r = mote_draw(&dev, &scene_meshes[i], &draw)) != MOTE_OK)
            fail("mote_draw", r);
    }
    if ((r = mote_end(&dev)) != MOTE_OK)
        fail("mote_end", r);
    if (fc.out_of_order || fc.next_row != H) {
        fw_puts("mote-firmware: the bands did not cover the frame in order\n");
        fw_exit(1);
    }
    put_uint("mote-firmware: ", W, 10);
    put_uint("x", H, 10);
    put_uint(" RGB565 depth16, bands of ", FW_BAND, 10);
    put_uint(" rows, triangles drawn ", mote_device_stats(&dev)->triangles_drawn, 10);
    fw_puts("\n");
    put_uint("mote-firmware: RAM for mote: band buffers ",
             (uint32_t)mote_band_bytes(W, FW_BAND, MOTE_FORMAT_RGB565, MOTE_DEPTH_FORMAT_16), 10);
    put_uint(" + device ", (uint32_t)sizeof dev, 10);
    put_uint(" = ", (uint32_t)(mote_band_bytes(W, FW_BAND, MOTE_FORMAT_RGB565, MOTE_DEPTH_FORMAT_16)
                               + sizeof dev), 10);
    fw_puts(" bytes\n");
    if (fw_stack_used() > 0) {
        put_uint("mote-firmware: stack used ", fw_stack_used(), 10);
        fw_puts(" bytes\n");
    }
    put_uint("mote-firmware: frame fnv1a ", fc.hash, 16);
    fw_puts("\n");
    fw_exit(0);
    return 0;
}
