/*
 * device.c - the public device API: results, formats, init, the frame
 * (begin/draw/end) and the three ways of executing it: direct, binned and
 * band by band.
 */
#include "internal.h"

const char *mote_result_string(mote_result result)
{
    /* one string of NUL-separated names: no table of pointers */
    static const char names[] =
#define MOTE__NAME(name, text) text "\0"
        MOTE__RESULTS(MOTE__NAME)
#undef MOTE__NAME
        ;
    if ((unsigned)result >= (unsigned)MOTE_RESULT_COUNT)
        return "unknown result";
    const char *s = names;
    for (int i = 0; i < (int)result; i++)
        while (*s++ != '\0')
            ;
    return s;
}

/* The bands of a frame: ceil(height / band_height). */
static int mote__band_count(int height, int band_height)
{
    return (height + band_height - 1) / band_height;
}

size_t mote_band_bins_bytes(int height, int band_height, uint32_t triangles)
{
    if (height <= 0 || band_height <= 0 || height > MOTE_MAX_SIZE || band_height >= height
        || mote__band_count(height, band_height) > 255)
        return 0;
    return 2 * (size_t)triangles;
}

mote_device_desc mote_device_desc_defaults(const mote_device_desc *desc)
{
    mote_device_desc d = *desc;
    if (d.color_format == MOTE_FORMAT_DEFAULT)
        d.color_format = MOTE_FORMAT_RGBA8888;
    if (d.depth_format == MOTE_DEPTH_FORMAT_DEFAULT)
        d.depth_format = MOTE_DEPTH_FORMAT_32;
    /* unsigned: a width no device has (init refuses it) must not overflow */
    if (d.color_stride == 0)
        d.color_stride = (int)((unsigned)d.width * (unsigned)mote_format_bytes(d.color_format));
    /* 0 < clear_depth <= 1 (not NaN) by its bits, which order as positive
     * floats do (-0 and negatives have the sign bit): no soft-float calls */
    if (mote__float_bits(d.clear_depth) - 1u >= 0x3f800000u)
        d.clear_depth = 1.0f;
    if (d.subpixel_bits == 0)
        d.subpixel_bits = 8;
    if (d.band_height == 0 || d.band_height > d.height)
        d.band_height = d.height;
    if (d.tile_size == 0)
        d.tile_size = 64;
    return d;
}

mote_result mote_device_init(mote_device *dev, const mote_device_desc *desc)
{
    if (!dev)
        return MOTE_ERR_INVALID_ARGUMENT;
    memset(dev, 0, sizeof *dev);
    if (!desc)
        return MOTE_ERR_INVALID_ARGUMENT;
    mote_device_desc d = mote_device_desc_defaults(desc);
    if (d.width < 1 || d.height < 1 || d.width > MOTE_MAX_SIZE || d.height > MOTE_MAX_SIZE)
        return MOTE_ERR_INVALID_ARGUMENT;
    if (d.color_format <= MOTE_FORMAT_DEFAULT || d.color_format >= MOTE_FORMAT_COUNT || !d.color)
        return MOTE_ERR_INVALID_ARGUMENT;
    if (d.depth_format <= MOTE_DEPTH_FORMAT_DEFAULT || d.depth_format >= MOTE_DEPTH_FORMAT_COUNT)
        return MOTE_ERR_INVALID_ARGUMENT;
    if (d.depth_format != MOTE_DEPTH_FORMAT_NONE && !d.depth)
        return MOTE_ERR_INVALID_ARGUMENT;
    /* pixels and depth values are stored as whole 16- and 32-bit words,
     * which a core without unaligned access (Cortex-M0+) faults on: the
     * buffers and the rows start at multiples of their size (1, 2 or 4) */
    const int pixel_mask = mote_format_bytes(d.color_format) - 1;
    const uintptr_t depth_bytes = (uintptr_t)mote_depth_format_bytes(d.depth_format);
    if (d.color_stride < d.width * (pixel_mask + 1) || (d.color_stride & pixel_mask)
        || ((uintptr_t)d.color & (uintptr_t)pixel_mask) || ((uintptr_t)d.color_back & (uintptr_t)pixel_mask)
        || (depth_bytes && ((uintptr_t)d.depth & (depth_bytes - 1))))
        return MOTE_ERR_INVALID_ARGUMENT;
    if (d.subpixel_bits < 4 || d.subpixel_bits > 8 || d.band_height < 1)
        return MOTE_ERR_INVALID_ARGUMENT;
    if (d.band_height < d.height && (!d.flush || d.arena))
        return MOTE_ERR_INVALID_ARGUMENT;
    if (d.tile_size < 8 || d.tile_size > 256 || (d.tile_size & (d.tile_size - 1)))
        return MOTE_ERR_INVALID_ARGUMENT;
    dev->desc = d;
    dev->bands.color = d.color;
    if (d.band_bins && mote_band_bins_bytes(d.height, d.band_height, 1) > 0) {
        mote__bands *bb = &dev->bands;
        size_t cap = d.band_bins_size / 2;
        bb->bins = (unsigned char *)d.band_bins;
        bb->capacity = cap < UINT32_MAX ? (uint32_t)cap : UINT32_MAX;
        /* row * scale >> 16 is within one band of row / band_height, below
         * it with scale_lo and above with scale_hi: a range one band wider
         * at most, never narrower, and no division per triangle */
        bb->scale_lo = 65536u / (uint32_t)d.band_height;
        bb->scale_hi = (65536u + (uint32_t)d.band_height - 1) / (uint32_t)d.band_height;
    }
    if (d.arena) {
        if (!MOTE_ENABLE_BINNING)
            return MOTE_ERR_UNSUPPORTED;
        mote__bin *b = &dev->bin;
        b->base = (unsigned char *)d.arena;
        /* whole 8-byte words, as the records in it are aligned from both
         * ends; and no more than its 32-bit offsets reach */
        b->size = (d.arena_size < UINT32_MAX ? d.arena_size : UINT32_MAX) & ~(size_t)7u;
        while ((1 << b->tile_shift) < d.tile_size)
            b->tile_shift++;
        b->tiles_x = (d.width + d.tile_size - 1) / d.tile_size;
        b->tiles_y = (d.height + d.tile_size - 1) / d.tile_size;
        if (((uintptr_t)d.arena & 7u) != 0)
            return MOTE_ERR_INVALID_ARGUMENT;
        /* clear_drawn_tiles_only: two bytes per tile at the arena's start,
         * kept from frame to frame; the first clear is a full one. Written
         * only once the description is accepted: a refused device touches
         * no byte of the caller's. */
        size_t tiles = (size_t)b->tiles_x * (size_t)b->tiles_y, marks = (2 * tiles + 7u) & ~(size_t)7u;
        if (MOTE_ENABLE_BINNING && d.clear_drawn_tiles_only && d.arena_size > marks) {
            b->drawn_before = b->base;
            b->drawn_now = b->base + tiles;
            memset(b->drawn_now, 1, tiles);
            b->base += marks;
            b->size -= marks;
        }
#if MOTE_ENABLE_BINNING  /* bin.c's functions exist only then */
        /* worth binning only with room for the tile table and some triangles */
        b->enabled = b->size >= mote__bin_table_bytes(dev) + 64 * mote_arena_bytes_per_triangle() + 4096;
#endif
    }
    mote__mat4_identity(dev->view_proj);
    dev->ready = true;
    return MOTE_OK;
}

const mote_stats *mote_device_stats(const mote_device *dev)
{
    return dev ? &dev->stats : NULL;
}

/* ---- the frame ----------------------------------------------------------- */

mote_result mote_begin(mote_device *dev, const mote_frame_desc *frame)
{
    if (!dev || !frame)
        return MOTE_ERR_INVALID_ARGUMENT;
    if (!dev->ready)
        return MOTE_ERR_STATE;
    if (!MOTE_ENABLE_ORTHOGRAPHIC && frame->camera.projection == MOTE_PROJECTION_ORTHOGRAPHIC)
        return MOTE_ERR_UNSUPPORTED;
    /* a frame begun again before its mote_end is abandoned, but the clear
     * it put off is owed: the marks of the tiles it was to clear are about
     * to be replaced */
    if (MOTE_ENABLE_BINNING && dev->in_frame && dev->clear_pending)
        mote__clear_frame(dev);
    dev->frame = *frame;
    /* a band's buffer holds other rows between frames: nothing to keep */
    if (mote__band_mode(dev))
        dev->frame.keep_color = dev->frame.keep_depth = false;
    if (dev->frame.light_count < 0)
        dev->frame.light_count = 0;
    if (dev->frame.light_count > MOTE_MAX_LIGHTS)
        dev->frame.light_count = MOTE_MAX_LIGHTS;
#if MOTE_ENABLE_LIGHT_FALLOFF
    /* once a frame, not per vertex: what geometry.c's mote__falloff takes
     * of a spot light's cone */
    for (int i = 0; i < dev->frame.light_count; i++) {
        const mote_light *l = &dev->frame.lights[i];
        dev->spot_cone[i][0] = mote__rsqrtf(mote__dot3(l->direction, l->direction));
        dev->spot_cone[i][1] = mote_cosf(0.5f * l->spot_angle);
    }
#endif
    /* The vertex stage works relative to the camera's position: a mesh's
     * translation and a light's position less the camera's, one float
     * subtraction each, exact when the two are within a factor of two of
     * each other however far from the origin both are; then the view
     * turns and projects. Composed as view x world, the view's
     * translation and the mesh's cancelled after each was rounded at its
     * own magnitude: a scene 1e5 units from the origin had its vertices
     * 0.3 pixel off at 160x120 and 1e6 units 2.3 pixels
     * (tests/test_stability.c). */
    for (int i = 0; i < dev->frame.light_count; i++)
        mote__sub3(dev->frame.lights[i].position, frame->camera.position);
    float proj[16], view[16];
    mote__view_rotation(&frame->camera, view);
    mote__projection(&frame->camera, (float)dev->desc.width / (float)dev->desc.height, proj);
    mote__mat4_mul(proj, view, dev->view_proj);
    memset(&dev->stats, 0, sizeof dev->stats);
    dev->draw_count = 0;
    dev->in_frame = true;
    /* The clear runs before binning, in stripes of whole rows: tile by
     * tile inside the tile jobs, short scattered rows streamed badly
     * (docs/performance.md). When draws are recorded for parallel setup,
     * the stripes wait for that setup and run beside it
     * (mote__bin_run_draws), which touches no pixel. */
    if (MOTE_ENABLE_BINNING && mote__binned(dev))
        mote__bin_begin(dev);
    dev->clear_pending = MOTE_ENABLE_BINNING && mote__binned(dev) && mote__bin_defers(dev);
    if (!dev->clear_pending && !mote__band_mode(dev))
        mote__clear_frame(dev);
    return MOTE_OK;
}

/* A draw drawn at once into region r of target tg. */
static mote_result mote__draw_direct(mote_device *dev, const mote_mesh *mesh, const mote_draw_desc *d,
                                     const mote__target *tg, mote__rect r)
{
    mote__sink sink;
    memset(&sink, 0, sizeof sink);
    sink.tg = tg;
    sink.region = r;
    return mote__process_draw(dev, mesh, d, &sink, NULL);
}

/* Keeps a draw for mote_end (band mode) or for binning in parallel. */
static void mote__record(mote_device *dev, const mote_mesh *mesh, const mote_draw_desc *d)
{
    mote__draw *rec = &dev->draws[dev->draw_count++];
    rec->mesh = mesh;
    rec->desc = *d;
    rec->band_known = false;
}

mote_result mote_draw(mote_device *dev, const mote_mesh *mesh, const mote_draw_desc *draw)
{
    if (!dev || !mesh)
        return MOTE_ERR_INVALID_ARGUMENT;
    if (!dev->ready || !dev->in_frame)
        return MOTE_ERR_STATE;
    if ((mesh->vertex_count > 0 && !mote__mesh_has_vertices(mesh))
        || (mesh->index_count > 0 && !mote__mesh_has_indices(mesh)))
        return MOTE_ERR_INVALID_ARGUMENT;
    if (mesh->hidden)
        return MOTE_OK;
    mote_draw_desc d;
    mote_result r = mote__resolve_draw_desc(draw, mesh, &d);
    if (r != MOTE_OK)
        return r;
    /* points and lines write colour alone */
    if (d.no_color_write && (d.mode == MOTE_MODE_POINTS || d.mode == MOTE_MODE_WIREFRAME))
        return MOTE_OK;
    if (mote__band_mode(dev)) {
        if (dev->draw_count >= MOTE_MAX_DRAWS)
            return MOTE_ERR_TOO_MANY_DRAWS;
        mote__record(dev, mesh, &d);
        return MOTE_OK;
    }
    mote__rect all = {0, 0, dev->desc.width, dev->desc.height};
    mote__target tg;
    mote__counts count = {0, 0};
    mote__full_target(dev, &tg, &count);
    bool triangles = d.mode != MOTE_MODE_POINTS && d.mode != MOTE_MODE_WIREFRAME;
    if (MOTE_ENABLE_BINNING && mote__binned(dev) && triangles) {
        if (mote__bin_defers(dev)) {
            /* set up later, in parallel (bin.c); a full record is binned first */
            r = dev->draw_count == MOTE_MAX_DRAWS ? mote__bin_run_draws(dev) : MOTE_OK;
            mote__record(dev, mesh, &d);
            return r;
        }
        r = mote__bin_draw(dev, mesh, &d);
    } else {
        /* points and lines are drawn at once; earlier binned triangles first */
        if (MOTE_ENABLE_BINNING && mote__binned(dev)) {
            r = mote__bin_run_draws(dev);
            mote__bin_flush(dev);
            mote__bin_mark_all_drawn(dev);   /* not through the tiles */
        }
        mote_result drawn = mote__draw_direct(dev, mesh, &d, &tg, all);
        r = r != MOTE_OK ? r : drawn;
    }
    mote__add_counts(dev, &count);
    return r;
}

static mote_result mote__draw_bands(mote_device *dev);

mote_result mote_end(mote_device *dev)
{
    if (!dev)
        return MOTE_ERR_INVALID_ARGUMENT;
    if (!dev->ready || !dev->in_frame)
        return MOTE_ERR_STATE;
    dev->in_frame = false;
    if (MOTE_ENABLE_BINNING && mote__binned(dev)) {
        mote_result r = mote__bin_run_draws(dev);
        mote__bin_flush(dev);
        return r;
    }
    if (!mote__band_mode(dev))
        return MOTE_OK;
    return mote__draw_bands(dev);
}

/* Band b of a draw: whether it may touch the band (unknown: yes). */
static bool mote__draw_in_band(const mote__draw *rec, int band)
{
    return !rec->band_known || (band >= rec->band_first && band <= rec->band_last);
}

/* The buffer band k is drawn into, once the transfer that last read it
 * (if any) is over. */
static void *mote__band_buffer(mote_device *dev, int k)
{
    const mote_device_desc *d = &dev->desc;
    int which = d->color_back ? (k & 1) : 0;
    void *color = which ? d->color_back : d->color;
    if (dev->bands.in_flight[which] && d->flush_wait)
        d->flush_wait(d->flush_user, color);
    dev->bands.in_flight[which] = false;
    return color;
}

static mote_result mote__draw_bands(mote_device *dev)
{
    const mote_device_desc *d = &dev->desc;
    mote__bands *bb = &dev->bands;
    mote_result result = MOTE_OK;
    mote_stats first_band = dev->stats;
    bb->used = 0;
    for (int k = 0, y0 = 0; y0 < d->height; k++, y0 += d->band_height) {
        int y1 = MOTE__MIN(y0 + d->band_height, d->height);
        mote__target tg;
        mote__counts count = {0, 0};
        mote__full_target(dev, &tg, &count);
        tg.color = (uint8_t *)mote__band_buffer(dev, k);
        tg.y0 = y0;
        bb->index = k;
        bb->color = tg.color;
        mote__rect band = {0, y0, d->width, y1};
        mote__clear_rect(dev, &tg, band);
        for (int i = 0; i < dev->draw_count; i++) {
            mote__draw *rec = &dev->draws[i];
            if (!mote__draw_in_band(rec, k))
                continue;
            bb->draw = rec;
            mote_result r = mote__draw_direct(dev, rec->mesh, &rec->desc, &tg, band);
            if (r != MOTE_OK)
                result = r;
        }
        bb->draw = NULL;
        mote__add_counts(dev, &count);
        /* the first band visits every triangle: count them once */
        if (k == 0)
            first_band = dev->stats;
        first_band.pixels_tested = dev->stats.pixels_tested;
        first_band.pixels_written = dev->stats.pixels_written;
        first_band.triangles_black = dev->stats.triangles_black;   /* by each first row's band */
        dev->stats = first_band;
        bb->in_flight[d->color_back ? (k & 1) : 0] = true;
        d->flush(d->flush_user, y0, y1 - y0, tg.color, d->color_stride);
    }
    return result;
}
