/*
 * mote_io.h - host-side companions of the mote core: .babylon and glTF 2.0
 * scene files (cJSON), textures (stb_image), PNG/PPM output (stb_image_write and a
 * hand-written P6 writer), and the OpenMP tile loop.
 *
 * Everything here may allocate; every object it creates has a function that
 * frees it, and every failing call frees what it allocated before returning.
 * Messages name the file and the place: "monkey.babylon: meshes[0].indices[57]:
 * 9999 is out of range (886 vertices)".
 */
#ifndef MOTE_IO_H
#define MOTE_IO_H

#include "mote.h"

#ifdef __cplusplus
extern "C" {
#endif

/* Resource limits for loaders. mote_limits_default() gives the defaults;
 * a zero field also means "default". */
typedef struct mote_limits {
    size_t max_file_bytes;        /* default 256 MiB */
    uint32_t max_vertices;        /* per mesh, default 16 Mi */
    uint32_t max_indices;         /* per mesh, default 48 Mi */
    uint32_t max_meshes;          /* default 65536 */
    int max_texture_width;        /* default 16384 */
    int max_texture_height;       /* default 16384 */
    size_t max_texture_bytes;     /* decoded, default 256 MiB */
    /* All the textures of one scene, decoded, default 512 MiB: checked
     * from each image's header before it is decoded. A file several
     * materials name, under any name ("b.png", "./b.png", a link to it),
     * is decoded once and counted once. Loading then holds at most this
     * much in textures, plus, while one more decodes, its file's bytes
     * and stb_image's working copies (an 8-bit RGB PNG's unfiltered rows:
     * 0.75 times its decoded size). */
    size_t max_total_texture_bytes;
    int max_json_depth;           /* default 64 */
    /* What parsing a scene's JSON may allocate, default 512 MiB: told
     * from the text before it is parsed (cJSON takes an item of 64 bytes
     * a value, numbers too: 40 times the text of "0,0,0,..."), so a file
     * past it is refused without the memory being taken. */
    size_t max_json_bytes;
    /* The triangles of all the scene's meshes together, default 1 Mi
     * (1,048,576): instances, thin instances, levels of detail and
     * hidden meshes each count, as any may be drawn. It bounds the time
     * a frame can take, which the counts above do not: 100,000 triangles
     * with 10 instances are 1.1 million to draw. */
    uint32_t max_triangles;
    bool allow_any_texture_path;  /* false: only inside the scene's folder */
    bool missing_texture_is_warning; /* true: render untextured, warn */
    /* glTF: which of the file's scenes to load, counted from 1; 0 (the
     * default): the file's `scene`, else its first. Past the last, the
     * load fails (MOTE_ERR_RANGE); a .babylon file, one scene, warns. */
    int gltf_scene;
} mote_limits;

mote_limits mote_limits_default(void);

/* ---- textures ---------------------------------------------------------- */

/* Loads PNG, JPEG, BMP, TGA, ... into an RGBA8888 texture (its real size).
 * Dimensions are checked against the limits before decoding. Radiance HDR
 * and 16-bit PNM images are refused (MOTE_ERR_UNSUPPORTED): stb_image
 * 2.27's decoders of those hang or overrun on hostile files. Files built to
 * reach the other known faults of that stb_image are refused as corrupt
 * (MOTE_ERR_PARSE), and palettes it would read past are padded with black
 * (docs/security.md, "Image decoding"). */
mote_result mote_texture_load(const char *path, const mote_limits *limits,
                              mote_texture *out, char *message, size_t message_size);
mote_result mote_texture_load_memory(const void *data, size_t size,
                                     const mote_limits *limits, mote_texture *out,
                                     char *message, size_t message_size);
/* Frees pixels allocated by a loader and zeroes the struct. */
void mote_texture_free(mote_texture *texture);

/* ---- scenes ------------------------------------------------------------ */

/* One level of detail of a mesh (Babylon.js's MeshLODLevel): what is drawn
 * in the base mesh's place, at its world matrix, when the camera is
 * farther than `distance` from it and no level before it in
 * mote_lod.levels is chosen. */
typedef struct mote_lod_level {
    float distance;               /* the lodDistances value */
    /* what it draws: scene->meshes[first_mesh .. first_mesh + mesh_count)
     * (its sub-meshes, or its thin instances); mesh_count 0: nothing
     * (past the last lodDistances, or a level naming an instance, which
     * stays where it is drawn anyway) */
    int first_mesh, mesh_count;
} mote_lod_level;

/* A mesh with levels of detail (lodMeshIds with lodDistances), or an
 * instance of one (an instance chooses its own level, by its own
 * bounding sphere, and draws it in its place). Exactly one of the base
 * and its levels is drawn in a frame (or none): mote_scene_choose_lod. */
typedef struct mote_lod {
    int first_mesh, mesh_count;   /* what the base mesh draws, as mote_lod_level's */
    int bounds_mesh;              /* the camera's distance is measured to this mesh's
                                     bounding-sphere centre, in world space */
    bool hidden;                  /* the base is hidden (isVisible false, disabled):
                                     no level is drawn either */
    const mote_lod_level *levels; /* in the order getLOD tries them: farthest first */
    int level_count;
} mote_lod;

/* A loaded scene: meshes ready for mote_draw (one mesh per sub-mesh, sharing
 * vertex and vertex colour arrays; after the file's meshes, transform
 * nodes and instances, the thin instances (meshes of their own, sharing
 * the arrays of the mesh they belong to) and hidden 0-vertex meshes may
 * follow: cameras and lights in the parent tree, and stand-ins for
 * sheared pivot or local matrices), their textures, the active camera and
 * the lights. */
typedef struct mote_scene {
    mote_mesh *meshes;
    int mesh_count;
    mote_texture *textures;       /* meshes[i].material.texture points in here */
    int texture_count;
    /* each texture's mip chain, built at load (texture_count of them;
     * count 1 for a texture without levels); materials.mipmaps point in
     * here, read by draws with mote_draw_desc.mip MOTE_MIP_TRIANGLE */
    const mote_mipmaps *mipmaps;
    mote_camera camera;           /* the scene's active camera, if has_camera */
    bool has_camera;
    /* camera.fov is the horizontal field of view, which mote_scene_frame
     * turns into the vertical one for its aspect ratio. */
    bool camera_fov_is_horizontal;
    mote_light lights[MOTE_MAX_LIGHTS];
    int light_count;
    bool has_lights;              /* the file lists lights, perhaps all disabled */
    /* The scene's ambient colour. The materials' emissive colours already
     * hold what it adds (docs/babylon.md, Materials), so mote_scene_frame
     * leaves the frame's ambient at 0. */
    float ambient[3];
    mote_rgba clear_color;
    /* world space, over the meshes not hidden, each level-of-detail group
     * counted by its base, as if the camera were near */
    float bounds_min[3], bounds_max[3];
    /* The file is right-handed and was loaded mirrored in z, as mote's core
     * is left-handed: a point (x, y, z) of the file is (x, y, -z) here, and
     * a camera of the caller's, given in the file's coordinates, needs its
     * z negated too (docs/babylon.md, Winding and right-handed scenes). */
    bool mirrored_z;
    /* Non-fatal notes (downgraded textures, ...), "; " between them: each
     * distinct one once, " (x12)" after one given 12 times, and "; N more
     * warnings" for those that do not fit. Every one of them, one by one:
     * mote_scene_warning. */
    char warning[256];
    /* One per mesh, or NULL for triangles throughout: what the mesh's
     * indices draw. MOTE_MODE_DEFAULT triangles; MOTE_MODE_POINTS its
     * every vertex, a point each (glTF's POINTS; no indices);
     * MOTE_MODE_WIREFRAME line segments, each segment (a, b) stored as the
     * triangle (a, b, b) (glTF's LINES, LINE_STRIP and LINE_LOOP).
     * mote_scene_draw_desc sets the draw's mode for these. */
    const mote_mode *modes;
    /* One flag per mesh (mesh_count): drawn with both sides (its material
     * says so). The core's culling is a draw option (mote_draw_desc.cull),
     * not a material property: mote_scene_draw_desc applies these. */
    const bool *two_sided;
    /* One flag per mesh: drawn without lights, in its material colour x
     * texture x vertex colour (its material says so);
     * mote_scene_draw_desc sets mote_draw_desc.unlit for these. */
    const bool *unlit;
    /* One flag per mesh, or NULL: drawn without writing depth (its
     * material says disableDepthWrite); mote_scene_draw_desc applies it. */
    const bool *no_depth_write;
    /* One mask per mesh, or NULL: the lights that do not light it
     * (mote_draw_desc.lights_off: a light's includedOnlyMeshesIds or
     * excludedMeshesIds, a material's maxSimultaneousLights);
     * mote_scene_draw_desc applies it. */
    const uint32_t *lights_off;
    /* One flag per mesh, or NULL: the fog leaves it alone (its applyFog or
     * its material's fogEnabled is false); mote_scene_draw_desc applies it. */
    const bool *no_fog;
    /* One flag per mesh, or NULL: a blended mesh drawn after a depth
     * pre-pass (its material says needDepthPrePass), so that only its
     * nearest surface is blended; mote_scene_draw draws it so. */
    const bool *depth_pre_pass;
    /* One per mesh, or NULL: its alphaIndex (FLT_MAX where unsaid), which
     * orders blended meshes before their distance (mote_scene_draw_order). */
    const float *alpha_index;
    /* The scene's fog (fogMode, fogColor, fogDensity, fogStart, fogEnd),
     * which mote_scene_frame puts in the frame. */
    mote_fog fog;
    /* The groups of meshes of which one is drawn by the camera's distance
     * (Babylon.js's levels of detail). mote_scene_load chooses for the
     * scene's camera (without one, each base); mote_scene_choose_lod
     * chooses again for any camera. */
    const mote_lod *lods;
    int lod_count;
    /* One per mesh, or NULL: the mip mode its texture's sampler asks for
     * (glTF's minFilter: *_MIPMAP_NEAREST MOTE_MIP_PIXEL, *_MIPMAP_LINEAR
     * MOTE_MIP_TRILINEAR), MOTE_MIP_DEFAULT for none; mote_scene_draw_desc
     * applies it where the draw leaves mip at its default. */
    const mote_mip *mip_modes;
    void *files_;                 /* private: the files read (mote_scene_reads_file) */
    void *warnings_;              /* private: every warning (mote_scene_warning) */
    void *storage_;               /* private: owned allocations */
} mote_scene;

/* Loads a scene file. Its format is told by its bytes, whatever its
 * name: a .babylon scene (Babylon.js's JSON, either layout;
 * docs/babylon.md) or a glTF 2.0 one (.gltf JSON with its buffers and
 * images, or a binary .glb; docs/gltf.md) loads; anything else fails
 * saying what it is: MOTE_ERR_UNSUPPORTED for a glTF 1.0 file, a
 * Wavefront OBJ file or an image, MOTE_ERR_IO for a Git LFS pointer in
 * place of the file, MOTE_ERR_PARSE for none of these. Textures and glTF
 * buffers resolve relative to the scene's folder. limits may be NULL. On
 * failure *out is zeroed and the message names the file and the place
 * (for a .glb's container, the byte offset). */
mote_result mote_scene_load(const char *path, const mote_limits *limits,
                            mote_scene *out, char *message, size_t message_size);
/* The same from size bytes of memory; base_dir resolves texture names
 * and glTF buffer files (NULL: no textures are loaded, materials keep
 * their colour, and a glTF buffer in a file is an error); name is used
 * in messages. */
mote_result mote_scene_load_memory(const char *data, size_t size, const char *name,
                                   const char *base_dir, const mote_limits *limits,
                                   mote_scene *out, char *message, size_t message_size);
void mote_scene_free(mote_scene *scene);

/* The scene's warnings, all of them where scene.warning shows those that
 * fit in 256 bytes: how many distinct ones the load kept (the first 4096
 * given; *dropped, when not NULL: how many more distinct ones it did
 * not), and the i-th of them in the order first given (NULL past the
 * last), with how many times it was given in *repeats (may be NULL). The
 * texts live as long as the scene. */
int mote_scene_warning_count(const mote_scene *scene, unsigned *dropped);
const char *mote_scene_warning(const mote_scene *scene, int i, unsigned *repeats);

/* Whether path names a file the scene was read from: its scene file
 * (mote_scene_load) or one its textures were decoded from. The same file
 * by device and inode, whatever the name ("./b.png", a link, a hard
 * link); false where the system cannot tell. mote-render and mote-bake
 * refuse to write their output over their input with it. */
bool mote_scene_reads_file(const mote_scene *scene, const char *path);

/* Fills a frame (camera and lights) for the scene: its own camera when
 * it has one (a horizontal fov made vertical for aspect, width / height),
 * else a camera that frames the bounding box from the front-top right; when
 * the file lists no lights, a point light above the camera. The ambient
 * stays 0: the materials hold the scene's (see mote_scene.ambient). */
void mote_scene_frame(const mote_scene *scene, float aspect, mote_frame_desc *frame);

/* Sets camera's znear and zfar for its position so that the whole scene
 * lies between them, as mote_scene_frame sets them for the camera it
 * frames the scene with: far past the far side of the sphere around the
 * scene's bounding box, near where the sphere begins (at least 1/100 of
 * the distance to its centre, and 1/1000 of far). For a caller's own
 * eye on a scene without a camera (mote-render --camera). */
void mote_scene_fit_planes(const mote_scene *scene, mote_camera *camera);

/* The draw options for scene->meshes[mesh]: *base (NULL: defaults) with
 * cull MOTE_CULL_NONE where the mesh's material has backFaceCulling false,
 * unlit where it says disableLighting (mote_scene.unlit), no_depth_write
 * where it says disableDepthWrite, no_fog where the mesh or its material
 * turns fog off, the mesh's lights_off, and the mode of
 * a mesh of points or lines (mote_scene.modes) whatever base's, but for
 * MOTE_MODE_POINTS asked of lines (their vertices are then drawn); lines
 * are drawn without culling, as a segment has no side. */
void mote_scene_draw_desc(const mote_scene *scene, int mesh, const mote_draw_desc *base,
                          mote_draw_desc *out);

/* The order Babylon.js draws the scene's meshes in, for camera: into
 * order (mesh_count entries), the opaque meshes first, then the
 * alpha-tested ones, each in the scene's order, then the blended ones
 * (mote_material.alpha_mode BLEND or TEST_AND_BLEND) by alpha_index, the
 * smaller first, and within one alpha_index from the farthest to the
 * nearest, by the distance from the camera's position to the centre of
 * the mesh's bounding sphere in world space (Babylon.js's RenderingGroup;
 * ties keep the scene's order). meshes: the scene's, or a
 * posed copy as below. Returns how many it wrote: mesh_count, or 0 for a
 * bad argument or when out of memory (then draw in the scene's order).
 * A program drawing its own meshes with blending sorts them so too. */
int mote_scene_draw_order(const mote_scene *scene, const mote_mesh *meshes, const mote_camera *camera,
                          int *order);

/* Draws scene mesh `mesh` of meshes (the scene's, or a posed copy) with
 * mote_scene_draw_desc's options for base: one mote_draw, or for a mesh
 * with depth_pre_pass two, its depth alone (no_color_write) and then its
 * colour where its depth is the nearest (depth_less_equal), as Babylon.js
 * draws a material that needs a depth pre-pass. Returns mote_draw's
 * result (MOTE_ERR_INVALID_ARGUMENT for a mesh out of range). */
mote_result mote_scene_draw(mote_device *dev, const mote_scene *scene, const mote_mesh *meshes, int mesh,
                            const mote_draw_desc *base);

/* Which level Babylon.js's getLOD draws of scene->lods[lod] for camera:
 * -1 the base, k its levels[k]. The distance is from the camera's
 * position to the centre of meshes[bounds_mesh]'s bounding sphere, in
 * world space (an orthographic camera's: its znear, as Babylon.js takes
 * its minZ); the base is drawn nearer than the last level's distance,
 * else the first level whose distance is below it. meshes: the scene's,
 * or a posed copy of them in the same order (mote-render turns its
 * copies), so that the distance is the one of the frame drawn. -1 for a
 * bad argument. */
int mote_scene_lod_level(const mote_scene *scene, int lod, const mote_mesh *meshes,
                         const mote_camera *camera);

/* Sets mote_mesh.hidden on meshes (the scene's, or a posed copy as
 * above) for every level-of-detail group: the level chosen for camera
 * (mote_scene_lod_level) is drawn, the base and the other levels are
 * not, and nothing of a hidden group is. Other meshes are left as they
 * are. Call it once a frame when the camera or the meshes move. */
void mote_scene_choose_lod(const mote_scene *scene, mote_mesh *meshes, const mote_camera *camera);

/* ---- images ------------------------------------------------------------ */

/* Writes the device's full-frame colour buffer, any format, as PNG or binary
 * PPM (P6). mote_write_image picks by the extension (.png, .ppm). */
mote_result mote_write_png(const char *path, const mote_device *dev,
                           char *message, size_t message_size);
mote_result mote_write_ppm(const char *path, const mote_device *dev,
                           char *message, size_t message_size);
mote_result mote_write_image(const char *path, const mote_device *dev,
                             char *message, size_t message_size);
/* The same from a plain RGBA8888 buffer. */
mote_result mote_write_rgba(const char *path, const uint8_t *rgba, int width,
                            int height, int stride, char *message, size_t message_size);
/* Writes size bytes of data to path, as the image writers above write:
 * into a new file beside path, renamed over it once complete, so that a
 * failed write leaves path as it was and removes nothing it did not
 * create (a link is followed: the file it names is replaced). A
 * terminal, /dev/null or a pipe (a character device, or a FIFO someone
 * reads) is written in place; a directory, a block device, a FIFO no one
 * reads or a link to nothing is refused. Errors are MOTE_ERR_IO with
 * why ("write error: No space left on device"). */
mote_result mote_write_file(const char *path, const void *data, size_t size,
                            char *message, size_t message_size);

/* ---- host parallelism -------------------------------------------------- */

/* A mote_parallel_for_fn running tiles on OpenMP threads; user points to an
 * int thread count (NULL or <= 0: all). Without OpenMP it runs serially. */
void mote_parallel_openmp(void *user, int count, mote_task_fn fn, void *task_arg);

/* A pool of threads that stay between frames, for desc.parallel_for
 * (mote_parallel_pool, with the pool as desc.parallel_user). The calling
 * thread works too, and a call returns once its tasks are done: a pool
 * thread the system has put aside (another process busy on its core)
 * holds nobody up, so asking for more threads than are free is never
 * slower than one; an OpenMP region waits for its latest thread. Pool
 * threads spin a few microseconds after a call, then sleep. One call at
 * a time: a call made while another runs (from another thread, or from
 * a task) runs its tasks on its own thread. Same bytes for any count.
 *
 *   .threads   threads working, the caller's included; 0: the cores online
 *   .on_wake   NULL; test hook: called by pool thread t (1 .. threads-1)
 *              each time it wakes for a call, before it takes a task
 *   .user      on_wake's first argument
 *
 * mote_pool_create returns MOTE_ERR_RANGE for threads outside
 * [0, 4096], MOTE_ERR_OUT_OF_MEMORY, or MOTE_ERR_IO when the system
 * refuses a thread; nothing is left behind then. Without POSIX threads
 * a pool has one thread, the caller. */
typedef struct mote_pool mote_pool;
typedef struct mote_pool_desc {
    int threads;
    void (*on_wake)(void *user, int thread);
    void *user;
} mote_pool_desc;
mote_result mote_pool_create(const mote_pool_desc *desc, mote_pool **pool,
                             char *message, size_t message_size);
/* Stops and joins the pool's threads (NULL: nothing). */
void mote_pool_destroy(mote_pool *pool);
/* Threads working in the pool's calls, the caller's included. */
int mote_pool_threads(const mote_pool *pool);
/* A mote_parallel_for_fn; user is a mote_pool (NULL: this thread alone). */
void mote_parallel_pool(void *user, int count, mote_task_fn fn, void *task_arg);

#ifdef __cplusplus
}
#endif

#endif /* MOTE_IO_H */
