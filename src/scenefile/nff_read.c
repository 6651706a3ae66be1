/* nff_read.c - Eric Haines' Neutral File Format (NFF), the format of the
 * Standard Procedural Databases (SPD): a view, a background, point lights,
 * fill materials, spheres, cylinders and cones, polygons and smooth
 * polygonal patches, one entity after another, read into a scene through
 * the public API. docs/nff.md gives the mapping onto glint's materials,
 * lights and camera; the first problem stops the load, as
 * "file:line:column: message". */
#include <errno.h>
#include <math.h>
#include <stdarg.h>
#include <stdint.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>
#include <sys/stat.h>
#include "core/array.h"
#include "core/error.h"
#include "core/short_decimal.h"
#include "core/vec.h"
#include "scene/polygon_split.h"
#include "scenefile/scene_bytes.h"
#include "scenefile/scene_file.h"
#include "scenefile/scene_reader.h"
#include "scenefile/sphere_list.h"

/* The longest word the reader quotes back in a message. */
#define QUOTED 40

/* Triangles gathered into one mesh: thousands of polygons (the SPD tetra's
 * 4,096) trace far faster as one mesh than as a mesh each. */
typedef struct gathered_mesh {
    float *positions, *normals;  /* normals: smooth patches only */
    uint32_t *indices;
    size_t position_cap, normal_cap, index_cap;
    int vertex_count, triangle_count;
} gathered_mesh;

typedef struct nff {
    const char *name, *p, *end, *line_start;
    int line;
    const char *word;           /* the last word read, its length, line and column */
    size_t word_length;
    int word_line, word_column;
    glint_scene *scene;
    glint_error *err;
    bool failed;
    bool viewed;                /* a `v` has been read */
    int material;               /* the last `f`'s, or -1 */
    bool transmits;             /* the last `f` lets light through */
    /* Lights are added once all are known: each gets sqrt(L) / (2 L). */
    glint_light *lights;
    size_t light_cap;
    int light_count;
    /* The smooth patches (`pp`) and the flat polygons (`p`) since the last
     * `f`: one mesh each. */
    gathered_mesh smooth, flat;
    /* The spheres: those whose fill lets light through apart, so that a
     * shadow ray stops at the others without asking what passes. */
    sphere_list opaque, clear;
    polygon_work polygon;
} nff;

/* Stops the load with "file:line:column: message" at the last word read. */
__attribute__((format(printf, 2, 3))) static bool fail(nff *n, const char *fmt, ...)
{
    if (n->failed)
        return false;
    char what[sizeof n->err->message];
    va_list ap;
    va_start(ap, fmt);
    vsnprintf(what, sizeof what, fmt, ap);
    va_end(ap);
    error_set(n->err, GLINT_ERR_INVALID, "%s:%d:%d: %s", n->name, n->word_line, n->word_column, what);
    n->failed = true;
    return false;
}

/* Stops the load with a failed call's error at the last word read, its
 * status kept (running out of memory stays GLINT_ERR_NOMEM). */
static bool fail_call(nff *n, const glint_error *call)
{
    bool ok = fail(n, "%s", call->message);
    n->err->status = call->status;
    return ok;
}

/* Whether c ends a word: a blank, a line end, a comment's `#`, or a zero
 * byte (which then ends the input). */
static inline bool word_end(char c)
{
    return c == ' ' || c == '\t' || c == '\r' || c == '\n' || c == '\f' || c == '\v' || c == '#' || c == '\0';
}

/* Reads the next word (skipping blanks, line ends and `#` comments) into
 * n->word; false at the end of the input. */
static bool next_word(nff *n)
{
    for (;;) {
        while (n->p < n->end && (*n->p == ' ' || *n->p == '\t' || *n->p == '\r' || *n->p == '\n' ||
                                 *n->p == '\f' || *n->p == '\v')) {
            if (*n->p == '\n') {
                n->line++;
                n->line_start = n->p + 1;
            }
            n->p++;
        }
        if (n->p < n->end && *n->p == '#') {
            while (n->p < n->end && *n->p != '\n')
                n->p++;
            continue;
        }
        break;
    }
    n->word = n->p;
    n->word_line = n->line;
    n->word_column = (int)(n->p - n->line_start) + 1;
    while (n->p < n->end && !word_end(*n->p))
        n->p++;
    n->word_length = (size_t)(n->p - n->word);
    return n->word_length > 0;
}

/* The last word as a message quotes it: printable, at most QUOTED bytes. */
static const char *quoted(const nff *n, char out[QUOTED + 4])
{
    size_t k = 0;
    for (; k < n->word_length && k < QUOTED; k++)
        out[k] = n->word[k] >= ' ' && n->word[k] < 127 ? n->word[k] : '?';
    strcpy(out + k, k < n->word_length ? "..." : "");
    return out;
}

/* An NFF colour, written for the screen as the SPD renderers wrote it out,
 * in glint's linear light (0 to 1 by the sRGB curve; beyond, as is). */
static glint_color linear(const double c[3])
{
    glint_color out;
    double *ch[3] = {&out.r, &out.g, &out.b};
    for (int i = 0; i < 3; i++)
        *ch[i] = c[i] > 0 && c[i] < 1 ? glint_srgb_to_linear(c[i]) : c[i];
    return out;
}

/* Reads a finite number, `what` naming it in a message. */
static bool number(nff *n, const char *what, double *v)
{
    char buf[64], q[QUOTED + 4];
    if (!next_word(n))
        return fail(n, "the file ends where %s should be", what);
    if (n->word_length >= sizeof buf)
        return fail(n, "%s should be a number, got '%s'", what, quoted(n, q));
    memcpy(buf, n->word, n->word_length);
    buf[n->word_length] = '\0';
    /* The SPD write short decimals, which short_decimal reads as strtod
     * would, in a tenth of the time. */
    if (short_decimal(buf, v))
        return true;
    char *stop;
    errno = 0;
    *v = strtod(buf, &stop);
    if (*stop || stop == buf)
        return fail(n, "%s should be a number, got '%s'", what, quoted(n, q));
    if (!isfinite(*v))
        return fail(n, "%s must be finite, got '%s'", what, quoted(n, q));
    return true;
}

static bool numbers(nff *n, const char *what, double *v, int count)
{
    for (int i = 0; i < count; i++)
        if (!number(n, what, &v[i]))
            return false;
    return true;
}

static bool point(nff *n, const char *what, glint_vec3 *p)
{
    double v[3];
    if (!numbers(n, what, v, 3))
        return false;
    *p = (glint_vec3){v[0], v[1], v[2]};
    return true;
}

/* Reads the word `key` of a view, then `count` numbers. */
static bool view_line(nff *n, const char *key, double *v, int count)
{
    char q[QUOTED + 4], what[48];
    if (!next_word(n))
        return fail(n, "the file ends where the view's '%s' should be", key);
    if (n->word_length != strlen(key) || memcmp(n->word, key, n->word_length) != 0)
        return fail(n, "the view's next line should start with '%s', got '%s'", key, quoted(n, q));
    snprintf(what, sizeof what, "the view's %s", key);
    return numbers(n, what, v, count);
}

/* `v`: from, at, up, angle, hither, resolution, in that order. The angle
 * runs between the centres of the top and bottom pixel rows; glint's field
 * of view runs between their outer edges. */
static bool read_view(nff *n)
{
    double from[3], at[3], up[3], angle, hither, resolution[2];
    if (!view_line(n, "from", from, 3) || !view_line(n, "at", at, 3) || !view_line(n, "up", up, 3) ||
        !view_line(n, "angle", &angle, 1) || !view_line(n, "hither", &hither, 1) ||
        !view_line(n, "resolution", resolution, 2))
        return false;
    if (!(angle > 0 && angle < 180))
        return fail(n, "the view's angle must be between 0 and 180 degrees, got %g", angle);
    if (resolution[0] != floor(resolution[0]) || resolution[1] != floor(resolution[1]) || resolution[0] < 1 ||
        resolution[1] < 1 || resolution[0] > 65536 || resolution[1] > 65536)
        return fail(n, "the view's resolution must be two whole numbers from 1 to 65536, got %g %g",
                    resolution[0], resolution[1]);
    glint_error call;
    glint_settings s = glint_scene_get_settings(n->scene);
    s.width = (int)resolution[0];
    s.height = (int)resolution[1];
    if (glint_scene_set_settings(n->scene, &s, &call))
        return fail_call(n, &call);
    double rows = resolution[1], half = tan(angle * M_PI / 360);
    double edges = rows > 1 ? 2 * atan(half * rows / (rows - 1)) * 180 / M_PI : angle;
    glint_camera cam = {.kind = GLINT_CAMERA_PINHOLE, .position = {from[0], from[1], from[2]},
                        .look_at = {at[0], at[1], at[2]}, .up = {up[0], up[1], up[2]},
                        .vfov_degrees = edges < 179 ? edges : 179};
    if (glint_scene_set_camera(n->scene, &cam, &call))
        return fail_call(n, &call);
    n->viewed = true;
    return true;
}

/* `f` r g b Kd Ks Shine T ior: Ks is both the highlight and the mirror
 * reflectance, T the refracted share, filtered by the colour (its index
 * unused, and 1, where T is 0). */
static bool read_fill(nff *n)
{
    double v[8];
    if (!numbers(n, "a fill's value", v, 8))
        return false;
    glint_material m = glint_material_default();
    m.color = linear(v);
    m.diffuse = v[3];
    m.specular = v[4];
    m.reflectivity = v[4];
    m.shininess = v[5];
    m.refraction = v[6];
    /* The SPD write an index of 0 for what transmits nothing. */
    m.ior = v[6] == 0 && v[7] <= 0 ? 1 : v[7];
    m.transparency = 0;
    m.tint = 1;
    glint_error call;
    int k = glint_scene_add_material(n->scene, NULL, &m, &call);
    if (k < 0)
        return fail_call(n, &call);
    n->material = k;
    n->transmits = v[6] != 0;
    return true;
}

/* The material objects take: the last `f`'s, or matte white before any. */
static bool material(nff *n, int *k)
{
    if (n->material < 0) {
        glint_material m = glint_material_default();
        m.color = (glint_color){1, 1, 1};
        m.specular = m.reflectivity = 0;
        glint_error call;
        n->material = glint_scene_add_material(n->scene, NULL, &m, &call);
        if (n->material < 0)
            return fail_call(n, &call);
    }
    *k = n->material;
    return true;
}

/* Whether the next word is a number, the input left where it was. */
static bool number_follows(nff *n)
{
    const char *at = n->p, *line_start = n->line_start;
    int line = n->line;
    bool found = false;
    if (next_word(n) && n->word_length < 64) {
        char buf[64], *stop;
        memcpy(buf, n->word, n->word_length);
        buf[n->word_length] = '\0';
        strtod(buf, &stop);
        found = stop != buf && !*stop;
    }
    n->p = at;
    n->line_start = line_start;
    n->line = line;
    return found;
}

/* `l` x y z [r g b]: the colour is optional, so the next word decides. */
static bool read_light(nff *n)
{
    glint_light l = glint_light_default(GLINT_LIGHT_POINT);
    if (!point(n, "a light's position", &l.position))
        return false;
    l.color = (glint_color){1, 1, 1};
    double c[3];
    if (number_follows(n)) {
        if (!numbers(n, "a light's colour", c, 3))
            return false;
        l.color = linear(c);
    }
    if (!array_reserve((void **)&n->lights, &n->light_cap, (size_t)n->light_count + 1, sizeof *n->lights))
        return fail(n, "out of memory");
    n->lights[n->light_count++] = l;
    return true;
}

/* The rotation taking +y to unit vector d, then the move to `to`. */
static glint_transform axis_frame(glint_vec3 d, glint_vec3 to)
{
    glint_vec3 other = fabs(d.x) < 0.6 ? (glint_vec3){1, 0, 0} : (glint_vec3){0, 1, 0};
    /* e1 across d, e2 = e1 x d: (e1, d, e2) turn as (x, y, z) do. */
    glint_vec3 e1 = {d.y * other.z - d.z * other.y, d.z * other.x - d.x * other.z, d.x * other.y - d.y * other.x};
    double l = sqrt(e1.x * e1.x + e1.y * e1.y + e1.z * e1.z);
    e1 = (glint_vec3){e1.x / l, e1.y / l, e1.z / l};
    glint_vec3 e2 = {e1.y * d.z - e1.z * d.y, e1.z * d.x - e1.x * d.z, e1.x * d.y - e1.y * d.x};
    glint_transform t = {{{e1.x, d.x, e2.x, to.x}, {e1.y, d.y, e2.y, to.y}, {e1.z, d.z, e2.z, to.z}}};
    return t;
}

/* `c`: base and radius, apex and radius; open at both ends. A negative
 * pair of radii (only the inside seen) is drawn as the outside would be. */
static bool read_cone(nff *n)
{
    double b[4], a[4];
    int k = -1;
    if (!numbers(n, "a cone's base", b, 4) || !numbers(n, "a cone's apex", a, 4) || !material(n, &k))
        return false;
    glint_vec3 d = {a[0] - b[0], a[1] - b[1], a[2] - b[2]};
    double h = sqrt(d.x * d.x + d.y * d.y + d.z * d.z);
    if (!(h > 0))
        return fail(n, "a cone's base and apex are the same point");
    double r0 = fabs(b[3]), r1 = fabs(a[3]);
    glint_shape s = glint_shape_default(r0 == r1 ? GLINT_SHAPE_CYLINDER : GLINT_SHAPE_CONE);
    s.center = (glint_vec3){0, 0, 0};
    s.radius = r0;
    s.height = h;
    s.capped = s.top_capped = false;
    if (r0 != r1)
        s.top_radius = r1;
    glint_transform t = axis_frame((glint_vec3){d.x / h, d.y / h, d.z / h}, (glint_vec3){b[0], b[1], b[2]});
    glint_error call;
    if (glint_scene_add_shape(n->scene, &s, k, &t, &call) < 0)
        return fail_call(n, &call);
    return true;
}

/* `s` x y z r; a negative radius is drawn as its size. */
static bool read_sphere(nff *n)
{
    double v[4];
    int k = -1;
    if (!numbers(n, "a sphere's value", v, 4))
        return false;
    if (v[3] == 0)
        return fail(n, "a sphere's radius must not be 0");
    if (!material(n, &k))
        return false;
    if (sphere_list_add(n->transmits ? &n->clear : &n->opaque, (glint_vec3){v[0], v[1], v[2]}, fabs(v[3]), k))
        return true;
    fail(n, "out of memory");
    n->err->status = GLINT_ERR_NOMEM;
    return false;
}

/* Adds the spheres gathered as one sphere set. */
static bool flush_spheres(nff *n, const sphere_list *g)
{
    glint_error call;
    if (g->count > 0 && glint_scene_add_spheres(n->scene, g->count, g->centers, g->radii, g->materials, &call) < 0)
        return fail_call(n, &call);
    return true;
}

/* A polygon's or patch's vertex count: a whole number from 3. */
static bool vertex_count(nff *n, const char *what, int *count)
{
    double v;
    if (!number(n, what, &v))
        return false;
    if (v != floor(v) || v < 3 || v > GLINT_MAX_POLYGON_POINTS)
        return fail(n, "%s must be a whole number from 3 to %d, got %g", what, GLINT_MAX_POLYGON_POINTS, v);
    *count = (int)v;
    return true;
}

/* Makes room in g for `vertices` more vertices (with normals when `smooth`)
 * and `triangles` more triangles. */
static bool mesh_room(nff *n, gathered_mesh *g, int vertices, int triangles, bool smooth)
{
    size_t v = (size_t)g->vertex_count + (size_t)vertices;
    size_t t = (size_t)g->triangle_count + (size_t)triangles;
    if (v > (1u << 30) || t > (1u << 30))
        return fail(n, "too many vertices for one mesh");
    if (!array_reserve((void **)&g->positions, &g->position_cap, 3 * v, sizeof *g->positions) ||
        (smooth && !array_reserve((void **)&g->normals, &g->normal_cap, 3 * v, sizeof *g->normals)) ||
        !array_reserve((void **)&g->indices, &g->index_cap, 3 * t, sizeof *g->indices))
        return fail(n, "out of memory");
    return true;
}

/* `p` count, then the points: one flat polygon, convex or not, its
 * triangles added to the current fill's flat mesh. */
static bool read_polygon(nff *n)
{
    int count = 0, k = -1;
    if (!vertex_count(n, "a polygon's vertex count", &count) || !material(n, &k))
        return false;
    glint_vec3 *points = malloc((size_t)count * sizeof *points);
    if (!points)
        return fail(n, "out of memory");
    bool ok = true;
    for (int i = 0; ok && i < count; i++)
        ok = point(n, "a polygon's vertex", &points[i]);
    gathered_mesh *g = &n->flat;
    ok = ok && mesh_room(n, g, count, count - 2, false);
    if (ok) {
        glint_error call;
        vec3 normal;
        uint32_t first = (uint32_t)g->vertex_count, *t = g->indices + 3 * (size_t)g->triangle_count;
        if (polygon_split(&n->polygon, points, count, g->positions + 3 * (size_t)first, &normal, t, &call)) {
            ok = fail_call(n, &call);
        } else {
            for (int i = 0; i < 3 * (count - 2); i++)
                t[i] += first;
            g->vertex_count += count;
            g->triangle_count += count - 2;
        }
    }
    free(points);
    return ok;
}

/* Adds the triangles gathered since the last `f` as one mesh, smooth or
 * flat, placed once. */
static bool flush_mesh(nff *n, gathered_mesh *g)
{
    if (g->triangle_count == 0)
        return true;
    glint_mesh_data m = {.positions = g->positions, .normals = g->normals,
                         .vertex_count = g->vertex_count, .indices = g->indices,
                         .triangle_count = g->triangle_count, .material = n->material};
    glint_error call;
    int mesh = glint_scene_add_mesh(n->scene, NULL, &m, &call);
    g->vertex_count = g->triangle_count = 0;
    if (mesh < 0 || glint_scene_add_instance(n->scene, mesh, -1, NULL, &call) < 0)
        return fail_call(n, &call);
    return true;
}

static bool flush_meshes(nff *n)
{
    return flush_mesh(n, &n->flat) && flush_mesh(n, &n->smooth);
}

static void free_mesh(gathered_mesh *g)
{
    free(g->positions);
    free(g->normals);
    free(g->indices);
}

/* `pp` count, then points each with its normal: a smooth patch, as a fan
 * of triangles into the current material's mesh. */
static bool read_patch(nff *n)
{
    int count = 0, k = -1;
    if (!vertex_count(n, "a patch's vertex count", &count) || !material(n, &k))
        return false;
    gathered_mesh *g = &n->smooth;
    if (!mesh_room(n, g, count, count - 2, true))
        return false;
    uint32_t first = (uint32_t)g->vertex_count;
    for (int i = 0; i < count; i++) {
        double v[6];
        if (!numbers(n, "a patch's vertex or normal", v, 6))
            return false;
        for (int c = 0; c < 3; c++) {
            float p = (float)v[c], q = (float)v[3 + c];
            if (!isfinite(p) || !isfinite(q))
                return fail(n, "a patch's vertex is too large for single precision");
            g->positions[3 * (first + (uint32_t)i) + (uint32_t)c] = p;
            g->normals[3 * (first + (uint32_t)i) + (uint32_t)c] = q;
        }
    }
    for (int i = 1; i + 1 < count; i++) {
        uint32_t *t = &g->indices[3 * (size_t)g->triangle_count++];
        t[0] = first;
        t[1] = first + (uint32_t)i;
        t[2] = first + (uint32_t)i + 1;
    }
    g->vertex_count += count;
    return true;
}

/* The entity named by the word just read. */
static bool read_entity(nff *n)
{
    char q[QUOTED + 4];
    const char *w = n->word;
    size_t len = n->word_length;
    if (len == 1 && w[0] == 'v')
        return read_view(n);
    if (len == 1 && w[0] == 'b') {
        double c[3];
        if (!numbers(n, "the background's colour", c, 3))
            return false;
        glint_settings s = glint_scene_get_settings(n->scene);
        s.background = linear(c);
        glint_error call;
        return glint_scene_set_settings(n->scene, &s, &call) ? fail_call(n, &call) : true;
    }
    if (len == 1 && w[0] == 'l')
        return read_light(n);
    if (len == 1 && w[0] == 'f')
        return flush_meshes(n) && read_fill(n);
    if (!n->viewed && ((len == 1 && strchr("csp", w[0])) || (len == 2 && memcmp(w, "pp", 2) == 0)))
        return fail(n, "'%s' before the view: an NFF file gives its 'v' before any object", quoted(n, q));
    if (len == 1 && w[0] == 'c')
        return read_cone(n);
    if (len == 1 && w[0] == 's')
        return read_sphere(n);
    if (len == 1 && w[0] == 'p')
        return read_polygon(n);
    if (len == 2 && memcmp(w, "pp", 2) == 0)
        return read_patch(n);
    return fail(n, "unknown entity '%s' (NFF has v, b, l, f, c, s, p, pp and # comments)", quoted(n, q));
}

/* Adds the lights, sqrt(L) / (2 L) each as the SPD suggest for L lights,
 * times their colours. */
static bool add_lights(nff *n)
{
    double share = sqrt(n->light_count) / (2.0 * n->light_count);
    glint_error call;
    for (int i = 0; i < n->light_count; i++) {
        glint_light l = n->lights[i];
        l.color = (glint_color){l.color.r * share, l.color.g * share, l.color.b * share};
        if (glint_scene_add_light(n->scene, &l, &call) < 0)
            return fail_call(n, &call);
    }
    return true;
}

/* Reads the NFF text data[0..size) named `name` into a new scene. */
static glint_scene *read_nff(const char *data, size_t size, const char *name, glint_error *err)
{
    nff n = {.name = name, .p = data, .end = data + size, .line_start = data, .line = 1, .err = err,
             .material = -1};
    n.scene = glint_scene_new();
    if (!n.scene) {
        error_set(err, GLINT_ERR_NOMEM, "out of memory");
        return NULL;
    }
    glint_settings s = glint_scene_get_settings(n.scene);
    s.samples_per_pixel = 1;
    s.max_depth = 5;
    s.background = (glint_color){0, 0, 0};
    /* The SPD's reference images have none: faces turned from every
     * light are black. */
    s.ambient_light = (glint_color){0, 0, 0};
    glint_error call;
    if (glint_scene_set_settings(n.scene, &s, &call))
        fail_call(&n, &call);
    while (!n.failed && next_word(&n))
        read_entity(&n);
    if (!n.failed && !n.viewed) {
        error_set(err, GLINT_ERR_INVALID, "%s: no view: an NFF file starts with 'v'", name);
        n.failed = true;
    }
    if (!n.failed && flush_meshes(&n) && flush_spheres(&n, &n.opaque) && flush_spheres(&n, &n.clear))
        add_lights(&n);
    free(n.lights);
    sphere_list_free(&n.opaque);
    sphere_list_free(&n.clear);
    free_mesh(&n.smooth);
    free_mesh(&n.flat);
    polygon_work_free(&n.polygon);
    if (n.failed) {
        glint_scene_free(n.scene);
        return NULL;
    }
    return n.scene;
}

/* The first problem also goes to the caller's report, as the YAML
 * reader's do. */
static glint_scene *reported(glint_scene *scene, const glint_load_options *o, const glint_error *err)
{
    if (!scene && o && o->report)
        o->report(o->report_user, err->message);
    return scene;
}

static glint_scene *nff_load_memory(const char *data, size_t size, const char *name,
                                    const glint_load_options *options, glint_error *err)
{
    glint_error mine;
    err = err ? err : &mine;
    name = name ? name : "<memory>";
    if (size > (size_t)SCENE_FILE_MAX_BYTES) {
        error_set(err, GLINT_ERR_INVALID, "scene '%s' is too large: %zu bytes (limit %ld)", name, size,
                  SCENE_FILE_MAX_BYTES);
        return reported(NULL, options, err);
    }
    return reported(read_nff(data ? data : "", data ? size : 0, name, err), options, err);
}

static glint_scene *nff_load_file(const char *path, const glint_load_options *options, glint_error *err)
{
    glint_error mine;
    err = err ? err : &mine;
    struct stat st;
    size_t size = 0;
    char *data = scene_bytes_of_file(path, false, &size, &st, err);
    glint_scene *scene = data ? read_nff(data, size, path, err) : NULL;
    free(data);
    return reported(scene, options, err);
}

static glint_scene *nff_load_stream(FILE *in, const char *name, const glint_load_options *options,
                                    glint_error *err)
{
    glint_error mine;
    err = err ? err : &mine;
    name = name ? name : "<stream>";
    size_t size = 0;
    char *data = scene_bytes_of_stream(in, name, &size, err);
    glint_scene *scene = data ? read_nff(data, size, name, err) : NULL;
    free(data);
    return reported(scene, options, err);
}

static const char *const NFF_EXTENSIONS[] = {".nff", NULL};

const scene_reader nff_scene_reader = {
    .name = "NFF", .extensions = NFF_EXTENSIONS, .load_file = nff_load_file, .load_memory = nff_load_memory,
    .load_stream = nff_load_stream,
};
