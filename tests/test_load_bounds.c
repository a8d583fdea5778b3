/*
 * test_load_bounds.c - scenes built to exhaust memory or time, generated
 * here, end in a clear error naming the limit, within the memory
 * docs/security.md states: a 20 MB scene whose parsed JSON would take
 * 800 MB (limits.max_json_bytes), 100,000 full-screen triangles drawn 11
 * times by 10 instances, and 2,000 instances of them
 * (limits.max_triangles), each loaded with the default limits.
 *
 * Each load runs in a child process, whose peak resident memory the
 * parent reads (wait4); it is printed with the time taken, and checked
 * against the bound, but for sanitizer builds (their shadow memory is
 * not the loader's). Times are printed, not checked.
 */
#define _DEFAULT_SOURCE           /* wait4 */
#include "support/io_test.h"

#include <sys/resource.h>
#include <sys/time.h>
#include <sys/wait.h>
#include <time.h>
#include <unistd.h>

#if defined(__SANITIZE_ADDRESS__)
#define SANITIZED 1
#elif defined(__has_feature)
#if __has_feature(address_sanitizer)
#define SANITIZED 1
#endif
#endif

void setUp(void) {}
void tearDown(void) {}

/* A growing text. */
typedef struct text {
    char *s;
    size_t len, cap;
} text;

static void put(text *t, const char *s)
{
    size_t n = strlen(s);
    if (t->len + n + 1 > t->cap) {
        t->cap = (t->len + n + 1) * 2;
        t->s = realloc(t->s, t->cap);
        TEST_ASSERT_NOT_NULL(t->s);
    }
    memcpy(t->s + t->len, s, n + 1);
    t->len += n;
}

/* What a load in a child process gave: its result, its message, the
 * child's peak resident memory and the time taken. */
typedef struct bounded_load {
    mote_result result;
    char message[256];
    double peak_mib, seconds;
} bounded_load;

/* Loads the scene in t (name in messages) in a child process with the
 * default limits. */
static bounded_load load_in_child(const text *t, const char *name)
{
    bounded_load out;
    memset(&out, 0, sizeof out);
    int pipe_fd[2];
    TEST_ASSERT_EQUAL(0, pipe(pipe_fd));
    fflush(stdout);
    struct timespec t0, t1;
    clock_gettime(CLOCK_MONOTONIC, &t0);
    pid_t pid = fork();
    TEST_ASSERT_TRUE(pid >= 0);
    if (pid == 0) {
        close(pipe_fd[0]);
        mote_scene s;
        bounded_load got;
        memset(&got, 0, sizeof got);
        got.result = mote_scene_load_memory(t->s, t->len, name, NULL, NULL, &s, got.message,
                                            sizeof got.message);
        mote_scene_free(&s);
        ssize_t w = write(pipe_fd[1], &got, sizeof got);
        _exit(w == (ssize_t)sizeof got ? 0 : 1);
    }
    close(pipe_fd[1]);
    ssize_t got = read(pipe_fd[0], &out, sizeof out);
    close(pipe_fd[0]);
    int status = 0;
    struct rusage ru;
    TEST_ASSERT_EQUAL(pid, wait4(pid, &status, 0, &ru));
    clock_gettime(CLOCK_MONOTONIC, &t1);
    TEST_ASSERT_TRUE_MESSAGE(WIFEXITED(status) && WEXITSTATUS(status) == 0, "the child failed");
    TEST_ASSERT_EQUAL((ssize_t)sizeof out, got);
    out.peak_mib = (double)ru.ru_maxrss / 1024.0;   /* kilobytes on Linux */
    out.seconds = (double)(t1.tv_sec - t0.tv_sec) + 1e-9 * (double)(t1.tv_nsec - t0.tv_nsec);
    printf("  %s: %.1f MB of text: %.1f MiB peak resident, %.2f s: %s\n", name,
           (double)t->len / 1e6, out.peak_mib, out.seconds, out.message);
    return out;
}

/* The child's peak within bound_mib, unless sanitizers inflate it. */
static void assert_peak_within(const bounded_load *l, double bound_mib)
{
#ifndef SANITIZED
    char why[96];
    snprintf(why, sizeof why, "peak %.1f MiB, more than %.0f MiB", l->peak_mib, bound_mib);
    TEST_ASSERT_TRUE_MESSAGE(l->peak_mib <= bound_mib, why);
#else
    (void)l;
    (void)bound_mib;
#endif
}

/* 20 MB of "0," (positions of a mesh): cJSON would take 40 times that;
 * told from the text, it is refused before anything is parsed. */
void a_scene_whose_parsed_json_passes_the_budget_should_be_refused_before_parsing(void)
{
    text t = {0};
    put(&t, "{\"meshes\":[{\"id\":\"m\",\"positions\":[0");
    char chunk[2001];
    for (int i = 0; i < 1000; i++)
        memcpy(chunk + 2 * i, ",0", 2);
    chunk[2000] = '\0';
    for (int i = 0; i < 10000; i++)
        put(&t, chunk);
    put(&t, "]}]}");
    bounded_load l = load_in_child(&t, "big.babylon");
    TEST_ASSERT_EQUAL(MOTE_ERR_LIMIT, l.result);
    TEST_ASSERT_NOT_NULL_MESSAGE(strstr(l.message, "big.babylon: parsing its JSON (10000007 "
                                        "values) would take 762.9 MiB, more than the limit of "
                                        "512.0 MiB (max_json_bytes)"), l.message);
    /* the text (20 MB, held by the parent too) and the process */
    assert_peak_within(&l, 20.0 + 32.0);
    free(t.s);
}

/* A mesh of `triangles` triangles that each cover the whole view of a
 * camera at z = -1 (three shared corners far out), with `instances`
 * instances. */
static text full_screen_triangles(int triangles, int instances)
{
    text t = {0};
    put(&t, "{\"cameras\":[{\"id\":\"c\",\"position\":[0,0,-1],\"target\":[0,0,0]}],"
            "\"materials\":[{\"id\":\"w\",\"backFaceCulling\":false}],"
            "\"meshes\":[{\"id\":\"m\",\"materialId\":\"w\","
            "\"positions\":[-100,-100,0, 100,-100,0, 0,100,0],\"indices\":[0,1,2");
    for (int i = 1; i < triangles; i++)
        put(&t, ",0,1,2");
    put(&t, "],\"instances\":[");
    char one[64];
    for (int i = 0; i < instances; i++) {
        snprintf(one, sizeof one, "%s{\"name\":\"i%d\",\"position\":[0,0,%d]}", i ? "," : "", i,
                 i);
        put(&t, one);
    }
    put(&t, "]}]}");
    return t;
}

/* 100,000 full-screen triangles with `instances` instances, loaded in a
 * child: refused with `message`, within 64 MiB. */
static void expect_triangle_limit(int instances, const char *name, const char *message)
{
    text t = full_screen_triangles(100000, instances);
    bounded_load l = load_in_child(&t, name);
    TEST_ASSERT_EQUAL(MOTE_ERR_LIMIT, l.result);
    TEST_ASSERT_EQUAL_STRING(message, l.message);
    assert_peak_within(&l, 64.0);
    free(t.s);
}

/* 100,000 triangles, each filling a 640x480 view, take about 16 s a
 * frame; with 10 instances, 11 times that. The triangles every instance
 * draws are counted against max_triangles. */
void full_screen_triangles_drawn_by_instances_should_pass_the_triangle_limit(void)
{
    expect_triangle_limit(10, "fill.babylon", "fill.babylon: 1100000 triangles in its 11 meshes "
                          "(instances count), more than the limit of 1048576 (max_triangles)");
    /* without the instances it loads */
    text t = full_screen_triangles(100000, 0);
    mote_scene s;
    char m[256];
    TEST_ASSERT_EQUAL_MESSAGE(MOTE_OK, mote_scene_load_memory(t.s, t.len, "one.babylon", NULL,
                                                              NULL, &s, m, sizeof m), m);
    TEST_ASSERT_EQUAL_UINT32(300000, s.meshes[0].index_count);
    mote_scene_free(&s);
    free(t.s);
}

/* 2,000 instances: 200 million triangles to draw. */
void two_thousand_instances_should_pass_the_triangle_limit(void)
{
    expect_triangle_limit(2000, "many.babylon", "many.babylon: 200100000 triangles in its 2001 "
                          "meshes (instances count), more than the limit of 1048576 "
                          "(max_triangles)");
}

/* A limit set higher lets such a scene load. */
void the_triangle_limit_should_be_settable(void)
{
    text t = full_screen_triangles(1000, 10);
    mote_limits lim = mote_limits_default();
    lim.max_triangles = 10999;
    mote_scene s;
    char m[256];
    TEST_ASSERT_EQUAL(MOTE_ERR_LIMIT, mote_scene_load_memory(t.s, t.len, "x.babylon", NULL, &lim,
                                                             &s, m, sizeof m));
    TEST_ASSERT_EQUAL_STRING("x.babylon: 11000 triangles in its 11 meshes (instances count), "
                             "more than the limit of 10999 (max_triangles)", m);
    lim.max_triangles = 11000;
    TEST_ASSERT_EQUAL_MESSAGE(MOTE_OK, mote_scene_load_memory(t.s, t.len, "x.babylon", NULL,
                                                              &lim, &s, m, sizeof m), m);
    TEST_ASSERT_EQUAL(11, s.mesh_count);
    mote_scene_free(&s);
    free(t.s);
}

int main(void)
{
    UNITY_BEGIN();
    RUN_TEST(a_scene_whose_parsed_json_passes_the_budget_should_be_refused_before_parsing);
    RUN_TEST(full_screen_triangles_drawn_by_instances_should_pass_the_triangle_limit);
    RUN_TEST(two_thousand_instances_should_pass_the_triangle_limit);
    RUN_TEST(the_triangle_limit_should_be_settable);
    return UNITY_END();
}
