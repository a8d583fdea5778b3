/*
 * 04_filled.c - tutorial chapter 4: filled triangles and a depth buffer.
 *
 *   04_filled [OUT_DIR]      writes OUT_DIR/04_filled.png (default: out)
 *
 * A torus runs through a sphere. Both are drawn in one flat colour each
 * (unlit), so the only thing that tells them apart is the depth test: each
 * pixel keeps the nearest surface, and the curve where they cut each other
 * comes out exact whatever the drawing order.
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
static uint32_t depth[W * H];   /* 24-bit depth, 0 = near, cleared to far */

int main(int argc, char **argv)
{
    const char *out_dir = argc > 1 ? argv[1] : "out";
    char message[512], path[1024];
    mote_scene torus_file, sphere_file;

    if (mote_scene_load(MOTE_ASSETS "/torus.babylon", NULL, &torus_file, message,
                        sizeof message) != MOTE_OK) {
        fprintf(stderr, "04_filled: %s\n", message);
        return 1;
    }
    if (mote_scene_load(MOTE_ASSETS "/sphere.babylon", NULL, &sphere_file, message,
                        sizeof message) != MOTE_OK) {
        fprintf(stderr, "04_filled: %s\n", message);
        mote_scene_free(&torus_file);
        return 1;
    }
    /* Copies of the loaded meshes with our own pose and a plain colour. */
    mote_mesh torus = torus_file.meshes[0], sphere = sphere_file.meshes[0];
    /* tilted so that its near side passes in front of the sphere and its
     * far side behind it */
    torus.rotation[0] = -0.45f;
    torus.rotation[2] = 0.35f;
    torus.material = (mote_material){0};
    torus.material.color = (mote_rgba){240, 140, 40, 255};
    torus.material.color_set = true;
    for (int k = 0; k < 3; k++)
        sphere.scaling[k] = 0.7f;
    sphere.material = (mote_material){0};
    sphere.material.color = (mote_rgba){60, 130, 220, 255};
    sphere.material.color_set = true;

    mote_device_desc desc = {0};
    desc.width = W;
    desc.height = H;
    desc.color = color;
    desc.depth = depth;
    desc.clear_color = (mote_rgba){16, 18, 24, 255};
    mote_device dev;
    mote_device_init(&dev, &desc);

    mote_frame_desc frame;
    mote_scene_frame(&torus_file, (float)W / H, &frame);

    mote_draw_desc draw = {0};
    draw.mode = MOTE_MODE_FLAT;
    draw.unlit = true;            /* the material colour as it is: no lights */
    mote_begin(&dev, &frame);
    mote_draw(&dev, &torus, &draw);
    mote_draw(&dev, &sphere, &draw);
    mote_result r = mote_end(&dev);

    mkdir(out_dir, 0777);
    snprintf(path, sizeof path, "%s/04_filled.png", out_dir);
    if (r == MOTE_OK)
        r = mote_write_png(path, &dev, message, sizeof message);
    else
        snprintf(message, sizeof message, "rendering: %s", mote_result_string(r));
    if (r != MOTE_OK) {
        fprintf(stderr, "04_filled: %s\n", message);
    } else {
        const mote_stats *st = mote_device_stats(&dev);
        printf("04_filled: %u triangles drawn, %llu of %llu pixels passed the depth test -> %s\n",
               st->triangles_drawn, (unsigned long long)st->pixels_written,
               (unsigned long long)st->pixels_tested, path);
    }
    mote_scene_free(&sphere_file);
    mote_scene_free(&torus_file);
    return r == MOTE_OK ? 0 : 1;
}
