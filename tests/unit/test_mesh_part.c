/* test_mesh_part.c - closed meshes as parts of combinations: the mesh's
 * own hierarchy against a test of every triangle in long double, rays
 * through its corners and edges that never slip through, points inside
 * and outside a faceted ball minus a sphere against the analytic set, a
 * cube of triangles that renders as the box shape does (either winding,
 * and in glass), the triangles' own materials and vertex normals, and the
 * meshes a combination refuses with their messages. */
#include <stdarg.h>
#include <stddef.h>
#include <setjmp.h>
#include <stdint.h>
#include <cmocka.h>
#include <math.h>
#include <stdlib.h>
#include <string.h>
#include "glint.h"
#include "first_crossing.h"
#include "geometry/triangle_tree.h"
#include "one_sample_scene.h"
#include "scene/scene.h"

/* A closed triangle mesh being made. */
typedef struct made {
    float p[3 * 4096];
    uint32_t idx[3 * 4096];
    int vertices, triangles;
} made;

static uint32_t vertex(made *m, double x, double y, double z)
{
    m->p[3 * m->vertices] = (float)x;
    m->p[3 * m->vertices + 1] = (float)y;
    m->p[3 * m->vertices + 2] = (float)z;
    return (uint32_t)m->vertices++;
}

static void triangle(made *m, uint32_t a, uint32_t b, uint32_t c)
{
    m->idx[3 * m->triangles] = a;
    m->idx[3 * m->triangles + 1] = b;
    m->idx[3 * m->triangles + 2] = c;
    m->triangles++;
}

/* The vertex halfway between a and b on the unit sphere, shared by both
 * triangles of the edge (looked up among those made so far). */
static uint32_t middle(made *m, uint32_t a, uint32_t b)
{
    double x = m->p[3 * a] + m->p[3 * b], y = m->p[3 * a + 1] + m->p[3 * b + 1], z = m->p[3 * a + 2] + m->p[3 * b + 2];
    double l = sqrt(x * x + y * y + z * z);
    float f[3] = {(float)(x / l), (float)(y / l), (float)(z / l)};
    for (int i = 0; i < m->vertices; i++)
        if (memcmp(&m->p[3 * i], f, sizeof f) == 0)
            return (uint32_t)i;
    return vertex(m, f[0], f[1], f[2]);
}

/* A convex faceted ball: an octahedron whose triangles are split in four
 * `levels` times, its corners pushed out to the unit sphere; anticlockwise
 * seen from outside. */
static void faceted_ball(made *m, int levels)
{
    m->vertices = m->triangles = 0;
    const double c[6][3] = {{1, 0, 0}, {-1, 0, 0}, {0, 1, 0}, {0, -1, 0}, {0, 0, 1}, {0, 0, -1}};
    for (int i = 0; i < 6; i++)
        vertex(m, c[i][0], c[i][1], c[i][2]);
    const uint32_t faces[8][3] = {{0, 2, 4}, {4, 2, 1}, {1, 2, 5}, {5, 2, 0},
                                  {0, 4, 3}, {4, 1, 3}, {1, 5, 3}, {5, 0, 3}};
    for (int i = 0; i < 8; i++)
        triangle(m, faces[i][0], faces[i][1], faces[i][2]);
    for (int l = 0; l < levels; l++) {
        int count = m->triangles;
        uint32_t old[3 * 4096];
        memcpy(old, m->idx, sizeof(uint32_t) * 3 * (size_t)count);
        m->triangles = 0;
        for (int t = 0; t < count; t++) {
            uint32_t a = old[3 * t], b = old[3 * t + 1], cc = old[3 * t + 2];
            uint32_t ab = middle(m, a, b), bc = middle(m, b, cc), ca = middle(m, cc, a);
            triangle(m, a, ab, ca);
            triangle(m, ab, b, bc);
            triangle(m, ca, bc, cc);
            triangle(m, ab, bc, ca);
        }
    }
}

/* The cube from -1 to 1, each face its own four vertices (as a model's
 * seams split them), split into two triangles; `inward`: wound the other
 * way. */
static void split_cube(made *m, bool inward)
{
    m->vertices = m->triangles = 0;
    for (int axis = 0; axis < 3; axis++)
        for (int side = -1; side <= 1; side += 2) {
            /* Corners of the face, anticlockwise seen from outside. */
            double q[4][2] = {{-1, -1}, {1, -1}, {1, 1}, {-1, 1}};
            uint32_t v[4];
            for (int k = 0; k < 4; k++) {
                double p[3];
                p[axis] = side;
                p[(axis + 1) % 3] = q[k][0] * side;
                p[(axis + 2) % 3] = q[k][1];
                v[k] = vertex(m, p[0], p[1], p[2]);
            }
            if (inward) {
                triangle(m, v[0], v[2], v[1]);
                triangle(m, v[0], v[3], v[2]);
            } else {
                triangle(m, v[0], v[1], v[2]);
                triangle(m, v[0], v[2], v[3]);
            }
        }
}

/* Corner k of triangle tri. */
static vec3 corner(const made *m, int tri, int k)
{
    const float *p = &m->p[3 * m->idx[3 * tri + k]];
    return v3(p[0], p[1], p[2]);
}

/* The unit normal of triangle tri, out of the solid. */
static vec3 face_normal(const made *m, int tri)
{
    vec3 p0 = corner(m, tri, 0);
    return v3_normalize(v3_cross(v3_sub(corner(m, tri, 1), p0), v3_sub(corner(m, tri, 2), p0)));
}

static int add_mesh(glint_scene *s, const made *m, const int *materials, int mat, bool normals)
{
    float n[3 * 4096];
    for (int i = 0; i < 3 * m->vertices; i++)
        n[i] = m->p[i];
    glint_mesh_data d = {m->p, normals ? n : NULL, NULL, m->vertices, m->idx, m->triangles, materials, mat};
    glint_error err;
    int i = glint_scene_add_mesh(s, NULL, &d, &err);
    if (i < 0)
        fail_msg("%s", err.message);
    return i;
}

/* The nearest crossing of r with triangle (a, b, c) past tmin, in long
 * double (Moller and Trumbore's), and how far inside its edges the point
 * is, as the least barycentric weight. */
static bool reference_hit(const ray *r, const float *a, const float *b, const float *c, double tmin, long double *t,
                          long double *inside)
{
    long double e1[3], e2[3], o[3], d[3] = {r->d.x, r->d.y, r->d.z}, org[3] = {r->o.x, r->o.y, r->o.z};
    for (int k = 0; k < 3; k++) {
        e1[k] = (long double)b[k] - a[k];
        e2[k] = (long double)c[k] - a[k];
        o[k] = org[k] - a[k];
    }
    long double p[3] = {d[1] * e2[2] - d[2] * e2[1], d[2] * e2[0] - d[0] * e2[2], d[0] * e2[1] - d[1] * e2[0]};
    long double det = e1[0] * p[0] + e1[1] * p[1] + e1[2] * p[2];
    if (det == 0)
        return false;
    long double u = (o[0] * p[0] + o[1] * p[1] + o[2] * p[2]) / det;
    long double q[3] = {o[1] * e1[2] - o[2] * e1[1], o[2] * e1[0] - o[0] * e1[2], o[0] * e1[1] - o[1] * e1[0]};
    long double v = (d[0] * q[0] + d[1] * q[1] + d[2] * q[2]) / det;
    *t = (e2[0] * q[0] + e2[1] * q[1] + e2[2] * q[2]) / det;
    *inside = fminl(fminl(u, v), 1 - u - v);
    return *inside >= 0 && *t > tmin;
}

static double uniform(unsigned *seed)
{
    *seed = *seed * 1664525u + 1013904223u;
    return (*seed >> 8) / 16777216.0;
}

/* The hierarchy finds what testing every triangle in long double finds:
 * the same triangle at the same distance, for random rays from inside and
 * outside a faceted ball, from 0 and from past a first crossing. Rays
 * within 1e-9 of an edge, where either triangle is right, are left out. */
static void test_tree_matches_every_triangle(void **state)
{
    static made m;
    faceted_ball(&m, 3);
    triangle_tree t;
    assert_int_equal(triangle_tree_build(&t, m.p, m.idx, m.triangles, NULL), GLINT_OK);
    unsigned seed = 7;
    int hits = 0, compared = 0;
    for (int i = 0; i < 4000; i++) {
        vec3 from = v3(4 * uniform(&seed) - 2, 4 * uniform(&seed) - 2, 4 * uniform(&seed) - 2);
        vec3 toward = v3(2 * uniform(&seed) - 1, 2 * uniform(&seed) - 1, 2 * uniform(&seed) - 1);
        ray r = {from, v3_sub(toward, from)};
        double tmin = i % 2 ? 0 : uniform(&seed);
        long double best = INFINITY, inside, at;
        int want = -1;
        bool edge = false;
        for (int k = 0; k < m.triangles; k++) {
            const uint32_t *v = &m.idx[3 * k];
            if (reference_hit(&r, &m.p[3 * v[0]], &m.p[3 * v[1]], &m.p[3 * v[2]], tmin, &at, &inside) && at < best) {
                best = at;
                want = k;
                edge = inside < 1e-9;
            }
        }
        if (edge)
            continue;
        double got;
        uint32_t tri;
        bool hit = triangle_tree_hit(&t, &r, tmin, INFINITY, &got, &tri);
        assert_int_equal(hit, want >= 0);
        compared++;
        if (!hit)
            continue;
        hits++;
        assert_int_equal((int)tri, want);
        assert_true(fabsl(got - best) <= 1e-12L * best);
    }
    assert_true(hits > 2500 && compared > 3900);
    triangle_tree_free(&t);
}

/* Rays aimed exactly at the ball's corners and at points of its edges,
 * from many directions, never slip between its triangles: each meets the
 * ball, first going in, and last coming out. */
static void test_rays_through_corners_and_edges_hit(void **state)
{
    static made m;
    faceted_ball(&m, 3);
    triangle_tree t;
    assert_int_equal(triangle_tree_build(&t, m.p, m.idx, m.triangles, NULL), GLINT_OK);
    unsigned seed = 11;
    int rays = 0;
    for (int k = 0; k < m.triangles; k++)
        for (int e = 0; e < 3; e++) {
            const float *a = &m.p[3 * m.idx[3 * k + e]], *b = &m.p[3 * m.idx[3 * k + (e + 1) % 3]];
            /* The corner itself, and a point along the edge exact in binary. */
            for (int w = 0; w < 2; w++) {
                double f = w ? 0.25 : 0;
                vec3 target = v3(a[0] + f * (b[0] - a[0]), a[1] + f * (b[1] - a[1]), a[2] + f * (b[2] - a[2]));
                vec3 from = v3_add(v3_scale(target, 2.5), v3(uniform(&seed) - 0.5, uniform(&seed) - 0.5,
                                                             uniform(&seed) - 0.5));
                ray r = {from, v3_sub(target, from)};
                double at, after = 0;
                uint32_t tri;
                int crossings = 0;
                bool last_in = false;
                while (triangle_tree_hit(&t, &r, after, INFINITY, &at, &tri)) {
                    bool in = v3_dot(face_normal(&m, (int)tri), r.d) < 0;
                    if (crossings == 0)
                        assert_true(in);
                    last_in = in;
                    after = at;
                    crossings++;
                }
                assert_true(crossings >= 2);
                assert_false(last_in);
                rays++;
            }
        }
    assert_int_equal(rays, 6 * m.triangles);
    triangle_tree_free(&t);
}

/* From each point of a grid, the first crossing of a faceted ball minus
 * a sphere leaves it exactly when the point is inside the set: inside
 * every face's plane (the ball is convex) and outside the sphere. */
static void test_inside_outside_on_a_grid(void **state)
{
    static made m;
    faceted_ball(&m, 2);
    glint_scene *s = glint_scene_new();
    glint_material look = glint_material_default();
    int mat = glint_scene_add_material(s, NULL, &look, NULL);
    glint_error err;
    glint_shape minus = glint_shape_default(GLINT_SHAPE_DIFFERENCE);
    int top = glint_scene_add_shape(s, &minus, -1, NULL, &err);
    assert_true(glint_scene_add_mesh_part(s, top, add_mesh(s, &m, NULL, mat, false), -1, NULL, &err) >= 0);
    glint_shape ball = glint_shape_default(GLINT_SHAPE_SPHERE);
    ball.center = (glint_vec3){0.6, 0.2, 0};
    ball.radius = 0.7;
    assert_true(glint_scene_add_part(s, top, &ball, mat, NULL, &err) >= 0);
    vec3 d = v3_normalize(v3(0.31, 0.17, 0.93));
    int inside = 0, checked = 0;
    for (double x = -1.15; x <= 1.15; x += 0.1)
        for (double y = -1.15; y <= 1.15; y += 0.1)
            for (double z = -1.15; z <= 1.15; z += 0.1) {
                vec3 p = v3(x, y, z);
                double ball_gap = v3_length(v3_sub(p, v3(0.6, 0.2, 0))) - 0.7, plane_gap = -INFINITY;
                for (int k = 0; k < m.triangles; k++)
                    plane_gap = fmax(plane_gap, v3_dot(v3_sub(p, corner(&m, k, 0)), face_normal(&m, k)));
                if (fabs(ball_gap) < 1e-9 || fabs(plane_gap) < 1e-9)
                    continue;
                bool want = plane_gap < 0 && ball_gap > 0;
                assert_int_equal(first_crossing_leaves(s, top, p, d), want);
                inside += want;
                checked++;
            }
    assert_true(inside > 100 && inside < checked - 100);
    glint_scene_free(s);
}

/* A glass ball cut by a cube (the box shape, or a cube of triangles wound
 * either way), lit and seen at an angle, through its refraction. */
static glint_image cut_ball(int cube)
{
    glint_camera cam = {.kind = GLINT_CAMERA_PINHOLE, .position = {2.2, 2.5, 4}, .look_at = {0, 0, 0},
                        .up = {0, 1, 0}, .vfov_degrees = 40};
    glint_scene *s = one_sample_scene(96, 72, (glint_color){0.2, 0.2, 0.2}, cam);
    glint_light lamp = glint_light_default(GLINT_LIGHT_POINT);
    lamp.position = (glint_vec3){5, 6, 4};
    glint_error err;
    assert_true(glint_scene_add_light(s, &lamp, &err) >= 0);
    glint_material red = glint_material_default(), glass = glint_material_default();
    red.color = (glint_color){0.8, 0.2, 0.2};
    glass.refraction = 0.9;
    glass.ior = 1.5;
    int r = glint_scene_add_material(s, NULL, &red, NULL), g = glint_scene_add_material(s, NULL, &glass, NULL);
    glint_shape floor = glint_shape_default(GLINT_SHAPE_PLANE);
    floor.center = (glint_vec3){0, -1.5, 0};
    floor.normal = (glint_vec3){0, 1, 0};
    assert_true(glint_scene_add_shape(s, &floor, r, NULL, &err) >= 0);
    glint_shape cut = glint_shape_default(GLINT_SHAPE_INTERSECTION), ball = glint_shape_default(GLINT_SHAPE_SPHERE);
    int top = glint_scene_add_shape(s, &cut, -1, NULL, &err);
    ball.radius = 1.3;
    assert_true(glint_scene_add_part(s, top, &ball, g, NULL, &err) >= 0);
    if (cube == 0) {
        glint_shape box = glint_shape_default(GLINT_SHAPE_BOX);
        box.min = (glint_vec3){-1, -1, -1};
        box.max = (glint_vec3){1, 1, 1};
        assert_true(glint_scene_add_part(s, top, &box, g, NULL, &err) >= 0);
    } else {
        static made m;
        split_cube(&m, cube == 2);
        assert_true(glint_scene_add_mesh_part(s, top, add_mesh(s, &m, NULL, r, false), g, NULL, &err) >= 0);
    }
    return render_and_free(s);
}

/* The cube of triangles, either way round, renders as the box shape does:
 * at most 1% of pixels (rays through the cube's edges) differ by more
 * than 1e-6 (none did when this was written). */
static void test_cube_of_triangles_renders_as_a_box(void **state)
{
    glint_image box = cut_ball(0);
    for (int cube = 1; cube <= 2; cube++) {
        glint_image cubed = cut_ball(cube);
        int differ = 0, pixels = box.width * box.height;
        for (int i = 0; i < 3 * pixels; i += 3)
            differ += fabsf(box.pixels[i] - cubed.pixels[i]) > 1e-6f || fabsf(box.pixels[i + 1] - cubed.pixels[i + 1]) > 1e-6f ||
                      fabsf(box.pixels[i + 2] - cubed.pixels[i + 2]) > 1e-6f;
        assert_true(differ <= pixels / 100);
        glint_image_free(&cubed);
    }
    glint_image_free(&box);
}

/* A mesh part shows its triangles' own materials (the ball's upper half
 * red, its lower half blue, seen flat from the front) unless given one;
 * with vertex normals it shades by them, blended across each triangle,
 * while its surface normal stays the triangle's. */
static void test_triangle_materials_and_vertex_normals(void **state)
{
    static made m;
    faceted_ball(&m, 2);
    glint_scene *s = silhouette_scene(40, 3);
    glint_material red = glint_material_default(), blue = glint_material_default();
    red.color = (glint_color){1, 0, 0};
    blue.color = (glint_color){0, 0, 1};
    red.ambient = blue.ambient = 1;
    red.diffuse = blue.diffuse = red.specular = blue.specular = 0;
    int r = glint_scene_add_material(s, NULL, &red, NULL), b = glint_scene_add_material(s, NULL, &blue, NULL);
    int materials[4096];
    for (int k = 0; k < m.triangles; k++) {
        const uint32_t *v = &m.idx[3 * k];
        materials[k] = m.p[3 * v[0] + 1] + m.p[3 * v[1] + 1] + m.p[3 * v[2] + 1] > 0 ? r : b;
    }
    glint_shape join = glint_shape_default(GLINT_SHAPE_UNION);
    glint_error err;
    int top = glint_scene_add_shape(s, &join, -1, NULL, &err);
    int part = glint_scene_add_mesh_part(s, top, add_mesh(s, &m, materials, 0, true), -1, NULL, &err);
    assert_true(part >= 0);
    glint_image im;
    glint_render_options o = {.threads = 2};
    assert_int_equal(glint_render(s, &o, &im, NULL, NULL), GLINT_OK);
    const float *upper = &im.pixels[3 * (12 * 40 + 20)], *lower = &im.pixels[3 * (28 * 40 + 20)];
    assert_true(upper[0] == 1 && upper[2] == 0 && lower[0] == 0 && lower[2] == 1);
    glint_image_free(&im);

    /* A ray straight down the z axis meets the ball at a corner of the
     * octahedron's split, where the vertex normal is (0, 0, 1); slightly
     * off it, the blend of three normals, not the face's. */
    ray down = {v3(0.05, 0.03, 5), v3(0, 0, -1)};
    shape_hit h;
    assert_true(shape_intersect(&s->shapes[top], &down, 0, INFINITY, &h));
    surface sf;
    shape_surface(&s->shapes[h.leaf], &down, &h, &sf);
    vec3 p[3], blend = v3(0, 0, 0);
    for (int k = 0; k < 3; k++)
        p[k] = corner(&m, h.part, k);
    vec3 face = face_normal(&m, h.part);
    /* The weights of the hit point, from the areas of the triangles it makes. */
    double whole = v3_length(v3_cross(v3_sub(p[1], p[0]), v3_sub(p[2], p[0])));
    for (int k = 0; k < 3; k++) {
        double w = v3_length(v3_cross(v3_sub(p[(k + 1) % 3], sf.p), v3_sub(p[(k + 2) % 3], sf.p))) / whole;
        blend = v3_madd(blend, p[k], w);
    }
    blend = v3_normalize(blend);
    assert_true(v3_length(v3_sub(sf.n, face)) < 1e-12);
    assert_true(v3_length(v3_sub(sf.shading_n, blend)) < 1e-9);
    assert_true(v3_length(v3_sub(sf.shading_n, sf.n)) > 1e-3);
    glint_scene_free(s);
}

/* The meshes and calls a combination refuses, with their messages. */
static void test_refusals(void **state)
{
    glint_scene *s = glint_scene_new();
    glint_material look = glint_material_default();
    int mat = glint_scene_add_material(s, NULL, &look, NULL);
    glint_shape join = glint_shape_default(GLINT_SHAPE_UNION);
    glint_error err;
    int top = glint_scene_add_shape(s, &join, -1, NULL, &err);
    static made m;
    split_cube(&m, false);
    /* One face turned: two triangles run the same way along its edges. */
    uint32_t swap = m.idx[1];
    m.idx[1] = m.idx[2];
    m.idx[2] = swap;
    int turned = add_mesh(s, &m, NULL, mat, false);
    assert_int_equal(glint_scene_add_mesh_part(s, top, turned, -1, NULL, &err), -1);
    assert_string_equal(err.message, "mesh 0 cannot be a part of a combination: two of its triangles run the same "
                                     "way along its edge from (-1, -1, -1) to (-1, 1, -1), so they face opposite ways or "
                                     "more than two meet there");
    /* The last face gone: open. */
    split_cube(&m, false);
    m.triangles -= 2;
    int open = add_mesh(s, &m, NULL, mat, false);
    assert_int_equal(glint_scene_add_mesh_part(s, top, open, -1, NULL, &err), -1);
    assert_string_equal(err.message, "mesh 1 is not closed, so it cannot be a part of a combination: its edge from "
                                     "(-1, -1, 1) to (-1, 1, 1) has a triangle on one side only");
    /* A triangle and itself turned over: closed, but holding nothing. */
    m.vertices = m.triangles = 0;
    uint32_t a = vertex(&m, 0, 0, 0), b = vertex(&m, 1, 0, 0), c = vertex(&m, 0, 1, 0);
    triangle(&m, a, b, c);
    triangle(&m, a, c, b);
    int flat = add_mesh(s, &m, NULL, mat, false);
    assert_int_equal(glint_scene_add_mesh_part(s, top, flat, -1, NULL, &err), -1);
    assert_string_equal(err.message, "mesh 2 encloses no volume, so it cannot be a part of a combination");

    split_cube(&m, false);
    int cube = add_mesh(s, &m, NULL, mat, false);
    assert_int_equal(glint_scene_add_mesh_part(s, top, 99, -1, NULL, &err), -1);
    assert_string_equal(err.message, "mesh 99 does not exist");
    assert_int_equal(glint_scene_add_mesh_part(s, top, cube, 7, NULL, &err), -1);
    assert_string_equal(err.message, "material 7 does not exist");
    assert_int_equal(glint_scene_add_mesh_part(s, -1, cube, -1, NULL, &err), -1);
    assert_string_equal(err.message, "shape -1 is not a union, intersection or difference");
    glint_shape desc = glint_shape_default(GLINT_SHAPE_MESH);
    assert_int_equal(glint_scene_add_part(s, top, &desc, mat, NULL, &err), -1);
    assert_string_equal(err.message, "a mesh is placed by glint_scene_add_instance, or made a part of a combination "
                                     "by glint_scene_add_mesh_part");
    assert_true(glint_scene_add_mesh_part(s, top, cube, -1, NULL, &err) >= 0);
    glint_scene_free(s);
}

int main(void)
{
    const struct CMUnitTest tests[] = {
        cmocka_unit_test(test_tree_matches_every_triangle),
        cmocka_unit_test(test_rays_through_corners_and_edges_hit),
        cmocka_unit_test(test_inside_outside_on_a_grid),
        cmocka_unit_test(test_cube_of_triangles_renders_as_a_box),
        cmocka_unit_test(test_triangle_materials_and_vertex_normals),
        cmocka_unit_test(test_refusals),
    };
    return cmocka_run_group_tests(tests, NULL, NULL);
}
