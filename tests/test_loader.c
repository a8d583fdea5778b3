/*
 * test_loader.c - the scene being built (src/io/loader.c): the size and
 * count limits checked before anything is allocated, warnings given once
 * with their count, and everything freed when a load fails.
 */
#include "io/loader.h"
#include "support/io_test.h"

static char msg[512];
static long live_before;

void setUp(void)
{
    msg[0] = '\0';
    live_before = io_test_begin();
}

void tearDown(void) {}

/* Each distinct warning is shown once, with a count when it repeats, so
 * that one given per sub-mesh or per extra light does not crowd out the
 * warnings after it in the 256 bytes of scene.warning; distinct ones past
 * what fits are counted. */
void loader_should_show_each_distinct_warning_once_with_its_count(void)
{
    char j[2048];
    int n = snprintf(j, sizeof j, "{\"multiMaterials\":[{\"id\":\"mm\",\"materials\":[null,null,null]}],"
                     "\"meshes\":[{\"id\":\"a\",\"materialId\":\"mm\",%s,\"subMeshes\":[", TRI);
    for (int k = 0; k < 12; k++)
        n += snprintf(j + n, sizeof j - (size_t)n, "%s{\"materialIndex\":5,\"indexStart\":0,"
                      "\"indexCount\":3}", k ? "," : "");
    n += snprintf(j + n, sizeof j - (size_t)n, "]}],\"activeCameraID\":\"nope\","
                  "\"cameras\":[{\"id\":\"c\"}],\"lights\":[");
    for (int k = 0; k < 12; k++)
        n += snprintf(j + n, sizeof j - (size_t)n, "%s{\"type\":3}", k ? "," : "");
    snprintf(j + n, sizeof j - (size_t)n, "]}");
    mote_scene s;
    io_load_json(j, "w", &s);
    TEST_ASSERT_EQUAL(12, s.mesh_count);
    TEST_ASSERT_EQUAL_STRING("meshes[0]: materialIndex 5 is past the 3 materials of \"mm\" (x12); "
                             "activeCamera \"nope\" names no camera; the first one is used; "
                             "lights[4]: more than 4 lights; it and 7 later ones are ignored",
                             s.warning);
    mote_scene_free(&s);
    /* twenty distinct ones: those that fit, then how many more */
    n = snprintf(j, sizeof j, "{\"meshes\":[");
    for (int k = 0; k < 20; k++)
        n += snprintf(j + n, sizeof j - (size_t)n, "%s{\"id\":\"m%d\",\"materialId\":\"x%d\"}",
                      k ? "," : "", k, k);
    snprintf(j + n, sizeof j - (size_t)n, "]}");
    io_load_json(j, "w", &s);
    TEST_ASSERT_EQUAL_PTR(s.warning, strstr(s.warning, "meshes[0].materialId: \"x0\" names no "
                                                       "material; "));
    TEST_ASSERT_NOT_NULL_MESSAGE(strstr(s.warning, "meshes[4].materialId: \"x4\" names no "
                                        "material; 15 more warnings"), s.warning);
    mote_scene_free(&s);
}

/* A file of n meshes each naming a material of its own that is not there:
 * n distinct warnings. */
static char *meshes_naming_no_material(int n)
{
    size_t cap = 64 + (size_t)n * 64;
    char *j = malloc(cap);
    if (!j) {
        TEST_FAIL_MESSAGE("out of memory");
        return NULL;
    }
    size_t len = (size_t)snprintf(j, cap, "{\"meshes\":[");
    for (int k = 0; k < n; k++)
        len += (size_t)snprintf(j + len, cap - len, "%s{\"id\":\"m%d\",\"materialId\":\"x%d\"}",
                                k ? "," : "", k, k);
    snprintf(j + len, cap - len, "]}");
    return j;
}

/* Every warning is kept, not only those scene.warning shows: one by
 * one, in the order given, with their repeats; past 4096 distinct ones,
 * counted. */
void loader_should_keep_every_warning_for_mote_scene_warning(void)
{
    char *j = meshes_naming_no_material(113);
    mote_scene s;
    io_load_json(j, "w", &s);
    unsigned dropped = 7, repeats = 0;
    TEST_ASSERT_EQUAL(113, mote_scene_warning_count(&s, &dropped));
    TEST_ASSERT_EQUAL_UINT(0, dropped);
    TEST_ASSERT_EQUAL_STRING("meshes[0].materialId: \"x0\" names no material",
                             mote_scene_warning(&s, 0, &repeats));
    TEST_ASSERT_EQUAL_UINT(1, repeats);
    TEST_ASSERT_NOT_NULL(strstr(mote_scene_warning(&s, 112, NULL), "\"x112\""));
    TEST_ASSERT_NULL(mote_scene_warning(&s, 113, NULL));
    TEST_ASSERT_NULL(mote_scene_warning(&s, -1, NULL));
    TEST_ASSERT_NOT_NULL_MESSAGE(strstr(s.warning, "more warnings"), s.warning);
    mote_scene_free(&s);
    TEST_ASSERT_EQUAL(0, mote_scene_warning_count(&s, &dropped));   /* freed: zeroed */
    free(j);
    /* repeats counted on the warning they repeat */
    io_load_json("{\"multiMaterials\":[{\"id\":\"mm\",\"materials\":[null]}],"
                 "\"meshes\":[{\"id\":\"a\",\"materialId\":\"mm\"," TRI ",\"subMeshes\":["
                 "{\"materialIndex\":5,\"indexStart\":0,\"indexCount\":3},"
                 "{\"materialIndex\":5,\"indexStart\":0,\"indexCount\":3}]}]}", "w", &s);
    TEST_ASSERT_EQUAL(1, mote_scene_warning_count(&s, NULL));
    TEST_ASSERT_NOT_NULL(mote_scene_warning(&s, 0, &repeats));
    TEST_ASSERT_EQUAL_UINT(2, repeats);
    mote_scene_free(&s);
    /* no warnings, and no scene */
    io_load_json("{}", "w", &s);
    TEST_ASSERT_EQUAL(0, mote_scene_warning_count(&s, &dropped));
    TEST_ASSERT_NULL(mote_scene_warning(&s, 0, NULL));
    mote_scene_free(&s);
    TEST_ASSERT_EQUAL(0, mote_scene_warning_count(NULL, NULL));
    /* past what is kept */
    j = meshes_naming_no_material(4100);
    io_load_json(j, "w", &s);
    TEST_ASSERT_EQUAL(4096, mote_scene_warning_count(&s, &dropped));
    TEST_ASSERT_EQUAL_UINT(4, dropped);
    mote_scene_free(&s);
    free(j);
    TEST_ASSERT_EQUAL(live_before, mote__io_live_allocations());
}

/* A load begun as a loader begins one, its name "x.babylon". */
static void begin(mote__loader *ld, mote_scene *s, size_t size, const mote_limits *lim)
{
    TEST_ASSERT_EQUAL_MESSAGE(MOTE_OK, mote__loader_begin(ld, "x.babylon", NULL, lim, size, s, msg,
                                                          sizeof msg), msg);
}

void loader_should_refuse_a_file_over_the_size_limit_before_allocating(void)
{
    mote_limits lim = mote_limits_default();
    lim.max_file_bytes = 10;
    mote__loader ld;
    mote_scene s;
    TEST_ASSERT_EQUAL(MOTE_ERR_LIMIT, mote__loader_begin(&ld, "x.babylon", NULL, &lim, 11, &s,
                                                         msg, sizeof msg));
    TEST_ASSERT_EQUAL_STRING("x.babylon: 11 bytes, more than the limit of 10", msg);
    TEST_ASSERT_EQUAL(live_before, mote__io_live_allocations());
    TEST_ASSERT_EQUAL(MOTE_ERR_LIMIT, mote__loader_end(&ld, MOTE_ERR_LIMIT));
    TEST_ASSERT_NULL(s.storage_);
    TEST_ASSERT_EQUAL(live_before, mote__io_live_allocations());
}

/* Counts are checked against their limit, and against what an int holds
 * whatever the limit, before anything is allocated for them. */
void loader_should_refuse_counts_over_the_limit_or_an_int(void)
{
    mote__loader ld;
    mote_scene s;
    begin(&ld, &s, 0, NULL);
    TEST_ASSERT_EQUAL(MOTE_OK, mote__check_count(&ld, "meshes[0].indices", 6, "indices", 6));
    TEST_ASSERT_EQUAL(MOTE_ERR_LIMIT, mote__check_count(&ld, "meshes[0].indices", 7, "indices", 6));
    TEST_ASSERT_EQUAL_STRING("x.babylon: meshes[0].indices: 7 indices, more than the limit of 6",
                             msg);
    TEST_ASSERT_EQUAL(MOTE_ERR_LIMIT, mote__check_count(&ld, "materials", (size_t)INT32_MAX + 1,
                                                        "materials", (size_t)-1));
    mote__loader_end(&ld, MOTE_ERR_LIMIT);
    TEST_ASSERT_EQUAL(live_before, mote__io_live_allocations());
}

/* What a failed load allocated, kept or temporary, is freed and the scene
 * zeroed; a load that succeeds keeps what it kept until mote_scene_free. */
void loader_should_free_everything_of_a_failed_load(void)
{
    mote__loader ld;
    mote_scene s;
    begin(&ld, &s, 0, NULL);
    TEST_ASSERT_NOT_NULL(mote__store_alloc(ld.keep, 100, 4));
    TEST_ASSERT_NOT_NULL(mote__store_alloc(&ld.tmp, 100, 4));
    mote__warn(&ld, "a %s", "warning");
    TEST_ASSERT_EQUAL(MOTE_ERR_RANGE, mote__fail(&ld, MOTE_ERR_RANGE, "meshes[%d]: wrong", 3));
    TEST_ASSERT_EQUAL_STRING("x.babylon: meshes[3]: wrong", msg);
    TEST_ASSERT_EQUAL(MOTE_ERR_RANGE, mote__loader_end(&ld, MOTE_ERR_RANGE));
    static const mote_scene zero;
    TEST_ASSERT_EQUAL_MEMORY(&zero, &s, sizeof s);
    TEST_ASSERT_EQUAL(live_before, mote__io_live_allocations());

    begin(&ld, &s, 0, NULL);
    TEST_ASSERT_NOT_NULL(mote__store_alloc(ld.keep, 100, 4));
    TEST_ASSERT_NOT_NULL(mote__store_alloc(&ld.tmp, 100, 4));
    mote__warn(&ld, "a %s", "warning");
    mote__warn(&ld, "a %s", "warning");
    TEST_ASSERT_EQUAL(MOTE_OK, mote__loader_end(&ld, MOTE_OK));
    TEST_ASSERT_EQUAL_STRING("a warning (x2)", s.warning);
    TEST_ASSERT_TRUE(mote__io_live_allocations() > live_before);
    mote_scene_free(&s);
    TEST_ASSERT_EQUAL(live_before, mote__io_live_allocations());
}

/* A count times a size past SIZE_MAX allocates nothing. */
void loader_store_should_refuse_sizes_that_overflow(void)
{
    mote__store st = {0};
    TEST_ASSERT_NULL(mote__store_alloc(&st, SIZE_MAX / 2 + 1, 2));
    TEST_ASSERT_NOT_NULL(mote__store_alloc(&st, 0, 8));   /* an empty array is not NULL */
    mote__store_release(&st);
    TEST_ASSERT_EQUAL(live_before, mote__io_live_allocations());
}

/* Names from files are quoted without control bytes, cut short. */
void loader_should_quote_names_safely(void)
{
    mote__quoted escaped = mote__quote("a\x1b" "b"), none = mote__quote(NULL);
    TEST_ASSERT_EQUAL_STRING("a?b", escaped.s);
    TEST_ASSERT_EQUAL_STRING("", none.s);
    char longname[200];
    memset(longname, 'n', sizeof longname - 1);
    longname[sizeof longname - 1] = '\0';
    mote__quoted q = mote__quote(longname);
    TEST_ASSERT_EQUAL(sizeof q.s - 1, strlen(q.s));
    TEST_ASSERT_EQUAL_STRING("...", q.s + sizeof q.s - 4);
    TEST_ASSERT_EQUAL_UINT8(0, mote__unit_byte(-1.0f));
    TEST_ASSERT_EQUAL_UINT8(128, mote__unit_byte(0.5f));
    TEST_ASSERT_EQUAL_UINT8(255, mote__unit_byte(2.0f));
}

int main(void)
{
    UNITY_BEGIN();
    RUN_TEST(loader_should_show_each_distinct_warning_once_with_its_count);
    RUN_TEST(loader_should_keep_every_warning_for_mote_scene_warning);
    RUN_TEST(loader_should_refuse_a_file_over_the_size_limit_before_allocating);
    RUN_TEST(loader_should_refuse_counts_over_the_limit_or_an_int);
    RUN_TEST(loader_should_free_everything_of_a_failed_load);
    RUN_TEST(loader_store_should_refuse_sizes_that_overflow);
    RUN_TEST(loader_should_quote_names_safely);
    return UNITY_END();
}
