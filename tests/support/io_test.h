/*
 * io_test.h - what the tests of src/io share: the headers they include, a
 * start for setUp, scenes loaded from JSON text (the test fails with the
 * loader's message when one does not load), a scratch folder, small
 * devices to draw on.
 */
#ifndef MOTE_IO_TEST_H
#define MOTE_IO_TEST_H

#include <mote/mote.h>
#include <mote/mote_io.h>
#include "io/io_internal.h"
#include "unity.h"

#include <math.h>
#include <stdbool.h>
#include <stdint.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>

#define DATA(name) MOTE_SOURCE_DIR "/tests/data/" name

/* one triangle's geometry, for scenes written inline */
#define TRI "\"positions\":[0,0,0, 1,0,0, 0,1,0],\"indices\":[0,1,2]"

#define ASSERT_VEC3(x, y, z, v, tol)               \
    do {                                           \
        TEST_ASSERT_FLOAT_WITHIN(tol, x, (v)[0]);  \
        TEST_ASSERT_FLOAT_WITHIN(tol, y, (v)[1]);  \
        TEST_ASSERT_FLOAT_WITHIN(tol, z, (v)[2]);  \
    } while (0)

/* For setUp: failure injection off (mote__io_set_alloc_failure_after);
 * returns the allocations alive now, for a test to compare at its end. */
long io_test_begin(void);

/* The fixture of a loader's tests: live_before, the allocations alive
 * when a test starts (to compare at its end), and msg, a loader message
 * buffer emptied for each test; Unity's setUp and tearDown with failure
 * injection off. At file scope, in a test file that needs no more. */
#define IO_TEST_FIXTURE                                                  \
    static long live_before;                                             \
    static char msg[512];                                                \
    void setUp(void)                                                     \
    {                                                                    \
        live_before = io_test_begin();                                   \
        msg[0] = '\0';                                                   \
    }                                                                    \
    void tearDown(void)                                                  \
    {                                                                    \
        mote__io_set_alloc_failure_after(-1);                            \
    }

/* Loads a scene from JSON text with its textures in folder dir (NULL: no
 * folder, colours only), or fails the test with the loader's message. */
void io_load_json_in(const char *json, const char *name, const char *dir, mote_scene *s);
void io_load_json(const char *json, const char *name, mote_scene *s);

/* A folder for the files a test writes, made on first use and removed when
 * the program exits; io_tmp_path gives a path in it (in a buffer the next
 * call overwrites). */
const char *io_tmp_dir(void);
const char *io_tmp_path(const char *name);
bool io_file_exists(const char *path);

/* A width x height RGBA device without depth. */
void io_init_color_device(mote_device *dev, uint8_t *color, int width, int height);
/* A size x size RGBA device without depth, its frame begun, the camera at
 * z = -3 looking at the origin. */
void io_begin_small_frame(mote_device *dev, uint8_t *color, int size);

/* Draws a loaded scene as mote-render does (its camera and lights, or the
 * framing ones; its draw options) into width x height RGBA pixels, with
 * a 32-bit depth buffer. */
void io_render_scene(const mote_scene *s, uint8_t *rgba, int width, int height);

/* Where a mesh's origin lands in the world. */
void io_world_origin(const mote_mesh *m, float out[3]);

#endif
