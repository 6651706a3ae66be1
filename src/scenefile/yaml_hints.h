/* yaml_hints.h - plain words for the YAML mistakes a new user makes, found
 * in the source text where libyaml's own message would puzzle: a colour
 * written #0000ff without quotes (a comment in YAML) and a tab used for
 * indentation. */
#ifndef GLINT_SCENEFILE_YAML_HINTS_H
#define GLINT_SCENEFILE_YAML_HINTS_H

#include <stdbool.h>
#include <stddef.h>

/* When the bytes of data from `at` are spaces or tabs, then a '#' that
 * begins a colour (3 to 8 hex digits: "#0000ff") on the same line, writes
 * "'#' starts a comment in YAML: write the colour in quotes, KEY: \"#0000ff\""
 * into msg, KEY being the key written before it ("color: #0000ff"), if
 * any; returns the offset of that '#' from `at`, or -1. */
long yaml_hidden_colour(const char *data, size_t size, size_t at, char *msg, size_t msg_size);

/* The same for the first such colour in a comment between data[from] and
 * data[to], outside quotes: inside a flow collection ({...} or [...]), a
 * comment hides the rest of its line, brackets included, and libyaml
 * stumbles on a later line. Returns the offset of the '#' from `from`. */
long yaml_hidden_colour_between(const char *data, size_t from, size_t to, char *msg, size_t msg_size);

/* Moves a position (0-based line and column, libyaml's: a column counts
 * characters) from data[from] to data[to]. */
void yaml_advance(const char *data, size_t from, size_t to, size_t *line, size_t *column);

/* Whether data[at] is a tab in its line's indentation (only spaces and
 * tabs before it). */
bool yaml_tab_indent(const char *data, size_t size, size_t at);

#endif
