/*
 * scene_texture.c - the textures a scene names (loader.h): files in the
 * scene's folder under the path rules, names written as URLs, images
 * embedded as data: URLs, each decoded once however many materials name
 * it.
 */
#include "loader.h"

#include <string.h>

static mote_result mote__texture_outcome(mote__loader *ld, const char *at, const char *key,
                                         mote_result r, const char *why, int index,
                                         mote_material *m);

/* The texture a material names (a file in the scene's folder, or with
 * embedded a data: URL), loaded once however many materials name it
 * (mote__texture_set); key names the JSON member in messages. fallback
 * (or NULL): the file to try when name cannot be opened. */
static mote_result mote__texture_found(mote__loader *ld, const char *at, const char *key,
                                       const char *name, const char *fallback, bool embedded,
                                       mote_material *m)
{
    mote__texture_set *set = &ld->textures;
    char why[256];
    int index = -1;
    mote_result r = embedded ? mote__texture_set_data_url(set, name, &ld->lim, &index, why, sizeof why)
                             : mote__texture_set_file(set, ld->base_dir, name, &ld->lim, &index, why,
                                                      sizeof why);
    if (r == MOTE_ERR_IO && fallback) {
        /* the fallback's own error, unless it cannot be opened either */
        char fallback_why[256];
        mote_result rf = mote__texture_set_file(set, ld->base_dir, fallback, &ld->lim, &index,
                                                fallback_why, sizeof fallback_why);
        if (rf != MOTE_ERR_IO) {
            r = rf;
            memcpy(why, fallback_why, sizeof why);
        }
    }
    return mote__texture_outcome(ld, at, key, r, why, index, m);
}

/* What a texture's load (r, why) makes of m: its texture, a warning
 * (limits.missing_texture_is_warning) or the load's failure. */
static mote_result mote__texture_outcome(mote__loader *ld, const char *at, const char *key,
                                         mote_result r, const char *why, int index,
                                         mote_material *m)
{
    ld->scene->texture_count = ld->textures.count;
    if (r == MOTE_ERR_RANGE)
        return mote__fail(ld, r, "%s.%s: %s (textures must be inside the scene's folder; see "
                          "limits.allow_any_texture_path)", at, key, why);
    if (r == MOTE_ERR_OUT_OF_MEMORY)
        return mote__fail(ld, r, "%s.%s: %s", at, key, why);
    if (r != MOTE_OK) {
        if (ld->lim.missing_texture_is_warning) {
            mote__warn(ld, "%s: %s (drawn untextured)", at, why);
            return MOTE_OK;
        }
        return mote__fail(ld, r, "%s.%s: %s (limits.missing_texture_is_warning draws its "
                          "material untextured)", at, key, why);
    }
    m->texture = &ld->scene->textures[index];
    return MOTE_OK;
}

static int mote__hex_digit(char c)
{
    if (c >= '0' && c <= '9')
        return c - '0';
    if ((c | 0x20) >= 'a' && (c | 0x20) <= 'f')
        return (c | 0x20) - 'a' + 10;
    return -1;
}

mote_result mote__url_decoded_name(mote__loader *ld, const char *at, const char *name,
                                          char **out)
{
    *out = NULL;
    size_t n = strcspn(name, "?"), k = 0;
    char *d = mote__store_alloc(&ld->tmp, n + 1, 1);
    if (!d)
        return mote__oom(ld, at);
    for (size_t i = 0; i < n; i++) {
        if (name[i] != '%') {
            d[k++] = name[i];
            continue;
        }
        /* '?' and the terminating NUL are no hex digits: no read past n */
        int hi = mote__hex_digit(name[i + 1]);
        int lo = hi >= 0 ? mote__hex_digit(name[i + 2]) : -1;
        if (lo < 0 || (hi | lo) == 0) {
            memcpy(d, name, n);   /* keep the escapes as written */
            k = n;
            break;
        }
        d[k++] = (char)(hi << 4 | lo);
        i += 2;
    }
    d[k] = '\0';
    if (strcmp(d, name) != 0)
        *out = d;
    return MOTE_OK;
}

mote_result mote__texture_slots(mote__loader *ld, size_t n, const char *at)
{
    mote__texture_set *set = &ld->textures;
    set->textures = ld->scene->textures = mote__store_alloc(ld->keep, n, sizeof(mote_texture));
    set->files = mote__store_alloc(ld->keep, n, sizeof *set->files);
    set->urls = mote__store_alloc(&ld->tmp, n, sizeof *set->urls);
    if (!set->textures || !set->files || !set->urls)
        return mote__oom(ld, at);
    set->cap = (int)n;
    ((mote__scene_files *)ld->scene->files_)->textures = set->files;
    return MOTE_OK;
}

mote_result mote__scene_texture(mote__loader *ld, const char *at, const char *key,
                                const char *name, const char *embedded, mote_material *m)
{
    if (!ld->base_dir)
        return MOTE_OK; /* colours only (embedded images too, as documented) */
    if (embedded)
        return mote__texture_found(ld, at, key, embedded, NULL, true, m);
    /* "://" past the start: Babylon.js's Texture.Parse fetches such a name
     * as it is (the SceneSerializer writes web textures so), not from the
     * scene's folder; mote downloads nothing */
    const char *scheme_end = strstr(name, "://");
    if (scheme_end && scheme_end != name) {
        if (ld->lim.missing_texture_is_warning) {
            mote__warn(ld, "%s: \"%s\" is a web address, which mote does not download (drawn "
                       "untextured)", at, mote__quote(name).s);
            return MOTE_OK;
        }
        return mote__fail(ld, MOTE_ERR_IO, "%s.%s: \"%s\" is a web address, which mote does "
                          "not download (textures are files in the scene's folder, or embedded; "
                          "limits.missing_texture_is_warning draws its material untextured)",
                          at, key, mote__quote(name).s);
    }
    /* decoded, the name is checked again: "%2e%2e/x.png" is not tried */
    char *decoded;
    const char *why;
    MOTE__TRY(mote__url_decoded_name(ld, at, name, &decoded));
    if (decoded && !ld->lim.allow_any_texture_path && mote__io_name_escapes(decoded, &why))
        decoded = NULL;
    return mote__texture_found(ld, at, key, name, decoded, false, m);
}

mote_result mote__scene_texture_bytes(mote__loader *ld, const char *at, const char *key,
                                      const void *data, size_t size, mote_material *m)
{
    if (!ld->base_dir)
        return MOTE_OK; /* colours only, as for data: URLs */
    char why[256];
    int index = -1;
    mote_result r = mote__texture_set_memory(&ld->textures, data, size, &ld->lim, &index, why,
                                             sizeof why);
    return mote__texture_outcome(ld, at, key, r, why, index, m);
}
