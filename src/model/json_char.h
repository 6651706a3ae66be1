/* json_char.h - the characters of a JSON string as a JSON parser decodes
 * them, escapes included, for the checks and readers that read a glTF's
 * JSON before Assimp does (gltf_check.c, json_scan.c): a key written
 * "nod\u0065s" is still the key nodes to Assimp, so it must be to them. */
#ifndef GLINT_MODEL_JSON_CHAR_H
#define GLINT_MODEL_JSON_CHAR_H

#include <stddef.h>

/* The next decoded character of the string at text[*i] (after its opening
 * quote), *i moved past it: an ASCII character, or 0x80 for anything else;
 * -1 at its closing quote, -2 at the end of the text or a broken escape. */
int json_next_char(const unsigned char *text, size_t size, size_t *i);

#endif
