/*
 * lcd_fake.c - lcd_platform.h as a panel in memory (lcd_fake.h). What it
 * holds the driver to: every command known and with its parameter count;
 * 5 ms of quiet after SWRESET and SLPOUT; RAMWR only after the panel is
 * awake, in 16-bit colour, displaying, inside a window that fits the
 * orientation MADCTL set, followed by exactly the window's pixels; pixels
 * only by DMA, never a byte on the bus while a DMA runs, and every DMA
 * waited for. The DMA's bytes are taken when it is waited for, so a
 * caller that changes the buffer before waiting sends changed pixels.
 */
#include "lcd_fake.h"

#include <stdbool.h>

#include "lcd_platform.h"
#include "platform.h"

#define PANEL_NATIVE_W 240
#define PANEL_NATIVE_H 320
#define MADCTL_MV 0x20u

static FW_OFF_CHIP uint8_t image[PANEL_NATIVE_W * PANEL_NATIVE_H * 2];

static struct {
    int dc;
    int cmd;                      /* the command being received, -1 none */
    uint8_t params[4];
    int nparams;
    unsigned quiet_ms;            /* still to wait before the next command */
    bool reset, awake, rgb565, on;
    uint8_t madctl;
    int x0, x1, y0, y1;           /* the window, as CASET and RASET set it */
    int x, y, half;               /* RAMWR's next pixel and byte */
    uint32_t window_pixels, window_written, pixels;
    const uint8_t *dma;
    size_t dma_n;
    bool dma_busy;
    const char *error;
    uint32_t error_value;
} panel = {.cmd = -1};

static void fail(const char *what, uint32_t value)
{
    if (!panel.error) {
        panel.error = what;
        panel.error_value = value;
    }
}

static int logical_w(void)
{
    return panel.madctl & MADCTL_MV ? PANEL_NATIVE_H : PANEL_NATIVE_W;
}

static int logical_h(void)
{
    return panel.madctl & MADCTL_MV ? PANEL_NATIVE_W : PANEL_NATIVE_H;
}

/* Parameters each command takes (-1: unknown to this panel). */
static int param_count(int cmd)
{
    switch (cmd) {
    case 0x01: case 0x11: case 0x13: case 0x21: case 0x29: case 0x2c: return 0;
    case 0x36: case 0x3a: return 1;
    case 0x2a: case 0x2b: return 4;
    default: return -1;
    }
}

/* The command's parameters are all in: act on it. */
static void complete(void)
{
    uint8_t *p = panel.params;
    switch (panel.cmd) {
    case 0x01: /* SWRESET */
        panel.reset = true;
        panel.awake = panel.rgb565 = panel.on = false;
        panel.madctl = 0;
        panel.quiet_ms = 5;
        break;
    case 0x11: /* SLPOUT */
        if (!panel.reset)
            fail("SLPOUT before SWRESET", 0x11);
        panel.awake = true;
        panel.quiet_ms = 5;
        break;
    case 0x29: /* DISPON */
        panel.on = true;
        break;
    case 0x3a: /* COLMOD */
        panel.rgb565 = p[0] == 0x55;
        if (!panel.rgb565)
            fail("COLMOD is not 16-bit colour (0x55)", p[0]);
        break;
    case 0x36: /* MADCTL */
        panel.madctl = p[0];
        break;
    case 0x2a: /* CASET */
        panel.x0 = p[0] << 8 | p[1];
        panel.x1 = p[2] << 8 | p[3];
        break;
    case 0x2b: /* RASET */
        panel.y0 = p[0] << 8 | p[1];
        panel.y1 = p[2] << 8 | p[3];
        break;
    case 0x2c: /* RAMWR */
        if (!panel.awake || !panel.rgb565 || !panel.on)
            fail("RAMWR before SLPOUT, COLMOD and DISPON", 0x2c);
        if (panel.x0 > panel.x1 || panel.y0 > panel.y1 || panel.x1 >= logical_w()
            || panel.y1 >= logical_h())
            fail("RAMWR window outside the panel as MADCTL turns it", (uint32_t)panel.y1);
        panel.x = panel.x0;
        panel.y = panel.y0;
        panel.half = 0;
        panel.window_pixels = (uint32_t)(panel.x1 - panel.x0 + 1) * (uint32_t)(panel.y1 - panel.y0 + 1);
        panel.window_written = 0;
        break;
    default:
        break;
    }
}

/* A command byte ends the one before it. */
static void end_command(void)
{
    if (panel.cmd == 0x2c && panel.window_written != panel.window_pixels)
        fail("RAMWR's pixels do not fill its window: pixels sent", panel.window_written);
    else if (panel.cmd >= 0 && panel.cmd != 0x2c && panel.nparams != param_count(panel.cmd))
        fail("a command with too few parameters", (uint32_t)panel.cmd);
    panel.cmd = -1;
}

static void pixel_byte(uint8_t b)
{
    if (panel.window_written >= panel.window_pixels) {
        fail("more pixels than RAMWR's window holds", panel.window_pixels);
        return;
    }
    image[((size_t)panel.y * (size_t)logical_w() + (size_t)panel.x) * 2 + (size_t)panel.half] = b;
    if (++panel.half < 2)
        return;
    panel.half = 0;
    panel.window_written++;
    panel.pixels++;
    if (++panel.x > panel.x1) {
        panel.x = panel.x0;
        panel.y++;
    }
}

static void receive(uint8_t b)
{
    if (!panel.dc) {
        end_command();
        if (panel.quiet_ms)
            fail("a command too soon after SWRESET or SLPOUT", b);
        if (param_count(b) < 0)
            fail("a command this panel does not know", b);
        panel.cmd = b;
        panel.nparams = 0;
        if (param_count(b) == 0)
            complete();
    } else if (panel.cmd == 0x2c) {
        pixel_byte(b);
    } else if (panel.cmd < 0 || panel.nparams >= param_count(panel.cmd)) {
        fail("a parameter byte no command takes", b);
    } else {
        panel.params[panel.nparams++] = b;
        if (panel.nparams == param_count(panel.cmd))
            complete();
    }
}

void lcd_spi_write(const uint8_t *data, size_t n)
{
    if (panel.dma_busy)
        fail("an SPI write while a DMA runs", (uint32_t)n);
    for (size_t i = 0; i < n; i++)
        receive(data[i]);
}

void lcd_dc(int data)
{
    if (panel.dma_busy)
        fail("D/C changed while a DMA runs", (uint32_t)data);
    panel.dc = data != 0;
}

void lcd_dma_start(const void *data, size_t n)
{
    if (panel.dma_busy)
        fail("a DMA started while one runs", (uint32_t)n);
    if (!panel.dc || panel.cmd != 0x2c)
        fail("a DMA that is not RAMWR's pixels", (uint32_t)n);
    panel.dma = data;
    panel.dma_n = n;
    panel.dma_busy = true;
}

void lcd_dma_wait(void)
{
    if (!panel.dma_busy)
        fail("a wait for no DMA", 0);
    panel.dma_busy = false;
    for (size_t i = 0; i < panel.dma_n; i++)
        receive(panel.dma[i]);
    panel.dma_n = 0;
}

void lcd_delay_ms(unsigned ms)
{
    panel.quiet_ms = ms >= panel.quiet_ms ? 0 : panel.quiet_ms - ms;
}

const char *lcd_fake_finish(int width, int height, uint32_t *image_hash, uint32_t *value)
{
    if (panel.dma_busy)
        fail("a DMA never waited for", (uint32_t)panel.dma_n);
    end_command();
    if (width != logical_w() || height != logical_h())
        fail("MADCTL's orientation is not the frame's: panel width", (uint32_t)logical_w());
    if (panel.pixels != (uint32_t)width * (uint32_t)height)
        fail("pixels sent, not the frame's", panel.pixels);
    *image_hash = fw_fnv1a(FW_FNV1A_START, image, (size_t)width * (size_t)height * 2);
    *value = panel.error_value;
    return panel.error;
}
