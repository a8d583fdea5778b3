/*
 * test_loader_transforms.c - how the .babylon loader places things, where
 * Babylon.js's rules are more than position, rotation and scaling: a
 * right-handed scene (useRightHandedSystem), loaded mirrored in z so that
 * mote's left-handed core draws what Babylon.js draws.
 */
#include <mote/mote.h>
#include <mote/mote_io.h>
#include "io/io_internal.h"
#include "unity.h"

#include <string.h>

#define W 96
#define H 72

static char msg[512];
static long live_before;
static uint8_t color[W * H * 4];
static uint32_t depth[W * H];

void setUp(void)
{
    msg[0] = '\0';
    live_before = mote__io_live_allocations();
}

void tearDown(void)
{
    TEST_ASSERT_EQUAL(live_before, mote__io_live_allocations());
}

static void load_json(const char *json, mote_scene *s)
{
    TEST_ASSERT_EQUAL_MESSAGE(MOTE_OK, mote_scene_load_memory(json, strlen(json), "t", NULL, NULL,
                                                              s, msg, sizeof msg), msg);
}

/* Draws the scene as mote-render does (its own camera and lights, each
 * mesh with mote_scene_draw_desc, Gouraud; unlit: the material's colour,
 * for where things land whichever way they face) into color; returns the
 * frame's statistics. */
static mote_stats render(const mote_scene *s, bool unlit)
{
    mote_device dev;
    mote_device_desc dd;
    memset(&dd, 0, sizeof dd);
    dd.width = W;
    dd.height = H;
    dd.color = color;
    dd.depth = depth;
    TEST_ASSERT_EQUAL(MOTE_OK, mote_device_init(&dev, &dd));
    mote_frame_desc frame;
    mote_scene_frame(s, (float)W / (float)H, &frame);
    TEST_ASSERT_EQUAL(MOTE_OK, mote_begin(&dev, &frame));
    mote_draw_desc base = {0}, d;
    base.mode = MOTE_MODE_GOURAUD;
    base.unlit = unlit;
    for (int i = 0; i < s->mesh_count; i++) {
        mote_scene_draw_desc(s, i, &base, &d);
        TEST_ASSERT_EQUAL(MOTE_OK, mote_draw(&dev, &s->meshes[i], &d));
    }
    TEST_ASSERT_EQUAL(MOTE_OK, mote_end(&dev));
    return *mote_device_stats(&dev);
}

/* The columns holding pixels other than black (the clear colour): *lo..*hi,
 * or -1, -1 for none; returns how many such pixels there are. */
static int drawn_columns(int *lo, int *hi)
{
    int n = 0;
    *lo = *hi = -1;
    for (int y = 0; y < H; y++)
        for (int x = 0; x < W; x++) {
            const uint8_t *p = &color[(y * W + x) * 4];
            if (p[0] == 0 && p[1] == 0 && p[2] == 0)
                continue;
            n++;
            if (*lo < 0 || x < *lo) *lo = x;
            if (x > *hi) *hi = x;
        }
    return n;
}

/* Loads json and draws it unlit (render); returns drawn_columns' count,
 * with the frame's statistics in *stats (NULL: not wanted). */
static int draw_unlit(const char *json, int *lo, int *hi, mote_stats *stats)
{
    mote_scene s;
    load_json(json, &s);
    mote_stats st = render(&s, true);
    if (stats)
        *stats = st;
    mote_scene_free(&s);
    return drawn_columns(lo, hi);
}

/* ---- useRightHandedSystem ---------------------------------------------- */

/* A right-handed scene: a transform node turning the camera (a child of
 * it, aimed by a target), a point and a directional light, a tetrahedron
 * with normals, turned by Euler angles and scaled, with an instance turned
 * by a quaternion, and a child pyramid without normals (smooth normals are
 * made) in the current layout, and a floor in the legacy one. */
static const char rh_scene[] =
    "{\"useRightHandedSystem\":true,"
    "\"materials\":[{\"id\":\"red\",\"diffuse\":[1,0.2,0.2]},{\"id\":\"green\",\"diffuse\":[0.2,1,0.2]}],"
    "\"transformNodes\":[{\"id\":\"rig\",\"position\":[0.5,1,3],\"rotation\":[0.1,0.2,0.05]}],"
    "\"cameras\":[{\"id\":\"cam\",\"parentId\":\"rig\",\"position\":[0.3,1,6],\"target\":[0.2,0.1,-3],"
    "\"fov\":0.9,\"minZ\":0.5,\"maxZ\":100}],\"activeCameraID\":\"cam\","
    "\"lights\":[{\"type\":0,\"id\":\"p\",\"position\":[3,4,5],\"intensity\":0.8},"
    "{\"type\":1,\"id\":\"d\",\"direction\":[-0.3,-1,-0.5],\"intensity\":0.5}],"
    "\"meshes\":["
    "{\"id\":\"box\",\"materialId\":\"red\",\"position\":[1,0.2,-1],\"rotation\":[0.3,0.7,0.2],"
    "\"scaling\":[1,1.5,1],"
    "\"positions\":[1,1,1, 1,-1,-1, -1,1,-1, -1,-1,1],"
    "\"normals\":[0.577,0.577,0.577, 0.577,-0.577,-0.577, -0.577,0.577,-0.577, -0.577,-0.577,0.577],"
    "\"indices\":[0,1,2, 0,3,1, 0,2,3, 1,3,2],"
    "\"instances\":[{\"name\":\"i\",\"position\":[-2,0.5,-2],\"rotationQuaternion\":[0.1,0.3,0.2,0.927]}]},"
    "{\"id\":\"kid\",\"materialId\":\"green\",\"parentId\":\"box\",\"position\":[0.1,1.2,0.5],"
    "\"rotationQuaternion\":[0.2,0.1,0.3,0.927],"
    "\"positions\":[0.1,0.8,0.1, -0.5,0,-0.5, 0.5,0,-0.5, 0.5,0,0.5, -0.5,0,0.5],"
    "\"indices\":[0,1,2, 0,2,3, 0,3,4, 0,4,1, 1,3,2, 1,4,3]},"
    "{\"id\":\"floor\",\"uvCount\":0,\"indices\":[0,1,2, 0,2,3],"
    "\"vertices\":[-3,-1.5,-3, 0,1,0, 3,-1.5,-3, 0,1,0, 3,-1.5,3, 0,1,0, -3,-1.5,3, 0,1,0]}]}";

/* The same scene mirrored by hand into a left-handed one: every z of a
 * position, target, direction and normal negated, Euler angles (rx, ry, rz)
 * written (-rx, -ry, rz), quaternions (x, y, z, w) written (-x, -y, z, w),
 * and each triangle's last two corners swapped. */
static const char lh_mirror[] =
    "{\"materials\":[{\"id\":\"red\",\"diffuse\":[1,0.2,0.2]},{\"id\":\"green\",\"diffuse\":[0.2,1,0.2]}],"
    "\"transformNodes\":[{\"id\":\"rig\",\"position\":[0.5,1,-3],\"rotation\":[-0.1,-0.2,0.05]}],"
    "\"cameras\":[{\"id\":\"cam\",\"parentId\":\"rig\",\"position\":[0.3,1,-6],\"target\":[0.2,0.1,3],"
    "\"fov\":0.9,\"minZ\":0.5,\"maxZ\":100}],\"activeCameraID\":\"cam\","
    "\"lights\":[{\"type\":0,\"id\":\"p\",\"position\":[3,4,-5],\"intensity\":0.8},"
    "{\"type\":1,\"id\":\"d\",\"direction\":[-0.3,-1,0.5],\"intensity\":0.5}],"
    "\"meshes\":["
    "{\"id\":\"box\",\"materialId\":\"red\",\"position\":[1,0.2,1],\"rotation\":[-0.3,-0.7,0.2],"
    "\"scaling\":[1,1.5,1],"
    "\"positions\":[1,1,-1, 1,-1,1, -1,1,1, -1,-1,-1],"
    "\"normals\":[0.577,0.577,-0.577, 0.577,-0.577,0.577, -0.577,0.577,0.577, -0.577,-0.577,-0.577],"
    "\"indices\":[0,2,1, 0,1,3, 0,3,2, 1,2,3],"
    "\"instances\":[{\"name\":\"i\",\"position\":[-2,0.5,2],\"rotationQuaternion\":[-0.1,-0.3,0.2,0.927]}]},"
    "{\"id\":\"kid\",\"materialId\":\"green\",\"parentId\":\"box\",\"position\":[0.1,1.2,-0.5],"
    "\"rotationQuaternion\":[-0.2,-0.1,0.3,0.927],"
    "\"positions\":[0.1,0.8,-0.1, -0.5,0,0.5, 0.5,0,0.5, 0.5,0,-0.5, -0.5,0,-0.5],"
    "\"indices\":[0,2,1, 0,3,2, 0,4,3, 0,1,4, 1,2,3, 1,3,4]},"
    "{\"id\":\"floor\",\"uvCount\":0,\"indices\":[0,2,1, 0,3,2],"
    "\"vertices\":[-3,-1.5,3, 0,1,0, 3,-1.5,3, 0,1,0, 3,-1.5,-3, 0,1,0, -3,-1.5,-3, 0,1,0]}]}";

/* The right-handed scene loads as its mirror, vertex for vertex and
 * triangle for triangle, and draws the same bytes: the mirror is the
 * image Babylon.js draws (see mote__mirror_point: P_LH V_LH(S e, S t, S u)
 * = P_RH V_RH(e, t, u) S). */
void right_handed_scene_should_draw_as_its_left_handed_mirror(void)
{
    mote_scene rh, lh;
    load_json(rh_scene, &rh);
    load_json(lh_mirror, &lh);
    TEST_ASSERT_EQUAL_STRING("", rh.warning);
    TEST_ASSERT_TRUE(rh.mirrored_z);
    TEST_ASSERT_FALSE(lh.mirrored_z);
    TEST_ASSERT_EQUAL(lh.mesh_count, rh.mesh_count);
    for (int i = 0; i < rh.mesh_count; i++) {
        const mote_mesh *a = &rh.meshes[i], *b = &lh.meshes[i];
        TEST_ASSERT_EQUAL_UINT32(b->vertex_count, a->vertex_count);
        TEST_ASSERT_EQUAL_UINT32(b->index_count, a->index_count);
        if (a->vertex_count)
            TEST_ASSERT_EQUAL_MEMORY(b->vertices, a->vertices, a->vertex_count * sizeof *a->vertices);
        if (a->index_count)
            TEST_ASSERT_EQUAL_MEMORY(b->indices, a->indices, a->index_count * sizeof *a->indices);
        TEST_ASSERT_EQUAL_MEMORY(b->position, a->position, sizeof a->position);
        TEST_ASSERT_EQUAL_MEMORY(b->rotation, a->rotation, sizeof a->rotation);
        TEST_ASSERT_EQUAL_MEMORY(b->rotation_quaternion, a->rotation_quaternion,
                                 sizeof a->rotation_quaternion);
    }
    TEST_ASSERT_EQUAL_MEMORY(&lh.camera, &rh.camera, sizeof rh.camera);
    TEST_ASSERT_EQUAL_MEMORY(lh.lights, rh.lights, sizeof rh.lights);
    static uint8_t mirror_image[W * H * 4];
    mote_stats st = render(&lh, false);
    memcpy(mirror_image, color, sizeof color);
    TEST_ASSERT_TRUE(st.triangles_drawn >= 6);
    int lo, hi;
    TEST_ASSERT_TRUE(drawn_columns(&lo, &hi) > 500);
    render(&rh, false);
    TEST_ASSERT_EQUAL_MEMORY(mirror_image, color, sizeof color);
    mote_scene_free(&rh);
    mote_scene_free(&lh);
}

/* A quad about (2, 0, 0), both sides drawn, seen by a camera at (0, 0, 10)
 * looking at the origin. Babylon.js's LookAtRH makes the view's z axis
 * eye - target = +z and its x axis up x z = (0, 1, 0) x (0, 0, 1) =
 * (1, 0, 0), which PerspectiveFovRH keeps pointing right on screen: the
 * quad is in the right half of the image. (Drawn left-handed as written,
 * LookAtLH's x axis is up x (target - eye) = (-1, 0, 0): the left half.) */
#define QUAD_AT_PLUS_X                                                            \
    "\"materials\":[{\"id\":\"both\",\"backFaceCulling\":false}],"                \
    "\"meshes\":[{\"id\":\"q\",\"materialId\":\"both\",\"position\":[2,0,0],"     \
    "\"positions\":[-1,-1,0, 1,-1,0, 1,1,0, -1,1,0],\"indices\":[0,1,2, 0,2,3]}]"

void right_handed_scene_should_put_plus_x_where_babylon_does(void)
{
    static const char *const looking_at_origin[] = {
        /* aimed by a target */
        "{\"useRightHandedSystem\":true,\"cameras\":[{\"id\":\"c\",\"position\":[0,0,10],"
        "\"target\":[0,0,0]}]," QUAD_AT_PLUS_X "}",
        /* turned by no rotation: a right-handed TargetCamera looks down -z */
        "{\"useRightHandedSystem\":true,\"cameras\":[{\"id\":\"c\",\"position\":[0,0,10],"
        "\"rotation\":[0,0,0]}]," QUAD_AT_PLUS_X "}",
    };
    int lo, hi;
    for (int k = 0; k < 2; k++) {
        TEST_ASSERT_TRUE(draw_unlit(looking_at_origin[k], &lo, &hi, NULL) > 20);
        TEST_ASSERT_TRUE_MESSAGE(lo >= W / 2, looking_at_origin[k]);
    }
    /* Without a rotation a right-handed TargetCamera starts turned half
     * about y (looking down +z, as before Babylon.js's cameras looked down
     * -z there): from (0, 0, -10) it sees the origin, and LookAtRH's x axis
     * is now (0, 1, 0) x (0, 0, -1) = (-1, 0, 0): the quad is on the left. */
    TEST_ASSERT_TRUE(draw_unlit("{\"useRightHandedSystem\":true,\"cameras\":[{\"id\":\"c\","
                                "\"position\":[0,0,-10]}]," QUAD_AT_PLUS_X "}", &lo, &hi, NULL) > 20);
    TEST_ASSERT_TRUE(hi < W / 2);
}

/* Back-face culling on (the default material): a mesh of a right-handed
 * scene gets sideOrientation ClockWise in Babylon.js (Mesh's constructor;
 * CounterClockWise in a left-handed one), and the renderer sets
 * gl.frontFace(CW) for it (engine.setState's reverseSide): the front faces
 * are those clockwise as the camera sees them. From (0, 0, 10), x right and
 * y up, the left quad's triangles run clockwise, the right one's counter-
 * clockwise: only the left one is drawn. */
void right_handed_scene_should_keep_its_front_faces_front(void)
{
    int lo, hi;
    mote_stats st;
    TEST_ASSERT_TRUE(draw_unlit("{\"useRightHandedSystem\":true,\"cameras\":[{\"id\":\"c\","
                                "\"position\":[0,0,10],\"target\":[0,0,0]}],\"meshes\":["
                                "{\"id\":\"cw\",\"position\":[-2,0,0],"
                                "\"positions\":[-1,-1,0, 1,-1,0, 1,1,0, -1,1,0],\"indices\":[0,2,1, 0,3,2]},"
                                "{\"id\":\"ccw\",\"position\":[2,0,0],"
                                "\"positions\":[-1,-1,0, 1,-1,0, 1,1,0, -1,1,0],\"indices\":[0,1,2, 0,2,3]}]}",
                                &lo, &hi, &st) > 20);
    TEST_ASSERT_EQUAL_UINT32(2, st.triangles_backface);
    TEST_ASSERT_TRUE(hi < W / 2);
}

/* An unindexed mesh's triangles are flipped too, also those of a sub-mesh
 * starting inside one of the whole mesh's triangles (vertex 1: its own
 * indices, as the shared ones are flipped in threes from vertex 0). */
void right_handed_scene_should_flip_unindexed_triangles_of_every_sub_mesh(void)
{
    mote_scene s;
    load_json("{\"useRightHandedSystem\":true,\"meshes\":[{\"id\":\"u\",\"isUnIndexed\":true,"
              "\"positions\":[0,0,0, 1,0,0, 0,1,0, 1,1,0, 2,0,0, 2,1,0, 3,0,0],"
              "\"subMeshes\":[{\"materialIndex\":0,\"verticesStart\":0,\"verticesCount\":6},"
              "{\"materialIndex\":0,\"verticesStart\":1,\"verticesCount\":6}]},"
              "{\"id\":\"whole\",\"isUnIndexed\":true,\"positions\":[0,0,0, 1,0,0, 0,1,0, 1,1,0]}]}",
              &s);
    TEST_ASSERT_EQUAL(3, s.mesh_count);
    static const uint32_t from0[6] = {0, 2, 1, 3, 5, 4}, from1[6] = {1, 3, 2, 4, 6, 5},
                          whole[3] = {0, 2, 1};
    TEST_ASSERT_EQUAL_UINT32(6, s.meshes[0].index_count);
    TEST_ASSERT_EQUAL_UINT32_ARRAY(from0, s.meshes[0].indices, 6);
    TEST_ASSERT_EQUAL_UINT32(6, s.meshes[1].index_count);
    TEST_ASSERT_EQUAL_UINT32_ARRAY(from1, s.meshes[1].indices, 6);
    TEST_ASSERT_EQUAL_UINT32(3, s.meshes[2].index_count);
    TEST_ASSERT_EQUAL_UINT32_ARRAY(whole, s.meshes[2].indices, 3);
    mote_scene_free(&s);
}

int main(void)
{
    UNITY_BEGIN();
    RUN_TEST(right_handed_scene_should_draw_as_its_left_handed_mirror);
    RUN_TEST(right_handed_scene_should_put_plus_x_where_babylon_does);
    RUN_TEST(right_handed_scene_should_keep_its_front_faces_front);
    RUN_TEST(right_handed_scene_should_flip_unindexed_triangles_of_every_sub_mesh);
    return UNITY_END();
}
