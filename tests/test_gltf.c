/*
 * test_gltf.c - the glTF loader on the project's own scenes, written by
 * tools/gen_gltf.c into MOTE_GLTF_DIR before the tests run: containers,
 * accessors (quantized, sparse, strided), modes, flat normals, materials,
 * the node tree, cameras and lights, as loaded and as drawn.
 */
#include "support/io_test.h"

#ifndef MOTE_GLTF_DIR
#error "MOTE_GLTF_DIR: the folder gen_gltf wrote (tests/tests.mk)"
#endif

enum { W = 64, H = 48 };

IO_TEST_FIXTURE

static const char *gpath(const char *name)
{
    static char path[512];
    snprintf(path, sizeof path, "%s/%s", MOTE_GLTF_DIR, name);
    return path;
}

static void load(const char *name, mote_scene *s)
{
    TEST_ASSERT_EQUAL_MESSAGE(MOTE_OK, mote_scene_load(gpath(name), NULL, s, msg, sizeof msg),
                              msg);
}

static void render(const mote_scene *s, uint8_t *out)
{
    io_render_scene(s, out, W, H);
}

/* Where the point p of mesh m lands in the (mirrored) world. */
static void world_point(const mote_mesh *m, const float p[3], float out[3])
{
    float w[16];
    mote_mesh_world_matrix(m, w);
    for (int k = 0; k < 3; k++)
        out[k] = w[k] * p[0] + w[4 + k] * p[1] + w[8 + k] * p[2] + w[12 + k];
}

/* The first mesh that draws something. */
static const mote_mesh *drawn_mesh(const mote_scene *s, int nth)
{
    for (int i = 0; i < s->mesh_count; i++)
        if (!s->meshes[i].hidden && nth-- == 0)
            return &s->meshes[i];
    TEST_FAIL_MESSAGE("no such drawn mesh");
    return NULL;
}

static int covered(const uint8_t *rgba)
{
    int n = 0;
    for (int i = 0; i < W * H; i++)
        n += rgba[4 * i] || rgba[4 * i + 1] || rgba[4 * i + 2];
    return n;
}

/* ---- containers -------------------------------------------------------- */

void the_quad_should_load_alike_from_a_bin_file_a_data_uri_and_a_glb(void)
{
    static const char *const names[3] = {"quad.gltf", "quad_embedded.gltf", "quad.glb"};
    static uint8_t pixels[3][W * H * 4];
    for (int c = 0; c < 3; c++) {
        mote_scene s;
        load(names[c], &s);
        TEST_ASSERT_TRUE(s.mirrored_z);
        const mote_mesh *m = drawn_mesh(&s, 0);
        TEST_ASSERT_EQUAL_UINT32(4, m->vertex_count);
        TEST_ASSERT_EQUAL_UINT32(6, m->index_count);
        /* (x, y, z) of the file is (x, y, -z) here */
        ASSERT_VEC3(-0.5f, -0.5f, 0.0f, m->vertices[0].position, 0.0f);
        ASSERT_VEC3(0.0f, 0.0f, -1.0f, m->vertices[0].normal, 0.0f);
        TEST_ASSERT_EQUAL_UINT8(255, m->material.color.r);
        TEST_ASSERT_EQUAL_UINT8(0, m->material.color.g);
        render(&s, pixels[c]);
        mote_scene_free(&s);
    }
    TEST_ASSERT_GREATER_THAN(W * H / 20, covered(pixels[0]));
    TEST_ASSERT_EQUAL_MEMORY(pixels[0], pixels[1], sizeof pixels[0]);
    TEST_ASSERT_EQUAL_MEMORY(pixels[0], pixels[2], sizeof pixels[0]);
    TEST_ASSERT_EQUAL(live_before, mote__io_live_allocations());
}

/* Texture coordinate (0, 0) is the image's top-left texel (glTF's v
 * axis), whether the image is a file, a data: URI or a buffer view. */
void a_texture_should_load_from_a_file_a_data_uri_and_a_buffer_view(void)
{
    static const char *const names[3] = {"textured.gltf", "textured_embedded.gltf",
                                         "textured.glb"};
    for (int c = 0; c < 3; c++) {
        mote_scene s;
        load(names[c], &s);
        TEST_ASSERT_EQUAL_MESSAGE(1, s.texture_count, names[c]);
        const mote_mesh *m = drawn_mesh(&s, 0);
        const mote_texture *t = m->material.texture;
        TEST_ASSERT_NOT_NULL(t);
        TEST_ASSERT_EQUAL(2, t->width);
        const uint8_t *px = t->pixels;
        TEST_ASSERT_EQUAL_UINT8(255, px[0]);          /* top left: red */
        TEST_ASSERT_EQUAL_UINT8(0, px[1]);
        TEST_ASSERT_FALSE(m->material.v_origin_bottom);
        /* corner 3, the quad's top left, samples (0, 0) */
        TEST_ASSERT_EQUAL_FLOAT(0.0f, m->vertices[3].uv[0]);
        TEST_ASSERT_EQUAL_FLOAT(0.0f, m->vertices[3].uv[1]);
        TEST_ASSERT_EQUAL(MOTE_WRAP_CLAMP, m->material.wrap_u);
        TEST_ASSERT_EQUAL(MOTE_WRAP_MIRROR, m->material.wrap_v);
        mote_scene_free(&s);
    }
    TEST_ASSERT_EQUAL(live_before, mote__io_live_allocations());
}

/* Without a folder nothing outside the bytes is read: an external
 * buffer is an error that says so. */
void a_buffer_file_should_need_a_folder(void)
{
    static const char json[] = "{\"asset\":{\"version\":\"2.0\"},\"buffers\":[{\"byteLength\":36,"
                               "\"uri\":\"a.bin\"}],\"bufferViews\":[{\"buffer\":0,"
                               "\"byteLength\":36}],\"accessors\":[{\"bufferView\":0,"
                               "\"componentType\":5126,\"count\":3,\"type\":\"VEC3\"}],"
                               "\"meshes\":[{\"primitives\":[{\"attributes\":{\"POSITION\":0}}]}],"
                               "\"nodes\":[{\"mesh\":0}],\"scenes\":[{\"nodes\":[0]}]}";
    mote_scene s;
    TEST_ASSERT_EQUAL(MOTE_ERR_IO, mote_scene_load_memory(json, strlen(json), "m.gltf", NULL,
                                                          NULL, &s, msg, sizeof msg));
    TEST_ASSERT_EQUAL_STRING("m.gltf: buffers[0].uri: \"a.bin\" is a file, and the scene was "
                             "read from memory without a folder", msg);
    TEST_ASSERT_EQUAL(live_before, mote__io_live_allocations());
}

/* ---- geometry ---------------------------------------------------------- */

void strips_and_fans_should_draw_the_quad_as_triangles_do(void)
{
    static const char *const names[4] = {"strip.gltf", "strip_indexed.gltf", "fan.gltf",
                                          "fan_indexed.gltf"};
    static uint8_t quad[W * H * 4], other[W * H * 4];
    mote_scene s;
    load("quad.gltf", &s);
    s.meshes[0].material.color = (mote_rgba){255, 255, 255, 255};
    render(&s, quad);
    mote_scene_free(&s);
    for (int k = 0; k < 4; k++) {
        load(names[k], &s);
        const mote_mesh *m = drawn_mesh(&s, 0);
        TEST_ASSERT_EQUAL_UINT32_MESSAGE(6, m->index_count, names[k]);
        render(&s, other);
        /* the same pixels covered: every triangle's winding kept (a
         * strip's other diagonal shades them a little apart) */
        for (int i = 0; i < W * H; i++)
            TEST_ASSERT_EQUAL_MESSAGE(quad[4 * i] != 0, other[4 * i] != 0, names[k]);
        mote_scene_free(&s);
    }
    TEST_ASSERT_EQUAL(live_before, mote__io_live_allocations());
}

/* Each line segment (a, b) is the triangle (a, b, b), drawn in wireframe;
 * points are the vertices, drawn as points; both in the material colour,
 * whatever mode the caller asks of the scene's triangles. */
void lines_and_points_should_draw_in_the_wireframe_and_points_modes(void)
{
    mote_scene s;
    load("lines.gltf", &s);
    TEST_ASSERT_EQUAL_STRING("", s.warning);
    TEST_ASSERT_EQUAL(6, s.mesh_count);
    TEST_ASSERT_NOT_NULL(s.modes);
    static const mote_mode want_mode[6] = {MOTE_MODE_WIREFRAME, MOTE_MODE_WIREFRAME,
                                           MOTE_MODE_WIREFRAME, MOTE_MODE_WIREFRAME,
                                           MOTE_MODE_POINTS, MOTE_MODE_POINTS};
    static const uint32_t want_corners[6] = {12, 12, 12, 9, 0, 0};
    static const uint32_t want_vertices[6] = {8, 4, 5, 4, 4, 4};
    for (int k = 0; k < 6; k++) {
        TEST_ASSERT_EQUAL(want_mode[k], s.modes[k]);
        TEST_ASSERT_EQUAL_UINT32(want_corners[k], s.meshes[k].index_count);
        TEST_ASSERT_EQUAL_UINT32(want_vertices[k], s.meshes[k].vertex_count);
        TEST_ASSERT_FALSE(s.meshes[k].hidden);
    }
    static const uint32_t loop[12] = {0, 1, 1, 1, 2, 2, 2, 3, 3, 3, 0, 0};
    TEST_ASSERT_EQUAL_UINT32_ARRAY(loop, s.meshes[1].indices, 12);
    /* a filled mode asked of the scene leaves them in theirs; points
     * asked of lines draw their vertices */
    mote_draw_desc base = {.mode = MOTE_MODE_FLAT}, d;
    mote_scene_draw_desc(&s, 0, &base, &d);
    TEST_ASSERT_EQUAL(MOTE_MODE_WIREFRAME, d.mode);
    TEST_ASSERT_EQUAL(MOTE_CULL_NONE, d.cull);
    mote_scene_draw_desc(&s, 4, &base, &d);
    TEST_ASSERT_EQUAL(MOTE_MODE_POINTS, d.mode);
    base.mode = MOTE_MODE_POINTS;
    mote_scene_draw_desc(&s, 0, &base, &d);
    TEST_ASSERT_EQUAL(MOTE_MODE_POINTS, d.mode);

    static uint8_t px[6][W * H * 4];
    for (int k = 0; k < 6; k++) {
        for (int i = 0; i < 6; i++)
            s.meshes[i].hidden = i != k;
        render(&s, px[k]);
    }
    mote_scene_free(&s);
    /* segments, the loop and the closed strip: the same outline */
    TEST_ASSERT_GREATER_THAN(20, covered(px[0]));
    TEST_ASSERT_EQUAL_MEMORY(px[0], px[1], sizeof px[0]);
    TEST_ASSERT_EQUAL_MEMORY(px[0], px[2], sizeof px[0]);
    TEST_ASSERT_EQUAL_MEMORY(px[4], px[5], sizeof px[4]);
    TEST_ASSERT_EQUAL(4, covered(px[4]));
    int open = 0;
    for (int i = 0; i < W * H; i++) {
        const uint8_t *p = &px[0][4 * i];
        if (p[0] || p[1] || p[2]) {             /* lit: the material colour */
            TEST_ASSERT_EQUAL_UINT8(0, p[0]);
            TEST_ASSERT_EQUAL_UINT8(255, p[1]);
            TEST_ASSERT_EQUAL_UINT8(0, p[2]);
        }
        /* the open strip and the corners lie on the outline */
        TEST_ASSERT_TRUE(!px[3][4 * i + 1] || p[1]);
        TEST_ASSERT_TRUE(!px[4][4 * i + 1] || p[1]);
        open += px[3][4 * i + 1] != 0;
    }
    TEST_ASSERT_TRUE(open > 0 && open < covered(px[0]));
    TEST_ASSERT_EQUAL(live_before, mote__io_live_allocations());
}

void quantized_positions_should_land_where_float_ones_do(void)
{
    mote_scene s, q;
    load("quad.gltf", &s);
    load("quantized.gltf", &q);
    const mote_mesh *a = drawn_mesh(&s, 0), *b = drawn_mesh(&q, 0);
    for (int v = 0; v < 4; v++) {
        float pa[3], pb[3];
        world_point(a, a->vertices[v].position, pa);
        world_point(b, b->vertices[v].position, pb);
        ASSERT_VEC3(pa[0], pa[1], pa[2], pb, 1e-6f);
        ASSERT_VEC3(0.0f, 0.0f, -1.0f, b->vertices[v].normal, 0.0f);
        TEST_ASSERT_FLOAT_WITHIN(1.0f / 255, a->vertices[v].uv[0], b->vertices[v].uv[0]);
        TEST_ASSERT_FLOAT_WITHIN(1.0f / 255, a->vertices[v].uv[1], b->vertices[v].uv[1]);
    }
    mote_scene_free(&s);
    mote_scene_free(&q);
    TEST_ASSERT_EQUAL(live_before, mote__io_live_allocations());
}

void sparse_values_should_replace_those_of_the_view_or_zeros(void)
{
    mote_scene s;
    load("sparse.gltf", &s);
    const mote_mesh *m = drawn_mesh(&s, 0);
    ASSERT_VEC3(0.5f, -0.5f, 0.0f, m->vertices[1].position, 0.0f);
    ASSERT_VEC3(1.0f, 1.0f, 0.0f, m->vertices[2].position, 0.0f);
    for (int v = 0; v < 4; v++)
        ASSERT_VEC3(0.0f, 0.0f, -1.0f, m->vertices[v].normal, 0.0f);
    mote_scene_free(&s);
    TEST_ASSERT_EQUAL(live_before, mote__io_live_allocations());
}

/* The specification's flat normals: each triangle its own vertices, all
 * three with the normal of its plane (outward, by its winding). */
void a_primitive_without_normals_should_get_flat_ones(void)
{
    mote_scene s;
    load("flat.gltf", &s);
    const mote_mesh *m = drawn_mesh(&s, 0);
    TEST_ASSERT_EQUAL_UINT32(6, m->vertex_count);
    TEST_ASSERT_EQUAL_UINT32(6, m->index_count);
    for (int t = 0; t < 2; t++) {
        const mote_vertex *v = &m->vertices[3 * t];
        float e1[3], e2[3];
        for (int k = 0; k < 3; k++) {
            e1[k] = v[1].position[k] - v[0].position[k];
            e2[k] = v[2].position[k] - v[0].position[k];
        }
        const float *n = v[0].normal;
        TEST_ASSERT_FLOAT_WITHIN(1e-6f, 0.0f, n[0] * e1[0] + n[1] * e1[1] + n[2] * e1[2]);
        TEST_ASSERT_FLOAT_WITHIN(1e-6f, 0.0f, n[0] * e2[0] + n[1] * e2[1] + n[2] * e2[2]);
        TEST_ASSERT_FLOAT_WITHIN(1e-6f, 1.0f, n[0] * n[0] + n[1] * n[1] + n[2] * n[2]);
        TEST_ASSERT_TRUE(n[1] > 0.0f);                /* the tent's sides face up */
        ASSERT_VEC3(n[0], n[1], n[2], v[2].normal, 0.0f);
    }
    mote_scene_free(&s);
    TEST_ASSERT_EQUAL(live_before, mote__io_live_allocations());
}

/* ---- materials --------------------------------------------------------- */

/* OPAQUE as is, MASK an alpha test at its cut-off over the base colour's
 * alpha, BLEND a blend by that alpha; an untextured MASK material under
 * its cut-off is not drawn (the core cuts only texels). */

/* The start of a glTF file whose one node draws a triangle of three
 * zero positions (its mesh and materials follow). */
#define ONE_TRIANGLE                                                                                 \
    "{\"asset\":{\"version\":\"2.0\"},\"scenes\":[{\"nodes\":[0]}],\"nodes\":[{\"mesh\":0}],"                \
    "\"buffers\":[{\"byteLength\":36,\"uri\":\"data:application/octet-stream;base64,"                  \
    "AAAAAAAAAAAAAAAAAAAAAAAAAAAAAAAAAAAAAAAAAAAAAAAA\"}],\"bufferViews\":[{\"buffer\":0,"                \
    "\"byteLength\":36}],\"accessors\":[{\"bufferView\":0,\"componentType\":5126,"                     \
    "\"count\":3,\"type\":\"VEC3\"}],"

void alpha_modes_should_map_onto_the_alpha_test_and_blending(void)
{
    mote_scene s;
    load("alpha.gltf", &s);
    TEST_ASSERT_EQUAL(3, s.mesh_count);
    TEST_ASSERT_EQUAL_STRING("", s.warning);
    const mote_material *o = &s.meshes[0].material, *t = &s.meshes[1].material,
                        *b = &s.meshes[2].material;
    TEST_ASSERT_EQUAL(MOTE_ALPHA_OPAQUE, o->alpha_mode);
    TEST_ASSERT_EQUAL(MOTE_ALPHA_TEST, t->alpha_mode);
    TEST_ASSERT_EQUAL_FLOAT(0.25f, t->alpha_cutoff);
    TEST_ASSERT_FALSE(s.meshes[1].hidden);
    TEST_ASSERT_EQUAL(MOTE_ALPHA_BLEND, b->alpha_mode);
    TEST_ASSERT_TRUE(b->alpha_set);
    TEST_ASSERT_EQUAL_FLOAT(0.5f, b->alpha);
    TEST_ASSERT_FALSE(b->use_texture_alpha);
    TEST_ASSERT_EQUAL_UINT8(0, b->color.r);
    TEST_ASSERT_EQUAL_UINT8(255, b->color.b);
    /* the blue quad alone over the black clear colour: half as bright
     * blended as drawn opaque */
    static uint8_t blended[W * H * 4], opaque[W * H * 4];
    s.meshes[0].hidden = s.meshes[1].hidden = true;
    render(&s, blended);
    s.meshes[2].material.alpha_mode = MOTE_ALPHA_OPAQUE;
    render(&s, opaque);
    const int centre = 4 * (W * (H / 2) + W / 2) + 2;
    TEST_ASSERT_GREATER_THAN(100, opaque[centre]);
    TEST_ASSERT_INT_WITHIN(2, (opaque[centre] + 1) / 2, blended[centre]);
    mote_scene_free(&s);

    /* a = 0.8: the texel cut-off is 0.5 / 0.8; a = 0.2, untextured: cut whole */
    static const char mask[] =
        ONE_TRIANGLE
        "\"meshes\":[{\"primitives\":[{\"attributes\":{\"POSITION\":0},\"material\":0},"
        "{\"attributes\":{\"POSITION\":0},\"material\":1}]}],\"materials\":[{\"alphaMode\":\"MASK\","
        "\"pbrMetallicRoughness\":{\"baseColorFactor\":[1,1,1,0.8]}},{\"alphaMode\":\"MASK\","
        "\"pbrMetallicRoughness\":{\"baseColorFactor\":[1,1,1,0.2]}}]}";
    io_load_json(mask, "mask.gltf", &s);
    TEST_ASSERT_EQUAL(2, s.mesh_count);
    TEST_ASSERT_FLOAT_WITHIN(1e-6f, 0.625f, s.meshes[0].material.alpha_cutoff);
    TEST_ASSERT_TRUE(s.meshes[1].hidden);
    mote_scene_free(&s);
    TEST_ASSERT_EQUAL(live_before, mote__io_live_allocations());
}

void an_emissive_texture_should_become_a_layer_and_min_filter_a_mip_mode(void)
{
    static const char j[] =
        ONE_TRIANGLE
        "\"meshes\":[{\"primitives\":[{\"attributes\":{\"POSITION\":0},\"material\":0}]}],"
        "\"images\":[{\"uri\":\"data:image/png;base64,iVBORw0KGgoAAAANSUhEUgAAAAIAAAACCAIAAAD91JpzAAAAEklEQVR4"
        "nGP4z8DAAMIM/4EAAB/uBfsL2WiLAAAAAElFTkSuQmCC\"}],\"samplers\":[{\"wrapS\":33071,\"minFilter\":9987}],"
        "\"textures\":[{\"source\":0,\"sampler\":0}],"
        "\"materials\":[{\"pbrMetallicRoughness\":{\"baseColorTexture\":{\"index\":0}},"
        "\"emissiveTexture\":{\"index\":0},\"emissiveFactor\":[1,0.5,0],"
        "\"extensions\":{\"KHR_materials_emissive_strength\":{\"emissiveStrength\":2}}}]}";
    mote_scene s;
    io_load_json_in(j, "glow.gltf", io_tmp_dir(), &s);
    const mote_material *m = &s.meshes[0].material;
    TEST_ASSERT_EQUAL(1, m->layer_count);
    TEST_ASSERT_EQUAL(MOTE_LAYER_EMISSIVE, m->layers[0].role);
    TEST_ASSERT_NOT_NULL(m->layers[0].texture);
    TEST_ASSERT_EQUAL(MOTE_WRAP_CLAMP, m->layers[0].wrap_u);
    /* the factor sRGB-encoded as the texture: 2 -> 2^(1/2.2), 1 -> 1 */
    TEST_ASSERT_FLOAT_WITHIN(1e-4f, 1.3703f, m->layers[0].factor[0]);
    TEST_ASSERT_FLOAT_WITHIN(1e-6f, 1.0f, m->layers[0].factor[1]);
    TEST_ASSERT_TRUE(m->layers[0].factor[2] < 1e-5f);
    /* LINEAR_MIPMAP_LINEAR: trilinear, unless the draw says otherwise */
    TEST_ASSERT_NOT_NULL(s.mip_modes);
    TEST_ASSERT_EQUAL(MOTE_MIP_TRILINEAR, s.mip_modes[0]);
    mote_draw_desc d;
    mote_scene_draw_desc(&s, 0, NULL, &d);
    TEST_ASSERT_EQUAL(MOTE_MIP_TRILINEAR, d.mip);
    const mote_draw_desc none = {.mip = MOTE_MIP_NONE};
    mote_scene_draw_desc(&s, 0, &none, &d);
    TEST_ASSERT_EQUAL(MOTE_MIP_NONE, d.mip);
    /* the texture's light instead of the constant's */
    TEST_ASSERT_EQUAL_UINT8(0, m->emissive.r);
    TEST_ASSERT_EQUAL_STRING("", s.warning);
    mote_scene_free(&s);
    TEST_ASSERT_EQUAL(live_before, mote__io_live_allocations());
}

void metallic_roughness_should_be_approximated_as_the_babylon_loader_does(void)
{
    /* the same function as a .babylon PBR material: colour base x (1 - m),
     * highlights 0.04 (1 - m) + base m, power 2 / roughness^4 - 2 */
    static const char j[] =
        ONE_TRIANGLE
        "\"meshes\":[{\"primitives\":[{\"attributes\":{\"POSITION\":0},\"material\":0},"
        "{\"attributes\":{\"POSITION\":0},\"material\":1},{\"attributes\":{\"POSITION\":0},\"material\":2}]}],"
        "\"materials\":[{\"pbrMetallicRoughness\":{\"baseColorFactor\":[1,1,0,1],\"metallicFactor\":1,"
        "\"roughnessFactor\":0.5}},{},{\"pbrMetallicRoughness\":{\"metallicFactor\":1,"
        "\"metallicRoughnessTexture\":{\"index\":0}}}]}";
    mote_scene s;
    io_load_json(j, "pbr.gltf", &s);
    TEST_ASSERT_EQUAL(3, s.mesh_count);
    const mote_material *metal = &s.meshes[0].material, *plain = &s.meshes[1].material;
    TEST_ASSERT_EQUAL_UINT8(0, metal->color.r);
    TEST_ASSERT_EQUAL_UINT8(255, metal->specular.r);
    TEST_ASSERT_EQUAL_UINT8(255, metal->specular.g);
    TEST_ASSERT_EQUAL_UINT8(0, metal->specular.b);
    TEST_ASSERT_FLOAT_WITHIN(1e-3f, 30.0f, metal->specular_power);
    /* unsaid: metallic 0 (not the specification's 1: without an
     * environment a metal is black but for its highlights), roughness 1 */
    TEST_ASSERT_EQUAL_UINT8(255, plain->color.g);
    TEST_ASSERT_EQUAL_UINT8(10, plain->specular.g);
    TEST_ASSERT_FLOAT_WITHIN(1e-6f, 1.0f, plain->specular_power);
    /* a metallic factor that scales an unread texture: metallic 0 */
    TEST_ASSERT_EQUAL_UINT8(255, s.meshes[2].material.color.r);
    mote_scene_free(&s);
    TEST_ASSERT_EQUAL(live_before, mote__io_live_allocations());
}

void materials_should_map_unlit_emissive_two_sided_and_texture_transforms(void)
{
    mote_scene s;
    load("materials.gltf", &s);
    TEST_ASSERT_NOT_NULL_MESSAGE(strstr(s.warning, "\"EXT_mote_unknown\" is not read"),
                                 s.warning);
    /* linear factors as sRGB bytes: 0.5 -> 188 */
    TEST_ASSERT_TRUE(s.unlit[0]);
    TEST_ASSERT_EQUAL_UINT8(188, s.meshes[0].material.color.r);
    TEST_ASSERT_NOT_NULL(s.meshes[0].colors);
    TEST_ASSERT_EQUAL_UINT8(255, s.meshes[0].colors[0].r);
    TEST_ASSERT_EQUAL_UINT8(0, s.meshes[0].colors[0].g);
    TEST_ASSERT_EQUAL_UINT8(255, s.meshes[0].colors[1].g);
    /* normalized unsigned bytes: 128 / 255 linear -> 188 */
    TEST_ASSERT_EQUAL_UINT8(188, s.meshes[1].colors[3].r);
    /* emissive (1, 0.5, 0) x strength 0.5 */
    TEST_ASSERT_FALSE(s.unlit[1]);
    TEST_ASSERT_EQUAL_UINT8(188, s.meshes[1].material.emissive.r);
    TEST_ASSERT_EQUAL_UINT8(137, s.meshes[1].material.emissive.g);
    TEST_ASSERT_EQUAL_UINT8(0, s.meshes[1].material.emissive.b);
    /* doubleSided; offset (0.5, 0), rotation pi/2, scale (2, 1) baked in
     * the uvs: (0, 0) -> (0.5, 0), (1, 1) -> (1.5, -2) */
    const mote_mesh *m = &s.meshes[2];
    TEST_ASSERT_TRUE(s.two_sided[2]);
    TEST_ASSERT_FALSE(s.two_sided[1]);
    TEST_ASSERT_NOT_NULL(m->material.texture);
    TEST_ASSERT_EQUAL(MOTE_WRAP_MIRROR, m->material.wrap_u);
    TEST_ASSERT_EQUAL(MOTE_WRAP_CLAMP, m->material.wrap_v);
    TEST_ASSERT_FLOAT_WITHIN(1e-6f, 0.5f, m->vertices[3].uv[0]);
    TEST_ASSERT_FLOAT_WITHIN(1e-6f, 0.0f, m->vertices[3].uv[1]);
    TEST_ASSERT_FLOAT_WITHIN(1e-6f, 1.5f, m->vertices[1].uv[0]);
    TEST_ASSERT_FLOAT_WITHIN(1e-6f, -2.0f, m->vertices[1].uv[1]);
    /* the transform's texCoord 1 over the texture's 0: TEXCOORD_1 x 2 */
    static const float uv1[8] = {0.25f, 0.5f, 0.5f, 0.5f, 0.5f, 0.25f, 0.25f, 0.25f};
    for (int v = 0; v < 4; v++) {
        TEST_ASSERT_FLOAT_WITHIN(1e-6f, 2.0f * uv1[2 * v], s.meshes[3].vertices[v].uv[0]);
        TEST_ASSERT_FLOAT_WITHIN(1e-6f, 2.0f * uv1[2 * v + 1], s.meshes[3].vertices[v].uv[1]);
    }
    mote_draw_desc d;
    mote_scene_draw_desc(&s, 2, NULL, &d);
    TEST_ASSERT_EQUAL(MOTE_CULL_NONE, d.cull);
    mote_scene_draw_desc(&s, 0, NULL, &d);
    TEST_ASSERT_TRUE(d.unlit);
    mote_scene_free(&s);
    TEST_ASSERT_EQUAL(live_before, mote__io_live_allocations());
}

/* ---- nodes, cameras, lights -------------------------------------------- */

void nodes_should_chain_translation_rotation_scale_and_matrices(void)
{
    mote_scene s;
    load("camera_light.gltf", &s);
    /* the child's (0.5, 0.5, 0): x2 and up 1 by its matrix -> (1, 1.5, 0);
     * a quarter turn about y -> (0, 1.5, -1); moved by (1, 2, 3) ->
     * (1, 3.5, 2), which is (1, 3.5, -2) mirrored */
    const mote_mesh *child = drawn_mesh(&s, 1);
    TEST_ASSERT_NOT_NULL(child->parent);
    float p[3];
    world_point(child, child->vertices[2].position, p);
    ASSERT_VEC3(1.0f, 3.5f, -2.0f, p, 1e-5f);
    mote_scene_free(&s);
    TEST_ASSERT_EQUAL(live_before, mote__io_live_allocations());
}

void the_first_camera_of_the_scene_should_be_the_view(void)
{
    mote_scene s;
    load("camera_light.gltf", &s);
    TEST_ASSERT_TRUE(s.has_camera);
    TEST_ASSERT_FALSE(s.camera_fov_is_horizontal);
    TEST_ASSERT_EQUAL(MOTE_PROJECTION_PERSPECTIVE, s.camera.projection);
    ASSERT_VEC3(0.0f, 0.0f, -5.0f, s.camera.position, 1e-6f);
    ASSERT_VEC3(0.0f, 0.0f, -4.0f, s.camera.target, 1e-6f);
    ASSERT_VEC3(0.0f, 1.0f, 0.0f, s.camera.up, 1e-6f);
    TEST_ASSERT_EQUAL_FLOAT(0.8f, s.camera.fov);
    TEST_ASSERT_EQUAL_FLOAT(0.1f, s.camera.znear);
    TEST_ASSERT_EQUAL_FLOAT(100.0f, s.camera.zfar);
    mote_scene_free(&s);

    static const char ortho[] =
        "{\"asset\":{\"version\":\"2.0\"},\"scenes\":[{\"nodes\":[0]}],\"nodes\":[{\"camera\":0,"
        "\"translation\":[0,0,3]}],\"cameras\":[{\"type\":\"orthographic\",\"orthographic\":"
        "{\"xmag\":2,\"ymag\":1.5,\"znear\":0,\"zfar\":10}}]}";
    io_load_json(ortho, "o.gltf", &s);
    TEST_ASSERT_EQUAL(MOTE_PROJECTION_ORTHOGRAPHIC, s.camera.projection);
    TEST_ASSERT_EQUAL_FLOAT(-2.0f, s.camera.ortho[0]);
    TEST_ASSERT_EQUAL_FLOAT(1.5f, s.camera.ortho[3]);
    TEST_ASSERT_EQUAL_FLOAT(0.0f, s.camera.znear);
    mote_scene_free(&s);
    TEST_ASSERT_EQUAL(live_before, mote__io_live_allocations());
}

void punctual_lights_should_be_placed_by_their_nodes(void)
{
    mote_scene s;
    load("camera_light.gltf", &s);
    TEST_ASSERT_TRUE(s.has_lights);
    TEST_ASSERT_EQUAL(3, s.light_count);
    const mote_light *d = &s.lights[0], *p = &s.lights[1], *sp = &s.lights[2];
    TEST_ASSERT_EQUAL(MOTE_LIGHT_DIRECTIONAL, d->type);
    ASSERT_VEC3(0.0f, -1.0f, 0.0f, d->direction, 1e-6f);   /* -z turned down */
    ASSERT_VEC3(1.0f, 0.5f, 0.25f, d->color, 0.0f);
    TEST_ASSERT_EQUAL_FLOAT(2.0f, d->intensity);
    TEST_ASSERT_EQUAL(MOTE_LIGHT_POINT, p->type);
    ASSERT_VEC3(0.0f, 5.0f, 0.0f, p->position, 0.0f);
    TEST_ASSERT_EQUAL_FLOAT(20.0f, p->range);
    /* candela over the squared distance to the scene's centre */
    float c[3], d2 = 0.0f;
    for (int k = 0; k < 3; k++) {
        c[k] = 0.5f * (s.bounds_min[k] + s.bounds_max[k]) - p->position[k];
        d2 += c[k] * c[k];
    }
    TEST_ASSERT_FLOAT_WITHIN(1e-3f, 50.0f / d2, p->intensity);
    TEST_ASSERT_EQUAL(MOTE_LIGHT_SPOT, sp->type);
    ASSERT_VEC3(0.0f, 0.0f, -4.0f, sp->position, 0.0f);
    ASSERT_VEC3(0.0f, 0.0f, 1.0f, sp->direction, 0.0f);
    TEST_ASSERT_FLOAT_WITHIN(1e-6f, 1.2f, sp->spot_angle);
    TEST_ASSERT_FLOAT_WITHIN(1e-4f, (float)(log(0.5) / log(cos(0.4))), sp->spot_exponent);
    mote_scene_free(&s);
    TEST_ASSERT_EQUAL(live_before, mote__io_live_allocations());
}

/* Without KHR_lights_punctual lights in the scene, mote_scene_frame lights
 * it as a viewer would: a white headlight at the camera, raised by the
 * radius of the sphere around the scene (the quad's: half its
 * diagonal). A file whose lights are all off is drawn dark, as it says. */
void a_scene_without_lights_should_get_a_headlight(void)
{
    mote_scene s;
    load("quad.gltf", &s);
    TEST_ASSERT_FALSE(s.has_lights);
    TEST_ASSERT_EQUAL(0, s.light_count);
    mote_frame_desc f;
    mote_scene_frame(&s, (float)W / (float)H, &f);
    TEST_ASSERT_EQUAL(1, f.light_count);
    const mote_light *l = &f.lights[0];
    TEST_ASSERT_EQUAL(MOTE_LIGHT_POINT, l->type);
    ASSERT_VEC3(f.camera.position[0], f.camera.position[1] + sqrtf(0.5f), f.camera.position[2],
                l->position, 1e-5f);
    ASSERT_VEC3(1.0f, 1.0f, 1.0f, l->color, 0.0f);
    TEST_ASSERT_EQUAL_FLOAT(1.0f, l->intensity);
    mote_scene_free(&s);

    static const char dark[] =
        "{\"asset\":{\"version\":\"2.0\"},\"extensionsUsed\":[\"KHR_lights_punctual\"],"
        "\"extensions\":{\"KHR_lights_punctual\":{\"lights\":[{\"type\":\"point\","
        "\"intensity\":0}]}},\"scenes\":[{\"nodes\":[0]}],\"nodes\":[{\"extensions\":"
        "{\"KHR_lights_punctual\":{\"light\":0}}}]}";
    io_load_json(dark, "dark.gltf", &s);
    TEST_ASSERT_TRUE(s.has_lights);
    TEST_ASSERT_EQUAL(0, s.light_count);
    mote_scene_frame(&s, (float)W / (float)H, &f);
    TEST_ASSERT_EQUAL(0, f.light_count);
    mote_scene_free(&s);
    TEST_ASSERT_EQUAL(live_before, mote__io_live_allocations());
}

/* ---- the demo scene and out of memory ---------------------------------- */

void the_demo_should_draw_and_fail_cleanly_on_every_allocation(void)
{
    mote_scene s;
    static uint8_t pixels[W * H * 4];
    load("demo.glb", &s);
    TEST_ASSERT_EQUAL_STRING("", s.warning);
    TEST_ASSERT_EQUAL(1, s.texture_count);
    render(&s, pixels);
    TEST_ASSERT_GREATER_THAN(W * H / 2, covered(pixels));
    mote_scene_free(&s);
    bool loaded = false;
    for (int n = 0; n < 400 && !loaded; n++) {
        mote__io_set_alloc_failure_after(n);
        mote_result r = mote_scene_load(gpath("demo.glb"), NULL, &s, msg, sizeof msg);
        mote__io_set_alloc_failure_after(-1);
        if (r == MOTE_OK) {
            loaded = true;
            mote_scene_free(&s);
        } else {
            TEST_ASSERT_EQUAL_MESSAGE(MOTE_ERR_OUT_OF_MEMORY, r, msg);
        }
        TEST_ASSERT_EQUAL(live_before, mote__io_live_allocations());
    }
    TEST_ASSERT_TRUE(loaded);
}

int main(void)
{
    UNITY_BEGIN();
    RUN_TEST(the_quad_should_load_alike_from_a_bin_file_a_data_uri_and_a_glb);
    RUN_TEST(a_texture_should_load_from_a_file_a_data_uri_and_a_buffer_view);
    RUN_TEST(a_buffer_file_should_need_a_folder);
    RUN_TEST(strips_and_fans_should_draw_the_quad_as_triangles_do);
    RUN_TEST(lines_and_points_should_draw_in_the_wireframe_and_points_modes);
    RUN_TEST(quantized_positions_should_land_where_float_ones_do);
    RUN_TEST(sparse_values_should_replace_those_of_the_view_or_zeros);
    RUN_TEST(a_primitive_without_normals_should_get_flat_ones);
    RUN_TEST(alpha_modes_should_map_onto_the_alpha_test_and_blending);
    RUN_TEST(materials_should_map_unlit_emissive_two_sided_and_texture_transforms);
    RUN_TEST(an_emissive_texture_should_become_a_layer_and_min_filter_a_mip_mode);
    RUN_TEST(metallic_roughness_should_be_approximated_as_the_babylon_loader_does);
    RUN_TEST(nodes_should_chain_translation_rotation_scale_and_matrices);
    RUN_TEST(the_first_camera_of_the_scene_should_be_the_view);
    RUN_TEST(punctual_lights_should_be_placed_by_their_nodes);
    RUN_TEST(a_scene_without_lights_should_get_a_headlight);
    RUN_TEST(the_demo_should_draw_and_fail_cleanly_on_every_allocation);
    return UNITY_END();
}
