/*
 * test_babylon_errors.c - malformed scenes must fail with the right code and
 * a message that says where, free everything and leave the scene zeroed.
 * The corpus is tests/data/bad/: EXPECTED.txt pairs each file with its
 * result code and a message substring. Every load is also repeated with
 * each allocation failing in turn (mote__io_set_alloc_failure_after).
 */
#include <mote/mote.h>
#include <mote/mote_io.h>
#include "io/io_internal.h"
#include "unity.h"

#include <stdio.h>
#include <stdlib.h>
#include <string.h>

#define BAD_DIR MOTE_SOURCE_DIR "/tests/data/bad"
#define MONKEY MOTE_SOURCE_DIR "/../shared/assets/monkey.babylon"

typedef struct expected_case {
    char file[96];
    mote_result code;
    char substring[256];
} expected_case;

static expected_case cases[256];
static int case_count;
static char msg[512];
static long live_before;

void setUp(void)
{
    msg[0] = '\0';
    mote__io_set_alloc_failure_after(-1);
    live_before = mote__io_live_allocations();
}

void tearDown(void)
{
    mote__io_set_alloc_failure_after(-1);
}

static mote_result code_by_name(const char *name)
{
    static const struct { const char *name; mote_result code; } names[] = {
        {"OK", MOTE_OK}, {"PARSE", MOTE_ERR_PARSE}, {"RANGE", MOTE_ERR_RANGE},
        {"LIMIT", MOTE_ERR_LIMIT}, {"IO", MOTE_ERR_IO},
        {"OUT_OF_MEMORY", MOTE_ERR_OUT_OF_MEMORY}, {"UNSUPPORTED", MOTE_ERR_UNSUPPORTED},
    };
    for (size_t i = 0; i < sizeof names / sizeof names[0]; i++)
        if (strcmp(names[i].name, name) == 0)
            return names[i].code;
    return MOTE_RESULT_COUNT;
}

static void read_expected(void)
{
    FILE *f = fopen(BAD_DIR "/EXPECTED.txt", "r");
    if (!f)
        return;
    char line[512];
    while (fgets(line, sizeof line, f) && case_count < 256) {
        line[strcspn(line, "\r\n")] = '\0';
        if (line[0] == '#' || line[0] == '\0')
            continue;
        expected_case *c = &cases[case_count];
        char code[32];
        int used = 0;
        if (sscanf(line, "%95s %31s %n", c->file, code, &used) != 2)
            continue;
        c->code = code_by_name(code);
        snprintf(c->substring, sizeof c->substring, "%s", line + used);
        case_count++;
    }
    fclose(f);
}

static bool scene_is_zeroed(const mote_scene *s)
{
    static const mote_scene zero;
    return memcmp(s, &zero, sizeof zero) == 0;
}

/* Loads one corpus file and checks it against its line; returns false and
 * says why in `why` when it does not match. */
static bool check_case(const expected_case *c, char *why, size_t why_size)
{
    char path[256];
    snprintf(path, sizeof path, "%s/%.95s", BAD_DIR, c->file);
    mote_scene s;
    char m[512] = "";
    mote_result r = mote_scene_load(path, NULL, &s, m, sizeof m);
    bool ok = true;
    if (r != c->code) {
        snprintf(why, why_size, "%s: got %s, expected %s (%s)", c->file, mote_result_string(r),
                 mote_result_string(c->code), m);
        ok = false;
    } else if (r == MOTE_OK) {
        bool want_empty = strcmp(c->substring, "-") == 0;
        if (want_empty ? s.warning[0] != '\0' : !strstr(s.warning, c->substring)) {
            snprintf(why, why_size, "%s: warning \"%s\", expected \"%s\"", c->file, s.warning,
                     c->substring);
            ok = false;
        }
    } else {
        size_t n = strlen(c->file);
        if (strncmp(m, c->file, n) != 0 || strncmp(m + n, ": ", 2) != 0 ||
            !strstr(m, c->substring)) {
            snprintf(why, why_size, "%s: message \"%s\", expected \"%s: ...%s...\"", c->file, m,
                     c->file, c->substring);
            ok = false;
        } else if (!scene_is_zeroed(&s)) {
            snprintf(why, why_size, "%s: the scene is not zeroed after an error", c->file);
            ok = false;
        }
    }
    mote_scene_free(&s);
    if (ok && mote__io_live_allocations() != live_before) {
        snprintf(why, why_size, "%s: %ld allocations leaked", c->file,
                 mote__io_live_allocations() - live_before);
        ok = false;
    }
    return ok;
}

void loader_should_reject_each_bad_file_with_its_code_and_message(void)
{
    TEST_ASSERT_TRUE_MESSAGE(case_count >= 50, "tests/data/bad/EXPECTED.txt: fewer than 50 cases");
    int failures = 0;
    char why[1024];
    for (int i = 0; i < case_count; i++) {
        TEST_ASSERT_TRUE_MESSAGE(cases[i].code != MOTE_RESULT_COUNT, cases[i].file);
        if (!check_case(&cases[i], why, sizeof why)) {
            printf("  %s\n", why);
            failures++;
        }
    }
    TEST_ASSERT_EQUAL_MESSAGE(0, failures, "corpus cases failed (listed above)");
}

/* Fails allocation n = 0, 1, ... until the load gets through: each failure
 * must be a clean MOTE_ERR_OUT_OF_MEMORY (or the file's own error, once the
 * failing allocation comes after it) with nothing left allocated. */
static int fail_every_allocation(const char *path, const char *json, const char *base_dir,
                                 mote_result final_code)
{
    int n = 0;
    for (;; n++) {
        TEST_ASSERT_TRUE_MESSAGE(n < 100000, "the allocation loop does not end");
        mote__io_set_alloc_failure_after(n);
        mote_scene s;
        char m[512] = "";
        mote_result r = path ? mote_scene_load(path, NULL, &s, m, sizeof m)
                             : mote_scene_load_memory(json, strlen(json), "mem.babylon",
                                                      base_dir, NULL, &s, m, sizeof m);
        /* the countdown still running means no allocation failed: done */
        bool failed_one = !mote__io_failure_pending();
        mote__io_set_alloc_failure_after(-1);
        if (r == MOTE_ERR_OUT_OF_MEMORY) {
            TEST_ASSERT_TRUE_MESSAGE(scene_is_zeroed(&s), m);
            TEST_ASSERT_NOT_NULL_MESSAGE(strstr(m, "out of memory"), m);
        } else {
            TEST_ASSERT_EQUAL_MESSAGE(final_code, r, m);
        }
        mote_scene_free(&s);
        TEST_ASSERT_EQUAL_MESSAGE(live_before, mote__io_live_allocations(), path ? path : json);
        if (r != MOTE_ERR_OUT_OF_MEMORY && !failed_one)
            break;
    }
    return n;
}

void loader_should_free_everything_when_any_allocation_fails(void)
{
    char path[256];
    int total = 0;
    for (int i = 0; i < case_count; i++) {
        snprintf(path, sizeof path, "%s/%.95s", BAD_DIR, cases[i].file);
        total += fail_every_allocation(path, NULL, NULL, cases[i].code);
    }
    const char *scene =
        "{\"materials\":[{\"id\":\"a\",\"diffuse\":[1,0,0]},{\"id\":\"b\"}],"
        "\"multiMaterials\":[{\"id\":\"mm\",\"materials\":[\"a\",\"b\",null]}],"
        "\"geometries\":{\"vertexData\":[{\"id\":\"g\",\"positions\":[0,0,0,1,0,0,0,1,0],"
        "\"indices\":[0,1,2]}]},"
        "\"transformNodes\":[{\"id\":\"t\",\"position\":[1,2,3]}],"
        "\"meshes\":[{\"id\":\"m\",\"parentId\":\"t\",\"materialId\":\"mm\",\"geometryId\":\"g\","
        "\"subMeshes\":[{\"materialIndex\":0,\"indexStart\":0,\"indexCount\":3},"
        "{\"materialIndex\":1,\"indexStart\":0,\"indexCount\":3}]},"
        "{\"id\":\"n\",\"parentId\":\"m\",\"positions\":[0,0,0,1,1,1,2,2,2],\"indices\":[0,1,2]}],"
        "\"cameras\":[{\"id\":\"c\",\"position\":[0,0,-5],\"rotation\":[0.1,0.2,0.3]}],"
        "\"lights\":[{\"type\":3}]}";
    total += fail_every_allocation(NULL, scene, NULL, MOTE_OK);
    /* vertex colours, inline (4 and 3 per vertex) and in geometries.vertexData */
    total += fail_every_allocation(MOTE_SOURCE_DIR "/tests/data/vertex_colors.babylon", NULL, NULL,
                                   MOTE_OK);
    /* the monkey: file reading, its texture decode and the scene */
    FILE *f = fopen(MONKEY, "rb");
    if (f) {
        fclose(f);
        int n = fail_every_allocation(MONKEY, NULL, NULL, MOTE_OK);
        TEST_ASSERT_TRUE(n >= 5);
        total += n;
    }
    TEST_ASSERT_TRUE(total > case_count);
}

/* Babylon.js resolves materialId with getLastMaterialById: the second
 * "t" (green) is the one drawn. */
void loader_should_keep_the_last_of_duplicate_material_ids(void)
{
    mote_scene s;
    TEST_ASSERT_EQUAL_MESSAGE(MOTE_OK, mote_scene_load(BAD_DIR "/material_duplicate_id.babylon",
                                                       NULL, &s, msg, sizeof msg), msg);
    TEST_ASSERT_EQUAL(1, s.mesh_count);
    TEST_ASSERT_EQUAL_UINT8(0, s.meshes[0].material.color.r);
    TEST_ASSERT_EQUAL_UINT8(255, s.meshes[0].material.color.g);
    mote_scene_free(&s);
}

void loader_should_bind_ids_with_invalid_utf8_bytes_exactly(void)
{
    mote_scene s;
    TEST_ASSERT_EQUAL_MESSAGE(MOTE_OK, mote_scene_load(BAD_DIR "/material_invalid_utf8_id.babylon",
                                                       NULL, &s, msg, sizeof msg), msg);
    TEST_ASSERT_TRUE(s.meshes[0].material.color_set);
    TEST_ASSERT_EQUAL_UINT8(255, s.meshes[0].material.color.r);
    mote_scene_free(&s);
}

void loader_should_infer_uvcount_when_only_one_stride_fits(void)
{
    mote_scene s;
    TEST_ASSERT_EQUAL_MESSAGE(MOTE_OK, mote_scene_load(BAD_DIR "/uvcount_missing_inferred.babylon",
                                                       NULL, &s, msg, sizeof msg), msg);
    /* 30 floats, largest index 4: stride 6 (5 vertices); 10 would give 3 */
    TEST_ASSERT_EQUAL_UINT32(5, s.meshes[0].vertex_count);
    TEST_ASSERT_FALSE(s.meshes[0].material.v_origin_bottom);
    mote_scene_free(&s);
}

void loader_should_give_empty_meshes_zero_triangles(void)
{
    mote_scene s;
    TEST_ASSERT_EQUAL_MESSAGE(MOTE_OK, mote_scene_load(BAD_DIR "/empty_mesh.babylon", NULL, &s,
                                                       msg, sizeof msg), msg);
    TEST_ASSERT_EQUAL(1, s.mesh_count);
    TEST_ASSERT_EQUAL_UINT32(0, s.meshes[0].vertex_count);
    TEST_ASSERT_EQUAL_UINT32(0, s.meshes[0].index_count);
    mote_scene_free(&s);
}

void loader_should_refuse_counts_over_the_limits(void)
{
    const char *j = "{\"meshes\":[{\"id\":\"a\",\"positions\":[0,0,0,1,0,0,0,1,0],"
                    "\"indices\":[0,1,2,2,1,0]},{\"id\":\"b\"}]}";
    mote_scene s;
    mote_limits lim = mote_limits_default();
    lim.max_vertices = 2;
    TEST_ASSERT_EQUAL(MOTE_ERR_LIMIT, mote_scene_load_memory(j, strlen(j), "l", NULL, &lim, &s,
                                                             msg, sizeof msg));
    TEST_ASSERT_NOT_NULL_MESSAGE(strstr(msg, "l: meshes[0].positions: 3 vertices, more than the "
                                             "limit of 2"), msg);
    lim = mote_limits_default();
    lim.max_indices = 5;
    TEST_ASSERT_EQUAL(MOTE_ERR_LIMIT, mote_scene_load_memory(j, strlen(j), "l", NULL, &lim, &s,
                                                             msg, sizeof msg));
    TEST_ASSERT_NOT_NULL_MESSAGE(strstr(msg, "meshes[0].indices: 6 indices"), msg);
    lim = mote_limits_default();
    lim.max_meshes = 1;
    TEST_ASSERT_EQUAL(MOTE_ERR_LIMIT, mote_scene_load_memory(j, strlen(j), "l", NULL, &lim, &s,
                                                             msg, sizeof msg));
    TEST_ASSERT_NOT_NULL_MESSAGE(strstr(msg, "2 meshes, more than the limit of 1"), msg);
    /* a camera that is a parent becomes a mesh and counts */
    const char *cam = "{\"meshes\":[{\"id\":\"m\",\"parentId\":\"c\"}],"
                      "\"cameras\":[{\"id\":\"c\"}]}";
    TEST_ASSERT_EQUAL(MOTE_ERR_LIMIT, mote_scene_load_memory(cam, strlen(cam), "l", NULL, &lim,
                                                             &s, msg, sizeof msg));
    TEST_ASSERT_NOT_NULL_MESSAGE(strstr(msg, "l: cameras[0]: more than the limit of 1 meshes"),
                                 msg);
    TEST_ASSERT_TRUE(scene_is_zeroed(&s));
    lim.max_meshes = 2;
    TEST_ASSERT_EQUAL_MESSAGE(MOTE_OK, mote_scene_load_memory(cam, strlen(cam), "l", NULL, &lim,
                                                              &s, msg, sizeof msg), msg);
    TEST_ASSERT_EQUAL(2, s.mesh_count);
    mote_scene_free(&s);
    lim = mote_limits_default();
    lim.max_json_depth = 2;
    TEST_ASSERT_EQUAL(MOTE_ERR_LIMIT, mote_scene_load_memory(j, strlen(j), "l", NULL, &lim, &s,
                                                             msg, sizeof msg));
    lim = mote_limits_default();
    lim.max_file_bytes = 20;
    TEST_ASSERT_EQUAL(MOTE_ERR_LIMIT, mote_scene_load_memory(j, strlen(j), "l", NULL, &lim, &s,
                                                             msg, sizeof msg));
    TEST_ASSERT_EQUAL(MOTE_ERR_LIMIT, mote_scene_load(BAD_DIR "/parent_cycle.babylon", &lim, &s,
                                                      msg, sizeof msg));
    TEST_ASSERT_NOT_NULL_MESSAGE(strstr(msg, "larger than the limit of 20 bytes"), msg);
    TEST_ASSERT_TRUE(scene_is_zeroed(&s));
    /* the same scene within the limits loads */
    lim = mote_limits_default();
    lim.max_vertices = 3;
    lim.max_indices = 6;
    lim.max_meshes = 2;
    TEST_ASSERT_EQUAL_MESSAGE(MOTE_OK, mote_scene_load_memory(j, strlen(j), "l", NULL, &lim, &s,
                                                              msg, sizeof msg), msg);
    mote_scene_free(&s);
    TEST_ASSERT_EQUAL(live_before, mote__io_live_allocations());
}

void loader_should_draw_untextured_and_warn_when_asked_to(void)
{
    mote_limits lim = mote_limits_default();
    lim.missing_texture_is_warning = true;
    mote_scene s;
    TEST_ASSERT_EQUAL_MESSAGE(MOTE_OK, mote_scene_load(BAD_DIR "/texture_missing.babylon", &lim,
                                                       &s, msg, sizeof msg), msg);
    TEST_ASSERT_NULL(s.meshes[0].material.texture);
    TEST_ASSERT_EQUAL(0, s.texture_count);
    TEST_ASSERT_NOT_NULL_MESSAGE(strstr(s.warning, "materials[0].diffuseTexture: "), s.warning);
    TEST_ASSERT_NOT_NULL_MESSAGE(strstr(s.warning, "drawn untextured"), s.warning);
    mote_scene_free(&s);
    TEST_ASSERT_EQUAL_MESSAGE(MOTE_OK, mote_scene_load(BAD_DIR "/texture_huge_dimensions.babylon",
                                                       &lim, &s, msg, sizeof msg), msg);
    TEST_ASSERT_NOT_NULL_MESSAGE(strstr(s.warning, "100000 x 100000"), s.warning);
    mote_scene_free(&s);
    /* a web address (the SceneSerializer's name for a texture loaded from
     * the web), which mote does not download */
    TEST_ASSERT_EQUAL_MESSAGE(MOTE_OK, mote_scene_load(BAD_DIR "/texture_web_address.babylon",
                                                       &lim, &s, msg, sizeof msg), msg);
    TEST_ASSERT_NULL(s.meshes[0].material.texture);
    TEST_ASSERT_EQUAL_STRING("materials[0].diffuseTexture: \"https://example.com/textures/"
                             "wood.png\" is a web address, which mote does not download (drawn "
                             "untextured)", s.warning);
    mote_scene_free(&s);
    /* path escapes stay errors */
    TEST_ASSERT_EQUAL(MOTE_ERR_RANGE, mote_scene_load(BAD_DIR "/texture_dotdot.babylon", &lim, &s,
                                                      msg, sizeof msg));
    TEST_ASSERT_EQUAL(live_before, mote__io_live_allocations());
}

void loader_should_follow_any_texture_path_when_allowed(void)
{
    /* "../bad/zero.png" from tests/data/bad is the corpus's empty file */
    const char *j = "{\"materials\":[{\"id\":\"t\",\"diffuseTexture\":{\"name\":"
                    "\"../bad/zero.png\"}}]}";
    mote_limits lim = mote_limits_default();
    mote_scene s;
    TEST_ASSERT_EQUAL(MOTE_ERR_RANGE, mote_scene_load_memory(j, strlen(j), "p", BAD_DIR, &lim,
                                                             &s, msg, sizeof msg));
    lim.allow_any_texture_path = true;
    TEST_ASSERT_EQUAL(MOTE_ERR_PARSE, mote_scene_load_memory(j, strlen(j), "p", BAD_DIR, &lim,
                                                             &s, msg, sizeof msg));
    TEST_ASSERT_NOT_NULL_MESSAGE(strstr(msg, "p: materials[0].diffuseTexture.name: "), msg);
    TEST_ASSERT_NOT_NULL_MESSAGE(strstr(msg, "empty image"), msg);
    /* without a base folder no texture is read: colours only */
    TEST_ASSERT_EQUAL_MESSAGE(MOTE_OK, mote_scene_load_memory(j, strlen(j), "p", NULL, &lim, &s,
                                                              msg, sizeof msg), msg);
    TEST_ASSERT_EQUAL(0, s.texture_count);
    mote_scene_free(&s);
}

void loader_should_report_a_missing_file_as_io(void)
{
    mote_scene s;
    TEST_ASSERT_EQUAL(MOTE_ERR_IO, mote_scene_load(BAD_DIR "/no-such-file.babylon", NULL, &s, msg,
                                                   sizeof msg));
    TEST_ASSERT_NOT_NULL_MESSAGE(strstr(msg, "no-such-file.babylon: cannot open"), msg);
    TEST_ASSERT_TRUE(scene_is_zeroed(&s));
    TEST_ASSERT_EQUAL(MOTE_ERR_IO, mote_scene_load(BAD_DIR, NULL, &s, msg, sizeof msg));
    TEST_ASSERT_EQUAL(MOTE_ERR_INVALID_ARGUMENT, mote_scene_load(NULL, NULL, &s, msg, sizeof msg));
    /* freeing a zeroed or already freed scene is harmless */
    mote_scene_free(&s);
    mote_scene_free(&s);
    mote_scene_free(NULL);
}

/* Positions one vertex short used to be blamed on the normals ("normals:
 * 12 floats, expected 3 per vertex (3 vertices)"): the message names the
 * vertex count positions gives and every array that disagrees with it. */
void loader_should_name_each_array_that_disagrees_with_positions(void)
{
    const char *short_positions =
        "{\"meshes\":[{\"id\":\"a\",\"positions\":[0,0,0, 1,0,0, 0,1,0],"
        "\"normals\":[0,0,1, 0,0,1, 0,0,1, 0,0,1],\"uvs\":[0,0, 1,0, 0,1, 1,1],"
        "\"colors\":[1,1,1,1, 1,1,1,1, 1,1,1,1],\"indices\":[0,1,2]}]}";
    mote_scene s;
    TEST_ASSERT_EQUAL(MOTE_ERR_RANGE, mote_scene_load_memory(short_positions,
                                                             strlen(short_positions), "v", NULL,
                                                             NULL, &s, msg, sizeof msg));
    TEST_ASSERT_EQUAL_STRING("v: meshes[0]: positions has 9 floats (3 vertices), but normals "
                             "has 12 floats (4 vertices), uvs has 8 floats (4 vertices)", msg);
    TEST_ASSERT_TRUE(scene_is_zeroed(&s));
    /* positions not in threes: said of positions, whatever the others */
    const char *ragged = "{\"meshes\":[{\"id\":\"a\",\"positions\":[0,0,0, 1,0,0, 0,1],"
                         "\"normals\":[0,0,1, 0,0,1, 0,0,1]}]}";
    TEST_ASSERT_EQUAL(MOTE_ERR_RANGE, mote_scene_load_memory(ragged, strlen(ragged), "v", NULL,
                                                             NULL, &s, msg, sizeof msg));
    TEST_ASSERT_EQUAL_STRING("v: meshes[0].positions: 8 floats is not a multiple of 3", msg);
    TEST_ASSERT_EQUAL(live_before, mote__io_live_allocations());
}

int main(void)
{
    read_expected();
    UNITY_BEGIN();
    RUN_TEST(loader_should_reject_each_bad_file_with_its_code_and_message);
    RUN_TEST(loader_should_free_everything_when_any_allocation_fails);
    RUN_TEST(loader_should_keep_the_last_of_duplicate_material_ids);
    RUN_TEST(loader_should_bind_ids_with_invalid_utf8_bytes_exactly);
    RUN_TEST(loader_should_infer_uvcount_when_only_one_stride_fits);
    RUN_TEST(loader_should_give_empty_meshes_zero_triangles);
    RUN_TEST(loader_should_refuse_counts_over_the_limits);
    RUN_TEST(loader_should_draw_untextured_and_warn_when_asked_to);
    RUN_TEST(loader_should_follow_any_texture_path_when_allowed);
    RUN_TEST(loader_should_report_a_missing_file_as_io);
    RUN_TEST(loader_should_name_each_array_that_disagrees_with_positions);
    return UNITY_END();
}
