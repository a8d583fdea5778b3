/*
 * gltf_camera.c - a glTF scene's view (the first camera in the scene,
 * perspective or orthographic) and its KHR_lights_punctual lights, placed
 * by their nodes: a camera and a light look down their node's -z, up its
 * +y (in the mirrored scene, +z).
 */
#include "gltf.h"

#include <math.h>
#include <stdio.h>
#include <string.h>

/* p = w (x, y, z, point ? 1 : 0); a direction is then normalised. */
static void mote__gltf_place(const float w[16], float x, float y, float z, bool point, float p[3])
{
    double q[3], len = 0.0;
    for (int k = 0; k < 3; k++) {
        q[k] = (double)w[k] * x + (double)w[4 + k] * y + (double)w[8 + k] * z +
               (point ? (double)w[12 + k] : 0.0);
        len += q[k] * q[k];
    }
    len = point || !(len > 0.0) ? 1.0 : sqrt(len);
    for (int k = 0; k < 3; k++)
        p[k] = (float)(q[k] / len);
}

/* obj[key] as a number > lo (strictly) that must be there. */
static mote_result mote__gltf_positive(mote__gltf *gl, const cJSON *obj, const char *key,
                                       const char *at, bool required, float *out)
{
    if (!mote__json_get(obj, key)) {
        if (required)
            return mote__fail(gl->load, MOTE_ERR_PARSE, "%s: missing \"%s\"", at, key);
        return MOTE_OK;
    }
    MOTE__TRY(mote__json_number(gl->load, obj, key, at, out));
    if (!(*out > 0.0f))
        return mote__fail(gl->load, MOTE_ERR_RANGE, "%s.%s: %g, expected a number above 0", at,
                          key, *out);
    return MOTE_OK;
}

mote_result mote__gltf_camera(mote__gltf *gl)
{
    if (gl->camera_node < 0)
        return MOTE_OK;           /* mote_scene_frame frames the scene */
    const mote__gltf_node *nd = &gl->nodes[gl->camera_node];
    const cJSON *cam;
    char at[MOTE__GLTF_AT];
    MOTE__TRY(mote__gltf_item(gl, "cameras", nd->camera, &cam, at));
    const char *type;
    MOTE__TRY(mote__json_string(gl->load, cam, "type", at, &type));
    bool ortho = type && strcmp(type, "orthographic") == 0;
    if (!type || (!ortho && strcmp(type, "perspective") != 0))
        return mote__fail(gl->load, MOTE_ERR_PARSE, "%s.type: expected \"perspective\" or "
                          "\"orthographic\"", at);
    const cJSON *p = mote__json_get(cam, type);
    char pat[MOTE__GLTF_AT + 16];
    snprintf(pat, sizeof pat, "%s.%s", at, type);
    if (!p)
        return mote__fail(gl->load, MOTE_ERR_PARSE, "%s: missing", pat);
    MOTE__TRY(mote__json_object(gl->load, p, pat));
    mote_scene *sc = gl->load->scene;
    mote_camera *c = &sc->camera;
    memset(c, 0, sizeof *c);
    float w[16];
    mote__gltf_node_world(gl, gl->camera_node, w);
    float forward[3];
    mote__gltf_place(w, 0, 0, 0, true, c->position);
    mote__gltf_place(w, 0, 0, 1, false, forward);
    mote__gltf_place(w, 0, 1, 0, false, c->up);
    for (int k = 0; k < 3; k++)
        c->target[k] = c->position[k] + forward[k];
    if (ortho) {
        float xmag = 0, ymag = 0;
        c->projection = MOTE_PROJECTION_ORTHOGRAPHIC;
        MOTE__TRY(mote__gltf_positive(gl, p, "xmag", pat, true, &xmag));
        MOTE__TRY(mote__gltf_positive(gl, p, "ymag", pat, true, &ymag));
        c->ortho[0] = -xmag, c->ortho[1] = xmag, c->ortho[2] = -ymag, c->ortho[3] = ymag;
        if (!mote__json_get(p, "znear"))
            return mote__fail(gl->load, MOTE_ERR_PARSE, "%s: missing \"znear\"", pat);
        MOTE__TRY(mote__json_number(gl->load, p, "znear", pat, &c->znear));
        MOTE__TRY(mote__gltf_positive(gl, p, "zfar", pat, true, &c->zfar));
    } else {
        MOTE__TRY(mote__gltf_positive(gl, p, "yfov", pat, true, &c->fov));
        if (!(c->fov < 3.14159f))
            return mote__fail(gl->load, MOTE_ERR_RANGE, "%s.yfov: %g is not in (0, pi)", pat,
                              c->fov);
        MOTE__TRY(mote__gltf_positive(gl, p, "znear", pat, true, &c->znear));
        MOTE__TRY(mote__gltf_positive(gl, p, "zfar", pat, false, &c->zfar));
        if (c->zfar == 0.0f) {
            /* an infinite projection: far enough for the whole scene */
            double d2 = 0.0, r2 = 0.0;
            for (int k = 0; k < 3; k++) {
                double mid = 0.5 * ((double)sc->bounds_min[k] + sc->bounds_max[k]);
                double half = 0.5 * ((double)sc->bounds_max[k] - sc->bounds_min[k]);
                d2 += (mid - c->position[k]) * (mid - c->position[k]);
                r2 += half * half;
            }
            double far = 2.0 * (sqrt(d2) + sqrt(r2));
            c->zfar = (float)(far > 2.0 * c->znear ? far : 1000.0 * c->znear);
        }
    }
    if (!(c->zfar > c->znear))
        return mote__fail(gl->load, MOTE_ERR_RANGE, "%s: znear %g is not below zfar %g", pat,
                          c->znear, c->zfar);
    sc->has_camera = true;
    return MOTE_OK;
}

/* The root's KHR_lights_punctual.lights, which nodes name. */
mote_result mote__gltf_light_defs(mote__gltf *gl)
{
    const cJSON *ext = mote__json_get(mote__json_get(gl->root, "extensions"),
                                      "KHR_lights_punctual");
    if (!ext)
        return MOTE_OK;
    MOTE__TRY(mote__json_object(gl->load, ext, "extensions.KHR_lights_punctual"));
    MOTE__TRY(mote__json_array(gl->load, ext, "lights", "extensions.KHR_lights_punctual",
                               &gl->light_defs));
    return mote__gltf_list_add(gl, "extensions.KHR_lights_punctual.lights", gl->light_defs,
                               &gl->light_def_count);
}

/* A light of nodes[i] into *L; *dark: it adds nothing. */
static mote_result mote__gltf_light(mote__gltf *gl, int i, mote_light *L, bool *dark)
{
    const mote__gltf_node *nd = &gl->nodes[i];
    const cJSON *def;
    char at[MOTE__GLTF_AT];
    MOTE__TRY(mote__gltf_item(gl, "extensions.KHR_lights_punctual.lights", nd->light, &def,
                              at));
    const char *type;
    MOTE__TRY(mote__json_string(gl->load, def, "type", at, &type));
    memset(L, 0, sizeof *L);
    if (type && strcmp(type, "directional") == 0)
        L->type = MOTE_LIGHT_DIRECTIONAL;
    else if (type && strcmp(type, "point") == 0)
        L->type = MOTE_LIGHT_POINT;
    else if (type && strcmp(type, "spot") == 0)
        L->type = MOTE_LIGHT_SPOT;
    else
        return mote__fail(gl->load, MOTE_ERR_PARSE, "%s.type: expected \"directional\", "
                          "\"point\" or \"spot\"", at);
    float color[3] = {1, 1, 1}, intensity = 1.0f;
    MOTE__TRY(mote__json_floats(gl->load, def, "color", at, 3, 0, color));
    MOTE__TRY(mote__json_number(gl->load, def, "intensity", at, &intensity));
    MOTE__TRY(mote__gltf_positive(gl, def, "range", at, false, &L->range));
    float w[16];
    mote__gltf_node_world(gl, i, w);
    mote__gltf_place(w, 0, 0, 0, true, L->position);
    mote__gltf_place(w, 0, 0, 1, false, L->direction);
    if (L->type == MOTE_LIGHT_SPOT) {
        const cJSON *spot = mote__json_get(def, "spot");
        float inner = 0.0f, outer = 0.7853982f;
        MOTE__TRY(mote__json_number(gl->load, spot, "innerConeAngle", at, &inner));
        MOTE__TRY(mote__json_number(gl->load, spot, "outerConeAngle", at, &outer));
        if (!(inner >= 0.0f && inner < outer && outer <= 1.5707964f))
            return mote__fail(gl->load, MOTE_ERR_RANGE, "%s.spot: innerConeAngle %g and "
                              "outerConeAngle %g, expected 0 <= inner < outer <= pi/2", at, inner,
                              outer);
        /* mote's cone: cos^exponent inside, nothing outside; the exponent
         * halves the light midway between glTF's inner and outer cones */
        L->spot_angle = 2.0f * outer;
        double mid = cos(0.5 * ((double)inner + outer));
        L->spot_exponent = mid < 1.0 ? (float)(log(0.5) / log(mid)) : 0.0f;
    }
    if (L->type != MOTE_LIGHT_DIRECTIONAL) {
        /* candela, and mote's lights have no inverse-square falloff: the
         * scene's centre gets the light the file means */
        mote_scene *sc = gl->load->scene;
        double d2 = 0.0;
        for (int k = 0; k < 3; k++) {
            double mid = 0.5 * ((double)sc->bounds_min[k] + sc->bounds_max[k]) - L->position[k];
            d2 += mid * mid;
        }
        intensity = (float)(intensity / (d2 > 1e-6 ? d2 : 1e-6));
    }
    memcpy(L->color, color, sizeof color);
    L->intensity = intensity;
    *dark = !(intensity > 0.0f) || !(color[0] > 0.0f || color[1] > 0.0f || color[2] > 0.0f);
    return MOTE_OK;
}

mote_result mote__gltf_lights(mote__gltf *gl)
{
    mote_scene *sc = gl->load->scene;
    int dropped = 0;
    for (int i = 0; i < gl->node_count; i++) {
        if (!gl->nodes[i].in_scene || gl->nodes[i].light < 0)
            continue;
        sc->has_lights = true;
        mote_light L;
        bool dark = false;
        MOTE__TRY(mote__gltf_light(gl, i, &L, &dark));
        if (dark)
            continue;
        if (sc->light_count >= MOTE_MAX_LIGHTS) {
            dropped++;
            continue;
        }
        sc->lights[sc->light_count++] = L;
    }
    if (dropped)
        mote__warn(gl->load, "KHR_lights_punctual: more than %d lights; %d are not drawn",
                   MOTE_MAX_LIGHTS, dropped);
    return MOTE_OK;
}
