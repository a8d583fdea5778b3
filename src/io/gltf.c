/*
 * gltf.c - glTF 2.0 files (.gltf JSON, .glb binary) to a mote_scene: the
 * containers, the version, the extensions, and the load in order. What
 * is read, and how, is docs/gltf.md; the parts are listed in gltf.h.
 */
#include "gltf.h"

#include <stdio.h>
#include <string.h>

/* ---- references -------------------------------------------------------- */

mote_result mote__gltf_index(mote__gltf *gl, const cJSON *obj, const char *key,
                             const char *where, int n, const char *what, int *out)
{
    const cJSON *v = mote__json_get(obj, key);
    if (!v)
        return MOTE_OK;
    char at[160];
    snprintf(at, sizeof at, "%s%s%s", where, where[0] ? "." : "", key);
    uint32_t i;
    MOTE__TRY(mote__json_uint(gl->load, v, at, 0, 4294967295.0, &i));
    if (i >= (uint32_t)n)
        return mote__fail(gl->load, MOTE_ERR_RANGE, "%s: %u names no %s (there are %d)", at,
                          (unsigned)i, what, n);
    *out = (int)i;
    return MOTE_OK;
}

mote_result mote__gltf_item(mote__gltf *gl, const char *key, int n, const cJSON **out,
                            char *path)
{
    const mote__gltf_list *l = NULL;
    for (int i = 0; i < gl->list_count && !l; i++)
        if (strcmp(gl->lists[i].key, key) == 0)
            l = &gl->lists[i];
    char own[MOTE__GLTF_AT];
    char *at = path ? path : own;
    snprintf(at, MOTE__GLTF_AT, "%s[%d]", key, n);
    if (!l || n < 0 || n >= l->count)
        return mote__fail(gl->load, MOTE_ERR_RANGE, "%s: missing", at);
    MOTE__TRY(mote__json_object(gl->load, l->items[n], at));
    *out = l->items[n];
    return MOTE_OK;
}

mote_result mote__gltf_list_add(mote__gltf *gl, const char *key, const cJSON *array, int *n)
{
    size_t len = mote__json_length(array);
    MOTE__TRY(mote__check_count(gl->load, key, len, key, gl->load->lim.max_meshes));
    if (gl->list_count >= MOTE__GLTF_LISTS)
        return mote__fail(gl->load, MOTE_ERR_LIMIT, "%s: more than %d lists", key,
                          MOTE__GLTF_LISTS);
    mote__gltf_list *l = &gl->lists[gl->list_count];
    l->items = mote__store_alloc(&gl->load->tmp, len, sizeof *l->items);
    if (!l->items)
        return mote__oom(gl->load, key);
    l->key = key;
    l->count = (int)len;
    int i = 0;
    for (const cJSON *e = array ? array->child : NULL; e; e = e->next)
        l->items[i++] = e;
    gl->list_count++;
    *n = (int)len;
    return MOTE_OK;
}

mote_result mote__gltf_count(mote__gltf *gl, const char *key, int *n)
{
    const cJSON *list;
    MOTE__TRY(mote__json_array(gl->load, gl->root, key, "", &list));
    return mote__gltf_list_add(gl, key, list, n);
}

bool mote__gltf_uses(const mote__gltf *gl, const char *name)
{
    const cJSON *used = mote__json_get(gl->root, "extensionsUsed");
    for (const cJSON *e = cJSON_IsArray(used) ? used->child : NULL; e; e = e->next)
        if (cJSON_IsString(e) && strcmp(e->valuestring, name) == 0)
            return true;
    return false;
}

/* ---- version and extensions -------------------------------------------- */

/* asset.version "2.x" (and minVersion, when given, at most "2.0"); glTF
 * 1.0 files, whose layout differs throughout, are refused as such. */
static mote_result mote__gltf_version(mote__gltf *gl)
{
    const cJSON *asset = mote__json_get(gl->root, "asset");
    if (!asset)
        return mote__fail(gl->load, MOTE_ERR_PARSE, "asset: missing (every glTF file has "
                          "asset.version)");
    MOTE__TRY(mote__json_object(gl->load, asset, "asset"));
    const cJSON *v = mote__json_get(asset, "version");
    /* glTF 1.0 exporters wrote the version as a number, too */
    if (cJSON_IsNumber(v) && v->valuedouble < 2.0)
        return mote__fail(gl->load, MOTE_ERR_UNSUPPORTED, "asset.version: %g: a glTF 1.0 file, "
                          "which mote does not read (it reads glTF 2.0)", v->valuedouble);
    const char *version;
    MOTE__TRY(mote__json_string(gl->load, asset, "version", "asset", &version));
    if (!version)
        return mote__fail(gl->load, MOTE_ERR_PARSE, "asset.version: missing");
    if (version[0] == '1' || version[0] == '0')
        return mote__fail(gl->load, MOTE_ERR_UNSUPPORTED, "asset.version: \"%s\": a glTF 1.0 "
                          "file, which mote does not read (it reads glTF 2.0)",
                          mote__quote(version).s);
    if (version[0] != '2' || version[1] != '.')
        return mote__fail(gl->load, MOTE_ERR_UNSUPPORTED, "asset.version: \"%s\": mote reads "
                          "glTF 2.0", mote__quote(version).s);
    const char *min;
    MOTE__TRY(mote__json_string(gl->load, asset, "minVersion", "asset", &min));
    if (min && strcmp(min, "2.0") != 0)
        return mote__fail(gl->load, MOTE_ERR_UNSUPPORTED, "asset.minVersion: \"%s\": mote "
                          "reads glTF 2.0", mote__quote(min).s);
    return MOTE_OK;
}

/* Extensions mote reads, and those whose data it cannot draw without. */
static const char *const mote__gltf_read_exts[] = {
    "KHR_mesh_quantization", "KHR_materials_unlit", "KHR_texture_transform",
    "KHR_materials_emissive_strength", "KHR_lights_punctual",
};
static const struct {
    const char *name, *what;
} mote__gltf_unreadable[] = {
    {"KHR_draco_mesh_compression", "Draco-compressed geometry"},
    {"EXT_meshopt_compression", "meshoptimizer-compressed buffers"},
    {"KHR_meshopt_compression", "meshoptimizer-compressed buffers"},
    {"KHR_texture_basisu", "KTX2/Basis Universal textures"},
    {"EXT_texture_webp", "WebP textures"},
    {"EXT_texture_avif", "AVIF textures"},
};

static bool mote__gltf_reads(const char *name)
{
    for (size_t i = 0; i < sizeof mote__gltf_read_exts / sizeof mote__gltf_read_exts[0]; i++)
        if (strcmp(name, mote__gltf_read_exts[i]) == 0)
            return true;
    return false;
}

/* extensionsRequired: one mote does not read is an error naming it;
 * extensionsUsed: one it does not read is a warning (what it adds is not
 * drawn; the rest of the file is). */
static mote_result mote__gltf_extensions(mote__gltf *gl)
{
    static const char *const keys[2] = {"extensionsRequired", "extensionsUsed"};
    for (int k = 0; k < 2; k++) {
        const cJSON *list;
        MOTE__TRY(mote__json_array(gl->load, gl->root, keys[k], "", &list));
        int i = 0;
        for (const cJSON *e = list ? list->child : NULL; e; e = e->next, i++) {
            if (!cJSON_IsString(e))
                return mote__fail(gl->load, MOTE_ERR_PARSE, "%s[%d]: expected a string, "
                                  "found %s", keys[k], i, mote__json_type_name(e));
            const char *name = e->valuestring;
            if (mote__gltf_reads(name))
                continue;
            const char *what = NULL;
            for (size_t u = 0; u < sizeof mote__gltf_unreadable / sizeof mote__gltf_unreadable[0];
                 u++)
                if (strcmp(name, mote__gltf_unreadable[u].name) == 0)
                    what = mote__gltf_unreadable[u].what;
            if (k == 0 && what)
                return mote__fail(gl->load, MOTE_ERR_UNSUPPORTED, "extensionsRequired[%d]: "
                                  "\"%s\" (%s), which mote does not read", i, name, what);
            if (k == 0)
                return mote__fail(gl->load, MOTE_ERR_UNSUPPORTED, "extensionsRequired[%d]: "
                                  "\"%s\", an extension mote does not read", i,
                                  mote__quote(name).s);
            mote__warn(gl->load, "extensionsUsed: \"%s\" is not read%s", mote__quote(name).s,
                       what ? " (its fallback is drawn)" : "");
        }
    }
    gl->quantized = mote__gltf_uses(gl, "KHR_mesh_quantization");
    gl->lights_ext = mote__gltf_uses(gl, "KHR_lights_punctual");
    return MOTE_OK;
}

/* ---- the load ---------------------------------------------------------- */

/* Animations are not played (skins and morph targets are said where a
 * node or primitive of the scene has them). */
static void mote__gltf_not_drawn(mote__gltf *gl)
{
    if (mote__json_length(mote__json_get(gl->root, "animations")))
        mote__warn(gl->load, "animations: not played; the scene is drawn at rest");
}

/* The parts in order: references are checked where they are followed. */
static mote_result mote__gltf_parts(mote__gltf *gl)
{
    mote_scene *sc = gl->load->scene;
    /* glTF is right-handed: loaded mirrored in z, as mote's core is left-handed */
    sc->mirrored_z = true;
    sc->clear_color = (mote_rgba){0, 0, 0, 255};
    MOTE__TRY(mote__gltf_version(gl));
    MOTE__TRY(mote__gltf_extensions(gl));
    MOTE__TRY(mote__gltf_count(gl, "buffers", &gl->buffer_count));
    MOTE__TRY(mote__gltf_count(gl, "bufferViews", &gl->view_count));
    MOTE__TRY(mote__gltf_count(gl, "accessors", &gl->accessor_count));
    MOTE__TRY(mote__gltf_count(gl, "images", &gl->image_count));
    MOTE__TRY(mote__gltf_count(gl, "textures", &gl->texture_count));
    MOTE__TRY(mote__gltf_count(gl, "samplers", &gl->sampler_count));
    MOTE__TRY(mote__gltf_count(gl, "materials", &gl->mat_count));
    MOTE__TRY(mote__gltf_count(gl, "meshes", &gl->mesh_count));
    MOTE__TRY(mote__gltf_count(gl, "nodes", &gl->node_count));
    MOTE__TRY(mote__gltf_count(gl, "cameras", &gl->camera_count));
    MOTE__TRY(mote__gltf_light_defs(gl));
    MOTE__TRY(mote__gltf_buffers(gl));
    MOTE__TRY(mote__gltf_materials(gl));
    MOTE__TRY(mote__gltf_scene_nodes(gl));
    MOTE__TRY(mote__gltf_build_meshes(gl));
    MOTE__TRY(mote__gltf_scene_bounds(gl));
    MOTE__TRY(mote__gltf_camera(gl));
    MOTE__TRY(mote__gltf_lights(gl));
    mote__gltf_not_drawn(gl);
    return MOTE_OK;
}

/* The glTF JSON root (and a .glb's BIN chunk, or NULL) into ld->scene. */
static mote_result mote__gltf_load(mote__loader *ld, const cJSON *root, const unsigned char *bin,
                                   size_t bin_size)
{
    mote__gltf gltf;
    memset(&gltf, 0, sizeof gltf);
    gltf.load = ld;
    gltf.root = root;
    gltf.bin = bin;
    gltf.bin_size = bin_size;
    gltf.scene = -1;
    mote_result r = mote__gltf_parts(&gltf);
    mote__gltf_free_buffers(&gltf);
    return r;
}

mote_result mote__gltf_load_json(mote__loader *ld, const cJSON *root)
{
    return mote__gltf_load(ld, root, NULL, 0);
}

/* ---- binary glTF ------------------------------------------------------- */

static uint32_t mote__le32(const unsigned char *p)
{
    return (uint32_t)p[0] | (uint32_t)p[1] << 8 | (uint32_t)p[2] << 16 | (uint32_t)p[3] << 24;
}

enum { MOTE__GLB_JSON = 0x4E4F534Au, MOTE__GLB_BIN = 0x004E4942u };

/* A .glb: the 12-byte header (magic, version 2, length), then chunks of
 * (length, type, data), each 4-byte aligned: JSON first, then at most one
 * BIN; chunks of other types are skipped, as the specification says.
 * Errors name the byte offset. */
mote_result mote__gltf_load_glb(mote__loader *ld, const unsigned char *d, size_t size)
{
    if (size < 12)
        return mote__fail(ld, MOTE_ERR_PARSE, "GLB byte 0: a %zu-byte file, shorter than the "
                          "12-byte GLB header", size);
    uint32_t version = mote__le32(d + 4), length = mote__le32(d + 8);
    if (version == 1)
        return mote__fail(ld, MOTE_ERR_UNSUPPORTED, "GLB byte 4: version 1: a glTF 1.0 binary "
                          "file, which mote does not read (it reads glTF 2.0)");
    if (version != 2)
        return mote__fail(ld, MOTE_ERR_UNSUPPORTED, "GLB byte 4: version %u, expected 2",
                          (unsigned)version);
    if (length != size)
        return mote__fail(ld, MOTE_ERR_PARSE, "GLB byte 8: length %u, but the file has %zu "
                          "bytes", (unsigned)length, size);
    const unsigned char *json = NULL, *bin = NULL;
    size_t json_size = 0, bin_size = 0;
    size_t at = 12;
    for (int chunk = 0; at < size; chunk++) {
        if (size - at < 8)
            return mote__fail(ld, MOTE_ERR_PARSE, "GLB byte %zu: chunk %d: %zu bytes left, "
                              "shorter than a chunk header (8)", at, chunk, size - at);
        uint32_t clen = mote__le32(d + at), type = mote__le32(d + at + 4);
        if (clen > size - at - 8)
            return mote__fail(ld, MOTE_ERR_PARSE, "GLB byte %zu: chunk %d: length %u, past "
                              "the end of the file (%zu bytes left)", at, chunk, (unsigned)clen,
                              size - at - 8);
        if (clen % 4)
            return mote__fail(ld, MOTE_ERR_PARSE, "GLB byte %zu: chunk %d: length %u is not a "
                              "multiple of 4 (chunks are padded to 4 bytes)", at, chunk,
                              (unsigned)clen);
        if (chunk == 0 && type != MOTE__GLB_JSON)
            return mote__fail(ld, MOTE_ERR_PARSE, "GLB byte %zu: the first chunk is of type "
                              "0x%08x, expected JSON (0x%08x)", at + 4, (unsigned)type,
                              (unsigned)MOTE__GLB_JSON);
        if (chunk == 0) {
            json = d + at + 8;
            json_size = clen;
        } else if (type == MOTE__GLB_JSON) {
            return mote__fail(ld, MOTE_ERR_PARSE, "GLB byte %zu: chunk %d: a second JSON chunk",
                              at, chunk);
        } else if (type == MOTE__GLB_BIN) {
            if (bin)
                return mote__fail(ld, MOTE_ERR_PARSE, "GLB byte %zu: chunk %d: a second BIN "
                                  "chunk", at, chunk);
            if (chunk != 1)
                return mote__fail(ld, MOTE_ERR_PARSE, "GLB byte %zu: chunk %d: the BIN chunk "
                                  "must be the second", at, chunk);
            bin = d + at + 8;
            bin_size = clen;
        }
        at += 8 + (size_t)clen;
    }
    if (!json)
        return mote__fail(ld, MOTE_ERR_PARSE, "GLB byte 12: no JSON chunk");
    /* the JSON chunk is padded with spaces, which the parser skips */
    cJSON *root;
    MOTE__TRY(mote__json_parse(ld, (const char *)json, json_size, &root));
    mote_result r = mote__gltf_load(ld, root, bin, bin_size);
    cJSON_Delete(root);
    return r;
}
