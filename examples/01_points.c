/*
 * 01_points.c - tutorial chapter 1: a camera, a mesh and a device; every
 * vertex of the mesh drawn as one point.
 *
 *   01_points [OUT_DIR]      writes OUT_DIR/01_points.png (default: out)
 *
 * The caller owns every byte mote draws into: here two static buffers, one
 * for colour (RGBA, 4 bytes a pixel) and one for depth.
 */
#define _POSIX_C_SOURCE 200809L   /* mkdir */

#include <mote/mote.h>
#include <mote/mote_io.h>

#include <stdio.h>
#include <sys/stat.h>

#ifndef MOTE_ASSETS
#define MOTE_ASSETS "assets"      /* the build passes the full path */
#endif

enum { W = 640, H = 480 };
static uint8_t color[W * H * 4];
static uint32_t depth[W * H];

int main(int argc, char **argv)
{
    const char *out_dir = argc > 1 ? argv[1] : "out";
    char message[512], path[1024];

    /* Chapter 3 explains the file; here it is only a source of vertices. */
    mote_scene scene;
    if (mote_scene_load(MOTE_ASSETS "/torus.babylon", NULL, &scene, message,
                        sizeof message) != MOTE_OK) {
        fprintf(stderr, "01_points: %s\n", message);
        return 1;
    }
    mote_mesh torus = scene.meshes[0];
    torus.rotation[0] = -0.6f;    /* tip it towards the camera (radians) */

    /* The device: the size and the buffers; zero means "default". */
    mote_device_desc desc = {0};
    desc.width = W;
    desc.height = H;
    desc.color = color;
    desc.depth = depth;
    desc.clear_color = (mote_rgba){16, 18, 24, 255};
    mote_device dev;
    mote_device_init(&dev, &desc);

    /* The camera: the scene's own (eye, target, field of view). */
    mote_frame_desc frame;
    mote_scene_frame(&scene, (float)W / H, &frame);

    /* One frame: begin (clears), draw, end. */
    mote_draw_desc draw = {0};
    draw.mode = MOTE_MODE_POINTS;
    draw.point_color = (mote_rgba){255, 214, 110, 255};
    mote_begin(&dev, &frame);
    mote_draw(&dev, &torus, &draw);
    mote_result r = mote_end(&dev);

    mkdir(out_dir, 0777);         /* may exist already */
    snprintf(path, sizeof path, "%s/01_points.png", out_dir);
    if (r == MOTE_OK)
        r = mote_write_png(path, &dev, message, sizeof message);
    else
        snprintf(message, sizeof message, "rendering: %s", mote_result_string(r));
    if (r != MOTE_OK)
        fprintf(stderr, "01_points: %s\n", message);
    else
        printf("01_points: %u points -> %s\n", torus.vertex_count, path);
    mote_scene_free(&scene);
    return r == MOTE_OK ? 0 : 1;
}
