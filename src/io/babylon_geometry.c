/*
 * babylon_geometry.c - a .babylon mesh's vertex arrays (the legacy
 * interleaved `vertices` or the current `positions`, `normals`, `uvs`,
 * `colors`, inline or in geometries.vertexData), its indices and
 * sub-meshes, every value checked before it is used.
 */
#include "babylon.h"

#include <cglm/vec3.h>
#include <float.h>
#include <math.h>
#include <stdio.h>
#include <string.h>

enum { MOTE__POS, MOTE__NRM, MOTE__UV, MOTE__UV2, MOTE__LEGACY };

/* Fills nd->verts (and nd->uv2 when it is there) from arr. */
static mote_result mote__fill_vertices(mote__babylon *bl, const cJSON *arr, const char *at,
                                       mote__node *nd, int what, size_t stride)
{
    mote_vertex *v = nd->verts;
    size_t k = 0;
    for (const cJSON *e = arr->child; e; e = e->next, k++) {
        float f;
        MOTE__TRY(mote__json_element_float(bl->load, e, at, k, &f));
        mote_vertex *vx = &v[k / stride];
        size_t c = k % stride;
        switch (what) {
        case MOTE__POS: vx->position[c] = f; break;
        case MOTE__NRM: vx->normal[c] = f; break;
        case MOTE__UV: vx->uv[c] = f; break;
        case MOTE__UV2: nd->uv2[k] = f; break;
        default:
            if (c < 3)
                vx->position[c] = f;
            else if (c < 6)
                vx->normal[c - 3] = f;
            else if (c < 8)
                vx->uv[c - 6] = f;
            else if (nd->uv2)
                nd->uv2[k / stride * 2 + c - 8] = f;
            break; /* uv2 is checked, and kept only when a material needs it */
        }
    }
    return MOTE_OK;
}

mote_result mote__babylon_indices(mote__babylon *bl, const cJSON *arr, const char *at,
                                  mote__node *nd, uint32_t *max_index)
{
    size_t n = mote__json_length(arr);
    *max_index = 0;
    MOTE__TRY(mote__check_count(bl->load, at, n, "indices", bl->load->lim.max_indices));
    if (n % 3)
        return mote__fail(bl->load, MOTE_ERR_RANGE, "%s: %zu indices is not a multiple of 3", at,
                          n);
    nd->idx = mote__store_alloc(bl->load->keep, n, sizeof *nd->idx);
    if (!nd->idx)
        return mote__oom(bl->load, at);
    nd->ni = (uint32_t)n;
    size_t k = 0;
    for (const cJSON *e = arr->child; e; e = e->next, k++) {
        double d = cJSON_IsNumber(e) ? e->valuedouble : -1.0;
        if (!(d >= 0.0 && d <= 4294967294.0 && d == floor(d))) {
            char at2[192];
            snprintf(at2, sizeof at2, "%s[%zu]", at, k);
            if (!cJSON_IsNumber(e))
                return mote__fail(bl->load, MOTE_ERR_PARSE, "%s: expected an integer, found %s",
                                  at2, mote__json_type_name(e));
            if (!isfinite(d) || d != floor(d))
                return mote__fail(bl->load, MOTE_ERR_PARSE, "%s: %g is not an integer", at2, d);
            return mote__fail(bl->load, MOTE_ERR_RANGE, "%s: %.17g is out of range", at2, d);
        }
        nd->idx[k] = (uint32_t)d;
        if (nd->idx[k] > *max_index)
            *max_index = nd->idx[k];
    }
    if (bl->right_handed)
        mote__flip_winding(nd->idx, nd->ni);
    return MOTE_OK;
}

mote_result mote__babylon_check_indices(mote__babylon *bl, const char *at, const mote__node *nd)
{
    for (uint32_t k = 0; k < nd->ni; k++)
        if (nd->idx[k] >= nd->nv) {
            /* where the file has it: a right-handed scene's triangles are
             * flipped already (mote__flip_winding swaps corners 1 and 2) */
            uint32_t in_file = k;
            if (bl->right_handed && k % 3 && k - k % 3 + 2 < nd->ni)
                in_file = k % 3 == 1 ? k + 1 : k - 1;
            return mote__fail(bl->load, MOTE_ERR_RANGE, "%s[%u]: %u is out of range (%u vertices)",
                              at, (unsigned)in_file, (unsigned)nd->idx[k], (unsigned)nd->nv);
        }
    return MOTE_OK;
}

static mote_result mote__alloc_vertices(mote__babylon *bl, const char *at, size_t nv,
                                        mote__node *nd)
{
    MOTE__TRY(mote__check_count(bl->load, at, nv, "vertices", bl->load->lim.max_vertices));
    nd->verts = mote__store_alloc(bl->load->keep, nv, sizeof *nd->verts);
    if (!nd->verts)
        return mote__oom(bl->load, at);
    nd->nv = (uint32_t)nv;
    return MOTE_OK;
}

/* A right-handed scene's positions and normals, mirrored (their
 * triangles are flipped as the indices are read: mote__babylon_indices). */
static void mote__mirror_vertices(const mote__babylon *bl, mote__node *nd)
{
    if (!bl->right_handed)
        return;
    for (uint32_t i = 0; i < nd->nv; i++) {
        mote__mirror_point(nd->verts[i].position);
        mote__mirror_point(nd->verts[i].normal);
    }
}

/* Smooth normals where a file has none: the sum of the faces' normals as
 * Babylon's VertexData.ComputeNormals orients them (left-handed, clockwise
 * front faces), normalised. */
static void mote__smooth_normals(mote__node *nd)
{
    for (uint32_t t = 0; t + 2 < nd->ni; t += 3) {
        float *p1 = nd->verts[nd->idx[t]].position;
        float *p2 = nd->verts[nd->idx[t + 1]].position;
        float *p3 = nd->verts[nd->idx[t + 2]].position;
        vec3 a, b, n;
        glm_vec3_sub(p1, p2, a);
        glm_vec3_sub(p3, p2, b);
        glm_vec3_cross(a, b, n);
        float len = glm_vec3_norm(n);
        if (!(len > 0.0f) || !isfinite(len))
            continue;
        for (int j = 0; j < 3; j++)
            for (int k = 0; k < 3; k++)
                nd->verts[nd->idx[t + j]].normal[k] += n[k] / len;
    }
    for (uint32_t i = 0; i < nd->nv; i++) {
        float *n = nd->verts[i].normal;
        float len = glm_vec3_norm(n);
        if (len > 0.0f && isfinite(len))
            for (int k = 0; k < 3; k++)
                n[k] /= len;
    }
}

/* The legacy interleaved layout: position, normal, uv (uvCount >= 1) and
 * uv2 (uvCount 2) per vertex. */
mote_result mote__babylon_legacy_geometry(mote__babylon *bl, const cJSON *mesh, const cJSON *verts,
                                          const char *where, mote__node *nd)
{
    char at[96], iat[96];
    snprintf(at, sizeof at, "%s.vertices", where);
    snprintf(iat, sizeof iat, "%s.indices", where);
    const cJSON *ind;
    MOTE__TRY(mote__json_array(bl->load, mesh, "indices", where, &ind));
    uint32_t max_index = 0;
    if (ind)
        MOTE__TRY(mote__babylon_indices(bl, ind, iat, nd, &max_index));
    size_t len = mote__json_length(verts);
    size_t stride = 0;
    uint32_t u = 0;
    if (mote__json_get(mesh, "uvCount")) {
        MOTE__TRY(mote__json_uint_member(bl->load, mesh, "uvCount", where, 2, &u));
        stride = 6 + 2 * (size_t)u;
        if (len % stride)
            return mote__fail(bl->load, MOTE_ERR_RANGE,
                              "%s: %zu floats is not a multiple of %zu (uvCount %u)", at, len,
                              stride, (unsigned)u);
    } else {
        /* no uvCount: the stride must be the only one that fits the length
         * and the largest index */
        int fits = 0;
        for (size_t s = 6; s <= 10; s += 2)
            if (len % s == 0 && (nd->ni == 0 || max_index < len / s)) {
                fits++;
                stride = s;
            }
        if (len == 0)
            fits = 1, stride = 6;
        if (fits != 1)
            return mote__fail(bl->load, MOTE_ERR_PARSE,
                              "%s: no uvCount, and %zu floats fit %s stride (6, 8 or 10)", at,
                              len, fits ? "more than one" : "no");
    }
    MOTE__TRY(mote__alloc_vertices(bl, at, len / stride, nd));
    if (stride == 10 && bl->any_uv2) {
        nd->uv2 = mote__store_alloc(&bl->load->tmp, nd->nv, 2 * sizeof *nd->uv2);
        if (!nd->uv2)
            return mote__oom(bl->load, at);
    }
    MOTE__TRY(mote__fill_vertices(bl, verts, at, nd, MOTE__LEGACY, stride));
    mote__mirror_vertices(bl, nd);
    nd->legacy = true;
    return mote__babylon_check_indices(bl, iat, nd);
}

/* Vertex colours: 4 floats per vertex (r, g, b, a), or 3 (alpha 1), told
 * apart by the length; each 0..1, rounded to a byte and clamped. */
static mote_result mote__colors(mote__babylon *bl, const cJSON *arr, const char *at, mote__node *nd)
{
    size_t n = mote__json_length(arr), nv = nd->nv;
    if (n == 0 && nv == 0)
        return MOTE_OK;           /* nothing to colour */
    /* n is 4 or 3 per vertex: mote__check_vertex_counts */
    size_t stride = n == nv * 4 ? 4 : 3;
    nd->colors = mote__store_alloc(bl->load->keep, nv, sizeof *nd->colors);
    if (!nd->colors)
        return mote__oom(bl->load, at);
    size_t k = 0;
    for (const cJSON *e = arr->child; e; e = e->next, k++) {
        float f;
        MOTE__TRY(mote__json_element_float(bl->load, e, at, k, &f));
        (&nd->colors[k / stride].r)[k % stride] = mote__unit_byte(f);
    }
    if (stride == 3)
        for (size_t i = 0; i < nv; i++)
            nd->colors[i].a = 255;
    return MOTE_OK;
}

/* Gives to the vertex and index arrays of from: shared, not copied. */
void mote__babylon_share_arrays(mote__node *to, mote__node *from)
{
    to->arrays = from->arrays ? from->arrays : from;
    to->uv2 = from->uv2;
    to->verts = from->verts;
    to->nv = from->nv;
    to->colors = from->colors;
    to->idx = from->idx;
    to->ni = from->ni;
}

/* An array of the current layout that has `per` floats for each vertex
 * (colours: `per`, or `per_alt` without alpha; 0: no second length). */
typedef struct mote__vertex_array {
    const char *key;
    const cJSON *arr;             /* NULL: absent */
    size_t per, per_alt;
} mote__vertex_array;

/* Every array present must have as many vertices as positions gives
 * (nv). When one has not, the message names each that disagrees and the
 * vertex count its length gives, so that a positions array one vertex
 * short is not blamed on the normals. */
static mote_result mote__check_vertex_counts(mote__babylon *bl, const char *where, size_t nv,
                                             const mote__vertex_array *arrays, int count)
{
    char list[320];
    size_t used = 0;
    list[0] = '\0';
    for (int i = 0; i < count; i++) {
        const mote__vertex_array *a = &arrays[i];
        size_t n = mote__json_length(a->arr);
        if (!a->arr || n == nv * a->per || (a->per_alt && n == nv * a->per_alt))
            continue;
        char gives[48];
        if (a->per_alt)
            snprintf(gives, sizeof gives, "not %zu or %zu per vertex", a->per, a->per_alt);
        else if (n % a->per)
            snprintf(gives, sizeof gives, "not a multiple of %zu", a->per);
        else
            snprintf(gives, sizeof gives, "%zu vertices", n / a->per);
        int w = snprintf(list + used, sizeof list - used, "%s%s has %zu floats (%s)",
                         used ? ", " : "", a->key, n, gives);
        if (w > 0)
            used += (size_t)w < sizeof list - used ? (size_t)w : sizeof list - used - 1;
    }
    if (used == 0)
        return MOTE_OK;
    return mote__fail(bl->load, MOTE_ERR_RANGE,
                      "%s: positions has %zu floats (%zu vertices), but %s", where, 3 * nv, nv,
                      list);
}

/* arr (where.key): `per` floats for each of nd's vertices (the length is
 * checked by mote__check_vertex_counts), into the part `what` says (uvs2
 * get their temporary array here). */
static mote_result mote__per_vertex(mote__babylon *bl, const cJSON *arr, const char *where,
                                    const char *key, size_t per, int what, mote__node *nd)
{
    char at[96];
    snprintf(at, sizeof at, "%s.%s", where, key);
    size_t nv = nd->nv;
    if (what == MOTE__UV2) {
        nd->uv2 = mote__store_alloc(&bl->load->tmp, nv, 2 * sizeof *nd->uv2);
        if (!nd->uv2)
            return mote__oom(bl->load, at);
        per = 1;                  /* a flat array */
    }
    return mote__fill_vertices(bl, arr, at, nd, what, per);
}

/* The indices first, first + 1, ... (count of them: vertices drawn as
 * triangles in their order), the triangles flipped in a right-handed
 * scene. */
static void mote__sequential_run(const mote__babylon *bl, uint32_t *idx, uint32_t first,
                                 uint32_t count)
{
    for (uint32_t k = 0; k < count; k++)
        idx[k] = first + k;
    if (bl->right_handed)
        mote__flip_winding(idx, count);
}

/* isUnIndexed: Babylon.js draws vertices 0,1,2 / 3,4,5 / ... as triangles
 * and ignores any indices. The indices 0..nv-1 let the core draw it as any
 * other mesh; the whole mesh draws the first nv - nv % 3 of them (a partial
 * last triangle is dropped, as drawArrays drops it), and a sub-mesh its own
 * vertex range (mote__babylon_submeshes). */
static mote_result mote__sequential_indices(mote__babylon *bl, const char *where, mote__node *nd)
{
    if (nd->nv > bl->load->lim.max_indices)
        return mote__fail(bl->load, MOTE_ERR_LIMIT, "%s: isUnIndexed: %u vertices, more indices "
                          "than the limit of %u", where, (unsigned)nd->nv,
                          (unsigned)bl->load->lim.max_indices);
    if (nd->nv % 3)
        mote__warn(bl->load, "%s: isUnIndexed, but %u vertices is not a multiple of 3; the last %u "
                   "are not drawn", where, (unsigned)nd->nv, (unsigned)(nd->nv % 3));
    nd->idx = mote__store_alloc(bl->load->keep, nd->nv, sizeof *nd->idx);
    if (!nd->idx)
        return mote__oom(bl->load, where);
    mote__sequential_run(bl, nd->idx, 0, nd->nv);
    nd->ni = nd->nv - nd->nv % 3;
    return MOTE_OK;
}

/* The current layout, from the mesh itself or from a geometries.vertexData
 * entry (src, named `where` in messages); nd->unindexed is the mesh's. */
mote_result mote__babylon_current_geometry(mote__babylon *bl, const cJSON *src, const char *where,
                                           mote__node *nd)
{
    const cJSON *pos, *nrm, *uvs, *uvs2 = NULL, *colors, *ind;
    /* null is no geometry to Babylon.js, but a file that writes it means
     * positions it lost: said here rather than by the indices it leaves
     * out of range */
    if (cJSON_IsNull(mote__json_member(src, "positions")))
        return mote__fail(bl->load, MOTE_ERR_PARSE, "%s.positions: expected an array of "
                          "numbers, found null", where);
    MOTE__TRY(mote__json_array(bl->load, src, "positions", where, &pos));
    MOTE__TRY(mote__json_array(bl->load, src, "normals", where, &nrm));
    MOTE__TRY(mote__json_array(bl->load, src, "uvs", where, &uvs));
    if (bl->any_uv2)
        MOTE__TRY(mote__json_array(bl->load, src, "uvs2", where, &uvs2));
    MOTE__TRY(mote__json_array(bl->load, src, "colors", where, &colors));
    MOTE__TRY(mote__json_array(bl->load, src, "indices", where, &ind));
    char at[96], iat[96];
    snprintf(iat, sizeof iat, "%s.indices", where);
    uint32_t max_index;
    if (ind && !nd->unindexed)
        MOTE__TRY(mote__babylon_indices(bl, ind, iat, nd, &max_index));
    size_t len = mote__json_length(pos);
    snprintf(at, sizeof at, "%s.positions", where);
    if (len % 3)
        return mote__fail(bl->load, MOTE_ERR_RANGE, "%s: %zu floats is not a multiple of 3", at,
                          len);
    size_t nv = len / 3;
    const mote__vertex_array arrays[4] = {
        {"normals", nrm, 3, 0}, {"uvs", uvs, 2, 0}, {"uvs2", uvs2, 2, 0}, {"colors", colors, 4, 3}};
    MOTE__TRY(mote__check_vertex_counts(bl, where, nv, arrays, 4));
    MOTE__TRY(mote__alloc_vertices(bl, at, nv, nd));
    if (nd->unindexed)
        MOTE__TRY(mote__sequential_indices(bl, where, nd));
    else if (!ind && nv > 0)
        mote__warn(bl->load, "%s: has positions but no indices (and no isUnIndexed): it draws no "
                   "triangles", where);
    if (pos)
        MOTE__TRY(mote__fill_vertices(bl, pos, at, nd, MOTE__POS, 3));
    if (nrm)
        MOTE__TRY(mote__per_vertex(bl, nrm, where, "normals", 3, MOTE__NRM, nd));
    if (uvs)
        MOTE__TRY(mote__per_vertex(bl, uvs, where, "uvs", 2, MOTE__UV, nd));
    if (uvs2)
        MOTE__TRY(mote__per_vertex(bl, uvs2, where, "uvs2", 2, MOTE__UV2, nd));
    if (colors) {
        snprintf(at, sizeof at, "%s.colors", where);
        MOTE__TRY(mote__colors(bl, colors, at, nd));
    }
    MOTE__TRY(mote__babylon_check_indices(bl, iat, nd));
    /* mirrored before smooth normals are made: from mirrored positions and
     * flipped triangles they come out as the file's, mirrored */
    mote__mirror_vertices(bl, nd);
    if (!nrm)
        mote__smooth_normals(nd);
    return MOTE_OK;
}

mote_result mote__babylon_submeshes(mote__babylon *bl, const cJSON *mesh, const char *where,
                                    mote__node *nd)
{
    const cJSON *subs;
    MOTE__TRY(mote__json_array(bl->load, mesh, "subMeshes", where, &subs));
    size_t n = mote__json_length(subs);
    if (n > bl->load->lim.max_meshes)
        return mote__fail(bl->load, MOTE_ERR_LIMIT,
                          "%s.subMeshes: %zu entries, more than the limit "
                          "of %u",
                          where, n, (unsigned)bl->load->lim.max_meshes);
    if (n == 0)
        return MOTE_OK;
    nd->subs = mote__store_alloc(&bl->load->tmp, n, sizeof *nd->subs);
    if (!nd->subs)
        return mote__oom(bl->load, where);
    int k = 0;
    for (const cJSON *s = subs->child; s; s = s->next, k++) {
        char at[96], at2[128];
        snprintf(at, sizeof at, "%s.subMeshes[%d]", where, k);
        MOTE__TRY(mote__json_object(bl->load, s, at));
        static const char *const keys[5] = {"materialIndex", "verticesStart", "verticesCount",
                                             "indexStart", "indexCount"};
        uint32_t v[5] = {0, 0, nd->nv, 0, nd->ni};
        for (int j = 0; j < 5; j++) {
            const cJSON *e = mote__json_get(s, keys[j]);
            snprintf(at2, sizeof at2, "%s.%s", at, keys[j]);
            if (!e) {
                if (j == 4 && !nd->unindexed)
                    return mote__fail(bl->load, MOTE_ERR_PARSE, "%s: missing", at2);
                continue;
            }
            MOTE__TRY(mote__json_uint(bl->load, e, at2, 0, 4294967295.0, &v[j]));
        }
        if ((uint64_t)v[1] + v[2] > nd->nv)
            return mote__fail(bl->load, MOTE_ERR_RANGE, "%s: vertices %u..%llu are out of range "
                              "(%u vertices)", at, (unsigned)v[1],
                              (unsigned long long)v[1] + v[2], (unsigned)nd->nv);
        nd->subs[k].material_index = v[0];
        if (nd->unindexed) {
            /* drawn as drawArrays(verticesStart, verticesCount): the
             * sequential indices from verticesStart, whole triangles only */
            nd->subs[k].index_start = v[1];
            nd->subs[k].index_count = v[2] - v[2] % 3;
            if (bl->right_handed && v[1] % 3) {
                /* one run per start modulo 3, shared: a copy per
                 * sub-mesh grew as sub-meshes x vertices */
                uint32_t r = v[1] % 3, **run = &nd->shifted_runs[r - 1];
                if (!*run) {
                    *run = mote__store_alloc(bl->load->keep, nd->nv - r, sizeof(uint32_t));
                    if (!*run)
                        return mote__oom(bl->load, at);
                    mote__sequential_run(bl, *run, r, nd->nv - r);
                }
                nd->subs[k].own_indices = *run + (v[1] - r);
            }
            continue;
        }
        if ((uint64_t)v[3] + v[4] > nd->ni)
            return mote__fail(bl->load, MOTE_ERR_RANGE, "%s: indices %u..%llu are out of range "
                              "(%u indices)", at, (unsigned)v[3],
                              (unsigned long long)v[3] + v[4], (unsigned)nd->ni);
        if (v[3] % 3 || v[4] % 3)
            return mote__fail(bl->load, MOTE_ERR_RANGE, "%s: indexStart %u and indexCount %u must "
                              "be multiples of 3", at, (unsigned)v[3], (unsigned)v[4]);
        nd->subs[k].index_start = v[3];
        nd->subs[k].index_count = v[4];
    }
    nd->sub_count = k;
    return MOTE_OK;
}

/* ---- what a (sub-)mesh draws ------------------------------------------- */

/* Points m (of node nd) at vertices whose uv is uvs2, made once per
 * shared vertex array; without uvs2, m keeps uvs (warned). */
mote_result mote__babylon_uv2_vertices(mote__babylon *bl, mote__node *nd, mote_mesh *m)
{
    mote__node *owner = nd->arrays ? nd->arrays : nd;
    if (!owner->uv2) {
        if (owner->nv)
            mote__warn(bl->load, "%s: its texture samples uvs2 (coordinatesIndex 1), which the "
                       "mesh lacks; uvs are used", nd->where);
        return MOTE_OK;
    }
    if (!owner->verts2) {
        owner->verts2 = mote__store_alloc(bl->load->keep, owner->nv, sizeof *owner->verts2);
        if (!owner->verts2)
            return mote__oom(bl->load, nd->where);
        for (uint32_t i = 0; i < owner->nv; i++) {
            owner->verts2[i] = owner->verts[i];
            owner->verts2[i].uv[0] = owner->uv2[2 * i];
            owner->verts2[i].uv[1] = owner->uv2[2 * i + 1];
        }
    }
    m->vertices = owner->verts2;
    return MOTE_OK;
}

/* Points m, (sub-)mesh s of node nd, at triangles with their last two
 * corners swapped when its side orientation turns its front faces round.
 * Babylon.js culls by the mesh's overrideMaterialSideOrientation, else by
 * its material's sideOrientation (Mesh._processRendering; the glTF loader
 * sets it on each mesh, and exports of glTF scenes keep it), whose
 * default is Material.CounterClockWiseSideOrientation, 1, in a
 * left-handed scene and ClockWiseSideOrientation, 0, in a right-handed
 * one (Material's and Mesh's constructors), which mote draws as it is; a
 * material's cullBackFaces false culls the front faces instead. The core
 * culls by winding, so such a mesh gets its triangles flipped (as a
 * right-handed scene's are), once per index array, whatever shares it:
 * the vertices and normals stay as they are. */
mote_result mote__babylon_side_indices(mote__babylon *bl, mote__node *nd, int s,
                                       const mote__mat *mat, mote_mesh *m)
{
    unsigned char side = nd->side != MOTE__SIDE_UNSAID ? nd->side
                         : mat                         ? mat->side
                                                       : MOTE__SIDE_UNSAID;
    bool flip = side != MOTE__SIDE_UNSAID && (side == MOTE__SIDE_CW) != bl->right_handed;
    if (mat && mat->cull_front)
        flip = !flip;
    if (nd->thin_mirrored)
        flip = !flip;
    if (!flip || !m->indices || m->index_count == 0)
        return MOTE_OK;
    if (nd->sub_count > 0 && (nd->subs[s].own_indices || nd->subs[s].index_start % 3)) {
        /* an unindexed sub-mesh starting inside one of the array's
         * triangles, or drawing a run of its own: a flipped copy of its own */
        uint32_t *own = mote__store_alloc(bl->load->keep, m->index_count, sizeof *own);
        if (!own)
            return mote__oom(bl->load, nd->where);
        memcpy(own, m->indices, (size_t)m->index_count * sizeof *own);
        mote__flip_winding(own, m->index_count);
        m->indices = own;
        return MOTE_OK;
    }
    mote__node *owner = nd->arrays ? nd->arrays : nd;
    if (!owner->idx_flipped) {
        owner->idx_flipped =
            mote__store_alloc(bl->load->keep, owner->ni, sizeof *owner->idx_flipped);
        if (!owner->idx_flipped)
            return mote__oom(bl->load, nd->where);
        memcpy(owner->idx_flipped, owner->idx, (size_t)owner->ni * sizeof *owner->idx);
        mote__flip_winding(owner->idx_flipped, owner->ni);
    }
    m->indices = owner->idx_flipped + (nd->sub_count > 0 ? nd->subs[s].index_start : 0);
    return MOTE_OK;
}
