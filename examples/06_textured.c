/*
 * 06_textured.c - tutorial chapter 6: texture mapping and back-face culling.
 *
 *   06_textured [OUT_DIR]    writes OUT_DIR/06_textured.png (default: out)
 *
 * Two cubes and a sphere textured with assets/checker.png (a red square
 * with a white "F" marks the texture's top-left corner: on every side face
 * it must read upright and unmirrored). The left cube comes from the legacy
 * file layout, the right one from the current layout; they must match.
 * Back faces are culled (the default): about half the triangles of a closed
 * mesh face away from the camera and cost nothing past that test.
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
    static const char *const files[3] = {MOTE_ASSETS "/cube.legacy.babylon",
                                         MOTE_ASSETS "/cube.babylon",
                                         MOTE_ASSETS "/sphere.babylon"};
    static const float x[3] = {-1.5f, 1.5f, 0.0f}, z[3] = {0.0f, 0.0f, 1.6f};
    char message[512], path[1024];
    mote_scene scenes[3];
    mote_mesh meshes[3];
    int loaded = 0;

    for (; loaded < 3; loaded++) {
        mote_scene *s = &scenes[loaded];
        if (mote_scene_load(files[loaded], NULL, s, message, sizeof message) != MOTE_OK) {
            fprintf(stderr, "06_textured: %s\n", message);
            break;
        }
        meshes[loaded] = s->meshes[0];   /* material.texture points into *s */
        meshes[loaded].position[0] = x[loaded];
        meshes[loaded].position[2] = z[loaded];
        meshes[loaded].rotation[1] = loaded == 2 ? 0.0f : -0.5f;
    }
    mote_result r = loaded == 3 ? MOTE_OK : MOTE_ERR_IO;

    if (r == MOTE_OK) {
        mote_device_desc desc = {0};
        desc.width = W;
        desc.height = H;
        desc.color = color;
        desc.depth = depth;
        desc.clear_color = scenes[0].clear_color;
        mote_device dev;
        mote_device_init(&dev, &desc);

        mote_frame_desc frame;
        mote_scene_frame(&scenes[0], (float)W / H, &frame);
        frame.camera.position[0] = 0.0f;
        frame.camera.position[1] = 2.4f;
        frame.camera.position[2] = -5.2f;
        frame.camera.target[2] = 0.5f;

        mote_draw_desc draw = {0};
        draw.mode = MOTE_MODE_TEXTURED;   /* Gouraud light x texel */
        draw.filter = MOTE_FILTER_BILINEAR;
        draw.cull = MOTE_CULL_BACK;       /* the default, spelled out */
        mote_begin(&dev, &frame);
        for (int i = 0; i < 3; i++)
            mote_draw(&dev, &meshes[i], &draw);
        r = mote_end(&dev);

        mkdir(out_dir, 0777);
        snprintf(path, sizeof path, "%s/06_textured.png", out_dir);
        if (r == MOTE_OK)
            r = mote_write_png(path, &dev, message, sizeof message);
        else
            snprintf(message, sizeof message, "rendering: %s", mote_result_string(r));
        if (r != MOTE_OK) {
            fprintf(stderr, "06_textured: %s\n", message);
        } else {
            const mote_stats *st = mote_device_stats(&dev);
            printf("06_textured: %u of %u triangles culled as back faces -> %s\n",
                   st->triangles_backface, st->triangles_in, path);
        }
    }
    for (int i = 0; i < loaded; i++)
        mote_scene_free(&scenes[i]);
    return r == MOTE_OK ? 0 : 1;
}
