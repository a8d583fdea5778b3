/*
 * test_io.c - the host I/O layer: the tutorial's monkey.babylon (legacy
 * layout), a current-layout scene written here, framing, texture loading
 * and PNG/PPM output.
 */
#define _POSIX_C_SOURCE 200809L /* mkdtemp */
#include <mote/mote.h>
#include <mote/mote_io.h>
#include "io/io_internal.h"
#include "unity.h"

#include <math.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>
#include <sys/stat.h>
#include <unistd.h>

#define MONKEY MOTE_SOURCE_DIR "/../shared/assets/monkey.babylon"
#define VERTEX_COLORS MOTE_SOURCE_DIR "/tests/data/vertex_colors.babylon"
#define DATA(name) MOTE_SOURCE_DIR "/tests/data/" name

static char msg[512];
static char tmpdir[256];
static long live_before;

void setUp(void)
{
    msg[0] = '\0';
    live_before = mote__io_live_allocations();
    mote__io_set_alloc_failure_after(-1);
}

void tearDown(void) {}

static bool file_exists(const char *path)
{
    FILE *f = fopen(path, "rb");
    if (f)
        fclose(f);
    return f != NULL;
}

static const char *tmp_path(const char *name)
{
    static char path[512];
    snprintf(path, sizeof path, "%s/%s", tmpdir, name);
    return path;
}

static long read_all(const char *path, unsigned char *buf, long cap)
{
    FILE *f = fopen(path, "rb");
    TEST_ASSERT_NOT_NULL_MESSAGE(f, path);
    long n = (long)fread(buf, 1, (size_t)cap, f);
    fclose(f);
    return n;
}

#define ASSERT_VEC3(x, y, z, v, tol)               \
    do {                                           \
        TEST_ASSERT_FLOAT_WITHIN(tol, x, (v)[0]);  \
        TEST_ASSERT_FLOAT_WITHIN(tol, y, (v)[1]);  \
        TEST_ASSERT_FLOAT_WITHIN(tol, z, (v)[2]);  \
    } while (0)

/* Loads a scene from JSON text with its textures in folder dir (NULL: no
 * folder, colours only), or fails the test with the loader's message. */
static void load_json_in(const char *json, const char *name, const char *dir, mote_scene *s)
{
    TEST_ASSERT_EQUAL_MESSAGE(MOTE_OK, mote_scene_load_memory(json, strlen(json), name, dir, NULL, s,
                                                              msg, sizeof msg), msg);
}

static void load_json(const char *json, const char *name, mote_scene *s)
{
    load_json_in(json, name, NULL, s);
}

/* A width x height RGBA device without depth. */
static void init_color_device(mote_device *dev, uint8_t *color, int width, int height)
{
    mote_device_desc dd;
    memset(&dd, 0, sizeof dd);
    dd.width = width;
    dd.height = height;
    dd.color = color;
    dd.depth_format = MOTE_DEPTH_FORMAT_NONE;
    TEST_ASSERT_EQUAL(MOTE_OK, mote_device_init(dev, &dd));
}

/* A size x size RGBA device without depth, its frame begun, the camera at
 * z = -3 looking at the origin. */
static void begin_small_frame(mote_device *dev, uint8_t *color, int size)
{
    init_color_device(dev, color, size, size);
    mote_frame_desc f;
    memset(&f, 0, sizeof f);
    f.camera.position[2] = -3.0f;
    TEST_ASSERT_EQUAL(MOTE_OK, mote_begin(dev, &f));
}

/* one triangle's geometry, for scenes written inline */
#define TRI "\"positions\":[0,0,0, 1,0,0, 0,1,0],\"indices\":[0,1,2]"
/* TRI drawn twice, by materialIndex 0 and 1 */
#define TRI_TWO_SLOTS TRI ",\"subMeshes\":[{\"materialIndex\":0,\"indexStart\":0,\"indexCount\":3}," \
                      "{\"materialIndex\":1,\"indexStart\":0,\"indexCount\":3}]"

/* mesh k's material colour is rgb */
static void assert_material_rgb(const mote_scene *s, int k, const uint8_t rgb[3])
{
    TEST_ASSERT_EQUAL_UINT8(rgb[0], s->meshes[k].material.color.r);
    TEST_ASSERT_EQUAL_UINT8(rgb[1], s->meshes[k].material.color.g);
    TEST_ASSERT_EQUAL_UINT8(rgb[2], s->meshes[k].material.color.b);
}

/* ---- the tutorial's monkey -------------------------------------------- */

void loader_should_read_the_tutorial_monkey(void)
{
    if (!file_exists(MONKEY))
        TEST_IGNORE_MESSAGE("../shared/assets/monkey.babylon is absent: monkey test skipped");
    mote_scene s;
    TEST_ASSERT_EQUAL_MESSAGE(MOTE_OK, mote_scene_load(MONKEY, NULL, &s, msg, sizeof msg), msg);
    TEST_ASSERT_EQUAL_STRING("", s.warning);
    TEST_ASSERT_EQUAL(1, s.mesh_count);
    const mote_mesh *m = &s.meshes[0];
    TEST_ASSERT_EQUAL_UINT32(886, m->vertex_count);
    TEST_ASSERT_EQUAL_UINT32(966 * 3, m->index_count);
    TEST_ASSERT_NULL(m->parent);
    ASSERT_VEC3(0.001f, 0.001f, 0.001f, m->position, 0.0f);
    ASSERT_VEC3(1.0f, 1.0f, 1.0f, m->scaling, 0.0f);
    TEST_ASSERT_FALSE(m->use_quaternion);
    /* material "02 - Default": diffuse 0.4706 -> 120, Suzanne.jpg, wrap */
    TEST_ASSERT_TRUE(m->material.color_set);
    TEST_ASSERT_EQUAL_UINT8(120, m->material.color.r);
    TEST_ASSERT_EQUAL_UINT8(120, m->material.color.g);
    TEST_ASSERT_EQUAL_UINT8(120, m->material.color.b);
    TEST_ASSERT_FALSE(m->material.v_origin_bottom);
    TEST_ASSERT_EQUAL(MOTE_WRAP_REPEAT, m->material.wrap_u);
    TEST_ASSERT_EQUAL(MOTE_WRAP_REPEAT, m->material.wrap_v);
    TEST_ASSERT_EQUAL_FLOAT(1.0f, m->material.u_scale);
    TEST_ASSERT_EQUAL(1, s.texture_count);
    TEST_ASSERT_EQUAL_PTR(&s.textures[0], m->material.texture);
    TEST_ASSERT_EQUAL(512, s.textures[0].width);
    TEST_ASSERT_EQUAL(512, s.textures[0].height);
    TEST_ASSERT_EQUAL(MOTE_FORMAT_RGBA8888, s.textures[0].format);
    TEST_ASSERT_EQUAL(512 * 4, s.textures[0].stride);
    /* every index in range, every normal of unit length */
    for (uint32_t i = 0; i < m->index_count; i++)
        TEST_ASSERT_TRUE(m->indices[i] < m->vertex_count);
    for (uint32_t i = 0; i < m->vertex_count; i++) {
        const float *n = m->vertices[i].normal;
        TEST_ASSERT_FLOAT_WITHIN(0.01f, 1.0f, sqrtf(n[0] * n[0] + n[1] * n[1] + n[2] * n[2]));
    }
    TEST_ASSERT_TRUE(m->bounds_radius > 1.0f && m->bounds_radius < 3.0f);
    /* camera and the legacy light (position in `data`) */
    TEST_ASSERT_TRUE(s.has_camera);
    ASSERT_VEC3(4.0768f, 1.3828f, -4.8015f, s.camera.position, 0.0f);
    ASSERT_VEC3(-0.1386f, 0.9719f, 0.1904f, s.camera.target, 0.0f);
    TEST_ASSERT_EQUAL_FLOAT(0.8576f, s.camera.fov);
    TEST_ASSERT_EQUAL_FLOAT(0.1f, s.camera.znear);
    TEST_ASSERT_EQUAL_FLOAT(100.0f, s.camera.zfar);
    TEST_ASSERT_EQUAL(1, s.light_count);
    TEST_ASSERT_EQUAL(MOTE_LIGHT_POINT, s.lights[0].type);
    ASSERT_VEC3(4.0762f, 5.9039f, 1.0055f, s.lights[0].position, 0.0f);
    ASSERT_VEC3(1.0f, 1.0f, 1.0f, s.lights[0].color, 0.0f);
    TEST_ASSERT_EQUAL_FLOAT(1.0f, s.lights[0].intensity);
    TEST_ASSERT_EQUAL_UINT8(0, s.clear_color.r);
    TEST_ASSERT_EQUAL_UINT8(255, s.clear_color.a);
    /* Suzanne is about 2.7 x 2 x 1.7 around the origin */
    TEST_ASSERT_TRUE(s.bounds_min[0] < -1.2f && s.bounds_max[0] > 1.2f);
    TEST_ASSERT_TRUE(s.bounds_max[1] - s.bounds_min[1] > 1.5f);
    mote_scene_free(&s);
    TEST_ASSERT_NULL(s.meshes);
    TEST_ASSERT_EQUAL(live_before, mote__io_live_allocations());
}

void loader_should_keep_the_monkeys_first_vertex_exactly(void)
{
    if (!file_exists(MONKEY))
        TEST_IGNORE_MESSAGE("../shared/assets/monkey.babylon is absent: monkey test skipped");
    /* the first 8 floats of `vertices` in the file, read independently */
    FILE *f = fopen(MONKEY, "rb");
    TEST_ASSERT_NOT_NULL(f);
    static char text[300000];
    size_t n = fread(text, 1, sizeof text - 1, f);
    fclose(f);
    text[n] = '\0';
    const char *v = strstr(text, "\"vertices\"");
    TEST_ASSERT_NOT_NULL(v);
    v = strchr(v, '[') + 1;
    float expect[8];
    for (int i = 0; i < 8; i++) {
        char *end;
        expect[i] = strtof(v, &end);
        v = strchr(end, ',') + 1;
    }
    mote_scene s;
    TEST_ASSERT_EQUAL_MESSAGE(MOTE_OK, mote_scene_load(MONKEY, NULL, &s, msg, sizeof msg), msg);
    const mote_vertex *vx = &s.meshes[0].vertices[0];
    ASSERT_VEC3(expect[0], expect[1], expect[2], vx->position, 0.0f);
    ASSERT_VEC3(expect[3], expect[4], expect[5], vx->normal, 0.0f);
    TEST_ASSERT_EQUAL_FLOAT(expect[6], vx->uv[0]);
    TEST_ASSERT_EQUAL_FLOAT(expect[7], vx->uv[1]);
    mote_scene_free(&s);
}

/* ---- a current-layout scene ------------------------------------------- */

static const char current_scene[] =
    "{\"ambientColor\":[0.1,0.2,0.3],\"clearColor\":[0.2,0.4,0.6,1],"
    "\"cameras\":[{\"id\":\"c1\",\"position\":[0,0,-10],\"target\":[0,0,0]},"
    " {\"id\":\"c2\",\"position\":[1,2,3],\"rotation\":[0,1.5707963705062866,0],"
    "  \"fov\":0.7,\"minZ\":0.2,\"maxZ\":20}],"
    "\"activeCameraID\":\"c2\","
    "\"lights\":[{\"type\":1,\"direction\":[0,-1,0],\"diffuse\":[1,0.5,0.25],\"intensity\":0.5},"
    " {\"type\":3,\"direction\":[0,1,0],\"groundColor\":[0.1,0.2,0.3]},"
    " {\"type\":2,\"position\":[5,6,7],\"direction\":[0,-1,1],\"angle\":0.8,\"exponent\":3,"
    "  \"range\":1.7976931348623157e+308}],"
    "\"materials\":[{\"id\":\"red\",\"diffuse\":[1,0,0]},"
    " {\"id\":\"pbr\",\"albedoColor\":[0,0.5,1]}],"
    "\"multiMaterials\":[{\"id\":\"multi\",\"materials\":[\"red\",\"pbr\"]}],"
    "\"geometries\":{\"vertexData\":[{\"id\":\"g1\",\"positions\":[0,0,0, 1,0,0, 0,1,0],"
    "  \"normals\":[0,0,-1, 0,0,-1, 0,0,-1],\"uvs\":[0,0, 1,0, 0,1],\"indices\":[0,2,1]}]},"
    "\"meshes\":["
    " {\"id\":\"child\",\"parentId\":\"root\",\"position\":[1,0,0],"
    "  \"positions\":[0,0,0, 0,1,0, 1,0,0, 1,1,0],\"uvs\":[0,0, 0,1, 1,0, 1,1],"
    "  \"indices\":[0,1,2, 2,1,3],\"materialId\":\"multi\",\"subMeshes\":["
    "   {\"materialIndex\":0,\"verticesStart\":0,\"verticesCount\":4,\"indexStart\":0,\"indexCount\":3},"
    "   {\"materialIndex\":1,\"verticesStart\":0,\"verticesCount\":4,\"indexStart\":3,\"indexCount\":3}]},"
    " {\"id\":\"root\",\"position\":[0,2,0],\"rotation\":[1,2,3],"
    "  \"rotationQuaternion\":[0,0,0.70710678,0.70710678],\"scaling\":[2,2,2],"
    "  \"geometryId\":\"g1\",\"materialId\":\"pbr\"}]}";

void loader_should_read_the_current_layout_with_exact_fields(void)
{
    mote_scene s;
    TEST_ASSERT_EQUAL_MESSAGE(MOTE_OK, mote_scene_load_memory(current_scene, strlen(current_scene),
                                                              "current.babylon", NULL, NULL, &s,
                                                              msg, sizeof msg), msg);
    TEST_ASSERT_EQUAL_STRING("", s.warning);
    TEST_ASSERT_EQUAL(3, s.mesh_count); /* child: two sub-meshes, root: one */
    const mote_mesh *c0 = &s.meshes[0], *c1 = &s.meshes[1], *root = &s.meshes[2];
    /* sub-meshes share the vertex array and split the indices */
    TEST_ASSERT_EQUAL_UINT32(4, c0->vertex_count);
    TEST_ASSERT_EQUAL_PTR(c0->vertices, c1->vertices);
    TEST_ASSERT_EQUAL_UINT32(3, c0->index_count);
    TEST_ASSERT_EQUAL_UINT32(3, c1->index_count);
    TEST_ASSERT_EQUAL_PTR(c0->indices + 3, c1->indices);
    TEST_ASSERT_EQUAL_UINT32(2, c1->indices[0]);
    TEST_ASSERT_EQUAL_UINT32(3, c1->indices[2]);
    ASSERT_VEC3(1.0f, 1.0f, 0.0f, c0->vertices[3].position, 0.0f);
    TEST_ASSERT_EQUAL_FLOAT(1.0f, c0->vertices[1].uv[1]);
    /* no normals in the file: smooth ones, oriented as Babylon computes them */
    for (int i = 0; i < 4; i++)
        ASSERT_VEC3(0.0f, 0.0f, 1.0f, c0->vertices[i].normal, 1e-6f);
    /* the multi-material's slots by materialIndex */
    TEST_ASSERT_TRUE(c0->material.color_set);
    TEST_ASSERT_EQUAL_UINT8(255, c0->material.color.r);
    TEST_ASSERT_EQUAL_UINT8(0, c0->material.color.g);
    TEST_ASSERT_EQUAL_UINT8(0, c1->material.color.r);
    TEST_ASSERT_EQUAL_UINT8(128, c1->material.color.g);
    TEST_ASSERT_EQUAL_UINT8(255, c1->material.color.b);
    TEST_ASSERT_TRUE(c0->material.v_origin_bottom);
    TEST_ASSERT_TRUE(root->material.v_origin_bottom);
    TEST_ASSERT_EQUAL_UINT8(128, root->material.color.g);
    /* parentId names a mesh defined later */
    TEST_ASSERT_EQUAL_PTR(root, c0->parent);
    TEST_ASSERT_EQUAL_PTR(root, c1->parent);
    TEST_ASSERT_NULL(root->parent);
    ASSERT_VEC3(1.0f, 0.0f, 0.0f, c0->position, 0.0f);
    /* rotationQuaternion overrides rotation */
    TEST_ASSERT_TRUE(root->use_quaternion);
    TEST_ASSERT_EQUAL_FLOAT(0.70710678f, root->rotation_quaternion[2]);
    TEST_ASSERT_EQUAL_FLOAT(0.70710678f, root->rotation_quaternion[3]);
    ASSERT_VEC3(2.0f, 2.0f, 2.0f, root->scaling, 0.0f);
    /* geometryId */
    TEST_ASSERT_EQUAL_UINT32(3, root->vertex_count);
    TEST_ASSERT_EQUAL_UINT32(3, root->index_count);
    TEST_ASSERT_EQUAL_UINT32(2, root->indices[1]);
    ASSERT_VEC3(0.0f, 0.0f, -1.0f, root->vertices[2].normal, 0.0f);
    TEST_ASSERT_EQUAL_FLOAT(1.0f, root->vertices[2].uv[1]);
    /* world box: root turns +x to +y, scales 2, moves up 2; the child sits
     * inside it at x + 1 */
    ASSERT_VEC3(-2.0f, 2.0f, 0.0f, s.bounds_min, 1e-5f);
    ASSERT_VEC3(0.0f, 6.0f, 0.0f, s.bounds_max, 1e-5f);
    /* camera c2: yaw pi/2 turns forward +z to +x */
    TEST_ASSERT_TRUE(s.has_camera);
    ASSERT_VEC3(1.0f, 2.0f, 3.0f, s.camera.position, 0.0f);
    ASSERT_VEC3(2.0f, 2.0f, 3.0f, s.camera.target, 1e-5f);
    TEST_ASSERT_EQUAL_FLOAT(0.7f, s.camera.fov);
    TEST_ASSERT_EQUAL_FLOAT(0.2f, s.camera.znear);
    TEST_ASSERT_EQUAL_FLOAT(20.0f, s.camera.zfar);
    /* lights: directional, hemispheric, spot (Number.MAX_VALUE range: none) */
    TEST_ASSERT_EQUAL(3, s.light_count);
    TEST_ASSERT_EQUAL(MOTE_LIGHT_DIRECTIONAL, s.lights[0].type);
    ASSERT_VEC3(0.0f, -1.0f, 0.0f, s.lights[0].direction, 0.0f);
    ASSERT_VEC3(1.0f, 0.5f, 0.25f, s.lights[0].color, 0.0f);
    TEST_ASSERT_EQUAL_FLOAT(0.5f, s.lights[0].intensity);
    TEST_ASSERT_EQUAL(MOTE_LIGHT_HEMISPHERIC, s.lights[1].type);
    ASSERT_VEC3(0.0f, 1.0f, 0.0f, s.lights[1].direction, 0.0f);
    ASSERT_VEC3(0.1f, 0.2f, 0.3f, s.lights[1].ground_color, 0.0f);
    TEST_ASSERT_EQUAL_FLOAT(1.0f, s.lights[1].intensity);
    TEST_ASSERT_EQUAL(MOTE_LIGHT_SPOT, s.lights[2].type);
    ASSERT_VEC3(5.0f, 6.0f, 7.0f, s.lights[2].position, 0.0f);
    ASSERT_VEC3(0.0f, -1.0f, 1.0f, s.lights[2].direction, 0.0f);
    TEST_ASSERT_EQUAL_FLOAT(0.8f, s.lights[2].spot_angle);
    TEST_ASSERT_EQUAL_FLOAT(3.0f, s.lights[2].spot_exponent);
    TEST_ASSERT_EQUAL_FLOAT(0.0f, s.lights[2].range);
    ASSERT_VEC3(0.1f, 0.2f, 0.3f, s.ambient, 0.0f);
    TEST_ASSERT_EQUAL_UINT8(51, s.clear_color.r);
    TEST_ASSERT_EQUAL_UINT8(102, s.clear_color.g);
    TEST_ASSERT_EQUAL_UINT8(153, s.clear_color.b);
    TEST_ASSERT_EQUAL(0, s.texture_count);
    mote_scene_free(&s);
    TEST_ASSERT_EQUAL(live_before, mote__io_live_allocations());
}

/* A light's range (point and spot; Babylon.js's default falloff) and a
 * spot light's cone; a parent moves a spot light and turns its direction. */
void loader_should_read_light_ranges_and_spot_cones(void)
{
    const char *j = "{\"transformNodes\":[{\"id\":\"t\",\"position\":[0,1,0],"
                    "  \"rotation\":[0,1.5707963705062866,0]}],"
                    "\"lights\":[{\"type\":0,\"position\":[1,2,3],\"range\":7.5},"
                    " {\"type\":1,\"direction\":[0,-1,0],\"range\":3},"
                    " {\"type\":2,\"parentId\":\"t\",\"position\":[0,0,2],\"direction\":[0,0,1],"
                    "  \"angle\":1.2,\"exponent\":0.5,\"range\":20},"
                    " {\"type\":2,\"position\":[0,0,0],\"range\":-2}]}";
    mote_scene s;
    load_json(j, "ranges.babylon", &s);
    TEST_ASSERT_EQUAL(4, s.light_count);
    TEST_ASSERT_EQUAL(MOTE_LIGHT_POINT, s.lights[0].type);
    TEST_ASSERT_EQUAL_FLOAT(7.5f, s.lights[0].range);
    TEST_ASSERT_EQUAL(MOTE_LIGHT_DIRECTIONAL, s.lights[1].type);
    TEST_ASSERT_EQUAL_FLOAT(0.0f, s.lights[1].range);      /* directional: none */
    TEST_ASSERT_EQUAL(MOTE_LIGHT_SPOT, s.lights[2].type);
    TEST_ASSERT_EQUAL_FLOAT(1.2f, s.lights[2].spot_angle);
    TEST_ASSERT_EQUAL_FLOAT(0.5f, s.lights[2].spot_exponent);
    TEST_ASSERT_EQUAL_FLOAT(20.0f, s.lights[2].range);
    /* the parent turns +z to +x and lifts by 1 */
    ASSERT_VEC3(2.0f, 1.0f, 0.0f, s.lights[2].position, 1e-5f);
    ASSERT_VEC3(1.0f, 0.0f, 0.0f, s.lights[2].direction, 1e-5f);
    /* Babylon.js's defaults: no angle (it lights nothing), exponent 0; a
     * negative range is none */
    TEST_ASSERT_EQUAL(MOTE_LIGHT_SPOT, s.lights[3].type);
    TEST_ASSERT_EQUAL_FLOAT(0.0f, s.lights[3].spot_angle);
    TEST_ASSERT_EQUAL_FLOAT(0.0f, s.lights[3].spot_exponent);
    TEST_ASSERT_EQUAL_FLOAT(0.0f, s.lights[3].range);
    mote_scene_free(&s);
}

void loader_should_give_transform_nodes_a_mesh_to_be_parents(void)
{
    const char *j = "{\"meshes\":[{\"id\":\"m\",\"parentId\":\"t\","
                    "\"positions\":[0,0,0, 1,0,0, 0,1,0],\"indices\":[0,1,2]}],"
                    "\"transformNodes\":[{\"id\":\"t\",\"position\":[10,0,0],"
                    "\"parentId\":\"e\"},{\"id\":\"e\",\"scaling\":[1,3,1]}]}";
    mote_scene s;
    load_json(j, "t", &s);
    TEST_ASSERT_EQUAL(3, s.mesh_count);
    TEST_ASSERT_EQUAL_PTR(&s.meshes[1], s.meshes[0].parent);
    TEST_ASSERT_EQUAL_PTR(&s.meshes[2], s.meshes[1].parent);
    TEST_ASSERT_EQUAL_UINT32(0, s.meshes[1].vertex_count);
    TEST_ASSERT_EQUAL_UINT32(0, s.meshes[1].index_count);
    ASSERT_VEC3(10.0f, 0.0f, 0.0f, s.meshes[1].position, 0.0f);
    /* world = scale(1,3,1) * translate(10,0,0) * mesh */
    ASSERT_VEC3(10.0f, 0.0f, 0.0f, s.bounds_min, 1e-5f);
    ASSERT_VEC3(11.0f, 3.0f, 0.0f, s.bounds_max, 1e-5f);
    mote_scene_free(&s);
}

/* Current Babylon.js writes parentId as the parent's numeric uniqueId
 * (Node._serializeAsParent), also for a parent defined later. */
void loader_should_resolve_a_numeric_parent_id_by_unique_id(void)
{
    const char *j = "{\"meshes\":[{\"id\":\"child\",\"uniqueId\":7,\"parentId\":5,"
                    TRI "},"
                    "{\"id\":\"5\",\"uniqueId\":9},"
                    "{\"id\":\"root\",\"uniqueId\":5,\"position\":[10,0,0]}]}";
    mote_scene s;
    load_json(j, "u", &s);
    TEST_ASSERT_EQUAL(3, s.mesh_count);
    /* the uniqueId 5, not the mesh whose id is the string "5" */
    TEST_ASSERT_EQUAL_PTR(&s.meshes[2], s.meshes[0].parent);
    ASSERT_VEC3(10.0f, 0.0f, 0.0f, s.bounds_min, 1e-5f);
    mote_scene_free(&s);
}

/* isVisible false hides one mesh; isEnabled false hides a mesh and its
 * children; hidden meshes stay parents, and stay out of the scene box. */
void loader_should_hide_invisible_and_disabled_meshes(void)
{
    const char *j = "{\"meshes\":["
                    "{\"id\":\"a\",\"isVisible\":false,\"position\":[100,0,0],"
                    TRI "},"
                    "{\"id\":\"a-child\",\"parentId\":\"a\","
                    TRI "},"
                    "{\"id\":\"b\",\"isEnabled\":false,"
                    TRI "},"
                    "{\"id\":\"b-child\",\"parentId\":\"b\",\"isVisible\":true,\"position\":[-50,0,0],"
                    TRI "},"
                    "{\"id\":\"c\",\"isVisible\":1,\"isEnabled\":true,"
                    TRI "}]}";
    mote_scene s;
    load_json(j, "h", &s);
    TEST_ASSERT_EQUAL(5, s.mesh_count);
    TEST_ASSERT_TRUE(s.meshes[0].hidden);
    TEST_ASSERT_FALSE(s.meshes[1].hidden);
    TEST_ASSERT_EQUAL_PTR(&s.meshes[0], s.meshes[1].parent);
    TEST_ASSERT_TRUE(s.meshes[2].hidden);
    TEST_ASSERT_TRUE(s.meshes[3].hidden);
    TEST_ASSERT_FALSE(s.meshes[4].hidden);
    /* the box: c (0..1) and a-child under a (100..101), not b-child at -50 */
    ASSERT_VEC3(0.0f, 0.0f, 0.0f, s.bounds_min, 1e-5f);
    ASSERT_VEC3(101.0f, 1.0f, 0.0f, s.bounds_max, 1e-5f);
    /* mote_draw skips a hidden mesh */
    static uint8_t color[8 * 8 * 4];
    mote_device dev;
    begin_small_frame(&dev, color, 8);
    TEST_ASSERT_EQUAL(MOTE_OK, mote_draw(&dev, &s.meshes[2], NULL));
    TEST_ASSERT_EQUAL(MOTE_OK, mote_end(&dev));
    TEST_ASSERT_EQUAL_UINT32(0, mote_device_stats(&dev)->draws);
    mote_scene_free(&s);
}

/* The texture's invertY says which row v = 0 is; unsaid, the layout does. */
void loader_should_take_the_texture_row_of_v0_from_invert_y(void)
{
    const char *j = "{\"materials\":["
                    "{\"id\":\"flip\",\"diffuseTexture\":{\"name\":\"t.png\",\"invertY\":true}},"
                    "{\"id\":\"keep\",\"diffuseTexture\":{\"name\":\"t.png\",\"invertY\":false}},"
                    "{\"id\":\"unsaid\",\"diffuseTexture\":{\"name\":\"t.png\"}}],"
                    "\"meshes\":["
                    "{\"id\":\"a\",\"materialId\":\"flip\",\"positions\":[0,0,0],\"indices\":[]},"
                    "{\"id\":\"b\",\"materialId\":\"keep\",\"positions\":[0,0,0],\"indices\":[]},"
                    "{\"id\":\"c\",\"materialId\":\"unsaid\",\"positions\":[0,0,0],\"indices\":[]},"
                    "{\"id\":\"d\",\"materialId\":\"unsaid\",\"uvCount\":0,\"vertices\":[0,0,0,0,0,1],"
                    "\"indices\":[]},"
                    "{\"id\":\"e\",\"materialId\":\"flip\",\"uvCount\":0,\"vertices\":[0,0,0,0,0,1],"
                    "\"indices\":[]}]}";
    mote_scene s;
    load_json(j, "v", &s);
    TEST_ASSERT_EQUAL(5, s.mesh_count);
    TEST_ASSERT_TRUE(s.meshes[0].material.v_origin_bottom);
    TEST_ASSERT_FALSE(s.meshes[1].material.v_origin_bottom);
    TEST_ASSERT_TRUE(s.meshes[2].material.v_origin_bottom);   /* current layout */
    TEST_ASSERT_FALSE(s.meshes[3].material.v_origin_bottom);  /* legacy layout */
    TEST_ASSERT_TRUE(s.meshes[4].material.v_origin_bottom);   /* legacy, said */
    mote_scene_free(&s);
}

/* scaling [0,0,0] in a file is a zero scale (the core reads zeros as
 * "unset"); a light of intensity 0 adds nothing, ground colour included;
 * a black hemispheric light keeps its ground colour at its intensity. */
void loader_should_keep_explicit_zeros_of_scale_and_light(void)
{
    const char *j = "{\"meshes\":[{\"id\":\"z\",\"scaling\":[0,0,0],"
                    TRI "}],"
                    "\"lights\":[{\"type\":3,\"intensity\":0,\"groundColor\":[1,1,1]},"
                    "{\"type\":3,\"intensity\":2,\"diffuse\":[0,0,0],\"groundColor\":[0.25,0.5,1]}]}";
    mote_scene s;
    load_json(j, "z", &s);
    float w[16];
    mote_mesh_world_matrix(&s.meshes[0], w);
    for (int c = 0; c < 3; c++)
        for (int r = 0; r < 3; r++)
            TEST_ASSERT_TRUE(fabsf(w[c * 4 + r]) < 1e-20f);
    TEST_ASSERT_EQUAL(2, s.light_count);
    /* what each adds to a vertex: intensity x (colour w + ground (1 - w)) */
    ASSERT_VEC3(0.0f, 0.0f, 0.0f, s.lights[0].ground_color, 0.0f);
    TEST_ASSERT_TRUE(s.lights[0].intensity * s.lights[0].color[0] < 1e-20f);
    TEST_ASSERT_EQUAL_FLOAT(2.0f, s.lights[1].intensity);
    ASSERT_VEC3(0.25f, 0.5f, 1.0f, s.lights[1].ground_color, 0.0f);
    TEST_ASSERT_TRUE(s.lights[1].color[0] < 1e-20f);
    mote_scene_free(&s);
}

/* Meshes naming one geometries.vertexData entry share its arrays: a small
 * file cannot multiply its memory by naming a big geometry many times. */
void loader_should_share_a_geometry_between_the_meshes_naming_it(void)
{
    const char *j = "{\"geometries\":{\"vertexData\":["
                    "{\"id\":\"g0\","
                    TRI "},"
                    "{\"id\":\"g1\",\"positions\":[0,0,0, 2,0,0, 0,2,0],\"indices\":[0,1,2]},"
                    "{\"id\":\"g0\",\"positions\":[5,5,5],\"indices\":[]}]},"
                    "\"meshes\":[{\"id\":\"a\",\"geometryId\":\"g1\"},{\"id\":\"b\",\"geometryId\":\"g0\"},"
                    "{\"id\":\"c\",\"geometryId\":\"g1\",\"position\":[3,0,0]}]}";
    mote_scene s;
    load_json(j, "g", &s);
    TEST_ASSERT_EQUAL(3, s.mesh_count);
    TEST_ASSERT_EQUAL_PTR(s.meshes[0].vertices, s.meshes[2].vertices);
    TEST_ASSERT_EQUAL_PTR(s.meshes[0].indices, s.meshes[2].indices);
    TEST_ASSERT_EQUAL_FLOAT(2.0f, s.meshes[0].vertices[1].position[0]);
    /* the first entry of an id wins */
    TEST_ASSERT_EQUAL_UINT32(3, s.meshes[1].vertex_count);
    TEST_ASSERT_EQUAL_FLOAT(1.0f, s.meshes[1].vertices[1].position[0]);
    ASSERT_VEC3(5.0f, 2.0f, 0.0f, s.bounds_max, 1e-5f);
    mote_scene_free(&s);
}

/* instances: the source's geometry, material and sub-meshes, with their
 * own transform, parent and visibility, after the meshes and transform
 * nodes */
void loader_should_draw_a_mesh_again_for_each_of_its_instances(void)
{
    const char *j = "{\"materials\":[{\"id\":\"red\",\"diffuse\":[1,0,0]}],"
                    "\"meshes\":[{\"id\":\"src\",\"materialId\":\"red\"," TRI ","
                    "\"subMeshes\":[{\"materialIndex\":0,\"verticesStart\":0,\"verticesCount\":3,"
                    "\"indexStart\":0,\"indexCount\":3}],"
                    "\"instances\":[{\"name\":\"i0\",\"position\":[5,0,0],\"scaling\":[2,2,2]},"
                    "{\"name\":\"i1\",\"parentId\":\"t\",\"isVisible\":false,\"rotationQuaternion\":[0,0,0,1]}]}],"
                    "\"transformNodes\":[{\"id\":\"t\",\"position\":[0,7,0]}]}";
    mote_scene s;
    load_json(j, "i", &s);
    TEST_ASSERT_EQUAL(4, s.mesh_count);
    for (int k = 2; k < 4; k++) {
        TEST_ASSERT_EQUAL_PTR(s.meshes[0].vertices, s.meshes[k].vertices);
        TEST_ASSERT_EQUAL_PTR(s.meshes[0].indices, s.meshes[k].indices);
        TEST_ASSERT_EQUAL_UINT32(3, s.meshes[k].index_count);
        TEST_ASSERT_EQUAL_UINT8(255, s.meshes[k].material.color.r);
        TEST_ASSERT_EQUAL_UINT8(0, s.meshes[k].material.color.g);
    }
    ASSERT_VEC3(5.0f, 0.0f, 0.0f, s.meshes[2].position, 0.0f);
    ASSERT_VEC3(2.0f, 2.0f, 2.0f, s.meshes[2].scaling, 0.0f);
    TEST_ASSERT_NULL(s.meshes[2].parent);
    TEST_ASSERT_FALSE(s.meshes[2].hidden);
    TEST_ASSERT_EQUAL_PTR(&s.meshes[1], s.meshes[3].parent);
    TEST_ASSERT_TRUE(s.meshes[3].use_quaternion);
    TEST_ASSERT_TRUE(s.meshes[3].hidden);
    /* the box: the source (0..1) and i0 at 5, twice as large (5..7) */
    ASSERT_VEC3(7.0f, 2.0f, 0.0f, s.bounds_max, 1e-5f);
    mote_scene_free(&s);
}

/* a child of an instance names the instance's source and the instance's
 * place among the source's instances (parentInstanceIndex); -1 is the
 * source itself */
void loader_should_attach_a_child_to_the_instance_its_parent_index_names(void)
{
    const char *j = "{\"meshes\":[{\"id\":\"src\"," TRI ","
                    "\"instances\":[{\"name\":\"i0\",\"position\":[5,0,0]},"
                    "{\"name\":\"i1\",\"position\":[-5,0,0]}]},"
                    "{\"id\":\"on-i1\",\"parentId\":\"src\",\"parentInstanceIndex\":1," TRI "},"
                    "{\"id\":\"on-src\",\"parentId\":\"src\",\"parentInstanceIndex\":-1," TRI "}]}";
    mote_scene s;
    load_json(j, "pi", &s);
    TEST_ASSERT_EQUAL(5, s.mesh_count);   /* src, on-i1, on-src, i0, i1 */
    ASSERT_VEC3(-5.0f, 0.0f, 0.0f, s.meshes[4].position, 0.0f);
    TEST_ASSERT_EQUAL_PTR(&s.meshes[4], s.meshes[1].parent);
    TEST_ASSERT_EQUAL_PTR(&s.meshes[0], s.meshes[2].parent);
    mote_scene_free(&s);
}

/* materialUniqueId picks among materials sharing an id (glTF re-exports);
 * when it matches nothing, materialId (last holder) is used; a multi-
 * material is found by its uniqueId too. */
void loader_should_resolve_material_unique_id_before_material_id(void)
{
    const char *j = "{\"materials\":[{\"id\":\"m\",\"uniqueId\":5,\"diffuse\":[1,0,0]},"
                    "{\"id\":\"m\",\"uniqueId\":6,\"diffuse\":[0,1,0]},"
                    "{\"id\":\"m\",\"uniqueId\":7,\"diffuse\":[0,0,1]}],"
                    "\"multiMaterials\":[{\"id\":\"mm\",\"uniqueId\":9,\"materials\":[\"m\"]}],"
                    "\"meshes\":[{\"id\":\"a\",\"materialId\":\"m\",\"materialUniqueId\":5," TRI "},"
                    "{\"id\":\"b\",\"materialId\":\"m\",\"materialUniqueId\":6," TRI "},"
                    "{\"id\":\"c\",\"materialId\":\"m\",\"materialUniqueId\":42," TRI "},"
                    "{\"id\":\"d\",\"materialUniqueId\":9," TRI "}]}";
    mote_scene s;
    load_json(j, "u", &s);
    TEST_ASSERT_EQUAL(4, s.mesh_count);
    static const uint8_t rgb[4][3] = {{255, 0, 0}, {0, 255, 0}, {0, 0, 255}, {0, 0, 255}};
    for (int k = 0; k < 4; k++)
        assert_material_rgb(&s, k, rgb[k]);
    mote_scene_free(&s);
}

/* A multi-material's materialsUniqueIds (the SceneSerializer writes them
 * beside the ids) pick its slots, as Babylon.js resolves them: here two
 * materials share the id "mat", as a playground naming every material so
 * writes them, and each slot gets its own. */
void loader_should_resolve_multi_material_slots_by_unique_id(void)
{
    const char *j = "{\"materials\":[{\"id\":\"mat\",\"uniqueId\":7,\"diffuse\":[1,0,0]},"
                    "{\"id\":\"mat\",\"uniqueId\":9,\"diffuse\":[0,0,1]}],"
                    "\"multiMaterials\":[{\"id\":\"mm\",\"uniqueId\":11,"
                    "\"materialsUniqueIds\":[7,9,null,8],\"materials\":[\"mat\",\"mat\",null,\"x\"]}],"
                    "\"meshes\":[{\"id\":\"a\",\"materialId\":\"mm\",\"materialUniqueId\":11,"
                    TRI_TWO_SLOTS "}]}";
    mote_scene s;
    load_json(j, "mu", &s);
    TEST_ASSERT_EQUAL(2, s.mesh_count);
    static const uint8_t red[3] = {255, 0, 0}, blue[3] = {0, 0, 255};
    assert_material_rgb(&s, 0, red);
    assert_material_rgb(&s, 1, blue);
    TEST_ASSERT_NOT_NULL_MESSAGE(strstr(s.warning, "multiMaterials[0].materialsUniqueIds[3]: 8 is "
                                        "the uniqueId of no material"), s.warning);
    mote_scene_free(&s);
}

/* A material of a type mote does not read (the materials library's sky,
 * grid or water, a node material) is drawn as a standard material of its
 * diffuse colour, with a warning; the standard and PBR types are read. */
void loader_should_warn_of_a_material_type_it_does_not_read(void)
{
    const char *j = "{\"materials\":[{\"id\":\"sky\",\"customType\":\"BABYLON.SkyMaterial\","
                    "\"luminance\":1},{\"id\":\"std\",\"customType\":\"BABYLON.StandardMaterial\"},"
                    "{\"id\":\"pbr\",\"customType\":\"BABYLON.PBRMaterial\",\"albedo\":[1,0,0]}],"
                    "\"meshes\":[{\"id\":\"a\",\"materialId\":\"sky\"," TRI "},"
                    "{\"id\":\"b\",\"materialId\":\"std\"," TRI "},"
                    "{\"id\":\"c\",\"materialId\":\"pbr\"," TRI "}]}";
    mote_scene s;
    load_json(j, "ct", &s);
    TEST_ASSERT_EQUAL_STRING("materials[0]: customType \"BABYLON.SkyMaterial\" is not read; drawn "
                             "as a standard material of its diffuse colour", s.warning);
    static const uint8_t red[3] = {255, 0, 0};
    TEST_ASSERT_FALSE(s.meshes[0].material.color_set);   /* white, as a default material */
    assert_material_rgb(&s, 2, red);
    mote_scene_free(&s);
}

/* Texture.Parse makes no texture of one without a name, null (as old 3ds
 * Max exports write a map without a bitmap), absent or "", even with a
 * base64String: the material keeps its colour, and nothing is loaded (nor
 * warned of, as an emissive texture with a name is). */
void loader_should_make_no_texture_of_one_without_a_name(void)
{
    const char *j = "{\"materials\":[{\"id\":\"null\",\"diffuse\":[1,0,0],\"diffuseTexture\":"
                    "{\"name\":null,\"level\":1.0,\"hasAlpha\":true}},"
                    "{\"id\":\"empty\",\"diffuse\":[1,0,0],\"diffuseTexture\":{\"name\":\"\"},"
                    "\"emissiveTexture\":{\"name\":null}},"
                    "{\"id\":\"b64\",\"diffuse\":[1,0,0],\"diffuseTexture\":{\"base64String\":"
                    "\"data:image/png;base64,iVBORw0KGgoAAAANSUhEUgAAAAIAAAACCAIAAAD91JpzAAAAEklEQVR4"
                    "nGP4z8DAAMIM/4EAAB/uBfsL2WiLAAAAAElFTkSuQmCC\"}}],"
                    "\"meshes\":[{\"id\":\"a\",\"materialId\":\"null\"," TRI "},"
                    "{\"id\":\"b\",\"materialId\":\"empty\"," TRI "},"
                    "{\"id\":\"c\",\"materialId\":\"b64\"," TRI "}]}";
    mote_scene s;
    load_json_in(j, "noname", DATA(""), &s);
    TEST_ASSERT_EQUAL_STRING("", s.warning);
    TEST_ASSERT_EQUAL(0, s.texture_count);
    static const uint8_t red[3] = {255, 0, 0};
    for (int k = 0; k < 3; k++) {
        TEST_ASSERT_NULL(s.meshes[k].material.texture);
        assert_material_rgb(&s, k, red);
    }
    mote_scene_free(&s);
}

/* PBRMetallicRoughnessMaterial (the 3ds Max exporter's PBR material) keeps
 * its albedo in baseColor and baseTexture, the only keys Babylon.js reads
 * for it: a diffuse written beside them is not its colour; other types
 * read no baseColor. */
void loader_should_read_the_base_colour_and_texture_of_a_metallic_roughness_material(void)
{
    const char *j = "{\"materials\":[{\"id\":\"mr\",\"customType\":"
                    "\"BABYLON.PBRMetallicRoughnessMaterial\",\"baseColor\":[0,0,1],\"diffuse\":[1,0,0],"
                    "\"baseTexture\":{\"name\":\"data:image/png;base64,iVBORw0KGgoAAAANSUhEUgAAAAIAAAACCAIAAAD9"
                    "1JpzAAAAEklEQVR4nGP4z8DAAMIM/4EAAB/uBfsL2WiLAAAAAElFTkSuQmCC\"}},"
                    "{\"id\":\"pbr\",\"customType\":\"BABYLON.PBRMaterial\",\"baseColor\":[0,0,1],"
                    "\"albedo\":[0,1,0]}],"
                    "\"meshes\":[{\"id\":\"a\",\"materialId\":\"mr\"," TRI "},"
                    "{\"id\":\"b\",\"materialId\":\"pbr\"," TRI "}]}";
    mote_scene s;
    load_json_in(j, "mr", DATA(""), &s);
    TEST_ASSERT_EQUAL_STRING("", s.warning);
    static const uint8_t blue[3] = {0, 0, 255}, green[3] = {0, 255, 0};
    assert_material_rgb(&s, 0, blue);
    TEST_ASSERT_EQUAL(1, s.texture_count);
    TEST_ASSERT_EQUAL_PTR(&s.textures[0], s.meshes[0].material.texture);
    assert_material_rgb(&s, 1, green);
    TEST_ASSERT_NULL(s.meshes[1].material.texture);
    mote_scene_free(&s);
}

/* An image embedded as a base64 data: URL, in base64String (SceneSerializer,
 * whose "name" is no file) or in name itself: decoded, loaded once for the
 * two materials carrying the same text, rows as in the PNG. */
void loader_should_decode_textures_embedded_as_base64_data_urls(void)
{
    mote_scene s;
    TEST_ASSERT_EQUAL_MESSAGE(MOTE_OK,
                              mote_scene_load(MOTE_SOURCE_DIR "/tests/data/bad/texture_embedded.babylon",
                                              NULL, &s, msg, sizeof msg), msg);
    TEST_ASSERT_EQUAL_STRING("", s.warning);
    TEST_ASSERT_EQUAL(2, s.mesh_count);
    TEST_ASSERT_EQUAL(1, s.texture_count);
    TEST_ASSERT_EQUAL_PTR(&s.textures[0], s.meshes[0].material.texture);
    TEST_ASSERT_EQUAL_PTR(&s.textures[0], s.meshes[1].material.texture);
    const mote_texture *t = &s.textures[0];
    TEST_ASSERT_EQUAL(2, t->width);
    TEST_ASSERT_EQUAL(2, t->height);
    /* red, green / blue, white */
    static const uint8_t want[16] = {255, 0, 0, 255, 0, 255, 0, 255,
                                     0, 0, 255, 255, 255, 255, 255, 255};
    TEST_ASSERT_EQUAL_UINT8_ARRAY(want, t->pixels, 16);
    mote_scene_free(&s);
    TEST_ASSERT_EQUAL(live_before, mote__io_live_allocations());
}

/* backFaceCulling false: both sides drawn. The flag is per mesh (sub-meshes
 * of a multi-material each get their slot's), applied by
 * mote_scene_draw_desc; the same triangle is drawn facing and turned away,
 * so exactly one of each pair is a back face. */
void loader_should_draw_both_sides_when_back_face_culling_is_false(void)
{
    const char *j = "{\"materials\":[{\"id\":\"two\",\"backFaceCulling\":false},"
                    "{\"id\":\"one\",\"backFaceCulling\":true}],"
                    "\"multiMaterials\":[{\"id\":\"mm\",\"materials\":[\"one\",\"two\"]}],"
                    "\"meshes\":[{\"id\":\"a\",\"materialId\":\"two\"," TRI "},"
                    "{\"id\":\"b\",\"materialId\":\"two\",\"rotation\":[0,3.14159265,0]," TRI "},"
                    "{\"id\":\"c\",\"materialId\":\"one\"," TRI "},"
                    "{\"id\":\"d\",\"materialId\":\"one\",\"rotation\":[0,3.14159265,0]," TRI "},"
                    "{\"id\":\"e\",\"materialId\":\"mm\"," TRI_TWO_SLOTS "}]}";
    mote_scene s;
    load_json(j, "b", &s);
    TEST_ASSERT_EQUAL(6, s.mesh_count);
    static const bool want[6] = {true, true, false, false, false, true};
    for (int k = 0; k < 6; k++)
        TEST_ASSERT_EQUAL(want[k], s.two_sided[k]);
    mote_draw_desc base = {0}, d;
    base.mode = MOTE_MODE_FLAT;
    mote_scene_draw_desc(&s, 0, &base, &d);
    TEST_ASSERT_EQUAL(MOTE_CULL_NONE, d.cull);
    TEST_ASSERT_EQUAL(MOTE_MODE_FLAT, d.mode);
    mote_scene_draw_desc(&s, 2, &base, &d);
    TEST_ASSERT_EQUAL(MOTE_CULL_DEFAULT, d.cull);
    static uint8_t color[16 * 16 * 4];
    mote_device dev;
    begin_small_frame(&dev, color, 16);
    for (int k = 0; k < 4; k++) {
        mote_scene_draw_desc(&s, k, NULL, &d);
        TEST_ASSERT_EQUAL(MOTE_OK, mote_draw(&dev, &s.meshes[k], &d));
    }
    TEST_ASSERT_EQUAL(MOTE_OK, mote_end(&dev));
    TEST_ASSERT_EQUAL_UINT32(1, mote_device_stats(&dev)->triangles_backface);
    mote_scene_free(&s);
}

/* Babylon.js culls by a mesh's overrideMaterialSideOrientation (7.x:
 * sideOrientation), else by its material's sideOrientation: 0
 * (ClockWiseSideOrientation) turns a left-handed scene's front faces round
 * (exports of glTF scenes write it on every mesh), as cullBackFaces false
 * does; in a right-handed scene 0 is the default and 1 turns them round.
 * The flipped triangles come from one copy of an index array, shared by
 * the meshes and instances drawing it. */
void loader_should_turn_the_front_faces_round_by_side_orientation(void)
{
    const char *j = "{\"materials\":[{\"id\":\"cw\",\"sideOrientation\":0},"
                    "{\"id\":\"ccw\",\"sideOrientation\":1},{\"id\":\"front\",\"cullBackFaces\":false}],"
                    "\"geometries\":{\"vertexData\":[{\"id\":\"g\"," TRI "}]},"
                    "\"meshes\":[{\"id\":\"a\"," TRI "},"
                    "{\"id\":\"b\",\"overrideMaterialSideOrientation\":0,\"geometryId\":\"g\","
                    "\"instances\":[{\"name\":\"bi\"}]},"
                    "{\"id\":\"c\",\"materialId\":\"cw\"," TRI "},"
                    "{\"id\":\"d\",\"materialId\":\"cw\",\"overrideMaterialSideOrientation\":1," TRI "},"
                    "{\"id\":\"e\",\"materialId\":\"ccw\",\"sideOrientation\":0,\"geometryId\":\"g\"},"
                    "{\"id\":\"f\",\"materialId\":\"cw\",\"overrideMaterialSideOrientation\":null," TRI "},"
                    "{\"id\":\"h\",\"materialId\":\"front\"," TRI "}]}";
    mote_scene s;
    load_json(j, "side", &s);
    TEST_ASSERT_EQUAL_STRING("", s.warning);
    TEST_ASSERT_EQUAL(8, s.mesh_count);
    static const uint32_t front[3] = {0, 1, 2}, round[3] = {0, 2, 1};
    static const bool flipped[8] = {false, true, true, false, true, true, true, true};
    for (int k = 0; k < 8; k++)
        TEST_ASSERT_EQUAL_UINT32_ARRAY(flipped[k] ? round : front, s.meshes[k].indices, 3);
    TEST_ASSERT_EQUAL_PTR(s.meshes[1].indices, s.meshes[4].indices);   /* geometry g, once */
    TEST_ASSERT_EQUAL_PTR(s.meshes[1].indices, s.meshes[7].indices);   /* b's instance */
    /* the camera sees the file's triangles' front: the flipped ones are culled */
    static uint8_t color[16 * 16 * 4];
    mote_device dev;
    begin_small_frame(&dev, color, 16);
    for (int k = 0; k < 8; k++) {
        mote_draw_desc d;
        mote_scene_draw_desc(&s, k, NULL, &d);
        TEST_ASSERT_EQUAL(MOTE_OK, mote_draw(&dev, &s.meshes[k], &d));
    }
    TEST_ASSERT_EQUAL(MOTE_OK, mote_end(&dev));
    TEST_ASSERT_EQUAL_UINT32(6, mote_device_stats(&dev)->triangles_backface);
    mote_scene_free(&s);
    const char *rh = "{\"useRightHandedSystem\":true,\"meshes\":[{\"id\":\"a\"," TRI "},"
                     "{\"id\":\"b\",\"overrideMaterialSideOrientation\":1," TRI "},"
                     "{\"id\":\"c\",\"overrideMaterialSideOrientation\":0," TRI "}]}";
    load_json(rh, "side_rh", &s);
    TEST_ASSERT_EQUAL_UINT32_ARRAY(round, s.meshes[0].indices, 3);   /* mirrored: flipped once */
    TEST_ASSERT_EQUAL_UINT32_ARRAY(front, s.meshes[1].indices, 3);
    TEST_ASSERT_EQUAL_UINT32_ARRAY(round, s.meshes[2].indices, 3);
    mote_scene_free(&s);
    TEST_ASSERT_EQUAL(live_before, mote__io_live_allocations());
}

/* Babylon.js's StandardMaterial adds the emissive colour and ambient x the
 * scene's ambientColor to lights x diffuse, then clamps. disableLighting
 * binds no lights: the material shows clamp(emissive + ambient x the
 * scene's ambient colour), and a PBR material's unlit its albedo; the flag
 * is per mesh, applied by mote_scene_draw_desc. A lit material takes the
 * same sum as its emissive colour, and mote_scene_frame leaves the frame's
 * ambient at 0, so a material without an ambient colour gets none of the
 * scene's (Babylon.js's default ambient colour is black). In a frame
 * without lights each triangle is then exactly that colour. */
void loader_should_add_emissive_and_ambient_colours_as_babylon_does(void)
{
    const char *j = "{\"ambientColor\":[0.5,0.5,0.5],\"materials\":["
                    "{\"id\":\"glow\",\"disableLighting\":true,\"diffuse\":[1,0,0],"
                    "\"emissive\":[0.2,0.4,0.6],\"ambient\":[0.4,0.2,0]},"
                    "{\"id\":\"dark\",\"disableLighting\":1,\"diffuse\":[1,1,1]},"
                    "{\"id\":\"pbr\",\"albedo\":[0,1,0],\"unlit\":true},"
                    "{\"id\":\"lit\",\"diffuse\":[0,0,1],\"emissiveColor\":[1,1,1]},"
                    "{\"id\":\"amb\",\"diffuse\":[1,1,1],\"emissive\":[0.1,0,0],\"ambient\":[0.2,0.4,0]},"
                    "{\"id\":\"plain\",\"diffuse\":[1,0,0]}],"
                    "\"meshes\":[{\"id\":\"a\",\"materialId\":\"glow\"," TRI "},"
                    "{\"id\":\"b\",\"materialId\":\"dark\"," TRI "},"
                    "{\"id\":\"c\",\"materialId\":\"pbr\"," TRI "},"
                    "{\"id\":\"d\",\"materialId\":\"lit\"," TRI "},"
                    "{\"id\":\"e\",\"materialId\":\"amb\"," TRI "},"
                    "{\"id\":\"f\",\"materialId\":\"plain\"," TRI "}]}";
    mote_scene s;
    load_json(j, "u", &s);
    TEST_ASSERT_EQUAL(6, s.mesh_count);
    TEST_ASSERT_EQUAL_STRING("", s.warning);
    static const bool want_unlit[6] = {true, true, true, false, false, false};
    /* unlit: 0.2 + 0.4 x 0.5, 0.4 + 0.2 x 0.5, 0.6: (102, 128, 153);
     * nothing; the albedo. Lit: the diffuse colour, and as emissive
     * white; 0.1 + 0.2 x 0.5, 0.4 x 0.5, 0: (51, 51, 0); none */
    static const uint8_t want_rgb[6][3] = {{102, 128, 153}, {0, 0, 0}, {0, 255, 0},
                                           {0, 0, 255}, {255, 255, 255}, {255, 0, 0}};
    static const uint8_t want_emissive[6][3] = {{0, 0, 0}, {0, 0, 0}, {0, 0, 0},
                                                {255, 255, 255}, {51, 51, 0}, {0, 0, 0}};
    for (int k = 0; k < 6; k++) {
        TEST_ASSERT_EQUAL(want_unlit[k], s.unlit[k]);
        TEST_ASSERT_TRUE(s.meshes[k].material.color_set);
        assert_material_rgb(&s, k, want_rgb[k]);
        const mote_rgba e = s.meshes[k].material.emissive;
        TEST_ASSERT_EQUAL_UINT8(want_emissive[k][0], e.r);
        TEST_ASSERT_EQUAL_UINT8(want_emissive[k][1], e.g);
        TEST_ASSERT_EQUAL_UINT8(want_emissive[k][2], e.b);
        mote_draw_desc d;
        mote_scene_draw_desc(&s, k, NULL, &d);
        TEST_ASSERT_EQUAL(want_unlit[k], d.unlit);
    }
    mote_frame_desc f;
    mote_scene_frame(&s, 1.0f, &f);
    ASSERT_VEC3(0.0f, 0.0f, 0.0f, f.ambient, 0.0f);
    /* a frame without lights: the unlit triangles are their colour, the lit
     * ones their emissive colour, pixel for pixel */
    for (int k = 0; k < 6; k++) {
        static uint8_t color[16 * 16 * 4];
        memset(color, 0, sizeof color);
        mote_device dev;
        begin_small_frame(&dev, color, 16);
        mote_draw_desc d;
        mote_scene_draw_desc(&s, k, NULL, &d);
        TEST_ASSERT_EQUAL(MOTE_OK, mote_draw(&dev, &s.meshes[k], &d));
        TEST_ASSERT_EQUAL(MOTE_OK, mote_end(&dev));
        const uint8_t *want = want_unlit[k] ? want_rgb[k] : want_emissive[k];
        int drawn = 0, coloured = 0;
        for (int p = 0; p < 16 * 16; p++) {
            const uint8_t *px = color + 4 * p;
            if (px[3] == 0)
                continue;
            drawn++;
            coloured += px[0] == want[0] && px[1] == want[1] && px[2] == want[2];
        }
        TEST_ASSERT_GREATER_THAN(4, drawn);
        TEST_ASSERT_EQUAL(drawn, coloured);
    }
    mote_scene_free(&s);
}

/* A texture with coordinatesIndex 1 samples uvs2: the meshes drawn with it
 * get vertices whose uv is uvs2 (current layout, legacy uvCount 2, shared
 * by an instance); a mesh with another material keeps its own uvs; a mesh
 * without uvs2 keeps uvs, with a warning. */
void loader_should_sample_uvs2_for_a_texture_with_coordinates_index_1(void)
{
    mote_scene s;
    TEST_ASSERT_EQUAL_MESSAGE(MOTE_OK,
                              mote_scene_load(MOTE_SOURCE_DIR "/tests/data/bad/texture_uv2.babylon",
                                              NULL, &s, msg, sizeof msg), msg);
    TEST_ASSERT_NOT_NULL(strstr(s.warning, "meshes[3]: its texture samples uvs2"));
    TEST_ASSERT_EQUAL(5, s.mesh_count); /* cur, leg, other, none, cur's instance */
    static const float cur[6] = {0, 0, 1, 0, 0, 1}, leg[6] = {0.25f, 0.75f, 0.5f, 0.5f,
                                                              0.75f, 0.25f};
    for (int v = 0; v < 3; v++) {
        TEST_ASSERT_EQUAL_FLOAT(cur[2 * v], s.meshes[0].vertices[v].uv[0]);
        TEST_ASSERT_EQUAL_FLOAT(cur[2 * v + 1], s.meshes[0].vertices[v].uv[1]);
        TEST_ASSERT_EQUAL_FLOAT(leg[2 * v], s.meshes[1].vertices[v].uv[0]);
        TEST_ASSERT_EQUAL_FLOAT(leg[2 * v + 1], s.meshes[1].vertices[v].uv[1]);
        TEST_ASSERT_EQUAL_FLOAT(0.9f, s.meshes[2].vertices[v].uv[0]);
        TEST_ASSERT_EQUAL_FLOAT(0.5f, s.meshes[3].vertices[v].uv[0]);
    }
    /* positions and normals come along; the instance shares the copy */
    TEST_ASSERT_EQUAL_FLOAT(1.0f, s.meshes[0].vertices[1].position[0]);
    TEST_ASSERT_EQUAL_FLOAT(-1.0f, s.meshes[1].vertices[2].normal[2]);
    TEST_ASSERT_EQUAL_PTR(s.meshes[0].vertices, s.meshes[4].vertices);
    mote_scene_free(&s);
    TEST_ASSERT_EQUAL(live_before, mote__io_live_allocations());
}

/* a parentId that several nodes hold names the last of them, as
 * Babylon.js's getLastEntryById finds it */
void loader_should_attach_a_child_to_the_last_node_of_its_parent_id(void)
{
    const char *j = "{\"meshes\":[{\"id\":\"dup\",\"position\":[-2,0,0]},"
                    "{\"id\":\"child\",\"parentId\":\"dup\"," TRI "},"
                    "{\"id\":\"dup\",\"position\":[2,0,0]}]}";
    mote_scene s;
    load_json(j, "pd", &s);
    TEST_ASSERT_EQUAL(3, s.mesh_count);
    TEST_ASSERT_EQUAL_PTR(&s.meshes[2], s.meshes[1].parent);
    mote_scene_free(&s);
}

void loader_should_use_the_first_camera_without_an_active_one(void)
{
    const char *j = "{\"cameras\":[{\"id\":\"a\",\"position\":[1,2,3],\"target\":[0,0,0]},"
                    "{\"id\":\"b\",\"position\":[9,9,9]}]}";
    mote_scene s;
    load_json(j, "c", &s);
    TEST_ASSERT_TRUE(s.has_camera);
    ASSERT_VEC3(1.0f, 2.0f, 3.0f, s.camera.position, 0.0f);
    /* absent: Babylon.js's Camera defaults */
    TEST_ASSERT_EQUAL_FLOAT(0.8f, s.camera.fov);
    TEST_ASSERT_EQUAL_FLOAT(1.0f, s.camera.znear);
    TEST_ASSERT_EQUAL_FLOAT(10000.0f, s.camera.zfar);
    TEST_ASSERT_EQUAL(0, s.mesh_count);
    mote_scene_free(&s);
}

/* ---- cameras and lights -------------------------------------------------- */

static void load_data(const char *path, mote_scene *s)
{
    TEST_ASSERT_EQUAL_MESSAGE(MOTE_OK, mote_scene_load(path, NULL, s, msg, sizeof msg), msg);
    TEST_ASSERT_EQUAL_STRING("", s->warning);
}

/* Where a mesh's origin lands in the world. */
static void world_origin(const mote_mesh *m, float out[3])
{
    float w[16];
    mote_mesh_world_matrix(m, w);
    memcpy(out, &w[12], 3 * sizeof *out);
}

/* Meshes parented to cameras and lights, by id and by uniqueId: a camera
 * turns its children as its view turns (its target gives yaw and pitch), a
 * light only moves them, a hemispheric light not even that. */
void loader_should_place_children_of_cameras_and_lights(void)
{
    mote_scene s;
    load_data(DATA("camera_light_parents.babylon"), &s);
    /* seven meshes, then hidden nodes for cam, side, p, h and above */
    TEST_ASSERT_EQUAL(12, s.mesh_count);
    for (int i = 7; i < 12; i++) {
        TEST_ASSERT_TRUE(s.meshes[i].hidden);
        TEST_ASSERT_EQUAL_UINT32(0, s.meshes[i].vertex_count);
    }
    TEST_ASSERT_EQUAL_PTR(s.meshes[0].parent, s.meshes[1].parent);
    float p[3];
    world_origin(&s.meshes[0], p);         /* 5 ahead of the camera at z -10 */
    ASSERT_VEC3(0.0f, 0.0f, -5.0f, p, 1e-5f);
    world_origin(&s.meshes[1], p);         /* by uniqueId 42 */
    ASSERT_VEC3(1.0f, 0.0f, -10.0f, p, 1e-5f);
    /* "side" at x 3 looks down -x, from z 0.001: TargetCamera.setTarget
     * moves a camera level with its target so (see
     * loader_should_move_a_camera_level_with_its_target_as_babylon_does) */
    world_origin(&s.meshes[2], p);
    ASSERT_VEC3(1.0f, 0.0f, 0.001f / 3.0f, p, 1e-5f);
    world_origin(&s.meshes[3], p);         /* its right is +z */
    ASSERT_VEC3(3.0f - 0.001f / 3.0f, 0.0f, 1.001f, p, 1e-5f);
    world_origin(&s.meshes[4], p);         /* the point light at y 5 */
    ASSERT_VEC3(1.0f, 5.0f, 0.0f, p, 1e-5f);
    world_origin(&s.meshes[5], p);         /* a hemispheric light: the identity */
    ASSERT_VEC3(0.0f, 2.0f, 0.0f, p, 1e-5f);
    world_origin(&s.meshes[6], p);         /* "above" pitches down a quarter, from z 0.001 */
    ASSERT_VEC3(0.0f, 3.0f, 0.00075f, p, 1e-5f);
    /* the scene's own camera and lights are as before */
    ASSERT_VEC3(0.0f, 0.0f, -10.0f, s.camera.position, 0.0f);
    TEST_ASSERT_EQUAL(2, s.light_count);
    ASSERT_VEC3(0.0f, 5.0f, 0.0f, s.lights[0].position, 0.0f);
    mote_scene_free(&s);
}

/* Equal ids: the last camera wins (scene.getLastEntryById), and a camera
 * comes before a light. */
void loader_should_take_the_last_camera_of_an_id_as_parent(void)
{
    mote_scene s;
    load_data(DATA("camera_parent_duplicate_id.babylon"), &s);
    float p[3];
    world_origin(&s.meshes[0], p);
    ASSERT_VEC3(7.0f, 0.0f, 0.0f, p, 1e-5f);
    mote_scene_free(&s);
}

/* A camera's and a light's parentId: the rig at x 5 turned a quarter to
 * the right carries the camera, the point light and the directional
 * light's direction; the hemispheric light ignores it (as in Babylon.js);
 * disabled lights, or lights under a disabled node, are left out. */
void loader_should_apply_a_parent_to_the_camera_and_lights(void)
{
    mote_scene s;
    load_data(DATA("camera_parent.babylon"), &s);
    ASSERT_VEC3(-5.0f, 0.0f, 0.0f, s.camera.position, 1e-5f);
    ASSERT_VEC3(-4.0f, 0.0f, 0.0f, s.camera.target, 1e-5f);
    ASSERT_VEC3(0.0f, 1.0f, 0.0f, s.camera.up, 1e-6f);
    TEST_ASSERT_TRUE(s.has_lights);
    TEST_ASSERT_EQUAL(3, s.light_count);
    TEST_ASSERT_EQUAL(MOTE_LIGHT_POINT, s.lights[0].type);
    ASSERT_VEC3(6.0f, 0.0f, 0.0f, s.lights[0].position, 1e-5f);
    TEST_ASSERT_EQUAL(MOTE_LIGHT_DIRECTIONAL, s.lights[1].type);
    ASSERT_VEC3(1.0f, 0.0f, 0.0f, s.lights[1].direction, 1e-6f);
    TEST_ASSERT_EQUAL(MOTE_LIGHT_HEMISPHERIC, s.lights[2].type);
    ASSERT_VEC3(0.0f, 1.0f, 0.0f, s.lights[2].direction, 0.0f);
    mote_scene_free(&s);
}

/* lockedTargetId: the camera looks at the node's world position. */
void loader_should_aim_a_camera_at_its_locked_target(void)
{
    mote_scene s;
    load_data(DATA("camera_locked_target.babylon"), &s);
    ASSERT_VEC3(0.0f, 0.0f, -10.0f, s.camera.position, 0.0f);
    ASSERT_VEC3(2.0f, 3.0f, 0.0f, s.camera.target, 1e-6f);
    mote_scene_free(&s);
}

/* rotationQuaternion overrides rotation: a quarter turn left looks down -x. */
void loader_should_turn_a_camera_by_its_quaternion(void)
{
    mote_scene s;
    load_data(DATA("camera_quaternion.babylon"), &s);
    ASSERT_VEC3(10.0f, 0.0f, 0.0f, s.camera.position, 0.0f);
    ASSERT_VEC3(9.0f, 0.0f, 0.0f, s.camera.target, 1e-6f);
    mote_scene_free(&s);
}

/* A camera turned with a z component (a roll in rotation, or a
 * quaternion's z) has its up vector turned with it, as TargetCamera does
 * (_rotateUpVectorWithCameraRotationMatrix): the view is the whole turn.
 * Here a roll of 0.5 about the view axis, either way: up (-sin, cos, 0). */
void loader_should_roll_a_camera_by_its_rotation_z(void)
{
    static const char *const cams[2] = {
        "{\"cameras\":[{\"id\":\"c\",\"position\":[0,0,0],\"rotation\":[0,0,0.5]}]}",
        "{\"cameras\":[{\"id\":\"c\",\"position\":[0,0,0],"
        "\"rotationQuaternion\":[0,0,0.24740395925452294,0.9689124217106447]}]}"};
    for (int k = 0; k < 2; k++) {
        mote_scene s;
        load_json(cams[k], "roll", &s);
        ASSERT_VEC3(0.0f, 0.0f, 1.0f, s.camera.target, 1e-6f);
        ASSERT_VEC3(-0.47942554f, 0.87758256f, 0.0f, s.camera.up, 1e-6f);
        mote_scene_free(&s);
    }
}

/* TargetCamera.setTarget moves a camera level with its target in z by
 * Epsilon (0.001) along z first: one at its target (an old 3ds Max
 * export's "Default camera" at the origin, looking at the origin) then
 * looks down -z, and one right above its target has -z at the top of the
 * image. A right-handed scene moves the file's z, -z here; an
 * ArcRotateCamera is not moved. */
void loader_should_move_a_camera_level_with_its_target_as_babylon_does(void)
{
    static const char *const cams[4] = {
        "{\"cameras\":[{\"id\":\"c\",\"position\":[0,0,0],\"target\":[0,0,0]}]}",
        "{\"cameras\":[{\"id\":\"c\",\"position\":[0,12,0],\"target\":[0,0,0]}]}",
        "{\"useRightHandedSystem\":true,\"cameras\":[{\"id\":\"c\",\"position\":[0,12,0],"
        "\"target\":[0,0,0]}]}",
        "{\"cameras\":[{\"id\":\"c\",\"type\":\"ArcRotateCamera\",\"position\":[0,12,0],"
        "\"target\":[0,0,0]}]}"};
    static const float want_y[4] = {0.0f, 12.0f, 12.0f, 12.0f}, want_z[4] = {1e-3f, 1e-3f, -1e-3f, 0.0f};
    for (int k = 0; k < 4; k++) {
        mote_scene s;
        load_json(cams[k], "level", &s);
        ASSERT_VEC3(0.0f, want_y[k], want_z[k], s.camera.position, 0.0f);
        ASSERT_VEC3(0.0f, 0.0f, 0.0f, s.camera.target, 0.0f);
        mote_scene_free(&s);
    }
    /* the camera at its target sees a point 5 down -z in the middle; the
     * one above its target sees the file's -z up the image */
    mote_scene s;
    load_json(cams[0], "level", &s);
    mote_frame_desc f;
    mote_scene_frame(&s, 1.0f, &f);
    float m[16], clip[4];
    mote_camera_view_matrix(&f.camera, m);
    static const float ahead[3] = {0.0f, 0.0f, -5.0f};
    for (int r = 0; r < 3; r++)
        clip[r] = m[r] * ahead[0] + m[4 + r] * ahead[1] + m[8 + r] * ahead[2] + m[12 + r];
    TEST_ASSERT_FLOAT_WITHIN(1e-5f, 0.0f, clip[0]);
    TEST_ASSERT_FLOAT_WITHIN(1e-5f, 0.0f, clip[1]);
    TEST_ASSERT_TRUE(clip[2] > 4.9f);   /* in front (view z grows forward) */
    mote_scene_free(&s);
    load_json(cams[1], "level", &s);
    mote_scene_frame(&s, 1.0f, &f);
    mote_camera_view_matrix(&f.camera, m);
    static const float north[3] = {0.0f, 0.0f, -5.0f};
    float y = m[1] * north[0] + m[5] * north[1] + m[9] * north[2] + m[13];
    TEST_ASSERT_TRUE(y > 4.9f);         /* up the image */
    mote_scene_free(&s);
}

/* activeCameraID finds a camera by name when it has no id. */
void loader_should_find_the_active_camera_by_name(void)
{
    mote_scene s;
    load_data(DATA("camera_name_only.babylon"), &s);
    ASSERT_VEC3(3.0f, 0.0f, -10.0f, s.camera.position, 0.0f);
    mote_scene_free(&s);
}

/* minZ <= 0 projects as 0.1, maxZ 0 is no far plane (2^24 times the near
 * distance), an absent maxZ is Babylon.js's 10000. */
void loader_should_read_camera_planes_as_babylon_does(void)
{
    mote_scene s;
    load_data(DATA("camera_planes_zero.babylon"), &s);
    TEST_ASSERT_EQUAL_FLOAT(0.1f, s.camera.znear);
    TEST_ASSERT_EQUAL_FLOAT(0.1f * 16777216.0f, s.camera.zfar);
    mote_scene_free(&s);
    load_data(DATA("camera_planes_default.babylon"), &s);
    TEST_ASSERT_EQUAL_FLOAT(0.1f, s.camera.znear);
    TEST_ASSERT_EQUAL_FLOAT(10000.0f, s.camera.zfar);
    mote_scene_free(&s);
}

/* A file whose only light is disabled is lit by nothing: no light, and no
 * stand-in light from mote_scene_frame either. */
void loader_should_leave_out_disabled_lights(void)
{
    mote_scene s;
    load_data(DATA("light_all_disabled.babylon"), &s);
    TEST_ASSERT_EQUAL(0, s.light_count);
    TEST_ASSERT_TRUE(s.has_lights);
    mote_frame_desc f;
    mote_scene_frame(&s, 1.0f, &f);
    TEST_ASSERT_EQUAL(0, f.light_count);
    mote_scene_free(&s);
}

void frame_should_look_at_the_box_from_the_front_top_right_without_a_camera(void)
{
    const char *j = "{\"meshes\":[{\"id\":\"m\",\"positions\":[-1,-1,-1, 1,1,1, 1,-1,1],"
                    "\"indices\":[0,1,2]}]}";
    mote_scene s;
    load_json(j, "f", &s);
    TEST_ASSERT_FALSE(s.has_camera);
    TEST_ASSERT_EQUAL(0, s.light_count);
    mote_frame_desc f;
    mote_scene_frame(&s, 4.0f / 3.0f, &f);
    ASSERT_VEC3(0.0f, 0.0f, 0.0f, f.camera.target, 0.0f);
    const float *p = f.camera.position;
    float dist = sqrtf(p[0] * p[0] + p[1] * p[1] + p[2] * p[2]);
    float radius = sqrtf(3.0f);
    /* from the direction (1, 0.6, -1.4) */
    float dir[3] = {p[0] / dist, p[1] / dist, p[2] / dist};
    ASSERT_VEC3(1.0f / 1.8220867f, 0.6f / 1.8220867f, -1.4f / 1.8220867f, dir, 1e-6f);
    /* the bounding sphere fits the vertical fov: sin(fov/2) >= r / dist */
    TEST_ASSERT_EQUAL_FLOAT(0.8f, f.camera.fov);
    TEST_ASSERT_TRUE(radius / dist <= sinf(0.4f));
    TEST_ASSERT_TRUE(radius / dist > sinf(0.4f) * 0.7f);
    TEST_ASSERT_TRUE(f.camera.znear > 0.0f && f.camera.znear < dist - radius);
    TEST_ASSERT_TRUE(f.camera.zfar > dist + radius);
    /* one point light above the camera */
    TEST_ASSERT_EQUAL(1, f.light_count);
    TEST_ASSERT_EQUAL(MOTE_LIGHT_POINT, f.lights[0].type);
    ASSERT_VEC3(p[0], p[1] + radius, p[2], f.lights[0].position, 1e-5f);
    mote_scene_free(&s);
}

/* ---- levels of detail ---------------------------------------------------- */

/* A base mesh at (1, 2, 3) whose triangle's bounding sphere is centred at
 * (1.5, 2.5, 3), with levels "far" at 20 and "mid" at 10 and a last
 * distance, 30, past which nothing is drawn; the levels stand elsewhere,
 * turned and scaled, in the file. */
#define LOD_SCENE(camera, extra)                                                              \
    "{" camera "\"meshes\":[{\"id\":\"base\",\"position\":[1,2,3],"                          \
    "\"lodMeshIds\":[\"far\",\"mid\"],\"lodDistances\":[20,10,30],\"lodCoverages\":[0.5,0.2]," \
    TRI extra "},"                                                                            \
    "{\"id\":\"mid\",\"position\":[7,7,7],\"rotation\":[0,1,0],\"scaling\":[3,3,3]," TRI "},"  \
    "{\"id\":\"far\",\"position\":[-7,0,0]," TRI "}]}"

/* the scene's camera, 5 from the base's centre */
#define LOD_CAMERA_5 "\"cameras\":[{\"id\":\"c\",\"position\":[1.5,2.5,-2],\"target\":[1.5,2.5,3]}],"

/* camera: at distance d from (1.5, 2.5, 3), looking along +z */
static mote_camera lod_camera(float d)
{
    mote_camera c;
    memset(&c, 0, sizeof c);
    c.position[0] = 1.5f;
    c.position[1] = 2.5f;
    c.position[2] = 3.0f - d;
    c.target[0] = 1.5f;
    c.target[1] = 2.5f;
    c.target[2] = 3.0f;
    return c;
}

/* lod is LOD_SCENE's group of base mesh `base` (one sub-mesh, its bounds
 * its own), its levels: nothing past 30, mesh `far` past 20, mesh `mid`
 * past 10 */
static void assert_lod(const mote_lod *lod, int base, int far, int mid)
{
    TEST_ASSERT_EQUAL(base, lod->first_mesh);
    TEST_ASSERT_EQUAL(1, lod->mesh_count);
    TEST_ASSERT_EQUAL(base, lod->bounds_mesh);
    TEST_ASSERT_EQUAL(3, lod->level_count);
    static const float distance[3] = {30.0f, 20.0f, 10.0f};
    const int first[3] = {0, far, mid}, count[3] = {0, 1, 1};
    for (int k = 0; k < 3; k++) {
        TEST_ASSERT_EQUAL_FLOAT(distance[k], lod->levels[k].distance);
        TEST_ASSERT_EQUAL(count[k], lod->levels[k].mesh_count);
        if (count[k]) {
            TEST_ASSERT_EQUAL(first[k], lod->levels[k].first_mesh);
        }
    }
}

/* which of base (0), mid (1) and far (2) are drawn, as "bmf" letters */
static const char *lod_drawn(const mote_mesh *m)
{
    static char out[4];
    int n = 0;
    for (int i = 0; i < 3; i++)
        if (!m[i].hidden)
            out[n++] = "bmf"[i];
    out[n] = '\0';
    return out;
}

/* Babylon.js's loadDetailLevels makes levels of lodMeshIds at lodDistances
 * (a last distance past the ids a level that draws nothing), sorted
 * farthest first; getLOD draws the base nearer than the last distance,
 * else the first level whose distance is below the camera's, measured to
 * the base's bounding-sphere centre in world space (strictly: at 10 the
 * base is still drawn, at 20 "mid"). The levels are drawn at the base's
 * world matrix, whatever their own transform. The load chooses for the
 * scene's camera, 5 away. */
void lod_should_choose_the_level_by_distance_as_get_lod_does(void)
{
    mote_scene s;
    load_json(LOD_SCENE(LOD_CAMERA_5, ""), "lod", &s);
    TEST_ASSERT_EQUAL_STRING("", s.warning);
    TEST_ASSERT_EQUAL(3, s.mesh_count);
    TEST_ASSERT_EQUAL(1, s.lod_count);
    assert_lod(&s.lods[0], 0, 2, 1);
    TEST_ASSERT_FALSE(s.lods[0].hidden);
    TEST_ASSERT_EQUAL_STRING("b", lod_drawn(s.meshes));
    /* the levels in the base's place: its child, with no transform */
    for (int i = 1; i < 3; i++) {
        float o[3];
        TEST_ASSERT_EQUAL_PTR(&s.meshes[0], s.meshes[i].parent);
        world_origin(&s.meshes[i], o);
        ASSERT_VEC3(1.0f, 2.0f, 3.0f, o, 0.0f);
        TEST_ASSERT_EQUAL_FLOAT(1.0f, s.meshes[i].scaling[0]);
    }
    static const struct {
        float d;
        int level;
        const char *drawn;
    } cases[] = {{5, -1, "b"},  {10, -1, "b"}, {10.5f, 2, "m"}, {20, 2, "m"},
                 {25, 1, "f"}, {30, 1, "f"},  {31, 0, ""}};
    for (size_t k = 0; k < sizeof cases / sizeof cases[0]; k++) {
        mote_camera c = lod_camera(cases[k].d);
        TEST_ASSERT_EQUAL(cases[k].level, mote_scene_lod_level(&s, 0, s.meshes, &c));
        mote_scene_choose_lod(&s, s.meshes, &c);
        TEST_ASSERT_EQUAL_STRING(cases[k].drawn, lod_drawn(s.meshes));
    }
    TEST_ASSERT_EQUAL(-1, mote_scene_lod_level(&s, 1, s.meshes, &s.camera));
    TEST_ASSERT_EQUAL(-1, mote_scene_lod_level(NULL, 0, s.meshes, &s.camera));
    mote_scene_free(&s);
    /* a scene whose camera is 25 away loads drawing "far" */
    load_json(LOD_SCENE("\"cameras\":[{\"id\":\"c\",\"position\":[1.5,2.5,-22],"
                        "\"target\":[1.5,2.5,3]}],", ""), "lod", &s);
    TEST_ASSERT_EQUAL_STRING("f", lod_drawn(s.meshes));
    mote_scene_free(&s);
    /* without a camera: the base, as if it were near; the bounds hold it */
    load_json(LOD_SCENE("", ""), "lod", &s);
    TEST_ASSERT_EQUAL_STRING("b", lod_drawn(s.meshes));
    ASSERT_VEC3(1.0f, 2.0f, 3.0f, s.bounds_min, 0.0f);
    ASSERT_VEC3(2.0f, 3.0f, 3.0f, s.bounds_max, 0.0f);
    mote_scene_free(&s);
}

/* getLOD takes an orthographic camera's distance to be its minZ, wherever
 * it stands. */
void lod_should_measure_an_orthographic_camera_by_its_znear(void)
{
    mote_scene s;
    load_json(LOD_SCENE("\"cameras\":[{\"id\":\"c\",\"mode\":1,\"minZ\":25,\"position\":[1.5,2.5,-2],"
                        "\"target\":[1.5,2.5,3],\"orthoLeft\":-1,\"orthoRight\":1,"
                        "\"orthoBottom\":-1,\"orthoTop\":1}],", ""), "ortho", &s);
    TEST_ASSERT_EQUAL(MOTE_PROJECTION_ORTHOGRAPHIC, s.camera.projection);
    TEST_ASSERT_EQUAL(1, mote_scene_lod_level(&s, 0, s.meshes, &s.camera));
    TEST_ASSERT_EQUAL_STRING("f", lod_drawn(s.meshes));
    mote_camera c = s.camera;
    c.znear = 5.0f;
    mote_scene_choose_lod(&s, s.meshes, &c);
    TEST_ASSERT_EQUAL_STRING("b", lod_drawn(s.meshes));
    mote_scene_free(&s);
}

/* The distance is measured on the meshes given, as mote-render turns its
 * copies of them each frame (--spin): a copy whose base has moved 40 away
 * draws nothing of it, and the scene's own meshes are left alone. */
void lod_should_choose_on_the_meshes_of_the_frame(void)
{
    mote_scene s;
    load_json(LOD_SCENE(LOD_CAMERA_5, ""), "posed", &s);
    mote_mesh posed[3];
    memcpy(posed, s.meshes, sizeof posed);
    for (int i = 0; i < 3; i++)
        if (posed[i].parent)
            posed[i].parent = &posed[posed[i].parent - s.meshes];
    posed[0].position[2] += 40.0f;
    mote_scene_choose_lod(&s, posed, &s.camera);
    TEST_ASSERT_EQUAL_STRING("", lod_drawn(posed));
    TEST_ASSERT_EQUAL_STRING("b", lod_drawn(s.meshes));
    posed[0].position[2] -= 15.0f;   /* 30 away: "far" */
    mote_scene_choose_lod(&s, posed, &s.camera);
    TEST_ASSERT_EQUAL_STRING("f", lod_drawn(posed));
    mote_scene_free(&s);
}

/* An instance of a base chooses its own level, by its own bounding
 * sphere (InstancedMesh.getLOD asks its source's getLOD with it), and the
 * level is drawn in the instance's place: each level has a copy for the
 * instance, sharing its arrays. The instance at (1, 2, 23) is 25 from the
 * camera: its "far" copy is drawn, while the base, 5 away, draws itself. */
void lod_instances_should_choose_their_own_level(void)
{
    mote_scene s;
    load_json(LOD_SCENE(LOD_CAMERA_5,
                        ",\"instances\":[{\"name\":\"i\",\"position\":[1,2,23]}]"), "inst", &s);
    TEST_ASSERT_EQUAL_STRING("", s.warning);
    /* base, mid, far, the instance, the instance's far and mid */
    TEST_ASSERT_EQUAL(6, s.mesh_count);
    TEST_ASSERT_EQUAL(2, s.lod_count);
    assert_lod(&s.lods[1], 3, 4, 5);
    TEST_ASSERT_EQUAL_PTR(s.meshes[2].vertices, s.meshes[4].vertices);
    TEST_ASSERT_EQUAL_PTR(&s.meshes[3], s.meshes[4].parent);
    float o[3];
    world_origin(&s.meshes[4], o);
    ASSERT_VEC3(1.0f, 2.0f, 23.0f, o, 0.0f);
    TEST_ASSERT_EQUAL_STRING("b", lod_drawn(s.meshes));
    TEST_ASSERT_TRUE(s.meshes[3].hidden);
    TEST_ASSERT_FALSE(s.meshes[4].hidden);
    TEST_ASSERT_TRUE(s.meshes[5].hidden);
    mote_scene_free(&s);
}

/* Drawn: a red quad near the camera, its green level past 10, as
 * mote-render draws a frame (each mesh through mote_scene_draw_desc). */
static void lod_render_centre(const mote_scene *s, const mote_camera *camera, uint8_t rgb[3])
{
    enum { N = 32 };
    static uint8_t px[N * N * 4];
    mote_device dev;
    init_color_device(&dev, px, N, N);
    mote_frame_desc f;
    memset(&f, 0, sizeof f);
    f.camera = *camera;
    TEST_ASSERT_EQUAL(MOTE_OK, mote_begin(&dev, &f));
    for (int i = 0; i < s->mesh_count; i++) {
        mote_draw_desc d;
        mote_scene_draw_desc(s, i, NULL, &d);
        TEST_ASSERT_EQUAL(MOTE_OK, mote_draw(&dev, &s->meshes[i], &d));
    }
    TEST_ASSERT_EQUAL(MOTE_OK, mote_end(&dev));
    memcpy(rgb, &px[(N / 2 * N + N / 2) * 4], 3);
}

void lod_should_draw_the_chosen_level_alone(void)
{
    static const char j[] =
        "{\"materials\":[{\"id\":\"red\",\"disableLighting\":true,\"emissive\":[1,0,0],"
        "\"backFaceCulling\":false},{\"id\":\"green\",\"disableLighting\":true,"
        "\"emissive\":[0,1,0],\"backFaceCulling\":false}],"
        "\"meshes\":[{\"id\":\"q\",\"materialId\":\"red\",\"lodMeshIds\":[\"g\"],"
        "\"lodDistances\":[10],\"positions\":[-1,-1,0, 1,-1,0, 1,1,0, -1,1,0],"
        "\"indices\":[0,1,2, 0,2,3]},{\"id\":\"g\",\"materialId\":\"green\",\"position\":[5,0,0],"
        "\"positions\":[-1,-1,0, 1,-1,0, 1,1,0, -1,1,0],\"indices\":[0,1,2, 0,2,3]}]}";
    mote_scene s;
    load_json(j, "draw", &s);
    mote_camera c;
    memset(&c, 0, sizeof c);
    c.position[2] = -5.0f;
    c.zfar = 100.0f;
    uint8_t rgb[3];
    mote_scene_choose_lod(&s, s.meshes, &c);
    lod_render_centre(&s, &c, rgb);
    TEST_ASSERT_EQUAL_UINT8(255, rgb[0]);
    TEST_ASSERT_EQUAL_UINT8(0, rgb[1]);
    c.position[2] = -15.0f;
    mote_scene_choose_lod(&s, s.meshes, &c);
    lod_render_centre(&s, &c, rgb);
    TEST_ASSERT_EQUAL_UINT8(0, rgb[0]);
    TEST_ASSERT_EQUAL_UINT8(255, rgb[1]);
    mote_scene_free(&s);
}

/* Equal distances keep the file's order (a stable sort); a master that is
 * itself a level is blocked, so its own levels are never drawn; a hidden
 * base draws no level. */
void lod_should_sort_levels_as_babylon_does_and_honour_blocked_masters(void)
{
    mote_scene s;
    /* "b" and "c" both at 10: "b", first in lodMeshIds, is chosen past 10 */
    load_json("{\"meshes\":[{\"id\":\"a\",\"lodMeshIds\":[\"b\",\"c\"],\"lodDistances\":[10,10]," TRI "},"
              "{\"id\":\"b\"," TRI "},{\"id\":\"c\"," TRI "}]}", "eq", &s);
    TEST_ASSERT_EQUAL(2, s.lods[0].level_count);
    TEST_ASSERT_EQUAL(1, s.lods[0].levels[0].first_mesh);
    TEST_ASSERT_EQUAL(2, s.lods[0].levels[1].first_mesh);
    mote_camera c;
    memset(&c, 0, sizeof c);
    c.position[2] = -50.0f;
    TEST_ASSERT_EQUAL(0, mote_scene_lod_level(&s, 0, s.meshes, &c));
    mote_scene_free(&s);
    /* "b" (before "a" in the file) has its level "c"; "a" takes "b": one
     * group, of "a", and "c" never drawn */
    load_json("{\"meshes\":[{\"id\":\"b\",\"lodMeshIds\":[\"c\"],\"lodDistances\":[5]," TRI "},"
              "{\"id\":\"a\",\"lodMeshIds\":[\"b\"],\"lodDistances\":[10]," TRI "},"
              "{\"id\":\"c\"," TRI "}]}", "chain", &s);
    TEST_ASSERT_EQUAL(1, s.lod_count);
    TEST_ASSERT_EQUAL(1, s.lods[0].first_mesh);
    TEST_ASSERT_EQUAL(0, s.lods[0].levels[0].first_mesh);
    mote_scene_choose_lod(&s, s.meshes, &c);
    TEST_ASSERT_FALSE(s.meshes[0].hidden);
    TEST_ASSERT_TRUE(s.meshes[1].hidden);
    TEST_ASSERT_TRUE(s.meshes[2].hidden);
    mote_scene_free(&s);
    load_json("{\"meshes\":[{\"id\":\"a\",\"isVisible\":false,\"lodMeshIds\":[\"b\"],"
              "\"lodDistances\":[10]," TRI "},{\"id\":\"b\"," TRI "}]}", "hidden", &s);
    TEST_ASSERT_TRUE(s.lods[0].hidden);
    mote_scene_choose_lod(&s, s.meshes, &c);
    TEST_ASSERT_TRUE(s.meshes[0].hidden);
    TEST_ASSERT_TRUE(s.meshes[1].hidden);
    mote_scene_free(&s);
}

/* What makes no level, as in Babylon.js (which says nothing of the first
 * three), is warned: an id naming no mesh (a transform node is none),
 * null, a mesh that is a level already, fewer distances than ids, and ids
 * without distances (lodCoverages is not read). */
void lod_should_warn_of_levels_babylon_does_not_make(void)
{
    static const struct {
        const char *json, *warning;
    } cases[] = {
        {"{\"transformNodes\":[{\"id\":\"t\"}],\"meshes\":[{\"id\":\"a\",\"lodMeshIds\":[\"t\"],"
         "\"lodDistances\":[5]," TRI "}]}",
         "meshes[0].lodMeshIds[0]: \"t\" names no mesh; Babylon.js adds no level for it"},
        {"{\"meshes\":[{\"id\":\"a\",\"lodMeshIds\":[null],\"lodDistances\":[5]," TRI "}]}",
         "meshes[0].lodMeshIds[0]: null names no mesh; Babylon.js adds no level for it"},
        {"{\"meshes\":[{\"id\":\"a\",\"lodMeshIds\":[\"b\",\"b\"],\"lodDistances\":[5,6]," TRI "},"
         "{\"id\":\"b\"," TRI "}]}",
         "meshes[0].lodMeshIds[1]: \"b\" is a level of detail of meshes[0] already; Babylon.js "
         "takes a mesh as a level once"},
        {"{\"meshes\":[{\"id\":\"a\",\"lodMeshIds\":[\"b\",\"c\"],\"lodDistances\":[5]," TRI "},"
         "{\"id\":\"b\"," TRI "},{\"id\":\"c\"," TRI "}]}",
         "meshes[0]: 1 lodDistances for 2 lodMeshIds: Babylon.js makes no levels of detail of "
         "them (\"Invalid level of detail distances\"), each mesh is drawn by itself"},
        {"{\"meshes\":[{\"id\":\"a\",\"lodMeshIds\":[\"b\"],\"lodCoverages\":[0.5]," TRI "},"
         "{\"id\":\"b\"," TRI "}]}",
         "meshes[0]: lodMeshIds without lodDistances (Babylon.js's loader reads no lodCoverages): "
         "no levels of detail are made, each mesh is drawn by itself, as in Babylon.js"},
    };
    for (size_t k = 0; k < sizeof cases / sizeof cases[0]; k++) {
        mote_scene s;
        load_json(cases[k].json, "w", &s);
        TEST_ASSERT_NOT_NULL_MESSAGE(strstr(s.warning, cases[k].warning), s.warning);
        for (int i = 0; i < s.mesh_count; i++) {
            if (k != 2 || i == 0) {
                TEST_ASSERT_FALSE(s.meshes[i].hidden);
            }
        }
        mote_scene_free(&s);
    }
}

/* ---- textures and images ---------------------------------------------- */

void texture_should_round_trip_a_png_exactly(void)
{
    enum { TW = 7, TH = 5 };
    uint8_t px[TW * TH * 4];
    for (int i = 0; i < TW * TH * 4; i++)
        px[i] = (uint8_t)(i * 37 + 11);
    const char *path = tmp_path("round.png");
    TEST_ASSERT_EQUAL_MESSAGE(MOTE_OK, mote_write_rgba(path, px, TW, TH, 0, msg, sizeof msg), msg);
    mote_texture t;
    TEST_ASSERT_EQUAL_MESSAGE(MOTE_OK, mote_texture_load(path, NULL, &t, msg, sizeof msg), msg);
    TEST_ASSERT_EQUAL(TW, t.width);
    TEST_ASSERT_EQUAL(TH, t.height);
    TEST_ASSERT_EQUAL(MOTE_FORMAT_RGBA8888, t.format);
    TEST_ASSERT_EQUAL(TW * 4, t.stride);
    TEST_ASSERT_EQUAL_UINT8_ARRAY(px, t.pixels, TW * TH * 4);
    mote_texture_free(&t);
    TEST_ASSERT_NULL(t.pixels);
    TEST_ASSERT_EQUAL(live_before, mote__io_live_allocations());
}

void texture_should_refuse_dimensions_over_the_limit_before_decoding(void)
{
    uint8_t px[16 * 4 * 4];
    memset(px, 200, sizeof px);
    const char *path = tmp_path("wide.png");
    TEST_ASSERT_EQUAL(MOTE_OK, mote_write_rgba(path, px, 16, 4, 0, msg, sizeof msg));
    mote_limits lim = mote_limits_default();
    lim.max_texture_width = 8;
    mote_texture t;
    TEST_ASSERT_EQUAL(MOTE_ERR_LIMIT, mote_texture_load(path, &lim, &t, msg, sizeof msg));
    TEST_ASSERT_NOT_NULL(strstr(msg, "16 x 4 is larger than the limit of 8 x 16384"));
    TEST_ASSERT_NULL(t.pixels);
    lim = mote_limits_default();
    lim.max_texture_bytes = 16 * 4 * 4 - 1;
    TEST_ASSERT_EQUAL(MOTE_ERR_LIMIT, mote_texture_load(path, &lim, &t, msg, sizeof msg));
    lim = mote_limits_default();
    lim.max_file_bytes = 10;
    TEST_ASSERT_EQUAL(MOTE_ERR_LIMIT, mote_texture_load(path, &lim, &t, msg, sizeof msg));
    TEST_ASSERT_EQUAL(MOTE_ERR_IO, mote_texture_load(tmp_path("none.png"), NULL, &t, msg,
                                                     sizeof msg));
    TEST_ASSERT_EQUAL(MOTE_ERR_PARSE, mote_texture_load_memory("not an image", 12, NULL, &t,
                                                               msg, sizeof msg));
    TEST_ASSERT_EQUAL(live_before, mote__io_live_allocations());
}

/* The decoders of Debian's stb_image 2.27 that have known faults are not
 * run: a truncated run-length HDR scanline looped for ever in
 * stbi_load_from_memory (CVE-2021-42715), and a 16-bit PGM was read past
 * the end of its buffer (CVE-2021-42716). An 8-bit PPM, as mote writes
 * them, still loads. */
void texture_should_refuse_the_hdr_and_16_bit_pnm_that_stb_mishandles(void)
{
    mote_texture t;
    /* the PNM first: without the check it fails here, not in a loop */
    unsigned char pgm[64] = "P5\n4 4\n65535\n";
    size_t head = strlen((const char *)pgm);
    TEST_ASSERT_EQUAL(MOTE_ERR_UNSUPPORTED,
                      mote_texture_load_memory(pgm, head + 4 * 4 * 2, NULL, &t, msg, sizeof msg));
    TEST_ASSERT_NOT_NULL_MESSAGE(strstr(msg, "16-bit PNM"), msg);
    TEST_ASSERT_NULL(t.pixels);
    static const char hdr[] = "#?RADIANCE\nFORMAT=32-bit_rle_rgbe\n\n-Y 1 +X 8\n\x02\x02\x00\x08";
    TEST_ASSERT_EQUAL(MOTE_ERR_UNSUPPORTED, mote_texture_load_memory(hdr, sizeof hdr - 1, NULL, &t,
                                                                     msg, sizeof msg));
    TEST_ASSERT_NOT_NULL_MESSAGE(strstr(msg, "Radiance HDR"), msg);
    TEST_ASSERT_NULL(t.pixels);
    static const uint8_t px[2 * 4] = {10, 20, 30, 255, 40, 50, 60, 255};
    const char *path = tmp_path("eight.ppm");
    TEST_ASSERT_EQUAL_MESSAGE(MOTE_OK, mote_write_rgba(path, px, 2, 1, 0, msg, sizeof msg), msg);
    TEST_ASSERT_EQUAL_MESSAGE(MOTE_OK, mote_texture_load(path, NULL, &t, msg, sizeof msg), msg);
    TEST_ASSERT_EQUAL(2, t.width);
    TEST_ASSERT_EQUAL_UINT8_ARRAY(px, t.pixels, sizeof px);
    mote_texture_free(&t);
    TEST_ASSERT_EQUAL(live_before, mote__io_live_allocations());
}

void write_ppm_should_write_exact_bytes_from_an_rgba_device(void)
{
    static uint8_t color[3 * 2 * 4];
    static uint32_t depth[3 * 2];
    mote_device dev;
    mote_device_desc d;
    memset(&d, 0, sizeof d);
    d.width = 3;
    d.height = 2;
    d.color = color;
    d.depth = depth;
    TEST_ASSERT_EQUAL(MOTE_OK, mote_device_init(&dev, &d));
    for (int i = 0; i < 3 * 2 * 4; i++)
        color[i] = (uint8_t)(i * 10);
    const char *path = tmp_path("out.ppm");
    TEST_ASSERT_EQUAL_MESSAGE(MOTE_OK, mote_write_ppm(path, &dev, msg, sizeof msg), msg);
    unsigned char got[64];
    long n = read_all(path, got, sizeof got);
    const char header[] = "P6\n3 2\n255\n";
    TEST_ASSERT_EQUAL(11 + 18, n);
    TEST_ASSERT_EQUAL_MEMORY(header, got, 11);
    for (int p = 0; p < 6; p++)
        for (int c = 0; c < 3; c++)
            TEST_ASSERT_EQUAL_UINT8(color[p * 4 + c], got[11 + p * 3 + c]);
    /* by extension, and the same bytes */
    TEST_ASSERT_EQUAL(MOTE_OK, mote_write_image(tmp_path("out2.ppm"), &dev, msg, sizeof msg));
    unsigned char got2[64];
    TEST_ASSERT_EQUAL(n, read_all(tmp_path("out2.ppm"), got2, sizeof got2));
    TEST_ASSERT_EQUAL_MEMORY(got, got2, (size_t)n);
}

void write_png_should_convert_an_rgb565_device_like_read_pixel(void)
{
    static uint16_t color[4 * 3];
    static uint32_t depth[4 * 3];
    mote_device dev;
    mote_device_desc d;
    memset(&d, 0, sizeof d);
    d.width = 4;
    d.height = 3;
    d.color_format = MOTE_FORMAT_RGB565;
    d.color = color;
    d.depth = depth;
    TEST_ASSERT_EQUAL(MOTE_OK, mote_device_init(&dev, &d));
    for (int i = 0; i < 12; i++)
        color[i] = (uint16_t)(i * 5003 + 17);
    const char *path = tmp_path("565.png");
    TEST_ASSERT_EQUAL_MESSAGE(MOTE_OK, mote_write_image(path, &dev, msg, sizeof msg), msg);
    mote_texture t;
    TEST_ASSERT_EQUAL_MESSAGE(MOTE_OK, mote_texture_load(path, NULL, &t, msg, sizeof msg), msg);
    TEST_ASSERT_EQUAL(4, t.width);
    TEST_ASSERT_EQUAL(3, t.height);
    const uint8_t *px = t.pixels;
    for (int y = 0; y < 3; y++)
        for (int x = 0; x < 4; x++) {
            mote_rgba want = mote_read_pixel(&dev, x, y);
            const uint8_t *p = px + y * t.stride + x * 4;
            TEST_ASSERT_EQUAL_UINT8(want.r, p[0]);
            TEST_ASSERT_EQUAL_UINT8(want.g, p[1]);
            TEST_ASSERT_EQUAL_UINT8(want.b, p[2]);
            TEST_ASSERT_EQUAL_UINT8(255, p[3]);
        }
    mote_texture_free(&t);
}

static void ignore_flush(void *user, int y0, int rows, const void *c, int stride)
{
    (void)user, (void)y0, (void)rows, (void)c, (void)stride;
}

void write_image_should_refuse_unknown_extensions_and_band_devices(void)
{
    uint8_t px[4] = {1, 2, 3, 4};
    TEST_ASSERT_EQUAL(MOTE_ERR_UNSUPPORTED, mote_write_rgba(tmp_path("x.jpg"), px, 1, 1, 0, msg,
                                                            sizeof msg));
    TEST_ASSERT_NOT_NULL(strstr(msg, "unknown image type"));
    static uint8_t color[8 * 2 * 4];
    static uint32_t depth[8 * 2];
    mote_device dev;
    mote_device_desc d;
    memset(&d, 0, sizeof d);
    d.width = 8;
    d.height = 8;
    d.band_height = 2;
    d.flush = ignore_flush;
    d.color = color;
    d.depth = depth;
    TEST_ASSERT_EQUAL(MOTE_OK, mote_device_init(&dev, &d));
    TEST_ASSERT_EQUAL(MOTE_ERR_UNSUPPORTED, mote_write_png(tmp_path("band.png"), &dev, msg,
                                                           sizeof msg));
    TEST_ASSERT_NOT_NULL(strstr(msg, "band-mode"));
    TEST_ASSERT_EQUAL(MOTE_ERR_UNSUPPORTED, mote_write_image(tmp_path("x.bmp"), &dev, msg,
                                                             sizeof msg));
    TEST_ASSERT_EQUAL(MOTE_ERR_IO, mote_write_rgba("/nonexistent-dir/x.ppm", px, 1, 1, 0, msg,
                                                   sizeof msg));
}

/* A write that fails half way (a full disk: /dev/full says ENOSPC to every
 * write) is an error for PNG as for PPM: stbi_write_png ignored fwrite's
 * result and said the PNG was written. A size whose rows stb_image_write
 * cannot count in an int is refused before a pixel is read (its buffer
 * size wrapped, and it wrote past the end). */
void write_image_should_report_a_full_disk_and_refuse_what_stb_cannot_encode(void)
{
    uint8_t px[4 * 4 * 4] = {0};
    static const char *const names[2] = {"full.png", "full.ppm"};
    for (int k = 0; k < 2 && file_exists("/dev/full"); k++) {
        const char *link = tmp_path(names[k]);
        TEST_ASSERT_EQUAL(0, symlink("/dev/full", link));
        msg[0] = '\0';
        mote_result r = mote_write_rgba(link, px, 4, 4, 0, msg, sizeof msg);
        unlink(link);
        TEST_ASSERT_EQUAL_MESSAGE(MOTE_ERR_IO, r, names[k]);
        TEST_ASSERT_NOT_NULL_MESSAGE(strstr(msg, "write error"), msg);
    }
    TEST_ASSERT_EQUAL(MOTE_ERR_IO, mote_write_rgba(tmp_path("no-dir/x.png"), px, 4, 4, 0, msg,
                                                   sizeof msg));
    TEST_ASSERT_NOT_NULL(strstr(msg, "cannot create"));
    TEST_ASSERT_EQUAL(MOTE_ERR_LIMIT, mote_write_rgba(tmp_path("huge.png"), px, 16384, 65537, 0,
                                                      msg, sizeof msg));
    TEST_ASSERT_NOT_NULL(strstr(msg, "16384 x 65537 is too large"));
    TEST_ASSERT_FALSE(file_exists(tmp_path("huge.png")));
}

void loader_should_load_a_texture_once_for_two_materials(void)
{
    uint8_t px[2 * 2 * 4] = {255, 0, 0, 255, 0, 255, 0, 255, 0, 0, 255, 255, 9, 9, 9, 255};
    char sub[300];
    snprintf(sub, sizeof sub, "%s/tex", tmpdir);
    mkdir(sub, 0700);
    TEST_ASSERT_EQUAL(MOTE_OK, mote_write_rgba(tmp_path("tex/a.png"), px, 2, 2, 0, msg, sizeof msg));
    const char *j = "{\"materials\":["
                    "{\"id\":\"m1\",\"diffuseTexture\":{\"name\":\"tex/a.png\",\"wrapU\":0,"
                    "\"wrapV\":2,\"uScale\":2,\"vScale\":3,\"uOffset\":0.25,\"vOffset\":0.5}},"
                    "{\"id\":\"m2\",\"albedoTexture\":{\"name\":\"tex\\\\a.png\",\"wrapU\":false}}],"
                    "\"meshes\":[{\"id\":\"a\",\"materialId\":\"m1\",\"positions\":[0,0,0],\"indices\":[]},"
                    "{\"id\":\"b\",\"materialId\":\"m2\"}]}";
    mote_scene s;
    load_json_in(j, "t", tmpdir, &s);
    TEST_ASSERT_EQUAL(1, s.texture_count);
    TEST_ASSERT_EQUAL(2, s.textures[0].width);
    TEST_ASSERT_EQUAL_PTR(&s.textures[0], s.meshes[0].material.texture);
    TEST_ASSERT_EQUAL_PTR(&s.textures[0], s.meshes[1].material.texture);
    TEST_ASSERT_EQUAL(MOTE_WRAP_CLAMP, s.meshes[0].material.wrap_u);
    TEST_ASSERT_EQUAL(MOTE_WRAP_MIRROR, s.meshes[0].material.wrap_v);
    TEST_ASSERT_EQUAL_FLOAT(2.0f, s.meshes[0].material.u_scale);
    TEST_ASSERT_EQUAL_FLOAT(3.0f, s.meshes[0].material.v_scale);
    TEST_ASSERT_EQUAL_FLOAT(0.25f, s.meshes[0].material.u_offset);
    TEST_ASSERT_EQUAL_FLOAT(0.5f, s.meshes[0].material.v_offset);
    TEST_ASSERT_EQUAL(MOTE_WRAP_CLAMP, s.meshes[1].material.wrap_u);
    TEST_ASSERT_EQUAL(MOTE_WRAP_REPEAT, s.meshes[1].material.wrap_v);
    TEST_ASSERT_EQUAL_UINT8_ARRAY(px, s.textures[0].pixels, sizeof px);
    /* a mesh without vertex data is a 0-vertex mesh */
    TEST_ASSERT_EQUAL_UINT32(0, s.meshes[1].vertex_count);
    mote_scene_free(&s);
    TEST_ASSERT_EQUAL(live_before, mote__io_live_allocations());
}

#define ASSERT_RGBA(R, G, B, A, c)           \
    do {                                     \
        TEST_ASSERT_EQUAL_UINT8(R, (c).r);   \
        TEST_ASSERT_EQUAL_UINT8(G, (c).g);   \
        TEST_ASSERT_EQUAL_UINT8(B, (c).b);   \
        TEST_ASSERT_EQUAL_UINT8(A, (c).a);   \
    } while (0)

void loader_should_read_vertex_colors_of_4_or_3_floats_inline_and_from_vertex_data(void)
{
    mote_scene s;
    TEST_ASSERT_EQUAL_MESSAGE(MOTE_OK, mote_scene_load(VERTEX_COLORS, NULL, &s, msg, sizeof msg), msg);
    TEST_ASSERT_EQUAL_STRING("", s.warning);
    TEST_ASSERT_EQUAL(5, s.mesh_count); /* rgba's two sub-meshes, rgb, shared, plain */
    const mote_mesh *sub0 = &s.meshes[0], *sub1 = &s.meshes[1], *rgb = &s.meshes[2];
    const mote_mesh *shared = &s.meshes[3], *plain = &s.meshes[4];
    /* 16 floats for 4 vertices: r, g, b, a each */
    TEST_ASSERT_NOT_NULL(sub0->colors);
    ASSERT_RGBA(255, 0, 0, 255, sub0->colors[0]);
    ASSERT_RGBA(0, 255, 0, 128, sub0->colors[1]);
    ASSERT_RGBA(0, 0, 255, 0, sub0->colors[2]);
    ASSERT_RGBA(51, 102, 153, 255, sub0->colors[3]);
    /* sub-meshes share the vertices, and their colours with them */
    TEST_ASSERT_EQUAL_PTR(sub0->vertices, sub1->vertices);
    TEST_ASSERT_EQUAL_PTR(sub0->colors, sub1->colors);
    /* 9 floats for 3 vertices: r, g, b, alpha 1; rounded to nearest and clamped */
    TEST_ASSERT_NOT_NULL(rgb->colors);
    ASSERT_RGBA(128, 64, 255, 255, rgb->colors[0]);
    ASSERT_RGBA(255, 0, 1, 255, rgb->colors[1]);
    ASSERT_RGBA(255, 0, 128, 255, rgb->colors[2]);
    /* geometryId: the colours of geometries.vertexData[0] */
    TEST_ASSERT_EQUAL_UINT32(3, shared->vertex_count);
    TEST_ASSERT_NOT_NULL(shared->colors);
    ASSERT_RGBA(255, 0, 0, 255, shared->colors[0]);
    ASSERT_RGBA(0, 255, 0, 255, shared->colors[1]);
    ASSERT_RGBA(0, 0, 255, 255, shared->colors[2]);
    /* no colors: NULL, which draws as before */
    TEST_ASSERT_NULL(plain->colors);
    mote_scene_free(&s);
    TEST_ASSERT_EQUAL(live_before, mote__io_live_allocations());
}

/* ---- geometry without indices ------------------------------------------- */

/* Babylon.js draws an isUnIndexed mesh with drawArrays: vertices 0,1,2 /
 * 3,4,5 / ... are its triangles, any indices ignored, a partial last
 * triangle dropped; a sub-mesh draws its vertex range. */
void loader_should_draw_unindexed_meshes_as_consecutive_triangles(void)
{
    mote_scene s;
    load_json("{\"meshes\":[{\"id\":\"u\",\"isUnIndexed\":true,\"indices\":[0,0,0],"
              "\"positions\":[0,0,0, 1,0,0, 0,1,0, 0,0,1, 1,0,1, 0,1,1, 5,5,5]}]}",
              "u", &s);
    TEST_ASSERT_EQUAL(1, s.mesh_count);
    const mote_mesh *m = &s.meshes[0];
    TEST_ASSERT_EQUAL_UINT32(7, m->vertex_count);
    TEST_ASSERT_EQUAL_UINT32(6, m->index_count);
    for (uint32_t i = 0; i < m->index_count; i++)
        TEST_ASSERT_EQUAL_UINT32(i, m->indices[i]);
    TEST_ASSERT_EQUAL_STRING("meshes[0]: isUnIndexed, but 7 vertices is not a multiple of 3; "
                             "the last 1 are not drawn", s.warning);
    /* smooth normals come from those triangles: the first faces -z */
    TEST_ASSERT_FLOAT_WITHIN(1e-6f, 1.0f, fabsf(m->vertices[0].normal[2]));
    mote_scene_free(&s);
    load_json("{\"meshes\":[{\"id\":\"u\",\"isUnIndexed\":true,"
              "\"positions\":[0,0,0, 1,0,0, 0,1,0, 0,0,1, 1,0,1, 0,1,1],"
              "\"subMeshes\":[{\"materialIndex\":0,\"verticesStart\":0,\"verticesCount\":3,"
              "\"indexStart\":0,\"indexCount\":3},{\"materialIndex\":0,\"verticesStart\":3,"
              "\"verticesCount\":3,\"indexStart\":3,\"indexCount\":3}]}]}", "u", &s);
    TEST_ASSERT_EQUAL_STRING("", s.warning);
    TEST_ASSERT_EQUAL(2, s.mesh_count);
    TEST_ASSERT_EQUAL_UINT32(3, s.meshes[1].index_count);
    TEST_ASSERT_EQUAL_UINT32(3, s.meshes[1].indices[0]);
    TEST_ASSERT_EQUAL_UINT32(5, s.meshes[1].indices[2]);
    mote_scene_free(&s);
    /* one geometry drawn unindexed by one mesh and by its indices by
     * another: read once each way, and each way shared by the meshes that
     * follow (a copy per mesh let a small file that names a big geometry
     * many times, alternating, take gigabytes) */
    load_json("{\"geometries\":{\"vertexData\":[{\"id\":\"g\",\"indices\":[2,1,0],"
              "\"positions\":[0,0,0, 1,0,0, 0,1,0, 0,0,1, 1,0,1, 0,1,1]}]},"
              "\"meshes\":[{\"id\":\"a\",\"geometryId\":\"g\",\"isUnIndexed\":true},"
              "{\"id\":\"b\",\"geometryId\":\"g\"},"
              "{\"id\":\"c\",\"geometryId\":\"g\",\"isUnIndexed\":true},"
              "{\"id\":\"d\",\"geometryId\":\"g\"}]}", "g", &s);
    TEST_ASSERT_EQUAL(4, s.mesh_count);
    TEST_ASSERT_EQUAL_UINT32(6, s.meshes[0].index_count);
    TEST_ASSERT_EQUAL_UINT32(3, s.meshes[1].index_count);
    TEST_ASSERT_EQUAL_UINT32(2, s.meshes[1].indices[0]);
    TEST_ASSERT_EQUAL_PTR(s.meshes[0].indices, s.meshes[2].indices);
    TEST_ASSERT_EQUAL_PTR(s.meshes[0].vertices, s.meshes[2].vertices);
    TEST_ASSERT_EQUAL_PTR(s.meshes[1].indices, s.meshes[3].indices);
    TEST_ASSERT_EQUAL_PTR(s.meshes[1].vertices, s.meshes[3].vertices);
    mote_scene_free(&s);
    TEST_ASSERT_EQUAL(live_before, mote__io_live_allocations());
}

/* Positions without indices (nor isUnIndexed) draw nothing: said, not silent. */
void loader_should_warn_about_positions_without_indices(void)
{
    mote_scene s;
    load_json("{\"meshes\":[{\"id\":\"p\",\"positions\":[0,0,0, 1,0,0, 0,1,0]}]}", "p", &s);
    TEST_ASSERT_EQUAL_UINT32(3, s.meshes[0].vertex_count);
    TEST_ASSERT_EQUAL_UINT32(0, s.meshes[0].index_count);
    TEST_ASSERT_EQUAL_STRING("meshes[0]: has positions but no indices (and no isUnIndexed): it "
                             "draws no triangles", s.warning);
    mote_scene_free(&s);
    /* empty arrays are an empty mesh, not a forgotten key */
    load_json("{\"meshes\":[{\"id\":\"p\",\"positions\":[]}]}", "p", &s);
    TEST_ASSERT_EQUAL_STRING("", s.warning);
    mote_scene_free(&s);
}

/* A parentId naming nothing (a partial export, "export selected"): as in
 * Babylon.js the node loads without a parent and keeps its own transform,
 * whether it is a mesh, the camera or a light; the file loads, warned. */
void loader_should_load_a_node_whose_parent_is_missing_without_a_parent(void)
{
    const char *j = "{\"meshes\":[{\"id\":\"m\",\"parentId\":\"gone\",\"position\":[1,2,3]," TRI "}],"
                    "\"cameras\":[{\"id\":\"c\",\"parentId\":\"gone\",\"position\":[0,0,-5],"
                    "\"target\":[0,0,0]}],"
                    "\"lights\":[{\"id\":\"l\",\"type\":0,\"parentId\":\"gone\","
                    "\"position\":[7,8,9]}]}";
    mote_scene s;
    load_json(j, "pm", &s);
    TEST_ASSERT_NULL(s.meshes[0].parent);
    float o[3];
    world_origin(&s.meshes[0], o);
    ASSERT_VEC3(1.0f, 2.0f, 3.0f, o, 0.0f);
    ASSERT_VEC3(0.0f, 0.0f, -5.0f, s.camera.position, 0.0f);
    ASSERT_VEC3(0.0f, 0.0f, 0.0f, s.camera.target, 0.0f);
    TEST_ASSERT_EQUAL(1, s.light_count);
    ASSERT_VEC3(7.0f, 8.0f, 9.0f, s.lights[0].position, 0.0f);
    TEST_ASSERT_NOT_NULL_MESSAGE(strstr(s.warning, "meshes[0].parentId: \"gone\" names no node; "
                                        "loaded without a parent"), s.warning);
    TEST_ASSERT_NOT_NULL_MESSAGE(strstr(s.warning, "cameras[0].parentId: \"gone\""), s.warning);
    TEST_ASSERT_NOT_NULL_MESSAGE(strstr(s.warning, "lights[0].parentId: \"gone\""), s.warning);
    mote_scene_free(&s);
    /* "" names nothing (Cinema 4D's exporter writes it for no parent, old
     * 3ds Max ones for no material or target), as Babylon.js looks nothing
     * up for it: no warning */
    load_json("{\"meshes\":[{\"id\":\"m\",\"parentId\":\"\",\"materialId\":\"\","
              "\"position\":[1,2,3]," TRI "}],"
              "\"cameras\":[{\"id\":\"c\",\"parentId\":\"\",\"lockedTargetId\":\"\","
              "\"position\":[0,0,-5]}],"
              "\"lights\":[{\"id\":\"l\",\"type\":0,\"parentId\":\"\",\"position\":[7,8,9]}]}",
              "pm", &s);
    TEST_ASSERT_EQUAL_STRING("", s.warning);
    TEST_ASSERT_EQUAL(1, s.mesh_count);
    TEST_ASSERT_NULL(s.meshes[0].parent);
    world_origin(&s.meshes[0], o);
    ASSERT_VEC3(1.0f, 2.0f, 3.0f, o, 0.0f);
    ASSERT_VEC3(7.0f, 8.0f, 9.0f, s.lights[0].position, 0.0f);
    mote_scene_free(&s);
    /* a numeric parentId is a uniqueId */
    load_json("{\"meshes\":[{\"id\":\"n\",\"parentId\":77,\"position\":[4,5,6]}]}", "pm", &s);
    TEST_ASSERT_NULL(s.meshes[0].parent);
    TEST_ASSERT_EQUAL_STRING("meshes[0].parentId: 77 is the uniqueId of no node; loaded without "
                             "a parent", s.warning);
    mote_scene_free(&s);
    TEST_ASSERT_EQUAL(live_before, mote__io_live_allocations());
}

/* A texture name written as a URL: when no file has the name as written,
 * the file named by it decoded, without its "?query", is loaded (once).
 * Invalid escapes and %00 are not decoded, and a decoded name is held to
 * the scene's folder as any other. */
void loader_should_read_a_url_encoded_texture_name_as_the_decoded_file(void)
{
    uint8_t px[4] = {1, 2, 3, 255};
    char sub[300];
    snprintf(sub, sizeof sub, "%s/my dir", tmpdir);
    mkdir(sub, 0700);
    TEST_ASSERT_EQUAL(MOTE_OK, mote_write_rgba(tmp_path("my dir/a b.png"), px, 1, 1, 0, msg,
                                               sizeof msg));
    const char *j = "{\"materials\":["
                    "{\"id\":\"m1\",\"diffuseTexture\":{\"name\":\"my%20dir/a%20b.png?v=2\"}},"
                    "{\"id\":\"m2\",\"diffuseTexture\":{\"name\":\"my dir/a b.png?x\"}},"
                    "{\"id\":\"m3\",\"diffuseTexture\":{\"name\":\"my dir/a b.png\"}}],"
                    "\"meshes\":[{\"id\":\"a\",\"materialId\":\"m1\"},"
                    "{\"id\":\"b\",\"materialId\":\"m2\"},{\"id\":\"c\",\"materialId\":\"m3\"}]}";
    mote_scene s;
    load_json_in(j, "u", tmpdir, &s);
    TEST_ASSERT_EQUAL(1, s.texture_count);
    for (int k = 0; k < 3; k++)
        TEST_ASSERT_EQUAL_PTR(&s.textures[0], s.meshes[k].material.texture);
    TEST_ASSERT_EQUAL_UINT8_ARRAY(px, s.textures[0].pixels, sizeof px);
    mote_scene_free(&s);
    /* not decoded, from the folder "my dir" (files "a b.png" in it and
     * above it): %00, a decoded name leaving the folder, invalid escapes */
    TEST_ASSERT_EQUAL(MOTE_OK, mote_write_rgba(tmp_path("a b.png"), px, 1, 1, 0, msg,
                                               sizeof msg));
    static const char *const refused[] = {"a%20b.png%00", "%2e%2e/a%20b.png", "a%2gb.png",
                                          "a%20b.png%"};
    for (size_t k = 0; k < sizeof refused / sizeof refused[0]; k++) {
        char scene[256];
        snprintf(scene, sizeof scene, "{\"materials\":[{\"id\":\"m\",\"diffuseTexture\":"
                 "{\"name\":\"%s\"}}]}", refused[k]);
        TEST_ASSERT_EQUAL_MESSAGE(MOTE_ERR_IO, mote_scene_load_memory(scene, strlen(scene), "u",
                                                                      sub, NULL, &s, msg,
                                                                      sizeof msg), refused[k]);
        TEST_ASSERT_NOT_NULL_MESSAGE(strstr(msg, "cannot open"), msg);
        TEST_ASSERT_NOT_NULL_MESSAGE(strstr(msg, refused[k]), msg);
    }
    TEST_ASSERT_EQUAL(live_before, mote__io_live_allocations());
}

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
    load_json(j, "w", &s);
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
    load_json(j, "w", &s);
    TEST_ASSERT_EQUAL_PTR(s.warning, strstr(s.warning, "meshes[0].materialId: \"x0\" names no "
                                                       "material; "));
    TEST_ASSERT_NOT_NULL_MESSAGE(strstr(s.warning, "meshes[4].materialId: \"x4\" names no "
                                        "material; 15 more warnings"), s.warning);
    mote_scene_free(&s);
}

/* A path naming a FIFO, a directory or a device is refused before it is
 * opened: fopen on a FIFO waits for a writer, and /dev/zero would be read
 * up to the size limit. */
void file_reading_should_refuse_a_fifo_a_directory_and_a_device(void)
{
#if defined(__unix__) || defined(__APPLE__)
    char fifo[512];
    snprintf(fifo, sizeof fifo, "%s", tmp_path("fifo.png"));
    TEST_ASSERT_EQUAL_MESSAGE(0, mkfifo(fifo, 0600), fifo);
    alarm(30);                    /* before the check, the open never returned */
    mote_texture t;
    TEST_ASSERT_EQUAL(MOTE_ERR_IO, mote_texture_load(fifo, NULL, &t, msg, sizeof msg));
    TEST_ASSERT_NOT_NULL_MESSAGE(strstr(msg, "fifo.png: cannot open: a FIFO, not a regular file"),
                                 msg);
    mote_scene s;
    TEST_ASSERT_EQUAL(MOTE_ERR_IO, mote_scene_load(fifo, NULL, &s, msg, sizeof msg));
    const char *j = "{\"materials\":[{\"id\":\"m\",\"diffuseTexture\":{\"name\":\"fifo.png\"}}]}";
    TEST_ASSERT_EQUAL(MOTE_ERR_IO, mote_scene_load_memory(j, strlen(j), "f", tmpdir, NULL, &s,
                                                          msg, sizeof msg));
    TEST_ASSERT_NOT_NULL_MESSAGE(strstr(msg, "f: materials[0].diffuseTexture.name: "), msg);
    TEST_ASSERT_NOT_NULL_MESSAGE(strstr(msg, "a FIFO, not a regular file"), msg);
    alarm(0);
    TEST_ASSERT_EQUAL(MOTE_ERR_IO, mote_texture_load(tmpdir, NULL, &t, msg, sizeof msg));
    TEST_ASSERT_NOT_NULL_MESSAGE(strstr(msg, "a directory, not a regular file"), msg);
    TEST_ASSERT_EQUAL(MOTE_ERR_IO, mote_texture_load("/dev/null", NULL, &t, msg, sizeof msg));
    TEST_ASSERT_EQUAL_STRING("/dev/null: cannot open: a device, not a regular file", msg);
    TEST_ASSERT_EQUAL(live_before, mote__io_live_allocations());
#else
    TEST_IGNORE_MESSAGE("no FIFOs or devices to test with here");
#endif
}

/* fovMode 1 (Babylon.js's FOVMODE_HORIZONTAL_FIXED): fov spans the width,
 * so the vertical field follows the aspect ratio. */
void loader_should_read_fov_mode_1_as_a_horizontal_field_of_view(void)
{
    mote_scene s;
    load_json("{\"cameras\":[{\"id\":\"c\",\"position\":[0,0,0],\"target\":[0,0,1],"
              "\"fov\":1.5707963267948966,\"fovMode\":1,\"minZ\":0.1,\"maxZ\":10}]}", "h", &s);
    TEST_ASSERT_TRUE(s.camera_fov_is_horizontal);
    /* 90 degrees across a 200 x 100 frame: x = z reaches the right edge,
     * y = z / 2 the top (the vertical field is 2 atan(1/2)) */
    static uint8_t color[200 * 100 * 4];
    mote_device dev;
    init_color_device(&dev, color, 200, 100);
    mote_frame_desc f;
    mote_scene_frame(&s, 2.0f, &f);
    TEST_ASSERT_EQUAL(MOTE_OK, mote_begin(&dev, &f));
    float x, y, z;
    const float right[3] = {1, 0, 1}, top[3] = {0, 0.5f, 1};
    TEST_ASSERT_TRUE(mote_project(&dev, right, &x, &y, &z));
    TEST_ASSERT_FLOAT_WITHIN(1e-3f, 200.0f, x);
    TEST_ASSERT_FLOAT_WITHIN(1e-3f, 50.0f, y);
    TEST_ASSERT_TRUE(mote_project(&dev, top, &x, &y, &z));
    TEST_ASSERT_FLOAT_WITHIN(1e-3f, 100.0f, x);
    TEST_ASSERT_FLOAT_WITHIN(1e-3f, 0.0f, y);
    TEST_ASSERT_EQUAL(MOTE_OK, mote_end(&dev));
    mote_scene_free(&s);
    /* fovMode 0, or none: vertical, as before */
    load_json("{\"cameras\":[{\"id\":\"c\",\"fovMode\":0}]}", "h", &s);
    TEST_ASSERT_FALSE(s.camera_fov_is_horizontal);
    mote_scene_free(&s);
}

/* An orthographic camera (mode 1): its box as written, right-handed files
 * too (the mirror in z leaves x and y alone), minZ as given, 0 or
 * negative, and no fov needed. A box missing an edge (or null), which
 * Babylon.js sizes by the canvas in pixels, is the core's default with a
 * warning; an empty one is an error. */
void loader_should_read_orthographic_cameras(void)
{
    const char *j = "{\"useRightHandedSystem\":true,"
                    "\"cameras\":[{\"id\":\"c\",\"mode\":1,\"position\":[0,0,-10],\"target\":[0,0,0],"
                    "\"fov\":0,\"minZ\":-2.5,\"maxZ\":40,\"orthoLeft\":-4,\"orthoRight\":6,"
                    "\"orthoBottom\":-1.5,\"orthoTop\":3}],"
                    "\"meshes\":[{\"id\":\"a\",\"pivotMatrix\":[1,0,0,0, 0,1,0,0, 0,0,1,0, 2,0,0,1]}]}";
    mote_scene s;
    load_json(j, "x", &s);
    TEST_ASSERT_EQUAL_STRING("", s.warning);   /* pivots and right-handed files are read too */
    TEST_ASSERT_EQUAL(MOTE_PROJECTION_ORTHOGRAPHIC, s.camera.projection);
    TEST_ASSERT_EQUAL_FLOAT(-4.0f, s.camera.ortho[0]);
    TEST_ASSERT_EQUAL_FLOAT(6.0f, s.camera.ortho[1]);
    TEST_ASSERT_EQUAL_FLOAT(-1.5f, s.camera.ortho[2]);
    TEST_ASSERT_EQUAL_FLOAT(3.0f, s.camera.ortho[3]);
    TEST_ASSERT_EQUAL_FLOAT(-2.5f, s.camera.znear);
    TEST_ASSERT_EQUAL_FLOAT(40.0f, s.camera.zfar);
    mote_scene_free(&s);
    load_json("{\"cameras\":[{\"id\":\"c\",\"mode\":1,\"minZ\":0,\"orthoLeft\":-4,"
              "\"orthoRight\":4,\"orthoBottom\":null,\"orthoTop\":3}]}", "x", &s);
    TEST_ASSERT_EQUAL_STRING("cameras[0]: an orthographic camera without all of orthoLeft, orthoRight, "
                             "orthoBottom and orthoTop (Babylon.js sizes it by the canvas, in pixels) is "
                             "drawn 2 units high", s.warning);
    TEST_ASSERT_EQUAL(MOTE_PROJECTION_ORTHOGRAPHIC, s.camera.projection);
    for (int k = 0; k < 4; k++)
        TEST_ASSERT_EQUAL_FLOAT(0.0f, s.camera.ortho[k]);
    TEST_ASSERT_EQUAL_FLOAT(0.0f, s.camera.znear);
    mote_scene_free(&s);
    /* mode 0, or none: perspective, minZ 0 as 0.1 */
    load_json("{\"cameras\":[{\"id\":\"c\",\"mode\":0,\"minZ\":0,\"orthoLeft\":-4}]}", "x", &s);
    TEST_ASSERT_EQUAL_STRING("", s.warning);
    TEST_ASSERT_EQUAL(MOTE_PROJECTION_PERSPECTIVE, s.camera.projection);
    TEST_ASSERT_EQUAL_FLOAT(0.1f, s.camera.znear);
    mote_scene_free(&s);
    const char *empty = "{\"cameras\":[{\"id\":\"c\",\"mode\":1,\"orthoLeft\":2,\"orthoRight\":2,"
                        "\"orthoBottom\":-1,\"orthoTop\":1}]}";
    TEST_ASSERT_EQUAL(MOTE_ERR_RANGE, mote_scene_load_memory(empty, strlen(empty), "e", NULL, NULL, &s, msg,
                                                             sizeof msg));
    TEST_ASSERT_EQUAL_STRING("e: cameras[0]: orthoLeft 2, orthoRight 2, orthoBottom -1 and orthoTop 1 "
                             "enclose nothing", msg);
    const char *flat = "{\"cameras\":[{\"id\":\"c\",\"mode\":1,\"minZ\":5,\"maxZ\":0}]}";
    TEST_ASSERT_EQUAL(MOTE_ERR_RANGE, mote_scene_load_memory(flat, strlen(flat), "f", NULL, NULL, &s, msg,
                                                             sizeof msg));
    TEST_ASSERT_EQUAL_STRING("f: cameras[0]: minZ 5 and maxZ 0 need minZ < maxZ", msg);
}

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
    load_json(j, "dup", &s);
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

int main(void)
{
    snprintf(tmpdir, sizeof tmpdir, "/tmp/mote-test-io-XXXXXX");
    if (!mkdtemp(tmpdir)) {
        perror("mkdtemp");
        return 1;
    }
    UNITY_BEGIN();
    RUN_TEST(loader_should_read_the_tutorial_monkey);
    RUN_TEST(loader_should_keep_the_monkeys_first_vertex_exactly);
    RUN_TEST(loader_should_read_the_current_layout_with_exact_fields);
    RUN_TEST(loader_should_read_light_ranges_and_spot_cones);
    RUN_TEST(loader_should_give_transform_nodes_a_mesh_to_be_parents);
    RUN_TEST(loader_should_resolve_a_numeric_parent_id_by_unique_id);
    RUN_TEST(loader_should_attach_a_child_to_the_instance_its_parent_index_names);
    RUN_TEST(loader_should_attach_a_child_to_the_last_node_of_its_parent_id);
    RUN_TEST(loader_should_hide_invisible_and_disabled_meshes);
    RUN_TEST(loader_should_take_the_texture_row_of_v0_from_invert_y);
    RUN_TEST(loader_should_keep_explicit_zeros_of_scale_and_light);
    RUN_TEST(loader_should_share_a_geometry_between_the_meshes_naming_it);
    RUN_TEST(loader_should_draw_a_mesh_again_for_each_of_its_instances);
    RUN_TEST(loader_should_use_the_first_camera_without_an_active_one);
    RUN_TEST(loader_should_place_children_of_cameras_and_lights);
    RUN_TEST(loader_should_take_the_last_camera_of_an_id_as_parent);
    RUN_TEST(loader_should_apply_a_parent_to_the_camera_and_lights);
    RUN_TEST(loader_should_aim_a_camera_at_its_locked_target);
    RUN_TEST(loader_should_turn_a_camera_by_its_quaternion);
    RUN_TEST(loader_should_roll_a_camera_by_its_rotation_z);
    RUN_TEST(loader_should_move_a_camera_level_with_its_target_as_babylon_does);
    RUN_TEST(loader_should_find_the_active_camera_by_name);
    RUN_TEST(loader_should_read_camera_planes_as_babylon_does);
    RUN_TEST(loader_should_leave_out_disabled_lights);
    RUN_TEST(frame_should_look_at_the_box_from_the_front_top_right_without_a_camera);
    RUN_TEST(texture_should_round_trip_a_png_exactly);
    RUN_TEST(texture_should_refuse_dimensions_over_the_limit_before_decoding);
    RUN_TEST(texture_should_refuse_the_hdr_and_16_bit_pnm_that_stb_mishandles);
    RUN_TEST(write_ppm_should_write_exact_bytes_from_an_rgba_device);
    RUN_TEST(write_png_should_convert_an_rgb565_device_like_read_pixel);
    RUN_TEST(write_image_should_refuse_unknown_extensions_and_band_devices);
    RUN_TEST(write_image_should_report_a_full_disk_and_refuse_what_stb_cannot_encode);
    RUN_TEST(loader_should_load_a_texture_once_for_two_materials);
    RUN_TEST(loader_should_read_vertex_colors_of_4_or_3_floats_inline_and_from_vertex_data);
    RUN_TEST(loader_should_resolve_material_unique_id_before_material_id);
    RUN_TEST(loader_should_resolve_multi_material_slots_by_unique_id);
    RUN_TEST(loader_should_warn_of_a_material_type_it_does_not_read);
    RUN_TEST(loader_should_read_the_base_colour_and_texture_of_a_metallic_roughness_material);
    RUN_TEST(loader_should_make_no_texture_of_one_without_a_name);
    RUN_TEST(loader_should_decode_textures_embedded_as_base64_data_urls);
    RUN_TEST(loader_should_draw_both_sides_when_back_face_culling_is_false);
    RUN_TEST(loader_should_turn_the_front_faces_round_by_side_orientation);
    RUN_TEST(loader_should_add_emissive_and_ambient_colours_as_babylon_does);
    RUN_TEST(loader_should_sample_uvs2_for_a_texture_with_coordinates_index_1);
    RUN_TEST(loader_should_draw_unindexed_meshes_as_consecutive_triangles);
    RUN_TEST(loader_should_warn_about_positions_without_indices);
    RUN_TEST(loader_should_load_a_node_whose_parent_is_missing_without_a_parent);
    RUN_TEST(loader_should_read_a_url_encoded_texture_name_as_the_decoded_file);
    RUN_TEST(loader_should_show_each_distinct_warning_once_with_its_count);
    RUN_TEST(file_reading_should_refuse_a_fifo_a_directory_and_a_device);
    RUN_TEST(loader_should_read_fov_mode_1_as_a_horizontal_field_of_view);
    RUN_TEST(loader_should_read_orthographic_cameras);
    RUN_TEST(loader_should_take_the_last_of_keys_written_twice);
    RUN_TEST(lod_should_choose_the_level_by_distance_as_get_lod_does);
    RUN_TEST(lod_should_measure_an_orthographic_camera_by_its_znear);
    RUN_TEST(lod_should_choose_on_the_meshes_of_the_frame);
    RUN_TEST(lod_instances_should_choose_their_own_level);
    RUN_TEST(lod_should_draw_the_chosen_level_alone);
    RUN_TEST(lod_should_sort_levels_as_babylon_does_and_honour_blocked_masters);
    RUN_TEST(lod_should_warn_of_levels_babylon_does_not_make);
    char cmd[300];
    snprintf(cmd, sizeof cmd, "rm -rf '%s'", tmpdir);
    if (system(cmd) != 0)
        fprintf(stderr, "could not remove %s\n", tmpdir);
    return UNITY_END();
}
