/*
 * json.c - typed getters over cJSON that name the JSON path in messages
 * (json.h).
 */
#include "json.h"

#include <float.h>
#include <math.h>
#include <stdio.h>
#include <string.h>

size_t mote__json_length(const cJSON *a)
{
    size_t n = 0;
    for (const cJSON *e = a ? a->child : NULL; e; e = e->next)
        n++;
    return n;
}

const char *mote__json_type_name(const cJSON *v)
{
    if (cJSON_IsNumber(v)) return "a number";
    if (cJSON_IsString(v)) return "a string";
    if (cJSON_IsArray(v)) return "an array";
    if (cJSON_IsObject(v)) return "an object";
    if (cJSON_IsBool(v)) return "a boolean";
    if (cJSON_IsNull(v)) return "null";
    return "something else";
}

const cJSON *mote__json_member(const cJSON *obj, const char *key)
{
    const cJSON *last = NULL;
    if (!cJSON_IsObject(obj))
        return NULL;
    for (const cJSON *e = obj->child; e; e = e->next)
        if (e->string && strcmp(e->string, key) == 0)
            last = e;
    return last;
}

const cJSON *mote__json_get(const cJSON *obj, const char *key)
{
    const cJSON *v = mote__json_member(obj, key);
    return cJSON_IsNull(v) ? NULL : v;
}

/* d as the float it rounds to, if that is finite: FLT_MAX as written to 8
 * digits (3.4028235e38) is a little over it but rounds to it, as
 * JavaScript's Math.fround does; from FLT_MAX plus half its last step up,
 * a float rounds to infinity. */
static bool mote__json_to_float(double d, float *out)
{
    if (!(fabs(d) < 0x1.ffffffp+127))
        return false;             /* also NaN */
    *out = d > (double)FLT_MAX ? FLT_MAX : d < -(double)FLT_MAX ? -FLT_MAX : (float)d;
    return true;
}

mote_result mote__json_float(mote__loader *ld, const cJSON *v, const char *at, float *out)
{
    if (!cJSON_IsNumber(v))
        return mote__fail(ld, MOTE_ERR_PARSE, "%s: expected a number, found %s", at,
                          mote__json_type_name(v));
    if (!mote__json_to_float(v->valuedouble, out))
        return mote__fail(ld, MOTE_ERR_RANGE, "%s: %g is not a finite float", at,
                          v->valuedouble);
    return MOTE_OK;
}

mote_result mote__json_uint(mote__loader *ld, const cJSON *v, const char *at, double lo,
                            double hi, uint32_t *out)
{
    if (!cJSON_IsNumber(v))
        return mote__fail(ld, MOTE_ERR_PARSE, "%s: expected an integer, found %s", at,
                          mote__json_type_name(v));
    double d = v->valuedouble;
    if (!isfinite(d) || d != floor(d))
        return mote__fail(ld, MOTE_ERR_PARSE, "%s: %g is not an integer", at, d);
    if (d < lo || d > hi)
        return mote__fail(ld, MOTE_ERR_RANGE, "%s: %.17g is out of range [%.17g, %.17g]", at,
                          d, lo, hi);
    *out = (uint32_t)d;
    return MOTE_OK;
}

mote_result mote__json_floats(mote__loader *ld, const cJSON *obj, const char *key,
                              const char *where, int n, int n_alt, float *out)
{
    const cJSON *a = mote__json_get(obj, key);
    if (!a)
        return MOTE_OK;
    char at[160];
    snprintf(at, sizeof at, "%s.%s", where, key);
    size_t len = mote__json_length(a);
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
        MOTE__TRY(mote__json_float(ld, e, at2, &tmp[k]));
    }
    memcpy(out, tmp, (size_t)n * sizeof *out);
    return MOTE_OK;
}

mote_result mote__json_number(mote__loader *ld, const cJSON *obj, const char *key,
                              const char *where, float *out)
{
    const cJSON *v = mote__json_get(obj, key);
    if (!v)
        return MOTE_OK;
    char at[160];
    snprintf(at, sizeof at, "%s.%s", where, key);
    return mote__json_float(ld, v, at, out);
}

mote_result mote__json_flag(mote__loader *ld, const cJSON *obj, const char *key,
                            const char *where, bool *out)
{
    const cJSON *v = mote__json_get(obj, key);
    if (!v)
        return MOTE_OK;
    if (cJSON_IsBool(v)) {
        *out = cJSON_IsTrue(v);
        return MOTE_OK;
    }
    char at[160];
    snprintf(at, sizeof at, "%s.%s", where, key);
    float f;
    MOTE__TRY(mote__json_float(ld, v, at, &f));
    *out = f != 0.0f;
    return MOTE_OK;
}

mote_result mote__json_uint_member(mote__loader *ld, const cJSON *obj, const char *key,
                                   const char *where, uint32_t hi, uint32_t *out)
{
    const cJSON *v = mote__json_get(obj, key);
    if (!v)
        return MOTE_OK;
    char at[160];
    snprintf(at, sizeof at, "%s.%s", where, key);
    return mote__json_uint(ld, v, at, 0, hi, out);
}

mote_result mote__json_string(mote__loader *ld, const cJSON *obj, const char *key,
                              const char *where, const char **out)
{
    const cJSON *v = mote__json_get(obj, key);
    *out = NULL;
    if (!v)
        return MOTE_OK;
    if (!cJSON_IsString(v) || !v->valuestring)
        return mote__fail(ld, MOTE_ERR_PARSE, "%s.%s: expected a string, found %s", where,
                          key, mote__json_type_name(v));
    *out = v->valuestring;
    return MOTE_OK;
}

mote_result mote__json_array(mote__loader *ld, const cJSON *obj, const char *key,
                             const char *where, const cJSON **out)
{
    const cJSON *v = mote__json_get(obj, key);
    *out = NULL;
    if (!v)
        return MOTE_OK;
    if (!cJSON_IsArray(v))
        return mote__fail(ld, MOTE_ERR_PARSE, "%s%s%s: expected an array, found %s", where,
                          where[0] ? "." : "", key, mote__json_type_name(v));
    *out = v;
    return MOTE_OK;
}

mote_result mote__json_object(mote__loader *ld, const cJSON *v, const char *at)
{
    if (!cJSON_IsObject(v))
        return mote__fail(ld, MOTE_ERR_PARSE, "%s: expected an object, found %s", at,
                          mote__json_type_name(v));
    return MOTE_OK;
}

mote_result mote__json_element_float(mote__loader *ld, const cJSON *e, const char *at, size_t k,
                                     float *out)
{
    if (!cJSON_IsNumber(e) || !mote__json_to_float(e->valuedouble, out)) {
        char at2[192];
        snprintf(at2, sizeof at2, "%s[%zu]", at, k);
        return mote__json_float(ld, e, at2, out);
    }
    return MOTE_OK;
}

/* Nesting depth checked on the text before cJSON (which recurses) sees it. */
static mote_result mote__json_check_depth(mote__loader *ld, const char *json, size_t size,
                                          bool *unclosed)
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

mote_result mote__json_parse(mote__loader *ld, const char *json, size_t size, cJSON **out)
{
    *out = NULL;
    bool unclosed = false;
    MOTE__TRY(mote__json_check_depth(ld, json, size, &unclosed));
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
