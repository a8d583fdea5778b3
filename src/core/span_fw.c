/*
 * span_fw.c - the firmware's pixel loop (MOTE_FIRMWARE_SPANS): the draws a
 * firmware makes most, Gouraud-shaded or flat (black included: the faces a
 * light does not reach, with no ambient), textured by nearest texels of a
 * repeating power-of-two RGB565 texture or untextured, perspective-correct,
 * into RGB565 (or byte-swapped) with a 16-bit depth buffer tested and
 * written. The same bytes as span.c's generic loop, which stays the
 * fallback for everything else (and for a triangle whose planes need a
 * scale per block: span.c's mote__fill_firmware), in under 2 KB of flash.
 *
 * What makes it fast on a 32-bit core without a 64-bit multiply
 * (Cortex-M0+): no call into libgcc per pixel. Products that need 64 bits
 * are built from 16x16-bit ones (mote__umul64), 64-bit shifts from 32-bit
 * halves, and the RGB565 conversion divides by 255 with a multiplication.
 */
#include "internal.h"
#include "plane.h"

#if MOTE_FIRMWARE_SPANS

/* floor(v / 255) for v < 2^16 */
static inline uint32_t mote__fw_div255(uint32_t v)
{
    return (v * 257 + 257) >> 16;
}

void mote__fill_fw(const mote__tri *t, const mote__target *tg, mote__rect r, int F)
{
    mote__walk w;
    if (!mote__walk_begin(&w, t, r, F))
        return;
    const mote__raster_state *rs = t->rs;
    /* a black triangle is filled untextured; a flat or black one has one
     * shade, vertex 0's, and no shade planes */
    const bool tex = rs->tex != MOTE__TEX_NONE && t->shade != MOTE__SHADE_BLACK, rgb = t->shade == MOTE__SHADE_RGB;
    const bool flat = t->shade == MOTE__SHADE_FLAT || t->shade == MOTE__SHADE_BLACK;
    const uint32_t flat_s[3] = {mote__clamp_shade((int32_t)t->a0[MOTE__A_R]), mote__clamp_shade((int32_t)t->a0[MOTE__A_G]),
                                mote__clamp_shade((int32_t)t->a0[MOTE__A_B])};
    const bool swapped = tg->format == MOTE_FORMAT_RGB565_SWAPPED;
    const int d = t->q_drop, nsh = d + t->n_extra, k = t->rbits, ash = MOTE__MAX(k - 20 - t->n_extra, 0);
    const int tb = t->texel_bits, planes = mote__plane_count(t->shade, tex);
    const uint8_t *texels = tex ? (const uint8_t *)rs->texture->pixels : NULL;
    const int tw = rs->tex_w - 1, th = rs->tex_h - 1, tstride = rs->tex_stride;
    /* the planes' 32-bit x steps; depth steps its exact 64-bit plane (span.c) */
    const uint32_t qdx = (uint32_t)mote__step32(t->qdx, d);
    const uint64_t zdx = (uint64_t)t->zdx;
    /* the planes the triangle has (mote__plane_count), 32-bit steps modular */
    int32_t a0[MOTE__ATTRS];
    uint32_t ndx[MOTE__ATTRS];
    int64_t nrow[MOTE__ATTRS];
    const int32_t dy0 = w.y - t->oy;
    for (int a = 0; a < planes; a++) {
        a0[a] = (int32_t)t->a0[a];
        ndx[a] = (uint32_t)mote__step32(t->n[a][1], nsh);
        nrow[a] = mote__plane_at(t->n[a][0], t->n[a][2], dy0);
    }
    int64_t zr = mote__plane_at(t->z, t->zdy, dy0), qr = mote__plane_at(t->q, t->qdy, dy0);
    const size_t stride = (size_t)tg->stride, zstride = (size_t)tg->width;
    uint8_t *crow = tg->color + (size_t)(w.y - tg->y0) * stride;
    uint16_t *zrow = (uint16_t *)tg->depth + (size_t)(w.y - tg->y0) * zstride;
    uint64_t tested = 0;
    uint32_t rejected = 0;
    for (; w.y < w.yend; crow += stride, zrow += zstride) {
        int x0, x1;
        int64_t span[2];
        mote__walk_row(&w, &x0, &x1, span);
        if (x0 < x1) {
            tested += (uint64_t)(x1 - x0);
            /* blocks of 64 pixels from the row's first (span.c's MOTE__BLOCK) */
            int32_t bx = (int32_t)(span[0] + ((x0 - span[0]) & -64));
            for (int32_t from = x0; from < x1; bx += 64) {
                const int32_t to = MOTE__MIN(bx + 64, x1), dx = bx - t->ox;
                const uint32_t off = (uint32_t)(from - bx);
                uint64_t z = (uint64_t)mote__plane_at(zr, t->zdx, dx + (int32_t)off);
                /* Q only where a plane divides by it */
                uint32_t q = flat && !tex ? 0u : (uint32_t)mote__to32(mote__plane_at(qr, t->qdx, dx), d) + qdx * off;
                uint32_t n[MOTE__ATTRS] = {0};
                for (int a = 0; a < planes; a++)
                    n[a] = (uint32_t)mote__to32(mote__plane_at(nrow[a], t->n[a][1], dx), nsh) + ndx[a] * off;
                uint16_t *px = (uint16_t *)(void *)crow;
                for (int32_t x = from; x < to; x++) {
                    const int64_t zz = (int64_t)z >> MOTE__DEPTH_FRAC;
                    uint32_t depth = (uint32_t)zz;
                    if ((uint64_t)zz > MOTE__DEPTH_MAX)
                        depth = zz < 0 ? 0u : MOTE__DEPTH_MAX;
                    depth >>= 8;
                    if (depth >= zrow[x]) {
                        rejected++;
                    } else {
                        const int32_t rr = flat && !tex ? 0 : mote__recip_k((int32_t)q, k);
                        uint32_t sr = flat_s[0], sg = flat_s[1], sb = flat_s[2];
                        if (!flat) {
                            sr = sg = sb = mote__clamp_shade(mote__attr(a0[MOTE__A_R], (int32_t)n[MOTE__A_R], rr, ash));
                            if (rgb) {
                                sg = mote__clamp_shade(mote__attr(a0[MOTE__A_G], (int32_t)n[MOTE__A_G], rr, ash));
                                sb = mote__clamp_shade(mote__attr(a0[MOTE__A_B], (int32_t)n[MOTE__A_B], rr, ash));
                            }
                        }
                        uint32_t c[3] = {255, 255, 255};
                        if (tex) {
                            const int32_t u = mote__attr(a0[MOTE__A_U], (int32_t)n[MOTE__A_U], rr, ash);
                            const int32_t v = mote__attr(a0[MOTE__A_V], (int32_t)n[MOTE__A_V], rr, ash);
                            mote__texel(MOTE_FORMAT_RGB565, texels + (size_t)((v >> tb) & th) * (size_t)tstride,
                                        (size_t)((u >> tb) & tw), c);
                        }
                        /* mote__modulate, then mote__pack's RGB565 */
                        const uint32_t cr = (c[0] * sr + (1u << 23)) >> 24, cg = (c[1] * sg + (1u << 23)) >> 24,
                                       cb = (c[2] * sb + (1u << 23)) >> 24;
                        uint32_t p = mote__fw_div255(cr * 31 + 127) << 11 | mote__fw_div255(cg * 63 + 127) << 5
                                   | mote__fw_div255(cb * 31 + 127);
                        if (swapped)
                            p = ((p & 0xff) << 8) | (p >> 8);
                        px[x] = (uint16_t)p;
                        zrow[x] = (uint16_t)depth;
                    }
                    z += zdx;
                    q += qdx;
                    for (int a = 0; a < planes; a++)
                        n[a] += ndx[a];
                }
                from = to;
            }
        }
        for (int a = 0; a < planes; a++)
            nrow[a] = (int64_t)((uint64_t)nrow[a] + (uint64_t)t->n[a][2]);
        zr = (int64_t)((uint64_t)zr + (uint64_t)t->zdy);
        qr = (int64_t)((uint64_t)qr + (uint64_t)t->qdy);
    }
    tg->counts->tested += tested;
    tg->counts->written += tested - rejected;
}

bool mote__fill_fw_fits(const mote__raster_state *rs, mote_format format, mote_depth_format depth_format)
{
    const bool target = (format == MOTE_FORMAT_RGB565 || format == MOTE_FORMAT_RGB565_SWAPPED)
                      && depth_format == MOTE_DEPTH_FORMAT_16 && rs->depth_test && rs->depth_write;
    const bool texels = rs->tex == MOTE__TEX_NONE
                     || (rs->tex == MOTE__TEX_NEAREST && rs->pow2_repeat && rs->texture->format == MOTE_FORMAT_RGB565);
    /* alpha, mip levels, layers and additive colour are the generic loop's */
    return target && texels && rs->persp == MOTE__PERSP_CORRECT && !rs->mips && !mote__generic_only(rs);
}

#else
typedef int mote__span_fw_unused;   /* ISO C: no empty translation unit */
#endif
