/*
 * test_babylon_transforms.c - how the .babylon loader places things, where
 * Babylon.js's rules are more than position, rotation and scaling: a
 * right-handed scene (useRightHandedSystem), loaded mirrored in z so that
 * mote's left-handed core draws what Babylon.js draws, and pivot and local
 * matrices, folded into the transforms.
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
 * with normals, turned by Euler angles, scaled unevenly about a pivot
 * (pivotMatrix), with an instance turned by a quaternion, and a child
 * pyramid without normals (smooth normals are made) in the current layout,
 * and a floor in the legacy one. */
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
    "\"scaling\":[1,1.5,1],\"pivotMatrix\":[1,0,0,0, 0,0.8,0.6,0, 0,-0.6,0.8,0, 0.5,0.2,0.3,1],"
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
 * a matrix M written S M S (S = diag(1, 1, -1): the elements in row or
 * column 2 but not both negated), and each triangle's last two corners
 * swapped. */
static const char lh_mirror[] =
    "{\"materials\":[{\"id\":\"red\",\"diffuse\":[1,0.2,0.2]},{\"id\":\"green\",\"diffuse\":[0.2,1,0.2]}],"
    "\"transformNodes\":[{\"id\":\"rig\",\"position\":[0.5,1,-3],\"rotation\":[-0.1,-0.2,0.05]}],"
    "\"cameras\":[{\"id\":\"cam\",\"parentId\":\"rig\",\"position\":[0.3,1,-6],\"target\":[0.2,0.1,3],"
    "\"fov\":0.9,\"minZ\":0.5,\"maxZ\":100}],\"activeCameraID\":\"cam\","
    "\"lights\":[{\"type\":0,\"id\":\"p\",\"position\":[3,4,-5],\"intensity\":0.8},"
    "{\"type\":1,\"id\":\"d\",\"direction\":[-0.3,-1,0.5],\"intensity\":0.5}],"
    "\"meshes\":["
    "{\"id\":\"box\",\"materialId\":\"red\",\"position\":[1,0.2,1],\"rotation\":[-0.3,-0.7,0.2],"
    "\"scaling\":[1,1.5,1],\"pivotMatrix\":[1,0,0,0, 0,0.8,-0.6,0, 0,0.6,0.8,0, 0.5,0.2,-0.3,1],"
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

/* Sub-meshes that start at the same vertex modulo 3 share one flipped run
 * of the node's: a copy each grew as sub-meshes x vertices (a 2 MB file of
 * 2,000 sub-meshes over 300,000 vertices took 2.4 GB). */
void unindexed_sub_meshes_of_a_right_handed_scene_should_share_their_runs(void)
{
    mote_scene s;
    load_json("{\"useRightHandedSystem\":true,\"meshes\":[{\"id\":\"u\",\"isUnIndexed\":true,"
              "\"positions\":[0,0,0, 1,0,0, 0,1,0, 1,1,0, 2,0,0, 2,1,0, 3,0,0, 3,1,0, 4,0,0],"
              "\"subMeshes\":[{\"materialIndex\":0,\"verticesStart\":1,\"verticesCount\":6},"
              "{\"materialIndex\":0,\"verticesStart\":4,\"verticesCount\":3},"
              "{\"materialIndex\":0,\"verticesStart\":2,\"verticesCount\":6},"
              "{\"materialIndex\":0,\"verticesStart\":5,\"verticesCount\":3}]}]}",
              &s);
    TEST_ASSERT_EQUAL(4, s.mesh_count);
    static const uint32_t from1[6] = {1, 3, 2, 4, 6, 5}, from4[3] = {4, 6, 5}, from2[6] = {2, 4, 3, 5, 7, 6},
                          from5[3] = {5, 7, 6};
    TEST_ASSERT_EQUAL_UINT32_ARRAY(from1, s.meshes[0].indices, 6);
    TEST_ASSERT_EQUAL_UINT32_ARRAY(from4, s.meshes[1].indices, 3);
    TEST_ASSERT_EQUAL_UINT32_ARRAY(from2, s.meshes[2].indices, 6);
    TEST_ASSERT_EQUAL_UINT32_ARRAY(from5, s.meshes[3].indices, 3);
    TEST_ASSERT_EQUAL_PTR(s.meshes[0].indices + 3, s.meshes[1].indices);
    TEST_ASSERT_EQUAL_PTR(s.meshes[2].indices + 3, s.meshes[3].indices);
    mote_scene_free(&s);
}

/* Messages name an index where the file has it, though a right-handed
 * scene's triangles are flipped as they are read. */
void an_index_out_of_range_should_be_named_where_the_file_has_it(void)
{
    static const char *const files[2] = {
        "{\"useRightHandedSystem\":true,\"meshes\":[{\"id\":\"a\",\"positions\":[0,0,0,1,0,0,0,1,0],"
        "\"indices\":[0,1,9]}]}",
        "{\"useRightHandedSystem\":true,\"meshes\":[{\"id\":\"a\",\"positions\":[0,0,0,1,0,0,0,1,0],"
        "\"indices\":[0,1,2, 2,7,0]}]}"};
    static const char *const expected[2] = {"t: meshes[0].indices[2]: 9 is out of range (3 vertices)",
                                            "t: meshes[0].indices[4]: 7 is out of range (3 vertices)"};
    for (int i = 0; i < 2; i++) {
        mote_scene s;
        TEST_ASSERT_EQUAL(MOTE_ERR_RANGE, mote_scene_load_memory(files[i], strlen(files[i]), "t", NULL, NULL,
                                                                 &s, msg, sizeof msg));
        TEST_ASSERT_EQUAL_STRING(expected[i], msg);
    }
}

/* ---- pivotMatrix and localMatrix --------------------------------------- */

/* The world position of mesh m's vertex v. */
static void world_vertex(const mote_mesh *m, uint32_t v, float out[3])
{
    float w[16];
    mote_mesh_world_matrix(m, w);
    const float *p = m->vertices[v].position;
    for (int k = 0; k < 3; k++)
        out[k] = w[k] * p[0] + w[4 + k] * p[1] + w[8 + k] * p[2] + w[12 + k];
}

#define ASSERT_WORLD_VERTEX(x, y, z, mesh, v)                 \
    do {                                                      \
        float p_[3];                                          \
        world_vertex(mesh, v, p_);                            \
        TEST_ASSERT_FLOAT_WITHIN(1e-5f, x, p_[0]);            \
        TEST_ASSERT_FLOAT_WITHIN(1e-5f, y, p_[1]);            \
        TEST_ASSERT_FLOAT_WITHIN(1e-5f, z, p_[2]);            \
    } while (0)

/* Babylon.js composes a node's local matrix with a matrix P (its arrays in
 * mote's column-major order; here with column vectors) as T R S P for a
 * localMatrix (setPreTransformMatrix) and T P^-1 R S P for a pivotMatrix
 * (setPivotMatrix, postMultiplyPivotMatrix by default); children follow the
 * whole of it, and an instance gets its source's matrix as a pivot
 * (InstancedMesh's constructor calls setPivotMatrix). The expected world
 * positions below are worked out by hand from those products. */
void loader_should_apply_pivot_and_local_matrices_as_babylon_does(void)
{
    mote_scene s;
    load_json("{\"meshes\":["
              /* P = translate(0, 0, 1) rotateZ(90 deg) scale(1, 3, 1); the
               * mesh: T = (1, 2, 3), R = a quarter turn about y (x -> -z,
               * z -> x), S = (2, 1, 1) */
              "{\"id\":\"pre\",\"position\":[1,2,3],\"rotation\":[0,1.5707963267948966,0],"
              "\"scaling\":[2,1,1],\"localMatrix\":[0,1,0,0, -3,0,0,0, 0,0,1,0, 0,0,1,1],"
              "\"positions\":[1,0,0, 0,1,0, 0,0,0],\"indices\":[0,1,2],"
              "\"instances\":[{\"name\":\"inst\",\"position\":[10,0,0],\"rotation\":[0,0,0],"
              "\"scaling\":[1,1,1]}]},"
              /* P = translate(0, 1, 0) rotateZ(c = 0.6, s = 0.8) scale(1, 2, 1);
               * the mesh: T = (0, 0, 5), S = (2, 1, 1): P^-1 S P is sheared */
              "{\"id\":\"piv\",\"position\":[0,0,5],\"scaling\":[2,1,1],"
              "\"pivotMatrix\":[0.6,0.8,0,0, -1.6,1.2,0,0, 0,0,1,0, 0,1,0,1],"
              "\"positions\":[1,0,0, 0,1,0, 0,0,0, -0.8,-0.3,0],\"indices\":[0,1,2]},"
              "{\"id\":\"kid\",\"parentId\":\"piv\",\"position\":[1,0,0],"
              "\"positions\":[0,0,0, 0,1,0, 1,0,0],\"indices\":[0,1,2]},"
              "{\"id\":\"tkid\",\"parentId\":\"tn\",\"position\":[0,0,1],"
              "\"positions\":[0,0,0, 1,0,0, 0,1,0],\"indices\":[0,1,2]}],"
              /* a transform node's localMatrix: translate(5, 0, 0) scale(1, 1, 2) */
              "\"transformNodes\":[{\"id\":\"tn\",\"localMatrix\":[1,0,0,0, 0,1,0,0, 0,0,2,0, "
              "5,0,0,1]}]}", &s);
    TEST_ASSERT_EQUAL_STRING("", s.warning);
    /* pre, piv, kid, tkid, tn, inst, then the helper taking piv's sheared
     * matrix in its place */
    TEST_ASSERT_EQUAL(7, s.mesh_count);
    const mote_mesh *pre = &s.meshes[0], *piv = &s.meshes[1], *kid = &s.meshes[2],
                    *tkid = &s.meshes[3], *inst = &s.meshes[5];
    /* pre: (1,0,0) -P-> (0,1,1) -S-> (0,1,1) -R-> (1,1,0) -T-> (2,3,3);
     * (0,1,0) -P-> (-3,0,1) -S-> (-6,0,1) -R-> (1,0,6) -T-> (2,2,9);
     * (0,0,0) -P-> (0,0,1) -> (0,0,1) -> (1,0,0) -> (2,2,3) */
    ASSERT_WORLD_VERTEX(2.0f, 3.0f, 3.0f, pre, 0);
    ASSERT_WORLD_VERTEX(2.0f, 2.0f, 9.0f, pre, 1);
    ASSERT_WORLD_VERTEX(2.0f, 2.0f, 3.0f, pre, 2);
    TEST_ASSERT_NULL(pre->parent);
    /* inst: T P^-1 P = T: its source's pre-transform undone */
    ASSERT_WORLD_VERTEX(11.0f, 0.0f, 0.0f, inst, 0);
    ASSERT_WORLD_VERTEX(10.0f, 1.0f, 0.0f, inst, 1);
    /* piv: x -> T + P^-1 S P x, with P^-1 y = diag(1, 1/2, 1) Rz^T (y - (0,1,0)):
     * (1,0,0) -P-> (0.6,1.8,0) -S-> (1.2,1.8,0) -P^-1-> (1.36,-0.24,0);
     * (0,1,0) -P-> (-1.6,2.2,0) -S-> (-3.2,2.2,0) -P^-1-> (-0.96,1.64,0);
     * the pivot point P^-1 (0,0,0) = (-0.8,-0.3,0) stays where it is */
    ASSERT_WORLD_VERTEX(1.36f, -0.24f, 5.0f, piv, 0);
    ASSERT_WORLD_VERTEX(-0.96f, 1.64f, 5.0f, piv, 1);
    ASSERT_WORLD_VERTEX(0.0f, 0.0f, 5.0f, piv, 2);
    ASSERT_WORLD_VERTEX(-0.8f, -0.3f, 5.0f, piv, 3);
    TEST_ASSERT_EQUAL_PTR(&s.meshes[6], piv->parent);
    TEST_ASSERT_TRUE(s.meshes[6].hidden);
    TEST_ASSERT_EQUAL_UINT32(0, s.meshes[6].vertex_count);
    /* kid, at (1,0,0) under piv: piv's matrix at (1,0,0) + its vertex:
     * (1,0,0) as above; (1,1,0) -P-> (-1,3,0) -S-> (-2,3,0) -P^-1-> (0.4,1.4,0);
     * (2,0,0) -P-> (1.2,2.6,0) -S-> (2.4,2.6,0) -P^-1-> (2.72,-0.48,0) */
    TEST_ASSERT_EQUAL_PTR(piv, kid->parent);
    ASSERT_WORLD_VERTEX(1.36f, -0.24f, 5.0f, kid, 0);
    ASSERT_WORLD_VERTEX(0.4f, 1.4f, 5.0f, kid, 1);
    ASSERT_WORLD_VERTEX(2.72f, -0.48f, 5.0f, kid, 2);
    /* tkid, at (0,0,1) under tn: P (0,0,1) = (5,0,2), P (1,0,1) = (6,0,2) */
    ASSERT_WORLD_VERTEX(5.0f, 0.0f, 2.0f, tkid, 0);
    ASSERT_WORLD_VERTEX(6.0f, 0.0f, 2.0f, tkid, 1);
    ASSERT_WORLD_VERTEX(5.0f, 1.0f, 2.0f, tkid, 2);
    mote_scene_free(&s);
}

/* Babylon.js's SceneSerializer writes a node's matrix as JSON.stringify
 * writes a Float32Array, an object with keys "0" to "15" (the identity on
 * every mesh it saves), and Matrix.FromArray reads it by index all the
 * same: such a matrix counts as the array of its values by key. */
void loader_should_read_a_matrix_written_as_an_object(void)
{
    mote_scene s;
    load_json("{\"meshes\":["
              /* translate(5, 0, 0) scale(1, 1, 2), its keys out of order */
              "{\"id\":\"pre\",\"localMatrix\":{\"12\":5,\"10\":2,\"0\":1,\"1\":0,\"2\":0,"
              "\"3\":0,\"4\":0,\"5\":1,\"6\":0,\"7\":0,\"8\":0,\"9\":0,\"11\":0,\"13\":0,"
              "\"14\":0,\"15\":1},\"positions\":[0,0,1, 1,0,1, 0,1,1],\"indices\":[0,1,2]},"
              /* the identity, as the serializer writes it on every mesh */
              "{\"id\":\"same\",\"position\":[0,3,0],\"localMatrix\":{\"0\":1,\"1\":0,"
              "\"2\":0,\"3\":0,\"4\":0,\"5\":1,\"6\":0,\"7\":0,\"8\":0,\"9\":0,\"10\":1,"
              "\"11\":0,\"12\":0,\"13\":0,\"14\":0,\"15\":1},"
              "\"positions\":[0,0,1, 1,0,1, 0,1,1],\"indices\":[0,1,2]}]}", &s);
    TEST_ASSERT_EQUAL_STRING("", s.warning);
    TEST_ASSERT_EQUAL(2, s.mesh_count);
    ASSERT_WORLD_VERTEX(5.0f, 0.0f, 2.0f, &s.meshes[0], 0);
    ASSERT_WORLD_VERTEX(6.0f, 0.0f, 2.0f, &s.meshes[0], 1);
    ASSERT_WORLD_VERTEX(5.0f, 1.0f, 2.0f, &s.meshes[0], 2);
    ASSERT_WORLD_VERTEX(0.0f, 3.0f, 1.0f, &s.meshes[1], 0);
    ASSERT_WORLD_VERTEX(1.0f, 3.0f, 1.0f, &s.meshes[1], 1);
    mote_scene_free(&s);
}

/* A pivot that only turns and moves, under an even scale, leaves the
 * node a rotation, scale and position: no helper node. First in the xy
 * plane, by hand: P = translate(1, 0, 0) rotateZ(c = 0.6, s = 0.8), the
 * node turned a quarter about z (x -> y) and scaled by 2: (0,0,0) -P->
 * (1,0,0) -R S-> (0,2,0) -P^-1-> Rz^T (-1,2,0) = (1,2,0); (1,0,0) -P->
 * (1.6,0.8,0) -R S-> (-1.6,3.2,0) -P^-1-> Rz^T (-2.6,3.2,0) = (1,4,0). */
void loader_should_fold_a_pivot_without_shear_into_the_node_alone(void)
{
    mote_scene s;
    load_json("{\"meshes\":[{\"id\":\"p\",\"rotation\":[0,0,1.5707963267948966],"
              "\"scaling\":[2,2,2],\"pivotMatrix\":[0.6,0.8,0,0, -0.8,0.6,0,0, 0,0,1,0, 1,0,0,1],"
              "\"positions\":[0,0,0, 1,0,0, 0,0,1],\"indices\":[0,1,2]}]}", &s);
    TEST_ASSERT_EQUAL(1, s.mesh_count);
    ASSERT_WORLD_VERTEX(1.0f, 2.0f, 0.0f, &s.meshes[0], 0);
    ASSERT_WORLD_VERTEX(1.0f, 4.0f, 0.0f, &s.meshes[0], 1);
    ASSERT_WORLD_VERTEX(1.0f, 2.0f, 2.0f, &s.meshes[0], 2);
    mote_scene_free(&s);
    /* Then about a slanted axis, whose six-digit matrix has columns
     * orthogonal only to rounding: with all three scales equal, rounding
     * alone would otherwise decide a split. P = translate(t = (1, 2, 3)) Q,
     * Q a turn; L = P^-1 (R 2) P keeps the pivot point x0 = P^-1 (0) =
     * -Q^T t = -(q0.t, q1.t, q2.t) = (-1.051366, -2.376956, -2.691601)
     * where it is, and doubles lengths about it without bending angles. */
    load_json("{\"meshes\":[{\"id\":\"p\",\"rotation\":[0.3,0.2,0.1],\"scaling\":[2,2,2],"
              "\"pivotMatrix\":[0.500324,0.793885,-0.345576,0, -0.554040,0.600259,0.576826,0, "
              "0.665368,-0.097137,0.740169,0, 1,2,3,1],"
              "\"positions\":[-1.051366,-2.376956,-2.691601, -0.051366,-2.376956,-2.691601, "
              "-1.051366,-1.376956,-2.691601],\"indices\":[0,1,2]}]}", &s);
    TEST_ASSERT_EQUAL(1, s.mesh_count);
    float x0[3], a[3], b[3];
    world_vertex(&s.meshes[0], 0, x0);
    world_vertex(&s.meshes[0], 1, a);
    world_vertex(&s.meshes[0], 2, b);
    TEST_ASSERT_FLOAT_WITHIN(1e-4f, -1.051366f, x0[0]);
    TEST_ASSERT_FLOAT_WITHIN(1e-4f, -2.376956f, x0[1]);
    TEST_ASSERT_FLOAT_WITHIN(1e-4f, -2.691601f, x0[2]);
    float aa = 0.0f, bb = 0.0f, ab = 0.0f;
    for (int k = 0; k < 3; k++) {
        aa += (a[k] - x0[k]) * (a[k] - x0[k]);
        bb += (b[k] - x0[k]) * (b[k] - x0[k]);
        ab += (a[k] - x0[k]) * (b[k] - x0[k]);
    }
    TEST_ASSERT_FLOAT_WITHIN(1e-4f, 4.0f, aa);
    TEST_ASSERT_FLOAT_WITHIN(1e-4f, 4.0f, bb);
    TEST_ASSERT_FLOAT_WITHIN(1e-4f, 0.0f, ab);
    mote_scene_free(&s);
}

/* A sheared mesh is lit by its normals turned by the inverse transpose of
 * its world matrix (the core's normal matrix), as Babylon.js's shaders
 * turn them for a mesh scaled unevenly (NONUNIFORMSCALING). The pivot of
 * the test above, with S = (2, 1, 1), gives L's 3x3 part columns
 * (1.36, -0.24, 0), (-0.96, 1.64, 0), (0, 0, 1); its cofactor matrix (the
 * inverse transpose times det = 2) takes the normal (0.6, 0, -0.8) to
 * (0.984, 0.576, -1.6), of length 1.9646: a light shining down +z lights
 * it 1.6 / 1.9646 = 0.8144, 208 of 255. (Turned by L itself, the normal
 * would give 0.695, 177.) */
void loader_should_light_a_sheared_mesh_by_its_turned_normals(void)
{
    mote_scene s;
    load_json("{\"cameras\":[{\"id\":\"c\",\"position\":[0,0,-10],\"target\":[0,0,0]}],"
              "\"lights\":[{\"type\":1,\"id\":\"d\",\"direction\":[0,0,1]}],"
              "\"meshes\":[{\"id\":\"t\",\"position\":[0,0,5],\"scaling\":[2,1,1],"
              "\"pivotMatrix\":[0.6,0.8,0,0, -1.6,1.2,0,0, 0,0,1,0, 0,1,0,1],"
              "\"positions\":[-1,-1,0, 1,-1,0, 0,1,0],"
              "\"normals\":[0.6,0,-0.8, 0.6,0,-0.8, 0.6,0,-0.8],\"indices\":[0,1,2]}]}", &s);
    render(&s, false);
    int drawn = 0;
    for (int i = 0; i < W * H; i++) {
        const uint8_t *p = &color[i * 4];
        if (p[0] == 0)
            continue;
        drawn++;
        TEST_ASSERT_UINT8_WITHIN(1, 208, p[0]);
        TEST_ASSERT_EQUAL_UINT8(p[0], p[2]);
    }
    TEST_ASSERT_TRUE(drawn > 50);
    mote_scene_free(&s);
}

/* The helper a sheared matrix takes is a mesh of the scene: it counts
 * against limits.max_meshes like any other, and the load fails, freeing
 * everything, when there is no room for it. */
void loader_should_count_helper_nodes_against_the_mesh_limit(void)
{
    static const char sheared[] =
        "{\"meshes\":[{\"id\":\"a\",\"scaling\":[2,1,1],"
        "\"pivotMatrix\":[0.6,0.8,0,0, -1.6,1.2,0,0, 0,0,1,0, 0,1,0,1]},"
        "{\"id\":\"b\",\"parentId\":\"a\"}]}";
    mote_limits lim = mote_limits_default();
    lim.max_meshes = 3;
    mote_scene s;
    TEST_ASSERT_EQUAL_MESSAGE(MOTE_OK, mote_scene_load_memory(sheared, strlen(sheared), "t", NULL,
                                                              &lim, &s, msg, sizeof msg), msg);
    TEST_ASSERT_EQUAL(3, s.mesh_count);
    mote_scene_free(&s);
    lim.max_meshes = 2;
    TEST_ASSERT_EQUAL(MOTE_ERR_LIMIT, mote_scene_load_memory(sheared, strlen(sheared), "t", NULL,
                                                             &lim, &s, msg, sizeof msg));
    TEST_ASSERT_EQUAL_STRING("t: meshes[0]: more than the limit of 2 meshes (nodes with a "
                             "sheared pivot or local matrix take two)", msg);
    TEST_ASSERT_EQUAL(0, s.mesh_count);
}

/* A chain deeper than MOTE_MAX_PARENTS only by the hidden helpers of its
 * sheared matrices says so. */
void a_chain_too_deep_by_its_helpers_should_say_why(void)
{
    enum { N = MOTE_MAX_PARENTS / 2 + 2 };
    static const char sheared[] = "\"scaling\":[2,1,1],\"pivotMatrix\":[0.6,0.8,0,0, -1.6,1.2,0,0, 0,0,1,0, 0,1,0,1]";
    static char json[N * 160];
    size_t at = (size_t)snprintf(json, sizeof json, "{\"meshes\":[{\"id\":\"n0\",%s}", sheared);
    for (int i = 1; i < N; i++)
        at += (size_t)snprintf(json + at, sizeof json - at, ",{\"id\":\"n%d\",\"parentId\":\"n%d\",%s}", i,
                               i - 1, sheared);
    snprintf(json + at, sizeof json - at, "]}");
    mote_scene s;
    TEST_ASSERT_EQUAL(MOTE_ERR_LIMIT, mote_scene_load_memory(json, strlen(json), "t", NULL, NULL, &s, msg,
                                                             sizeof msg));
    TEST_ASSERT_NOT_NULL_MESSAGE(strstr(msg, "parents (MOTE_MAX_PARENTS), counting one for each sheared "
                                             "pivotMatrix or localMatrix above it"),
                                 msg);
}

/* ---- thin instances ----------------------------------------------------- */

/* A mesh's thin instances are drawn at the mesh's world matrix times
 * their own (the shaders' world * instance matrix, so each matrix is in
 * the mesh's own space), sharing its arrays, one mesh per sub-mesh each;
 * the mesh itself and its instances are not drawn (Mesh._processRendering
 * draws the thin instances alone), and a sheared matrix gets a helper as
 * a sheared localMatrix does. The mesh: T = (0, 0, 5), S = 2. */
void loader_should_draw_thin_instances_where_babylon_puts_them(void)
{
    mote_scene s;
    load_json("{\"meshes\":[{\"id\":\"m\",\"position\":[0,0,5],\"scaling\":[2,2,2],"
              "\"positions\":[0,0,0, 1,0,0, 0,1,0],\"indices\":[0,1,2],"
              "\"subMeshes\":[{\"materialIndex\":0,\"indexStart\":0,\"indexCount\":3},"
              "{\"materialIndex\":1,\"indexStart\":0,\"indexCount\":3}],"
              "\"instances\":[{\"name\":\"i\",\"position\":[0,9,0]}],"
              "\"thinInstances\":{\"instancesCount\":3,\"matrixBufferSize\":48,\"matrixData\":["
              /* translate(1, 0, 0) */
              "1,0,0,0, 0,1,0,0, 0,0,1,0, 1,0,0,1, "
              /* a quarter turn about z: x -> y, y -> -x */
              "0,1,0,0, -1,0,0,0, 0,0,1,0, 0,0,0,1, "
              /* a shear (x += y) and translate(0, 2, 0) */
              "1,0,0,0, 1,1,0,0, 0,0,1,0, 0,2,0,1]}}]}", &s);
    TEST_ASSERT_EQUAL_STRING("meshes[0]: its instances are not drawn: Babylon.js draws a mesh's "
                             "thin instances in place of it and its instances", s.warning);
    /* m and its instance (2 sub-meshes each), the thin instances (2
     * each), the helper of the sheared one */
    TEST_ASSERT_EQUAL(11, s.mesh_count);
    for (int i = 0; i < 4; i++)
        TEST_ASSERT_TRUE(s.meshes[i].hidden);
    for (int i = 4; i < 10; i++) {
        TEST_ASSERT_FALSE(s.meshes[i].hidden);
        TEST_ASSERT_EQUAL_PTR(s.meshes[0].vertices, s.meshes[i].vertices);
        TEST_ASSERT_EQUAL_PTR(s.meshes[i % 2].indices, s.meshes[i].indices);
    }
    TEST_ASSERT_TRUE(s.meshes[10].hidden);
    TEST_ASSERT_EQUAL_PTR(&s.meshes[10], s.meshes[8].parent);
    TEST_ASSERT_EQUAL_PTR(&s.meshes[0], s.meshes[10].parent);
    /* (1,0,0) -> (2,0,0) -> 2 (2,0,0) + (0,0,5); (0,0,0) -> (1,0,0) -> (2,0,5) */
    ASSERT_WORLD_VERTEX(4.0f, 0.0f, 5.0f, &s.meshes[4], 1);
    ASSERT_WORLD_VERTEX(2.0f, 0.0f, 5.0f, &s.meshes[5], 0);
    /* (1,0,0) -> (0,1,0) -> (0,2,5); (0,1,0) -> (-1,0,0) -> (-2,0,5) */
    ASSERT_WORLD_VERTEX(0.0f, 2.0f, 5.0f, &s.meshes[6], 1);
    ASSERT_WORLD_VERTEX(-2.0f, 0.0f, 5.0f, &s.meshes[7], 2);
    /* (0,1,0) -> (1,1,0) + (0,2,0) -> (2,6,5); (1,0,0) -> (1,2,0) -> (2,4,5) */
    ASSERT_WORLD_VERTEX(2.0f, 6.0f, 5.0f, &s.meshes[8], 2);
    ASSERT_WORLD_VERTEX(2.0f, 4.0f, 5.0f, &s.meshes[9], 1);
    mote_scene_free(&s);
}

/* Drawn, the thin instances of a quad at the origin stand at x = -3 and
 * x = +3 (left and right of the image), and nothing at the middle, where
 * the mesh itself would be. */
void thin_instances_should_be_drawn_in_their_places_and_the_mesh_not(void)
{
    int lo, hi;
    int n = draw_unlit("{\"cameras\":[{\"id\":\"c\",\"position\":[0,0,-10],\"target\":[0,0,0]}],"
                       "\"materials\":[{\"id\":\"red\",\"diffuse\":[1,0,0],\"emissive\":[1,0,0],"
                       "\"backFaceCulling\":false}],"
                       "\"meshes\":[{\"id\":\"q\",\"materialId\":\"red\","
                       "\"positions\":[-0.5,-0.5,0, 0.5,-0.5,0, 0.5,0.5,0, -0.5,0.5,0],"
                       "\"indices\":[0,1,2, 0,2,3],\"thinInstances\":{\"instancesCount\":2,"
                       "\"matrixData\":[1,0,0,0, 0,1,0,0, 0,0,1,0, -3,0,0,1, "
                       "1,0,0,0, 0,1,0,0, 0,0,1,0, 3,0,0,1]}}]}", &lo, &hi, NULL);
    TEST_ASSERT_TRUE(n > 0);
    /* x = +-3 at distance 10 with fov 0.8: 3 / (10 tan 0.4 x 4/3) of the
     * half width 48, 25.5 pixels from the middle */
    const uint8_t *left = &color[(H / 2 * W + 22) * 4], *right = &color[(H / 2 * W + 73) * 4],
                  *middle = &color[(H / 2 * W + W / 2) * 4];
    TEST_ASSERT_TRUE(left[0] > 0);
    TEST_ASSERT_TRUE(right[0] > 0);
    TEST_ASSERT_EQUAL_UINT8(0, middle[0]);
    TEST_ASSERT_TRUE(lo >= 16 && hi <= W - 16);
}

/* Babylon.js culls all the thin instances of a mesh by the mesh's own
 * world matrix (they are one draw), so a thin instance whose matrix
 * mirrors shows its back faces: of a triangle facing the camera, drawn
 * with back faces culled, the plain one is drawn and the mirrored one
 * (scale x by -1) is not. In a right-handed scene a thin instance's
 * matrix is mirrored with the rest: translate(2, 0, 3) of the file is
 * (2, 0, -3) here. */
void a_mirroring_thin_instance_should_be_culled_as_babylon_culls_it(void)
{
    mote_scene s;
    load_json("{\"cameras\":[{\"id\":\"c\",\"position\":[0,0,-10],\"target\":[0,0,0]}],"
              "\"meshes\":[{\"id\":\"t\",\"positions\":[0,0,0, 1,0,0, 0,1,0],\"indices\":[0,1,2],"
              "\"thinInstances\":{\"instancesCount\":2,\"matrixData\":[1,0,0,0, 0,1,0,0, 0,0,1,0, "
              "-2,0,0,1, -1,0,0,0, 0,1,0,0, 0,0,1,0, 2,0,0,1]}}]}", &s);
    render(&s, true);
    int lo, hi;
    drawn_columns(&lo, &hi);
    TEST_ASSERT_TRUE(lo >= 0);
    TEST_ASSERT_TRUE(hi < W / 2);
    mote_scene_free(&s);
    load_json("{\"useRightHandedSystem\":true,\"meshes\":[{\"id\":\"t\","
              "\"positions\":[0,0,0, 1,0,0, 0,1,0],\"indices\":[0,1,2],"
              "\"thinInstances\":{\"instancesCount\":1,\"matrixData\":[1,0,0,0, 0,1,0,0, 0,0,1,0, "
              "2,0,3,1]}}]}", &s);
    ASSERT_WORLD_VERTEX(3.0f, 0.0f, -3.0f, &s.meshes[1], 1);
    mote_scene_free(&s);
}

/* Thin instances are meshes of the scene: they count against
 * limits.max_meshes before anything is made for them, and an
 * instancesCount past the matrices (millions of them) makes none, the
 * mesh drawn neither, as WebGL draws nothing of Babylon.js's draw call
 * past its buffer. */
void thin_instances_should_count_against_the_mesh_limit(void)
{
    static const char four[] =
        "{\"meshes\":[{\"id\":\"a\",\"positions\":[0,0,0, 1,0,0, 0,1,0],\"indices\":[0,1,2],"
        "\"thinInstances\":{\"instancesCount\":4,\"matrixData\":[1,0,0,0, 0,1,0,0, 0,0,1,0, 0,0,0,1,"
        " 1,0,0,0, 0,1,0,0, 0,0,1,0, 1,0,0,1, 1,0,0,0, 0,1,0,0, 0,0,1,0, 2,0,0,1,"
        " 1,0,0,0, 0,1,0,0, 0,0,1,0, 3,0,0,1]}}]}";
    mote_limits lim = mote_limits_default();
    lim.max_meshes = 4;
    mote_scene s;
    TEST_ASSERT_EQUAL(MOTE_ERR_LIMIT, mote_scene_load_memory(four, strlen(four), "t", NULL, &lim,
                                                             &s, msg, sizeof msg));
    TEST_ASSERT_EQUAL_STRING("t: meshes: 5 meshes, more than the limit of 4 (transform nodes, "
                             "instances and thin instances count)", msg);
    TEST_ASSERT_EQUAL(0, s.mesh_count);
    lim.max_meshes = 5;
    TEST_ASSERT_EQUAL_MESSAGE(MOTE_OK, mote_scene_load_memory(four, strlen(four), "t", NULL, &lim,
                                                              &s, msg, sizeof msg), msg);
    TEST_ASSERT_EQUAL(5, s.mesh_count);
    mote_scene_free(&s);
    load_json("{\"meshes\":[{\"id\":\"a\",\"positions\":[0,0,0, 1,0,0, 0,1,0],\"indices\":[0,1,2],"
              "\"thinInstances\":{\"instancesCount\":3000000,\"matrixData\":[1,0,0,0, 0,1,0,0, "
              "0,0,1,0, 0,0,0,1]}}]}", &s);
    TEST_ASSERT_EQUAL(1, s.mesh_count);
    TEST_ASSERT_TRUE(s.meshes[0].hidden);
    TEST_ASSERT_EQUAL_STRING("meshes[0].thinInstances: instancesCount 3000000, but matrixData holds "
                             "1 matrix: Babylon.js's draw reads past it, which WebGL refuses: "
                             "the mesh is not drawn", s.warning);
    mote_scene_free(&s);
}

int main(void)
{
    UNITY_BEGIN();
    RUN_TEST(right_handed_scene_should_draw_as_its_left_handed_mirror);
    RUN_TEST(right_handed_scene_should_put_plus_x_where_babylon_does);
    RUN_TEST(right_handed_scene_should_keep_its_front_faces_front);
    RUN_TEST(right_handed_scene_should_flip_unindexed_triangles_of_every_sub_mesh);
    RUN_TEST(unindexed_sub_meshes_of_a_right_handed_scene_should_share_their_runs);
    RUN_TEST(an_index_out_of_range_should_be_named_where_the_file_has_it);
    RUN_TEST(loader_should_apply_pivot_and_local_matrices_as_babylon_does);
    RUN_TEST(loader_should_read_a_matrix_written_as_an_object);
    RUN_TEST(loader_should_fold_a_pivot_without_shear_into_the_node_alone);
    RUN_TEST(loader_should_light_a_sheared_mesh_by_its_turned_normals);
    RUN_TEST(loader_should_count_helper_nodes_against_the_mesh_limit);
    RUN_TEST(a_chain_too_deep_by_its_helpers_should_say_why);
    RUN_TEST(loader_should_draw_thin_instances_where_babylon_puts_them);
    RUN_TEST(thin_instances_should_be_drawn_in_their_places_and_the_mesh_not);
    RUN_TEST(a_mirroring_thin_instance_should_be_culled_as_babylon_culls_it);
    RUN_TEST(thin_instances_should_count_against_the_mesh_limit);
    return UNITY_END();
}
