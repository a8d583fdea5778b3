/*
 * babylon_node.c - a .babylon file's meshes, transform nodes, instances
 * and thin instances as nodes: their transforms and matrices, their
 * parents, and the mote meshes made of them.
 */
#include "babylon.h"

#include <float.h>
#include <math.h>
#include <stdio.h>
#include <string.h>

/* ---- a node's own keys ------------------------------------------------- */

/* Whether a node names a parent: a parentId other than "", which Cinema
 * 4D's exporter writes for none (Babylon.js looks no parent up for it). */
bool mote__babylon_names_parent(const cJSON *node)
{
    const cJSON *p = mote__json_get(node, "parentId");
    return p && !(cJSON_IsString(p) && p->valuestring[0] == '\0');
}

/* What every node has: its ids, parent, transform and visibility. */
mote_result mote__babylon_node_common(mote__babylon *bl, const cJSON *mesh, const char *where,
                                      mote__node *nd)
{
    MOTE__TRY(mote__json_object(bl->load, mesh, where));
    MOTE__TRY(mote__json_string(bl->load, mesh, "id", where, &nd->id));
    if (!nd->id)
        MOTE__TRY(mote__json_string(bl->load, mesh, "name", where, &nd->id));
    MOTE__TRY(mote__babylon_number_text(bl, mesh, "uniqueId", where, &nd->unique_id));
    /* a parent's id, or (current Babylon.js) its uniqueId */
    nd->parent_by_unique = cJSON_IsNumber(mote__json_get(mesh, "parentId"));
    if (nd->parent_by_unique)
        MOTE__TRY(mote__babylon_number_text(bl, mesh, "parentId", where, &nd->parent_id));
    else
        MOTE__TRY(mote__babylon_id_ref(bl, mesh, "parentId", where, &nd->parent_id));
    /* a child of an instance names the instance's source mesh and the
     * instance's place among the source's instances (Babylon.js resolves
     * it so when it loads parents); -1, or absent: the parent itself */
    nd->parent_instance = -1;
    const cJSON *pii = mote__json_get(mesh, "parentInstanceIndex");
    if (pii && !(cJSON_IsNumber(pii) && pii->valuedouble == -1.0)) {
        char at[96];
        uint32_t k;
        snprintf(at, sizeof at, "%s.parentInstanceIndex", where);
        MOTE__TRY(mote__json_uint(bl->load, pii, at, 0, INT32_MAX, &k));
        nd->parent_instance = (int)k;
    }
    MOTE__TRY(mote__json_floats(bl->load, mesh, "position", where, 3, 0, nd->trs.position));
    MOTE__TRY(mote__json_floats(bl->load, mesh, "rotation", where, 3, 0, nd->trs.rotation));
    nd->trs.scaling[0] = nd->trs.scaling[1] = nd->trs.scaling[2] = 1.0f;
    MOTE__TRY(mote__json_floats(bl->load, mesh, "scaling", where, 3, 0, nd->trs.scaling));
    /* the core reads {0,0,0} as "unset" (1): an explicit zero scale gets
     * one so small that the mesh, and its children, collapse to a point */
    if (nd->trs.scaling[0] == 0.0f && nd->trs.scaling[1] == 0.0f && nd->trs.scaling[2] == 0.0f)
        nd->trs.scaling[0] = nd->trs.scaling[1] = nd->trs.scaling[2] = 1e-30f;
    bool visible = true, enabled = true;
    MOTE__TRY(mote__json_flag(bl->load, mesh, "isVisible", where, &visible));
    MOTE__TRY(mote__json_flag(bl->load, mesh, "isEnabled", where, &enabled));
    nd->invisible = !visible;
    nd->disabled = !enabled;
    if (mote__json_get(mesh, "rotationQuaternion")) {
        MOTE__TRY(mote__json_floats(bl->load, mesh, "rotationQuaternion", where, 4, 0,
                                    nd->trs.quat));
        nd->trs.use_quat = true;
    }
    if (bl->right_handed) {
        mote__mirror_point(nd->trs.position);
        mote__mirror_rotation(nd->trs.rotation, nd->trs.quat);
    }
    return MOTE_OK;
}

/* Element k of a matrix: an array of 16 numbers, or an object with keys
 * "0" to "15", as Babylon.js's SceneSerializer writes one (its matrices
 * are Float32Arrays, which JSON.stringify writes that way) and
 * Matrix.FromArray reads alike (m[k]). NULL when there is none. */
static const cJSON *mote__matrix_at(const cJSON *m, int k)
{
    if (cJSON_IsArray(m))
        return mote__json_length(m) == 16 ? cJSON_GetArrayItem(m, k) : NULL;
    char key[12];
    snprintf(key, sizeof key, "%d", k);
    return mote__json_member(m, key);
}

/* Whether obj[key] is absent or the identity matrix. */
static bool mote__absent_or_identity(const cJSON *obj, const char *key)
{
    const cJSON *m = mote__json_get(obj, key);
    if (!m)
        return true;
    for (int k = 0; k < 16; k++) {
        const cJSON *e = mote__matrix_at(m, k);
        if (!cJSON_IsNumber(e) || e->valuedouble != (k % 5 == 0 ? 1.0 : 0.0))
            return false;
    }
    return true;
}

/* Whether a mesh or transform node may have a matrix mote__read_matrix
 * keeps: room for a helper node, counted generously (an identity
 * localMatrix beside a pivotMatrix counts, though neither is kept; one it
 * refuses fails the load anyway). */
static bool mote__may_have_matrix(const cJSON *node)
{
    return !mote__absent_or_identity(node, "localMatrix") ||
           !mote__absent_or_identity(node, "pivotMatrix");
}

/* The matrix Babylon.js's Mesh.Parse and TransformNode.Parse give a node:
 * localMatrix, as a pre-transform (setPreTransformMatrix: applied before
 * scale, turn and position), else pivotMatrix, as a pivot
 * (setPivotMatrix's default postMultiplyPivotMatrix: its inverse applied
 * again after scale and turn, so that they happen about the pivot). The
 * identity changes nothing (_usePivotMatrix is false). It must be affine:
 * the core's transforms are. */
static mote_result mote__read_matrix(mote__babylon *bl, const cJSON *node, const char *where,
                                     mote__node *nd)
{
    const char *key = mote__json_get(node, "localMatrix") ? "localMatrix" : "pivotMatrix";
    const cJSON *m = mote__json_get(node, key);
    if (!m || mote__absent_or_identity(node, key))
        return MOTE_OK;
    char at[96];
    snprintf(at, sizeof at, "%s.%s", where, key);
    for (size_t k = 0; k < 16; k++) {
        const cJSON *e = mote__matrix_at(m, (int)k);
        if (cJSON_IsObject(m) && !e)
            return mote__fail(bl->load, MOTE_ERR_PARSE, "%s: expected an array of 16 numbers or an "
                              "object with keys \"0\" to \"15\", but \"%zu\" is missing", at, k);
        if (!e)
            return mote__fail(bl->load, MOTE_ERR_PARSE,
                              "%s: expected an array of 16 numbers, found "
                              "%s",
                              at, cJSON_IsArray(m) ? "another length" : mote__json_type_name(m));
        MOTE__TRY(mote__json_element_float(bl->load, e, at, k, &nd->matrix[k]));
    }
    const float *f = nd->matrix;
    if (f[3] != 0.0f || f[7] != 0.0f || f[11] != 0.0f || f[15] != 1.0f)
        return mote__fail(bl->load, MOTE_ERR_RANGE, "%s: not an affine transform (elements 3, 7, "
                          "11 and 15 must be 0, 0, 0 and 1)", at);
    if (bl->right_handed)
        mote__mirror_matrix(nd->matrix);
    nd->has_matrix = true;
    nd->matrix_name = key;
    nd->matrix_undone = key[0] == 'p';
    return MOTE_OK;
}

/* Whether JavaScript takes v for true: absent, null, false, 0, NaN and ""
 * are false. */
static bool mote__js_truthy(const cJSON *v)
{
    if (!v || cJSON_IsNull(v) || cJSON_IsFalse(v))
        return false;
    if (cJSON_IsNumber(v))
        return v->valuedouble != 0.0 && v->valuedouble == v->valuedouble;
    if (cJSON_IsString(v))
        return v->valuestring && v->valuestring[0];
    return true;
}

static void mote__warn_separate_geometry(mote__babylon *bl, const char *where)
{
    mote__warn(bl->load, "%s: its geometry is in a separate file (an incremental or binary "
               "export), which mote does not read; it is drawn without it", where);
}

/* One entry of meshes[] or transformNodes[]. */
/* Mesh.Parse's applyFog (true) and alphaIndex (unsaid: after every mesh
 * that has one; the serialiser writes Number.MAX_VALUE, past a float) */
static mote_result mote__mesh_draw_options(mote__babylon *bl, const cJSON *mesh, const char *where, mote__node *nd)
{
    bool fog = true;
    MOTE__TRY(mote__json_flag(bl->load, mesh, "applyFog", where, &fog));
    nd->no_fog = !fog;
    const cJSON *index = mote__json_get(mesh, "alphaIndex");
    if (cJSON_IsNumber(index)) {
        const double v = index->valuedouble;
        nd->alpha_index = v >= FLT_MAX ? FLT_MAX : v <= -FLT_MAX ? -FLT_MAX : (float)v;
        nd->alpha_index_set = true;
    } else if (index) {
        MOTE__TRY(mote__json_number(bl->load, mesh, "alphaIndex", where, &nd->alpha_index));   /* says why not */
    }
    return MOTE_OK;
}

static mote_result mote__node_read(mote__babylon *bl, const cJSON *mesh, const char *where,
                                   mote__node *nd)
{
    MOTE__TRY(mote__babylon_node_common(bl, mesh, where, nd));
    MOTE__TRY(mote__read_matrix(bl, mesh, where, nd));
    MOTE__TRY(mote__babylon_id_ref(bl, mesh, "materialId", where, &nd->material_id));
    MOTE__TRY(mote__babylon_number_text(bl, mesh, "materialUniqueId", where,
                                        &nd->material_unique_id));
    MOTE__TRY(mote__json_flag(bl->load, mesh, "isUnIndexed", where, &nd->unindexed));
    MOTE__TRY(mote__mesh_draw_options(bl, mesh, where, nd));
    /* Mesh.Parse: overrideMaterialSideOrientation (older files; null: none),
     * then sideOrientation (Babylon.js 7's), each overriding the
     * material's (the glTF loader sets it on every mesh it makes) */
    MOTE__TRY(mote__babylon_side(bl, mesh, "overrideMaterialSideOrientation", where, &nd->side));
    MOTE__TRY(mote__babylon_side(bl, mesh, "sideOrientation", where, &nd->side));
    /* An incremental (.incremental.babylon) or binary export keeps the
     * arrays in another file, which mote does not read: said rather than
     * drawn as nothing without a word. Mesh.Parse tests delayLoadingFile
     * (as JavaScript tests truth) before any geometry, so the file's
     * geometryId, arrays and subMeshes are not looked at either. */
    if (mote__js_truthy(mote__json_get(mesh, "delayLoadingFile"))) {
        mote__warn_separate_geometry(bl, where);
        return MOTE_OK;
    }
    const cJSON *verts, *pos;
    MOTE__TRY(mote__json_array(bl->load, mesh, "vertices", where, &verts));
    MOTE__TRY(mote__json_array(bl->load, mesh, "positions", where, &pos));
    const char *geometry_id;
    MOTE__TRY(mote__json_string(bl->load, mesh, "geometryId", where, &geometry_id));
    if (verts && pos)
        return mote__fail(bl->load, MOTE_ERR_PARSE, "%s: has both \"vertices\" and \"positions\"",
                          where);
    if (verts) {
        MOTE__TRY(mote__babylon_legacy_geometry(bl, mesh, verts, where, nd));
    } else if (pos) {
        MOTE__TRY(mote__babylon_current_geometry(bl, mesh, where, nd));
    } else if (geometry_id) {
        int k = mote__idmap_find(bl->geometry_map, geometry_id);
        if (k < 0)
            return mote__fail(bl->load, MOTE_ERR_RANGE,
                              "%s.geometryId: \"%s\" names no geometries.vertexData entry",
                              where, mote__quote(geometry_id).s);
        mote__geometry *g = &bl->geometries[k];
        /* parsed once for the meshes that draw it by its indices and once
         * for those that draw it unindexed (their arrays differ: indices,
         * smooth normals); the others share (no copies, however many
         * meshes name it either way) */
        int *owner = &g->owner[nd->unindexed];
        if (*owner >= 0) {
            mote__babylon_share_arrays(nd, &bl->nodes[*owner]);
        } else {
            char gat[64];
            snprintf(gat, sizeof gat, "geometries.vertexData[%d]", k);
            MOTE__TRY(mote__babylon_current_geometry(bl, g->json, gat, nd));
            *owner = (int)(nd - bl->nodes);
        }
    } else if (cJSON_IsNull(mote__json_member(mesh, "positions"))) {
        MOTE__TRY(mote__babylon_current_geometry(bl, mesh, where, nd)); /* says it is null */
    } else {
        if (mote__json_get(mesh, "_binaryInfo"))
            mote__warn_separate_geometry(bl, where);
        const cJSON *ind;
        MOTE__TRY(mote__json_array(bl->load, mesh, "indices", where, &ind));
        if (ind && ind->child) {
            char iat[96];
            snprintf(iat, sizeof iat, "%s.indices", where);
            uint32_t max_index;
            MOTE__TRY(mote__babylon_indices(bl, ind, iat, nd, &max_index));
            MOTE__TRY(mote__babylon_check_indices(bl, iat, nd));
        }
    }
    return mote__babylon_submeshes(bl, mesh, where, nd);
}

/* ---- thin instances ---------------------------------------------------- */

/* How many thin instances of a mesh Babylon.js draws. Mesh.Parse gives it
 * thinInstanceSetBuffer("matrix", new Float32Array(matrixData), 16) and
 * then the file's instancesCount, which hasThinInstances tests and the
 * instanced draw draws (mesh.ts, thinInstanceMesh.ts); the mesh itself
 * is then not drawn (_processRendering draws the thin instances only).
 * *count: the thin instances drawn; *undrawn: the mesh is drawn neither
 * itself nor by thin instances (a draw of more instances than matrixData
 * holds, which WebGL refuses). warn: say why, once (when the mesh is
 * read; its instances are first counted without a word). */
static mote_result mote__thin_count(mote__babylon *bl, const cJSON *mesh, const char *where,
                                    bool warn, uint32_t *count, bool *undrawn)
{
    *count = 0;
    *undrawn = false;
    const cJSON *thin = mote__json_get(mesh, "thinInstances");
    if (!thin)
        return MOTE_OK;
    char at[64];
    snprintf(at, sizeof at, "%s.thinInstances", where);
    MOTE__TRY(mote__json_object(bl->load, thin, at));
    uint32_t n = 0;
    MOTE__TRY(mote__json_uint_member(bl->load, thin, "instancesCount", at, INT32_MAX, &n));
    const cJSON *data = mote__json_get(thin, "matrixData");
    if (!data) {
        if (n > 0 && warn)
            mote__warn(bl->load,
                       "%s: instancesCount %u without matrixData: Babylon.js draws the mesh "
                       "itself, and so does mote",
                       at, (unsigned)n);
        return MOTE_OK;
    }
    /* JSON.stringify writes a Float32Array as an object with keys "0",
     * "1"...: it has no length, so new Float32Array makes no matrix of it */
    size_t len = 0;
    if (cJSON_IsArray(data))
        len = mote__json_length(data);
    else if (!cJSON_IsObject(data))
        return mote__fail(bl->load, MOTE_ERR_PARSE, "%s.matrixData: expected an array of numbers, "
                          "found %s", at, mote__json_type_name(data));
    else if (mote__json_member(data, "length"))
        return mote__fail(bl->load, MOTE_ERR_PARSE, "%s.matrixData: an object with a \"length\", "
                          "which mote does not read (expected an array of numbers)", at);
    size_t matrices = len / 16;
    if (n == 0) {
        if (matrices > 0 && warn)
            mote__warn(bl->load, "%s: no instancesCount (or 0): Babylon.js draws the mesh itself, "
                       "not the %zu matri%s of matrixData, and so does mote", at, matrices,
                       matrices == 1 ? "x" : "ces");
        return MOTE_OK;
    }
    if (n > matrices) {
        *undrawn = true;
        if (warn && cJSON_IsObject(data))
            mote__warn(bl->load,
                       "%s.matrixData: an object, of which Babylon.js makes no matrix (new "
                       "Float32Array of it is empty), so its draw of %u instance%s reads past "
                       "its buffer, which WebGL refuses: the mesh is not drawn",
                       at, (unsigned)n, n == 1 ? "" : "s");
        else if (warn)
            mote__warn(bl->load,
                       "%s: instancesCount %u, but matrixData holds %zu matri%s: Babylon.js's "
                       "draw reads past it, which WebGL refuses: the mesh is not drawn",
                       at, (unsigned)n, matrices, matrices == 1 ? "x" : "ces");
        return MOTE_OK;
    }
    if (len % 16 && warn)
        mote__warn(bl->load,
                   "%s.matrixData: %zu numbers, not a multiple of 16: the last %zu are not "
                   "read",
                   at, len, len % 16);
    /* thinInstanceSetBuffer of other kinds: per-instance colours (which
     * multiply the material's) and custom attributes */
    if (mote__json_get(thin, "userThinInstance") && warn)
        mote__warn(bl->load,
                   "%s.userThinInstance: its per-instance buffers (colours...) are not read: "
                   "each thin instance is drawn in the mesh's material",
                   at);
    *count = n;
    return MOTE_OK;
}

/* The thin instances of mesh i (nodes[host]): count nodes from `first`,
 * each a child of the mesh with its matrix of matrixData as a
 * pre-transform (the shaders' world * instance matrix: the matrix is in
 * the mesh's own space), drawn with the mesh's arrays, material and
 * sub-meshes (shared), and shown when the mesh is. The matrix is folded
 * as a localMatrix is (mote__fold_node_matrix), so it must be affine. */
static mote_result mote__thin_instances(mote__babylon *bl, const cJSON *mesh, int i, int host,
                                        int first, uint32_t count)
{
    const mote__node *h = &bl->nodes[host];
    const cJSON *data = mote__json_get(mote__json_get(mesh, "thinInstances"), "matrixData");
    char at[80];
    snprintf(at, sizeof at, "%s.thinInstances.matrixData", h->where);
    const cJSON *e = data->child;   /* an array of at least 16 count numbers */
    for (uint32_t k = 0; k < count; k++) {
        mote__node *t = &bl->nodes[first + (int)k];
        snprintf(t->where, sizeof t->where, "meshes[%d].thinInstances[%u]", i, (unsigned)k);
        bool identity = true;
        for (int j = 0; j < 16; j++, e = e->next) {
            MOTE__TRY(mote__json_element_float(bl->load, e, at, (size_t)k * 16 + (size_t)j,
                                               &t->matrix[j]));
            identity = identity && t->matrix[j] == (j % 5 == 0 ? 1.0f : 0.0f);
        }
        const float *f = t->matrix;
        if (f[3] != 0.0f || f[7] != 0.0f || f[11] != 0.0f || f[15] != 1.0f)
            return mote__fail(bl->load, MOTE_ERR_RANGE,
                              "%s: matrix %u (numbers %zu to %zu) is not an "
                              "affine transform (its numbers 3, 7, 11 and 15 must be 0, 0, 0 "
                              "and 1)",
                              at, (unsigned)k, (size_t)k * 16, (size_t)k * 16 + 15);
        double det = (double)f[0] * ((double)f[5] * f[10] - (double)f[6] * f[9]) -
                     (double)f[4] * ((double)f[1] * f[10] - (double)f[2] * f[9]) +
                     (double)f[8] * ((double)f[1] * f[6] - (double)f[2] * f[5]);
        t->thin_mirrored = det < 0.0;
        if (bl->right_handed)
            mote__mirror_matrix(t->matrix);
        t->has_matrix = !identity;
        t->matrix_name = "thin instance matrix";
        t->is_thin = true;
        t->host = host;
        t->parent_instance = -1;
        t->trs.scaling[0] = t->trs.scaling[1] = t->trs.scaling[2] = 1.0f;
        t->material_id = h->material_id;
        t->material_unique_id = h->material_unique_id;
        t->legacy = h->legacy;
        t->side = h->side;
        t->no_fog = h->no_fog;
        t->alpha_index = h->alpha_index;
        t->alpha_index_set = h->alpha_index_set;
        t->invisible = h->invisible;  /* drawn when the mesh is (its parent's flags do the rest) */
        mote__babylon_share_arrays(t, (mote__node *)h);
        t->subs = h->subs;
        t->sub_count = h->sub_count;
    }
    return MOTE_OK;
}

/* ---- the nodes of a file ----------------------------------------------- */

/* meshes[], transformNodes[], the meshes' instances and thin instances as
 * nodes, with room counted for the nodes made later (cameras and lights
 * in the tree, helpers of sheared matrices, levels of detail of
 * instances), within limits.max_meshes. */
mote_result mote__babylon_nodes(mote__babylon *bl)
{
    const cJSON *meshes, *tnodes, *geos = mote__json_get(bl->root, "geometries");
    MOTE__TRY(mote__json_array(bl->load, bl->root, "meshes", "", &meshes));
    MOTE__TRY(mote__json_array(bl->load, bl->root, "transformNodes", "", &tnodes));
    /* an array (Cinema 4D's exporter writes "geometries": []) has no
     * vertexData member, so Babylon.js finds no geometries in it */
    if (cJSON_IsArray(geos)) {
        if (geos->child)
            mote__warn(bl->load, "geometries: an array, not an object: Babylon.js reads no "
                       "geometries from it, nor does mote");
        geos = NULL;
    }
    if (geos) {
        const cJSON *vertex_data;
        MOTE__TRY(mote__json_object(bl->load, geos, "geometries"));
        MOTE__TRY(mote__json_array(bl->load, geos, "vertexData", "geometries", &vertex_data));
        size_t ng = mote__json_length(vertex_data);
        bl->geometries = mote__store_alloc(&bl->load->tmp, ng + 1, sizeof *bl->geometries);
        if (!bl->geometries)
            return mote__oom(bl->load, "geometries");
        for (const cJSON *g = vertex_data ? vertex_data->child : NULL; g; g = g->next) {
            const cJSON *gid = mote__json_member(g, "id");
            mote__geometry *e = &bl->geometries[bl->geometry_count++];
            e->id = cJSON_IsString(gid) ? gid->valuestring : NULL;
            e->json = g;
            e->owner[0] = e->owner[1] = -1;
        }
        int dup;
        bl->geometry_map = mote__idmap_build(bl, &bl->geometries[0].id, sizeof *bl->geometries,
                                             bl->geometry_count, &dup);
        if (!bl->geometry_map)
            return mote__oom(bl->load, "geometries");
    }
    /* nh: nodes that may need a helper node (mote__fold_node_matrix); nl: the
     * levels of detail that instances of their master may draw (mote__babylon_lods) */
    size_t nm = mote__json_length(meshes), nt = mote__json_length(tnodes), ni = 0, nth = 0, nh = 0,
           nl = 0;
    int i = 0;
    for (const cJSON *m = meshes ? meshes->child : NULL; m; m = m->next, i++) {
        char at[32];
        snprintf(at, sizeof at, "meshes[%d]", i);
        const cJSON *inst = NULL, *lod_ids = NULL;
        uint32_t thin = 0;
        bool unused;
        if (cJSON_IsObject(m)) {
            MOTE__TRY(mote__json_array(bl->load, m, "instances", at, &inst));
            MOTE__TRY(mote__json_array(bl->load, m, "lodMeshIds", at, &lod_ids));
            MOTE__TRY(mote__thin_count(bl, m, at, false, &thin, &unused));
        }
        size_t n = mote__json_length(inst);
        ni += n;
        nth += thin;
        if (mote__may_have_matrix(m))
            nh += 1 + n;
        if (thin)   /* a thin instance's matrix may be sheared */
            nh += thin;
        nl += n * mote__json_length(lod_ids);
        if (ni + nth > bl->load->lim.max_meshes)
            break;   /* no sum past the limit (nor its overflow) */
    }
    for (const cJSON *t = tnodes ? tnodes->child : NULL; t; t = t->next)
        nh += mote__may_have_matrix(t);
    if (nm + nt + ni + nth > bl->load->lim.max_meshes)
        return mote__fail(bl->load, MOTE_ERR_LIMIT, "meshes: %zu meshes, more than the limit of %u "
                          "(transform nodes, instances and thin instances count)",
                          nm + nt + ni + nth, (unsigned)bl->load->lim.max_meshes);
    /* cameras and lights may join the tree (mote__entry_node), and helpers of
     * nodes with a matrix; each becomes a mesh, so no more than the mesh
     * limit leaves room for */
    const cJSON *cams, *lights;
    MOTE__TRY(mote__json_array(bl->load, bl->root, "cameras", "", &cams));
    MOTE__TRY(mote__json_array(bl->load, bl->root, "lights", "", &lights));
    size_t nx = mote__json_length(cams) + mote__json_length(lights) + nh + nl;
    const size_t base = nm + nt + ni + nth;
    if (nx > bl->load->lim.max_meshes - base)
        nx = bl->load->lim.max_meshes - base;
    bl->nodes = mote__store_alloc(&bl->load->tmp, base + nx, sizeof *bl->nodes);
    if (!bl->nodes)
        return mote__oom(bl->load, "meshes");
    bl->node_count = (int)base;
    bl->node_cap = (int)(base + nx);
    bl->file_meshes = (int)nm;
    bl->instances_first = (int)(nm + nt);
    bl->instances_end = (int)(nm + nt + ni);
    /* meshes, then transform nodes, then instances: each the source mesh's
     * geometry, material and sub-meshes with a transform and parent of its
     * own (Babylon.js's Mesh.Parse and createInstance), then thin instances */
    int next_instance = (int)(nm + nt), next_thin = (int)(nm + nt + ni);
    i = 0;
    for (const cJSON *m = meshes ? meshes->child : NULL; m; m = m->next, i++) {
        mote__node *nd = &bl->nodes[i];
        snprintf(nd->where, sizeof nd->where, "meshes[%d]", i);
        MOTE__TRY(mote__node_read(bl, m, nd->where, nd));
        /* levels of detail, resolved once every mesh is known (mote__babylon_lods);
         * arrays: checked above */
        nd->lod_ids = mote__json_get(m, "lodMeshIds");
        MOTE__TRY(mote__json_array(bl->load, m, "lodDistances", nd->where, &nd->lod_distances));
        if (nd->lod_ids && nd->lod_ids->child && !nd->lod_distances)
            mote__warn(bl->load,
                       "%s: lodMeshIds without lodDistances (Babylon.js's loader reads no "
                       "lodCoverages): no levels of detail are made, each mesh is drawn by "
                       "itself, as in Babylon.js",
                       nd->where);
        uint32_t thin;
        MOTE__TRY(mote__thin_count(bl, m, nd->where, true, &thin, &nd->undrawn));
        if (thin) {
            nd->undrawn = true;
            nd->first_thin = next_thin;
            nd->thin_count = (int)thin;
            MOTE__TRY(mote__thin_instances(bl, m, i, i, next_thin, thin));
            next_thin += (int)thin;
        }
        const cJSON *inst = mote__json_get(m, "instances");   /* an array: checked above */
        nd->first_instance = next_instance;
        nd->instance_count = (int)mote__json_length(inst);
        if (nd->undrawn && nd->instance_count)
            mote__warn(bl->load, "%s: its instances are not drawn: Babylon.js draws a mesh's thin "
                       "instances in place of it and its instances", nd->where);
        int k = 0;
        for (const cJSON *e = inst ? inst->child : NULL; e; e = e->next, k++) {
            mote__node *in = &bl->nodes[next_instance++];
            snprintf(in->where, sizeof in->where, "meshes[%d].instances[%d]", i, k);
            MOTE__TRY(mote__babylon_node_common(bl, e, in->where, in));
            in->material_id = nd->material_id;
            in->material_unique_id = nd->material_unique_id;
            in->legacy = nd->legacy;
            in->side = nd->side;   /* drawn through its source mesh */
            in->no_fog = nd->no_fog;
            in->alpha_index = nd->alpha_index;
            in->alpha_index_set = nd->alpha_index_set;
            in->undrawn = nd->undrawn;
            /* InstancedMesh's constructor: setPivotMatrix(source's matrix),
             * with the default postMultiplyPivotMatrix, so an instance
             * undoes even a localMatrix (a pre-transform of its source) */
            memcpy(in->matrix, nd->matrix, sizeof in->matrix);
            in->has_matrix = nd->has_matrix;
            in->matrix_name = nd->matrix_undone ? "source's pivotMatrix" : "source's localMatrix";
            in->matrix_undone = true;
            mote__babylon_share_arrays(in, nd);
            in->subs = nd->subs;
            in->sub_count = nd->sub_count;
        }
    }
    int t = 0;
    for (const cJSON *m = tnodes ? tnodes->child : NULL; m; m = m->next, i++, t++) {
        mote__node *nd = &bl->nodes[i];
        snprintf(nd->where, sizeof nd->where, "transformNodes[%d]", t);
        MOTE__TRY(mote__node_read(bl, m, nd->where, nd));
        if (nd->nv || nd->ni || nd->sub_count)
            return mote__fail(bl->load, MOTE_ERR_PARSE, "%s: a transform node has no geometry",
                              nd->where);
    }
    return MOTE_OK;
}

/* ---- parents and matrices ---------------------------------------------- */

/* nodes[index]'s localMatrix or pivotMatrix folded into its transform
 * (mote__fold_matrix): as Babylon.js's TransformNode.computeWorldMatrix
 * composes it (in mote's column vectors; Babylon.js's row-vector product
 * P S R [P^-1], then the position added), a localMatrix is a
 * pre-transform and a pivotMatrix a pivot. A sheared one takes a hidden
 * helper node, in the node's place under its parent. */
static mote_result mote__fold_node_matrix(mote__babylon *bl, int index)
{
    mote__node *nd = &bl->nodes[index];
    mote__trs outer;
    mote__fold folded = mote__fold_matrix(&nd->trs, nd->matrix, nd->matrix_undone, &outer);
    if (folded == MOTE__FOLD_SINGULAR)
        return mote__fail(bl->load, MOTE_ERR_RANGE, "%s: its %s is not invertible (as a pivot "
                          "it is undone by its inverse)", nd->where, nd->matrix_name);
    if (folded == MOTE__FOLDED)
        return MOTE_OK;
    if (bl->node_count >= bl->node_cap)
        return mote__fail(bl->load, MOTE_ERR_LIMIT, "%s: more than the limit of %u meshes "
                          "(nodes with a sheared pivot or local matrix take two)", nd->where,
                          (unsigned)bl->load->lim.max_meshes);
    int h = bl->node_count++;
    mote__node *helper = &bl->nodes[h];
    memcpy(helper->where, nd->where, sizeof helper->where);
    helper->parent = nd->parent;
    helper->parent_id = nd->parent_id;   /* for messages: it stands in the node's place */
    helper->parent_instance = -1;
    helper->invisible = true;
    helper->is_helper = true;
    helper->trs = outer;
    nd->parent = h;
    return MOTE_OK;
}

/* parentId -> node index; then every chain must end (no cycle) within the
 * depth the core follows. */
mote_result mote__babylon_parents(mote__babylon *bl)
{
    int dup;
    bl->node_map = mote__idmap_build(bl, &bl->nodes[0].id, sizeof *bl->nodes, bl->node_count,
                                     &dup);
    mote__idmap *unique_map = mote__idmap_build(bl, &bl->nodes[0].unique_id, sizeof *bl->nodes,
                                                bl->node_count, &dup);
    if (!bl->node_map || !unique_map)
        return mote__oom(bl->load, "meshes");
    for (int i = 0; i < bl->node_count; i++) {
        mote__node *nd = &bl->nodes[i];
        nd->parent = nd->is_thin ? nd->host : -1;
        if (!nd->parent_id)
            continue;
        if (nd->parent_by_unique)
            nd->parent = mote__idmap_find(unique_map, nd->parent_id);
        else
            nd->parent = mote__idmap_find_last(bl->node_map, nd->parent_id);
        if (nd->parent < 0)
            MOTE__TRY(mote__babylon_camera_light_parent(bl, nd));
        /* Babylon.js leaves such a node without a parent (a partial export,
         * "export selected"): it keeps its own transform */
        if (nd->parent < 0 && nd->parent_by_unique)
            mote__warn(bl->load, "%s.parentId: %s is the uniqueId of no node; loaded without a "
                       "parent", nd->where, nd->parent_id);
        else if (nd->parent < 0)
            mote__warn(bl->load, "%s.parentId: \"%s\" names no node; loaded without a parent",
                       nd->where, mote__quote(nd->parent_id).s);
    }
    for (int i = 0; i < bl->node_count; i++) {
        mote__node *nd = &bl->nodes[i];
        if (nd->parent < 0 || nd->parent_instance < 0)
            continue;
        const mote__node *p = &bl->nodes[nd->parent];
        if (nd->parent_instance >= p->instance_count)
            return mote__fail(bl->load, MOTE_ERR_RANGE,
                              "%s.parentInstanceIndex: %s has no instance %d "
                              "(it has %d)",
                              nd->where, p->where, nd->parent_instance, p->instance_count);
        nd->parent = p->first_instance + nd->parent_instance;
    }
    /* levels of detail take their master's place (and its instances get
     * levels of their own), before the matrices are folded */
    MOTE__TRY(mote__babylon_lods(bl));
    /* the matrices, now that the parents are known (helpers take them) */
    for (int i = 0, n = bl->node_count; i < n; i++)
        if (bl->nodes[i].has_matrix)
            MOTE__TRY(mote__fold_node_matrix(bl, i));
    for (int i = 0; i < bl->node_count; i++) {
        /* walk up marking the path; meeting the path again is a cycle */
        int j = i;
        while (j >= 0 && bl->nodes[j].state == 0) {
            bl->nodes[j].state = 1;
            j = bl->nodes[j].parent;
        }
        if (j >= 0 && bl->nodes[j].state == 1)
            return mote__fail(bl->load, MOTE_ERR_RANGE, "%s.parentId: \"%s\" makes a cycle",
                              bl->nodes[j].where, mote__quote(bl->nodes[j].parent_id).s);
        for (j = i; j >= 0 && bl->nodes[j].state == 1; j = bl->nodes[j].parent)
            bl->nodes[j].state = 2;
    }
    /* the core follows at most MOTE_MAX_PARENTS parents, hidden helpers
     * (mote__fold_node_matrix) among them */
    for (int i = 0; i < bl->node_count; i++) {
        int depth = 0, helpers = 0;
        for (int j = bl->nodes[i].parent; j >= 0; j = bl->nodes[j].parent) {
            helpers += bl->nodes[j].is_helper;
            if (++depth > MOTE_MAX_PARENTS)
                return mote__fail(bl->load, MOTE_ERR_LIMIT,
                                  "%s: more than %d parents (MOTE_MAX_PARENTS)%s",
                                  bl->nodes[i].where, MOTE_MAX_PARENTS,
                                  helpers ? ", counting one for each sheared pivotMatrix or "
                                            "localMatrix above it"
                                          : "");
        }
    }
    return MOTE_OK;
}

/* ---- the meshes drawn -------------------------------------------------- */

/* Whether it or a parent is disabled (chains are finite and short:
 * mote__babylon_parents). */
bool mote__babylon_node_disabled(const mote__babylon *bl, const mote__node *nd)
{
    for (; nd; nd = nd->parent >= 0 ? &bl->nodes[nd->parent] : NULL)
        if (nd->disabled)
            return true;
    return false;
}

/* Whether a node is not drawn: it is invisible or disabled. */
bool mote__babylon_node_hidden(const mote__babylon *bl, const mote__node *nd)
{
    return nd->invisible || mote__babylon_node_disabled(bl, nd);
}

mote_result mote__babylon_build_meshes(mote__babylon *bl)
{
    size_t total = 0;
    for (int i = 0; i < bl->node_count; i++) {
        mote__node *nd = &bl->nodes[i];
        nd->first_mesh = (int)total;
        nd->mesh_count = nd->sub_count > 0 ? nd->sub_count : 1;
        total += (size_t)nd->mesh_count;
    }
    if (total > bl->load->lim.max_meshes)
        return mote__fail(bl->load, MOTE_ERR_LIMIT,
                          "meshes: %zu meshes with their sub-meshes, more "
                          "than the limit of %u",
                          total, (unsigned)bl->load->lim.max_meshes);
    mote_scene *sc = bl->load->scene;
    /* one allocation, never moved: parents point into it */
    sc->meshes = mote__store_alloc(bl->load->keep, total, sizeof *sc->meshes);
    if (!sc->meshes)
        return mote__oom(bl->load, "meshes");
    sc->mesh_count = (int)total;
    /* a byte per mesh and flag, so that mote_scene_draw_desc needs no search */
    bool *two_sided = mote__store_alloc(bl->load->keep, 5 * total, sizeof *two_sided);
    float *alpha_index = mote__store_alloc(bl->load->keep, total, sizeof *alpha_index);
    if (!two_sided || !alpha_index)
        return mote__oom(bl->load, "meshes");
    bool *unlit = two_sided + total, *no_depth_write = unlit + total, *no_fog = no_depth_write + total;
    bool *depth_pre_pass = no_fog + total;
    sc->two_sided = two_sided;
    sc->unlit = unlit;
    sc->no_depth_write = no_depth_write;
    sc->no_fog = no_fog;
    sc->depth_pre_pass = depth_pre_pass;
    sc->alpha_index = alpha_index;
    bl->max_lights = mote__store_alloc(&bl->load->tmp, total, sizeof *bl->max_lights);
    if (!bl->max_lights)
        return mote__oom(bl->load, "meshes");
    for (int i = 0; i < bl->node_count; i++) {
        mote__node *nd = &bl->nodes[i];
        for (int s = 0; s < nd->mesh_count; s++) {
            mote_mesh *m = &sc->meshes[nd->first_mesh + s];
            m->vertices = nd->verts;
            m->vertex_count = nd->nv;
            m->colors = nd->colors;   /* sub-meshes share the vertices, so these too */
            m->indices = nd->idx;
            m->index_count = nd->ni;
            uint32_t material_index = 0;
            if (nd->sub_count > 0) {
                m->indices = nd->subs[s].own_indices ? nd->subs[s].own_indices
                             : nd->idx                ? nd->idx + nd->subs[s].index_start
                                                      : NULL;
                m->index_count = nd->subs[s].index_count;
                material_index = nd->subs[s].material_index;
            }
            memcpy(m->position, nd->trs.position, sizeof m->position);
            memcpy(m->rotation, nd->trs.rotation, sizeof m->rotation);
            memcpy(m->rotation_quaternion, nd->trs.quat, sizeof m->rotation_quaternion);
            m->use_quaternion = nd->trs.use_quat;
            memcpy(m->scaling, nd->trs.scaling, sizeof m->scaling);
            m->parent = nd->parent >= 0 ? &sc->meshes[bl->nodes[nd->parent].first_mesh] : NULL;
            const mote__mat *mat = mote__babylon_resolve_material(bl, nd, material_index);
            no_fog[nd->first_mesh + s] = nd->no_fog || (mat && mat->no_fog);
            alpha_index[nd->first_mesh + s] = nd->alpha_index_set ? nd->alpha_index : FLT_MAX;
            if (mat) {
                m->material = mat->material;
                two_sided[nd->first_mesh + s] = mat->two_sided;
                unlit[nd->first_mesh + s] = mat->unlit;
                no_depth_write[nd->first_mesh + s] = mat->no_depth_write;
                depth_pre_pass[nd->first_mesh + s] = mat->depth_pre_pass;
                if (mat->uv2)
                    MOTE__TRY(mote__babylon_uv2_vertices(bl, nd, m));
            }
            bl->max_lights[nd->first_mesh + s] = (uint8_t)(!mat ? 4u : mat->max_lights < 32u ? mat->max_lights : 32u);
            MOTE__TRY(mote__babylon_side_indices(bl, nd, s, mat, m));
            /* v = 0: the bottom row when the texture says invertY (what
             * Babylon.js does by default, and current exporters rely on),
             * the top row when it says not; unsaid, legacy files (the
             * tutorial's) address the top row, current ones the bottom */
            m->material.v_origin_bottom =
                mat && mat->invert_y >= 0 ? mat->invert_y != 0 : !nd->legacy;
            m->hidden = mote__babylon_node_hidden(bl, nd) || nd->undrawn;
            mote_mesh_update_bounds(m);
        }
    }
    return MOTE_OK;
}

/* scene.bounds: a world-space box over every drawn vertex (once per node:
 * sub-meshes share). */
mote_result mote__babylon_scene_bounds(mote__babylon *bl)
{
    mote_scene *sc = bl->load->scene;
    bool any = false;
    for (int i = 0; i < bl->node_count; i++) {
        const mote__node *nd = &bl->nodes[i];
        if (nd->nv == 0 || sc->meshes[nd->first_mesh].hidden)
            continue;
        mote__scene_bounds_add(sc, &sc->meshes[nd->first_mesh], &any);
    }
    return MOTE_OK;
}
