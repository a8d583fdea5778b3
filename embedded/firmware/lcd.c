/*
 * lcd.c - ST7789 and ILI9341 over SPI (lcd.h). Both controllers speak MIPI
 * DCS: the commands used here mean the same on both; only the start-up
 * details differ (the ST7789's panels are wired inverted, the ILI9341's
 * BGR).
 */
#include "lcd.h"

#include "lcd_platform.h"

enum {
    DCS_SWRESET = 0x01,
    DCS_SLPOUT = 0x11,
    DCS_NORON = 0x13,
    DCS_INVON = 0x21,
    DCS_DISPON = 0x29,
    DCS_CASET = 0x2a,
    DCS_RASET = 0x2b,
    DCS_RAMWR = 0x2c,
    DCS_MADCTL = 0x36,
    DCS_COLMOD = 0x3a,
};

/* MADCTL bits: row/column exchange (landscape), column order, BGR panel */
#define MADCTL_MV 0x20u
#define MADCTL_MX 0x40u
#define MADCTL_BGR 0x08u
/* COLMOD: 16 bits a pixel on the interface and in the panel */
#define COLMOD_RGB565 0x55u

static void command(uint8_t cmd, const uint8_t *params, size_t n)
{
    lcd_dc(0);
    lcd_spi_write(&cmd, 1);
    if (n) {
        lcd_dc(1);
        lcd_spi_write(params, n);
    }
}

/* CASET or RASET: first and last, high byte first */
static void set_range(uint8_t cmd, int first, int last)
{
    uint8_t p[4] = {(uint8_t)(first >> 8), (uint8_t)first, (uint8_t)(last >> 8), (uint8_t)last};
    command(cmd, p, sizeof p);
}

void lcd_init(lcd *panel, lcd_controller controller, int width, int height)
{
    panel->controller = controller;
    panel->width = width;
    panel->height = height;
    panel->busy = false;
    /* both datasheets: 5 ms after a reset before the next command, 120 ms
     * after leaving sleep before the display is turned on */
    command(DCS_SWRESET, NULL, 0);
    lcd_delay_ms(150);
    command(DCS_SLPOUT, NULL, 0);
    lcd_delay_ms(120);
    uint8_t colmod = COLMOD_RGB565;
    command(DCS_COLMOD, &colmod, 1);
    uint8_t madctl = width > height ? MADCTL_MV | MADCTL_MX : 0;
    if (controller == LCD_ILI9341)
        madctl |= MADCTL_BGR;
    command(DCS_MADCTL, &madctl, 1);
    if (controller == LCD_ST7789)
        command(DCS_INVON, NULL, 0);
    command(DCS_NORON, NULL, 0);
    command(DCS_DISPON, NULL, 0);
    lcd_delay_ms(20);
}

void lcd_start_rows(lcd *panel, int y0, int rows, const void *pixels)
{
    lcd_wait(panel);
    set_range(DCS_CASET, 0, panel->width - 1);
    set_range(DCS_RASET, y0, y0 + rows - 1);
    command(DCS_RAMWR, NULL, 0);
    lcd_dc(1);
    lcd_dma_start(pixels, (size_t)panel->width * (size_t)rows * 2);
    panel->busy = true;
}

void lcd_wait(lcd *panel)
{
    if (panel->busy)
        lcd_dma_wait();
    panel->busy = false;
}
