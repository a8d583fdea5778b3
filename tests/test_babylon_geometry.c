/*
 * test_babylon_geometry.c - a .babylon mesh's geometry (src/io/babylon_geometry.c): the
 * tutorial's monkey.babylon (legacy layout), a current-layout scene
 * written here, shared geometries, vertex colours, unindexed meshes.
 */
#include "support/io_test.h"

#define MONKEY MOTE_SOURCE_DIR "/../shared/assets/monkey.babylon"
#define VERTEX_COLORS MOTE_SOURCE_DIR "/tests/data/vertex_colors.babylon"

static char msg[512];
static long live_before;

void setUp(void)
{
    msg[0] = '\0';
    live_before = io_test_begin();
}

void tearDown(void) {}

void loader_should_read_the_tutorial_monkey(void)
{
    if (!io_file_exists(MONKEY))
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
    if (!io_file_exists(MONKEY))
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
    io_load_json(j, "g", &s);
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

/* Babylon.js draws an isUnIndexed mesh with drawArrays: vertices 0,1,2 /
 * 3,4,5 / ... are its triangles, any indices ignored, a partial last
 * triangle dropped; a sub-mesh draws its vertex range. */
void loader_should_draw_unindexed_meshes_as_consecutive_triangles(void)
{
    mote_scene s;
    io_load_json("{\"meshes\":[{\"id\":\"u\",\"isUnIndexed\":true,\"indices\":[0,0,0],"
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
    io_load_json("{\"meshes\":[{\"id\":\"u\",\"isUnIndexed\":true,"
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
    io_load_json("{\"geometries\":{\"vertexData\":[{\"id\":\"g\",\"indices\":[2,1,0],"
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
    io_load_json("{\"meshes\":[{\"id\":\"p\",\"positions\":[0,0,0, 1,0,0, 0,1,0]}]}", "p", &s);
    TEST_ASSERT_EQUAL_UINT32(3, s.meshes[0].vertex_count);
    TEST_ASSERT_EQUAL_UINT32(0, s.meshes[0].index_count);
    TEST_ASSERT_EQUAL_STRING("meshes[0]: has positions but no indices (and no isUnIndexed): it "
                             "draws no triangles", s.warning);
    mote_scene_free(&s);
    /* empty arrays are an empty mesh, not a forgotten key */
    io_load_json("{\"meshes\":[{\"id\":\"p\",\"positions\":[]}]}", "p", &s);
    TEST_ASSERT_EQUAL_STRING("", s.warning);
    mote_scene_free(&s);
}

int main(void)
{
    UNITY_BEGIN();
    RUN_TEST(loader_should_read_the_tutorial_monkey);
    RUN_TEST(loader_should_keep_the_monkeys_first_vertex_exactly);
    RUN_TEST(loader_should_read_the_current_layout_with_exact_fields);
    RUN_TEST(loader_should_share_a_geometry_between_the_meshes_naming_it);
    RUN_TEST(loader_should_read_vertex_colors_of_4_or_3_floats_inline_and_from_vertex_data);
    RUN_TEST(loader_should_draw_unindexed_meshes_as_consecutive_triangles);
    RUN_TEST(loader_should_warn_about_positions_without_indices);
    return UNITY_END();
}
