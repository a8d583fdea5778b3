/*
 * gen_gltf - writes the project's own glTF 2.0 test scenes, which
 * tests/test_gltf.c loads and draws (make test runs it first):
 *
 *   quad.gltf + quad.bin, quad_embedded.gltf, quad.glb
 *                        one red unit quad facing +z (two indexed
 *                        triangles), in each container: external buffer,
 *                        base64 data: URI, GLB BIN chunk
 *   textured.gltf + checker2.png, textured_embedded.gltf, textured.glb
 *                        the quad with a 2x2 texture (red, green / blue,
 *                        white from the top left): a file, a data: URI, a
 *                        buffer view
 *   strip.gltf, fan.gltf, strip_indexed.gltf, fan_indexed.gltf
 *                        the same quad as TRIANGLE_STRIP and TRIANGLE_FAN
 *   lines.gltf           the quad's outline as LINES, LINE_LOOP, LINE_STRIP
 *                        (closed, and open: three sides) and its corners as
 *                        POINTS, indexed and not, one primitive each
 *   quantized.gltf       KHR_mesh_quantization: unsigned short positions
 *                        scaled by the node, byte normals, byte uvs
 *   sparse.gltf          a sparse accessor over a view, and one over zeros
 *   flat.gltf            no normals: flat ones are made
 *   alpha.gltf           OPAQUE, MASK and BLEND materials, one primitive each
 *   materials.gltf       unlit, emissive strength, doubleSided, texture
 *                        transforms (one choosing its uv set), vertex
 *                        colours, wrap modes
 *   camera_light.gltf    a node tree (TRS and matrix), a perspective and an
 *                        orthographic camera, directional, point and spot lights
 *   demo.glb             the picture of docs/images/gltf.png
 *
 *   gen_gltf DIR
 *
 * Numbers are written with fixed formats: the same bytes on every run.
 */
#include <stb_image_write.h>

#include <math.h>
#include <stdarg.h>
#include <stdbool.h>
#include <stdint.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>

static const char *out_dir;

static void die(const char *what)
{
    fprintf(stderr, "gen_gltf: %s\n", what);
    exit(1);
}

/* ---- a file being built: binary data, views, accessors, JSON ----------- */

typedef struct text {
    char s[1 << 16];
    size_t n;
} text;

static void add(text *t, const char *fmt, ...)
{
    va_list ap;
    va_start(ap, fmt);
    int k = vsnprintf(t->s + t->n, sizeof t->s - t->n, fmt, ap);
    va_end(ap);
    if (k < 0 || (size_t)k >= sizeof t->s - t->n)
        die("text too long");
    t->n += (size_t)k;
}

typedef struct gltf {
    unsigned char bin[1 << 16];
    size_t bin_n;
    text views, accessors;
    int view_count, accessor_count;
} gltf;

/* A buffer view of size bytes (stride 0: none), 4-byte aligned. */
static int view(gltf *g, const void *data, size_t size, int stride)
{
    if (g->bin_n + size + 4 > sizeof g->bin)
        die("buffer too long");
    memcpy(g->bin + g->bin_n, data, size);
    add(&g->views, "%s{\"buffer\":0,\"byteOffset\":%zu,\"byteLength\":%zu", g->view_count ? "," : "",
        g->bin_n, size);
    if (stride)
        add(&g->views, ",\"byteStride\":%d", stride);
    add(&g->views, "}");
    g->bin_n += (size + 3) & ~(size_t)3;
    return g->view_count++;
}

/* An accessor; view -1: none; extra: more members (",\"sparse\":...") or "". */
static int accessor(gltf *g, int v, int offset, int ctype, int count, const char *type,
                    bool normalized, const char *extra)
{
    add(&g->accessors, "%s{", g->accessor_count ? "," : "");
    if (v >= 0)
        add(&g->accessors, "\"bufferView\":%d,\"byteOffset\":%d,", v, offset);
    add(&g->accessors, "\"componentType\":%d,\"count\":%d,\"type\":\"%s\"%s%s}", ctype, count,
        type, normalized ? ",\"normalized\":true" : "", extra);
    return g->accessor_count++;
}

/* An index accessor: count unsigned bytes (5121) or shorts (5123). */
static int indices(gltf *g, const void *idx, int count, int ctype)
{
    size_t size = (size_t)count * (ctype == 5121 ? 1 : 2);
    return accessor(g, view(g, idx, size, 0), 0, ctype, count, "SCALAR", false, "");
}

static int floats(gltf *g, const float *f, int count, int comps, const char *type)
{
    return accessor(g, view(g, f, (size_t)count * (size_t)comps * 4, 0), 0, 5126, count, type,
                    false, "");
}

enum container { EXTERNAL, DATA_URI, GLB };

static FILE *open_out(const char *name)
{
    char path[1024];
    snprintf(path, sizeof path, "%s/%s", out_dir, name);
    FILE *f = fopen(path, "wb");
    if (!f)
        die("cannot write a file in the folder given");
    return f;
}

static void base64(text *t, const unsigned char *d, size_t n)
{
    static const char a[] = "ABCDEFGHIJKLMNOPQRSTUVWXYZabcdefghijklmnopqrstuvwxyz0123456789+/";
    for (size_t i = 0; i < n; i += 3) {
        uint32_t v = (uint32_t)d[i] << 16 | (i + 1 < n ? (uint32_t)d[i + 1] << 8 : 0) |
                     (i + 2 < n ? d[i + 2] : 0);
        add(t, "%c%c%c%c", a[v >> 18 & 63], a[v >> 12 & 63], i + 1 < n ? a[v >> 6 & 63] : '=',
            i + 2 < n ? a[v & 63] : '=');
    }
}

static void le32(unsigned char *p, uint32_t v)
{
    p[0] = (unsigned char)v, p[1] = (unsigned char)(v >> 8);
    p[2] = (unsigned char)(v >> 16), p[3] = (unsigned char)(v >> 24);
}

/* Writes name (".gltf" or ".glb" added) with the rest of its JSON in body
 * (members after the buffers, views and accessors, no leading comma). */
static void write_gltf(const gltf *g, const char *name, enum container c, const char *body)
{
    static text json;
    json.n = 0;
    add(&json, "{\"asset\":{\"version\":\"2.0\",\"generator\":\"mote gen_gltf\"},");
    add(&json, "\"buffers\":[{\"byteLength\":%zu", g->bin_n);
    char file[256];
    if (c == EXTERNAL) {
        snprintf(file, sizeof file, "%s.bin", name);
        add(&json, ",\"uri\":\"%s\"", file);
        FILE *f = open_out(file);
        fwrite(g->bin, 1, g->bin_n, f);
        fclose(f);
    } else if (c == DATA_URI) {
        add(&json, ",\"uri\":\"data:application/octet-stream;base64,");
        base64(&json, g->bin, g->bin_n);
        add(&json, "\"");
    }
    add(&json, "}],\"bufferViews\":[%s],\"accessors\":[%s],%s}", g->views.s, g->accessors.s,
        body);
    snprintf(file, sizeof file, "%s.%s", name, c == GLB ? "glb" : "gltf");
    FILE *f = open_out(file);
    if (c != GLB) {
        fwrite(json.s, 1, json.n, f);
    } else {
        size_t jn = (json.n + 3) & ~(size_t)3, bn = (g->bin_n + 3) & ~(size_t)3;
        unsigned char h[12], ch[8];
        memcpy(h, "glTF", 4);
        le32(h + 4, 2);
        le32(h + 8, (uint32_t)(12 + 8 + jn + 8 + bn));
        fwrite(h, 1, 12, f);
        le32(ch, (uint32_t)jn);
        memcpy(ch + 4, "JSON", 4);
        fwrite(ch, 1, 8, f);
        fwrite(json.s, 1, json.n, f);
        fwrite("   ", 1, jn - json.n, f);
        le32(ch, (uint32_t)bn);
        memcpy(ch + 4, "BIN\0", 4);
        fwrite(ch, 1, 8, f);
        fwrite(g->bin, 1, g->bin_n, f);
        fwrite("\0\0\0", 1, bn - g->bin_n, f);
    }
    fclose(f);
}

/* ---- the scenes -------------------------------------------------------- */

/* Writes name: a scene of one node drawing one mesh of prims (its
 * primitives' objects, comma-separated), then rest (more members, or ""). */
static void write_one_mesh(const gltf *g, const char *name, enum container c, const char *prims,
                           const char *rest)
{
    static text body;
    body.n = 0;
    add(&body, "\"scenes\":[{\"nodes\":[0]}],\"nodes\":[{\"mesh\":0}],"
        "\"meshes\":[{\"primitives\":[%s]}]%s%s", prims, *rest ? "," : "", rest);
    write_gltf(g, name, c, body.s);
}

/* The file being built, emptied. */
static gltf *new_gltf(void)
{
    static gltf g;
    memset(&g, 0, sizeof g);
    return &g;
}

/* The unit quad in x, y from -0.5 to 0.5 at z = 0, facing +z: corners
 * bottom-left, bottom-right, top-right, top-left; uv (0, 0) top left. */
static const float quad_pos[12] = {-0.5f, -0.5f, 0, 0.5f, -0.5f, 0, 0.5f, 0.5f, 0, -0.5f, 0.5f, 0};
static const float quad_nrm[12] = {0, 0, 1, 0, 0, 1, 0, 0, 1, 0, 0, 1};
static const float quad_uv[8] = {0, 1, 1, 1, 1, 0, 0, 0};
static const uint16_t quad_idx[6] = {0, 1, 2, 0, 2, 3};

/* The quad's position, normal, uv accessors (0, 1, 2), then its indices (3). */
static void quad_accessors(gltf *g)
{
    floats(g, quad_pos, 4, 3, "VEC3");
    floats(g, quad_nrm, 4, 3, "VEC3");
    floats(g, quad_uv, 4, 2, "VEC2");
    indices(g, quad_idx, 6, 5123);
}

static const char quad_body[] =
    "\"scene\":0,\"scenes\":[{\"nodes\":[0]}],\"nodes\":[{\"mesh\":0}],"
    "\"meshes\":[{\"primitives\":[{\"attributes\":{\"POSITION\":0,\"NORMAL\":1,"
    "\"TEXCOORD_0\":2},\"indices\":3,\"material\":0}]}],"
    "\"materials\":[{\"pbrMetallicRoughness\":{\"baseColorFactor\":[1,0,0,1]%s}}]%s";

static void write_quads(void)
{
    static const char *const names[3] = {"quad", "quad_embedded", "quad"};
    char body[1024];
    snprintf(body, sizeof body, quad_body, "", "");
    for (int c = EXTERNAL; c <= GLB; c++) {
        gltf *g = new_gltf();
        quad_accessors(g);
        write_gltf(g, names[c], (enum container)c, body);
    }
}

typedef struct png_out {
    unsigned char data[4096];
    size_t size;
} png_out;

static void png_write(void *context, void *data, int size)
{
    png_out *o = context;
    if (size < 0 || o->size + (size_t)size > sizeof o->data)
        die("PNG too long");
    memcpy(o->data + o->size, data, (size_t)size);
    o->size += (size_t)size;
}

/* A 2x2 PNG: red, green / blue, white from the top left. */
static const png_out *checker_png(void)
{
    static const unsigned char px[16] = {255, 0, 0, 255, 0, 255, 0, 255,
                                         0, 0, 255, 255, 255, 255, 255, 255};
    static png_out o;
    o.size = 0;
    if (!stbi_write_png_to_func(png_write, &o, 2, 2, 4, px, 8))
        die("cannot encode a PNG");
    return &o;
}

static void write_textured(void)
{
    const png_out *png = checker_png();
    FILE *f = open_out("checker2.png");
    fwrite(png->data, 1, png->size, f);
    fclose(f);
    static const char *const names[3] = {"textured", "textured_embedded", "textured"};
    const char *tex = ",\"baseColorTexture\":{\"index\":0}";
    for (int c = EXTERNAL; c <= GLB; c++) {
        gltf *g = new_gltf();
        quad_accessors(g);
        static text images;
        images.n = 0;
        if (c == EXTERNAL) {
            add(&images, "{\"uri\":\"checker2.png\"}");
        } else if (c == DATA_URI) {
            add(&images, "{\"uri\":\"data:image/png;base64,");
            base64(&images, png->data, png->size);
            add(&images, "\"}");
        } else {
            add(&images, "{\"bufferView\":%d,\"mimeType\":\"image/png\"}",
                view(g, png->data, png->size, 0));
        }
        static text rest;
        rest.n = 0;
        add(&rest, ",\"textures\":[{\"source\":0,\"sampler\":0}],\"images\":[%s],"
            "\"samplers\":[{\"magFilter\":9728,\"wrapS\":33071,\"wrapT\":33648}]", images.s);
        static char body[1 << 17];
        snprintf(body, sizeof body, quad_body, tex, rest.s);
        /* white, so the texels show as they are */
        char *red = strstr(body, "[1,0,0,1]");
        memcpy(red, "[1,1,1,1]", 9);
        write_gltf(g, names[c], (enum container)c, body);
    }
}

/* The quad as a strip (corners 0, 1, 3, 2) and as a fan (0, 1, 2, 3),
 * unindexed and indexed. */
static void write_strips_and_fans(void)
{
    static const int orders[2][4] = {{0, 1, 3, 2}, {0, 1, 2, 3}};
    static const char *const names[2][2] = {{"strip", "strip_indexed"}, {"fan", "fan_indexed"}};
    for (int mode = 0; mode < 2; mode++)
        for (int indexed = 0; indexed < 2; indexed++) {
            gltf *g = new_gltf();
            float p[12], n[12];
            uint8_t idx[4];
            for (int k = 0; k < 4; k++) {
                int c = indexed ? k : orders[mode][k];
                memcpy(p + 3 * k, quad_pos + 3 * c, 12);
                memcpy(n + 3 * k, quad_nrm + 3 * c, 12);
                idx[k] = (uint8_t)orders[mode][k];
            }
            floats(g, p, 4, 3, "VEC3");
            floats(g, n, 4, 3, "VEC3");
            if (indexed)
                indices(g, idx, 4, 5121);
            char prim[128];
            snprintf(prim, sizeof prim, "{\"attributes\":{\"POSITION\":0,\"NORMAL\":1}%s,"
                     "\"mode\":%d}", indexed ? ",\"indices\":2" : "", mode ? 6 : 5);
            write_one_mesh(g, names[mode][indexed], EXTERNAL, prim, "");
        }
}

/* The quad's outline, green, as segments (unindexed), a loop (indexed),
 * a strip back to the first corner (unindexed) and an open strip
 * (indexed: three sides); its corners as points, indexed and not. */
static void write_lines(void)
{
    gltf *g = new_gltf();
    static const uint8_t segments[8] = {0, 1, 1, 2, 2, 3, 3, 0};
    static const uint8_t ring[5] = {0, 1, 2, 3, 0};
    float seg_p[8 * 3], ring_p[5 * 3];
    for (int k = 0; k < 8; k++)
        memcpy(seg_p + 3 * k, quad_pos + 3 * segments[k], 12);
    for (int k = 0; k < 5; k++)
        memcpy(ring_p + 3 * k, quad_pos + 3 * ring[k], 12);
    floats(g, seg_p, 8, 3, "VEC3");                                      /* 0 */
    floats(g, quad_pos, 4, 3, "VEC3");                                   /* 1 */
    floats(g, ring_p, 5, 3, "VEC3");                                     /* 2 */
    indices(g, ring, 4, 5121);   /* 3: 0 1 2 3 */
    write_one_mesh(g, "lines", EXTERNAL,
                   "{\"attributes\":{\"POSITION\":0},\"mode\":1,\"material\":0},"
                   "{\"attributes\":{\"POSITION\":1},\"indices\":3,\"mode\":2,\"material\":0},"
                   "{\"attributes\":{\"POSITION\":2},\"mode\":3,\"material\":0},"
                   "{\"attributes\":{\"POSITION\":1},\"indices\":3,\"mode\":3,\"material\":0},"
                   "{\"attributes\":{\"POSITION\":1},\"indices\":3,\"mode\":0,\"material\":0},"
                   "{\"attributes\":{\"POSITION\":1},\"mode\":0,\"material\":0}",
                   "\"materials\":[{\"pbrMetallicRoughness\":{\"baseColorFactor\":[0,1,0,1]}}]");
}

/* Positions as unsigned shorts 0..2 (scaled by 0.5 and moved by the
 * node: the quad again), normals as normalized bytes, uvs as normalized
 * unsigned bytes, interleaved in one view with a stride. */
static void write_quantized(void)
{
    gltf *g = new_gltf();
    unsigned char v[4 * 16];
    memset(v, 0, sizeof v);
    static const uint16_t q[4][3] = {{0, 0, 0}, {2, 0, 0}, {2, 2, 0}, {0, 2, 0}};
    for (int k = 0; k < 4; k++) {
        unsigned char *e = v + 16 * k;
        memcpy(e, q[k], 6);                /* 0..5 position, 6..7 padding */
        e[8] = 0, e[9] = 0, e[10] = 127;   /* normal +z, 11 padding */
        e[12] = (unsigned char)(quad_uv[2 * k] * 255.0f);
        e[13] = (unsigned char)(quad_uv[2 * k + 1] * 255.0f);
    }
    int vv = view(g, v, sizeof v, 16);
    accessor(g, vv, 0, 5123, 4, "VEC3", false, "");
    accessor(g, vv, 8, 5120, 4, "VEC3", true, "");
    accessor(g, vv, 12, 5121, 4, "VEC2", true, "");
    indices(g, quad_idx, 6, 5123);
    write_gltf(g, "quantized", EXTERNAL,
               "\"extensionsUsed\":[\"KHR_mesh_quantization\"],"
               "\"extensionsRequired\":[\"KHR_mesh_quantization\"],"
               "\"scenes\":[{\"nodes\":[0]}],\"nodes\":[{\"mesh\":0,"
               "\"translation\":[-0.5,-0.5,0],\"scale\":[0.5,0.5,0.5]}],"
               "\"meshes\":[{\"primitives\":[{\"attributes\":{\"POSITION\":0,\"NORMAL\":1,"
               "\"TEXCOORD_0\":2},\"indices\":3}]}]");
}

/* Positions: the quad with corner 2 moved to (1, 1, 0) by a sparse
 * accessor; normals: zeros (no view) with all four set sparsely. */
static void write_sparse(void)
{
    gltf *g = new_gltf();
    int pv = view(g, quad_pos, sizeof quad_pos, 0);
    static const uint8_t si[1] = {2};
    static const float sv[3] = {1, 1, 0};
    int siv = view(g, si, 1, 0), svv = view(g, sv, sizeof sv, 0);
    char sparse[256];
    snprintf(sparse, sizeof sparse, ",\"sparse\":{\"count\":1,\"indices\":{\"bufferView\":%d,"
             "\"componentType\":5121},\"values\":{\"bufferView\":%d}}", siv, svv);
    accessor(g, pv, 0, 5126, 4, "VEC3", false, sparse);
    static const uint16_t ni[4] = {0, 1, 2, 3};
    int niv = view(g, ni, sizeof ni, 0), nvv = view(g, quad_nrm, sizeof quad_nrm, 0);
    snprintf(sparse, sizeof sparse, ",\"sparse\":{\"count\":4,\"indices\":{\"bufferView\":%d,"
             "\"componentType\":5123},\"values\":{\"bufferView\":%d}}", niv, nvv);
    accessor(g, -1, 0, 5126, 4, "VEC3", false, sparse);
    indices(g, quad_idx, 6, 5123);
    write_one_mesh(g, "sparse", DATA_URI,
                   "{\"attributes\":{\"POSITION\":0,\"NORMAL\":1},\"indices\":2}", "");
}

static void write_flat(void)
{
    gltf *g = new_gltf();
    /* a tent: two triangles meeting at a ridge, no normals */
    static const float p[12] = {-1, 0, 0, 0, 0, 1, 0, 1, 0, 1, 0, 0};
    static const uint16_t idx[6] = {0, 1, 2, 1, 3, 2};
    floats(g, p, 4, 3, "VEC3");
    indices(g, idx, 6, 5123);
    write_one_mesh(g, "flat", DATA_URI, "{\"attributes\":{\"POSITION\":0},\"indices\":1}", "");
}

static void write_alpha(void)
{
    gltf *g = new_gltf();
    quad_accessors(g);
    write_one_mesh(g, "alpha", DATA_URI,
                   "{\"attributes\":{\"POSITION\":0,\"NORMAL\":1},\"indices\":3,\"material\":0},"
                   "{\"attributes\":{\"POSITION\":0,\"NORMAL\":1},\"indices\":3,\"material\":1},"
                   "{\"attributes\":{\"POSITION\":0,\"NORMAL\":1},\"indices\":3,\"material\":2}",
                   "\"materials\":[{\"alphaMode\":\"OPAQUE\"},"
                   "{\"alphaMode\":\"MASK\",\"alphaCutoff\":0.25},"
                   "{\"alphaMode\":\"BLEND\",\"pbrMetallicRoughness\":{\"baseColorFactor\":"
                   "[0,0,1,0.5]}}]");
}

/* Vertex colours (floats and normalized unsigned bytes), an unlit
 * material, emissive strength, a double-sided one with a texture
 * transform, and one whose transform samples TEXCOORD_1. */
static void write_materials(void)
{
    gltf *g = new_gltf();
    quad_accessors(g);
    static const float col[16] = {1, 0, 0, 1, 0, 1, 0, 1, 0, 0, 1, 1, 1, 1, 1, 1};
    floats(g, col, 4, 4, "VEC4");
    static const uint8_t col8[12] = {255, 0, 0, 0, 255, 0, 0, 0, 255, 128, 128, 128};
    accessor(g, view(g, col8, sizeof col8, 0), 0, 5121, 4, "VEC3", true, "");
    static const float uv1[8] = {0.25f, 0.5f, 0.5f, 0.5f, 0.5f, 0.25f, 0.25f, 0.25f};
    floats(g, uv1, 4, 2, "VEC2");                                                  /* 6 */
    const png_out *png = checker_png();
    static text rest;
    rest.n = 0;
    add(&rest,
        "\"extensionsUsed\":[\"KHR_materials_unlit\",\"KHR_materials_emissive_strength\","
        "\"KHR_texture_transform\",\"EXT_mote_unknown\"],"
        "\"materials\":[{\"extensions\":{\"KHR_materials_unlit\":{}},\"pbrMetallicRoughness\":"
        "{\"baseColorFactor\":[0.5,0.5,0.5,1]}},"
        "{\"emissiveFactor\":[1,0.5,0],\"extensions\":{\"KHR_materials_emissive_strength\":"
        "{\"emissiveStrength\":0.5}}},"
        "{\"doubleSided\":true,\"pbrMetallicRoughness\":{\"baseColorTexture\":{\"index\":0,"
        "\"extensions\":{\"KHR_texture_transform\":{\"offset\":[0.5,0],\"scale\":[2,1],"
        "\"rotation\":1.5707963}}}}},"
        "{\"pbrMetallicRoughness\":{\"baseColorTexture\":{\"index\":0,\"texCoord\":0,"
        "\"extensions\":{\"KHR_texture_transform\":{\"texCoord\":1,\"scale\":[2,2]}}}}}],"
        "\"textures\":[{\"source\":0,\"sampler\":0}],\"samplers\":[{\"wrapS\":33648,"
        "\"wrapT\":33071}],\"images\":[{\"uri\":\"data:image/png;base64,");
    base64(&rest, png->data, png->size);
    add(&rest, "\"}]");
    write_one_mesh(g, "materials", EXTERNAL,
                   "{\"attributes\":{\"POSITION\":0,\"NORMAL\":1,\"COLOR_0\":4},\"indices\":3,"
                   "\"material\":0},"
                   "{\"attributes\":{\"POSITION\":0,\"NORMAL\":1,\"COLOR_0\":5},\"indices\":3,"
                   "\"material\":1},"
                   "{\"attributes\":{\"POSITION\":0,\"NORMAL\":1,\"TEXCOORD_0\":2},\"indices\":3,"
                   "\"material\":2},"
                   "{\"attributes\":{\"POSITION\":0,\"NORMAL\":1,\"TEXCOORD_0\":2,"
                   "\"TEXCOORD_1\":6},\"indices\":3,\"material\":3}", rest.s);
}

/* A parent turned 90 degrees about y and moved, a child by matrix; a
 * camera at (0, 0, 5) looking down -z, an orthographic one after it;
 * a directional light down -y, a point light, a spot light. */
static void write_camera_light(void)
{
    gltf *g = new_gltf();
    quad_accessors(g);
    write_gltf(g, "camera_light", EXTERNAL,
               "\"extensionsUsed\":[\"KHR_lights_punctual\"],"
               "\"extensions\":{\"KHR_lights_punctual\":{\"lights\":["
               "{\"type\":\"directional\",\"color\":[1,0.5,0.25],\"intensity\":2},"
               "{\"type\":\"point\",\"intensity\":50,\"range\":20},"
               "{\"type\":\"spot\",\"spot\":{\"innerConeAngle\":0.2,\"outerConeAngle\":0.6}}]}},"
               "\"scenes\":[{\"nodes\":[0,2,3,4,5,6]}],\"nodes\":["
               "{\"mesh\":0,\"translation\":[1,2,3],\"rotation\":[0,0.70710678,0,0.70710678],"
               "\"children\":[1]},"
               "{\"mesh\":0,\"matrix\":[2,0,0,0, 0,1,0,0, 0,0,1,0, 0,1,0,1]},"
               "{\"camera\":0,\"translation\":[0,0,5]},"
               "{\"camera\":1,\"translation\":[0,0,-5]},"
               "{\"extensions\":{\"KHR_lights_punctual\":{\"light\":0}},"
               "\"rotation\":[-0.70710678,0,0,0.70710678]},"
               "{\"extensions\":{\"KHR_lights_punctual\":{\"light\":1}},\"translation\":[0,5,0]},"
               "{\"extensions\":{\"KHR_lights_punctual\":{\"light\":2}},\"translation\":[0,0,4]}],"
               "\"cameras\":[{\"type\":\"perspective\",\"perspective\":{\"yfov\":0.8,"
               "\"znear\":0.1,\"zfar\":100,\"aspectRatio\":1.5}},"
               "{\"type\":\"orthographic\",\"orthographic\":{\"xmag\":2,\"ymag\":1.5,"
               "\"znear\":0.5,\"zfar\":50}}],"
               "\"meshes\":[{\"primitives\":[{\"attributes\":{\"POSITION\":0,\"NORMAL\":1},"
               "\"indices\":3}]}]");
}

/* ---- the demo scene ---------------------------------------------------- */

/* A ring of n quads (a band around y), a floor and a fan-made pyramid. */
static void write_demo(void)
{
    gltf *g = new_gltf();
    enum { N = 48 };
    float p[(N + 1) * 2 * 3], n[(N + 1) * 2 * 3], uv[(N + 1) * 2 * 2];
    for (int i = 0; i <= N; i++) {
        double a = 2.0 * 3.14159265358979 * i / N;
        for (int k = 0; k < 2; k++) {
            float *q = p + 6 * i + 3 * k, *m = n + 6 * i + 3 * k;
            q[0] = (float)cos(a), q[1] = (float)k * 0.8f, q[2] = (float)-sin(a);
            m[0] = (float)cos(a), m[1] = 0, m[2] = (float)-sin(a);
            uv[4 * i + 2 * k] = (float)i / N * 4.0f;
            uv[4 * i + 2 * k + 1] = 1.0f - (float)k;
        }
    }
    floats(g, p, (N + 1) * 2, 3, "VEC3");   /* 0: the band, a strip */
    floats(g, n, (N + 1) * 2, 3, "VEC3");   /* 1 */
    floats(g, uv, (N + 1) * 2, 2, "VEC2");  /* 2 */
    static const float pyr[15] = {0, 1.2f, 0, -0.6f, 0, 0.6f, 0.6f, 0, 0.6f,
                                  0.6f, 0, -0.6f, -0.6f, 0, -0.6f};
    static const uint8_t fan[6] = {0, 1, 2, 3, 4, 1};
    static const float pcol[15] = {1, 1, 0.2f, 1, 0.1f, 0.1f, 0.1f, 1, 0.1f, 0.1f, 0.2f, 1,
                                   1, 0.1f, 1};
    floats(g, pyr, 5, 3, "VEC3");           /* 3: no normals: flat ones */
    indices(g, fan, 6, 5121);   /* 4 */
    floats(g, pcol, 5, 3, "VEC3");          /* 5 */
    static const float floor_p[12] = {-3, 0, 3, 3, 0, 3, 3, 0, -3, -3, 0, -3};
    static const float floor_n[12] = {0, 1, 0, 0, 1, 0, 0, 1, 0, 0, 1, 0};
    static const float floor_uv[8] = {0, 6, 6, 6, 6, 0, 0, 0};
    floats(g, floor_p, 4, 3, "VEC3");       /* 6 */
    floats(g, floor_n, 4, 3, "VEC3");       /* 7 */
    floats(g, floor_uv, 4, 2, "VEC2");      /* 8 */
    indices(g, quad_idx, 6, 5123);
    const png_out *png = checker_png();
    static text body;
    body.n = 0;
    add(&body,
        "\"extensionsUsed\":[\"KHR_lights_punctual\"],"
        "\"extensions\":{\"KHR_lights_punctual\":{\"lights\":[{\"type\":\"directional\","
        "\"intensity\":0.9},{\"type\":\"point\",\"color\":[1,0.8,0.6],\"intensity\":12}]}},"
        "\"scene\":0,\"scenes\":[{\"nodes\":[0,1,2,3,4,5]}],\"nodes\":["
        "{\"mesh\":0,\"translation\":[-1.3,0,0]},"
        "{\"mesh\":1,\"translation\":[1.3,0,0.3],\"rotation\":[0,0.3826834,0,0.9238795]},"
        "{\"mesh\":2},"
        "{\"camera\":0,\"translation\":[0,2.6,5.4],\"rotation\":[-0.2164396,0,0,0.976296]},"
        "{\"extensions\":{\"KHR_lights_punctual\":{\"light\":0}},"
        "\"rotation\":[-0.4545195,0.3265056,0.1893771,0.8067734]},"
        "{\"extensions\":{\"KHR_lights_punctual\":{\"light\":1}},\"translation\":[1,3,2]}],"
        "\"cameras\":[{\"type\":\"perspective\",\"perspective\":{\"yfov\":0.7,\"znear\":0.5,"
        "\"zfar\":30}}],"
        "\"meshes\":[{\"primitives\":[{\"attributes\":{\"POSITION\":0,\"NORMAL\":1,"
        "\"TEXCOORD_0\":2},\"mode\":5,\"material\":0}]},"
        "{\"primitives\":[{\"attributes\":{\"POSITION\":3,\"COLOR_0\":5},\"indices\":4,"
        "\"mode\":6}]},"
        "{\"primitives\":[{\"attributes\":{\"POSITION\":6,\"NORMAL\":7,\"TEXCOORD_0\":8},"
        "\"indices\":9,\"material\":1}]}],"
        "\"materials\":[{\"doubleSided\":true,\"pbrMetallicRoughness\":{\"baseColorTexture\":"
        "{\"index\":0}}},{\"pbrMetallicRoughness\":{\"baseColorFactor\":[0.6,0.6,0.7,1],"
        "\"baseColorTexture\":{\"index\":0}}}],"
        "\"textures\":[{\"source\":0,\"sampler\":0}],\"samplers\":[{\"magFilter\":9728}],"
        "\"images\":[{\"bufferView\":%d,\"mimeType\":\"image/png\"}]",
        view(g, png->data, png->size, 0));
    write_gltf(g, "demo", GLB, body.s);
}

int main(int argc, char **argv)
{
    if (argc != 2) {
        fprintf(stderr, "usage: gen_gltf DIR\n");
        return 2;
    }
    out_dir = argv[1];
    write_quads();
    write_textured();
    write_strips_and_fans();
    write_lines();
    write_quantized();
    write_sparse();
    write_flat();
    write_alpha();
    write_materials();
    write_camera_light();
    write_demo();
    return 0;
}
