/*
 * babylon.h - the .babylon loader's own state, shared by its files: what
 * it reads is written in docs/babylon.md. Not API.
 *
 *   babylon.c           the load in order, id maps, Babylon.js's ids and
 *                       numbers as text, the scene's colours
 *   babylon_material.c  materials, multi-materials and their textures
 *   babylon_geometry.c  vertex arrays (both layouts), indices, sub-meshes
 *   babylon_node.c      meshes, transform nodes, instances, thin instances,
 *                       parents, matrices folded; the mote meshes made
 *   babylon_lod.c       levels of detail
 *   babylon_camera.c    cameras and lights, in the node tree too
 */
#ifndef MOTE_IO_BABYLON_H
#define MOTE_IO_BABYLON_H

#include "json.h"
#include "loader.h"
#include "matrix_fold.h"

/* A sideOrientation as Babylon.js culls by it: 0 (Material.ClockWise-
 * SideOrientation) or any other number; not said: the scene's default */
enum { MOTE__SIDE_UNSAID = 0, MOTE__SIDE_CW, MOTE__SIDE_OTHER };

typedef struct mote__mat {
    const char *id;
    const char *unique_id;        /* uniqueId as text ("%.17g"), or NULL */
    mote_material material;
    signed char invert_y;         /* the texture's invertY: 0, 1, or -1 (not said) */
    bool two_sided;               /* backFaceCulling false */
    bool unlit;                   /* disableLighting (or PBR's unlit): no lights */
    bool uv2;                     /* the texture's coordinatesIndex is 1: it samples uvs2 */
    unsigned char side;           /* sideOrientation (MOTE__SIDE_...) */
    bool cull_front;              /* cullBackFaces false: the front faces are culled */
    bool no_depth_write;          /* disableDepthWrite */
    bool no_fog;                  /* fogEnabled false */
    bool depth_pre_pass;          /* needDepthPrePass, on a blended material */
    uint32_t max_lights;          /* maxSimultaneousLights (4) */
} mote__mat;

typedef struct mote__multi {
    const char *id;
    const char *unique_id;        /* uniqueId as text ("%.17g"), or NULL */
    int *slots;                   /* material index per slot, -1: default */
    int slot_count;
} mote__multi;

typedef struct mote__submesh {
    uint32_t index_start, index_count;
    uint32_t material_index;
    /* its own triangles, or NULL: the node's from index_start. An
     * unindexed sub-mesh of a right-handed scene starting inside one of
     * the node's flipped triangles takes them from the node's run that
     * starts where it does, modulo 3 (mote__babylon_submeshes) */
    uint32_t *own_indices;
} mote__submesh;

typedef struct mote__node {
    const char *id;
    const char *unique_id;        /* uniqueId as text ("%.17g"), or NULL */
    const char *parent_id;        /* an id, or a uniqueId as text (parent_by_unique) */
    bool parent_by_unique; /* parentId was a number: Babylon.js writes the parent's uniqueId */
    int parent_instance; /* parentInstanceIndex: the parent's instance, -1: the parent itself */
    int first_instance, instance_count;   /* a mesh's instances among the nodes */
    const char *material_id;
    const char *material_unique_id; /* materialUniqueId as text, or NULL */
    char where[48];               /* "meshes[3]" or "transformNodes[0]" */
    int parent;                   /* node index, -1: none */
    int state;                    /* cycle search: 0 new, 1 on the path, 2 done */
    int first_mesh, mesh_count;
    mote__trs trs;                /* its own transform; the matrix is folded in later */
    /* localMatrix or pivotMatrix (Babylon.js's array order, which is
     * mote's column-major one), folded into trs by
     * mote__fold_matrix; has_matrix false: none, or the identity */
    float matrix[16];
    bool has_matrix;
    bool matrix_undone;           /* a pivot: its inverse applied after the turn and scale */
    const char *matrix_name;      /* for messages: "pivotMatrix", "source's localMatrix"... */
    bool invisible, disabled;     /* isVisible false; isEnabled false (children too) */
    bool no_fog;                  /* applyFog false */
    bool alpha_index_set;         /* alphaIndex written: alpha_index */
    float alpha_index;
    bool legacy;                  /* interleaved `vertices`: v = 0 is the top row */
    bool unindexed;               /* isUnIndexed: vertices 0,1,2 / 3,4,5 / ... are the triangles */
    bool is_helper;               /* a sheared matrix's hidden stand-in (mote__fold_matrix) */
    unsigned char side; /* overrideMaterialSideOrientation or sideOrientation (MOTE__SIDE_...) */
    mote_vertex *verts;
    uint32_t nv;
    /* uvs2, 2 floats per vertex, in the temporary store; read only when a
     * material of the file samples them (mote__babylon.any_uv2) */
    float *uv2;
    /* verts with uv2 in place of uv, made (once, kept) for the first
     * (sub-)mesh drawn with a material that samples uvs2: the core has one
     * uv per vertex, so such meshes need their own copy; meshes without
     * such a material pay nothing */
    mote_vertex *verts2;
    struct mote__node *arrays;    /* the node whose arrays this one shares, or NULL */
    mote_rgba *colors;            /* one per vertex, or NULL */
    uint32_t *idx;
    /* unindexed, right-handed: the flipped sequential runs from vertex 1
     * and 2, made for the sub-meshes that start there (modulo 3) */
    uint32_t *shifted_runs[2];
    /* idx with each triangle's last two corners swapped, made (once, kept)
     * for the first (sub-)mesh whose side orientation turns its front
     * faces round (mote__babylon_side_indices) */
    uint32_t *idx_flipped;
    uint32_t ni;
    mote__submesh *subs;
    int sub_count;
    /* a mesh's thin instances: nodes [first_thin, first_thin + thin_count)
     * after the instances, each its child at one matrix of matrixData */
    int first_thin, thin_count;
    bool is_thin;                 /* a thin instance, of the mesh nodes[host] (its parent) */
    int host;
    /* a thin instance whose matrix mirrors: Babylon.js culls all of a
     * mesh's thin instances by the mesh's own world matrix (one draw), so
     * such a one shows its back faces (mote__babylon_side_indices) */
    bool thin_mirrored;
    /* its own meshes are not drawn: a mesh drawn as its thin instances, an
     * instance of one (Babylon.js draws a mesh's thin instances in place
     * of it and its instances), or a mesh whose thin instances cannot be
     * drawn (mote__thin_count) */
    bool undrawn;
    const cJSON *lod_ids, *lod_distances; /* lodMeshIds, lodDistances: arrays, or NULL */
    bool lod_copy; /* a level drawn for an instance of its master (mote__lod_copies) */
} mote__node;

/* A level of detail while loading: its node (-1: it draws nothing), its
 * distance and its place among its master's levels as the file gives them
 * (Babylon.js sorts them by distance, equal ones in that order). */
typedef struct mote__lod_level {
    float distance;
    int node, seq;
} mote__lod_level;

/* A mesh or instance that draws one of its levels: levels
 * [first_level, first_level + level_count) of mote__babylon.lod_levels. */
typedef struct mote__lod_group {
    int base, first_level, level_count;
} mote__lod_group;

/* An entry of geometries.vertexData, parsed by the first mesh that names
 * it; later ones share its arrays. */
typedef struct mote__geometry {
    const char *id;
    const cJSON *json;
    /* the node holding its arrays as drawn by its indices [0] or
     * unindexed [1] (isUnIndexed), -1: none yet */
    int owner[2];
} mote__geometry;

/* An id -> index map: a count, then sorted (id, index) pairs; the first of
 * equal ids wins, or the last for mote__idmap_find_last. */
typedef struct mote__idmap {
    const char *id;
    int index;
} mote__idmap;

/* The cameras or the lights: their entries, the node made for each (-1:
 * none yet; mote__entry_node), and maps by id (or name) and by uniqueId, looked
 * up for the file's last entry (mote__idmap_find_last, as
 * scene.getLastEntryById). */
typedef struct mote__entry_list {
    const cJSON **items;
    int *node;
    int count;
    mote__idmap *ids, *uniques;
} mote__entry_list;

/* A .babylon file being loaded: the load (loader.h), the file's JSON and
 * what has been read of it. Nodes are the meshes, then the transform
 * nodes, then the instances, then the thin instances, then the nodes
 * made while loading (cameras and lights in the parent tree, helpers of
 * sheared matrices, levels of detail drawn by instances). */
typedef struct mote__babylon {
    mote__loader *load;
    const cJSON *root;
    mote__mat *mats;
    int mat_count;
    mote__idmap *mat_map, *mat_unique_map;
    mote__multi *multis;
    int multi_count;
    mote__idmap *multi_map, *multi_unique_map;
    mote__geometry *geometries;   /* geometries.vertexData */
    int geometry_count;
    mote__idmap *geometry_map;
    mote__node *nodes;
    int node_count;
    int node_cap;                 /* room for the nodes made while loading */
    mote__entry_list entry_lists[2]; /* cameras, lights */
    mote__idmap *node_map;
    bool any_uv2;                 /* a material samples uvs2: keep them while loading */
    uint8_t *max_lights;          /* per scene mesh: its material's maxSimultaneousLights (at most 32) */
    bool right_handed;            /* useRightHandedSystem: loaded mirrored (mote__mirror_point) */
    mote__lod_group *lod_groups;  /* masters, then instances of masters (mote__babylon_lods) */
    int lod_group_count;
    mote__lod_level *lod_levels;
    int lod_level_count;
    /* per node: the master it is a level of detail of (-1: none); NULL
     * when no mesh has levels */
    int *lod_master;
    int file_meshes;              /* meshes[]: nodes [0, file_meshes) */
    int instances_first, instances_end; /* the instances' nodes */
} mote__babylon;

/* Loads the parsed .babylon JSON root into ld->scene (scene.c calls it). */
mote_result mote__babylon_load(mote__loader *ld, const cJSON *root);

/* babylon.c */
mote_result mote__babylon_color3(mote__babylon *bl, const cJSON *obj, const char *key,
                                 const char *where, float out[3]);
mote_result mote__babylon_side(mote__babylon *bl, const cJSON *obj, const char *key,
                               const char *where, unsigned char *out);
mote_result mote__babylon_id_ref(mote__babylon *bl, const cJSON *obj, const char *key,
                                 const char *where, const char **out);
mote_result mote__babylon_double_text(mote__babylon *bl, double v, const char *at,
                                      const char **out);
mote_result mote__babylon_number_value_text(mote__babylon *bl, const cJSON *v, const char *at,
                                            const char **out);
mote_result mote__babylon_number_text(mote__babylon *bl, const cJSON *obj, const char *key,
                                      const char *where, const char **out);
mote__idmap *mote__idmap_build(mote__babylon *bl, const char *const *ids, size_t stride, int n,
                               int *dup_index);
int mote__idmap_find(const mote__idmap *m, const char *id);
int mote__idmap_find_last(const mote__idmap *m, const char *id);

/* babylon_material.c */
mote_result mote__babylon_materials(mote__babylon *bl);
mote_result mote__babylon_multi_materials(mote__babylon *bl);
const mote__mat *mote__babylon_resolve_material(mote__babylon *bl, const mote__node *nd,
                                                uint32_t material_index);

/* babylon_geometry.c */
mote_result mote__babylon_indices(mote__babylon *bl, const cJSON *arr, const char *at,
                                  mote__node *nd, uint32_t *max_index);
mote_result mote__babylon_check_indices(mote__babylon *bl, const char *at, const mote__node *nd);
mote_result mote__babylon_legacy_geometry(mote__babylon *bl, const cJSON *mesh, const cJSON *verts,
                                          const char *where, mote__node *nd);
void mote__babylon_share_arrays(mote__node *to, mote__node *from);
mote_result mote__babylon_current_geometry(mote__babylon *bl, const cJSON *src, const char *where,
                                           mote__node *nd);
mote_result mote__babylon_submeshes(mote__babylon *bl, const cJSON *mesh, const char *where,
                                    mote__node *nd);
mote_result mote__babylon_uv2_vertices(mote__babylon *bl, mote__node *nd, mote_mesh *m);
mote_result mote__babylon_side_indices(mote__babylon *bl, mote__node *nd, int s,
                                       const mote__mat *mat, mote_mesh *m);

/* babylon_node.c */
bool mote__babylon_names_parent(const cJSON *node);
mote_result mote__babylon_node_common(mote__babylon *bl, const cJSON *mesh, const char *where,
                                      mote__node *nd);
mote_result mote__babylon_nodes(mote__babylon *bl);
mote_result mote__babylon_parents(mote__babylon *bl);
bool mote__babylon_node_disabled(const mote__babylon *bl, const mote__node *nd);
bool mote__babylon_node_hidden(const mote__babylon *bl, const mote__node *nd);
mote_result mote__babylon_build_meshes(mote__babylon *bl);
mote_result mote__babylon_scene_bounds(mote__babylon *bl);

/* babylon_lod.c */
mote_result mote__babylon_lods(mote__babylon *bl);
mote_result mote__babylon_lod_groups(mote__babylon *bl);

/* babylon_camera.c */
mote_result mote__babylon_camera_light_parent(mote__babylon *bl, mote__node *nd);
mote_result mote__babylon_camera_light_nodes(mote__babylon *bl);
mote_result mote__babylon_camera(mote__babylon *bl);
mote_result mote__babylon_lights(mote__babylon *bl);

#endif
