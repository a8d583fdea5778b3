/*
 * scenes.h - small built-in scenes for the accuracy tests and `make
 * accuracy`: a textured floor and cube seen in strong perspective, lit
 * Gouraud spheres that intersect, intersecting quads for the depth test,
 * and the floor, cube and a sphere with vertex colours.
 * Textures are generated (no files); everything is static, so a scene stays
 * valid until the next tu_scene_build call.
 */
#ifndef MOTE_TEST_SCENES_H
#define MOTE_TEST_SCENES_H

#include <mote/mote.h>

#define TU_SCENE_MAX_MESHES 4

typedef struct tu_scene {
    const char *name;
    mote_frame_desc frame;
    mote_mesh meshes[TU_SCENE_MAX_MESHES];
    int mesh_count;
    mote_mode mode;               /* the mode the scene is meant for */
} tu_scene;

enum { TU_SCENE_TEXTURED, TU_SCENE_GOURAUD, TU_SCENE_DEPTH, TU_SCENE_COLORS, TU_SCENE_COUNT };

/* A mesh of those arrays, everything else zero (untransformed, white). */
mote_mesh tu_mesh_of(const mote_vertex *v, uint32_t nv, const uint32_t *idx, uint32_t ni);

/* Builds scene `which`; wrap applies to every textured mesh. */
void tu_scene_build(int which, mote_wrap wrap, tu_scene *out);

/* The generated 64x64 RGBA texture: smooth gradients with a few hard edges. */
const mote_texture *tu_scene_texture(void);

#endif
