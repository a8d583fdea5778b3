/*
 * test_babylon_lod.c - levels of detail (src/io/babylon_lod.c and
 * mote_scene_choose_lod in src/io/scene.c), as Babylon.js makes and
 * chooses them.
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
    io_load_json(LOD_SCENE(LOD_CAMERA_5, ""), "lod", &s);
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
        io_world_origin(&s.meshes[i], o);
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
    io_load_json(LOD_SCENE("\"cameras\":[{\"id\":\"c\",\"position\":[1.5,2.5,-22],"
                        "\"target\":[1.5,2.5,3]}],", ""), "lod", &s);
    TEST_ASSERT_EQUAL_STRING("f", lod_drawn(s.meshes));
    mote_scene_free(&s);
    /* without a camera: the base, as if it were near; the bounds hold it */
    io_load_json(LOD_SCENE("", ""), "lod", &s);
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
    io_load_json(LOD_SCENE("\"cameras\":[{\"id\":\"c\",\"mode\":1,\"minZ\":25,\"position\":[1.5,2.5,-2],"
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
    io_load_json(LOD_SCENE(LOD_CAMERA_5, ""), "posed", &s);
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
    io_load_json(LOD_SCENE(LOD_CAMERA_5,
                        ",\"instances\":[{\"name\":\"i\",\"position\":[1,2,23]}]"), "inst", &s);
    TEST_ASSERT_EQUAL_STRING("", s.warning);
    /* base, mid, far, the instance, the instance's far and mid */
    TEST_ASSERT_EQUAL(6, s.mesh_count);
    TEST_ASSERT_EQUAL(2, s.lod_count);
    assert_lod(&s.lods[1], 3, 4, 5);
    TEST_ASSERT_EQUAL_PTR(s.meshes[2].vertices, s.meshes[4].vertices);
    TEST_ASSERT_EQUAL_PTR(&s.meshes[3], s.meshes[4].parent);
    float o[3];
    io_world_origin(&s.meshes[4], o);
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
    io_init_color_device(&dev, px, N, N);
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
    io_load_json(j, "draw", &s);
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
    io_load_json("{\"meshes\":[{\"id\":\"a\",\"lodMeshIds\":[\"b\",\"c\"],\"lodDistances\":[10,10]," TRI "},"
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
    io_load_json("{\"meshes\":[{\"id\":\"b\",\"lodMeshIds\":[\"c\"],\"lodDistances\":[5]," TRI "},"
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
    io_load_json("{\"meshes\":[{\"id\":\"a\",\"isVisible\":false,\"lodMeshIds\":[\"b\"],"
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
        io_load_json(cases[k].json, "w", &s);
        TEST_ASSERT_NOT_NULL_MESSAGE(strstr(s.warning, cases[k].warning), s.warning);
        for (int i = 0; i < s.mesh_count; i++) {
            if (k != 2 || i == 0) {
                TEST_ASSERT_FALSE(s.meshes[i].hidden);
            }
        }
        mote_scene_free(&s);
    }
}

int main(void)
{
    UNITY_BEGIN();
    RUN_TEST(lod_should_choose_the_level_by_distance_as_get_lod_does);
    RUN_TEST(lod_should_measure_an_orthographic_camera_by_its_znear);
    RUN_TEST(lod_should_choose_on_the_meshes_of_the_frame);
    RUN_TEST(lod_instances_should_choose_their_own_level);
    RUN_TEST(lod_should_draw_the_chosen_level_alone);
    RUN_TEST(lod_should_sort_levels_as_babylon_does_and_honour_blocked_masters);
    RUN_TEST(lod_should_warn_of_levels_babylon_does_not_make);
    return UNITY_END();
}
