/* json_scan.h - reading a glTF's JSON a value at a time, for the checks
 * and readers that look at it before Assimp does (gltf_nodes.c,
 * gltf_emissive.c). The scan is lenient: JSON it cannot follow stops it,
 * and is left to Assimp's parser, which refuses it; what valid JSON holds
 * it reads as that parser does (the first of two equal keys, escapes
 * decoded through json_char.h), never recursing however deep the nesting. */
#ifndef GLINT_MODEL_JSON_SCAN_H
#define GLINT_MODEL_JSON_SCAN_H

#include <stdbool.h>
#include <stddef.h>
#include <stdint.h>

/* Where the scan is in the JSON text. */
typedef struct json_scan {
    const unsigned char *t;
    size_t size, i;
    bool nomem;               /* memory ran out (the scan stops as for broken JSON) */
} json_scan;

/* What json_read_index gives for a value that is not an unsigned integer
 * (Assimp skips it, or refuses the file), or for one too large for any
 * index. */
#define JSON_NO_INDEX ((1ULL << 63) - 1)

/* Moves past blanks. */
void json_skip_space(json_scan *r);

/* True, the scan past it, when `c` comes next. */
bool json_take(json_scan *r, unsigned char c);

/* Decodes the string at the scan into key (its first size - 1
 * characters; a longer one is cut to size - 1 and marked with a final
 * 0x01, so that it equals no short key). False at a broken string. */
bool json_read_string(json_scan *r, char *key, size_t size);

/* Skips one value of any kind; nesting is counted, never recursed into. */
bool json_skip_value(json_scan *r);

/* Moves to the next item of an array or object whose opening bracket has
 * been read: 1 when one follows (the scan at it), 0 past the closing
 * bracket, -1 at broken JSON. *first is true before the first item. */
int json_next_item(json_scan *r, bool *first, unsigned char close);

/* json_next_item for an object, its key decoded into key and the scan at
 * its value. */
int json_next_member(json_scan *r, bool *first, char *key, size_t size);

/* Reads one value into *v: its number when it is an unsigned integer
 * (as Assimp's parser takes "-0" for 0), JSON_NO_INDEX when it is anything
 * else or more than JSON_NO_INDEX. False at broken JSON. */
bool json_read_index(json_scan *r, uint64_t *v);

/* Reads one value; when it is a number (JSON's form: an optional '-',
 * digits, an optional fraction and exponent), sets *is_number and *v to
 * the nearest double, infinite when it is too large for one. False at
 * broken JSON. */
bool json_read_number(json_scan *r, bool *is_number, double *v);

/* Calls on(r, ctx, key) for a member of the object at the scan, the scan
 * at its value, which on must read, when its key is one of the
 * `key_count` (at most 32) keys; the first of two equal keys is the one
 * JSON parsers keep, so each key is handed over once. Other members are
 * skipped, and so is a value that is not an object. */
typedef bool (*json_member_fn)(json_scan *r, void *ctx, const char *key);
bool json_each_member(json_scan *r, void *ctx, json_member_fn on, const char *const *keys, int key_count);

/* Calls on(r, ctx) for each item of the array at the scan, which on must
 * read; a value that is not an array is skipped. */
typedef bool (*json_item_fn)(json_scan *r, void *ctx);
bool json_each_item(json_scan *r, void *ctx, json_item_fn on);

#endif
