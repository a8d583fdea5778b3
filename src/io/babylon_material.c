/*
 * babylon_material.c - a .babylon file's materials and multi-materials:
 * colours, textures, culling and lighting flags, resolved for each mesh.
 */
#include "babylon.h"

#include <stdio.h>
#include <string.h>

/* A material's texture: how it maps (scales, offsets, invertY, uv set,
 * wrap) and its image, a file named by "name", or a base64 data: URL in
 * "base64String" (Babylon.js's SceneSerializer; "name" is then no file)
 * or in "name" itself (mote__scene_texture). A texture without a name is
 * none. */
static mote_result mote__material_texture(mote__babylon *bl, const cJSON *tex, const char *at,
                                          mote__mat *mm)
{
    mote_material *m = &mm->material;
    MOTE__TRY(mote__json_object(bl->load, tex, at));
    const char *name, *embedded;
    MOTE__TRY(mote__json_string(bl->load, tex, "name", at, &name));
    MOTE__TRY(mote__json_string(bl->load, tex, "base64String", at, &embedded));
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
    MOTE__TRY(mote__json_number(bl->load, tex, "uScale", at, &m->u_scale));
    MOTE__TRY(mote__json_number(bl->load, tex, "vScale", at, &m->v_scale));
    MOTE__TRY(mote__json_number(bl->load, tex, "uOffset", at, &m->u_offset));
    MOTE__TRY(mote__json_number(bl->load, tex, "vOffset", at, &m->v_offset));
    if (mote__json_get(tex, "invertY")) {
        bool inv = true;
        MOTE__TRY(mote__json_flag(bl->load, tex, "invertY", at, &inv));
        mm->invert_y = inv;
    }
    /* which uv set the texture samples: uvs (0) or uvs2 (1); Babylon.js
     * has more (uvs3...), which mote does not read */
    uint32_t ci = 0;
    MOTE__TRY(mote__json_uint_member(bl->load, tex, "coordinatesIndex", at, 5, &ci));
    if (ci) {
        if (ci > 1)
            mote__warn(bl->load,
                       "%s.coordinatesIndex: %u: only uvs and uvs2 are read; uvs are used", at,
                       (unsigned)ci);
        mm->uv2 = ci == 1;
        bl->any_uv2 = bl->any_uv2 || mm->uv2;
    }
    static const char *const wrap_keys[2] = {"wrapU", "wrapV"};
    for (int k = 0; k < 2; k++) {
        const cJSON *w = mote__json_get(tex, wrap_keys[k]);
        mote_wrap mode = MOTE_WRAP_REPEAT;
        if (cJSON_IsBool(w)) {
            mode = cJSON_IsTrue(w) ? MOTE_WRAP_REPEAT : MOTE_WRAP_CLAMP;
        } else if (w) {
            char at2[176];
            snprintf(at2, sizeof at2, "%s.%s", at, wrap_keys[k]);
            uint32_t v;
            MOTE__TRY(mote__json_uint(bl->load, w, at2, 0, 2, &v));
            mode = v == 0 ? MOTE_WRAP_CLAMP : v == 1 ? MOTE_WRAP_REPEAT : MOTE_WRAP_MIRROR;
        }
        if (k == 0)
            m->wrap_u = mode;
        else
            m->wrap_v = mode;
    }
    return mote__scene_texture(bl->load, at, key, name, embedded, m);
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
static mote_result mote__emissive(mote__babylon *bl, const cJSON *m, const char *at, mote__mat *mm)
{
    float emissive[3] = {0, 0, 0}, ambient[3] = {0, 0, 0};
    const char *key = mote__json_get(m, "emissiveColor") && !mote__json_get(m, "emissive")
                          ? "emissiveColor"
                          : "emissive";
    MOTE__TRY(mote__babylon_color3(bl, m, key, at, emissive));
    MOTE__TRY(mote__babylon_color3(bl, m, "ambient", at, ambient));
    bool pbr_unlit = false;
    MOTE__TRY(mote__json_flag(bl->load, m, "unlit", at, &pbr_unlit));
    if (pbr_unlit) {
        mm->unlit = true;
        return MOTE_OK;
    }
    float c[3];
    for (int k = 0; k < 3; k++)
        c[k] = emissive[k] + ambient[k] * bl->load->scene->ambient[k];
    if (mm->unlit) {
        mote__set_color(&mm->material, c);
        return MOTE_OK;
    }
    mote__set_rgb(&mm->material.emissive, c);
    return MOTE_OK;
}

/* Transparency as Babylon.js's StandardMaterial (and PBR) decide it:
 * transparencyMode when written (0 opaque, 1 alpha test, 2 blend, 3
 * both), else blending when alpha < 1 (or an opacity texture, or the
 * diffuse texture's alpha with useAlphaFromDiffuseTexture), and else an
 * alpha test when the diffuse texture hasAlpha. tex is the diffuse texture's
 * JSON (NULL: none), at tex_at. */
static mote_result mote__transparency(mote__babylon *bl, const cJSON *m, const cJSON *tex, const char *at,
                                      const char *tex_at, mote__mat *mm)
{
    mote_material *mat = &mm->material;
    float alpha = 1.0f, cutoff = 0.4f;
    bool has_alpha = false, from_texture = false, from_albedo = false;
    MOTE__TRY(mote__json_number(bl->load, m, "alpha", at, &alpha));
    MOTE__TRY(mote__json_number(bl->load, m, "alphaCutOff", at, &cutoff));
    MOTE__TRY(mote__json_flag(bl->load, m, "useAlphaFromDiffuseTexture", at, &from_texture));
    MOTE__TRY(mote__json_flag(bl->load, m, "useAlphaFromAlbedoTexture", at, &from_albedo));
    MOTE__TRY(mote__json_flag(bl->load, m, "disableDepthWrite", at, &mm->no_depth_write));
    const bool textured = mat->texture != NULL;
    if (tex && textured)
        MOTE__TRY(mote__json_flag(bl->load, tex, "hasAlpha", tex_at, &has_alpha));
    from_texture = (from_texture || from_albedo) && has_alpha;
    const cJSON *opacity = mote__json_get(m, "opacityTexture");
    const cJSON *opacity_name = cJSON_IsObject(opacity) ? mote__json_get(opacity, "name") : NULL;
    const bool has_opacity = cJSON_IsString(opacity_name) && opacity_name->valuestring[0];
    /* Babylon.js turns the test off for a blended material
     * (Material._shouldTurnAlphaTestOn) unless transparencyMode says both */
    bool blend = alpha < 1.0f || has_opacity || from_texture, test = has_alpha && !blend;
    const cJSON *mode = mote__json_get(m, "transparencyMode");
    if (cJSON_IsNumber(mode)) {
        const int t = (int)mode->valuedouble;
        test = t == 1 || t == 3;
        blend = t == 2 || t == 3;
        from_texture = from_texture && t != 0;
    }
    /* RenderingGroup gives a pre-pass to blended meshes alone */
    MOTE__TRY(mote__json_flag(bl->load, m, "needDepthPrePass", at, &mm->depth_pre_pass));
    const cJSON *blend_mode = mote__json_get(m, "alphaMode");
    if (blend && cJSON_IsNumber(blend_mode) && blend_mode->valuedouble != 2) {
        if (blend_mode->valuedouble == 0)
            blend = false;        /* ALPHA_DISABLE */
        else
            mote__warn(bl->load, "%s.alphaMode: %g is drawn as 2 (ALPHA_COMBINE: src a + dst (1 - a))", at,
                       blend_mode->valuedouble);
    }
    mat->alpha_mode = test && blend ? MOTE_ALPHA_TEST_AND_BLEND
                    : test          ? MOTE_ALPHA_TEST
                    : blend         ? MOTE_ALPHA_BLEND
                                    : MOTE_ALPHA_OPAQUE;
    mat->alpha = alpha < 0.0f ? 0.0f : alpha > 1.0f ? 1.0f : alpha;
    mat->alpha_set = true;
    mat->use_texture_alpha = from_texture;
    mm->depth_pre_pass = mm->depth_pre_pass && blend;
    /* 0 is the core's "default": a cut-off of 0 cuts nothing anyway,
     * nor does one at or below the smallest alpha step */
    mat->alpha_cutoff = cutoff > 0.0f ? cutoff : 1e-6f;
    return MOTE_OK;
}

/* Highlights as Babylon.js adds them: a StandardMaterial's `specular`
 * (white when unsaid) and `specularPower` (64); a specular-glossiness
 * material's specularColor and glossiness; a metallic-roughness one
 * (PBRMaterial with metallic or roughness written, or
 * PBRMetallicRoughnessMaterial) approximated, docs/babylon.md: the
 * albedo x (1 - metallic) lit diffusely, highlights of colour
 * 0.04 (1 - metallic) + albedo metallic and power 2 / roughness^4 - 2.
 * Other PBR materials keep their albedo, without highlights. */
static mote_result mote__specular(mote__babylon *bl, const cJSON *m, const char *at, int kind, mote__mat *mm)
{
    mote_material *mat = &mm->material;
    float spec[3] = {1, 1, 1}, power = 64.0f;
    const cJSON *metal = mote__json_get(m, "metallic"), *rough = mote__json_get(m, "roughness");
    if (kind == 2 || (kind == 1 && (cJSON_IsNumber(metal) || cJSON_IsNumber(rough)))) {
        /* metallic unsaid: 0, not Babylon.js's 1, which without an
         * environment (mote draws none) leaves only the highlights */
        float metallic = 0.0f, roughness = 1.0f;
        MOTE__TRY(mote__json_number(bl->load, m, "metallic", at, &metallic));
        MOTE__TRY(mote__json_number(bl->load, m, "roughness", at, &roughness));
        mote__metallic_roughness(mat, metallic, roughness);
        return MOTE_OK;
    } else if (kind == 3) {
        float gloss = 1.0f;
        MOTE__TRY(mote__babylon_color3(bl, m, "specularColor", at, spec));
        MOTE__TRY(mote__json_number(bl->load, m, "glossiness", at, &gloss));
        const float r = 1.0f - (gloss < 0.0f ? 0.0f : gloss > 0.95f ? 0.95f : gloss);
        power = 2.0f / (r * r * r * r) - 2.0f;
    } else if (kind == 1) {
        return MOTE_OK;           /* PBRMaterial without metallic-roughness */
    } else {
        const char *key = mote__json_get(m, "specularColor") && !mote__json_get(m, "specular") ? "specularColor"
                                                                                                  : "specular";
        MOTE__TRY(mote__babylon_color3(bl, m, key, at, spec));
        MOTE__TRY(mote__json_number(bl->load, m, "specularPower", at, &power));
    }
    mote__set_rgb(&mat->specular, spec);
    mat->specular_power = power > 1.0f ? (power < 4096.0f ? power : 4096.0f) : 1.0f;
    return MOTE_OK;
}

/* emissiveTexture, opacityTexture and specularTexture as the material's
 * texture layers (mote_layer): each read as the diffuse texture is (its
 * own scale, offset and wrap), its `level` the layer's factor, an opacity
 * map's getAlphaFromRGB its luminance. Babylon.js's specular map takes
 * the place of the specular colour: that becomes white. A layer on
 * another uv set than the material's texture is drawn on the latter's,
 * and warned. */
static mote_result mote__material_layers(mote__babylon *bl, const cJSON *m, const char *at, mote__mat *mm)
{
    static const char *const keys[3] = {"emissiveTexture", "opacityTexture", "specularTexture"};
    static const mote_layer_role roles[3] = {MOTE_LAYER_EMISSIVE, MOTE_LAYER_OPACITY, MOTE_LAYER_SPECULAR};
    mote_material *mat = &mm->material;
    mote_layer *layers = NULL;
    int n = 0;
    for (int k = 0; k < 3; k++) {
        const cJSON *t = mote__json_get(m, keys[k]);
        if (!t)
            continue;
        char at2[96];
        snprintf(at2, sizeof at2, "%s.%s", at, keys[k]);
        mote__mat scratch;
        memset(&scratch, 0, sizeof scratch);
        MOTE__TRY(mote__material_texture(bl, t, at2, &scratch));
        const mote_material *sm = &scratch.material;
        if (!sm->texture)         /* no name, or missing and warned */
            continue;
        if (scratch.uv2 != mm->uv2)
            mote__warn(bl->load, "%s.coordinatesIndex: %s, drawn on %s as the material's texture", at2,
                       scratch.uv2 ? "uvs2" : "uvs", mm->uv2 ? "uvs2" : "uvs");
        if (!layers) {
            layers = mote__store_alloc(bl->load->keep, MOTE_MAX_LAYERS, sizeof *layers);
            if (!layers)
                return mote__oom(bl->load, at2);
        }
        mote_layer *l = &layers[n++];
        memset(l, 0, sizeof *l);
        l->role = roles[k];
        l->texture = sm->texture;
        l->wrap_u = sm->wrap_u;
        l->wrap_v = sm->wrap_v;
        l->u_scale = sm->u_scale;
        l->v_scale = sm->v_scale;
        l->u_offset = sm->u_offset;
        l->v_offset = sm->v_offset;
        float level = 1.0f;
        MOTE__TRY(mote__json_number(bl->load, t, "level", at2, &level));
        l->factor[0] = l->factor[1] = l->factor[2] = level > 0.0f ? level : 1e-6f;
        MOTE__TRY(mote__json_flag(bl->load, t, "getAlphaFromRGB", at2, &l->from_rgb));
        if (roles[k] == MOTE_LAYER_SPECULAR && !mm->unlit)
            mat->specular = (mote_rgba){255, 255, 255, 255};
    }
    mat->layers = layers;
    mat->layer_count = n;
    return MOTE_OK;
}

mote_result mote__babylon_materials(mote__babylon *bl)
{
    const cJSON *list;
    MOTE__TRY(mote__json_array(bl->load, bl->root, "materials", "", &list));
    size_t n = mote__json_length(list);
    MOTE__TRY(mote__check_count(bl->load, "materials", n, "materials", bl->load->lim.max_meshes));
    bl->mats = mote__store_alloc(&bl->load->tmp, n, sizeof *bl->mats);
    if (!bl->mats)
        return mote__oom(bl->load, "materials");
    /* a texture per material and its layers at most */
    MOTE__TRY(mote__texture_slots(bl->load, n * (1 + MOTE_MAX_LAYERS), "materials"));
    int i = 0;
    for (const cJSON *m = list ? list->child : NULL; m; m = m->next, i++) {
        char at[64];
        snprintf(at, sizeof at, "materials[%d]", i);
        MOTE__TRY(mote__json_object(bl->load, m, at));
        mote__mat *mm = &bl->mats[i];
        mm->invert_y = -1;
        MOTE__TRY(mote__json_string(bl->load, m, "id", at, &mm->id));
        if (!mm->id)
            MOTE__TRY(mote__json_string(bl->load, m, "name", at, &mm->id));
        if (!mm->id)
            return mote__fail(bl->load, MOTE_ERR_PARSE, "%s: expected an \"id\" string", at);
        MOTE__TRY(mote__babylon_number_text(bl, m, "uniqueId", at, &mm->unique_id));
        bl->mat_count = i + 1;
    }
    int dup, unused;
    bl->mat_map = mote__idmap_build(bl, &bl->mats[0].id, sizeof *bl->mats, bl->mat_count, &dup);
    bl->mat_unique_map = mote__idmap_build(bl, &bl->mats[0].unique_id, sizeof *bl->mats,
                                           bl->mat_count, &unused);
    if (!bl->mat_map || !bl->mat_unique_map)
        return mote__oom(bl->load, "materials");
    if (dup >= 0)
        mote__warn(bl->load, "materials[%d]: id \"%s\" is used before; the last one is kept", dup,
                   mote__quote(bl->mats[dup].id).s);
    i = 0;
    for (const cJSON *m = list ? list->child : NULL; m; m = m->next, i++) {
        char at[64];
        snprintf(at, sizeof at, "materials[%d]", i);
        mote__mat *mm = &bl->mats[i];
        /* shadowed by a later one of the same id, and not reachable by a
         * uniqueId: never used, so its texture is not loaded */
        if (mote__idmap_find_last(bl->mat_map, mm->id) != i && !mm->unique_id)
            continue;
        /* other types (the materials library's sky, grid, water..., node
         * materials) draw by rules of their own */
        const cJSON *type = mote__json_get(m, "customType");
        static const char *const read_types[4] = {
            "BABYLON.StandardMaterial", "BABYLON.PBRMaterial",
            "BABYLON.PBRMetallicRoughnessMaterial", "BABYLON.PBRSpecularGlossinessMaterial"};
        bool read_type = !cJSON_IsString(type);
        for (int k = 0; k < 4 && !read_type; k++)
            read_type = strcmp(type->valuestring, read_types[k]) == 0;
        if (!read_type)
            mote__warn(bl->load,
                       "%s: customType \"%s\" is not read; drawn as a standard material of "
                       "its diffuse colour",
                       at, mote__quote(type->valuestring).s);
        bool cull_back = true, cull_back_faces = true;
        MOTE__TRY(mote__json_flag(bl->load, m, "backFaceCulling", at, &cull_back));
        mm->two_sided = !cull_back;
        MOTE__TRY(mote__babylon_side(bl, m, "sideOrientation", at, &mm->side));
        MOTE__TRY(mote__json_flag(bl->load, m, "cullBackFaces", at, &cull_back_faces));
        mm->cull_front = !cull_back_faces;
        MOTE__TRY(mote__json_flag(bl->load, m, "disableLighting", at, &mm->unlit));
        bool fog = true;
        MOTE__TRY(mote__json_flag(bl->load, m, "fogEnabled", at, &fog));
        mm->no_fog = !fog;
        /* PBRMetallicRoughnessMaterial (the 3ds Max exporter's PBR
         * material) serialises its albedo as baseColor and baseTexture
         * and reads no other key for them; the other types write diffuse
         * (standard, specular-glossiness) or albedo (PBRMaterial) */
        const bool metal_rough =
            cJSON_IsString(type) && strcmp(type->valuestring, read_types[2]) == 0;
        static const char *const color_keys[5] = {"diffuse", "diffuseColor", "albedo",
                                                  "albedoColor", "baseColor"};
        for (int k = metal_rough ? 4 : 0; k < (metal_rough ? 5 : 4); k++) {
            float c[4] = {1, 1, 1, 1};
            if (!mote__json_get(m, color_keys[k]))
                continue;
            MOTE__TRY(mote__babylon_color3(bl, m, color_keys[k], at, c));
            mote__set_color(&mm->material, c);
            break;
        }
        MOTE__TRY(mote__emissive(bl, m, at, mm));
        /* 0 standard, 1 PBRMaterial, 2 metallic-roughness, 3 specular-glossiness */
        int kind = 0;
        for (int k = 1; k < 4; k++)
            kind = cJSON_IsString(type) && strcmp(type->valuestring, read_types[k]) == 0 ? k : kind;
        if (!mm->unlit)
            MOTE__TRY(mote__specular(bl, m, at, kind, mm));
        mm->max_lights = 4;
        MOTE__TRY(mote__json_uint_member(bl->load, m, "maxSimultaneousLights", at, 1024, &mm->max_lights));
        static const char *const tex_keys[3] = {"diffuseTexture", "albedoTexture", "baseTexture"};
        const cJSON *diffuse = NULL;
        char at2[96] = "";
        for (int k = metal_rough ? 2 : 0; k < (metal_rough ? 3 : 2); k++) {
            const cJSON *t = mote__json_get(m, tex_keys[k]);
            if (!t)
                continue;
            snprintf(at2, sizeof at2, "%s.%s", at, tex_keys[k]);
            MOTE__TRY(mote__material_texture(bl, t, at2, mm));
            diffuse = t;
            break;
        }
        MOTE__TRY(mote__transparency(bl, m, diffuse, at, at2, mm));
        MOTE__TRY(mote__material_layers(bl, m, at, mm));
    }
    return MOTE_OK;
}

mote_result mote__babylon_multi_materials(mote__babylon *bl)
{
    const cJSON *list;
    MOTE__TRY(mote__json_array(bl->load, bl->root, "multiMaterials", "", &list));
    size_t n = mote__json_length(list);
    MOTE__TRY(mote__check_count(bl->load, "multiMaterials", n, "entries",
                                bl->load->lim.max_meshes));
    bl->multis = mote__store_alloc(&bl->load->tmp, n, sizeof *bl->multis);
    if (!bl->multis)
        return mote__oom(bl->load, "multiMaterials");
    int i = 0;
    for (const cJSON *m = list ? list->child : NULL; m; m = m->next, i++) {
        char at[64];
        snprintf(at, sizeof at, "multiMaterials[%d]", i);
        MOTE__TRY(mote__json_object(bl->load, m, at));
        mote__multi *mm = &bl->multis[i];
        MOTE__TRY(mote__json_string(bl->load, m, "id", at, &mm->id));
        if (!mm->id)
            return mote__fail(bl->load, MOTE_ERR_PARSE, "%s: expected an \"id\" string", at);
        MOTE__TRY(mote__babylon_number_text(bl, m, "uniqueId", at, &mm->unique_id));
        /* the SceneSerializer writes the slots by uniqueId as well, and
         * Babylon.js then resolves them so (materials sharing an id, as
         * playgrounds name them, stay apart) */
        const cJSON *slots, *unique_slots;
        MOTE__TRY(mote__json_array(bl->load, m, "materials", at, &slots));
        MOTE__TRY(mote__json_array(bl->load, m, "materialsUniqueIds", at, &unique_slots));
        if (unique_slots)
            slots = unique_slots;
        size_t count = mote__json_length(slots);
        if (count > bl->load->lim.max_meshes)
            return mote__fail(bl->load, MOTE_ERR_LIMIT, "%s.materials: %zu slots, more than the "
                              "limit of %u", at, count, (unsigned)bl->load->lim.max_meshes);
        mm->slots = mote__store_alloc(&bl->load->tmp, count, sizeof *mm->slots);
        if (!mm->slots)
            return mote__oom(bl->load, at);
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
                MOTE__TRY(mote__babylon_number_value_text(bl, s, at2, &text));
                mm->slots[k] = mote__idmap_find_last(bl->mat_unique_map, text);
                if (mm->slots[k] < 0)
                    mote__warn(bl->load, "%s: %s is the uniqueId of no material", at2, text);
                continue;
            }
            if (!cJSON_IsString(s))
                return mote__fail(bl->load, MOTE_ERR_PARSE,
                                  "%s.materials[%d]: expected a material id, found %s", at,
                                  k, mote__json_type_name(s));
            mm->slots[k] = mote__idmap_find_last(bl->mat_map, s->valuestring);
            if (mm->slots[k] < 0)
                mote__warn(bl->load, "%s.materials[%d]: \"%s\" names no material", at, k,
                           mote__quote(s->valuestring).s);
        }
        bl->multi_count = i + 1;
    }
    int dup, unused;
    bl->multi_map = mote__idmap_build(bl, &bl->multis[0].id, sizeof *bl->multis,
                                      bl->multi_count, &dup);
    bl->multi_unique_map = mote__idmap_build(bl, &bl->multis[0].unique_id, sizeof *bl->multis,
                                             bl->multi_count, &unused);
    if (!bl->multi_map || !bl->multi_unique_map)
        return mote__oom(bl->load, "multiMaterials");
    if (dup >= 0)
        mote__warn(bl->load, "multiMaterials[%d]: id \"%s\" is used before; the last one is kept",
                   dup, mote__quote(bl->multis[dup].id).s);
    return MOTE_OK;
}

/* The material of a (sub-)mesh: a material, a multi-material slot, or NULL
 * for the default (white) one, with a warning when nothing is named.
 * materialUniqueId comes first, as in Babylon.js (materials re-exported from
 * glTF often share an id); when it matches nothing, materialId is tried.
 * Either resolves to the last holder, as getLastMaterialById does. */
const mote__mat *mote__babylon_resolve_material(mote__babylon *bl, const mote__node *nd,
                                                uint32_t material_index)
{
    int m = -1, mm = -1;
    if (nd->material_unique_id) {
        m = mote__idmap_find_last(bl->mat_unique_map, nd->material_unique_id);
        if (m < 0)
            mm = mote__idmap_find_last(bl->multi_unique_map, nd->material_unique_id);
    }
    if (m < 0 && mm < 0 && nd->material_id) {
        m = mote__idmap_find_last(bl->mat_map, nd->material_id);
        if (m < 0)
            mm = mote__idmap_find_last(bl->multi_map, nd->material_id);
    }
    if (m >= 0)
        return &bl->mats[m];
    if (mm < 0) {
        if (nd->material_id)
            mote__warn(bl->load, "%s.materialId: \"%s\" names no material", nd->where,
                       mote__quote(nd->material_id).s);
        else if (nd->material_unique_id)
            mote__warn(bl->load, "%s.materialUniqueId: %s is the uniqueId of no material",
                       nd->where, nd->material_unique_id);
        return NULL;
    }
    const mote__multi *multi = &bl->multis[mm];
    if (material_index >= (uint32_t)multi->slot_count) {
        mote__warn(bl->load, "%s: materialIndex %u is past the %d materials of \"%s\"", nd->where,
                   (unsigned)material_index, multi->slot_count, mote__quote(multi->id).s);
        return NULL;
    }
    int slot = multi->slots[material_index];
    return slot >= 0 ? &bl->mats[slot] : NULL;
}
