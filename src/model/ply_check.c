/* ply_check.c - the check a PLY model passes in full, header and data,
 * before Assimp parses it: Assimp's PLY reader allocates whatever element
 * counts the header claims, and goes astray (heap corruption, endless
 * loops) on headers and data that do not follow the format (fuzzing found
 * all three). The grammar accepted is docs/meshes.md's. */
#include <ctype.h>
#include <limits.h>
#include <stdlib.h>
#include <string.h>
#include "core/error.h"
#include "model/assimp_check.h"

#define PLY_MAX_WORDS 6
#define PLY_MAX_ELEMENTS 64
#define PLY_MAX_PROPERTIES 64

/* A header line split into words, each cut to fit; n counts them all.
 * `control` is set when the line holds a control character other than a
 * tab, or a carriage return just before its newline: Assimp ends lines at
 * some of them (form feed, NUL) where this check would not, and the two
 * would then read different headers. */
typedef struct line_words {
    char w[PLY_MAX_WORDS][40];
    int n;
    bool control;
} line_words;

static bool is_blank(unsigned char c)
{
    return c == ' ' || c == '\t';
}

/* Splits the line at data[*pos...] into words at spaces and tabs and moves
 * *pos past it. */
static void next_line(const unsigned char *data, size_t size, size_t *pos, line_words *lw)
{
    memset(lw, 0, sizeof *lw);
    size_t i = *pos;
    for (size_t k = i; k < size && data[k] != '\n'; k++) {
        bool crlf = data[k] == '\r' && k + 1 < size && data[k + 1] == '\n';
        if ((data[k] < 0x20 && !is_blank(data[k]) && !crlf) || data[k] == 0x7f)
            lw->control = true;
    }
    while (i < size && data[i] != '\n') {
        while (i < size && data[i] != '\n' && (is_blank(data[i]) || data[i] == '\r'))
            i++;
        if (i >= size || data[i] == '\n')
            break;
        size_t len = 0;
        while (i < size && data[i] != '\n' && !is_blank(data[i]) && data[i] != '\r') {
            if (lw->n < PLY_MAX_WORDS && len + 1 < sizeof lw->w[0])
                lw->w[lw->n][len++] = isprint(data[i]) ? (char)data[i] : '?';
            i++;
        }
        lw->n++;
    }
    *pos = i < size ? i + 1 : size;
}

/* Bytes one value of a PLY scalar type takes in a binary file, 0 for an
 * unknown type; *integer tells whether it may count a list. */
static unsigned ply_type_size(const char *type, bool *integer)
{
    static const struct {
        const char *name;
        unsigned size;
        bool integer;
    } types[] = {
        {"char", 1, true}, {"uchar", 1, true}, {"int8", 1, true}, {"uint8", 1, true},
        {"short", 2, true}, {"ushort", 2, true}, {"int16", 2, true}, {"uint16", 2, true},
        {"int", 4, true}, {"uint", 4, true}, {"int32", 4, true}, {"uint32", 4, true},
        {"float", 4, false}, {"float32", 4, false}, {"double", 8, false}, {"float64", 8, false},
    };
    for (size_t i = 0; i < sizeof types / sizeof types[0]; i++)
        if (strcmp(type, types[i].name) == 0) {
            *integer = types[i].integer;
            return types[i].size;
        }
    return 0;
}

/* A decimal count of digits only, ULLONG_MAX when it overflows; false when
 * it is not one. */
static bool parse_count(const char *s, unsigned long long *out)
{
    unsigned long long n = 0;
    if (!*s)
        return false;
    for (; *s; s++) {
        if (!isdigit((unsigned char)*s))
            return false;
        unsigned d = (unsigned)(*s - '0');
        n = n > (ULLONG_MAX - d) / 10 ? ULLONG_MAX : n * 10 + d;
    }
    *out = n;
    return true;
}

typedef struct ply_property {
    unsigned count_size;      /* list: bytes of the length; 0 for a scalar */
    unsigned size;            /* bytes of the value, or of each list item */
    bool count_signed;
} ply_property;

typedef struct ply_element {
    char name[40];
    unsigned long long count;
    ply_property props[PLY_MAX_PROPERTIES];
    int prop_count;
} ply_element;

typedef struct ply_header {
    int format;               /* 0 ascii, 1 binary little-endian, 2 binary big-endian */
    ply_element elems[PLY_MAX_ELEMENTS];
    int elem_count;
    size_t body;              /* offset of the data */
} ply_header;

static glint_status header_error(const char *file, int line, glint_error *err)
{
    return error_set(err, GLINT_ERR_INVALID, "%s: PLY header line %d is not understood", file, line);
}

/* Reads a "property" line into the last element. */
static bool read_property(const line_words *lw, ply_header *h)
{
    if (h->elem_count == 0)
        return false;
    ply_element *e = &h->elems[h->elem_count - 1];
    if (e->prop_count == PLY_MAX_PROPERTIES)
        return false;
    ply_property *p = &e->props[e->prop_count];
    bool integer = false;
    if (lw->n == 3) {
        p->size = ply_type_size(lw->w[1], &integer);
        p->count_size = 0;
    } else if (lw->n == 5 && strcmp(lw->w[1], "list") == 0) {
        p->count_size = ply_type_size(lw->w[2], &integer);
        p->count_signed = lw->w[2][0] != 'u';
        if (!integer)
            return false;
        p->size = ply_type_size(lw->w[3], &integer);
    } else {
        return false;
    }
    if (p->size == 0 || p->count_size > 4)
        return false;
    e->prop_count++;
    return true;
}

/* Reads the header, line by line, accepting only the grammar of the PLY
 * format: Assimp's reader goes astray on anything else. */
static glint_status read_header(const unsigned char *data, size_t size, const char *file, ply_header *h,
                                glint_error *err)
{
    static const char *const format_names[] = {"ascii", "binary_little_endian", "binary_big_endian"};
    size_t pos = 0;
    line_words lw;
    h->format = -1;
    h->elem_count = 0;
    for (int line = 1; pos < size; line++) {
        next_line(data, size, &pos, &lw);
        const char *key = lw.w[0];
        bool ok = false;
        if (lw.control) {
            ok = false;
        } else if (line == 1) {
            ok = lw.n == 1 && strcmp(key, "ply") == 0;
        } else if (strcmp(key, "comment") == 0 || strcmp(key, "obj_info") == 0) {
            ok = true;
        } else if (strcmp(key, "format") == 0 && lw.n == 3 && h->format < 0 && strcmp(lw.w[2], "1.0") == 0) {
            for (int f = 0; f < 3; f++)
                if (strcmp(lw.w[1], format_names[f]) == 0)
                    h->format = f;
            ok = h->format >= 0;
        } else if (strcmp(key, "element") == 0 && lw.n == 3) {
            if (h->elem_count == PLY_MAX_ELEMENTS)
                return error_set(err, GLINT_ERR_INVALID, "%s: PLY header declares more than %d elements", file,
                                 PLY_MAX_ELEMENTS);
            ply_element *e = &h->elems[h->elem_count];
            ok = parse_count(lw.w[2], &e->count);
            memcpy(e->name, lw.w[1], sizeof e->name);
            e->prop_count = 0;
            h->elem_count += ok;
        } else if (strcmp(key, "property") == 0) {
            ok = read_property(&lw, h);
        } else if (strcmp(key, "end_header") == 0 && lw.n == 1 && h->format >= 0) {
            h->body = pos;
            return GLINT_OK;
        }
        if (!ok)
            return header_error(file, line, err);
    }
    /* Assimp's reader loops for ever on a header cut short. */
    return error_set(err, GLINT_ERR_INVALID, "%s: PLY header has no end_header line", file);
}

static glint_status data_error(const char *file, const ply_element *e, unsigned long long item, glint_error *err)
{
    return error_set(err, GLINT_ERR_INVALID, "%s: PLY data of element '%s' item %llu does not match the header",
                     file, e->name, item);
}

/* Reads an unsigned or signed little- or big-endian integer of n bytes. */
static long long read_int(const unsigned char *p, unsigned n, bool big, bool is_signed)
{
    unsigned long long v = 0;
    for (unsigned i = 0; i < n; i++)
        v |= (unsigned long long)p[big ? n - 1 - i : i] << (8 * i);
    if (is_signed && n < 8 && (v >> (8 * n - 1)) & 1)
        return (long long)v - (1LL << (8 * n));
    return (long long)v;
}

/* Walks every item of binary data, with each list's own length. */
static glint_status check_binary(const unsigned char *data, size_t size, const ply_header *h, const char *file,
                                 glint_error *err)
{
    size_t pos = h->body;
    for (int i = 0; i < h->elem_count; i++) {
        const ply_element *e = &h->elems[i];
        for (unsigned long long k = 0; k < e->count; k++)
            for (int j = 0; j < e->prop_count; j++) {
                const ply_property *p = &e->props[j];
                long long n = 1;
                if (p->count_size) {
                    if (size - pos < p->count_size)
                        return data_error(file, e, k, err);
                    n = read_int(data + pos, p->count_size, h->format == 2, p->count_signed);
                    pos += p->count_size;
                }
                if (n < 0 || (unsigned long long)n > (size - pos) / p->size)
                    return data_error(file, e, k, err);
                pos += (size_t)n * p->size;
            }
    }
    return GLINT_OK;
}

/* True for a token Assimp's number reader takes whole. */
static bool is_number(const unsigned char *t, size_t len)
{
    if (len == 0)
        return false;
    for (size_t i = 0; i < len; i++)
        if (!isdigit(t[i]) && !strchr("+-.eE", t[i]))
            return false;
    return true;
}

/* Walks every item of ASCII data: one line each, with a number for each
 * value and a list's length before its values. */
static glint_status check_ascii(const unsigned char *data, size_t size, const ply_header *h, const char *file,
                                glint_error *err)
{
    size_t pos = h->body;
    for (int i = 0; i < h->elem_count; i++) {
        const ply_element *e = &h->elems[i];
        for (unsigned long long k = 0; k < e->count; k++) {
            size_t end = pos;
            while (end < size && data[end] != '\n')
                end++;
            bool ok = true;
            int prop = 0;             /* the property the next token starts */
            long long left = 0;       /* values still due in the current list */
            for (size_t t = pos; ok && t < end;) {
                while (t < end && isspace(data[t]))
                    t++;
                if (t >= end)
                    break;
                size_t len = 0;
                while (t + len < end && !isspace(data[t + len]))
                    len++;
                ok = is_number(data + t, len);
                if (ok && left > 0) {
                    left--;
                } else if (ok && prop < e->prop_count) {
                    if (e->props[prop].count_size) {
                        unsigned long long n;
                        char buf[24];
                        ok = len < sizeof buf;
                        if (ok) {
                            memcpy(buf, data + t, len);
                            buf[len] = '\0';
                            ok = parse_count(buf, &n) && n <= (unsigned long long)(end - t) / 2;
                            left = (long long)n;
                        }
                    }
                    prop++;
                } else {
                    ok = false;
                }
                t += len;
            }
            if (!ok || prop != e->prop_count || left != 0)
                return data_error(file, e, k, err);
            pos = end < size ? end + 1 : size;
        }
    }
    return GLINT_OK;
}

/* The header's grammar first, then that no element claims more items than
 * the data can hold (before walking them), then that the data matches it. */
glint_status ply_check(const unsigned char *data, size_t size, const char *file, glint_error *err)
{
    ply_header *h = malloc(sizeof *h);
    if (!h)
        return error_set(err, GLINT_ERR_NOMEM, "%s: out of memory", file);
    glint_status s = read_header(data, size, file, h, err);
    size_t body = s ? 0 : size - h->body;
    for (int i = 0; !s && i < h->elem_count; i++) {
        const ply_element *e = &h->elems[i];
        unsigned long long least = 0;
        for (int j = 0; j < e->prop_count; j++)
            least += h->format ? (e->props[j].count_size ? e->props[j].count_size : e->props[j].size) : 2;
        if (least == 0)
            least = 1;
        if (e->count > body / least)
            s = error_set(err, GLINT_ERR_INVALID,
                          "%s: PLY element '%s' claims %llu items, more than the file's %zu bytes of data can hold",
                          file, e->name, e->count, body);
    }
    if (!s)
        s = h->format ? check_binary(data, size, h, file, err) : check_ascii(data, size, h, file, err);
    free(h);
    return s;
}
