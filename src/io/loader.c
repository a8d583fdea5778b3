/*
 * loader.c - the scene being built, as every loader builds it: allocations
 * recorded for release together, messages that start with the file's
 * name, warnings given once each, and the scene freed whole on failure.
 */
#include "loader.h"

#include <math.h>
#include <stdio.h>
#include <string.h>

void mote__store_release(mote__store *s)
{
    for (size_t i = 0; i < s->count; i++)
        mote__io_free(s->ptrs[i]);
    mote__io_free(s->ptrs);
    s->ptrs = NULL;
    s->count = s->cap = 0;
}

void *mote__store_alloc(mote__store *s, size_t count, size_t size)
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

mote_result mote__fail(mote__loader *ld, mote_result code, const char *fmt, ...)
{
    char what[512];
    va_list ap;
    va_start(ap, fmt);
    vsnprintf(what, sizeof what, fmt, ap);
    va_end(ap);
    return mote__io_error(ld->msg, ld->msg_size, code, "%s: %s", ld->name, what);
}

mote_result mote__oom(mote__loader *ld, const char *at)
{
    return mote__fail(ld, MOTE_ERR_OUT_OF_MEMORY, "%s: out of memory", at);
}

mote_result mote__check_count(mote__loader *ld, const char *at, size_t count,
                              const char *what, size_t limit)
{
    if (count > limit || count > (size_t)INT32_MAX)
        return mote__fail(ld, MOTE_ERR_LIMIT, "%s: %zu %s, more than the limit of %zu", at,
                          count, what, limit);
    return MOTE_OK;
}

/* scene.warning from ld->warnings: each distinct warning once, "(xN)"
 * when it was given N times, so that a warning repeated per sub-mesh does
 * not crowd out the ones after it; what does not fit is counted at the
 * end. */
static void mote__show_warnings(mote__loader *ld)
{
    const mote__warnings *ws = ld->warnings;
    char *w = ld->scene->warning;
    const size_t cap = sizeof ld->scene->warning, tail = 24; /* "; 99 more warnings" */
    size_t used = 0;
    int shown = 0;
    w[0] = '\0';
    for (; shown < ws->n; shown++) {
        char count[24] = "";
        if (ws->count[shown] > 1)
            snprintf(count, sizeof count, " (x%u)", ws->count[shown]);
        size_t need = (used ? 2 : 0) + strlen(ws->text[shown]) + strlen(count);
        if (used && used + need + tail >= cap)
            break;                /* the first is shown, cut short if it must be */
        snprintf(w + used, cap - used, "%s%s%s", used ? "; " : "", ws->text[shown], count);
        used = strlen(w);
    }
    unsigned more = ws->dropped + (unsigned)(ws->n - shown);
    if (more)
        snprintf(w + used, cap - used, "; %u more warning%s", more, more > 1 ? "s" : "");
}

/* Slots of the lookup: a power of 2, at least twice the warnings kept. */
#define MOTE__WARNING_SLOTS (2 * MOTE__MAX_WARNINGS)

static size_t mote__text_hash(const char *s)
{
    size_t h = 2166136261u;       /* FNV-1a */
    for (; *s; s++)
        h = (h ^ (unsigned char)*s) * 16777619u;
    return h;
}

/* The list at the first warning; NULL when out of memory. */
static mote__warnings *mote__warning_list(mote__loader *ld)
{
    if (ld->warnings)
        return ld->warnings;
    mote__warnings *ws = mote__store_alloc(ld->keep, 1, sizeof *ws);
    if (!ws)
        return NULL;
    ws->text = mote__store_alloc(ld->keep, MOTE__MAX_WARNINGS, sizeof *ws->text);
    ws->count = mote__store_alloc(ld->keep, MOTE__MAX_WARNINGS, sizeof *ws->count);
    ws->slots = mote__store_alloc(&ld->tmp, MOTE__WARNING_SLOTS, sizeof *ws->slots);
    if (!ws->text || !ws->count || !ws->slots)
        return NULL;              /* what was allocated goes with the scene */
    ld->warnings = ws;
    ld->scene->warnings_ = ws;
    return ws;
}

void mote__warn(mote__loader *ld, const char *fmt, ...)
{
    char text[256];
    va_list ap;
    va_start(ap, fmt);
    vsnprintf(text, sizeof text, fmt, ap);
    va_end(ap);
    mote__warnings *ws = mote__warning_list(ld);
    if (!ws) {
        ld->warning_lost = true;  /* out of memory: mote__loader_end says so */
        return;
    }
    size_t slot = mote__text_hash(text) & (MOTE__WARNING_SLOTS - 1);
    while (ws->slots[slot] && strcmp(ws->text[ws->slots[slot] - 1], text) != 0)
        slot = (slot + 1) & (MOTE__WARNING_SLOTS - 1);
    if (ws->slots[slot]) {
        ws->count[ws->slots[slot] - 1]++;
    } else {
        size_t len = strlen(text) + 1;
        char *copy = ws->n < MOTE__MAX_WARNINGS ? mote__store_alloc(ld->keep, len, 1) : NULL;
        if (!copy) {
            ld->warning_lost |= ws->n < MOTE__MAX_WARNINGS;
            ws->dropped++;
        } else {
            memcpy(copy, text, len);
            ws->text[ws->n] = copy;
            ws->count[ws->n] = 1;
            ws->slots[slot] = ++ws->n;
        }
    }
    mote__show_warnings(ld);
}

int mote_scene_warning_count(const mote_scene *scene, unsigned *dropped)
{
    const mote__warnings *ws = scene ? scene->warnings_ : NULL;
    if (dropped)
        *dropped = ws ? ws->dropped : 0;
    return ws ? ws->n : 0;
}

const char *mote_scene_warning(const mote_scene *scene, int i, unsigned *repeats)
{
    const mote__warnings *ws = scene ? scene->warnings_ : NULL;
    if (!ws || i < 0 || i >= ws->n)
        return NULL;
    if (repeats)
        *repeats = ws->count[i];
    return ws->text[i];
}

mote__quoted mote__quote(const char *s)
{
    mote__quoted q;
    mote__io_clean_name(q.s, sizeof q.s, s ? s : "");
    return q;
}

uint8_t mote__unit_byte(float c)
{
    if (!(c > 0.0f))
        return 0;
    if (c >= 1.0f)
        return 255;
    return (uint8_t)(c * 255.0f + 0.5f);
}

void mote__scene_bounds_add(mote_scene *sc, const mote_mesh *m, bool *any)
{
    float w[16];
    mote_mesh_world_matrix(m, w);
    for (uint32_t v = 0; v < m->vertex_count; v++) {
        const float *p = m->vertices[v].position;
        float q[3];
        for (int k = 0; k < 3; k++)
            q[k] = w[k] * p[0] + w[4 + k] * p[1] + w[8 + k] * p[2] + w[12 + k];
        if (!isfinite(q[0]) || !isfinite(q[1]) || !isfinite(q[2]))
            continue;
        for (int k = 0; k < 3; k++) {
            if (!*any || q[k] < sc->bounds_min[k]) sc->bounds_min[k] = q[k];
            if (!*any || q[k] > sc->bounds_max[k]) sc->bounds_max[k] = q[k];
        }
        *any = true;
    }
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

mote_result mote__loader_begin(mote__loader *ld, const char *name, const char *base_dir,
                               const mote_limits *limits, size_t size, mote_scene *out,
                               char *message, size_t message_size)
{
    memset(ld, 0, sizeof *ld);
    mote__io_clean_name(ld->name, sizeof ld->name, name ? name : "scene");
    ld->base_dir = base_dir;
    ld->lim = mote__io_limits(limits);
    ld->msg = message;
    ld->msg_size = message_size;
    ld->scene = out;
    memset(out, 0, sizeof *out);
    if (size > ld->lim.max_file_bytes)
        return mote__fail(ld, MOTE_ERR_LIMIT, "%zu bytes, more than the limit of %zu", size,
                          ld->lim.max_file_bytes);
    ld->keep = mote__io_calloc(1, sizeof *ld->keep);
    if (!ld->keep)
        return mote__oom(ld, "scene");
    out->storage_ = ld->keep;
    out->files_ = mote__store_alloc(ld->keep, 1, sizeof(mote__scene_files));
    if (!out->files_)
        return mote__oom(ld, "scene");
    return MOTE_OK;
}

/* The triangles of every mesh the scene holds (instances, thin
 * instances, levels of detail and hidden meshes each count: any of them
 * may be drawn in a frame) against limits.max_triangles, which bounds
 * the time a frame takes as max_meshes and the vertex limits do not. */
static mote_result mote__check_triangles(mote__loader *ld)
{
    const mote_scene *sc = ld->scene;
    uint64_t total = 0;
    for (int i = 0; i < sc->mesh_count; i++)
        total += sc->meshes[i].index_count / 3;
    if (total > ld->lim.max_triangles)
        return mote__fail(ld, MOTE_ERR_LIMIT, "%llu triangles in its %d meshes (instances "
                          "count), more than the limit of %llu (max_triangles)",
                          (unsigned long long)total, sc->mesh_count,
                          (unsigned long long)ld->lim.max_triangles);
    return MOTE_OK;
}

mote_result mote__loader_end(mote__loader *ld, mote_result r)
{
    if (r == MOTE_OK)
        r = mote__check_triangles(ld);
    if (r == MOTE_OK && ld->warning_lost)
        r = mote__oom(ld, "a warning");
    if (ld->warnings)
        ld->warnings->slots = NULL;   /* a temporary: no warnings come after the load */
    mote__store_release(&ld->tmp);
    if (r != MOTE_OK)
        mote_scene_free(ld->scene);
    return r;
}

void mote__metallic_roughness(mote_material *mat, float metallic, float roughness)
{
    metallic = metallic > 0.0f ? (metallic < 1.0f ? metallic : 1.0f) : 0.0f;     /* NaN: 0 */
    roughness = roughness > 0.05f ? (roughness < 1.0f ? roughness : 1.0f) : 0.05f;
    for (int k = 0; k < 3; k++) {
        const float albedo = mat->color_set ? (float)(&mat->color.r)[k] / 255.0f : 1.0f;
        (&mat->specular.r)[k] = mote__unit_byte(0.04f * (1.0f - metallic) + albedo * metallic);
        (&mat->color.r)[k] = mote__unit_byte(albedo * (1.0f - metallic));
    }
    mat->color.a = mat->specular.a = 255;
    mat->color_set = true;
    const float a2 = roughness * roughness * roughness * roughness;
    const float power = 2.0f / a2 - 2.0f;
    mat->specular_power = power > 1.0f ? (power < 4096.0f ? power : 4096.0f) : 1.0f;
}
