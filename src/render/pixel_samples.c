/* pixel_samples.c - the samplers: sample positions in the pixel and on the
 * lens (pixel_samples.h). */
#include "core/hash.h"
#include "render/pixel_samples.h"

void pixel_sampler_init(pixel_sampler *ps, const glint_settings *s, bool lens, bool motion)
{
    *ps = (pixel_sampler){.kind = s->sampler, .seed = glint_settings_random_seed(s), .lens = lens, .grid = 1,
                          .motion = motion};
    while (ps->grid * ps->grid < s->samples_per_pixel)
        ps->grid++;
    pixel_filter_init(&ps->filter, s->filter, s->filter_radius);
    ps->plain_box = s->filter == GLINT_FILTER_BOX && ps->filter.radius == 0.5;
}

static uint32_t gcd(uint32_t x, uint32_t y)
{
    while (y) {
        uint32_t r = x % y;
        x = y;
        y = r;
    }
    return x;
}

void pixel_samples_start(const pixel_sampler *ps, const int px[RAY8], const int py[RAY8], pixel_block_samples *b)
{
    uint32_t cells = (uint32_t)(ps->grid * ps->grid);
    bool patterned = ps->lens || ps->kind == GLINT_SAMPLER_SOBOL;
    for (int i = 0; i < RAY8; i++) {
        b->px[i] = px[i];
        b->py[i] = py[i];
        if (ps->motion)
            b->time_scramble[i] = hash4((uint32_t)px[i], (uint32_t)py[i], 0x54494d45U, ps->seed);
        if (!patterned)
            continue;
        uint32_t h = hash4((uint32_t)px[i], (uint32_t)py[i], 0, ps->seed ^ 0x4c454e53U);
        b->pattern[i] = h;
        if (ps->kind == GLINT_SAMPLER_SOBOL)
            for (int d = 0; d < 4; d++)
                b->scramble[d][i] = hash_u32(h ^ (uint32_t)(d + 1) * 0x9e3779b9U);
        if (!ps->lens || ps->kind == GLINT_SAMPLER_SOBOL)
            continue;
        b->shuffle_a[i] = 1 + hash_u32(h) % cells;
        b->shuffle_b[i] = h % cells;
        while (gcd(b->shuffle_a[i], cells) != 1)
            b->shuffle_a[i]++;
    }
}

/* Sample k's point in each lane's pixel, in [0, 1)^2: the sampler chosen
 * once for the eight lanes, whose loops then run without a branch (the
 * Sobol points are worked out for the eight at once). */
static void points_in_pixels(const pixel_sampler *ps, const pixel_block_samples *b, int k, double u[RAY8],
                             double v[RAY8])
{
    int n = ps->grid, sx = k % n, sy = k / n;
    switch (ps->kind) {
    case GLINT_SAMPLER_SOBOL:
        sobol_scrambled8(sobol_same((uint32_t)k), b->scramble[0], u);
        sobol_scrambled8(sobol_same(sobol_second_reversed((uint32_t)k)), b->scramble[1], v);
        return;
    case GLINT_SAMPLER_JITTERED:
        for (int i = 0; i < RAY8; i++) {
            uint32_t h = hash4((uint32_t)b->px[i], (uint32_t)b->py[i], (uint32_t)k, ps->seed);
            u[i] = (sx + hash_unit(h)) / n;
            v[i] = (sy + hash_unit(hash_u32(h ^ 0x9e3779b9U))) / n;
        }
        return;
    default:
        regular_point(n, k, &u[0], &v[0]);
        for (int i = 1; i < RAY8; i++) {
            u[i] = u[0];
            v[i] = v[0];
        }
    }
}

/* Sample k's point on each lane's lens, in [0, 1)^2: for the grid
 * samplers, a hashed point in the lens cell its image cell is shuffled to. */
static void points_on_lenses(const pixel_sampler *ps, const pixel_block_samples *b, int k, camera_lens8 *lens)
{
    if (ps->kind == GLINT_SAMPLER_SOBOL) {
        uint32_t third, fourth;
        sobol_third_fourth_reversed((uint32_t)k, &third, &fourth);
        sobol_scrambled8(sobol_same(third), b->scramble[2], lens->u);
        sobol_scrambled8(sobol_same(fourth), b->scramble[3], lens->v);
        return;
    }
    int n = ps->grid;
    uint32_t cells = (uint32_t)(n * n);
    for (int i = 0; i < RAY8; i++) {
        int cell = (int)(((uint64_t)b->shuffle_a[i] * (uint32_t)k + b->shuffle_b[i]) % cells);
        uint32_t h = hash_u32(b->pattern[i] ^ (uint32_t)(cell + 1) * 0x9e3779b9U);
        lens->u[i] = (cell % n + hash_unit(h)) / n;
        lens->v[i] = (cell / n + hash_unit(hash_u32(h ^ 0x85ebca6bU))) / n;
    }
}

void pixel_samples_at_any(const pixel_sampler *ps, const pixel_block_samples *b, int k, double x[RAY8],
                          double y[RAY8], camera_lens8 *lens, bool negative[RAY8])
{
    double u[RAY8], v[RAY8];
    points_in_pixels(ps, b, k, u, v);
    for (int i = 0; i < RAY8; i++) {
        negative[i] = false;
        if (ps->plain_box) {
            x[i] = b->px[i] + u[i];
            y[i] = b->py[i] + v[i];
        } else {
            bool below_x, below_y;
            x[i] = b->px[i] + 0.5 + pixel_filter_offset(&ps->filter, u[i], &below_x);
            y[i] = b->py[i] + 0.5 + pixel_filter_offset(&ps->filter, v[i], &below_y);
            negative[i] = below_x != below_y;
        }
    }
    if (ps->lens)
        points_on_lenses(ps, b, k, lens);
}

void pixel_samples_time(const pixel_block_samples *b, int k, double time[RAY8])
{
    sobol_scrambled8(sobol_same((uint32_t)k), b->time_scramble, time);
}
