/* read_values.c - the scene loader's typed reads: numbers in ranges, words
 * from a list, typed maps, paths relative to a file, and any kind's keys
 * read through its parameter table. */
#include <stdio.h>
#include <stdlib.h>
#include <string.h>
#include "core/array.h"
#include "scenefile/loader.h"

bool need_number(loader *l, const ynode *map, const char *key, const char *what, double *out)
{
    const ynode *n = yr_need(&l->r, map, key, what);
    return n && yr_number(&l->r, n, key, out);
}

bool need_vec3(loader *l, const ynode *map, const char *key, const char *what, vec3 *out)
{
    const ynode *n = yr_need(&l->r, map, key, what);
    return n && yr_vec3(&l->r, n, key, out);
}

/* Matches a scalar against a list of words; reports with a hint. */
int word(loader *l, const ynode *n, const char *key, const char *const *words, int count)
{
    if (n->kind == YNODE_SCALAR)
        for (int i = 0; i < count; i++)
            if (strcmp(n->value, words[i]) == 0)
                return i;
    char list[200] = "";
    for (int i = 0; i < count; i++) {
        strcat(list, i == 0 ? "" : i == count - 1 ? " or " : ", ");
        strcat(list, words[i]);
    }
    const char *hint = n->kind == YNODE_SCALAR ? diag_suggest(n->value, words, count) : NULL;
    if (hint)
        diag_at(&l->d, n, "'%s' must be %s, got '%.60s' (did you mean '%s'?)", key, list, n->value, hint);
    else if (n->kind == YNODE_SCALAR)
        diag_at(&l->d, n, "'%s' must be %s, got '%.60s'", key, list, n->value);
    else
        diag_at(&l->d, n, "'%s' must be %s, got %s", key, list, ynode_describe(n));
    return -1;
}

/* The kind of a map that must say its `type`: the index of that word among
 * `kinds`, or -1 after a report. `what` names the map ("a light"). */
int typed_map(loader *l, const ynode *n, const char *what, const char *const *kinds, int count)
{
    if (!yr_is_map(&l->r, n, what))
        return -1;
    const ynode *type = yr_need(&l->r, n, "type", what);
    return type ? word(l, type, "type", kinds, count) : -1;
}

/* Joins a path named in file `from` to that file's directory. */
char *relative_to(const char *from, const char *path)
{
    const char *slash = strrchr(from, '/');
    size_t dir = path[0] == '/' || !slash ? 0 : (size_t)(slash - from) + 1;
    char *out = malloc(dir + strlen(path) + 1);
    if (out) {
        memcpy(out, from, dir);
        strcpy(out + dir, path);
    }
    return out;
}


bool is_keyed(loader *l, const ynode *n)
{
    return n->kind == YNODE_MAPPING && yr_get(&l->r, n, "keys");
}

/* The numbers of a value of p's type (a number, vector or colour), and
 * how many: 0 for a type that cannot be keyed. */
static int value_numbers(const param *p, void *field, double **numbers)
{
    *numbers = field;
    return p->type == PARAM_NUMBER ? 1 : p->type == PARAM_VEC3 || p->type == PARAM_DIRECTION || p->type == PARAM_COLOR ? 3 : 0;
}


/* A colour map: a list of [value, colour] stops, their values ascending
 * from 0 to 1. */
static bool read_stops(loader *l, const ynode *n, const param *p, void *obj)
{
    bool shaped = n->kind == YNODE_SEQUENCE && n->count >= p->min_count && n->count <= p->max_count;
    for (int i = 0; shaped && i < n->count; i++)
        shaped = n->items[i]->kind == YNODE_SEQUENCE && n->items[i]->count == 2;
    if (!shaped) {
        diag_at(&l->d, n, "'%s' must be a list of %d to %d stops, each [value, colour]", p->key, p->min_count,
                p->max_count);
        return false;
    }
    glint_color_stop *stops = (glint_color_stop *)((char *)obj + p->offset);
    for (int i = 0; i < n->count; i++) {
        const ynode *at = n->items[i]->items[0];
        if (!yr_number(&l->r, at, p->key, &stops[i].at) ||
            !yr_color(&l->r, n->items[i]->items[1], p->key, (color *)&stops[i].color))
            return false;
        double before = i ? stops[i - 1].at : 0;
        if (!(stops[i].at >= before && stops[i].at <= 1)) {
            diag_at(&l->d, at, "'%s' stop values must go from 0 to 1 in order, got %g after %g", p->key,
                    stops[i].at, before);
            return false;
        }
    }
    *(int *)((char *)obj + p->count_offset) = n->count;
    return true;
}

/* A keyed value of parameter p, `{keys: [[time, value], ...], interpolate}`
 * (n, is_keyed), into *field as it is at the loader's time: each value
 * read and checked as p's own, the times increasing. */
static bool read_keyed(loader *l, const ynode *n, const param *p, void *field)
{
    static const char *const keyed_keys[] = {"keys", "interpolate"};
    static const char *const ways[] = {"linear", "smooth", "step"};
    double *numbers;
    int width = value_numbers(p, field, &numbers);
    if (!width || p->constant) {
        diag_at(&l->d, n, "'%s' cannot change with time", p->key);
        return false;
    }
    l->keyed = true;
    yr_check_keys(&l->r, n, p->key, keyed_keys, COUNT(keyed_keys));
    const ynode *list = yr_get(&l->r, n, "keys"), *how = yr_get(&l->r, n, "interpolate");
    int way = how ? word(l, how, "interpolate", ways, COUNT(ways)) : GLINT_INTERPOLATE_LINEAR;
    if (!yr_is_list(&l->r, list, "'keys'") || way < 0)
        return false;
    if (list->count == 0) {
        diag_at(&l->d, list, "'keys' needs at least one [time, value]");
        return false;
    }
    double *times = malloc(sizeof *times * (size_t)list->count);
    double *values = malloc(sizeof *values * (size_t)list->count * (size_t)width);
    if (!times || !values) {
        free(times);
        free(values);
        diag_raw(&l->d, GLINT_ERR_NOMEM, "out of memory");
        return false;
    }
    param one = *p;
    one.offset = 0;
    bool good = true;
    for (int i = 0; i < list->count; i++) {
        const ynode *key = list->items[i];
        if (key->kind != YNODE_SEQUENCE || key->count != 2) {
            diag_at(&l->d, key, "each of '%s''s keys is [time in seconds, value], got %s", p->key, ynode_describe(key));
            good = false;
            continue;
        }
        double value[GLINT_KEY_WIDTH_MAX];
        if (!yr_number(&l->r, key->items[0], "time", &times[i]) || !read_param(l, key->items[1], &one, value)) {
            good = false;
            continue;
        }
        if (i > 0 && good && !(times[i] > times[i - 1])) {
            diag_at(&l->d, key->items[0], "key times must increase: %g s comes after %g s", times[i], times[i - 1]);
            good = false;
        }
        memcpy(values + i * width, value, sizeof *values * (size_t)width);
    }
    if (good) {
        glint_keys keys = {times, values, list->count, width, (glint_interpolation)way};
        glint_keys_value(&keys, l->time, numbers);
        if (p->type == PARAM_DIRECTION && numbers[0] == 0 && numbers[1] == 0 && numbers[2] == 0) {
            diag_at(&l->d, n, "'%s' is zero at %g s, where its keys pass through zero", p->key, l->time);
            good = false;
        }
    }
    free(times);
    free(values);
    return good;
}

bool read_param(loader *l, const ynode *n, const param *p, void *obj)
{
    void *f = (char *)obj + p->offset;
    if (is_keyed(l, n))
        return read_keyed(l, n, p, f);
    switch (p->type) {
    case PARAM_NUMBER: {
        double v;
        if (!yr_number(&l->r, n, p->key, &v))
            return false;
        if (!param_in_range(p, v)) {
            char range[96];
            param_range_text(p, range, sizeof range);
            diag_at(&l->d, n, "'%s' must be %s, got %g", p->key, range, v);
            return false;
        }
        *(double *)f = v;
        return true;
    }
    case PARAM_INTEGER: {
        long long v;
        if (!yr_integer(&l->r, n, p->key, (long long)p->lo, (long long)p->hi, &v))
            return false;
        if (p->rule && !p->rule((double)v)) {
            diag_at(&l->d, n, "'%s' must be %s, got %lld", p->key, p->rule_text, v);
            return false;
        }
        *(int *)f = (int)v;
        return true;
    }
    case PARAM_UINT32: {
        long long v;
        if (!yr_integer(&l->r, n, p->key, 0, UINT32_MAX, &v))
            return false;
        *(uint32_t *)f = (uint32_t)v;
        return true;
    }
    case PARAM_CHOICE: {
        int k = word(l, n, p->key, p->words, p->word_count);
        if (k >= 0)
            *(int *)f = k;
        return k >= 0;
    }
    case PARAM_BOOL:
        return yr_bool(&l->r, n, p->key, f);
    case PARAM_VEC3:
        return yr_vec3(&l->r, n, p->key, f);
    case PARAM_DIRECTION: {
        vec3 v;
        if (!yr_vec3(&l->r, n, p->key, &v))
            return false;
        if (v.x == 0 && v.y == 0 && v.z == 0) {
            diag_at(&l->d, n, "'%s' must not be zero", p->key);
            return false;
        }
        *(vec3 *)f = v;
        return true;
    }
    case PARAM_COLOR:
        return yr_color(&l->r, n, p->key, f);
    case PARAM_COLOR_PAIR:
        if (n->kind != YNODE_SEQUENCE || n->count != 2) {
            diag_at(&l->d, n, "'%s' must be a list of two colours", p->key);
            return false;
        }
        return yr_color(&l->r, n->items[0], p->key, (color *)f) &&
               yr_color(&l->r, n->items[1], p->key, (color *)f + 1);
    case PARAM_PATH: {
        const char *path;
        if (!yr_text(&l->r, n, p->key, &path))
            return false;
        char *full = relative_to(n->file, path);
        if (!full || !array_reserve((void **)&l->paths, &l->path_cap, l->path_count + 1, sizeof *l->paths)) {
            free(full);
            diag_raw(&l->d, GLINT_ERR_NOMEM, "out of memory");
            return false;
        }
        l->paths[l->path_count++] = full;
        *(const char **)f = full;
        return true;
    }
    case PARAM_POINTS: {
        char list[40];
        snprintf(list, sizeof list, "'%s'", p->key);
        if (!yr_is_list(&l->r, n, list))
            return false;
        if (n->count < p->min_count || n->count > p->max_count) {
            diag_at(&l->d, n, "'%s' must hold %d %s %d points, got %d", p->key, p->min_count,
                    p->max_count == p->min_count + 1 ? "or" : "to", p->max_count, n->count);
            return false;
        }
        for (int i = 0; i < n->count; i++)
            if (!yr_vec3(&l->r, n->items[i], p->key, (vec3 *)f + i))
                return false;
        *(int *)((char *)obj + p->count_offset) = n->count;
        return true;
    }
    case PARAM_NUMBERS:
        if (n->kind != YNODE_SEQUENCE || n->count != p->max_count) {
            diag_at(&l->d, n, "'%s' must be a list of %d numbers", p->key, p->max_count);
            return false;
        }
        for (int i = 0; i < n->count; i++)
            if (!yr_number(&l->r, n->items[i], p->key, (double *)f + i))
                return false;
        return true;
    case PARAM_COLOR_STOPS:
        return read_stops(l, n, p, obj);
    }
    return false;
}

bool read_params(loader *l, const ynode *map, param_table t, const char *what, void *obj)
{
    bool good = true;
    for (int i = 0; i < t.count; i++) {
        const param *p = &t.params[i];
        const ynode *n = p->required ? yr_need(&l->r, map, p->key, what) : yr_get(&l->r, map, p->key);
        if (n)
            good = read_param(l, n, p, obj) && good;
        else
            good = good && !p->required;
    }
    return good;
}

bool read_sub_map(loader *l, const ynode *parent, const char *key, param_table t, void *obj)
{
    char quoted[40];
    snprintf(quoted, sizeof quoted, "'%s'", key);
    const ynode *n = yr_get(&l->r, parent, key);
    if (!n || !yr_is_map(&l->r, n, quoted))
        return false;
    const char *keys[8];
    int count = param_keys(t, NULL, 0, keys, COUNT(keys));
    yr_check_keys(&l->r, n, key, keys, count);
    params_defaults(t, obj);
    return read_params(l, n, t, key, obj);
}

int param_keys(param_table t, const char *const *common, int common_count, const char **keys, int room)
{
    int count = 0;
    for (int i = 0; i < common_count && count < room; i++)
        keys[count++] = common[i];
    for (int i = 0; i < t.count && count < room; i++)
        keys[count++] = t.params[i].key;
    return count;
}
