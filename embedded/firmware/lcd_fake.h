/*
 * lcd_fake.h - a panel in memory behind lcd_platform.h, for the emulated
 * boards and the host: it reads the bytes the driver sends as an ST7789 or
 * ILI9341 would (240x320 in its own orientation), checks them against the
 * rules the datasheets set, and keeps the image the pixels make.
 */
#ifndef MOTE_FIRMWARE_LCD_FAKE_H
#define MOTE_FIRMWARE_LCD_FAKE_H

#include <stdint.h>

/* Ends the session: NULL when the panel was set up and then received
 * width x height pixels (the frame, each pixel once) by the rules, else
 * the first thing that went wrong, with *value the command byte or count
 * it concerns. *image_hash: fw_fnv1a of the image as the panel shows it,
 * top row first, two bytes a pixel in the order they arrived. */
const char *lcd_fake_finish(int width, int height, uint32_t *image_hash, uint32_t *value);

#endif
