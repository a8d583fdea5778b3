/*
 * babylon.c - .babylon scenes (Babylon.js's JSON format) to a mote_scene:
 * the load in order, and what its parts share. What is read, and how, is
 * docs/babylon.md; the parts are listed in babylon.h.
 */
#include "babylon.h"

#include <stdio.h>
#include <stdlib.h>
#include <string.h>

/* The scene's ambientColor and clearColor. */
static mote_result mote__scene_colors(mote__babylon *bl)
{
    mote_scene *sc = bl->load->scene;
    MOTE__TRY(mote__babylon_color3(bl, bl->root, "ambientColor", "scene", sc->ambient));
    float c[4] = {0, 0, 0, 1};
    MOTE__TRY(mote__json_floats(bl->load, bl->root, "clearColor", "scene", 3, 4, c));
    sc->clear_color.r = mote__unit_byte(c[0]);
    sc->clear_color.g = mote__unit_byte(c[1]);
    sc->clear_color.b = mote__unit_byte(c[2]);
    sc->clear_color.a = 255;
    /* fog: Babylon.js's fogMode 1 exp, 2 exp2, 3 linear */
    uint32_t mode = 0;
    MOTE__TRY(mote__json_uint_member(bl->load, bl->root, "fogMode", "scene", 3, &mode));
    static const mote_fog_mode modes[4] = {MOTE_FOG_NONE, MOTE_FOG_EXP, MOTE_FOG_EXP2, MOTE_FOG_LINEAR};
    sc->fog.mode = modes[mode];
    sc->fog.color[0] = sc->fog.color[1] = sc->fog.color[2] = 0.2f;   /* Babylon.js's defaults */
    sc->fog.density = 0.1f;
    sc->fog.end = 1000.0f;
    MOTE__TRY(mote__babylon_color3(bl, bl->root, "fogColor", "scene", sc->fog.color));
    MOTE__TRY(mote__json_number(bl->load, bl->root, "fogDensity", "scene", &sc->fog.density));
    MOTE__TRY(mote__json_number(bl->load, bl->root, "fogStart", "scene", &sc->fog.start));
    MOTE__TRY(mote__json_number(bl->load, bl->root, "fogEnd", "scene", &sc->fog.end));
    return MOTE_OK;
}

mote_result mote__babylon_load(mote__loader *ld, const cJSON *root)
{
    mote__babylon babylon;
    memset(&babylon, 0, sizeof babylon);
    mote__babylon *bl = &babylon;
    bl->load = ld;
    bl->root = root;
    mote_scene *sc = ld->scene;
    /* a right-handed scene is loaded mirrored (mote__mirror_point) */
    MOTE__TRY(mote__json_flag(ld, root, "useRightHandedSystem", "scene", &bl->right_handed));
    sc->mirrored_z = bl->right_handed;
    /* the ambient colour first: an unlit material's colour takes it in */
    MOTE__TRY(mote__scene_colors(bl));
    MOTE__TRY(mote__babylon_materials(bl));
    MOTE__TRY(mote__babylon_multi_materials(bl));
    MOTE__TRY(mote__babylon_nodes(bl));
    MOTE__TRY(mote__babylon_camera_light_nodes(bl));
    MOTE__TRY(mote__babylon_parents(bl));
    MOTE__TRY(mote__babylon_build_meshes(bl));
    MOTE__TRY(mote__babylon_lod_groups(bl));
    MOTE__TRY(mote__babylon_scene_bounds(bl));
    MOTE__TRY(mote__babylon_camera(bl));
    MOTE__TRY(mote__babylon_lights(bl));
    /* the levels of detail Babylon.js draws for the scene's camera */
    if (sc->has_camera)
        mote_scene_choose_lod(sc, sc->meshes, &sc->camera);
    return MOTE_OK;
}

/* ---- values as Babylon.js writes them ---------------------------------- */

/* key -> a Color3 (absent or null keeps out): 3 numbers, or 4, whose last
 * is not read, as Color3.FromArray reads the first three (old 3ds Max
 * exporters write [r, g, b, a] for every colour). */
mote_result mote__babylon_color3(mote__babylon *bl, const cJSON *obj, const char *key,
                                 const char *where, float out[3])
{
    return mote__json_floats(bl->load, obj, key, where, 3, 4, out);
}

/* key -> a side orientation (MOTE__SIDE_...): a number, 0 or not (Babylon.js
 * tells only Material.ClockWiseSideOrientation, 0, from the rest); absent
 * or null keeps *out. */
mote_result mote__babylon_side(mote__babylon *bl, const cJSON *obj, const char *key,
                               const char *where, unsigned char *out)
{
    const cJSON *v = mote__json_get(obj, key);
    float unused;
    /* a finite number, or absent */
    MOTE__TRY(mote__json_number(bl->load, obj, key, where, &unused));
    if (v)
        *out = v->valuedouble == 0.0 ? MOTE__SIDE_CW : MOTE__SIDE_OTHER;
    return MOTE_OK;
}

/* key -> the id a node refers to, or NULL: absent, null or "" (old 3ds
 * Max exports write "" for no material, Cinema 4D's for no parent, and
 * Babylon.js looks nothing up for it); anything but a string is an error. */
mote_result mote__babylon_id_ref(mote__babylon *bl, const cJSON *obj, const char *key,
                                 const char *where, const char **out)
{
    MOTE__TRY(mote__json_string(bl->load, obj, key, where, out));
    if (*out && !(*out)[0])
        *out = NULL;
    return MOTE_OK;
}

/* v as text ("%.17g", in the temporary store): how uniqueIds are compared */
mote_result mote__babylon_double_text(mote__babylon *bl, double v, const char *at, const char **out)
{
    char text[32];
    int n = snprintf(text, sizeof text, "%.17g", v);
    char *copy = mote__store_alloc(&bl->load->tmp, (size_t)n + 1, 1);
    if (!copy)
        return mote__oom(bl->load, at);
    memcpy(copy, text, (size_t)n + 1);
    *out = copy;
    return MOTE_OK;
}

/* A finite number v (at names it) as mote__babylon_double_text. */
mote_result mote__babylon_number_value_text(mote__babylon *bl, const cJSON *v, const char *at,
                                            const char **out)
{
    float unused;
    MOTE__TRY(mote__json_float(bl->load, v, at, &unused));
    return mote__babylon_double_text(bl, v->valuedouble, at, out);
}

/* key -> a number's text ("%.17g", so equal numbers give equal text) or
 * NULL (absent); anything else is an error. For numeric ids. */
mote_result mote__babylon_number_text(mote__babylon *bl, const cJSON *obj, const char *key,
                                      const char *where, const char **out)
{
    const cJSON *v = mote__json_get(obj, key);
    *out = NULL;
    if (!v)
        return MOTE_OK;
    char at[160];
    snprintf(at, sizeof at, "%s.%s", where, key);
    return mote__babylon_number_value_text(bl, v, at, out);
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
mote__idmap *mote__idmap_build(mote__babylon *bl, const char *const *ids, size_t stride, int n,
                               int *dup_index)
{
    mote__idmap *head = mote__store_alloc(&bl->load->tmp, (size_t)n + 1, sizeof *head);
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

int mote__idmap_find(const mote__idmap *m, const char *id)
{
    return mote__idmap_lookup(m, id, false);
}

/* The last of equal ids, as Babylon.js resolves materials
 * (getLastMaterialById) and parents (getLastEntryById). */
int mote__idmap_find_last(const mote__idmap *m, const char *id)
{
    return mote__idmap_lookup(m, id, true);
}
