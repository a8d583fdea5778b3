/*
 * scenes.c - see scenes.h.
 */
#include "support/scenes.h"

#include <math.h>
#include <string.h>

static uint8_t tex_pixels[64 * 64 * 4];
static mote_texture tex = {64, 64, MOTE_FORMAT_RGBA8888, 64 * 4, tex_pixels};

const mote_texture *tu_scene_texture(void)
{
    for (int y = 0; y < 64; y++)
        for (int x = 0; x < 64; x++) {
            uint8_t *p = &tex_pixels[4 * (y * 64 + x)];
            bool block = ((x >> 4) ^ (y >> 4)) & 1;   /* hard edges every 16 texels */
            p[0] = (uint8_t)(x * 4);
            p[1] = (uint8_t)(block ? 200 - y * 2 : 40 + y * 3);
            p[2] = (uint8_t)(128 + 100 * sin(x * 0.2) * cos(y * 0.15));
            p[3] = 255;
        }
    return &tex;
}

/* ---- geometry ----------------------------------------------------------- */

static mote_vertex floor_v[4];
static uint32_t floor_i[6] = {0, 1, 2, 0, 2, 3};
static mote_vertex cube_v[24];
static uint32_t cube_i[36];
static mote_vertex sphere_v[2][17 * 33];
static uint32_t sphere_i[6 * 16 * 32];
static mote_vertex quad_v[2][4];
static uint32_t quad_i[6] = {0, 1, 2, 0, 2, 3};
static mote_rgba floor_c[4], cube_c[24], sphere_c[17 * 33];

mote_mesh tu_mesh_of(const mote_vertex *v, uint32_t nv, const uint32_t *i, uint32_t ni)
{
    mote_mesh m;
    memset(&m, 0, sizeof m);
    m.vertices = v;
    m.vertex_count = nv;
    m.indices = i;
    m.index_count = ni;
    return m;
}

static void build_floor(float size, float y, float uv_repeat)
{
    const float c[4][2] = {{-1, -1}, {1, -1}, {1, 1}, {-1, 1}};
    memset(floor_v, 0, sizeof floor_v);
    for (int k = 0; k < 4; k++) {
        floor_v[k].position[0] = c[k][0] * size;
        floor_v[k].position[1] = y;
        floor_v[k].position[2] = c[k][1] * size;
        floor_v[k].normal[1] = 1;
        floor_v[k].uv[0] = (c[k][0] + 1) * 0.5f * uv_repeat - 0.3f;
        floor_v[k].uv[1] = (c[k][1] + 1) * 0.5f * uv_repeat - 0.2f;
    }
}

static void build_cube(void)
{
    static const float n[6][3] = {{0, 0, -1}, {0, 0, 1}, {-1, 0, 0}, {1, 0, 0}, {0, -1, 0}, {0, 1, 0}};
    int nv = 0, ni = 0;
    for (int f = 0; f < 6; f++) {
        /* two axes spanning the face */
        float u[3] = {0, 0, 0}, v[3] = {0, 0, 0};
        int a = f < 2 ? 0 : f < 4 ? 2 : 0, b = f < 2 ? 1 : f < 4 ? 1 : 2;
        u[a] = 1;
        v[b] = 1;
        for (int k = 0; k < 4; k++) {
            float s = (k == 1 || k == 2) ? 1.0f : -1.0f, t = k >= 2 ? 1.0f : -1.0f;
            mote_vertex *p = &cube_v[nv + k];
            memset(p, 0, sizeof *p);
            for (int j = 0; j < 3; j++) {
                p->position[j] = n[f][j] + s * u[j] + t * v[j];
                p->normal[j] = n[f][j];
            }
            p->uv[0] = (s + 1) * 0.5f;
            p->uv[1] = (t + 1) * 0.5f;
        }
        uint32_t q[6] = {0, 1, 2, 0, 2, 3};
        for (int k = 0; k < 6; k++)
            cube_i[ni++] = (uint32_t)nv + q[k];
        nv += 4;
    }
}

static int build_sphere(mote_vertex *v, float r)
{
    const int R = 16, S = 32;
    int nv = 0, ni = 0;
    for (int i = 0; i <= R; i++)
        for (int j = 0; j <= S; j++) {
            double th = 3.141592653589793 * i / R, ph = 6.283185307179586 * j / S;
            mote_vertex *p = &v[nv++];
            memset(p, 0, sizeof *p);
            p->normal[0] = (float)(sin(th) * cos(ph));
            p->normal[1] = (float)cos(th);
            p->normal[2] = (float)(sin(th) * sin(ph));
            for (int k = 0; k < 3; k++)
                p->position[k] = p->normal[k] * r;
            p->uv[0] = (float)j / S * 2;
            p->uv[1] = (float)i / R;
        }
    for (int i = 0; i < R; i++)
        for (int j = 0; j < S; j++) {
            uint32_t a = (uint32_t)(i * (S + 1) + j), b = a + 1, c = a + (uint32_t)S + 2, d = a + (uint32_t)S + 1;
            uint32_t q[6] = {a, b, c, a, c, d};
            for (int k = 0; k < 6; k++)
                sphere_i[ni++] = q[k];
        }
    return ni;
}

static void base_frame(mote_frame_desc *f)
{
    memset(f, 0, sizeof *f);
    f->camera.fov = 0.9f;
    f->camera.znear = 0.1f;
    f->camera.zfar = 60.0f;
    f->light_count = 2;
    f->lights[0].type = MOTE_LIGHT_POINT;
    f->lights[0].position[0] = 4;
    f->lights[0].position[1] = 6;
    f->lights[0].position[2] = -5;
    f->lights[0].color[0] = 1.0f;
    f->lights[0].color[1] = 0.9f;
    f->lights[0].color[2] = 0.8f;
    f->lights[1].type = MOTE_LIGHT_DIRECTIONAL;
    f->lights[1].direction[0] = -1;
    f->lights[1].direction[1] = -0.5f;
    f->lights[1].direction[2] = 0.3f;
    f->lights[1].intensity = 0.4f;
    f->ambient[0] = f->ambient[1] = f->ambient[2] = 0.15f;
}

void tu_scene_build(int which, mote_wrap wrap, tu_scene *s)
{
    memset(s, 0, sizeof *s);
    base_frame(&s->frame);
    const mote_texture *t = tu_scene_texture();
    if (which == TU_SCENE_TEXTURED) {
        s->name = "textured floor and cube";
        s->mode = MOTE_MODE_TEXTURED;
        s->frame.camera.position[0] = 1.5f;
        s->frame.camera.position[1] = 1.2f;
        s->frame.camera.position[2] = -6;
        s->frame.camera.target[1] = -0.5f;
        build_floor(12, -1, 6);
        build_cube();
        s->meshes[0] = tu_mesh_of(floor_v, 4, floor_i, 6);
        s->meshes[1] = tu_mesh_of(cube_v, 24, cube_i, 36);
        s->meshes[1].rotation[0] = 0.5f;
        s->meshes[1].rotation[1] = 0.7f;
        s->meshes[1].position[1] = 0.6f;
        s->meshes[1].scaling[0] = s->meshes[1].scaling[1] = s->meshes[1].scaling[2] = 1.2f;
        s->mesh_count = 2;
        for (int i = 0; i < 2; i++) {
            s->meshes[i].material.texture = t;
            s->meshes[i].material.wrap_u = s->meshes[i].material.wrap_v = wrap;
        }
        s->meshes[1].material.u_scale = 1.7f;
        s->meshes[1].material.v_offset = -0.4f;
    } else if (which == TU_SCENE_GOURAUD) {
        s->name = "Gouraud spheres, intersecting";
        s->mode = MOTE_MODE_GOURAUD;
        s->frame.camera.position[1] = 1;
        s->frame.camera.position[2] = -4.5f;
        int ni = build_sphere(sphere_v[0], 1.3f);
        build_sphere(sphere_v[1], 1.0f);
        for (int i = 0; i < 2; i++) {
            s->meshes[i] = tu_mesh_of(sphere_v[i], 17 * 33, sphere_i, (uint32_t)ni);
            s->meshes[i].material.color_set = true;
        }
        s->meshes[0].material.color = (mote_rgba){230, 120, 60, 255};
        s->meshes[1].material.color = (mote_rgba){70, 160, 240, 255};
        s->meshes[0].position[0] = -0.7f;
        s->meshes[1].position[0] = 0.9f;
        s->meshes[1].position[1] = 0.3f;
        s->meshes[1].position[2] = -0.4f;
        s->mesh_count = 2;
    } else if (which == TU_SCENE_COLORS) {
        /* the textured scene, its meshes tinted per vertex, and a sphere
         * whose colour follows its normal (smooth, strongly saturated) */
        tu_scene_build(TU_SCENE_TEXTURED, wrap, s);
        s->name = "vertex colours";
        static const mote_rgba corners[4] = {{255, 40, 40, 255}, {40, 255, 80, 255},
                                             {60, 90, 255, 255}, {255, 255, 255, 255}};
        memcpy(floor_c, corners, sizeof corners);
        for (int i = 0; i < 24; i++)
            cube_c[i] = (mote_rgba){(uint8_t)(60 + (i * 37) % 196), (uint8_t)(255 - (i * 53) % 200),
                                    (uint8_t)(30 + (i * 91) % 226), 255};
        s->meshes[0].colors = floor_c;
        s->meshes[1].colors = cube_c;
        int ni = build_sphere(sphere_v[0], 0.7f);
        for (int i = 0; i < 17 * 33; i++) {
            const float *n = sphere_v[0][i].normal;
            sphere_c[i] = (mote_rgba){(uint8_t)(127.5f + 127.0f * n[0]), (uint8_t)(127.5f + 127.0f * n[1]),
                                      (uint8_t)(127.5f - 127.0f * n[2]), 255};
        }
        s->meshes[2] = tu_mesh_of(sphere_v[0], 17 * 33, sphere_i, (uint32_t)ni);
        s->meshes[2].colors = sphere_c;
        s->meshes[2].material.color = (mote_rgba){250, 230, 200, 255};
        s->meshes[2].material.color_set = true;
        s->meshes[2].position[0] = -1.8f;
        s->meshes[2].position[1] = 0.2f;
        s->meshes[2].position[2] = -1.0f;
        s->mesh_count = 3;
    } else {
        s->name = "intersecting quads (depth)";
        s->mode = MOTE_MODE_FLAT;
        s->frame.camera.position[2] = -3;
        for (int q = 0; q < 2; q++) {
            const float c[4][2] = {{-1, -1}, {-1, 1}, {1, 1}, {1, -1}};
            for (int k = 0; k < 4; k++) {
                mote_vertex *p = &quad_v[q][k];
                memset(p, 0, sizeof *p);
                p->position[0] = c[k][0] * 1.5f;
                p->position[1] = c[k][1] * 1.2f;
                /* the two quads lean opposite ways and cross at z = 0 */
                p->position[2] = (q ? 0.8f : -0.6f) * c[k][0] + (q ? -0.3f : 0.4f) * c[k][1];
                p->normal[2] = -1;
            }
            s->meshes[q] = tu_mesh_of(quad_v[q], 4, quad_i, 6);
            s->meshes[q].material.color_set = true;
        }
        s->meshes[0].material.color = (mote_rgba){250, 60, 60, 255};
        s->meshes[1].material.color = (mote_rgba){60, 250, 90, 255};
        s->mesh_count = 2;
    }
}
