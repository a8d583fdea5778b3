/*
 * stb_guard_png.c - a PNG's chunks and zlib stream read by the rules of
 * stb_image's parser and inflater, to refuse the files that reach its
 * known faults and pad the palettes it reads past (stb_guard.c).
 */
#include "stb_guard.h"

#include <string.h>

/* The zlib stream of a PNG (its IDAT chunks end to end), read by the rules
 * of stb_image's inflater without writing the output, only counting it. */
typedef struct mote__zin {
    const unsigned char *z, *end;
    uint32_t buf;
    int bits;
    bool corrupt; /* stb_image's reader met a state it calls corrupt */
    size_t out;
} mote__zin;

typedef struct mote__zhuff {
    uint16_t count[16];
    uint32_t first[16];
    int offset[16];
    uint16_t symbol[288];
    /* codes of up to 9 bits by the next 9 bits of the stream: length << 9 | symbol */
    uint16_t fast[512];
} mote__zhuff;

static unsigned mote__zget8(mote__zin *z)
{
    return z->z < z->end ? *z->z++ : 0;
}

static void mote__zfill(mote__zin *z)
{
    do {
        if (z->bits < 0 || z->buf >> z->bits) {
            /* stb_image sees bits above the count: corrupt, it stops reading
             * (and with a negative count its own test is undefined) */
            z->corrupt = true;
            z->z = z->end;
            return;
        }
        z->buf |= (uint32_t)mote__zget8(z) << z->bits;
        z->bits += 8;
    } while (z->bits <= 24);
}

static unsigned mote__zbits(mote__zin *z, int n)
{
    if (z->bits < n)
        mote__zfill(z);
    unsigned k = z->buf & ((1u << n) - 1);
    z->buf >>= n;
    z->bits -= n;
    return k;
}

/* Canonical codes from lengths, refused as stb_image refuses them. */
static bool mote__zbuild(mote__zhuff *h, const uint8_t *lengths, int num)
{
    memset(h->count, 0, sizeof h->count);
    memset(h->fast, 0, sizeof h->fast);
    for (int i = 0; i < num; i++)
        h->count[lengths[i]]++;
    if (!mote__huffman_canonical(h->count, 15, h->first, h->offset))
        return false;
    int next[16];
    for (int len = 1; len < 16; len++)
        next[len] = h->offset[len];
    for (int i = 0; i < num; i++) {
        int len = lengths[i];
        if (!len)
            continue;
        int index = next[len]++;
        h->symbol[index] = (uint16_t)i;
        if (len <= 9) {
            /* the code's bits arrive lowest first: reversed */
            uint32_t c = h->first[len] + (uint32_t)(index - h->offset[len]), r = 0;
            for (int b = 0; b < len; b++)
                r |= ((c >> b) & 1) << (len - 1 - b);
            for (uint32_t j = r; j < 512; j += 1u << len)
                h->fast[j] = (uint16_t)(len << 9 | i);
        }
    }
    return true;
}

/* A symbol, or -1 where stb_image reports a bad code. */
static int mote__zdecode(mote__zin *z, const mote__zhuff *h)
{
    if (z->bits < 16) {
        if (z->z >= z->end)
            return -1;
        mote__zfill(z);
    }
    unsigned f = h->fast[z->buf & 511];
    if (f) {
        z->buf >>= f >> 9;
        z->bits -= (int)(f >> 9);
        return (int)(f & 511);
    }
    uint32_t code = 0;
    for (int len = 1; len < 16; len++) {
        code = code << 1 | ((z->buf >> (len - 1)) & 1);
        if (len > 9 && code < h->first[len] + h->count[len]) {
            z->buf >>= len;
            z->bits -= len;
            return h->symbol[h->offset[len] + (int)(code - h->first[len])];
        }
    }
    return -1;
}

static mote__verdict mote__zcodes(mote__zin *z, mote__zhuff *lit, mote__zhuff *dist)
{
    static const uint8_t order[19] = {16, 17, 18, 0, 8, 7, 9, 6, 10, 5, 11, 4, 12, 3, 13, 2, 14, 1, 15};
    uint8_t lengths[286 + 32 + 137], cl[19] = {0};
    int hlit = (int)mote__zbits(z, 5) + 257, hdist = (int)mote__zbits(z, 5) + 1;
    int hclen = (int)mote__zbits(z, 4) + 4, total = hlit + hdist;
    for (int i = 0; i < hclen; i++)
        cl[order[i]] = (uint8_t)mote__zbits(z, 3);
    if (!mote__zbuild(lit, cl, 19))
        return MOTE__STB_FAILS;
    int n = 0;
    while (n < total) {
        int c = mote__zdecode(z, lit);
        if (c < 0 || c >= 19)
            return MOTE__STB_FAILS;
        if (c < 16) {
            lengths[n++] = (uint8_t)c;
            continue;
        }
        uint8_t fill = 0;
        if (c == 16) {
            c = (int)mote__zbits(z, 2) + 3;
            if (n == 0)
                return MOTE__STB_FAILS;
            fill = lengths[n - 1];
        } else {
            c = c == 17 ? (int)mote__zbits(z, 3) + 3 : (int)mote__zbits(z, 7) + 11;
        }
        if (total - n < c)
            return MOTE__STB_FAILS;
        memset(lengths + n, fill, (size_t)c);
        n += c;
    }
    if (!mote__zbuild(lit, lengths, hlit) || !mote__zbuild(dist, lengths + hlit, hdist))
        return MOTE__STB_FAILS;
    return MOTE__GO;
}

/* The inflate of stb_image up to where it fails or ends; refused where it
 * would meet a length code 286-287 or a distance code 30-31, which DEFLATE
 * forbids: stb_image 2.27 reads a distance of 0 for those and copies the
 * output byte onto itself, so bytes malloc never initialised become
 * pixels (fixed upstream in 2.28). */
static mote__verdict mote__zcheck(mote__zin *z, mote__zhuff *lit, mote__zhuff *dist, bool header,
                                  char *message, size_t message_size)
{
    static const uint16_t len_base[29] = {3,  4,  5,  6,  7,  8,  9,  10, 11,  13,  15,  17,  19,  23, 27,
                                          31, 35, 43, 51, 59, 67, 83, 99, 115, 131, 163, 195, 227, 258};
    static const uint8_t len_extra[29] = {0, 0, 0, 0, 0, 0, 0, 0, 1, 1, 1, 1, 2, 2, 2,
                                          2, 3, 3, 3, 3, 4, 4, 4, 4, 5, 5, 5, 5, 0};
    static const uint16_t dist_base[30] = {1,    2,    3,    4,    5,    7,     9,     13,    17,  25,
                                           33,   49,   65,   97,   129,  193,   257,   385,   513, 769,
                                           1025, 1537, 2049, 3073, 4097, 6145, 8193, 12289, 16385, 24577};
    mote__verdict v = MOTE__STB_FAILS;
    if (header) {
        unsigned cmf = mote__zget8(z), flg = mote__zget8(z);
        if (z->z >= z->end || (cmf * 256 + flg) % 31 || (flg & 32) || (cmf & 15) != 8)
            goto out;
    }
    bool final;
    do {
        final = mote__zbits(z, 1);
        unsigned type = mote__zbits(z, 2);
        if (type == 0) {
            uint8_t head[4];
            int k = 0;
            if (z->bits & 7)
                (void)mote__zbits(z, z->bits & 7);
            while (z->bits > 0) {
                head[k++] = (uint8_t)z->buf;
                z->buf >>= 8;
                z->bits -= 8;
            }
            if (z->bits < 0)
                goto out;
            while (k < 4)
                head[k++] = (uint8_t)mote__zget8(z);
            unsigned len = head[1] * 256u + head[0], nlen = head[3] * 256u + head[2];
            if (nlen != (len ^ 0xffff) || len > (size_t)(z->end - z->z))
                goto out;
            z->z += len;
            z->out += len;
            continue;
        }
        if (type == 3)
            goto out;
        if (type == 1) {
            uint8_t fixed[288];
            memset(fixed, 8, 144);
            memset(fixed + 144, 9, 112);
            memset(fixed + 256, 7, 24);
            memset(fixed + 280, 8, 8);
            (void)mote__zbuild(lit, fixed, 288);
            memset(fixed, 5, 32);
            (void)mote__zbuild(dist, fixed, 32);
        } else if ((v = mote__zcodes(z, lit, dist)) != MOTE__GO) {
            goto out;
        }
        v = MOTE__STB_FAILS;
        for (;;) {
            int c = mote__zdecode(z, lit);
            if (c < 0)
                goto out;
            if (c < 256) {
                z->out++;
                continue;
            }
            if (c == 256)
                break;
            if (c >= 286)
                goto forbidden;
            c -= 257;
            size_t len = len_base[c] + (len_extra[c] ? mote__zbits(z, len_extra[c]) : 0);
            c = mote__zdecode(z, dist);
            if (c < 0)
                goto out;
            if (c >= 30)
                goto forbidden;
            int extra = c < 4 ? 0 : c / 2 - 1;
            size_t back = dist_base[c] + (extra ? mote__zbits(z, extra) : 0);
            if (z->out < back)
                goto out; /* stb_image: "bad dist" */
            z->out += len;
        }
    } while (!final);
    v = MOTE__GO;
    goto out;
forbidden:
    mote__io_error(message, message_size, MOTE_ERR_PARSE,
                   "texture: corrupt PNG: its deflate stream uses a length or distance code that "
                   "DEFLATE forbids (stb_image 2.27 would copy uninitialised memory into the "
                   "pixels)");
    v = MOTE__REFUSE;
out:
    if (z->corrupt && v != MOTE__REFUSE) {
        /* past that state stb_image's reader depends on undefined shifts:
         * refuse rather than guess */
        mote__io_error(message, message_size, MOTE_ERR_PARSE,
                       "texture: corrupt PNG: its deflate stream runs past its end");
        v = MOTE__REFUSE;
    }
    return v;
}

static uint32_t mote__crc32(const unsigned char *p, size_t n, uint32_t crc)
{
    crc = ~crc;
    while (n--) {
        crc ^= *p++;
        for (int k = 0; k < 8; k++)
            crc = crc >> 1 ^ (0xedb88320u & (0u - (crc & 1)));
    }
    return ~crc;
}

/* The PNG's chunks as stb_image's parse_png_file takes them. Checked: the
 * zlib stream (mote__zcheck). Padded: the palette of a colour type 3 image
 * to all 2^depth entries, black, in a copy (*fixed): stb_image keeps the
 * palette in an uninitialised stack array and looks every index up there,
 * so an index past the PLTE chunk's entries shows stack memory (reported upstream
 * as nothings/stb#1861, open). Out-of-range indices draw black, as browsers draw
 * them. */
mote_result mote__stb_guard_png(const unsigned char *d, size_t n, unsigned char **fixed,
                                size_t *fixed_size, char *message, size_t message_size)
{
    size_t p = 8, idat = 0, short_plte = 0;
    unsigned depth = 0, color = 0, pal_len = 0;
    bool first = true, iphone = false;
    for (;;) {
        if (n - p < 8)
            return MOTE_OK; /* stb_image reads zeros: an unknown critical chunk */
        uint32_t len = mote__be32(d, n, p), type = mote__be32(d, n, p + 4);
        bool whole = len <= n - p - 8 && n - p - 8 - len >= 4;
        if (type == 0x49454e44u) /* IEND */
            break;
        if (type == 0x49444154u && len > n - p - 8)
            /* stb_image fails on it, but first reallocates its buffer to the
             * length the chunk claims, up to 2 GiB for a file of a few bytes */
            return mote__io_error(message, message_size, MOTE_ERR_PARSE,
                                  "texture: truncated PNG: an IDAT chunk of %lu bytes with %zu "
                                  "left in the file", (unsigned long)len, n - p - 8);
        if (!whole)
            return MOTE_OK; /* a chunk cut short: stb_image fails after it */
        const unsigned char *body = d + p + 8;
        if (type == 0x43674249u) { /* CgBI: a raw deflate stream */
            iphone = true;
        } else if (type == 0x49484452u) { /* IHDR */
            if (!first || len != 13)
                return MOTE_OK;
            first = false;
            depth = body[8];
            color = body[9];
            if ((depth != 1 && depth != 2 && depth != 4 && depth != 8 && depth != 16) || color > 6)
                return MOTE_OK; /* stb_image fails */
        } else if (first) {
            return MOTE_OK;
        } else if (type == 0x504c5445u) { /* PLTE */
            if (len > 768 || len % 3)
                return MOTE_OK;
            pal_len = len / 3;
            if (color == 3 && pal_len && pal_len < (1u << depth))
                short_plte++;
        } else if (type == 0x74524e53u) { /* tRNS */
            if (color == 3 && (idat || !pal_len || len > pal_len))
                return MOTE_OK; /* stb_image fails: do not pad it into passing */
        } else if (type == 0x49444154u) { /* IDAT */
            if (color == 3 && !pal_len)
                return MOTE_OK;
            idat += len;
        } else if (!(type & 0x20000000u)) {
            return MOTE_OK; /* an unknown critical chunk */
        }
        p += 12 + (size_t)len;
    }
    if (first || !idat || (color == 3 && depth > 8))
        return MOTE_OK;

    /* the IDAT chunks end to end, as stb_image inflates them */
    mote__zhuff *tables = idat <= SIZE_MAX - 2 * sizeof *tables
                              ? mote__io_malloc(2 * sizeof *tables + idat) : NULL;
    if (!tables)
        return mote__io_error(message, message_size, MOTE_ERR_OUT_OF_MEMORY,
                              "texture: out of memory checking a PNG");
    unsigned char *z = (unsigned char *)(tables + 2);
    size_t at = 0;
    for (size_t q = 8; q < p; q += 12 + (size_t)mote__be32(d, n, q))
        if (mote__be32(d, n, q + 4) == 0x49444154u) {
            memcpy(z + at, d + q + 8, mote__be32(d, n, q));
            at += mote__be32(d, n, q);
        }
    mote__zin in = {z, z + idat, 0, 0, false, 0};
    mote__verdict v = mote__zcheck(&in, tables, tables + 1, !iphone, message, message_size);
    mote__io_free(tables);
    if (v == MOTE__REFUSE)
        return MOTE_ERR_PARSE;
    if (v == MOTE__STB_FAILS || !short_plte)
        return MOTE_OK;

    size_t full = 3u << depth, size = n + short_plte * 768;
    unsigned char *out = mote__io_malloc(size);
    if (!out)
        return mote__io_error(message, message_size, MOTE_ERR_OUT_OF_MEMORY,
                              "texture: out of memory padding a PNG palette");
    size_t o = 0;
    for (size_t q = 0; q < n;) {
        if (q < 8 || q >= p || mote__be32(d, n, q + 4) != 0x504c5445u ||
            mote__be32(d, n, q) >= full || mote__be32(d, n, q) == 0) {
            size_t step = q < 8 ? 8 : q >= p ? n - q : 12 + (size_t)mote__be32(d, n, q);
            memcpy(out + o, d + q, step);
            o += step;
            q += step;
            continue;
        }
        uint32_t len = mote__be32(d, n, q);
        unsigned char *c = out + o;
        c[0] = (unsigned char)(full >> 24);
        c[1] = (unsigned char)(full >> 16);
        c[2] = (unsigned char)(full >> 8);
        c[3] = (unsigned char)full;
        memcpy(c + 4, d + q + 4, 4 + (size_t)len);
        memset(c + 8 + len, 0, full - len);
        uint32_t crc = mote__crc32(c + 4, 4 + full, 0);
        for (int k = 0; k < 4; k++)
            c[8 + full + (size_t)k] = (unsigned char)(crc >> (24 - 8 * k));
        o += 12 + full;
        q += 12 + (size_t)len;
    }
    *fixed = out;
    *fixed_size = o;
    return MOTE_OK;
}
