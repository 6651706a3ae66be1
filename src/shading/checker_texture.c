/* checker_texture.c - two colours in square cells. */
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

static color checker_at(const texture *t, double u, double v)
{
    return checker_eval(t->a, t->b, t->cell, u, v);
}

static const param CHECKER_PARAMS[] = {
    {.key = "colors", .type = PARAM_COLOR_PAIR, .offset = offsetof(glint_texture, colors),
     .def = {0, 0, 0, 1, 1, 1}, .lo = 0, .hi = DBL_MAX,
     .meaning = "the first colour where floor(u/size) + floor(v/size) is even, the second where odd"},
    {.key = "size", .type = PARAM_NUMBER, .offset = offsetof(glint_texture, size), .def = {1}, PARAM_POSITIVE,
     .meaning = "cell size in (u, v) units"},
};

const texture_kind checker_texture = {
    .name = "checker", .id = GLINT_TEXTURE_CHECKER, .params = PARAM_TABLE(CHECKER_PARAMS), .init = checker_init,
    .eval = checker_at,
};
