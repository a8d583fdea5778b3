/*
 * scene_texture.c - the textures a scene names (loader.h): files in the
 * scene's folder under the path rules, names written as URLs, images
 * embedded as data: URLs, each decoded once however many materials name
 * it.
 */
#include "loader.h"

#include <string.h>

static bool mote__path_escapes(const char *name, const char **why)
{
    if (!name[0]) {
        *why = "is empty";
        return true;
    }
    if (name[0] == '/' || name[0] == '\\' ||
        (((name[0] | 0x20) >= 'a' && (name[0] | 0x20) <= 'z') && name[1] == ':')) {
        *why = "is an absolute path";
        return true;
    }
    const char *p = name;
    while (*p) {
        const char *q = p;
        while (*q && *q != '/' && *q != '\\')
            q++;
        if (q - p == 2 && p[0] == '.' && p[1] == '.') {
            *why = "leaves the scene's folder with '..'";
            return true;
        }
        p = *q ? q + 1 : q;
    }
    return false;
}

/* The texture already loaded from path, or NULL. */
static mote_texture *mote__loaded_texture(const mote__loader *ld, const char *path)
{
    for (int i = 0; i < ld->scene->texture_count; i++)
        if (strcmp(ld->texture_paths[i], path) == 0)
            return &ld->scene->textures[i];
    return NULL;
}

/* The texture at path (a file, or with embedded a data: URL), loaded once
 * however many materials name it; key names the JSON member in messages.
 * fallback (or NULL): the file to try when path cannot be opened. */
static mote_result mote__texture_found(mote__loader *ld, const char *at, const char *key,
                                       const char *path, const char *fallback, bool embedded,
                                       mote_material *m)
{
    mote_scene *sc = ld->scene;
    m->texture = mote__loaded_texture(ld, path);
    if (m->texture)
        return MOTE_OK;
    if (sc->texture_count >= ld->texture_cap)
        return mote__fail(ld, MOTE_ERR_LIMIT, "%s: too many textures", at);
    char why[256];
    mote_texture *t = &sc->textures[sc->texture_count];
    mote_result r = embedded
              ? mote__io_texture_load_data_url(path, &ld->lim, t, why, sizeof why)
              : mote_texture_load(path, &ld->lim, t, why, sizeof why);
    if (r == MOTE_ERR_IO && fallback) {
        m->texture = mote__loaded_texture(ld, fallback);
        if (m->texture)
            return MOTE_OK;
        /* the fallback's own error, unless it cannot be opened either */
        char fallback_why[256];
        mote_result rf =
            mote_texture_load(fallback, &ld->lim, t, fallback_why, sizeof fallback_why);
        if (rf != MOTE_ERR_IO) {
            r = rf;
            path = fallback;
            memcpy(why, fallback_why, sizeof why);
        }
    }
    if (r == MOTE_ERR_OUT_OF_MEMORY)
        return mote__fail(ld, r, "%s.%s: %s", at, key, why);
    if (r != MOTE_OK) {
        if (ld->lim.missing_texture_is_warning) {
            mote__warn(ld, "%s: %s (drawn untextured)", at, why);
            return MOTE_OK;
        }
        return mote__fail(ld, r, "%s.%s: %s", at, key, why);
    }
    ld->texture_paths[sc->texture_count++] = path;
    m->texture = t;
    return MOTE_OK;
}

/* The path of the texture file `name` (in the temporary store): in the
 * scene's folder, Windows separators turned. NULL, with *why, when name
 * leaves that folder and limits.allow_any_texture_path is not set. */
static mote_result mote__texture_file(mote__loader *ld, const char *at, const char *name,
                                      const char **why, char **out)
{
    *out = NULL;
    if (!ld->lim.allow_any_texture_path && mote__path_escapes(name, why))
        return MOTE_OK;
    bool absolute = name[0] == '/' || name[0] == '\\';
    size_t blen = strlen(ld->base_dir), nlen = strlen(name);
    char *path = mote__store_alloc(&ld->tmp, blen + nlen + 2, 1);
    if (!path)
        return mote__oom(ld, at);
    if (absolute || blen == 0) {
        memcpy(path, name, nlen + 1);
    } else {
        memcpy(path, ld->base_dir, blen);
        path[blen] = '/';
        memcpy(path + blen + 1, name, nlen + 1);
    }
#ifndef _WIN32
    for (char *c = path + (absolute ? 0 : blen + 1); *c; c++)
        if (*c == '\\')
            *c = '/'; /* exporters on Windows write folder\\image.png */
#endif
    *out = path;
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

/* A texture name written as a URL ("my%20tex.png?v=2", as web exporters
 * write them) read as a file name: the "?query" dropped and %XX escapes
 * decoded. An invalid escape, or %00, leaves the escapes as written.
 * NULL: the same as name. */
static mote_result mote__url_decoded_name(mote__loader *ld, const char *at, const char *name,
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
    ld->scene->textures = mote__store_alloc(ld->keep, n, sizeof(mote_texture));
    ld->texture_paths = mote__store_alloc(&ld->tmp, n, sizeof(char *));
    if (!ld->scene->textures || !ld->texture_paths)
        return mote__oom(ld, at);
    ld->texture_cap = (int)n;
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
                          "not download (textures are files in the scene's folder, or embedded)",
                          at, key, mote__quote(name).s);
    }
    const char *why = "";
    char *path, *decoded, *decoded_path = NULL;
    MOTE__TRY(mote__texture_file(ld, at, name, &why, &path));
    if (!path)
        return mote__fail(ld, MOTE_ERR_RANGE,
                          "%s.%s: \"%s\" %s (textures must be inside the scene's "
                          "folder; see limits.allow_any_texture_path)",
                          at, key, mote__quote(name).s, why);
    /* decoded, the name is checked again: "%2e%2e/x.png" is not tried */
    MOTE__TRY(mote__url_decoded_name(ld, at, name, &decoded));
    if (decoded)
        MOTE__TRY(mote__texture_file(ld, at, decoded, &why, &decoded_path));
    return mote__texture_found(ld, at, key, path, decoded_path, false, m);
}
