/*
 * gltf_mesh.c - a glTF mesh's primitives as mote draws them: vertices
 * (positions, normals, the uv set the material samples, COLOR_0) and a
 * triangle list made from any of the triangle modes, indexed or not (or
 * points and line segments, drawn in the core's points and wireframe
 * modes); flat normals where none are given; texture transforms applied to the
 * uvs; mirrored in z (matrix_fold.h).
 */
#include "gltf.h"

#include <math.h>
#include <stdio.h>
#include <string.h>

/* Which component types (and normalized) an attribute may have: bit
 * (componentType - 5120) * 2 + normalized. */
enum {
    MOTE__B = 1 << 0, MOTE__B_N = 1 << 1, MOTE__UB = 1 << 2, MOTE__UB_N = 1 << 3,
    MOTE__S = 1 << 4, MOTE__S_N = 1 << 5, MOTE__US = 1 << 6, MOTE__US_N = 1 << 7,
    MOTE__UI = 1 << 10, MOTE__F = 1 << 12,
    MOTE__INTS = MOTE__B | MOTE__B_N | MOTE__UB | MOTE__UB_N | MOTE__S | MOTE__S_N | MOTE__US |
                 MOTE__US_N,
};

/* attributes[name] (or, with attrs NULL, the primitive's indices at
 * obj[name]) as an accessor of comps components (or comps_alt) and of a
 * type in `types`; count, when not 0, must match. *present false when
 * absent. expected says what is read, for the message. */
static mote_result mote__gltf_attribute(mote__gltf *gl, const cJSON *obj, const char *name,
                                        const char *at, int comps, int comps_alt, unsigned types,
                                        uint32_t count, const char *expected,
                                        mote__gltf_accessor *a, bool *present)
{
    int index = -1;
    *present = false;
    MOTE__TRY(mote__gltf_index(gl, obj, name, at, gl->accessor_count, "accessor", &index));
    if (index < 0)
        return MOTE_OK;
    char use[160];
    snprintf(use, sizeof use, "%s.%s", at, name);
    MOTE__TRY(mote__gltf_resolve(gl, index, use, a));
    unsigned bit = 1u << ((a->ctype - 5120) * 2 + (a->normalized ? 1 : 0));
    if ((a->comps != comps && a->comps != comps_alt) || !(types & bit))
        return mote__fail(gl->load, MOTE_ERR_PARSE, "%s: accessors[%d] holds %d component%s of "
                          "type %u%s, expected %s", use, index, a->comps, a->comps > 1 ? "s" : "",
                          (unsigned)a->ctype, a->normalized ? " normalized" : "", expected);
    if (count && a->count != count)
        return mote__fail(gl->load, MOTE_ERR_PARSE, "%s: accessors[%d] has %u elements, but "
                          "POSITION has %u", use, index, (unsigned)a->count, (unsigned)count);
    *present = true;
    return MOTE_OK;
}

/* Element i of a as n floats, which must be finite. */
static mote_result mote__gltf_finite(mote__gltf *gl, const mote__gltf_accessor *a, uint32_t i,
                                     int n, const char *at, const char *name, float *out)
{
    mote__gltf_read_floats(a, i, n, out);
    for (int k = 0; k < n; k++)
        if (!isfinite(out[k]))
            return mote__fail(gl->load, MOTE_ERR_RANGE, "%s.%s[%u]: %g is not a finite number",
                              at, name, (unsigned)i, out[k]);
    return MOTE_OK;
}

/* Corners an element of a mode has, and how many elements n indices (or
 * vertices) make: POINTS one corner each, the lines two, the triangles
 * three. */
static int mote__gltf_corners(uint32_t mode)
{
    return mode == 0 ? 1 : mode < 4 ? 2 : 3;
}

static size_t mote__gltf_elements(uint32_t mode, uint32_t n)
{
    switch (mode) {
    case 0: return n;
    case 1: return n / 2;
    case 2: return n >= 2 ? n : 0;          /* LINE_LOOP: the last back to the first */
    case 3: return n >= 2 ? n - 1 : 0;
    case 4: return n / 3;
    default: return n >= 3 ? n - 2 : 0;     /* strips and fans */
    }
}

/* Which index (or vertex) corner j of element k of the mode reads. */
static uint32_t mote__gltf_corner(uint32_t mode, uint32_t n, size_t k, int j)
{
    switch (mode) {
    case 0: return (uint32_t)k;
    case 1: return (uint32_t)(2 * k) + (uint32_t)j;
    case 2: return j == 0 ? (uint32_t)k : (uint32_t)((k + 1) % n);
    case 3: return (uint32_t)k + (uint32_t)j;
    case 4: return (uint32_t)(3 * k) + (uint32_t)j;
    case 5:                       /* odd triangles turned, so all keep one winding */
        return j == 0 ? (uint32_t)k : (uint32_t)(k + (j == 1 ? 1 + k % 2 : 2 - k % 2));
    default:                      /* fan: (k + 1, k + 2, 0), as the specification orders it */
        return j == 2 ? 0 : (uint32_t)(k + 1) + (uint32_t)j;
    }
}

/* The primitive's elements as corners into its vertices, from indices
 * (or 0, 1, 2, ...), by mode: triangles three corners each; a line
 * segment (a, b) the triangle (a, b, b), whose wireframe is the segment;
 * a point one. *out_n: the corners. */
static mote_result mote__gltf_elements_read(mote__gltf *gl, const mote__gltf_accessor *ia,
                                            bool indexed, uint32_t nv, uint32_t mode,
                                            const char *at, uint32_t **out, uint32_t *out_n)
{
    uint32_t n = indexed ? ia->count : nv;
    int per = mote__gltf_corners(mode);
    size_t t = mote__gltf_elements(mode, n);
    if ((mode == 1 || mode == 4) && n % (uint32_t)per)
        mote__warn(gl->load, "%s: %u %s, not a multiple of %d; the last %u are not drawn", at,
                   (unsigned)n, indexed ? "indices" : "vertices", per, (unsigned)(n % (uint32_t)per));
    size_t stored = mode == 0 ? t : t * 3;
    MOTE__TRY(mote__check_count(gl->load, at, stored, mode == 0 ? "points" : "triangle corners",
                                gl->load->lim.max_indices));
    uint32_t *idx = mote__store_alloc(gl->load->keep, stored, sizeof *idx);
    if (!idx)
        return mote__oom(gl->load, at);
    for (size_t k = 0; k < t; k++) {
        uint32_t *e = idx + (mode == 0 ? k : 3 * k);
        for (int j = 0; j < per; j++) {
            uint32_t c = mote__gltf_corner(mode, n, k, j);
            uint32_t v = indexed ? mote__gltf_read_uint(ia, c) : c;
            if (v >= nv)
                return mote__fail(gl->load, MOTE_ERR_RANGE, "%s.indices[%u]: %u is out of range "
                                  "(%u vertices)", at, (unsigned)c, (unsigned)v, (unsigned)nv);
            e[j] = v;
        }
        if (per == 2)
            e[2] = e[1];
    }
    *out = idx;
    *out_n = (uint32_t)stored;
    return MOTE_OK;
}

/* Each corner its own vertex (and colour), in the corners' order: what
 * (for the limit's message) names why. */
static mote_result mote__gltf_unweld(mote__gltf *gl, mote__gltf_prim *p, const char *at,
                                     const char *what)
{
    MOTE__TRY(mote__check_count(gl->load, at, p->ni, what, gl->load->lim.max_vertices));
    mote_vertex *v = mote__store_alloc(gl->load->keep, p->ni, sizeof *v);
    mote_rgba *c = p->colors ? mote__store_alloc(gl->load->keep, p->ni, sizeof *c) : NULL;
    if (!v || (p->colors && !c))
        return mote__oom(gl->load, at);
    for (uint32_t k = 0; k < p->ni; k++) {
        v[k] = p->verts[p->idx[k]];
        if (c)
            c[k] = p->colors[p->idx[k]];
    }
    p->verts = v;
    p->colors = c;
    p->nv = p->ni;
    return MOTE_OK;
}

/* The vertices the points name, in order, and no indices: the core
 * draws a points mesh's every vertex. */
static mote_result mote__gltf_point_vertices(mote__gltf *gl, mote__gltf_prim *p, const char *at)
{
    MOTE__TRY(mote__gltf_unweld(gl, p, at, "vertices (points)"));
    p->idx = NULL;
    p->ni = 0;
    return MOTE_OK;
}

/* Unwelds the triangles (each its own three vertices) and gives each the
 * normal of its plane: the specification's flat normals for a primitive
 * without NORMAL. */
static mote_result mote__gltf_flat_normals(mote__gltf *gl, mote__gltf_prim *p, const char *at)
{
    MOTE__TRY(mote__gltf_unweld(gl, p, at, "vertices (flat normals: three a triangle)"));
    mote_vertex *v = p->verts;
    for (uint32_t k = 0; k + 2 < p->ni; k += 3) {
        double e1[3], e2[3], n[3];
        for (int j = 0; j < 3; j++) {
            e1[j] = (double)v[k + 1].position[j] - v[k].position[j];
            e2[j] = (double)v[k + 2].position[j] - v[k].position[j];
        }
        n[0] = e1[1] * e2[2] - e1[2] * e2[1];
        n[1] = e1[2] * e2[0] - e1[0] * e2[2];
        n[2] = e1[0] * e2[1] - e1[1] * e2[0];
        double len = sqrt(n[0] * n[0] + n[1] * n[1] + n[2] * n[2]);
        for (int j = 0; j < 3 && len > 0.0; j++)
            v[k].normal[j] = v[k + 1].normal[j] = v[k + 2].normal[j] = (float)(n[j] / len);
        p->idx[k] = k, p->idx[k + 1] = k + 1, p->idx[k + 2] = k + 2;
    }
    return MOTE_OK;
}

/* The vertices of a primitive from its attributes. */
static mote_result mote__gltf_vertices(mote__gltf *gl, const cJSON *attrs, const char *at,
                                       const mote__gltf_mat *mm, const mote__gltf_accessor *pos,
                                       mote__gltf_prim *p, bool *has_normals)
{
    const unsigned q = gl->quantized ? MOTE__INTS : 0;
    mote__gltf_accessor nrm, uv, col;
    bool has_uv, has_col;
    char uv_name[24];
    snprintf(uv_name, sizeof uv_name, "TEXCOORD_%d", mm->tex_coord);
    char attr_at[MOTE__GLTF_AT + 40];
    snprintf(attr_at, sizeof attr_at, "%s.attributes", at);
    MOTE__TRY(mote__gltf_attribute(gl, attrs, "NORMAL", attr_at, 3, 3,
                                   MOTE__F | (q ? MOTE__B_N | MOTE__S_N : 0), p->nv,
                                   q ? "VEC3 of floats or normalized bytes or shorts "
                                       "(KHR_mesh_quantization)" : "VEC3 of floats (5126)",
                                   &nrm, has_normals));
    MOTE__TRY(mote__gltf_attribute(gl, attrs, uv_name, attr_at, 2, 2,
                                   MOTE__F | MOTE__UB_N | MOTE__US_N | q, p->nv,
                                   q ? "VEC2 of floats or integers (KHR_mesh_quantization)"
                                     : "VEC2 of floats or normalized unsigned bytes or shorts",
                                   &uv, &has_uv));
    MOTE__TRY(mote__gltf_attribute(gl, attrs, "COLOR_0", attr_at, 3, 4,
                                   MOTE__F | MOTE__UB_N | MOTE__US_N, p->nv,
                                   "VEC3 or VEC4 of floats or normalized unsigned bytes or shorts",
                                   &col, &has_col));
    p->verts = mote__store_alloc(gl->load->keep, p->nv, sizeof *p->verts);
    p->colors = has_col ? mote__store_alloc(gl->load->keep, p->nv, sizeof *p->colors) : NULL;
    if (!p->verts || (has_col && !p->colors))
        return mote__oom(gl->load, at);
    const float *t = mm->uv_transform;
    for (uint32_t i = 0; i < p->nv; i++) {
        mote_vertex *v = &p->verts[i];
        MOTE__TRY(mote__gltf_finite(gl, pos, i, 3, attr_at, "POSITION", v->position));
        if (*has_normals)
            MOTE__TRY(mote__gltf_finite(gl, &nrm, i, 3, attr_at, "NORMAL", v->normal));
        if (has_uv) {
            float u[2];
            MOTE__TRY(mote__gltf_finite(gl, &uv, i, 2, attr_at, uv_name, u));
            /* glTF's v = 0 is the image's top row, as mote's default */
            v->uv[0] = mm->has_uv_transform ? t[0] * u[0] + t[2] * u[1] + t[4] : u[0];
            v->uv[1] = mm->has_uv_transform ? t[1] * u[0] + t[3] * u[1] + t[5] : u[1];
        }
        if (has_col) {
            float c[4];
            mote__gltf_read_floats(&col, i, 3, c);
            p->colors[i] = (mote_rgba){mote__gltf_srgb_byte(c[0]), mote__gltf_srgb_byte(c[1]),
                                       mote__gltf_srgb_byte(c[2]), 255};
        }
    }
    return MOTE_OK;
}

/* meshes[m].primitives[k] into p. */
static mote_result mote__gltf_primitive(mote__gltf *gl, const cJSON *prim, const char *at,
                                        mote__gltf_prim *p)
{
    MOTE__TRY(mote__json_object(gl->load, prim, at));
    const cJSON *attrs = mote__json_get(prim, "attributes");
    char attr_at[MOTE__GLTF_AT + 40];
    snprintf(attr_at, sizeof attr_at, "%s.attributes", at);
    if (!attrs)
        return mote__fail(gl->load, MOTE_ERR_PARSE, "%s: missing \"attributes\"", at);
    MOTE__TRY(mote__json_object(gl->load, attrs, attr_at));
    uint32_t mode = 4;
    MOTE__TRY(mote__json_uint_member(gl->load, prim, "mode", at, 6, &mode));
    p->material = -1;
    MOTE__TRY(mote__gltf_index(gl, prim, "material", at, gl->mat_count, "material",
                               &p->material));
    if (mote__json_get(prim, "targets"))
        mote__warn(gl->load, "morph targets: not applied (meshes are drawn at rest)");
    mote__gltf_accessor pos, ia;
    bool has_pos, indexed;
    const unsigned q = gl->quantized ? MOTE__INTS : 0;
    MOTE__TRY(mote__gltf_attribute(gl, attrs, "POSITION", attr_at, 3, 3, MOTE__F | q, 0,
                                   q ? "VEC3 of floats or integers (KHR_mesh_quantization)"
                                     : "VEC3 of floats (5126)", &pos, &has_pos));
    if (!has_pos) {
        mote__warn(gl->load, "%s: no POSITION; not drawn", at);
        return MOTE_OK;
    }
    MOTE__TRY(mote__check_count(gl->load, attr_at, pos.count, "vertices",
                                gl->load->lim.max_vertices));
    MOTE__TRY(mote__gltf_attribute(gl, prim, "indices", at, 1, 1,
                                   MOTE__UB | MOTE__US | MOTE__UI, 0,
                                   "SCALAR of unsigned bytes, shorts or ints", &ia, &indexed));
    if (indexed)
        MOTE__TRY(mote__check_count(gl->load, at, ia.count, "indices", gl->load->lim.max_indices));
    const mote__gltf_mat *mm;
    MOTE__TRY(mote__gltf_material(gl, p->material, &mm));
    p->nv = pos.count;
    bool has_normals;
    MOTE__TRY(mote__gltf_vertices(gl, attrs, at, mm, &pos, p, &has_normals));
    MOTE__TRY(mote__gltf_elements_read(gl, &ia, indexed, p->nv, mode, at, &p->idx, &p->ni));
    /* points and lines are drawn unlit, in the material colour: no normals */
    p->mode = mode == 0 ? MOTE_MODE_POINTS : mode < 4 ? MOTE_MODE_WIREFRAME : MOTE_MODE_DEFAULT;
    if (mode == 0)
        MOTE__TRY(mote__gltf_point_vertices(gl, p, at));
    else if (!has_normals && mode >= 4)
        MOTE__TRY(mote__gltf_flat_normals(gl, p, at));
    /* right-handed to mote's left-handed space (matrix_fold.h); the
     * mirror turns glTF's counter-clockwise fronts into mote's */
    for (uint32_t i = 0; i < p->nv; i++) {
        mote__mirror_point(p->verts[i].position);
        mote__mirror_point(p->verts[i].normal);
    }
    p->drawn = mode == 0 ? p->nv > 0 : p->ni > 0;
    return MOTE_OK;
}

mote_result mote__gltf_mesh_read(mote__gltf *gl, int index)
{
    mote__gltf_mesh *mesh = &gl->meshes[index];
    if (mesh->read)
        return MOTE_OK;
    const cJSON *obj;
    char at[MOTE__GLTF_AT];
    MOTE__TRY(mote__gltf_item(gl, "meshes", index, &obj, at));
    const cJSON *prims;
    MOTE__TRY(mote__json_array(gl->load, obj, "primitives", at, &prims));
    size_t n = mote__json_length(prims);
    if (!n)
        return mote__fail(gl->load, MOTE_ERR_PARSE, "%s.primitives: missing or empty", at);
    MOTE__TRY(mote__check_count(gl->load, at, n, "primitives", gl->load->lim.max_meshes));
    mesh->prims = mote__store_alloc(&gl->load->tmp, n, sizeof *mesh->prims);
    if (!mesh->prims)
        return mote__oom(gl->load, at);
    int k = 0;
    for (const cJSON *p = prims->child; p; p = p->next, k++) {
        char pat[MOTE__GLTF_AT + 24];
        snprintf(pat, sizeof pat, "%s.primitives[%d]", at, k);
        MOTE__TRY(mote__gltf_primitive(gl, p, pat, &mesh->prims[k]));
    }
    mesh->prim_count = k;
    mesh->read = true;
    return MOTE_OK;
}
