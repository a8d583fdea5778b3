/*
 * json.c - typed getters over cJSON that name the JSON path in messages
 * (json.h).
 */
#include "json.h"

#include <float.h>
#include <math.h>
#include <stdio.h>
#include <stdlib.h>
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

/* ---- the parse's memory ------------------------------------------------ */

/* What cJSON 1.7 allocates to parse a text, told from the text: a cJSON
 * item per value (the root, each array element, each object member, its
 * key included), and for each string, key or value, its length between
 * the quotes plus 2; a number is copied while it is read (Debian's
 * cJSON), one at a time. Each allocation is counted as malloc spends it:
 * rounded up to 16 bytes, plus 16. */
static size_t mote__json_alloc_cost(size_t size)
{
    return ((size + 15) & ~(size_t)15) + 16;
}

/* What the scan of a text finds before cJSON sees it. */
typedef struct mote__json_scan {
    bool unclosed;                /* a string or bracket left open */
    size_t values;                /* strings + numbers + literals + arrays + objects - keys */
    size_t bytes;                 /* what parsing it allocates, at most */
} mote__json_scan;

static bool mote__json_token_char(char c)
{
    return (c >= '0' && c <= '9') || (c >= 'a' && c <= 'z') || (c >= 'A' && c <= 'Z') ||
           c == '.' || c == '+' || c == '-';
}

/* The nesting depth (checked before cJSON, which recurses, sees the text)
 * and what the parse will allocate (*scan: at most that much, for a text
 * that parses; a text that fails, fails before one more item past it).
 * Keys are the strings a ':' follows. */
static mote_result mote__json_scan_text(mote__loader *ld, const char *json, size_t size,
                                        mote__json_scan *scan)
{
    int depth = 0;
    size_t tokens = 0, keys = 0, string_start = 0, run = 0, longest_run = 0;
    bool in_string = false, after_string = false;
    memset(scan, 0, sizeof *scan);
    for (size_t i = 0; i < size; i++) {
        char c = json[i];
        if (in_string) {
            if (c == '\\') {
                i++;
            } else if (c == '"') {
                in_string = false;
                after_string = true;
                scan->bytes += mote__json_alloc_cost(i - string_start + 2);
            }
            continue;
        }
        run = mote__json_token_char(c) ? run + 1 : 0;
        longest_run = run > longest_run ? run : longest_run;
        if (c == ' ' || c == '\t' || c == '\r' || c == '\n')
            continue;
        bool was_after_string = after_string;
        after_string = false;
        if (c == '"') {
            in_string = true;
            string_start = i + 1;
            tokens++;
        } else if (c == ':') {
            keys += was_after_string;
        } else if (c == '[' || c == '{') {
            tokens++;
            if (++depth > ld->lim.max_json_depth)
                return mote__fail(ld, MOTE_ERR_LIMIT,
                                  "byte %zu: nesting deeper than the limit of %d levels", i,
                                  ld->lim.max_json_depth);
        } else if (c == ']' || c == '}') {
            depth--;
        } else if (((c >= '0' && c <= '9') || c == '-' || c == 't' || c == 'f' || c == 'n') &&
                   !(i > 0 && mote__json_token_char(json[i - 1]))) {
            tokens++;             /* a number or literal starts */
        }
    }
    scan->unclosed = in_string || depth > 0;
    /* one item more: cJSON makes an element's item before it reads it */
    scan->values = tokens - keys + 1;
    scan->bytes += mote__json_alloc_cost(longest_run + 1);   /* the number being read */
    size_t item = mote__json_alloc_cost(sizeof(cJSON));
    if (scan->values > SIZE_MAX / item || scan->bytes > SIZE_MAX - scan->values * item)
        scan->bytes = SIZE_MAX;
    else
        scan->bytes += scan->values * item;
    return MOTE_OK;
}

/* n bytes for a message: "812 bytes", "3.5 MiB". */
static void mote__json_bytes_text(char *out, size_t out_size, size_t n)
{
    if (n < ((size_t)1 << 20))
        snprintf(out, out_size, "%zu bytes", n);
    else
        snprintf(out, out_size, "%.1f MiB", (double)n / (1 << 20));
}

/* cJSON's allocations, through hooks given once for the process
 * (cJSON_InitHooks is global): malloc, counting each that fails, so that
 * a parse that fails knows whether memory ran out; free as it is. A test
 * can make the next one fail (mote__io_should_fail, once a parse). */
static long mote__json_failed_allocations;
static int mote__json_fail_next;
static int mote__json_hooks_state;     /* 0 none, 1 being given, 2 given */

static void *mote__json_malloc(size_t size)
{
    if (MOTE__IO_EXCHANGE(&mote__json_fail_next, 0)) {
        MOTE__IO_ADD(&mote__json_failed_allocations, 1);
        return NULL;
    }
    void *p = malloc(size);
    if (!p)
        MOTE__IO_ADD(&mote__json_failed_allocations, 1);
    return p;
}

static void mote__json_give_hooks(void)
{
    if (MOTE__IO_LOAD_ACQUIRE(&mote__json_hooks_state) == 2)
        return;
    if (mote__io_claim(&mote__json_hooks_state)) {
        cJSON_Hooks hooks = {mote__json_malloc, free};
        cJSON_InitHooks(&hooks);
        MOTE__IO_STORE_RELEASE(&mote__json_hooks_state, 2);
    } else {
        while (MOTE__IO_LOAD_ACQUIRE(&mote__json_hooks_state) != 2)
            ;                     /* another thread is giving them: a few instructions */
    }
}

mote_result mote__json_parse(mote__loader *ld, const char *json, size_t size, cJSON **out)
{
    *out = NULL;
    mote__json_scan scan;
    MOTE__TRY(mote__json_scan_text(ld, json, size, &scan));
    if (size == 0)
        return mote__fail(ld, MOTE_ERR_PARSE, "empty file");
    if (scan.bytes > ld->lim.max_json_bytes) {
        char need[32], limit[32];
        mote__json_bytes_text(need, sizeof need, scan.bytes);
        mote__json_bytes_text(limit, sizeof limit, ld->lim.max_json_bytes);
        return mote__fail(ld, MOTE_ERR_LIMIT, "parsing its JSON (%zu values) would take %s, more "
                          "than the limit of %s (max_json_bytes)", scan.values, need, limit);
    }
    mote__json_give_hooks();
    long failed_before = MOTE__IO_LOAD(&mote__json_failed_allocations);
    if (mote__io_should_fail())
        MOTE__IO_EXCHANGE(&mote__json_fail_next, 1);
    const char *end = NULL;
    cJSON *root = cJSON_ParseWithLengthOpts(json, size, &end, 0);
    MOTE__IO_EXCHANGE(&mote__json_fail_next, 0);
    if (!root) {
        size_t at = end && end >= json && end <= json + size ? (size_t)(end - json) : size;
        size_t line = 1;
        for (size_t i = 0; i < at && i < size; i++)
            line += json[i] == '\n';
        if (MOTE__IO_LOAD(&mote__json_failed_allocations) != failed_before)
            return mote__fail(ld, MOTE_ERR_OUT_OF_MEMORY, "line %zu, byte %zu: out of memory "
                              "parsing the JSON", line, at);
        if (at >= size || scan.unclosed)
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
