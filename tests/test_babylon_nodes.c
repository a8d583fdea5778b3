/*
 * test_babylon_nodes.c - a .babylon file's nodes (src/io/babylon_node.c): transform
 * nodes, parents by id and uniqueId, instances, visibility, explicit
 * zeros.
 */
#include "support/io_test.h"

static char msg[512];
static long live_before;

void setUp(void)
{
    msg[0] = '\0';
    live_before = io_test_begin();
}

void tearDown(void) {}

void loader_should_give_transform_nodes_a_mesh_to_be_parents(void)
{
    const char *j = "{\"meshes\":[{\"id\":\"m\",\"parentId\":\"t\","
                    "\"positions\":[0,0,0, 1,0,0, 0,1,0],\"indices\":[0,1,2]}],"
                    "\"transformNodes\":[{\"id\":\"t\",\"position\":[10,0,0],"
                    "\"parentId\":\"e\"},{\"id\":\"e\",\"scaling\":[1,3,1]}]}";
    mote_scene s;
    io_load_json(j, "t", &s);
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
    io_load_json(j, "u", &s);
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
    io_load_json(j, "h", &s);
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
    io_begin_small_frame(&dev, color, 8);
    TEST_ASSERT_EQUAL(MOTE_OK, mote_draw(&dev, &s.meshes[2], NULL));
    TEST_ASSERT_EQUAL(MOTE_OK, mote_end(&dev));
    TEST_ASSERT_EQUAL_UINT32(0, mote_device_stats(&dev)->draws);
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
    io_load_json(j, "z", &s);
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
    io_load_json(j, "i", &s);
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
    io_load_json(j, "pi", &s);
    TEST_ASSERT_EQUAL(5, s.mesh_count);   /* src, on-i1, on-src, i0, i1 */
    ASSERT_VEC3(-5.0f, 0.0f, 0.0f, s.meshes[4].position, 0.0f);
    TEST_ASSERT_EQUAL_PTR(&s.meshes[4], s.meshes[1].parent);
    TEST_ASSERT_EQUAL_PTR(&s.meshes[0], s.meshes[2].parent);
    mote_scene_free(&s);
}

/* a parentId that several nodes hold names the last of them, as
 * Babylon.js's getLastEntryById finds it */
void loader_should_attach_a_child_to_the_last_node_of_its_parent_id(void)
{
    const char *j = "{\"meshes\":[{\"id\":\"dup\",\"position\":[-2,0,0]},"
                    "{\"id\":\"child\",\"parentId\":\"dup\"," TRI "},"
                    "{\"id\":\"dup\",\"position\":[2,0,0]}]}";
    mote_scene s;
    io_load_json(j, "pd", &s);
    TEST_ASSERT_EQUAL(3, s.mesh_count);
    TEST_ASSERT_EQUAL_PTR(&s.meshes[2], s.meshes[1].parent);
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
    io_load_json(j, "pm", &s);
    TEST_ASSERT_NULL(s.meshes[0].parent);
    float o[3];
    io_world_origin(&s.meshes[0], o);
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
    io_load_json("{\"meshes\":[{\"id\":\"m\",\"parentId\":\"\",\"materialId\":\"\","
              "\"position\":[1,2,3]," TRI "}],"
              "\"cameras\":[{\"id\":\"c\",\"parentId\":\"\",\"lockedTargetId\":\"\","
              "\"position\":[0,0,-5]}],"
              "\"lights\":[{\"id\":\"l\",\"type\":0,\"parentId\":\"\",\"position\":[7,8,9]}]}",
              "pm", &s);
    TEST_ASSERT_EQUAL_STRING("", s.warning);
    TEST_ASSERT_EQUAL(1, s.mesh_count);
    TEST_ASSERT_NULL(s.meshes[0].parent);
    io_world_origin(&s.meshes[0], o);
    ASSERT_VEC3(1.0f, 2.0f, 3.0f, o, 0.0f);
    ASSERT_VEC3(7.0f, 8.0f, 9.0f, s.lights[0].position, 0.0f);
    mote_scene_free(&s);
    /* a numeric parentId is a uniqueId */
    io_load_json("{\"meshes\":[{\"id\":\"n\",\"parentId\":77,\"position\":[4,5,6]}]}", "pm", &s);
    TEST_ASSERT_NULL(s.meshes[0].parent);
    TEST_ASSERT_EQUAL_STRING("meshes[0].parentId: 77 is the uniqueId of no node; loaded without "
                             "a parent", s.warning);
    mote_scene_free(&s);
    TEST_ASSERT_EQUAL(live_before, mote__io_live_allocations());
}

int main(void)
{
    UNITY_BEGIN();
    RUN_TEST(loader_should_give_transform_nodes_a_mesh_to_be_parents);
    RUN_TEST(loader_should_resolve_a_numeric_parent_id_by_unique_id);
    RUN_TEST(loader_should_attach_a_child_to_the_instance_its_parent_index_names);
    RUN_TEST(loader_should_attach_a_child_to_the_last_node_of_its_parent_id);
    RUN_TEST(loader_should_hide_invisible_and_disabled_meshes);
    RUN_TEST(loader_should_keep_explicit_zeros_of_scale_and_light);
    RUN_TEST(loader_should_draw_a_mesh_again_for_each_of_its_instances);
    RUN_TEST(loader_should_load_a_node_whose_parent_is_missing_without_a_parent);
    return UNITY_END();
}
