/*
 * json.h - reading a scene's JSON with cJSON: typed getters that name the
 * JSON path in their messages ("meshes[0].position[1]: expected a number,
 * found a string"), finite floats and whole numbers checked, and the
 * nesting limit checked before cJSON, which recurses, sees the text.
 * Messages go to the load (loader.h). Not API.
 *
 * `where` is the path of obj ("meshes[3]", "" at the top level), `at` the
 * path of the value itself. A getter of a member leaves *out as it was
 * when the member is absent or null.
 */
#ifndef MOTE_IO_JSON_H
#define MOTE_IO_JSON_H

#include "loader.h"

#include <cJSON.h>

/* Parses size bytes of JSON text into *out (cJSON_Delete it): the nesting
 * limit (limits.max_json_depth), an empty or truncated text, text after
 * the value and a top level that is no object are errors that say where. */
mote_result mote__json_parse(mote__loader *ld, const char *json, size_t size, cJSON **out);

/* The elements of an array (or members of an object); 0 for NULL. */
size_t mote__json_length(const cJSON *a);
/* "a number", "an array", ... for messages. */
const char *mote__json_type_name(const cJSON *v);

/* obj[key], or NULL. Of keys written twice the last counts, as with
 * JSON.parse (cJSON's own lookup finds the first); every lookup of a
 * loader goes through here. */
const cJSON *mote__json_member(const cJSON *obj, const char *key);
/* obj[key]; NULL when absent or null. */
const cJSON *mote__json_get(const cJSON *obj, const char *key);

/* v as a finite float (a number within float range). */
mote_result mote__json_float(mote__loader *ld, const cJSON *v, const char *at, float *out);
/* v as a whole number in [lo, hi]. */
mote_result mote__json_uint(mote__loader *ld, const cJSON *v, const char *at, double lo,
                            double hi, uint32_t *out);
/* Element k of the array at `at` as mote__json_float reads it; the path
 * is spelled out only for an error, as vertex arrays are long. */
mote_result mote__json_element_float(mote__loader *ld, const cJSON *e, const char *at, size_t k,
                                     float *out);

/* obj[key] as n floats, or n_alt (0: no second length; colours may carry
 * alpha), into out[0..n). */
mote_result mote__json_floats(mote__loader *ld, const cJSON *obj, const char *key,
                              const char *where, int n, int n_alt, float *out);
/* obj[key] as a finite float. */
mote_result mote__json_number(mote__loader *ld, const cJSON *obj, const char *key,
                              const char *where, float *out);
/* obj[key] as a flag: a boolean, or a number (0 is false). */
mote_result mote__json_flag(mote__loader *ld, const cJSON *obj, const char *key,
                            const char *where, bool *out);
/* obj[key] as a whole number in [0, hi]. */
mote_result mote__json_uint_member(mote__loader *ld, const cJSON *obj, const char *key,
                                   const char *where, uint32_t hi, uint32_t *out);
/* obj[key] as a string; *out NULL when absent or null. */
mote_result mote__json_string(mote__loader *ld, const cJSON *obj, const char *key,
                              const char *where, const char **out);
/* obj[key] as an array; *out NULL when absent or null. */
mote_result mote__json_array(mote__loader *ld, const cJSON *obj, const char *key,
                             const char *where, const cJSON **out);
/* An error unless v is an object. */
mote_result mote__json_object(mote__loader *ld, const cJSON *v, const char *at);

#endif
