/*
 * gen_assets - writes mote's own assets (the files in assets/):
 *
 *   checker.png                256x128 checker; top-left a red square with a
 *                              white "F", so any flip or mirror shows
 *   cube|sphere|torus.babylon          current layout: positions, normals,
 *                                      uvs (v = 0 is the bottom row), subMeshes
 *   cube|sphere|torus.legacy.babylon   legacy layout: interleaved vertices,
 *                                      uvCount 1 (stride 8), v = 0 the top row
 *   demo.babylon               torus, sphere and cube on a textured ground,
 *                              two lights (what `make demo` renders)
 *
 *   gen_assets [DIR]           (default: assets)
 *
 * Each scene has a camera (activeCamera/activeCameraID) and a point light.
 * Winding is Babylon's: seen from outside, a triangle's outward normal is
 * cross(v2 - v0, v1 - v0) (the order Babylon's ComputeNormals and its
 * exporters use). Numbers are printed with fixed formats, so the files are
 * the same bytes on every run.
 */
#include <stb_image_write.h>

#include <math.h>
#include <stdbool.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>

#define PI 3.14159265358979323846

/* ---- meshes ------------------------------------------------------------ */

typedef struct gvert {
    double p[3], n[3];
    double uv[2];                 /* v = 0 is the top row of the texture */
} gvert;

typedef struct gmesh {
    gvert *v;
    int vertex_count, vertex_cap;
    unsigned *index;
    int index_count, index_cap;
} gmesh;

static void *grow(void *p, int *cap, int need, size_t size)
{
    if (need <= *cap)
        return p;
    int n = *cap ? *cap * 2 : 256;
    while (n < need)
        n *= 2;
    void *q = realloc(p, (size_t)n * size);
    if (!q) {
        fprintf(stderr, "gen_assets: out of memory\n");
        exit(1);
    }
    *cap = n;
    return q;
}

static int add_vertex(gmesh *m, const double p[3], const double n[3], double u, double v)
{
    m->v = grow(m->v, &m->vertex_cap, m->vertex_count + 1, sizeof *m->v);
    gvert *g = &m->v[m->vertex_count];
    double len = sqrt(n[0] * n[0] + n[1] * n[1] + n[2] * n[2]);
    for (int k = 0; k < 3; k++) {
        g->p[k] = p[k];
        g->n[k] = len > 0.0 ? n[k] / len : 0.0;
    }
    g->uv[0] = u;
    g->uv[1] = v;
    return m->vertex_count++;
}

/* Adds triangle a, b, c in Babylon's front-face order: its outward side is
 * the one its vertex normals point to. Zero-area triangles (at a sphere's
 * poles) are left out. */
static void add_triangle(gmesh *m, int a, int b, int c)
{
    const double *pa = m->v[a].p, *pb = m->v[b].p, *pc = m->v[c].p;
    double e1[3], e2[3], g[3], n[3];
    for (int k = 0; k < 3; k++) {
        e1[k] = pc[k] - pa[k];
        e2[k] = pb[k] - pa[k];
        n[k] = m->v[a].n[k] + m->v[b].n[k] + m->v[c].n[k];
    }
    g[0] = e1[1] * e2[2] - e1[2] * e2[1];
    g[1] = e1[2] * e2[0] - e1[0] * e2[2];
    g[2] = e1[0] * e2[1] - e1[1] * e2[0];
    if (g[0] * g[0] + g[1] * g[1] + g[2] * g[2] < 1e-14)
        return;
    if (g[0] * n[0] + g[1] * n[1] + g[2] * n[2] < 0.0) {
        int t = b;
        b = c;
        c = t;
    }
    m->index = grow(m->index, &m->index_cap, m->index_count + 3, sizeof *m->index);
    m->index[m->index_count++] = (unsigned)a;
    m->index[m->index_count++] = (unsigned)b;
    m->index[m->index_count++] = (unsigned)c;
}

static void free_mesh(gmesh *m)
{
    free(m->v);
    free(m->index);
    memset(m, 0, sizeof *m);
}

/* A cube of half-size s: four vertices per face, so each face has its own
 * normal and a whole copy of the texture, upright and unmirrored as seen
 * from outside (the "F" at each face's top-left corner). */
static void make_cube(gmesh *m, double s)
{
    /* outward normal and the face's "up" as seen from outside */
    static const double faces[6][2][3] = {
        {{0, 0, -1}, {0, 1, 0}}, {{1, 0, 0}, {0, 1, 0}}, {{0, 0, 1}, {0, 1, 0}},
        {{-1, 0, 0}, {0, 1, 0}}, {{0, 1, 0}, {0, 0, 1}}, {{0, -1, 0}, {0, 0, -1}},
    };
    for (int f = 0; f < 6; f++) {
        const double *n = faces[f][0], *up = faces[f][1];
        /* right = up x forward with forward = -n (left-handed, as a camera's) */
        double r[3] = {n[1] * up[2] - n[2] * up[1], n[2] * up[0] - n[0] * up[2],
                       n[0] * up[1] - n[1] * up[0]};
        int corner[4];
        for (int k = 0; k < 4; k++) {
            double x = (k == 1 || k == 2) ? 1.0 : -1.0;   /* right */
            double y = (k >= 2) ? -1.0 : 1.0;             /* up */
            double p[3];
            for (int j = 0; j < 3; j++)
                p[j] = s * (n[j] + x * r[j] + y * up[j]);
            corner[k] = add_vertex(m, p, n, (x + 1.0) * 0.5, (1.0 - y) * 0.5);
        }
        add_triangle(m, corner[0], corner[1], corner[2]);
        add_triangle(m, corner[0], corner[2], corner[3]);
    }
}

typedef void (*surface_fn)(double u, double v, const double *param, double p[3], double n[3]);

/* A (cols + 1) x (rows + 1) grid over u, v in [0, 1], so the seam has its
 * own column of vertices with u = 1. */
static void make_grid(gmesh *m, int cols, int rows, surface_fn fn, const double *param)
{
    int base = m->vertex_count;
    for (int j = 0; j <= rows; j++) {
        for (int i = 0; i <= cols; i++) {
            double u = (double)i / cols, v = (double)j / rows, p[3], n[3];
            fn(u, v, param, p, n);
            add_vertex(m, p, n, u, v);
        }
    }
    for (int j = 0; j < rows; j++) {
        for (int i = 0; i < cols; i++) {
            int a = base + j * (cols + 1) + i, b = a + 1;
            int c = a + cols + 1, d = c + 1;
            add_triangle(m, a, b, d);
            add_triangle(m, a, d, c);
        }
    }
}

/* u goes round the y axis starting at -z, towards +x (to the right as seen
 * from the front), v from the top down. */
static void sphere_point(double u, double v, const double *param, double p[3], double n[3])
{
    double phi = 2.0 * PI * u, theta = PI * v;
    n[0] = sin(theta) * sin(phi);
    n[1] = cos(theta);
    n[2] = -sin(theta) * cos(phi);
    if (v == 0.0 || v == 1.0)
        n[0] = n[2] = 0.0;       /* exactly on the axis: no -0 noise */
    for (int k = 0; k < 3; k++)
        p[k] = param[0] * n[k];
}

/* param: major radius, minor radius; v starts on top of the tube and goes
 * over the outside first. */
static void torus_point(double u, double v, const double *param, double p[3], double n[3])
{
    double phi = 2.0 * PI * u, t = 2.0 * PI * v;
    double d[3] = {sin(phi), 0.0, -cos(phi)};
    double radial = param[0] + param[1] * sin(t);
    for (int k = 0; k < 3; k++) {
        n[k] = d[k] * sin(t);
        p[k] = d[k] * radial;
    }
    n[1] = cos(t);
    p[1] = param[1] * cos(t);
}

static void plane_point(double u, double v, const double *param, double p[3], double n[3])
{
    p[0] = (u - 0.5) * param[0];
    p[1] = 0.0;
    p[2] = (0.5 - v) * param[0];  /* v = 0 (top of the texture) at the far side */
    n[0] = n[2] = 0.0;
    n[1] = 1.0;
}

/* ---- writing ----------------------------------------------------------- */

/* Shortest fixed-format text of x with at most `decimals` decimals: the same
 * bytes everywhere, no "-0", no trailing zeros. */
static const char *num(char *buf, double x, int decimals)
{
    sprintf(buf, "%.*f", decimals, x);
    char *dot = strchr(buf, '.');
    if (dot) {
        char *end = buf + strlen(buf) - 1;
        while (end > dot && *end == '0')
            *end-- = '\0';
        if (end == dot)
            *end = '\0';
    }
    if (strcmp(buf, "-0") == 0)
        strcpy(buf, "0");
    return buf;
}

static void put_vec(FILE *f, const double *v, int count)
{
    char b[64];
    fputc('[', f);
    for (int k = 0; k < count; k++)
        fprintf(f, "%s%s", k ? ", " : "", num(b, v[k], 4));
    fputc(']', f);
}

typedef enum layout { LAYOUT_CURRENT, LAYOUT_LEGACY } layout;

typedef struct gobject {
    const char *name;
    const gmesh *mesh;
    const char *material;
    double position[3], rotation[3], scaling[3];
} gobject;

typedef struct gmaterial {
    const char *id;
    double diffuse[3];
    const char *texture;          /* NULL: none */
    double u_scale, v_scale;
} gmaterial;

typedef struct glight {
    int type;                     /* Babylon's: 0 point, 3 hemispheric */
    double vec[3];                /* point: position; hemispheric: direction (up) */
    double diffuse[3], ground[3];
    double intensity;
} glight;

typedef struct gscene {
    double clear[3], ambient[3];
    double eye[3], target[3], fov;
    const glight *lights;
    int light_count;
    const gmaterial *materials;
    int material_count;
    const gobject *objects;
    int object_count;
} gscene;

static void write_mesh(FILE *f, const gobject *o, layout lay)
{
    const gmesh *m = o->mesh;
    char b[3][64];
    fprintf(f, "    {\n      \"name\": \"%s\",\n      \"id\": \"%s\",\n", o->name, o->name);
    fprintf(f, "      \"materialId\": \"%s\",\n", o->material);
    fprintf(f, "      \"position\": ");
    put_vec(f, o->position, 3);
    fprintf(f, ",\n      \"rotation\": ");
    put_vec(f, o->rotation, 3);
    fprintf(f, ",\n      \"scaling\": ");
    put_vec(f, o->scaling, 3);
    fprintf(f, ",\n      \"isVisible\": true,\n");
    if (lay == LAYOUT_LEGACY) {
        /* position, normal, uv per vertex; v = 0 is the texture's top row */
        fprintf(f, "      \"uvCount\": 1,\n      \"vertices\": [\n");
        for (int i = 0; i < m->vertex_count; i++) {
            const gvert *v = &m->v[i];
            fprintf(f, "        %s,%s,%s, ", num(b[0], v->p[0], 4), num(b[1], v->p[1], 4),
                    num(b[2], v->p[2], 4));
            fprintf(f, "%s,%s,%s, ", num(b[0], v->n[0], 4), num(b[1], v->n[1], 4),
                    num(b[2], v->n[2], 4));
            fprintf(f, "%s,%s%s\n", num(b[0], v->uv[0], 4), num(b[1], v->uv[1], 4),
                    i + 1 < m->vertex_count ? "," : "");
        }
        fprintf(f, "      ],\n");
    } else {
        /* separate arrays; Babylon's current uvs have v = 0 at the bottom */
        static const char *const names[3] = {"positions", "normals", "uvs"};
        for (int a = 0; a < 3; a++) {
            fprintf(f, "      \"%s\": [\n", names[a]);
            for (int i = 0; i < m->vertex_count; i++) {
                const gvert *v = &m->v[i];
                const char *end = i + 1 < m->vertex_count ? "," : "";
                if (a == 2)
                    fprintf(f, "        %s,%s%s\n", num(b[0], v->uv[0], 4),
                            num(b[1], 1.0 - v->uv[1], 4), end);
                else {
                    const double *x = a == 0 ? v->p : v->n;
                    fprintf(f, "        %s,%s,%s%s\n", num(b[0], x[0], 4), num(b[1], x[1], 4),
                            num(b[2], x[2], 4), end);
                }
            }
            fprintf(f, "      ],\n");
        }
    }
    fprintf(f, "      \"indices\": [\n");
    for (int i = 0; i < m->index_count; i += 3)
        fprintf(f, "        %u,%u,%u%s\n", m->index[i], m->index[i + 1], m->index[i + 2],
                i + 3 < m->index_count ? "," : "");
    fprintf(f, "      ],\n");
    fprintf(f, "      \"subMeshes\": [{\"materialIndex\": 0, \"verticesStart\": 0, "
               "\"verticesCount\": %d, \"indexStart\": 0, \"indexCount\": %d}]\n    }",
            m->vertex_count, m->index_count);
}

static int write_scene(const char *dir, const char *file, const gscene *s, layout lay)
{
    char path[1024];
    snprintf(path, sizeof path, "%s/%s", dir, file);
    FILE *f = fopen(path, "wb");
    if (!f) {
        fprintf(stderr, "gen_assets: cannot write %s\n", path);
        return 1;
    }
    char b[64];
    fprintf(f, "{\n  \"producer\": {\"name\": \"mote gen_assets\", \"file\": \"%s\"},\n", file);
    fprintf(f, "  \"autoClear\": true,\n  \"clearColor\": ");
    put_vec(f, s->clear, 3);
    fprintf(f, ",\n  \"ambientColor\": ");
    put_vec(f, s->ambient, 3);
    fprintf(f, ",\n  \"cameras\": [\n    {\"name\": \"camera\", \"id\": \"camera\", "
               "\"position\": ");
    put_vec(f, s->eye, 3);
    fprintf(f, ", \"target\": ");
    put_vec(f, s->target, 3);
    fprintf(f, ", \"fov\": %s, \"minZ\": 0.1, \"maxZ\": 100}\n  ],\n", num(b, s->fov, 4));
    /* the legacy exporters wrote activeCamera, the current ones activeCameraID */
    fprintf(f, "  \"%s\": \"camera\",\n",
            lay == LAYOUT_LEGACY ? "activeCamera" : "activeCameraID");
    fprintf(f, "  \"lights\": [\n");
    for (int i = 0; i < s->light_count; i++) {
        const glight *l = &s->lights[i];
        fprintf(f, "    {\"name\": \"light%d\", \"id\": \"light%d\", \"type\": %d, ", i, i,
                l->type);
        if (l->type == 0)
            fprintf(f, "\"%s\": ", lay == LAYOUT_LEGACY ? "data" : "position");
        else
            fprintf(f, "\"%s\": ", lay == LAYOUT_LEGACY ? "data" : "direction");
        put_vec(f, l->vec, 3);
        fprintf(f, ", \"intensity\": %s, \"diffuse\": ", num(b, l->intensity, 4));
        put_vec(f, l->diffuse, 3);
        if (l->type == 3) {
            fprintf(f, ", \"groundColor\": ");
            put_vec(f, l->ground, 3);
        }
        fprintf(f, "}%s\n", i + 1 < s->light_count ? "," : "");
    }
    fprintf(f, "  ],\n  \"materials\": [\n");
    for (int i = 0; i < s->material_count; i++) {
        const gmaterial *m = &s->materials[i];
        fprintf(f, "    {\"name\": \"%s\", \"id\": \"%s\", \"diffuse\": ", m->id, m->id);
        put_vec(f, m->diffuse, 3);
        /* Babylon.js adds the scene's ambientColor times the material's
         * ambient colour (black unless written): the diffuse colour, so
         * that the ambient light tints as the lights do */
        fprintf(f, ", \"ambient\": ");
        put_vec(f, m->diffuse, 3);
        if (m->texture) {
            fprintf(f, ",\n     \"diffuseTexture\": {\"name\": \"%s\", \"uScale\": %s, ",
                    m->texture, num(b, m->u_scale, 4));
            fprintf(f, "\"vScale\": %s, \"uOffset\": 0, \"vOffset\": 0, \"wrapU\": 1, "
                       "\"wrapV\": 1}", num(b, m->v_scale, 4));
        }
        fprintf(f, "}%s\n", i + 1 < s->material_count ? "," : "");
    }
    fprintf(f, "  ],\n  \"meshes\": [\n");
    for (int i = 0; i < s->object_count; i++) {
        write_mesh(f, &s->objects[i], lay);
        fprintf(f, "%s\n", i + 1 < s->object_count ? "," : "");
    }
    fprintf(f, "  ]\n}\n");
    long size = ftell(f);
    if (fclose(f) != 0 || size < 0) {
        fprintf(stderr, "gen_assets: error writing %s\n", path);
        return 1;
    }
    printf("wrote %s (%ld bytes)\n", path, size);
    return 0;
}

/* ---- the texture ------------------------------------------------------- */

static int write_checker(const char *dir)
{
    enum { W = 256, H = 128, SQ = 16 };
    static const unsigned char dark[4][3] = {
        {40, 100, 190}, {50, 150, 80}, {120, 70, 170}, {30, 140, 150}};
    static unsigned char px[W * H * 4];
    for (int y = 0; y < H; y++) {
        for (int x = 0; x < W; x++) {
            unsigned char *p = &px[(y * W + x) * 4];
            int cx = x / SQ, cy = y / SQ;
            const unsigned char *c = dark[(cx / 4) % 4];
            unsigned char light[3] = {236, 232, 220};
            if ((cx + cy) % 2 == 0)
                c = light;
            /* top-left 2x2 squares: a red field with a white "F" */
            if (x < 2 * SQ && y < 2 * SQ) {
                static const unsigned char red[3] = {215, 40, 35}, white[3] = {255, 255, 255};
                bool stem = x >= 8 && x < 13 && y >= 5 && y < 27;
                bool top = x >= 8 && x < 24 && y >= 5 && y < 10;
                bool mid = x >= 8 && x < 20 && y >= 14 && y < 18;
                c = (stem || top || mid) ? white : red;
            }
            p[0] = c[0];
            p[1] = c[1];
            p[2] = c[2];
            p[3] = 255;
        }
    }
    char path[1024];
    snprintf(path, sizeof path, "%s/checker.png", dir);
    if (!stbi_write_png(path, W, H, 4, px, W * 4)) {
        fprintf(stderr, "gen_assets: cannot write %s\n", path);
        return 1;
    }
    printf("wrote %s (%dx%d)\n", path, W, H);
    return 0;
}

/* ---- the scenes -------------------------------------------------------- */

int main(int argc, char **argv)
{
    const char *dir = argc > 1 ? argv[1] : "assets";
    if (argc > 2 || (argc > 1 && (strcmp(argv[1], "--help") == 0 || argv[1][0] == '-'))) {
        fprintf(argc > 2 || strcmp(argv[1], "--help") != 0 ? stderr : stdout,
                "usage: gen_assets [DIR]   writes mote's assets into DIR (default assets)\n");
        return argc > 2 || strcmp(argv[1], "--help") != 0;
    }
    int err = write_checker(dir);

    gmesh cube = {0}, sphere = {0}, torus = {0}, ground = {0};
    gmesh demo_torus = {0}, ball = {0};   /* coarser, to keep demo.babylon small */
    static const double sphere_param[1] = {1.0};
    static const double torus_param[2] = {0.8, 0.3};
    static const double ground_param[1] = {14.0};
    make_cube(&cube, 0.8);
    make_grid(&sphere, 32, 16, sphere_point, sphere_param);
    make_grid(&torus, 40, 20, torus_point, torus_param);
    make_grid(&ground, 10, 10, plane_point, ground_param);
    make_grid(&demo_torus, 32, 16, torus_point, torus_param);
    make_grid(&ball, 20, 10, sphere_point, sphere_param);

    /* one object per file, seen from the front-top-right, lit from the
     * front-top-left */
    static const glight lamp = {0, {-2.0, 3.5, -4.0}, {1, 1, 1}, {0, 0, 0}, 1.0};
    static const gmaterial textured = {"checker", {1, 1, 1}, "checker.png", 1, 1};
    static const gmaterial torus_mat = {"checker", {1, 1, 1}, "checker.png", 2, 1};
    const struct {
        const char *name;
        const gmesh *mesh;
        const gmaterial *material;
    } singles[3] = {{"cube", &cube, &textured}, {"sphere", &sphere, &textured},
                    {"torus", &torus, &torus_mat}};
    for (int i = 0; i < 3; i++) {
        gobject o = {singles[i].name, singles[i].mesh, "checker",
                     {0, 0, 0}, {0, 0, 0}, {1, 1, 1}};
        gscene s = {{0.12, 0.13, 0.16}, {0.1, 0.1, 0.1}, {2.0, 1.6, -3.2}, {0, 0, 0}, 0.8,
                    &lamp, 1, singles[i].material, 1, &o, 1};
        char name[64];
        snprintf(name, sizeof name, "%s.babylon", singles[i].name);
        err |= write_scene(dir, name, &s, LAYOUT_CURRENT);
        snprintf(name, sizeof name, "%s.legacy.babylon", singles[i].name);
        err |= write_scene(dir, name, &s, LAYOUT_LEGACY);
    }

    /* the demo: a point light and a sky/ground light over four objects */
    static const glight demo_lights[2] = {
        {0, {-3.0, 5.0, -4.0}, {1.0, 0.95, 0.85}, {0, 0, 0}, 0.8},
        {3, {0.0, 1.0, 0.0}, {0.35, 0.4, 0.5}, {0.12, 0.1, 0.08}, 1.0},
    };
    static const gmaterial demo_materials[4] = {
        {"ground", {0.55, 0.58, 0.62}, NULL, 1, 1},
        {"checker", {1, 1, 1}, "checker.png", 1, 1},
        {"orange", {1.0, 0.55, 0.15}, NULL, 1, 1},
        {"teal", {0.2, 0.75, 0.8}, NULL, 1, 1},
    };
    const gobject demo_objects[5] = {
        {"ground", &ground, "ground", {0, 0, 0}, {0, 0, 0}, {1, 1, 1}},
        {"torus", &demo_torus, "orange", {-1.9, 1.05, 0.6}, {1.1, 0.5, 0}, {1, 1, 1}},
        {"sphere", &sphere, "checker", {0.2, 1.0, 0.9}, {0, 0.3, 0}, {1, 1, 1}},
        {"cube", &cube, "checker", {1.8, 0.8, -0.2}, {0, -0.6, 0}, {1, 1, 1}},
        {"ball", &ball, "teal", {-0.4, 0.45, -1.6}, {0, 0, 0}, {0.45, 0.45, 0.45}},
    };
    gscene demo = {{0.1, 0.11, 0.15}, {0.08, 0.08, 0.1}, {0.9, 3.3, -7.4}, {0.2, 0.6, 0.3},
                   0.75, demo_lights, 2, demo_materials, 4, demo_objects, 5};
    err |= write_scene(dir, "demo.babylon", &demo, LAYOUT_CURRENT);

    free_mesh(&cube);
    free_mesh(&sphere);
    free_mesh(&torus);
    free_mesh(&ground);
    free_mesh(&demo_torus);
    free_mesh(&ball);
    return err ? 1 : 0;
}
