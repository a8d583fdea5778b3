/*
 * bench.c - `make bench`: mote's speed against its error, per mode, beside
 * Mesa's llvmpipe (OSMesa) on the same scenes, with thread scaling and the
 * measured saving of each "skip what a scene doesn't need" shortcut.
 *
 * Scenes: Suzanne (../shared/assets/monkey.babylon + Suzanne.jpg) rotating
 * at 640x480 and 1920x1080, a 10x10 grid of them at 1920x1080, and a
 * fill-heavy stack of screen-covering quads (overdraw 6). Without
 * ../shared the monkey is replaced by a generated torus of 966 triangles.
 *
 * Timing: CLOCK_MONOTONIC around mote_begin..mote_end (llvmpipe: around
 * the whole GL frame including glFinish, which leaves the image in the
 * caller's buffer), after 2 warm-up frames; each run stops at the frames
 * asked for or after --cap seconds, and prints how many it timed.
 *
 * Error: one frame (BENCH_ERR_FRAME) of every configuration against a
 * reference image: PSNR over RGB of the whole image, largest channel
 * difference over pixels both cover, and pixels covered by one but not the
 * other (coverage from the depth buffers).
 *
 * Output: fixed-width tables on stdout, out/bench/bench.csv, bench.md
 * (markdown, for docs/performance.md) and pareto.dat/pareto_front.dat, which
 * tests/bench/pareto.gp turns into pareto.png.
 */
#ifdef __linux__
#define _GNU_SOURCE               /* sched_setaffinity: the single-thread core */
#else
#define _POSIX_C_SOURCE 200809L
#endif
#include "bench.h"

#include <errno.h>
#include <math.h>
#include <stdarg.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>
#include <sys/stat.h>
#include <time.h>
#include <unistd.h>
#ifdef __linux__
#include <sched.h>
#include <signal.h>
#include <sys/prctl.h>
#include <sys/wait.h>
#endif

#ifdef _OPENMP
#include <omp.h>
#endif

#define BENCH_PI 3.14159265358979f
#define BENCH_ERR_FRAME 20
#define BENCH_WARMUP 2
#define BENCH_MAX_FRAMES 1000

/* ---- options and small helpers ---------------------------------------- */

static struct {
    const char *out_dir;
    const char *assets;
    double cap_s;                 /* seconds per timed run at most */
    int frames;                   /* frames per run (grid and fill: see scenes) */
    int max_threads;
    bool dump;                    /* write the error frames as PPM */
    const char *scene;            /* only scenes whose name starts so (profiling) */
    const char *mode;             /* only this mode, mote only, no other section (profiling) */
    const char *only;             /* only this section after the modes: threads, contention */
} opt = {"out/bench", NULL, 2.0, 100, 0, false, NULL, NULL, NULL};

/* The 1-minute load average: other work on the machine skews timings. */
static double bench_load(void)
{
    double l = -1.0;
    FILE *f = fopen("/proc/loadavg", "r");
    if (f) {
        if (fscanf(f, "%lf", &l) != 1)
            l = -1.0;
        fclose(f);
    }
    return l;
}

/* The processor's name (Linux: /proc/cpuinfo's first "model name"), or
 * "unknown processor": llvmpipe's time against mote's moves with it. */
static void bench_cpu_name(char *out, size_t size)
{
    snprintf(out, size, "unknown processor");
    FILE *f = fopen("/proc/cpuinfo", "r");
    if (!f)
        return;
    char line[256];
    while (fgets(line, sizeof line, f)) {
        char *colon = strchr(line, ':');
        if (strncmp(line, "model name", 10) != 0 || !colon)
            continue;
        colon += 1 + (colon[1] == ' ');
        colon[strcspn(colon, "\n")] = 0;
        if (*colon)
            snprintf(out, size, "%s", colon);
        break;
    }
    fclose(f);
}

static double bench_now(void)
{
    struct timespec ts;
    clock_gettime(CLOCK_MONOTONIC, &ts);
    return (double)ts.tv_sec + (double)ts.tv_nsec * 1e-9;
}

/* ---- the core for single-thread timings ---------------------------------
 * On the shared VM one core has run 1.3x slower than the other for hours
 * (a neighbour on its physical core, presumably): single-thread runs that
 * the scheduler moves between cores swing with it, and a 1-thread baseline
 * that lands on the slow core makes 2 threads look more than twice as
 * fast. So the benchmark first times each core alone (check_cores), runs
 * every single-thread timing pinned to the fastest, and prints the cores'
 * speeds beside the thread scaling. Multi-thread runs use every core. */

#define BENCH_MAX_CPUS 64
static int fast_cpu = -1;         /* -1: not pinned (not Linux, or one core) */
#ifdef __linux__
static cpu_set_t start_cpus;      /* the mask the process started with */
static int pinned_cpu = -1;

/* Runs the calling thread on cpu alone (-1: on every core it started with). */
static void bench_pin(int cpu)
{
    if (cpu == pinned_cpu)
        return;
    cpu_set_t set = start_cpus;
    if (cpu >= 0) {
        CPU_ZERO(&set);
        CPU_SET(cpu, &set);
    }
    if (sched_setaffinity(0, sizeof set, &set) == 0)
        pinned_cpu = cpu;
}

/* The cores the process may run on, at most max; 0 when unknown. */
static int bench_cpus(int ids[], int max)
{
    if (sched_getaffinity(0, sizeof start_cpus, &start_cpus) != 0)
        return 0;
    int n = 0;
    for (int c = 0; c < CPU_SETSIZE && n < max; c++)
        if (CPU_ISSET(c, &start_cpus))
            ids[n++] = c;
    return n;
}

/* A process spinning on cpu, which dies with this one: another program
 * busy on one of the cores. 0 when it could not be started. */
static pid_t bench_busy_start(int cpu)
{
    pid_t pid = fork();
    if (pid == 0) {
        prctl(PR_SET_PDEATHSIG, SIGKILL);
        bench_pin(cpu);
        for (volatile unsigned long i = 0;; i++)
            ;
    }
    return pid > 0 ? pid : 0;
}

static void bench_busy_stop(pid_t pid)
{
    if (pid > 0) {
        kill(pid, SIGKILL);
        waitpid(pid, NULL, 0);
    }
}
#else
static int pinned_cpu = -1;
static void bench_pin(int cpu) { (void)cpu; }
static int bench_cpus(int ids[], int max) { (void)ids; (void)max; return 0; }
static pid_t bench_busy_start(int cpu) { (void)cpu; return 0; }
static void bench_busy_stop(pid_t pid) { (void)pid; }
#endif

static void *bench_alloc(size_t n)
{
    void *p = calloc(1, n ? n : 1);
    if (!p) {
        fprintf(stderr, "bench: out of memory (%zu bytes)\n", n);
        exit(1);
    }
    return p;
}

/* Copies src into dst[n], cut to fit (snprintf would warn about the cut). */
static void copy_str(char *dst, size_t n, const char *src)
{
    size_t len = strlen(src);
    if (len >= n)
        len = n - 1;
    memcpy(dst, src, len);
    dst[len] = 0;
}

static int bench_cmp_double(const void *a, const void *b)
{
    double x = *(const double *)a, y = *(const double *)b;
    return x < y ? -1 : x > y;
}

/* ---- tables: printed fixed-width and written as markdown --------------- */

#define TBL_COLS 14
#define TBL_ROWS 96
#define TBL_CELL 112

typedef struct bench_table {
    char title[160];
    int cols, rows;
    char head[TBL_COLS][TBL_CELL];
    char cell[TBL_ROWS][TBL_COLS][TBL_CELL];
    char note[1024];
} bench_table;

static bench_table *tbl_new(const char *title, const char *heads)
{
    bench_table *t = bench_alloc(sizeof *t);
    copy_str(t->title, sizeof t->title, title);
    char buf[512];
    copy_str(buf, sizeof buf, heads);
    for (char *h = strtok(buf, "|"); h && t->cols < TBL_COLS; h = strtok(NULL, "|"))
        copy_str(t->head[t->cols++], TBL_CELL, h);
    return t;
}

static void tbl_row(bench_table *t, const char *fmt, ...)
{
    if (t->rows >= TBL_ROWS)
        return;
    char buf[TBL_COLS * TBL_CELL];
    va_list ap;
    va_start(ap, fmt);
    vsnprintf(buf, sizeof buf, fmt, ap);
    va_end(ap);
    int c = 0;
    char *p = buf;
    while (c < t->cols) {
        char *bar = strchr(p, '|');
        if (bar)
            *bar = 0;
        copy_str(t->cell[t->rows][c++], TBL_CELL, p);
        if (!bar)
            break;
        p = bar + 1;
    }
    t->rows++;
}

static void tbl_note(bench_table *t, const char *fmt, ...)
{
    size_t len = strlen(t->note);
    va_list ap;
    va_start(ap, fmt);
    vsnprintf(t->note + len, sizeof t->note - len, fmt, ap);
    va_end(ap);
}

static void tbl_print(const bench_table *t, FILE *f, bool md)
{
    int w[TBL_COLS];
    for (int c = 0; c < t->cols; c++) {
        w[c] = (int)strlen(t->head[c]);
        for (int r = 0; r < t->rows; r++)
            if ((int)strlen(t->cell[r][c]) > w[c])
                w[c] = (int)strlen(t->cell[r][c]);
    }
    if (md) {
        fprintf(f, "### %s\n\n|", t->title);
        for (int c = 0; c < t->cols; c++)
            fprintf(f, " %s |", t->head[c]);
        fprintf(f, "\n|");
        for (int c = 0; c < t->cols; c++)
            fprintf(f, "%s|", c < 2 ? "---" : "---:");
        fprintf(f, "\n");
        for (int r = 0; r < t->rows; r++) {
            fprintf(f, "|");
            for (int c = 0; c < t->cols; c++)
                fprintf(f, " %s |", t->cell[r][c]);
            fprintf(f, "\n");
        }
        if (t->note[0])
            fprintf(f, "\n%s\n", t->note);
        fprintf(f, "\n");
        return;
    }
    fprintf(f, "\n== %s\n", t->title);
    for (int c = 0; c < t->cols; c++)
        fprintf(f, c < 2 ? "%-*s  " : "%*s  ", w[c], t->head[c]);
    fprintf(f, "\n");
    for (int c = 0; c < t->cols; c++) {
        for (int i = 0; i < w[c]; i++)
            fputc('-', f);
        fputs("  ", f);
    }
    fprintf(f, "\n");
    for (int r = 0; r < t->rows; r++) {
        for (int c = 0; c < t->cols; c++)
            fprintf(f, c < 2 ? "%-*s  " : "%*s  ", w[c], t->cell[r][c]);
        fprintf(f, "\n");
    }
    if (t->note[0])
        fprintf(f, "%s\n", t->note);
    fflush(f);
}

/* ---- scenes ------------------------------------------------------------ */

void bench_pose(bench_scene *s, int f)
{
    for (int i = 0; i < s->mesh_count; i++)
        for (int k = 0; k < 3; k++)
            s->meshes[i].rotation[k] = s->base_rotation[3 * i + k] + (float)f * s->spin[3 * i + k];
}

static void scene_alloc_meshes(bench_scene *s, int n)
{
    s->mesh_count = n;
    s->meshes = bench_alloc(sizeof *s->meshes * (size_t)n);
    s->base_rotation = bench_alloc(sizeof(float) * 3 * (size_t)n);
    s->spin = bench_alloc(sizeof(float) * 3 * (size_t)n);
}

static void scene_finish(bench_scene *s)
{
    s->triangles = 0;
    for (int i = 0; i < s->mesh_count; i++) {
        mote_mesh_update_bounds(&s->meshes[i]);
        s->triangles += s->meshes[i].index_count / 3;
        for (int k = 0; k < 3; k++)
            s->base_rotation[3 * i + k] = s->meshes[i].rotation[k];
    }
}

static void scene_free(bench_scene *s)
{
    if (s->has_loaded)
        mote_scene_free(&s->loaded);
    free(s->meshes);
    free(s->base_rotation);
    free(s->spin);
    free(s->gen_vertices);
    free(s->gen_indices);
    free(s->gen_texels);
    memset(s, 0, sizeof *s);
}

/* A checkerboard with colour ramps: 256x256 RGBA, power of two. */
static void gen_texture(bench_scene *s)
{
    const int n = 256;
    s->gen_texels = bench_alloc((size_t)n * n * 4);
    for (int y = 0; y < n; y++)
        for (int x = 0; x < n; x++) {
            uint8_t *p = s->gen_texels + ((size_t)y * n + (size_t)x) * 4;
            bool dark = ((x >> 5) ^ (y >> 5)) & 1;
            p[0] = (uint8_t)(dark ? x / 2 : 255 - x / 4);
            p[1] = (uint8_t)(dark ? y / 2 : 255 - y / 4);
            p[2] = (uint8_t)(dark ? 40 : 200);
            p[3] = 255;
        }
    s->gen_texture.width = n;
    s->gen_texture.height = n;
    s->gen_texture.format = MOTE_FORMAT_RGBA8888;
    s->gen_texture.stride = n * 4; /* explicit: the core reads stride as given (0 is documented as the default) */
    s->gen_texture.pixels = s->gen_texels;
}

/* Torus of 23 x 21 quads = 966 triangles, the monkey's count. Front faces
 * run counter-clockwise on screen seen from outside (check_winding). */
static mote_mesh gen_torus(bench_scene *s)
{
    const int nu = 23, nv = 21;
    const float R = 1.0f, r = 0.45f;
    size_t nvert = (size_t)(nu + 1) * (size_t)(nv + 1);
    s->gen_vertices = bench_alloc(sizeof(mote_vertex) * nvert);
    s->gen_indices = bench_alloc(sizeof(uint32_t) * 6 * (size_t)nu * (size_t)nv);
    for (int i = 0; i <= nu; i++)
        for (int j = 0; j <= nv; j++) {
            float a = 2.0f * BENCH_PI * (float)i / (float)nu, b = 2.0f * BENCH_PI * (float)j / (float)nv;
            mote_vertex *v = &s->gen_vertices[i * (nv + 1) + j];
            float ca = cosf(a), sa = sinf(a), cb = cosf(b), sb = sinf(b);
            v->position[0] = (R + r * cb) * ca;
            v->position[1] = r * sb;
            v->position[2] = (R + r * cb) * sa;
            v->normal[0] = cb * ca;
            v->normal[1] = sb;
            v->normal[2] = cb * sa;
            v->uv[0] = 2.0f * (float)i / (float)nu;
            v->uv[1] = (float)j / (float)nv;
        }
    uint32_t *ix = s->gen_indices;
    for (int i = 0; i < nu; i++)
        for (int j = 0; j < nv; j++) {
            uint32_t a = (uint32_t)(i * (nv + 1) + j), b = (uint32_t)((i + 1) * (nv + 1) + j);
            uint32_t c = b + 1, d = a + 1;
            *ix++ = a; *ix++ = b; *ix++ = c;
            *ix++ = a; *ix++ = c; *ix++ = d;
        }
    mote_mesh m;
    memset(&m, 0, sizeof m);
    m.vertices = s->gen_vertices;
    m.vertex_count = (uint32_t)nvert;
    m.indices = s->gen_indices;
    m.index_count = (uint32_t)(6 * nu * nv);
    m.rotation[0] = 0.9f;         /* tilted towards the camera */
    m.material.texture = &s->gen_texture;
    return m;
}

static void default_frame(bench_scene *s, const float eye[3], const float target[3])
{
    memset(&s->frame, 0, sizeof s->frame);
    for (int k = 0; k < 3; k++) {
        s->frame.camera.position[k] = eye[k];
        s->frame.camera.target[k] = target[k];
    }
    s->frame.camera.fov = 0.8576f;
    s->frame.camera.znear = 0.1f;
    s->frame.camera.zfar = 200.0f;
    s->frame.light_count = 1;
    s->frame.lights[0].type = MOTE_LIGHT_POINT;
    s->frame.lights[0].position[0] = eye[0] + 4.0f;
    s->frame.lights[0].position[1] = eye[1] + 10.0f;
    s->frame.lights[0].position[2] = eye[2];
    s->frame.ambient[0] = s->frame.ambient[1] = s->frame.ambient[2] = 0.1f;
}

/* Suzanne from the seed's assets, or the torus. grid: 10x10 copies;
 * offscreen: the grid seen from close to its corner (most meshes outside). */
typedef enum { SCENE_ONE, SCENE_GRID, SCENE_OFFSCREEN } scene_layout;

static bool scene_model(bench_scene *s, const char *name, int w, int h, scene_layout layout,
                        bool use_assets)
{
    memset(s, 0, sizeof *s);
    copy_str(s->name, sizeof s->name, name);
    s->width = w;
    s->height = h;
    s->frames = opt.frames;
    mote_mesh proto[8];
    int nproto = 0;
    if (use_assets) {
        char path[1024], msg[512];
        snprintf(path, sizeof path, "%s/monkey.babylon", opt.assets);
        mote_result r = mote_scene_load(path, NULL, &s->loaded, msg, sizeof msg);
        if (r != MOTE_OK) {
            fprintf(stderr, "bench: %s: %s (%s)\n", path, mote_result_string(r), msg);
            return false;
        }
        s->has_loaded = true;
        mote_scene_frame(&s->loaded, (float)w / (float)h, &s->frame);
        s->clear_color = s->loaded.clear_color;
        nproto = s->loaded.mesh_count < 8 ? s->loaded.mesh_count : 8;
        for (int i = 0; i < nproto; i++)
            proto[i] = s->loaded.meshes[i];
    } else {
        gen_texture(s);
        proto[0] = gen_torus(s);
        nproto = 1;
        const float eye[3] = {0.0f, 1.2f, -3.6f}, target[3] = {0, 0, 0};
        default_frame(s, eye, target);
    }
    if (layout == SCENE_ONE) {
        scene_alloc_meshes(s, nproto);
        for (int i = 0; i < nproto; i++) {
            s->meshes[i] = proto[i];
            s->spin[3 * i + 1] = 2.0f * BENCH_PI / 100.0f;   /* one turn in 100 frames */
        }
    } else {
        scene_alloc_meshes(s, 100 * nproto);
        const float dx = 2.6f, dy = 2.2f;
        for (int j = 0; j < 10; j++)
            for (int i = 0; i < 10; i++)
                for (int p = 0; p < nproto; p++) {
                    int k = (j * 10 + i) * nproto + p;
                    s->meshes[k] = proto[p];
                    s->meshes[k].position[0] = ((float)i - 4.5f) * dx;
                    s->meshes[k].position[1] = ((float)j - 4.5f) * dy;
                    s->meshes[k].position[2] = 0.0f;
                    s->meshes[k].rotation[1] = 0.1f * (float)(j * 10 + i); /* not all alike */
                    s->spin[3 * k + 1] = 2.0f * BENCH_PI / 100.0f;
                }
        /* the models face -z: look from there (torus: from above-front) */
        float eye[3] = {0.0f, use_assets ? 0.0f : 6.0f, -27.0f}, target[3] = {0, 0, 0};
        if (layout == SCENE_OFFSCREEN) {
            target[0] = -4.5f * dx;
            target[1] = -4.5f * dy;
            eye[0] = target[0];
            eye[1] = target[1] + (use_assets ? 0.0f : 1.5f);
            eye[2] = -4.0f;
        }
        mote_frame_desc keep = s->frame;
        default_frame(s, eye, target);
        if (use_assets)
            s->frame.ambient[0] = keep.ambient[0], s->frame.ambient[1] = keep.ambient[1],
            s->frame.ambient[2] = keep.ambient[2];
    }
    scene_finish(s);
    return true;
}

/* The like-for-like scene, described so any renderer can draw it: Suzanne
 * centred and scaled to height 2, the camera 4.054 away on -z, vertical
 * fov 0.78 rad, textured with one white directional light per vertex
 * (I = 0.2 + 0.8 max(0, N.L)), turning 3.6 degrees a frame; the grid is
 * 10x10 of it seen from 31.9 away with near/far 20/50. Other renderers are
 * timed on exactly this scene (docs/performance.md). */
static bool scene_like_for_like(bench_scene *s, const char *name, int w, int h, bool grid)
{
    memset(s, 0, sizeof *s);
    copy_str(s->name, sizeof s->name, name);
    s->width = w;
    s->height = h;
    s->frames = opt.frames;
    char path[1024], msg[512];
    snprintf(path, sizeof path, "%s/monkey.babylon", opt.assets);
    mote_result r = mote_scene_load(path, NULL, &s->loaded, msg, sizeof msg);
    if (r != MOTE_OK || s->loaded.mesh_count < 1) {
        fprintf(stderr, "bench: %s: %s (%s)\n", path, mote_result_string(r), msg);
        return false;
    }
    s->has_loaded = true;
    const mote_mesh *src = &s->loaded.meshes[0];
    /* the vertices moved and scaled once, so the model turns about its centre */
    s->gen_vertices = bench_alloc(sizeof(mote_vertex) * src->vertex_count);
    float lo[3] = {INFINITY, INFINITY, INFINITY}, hi[3] = {-INFINITY, -INFINITY, -INFINITY};
    for (uint32_t i = 0; i < src->vertex_count; i++)
        for (int k = 0; k < 3; k++) {
            lo[k] = fminf(lo[k], src->vertices[i].position[k]);
            hi[k] = fmaxf(hi[k], src->vertices[i].position[k]);
        }
    const float scale = 2.0f / (hi[1] - lo[1]);
    for (uint32_t i = 0; i < src->vertex_count; i++) {
        s->gen_vertices[i] = src->vertices[i];
        for (int k = 0; k < 3; k++)
            s->gen_vertices[i].position[k] = (src->vertices[i].position[k] - 0.5f * (lo[k] + hi[k])) * scale;
    }
    mote_mesh proto;
    memset(&proto, 0, sizeof proto);
    proto.vertices = s->gen_vertices;
    proto.vertex_count = src->vertex_count;
    proto.indices = src->indices;
    proto.index_count = src->index_count;
    proto.material.texture = src->material.texture;    /* white diffuse, no emissive */
    const int n = grid ? 100 : 1;
    const float pitch = 2.5f;
    scene_alloc_meshes(s, n);
    for (int k = 0; k < n; k++) {
        s->meshes[k] = proto;
        if (grid) {
            s->meshes[k].position[0] = ((float)(k % 10) - 4.5f) * pitch;
            s->meshes[k].position[1] = ((float)(k / 10) - 4.5f) * pitch;
        }
        s->spin[3 * k + 1] = 2.0f * BENCH_PI / 100.0f;
    }
    memset(&s->frame, 0, sizeof s->frame);
    s->frame.camera.position[2] = grid ? -31.9f : -4.054f;
    s->frame.camera.fov = 0.78f;
    s->frame.camera.znear = grid ? 20.0f : 0.1f;
    s->frame.camera.zfar = grid ? 50.0f : 100.0f;
    s->frame.light_count = 1;
    s->frame.lights[0].type = MOTE_LIGHT_DIRECTIONAL;
    const float dir[3] = {0.4f, -0.5f, 0.7681146f};   /* unit length */
    memcpy(s->frame.lights[0].direction, dir, sizeof dir);
    s->frame.lights[0].intensity = 0.8f;
    s->frame.ambient[0] = s->frame.ambient[1] = s->frame.ambient[2] = 0.2f;
    s->clear_color = (mote_rgba){0, 0, 0, 255};
    scene_finish(s);
    return true;
}

/* Six screen-covering textured quads at increasing distance, each turning
 * about the view axis: overdraw 6. Listed back to front (the painter's
 * worst case for the depth test); order 1 draws them front to back. */
static void scene_fill(bench_scene *s, int w, int h)
{
    memset(s, 0, sizeof *s);
    snprintf(s->name, sizeof s->name, "fill-%dx%d", w, h);
    s->width = w;
    s->height = h;
    s->frames = opt.frames;
    gen_texture(s);
    const int layers = 6;
    s->gen_vertices = bench_alloc(sizeof(mote_vertex) * 4);
    s->gen_indices = bench_alloc(sizeof(uint32_t) * 6);
    const float q[4][2] = {{-1, -1}, {1, -1}, {1, 1}, {-1, 1}};
    for (int k = 0; k < 4; k++) {
        s->gen_vertices[k].position[0] = q[k][0];
        s->gen_vertices[k].position[1] = q[k][1];
        s->gen_vertices[k].normal[2] = -1.0f;
        s->gen_vertices[k].uv[0] = (q[k][0] + 1.0f) * 2.0f;
        s->gen_vertices[k].uv[1] = (1.0f - q[k][1]) * 2.0f;
    }
    /* counter-clockwise on screen seen from -z (y up in the world, down on screen) */
    const uint32_t idx[6] = {0, 1, 2, 0, 2, 3};
    memcpy(s->gen_indices, idx, sizeof idx);
    scene_alloc_meshes(s, layers);
    const float eye[3] = {0, 0, -10.0f}, target[3] = {0, 0, 0};
    default_frame(s, eye, target);
    s->frame.lights[0].position[0] = 0.0f;
    s->frame.lights[0].position[1] = 0.0f;
    s->frame.lights[0].position[2] = -12.0f;
    for (int i = 0; i < layers; i++) {
        int layer = layers - 1 - i;                /* back to front */
        float dist = 5.0f + 1.5f * (float)layer;  /* from the eye */
        mote_mesh *m = &s->meshes[i];
        m->vertices = s->gen_vertices;
        m->vertex_count = 4;
        m->indices = s->gen_indices;
        m->index_count = 6;
        m->position[2] = dist - 10.0f;
        /* half-size 0.9 d covers the half-diagonal 0.86 d of a 16:9 view at any angle */
        m->scaling[0] = m->scaling[1] = 0.9f * dist;
        m->scaling[2] = 1.0f;
        m->rotation[2] = 0.3f * (float)layer;
        m->material.texture = &s->gen_texture;
        s->spin[3 * i + 2] = (layer & 1 ? 1.0f : -1.0f) * 2.0f * BENCH_PI / 100.0f;
    }
    scene_finish(s);
}

/* ---- devices, frames, timing ------------------------------------------- */

/* RUN_POOL: desc.parallel_for = mote_parallel_pool; RUN_OMP: mote_parallel_openmp */
typedef enum { RUN_SERIAL, RUN_OMP, RUN_POOL, RUN_DIRECT } run_kind;

typedef struct bench_dev {
    mote_device dev;
    uint8_t *color;
    void *depth;
    void *arena;
    int threads;                  /* mote_parallel_openmp's user int */
    mote_pool *pool;
} bench_dev;

/* Binned devices clear only the tiles drawn into since their last clear
 * (desc.clear_drawn_tiles_only: the benchmark is the only writer of its
 * buffers), except while this is set: the saving's "without" runs. */
static bool full_clear;
/* Set for the coarse depth saving's "without" runs: desc.no_tile_depth. */
static bool tile_depth_off;

static void dev_init(bench_dev *bd, const bench_scene *s, const bench_mode *m, run_kind kind,
                     int threads)
{
    memset(bd, 0, sizeof *bd);
    mote_device_desc d;
    memset(&d, 0, sizeof d);
    size_t px = (size_t)s->width * (size_t)s->height;
    d.width = s->width;
    d.height = s->height;
    bd->color = bench_alloc(px * 4);
    bd->depth = bench_alloc(px * 4);
    d.color = bd->color;
    d.depth = bd->depth;
    d.depth_format = m->depth != MOTE_DEPTH_FORMAT_DEFAULT ? m->depth : MOTE_DEPTH_FORMAT_32;
    d.clear_color = s->clear_color;
    d.subpixel_bits = m->subpixel_bits;
    if (kind != RUN_DIRECT) {
        uint32_t maxv = 0;
        for (int i = 0; i < s->mesh_count; i++)
            if (s->meshes[i].vertex_count > maxv)
                maxv = s->meshes[i].vertex_count;
        /* room for every triangle of the frame: no mid-frame flushes */
        size_t bytes = (size_t)s->triangles * mote_arena_bytes_per_triangle() * 2
                     + (size_t)maxv * 256 + ((size_t)16 << 20);
        bd->arena = bench_alloc(bytes);
        d.arena = bd->arena;
        d.arena_size = bytes;
        d.clear_drawn_tiles_only = !full_clear;
        d.no_tile_depth = tile_depth_off;
    }
    if (kind == RUN_OMP) {
        bd->threads = threads;
        d.parallel_for = mote_parallel_openmp;
        d.parallel_user = &bd->threads;
    }
    if (kind == RUN_POOL) {
        /* threads inherit the mask of the thread that starts them */
        int pinned = pinned_cpu;
        bench_pin(-1);
        char msg[256];
        mote_pool_desc pd = {threads, NULL, NULL};
        if (mote_pool_create(&pd, &bd->pool, msg, sizeof msg) != MOTE_OK) {
            fprintf(stderr, "bench: %s\n", msg);
            exit(1);
        }
        bench_pin(pinned);
        d.parallel_for = mote_parallel_pool;
        d.parallel_user = bd->pool;
    }
    mote_result r = mote_device_init(&bd->dev, &d);
    if (r != MOTE_OK) {
        fprintf(stderr, "bench: mote_device_init: %s\n", mote_result_string(r));
        exit(1);
    }
}

static void dev_free(bench_dev *bd)
{
    mote_pool_destroy(bd->pool);
    free(bd->color);
    free(bd->depth);
    free(bd->arena);
}

static void dev_render(bench_dev *bd, bench_scene *s, const bench_mode *m, int f, int order)
{
    bench_pose(s, f);
    mote_result r = mote_begin(&bd->dev, &s->frame);
    for (int n = 0; n < s->mesh_count && r == MOTE_OK; n++)
        r = mote_draw(&bd->dev, &s->meshes[order ? s->mesh_count - 1 - n : n], &m->draw);
    if (r == MOTE_OK)
        r = mote_end(&bd->dev);
    if (r != MOTE_OK) {
        fprintf(stderr, "bench: %s/%s: %s\n", s->name, m->name, mote_result_string(r));
        exit(1);
    }
}

/* Colour (RGBA8888) and coverage (depth written) of the device's frame. */
static void dev_image(const bench_dev *bd, uint8_t *rgba, uint8_t *cov)
{
    const mote_device_desc *d = &bd->dev.desc;
    size_t n = (size_t)d->width * (size_t)d->height;
    memcpy(rgba, bd->color, n * 4);
    for (size_t i = 0; i < n; i++)
        cov[i] = d->depth_format == MOTE_DEPTH_FORMAT_16 ? ((const uint16_t *)bd->depth)[i] != 0xffffu
                                                         : ((const uint32_t *)bd->depth)[i] != 0xffffffu;
}

typedef struct bench_time {
    int frames;
    double med, min, max, q1, q3; /* ms */
} bench_time;

typedef void (*frame_fn)(void *ctx, int f);

static bench_time summarize(double *ms, int n)
{
    bench_time t;
    qsort(ms, (size_t)n, sizeof ms[0], bench_cmp_double);
    t.frames = n;
    t.min = ms[0];
    t.max = ms[n - 1];
    t.med = n & 1 ? ms[n / 2] : 0.5 * (ms[n / 2 - 1] + ms[n / 2]);
    t.q1 = ms[(n - 1) / 4];
    t.q3 = ms[(3 * (n - 1) + 3) / 4];
    return t;
}

/* Times count renderers in turns, BENCH_TURN frames each per round, so that
 * all of them see the same machine: on the shared 2-core VM the same binary
 * runs up to 1.4x slower for minutes at a time, and ratios of runs taken
 * one after another (thread scaling, mote against llvmpipe) swung with it.
 * A turn's first frames find the caches full of the other renderer's
 * buffers: the first frame after a switch took 1.6x mote's usual time at
 * 1080p (Suzanne, tex-nearest) and 1.15x llvmpipe's, and the grid took
 * four or five frames to recover. So with two renderers or more each turn
 * begins with BENCH_TURN_WARM frames that are drawn but not timed (the
 * frames before the turn's first), as an application drawing only with
 * one renderer would have warmed its caches. */
#define BENCH_MAX_PAIRED BENCH_MAX_CPUS   /* check_cores times every core in turns */
#define BENCH_TURN 10
#define BENCH_TURN_WARM 3
static void time_frames_paired(const frame_fn fn[], void *const ctx[], int count, int frames,
                               bench_time out[])
{
    static double ms[BENCH_MAX_PAIRED][BENCH_MAX_FRAMES];
    if (frames > BENCH_MAX_FRAMES)
        frames = BENCH_MAX_FRAMES;
    for (int i = 0; i < count; i++)
        for (int f = 0; f < BENCH_WARMUP; f++)
            fn[i](ctx[i], f);
    double start = bench_now();
    int n = 0;
    while (n < frames) {
        int turn = frames - n < BENCH_TURN ? frames - n : BENCH_TURN;
        double t1 = 0.0;
        for (int i = 0; i < count; i++) {
            for (int w = count > 1 ? BENCH_TURN_WARM : 0; w > 0; w--)
                fn[i](ctx[i], n >= w ? n - w : 0);
            for (int f = n; f < n + turn; f++) {
                double t0 = bench_now();
                fn[i](ctx[i], f);
                t1 = bench_now();
                ms[i][f] = (t1 - t0) * 1e3;
            }
        }
        n += turn;
        if (t1 - start > opt.cap_s * count && n >= 5)
            break;
    }
    for (int i = 0; i < count; i++)
        out[i] = summarize(ms[i], n);
}

static bench_time time_frames(frame_fn fn, void *ctx, int frames)
{
    bench_time t;
    time_frames_paired(&fn, &ctx, 1, frames, &t);
    return t;
}

typedef struct mote_ctx {
    bench_dev *bd;
    bench_scene *s;
    const bench_mode *m;
    int order;
} mote_ctx;

static void mote_frame(void *ctx, int f)
{
    mote_ctx *c = (mote_ctx *)ctx;
    dev_render(c->bd, c->s, c->m, f, c->order);
}

typedef struct gl_ctx {
    bench_gl *g;
    bench_scene *s;
    const bench_mode *m;
} gl_ctx;

static void gl_frame(void *ctx, int f)
{
    gl_ctx *c = (gl_ctx *)ctx;
    const uint8_t *rgba;
    bench_gl_frame(c->g, c->s, c->m, f, &rgba, NULL);
}

/* Another renderer's frame, on one core (-1: on every core). */
typedef struct pinned_ctx {
    frame_fn fn;
    void *ctx;
    int cpu;
} pinned_ctx;

static void no_task(void *arg, int index)
{
    (void)arg;
    (void)index;
}

static void pinned_frame(void *ctx, int f)
{
    pinned_ctx *p = (pinned_ctx *)ctx;
    bench_pin(p->cpu);
    p->fn(p->ctx, f);
}

/* ---- error ------------------------------------------------------------- */

static bench_err compare(const uint8_t *a, const uint8_t *ca, const uint8_t *b, const uint8_t *cb,
                         int w, int h)
{
#ifdef BENCH_HAVE_REF
    return bench_ref_compare(a, ca, b, cb, w, h);
#else
    bench_err e = {true, 0, 0, 0};
    double se = 0.0;
    size_t n = (size_t)w * (size_t)h;
    for (size_t i = 0; i < n; i++) {
        for (int k = 0; k < 3; k++) {
            int d = abs((int)a[4 * i + (size_t)k] - (int)b[4 * i + (size_t)k]);
            se += (double)d * d;
            if (ca[i] && cb[i] && d > e.max_err)
                e.max_err = d;
        }
        if (ca[i] != cb[i])
            e.mismatch++;
    }
    double mse = se / (3.0 * (double)n);
    e.psnr = mse > 0.0 ? 10.0 * log10(255.0 * 255.0 / mse) : INFINITY;
    return e;
#endif
}

/* --dump: the frame an error was measured on, as binary PPM. */
static void dump_image(const bench_scene *s, const char *mode, const char *who, const uint8_t *rgba)
{
    if (!opt.dump)
        return;
    char path[1024];
    snprintf(path, sizeof path, "%s/%s-%s-%s.ppm", opt.out_dir, s->name, mode, who);
    FILE *f = fopen(path, "wb");
    if (!f)
        return;
    fprintf(f, "P6\n%d %d\n255\n", s->width, s->height);
    size_t n = (size_t)s->width * (size_t)s->height;
    for (size_t i = 0; i < n; i++)
        fwrite(rgba + 4 * i, 1, 3, f);
    fclose(f);
}

static const char *psnr_str(double p, char *buf)
{
    if (isinf(p))
        return "inf";
    sprintf(buf, "%.2f", p);
    return buf;
}

/* The reference image of a scene at frame f for a mode. With tests/ref
 * (BENCH_HAVE_REF): the double-precision reference renderer. Without it:
 * mote itself with every approximation off (per-pixel perspective, 8-bit
 * subpixel, 32-bit depth, same shading and filter), so errors then show
 * only what each shortcut costs against mote's best. */
static const char *reference_name;

typedef struct ref_cache {
    const bench_scene *scene;
    int key;
    uint8_t *rgba, *cov;
} ref_cache;
static ref_cache refs[8];

static void reference_image(bench_scene *s, const bench_mode *m, int f, const uint8_t **rgba,
                            const uint8_t **cov)
{
    int key = (int)m->draw.mode * 4 + (int)m->draw.filter;
    ref_cache *slot = NULL;
    for (int i = 0; i < 8; i++) {
        if (refs[i].scene == s && refs[i].key == key && refs[i].rgba) {
            *rgba = refs[i].rgba;
            *cov = refs[i].cov;
            return;
        }
        if (!slot && (!refs[i].rgba || refs[i].scene != s))
            slot = &refs[i];
    }
    if (!slot)
        slot = &refs[0];
    free(slot->rgba);
    free(slot->cov);
    size_t n = (size_t)s->width * (size_t)s->height;
    slot->scene = s;
    slot->key = key;
    slot->rgba = bench_alloc(n * 4);
    slot->cov = bench_alloc(n);
#ifdef BENCH_HAVE_REF
    reference_name = bench_ref_render(s, m, f, slot->rgba, slot->cov);
#else
    bench_mode hq = *m;
    hq.draw.perspective = MOTE_PERSPECTIVE_CORRECT;
    hq.subpixel_bits = 8;
    hq.depth = MOTE_DEPTH_FORMAT_32;
    bench_dev bd;
    dev_init(&bd, s, &hq, RUN_DIRECT, 0);
    dev_render(&bd, s, &hq, f, 0);
    dev_image(&bd, slot->rgba, slot->cov);
    dev_free(&bd);
    reference_name = "mote itself, per-pixel perspective, 8-bit subpixel, 32-bit depth "
                     "(tests/ref was not there when this was built)";
#endif
    *rgba = slot->rgba;
    *cov = slot->cov;
}

static void refs_drop(const bench_scene *s)
{
    for (int i = 0; i < 8; i++)
        if (refs[i].scene == s) {
            free(refs[i].rgba);
            free(refs[i].cov);
            memset(&refs[i], 0, sizeof refs[i]);
        }
}

/* ---- results ------------------------------------------------------------ */

typedef struct bench_row {
    char section[16], scene[32], mode[40], renderer[16];
    int width, height, threads, frames;
    bench_time t;
    double tris, pixels;          /* per frame: submitted triangles, pixels written */
    bench_err err;
    bool pareto;
    double paired_med;            /* ms: the run timed in turns with this one (mote 1 thread, or
                                   * mote beside llvmpipe); 0 when none */
} bench_row;

static bench_row rows[512];
static int row_count;

static bench_row *add_row(const char *section, const bench_scene *s, const char *mode,
                          const char *renderer, int threads, bench_time t)
{
    if (row_count >= (int)(sizeof rows / sizeof rows[0]))
        row_count--;
    bench_row *r = &rows[row_count++];
    memset(r, 0, sizeof *r);
    copy_str(r->section, sizeof r->section, section);
    copy_str(r->scene, sizeof r->scene, s->name);
    copy_str(r->mode, sizeof r->mode, mode);
    copy_str(r->renderer, sizeof r->renderer, renderer);
    r->width = s->width;
    r->height = s->height;
    r->threads = threads;
    r->frames = t.frames;
    r->t = t;
    return r;
}

static const bench_row *find_row(const char *section, const char *scene, const char *mode,
                                 const char *renderer, int threads)
{
    for (int i = 0; i < row_count; i++)
        if (!strcmp(rows[i].section, section) && !strcmp(rows[i].scene, scene)
            && !strcmp(rows[i].mode, mode) && !strcmp(rows[i].renderer, renderer)
            && (threads < 0 || rows[i].threads == threads))
            return &rows[i];
    return NULL;
}

/* One timed mote run plus its frame-BENCH_ERR_FRAME error, recorded. */
static bench_row *run_mote(const char *section, bench_scene *s, const bench_mode *m, run_kind kind,
                           int threads, int order, bool with_error, mote_stats *stats_out)
{
    bench_dev bd;
    dev_init(&bd, s, m, kind, threads);
    mote_ctx c = {&bd, s, m, order};
    bench_time t = time_frames(mote_frame, &c, s->frames);
    mote_stats st = *mote_device_stats(&bd.dev);
    bench_row *r = add_row(section, s, m->name, "mote", kind == RUN_OMP || kind == RUN_POOL ? threads : 1, t);
    r->tris = st.triangles_in;
    r->pixels = (double)st.pixels_written;
    if (st.arena_flushes)
        fprintf(stderr, "bench: %s/%s: the arena filled up %u times per frame\n", s->name, m->name,
                st.arena_flushes);
    if (with_error) {
        size_t n = (size_t)s->width * (size_t)s->height;
        uint8_t *rgba = bench_alloc(n * 4), *cov = bench_alloc(n);
        dev_render(&bd, s, m, BENCH_ERR_FRAME, order);
        dev_image(&bd, rgba, cov);
        const uint8_t *rr, *rc;
        reference_image(s, m, BENCH_ERR_FRAME, &rr, &rc);
        r->err = compare(rgba, cov, rr, rc, s->width, s->height);
        dump_image(s, m->name, "mote", rgba);
        dump_image(s, m->name, "ref", rr);
        free(rgba);
        free(cov);
    }
    if (stats_out)
        *stats_out = st;
    dev_free(&bd);
    return r;
}

/* ---- the modes ----------------------------------------------------------- */

static const bench_mode modes[] = {
    {"flat", {.mode = MOTE_MODE_FLAT}, 0, MOTE_DEPTH_FORMAT_DEFAULT},
    {"gouraud", {.mode = MOTE_MODE_GOURAUD}, 0, MOTE_DEPTH_FORMAT_DEFAULT},
    {"tex-nearest", {.mode = MOTE_MODE_TEXTURED}, 0, MOTE_DEPTH_FORMAT_DEFAULT},
    {"tex-bilinear", {.mode = MOTE_MODE_TEXTURED, .filter = MOTE_FILTER_BILINEAR}, 0, MOTE_DEPTH_FORMAT_DEFAULT},
    {"tex-affine", {.mode = MOTE_MODE_TEXTURED, .perspective = MOTE_PERSPECTIVE_AFFINE}, 0, MOTE_DEPTH_FORMAT_DEFAULT},
    {"tex-subspan8", {.mode = MOTE_MODE_TEXTURED, .perspective = MOTE_PERSPECTIVE_SUBSPAN, .subspan_log2 = 3}, 0, MOTE_DEPTH_FORMAT_DEFAULT},
    {"tex-subpixel4", {.mode = MOTE_MODE_TEXTURED}, 4, MOTE_DEPTH_FORMAT_DEFAULT},
    {"tex-depth16", {.mode = MOTE_MODE_TEXTURED}, 0, MOTE_DEPTH_FORMAT_16},
};
#define MODE_COUNT ((int)(sizeof modes / sizeof modes[0]))
#define MODE_TEX 2                /* the goal mode: nearest, per-pixel perspective, 8-bit subpixel */
#define MODE_FLAT 0

static const char *fmt_ms(double ms, char *buf)
{
    sprintf(buf, ms < 10.0 ? "%.3f" : ms < 100.0 ? "%.2f" : "%.1f", ms);
    return buf;
}

/* ---- sections ------------------------------------------------------------ */

#define SCENE_MAX 7
static bench_scene scenes[SCENE_MAX];
static int scene_count;
static bench_scene offscreen;
static bool have_assets;
static bool have_gl;
static char gl_why[256], gl_name[128];

static bench_scene *scene_named(const char *prefix)
{
    for (int i = 0; i < scene_count; i++)
        if (!strncmp(scenes[i].name, prefix, strlen(prefix)))
            return &scenes[i];
    return NULL;
}

/* Each core alone, in turns, on the goal mode of the 1080p scene: the
 * fastest runs the single-thread timings (see bench_pin), and core_speed[]
 * (ascending, relative to the fastest) gives the speed-up the cores allow. */
static double core_speed[BENCH_MAX_CPUS];
static int core_count;
static char cores_line[1024] = "not measured";

static void check_cores(void)
{
    int ids[BENCH_MAX_CPUS], n = bench_cpus(ids, BENCH_MAX_CPUS);
    bench_scene *s = scene_named(have_assets ? "monkey-1920" : "torus-1920");
    if (n < 2 || !s) {
        snprintf(cores_line, sizeof cores_line, "not measured (%s)",
                 !s ? "no 1080p scene" : n == 0 ? "no CPU affinity here" : "one core");
        return;
    }
    const bench_mode *m = &modes[MODE_TEX];
    bench_dev bd;
    dev_init(&bd, s, m, RUN_SERIAL, 1);
    mote_ctx c = {&bd, s, m, 0};
    static pinned_ctx pc[BENCH_MAX_CPUS];
    frame_fn fns[BENCH_MAX_CPUS];
    void *ctxs[BENCH_MAX_CPUS];
    bench_time t[BENCH_MAX_CPUS];
    for (int i = 0; i < n; i++) {
        pc[i] = (pinned_ctx){mote_frame, &c, ids[i]};
        fns[i] = pinned_frame;
        ctxs[i] = &pc[i];
    }
    time_frames_paired(fns, ctxs, n, 50, t);
    bench_pin(-1);
    dev_free(&bd);
    int best = 0;
    for (int i = 1; i < n; i++)
        if (t[i].med < t[best].med)
            best = i;
    fast_cpu = ids[best];
    core_count = n;
    size_t len = (size_t)snprintf(cores_line, sizeof cores_line, "%s %s, median ms of %d frames per core in turns:",
                                  s->name, m->name, t[0].frames);
    for (int i = 0; i < n && len < sizeof cores_line; i++) {
        core_speed[i] = t[best].med / t[i].med;
        len += (size_t)snprintf(cores_line + len, sizeof cores_line - len, " cpu%d %.3f", ids[i], t[i].med);
    }
    qsort(core_speed, (size_t)n, sizeof core_speed[0], bench_cmp_double);
    if (len < sizeof cores_line)
        snprintf(cores_line + len, sizeof cores_line - len, "; single-thread timings run on cpu%d", fast_cpu);
}

/* The speed-up the cores allow th threads: the th fastest cores' speeds,
 * relative to the fastest (th when the cores were not measured). */
static double ideal_speedup(int th)
{
    if (core_count == 0)
        return th;
    double sum = 0.0;
    for (int i = 0; i < th && i < core_count; i++)
        sum += core_speed[core_count - 1 - i];
    return sum;
}

static bench_table *section_modes(void)
{
    bench_table *t = tbl_new("mote, one thread (binned, tiles in order on the calling thread, clearing only the tiles drawn into)",
                             "scene|mode|frames|ms median|ms min|ms max|ms IQR|Mtri/s|Mpix/s|PSNR dB|max err|cov miss");
    char a[32], b[32], c[32], d[32], e[32], p[32];
    for (int i = 0; i < scene_count; i++) {
        bench_scene *s = &scenes[i];
        for (int k = 0; k < MODE_COUNT; k++) {
            const bench_mode *m = &modes[k];
            if (opt.mode && strcmp(opt.mode, m->name) != 0)
                continue;
            bench_row *r = run_mote("modes", s, m, RUN_SERIAL, 1, 0, !opt.mode, NULL);
            tbl_row(t, "%s|%s|%d|%s|%s|%s|%s-%s|%.1f|%.1f|%s|%d|%ld", s->name, m->name, r->frames,
                    fmt_ms(r->t.med, a), fmt_ms(r->t.min, b), fmt_ms(r->t.max, c), fmt_ms(r->t.q1, d),
                    fmt_ms(r->t.q3, e), r->tris / r->t.med * 1e-3, r->pixels / r->t.med * 1e-3,
                    r->err.valid ? psnr_str(r->err.psnr, p) : "-", r->err.max_err, r->err.mismatch);
            fprintf(stderr, "  %s %s %.3f ms\n", s->name, m->name, r->t.med);
        }
    }
    tbl_note(t, "Mtri/s: triangles submitted per second at the median; Mpix/s: pixels written "
                "(depth test passed) per second. PSNR over RGB of the whole frame %d; max err: "
                "largest channel difference where both images cover the pixel; cov miss: pixels "
                "covered by one image only. Reference: %s.",
             BENCH_ERR_FRAME, reference_name ? reference_name : "-");
    return t;
}

static bench_table *section_llvmpipe(void)
{
    bench_table *t = tbl_new("llvmpipe (OSMesa, LP_NUM_THREADS=0) beside mote (one thread)",
                             "scene|mode|lp frames|lp ms median|lp ms min-max|mote ms median|mote/lp time|lp PSNR|mote PSNR|mote-lp dB|lp max err|mote max err|lp cov miss|mote cov miss");
    if (!have_gl) {
        tbl_note(t, "skipped: %s", gl_why);
        return t;
    }
    char a[32], b[32], c[32], d[32], p1[32], p2[32];
    for (int i = 0; i < scene_count; i++) {
        bench_scene *s = &scenes[i];
        char why[256];
        bench_gl *g = bench_gl_create(s, why, sizeof why);
        if (!g) {
            tbl_row(t, "%s|-|skipped: %s", s->name, why);
            continue;
        }
        size_t n = (size_t)s->width * (size_t)s->height;
        uint8_t *cov = bench_alloc(n);
        for (int k = 0; k < MODE_COUNT; k++) {
            const bench_mode *m = &modes[k];
            const uint8_t *rgba;
            if (!bench_gl_frame(g, s, m, BENCH_ERR_FRAME, &rgba, cov))
                continue;         /* a mode GL has no twin for */
            const uint8_t *rr, *rc;
            reference_image(s, m, BENCH_ERR_FRAME, &rr, &rc);
            bench_err e = compare(rgba, cov, rr, rc, s->width, s->height);
            dump_image(s, m->name, "llvmpipe", rgba);
            /* llvmpipe in turns with mote, on a device set up as in the modes section */
            gl_ctx ctx = {g, s, m};
            bench_dev bd;
            dev_init(&bd, s, m, RUN_SERIAL, 1);
            mote_ctx mc = {&bd, s, m, 0};
            const frame_fn fns[2] = {gl_frame, mote_frame};
            void *const ctxs[2] = {&ctx, &mc};
            bench_time tt[2];
            time_frames_paired(fns, ctxs, 2, s->frames, tt);
            dev_free(&bd);
            bench_time tm = tt[0];
            bench_row *r = add_row("llvmpipe", s, m->name, "llvmpipe", 1, tm);
            r->err = e;
            r->tris = s->triangles;
            r->paired_med = tt[1].med;
            const bench_row *mr = find_row("modes", s->name, m->name, "mote", -1);
            char dp[32] = "-";
            if (mr && !isinf(mr->err.psnr) && !isinf(e.psnr))
                snprintf(dp, sizeof dp, "%+.1f", mr->err.psnr - e.psnr);
            else if (mr && isinf(mr->err.psnr) && !isinf(e.psnr))
                snprintf(dp, sizeof dp, "+inf");
            tbl_row(t, "%s|%s|%d|%s|%s-%s|%s|%.3f|%s|%s|%s|%d|%d|%ld|%ld", s->name, m->name, tm.frames,
                    fmt_ms(tm.med, a), fmt_ms(tm.min, b), fmt_ms(tm.max, c),
                    fmt_ms(r->paired_med, d), r->paired_med / tm.med, psnr_str(e.psnr, p1),
                    mr ? psnr_str(mr->err.psnr, p2) : "-", dp, e.max_err, mr ? mr->err.max_err : -1,
                    e.mismatch, mr ? mr->err.mismatch : -1);
            fprintf(stderr, "  llvmpipe %s %s %.3f ms\n", s->name, m->name, tm.med);
        }
        free(cov);
        bench_gl_destroy(g);
    }
    tbl_note(t, "%s. Same camera, triangles, texture; GL fixed-function per-vertex lighting "
                "(mote's formula for a diffuse point light); time includes glFinish (OSMesa then has "
                "the image in the caller's buffer). Each mode's llvmpipe and mote (one thread, serial binned path) "
                "frames are timed in turns of %d frames (each turn after %d frames drawn untimed), in one run: "
                "mote ms median and mote/lp "
                "time come from that run. mote/lp time < 1: mote is faster. Errors against "
                "the same reference as above. GL flat shading takes the provoking vertex's lit colour, "
                "mote's the centroid's: flat errors differ for that reason.",
             gl_name, BENCH_TURN, BENCH_TURN_WARM);
    return t;
}

/* Each thread count is timed in turns with one thread (time_frames_paired):
 * the speed-up is the ratio of the two medians of that run. */
static bench_table *section_threads(void)
{
    bench_table *t = tbl_new("thread scaling (binned with arena, desc.parallel_for = mote_parallel_pool)",
                             "scene|mode|threads|frames|ms median|ms min|ms max|1 thread, same run|speed-up|cores allow|efficiency");
    const char *names[] = {"ll-suzanne-640", "ll-suzanne-1920", "ll-grid-1920", "monkey-1920", "torus-1920",
                           "grid-1920", "fill-1920"};
    char a[32], b[32], c[32], d[32];
    for (int j = 0; j < (int)(sizeof names / sizeof names[0]); j++) {
        bench_scene *s = scene_named(names[j]);
        if (!s)
            continue;
        const bench_mode *m = &modes[MODE_TEX];
        for (int th = opt.max_threads > 1 ? 2 : 1; th <= opt.max_threads; th++) {
            bench_dev one, many;
            /* one thread: the serial binned path, which does not pay for
             * cutting draws into pieces (as one thread through parallel_for would) */
            dev_init(&one, s, m, RUN_SERIAL, 1);
            dev_init(&many, s, m, RUN_POOL, th);
            mote_ctx c1 = {&one, s, m, 0}, c2 = {&many, s, m, 0};
            pinned_ctx p1 = {mote_frame, &c1, fast_cpu}, p2 = {mote_frame, &c2, -1};
            const frame_fn fns[2] = {pinned_frame, pinned_frame};
            void *const ctxs[2] = {&p1, &p2};
            bench_time tt[2];
            time_frames_paired(fns, ctxs, th > 1 ? 2 : 1, s->frames, tt);
            dev_free(&one);
            dev_free(&many);
            if (th <= 2) {
                bench_row *r1 = add_row("threads", s, m->name, "mote", 1, tt[0]);
                tbl_row(t, "%s|%s|1|%d|%s|%s|%s|-|1.00x|1.00x|100%%", s->name, m->name, r1->frames,
                        fmt_ms(r1->t.med, a), fmt_ms(r1->t.min, b), fmt_ms(r1->t.max, c));
                fprintf(stderr, "  threads %s 1 %.3f ms\n", s->name, r1->t.med);
            }
            if (th == 1)
                continue;
            bench_row *r = add_row("threads", s, m->name, "mote", th, tt[1]);
            r->paired_med = tt[0].med;
            double sp = tt[0].med / r->t.med, ideal = ideal_speedup(th);
            tbl_row(t, "%s|%s|%d|%d|%s|%s|%s|%s|%.2fx|%.2fx|%.0f%%", s->name, m->name, th, r->frames,
                    fmt_ms(r->t.med, a), fmt_ms(r->t.min, b), fmt_ms(r->t.max, c), fmt_ms(tt[0].med, d), sp,
                    ideal, 100.0 * sp / ideal);
            fprintf(stderr, "  threads %s %d %.3f ms (1 thread %.3f ms)\n", s->name, th, r->t.med, tt[0].med);
        }
    }
    tbl_note(t, "each thread count timed in turns of %d frames (each turn after %d frames drawn untimed) "
                "with a 1-thread device (binned, no parallel_for, on the fastest core), "
                "in one run; speed-up: the ratio of their medians; cores allow: the sum of the speeds of that "
                "many fastest cores, relative to the fastest (core check: %s); efficiency: speed-up over what "
                "the cores allow; %d cores online.", BENCH_TURN, BENCH_TURN_WARM, cores_line, opt.max_threads);
    return t;
}

/* Another process spins on one core (the one the single-thread runs do not
 * prefer) while one thread, two on the pool and two on OpenMP take turns,
 * none pinned: asking for two threads must not be slower than one. */
static bench_table *section_contention(void)
{
    bench_table *t = tbl_new("contention: a busy loop on one core, 1 thread against 2 (pool and OpenMP), none pinned",
                             "scene|mode|frames|1 thread ms median|max|pool 2 ms median|max|OpenMP 2 ms median|max|pool/1|OpenMP/1");
    int ids[BENCH_MAX_CPUS], n = bench_cpus(ids, BENCH_MAX_CPUS);
    if (n < 2 || opt.max_threads < 2) {
        tbl_note(t, "skipped: %s", n < 2 ? "fewer than 2 cores, or no CPU affinity here" : "--threads 1");
        return t;
    }
    int busy_cpu = ids[0] == fast_cpu ? ids[1] : ids[0];
    const char *names[] = {"ll-suzanne-640", "ll-suzanne-1920", "ll-grid-1920", "grid-1920"};
    char a[32], b[32], c[32], d[32], e[32], f[32];
    bench_pin(-1);
    for (int j = 0; j < (int)(sizeof names / sizeof names[0]); j++) {
        bench_scene *s = scene_named(names[j]);
        if (!s)
            continue;
        const bench_mode *m = &modes[MODE_TEX];
        bench_dev one, pool, omp;
        dev_init(&one, s, m, RUN_SERIAL, 1);
        dev_init(&pool, s, m, RUN_POOL, 2);
        dev_init(&omp, s, m, RUN_OMP, 2);
        mote_ctx c1 = {&one, s, m, 0}, c2 = {&pool, s, m, 0}, c3 = {&omp, s, m, 0};
        const frame_fn fns[3] = {mote_frame, mote_frame, mote_frame};
        void *const ctxs[3] = {&c1, &c2, &c3};
        bench_time tt[3];
        pid_t busy = bench_busy_start(busy_cpu);
        time_frames_paired(fns, ctxs, 3, s->frames, tt);
        bench_busy_stop(busy);
        dev_free(&one);
        dev_free(&pool);
        dev_free(&omp);
        bench_row *r = add_row("contention", s, m->name, "mote-pool", 2, tt[1]);
        r->paired_med = tt[0].med;
        tbl_row(t, "%s|%s|%d|%s|%s|%s|%s|%s|%s|%.2fx|%.2fx", s->name, m->name, tt[0].frames, fmt_ms(tt[0].med, a),
                fmt_ms(tt[0].max, b), fmt_ms(tt[1].med, c), fmt_ms(tt[1].max, d), fmt_ms(tt[2].med, e),
                fmt_ms(tt[2].max, f), tt[0].med / tt[1].med, tt[0].med / tt[2].med);
        fprintf(stderr, "  contention %s 1: %.3f pool 2: %.3f omp 2: %.3f ms\n", s->name, tt[0].med, tt[1].med,
                tt[2].med);
    }
    tbl_note(t, "a process spinning on cpu%d throughout; the three devices timed in turns of %d frames (each "
                "turn after %d frames drawn untimed), in one run; pool/1 and OpenMP/1: the 1-thread median over "
                "the 2-thread one (above 1: two threads faster). max: the slowest frame.",
             busy_cpu, BENCH_TURN, BENCH_TURN_WARM);
    return t;
}

static bench_table *section_savings(void)
{
    bench_table *t = tbl_new("skip what a scene doesn't need: each saving measured (one thread)",
                             "shortcut|scene|with ms|without ms|saved|evidence");
    const bench_mode *tex = &modes[MODE_TEX];
    char a[32], b[32];
    mote_stats sw, so;

    /* whole-mesh frustum rejection */
    {
        bench_scene *s = &offscreen;
        bench_row *with = run_mote("savings", s, tex, RUN_SERIAL, 1, 0, false, &sw);
        snprintf(with->mode, sizeof with->mode, "bounds-set");
        float *radius = bench_alloc(sizeof(float) * (size_t)s->mesh_count);
        for (int i = 0; i < s->mesh_count; i++) {
            radius[i] = s->meshes[i].bounds_radius;
            s->meshes[i].bounds_radius = 0.0f;
        }
        bench_row *without = run_mote("savings", s, tex, RUN_SERIAL, 1, 0, false, &so);
        snprintf(without->mode, sizeof without->mode, "bounds-radius-0");
        for (int i = 0; i < s->mesh_count; i++)
            s->meshes[i].bounds_radius = radius[i];
        free(radius);
        tbl_row(t, "whole-mesh frustum rejection|%s|%s|%s|%.0f%%|%u of %u meshes rejected; without: %u triangles clipped away one by one",
                s->name, fmt_ms(with->t.med, a), fmt_ms(without->t.med, b),
                100.0 * (1.0 - with->t.med / without->t.med), sw.meshes_culled, sw.draws,
                so.triangles_clipped_away);
    }
    /* back-face culling, early depth reject */
    const char *cull_scenes[] = {"monkey-1920", "torus-1920", "grid-1920"};
    for (int j = 0; j < 3; j++) {
        bench_scene *s = scene_named(cull_scenes[j]);
        if (!s)
            continue;
        bench_mode none = *tex;
        none.name = "tex-nearest-cull-none";
        none.draw.cull = MOTE_CULL_NONE;
        bench_row *with = run_mote("savings", s, tex, RUN_SERIAL, 1, 0, false, &sw);
        snprintf(with->mode, sizeof with->mode, "cull-back");
        bench_row *without = run_mote("savings", s, &none, RUN_SERIAL, 1, 0, false, &so);
        tbl_row(t, "back-face culling|%s|%s|%s|%.0f%%|%u back faces skipped; pixels written %.0f vs %.0f",
                s->name, fmt_ms(with->t.med, a), fmt_ms(without->t.med, b),
                100.0 * (1.0 - with->t.med / without->t.med), sw.triangles_backface,
                (double)sw.pixels_written, (double)so.pixels_written);
    }
    /* unlit triangles filled black without their texture, against the same
     * frame with an ambient of 2^-22: a few units of the 2^24 shade scale,
     * so no triangle is black, and a lit channel moves only where its
     * product lies within a hair of a rounding boundary (the two frames
     * compared as the error columns compare) */
    bench_scene *black_scene = scene_named(have_assets ? "monkey-1920" : "torus-1920");
    if (black_scene) {            /* absent when --scene picked another */
        bench_scene *s = black_scene;
        const float dim = 1.0f / 4194304.0f;
        bench_row *with = run_mote("savings", s, tex, RUN_SERIAL, 1, 0, false, &sw);
        snprintf(with->mode, sizeof with->mode, "black-unlit");
        size_t n = (size_t)s->width * (size_t)s->height;
        uint8_t *black = bench_alloc(n * 4), *black_cov = bench_alloc(n);
        uint8_t *dimmed = bench_alloc(n * 4), *dimmed_cov = bench_alloc(n);
        float keep[3];
        memcpy(keep, s->frame.ambient, sizeof keep);
        bench_dev bd;
        dev_init(&bd, s, tex, RUN_SERIAL, 1);
        dev_render(&bd, s, tex, BENCH_ERR_FRAME, 0);
        dev_image(&bd, black, black_cov);
        for (int c = 0; c < 3; c++)
            s->frame.ambient[c] = keep[c] + dim;
        dev_render(&bd, s, tex, BENCH_ERR_FRAME, 0);
        dev_image(&bd, dimmed, dimmed_cov);
        dev_free(&bd);
        bench_err e = compare(black, black_cov, dimmed, dimmed_cov, s->width, s->height);
        free(black); free(black_cov); free(dimmed); free(dimmed_cov);
        bench_row *without = run_mote("savings", s, tex, RUN_SERIAL, 1, 0, false, &so);
        snprintf(without->mode, sizeof without->mode, "ambient-2^-22");
        memcpy(s->frame.ambient, keep, sizeof keep);
        char p[16];
        tbl_row(t, "unlit triangles filled black, not textured|%s|%s|%s|%.0f%%|%u of %u triangles black; "
                   "without: ambient +2^-22, %u black, PSNR %s dB to it, max err %d, cov miss %ld",
                s->name, fmt_ms(with->t.med, a), fmt_ms(without->t.med, b),
                100.0 * (1.0 - with->t.med / without->t.med), sw.triangles_black, sw.triangles_drawn,
                so.triangles_black, psnr_str(e.psnr, p), e.max_err, e.mismatch);
    }
    bench_scene *fill = scene_named("fill");
    if (fill) {
        bench_row *with = run_mote("savings", fill, tex, RUN_SERIAL, 1, 1, false, &sw);
        snprintf(with->mode, sizeof with->mode, "front-to-back");
        bench_row *without = run_mote("savings", fill, tex, RUN_SERIAL, 1, 0, false, &so);
        snprintf(without->mode, sizeof without->mode, "back-to-front");
        double area = (double)fill->width * fill->height;
        tbl_row(t, "early depth reject|%s|%s|%s|%.0f%%|pixels written %.2f vs %.2f per screen pixel (overdraw)",
                fill->name, fmt_ms(with->t.med, a), fmt_ms(without->t.med, b),
                100.0 * (1.0 - with->t.med / without->t.med), (double)sw.pixels_written / area,
                (double)so.pixels_written / area);
    }
    /* the coarse depth per tile: triangles behind what a tile has drawn
     * skipped before their edges are walked (the fill scene front to back) */
    const char *depth_scenes[] = {"fill-1920", "ll-grid-1920", "grid-1920", "ll-suzanne-1920"};
    for (int j = 0; j < 4; j++) {
        bench_scene *s = scene_named(depth_scenes[j]);
        if (!s)
            continue;
        const int order = j == 0;
        bench_row *with = run_mote("savings", s, tex, RUN_SERIAL, 1, order, false, &sw);
        snprintf(with->mode, sizeof with->mode, "tile-depth");
        tile_depth_off = true;
        bench_row *without = run_mote("savings", s, tex, RUN_SERIAL, 1, order, false, &so);
        tile_depth_off = false;
        snprintf(without->mode, sizeof without->mode, "no-tile-depth");
        tbl_row(t, "coarse depth per tile|%s%s|%s|%s|%.0f%%|%u triangle visits to tiles skipped; pixels tested %.0f vs %.0f",
                s->name, order ? " front to back" : "", fmt_ms(with->t.med, a), fmt_ms(without->t.med, b),
                100.0 * (1.0 - with->t.med / without->t.med), sw.tile_triangles_behind,
                (double)sw.pixels_tested, (double)so.pixels_tested);
    }
    /* the clear of tiles still clear from the last frame */
    for (int i = 0; i < scene_count; i++) {
        bench_scene *s = &scenes[i];
        bench_row *with = run_mote("savings", s, tex, RUN_SERIAL, 1, 0, false, &sw);
        snprintf(with->mode, sizeof with->mode, "clear-drawn-tiles");
        full_clear = true;
        bench_row *without = run_mote("savings", s, tex, RUN_SERIAL, 1, 0, false, &so);
        full_clear = false;
        snprintf(without->mode, sizeof without->mode, "clear-all");
        tbl_row(t, "clear only the tiles drawn into|%s|%s|%s|%.0f%%|%u of %u tiles still clear, not cleared",
                s->name, fmt_ms(with->t.med, a), fmt_ms(without->t.med, b),
                100.0 * (1.0 - with->t.med / without->t.med), sw.tiles_clear_skipped,
                sw.tiles_empty + sw.tiles_drawn);
    }
    /* empty tiles: binned (empty tiles cost nothing) against direct drawing,
     * both clearing the whole frame */
    full_clear = true;
    for (int i = 0; i < scene_count; i++) {
        bench_scene *s = &scenes[i];
        if (s == fill)
            continue;
        bench_row *with = run_mote("savings", s, tex, RUN_SERIAL, 1, 0, false, &sw);
        snprintf(with->mode, sizeof with->mode, "binned");
        bench_row *without = run_mote("savings", s, tex, RUN_DIRECT, 1, 0, false, &so);
        snprintf(without->mode, sizeof without->mode, "direct");
        tbl_row(t, "empty tiles skipped (binned vs direct)|%s|%s|%s|%.0f%%|%u of %u tiles empty, skipped",
                s->name, fmt_ms(with->t.med, a), fmt_ms(without->t.med, b),
                100.0 * (1.0 - with->t.med / without->t.med), sw.tiles_empty,
                sw.tiles_empty + sw.tiles_drawn);
    }
    full_clear = false;
    /* untextured flat against textured, from the mode table */
    for (int i = 0; i < scene_count; i++) {
        const bench_row *f = find_row("modes", scenes[i].name, "flat", "mote", -1);
        const bench_row *x = find_row("modes", scenes[i].name, "tex-nearest", "mote", -1);
        if (f && x)
            tbl_row(t, "untextured flat vs textured|%s|%s|%s|%.0f%%|flat span: one constant pixel, no UV or weights",
                    scenes[i].name, fmt_ms(f->t.med, a), fmt_ms(x->t.med, b),
                    100.0 * (1.0 - f->t.med / x->t.med));
    }
    tbl_note(t, "with/without: median ms per frame with the shortcut and without it; saved = 1 - with/without. "
                "The empty-tile row compares binned drawing, which never visits an empty tile, with direct "
                "drawing, which has no tiles, both clearing the whole frame: it shows what binning costs or "
                "saves, not the empty tiles alone.");
    return t;
}

static bench_table *section_goals(void)
{
    bench_table *t = tbl_new("goals on the like-for-like scenes: tex-nearest (per-pixel perspective, 8-bit subpixel)",
                             "goal|scene|mote ms|llvmpipe ms|measured|target|met");
    static const struct { const char *scene; double target; } g[] = {
        {"ll-suzanne-640x480", 0.28}, {"ll-suzanne-1920x1080", 0.28}, {"ll-grid-1920x1080", 0.25}};
    char a[32], b[32];
    for (int i = 0; i < 3; i++) {
        const bench_row *m = find_row("modes", g[i].scene, "tex-nearest", "mote", -1);
        const bench_row *l = find_row("llvmpipe", g[i].scene, "tex-nearest", "llvmpipe", -1);
        if (!m)
            continue;
        if (!l) {
            tbl_row(t, "time vs llvmpipe, 1 thread|%s|%s|-|-|<= %.2fx|n/a (no llvmpipe)", g[i].scene,
                    fmt_ms(m->t.med, a), g[i].target);
            continue;
        }
        double ratio = l->paired_med / l->t.med;   /* timed in turns (section_llvmpipe) */
        tbl_row(t, "time vs llvmpipe, 1 thread|%s|%s|%s|%.3fx|<= %.2fx|%s", g[i].scene, fmt_ms(l->paired_med, a),
                fmt_ms(l->t.med, b), ratio, g[i].target, ratio <= g[i].target ? "yes" : "NO");
    }
    for (int i = 0; i < 3; i++) {
        const bench_row *two = find_row("threads", g[i].scene, "tex-nearest", "mote", 2);
        if (!find_row("modes", g[i].scene, "tex-nearest", "mote", -1))
            continue;
        if (!two) {
            tbl_row(t, "2 threads vs 1|%s|-|-|-|>= 1.80x|n/a (fewer than 2 cores)", g[i].scene);
            continue;
        }
        double sp = two->paired_med / two->t.med;
        tbl_row(t, "2 threads vs 1|%s|%s|-|%.2fx|>= 1.80x|%s", g[i].scene, fmt_ms(two->t.med, a), sp,
                sp >= 1.8 ? "yes" : "NO");
    }
    for (int i = 0; i < 3; i++) {
        const bench_row *two = find_row("contention", g[i].scene, "tex-nearest", "mote-pool", 2);
        if (!two)
            continue;
        double sp = two->paired_med / two->t.med;
        tbl_row(t, "2 threads vs 1, one core busy|%s|%s|-|%.2fx|>= 1.00x|%s", g[i].scene, fmt_ms(two->t.med, a),
                sp, sp >= 1.0 ? "yes" : "NO");
    }
    tbl_note(t, "The like-for-like scenes are described in docs/performance.md so that other renderers "
                "draw exactly the same work; the targets are half of TinyGL's time on them, stated as "
                "llvmpipe ratios so that one run measures them.");
    return t;
}

/* ---- pareto, csv, markdown ---------------------------------------------- */

static void write_pareto(FILE *pts, FILE *front)
{
    for (int i = 0; i < scene_count; i++) {
        int idx[64], n = 0;
        for (int r = 0; r < row_count && n < 64; r++)
            if (!strcmp(rows[r].scene, scenes[i].name)
                && (!strcmp(rows[r].section, "modes") || !strcmp(rows[r].section, "llvmpipe"))
                && rows[r].err.valid)
                idx[n++] = r;
        /* by time; a point is on the front when nothing at most as slow is more accurate */
        for (int a = 1; a < n; a++)
            for (int b = a; b > 0 && rows[idx[b]].t.med < rows[idx[b - 1]].t.med; b--) {
                int tmp = idx[b]; idx[b] = idx[b - 1]; idx[b - 1] = tmp;
            }
        double best = -1.0;
        fprintf(pts, "# %s\n", scenes[i].name);
        fprintf(front, "# %s\n", scenes[i].name);
        for (int a = 0; a < n; a++) {
            bench_row *r = &rows[idx[a]];
            double p = isinf(r->err.psnr) ? 110.0 : r->err.psnr;
            if (p > best) {
                best = p;
                r->pareto = true;
                fprintf(front, "%.4f %.3f\n", r->t.med, p);
            }
            fprintf(pts, "%.4f %.3f %s%s %d\n", r->t.med, p, strcmp(r->renderer, "mote") ? "lp:" : "",
                    r->mode, strcmp(r->renderer, "mote") ? 1 : 0);
        }
        fprintf(pts, "\n\n");
        fprintf(front, "\n\n");
    }
}

static void write_csv(FILE *f)
{
    fprintf(f, "section,scene,width,height,renderer,mode,threads,frames,ms_median,ms_min,ms_max,ms_q1,ms_q3,"
               "tris_per_frame,mtris_per_s,pixels_per_frame,mpix_per_s,psnr_db,max_err,coverage_mismatch,pareto\n");
    for (int i = 0; i < row_count; i++) {
        const bench_row *r = &rows[i];
        char p[32] = "";
        if (r->err.valid)
            copy_str(p, sizeof p, isinf(r->err.psnr) ? "inf" : "");
        if (r->err.valid && !isinf(r->err.psnr))
            snprintf(p, sizeof p, "%.3f", r->err.psnr);
        fprintf(f, "%s,%s,%d,%d,%s,%s,%d,%d,%.4f,%.4f,%.4f,%.4f,%.4f,%.0f,%.3f,%.0f,%.3f,%s,", r->section,
                r->scene, r->width, r->height, r->renderer, r->mode, r->threads, r->frames, r->t.med,
                r->t.min, r->t.max, r->t.q1, r->t.q3, r->tris, r->tris / r->t.med * 1e-3, r->pixels,
                r->pixels / r->t.med * 1e-3, p);
        if (r->err.valid)
            fprintf(f, "%d,%ld,", r->err.max_err, r->err.mismatch);
        else
            fprintf(f, ",,");
        fprintf(f, "%d\n", r->pareto ? 1 : 0);
    }
}

static FILE *open_out(const char *name)
{
    char path[1024];
    snprintf(path, sizeof path, "%s/%s", opt.out_dir, name);
    FILE *f = fopen(path, "w");
    if (!f) {
        fprintf(stderr, "bench: cannot write %s: %s\n", path, strerror(errno));
        exit(1);
    }
    return f;
}

static void mkdirs(const char *dir)
{
    char buf[1024];
    copy_str(buf, sizeof buf, dir);
    for (char *p = buf + 1; *p; p++)
        if (*p == '/') {
            *p = 0;
            mkdir(buf, 0777);
            *p = '/';
        }
    mkdir(buf, 0777);
}

/* Generated scenes must look the same with and without back-face culling
 * (closed or camera-facing surfaces): otherwise their winding is wrong. */
static void check_winding(bench_scene *s)
{
    bench_mode none = modes[MODE_TEX];
    none.draw.cull = MOTE_CULL_NONE;
    size_t n = (size_t)s->width * (size_t)s->height;
    uint8_t *a = bench_alloc(n * 4), *b = bench_alloc(n * 4), *ca = bench_alloc(n), *cb = bench_alloc(n);
    bench_dev bd;
    dev_init(&bd, s, &modes[MODE_TEX], RUN_DIRECT, 0);
    dev_render(&bd, s, &modes[MODE_TEX], BENCH_ERR_FRAME, 0);
    dev_image(&bd, a, ca);
    dev_render(&bd, s, &none, BENCH_ERR_FRAME, 0);
    dev_image(&bd, b, cb);
    long covered = 0, differ = 0;
    for (size_t i = 0; i < n; i++) {
        covered += ca[i] || cb[i];
        differ += ca[i] != cb[i] || memcmp(a + 4 * i, b + 4 * i, 3) != 0;
    }
    if (differ)
        fprintf(stderr, "bench: warning: %s: %ld of its %ld pixels differ with and without back-face "
                        "culling: its winding is wrong\n", s->name, differ, covered);
    dev_free(&bd);
    free(a); free(b); free(ca); free(cb);
}

int main(int argc, char **argv)
{
    /* llvmpipe reads these when its screen is created: before any OSMesa call */
    setenv("LP_NUM_THREADS", "0", 1);
    setenv("GALLIUM_DRIVER", "llvmpipe", 1);
    static char assets_default[1024];
#ifdef MOTE_SOURCE_DIR
    snprintf(assets_default, sizeof assets_default, "%s/../shared/assets", MOTE_SOURCE_DIR);
#else
    snprintf(assets_default, sizeof assets_default, "../shared/assets");
#endif
    opt.assets = assets_default;
    long cores = sysconf(_SC_NPROCESSORS_ONLN);
    opt.max_threads = cores > 0 ? (int)cores : 1;
    for (int i = 1; i < argc; i++) {
        if (!strcmp(argv[i], "--out") && i + 1 < argc)
            opt.out_dir = argv[++i];
        else if (!strcmp(argv[i], "--assets") && i + 1 < argc)
            opt.assets = argv[++i];
        else if (!strcmp(argv[i], "--cap") && i + 1 < argc)
            opt.cap_s = atof(argv[++i]);
        else if (!strcmp(argv[i], "--frames") && i + 1 < argc)
            opt.frames = atoi(argv[++i]);
        else if (!strcmp(argv[i], "--threads") && i + 1 < argc)
            opt.max_threads = atoi(argv[++i]);
        else if (!strcmp(argv[i], "--dump"))
            opt.dump = true;
        else if (!strcmp(argv[i], "--scene") && i + 1 < argc)
            opt.scene = argv[++i];
        else if (!strcmp(argv[i], "--mode") && i + 1 < argc)
            opt.mode = argv[++i];
        else if (!strcmp(argv[i], "--only") && i + 1 < argc)
            opt.only = argv[++i];
        else if (!strcmp(argv[i], "--no-tile-depth"))   /* profiling the coarse depth's cost */
            tile_depth_off = true;
        else {
            fprintf(stderr, "usage: %s [--out DIR] [--assets DIR] [--cap SECONDS] [--frames N] [--threads N] [--dump]\n"
                            "       [--scene PREFIX] [--mode NAME]   (profiling: that scene/mode only, no error, no other section)\n"
                            "       [--only threads|contention|savings]   (that section alone, no other)\n"
                            "       [--no-tile-depth]   (devices with desc.no_tile_depth)\n", argv[0]);
            return 2;
        }
    }
    if (opt.frames < 5)
        opt.frames = 5;
    if (opt.max_threads < 1)
        opt.max_threads = 1;
    mkdirs(opt.out_dir);
    double t_start = bench_now();

    char path[1024];
    snprintf(path, sizeof path, "%s/monkey.babylon", opt.assets);
    have_assets = access(path, R_OK) == 0;
    if (!have_assets)
        printf("bench: %s is absent: skipping the monkey scenes; a generated torus of 966 "
               "triangles and a checker texture stand in for Suzanne\n", path);
    const char *model = have_assets ? "monkey" : "torus";
    char name[32];
    snprintf(name, sizeof name, "%s-640x480", model);
    if (!scene_model(&scenes[scene_count], name, 640, 480, SCENE_ONE, have_assets))
        return 1;
    scene_count++;
    snprintf(name, sizeof name, "%s-1920x1080", model);
    if (!scene_model(&scenes[scene_count], name, 1920, 1080, SCENE_ONE, have_assets))
        return 1;
    scene_count++;
    snprintf(name, sizeof name, "grid-1920x1080");
    if (!scene_model(&scenes[scene_count], name, 1920, 1080, SCENE_GRID, have_assets))
        return 1;
    scene_count++;
    scene_fill(&scenes[scene_count++], 1920, 1080);
    if (have_assets) {
        static const struct { const char *name; int w, h; bool grid; } ll[] = {
            {"ll-suzanne-640x480", 640, 480, false},
            {"ll-suzanne-1920x1080", 1920, 1080, false},
            {"ll-grid-1920x1080", 1920, 1080, true},
        };
        for (int i = 0; i < 3; i++)
            if (!scene_like_for_like(&scenes[scene_count++], ll[i].name, ll[i].w, ll[i].h, ll[i].grid))
                return 1;
    } else {
        printf("bench: skipping the like-for-like scenes, which need Suzanne\n");
    }
    if (!scene_model(&offscreen, "offscreen-grid-1920x1080", 1920, 1080, SCENE_OFFSCREEN, have_assets))
        return 1;
    if (opt.scene) {
        int kept = 0;
        for (int i = 0; i < scene_count; i++) {
            if (!strncmp(scenes[i].name, opt.scene, strlen(opt.scene)))
                scenes[kept++] = scenes[i];
            else
                scene_free(&scenes[i]);
        }
        scene_count = kept;
    }
    if (!opt.mode) {
        for (int i = 0; i < scene_count; i++)
            if (!have_assets || !strncmp(scenes[i].name, "fill", 4))
                check_winding(&scenes[i]);
    }

    /* is llvmpipe there? */
    if (scene_count > 0) {
        bench_gl *g = bench_gl_create(&scenes[0], gl_why, sizeof gl_why);
        have_gl = g != NULL;
        if (g)
            copy_str(gl_name, sizeof gl_name, bench_gl_renderer(g));
        bench_gl_destroy(g);
    }
    /* OpenMP's threads start with the mask of the thread that starts them:
     * start them all before anything is pinned */
    int all = opt.max_threads;
    mote_parallel_openmp(&all, all, no_task, NULL);
    if (!opt.mode)                /* profiling: that mode's frames alone (make profile counts them) */
        check_cores();
    else
        snprintf(cores_line, sizeof cores_line, "not measured (profiling one mode)");

    char cpu[160];
    bench_cpu_name(cpu, sizeof cpu);
    printf("mote benchmark: %s, %ld cores online, OpenMP %s, time cap %.1f s per run, %d frames asked per run, "
           "error frame %d\n", cpu, cores,
#ifdef _OPENMP
           "on",
#else
           "off",
#endif
           opt.cap_s, opt.frames, BENCH_ERR_FRAME);
    double load0 = bench_load();
    printf("  load average before: %.2f (anything above 0 on a %ld-core machine slows the runs)\n", load0, cores);
    printf("  core check: %s\n", cores_line);
    for (int i = 0; i < scene_count; i++)
        printf("  scene %-22s %4dx%-4d %6u triangles in %d meshes\n", scenes[i].name, scenes[i].width,
               scenes[i].height, scenes[i].triangles, scenes[i].mesh_count);
    printf("  llvmpipe: %s\n", have_gl ? gl_name : gl_why);
    fflush(stdout);

    bench_table *tabs[6];
    int ntab = 0;
    if (opt.only) {
        bench_table *one = !strcmp(opt.only, "threads") ? section_threads()
                         : !strcmp(opt.only, "contention") ? section_contention()
                         : !strcmp(opt.only, "savings") ? section_savings() : NULL;
        if (one)
            tbl_print(one, stdout, false);
        else
            fprintf(stderr, "bench: --only %s: not a section (threads, contention, savings)\n", opt.only);
        free(one);
        for (int i = 0; i < scene_count; i++)
            scene_free(&scenes[i]);
        scene_free(&offscreen);
        return one ? 0 : 2;
    }
    bench_pin(fast_cpu);
    tabs[ntab++] = section_modes();
    tbl_print(tabs[0], stdout, false);
    if (opt.mode || scene_count == 0) {
        free(tabs[0]);
        for (int i = 0; i < scene_count; i++)
            scene_free(&scenes[i]);
        scene_free(&offscreen);
        return 0;
    }
    tabs[ntab++] = section_llvmpipe();
    tbl_print(tabs[1], stdout, false);
    tabs[ntab++] = section_threads();
    tbl_print(tabs[2], stdout, false);
    tabs[ntab++] = section_contention();
    tbl_print(tabs[3], stdout, false);
    bench_pin(fast_cpu);
    tabs[ntab++] = section_savings();
    tbl_print(tabs[4], stdout, false);
    tabs[ntab++] = section_goals();
    tbl_print(tabs[5], stdout, false);

    double load1 = bench_load();
    printf("\nload average after: %.2f (before: %.2f)\n", load1, load0);
    FILE *pts = open_out("pareto.dat"), *front = open_out("pareto_front.dat");
    write_pareto(pts, front);
    fclose(pts);
    fclose(front);
    FILE *csv = open_out("bench.csv");
    write_csv(csv);
    fclose(csv);
    FILE *md = open_out("bench.md");
    fprintf(md, "## Benchmark\n\n`make bench` on %s, %ld cores; scenes rotate one turn per 100 frames; "
                "%s. Frames timed per run: the `frames` column (capped at %.1f s per run). "
                "Load average %.2f before, %.2f after (other work skews the timings). "
                "Core check (each core alone): %s.\n\n",
            cpu, cores, have_assets ? "Suzanne from ../shared/assets" : "a generated torus instead of Suzanne (../shared absent)",
            opt.cap_s, load0, load1, cores_line);
    for (int i = 0; i < ntab; i++)
        tbl_print(tabs[i], md, true);
    fprintf(md, "![run time against error](pareto.png)\n");
    fclose(md);
    printf("\nwrote %s/bench.csv, bench.md, pareto.dat, pareto_front.dat in %.1f s\n", opt.out_dir,
           bench_now() - t_start);

    for (int i = 0; i < ntab; i++)
        free(tabs[i]);
    for (int i = 0; i < scene_count; i++) {
        refs_drop(&scenes[i]);
        scene_free(&scenes[i]);
    }
    refs_drop(&offscreen);
    scene_free(&offscreen);
    return 0;
}
