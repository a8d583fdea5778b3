/*
 * test_exporters.c - scenes in the layouts Babylon.js's exporters write
 * (tests/data/exporters, made by tests/data/make_exporters.py): each loads
 * with exactly the warnings listed for it, and draws what it holds.
 */
#include "support/io_test.h"

IO_TEST_FIXTURE

enum { W = 96, H = 64 };
static uint8_t img[W * H * 4];

/* Loads tests/data/exporters/<name> and holds its warnings to want (NULL
 * ended): the same texts in the same order, none more. */
static void load_expecting(const char *name, const char *const *want, mote_scene *s)
{
    char path[512];
    snprintf(path, sizeof path, "%s/tests/data/exporters/%s", MOTE_SOURCE_DIR, name);
    TEST_ASSERT_EQUAL_MESSAGE(MOTE_OK, mote_scene_load(path, NULL, s, msg, sizeof msg), msg);
    int n = mote_scene_warning_count(s, NULL);
    int k = 0;
    for (; want[k]; k++) {
        const char *got = mote_scene_warning(s, k, NULL);
        TEST_ASSERT_NOT_NULL_MESSAGE(got, want[k]);
        TEST_ASSERT_EQUAL_STRING(want[k], got);
    }
    TEST_ASSERT_EQUAL_MESSAGE(k, n, k < n ? mote_scene_warning(s, k, NULL) : "a warning is missing");
}

/* the pixel at (x, y), from the top left, is r, g, b (each within tol) */
static void assert_pixel(int x, int y, int r, int g, int b, int tol)
{
    const uint8_t *p = img + ((size_t)y * W + (size_t)x) * 4;
    char where[64];
    snprintf(where, sizeof where, "pixel (%d, %d): %d %d %d", x, y, p[0], p[1], p[2]);
    TEST_ASSERT_INT_WITHIN_MESSAGE(tol, r, p[0], where);
    TEST_ASSERT_INT_WITHIN_MESSAGE(tol, g, p[1], where);
    TEST_ASSERT_INT_WITHIN_MESSAGE(tol, b, p[2], where);
}

/* pixels that differ from the clear colour */
static int coverage(const mote_scene *s)
{
    int n = 0;
    for (int i = 0; i < W * H; i++) {
        const uint8_t *p = img + (size_t)i * 4;
        n += p[0] != s->clear_color.r || p[1] != s->clear_color.g || p[2] != s->clear_color.b;
    }
    return n;
}

static void finish(mote_scene *s)
{
    mote_scene_free(s);
    TEST_ASSERT_EQUAL(live_before, mote__io_live_allocations());
}

/* 3ds Max: the mesh kept in a delayLoadingFile and the "Infinity" camera
 * are the warnings; [r,g,b,a] colours and "" for no parent or material are
 * read without one. The key light lights only the meshes it lists, the
 * PBRMetallicRoughnessMaterial draws its baseColor, the multi-material
 * slot 1 its emissive blue. */
void max_file_should_load_with_its_warnings_and_draw(void)
{
    static const char *const want[] = {
        "meshes[3]: its geometry is in a separate file (an incremental or binary export), which "
        "mote does not read; it is drawn without it",
        "cameras[0].position: \"Infinity\", \"-Infinity\" or \"NaN\" written as text: Babylon.js's "
        "view through this camera is not a number and draws nothing; mote frames the scene with a "
        "camera of its own",
        NULL};
    mote_scene s;
    load_expecting("max.babylon", want, &s);
    TEST_ASSERT_FALSE(s.has_camera);
    TEST_ASSERT_NOT_NULL(s.lights_off);
    TEST_ASSERT_EQUAL_UINT32(1, s.lights_off[0]);   /* RedBox is not listed */
    TEST_ASSERT_EQUAL_UINT32(0, s.lights_off[1]);
    io_render_scene(&s, img, W, H);
    assert_pixel(30, 30, 0, 0, 0, 0);          /* RedBox: unlit, no emissive */
    assert_pixel(45, 33, 163, 163, 36, 8);     /* MetalBox: baseColor lit */
    assert_pixel(65, 29, 0, 0, 255, 0);        /* TwoTone's top: slot 1, emissive */
    assert_pixel(62, 38, 144, 0, 0, 8);        /* TwoTone's front: slot 0, lit red */
    finish(&s);
}

/* Blender: no warning. The leaf's hasAlpha texture cuts its corners (the
 * clear colour shows), the glass box (alpha 0.5) is half its lit grey over
 * the clear colour (opaque, it draws 185 178 171). */
void blender_file_should_load_without_warnings_and_draw(void)
{
    static const char *const want[] = {NULL};
    mote_scene s;
    load_expecting("blender.babylon", want, &s);
    TEST_ASSERT_TRUE(s.has_camera);
    TEST_ASSERT_TRUE(s.two_sided[1]);   /* the leaf: backFaceCulling false */
    TEST_ASSERT_EQUAL_FLOAT(0.5f, s.meshes[2].material.alpha);
    io_render_scene(&s, img, W, H);
    assert_pixel(34, 33, 30, 145, 42, 8);      /* the leaf's texel, lit */
    assert_pixel(26, 24, 13, 13, 13, 0);       /* its cut corner */
    assert_pixel(65, 33, 99, 96, 92, 3);       /* glass: (185 + 13) / 2 */
    assert_pixel(48, 40, 59, 57, 146, 8);      /* the ground box, lit blue */
    finish(&s);
}

/* Maya: no warning. The StandardMaterial's emissiveTexture is added to its
 * dark grey (red, full), the PBRMaterial's albedo is lit green by the
 * hemispheric light; both boxes hang from a transform node. */
void maya_file_should_load_without_warnings_and_draw(void)
{
    static const char *const want[] = {NULL};
    mote_scene s;
    load_expecting("maya.babylon", want, &s);
    TEST_ASSERT_TRUE(s.has_camera);
    TEST_ASSERT_EQUAL(1, s.meshes[0].material.layer_count);
    TEST_ASSERT_EQUAL(MOTE_LAYER_EMISSIVE, s.meshes[0].material.layers[0].role);
    io_render_scene(&s, img, W, H);
    assert_pixel(25, 30, 255, 31, 31, 3);      /* emissive red over the grey */
    assert_pixel(70, 30, 16, 122, 16, 8);      /* albedo green, lit */
    TEST_ASSERT_GREATER_THAN(W * H / 5, coverage(&s));
    finish(&s);
}

/* The SceneSerializer: no warning. Both meshes draw the one
 * geometries.vertexData entry; the box's multi-material is found by its
 * uniqueId and its slots by materialsUniqueIds, the child hangs from the
 * box by its uniqueId, the instance draws the box again below it, and the
 * texture comes from its base64String. */
void serializer_file_should_load_without_warnings_and_draw(void)
{
    static const char *const want[] = {NULL};
    mote_scene s;
    load_expecting("serializer.babylon", want, &s);
    io_render_scene(&s, img, W, H);
    TEST_ASSERT_EQUAL(5, s.mesh_count);   /* box's 2 slots, child, instance's 2 */
    float at[3];
    io_world_origin(&s.meshes[2], at);
    ASSERT_VEC3(1, 0, 0, at, 1e-5f);       /* the child: 2 right of the box */
    io_world_origin(&s.meshes[3], at);
    ASSERT_VEC3(0, -1.2f, 0, at, 1e-5f);   /* the instance, where it is written */
    TEST_ASSERT_EQUAL_PTR(s.meshes[0].vertices, s.meshes[2].vertices);
    io_render_scene(&s, img, W, H);
    /* the hemispheric light gives a side 0.65: 255 x 0.65 = 166 */
    assert_pixel(26, 32, 166, 166, 166, 2);    /* the box's front: the white stripe */
    assert_pixel(36, 32, 166, 83, 0, 2);       /* the orange stripe */
    assert_pixel(64, 30, 17, 33, 166, 2);      /* the child, blue */
    assert_pixel(52, 54, 166, 83, 0, 2);       /* the instance's front, textured */
    assert_pixel(45, 41, 26, 51, 255, 2);      /* its top: slot 1, facing the light */
    finish(&s);
}

/* A glTF file saved again by Babylon.js: no warning. The "__root__" node
 * (turned half about y, z scaled by -1) takes "Cube", written at x 0.8,
 * to -0.8; its mirror and each mesh's side orientation 0 turn the glTF
 * winding round twice, so the outsides face the camera, lit:
 * 255 x 0.8 albedo x 0.88 (the light on the front faces) = 180. */
void gltf_file_should_load_without_warnings_and_draw(void)
{
    static const char *const want[] = {NULL};
    mote_scene s;
    load_expecting("gltf.babylon", want, &s);
    float at[3];
    io_world_origin(&s.meshes[0], at);
    ASSERT_VEC3(-0.8f, 0, 0, at, 1e-5f);
    io_world_origin(&s.meshes[1], at);
    ASSERT_VEC3(0.8f, 0, 0, at, 1e-5f);
    io_render_scene(&s, img, W, H);
    assert_pixel(30, 33, 180, 23, 23, 3);      /* Cube's outside front, red */
    assert_pixel(65, 33, 23, 180, 23, 3);      /* Cube.001's, green */
    finish(&s);
}

/* Cinema 4D: no warning. Its exporter writes no normals, so the cube's
 * eight shared points get Babylon.js's computed ones, the sum of the
 * normals of the triangles at each: a corner on a face's diagonal counts
 * that face twice, (1, 1, 2) / sqrt(6), so the directional light
 * (intensity 0.5) straight down +z lights the front's centre (on the
 * diagonal) at 2 / sqrt(6): 127.5 x 0.816 = 104 (a box with a vertex for
 * each face corner draws 128 there). The plane hangs from the cube by the
 * parent's name and lands at x -0.8 + 1.6; the red point light hangs
 * from the plane, 1 in front of its centre, so each of its corners gets
 * 127.5 / sqrt(0.6^2 + 0.6^2 + 1) = 97 more red, evenly. No material is
 * exported (every materialId ""): both draw in the default white one. */
void c4d_file_should_load_without_warnings_and_draw(void)
{
    static const char *const want[] = {NULL};
    mote_scene s;
    load_expecting("c4d.babylon", want, &s);
    TEST_ASSERT_TRUE(s.has_camera);
    TEST_ASSERT_EQUAL(8, s.meshes[0].vertex_count);
    float at[3];
    io_world_origin(&s.meshes[1], at);
    ASSERT_VEC3(0.8f, 0, 0, at, 1e-5f);
    io_render_scene(&s, img, W, H);
    const uint8_t *p = img + ((size_t)32 * W + 30) * 4;
    TEST_ASSERT_GREATER_THAN(p[1], p[0]);      /* the red point light */
    assert_pixel(30, 32, p[0], 104, 104, 2);   /* the cube's front, smooth */
    assert_pixel(56, 32, 225, 128, 128, 2);    /* the plane, left */
    assert_pixel(70, 32, 225, 128, 128, 2);    /* and right: the light on its axis */
    assert_pixel(48, 32, 51, 51, 128, 0);      /* between them, the clear colour */
    finish(&s);
}

/* Babylon.js 1.x's C# converter, from an OBJ: no warning. The invisible
 * proxy mesh, without vertices, is the parts' parent; each part's
 * interleaved vertices (position, normal, uv) and uvCount 1 are read
 * with a stride of 8. The OBJ's winding is kept, so the outsides are
 * back faces, which the MTL materials' backFaceCulling false draws: the
 * slab's near side shows lit red, with the normals pointing out, over
 * the faces behind. The crate's side facing the "Default light" (at the
 * "Default camera", the middle of the bounds plus their extent) shows
 * crate.png, named by its file name: white left of u 0.5, orange right. */
void babylonexport_file_should_load_without_warnings_and_draw(void)
{
    static const char *const want[] = {NULL};
    mote_scene s;
    load_expecting("babylonexport.babylon", want, &s);
    TEST_ASSERT_TRUE(s.has_camera);
    TEST_ASSERT_EQUAL(3, s.mesh_count);
    TEST_ASSERT_EQUAL(0, s.meshes[0].vertex_count);   /* the proxy */
    TEST_ASSERT_TRUE(s.meshes[0].hidden);
    TEST_ASSERT_EQUAL_PTR(&s.meshes[0], s.meshes[1].parent);
    TEST_ASSERT_EQUAL(24, s.meshes[2].vertex_count);
    TEST_ASSERT_TRUE(s.two_sided[1] && s.two_sided[2]);
    io_render_scene(&s, img, W, H);
    assert_pixel(45, 35, 172, 0, 0, 3);        /* the slab's near side */
    assert_pixel(42, 18, 224, 224, 224, 3);    /* the crate's side: white */
    assert_pixel(54, 19, 237, 119, 0, 3);      /* and orange */
    finish(&s);
}

/* A glTF file loaded into a right-handed Babylon.js scene and saved:
 * no warning. The loader mirrors it in z, and each mesh's
 * sideOrientation 1 (not the right-handed default 0) turns glTF's
 * winding round, so the outsides face the camera, which looks down -z
 * with +x on the right as Babylon.js's right-handed view puts it: the
 * red cube (x 0.8, turned 30 degrees about y, showing its -x side on the
 * left) right, the green one left, at x -0.8 only through its mirroring
 * scale (it would be at -0.2 without), outsides lit 255 x 0.8 albedo x
 * 0.88 = 180. The same scene written left-handed draws the same bytes. */
void righthanded_file_should_load_without_warnings_and_draw_as_its_mirror(void)
{
    static const char *const want[] = {NULL};
    static uint8_t mirror[W * H * 4];
    mote_scene s;
    load_expecting("righthanded_lh.babylon", want, &s);
    TEST_ASSERT_FALSE(s.mirrored_z);
    io_render_scene(&s, mirror, W, H);
    finish(&s);
    load_expecting("righthanded.babylon", want, &s);
    TEST_ASSERT_TRUE(s.mirrored_z);
    io_render_scene(&s, img, W, H);
    TEST_ASSERT_EQUAL_MEMORY(mirror, img, sizeof img);
    assert_pixel(34, 32, 23, 180, 23, 2);      /* the mirrored cube's outside */
    assert_pixel(66, 32, 138, 18, 18, 2);      /* the turned cube's front */
    assert_pixel(54, 32, 121, 15, 15, 2);      /* and its -x side, to its left */
    assert_pixel(48, 32, 51, 51, 77, 0);       /* the clear colour between */
    finish(&s);
}

int main(void)
{
    UNITY_BEGIN();
    RUN_TEST(max_file_should_load_with_its_warnings_and_draw);
    RUN_TEST(blender_file_should_load_without_warnings_and_draw);
    RUN_TEST(maya_file_should_load_without_warnings_and_draw);
    RUN_TEST(serializer_file_should_load_without_warnings_and_draw);
    RUN_TEST(gltf_file_should_load_without_warnings_and_draw);
    RUN_TEST(c4d_file_should_load_without_warnings_and_draw);
    RUN_TEST(babylonexport_file_should_load_without_warnings_and_draw);
    RUN_TEST(righthanded_file_should_load_without_warnings_and_draw_as_its_mirror);
    return UNITY_END();
}
