/*
 * babylon_lod.c - levels of detail (lodMeshIds with lodDistances) as
 * Babylon.js's loader makes them and its getLOD chooses them.
 */
#include "babylon.h"

#include <stdio.h>
#include <stdlib.h>
#include <string.h>

/* A level of detail takes its master's place: AbstractMesh.getWorldMatrix
 * returns the master's world matrix while the mesh has one (addLODLevel
 * sets _masterMesh), whatever the level's own transform, pivot and
 * parent; as the master's child with the identity transform it has that
 * matrix, and its children follow it as they follow getWorldMatrix. */
static void mote__lod_take_place(mote__node *nd, int master)
{
    memset(nd->trs.position, 0, sizeof nd->trs.position);
    memset(nd->trs.rotation, 0, sizeof nd->trs.rotation);
    memset(nd->trs.quat, 0, sizeof nd->trs.quat);
    nd->trs.use_quat = false;
    nd->trs.scaling[0] = nd->trs.scaling[1] = nd->trs.scaling[2] = 1.0f;
    nd->has_matrix = false;
    nd->parent = master;
    nd->parent_instance = -1;
}

/* Farthest first, as Mesh._sortLODLevels sorts them; equal distances in
 * the order they were added (Array.prototype.sort is stable). */
static int mote__lod_level_cmp(const void *a, const void *b)
{
    const mote__lod_level *x = a, *y = b;
    if (x->distance != y->distance)
        return x->distance > y->distance ? -1 : 1;
    return (x->seq > y->seq) - (x->seq < y->seq);
}

/* Sorts n levels as getLOD walks them and makes each run of levels that
 * draw nothing one level, of the run's last (smallest) distance: getLOD
 * picks the first level below the camera's distance, so the run is
 * picked exactly when that one would be. Returns the new count. */
static int mote__lod_sort(mote__lod_level *lv, int n)
{
    qsort(lv, (size_t)n, sizeof *lv, mote__lod_level_cmp);
    int k = 0;
    for (int j = 0; j < n; j++) {
        if (k > 0 && lv[j].node < 0 && lv[k - 1].node < 0)
            lv[k - 1] = lv[j];
        else
            lv[k++] = lv[j];
    }
    return k;
}

static bool mote__is_instance(const mote__babylon *bl, int node)
{
    return node >= bl->instances_first && node < bl->instances_end;
}

/* A copy of level mesh `level` for instance `inst` of its master, drawn in
 * the instance's place: InstancedMesh.getLOD asks its source's getLOD with
 * the instance's own bounding sphere, and the level chosen is drawn as an
 * instance of the level mesh, at the instance's world matrix. It shares
 * the level's arrays, material and sub-meshes. */
static mote_result mote__lod_copy(mote__babylon *bl, int level, int inst, int *out)
{
    if (bl->node_count >= bl->node_cap)
        return mote__fail(bl->load, MOTE_ERR_LIMIT, "%s: more than the limit of %u meshes (each "
                          "instance of a mesh with levels of detail has its own)",
                          bl->nodes[inst].where, (unsigned)bl->load->lim.max_meshes);
    mote__node *c = &bl->nodes[bl->node_count];
    const mote__node *l = &bl->nodes[level];
    *c = *l;
    c->arrays = l->arrays ? l->arrays : &bl->nodes[level];
    c->id = c->unique_id = c->parent_id = NULL;
    c->parent_by_unique = false;
    c->first_instance = c->instance_count = 0;
    /* drawn as the level's geometry: the level's thin instances are not
     * copied */
    c->first_thin = c->thin_count = 0;
    c->undrawn = false;
    c->lod_ids = c->lod_distances = NULL;
    c->lod_copy = true;
    c->invisible = c->disabled = false;   /* a level's own flags are not read */
    c->state = 0;
    mote__lod_take_place(c, inst);
    *out = bl->node_count++;
    return MOTE_OK;
}

/* Levels for the instances of each master (mote__lod_copy): a group per
 * instance, its levels those of its master with the copies in place of
 * the level meshes. Counted against the mesh limit before any is made. */
static mote_result mote__lod_copies(mote__babylon *bl)
{
    size_t copies = 0, levels = 0;
    const int groups = bl->lod_group_count;
    for (int gi = 0; gi < groups; gi++) {
        const mote__lod_group *g = &bl->lod_groups[gi];
        size_t meshes = 0, n = (size_t)bl->nodes[g->base].instance_count;
        for (int k = 0; k < g->level_count; k++)
            meshes += bl->lod_levels[g->first_level + k].node >= 0;
        copies += n * meshes;
        levels += n * (size_t)g->level_count;
    }
    if (levels == 0)
        return MOTE_OK;
    if (copies > (size_t)(bl->node_cap - bl->node_count))
        return mote__fail(bl->load, MOTE_ERR_LIMIT,
                          "meshes: more than the limit of %u meshes (each "
                          "instance of a mesh with levels of detail has its own: %zu)",
                          (unsigned)bl->load->lim.max_meshes, copies);
    mote__lod_level *all = mote__store_alloc(&bl->load->tmp, (size_t)bl->lod_level_count + levels,
                                             sizeof *all);
    if (!all)
        return mote__oom(bl->load, "meshes");
    memcpy(all, bl->lod_levels, (size_t)bl->lod_level_count * sizeof *all);
    bl->lod_levels = all;
    for (int gi = 0; gi < groups; gi++) {
        const mote__lod_group g = bl->lod_groups[gi];
        const mote__node *m = &bl->nodes[g.base];
        for (int j = 0; j < m->instance_count; j++) {
            int inst = m->first_instance + j;
            if (bl->lod_master[inst] >= 0)
                continue;   /* itself a level: it chooses none (mote__babylon_lods) */
            mote__lod_group *ng = &bl->lod_groups[bl->lod_group_count++];
            ng->base = inst;
            ng->first_level = bl->lod_level_count;
            ng->level_count = g.level_count;
            for (int k = 0; k < g.level_count; k++) {
                mote__lod_level lv = bl->lod_levels[g.first_level + k];
                if (lv.node >= 0)
                    MOTE__TRY(mote__lod_copy(bl, lv.node, inst, &lv.node));
                bl->lod_levels[bl->lod_level_count++] = lv;
            }
        }
    }
    return MOTE_OK;
}

/* The levels of detail of the meshes that say lodMeshIds with
 * lodDistances, as babylonFileLoader.ts's loadDetailLevels makes them
 * (master by master, in the file's order): level k is the mesh
 * scene.getMeshById(lodMeshIds[k]) finds (the first mesh of that id,
 * each mesh followed by its instances; none: no level, warned) at
 * lodDistances[k], and a last lodDistances past the ids, when above 0, is
 * a level that draws nothing; fewer distances than ids make no levels
 * (warned, as Babylon.js warns). A mesh already a level of another is not
 * taken again (addLODLevel: "You cannot use a mesh as LOD level twice").
 * lodCoverages is not read: loadDetailLevels uses the distances alone.
 * Each level mesh takes its master's place (mote__lod_take_place); a
 * master that is itself a level keeps its levels hidden (a level is
 * blocked: its own getLOD never runs); an instance named as a level stands
 * in its master's place and is drawn there as it would be anyway (an
 * InstancedMesh is never blocked), the level drawing nothing more. */
mote_result mote__babylon_lods(mote__babylon *bl)
{
    const int nm = bl->file_meshes;
    size_t cap = 0;
    for (int i = 0; i < nm; i++)
        if (bl->nodes[i].lod_ids && bl->nodes[i].lod_distances)
            cap += mote__json_length(bl->nodes[i].lod_ids) + 1;
    if (cap == 0)
        return MOTE_OK;
    /* the meshes in scene.meshes' order, for getMeshById */
    int n = 0;
    int *order = mote__store_alloc(&bl->load->tmp, (size_t)bl->node_count, sizeof *order);
    const char **ids = mote__store_alloc(&bl->load->tmp, (size_t)bl->node_count, sizeof *ids);
    bl->lod_master =
        mote__store_alloc(&bl->load->tmp, (size_t)bl->node_cap, sizeof *bl->lod_master);
    bl->lod_levels = mote__store_alloc(&bl->load->tmp, cap, sizeof *bl->lod_levels);
    bl->lod_groups = mote__store_alloc(&bl->load->tmp, (size_t)bl->node_count,
                                       sizeof *bl->lod_groups);
    if (!order || !ids || !bl->lod_master || !bl->lod_levels || !bl->lod_groups)
        return mote__oom(bl->load, "meshes");
    for (int i = 0; i < nm; i++) {
        const mote__node *m = &bl->nodes[i];
        order[n] = i;
        ids[n++] = m->id;
        for (int j = 0; j < m->instance_count; j++) {
            order[n] = m->first_instance + j;
            ids[n++] = bl->nodes[m->first_instance + j].id;
        }
    }
    int dup;
    mote__idmap *map = mote__idmap_build(bl, ids, sizeof *ids, n, &dup);
    if (!map)
        return mote__oom(bl->load, "meshes");
    for (int i = 0; i < bl->node_cap; i++)
        bl->lod_master[i] = -1;
    for (int i = 0; i < nm; i++) {
        const mote__node *m = &bl->nodes[i];
        if (!m->lod_ids || !m->lod_ids->child || !m->lod_distances)
            continue;
        size_t nid = mote__json_length(m->lod_ids), ndist = mote__json_length(m->lod_distances);
        if (ndist < nid) {
            mote__warn(bl->load,
                       "%s: %zu lodDistances for %zu lodMeshIds: Babylon.js makes no levels "
                       "of detail of them (\"Invalid level of detail distances\"), each mesh is "
                       "drawn by itself",
                       m->where, ndist, nid);
            continue;
        }
        mote__lod_group *g = &bl->lod_groups[bl->lod_group_count];
        g->base = i;
        g->first_level = bl->lod_level_count;
        int seq = 0;
        size_t k = 0;
        const cJSON *d = m->lod_distances->child;
        for (const cJSON *e = m->lod_ids->child; e; e = e->next, d = d->next, k++) {
            char at[96];
            snprintf(at, sizeof at, "%s.lodMeshIds[%zu]", m->where, k);
            if (cJSON_IsNull(e)) {
                mote__warn(bl->load, "%s: null names no mesh; Babylon.js adds no level for it (one "
                           "past which nothing is drawn is a last lodDistances value past the "
                           "ids)", at);
                continue;
            }
            if (!cJSON_IsString(e))
                return mote__fail(bl->load, MOTE_ERR_PARSE, "%s: expected a string, found %s", at,
                                  mote__json_type_name(e));
            int pos = mote__idmap_find(map, e->valuestring);
            if (pos < 0) {
                mote__warn(bl->load, "%s: \"%s\" names no mesh; Babylon.js adds no level for it",
                           at, mote__quote(e->valuestring).s);
                continue;
            }
            int l = order[pos];
            if (l == i)
                return mote__fail(bl->load, MOTE_ERR_RANGE,
                                  "%s: \"%s\" names the mesh itself (a level "
                                  "is drawn at its master's world matrix)",
                                  at, mote__quote(e->valuestring).s);
            if (bl->lod_master[l] >= 0) {
                mote__warn(bl->load,
                           "%s: \"%s\" is a level of detail of %s already; Babylon.js takes "
                           "a mesh as a level once",
                           at, mote__quote(e->valuestring).s, bl->nodes[bl->lod_master[l]].where);
                continue;
            }
            char dat[96];
            float distance;
            snprintf(dat, sizeof dat, "%s.lodDistances[%zu]", m->where, k);
            MOTE__TRY(mote__json_float(bl->load, d, dat, &distance));
            /* steps: no walk round a cycle of parents (mote__babylon_parents
             * reports it after) */
            for (int a = m->parent, steps = 0; a >= 0 && steps <= bl->node_count;
                 a = bl->nodes[a].parent, steps++)
                if (a == l)
                    return mote__fail(bl->load, MOTE_ERR_RANGE,
                                      "%s: \"%s\" is a parent of the mesh, "
                                      "whose place it would take",
                                      at, mote__quote(e->valuestring).s);
            bl->lod_master[l] = i;
            mote__lod_take_place(&bl->nodes[l], i);
            mote__lod_level *lv = &bl->lod_levels[bl->lod_level_count++];
            lv->distance = distance;
            lv->node = mote__is_instance(bl, l) ? -1 : l;
            lv->seq = seq++;
        }
        if (ndist > nid) {
            const cJSON *last = m->lod_distances->child;
            for (size_t j = 1; j < ndist; j++)
                last = last->next;
            char dat[96];
            float culling;
            snprintf(dat, sizeof dat, "%s.lodDistances[%zu]", m->where, ndist - 1);
            MOTE__TRY(mote__json_float(bl->load, last, dat, &culling));
            if (culling > 0.0f) {
                mote__lod_level *lv = &bl->lod_levels[bl->lod_level_count++];
                lv->distance = culling;
                lv->node = -1;
                lv->seq = seq++;
            }
        }
        g->level_count = mote__lod_sort(&bl->lod_levels[g->first_level],
                                        bl->lod_level_count - g->first_level);
        bl->lod_level_count = g->first_level + g->level_count;
        if (g->level_count > 0)
            bl->lod_group_count++;
    }
    /* a master that is itself a level is blocked: only its master chooses */
    int kept = 0;
    for (int gi = 0; gi < bl->lod_group_count; gi++)
        if (bl->lod_master[bl->lod_groups[gi].base] < 0)
            bl->lod_groups[kept++] = bl->lod_groups[gi];
    bl->lod_group_count = kept;
    return mote__lod_copies(bl);
}

/* ---- groups in the scene ----------------------------------------------- */

/* What a node draws as the base or a level of detail: its sub-meshes, or
 * its thin instances' (contiguous nodes, so contiguous meshes); nothing
 * when its own are not drawn and it has no thin instances. */
static void mote__lod_unit(const mote__babylon *bl, int node, int *first, int *count)
{
    const mote__node *nd = &bl->nodes[node];
    *first = nd->first_mesh;
    *count = 0;
    if (nd->thin_count > 0) {
        const mote__node *t = &bl->nodes[nd->first_thin];
        *first = t->first_mesh;
        *count = nd->thin_count * t->mesh_count;
    } else if (!nd->undrawn) {
        *count = nd->mesh_count;
    }
}

/* scene.lods from the groups of mote__babylon_lods, once the meshes are made, each
 * showing its base; the levels of groups that are none (masters that are
 * levels themselves) are hidden for good. */
mote_result mote__babylon_lod_groups(mote__babylon *bl)
{
    mote_scene *sc = bl->load->scene;
    if (!bl->lod_master)
        return MOTE_OK;
    for (int i = 0; i < bl->node_count; i++) {
        /* an instance taken as a level is drawn as ever (mote__babylon_lods) */
        if ((bl->lod_master[i] < 0 || mote__is_instance(bl, i)) && !bl->nodes[i].lod_copy)
            continue;
        int first, count;
        mote__lod_unit(bl, i, &first, &count);
        for (int k = first; k < first + count; k++)
            sc->meshes[k].hidden = true;
    }
    if (bl->lod_group_count == 0)
        return MOTE_OK;
    mote_lod *lods = mote__store_alloc(bl->load->keep, (size_t)bl->lod_group_count, sizeof *lods);
    mote_lod_level *levels = mote__store_alloc(bl->load->keep, (size_t)bl->lod_level_count,
                                               sizeof *levels);
    if (!lods || !levels)
        return mote__oom(bl->load, "meshes");
    for (int g = 0; g < bl->lod_group_count; g++) {
        const mote__lod_group *lg = &bl->lod_groups[g];
        mote_lod *lod = &lods[g];
        mote__lod_unit(bl, lg->base, &lod->first_mesh, &lod->mesh_count);
        lod->bounds_mesh = bl->nodes[lg->base].first_mesh;
        lod->hidden = mote__babylon_node_hidden(bl, &bl->nodes[lg->base]);
        lod->levels = levels;
        lod->level_count = lg->level_count;
        for (int k = 0; k < lg->level_count; k++) {
            const mote__lod_level *lv = &bl->lod_levels[lg->first_level + k];
            levels[k].distance = lv->distance;
            levels[k].first_mesh = 0;
            levels[k].mesh_count = 0;
            if (lv->node >= 0)
                mote__lod_unit(bl, lv->node, &levels[k].first_mesh, &levels[k].mesh_count);
        }
        levels += lg->level_count;
    }
    sc->lods = lods;
    sc->lod_count = bl->lod_group_count;
    for (int g = 0; g < sc->lod_count; g++)
        mote__lod_show(sc, sc->meshes, g, -1);
    return MOTE_OK;
}
