/* params.h - parameter tables: the one place where a kind's keys, their
 * types, defaults, ranges and meanings are written down.
 *
 * Every kind (a shape, a light, a texture, a material, the settings...) is
 * described by a C struct of the public API and a table of its parameters,
 * each naming a field of that struct by offset. The C API fills defaults
 * and checks values through the table (params_defaults, params_check); the
 * scene-file loader reads keys through the same table; a test checks that
 * docs/scene-format.md documents every key with the table's default and
 * range. A rule that spans several fields (a box's min below its max)
 * stays in the kind's own check, after the table's. */
#ifndef GLINT_CORE_PARAMS_H
#define GLINT_CORE_PARAMS_H

#include <float.h>
#include <stdbool.h>
#include <stddef.h>
#include <stdint.h>
#include "glint.h"

typedef enum param_type {
    PARAM_NUMBER,   /* double */
    PARAM_INTEGER,  /* int */
    PARAM_UINT32,   /* uint32_t */
    PARAM_CHOICE,   /* an enum (int): the index of one of `words` */
    PARAM_VEC3,     /* glint_vec3: any finite vector */
    PARAM_DIRECTION,/* glint_vec3: finite and not zero */
    PARAM_COLOR,    /* glint_color: finite channels within the range */
    PARAM_COLOR_PAIR,/* glint_color[2]: two colours, as PARAM_COLOR each */
    PARAM_PATH,     /* const char *: a file, relative to the scene file that names it */
    PARAM_BOOL,     /* bool */
    PARAM_POINTS,   /* glint_vec3[], the count in the int at count_offset */
    PARAM_NUMBERS,  /* double[max_count]: exactly that many finite numbers; 0 each by default */
    PARAM_COLOR_STOPS /* glint_color_stop[], the count in the int at count_offset: a colour
                         map, its stops' `at` ascending from 0 to 1 and colours as
                         PARAM_COLOR's; the default is two, def[0..2] at 0 and def[3..5] at 1 */
} param_type;

/* Which ends of a number's range are excluded. */
typedef enum param_bounds { PARAM_CLOSED, PARAM_OPEN_LOW, PARAM_OPEN_BOTH } param_bounds;

typedef struct param {
    const char *key;          /* the scene-file key, and the name in messages */
    param_type type;
    size_t offset;            /* of the field in the kind's struct */
    bool required;            /* a scene file must give it: no default */
    double def[6];            /* the default: a number, a bool (0 or 1), a vector or colour,
                                 two colours */
    double lo, hi;            /* numbers, integers and colour channels: the range */
    param_bounds bounds;
    const char *unit;         /* appended to the range's wording ("degrees"), or NULL */
    int min_count, max_count; /* points, stops: how many; numbers: max_count */
    size_t count_offset;      /* points, stops: the int that holds the count */
    const char *const *words; /* choices: the words, in the enum's order */
    int word_count;
    /* A rule beyond the range (a square number), or NULL, and its wording
     * ("a square number (1, 4, 9, 16, ...)"), which replaces the range's in
     * messages. */
    bool (*rule)(double v);
    const char *rule_text;
    bool constant;            /* a number, vector or colour that cannot change with time
                                 (keyed values: docs/animation.md) */
    const char *meaning;      /* one line, for the docs */
    /* The docs' words for a default that depends on more than the key (a
     * mapping centred on its shape), or NULL: def is shown. */
    const char *default_text;
} param;

/* The range of numbers above 0 (any finite positive number). */
#define PARAM_POSITIVE .lo = 0, .hi = DBL_MAX, .bounds = PARAM_OPEN_LOW

/* A table and its length, as kinds hand them around. */
typedef struct param_table {
    const param *params;
    int count;
} param_table;

#define PARAM_TABLE(array) ((param_table){(array), (int)(sizeof(array) / sizeof((array)[0]))})

/* Sets every field of the table in obj to its default (required fields to
 * zero, points to none). */
void params_defaults(param_table t, void *obj);

/* Checks every field of obj against the table: finite values within their
 * ranges, non-zero directions, point counts. On the first failure fills err
 * with "<what> <key> must be <range>, got <value>" (or "is not finite",
 * "must not be zero") and returns GLINT_ERR_INVALID. */
glint_status params_check(param_table t, const void *obj, const char *what, glint_error *err);

/* Whether number v lies in p's range and keeps its rule. */
bool param_in_range(const param *p, double v);

/* Writes p's range in words, each end saying whether it is included
 * ("from 0 to 1", "positive", "at least 0", "more than 0 and less than 180
 * degrees", "more than 0 and at most 90 degrees"), or the rule's wording,
 * into buf. */
void param_range_text(const param *p, char *buf, size_t size);

/* Whether p's field in obj holds p's default bit for bit (a -0 is not a
 * default 0). A required parameter, a path and a list of points have no
 * default to hold: false. */
bool param_is_default(const param *p, const void *obj);

/* The parameter of the table with that key, or NULL. */
const param *params_find(param_table t, const char *key);

#endif
