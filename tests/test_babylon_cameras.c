/*
 * test_babylon_cameras.c - a .babylon file's cameras and lights
 * (src/io/babylon_camera.c): the active camera, its view, planes, field
 * of view and projection, lights, and both in the parent tree.
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

/* A light's range (point and spot; Babylon.js's default falloff) and a
 * spot light's cone; a parent moves a spot light and turns its direction. */
void loader_should_read_light_ranges_and_spot_cones(void)
{
    const char *j = "{\"transformNodes\":[{\"id\":\"t\",\"position\":[0,1,0],"
                    "  \"rotation\":[0,1.5707963705062866,0]}],"
                    "\"lights\":[{\"type\":0,\"position\":[1,2,3],\"range\":7.5},"
                    " {\"type\":1,\"direction\":[0,-1,0],\"range\":3},"
                    " {\"type\":2,\"parentId\":\"t\",\"position\":[0,0,2],\"direction\":[0,0,1],"
                    "  \"angle\":1.2,\"exponent\":0.5,\"range\":20},"
                    " {\"type\":2,\"position\":[0,0,0],\"range\":-2}]}";
    mote_scene s;
    io_load_json(j, "ranges.babylon", &s);
    TEST_ASSERT_EQUAL(4, s.light_count);
    TEST_ASSERT_EQUAL(MOTE_LIGHT_POINT, s.lights[0].type);
    TEST_ASSERT_EQUAL_FLOAT(7.5f, s.lights[0].range);
    TEST_ASSERT_EQUAL(MOTE_LIGHT_DIRECTIONAL, s.lights[1].type);
    TEST_ASSERT_EQUAL_FLOAT(0.0f, s.lights[1].range);      /* directional: none */
    TEST_ASSERT_EQUAL(MOTE_LIGHT_SPOT, s.lights[2].type);
    TEST_ASSERT_EQUAL_FLOAT(1.2f, s.lights[2].spot_angle);
    TEST_ASSERT_EQUAL_FLOAT(0.5f, s.lights[2].spot_exponent);
    TEST_ASSERT_EQUAL_FLOAT(20.0f, s.lights[2].range);
    /* the parent turns +z to +x and lifts by 1 */
    ASSERT_VEC3(2.0f, 1.0f, 0.0f, s.lights[2].position, 1e-5f);
    ASSERT_VEC3(1.0f, 0.0f, 0.0f, s.lights[2].direction, 1e-5f);
    /* Babylon.js's defaults: no angle (it lights nothing), exponent 0; a
     * negative range is none */
    TEST_ASSERT_EQUAL(MOTE_LIGHT_SPOT, s.lights[3].type);
    TEST_ASSERT_EQUAL_FLOAT(0.0f, s.lights[3].spot_angle);
    TEST_ASSERT_EQUAL_FLOAT(0.0f, s.lights[3].spot_exponent);
    TEST_ASSERT_EQUAL_FLOAT(0.0f, s.lights[3].range);
    mote_scene_free(&s);
}

void loader_should_use_the_first_camera_without_an_active_one(void)
{
    const char *j = "{\"cameras\":[{\"id\":\"a\",\"position\":[1,2,3],\"target\":[0,0,0]},"
                    "{\"id\":\"b\",\"position\":[9,9,9]}]}";
    mote_scene s;
    io_load_json(j, "c", &s);
    TEST_ASSERT_TRUE(s.has_camera);
    ASSERT_VEC3(1.0f, 2.0f, 3.0f, s.camera.position, 0.0f);
    /* absent: Babylon.js's Camera defaults */
    TEST_ASSERT_EQUAL_FLOAT(0.8f, s.camera.fov);
    TEST_ASSERT_EQUAL_FLOAT(1.0f, s.camera.znear);
    TEST_ASSERT_EQUAL_FLOAT(10000.0f, s.camera.zfar);
    TEST_ASSERT_EQUAL(0, s.mesh_count);
    mote_scene_free(&s);
}

static void load_data(const char *path, mote_scene *s)
{
    TEST_ASSERT_EQUAL_MESSAGE(MOTE_OK, mote_scene_load(path, NULL, s, msg, sizeof msg), msg);
    TEST_ASSERT_EQUAL_STRING("", s->warning);
}

/* Meshes parented to cameras and lights, by id and by uniqueId: a camera
 * turns its children as its view turns (its target gives yaw and pitch), a
 * light only moves them, a hemispheric light not even that. */
void loader_should_place_children_of_cameras_and_lights(void)
{
    mote_scene s;
    load_data(DATA("camera_light_parents.babylon"), &s);
    /* seven meshes, then hidden nodes for cam, side, p, h and above */
    TEST_ASSERT_EQUAL(12, s.mesh_count);
    for (int i = 7; i < 12; i++) {
        TEST_ASSERT_TRUE(s.meshes[i].hidden);
        TEST_ASSERT_EQUAL_UINT32(0, s.meshes[i].vertex_count);
    }
    TEST_ASSERT_EQUAL_PTR(s.meshes[0].parent, s.meshes[1].parent);
    float p[3];
    io_world_origin(&s.meshes[0], p);         /* 5 ahead of the camera at z -10 */
    ASSERT_VEC3(0.0f, 0.0f, -5.0f, p, 1e-5f);
    io_world_origin(&s.meshes[1], p);         /* by uniqueId 42 */
    ASSERT_VEC3(1.0f, 0.0f, -10.0f, p, 1e-5f);
    /* "side" at x 3 looks down -x, from z 0.001: TargetCamera.setTarget
     * moves a camera level with its target so (see
     * loader_should_move_a_camera_level_with_its_target_as_babylon_does) */
    io_world_origin(&s.meshes[2], p);
    ASSERT_VEC3(1.0f, 0.0f, 0.001f / 3.0f, p, 1e-5f);
    io_world_origin(&s.meshes[3], p);         /* its right is +z */
    ASSERT_VEC3(3.0f - 0.001f / 3.0f, 0.0f, 1.001f, p, 1e-5f);
    io_world_origin(&s.meshes[4], p);         /* the point light at y 5 */
    ASSERT_VEC3(1.0f, 5.0f, 0.0f, p, 1e-5f);
    io_world_origin(&s.meshes[5], p);         /* a hemispheric light: the identity */
    ASSERT_VEC3(0.0f, 2.0f, 0.0f, p, 1e-5f);
    io_world_origin(&s.meshes[6], p);         /* "above" pitches down a quarter, from z 0.001 */
    ASSERT_VEC3(0.0f, 3.0f, 0.00075f, p, 1e-5f);
    /* the scene's own camera and lights are as before */
    ASSERT_VEC3(0.0f, 0.0f, -10.0f, s.camera.position, 0.0f);
    TEST_ASSERT_EQUAL(2, s.light_count);
    ASSERT_VEC3(0.0f, 5.0f, 0.0f, s.lights[0].position, 0.0f);
    mote_scene_free(&s);
}

/* Equal ids: the last camera wins (scene.getLastEntryById), and a camera
 * comes before a light. */
void loader_should_take_the_last_camera_of_an_id_as_parent(void)
{
    mote_scene s;
    load_data(DATA("camera_parent_duplicate_id.babylon"), &s);
    float p[3];
    io_world_origin(&s.meshes[0], p);
    ASSERT_VEC3(7.0f, 0.0f, 0.0f, p, 1e-5f);
    mote_scene_free(&s);
}

/* A camera's and a light's parentId: the rig at x 5 turned a quarter to
 * the right carries the camera, the point light and the directional
 * light's direction; the hemispheric light ignores it (as in Babylon.js);
 * disabled lights, or lights under a disabled node, are left out. */
void loader_should_apply_a_parent_to_the_camera_and_lights(void)
{
    mote_scene s;
    load_data(DATA("camera_parent.babylon"), &s);
    ASSERT_VEC3(-5.0f, 0.0f, 0.0f, s.camera.position, 1e-5f);
    ASSERT_VEC3(-4.0f, 0.0f, 0.0f, s.camera.target, 1e-5f);
    ASSERT_VEC3(0.0f, 1.0f, 0.0f, s.camera.up, 1e-6f);
    TEST_ASSERT_TRUE(s.has_lights);
    TEST_ASSERT_EQUAL(3, s.light_count);
    TEST_ASSERT_EQUAL(MOTE_LIGHT_POINT, s.lights[0].type);
    ASSERT_VEC3(6.0f, 0.0f, 0.0f, s.lights[0].position, 1e-5f);
    TEST_ASSERT_EQUAL(MOTE_LIGHT_DIRECTIONAL, s.lights[1].type);
    ASSERT_VEC3(1.0f, 0.0f, 0.0f, s.lights[1].direction, 1e-6f);
    TEST_ASSERT_EQUAL(MOTE_LIGHT_HEMISPHERIC, s.lights[2].type);
    ASSERT_VEC3(0.0f, 1.0f, 0.0f, s.lights[2].direction, 0.0f);
    mote_scene_free(&s);
}

/* lockedTargetId: the camera looks at the node's world position. */
void loader_should_aim_a_camera_at_its_locked_target(void)
{
    mote_scene s;
    load_data(DATA("camera_locked_target.babylon"), &s);
    ASSERT_VEC3(0.0f, 0.0f, -10.0f, s.camera.position, 0.0f);
    ASSERT_VEC3(2.0f, 3.0f, 0.0f, s.camera.target, 1e-6f);
    mote_scene_free(&s);
}

/* rotationQuaternion overrides rotation: a quarter turn left looks down -x. */
void loader_should_turn_a_camera_by_its_quaternion(void)
{
    mote_scene s;
    load_data(DATA("camera_quaternion.babylon"), &s);
    ASSERT_VEC3(10.0f, 0.0f, 0.0f, s.camera.position, 0.0f);
    ASSERT_VEC3(9.0f, 0.0f, 0.0f, s.camera.target, 1e-6f);
    mote_scene_free(&s);
}

/* A camera turned with a z component (a roll in rotation, or a
 * quaternion's z) has its up vector turned with it, as TargetCamera does
 * (_rotateUpVectorWithCameraRotationMatrix): the view is the whole turn.
 * Here a roll of 0.5 about the view axis, either way: up (-sin, cos, 0). */
void loader_should_roll_a_camera_by_its_rotation_z(void)
{
    static const char *const cams[2] = {
        "{\"cameras\":[{\"id\":\"c\",\"position\":[0,0,0],\"rotation\":[0,0,0.5]}]}",
        "{\"cameras\":[{\"id\":\"c\",\"position\":[0,0,0],"
        "\"rotationQuaternion\":[0,0,0.24740395925452294,0.9689124217106447]}]}"};
    for (int k = 0; k < 2; k++) {
        mote_scene s;
        io_load_json(cams[k], "roll", &s);
        ASSERT_VEC3(0.0f, 0.0f, 1.0f, s.camera.target, 1e-6f);
        ASSERT_VEC3(-0.47942554f, 0.87758256f, 0.0f, s.camera.up, 1e-6f);
        mote_scene_free(&s);
    }
}

/* TargetCamera.setTarget moves a camera level with its target in z by
 * Epsilon (0.001) along z first: one at its target (an old 3ds Max
 * export's "Default camera" at the origin, looking at the origin) then
 * looks down -z, and one right above its target has -z at the top of the
 * image. A right-handed scene moves the file's z, -z here; an
 * ArcRotateCamera is not moved. */
void loader_should_move_a_camera_level_with_its_target_as_babylon_does(void)
{
    static const char *const cams[4] = {
        "{\"cameras\":[{\"id\":\"c\",\"position\":[0,0,0],\"target\":[0,0,0]}]}",
        "{\"cameras\":[{\"id\":\"c\",\"position\":[0,12,0],\"target\":[0,0,0]}]}",
        "{\"useRightHandedSystem\":true,\"cameras\":[{\"id\":\"c\",\"position\":[0,12,0],"
        "\"target\":[0,0,0]}]}",
        "{\"cameras\":[{\"id\":\"c\",\"type\":\"ArcRotateCamera\",\"position\":[0,12,0],"
        "\"target\":[0,0,0]}]}"};
    static const float want_y[4] = {0.0f, 12.0f, 12.0f, 12.0f}, want_z[4] = {1e-3f, 1e-3f, -1e-3f, 0.0f};
    for (int k = 0; k < 4; k++) {
        mote_scene s;
        io_load_json(cams[k], "level", &s);
        ASSERT_VEC3(0.0f, want_y[k], want_z[k], s.camera.position, 0.0f);
        ASSERT_VEC3(0.0f, 0.0f, 0.0f, s.camera.target, 0.0f);
        mote_scene_free(&s);
    }
    /* the camera at its target sees a point 5 down -z in the middle; the
     * one above its target sees the file's -z up the image */
    mote_scene s;
    io_load_json(cams[0], "level", &s);
    mote_frame_desc f;
    mote_scene_frame(&s, 1.0f, &f);
    float m[16], clip[4];
    mote_camera_view_matrix(&f.camera, m);
    static const float ahead[3] = {0.0f, 0.0f, -5.0f};
    for (int r = 0; r < 3; r++)
        clip[r] = m[r] * ahead[0] + m[4 + r] * ahead[1] + m[8 + r] * ahead[2] + m[12 + r];
    TEST_ASSERT_FLOAT_WITHIN(1e-5f, 0.0f, clip[0]);
    TEST_ASSERT_FLOAT_WITHIN(1e-5f, 0.0f, clip[1]);
    TEST_ASSERT_TRUE(clip[2] > 4.9f);   /* in front (view z grows forward) */
    mote_scene_free(&s);
    io_load_json(cams[1], "level", &s);
    mote_scene_frame(&s, 1.0f, &f);
    mote_camera_view_matrix(&f.camera, m);
    static const float north[3] = {0.0f, 0.0f, -5.0f};
    float y = m[1] * north[0] + m[5] * north[1] + m[9] * north[2] + m[13];
    TEST_ASSERT_TRUE(y > 4.9f);         /* up the image */
    mote_scene_free(&s);
}

/* activeCameraID finds a camera by name when it has no id. */
void loader_should_find_the_active_camera_by_name(void)
{
    mote_scene s;
    load_data(DATA("camera_name_only.babylon"), &s);
    ASSERT_VEC3(3.0f, 0.0f, -10.0f, s.camera.position, 0.0f);
    mote_scene_free(&s);
}

/* minZ <= 0 projects as 0.1, maxZ 0 is no far plane (2^24 times the near
 * distance), an absent maxZ is Babylon.js's 10000. */
void loader_should_read_camera_planes_as_babylon_does(void)
{
    mote_scene s;
    load_data(DATA("camera_planes_zero.babylon"), &s);
    TEST_ASSERT_EQUAL_FLOAT(0.1f, s.camera.znear);
    TEST_ASSERT_EQUAL_FLOAT(0.1f * 16777216.0f, s.camera.zfar);
    mote_scene_free(&s);
    load_data(DATA("camera_planes_default.babylon"), &s);
    TEST_ASSERT_EQUAL_FLOAT(0.1f, s.camera.znear);
    TEST_ASSERT_EQUAL_FLOAT(10000.0f, s.camera.zfar);
    mote_scene_free(&s);
}

/* An old 3ds Max export: a camera framing an empty box, its numbers
 * written as "-Infinity" and "Infinity", and colours of 4 components.
 * Babylon.js loads it and draws nothing through that camera; mote loads
 * it without the camera (mote_scene_frame frames the scene), warned, and
 * reads the colours' first three components, as Color3.FromArray does. */
void loader_should_frame_the_scene_itself_past_a_camera_written_with_infinity_text(void)
{
    mote_scene s;
    TEST_ASSERT_EQUAL_MESSAGE(MOTE_OK, mote_scene_load(DATA("camera_infinity_text.babylon"), NULL,
                                                       &s, msg, sizeof msg), msg);
    TEST_ASSERT_FALSE(s.has_camera);
    TEST_ASSERT_NOT_NULL_MESSAGE(strstr(s.warning, "cameras[0].position: \"Infinity\", "
                                        "\"-Infinity\" or \"NaN\" written as text"), s.warning);
    TEST_ASSERT_EQUAL(1, s.mesh_count);
    TEST_ASSERT_EQUAL(1, s.light_count);
    ASSERT_VEC3(1.0f, 1.0f, 1.0f, s.lights[0].color, 0.0f);
    ASSERT_VEC3(0.2f, 0.2f, 0.2f, s.lights[0].ground_color, 0.0f);
    TEST_ASSERT_EQUAL_UINT8(255, s.meshes[0].material.color.r);
    TEST_ASSERT_EQUAL_UINT8(0, s.meshes[0].material.color.g);
    mote_frame_desc frame;
    mote_scene_frame(&s, 4.0f / 3.0f, &frame);
    TEST_ASSERT_TRUE(isfinite(frame.camera.position[2]) && isfinite(frame.camera.zfar));
    mote_scene_free(&s);
    /* a scene's ambient colour of 4 components too; 5 is still an error */
    io_load_json("{\"ambientColor\":[0.25,0.5,0.75,1]}", "ambient4.babylon", &s);
    ASSERT_VEC3(0.25f, 0.5f, 0.75f, s.ambient, 0.0f);
    mote_scene_free(&s);
    mote_scene bad;
    const char *five = "{\"lights\":[{\"type\":3,\"diffuse\":[1,1,1,1,1]}]}";
    TEST_ASSERT_EQUAL(MOTE_ERR_PARSE, mote_scene_load_memory(five, strlen(five), "five.babylon",
                                                             NULL, NULL, &bad, msg, sizeof msg));
    TEST_ASSERT_EQUAL_STRING("five.babylon: lights[0].diffuse: expected an array of 3 or 4 "
                             "numbers", msg);
}

/* A file whose only light is disabled is lit by nothing: no light, and no
 * stand-in light from mote_scene_frame either. */
void loader_should_leave_out_disabled_lights(void)
{
    mote_scene s;
    load_data(DATA("light_all_disabled.babylon"), &s);
    TEST_ASSERT_EQUAL(0, s.light_count);
    TEST_ASSERT_TRUE(s.has_lights);
    mote_frame_desc f;
    mote_scene_frame(&s, 1.0f, &f);
    TEST_ASSERT_EQUAL(0, f.light_count);
    mote_scene_free(&s);
}

/* fovMode 1 (Babylon.js's FOVMODE_HORIZONTAL_FIXED): fov spans the width,
 * so the vertical field follows the aspect ratio. */
void loader_should_read_fov_mode_1_as_a_horizontal_field_of_view(void)
{
    mote_scene s;
    io_load_json("{\"cameras\":[{\"id\":\"c\",\"position\":[0,0,0],\"target\":[0,0,1],"
              "\"fov\":1.5707963267948966,\"fovMode\":1,\"minZ\":0.1,\"maxZ\":10}]}", "h", &s);
    TEST_ASSERT_TRUE(s.camera_fov_is_horizontal);
    /* 90 degrees across a 200 x 100 frame: x = z reaches the right edge,
     * y = z / 2 the top (the vertical field is 2 atan(1/2)) */
    static uint8_t color[200 * 100 * 4];
    mote_device dev;
    io_init_color_device(&dev, color, 200, 100);
    mote_frame_desc f;
    mote_scene_frame(&s, 2.0f, &f);
    TEST_ASSERT_EQUAL(MOTE_OK, mote_begin(&dev, &f));
    float x, y, z;
    const float right[3] = {1, 0, 1}, top[3] = {0, 0.5f, 1};
    TEST_ASSERT_TRUE(mote_project(&dev, right, &x, &y, &z));
    TEST_ASSERT_FLOAT_WITHIN(1e-3f, 200.0f, x);
    TEST_ASSERT_FLOAT_WITHIN(1e-3f, 50.0f, y);
    TEST_ASSERT_TRUE(mote_project(&dev, top, &x, &y, &z));
    TEST_ASSERT_FLOAT_WITHIN(1e-3f, 100.0f, x);
    TEST_ASSERT_FLOAT_WITHIN(1e-3f, 0.0f, y);
    TEST_ASSERT_EQUAL(MOTE_OK, mote_end(&dev));
    mote_scene_free(&s);
    /* fovMode 0, or none: vertical, as before */
    io_load_json("{\"cameras\":[{\"id\":\"c\",\"fovMode\":0}]}", "h", &s);
    TEST_ASSERT_FALSE(s.camera_fov_is_horizontal);
    mote_scene_free(&s);
}

/* An orthographic camera (mode 1): its box as written, right-handed files
 * too (the mirror in z leaves x and y alone), minZ as given, 0 or
 * negative, and no fov needed. A box missing an edge (or null), which
 * Babylon.js sizes by the canvas in pixels, is the core's default with a
 * warning; an empty one is an error. */
void loader_should_read_orthographic_cameras(void)
{
    const char *j = "{\"useRightHandedSystem\":true,"
                    "\"cameras\":[{\"id\":\"c\",\"mode\":1,\"position\":[0,0,-10],\"target\":[0,0,0],"
                    "\"fov\":0,\"minZ\":-2.5,\"maxZ\":40,\"orthoLeft\":-4,\"orthoRight\":6,"
                    "\"orthoBottom\":-1.5,\"orthoTop\":3}],"
                    "\"meshes\":[{\"id\":\"a\",\"pivotMatrix\":[1,0,0,0, 0,1,0,0, 0,0,1,0, 2,0,0,1]}]}";
    mote_scene s;
    io_load_json(j, "x", &s);
    TEST_ASSERT_EQUAL_STRING("", s.warning);   /* pivots and right-handed files are read too */
    TEST_ASSERT_EQUAL(MOTE_PROJECTION_ORTHOGRAPHIC, s.camera.projection);
    TEST_ASSERT_EQUAL_FLOAT(-4.0f, s.camera.ortho[0]);
    TEST_ASSERT_EQUAL_FLOAT(6.0f, s.camera.ortho[1]);
    TEST_ASSERT_EQUAL_FLOAT(-1.5f, s.camera.ortho[2]);
    TEST_ASSERT_EQUAL_FLOAT(3.0f, s.camera.ortho[3]);
    TEST_ASSERT_EQUAL_FLOAT(-2.5f, s.camera.znear);
    TEST_ASSERT_EQUAL_FLOAT(40.0f, s.camera.zfar);
    mote_scene_free(&s);
    io_load_json("{\"cameras\":[{\"id\":\"c\",\"mode\":1,\"minZ\":0,\"orthoLeft\":-4,"
              "\"orthoRight\":4,\"orthoBottom\":null,\"orthoTop\":3}]}", "x", &s);
    TEST_ASSERT_EQUAL_STRING("cameras[0]: an orthographic camera without all of orthoLeft, orthoRight, "
                             "orthoBottom and orthoTop (Babylon.js sizes it by the canvas, in pixels) is "
                             "drawn 2 units high", s.warning);
    TEST_ASSERT_EQUAL(MOTE_PROJECTION_ORTHOGRAPHIC, s.camera.projection);
    for (int k = 0; k < 4; k++)
        TEST_ASSERT_EQUAL_FLOAT(0.0f, s.camera.ortho[k]);
    TEST_ASSERT_EQUAL_FLOAT(0.0f, s.camera.znear);
    mote_scene_free(&s);
    /* mode 0, or none: perspective, minZ 0 as 0.1 */
    io_load_json("{\"cameras\":[{\"id\":\"c\",\"mode\":0,\"minZ\":0,\"orthoLeft\":-4}]}", "x", &s);
    TEST_ASSERT_EQUAL_STRING("", s.warning);
    TEST_ASSERT_EQUAL(MOTE_PROJECTION_PERSPECTIVE, s.camera.projection);
    TEST_ASSERT_EQUAL_FLOAT(0.1f, s.camera.znear);
    mote_scene_free(&s);
    const char *empty = "{\"cameras\":[{\"id\":\"c\",\"mode\":1,\"orthoLeft\":2,\"orthoRight\":2,"
                        "\"orthoBottom\":-1,\"orthoTop\":1}]}";
    TEST_ASSERT_EQUAL(MOTE_ERR_RANGE, mote_scene_load_memory(empty, strlen(empty), "e", NULL, NULL, &s, msg,
                                                             sizeof msg));
    TEST_ASSERT_EQUAL_STRING("e: cameras[0]: orthoLeft 2, orthoRight 2, orthoBottom -1 and orthoTop 1 "
                             "enclose nothing", msg);
    const char *flat = "{\"cameras\":[{\"id\":\"c\",\"mode\":1,\"minZ\":5,\"maxZ\":0}]}";
    TEST_ASSERT_EQUAL(MOTE_ERR_RANGE, mote_scene_load_memory(flat, strlen(flat), "f", NULL, NULL, &s, msg,
                                                             sizeof msg));
    TEST_ASSERT_EQUAL_STRING("f: cameras[0]: minZ 5 and maxZ 0 need minZ < maxZ", msg);
}

int main(void)
{
    UNITY_BEGIN();
    RUN_TEST(loader_should_read_light_ranges_and_spot_cones);
    RUN_TEST(loader_should_use_the_first_camera_without_an_active_one);
    RUN_TEST(loader_should_place_children_of_cameras_and_lights);
    RUN_TEST(loader_should_take_the_last_camera_of_an_id_as_parent);
    RUN_TEST(loader_should_apply_a_parent_to_the_camera_and_lights);
    RUN_TEST(loader_should_aim_a_camera_at_its_locked_target);
    RUN_TEST(loader_should_turn_a_camera_by_its_quaternion);
    RUN_TEST(loader_should_roll_a_camera_by_its_rotation_z);
    RUN_TEST(loader_should_move_a_camera_level_with_its_target_as_babylon_does);
    RUN_TEST(loader_should_find_the_active_camera_by_name);
    RUN_TEST(loader_should_read_camera_planes_as_babylon_does);
    RUN_TEST(loader_should_frame_the_scene_itself_past_a_camera_written_with_infinity_text);
    RUN_TEST(loader_should_leave_out_disabled_lights);
    RUN_TEST(loader_should_read_fov_mode_1_as_a_horizontal_field_of_view);
    RUN_TEST(loader_should_read_orthographic_cameras);
    return UNITY_END();
}
