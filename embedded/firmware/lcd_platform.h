/*
 * lcd_platform.h - what the LCD driver (lcd.c) needs from the board: an SPI
 * bus to the panel with its data/command pin, a DMA channel that feeds the
 * same bus, and a delay. A port implements these five functions for its
 * SPI peripheral and pins (chip select held low, or driven by the SPI
 * peripheral); lcd_fake.c implements them as a panel in memory for the
 * emulated boards.
 */
#ifndef MOTE_FIRMWARE_LCD_PLATFORM_H
#define MOTE_FIRMWARE_LCD_PLATFORM_H

#include <stddef.h>
#include <stdint.h>

/* Sends n bytes and returns when the last has left the bus. */
void lcd_spi_write(const uint8_t *data, size_t n);
/* Sets the D/C pin: 0 for a command byte, 1 for parameters and pixels. */
void lcd_dc(int data);
/* Starts a DMA of n bytes from data to the SPI bus and returns at once;
 * data must stay unchanged until lcd_dma_wait returns. */
void lcd_dma_start(const void *data, size_t n);
/* Returns when the DMA lcd_dma_start started has sent its last byte. */
void lcd_dma_wait(void);
/* Waits at least ms milliseconds. */
void lcd_delay_ms(unsigned ms);

#endif
