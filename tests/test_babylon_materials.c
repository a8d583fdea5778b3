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

/* Loads a scene file of tests/data, which must load without a warning. */
static void load_quiet_scene(const char *path, mote_scene *s)
{
    char message[256] = "";
    TEST_ASSERT_EQUAL_MESSAGE(MOTE_OK, mote_scene_load(path, NULL, s, message, sizeof message), message);
    TEST_ASSERT_EQUAL_STRING_MESSAGE("", s->warning, path);
}

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

void loader_should_read_emissive_opacity_and_specular_textures_as_layers(void)
{
    uint8_t px[2 * 2 * 4] = {255, 0, 0, 255, 0, 255, 0, 128, 0, 0, 255, 255, 9, 9, 9, 0};
    TEST_ASSERT_EQUAL(MOTE_OK, mote_write_rgba(io_tmp_path("glow.png"), px, 2, 2, 0, msg, sizeof msg));
    const char *j = "{\"materials\":["
                    "{\"id\":\"m\",\"diffuseTexture\":{\"name\":\"glow.png\"},"
                    "\"emissiveTexture\":{\"name\":\"glow.png\",\"uScale\":2,\"level\":0.5},"
                    "\"opacityTexture\":{\"name\":\"glow.png\",\"getAlphaFromRGB\":true,\"wrapU\":0},"
                    "\"specularTexture\":{\"name\":\"glow.png\",\"coordinatesIndex\":1}}],"
                    "\"meshes\":[{\"id\":\"a\",\"materialId\":\"m\",\"positions\":[0,0,0],\"indices\":[]}]}";
    mote_scene s;
    io_load_json_in(j, "t", io_tmp_dir(), &s);
    const mote_material *m = &s.meshes[0].material;
    TEST_ASSERT_EQUAL(3, m->layer_count);
    TEST_ASSERT_EQUAL(MOTE_LAYER_EMISSIVE, m->layers[0].role);
    TEST_ASSERT_EQUAL_FLOAT(2.0f, m->layers[0].u_scale);
    TEST_ASSERT_EQUAL_FLOAT(0.5f, m->layers[0].factor[1]);
    TEST_ASSERT_EQUAL(MOTE_LAYER_OPACITY, m->layers[1].role);
    TEST_ASSERT_TRUE(m->layers[1].from_rgb);
    TEST_ASSERT_EQUAL(MOTE_WRAP_CLAMP, m->layers[1].wrap_u);
    TEST_ASSERT_EQUAL(MOTE_LAYER_SPECULAR, m->layers[2].role);
    TEST_ASSERT_EQUAL_PTR(m->texture, m->layers[2].texture);
    /* an opacity map blends; the specular map's colour is the map's */
    TEST_ASSERT_EQUAL(MOTE_ALPHA_BLEND, m->alpha_mode);
    TEST_ASSERT_EQUAL_UINT8(255, m->specular.g);
    /* only the specular map's other uv set is warned */
    TEST_ASSERT_EQUAL(1, mote_scene_warning_count(&s, NULL));
    TEST_ASSERT_NOT_NULL(strstr(mote_scene_warning(&s, 0, NULL), "specularTexture.coordinatesIndex"));
    mote_scene_free(&s);
    TEST_ASSERT_EQUAL(live_before, mote__io_live_allocations());
}

void a_floor_scene_should_load_its_emissive_maps_without_a_warning(void)
{
    mote_scene s;
    load_quiet_scene(DATA("floor.babylon"), &s);
    TEST_ASSERT_EQUAL(MOTE_FOG_NONE, s.fog.mode);
    TEST_ASSERT_EQUAL(0, s.meshes[0].material.layer_count);   /* the floor */
    TEST_ASSERT_EQUAL(1, s.meshes[1].material.layer_count);   /* a glowing box */
    TEST_ASSERT_EQUAL(MOTE_LAYER_EMISSIVE, s.meshes[1].material.layers[0].role);
    TEST_ASSERT_EQUAL_FLOAT(0.6f, s.meshes[1].material.layers[0].factor[0]);
    /* drawn through every layer path without fault (sanitizer builds) */
    enum { SW = 96, SH = 64 };
    static uint8_t img[SW * SH * 4];
    io_render_scene(&s, img, SW, SH);
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

/* Transparency as Babylon.js's StandardMaterial decides it: alpha < 1
 * blends, else a texture with hasAlpha is cut at alphaCutOff (0.4
 * unsaid), and transparencyMode, when written, says which of the two (or
 * both). */
void loader_should_read_transparency_as_babylon_decides_it(void)
{
    const uint8_t px[4 * 4] = {255, 0, 0, 0, 0, 255, 0, 100, 0, 0, 255, 200, 255, 255, 255, 255};
    TEST_ASSERT_EQUAL(MOTE_OK, mote_write_rgba(io_tmp_path("alpha.png"), px, 2, 2, 0, msg, sizeof msg));
    const char *j =
        "{\"materials\":["
        "{\"id\":\"glass\",\"alpha\":0.25,\"disableDepthWrite\":true},"
        "{\"id\":\"leaf\",\"diffuseTexture\":{\"name\":\"alpha.png\",\"hasAlpha\":true},\"alphaCutOff\":0.6},"
        "{\"id\":\"both\",\"alpha\":0.5,\"diffuseTexture\":{\"name\":\"alpha.png\",\"hasAlpha\":true},"
        "\"useAlphaFromDiffuseTexture\":true},"
        "{\"id\":\"opaque\",\"alpha\":0.5,\"transparencyMode\":0},"
        "{\"id\":\"blend\",\"diffuseTexture\":{\"name\":\"alpha.png\",\"hasAlpha\":true},"
        "\"transparencyMode\":2,\"alphaMode\":1},"
        "{\"id\":\"plain\",\"transparencyMode\":null},"
        "{\"id\":\"three\",\"diffuseTexture\":{\"name\":\"alpha.png\",\"hasAlpha\":true},\"transparencyMode\":3}],"
        "\"meshes\":["
        "{\"id\":\"a\",\"materialId\":\"glass\"," TRI "},"
        "{\"id\":\"b\",\"materialId\":\"leaf\"," TRI "},"
        "{\"id\":\"c\",\"materialId\":\"both\"," TRI "},"
        "{\"id\":\"d\",\"materialId\":\"opaque\"," TRI "},"
        "{\"id\":\"e\",\"materialId\":\"blend\"," TRI "},"
        "{\"id\":\"f\",\"materialId\":\"plain\"," TRI "},"
        "{\"id\":\"g\",\"materialId\":\"three\"," TRI "}]}";
    mote_scene s;
    io_load_json_in(j, "alpha", io_tmp_dir(), &s);
    TEST_ASSERT_EQUAL(7, s.mesh_count);
    TEST_ASSERT_EQUAL(MOTE_ALPHA_TEST_AND_BLEND, s.meshes[6].material.alpha_mode);
    const mote_material *m = &s.meshes[0].material;
    TEST_ASSERT_EQUAL(MOTE_ALPHA_BLEND, m->alpha_mode);
    TEST_ASSERT_FLOAT_WITHIN(1e-6f, 0.25f, m->alpha);
    TEST_ASSERT_TRUE(m->alpha_set);
    mote_draw_desc d;
    mote_scene_draw_desc(&s, 0, NULL, &d);
    TEST_ASSERT_TRUE(d.no_depth_write);
    mote_scene_draw_desc(&s, 1, NULL, &d);
    TEST_ASSERT_FALSE(d.no_depth_write);
    m = &s.meshes[1].material;
    TEST_ASSERT_EQUAL(MOTE_ALPHA_TEST, m->alpha_mode);
    TEST_ASSERT_FLOAT_WITHIN(1e-6f, 0.6f, m->alpha_cutoff);
    TEST_ASSERT_FALSE(m->use_texture_alpha);
    m = &s.meshes[2].material;
    TEST_ASSERT_EQUAL(MOTE_ALPHA_BLEND, m->alpha_mode);   /* no test while blending */
    TEST_ASSERT_TRUE(m->use_texture_alpha);
    TEST_ASSERT_FLOAT_WITHIN(1e-6f, 0.4f, m->alpha_cutoff);
    TEST_ASSERT_EQUAL(MOTE_ALPHA_OPAQUE, s.meshes[3].material.alpha_mode);
    TEST_ASSERT_EQUAL(MOTE_ALPHA_BLEND, s.meshes[4].material.alpha_mode);
    TEST_ASSERT_EQUAL(MOTE_ALPHA_OPAQUE, s.meshes[5].material.alpha_mode);
    TEST_ASSERT_NOT_NULL_MESSAGE(strstr(s.warning, "materials[4].alphaMode: 1 is drawn as 2"), s.warning);
    mote_scene_free(&s);
}

/* The draw order of a scene of six meshes for a camera at z on the z axis. */
static void assert_draw_order(const mote_scene *s, float z, const int want[6])
{
    mote_camera cam;
    memset(&cam, 0, sizeof cam);
    cam.position[2] = z;
    int order[6];
    TEST_ASSERT_EQUAL_INT(6, mote_scene_draw_order(s, s->meshes, &cam, order));
    TEST_ASSERT_EQUAL_INT_ARRAY(want, order, 6);
}

/* Opaque meshes first, then alpha-tested ones, in the file's order; then
 * the blended ones from the farthest to the nearest (bounding-sphere
 * centres, in world space), ties in the file's order. */
void draw_order_should_put_blended_meshes_last_from_back_to_front(void)
{
    const char *j =
        "{\"materials\":[{\"id\":\"glass\",\"alpha\":0.5},"
        "{\"id\":\"cut\",\"transparencyMode\":1}],"
        "\"meshes\":["
        "{\"id\":\"near\",\"materialId\":\"glass\",\"position\":[0,0,1]," TRI "},"
        "{\"id\":\"solid\"," TRI "},"
        "{\"id\":\"far\",\"materialId\":\"glass\",\"position\":[0,0,9]," TRI "},"
        "{\"id\":\"cutout\",\"materialId\":\"cut\"," TRI "},"
        "{\"id\":\"mid\",\"materialId\":\"glass\",\"position\":[0,0,5]," TRI "},"
        "{\"id\":\"mid2\",\"materialId\":\"glass\",\"position\":[0,0,5]," TRI "}]}";
    mote_scene s;
    io_load_json(j, "order", &s);
    const int want[6] = {1, 3, 2, 4, 5, 0};
    assert_draw_order(&s, -10.0f, want);
    /* the camera behind the far end turns the blended ones round */
    const int back[6] = {1, 3, 0, 4, 5, 2};
    assert_draw_order(&s, 20.0f, back);
    int order[6];
    TEST_ASSERT_EQUAL_INT(0, mote_scene_draw_order(&s, s.meshes, NULL, order));
    mote_scene_free(&s);
}

/* tests/data/transparency.babylon (tests/data/make_transparency.py): a
 * fence cut out of an embedded PNG's alpha and two glass boxes; it loads
 * without warnings, its glass is drawn last, and the cut-outs and glass
 * show what lies behind them. */
void a_scene_with_cut_outs_and_glass_should_show_what_lies_behind(void)
{
    mote_scene s;
    load_quiet_scene(DATA("transparency.babylon"), &s);
    TEST_ASSERT_EQUAL(4, s.mesh_count);
    TEST_ASSERT_EQUAL(MOTE_ALPHA_TEST, s.meshes[1].material.alpha_mode);
    TEST_ASSERT_EQUAL(MOTE_ALPHA_BLEND, s.meshes[2].material.alpha_mode);
    enum { SW = 160, SH = 120 };
    static uint8_t see_through[SW * SH * 4], solid[SW * SH * 4];
    io_render_scene(&s, see_through, SW, SH);
    for (int i = 0; i < s.mesh_count; i++)
        s.meshes[i].material.alpha_mode = MOTE_ALPHA_OPAQUE;
    io_render_scene(&s, solid, SW, SH);
    long sky_through = 0, sky_solid = 0, differ = 0;
    const mote_rgba sky = s.clear_color;
    for (int i = 0; i < SW * SH; i++) {
        sky_through += see_through[4 * i] == sky.r && see_through[4 * i + 1] == sky.g && see_through[4 * i + 2] == sky.b;
        sky_solid += solid[4 * i] == sky.r && solid[4 * i + 1] == sky.g && solid[4 * i + 2] == sky.b;
        differ += memcmp(&see_through[4 * i], &solid[4 * i], 3) != 0;
    }
    snprintf(msg, sizeof msg, "sky %ld through the fence, %ld without; %ld pixels differ", sky_through, sky_solid,
             differ);
    TEST_ASSERT_TRUE_MESSAGE(sky_through > sky_solid + 50 && differ > SW * SH / 20, msg);
    mote_scene_free(&s);
}

/* tests/data/fog.babylon (make_transparency.py --fog): linear fog, shiny
 * boxes, a light only for the floor and one the floor excludes; loads
 * without warnings, and its far floor fades into the fog colour. */
void a_fogged_scene_should_read_fog_highlights_and_light_lists(void)
{
    mote_scene s;
    load_quiet_scene(DATA("fog.babylon"), &s);
    TEST_ASSERT_EQUAL(MOTE_FOG_LINEAR, s.fog.mode);
    TEST_ASSERT_FLOAT_WITHIN(1e-6f, 40.0f, s.fog.end);
    TEST_ASSERT_EQUAL(3, s.light_count);
    TEST_ASSERT_NOT_NULL(s.lights_off);
    TEST_ASSERT_EQUAL_UINT32(1, s.lights_off[0]);   /* the floor: not the sky */
    TEST_ASSERT_EQUAL_UINT32(4, s.lights_off[1]);   /* a box: not the floor lamp */
    TEST_ASSERT_EQUAL_UINT8(255, s.meshes[1].material.specular.r);
    TEST_ASSERT_FLOAT_WITHIN(1e-6f, 24.0f, s.meshes[1].material.specular_power);
    TEST_ASSERT_EQUAL(0, s.meshes[0].material.specular.r | s.meshes[0].material.specular.g);
    TEST_ASSERT_NOT_NULL(s.meshes[0].material.mipmaps);   /* built at load */
    mote_frame_desc f;
    mote_scene_frame(&s, 1.0f, &f);
    TEST_ASSERT_EQUAL(MOTE_FOG_LINEAR, f.fog.mode);
    enum { SW = 96, SH = 96 };
    static uint8_t img[SW * SH * 4];
    io_render_scene(&s, img, SW, SH);
    /* the far floor is all fog: with a red fog, pure red (the file's fog
     * is the clear colour, so it would melt into the sky) */
    s.fog.color[0] = 1.0f;
    s.fog.color[1] = s.fog.color[2] = 0.0f;
    io_render_scene(&s, img, SW, SH);
    int red = 0;
    for (int y = 0; y < SH; y++) {
        const uint8_t *p = &img[(y * SW + SW / 2) * 4];
        red += p[0] == 255 && p[1] == 0 && p[2] == 0;
    }
    snprintf(msg, sizeof msg, "%d rows of pure fog in the middle column", red);
    TEST_ASSERT_TRUE_MESSAGE(red >= 2, msg);
    mote_scene_free(&s);
}

/* A mesh's alphaIndex orders the blended meshes before their distance,
 * the smaller first; unsaid, or Number.MAX_VALUE as the serialiser
 * writes it, they come after every one that says it. */
void draw_order_should_sort_blended_meshes_by_alpha_index_first(void)
{
    const char *j =
        "{\"materials\":[{\"id\":\"glass\",\"alpha\":0.5}],"
        "\"meshes\":["
        "{\"id\":\"near\",\"materialId\":\"glass\",\"alphaIndex\":0,\"position\":[0,0,1]," TRI "},"
        "{\"id\":\"far\",\"materialId\":\"glass\",\"position\":[0,0,9]," TRI "},"
        "{\"id\":\"mid\",\"materialId\":\"glass\",\"alphaIndex\":0,\"position\":[0,0,5]," TRI "},"
        "{\"id\":\"max\",\"materialId\":\"glass\",\"alphaIndex\":1.7976931348623157e308,\"position\":[0,0,7]," TRI "},"
        "{\"id\":\"first\",\"materialId\":\"glass\",\"alphaIndex\":-1.5,\"position\":[0,0,0]," TRI "},"
        "{\"id\":\"solid\"," TRI "}]}";
    mote_scene s;
    io_load_json(j, "alpha-index", &s);
    TEST_ASSERT_EQUAL_STRING("", s.warning);
    const int want[6] = {5, 4, 2, 0, 1, 3};
    assert_draw_order(&s, -10.0f, want);
    mote_scene_free(&s);
    /* a string is refused, with where */
    const char *bad = "{\"meshes\":[{\"id\":\"a\",\"alphaIndex\":\"front\"," TRI "}]}";
    TEST_ASSERT_NOT_EQUAL(MOTE_OK, mote_scene_load_memory(bad, strlen(bad), "bad", NULL, NULL, &s, msg, sizeof msg));
    TEST_ASSERT_NOT_NULL_MESSAGE(strstr(msg, "meshes[0].alphaIndex"), msg);
}

/* A mesh's applyFog false, or its material's fogEnabled false: the fog
 * leaves it alone (mote_draw_desc.no_fog); instances follow their mesh. */
void fog_should_leave_meshes_alone_that_turn_it_off(void)
{
    const char *j =
        "{\"fogMode\":3,\"fogStart\":1,\"fogEnd\":20,"
        "\"materials\":[{\"id\":\"clear\",\"fogEnabled\":false},{\"id\":\"plain\"}],"
        "\"meshes\":["
        "{\"id\":\"a\",\"materialId\":\"plain\"," TRI "},"
        "{\"id\":\"b\",\"materialId\":\"plain\",\"applyFog\":false," TRI ",\"instances\":[{\"name\":\"b1\"}]},"
        "{\"id\":\"c\",\"materialId\":\"clear\"," TRI "},"
        "{\"id\":\"d\",\"materialId\":\"plain\",\"applyFog\":true," TRI "}]}";
    mote_scene s;
    io_load_json(j, "no-fog", &s);
    TEST_ASSERT_EQUAL_STRING("", s.warning);
    TEST_ASSERT_EQUAL(5, s.mesh_count);
    const bool want[5] = {false, true, true, false, true};   /* the instance last */
    for (int k = 0; k < 5; k++) {
        mote_draw_desc d;
        mote_scene_draw_desc(&s, k, NULL, &d);
        snprintf(msg, sizeof msg, "mesh %d", k);
        TEST_ASSERT_EQUAL_MESSAGE(want[k], d.no_fog, msg);
    }
    mote_scene_free(&s);
}

/* needDepthPrePass on a blended material: its mesh's depth first, then
 * its colour where it is nearest, so that of two overlapping layers in
 * one mesh only the nearer is blended: as the same mesh drawn nearer
 * layer first without the pre-pass. */
#define LAYERS(first, second) \
    "\"positions\":[-1,-1,1, 1,-1,1, 1,1,1, -1,1,1, -0.5,-0.8,0, 1.5,-0.8,0, 1.5,1.2,0, -0.5,1.2,0]," \
    "\"normals\":[0,0,-1, 0,0,-1, 0,0,-1, 0,0,-1, 0,0,-1, 0,0,-1, 0,0,-1, 0,0,-1]," \
    "\"indices\":[" first "," second "]"
#define FAR_QUAD "0,1,2, 0,2,3"
#define NEAR_QUAD "4,5,6, 4,6,7"
void a_depth_pre_pass_should_blend_only_the_nearest_layer_of_a_mesh(void)
{
    const char *fmt =
        "{\"clearColor\":[0.2,0.3,0.4],"
        "\"materials\":[{\"id\":\"glass\",\"alpha\":0.6,\"backFaceCulling\":false,\"disableLighting\":true,"
        "\"emissive\":[0.9,0.5,0.1],\"needDepthPrePass\":%s}],"
        "\"meshes\":[{\"id\":\"layers\",\"materialId\":\"glass\",%s}]}";
    const char *far_first = LAYERS(FAR_QUAD, NEAR_QUAD), *near_first = LAYERS(NEAR_QUAD, FAR_QUAD);
    enum { SW = 80, SH = 60 };
    static uint8_t pre_pass[SW * SH * 4], sorted[SW * SH * 4], plain[SW * SH * 4];
    char j[1024];
    mote_scene s;
    snprintf(j, sizeof j, fmt, "true", far_first);
    io_load_json(j, "pre-pass", &s);
    TEST_ASSERT_EQUAL_STRING("", s.warning);
    TEST_ASSERT_TRUE(s.depth_pre_pass && s.depth_pre_pass[0]);
    io_render_scene(&s, pre_pass, SW, SH);
    mote_scene_free(&s);
    snprintf(j, sizeof j, fmt, "false", near_first);
    io_load_json(j, "near-first", &s);
    io_render_scene(&s, sorted, SW, SH);
    mote_scene_free(&s);
    snprintf(j, sizeof j, fmt, "false", far_first);
    io_load_json(j, "far-first", &s);
    io_render_scene(&s, plain, SW, SH);
    mote_scene_free(&s);
    TEST_ASSERT_EQUAL_MEMORY(sorted, pre_pass, sizeof sorted);
    long twice = 0;               /* the overlap, blended twice without it */
    for (int i = 0; i < SW * SH; i++)
        twice += memcmp(&plain[4 * i], &pre_pass[4 * i], 4) != 0;
    snprintf(msg, sizeof msg, "%ld pixels differ without the pre-pass", twice);
    TEST_ASSERT_TRUE_MESSAGE(twice > SW * SH / 20, msg);
}

/* tests/data/shiny.babylon (make_transparency.py --shiny): three red
 * spheres sharing one geometry under a white point light, specularPower
 * 8, 32 and 128; it loads without warnings, and the smaller the power,
 * the larger the white highlight (pixels whose green, which the red
 * diffuse barely has, passes 200). */
void a_shiny_scene_should_draw_highlights_by_their_power(void)
{
    mote_scene s;
    load_quiet_scene(DATA("shiny.babylon"), &s);
    TEST_ASSERT_EQUAL(3, s.mesh_count);
    enum { SW = 192, SH = 108 };
    static uint8_t img[SW * SH * 4];
    io_render_scene(&s, img, SW, SH);
    int white[3] = {0, 0, 0};
    for (int y = 0; y < SH; y++)
        for (int x = 0; x < SW; x++)
            white[x * 3 / SW] += img[(y * SW + x) * 4 + 1] > 200;
    snprintf(msg, sizeof msg, "highlight pixels %d, %d, %d", white[0], white[1], white[2]);
    TEST_ASSERT_TRUE_MESSAGE(white[0] > white[1] && white[1] > white[2] && white[2] > 0, msg);
    mote_scene_free(&s);
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
    RUN_TEST(loader_should_read_transparency_as_babylon_decides_it);
    RUN_TEST(draw_order_should_put_blended_meshes_last_from_back_to_front);
    RUN_TEST(draw_order_should_sort_blended_meshes_by_alpha_index_first);
    RUN_TEST(fog_should_leave_meshes_alone_that_turn_it_off);
    RUN_TEST(a_depth_pre_pass_should_blend_only_the_nearest_layer_of_a_mesh);
    RUN_TEST(a_scene_with_cut_outs_and_glass_should_show_what_lies_behind);
    RUN_TEST(a_fogged_scene_should_read_fog_highlights_and_light_lists);
    RUN_TEST(a_shiny_scene_should_draw_highlights_by_their_power);
    RUN_TEST(loader_should_read_emissive_opacity_and_specular_textures_as_layers);
    RUN_TEST(a_floor_scene_should_load_its_emissive_maps_without_a_warning);
    return UNITY_END();
}
