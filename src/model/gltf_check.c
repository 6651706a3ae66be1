/* gltf_check.c - the checks a glTF or GLB model passes before Assimp reads
 * it. Assimp picks its reader by extension, but falls back to sniffing the
 * content with every reader it has when none claims the file: a glTF must
 * start as JSON and a GLB with its magic. A GLB's chunks must fit in the
 * file, as Assimp allocates whatever length they claim. And Assimp's glTF
 * 2 reader takes the part of an embedded image's media type after its '/'
 * without looking for one, so an image whose mimeType is "imagepng", or
 * whose data URI is "data:imagepng;base64,...", makes it read from address
 * 1 (fuzzing found it): every mimeType and every data URI's media type must
 * have its '/'. That scan decodes JSON strings as a JSON parser does,
 * escapes included, so "mime\u0054ype" is still seen as the key mimeType.
 * The node hierarchy is counted before Assimp expands it (gltf_nodes.c). */
#include <ctype.h>
#include <limits.h>
#include <stdint.h>
#include <stdio.h>
#include <string.h>
#include "core/error.h"
#include "model/assimp_check.h"
#include "model/json_char.h"

/* What one decoded JSON string holds, as far as the check needs it. */
typedef struct json_string {
    size_t start;             /* offset of its opening quote */
    char head[48];            /* its first characters, NUL-terminated; others as '?' */
    size_t length;            /* in decoded characters */
    bool slash;               /* a '/' anywhere */
    size_t media_end;         /* for a "data:" URI: where its media type ends */
    bool media_slash;         /* a '/' in that media type */
} json_string;

/* Decodes the string whose opening quote is at text[*i]; *i ends past its
 * closing quote. False when the text ends first. */
static bool read_string(const unsigned char *text, size_t size, size_t *i, json_string *s)
{
    memset(s, 0, sizeof *s);
    s->start = (*i)++;
    int c;
    while ((c = json_next_char(text, size, i)) >= 0) {
        if (s->length < sizeof s->head - 1)
            s->head[s->length] = c >= 0x20 && c < 0x7F ? (char)c : '?';
        s->length++;
        s->slash |= c == '/';
        bool data_uri = s->length > 5 && strncmp(s->head, "data:", 5) == 0;
        if (data_uri && s->media_end == 0) {
            if (c == ';' || c == ',')
                s->media_end = s->length - 1;
            else
                s->media_slash |= c == '/';
        }
    }
    /* A data URI with neither ';' nor ',' is all media type. */
    if (s->length > 5 && strncmp(s->head, "data:", 5) == 0 && s->media_end == 0)
        s->media_end = s->length;
    return c == -1;
}

/* line:column of offset `at` in text, from 1. */
static void position_of(const unsigned char *text, size_t at, int *line, int *column)
{
    *line = *column = 1;
    for (size_t k = 0; k < at; k++) {
        if (text[k] == '\n') {
            (*line)++;
            *column = 1;
        } else {
            (*column)++;
        }
    }
}

/* Refuses string s, naming `what` and its characters from `from` to `to`. */
static glint_status refuse(const unsigned char *text, const json_string *s, const char *where, const char *what,
                           size_t from, size_t to, glint_error *err)
{
    int line, column;
    position_of(text, s->start, &line, &column);
    if (to > sizeof s->head - 1)
        to = sizeof s->head - 1;
    return error_set(err, GLINT_ERR_INVALID, "%s%d:%d: %s '%.*s' has no '/' (as in image/png)", where, line,
                     column, what, (int)(to - from), s->head + from);
}

/* Refuses glTF JSON text (size bytes) in which an image's mimeType, or a
 * data URI's media type, has no '/'. Messages start with `where` and then
 * "line:column: ", the position in the text. */
static glint_status check_media_types(const unsigned char *text, size_t size, const char *where, glint_error *err)
{
    bool after_mime = false, after_uri = false; /* the last key, when its value comes next */
    size_t i = 0;
    while (i < size) {
        unsigned char c = text[i];
        if (c != '"') {
            if (c != ' ' && c != '\t' && c != '\n' && c != '\r' && c != ':')
                after_mime = after_uri = false;
            i++;
            continue;
        }
        json_string s;
        if (!read_string(text, size, &i, &s))
            return GLINT_OK; /* broken JSON: Assimp's parser refuses it */
        size_t k = i;
        while (k < size && (text[k] == ' ' || text[k] == '\t' || text[k] == '\n' || text[k] == '\r'))
            k++;
        if (k < size && text[k] == ':') {
            after_mime = s.length == 8 && strcmp(s.head, "mimeType") == 0;
            after_uri = s.length == 3 && strcmp(s.head, "uri") == 0;
            i = k + 1;
            continue;
        }
        if (after_mime && s.length > 0 && !s.slash)
            return refuse(text, &s, where, "image mimeType", 0, s.length, err);
        if (after_uri && s.media_end > 5 && !s.media_slash)
            return refuse(text, &s, where, "data URI media type", 5, s.media_end, err);
        after_mime = after_uri = false;
    }
    return GLINT_OK;
}

glint_status gltf_check(const unsigned char *data, size_t size, const char *file, glint_error *err)
{
    size_t i = size >= 3 && memcmp(data, "\xEF\xBB\xBF", 3) == 0 ? 3 : 0;
    while (i < size && isspace(data[i]))
        i++;
    if (i == size || data[i] != '{')
        return error_set(err, GLINT_ERR_INVALID, "%s: not a glTF file (it does not start with a JSON object)", file);
    char where[PATH_MAX + 2];
    snprintf(where, sizeof where, "%s:", file);
    glint_status s = check_media_types(data, size, where, err);
    return s ? s : gltf_check_nodes(data, size, file, err);
}

/* The little-endian 32-bit number at p: a GLB's lengths. */
static uint32_t le32(const unsigned char *p)
{
    return (uint32_t)p[0] | (uint32_t)p[1] << 8 | (uint32_t)p[2] << 16 | (uint32_t)p[3] << 24;
}

/* The JSON chunk, and the binary chunk when the file has one, must fit in
 * the file (fuzzing found a 2 GB one). */
glint_status glb_check(const unsigned char *data, size_t size, const char *file, glint_error *err)
{
    if (size < 4 || memcmp(data, "glTF", 4) != 0)
        return error_set(err, GLINT_ERR_INVALID, "%s: not a binary glTF file (it does not start with 'glTF')", file);
    size_t pos = 12;
    for (int chunk = 0; chunk < 2 && pos <= size && size - pos >= 8; chunk++) {
        unsigned long long length = le32(data + pos);
        if (length > size - pos - 8)
            return error_set(err, GLINT_ERR_INVALID,
                             "%s: GLB chunk %d claims %llu bytes, more than the file's %zu after it", file, chunk,
                             length, size - pos - 8);
        pos += 8 + (size_t)(length + 3) / 4 * 4;
    }
    const unsigned char *json;
    size_t json_size;
    if (!glb_json(data, size, &json, &json_size))
        return GLINT_OK;
    /* Positions in messages are within the JSON chunk. */
    char where[PATH_MAX + 32];
    snprintf(where, sizeof where, "%s: JSON chunk ", file);
    glint_status s = check_media_types(json, json_size, where, err);
    return s ? s : gltf_check_nodes(json, json_size, file, err);
}

bool glb_json(const unsigned char *data, size_t size, const unsigned char **json, size_t *json_size)
{
    if (size < 20)
        return false;
    *json = data + 20;
    *json_size = le32(data + 12);
    return true;
}
