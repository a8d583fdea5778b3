/*
 * 02_wireframe.c - tutorial chapter 2: the triangles' edges as lines
 * (the tutorial's Bresenham lines; mote clips them to the image and draws
 * each pixel once).
 *
 *   02_wireframe [OUT_DIR]   writes OUT_DIR/02_wireframe.png (default: out)
 *
 * Back faces are culled, as in every mode, so only the near side's edges
 * show; set draw.cull = MOTE_CULL_NONE to see through the mesh.
 */
#define _POSIX_C_SOURCE 200809L   /* mkdir */

#include <mote/mote.h>
#include <mote/mote_io.h>

#include <stdio.h>
#include <sys/stat.h>

#ifndef MOTE_ASSETS
#define MOTE_ASSETS "assets"
#endif

enum { W = 640, H = 480 };
static uint8_t color[W * H * 4];
static uint32_t depth[W * H];

int main(int argc, char **argv)
{
    const char *out_dir = argc > 1 ? argv[1] : "out";
    char message[512], path[1024];

    mote_scene scene;
    if (mote_scene_load(MOTE_ASSETS "/sphere.babylon", NULL, &scene, message,
                        sizeof message) != MOTE_OK) {
        fprintf(stderr, "02_wireframe: %s\n", message);
        return 1;
    }
    /* A mesh is plain data: turn it by setting its Euler angles (radians,
     * applied z, then x, then y, as Babylon does). */
    mote_mesh sphere = scene.meshes[0];
    sphere.rotation[0] = 0.4f;
    sphere.rotation[1] = 0.3f;

    mote_device_desc desc = {0};
    desc.width = W;
    desc.height = H;
    desc.color = color;
    desc.depth = depth;
    desc.clear_color = (mote_rgba){16, 18, 24, 255};
    mote_device dev;
    mote_device_init(&dev, &desc);

    mote_frame_desc frame;
    mote_scene_frame(&scene, (float)W / H, &frame);

    mote_draw_desc draw = {0};
    draw.mode = MOTE_MODE_WIREFRAME;
    draw.point_color = (mote_rgba){120, 220, 255, 255};   /* the line colour */
    mote_begin(&dev, &frame);
    mote_draw(&dev, &sphere, &draw);
    mote_result r = mote_end(&dev);

    mkdir(out_dir, 0777);
    snprintf(path, sizeof path, "%s/02_wireframe.png", out_dir);
    if (r == MOTE_OK)
        r = mote_write_png(path, &dev, message, sizeof message);
    else
        snprintf(message, sizeof message, "rendering: %s", mote_result_string(r));
    if (r != MOTE_OK)
        fprintf(stderr, "02_wireframe: %s\n", message);
    else
        printf("02_wireframe: %u triangles -> %s\n", sphere.index_count / 3, path);
    mote_scene_free(&scene);
    return r == MOTE_OK ? 0 : 1;
}
