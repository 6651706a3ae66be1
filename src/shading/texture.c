/* texture.c - the registry of texture kinds, the checks every texture
 * passes, the uv mappings, and the checker and image look-ups. */
#include <math.h>
#include <stddef.h>
#include <stdint.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>
#include "core/error.h"
#include "core/lanes.h"
#include "core/registry.h"
#include "geometry/shape_math.h"
#include "shading/texture.h"

static const texture_kind *const KINDS[] = {&checker_texture, &image_texture, &checker_3d_texture, &noise_texture,
                                            &marble_texture, &wood_texture, &granite_texture};

REGISTRY_LOOKUPS(texture_kind, texture_kind, glint_texture_kind, KINDS)

glint_texture glint_texture_default(glint_texture_kind kind)
{
    glint_texture t;
    memset(&t, 0, sizeof t);
    t.kind = kind;
    t.mapping.kind = GLINT_MAP_UV;
    t.mapping.scale = 1;
    t.transform = glint_transform_identity();
    const texture_kind *k = texture_kind_of(kind);
    if (k)
        params_defaults(k->params, &t);
    return t;
}

static const char *const MAPPINGS[] = {"uv", "planar", "spherical", "cylindrical"};

#define MAPPING(name) .offset = offsetof(glint_mapping, name)

static const param MAPPING_PARAMS[] = {
    {.key = "type", .type = PARAM_CHOICE, MAPPING(kind), .required = true, .words = MAPPINGS, .word_count = 4,
     .meaning = "uv, planar, spherical or cylindrical"},
    {.key = "center", .type = PARAM_VEC3, MAPPING(center),
     .default_text = "the shape's centre; planar: `[0, 0, 0]`",
     .meaning = "origin of the mapping, in the shape's own coordinates (planar, spherical, cylindrical)"},
    {.key = "scale", .type = PARAM_NUMBER, MAPPING(scale), .def = {1}, PARAM_POSITIVE,
     .meaning = "distance per unit of u and v: 2 makes the texture twice as large (planar, cylindrical)"},
    {.key = "u_axis", .type = PARAM_VEC3, MAPPING(u_axis),
     .meaning = "direction of u, with v_axis or not at all; x when neither is given (planar)"},
    {.key = "v_axis", .type = PARAM_VEC3, MAPPING(v_axis),
     .meaning = "direction of v, not parallel to u_axis; z when neither is given (planar)"},
};

param_table mapping_params(void)
{
    return PARAM_TABLE(MAPPING_PARAMS);
}

int mapping_key_count(glint_mapping_kind kind)
{
    static const int counts[] = {[GLINT_MAP_UV] = 1, [GLINT_MAP_PLANAR] = 5, [GLINT_MAP_SPHERICAL] = 2,
                                 [GLINT_MAP_CYLINDRICAL] = 3};
    return kind >= GLINT_MAP_UV && kind <= GLINT_MAP_CYLINDRICAL ? counts[kind] : 1;
}

glint_status mapping_validate(const glint_mapping *given, glint_error *err)
{
    glint_mapping m = *given;
    if (m.scale == 0)
        m.scale = 1;
    glint_status s = params_check(mapping_params(), &m, "mapping", err);
    if (s)
        return s;
    /* A centre set without the flag would be ignored without a word. */
    if (!m.center_given && v3_length(m.center) != 0)
        return error_set(err, GLINT_ERR_INVALID, "mapping center is set but center_given is false");
    if (m.kind == GLINT_MAP_PLANAR) {
        bool u0 = v3_length(m.u_axis) == 0, v0 = v3_length(m.v_axis) == 0;
        if (u0 != v0)
            return error_set(err, GLINT_ERR_INVALID, "planar mapping needs both axes or neither");
        if (!u0 && v3_length(v3_cross(m.u_axis, m.v_axis)) == 0)
            return error_set(err, GLINT_ERR_INVALID, "planar mapping axes must not be parallel");
    }
    return GLINT_OK;
}

glint_status texture_init(texture *t, const glint_texture *desc, image_load_fn load, void *user, glint_error *err)
{
    memset(t, 0, sizeof *t);
    t->kind = texture_kind_of(desc->kind);
    if (!t->kind)
        return error_set(err, GLINT_ERR_INVALID, "unknown texture kind %d", (int)desc->kind);
    char what[40];
    snprintf(what, sizeof what, "%s texture", t->kind->name);
    glint_status s = params_check(t->kind->params, desc, what, err);
    if (!s)
        s = mapping_validate(&desc->mapping, err);
    if (s)
        return s;
    transform place = desc->transform;
    static const transform unset;
    if (memcmp(&place, &unset, sizeof place) == 0)
        place = glint_transform_identity();
    if (!xf_invert(&place, &t->to_texture))
        return error_set(err, GLINT_ERR_INVALID, "%s transform is singular or not finite", what);
    t->placed = !xf_is_identity(&place);
    t->mapping = desc->mapping;
    if (t->mapping.kind == GLINT_MAP_PLANAR)
        t->planar = planar_map_of(&t->mapping, t->placed ? &t->to_texture : NULL);
    t->desc = *desc;
    t->desc.transform = place;
    t->desc.file = NULL;
    if (!texture_set_file(t, desc->file))
        return error_set(err, GLINT_ERR_NOMEM, "out of memory");
    s = t->kind->init(t, desc, load, user, err);
    if (s)
        texture_set_file(t, NULL);
    return s;
}

color texture_solid_one(const texture *t, vec3 p)
{
    color c;
    texture_solid_points(t, &p, 1, &c);
    return c;
}

void texture_solid_points(const texture *t, const vec3 p[], int lanes, color out[])
{
    if (!t->kind->solid4) {
        for (int l = 0; l < lanes; l++)
            out[l] = t->kind->solid(t, p[l]);
        return;
    }
    /* Lanes past `lanes` repeat the first point, and are not read. */
    quad_f64 q[3];
    for (int l = 0; l < QUAD; l++) {
        vec3 at = p[l < lanes ? l : 0];
        q[0][l] = at.x;
        q[1][l] = at.y;
        q[2][l] = at.z;
    }
    color c[QUAD];
    t->kind->solid4(t, q, lanes, c);
    for (int l = 0; l < lanes; l++)
        out[l] = c[l];
}

bool texture_set_file(texture *t, const char *path)
{
    char *copy = path ? strdup(path) : NULL;
    if (path && !copy)
        return false;
    free((char *)t->desc.file);
    t->desc.file = copy;
    return true;
}

/* Whether a planar mapping was given its axes (both or neither, as
 * mapping_validate checks); no square root to say so. */
static bool planar_axes_given(const glint_mapping *m) { return v3_dot(m->u_axis, m->u_axis) != 0; }

/* Gradients g_u and g_v of (u, v) carried through the placement
 * to_texture, which maps (u, v, 0) by its first two rows. */
static void placed_gradients(const transform *to_texture, vec3 *g_u, vec3 *g_v)
{
    const double (*x)[4] = to_texture->m;
    vec3 a = *g_u, b = *g_v;
    *g_u = v3_add(v3_scale(a, x[0][0]), v3_scale(b, x[0][1]));
    *g_v = v3_add(v3_scale(a, x[1][0]), v3_scale(b, x[1][1]));
}

planar_map planar_map_of(const glint_mapping *m, const transform *to_texture)
{
    double scale = m->scale > 0 ? m->scale : 1.0;
    bool axes = planar_axes_given(m);
    vec3 a = v3_scale(axes ? v3_normalize(m->u_axis) : v3(1, 0, 0), 1 / scale);
    vec3 b = v3_scale(axes ? v3_normalize(m->v_axis) : v3(0, 0, 1), 1 / scale);
    /* Before placing, u = a . (p - c) and v = b . (p - c), where c is the
     * mapping's centre (the origin unless given): a planar mapping starts
     * from the origin of the shape's coordinates, so neighbouring shapes
     * continue one pattern (a floor of tiles). */
    planar_map map = {a, b, -v3_dot(a, m->center), -v3_dot(b, m->center)};
    if (!to_texture)
        return map;
    const double (*x)[4] = to_texture->m;
    placed_gradients(to_texture, &map.g_u, &map.g_v);
    return (planar_map){map.g_u, map.g_v, x[0][0] * map.u0 + x[0][1] * map.v0 + x[0][3],
                        x[1][0] * map.u0 + x[1][1] * map.v0 + x[1][3]};
}

bool mapping_gradients(const texture *t, vec3 p_obj, vec3 center, vec3 *g_u, vec3 *g_v)
{
    const glint_mapping *m = &t->mapping;
    if (m->kind == GLINT_MAP_PLANAR) {
        *g_u = t->planar.g_u;
        *g_v = t->planar.g_v;
        return true;
    }
    if (m->kind != GLINT_MAP_SPHERICAL)
        return false;
    /* spherical_uv of d = p - c: u = 1/2 + atan2(x, z) / 2 pi, v = 1/2 -
     * asin(y / r) / pi, whose gradients are (z, 0, -x) / (2 pi rho^2) and
     * (x y / rho, -rho, z y / rho) / (pi r^2), rho^2 = x^2 + z^2. Within
     * a millionth of r of the axis through the poles, where u's grows
     * without bound and has no direction at the axis itself, false: steps
     * measure the footprint there. */
    vec3 d = v3_sub(p_obj, m->center_given ? m->center : center);
    double r2 = v3_dot(d, d), rho2 = d.x * d.x + d.z * d.z;
    if (!(rho2 > 1e-12 * r2))
        return false;
    double rho = sqrt(rho2), along_u = 1 / (2 * M_PI * rho2), along_v = 1 / (M_PI * r2);
    *g_u = v3(d.z * along_u, 0, -d.x * along_u);
    *g_v = v3(d.x * d.y / rho * along_v, -rho * along_v, d.z * d.y / rho * along_v);
    if (t->placed)
        placed_gradients(&t->to_texture, g_u, g_v);
    return true;
}

void mapping_apply(const glint_mapping *m, const surface *s, vec3 center, double *u, double *v)
{
    double scale = m->scale > 0 ? m->scale : 1.0;
    vec3 d = v3_sub(s->p_obj, m->center_given ? m->center : center);
    switch (m->kind) {
    case GLINT_MAP_UV:
        *u = s->u;
        *v = s->v;
        return;
    case GLINT_MAP_PLANAR: {
        planar_map map = planar_map_of(m, NULL);
        planar_map_apply(&map, s->p_obj, u, v);
        return;
    }
    case GLINT_MAP_SPHERICAL:
        spherical_uv(v3_normalize(d), u, v);
        return;
    case GLINT_MAP_CYLINDRICAL: {
        vec3 around = v3_normalize(v3(d.x, 0, d.z));
        *u = polar_u(around.x, around.z);
        *v = d.y / scale;
        return;
    }
    }
    *u = *v = 0;
}

color checker_eval(color a, color b, double cell, double u, double v)
{
    double k = floor(u / cell) + floor(v / cell);
    /* k is a whole number: even exactly when half of it is whole too (every
     * double from 2^53 up is even), without fmod's library call. */
    double half = 0.5 * k;
    /* Chosen by address, not by a branch: a blurred or distant checker
     * flips from sample to sample, and the mispredicted branch cost a depth
     * of field about 2% of its time. */
    const color *chosen = half == floor(half) ? &a : &b;
    return *chosen;
}

/* A texel's linear channels, from index i of its first, in a quad's first
 * three lanes: one conversion to double for all three. Floats are one
 * load of four (the fourth the next texel's, or TEXEL_SLACK's, and
 * unused). Inlined where `hdr` is a constant, so the test for the format
 * runs once a look-up. */
static inline __attribute__((always_inline)) quad_f64 texel(const texture_image *img, bool hdr, size_t i)
{
    if (hdr)
        return quad_from_floats(img->hdr + i);
    return quad_widen(
        (quad_f32){img->linear[img->srgb[i]], img->linear[img->srgb[i + 1]], img->linear[img->srgb[i + 2]], 0});
}

/* rgb_lerp on quads: a (1 - t) + b t, lane by lane, the same bits. */
static inline quad_f64 quad_lerp(quad_f64 a, quad_f64 b, double t)
{
    return a * quad_splat(1.0 - t) + b * quad_splat(t);
}

/* The bilinear blend of the texels at rows y0 and y1 and columns x0 and x1
 * of img, weights tx and ty of the second of each: its channels in a
 * quad's first three lanes. */
static inline __attribute__((always_inline)) quad_f64 bilinear_in(const texture_image *img, bool hdr, int x0, int x1,
                                                                   int y0, int y1, double tx, double ty)
{
    size_t row0 = (size_t)y0 * img->width, row1 = (size_t)y1 * img->width;
    quad_f64 top = quad_lerp(texel(img, hdr, 3 * (row0 + x0)), texel(img, hdr, 3 * (row0 + x1)), tx);
    quad_f64 bottom = quad_lerp(texel(img, hdr, 3 * (row1 + x0)), texel(img, hdr, 3 * (row1 + x1)), tx);
    return quad_lerp(top, bottom, ty);
}

/* bilinear_in, img's format tested once. Always inline, as are the two
 * above: the profile-guided build had made the look-up of sRGB bytes a
 * call, and each of its texels another. */
static inline __attribute__((always_inline)) quad_f64 bilinear(const texture_image *img, int x0, int x1, int y0,
                                                                int y1, double tx, double ty)
{
    return img->hdr ? bilinear_in(img, true, x0, x1, y0, y1, tx, ty) : bilinear_in(img, false, x0, x1, y0, y1, tx, ty);
}

/* Along an axis of n texels wrapped by w, the texels *i0 and *i1 either
 * side of coordinate c and the weight *t of *i1. A mirrored coordinate is
 * first folded into [0, 1], where it then reads as clamped. */
static inline __attribute__((always_inline)) void wrap_axis(double c, int n, glint_wrap w, int *i0, int *i1, double *t)
{
    if (w == GLINT_WRAP_MIRROR) {
        double folded = c - 2 * floor(0.5 * c);
        c = folded <= 1 ? folded : 2 - folded;
    }
    double f = (w == GLINT_WRAP_REPEAT ? c - floor(c) : c < 0 ? 0 : c > 1 ? 1 : c) * n - 0.5;
    double f0 = floor(f);
    *t = f - f0;
    int a = (int)f0, b = a + 1;
    if (w == GLINT_WRAP_REPEAT) {
        /* The fraction keeps f within [-0.5, n - 0.5], so a is from -1 to
         * n - 1: no division is needed to wrap it (this runs twice for
         * every bilinear look-up). */
        a = a < 0 ? n - 1 : a;
        b = b >= n ? 0 : b;
    } else {
        a = a < 0 ? 0 : a;
        b = b >= n ? n - 1 : b;
    }
    *i0 = a;
    *i1 = b;
}

color image_eval(const texture_image *img, double u, double v, glint_wrap wrap_u, glint_wrap wrap_v)
{
    if (!isfinite(u) || !isfinite(v))
        return rgb(0, 0, 0);
    int x0, x1, y0, y1;
    double tx, ty;
    wrap_axis(u, img->width, wrap_u, &x0, &x1, &tx);
    wrap_axis(v, img->height, wrap_v, &y0, &y1, &ty);
    quad_f64 c = bilinear(img, x0, x1, y0, y1, tx, ty);
    return rgb(c[0], c[1], c[2]);
}

/* The level of a footprint whose width in texels, squared, is `area`
 * (finite, from 1 to 2^60): half its log2, from its bits. With area =
 * m 2^e (m from 1 to 2), (e + m - 1) / 2: exact where area is a power of
 * 2, growing with the area between. libm's log2 would be a call, spilling
 * every register a sample's shading holds, and a series a chain of
 * divisions and multiplications the look-ups wait for. */
static double level_of_area(double area)
{
    uint64_t bits;
    memcpy(&bits, &area, sizeof bits);
    int e = (int)(bits >> 52) - 1023;
    bits = (bits & 0x000fffffffffffffULL) | 0x3ff0000000000000ULL;
    double m;
    memcpy(&m, &bits, sizeof m);
    return 0.5 * (e + (m - 1));
}

double image_level(const texture_image *img, uv_extent covered)
{
    double w = img->width, h = img->height;
    double along_u = covered.u2 * (w * w), along_v = covered.v2 * (h * h);
    /* Compared, not libm's fmax: a call. */
    double area = along_u > along_v ? along_u : along_v;
    if (!(area > 1) || img->level_count < 2)
        return 0;
    double top = img->level_count - 1;
    if (!(area < 0x1p60))
        return top; /* and NaN-free past any image's size */
    double level = level_of_area(area);
    return level < top ? level : top;
}

/* The two levels of img a look-up at `level` (above 0) blends: *below,
 * and *above with weight *blend, when it returns true; else *below alone
 * (*above left as it was). */
static inline __attribute__((always_inline)) bool level_pair(const texture_image *img, double level,
                                                             const texture_image **below,
                                                             const texture_image **above, double *blend)
{
    int k = (int)level;
    *blend = level - k;
    *below = k == 0 ? img : &img->levels[k - 1];
    if (!(*blend > 0 && k + 1 < img->level_count))
        return false;
    *above = &img->levels[k];
    return true;
}

color image_eval_level(const texture_image *img, double u, double v, glint_wrap wrap_u, glint_wrap wrap_v,
                       double level)
{
    if (!(level > 0))
        return image_eval(img, u, v, wrap_u, wrap_v);
    const texture_image *below, *above;
    double blend;
    bool blended = level_pair(img, level, &below, &above, &blend);
    color c = image_eval(below, u, v, wrap_u, wrap_v);
    if (blended)
        c = rgb_lerp(c, image_eval(above, u, v, wrap_u, wrap_v), blend);
    return c;
}

/* wrap_axis for four lanes, each along an axis of n[k] texels: the same
 * operations, so the same bits. Texel indices are 32-bit (an image's
 * channels number under 2^31, TEXTURE_IMAGE_MAX_PIXELS): without
 * AVX-512, converting doubles to 64-bit integers and multiplying those
 * takes a scalar instruction a lane, the 32-bit forms one for four. */
static inline __attribute__((always_inline)) void wrap_axis4(quad_f64 c, quad_f64 n, glint_wrap w, quad_i32 *i0,
                                                             quad_i32 *i1, quad_f64 *t)
{
    if (w == GLINT_WRAP_MIRROR) {
        quad_f64 folded = c - 2 * quad_floor(0.5 * c);
        c = quad_select(folded <= 1, folded, 2 - folded);
    }
    quad_f64 within = w == GLINT_WRAP_REPEAT
                          ? c - quad_floor(c)
                          : quad_select(c < 0, quad_splat(0), quad_select(c > 1, quad_splat(1), c));
    quad_f64 f = within * n - 0.5;
    quad_f64 f0 = quad_floor(f);
    *t = f - f0;
    quad_i32 a = __builtin_convertvector(f0, quad_i32), b = a + 1;
    quad_i32 last = __builtin_convertvector(n, quad_i32) - 1;
    if (w == GLINT_WRAP_REPEAT) {
        a = quad_i32_select(a < 0, last, a);
        b = quad_i32_select(b > last, (quad_i32){0, 0, 0, 0}, b);
    } else {
        a = quad_i32_select(a < 0, (quad_i32){0, 0, 0, 0}, a);
        b = quad_i32_select(b > last, last, b);
    }
    *i0 = a;
    *i1 = b;
}

/* Lane k's texel columns *x0 and *x1, rows *y0 and *y1 and weights *tx
 * and *ty in imgs[k] at (u[k], v[k]), each finite: wrap_axis4 on each
 * lane's image size. */
static inline __attribute__((always_inline)) void wrap_lanes(const texture_image *const imgs[QUAD], quad_f64 u,
                                                             quad_f64 v, glint_wrap wrap_u, glint_wrap wrap_v,
                                                             quad_i32 *x0, quad_i32 *x1, quad_i32 *y0,
                                                             quad_i32 *y1, quad_f64 *tx, quad_f64 *ty)
{
    const quad_f64 width = {imgs[0]->width, imgs[1]->width, imgs[2]->width, imgs[3]->width};
    const quad_f64 height = {imgs[0]->height, imgs[1]->height, imgs[2]->height, imgs[3]->height};
    wrap_axis4(u, width, wrap_u, x0, x1, tx);
    wrap_axis4(v, height, wrap_v, y0, y1, ty);
}

quad_f64 image_level4(const texture_image *img, quad_f64 u2, quad_f64 v2)
{
    double w = img->width, h = img->height, top = img->level_count - 1;
    quad_f64 along_u = u2 * (w * w), along_v = v2 * (h * h);
    quad_f64 area = quad_select(along_u > along_v, along_u, along_v);
    if (img->level_count < 2)
        return quad_splat(0);
    /* level_of_area, from the bits of each lane's area. */
    quad_mask bits;
    memcpy(&bits, &area, sizeof bits);
    quad_mask e = (bits >> 52) - 1023;
    bits = (bits & 0x000fffffffffffffLL) | 0x3ff0000000000000LL;
    quad_f64 m;
    memcpy(&m, &bits, sizeof m);
    quad_f64 level = 0.5 * (__builtin_convertvector(e, quad_f64) + (m - 1));
    level = quad_select(level < top, level, quad_splat(top));
    level = quad_select(area < 0x1p60, level, quad_splat(top));
    return quad_select(area > 1, level, quad_splat(0));
}

void image_eval_level4(const texture_image *img, quad_f64 u, quad_f64 v, glint_wrap wrap_u, glint_wrap wrap_v,
                       quad_f64 level, int lanes, quad_f64 out[3])
{
    /* A lane at a non-finite point is black, as image_eval gives it, and
     * is wrapped at (0, 0) like the lanes past `lanes`: neither is looked
     * up. */
    quad_mask finite = (quad_abs(u) < INFINITY) & (quad_abs(v) < INFINITY);
    u = quad_select(finite, u, quad_splat(0));
    v = quad_select(finite, v, quad_splat(0));
    bool looked_up[QUAD];
    for (int k = 0; k < QUAD; k++)
        looked_up[k] = k < lanes && finite[k];
    /* Each lane's two levels, as image_eval_level takes them. */
    const texture_image *below[QUAD], *above[QUAD];
    quad_f64 blend = quad_splat(0);
    quad_mask blended = {0};
    for (int k = 0; k < QUAD; k++) {
        below[k] = above[k] = img;
        if (!looked_up[k] || !(level[k] > 0))
            continue;
        double lane_blend;
        if (level_pair(img, level[k], &below[k], &above[k], &lane_blend)) {
            blend[k] = lane_blend;
            blended[k] = -1;
        }
    }
    /* The wrapping four lanes at a time, each lane's look-up on its own:
     * one load a texel of floats, where lanes of channels took four. */
    quad_i32 x0, x1, y0, y1;
    quad_f64 tx, ty;
    wrap_lanes(below, u, v, wrap_u, wrap_v, &x0, &x1, &y0, &y1, &tx, &ty);
    quad_f64 texels[QUAD];
    for (int k = 0; k < QUAD; k++)
        texels[k] = looked_up[k] ? bilinear(below[k], x0[k], x1[k], y0[k], y1[k], tx[k], ty[k]) : quad_splat(0);
    if (quad_any(blended)) {
        wrap_lanes(above, u, v, wrap_u, wrap_v, &x0, &x1, &y0, &y1, &tx, &ty);
        for (int k = 0; k < lanes; k++)
            if (blended[k])
                texels[k] = quad_lerp(texels[k], bilinear(above[k], x0[k], x1[k], y0[k], y1[k], tx[k], ty[k]),
                                      blend[k]);
    }
    /* Lanes of texels to lanes of channels. */
    quad_f64 rb01 = __builtin_shufflevector(texels[0], texels[1], 0, 4, 2, 6);
    quad_f64 g01 = __builtin_shufflevector(texels[0], texels[1], 1, 5, 3, 7);
    quad_f64 rb23 = __builtin_shufflevector(texels[2], texels[3], 0, 4, 2, 6);
    quad_f64 g23 = __builtin_shufflevector(texels[2], texels[3], 1, 5, 3, 7);
    out[0] = __builtin_shufflevector(rb01, rb23, 0, 1, 4, 5);
    out[1] = __builtin_shufflevector(g01, g23, 0, 1, 4, 5);
    out[2] = __builtin_shufflevector(rb01, rb23, 2, 3, 6, 7);
}

void texture_release(texture *t)
{
    free(t->name);
    t->name = NULL;
    texture_set_file(t, NULL);
    texture_image_free(&t->image);
}
