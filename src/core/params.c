/* params.c - defaults and checks from a parameter table (params.h). */
#include <math.h>
#include <stdio.h>
#include <string.h>
#include "core/error.h"
#include "core/params.h"

static void *field(void *obj, size_t offset) { return (char *)obj + offset; }
static const void *cfield(const void *obj, size_t offset) { return (const char *)obj + offset; }

void params_defaults(param_table t, void *obj)
{
    for (int i = 0; i < t.count; i++) {
        const param *p = &t.params[i];
        void *f = field(obj, p->offset);
        switch (p->type) {
        case PARAM_NUMBER:
            *(double *)f = p->def[0];
            break;
        case PARAM_INTEGER:
        case PARAM_CHOICE:
            *(int *)f = (int)p->def[0];
            break;
        case PARAM_UINT32:
            *(uint32_t *)f = (uint32_t)p->def[0];
            break;
        case PARAM_BOOL:
            *(bool *)f = p->def[0] != 0;
            break;
        case PARAM_VEC3:
        case PARAM_DIRECTION:
            *(glint_vec3 *)f = (glint_vec3){p->def[0], p->def[1], p->def[2]};
            break;
        case PARAM_COLOR:
            *(glint_color *)f = (glint_color){p->def[0], p->def[1], p->def[2]};
            break;
        case PARAM_COLOR_PAIR:
            ((glint_color *)f)[0] = (glint_color){p->def[0], p->def[1], p->def[2]};
            ((glint_color *)f)[1] = (glint_color){p->def[3], p->def[4], p->def[5]};
            break;
        case PARAM_PATH:
            *(const char **)f = NULL;
            break;
        case PARAM_POINTS:
            *(int *)field(obj, p->count_offset) = 0;
            break;
        case PARAM_NUMBERS:
            memset(f, 0, sizeof(double) * (size_t)p->max_count);
            break;
        case PARAM_COLOR_STOPS:
            ((glint_color_stop *)f)[0] = (glint_color_stop){0, {p->def[0], p->def[1], p->def[2]}};
            ((glint_color_stop *)f)[1] = (glint_color_stop){1, {p->def[3], p->def[4], p->def[5]}};
            *(int *)field(obj, p->count_offset) = 2;
            break;
        }
    }
}

bool param_in_range(const param *p, double v)
{
    if (!(v >= p->lo && v <= p->hi))
        return false;
    if (p->bounds != PARAM_CLOSED && v == p->lo)
        return false;
    if (p->bounds == PARAM_OPEN_BOTH && v == p->hi)
        return false;
    return !p->rule || p->rule(v);
}

/* v as %g writes it, but an exponent as people write it: 1e300, not
 * 1e+300. */
static void number_text(double v, char *buf, size_t size)
{
    char raw[40];
    snprintf(raw, sizeof raw, "%g", v);
    char *e = strchr(raw, 'e');
    if (e && e[1] == '+')
        memmove(e + 1, e + 2, strlen(e + 2) + 1);
    snprintf(buf, size, "%s", raw);
}

void param_range_text(const param *p, char *buf, size_t size)
{
    /* Each end says whether it is included: "from 1 to 10" and "at least"
     * or "at most" include it, "more than" and "less than" do not. */
    const char *unit = p->unit ? p->unit : "";
    const char *space = p->unit ? " " : "";
    char lo[40], hi[40];
    number_text(p->lo, lo, sizeof lo);
    number_text(p->hi, hi, sizeof hi);
    bool open_low = p->bounds != PARAM_CLOSED, open_high = p->bounds == PARAM_OPEN_BOTH;
    bool no_high = p->hi >= DBL_MAX, no_low = p->lo <= -DBL_MAX;
    if (p->rule_text)
        snprintf(buf, size, "%s", p->rule_text);
    else if (open_low && no_high && p->lo == 0)
        snprintf(buf, size, "positive");
    else if (no_high)
        snprintf(buf, size, "%s %s%s%s", open_low ? "more than" : "at least", lo, space, unit);
    else if (no_low)
        snprintf(buf, size, "%s %s%s%s", open_high ? "less than" : "at most", hi, space, unit);
    else if (!open_low && !open_high)
        snprintf(buf, size, "from %s to %s%s%s", lo, hi, space, unit);
    else
        snprintf(buf, size, "%s %s and %s %s%s%s", open_low ? "more than" : "at least", lo,
                 open_high ? "less than" : "at most", hi, space, unit);
}

/* Fills err for number v of p, out of its range. */
static glint_status out_of_range(const param *p, const char *what, double v, glint_error *err)
{
    if (!isfinite(v))
        return error_set(err, GLINT_ERR_INVALID, "%s %s is not finite", what, p->key);
    char range[96];
    param_range_text(p, range, sizeof range);
    return error_set(err, GLINT_ERR_INVALID, "%s %s must be %s, got %g", what, p->key, range, v);
}

static bool vec_finite(glint_vec3 v) { return isfinite(v.x) && isfinite(v.y) && isfinite(v.z); }

/* Whether every channel of c lies in p's range. */
static bool color_in_range(const param *p, glint_color c)
{
    return param_in_range(p, c.r) && param_in_range(p, c.g) && param_in_range(p, c.b);
}

/* Checks one field of obj. */
static glint_status check_one(const param *p, const void *obj, const char *what, glint_error *err)
{
    const void *f = cfield(obj, p->offset);
    switch (p->type) {
    case PARAM_NUMBER: {
        double v = *(const double *)f;
        return param_in_range(p, v) ? GLINT_OK : out_of_range(p, what, v, err);
    }
    case PARAM_INTEGER: {
        int v = *(const int *)f;
        return param_in_range(p, v) ? GLINT_OK : out_of_range(p, what, v, err);
    }
    case PARAM_UINT32:
        return GLINT_OK; /* every value is in range */
    case PARAM_CHOICE: {
        int v = *(const int *)f;
        if (v >= 0 && v < p->word_count)
            return GLINT_OK;
        return error_set(err, GLINT_ERR_INVALID, "%s %s must be one of %d choices, got %d", what, p->key,
                         p->word_count, v);
    }
    case PARAM_BOOL:
        return GLINT_OK;
    case PARAM_VEC3:
    case PARAM_DIRECTION: {
        glint_vec3 v = *(const glint_vec3 *)f;
        if (!vec_finite(v))
            return error_set(err, GLINT_ERR_INVALID, "%s %s is not finite", what, p->key);
        if (p->type == PARAM_DIRECTION && v.x == 0 && v.y == 0 && v.z == 0)
            return error_set(err, GLINT_ERR_INVALID, "%s %s must not be zero", what, p->key);
        return GLINT_OK;
    }
    case PARAM_COLOR:
    case PARAM_COLOR_PAIR: {
        const glint_color *c = f;
        for (int i = 0; i < (p->type == PARAM_COLOR ? 1 : 2); i++)
            if (!color_in_range(p, c[i]))
                return error_set(err, GLINT_ERR_INVALID, "%s %s must be finite and not negative", what, p->key);
        return GLINT_OK;
    }
    case PARAM_NUMBERS: {
        const double *v = f;
        for (int k = 0; k < p->max_count; k++)
            if (!isfinite(v[k]))
                return error_set(err, GLINT_ERR_INVALID, "%s %s number %d is not finite", what, p->key, k);
        return GLINT_OK;
    }
    case PARAM_COLOR_STOPS: {
        int n = *(const int *)cfield(obj, p->count_offset);
        if (n < p->min_count || n > p->max_count)
            return error_set(err, GLINT_ERR_INVALID, "%s %s needs %d to %d stops, got %d", what, p->key,
                             p->min_count, p->max_count, n);
        const glint_color_stop *stops = f;
        for (int k = 0; k < n; k++) {
            double at = stops[k].at, before = k ? stops[k - 1].at : 0;
            if (!(at >= before && at <= 1))
                return error_set(err, GLINT_ERR_INVALID, "%s %s stop %d is at %g: stops go from 0 to 1, in order",
                                 what, p->key, k, at);
            if (!color_in_range(p, stops[k].color))
                return error_set(err, GLINT_ERR_INVALID, "%s %s stop %d's colour must be finite and not negative",
                                 what, p->key, k);
        }
        return GLINT_OK;
    }
    case PARAM_PATH: {
        const char *path = *(const char *const *)f;
        if (!path || !path[0])
            return error_set(err, GLINT_ERR_INVALID, "%s needs a %s", what, p->key);
        return GLINT_OK;
    }
    case PARAM_POINTS: {
        int n = *(const int *)cfield(obj, p->count_offset);
        if (n < p->min_count || n > p->max_count)
            return error_set(err, GLINT_ERR_INVALID, "%s needs %d %s %d %s, got %d", what, p->min_count,
                             p->max_count == p->min_count + 1 ? "or" : "to", p->max_count, p->key, n);
        const glint_vec3 *pts = f;
        for (int k = 0; k < n; k++)
            if (!vec_finite(pts[k]))
                return error_set(err, GLINT_ERR_INVALID, "%s point %d is not finite", what, k);
        return GLINT_OK;
    }
    }
    return GLINT_OK;
}

glint_status params_check(param_table t, const void *obj, const char *what, glint_error *err)
{
    for (int i = 0; i < t.count; i++) {
        glint_status s = check_one(&t.params[i], obj, what, err);
        if (s)
            return s;
    }
    return GLINT_OK;
}

/* Whether the n doubles at f are those of def, bit for bit. */
static bool same_doubles(const void *f, const double *def, int n)
{
    return memcmp(f, def, (size_t)n * sizeof(double)) == 0;
}

bool param_is_default(const param *p, const void *obj)
{
    const void *f = cfield(obj, p->offset);
    if (p->required)
        return false;
    switch (p->type) {
    case PARAM_NUMBER:
        return same_doubles(f, p->def, 1);
    case PARAM_INTEGER:
    case PARAM_CHOICE:
        return *(const int *)f == (int)p->def[0];
    case PARAM_UINT32:
        return *(const uint32_t *)f == (uint32_t)p->def[0];
    case PARAM_BOOL:
        return *(const bool *)f == (p->def[0] != 0);
    case PARAM_VEC3:
    case PARAM_DIRECTION:
    case PARAM_COLOR:
        return same_doubles(f, p->def, 3);
    case PARAM_COLOR_PAIR:
        return same_doubles(f, p->def, 6);
    case PARAM_NUMBERS:
        for (int k = 0; k < p->max_count; k++)
            if (((const double *)f)[k] != 0)
                return false;
        return true;
    case PARAM_COLOR_STOPS: {
        const glint_color_stop *stops = f;
        return *(const int *)cfield(obj, p->count_offset) == 2 && stops[0].at == 0 && stops[1].at == 1 &&
               same_doubles(&stops[0].color, p->def, 3) && same_doubles(&stops[1].color, p->def + 3, 3);
    }
    case PARAM_PATH:
    case PARAM_POINTS:
        return false;
    }
    return false;
}

const param *params_find(param_table t, const char *key)
{
    for (int i = 0; i < t.count; i++)
        if (strcmp(t.params[i].key, key) == 0)
            return &t.params[i];
    return NULL;
}
