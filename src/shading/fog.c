/* fog.c - fog factor and blending. The factor is clamped to [0, 1], which the
 * original forgot to do. */
#include <math.h>
#include <stddef.h>
#include "core/error.h"
#include "shading/fog.h"

static const char *const FOG_KINDS[] = {"none", "linear", "exponential"};

#define FOG(name) .offset = offsetof(glint_fog, name)

/* The type first, then the keys of every type (fog_validate checks those
 * of the fog's own type). */
static const param FOG_PARAMS[] = {
    {.key = "type", .type = PARAM_CHOICE, FOG(kind), .required = true, .words = FOG_KINDS, .word_count = 3,
     .meaning = "none, linear or exponential"},
    {.key = "color", .type = PARAM_COLOR, FOG(color), .def = {1, 1, 1}, .lo = 0, .hi = DBL_MAX,
     .meaning = "what a fully fogged ray shows"},
    {.key = "start", .type = PARAM_NUMBER, FOG(start), .lo = -DBL_MAX, .hi = DBL_MAX,
     .meaning = "linear: distance where the fog begins; may be negative"},
    {.key = "end", .type = PARAM_NUMBER, FOG(end), .lo = -DBL_MAX, .hi = DBL_MAX,
     .meaning = "linear: distance where the fog is complete, above start"},
    {.key = "density", .type = PARAM_NUMBER, FOG(density), PARAM_POSITIVE,
     .meaning = "exponential: how fast the fog thickens, f = 1 - exp(-density d)"},
};

enum { FOG_TYPE_PARAM, FOG_COLOR_PARAM, FOG_START_PARAM, FOG_END_PARAM, FOG_DENSITY_PARAM };

param_table fog_params(void)
{
    return PARAM_TABLE(FOG_PARAMS);
}

bool fog_reads(glint_fog_kind kind, const param *p)
{
    ptrdiff_t i = p - FOG_PARAMS;
    if (i == FOG_TYPE_PARAM || i == FOG_COLOR_PARAM)
        return true;
    if (i == FOG_START_PARAM || i == FOG_END_PARAM)
        return kind == GLINT_FOG_LINEAR;
    return i == FOG_DENSITY_PARAM && kind == GLINT_FOG_EXPONENTIAL;
}

glint_status fog_validate(const glint_fog *f, glint_error *err)
{
    if (f->kind == GLINT_FOG_NONE)
        return GLINT_OK;
    /* The parameters a fog of each kind reads: a run of the table. */
    param_table linear = {FOG_PARAMS + FOG_COLOR_PARAM, 3}, exponential = {FOG_PARAMS + FOG_COLOR_PARAM, 1};
    glint_status s;
    if (f->kind == GLINT_FOG_LINEAR) {
        if ((s = params_check(linear, f, "fog", err)))
            return s;
        if (!(f->start < f->end))
            return error_set(err, GLINT_ERR_INVALID, "linear fog needs start < end, got %g and %g", f->start,
                             f->end);
        return GLINT_OK;
    }
    if (f->kind == GLINT_FOG_EXPONENTIAL) {
        if ((s = params_check(exponential, f, "fog", err)))
            return s;
        return params_check((param_table){FOG_PARAMS + FOG_DENSITY_PARAM, 1}, f, "fog", err);
    }
    return error_set(err, GLINT_ERR_INVALID, "unknown fog kind %d", (int)f->kind);
}

double fog_factor(const glint_fog *f, double d)
{
    double t;
    switch (f->kind) {
    case GLINT_FOG_LINEAR:
        t = (d - f->start) / (f->end - f->start);
        return t < 0 ? 0 : t > 1 ? 1 : t;
    case GLINT_FOG_EXPONENTIAL:
        return 1 - exp(-f->density * d);
    default:
        return 0;
    }
}

color fog_apply(const glint_fog *f, color c, double d)
{
    double t = fog_factor(f, d);
    return t > 0 ? rgb_lerp(c, f->color, t) : c;
}

bool fog_hides(const glint_fog *f, double d)
{
    /* At factor 1, c * 0 + fog * 1 is the fog colour to the bit. Linear
     * fog's factor is (d - start) / (end - start), at least 1 when the
     * numerator is at least the denominator: no division needed. */
    if (f->kind == GLINT_FOG_LINEAR)
        return d - f->start >= f->end - f->start;
    return f->kind != GLINT_FOG_NONE && fog_factor(f, d) >= 1;
}

double fog_reach(const glint_fog *f)
{
    /* d - start >= end - start for every d >= end: rounding keeps the
     * order of the differences. Exponential fog would hide everything
     * only where exp underflows; it is not worth the care. */
    return f->kind == GLINT_FOG_LINEAR ? f->end : INFINITY;
}
