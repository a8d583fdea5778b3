/*
 * span_simd.h - fill functions that run the pixel loop MOTE__VN pixels a
 * step in vector registers, for one instruction set each: span_sse2.c (4
 * lanes), span_avx2.c (8), span_neon.c (4) include this file once.
 *
 * They draw the same bytes as span.c's scalar loops, which stay their
 * oracle (tests/test_spans.c): the same edge walk, the same rows cut into
 * blocks of MOTE__BLOCK pixels with the same 32-bit planes at each
 * block's first pixel, and in every lane the scalar pixel's arithmetic,
 * modular where the scalar's is. Each lane steps its planes from the
 * block's first drawn pixel by its own multiple of the step, which is the
 * scalar loop's sum of single steps, modulo 2^32. The reciprocal
 * floor(2^K / q) comes from a double division and one integer correction
 * (see mote__v_recip), so it is exact too.
 *
 * The common variants only (mote__simd_table): nearest texels from a
 * power-of-two repeating RGBA8888 texture or none, any shade, affine or
 * per-pixel perspective, depth tested and written (16 or 32 bits) or none,
 * RGBA8888 or RGB565 pixels. Everything else (bilinear, sub-span, other
 * wraps and formats, what span.c's generic loop adds) keeps span.c's.
 *
 * The including file defines MOTE__VN, the names of the table and of the
 * reciprocal's test hook, MOTE__SIMD_TABLE and MOTE__SIMD_RECIP, and
 * three helpers:
 *   mote__v_mulshift(n, r, s)  lanes (int32)(((int64) n r) >> s), r >= 0
 *   mote__v_gather(base, off)  the 32-bit words at base + off (bytes), if
 *                              it defines MOTE__V_GATHER (else lane by lane)
 *   mote__v_bits(mask)         lane i's mask (all ones or 0) as bit i
 */
#ifndef MOTE__VN
#error "span_simd.h is included by span_sse2.c, span_avx2.c and span_neon.c"
#endif

typedef int32_t mote__vi __attribute__((vector_size(4 * MOTE__VN)));
typedef uint32_t mote__vu __attribute__((vector_size(4 * MOTE__VN)));
typedef double mote__vd __attribute__((vector_size(8 * MOTE__VN)));

#define MOTE__VINLINE static inline __attribute__((always_inline))
#define MOTE__PLANE_FN MOTE__VINLINE
#include "plane.h"

/* Triangles whose box is narrower than this many columns (most of their
 * rows shorter than a vector) are filled by the scalar loops, which cost
 * less a row. */
#ifndef MOTE__SIMD_NARROW
#define MOTE__SIMD_NARROW MOTE__VN
#endif

/* The 32-bit planes' block length: span.c's MOTE__BLOCK */
#define MOTE__VBLOCK_LOG2 6
enum { MOTE__VD_NONE, MOTE__VD_16, MOTE__VD_32 };   /* depth buffers, as span.c's */

MOTE__VINLINE mote__vi mote__v_splat(int32_t x)
{
    return (mote__vi){0} + x;
}

MOTE__VINLINE mote__vi mote__v_iota(void)
{
    mote__vi v;
    for (int i = 0; i < MOTE__VN; i++)
        v[i] = i;
    return v;
}

/* lanes of a where mask is all ones, of b where it is 0 */
MOTE__VINLINE mote__vi mote__v_select(mote__vi mask, mote__vi a, mote__vi b)
{
    return (a & mask) | (b & ~mask);
}

MOTE__VINLINE mote__vi mote__v_clamp(mote__vi v, int32_t lo, int32_t hi)
{
    v = mote__v_select(v < lo, mote__v_splat(lo), v);
    return mote__v_select(v > hi, mote__v_splat(hi), v);
}

/* base + i step in lane i, modulo 2^32 (the scalar loop's sums) */
MOTE__VINLINE mote__vi mote__v_ramp(int32_t base, int32_t step)
{
    return (mote__vi)((mote__vu)mote__v_splat(base) + (mote__vu)mote__v_iota() * (uint32_t)step);
}

/* each lane MOTE__VN steps on, modulo 2^32 */
MOTE__VINLINE mote__vi mote__v_next(mote__vi a, int32_t step)
{
    return (mote__vi)((mote__vu)a + (uint32_t)step * (uint32_t)MOTE__VN);
}

/* min(floor(2^k / max(q, 1)), 2^31 - 1) in each lane (mote__recip_k).
 * The double quotient of exact operands, truncated, is the floor or one
 * more (rounding is monotonic and the floor is a double); the remainder
 * 2^k - r d, in (-2^31, 2^31), tells which, from its low 32 bits. The
 * quotient reaches 2^31 - 1 exactly when max(q, 1) <= 2^(k - 31) (k > 30):
 * those lanes take 2^31 - 1, and divide by 2^(k - 31) + 1 meanwhile so
 * that no lane's quotient leaves int32. */
MOTE__VINLINE mote__vi mote__v_recip(mote__vi q, int k)
{
    const int32_t most = k > 30 ? (int32_t)1 << (k - 31) : 0;
    const mote__vi d = mote__v_select(q > most, q, mote__v_splat(most + 1));
    const mote__vd x = (double)((uint64_t)1 << k) / __builtin_convertvector(d, mote__vd);
    mote__vi r = __builtin_convertvector(x, mote__vi);
    const uint32_t low = k < 32 ? (uint32_t)1 << k : 0u;   /* 2^k mod 2^32 */
    const mote__vi rem = (mote__vi)(low - (mote__vu)r * (mote__vu)d);
    r += rem >> 31;
    return most > 0 ? mote__v_select(q <= most, mote__v_splat(0x7fffffff), r) : r;
}

/* (c s + 2^23) >> 24 by lanes (mote__modulate): c <= 255, s <= 2^24 */
MOTE__VINLINE mote__vu mote__v_modulate(mote__vu c, mote__vu s)
{
    return (c * s + (1u << 23)) >> 24;
}

/* channels 0..255 as pixels of the format (mote__pack) */
MOTE__VINLINE mote__vu mote__v_pack(mote_format fmt, mote__vu r, mote__vu g, mote__vu b)
{
    if (fmt == MOTE_FORMAT_RGBA8888)
        return r | g << 8 | b << 16 | 0xff000000u;
    /* (c n + 127) / 255 for c n + 127 < 2^16: x / 255 = (x 0x8081) >> 23 */
    const mote__vu r5 = ((r * 31 + 127) * 0x8081u) >> 23, g6 = ((g * 63 + 127) * 0x8081u) >> 23;
    const mote__vu b5 = ((b * 31 + 127) * 0x8081u) >> 23;
    return r5 << 11 | g6 << 5 | b5;
}

/* A block's scale (span.c's mote__block): the x steps of q and the
 * numerators, K and the attributes' shift. */
typedef struct mote__vblock {
    int32_t qdx, ndx[MOTE__ATTRS];
    int k, ash;
} mote__vblock;

/* What the pixels need of a triangle and its draw, once per fill. */
typedef struct mote__vctx {
    int64_t zdx, qdx;
    int64_t n0[MOTE__ATTRS], ndx[MOTE__ATTRS], ndy[MOTE__ATTRS];
    int32_t a0[MOTE__ATTRS];
    uint32_t sr, sg, sb;          /* the shade when it does not vary */
    uint32_t flat_px;
    int n_extra, q_drop, tb;
    int32_t affine_r;
    mote__vblock steps;           /* q_drop >= 0: every block's scale (zero when nothing varies) */
    const uint8_t *texels;
    int32_t umask, vmask;         /* texture width - 1, height - 1 */
    int stride_log2;
} mote__vctx;

/* A block's 32-bit planes at its first pixel to draw (span.c's
 * mote__block_at). */
typedef struct mote__vblock_at {
    int32_t q, n[MOTE__ATTRS];
} mote__vblock_at;

/* span.c's mote__block_begin: the planes at the block's first pixel to
 * draw, and the scale, the triangle's (c->steps) or the block's own. */
MOTE__VINLINE const mote__vblock *mote__v_block(const mote__vctx *c, mote__vblock *own, mote__vblock_at *at,
                                                int64_t q64, const uint64_t n64[MOTE__ATTRS], int32_t len,
                                                int32_t off, const int shade, const int tex)
{
    const mote__vblock *b = &c->steps;
    int d = c->q_drop;
    if (d < 0) {
        const int64_t q64e = mote__plane_at(q64, c->qdx, len);
        const mote__block_scale sc = mote__block_scale_of(q64, q64e, c->n_extra);
        d = sc.d;
        own->qdx = mote__step32(c->qdx, d);
        own->k = sc.k;
        own->ash = sc.ash;
        for (int a = 0; a < MOTE__ATTRS; a++)
            own->ndx[a] = mote__has_plane(a, (mote__shade_kind)shade, tex) ? mote__step32(c->ndx[a], d + c->n_extra) : 0;
        b = own;
    }
    const int nsh = d + c->n_extra;
    at->q = mote__add32(mote__to32(q64, d), b->qdx, off);
    for (int a = 0; a < MOTE__ATTRS; a++)
        at->n[a] = mote__has_plane(a, (mote__shade_kind)shade, tex)
                 ? mote__add32(mote__to32((int64_t)n64[a], nsh), b->ndx[a], off) : 0;
    return b;
}

#ifndef MOTE__V_GATHER
MOTE__VINLINE mote__vi mote__v_gather(const uint8_t *base, mote__vi off)
{
    mote__vi v;
    for (int i = 0; i < MOTE__VN; i++) {
        int32_t one;
        memcpy(&one, base + off[i], 4);
        v[i] = one;
    }
    return v;
}
#endif

/* The first count lanes of p (the others 0), without reading past them:
 * a row's last pixels may be the buffer's. A loop of constant length, so
 * that no compiler makes it a call to memcpy. */
MOTE__VINLINE mote__vu mote__v_load_part(const uint32_t *p, int count)
{
    mote__vu v = {0};
    for (int i = 0; i < MOTE__VN; i++)
        if (i < count)
            v[i] = p[i];
    return v;
}

MOTE__VINLINE mote__vu mote__v_load16(const uint16_t *p, int count)
{
    mote__vu v = {0};
    for (int i = 0; i < MOTE__VN; i++)
        if (i < count)
            v[i] = p[i];
    return v;
}

/* The depth values before clamping, z >> 16 of the 64-bit
 * plane, for the pixels [x, x + n) of a block from z at x: while they lie
 * within +-2^30 (always, inside a triangle: depths are 24-bit), lane i's
 * is hi + (lo >> 16) modulo 2^32, with hi = z >> 16 + i (zdx >> 16) and
 * lo = z mod 2^16 + i (zdx mod 2^16), which a block keeps below 2^22
 * (mote__v_depth_step). false otherwise: then lane by lane in 64 bits. */
MOTE__VINLINE bool mote__v_depth_ramp(int64_t z, int64_t zdx, ptrdiff_t n, mote__vi *hi, mote__vi *lo)
{
    const int64_t zh = mote__floor_shift64(z, 16), ze = mote__floor_shift64(mote__plane_at(z, zdx, n - 1), 16);
    const int64_t lim = (int64_t)1 << 30;
    *hi = mote__v_ramp((int32_t)zh, (int32_t)mote__floor_shift64(zdx, 16));
    *lo = mote__v_ramp((int32_t)(z & 0xffff), (int32_t)(zdx & 0xffff));
    return zh >= -lim && zh <= lim && ze >= -lim && ze <= lim;
}

/* Pixels [x0, x1) of a row, in one block, from its planes at x0: the
 * scalar pixel loop's arithmetic, MOTE__VN pixels a step. */
MOTE__VINLINE void mote__v_pixels(const mote__vctx *c, const mote__vblock *b, const mote__vblock_at *at,
                                  uint8_t *crow, uint8_t *zrow,
                                  ptrdiff_t x0, ptrdiff_t x1, int64_t z, uint32_t *rejected,
                                  const int tex, const int shade, const int persp, const int dsel, const mote_format fmt)
{
    const bool varying = shade != MOTE__SHADE_FLAT || tex;
    const int pb = fmt == MOTE_FORMAT_RGBA8888 ? 4 : 2, zb = dsel == MOTE__VD_16 ? 2 : 4;
    const int vn = MOTE__VN;
    mote__vi q = {0}, nr = {0}, ng = {0}, nb = {0}, nu = {0}, nv = {0};
    if (varying) {
        q = mote__v_ramp(at->q, b->qdx);
        if (shade != MOTE__SHADE_FLAT)
            nr = mote__v_ramp(at->n[MOTE__A_R], b->ndx[MOTE__A_R]);
        if (shade == MOTE__SHADE_RGB) {
            ng = mote__v_ramp(at->n[MOTE__A_G], b->ndx[MOTE__A_G]);
            nb = mote__v_ramp(at->n[MOTE__A_B], b->ndx[MOTE__A_B]);
        }
        if (tex) {
            nu = mote__v_ramp(at->n[MOTE__A_U], b->ndx[MOTE__A_U]);
            nv = mote__v_ramp(at->n[MOTE__A_V], b->ndx[MOTE__A_V]);
        }
    }
    mote__vi zhi = {0}, zlo = {0};
    bool z_ramp = false;
    if (dsel != MOTE__VD_NONE)
        z_ramp = mote__v_depth_ramp(z, c->zdx, x1 - x0, &zhi, &zlo);
    const int32_t zhstep = (int32_t)mote__floor_shift64(c->zdx, 16), zlstep = (int32_t)(c->zdx & 0xffff);
    const mote__vi iota = mote__v_iota();
    for (ptrdiff_t x = x0; x < x1; x += vn) {
        const int count = (int)MOTE__MIN(x1 - x, (ptrdiff_t)vn);
        const bool full = count == vn;
        mote__vi live = iota < count;
        mote__vu depth = {0};
        if (dsel != MOTE__VD_NONE) {
            mote__vi zz;
            if (z_ramp) {
                zz = (mote__vi)((mote__vu)zhi + (mote__vu)(zlo >> 16));
                zhi = mote__v_next(zhi, zhstep);
                zlo = mote__v_next(zlo, zlstep);
            } else {
                for (int i = 0; i < MOTE__VN; i++)
                    zz[i] = (int32_t)mote__floor_shift64(mote__plane_at(z, c->zdx, x - x0 + i), 16);
            }
            depth = (mote__vu)mote__v_clamp(zz, 0, (int32_t)MOTE__DEPTH_MAX);
            mote__vu old;
            if (dsel == MOTE__VD_16) {
                depth >>= 8;      /* the top 16 bits of the 24-bit depth */
                old = mote__v_load16((const uint16_t *)(const void *)zrow + x, count);
            } else if (full) {
                memcpy(&old, (const uint32_t *)(const void *)zrow + x, sizeof old);
            } else {
                old = mote__v_load_part((const uint32_t *)(const void *)zrow + x, count);
            }
            const mote__vi pass = (mote__vi)(depth < old);
            *rejected += (uint32_t)__builtin_popcount(mote__v_bits(live & ~pass));
            live &= pass;
        }
        const unsigned bits = mote__v_bits(live);
        mote__vu px = (mote__vu)mote__v_splat((int32_t)c->flat_px);
        if (bits && varying) {
            mote__vi r = mote__v_splat(c->affine_r);
            if (persp != MOTE__PERSP_AFFINE)
                r = mote__v_recip(q, b->k);
            mote__vu sr = (mote__vu)mote__v_splat((int32_t)c->sr), sg = (mote__vu)mote__v_splat((int32_t)c->sg);
            mote__vu sb = (mote__vu)mote__v_splat((int32_t)c->sb);
            if (shade != MOTE__SHADE_FLAT) {
                sr = (mote__vu)mote__v_clamp(mote__v_splat(c->a0[MOTE__A_R]) + mote__v_mulshift(nr, r, b->ash), 0,
                                             MOTE__SHADE_ONE);
                sg = sb = sr;
            }
            if (shade == MOTE__SHADE_RGB) {
                sg = (mote__vu)mote__v_clamp(mote__v_splat(c->a0[MOTE__A_G]) + mote__v_mulshift(ng, r, b->ash), 0,
                                             MOTE__SHADE_ONE);
                sb = (mote__vu)mote__v_clamp(mote__v_splat(c->a0[MOTE__A_B]) + mote__v_mulshift(nb, r, b->ash), 0,
                                             MOTE__SHADE_ONE);
            }
            mote__vu cr = {0}, cg = {0}, cb = {0};
            cr += 255;
            cg += 255;
            cb += 255;
            if (tex) {
                const mote__vi u = (mote__vi)((mote__vu)mote__v_splat(c->a0[MOTE__A_U])
                                              + (mote__vu)mote__v_mulshift(nu, r, b->ash));
                const mote__vi v = (mote__vi)((mote__vu)mote__v_splat(c->a0[MOTE__A_V])
                                              + (mote__vu)mote__v_mulshift(nv, r, b->ash));
                const mote__vi off = ((v >> c->tb) & c->vmask) << c->stride_log2 | ((u >> c->tb) & c->umask) << 2;
                const mote__vu w = (mote__vu)mote__v_gather(c->texels, off);
                cr = w & 0xff;
                cg = (w >> 8) & 0xff;
                cb = (w >> 16) & 0xff;
            }
            px = mote__v_pack(fmt, mote__v_modulate(cr, sr), mote__v_modulate(cg, sg), mote__v_modulate(cb, sb));
        }
        if (bits == (1u << vn) - 1) {
            if (fmt == MOTE_FORMAT_RGBA8888) {
                memcpy(crow + 4 * x, &px, sizeof px);
            } else {
                uint16_t p16[MOTE__VN];
                for (int i = 0; i < vn; i++)
                    p16[i] = (uint16_t)px[i];
                memcpy(crow + 2 * x, p16, sizeof p16);
            }
            if (dsel == MOTE__VD_32)
                memcpy(zrow + 4 * x, &depth, sizeof depth);
            else if (dsel == MOTE__VD_16) {
                uint16_t d16[MOTE__VN];
                for (int i = 0; i < vn; i++)
                    d16[i] = (uint16_t)depth[i];
                memcpy(zrow + 2 * x, d16, sizeof d16);
            }
        } else {
            for (unsigned m = bits; m; m &= m - 1) {
                const int i = __builtin_ctz(m);
                const ptrdiff_t xi = x + i;
                if (pb == 4) {
                    const uint32_t one = (uint32_t)px[i];
                    memcpy(crow + 4 * xi, &one, 4);
                }
                else
                    ((uint16_t *)(void *)crow)[xi] = (uint16_t)px[i];
                if (zb == 4 && dsel == MOTE__VD_32)
                    ((uint32_t *)(void *)zrow)[xi] = depth[i];
                else if (dsel == MOTE__VD_16)
                    ((uint16_t *)(void *)zrow)[xi] = (uint16_t)depth[i];
            }
        }
        if (varying)
            q = mote__v_next(q, b->qdx);
        if (shade != MOTE__SHADE_FLAT)
            nr = mote__v_next(nr, b->ndx[MOTE__A_R]);
        if (shade == MOTE__SHADE_RGB) {
            ng = mote__v_next(ng, b->ndx[MOTE__A_G]);
            nb = mote__v_next(nb, b->ndx[MOTE__A_B]);
        }
        if (tex) {
            nu = mote__v_next(nu, b->ndx[MOTE__A_U]);
            nv = mote__v_next(nv, b->ndx[MOTE__A_V]);
        }
    }
}

/* Row by row, as span.c's mote__rows: the edge walk, the 64-bit planes
 * stepped from column ox of the first row, taken to 32 bits at each
 * block's first pixel, and each block's pixels in vectors. */
MOTE__VINLINE void mote__v_rows(const mote__vctx *c, mote__walk *w, const mote__tri *t, const mote__target *tg,
                                const int tex, const int shade, const int persp, const int dsel, const mote_format fmt)
{
    const bool varying = shade != MOTE__SHADE_FLAT || tex;
    const size_t stride = (size_t)tg->stride, zstride = (size_t)tg->width * (dsel == MOTE__VD_16 ? 2 : 4);
    uint8_t *crow = tg->color + (size_t)(w->y - tg->y0) * stride;
    uint8_t *zrow = dsel != MOTE__VD_NONE ? (uint8_t *)tg->depth + (size_t)(w->y - tg->y0) * zstride : NULL;
    const int64_t dy0 = w->y - t->oy;
    uint64_t zr = (uint64_t)mote__plane_at(t->z, t->zdy, dy0), qr = 0, nrow[MOTE__ATTRS] = {0};
    if (varying) {
        qr = (uint64_t)mote__plane_at(t->q, t->qdy, dy0);
        for (int a = 0; a < MOTE__ATTRS; a++)
            if (mote__has_plane(a, (mote__shade_kind)shade, tex))
                nrow[a] = (uint64_t)mote__plane_at(c->n0[a], c->ndy[a], dy0);
    }
    const int ox = t->ox;
    uint32_t rejected = 0;
    mote__vblock own;             /* a block's scale, where the triangle has none */
    /* a turn a block, as span.c's mote__rows */
    mote__span_blocks sb = {0};
    for (bool first = true;; first = false) {
        if (sb.from >= sb.x1) {
            if (!first) {
                zr += (uint64_t)t->zdy;
                qr += (uint64_t)t->qdy;
                for (int a = 0; a < MOTE__ATTRS; a++)
                    nrow[a] += (uint64_t)c->ndy[a];
                crow += stride;
                if (dsel != MOTE__VD_NONE)
                    zrow += zstride;
            }
            if (w->y >= w->yend)
                break;
            if (!mote__span_begin(w, &sb, MOTE__VBLOCK_LOG2))
                continue;
        }
        const ptrdiff_t from = sb.from, bx = sb.bx, last = sb.last;
        const ptrdiff_t end = bx + ((ptrdiff_t)1 << MOTE__VBLOCK_LOG2), to = MOTE__MIN(end, sb.x1);
        const int32_t off = (int32_t)(from - bx);
        const mote__vblock *b = &c->steps;
        mote__vblock_at at = {0};
        if (varying) {
            const int64_t d = bx - ox;
            uint64_t nb[MOTE__ATTRS] = {0};
            for (int a = 0; a < MOTE__ATTRS; a++)
                if (mote__has_plane(a, (mote__shade_kind)shade, tex))
                    nb[a] = (uint64_t)mote__plane_at((int64_t)nrow[a], c->ndx[a], d);
            b = mote__v_block(c, &own, &at, mote__plane_at((int64_t)qr, c->qdx, d), nb,
                              (int32_t)(MOTE__MIN(end, last) - bx), off, shade, tex);
        }
        mote__v_pixels(c, b, &at, crow, zrow, from, to, mote__plane_at((int64_t)zr, c->zdx, (int32_t)(from - ox)),
                       &rejected, tex, shade, persp, dsel, fmt);
        sb.from = to;
        sb.bx = end;
    }
    const uint64_t tested = sb.tested;
    tg->counts->tested += tested;
    tg->counts->written += tested - rejected;
}

/* A triangle inside region r (span.c's mote__fill_body): its constants,
 * then the rows. */
MOTE__VINLINE void mote__v_fill(const mote__tri *t, const mote__target *tg, mote__rect r, int bits, const int tex,
                                const int shade, const int persp, const int dsel, const mote_format fmt)
{
    mote__walk w;
    if (!mote__walk_begin(&w, t, r, bits))
        return;
    const mote__raster_state *rs = t->rs;
    const bool varying = shade != MOTE__SHADE_FLAT || tex;
    mote__vctx c;
    c.zdx = t->zdx;
    c.qdx = t->qdx;
    c.n_extra = t->n_extra;
    c.tb = t->texel_bits;
    for (int a = 0; a < MOTE__ATTRS; a++) {
        const bool has = mote__has_plane(a, (mote__shade_kind)shade, tex);
        c.a0[a] = (int32_t)t->a0[a];
        c.n0[a] = has ? t->n[a][0] : 0;
        c.ndx[a] = has ? t->n[a][1] : 0;
        c.ndy[a] = has ? t->n[a][2] : 0;
    }
    c.sr = mote__clamp_shade(c.a0[MOTE__A_R]);
    c.sg = mote__clamp_shade(c.a0[MOTE__A_G]);
    c.sb = mote__clamp_shade(c.a0[MOTE__A_B]);
    c.flat_px = mote__pack(fmt, (255 * c.sr + (1u << 23)) >> 24, (255 * c.sg + (1u << 23)) >> 24,
                           (255 * c.sb + (1u << 23)) >> 24);
    c.texels = NULL;
    c.umask = c.vmask = 0;
    c.stride_log2 = 0;
    if (tex) {
        c.texels = (const uint8_t *)rs->texture->pixels;
        c.umask = rs->tex_w - 1;
        c.vmask = rs->tex_h - 1;
        c.stride_log2 = rs->tex_stride_log2;
    }
    c.q_drop = t->q_drop;
    c.affine_r = 0;
    memset(&c.steps, 0, sizeof c.steps);
    if (varying && c.q_drop >= 0) {
        const int d = c.q_drop;
        c.steps.qdx = mote__step32(t->qdx, d);
        c.steps.k = t->rbits;
        c.steps.ash = MOTE__MAX(t->rbits - 20 - t->n_extra, 0);
        for (int a = 0; a < MOTE__ATTRS; a++)
            c.steps.ndx[a] = mote__has_plane(a, (mote__shade_kind)shade, tex) ? mote__step32(c.ndx[a], d + t->n_extra) : 0;
        if (persp == MOTE__PERSP_AFFINE)
            c.affine_r = mote__recip_k(mote__to32(t->q, d), t->rbits);
    }
    mote__v_rows(&c, &w, t, tg, tex, shade, persp, dsel, fmt);
}

/* The variants: texture (none, nearest) x shade (flat, mono, RGB) x
 * perspective (affine, exact) x depth (none, 16, 32 bits, tested and
 * written) x format (RGBA8888, RGB565), in mote__simd_select's order. An
 * exact variant hands a triangle with one w at its corners to its affine
 * sibling, as span.c's do. */
#define MOTE__VFORMATS(X, T, S, P, D) X(T, S, P, D, 0) X(T, S, P, D, 1)
#define MOTE__VDEPTHS(X, T, S, P) MOTE__VFORMATS(X, T, S, P, 0) MOTE__VFORMATS(X, T, S, P, 1) MOTE__VFORMATS(X, T, S, P, 2)
#define MOTE__VPERSPS(X, T, S) MOTE__VDEPTHS(X, T, S, 0) MOTE__VDEPTHS(X, T, S, 1)
#define MOTE__VSHADES(X, T) MOTE__VPERSPS(X, T, 0) MOTE__VPERSPS(X, T, 1) MOTE__VPERSPS(X, T, 2)
#define MOTE__VALL(X) MOTE__VSHADES(X, 0) MOTE__VSHADES(X, 1)

#define MOTE__VDEFINE(T, S, P, D, F)                                                               \
    static void mote__vfill_##T##S##P##D##F(const mote__tri *t, const mote__target *tg, mote__rect r, \
                                            int bits)                                              \
    {                                                                                              \
        if (t->xmax - t->xmin < MOTE__SIMD_NARROW) {                                               \
            mote__fill_table[(((T * 3 + S) * 3 + P) * 3 + D) * 2 + F](t, tg, r, bits);             \
            return;                                                                                \
        }                                                                                          \
        if (P == MOTE__PERSP_CORRECT && (T || S) && (t->qdx | t->qdy) == 0) {                       \
            mote__vfill_##T##S##0##D##F(t, tg, r, bits);                                           \
            return;                                                                                \
        }                                                                                          \
        mote__v_fill(t, tg, r, bits, T, S, P, D, F ? MOTE_FORMAT_RGB565 : MOTE_FORMAT_RGBA8888);   \
    }
MOTE__VALL(MOTE__VDEFINE)
#undef MOTE__VDEFINE

#define MOTE__VENTRY(T, S, P, D, F) mote__vfill_##T##S##P##D##F,
const mote__fill_fn MOTE__SIMD_TABLE[MOTE__SIMD_VARIANTS] = {MOTE__VALL(MOTE__VENTRY)};
#undef MOTE__VENTRY

/* mote__v_recip of MOTE__VN values, for the tests to hold it to
 * mote__recip_k where the double quotient rounds up to an integer */
void MOTE__SIMD_RECIP(const int32_t *q, int k, int32_t *out)
{
    mote__vi v;
    memcpy(&v, q, sizeof v);
    v = mote__v_recip(v, k);
    memcpy(out, &v, sizeof v);
}
