/*
 * scene.c - mote_scene_load and what is done with a loaded scene: framing,
 * draw options, levels of detail. Loading looks at the bytes and hands
 * them to the loader of their format, or says what they are (loader.h
 * lists the files).
 */
#include "babylon.h"
#include "gltf.h"

#include <float.h>
#include <math.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>

/* ---- what the bytes are ------------------------------------------------ */

/* What a file holds, told by its first bytes before anything parses it. */
typedef enum mote__format {
    MOTE__FORMAT_JSON,            /* .babylon or glTF: told apart once parsed */
    MOTE__FORMAT_GLB,             /* binary glTF */
    MOTE__FORMAT_OBJ,             /* Wavefront OBJ or MTL */
    MOTE__FORMAT_LFS_POINTER,     /* a Git LFS pointer in place of the file */
    MOTE__FORMAT_IMAGE,
    MOTE__FORMAT_UNKNOWN
} mote__format;

static bool mote__starts_with(const unsigned char *d, size_t n, const char *prefix, size_t len)
{
    return n >= len && memcmp(d, prefix, len) == 0;
}

/* The kind of image d holds ("a PNG image"): a format stb_image reads,
 * told as it tells them (but TGA, which has no signature: *tga), or one
 * of a few others by their signatures; NULL: none of them. */
static const char *mote__image_kind(const unsigned char *d, size_t n, bool *tga)
{
    static const char *const stb_kinds[] = {
        [MOTE__IMAGE_PNG] = "a PNG image",
        [MOTE__IMAGE_BMP] = "a BMP image",
        [MOTE__IMAGE_GIF] = "a GIF image",
        [MOTE__IMAGE_PSD] = "a Photoshop (PSD) image",
        [MOTE__IMAGE_PIC] = "a Softimage PIC image",
        [MOTE__IMAGE_JPEG] = "a JPEG image",
        [MOTE__IMAGE_PNM] = "a PNM image",
        [MOTE__IMAGE_HDR] = "a Radiance HDR image",
    };
    static const struct {
        const char *magic;
        size_t len;
        const char *kind;
    } others[] = {
        {"II*\0", 4, "a TIFF image"},
        {"MM\0*", 4, "a TIFF image"},
        {"\x76\x2f\x31\x01", 4, "an OpenEXR image"},
        {"\xabKTX", 4, "a KTX texture"},
        {"DDS ", 4, "a DDS texture"},
        {"qoif", 4, "a QOI image"},
    };
    mote__image_format f = mote__stb_image_format(d, n);
    *tga = f == MOTE__IMAGE_TGA;
    if (f != MOTE__IMAGE_NONE && !*tga)
        return stb_kinds[f];
    for (size_t i = 0; i < sizeof others / sizeof others[0]; i++)
        if (mote__starts_with(d, n, others[i].magic, others[i].len))
            return others[i].kind;
    if (n >= 12 && memcmp(d, "RIFF", 4) == 0 && memcmp(d + 8, "WEBP", 4) == 0)
        return "a WebP image";
    return NULL;
}

static bool mote__is_space(unsigned char c)
{
    return c == ' ' || c == '\t' || c == '\r' || c == '\n';
}

/* The kind of Wavefront file d is, "a Wavefront OBJ file" or an MTL
 * file, told by its first line that is neither blank nor a '#' comment
 * (within 4 KiB); NULL: neither. */
static const char *mote__obj_kind(const unsigned char *d, size_t n)
{
    static const char *const statements[] = {"v", "vt", "vn", "vp", "f", "l", "p", "o", "g",
                                             "s", "mtllib", "usemtl"};
    size_t end = n < 4096 ? n : 4096, i = 0;
    while (i < end) {
        while (i < end && mote__is_space(d[i]))
            i++;
        if (i < end && d[i] == '#') {
            while (i < end && d[i] != '\n')
                i++;
            continue;
        }
        size_t word = i;
        while (i < end && !mote__is_space(d[i]))
            i++;
        if (i >= end || (d[i] != ' ' && d[i] != '\t'))
            return NULL;
        if (i - word == 6 && memcmp(d + word, "newmtl", 6) == 0)
            return "a Wavefront MTL file (an OBJ file's materials)";
        for (size_t k = 0; k < sizeof statements / sizeof statements[0]; k++)
            if (strlen(statements[k]) == i - word &&
                memcmp(d + word, statements[k], i - word) == 0)
                return "a Wavefront OBJ file";
        return NULL;
    }
    return NULL;
}

/* The format of the n bytes d; *kind names an image's or an OBJ file's. */
static mote__format mote__scene_format(const unsigned char *d, size_t n, const char **kind)
{
    bool tga;
    *kind = mote__image_kind(d, n, &tga);
    if (*kind)
        return MOTE__FORMAT_IMAGE;
    if (mote__starts_with(d, n, "glTF", 4))
        return MOTE__FORMAT_GLB;
    if (mote__starts_with(d, n, "version https://git-lfs", 23))
        return MOTE__FORMAT_LFS_POINTER;
    size_t i = mote__starts_with(d, n, "\xef\xbb\xbf", 3) ? 3 : 0;   /* a UTF-8 byte order mark */
    while (i < n && mote__is_space(d[i]))
        i++;
    if (i == n || d[i] == '{' || d[i] == '[')
        return MOTE__FORMAT_JSON;
    *kind = mote__obj_kind(d, n);
    if (*kind)
        return MOTE__FORMAT_OBJ;
    /* last: stb_image takes for a TGA what no other test claims */
    *kind = tga ? "a TGA image" : NULL;
    return tga ? MOTE__FORMAT_IMAGE : MOTE__FORMAT_UNKNOWN;
}

/* The first bytes of d in hex, for a message. */
static void mote__first_bytes(const unsigned char *d, size_t n, char *out, size_t out_size)
{
    size_t used = 0;
    out[0] = '\0';
    for (size_t i = 0; i < n && i < 8 && used + 4 <= out_size; i++)
        used += (size_t)snprintf(out + used, out_size - used, "%s%02x", i ? " " : "", d[i]);
}

/* Every texture's mip chain, built once (mote_scene.mipmaps), and the
 * materials pointed at them: a draw with mip MOTE_MIP_TRIANGLE samples
 * them. */
static mote_result mote__scene_mipmaps(mote__loader *ld)
{
    mote_scene *sc = ld->scene;
    if (sc->texture_count <= 0)
        return MOTE_OK;
    mote_mipmaps *mips = mote__store_alloc(ld->keep, (size_t)sc->texture_count, sizeof *mips);
    if (!mips)
        return mote__oom(ld, "textures");
    for (int i = 0; i < sc->texture_count; i++) {
        size_t bytes = mote_mipmaps_bytes(&sc->textures[i]);
        void *memory = bytes ? mote__store_alloc(ld->keep, bytes, 1) : NULL;
        if (bytes && !memory)
            return mote__oom(ld, "textures");
        if (sc->textures[i].pixels && mote_mipmaps_build(&sc->textures[i], memory, bytes, &mips[i]) != MOTE_OK)
            mips[i].count = 0;
    }
    sc->mipmaps = mips;
    for (int m = 0; m < sc->mesh_count; m++) {
        const mote_texture *t = sc->meshes[m].material.texture;
        ptrdiff_t k = t ? t - sc->textures : -1;
        if (k >= 0 && k < sc->texture_count && mips[k].count > 1)
            sc->meshes[m].material.mipmaps = &mips[k];
    }
    return MOTE_OK;
}

/* The scene in data into ld->scene: a .babylon or glTF scene, or an
 * error that says what else the file is. */
static mote_result mote__scene_from_bytes(mote__loader *ld, const char *data, size_t size)
{
    const unsigned char *d = (const unsigned char *)data;
    const char *kind;
    char first[32];
    switch (mote__scene_format(d, size, &kind)) {
    case MOTE__FORMAT_JSON:
        break;
    case MOTE__FORMAT_GLB:
        return mote__gltf_load_glb(ld, d, size);
    case MOTE__FORMAT_OBJ:
        return mote__fail(ld, MOTE_ERR_UNSUPPORTED, "%s, which mote does not read (it reads "
                          ".babylon and glTF scenes)", kind);
    case MOTE__FORMAT_LFS_POINTER:
        return mote__fail(ld, MOTE_ERR_IO, "a Git LFS pointer, not the file it stands for "
                          "(git lfs pull fetches it)");
    case MOTE__FORMAT_IMAGE:
        return mote__fail(ld, MOTE_ERR_UNSUPPORTED, "%s, not a scene (images are the textures "
                          "a scene names)", kind);
    case MOTE__FORMAT_UNKNOWN:
        mote__first_bytes(d, size, first, sizeof first);
        return mote__fail(ld, MOTE_ERR_PARSE, "not a scene: neither .babylon nor glTF, nor a "
                          "format mote knows (it starts with bytes %s)", first);
    }
    cJSON *root;
    MOTE__TRY(mote__json_parse(ld, data, size, &root));
    mote_result r;
    const cJSON *gltf_version = mote__json_member(mote__json_member(root, "asset"), "version");
    if (gltf_version)
        r = mote__gltf_load_json(ld, root);
    else {
        if (ld->lim.gltf_scene > 1)
            mote__warn(ld, "limits.gltf_scene %d: a .babylon file holds one scene, which is "
                       "loaded", ld->lim.gltf_scene);
        r = mote__babylon_load(ld, root);
    }
    cJSON_Delete(root);
    return r;
}

mote_result mote_scene_load_memory(const char *data, size_t size, const char *name,
                                   const char *base_dir, const mote_limits *limits,
                                   mote_scene *out, char *message, size_t message_size)
{
    if (message && message_size)
        message[0] = '\0';
    if (!out)
        return mote__io_error(message, message_size, MOTE_ERR_INVALID_ARGUMENT,
                              "scene: no output scene given");
    memset(out, 0, sizeof *out);
    if (!data && size > 0)
        return mote__io_error(message, message_size, MOTE_ERR_INVALID_ARGUMENT,
                              "scene: no data given");
    mote__loader ld;
    mote_result r = mote__loader_begin(&ld, name, base_dir, limits, size, out, message,
                                       message_size);
    if (r == MOTE_OK)
        r = mote__scene_from_bytes(&ld, data ? data : "", size);
    if (r == MOTE_OK)
        r = mote__scene_mipmaps(&ld);
    return mote__loader_end(&ld, r);
}

mote_result mote_scene_load(const char *path, const mote_limits *limits, mote_scene *out,
                            char *message, size_t message_size)
{
    if (out)
        memset(out, 0, sizeof *out);
    if (!path || !out)
        return mote__io_error(message, message_size, MOTE_ERR_INVALID_ARGUMENT,
                              "scene: no path or no output scene given");
    mote_limits lim = mote__io_limits(limits);
    char *data = NULL;
    size_t size = 0;
    mote__io_file file;
    mote_result r = mote__io_open(path, &file, message, message_size);
    const mote__io_file_id id = file.id;
    if (r == MOTE_OK)
        r = mote__io_read_open(&file, lim.max_file_bytes, &data, &size, message, message_size);
    if (r != MOTE_OK)
        return r;
    /* split "dir/name.babylon": textures resolve in dir, messages say name */
    const char *slash = strrchr(path, '/');
#ifdef _WIN32
    const char *bslash = strrchr(path, '\\');
    if (bslash && (!slash || bslash > slash))
        slash = bslash;
#endif
    const char *base = slash ? slash + 1 : path;
    size_t dir_len = slash ? (size_t)(slash - path) : 1;
    char *dir = mote__io_malloc(dir_len + 1);
    if (!dir) {
        mote__io_free(data);
        return mote__io_error(message, message_size, MOTE_ERR_OUT_OF_MEMORY,
                              "%s: out of memory", base);
    }
    if (slash)
        memcpy(dir, path, dir_len);
    else
        dir[0] = '.';
    if (slash && dir_len == 0)
        dir[dir_len++] = '/'; /* "/scene.babylon" lives in "/" */
    dir[dir_len] = '\0';
    r = mote_scene_load_memory(data, size, base, dir, &lim, out, message, message_size);
    if (r == MOTE_OK)
        ((mote__scene_files *)out->files_)->scene = id;
    mote__io_free(dir);
    mote__io_free(data);
    return r;
}

void mote_scene_draw_desc(const mote_scene *scene, int mesh, const mote_draw_desc *base,
                          mote_draw_desc *out)
{
    if (!out)
        return;
    if (base)
        *out = *base;
    else
        memset(out, 0, sizeof *out);
    if (!scene || mesh < 0 || mesh >= scene->mesh_count)
        return;
    /* a mesh of points or lines has no triangles to fill, so a filled
     * mode asked of the whole scene leaves it in its own */
    mote_mode own = scene->modes ? scene->modes[mesh] : MOTE_MODE_DEFAULT;
    if (own == MOTE_MODE_POINTS || (own == MOTE_MODE_WIREFRAME && out->mode != MOTE_MODE_POINTS))
        out->mode = own;
    if (own == MOTE_MODE_WIREFRAME)
        out->cull = MOTE_CULL_NONE;
    /* Babylon.js draws both sides of a mesh whose material says
     * backFaceCulling false: no culling, whatever the caller asked */
    if (scene->two_sided && scene->two_sided[mesh])
        out->cull = MOTE_CULL_NONE;
    if (scene->mip_modes && out->mip == MOTE_MIP_DEFAULT)
        out->mip = scene->mip_modes[mesh];
    /* and without lights one whose material says disableLighting (its
     * colour is then the emissive one: mote__emissive) */
    if (scene->unlit && scene->unlit[mesh])
        out->unlit = true;
    if (scene->no_depth_write && scene->no_depth_write[mesh])
        out->no_depth_write = true;
    if (scene->no_fog && scene->no_fog[mesh])
        out->no_fog = true;
    if (scene->lights_off)
        out->lights_off |= scene->lights_off[mesh];
}

static bool mote__blended(const mote_mesh *m)
{
    return m->material.alpha_mode == MOTE_ALPHA_BLEND || m->material.alpha_mode == MOTE_ALPHA_TEST_AND_BLEND;
}

/* squared distance from p to the centre of m's bounding sphere, in world
 * space (the origin of its own space when it has no bounds) */
static double mote__centre_distance2(const mote_mesh *m, const float p[3])
{
    float w[16];
    mote_mesh_world_matrix(m, w);
    const float *c = m->bounds_center;
    double d2 = 0.0;
    for (int k = 0; k < 3; k++) {
        double x = (double)w[k] * c[0] + (double)w[4 + k] * c[1] + (double)w[8 + k] * c[2] + w[12 + k] - p[k];
        d2 += x * x;
    }
    return d2;
}

int mote_scene_draw_order(const mote_scene *scene, const mote_mesh *meshes, const mote_camera *camera, int *order)
{
    if (!scene || !meshes || !camera || !order || scene->mesh_count <= 0)
        return 0;
    const int n = scene->mesh_count;
    double *dist = malloc((size_t)n * sizeof *dist);
    if (!dist)
        return 0;
    int count = 0;
    for (int pass = 0; pass < 2; pass++)
        for (int i = 0; i < n; i++) {
            const mote_alpha_mode a = meshes[i].material.alpha_mode;
            if (!mote__blended(&meshes[i]) && (a == MOTE_ALPHA_TEST) == (pass == 1))
                order[count++] = i;
        }
    const int first = count;
    for (int i = 0; i < n; i++)
        if (mote__blended(&meshes[i])) {
            /* insertion sort, by alpha index then farthest first, stable:
             * few meshes blend */
            const double d = mote__centre_distance2(&meshes[i], camera->position);
            const float ai = scene->alpha_index ? scene->alpha_index[i] : FLT_MAX;
            int k = count++;
            while (k > first) {
                const float ak = scene->alpha_index ? scene->alpha_index[order[k - 1]] : FLT_MAX;
                if (!(ak > ai || (ak == ai && dist[k - 1] < d)))
                    break;
                order[k] = order[k - 1];
                dist[k] = dist[k - 1];
                k--;
            }
            order[k] = i;
            dist[k] = d;
        }
    free(dist);
    return count;
}

mote_result mote_scene_draw(mote_device *dev, const mote_scene *scene, const mote_mesh *meshes, int mesh,
                            const mote_draw_desc *base)
{
    if (!scene || !meshes || mesh < 0 || mesh >= scene->mesh_count)
        return MOTE_ERR_INVALID_ARGUMENT;
    mote_draw_desc d;
    mote_scene_draw_desc(scene, mesh, base, &d);
    /* a build without blending draws the mesh opaque, once */
    if (MOTE_ENABLE_BLEND && scene->depth_pre_pass && scene->depth_pre_pass[mesh] && mote__blended(&meshes[mesh])) {
        mote_draw_desc depth_only = d;
        depth_only.no_color_write = true;
        const mote_result r = mote_draw(dev, &meshes[mesh], &depth_only);
        if (r != MOTE_OK)
            return r;
        d.depth_less_equal = true;
    }
    return mote_draw(dev, &meshes[mesh], &d);
}

int mote_scene_lod_level(const mote_scene *scene, int lod, const mote_mesh *meshes,
                         const mote_camera *camera)
{
    if (!scene || !meshes || !camera || lod < 0 || lod >= scene->lod_count)
        return -1;
    const mote_lod *g = &scene->lods[lod];
    if (g->level_count <= 0 || !g->levels || g->bounds_mesh < 0 ||
        g->bounds_mesh >= scene->mesh_count)
        return -1;
    /* Mesh.getLOD: an orthographic camera's minZ, else the distance from
     * the camera to the bounding sphere's centre in world space */
    float distance = camera->znear;
    if (camera->projection != MOTE_PROJECTION_ORTHOGRAPHIC) {
        const mote_mesh *m = &meshes[g->bounds_mesh];
        const float *c = m->bounds_center;
        float w[16];
        double sum = 0.0;
        mote_mesh_world_matrix(m, w);
        for (int k = 0; k < 3; k++) {
            double d = (double)w[k] * c[0] + (double)w[4 + k] * c[1] + (double)w[8 + k] * c[2] +
                       (double)w[12 + k] - (double)camera->position[k];
            sum += d * d;
        }
        distance = (float)sqrt(sum);
    }
    /* nearer than the last (smallest) distance: the base; else the first
     * level, farthest first, whose distance is below the camera's (an
     * equal one is not: the comparisons are strict, as in getLOD) */
    if (g->levels[g->level_count - 1].distance > distance)
        return -1;
    for (int k = 0; k < g->level_count; k++)
        if (g->levels[k].distance < distance)
            return k;
    return -1;
}

void mote__lod_show(const mote_scene *sc, mote_mesh *meshes, int g, int chosen)
{
    const mote_lod *lod = &sc->lods[g];
    for (int k = -1; k < lod->level_count; k++) {
        int first = k < 0 ? lod->first_mesh : lod->levels[k].first_mesh;
        int count = k < 0 ? lod->mesh_count : lod->levels[k].mesh_count;
        if (first < 0 || count < 0 || count > sc->mesh_count - first)
            continue;
        for (int i = first; i < first + count; i++)
            meshes[i].hidden = lod->hidden || k != chosen;
    }
}

void mote_scene_choose_lod(const mote_scene *scene, mote_mesh *meshes, const mote_camera *camera)
{
    if (!scene || !meshes || !camera)
        return;
    for (int g = 0; g < scene->lod_count; g++)
        mote__lod_show(scene, meshes, g, mote_scene_lod_level(scene, g, meshes, camera));
}

/* The sphere around the scene's bounding box: its centre and radius (1
 * for an empty or degenerate box). */
static float mote__scene_sphere(const mote_scene *scene, float c[3])
{
    float r2 = 0.0f;
    for (int k = 0; k < 3; k++) {
        float d = 0.5f * (scene->bounds_max[k] - scene->bounds_min[k]);
        c[k] = 0.5f * (scene->bounds_min[k] + scene->bounds_max[k]);
        r2 += d * d;
    }
    float radius = sqrtf(r2);
    return radius > 1e-6f && isfinite(radius) ? radius : 1.0f;
}

/* Planes that hold the sphere (c, radius) seen from dist away: far past
 * its far side, near where it begins (at least 1/100 of the distance, and
 * 1/1000 of far for an eye inside it). */
static void mote__planes_for(float dist, float radius, mote_camera *cam)
{
    cam->zfar = dist + radius * 2.0f;
    cam->znear = dist - radius * 1.5f;
    if (cam->znear < dist * 0.01f)
        cam->znear = dist * 0.01f;
    if (cam->znear < cam->zfar * 0.001f)
        cam->znear = cam->zfar * 0.001f;
}

void mote_scene_fit_planes(const mote_scene *scene, mote_camera *camera)
{
    if (!scene || !camera)
        return;
    float c[3];
    float radius = mote__scene_sphere(scene, c);
    double d2 = 0.0;
    for (int k = 0; k < 3; k++) {
        double d = (double)camera->position[k] - c[k];
        d2 += d * d;
    }
    float dist = (float)sqrt(d2);
    if (isfinite(dist))
        mote__planes_for(dist, radius, camera);
}

void mote_scene_frame(const mote_scene *scene, float aspect, mote_frame_desc *frame)
{
    if (!frame)
        return;
    memset(frame, 0, sizeof *frame);
    if (!scene)
        return;
    float c[3];
    float radius = mote__scene_sphere(scene, c);
    if (scene->has_camera) {
        frame->camera = scene->camera;
        /* the horizontal field of view as the core's vertical one, as
         * Babylon.js projects it: tan(v / 2) = tan(h / 2) / aspect */
        if (scene->camera_fov_is_horizontal && aspect > 0.0f)
            frame->camera.fov = 2.0f * atanf(mote_tanf(0.5f * scene->camera.fov) / aspect);
    } else {
        /* front-top-right of the box, far enough that the bounding sphere
         * fits the narrower of the two fields of view, with a margin */
        const float fov = 0.8f;
        float dir[3] = {1.0f, 0.6f, -1.4f};
        float len = sqrtf(dir[0] * dir[0] + dir[1] * dir[1] + dir[2] * dir[2]);
        float half = 0.5f * fov;
        float s = mote_sinf(half);
        if (aspect > 0.0f && aspect < 1.0f) {
            /* sin(atan(t * aspect)) for the horizontal half angle */
            float th = mote_tanf(half) * aspect;
            float sh = th / sqrtf(1.0f + th * th);
            if (sh < s)
                s = sh;
        }
        float dist = radius / s * 1.1f;
        mote_camera *cam = &frame->camera;
        for (int k = 0; k < 3; k++) {
            cam->position[k] = c[k] + dir[k] / len * dist;
            cam->target[k] = c[k];
        }
        cam->fov = fov;
        mote__planes_for(dist, radius, cam);
    }
    frame->fog = scene->fog;
    int n = scene->light_count;
    if (n > MOTE_MAX_LIGHTS)
        n = MOTE_MAX_LIGHTS;
    for (int i = 0; i < n; i++)
        frame->lights[i] = scene->lights[i];
    frame->light_count = n;
    /* a file whose lights are all disabled is lit by none, as in Babylon.js */
    if (n == 0 && !scene->has_lights) {
        mote_light *l = &frame->lights[0];
        l->type = MOTE_LIGHT_POINT;
        memcpy(l->position, frame->camera.position, sizeof l->position);
        l->position[1] += radius;
        l->color[0] = l->color[1] = l->color[2] = 1.0f;
        l->intensity = 1.0f;
        frame->light_count = 1;
    }
    /* frame->ambient stays 0: the materials' emissive colours hold the
     * scene's ambient colour as Babylon.js adds it (mote__emissive) */
}
