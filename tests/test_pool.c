/*
 * test_pool.c - the thread pool of src/host/pool.c: every task run once,
 * the same frame bytes for any thread count and with a pool thread that
 * is late to every call, a call that returns while a pool thread is
 * still held, calls from inside a task, and its errors.
 */
#define _POSIX_C_SOURCE 200809L /* nanosleep, clock_gettime */
#include "support/io_test.h"
#include "support/scenes.h"

#include <pthread.h>
#include <time.h>

IO_TEST_FIXTURE

enum { W = 160, H = 120, GRID = 24, COPIES = 6 };

/* ---- tasks --------------------------------------------------------------- */

typedef struct count_job {
    int *runs;
    mote_pool *pool;              /* calls the pool again from its tasks when set */
    int inner;
} count_job;

static void count_task(void *arg, int i)
{
    count_job *j = (count_job *)arg;
    __atomic_add_fetch(&j->runs[i], 1, __ATOMIC_RELAXED);
    if (j->pool && j->inner > 0) {
        int inner_runs[8] = {0};
        count_job in = {inner_runs, j->pool, 0};
        mote_parallel_pool(j->pool, j->inner, count_task, &in);
        for (int k = 0; k < j->inner; k++)
            TEST_ASSERT_EQUAL_INT(1, inner_runs[k]);
    }
}

static void check_each_task_once(mote_pool *pool, int count)
{
    int *runs = (int *)calloc((size_t)(count > 0 ? count : 1), sizeof *runs);
    TEST_ASSERT_NOT_NULL(runs);
    count_job j = {runs, NULL, 0};
    mote_parallel_pool(pool, count, count_task, &j);
    for (int i = 0; i < count; i++)
        if (runs[i] != 1)
            TEST_FAIL_MESSAGE("a task did not run exactly once");
    free(runs);
}

static mote_pool *pool_of(int threads, void (*on_wake)(void *, int), void *user)
{
    mote_pool_desc d = {threads, on_wake, user};
    mote_pool *pool = NULL;
    TEST_ASSERT_EQUAL_MESSAGE(MOTE_OK, mote_pool_create(&d, &pool, msg, sizeof msg), msg);
    TEST_ASSERT_NOT_NULL(pool);
    return pool;
}

void test_pool_runs_every_task_exactly_once(void)
{
    static const int threads[] = {1, 2, 3, 8};
    /* 300,000 is more than two threads' runs hold in one step */
    static const int counts[] = {0, 1, 2, 3, 7, 64, 1000, 300000};
    for (size_t t = 0; t < sizeof threads / sizeof threads[0]; t++) {
        mote_pool *pool = pool_of(threads[t], NULL, NULL);
        TEST_ASSERT_EQUAL_INT(threads[t], mote_pool_threads(pool));
        for (int round = 0; round < 20; round++)
            for (size_t c = 0; c < sizeof counts / sizeof counts[0]; c++)
                check_each_task_once(pool, counts[c]);
        mote_pool_destroy(pool);
    }
    check_each_task_once(NULL, 100);   /* no pool: this thread alone */
}

void test_pool_called_from_its_own_task_runs_that_call_on_the_task_thread(void)
{
    mote_pool *pool = pool_of(3, NULL, NULL);
    int runs[40] = {0};
    count_job j = {runs, pool, 8};
    mote_parallel_pool(pool, 40, count_task, &j);
    for (int i = 0; i < 40; i++)
        TEST_ASSERT_EQUAL_INT(1, runs[i]);
    mote_pool_destroy(pool);
}

/* ---- a call that does not wait for a late thread ------------------------ */

/* Pool thread 1 is held at its wake until released (or a few seconds
 * pass): the call must return without it. */
typedef struct hold {
    pthread_mutex_t lock;
    pthread_cond_t cond;
    bool released, timed_out;
    int wakes;
} hold;

static void hold_on_wake(void *user, int thread)
{
    hold *h = (hold *)user;
    if (thread != 1)
        return;
    struct timespec until;
    clock_gettime(CLOCK_REALTIME, &until);
    until.tv_sec += 5;
    pthread_mutex_lock(&h->lock);
    h->wakes++;
    while (!h->released && !h->timed_out)
        if (pthread_cond_timedwait(&h->cond, &h->lock, &until) != 0)
            h->timed_out = true;
    pthread_mutex_unlock(&h->lock);
}

void test_pool_call_returns_while_a_pool_thread_is_still_held(void)
{
    hold h = {PTHREAD_MUTEX_INITIALIZER, PTHREAD_COND_INITIALIZER, false, false, 0};
    mote_pool *pool = pool_of(2, hold_on_wake, &h);
    int runs[500] = {0};
    count_job j = {runs, NULL, 0};
    mote_parallel_pool(pool, 500, count_task, &j);
    pthread_mutex_lock(&h.lock);
    bool returned_first = !h.timed_out;
    h.released = true;
    pthread_cond_broadcast(&h.cond);
    pthread_mutex_unlock(&h.lock);
    TEST_ASSERT_TRUE_MESSAGE(returned_first, "the call waited for the held thread");
    for (int i = 0; i < 500; i++)
        TEST_ASSERT_EQUAL_INT(1, runs[i]);
    /* the released thread comes back to a finished call: it takes nothing
     * from it, and the next calls still run every task once */
    for (int round = 0; round < 50; round++)
        check_each_task_once(pool, 333);
    mote_pool_destroy(pool);
}

/* ---- frames ---------------------------------------------------------------- */

/* A wavy GRID x GRID sheet, COPIES of it turned about, and the textured
 * test scene: enough triangles that binning is cut into parallel groups
 * and the tiles are many. */
static mote_vertex sheet_v[(GRID + 1) * (GRID + 1)];
static uint32_t sheet_i[GRID * GRID * 6];

static void build_sheet(void)
{
    for (int y = 0; y <= GRID; y++)
        for (int x = 0; x <= GRID; x++) {
            mote_vertex *v = &sheet_v[y * (GRID + 1) + x];
            memset(v, 0, sizeof *v);
            float fx = (float)x / GRID - 0.5f, fy = (float)y / GRID - 0.5f;
            v->position[0] = 2.0f * fx;
            v->position[1] = 2.0f * fy;
            v->position[2] = 0.15f * sinf(9.0f * fx) * cosf(7.0f * fy);
            v->normal[2] = -1.0f;
            v->normal[0] = 0.3f * fx;
            v->uv[0] = (float)x / GRID;
            v->uv[1] = (float)y / GRID;
        }
    uint32_t *p = sheet_i;
    for (int y = 0; y < GRID; y++)
        for (int x = 0; x < GRID; x++) {
            uint32_t a = (uint32_t)(y * (GRID + 1) + x), b = a + 1, c = a + GRID + 1, d = c + 1;
            *p++ = a, *p++ = c, *p++ = b;
            *p++ = b, *p++ = c, *p++ = d;
        }
}

/* Renders three frames of the scene through parallel_for (NULL: binned
 * on this thread) and returns the last one's colour and depth bytes. */
static void render(mote_parallel_for_fn parallel_for, void *user, uint8_t *color, uint32_t *depth)
{
    static unsigned char arena[4 << 20];
    tu_scene sc;
    tu_scene_build(TU_SCENE_TEXTURED, MOTE_WRAP_REPEAT, &sc);
    mote_mesh meshes[TU_SCENE_MAX_MESHES + COPIES];
    int n = 0;
    for (int i = 0; i < sc.mesh_count; i++)
        meshes[n++] = sc.meshes[i];
    for (int k = 0; k < COPIES; k++) {
        mote_mesh m = tu_mesh_of(sheet_v, (GRID + 1) * (GRID + 1), sheet_i, GRID * GRID * 6);
        m.material.texture = tu_scene_texture();
        m.position[0] = 0.9f * (float)(k % 3) - 0.9f;
        m.position[1] = 0.8f * (float)(k / 3) - 0.4f;
        m.position[2] = 0.3f * (float)k;
        m.rotation[2] = 0.4f * (float)k;
        meshes[n++] = m;
    }
    const mote_device_desc d = {.width = W, .height = H, .color = color, .depth = depth,
                                .clear_color = {10, 20, 30, 255}, .arena = arena, .arena_size = sizeof arena,
                                .tile_size = 16, .parallel_for = parallel_for, .parallel_user = user};
    mote_device dev;
    TEST_ASSERT_EQUAL(MOTE_OK, mote_device_init(&dev, &d));
    mote_draw_desc dd;
    memset(&dd, 0, sizeof dd);
    dd.mode = MOTE_MODE_TEXTURED;
    dd.cull = MOTE_CULL_NONE;     /* the sheets' both sides */
    for (int frame = 0; frame < 3; frame++) {
        for (int i = sc.mesh_count; i < n; i++)
            meshes[i].rotation[1] = 0.2f * (float)frame;
        TEST_ASSERT_EQUAL(MOTE_OK, mote_begin(&dev, &sc.frame));
        for (int i = 0; i < n; i++)
            TEST_ASSERT_EQUAL(MOTE_OK, mote_draw(&dev, &meshes[i], &dd));
        TEST_ASSERT_EQUAL(MOTE_OK, mote_end(&dev));
    }
}

static uint8_t ref_color[W * H * 4], got_color[W * H * 4];
static uint32_t ref_depth[W * H], got_depth[W * H];

static void check_frame(mote_pool *pool)
{
    memset(got_color, 0, sizeof got_color);
    memset(got_depth, 0, sizeof got_depth);
    render(mote_parallel_pool, pool, got_color, got_depth);
    TEST_ASSERT_EQUAL_MEMORY(ref_color, got_color, sizeof ref_color);
    TEST_ASSERT_EQUAL_MEMORY(ref_depth, got_depth, sizeof ref_depth);
}

void test_pool_frames_have_the_same_bytes_for_1_2_3_and_8_threads(void)
{
    build_sheet();
    render(NULL, NULL, ref_color, ref_depth);
    static const int threads[] = {1, 2, 3, 8};
    for (size_t t = 0; t < sizeof threads / sizeof threads[0]; t++) {
        mote_pool *pool = pool_of(threads[t], NULL, NULL);
        check_frame(pool);
        mote_pool_destroy(pool);
    }
}

/* Pool thread 1 sleeps each time it wakes for a call: it comes to each
 * of the frame's steps late, often after the call has returned. */
static void sleep_on_wake(void *user, int thread)
{
    if (thread != 1)
        return;
    __atomic_add_fetch((int *)user, 1, __ATOMIC_RELAXED);
    struct timespec ts = {0, 2000000};
    nanosleep(&ts, NULL);
}

void test_pool_frame_with_a_thread_that_sleeps_before_taking_work_has_the_same_bytes(void)
{
    build_sheet();
    render(NULL, NULL, ref_color, ref_depth);
    for (int threads = 2; threads <= 3; threads++) {
        int wakes = 0;
        mote_pool *pool = pool_of(threads, sleep_on_wake, &wakes);
        /* on a loaded machine the thread may not run at all during a
         * frame (the frame does not wait for it): until it has woken */
        for (int tries = 0; tries < 100 && !__atomic_load_n(&wakes, __ATOMIC_RELAXED); tries++)
            check_frame(pool);
        check_frame(pool);
        mote_pool_destroy(pool);
        TEST_ASSERT_TRUE(__atomic_load_n(&wakes, __ATOMIC_RELAXED) > 0);
    }
}

/* ---- errors ----------------------------------------------------------------- */

void test_pool_create_refuses_a_bad_thread_count_naming_it(void)
{
    mote_pool *pool = (mote_pool *)&pool;
    mote_pool_desc d = {-1, NULL, NULL};
    TEST_ASSERT_EQUAL(MOTE_ERR_RANGE, mote_pool_create(&d, &pool, msg, sizeof msg));
    TEST_ASSERT_NULL(pool);
    TEST_ASSERT_NOT_NULL(strstr(msg, "-1"));
    d.threads = 5000;
    TEST_ASSERT_EQUAL(MOTE_ERR_RANGE, mote_pool_create(&d, &pool, msg, sizeof msg));
    TEST_ASSERT_EQUAL(MOTE_ERR_INVALID_ARGUMENT, mote_pool_create(&d, NULL, msg, sizeof msg));
    mote_pool_destroy(NULL);
}

void test_pool_create_with_no_desc_uses_the_cores_online(void)
{
    mote_pool *pool = NULL;
    TEST_ASSERT_EQUAL(MOTE_OK, mote_pool_create(NULL, &pool, msg, sizeof msg));
    TEST_ASSERT_TRUE(mote_pool_threads(pool) >= 1);
    check_each_task_once(pool, 100);
    mote_pool_destroy(pool);
}

void test_pool_create_out_of_memory_frees_what_it_made(void)
{
    for (int n = 0; n < 8; n++) {
        mote_pool_desc d = {4, NULL, NULL};
        mote_pool *pool = NULL;
        mote__io_set_alloc_failure_after(n);
        mote_result r = mote_pool_create(&d, &pool, msg, sizeof msg);
        mote__io_set_alloc_failure_after(-1);
        if (r == MOTE_OK) {
            check_each_task_once(pool, 50);
            mote_pool_destroy(pool);
        } else {
            TEST_ASSERT_EQUAL(MOTE_ERR_OUT_OF_MEMORY, r);
            TEST_ASSERT_NULL(pool);
            TEST_ASSERT_NOT_NULL(strstr(msg, "out of memory"));
        }
        TEST_ASSERT_EQUAL(live_before, mote__io_live_allocations());
    }
}

int main(void)
{
    UNITY_BEGIN();
    RUN_TEST(test_pool_runs_every_task_exactly_once);
    RUN_TEST(test_pool_called_from_its_own_task_runs_that_call_on_the_task_thread);
    RUN_TEST(test_pool_call_returns_while_a_pool_thread_is_still_held);
    RUN_TEST(test_pool_frames_have_the_same_bytes_for_1_2_3_and_8_threads);
    RUN_TEST(test_pool_frame_with_a_thread_that_sleeps_before_taking_work_has_the_same_bytes);
    RUN_TEST(test_pool_create_refuses_a_bad_thread_count_naming_it);
    RUN_TEST(test_pool_create_with_no_desc_uses_the_cores_online);
    RUN_TEST(test_pool_create_out_of_memory_frees_what_it_made);
    return UNITY_END();
}
