/*
 * test_gltf_errors.c - glTF files that are broken, or that mote cannot
 * draw, must fail with the right code and a message that says where,
 * free everything and leave the scene zeroed; those it reads load with
 * their warnings and draw. Two sets: hostile inputs written here, and
 * every glTF file of Debian's assimp-testmodels (make test installs it;
 * without it that test is skipped, saying so). Each load is repeated
 * with allocations failing in turn.
 */
#include "support/io_test.h"

#define CORPUS "/usr/share/assimp/models"

IO_TEST_FIXTURE

static bool scene_is_zeroed(const mote_scene *s)
{
    static const mote_scene zero;
    return memcmp(s, &zero, sizeof zero) == 0;
}

/* Loads (path, or the bytes with no folder) expecting code and `says` in
 * the message (or, for MOTE_OK, in the warnings; "-": none), draws what
 * loads, and loads again with each of the first allocations failing. */
static void expect(const char *path, const void *bytes, size_t size, mote_result code,
                   const char *says)
{
    mote_scene s;
    char label[600];
    for (int fail = -1; fail < 48; fail++) {
        mote__io_set_alloc_failure_after(fail);
        mote_result r = path ? mote_scene_load(path, NULL, &s, msg, sizeof msg)
                             : mote_scene_load_memory(bytes, size, "e.gltf", NULL, NULL, &s, msg,
                                                      sizeof msg);
        mote__io_set_alloc_failure_after(-1);
        snprintf(label, sizeof label, "%s (allocation %d fails): %s", path ? path : says, fail,
                 r == MOTE_OK ? s.warning : msg);
        if (fail >= 0 && r == MOTE_ERR_OUT_OF_MEMORY) {
            TEST_ASSERT_TRUE_MESSAGE(scene_is_zeroed(&s), label);
            TEST_ASSERT_EQUAL_MESSAGE(live_before, mote__io_live_allocations(), label);
            continue;
        }
        TEST_ASSERT_EQUAL_STRING_MESSAGE(mote_result_string(code), mote_result_string(r), label);
        if (r == MOTE_OK) {
            if (strcmp(says, "-") == 0)
                TEST_ASSERT_EQUAL_STRING_MESSAGE("", s.warning, label);
            else
                TEST_ASSERT_NOT_NULL_MESSAGE(strstr(s.warning, says), label);
            if (fail < 0) {
                static uint8_t rgba[48 * 32 * 4];
                io_render_scene(&s, rgba, 48, 32);
            }
            mote_scene_free(&s);
        } else {
            TEST_ASSERT_NOT_NULL_MESSAGE(strstr(msg, says), label);
            TEST_ASSERT_TRUE_MESSAGE(scene_is_zeroed(&s), label);
        }
        TEST_ASSERT_EQUAL_MESSAGE(live_before, mote__io_live_allocations(), label);
        if (fail >= 0)
            break;            /* the first allocation past the load's last: done */
    }
}

static void expect_json(const char *json, mote_result code, const char *says)
{
    expect(NULL, json, strlen(json), code, says);
}

/* ---- written here ------------------------------------------------------ */

#define ASSET "{\"asset\":{\"version\":\"2.0\"},"
/* 3 positions (36 bytes of zeros, base64) in buffer 0 */
#define BUF "\"buffers\":[{\"byteLength\":36,\"uri\":\"data:application/octet-stream;base64," \
            "AAAAAAAAAAAAAAAAAAAAAAAAAAAAAAAAAAAAAAAAAAAAAAAA\"}],"
/* BUF's 3 positions (accessor 0), and the indices 0 5 (accessor 1, bytes)
 * in buffer 1 */
#define BUF_AND_INDICES                                                                      \
    "\"buffers\":[{\"byteLength\":36,\"uri\":\"data:application/octet-stream;base64,"        \
    "AAAAAAAAAAAAAAAAAAAAAAAAAAAAAAAAAAAAAAAAAAAAAAAA\"},{\"byteLength\":2,"                 \
    "\"uri\":\"data:application/octet-stream;base64,AAU=\"}],"                               \
    "\"bufferViews\":[{\"buffer\":0,\"byteLength\":36},{\"buffer\":1,\"byteLength\":2}],"    \
    "\"accessors\":[{\"bufferView\":0,\"componentType\":5126,\"count\":3,"                   \
    "\"type\":\"VEC3\"},{\"bufferView\":1,\"componentType\":5121,\"count\":2,"               \
    "\"type\":\"SCALAR\"}],"
#define TRI_MESH "\"meshes\":[{\"primitives\":[{\"attributes\":{\"POSITION\":0}}]}]," \
                 "\"nodes\":[{\"mesh\":0}],\"scenes\":[{\"nodes\":[0]}]"

void required_extensions_mote_cannot_draw_should_be_named(void)
{
    expect_json(ASSET "\"extensionsRequired\":[\"KHR_draco_mesh_compression\"]}",
                MOTE_ERR_UNSUPPORTED, "extensionsRequired[0]: \"KHR_draco_mesh_compression\" "
                "(Draco-compressed geometry), which mote does not read");
    expect_json(ASSET "\"extensionsRequired\":[\"KHR_mesh_quantization\",\"EXT_meshopt_compression\"]}",
                MOTE_ERR_UNSUPPORTED, "extensionsRequired[1]: \"EXT_meshopt_compression\"");
    expect_json(ASSET "\"extensionsRequired\":[\"KHR_texture_basisu\"]}", MOTE_ERR_UNSUPPORTED,
                "KTX2/Basis Universal textures");
    expect_json(ASSET "\"extensionsRequired\":[\"EXT_texture_webp\"]}", MOTE_ERR_UNSUPPORTED,
                "WebP textures");
    expect_json(ASSET "\"extensionsRequired\":[\"X_new\"]}", MOTE_ERR_UNSUPPORTED,
                "\"X_new\", an extension mote does not read");
    expect_json(ASSET "\"extensionsUsed\":[\"X_new\"]}", MOTE_OK,
                "extensionsUsed: \"X_new\" is not read");
    expect_json("{\"asset\":{\"version\":\"3.0\"}}", MOTE_ERR_UNSUPPORTED, "mote reads glTF 2.0");
    expect_json("{\"asset\":{\"version\":\"2.0\",\"minVersion\":\"2.1\"}}", MOTE_ERR_UNSUPPORTED,
                "asset.minVersion");
}

void accessors_past_their_views_should_be_refused_before_reading(void)
{
    expect_json(ASSET BUF "\"bufferViews\":[{\"buffer\":0,\"byteLength\":36}],"
                "\"accessors\":[{\"bufferView\":0,\"byteOffset\":4,\"componentType\":5126,"
                "\"count\":3,\"type\":\"VEC3\"}]," TRI_MESH "}",
                MOTE_ERR_RANGE, "accessors[0]: 3 elements of 12 bytes every 12 from byte 4, past "
                "the end of bufferViews[0] (36 bytes)");
    expect_json(ASSET BUF "\"bufferViews\":[{\"buffer\":0,\"byteLength\":36,\"byteOffset\":4}],"
                "\"accessors\":[{\"bufferView\":0,\"componentType\":5126,\"count\":3,"
                "\"type\":\"VEC3\"}]," TRI_MESH "}",
                MOTE_ERR_RANGE, "bufferViews[0]: bytes 4 to 40, past the end of buffers[0]");
    expect_json(ASSET BUF "\"bufferViews\":[{\"buffer\":0,\"byteLength\":36,\"byteStride\":6}],"
                "\"accessors\":[{\"bufferView\":0,\"componentType\":5126,\"count\":3,"
                "\"type\":\"VEC3\"}]," TRI_MESH "}",
                MOTE_ERR_RANGE, "bufferViews[0].byteStride: 6, expected a multiple of 4");
    expect_json(ASSET BUF "\"bufferViews\":[{\"buffer\":0,\"byteLength\":36,\"byteStride\":8}],"
                "\"accessors\":[{\"bufferView\":0,\"componentType\":5126,\"count\":3,"
                "\"type\":\"VEC3\"}]," TRI_MESH "}",
                MOTE_ERR_RANGE, "elements of 12 bytes, more than bufferViews[0].byteStride 8");
    expect_json(ASSET BUF "\"bufferViews\":[{\"buffer\":0,\"byteLength\":36}],"
                "\"accessors\":[{\"bufferView\":0,\"componentType\":5126,\"count\":3,"
                "\"type\":\"VEC2\"}]," TRI_MESH "}",
                MOTE_ERR_PARSE, "meshes[0].primitives[0].attributes.POSITION: accessors[0] holds "
                "2 components of type 5126, expected VEC3 of floats (5126)");
    expect_json(ASSET "\"buffers\":[{\"byteLength\":36,\"uri\":\"data:application/"
                "octet-stream;base64,AAAA\"}],\"bufferViews\":[{\"buffer\":0,\"byteLength\":36}],"
                "\"accessors\":[{\"bufferView\":0,\"componentType\":5126,\"count\":3,"
                "\"type\":\"VEC3\"}]," TRI_MESH "}",
                MOTE_ERR_PARSE, "buffers[0].uri: 3 bytes of data, fewer than its byteLength 36");
    expect_json(ASSET "\"buffers\":[{\"byteLength\":3,\"uri\":\"data:application/"
                "octet-stream;base64,AA!A\"}],\"bufferViews\":[{\"buffer\":0,\"byteLength\":3}],"
                "\"accessors\":[{\"bufferView\":0,\"componentType\":5126,\"count\":3,"
                "\"type\":\"VEC3\"}]," TRI_MESH "}",
                MOTE_ERR_PARSE, "buffers[0].uri: invalid base64 at character 2");
    expect_json(ASSET "\"accessors\":[{\"componentType\":5124,\"count\":3,\"type\":\"VEC3\"}],"
                TRI_MESH "}", MOTE_ERR_RANGE, "accessors[0].componentType: 5124");
    /* an accessor without a view is zeros: a triangle of no area, drawn */
    expect_json(ASSET "\"accessors\":[{\"componentType\":5126,\"count\":3,\"type\":\"VEC3\"}],"
                TRI_MESH "}", MOTE_OK, "-");
}

/* Integer attributes only with KHR_mesh_quantization, and then only the
 * types it lists: positions any, normals normalized signed ones. */
void quantized_attributes_should_need_the_extension_and_its_types(void)
{
    static const char mesh[] =
        ASSET "%s" BUF "\"bufferViews\":[{\"buffer\":0,\"byteLength\":36}],"
        "\"accessors\":[{\"bufferView\":0,\"componentType\":%d,\"count\":3,"
        "\"type\":\"VEC3\"%s}],\"meshes\":[{\"primitives\":[{\"attributes\":"
        "{\"POSITION\":%d%s}}]}],\"nodes\":[{\"mesh\":0}],\"scenes\":[{\"nodes\":[0]}]}";
    static const char ext[] = "\"extensionsUsed\":[\"KHR_mesh_quantization\"],";
    char json[1024];
    snprintf(json, sizeof json, mesh, "", 5123, "", 0, "");
    expect_json(json, MOTE_ERR_PARSE, "attributes.POSITION: accessors[0] holds 3 components of "
                "type 5123, expected VEC3 of floats (5126)");
    snprintf(json, sizeof json, mesh, ext, 5123, "", 0, "");
    expect_json(json, MOTE_OK, "-");
    snprintf(json, sizeof json, mesh, ext, 5122, ",\"normalized\":true", 0,
             ",\"NORMAL\":0");
    expect_json(json, MOTE_OK, "-");
    snprintf(json, sizeof json, mesh, ext, 5121, "", 0, ",\"NORMAL\":0");
    expect_json(json, MOTE_ERR_PARSE, "meshes[0].primitives[0].attributes.NORMAL: accessors[0] "
                "holds 3 components of type 5121, expected VEC3 of floats or normalized bytes "
                "or shorts (KHR_mesh_quantization)");
}

void sparse_indices_should_rise_inside_the_accessor(void)
{
    /* buffer: indices 2, 1 (unsigned bytes), then values */
    static const char head[] = ASSET "\"buffers\":[{\"byteLength\":36,\"uri\":\"data:application/"
                               "octet-stream;base64,AgEAAAAAAAAAAAAAAAAAAAAAAAAAAAAAAAAAAAAAAAAAAAAA\"}],"
                               "\"bufferViews\":[{\"buffer\":0,\"byteLength\":4},{\"buffer\":0,"
                               "\"byteOffset\":4,\"byteLength\":32}],";
    char json[1024];
    snprintf(json, sizeof json, "%s\"accessors\":[{\"componentType\":5126,\"count\":3,"
             "\"type\":\"VEC3\",\"sparse\":{\"count\":2,\"indices\":{\"bufferView\":0,"
             "\"componentType\":5121},\"values\":{\"bufferView\":1}}}]," TRI_MESH "}", head);
    expect_json(json, MOTE_ERR_RANGE, "accessors[0].sparse.indices[1]: 1, expected an index "
                "below 3 greater than the one before");
    snprintf(json, sizeof json, "%s\"accessors\":[{\"componentType\":5126,\"count\":3,"
             "\"type\":\"VEC3\",\"sparse\":{\"count\":3,\"indices\":{\"bufferView\":0,"
             "\"componentType\":5121},\"values\":{\"bufferView\":1}}}]," TRI_MESH "}", head);
    expect_json(json, MOTE_ERR_RANGE, "accessors[0].sparse.values: 3 entries of 12 bytes from "
                "byte 0, past the end of bufferViews[1] (32 bytes)");
}

void node_trees_should_have_no_cycles_shared_children_or_bad_references(void)
{
    expect_json(ASSET "\"nodes\":[{\"children\":[1]},{\"children\":[1]}],"
                "\"scenes\":[{\"nodes\":[0]}]}",
                MOTE_ERR_RANGE, "nodes[1].children[0]: nodes[1] makes a cycle");
    expect_json(ASSET "\"nodes\":[{\"children\":[2]},{\"children\":[2]},{}],"
                "\"scenes\":[{\"nodes\":[0,1]}]}",
                MOTE_ERR_RANGE, "nodes[1].children[0]: nodes[2] is reached a second time");
    expect_json(ASSET "\"nodes\":[{\"mesh\":3}],\"scenes\":[{\"nodes\":[0]}]}",
                MOTE_ERR_RANGE, "nodes[0].mesh: 3 names no mesh (there are 0)");
    expect_json(ASSET "\"nodes\":[{}],\"scenes\":[{\"nodes\":[1]}]}",
                MOTE_ERR_RANGE, "scenes[0].nodes[0]: 1 is out of range [0, 0]");
    expect_json(ASSET "\"nodes\":[{\"matrix\":[1,0,0,1, 0,1,0,0, 0,0,1,0, 0,0,0,1]}],"
                "\"scenes\":[{\"nodes\":[0]}]}",
                MOTE_ERR_RANGE, "nodes[0].matrix: its last row is 1 0 0 1");
    expect_json(ASSET "\"scene\":1,\"scenes\":[{}]}", MOTE_ERR_RANGE,
                "scene: 1 names no scene (there are 1)");
    /* a chain deeper than the core follows */
    char json[4096];
    size_t n = (size_t)snprintf(json, sizeof json, ASSET "\"scenes\":[{\"nodes\":[0]}],"
                                "\"nodes\":[");
    for (int i = 0; i < MOTE_MAX_PARENTS + 2; i++)
        n += (size_t)snprintf(json + n, sizeof json - n, "%s{\"children\":[%d]}", i ? "," : "",
                              i + 1);
    snprintf(json + n, sizeof json - n, ",{}]}");
    expect_json(json, MOTE_ERR_LIMIT, "more than 64 parents (MOTE_MAX_PARENTS)");
}

/* Two scenes, the second the file's default: the first shows one node,
 * the second two (a node without a mesh is a hidden mesh). */
void the_caller_should_choose_which_scene_to_load(void)
{
    static const char json[] = ASSET "\"scene\":1,\"nodes\":[{},{},{}],"
                               "\"scenes\":[{\"nodes\":[0]},{\"nodes\":[1,2]}]}";
    static const struct {
        int choice;                 /* mote_limits.gltf_scene */
        mote_result code;
        int meshes;
    } cases[] = {{0, MOTE_OK, 2}, {1, MOTE_OK, 1}, {2, MOTE_OK, 2}, {3, MOTE_ERR_RANGE, 0}};
    for (size_t i = 0; i < sizeof cases / sizeof cases[0]; i++) {
        mote_limits lim = mote_limits_default();
        lim.gltf_scene = cases[i].choice;
        mote_scene s;
        mote_result r = mote_scene_load_memory(json, strlen(json), "two.gltf", NULL, &lim, &s, msg,
                                               sizeof msg);
        TEST_ASSERT_EQUAL_STRING(mote_result_string(cases[i].code), mote_result_string(r));
        if (r == MOTE_OK) {
            TEST_ASSERT_EQUAL_INT(cases[i].meshes, s.mesh_count);
            mote_scene_free(&s);
        } else {
            TEST_ASSERT_NOT_NULL_MESSAGE(strstr(msg, "limits.gltf_scene: 3 asks for scenes[2], but "
                                                     "the file has 2 scenes"), msg);
            TEST_ASSERT_TRUE(scene_is_zeroed(&s));
        }
    }
    /* a .babylon file holds one scene: a choice past it is warned */
    static const char babylon[] = "{\"meshes\":[]}";
    mote_limits lim = mote_limits_default();
    lim.gltf_scene = 2;
    mote_scene s;
    TEST_ASSERT_EQUAL(MOTE_OK, mote_scene_load_memory(babylon, strlen(babylon), "one.babylon", NULL,
                                                      &lim, &s, msg, sizeof msg));
    TEST_ASSERT_NOT_NULL_MESSAGE(strstr(s.warning, "limits.gltf_scene 2: a .babylon file holds "
                                                   "one scene"), s.warning);
    mote_scene_free(&s);
    TEST_ASSERT_EQUAL(live_before, mote__io_live_allocations());
}

void primitives_should_name_what_is_wrong_with_them(void)
{
    expect_json(ASSET BUF "\"bufferViews\":[{\"buffer\":0,\"byteLength\":36}],"
                "\"accessors\":[{\"bufferView\":0,\"componentType\":5126,\"count\":3,"
                "\"type\":\"VEC3\"}],\"meshes\":[{\"primitives\":[{\"attributes\":"
                "{\"POSITION\":0},\"mode\":7}]}],\"nodes\":[{\"mesh\":0}],"
                "\"scenes\":[{\"nodes\":[0]}]}",
                MOTE_ERR_RANGE, "meshes[0].primitives[0].mode: 7 is out of range [0, 6]");
    /* lines: a pair short of its second end; an index past the vertices */
    expect_json(ASSET BUF "\"bufferViews\":[{\"buffer\":0,\"byteLength\":36}],"
                "\"accessors\":[{\"bufferView\":0,\"componentType\":5126,\"count\":3,"
                "\"type\":\"VEC3\"}],\"meshes\":[{\"primitives\":[{\"attributes\":"
                "{\"POSITION\":0},\"mode\":1}]}],\"nodes\":[{\"mesh\":0}],"
                "\"scenes\":[{\"nodes\":[0]}]}",
                MOTE_OK, "meshes[0].primitives[0]: 3 vertices, not a multiple of 2; the last 1 "
                "are not drawn");
    expect_json(ASSET BUF_AND_INDICES "\"meshes\":[{\"primitives\":[{\"attributes\":"
                "{\"POSITION\":0},\"indices\":1,\"mode\":2}]}],\"nodes\":[{\"mesh\":0}],"
                "\"scenes\":[{\"nodes\":[0]}]}",
                MOTE_ERR_RANGE, "meshes[0].primitives[0].indices[1]: 5 is out of range "
                "(3 vertices)");
    expect_json(ASSET BUF_AND_INDICES "\"meshes\":[{\"primitives\":[{\"attributes\":"
                "{\"POSITION\":0},\"indices\":1,\"mode\":0}]}],\"nodes\":[{\"mesh\":0}],"
                "\"scenes\":[{\"nodes\":[0]}]}",
                MOTE_ERR_RANGE, "meshes[0].primitives[0].indices[1]: 5 is out of range");
    expect_json(ASSET "\"meshes\":[{\"primitives\":[{\"attributes\":{}}]}],"
                "\"nodes\":[{\"mesh\":0}],\"scenes\":[{\"nodes\":[0]}]}",
                MOTE_OK, "meshes[0].primitives[0]: no POSITION; not drawn");
    expect_json(ASSET "\"meshes\":[{\"primitives\":[]}],\"nodes\":[{\"mesh\":0}],"
                "\"scenes\":[{\"nodes\":[0]}]}",
                MOTE_ERR_PARSE, "meshes[0].primitives: missing or empty");
    /* materials are read where a primitive uses them */
    expect_json(ASSET "\"materials\":[{\"alphaMode\":\"SOME\"}]}", MOTE_OK,
                "no scenes: nothing is drawn");
}

void materials_cameras_and_lights_should_be_checked_where_used(void)
{
    static const char cam[] = ASSET "\"nodes\":[{\"camera\":0}],\"scenes\":[{\"nodes\":[0]}],"
                              "\"cameras\":[{\"type\":\"perspective\",\"perspective\":{%s}}]}";
    char json[512];
    snprintf(json, sizeof json, cam, "\"znear\":0.1");
    expect_json(json, MOTE_ERR_PARSE, "cameras[0].perspective: missing \"yfov\"");
    snprintf(json, sizeof json, cam, "\"yfov\":4,\"znear\":0.1");
    expect_json(json, MOTE_ERR_RANGE, "cameras[0].perspective.yfov: 4 is not in (0, pi)");
    snprintf(json, sizeof json, cam, "\"yfov\":1,\"znear\":2,\"zfar\":1");
    expect_json(json, MOTE_ERR_RANGE, "cameras[0].perspective: znear 2 is not below zfar 1");
    expect_json(ASSET "\"extensions\":{\"KHR_lights_punctual\":{\"lights\":[{\"type\":\"area\"}]}},"
                "\"nodes\":[{\"extensions\":{\"KHR_lights_punctual\":{\"light\":0}}}],"
                "\"scenes\":[{\"nodes\":[0]}]}",
                MOTE_ERR_PARSE, "extensions.KHR_lights_punctual.lights[0].type: expected "
                "\"directional\", \"point\" or \"spot\"");
    expect_json(ASSET "\"extensions\":{\"KHR_lights_punctual\":{\"lights\":[]}},"
                "\"nodes\":[{\"extensions\":{\"KHR_lights_punctual\":{\"light\":0}}}],"
                "\"scenes\":[{\"nodes\":[0]}]}",
                MOTE_ERR_RANGE, "KHR_lights_punctual.light: 0 names no light (there are 0)");
    expect_json(ASSET BUF "\"bufferViews\":[{\"buffer\":0,\"byteLength\":36}],"
                "\"accessors\":[{\"bufferView\":0,\"componentType\":5126,\"count\":3,"
                "\"type\":\"VEC3\"}],\"materials\":[{\"alphaMode\":\"SOME\"}],"
                "\"meshes\":[{\"primitives\":[{\"attributes\":{\"POSITION\":0},\"material\":0}]}],"
                "\"nodes\":[{\"mesh\":0}],\"scenes\":[{\"nodes\":[0]}]}",
                MOTE_ERR_PARSE, "materials[0].alphaMode: \"SOME\", expected \"OPAQUE\"");
}

/* A .glb's header and chunks, each error at its byte offset. */
void glb_containers_should_be_checked_chunk_by_chunk(void)
{
    unsigned char glb[64] = {'g', 'l', 'T', 'F', 2, 0, 0, 0, 40, 0, 0, 0,
                             20, 0, 0, 0, 'J', 'S', 'O', 'N'};
    memcpy(glb + 20, "{\"asset\":{\"version\":\"2.0\"}}", 20);
    memcpy(glb + 20, "{\"asset\":{\"version\":", 20);
    /* the JSON cut off is the JSON parser's error */
    expect(NULL, glb, 40, MOTE_ERR_PARSE, "unexpected end of the JSON text");
    glb[8] = 41;
    expect(NULL, glb, 40, MOTE_ERR_PARSE, "GLB byte 8: length 41, but the file has 40 bytes");
    glb[8] = 40;
    glb[12] = 21;
    expect(NULL, glb, 40, MOTE_ERR_PARSE, "GLB byte 12: chunk 0: length 21, past the end of "
           "the file (20 bytes left)");
    glb[12] = 18;
    expect(NULL, glb, 40, MOTE_ERR_PARSE, "GLB byte 12: chunk 0: length 18 is not a multiple "
           "of 4");
    glb[12] = 20;
    glb[16] = 'X';
    expect(NULL, glb, 40, MOTE_ERR_PARSE, "GLB byte 16: the first chunk is of type 0x4e4f5358, "
           "expected JSON");
    expect(NULL, glb, 10, MOTE_ERR_PARSE, "GLB byte 0: a 10-byte file, shorter than the 12-byte "
           "GLB header");
    glb[4] = 3;
    expect(NULL, glb, 40, MOTE_ERR_UNSUPPORTED, "GLB byte 4: version 3, expected 2");
}

/* ---- assimp-testmodels ------------------------------------------------- */

/* Each file and what it gives: a code and a substring of the message, or
 * for OK of the warnings ("-": none). */
static const struct {
    const char *file;
    mote_result code;
    const char *says;
} corpus[] = {
    {"glTF/BoxTextured-glTF-Binary/BoxTextured.glb", MOTE_ERR_UNSUPPORTED,
     "GLB byte 4: version 1: a glTF 1.0 binary file, which mote does not read"},
    {"glTF/BoxTextured-glTF-Embedded/BoxTextured.gltf", MOTE_ERR_UNSUPPORTED,
     "asset.version: \"1.0\": a glTF 1.0 file, which mote does not read (it reads glTF 2.0)"},
    {"glTF/BoxTextured-glTF-MaterialsCommon/BoxTextured.gltf", MOTE_ERR_UNSUPPORTED,
     "a glTF 1.0 file"},
    {"glTF/BoxTextured-glTF/BoxTextured.gltf", MOTE_ERR_UNSUPPORTED, "a glTF 1.0 file"},
    {"glTF/CesiumMilkTruck/CesiumMilkTruck.gltf", MOTE_ERR_UNSUPPORTED,
     "asset.version: 1: a glTF 1.0 file"},
    {"glTF/IncorrectVertexArrays/Cube_v1.gltf", MOTE_ERR_UNSUPPORTED, "a glTF 1.0 file"},
    {"glTF/TwoBoxes/TwoBoxes.gltf", MOTE_ERR_UNSUPPORTED, "a glTF 1.0 file"},
    {"glTF2/2CylinderEngine-glTF-Binary/2CylinderEngine.glb", MOTE_OK, "-"},
    {"glTF2/BoxBadNormals-glTF-Binary/BoxBadNormals.glb", MOTE_OK, "-"},
    {"glTF2/BoxTexcoords-glTF/boxTexcoords.gltf", MOTE_OK, "-"},
    {"glTF2/BoxTextured-glTF-Binary/BoxTextured.glb", MOTE_OK, "-"},
    {"glTF2/BoxTextured-glTF-Embedded/BoxTextured.gltf", MOTE_OK, "-"},
    {"glTF2/BoxTextured-glTF-pbrSpecularGlossiness/BoxTextured.gltf", MOTE_OK,
     "extensionsUsed: \"KHR_materials_pbrSpecularGlossiness\" is not read"},
    {"glTF2/BoxTextured-glTF-techniqueWebGL/BoxTextured.gltf", MOTE_ERR_UNSUPPORTED,
     "extensionsRequired[0]: \"KHR_technique_webgl\", an extension mote does not read"},
    {"glTF2/BoxTextured-glTF/BoxTextured.gltf", MOTE_OK, "-"},
    {"glTF2/BoxWithInfinites-glTF-Binary/BoxWithInfinites.glb", MOTE_ERR_RANGE,
     "meshes[0].primitives[0].attributes.POSITION[0]: -inf is not a finite number"},
    {"glTF2/ClearCoat-glTF/ClearCoatTest.gltf", MOTE_OK,
     "extensionsUsed: \"KHR_materials_clearcoat\" is not read"},
    {"glTF2/IncorrectVertexArrays/Cube.gltf", MOTE_OK,
     "meshes[1].primitives[0]: 35 vertices, not a multiple of 3; the last 2 are not drawn"},
    {"glTF2/IndexOutOfRange/AllIndicesOutOfRange.gltf", MOTE_ERR_RANGE,
     "meshes[0].primitives[0].indices[0]: 65535 is out of range (24 vertices)"},
    {"glTF2/IndexOutOfRange/IndexOutOfRange.gltf", MOTE_ERR_RANGE,
     "meshes[0].primitives[0].indices[0]: 255 is out of range (24 vertices)"},
    {"glTF2/MissingBin/BoxTextured.gltf", MOTE_ERR_IO,
     "buffers[0].uri: " CORPUS "/glTF2/MissingBin/BoxTextured0.bin: cannot open: No such file"},
    {"glTF2/RecursiveNodes/RecursiveNodes.gltf", MOTE_ERR_RANGE,
     "nodes[1].children[0]: nodes[0] makes a cycle (a node is its own ancestor)"},
    {"glTF2/SchemaFailures/sceneWrongType.gltf", MOTE_ERR_PARSE,
     "scene: expected an integer, found a string"},
    {"glTF2/TestNoRootNode/NoScene.gltf", MOTE_ERR_RANGE, "scene: 0 names no scene (there are 0)"},
    {"glTF2/TestNoRootNode/SceneWithoutNodes.gltf", MOTE_OK, "-"},
    {"glTF2/cameras/Cameras.gltf", MOTE_OK, "-"},
    {"glTF2/draco/2CylinderEngine.gltf", MOTE_ERR_UNSUPPORTED,
     "extensionsRequired[0]: \"KHR_draco_mesh_compression\" (Draco-compressed geometry)"},
    {"glTF2/glTF-Sample-Models/AnimatedMorphCube-glTF/AnimatedMorphCube.gltf", MOTE_OK,
     "morph targets: not applied (meshes are drawn at rest); animations: not played"},
    {"glTF2/issue_3269/texcoord_crash.gltf", MOTE_OK, "-"},
    {"glTF2/simple_skin/simple_skin.gltf", MOTE_OK,
     "skins: skinned meshes are drawn in their bind pose; animations: not played"},
    {"glTF2/textureTransform/TextureTransformTest.gltf", MOTE_OK, "-"},
    {"glTF2/wrongTypes/badArray.gltf", MOTE_ERR_PARSE,
     "meshes[0].primitives: expected an array, found an object"},
    {"glTF2/wrongTypes/badExtension.gltf", MOTE_ERR_PARSE,
     "materials[0].pbrMetallicRoughness.baseColorTexture.extensions.KHR_texture_transform: "
     "expected an object, found a string"},
    /* a normal map's scale and a name are not read */
    {"glTF2/wrongTypes/badNumber.gltf", MOTE_OK, "-"},
    {"glTF2/wrongTypes/badString.gltf", MOTE_OK, "-"},
    {"glTF2/wrongTypes/badObject.gltf", MOTE_ERR_PARSE,
     "materials[0].pbrMetallicRoughness: expected an object, found an array"},
    {"glTF2/wrongTypes/badUint.gltf", MOTE_ERR_RANGE,
     "materials[0].pbrMetallicRoughness.baseColorTexture.index: -1 is out of range"},
};

void every_assimp_gltf_file_should_load_or_fail_as_named(void)
{
    if (!io_file_exists(CORPUS "/glTF2/cameras/Cameras.gltf"))
        TEST_IGNORE_MESSAGE("Debian's assimp-testmodels is not installed (" CORPUS "): "
                            "apt-get install assimp-testmodels");
    char path[512];
    for (size_t i = 0; i < sizeof corpus / sizeof corpus[0]; i++) {
        snprintf(path, sizeof path, "%s/%s", CORPUS, corpus[i].file);
        expect(path, NULL, 0, corpus[i].code, corpus[i].says);
    }
    /* the asset generator's primitive modes: every one draws, points and
     * lines in the points and wireframe modes */
    static const mote_mode modes[16] = {
        MOTE_MODE_POINTS, MOTE_MODE_WIREFRAME, MOTE_MODE_WIREFRAME, MOTE_MODE_WIREFRAME,
        MOTE_MODE_DEFAULT, MOTE_MODE_DEFAULT, MOTE_MODE_DEFAULT, MOTE_MODE_POINTS,
        MOTE_MODE_WIREFRAME, MOTE_MODE_WIREFRAME, MOTE_MODE_WIREFRAME, MOTE_MODE_DEFAULT,
        MOTE_MODE_DEFAULT, MOTE_MODE_DEFAULT, MOTE_MODE_DEFAULT, MOTE_MODE_DEFAULT};
    for (int k = 0; k < 16; k++) {
        snprintf(path, sizeof path, "%s/glTF2/glTF-Asset-Generator/Mesh_PrimitiveMode/"
                 "Mesh_PrimitiveMode_%02d.gltf", CORPUS, k);
        expect(path, NULL, 0, MOTE_OK, "-");
        mote_scene s;
        TEST_ASSERT_EQUAL_MESSAGE(MOTE_OK, mote_scene_load(path, NULL, &s, msg, sizeof msg), msg);
        TEST_ASSERT_FALSE_MESSAGE(s.meshes[0].hidden, path);
        TEST_ASSERT_EQUAL_MESSAGE(modes[k], s.modes[0], path);
        static uint8_t rgba[48 * 32 * 4];
        io_render_scene(&s, rgba, 48, 32);
        int lit = 0;
        for (int i = 0; i < 48 * 32; i++)
            lit += rgba[4 * i] || rgba[4 * i + 1] || rgba[4 * i + 2];
        TEST_ASSERT_GREATER_THAN_MESSAGE(20, lit, path);
        mote_scene_free(&s);
    }
}

int main(void)
{
    UNITY_BEGIN();
    RUN_TEST(required_extensions_mote_cannot_draw_should_be_named);
    RUN_TEST(accessors_past_their_views_should_be_refused_before_reading);
    RUN_TEST(quantized_attributes_should_need_the_extension_and_its_types);
    RUN_TEST(sparse_indices_should_rise_inside_the_accessor);
    RUN_TEST(node_trees_should_have_no_cycles_shared_children_or_bad_references);
    RUN_TEST(primitives_should_name_what_is_wrong_with_them);
    RUN_TEST(materials_cameras_and_lights_should_be_checked_where_used);
    RUN_TEST(glb_containers_should_be_checked_chunk_by_chunk);
    RUN_TEST(every_assimp_gltf_file_should_load_or_fail_as_named);
    return UNITY_END();
}
