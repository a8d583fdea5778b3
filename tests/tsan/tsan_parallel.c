/*
 * tsan_parallel.c - the parallel path under ThreadSanitizer (`make tsan`,
 * tests/tsan/tsan.mk).
 *
 * The core runs its parallel steps (the vertex chunks of a draw cut into
 * pieces, the setup groups, the clear's stripes beside them, the tile
 * jobs) through the caller's parallel_for. Here that is a pool of
 * pthreads, which ThreadSanitizer understands: each worker is started and
 * waited for through two semaphores of its own (the happens-before edges
 * of a fork and of a join, and no others), and takes its jobs by a fixed
 * stride or by a relaxed atomic counter (from the front or the back),
 * which orders nothing. Two jobs of one step are thus ordered only when
 * one thread ran both, and memory that two jobs touch, one of them
 * writing, is a reported race. Every frame is also compared byte for
 * byte (colour, padding, depth) with the one-thread frame (parallel_for
 * NULL) of the same device.
 *
 * The pthreads build also runs the tests on the library's own pool
 * (mote_parallel_pool), whose claims synchronise the jobs they hand out:
 * there it checks the pool itself, and the frames' bytes.
 *
 * Built a second way (tsan.mk): with clang, -fopenmp and LLVM's Archer,
 * which tells ThreadSanitizer about the OpenMP runtime's synchronisation,
 * the same tests run through src/host/parallel.c's OpenMP loop
 * (mote_parallel_openmp) on 2, 3 and 4 threads instead of the pool.
 *
 * A test fails when ThreadSanitizer reported anything while it ran
 * (__tsan_on_report counts the reports), or when a frame differs.
 */
#define _POSIX_C_SOURCE 200809L
#include "unity.h"

#include <mote/mote.h>
#include <mote/mote_io.h>
#include "support/scenes.h"

#include <math.h>
#include <pthread.h>
#include <semaphore.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>

#ifdef _OPENMP
#include <omp.h>
#endif

#ifndef MOTE_SOURCE_DIR
#define MOTE_SOURCE_DIR "."
#endif

/* ---- reports ------------------------------------------------------------ */

/* ThreadSanitizer calls this for every report it prints. */
void __tsan_on_report(void *report);
static int reports;
void __tsan_on_report(void *report)
{
    (void)report;
    __atomic_add_fetch(&reports, 1, __ATOMIC_RELAXED);
}

static int reports_before;

void setUp(void)
{
    reports_before = __atomic_load_n(&reports, __ATOMIC_RELAXED);
}

void tearDown(void)
{
    int n = __atomic_load_n(&reports, __ATOMIC_RELAXED) - reports_before;
    if (n > 0) {
        char msg[80];
        snprintf(msg, sizeof msg, "ThreadSanitizer reported %d warning(s), above", n);
        TEST_FAIL_MESSAGE(msg);
    }
}

/* ---- executors ---------------------------------------------------------- */

enum { MAX_THREADS = 8 };

typedef enum order {
    ORDER_STRIDE,                 /* worker k: jobs k, k + n, ...: neighbours on other threads */
    ORDER_FRONT,                  /* a relaxed atomic counter from the front */
    ORDER_BACK,                   /* the same from the back */
    ORDER_OPENMP,                 /* mote_parallel_openmp (the TSAN_OPENMP build) */
    ORDER_MOTE_POOL,              /* mote_parallel_pool */
    ORDER_COUNT
} order;

static const char *const order_names[ORDER_COUNT] = {"stride", "front", "back", "openmp", "mote-pool"};

typedef struct pool pool;

typedef struct worker {
    pool *p;
    int k;
    pthread_t thread;
    sem_t go, done;               /* this worker's fork and join, nothing else */
    int ran;                      /* jobs it ran in the step */
} worker;

struct pool {
    int threads;
    order order;
    worker w[MAX_THREADS];
    /* the step in progress, written before the workers are started */
    int count;
    mote_task_fn fn;
    void *arg;
    bool quit;
    int next;                     /* ORDER_FRONT/BACK: claims, relaxed */
    /* steps run, and steps whose jobs ran on two threads or more */
    long steps, shared_steps;
    int seen[MAX_THREADS];        /* ORDER_OPENMP, ORDER_MOTE_POOL: jobs per thread in the step */
    mote_pool *mpool;             /* ORDER_MOTE_POOL */
};

static int claim(pool *p)
{
    return __atomic_fetch_add(&p->next, 1, __ATOMIC_RELAXED);
}

static void *pool_worker(void *arg)
{
    worker *w = (worker *)arg;
    pool *p = w->p;
    for (;;) {
        sem_wait(&w->go);
        if (p->quit)
            return NULL;
        int n = 0;
        if (p->order == ORDER_STRIDE) {
            for (int i = w->k; i < p->count; i += p->threads, n++)
                p->fn(p->arg, i);
        } else {
            for (int i; (i = claim(p)) < p->count; n++)
                p->fn(p->arg, p->order == ORDER_BACK ? p->count - 1 - i : i);
        }
        w->ran = n;
        sem_post(&w->done);
    }
}

static void count_step(pool *p, const int *ran, int n)
{
    int busy = 0;
    for (int k = 0; k < n; k++)
        busy += ran[k] > 0;
    p->steps++;
    p->shared_steps += busy >= 2;
}

#ifdef _OPENMP
typedef struct omp_step {
    pool *p;
    mote_task_fn fn;
    void *arg;
} omp_step;

static void omp_job(void *arg, int index)
{
    omp_step *s = (omp_step *)arg;
    int t = omp_get_thread_num();
    if (t < MAX_THREADS)
        s->p->seen[t]++;          /* this thread's own slot */
    s->fn(s->arg, index);
}
#endif

/* ORDER_MOTE_POOL: the pool thread running a job (0: the caller), set as
 * each wakes for a call; each thread counts its jobs in its own slot. */
static __thread int mote_pool_thread;

static void mote_pool_wake(void *user, int thread)
{
    (void)user;
    mote_pool_thread = thread;
}

typedef struct mpool_step {
    pool *p;
    mote_task_fn fn;
    void *arg;
} mpool_step;

static void mpool_job(void *arg, int index)
{
    mpool_step *s = (mpool_step *)arg;
    s->p->seen[mote_pool_thread]++;
    s->fn(s->arg, index);
}

/* The mote_parallel_for_fn: user is the pool. */
static void pool_for(void *user, int count, mote_task_fn fn, void *arg)
{
    pool *p = (pool *)user;
    if (p->order == ORDER_MOTE_POOL) {
        mpool_step s = {p, fn, arg};
        memset(p->seen, 0, sizeof p->seen);
        mote_parallel_pool(p->mpool, count, mpool_job, &s);
        count_step(p, p->seen, MAX_THREADS);
        return;
    }
#ifdef _OPENMP
    if (p->order == ORDER_OPENMP) {
        omp_step s = {p, fn, arg};
        memset(p->seen, 0, sizeof p->seen);
        mote_parallel_openmp(&p->threads, count, omp_job, &s);
        count_step(p, p->seen, MAX_THREADS);
        return;
    }
#endif
    p->count = count;
    p->fn = fn;
    p->arg = arg;
    p->next = 0;
    for (int k = 0; k < p->threads; k++)
        sem_post(&p->w[k].go);
    int ran[MAX_THREADS];
    for (int k = 0; k < p->threads; k++) {
        sem_wait(&p->w[k].done);
        ran[k] = p->w[k].ran;
    }
    count_step(p, ran, p->threads);
}

static void pool_start(pool *p, int threads, order o)
{
    memset(p, 0, sizeof *p);
    p->threads = threads;
    p->order = o;
    if (o == ORDER_OPENMP)
        return;
    if (o == ORDER_MOTE_POOL) {
        mote_pool_desc d = {threads, mote_pool_wake, NULL};
        TEST_ASSERT_EQUAL(MOTE_OK, mote_pool_create(&d, &p->mpool, NULL, 0));
        return;
    }
    for (int k = 0; k < threads; k++) {
        worker *w = &p->w[k];
        w->p = p;
        w->k = k;
        TEST_ASSERT_EQUAL(0, sem_init(&w->go, 0, 0));
        TEST_ASSERT_EQUAL(0, sem_init(&w->done, 0, 0));
        TEST_ASSERT_EQUAL(0, pthread_create(&w->thread, NULL, pool_worker, w));
    }
}

static void pool_stop(pool *p)
{
    if (p->order == ORDER_OPENMP)
        return;
    if (p->order == ORDER_MOTE_POOL) {
        mote_pool_destroy(p->mpool);
        return;
    }
    p->quit = true;
    for (int k = 0; k < p->threads; k++)
        sem_post(&p->w[k].go);
    for (int k = 0; k < p->threads; k++) {
        pthread_join(p->w[k].thread, NULL);
        sem_destroy(&p->w[k].go);
        sem_destroy(&p->w[k].done);
    }
}

/* The executors a device is checked with: thread counts and orders. */
typedef struct exec_spec {
    int threads;
    order order;
} exec_spec;

#ifdef _OPENMP
#define EXECS(...) {{2, ORDER_OPENMP}, {3, ORDER_OPENMP}, {4, ORDER_OPENMP}}
#else
#define EXECS(...) {__VA_ARGS__, {2, ORDER_MOTE_POOL}, {3, ORDER_MOTE_POOL}}
#endif

/* ---- meshes and textures ------------------------------------------------ */

#define GRID 48                   /* 4608 triangles, 2401 vertices: cut into pieces */
#define BALL_R 12
#define BALL_S 24                 /* 576 triangles, 325 vertices */
#define SMALL_DRAWS 300           /* more than MOTE_MAX_DRAWS: several batches a frame */
#define SLIVERS 480               /* needles across the screen: few pixels, many tiles each */

static mote_vertex grid_v[(GRID + 1) * (GRID + 1)];
static mote_rgba grid_c[(GRID + 1) * (GRID + 1)];
static uint32_t grid_i[GRID * GRID * 6];
static mote_vertex ball_v[(BALL_R + 1) * (BALL_S + 1)];
static mote_rgba ball_c[(BALL_R + 1) * (BALL_S + 1)];
static uint32_t ball_i[BALL_R * BALL_S * 6];
static uint8_t tex64_px[64 * 64 * 4], tex_odd_px[40 * 24 * 4];
static mote_texture tex64 = {64, 64, MOTE_FORMAT_RGBA8888, 0, tex64_px};    /* a power of two: masks */
static mote_texture tex_odd = {40, 24, MOTE_FORMAT_RGBA8888, 0, tex_odd_px}; /* not: divisions */

static mote_vertex sliver_v[3 * SLIVERS];
static uint32_t sliver_i[3 * SLIVERS];

enum { M_GRID, M_GRID_COLORED, M_BALL_LIT, M_BALL_TEX, M_BALL_UNLIT, M_BALL_POINTS, M_BALL_WIRE, M_BALL_AWAY,
       M_SLIVERS, M_COUNT };
static mote_mesh meshes[M_COUNT];
static mote_mesh small[SMALL_DRAWS];

static void build_textures(void)
{
    for (int y = 0; y < 64; y++)
        for (int x = 0; x < 64; x++) {
            uint8_t *p = &tex64_px[4 * (y * 64 + x)];
            p[0] = (uint8_t)(x * 4);
            p[1] = (uint8_t)((((x >> 3) ^ (y >> 3)) & 1) ? 220 - y * 2 : 30 + y * 3);
            p[2] = (uint8_t)(y * 4);
            p[3] = 255;
        }
    for (int y = 0; y < 24; y++)
        for (int x = 0; x < 40; x++) {
            uint8_t *p = &tex_odd_px[4 * (y * 40 + x)];
            p[0] = (uint8_t)(250 - x * 6);
            p[1] = (uint8_t)(((x + y) % 5) * 50);
            p[2] = (uint8_t)(y * 10);
            p[3] = 255;
        }
}

/* A wavy height field over [-3, 3]^2 on the xz plane. */
static void build_grid(void)
{
    const int n = GRID + 1;
    for (int j = 0; j < n; j++)
        for (int i = 0; i < n; i++) {
            mote_vertex *v = &grid_v[j * n + i];
            float x = -3.0f + 6.0f * (float)i / GRID, z = -3.0f + 6.0f * (float)j / GRID;
            float y = 0.4f * sinf(1.7f * x) * cosf(1.3f * z);
            float dx = 0.68f * cosf(1.7f * x) * cosf(1.3f * z), dz = -0.52f * sinf(1.7f * x) * sinf(1.3f * z);
            float len = sqrtf(dx * dx + 1.0f + dz * dz);
            v->position[0] = x;
            v->position[1] = y;
            v->position[2] = z;
            v->normal[0] = -dx / len;
            v->normal[1] = 1.0f / len;
            v->normal[2] = -dz / len;
            v->uv[0] = 3.0f * (float)i / GRID;
            v->uv[1] = 3.0f * (float)j / GRID;
            grid_c[j * n + i] = (mote_rgba){(uint8_t)(255 - 4 * i), (uint8_t)(128 + 2 * j), (uint8_t)(5 * (i ^ j)), 255};
        }
    uint32_t *p = grid_i;
    for (int j = 0; j < GRID; j++)
        for (int i = 0; i < GRID; i++) {
            uint32_t a = (uint32_t)(j * n + i), b = a + 1, c = a + (uint32_t)n + 1, d = a + (uint32_t)n;
            const uint32_t q[6] = {a, c, d, a, b, c};   /* front faces up, seen from above */
            memcpy(p, q, sizeof q);
            p += 6;
        }
}

static void build_ball(void)
{
    int nv = 0;
    for (int i = 0; i <= BALL_R; i++)
        for (int j = 0; j <= BALL_S; j++) {
            double th = 3.141592653589793 * i / BALL_R, ph = 6.283185307179586 * j / BALL_S;
            mote_vertex *v = &ball_v[nv];
            v->normal[0] = (float)(sin(th) * cos(ph));
            v->normal[1] = (float)cos(th);
            v->normal[2] = (float)(sin(th) * sin(ph));
            memcpy(v->position, v->normal, sizeof v->position);
            v->uv[0] = 2.0f * (float)j / BALL_S;
            v->uv[1] = (float)i / BALL_R;
            ball_c[nv] = (mote_rgba){(uint8_t)(20 * i), (uint8_t)(255 - 10 * j), 200, 255};
            nv++;
        }
    uint32_t *p = ball_i;
    for (int i = 0; i < BALL_R; i++)
        for (int j = 0; j < BALL_S; j++) {
            uint32_t a = (uint32_t)(i * (BALL_S + 1) + j), b = a + 1, c = a + BALL_S + 2, d = a + BALL_S + 1;
            const uint32_t q[6] = {a, b, c, a, c, d};
            memcpy(p, q, sizeof q);
            p += 6;
        }
}

/* Needles from one edge of the view to the other (about 3 units of the
 * z = 5 plane across), each a pixel or two wide: a bounding box of most
 * tiles and a few hundred pixels, so that tile lists outgrow the arena
 * bytes a group's slice is sized by. */
static void build_slivers(void)
{
    for (int k = 0; k < SLIVERS; k++) {
        float t = (float)k / SLIVERS, a = 6.2831853f * t * 7.0f;
        float cx = 1.6f * cosf(a), cy = 1.2f * sinf(a), w = 0.004f + 0.01f * (float)(k % 3);
        const float p[3][2] = {{-cx, -cy}, {cx, cy}, {cx + w * cy, cy - w * cx}};
        for (int j = 0; j < 3; j++) {
            mote_vertex *v = &sliver_v[3 * k + j];
            v->position[0] = p[j][0];
            v->position[1] = p[j][1];
            v->position[2] = 0.05f * (float)(k % 17);
            v->normal[2] = -1.0f;
            v->uv[0] = (float)j * 0.5f + t;
            v->uv[1] = t * 4.0f;
            sliver_i[3 * k + j] = (uint32_t)(3 * k + j);
        }
    }
}

static void place(mote_mesh *m, float x, float y, float z, float s)
{
    m->position[0] = x;
    m->position[1] = y;
    m->position[2] = z;
    m->scaling[0] = m->scaling[1] = m->scaling[2] = s;
    mote_mesh_update_bounds(m);
}

static void build_meshes(void)
{
    static bool built;
    if (built)
        return;
    built = true;
    build_textures();
    build_grid();
    build_ball();
    build_slivers();
    const uint32_t nv = (GRID + 1) * (GRID + 1), bv = (BALL_R + 1) * (BALL_S + 1);
    meshes[M_GRID] = tu_mesh_of(grid_v, nv, grid_i, GRID * GRID * 6);
    meshes[M_GRID].material.texture = &tex64;
    meshes[M_GRID_COLORED] = meshes[M_GRID];
    meshes[M_GRID_COLORED].colors = grid_c;
    meshes[M_GRID_COLORED].rotation[1] = 0.3f;
    for (int m = M_BALL_LIT; m <= M_BALL_AWAY; m++)
        meshes[m] = tu_mesh_of(ball_v, bv, ball_i, BALL_R * BALL_S * 6);
    meshes[M_BALL_LIT].colors = ball_c;
    meshes[M_BALL_TEX].material.texture = &tex_odd;
    meshes[M_BALL_TEX].material.wrap_u = MOTE_WRAP_MIRROR;
    meshes[M_BALL_TEX].material.wrap_v = MOTE_WRAP_CLAMP;
    meshes[M_BALL_UNLIT].material.color = (mote_rgba){200, 90, 40, 255};
    meshes[M_BALL_UNLIT].material.color_set = true;
    meshes[M_BALL_POINTS].material.color = (mote_rgba){255, 0, 255, 255};
    meshes[M_BALL_POINTS].material.color_set = true;
    place(&meshes[M_GRID], 0, 0, 0, 1);
    place(&meshes[M_GRID_COLORED], 0, -0.3f, 0, 1.2f);
    place(&meshes[M_BALL_LIT], -1.5f, 0.8f, 0.5f, 0.9f);
    place(&meshes[M_BALL_TEX], 1.4f, 0.7f, -0.6f, 0.8f);
    place(&meshes[M_BALL_UNLIT], 0.2f, 1.1f, 1.6f, 0.6f);
    place(&meshes[M_BALL_POINTS], 0.5f, 1.6f, -1.5f, 0.7f);
    place(&meshes[M_BALL_WIRE], -0.6f, 1.5f, -0.2f, 0.5f);
    place(&meshes[M_BALL_AWAY], 0.0f, 0.0f, -500.0f, 1.0f);   /* behind every camera: culled whole */
    meshes[M_SLIVERS] = tu_mesh_of(sliver_v, 3 * SLIVERS, sliver_i, 3 * SLIVERS);
    meshes[M_SLIVERS].material.texture = &tex64;
    place(&meshes[M_SLIVERS], 0.0f, 1.0f, 0.0f, 1.0f);
    /* many small draws: 16-triangle slices of the grid, and single
     * triangles, each a mesh of its own, spread out */
    for (int k = 0; k < SMALL_DRAWS; k++) {
        uint32_t tris = k % 5 == 4 ? 1 : 16, first = (uint32_t)(k * 97 % (GRID * GRID * 2 - 16));
        small[k] = tu_mesh_of(grid_v, nv, grid_i + 3 * first, 3 * tris);
        small[k].material.texture = k % 3 == 0 ? &tex64 : k % 3 == 1 ? &tex_odd : NULL;
        small[k].colors = k % 4 == 1 ? grid_c : NULL;
        place(&small[k], 0.3f * (float)(k % 7 - 3), 0.05f * (float)(k % 11), 0.2f * (float)(k % 5 - 2), 1);
        small[k].rotation[1] = 0.02f * (float)k;
    }
}

/* ---- frames ------------------------------------------------------------- */

/* Every light type, with falloff, the camera orbiting by frame. */
static mote_frame_desc frame_of(int f, bool ortho)
{
    mote_frame_desc fr;
    memset(&fr, 0, sizeof fr);
    float a = 0.45f * (float)f;
    fr.camera.position[0] = 6.0f * sinf(a);
    fr.camera.position[1] = 3.5f;
    fr.camera.position[2] = -6.0f * cosf(a);
    fr.camera.fov = 0.8f;
    fr.camera.znear = 0.5f;
    fr.camera.zfar = 30.0f;
    if (ortho) {
        const float box[4] = {-3.5f, 4.0f, -2.5f, 3.0f};   /* off centre, not of the image's aspect */
        fr.camera.projection = MOTE_PROJECTION_ORTHOGRAPHIC;
        memcpy(fr.camera.ortho, box, sizeof box);
        fr.camera.znear = -2.0f;                         /* sees behind the camera too */
    }
    fr.light_count = 4;
    fr.lights[0].type = MOTE_LIGHT_POINT;
    fr.lights[0].position[1] = 4.0f;
    fr.lights[0].range = 12.0f;
    fr.lights[1].type = MOTE_LIGHT_DIRECTIONAL;
    fr.lights[1].direction[0] = 1.0f;
    fr.lights[1].direction[1] = -0.6f;
    fr.lights[1].color[0] = 0.4f;
    fr.lights[1].color[1] = 0.2f;
    fr.lights[1].color[2] = 0.1f;
    fr.lights[2].type = MOTE_LIGHT_HEMISPHERIC;
    fr.lights[2].direction[1] = 1.0f;
    fr.lights[2].intensity = 0.4f;
    fr.lights[2].ground_color[2] = 0.5f;
    fr.lights[3].type = MOTE_LIGHT_SPOT;
    fr.lights[3].position[0] = -1.0f;
    fr.lights[3].position[1] = 3.0f;
    fr.lights[3].position[2] = -3.0f;
    fr.lights[3].direction[0] = 0.3f;
    fr.lights[3].direction[1] = -1.0f;
    fr.lights[3].direction[2] = 0.8f;
    fr.lights[3].color[1] = 0.7f;
    fr.lights[3].spot_angle = 1.1f;
    fr.lights[3].spot_exponent = 2.5f;
    fr.lights[3].range = 9.0f;
    fr.ambient[0] = fr.ambient[1] = fr.ambient[2] = 0.1f;
    return fr;
}

static void draw(mote_device *dev, int mesh, mote_draw_desc d)
{
    TEST_ASSERT_EQUAL(MOTE_OK, mote_draw(dev, &meshes[mesh], &d));
}

typedef void (*frame_fn)(mote_device *dev, int f);

/* The big grid (cut into pieces) in every mode by frame, and lit,
 * textured and unlit balls (whole draws, set up in groups). */
static void draw_mix(mote_device *dev, int f)
{
    static const mote_mode modes[4] = {MOTE_MODE_TEXTURED, MOTE_MODE_TEXTURED, MOTE_MODE_GOURAUD, MOTE_MODE_FLAT};
    static const mote_perspective persp[4] = {MOTE_PERSPECTIVE_CORRECT, MOTE_PERSPECTIVE_SUBSPAN,
                                              MOTE_PERSPECTIVE_AFFINE, MOTE_PERSPECTIVE_CORRECT};
    const mote_filter filter = f % 2 ? MOTE_FILTER_BILINEAR : MOTE_FILTER_NEAREST;
    const mote_mode shading = f % 2 ? MOTE_MODE_FLAT : MOTE_MODE_GOURAUD;
    draw(dev, f % 2 ? M_GRID_COLORED : M_GRID,
         (mote_draw_desc){.mode = modes[f % 4], .filter = filter, .perspective = persp[f % 4]});
    draw(dev, M_BALL_LIT, (mote_draw_desc){.mode = shading, .filter = filter, .perspective = persp[(f + 1) % 4]});
    draw(dev, M_BALL_TEX,
         (mote_draw_desc){.mode = MOTE_MODE_TEXTURED, .filter = filter, .perspective = persp[(f + 2) % 4]});
    draw(dev, M_BALL_UNLIT, (mote_draw_desc){.mode = shading, .filter = filter, .perspective = persp[f % 4],
                                             .unlit = true, .cull = MOTE_CULL_NONE});
}

static void mix_seen(mote_device *dev, int f, bool ortho)
{
    mote_frame_desc fr = frame_of(f, ortho);
    TEST_ASSERT_EQUAL(MOTE_OK, mote_begin(dev, &fr));
    draw_mix(dev, f);
    TEST_ASSERT_EQUAL(MOTE_OK, mote_end(dev));
}

static void frame_mix(mote_device *dev, int f)
{
    mix_seen(dev, f, false);
}

static void frame_ortho(mote_device *dev, int f)
{
    mix_seen(dev, f, true);
}

/* Many small draws: several batches a frame, each set up in groups. */
static void frame_small(mote_device *dev, int f)
{
    mote_frame_desc fr = frame_of(f, false);
    TEST_ASSERT_EQUAL(MOTE_OK, mote_begin(dev, &fr));
    for (int k = 0; k < SMALL_DRAWS; k++) {
        mote_draw_desc d = {.mode = k % 3 == 2 ? MOTE_MODE_FLAT : MOTE_MODE_DEFAULT,
                            .filter = k % 2 ? MOTE_FILTER_BILINEAR : MOTE_FILTER_NEAREST,
                            .cull = k % 4 == 3 ? MOTE_CULL_NONE : MOTE_CULL_DEFAULT};
        TEST_ASSERT_EQUAL(MOTE_OK, mote_draw(dev, &small[k], &d));
    }
    TEST_ASSERT_EQUAL(MOTE_OK, mote_end(dev));
}

/* Points and wireframe between binned draws (which flush what is binned
 * and draw at once), frames keeping colour, depth or both. */
static void frame_lines_keep(mote_device *dev, int f)
{
    mote_frame_desc fr = frame_of(f, false);
    fr.keep_color = f == 2 || f == 4;
    fr.keep_depth = f == 3 || f == 4;
    TEST_ASSERT_EQUAL(MOTE_OK, mote_begin(dev, &fr));
    const mote_draw_desc tex = {.mode = MOTE_MODE_TEXTURED};
    if (f != 2)
        draw(dev, M_GRID, tex);
    if (f == 0 || f == 4) {
        draw(dev, M_BALL_POINTS, (mote_draw_desc){.mode = MOTE_MODE_POINTS});
        draw(dev, M_BALL_LIT, (mote_draw_desc){.mode = MOTE_MODE_GOURAUD});
        draw(dev, M_BALL_WIRE, (mote_draw_desc){.mode = MOTE_MODE_WIREFRAME, .point_color = {0, 255, 0, 255}});
    }
    draw(dev, M_BALL_TEX, tex);
    if (f >= 2)
        draw(dev, M_BALL_UNLIT, (mote_draw_desc){.mode = MOTE_MODE_FLAT});
    TEST_ASSERT_EQUAL(MOTE_OK, mote_end(dev));
}

/* The needles, facing the camera, which looks along z, a lit ball, and
 * one behind the camera, culled whole. */
static void frame_slivers(mote_device *dev, int f)
{
    mote_frame_desc fr = frame_of(f, false);
    memset(&fr.camera, 0, sizeof fr.camera);
    fr.camera.position[1] = 1.0f;
    fr.camera.position[2] = -2.6f - 0.2f * (float)f;
    fr.camera.target[1] = 1.0f;
    fr.camera.target[2] = 1.0f;
    TEST_ASSERT_EQUAL(MOTE_OK, mote_begin(dev, &fr));
    mote_draw_desc d = {.mode = f % 2 ? MOTE_MODE_GOURAUD : MOTE_MODE_TEXTURED, .cull = MOTE_CULL_NONE};
    draw(dev, M_SLIVERS, d);
    draw(dev, M_BALL_AWAY, d);
    draw(dev, M_BALL_LIT, d);
    TEST_ASSERT_EQUAL(MOTE_OK, mote_end(dev));
}

/* A frame begun again before its mote_end: the first is abandoned with
 * its draws recorded and its clear still to run (which then runs). */
static void frame_abandoned(mote_device *dev, int f)
{
    mote_frame_desc fr = frame_of(f, false);
    TEST_ASSERT_EQUAL(MOTE_OK, mote_begin(dev, &fr));
    draw(dev, M_BALL_TEX, (mote_draw_desc){.mode = MOTE_MODE_TEXTURED});
    draw(dev, M_GRID, (mote_draw_desc){.mode = MOTE_MODE_GOURAUD});
    fr = frame_of(f + 1, f % 2 == 1);
    TEST_ASSERT_EQUAL(MOTE_OK, mote_begin(dev, &fr));
    draw_mix(dev, f);
    draw(dev, M_BALL_AWAY, (mote_draw_desc){.mode = MOTE_MODE_GOURAUD});
    TEST_ASSERT_EQUAL(MOTE_OK, mote_end(dev));
}

/* ---- rendering and comparing -------------------------------------------- */

#define MAX_FRAMES 6
#define COUNT(a) ((int)(sizeof(a) / sizeof((a)[0])))

/* A device and its frames; zero fields are the defaults (with_defaults). */
typedef struct config {
    frame_fn frame;
    int frames;                   /* 0: 4 */
    int width, height;            /* 0: 203 x 151, no multiple of a tile: partial tiles at the edges */
    int tile;                     /* 0: 64 */
    int pad;                      /* bytes past each colour row */
    mote_format format;           /* 0: RGBA8888 */
    mote_depth_format depth;      /* 0: 32-bit */
    size_t arena;                 /* bytes; 0: as mote-render sizes it, never full */
    bool full_clear;              /* false: clear_drawn_tiles_only, as mote-render */
    bool hook;                    /* a triangle hook: binned on the calling thread, tiles in parallel */
} config;

static config with_defaults(config c)
{
    c.frames = c.frames ? c.frames : 4;
    c.width = c.width ? c.width : 203;
    c.height = c.height ? c.height : 151;
    c.tile = c.tile ? c.tile : 64;
    c.format = c.format ? c.format : MOTE_FORMAT_RGBA8888;
    c.depth = c.depth ? c.depth : MOTE_DEPTH_FORMAT_32;
    return c;
}

typedef struct shot {
    size_t color_bytes, depth_bytes, frame_bytes;
    uint8_t *frames;              /* per frame: colour rows with padding, then depth */
    mote_stats stats[MAX_FRAMES];
} shot;

static size_t mote_render_arena(size_t triangles)
{
    return mote_arena_bytes_per_triangle() * triangles * 2 + ((size_t)1 << 20);
}

static void count_triangle(void *user, const int32_t x[3], const int32_t y[3], const float z[3], const float w[3])
{
    (void)x;
    (void)y;
    (void)z;
    (void)w;
    ++*(long *)user;              /* called on the thread that draws, in order */
}

/* Renders c's frames on executor p (NULL: parallel_for NULL). */
static void render(const config *c, pool *p, shot *s)
{
    size_t stride = (size_t)c->width * (size_t)mote_format_bytes(c->format) + (size_t)c->pad;
    s->color_bytes = stride * (size_t)c->height;
    s->depth_bytes = (size_t)c->width * (size_t)c->height * (size_t)mote_depth_format_bytes(c->depth);
    s->frame_bytes = s->color_bytes + s->depth_bytes;
    s->frames = (uint8_t *)malloc(s->frame_bytes * (size_t)c->frames);
    size_t arena_size = c->arena ? c->arena : mote_render_arena(10000);
    uint64_t *color = (uint64_t *)malloc(s->color_bytes + 8), *depth = (uint64_t *)malloc(s->depth_bytes + 8);
    uint64_t *arena = (uint64_t *)malloc(arena_size);
    TEST_ASSERT_NOT_NULL(s->frames);
    TEST_ASSERT_NOT_NULL(color);
    TEST_ASSERT_NOT_NULL(depth);
    TEST_ASSERT_NOT_NULL(arena);
    memset(color, 0x5a, s->color_bytes);
    memset(depth, 0xa5, s->depth_bytes);
    mote_device_desc d;
    memset(&d, 0, sizeof d);
    d.width = c->width;
    d.height = c->height;
    d.color_format = c->format;
    d.color = color;
    d.color_stride = (int)stride;
    d.depth_format = c->depth;
    d.depth = c->depth == MOTE_DEPTH_FORMAT_NONE ? NULL : depth;
    d.clear_color = (mote_rgba){10, 20, 30, 255};
    d.arena = arena;
    d.arena_size = arena_size;
    d.tile_size = c->tile;
    d.clear_drawn_tiles_only = !c->full_clear;
    d.parallel_for = p ? pool_for : NULL;
    d.parallel_user = p;
    long hooked = 0;
    d.triangle_hook = c->hook ? count_triangle : NULL;
    d.triangle_hook_user = &hooked;
    mote_device dev;
    TEST_ASSERT_EQUAL(MOTE_OK, mote_device_init(&dev, &d));
    for (int f = 0; f < c->frames; f++) {
        c->frame(&dev, f);
        uint8_t *out = s->frames + s->frame_bytes * (size_t)f;
        memcpy(out, color, s->color_bytes);
        memcpy(out + s->color_bytes, depth, s->depth_bytes);
        s->stats[f] = *mote_device_stats(&dev);
    }
    TEST_ASSERT_TRUE(!c->hook || hooked > 0);
    free(arena);
    free(depth);
    free(color);
}

static void assert_same(const config *c, const shot *ref, const shot *got, const char *what)
{
    char msg[200];
    for (int f = 0; f < c->frames; f++) {
        snprintf(msg, sizeof msg, "%s, frame %d, %dx%d tile %d format %d depth %d arena %zu%s", what, f, c->width,
                 c->height, c->tile, (int)c->format, (int)c->depth, c->arena, c->full_clear ? " full clear" : "");
        const uint8_t *a = ref->frames + ref->frame_bytes * (size_t)f, *b = got->frames + got->frame_bytes * (size_t)f;
        TEST_ASSERT_EQUAL_MEMORY_MESSAGE(a, b, ref->color_bytes, msg);
        if (ref->depth_bytes)
            TEST_ASSERT_EQUAL_MEMORY_MESSAGE(a + ref->color_bytes, b + ref->color_bytes, ref->depth_bytes, msg);
        const mote_stats *x = &ref->stats[f], *y = &got->stats[f];
        TEST_ASSERT_EQUAL_UINT32_MESSAGE(x->draws, y->draws, msg);
        TEST_ASSERT_EQUAL_UINT32_MESSAGE(x->triangles_in, y->triangles_in, msg);
        TEST_ASSERT_EQUAL_UINT32_MESSAGE(x->triangles_drawn, y->triangles_drawn, msg);
        TEST_ASSERT_EQUAL_UINT32_MESSAGE(x->tiles_clear_skipped, y->tiles_clear_skipped, msg);
        TEST_ASSERT_EQUAL_UINT64_MESSAGE(x->pixels_tested, y->pixels_tested, msg);
        TEST_ASSERT_EQUAL_UINT64_MESSAGE(x->pixels_written, y->pixels_written, msg);
    }
}

/* What the checks of a test did, for its figures. */
typedef struct tally {
    long runs, steps, shared_steps, flushes, skipped;
} tally;

/* Renders each config with parallel_for NULL, then on each executor, and
 * compares; prints what was done and returns it. */
static tally check(const char *name, const config *configs, int nc, const exec_spec *execs, int ne)
{
    build_meshes();
    tally t = {0, 0, 0, 0, 0};
    for (int i = 0; i < nc; i++) {
        const config c = with_defaults(configs[i]);
        shot ref, got;
        render(&c, NULL, &ref);
        for (int e = 0; e < ne; e++) {
            pool p;
            pool_start(&p, execs[e].threads, execs[e].order);
            render(&c, &p, &got);
            pool_stop(&p);
            char what[40];
            snprintf(what, sizeof what, "%d threads, %s", execs[e].threads, order_names[execs[e].order]);
            assert_same(&c, &ref, &got, what);
            t.runs++;
            t.steps += p.steps;
            t.shared_steps += p.shared_steps;
            for (int f = 0; f < c.frames; f++) {
                t.flushes += got.stats[f].arena_flushes;
                t.skipped += got.stats[f].tiles_clear_skipped;
            }
            free(got.frames);
        }
        free(ref.frames);
    }
    printf("%s: %d devices, %ld runs, %ld parallel steps (%ld on two threads or more), %ld arena flushes, "
           "%ld tile clears skipped\n",
           name, nc, t.runs, t.steps, t.shared_steps, t.flushes, t.skipped);
    TEST_ASSERT_TRUE_MESSAGE(t.shared_steps > 0, "no step ran on two threads");
    return t;
}

/* ---- the tests ---------------------------------------------------------- */

/* A big draw cut into pieces (its vertices prepared in parallel chunks),
 * whole draws in groups, the clear's stripes beside them, and the tiles,
 * on 2 to 8 threads, every order, tiles from 8 to 256 pixels. */
void big_draws_in_pieces_should_race_nowhere_and_match_one_thread(void)
{
    static const exec_spec execs[] = EXECS({2, ORDER_STRIDE}, {2, ORDER_FRONT}, {3, ORDER_BACK}, {4, ORDER_STRIDE},
                                           {5, ORDER_FRONT}, {8, ORDER_STRIDE});
    static const config configs[] = {{.frame = frame_mix, .tile = 8},
                                     {.frame = frame_mix, .tile = 16, .full_clear = true},
                                     {.frame = frame_mix, .tile = 64},
                                     {.frame = frame_mix, .tile = 256, .full_clear = true}};
    check("big draws", configs, COUNT(configs), execs, COUNT(execs));
}

/* 300 small draws a frame: batches of MOTE_MAX_DRAWS set up in groups
 * mid-frame, textured, Gouraud, flat, with and without vertex colours. */
void many_small_draws_in_batches_should_race_nowhere_and_match_one_thread(void)
{
    static const exec_spec execs[] = EXECS({2, ORDER_STRIDE}, {3, ORDER_FRONT}, {4, ORDER_BACK}, {7, ORDER_STRIDE});
    static const config configs[] = {{.frame = frame_small, .frames = 3, .tile = 32},
                                     {.frame = frame_small, .frames = 3, .tile = 16, .full_clear = true}};
    check("small draws", configs, COUNT(configs), execs, COUNT(execs));
}

/* Arenas that fill up: the groups' slices too small (the batch binned
 * serially instead), and the frame flushing its tiles mid-frame, more
 * than once. */
void arenas_that_fill_mid_frame_should_race_nowhere_and_match_one_thread(void)
{
    static const exec_spec execs[] = EXECS({2, ORDER_STRIDE}, {3, ORDER_FRONT}, {6, ORDER_BACK});
    static const config configs[] = {{.frame = frame_mix, .frames = 3, .tile = 32, .arena = 64u << 10},
                                     {.frame = frame_small, .frames = 3, .tile = 32, .arena = 160u << 10,
                                      .full_clear = true},
                                     {.frame = frame_mix, .frames = 3, .tile = 8, .arena = 400u << 10}};
    tally t = check("small arenas", configs, COUNT(configs), execs, COUNT(execs));
    TEST_ASSERT_TRUE_MESSAGE(t.flushes > 0, "no arena filled up");
}

/* Arena sizes from one that barely bins to one that holds every frame,
 * each 1.3 times the last: the groups' slices sized in proportion to a
 * space smaller than their estimates, groups whose slice runs out (long
 * tile lists of the needles; the batch is then binned serially), the
 * scratch not fitting (serial), flushes mid-frame. */
void arena_sizes_swept_should_race_nowhere_and_match_one_thread(void)
{
    static const exec_spec execs[] = EXECS({2, ORDER_STRIDE}, {3, ORDER_BACK});
    config configs[20];
    int n = 0;
    for (size_t size = 40u << 10; size < (3u << 20); size = size * 13 / 10, n++) {
        TEST_ASSERT_TRUE(n < COUNT(configs));
        memset(&configs[n], 0, sizeof configs[n]);
        configs[n].frame = n % 2 ? frame_mix : frame_slivers;
        configs[n].frames = 2;
        configs[n].tile = n % 3 ? 8 : 16;
        configs[n].arena = size;
        configs[n].full_clear = n % 2;
    }
    tally t = check("arena sweep", configs, n, execs, COUNT(execs));
    TEST_ASSERT_TRUE_MESSAGE(t.flushes > 0, "no arena filled up");
}

/* Points and wireframe between binned draws, frames keeping the colour,
 * the depth or both, with and without clear_drawn_tiles_only. */
void points_wireframe_and_kept_buffers_should_race_nowhere_and_match_one_thread(void)
{
    static const exec_spec execs[] = EXECS({2, ORDER_STRIDE}, {3, ORDER_BACK}, {4, ORDER_FRONT});
    static const config configs[] = {{.frame = frame_lines_keep, .frames = 6, .tile = 16},
                                     {.frame = frame_lines_keep, .frames = 6, .full_clear = true}};
    tally t = check("points, wireframe, keep", configs, COUNT(configs), execs, COUNT(execs));
    TEST_ASSERT_TRUE_MESSAGE(t.skipped > 0, "no tile clear was skipped");
}

/* Pixels of 1 and 2 bytes, 16-bit and no depth, padded rows, 8-pixel
 * tiles: neighbouring tiles share cache lines and words of a row. */
void narrow_pixels_and_tiles_should_race_nowhere_and_match_one_thread(void)
{
    static const exec_spec execs[] = EXECS({2, ORDER_STRIDE}, {4, ORDER_STRIDE}, {3, ORDER_FRONT});
    static const config configs[] = {
        {.frame = frame_mix, .frames = 2, .tile = 8, .pad = 2, .format = MOTE_FORMAT_GREY8,
         .depth = MOTE_DEPTH_FORMAT_16},
        {.frame = frame_mix, .frames = 2, .tile = 8, .pad = 6, .format = MOTE_FORMAT_RGB565,
         .depth = MOTE_DEPTH_FORMAT_NONE},
        {.frame = frame_mix, .frames = 2, .tile = 8, .pad = 10, .format = MOTE_FORMAT_RGB565_SWAPPED}};
    check("narrow pixels", configs, COUNT(configs), execs, COUNT(execs));
}

/* An orthographic camera (one w at every corner: the affine variants). */
void orthographic_frames_should_race_nowhere_and_match_one_thread(void)
{
    static const exec_spec execs[] = EXECS({2, ORDER_STRIDE}, {4, ORDER_BACK}, {8, ORDER_FRONT});
    static const config configs[] = {{.frame = frame_ortho, .frames = 3, .tile = 8, .full_clear = true},
                                     {.frame = frame_ortho, .frames = 3, .tile = 32}};
    check("orthographic", configs, COUNT(configs), execs, COUNT(execs));
}

/* A triangle hook (the draws are then binned on the calling thread, the
 * clear and the tiles still run in parallel), and frames begun again
 * before their end, whose clear was still to run. */
void hooked_and_abandoned_frames_should_race_nowhere_and_match_one_thread(void)
{
    static const exec_spec execs[] = EXECS({2, ORDER_STRIDE}, {4, ORDER_FRONT});
    static const config configs[] = {{.frame = frame_abandoned, .frames = 3},
                                     {.frame = frame_abandoned, .frames = 3, .tile = 16, .hook = true},
                                     {.frame = frame_mix, .frames = 3, .hook = true, .full_clear = true},
                                     {.frame = frame_mix, .frames = 3, .tile = 16, .hook = true}};
    check("hooked, abandoned", configs, COUNT(configs), execs, COUNT(execs));
}

/* ---- Suzanne, loaded and drawn as mote-render draws it ----------------- */

#define MONKEY MOTE_SOURCE_DIR "/../shared/assets/monkey.babylon"
#define MONKEY_MESHES 4

static mote_scene monkey;
static mote_mesh monkey_posed[9][MONKEY_MESHES];

/* mote-render's path: the scene's frame and draw options
 * (mote_scene_draw_desc), its meshes turned about y by frame (posed
 * before the frame, as mote-render does); copies of it in a 3x3 grid,
 * or one. */
static void monkey_frame(mote_device *dev, int f, int copies)
{
    mote_frame_desc fr;
    mote_scene_frame(&monkey, 320.0f / 240.0f, &fr);
    if (copies > 1) {
        fr.camera.position[2] -= 6.0f;
        fr.camera.position[1] += 1.0f;
    }
    for (int k = 0; k < copies; k++)
        for (int i = 0; i < monkey.mesh_count && i < MONKEY_MESHES; i++) {
            mote_mesh *m = &monkey_posed[k][i];
            *m = monkey.meshes[i];
            if (copies > 1) {
                m->position[0] += 2.6f * (float)(k % 3 - 1);
                m->position[1] += 2.2f * (float)(k / 3 - 1);
            }
            m->rotation[1] += 0.35f * (float)f;
        }
    TEST_ASSERT_EQUAL(MOTE_OK, mote_begin(dev, &fr));
    for (int k = 0; k < copies; k++)
        for (int i = 0; i < monkey.mesh_count && i < MONKEY_MESHES; i++) {
            mote_draw_desc d;
            mote_scene_draw_desc(&monkey, i, NULL, &d);
            d.filter = f == 2 ? MOTE_FILTER_BILINEAR : d.filter;
            TEST_ASSERT_EQUAL(MOTE_OK, mote_draw(dev, &monkey_posed[k][i], &d));
        }
    TEST_ASSERT_EQUAL(MOTE_OK, mote_end(dev));
}

static void frame_monkey(mote_device *dev, int f)
{
    monkey_frame(dev, f, 1);
}

static void frame_monkeys(mote_device *dev, int f)
{
    monkey_frame(dev, f, 9);
}

void suzanne_as_mote_render_draws_it_should_race_nowhere_and_match_one_thread(void)
{
    char msg[256] = "";
    FILE *probe = fopen(MONKEY, "rb");
    if (!probe)
        TEST_IGNORE_MESSAGE("../shared/assets/monkey.babylon is absent");
    fclose(probe);
    TEST_ASSERT_EQUAL_MESSAGE(MOTE_OK, mote_scene_load(MONKEY, NULL, &monkey, msg, sizeof msg), msg);
    static const exec_spec execs[] = EXECS({2, ORDER_STRIDE}, {4, ORDER_FRONT}, {8, ORDER_BACK});
    static const config configs[] = {{.frame = frame_monkey, .width = 320, .height = 240},
                                     {.frame = frame_monkeys, .width = 320, .height = 240, .tile = 32}};
    check("Suzanne", configs, COUNT(configs), execs, COUNT(execs));
    mote_scene_free(&monkey);
}

/* ---- devices on several threads ---------------------------------------- */

/* The core keeps no global mutable state, and the io library's is atomic:
 * devices of their own on several threads at once, each loading the demo
 * scene itself and drawing it, the shared meshes and textures only read,
 * give each the bytes of one device alone. */
typedef struct lone {
    const config *c;
    pool *p;
    shot s;
    mote_result loaded;
    int meshes;
} lone;

static void *lone_render(void *arg)
{
    lone *l = (lone *)arg;
    mote_scene scene;
    char msg[128];
    l->loaded = mote_scene_load(MOTE_SOURCE_DIR "/assets/demo.babylon", NULL, &scene, msg, sizeof msg);
    if (l->loaded == MOTE_OK) {
        l->meshes = scene.mesh_count;
        mote_scene_free(&scene);
    }
    render(l->c, l->p, &l->s);
    return NULL;
}

void devices_on_several_threads_should_share_nothing(void)
{
    enum { DEVICES = 3 };
    static const exec_spec execs[] = EXECS({2, ORDER_STRIDE});
    build_meshes();
    const config c = with_defaults((config){.frame = frame_mix, .frames = 2});
    shot ref;
    render(&c, NULL, &ref);
    pool p;
    pool_start(&p, execs[0].threads, execs[0].order);
    lone l[DEVICES];
    pthread_t th[DEVICES];
    memset(l, 0, sizeof l);
    for (int k = 0; k < DEVICES; k++) {
        l[k].c = &c;
        l[k].p = k == 0 ? &p : NULL;   /* one through a pool of its own */
        TEST_ASSERT_EQUAL(0, pthread_create(&th[k], NULL, lone_render, &l[k]));
    }
    for (int k = 0; k < DEVICES; k++)
        pthread_join(th[k], NULL);
    pool_stop(&p);
    for (int k = 0; k < DEVICES; k++) {
        TEST_ASSERT_EQUAL(MOTE_OK, l[k].loaded);
        TEST_ASSERT_EQUAL(l[0].meshes, l[k].meshes);
        assert_same(&c, &ref, &l[k].s, k ? "a device alone on its thread" : "a device on a pool");
        free(l[k].s.frames);
    }
    free(ref.frames);
}

int main(void)
{
    UNITY_BEGIN();
    RUN_TEST(big_draws_in_pieces_should_race_nowhere_and_match_one_thread);
    RUN_TEST(many_small_draws_in_batches_should_race_nowhere_and_match_one_thread);
    RUN_TEST(arenas_that_fill_mid_frame_should_race_nowhere_and_match_one_thread);
    RUN_TEST(arena_sizes_swept_should_race_nowhere_and_match_one_thread);
    RUN_TEST(points_wireframe_and_kept_buffers_should_race_nowhere_and_match_one_thread);
    RUN_TEST(narrow_pixels_and_tiles_should_race_nowhere_and_match_one_thread);
    RUN_TEST(orthographic_frames_should_race_nowhere_and_match_one_thread);
    RUN_TEST(hooked_and_abandoned_frames_should_race_nowhere_and_match_one_thread);
    RUN_TEST(suzanne_as_mote_render_draws_it_should_race_nowhere_and_match_one_thread);
    RUN_TEST(devices_on_several_threads_should_share_nothing);
    return UNITY_END();
}
