/*
 * test_json.c - the JSON helpers (src/io/json.c): typed getters whose
 * messages name the JSON path and what was found, finite floats and whole
 * numbers, the nesting limit checked before parsing, and keys written
 * twice as the loader reads them.
 */
#include "io/json.h"
#include "support/io_test.h"

#include <float.h>

static char msg[512];
static long live_before;

void setUp(void)
{
    msg[0] = '\0';
    live_before = io_test_begin();
}

void tearDown(void) {}

/* Keys written twice: the last counts, as JSON.parse (which Babylon.js
 * reads .babylon files with) keeps it; cJSON's lookup alone would find the
 * first. At the top level, in a mesh, a material, a camera and a
 * geometries.vertexData entry. */
void loader_should_take_the_last_of_keys_written_twice(void)
{
    const char *j = "{\"meshes\":[{\"id\":\"first\"}],"
                    "\"materials\":[{\"id\":\"m\",\"diffuse\":[1,0,0],\"diffuse\":[0,0,1]}],"
                    "\"geometries\":{\"vertexData\":[{\"id\":\"x\",\"id\":\"g\","
                    "\"positions\":[0,0,0, 1,0,0, 0,1,0],\"indices\":[0,1,2]}]},"
                    "\"cameras\":[{\"id\":\"one\",\"id\":\"c\",\"position\":[0,0,-3],"
                    "\"target\":[0,0,0]}],\"activeCameraID\":\"c\","
                    "\"meshes\":[{\"id\":\"a\",\"materialId\":\"m\",\"geometryId\":\"g\","
                    "\"position\":[1,2,3],\"position\":[4,5,6],\"isVisible\":false,"
                    "\"isVisible\":null}]}";
    mote_scene s;
    io_load_json(j, "dup", &s);
    TEST_ASSERT_EQUAL_STRING("", s.warning);
    TEST_ASSERT_EQUAL(1, s.mesh_count);
    ASSERT_VEC3(4.0f, 5.0f, 6.0f, s.meshes[0].position, 0.0f);
    TEST_ASSERT_FALSE(s.meshes[0].hidden);    /* null: as if not written */
    TEST_ASSERT_EQUAL_UINT8(0, s.meshes[0].material.color.r);
    TEST_ASSERT_EQUAL_UINT8(255, s.meshes[0].material.color.b);
    TEST_ASSERT_EQUAL_UINT32(3, s.meshes[0].index_count);
    TEST_ASSERT_TRUE(s.has_camera);
    ASSERT_VEC3(0.0f, 0.0f, -3.0f, s.camera.position, 0.0f);
    mote_scene_free(&s);
}

static mote__loader ld;
static mote_scene scene;

/* Parses text for a load named "x.babylon" (limits: lim, NULL for the
 * defaults); the caller ends it with finish. */
static mote_result parse(const char *text, const mote_limits *lim, cJSON **root)
{
    TEST_ASSERT_EQUAL(MOTE_OK, mote__loader_begin(&ld, "x.babylon", NULL, lim, strlen(text),
                                                  &scene, msg, sizeof msg));
    return mote__json_parse(&ld, text, strlen(text), root);
}

static void finish(cJSON *root)
{
    cJSON_Delete(root);
    mote__loader_end(&ld, MOTE_ERR_PARSE);
    TEST_ASSERT_EQUAL(live_before, mote__io_live_allocations());
}

void json_getters_should_name_the_path_and_what_they_found(void)
{
    cJSON *root;
    TEST_ASSERT_EQUAL_MESSAGE(MOTE_OK, parse("{\"a\": [1, \"x\"], \"b\": true, \"c\": 1.5, "
                                             "\"n\": null, \"o\": {}}", NULL, &root), msg);
    float v[2] = {7, 7};
    TEST_ASSERT_EQUAL(MOTE_ERR_PARSE, mote__json_floats(&ld, root, "a", "meshes[0]", 2, 0, v));
    TEST_ASSERT_EQUAL_STRING("x.babylon: meshes[0].a[1]: expected a number, found a string", msg);
    TEST_ASSERT_EQUAL(MOTE_ERR_PARSE, mote__json_floats(&ld, root, "a", "m", 3, 4, v));
    TEST_ASSERT_EQUAL_STRING("x.babylon: m.a: expected an array of 3 or 4 numbers", msg);
    const char *s = "kept";
    TEST_ASSERT_EQUAL(MOTE_ERR_PARSE, mote__json_string(&ld, root, "c", "m", &s));
    TEST_ASSERT_EQUAL_STRING("x.babylon: m.c: expected a string, found a number", msg);
    const cJSON *arr;
    TEST_ASSERT_EQUAL(MOTE_ERR_PARSE, mote__json_array(&ld, root, "o", "", &arr));
    TEST_ASSERT_EQUAL_STRING("x.babylon: o: expected an array, found an object", msg);
    TEST_ASSERT_EQUAL(MOTE_ERR_PARSE, mote__json_object(&ld, mote__json_get(root, "b"), "b"));
    TEST_ASSERT_EQUAL_STRING("x.babylon: b: expected an object, found a boolean", msg);
    /* absent or null: *out as it was */
    TEST_ASSERT_EQUAL(MOTE_OK, mote__json_floats(&ld, root, "n", "m", 2, 0, v));
    TEST_ASSERT_EQUAL(MOTE_OK, mote__json_floats(&ld, root, "none", "m", 2, 0, v));
    TEST_ASSERT_EQUAL_FLOAT(7.0f, v[0]);
    TEST_ASSERT_NULL(mote__json_get(root, "n"));
    TEST_ASSERT_NOT_NULL(mote__json_member(root, "n"));
    bool flag = false;
    TEST_ASSERT_EQUAL(MOTE_OK, mote__json_flag(&ld, root, "c", "m", &flag));   /* 1.5: true */
    TEST_ASSERT_TRUE(flag);
    TEST_ASSERT_EQUAL(2, (int)mote__json_length(mote__json_get(root, "a")));
    TEST_ASSERT_EQUAL(0, (int)mote__json_length(NULL));
    finish(root);
}

void json_numbers_should_be_finite_floats_and_whole_numbers(void)
{
    cJSON *root;
    TEST_ASSERT_EQUAL_MESSAGE(MOTE_OK, parse("{\"big\": 1e39, \"half\": 2.5, \"seven\": 7}", NULL,
                                             &root), msg);
    float f;
    uint32_t u = 0;
    TEST_ASSERT_EQUAL(MOTE_ERR_RANGE, mote__json_number(&ld, root, "big", "m", &f));
    TEST_ASSERT_EQUAL_STRING("x.babylon: m.big: 1e+39 is not a finite float", msg);
    TEST_ASSERT_EQUAL(MOTE_ERR_PARSE, mote__json_uint_member(&ld, root, "half", "m", 9, &u));
    TEST_ASSERT_EQUAL_STRING("x.babylon: m.half: 2.5 is not an integer", msg);
    TEST_ASSERT_EQUAL(MOTE_ERR_RANGE, mote__json_uint_member(&ld, root, "seven", "m", 5, &u));
    TEST_ASSERT_EQUAL_STRING("x.babylon: m.seven: 7 is out of range [0, 5]", msg);
    TEST_ASSERT_EQUAL(MOTE_OK, mote__json_uint_member(&ld, root, "seven", "m", 7, &u));
    TEST_ASSERT_EQUAL_UINT32(7, u);
    /* an element names its place only when it is wrong */
    TEST_ASSERT_EQUAL(MOTE_OK,
                      mote__json_element_float(&ld, mote__json_get(root, "half"), "v", 4, &f));
    TEST_ASSERT_EQUAL_FLOAT(2.5f, f);
    TEST_ASSERT_EQUAL(MOTE_ERR_RANGE,
                      mote__json_element_float(&ld, mote__json_get(root, "big"), "v", 4, &f));
    TEST_ASSERT_EQUAL_STRING("x.babylon: v[4]: 1e+39 is not a finite float", msg);
    finish(root);
}

/* FLT_MAX written to 8 digits is a hair above it and rounds to it, as a
 * float; from FLT_MAX plus half its last step a float is infinite. */
void json_floats_should_take_what_rounds_to_the_largest_float(void)
{
    cJSON *root;
    TEST_ASSERT_EQUAL_MESSAGE(MOTE_OK, parse("{\"a\": [3.4028235e38, -3.4028235e38, "
                                             "3.40282356779733e38], \"b\": 3.4028236e38}", NULL,
                                             &root), msg);
    float v[3] = {0, 0, 0}, f = 0;
    TEST_ASSERT_EQUAL_MESSAGE(MOTE_OK, mote__json_floats(&ld, root, "a", "m", 3, 0, v), msg);
    TEST_ASSERT_EQUAL_FLOAT(FLT_MAX, v[0]);
    TEST_ASSERT_EQUAL_FLOAT(-FLT_MAX, v[1]);
    TEST_ASSERT_EQUAL_FLOAT(FLT_MAX, v[2]);
    TEST_ASSERT_EQUAL(MOTE_ERR_RANGE, mote__json_number(&ld, root, "b", "m", &f));
    TEST_ASSERT_EQUAL_STRING("x.babylon: m.b: 3.40282e+38 is not a finite float", msg);
    const cJSON *a = mote__json_get(root, "a");
    TEST_ASSERT_EQUAL(MOTE_OK, mote__json_element_float(&ld, a->child, "a", 0, &f));
    TEST_ASSERT_EQUAL_FLOAT(FLT_MAX, f);
    finish(root);
}

/* The depth is counted on the text, before cJSON (which recurses) sees it;
 * brackets inside strings do not count. */
void json_parse_should_stop_at_the_nesting_limit_before_parsing(void)
{
    mote_limits lim = mote_limits_default();
    lim.max_json_depth = 3;
    cJSON *root = NULL;
    TEST_ASSERT_EQUAL(MOTE_ERR_LIMIT, parse("{\"a\": [[[1]]]}", &lim, &root));
    TEST_ASSERT_EQUAL_STRING("x.babylon: byte 8: nesting deeper than the limit of 3 levels", msg);
    finish(root);
    TEST_ASSERT_EQUAL_MESSAGE(MOTE_OK, parse("{\"a\": [[\"[[[[{{{\"]]}", &lim, &root), msg);
    finish(root);
    TEST_ASSERT_EQUAL(MOTE_ERR_PARSE, parse("{\"a\": 1} x", NULL, &root));
    TEST_ASSERT_EQUAL_STRING("x.babylon: byte 9: text after the end of the JSON value", msg);
    finish(root);
}

/* What the parse will allocate is told from the text, before cJSON sees
 * it (an item per value, numbers too): past limits.max_json_bytes the
 * text is refused, naming the limit, and nothing is parsed. */
void json_parse_should_refuse_a_tree_larger_than_max_json_bytes(void)
{
    char text[4096] = "{\"a\": [0";
    for (int i = 0; i < 200; i++)
        strcat(text, ",0");
    strcat(text, "]}");
    mote_limits lim = mote_limits_default();
    lim.max_json_bytes = 8000;    /* 204 items of 80 bytes, a key and a number copy */
    cJSON *root = NULL;
    TEST_ASSERT_EQUAL(MOTE_ERR_LIMIT, parse(text, &lim, &root));
    TEST_ASSERT_NULL(root);
    TEST_ASSERT_EQUAL_STRING("x.babylon: parsing its JSON (204 values) would take 16384 bytes, "
                             "more than the limit of 8000 bytes (max_json_bytes)", msg);
    finish(root);
    lim.max_json_bytes = 20000;
    TEST_ASSERT_EQUAL_MESSAGE(MOTE_OK, parse(text, &lim, &root), msg);
    TEST_ASSERT_EQUAL(201, (int)mote__json_length(mote__json_get(root, "a")));
    finish(root);
}

/* cJSON running out of memory is out of memory, not malformed JSON. */
void json_parse_should_report_running_out_of_memory_as_such(void)
{
    const char *text = "{\"a\": [1, 2, 3],\n \"b\": \"x\"}";
    TEST_ASSERT_EQUAL(MOTE_OK, mote__loader_begin(&ld, "x.babylon", NULL, NULL, strlen(text),
                                                  &scene, msg, sizeof msg));
    cJSON *root = NULL;
    mote__io_set_alloc_failure_after(0);
    mote_result r = mote__json_parse(&ld, text, strlen(text), &root);
    mote__io_set_alloc_failure_after(-1);
    TEST_ASSERT_EQUAL(MOTE_ERR_OUT_OF_MEMORY, r);
    TEST_ASSERT_EQUAL_STRING("x.babylon: line 1, byte 0: out of memory parsing the JSON", msg);
    finish(root);
    /* the next parse is whole again */
    TEST_ASSERT_EQUAL_MESSAGE(MOTE_OK, parse(text, NULL, &root), msg);
    finish(root);
}

int main(void)
{
    UNITY_BEGIN();
    RUN_TEST(loader_should_take_the_last_of_keys_written_twice);
    RUN_TEST(json_getters_should_name_the_path_and_what_they_found);
    RUN_TEST(json_numbers_should_be_finite_floats_and_whole_numbers);
    RUN_TEST(json_floats_should_take_what_rounds_to_the_largest_float);
    RUN_TEST(json_parse_should_stop_at_the_nesting_limit_before_parsing);
    RUN_TEST(json_parse_should_refuse_a_tree_larger_than_max_json_bytes);
    RUN_TEST(json_parse_should_report_running_out_of_memory_as_such);
    return UNITY_END();
}
