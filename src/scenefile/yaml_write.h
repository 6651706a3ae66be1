/* yaml_write.h - writing scene-file values as YAML text that the scene
 * loader reads back to the same bits: numbers in their shortest exact
 * form, colours as display values where one gives the colour exactly,
 * text quoted where YAML would misread it, and any kind's keys through its
 * parameter table. write_scene.c writes whole scenes with them. */
#ifndef GLINT_SCENEFILE_YAML_WRITE_H
#define GLINT_SCENEFILE_YAML_WRITE_H

#include <stdbool.h>
#include <stdio.h>
#include "core/params.h"

/* A map being written: in flow style, {a: 1, b: 2} on one line, or in
 * block style, a key a line at `indent` spaces (the first key goes where
 * the text stands, after "- " or "key:\n" and its indent). */
typedef struct ymap {
    FILE *f;
    bool flow;
    int indent;
    int count;                /* keys written so far */
} ymap;

/* Starts a map at the current position of f. */
ymap ymap_begin(FILE *f, bool flow, int indent);

/* Writes the next key and ": "; its value follows. */
void ymap_key(ymap *m, const char *key);

/* Writes the next key and ":", for a value in block style that the caller
 * starts on the next line (a map in block style only). */
void ymap_key_block(ymap *m, const char *key);

/* Ends the map: "}" (or "{}") in flow style, a newline in block style. */
void ymap_end(ymap *m);

/* A number in the shortest form that strtod reads back to the same bits. */
void yw_number(FILE *f, double v);
/* A float as few digits as read back, through a double, to it. */
void yw_float(FILE *f, float v);

/* A vector as [x, y, z]. */
void yw_vec3(FILE *f, glint_vec3 v);

/* A linear colour as display values [r, g, b] when each channel has one
 * that the loader's conversion turns into exactly that channel, else as
 * {linear: [r, g, b]}. */
void yw_color(FILE *f, glint_color c);

/* Text: plain where YAML reads it back as the same text, else in double
 * quotes with escapes. */
void yw_text(FILE *f, const char *s);

/* The value of parameter p in obj. */
void yw_param(FILE *f, const param *p, const void *obj);

/* Writes each parameter of t (as key: value into m) whose value is not its
 * default, or with `all` every one. */
void yw_params(ymap *m, param_table t, const void *obj, bool all);

#endif
