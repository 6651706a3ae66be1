/* fog.c - fog factor and blending. The factor is clamped to [0, 1], which the
 * original forgot to do. */
#include <math.h>
#include "core/error.h"
#include "shading/fog.h"

glint_status fog_validate(const glint_fog *f, glint_error *err)
{
    if (f->kind == GLINT_FOG_NONE)
        return GLINT_OK;
    if (!isfinite(f->color.r) || !isfinite(f->color.g) || !isfinite(f->color.b))
        return error_set(err, GLINT_ERR_INVALID, "fog colour must be finite");
    if (f->kind == GLINT_FOG_LINEAR) {
        if (!isfinite(f->start) || !isfinite(f->end) || !(f->start < f->end))
            return error_set(err, GLINT_ERR_INVALID,
                             "linear fog needs finite start < end, got %g and %g", f->start, f->end);
        return GLINT_OK;
    }
    if (f->kind == GLINT_FOG_EXPONENTIAL) {
        if (!(isfinite(f->density) && f->density > 0))
            return error_set(err, GLINT_ERR_INVALID, "fog density must be positive, got %g", f->density);
        return GLINT_OK;
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
