/* noise_texture.c - the solid textures made of noise: noise (POV-Ray's
 * bozo), marble, wood and granite. Each is a pattern, a value from 0 to 1
 * at every point of the thing's own space, seen through a colour map. */
#include <math.h>
#include <stddef.h>
#include "shading/noise.h"
#include "shading/texture.h"

static glint_status noise_init(texture *t, const glint_texture *d, image_load_fn load, void *user,
                               glint_error *err)
{
    return GLINT_OK; /* t->desc holds all it reads */
}

/* The colour map of t at value v: stops blended linearly. */
static color color_map(const texture *t, double v)
{
    const glint_color_stop *s = t->desc.stops;
    int n = t->desc.stop_count;
    if (!(v > s[0].at))
        return s[0].color;
    for (int i = 1; i < n; i++)
        if (v < s[i].at) {
            double f = (v - s[i - 1].at) / (s[i].at - s[i - 1].at);
            return rgb_lerp(s[i - 1].color, s[i].color, f);
        }
    return s[n - 1].color;
}

static noise_octaves octaves(const texture *t)
{
    return (noise_octaves){t->desc.octaves, t->desc.lacunarity, t->desc.gain};
}

/* The pattern's points: p in units of the pattern's scale. */
static void pattern_points(const texture *t, const quad_f64 p[3], quad_f64 q[3])
{
    quad_f64 per = quad_splat(1 / t->desc.scale);
    for (int k = 0; k < 3; k++)
        q[k] = p[k] * per;
}

/* noise: 0.5 + 0.5 fbm(q), so mostly between 0.3 and 0.7. */
static void noise_at_points(const texture *t, const quad_f64 p[3], int lanes, color out[QUAD])
{
    quad_f64 q[3];
    pattern_points(t, p, q);
    quad_f64 v = quad_splat(0.5) + quad_splat(0.5) * noise_fbm4(q, octaves(t));
    for (int i = 0; i < lanes; i++)
        out[i] = color_map(t, v[i]);
}

/* marble: 0.5 - 0.5 cos(2 pi (q.x + turbulence fbm(q))), bands one unit of
 * q apart, 0 where q.x is whole. */
static void marble_at(const texture *t, const quad_f64 p[3], int lanes, color out[QUAD])
{
    quad_f64 q[3];
    pattern_points(t, p, q);
    quad_f64 x = q[0] + quad_splat(t->desc.turbulence) * noise_fbm4(q, octaves(t));
    for (int i = 0; i < lanes; i++)
        out[i] = color_map(t, 0.5 - 0.5 * cos(2 * M_PI * x[i]));
}

/* wood: the fraction of r = |q.xz| + turbulence fbm(q), rings one unit of
 * q apart that darken outwards and start again, as a year's growth does. */
static void wood_at(const texture *t, const quad_f64 p[3], int lanes, color out[QUAD])
{
    quad_f64 q[3];
    pattern_points(t, p, q);
    quad_f64 r = quad_sqrt(q[0] * q[0] + q[2] * q[2]) + quad_splat(t->desc.turbulence) * noise_fbm4(q, octaves(t));
    r -= quad_floor(r);
    for (int i = 0; i < lanes; i++)
        out[i] = color_map(t, r[i]);
}

/* granite: min(1, 2 turbulence(q)), flecks with sharp dark creases. */
static void granite_at(const texture *t, const quad_f64 p[3], int lanes, color out[QUAD])
{
    quad_f64 q[3];
    pattern_points(t, p, q);
    quad_f64 v = quad_splat(2) * noise_turbulence4(q, octaves(t));
    for (int i = 0; i < lanes; i++)
        out[i] = color_map(t, v[i] < 1 ? v[i] : 1);
}

/* The keys of every noise texture, with that kind's defaults. */
#define NOISE_PARAMS(scale_default, octaves_default)                                                           \
    {.key = "colors", .type = PARAM_COLOR_STOPS, .offset = offsetof(glint_texture, stops),                     \
     .count_offset = offsetof(glint_texture, stop_count), .min_count = 2, .max_count = GLINT_MAX_COLOR_STOPS, \
     .def = {0, 0, 0, 1, 1, 1}, .lo = 0, .hi = DBL_MAX,                                                        \
     .meaning = "the colour map: [value, colour] stops, blended between"},                                   \
    {.key = "scale", .type = PARAM_NUMBER, .offset = offsetof(glint_texture, scale), .def = {scale_default},  \
     PARAM_POSITIVE, .meaning = "the size of the pattern's features, in the thing's own units"},              \
    {.key = "octaves", .type = PARAM_INTEGER, .offset = offsetof(glint_texture, octaves),                     \
     .def = {octaves_default}, .lo = 1, .hi = 16, .meaning = "layers of noise, each finer than the last"},    \
    {.key = "lacunarity", .type = PARAM_NUMBER, .offset = offsetof(glint_texture, lacunarity), .def = {2},    \
     .lo = 1, .hi = 16, .bounds = PARAM_OPEN_LOW, .meaning = "each octave's frequency over the last's"},      \
    {.key = "gain", .type = PARAM_NUMBER, .offset = offsetof(glint_texture, gain), .def = {0.5}, .lo = 0,     \
     .hi = 1, .meaning = "each octave's amplitude over the last's: higher is rougher"}

#define TURBULENCE_PARAM(turbulence_default)                                                                   \
    {.key = "turbulence", .type = PARAM_NUMBER, .offset = offsetof(glint_texture, turbulence),                \
     .def = {turbulence_default}, .lo = 0, .hi = 1e6, .meaning = "how far noise swirls the pattern, in its units"}

static const param NOISE_TABLE[] = {NOISE_PARAMS(1, 4)};
static const param MARBLE_TABLE[] = {NOISE_PARAMS(1, 6), TURBULENCE_PARAM(1.5)};
static const param WOOD_TABLE[] = {NOISE_PARAMS(0.1, 4), TURBULENCE_PARAM(0.3)};
static const param GRANITE_TABLE[] = {NOISE_PARAMS(0.25, 6)};

const texture_kind noise_texture = {.name = "noise", .id = GLINT_TEXTURE_NOISE, .params = PARAM_TABLE(NOISE_TABLE),
                                    .init = noise_init, .solid = texture_solid_one, .solid4 = noise_at_points};
const texture_kind marble_texture = {.name = "marble", .id = GLINT_TEXTURE_MARBLE,
                                     .params = PARAM_TABLE(MARBLE_TABLE), .init = noise_init,
                                     .solid = texture_solid_one, .solid4 = marble_at};
const texture_kind wood_texture = {.name = "wood", .id = GLINT_TEXTURE_WOOD, .params = PARAM_TABLE(WOOD_TABLE),
                                   .init = noise_init, .solid = texture_solid_one, .solid4 = wood_at};
const texture_kind granite_texture = {.name = "granite", .id = GLINT_TEXTURE_GRANITE,
                                      .params = PARAM_TABLE(GRANITE_TABLE), .init = noise_init,
                                      .solid = texture_solid_one, .solid4 = granite_at};
