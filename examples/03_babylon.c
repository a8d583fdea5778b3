/*
 * 03_babylon.c - tutorial chapter 3: meshes from Babylon.js scene files.
 *
 *   03_babylon [OUT_DIR]     writes OUT_DIR/03_babylon.png (default: out)
 *
 * mote_scene_load reads both layouts of a .babylon file: the legacy one the
 * tutorial uses (one interleaved "vertices" array, uvCount telling its
 * stride; texture v = 0 is the top row) and the current one ("positions",
 * "normals", "uvs"; v = 0 is the bottom row). The same torus saved both ways
 * is drawn side by side: the two must look the same, texture included.
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
    static const char *const files[2] = {MOTE_ASSETS "/torus.legacy.babylon",
                                         MOTE_ASSETS "/torus.babylon"};
    char message[512], path[1024];
    mote_scene scenes[2];
    mote_mesh tori[2];

    for (int i = 0; i < 2; i++) {
        /* On failure the message names the file and the place, e.g.
         * "torus.babylon: meshes[0].indices[57]: 9999 is out of range". */
        if (mote_scene_load(files[i], NULL, &scenes[i], message, sizeof message) != MOTE_OK) {
            fprintf(stderr, "03_babylon: %s\n", message);
            if (i == 1)
                mote_scene_free(&scenes[0]);
            return 1;
        }
        printf("03_babylon: %s: %d mesh(es), %u vertices, %u triangles, %d texture(s)\n",
               files[i], scenes[i].mesh_count, scenes[i].meshes[0].vertex_count,
               scenes[i].meshes[0].index_count / 3, scenes[i].texture_count);
        tori[i] = scenes[i].meshes[0];
        tori[i].position[0] = i == 0 ? -1.2f : 1.2f;   /* legacy left, current right */
        tori[i].rotation[0] = -0.5f;
    }

    mote_device_desc desc = {0};
    desc.width = W;
    desc.height = H;
    desc.color = color;
    desc.depth = depth;
    desc.clear_color = scenes[0].clear_color;
    mote_device dev;
    mote_device_init(&dev, &desc);

    /* The file's light (its ambient colour is in the materials), with a
     * camera that fits both tori. */
    mote_frame_desc frame;
    mote_scene_frame(&scenes[0], (float)W / H, &frame);
    frame.camera.position[0] = 0.0f;
    frame.camera.position[1] = 2.0f;
    frame.camera.position[2] = -5.0f;

    mote_begin(&dev, &frame);
    for (int i = 0; i < 2; i++)
        mote_draw(&dev, &tori[i], NULL);   /* NULL: defaults (Gouraud, textured) */
    mote_result r = mote_end(&dev);

    mkdir(out_dir, 0777);
    snprintf(path, sizeof path, "%s/03_babylon.png", out_dir);
    if (r == MOTE_OK)
        r = mote_write_png(path, &dev, message, sizeof message);
    else
        snprintf(message, sizeof message, "rendering: %s", mote_result_string(r));
    if (r != MOTE_OK)
        fprintf(stderr, "03_babylon: %s\n", message);
    else
        printf("03_babylon: -> %s\n", path);
    mote_scene_free(&scenes[0]);
    mote_scene_free(&scenes[1]);
    return r == MOTE_OK ? 0 : 1;
}
