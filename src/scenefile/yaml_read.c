/* yaml_read.c - typed getters over the YAML tree, with their messages. */
#include <math.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>
#include <strings.h>
#include "core/short_decimal.h"
#include "scenefile/yaml_read.h"

/* Merge keys may merge maps that merge maps; a cycle is impossible (aliases
 * only name finished nodes), but depth is bounded anyway. */
#define MAX_MERGE_DEPTH 16

static bool is_merge_key(const ynode *k)
{
    return k->kind == YNODE_SCALAR && !k->quoted && strcmp(k->value, "<<") == 0;
}

static const ynode *get_depth(reader *r, const ynode *map, const char *key, int depth)
{
    if (map->kind != YNODE_MAPPING || depth > MAX_MERGE_DEPTH)
        return NULL;
    for (int i = 0; i + 1 < map->count; i += 2) {
        const ynode *k = map->items[i];
        if (k->kind == YNODE_SCALAR && !is_merge_key(k) && strcmp(k->value, key) == 0)
            return map->items[i + 1];
    }
    /* Keys written in the map win over merged ones; earlier merges win over later. */
    for (int i = 0; i + 1 < map->count; i += 2) {
        if (!is_merge_key(map->items[i]))
            continue;
        const ynode *v = map->items[i + 1];
        if (v->kind == YNODE_MAPPING) {
            const ynode *found = get_depth(r, v, key, depth + 1);
            if (found)
                return found;
        }
        for (int j = 0; v->kind == YNODE_SEQUENCE && j < v->count; j++) {
            const ynode *found = get_depth(r, v->items[j], key, depth + 1);
            if (found)
                return found;
        }
    }
    return NULL;
}

const ynode *yr_get(reader *r, const ynode *map, const char *key)
{
    return get_depth(r, map, key, 0);
}

static void check_keys_depth(reader *r, const ynode *map, const char *what, const char *const *allowed, int count,
                             int depth)
{
    for (int i = 0; i + 1 < map->count && !diag_full(r->d); i += 2) {
        const ynode *k = map->items[i], *v = map->items[i + 1];
        if (is_merge_key(k)) {
            const ynode *bad = v->kind == YNODE_MAPPING || v->kind == YNODE_SEQUENCE ? NULL : v;
            for (int j = 0; !bad && v->kind == YNODE_SEQUENCE && j < v->count; j++)
                if (v->items[j]->kind != YNODE_MAPPING)
                    bad = v->items[j];
            if (bad) {
                diag_at(r->d, bad, "a merge key (<<) needs a map or a list of maps");
                continue;
            }
            if (depth >= MAX_MERGE_DEPTH) {
                diag_at(r->d, v, "merge keys (<<) nested too deep (limit %d)", MAX_MERGE_DEPTH);
                continue;
            }
            if (v->kind == YNODE_MAPPING)
                check_keys_depth(r, v, what, allowed, count, depth + 1);
            for (int j = 0; v->kind == YNODE_SEQUENCE && j < v->count; j++)
                check_keys_depth(r, v->items[j], what, allowed, count, depth + 1);
            continue;
        }
        if (k->kind != YNODE_SCALAR) {
            diag_at(r->d, k, "a key in %s must be a word, got %s", what, ynode_describe(k));
            continue;
        }
        bool known = false;
        for (int j = 0; j < count && !known; j++)
            known = strcmp(k->value, allowed[j]) == 0;
        if (known) {
            /* Only known keys are compared, so this stays linear in the map's size. */
            for (int j = 0; j < i; j += 2)
                if (map->items[j]->kind == YNODE_SCALAR && strcmp(map->items[j]->value, k->value) == 0) {
                    diag_at(r->d, k, "duplicate key '%.100s' in %s", k->value, what);
                    break;
                }
            continue;
        }
        const char *hint = diag_suggest(k->value, allowed, count);
        if (hint)
            diag_at(r->d, k, "unknown key '%.100s' in %s (did you mean '%s'?)", k->value, what, hint);
        else
            diag_at(r->d, k, "unknown key '%.100s' in %s", k->value, what);
    }
}

void yr_check_keys(reader *r, const ynode *map, const char *what, const char *const *allowed, int count)
{
    check_keys_depth(r, map, what, allowed, count, 0);
}

bool yr_is_map(reader *r, const ynode *n, const char *what)
{
    if (n->kind == YNODE_MAPPING)
        return true;
    diag_at(r->d, n, "%s must be a map, got %s", what, ynode_describe(n));
    return false;
}

bool yr_is_list(reader *r, const ynode *n, const char *what)
{
    if (n->kind == YNODE_SEQUENCE)
        return true;
    diag_at(r->d, n, "%s must be a list, got %s", what, ynode_describe(n));
    return false;
}

/* Parses text as a finite number; `why` says what went wrong. */
static bool parse_text(const char *text, double *out, const char **why)
{
    *why = "a number";
    if (short_decimal(text, out))
        return true;
    if (text[0] == '\0')
        return false;
    char *end;
    double v = strtod(text, &end);
    if (end == text || *end != '\0') {
        /* YAML's own spellings of infinity and not-a-number. */
        const char *word = text + (text[0] == '-' || text[0] == '+');
        if (!strcasecmp(word, ".inf") || !strcasecmp(word, ".nan"))
            *why = "a finite number";
        return false;
    }
    if (!isfinite(v)) {
        *why = "a finite number";
        return false;
    }
    *out = v;
    return true;
}

/* Parses a plain scalar as a finite number: quotes make text. */
static bool parse_number(const ynode *n, double *out, const char **why)
{
    *why = "a number";
    return n->kind == YNODE_SCALAR && !n->quoted && parse_text(n->value, out, why);
}

/* How a wrong value is named in a message: its text, or what it is. A
 * value in quotes that would be right without them (right_bare) says so:
 * in YAML, quotes make text of "1" and "false". */
static void got(const ynode *n, bool right_bare, char *buf, size_t size)
{
    if (n->kind == YNODE_SCALAR && n->quoted && right_bare)
        snprintf(buf, size, "'%.60s' in quotes, which is text: write %.60s without quotes", n->value, n->value);
    else if (n->kind == YNODE_SCALAR && n->quoted)
        snprintf(buf, size, "'%.60s' in quotes, which is text", n->value);
    else if (n->kind == YNODE_SCALAR && strcmp(ynode_describe(n), "nothing") != 0)
        snprintf(buf, size, "'%.60s'", n->value);
    else
        snprintf(buf, size, "%s", ynode_describe(n));
}

/* Whether scalar n's text, without its quotes, is a number from lo to hi
 * (whole when `whole`). */
static bool bare_number(const ynode *n, bool whole, double lo, double hi)
{
    double v;
    const char *why;
    return n->kind == YNODE_SCALAR && parse_text(n->value, &v, &why) && (!whole || v == floor(v)) && v >= lo &&
           v <= hi;
}

bool yr_number(reader *r, const ynode *n, const char *key, double *out)
{
    const char *why;
    char what[200];
    if (parse_number(n, out, &why))
        return true;
    got(n, bare_number(n, false, -INFINITY, INFINITY), what, sizeof what);
    diag_at(r->d, n, "'%s' must be %s, got %s", key, why, what);
    return false;
}

bool yr_integer(reader *r, const ynode *n, const char *key, long long lo, long long hi, long long *out)
{
    double v;
    const char *why;
    char what[200];
    if (parse_number(n, &v, &why) && v == floor(v) && v >= (double)lo && v <= (double)hi) {
        *out = (long long)v;
        return true;
    }
    got(n, bare_number(n, true, (double)lo, (double)hi), what, sizeof what);
    diag_at(r->d, n, "'%s' must be a whole number from %lld to %lld, got %s", key, lo, hi, what);
    return false;
}

bool yr_bool(reader *r, const ynode *n, const char *key, bool *out)
{
    bool word = n->kind == YNODE_SCALAR && (!strcmp(n->value, "true") || !strcmp(n->value, "false"));
    if (word && !n->quoted) {
        *out = n->value[0] == 't';
        return true;
    }
    char what[200];
    got(n, word, what, sizeof what);
    diag_at(r->d, n, "'%s' must be true or false, got %s", key, what);
    return false;
}

/* Reads a list of exactly three numbers. */
static bool triple(reader *r, const ynode *n, double v[3])
{
    const char *why;
    if (n->kind != YNODE_SEQUENCE || n->count != 3)
        return false;
    for (int i = 0; i < 3; i++)
        if (!parse_number(n->items[i], &v[i], &why))
            return false;
    return true;
}

bool yr_vec3(reader *r, const ynode *n, const char *key, vec3 *out)
{
    double v[3];
    if (!triple(r, n, v)) {
        diag_at(r->d, n, "'%s' must be a list of 3 finite numbers [x, y, z]", key);
        return false;
    }
    *out = v3(v[0], v[1], v[2]);
    return true;
}

static int hex_digit(char c)
{
    if (c >= '0' && c <= '9')
        return c - '0';
    if (c >= 'a' && c <= 'f')
        return c - 'a' + 10;
    if (c >= 'A' && c <= 'F')
        return c - 'A' + 10;
    return -1;
}

static bool hex_color(const char *s, double v[3])
{
    if (s[0] != '#' || strlen(s) != 7)
        return false;
    for (int i = 0; i < 3; i++) {
        int hi = hex_digit(s[1 + 2 * i]), lo = hex_digit(s[2 + 2 * i]);
        if (hi < 0 || lo < 0)
            return false;
        v[i] = (hi * 16 + lo) / 255.0;
    }
    return true;
}

bool yr_color(reader *r, const ynode *n, const char *key, color *out)
{
    double v[3];
    bool linear = false, ok = false;
    if (n->kind == YNODE_SCALAR)
        ok = hex_color(n->value, v);
    else if (n->kind == YNODE_SEQUENCE)
        ok = triple(r, n, v);
    else if (n->kind == YNODE_MAPPING && n->count == 2) {
        const ynode *lin = yr_get(r, n, "linear");
        ok = linear = lin && triple(r, lin, v);
    }
    if (ok && (v[0] < 0 || v[1] < 0 || v[2] < 0)) {
        diag_at(r->d, n, "'%s' must not have negative channels", key);
        return false;
    }
    if (ok && !linear && (v[0] > 1 || v[1] > 1 || v[2] > 1)) {
        diag_at(r->d, n, "'%s' channels must be from 0 to 1 (a light's 'intensity' makes it brighter)", key);
        return false;
    }
    if (!ok) {
        diag_at(r->d, n, "'%s' must be a colour: [r, g, b], \"#rrggbb\" or {linear: [r, g, b]}", key);
        return false;
    }
    *out = linear ? rgb(v[0], v[1], v[2])
                  : rgb(glint_srgb_to_linear(v[0]), glint_srgb_to_linear(v[1]), glint_srgb_to_linear(v[2]));
    return true;
}

bool yr_text(reader *r, const ynode *n, const char *key, const char **out)
{
    if (n->kind == YNODE_SCALAR && n->value[0] != '\0') {
        *out = n->value;
        return true;
    }
    if (n->kind == YNODE_SCALAR)
        diag_at(r->d, n, "'%s' must not be empty", key);
    else
        diag_at(r->d, n, "'%s' must be text, got %s", key, ynode_describe(n));
    return false;
}

bool yr_opt_number(reader *r, const ynode *map, const char *key, double *out)
{
    const ynode *n = yr_get(r, map, key);
    return !n || yr_number(r, n, key, out);
}

bool yr_opt_integer(reader *r, const ynode *map, const char *key, long long lo, long long hi, long long *out)
{
    const ynode *n = yr_get(r, map, key);
    return !n || yr_integer(r, n, key, lo, hi, out);
}

bool yr_opt_bool(reader *r, const ynode *map, const char *key, bool *out)
{
    const ynode *n = yr_get(r, map, key);
    return !n || yr_bool(r, n, key, out);
}

bool yr_opt_vec3(reader *r, const ynode *map, const char *key, vec3 *out)
{
    const ynode *n = yr_get(r, map, key);
    return !n || yr_vec3(r, n, key, out);
}

bool yr_opt_color(reader *r, const ynode *map, const char *key, color *out)
{
    const ynode *n = yr_get(r, map, key);
    return !n || yr_color(r, n, key, out);
}

const ynode *yr_need(reader *r, const ynode *map, const char *key, const char *what)
{
    const ynode *n = yr_get(r, map, key);
    if (!n)
        diag_at(r->d, map, "%s needs '%s'", what, key);
    return n;
}
