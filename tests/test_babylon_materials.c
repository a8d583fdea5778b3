/*
 * test_babylon_materials.c - a .babylon file's materials and their textures
 * (src/io/babylon_material.c, src/io/scene_texture.c): ids and uniqueIds,
 * multi-materials, PBR colours, embedded and URL-named textures, culling
 * and lighting flags, uvs2.
 */
#define _POSIX_C_SOURCE 200809L /* mkdir */
#include "support/io_test.h"

#include <sys/stat.h>

static char msg[512];
static long live_before;

void setUp(void)
{
    msg[0] = '\0';
    live_before = io_test_begin();
}

void tearDown(void) {}

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
    io_load_json(j, "v", &s);
    TEST_ASSERT_EQUAL(5, s.mesh_count);
    TEST_ASSERT_TRUE(s.meshes[0].material.v_origin_bottom);
    TEST_ASSERT_FALSE(s.meshes[1].material.v_origin_bottom);
    TEST_ASSERT_TRUE(s.meshes[2].material.v_origin_bottom);   /* current layout */
    TEST_ASSERT_FALSE(s.meshes[3].material.v_origin_bottom);  /* legacy layout */
    TEST_ASSERT_TRUE(s.meshes[4].material.v_origin_bottom);   /* legacy, said */
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
    io_load_json(j, "u", &s);
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
    io_load_json(j, "mu", &s);
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
    io_load_json(j, "ct", &s);
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
    io_load_json_in(j, "noname", DATA(""), &s);
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
    io_load_json_in(j, "mr", DATA(""), &s);
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
    io_load_json(j, "b", &s);
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
    io_begin_small_frame(&dev, color, 16);
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
    io_load_json(j, "side", &s);
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
    io_begin_small_frame(&dev, color, 16);
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
    io_load_json(rh, "side_rh", &s);
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
    io_load_json(j, "u", &s);
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
        io_begin_small_frame(&dev, color, 16);
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

void loader_should_load_a_texture_once_for_two_materials(void)
{
    uint8_t px[2 * 2 * 4] = {255, 0, 0, 255, 0, 255, 0, 255, 0, 0, 255, 255, 9, 9, 9, 255};
    char sub[300];
    snprintf(sub, sizeof sub, "%s/tex", io_tmp_dir());
    mkdir(sub, 0700);
    TEST_ASSERT_EQUAL(MOTE_OK, mote_write_rgba(io_tmp_path("tex/a.png"), px, 2, 2, 0, msg, sizeof msg));
    const char *j = "{\"materials\":["
                    "{\"id\":\"m1\",\"diffuseTexture\":{\"name\":\"tex/a.png\",\"wrapU\":0,"
                    "\"wrapV\":2,\"uScale\":2,\"vScale\":3,\"uOffset\":0.25,\"vOffset\":0.5}},"
                    "{\"id\":\"m2\",\"albedoTexture\":{\"name\":\"tex\\\\a.png\",\"wrapU\":false}}],"
                    "\"meshes\":[{\"id\":\"a\",\"materialId\":\"m1\",\"positions\":[0,0,0],\"indices\":[]},"
                    "{\"id\":\"b\",\"materialId\":\"m2\"}]}";
    mote_scene s;
    io_load_json_in(j, "t", io_tmp_dir(), &s);
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

/* A texture name written as a URL: when no file has the name as written,
 * the file named by it decoded, without its "?query", is loaded (once).
 * Invalid escapes and %00 are not decoded, and a decoded name is held to
 * the scene's folder as any other. */
void loader_should_read_a_url_encoded_texture_name_as_the_decoded_file(void)
{
    uint8_t px[4] = {1, 2, 3, 255};
    char sub[300];
    snprintf(sub, sizeof sub, "%s/my dir", io_tmp_dir());
    mkdir(sub, 0700);
    TEST_ASSERT_EQUAL(MOTE_OK, mote_write_rgba(io_tmp_path("my dir/a b.png"), px, 1, 1, 0, msg,
                                               sizeof msg));
    const char *j = "{\"materials\":["
                    "{\"id\":\"m1\",\"diffuseTexture\":{\"name\":\"my%20dir/a%20b.png?v=2\"}},"
                    "{\"id\":\"m2\",\"diffuseTexture\":{\"name\":\"my dir/a b.png?x\"}},"
                    "{\"id\":\"m3\",\"diffuseTexture\":{\"name\":\"my dir/a b.png\"}}],"
                    "\"meshes\":[{\"id\":\"a\",\"materialId\":\"m1\"},"
                    "{\"id\":\"b\",\"materialId\":\"m2\"},{\"id\":\"c\",\"materialId\":\"m3\"}]}";
    mote_scene s;
    io_load_json_in(j, "u", io_tmp_dir(), &s);
    TEST_ASSERT_EQUAL(1, s.texture_count);
    for (int k = 0; k < 3; k++)
        TEST_ASSERT_EQUAL_PTR(&s.textures[0], s.meshes[k].material.texture);
    TEST_ASSERT_EQUAL_UINT8_ARRAY(px, s.textures[0].pixels, sizeof px);
    mote_scene_free(&s);
    /* not decoded, from the folder "my dir" (files "a b.png" in it and
     * above it): %00, a decoded name leaving the folder, invalid escapes */
    TEST_ASSERT_EQUAL(MOTE_OK, mote_write_rgba(io_tmp_path("a b.png"), px, 1, 1, 0, msg,
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

int main(void)
{
    UNITY_BEGIN();
    RUN_TEST(loader_should_take_the_texture_row_of_v0_from_invert_y);
    RUN_TEST(loader_should_load_a_texture_once_for_two_materials);
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
    RUN_TEST(loader_should_read_a_url_encoded_texture_name_as_the_decoded_file);
    return UNITY_END();
}
