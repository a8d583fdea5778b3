/*
 * mote-render - renders a .babylon scene to a PNG or PPM image, and times it.
 *
 *   mote-render SCENE -o OUT.png|OUT.ppm [--size WxH] [--mode MODE] [--no-cull]
 *               [--camera ex,ey,ez:tx,ty,tz] [--fov RADIANS | --ortho HEIGHT]
 *               [--rotate rx,ry,rz]
 *               [--frames N] [--threads T] [--spin DEGREES]
 *               [--perspective correct|affine|subspan] [--filter nearest|bilinear]
 *               [--mip none|triangle|pixel|trilinear]
 *               [--subpixel-bits N] [--full-clear] [--allow-missing-textures]
 *               [--near N] [--far F] [--max-triangles N] [--scene I] [--warnings|-v]
 *
 * The device bins triangles into an arena and rasterises the tiles on a
 * pool of threads (mote_parallel_pool, the calling thread among them; with
 * --threads 1 on the calling thread alone, the serial path). With --frames N it renders one warm-up
 * frame and then N timed frames (begin, draws, end: no loading, no writing),
 * turning the scene --spin degrees about the world y axis each frame, and
 * prints "ms/frame: median X (min Y, max Z)". The image written is always
 * the unturned frame, so it does not depend on --frames or --spin. Frames
 * clear only the tiles drawn into since their last clear (the tool is the
 * only writer of its buffers); --full-clear clears the whole frame. Each
 * frame draws the levels of detail its camera (the scene's, or --camera,
 * --fov, --ortho's) chooses for the meshes as turned in it. A
 * texture file that is missing or cannot be read fails the load, unless
 * --allow-missing-textures: its material is then drawn in its colour, and
 * the loader's warning says which file it was. --camera on a scene
 * without a camera of its own fits the near and far planes to the scene
 * from the eye given (mote_scene_fit_planes); --near and --far set them. The image is written as
 * mote_write_image writes (a new file renamed over OUT), and never over
 * the scene's own file or one of its textures.
 */
#define _POSIX_C_SOURCE 200809L

#include <mote/mote.h>
#include <mote/mote_io.h>

#include <errno.h>
#include <limits.h>
#include <stdarg.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>
#include <time.h>

typedef struct options {
    const char *scene_path;
    const char *out_path;
    int width, height;
    mote_draw_desc draw;
    bool has_camera;
    float eye[3], target[3];
    float fov;                    /* 0: the scene's (or the default) */
    float ortho_height;           /* > 0: an orthographic view this many units high */
    float rotate[3];
    int frames;                   /* 0: no timing */
    int threads;                  /* 0: all */
    float spin_degrees;
    int subpixel_bits;            /* 0: default */
    bool full_clear;              /* clear every tile, not only those drawn into */
    bool allow_missing_textures;  /* draw in the material's colour, warn */
    uint32_t max_triangles;       /* 0: the loader's default */
    int gltf_scene;               /* --scene I: I + 1; 0: the file's default */
    float znear, zfar;            /* > 0: --near, --far */
    bool all_warnings;            /* --warnings: each on a line of its own */
} options;

static void usage(FILE *out)
{
    fprintf(out,
            "usage: mote-render SCENE -o OUT.png|OUT.ppm [options]\n"
            "  --size WxH              image size (default 640x480)\n"
            "  --mode MODE             points|wireframe|flat|gouraud|textured\n"
            "                          (default: gouraud, textured where a material has a texture)\n"
            "  --no-cull               draw back faces too\n"
            "  --camera EX,EY,EZ:TX,TY,TZ  eye and target (default: the scene's camera,\n"
            "                          else one that frames the scene); without a camera in\n"
            "                          the scene, near and far fitted to the scene from EX,EY,EZ\n"
            "  --near N, --far F       the near and far planes (default: the camera's)\n"
            "  --fov RADIANS           vertical field of view (whatever the file's fovMode;\n"
            "                          a perspective view also of an orthographic camera)\n"
            "  --ortho HEIGHT          an orthographic view, HEIGHT world units high and\n"
            "                          centred (of a perspective camera too)\n"
            "  --rotate RX,RY,RZ       add to every mesh's rotation (radians)\n"
            "  --frames N              time N frames after a warm-up and print ms/frame\n"
            "  --spin DEGREES          turn the scene about y by this much per timed frame\n"
            "  --threads T             rasteriser threads (default: all)\n"
            "  --perspective P         correct|affine|subspan (default correct)\n"
            "  --filter F              nearest|bilinear (default nearest)\n"
            "  --mip M                 none|triangle|pixel|trilinear: texels from the mip level\n"
            "                          nearest each triangle's or pixel's scale,\n"
            "                          or the two around it blended\n"
            "                          (default none)\n"
            "  --subpixel-bits N       snapping grid, 4..8 (default 8)\n"
            "  --full-clear            clear the whole frame each time (default: only the tiles\n"
            "                          drawn into since their last clear)\n"
            "  --allow-missing-textures  draw a material whose texture file is missing or\n"
            "                          unreadable in its colour, with a warning (default:\n"
            "                          such a scene fails to load)\n"
            "  --max-triangles N       load scenes of up to N triangles, instances counted\n"
            "                          (default 1048576)\n"
            "  --scene I               a glTF file's scene I, counted from 0 (default: the\n"
            "                          file's scene, else its first)\n"
            "  --warnings, -v          print every warning of the loader, one a line (default:\n"
            "                          those that fit in a line, and how many more)\n"
            "  --help                  this text\n");
}

static int fail(const char *fmt, ...)
{
    va_list ap;
    va_start(ap, fmt);
    fprintf(stderr, "mote-render: ");
    vfprintf(stderr, fmt, ap);
    fprintf(stderr, "\n");
    va_end(ap);
    return 1;
}

/* Parses exactly `count` comma-separated floats; false on anything else. */
static bool parse_floats(const char *s, float *v, int count)
{
    for (int i = 0; i < count; i++) {
        char *end;
        errno = 0;
        double d = strtod(s, &end);
        if (end == s || errno != 0 || d != d || d > 1e30 || d < -1e30)
            return false;
        v[i] = (float)d;
        s = end;
        if (i + 1 < count) {
            if (*s != ',')
                return false;
            s++;
        }
    }
    return *s == '\0';
}

static bool parse_int(const char *s, int lo, int hi, int *out)
{
    char *end;
    errno = 0;
    long v = strtol(s, &end, 10);
    if (end == s || *end != '\0' || errno != 0 || v < lo || v > hi)
        return false;
    *out = (int)v;
    return true;
}

static bool parse_size(const char *s, int *w, int *h)
{
    char buf[64];
    const char *x = strchr(s, 'x');
    if (!x || (size_t)(x - s) >= sizeof buf)
        return false;
    memcpy(buf, s, (size_t)(x - s));
    buf[x - s] = '\0';
    return parse_int(buf, 1, MOTE_MAX_SIZE, w) && parse_int(x + 1, 1, MOTE_MAX_SIZE, h);
}

/* Picks the index of `s` in a NULL-terminated list; -1 when absent. */
static int pick(const char *s, const char *const *names)
{
    for (int i = 0; names[i]; i++)
        if (strcmp(s, names[i]) == 0)
            return i;
    return -1;
}

static bool has_suffix(const char *s, const char *suffix)
{
    size_t n = strlen(s), k = strlen(suffix);
    return n >= k && strcmp(s + n - k, suffix) == 0;
}

/* Returns 0 on success, 1 on a bad argument (message printed), 2 for --help. */
static int parse_args(int argc, char **argv, options *o)
{
    static const char *const modes[] = {"points", "wireframe", "flat", "gouraud",
                                        "textured", NULL};
    static const mote_mode mode_values[] = {MOTE_MODE_POINTS, MOTE_MODE_WIREFRAME,
                                            MOTE_MODE_FLAT, MOTE_MODE_GOURAUD,
                                            MOTE_MODE_TEXTURED};
    static const char *const persp[] = {"correct", "affine", "subspan", NULL};
    static const mote_perspective persp_values[] = {MOTE_PERSPECTIVE_CORRECT,
                                                    MOTE_PERSPECTIVE_AFFINE,
                                                    MOTE_PERSPECTIVE_SUBSPAN};
    static const char *const filters[] = {"nearest", "bilinear", NULL};
    static const mote_filter filter_values[] = {MOTE_FILTER_NEAREST, MOTE_FILTER_BILINEAR};
    static const char *const mips[] = {"none", "triangle", "pixel", "trilinear", NULL};
    static const mote_mip mip_values[] = {MOTE_MIP_NONE, MOTE_MIP_TRIANGLE, MOTE_MIP_PIXEL, MOTE_MIP_TRILINEAR};
    static const char *const valued[] = {"-o", "--size", "--mode", "--camera", "--fov", "--ortho",
                                         "--rotate", "--frames", "--threads", "--spin",
                                         "--perspective", "--filter", "--mip", "--max-triangles",
                                         "--subpixel-bits", "--near", "--far", "--scene", NULL};

    memset(o, 0, sizeof *o);
    o->width = 640;
    o->height = 480;
    for (int i = 1; i < argc; i++) {
        const char *a = argv[i];
        if (strcmp(a, "--help") == 0 || strcmp(a, "-h") == 0)
            return 2;
        if (strcmp(a, "--no-cull") == 0) {
            o->draw.cull = MOTE_CULL_NONE;
            continue;
        }
        if (strcmp(a, "--full-clear") == 0) {
            o->full_clear = true;
            continue;
        }
        if (strcmp(a, "--allow-missing-textures") == 0) {
            o->allow_missing_textures = true;
            continue;
        }
        if (strcmp(a, "--warnings") == 0 || strcmp(a, "-v") == 0) {
            o->all_warnings = true;
            continue;
        }
        if (a[0] != '-' || a[1] == '\0') {
            if (o->scene_path)
                return fail("more than one scene given (\"%s\"); see --help", a);
            o->scene_path = a;
            continue;
        }
        /* every other option takes a value */
        if (pick(a, valued) < 0)
            return fail("unknown option %s; see --help", a);
        if (i + 1 >= argc)
            return fail("%s needs a value; see --help", a);
        const char *v = argv[++i];
        int k;
        if (strcmp(a, "-o") == 0) {
            o->out_path = v;
        } else if (strcmp(a, "--size") == 0) {
            if (!parse_size(v, &o->width, &o->height))
                return fail("--size \"%s\": expected WxH, each 1..%d", v, MOTE_MAX_SIZE);
        } else if (strcmp(a, "--mode") == 0) {
            if ((k = pick(v, modes)) < 0)
                return fail("--mode \"%s\": expected points, wireframe, flat, gouraud "
                            "or textured", v);
            o->draw.mode = mode_values[k];
        } else if (strcmp(a, "--camera") == 0) {
            const char *colon = strchr(v, ':');
            char eye[128];
            if (!colon || (size_t)(colon - v) >= sizeof eye)
                return fail("--camera \"%s\": expected ex,ey,ez:tx,ty,tz", v);
            memcpy(eye, v, (size_t)(colon - v));
            eye[colon - v] = '\0';
            if (!parse_floats(eye, o->eye, 3) || !parse_floats(colon + 1, o->target, 3))
                return fail("--camera \"%s\": expected ex,ey,ez:tx,ty,tz", v);
            o->has_camera = true;
        } else if (strcmp(a, "--fov") == 0) {
            if (!parse_floats(v, &o->fov, 1) || !(o->fov > 0.0f && o->fov < 3.14159f))
                return fail("--fov \"%s\": expected radians in (0, pi)", v);
        } else if (strcmp(a, "--ortho") == 0) {
            if (!parse_floats(v, &o->ortho_height, 1) || !(o->ortho_height > 0.0f && o->ortho_height < 1e30f))
                return fail("--ortho \"%s\": expected a height above 0", v);
        } else if (strcmp(a, "--near") == 0 || strcmp(a, "--far") == 0) {
            float *plane = a[2] == 'n' ? &o->znear : &o->zfar;
            if (!parse_floats(v, plane, 1) || !(*plane > 0.0f))
                return fail("%s \"%s\": expected a distance above 0", a, v);
        } else if (strcmp(a, "--rotate") == 0) {
            if (!parse_floats(v, o->rotate, 3))
                return fail("--rotate \"%s\": expected rx,ry,rz in radians", v);
        } else if (strcmp(a, "--frames") == 0) {
            if (!parse_int(v, 1, 1000000, &o->frames))
                return fail("--frames \"%s\": expected a count from 1 to 1000000", v);
        } else if (strcmp(a, "--threads") == 0) {
            if (!parse_int(v, 1, 4096, &o->threads))
                return fail("--threads \"%s\": expected a count from 1 to 4096", v);
        } else if (strcmp(a, "--spin") == 0) {
            if (!parse_floats(v, &o->spin_degrees, 1))
                return fail("--spin \"%s\": expected degrees", v);
        } else if (strcmp(a, "--perspective") == 0) {
            if ((k = pick(v, persp)) < 0)
                return fail("--perspective \"%s\": expected correct, affine or subspan", v);
            o->draw.perspective = persp_values[k];
        } else if (strcmp(a, "--mip") == 0) {
            if ((k = pick(v, mips)) < 0)
                return fail("--mip \"%s\": expected none, triangle, pixel or trilinear", v);
            o->draw.mip = mip_values[k];
        } else if (strcmp(a, "--filter") == 0) {
            if ((k = pick(v, filters)) < 0)
                return fail("--filter \"%s\": expected nearest or bilinear", v);
            o->draw.filter = filter_values[k];
        } else if (strcmp(a, "--max-triangles") == 0) {
            if (!parse_int(v, 1, INT_MAX, &k))
                return fail("--max-triangles \"%s\": expected a count from 1 to %d", v, INT_MAX);
            o->max_triangles = (uint32_t)k;
        } else if (strcmp(a, "--scene") == 0) {
            if (!parse_int(v, 0, INT_MAX - 1, &k))
                return fail("--scene \"%s\": expected a scene's index from 0", v);
            o->gltf_scene = k + 1;
        } else if (strcmp(a, "--subpixel-bits") == 0) {
            if (!parse_int(v, 4, 8, &o->subpixel_bits))
                return fail("--subpixel-bits \"%s\": expected 4 to 8", v);
        }
    }
    if (!o->scene_path)
        return fail("no scene given; see --help");
    if (o->fov > 0.0f && o->ortho_height > 0.0f)
        return fail("--fov and --ortho: one view or the other");
    if (o->znear > 0.0f && o->zfar > 0.0f && !(o->znear < o->zfar))
        return fail("--near %g and --far %g: near must be below far", o->znear, o->zfar);
    if (!o->out_path)
        return fail("no output given (-o OUT.png or OUT.ppm); see --help");
    if (!has_suffix(o->out_path, ".png") && !has_suffix(o->out_path, ".ppm"))
        return fail("-o \"%s\": the name must end in .png or .ppm", o->out_path);
    return 0;
}

/* The loader's message, its hint at the limit that downgrades a missing
 * texture said as the option that sets it. */
static void print_load_error(const char *message)
{
    static const char hint[] = "limits.missing_texture_is_warning";
    const char *at = strstr(message, hint);
    if (!at) {
        fprintf(stderr, "mote-render: %s\n", message);
        return;
    }
    fprintf(stderr, "mote-render: %.*s--allow-missing-textures%s\n", (int)(at - message), message,
            at + strlen(hint));
}

/* The loader's warnings: the line that holds those that fit, or with
 * --warnings each on a line of its own. */
static void print_warnings(const mote_scene *scene, bool all)
{
    unsigned dropped = 0, repeats = 0;
    int n = mote_scene_warning_count(scene, &dropped);
    if (!all) {
        if (scene->warning[0])
            fprintf(stderr, "mote-render: warning: %s%s\n", scene->warning,
                    strstr(scene->warning, " more warning") ? " (--warnings lists them all)" : "");
        return;
    }
    for (int i = 0; i < n; i++) {
        const char *w = mote_scene_warning(scene, i, &repeats);
        if (repeats > 1)
            fprintf(stderr, "mote-render: warning: %s (x%u)\n", w, repeats);
        else
            fprintf(stderr, "mote-render: warning: %s\n", w);
    }
    if (dropped)
        fprintf(stderr, "mote-render: warning: and %u more, not kept\n", dropped);
}

/* q = a * b for quaternions stored (x, y, z, w). */
static void quat_mul(const float a[4], const float b[4], float q[4])
{
    float x = a[3] * b[0] + a[0] * b[3] + a[1] * b[2] - a[2] * b[1];
    float y = a[3] * b[1] - a[0] * b[2] + a[1] * b[3] + a[2] * b[0];
    float z = a[3] * b[2] + a[0] * b[1] - a[1] * b[0] + a[2] * b[3];
    float w = a[3] * b[3] - a[0] * b[0] - a[1] * b[1] - a[2] * b[2];
    q[0] = x; q[1] = y; q[2] = z; q[3] = w;
}

/* The quaternion of Babylon's yaw (y), pitch (x), roll (z) rotation. */
static void quat_yaw_pitch_roll(const float r[3], float q[4])
{
    float sp = mote_sinf(r[0] * 0.5f), cp = mote_cosf(r[0] * 0.5f);
    float sy = mote_sinf(r[1] * 0.5f), cy = mote_cosf(r[1] * 0.5f);
    float sr = mote_sinf(r[2] * 0.5f), cr = mote_cosf(r[2] * 0.5f);
    q[0] = cy * sp * cr + sy * cp * sr;
    q[1] = sy * cp * cr - cy * sp * sr;
    q[2] = cy * cp * sr - sy * sp * cr;
    q[3] = cy * cp * cr + sy * sp * sr;
}

/* Copies the loaded meshes into `out`, each root mesh turned by `rotate`
 * (added to its own rotation) and the whole scene then turned by `spin`
 * radians about the world y axis. Children follow their parents. */
static void pose_meshes(const mote_scene *scene, mote_mesh *out, const float rotate[3],
                        float spin)
{
    mote_mesh turn;
    memset(&turn, 0, sizeof turn);
    turn.rotation[1] = spin;
    float m[16];
    mote_mesh_world_matrix(&turn, m);   /* the core's own rotation about y */
    for (int i = 0; i < scene->mesh_count; i++) {
        const mote_mesh *src = &scene->meshes[i];
        mote_mesh *dst = &out[i];
        *dst = *src;
        if (src->parent) {   /* keep the hierarchy inside the copy */
            ptrdiff_t p = src->parent - scene->meshes;
            dst->parent = (p >= 0 && p < scene->mesh_count) ? &out[p] : src->parent;
            continue;
        }
        const float *p = src->position;
        dst->position[0] = m[0] * p[0] + m[4] * p[1] + m[8] * p[2];
        dst->position[1] = m[1] * p[0] + m[5] * p[1] + m[9] * p[2];
        dst->position[2] = m[2] * p[0] + m[6] * p[1] + m[10] * p[2];
        float add[3] = {rotate[0], rotate[1] + spin, rotate[2]};
        if (src->use_quaternion) {
            float q[4];
            quat_yaw_pitch_roll(add, q);
            quat_mul(q, src->rotation_quaternion, dst->rotation_quaternion);
        } else {
            for (int k = 0; k < 3; k++)
                dst->rotation[k] = src->rotation[k] + add[k];
        }
    }
}

/* meshes: the scene's, posed (same order, so the scene's per-mesh draw
 * options still apply); drawn in Babylon.js's order (opaque, alpha
 * tested, then blended from back to front), or the scene's when that
 * cannot be had */
static mote_result render_frame(mote_device *dev, const mote_frame_desc *frame,
                                const mote_scene *scene, const mote_mesh *meshes,
                                const mote_draw_desc *draw)
{
    mote_result r = mote_begin(dev, frame);
    int *order = malloc((size_t)(scene->mesh_count > 0 ? scene->mesh_count : 1) * sizeof *order);
    int n = order ? mote_scene_draw_order(scene, meshes, &frame->camera, order) : 0;
    for (int k = 0; k < scene->mesh_count && r == MOTE_OK; k++) {
        int i = n == scene->mesh_count ? order[k] : k;
        r = mote_scene_draw(dev, scene, meshes, i, draw);
    }
    free(order);
    mote_result e = mote_end(dev);
    return r != MOTE_OK ? r : e;
}

/* The binning arena: twice what the scene's triangles need, so that a
 * frame's binning rarely fills it, but at most ARENA_CAP however many
 * instances a scene draws: once full, the core rasterises what it has
 * binned and starts again (mote_stats.arena_flushes), slower but the same
 * bytes. */
#define ARENA_CAP ((size_t)256 << 20)

static size_t arena_bytes(size_t triangles)
{
    const size_t per_triangle = mote_arena_bytes_per_triangle(), spare = (size_t)1 << 20;
    if (triangles > (ARENA_CAP - spare) / per_triangle / 2)
        return ARENA_CAP;
    return per_triangle * triangles * 2 + spare;
}

static double now_ms(void)
{
    struct timespec ts;
    clock_gettime(CLOCK_MONOTONIC, &ts);
    return (double)ts.tv_sec * 1e3 + (double)ts.tv_nsec * 1e-6;
}

static int compare_double(const void *a, const void *b)
{
    double x = *(const double *)a, y = *(const double *)b;
    return (x > y) - (x < y);
}

int main(int argc, char **argv)
{
    options o;
    int status = parse_args(argc, argv, &o);
    if (status == 2) {
        usage(stdout);
        return 0;
    }
    if (status != 0)
        return 1;

    char message[512] = "";
    mote_scene scene;
    mote_limits limits = mote_limits_default();
    limits.missing_texture_is_warning = o.allow_missing_textures;
    if (o.max_triangles)
        limits.max_triangles = o.max_triangles;
    limits.gltf_scene = o.gltf_scene;
    mote_result r = mote_scene_load(o.scene_path, &limits, &scene, message, sizeof message);
    if (r != MOTE_OK) {
        print_load_error(message[0] ? message : mote_result_string(r));
        return 1;
    }
    print_warnings(&scene, o.all_warnings);

    int exit_code = 1;
    if (mote_scene_reads_file(&scene, o.out_path)) {
        fprintf(stderr, "mote-render: -o \"%s\" is the scene's own file or one of its "
                        "textures: not overwritten\n", o.out_path);
        mote_scene_free(&scene);
        return 1;
    }
    size_t pixels = (size_t)o.width * (size_t)o.height;
    size_t triangles = 0;
    for (int i = 0; i < scene.mesh_count; i++)
        triangles += scene.meshes[i].index_count / 3;
    size_t arena_size = arena_bytes(triangles);
    uint8_t *color = malloc(pixels * 4);
    uint32_t *depth = malloc(pixels * sizeof *depth);
    void *arena = malloc(arena_size);
    mote_mesh *posed = calloc((size_t)scene.mesh_count + 1, sizeof *posed);
    double *times = calloc((size_t)o.frames + 1, sizeof *times);
    mote_pool *pool = NULL;
    if (!color || !depth || !arena || !posed || !times) {
        fprintf(stderr, "mote-render: out of memory for a %dx%d image and %zu triangles\n",
                o.width, o.height, triangles);
        goto done;
    }

    mote_device dev;
    mote_device_desc desc;
    memset(&desc, 0, sizeof desc);
    desc.width = o.width;
    desc.height = o.height;
    desc.color = color;
    desc.depth = depth;
    desc.clear_color = scene.clear_color;
    desc.subpixel_bits = o.subpixel_bits;
    desc.arena = arena;
    desc.arena_size = arena_size;
    desc.clear_drawn_tiles_only = !o.full_clear;
    /* one thread: the serial path, which cuts no draw into pieces for
     * threads that are not there */
    if (o.threads != 1) {
        char msg[256];
        mote_pool_desc pd = {o.threads, NULL, NULL};
        r = mote_pool_create(&pd, &pool, msg, sizeof msg);
        if (r != MOTE_OK) {
            fprintf(stderr, "mote-render: %s\n", msg);
            goto done;
        }
        desc.parallel_for = mote_parallel_pool;
        desc.parallel_user = pool;
    }
    r = mote_device_init(&dev, &desc);
    if (r != MOTE_OK) {
        fprintf(stderr, "mote-render: cannot set up the device: %s\n", mote_result_string(r));
        goto done;
    }

    /* the options speak of the file's coordinates; a right-handed file is
     * loaded mirrored in z, so they are mirrored with it (rotations as the
     * loader mirrors them: angles about x and y change sign) */
    if (scene.mirrored_z) {
        o.eye[2] = 0.0f - o.eye[2];
        o.target[2] = 0.0f - o.target[2];
        o.rotate[0] = 0.0f - o.rotate[0];
        o.rotate[1] = 0.0f - o.rotate[1];
        o.spin_degrees = 0.0f - o.spin_degrees;
    }

    mote_frame_desc frame;
    memset(&frame, 0, sizeof frame);
    mote_scene_frame(&scene, (float)o.width / (float)o.height, &frame);
    if (o.has_camera) {
        memcpy(frame.camera.position, o.eye, sizeof o.eye);
        memcpy(frame.camera.target, o.target, sizeof o.target);
        memset(frame.camera.up, 0, sizeof frame.camera.up);
        /* the framing camera's planes were made for its own eye; a file's
         * camera keeps its minZ and maxZ */
        if (!scene.has_camera)
            mote_scene_fit_planes(&scene, &frame.camera);
    }
    if (o.fov > 0.0f) {
        frame.camera.fov = o.fov;
        frame.camera.projection = MOTE_PROJECTION_PERSPECTIVE;
    }
    if (o.ortho_height > 0.0f) {
        const float h = 0.5f * o.ortho_height, w = h * (float)o.width / (float)o.height;
        const float box[4] = {-w, w, -h, h};
        frame.camera.projection = MOTE_PROJECTION_ORTHOGRAPHIC;
        memcpy(frame.camera.ortho, box, sizeof box);
    }
    if (o.znear > 0.0f)
        frame.camera.znear = o.znear;
    if (o.zfar > 0.0f)
        frame.camera.zfar = o.zfar;
    if (!(frame.camera.znear < frame.camera.zfar)) {
        fprintf(stderr, "mote-render: the near plane %g is not below the far plane %g (--near, "
                        "--far)\n", frame.camera.znear, frame.camera.zfar);
        goto done;
    }

    if (o.frames > 0) {
        const float spin = o.spin_degrees * 3.14159265358979f / 180.0f;
        for (int f = 0; f <= o.frames && r == MOTE_OK; f++) {
            /* frame 0 warms caches and pages the arena in; it is not timed */
            pose_meshes(&scene, posed, o.rotate, spin * (float)f);
            /* turned, a mesh's distance to the camera changes, and with it
             * the level of detail drawn */
            mote_scene_choose_lod(&scene, posed, &frame.camera);
            double t0 = now_ms();
            r = render_frame(&dev, &frame, &scene, posed, &o.draw);
            times[f] = now_ms() - t0;
        }
        if (r == MOTE_OK) {
            qsort(times + 1, (size_t)o.frames, sizeof *times, compare_double);
            double median = (o.frames % 2) ? times[1 + o.frames / 2]
                                           : 0.5 * (times[o.frames / 2] + times[1 + o.frames / 2]);
            printf("ms/frame: median %.3f (min %.3f, max %.3f)\n", median, times[1],
                   times[o.frames]);
        }
    }
    if (r == MOTE_OK) {
        pose_meshes(&scene, posed, o.rotate, 0.0f);
        mote_scene_choose_lod(&scene, posed, &frame.camera);
        r = render_frame(&dev, &frame, &scene, posed, &o.draw);
    }
    if (r != MOTE_OK) {
        fprintf(stderr, "mote-render: rendering failed: %s\n", mote_result_string(r));
        goto done;
    }
    r = mote_write_image(o.out_path, &dev, message, sizeof message);
    if (r != MOTE_OK) {
        fprintf(stderr, "mote-render: %s\n", message[0] ? message : mote_result_string(r));
        goto done;
    }
    exit_code = 0;

done:
    mote_pool_destroy(pool);
    free(times);
    free(posed);
    free(arena);
    free(depth);
    free(color);
    mote_scene_free(&scene);
    return exit_code;
}
