/*
 * accuracy.c - `make accuracy`: renders each scene in each mode with mote
 * and with the double-precision reference (tests/ref) and prints a table of
 * the error metrics: coverage mismatches (pixels drawn by one only, next to
 * an edge or not), max and mean absolute channel error, PSNR and the pixels
 * off by more than 1 LSB, over the pixels both drew.
 *
 * Scenes: the built-in test scenes (tests/support/scenes.c), the project's
 * assets/{cube,sphere,torus,demo}.babylon, and ../shared/assets/monkey.babylon when present.
 * The reference is always perspective-correct, with the row's sub-pixel
 * bits and a double depth buffer, so each row shows what its approximation
 * costs against the ideal.
 */
#include <mote/mote.h>
#include <mote/mote_io.h>

#include "ref/ref.h"
#include "support/scenes.h"
#include "support/testutil.h"

#include <stdio.h>
#include <string.h>

#define W 320
#define H 240

typedef struct mode {
    const char *name;
    mote_mode mode;
    mote_filter filter;
    mote_perspective persp;
    int subspan_log2;
    int bits;
    mote_depth_format depth;
    bool textured;                /* needs a texture to differ from Gouraud */
} mode;

static const mode modes[] = {
    {"flat", MOTE_MODE_FLAT, MOTE_FILTER_NEAREST, MOTE_PERSPECTIVE_CORRECT, 0, 8, MOTE_DEPTH_FORMAT_32, false},
    {"Gouraud", MOTE_MODE_GOURAUD, MOTE_FILTER_NEAREST, MOTE_PERSPECTIVE_CORRECT, 0, 8, MOTE_DEPTH_FORMAT_32, false},
    {"Gouraud, 4 sub-pixel bits", MOTE_MODE_GOURAUD, MOTE_FILTER_NEAREST, MOTE_PERSPECTIVE_CORRECT, 0, 4, MOTE_DEPTH_FORMAT_32, false},
    {"Gouraud, 16-bit depth", MOTE_MODE_GOURAUD, MOTE_FILTER_NEAREST, MOTE_PERSPECTIVE_CORRECT, 0, 8, MOTE_DEPTH_FORMAT_16, false},
    {"Gouraud, affine", MOTE_MODE_GOURAUD, MOTE_FILTER_NEAREST, MOTE_PERSPECTIVE_AFFINE, 0, 8, MOTE_DEPTH_FORMAT_32, false},
    {"textured nearest", MOTE_MODE_TEXTURED, MOTE_FILTER_NEAREST, MOTE_PERSPECTIVE_CORRECT, 0, 8, MOTE_DEPTH_FORMAT_32, true},
    {"textured bilinear", MOTE_MODE_TEXTURED, MOTE_FILTER_BILINEAR, MOTE_PERSPECTIVE_CORRECT, 0, 8, MOTE_DEPTH_FORMAT_32, true},
    {"textured bilinear, exact every 8 px", MOTE_MODE_TEXTURED, MOTE_FILTER_BILINEAR, MOTE_PERSPECTIVE_SUBSPAN, 3, 8, MOTE_DEPTH_FORMAT_32, true},
    {"textured bilinear, exact every 32 px", MOTE_MODE_TEXTURED, MOTE_FILTER_BILINEAR, MOTE_PERSPECTIVE_SUBSPAN, 5, 8, MOTE_DEPTH_FORMAT_32, true},
    {"textured bilinear, affine", MOTE_MODE_TEXTURED, MOTE_FILTER_BILINEAR, MOTE_PERSPECTIVE_AFFINE, 0, 8, MOTE_DEPTH_FORMAT_32, true},
};

/* `make accuracy` builds this twice: with the float vertex stage and with
 * the integer one (MOTE_FIXED_VERTEX), whose rows say so */
#if MOTE_FIXED_VERTEX
#define STAGE ", integer vertex"
#else
#define STAGE ""
#endif

static void header(void)
{
    printf("%-30s %-50s %7s %8s %6s %4s %8s %7s %7s %9s\n", "scene", "mode", "drawn", "cov.miss",
           "(off-", "max", "mean", "PSNR", ">1 LSB", "within 1");
    printf("%-30s %-50s %7s %8s %6s %4s %8s %7s %7s %9s\n", "", "", "px", "px", "edge)", "err", "err",
           "dB", "px", "LSB %");
}

static void row(const char *scene, const mode *m, const mote_frame_desc *frame, const mote_mesh *meshes,
                int n, mote_cull cull)
{
    mote_draw_desc d;
    memset(&d, 0, sizeof d);
    d.mode = m->mode;
    d.filter = m->filter;
    d.perspective = m->persp;
    d.subspan_log2 = m->subspan_log2;
    d.cull = cull;
    tu_vs_opts o = {W, H, m->bits, m->depth};
    char name[64];
    snprintf(name, sizeof name, "%s%s", m->name, STAGE);
    tu_vs_result r;
    if (!tu_vs_ref(&o, frame, meshes, n, &d, true, &r, NULL, NULL)) {
        printf("%-30s %-50s (render failed)\n", scene, name);
        return;
    }
    char psnr[16];
    if (r.m.psnr > 1e300)
        snprintf(psnr, sizeof psnr, "inf");
    else
        snprintf(psnr, sizeof psnr, "%.2f", r.m.psnr);
    printf("%-30s %-50s %7ld %8ld %6ld %4d %8.4f %7s %7ld %9.3f\n", scene, name, r.m.covered_b,
           r.m.coverage_mismatch, r.unexplained, r.m.max_err, r.m.mean_err, psnr, r.m.off_by_more_than_1,
           100.0 * r.m.within_1_fraction);
}

static void table(const char *scene, const mote_frame_desc *frame, const mote_mesh *meshes, int n,
                  mote_cull cull)
{
    bool textured = false;
    for (int i = 0; i < n; i++)
        textured |= meshes[i].material.texture != NULL;
    for (size_t k = 0; k < sizeof modes / sizeof modes[0]; k++)
        if (!modes[k].textured || textured)
            row(scene, &modes[k], frame, meshes, n, cull);
}

static void file_scene(const char *path, const char *label)
{
    mote_scene s;
    char message[256];
    mote_limits lim = mote_limits_default();
    lim.missing_texture_is_warning = true;
    if (mote_scene_load(path, &lim, &s, message, sizeof message) != MOTE_OK) {
        printf("%-30s (not loaded: %s)\n", label, message);
        return;
    }
    mote_frame_desc f;
    mote_scene_frame(&s, (float)W / (float)H, &f);
    table(label, &f, s.meshes, s.mesh_count, MOTE_CULL_BACK);
    mote_scene_free(&s);
}

int main(void)
{
    printf("mote against the reference renderer (tests/ref: double precision, exact coverage,\n"
           "perspective-correct, exact bilinear weights), %dx%d. Colour errors are over the pixels\n"
           "both drew; coverage mismatches come from float vs double snapping of vertices and\n"
           "clipped vertices (\"off-edge\" ones are not next to a reference edge and would be bugs).\n\n",
           W, H);
    header();
    for (int k = 0; k < TU_SCENE_COUNT; k++) {
        tu_scene s;
        tu_scene_build(k, MOTE_WRAP_REPEAT, &s);
        table(s.name, &s.frame, s.meshes, s.mesh_count, MOTE_CULL_NONE);
    }
    static const char *assets[] = {"cube", "sphere", "torus", "demo"};
    for (size_t i = 0; i < sizeof assets / sizeof assets[0]; i++) {
        char path[512], label[64];
        snprintf(path, sizeof path, "%s/assets/%s.babylon", MOTE_SOURCE_DIR, assets[i]);
        snprintf(label, sizeof label, "assets/%s.babylon", assets[i]);
        FILE *fp = fopen(path, "rb");
        if (!fp)
            continue;
        fclose(fp);
        file_scene(path, label);
    }
    const char *monkey = MOTE_SOURCE_DIR "/../shared/assets/monkey.babylon";
    FILE *fp = fopen(monkey, "rb");
    if (fp) {
        fclose(fp);
        file_scene(monkey, "monkey.babylon");
    } else {
        printf("monkey.babylon: not present (../shared/assets), skipped\n");
    }
    return 0;
}
