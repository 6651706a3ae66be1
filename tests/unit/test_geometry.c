/* test_geometry.c - the analytic shapes: exact hits, misses, normals, uv,
 * bounds and validation, in object space and under transforms. Expected
 * values are worked out by hand in the comments, never by the code under
 * test. */
#include <stdarg.h>
#include <stddef.h>
#include <setjmp.h>
#include <stdint.h>
#include <cmocka.h>
#include <float.h>
#include <math.h>
#include <string.h>
#include "geometry/poly_roots.h"
#include "geometry/shape_kind.h"

#define EPS 1e-9

/* ------------------------------------------------------------ assertions */

static void near_at(const char *file, int line, double got, double want)
{
    if (!(fabs(got - want) < EPS)) {
        print_error("got %.17g, want %.17g\n", got, want);
        _fail(file, line);
    }
}
#define NEAR(got, want) near_at(__FILE__, __LINE__, (got), (want))

static void vnear_at(const char *file, int line, vec3 got, vec3 want)
{
    if (!(fabs(got.x - want.x) < EPS && fabs(got.y - want.y) < EPS && fabs(got.z - want.z) < EPS)) {
        print_error("got (%.17g, %.17g, %.17g), want (%.17g, %.17g, %.17g)\n", got.x, got.y, got.z,
                    want.x, want.y, want.z);
        _fail(file, line);
    }
}
#define VNEAR(got, want) vnear_at(__FILE__, __LINE__, (got), (want))

static shape make_at(const char *file, int line, glint_shape d, const glint_transform *m)
{
    shape s;
    glint_error err = {0};
    if (shape_init(&s, &d, m, 7, &err) != GLINT_OK) {
        print_error("shape_init: %s\n", err.message);
        _fail(file, line);
    }
    return s;
}
#define MAKE(d, m) make_at(__FILE__, __LINE__, (d), (m))

/* Asserts that r hits s at t on part, at world point p with world normal
 * n; returns the surface for further checks. */
static surface hit_at(const char *file, int line, const shape *s, ray r, double tmin, double tmax, double t,
                      int part, vec3 p, vec3 n)
{
    shape_hit h;
    surface sf;
    memset(&sf, 0, sizeof sf);
    if (!shape_intersect(s, &r, tmin, tmax, &h)) {
        print_error("missed, want a hit at t = %.17g\n", t);
        _fail(file, line);
        return sf;
    }
    near_at(file, line, h.t, t);
    if (h.part != part) {
        print_error("part %d, want %d\n", h.part, part);
        _fail(file, line);
    }
    shape_surface(s, &r, &h, &sf);
    shape_surface_uv(s, &sf);
    vnear_at(file, line, sf.p, p);
    vnear_at(file, line, sf.n, n);
    return sf;
}
#define HIT(s, r, t, part, p, n) hit_at(__FILE__, __LINE__, &(s), (r), 0, INFINITY, (t), (part), (p), (n))
#define HIT_WITHIN(s, r, tmin, tmax, t, part, p, n) \
    hit_at(__FILE__, __LINE__, &(s), (r), (tmin), (tmax), (t), (part), (p), (n))

static void miss_at(const char *file, int line, const shape *s, ray r, double tmin, double tmax)
{
    shape_hit h;
    if (shape_intersect(s, &r, tmin, tmax, &h)) {
        print_error("hit at t = %.17g part %d, want a miss\n", h.t, h.part);
        _fail(file, line);
    }
}
#define MISS(s, r) miss_at(__FILE__, __LINE__, &(s), (r), 0, INFINITY)
#define MISS_WITHIN(s, r, tmin, tmax) miss_at(__FILE__, __LINE__, &(s), (r), (tmin), (tmax))

static void rejects_at(const char *file, int line, glint_shape d, const glint_transform *m, const char *message)
{
    shape s;
    glint_error err = {0};
    if (shape_init(&s, &d, m, 0, &err) != GLINT_ERR_INVALID || strcmp(err.message, message) != 0) {
        print_error("message \"%s\", want \"%s\"\n", err.message, message);
        _fail(file, line);
    }
}
#define REJECTS(d, m, message) rejects_at(__FILE__, __LINE__, (d), (m), (message))

static ray R(vec3 o, vec3 d)
{
    ray r = {o, d};
    return r;
}

/* ----------------------------------------------------------- descriptions */

static glint_shape sphere_d(vec3 c, double radius)
{
    glint_shape d = {.kind = GLINT_SHAPE_SPHERE, .center = c, .radius = radius};
    return d;
}

static glint_shape plane_d(vec3 point, vec3 normal)
{
    glint_shape d = {.kind = GLINT_SHAPE_PLANE, .center = point, .normal = normal};
    return d;
}

static glint_shape poly_d(int count, vec3 a, vec3 b, vec3 c, vec3 e)
{
    glint_shape d = {.kind = GLINT_SHAPE_POLYGON, .point_count = count, .points = {a, b, c, e}};
    return d;
}

static glint_shape box_d(vec3 lo, vec3 hi)
{
    glint_shape d = {.kind = GLINT_SHAPE_BOX, .min = lo, .max = hi};
    return d;
}

static glint_shape axial_d(glint_shape_kind kind, vec3 c, double radius, double height, bool capped)
{
    glint_shape d = {.kind = kind, .center = c, .radius = radius, .height = height, .capped = capped};
    return d;
}

/* The shapes most tests use. */
static glint_shape test_sphere(void) { return sphere_d(v3(1, 2, 3), 2); }
static glint_shape test_floor(void) { return plane_d(v3(0, -1, 0), v3(0, 2, 0)); }
static glint_shape test_triangle(void) { return poly_d(3, v3(0, 0, 0), v3(2, 0, 0), v3(0, 2, 0), v3(0, 0, 0)); }
/* A slanted parallelogram: (u, v) are coordinates along its two edges. */
static glint_shape test_quad(void) { return poly_d(4, v3(0, 0, 0), v3(2, 0, 0), v3(3, 1, 0), v3(1, 1, 0)); }
static glint_shape test_box(void) { return box_d(v3(-1, -2, -3), v3(1, 2, 3)); }
/* y from -1 to 1, radius 1. */
static glint_shape test_cylinder(bool capped) { return axial_d(GLINT_SHAPE_CYLINDER, v3(0, -1, 0), 1, 2, capped); }
/* Base radius 1 at y = 0, apex at y = 2: the radius at height y is (2 - y) / 2. */
static glint_shape test_cone(bool capped) { return axial_d(GLINT_SHAPE_CONE, v3(0, 0, 0), 1, 2, capped); }

/* object (x, y, z) -> world (10 - 3y, 20 + 2x, 30 + 4z): scale (2, 3, 4),
 * then 90 degrees about z, then a move. */
static glint_transform m_axis(void)
{
    glint_transform t = glint_transform_scale(glint_transform_identity(), 2, 3, 4);
    t = glint_transform_rotate(t, v3(0, 0, 1), 90);
    return glint_transform_translate(t, 10, 20, 30);
}

/* Non-uniform scale, 30 degrees about a skew axis, a move. */
static glint_transform m_skew(void)
{
    glint_transform t = glint_transform_scale(glint_transform_identity(), 0.5, 2, 1.5);
    t = glint_transform_rotate(t, v3(1, 2, 3), 30);
    return glint_transform_translate(t, -4, 5, 7);
}

/* ----------------------------------------------------------------- sphere */

static void test_sphere_hit(void **state)
{
    shape s = MAKE(test_sphere(), NULL);
    /* Along z through the centre's x and y: the near pole is z = 3 - 2. */
    surface sf = HIT(s, R(v3(1, 2, -10), v3(0, 0, 2)), 5.5, 0, v3(1, 2, 1), v3(0, 0, -1));
    VNEAR(sf.p_obj, v3(1, 2, 1));
    assert_int_equal(s.material, 7);
}

static void test_sphere_miss(void **state)
{
    shape s = MAKE(test_sphere(), NULL);
    MISS(s, R(v3(4, 2, -10), v3(0, 0, 1)));
    MISS(s, R(v3(1, 2, -10), v3(1, 0, 0)));
    MISS(s, R(v3(1, 2, -10), v3(0, 0, 0)));
}

/* A tangent ray hits, once, at the point of tangency. */
static void test_sphere_grazing(void **state)
{
    shape s = MAKE(test_sphere(), NULL);
    HIT(s, R(v3(3, 2, -10), v3(0, 0, 1)), 13, 0, v3(3, 2, 3), v3(1, 0, 0));
    MISS(s, R(v3(3 + 1e-9, 2, -10), v3(0, 0, 1)));
}

static void test_sphere_inside(void **state)
{
    shape s = MAKE(test_sphere(), NULL);
    HIT(s, R(v3(1, 2, 3), v3(0, 3, 0)), 2.0 / 3, 0, v3(1, 4, 3), v3(0, 1, 0));
    /* Leaving from the surface itself: tmin skips the start point. */
    HIT_WITHIN(s, R(v3(1, 2, 1), v3(0, 0, 1)), 1e-9, INFINITY, 4, 0, v3(1, 2, 5), v3(0, 0, 1));
}

static void test_sphere_behind(void **state)
{
    shape s = MAKE(test_sphere(), NULL);
    MISS(s, R(v3(1, 2, 10), v3(0, 0, 1)));
}

static void test_sphere_tmax(void **state)
{
    shape s = MAKE(test_sphere(), NULL);
    ray r = R(v3(1, 2, -10), v3(0, 0, 2));
    MISS_WITHIN(s, r, 0, 5.5);
    HIT_WITHIN(s, r, 0, 5.5 + 1e-9, 5.5, 0, v3(1, 2, 1), v3(0, 0, -1));
    /* With the near hit before tmin, the far one is next. */
    HIT_WITHIN(s, r, 5.5, INFINITY, 7.5, 0, v3(1, 2, 5), v3(0, 0, 1));
}

static void test_sphere_uv(void **state)
{
    shape s = MAKE(test_sphere(), NULL);
    surface north = HIT(s, R(v3(1, 10, 3), v3(0, -1, 0)), 6, 0, v3(1, 4, 3), v3(0, 1, 0));
    NEAR(north.v, 0);
    surface south = HIT(s, R(v3(1, -10, 3), v3(0, 1, 0)), 10, 0, v3(1, 0, 3), v3(0, -1, 0));
    NEAR(south.v, 1);
    surface front = HIT(s, R(v3(1, 2, 10), v3(0, 0, -1)), 5, 0, v3(1, 2, 5), v3(0, 0, 1));
    NEAR(front.u, 0.5);
    NEAR(front.v, 0.5);
    surface east = HIT(s, R(v3(10, 2, 3), v3(-1, 0, 0)), 7, 0, v3(3, 2, 3), v3(1, 0, 0));
    NEAR(east.u, 0.75);
    surface west = HIT(s, R(v3(-10, 2, 3), v3(1, 0, 0)), 9, 0, v3(-1, 2, 3), v3(-1, 0, 0));
    NEAR(west.u, 0.25);
    /* The seam is at -z: just to the +x side of it u is nearly 1, just to
     * the -x side nearly 0. The hit direction there is (+-0.01, 0, -..). */
    shape_hit h;
    surface sf;
    ray r = R(v3(1.02, 2, -10), v3(0, 0, 1));
    assert_true(shape_intersect(&s, &r, 0, INFINITY, &h));
    shape_surface(&s, &r, &h, &sf);
    shape_surface_uv(&s, &sf);
    NEAR(sf.u, 1 - asin(0.01) / (2 * M_PI));
    NEAR(sf.v, 0.5);
    r = R(v3(0.98, 2, -10), v3(0, 0, 1));
    assert_true(shape_intersect(&s, &r, 0, INFINITY, &h));
    shape_surface(&s, &r, &h, &sf);
    shape_surface_uv(&s, &sf);
    NEAR(sf.u, asin(0.01) / (2 * M_PI));
}

/* ------------------------------------------------------------------ plane */

static void test_plane_hit(void **state)
{
    shape s = MAKE(test_floor(), NULL);
    surface sf = HIT(s, R(v3(1, 5, 2), v3(0, -3, 0)), 2, 0, v3(1, -1, 2), v3(0, 1, 0));
    /* Floors: u along +x, v along +z, from the plane's point. */
    NEAR(sf.u, 1);
    NEAR(sf.v, 2);
}

/* A ring about (1, 2, 3) facing +z: outer radius 2, a hole of radius 0.5. */
static glint_shape test_ring(void)
{
    glint_shape d = glint_shape_default(GLINT_SHAPE_DISK);
    d.center = v3(1, 2, 3);
    d.normal = v3(0, 0, 4);
    d.radius = 2;
    d.inner_radius = 0.5;
    return d;
}

/* Discs and rings: exact hits from both sides, the rims on the disc, the
 * hole and the outside missed, uv across the disc's square, tight bounds,
 * and what it is: flat, open, crossed once. */
static void test_disk(void **state)
{
    shape s = MAKE(test_ring(), NULL);
    /* From the front, 5 units away, 1.25 from the centre along +x. */
    surface sf = HIT(s, R(v3(2.25, 2, 8), v3(0, 0, -1)), 5, 0, v3(2.25, 2, 3), v3(0, 0, 1));
    /* A wall facing +z: u along +x, v down, over the square of side 4. */
    NEAR(sf.u, 0.5 + 1.25 / 4);
    NEAR(sf.v, 0.5);
    /* From behind, slanted: t where z reaches 3; the normal stays +z. */
    HIT(s, R(v3(1, 0.5, -1), v3(0, 0.125, 2)), 2, 0, v3(1, 0.75, 3), v3(0, 0, 1));
    /* Both rims belong to the ring (exact: distances 2 and 0.5 along y). */
    HIT(s, R(v3(1, 4, 5), v3(0, 0, -1)), 2, 0, v3(1, 4, 3), v3(0, 0, 1));
    HIT(s, R(v3(1, 2.5, 5), v3(0, 0, -1)), 2, 0, v3(1, 2.5, 3), v3(0, 0, 1));
    MISS(s, R(v3(1, 2.25, 5), v3(0, 0, -1)));                /* in the hole */
    MISS(s, R(v3(1, 4.0000001, 5), v3(0, 0, -1)));          /* just outside */
    MISS(s, R(v3(1, 2, 5), v3(1, 0, 0)));                    /* parallel */
    MISS_WITHIN(s, R(v3(2.25, 2, 8), v3(0, 0, -1)), 0, 4.5); /* beyond reach */
    vec3 lo, hi;
    shape_bounds(&s, &lo, &hi);
    VNEAR(lo, v3(-1, 0, 3));
    VNEAR(hi, v3(3, 4, 3));
    assert_true(s.kind->flat);
    assert_int_equal(shape_max_crossings(&s), 1);
    /* A full disc, tilted 45 degrees about x: reaches sqrt(0.5) r in y, z. */
    glint_shape tilted = glint_shape_default(GLINT_SHAPE_DISK);
    tilted.radius = 2;
    tilted.normal = v3(0, 1, 1);
    s = MAKE(tilted, NULL);
    shape_bounds(&s, &lo, &hi);
    VNEAR(lo, v3(-2, -sqrt(2), -sqrt(2)));
    VNEAR(hi, v3(2, sqrt(2), sqrt(2)));
    HIT(s, R(v3(0, 5, 0), v3(0, -1, 0)), 5, 0, v3(0, 0, 0), v3(0, sqrt(0.5), sqrt(0.5)));
    /* Moved by a transform: a disc of radius 1 facing +y, scaled 3 times. */
    glint_shape unit = glint_shape_default(GLINT_SHAPE_DISK);
    unit.radius = 1;
    glint_transform grow = glint_transform_scale(glint_transform_identity(), 3, 3, 3);
    s = MAKE(unit, &grow);
    HIT(s, R(v3(2.9, 4, 0), v3(0, -2, 0)), 2, 0, v3(2.9, 0, 0), v3(0, 1, 0));
    MISS(s, R(v3(3.1, 4, 0), v3(0, -2, 0)));
}

static void test_disk_validation(void **state)
{
    glint_shape d = test_ring();
    d.inner_radius = 2;
    REJECTS(d, NULL, "disk inner_radius must be below its radius 2, got 2");
    d.inner_radius = -1;
    REJECTS(d, NULL, "disk inner_radius must be at least 0, got -1");
    d = test_ring();
    d.radius = 0;
    REJECTS(d, NULL, "disk radius must be positive, got 0");
    d = test_ring();
    d.normal = v3(0, 0, 0);
    REJECTS(d, NULL, "disk normal must not be zero");
    d = test_ring();
    d.center.y = NAN;
    REJECTS(d, NULL, "disk center is not finite");
    /* The defaults: a full disc about the origin facing +y, its radius
     * still to be given. */
    d = glint_shape_default(GLINT_SHAPE_DISK);
    assert_int_equal(d.kind, GLINT_SHAPE_DISK);
    VNEAR(d.normal, v3(0, 1, 0));
    assert_true(d.radius == 0 && d.inner_radius == 0);
    REJECTS(d, NULL, "disk radius must be positive, got 0");
}

/* n values in [-5, 5) from a small linear congruential generator, the
 * same on every machine. */
static void random_values(uint32_t *seed, double *v, int n)
{
    for (int k = 0; k < n; k++) {
        *seed = *seed * 1664525u + 1013904223u;
        v[k] = (*seed >> 8) / 16777216.0 * 10 - 5;
    }
}

/* plane_hit4 must give plane_hit's answer and, where it hits, its t to the
 * bit, lane by lane: rays in front of, behind, along and beyond the reach
 * of a tilted plane. */
static void test_plane_hit4_matches(void **state)
{
    vec3 point = v3(0.3, -1.7, 2.1), n = v3(0.2, 0.9, -0.4);
    uint32_t seed = 7;
    int hits = 0, misses = 0;
    for (int round = 0; round < 200; round++) {
        ray8 r;
        double tmax[RAY8];
        for (int i = 0; i < RAY8; i++) {
            double v[7];
            random_values(&seed, v, 7);
            vec3 d = v3(v[3], v[4], v[5]);
            if (i == 3) /* parallel to the plane */
                d = v3_cross(n, v3(1, 0, 0));
            ray8_set(&r, i, (ray){v3(v[0], v[1], v[2]), d});
            tmax[i] = i == 5 ? INFINITY : fabs(v[6]);
        }
        for (int q = 0; q < RAY8; q += QUAD) {
            quad_f64 t;
            quad_mask m = plane_hit4(point, n, &r, q, 0, quad_load(tmax + q), &t);
            for (int k = 0; k < QUAD; k++) {
                ray one = ray8_get(&r, q + k);
                double t1;
                bool want = plane_hit(point, n, &one, 0, tmax[q + k], &t1);
                assert_int_equal(m[k] != 0, want);
                double tk = t[k];
                if (want)
                    assert_memory_equal(&tk, &t1, sizeof t1);
                hits += want;
                misses += !want;
            }
        }
    }
    assert_true(hits > 200 && misses > 200);
}

/* float_far is a float bound never short of t: just above (float)t, or
 * infinity past float's range; quad_float_far gives each lane its bits. */
static void test_float_far(void **state)
{
    double ts[] = {0, 1e-320, 1e-45, 1e-30, 0.1, 1, 3.0000001, 1e10, 3.4e38, (double)FLT_MAX, 3.5e38, 1e300,
                   INFINITY};
    assert_true(float_far(0) > 0);
    assert_true(float_far(1) > 1 && float_far(1) == nextafterf(1, INFINITY));
    assert_true(isinf(float_far((double)FLT_MAX)) && isinf(float_far(INFINITY)) && isinf(float_far(1e300)));
    uint32_t seed = 5;
    for (int round = 0; round < 100; round++) {
        double v[QUAD];
        random_values(&seed, v, QUAD);
        for (int k = 0; k < QUAD; k++) /* 5e-30 to 5e30, and the fixed values */
            v[k] = round < 4 && 4 * round + k < (int)(sizeof ts / sizeof ts[0]) ? ts[4 * round + k]
                                                                                 : fabs(v[k]) * pow(10, 6 * v[k]);
        float quad_out[QUAD];
        quad_float_far(quad_load(v), quad_out);
        for (int k = 0; k < QUAD; k++) {
            float one = float_far(v[k]);
            assert_memory_equal(&quad_out[k], &one, sizeof one);
            assert_true((double)one > v[k] || isinf(one));
            assert_true(isinf(one) || nextafterf(one, 0) == (float)v[k]);
        }
    }
}

/* shape_intersect4 gives every lane shape_intersect's answer, t and part
 * bit for bit: a sphere, a triangle, a tilted quad, a tilted plane, a ring
 * (a disk with a hole), capped and open cylinders, a pointed cone and
 * cones cut off narrower and wider, and a sphere, a quad, a cylinder and a
 * cone under transforms (turned, moved, stretched), rays aimed near them
 * from outside and inside, along the quad's plane, the cylinders' axis and
 * the cones' slant, with a zero direction, and with reaches from short to
 * infinite. */
static void test_shape_intersect4_matches(void **state)
{
    glint_shape sphere = {.kind = GLINT_SHAPE_SPHERE, .center = {0.4, -0.3, 1.2}, .radius = 1.7};
    glint_shape triangle = {.kind = GLINT_SHAPE_POLYGON, .point_count = 3,
                            .points = {{-1, 0, -1}, {2, 0.5, -1}, {0, 2, 1}}};
    glint_shape quad = {.kind = GLINT_SHAPE_POLYGON, .point_count = 4,
                        .points = {{-1, -1, 0.5}, {1, -1, 0}, {1, 1, 0}, {-1, 1, 0.5}}};
    glint_shape plane = {.kind = GLINT_SHAPE_PLANE, .center = {0.2, -0.1, 0.3}, .normal = {0.3, 1, 0.2}};
    glint_shape ring = {.kind = GLINT_SHAPE_DISK, .center = {0.4, 0.2, -0.3}, .normal = {0.2, 0.4, 1}, .radius = 1.2,
                        .inner_radius = 0.3};
    glint_shape capped = {.kind = GLINT_SHAPE_CYLINDER, .center = {0.2, -0.8, 0.1}, .radius = 0.9, .height = 1.6,
                          .capped = true};
    glint_shape open = capped;
    open.capped = false;
    glint_shape cone = {.kind = GLINT_SHAPE_CONE, .center = {-0.1, -0.7, 0.2}, .radius = 1.1, .height = 1.5,
                        .capped = true};
    glint_shape narrower = cone, wider = cone;
    narrower.top_radius = 0.4;
    narrower.top_capped = true;
    wider.top_radius = 1.6;
    wider.capped = false;
    glint_transform turned = glint_transform_rotate(glint_transform_identity(), (glint_vec3){0.3, 0.2, 0.9}, 37);
    turned = glint_transform_translate(turned, 0.4, -0.2, 0.3);
    glint_transform stretched = glint_transform_scale(turned, 1.3, 0.7, 1.1);
    const struct {
        const glint_shape *desc;
        const glint_transform *to_world;
    } cases[] = {{&sphere, NULL},       {&triangle, NULL}, {&quad, NULL},     {&plane, NULL},
                 {&ring, NULL},         {&capped, NULL},   {&open, NULL},     {&cone, NULL},
                 {&narrower, NULL},     {&wider, NULL},    {&capped, &turned}, {&narrower, &stretched},
                 {&sphere, &stretched}, {&quad, &turned}};
    uint32_t seed = 11;
    for (size_t c = 0; c < sizeof cases / sizeof cases[0]; c++) {
        const glint_shape *desc = cases[c].desc;
        shape s = MAKE(*desc, cases[c].to_world);
        assert_true(shape_has_intersect4(&s));
        /* Where most rays aim, and a direction along the shape (its
         * plane's, or a cylinder's axis), in object space. */
        vec3 middle = desc->center, along = v3(0, 1, 0);
        if (desc->kind == GLINT_SHAPE_POLYGON) {
            int n = desc->point_count;
            middle = v3(0, 0, 0);
            for (int k = 0; k < n; k++)
                middle = v3_add(middle, v3_scale(desc->points[k], 1.0 / n));
        }
        if (desc->kind == GLINT_SHAPE_CYLINDER || desc->kind == GLINT_SHAPE_CONE)
            middle = v3_add(middle, v3(0, desc->height / 2, 0));
        if (desc->kind == GLINT_SHAPE_CONE) /* its quadratic is linear along the slant */
            along = v3((desc->radius - desc->top_radius) / desc->height, 1, 0);
        middle = xf_point(&s.to_world, middle);
        int hits = 0, misses = 0;
        for (int round = 0; round < 400; round++) {
            ray8 r;
            double tmax[RAY8];
            for (int i = 0; i < RAY8; i++) {
                double v[7];
                random_values(&seed, v, 7);
                vec3 o = v3(v[0], v[1], v[2]), jitter = v3(v[3], v[4], v[5]);
                vec3 dir = v3_sub(v3_add(middle, v3_scale(jitter, 0.15)), o);
                if (i == 1)
                    o = v3_add(middle, v3_scale(jitter, 0.1)); /* inside the solids */
                if (i == 2 && desc->kind == GLINT_SHAPE_POLYGON)
                    along = v3_cross(s.poly_normal, jitter);
                else if (i == 2 && (desc->kind == GLINT_SHAPE_PLANE || desc->kind == GLINT_SHAPE_DISK))
                    along = v3_cross(desc->normal, jitter);
                else if (i == 2 && desc->kind == GLINT_SHAPE_SPHERE)
                    along = v3_cross(v3(0, 1, 0), jitter);
                if (i == 2) /* along the shape, from near it */
                    dir = xf_vector(&s.to_world, along);
                if (i == 3 && round % 50 == 0)
                    dir = v3(0, 0, 0);
                ray8_set(&r, i, (ray){o, dir});
                tmax[i] = i == 5 ? INFINITY : i == 6 ? fabs(v[6]) * 0.2 : fabs(v[6]);
            }
            for (int q = 0; q < RAY8; q += QUAD) {
                quad_hit qh;
                quad_mask m = shape_intersect4(&s, &r, q, quad_load(tmax + q), &qh);
                for (int k = 0; k < QUAD; k++) {
                    ray one = ray8_get(&r, q + k);
                    shape_hit h;
                    bool want = shape_intersect(&s, &one, 0, tmax[q + k], &h);
                    assert_int_equal(m[k] != 0, want);
                    double tk = qh.t[k];
                    if (want) {
                        assert_memory_equal(&tk, &h.t, sizeof h.t);
                        assert_int_equal(qh.part[k], h.part);
                        assert_int_equal(qh.leaf[k], -1);
                    }
                    hits += want;
                    misses += !want;
                }
            }
        }
        assert_true(hits > 400 && misses > 400);
    }
    /* Moving shapes are tested one lane at a time. */
    glint_transform poses[2] = {glint_transform_identity(), turned};
    shape s = MAKE(sphere, NULL);
    shape_move(&s, poses, 2);
    assert_false(shape_has_intersect4(&s));
}

/* The normal is the given one from either side; shading flips it. */
static void test_plane_from_below(void **state)
{
    shape s = MAKE(test_floor(), NULL);
    HIT(s, R(v3(1, -4, 2), v3(0, 1, 0)), 3, 0, v3(1, -1, 2), v3(0, 1, 0));
}

static void test_plane_miss(void **state)
{
    shape s = MAKE(test_floor(), NULL);
    MISS(s, R(v3(0, 5, 0), v3(1, 0, 0)));
    MISS(s, R(v3(0, -1, 0), v3(1, 0, 1)));
    MISS(s, R(v3(0, 5, 0), v3(0, 1, 0)));
    MISS_WITHIN(s, R(v3(1, 5, 2), v3(0, -3, 0)), 0, 2);
    MISS(s, R(v3(3, -1, 3), v3(0, 1, 0)));
}

static void test_plane_uv_axes(void **state)
{
    /* A wall facing +z: u runs along +x and v down, like an image seen
     * from the front. */
    shape wall = MAKE(plane_d(v3(1, 2, 3), v3(0, 0, 5)), NULL);
    surface sf = HIT(wall, R(v3(3, 5, 10), v3(0, 0, -1)), 7, 0, v3(3, 5, 3), v3(0, 0, 1));
    NEAR(sf.u, 2);
    NEAR(sf.v, -3);
    /* A ceiling (seen from below): u along -x, v along +z. */
    shape ceiling = MAKE(plane_d(v3(0, 4, 0), v3(0, -1, 0)), NULL);
    sf = HIT(ceiling, R(v3(2, 0, 3), v3(0, 1, 0)), 4, 0, v3(2, 4, 3), v3(0, -1, 0));
    NEAR(sf.u, -2);
    NEAR(sf.v, 3);
    /* A 45 degree slope facing +x and up: u along -z, v down the slope. */
    shape slope = MAKE(plane_d(v3(0, 0, 0), v3(1, 1, 0)), NULL);
    double h = sqrt(0.5);
    VNEAR(slope.plane_u, v3(0, 0, -1));
    VNEAR(slope.plane_v, v3(h, -h, 0));
    VNEAR(slope.desc.normal, v3(h, h, 0));
    /* Past 45 degrees from vertical a plane counts as a floor: u is the
     * projection of +x, v that of +z. */
    shape steep = MAKE(plane_d(v3(0, 0, 0), v3(0.6, 0.8, 0)), NULL);
    VNEAR(steep.plane_u, v3(0.8, -0.6, 0));
    VNEAR(steep.plane_v, v3(0, 0, 1));
}

/* ---------------------------------------------------------------- polygon */

static void test_triangle_hit(void **state)
{
    shape s = MAKE(test_triangle(), NULL);
    surface sf = HIT(s, R(v3(0.5, 0.5, 5), v3(0, 0, -2)), 2.5, 0, v3(0.5, 0.5, 0), v3(0, 0, 1));
    NEAR(sf.u, 0.25);
    NEAR(sf.v, 0.25);
    /* From the back the normal is the same. */
    HIT(s, R(v3(0.5, 0.5, -5), v3(0, 0, 1)), 5, 0, v3(0.5, 0.5, 0), v3(0, 0, 1));
}

static void test_triangle_outside(void **state)
{
    shape s = MAKE(test_triangle(), NULL);
    MISS(s, R(v3(1.5, 1.5, 5), v3(0, 0, -1)));
    MISS(s, R(v3(-0.1, 0.5, 5), v3(0, 0, -1)));
    MISS(s, R(v3(0.5, -0.1, 5), v3(0, 0, -1)));
    MISS(s, R(v3(0.5, 0.5, 5), v3(0, 0, 1)));
    MISS(s, R(v3(0.5, 0.5, 0), v3(1, 0, 0)));
    MISS_WITHIN(s, R(v3(0.5, 0.5, 5), v3(0, 0, -1)), 0, 4.9);
}

/* Points on an edge or a corner are inside. */
static void test_triangle_edges(void **state)
{
    shape s = MAKE(test_triangle(), NULL);
    surface sf = HIT(s, R(v3(1, 1, 5), v3(0, 0, -1)), 5, 0, v3(1, 1, 0), v3(0, 0, 1));
    NEAR(sf.u, 0.5);
    NEAR(sf.v, 0.5);
    HIT(s, R(v3(0, 0.5, 5), v3(0, 0, -1)), 5, 0, v3(0, 0.5, 0), v3(0, 0, 1));
    sf = HIT(s, R(v3(2, 0, 5), v3(0, 0, -1)), 5, 0, v3(2, 0, 0), v3(0, 0, 1));
    NEAR(sf.u, 1);
    NEAR(sf.v, 0);
}

static void test_triangle_clockwise(void **state)
{
    shape s = MAKE(poly_d(3, v3(0, 0, 0), v3(0, 2, 0), v3(2, 0, 0), v3(0, 0, 0)), NULL);
    HIT(s, R(v3(0.5, 0.5, 5), v3(0, 0, -1)), 5, 0, v3(0.5, 0.5, 0), v3(0, 0, -1));
}

static void test_quad_hit(void **state)
{
    shape s = MAKE(test_quad(), NULL);
    /* (1.5, 0.5) = p0 + 0.5 (2, 0) + 0.5 (1, 1). */
    surface sf = HIT(s, R(v3(1.5, 0.5, 3), v3(0, 0, -1)), 3, 0, v3(1.5, 0.5, 0), v3(0, 0, 1));
    NEAR(sf.u, 0.5);
    NEAR(sf.v, 0.5);
    sf = HIT(s, R(v3(3, 1, 3), v3(0, 0, -1)), 3, 0, v3(3, 1, 0), v3(0, 0, 1));
    NEAR(sf.u, 1);
    NEAR(sf.v, 1);
    /* On the slanted edge x - y = 2. */
    sf = HIT(s, R(v3(2.5, 0.5, 3), v3(0, 0, -1)), 3, 0, v3(2.5, 0.5, 0), v3(0, 0, 1));
    NEAR(sf.u, 1);
    NEAR(sf.v, 0.5);
    /* Left of the fourth edge x = y, and right of the second. */
    MISS(s, R(v3(0.2, 0.5, 3), v3(0, 0, -1)));
    MISS(s, R(v3(2.8, 0.5, 3), v3(0, 0, -1)));
    MISS(s, R(v3(1.5, 1.1, 3), v3(0, 0, -1)));
}

/* A quad in the plane y = z, normal (0, -1, 1) / sqrt 2. */
static void test_quad_tilted(void **state)
{
    shape s = MAKE(poly_d(4, v3(0, 0, 0), v3(1, 0, 0), v3(1, 1, 1), v3(0, 1, 1)), NULL);
    double h = sqrt(0.5);
    surface sf = HIT(s, R(v3(0.5, 0, 1), v3(0, 1, -1)), 0.5, 0, v3(0.5, 0.5, 0.5), v3(0, -h, h));
    NEAR(sf.u, 0.5);
    NEAR(sf.v, 0.5);
    MISS(s, R(v3(1.5, 0, 1), v3(0, 1, -1)));
}

/* A plane's or polygon's normal is the same at every hit, so shape_init
 * normalises it once: shape_surface gives exactly the bits normalising at
 * the hit would. Moved ones still map and normalise at each hit. */
static void test_flat_normal_computed_once(void **state)
{
    glint_shape plane = {.kind = GLINT_SHAPE_PLANE, .center = {0, -1, 0}, .normal = {1, 2, 3}};
    shape flat[] = {MAKE(poly_d(4, v3(0, 0, 0), v3(1, 0, 0), v3(1, 1, 1), v3(0, 1, 1)), NULL),
                    MAKE(poly_d(3, v3(0, 0, 0.3), v3(2, 0.1, 0), v3(0.7, 1.9, 0.4), v3(0, 0, 0)), NULL),
                    MAKE(plane, NULL)};
    ray rays[] = {R(v3(0.4, 0.3, 5), v3(0.01, 0.02, -1)), R(v3(0.4, 0.3, 5), v3(0.01, 0.02, -1)),
                  R(v3(0, 5, 0), v3(0, -1, 0))};
    for (int k = 0; k < 3; k++) {
        assert_true(flat[k].flat);
        vec3 n = v3_normalize(k < 2 ? flat[k].poly_normal : flat[k].desc.normal);
        shape_hit h;
        assert_true(shape_intersect(&flat[k], &rays[k], 0, INFINITY, &h));
        surface sf;
        shape_surface(&flat[k], &rays[k], &h, &sf);
        assert_memory_equal(&sf.n, &n, sizeof n);
        assert_memory_equal(&sf.shading_n, &n, sizeof n);
    }
    glint_transform m = glint_transform_rotate(glint_transform_identity(), (glint_vec3){0, 0, 1}, 90);
    shape moved = MAKE(plane, &m);
    assert_false(moved.flat);
    shape_hit h;
    assert_true(shape_intersect(&moved, &rays[2], 0, INFINITY, &h));
    surface sf;
    shape_surface(&moved, &rays[2], &h, &sf);
    /* (1, 2, 3) turned a quarter about z is (-2, 1, 3). */
    VNEAR(sf.n, v3_normalize(v3(-2, 1, 3)));
}

static void test_polygon_validation(void **state)
{
    vec3 o = v3(0, 0, 0);
    glint_shape d = test_triangle();
    d.point_count = 5;
    REJECTS(d, NULL, "polygon needs 3 or 4 points, got 5");
    d.point_count = 2;
    REJECTS(d, NULL, "polygon needs 3 or 4 points, got 2");
    d = test_triangle();
    d.points[1].y = NAN;
    REJECTS(d, NULL, "polygon point 1 is not finite");
    REJECTS(poly_d(3, o, v3(1, 0, 0), v3(1, 0, 0), o), NULL, "polygon points 1 and 2 coincide");
    REJECTS(poly_d(4, o, v3(1, 0, 0), v3(1, 1, 0), o), NULL, "polygon points 3 and 0 coincide");
    REJECTS(poly_d(3, o, v3(1, 1, 1), v3(2, 2, 2), o), NULL, "polygon points are collinear");
    REJECTS(poly_d(3, o, v3(1, 1, 1), v3(-3, -3, -3), o), NULL, "polygon points are collinear");
    REJECTS(poly_d(4, o, v3(1, 0, 0), v3(1, 1, 0), v3(0, 1, 0.1)), NULL, "polygon is not planar");
    /* A dart: the corner at (0.5, 0.5) bends the wrong way. */
    REJECTS(poly_d(4, o, v3(2, 0, 0), v3(0.5, 0.5, 0), v3(0, 2, 0)), NULL, "polygon is not convex");
    /* A bow tie crosses itself. */
    REJECTS(poly_d(4, o, v3(1, 0, 0), v3(0, 1, 0), v3(1, 1, 0)), NULL, "polygon is not convex");
    REJECTS(poly_d(4, o, v3(2, 0, 0), v3(0, 1, 0), v3(3, 3, 0)), NULL, "polygon is not convex");
    /* A straight corner: really a triangle. */
    REJECTS(poly_d(4, o, v3(1, 0, 0), v3(2, 0, 0), v3(0, 1, 0)), NULL, "polygon is not convex");
    /* Clockwise order is not an error: it only turns the normal round. */
    shape s = MAKE(poly_d(4, o, v3(0, 1, 0), v3(1, 1, 0), v3(1, 0, 0)), NULL);
    VNEAR(s.poly_normal, v3(0, 0, -1));
}

/* -------------------------------------------------------------------- box */

static void test_box_faces(void **state)
{
    shape s = MAKE(test_box(), NULL);
    HIT(s, R(v3(-5, 0.5, 0.5), v3(2, 0, 0)), 2, 1, v3(-1, 0.5, 0.5), v3(-1, 0, 0));
    HIT(s, R(v3(5, 0.5, 0.5), v3(-1, 0, 0)), 4, 2, v3(1, 0.5, 0.5), v3(1, 0, 0));
    HIT(s, R(v3(0.5, -6, 0.5), v3(0, 1, 0)), 4, 3, v3(0.5, -2, 0.5), v3(0, -1, 0));
    HIT(s, R(v3(0.5, 6, 0.5), v3(0, -1, 0)), 4, 4, v3(0.5, 2, 0.5), v3(0, 1, 0));
    HIT(s, R(v3(0.5, 0.5, -7), v3(0, 0, 1)), 4, 5, v3(0.5, 0.5, -3), v3(0, 0, -1));
    HIT(s, R(v3(0.5, 0.5, 7), v3(0, 0, -0.5)), 8, 6, v3(0.5, 0.5, 3), v3(0, 0, 1));
    /* Oblique, entering by the y face: x slab from t = 0.5, y from t = 1. */
    HIT(s, R(v3(-2, -3, 0), v3(2, 1, 0)), 1, 3, v3(0, -2, 0), v3(0, -1, 0));
}

static void test_box_miss(void **state)
{
    shape s = MAKE(test_box(), NULL);
    MISS(s, R(v3(-5, 2.5, 0), v3(1, 0, 0)));
    MISS(s, R(v3(-5, 0, 0), v3(1, 1, 0)));
    MISS(s, R(v3(5, 0, 0), v3(1, 0, 0)));
    MISS_WITHIN(s, R(v3(-5, 0, 0), v3(1, 0, 0)), 0, 4);
    HIT_WITHIN(s, R(v3(-5, 0, 0), v3(1, 0, 0)), 4, INFINITY, 6, 2, v3(1, 0, 0), v3(1, 0, 0));
}

static void test_box_inside(void **state)
{
    shape s = MAKE(test_box(), NULL);
    HIT(s, R(v3(0, 0, 0), v3(0, 0, 0.5)), 6, 6, v3(0, 0, 3), v3(0, 0, 1));
    HIT(s, R(v3(0, 0, 0), v3(-1, 0, 0)), 1, 1, v3(-1, 0, 0), v3(-1, 0, 0));
}

/* Rays that only touch the box (along a face or an edge) hit. */
static void test_box_touching(void **state)
{
    shape s = MAKE(test_box(), NULL);
    HIT(s, R(v3(-5, 2, 0), v3(1, 0, 0)), 4, 1, v3(-1, 2, 0), v3(-1, 0, 0));
    HIT(s, R(v3(-5, 2, 3), v3(1, 0, 0)), 4, 1, v3(-1, 2, 3), v3(-1, 0, 0));
    MISS(s, R(v3(-5, 2 + 1e-9, 0), v3(1, 0, 0)));
    /* Across the edge x = 1, y = 2, touching the box at one point only. */
    shape_hit h;
    surface sf;
    ray edge = R(v3(0, 3, 0), v3(1, -1, 0));
    assert_true(shape_intersect(&s, &edge, 0, INFINITY, &h));
    NEAR(h.t, 1);
    shape_surface(&s, &edge, &h, &sf);
    shape_surface_uv(&s, &sf);
    VNEAR(sf.p, v3(1, 2, 0));
    MISS(s, R(v3(0, 3 + 1e-9, 0), v3(1, -1, 0)));
    /* Through the corner (-1, -2, -3) diagonally: every slab starts at t = 1. */
    ray r = R(v3(-2, -3, -4), v3(1, 1, 1));
    assert_true(shape_intersect(&s, &r, 0, INFINITY, &h));
    NEAR(h.t, 1);
}

/* Seen from outside, u runs right and v down across each face. */
static void test_box_uv(void **state)
{
    shape s = MAKE(test_box(), NULL);
    struct { vec3 o, d; double u, v; } faces[] = {
        {v3(-5, 1, 2), v3(1, 0, 0), 5.0 / 6, 0.25},     /* -x: u along +z, v along -y */
        {v3(5, 1, 2), v3(-1, 0, 0), 1.0 / 6, 0.25},     /* +x: u along -z */
        {v3(0.5, -5, 1.5), v3(0, 1, 0), 0.25, 0.75},    /* -y: u along -x, v along +z */
        {v3(0.5, 5, 1.5), v3(0, -1, 0), 0.75, 0.75},    /* +y: u along +x, v along +z */
        {v3(0.5, 1, -5), v3(0, 0, 1), 0.25, 0.25},      /* -z: u along -x */
        {v3(0.5, 1, 5), v3(0, 0, -1), 0.75, 0.25},      /* +z: u along +x */
    };
    for (int i = 0; i < 6; i++) {
        shape_hit h;
        surface sf;
        ray r = R(faces[i].o, faces[i].d);
        assert_true(shape_intersect(&s, &r, 0, INFINITY, &h));
        assert_int_equal(h.part, i + 1);
        shape_surface(&s, &r, &h, &sf);
        shape_surface_uv(&s, &sf);
        NEAR(sf.u, faces[i].u);
        NEAR(sf.v, faces[i].v);
    }
}

/* --------------------------------------------------------------- cylinder */

static void test_cylinder_side(void **state)
{
    shape s = MAKE(test_cylinder(true), NULL);
    surface sf = HIT(s, R(v3(5, 0, 0), v3(-2, 0, 0)), 2, 0, v3(1, 0, 0), v3(1, 0, 0));
    NEAR(sf.u, 0.75);
    NEAR(sf.v, 0.5);
    sf = HIT(s, R(v3(0, 0.5, 5), v3(0, 0, -1)), 4, 0, v3(0, 0.5, 1), v3(0, 0, 1));
    NEAR(sf.u, 0.5);
    NEAR(sf.v, 0.75);
}

static void test_cylinder_miss(void **state)
{
    shape s = MAKE(test_cylinder(true), NULL);
    MISS(s, R(v3(5, 0, 1.5), v3(-1, 0, 0)));
    MISS(s, R(v3(5, 1.5, 0), v3(-1, 0, 0)));
    MISS(s, R(v3(5, 0, 0), v3(1, 0, 0)));
    MISS(s, R(v3(0, 5, 0), v3(0, 1, 0)));
    MISS_WITHIN(s, R(v3(5, 0, 0), v3(-1, 0, 0)), 0, 4);
    HIT_WITHIN(s, R(v3(5, 0, 0), v3(-1, 0, 0)), 0, 4.0001, 4, 0, v3(1, 0, 0), v3(1, 0, 0));
}

/* A ray tangent to the side hits at the point of tangency. */
static void test_cylinder_grazing(void **state)
{
    shape s = MAKE(test_cylinder(false), NULL);
    HIT(s, R(v3(1, 0, -5), v3(0, 0, 1)), 5, 0, v3(1, 0, 0), v3(1, 0, 0));
    MISS(s, R(v3(1 + 1e-9, 0, -5), v3(0, 0, 1)));
}

static void test_cylinder_inside(void **state)
{
    shape s = MAKE(test_cylinder(true), NULL);
    HIT(s, R(v3(0, 0, 0), v3(0, 1, 0)), 1, 2, v3(0, 1, 0), v3(0, 1, 0));
    HIT(s, R(v3(0, 0, 0), v3(0, -2, 0)), 0.5, 1, v3(0, -1, 0), v3(0, -1, 0));
    HIT(s, R(v3(0, 0, 0), v3(0, 0, -1)), 1, 0, v3(0, 0, -1), v3(0, 0, -1));
}

static void test_cylinder_caps(void **state)
{
    shape s = MAKE(test_cylinder(true), NULL);
    surface sf = HIT(s, R(v3(0, 5, 0), v3(0, -1, 0)), 4, 2, v3(0, 1, 0), v3(0, 1, 0));
    NEAR(sf.u, 0.5);
    NEAR(sf.v, 0.5);
    sf = HIT(s, R(v3(0.5, -5, 0), v3(0, 1, 0)), 4, 1, v3(0.5, -1, 0), v3(0, -1, 0));
    NEAR(sf.u, 0.75);
    NEAR(sf.v, 0.5);
    sf = HIT(s, R(v3(0, 5, -0.5), v3(0, -2, 0)), 2, 2, v3(0, 1, -0.5), v3(0, 1, 0));
    NEAR(sf.u, 0.5);
    NEAR(sf.v, 0.25);
}

/* Rays through the rim circle hit it, whether or not there are caps. */
static void test_cylinder_rims(void **state)
{
    for (int capped = 0; capped < 2; capped++) {
        shape s = MAKE(test_cylinder(capped), NULL);
        shape_hit h;
        surface sf;
        ray top = R(v3(2, 2, 0), v3(-1, -1, 0));
        assert_true(shape_intersect(&s, &top, 0, INFINITY, &h));
        NEAR(h.t, 1);
        shape_surface(&s, &top, &h, &sf);
        shape_surface_uv(&s, &sf);
        VNEAR(sf.p, v3(1, 1, 0));
        ray bottom = R(v3(-2, -2, 0), v3(1, 1, 0));
        assert_true(shape_intersect(&s, &bottom, 0, INFINITY, &h));
        NEAR(h.t, 1);
        shape_surface(&s, &bottom, &h, &sf);
        shape_surface_uv(&s, &sf);
        VNEAR(sf.p, v3(-1, -1, 0));
        /* In the plane of the top cap, tangent to the rim circle. */
        HIT(s, R(v3(1, 1, -5), v3(0, 0, 1)), 5, 0, v3(1, 1, 0), v3(1, 0, 0));
    }
}

static void test_cylinder_open(void **state)
{
    shape s = MAKE(test_cylinder(false), NULL);
    /* Straight down the axis, or parallel to it, nothing is hit. */
    MISS(s, R(v3(0, 5, 0), v3(0, -1, 0)));
    MISS(s, R(v3(0.5, 5, 0), v3(0, -1, 0)));
    MISS(s, R(v3(0, 0, 0), v3(0, 1, 0)));
    /* From inside, or in through the open top, the far wall is hit; its
     * normal still points out of the tube. */
    HIT(s, R(v3(0, 0, 0), v3(1, 0, 0)), 1, 0, v3(1, 0, 0), v3(1, 0, 0));
    HIT(s, R(v3(0, 5, 0), v3(1, -5, 0)), 1, 0, v3(1, 0, 0), v3(1, 0, 0));
    /* With caps the same ray stops at the top cap, at y = 1, x = 0.8. */
    shape capped = MAKE(test_cylinder(true), NULL);
    HIT(capped, R(v3(0, 5, 0), v3(1, -5, 0)), 0.8, 2, v3(0.8, 1, 0), v3(0, 1, 0));
}

/* A ray along the wall itself never hits the side: only caps stop it, at
 * the rim. Parallel to the axis but outside, it misses even the caps. */
static void test_cylinder_along_wall(void **state)
{
    shape open = MAKE(test_cylinder(false), NULL);
    MISS(open, R(v3(1, -5, 0), v3(0, 1, 0)));
    shape capped = MAKE(test_cylinder(true), NULL);
    HIT(capped, R(v3(1, -5, 0), v3(0, 1, 0)), 4, 1, v3(1, -1, 0), v3(0, -1, 0));
    MISS(capped, R(v3(1 + 1e-9, -5, 0), v3(0, 1, 0)));
    MISS(capped, R(v3(2, -5, 0), v3(0, 2, 0)));
}

/* ------------------------------------------------------------------- cone */

/* The gradient of x^2 + z^2 - (R/h)^2 (h - y)^2 for the test cone. */
static vec3 cone_gradient(vec3 p) { return v3_normalize(v3(2 * p.x, 2 * 0.25 * (2 - p.y), 2 * p.z)); }

static void test_cone_side(void **state)
{
    shape s = MAKE(test_cone(true), NULL);
    /* At y = 1 the radius is 0.5. */
    surface sf = HIT(s, R(v3(5, 1, 0), v3(-1, 0, 0)), 4.5, 0, v3(0.5, 1, 0), v3_normalize(v3(1, 0.5, 0)));
    VNEAR(sf.n, cone_gradient(v3(0.5, 1, 0)));
    NEAR(sf.u, 0.75);
    NEAR(sf.v, 0.5);
    /* At y = 0.5 the radius is 0.75; come in along (-0.6, 0, -0.8). */
    vec3 p = v3(0.45, 0.5, 0.6);
    sf = HIT(s, R(v3(2.25, 0.5, 3), v3(-0.6, 0, -0.8)), 3, 0, p, cone_gradient(p));
    NEAR(sf.u, 0.5 + atan2(0.6, 0.8) / (2 * M_PI));
    NEAR(sf.v, 0.25);
}

static void test_cone_miss(void **state)
{
    shape s = MAKE(test_cone(true), NULL);
    MISS(s, R(v3(5, 1, 0.6), v3(-1, 0, 0)));
    /* Through where the other nappe, above the apex, would be. */
    MISS(s, R(v3(5, 3, 0), v3(-1, 0, 0)));
    MISS(s, R(v3(5, 1, 0), v3(1, 0, 0)));
    MISS(s, R(v3(0, -1, 0), v3(0, -1, 0)));
    /* Crossing the base plane beside the base, never near the side. */
    MISS(s, R(v3(3, -1, 2), v3(-1, 1, 0)));
    MISS_WITHIN(s, R(v3(5, 1, 0), v3(-1, 0, 0)), 0, 4.5);
}

static void test_cone_grazing(void **state)
{
    shape s = MAKE(test_cone(false), NULL);
    HIT(s, R(v3(5, 1, 0.5), v3(-1, 0, 0)), 5, 0, v3(0, 1, 0.5), v3_normalize(v3(0, 0.5, 1)));
    MISS(s, R(v3(5, 1, 0.5 + 1e-9), v3(-1, 0, 0)));
}

/* The apex is on the surface, with normal +y. */
static void test_cone_apex(void **state)
{
    shape s = MAKE(test_cone(true), NULL);
    HIT(s, R(v3(0, 5, 0), v3(0, -1, 0)), 3, 0, v3(0, 2, 0), v3(0, 1, 0));
}

static void test_cone_inside(void **state)
{
    shape s = MAKE(test_cone(true), NULL);
    HIT(s, R(v3(0, 0.5, 0), v3(1, 0, 0)), 0.75, 0, v3(0.75, 0.5, 0), cone_gradient(v3(0.75, 0.5, 0)));
    HIT(s, R(v3(0, 0.5, 0), v3(0, -1, 0)), 0.5, 1, v3(0, 0, 0), v3(0, -1, 0));
    HIT(s, R(v3(0, 0.5, 0), v3(0, 2, 0)), 0.75, 0, v3(0, 2, 0), v3(0, 1, 0));
    shape open = MAKE(test_cone(false), NULL);
    MISS(open, R(v3(0, 0.5, 0), v3(0, -1, 0)));
}

static void test_cone_cap(void **state)
{
    shape s = MAKE(test_cone(true), NULL);
    surface sf = HIT(s, R(v3(0, -5, 0), v3(0, 1, 0)), 5, 1, v3(0, 0, 0), v3(0, -1, 0));
    NEAR(sf.u, 0.5);
    NEAR(sf.v, 0.5);
    sf = HIT(s, R(v3(0.5, -5, -0.25), v3(0, 1, 0)), 5, 1, v3(0.5, 0, -0.25), v3(0, -1, 0));
    NEAR(sf.u, 0.75);
    NEAR(sf.v, 0.375);
    /* Without the cap the ray goes in through the open base to the apex. */
    shape open = MAKE(test_cone(false), NULL);
    HIT(open, R(v3(0, -5, 0), v3(0, 1, 0)), 7, 0, v3(0, 2, 0), v3(0, 1, 0));
}

static void test_cone_rim(void **state)
{
    for (int capped = 0; capped < 2; capped++) {
        shape s = MAKE(test_cone(capped), NULL);
        shape_hit h;
        surface sf;
        ray r = R(v3(2, -1, 0), v3(-1, 1, 0));
        assert_true(shape_intersect(&s, &r, 0, INFINITY, &h));
        NEAR(h.t, 1);
        shape_surface(&s, &r, &h, &sf);
        shape_surface_uv(&s, &sf);
        VNEAR(sf.p, v3(1, 0, 0));
    }
}

/* A ray parallel to the slant (the equation is linear, not quadratic). */
static void test_cone_parallel_to_slant(void **state)
{
    /* x = 0.5 - t, y = -1 + 2t: in through the base at t = 0.5, (0, 0, 0);
     * out through the side at t = 1, (-0.5, 1, 0), where the radius is 0.5. */
    ray r = R(v3(0.5, -1, 0), v3(-1, 2, 0));
    shape open = MAKE(test_cone(false), NULL);
    HIT(open, r, 1, 0, v3(-0.5, 1, 0), cone_gradient(v3(-0.5, 1, 0)));
    shape capped = MAKE(test_cone(true), NULL);
    HIT(capped, r, 0.5, 1, v3(0, 0, 0), v3(0, -1, 0));
    /* Shifted by 1.5 in x it passes beside the base and above the apex. */
    MISS(capped, R(v3(2, -1, 0), v3(-1, 2, 0)));
    /* Along the slant line through (1, 0, 0) and the apex, it lies in the
     * surface: only the cap stops it, at the rim. */
    ray slant = R(v3(1.5, -1, 0), v3(-0.5, 1, 0));
    MISS(open, slant);
    HIT(capped, slant, 1, 1, v3(1, 0, 0), v3(0, -1, 0));
}

/* Beside the base (x = 1.5 at y = 0), then into the side at y = 1. */
static void test_cone_beside_base(void **state)
{
    shape s = MAKE(test_cone(true), NULL);
    HIT(s, R(v3(2.5, -1, 0), v3(-1, 1, 0)), 2, 0, v3(0.5, 1, 0), cone_gradient(v3(0.5, 1, 0)));
}

static void test_cone_offset(void **state)
{
    shape s = MAKE(axial_d(GLINT_SHAPE_CONE, v3(1, -1, 2), 2, 4, true), NULL);
    /* At y = 1 (2 above the base) the radius is 1; the slope R/h is 0.5. */
    surface sf = HIT(s, R(v3(1, 1, -5), v3(0, 0, 1)), 6, 0, v3(1, 1, 1), v3_normalize(v3(0, 0.5, -1)));
    NEAR(sf.u, 1);
    NEAR(sf.v, 0.5);
}

/* ------------------------------------------------------------ transforms */

/* Under m_axis the unit sphere is the ellipsoid with semi-axes 3, 2, 4 about
 * (10, 20, 30). At Y = 21, Z = 30: ((X - 10) / 3)^2 = 3/4. */
static void test_transform_sphere(void **state)
{
    glint_transform m = m_axis();
    shape s = MAKE(sphere_d(v3(0, 0, 0), 1), &m);
    double x = 10 + 1.5 * sqrt(3);
    /* The gradient (2 (X - 10) / 9, 2 (Y - 20) / 4, 0). */
    vec3 n = v3_normalize(v3(sqrt(3) / 3, 0.5, 0));
    surface sf = HIT(s, R(v3(100, 21, 30), v3(-1, 0, 0)), 100 - x, 0, v3(x, 21, 30), n);
    VNEAR(sf.p_obj, v3(0.5, -sqrt(3) / 2, 0));
    MISS(s, R(v3(100, 22.01, 30), v3(-1, 0, 0)));
}

/* Under m_axis the cube [-1, 1]^3 is [7, 13] x [18, 22] x [26, 34], and the
 * face X = 7 is its +y face. */
static void test_transform_box(void **state)
{
    glint_transform m = m_axis();
    shape s = MAKE(box_d(v3(-1, -1, -1), v3(1, 1, 1)), &m);
    HIT(s, R(v3(0, 21, 31), v3(1, 0, 0)), 7, 4, v3(7, 21, 31), v3(-1, 0, 0));
    HIT(s, R(v3(8, 21, 0), v3(0, 0, 2)), 13, 5, v3(8, 21, 26), v3(0, 0, -1));
    HIT(s, R(v3(10, 20, 30), v3(0, 1, 0)), 2, 2, v3(10, 22, 30), v3(0, 1, 0));
}

/* Under m_axis the cylinder's axis runs from X = 10 down to X = 4, and its
 * section is the ellipse ((Y - 20) / 2)^2 + ((Z - 30) / 4)^2 = 1. */
static void test_transform_cylinder(void **state)
{
    glint_transform m = m_axis();
    shape s = MAKE(axial_d(GLINT_SHAPE_CYLINDER, v3(0, 0, 0), 1, 2, true), &m);
    /* At Y = 21: ((Z - 30) / 4)^2 = 3/4; gradient (0, 1/2, sqrt(3)/4). */
    double z = 30 + 2 * sqrt(3);
    surface sf = HIT(s, R(v3(8, 21, 100), v3(0, 0, -1)), 100 - z, 0, v3(8, 21, z), v3(0, 2 / sqrt(7), sqrt(3 / 7.0)));
    NEAR(sf.v, 1.0 / 3);
    /* The top cap, y = 2, is at X = 4 and faces -X. */
    HIT(s, R(v3(0, 20, 30), v3(1, 0, 0)), 4, 2, v3(4, 20, 30), v3(-1, 0, 0));
}

/* Under m_axis the cone's apex is at X = 4; at X = 7 (y = 1) its radius
 * 0.5 reaches Z = 32. The gradient there, by the chain rule through
 * y = (10 - X) / 3 and z = (Z - 30) / 4, is (-1/6, 0, 1/4). */
static void test_transform_cone(void **state)
{
    glint_transform m = m_axis();
    shape s = MAKE(test_cone(true), &m);
    HIT(s, R(v3(7, 20, 100), v3(0, 0, -1)), 68, 0, v3(7, 20, 32), v3_normalize(v3(-2, 0, 3)));
    HIT(s, R(v3(20, 20.5, 30), v3(-1, 0, 0)), 10, 1, v3(10, 20.5, 30), v3(1, 0, 0));
}

/* Under m_axis the plane y = 0 is X = 10, facing -X. */
static void test_transform_plane(void **state)
{
    glint_transform m = m_axis();
    shape s = MAKE(plane_d(v3(0, 0, 0), v3(0, 1, 0)), &m);
    surface sf = HIT(s, R(v3(0, 5, 5), v3(2, 0, 0)), 5, 0, v3(10, 5, 5), v3(-1, 0, 0));
    VNEAR(sf.p_obj, v3(-7.5, 0, -6.25));
    NEAR(sf.u, -7.5);
    NEAR(sf.v, -6.25);
}

/* Under m_axis the unit right triangle in z = 0 has corners (10, 20, 30),
 * (10, 22, 30), (7, 20, 30). */
static void test_transform_polygon(void **state)
{
    glint_transform m = m_axis();
    shape s = MAKE(poly_d(3, v3(0, 0, 0), v3(1, 0, 0), v3(0, 1, 0), v3(0, 0, 0)), &m);
    surface sf = HIT(s, R(v3(9, 20.5, 40), v3(0, 0, -1)), 10, 0, v3(9, 20.5, 30), v3(0, 0, 1));
    NEAR(sf.u, 0.25);
    NEAR(sf.v, 1.0 / 3);
    MISS(s, R(v3(8, 21.5, 40), v3(0, 0, -1)));
}

/* A point p on the object-space surface with outward normal n, tangents a
 * and b, part and (u, v). Under transform m the world ray from M(p) + 3 N,
 * with N the image of n, back along -N reaches M(p) at t = 3; the world
 * normal must be perpendicular to the images of both tangents. */
typedef struct surface_point {
    vec3 p, n, a, b;
    int part;
    double u, v;
} surface_point;

static vec3 map_vector(const glint_transform *m, vec3 v)
{
    return v3_sub(glint_transform_point(m, v), glint_transform_point(m, v3(0, 0, 0)));
}

static void check_mapped(const glint_shape *d, const glint_transform *m, const surface_point *sp, int count)
{
    shape s = MAKE(*d, m);
    for (int i = 0; i < count; i++) {
        vec3 p = glint_transform_point(m, sp[i].p), out = map_vector(m, sp[i].n);
        vec3 n = v3_normalize(v3_cross(map_vector(m, sp[i].a), map_vector(m, sp[i].b)));
        if (v3_dot(n, out) < 0)
            n = v3_neg(n);
        ray r = R(v3_madd(p, out, 3), v3_neg(out));
        surface sf = HIT(s, r, 3, sp[i].part, p, n);
        VNEAR(sf.p_obj, sp[i].p);
        NEAR(sf.u, sp[i].u);
        NEAR(sf.v, sp[i].v);
        /* t is 3 up to rounding in the two transforms. */
        MISS_WITHIN(s, r, 0, 3 - 1e-9);
        MISS(s, R(r.o, out));
    }
}

static void check_every_shape(const glint_transform *m)
{
    double u68 = 0.5 + atan2(0.6, 0.8) / (2 * M_PI);
    vec3 x = v3(1, 0, 0), y = v3(0, 1, 0), z = v3(0, 0, 1), around = v3(0.8, 0, -0.6);

    glint_shape d = test_sphere();
    surface_point sphere[] = {
        {v3(1, 2, 5), z, x, y, 0, 0.5, 0.5},
        {v3(2.2, 2, 4.6), v3(0.6, 0, 0.8), y, around, 0, u68, 0.5},
        {v3(1, 3.2, 4.6), v3(0, 0.6, 0.8), x, v3(0, 0.8, -0.6), 0, 0.5, 0.5 - asin(0.6) / M_PI},
    };
    check_mapped(&d, m, sphere, 3);

    d = test_floor();
    surface_point floor[] = {{v3(2, -1, 3), y, x, z, 0, 2, 3}};
    check_mapped(&d, m, floor, 1);

    d = test_triangle();
    surface_point triangle[] = {{v3(0.5, 0.5, 0), z, x, y, 0, 0.25, 0.25}};
    check_mapped(&d, m, triangle, 1);

    d = test_quad();
    surface_point quad[] = {{v3(1.5, 0.5, 0), z, x, y, 0, 0.5, 0.5}};
    check_mapped(&d, m, quad, 1);

    d = test_box();
    surface_point box[] = {
        {v3(-1, 1, 2), v3(-1, 0, 0), y, z, 1, 5.0 / 6, 0.25},
        {v3(1, 1, 2), x, y, z, 2, 1.0 / 6, 0.25},
        {v3(0.5, -2, 1.5), v3(0, -1, 0), x, z, 3, 0.25, 0.75},
        {v3(0.5, 2, 1.5), y, x, z, 4, 0.75, 0.75},
        {v3(0.5, 1, -3), v3(0, 0, -1), x, y, 5, 0.25, 0.25},
        {v3(0.5, 1, 3), z, x, y, 6, 0.75, 0.25},
    };
    check_mapped(&d, m, box, 6);

    surface_point cylinder[] = {
        {v3(0.6, 0, 0.8), v3(0.6, 0, 0.8), y, around, 0, u68, 0.5},
        {v3(0.5, 1, 0), y, x, z, 2, 0.75, 0.5},
        {v3(0, -1, 0.5), v3(0, -1, 0), x, z, 1, 0.5, 0.75},
    };
    d = test_cylinder(true);
    check_mapped(&d, m, cylinder, 3);
    d = test_cylinder(false);
    check_mapped(&d, m, cylinder, 1);

    /* On the cone at y = 1 (radius 0.5) towards (0.6, 0, 0.8): the gradient
     * is (0.6, 0.5, 0.8); the slant runs up to the apex (0, 2, 0). */
    surface_point cone[] = {
        {v3(0.3, 1, 0.4), v3(0.6, 0.5, 0.8), around, v3(-0.3, 1, -0.4), 0, u68, 0.5},
        {v3(0.5, 0, 0), v3(0, -1, 0), x, z, 1, 0.75, 0.5},
    };
    d = test_cone(true);
    check_mapped(&d, m, cone, 2);
    d = test_cone(false);
    check_mapped(&d, m, cone, 1);
}

static void test_mapped_identity(void **state)
{
    glint_transform m = glint_transform_identity();
    check_every_shape(&m);
}

static void test_mapped_axis(void **state)
{
    glint_transform m = m_axis();
    check_every_shape(&m);
}

static void test_mapped_skew(void **state)
{
    glint_transform m = m_skew();
    check_every_shape(&m);
}

static void test_has_transform(void **state)
{
    glint_transform id = glint_transform_identity(), m = m_axis();
    assert_false(MAKE(test_sphere(), NULL).has_transform);
    assert_false(MAKE(test_sphere(), &id).has_transform);
    assert_true(MAKE(test_sphere(), &m).has_transform);
}

/* ----------------------------------------------------------------- bounds */

static void bounds_are(const shape *s, vec3 lo, vec3 hi)
{
    vec3 a, b;
    shape_bounds(s, &a, &b);
    VNEAR(a, lo);
    VNEAR(b, hi);
}

static void test_bounds(void **state)
{
    shape s = MAKE(test_sphere(), NULL);
    bounds_are(&s, v3(-1, 0, 1), v3(3, 4, 5));
    s = MAKE(test_box(), NULL);
    bounds_are(&s, v3(-1, -2, -3), v3(1, 2, 3));
    s = MAKE(test_triangle(), NULL);
    bounds_are(&s, v3(0, 0, 0), v3(2, 2, 0));
    s = MAKE(test_cylinder(false), NULL);
    bounds_are(&s, v3(-1, -1, -1), v3(1, 1, 1));
    s = MAKE(test_cone(true), NULL);
    bounds_are(&s, v3(-1, 0, -1), v3(1, 2, 1));
    glint_transform m = m_skew();
    s = MAKE(test_floor(), &m);
    bounds_are(&s, v3(-SHAPE_PLANE_EXTENT, -SHAPE_PLANE_EXTENT, -SHAPE_PLANE_EXTENT),
               v3(SHAPE_PLANE_EXTENT, SHAPE_PLANE_EXTENT, SHAPE_PLANE_EXTENT));
}

/* The unit cube turned 45 degrees about z: its x and y edges become
 * diagonals of length sqrt 2. */
static void test_bounds_rotated_box(void **state)
{
    glint_transform m = glint_transform_rotate(glint_transform_identity(), v3(0, 0, 1), 45);
    shape s = MAKE(box_d(v3(0, 0, 0), v3(1, 1, 1)), &m);
    double h = sqrt(0.5);
    bounds_are(&s, v3(-h, 0, 0), v3(h, 2 * h, 1));
    m = m_axis();
    s = MAKE(test_box(), &m);
    bounds_are(&s, v3(4, 18, 18), v3(16, 22, 42));
}

/* A thin cylinder (radius 0.1, height 4) turned 45 degrees about z: its
 * one world box is 2.97 x 2.97 x 0.2, area 20.0. Cut across its height
 * into n slices, each box is 0.707 (0.2 + 4 / n) wide in x and y: the
 * total areas for n = 1..8 are 20.0, 12.2, 9.65, 8.48, 7.82, 7.45, 7.21,
 * 7.09, and a slice more pays only for a tenth less, so 6. Slice 0 holds
 * object heights 0 to 2/3: its box is centred on the image of (0, 1/3, 0)
 * with half extents 0.707 (0.1 + 1/3) in x and y. The slices' boxes
 * together reach as far as the whole box. Shapes whose box is square with
 * the world, or that move, keep one box. */
static void test_pieces_of_a_slanted_cylinder(void **state)
{
    glint_transform m = glint_transform_rotate(glint_transform_identity(), v3(0, 0, 1), 45);
    shape s = MAKE(axial_d(GLINT_SHAPE_CYLINDER, v3(0, 0, 0), 0.1, 4, false), &m);
    assert_int_equal(shape_pieces(&s), 6);
    double c = sqrt(0.5), reach = c * (0.1 + 1.0 / 3);
    vec3 mid = v3(-c / 3, c / 3, 0), lo, hi;
    shape_piece_bounds(&s, 0, 6, &lo, &hi);
    VNEAR(lo, v3_sub(mid, v3(reach, reach, 0.1)));
    VNEAR(hi, v3_add(mid, v3(reach, reach, 0.1)));
    vec3 all_lo, all_hi, most = v3(-INFINITY, -INFINITY, -INFINITY), least = v3(INFINITY, INFINITY, INFINITY);
    shape_bounds(&s, &all_lo, &all_hi);
    for (int piece = 0; piece < 6; piece++) {
        shape_piece_bounds(&s, piece, 6, &lo, &hi);
        least = v3(fmin(least.x, lo.x), fmin(least.y, lo.y), fmin(least.z, lo.z));
        most = v3(fmax(most.x, hi.x), fmax(most.y, hi.y), fmax(most.z, hi.z));
    }
    VNEAR(least, all_lo);
    VNEAR(most, all_hi);
    VNEAR(all_lo, v3(-c * 4.1, -c * 0.1, -0.1));
    VNEAR(all_hi, v3(c * 0.1, c * 4.1, 0.1));

    glint_transform moved = glint_transform_translate(glint_transform_identity(), 1, 2, 3);
    s = MAKE(axial_d(GLINT_SHAPE_CYLINDER, v3(0, 0, 0), 0.1, 4, false), &moved);
    assert_int_equal(shape_pieces(&s), 1);
    s = MAKE(axial_d(GLINT_SHAPE_CYLINDER, v3(0, 0, 0), 0.1, 4, false), NULL);
    assert_int_equal(shape_pieces(&s), 1);
    s = MAKE(axial_d(GLINT_SHAPE_CYLINDER, v3(0, 0, 0), 0.1, 4, false), &m);
    transform poses[2] = {s.to_world, s.to_world};
    shape_move(&s, poses, 2);
    assert_int_equal(shape_pieces(&s), 1);
}

/* For x -> A x + t, the unit sphere's image reaches furthest along world
 * axis i at t + A A^T e_i / |A^T e_i|: the bounds must hold those points. */
static void test_bounds_transformed_sphere(void **state)
{
    glint_transform m = m_axis();
    shape s = MAKE(sphere_d(v3(0, 0, 0), 1), &m);
    bounds_are(&s, v3(7, 18, 26), v3(13, 22, 34));
    m = m_skew();
    s = MAKE(sphere_d(v3(0, 0, 0), 1), &m);
    vec3 lo, hi;
    shape_bounds(&s, &lo, &hi);
    for (int i = 0; i < 3; i++) {
        vec3 row = v3(m.m[i][0], m.m[i][1], m.m[i][2]);
        for (int sign = -1; sign <= 1; sign += 2) {
            vec3 p = glint_transform_point(&m, v3_scale(row, sign / v3_length(row)));
            assert_true(p.x >= lo.x - EPS && p.y >= lo.y - EPS && p.z >= lo.z - EPS);
            assert_true(p.x <= hi.x + EPS && p.y <= hi.y + EPS && p.z <= hi.z + EPS);
        }
    }
}

/* ---------------------------------------------------------------- frustum */

/* A cone cut off at height 2 with radius 0.5 there, base radius 1: the
 * radius at height y is 1 - y / 4, the slope (R - top) / h 0.25. */
static glint_shape test_frustum(bool capped, bool top_capped)
{
    glint_shape d = axial_d(GLINT_SHAPE_CONE, v3(0, 0, 0), 1, 2, capped);
    d.top_radius = 0.5;
    d.top_capped = top_capped;
    return d;
}

static void test_frustum_side_and_caps(void **state)
{
    shape s = MAKE(test_frustum(true, true), NULL);
    /* At y = 1 the radius is 0.75. */
    surface sf = HIT(s, R(v3(5, 1, 0), v3(-1, 0, 0)), 4.25, 0, v3(0.75, 1, 0), v3_normalize(v3(1, 0.25, 0)));
    NEAR(sf.v, 0.5);
    /* Down onto the top cap, and out through the base cap. */
    sf = HIT(s, R(v3(0.2, 5, 0), v3(0, -1, 0)), 3, 2, v3(0.2, 2, 0), v3(0, 1, 0));
    NEAR(sf.u, 0.5 + 0.2 / 1.0);
    NEAR(sf.v, 0.5);
    HIT_WITHIN(s, R(v3(0.2, 5, 0), v3(0, -1, 0)), 3, INFINITY, 5, 1, v3(0.2, 0, 0), v3(0, -1, 0));
    /* Past the top's rim (0.6 from the axis at y = 2 is outside 0.5) to
     * the side below: at x = 0.6 the radius is 0.6 at y = 1.6. */
    HIT(s, R(v3(0.6, 5, 0), v3(0, -1, 0)), 3.4, 0, v3(0.6, 1.6, 0), v3_normalize(v3(1, 0.25, 0)));
    /* Without the top cap a ray down the axis meets the base cap from
     * inside; without either cap it passes through. */
    shape open_top = MAKE(test_frustum(true, false), NULL);
    HIT(open_top, R(v3(0, 5, 0), v3(0, -1, 0)), 5, 1, v3(0, 0, 0), v3(0, -1, 0));
    shape open = MAKE(test_frustum(false, false), NULL);
    MISS(open, R(v3(0, 5, 0), v3(0, -1, 0)));
    bounds_are(&s, v3(-1, 0, -1), v3(1, 2, 1));
}

/* Wider at the top (0.5 at the base, 1 at height 2): the slope turns, and
 * the bounds take the top's radius. */
static void test_frustum_wider_at_top(void **state)
{
    glint_shape d = axial_d(GLINT_SHAPE_CONE, v3(0, 0, 0), 0.5, 2, true);
    d.top_radius = 1;
    d.top_capped = true;
    shape s = MAKE(d, NULL);
    HIT(s, R(v3(5, 1, 0), v3(-1, 0, 0)), 4.25, 0, v3(0.75, 1, 0), v3_normalize(v3(1, -0.25, 0)));
    HIT(s, R(v3(0.9, 5, 0), v3(0, -1, 0)), 3, 2, v3(0.9, 2, 0), v3(0, 1, 0));
    bounds_are(&s, v3(-1, 0, -1), v3(1, 2, 1));
}

/* Points sampled by area lie on the frustum's side or caps, with the
 * density 1 / (pi (R + top) slant + pi R^2 + pi top^2); the side gets its
 * share of them, and its points spread by area: the lower half of its
 * height (radii 1 to 0.75) holds (1 + 0.75) / (1 + 0.5) of half of it. */
static void test_frustum_sample(void **state)
{
    shape s = MAKE(test_frustum(true, true), NULL);
    double slant = sqrt(0.25 + 4), side = M_PI * 1.5 * slant, all = side + M_PI + M_PI * 0.25;
    int n = 200, on_side = 0, low = 0;
    for (int i = 0; i < n; i++) {
        for (int j = 0; j < n; j++) {
            vec3 p, normal;
            NEAR(shape_sample(&s, (i + 0.5) / n, (j + 0.5) / n, &p, &normal), 1 / all);
            double axis = sqrt(p.x * p.x + p.z * p.z);
            if (fabs(p.y) < 1e-12 || fabs(p.y - 2) < 1e-12) {
                assert_true(axis <= (p.y < 1 ? 1 : 0.5) + 1e-12);
                continue;
            }
            assert_true(fabs(axis - (1 - p.y / 4)) < 1e-12);
            on_side++;
            low += p.y < 1;
        }
    }
    /* Within a step of the grid, 1 / n. */
    assert_true(fabs((double)on_side / (n * n) - side / all) < 1.0 / n);
    assert_true(fabs((double)low / on_side - 1.75 / 3) < 1.0 / n);
}

/* ------------------------------------------------------------------ torus */

/* Major radius 2, minor 0.5, about +y through the origin: along the x
 * axis the tube spans |x| from 1.5 to 2.5. */
static glint_shape test_torus(void)
{
    glint_shape d = {.kind = GLINT_SHAPE_TORUS, .radius = 2, .minor_radius = 0.5};
    return d;
}

static void test_torus_crossings(void **state)
{
    shape s = MAKE(test_torus(), NULL);
    /* Along the x axis: in at -2.5, out at -1.5, in at 1.5, out at 2.5. */
    ray r = R(v3(-10, 0, 0), v3(1, 0, 0));
    HIT(s, r, 7.5, 0, v3(-2.5, 0, 0), v3(-1, 0, 0));
    HIT_WITHIN(s, r, 7.5, INFINITY, 8.5, 0, v3(-1.5, 0, 0), v3(1, 0, 0));
    HIT_WITHIN(s, r, 8.5, INFINITY, 11.5, 0, v3(1.5, 0, 0), v3(-1, 0, 0));
    HIT_WITHIN(s, r, 11.5, INFINITY, 12.5, 0, v3(2.5, 0, 0), v3(1, 0, 0));
    MISS_WITHIN(s, r, 12.5, INFINITY);
    MISS_WITHIN(s, r, 0, 7.5);
    /* Down onto the top of the tube; down through the hole; over the top. */
    HIT(s, R(v3(0, 10, 2), v3(0, -1, 0)), 9.5, 0, v3(0, 0.5, 2), v3(0, 1, 0));
    MISS(s, R(v3(0, 10, 0), v3(0, -1, 0)));
    MISS(s, R(v3(-10, 0.5 + 1e-9, 0), v3(1, 0, 0)));
    /* From the centre of the hole, the inner equator at 1.5, whatever the
     * direction's length: (1, 0, 1) is sqrt(2) long. */
    double h = 1.5 / sqrt(2);
    HIT(s, R(v3(0, 0, 0), v3(1, 0, 1)), h / 1, 0, v3(h, 0, h), v3(-sqrt(0.5), 0, -sqrt(0.5)));
}

/* Rays from the middle of the hole towards the top of the tube, ever
 * nearer grazing it: at height y = 0.5 - 10^-k the tube is crossed at
 * x = 2 -+ w, w = sqrt(0.25 - y^2), the two roots only 2e-6 apart at
 * k = 12; just above the top, none. Then a sweep of 20,000 rays along x
 * at heights in the last thousandth below the top: each one hits, on the
 * torus (as its implicit equation says), none lost to a speckle. */
static void test_torus_grazing(void **state)
{
    shape s = MAKE(test_torus(), NULL);
    for (int k = 1; k <= 12; k++) {
        double gap = pow(10, -k), y = 0.5 - gap, w = sqrt(gap * (1 - gap));
        HIT(s, R(v3(0, y, 0), v3(1, 0, 0)), 2 - w, 0, v3(2 - w, y, 0), v3(-2 * w, 2 * y, 0));
        MISS(s, R(v3(0, 0.5 + gap, 0), v3(1, 0, 0)));
    }
    for (int i = 0; i < 20000; i++) {
        double y = 0.5 - 1e-3 * (i + 0.5) / 20000;
        ray r = R(v3(-7, y, 0.3), v3(1, 0, 0));
        shape_hit hit;
        assert_true(shape_intersect(&s, &r, 0, INFINITY, &hit));
        vec3 p = v3_madd(r.o, r.d, hit.t);
        double axis = sqrt(p.x * p.x + p.z * p.z), tube = (axis - 2) * (axis - 2) + p.y * p.y;
        assert_true(fabs(tube - 0.25) < 1e-9);
        assert_true(p.x < 0);
    }
}

/* From a million units away the hit is where it is from ten: the ray is
 * measured from where it enters the torus's box. */
static void test_torus_far(void **state)
{
    shape s = MAKE(test_torus(), NULL);
    shape_hit hit;
    /* At height 0.3 the tube's outside is at x = -(2 + 0.4): within a
     * hundred units in the last place of t (1.2e-10 at a million). */
    ray far = R(v3(-1e6, 0.3, 0), v3(1, 0, 0)), slow = R(v3(-1e6, 0.3, 0), v3(1e-3, 0, 0));
    assert_true(shape_intersect(&s, &far, 0, INFINITY, &hit));
    assert_true(fabs(hit.t - (1e6 - 2.4)) < 1e-8);
    assert_true(shape_intersect(&s, &slow, 0, INFINITY, &hit));
    assert_true(fabs(hit.t - (1e9 - 2400)) < 1e-5);
}

/* u about the axis as a cylinder's; v about the tube: 0 at the outer
 * equator, 0.25 on top, 0.5 at the inner equator, 0.75 underneath. */
static void test_torus_uv(void **state)
{
    shape s = MAKE(test_torus(), NULL);
    surface sf = HIT(s, R(v3(0, 0, 10), v3(0, 0, -1)), 7.5, 0, v3(0, 0, 2.5), v3(0, 0, 1));
    NEAR(sf.u, 0.5);
    NEAR(sf.v, 0);
    sf = HIT(s, R(v3(2, 10, 0), v3(0, -1, 0)), 9.5, 0, v3(2, 0.5, 0), v3(0, 1, 0));
    NEAR(sf.u, 0.75);
    NEAR(sf.v, 0.25);
    sf = HIT(s, R(v3(0, 0, 0), v3(0, 0, -1)), 1.5, 0, v3(0, 0, -1.5), v3(0, 0, 1));
    NEAR(sf.v, 0.5);
    sf = HIT(s, R(v3(-2, -10, 0), v3(0, 1, 0)), 9.5, 0, v3(-2, -0.5, 0), v3(0, -1, 0));
    NEAR(sf.u, 0.25);
    NEAR(sf.v, 0.75);
}

/* Points sampled uniformly by area (density 1 / (4 pi^2 R r)) lie on the
 * torus with its outward normal, and its outer half (cos theta > 0) gets its share of the area,
 * (pi R + 2 r) / (2 pi R) = 0.5 + 1 / (4 pi), from a grid of samples. */
static void test_torus_sample(void **state)
{
    shape s = MAKE(test_torus(), NULL);
    int outer = 0, n = 200;
    for (int i = 0; i < n; i++) {
        for (int j = 0; j < n; j++) {
            vec3 p, normal;
            NEAR(shape_sample(&s, (i + 0.5) / n, (j + 0.5) / n, &p, &normal), 1 / (4 * M_PI * M_PI * 2 * 0.5));
            double axis = sqrt(p.x * p.x + p.z * p.z);
            assert_true(fabs((axis - 2) * (axis - 2) + p.y * p.y - 0.25) < 1e-12);
            VNEAR(normal, v3_scale(v3(p.x - 2 * p.x / axis, p.y, p.z - 2 * p.z / axis), 2));
            outer += axis > 2;
        }
    }
    assert_true(fabs((double)outer / (n * n) - (0.5 + 1 / (4 * M_PI))) < 1e-3);
}

static void test_torus_validation(void **state)
{
    glint_shape d = test_torus();
    d.minor_radius = 2;
    REJECTS(d, NULL, "torus minor_radius must be below its major_radius 2, got 2");
    d.minor_radius = 0;
    REJECTS(d, NULL, "torus minor_radius must be positive, got 0");
    shape s = MAKE(test_torus(), NULL);
    bounds_are(&s, v3(-2.5, -0.5, -2.5), v3(2.5, 0.5, 2.5));
}

/* -------------------------------------------------------------- quadrics */

/* A quadric of coefficients k (A..J) within the box lo..hi. */
static glint_shape quadric_d(const double *k, vec3 lo, vec3 hi)
{
    glint_shape d = glint_shape_default(GLINT_SHAPE_QUADRIC);
    memcpy(d.coefficients, k, sizeof d.coefficients);
    d.min = lo;
    d.max = hi;
    return d;
}

/* x^2 + y^2 + z^2 - 1 = 0 is the unit sphere: the same hit distances as the
 * sphere for rays from every side, to the last few bits, and its normal
 * (the gradient, 2p) points out. */
static void test_quadric_is_a_sphere(void **state)
{
    static const double unit[10] = {1, 1, 1, 0, 0, 0, 0, 0, 0, -1};
    shape q = MAKE(quadric_d(unit, v3(-2, -2, -2), v3(2, 2, 2)), NULL), ball = MAKE(sphere_d(v3(0, 0, 0), 1), NULL);
    HIT(q, ((ray){v3(0, 0, 5), v3(0, 0, -1)}), 4, 0, v3(0, 0, 1), v3(0, 0, 1));
    for (int i = 0; i < 200; i++) {
        double a = i * 0.7, b = i * 1.3;
        vec3 o = v3_scale(v3(cos(a) * sin(b), cos(b), sin(a) * sin(b)), 30);
        vec3 d = v3_normalize(v3_sub(v3(0.3 * sin(i), 0.2 * cos(3 * i), 0.1), o));
        ray r = {o, d};
        shape_hit hq, hs;
        bool got = shape_intersect(&q, &r, 0, INFINITY, &hq), want = shape_intersect(&ball, &r, 0, INFINITY, &hs);
        assert_int_equal(got, want);
        if (want)
            assert_true(fabs(hq.t - hs.t) <= 1e-12 * hs.t);
    }
}

/* The paraboloid y = x^2 + z^2 (x^2 + z^2 - y = 0): straight down at x =
 * 0.5 it is met at y = 0.25, its normal (2x, -1, 2z) there, unit; the box
 * cuts it off: below the bowl's rim at y = 1 a ray across it at y = 2
 * misses, and a ray up the axis from below the box's floor meets it only
 * where the box starts, at the bowl's bottom. */
static void test_quadric_paraboloid_and_box(void **state)
{
    static const double bowl[10] = {1, 0, 1, 0, 0, 0, 0, -1, 0, 0};
    shape q = MAKE(quadric_d(bowl, v3(-1, 0, -1), v3(1, 1, 1)), NULL);
    HIT(q, ((ray){v3(0.5, 5, 0), v3(0, -1, 0)}), 4.75, 0, v3(0.5, 0.25, 0), v3_normalize(v3(1, -1, 0)));
    MISS(q, ((ray){v3(-5, 2, 0), v3(1, 0, 0)}));
    HIT(q, ((ray){v3(0, -3, 0), v3(0, 1, 0)}), 3, 0, v3(0, 0, 0), v3(0, -1, 0));
    /* The unit sphere cut to z >= 0: from behind, the near half is gone
     * and the far half is met from inside. */
    static const double unit[10] = {1, 1, 1, 0, 0, 0, 0, 0, 0, -1};
    shape half = MAKE(quadric_d(unit, v3(-2, -2, 0), v3(2, 2, 2)), NULL);
    HIT(half, ((ray){v3(0, 0, -5), v3(0, 0, 1)}), 6, 0, v3(0, 0, 1), v3(0, 0, 1));
    /* A hyperboloid of two sheets, x^2 - y^2 - z^2 = 1: a ray leaving one
     * sheet outwards meets the other, so it is never left behind. */
    static const double sheets[10] = {1, -1, -1, 0, 0, 0, 0, 0, 0, -1};
    shape two = MAKE(quadric_d(sheets, v3(-3, -3, -3), v3(3, 3, 3)), NULL);
    assert_false(shape_is_left_behind(&two, v3(-1, 0, 0), v3(1, 0, 0)));
    HIT(two, ((ray){v3(-1, 0, 0), v3(1, 0, 0)}), 2, 0, v3(1, 0, 0), v3(1, 0, 0));
}

static void test_quadric_validation(void **state)
{
    static const double none[10] = {0, 0, 0, 0, 0, 0, 0, 0, 0, 5};
    static const double unit[10] = {1, 1, 1, 0, 0, 0, 0, 0, 0, -1};
    REJECTS(quadric_d(none, v3(-1, -1, -1), v3(1, 1, 1)), NULL,
            "quadric coefficients A to I are all 0: it has no surface");
    REJECTS(quadric_d(unit, v3(-1, 1, -1), v3(1, 1, 1)), NULL, "quadric min must be below max on every axis");
    glint_shape d = quadric_d(unit, v3(-1, -1, -1), v3(1, 1, 1));
    d.coefficients[4] = NAN;
    REJECTS(d, NULL, "quadric coefficients number 4 is not finite");
}

/* ------------------------------------------------------------- validation */

static void test_validation(void **state)
{
    REJECTS(sphere_d(v3(0, 0, 0), -1), NULL, "sphere radius must be positive, got -1");
    glint_shape same = test_frustum(true, true);
    same.top_radius = 1;
    REJECTS(same, NULL, "cone top_radius must differ from its radius 1 (one radius all the way up is a cylinder)");
    REJECTS(sphere_d(v3(0, 0, 0), 0), NULL, "sphere radius must be positive, got 0");
    REJECTS(sphere_d(v3(0, 0, 0), NAN), NULL, "sphere radius is not finite");
    REJECTS(sphere_d(v3(0, INFINITY, 0), 1), NULL, "sphere center is not finite");
    REJECTS(plane_d(v3(0, 0, 0), v3(0, 0, 0)), NULL, "plane normal must not be zero");
    REJECTS(plane_d(v3(0, 0, 0), v3(0, NAN, 0)), NULL, "plane normal is not finite");
    REJECTS(plane_d(v3(NAN, 0, 0), v3(0, 1, 0)), NULL, "plane point is not finite");
    REJECTS(box_d(v3(0, 0, 0), v3(1, 0, 1)), NULL, "box min must be below max on every axis");
    REJECTS(box_d(v3(0, 2, 0), v3(1, 1, 1)), NULL, "box min must be below max on every axis");
    REJECTS(box_d(v3(0, 0, 0), v3(1, 1, INFINITY)), NULL, "box max is not finite");
    REJECTS(axial_d(GLINT_SHAPE_CYLINDER, v3(0, 0, 0), 1, 0, true), NULL, "cylinder height must be positive, got 0");
    REJECTS(axial_d(GLINT_SHAPE_CYLINDER, v3(0, 0, 0), -2, 1, true), NULL, "cylinder radius must be positive, got -2");
    REJECTS(axial_d(GLINT_SHAPE_CYLINDER, v3(0, NAN, 0), 1, 1, true), NULL, "cylinder center is not finite");
    REJECTS(axial_d(GLINT_SHAPE_CONE, v3(0, 0, 0), 1, -1, true), NULL, "cone height must be positive, got -1");
    REJECTS(axial_d(GLINT_SHAPE_CONE, v3(0, 0, 0), INFINITY, 1, true), NULL, "cone radius is not finite");
    glint_shape d = test_sphere();
    d.kind = (glint_shape_kind)42;
    REJECTS(d, NULL, "unknown shape kind 42");
    glint_transform flat = glint_transform_scale(glint_transform_identity(), 1, 1, 0);
    REJECTS(test_sphere(), &flat, "transform is singular or not finite");
    glint_transform bad = glint_transform_identity();
    bad.m[1][3] = NAN;
    REJECTS(test_sphere(), &bad, "transform is singular or not finite");
}

/* Huge and tiny plane normals are normalised without overflow. */
static void test_plane_normal_scale(void **state)
{
    shape s = MAKE(plane_d(v3(0, 0, 0), v3(0, 1e300, 0)), NULL);
    VNEAR(s.desc.normal, v3(0, 1, 0));
    s = MAKE(plane_d(v3(0, 0, 0), v3(0, 0, -1e-310)), NULL);
    VNEAR(s.desc.normal, v3(0, 0, -1));
}

/* A ray leaving a shape outward never meets it again, and a flat shape is
 * never met again at all; so shape_is_left_behind may skip them. Checked
 * from points all over each shape, plain and skewed, in many directions. */
static void test_left_behind(void **state)
{
    glint_shape descs[] = {test_sphere(), test_box(), test_cylinder(true), test_cylinder(false),
                           test_cone(true), test_cone(false), test_triangle(), test_quad()};
    glint_transform skew = m_skew();
    int checked = 0;
    for (size_t k = 0; k < sizeof descs / sizeof descs[0]; k++) {
        for (int transformed = 0; transformed < 2; transformed++) {
            shape s = MAKE(descs[k], transformed ? &skew : NULL);
            vec3 lo, hi;
            shape_bounds(&s, &lo, &hi);
            vec3 mid = v3_scale(v3_add(lo, hi), 0.5);
            bool flat = descs[k].kind == GLINT_SHAPE_POLYGON;
            for (int a = 0; a < 64; a++) {
                /* Rays from far away towards the middle, from all around. */
                double th = 0.3 + 2.4 * (a % 8) / 8.0, ph = 2 * M_PI * (a / 8) / 8.0 + 0.1;
                vec3 dir = v3(sin(th) * cos(ph), cos(th), sin(th) * sin(ph));
                ray in = {v3_add(mid, v3_scale(dir, 100)), v3_neg(dir)};
                shape_hit h;
                if (!shape_intersect(&s, &in, 0, INFINITY, &h))
                    continue;
                surface sf;
                shape_surface(&s, &in, &h, &sf);
                for (int b = 0; b < 64; b++) {
                    double t2 = 0.2 + 2.7 * (b % 8) / 8.0, p2 = 2 * M_PI * (b / 8) / 8.0 + 0.3;
                    vec3 d = v3(sin(t2) * cos(p2), cos(t2), sin(t2) * sin(p2));
                    double out = v3_dot(sf.n, d);
                    if (fabs(out) < 1e-3)
                        continue;
                    assert_int_equal(shape_is_left_behind(&s, sf.n, d), flat || out > 0);
                    if (!shape_is_left_behind(&s, sf.n, d))
                        continue;
                    ray leave = {sf.p, d};
                    shape_hit again;
                    if (shape_intersect(&s, &leave, 1e-9 * (1 + v3_length(sf.p)), INFINITY, &again)) {
                        print_error("shape %zu%s: met again at t = %g\n", k, transformed ? " (skewed)" : "", again.t);
                        fail();
                    }
                    checked++;
                }
            }
        }
    }
    assert_true(checked > 5000);
}

/* poly_roots gives a polynomial's roots in order, and only the first
 * `most` when asked: (x - 1)(x - 2)(x - 3)(x - 4) in [0, 5] and in
 * [2.5, 5], each within 1e-12. */
static void test_poly_roots_first_ones(void **state)
{
    (void)state;
    const double c[5] = {24, -50, 35, -10, 1};
    double roots[POLY_MAX_DEGREE + 1];
    assert_int_equal(poly_roots(c, 4, 0, 5, roots, 4), 4);
    for (int i = 0; i < 4; i++)
        assert_true(fabs(roots[i] - (i + 1)) < 1e-12);
    assert_int_equal(poly_roots(c, 4, 0, 5, roots, 1), 1);
    assert_true(fabs(roots[0] - 1) < 1e-12);
    assert_int_equal(poly_roots(c, 4, 2.5, 5, roots, 1), 1);
    assert_true(fabs(roots[0] - 3) < 1e-12);
    assert_int_equal(poly_roots(c, 4, 2.5, 5, roots, 4), 2);
    assert_int_equal(poly_roots(c, 4, 4.5, 5, roots, 1), 0);
}

int main(void)
{
    const struct CMUnitTest tests[] = {
        cmocka_unit_test(test_sphere_hit),
        cmocka_unit_test(test_left_behind),
        cmocka_unit_test(test_sphere_miss),
        cmocka_unit_test(test_sphere_grazing),
        cmocka_unit_test(test_sphere_inside),
        cmocka_unit_test(test_sphere_behind),
        cmocka_unit_test(test_sphere_tmax),
        cmocka_unit_test(test_sphere_uv),
        cmocka_unit_test(test_plane_hit),
        cmocka_unit_test(test_plane_hit4_matches),
        cmocka_unit_test(test_shape_intersect4_matches),
        cmocka_unit_test(test_float_far),
        cmocka_unit_test(test_plane_from_below),
        cmocka_unit_test(test_plane_miss),
        cmocka_unit_test(test_plane_uv_axes),
        cmocka_unit_test(test_plane_normal_scale),
        cmocka_unit_test(test_triangle_hit),
        cmocka_unit_test(test_triangle_outside),
        cmocka_unit_test(test_triangle_edges),
        cmocka_unit_test(test_triangle_clockwise),
        cmocka_unit_test(test_quad_hit),
        cmocka_unit_test(test_quad_tilted),
        cmocka_unit_test(test_flat_normal_computed_once),
        cmocka_unit_test(test_polygon_validation),
        cmocka_unit_test(test_box_faces),
        cmocka_unit_test(test_box_miss),
        cmocka_unit_test(test_box_inside),
        cmocka_unit_test(test_box_touching),
        cmocka_unit_test(test_box_uv),
        cmocka_unit_test(test_cylinder_side),
        cmocka_unit_test(test_cylinder_miss),
        cmocka_unit_test(test_cylinder_grazing),
        cmocka_unit_test(test_cylinder_inside),
        cmocka_unit_test(test_cylinder_caps),
        cmocka_unit_test(test_cylinder_rims),
        cmocka_unit_test(test_cylinder_open),
        cmocka_unit_test(test_cylinder_along_wall),
        cmocka_unit_test(test_cone_side),
        cmocka_unit_test(test_cone_miss),
        cmocka_unit_test(test_cone_grazing),
        cmocka_unit_test(test_cone_apex),
        cmocka_unit_test(test_cone_inside),
        cmocka_unit_test(test_cone_cap),
        cmocka_unit_test(test_cone_rim),
        cmocka_unit_test(test_cone_parallel_to_slant),
        cmocka_unit_test(test_cone_beside_base),
        cmocka_unit_test(test_cone_offset),
        cmocka_unit_test(test_frustum_side_and_caps),
        cmocka_unit_test(test_frustum_wider_at_top),
        cmocka_unit_test(test_frustum_sample),
        cmocka_unit_test(test_poly_roots_first_ones),
        cmocka_unit_test(test_torus_crossings),
        cmocka_unit_test(test_torus_grazing),
        cmocka_unit_test(test_torus_far),
        cmocka_unit_test(test_torus_uv),
        cmocka_unit_test(test_torus_sample),
        cmocka_unit_test(test_torus_validation),
        cmocka_unit_test(test_quadric_is_a_sphere),
        cmocka_unit_test(test_quadric_paraboloid_and_box),
        cmocka_unit_test(test_quadric_validation),
        cmocka_unit_test(test_transform_sphere),
        cmocka_unit_test(test_transform_box),
        cmocka_unit_test(test_transform_cylinder),
        cmocka_unit_test(test_transform_cone),
        cmocka_unit_test(test_transform_plane),
        cmocka_unit_test(test_transform_polygon),
        cmocka_unit_test(test_mapped_identity),
        cmocka_unit_test(test_mapped_axis),
        cmocka_unit_test(test_mapped_skew),
        cmocka_unit_test(test_has_transform),
        cmocka_unit_test(test_bounds),
        cmocka_unit_test(test_bounds_rotated_box),
        cmocka_unit_test(test_bounds_transformed_sphere),
        cmocka_unit_test(test_pieces_of_a_slanted_cylinder),
        cmocka_unit_test(test_validation),
        cmocka_unit_test(test_disk),
        cmocka_unit_test(test_disk_validation),
    };
    return cmocka_run_group_tests(tests, NULL, NULL);
}
