/* checker_texture.c - two colours in square cells of (u, v), and the solid
 * checker: two colours in cubic cells filling the thing's own space, as
 * if it were carved from a block of them. */
#include <math.h>
#include <stddef.h>
#include "shading/texture.h"

static glint_status checker_init(texture *t, const glint_texture *d, image_load_fn load, void *user,
                                 glint_error *err)
{
    t->a = d->colors[0];
    t->b = d->colors[1];
    t->cell = d->size;
    return GLINT_OK;
}

static color checker_at(const texture *t, double u, double v, uv_extent covered)
{
    (void)covered;
    return checker_eval(t->a, t->b, t->cell, u, v);
}

/* The keys both checkers read: their colours and cell size. */
#define CELL_PARAMS(cells, units)                                                                              \
    {.key = "colors", .type = PARAM_COLOR_PAIR, .offset = offsetof(glint_texture, colors),                     \
     .def = {0, 0, 0, 1, 1, 1}, .lo = 0, .hi = DBL_MAX,                                                        \
     .meaning = "the first colour where " cells " is even, the second where odd"},                           \
    {.key = "size", .type = PARAM_NUMBER, .offset = offsetof(glint_texture, size), .def = {1}, PARAM_POSITIVE, \
     .meaning = "cell size in " units}

static const param CHECKER_PARAMS[] = {CELL_PARAMS("floor(u/size) + floor(v/size)", "(u, v) units")};

const texture_kind checker_texture = {
    .name = "checker", .id = GLINT_TEXTURE_CHECKER, .params = PARAM_TABLE(CHECKER_PARAMS), .init = checker_init,
    .eval = checker_at,
};

/* The cell's parity from the sum of the three cell indices, halved as
 * checker_eval halves its two. */
static color checker_3d_at(const texture *t, vec3 p)
{
    double k = floor(p.x / t->cell) + floor(p.y / t->cell) + floor(p.z / t->cell), half = 0.5 * k;
    return half == floor(half) ? t->a : t->b;
}

static const param CHECKER_3D_PARAMS[] = {
    CELL_PARAMS("floor(x/size) + floor(y/size) + floor(z/size)", "the thing's own units")};

const texture_kind checker_3d_texture = {
    .name = "checker_3d", .id = GLINT_TEXTURE_CHECKER_3D, .params = PARAM_TABLE(CHECKER_3D_PARAMS),
    .init = checker_init, .solid = checker_3d_at,
};
