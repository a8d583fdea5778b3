/*
 * test_common.c - the host I/O helpers (src/io/common.c): file reading.
 */
#define _POSIX_C_SOURCE 200809L /* mkfifo, alarm */
#include "support/io_test.h"

#include <sys/stat.h>
#include <unistd.h>

static char msg[512];
static long live_before;

void setUp(void)
{
    msg[0] = '\0';
    live_before = io_test_begin();
}

void tearDown(void) {}

/* A path naming a FIFO, a directory or a device is refused before it is
 * opened: fopen on a FIFO waits for a writer, and /dev/zero would be read
 * up to the size limit. */
void file_reading_should_refuse_a_fifo_a_directory_and_a_device(void)
{
#if defined(__unix__) || defined(__APPLE__)
    char fifo[512];
    snprintf(fifo, sizeof fifo, "%s", io_tmp_path("fifo.png"));
    TEST_ASSERT_EQUAL_MESSAGE(0, mkfifo(fifo, 0600), fifo);
    alarm(30);                    /* before the check, the open never returned */
    mote_texture t;
    TEST_ASSERT_EQUAL(MOTE_ERR_IO, mote_texture_load(fifo, NULL, &t, msg, sizeof msg));
    TEST_ASSERT_NOT_NULL_MESSAGE(strstr(msg, "fifo.png: cannot open: a FIFO, not a regular file"),
                                 msg);
    mote_scene s;
    TEST_ASSERT_EQUAL(MOTE_ERR_IO, mote_scene_load(fifo, NULL, &s, msg, sizeof msg));
    const char *j = "{\"materials\":[{\"id\":\"m\",\"diffuseTexture\":{\"name\":\"fifo.png\"}}]}";
    TEST_ASSERT_EQUAL(MOTE_ERR_IO, mote_scene_load_memory(j, strlen(j), "f", io_tmp_dir(), NULL, &s,
                                                          msg, sizeof msg));
    TEST_ASSERT_NOT_NULL_MESSAGE(strstr(msg, "f: materials[0].diffuseTexture.name: "), msg);
    TEST_ASSERT_NOT_NULL_MESSAGE(strstr(msg, "a FIFO, not a regular file"), msg);
    alarm(0);
    TEST_ASSERT_EQUAL(MOTE_ERR_IO, mote_texture_load(io_tmp_dir(), NULL, &t, msg, sizeof msg));
    TEST_ASSERT_NOT_NULL_MESSAGE(strstr(msg, "a directory, not a regular file"), msg);
    TEST_ASSERT_EQUAL(MOTE_ERR_IO, mote_texture_load("/dev/null", NULL, &t, msg, sizeof msg));
    TEST_ASSERT_EQUAL_STRING("/dev/null: cannot open: a device, not a regular file", msg);
    TEST_ASSERT_EQUAL(live_before, mote__io_live_allocations());
#else
    TEST_IGNORE_MESSAGE("no FIFOs or devices to test with here");
#endif
}

int main(void)
{
    UNITY_BEGIN();
    RUN_TEST(file_reading_should_refuse_a_fifo_a_directory_and_a_device);
    return UNITY_END();
}
