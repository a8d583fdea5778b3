/*
 * test_format.c - the format module (src/core/format.h, format.c): sizes,
 * names, packing, storing, texel reads, depth stores, conversion and
 * reading pixels back, format by format.
 *
 * What is asserted, and why it must hold exactly:
 *   - Every colour channel 0..255 packs to the nearest value the format
 *     holds (RGB565: round(c * 31 / 255) and round(c * 63 / 255); GREY8:
 *     the BT.601 weights 77, 150, 29 with rounding), and reads back as
 *     the 8-bit value nearest to what was stored (RGB565's 5 and 6 bits
 *     widened with rounding), so pack then read is the identity on
 *     RGBA8888 and on every value an RGB565 or GREY8 pixel can hold.
 *   - RGB565_SWAPPED stores RGB565's two bytes the other way round.
 *   - mote_convert_row to a format and back to RGBA8888 gives what
 *     packing and reading give, pixel for pixel; an unknown format
 *     converts nothing.
 *   - A 16-bit depth buffer stores D >> 8 of the 24-bit depth.
 *   - Names and texture formats: each valid format has one name, and the
 *     texture formats are those the texel read knows.
 */
#include <mote/mote.h>
#include "core/format.h"
#include "unity.h"

#include <string.h>

void setUp(void) {}
void tearDown(void) {}

static const mote_format all_formats[] = {MOTE_FORMAT_RGBA8888, MOTE_FORMAT_RGB565, MOTE_FORMAT_RGB565_SWAPPED,
                                          MOTE_FORMAT_GREY8};

void format_bytes_should_be_those_of_each_format(void)
{
    TEST_ASSERT_EQUAL(4, mote_format_bytes(MOTE_FORMAT_DEFAULT));
    TEST_ASSERT_EQUAL(4, mote_format_bytes(MOTE_FORMAT_RGBA8888));
    TEST_ASSERT_EQUAL(2, mote_format_bytes(MOTE_FORMAT_RGB565));
    TEST_ASSERT_EQUAL(2, mote_format_bytes(MOTE_FORMAT_RGB565_SWAPPED));
    TEST_ASSERT_EQUAL(1, mote_format_bytes(MOTE_FORMAT_GREY8));
    TEST_ASSERT_EQUAL(0, mote_format_bytes(MOTE_FORMAT_COUNT));
    TEST_ASSERT_EQUAL(0, mote_format_bytes((mote_format)-1));
    TEST_ASSERT_EQUAL(4, mote_depth_format_bytes(MOTE_DEPTH_FORMAT_DEFAULT));
    TEST_ASSERT_EQUAL(4, mote_depth_format_bytes(MOTE_DEPTH_FORMAT_32));
    TEST_ASSERT_EQUAL(2, mote_depth_format_bytes(MOTE_DEPTH_FORMAT_16));
    TEST_ASSERT_EQUAL(0, mote_depth_format_bytes(MOTE_DEPTH_FORMAT_NONE));
    TEST_ASSERT_EQUAL(0, mote_depth_format_bytes(MOTE_DEPTH_FORMAT_COUNT));
    TEST_ASSERT_EQUAL(320 * 16 * 4, mote_band_bytes(320, 16, MOTE_FORMAT_RGB565, MOTE_DEPTH_FORMAT_16));
    TEST_ASSERT_EQUAL(0, mote_band_bytes(MOTE_MAX_SIZE + 1, 16, MOTE_FORMAT_RGB565, MOTE_DEPTH_FORMAT_16));
}

void each_format_should_have_one_name_and_texture_formats_should_be_readable(void)
{
    for (size_t i = 0; i < sizeof all_formats / sizeof all_formats[0]; i++) {
        const char *n = mote_format_name(all_formats[i]);
        TEST_ASSERT_NOT_NULL(n);
        for (size_t j = 0; j < i; j++)
            TEST_ASSERT_TRUE(strcmp(n, mote_format_name(all_formats[j])) != 0);
    }
    TEST_ASSERT_EQUAL_STRING("rgb565", mote_format_name(MOTE_FORMAT_RGB565));
    TEST_ASSERT_NULL(mote_format_name(MOTE_FORMAT_DEFAULT));
    TEST_ASSERT_NULL(mote_format_name(MOTE_FORMAT_COUNT));
    TEST_ASSERT_TRUE(mote_format_is_texture(MOTE_FORMAT_RGBA8888));
    TEST_ASSERT_TRUE(mote_format_is_texture(MOTE_FORMAT_RGB565));
    TEST_ASSERT_TRUE(mote_format_is_texture(MOTE_FORMAT_GREY8));
    TEST_ASSERT_FALSE(mote_format_is_texture(MOTE_FORMAT_RGB565_SWAPPED));
    TEST_ASSERT_FALSE(mote_format_is_texture(MOTE_FORMAT_DEFAULT));
}

/* round(c * max / 255) */
static uint32_t narrow(uint32_t c, uint32_t max)
{
    return (c * max * 2 + 255) / 510;
}

/* round(v * 255 / max) */
static uint32_t widen(uint32_t v, uint32_t max)
{
    return (v * 255 * 2 + max) / (2 * max);
}

void rgb565_should_pack_to_the_nearest_value_and_read_back_the_nearest_byte(void)
{
    for (uint32_t c = 0; c < 256; c++) {
        uint32_t v = mote__pack(MOTE_FORMAT_RGB565, c, c, c);
        TEST_ASSERT_EQUAL_UINT32(narrow(c, 31), v >> 11);
        TEST_ASSERT_EQUAL_UINT32(narrow(c, 63), (v >> 5) & 63);
        TEST_ASSERT_EQUAL_UINT32(narrow(c, 31), v & 31);
    }
    for (uint32_t v = 0; v < 65536; v++) {
        uint16_t px = (uint16_t)v;
        uint32_t c[3];
        mote__texel(MOTE_FORMAT_RGB565, (const uint8_t *)&px, 0, c);
        TEST_ASSERT_EQUAL_UINT32(widen(v >> 11, 31), c[0]);
        TEST_ASSERT_EQUAL_UINT32(widen((v >> 5) & 63, 63), c[1]);
        TEST_ASSERT_EQUAL_UINT32(widen(v & 31, 31), c[2]);
        /* and packed again, the same pixel */
        TEST_ASSERT_EQUAL_UINT32(v, mote__pack(MOTE_FORMAT_RGB565, c[0], c[1], c[2]));
    }
}

void grey8_should_weigh_the_channels_and_read_back_as_grey(void)
{
    TEST_ASSERT_EQUAL_UINT32(255, mote__pack(MOTE_FORMAT_GREY8, 255, 255, 255));
    TEST_ASSERT_EQUAL_UINT32((77 * 200 + 128) >> 8, mote__pack(MOTE_FORMAT_GREY8, 200, 0, 0));
    TEST_ASSERT_EQUAL_UINT32((150 * 200 + 128) >> 8, mote__pack(MOTE_FORMAT_GREY8, 0, 200, 0));
    TEST_ASSERT_EQUAL_UINT32((29 * 200 + 128) >> 8, mote__pack(MOTE_FORMAT_GREY8, 0, 0, 200));
    for (uint32_t g = 0; g < 256; g++) {
        uint8_t px = (uint8_t)g;
        uint32_t c[3];
        mote__texel(MOTE_FORMAT_GREY8, &px, 0, c);
        TEST_ASSERT_TRUE(c[0] == g && c[1] == g && c[2] == g);
        TEST_ASSERT_EQUAL_UINT32(g, mote__pack(MOTE_FORMAT_GREY8, g, g, g));
    }
}

void every_format_should_store_what_it_packs_and_read_it_back(void)
{
    for (size_t i = 0; i < sizeof all_formats / sizeof all_formats[0]; i++) {
        mote_format f = all_formats[i];
        for (uint32_t k = 0; k < 4096; k++) {
            uint32_t r = (k * 37) & 255, g = (k * 101 + 7) & 255, b = (k * 53 + 200) & 255;
            uint8_t row[3 * 4];
            memset(row, 0xee, sizeof row);
            mote__write_rgb(row, 1, f, r, g, b);
            int bpp = mote_format_bytes(f);
            /* only pixel 1 is written */
            for (int j = 0; j < bpp; j++) {
                TEST_ASSERT_EQUAL_HEX8(0xee, row[j]);
                TEST_ASSERT_EQUAL_HEX8(0xee, row[2 * bpp + j]);
            }
            uint8_t back[4];
            mote__read_rgba(row, 1, f, back);
            uint8_t expect[4] = {(uint8_t)r, (uint8_t)g, (uint8_t)b, 255};
            if (f == MOTE_FORMAT_GREY8) {
                uint8_t y = (uint8_t)mote__pack(f, r, g, b);
                expect[0] = expect[1] = expect[2] = y;
            } else if (f != MOTE_FORMAT_RGBA8888) {
                uint32_t c[3];
                uint16_t v = (uint16_t)mote__pack(MOTE_FORMAT_RGB565, r, g, b);
                mote__texel(MOTE_FORMAT_RGB565, (const uint8_t *)&v, 0, c);
                for (int j = 0; j < 3; j++)
                    expect[j] = (uint8_t)c[j];
            }
            TEST_ASSERT_EQUAL_UINT8_ARRAY(expect, back, 4);
        }
    }
}

void rgb565_swapped_should_store_the_bytes_of_rgb565_the_other_way_round(void)
{
    for (uint32_t k = 0; k < 4096; k++) {
        uint32_t r = (k * 37) & 255, g = (k * 101 + 7) & 255, b = (k * 53 + 200) & 255;
        uint8_t a[2], s[2];
        mote__write_rgb(a, 0, MOTE_FORMAT_RGB565, r, g, b);
        mote__write_rgb(s, 0, MOTE_FORMAT_RGB565_SWAPPED, r, g, b);
        TEST_ASSERT_EQUAL_HEX8(a[0], s[1]);
        TEST_ASSERT_EQUAL_HEX8(a[1], s[0]);
    }
}

void convert_row_should_pack_and_read_as_the_module_does(void)
{
    enum { N = 300 };
    uint8_t rgba[N * 4], back[N * 4], mid[N * 4];
    for (int x = 0; x < N; x++) {
        rgba[4 * x] = (uint8_t)(x * 7);
        rgba[4 * x + 1] = (uint8_t)(x * 13 + 5);
        rgba[4 * x + 2] = (uint8_t)(255 - x);
        rgba[4 * x + 3] = (uint8_t)(x * 3);
    }
    for (size_t i = 0; i < sizeof all_formats / sizeof all_formats[0]; i++) {
        mote_format f = all_formats[i];
        mote_convert_row(rgba, MOTE_FORMAT_RGBA8888, mid, f, N);
        mote_convert_row(mid, f, back, MOTE_FORMAT_DEFAULT, N);
        for (int x = 0; x < N; x++) {
            uint8_t px[4], expect[4];
            mote__write_rgb(px, 0, f, rgba[4 * x], rgba[4 * x + 1], rgba[4 * x + 2]);
            if (f == MOTE_FORMAT_RGBA8888)
                px[3] = rgba[4 * x + 3];   /* conversion keeps RGBA8888's alpha */
            mote__read_rgba(px, 0, f, expect);
            TEST_ASSERT_EQUAL_UINT8_ARRAY(expect, &back[4 * x], 4);
        }
    }
    memset(back, 0x5a, sizeof back);
    mote_convert_row(rgba, MOTE_FORMAT_COUNT, back, MOTE_FORMAT_RGBA8888, N);
    mote_convert_row(rgba, MOTE_FORMAT_RGBA8888, back, (mote_format)99, N);
    for (size_t k = 0; k < sizeof back; k++)
        TEST_ASSERT_EQUAL_HEX8(0x5a, back[k]);
}

void read_pixel_should_read_each_format_of_a_device(void)
{
    for (size_t i = 0; i < sizeof all_formats / sizeof all_formats[0]; i++) {
        mote_format f = all_formats[i];
        uint8_t color[4 * 4 * 4];
        mote_device dev;
        mote_device_desc d = {.width = 4, .height = 4, .color_format = f, .color = color,
                              .depth_format = MOTE_DEPTH_FORMAT_NONE, .clear_color = {200, 100, 50, 77}};
        TEST_ASSERT_EQUAL(MOTE_OK, mote_device_init(&dev, &d));
        mote_frame_desc frame;
        memset(&frame, 0, sizeof frame);
        TEST_ASSERT_EQUAL(MOTE_OK, mote_begin(&dev, &frame));
        TEST_ASSERT_EQUAL(MOTE_OK, mote_end(&dev));
        uint8_t px[4], expect[4];
        mote__write_rgb(px, 0, f, 200, 100, 50);
        mote__read_rgba(px, 0, f, expect);
        if (f == MOTE_FORMAT_RGBA8888)
            expect[3] = 77;         /* the clear colour's alpha */
        mote_rgba c = mote_read_pixel(&dev, 3, 2);
        TEST_ASSERT_EQUAL_UINT8_ARRAY(expect, &c.r, 4);
        c = mote_read_pixel(&dev, 4, 0);
        TEST_ASSERT_TRUE(c.r == 0 && c.g == 0 && c.b == 0 && c.a == 0);
    }
}

void depth16_should_store_the_top_16_of_24_bits(void)
{
    uint16_t d16[2] = {0, 0};
    uint32_t d32[2] = {0, 0};
    mote__depth_store(d16, 1, MOTE_DEPTH_FORMAT_16, 0xabcdefu);
    mote__depth_store(d32, 1, MOTE_DEPTH_FORMAT_32, 0xabcdefu);
    TEST_ASSERT_EQUAL_HEX16(0xabcd, d16[1]);
    TEST_ASSERT_EQUAL_HEX32(0xabcdef, d32[1]);
    TEST_ASSERT_EQUAL(0, d16[0]);
    TEST_ASSERT_EQUAL(0, d32[0]);
}

int main(void)
{
    UNITY_BEGIN();
    RUN_TEST(format_bytes_should_be_those_of_each_format);
    RUN_TEST(each_format_should_have_one_name_and_texture_formats_should_be_readable);
    RUN_TEST(rgb565_should_pack_to_the_nearest_value_and_read_back_the_nearest_byte);
    RUN_TEST(grey8_should_weigh_the_channels_and_read_back_as_grey);
    RUN_TEST(every_format_should_store_what_it_packs_and_read_it_back);
    RUN_TEST(rgb565_swapped_should_store_the_bytes_of_rgb565_the_other_way_round);
    RUN_TEST(convert_row_should_pack_and_read_as_the_module_does);
    RUN_TEST(read_pixel_should_read_each_format_of_a_device);
    RUN_TEST(depth16_should_store_the_top_16_of_24_bits);
    return UNITY_END();
}
