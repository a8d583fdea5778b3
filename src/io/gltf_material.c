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
    char at[MOTE__GLTF_AT];
    MOTE__TRY(mote__gltf_item(gl, "images", index, &img, at));
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

/* samplers[index]'s wrap modes into m, and the mip mode its minFilter
 * asks for into *mip: between levels, nearest (9984, 9985) per-pixel
 * levels, linear (9986, 9987) trilinear; else none said. Within a level
 * the filter is the draw's (mote_draw_desc.filter). */
static mote_result mote__gltf_sampler(mote__gltf *gl, int index, mote_material *m, mote_mip *mip)
{
    const cJSON *s;
    char at[MOTE__GLTF_AT];
    MOTE__TRY(mote__gltf_item(gl, "samplers", index, &s, at));
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
    uint32_t min = 0;
    MOTE__TRY(mote__json_uint_member(gl->load, s, "minFilter", at, 65535, &min));
    *mip = min == 9984 || min == 9985 ? MOTE_MIP_PIXEL : min == 9986 || min == 9987 ? MOTE_MIP_TRILINEAR
                                                                                    : MOTE_MIP_DEFAULT;
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
    char tat[MOTE__GLTF_AT];
    MOTE__TRY(mote__gltf_item(gl, "textures", tex, &t, tat));
    int source = -1, sampler = -1;
    MOTE__TRY(mote__gltf_index(gl, t, "source", tat, gl->image_count, "image", &source));
    MOTE__TRY(mote__gltf_index(gl, t, "sampler", tat, gl->sampler_count, "sampler", &sampler));
    mote_material *m = &mm->material;
    m->wrap_u = m->wrap_v = MOTE_WRAP_REPEAT;
    if (sampler >= 0)
        MOTE__TRY(mote__gltf_sampler(gl, sampler, m, &mm->mip));
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

/* The emissive colour: emissiveFactor x KHR_materials_emissive_strength,
 * or with an emissiveTexture an emissive texture layer (mote_layer) whose
 * factor that is (sRGB-encoded as the texture is; above 1, by the power
 * 1/2.2). The layer samples the base colour texture's uv set and
 * transform (without a base colour texture, the mesh's uvs follow the
 * emissive texture's); other ones are warned. */
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
    const cJSON *info = mote__json_get(mat, "emissiveTexture");
    if (!info) {
        mm->material.emissive.r = mote__gltf_srgb_byte(e[0] * strength);
        mm->material.emissive.g = mote__gltf_srgb_byte(e[1] * strength);
        mm->material.emissive.b = mote__gltf_srgb_byte(e[2] * strength);
        return MOTE_OK;
    }
    char tat[112];
    snprintf(tat, sizeof tat, "%s.emissiveTexture", at);
    mote__gltf_mat glow;
    memset(&glow, 0, sizeof glow);
    MOTE__TRY(mote__gltf_texture_info(gl, info, tat, &glow));
    if (!glow.material.texture || (e[0] == 0.0f && e[1] == 0.0f && e[2] == 0.0f))
        return MOTE_OK;           /* unread, or black: no light */
    if (!mm->material.texture) {  /* the mesh's uvs follow this texture */
        mm->tex_coord = glow.tex_coord;
        mm->has_uv_transform = glow.has_uv_transform;
        memcpy(mm->uv_transform, glow.uv_transform, sizeof mm->uv_transform);
    } else if (glow.tex_coord != mm->tex_coord || glow.has_uv_transform != mm->has_uv_transform
               || memcmp(glow.uv_transform, mm->uv_transform, sizeof mm->uv_transform) != 0) {
        mote__warn(gl->load, "%s: its uv set or KHR_texture_transform is not the base colour texture's, "
                   "whose is drawn", tat);
    }
    mote_layer *l = mote__store_alloc(gl->load->keep, 1, sizeof *l);
    if (!l)
        return mote__oom(gl->load, tat);
    memset(l, 0, sizeof *l);
    l->role = MOTE_LAYER_EMISSIVE;
    l->texture = glow.material.texture;
    l->wrap_u = glow.material.wrap_u;
    l->wrap_v = glow.material.wrap_v;
    for (int k = 0; k < 3; k++) {
        const float v = e[k] * strength;
        l->factor[k] = v <= 1.0f ? (float)mote__gltf_srgb_byte(v) / 255.0f : (float)pow((double)v, 1.0 / 2.2);
        l->factor[k] = l->factor[k] > 0.0f ? l->factor[k] : 1e-6f;   /* all 0 would read as white */
    }
    mm->material.layers = l;
    mm->material.layer_count = 1;
    return MOTE_OK;
}

/* alphaMode onto mote's alpha: MASK an alpha test at alphaCutoff, BLEND a
 * blend by the base colour's alpha a (x the texture's). The core tests
 * the texel's alpha alone and cuts nothing untextured, so a divides the
 * cut-off (texel x a < c is texel < c / a, and above 1 every texel is
 * cut), and an untextured MASK material under its cut-off is cut whole
 * (mm->cut_away: its meshes are hidden). A vertex colour's alpha is not
 * drawn. */
static mote_result mote__gltf_alpha(mote__gltf *gl, const cJSON *mat, const char *at, float a,
                                    mote__gltf_mat *mm)
{
    const char *mode;
    MOTE__TRY(mote__json_string(gl->load, mat, "alphaMode", at, &mode));
    float cutoff = 0.5f;
    MOTE__TRY(mote__json_number(gl->load, mat, "alphaCutoff", at, &cutoff));
    mote_material *m = &mm->material;
    a = a > 0.0f ? (a < 1.0f ? a : 1.0f) : 0.0f;      /* NaN: 0 */
    if (!mode || strcmp(mode, "OPAQUE") == 0) {
        m->alpha_mode = MOTE_ALPHA_OPAQUE;
        return MOTE_OK;
    }
    if (strcmp(mode, "MASK") == 0) {
        m->alpha_mode = MOTE_ALPHA_TEST;
        /* 0 is the core's default cut-off (0.4): the smallest one cuts nothing either */
        float c = a > 0.0f ? cutoff / a : 2.0f;
        m->alpha_cutoff = c > 1e-6f ? c : 1e-6f;
        mm->cut_away = !m->texture && a < cutoff;
        return MOTE_OK;
    }
    if (strcmp(mode, "BLEND") == 0) {
        m->alpha_mode = MOTE_ALPHA_BLEND;
        m->alpha = a;
        m->alpha_set = true;
        m->use_texture_alpha = m->texture != NULL;
        return MOTE_OK;
    }
    return mote__fail(gl->load, MOTE_ERR_PARSE, "%s.alphaMode: \"%s\", expected \"OPAQUE\", "
                      "\"MASK\" or \"BLEND\"", at, mote__quote(mode).s);
}

/* materials[index] read into gl->mats[index]. */
static mote_result mote__gltf_material_read(mote__gltf *gl, int index)
{
    const cJSON *mat;
    char at[MOTE__GLTF_AT];
    MOTE__TRY(mote__gltf_item(gl, "materials", index, &mat, at));
    mote__gltf_mat *mm = &gl->mats[index];
    const cJSON *pbr = mote__json_get(mat, "pbrMetallicRoughness");
    char pat[MOTE__GLTF_AT + 24];
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
    MOTE__TRY(mote__gltf_alpha(gl, mat, at, base[3], mm));
    MOTE__TRY(mote__json_flag(gl->load, mat, "doubleSided", at, &mm->two_sided));
    mm->unlit = mote__json_get(mote__json_get(mat, "extensions"), "KHR_materials_unlit") != NULL;
    if (!mm->unlit) {
        /* as the .babylon loader's PBR materials: metallic 0 unless
         * metallicFactor is written without a metallicRoughnessTexture
         * (which scales the texture's, unread), as without an environment
         * a metal shows only its highlights */
        float metallic = 0.0f, roughness = 1.0f;
        if (!mote__json_get(pbr, "metallicRoughnessTexture"))
            MOTE__TRY(mote__json_number(gl->load, pbr, "metallicFactor", pat, &metallic));
        MOTE__TRY(mote__json_number(gl->load, pbr, "roughnessFactor", pat, &roughness));
        mote__metallic_roughness(m, metallic, roughness);
    }
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
