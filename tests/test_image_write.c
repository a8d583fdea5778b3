/*
 * test_image_write.c - PNG and PPM output (src/io/image_write.c).
 */
#define _POSIX_C_SOURCE 200809L /* symlink */
#include "support/io_test.h"

#include <unistd.h>

static char msg[512];
static long live_before;

void setUp(void)
{
    msg[0] = '\0';
    live_before = io_test_begin();
}

void tearDown(void) {}

static long read_all(const char *path, unsigned char *buf, long cap)
{
    FILE *f = fopen(path, "rb");
    TEST_ASSERT_NOT_NULL_MESSAGE(f, path);
    long n = (long)fread(buf, 1, (size_t)cap, f);
    fclose(f);
    return n;
}

void write_ppm_should_write_exact_bytes_from_an_rgba_device(void)
{
    static uint8_t color[3 * 2 * 4];
    static uint32_t depth[3 * 2];
    mote_device dev;
    mote_device_desc d;
    memset(&d, 0, sizeof d);
    d.width = 3;
    d.height = 2;
    d.color = color;
    d.depth = depth;
    TEST_ASSERT_EQUAL(MOTE_OK, mote_device_init(&dev, &d));
    for (int i = 0; i < 3 * 2 * 4; i++)
        color[i] = (uint8_t)(i * 10);
    const char *path = io_tmp_path("out.ppm");
    TEST_ASSERT_EQUAL_MESSAGE(MOTE_OK, mote_write_ppm(path, &dev, msg, sizeof msg), msg);
    unsigned char got[64];
    long n = read_all(path, got, sizeof got);
    const char header[] = "P6\n3 2\n255\n";
    TEST_ASSERT_EQUAL(11 + 18, n);
    TEST_ASSERT_EQUAL_MEMORY(header, got, 11);
    for (int p = 0; p < 6; p++)
        for (int c = 0; c < 3; c++)
            TEST_ASSERT_EQUAL_UINT8(color[p * 4 + c], got[11 + p * 3 + c]);
    /* by extension, and the same bytes */
    TEST_ASSERT_EQUAL(MOTE_OK, mote_write_image(io_tmp_path("out2.ppm"), &dev, msg, sizeof msg));
    unsigned char got2[64];
    TEST_ASSERT_EQUAL(n, read_all(io_tmp_path("out2.ppm"), got2, sizeof got2));
    TEST_ASSERT_EQUAL_MEMORY(got, got2, (size_t)n);
}

void write_png_should_convert_an_rgb565_device_like_read_pixel(void)
{
    static uint16_t color[4 * 3];
    static uint32_t depth[4 * 3];
    mote_device dev;
    mote_device_desc d;
    memset(&d, 0, sizeof d);
    d.width = 4;
    d.height = 3;
    d.color_format = MOTE_FORMAT_RGB565;
    d.color = color;
    d.depth = depth;
    TEST_ASSERT_EQUAL(MOTE_OK, mote_device_init(&dev, &d));
    for (int i = 0; i < 12; i++)
        color[i] = (uint16_t)(i * 5003 + 17);
    const char *path = io_tmp_path("565.png");
    TEST_ASSERT_EQUAL_MESSAGE(MOTE_OK, mote_write_image(path, &dev, msg, sizeof msg), msg);
    mote_texture t;
    TEST_ASSERT_EQUAL_MESSAGE(MOTE_OK, mote_texture_load(path, NULL, &t, msg, sizeof msg), msg);
    TEST_ASSERT_EQUAL(4, t.width);
    TEST_ASSERT_EQUAL(3, t.height);
    const uint8_t *px = t.pixels;
    for (int y = 0; y < 3; y++)
        for (int x = 0; x < 4; x++) {
            mote_rgba want = mote_read_pixel(&dev, x, y);
            const uint8_t *p = px + y * t.stride + x * 4;
            TEST_ASSERT_EQUAL_UINT8(want.r, p[0]);
            TEST_ASSERT_EQUAL_UINT8(want.g, p[1]);
            TEST_ASSERT_EQUAL_UINT8(want.b, p[2]);
            TEST_ASSERT_EQUAL_UINT8(255, p[3]);
        }
    mote_texture_free(&t);
}

static void ignore_flush(void *user, int y0, int rows, const void *c, int stride)
{
    (void)user, (void)y0, (void)rows, (void)c, (void)stride;
}

void write_image_should_refuse_unknown_extensions_and_band_devices(void)
{
    uint8_t px[4] = {1, 2, 3, 4};
    TEST_ASSERT_EQUAL(MOTE_ERR_UNSUPPORTED, mote_write_rgba(io_tmp_path("x.jpg"), px, 1, 1, 0, msg,
                                                            sizeof msg));
    TEST_ASSERT_NOT_NULL(strstr(msg, "unknown image type"));
    static uint8_t color[8 * 2 * 4];
    static uint32_t depth[8 * 2];
    mote_device dev;
    mote_device_desc d;
    memset(&d, 0, sizeof d);
    d.width = 8;
    d.height = 8;
    d.band_height = 2;
    d.flush = ignore_flush;
    d.color = color;
    d.depth = depth;
    TEST_ASSERT_EQUAL(MOTE_OK, mote_device_init(&dev, &d));
    TEST_ASSERT_EQUAL(MOTE_ERR_UNSUPPORTED, mote_write_png(io_tmp_path("band.png"), &dev, msg,
                                                           sizeof msg));
    TEST_ASSERT_NOT_NULL(strstr(msg, "band-mode"));
    TEST_ASSERT_EQUAL(MOTE_ERR_UNSUPPORTED, mote_write_image(io_tmp_path("x.bmp"), &dev, msg,
                                                             sizeof msg));
    TEST_ASSERT_EQUAL(MOTE_ERR_IO, mote_write_rgba("/nonexistent-dir/x.ppm", px, 1, 1, 0, msg,
                                                   sizeof msg));
}

/* A write that fails half way (a full disk: /dev/full says ENOSPC to every
 * write) is an error for PNG as for PPM: stbi_write_png ignored fwrite's
 * result and said the PNG was written. A size whose rows stb_image_write
 * cannot count in an int is refused before a pixel is read (its buffer
 * size wrapped, and it wrote past the end). */
void write_image_should_report_a_full_disk_and_refuse_what_stb_cannot_encode(void)
{
    uint8_t px[4 * 4 * 4] = {0};
    static const char *const names[2] = {"full.png", "full.ppm"};
    for (int k = 0; k < 2 && io_file_exists("/dev/full"); k++) {
        const char *link = io_tmp_path(names[k]);
        TEST_ASSERT_EQUAL(0, symlink("/dev/full", link));
        msg[0] = '\0';
        mote_result r = mote_write_rgba(link, px, 4, 4, 0, msg, sizeof msg);
        unlink(link);
        TEST_ASSERT_EQUAL_MESSAGE(MOTE_ERR_IO, r, names[k]);
        TEST_ASSERT_NOT_NULL_MESSAGE(strstr(msg, "write error"), msg);
    }
    TEST_ASSERT_EQUAL(MOTE_ERR_IO, mote_write_rgba(io_tmp_path("no-dir/x.png"), px, 4, 4, 0, msg,
                                                   sizeof msg));
    TEST_ASSERT_NOT_NULL(strstr(msg, "cannot create"));
    TEST_ASSERT_EQUAL(MOTE_ERR_LIMIT, mote_write_rgba(io_tmp_path("huge.png"), px, 16384, 65537, 0,
                                                      msg, sizeof msg));
    TEST_ASSERT_NOT_NULL(strstr(msg, "16384 x 65537 is too large"));
    TEST_ASSERT_FALSE(io_file_exists(io_tmp_path("huge.png")));
}

int main(void)
{
    UNITY_BEGIN();
    RUN_TEST(write_ppm_should_write_exact_bytes_from_an_rgba_device);
    RUN_TEST(write_png_should_convert_an_rgb565_device_like_read_pixel);
    RUN_TEST(write_image_should_refuse_unknown_extensions_and_band_devices);
    RUN_TEST(write_image_should_report_a_full_disk_and_refuse_what_stb_cannot_encode);
    return UNITY_END();
}
