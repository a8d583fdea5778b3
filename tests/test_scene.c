/*
 * test_scene.c - src/io/scene.c: mote_scene_load tells a file's format by
 * its bytes, whatever its name (.babylon JSON loads, anything else fails
 * with a message that says what it is, leaving the scene zeroed and
 * nothing allocated), and mote_scene_frame frames a scene.
 */
#define _POSIX_C_SOURCE 200809L /* mkdtemp */
#include <mote/mote.h>
#include <mote/mote_io.h>
#include "io/io_internal.h"
#include "support/io_test.h"
#include "unity.h"

#include <stdio.h>
#include <stdlib.h>
#include <string.h>
#include <unistd.h>

static char msg[512];
static long live_before;

void setUp(void)
{
    msg[0] = '\0';
    live_before = mote__io_live_allocations();
    mote__io_set_alloc_failure_after(-1);
}

void tearDown(void) {}

static bool scene_is_zeroed(const mote_scene *s)
{
    static const mote_scene zero;
    return memcmp(s, &zero, sizeof zero) == 0;
}

/* Loads size bytes named "x.babylon" and expects code, a message that
 * starts with the name and holds `says`, a zeroed scene and no leak. */
static void assert_refused(const void *bytes, size_t size, mote_result code, const char *says)
{
    mote_scene s;
    mote_result r = mote_scene_load_memory(bytes, size, "x.babylon", NULL, NULL, &s, msg,
                                           sizeof msg);
    TEST_ASSERT_EQUAL_STRING_MESSAGE(mote_result_string(code), mote_result_string(r), msg);
    TEST_ASSERT_EQUAL_STRING_LEN_MESSAGE("x.babylon: ", msg, 11, msg);
    TEST_ASSERT_NOT_NULL_MESSAGE(strstr(msg, says), msg);
    TEST_ASSERT_TRUE(scene_is_zeroed(&s));
    mote_scene_free(&s);
    TEST_ASSERT_EQUAL(live_before, mote__io_live_allocations());
}

/* A glTF 1.0 file (JSON or binary) is told for what it is: its layout
 * differs throughout from glTF 2.0's, which mote reads. */
void scene_load_should_name_a_gltf_1_json_file(void)
{
    static const char gltf[] = " {\"asset\": {\"generator\": \"x\", \"version\": \"1.0\"}, "
                               "\"meshes\": {}, \"scene\": \"s\"}";
    assert_refused(gltf, strlen(gltf), MOTE_ERR_UNSUPPORTED,
                   "asset.version: \"1.0\": a glTF 1.0 file, which mote does not read (it reads "
                   "glTF 2.0)");
}

void scene_load_should_name_a_binary_gltf_1_file(void)
{
    /* the 12-byte header, then a JSON chunk: a .glb reported "nesting
     * deeper than the limit" when read as JSON */
    static const unsigned char glb[] = {
        'g', 'l', 'T', 'F', 1, 0, 0, 0, 48, 0, 0, 0, 28, 0, 0, 0, 0, 0, 0, 0,
        '{', '"', 'a', 's', 's', 'e', 't', '"', ':', '{', '"', 'v', 'e', 'r', 's', 'i',
        'o', 'n', '"', ':', '"', '1', '.', '0', '"', '}', '}', ' '};
    assert_refused(glb, sizeof glb, MOTE_ERR_UNSUPPORTED, "a glTF 1.0 binary file");
}

void scene_load_should_name_a_wavefront_obj_file(void)
{
    static const char obj[] = "# Blender 3.6.0\n# www.blender.org\n\nmtllib cube.mtl\no Cube\n"
                              "v 1.000000 1.000000 -1.000000\nf 1 2 3\n";
    assert_refused(obj, strlen(obj), MOTE_ERR_UNSUPPORTED, "a Wavefront OBJ file");
    static const char vertices_first[] = "v 0 0 0\nv 1 0 0\nv 0 1 0\nf 1 2 3\n";
    assert_refused(vertices_first, strlen(vertices_first), MOTE_ERR_UNSUPPORTED,
                   "a Wavefront OBJ file");
    static const char mtl[] = "# materials\nnewmtl Material\nKd 0.8 0.8 0.8\n";
    assert_refused(mtl, strlen(mtl), MOTE_ERR_UNSUPPORTED, "a Wavefront MTL file");
}

void scene_load_should_name_a_git_lfs_pointer(void)
{
    static const char pointer[] =
        "version https://git-lfs.github.com/spec/v1\n"
        "oid sha256:4d7a214614ab2935c943f9e0ff69d22eadbb8f32b1258daaa5e2ca24d17e2393\n"
        "size 12345\n";
    assert_refused(pointer, strlen(pointer), MOTE_ERR_IO,
                   "a Git LFS pointer, not the file it stands for");
}

void scene_load_should_name_an_image(void)
{
    static const struct {
        const char *bytes;
        size_t size;
        const char *says;
    } images[] = {
        {"\x89PNG\r\n\x1a\n\0\0\0\rIHDR", 16, "a PNG image, not a scene"},
        {"\xff\xd8\xff\xe0\0\x10JFIF", 10, "a JPEG image"},
        {"GIF89a\1\0\1\0", 10, "a GIF image"},
        {"BM\x46\0\0\0\0\0\0\0\x36\0\0\0\x28\0\0\0\1\0\0\0\1\0\0\0", 26, "a BMP image"},
        {"P6\n1 1\n255\n\0\0\0", 14, "a PNM image"},
        {"#?RADIANCE\nFORMAT=32-bit_rle_rgbe\n", 34, "a Radiance HDR image"},
        {"RIFF\x1a\0\0\0WEBPVP8 ", 16, "a WebP image"},
        /* no signature: told last, by stb_image's own test of its header */
        {"\0\0\2\0\0\0\0\0\0\0\0\0\1\0\1\0\x18\0\0\0\xff", 21, "a TGA image"},
    };
    for (size_t i = 0; i < sizeof images / sizeof images[0]; i++)
        assert_refused(images[i].bytes, images[i].size, MOTE_ERR_UNSUPPORTED, images[i].says);
}

void scene_load_should_say_what_it_cannot_name(void)
{
    static const unsigned char elf[16] = {0x7f, 'E', 'L', 'F', 2, 1, 1, 0};
    assert_refused(elf, sizeof elf, MOTE_ERR_PARSE,
                   "not a scene: neither .babylon nor glTF, nor a format mote knows (it starts "
                   "with bytes 7f 45 4c 46 02 01 01 00)");
    assert_refused("42", 2, MOTE_ERR_PARSE, "it starts with bytes 34 32)");
}

/* What starts as JSON goes to the JSON parser, which says what is wrong
 * with it, as before formats were told apart. */
void scene_load_should_keep_the_json_messages_for_json(void)
{
    assert_refused("", 0, MOTE_ERR_PARSE, "empty file");
    assert_refused("{\"meshes\": [", 11, MOTE_ERR_PARSE, "unexpected end of the JSON text");
    assert_refused("[1, 2]", 6, MOTE_ERR_PARSE, "expected a JSON object at the top level");
    assert_refused("{\"a\": tru}", 10, MOTE_ERR_PARSE, "malformed JSON");
    char deep[200];
    memset(deep, '[', sizeof deep);
    assert_refused(deep, sizeof deep, MOTE_ERR_LIMIT, "nesting deeper than the limit of 64");
}

/* An "asset" without a "version" is no glTF file: a .babylon scene may
 * hold any key. A byte order mark starts JSON too. */
void scene_load_should_load_babylon_json_whatever_its_keys(void)
{
    static const char scene[] = "{\"asset\": {\"id\": \"a\"}, \"meshes\": [{\"id\": \"m\", "
                                "\"positions\": [0,0,0, 1,0,0, 0,1,0], \"indices\": [0,1,2]}]}";
    mote_scene s;
    TEST_ASSERT_EQUAL_MESSAGE(MOTE_OK, mote_scene_load_memory(scene, strlen(scene), "a.babylon",
                                                              NULL, NULL, &s, msg, sizeof msg),
                              msg);
    TEST_ASSERT_EQUAL(1, s.mesh_count);
    TEST_ASSERT_EQUAL_UINT32(3, s.meshes[0].index_count);
    mote_scene_free(&s);
    /* with a UTF-8 byte order mark, as some editors save JSON */
    TEST_ASSERT_EQUAL_MESSAGE(MOTE_OK, mote_scene_load_memory("\xef\xbb\xbf{}", 5, "b.babylon",
                                                              NULL, NULL, &s, msg, sizeof msg),
                              msg);
    mote_scene_free(&s);
    TEST_ASSERT_EQUAL(live_before, mote__io_live_allocations());
}

/* The name says nothing: a .babylon scene named .glb loads, and a glTF
 * file named .babylon is told for what it is. */
void scene_load_should_go_by_the_bytes_not_the_file_name(void)
{
    char dir[] = "/tmp/mote-scene-load-XXXXXX";
    TEST_ASSERT_NOT_NULL(mkdtemp(dir));
    char path[64];
    snprintf(path, sizeof path, "%s/scene.glb", dir);
    FILE *f = fopen(path, "wb");
    TEST_ASSERT_NOT_NULL(f);
    fputs("{\"meshes\": [{\"id\": \"m\", \"positions\": [0,0,0, 1,0,0, 0,1,0], "
          "\"indices\": [0,1,2]}]}", f);
    fclose(f);
    mote_scene s;
    TEST_ASSERT_EQUAL_MESSAGE(MOTE_OK, mote_scene_load(path, NULL, &s, msg, sizeof msg), msg);
    TEST_ASSERT_EQUAL(1, s.mesh_count);
    mote_scene_free(&s);
    remove(path);

    snprintf(path, sizeof path, "%s/scene.babylon", dir);
    f = fopen(path, "wb");
    TEST_ASSERT_NOT_NULL(f);
    fputs("{\"asset\": {\"version\": \"1.0\"}}", f);
    fclose(f);
    TEST_ASSERT_EQUAL(MOTE_ERR_UNSUPPORTED, mote_scene_load(path, NULL, &s, msg, sizeof msg));
    TEST_ASSERT_EQUAL_STRING("scene.babylon: asset.version: \"1.0\": a glTF 1.0 file, which mote "
                             "does not read (it reads glTF 2.0)", msg);
    TEST_ASSERT_TRUE(scene_is_zeroed(&s));
    remove(path);
    rmdir(dir);
    TEST_ASSERT_EQUAL(live_before, mote__io_live_allocations());
}

void frame_should_look_at_the_box_from_the_front_top_right_without_a_camera(void)
{
    const char *j = "{\"meshes\":[{\"id\":\"m\",\"positions\":[-1,-1,-1, 1,1,1, 1,-1,1],"
                    "\"indices\":[0,1,2]}]}";
    mote_scene s;
    io_load_json(j, "f", &s);
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

/* A caller's eye gets planes that hold the whole scene from there, as the
 * framing camera gets them from its own: far away, inside the scene,
 * at its centre. */
void fit_planes_should_hold_the_scene_from_any_eye(void)
{
    const char *j = "{\"meshes\":[{\"id\":\"m\",\"positions\":[-1,-1,-1, 1,1,1, 1,-1,1],"
                    "\"indices\":[0,1,2]}]}";
    mote_scene s;
    io_load_json(j, "f", &s);
    const float radius = sqrtf(3.0f), eyes[3] = {50.0f, 0.5f, 0.0f};
    for (int k = 0; k < 3; k++) {
        mote_camera c;
        memset(&c, 0, sizeof c);
        c.position[2] = -eyes[k];
        mote_scene_fit_planes(&s, &c);
        TEST_ASSERT_TRUE(c.znear > 0.0f && c.znear < c.zfar);
        TEST_ASSERT_TRUE(c.zfar >= eyes[k] + radius);
        /* where the scene begins; from inside it, a hundredth of the way
         * to its centre or a thousandth of far */
        float inside = fmaxf(eyes[k] * 0.01f, c.zfar * 0.001f);
        TEST_ASSERT_TRUE(c.znear <= (eyes[k] > radius ? eyes[k] - radius : inside));
    }
    mote_camera untouched;
    memset(&untouched, 0, sizeof untouched);
    mote_scene_fit_planes(NULL, &untouched);
    TEST_ASSERT_EQUAL_FLOAT(0.0f, untouched.zfar);
    mote_scene_free(&s);
}

int main(void)
{
    UNITY_BEGIN();
    RUN_TEST(scene_load_should_name_a_gltf_1_json_file);
    RUN_TEST(scene_load_should_name_a_binary_gltf_1_file);
    RUN_TEST(scene_load_should_name_a_wavefront_obj_file);
    RUN_TEST(scene_load_should_name_a_git_lfs_pointer);
    RUN_TEST(scene_load_should_name_an_image);
    RUN_TEST(scene_load_should_say_what_it_cannot_name);
    RUN_TEST(scene_load_should_keep_the_json_messages_for_json);
    RUN_TEST(scene_load_should_load_babylon_json_whatever_its_keys);
    RUN_TEST(scene_load_should_go_by_the_bytes_not_the_file_name);
    RUN_TEST(frame_should_look_at_the_box_from_the_front_top_right_without_a_camera);
    RUN_TEST(fit_planes_should_hold_the_scene_from_any_eye);
    return UNITY_END();
}
