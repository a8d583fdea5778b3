/*
 * mote_internal_types.h - the parts of mote's private state that live inside
 * mote_device, declared here only so that the device can be a plain struct
 * placed by the caller. Not API: fields may change in any release.
 */
#ifndef MOTE_INTERNAL_TYPES_H
#define MOTE_INTERNAL_TYPES_H

/* A recorded draw (band mode, or binned through desc.parallel_for). */
typedef struct mote__draw {
    const struct mote_mesh *mesh;
    struct mote_draw_desc desc;
    /* band mode with band bins: where its triangles' ranges start, and the
     * bands its triangles touch (first > last: none), known once the
     * first band has drawn it with every triangle's range recorded */
    uint32_t bin_first;
    uint8_t band_first, band_last;
    bool band_known;
} mote__draw;

/* Band-mode state: the band being drawn, the buffer it is drawn into, and
 * the band bins (2 bytes a triangle: first and last band). */
typedef struct mote__bands {
    unsigned char *bins;
    uint32_t capacity, used;      /* triangles */
    uint32_t scale_lo, scale_hi;  /* 2^16 / band_height, floored and ceiled */
    int index;                    /* the band being drawn */
    void *color;                  /* the buffer it is drawn into */
    struct mote__draw *draw;      /* the recorded draw being drawn */
    bool in_flight[2];            /* color, color_back: flushed, not waited for */
} mote__bands;

/* Binned-mode state: a bump allocator over the caller's arena. */
typedef struct mote__bin {
    unsigned char *base;
    size_t size, used, top;       /* bump from the bottom; per-draw scratch from the top */
    size_t batch_start;           /* arena offset where binned triangles begin */
    int tiles_x, tiles_y, tile_shift;
    void *tiles;                  /* mote__tile[tiles_x * tiles_y] */
    unsigned triangles;           /* binned in this batch */
    size_t shared;                /* arena bytes other threads read since the last mote_begin */
    bool enabled;                 /* an arena large enough was given */
    unsigned char *cache;         /* a group's vertex cache (cache_size bytes), outside its slice */
    size_t cache_size;
    bool group;                   /* a group's private copy of the device: never flushes */
    bool overflowed;              /* that group ran out of its slice of the arena */
    bool groups_linked;           /* since the last reset: triangles binned on other cores */
    /* clear_drawn_tiles_only: a byte per tile, in the arena before base:
     * drawn into in this frame (the tile jobs set it), and since the last
     * clear as mote_begin found it (what the clear reads) */
    unsigned char *drawn_now, *drawn_before;
} mote__bin;

#endif
