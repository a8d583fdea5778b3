/*
 * lcd.h - a driver for ST7789 and ILI9341 SPI LCDs (MIPI DCS commands,
 * 16-bit colour), over the board's SPI, D/C pin and DMA (lcd_platform.h).
 *
 * Pixels go to the panel as mote renders them in MOTE_FORMAT_RGB565_SWAPPED
 * (the panel takes the high byte first), straight from the band buffer:
 *
 *   lcd panel;
 *   lcd_init(&panel, LCD_ST7789, 320, 240);
 *   ... in the band flush:  lcd_start_rows(&panel, y0, rows, color);
 *                           lcd_wait(&panel);
 *
 * A transfer is started and waited for separately, so that a caller with
 * two band buffers can render the next band while the DMA sends this one
 * and wait only before it reuses a buffer. lcd_start_rows waits for the
 * transfer before it, as the panel takes no command while pixels flow.
 */
#ifndef MOTE_FIRMWARE_LCD_H
#define MOTE_FIRMWARE_LCD_H

#include <stdbool.h>

typedef enum lcd_controller {
    LCD_ST7789,
    LCD_ILI9341,
} lcd_controller;

typedef struct lcd {
    lcd_controller controller;
    int width, height;            /* as drawn: landscape when width > height */
    bool busy;                    /* a transfer is under way */
} lcd;

/* Resets the controller, wakes it, sets 16-bit colour and the orientation
 * for width x height (240x320 or 320x240, or smaller), turns the display
 * on. Takes about 300 ms of lcd_delay_ms. */
void lcd_init(lcd *panel, lcd_controller controller, int width, int height);

/* Starts sending rows y0 .. y0 + rows - 1 of packed RGB565_SWAPPED pixels
 * (width pixels a row): the window, RAMWR, then a DMA of the pixels.
 * Returns once the DMA is under way; pixels must stay unchanged until
 * lcd_wait. */
void lcd_start_rows(lcd *panel, int y0, int rows, const void *pixels);

/* Returns when the transfer lcd_start_rows started is done (at once when
 * none is). */
void lcd_wait(lcd *panel);

#endif
