/*
 * gltf.h - the glTF 2.0 loader's own state, shared by its files: what it
 * reads is written in docs/gltf.md. Not API.
 *
 *   gltf.c           the load in order: the containers (.gltf JSON, .glb
 *                    chunks), the version, the extensions, the references
 *   gltf_buffer.c    buffers (GLB's BIN chunk, data: URIs, files beside
 *                    the scene), buffer views and accessors, sparse too
 *   gltf_mesh.c      primitives to vertices and triangles (or points and
 *                    lines): modes, flat
 *                    normals, texture transforms, mirrored in z
 *   gltf_node.c      scenes and the node tree, the mote meshes made
 *   gltf_material.c  materials, textures, images and samplers
 *   gltf_camera.c    cameras and KHR_lights_punctual
 */
#ifndef MOTE_IO_GLTF_H
#define MOTE_IO_GLTF_H

#include "json.h"
#include "loader.h"
#include "matrix_fold.h"

/* A buffer's bytes: GLB's BIN chunk, a decoded data: URI or a file read
 * beside the scene (the last two in the temporary store), read on first
 * use; size is its byteLength. */
typedef struct mote__gltf_buffer {
    const cJSON *json;
    const unsigned char *data;
    size_t size;
    char *owned;                  /* a file's bytes (mote__io_malloc), freed by the load */
} mote__gltf_buffer;

/* An accessor checked against its buffer view and buffer, ready to read:
 * element i's component k is at data + i * stride + k * component size,
 * or 0 without a buffer view; sparse entries are applied by
 * mote__gltf_read_floats. */
typedef struct mote__gltf_accessor {
    uint32_t count;
    int comps;                    /* 1 SCALAR .. 4 VEC4 (MATn are refused where read) */
    uint32_t ctype;               /* 5120 BYTE .. 5126 FLOAT */
    bool normalized;
    const unsigned char *data;    /* NULL: zeros */
    size_t stride;
    uint32_t sparse_count;
    const unsigned char *sparse_indices;
    uint32_t sparse_index_type;
    const unsigned char *sparse_values;
} mote__gltf_accessor;

/* A material as the primitives that use it need it. */
typedef struct mote__gltf_mat {
    mote_material material;
    bool two_sided;               /* doubleSided */
    bool unlit;                   /* KHR_materials_unlit */
    bool cut_away;                /* MASK under its cut-off, untextured: not drawn */
    mote_mip mip;                 /* its sampler's minFilter (mote_scene.mip_modes) */
    int tex_coord;                /* TEXCOORD_n the base colour texture samples */
    bool has_uv_transform;        /* KHR_texture_transform: uv' = M (u, v, 1) */
    float uv_transform[6];        /* column-major 2x3 */
} mote__gltf_mat;

/* A primitive as mote draws it: vertices and colours shared by every
 * node that draws its mesh, and triangles; or points (every vertex, no
 * indices) or line segments (a, b) as triangles (a, b, b), drawn in mode.
 * drawn false: nothing to draw (no positions, too few vertices), a
 * hidden mesh. */
typedef struct mote__gltf_prim {
    mote_vertex *verts;
    uint32_t nv;
    mote_rgba *colors;
    uint32_t *idx;
    uint32_t ni;
    int material;                 /* -1: the default material */
    mote_mode mode;               /* DEFAULT, or POINTS or WIREFRAME (lines) */
    bool drawn;
} mote__gltf_prim;

/* A glTF mesh: its primitives, read by the first node of the scene that
 * names it. */
typedef struct mote__gltf_mesh {
    mote__gltf_prim *prims;
    int prim_count;
    bool read;
} mote__gltf_mesh;

typedef struct mote__gltf_node {
    int parent;                   /* node index, -1: a root of the scene */
    int state;                    /* scene walk: 0 new, 1 on the path, 2 done */
    bool in_scene;
    int mesh, camera, light;      /* -1: none */
    mote__trs trs;                /* its own transform, mirrored in z */
    bool sheared;                 /* its matrix needs a helper above it (mote__fold_matrix) */
    mote__trs outer;              /* the helper's transform when sheared */
    /* its mote meshes: [helper] then its primitives (or one hidden mesh
     * when it has none); children hang under the first of its own */
    int first_mesh, mesh_count;
    int self;                     /* its first own mesh: its children's parent */
    int depth;                    /* parents above its own meshes, helpers counted */
} mote__gltf_node;

/* A top-level array of the file ("accessors"), its elements by index. */
typedef struct mote__gltf_list {
    const char *key;
    const cJSON **items;
    int count;
} mote__gltf_list;

enum { MOTE__GLTF_LISTS = 16 };

/* A glTF file being loaded: the load (loader.h), the file's JSON and what
 * has been read of it. */
typedef struct mote__gltf {
    mote__loader *load;
    const cJSON *root;
    const unsigned char *bin;     /* GLB's BIN chunk, or NULL */
    size_t bin_size;
    mote__gltf_buffer *buffers;
    int buffer_count;
    int view_count, accessor_count, image_count, texture_count, sampler_count;
    mote__gltf_mat *mats;         /* mat_count of them, then the default material */
    unsigned char *mat_state;     /* per material: 1 once read */
    int mat_count;
    int *image_texture;           /* per image: scene texture index, -1 none, -2 unread */
    mote__gltf_mesh *meshes;
    int mesh_count;
    mote__gltf_node *nodes;
    int node_count;
    int scene;                    /* the scene drawn, -1: none */
    int camera_count;
    int camera_node;              /* the first node of the scene with a camera, -1: none */
    const cJSON *light_defs;      /* extensions.KHR_lights_punctual.lights, or NULL */
    int light_def_count;
    bool quantized;               /* KHR_mesh_quantization is used */
    bool lights_ext;              /* KHR_lights_punctual is used */
    mote__gltf_list lists[MOTE__GLTF_LISTS]; /* looked up by index, not walked */
    int list_count;
} mote__gltf;

/* Loads a glTF 2.0 file into ld->scene (scene.c calls them): the JSON
 * text of a .gltf, already parsed, or the whole of a .glb. */
mote_result mote__gltf_load_json(mote__loader *ld, const cJSON *root);
mote_result mote__gltf_load_glb(mote__loader *ld, const unsigned char *data, size_t size);

/* gltf.c: references. A member that is an index into an array of n
 * things (what names them in messages): absent leaves *out as it is. */
mote_result mote__gltf_index(mote__gltf *gl, const cJSON *obj, const char *key,
                             const char *where, int n, const char *what, int *out);
/* The n-th element of the list key ("meshes"), an object, or an error;
 * path (may be NULL, else MOTE__GLTF_AT bytes): its JSON path for
 * messages, "meshes[2]". */
enum { MOTE__GLTF_AT = 64 };
mote_result mote__gltf_item(mote__gltf *gl, const char *key, int n, const cJSON **out,
                            char *path);
/* Lists array (NULL: empty) as key for mote__gltf_item, its length held
 * to the mesh limit (each element may make meshes or textures). */
mote_result mote__gltf_list_add(mote__gltf *gl, const char *key, const cJSON *array, int *n);
/* The same for root[key], which must be an array when present. */
mote_result mote__gltf_count(mote__gltf *gl, const char *key, int *n);
/* Whether extension name is in extensionsUsed. */
bool mote__gltf_uses(const mote__gltf *gl, const char *name);

/* gltf_buffer.c */
mote_result mote__gltf_buffers(mote__gltf *gl);
void mote__gltf_free_buffers(mote__gltf *gl);
/* accessors[index] checked and resolved; use names its user in messages. */
mote_result mote__gltf_resolve(mote__gltf *gl, int index, const char *use,
                                mote__gltf_accessor *out);
/* Element i's first n components as floats: normalized integers mapped
 * to [0, 1] or [-1, 1] as the specification says, others as they are. */
void mote__gltf_read_floats(const mote__gltf_accessor *a, uint32_t i, int n, float *out);
/* Element i of a SCALAR accessor as an unsigned integer. */
uint32_t mote__gltf_read_uint(const mote__gltf_accessor *a, uint32_t i);
/* The bytes of bufferViews[index] (images), checked. */
mote_result mote__gltf_view_bytes(mote__gltf *gl, int index, const char *use,
                                  const unsigned char **data, size_t *size);

/* gltf_mesh.c */
mote_result mote__gltf_mesh_read(mote__gltf *gl, int mesh);

/* gltf_node.c */
mote_result mote__gltf_scene_nodes(mote__gltf *gl);
mote_result mote__gltf_build_meshes(mote__gltf *gl);
mote_result mote__gltf_scene_bounds(mote__gltf *gl);
/* A node's world matrix in the mirrored scene (after build_meshes). */
void mote__gltf_node_world(const mote__gltf *gl, int node, float w[16]);

/* gltf_material.c */
mote_result mote__gltf_materials(mote__gltf *gl);
/* The material a primitive's index names (-1: the default one), read on
 * first use. */
mote_result mote__gltf_material(mote__gltf *gl, int index, const mote__gltf_mat **out);
/* A linear 0..1 channel as an sRGB byte, rounded, clamped (NaN: 0). */
uint8_t mote__gltf_srgb_byte(float c);

/* gltf_camera.c */
mote_result mote__gltf_light_defs(mote__gltf *gl);
mote_result mote__gltf_camera(mote__gltf *gl);
mote_result mote__gltf_lights(mote__gltf *gl);

#endif
