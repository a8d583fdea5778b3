/*
 * babylon.c - .babylon scene files (cJSON) to mote meshes, materials,
 * textures, camera and lights. Both layouts are read: the tutorial's legacy
 * interleaved `vertices` and the current `positions`/`normals`/`uvs`/`colors`
 * (inline or through `geometryId`). See ACCURACY.md, "The .babylon format".
 * Babylon.js serialises no switch for vertex colours (`useVertexColors` is
 * a run-time property of its meshes, not written to files), so `colors` are
 * always used; `hasVertexAlpha` is not read, as mote ignores alpha.
 * Materials: diffuse/albedo (PBRMetallicRoughness: baseColor) colour and
 * texture, backFaceCulling (kept per mesh in mote_scene.two_sided: the
 * core's culling is a draw option),
 * disableLighting with the emissive and ambient colours, or PBR's unlit
 * (mote_scene.unlit, drawn without lights), and
 * the texture's coordinatesIndex (1: uvs2, read only when a material asks
 * for it). Textures are files in the scene's folder, or base64 data: URLs
 * (base64String, or name) decoded in texture.c.
 *
 * Every value is checked before it is used: types, finite floats, index
 * ranges, counts against the limits before anything is allocated. Errors
 * name the file and the JSON path. All allocations made for the scene are
 * recorded in a store that mote_scene_free releases; temporaries go in a
 * second store released at the end of every load, failed or not.
 *
 * Decisions (tested in tests/test_loader_errors.c):
 * - Of a key written twice in an object the last counts, as with
 *   JSON.parse (mote__member; tested in tests/test_io.c).
 * - A mesh with no vertex data loads as a 0-vertex mesh (it may be a
 *   parent); empty arrays are fine and give 0 triangles. Positions with
 *   no indices give 0 triangles too, with a warning, unless the mesh says
 *   isUnIndexed (its vertices taken three by three: mote__sequential_indices).
 * - Duplicate material (and multi-material) ids: the last wins, with a
 *   warning, as Babylon.js resolves materialId with getLastMaterialById.
 *   A mesh's materialUniqueId, when it matches a (multi-)material's
 *   uniqueId, is used before its materialId (current Babylon.js files).
 * - A materialId (or multi-material slot) naming nothing: default white
 *   material, with a warning. A parentId naming nothing leaves the node
 *   (mesh, camera or light) without a parent, with a warning, as Babylon.js
 *   loads it; a parentInstanceIndex past the parent's instances is an
 *   error. A parentId several nodes hold names the last of them
 *   (Babylon.js's getLastEntryById).
 * - A mesh whose arrays are in another file (incremental or binary
 *   exports) loads without them, with a warning.
 * - Materials and multi-materials count against limits.max_meshes too, and
 *   so do transform nodes and instances.
 * - Meshes naming one geometryId, and a mesh's instances, share its arrays.
 * - A mesh drawn with a coordinatesIndex 1 texture but without uvs2 keeps
 *   its uvs, with a warning; coordinatesIndex 2..5 (uvs3...) warns too.
 * - With no base_dir (mote_scene_load_memory), embedded images are not
 *   loaded either: no textures at all, as documented.
 * - An orthographic camera (mode 1) keeps its box (orthoLeft...); one
 *   that lacks an edge, which Babylon.js sizes by the canvas in pixels,
 *   is drawn 2 units high, with a warning.
 * - A localMatrix or pivotMatrix is folded into its node's transform, a
 *   sheared one with a hidden helper node (mote__fold_matrix); one not
 *   affine, or a pivot with no inverse, is an error.
 * - useRightHandedSystem true: the scene is loaded mirrored in z, which
 *   draws Babylon.js's image on mote's left-handed core (mote__mirror_point;
 *   tested in tests/test_loader_transforms.c).
 * - A mesh's overrideMaterialSideOrientation (or sideOrientation), else its
 *   material's sideOrientation, other than the scene's default, or a
 *   material's cullBackFaces false, turns its front faces round: its
 *   triangles are drawn flipped (mote__side_indices).
 * - A mesh's thinInstances become nodes of their own, children of the mesh
 *   at their matrices, and the mesh and its instances are not drawn
 *   (mote__thin_count, mote__thin_instances; tested in
 *   tests/test_loader_transforms.c).
 * - lodMeshIds with lodDistances make levels of detail: each level takes
 *   its master's place, and scene.lods says which are shown for a camera
 *   (mote__lods, mote_scene_choose_lod; tested in tests/test_io.c).
 *
 * Cameras and lights (tested in tests/test_io.c), as Babylon.js does:
 * - A parentId naming no mesh or transform node may name a camera, then a
 *   light (by id, name when it has no id, or uniqueId; the last of equal
 *   ones, as scene.getLastEntryById). That camera or light, the active
 *   camera and every light with a parentId get a hidden 0-vertex mesh
 *   after the others in scene.meshes (mote__xnode), so their chains are
 *   checked and placed like any other: a camera's turns as its view, a
 *   light's is its position only, a hemispheric light's is the identity
 *   (its parent ignored).
 * - The active camera's parent moves its position, target and up; a
 *   light's moves a point or spot light's position and turns a directional
 *   light's direction. A light disabled, or under a disabled node, is left
 *   out; when all are, mote_scene_frame adds no stand-in (has_lights).
 * - lockedTargetId (a mesh or transform node; else a warning) sets the
 *   target to that node's world position; then target, then rotation
 *   (rotationQuaternion overriding it) give the view direction; a camera
 *   level with its target or locked target in z is first moved 0.001
 *   along z, as TargetCamera.setTarget does (mote__level_target_nudge).
 * - minZ and maxZ default to 1 and 10000 (Camera's); minZ <= 0 is 0.1,
 *   maxZ 0 is no far plane (a far one: mote__camera); minZ >= maxZ is an
 *   error. activeCameraID matches an id, or a name when there is no id.
 */
#include "io_internal.h"

#include <cJSON.h>

#include <float.h>
#include <math.h>
#include <stdint.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>

/* ---- owned allocations ------------------------------------------------- */

typedef struct mote__store {
    void **ptrs;
    size_t count, cap;
} mote__store;

static void mote__store_release(mote__store *s)
{
    for (size_t i = 0; i < s->count; i++)
        mote__io_free(s->ptrs[i]);
    mote__io_free(s->ptrs);
    s->ptrs = NULL;
    s->count = s->cap = 0;
}

/* Zeroed memory recorded in s; NULL when out of memory (nothing leaks). */
static void *mote__store_alloc(mote__store *s, size_t count, size_t size)
{
    if (size && count > SIZE_MAX / size)
        return NULL;
    if (s->count == s->cap) {
        size_t ncap = s->cap ? s->cap * 2 : 32;
        void **np = mote__io_malloc(ncap * sizeof *np);
        if (!np)
            return NULL;
        if (s->count)
            memcpy(np, s->ptrs, s->count * sizeof *np);
        mote__io_free(s->ptrs);
        s->ptrs = np;
        s->cap = ncap;
    }
    void *p = mote__io_calloc(count ? count : 1, size ? size : 1);
    if (p)
        s->ptrs[s->count++] = p;
    return p;
}

/* ---- loader state ------------------------------------------------------ */

/* A sideOrientation as Babylon.js culls by it: 0 (Material.ClockWise-
 * SideOrientation) or any other number; not said: the scene's default */
enum { MOTE__SIDE_UNSAID = 0, MOTE__SIDE_CW, MOTE__SIDE_OTHER };

typedef struct mote__mat {
    const char *id;
    const char *unique_id;        /* uniqueId as text ("%.17g"), or NULL */
    mote_material material;
    signed char invert_y;         /* the texture's invertY: 0, 1, or -1 (not said) */
    bool two_sided;               /* backFaceCulling false */
    bool unlit;                   /* disableLighting (or PBR's unlit): no lights */
    bool uv2;                     /* the texture's coordinatesIndex is 1: it samples uvs2 */
    unsigned char side;           /* sideOrientation (MOTE__SIDE_...) */
    bool cull_front;              /* cullBackFaces false: the front faces are culled */
} mote__mat;

typedef struct mote__multi {
    const char *id;
    const char *unique_id;        /* uniqueId as text ("%.17g"), or NULL */
    int *slots;                   /* material index per slot, -1: default */
    int slot_count;
} mote__multi;

typedef struct mote__sub {
    uint32_t index_start, index_count;
    uint32_t material_index;
    /* its own triangles, or NULL: the node's from index_start. An
     * unindexed sub-mesh of a right-handed scene starting inside one of
     * the node's flipped triangles takes them from the node's run that
     * starts where it does, modulo 3 (mote__submeshes) */
    uint32_t *own_indices;
} mote__sub;

typedef struct mote__node {
    const char *id;
    const char *unique_id;        /* uniqueId as text ("%.17g"), or NULL */
    const char *parent_id;        /* an id, or a uniqueId as text (parent_by_unique) */
    bool parent_by_unique;        /* parentId was a number: Babylon.js writes the parent's uniqueId */
    int parent_instance;          /* parentInstanceIndex: the parent's instance, -1: the parent itself */
    int first_instance, instance_count;   /* a mesh's instances among the nodes */
    const char *material_id;
    const char *material_unique_id; /* materialUniqueId as text, or NULL */
    char where[48];               /* "meshes[3]" or "transformNodes[0]" */
    int parent;                   /* node index, -1: none */
    int state;                    /* cycle search: 0 new, 1 on the path, 2 done */
    int first_mesh, mesh_count;
    float position[3], rotation[3], quat[4], scaling[3];
    bool use_quat;
    /* localMatrix or pivotMatrix (Babylon.js's array order, which is
     * mote's column-major one), folded into the transform by
     * mote__fold_matrix; has_matrix false: none, or the identity */
    float matrix[16];
    bool has_matrix;
    bool matrix_undone;           /* a pivot: its inverse applied after the turn and scale */
    const char *matrix_name;      /* for messages: "pivotMatrix", "source's localMatrix"... */
    bool invisible, disabled;     /* isVisible false; isEnabled false (children too) */
    bool legacy;                  /* interleaved `vertices`: v = 0 is the top row */
    bool unindexed;               /* isUnIndexed: vertices 0,1,2 / 3,4,5 / ... are the triangles */
    bool is_helper;               /* a sheared matrix's hidden stand-in (mote__fold_matrix) */
    unsigned char side;           /* overrideMaterialSideOrientation or sideOrientation (MOTE__SIDE_...) */
    mote_vertex *verts;
    uint32_t nv;
    /* uvs2, 2 floats per vertex, in the temporary store; read only when a
     * material of the file samples them (mote__ld.any_uv2) */
    float *uv2;
    /* verts with uv2 in place of uv, made (once, kept) for the first
     * (sub-)mesh drawn with a material that samples uvs2: the core has one
     * uv per vertex, so such meshes need their own copy; meshes without
     * such a material pay nothing */
    mote_vertex *verts2;
    struct mote__node *arrays;    /* the node whose arrays this one shares, or NULL */
    mote_rgba *colors;            /* one per vertex, or NULL */
    uint32_t *idx;
    /* unindexed, right-handed: the flipped sequential runs from vertex 1
     * and 2, made for the sub-meshes that start there (modulo 3) */
    uint32_t *shifted_runs[2];
    /* idx with each triangle's last two corners swapped, made (once, kept)
     * for the first (sub-)mesh whose side orientation turns its front
     * faces round (mote__side_indices) */
    uint32_t *idx_flipped;
    uint32_t ni;
    mote__sub *subs;
    int sub_count;
    /* a mesh's thin instances: nodes [first_thin, first_thin + thin_count)
     * after the instances, each its child at one matrix of matrixData */
    int first_thin, thin_count;
    bool is_thin;                 /* a thin instance, of the mesh nodes[host] (its parent) */
    int host;
    /* a thin instance whose matrix mirrors: Babylon.js culls all of a
     * mesh's thin instances by the mesh's own world matrix (one draw), so
     * such a one shows its back faces (mote__side_indices) */
    bool thin_mirrored;
    /* its own meshes are not drawn: a mesh drawn as its thin instances, an
     * instance of one (Babylon.js draws a mesh's thin instances in place
     * of it and its instances), or a mesh whose thin instances cannot be
     * drawn (mote__thin_count) */
    bool undrawn;
    const cJSON *lod_ids, *lod_distances; /* lodMeshIds, lodDistances: arrays, or NULL */
    bool lod_copy;                /* a level drawn for an instance of its master (mote__lod_copies) */
} mote__node;

/* A level of detail while loading: its node (-1: it draws nothing), its
 * distance and its place among its master's levels as the file gives them
 * (Babylon.js sorts them by distance, equal ones in that order). */
typedef struct mote__lod_level {
    float distance;
    int node, seq;
} mote__lod_level;

/* A mesh or instance that draws one of its levels: levels
 * [first_level, first_level + level_count) of mote__ld.lod_levels. */
typedef struct mote__lod_group {
    int base, first_level, level_count;
} mote__lod_group;

/* An entry of geometries.vertexData, parsed by the first mesh that names
 * it; later ones share its arrays. */
typedef struct mote__geometry {
    const char *id;
    const cJSON *json;
    /* the node holding its arrays as drawn by its indices [0] or
     * unindexed [1] (isUnIndexed), -1: none yet */
    int owner[2];
} mote__geometry;

/* An id -> index map: a count, then sorted (id, index) pairs; the first of
 * equal ids wins, or the last for mote__idmap_find_last. */
typedef struct mote__idmap {
    const char *id;
    int index;
} mote__idmap;

/* The cameras or the lights: their entries, the node made for each (-1:
 * none yet; mote__xnode), and maps by id (or name) and by uniqueId, looked
 * up for the file's last entry (mote__idmap_find_last, as
 * scene.getLastEntryById). */
typedef struct mote__xlist {
    const cJSON **items;
    int *node;
    int count;
    mote__idmap *ids, *uniques;
} mote__xlist;

/* A distinct warning and how many times it was given. */
typedef struct mote__warning {
    char text[256];
    unsigned count;
} mote__warning;

/* More distinct warnings than scene.warning (256 bytes) can show anyway. */
#define MOTE__MAX_WARNINGS 16

typedef struct mote__ld {
    char name[128];
    const char *base_dir;
    mote_limits lim;
    char *msg;
    size_t msg_size;
    mote_scene *scene;
    mote__store *keep;            /* becomes scene->storage_ */
    mote__store tmp;
    const cJSON *root;
    mote__mat *mats;
    int mat_count;
    mote__idmap *mat_map, *mat_unique_map;
    mote__multi *multis;
    int multi_count;
    mote__idmap *multi_map, *multi_unique_map;
    mote__geometry *geometries;   /* geometries.vertexData */
    int geometry_count;
    mote__idmap *geometry_map;
    mote__node *nodes;
    int node_count;
    int node_cap;                 /* room for the cameras and lights in the tree */
    mote__xlist xlists[2];        /* cameras, lights */
    mote__idmap *node_map;
    bool any_uv2;                 /* a material samples uvs2: keep them while loading */
    mote__texture_set textures;   /* scene->textures, each file or data: URL decoded once */
    bool right_handed;            /* useRightHandedSystem: loaded mirrored (mote__mirror_point) */
    mote__lod_group *lod_groups;  /* masters, then instances of masters (mote__lods) */
    int lod_group_count;
    mote__lod_level *lod_levels;
    int lod_level_count;
    /* per node: the master it is a level of detail of (-1: none); NULL
     * when no mesh has levels */
    int *lod_master;
    int file_meshes;              /* meshes[]: nodes [0, file_meshes) */
    int instances_first, instances_end; /* the instances' nodes */
    mote__warning warnings[MOTE__MAX_WARNINGS]; /* in order of first appearance */
    int warning_count;
    unsigned warnings_dropped;    /* given after the list was full */
} mote__ld;

typedef mote_result R;
#define MOTE__TRY(expr)               \
    do {                              \
        mote_result r__ = (expr);     \
        if (r__ != MOTE_OK)           \
            return r__;               \
    } while (0)

#if defined(__GNUC__)
__attribute__((format(printf, 3, 4)))
#endif
static R mote__fail(mote__ld *ld, R code, const char *fmt, ...)
{
    char what[512];
    va_list ap;
    va_start(ap, fmt);
    vsnprintf(what, sizeof what, fmt, ap);
    va_end(ap);
    return mote__io_error(ld->msg, ld->msg_size, code, "%s: %s", ld->name, what);
}

static R mote__oom(mote__ld *ld, const char *at)
{
    return mote__fail(ld, MOTE_ERR_OUT_OF_MEMORY, "%s: out of memory", at);
}

/* scene.warning from ld->warnings: each distinct warning once, "(xN)"
 * when it was given N times, so that a warning repeated per sub-mesh does
 * not crowd out the ones after it; what does not fit is counted at the
 * end. */
static void mote__show_warnings(mote__ld *ld)
{
    char *w = ld->scene->warning;
    const size_t cap = sizeof ld->scene->warning, tail = 24; /* "; 99 more warnings" */
    size_t used = 0;
    int shown = 0;
    w[0] = '\0';
    for (; shown < ld->warning_count; shown++) {
        const mote__warning *e = &ld->warnings[shown];
        char count[24] = "";
        if (e->count > 1)
            snprintf(count, sizeof count, " (x%u)", e->count);
        size_t need = (used ? 2 : 0) + strlen(e->text) + strlen(count);
        if (used && used + need + tail >= cap)
            break;                /* the first is shown, cut short if it must be */
        snprintf(w + used, cap - used, "%s%s%s", used ? "; " : "", e->text, count);
        used = strlen(w);
    }
    unsigned more = ld->warnings_dropped + (unsigned)(ld->warning_count - shown);
    if (more)
        snprintf(w + used, cap - used, "; %u more warning%s", more, more > 1 ? "s" : "");
}

#if defined(__GNUC__)
__attribute__((format(printf, 2, 3)))
#endif
static void mote__warn(mote__ld *ld, const char *fmt, ...)
{
    char text[sizeof ld->warnings[0].text];
    va_list ap;
    va_start(ap, fmt);
    vsnprintf(text, sizeof text, fmt, ap);
    va_end(ap);
    int i = 0;
    while (i < ld->warning_count && strcmp(ld->warnings[i].text, text) != 0)
        i++;
    if (i < ld->warning_count) {
        ld->warnings[i].count++;
    } else if (i < MOTE__MAX_WARNINGS) {
        memcpy(ld->warnings[i].text, text, sizeof text);
        ld->warnings[i].count = 1;
        ld->warning_count++;
    } else {
        ld->warnings_dropped++;
    }
    mote__show_warnings(ld);
}

/* A name from the file, safe to print (no control bytes, bounded). */
typedef struct mote__q {
    char s[72];
} mote__q;

static mote__q mote__quote(const char *s)
{
    mote__q q;
    mote__io_clean_name(q.s, sizeof q.s, s ? s : "");
    return q;
}

/* ---- JSON value helpers ------------------------------------------------ */

static size_t mote__array_len(const cJSON *a)
{
    size_t n = 0;
    for (const cJSON *e = a ? a->child : NULL; e; e = e->next)
        n++;
    return n;
}

static const char *mote__type_name(const cJSON *v)
{
    if (cJSON_IsNumber(v)) return "a number";
    if (cJSON_IsString(v)) return "a string";
    if (cJSON_IsArray(v)) return "an array";
    if (cJSON_IsObject(v)) return "an object";
    if (cJSON_IsBool(v)) return "a boolean";
    if (cJSON_IsNull(v)) return "null";
    return "something else";
}

/* obj[key], or NULL. Of keys written twice the last counts, as with
 * JSON.parse, which Babylon.js reads files with (cJSON's own lookup
 * finds the first). Every lookup of the loader goes through here. */
static const cJSON *mote__member(const cJSON *obj, const char *key)
{
    const cJSON *last = NULL;
    if (!cJSON_IsObject(obj))
        return NULL;
    for (const cJSON *e = obj->child; e; e = e->next)
        if (e->string && strcmp(e->string, key) == 0)
            last = e;
    return last;
}

/* An optional member of an object; NULL when absent or null. */
static const cJSON *mote__get(const cJSON *obj, const char *key)
{
    const cJSON *v = mote__member(obj, key);
    return cJSON_IsNull(v) ? NULL : v;
}

static R mote__to_float(mote__ld *ld, const cJSON *v, const char *at, float *out)
{
    if (!cJSON_IsNumber(v))
        return mote__fail(ld, MOTE_ERR_PARSE, "%s: expected a number, found %s", at,
                          mote__type_name(v));
    double d = v->valuedouble;
    if (!isfinite(d) || fabs(d) > (double)FLT_MAX)
        return mote__fail(ld, MOTE_ERR_RANGE, "%s: %g is not a finite float", at, d);
    *out = (float)d;
    return MOTE_OK;
}

/* A whole number in [lo, hi]. */
static R mote__to_uint(mote__ld *ld, const cJSON *v, const char *at, double lo, double hi,
                       uint32_t *out)
{
    if (!cJSON_IsNumber(v))
        return mote__fail(ld, MOTE_ERR_PARSE, "%s: expected an integer, found %s", at,
                          mote__type_name(v));
    double d = v->valuedouble;
    if (!isfinite(d) || d != floor(d))
        return mote__fail(ld, MOTE_ERR_PARSE, "%s: %g is not an integer", at, d);
    if (d < lo || d > hi)
        return mote__fail(ld, MOTE_ERR_RANGE, "%s: %.17g is out of range [%.17g, %.17g]", at,
                          d, lo, hi);
    *out = (uint32_t)d;
    return MOTE_OK;
}

/* key -> n floats; absent keeps *out. n_alt: a second accepted length
 * (colours may carry alpha), 0 for none. */
static R mote__vec(mote__ld *ld, const cJSON *obj, const char *key, const char *where,
                   int n, int n_alt, float *out)
{
    const cJSON *a = mote__get(obj, key);
    if (!a)
        return MOTE_OK;
    char at[160];
    snprintf(at, sizeof at, "%s.%s", where, key);
    size_t len = mote__array_len(a);
    if (!cJSON_IsArray(a) || (len != (size_t)n && (n_alt == 0 || len != (size_t)n_alt))) {
        if (n_alt)
            return mote__fail(ld, MOTE_ERR_PARSE, "%s: expected an array of %d or %d numbers",
                              at, n, n_alt);
        return mote__fail(ld, MOTE_ERR_PARSE, "%s: expected an array of %d numbers", at, n);
    }
    float tmp[4];
    int k = 0;
    for (const cJSON *e = a->child; e; e = e->next, k++) {
        char at2[176];
        snprintf(at2, sizeof at2, "%s[%d]", at, k);
        MOTE__TRY(mote__to_float(ld, e, at2, &tmp[k]));
    }
    memcpy(out, tmp, (size_t)n * sizeof *out);
    return MOTE_OK;
}

static R mote__num(mote__ld *ld, const cJSON *obj, const char *key, const char *where,
                   float *out)
{
    const cJSON *v = mote__get(obj, key);
    if (!v)
        return MOTE_OK;
    char at[160];
    snprintf(at, sizeof at, "%s.%s", where, key);
    return mote__to_float(ld, v, at, out);
}

/* key -> a true/false flag (a boolean, or a number: 0 is false); absent
 * keeps *out. */
static R mote__flag(mote__ld *ld, const cJSON *obj, const char *key, const char *where,
                    bool *out)
{
    const cJSON *v = mote__get(obj, key);
    if (!v)
        return MOTE_OK;
    if (cJSON_IsBool(v)) {
        *out = cJSON_IsTrue(v);
        return MOTE_OK;
    }
    char at[160];
    snprintf(at, sizeof at, "%s.%s", where, key);
    float f;
    MOTE__TRY(mote__to_float(ld, v, at, &f));
    *out = f != 0.0f;
    return MOTE_OK;
}

/* key -> a side orientation (MOTE__SIDE_...): a number, 0 or not (Babylon.js
 * tells only Material.ClockWiseSideOrientation, 0, from the rest); absent
 * or null keeps *out. */
static R mote__side(mote__ld *ld, const cJSON *obj, const char *key, const char *where,
                    unsigned char *out)
{
    const cJSON *v = mote__get(obj, key);
    float unused;
    MOTE__TRY(mote__num(ld, obj, key, where, &unused));   /* a finite number, or absent */
    if (v)
        *out = v->valuedouble == 0.0 ? MOTE__SIDE_CW : MOTE__SIDE_OTHER;
    return MOTE_OK;
}

/* key -> a whole number in [0, hi]; absent keeps *out. */
static R mote__uint_member(mote__ld *ld, const cJSON *obj, const char *key, const char *where,
                           uint32_t hi, uint32_t *out)
{
    const cJSON *v = mote__get(obj, key);
    if (!v)
        return MOTE_OK;
    char at[160];
    snprintf(at, sizeof at, "%s.%s", where, key);
    return mote__to_uint(ld, v, at, 0, hi, out);
}

/* key -> string or NULL; anything else is an error. */
static R mote__str(mote__ld *ld, const cJSON *obj, const char *key, const char *where,
                   const char **out)
{
    const cJSON *v = mote__get(obj, key);
    *out = NULL;
    if (!v)
        return MOTE_OK;
    if (!cJSON_IsString(v) || !v->valuestring)
        return mote__fail(ld, MOTE_ERR_PARSE, "%s.%s: expected a string, found %s", where,
                          key, mote__type_name(v));
    *out = v->valuestring;
    return MOTE_OK;
}

/* key -> the id a node refers to, or NULL: absent, null or "" (old 3ds
 * Max exports write "" for no material, Cinema 4D's for no parent, and
 * Babylon.js looks nothing up for it); anything but a string is an error. */
static R mote__id_ref(mote__ld *ld, const cJSON *obj, const char *key, const char *where,
                      const char **out)
{
    MOTE__TRY(mote__str(ld, obj, key, where, out));
    if (*out && !(*out)[0])
        *out = NULL;
    return MOTE_OK;
}

/* key -> a number's text ("%.17g", so equal numbers give equal text) or
 * NULL (absent); anything else is an error. For numeric ids. */
/* v as text ("%.17g", in the temporary store): how uniqueIds are compared */
static R mote__double_text(mote__ld *ld, double v, const char *at, const char **out)
{
    char text[32];
    int n = snprintf(text, sizeof text, "%.17g", v);
    char *copy = mote__store_alloc(&ld->tmp, (size_t)n + 1, 1);
    if (!copy)
        return mote__oom(ld, at);
    memcpy(copy, text, (size_t)n + 1);
    *out = copy;
    return MOTE_OK;
}

/* A finite number v (at names it) as mote__double_text. */
static R mote__number_value_text(mote__ld *ld, const cJSON *v, const char *at, const char **out)
{
    float unused;
    MOTE__TRY(mote__to_float(ld, v, at, &unused));
    return mote__double_text(ld, v->valuedouble, at, out);
}

static R mote__number_text(mote__ld *ld, const cJSON *obj, const char *key, const char *where,
                           const char **out)
{
    const cJSON *v = mote__get(obj, key);
    *out = NULL;
    if (!v)
        return MOTE_OK;
    char at[160];
    snprintf(at, sizeof at, "%s.%s", where, key);
    return mote__number_value_text(ld, v, at, out);
}

/* key -> array or NULL (absent); anything else is an error. */
static R mote__arr(mote__ld *ld, const cJSON *obj, const char *key, const char *where,
                   const cJSON **out)
{
    const cJSON *v = mote__get(obj, key);
    *out = NULL;
    if (!v)
        return MOTE_OK;
    if (!cJSON_IsArray(v))
        return mote__fail(ld, MOTE_ERR_PARSE, "%s%s%s: expected an array, found %s", where,
                          where[0] ? "." : "", key, mote__type_name(v));
    *out = v;
    return MOTE_OK;
}

static R mote__obj_at(mote__ld *ld, const cJSON *v, const char *at)
{
    if (!cJSON_IsObject(v))
        return mote__fail(ld, MOTE_ERR_PARSE, "%s: expected an object, found %s", at,
                          mote__type_name(v));
    return MOTE_OK;
}

/* ---- right-handed scenes ---------------------------------------------- */

/* Babylon.js draws a scene saying useRightHandedSystem with right-handed
 * view and projection matrices (LookAtRH, PerspectiveFovRH) and, as a
 * mesh's default sideOrientation there is the other one, front faces
 * turning the other way on screen. mote's core is left-handed only, so
 * such a scene is loaded mirrored in z, S = diag(1, 1, -1): every point
 * and direction p becomes S p and every transform M becomes S M S. Then
 * P_LH V_LH(S eye, S target, S up) = P_RH V_RH(eye, target, up) S, so the
 * mirrored scene through the mirrored camera lands on the same pixels as
 * Babylon.js's; only the triangles' order is reversed (mote__flip_winding)
 * so that what Babylon.js takes for a front face mote does too. */
static void mote__mirror_point(float p[3])
{
    p[2] = 0.0f - p[2];   /* exactly -p[2], but a zero stays +0 */
}

/* S R S for a rotation R: a quaternion (x, y, z, w) becomes (-x, -y, z,
 * w), Euler angles (rx, ry, rz), applied z, then x, then y, become (-rx,
 * -ry, rz): S Ry(a) S = Ry(-a), S Rx(a) S = Rx(-a), S Rz(a) S = Rz(a). */
static void mote__mirror_rotation(float euler[3], float quat[4])
{
    euler[0] = 0.0f - euler[0];
    euler[1] = 0.0f - euler[1];
    quat[0] = 0.0f - quat[0];
    quat[1] = 0.0f - quat[1];
}

/* S M S for a column-major 4x4 M: the elements of row 2 and of column 2,
 * but not both, change sign. */
static void mote__mirror_matrix(float m[16])
{
    static const int row_or_column_2[6] = {2, 6, 14, 8, 9, 11};
    for (int k = 0; k < 6; k++)
        m[row_or_column_2[k]] = 0.0f - m[row_or_column_2[k]];
}

/* Swaps the last two corners of each whole triangle of idx[0..n). */
static void mote__flip_winding(uint32_t *idx, uint32_t n)
{
    for (uint32_t t = 0; t + 2 < n; t += 3) {
        uint32_t k = idx[t + 1];
        idx[t + 1] = idx[t + 2];
        idx[t + 2] = k;
    }
}

/* The indices first, first + 1, ... (count of them: vertices drawn as
 * triangles in their order), the triangles flipped in a right-handed
 * scene. */
static void mote__sequential_run(const mote__ld *ld, uint32_t *idx, uint32_t first, uint32_t count)
{
    for (uint32_t k = 0; k < count; k++)
        idx[k] = first + k;
    if (ld->right_handed)
        mote__flip_winding(idx, count);
}

/* ---- id maps ----------------------------------------------------------- */

static int mote__idmap_cmp(const void *a, const void *b)
{
    const mote__idmap *x = a, *y = b;
    int c = strcmp(x->id, y->id);
    if (c)
        return c;
    return (x->index > y->index) - (x->index < y->index);
}

/* Builds a map of the non-NULL ids; *dup_index: the second holder of the
 * first duplicated id (or -1). */
static mote__idmap *mote__idmap_build(mote__ld *ld, const char *const *ids, size_t stride,
                                      int n, int *dup_index)
{
    mote__idmap *head = mote__store_alloc(&ld->tmp, (size_t)n + 1, sizeof *head);
    if (!head)
        return NULL;
    mote__idmap *m = head + 1; /* head->index: the entry count */
    int k = 0;
    for (int i = 0; i < n; i++) {
        const char *id = *(const char *const *)((const char *)ids + (size_t)i * stride);
        if (id) {
            m[k].id = id;
            m[k].index = i;
            k++;
        }
    }
    qsort(m, (size_t)k, sizeof *m, mote__idmap_cmp);
    *dup_index = -1;
    for (int i = 1; i < k; i++)
        if (strcmp(m[i - 1].id, m[i].id) == 0 && (*dup_index < 0 || m[i].index < *dup_index))
            *dup_index = m[i].index;
    head->id = "";
    head->index = k;
    return head;
}

/* The first (last: false) or last holder of id, or -1. */
static int mote__idmap_lookup(const mote__idmap *m, const char *id, bool last)
{
    if (!m || !id)
        return -1;
    int n = m[0].index, lo = 0, hi = n; /* m[0] holds the count */
    m++;
    while (lo < hi) { /* first entry > id (last) or >= id */
        int mid = lo + (hi - lo) / 2;
        int c = strcmp(m[mid].id, id);
        if (c < 0 || (last && c == 0))
            lo = mid + 1;
        else
            hi = mid;
    }
    if (last)
        lo--;
    return (lo >= 0 && lo < n && strcmp(m[lo].id, id) == 0) ? m[lo].index : -1;
}

static int mote__idmap_find(const mote__idmap *m, const char *id)
{
    return mote__idmap_lookup(m, id, false);
}

/* The last of equal ids, as Babylon.js resolves materials
 * (getLastMaterialById) and parents (getLastEntryById). */
static int mote__idmap_find_last(const mote__idmap *m, const char *id)
{
    return mote__idmap_lookup(m, id, true);
}

/* ---- textures ---------------------------------------------------------- */

/* The texture a material names (a file in the scene's folder, or with
 * embedded a data: URL), loaded once however many materials name it
 * (mote__texture_set); key names the JSON member in messages. fallback
 * (or NULL): the file to try when name cannot be opened. */
static R mote__texture_found(mote__ld *ld, const char *at, const char *key, const char *name,
                             const char *fallback, bool embedded, mote_material *m)
{
    mote__texture_set *set = &ld->textures;
    char why[256];
    int index = -1;
    R r = embedded ? mote__texture_set_data_url(set, name, &ld->lim, &index, why, sizeof why)
                   : mote__texture_set_file(set, ld->base_dir, name, &ld->lim, &index, why,
                                            sizeof why);
    if (r == MOTE_ERR_IO && fallback) {
        /* the fallback's own error, unless it cannot be opened either */
        char fallback_why[256];
        R rf = mote__texture_set_file(set, ld->base_dir, fallback, &ld->lim, &index,
                                      fallback_why, sizeof fallback_why);
        if (rf != MOTE_ERR_IO) {
            r = rf;
            memcpy(why, fallback_why, sizeof why);
        }
    }
    ld->scene->texture_count = set->count;
    if (r == MOTE_ERR_RANGE)
        return mote__fail(ld, r, "%s.%s: %s (textures must be inside the scene's folder; see "
                          "limits.allow_any_texture_path)", at, key, why);
    if (r == MOTE_ERR_OUT_OF_MEMORY)
        return mote__fail(ld, r, "%s.%s: %s", at, key, why);
    if (r != MOTE_OK) {
        if (ld->lim.missing_texture_is_warning) {
            mote__warn(ld, "%s: %s (drawn untextured)", at, why);
            return MOTE_OK;
        }
        return mote__fail(ld, r, "%s.%s: %s", at, key, why);
    }
    m->texture = &ld->scene->textures[index];
    return MOTE_OK;
}

static int mote__hex_digit(char c)
{
    if (c >= '0' && c <= '9')
        return c - '0';
    if ((c | 0x20) >= 'a' && (c | 0x20) <= 'f')
        return (c | 0x20) - 'a' + 10;
    return -1;
}

/* A texture name written as a URL ("my%20tex.png?v=2", as web exporters
 * write them) read as a file name: the "?query" dropped and %XX escapes
 * decoded. An invalid escape, or %00, leaves the escapes as written.
 * NULL: the same as name. */
static R mote__url_decoded_name(mote__ld *ld, const char *at, const char *name, char **out)
{
    *out = NULL;
    size_t n = strcspn(name, "?"), k = 0;
    char *d = mote__store_alloc(&ld->tmp, n + 1, 1);
    if (!d)
        return mote__oom(ld, at);
    for (size_t i = 0; i < n; i++) {
        if (name[i] != '%') {
            d[k++] = name[i];
            continue;
        }
        /* '?' and the terminating NUL are no hex digits: no read past n */
        int hi = mote__hex_digit(name[i + 1]);
        int lo = hi >= 0 ? mote__hex_digit(name[i + 2]) : -1;
        if (lo < 0 || (hi | lo) == 0) {
            memcpy(d, name, n);   /* keep the escapes as written */
            k = n;
            break;
        }
        d[k++] = (char)(hi << 4 | lo);
        i += 2;
    }
    d[k] = '\0';
    if (strcmp(d, name) != 0)
        *out = d;
    return MOTE_OK;
}

/* Loads (once per resolved path) the texture a material names: a file in
 * the scene's folder (as written, else as a URL: mote__url_decoded_name), or an image embedded as a base64 data: URL, in
 * "base64String" (Babylon.js's SceneSerializer; "name" is then no file) or
 * in "name" itself. A texture without a name is none. */
static R mote__material_texture(mote__ld *ld, const cJSON *tex, const char *at,
                                mote__mat *mm)
{
    mote_material *m = &mm->material;
    MOTE__TRY(mote__obj_at(ld, tex, at));
    const char *name, *embedded;
    MOTE__TRY(mote__str(ld, tex, "name", at, &name));
    MOTE__TRY(mote__str(ld, tex, "base64String", at, &embedded));
    /* Texture.Parse makes no texture of one without a name (null, absent
     * or ""), base64String or not: old 3ds Max exports write "name": null
     * for a map without a bitmap, and Babylon.js draws the material's
     * colour alone */
    if (!name || !name[0])
        return MOTE_OK;
    const char *key = embedded ? "base64String" : "name";
    if (!embedded && mote__io_is_data_url(name))
        embedded = name;
    m->u_scale = 1.0f;
    m->v_scale = 1.0f;
    MOTE__TRY(mote__num(ld, tex, "uScale", at, &m->u_scale));
    MOTE__TRY(mote__num(ld, tex, "vScale", at, &m->v_scale));
    MOTE__TRY(mote__num(ld, tex, "uOffset", at, &m->u_offset));
    MOTE__TRY(mote__num(ld, tex, "vOffset", at, &m->v_offset));
    if (mote__get(tex, "invertY")) {
        bool inv = true;
        MOTE__TRY(mote__flag(ld, tex, "invertY", at, &inv));
        mm->invert_y = inv;
    }
    /* which uv set the texture samples: uvs (0) or uvs2 (1); Babylon.js
     * has more (uvs3...), which mote does not read */
    uint32_t ci = 0;
    MOTE__TRY(mote__uint_member(ld, tex, "coordinatesIndex", at, 5, &ci));
    if (ci) {
        if (ci > 1)
            mote__warn(ld, "%s.coordinatesIndex: %u: only uvs and uvs2 are read; uvs are used",
                       at, (unsigned)ci);
        mm->uv2 = ci == 1;
        ld->any_uv2 = ld->any_uv2 || mm->uv2;
    }
    static const char *const wrap_keys[2] = {"wrapU", "wrapV"};
    for (int k = 0; k < 2; k++) {
        const cJSON *w = mote__get(tex, wrap_keys[k]);
        mote_wrap mode = MOTE_WRAP_REPEAT;
        if (cJSON_IsBool(w)) {
            mode = cJSON_IsTrue(w) ? MOTE_WRAP_REPEAT : MOTE_WRAP_CLAMP;
        } else if (w) {
            char at2[176];
            snprintf(at2, sizeof at2, "%s.%s", at, wrap_keys[k]);
            uint32_t v;
            MOTE__TRY(mote__to_uint(ld, w, at2, 0, 2, &v));
            mode = v == 0 ? MOTE_WRAP_CLAMP : v == 1 ? MOTE_WRAP_REPEAT : MOTE_WRAP_MIRROR;
        }
        if (k == 0)
            m->wrap_u = mode;
        else
            m->wrap_v = mode;
    }
    if (!ld->base_dir)
        return MOTE_OK; /* colours only (embedded images too, as documented) */
    if (embedded)
        return mote__texture_found(ld, at, key, embedded, NULL, true, m);
    /* "://" past the start: Babylon.js's Texture.Parse fetches such a name
     * as it is (the SceneSerializer writes web textures so), not from the
     * scene's folder; mote downloads nothing */
    const char *scheme_end = strstr(name, "://");
    if (scheme_end && scheme_end != name) {
        if (ld->lim.missing_texture_is_warning) {
            mote__warn(ld, "%s: \"%s\" is a web address, which mote does not download (drawn "
                       "untextured)", at, mote__quote(name).s);
            return MOTE_OK;
        }
        return mote__fail(ld, MOTE_ERR_IO, "%s.name: \"%s\" is a web address, which mote does "
                          "not download (textures are files in the scene's folder, or embedded)",
                          at, mote__quote(name).s);
    }
    /* decoded, the name is checked again: "%2e%2e/x.png" is not tried */
    char *decoded;
    const char *why;
    MOTE__TRY(mote__url_decoded_name(ld, at, name, &decoded));
    if (decoded && !ld->lim.allow_any_texture_path && mote__io_name_escapes(decoded, &why))
        decoded = NULL;
    return mote__texture_found(ld, at, key, name, decoded, false, m);
}

/* ---- materials --------------------------------------------------------- */

static uint8_t mote__unit_byte(float c)
{
    if (!(c > 0.0f))
        return 0;
    if (c >= 1.0f)
        return 255;
    return (uint8_t)(c * 255.0f + 0.5f);
}

/* A colour's channels from 0..1 (clamped); alpha as it was. */
static void mote__set_rgb(mote_rgba *out, const float c[3])
{
    out->r = mote__unit_byte(c[0]);
    out->g = mote__unit_byte(c[1]);
    out->b = mote__unit_byte(c[2]);
}

/* A material's colour from 0..1 channels (clamped). */
static void mote__set_color(mote_material *mat, const float c[3])
{
    mote__set_rgb(&mat->color, c);
    mat->color.a = 255;
    mat->color_set = true;
}

/* Babylon.js's StandardMaterial draws clamp(lights x diffuse + emissive +
 * ambient x the scene's ambient colour) x texture x vertex colour: mote's
 * lit colour (mote.h, Lighting) with the last two sums as the material's
 * emissive colour. So the scene's ambient colour is taken in here, and
 * mote_scene_frame leaves the frame's (which mote multiplies by the
 * diffuse colour) at 0: a material without an ambient colour (Babylon.js's
 * default is black) gets none of it. With disableLighting Babylon.js binds
 * no lights, so those two alone, clamped, multiply the texture and the
 * vertex colours: exactly mote's unlit draw with that as the material
 * colour. A PBR material's unlit shows its albedo as it is. */
static R mote__emissive(mote__ld *ld, const cJSON *m, const char *at, mote__mat *mm)
{
    float emissive[3] = {0, 0, 0}, ambient[3] = {0, 0, 0};
    const char *key = mote__get(m, "emissiveColor") && !mote__get(m, "emissive") ? "emissiveColor"
                                                                                 : "emissive";
    MOTE__TRY(mote__vec(ld, m, key, at, 3, 4, emissive));
    MOTE__TRY(mote__vec(ld, m, "ambient", at, 3, 4, ambient));
    /* an emissive texture (one with a name: Texture.Parse makes none
     * otherwise) adds its colour, lit or not, as no mote draw can: named,
     * as a glowing colour is (Maya's incandescence map is one) */
    const cJSON *glow = mote__get(m, "emissiveTexture");
    const cJSON *glow_name = cJSON_IsObject(glow) ? mote__get(glow, "name") : NULL;
    if (cJSON_IsString(glow_name) && glow_name->valuestring[0])
        mote__warn(ld, "%s.emissiveTexture: \"%s\" is not drawn (mote adds no texture's light "
                   "to a material)", at, mote__quote(glow_name->valuestring).s);
    bool pbr_unlit = false;
    MOTE__TRY(mote__flag(ld, m, "unlit", at, &pbr_unlit));
    if (pbr_unlit) {
        mm->unlit = true;
        return MOTE_OK;
    }
    float c[3];
    for (int k = 0; k < 3; k++)
        c[k] = emissive[k] + ambient[k] * ld->scene->ambient[k];
    if (mm->unlit) {
        mote__set_color(&mm->material, c);
        return MOTE_OK;
    }
    mote__set_rgb(&mm->material.emissive, c);
    return MOTE_OK;
}

static R mote__materials(mote__ld *ld)
{
    const cJSON *list;
    MOTE__TRY(mote__arr(ld, ld->root, "materials", "", &list));
    size_t n = mote__array_len(list);
    if (n > ld->lim.max_meshes)
        return mote__fail(ld, MOTE_ERR_LIMIT, "materials: %zu materials, more than the limit "
                          "of %u", n, (unsigned)ld->lim.max_meshes);
    ld->mats = mote__store_alloc(&ld->tmp, n, sizeof *ld->mats);
    if (!ld->mats)
        return mote__oom(ld, "materials");
    /* textures live in the scene, one per material at most: allocate once
     * so that the pointers materials keep stay valid */
    mote__texture_set *set = &ld->textures;
    set->textures = ld->scene->textures = mote__store_alloc(ld->keep, n, sizeof(mote_texture));
    set->files = mote__store_alloc(ld->keep, n, sizeof *set->files);
    set->urls = mote__store_alloc(&ld->tmp, n, sizeof *set->urls);
    if (!set->textures || !set->files || !set->urls)
        return mote__oom(ld, "materials");
    set->cap = (int)n;
    ((mote__scene_files *)ld->scene->files_)->textures = set->files;
    int i = 0;
    for (const cJSON *m = list ? list->child : NULL; m; m = m->next, i++) {
        char at[64];
        snprintf(at, sizeof at, "materials[%d]", i);
        MOTE__TRY(mote__obj_at(ld, m, at));
        mote__mat *mm = &ld->mats[i];
        mm->invert_y = -1;
        MOTE__TRY(mote__str(ld, m, "id", at, &mm->id));
        if (!mm->id)
            MOTE__TRY(mote__str(ld, m, "name", at, &mm->id));
        if (!mm->id)
            return mote__fail(ld, MOTE_ERR_PARSE, "%s: expected an \"id\" string", at);
        MOTE__TRY(mote__number_text(ld, m, "uniqueId", at, &mm->unique_id));
        ld->mat_count = i + 1;
    }
    int dup, unused;
    ld->mat_map = mote__idmap_build(ld, &ld->mats[0].id, sizeof *ld->mats, ld->mat_count, &dup);
    ld->mat_unique_map = mote__idmap_build(ld, &ld->mats[0].unique_id, sizeof *ld->mats,
                                           ld->mat_count, &unused);
    if (!ld->mat_map || !ld->mat_unique_map)
        return mote__oom(ld, "materials");
    if (dup >= 0)
        mote__warn(ld, "materials[%d]: id \"%s\" is used before; the last one is kept", dup,
                   mote__quote(ld->mats[dup].id).s);
    i = 0;
    for (const cJSON *m = list ? list->child : NULL; m; m = m->next, i++) {
        char at[64];
        snprintf(at, sizeof at, "materials[%d]", i);
        mote__mat *mm = &ld->mats[i];
        /* shadowed by a later one of the same id, and not reachable by a
         * uniqueId: never used, so its texture is not loaded */
        if (mote__idmap_find_last(ld->mat_map, mm->id) != i && !mm->unique_id)
            continue;
        /* other types (the materials library's sky, grid, water..., node
         * materials) draw by rules of their own */
        const cJSON *type = mote__get(m, "customType");
        static const char *const read_types[4] = {
            "BABYLON.StandardMaterial", "BABYLON.PBRMaterial",
            "BABYLON.PBRMetallicRoughnessMaterial", "BABYLON.PBRSpecularGlossinessMaterial"};
        bool read_type = !cJSON_IsString(type);
        for (int k = 0; k < 4 && !read_type; k++)
            read_type = strcmp(type->valuestring, read_types[k]) == 0;
        if (!read_type)
            mote__warn(ld, "%s: customType \"%s\" is not read; drawn as a standard material of "
                       "its diffuse colour", at, mote__quote(type->valuestring).s);
        bool cull_back = true, cull_back_faces = true;
        MOTE__TRY(mote__flag(ld, m, "backFaceCulling", at, &cull_back));
        mm->two_sided = !cull_back;
        MOTE__TRY(mote__side(ld, m, "sideOrientation", at, &mm->side));
        MOTE__TRY(mote__flag(ld, m, "cullBackFaces", at, &cull_back_faces));
        mm->cull_front = !cull_back_faces;
        MOTE__TRY(mote__flag(ld, m, "disableLighting", at, &mm->unlit));
        /* PBRMetallicRoughnessMaterial (the 3ds Max exporter's PBR
         * material) serialises its albedo as baseColor and baseTexture
         * and reads no other key for them; the other types write diffuse
         * (standard, specular-glossiness) or albedo (PBRMaterial) */
        const bool metal_rough = cJSON_IsString(type) && strcmp(type->valuestring, read_types[2]) == 0;
        static const char *const color_keys[5] = {"diffuse", "diffuseColor", "albedo",
                                                  "albedoColor", "baseColor"};
        for (int k = metal_rough ? 4 : 0; k < (metal_rough ? 5 : 4); k++) {
            float c[4] = {1, 1, 1, 1};
            if (!mote__get(m, color_keys[k]))
                continue;
            MOTE__TRY(mote__vec(ld, m, color_keys[k], at, 3, 4, c));
            mote__set_color(&mm->material, c);
            break;
        }
        MOTE__TRY(mote__emissive(ld, m, at, mm));
        static const char *const tex_keys[3] = {"diffuseTexture", "albedoTexture", "baseTexture"};
        for (int k = metal_rough ? 2 : 0; k < (metal_rough ? 3 : 2); k++) {
            const cJSON *t = mote__get(m, tex_keys[k]);
            if (!t)
                continue;
            char at2[96];
            snprintf(at2, sizeof at2, "%s.%s", at, tex_keys[k]);
            MOTE__TRY(mote__material_texture(ld, t, at2, mm));
            break;
        }
    }
    return MOTE_OK;
}

static R mote__multi_materials(mote__ld *ld)
{
    const cJSON *list;
    MOTE__TRY(mote__arr(ld, ld->root, "multiMaterials", "", &list));
    size_t n = mote__array_len(list);
    if (n > ld->lim.max_meshes)
        return mote__fail(ld, MOTE_ERR_LIMIT, "multiMaterials: %zu entries, more than the "
                          "limit of %u", n, (unsigned)ld->lim.max_meshes);
    ld->multis = mote__store_alloc(&ld->tmp, n, sizeof *ld->multis);
    if (!ld->multis)
        return mote__oom(ld, "multiMaterials");
    int i = 0;
    for (const cJSON *m = list ? list->child : NULL; m; m = m->next, i++) {
        char at[64];
        snprintf(at, sizeof at, "multiMaterials[%d]", i);
        MOTE__TRY(mote__obj_at(ld, m, at));
        mote__multi *mm = &ld->multis[i];
        MOTE__TRY(mote__str(ld, m, "id", at, &mm->id));
        if (!mm->id)
            return mote__fail(ld, MOTE_ERR_PARSE, "%s: expected an \"id\" string", at);
        MOTE__TRY(mote__number_text(ld, m, "uniqueId", at, &mm->unique_id));
        /* the SceneSerializer writes the slots by uniqueId as well, and
         * Babylon.js then resolves them so (materials sharing an id, as
         * playgrounds name them, stay apart) */
        const cJSON *slots, *unique_slots;
        MOTE__TRY(mote__arr(ld, m, "materials", at, &slots));
        MOTE__TRY(mote__arr(ld, m, "materialsUniqueIds", at, &unique_slots));
        if (unique_slots)
            slots = unique_slots;
        size_t count = mote__array_len(slots);
        if (count > ld->lim.max_meshes)
            return mote__fail(ld, MOTE_ERR_LIMIT, "%s.materials: %zu slots, more than the "
                              "limit of %u", at, count, (unsigned)ld->lim.max_meshes);
        mm->slots = mote__store_alloc(&ld->tmp, count, sizeof *mm->slots);
        if (!mm->slots)
            return mote__oom(ld, at);
        mm->slot_count = (int)count;
        int k = 0;
        for (const cJSON *s = slots ? slots->child : NULL; s; s = s->next, k++) {
            mm->slots[k] = -1;
            if (cJSON_IsNull(s))
                continue;
            if (unique_slots) {
                char at2[96];
                snprintf(at2, sizeof at2, "%s.materialsUniqueIds[%d]", at, k);
                const char *text;
                MOTE__TRY(mote__number_value_text(ld, s, at2, &text));
                mm->slots[k] = mote__idmap_find_last(ld->mat_unique_map, text);
                if (mm->slots[k] < 0)
                    mote__warn(ld, "%s: %s is the uniqueId of no material", at2, text);
                continue;
            }
            if (!cJSON_IsString(s))
                return mote__fail(ld, MOTE_ERR_PARSE,
                                  "%s.materials[%d]: expected a material id, found %s", at,
                                  k, mote__type_name(s));
            mm->slots[k] = mote__idmap_find_last(ld->mat_map, s->valuestring);
            if (mm->slots[k] < 0)
                mote__warn(ld, "%s.materials[%d]: \"%s\" names no material", at, k,
                           mote__quote(s->valuestring).s);
        }
        ld->multi_count = i + 1;
    }
    int dup, unused;
    ld->multi_map = mote__idmap_build(ld, &ld->multis[0].id, sizeof *ld->multis,
                                      ld->multi_count, &dup);
    ld->multi_unique_map = mote__idmap_build(ld, &ld->multis[0].unique_id, sizeof *ld->multis,
                                             ld->multi_count, &unused);
    if (!ld->multi_map || !ld->multi_unique_map)
        return mote__oom(ld, "multiMaterials");
    if (dup >= 0)
        mote__warn(ld, "multiMaterials[%d]: id \"%s\" is used before; the last one is kept",
                   dup, mote__quote(ld->multis[dup].id).s);
    return MOTE_OK;
}

/* ---- geometry ---------------------------------------------------------- */

enum { MOTE__POS, MOTE__NRM, MOTE__UV, MOTE__UV2, MOTE__LEGACY };

/* Element k of the array at `at` as a float; the place is spelled out only
 * for an error, as vertex arrays are long. */
static R mote__element_float(mote__ld *ld, const cJSON *e, const char *at, size_t k, float *out)
{
    if (!cJSON_IsNumber(e) || !isfinite(e->valuedouble) ||
        fabs(e->valuedouble) > (double)FLT_MAX) {
        char at2[192];
        snprintf(at2, sizeof at2, "%s[%zu]", at, k);
        return mote__to_float(ld, e, at2, out);
    }
    *out = (float)e->valuedouble;
    return MOTE_OK;
}

/* Fills nd->verts (and nd->uv2 when it is there) from arr. */
static R mote__fill(mote__ld *ld, const cJSON *arr, const char *at, mote__node *nd,
                    int what, size_t stride)
{
    mote_vertex *v = nd->verts;
    size_t k = 0;
    for (const cJSON *e = arr->child; e; e = e->next, k++) {
        float f;
        MOTE__TRY(mote__element_float(ld, e, at, k, &f));
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

static R mote__indices(mote__ld *ld, const cJSON *arr, const char *at, mote__node *nd,
                       uint32_t *max_index)
{
    size_t n = mote__array_len(arr);
    *max_index = 0;
    if (n > ld->lim.max_indices || n > (size_t)INT32_MAX)
        return mote__fail(ld, MOTE_ERR_LIMIT, "%s: %zu indices, more than the limit of %u", at,
                          n, (unsigned)ld->lim.max_indices);
    if (n % 3)
        return mote__fail(ld, MOTE_ERR_RANGE, "%s: %zu indices is not a multiple of 3", at, n);
    nd->idx = mote__store_alloc(ld->keep, n, sizeof *nd->idx);
    if (!nd->idx)
        return mote__oom(ld, at);
    nd->ni = (uint32_t)n;
    size_t k = 0;
    for (const cJSON *e = arr->child; e; e = e->next, k++) {
        double d = cJSON_IsNumber(e) ? e->valuedouble : -1.0;
        if (!(d >= 0.0 && d <= 4294967294.0 && d == floor(d))) {
            char at2[192];
            snprintf(at2, sizeof at2, "%s[%zu]", at, k);
            if (!cJSON_IsNumber(e))
                return mote__fail(ld, MOTE_ERR_PARSE, "%s: expected an integer, found %s",
                                  at2, mote__type_name(e));
            if (!isfinite(d) || d != floor(d))
                return mote__fail(ld, MOTE_ERR_PARSE, "%s: %g is not an integer", at2, d);
            return mote__fail(ld, MOTE_ERR_RANGE, "%s: %.17g is out of range", at2, d);
        }
        nd->idx[k] = (uint32_t)d;
        if (nd->idx[k] > *max_index)
            *max_index = nd->idx[k];
    }
    if (ld->right_handed)
        mote__flip_winding(nd->idx, nd->ni);
    return MOTE_OK;
}

static R mote__check_indices(mote__ld *ld, const char *at, const mote__node *nd)
{
    for (uint32_t k = 0; k < nd->ni; k++)
        if (nd->idx[k] >= nd->nv) {
            /* where the file has it: a right-handed scene's triangles are
             * flipped already (mote__flip_winding swaps corners 1 and 2) */
            uint32_t in_file = k;
            if (ld->right_handed && k % 3 && k - k % 3 + 2 < nd->ni)
                in_file = k % 3 == 1 ? k + 1 : k - 1;
            return mote__fail(ld, MOTE_ERR_RANGE, "%s[%u]: %u is out of range (%u vertices)",
                              at, (unsigned)in_file, (unsigned)nd->idx[k], (unsigned)nd->nv);
        }
    return MOTE_OK;
}

static R mote__alloc_vertices(mote__ld *ld, const char *at, size_t nv, mote__node *nd)
{
    if (nv > ld->lim.max_vertices || nv > (size_t)INT32_MAX)
        return mote__fail(ld, MOTE_ERR_LIMIT, "%s: %zu vertices, more than the limit of %u",
                          at, nv, (unsigned)ld->lim.max_vertices);
    nd->verts = mote__store_alloc(ld->keep, nv, sizeof *nd->verts);
    if (!nd->verts)
        return mote__oom(ld, at);
    nd->nv = (uint32_t)nv;
    return MOTE_OK;
}

/* A right-handed scene's positions and normals, mirrored (their
 * triangles are flipped as the indices are read: mote__indices). */
static void mote__mirror_vertices(const mote__ld *ld, mote__node *nd)
{
    if (!ld->right_handed)
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
        const float *p1 = nd->verts[nd->idx[t]].position;
        const float *p2 = nd->verts[nd->idx[t + 1]].position;
        const float *p3 = nd->verts[nd->idx[t + 2]].position;
        float a[3], b[3], n[3];
        for (int k = 0; k < 3; k++) {
            a[k] = p1[k] - p2[k];
            b[k] = p3[k] - p2[k];
        }
        n[0] = a[1] * b[2] - a[2] * b[1];
        n[1] = a[2] * b[0] - a[0] * b[2];
        n[2] = a[0] * b[1] - a[1] * b[0];
        float len = sqrtf(n[0] * n[0] + n[1] * n[1] + n[2] * n[2]);
        if (!(len > 0.0f) || !isfinite(len))
            continue;
        for (int j = 0; j < 3; j++)
            for (int k = 0; k < 3; k++)
                nd->verts[nd->idx[t + j]].normal[k] += n[k] / len;
    }
    for (uint32_t i = 0; i < nd->nv; i++) {
        float *n = nd->verts[i].normal;
        float len = sqrtf(n[0] * n[0] + n[1] * n[1] + n[2] * n[2]);
        if (len > 0.0f && isfinite(len))
            for (int k = 0; k < 3; k++)
                n[k] /= len;
    }
}

/* The legacy interleaved layout: position, normal, uv (uvCount >= 1) and
 * uv2 (uvCount 2) per vertex. */
static R mote__legacy_geometry(mote__ld *ld, const cJSON *mesh, const cJSON *verts,
                               const char *where, mote__node *nd)
{
    char at[96], iat[96];
    snprintf(at, sizeof at, "%s.vertices", where);
    snprintf(iat, sizeof iat, "%s.indices", where);
    const cJSON *ind;
    MOTE__TRY(mote__arr(ld, mesh, "indices", where, &ind));
    uint32_t max_index = 0;
    if (ind)
        MOTE__TRY(mote__indices(ld, ind, iat, nd, &max_index));
    size_t len = mote__array_len(verts);
    size_t stride = 0;
    uint32_t u = 0;
    if (mote__get(mesh, "uvCount")) {
        MOTE__TRY(mote__uint_member(ld, mesh, "uvCount", where, 2, &u));
        stride = 6 + 2 * (size_t)u;
        if (len % stride)
            return mote__fail(ld, MOTE_ERR_RANGE,
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
            return mote__fail(ld, MOTE_ERR_PARSE,
                              "%s: no uvCount, and %zu floats fit %s stride (6, 8 or 10)", at,
                              len, fits ? "more than one" : "no");
    }
    MOTE__TRY(mote__alloc_vertices(ld, at, len / stride, nd));
    if (stride == 10 && ld->any_uv2) {
        nd->uv2 = mote__store_alloc(&ld->tmp, nd->nv, 2 * sizeof *nd->uv2);
        if (!nd->uv2)
            return mote__oom(ld, at);
    }
    MOTE__TRY(mote__fill(ld, verts, at, nd, MOTE__LEGACY, stride));
    mote__mirror_vertices(ld, nd);
    nd->legacy = true;
    return mote__check_indices(ld, iat, nd);
}

/* Vertex colours: 4 floats per vertex (r, g, b, a), or 3 (alpha 1), told
 * apart by the length; each 0..1, rounded to a byte and clamped. */
static R mote__colors(mote__ld *ld, const cJSON *arr, const char *at, mote__node *nd)
{
    size_t n = mote__array_len(arr), nv = nd->nv;
    if (n == 0 && nv == 0)
        return MOTE_OK;           /* nothing to colour */
    /* n is 4 or 3 per vertex: mote__check_vertex_counts */
    size_t stride = n == nv * 4 ? 4 : 3;
    nd->colors = mote__store_alloc(ld->keep, nv, sizeof *nd->colors);
    if (!nd->colors)
        return mote__oom(ld, at);
    size_t k = 0;
    for (const cJSON *e = arr->child; e; e = e->next, k++) {
        float f;
        MOTE__TRY(mote__element_float(ld, e, at, k, &f));
        (&nd->colors[k / stride].r)[k % stride] = mote__unit_byte(f);
    }
    if (stride == 3)
        for (size_t i = 0; i < nv; i++)
            nd->colors[i].a = 255;
    return MOTE_OK;
}

/* Gives to the vertex and index arrays of from: shared, not copied. */
static void mote__share_arrays(mote__node *to, mote__node *from)
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
static R mote__check_vertex_counts(mote__ld *ld, const char *where, size_t nv,
                                   const mote__vertex_array *arrays, int count)
{
    char list[320];
    size_t used = 0;
    list[0] = '\0';
    for (int i = 0; i < count; i++) {
        const mote__vertex_array *a = &arrays[i];
        size_t n = mote__array_len(a->arr);
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
    return mote__fail(ld, MOTE_ERR_RANGE, "%s: positions has %zu floats (%zu vertices), but %s",
                      where, 3 * nv, nv, list);
}

/* arr (where.key): `per` floats for each of nd's vertices (the length is
 * checked by mote__check_vertex_counts), into the part `what` says (uvs2
 * get their temporary array here). */
static R mote__per_vertex(mote__ld *ld, const cJSON *arr, const char *where, const char *key,
                          size_t per, int what, mote__node *nd)
{
    char at[96];
    snprintf(at, sizeof at, "%s.%s", where, key);
    size_t nv = nd->nv;
    if (what == MOTE__UV2) {
        nd->uv2 = mote__store_alloc(&ld->tmp, nv, 2 * sizeof *nd->uv2);
        if (!nd->uv2)
            return mote__oom(ld, at);
        per = 1;                  /* a flat array */
    }
    return mote__fill(ld, arr, at, nd, what, per);
}

/* isUnIndexed: Babylon.js draws vertices 0,1,2 / 3,4,5 / ... as triangles
 * and ignores any indices. The indices 0..nv-1 let the core draw it as any
 * other mesh; the whole mesh draws the first nv - nv % 3 of them (a partial
 * last triangle is dropped, as drawArrays drops it), and a sub-mesh its own
 * vertex range (mote__submeshes). */
static R mote__sequential_indices(mote__ld *ld, const char *where, mote__node *nd)
{
    if (nd->nv > ld->lim.max_indices)
        return mote__fail(ld, MOTE_ERR_LIMIT, "%s: isUnIndexed: %u vertices, more indices "
                          "than the limit of %u", where, (unsigned)nd->nv,
                          (unsigned)ld->lim.max_indices);
    if (nd->nv % 3)
        mote__warn(ld, "%s: isUnIndexed, but %u vertices is not a multiple of 3; the last %u "
                   "are not drawn", where, (unsigned)nd->nv, (unsigned)(nd->nv % 3));
    nd->idx = mote__store_alloc(ld->keep, nd->nv, sizeof *nd->idx);
    if (!nd->idx)
        return mote__oom(ld, where);
    mote__sequential_run(ld, nd->idx, 0, nd->nv);
    nd->ni = nd->nv - nd->nv % 3;
    return MOTE_OK;
}

/* The current layout, from the mesh itself or from a geometries.vertexData
 * entry (src, named `where` in messages); nd->unindexed is the mesh's. */
static R mote__current_geometry(mote__ld *ld, const cJSON *src, const char *where,
                                mote__node *nd)
{
    const cJSON *pos, *nrm, *uvs, *uvs2 = NULL, *colors, *ind;
    MOTE__TRY(mote__arr(ld, src, "positions", where, &pos));
    MOTE__TRY(mote__arr(ld, src, "normals", where, &nrm));
    MOTE__TRY(mote__arr(ld, src, "uvs", where, &uvs));
    if (ld->any_uv2)
        MOTE__TRY(mote__arr(ld, src, "uvs2", where, &uvs2));
    MOTE__TRY(mote__arr(ld, src, "colors", where, &colors));
    MOTE__TRY(mote__arr(ld, src, "indices", where, &ind));
    char at[96], iat[96];
    snprintf(iat, sizeof iat, "%s.indices", where);
    uint32_t max_index;
    if (ind && !nd->unindexed)
        MOTE__TRY(mote__indices(ld, ind, iat, nd, &max_index));
    size_t len = mote__array_len(pos);
    snprintf(at, sizeof at, "%s.positions", where);
    if (len % 3)
        return mote__fail(ld, MOTE_ERR_RANGE, "%s: %zu floats is not a multiple of 3", at,
                          len);
    size_t nv = len / 3;
    const mote__vertex_array arrays[4] = {
        {"normals", nrm, 3, 0}, {"uvs", uvs, 2, 0}, {"uvs2", uvs2, 2, 0}, {"colors", colors, 4, 3}};
    MOTE__TRY(mote__check_vertex_counts(ld, where, nv, arrays, 4));
    MOTE__TRY(mote__alloc_vertices(ld, at, nv, nd));
    if (nd->unindexed)
        MOTE__TRY(mote__sequential_indices(ld, where, nd));
    else if (!ind && nv > 0)
        mote__warn(ld, "%s: has positions but no indices (and no isUnIndexed): it draws no "
                   "triangles", where);
    if (pos)
        MOTE__TRY(mote__fill(ld, pos, at, nd, MOTE__POS, 3));
    if (nrm)
        MOTE__TRY(mote__per_vertex(ld, nrm, where, "normals", 3, MOTE__NRM, nd));
    if (uvs)
        MOTE__TRY(mote__per_vertex(ld, uvs, where, "uvs", 2, MOTE__UV, nd));
    if (uvs2)
        MOTE__TRY(mote__per_vertex(ld, uvs2, where, "uvs2", 2, MOTE__UV2, nd));
    if (colors) {
        snprintf(at, sizeof at, "%s.colors", where);
        MOTE__TRY(mote__colors(ld, colors, at, nd));
    }
    MOTE__TRY(mote__check_indices(ld, iat, nd));
    /* mirrored before smooth normals are made: from mirrored positions and
     * flipped triangles they come out as the file's, mirrored */
    mote__mirror_vertices(ld, nd);
    if (!nrm)
        mote__smooth_normals(nd);
    return MOTE_OK;
}

static R mote__submeshes(mote__ld *ld, const cJSON *mesh, const char *where, mote__node *nd)
{
    const cJSON *subs;
    MOTE__TRY(mote__arr(ld, mesh, "subMeshes", where, &subs));
    size_t n = mote__array_len(subs);
    if (n > ld->lim.max_meshes)
        return mote__fail(ld, MOTE_ERR_LIMIT, "%s.subMeshes: %zu entries, more than the limit "
                          "of %u", where, n, (unsigned)ld->lim.max_meshes);
    if (n == 0)
        return MOTE_OK;
    nd->subs = mote__store_alloc(&ld->tmp, n, sizeof *nd->subs);
    if (!nd->subs)
        return mote__oom(ld, where);
    int k = 0;
    for (const cJSON *s = subs->child; s; s = s->next, k++) {
        char at[96], at2[128];
        snprintf(at, sizeof at, "%s.subMeshes[%d]", where, k);
        MOTE__TRY(mote__obj_at(ld, s, at));
        static const char *const keys[5] = {"materialIndex", "verticesStart", "verticesCount",
                                             "indexStart", "indexCount"};
        uint32_t v[5] = {0, 0, nd->nv, 0, nd->ni};
        for (int j = 0; j < 5; j++) {
            const cJSON *e = mote__get(s, keys[j]);
            snprintf(at2, sizeof at2, "%s.%s", at, keys[j]);
            if (!e) {
                if (j == 4 && !nd->unindexed)
                    return mote__fail(ld, MOTE_ERR_PARSE, "%s: missing", at2);
                continue;
            }
            MOTE__TRY(mote__to_uint(ld, e, at2, 0, 4294967295.0, &v[j]));
        }
        if ((uint64_t)v[1] + v[2] > nd->nv)
            return mote__fail(ld, MOTE_ERR_RANGE, "%s: vertices %u..%llu are out of range "
                              "(%u vertices)", at, (unsigned)v[1],
                              (unsigned long long)v[1] + v[2], (unsigned)nd->nv);
        nd->subs[k].material_index = v[0];
        if (nd->unindexed) {
            /* drawn as drawArrays(verticesStart, verticesCount): the
             * sequential indices from verticesStart, whole triangles only */
            nd->subs[k].index_start = v[1];
            nd->subs[k].index_count = v[2] - v[2] % 3;
            if (ld->right_handed && v[1] % 3) {
                /* one run per start modulo 3, shared: a copy per
                 * sub-mesh grew as sub-meshes x vertices */
                uint32_t r = v[1] % 3, **run = &nd->shifted_runs[r - 1];
                if (!*run) {
                    *run = mote__store_alloc(ld->keep, nd->nv - r, sizeof(uint32_t));
                    if (!*run)
                        return mote__oom(ld, at);
                    mote__sequential_run(ld, *run, r, nd->nv - r);
                }
                nd->subs[k].own_indices = *run + (v[1] - r);
            }
            continue;
        }
        if ((uint64_t)v[3] + v[4] > nd->ni)
            return mote__fail(ld, MOTE_ERR_RANGE, "%s: indices %u..%llu are out of range "
                              "(%u indices)", at, (unsigned)v[3],
                              (unsigned long long)v[3] + v[4], (unsigned)nd->ni);
        if (v[3] % 3 || v[4] % 3)
            return mote__fail(ld, MOTE_ERR_RANGE, "%s: indexStart %u and indexCount %u must "
                              "be multiples of 3", at, (unsigned)v[3], (unsigned)v[4]);
        nd->subs[k].index_start = v[3];
        nd->subs[k].index_count = v[4];
    }
    nd->sub_count = k;
    return MOTE_OK;
}

/* Whether a node names a parent: a parentId other than "", which Cinema
 * 4D's exporter writes for none (Babylon.js looks no parent up for it). */
static bool mote__names_parent(const cJSON *node)
{
    const cJSON *p = mote__get(node, "parentId");
    return p && !(cJSON_IsString(p) && p->valuestring[0] == '\0');
}

/* What every node has: its ids, parent, transform and visibility. */
static R mote__node_common(mote__ld *ld, const cJSON *mesh, const char *where, mote__node *nd)
{
    MOTE__TRY(mote__obj_at(ld, mesh, where));
    MOTE__TRY(mote__str(ld, mesh, "id", where, &nd->id));
    if (!nd->id)
        MOTE__TRY(mote__str(ld, mesh, "name", where, &nd->id));
    MOTE__TRY(mote__number_text(ld, mesh, "uniqueId", where, &nd->unique_id));
    /* a parent's id, or (current Babylon.js) its uniqueId */
    nd->parent_by_unique = cJSON_IsNumber(mote__get(mesh, "parentId"));
    if (nd->parent_by_unique)
        MOTE__TRY(mote__number_text(ld, mesh, "parentId", where, &nd->parent_id));
    else
        MOTE__TRY(mote__id_ref(ld, mesh, "parentId", where, &nd->parent_id));
    /* a child of an instance names the instance's source mesh and the
     * instance's place among the source's instances (Babylon.js resolves
     * it so when it loads parents); -1, or absent: the parent itself */
    nd->parent_instance = -1;
    const cJSON *pii = mote__get(mesh, "parentInstanceIndex");
    if (pii && !(cJSON_IsNumber(pii) && pii->valuedouble == -1.0)) {
        char at[96];
        uint32_t k;
        snprintf(at, sizeof at, "%s.parentInstanceIndex", where);
        MOTE__TRY(mote__to_uint(ld, pii, at, 0, INT32_MAX, &k));
        nd->parent_instance = (int)k;
    }
    MOTE__TRY(mote__vec(ld, mesh, "position", where, 3, 0, nd->position));
    MOTE__TRY(mote__vec(ld, mesh, "rotation", where, 3, 0, nd->rotation));
    nd->scaling[0] = nd->scaling[1] = nd->scaling[2] = 1.0f;
    MOTE__TRY(mote__vec(ld, mesh, "scaling", where, 3, 0, nd->scaling));
    /* the core reads {0,0,0} as "unset" (1): an explicit zero scale gets
     * one so small that the mesh, and its children, collapse to a point */
    if (nd->scaling[0] == 0.0f && nd->scaling[1] == 0.0f && nd->scaling[2] == 0.0f)
        nd->scaling[0] = nd->scaling[1] = nd->scaling[2] = 1e-30f;
    bool visible = true, enabled = true;
    MOTE__TRY(mote__flag(ld, mesh, "isVisible", where, &visible));
    MOTE__TRY(mote__flag(ld, mesh, "isEnabled", where, &enabled));
    nd->invisible = !visible;
    nd->disabled = !enabled;
    if (mote__get(mesh, "rotationQuaternion")) {
        MOTE__TRY(mote__vec(ld, mesh, "rotationQuaternion", where, 4, 0, nd->quat));
        nd->use_quat = true;
    }
    if (ld->right_handed) {
        mote__mirror_point(nd->position);
        mote__mirror_rotation(nd->rotation, nd->quat);
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
        return mote__array_len(m) == 16 ? cJSON_GetArrayItem(m, k) : NULL;
    char key[12];
    snprintf(key, sizeof key, "%d", k);
    return mote__member(m, key);
}

/* Whether obj[key] is absent or the identity matrix. */
static bool mote__absent_or_identity(const cJSON *obj, const char *key)
{
    const cJSON *m = mote__get(obj, key);
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
static R mote__read_matrix(mote__ld *ld, const cJSON *node, const char *where, mote__node *nd)
{
    const char *key = mote__get(node, "localMatrix") ? "localMatrix" : "pivotMatrix";
    const cJSON *m = mote__get(node, key);
    if (!m || mote__absent_or_identity(node, key))
        return MOTE_OK;
    char at[96];
    snprintf(at, sizeof at, "%s.%s", where, key);
    for (size_t k = 0; k < 16; k++) {
        const cJSON *e = mote__matrix_at(m, (int)k);
        if (cJSON_IsObject(m) && !e)
            return mote__fail(ld, MOTE_ERR_PARSE, "%s: expected an array of 16 numbers or an "
                              "object with keys \"0\" to \"15\", but \"%zu\" is missing", at, k);
        if (!e)
            return mote__fail(ld, MOTE_ERR_PARSE, "%s: expected an array of 16 numbers, found "
                              "%s", at, cJSON_IsArray(m) ? "another length" : mote__type_name(m));
        MOTE__TRY(mote__element_float(ld, e, at, k, &nd->matrix[k]));
    }
    const float *f = nd->matrix;
    if (f[3] != 0.0f || f[7] != 0.0f || f[11] != 0.0f || f[15] != 1.0f)
        return mote__fail(ld, MOTE_ERR_RANGE, "%s: not an affine transform (elements 3, 7, "
                          "11 and 15 must be 0, 0, 0 and 1)", at);
    if (ld->right_handed)
        mote__mirror_matrix(nd->matrix);
    nd->has_matrix = true;
    nd->matrix_name = key;
    nd->matrix_undone = key[0] == 'p';
    return MOTE_OK;
}

/* One entry of meshes[] or transformNodes[]. */
static R mote__node_read(mote__ld *ld, const cJSON *mesh, const char *where, mote__node *nd)
{
    MOTE__TRY(mote__node_common(ld, mesh, where, nd));
    MOTE__TRY(mote__read_matrix(ld, mesh, where, nd));
    MOTE__TRY(mote__id_ref(ld, mesh, "materialId", where, &nd->material_id));
    MOTE__TRY(mote__number_text(ld, mesh, "materialUniqueId", where, &nd->material_unique_id));
    MOTE__TRY(mote__flag(ld, mesh, "isUnIndexed", where, &nd->unindexed));
    /* Mesh.Parse: overrideMaterialSideOrientation (older files; null: none),
     * then sideOrientation (Babylon.js 7's), each overriding the
     * material's (the glTF loader sets it on every mesh it makes) */
    MOTE__TRY(mote__side(ld, mesh, "overrideMaterialSideOrientation", where, &nd->side));
    MOTE__TRY(mote__side(ld, mesh, "sideOrientation", where, &nd->side));
    const cJSON *verts, *pos;
    MOTE__TRY(mote__arr(ld, mesh, "vertices", where, &verts));
    MOTE__TRY(mote__arr(ld, mesh, "positions", where, &pos));
    const char *geometry_id;
    MOTE__TRY(mote__str(ld, mesh, "geometryId", where, &geometry_id));
    if (verts && pos)
        return mote__fail(ld, MOTE_ERR_PARSE, "%s: has both \"vertices\" and \"positions\"",
                          where);
    if (verts) {
        MOTE__TRY(mote__legacy_geometry(ld, mesh, verts, where, nd));
    } else if (pos) {
        MOTE__TRY(mote__current_geometry(ld, mesh, where, nd));
    } else if (geometry_id) {
        int k = mote__idmap_find(ld->geometry_map, geometry_id);
        if (k < 0)
            return mote__fail(ld, MOTE_ERR_RANGE,
                              "%s.geometryId: \"%s\" names no geometries.vertexData entry",
                              where, mote__quote(geometry_id).s);
        mote__geometry *g = &ld->geometries[k];
        /* parsed once for the meshes that draw it by its indices and once
         * for those that draw it unindexed (their arrays differ: indices,
         * smooth normals); the others share (no copies, however many
         * meshes name it either way) */
        int *owner = &g->owner[nd->unindexed];
        if (*owner >= 0) {
            mote__share_arrays(nd, &ld->nodes[*owner]);
        } else {
            char gat[64];
            snprintf(gat, sizeof gat, "geometries.vertexData[%d]", k);
            MOTE__TRY(mote__current_geometry(ld, g->json, gat, nd));
            *owner = (int)(nd - ld->nodes);
        }
    } else {
        /* an incremental (.incremental.babylon) or binary export keeps the
         * arrays in another file, which mote does not read: say so rather
         * than draw nothing without a word */
        if (mote__get(mesh, "delayLoadingFile") || mote__get(mesh, "_binaryInfo"))
            mote__warn(ld, "%s: its geometry is in a separate file (an incremental or binary "
                       "export), which mote does not read; it is drawn without it", where);
        const cJSON *ind;
        MOTE__TRY(mote__arr(ld, mesh, "indices", where, &ind));
        if (ind && ind->child) {
            char iat[96];
            snprintf(iat, sizeof iat, "%s.indices", where);
            uint32_t max_index;
            MOTE__TRY(mote__indices(ld, ind, iat, nd, &max_index));
            MOTE__TRY(mote__check_indices(ld, iat, nd));
        }
    }
    return mote__submeshes(ld, mesh, where, nd);
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
static R mote__thin_count(mote__ld *ld, const cJSON *mesh, const char *where, bool warn,
                          uint32_t *count, bool *undrawn)
{
    *count = 0;
    *undrawn = false;
    const cJSON *thin = mote__get(mesh, "thinInstances");
    if (!thin)
        return MOTE_OK;
    char at[64];
    snprintf(at, sizeof at, "%s.thinInstances", where);
    MOTE__TRY(mote__obj_at(ld, thin, at));
    uint32_t n = 0;
    MOTE__TRY(mote__uint_member(ld, thin, "instancesCount", at, INT32_MAX, &n));
    const cJSON *data = mote__get(thin, "matrixData");
    if (!data) {
        if (n > 0 && warn)
            mote__warn(ld, "%s: instancesCount %u without matrixData: Babylon.js draws the mesh "
                       "itself, and so does mote", at, (unsigned)n);
        return MOTE_OK;
    }
    /* JSON.stringify writes a Float32Array as an object with keys "0",
     * "1"...: it has no length, so new Float32Array makes no matrix of it */
    size_t len = 0;
    if (cJSON_IsArray(data))
        len = mote__array_len(data);
    else if (!cJSON_IsObject(data))
        return mote__fail(ld, MOTE_ERR_PARSE, "%s.matrixData: expected an array of numbers, "
                          "found %s", at, mote__type_name(data));
    else if (mote__member(data, "length"))
        return mote__fail(ld, MOTE_ERR_PARSE, "%s.matrixData: an object with a \"length\", "
                          "which mote does not read (expected an array of numbers)", at);
    size_t matrices = len / 16;
    if (n == 0) {
        if (matrices > 0 && warn)
            mote__warn(ld, "%s: no instancesCount (or 0): Babylon.js draws the mesh itself, "
                       "not the %zu matri%s of matrixData, and so does mote", at, matrices,
                       matrices == 1 ? "x" : "ces");
        return MOTE_OK;
    }
    if (n > matrices) {
        *undrawn = true;
        if (warn && cJSON_IsObject(data))
            mote__warn(ld, "%s.matrixData: an object, of which Babylon.js makes no matrix (new "
                       "Float32Array of it is empty), so its draw of %u instance%s reads past "
                       "its buffer, which WebGL refuses: the mesh is not drawn", at, (unsigned)n,
                       n == 1 ? "" : "s");
        else if (warn)
            mote__warn(ld, "%s: instancesCount %u, but matrixData holds %zu matri%s: Babylon.js's "
                       "draw reads past it, which WebGL refuses: the mesh is not drawn", at,
                       (unsigned)n, matrices, matrices == 1 ? "x" : "ces");
        return MOTE_OK;
    }
    if (len % 16 && warn)
        mote__warn(ld, "%s.matrixData: %zu numbers, not a multiple of 16: the last %zu are not "
                   "read", at, len, len % 16);
    /* thinInstanceSetBuffer of other kinds: per-instance colours (which
     * multiply the material's) and custom attributes */
    if (mote__get(thin, "userThinInstance") && warn)
        mote__warn(ld, "%s.userThinInstance: its per-instance buffers (colours...) are not read: "
                   "each thin instance is drawn in the mesh's material", at);
    *count = n;
    return MOTE_OK;
}

/* The thin instances of mesh i (nodes[host]): count nodes from `first`,
 * each a child of the mesh with its matrix of matrixData as a
 * pre-transform (the shaders' world * instance matrix: the matrix is in
 * the mesh's own space), drawn with the mesh's arrays, material and
 * sub-meshes (shared), and shown when the mesh is. The matrix is folded
 * as a localMatrix is (mote__fold_matrix), so it must be affine. */
static R mote__thin_instances(mote__ld *ld, const cJSON *mesh, int i, int host, int first,
                              uint32_t count)
{
    const mote__node *h = &ld->nodes[host];
    const cJSON *data = mote__get(mote__get(mesh, "thinInstances"), "matrixData");
    char at[80];
    snprintf(at, sizeof at, "%s.thinInstances.matrixData", h->where);
    const cJSON *e = data->child;   /* an array of at least 16 count numbers */
    for (uint32_t k = 0; k < count; k++) {
        mote__node *t = &ld->nodes[first + (int)k];
        snprintf(t->where, sizeof t->where, "meshes[%d].thinInstances[%u]", i, (unsigned)k);
        bool identity = true;
        for (int j = 0; j < 16; j++, e = e->next) {
            MOTE__TRY(mote__element_float(ld, e, at, (size_t)k * 16 + (size_t)j, &t->matrix[j]));
            identity = identity && t->matrix[j] == (j % 5 == 0 ? 1.0f : 0.0f);
        }
        const float *f = t->matrix;
        if (f[3] != 0.0f || f[7] != 0.0f || f[11] != 0.0f || f[15] != 1.0f)
            return mote__fail(ld, MOTE_ERR_RANGE, "%s: matrix %u (numbers %zu to %zu) is not an "
                              "affine transform (its numbers 3, 7, 11 and 15 must be 0, 0, 0 "
                              "and 1)", at, (unsigned)k, (size_t)k * 16, (size_t)k * 16 + 15);
        double det = (double)f[0] * ((double)f[5] * f[10] - (double)f[6] * f[9]) -
                     (double)f[4] * ((double)f[1] * f[10] - (double)f[2] * f[9]) +
                     (double)f[8] * ((double)f[1] * f[6] - (double)f[2] * f[5]);
        t->thin_mirrored = det < 0.0;
        if (ld->right_handed)
            mote__mirror_matrix(t->matrix);
        t->has_matrix = !identity;
        t->matrix_name = "thin instance matrix";
        t->is_thin = true;
        t->host = host;
        t->parent_instance = -1;
        t->scaling[0] = t->scaling[1] = t->scaling[2] = 1.0f;
        t->material_id = h->material_id;
        t->material_unique_id = h->material_unique_id;
        t->legacy = h->legacy;
        t->side = h->side;
        t->invisible = h->invisible;  /* drawn when the mesh is (its parent's flags do the rest) */
        mote__share_arrays(t, (mote__node *)h);
        t->subs = h->subs;
        t->sub_count = h->sub_count;
    }
    return MOTE_OK;
}

static R mote__nodes(mote__ld *ld)
{
    const cJSON *meshes, *tnodes, *geos = mote__get(ld->root, "geometries");
    MOTE__TRY(mote__arr(ld, ld->root, "meshes", "", &meshes));
    MOTE__TRY(mote__arr(ld, ld->root, "transformNodes", "", &tnodes));
    /* an array (Cinema 4D's exporter writes "geometries": []) has no
     * vertexData member, so Babylon.js finds no geometries in it */
    if (cJSON_IsArray(geos)) {
        if (geos->child)
            mote__warn(ld, "geometries: an array, not an object: Babylon.js reads no "
                       "geometries from it, nor does mote");
        geos = NULL;
    }
    if (geos) {
        const cJSON *vertex_data;
        MOTE__TRY(mote__obj_at(ld, geos, "geometries"));
        MOTE__TRY(mote__arr(ld, geos, "vertexData", "geometries", &vertex_data));
        size_t ng = mote__array_len(vertex_data);
        ld->geometries = mote__store_alloc(&ld->tmp, ng + 1, sizeof *ld->geometries);
        if (!ld->geometries)
            return mote__oom(ld, "geometries");
        for (const cJSON *g = vertex_data ? vertex_data->child : NULL; g; g = g->next) {
            const cJSON *gid = mote__member(g, "id");
            mote__geometry *e = &ld->geometries[ld->geometry_count++];
            e->id = cJSON_IsString(gid) ? gid->valuestring : NULL;
            e->json = g;
            e->owner[0] = e->owner[1] = -1;
        }
        int dup;
        ld->geometry_map = mote__idmap_build(ld, &ld->geometries[0].id, sizeof *ld->geometries,
                                             ld->geometry_count, &dup);
        if (!ld->geometry_map)
            return mote__oom(ld, "geometries");
    }
    /* nh: nodes that may need a helper node (mote__fold_matrix); nl: the
     * levels of detail that instances of their master may draw (mote__lods) */
    size_t nm = mote__array_len(meshes), nt = mote__array_len(tnodes), ni = 0, nth = 0, nh = 0,
           nl = 0;
    int i = 0;
    for (const cJSON *m = meshes ? meshes->child : NULL; m; m = m->next, i++) {
        char at[32];
        snprintf(at, sizeof at, "meshes[%d]", i);
        const cJSON *inst = NULL, *lod_ids = NULL;
        uint32_t thin = 0;
        bool unused;
        if (cJSON_IsObject(m)) {
            MOTE__TRY(mote__arr(ld, m, "instances", at, &inst));
            MOTE__TRY(mote__arr(ld, m, "lodMeshIds", at, &lod_ids));
            MOTE__TRY(mote__thin_count(ld, m, at, false, &thin, &unused));
        }
        size_t n = mote__array_len(inst);
        ni += n;
        nth += thin;
        if (mote__may_have_matrix(m))
            nh += 1 + n;
        if (thin)   /* a thin instance's matrix may be sheared */
            nh += thin;
        nl += n * mote__array_len(lod_ids);
        if (ni + nth > ld->lim.max_meshes)
            break;   /* no sum past the limit (nor its overflow) */
    }
    for (const cJSON *t = tnodes ? tnodes->child : NULL; t; t = t->next)
        nh += mote__may_have_matrix(t);
    if (nm + nt + ni + nth > ld->lim.max_meshes)
        return mote__fail(ld, MOTE_ERR_LIMIT, "meshes: %zu meshes, more than the limit of %u "
                          "(transform nodes, instances and thin instances count)",
                          nm + nt + ni + nth, (unsigned)ld->lim.max_meshes);
    /* cameras and lights may join the tree (mote__xnode), and helpers of
     * nodes with a matrix; each becomes a mesh, so no more than the mesh
     * limit leaves room for */
    const cJSON *cams, *lights;
    MOTE__TRY(mote__arr(ld, ld->root, "cameras", "", &cams));
    MOTE__TRY(mote__arr(ld, ld->root, "lights", "", &lights));
    size_t nx = mote__array_len(cams) + mote__array_len(lights) + nh + nl;
    const size_t base = nm + nt + ni + nth;
    if (nx > ld->lim.max_meshes - base)
        nx = ld->lim.max_meshes - base;
    ld->nodes = mote__store_alloc(&ld->tmp, base + nx, sizeof *ld->nodes);
    if (!ld->nodes)
        return mote__oom(ld, "meshes");
    ld->node_count = (int)base;
    ld->node_cap = (int)(base + nx);
    ld->file_meshes = (int)nm;
    ld->instances_first = (int)(nm + nt);
    ld->instances_end = (int)(nm + nt + ni);
    /* meshes, then transform nodes, then instances: each the source mesh's
     * geometry, material and sub-meshes with a transform and parent of its
     * own (Babylon.js's Mesh.Parse and createInstance), then thin instances */
    int next_instance = (int)(nm + nt), next_thin = (int)(nm + nt + ni);
    i = 0;
    for (const cJSON *m = meshes ? meshes->child : NULL; m; m = m->next, i++) {
        mote__node *nd = &ld->nodes[i];
        snprintf(nd->where, sizeof nd->where, "meshes[%d]", i);
        MOTE__TRY(mote__node_read(ld, m, nd->where, nd));
        /* levels of detail, resolved once every mesh is known (mote__lods);
         * arrays: checked above */
        nd->lod_ids = mote__get(m, "lodMeshIds");
        MOTE__TRY(mote__arr(ld, m, "lodDistances", nd->where, &nd->lod_distances));
        if (nd->lod_ids && nd->lod_ids->child && !nd->lod_distances)
            mote__warn(ld, "%s: lodMeshIds without lodDistances (Babylon.js's loader reads no "
                       "lodCoverages): no levels of detail are made, each mesh is drawn by "
                       "itself, as in Babylon.js", nd->where);
        uint32_t thin;
        MOTE__TRY(mote__thin_count(ld, m, nd->where, true, &thin, &nd->undrawn));
        if (thin) {
            nd->undrawn = true;
            nd->first_thin = next_thin;
            nd->thin_count = (int)thin;
            MOTE__TRY(mote__thin_instances(ld, m, i, i, next_thin, thin));
            next_thin += (int)thin;
        }
        const cJSON *inst = mote__get(m, "instances");   /* an array: checked above */
        nd->first_instance = next_instance;
        nd->instance_count = (int)mote__array_len(inst);
        if (nd->undrawn && nd->instance_count)
            mote__warn(ld, "%s: its instances are not drawn: Babylon.js draws a mesh's thin "
                       "instances in place of it and its instances", nd->where);
        int k = 0;
        for (const cJSON *e = inst ? inst->child : NULL; e; e = e->next, k++) {
            mote__node *in = &ld->nodes[next_instance++];
            snprintf(in->where, sizeof in->where, "meshes[%d].instances[%d]", i, k);
            MOTE__TRY(mote__node_common(ld, e, in->where, in));
            in->material_id = nd->material_id;
            in->material_unique_id = nd->material_unique_id;
            in->legacy = nd->legacy;
            in->side = nd->side;   /* drawn through its source mesh */
            in->undrawn = nd->undrawn;
            /* InstancedMesh's constructor: setPivotMatrix(source's matrix),
             * with the default postMultiplyPivotMatrix, so an instance
             * undoes even a localMatrix (a pre-transform of its source) */
            memcpy(in->matrix, nd->matrix, sizeof in->matrix);
            in->has_matrix = nd->has_matrix;
            in->matrix_name = nd->matrix_undone ? "source's pivotMatrix" : "source's localMatrix";
            in->matrix_undone = true;
            mote__share_arrays(in, nd);
            in->subs = nd->subs;
            in->sub_count = nd->sub_count;
        }
    }
    int t = 0;
    for (const cJSON *m = tnodes ? tnodes->child : NULL; m; m = m->next, i++, t++) {
        mote__node *nd = &ld->nodes[i];
        snprintf(nd->where, sizeof nd->where, "transformNodes[%d]", t);
        MOTE__TRY(mote__node_read(ld, m, nd->where, nd));
        if (nd->nv || nd->ni || nd->sub_count)
            return mote__fail(ld, MOTE_ERR_PARSE, "%s: a transform node has no geometry",
                              nd->where);
    }
    return MOTE_OK;
}

/* ---- cameras and lights in the node tree ------------------------------- */

/* lights[k].type: 0 point, 1 directional, 2 spot, 3 hemispheric. */
static R mote__light_type(mote__ld *ld, const cJSON *l, const char *at, uint32_t *t)
{
    char at2[64];
    snprintf(at2, sizeof at2, "%s.type", at);
    const cJSON *type = mote__get(l, "type");
    if (!type)
        return mote__fail(ld, MOTE_ERR_PARSE, "%s: missing", at2);
    return mote__to_uint(ld, type, at2, 0, 3, t);
}

/* What a camera or light is found by: its id, or its name when it has no
 * id (Babylon.js gives a node without an id its name); NULL: neither. */
static const char *mote__entry_key(const cJSON *e)
{
    const cJSON *id = mote__member(e, "id");
    if (!cJSON_IsString(id))
        id = mote__member(e, "name");
    return cJSON_IsString(id) ? id->valuestring : NULL;
}

typedef struct mote__xkey {
    const char *id, *unique;
} mote__xkey;

/* ld->xlists: maps, so that a file with many parents or lights is not
 * searched once per reference. */
static R mote__xlists(mote__ld *ld)
{
    static const char *const names[2] = {"cameras", "lights"};
    for (int l = 0; l < 2; l++) {
        mote__xlist *x = &ld->xlists[l];
        const cJSON *arr;
        MOTE__TRY(mote__arr(ld, ld->root, names[l], "", &arr));
        size_t n = mote__array_len(arr);
        x->items = mote__store_alloc(&ld->tmp, n, sizeof *x->items);
        x->node = mote__store_alloc(&ld->tmp, n, sizeof *x->node);
        mote__xkey *keys = mote__store_alloc(&ld->tmp, n, sizeof *keys);
        if (!x->items || !x->node || !keys)
            return mote__oom(ld, names[l]);
        int k = 0;
        for (const cJSON *e = arr ? arr->child : NULL; e; e = e->next, k++) {
            x->items[k] = e;
            x->node[k] = -1;
            mote__xkey *key = &keys[k];
            if (!cJSON_IsObject(e))
                continue;
            key->id = mote__entry_key(e);
            const cJSON *u = mote__get(e, "uniqueId");
            if (cJSON_IsNumber(u) && isfinite(u->valuedouble))
                MOTE__TRY(mote__double_text(ld, u->valuedouble, names[l], &key->unique));
        }
        x->count = k;
        int dup;
        x->ids = mote__idmap_build(ld, &keys[0].id, sizeof *keys, k, &dup);
        x->uniques = mote__idmap_build(ld, &keys[0].unique, sizeof *keys, k, &dup);
        if (!x->ids || !x->uniques)
            return mote__oom(ld, names[l]);
    }
    return MOTE_OK;
}

/* A camera's turn: its rotation, or its rotationQuaternion (*use_quat)
 * when it has one, mirrored in a right-handed scene. Without a rotation,
 * TargetCamera's default: none, but in a right-handed scene a half turn
 * about y, which keeps such a camera looking down +z (its forward is -z
 * there) as Babylon.js's cameras did before they looked down -z. */
static R mote__camera_turn(mote__ld *ld, const cJSON *cam, const char *at, float rotation[3],
                           float quat[4], bool *use_quat)
{
    memset(rotation, 0, 3 * sizeof *rotation);
    if (ld->right_handed && !mote__get(cam, "rotation"))
        rotation[1] = 3.14159265f;
    MOTE__TRY(mote__vec(ld, cam, "rotation", at, 3, 0, rotation));
    quat[0] = quat[1] = quat[2] = 0.0f;
    quat[3] = 1.0f;
    MOTE__TRY(mote__vec(ld, cam, "rotationQuaternion", at, 4, 0, quat));
    *use_quat = mote__get(cam, "rotationQuaternion") != NULL;
    if (ld->right_handed)
        mote__mirror_rotation(rotation, quat);
    return MOTE_OK;
}

/* TargetCamera.setTarget first moves a camera level with its target in z
 * by Epsilon (0.001) along z, so that one at its target looks down -z and
 * one right above or below it has a way round, where a look-at has none;
 * an ArcRotateCamera (and its stereo kinds) places itself otherwise. On
 * the file's position and target, mirrored in a right-handed scene (the
 * file's +z is -z here). */
static void mote__level_target_nudge(const mote__ld *ld, const cJSON *cam, float position[3],
                                     const float target[3])
{
    const cJSON *type = mote__get(cam, "type");
    if (cJSON_IsString(type) && strstr(type->valuestring, "ArcRotateCamera"))
        return;
    if (position[2] == target[2])
        position[2] += ld->right_handed ? -1e-3f : 1e-3f;
}

/* The node standing for cameras[k] (list 0) or lights[k] (list 1), at
 * `where`, made on first use: in Babylon.js cameras and lights are nodes, so they may be parents
 * and have parents. It goes at the end of ld->nodes with no id in the node
 * maps (a mesh or transform node of the same id is found first, as in
 * scene.getLastEntryById), no geometry, and hidden; its transform is the
 * world matrix Babylon.js gives the camera or light. */
static R mote__xnode(mote__ld *ld, int list, int k, const char *where, int *out)
{
    mote__xlist *x = &ld->xlists[list];
    const cJSON *json = x->items[k];
    bool is_light = list == 1;
    *out = x->node[k];
    if (*out >= 0)
        return MOTE_OK;
    if (ld->node_count >= ld->node_cap)
        return mote__fail(ld, MOTE_ERR_LIMIT, "%s: more than the limit of %u meshes (cameras "
                          "and lights in the parent tree count)", where,
                          (unsigned)ld->lim.max_meshes);
    mote__node *nd = &ld->nodes[ld->node_count];
    snprintf(nd->where, sizeof nd->where, "%s", where);
    if (is_light) {
        uint32_t t;
        MOTE__TRY(mote__light_type(ld, json, where, &t));
        if (t == 0 || t == 2)     /* legacy files keep the position in `data` */
            MOTE__TRY(mote__vec(ld, json, "data", where, 3, 0, nd->position));
        MOTE__TRY(mote__node_common(ld, json, where, nd));
        /* a light's world matrix is its position only (ShadowLight); a
         * hemispheric light's is the identity, parent or not */
        memset(nd->rotation, 0, sizeof nd->rotation);
        nd->use_quat = false;
        if (t == 3) {
            memset(nd->position, 0, sizeof nd->position);
            nd->parent_id = NULL;
        }
    } else {
        MOTE__TRY(mote__node_common(ld, json, where, nd));
        MOTE__TRY(mote__camera_turn(ld, json, where, nd->rotation, nd->quat, &nd->use_quat));
        float target[3];
        if (mote__get(json, "target")) {
            /* setTarget: yaw and pitch that turn +z toward the target, no roll */
            MOTE__TRY(mote__vec(ld, json, "target", where, 3, 0, target));
            if (ld->right_handed)
                mote__mirror_point(target);
            mote__level_target_nudge(ld, json, nd->position, target);
            float d[3] = {target[0] - nd->position[0], target[1] - nd->position[1],
                          target[2] - nd->position[2]};
            nd->rotation[0] = atan2f(-d[1], sqrtf(d[0] * d[0] + d[2] * d[2]));
            nd->rotation[1] = atan2f(d[0], d[2]);
            nd->rotation[2] = 0.0f;
            nd->use_quat = false;
        }
    }
    /* a camera's world matrix is its inverted view, a light's a translation:
     * neither scales */
    nd->scaling[0] = nd->scaling[1] = nd->scaling[2] = 1.0f;
    nd->id = nd->unique_id = NULL;
    nd->invisible = true;
    *out = x->node[k] = ld->node_count++;
    return MOTE_OK;
}

/* A parentId that names no mesh or transform node may name a camera, then
 * a light (scene.getLastEntryById's order, the last of equal ids winning).
 * Leaves nd->parent -1 when nothing matches. */
static R mote__camera_light_parent(mote__ld *ld, mote__node *nd)
{
    for (int l = 0; l < 2; l++) {
        const mote__xlist *x = &ld->xlists[l];
        int k = mote__idmap_find_last(nd->parent_by_unique ? x->uniques : x->ids, nd->parent_id);
        if (k >= 0) {
            char where[48];
            snprintf(where, sizeof where, "%s[%d]", l ? "lights" : "cameras", k);
            return mote__xnode(ld, l, k, where, &nd->parent);
        }
    }
    return MOTE_OK;
}

/* The active camera: the first whose id (or name) is activeCameraID (older
 * files: activeCamera), else the first, with a warning. NULL: no cameras. */
static R mote__active_camera(mote__ld *ld, bool warn, const cJSON **out, int *index)
{
    const cJSON *cams;
    *out = NULL;
    *index = 0;
    MOTE__TRY(mote__arr(ld, ld->root, "cameras", "", &cams));
    if (!cams || !cams->child)
        return MOTE_OK;
    const char *active;
    MOTE__TRY(mote__str(ld, ld->root, "activeCameraID", "scene", &active));
    if (!active)
        MOTE__TRY(mote__str(ld, ld->root, "activeCamera", "scene", &active));
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
        mote__warn(ld, "activeCamera \"%s\" names no camera; the first one is used",
                   mote__quote(active).s);
    return MOTE_OK;
}

/* Nodes for the active camera and the lights that have a parent, made
 * before the parents are resolved so that their chains are checked (cycles,
 * depth) with the rest. */
static R mote__camera_light_nodes(mote__ld *ld)
{
    const cJSON *cam;
    int index, unused;
    MOTE__TRY(mote__xlists(ld));
    MOTE__TRY(mote__active_camera(ld, false, &cam, &index));
    if (cam && cJSON_IsObject(cam) && mote__names_parent(cam)) {
        char at[48];
        snprintf(at, sizeof at, "cameras[%d]", index);
        MOTE__TRY(mote__xnode(ld, 0, index, at, &unused));
    }
    const mote__xlist *lights = &ld->xlists[1];
    for (int i = 0; i < lights->count; i++) {
        if (!cJSON_IsObject(lights->items[i]) || !mote__names_parent(lights->items[i]))
            continue;
        char at[48];
        snprintf(at, sizeof at, "lights[%d]", i);
        MOTE__TRY(mote__xnode(ld, 1, i, at, &unused));
    }
    return MOTE_OK;
}

/* ---- pivot and local matrices ----------------------------------------- */

/* translate(position) * rotate * scale(scaling) as the core makes a mesh's
 * (mote_mesh_world_matrix, no parent); NULL position: none, NULL scaling:
 * 1. */
static void mote__transform_matrix(const float position[3], const float rotation[3],
                                   const float quat[4], bool use_quat, const float scaling[3],
                                   float w[16])
{
    mote_mesh m;
    memset(&m, 0, sizeof m);
    if (position)
        memcpy(m.position, position, sizeof m.position);
    memcpy(m.rotation, rotation, sizeof m.rotation);
    memcpy(m.rotation_quaternion, quat, sizeof m.rotation_quaternion);
    m.use_quaternion = use_quat;
    if (scaling)
        memcpy(m.scaling, scaling, sizeof m.scaling);
    mote_mesh_world_matrix(&m, w);
}

/* out = a b, column-major 4x4 (out may be a or b). */
static void mote__mul4(const double a[16], const double b[16], double out[16])
{
    double r[16];
    for (int c = 0; c < 4; c++)
        for (int row = 0; row < 4; row++) {
            double sum = 0.0;
            for (int k = 0; k < 4; k++)
                sum += a[k * 4 + row] * b[c * 4 + k];
            r[c * 4 + row] = sum;
        }
    memcpy(out, r, sizeof r);
}

/* The inverse of the affine m; false when it has none. The 3x3 part's
 * inverse is its adjugate over the determinant (cofactors with indices
 * taken cyclically carry their own signs), the translation -inverse t. */
static bool mote__affine_inverse(const double m[16], double out[16])
{
#define M(r, c) m[(c) * 4 + (r)]
    double cof[3][3];
    for (int r = 0; r < 3; r++)
        for (int c = 0; c < 3; c++) {
            int r1 = (r + 1) % 3, r2 = (r + 2) % 3, c1 = (c + 1) % 3, c2 = (c + 2) % 3;
            cof[r][c] = M(r1, c1) * M(r2, c2) - M(r1, c2) * M(r2, c1);
        }
    double det = M(0, 0) * cof[0][0] + M(0, 1) * cof[0][1] + M(0, 2) * cof[0][2];
    if (!(fabs(det) > 0.0) || !isfinite(1.0 / det))
        return false;
    memset(out, 0, 16 * sizeof *out);
    for (int r = 0; r < 3; r++) {
        for (int c = 0; c < 3; c++)
            out[c * 4 + r] = cof[c][r] / det;
        out[12 + r] = -(out[r] * M(0, 3) + out[4 + r] * M(1, 3) + out[8 + r] * M(2, 3));
    }
    out[15] = 1.0;
#undef M
    return true;
}

/* Eigenvalues w and eigenvectors (the columns of v, a rotation) of the
 * symmetric a, by cyclic Jacobi rotations (each zeroes one off-diagonal
 * element; a few sweeps leave them at rounding). a is consumed. */
static void mote__symmetric_eigen3(double a[3][3], double w[3], double v[3][3])
{
    static const int pairs[3][2] = {{0, 1}, {0, 2}, {1, 2}};
    memset(v, 0, 9 * sizeof **v);
    v[0][0] = v[1][1] = v[2][2] = 1.0;
    for (int sweep = 0; sweep < 50; sweep++) {
        double off = a[0][1] * a[0][1] + a[0][2] * a[0][2] + a[1][2] * a[1][2];
        double diag = a[0][0] * a[0][0] + a[1][1] * a[1][1] + a[2][2] * a[2][2];
        if (!(off > 1e-32 * diag))
            break;
        for (int k = 0; k < 3; k++) {
            int p = pairs[k][0], q = pairs[k][1];
            if (a[p][q] == 0.0)
                continue;
            /* the rotation J in the (p, q) plane with (J^T a J)[p][q] = 0 */
            double theta = (a[q][q] - a[p][p]) / (2.0 * a[p][q]);
            double t = (theta >= 0.0 ? 1.0 : -1.0) / (fabs(theta) + sqrt(theta * theta + 1.0));
            double c = 1.0 / sqrt(t * t + 1.0), s = t * c;
            for (int i = 0; i < 3; i++) {   /* a J, and v J */
                double aip = a[i][p], aiq = a[i][q], vip = v[i][p], viq = v[i][q];
                a[i][p] = c * aip - s * aiq;
                a[i][q] = s * aip + c * aiq;
                v[i][p] = c * vip - s * viq;
                v[i][q] = s * vip + c * viq;
            }
            for (int j = 0; j < 3; j++) {   /* J^T (a J) */
                double apj = a[p][j], aqj = a[q][j];
                a[p][j] = c * apj - s * aqj;
                a[q][j] = s * apj + c * aqj;
            }
        }
    }
    for (int i = 0; i < 3; i++)
        w[i] = a[i][i];
}

static void mote__cross3d(const double a[3], const double b[3], double out[3])
{
    out[0] = a[1] * b[2] - a[2] * b[1];
    out[1] = a[2] * b[0] - a[0] * b[2];
    out[2] = a[0] * b[1] - a[1] * b[0];
}

/* a = U diag(sigma) V^T, U and V rotations, given as the arrays
 * mote__rotation_quat takes for U and for V^T: ut, whose rows are U's
 * columns, and v, whose rows are V^T's. V holds the eigenvectors of a^T a,
 * sigma the roots of its eigenvalues, U's columns a V / sigma; a negative
 * sigma where a mirrors. A sigma of 0 (a flattened axis) gets a U column
 * that completes the rotation. */
static void mote__svd3(double a[3][3], double ut[3][3], double sigma[3], double v[3][3])
{
    double ata[3][3], most = 0.0;
    for (int i = 0; i < 3; i++)
        for (int j = 0; j < 3; j++)
            ata[i][j] = a[0][i] * a[0][j] + a[1][i] * a[1][j] + a[2][i] * a[2][j];
    /* columns of a orthogonal but for float rounding (the cosine of their
     * angle within 1e-6) are taken as orthogonal: V stays the identity,
     * where rounding would turn it as it pleases between equal sigmas */
    for (int i = 0; i < 3; i++)
        for (int j = i + 1; j < 3; j++)
            if (fabs(ata[i][j]) <= 1e-6 * sqrt(ata[i][i] * ata[j][j]))
                ata[i][j] = ata[j][i] = 0.0;
    mote__symmetric_eigen3(ata, sigma, v);
    for (int j = 0; j < 3; j++) {
        sigma[j] = sigma[j] > 0.0 ? sqrt(sigma[j]) : 0.0;
        most = sigma[j] > most ? sigma[j] : most;
    }
    int flat = 0, kept = 0;
    for (int j = 0; j < 3; j++) {
        if (!(sigma[j] > 1e-12 * most)) {
            flat++;
            memset(ut[j], 0, sizeof ut[j]);
            continue;
        }
        kept = j;
        for (int i = 0; i < 3; i++)
            ut[j][i] = (a[i][0] * v[0][j] + a[i][1] * v[1][j] + a[i][2] * v[2][j]) / sigma[j];
    }
    if (flat == 3) {
        memset(ut, 0, 9 * sizeof **ut);
        ut[0][0] = ut[1][1] = ut[2][2] = 1.0;
    } else if (flat == 2) {
        /* the one kept column, then any unit vector across it */
        int j1 = (kept + 1) % 3, j2 = (kept + 2) % 3, axis = 0;
        for (int i = 1; i < 3; i++)
            if (fabs(ut[kept][i]) < fabs(ut[kept][axis]))
                axis = i;
        double e[3] = {0.0, 0.0, 0.0};
        e[axis] = 1.0;
        mote__cross3d(ut[kept], e, ut[j1]);
        double len = sqrt(ut[j1][0] * ut[j1][0] + ut[j1][1] * ut[j1][1] + ut[j1][2] * ut[j1][2]);
        for (int i = 0; i < 3; i++)
            ut[j1][i] /= len;
        mote__cross3d(ut[kept], ut[j1], ut[j2]);
    } else if (flat == 1) {
        for (int j = 0; j < 3; j++)
            if (!(sigma[j] > 1e-12 * most))
                mote__cross3d(ut[(j + 1) % 3], ut[(j + 2) % 3], ut[j]);
    }
    double c[3];
    mote__cross3d(ut[1], ut[2], c);
    if (ut[0][0] * c[0] + ut[0][1] * c[1] + ut[0][2] * c[2] < 0.0) {
        /* a mirrors: the core's transform takes it as a negative scale */
        sigma[0] = -sigma[0];
        for (int i = 0; i < 3; i++)
            ut[0][i] = -ut[0][i];
    }
}

/* The quaternion (x, y, z, w) of the rotation whose columns are the rows
 * of rt (Shepperd's method: divides by the largest of 4w^2, 4x^2, 4y^2,
 * 4z^2). */
static void mote__rotation_quat(double rt[3][3], float q[4])
{
#define R(i, j) rt[j][i]
    double tr = R(0, 0) + R(1, 1) + R(2, 2), x, y, z, w, s;
    if (tr > 0.0) {
        s = 2.0 * sqrt(tr + 1.0);
        w = 0.25 * s;
        x = (R(2, 1) - R(1, 2)) / s;
        y = (R(0, 2) - R(2, 0)) / s;
        z = (R(1, 0) - R(0, 1)) / s;
    } else if (R(0, 0) > R(1, 1) && R(0, 0) > R(2, 2)) {
        s = 2.0 * sqrt(1.0 + R(0, 0) - R(1, 1) - R(2, 2));
        w = (R(2, 1) - R(1, 2)) / s;
        x = 0.25 * s;
        y = (R(0, 1) + R(1, 0)) / s;
        z = (R(0, 2) + R(2, 0)) / s;
    } else if (R(1, 1) > R(2, 2)) {
        s = 2.0 * sqrt(1.0 + R(1, 1) - R(0, 0) - R(2, 2));
        w = (R(0, 2) - R(2, 0)) / s;
        x = (R(0, 1) + R(1, 0)) / s;
        y = 0.25 * s;
        z = (R(1, 2) + R(2, 1)) / s;
    } else {
        s = 2.0 * sqrt(1.0 + R(2, 2) - R(0, 0) - R(1, 1));
        w = (R(1, 0) - R(0, 1)) / s;
        x = (R(0, 2) + R(2, 0)) / s;
        y = (R(1, 2) + R(2, 1)) / s;
        z = 0.25 * s;
    }
#undef R
    q[0] = (float)x;
    q[1] = (float)y;
    q[2] = (float)z;
    q[3] = (float)w;
}

/* A node's transform set to a turn, scale and position (the scale of a
 * flattened node never all 0, which the core reads as 1). */
static void mote__set_transform(mote__node *nd, const double position[3], double rt[3][3],
                                const double scaling[3])
{
    for (int k = 0; k < 3; k++) {
        nd->position[k] = (float)position[k];
        nd->scaling[k] = (float)scaling[k];
        nd->rotation[k] = 0.0f;
    }
    if (nd->scaling[0] == 0.0f && nd->scaling[1] == 0.0f && nd->scaling[2] == 0.0f)
        nd->scaling[0] = nd->scaling[1] = nd->scaling[2] = 1e-30f;
    mote__rotation_quat(rt, nd->quat);
    nd->use_quat = true;
}

/* nodes[index]'s localMatrix or pivotMatrix P folded into its transform.
 * Its local matrix, as Babylon.js's TransformNode.computeWorldMatrix
 * composes it (in mote's column vectors; Babylon.js's row-vector product
 * P S R [P^-1], then the position added), is L = T R S P for a
 * pre-transform and L = T P^-1 R S P for a pivot. The core's transforms
 * are T R S only: L = T U S' V^T (mote__svd3) is one when V^T is the
 * identity (L has no shear: the common case, a pivot that only moves, or
 * turns with an even scale); else a hidden helper node takes T U S', in
 * the node's place under its parent, and the node keeps only the turn V^T.
 * Either way its vertices and children land where Babylon.js puts them
 * (normals too: the core's normal matrix is the chain's inverse transpose),
 * and no vertex array, perhaps shared, is touched. */
static R mote__fold_matrix(mote__ld *ld, int index)
{
    mote__node *nd = &ld->nodes[index];
    float f[16];
    double l[16], p[16], undo[16];
    mote__transform_matrix(nd->position, nd->rotation, nd->quat, nd->use_quat, nd->scaling, f);
    for (int k = 0; k < 16; k++) {
        l[k] = f[k];
        p[k] = nd->matrix[k];
    }
    if (nd->matrix_undone) {
        /* T P^-1 (R S) P: the position taken out, put back last */
        if (!mote__affine_inverse(p, undo))
            return mote__fail(ld, MOTE_ERR_RANGE, "%s: its %s is not invertible (as a pivot "
                              "it is undone by its inverse)", nd->where, nd->matrix_name);
        double position[3] = {l[12], l[13], l[14]};
        l[12] = l[13] = l[14] = 0.0;
        mote__mul4(undo, l, l);
        for (int k = 0; k < 3; k++)
            l[12 + k] += position[k];
    }
    mote__mul4(l, p, l);
    double a[3][3], ut[3][3], sigma[3], v[3][3];
    for (int r = 0; r < 3; r++)
        for (int c = 0; c < 3; c++)
            a[r][c] = l[c * 4 + r];
    mote__svd3(a, ut, sigma, v);
    bool sheared = false;
    for (int r = 0; r < 3; r++)
        for (int c = 0; c < 3; c++)
            sheared = sheared || fabs(v[r][c] - (r == c ? 1.0 : 0.0)) > 1e-6;
    if (!sheared) {
        mote__set_transform(nd, &l[12], ut, sigma);
        return MOTE_OK;
    }
    if (ld->node_count >= ld->node_cap)
        return mote__fail(ld, MOTE_ERR_LIMIT, "%s: more than the limit of %u meshes (nodes "
                          "with a sheared pivot or local matrix take two)", nd->where,
                          (unsigned)ld->lim.max_meshes);
    int h = ld->node_count++;
    mote__node *helper = &ld->nodes[h];
    memcpy(helper->where, nd->where, sizeof helper->where);
    helper->parent = nd->parent;
    helper->parent_id = nd->parent_id;   /* for messages: it stands in the node's place */
    helper->parent_instance = -1;
    helper->invisible = true;
    helper->is_helper = true;
    mote__set_transform(helper, &l[12], ut, sigma);
    static const double origin[3] = {0.0, 0.0, 0.0}, unit[3] = {1.0, 1.0, 1.0};
    mote__set_transform(nd, origin, v, unit);
    nd->parent = h;
    return MOTE_OK;
}

/* ---- levels of detail -------------------------------------------------- */

/* A level of detail takes its master's place: AbstractMesh.getWorldMatrix
 * returns the master's world matrix while the mesh has one (addLODLevel
 * sets _masterMesh), whatever the level's own transform, pivot and
 * parent; as the master's child with the identity transform it has that
 * matrix, and its children follow it as they follow getWorldMatrix. */
static void mote__lod_take_place(mote__node *nd, int master)
{
    memset(nd->position, 0, sizeof nd->position);
    memset(nd->rotation, 0, sizeof nd->rotation);
    memset(nd->quat, 0, sizeof nd->quat);
    nd->use_quat = false;
    nd->scaling[0] = nd->scaling[1] = nd->scaling[2] = 1.0f;
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

static bool mote__is_instance(const mote__ld *ld, int node)
{
    return node >= ld->instances_first && node < ld->instances_end;
}

/* A copy of level mesh `level` for instance `inst` of its master, drawn in
 * the instance's place: InstancedMesh.getLOD asks its source's getLOD with
 * the instance's own bounding sphere, and the level chosen is drawn as an
 * instance of the level mesh, at the instance's world matrix. It shares
 * the level's arrays, material and sub-meshes. */
static R mote__lod_copy(mote__ld *ld, int level, int inst, int *out)
{
    if (ld->node_count >= ld->node_cap)
        return mote__fail(ld, MOTE_ERR_LIMIT, "%s: more than the limit of %u meshes (each "
                          "instance of a mesh with levels of detail has its own)",
                          ld->nodes[inst].where, (unsigned)ld->lim.max_meshes);
    mote__node *c = &ld->nodes[ld->node_count];
    const mote__node *l = &ld->nodes[level];
    *c = *l;
    c->arrays = l->arrays ? l->arrays : &ld->nodes[level];
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
    *out = ld->node_count++;
    return MOTE_OK;
}

/* Levels for the instances of each master (mote__lod_copy): a group per
 * instance, its levels those of its master with the copies in place of
 * the level meshes. Counted against the mesh limit before any is made. */
static R mote__lod_copies(mote__ld *ld)
{
    size_t copies = 0, levels = 0;
    const int groups = ld->lod_group_count;
    for (int gi = 0; gi < groups; gi++) {
        const mote__lod_group *g = &ld->lod_groups[gi];
        size_t meshes = 0, n = (size_t)ld->nodes[g->base].instance_count;
        for (int k = 0; k < g->level_count; k++)
            meshes += ld->lod_levels[g->first_level + k].node >= 0;
        copies += n * meshes;
        levels += n * (size_t)g->level_count;
    }
    if (levels == 0)
        return MOTE_OK;
    if (copies > (size_t)(ld->node_cap - ld->node_count))
        return mote__fail(ld, MOTE_ERR_LIMIT, "meshes: more than the limit of %u meshes (each "
                          "instance of a mesh with levels of detail has its own: %zu)",
                          (unsigned)ld->lim.max_meshes, copies);
    mote__lod_level *all = mote__store_alloc(&ld->tmp, (size_t)ld->lod_level_count + levels,
                                             sizeof *all);
    if (!all)
        return mote__oom(ld, "meshes");
    memcpy(all, ld->lod_levels, (size_t)ld->lod_level_count * sizeof *all);
    ld->lod_levels = all;
    for (int gi = 0; gi < groups; gi++) {
        const mote__lod_group g = ld->lod_groups[gi];
        const mote__node *m = &ld->nodes[g.base];
        for (int j = 0; j < m->instance_count; j++) {
            int inst = m->first_instance + j;
            if (ld->lod_master[inst] >= 0)
                continue;   /* itself a level: it chooses none (mote__lods) */
            mote__lod_group *ng = &ld->lod_groups[ld->lod_group_count++];
            ng->base = inst;
            ng->first_level = ld->lod_level_count;
            ng->level_count = g.level_count;
            for (int k = 0; k < g.level_count; k++) {
                mote__lod_level lv = ld->lod_levels[g.first_level + k];
                if (lv.node >= 0)
                    MOTE__TRY(mote__lod_copy(ld, lv.node, inst, &lv.node));
                ld->lod_levels[ld->lod_level_count++] = lv;
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
static R mote__lods(mote__ld *ld)
{
    const int nm = ld->file_meshes;
    size_t cap = 0;
    for (int i = 0; i < nm; i++)
        if (ld->nodes[i].lod_ids && ld->nodes[i].lod_distances)
            cap += mote__array_len(ld->nodes[i].lod_ids) + 1;
    if (cap == 0)
        return MOTE_OK;
    /* the meshes in scene.meshes' order, for getMeshById */
    int n = 0;
    int *order = mote__store_alloc(&ld->tmp, (size_t)ld->node_count, sizeof *order);
    const char **ids = mote__store_alloc(&ld->tmp, (size_t)ld->node_count, sizeof *ids);
    ld->lod_master = mote__store_alloc(&ld->tmp, (size_t)ld->node_cap, sizeof *ld->lod_master);
    ld->lod_levels = mote__store_alloc(&ld->tmp, cap, sizeof *ld->lod_levels);
    ld->lod_groups = mote__store_alloc(&ld->tmp, (size_t)ld->node_count,
                                       sizeof *ld->lod_groups);
    if (!order || !ids || !ld->lod_master || !ld->lod_levels || !ld->lod_groups)
        return mote__oom(ld, "meshes");
    for (int i = 0; i < nm; i++) {
        const mote__node *m = &ld->nodes[i];
        order[n] = i;
        ids[n++] = m->id;
        for (int j = 0; j < m->instance_count; j++) {
            order[n] = m->first_instance + j;
            ids[n++] = ld->nodes[m->first_instance + j].id;
        }
    }
    int dup;
    mote__idmap *map = mote__idmap_build(ld, ids, sizeof *ids, n, &dup);
    if (!map)
        return mote__oom(ld, "meshes");
    for (int i = 0; i < ld->node_cap; i++)
        ld->lod_master[i] = -1;
    for (int i = 0; i < nm; i++) {
        const mote__node *m = &ld->nodes[i];
        if (!m->lod_ids || !m->lod_ids->child || !m->lod_distances)
            continue;
        size_t nid = mote__array_len(m->lod_ids), ndist = mote__array_len(m->lod_distances);
        if (ndist < nid) {
            mote__warn(ld, "%s: %zu lodDistances for %zu lodMeshIds: Babylon.js makes no levels "
                       "of detail of them (\"Invalid level of detail distances\"), each mesh is "
                       "drawn by itself", m->where, ndist, nid);
            continue;
        }
        mote__lod_group *g = &ld->lod_groups[ld->lod_group_count];
        g->base = i;
        g->first_level = ld->lod_level_count;
        int seq = 0;
        size_t k = 0;
        const cJSON *d = m->lod_distances->child;
        for (const cJSON *e = m->lod_ids->child; e; e = e->next, d = d->next, k++) {
            char at[96];
            snprintf(at, sizeof at, "%s.lodMeshIds[%zu]", m->where, k);
            if (cJSON_IsNull(e)) {
                mote__warn(ld, "%s: null names no mesh; Babylon.js adds no level for it (one "
                           "past which nothing is drawn is a last lodDistances value past the "
                           "ids)", at);
                continue;
            }
            if (!cJSON_IsString(e))
                return mote__fail(ld, MOTE_ERR_PARSE, "%s: expected a string, found %s", at,
                                  mote__type_name(e));
            int pos = mote__idmap_find(map, e->valuestring);
            if (pos < 0) {
                mote__warn(ld, "%s: \"%s\" names no mesh; Babylon.js adds no level for it", at,
                           mote__quote(e->valuestring).s);
                continue;
            }
            int l = order[pos];
            if (l == i)
                return mote__fail(ld, MOTE_ERR_RANGE, "%s: \"%s\" names the mesh itself (a level "
                                  "is drawn at its master's world matrix)", at,
                                  mote__quote(e->valuestring).s);
            if (ld->lod_master[l] >= 0) {
                mote__warn(ld, "%s: \"%s\" is a level of detail of %s already; Babylon.js takes "
                           "a mesh as a level once", at, mote__quote(e->valuestring).s,
                           ld->nodes[ld->lod_master[l]].where);
                continue;
            }
            char dat[96];
            float distance;
            snprintf(dat, sizeof dat, "%s.lodDistances[%zu]", m->where, k);
            MOTE__TRY(mote__to_float(ld, d, dat, &distance));
            /* steps: no walk round a cycle of parents (mote__parents
             * reports it after) */
            for (int a = m->parent, steps = 0; a >= 0 && steps <= ld->node_count;
                 a = ld->nodes[a].parent, steps++)
                if (a == l)
                    return mote__fail(ld, MOTE_ERR_RANGE, "%s: \"%s\" is a parent of the mesh, "
                                      "whose place it would take", at,
                                      mote__quote(e->valuestring).s);
            ld->lod_master[l] = i;
            mote__lod_take_place(&ld->nodes[l], i);
            mote__lod_level *lv = &ld->lod_levels[ld->lod_level_count++];
            lv->distance = distance;
            lv->node = mote__is_instance(ld, l) ? -1 : l;
            lv->seq = seq++;
        }
        if (ndist > nid) {
            const cJSON *last = m->lod_distances->child;
            for (size_t j = 1; j < ndist; j++)
                last = last->next;
            char dat[96];
            float culling;
            snprintf(dat, sizeof dat, "%s.lodDistances[%zu]", m->where, ndist - 1);
            MOTE__TRY(mote__to_float(ld, last, dat, &culling));
            if (culling > 0.0f) {
                mote__lod_level *lv = &ld->lod_levels[ld->lod_level_count++];
                lv->distance = culling;
                lv->node = -1;
                lv->seq = seq++;
            }
        }
        g->level_count = mote__lod_sort(&ld->lod_levels[g->first_level],
                                        ld->lod_level_count - g->first_level);
        ld->lod_level_count = g->first_level + g->level_count;
        if (g->level_count > 0)
            ld->lod_group_count++;
    }
    /* a master that is itself a level is blocked: only its master chooses */
    int kept = 0;
    for (int gi = 0; gi < ld->lod_group_count; gi++)
        if (ld->lod_master[ld->lod_groups[gi].base] < 0)
            ld->lod_groups[kept++] = ld->lod_groups[gi];
    ld->lod_group_count = kept;
    return mote__lod_copies(ld);
}

/* parentId -> node index; then every chain must end (no cycle) within the
 * depth the core follows. */
static R mote__parents(mote__ld *ld)
{
    int dup;
    ld->node_map = mote__idmap_build(ld, &ld->nodes[0].id, sizeof *ld->nodes, ld->node_count,
                                     &dup);
    mote__idmap *unique_map = mote__idmap_build(ld, &ld->nodes[0].unique_id, sizeof *ld->nodes,
                                                ld->node_count, &dup);
    if (!ld->node_map || !unique_map)
        return mote__oom(ld, "meshes");
    for (int i = 0; i < ld->node_count; i++) {
        mote__node *nd = &ld->nodes[i];
        nd->parent = nd->is_thin ? nd->host : -1;
        if (!nd->parent_id)
            continue;
        if (nd->parent_by_unique)
            nd->parent = mote__idmap_find(unique_map, nd->parent_id);
        else
            nd->parent = mote__idmap_find_last(ld->node_map, nd->parent_id);
        if (nd->parent < 0)
            MOTE__TRY(mote__camera_light_parent(ld, nd));
        /* Babylon.js leaves such a node without a parent (a partial export,
         * "export selected"): it keeps its own transform */
        if (nd->parent < 0 && nd->parent_by_unique)
            mote__warn(ld, "%s.parentId: %s is the uniqueId of no node; loaded without a "
                       "parent", nd->where, nd->parent_id);
        else if (nd->parent < 0)
            mote__warn(ld, "%s.parentId: \"%s\" names no node; loaded without a parent",
                       nd->where, mote__quote(nd->parent_id).s);
    }
    for (int i = 0; i < ld->node_count; i++) {
        mote__node *nd = &ld->nodes[i];
        if (nd->parent < 0 || nd->parent_instance < 0)
            continue;
        const mote__node *p = &ld->nodes[nd->parent];
        if (nd->parent_instance >= p->instance_count)
            return mote__fail(ld, MOTE_ERR_RANGE, "%s.parentInstanceIndex: %s has no instance %d "
                              "(it has %d)", nd->where, p->where, nd->parent_instance,
                              p->instance_count);
        nd->parent = p->first_instance + nd->parent_instance;
    }
    /* levels of detail take their master's place (and its instances get
     * levels of their own), before the matrices are folded */
    MOTE__TRY(mote__lods(ld));
    /* the matrices, now that the parents are known (helpers take them) */
    for (int i = 0, n = ld->node_count; i < n; i++)
        if (ld->nodes[i].has_matrix)
            MOTE__TRY(mote__fold_matrix(ld, i));
    for (int i = 0; i < ld->node_count; i++) {
        /* walk up marking the path; meeting the path again is a cycle */
        int j = i;
        while (j >= 0 && ld->nodes[j].state == 0) {
            ld->nodes[j].state = 1;
            j = ld->nodes[j].parent;
        }
        if (j >= 0 && ld->nodes[j].state == 1)
            return mote__fail(ld, MOTE_ERR_RANGE, "%s.parentId: \"%s\" makes a cycle",
                              ld->nodes[j].where, mote__quote(ld->nodes[j].parent_id).s);
        for (j = i; j >= 0 && ld->nodes[j].state == 1; j = ld->nodes[j].parent)
            ld->nodes[j].state = 2;
    }
    /* the core follows at most MOTE_MAX_PARENTS parents, hidden helpers
     * (mote__fold_matrix) among them */
    for (int i = 0; i < ld->node_count; i++) {
        int depth = 0, helpers = 0;
        for (int j = ld->nodes[i].parent; j >= 0; j = ld->nodes[j].parent) {
            helpers += ld->nodes[j].is_helper;
            if (++depth > MOTE_MAX_PARENTS)
                return mote__fail(ld, MOTE_ERR_LIMIT, "%s: more than %d parents (MOTE_MAX_PARENTS)%s",
                                  ld->nodes[i].where, MOTE_MAX_PARENTS,
                                  helpers ? ", counting one for each sheared pivotMatrix or localMatrix above it"
                                          : "");
        }
    }
    return MOTE_OK;
}

/* The material of a (sub-)mesh: a material, a multi-material slot, or NULL
 * for the default (white) one, with a warning when nothing is named.
 * materialUniqueId comes first, as in Babylon.js (materials re-exported from
 * glTF often share an id); when it matches nothing, materialId is tried.
 * Either resolves to the last holder, as getLastMaterialById does. */
static const mote__mat *mote__resolve_material(mote__ld *ld, const mote__node *nd,
                                               uint32_t material_index)
{
    int m = -1, mm = -1;
    if (nd->material_unique_id) {
        m = mote__idmap_find_last(ld->mat_unique_map, nd->material_unique_id);
        if (m < 0)
            mm = mote__idmap_find_last(ld->multi_unique_map, nd->material_unique_id);
    }
    if (m < 0 && mm < 0 && nd->material_id) {
        m = mote__idmap_find_last(ld->mat_map, nd->material_id);
        if (m < 0)
            mm = mote__idmap_find_last(ld->multi_map, nd->material_id);
    }
    if (m >= 0)
        return &ld->mats[m];
    if (mm < 0) {
        if (nd->material_id)
            mote__warn(ld, "%s.materialId: \"%s\" names no material", nd->where,
                       mote__quote(nd->material_id).s);
        else if (nd->material_unique_id)
            mote__warn(ld, "%s.materialUniqueId: %s is the uniqueId of no material",
                       nd->where, nd->material_unique_id);
        return NULL;
    }
    const mote__multi *multi = &ld->multis[mm];
    if (material_index >= (uint32_t)multi->slot_count) {
        mote__warn(ld, "%s: materialIndex %u is past the %d materials of \"%s\"", nd->where,
                   (unsigned)material_index, multi->slot_count, mote__quote(multi->id).s);
        return NULL;
    }
    int slot = multi->slots[material_index];
    return slot >= 0 ? &ld->mats[slot] : NULL;
}

/* Whether it or a parent is disabled (chains are finite and short:
 * mote__parents). */
static bool mote__node_disabled(const mote__ld *ld, const mote__node *nd)
{
    for (; nd; nd = nd->parent >= 0 ? &ld->nodes[nd->parent] : NULL)
        if (nd->disabled)
            return true;
    return false;
}

/* Points m (of node nd) at vertices whose uv is uvs2, made once per
 * shared vertex array; without uvs2, m keeps uvs (warned). */
static R mote__uv2_vertices(mote__ld *ld, mote__node *nd, mote_mesh *m)
{
    mote__node *owner = nd->arrays ? nd->arrays : nd;
    if (!owner->uv2) {
        if (owner->nv)
            mote__warn(ld, "%s: its texture samples uvs2 (coordinatesIndex 1), which the "
                       "mesh lacks; uvs are used", nd->where);
        return MOTE_OK;
    }
    if (!owner->verts2) {
        owner->verts2 = mote__store_alloc(ld->keep, owner->nv, sizeof *owner->verts2);
        if (!owner->verts2)
            return mote__oom(ld, nd->where);
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
static R mote__side_indices(mote__ld *ld, mote__node *nd, int s, const mote__mat *mat, mote_mesh *m)
{
    unsigned char side = nd->side != MOTE__SIDE_UNSAID ? nd->side
                         : mat                         ? mat->side
                                                       : MOTE__SIDE_UNSAID;
    bool flip = side != MOTE__SIDE_UNSAID && (side == MOTE__SIDE_CW) != ld->right_handed;
    if (mat && mat->cull_front)
        flip = !flip;
    if (nd->thin_mirrored)
        flip = !flip;
    if (!flip || !m->indices || m->index_count == 0)
        return MOTE_OK;
    if (nd->sub_count > 0 && (nd->subs[s].own_indices || nd->subs[s].index_start % 3)) {
        /* an unindexed sub-mesh starting inside one of the array's
         * triangles, or drawing a run of its own: a flipped copy of its own */
        uint32_t *own = mote__store_alloc(ld->keep, m->index_count, sizeof *own);
        if (!own)
            return mote__oom(ld, nd->where);
        memcpy(own, m->indices, (size_t)m->index_count * sizeof *own);
        mote__flip_winding(own, m->index_count);
        m->indices = own;
        return MOTE_OK;
    }
    mote__node *owner = nd->arrays ? nd->arrays : nd;
    if (!owner->idx_flipped) {
        owner->idx_flipped = mote__store_alloc(ld->keep, owner->ni, sizeof *owner->idx_flipped);
        if (!owner->idx_flipped)
            return mote__oom(ld, nd->where);
        memcpy(owner->idx_flipped, owner->idx, (size_t)owner->ni * sizeof *owner->idx);
        mote__flip_winding(owner->idx_flipped, owner->ni);
    }
    m->indices = owner->idx_flipped + (nd->sub_count > 0 ? nd->subs[s].index_start : 0);
    return MOTE_OK;
}

/* Whether a node is not drawn: it is invisible or disabled. */
static bool mote__node_hidden(const mote__ld *ld, const mote__node *nd)
{
    return nd->invisible || mote__node_disabled(ld, nd);
}

static R mote__build_meshes(mote__ld *ld)
{
    size_t total = 0;
    for (int i = 0; i < ld->node_count; i++) {
        mote__node *nd = &ld->nodes[i];
        nd->first_mesh = (int)total;
        nd->mesh_count = nd->sub_count > 0 ? nd->sub_count : 1;
        total += (size_t)nd->mesh_count;
    }
    if (total > ld->lim.max_meshes)
        return mote__fail(ld, MOTE_ERR_LIMIT, "meshes: %zu meshes with their sub-meshes, more "
                          "than the limit of %u", total, (unsigned)ld->lim.max_meshes);
    mote_scene *sc = ld->scene;
    /* one allocation, never moved: parents point into it */
    sc->meshes = mote__store_alloc(ld->keep, total, sizeof *sc->meshes);
    if (!sc->meshes)
        return mote__oom(ld, "meshes");
    sc->mesh_count = (int)total;
    /* a byte per mesh and flag, so that mote_scene_draw_desc needs no search */
    bool *two_sided = mote__store_alloc(ld->keep, 2 * total, sizeof *two_sided);
    if (!two_sided)
        return mote__oom(ld, "meshes");
    bool *unlit = two_sided + total;
    sc->two_sided = two_sided;
    sc->unlit = unlit;
    for (int i = 0; i < ld->node_count; i++) {
        mote__node *nd = &ld->nodes[i];
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
            memcpy(m->position, nd->position, sizeof m->position);
            memcpy(m->rotation, nd->rotation, sizeof m->rotation);
            memcpy(m->rotation_quaternion, nd->quat, sizeof m->rotation_quaternion);
            m->use_quaternion = nd->use_quat;
            memcpy(m->scaling, nd->scaling, sizeof m->scaling);
            m->parent = nd->parent >= 0 ? &sc->meshes[ld->nodes[nd->parent].first_mesh] : NULL;
            const mote__mat *mat = mote__resolve_material(ld, nd, material_index);
            if (mat) {
                m->material = mat->material;
                two_sided[nd->first_mesh + s] = mat->two_sided;
                unlit[nd->first_mesh + s] = mat->unlit;
                if (mat->uv2)
                    MOTE__TRY(mote__uv2_vertices(ld, nd, m));
            }
            MOTE__TRY(mote__side_indices(ld, nd, s, mat, m));
            /* v = 0: the bottom row when the texture says invertY (what
             * Babylon.js does by default, and current exporters rely on),
             * the top row when it says not; unsaid, legacy files (the
             * tutorial's) address the top row, current ones the bottom */
            m->material.v_origin_bottom = mat && mat->invert_y >= 0 ? mat->invert_y != 0 : !nd->legacy;
            m->hidden = mote__node_hidden(ld, nd) || nd->undrawn;
            mote_mesh_update_bounds(m);
        }
    }
    return MOTE_OK;
}

/* What a node draws as the base or a level of detail: its sub-meshes, or
 * its thin instances' (contiguous nodes, so contiguous meshes); nothing
 * when its own are not drawn and it has no thin instances. */
static void mote__lod_unit(const mote__ld *ld, int node, int *first, int *count)
{
    const mote__node *nd = &ld->nodes[node];
    *first = nd->first_mesh;
    *count = 0;
    if (nd->thin_count > 0) {
        const mote__node *t = &ld->nodes[nd->first_thin];
        *first = t->first_mesh;
        *count = nd->thin_count * t->mesh_count;
    } else if (!nd->undrawn) {
        *count = nd->mesh_count;
    }
}

/* Shows group g's base (chosen -1) or its level `chosen` in meshes, and
 * hides the rest of it (all of it when the group is hidden). */
static void mote__lod_show(const mote_scene *sc, mote_mesh *meshes, int g, int chosen)
{
    const mote_lod *lod = &sc->lods[g];
    for (int k = -1; k < lod->level_count; k++) {
        int first = k < 0 ? lod->first_mesh : lod->levels[k].first_mesh;
        int count = k < 0 ? lod->mesh_count : lod->levels[k].mesh_count;
        if (first < 0 || count < 0 || count > sc->mesh_count - first)
            continue;
        for (int i = first; i < first + count; i++)
            meshes[i].hidden = lod->hidden || k != chosen;
    }
}

/* scene.lods from the groups of mote__lods, once the meshes are made, each
 * showing its base; the levels of groups that are none (masters that are
 * levels themselves) are hidden for good. */
static R mote__lod_groups(mote__ld *ld)
{
    mote_scene *sc = ld->scene;
    if (!ld->lod_master)
        return MOTE_OK;
    for (int i = 0; i < ld->node_count; i++) {
        /* an instance taken as a level is drawn as ever (mote__lods) */
        if ((ld->lod_master[i] < 0 || mote__is_instance(ld, i)) && !ld->nodes[i].lod_copy)
            continue;
        int first, count;
        mote__lod_unit(ld, i, &first, &count);
        for (int k = first; k < first + count; k++)
            sc->meshes[k].hidden = true;
    }
    if (ld->lod_group_count == 0)
        return MOTE_OK;
    mote_lod *lods = mote__store_alloc(ld->keep, (size_t)ld->lod_group_count, sizeof *lods);
    mote_lod_level *levels = mote__store_alloc(ld->keep, (size_t)ld->lod_level_count,
                                               sizeof *levels);
    if (!lods || !levels)
        return mote__oom(ld, "meshes");
    for (int g = 0; g < ld->lod_group_count; g++) {
        const mote__lod_group *lg = &ld->lod_groups[g];
        mote_lod *lod = &lods[g];
        mote__lod_unit(ld, lg->base, &lod->first_mesh, &lod->mesh_count);
        lod->bounds_mesh = ld->nodes[lg->base].first_mesh;
        lod->hidden = mote__node_hidden(ld, &ld->nodes[lg->base]);
        lod->levels = levels;
        lod->level_count = lg->level_count;
        for (int k = 0; k < lg->level_count; k++) {
            const mote__lod_level *lv = &ld->lod_levels[lg->first_level + k];
            levels[k].distance = lv->distance;
            levels[k].first_mesh = 0;
            levels[k].mesh_count = 0;
            if (lv->node >= 0)
                mote__lod_unit(ld, lv->node, &levels[k].first_mesh, &levels[k].mesh_count);
        }
        levels += lg->level_count;
    }
    sc->lods = lods;
    sc->lod_count = ld->lod_group_count;
    for (int g = 0; g < sc->lod_count; g++)
        mote__lod_show(sc, sc->meshes, g, -1);
    return MOTE_OK;
}

/* scene.bounds: a world-space box over every drawn vertex (once per node:
 * sub-meshes share). */
static R mote__scene_bounds(mote__ld *ld)
{
    mote_scene *sc = ld->scene;
    bool any = false;
    for (int i = 0; i < ld->node_count; i++) {
        const mote__node *nd = &ld->nodes[i];
        if (nd->nv == 0 || sc->meshes[nd->first_mesh].hidden)
            continue;
        float w[16];
        mote_mesh_world_matrix(&sc->meshes[nd->first_mesh], w);
        for (uint32_t v = 0; v < nd->nv; v++) {
            const float *p = nd->verts[v].position;
            float q[3];
            for (int k = 0; k < 3; k++)
                q[k] = w[k] * p[0] + w[4 + k] * p[1] + w[8 + k] * p[2] + w[12 + k];
            if (!isfinite(q[0]) || !isfinite(q[1]) || !isfinite(q[2]))
                continue;
            for (int k = 0; k < 3; k++) {
                if (!any || q[k] < sc->bounds_min[k]) sc->bounds_min[k] = q[k];
                if (!any || q[k] > sc->bounds_max[k]) sc->bounds_max[k] = q[k];
            }
            any = true;
        }
    }
    return MOTE_OK;
}

/* ---- camera, lights, scene colours ------------------------------------ */

/* The world matrix of the parent of cameras[k] (list 0) or lights[k] (1),
 * when it has one (its node: mote__camera_light_nodes). */
static bool mote__parent_world(const mote__ld *ld, int list, int k, float w[16])
{
    int x = ld->xlists[list].node[k];
    if (x < 0 || ld->nodes[x].parent < 0)
        return false;
    mote_mesh_world_matrix(&ld->scene->meshes[ld->nodes[ld->nodes[x].parent].first_mesh], w);
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
static void mote__turned_axes(const float rotation[3], const float quat[4], bool use_quat,
                              float forward[3], float up[3])
{
    float w[16];
    mote__transform_matrix(NULL, rotation, quat, use_quat, NULL, w);
    memcpy(forward, &w[8], 3 * sizeof *forward);
    memcpy(up, &w[4], 3 * sizeof *up);
}

/* An orthographic camera's box (orthoLeft, orthoRight, orthoBottom,
 * orthoTop). Babylon.js sizes a missing or null edge by the canvas, half
 * its width or height in pixels, which a file does not know: then the
 * core's default box, 2 units high, with a warning. */
static R mote__ortho_box(mote__ld *ld, const cJSON *cam, const char *at, mote_camera *c)
{
    static const char *const keys[4] = {"orthoLeft", "orthoRight", "orthoBottom", "orthoTop"};
    c->projection = MOTE_PROJECTION_ORTHOGRAPHIC;
    int given = 0;
    for (int k = 0; k < 4; k++) {
        given += mote__get(cam, keys[k]) != NULL;   /* null: not written */
        MOTE__TRY(mote__num(ld, cam, keys[k], at, &c->ortho[k]));
    }
    if (given < 4) {
        memset(c->ortho, 0, sizeof c->ortho);
        mote__warn(ld, "%s: an orthographic camera without all of orthoLeft, orthoRight, orthoBottom "
                   "and orthoTop (Babylon.js sizes it by the canvas, in pixels) is drawn 2 units high", at);
    } else if (!(c->ortho[0] != c->ortho[1] && c->ortho[2] != c->ortho[3])) {
        return mote__fail(ld, MOTE_ERR_RANGE, "%s: orthoLeft %g, orthoRight %g, orthoBottom %g and "
                          "orthoTop %g enclose nothing", at, c->ortho[0], c->ortho[1], c->ortho[2],
                          c->ortho[3]);
    }
    return MOTE_OK;
}

static R mote__camera(mote__ld *ld)
{
    const cJSON *cam;
    int index;
    MOTE__TRY(mote__active_camera(ld, true, &cam, &index));
    if (!cam)
        return MOTE_OK;
    char at[48];
    snprintf(at, sizeof at, "cameras[%d]", index);
    MOTE__TRY(mote__obj_at(ld, cam, at));
    const cJSON *mode = mote__get(cam, "mode");
    const bool ortho = cJSON_IsNumber(mode) && mode->valuedouble == 1.0;   /* ORTHOGRAPHIC_CAMERA */
    mote_camera *c = &ld->scene->camera;
    memset(c, 0, sizeof *c);
    if (ortho)
        MOTE__TRY(mote__ortho_box(ld, cam, at, c));
    MOTE__TRY(mote__vec(ld, cam, "position", at, 3, 0, c->position));
    if (ld->right_handed)
        mote__mirror_point(c->position);
    const char *locked;
    float turned_up[3];
    bool rolled = false;
    MOTE__TRY(mote__id_ref(ld, cam, "lockedTargetId", at, &locked));
    int target_node = mote__idmap_find_last(ld->node_map, locked);
    if (locked && target_node < 0)
        mote__warn(ld, "%s.lockedTargetId: \"%s\" names no mesh or transform node; the "
                   "camera's own direction is used", at, mote__quote(locked).s);
    if (target_node >= 0) {
        /* a target camera (3ds Max) looks at the node's world position */
        float w[16];
        mote_mesh_world_matrix(&ld->scene->meshes[ld->nodes[target_node].first_mesh], w);
        memcpy(c->target, &w[12], sizeof c->target);
        mote__level_target_nudge(ld, cam, c->position, c->target);
    } else if (mote__get(cam, "target")) {
        MOTE__TRY(mote__vec(ld, cam, "target", at, 3, 0, c->target));
        if (ld->right_handed)
            mote__mirror_point(c->target);
        mote__level_target_nudge(ld, cam, c->position, c->target);
    } else {
        /* target = position + forward (+z) turned by the rotation (yaw,
         * pitch, roll; rotationQuaternion overrides it), as meshes turn */
        float rotation[3], quat[4], fwd[3];
        bool use_quat;
        MOTE__TRY(mote__camera_turn(ld, cam, at, rotation, quat, &use_quat));
        mote__turned_axes(rotation, quat, use_quat, fwd, turned_up);
        rolled = use_quat ? quat[2] != 0.0f : rotation[2] != 0.0f;
        for (int k = 0; k < 3; k++)
            c->target[k] = c->position[k] + fwd[k];
    }
    MOTE__TRY(mote__vec(ld, cam, "upVector", at, 3, 0, c->up));
    if (ld->right_handed)
        mote__mirror_point(c->up);
    if (rolled)
        memcpy(c->up, turned_up, sizeof c->up);
    /* Babylon.js's Camera defaults */
    c->fov = 0.8f;
    c->znear = 1.0f;
    c->zfar = 10000.0f;
    MOTE__TRY(mote__num(ld, cam, "fov", at, &c->fov));
    MOTE__TRY(mote__num(ld, cam, "minZ", at, &c->znear));
    MOTE__TRY(mote__num(ld, cam, "maxZ", at, &c->zfar));
    if (!ortho && !(c->fov > 0.0f && c->fov < 3.14159f))   /* unused by an orthographic one */
        return mote__fail(ld, MOTE_ERR_RANGE, "%s.fov: %g is not in (0, pi)", at, c->fov);
    /* Babylon.js's FOVMODE_HORIZONTAL_FIXED: any fovMode but 0 (vertical);
     * the aspect ratio is known only when framing (mote_scene_frame) */
    MOTE__TRY(mote__flag(ld, cam, "fovMode", at, &ld->scene->camera_fov_is_horizontal));
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
        return mote__fail(ld, MOTE_ERR_RANGE, "%s: minZ %g and maxZ %g need minZ < maxZ%s", at, c->znear,
                          c->zfar, ortho ? "" : " (maxZ 0: no far plane)");
    /* a parent (3ds Max rigs) moves and turns the whole view: the view
     * matrix is the parent's world matrix after the camera's own */
    float w[16];
    if (mote__parent_world(ld, 0, index, w)) {
        if (c->up[0] == 0.0f && c->up[1] == 0.0f && c->up[2] == 0.0f)
            c->up[1] = 1.0f;
        mote__transform(w, c->position, true);
        mote__transform(w, c->target, true);
        mote__transform(w, c->up, false);
    }
    ld->scene->has_camera = true;
    return MOTE_OK;
}

/* A point or spot light's range: > 0 fades it to nothing at that distance
 * (Babylon.js's default falloff). Babylon.js writes Number.MAX_VALUE, which
 * no float holds, for a light without one; that, 0, and a negative range
 * leave it unlimited (0). */
static R mote__light_range(mote__ld *ld, const cJSON *light, const char *at, float *range)
{
    const cJSON *v = mote__get(light, "range");
    if (cJSON_IsNumber(v) && v->valuedouble > (double)FLT_MAX)
        return MOTE_OK;
    MOTE__TRY(mote__num(ld, light, "range", at, range));
    if (!(*range > 0.0f))
        *range = 0.0f;
    return MOTE_OK;
}

static R mote__lights(mote__ld *ld)
{
    const cJSON *lights;
    MOTE__TRY(mote__arr(ld, ld->root, "lights", "", &lights));
    int i = 0, ignored = 0, first_ignored = 0;
    mote_scene *sc = ld->scene;
    sc->has_lights = lights && lights->child;
    for (const cJSON *l = lights ? lights->child : NULL; l; l = l->next, i++) {
        char at[48];
        snprintf(at, sizeof at, "lights[%d]", i);
        MOTE__TRY(mote__obj_at(ld, l, at));
        uint32_t t = 0;
        MOTE__TRY(mote__light_type(ld, l, at, &t));
        mote_light L;
        memset(&L, 0, sizeof L);
        float data[3] = {0, 0, 0};
        MOTE__TRY(mote__vec(ld, l, "data", at, 3, 0, data));
        bool has_data = mote__get(l, "data") != NULL;
        if (t == 0 || t == 2) {
            L.type = t == 0 ? MOTE_LIGHT_POINT : MOTE_LIGHT_SPOT;
            memcpy(L.position, data, sizeof data);
            MOTE__TRY(mote__vec(ld, l, "position", at, 3, 0, L.position));
            MOTE__TRY(mote__light_range(ld, l, at, &L.range));
            if (t == 2) {         /* Babylon.js makes a spot light of no angle and exponent 0 */
                MOTE__TRY(mote__vec(ld, l, "direction", at, 3, 0, L.direction));
                MOTE__TRY(mote__num(ld, l, "angle", at, &L.spot_angle));
                MOTE__TRY(mote__num(ld, l, "exponent", at, &L.spot_exponent));
            }
        } else if (t == 1) {
            L.type = MOTE_LIGHT_DIRECTIONAL;
            L.direction[1] = -1.0f;
            if (has_data)
                memcpy(L.direction, data, sizeof data);
            MOTE__TRY(mote__vec(ld, l, "direction", at, 3, 0, L.direction));
        } else {
            L.type = MOTE_LIGHT_HEMISPHERIC;
            L.direction[1] = 1.0f;
            if (has_data)
                memcpy(L.direction, data, sizeof data);
            MOTE__TRY(mote__vec(ld, l, "direction", at, 3, 0, L.direction));
            MOTE__TRY(mote__vec(ld, l, "groundColor", at, 3, 0, L.ground_color));
        }
        if (ld->right_handed) {
            mote__mirror_point(L.position);
            mote__mirror_point(L.direction);
        }
        float color[3] = {1, 1, 1}, intensity = 1.0f;
        MOTE__TRY(mote__vec(ld, l, "diffuse", at, 3, 0, color));
        MOTE__TRY(mote__num(ld, l, "intensity", at, &intensity));
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
        /* a disabled light, or one under a disabled parent, lights nothing */
        bool enabled = true;
        MOTE__TRY(mote__flag(ld, l, "isEnabled", at, &enabled));
        int x = ld->xlists[1].node[i];
        if (!enabled || (x >= 0 && mote__node_disabled(ld, &ld->nodes[x])))
            continue;
        /* a parent moves a point or spot light and turns a directional one
         * (ShadowLight's transformed position and direction); a
         * hemispheric light keeps its direction (its node has no parent) */
        float w[16];
        if (mote__parent_world(ld, 1, i, w)) {
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
        sc->lights[sc->light_count++] = L;
    }
    /* one warning for them all, not one each */
    if (ignored == 1)
        mote__warn(ld, "lights[%d]: more than %d lights; this one is ignored", first_ignored,
                   MOTE_MAX_LIGHTS);
    else if (ignored > 1)
        mote__warn(ld, "lights[%d]: more than %d lights; it and %d later ones are ignored",
                   first_ignored, MOTE_MAX_LIGHTS, ignored - 1);
    return MOTE_OK;
}

static R mote__scene_colors(mote__ld *ld)
{
    mote_scene *sc = ld->scene;
    MOTE__TRY(mote__vec(ld, ld->root, "ambientColor", "scene", 3, 0, sc->ambient));
    float c[4] = {0, 0, 0, 1};
    MOTE__TRY(mote__vec(ld, ld->root, "clearColor", "scene", 3, 4, c));
    sc->clear_color.r = mote__unit_byte(c[0]);
    sc->clear_color.g = mote__unit_byte(c[1]);
    sc->clear_color.b = mote__unit_byte(c[2]);
    sc->clear_color.a = 255;
    return MOTE_OK;
}

/* ---- parsing ----------------------------------------------------------- */

/* Nesting depth checked on the text before cJSON (which recurses) sees it. */
static R mote__check_depth(mote__ld *ld, const char *json, size_t size, bool *unclosed)
{
    int depth = 0;
    bool in_string = false;
    for (size_t i = 0; i < size; i++) {
        char c = json[i];
        if (in_string) {
            if (c == '\\')
                i++;
            else if (c == '"')
                in_string = false;
        } else if (c == '"') {
            in_string = true;
        } else if (c == '[' || c == '{') {
            if (++depth > ld->lim.max_json_depth)
                return mote__fail(ld, MOTE_ERR_LIMIT,
                                  "byte %zu: nesting deeper than the limit of %d levels", i,
                                  ld->lim.max_json_depth);
        } else if (c == ']' || c == '}') {
            depth--;
        }
    }
    *unclosed = in_string || depth > 0;
    return MOTE_OK;
}

static R mote__parse(mote__ld *ld, const char *json, size_t size, cJSON **out)
{
    *out = NULL;
    bool unclosed = false;
    MOTE__TRY(mote__check_depth(ld, json, size, &unclosed));
    if (size == 0)
        return mote__fail(ld, MOTE_ERR_PARSE, "empty file");
    const char *end = NULL;
    cJSON *root = cJSON_ParseWithLengthOpts(json, size, &end, 0);
    if (!root) {
        size_t at = end && end >= json && end <= json + size ? (size_t)(end - json) : size;
        size_t line = 1;
        for (size_t i = 0; i < at && i < size; i++)
            line += json[i] == '\n';
        if (at >= size || unclosed)
            return mote__fail(ld, MOTE_ERR_PARSE, "line %zu: unexpected end of the JSON text "
                              "(truncated?)", line);
        return mote__fail(ld, MOTE_ERR_PARSE, "line %zu, byte %zu: malformed JSON", line, at);
    }
    size_t at = end ? (size_t)(end - json) : size;
    while (at < size && (json[at] == ' ' || json[at] == '\t' || json[at] == '\r' ||
                         json[at] == '\n' || json[at] == '\0'))
        at++;
    if (at < size) {
        cJSON_Delete(root);
        return mote__fail(ld, MOTE_ERR_PARSE, "byte %zu: text after the end of the JSON value",
                          at);
    }
    if (!cJSON_IsObject(root)) {
        cJSON_Delete(root);
        return mote__fail(ld, MOTE_ERR_PARSE, "expected a JSON object at the top level");
    }
    *out = root;
    return MOTE_OK;
}

static R mote__load(mote__ld *ld, const char *json, size_t size)
{
    cJSON *root;
    MOTE__TRY(mote__parse(ld, json, size, &root));
    ld->root = root;
    /* a right-handed scene is loaded mirrored (mote__mirror_point) */
    R r = mote__flag(ld, root, "useRightHandedSystem", "scene", &ld->right_handed);
    ld->scene->mirrored_z = ld->right_handed;
    /* the ambient colour first: an unlit material's colour takes it in */
    if (r == MOTE_OK) r = mote__scene_colors(ld);
    if (r == MOTE_OK) r = mote__materials(ld);
    if (r == MOTE_OK) r = mote__multi_materials(ld);
    if (r == MOTE_OK) r = mote__nodes(ld);
    if (r == MOTE_OK) r = mote__camera_light_nodes(ld);
    if (r == MOTE_OK) r = mote__parents(ld);
    if (r == MOTE_OK) r = mote__build_meshes(ld);
    if (r == MOTE_OK) r = mote__lod_groups(ld);
    if (r == MOTE_OK) r = mote__scene_bounds(ld);
    if (r == MOTE_OK) r = mote__camera(ld);
    if (r == MOTE_OK) r = mote__lights(ld);
    /* the levels of detail Babylon.js draws for the scene's camera */
    if (r == MOTE_OK && ld->scene->has_camera)
        mote_scene_choose_lod(ld->scene, ld->scene->meshes, &ld->scene->camera);
    cJSON_Delete(root);
    ld->root = NULL;
    return r;
}

static void mote__free_storage(mote_scene *scene)
{
    mote__store *keep = scene->storage_;
    if (scene->textures)
        for (int i = 0; i < scene->texture_count; i++)
            mote_texture_free(&scene->textures[i]);
    if (keep) {
        mote__store_release(keep);
        mote__io_free(keep);
    }
}

void mote_scene_free(mote_scene *scene)
{
    if (!scene)
        return;
    mote__free_storage(scene);
    memset(scene, 0, sizeof *scene);
}

mote_result mote_scene_load_memory(const char *json, size_t size, const char *name,
                                   const char *base_dir, const mote_limits *limits,
                                   mote_scene *out, char *message, size_t message_size)
{
    if (message && message_size)
        message[0] = '\0';
    if (!out)
        return mote__io_error(message, message_size, MOTE_ERR_INVALID_ARGUMENT,
                              "scene: no output scene given");
    memset(out, 0, sizeof *out);
    if (!json && size > 0)
        return mote__io_error(message, message_size, MOTE_ERR_INVALID_ARGUMENT,
                              "scene: no JSON text given");
    mote__ld ld;
    memset(&ld, 0, sizeof ld);
    mote__io_clean_name(ld.name, sizeof ld.name, name ? name : "scene");
    ld.base_dir = base_dir;
    ld.lim = mote__io_limits(limits);
    ld.msg = message;
    ld.msg_size = message_size;
    ld.scene = out;
    if (size > ld.lim.max_file_bytes)
        return mote__fail(&ld, MOTE_ERR_LIMIT, "%zu bytes, more than the limit of %zu", size,
                          ld.lim.max_file_bytes);
    ld.keep = mote__io_calloc(1, sizeof *ld.keep);
    if (!ld.keep)
        return mote__oom(&ld, "scene");
    out->storage_ = ld.keep;
    out->files_ = mote__store_alloc(ld.keep, 1, sizeof(mote__scene_files));
    if (!out->files_) {
        mote_scene_free(out);
        return mote__oom(&ld, "scene");
    }
    R r = mote__load(&ld, json ? json : "", size);
    mote__store_release(&ld.tmp);
    if (r != MOTE_OK) {
        mote_scene_free(out);
        return r;
    }
    return MOTE_OK;
}

mote_result mote_scene_load(const char *path, const mote_limits *limits, mote_scene *out,
                            char *message, size_t message_size)
{
    if (out)
        memset(out, 0, sizeof *out);
    if (!path || !out)
        return mote__io_error(message, message_size, MOTE_ERR_INVALID_ARGUMENT,
                              "scene: no path or no output scene given");
    mote_limits lim = mote__io_limits(limits);
    char *data = NULL;
    size_t size = 0;
    mote__io_file file;
    R r = mote__io_open(path, &file, message, message_size);
    const mote__io_file_id id = file.id;
    if (r == MOTE_OK)
        r = mote__io_read_open(&file, lim.max_file_bytes, &data, &size, message, message_size);
    if (r != MOTE_OK)
        return r;
    /* split "dir/name.babylon": textures resolve in dir, messages say name */
    const char *slash = strrchr(path, '/');
#ifdef _WIN32
    const char *bslash = strrchr(path, '\\');
    if (bslash && (!slash || bslash > slash))
        slash = bslash;
#endif
    const char *base = slash ? slash + 1 : path;
    size_t dir_len = slash ? (size_t)(slash - path) : 1;
    char *dir = mote__io_malloc(dir_len + 1);
    if (!dir) {
        mote__io_free(data);
        return mote__io_error(message, message_size, MOTE_ERR_OUT_OF_MEMORY,
                              "%s: out of memory", base);
    }
    if (slash)
        memcpy(dir, path, dir_len);
    else
        dir[0] = '.';
    if (slash && dir_len == 0)
        dir[dir_len++] = '/'; /* "/scene.babylon" lives in "/" */
    dir[dir_len] = '\0';
    r = mote_scene_load_memory(data, size, base, dir, &lim, out, message, message_size);
    if (r == MOTE_OK)
        ((mote__scene_files *)out->files_)->scene = id;
    mote__io_free(dir);
    mote__io_free(data);
    return r;
}

/* ---- framing ----------------------------------------------------------- */

void mote_scene_draw_desc(const mote_scene *scene, int mesh, const mote_draw_desc *base,
                          mote_draw_desc *out)
{
    if (!out)
        return;
    if (base)
        *out = *base;
    else
        memset(out, 0, sizeof *out);
    /* Babylon.js draws both sides of a mesh whose material says
     * backFaceCulling false: no culling, whatever the caller asked */
    if (!scene || mesh < 0 || mesh >= scene->mesh_count)
        return;
    if (scene->two_sided && scene->two_sided[mesh])
        out->cull = MOTE_CULL_NONE;
    /* and without lights one whose material says disableLighting (its
     * colour is then the emissive one: mote__emissive) */
    if (scene->unlit && scene->unlit[mesh])
        out->unlit = true;
}

int mote_scene_lod_level(const mote_scene *scene, int lod, const mote_mesh *meshes,
                         const mote_camera *camera)
{
    if (!scene || !meshes || !camera || lod < 0 || lod >= scene->lod_count)
        return -1;
    const mote_lod *g = &scene->lods[lod];
    if (g->level_count <= 0 || !g->levels || g->bounds_mesh < 0 ||
        g->bounds_mesh >= scene->mesh_count)
        return -1;
    /* Mesh.getLOD: an orthographic camera's minZ, else the distance from
     * the camera to the bounding sphere's centre in world space */
    float distance = camera->znear;
    if (camera->projection != MOTE_PROJECTION_ORTHOGRAPHIC) {
        const mote_mesh *m = &meshes[g->bounds_mesh];
        const float *c = m->bounds_center;
        float w[16];
        double sum = 0.0;
        mote_mesh_world_matrix(m, w);
        for (int k = 0; k < 3; k++) {
            double d = (double)w[k] * c[0] + (double)w[4 + k] * c[1] + (double)w[8 + k] * c[2] +
                       (double)w[12 + k] - (double)camera->position[k];
            sum += d * d;
        }
        distance = (float)sqrt(sum);
    }
    /* nearer than the last (smallest) distance: the base; else the first
     * level, farthest first, whose distance is below the camera's (an
     * equal one is not: the comparisons are strict, as in getLOD) */
    if (g->levels[g->level_count - 1].distance > distance)
        return -1;
    for (int k = 0; k < g->level_count; k++)
        if (g->levels[k].distance < distance)
            return k;
    return -1;
}

void mote_scene_choose_lod(const mote_scene *scene, mote_mesh *meshes, const mote_camera *camera)
{
    if (!scene || !meshes || !camera)
        return;
    for (int g = 0; g < scene->lod_count; g++)
        mote__lod_show(scene, meshes, g, mote_scene_lod_level(scene, g, meshes, camera));
}

void mote_scene_frame(const mote_scene *scene, float aspect, mote_frame_desc *frame)
{
    if (!frame)
        return;
    memset(frame, 0, sizeof *frame);
    if (!scene)
        return;
    float c[3], d[3], r2 = 0.0f;
    for (int k = 0; k < 3; k++) {
        c[k] = 0.5f * (scene->bounds_min[k] + scene->bounds_max[k]);
        d[k] = 0.5f * (scene->bounds_max[k] - scene->bounds_min[k]);
        r2 += d[k] * d[k];
    }
    float radius = sqrtf(r2);
    if (!(radius > 1e-6f) || !isfinite(radius))
        radius = 1.0f;
    if (scene->has_camera) {
        frame->camera = scene->camera;
        /* the horizontal field of view as the core's vertical one, as
         * Babylon.js projects it: tan(v / 2) = tan(h / 2) / aspect */
        if (scene->camera_fov_is_horizontal && aspect > 0.0f)
            frame->camera.fov = 2.0f * atanf(mote_tanf(0.5f * scene->camera.fov) / aspect);
    } else {
        /* front-top-right of the box, far enough that the bounding sphere
         * fits the narrower of the two fields of view, with a margin */
        const float fov = 0.8f;
        float dir[3] = {1.0f, 0.6f, -1.4f};
        float len = sqrtf(dir[0] * dir[0] + dir[1] * dir[1] + dir[2] * dir[2]);
        float half = 0.5f * fov;
        float s = mote_sinf(half);
        if (aspect > 0.0f && aspect < 1.0f) {
            /* sin(atan(t * aspect)) for the horizontal half angle */
            float th = mote_tanf(half) * aspect;
            float sh = th / sqrtf(1.0f + th * th);
            if (sh < s)
                s = sh;
        }
        float dist = radius / s * 1.1f;
        mote_camera *cam = &frame->camera;
        for (int k = 0; k < 3; k++) {
            cam->position[k] = c[k] + dir[k] / len * dist;
            cam->target[k] = c[k];
        }
        cam->fov = fov;
        cam->znear = dist - radius * 1.5f;
        if (cam->znear < dist * 0.01f)
            cam->znear = dist * 0.01f;
        cam->zfar = dist + radius * 2.0f;
    }
    int n = scene->light_count;
    if (n > MOTE_MAX_LIGHTS)
        n = MOTE_MAX_LIGHTS;
    for (int i = 0; i < n; i++)
        frame->lights[i] = scene->lights[i];
    frame->light_count = n;
    /* a file whose lights are all disabled is lit by none, as in Babylon.js */
    if (n == 0 && !scene->has_lights) {
        mote_light *l = &frame->lights[0];
        l->type = MOTE_LIGHT_POINT;
        memcpy(l->position, frame->camera.position, sizeof l->position);
        l->position[1] += radius;
        l->color[0] = l->color[1] = l->color[2] = 1.0f;
        l->intensity = 1.0f;
        frame->light_count = 1;
    }
    /* frame->ambient stays 0: the materials' emissive colours hold the
     * scene's ambient colour as Babylon.js adds it (mote__emissive) */
}
