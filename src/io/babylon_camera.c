/*
 * babylon_camera.c - a .babylon file's active camera and lights, and the
 * nodes they take in the parent tree (they may be parents, and have them).
 */
#include "babylon.h"

#include <float.h>
#include <math.h>
#include <stdio.h>
#include <string.h>

/* ---- cameras and lights in the node tree ------------------------------- */

/* Whether v is, or an array holds, a number written as the text
 * "Infinity", "-Infinity" or "NaN", as .NET serialisers write a float
 * JSON has no number for. */
static bool mote__non_finite_text(const cJSON *v)
{
    if (cJSON_IsArray(v)) {
        for (const cJSON *e = v->child; e; e = e->next)
            if (mote__non_finite_text(e))
                return true;
        return false;
    }
    return cJSON_IsString(v) && (strcmp(v->valuestring, "Infinity") == 0 ||
                                 strcmp(v->valuestring, "-Infinity") == 0 ||
                                 strcmp(v->valuestring, "NaN") == 0);
}

/* The first key of the camera that holds such a text, or NULL. Old 3ds
 * Max exporters write a "Default camera" framing an empty box this way:
 * position and target ["-Infinity", ...], maxZ "Infinity". JSON.parse
 * keeps the strings, Camera.Parse copies them in as they are, and
 * JavaScript's arithmetic makes them infinite: the view and projection
 * come out NaN and Babylon.js draws nothing through that camera. */
static const char *mote__camera_non_finite(const cJSON *cam)
{
    static const char *const keys[] = {"position", "target", "rotation", "rotationQuaternion",
                                       "upVector", "fov", "minZ", "maxZ", "orthoLeft",
                                       "orthoRight", "orthoBottom", "orthoTop"};
    for (size_t k = 0; k < sizeof keys / sizeof keys[0]; k++)
        if (mote__non_finite_text(mote__json_get(cam, keys[k])))
            return keys[k];
    return NULL;
}

/* lights[k].type: 0 point, 1 directional, 2 spot, 3 hemispheric. */
static mote_result mote__light_type(mote__babylon *bl, const cJSON *l, const char *at, uint32_t *t)
{
    char at2[64];
    snprintf(at2, sizeof at2, "%s.type", at);
    const cJSON *type = mote__json_get(l, "type");
    if (!type)
        return mote__fail(bl->load, MOTE_ERR_PARSE, "%s: missing", at2);
    return mote__json_uint(bl->load, type, at2, 0, 3, t);
}

/* What a camera or light is found by: its id, or its name when it has no
 * id (Babylon.js gives a node without an id its name); NULL: neither. */
static const char *mote__entry_key(const cJSON *e)
{
    const cJSON *id = mote__json_member(e, "id");
    if (!cJSON_IsString(id))
        id = mote__json_member(e, "name");
    return cJSON_IsString(id) ? id->valuestring : NULL;
}

typedef struct mote__entry_keys {
    const char *id, *unique;
} mote__entry_keys;

/* bl->entry_lists: maps, so that a file with many parents or lights is not
 * searched once per reference. */
static mote_result mote__index_entries(mote__babylon *bl)
{
    static const char *const names[2] = {"cameras", "lights"};
    for (int l = 0; l < 2; l++) {
        mote__entry_list *x = &bl->entry_lists[l];
        const cJSON *arr;
        MOTE__TRY(mote__json_array(bl->load, bl->root, names[l], "", &arr));
        size_t n = mote__json_length(arr);
        x->items = mote__store_alloc(&bl->load->tmp, n, sizeof *x->items);
        x->node = mote__store_alloc(&bl->load->tmp, n, sizeof *x->node);
        mote__entry_keys *keys = mote__store_alloc(&bl->load->tmp, n, sizeof *keys);
        if (!x->items || !x->node || !keys)
            return mote__oom(bl->load, names[l]);
        int k = 0;
        for (const cJSON *e = arr ? arr->child : NULL; e; e = e->next, k++) {
            x->items[k] = e;
            x->node[k] = -1;
            mote__entry_keys *key = &keys[k];
            if (!cJSON_IsObject(e))
                continue;
            key->id = mote__entry_key(e);
            const cJSON *u = mote__json_get(e, "uniqueId");
            if (cJSON_IsNumber(u) && isfinite(u->valuedouble))
                MOTE__TRY(mote__babylon_double_text(bl, u->valuedouble, names[l], &key->unique));
        }
        x->count = k;
        int dup;
        x->ids = mote__idmap_build(bl, &keys[0].id, sizeof *keys, k, &dup);
        x->uniques = mote__idmap_build(bl, &keys[0].unique, sizeof *keys, k, &dup);
        if (!x->ids || !x->uniques)
            return mote__oom(bl->load, names[l]);
    }
    return MOTE_OK;
}

/* A camera's turn: its rotation, or its rotationQuaternion (use_quat)
 * when it has one, mirrored in a right-handed scene. Without a rotation,
 * TargetCamera's default: none, but in a right-handed scene a half turn
 * about y, which keeps such a camera looking down +z (its forward is -z
 * there) as Babylon.js's cameras did before they looked down -z. */
static mote_result mote__camera_turn(mote__babylon *bl, const cJSON *cam, const char *at,
                                     mote__trs *turn)
{
    float *rotation = turn->rotation, *quat = turn->quat;
    memset(rotation, 0, 3 * sizeof *rotation);
    if (bl->right_handed && !mote__json_get(cam, "rotation"))
        rotation[1] = 3.14159265f;
    MOTE__TRY(mote__json_floats(bl->load, cam, "rotation", at, 3, 0, rotation));
    quat[0] = quat[1] = quat[2] = 0.0f;
    quat[3] = 1.0f;
    MOTE__TRY(mote__json_floats(bl->load, cam, "rotationQuaternion", at, 4, 0, quat));
    turn->use_quat = mote__json_get(cam, "rotationQuaternion") != NULL;
    if (bl->right_handed)
        mote__mirror_rotation(rotation, quat);
    return MOTE_OK;
}

/* TargetCamera.setTarget first moves a camera level with its target in z
 * by Epsilon (0.001) along z, so that one at its target looks down -z and
 * one right above or below it has a way round, where a look-at has none;
 * an ArcRotateCamera (and its stereo kinds) places itself otherwise. On
 * the file's position and target, mirrored in a right-handed scene (the
 * file's +z is -z here). */
static void mote__level_target_nudge(const mote__babylon *bl, const cJSON *cam, float position[3],
                                     const float target[3])
{
    const cJSON *type = mote__json_get(cam, "type");
    if (cJSON_IsString(type) && strstr(type->valuestring, "ArcRotateCamera"))
        return;
    if (position[2] == target[2])
        position[2] += bl->right_handed ? -1e-3f : 1e-3f;
}

/* The node standing for cameras[k] (list 0) or lights[k] (list 1), at
 * `where`, made on first use: in Babylon.js cameras and lights are nodes, so they may be parents
 * and have parents. It goes at the end of bl->nodes with no id in the node
 * maps (a mesh or transform node of the same id is found first, as in
 * scene.getLastEntryById), no geometry, and hidden; its transform is the
 * world matrix Babylon.js gives the camera or light. */
static mote_result mote__entry_node(mote__babylon *bl, int list, int k, const char *where, int *out)
{
    mote__entry_list *x = &bl->entry_lists[list];
    const cJSON *json = x->items[k];
    bool is_light = list == 1;
    *out = x->node[k];
    if (*out >= 0)
        return MOTE_OK;
    if (bl->node_count >= bl->node_cap)
        return mote__fail(bl->load, MOTE_ERR_LIMIT, "%s: more than the limit of %u meshes (cameras "
                          "and lights in the parent tree count)", where,
                          (unsigned)bl->load->lim.max_meshes);
    mote__node *nd = &bl->nodes[bl->node_count];
    snprintf(nd->where, sizeof nd->where, "%s", where);
    if (is_light) {
        uint32_t t;
        MOTE__TRY(mote__light_type(bl, json, where, &t));
        if (t == 0 || t == 2)     /* legacy files keep the position in `data` */
            MOTE__TRY(mote__json_floats(bl->load, json, "data", where, 3, 0, nd->trs.position));
        MOTE__TRY(mote__babylon_node_common(bl, json, where, nd));
        /* a light's world matrix is its position only (ShadowLight); a
         * hemispheric light's is the identity, parent or not */
        memset(nd->trs.rotation, 0, sizeof nd->trs.rotation);
        nd->trs.use_quat = false;
        if (t == 3) {
            memset(nd->trs.position, 0, sizeof nd->trs.position);
            nd->parent_id = NULL;
        }
    } else {
        MOTE__TRY(mote__babylon_node_common(bl, json, where, nd));
        MOTE__TRY(mote__camera_turn(bl, json, where, &nd->trs));
        float target[3];
        if (mote__json_get(json, "target")) {
            /* setTarget: yaw and pitch that turn +z toward the target, no roll */
            MOTE__TRY(mote__json_floats(bl->load, json, "target", where, 3, 0, target));
            if (bl->right_handed)
                mote__mirror_point(target);
            mote__level_target_nudge(bl, json, nd->trs.position, target);
            float d[3] = {target[0] - nd->trs.position[0], target[1] - nd->trs.position[1],
                          target[2] - nd->trs.position[2]};
            nd->trs.rotation[0] = atan2f(-d[1], sqrtf(d[0] * d[0] + d[2] * d[2]));
            nd->trs.rotation[1] = atan2f(d[0], d[2]);
            nd->trs.rotation[2] = 0.0f;
            nd->trs.use_quat = false;
        }
    }
    /* a camera's world matrix is its inverted view, a light's a translation:
     * neither scales */
    nd->trs.scaling[0] = nd->trs.scaling[1] = nd->trs.scaling[2] = 1.0f;
    nd->id = nd->unique_id = NULL;
    nd->invisible = true;
    *out = x->node[k] = bl->node_count++;
    return MOTE_OK;
}

/* A parentId that names no mesh or transform node may name a camera, then
 * a light (scene.getLastEntryById's order, the last of equal ids winning).
 * Leaves nd->parent -1 when nothing matches. */
mote_result mote__babylon_camera_light_parent(mote__babylon *bl, mote__node *nd)
{
    for (int l = 0; l < 2; l++) {
        const mote__entry_list *x = &bl->entry_lists[l];
        int k = mote__idmap_find_last(nd->parent_by_unique ? x->uniques : x->ids, nd->parent_id);
        if (k >= 0) {
            char where[48];
            snprintf(where, sizeof where, "%s[%d]", l ? "lights" : "cameras", k);
            return mote__entry_node(bl, l, k, where, &nd->parent);
        }
    }
    return MOTE_OK;
}

/* The active camera: the first whose id (or name) is activeCameraID (older
 * files: activeCamera), else the first, with a warning. NULL: no cameras. */
static mote_result mote__active_camera(mote__babylon *bl, bool warn, const cJSON **out, int *index)
{
    const cJSON *cams;
    *out = NULL;
    *index = 0;
    MOTE__TRY(mote__json_array(bl->load, bl->root, "cameras", "", &cams));
    if (!cams || !cams->child)
        return MOTE_OK;
    const char *active;
    MOTE__TRY(mote__json_string(bl->load, bl->root, "activeCameraID", "scene", &active));
    if (!active)
        MOTE__TRY(mote__json_string(bl->load, bl->root, "activeCamera", "scene", &active));
    *out = cams->child;
    if (!active)
        return MOTE_OK;
    int k = 0;
    for (const cJSON *c = cams->child; c; c = c->next, k++) {
        const char *key = cJSON_IsObject(c) ? mote__entry_key(c) : NULL;
        if (key && strcmp(key, active) == 0) {
            *out = c;
            *index = k;
            return MOTE_OK;
        }
    }
    if (warn)
        mote__warn(bl->load, "activeCamera \"%s\" names no camera; the first one is used",
                   mote__quote(active).s);
    return MOTE_OK;
}

/* Nodes for the active camera and the lights that have a parent, made
 * before the parents are resolved so that their chains are checked (cycles,
 * depth) with the rest. */
mote_result mote__babylon_camera_light_nodes(mote__babylon *bl)
{
    const cJSON *cam;
    int index, unused;
    MOTE__TRY(mote__index_entries(bl));
    MOTE__TRY(mote__active_camera(bl, false, &cam, &index));
    if (cam && cJSON_IsObject(cam) && mote__babylon_names_parent(cam) &&
        !mote__camera_non_finite(cam)) {  /* not used (mote__babylon_camera) */
        char at[48];
        snprintf(at, sizeof at, "cameras[%d]", index);
        MOTE__TRY(mote__entry_node(bl, 0, index, at, &unused));
    }
    const mote__entry_list *lights = &bl->entry_lists[1];
    for (int i = 0; i < lights->count; i++) {
        if (!cJSON_IsObject(lights->items[i]) || !mote__babylon_names_parent(lights->items[i]))
            continue;
        char at[48];
        snprintf(at, sizeof at, "lights[%d]", i);
        MOTE__TRY(mote__entry_node(bl, 1, i, at, &unused));
    }
    return MOTE_OK;
}

/* ---- the active camera and the lights ---------------------------------- */

/* The world matrix of the parent of cameras[k] (list 0) or lights[k] (1),
 * when it has one (its node: mote__babylon_camera_light_nodes). */
static bool mote__parent_world(const mote__babylon *bl, int list, int k, float w[16])
{
    int x = bl->entry_lists[list].node[k];
    if (x < 0 || bl->nodes[x].parent < 0)
        return false;
    mote_mesh_world_matrix(&bl->load->scene->meshes[bl->nodes[bl->nodes[x].parent].first_mesh], w);
    return true;
}

/* p by the world matrix w: as a point (with w's translation) or not. */
static void mote__transform(const float w[16], float p[3], bool point)
{
    float q[3];
    for (int k = 0; k < 3; k++)
        q[k] = w[k] * p[0] + w[4 + k] * p[1] + w[8 + k] * p[2] + (point ? w[12 + k] : 0.0f);
    memcpy(p, q, sizeof q);
}

/* A camera's rotation turning +z, the view direction, and +y, the up
 * vector TargetCamera takes (_rotateUpVectorWithCameraRotationMatrix)
 * when the turn has a z component (rotation.z, a roll, or a quaternion's
 * z): then the view is the whole turn. */
static void mote__turned_axes(const mote__trs *turn, float forward[3], float up[3])
{
    float w[16];
    mote__trs_matrix(turn, w);
    memcpy(forward, &w[8], 3 * sizeof *forward);
    memcpy(up, &w[4], 3 * sizeof *up);
}

/* An orthographic camera's box (orthoLeft, orthoRight, orthoBottom,
 * orthoTop). Babylon.js sizes a missing or null edge by the canvas, half
 * its width or height in pixels, which a file does not know: then the
 * core's default box, 2 units high, with a warning. */
static mote_result mote__ortho_box(mote__babylon *bl, const cJSON *cam, const char *at,
                                   mote_camera *c)
{
    static const char *const keys[4] = {"orthoLeft", "orthoRight", "orthoBottom", "orthoTop"};
    c->projection = MOTE_PROJECTION_ORTHOGRAPHIC;
    int given = 0;
    for (int k = 0; k < 4; k++) {
        given += mote__json_get(cam, keys[k]) != NULL;   /* null: not written */
        MOTE__TRY(mote__json_number(bl->load, cam, keys[k], at, &c->ortho[k]));
    }
    if (given < 4) {
        memset(c->ortho, 0, sizeof c->ortho);
        mote__warn(bl->load,
                   "%s: an orthographic camera without all of orthoLeft, orthoRight, orthoBottom "
                   "and orthoTop (Babylon.js sizes it by the canvas, in pixels) is drawn 2 units "
                   "high",
                   at);
    } else if (!(c->ortho[0] != c->ortho[1] && c->ortho[2] != c->ortho[3])) {
        return mote__fail(bl->load, MOTE_ERR_RANGE,
                          "%s: orthoLeft %g, orthoRight %g, orthoBottom %g and "
                          "orthoTop %g enclose nothing",
                          at, c->ortho[0], c->ortho[1], c->ortho[2], c->ortho[3]);
    }
    return MOTE_OK;
}

mote_result mote__babylon_camera(mote__babylon *bl)
{
    const cJSON *cam;
    int index;
    MOTE__TRY(mote__active_camera(bl, true, &cam, &index));
    if (!cam)
        return MOTE_OK;
    char at[48];
    snprintf(at, sizeof at, "cameras[%d]", index);
    MOTE__TRY(mote__json_object(bl->load, cam, at));
    const char *infinite = mote__camera_non_finite(cam);
    if (infinite) {
        /* rather than nothing, the scene as a camera of mote's frames it */
        mote__warn(bl->load, "%s.%s: \"Infinity\", \"-Infinity\" or \"NaN\" written as text: "
                   "Babylon.js's view through this camera is not a number and draws nothing; "
                   "mote frames the scene with a camera of its own", at, infinite);
        return MOTE_OK;
    }
    const cJSON *mode = mote__json_get(cam, "mode");
    const bool ortho = cJSON_IsNumber(mode) && mode->valuedouble == 1.0;   /* ORTHOGRAPHIC_CAMERA */
    mote_camera *c = &bl->load->scene->camera;
    memset(c, 0, sizeof *c);
    if (ortho)
        MOTE__TRY(mote__ortho_box(bl, cam, at, c));
    MOTE__TRY(mote__json_floats(bl->load, cam, "position", at, 3, 0, c->position));
    if (bl->right_handed)
        mote__mirror_point(c->position);
    const char *locked;
    float turned_up[3];
    bool rolled = false;
    MOTE__TRY(mote__babylon_id_ref(bl, cam, "lockedTargetId", at, &locked));
    int target_node = mote__idmap_find_last(bl->node_map, locked);
    if (locked && target_node < 0)
        mote__warn(bl->load, "%s.lockedTargetId: \"%s\" names no mesh or transform node; the "
                   "camera's own direction is used", at, mote__quote(locked).s);
    if (target_node >= 0) {
        /* a target camera (3ds Max) looks at the node's world position */
        float w[16];
        mote_mesh_world_matrix(&bl->load->scene->meshes[bl->nodes[target_node].first_mesh], w);
        memcpy(c->target, &w[12], sizeof c->target);
        mote__level_target_nudge(bl, cam, c->position, c->target);
    } else if (mote__json_get(cam, "target")) {
        MOTE__TRY(mote__json_floats(bl->load, cam, "target", at, 3, 0, c->target));
        if (bl->right_handed)
            mote__mirror_point(c->target);
        mote__level_target_nudge(bl, cam, c->position, c->target);
    } else {
        /* target = position + forward (+z) turned by the rotation (yaw,
         * pitch, roll; rotationQuaternion overrides it), as meshes turn */
        mote__trs turn;
        float fwd[3];
        memset(&turn, 0, sizeof turn);   /* at the origin, unscaled */
        MOTE__TRY(mote__camera_turn(bl, cam, at, &turn));
        mote__turned_axes(&turn, fwd, turned_up);
        rolled = turn.use_quat ? turn.quat[2] != 0.0f : turn.rotation[2] != 0.0f;
        for (int k = 0; k < 3; k++)
            c->target[k] = c->position[k] + fwd[k];
    }
    MOTE__TRY(mote__json_floats(bl->load, cam, "upVector", at, 3, 0, c->up));
    if (bl->right_handed)
        mote__mirror_point(c->up);
    if (rolled)
        memcpy(c->up, turned_up, sizeof c->up);
    /* Babylon.js's Camera defaults */
    c->fov = 0.8f;
    c->znear = 1.0f;
    c->zfar = 10000.0f;
    MOTE__TRY(mote__json_number(bl->load, cam, "fov", at, &c->fov));
    MOTE__TRY(mote__json_number(bl->load, cam, "minZ", at, &c->znear));
    MOTE__TRY(mote__json_number(bl->load, cam, "maxZ", at, &c->zfar));
    if (!ortho && !(c->fov > 0.0f && c->fov < 3.14159f))   /* unused by an orthographic one */
        return mote__fail(bl->load, MOTE_ERR_RANGE, "%s.fov: %g is not in (0, pi)", at, c->fov);
    /* Babylon.js's FOVMODE_HORIZONTAL_FIXED: any fovMode but 0 (vertical);
     * the aspect ratio is known only when framing (mote_scene_frame) */
    MOTE__TRY(mote__json_flag(bl->load, cam, "fovMode", at,
                              &bl->load->scene->camera_fov_is_horizontal));
    /* an orthographic camera takes minZ as given, 0 or negative too; a
     * perspective one, as Babylon.js projects it, minZ <= 0 as 0.1 */
    if (!ortho && c->znear <= 0.0f)
        c->znear = 0.1f;
    /* maxZ 0: an infinite far plane (perspective). 2^24 times the near
     * distance instead: there far / (far - near), the factor depth differs
     * by from an infinite projection's, is 1 within half a float epsilon,
     * so depths match the infinite projection's to float rounding */
    if (!ortho && c->zfar == 0.0f)
        c->zfar = c->znear * 16777216.0f;
    if (!(c->zfar > c->znear))
        return mote__fail(bl->load, MOTE_ERR_RANGE, "%s: minZ %g and maxZ %g need minZ < maxZ%s",
                          at, c->znear, c->zfar, ortho ? "" : " (maxZ 0: no far plane)");
    /* a parent (3ds Max rigs) moves and turns the whole view: the view
     * matrix is the parent's world matrix after the camera's own */
    float w[16];
    if (mote__parent_world(bl, 0, index, w)) {
        if (c->up[0] == 0.0f && c->up[1] == 0.0f && c->up[2] == 0.0f)
            c->up[1] = 1.0f;
        mote__transform(w, c->position, true);
        mote__transform(w, c->target, true);
        mote__transform(w, c->up, false);
    }
    bl->load->scene->has_camera = true;
    return MOTE_OK;
}

/* A point or spot light's range: > 0 fades it to nothing at that distance
 * (Babylon.js's default falloff). Babylon.js writes Number.MAX_VALUE, which
 * no float holds, for a light without one; that, 0, and a negative range
 * leave it unlimited (0). */
static mote_result mote__light_range(mote__babylon *bl, const cJSON *light, const char *at,
                                     float *range)
{
    const cJSON *v = mote__json_get(light, "range");
    if (cJSON_IsNumber(v) && v->valuedouble > (double)FLT_MAX)
        return MOTE_OK;
    MOTE__TRY(mote__json_number(bl->load, light, "range", at, range));
    if (!(*range > 0.0f))
        *range = 0.0f;
    return MOTE_OK;
}

/* The scene's lights_off, made on first use. */
static uint32_t *mote__lights_off(mote__babylon *bl)
{
    mote_scene *sc = bl->load->scene;
    if (!sc->lights_off && sc->mesh_count > 0)
        sc->lights_off = mote__store_alloc(bl->load->keep, (size_t)sc->mesh_count, sizeof *sc->lights_off);
    return (uint32_t *)(uintptr_t)sc->lights_off;
}

/* Whether list (an array of ids, or absent) holds id. */
static bool mote__listed(const cJSON *list, const char *id)
{
    for (const cJSON *e = cJSON_IsArray(list) ? list->child : NULL; e && id; e = e->next)
        if (cJSON_IsString(e) && strcmp(e->valuestring, id) == 0)
            return true;
    return false;
}

/* Light l (the scene's light `index`) lights only the meshes its
 * includedOnlyMeshesIds names, when that lists any, and none that its
 * excludedMeshesIds names: the others get its bit in lights_off. */
static mote_result mote__light_meshes(mote__babylon *bl, const cJSON *l, const char *at, int index)
{
    const cJSON *only = mote__json_get(l, "includedOnlyMeshesIds"), *excluded = mote__json_get(l, "excludedMeshesIds");
    const bool has_only = cJSON_IsArray(only) && only->child, has_not = cJSON_IsArray(excluded) && excluded->child;
    if (!has_only && !has_not)
        return MOTE_OK;
    uint32_t *off = mote__lights_off(bl);
    if (!off)
        return bl->load->scene->mesh_count > 0 ? mote__oom(bl->load, at) : MOTE_OK;
    for (int i = 0; i < bl->node_count; i++) {
        const mote__node *nd = &bl->nodes[i];
        const bool lit = (!has_only || mote__listed(only, nd->id)) && !mote__listed(excluded, nd->id);
        for (int k = 0; !lit && k < nd->mesh_count; k++)
            off[nd->first_mesh + k] |= (uint32_t)1 << index;
    }
    return MOTE_OK;
}

/* A material's maxSimultaneousLights: of the lights that light a mesh, in
 * the scene's order, the first that many do (Babylon.js binds no more). */
static mote_result mote__light_limits(mote__babylon *bl)
{
    mote_scene *sc = bl->load->scene;
    for (int m = 0; m < sc->mesh_count && bl->max_lights; m++) {
        if (bl->max_lights[m] >= sc->light_count)
            continue;
        uint32_t *off = mote__lights_off(bl);
        if (!off)
            return mote__oom(bl->load, "lights");
        int lit = 0;
        for (int i = 0; i < sc->light_count; i++)
            if (!(off[m] >> i & 1) && lit++ >= bl->max_lights[m])
                off[m] |= (uint32_t)1 << i;
    }
    return MOTE_OK;
}

mote_result mote__babylon_lights(mote__babylon *bl)
{
    const cJSON *lights;
    MOTE__TRY(mote__json_array(bl->load, bl->root, "lights", "", &lights));
    int i = 0, ignored = 0, first_ignored = 0;
    mote_scene *sc = bl->load->scene;
    sc->has_lights = lights && lights->child;
    for (const cJSON *l = lights ? lights->child : NULL; l; l = l->next, i++) {
        char at[48];
        snprintf(at, sizeof at, "lights[%d]", i);
        MOTE__TRY(mote__json_object(bl->load, l, at));
        uint32_t t = 0;
        MOTE__TRY(mote__light_type(bl, l, at, &t));
        mote_light L;
        memset(&L, 0, sizeof L);
        float data[3] = {0, 0, 0};
        MOTE__TRY(mote__json_floats(bl->load, l, "data", at, 3, 0, data));
        bool has_data = mote__json_get(l, "data") != NULL;
        if (t == 0 || t == 2) {
            L.type = t == 0 ? MOTE_LIGHT_POINT : MOTE_LIGHT_SPOT;
            memcpy(L.position, data, sizeof data);
            MOTE__TRY(mote__json_floats(bl->load, l, "position", at, 3, 0, L.position));
            MOTE__TRY(mote__light_range(bl, l, at, &L.range));
            if (t == 2) {         /* Babylon.js makes a spot light of no angle and exponent 0 */
                MOTE__TRY(mote__json_floats(bl->load, l, "direction", at, 3, 0, L.direction));
                MOTE__TRY(mote__json_number(bl->load, l, "angle", at, &L.spot_angle));
                MOTE__TRY(mote__json_number(bl->load, l, "exponent", at, &L.spot_exponent));
            }
        } else if (t == 1) {
            L.type = MOTE_LIGHT_DIRECTIONAL;
            L.direction[1] = -1.0f;
            if (has_data)
                memcpy(L.direction, data, sizeof data);
            MOTE__TRY(mote__json_floats(bl->load, l, "direction", at, 3, 0, L.direction));
        } else {
            L.type = MOTE_LIGHT_HEMISPHERIC;
            L.direction[1] = 1.0f;
            if (has_data)
                memcpy(L.direction, data, sizeof data);
            MOTE__TRY(mote__json_floats(bl->load, l, "direction", at, 3, 0, L.direction));
            MOTE__TRY(mote__babylon_color3(bl, l, "groundColor", at, L.ground_color));
        }
        if (bl->right_handed) {
            mote__mirror_point(L.position);
            mote__mirror_point(L.direction);
        }
        float color[3] = {1, 1, 1}, intensity = 1.0f;
        MOTE__TRY(mote__babylon_color3(bl, l, "diffuse", at, color));
        MOTE__TRY(mote__json_number(bl->load, l, "intensity", at, &intensity));
        memcpy(L.color, color, sizeof color);
        L.intensity = intensity;
        /* the core reads 0 as "default": a black light gets a colour so
         * small that it adds nothing (a hemispheric one keeps its ground
         * colour at its intensity); a light of intensity 0 adds nothing at
         * all, ground included */
        if ((color[0] == 0.0f && color[1] == 0.0f && color[2] == 0.0f) ||
            intensity == 0.0f) {
            L.color[0] = 1e-30f;
            L.color[1] = L.color[2] = 0.0f;
        }
        if (intensity == 0.0f) {
            L.intensity = 1.0f;
            memset(L.ground_color, 0, sizeof L.ground_color);
        }
        /* highlights' colour (white unsaid; black, which the core reads
         * as unset, as good as none) */
        float spec[3] = {1, 1, 1};
        MOTE__TRY(mote__babylon_color3(bl, l, "specular", at, spec));
        memcpy(L.specular, spec, sizeof spec);
        if ((spec[0] == 0.0f && spec[1] == 0.0f && spec[2] == 0.0f) || intensity == 0.0f) {
            L.specular[0] = 1e-30f;
            L.specular[1] = L.specular[2] = 0.0f;
        }
        /* a disabled light, or one under a disabled parent, lights nothing */
        bool enabled = true;
        MOTE__TRY(mote__json_flag(bl->load, l, "isEnabled", at, &enabled));
        int x = bl->entry_lists[1].node[i];
        if (!enabled || (x >= 0 && mote__babylon_node_disabled(bl, &bl->nodes[x])))
            continue;
        /* a parent moves a point or spot light and turns a directional one
         * (ShadowLight's transformed position and direction); a
         * hemispheric light keeps its direction (its node has no parent) */
        float w[16];
        if (mote__parent_world(bl, 1, i, w)) {
            if (L.type != MOTE_LIGHT_DIRECTIONAL)   /* point or spot */
                mote__transform(w, L.position, true);
            if (L.type != MOTE_LIGHT_POINT)         /* directional or spot */
                mote__transform(w, L.direction, false);
        }
        if (sc->light_count >= MOTE_MAX_LIGHTS) {
            if (ignored++ == 0)
                first_ignored = i;
            continue;
        }
        MOTE__TRY(mote__light_meshes(bl, l, at, sc->light_count));
        sc->lights[sc->light_count++] = L;
    }
    MOTE__TRY(mote__light_limits(bl));
    /* one warning for them all, not one each */
    if (ignored == 1)
        mote__warn(bl->load, "lights[%d]: more than %d lights; this one is ignored", first_ignored,
                   MOTE_MAX_LIGHTS);
    else if (ignored > 1)
        mote__warn(bl->load, "lights[%d]: more than %d lights; it and %d later ones are ignored",
                   first_ignored, MOTE_MAX_LIGHTS, ignored - 1);
    return MOTE_OK;
}
