/*
 * gltf_material.c - a glTF file's materials as mote draws them: base
 * colour (factor and texture), emissive colour, culling, unlit, texture
 * transforms, and the images and samplers their textures name. Each
 * material is read when a primitive first uses it, each image decoded
 * once.
 */
#include "gltf.h"

#include <math.h>
#include <stdio.h>
#include <string.h>

/* A linear 0..1 channel as an sRGB byte: glTF's factors and vertex colours
 * are linear, its colour textures sRGB, and mote multiplies bytes as they
 * are, so factors are encoded as the textures are (a product of powers is
 * the power of the product: factor x texture comes out right). */
uint8_t mote__gltf_srgb_byte(float c)
{
    if (!(c > 0.0f))
        return 0;
    if (c >= 1.0f)
        return 255;
    double s = c <= 0.0031308f ? 12.92 * c : 1.055 * pow((double)c, 1.0 / 2.4) - 0.055;
    return (uint8_t)(s * 255.0 + 0.5);
}

mote_result mote__gltf_materials(mote__gltf *gl)
{
    /* the file's materials, then the default one (white, one-sided, lit) */
    gl->mats = mote__store_alloc(&gl->load->tmp, (size_t)gl->mat_count + 1, sizeof *gl->mats);
    gl->mat_state = mote__store_alloc(&gl->load->tmp, (size_t)gl->mat_count + 1, 1);
    gl->image_texture = mote__store_alloc(&gl->load->tmp, (size_t)gl->image_count + 1,
                                          sizeof *gl->image_texture);
    if (!gl->mats || !gl->mat_state || !gl->image_texture)
        return mote__oom(gl->load, "materials");
    for (int i = 0; i < gl->image_count; i++)
        gl->image_texture[i] = -2;
    gl->mat_state[gl->mat_count] = 1;
    /* one scene texture per image at most */
    return mote__texture_slots(gl->load, (size_t)gl->image_count, "images");
}

/* images[index] decoded (once) into the scene's textures; *out the
 * scene texture index, -1 when it could not be loaded and that is a
 * warning (limits.missing_texture_is_warning) or there is no folder. */
static mote_result mote__gltf_image(mote__gltf *gl, int index, int *out)
{
    if (gl->image_texture[index] != -2) {
        *out = gl->image_texture[index];
        return MOTE_OK;
    }
    const cJSON *img;
    MOTE__TRY(mote__gltf_item(gl, "images", index, &img));
    char at[48];
    snprintf(at, sizeof at, "images[%d]", index);
    const char *uri;
    int view = -1;
    MOTE__TRY(mote__json_string(gl->load, img, "uri", at, &uri));
    MOTE__TRY(mote__gltf_index(gl, img, "bufferView", at, gl->view_count, "buffer view", &view));
    mote_material m;
    memset(&m, 0, sizeof m);
    if (uri) {
        const char *embedded = mote__io_is_data_url(uri) ? uri : NULL;
        MOTE__TRY(mote__scene_texture(gl->load, at, "uri", uri, embedded, &m));
    } else if (view >= 0) {
        const unsigned char *data;
        size_t size;
        MOTE__TRY(mote__gltf_view_bytes(gl, view, at, &data, &size));
        MOTE__TRY(mote__scene_texture_bytes(gl->load, at, "bufferView", data, size, &m));
    } else {
        return mote__fail(gl->load, MOTE_ERR_PARSE, "%s: neither \"uri\" nor \"bufferView\"",
                          at);
    }
    *out = gl->image_texture[index] = m.texture ? (int)(m.texture - gl->load->scene->textures)
                                                : -1;
    return MOTE_OK;
}

/* samplers[index]'s wrap modes into m (its filters are the draw's:
 * mote_draw_desc.filter). */
static mote_result mote__gltf_sampler(mote__gltf *gl, int index, mote_material *m)
{
    const cJSON *s;
    MOTE__TRY(mote__gltf_item(gl, "samplers", index, &s));
    char at[48];
    snprintf(at, sizeof at, "samplers[%d]", index);
    static const char *const keys[2] = {"wrapS", "wrapT"};
    for (int k = 0; k < 2; k++) {
        uint32_t w = 10497;
        MOTE__TRY(mote__json_uint_member(gl->load, s, keys[k], at, 65535, &w));
        mote_wrap mode = w == 33071 ? MOTE_WRAP_CLAMP : w == 33648 ? MOTE_WRAP_MIRROR
                       : w == 10497 ? MOTE_WRAP_REPEAT : MOTE_WRAP_COUNT;
        if (mode == MOTE_WRAP_COUNT)
            return mote__fail(gl->load, MOTE_ERR_RANGE, "%s.%s: %u, expected 33071 (clamp), "
                              "33648 (mirror) or 10497 (repeat)", at, keys[k], (unsigned)w);
        if (k == 0)
            m->wrap_u = mode;
        else
            m->wrap_v = mode;
    }
    return MOTE_OK;
}

/* KHR_texture_transform of a texture info: uv' = T R S uv, as a 2x3
 * column-major matrix; its texCoord, when given, overrides the info's. */
static mote_result mote__gltf_uv_transform(mote__gltf *gl, const cJSON *info, const char *at,
                                           mote__gltf_mat *mm)
{
    const cJSON *x = mote__json_get(mote__json_get(info, "extensions"), "KHR_texture_transform");
    if (!x)
        return MOTE_OK;
    char at2[192];
    snprintf(at2, sizeof at2, "%s.extensions.KHR_texture_transform", at);
    MOTE__TRY(mote__json_object(gl->load, x, at2));
    float offset[2] = {0, 0}, scale[2] = {1, 1}, rotation = 0;
    MOTE__TRY(mote__json_floats(gl->load, x, "offset", at2, 2, 0, offset));
    MOTE__TRY(mote__json_floats(gl->load, x, "scale", at2, 2, 0, scale));
    MOTE__TRY(mote__json_number(gl->load, x, "rotation", at2, &rotation));
    uint32_t tc = (uint32_t)mm->tex_coord;
    MOTE__TRY(mote__json_uint_member(gl->load, x, "texCoord", at2, 65535, &tc));
    mm->tex_coord = (int)tc;
    double c = cos((double)rotation), s = sin((double)rotation);
    float *t = mm->uv_transform;
    t[0] = (float)(c * scale[0]);
    t[1] = (float)(-s * scale[0]);
    t[2] = (float)(s * scale[1]);
    t[3] = (float)(c * scale[1]);
    t[4] = offset[0];
    t[5] = offset[1];
    mm->has_uv_transform = true;
    return MOTE_OK;
}

/* A texture info (the base colour one): its texture's image and
 * sampler, its uv set and transform. */
static mote_result mote__gltf_texture_info(mote__gltf *gl, const cJSON *info, const char *at,
                                           mote__gltf_mat *mm)
{
    MOTE__TRY(mote__json_object(gl->load, info, at));
    int tex = -1;
    MOTE__TRY(mote__gltf_index(gl, info, "index", at, gl->texture_count, "texture", &tex));
    if (tex < 0)
        return mote__fail(gl->load, MOTE_ERR_PARSE, "%s: missing \"index\"", at);
    uint32_t tc = 0;
    MOTE__TRY(mote__json_uint_member(gl->load, info, "texCoord", at, 65535, &tc));
    mm->tex_coord = (int)tc;
    MOTE__TRY(mote__gltf_uv_transform(gl, info, at, mm));
    const cJSON *t;
    MOTE__TRY(mote__gltf_item(gl, "textures", tex, &t));
    char tat[48];
    snprintf(tat, sizeof tat, "textures[%d]", tex);
    int source = -1, sampler = -1;
    MOTE__TRY(mote__gltf_index(gl, t, "source", tat, gl->image_count, "image", &source));
    MOTE__TRY(mote__gltf_index(gl, t, "sampler", tat, gl->sampler_count, "sampler", &sampler));
    mote_material *m = &mm->material;
    m->wrap_u = m->wrap_v = MOTE_WRAP_REPEAT;
    if (sampler >= 0)
        MOTE__TRY(mote__gltf_sampler(gl, sampler, m));
    if (source < 0) {
        /* only an extension's image (KTX2, WebP), which is not read */
        mote__warn(gl->load, "%s: no \"source\" image mote reads (drawn untextured)", tat);
        return MOTE_OK;
    }
    int scene_tex = -1;
    MOTE__TRY(mote__gltf_image(gl, source, &scene_tex));
    if (scene_tex >= 0)
        m->texture = &gl->load->scene->textures[scene_tex];
    return MOTE_OK;
}

/* The emissive colour: emissiveFactor x KHR_materials_emissive_strength.
 * An emissive texture cannot be drawn (mote adds a colour, not a
 * texture's), and its factor alone would light the whole surface, so
 * neither is drawn then. */
static mote_result mote__gltf_emissive(mote__gltf *gl, const cJSON *mat, const char *at,
                                       mote__gltf_mat *mm)
{
    float e[3] = {0, 0, 0}, strength = 1.0f;
    MOTE__TRY(mote__json_floats(gl->load, mat, "emissiveFactor", at, 3, 0, e));
    const cJSON *x = mote__json_get(mote__json_get(mat, "extensions"),
                                    "KHR_materials_emissive_strength");
    if (x) {
        char at2[112];
        snprintf(at2, sizeof at2, "%s.extensions.KHR_materials_emissive_strength", at);
        MOTE__TRY(mote__json_object(gl->load, x, at2));
        MOTE__TRY(mote__json_number(gl->load, x, "emissiveStrength", at2, &strength));
    }
    if (mote__json_get(mat, "emissiveTexture")) {
        mote__warn(gl->load, "%s.emissiveTexture: not drawn (mote adds no texture's light to "
                   "a material), nor its emissiveFactor", at);
        return MOTE_OK;
    }
    mm->material.emissive.r = mote__gltf_srgb_byte(e[0] * strength);
    mm->material.emissive.g = mote__gltf_srgb_byte(e[1] * strength);
    mm->material.emissive.b = mote__gltf_srgb_byte(e[2] * strength);
    return MOTE_OK;
}

/* alphaMode: transparency is not drawn yet; said once per mode. */
static mote_result mote__gltf_alpha(mote__gltf *gl, const cJSON *mat, const char *at)
{
    const char *mode;
    MOTE__TRY(mote__json_string(gl->load, mat, "alphaMode", at, &mode));
    float cutoff = 0.5f;
    MOTE__TRY(mote__json_number(gl->load, mat, "alphaCutoff", at, &cutoff));
    if (!mode || strcmp(mode, "OPAQUE") == 0)
        return MOTE_OK;
    if (strcmp(mode, "MASK") == 0) {
        mote__warn(gl->load, "alphaMode MASK: drawn opaque (mote does not test alpha yet)");
        return MOTE_OK;
    }
    if (strcmp(mode, "BLEND") == 0) {
        mote__warn(gl->load, "alphaMode BLEND: drawn opaque (mote does not blend yet)");
        return MOTE_OK;
    }
    return mote__fail(gl->load, MOTE_ERR_PARSE, "%s.alphaMode: \"%s\", expected \"OPAQUE\", "
                      "\"MASK\" or \"BLEND\"", at, mote__quote(mode).s);
}

/* materials[index] read into gl->mats[index]. */
static mote_result mote__gltf_material_read(mote__gltf *gl, int index)
{
    const cJSON *mat;
    MOTE__TRY(mote__gltf_item(gl, "materials", index, &mat));
    char at[48];
    snprintf(at, sizeof at, "materials[%d]", index);
    mote__gltf_mat *mm = &gl->mats[index];
    const cJSON *pbr = mote__json_get(mat, "pbrMetallicRoughness");
    char pat[80];
    snprintf(pat, sizeof pat, "%s.pbrMetallicRoughness", at);
    if (pbr)
        MOTE__TRY(mote__json_object(gl->load, pbr, pat));
    float base[4] = {1, 1, 1, 1};
    MOTE__TRY(mote__json_floats(gl->load, pbr, "baseColorFactor", pat, 4, 0, base));
    mote_material *m = &mm->material;
    m->color = (mote_rgba){mote__gltf_srgb_byte(base[0]), mote__gltf_srgb_byte(base[1]),
                           mote__gltf_srgb_byte(base[2]), 255};
    m->color_set = true;
    const cJSON *info = mote__json_get(pbr, "baseColorTexture");
    if (info) {
        char tat[112];
        snprintf(tat, sizeof tat, "%s.baseColorTexture", pat);
        MOTE__TRY(mote__gltf_texture_info(gl, info, tat, mm));
    }
    MOTE__TRY(mote__gltf_emissive(gl, mat, at, mm));
    MOTE__TRY(mote__gltf_alpha(gl, mat, at));
    MOTE__TRY(mote__json_flag(gl->load, mat, "doubleSided", at, &mm->two_sided));
    mm->unlit = mote__json_get(mote__json_get(mat, "extensions"), "KHR_materials_unlit") != NULL;
    return MOTE_OK;
}

mote_result mote__gltf_material(mote__gltf *gl, int index, const mote__gltf_mat **out)
{
    int i = index < 0 ? gl->mat_count : index;
    if (!gl->mat_state[i]) {
        MOTE__TRY(mote__gltf_material_read(gl, i));
        gl->mat_state[i] = 1;
    }
    *out = &gl->mats[i];
    return MOTE_OK;
}
