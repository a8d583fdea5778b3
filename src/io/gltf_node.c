/*
 * gltf_node.c - the scene drawn and its node tree: each node's transform
 * (translation, rotation, scale, or a matrix folded into them), its mesh,
 * camera and light; then the mote meshes: a node's primitives under its
 * parent's, in the file's mirrored space.
 */
#include "gltf.h"

#include <math.h>
#include <stdio.h>
#include <string.h>

/* A node's own transform: matrix (folded into T R S, with a helper above
 * when it shears: mote__fold_matrix) or translation, rotation, scale. */
static mote_result mote__gltf_node_transform(mote__gltf *gl, const cJSON *node, const char *at,
                                             mote__gltf_node *nd)
{
    mote__trs *t = &nd->trs;
    memset(t, 0, sizeof *t);
    t->quat[3] = 1.0f;
    t->use_quat = true;
    t->scaling[0] = t->scaling[1] = t->scaling[2] = 1.0f;
    if (mote__json_get(node, "matrix")) {
        /* 16 numbers (mote__json_floats reads at most 4) */
        const cJSON *a = mote__json_get(node, "matrix");
        char mat[64];
        snprintf(mat, sizeof mat, "%s.matrix", at);
        if (!cJSON_IsArray(a) || mote__json_length(a) != 16)
            return mote__fail(gl->load, MOTE_ERR_PARSE, "%s: expected an array of 16 numbers",
                              mat);
        float m[16];
        size_t k = 0;
        for (const cJSON *e = a->child; e; e = e->next, k++)
            MOTE__TRY(mote__json_element_float(gl->load, e, mat, k, &m[k]));
        static const float id[16] = {1, 0, 0, 0, 0, 1, 0, 0, 0, 0, 1, 0, 0, 0, 0, 1};
        if (memcmp(m, id, sizeof m) == 0)
            return MOTE_OK;
        if (m[3] != 0.0f || m[7] != 0.0f || m[11] != 0.0f || m[15] != 1.0f)
            return mote__fail(gl->load, MOTE_ERR_RANGE, "%s.matrix: its last row is %g %g %g "
                              "%g, expected 0 0 0 1 (an affine transform)", at, m[3], m[7],
                              m[11], m[15]);
        mote__mirror_matrix(m);
        nd->sheared = mote__fold_matrix(t, m, false, &nd->outer) == MOTE__FOLDED_SHEARED;
        return MOTE_OK;
    }
    MOTE__TRY(mote__json_floats(gl->load, node, "translation", at, 3, 0, t->position));
    MOTE__TRY(mote__json_floats(gl->load, node, "rotation", at, 4, 0, t->quat));
    MOTE__TRY(mote__json_floats(gl->load, node, "scale", at, 3, 0, t->scaling));
    /* mote reads a scale of 0 0 0 as 1 1 1; glTF means nothing shows */
    if (t->scaling[0] == 0.0f && t->scaling[1] == 0.0f && t->scaling[2] == 0.0f)
        t->scaling[0] = t->scaling[1] = t->scaling[2] = 1e-30f;
    mote__mirror_point(t->position);
    float unused[3] = {0, 0, 0};
    mote__mirror_rotation(unused, t->quat);
    return MOTE_OK;
}

static mote_result mote__gltf_walk(mote__gltf *gl, int i, int parent, int depth,
                                   const char *by);

/* The nodes the array list (at, NULL: none) names, and their trees,
 * under parent at depth (mote__gltf_walk). */
static mote_result mote__gltf_walk_list(mote__gltf *gl, const cJSON *list, const char *at,
                                        int parent, int depth)
{
    int k = 0;
    for (const cJSON *e = list ? list->child : NULL; e; e = e->next, k++) {
        char eat[96];
        snprintf(eat, sizeof eat, "%s[%d]", at, k);
        if (gl->node_count == 0)
            return mote__fail(gl->load, MOTE_ERR_RANGE, "%s: names a node, and there are none",
                              eat);
        uint32_t i;
        MOTE__TRY(mote__json_uint(gl->load, e, eat, 0, (double)gl->node_count - 1, &i));
        MOTE__TRY(mote__gltf_walk(gl, (int)i, parent, depth, eat));
    }
    return MOTE_OK;
}

/* nodes[i] and the tree under it, parent its parent (-1: a root);
 * depth: the mote meshes above its own. Every node is reached once: a
 * node that is its own ancestor, or has two parents, is an error. */
static mote_result mote__gltf_walk(mote__gltf *gl, int i, int parent, int depth, const char *by)
{
    mote__gltf_node *nd = &gl->nodes[i];
    char at[48];
    snprintf(at, sizeof at, "nodes[%d]", i);
    if (nd->state == 1)
        return mote__fail(gl->load, MOTE_ERR_RANGE, "%s: %s makes a cycle (a node is its own "
                          "ancestor)", by, at);
    if (nd->state == 2)
        return mote__fail(gl->load, MOTE_ERR_RANGE, "%s: %s is reached a second time (a node "
                          "has one parent, and a scene names each root once)", by, at);
    nd->state = 1;
    nd->in_scene = true;
    nd->parent = parent;
    const cJSON *node;
    MOTE__TRY(mote__gltf_item(gl, "nodes", i, &node, NULL));
    MOTE__TRY(mote__gltf_node_transform(gl, node, at, nd));
    nd->depth = depth + 1 + (nd->sheared ? 1 : 0);
    if (nd->depth - 1 > MOTE_MAX_PARENTS)
        return mote__fail(gl->load, MOTE_ERR_LIMIT, "%s: more than %d parents "
                          "(MOTE_MAX_PARENTS)", at, MOTE_MAX_PARENTS);
    MOTE__TRY(mote__gltf_index(gl, node, "mesh", at, gl->mesh_count, "mesh", &nd->mesh));
    MOTE__TRY(mote__gltf_index(gl, node, "camera", at, gl->camera_count, "camera", &nd->camera));
    if (nd->camera >= 0 && gl->camera_node < 0)
        gl->camera_node = i;      /* the first in the scene is the view, as viewers take it */
    const cJSON *lp = mote__json_get(mote__json_get(node, "extensions"), "KHR_lights_punctual");
    if (lp) {
        char lat[96];
        snprintf(lat, sizeof lat, "%s.extensions.KHR_lights_punctual", at);
        MOTE__TRY(mote__json_object(gl->load, lp, lat));
        MOTE__TRY(mote__gltf_index(gl, lp, "light", lat, gl->light_def_count, "light",
                                   &nd->light));
    }
    if (mote__json_get(node, "skin"))
        mote__warn(gl->load, "skins: skinned meshes are drawn in their bind pose");
    if (nd->mesh >= 0)
        MOTE__TRY(mote__gltf_mesh_read(gl, nd->mesh));
    const cJSON *children;
    MOTE__TRY(mote__json_array(gl->load, node, "children", at, &children));
    char cat[64];
    snprintf(cat, sizeof cat, "%s.children", at);
    MOTE__TRY(mote__gltf_walk_list(gl, children, cat, i, nd->depth));
    nd->state = 2;
    return MOTE_OK;
}

mote_result mote__gltf_scene_nodes(mote__gltf *gl)
{
    gl->nodes = mote__store_alloc(&gl->load->tmp, (size_t)gl->node_count, sizeof *gl->nodes);
    gl->meshes = mote__store_alloc(&gl->load->tmp, (size_t)gl->mesh_count, sizeof *gl->meshes);
    if (!gl->nodes || !gl->meshes)
        return mote__oom(gl->load, "nodes");
    for (int i = 0; i < gl->node_count; i++) {
        mote__gltf_node *nd = &gl->nodes[i];
        nd->parent = nd->mesh = nd->camera = nd->light = -1;
    }
    gl->camera_node = -1;
    int scene_count;
    MOTE__TRY(mote__gltf_count(gl, "scenes", &scene_count));
    /* the default scene, else the first, as viewers choose */
    gl->scene = scene_count ? 0 : -1;
    if (mote__json_get(gl->root, "scene")) {
        const cJSON *v = mote__json_get(gl->root, "scene");
        uint32_t s;
        MOTE__TRY(mote__json_uint(gl->load, v, "scene", 0, 4294967295.0, &s));
        if (s >= (uint32_t)scene_count)
            return mote__fail(gl->load, MOTE_ERR_RANGE, "scene: %u names no scene (there are "
                              "%d)", (unsigned)s, scene_count);
        gl->scene = (int)s;
    }
    const int chosen = gl->load->lim.gltf_scene;   /* counted from 1; 0: as above */
    if (chosen > scene_count)
        return mote__fail(gl->load, MOTE_ERR_RANGE, "limits.gltf_scene: %d asks for scenes[%d], "
                          "but the file has %d scene%s", chosen, chosen - 1, scene_count,
                          scene_count == 1 ? "" : "s");
    if (chosen > 0)
        gl->scene = chosen - 1;
    if (gl->scene < 0) {
        mote__warn(gl->load, "no scenes: nothing is drawn");
        return MOTE_OK;
    }
    const cJSON *scene;
    char at[MOTE__GLTF_AT];
    MOTE__TRY(mote__gltf_item(gl, "scenes", gl->scene, &scene, at));
    const cJSON *roots;
    MOTE__TRY(mote__json_array(gl->load, scene, "nodes", at, &roots));
    snprintf(at, sizeof at, "scenes[%d].nodes", gl->scene);
    return mote__gltf_walk_list(gl, roots, at, -1, 0);
}

/* The mote meshes made for nodes[i]: its helper, then its primitives or
 * one hidden mesh. */
static void mote__gltf_fill_node(mote__gltf *gl, int i, bool *two_sided, bool *unlit,
                                 mote_mode *modes, mote_mip *mips)
{
    mote_scene *sc = gl->load->scene;
    const mote__gltf_node *nd = &gl->nodes[i];
    const mote_mesh *above = nd->parent >= 0 ? &sc->meshes[gl->nodes[nd->parent].self] : NULL;
    int k = nd->first_mesh;
    if (nd->sheared) {
        mote_mesh *h = &sc->meshes[k++];
        memcpy(h->position, nd->outer.position, sizeof h->position);
        memcpy(h->rotation_quaternion, nd->outer.quat, sizeof h->rotation_quaternion);
        h->use_quaternion = nd->outer.use_quat;
        memcpy(h->rotation, nd->outer.rotation, sizeof h->rotation);
        memcpy(h->scaling, nd->outer.scaling, sizeof h->scaling);
        h->parent = above;
        h->hidden = true;
        above = h;
    }
    const mote__gltf_mesh *gm = nd->mesh >= 0 ? &gl->meshes[nd->mesh] : NULL;
    for (; k < nd->first_mesh + nd->mesh_count; k++) {
        mote_mesh *m = &sc->meshes[k];
        memcpy(m->position, nd->trs.position, sizeof m->position);
        memcpy(m->rotation, nd->trs.rotation, sizeof m->rotation);
        memcpy(m->rotation_quaternion, nd->trs.quat, sizeof m->rotation_quaternion);
        m->use_quaternion = nd->trs.use_quat;
        memcpy(m->scaling, nd->trs.scaling, sizeof m->scaling);
        m->parent = above;
        m->hidden = true;
        int p = k - nd->self;
        if (!gm || p >= gm->prim_count)
            continue;
        const mote__gltf_prim *pr = &gm->prims[p];
        const mote__gltf_mat *mm = &gl->mats[pr->material < 0 ? gl->mat_count : pr->material];
        m->vertices = pr->verts;
        m->vertex_count = pr->nv;
        m->indices = pr->idx;
        m->index_count = pr->ni;
        m->colors = pr->colors;
        m->material = mm->material;
        m->hidden = !pr->drawn || mm->cut_away;
        two_sided[k] = mm->two_sided;
        unlit[k] = mm->unlit;
        modes[k] = pr->mode;
        mips[k] = mm->mip;
        mote_mesh_update_bounds(m);
    }
}

mote_result mote__gltf_build_meshes(mote__gltf *gl)
{
    size_t total = 0;
    for (int i = 0; i < gl->node_count; i++) {
        mote__gltf_node *nd = &gl->nodes[i];
        if (!nd->in_scene)
            continue;
        int prims = nd->mesh >= 0 ? gl->meshes[nd->mesh].prim_count : 0;
        nd->first_mesh = (int)total;
        nd->self = nd->first_mesh + (nd->sheared ? 1 : 0);
        nd->mesh_count = (nd->sheared ? 1 : 0) + (prims > 0 ? prims : 1);
        total += (size_t)nd->mesh_count;
        if (total > gl->load->lim.max_meshes)
            return mote__fail(gl->load, MOTE_ERR_LIMIT, "nodes: more than the limit of %u "
                              "meshes, one a primitive", (unsigned)gl->load->lim.max_meshes);
    }
    mote_scene *sc = gl->load->scene;
    /* one allocation, never moved: parents point into it */
    sc->meshes = mote__store_alloc(gl->load->keep, total, sizeof *sc->meshes);
    bool *flags = mote__store_alloc(gl->load->keep, 2 * total, sizeof *flags);
    mote_mode *modes = mote__store_alloc(gl->load->keep, total, sizeof *modes);
    mote_mip *mips = mote__store_alloc(gl->load->keep, total, sizeof *mips);
    if (!sc->meshes || !flags || !modes || !mips)
        return mote__oom(gl->load, "meshes");
    sc->mip_modes = mips;
    sc->mesh_count = (int)total;
    sc->two_sided = flags;
    sc->unlit = flags + total;
    sc->modes = modes;
    for (int i = 0; i < gl->node_count; i++)
        if (gl->nodes[i].in_scene)
            mote__gltf_fill_node(gl, i, flags, flags + total, modes, mips);
    return MOTE_OK;
}

void mote__gltf_node_world(const mote__gltf *gl, int node, float w[16])
{
    mote_mesh_world_matrix(&gl->load->scene->meshes[gl->nodes[node].self], w);
}

/* scene.bounds: a world-space box over the vertices drawn. */
mote_result mote__gltf_scene_bounds(mote__gltf *gl)
{
    mote_scene *sc = gl->load->scene;
    bool any = false;
    for (int i = 0; i < sc->mesh_count; i++) {
        const mote_mesh *m = &sc->meshes[i];
        if (!m->hidden && m->vertex_count)
            mote__scene_bounds_add(sc, m, &any);
    }
    return MOTE_OK;
}
