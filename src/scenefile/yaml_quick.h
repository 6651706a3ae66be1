/* yaml_quick.h - a fast reader for the plain YAML that scene files are
 * written in, giving the events libyaml would give for it. libyaml spends
 * some 4 s on a generated scene of a million objects; this reads the same
 * text in a small fraction of that. For any text outside its subset it says
 * so, and libyaml reads the file instead, with libyaml's messages. */
#ifndef GLINT_SCENEFILE_YAML_QUICK_H
#define GLINT_SCENEFILE_YAML_QUICK_H

#include <stddef.h>
#include <yaml.h>

/* Takes one event; returns 0 to go on, anything else to stop with it. */
typedef int (*yaml_quick_sink)(void *user, const yaml_event_t *event);

/* The subset: one document of block maps and lists; flow maps and lists,
 * over lines or not, whose keys are plain words; plain scalars on one line;
 * quoted scalars on one line without escapes; comments; printable ASCII with spaces for indentation.
 * Not in it: anchors, aliases, tags, block scalars, empty values, keys that
 * are not plain words, document markers, tabs, carriage returns, text
 * outside ASCII, and every syntax error.
 *
 * Reads `size` bytes of data and gives each event to sink (NULL: none, a
 * dry run) exactly as libyaml's yaml_parser_parse would give them for the
 * same text: the same types, values, styles and start marks (scalar values
 * point into data and are not NUL-terminated). Returns 0 when the whole
 * text is within the subset and every event was given, -1 when it is not
 * within it (some events may have been given: a dry run first tells), or
 * the sink's nonzero return. */
int yaml_quick_parse(const char *data, size_t size, yaml_quick_sink sink, void *user);

#endif
