/*
 * 05_shading.c - tutorial chapter 5: light, flat and Gouraud shading.
 *
 *   05_shading [OUT_DIR]     writes OUT_DIR/05_shading.png (default: out)
 *
 * The same sphere twice under the file's point light. Left, flat: one
 * brightness per triangle, from its own normal at its centre. Right,
 * Gouraud: a brightness per vertex, from the vertex normals, blended
 * across each triangle. Brightness is n.l (clamped at 0) times the light's
 * colour, times the material colour, plus the material's emissive colour
 * (the loader puts the scene's ambient colour there, times the material's
 * ambient), clamped.
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
        fprintf(stderr, "05_shading: %s\n", message);
        return 1;
    }
    mote_mesh left = scene.meshes[0], right = scene.meshes[0];
    left.position[0] = -1.15f;
    right.position[0] = 1.15f;
    /* untextured, a warm white: shading alone */
    left.material = (mote_material){0};
    left.material.color = (mote_rgba){250, 235, 210, 255};
    left.material.color_set = true;
    right.material = left.material;

    mote_device_desc desc = {0};
    desc.width = W;
    desc.height = H;
    desc.color = color;
    desc.depth = depth;
    desc.clear_color = scene.clear_color;
    mote_device dev;
    mote_device_init(&dev, &desc);

    /* The file's point light (its ambient colour is in the materials); a
     * camera facing both spheres. */
    mote_frame_desc frame;
    mote_scene_frame(&scene, (float)W / H, &frame);
    frame.camera.position[0] = 0.0f;
    frame.camera.position[1] = 1.5f;
    frame.camera.position[2] = -4.6f;

    mote_draw_desc flat = {0}, gouraud = {0};
    flat.mode = MOTE_MODE_FLAT;
    gouraud.mode = MOTE_MODE_GOURAUD;
    mote_begin(&dev, &frame);
    mote_draw(&dev, &left, &flat);
    mote_draw(&dev, &right, &gouraud);
    mote_result r = mote_end(&dev);

    mkdir(out_dir, 0777);
    snprintf(path, sizeof path, "%s/05_shading.png", out_dir);
    if (r == MOTE_OK)
        r = mote_write_png(path, &dev, message, sizeof message);
    else
        snprintf(message, sizeof message, "rendering: %s", mote_result_string(r));
    if (r != MOTE_OK)
        fprintf(stderr, "05_shading: %s\n", message);
    else
        printf("05_shading: flat (left), gouraud (right) -> %s\n", path);
    mote_scene_free(&scene);
    return r == MOTE_OK ? 0 : 1;
}
