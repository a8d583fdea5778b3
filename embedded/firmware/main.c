/*
 * main.c - the mote firmware example: renders a baked scene (a header made
 * by mote-bake, no files, no JSON, no heap) at its baked size with a
 * 16-bit depth buffer, FW_BAND rows at a time (at least the height: the
 * whole frame at once), and prints the FNV-1a hash of the frame. The same
 * source built for the host gives the reference hash that
 * embedded/test-embedded.sh and embedded/bench-embedded.sh compare with.
 *
 * FW_LCD 0: RGB565, the frame only hashed. FW_LCD 1: RGB565_SWAPPED, the
 * byte order of SPI LCDs, each band sent to an ST7789 through lcd.c from
 * two band buffers: the DMA sends one while mote draws the next into the
 * other (desc.color_back, desc.flush_wait). On the emulated boards and the
 * host the panel is lcd_fake.c, which takes a DMA's bytes only when it is
 * waited for, and the image it received must hash as the frame does.
 *
 * FW_BINS 1 (the default): band bins, two bytes a triangle
 * (mote_band_bins_bytes), so that each band sets up only the triangles
 * that touch it; 0: every band replays the frame.
 *
 * RAM for the library is static and sized for the band: fw_color (and
 * fw_color_back), fw_depth (mote_band_bytes(W, rows, format, DEPTH16)),
 * fw_bins and fw_device; bench-embedded reads their sizes from the ELF's
 * symbols.
 *
 * Counted per frame (fw_count_start to fw_count_stop): mote_begin, the
 * draws and mote_end, less the flush callback, which stands for the
 * display.
 */
#include <mote/mote.h>

#include "lcd.h"
#include "lcd_fake.h"
#include "platform.h"
#include "scene.h"

#ifndef FW_BAND
#define FW_BAND 30
#endif
#ifndef FW_LCD
#define FW_LCD 0
#endif
#ifndef FW_BINS
#define FW_BINS 1
#endif

#define W SCENE_WIDTH
#define H SCENE_HEIGHT
#define ROWS (FW_BAND < H ? FW_BAND : H)
#define FORMAT (FW_LCD ? MOTE_FORMAT_RGB565_SWAPPED : MOTE_FORMAT_RGB565)

static uint16_t fw_color[W * ROWS];
static uint16_t fw_depth[W * ROWS];
static mote_device fw_device;
#if FW_BINS && ROWS < H
static uint16_t fw_bins[SCENE_TRIANGLE_COUNT];   /* 2 bytes a triangle */
#endif
#if FW_LCD
static uint16_t fw_color_back[W * ROWS];
static lcd fw_lcd;
static const void *fw_sending;    /* the buffer the DMA reads, until waited for */
#endif

/* What the flush callback saw: the hash so far and the next row expected. */
typedef struct frame_check {
    uint32_t hash;
    int next_row;
    bool out_of_order;
} frame_check;

/* Rows of the frame, done: hashed, and sent to the LCD. */
static void take_rows(frame_check *fc, int y0, int rows, const void *color, int stride)
{
    if (y0 != fc->next_row || stride != W * 2)
        fc->out_of_order = true;
    fc->hash = fw_fnv1a(fc->hash, color, (size_t)rows * W * 2);
    fc->next_row = y0 + rows;
#if FW_LCD
    /* started, not waited for: mote draws the next band into the other
     * buffer meanwhile, and waits (wait_rows) before it reuses this one */
    lcd_start_rows(&fw_lcd, y0, rows, color);
    fw_sending = color;
#endif
}

#if FW_LCD
static void wait_rows(void *user, const void *color)
{
    (void)user;
    fw_count_stop();
    if (color == fw_sending) {
        lcd_wait(&fw_lcd);
        fw_sending = NULL;
    }
    fw_count_start();
}
#endif

static void flush(void *user, int y0, int rows, const void *color, int stride)
{
    fw_count_stop();
    take_rows(user, y0, rows, color, stride);
    fw_count_start();
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

static void render(void)
{
    mote_result r;
    if ((r = mote_begin(&fw_device, &scene_frame)) != MOTE_OK)
        fail("mote_begin", r);
    /* the baked header's draw options and order, as mote_scene_draw */
    if ((r = scene_draw(&fw_device)) != MOTE_OK)
        fail("mote_draw", r);
    if ((r = mote_end(&fw_device)) != MOTE_OK)
        fail("mote_end", r);
}

int main(void)
{
    fw_stack_paint();
    frame_check fc = {FW_FNV1A_START, 0, false};
    mote_device_desc desc = {0};
    desc.width = W;
    desc.height = H;
    desc.color_format = FORMAT;
    desc.color = fw_color;
    desc.depth_format = MOTE_DEPTH_FORMAT_16;
    desc.depth = fw_depth;
    desc.band_height = ROWS;
    desc.clear_color = scene_clear_color;
    if (ROWS < H) {
        desc.flush = flush;
        desc.flush_user = &fc;
#if FW_BINS && ROWS < H
        desc.band_bins = fw_bins;
        desc.band_bins_size = sizeof fw_bins;
#endif
#if FW_LCD
        desc.color_back = fw_color_back;
        desc.flush_wait = wait_rows;
#endif
    }
    mote_result r = mote_device_init(&fw_device, &desc);
    if (r != MOTE_OK)
        fail("mote_device_init", r);
#if FW_LCD
    lcd_init(&fw_lcd, LCD_ST7789, W, H);
#endif

    fw_count_start();
    render();
    fw_count_stop();
    if (ROWS == H)
        take_rows(&fc, 0, H, fw_color, W * 2);
#if FW_LCD
    lcd_wait(&fw_lcd);            /* the last band's transfer */
#endif

    if (fc.out_of_order || fc.next_row != H) {
        fw_puts("mote-firmware: the bands did not cover the frame in order\n");
        fw_exit(1);
    }
    fw_put_uint("mote-firmware: ", W, 10);
    fw_put_uint("x", H, 10);
    fw_puts(FW_LCD ? " RGB565_SWAPPED" : " RGB565");
    fw_put_uint(" depth16, bands of ", ROWS, 10);
    fw_put_uint(" rows, triangles drawn ", mote_device_stats(&fw_device)->triangles_drawn, 10);
    fw_put_uint(", pixels written ", (uint32_t)mote_device_stats(&fw_device)->pixels_written, 10);
    fw_puts("\n");
    size_t buffers = mote_band_bytes(W, ROWS, FORMAT, MOTE_DEPTH_FORMAT_16);
#if FW_LCD
    buffers += sizeof fw_color_back;
#endif
    size_t bins = 0;
#if FW_BINS && ROWS < H
    bins = sizeof fw_bins;
#endif
    fw_put_uint("mote-firmware: RAM for mote: band buffers ", (uint32_t)buffers, 10);
    fw_put_uint(" + band bins ", (uint32_t)bins, 10);
    fw_put_uint(" + device ", (uint32_t)sizeof fw_device, 10);
    fw_put_uint(" = ", (uint32_t)(buffers + bins + sizeof fw_device), 10);
    fw_puts(" bytes\n");
    if (fw_stack_used() > 0) {
        fw_put_uint("mote-firmware: stack used ", fw_stack_used(), 10);
        fw_puts(" bytes\n");
    }
#if FW_LCD
    uint32_t image_hash, value;
    const char *lcd_error = lcd_fake_finish(W, H, &image_hash, &value);
    if (lcd_error) {
        fw_puts("mote-firmware: LCD: ");
        fw_puts(lcd_error);
        fw_put_uint(" ", value, 16);
        fw_puts("\n");
        fw_exit(1);
    }
    fw_put_uint("mote-firmware: LCD image fnv1a ", image_hash, 16);
    fw_puts(image_hash == fc.hash ? ", the frame's\n" : ", not the frame's\n");
    if (image_hash != fc.hash)
        fw_exit(1);
#endif
    fw_put_uint("mote-firmware: frame fnv1a ", fc.hash, 16);
    fw_puts("\n");
    fw_exit(0);
    return 0;
}
