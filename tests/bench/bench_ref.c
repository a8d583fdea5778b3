/*
 * bench_ref.c - the benchmark's bridge to the reference renderer
 * (tests/ref): reference images and error metrics. Built only when
 * tests/ref/ exists; otherwise bench.c measures against mote itself.
 */
#include "bench.h"
#include "ref/ref.h"

#include <stdio.h>
#include <string.h>

const char *bench_ref_render(bench_scene *s, const bench_mode *m, int f, uint8_t *rgba, uint8_t *cov)
{
    ref_target t;
    /* the ideal: 8-bit subpixel, double depth, per-pixel perspective */
    if (!ref_target_init(&t, s->width, s->height, 8)) {
        fprintf(stderr, "bench: ref_target_init failed (out of memory?)\n");
        memset(rgba, 0, (size_t)s->width * (size_t)s->height * 4);
        memset(cov, 0, (size_t)s->width * (size_t)s->height);
        return "none (reference renderer failed)";
    }
    mote_draw_desc d = m->draw;
    d.perspective = MOTE_PERSPECTIVE_CORRECT;
    bench_pose(s, f);
    ref_begin(&t, &s->frame, s->clear_color);
    for (int i = 0; i < s->mesh_count; i++)
        ref_draw(&t, &s->meshes[i], &d);
    size_t n = (size_t)s->width * (size_t)s->height;
    memcpy(rgba, t.rgba, n * 4);
    for (size_t i = 0; i < n; i++)
        cov[i] = t.cov[i] != 0;
    ref_target_free(&t);
    return "tests/ref (double precision, per-pixel perspective, 8-bit subpixel, exact bilinear weights)";
}

bench_err bench_ref_compare(const uint8_t *a, const uint8_t *ca, const uint8_t *b, const uint8_t *cb,
                            int w, int h)
{
    ref_metrics r = ref_compare(a, ca, b, cb, w, h);
    bench_err e;
    e.valid = true;
    e.psnr = r.psnr_image;
    e.max_err = r.max_err;
    e.mismatch = r.coverage_mismatch;
    return e;
}
