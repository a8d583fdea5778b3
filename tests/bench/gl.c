/*
 * gl.c - the same scenes drawn by Mesa's llvmpipe through OSMesa, for the
 * benchmark's comparison. Fixed-function OpenGL: the same camera (mote's
 * own view and projection matrices, depth remapped from [0,1] to GL's
 * [-1,1]), the same triangles from vertex buffers uploaded once, the same
 * texture, and per-vertex lighting by GL's lighting model, which for one
 * diffuse point or directional light with no specular term and constant
 * attenuation is mote's formula. Built with BENCH_OSMESA when
 * libosmesa6-dev is installed; otherwise every call says why not.
 */
#define _POSIX_C_SOURCE 200809L
#include "bench.h"

#include <stdio.h>
#include <stdlib.h>
#include <string.h>

#ifdef BENCH_OSMESA
#define GL_GLEXT_PROTOTYPES
#include <GL/osmesa.h>
#include <GL/gl.h>
#include <GL/glext.h>

typedef struct bench_gl_buffers {
    const mote_vertex *vertices;
    const uint32_t *indices;
    GLuint vbo, ibo;
} bench_gl_buffers;

struct bench_gl {
    OSMesaContext ctx;
    int w, h;
    uint8_t *color;
    float *depth;
    bench_gl_buffers *bufs;       /* one per distinct vertex/index array */
    int buf_count;
    int *mesh_buf;                /* mesh -> bufs index */
    const mote_texture **textures;
    GLuint *tex_names;
    int tex_count;
    char renderer[128];
};

static int bench_gl_texture(bench_gl *g, const mote_texture *t)
{
    for (int i = 0; i < g->tex_count; i++)
        if (g->textures[i] == t)
            return i;
    int i = g->tex_count++;
    g->textures = realloc((void *)g->textures, sizeof *g->textures * (size_t)g->tex_count);
    g->tex_names = realloc(g->tex_names, sizeof *g->tex_names * (size_t)g->tex_count);
    g->textures[i] = t;
    uint8_t *rgba = malloc((size_t)t->width * (size_t)t->height * 4);
    int stride = t->stride ? t->stride : t->width * mote_format_bytes(t->format);
    for (int y = 0; y < t->height; y++)
        mote_convert_row((const uint8_t *)t->pixels + (size_t)y * (size_t)stride, t->format,
                         rgba + (size_t)y * (size_t)t->width * 4, MOTE_FORMAT_RGBA8888, t->width);
    glGenTextures(1, &g->tex_names[i]);
    glBindTexture(GL_TEXTURE_2D, g->tex_names[i]);
    glPixelStorei(GL_UNPACK_ALIGNMENT, 1);
    /* the first row in memory is t = 0, as mote's v = 0 is the top row */
    glTexImage2D(GL_TEXTURE_2D, 0, GL_RGBA8, t->width, t->height, 0, GL_RGBA, GL_UNSIGNED_BYTE, rgba);
    free(rgba);
    return i;
}

bench_gl *bench_gl_create(const bench_scene *s, char *why, size_t why_size)
{
    bench_gl *g = calloc(1, sizeof *g);
    if (!g) {
        snprintf(why, why_size, "out of memory");
        return NULL;
    }
    g->w = s->width;
    g->h = s->height;
    g->color = malloc((size_t)g->w * (size_t)g->h * 4);
    g->depth = malloc((size_t)g->w * (size_t)g->h * sizeof(float));
    g->mesh_buf = calloc((size_t)s->mesh_count, sizeof *g->mesh_buf);
    g->ctx = OSMesaCreateContextExt(OSMESA_RGBA, 24, 0, 0, NULL);
    if (!g->color || !g->depth || !g->mesh_buf || !g->ctx
        || !OSMesaMakeCurrent(g->ctx, g->color, GL_UNSIGNED_BYTE, g->w, g->h)) {
        snprintf(why, why_size, "OSMesa could not create a %dx%d RGBA context", g->w, g->h);
        bench_gl_destroy(g);
        return NULL;
    }
    OSMesaPixelStore(OSMESA_Y_UP, 0); /* row 0 is the top row, as in mote */
    snprintf(g->renderer, sizeof g->renderer, "%s", (const char *)glGetString(GL_RENDERER));
    for (int i = 0; i < s->mesh_count; i++) {
        const mote_mesh *m = &s->meshes[i];
        int b = -1;
        for (int j = 0; j < g->buf_count; j++)
            if (g->bufs[j].vertices == m->vertices && g->bufs[j].indices == m->indices)
                b = j;
        if (b < 0) {
            b = g->buf_count++;
            g->bufs = realloc(g->bufs, sizeof *g->bufs * (size_t)g->buf_count);
            bench_gl_buffers *bb = &g->bufs[b];
            bb->vertices = m->vertices;
            bb->indices = m->indices;
            glGenBuffers(1, &bb->vbo);
            glBindBuffer(GL_ARRAY_BUFFER, bb->vbo);
            glBufferData(GL_ARRAY_BUFFER, (GLsizeiptr)(m->vertex_count * sizeof(mote_vertex)),
                         m->vertices, GL_STATIC_DRAW);
            glGenBuffers(1, &bb->ibo);
            glBindBuffer(GL_ELEMENT_ARRAY_BUFFER, bb->ibo);
            glBufferData(GL_ELEMENT_ARRAY_BUFFER, (GLsizeiptr)((m->index_count / 3 * 3) * sizeof(uint32_t)),
                         m->indices, GL_STATIC_DRAW);
        }
        g->mesh_buf[i] = b;
        if (m->material.texture)
            bench_gl_texture(g, m->material.texture);
    }
    glFinish();
    return g;
}

const char *bench_gl_renderer(const bench_gl *g)
{
    return g->renderer;
}

static GLint bench_gl_wrap(mote_wrap w)
{
    return w == MOTE_WRAP_CLAMP ? GL_CLAMP_TO_EDGE : w == MOTE_WRAP_MIRROR ? GL_MIRRORED_REPEAT : GL_REPEAT;
}

bool bench_gl_frame(bench_gl *g, bench_scene *s, const bench_mode *m, int f,
                    const uint8_t **rgba, uint8_t *cov)
{
    const mote_draw_desc *d = &m->draw;
    bool textured = d->mode == MOTE_MODE_TEXTURED || d->mode == MOTE_MODE_DEFAULT;
    if (d->mode != MOTE_MODE_FLAT && d->mode != MOTE_MODE_GOURAUD && !textured)
        return false;
    if (textured && d->perspective != MOTE_PERSPECTIVE_DEFAULT && d->perspective != MOTE_PERSPECTIVE_CORRECT)
        return false;
    if ((m->subpixel_bits != 0 && m->subpixel_bits != 8)
        || (m->depth != MOTE_DEPTH_FORMAT_DEFAULT && m->depth != MOTE_DEPTH_FORMAT_32))
        return false;
    bench_pose(s, f);
    OSMesaMakeCurrent(g->ctx, g->color, GL_UNSIGNED_BYTE, g->w, g->h);

    float view[16], proj[16];
    mote_camera_view_matrix(&s->frame.camera, view);
    mote_camera_projection_matrix(&s->frame.camera, (float)s->width / (float)s->height, proj);
    /* mote's depth z/w runs 0..1 (Direct3D); GL clips z to [-w, w]: z' = 2z - w */
    for (int c = 0; c < 4; c++)
        proj[c * 4 + 2] = 2.0f * proj[c * 4 + 2] - proj[c * 4 + 3];

    glViewport(0, 0, g->w, g->h);
    glClearColor(s->clear_color.r / 255.0f, s->clear_color.g / 255.0f, s->clear_color.b / 255.0f, 1.0f);
    glClearDepth(1.0);
    glClear(GL_COLOR_BUFFER_BIT | GL_DEPTH_BUFFER_BIT);
    glEnable(GL_DEPTH_TEST);
    glDepthFunc(GL_LESS);
    glDepthMask(d->no_depth_write ? GL_FALSE : GL_TRUE);
    if (d->no_depth_test)
        glDisable(GL_DEPTH_TEST);
    mote_cull cull = d->cull == MOTE_CULL_DEFAULT ? MOTE_CULL_BACK : d->cull;
    if (cull == MOTE_CULL_NONE) {
        glDisable(GL_CULL_FACE);
    } else {
        glEnable(GL_CULL_FACE);
        glCullFace(cull == MOTE_CULL_BACK ? GL_BACK : GL_FRONT);
    }
    /* the image is the same either way up, so clockwise on mote's screen is
     * clockwise as GL sees it */
    glFrontFace(d->front_face == MOTE_FRONT_CW ? GL_CW : GL_CCW);
    glShadeModel(d->mode == MOTE_MODE_FLAT ? GL_FLAT : GL_SMOOTH);

    glMatrixMode(GL_PROJECTION);
    glLoadMatrixf(proj);
    glMatrixMode(GL_MODELVIEW);
    glLoadMatrixf(view);
    glEnable(GL_LIGHTING);
    glEnable(GL_NORMALIZE);
    float amb[4] = {s->frame.ambient[0], s->frame.ambient[1], s->frame.ambient[2], 1.0f};
    glLightModelfv(GL_LIGHT_MODEL_AMBIENT, amb);
    for (int i = 0; i < 8; i++)
        glDisable(GL_LIGHT0 + i);
    for (int i = 0; i < s->frame.light_count && i < 8; i++) {
        const mote_light *l = &s->frame.lights[i];
        float col[3] = {l->color[0], l->color[1], l->color[2]};
        if (col[0] == 0.0f && col[1] == 0.0f && col[2] == 0.0f)
            col[0] = col[1] = col[2] = 1.0f;
        float k = l->intensity != 0.0f ? l->intensity : 1.0f;
        float diffuse[4] = {col[0] * k, col[1] * k, col[2] * k, 1.0f}, zero[4] = {0, 0, 0, 1};
        float pos[4];
        if (l->type == MOTE_LIGHT_POINT) {
            pos[0] = l->position[0]; pos[1] = l->position[1]; pos[2] = l->position[2]; pos[3] = 1.0f;
        } else if (l->type == MOTE_LIGHT_DIRECTIONAL) {
            pos[0] = -l->direction[0]; pos[1] = -l->direction[1]; pos[2] = -l->direction[2]; pos[3] = 0.0f;
        } else {
            continue;             /* hemispheric has no fixed-function twin */
        }
        GLenum L = (GLenum)(GL_LIGHT0 + i);
        glEnable(L);
        glLightfv(L, GL_POSITION, pos); /* through the view matrix, as GL wants */
        glLightfv(L, GL_DIFFUSE, diffuse);
        glLightfv(L, GL_AMBIENT, zero);
        glLightfv(L, GL_SPECULAR, zero);
    }

    glEnableClientState(GL_VERTEX_ARRAY);
    glEnableClientState(GL_NORMAL_ARRAY);
    int order = 0;
    for (int n = 0; n < s->mesh_count; n++) {
        int i = order ? s->mesh_count - 1 - n : n;
        const mote_mesh *mesh = &s->meshes[i];
        const mote_material *mat = &mesh->material;
        float mc[4] = {1, 1, 1, 1}, black[4] = {0, 0, 0, 1};
        if (mat->color_set) {
            mc[0] = mat->color.r / 255.0f;
            mc[1] = mat->color.g / 255.0f;
            mc[2] = mat->color.b / 255.0f;
        }
        glMaterialfv(GL_FRONT_AND_BACK, GL_AMBIENT_AND_DIFFUSE, mc);
        glMaterialfv(GL_FRONT_AND_BACK, GL_SPECULAR, black);
        glMaterialfv(GL_FRONT_AND_BACK, GL_EMISSION, black);
        bool tex = textured && mat->texture;
        if (tex) {
            int t = bench_gl_texture(g, mat->texture);
            glEnable(GL_TEXTURE_2D);
            glBindTexture(GL_TEXTURE_2D, g->tex_names[t]);
            GLint filt = d->filter == MOTE_FILTER_BILINEAR ? GL_LINEAR : GL_NEAREST;
            glTexParameteri(GL_TEXTURE_2D, GL_TEXTURE_MIN_FILTER, filt);
            glTexParameteri(GL_TEXTURE_2D, GL_TEXTURE_MAG_FILTER, filt);
            glTexParameteri(GL_TEXTURE_2D, GL_TEXTURE_WRAP_S, bench_gl_wrap(mat->wrap_u));
            glTexParameteri(GL_TEXTURE_2D, GL_TEXTURE_WRAP_T, bench_gl_wrap(mat->wrap_v));
            glTexEnvi(GL_TEXTURE_ENV, GL_TEXTURE_ENV_MODE, GL_MODULATE);
            float us = mat->u_scale != 0.0f ? mat->u_scale : 1.0f, vs = mat->v_scale != 0.0f ? mat->v_scale : 1.0f;
            float tm[16] = {us, 0, 0, 0, 0, vs, 0, 0, 0, 0, 1, 0, mat->u_offset, mat->v_offset, 0, 1};
            if (mat->v_origin_bottom) {   /* t = 1 - (v * vs + vo) */
                tm[5] = -vs;
                tm[13] = 1.0f - mat->v_offset;
            }
            glMatrixMode(GL_TEXTURE);
            glLoadMatrixf(tm);
            glMatrixMode(GL_MODELVIEW);
            glEnableClientState(GL_TEXTURE_COORD_ARRAY);
        } else {
            glDisable(GL_TEXTURE_2D);
            glDisableClientState(GL_TEXTURE_COORD_ARRAY);
        }
        float world[16], mv[16];
        mote_mesh_world_matrix(mesh, world);
        for (int c = 0; c < 4; c++)
            for (int r = 0; r < 4; r++) {
                float a = 0.0f;
                for (int k = 0; k < 4; k++)
                    a += view[k * 4 + r] * world[c * 4 + k];
                mv[c * 4 + r] = a;
            }
        glLoadMatrixf(mv);
        const bench_gl_buffers *bb = &g->bufs[g->mesh_buf[i]];
        glBindBuffer(GL_ARRAY_BUFFER, bb->vbo);
        glBindBuffer(GL_ELEMENT_ARRAY_BUFFER, bb->ibo);
        glVertexPointer(3, GL_FLOAT, sizeof(mote_vertex), (const void *)offsetof(mote_vertex, position));
        glNormalPointer(GL_FLOAT, sizeof(mote_vertex), (const void *)offsetof(mote_vertex, normal));
        glTexCoordPointer(2, GL_FLOAT, sizeof(mote_vertex), (const void *)offsetof(mote_vertex, uv));
        glDrawElements(GL_TRIANGLES, (GLsizei)(mesh->index_count / 3 * 3), GL_UNSIGNED_INT, (const void *)0);
    }
    glFinish();                   /* the image is in g->color now */
    *rgba = g->color;
    if (cov) {
        /* GL rows are bottom-up here whatever OSMESA_Y_UP says */
        glReadPixels(0, 0, g->w, g->h, GL_DEPTH_COMPONENT, GL_FLOAT, g->depth);
        for (int y = 0; y < g->h; y++)
            for (int x = 0; x < g->w; x++)
                cov[(size_t)y * (size_t)g->w + (size_t)x] = g->depth[(size_t)(g->h - 1 - y) * (size_t)g->w + (size_t)x] < 1.0f;
    }
    return true;
}

void bench_gl_destroy(bench_gl *g)
{
    if (!g)
        return;
    if (g->ctx) {
        OSMesaMakeCurrent(g->ctx, g->color, GL_UNSIGNED_BYTE, g->w, g->h);
        for (int i = 0; i < g->buf_count; i++) {
            glDeleteBuffers(1, &g->bufs[i].vbo);
            glDeleteBuffers(1, &g->bufs[i].ibo);
        }
        if (g->tex_count)
            glDeleteTextures(g->tex_count, g->tex_names);
        OSMesaDestroyContext(g->ctx);
    }
    free(g->bufs);
    free(g->mesh_buf);
    free((void *)g->textures);
    free(g->tex_names);
    free(g->color);
    free(g->depth);
    free(g);
}

#else /* no OSMesa */

struct bench_gl { int unused; };

bench_gl *bench_gl_create(const bench_scene *s, char *why, size_t why_size)
{
    (void)s;
    snprintf(why, why_size, "built without OSMesa (libosmesa6-dev was not installed)");
    return NULL;
}

bool bench_gl_frame(bench_gl *g, bench_scene *s, const bench_mode *m, int f,
                    const uint8_t **rgba, uint8_t *cov)
{
    (void)g; (void)s; (void)m; (void)f; (void)rgba; (void)cov;
    return false;
}

const char *bench_gl_renderer(const bench_gl *g)
{
    (void)g;
    return "none";
}

void bench_gl_destroy(bench_gl *g)
{
    (void)g;
}
#endif
