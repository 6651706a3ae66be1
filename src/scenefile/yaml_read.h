/* yaml_read.h - typed reading of YAML nodes for the scene loader: each
 * getter checks the value's type and reports a problem at its place. A walk
 * over the tree needs no count of its own: the parser bounds what aliases
 * add (yaml_tree.h). */
#ifndef GLINT_SCENEFILE_YAML_READ_H
#define GLINT_SCENEFILE_YAML_READ_H

#include "core/color.h"
#include "core/vec.h"
#include "scenefile/diag.h"

typedef struct reader {
    diag *d;
} reader;

/* The value of key in mapping map, looking through merge keys (<<), or NULL. */
const ynode *yr_get(reader *r, const ynode *map, const char *key);

/* Reports every key of map (merged maps included) that is not one of the
 * `count` allowed keys, with a "did you mean" hint; `what` names the map. */
void yr_check_keys(reader *r, const ynode *map, const char *what, const char *const *allowed, int count);

/* True when n is a mapping; otherwise reports "<what> must be a map, got ...". */
bool yr_is_map(reader *r, const ynode *n, const char *what);

/* True when n is a sequence; otherwise reports "<what> must be a list, got ...". */
bool yr_is_list(reader *r, const ynode *n, const char *what);

/* Each reads the value node n of `key` into *out; on a wrong value they
 * report it and return false, leaving *out alone. */
bool yr_number(reader *r, const ynode *n, const char *key, double *out);
bool yr_integer(reader *r, const ynode *n, const char *key, long long lo, long long hi, long long *out);
bool yr_bool(reader *r, const ynode *n, const char *key, bool *out);
bool yr_vec3(reader *r, const ynode *n, const char *key, vec3 *out);
/* [r, g, b] (channels 0..1) and "#rrggbb" are sRGB display colours,
 * converted to linear; {linear: [r, g, b]} (channels >= 0) is taken as it is. */
bool yr_color(reader *r, const ynode *n, const char *key, color *out);
/* A non-empty scalar. */
bool yr_text(reader *r, const ynode *n, const char *key, const char **out);

/* Optional keys of a map: when key is present, read it into *out; true
 * when absent or well formed. */
bool yr_opt_number(reader *r, const ynode *map, const char *key, double *out);
bool yr_opt_integer(reader *r, const ynode *map, const char *key, long long lo, long long hi, long long *out);
bool yr_opt_bool(reader *r, const ynode *map, const char *key, bool *out);
bool yr_opt_vec3(reader *r, const ynode *map, const char *key, vec3 *out);
bool yr_opt_color(reader *r, const ynode *map, const char *key, color *out);

/* A required key: reports "<what> needs '<key>'" at the map when absent. */
const ynode *yr_need(reader *r, const ynode *map, const char *key, const char *what);

#endif
