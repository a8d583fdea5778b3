/*
 * format.h - colour and depth formats: bytes per pixel.
 */
#ifndef MOTE_CORE_FORMAT_H
#define MOTE_CORE_FORMAT_H

#include <mote/mote.h>

/* mote_format_bytes, inline: the pixel loops address rows with it, where
 * the format is a constant. */
static inline int mote__format_bytes(mote_format format)
{
    switch (format) {
    case MOTE_FORMAT_DEFAULT:
    case MOTE_FORMAT_RGBA8888: return 4;
    case MOTE_FORMAT_RGB565:
    case MOTE_FORMAT_RGB565_SWAPPED: return 2;
    case MOTE_FORMAT_GREY8: return 1;
    default: return 0;
    }
}

/* mote_depth_format_bytes */
static inline int mote__depth_format_bytes(mote_depth_format format)
{
    switch (format) {
    case MOTE_DEPTH_FORMAT_DEFAULT:
    case MOTE_DEPTH_FORMAT_32: return 4;
    case MOTE_DEPTH_FORMAT_16: return 2;
    default: return 0;
    }
}

#endif
