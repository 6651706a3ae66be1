/* obj_parse.h - the inside of glint's OBJ reader (obj_read.h), shared by
 * its files: the parser's state, the face corners of obj_corner.c and the
 * statements of obj_statement.c. Each statement of a logical line goes
 * into the model as it is read; obj_ahead.c parses lines ahead in threads
 * and hands them to the same functions in the file's order, so that the
 * model and every message are those of one pass. */
#ifndef GLINT_MODEL_OBJ_PARSE_H
#define GLINT_MODEL_OBJ_PARSE_H

#include <stdbool.h>
#include <stddef.h>
#include <stdint.h>
#include "core/error.h"
#include "glint.h"
#include "core/id_table.h"
#include "model/model_build.h"
#include "model/obj_read.h"
#include "model/text_scan.h"
#include "model/triangulate.h"

/* What reading needs besides the model. */
typedef struct obj_parser {
    obj_model *m;
    const char *file;
    long line;                /* number of the next line */
    int32_t material;         /* the usemtl in force, or -1 */
    id_table corner_index;    /* corner ids by (v, vt, vn), but for those below */
    uint32_t *by_vertex;      /* ids of corners in `relation` by their v; UINT32_MAX for none yet */
    size_t by_vertex_len, by_vertex_cap;
    int64_t relation[2];      /* vt - v and vn - v of the first corner read (INT64_MIN for none) */
    bool related;             /* relation is set */
    id_table name_index;      /* usemtl names by text */
    uint32_t *face;           /* the corner ids of the face being read */
    uint32_t *face_at;        /* and their positions */
    size_t face_cap;
    int32_t *raw;             /* a plain face's indices as written (obj_scan_plain_face) */
    size_t raw_cap;
    obj_corner *resolved;     /* a face's corners resolved before any is entered (obj_raw_face) */
    size_t resolved_cap;
    uint32_t *split;          /* its triangles as corner numbers */
    size_t split_cap;
    triangulate_work work;
    int threads;              /* threads that parse ahead (obj_ahead.c), 1 for none */
    size_t piece_min;         /* the least text worth a thread */
} obj_parser;

/* What a face corner names: a part of the vertex data. */
typedef enum obj_part {
    PART_V,
    PART_VT,
    PART_VN
} obj_part;

/* The nouns of each part, one and many, for messages. */
extern const char *const obj_part_name[3], *const obj_part_names[3];

/* The statements glint reads; KEY_OTHER for every other word. */
typedef enum obj_keyword {
    KEY_V,
    KEY_VT,
    KEY_VN,
    KEY_F,
    KEY_USEMTL,
    KEY_MTLLIB,
    KEY_OTHER
} obj_keyword;

/* The message of memory running out while reading. */
static inline glint_status obj_out_of_memory(const obj_parser *r, glint_error *err)
{
    return error_set(err, GLINT_ERR_NOMEM, "%s: out of memory", r->file);
}

/* The message of a count passing glint's mesh limit, at `at`. */
static inline glint_status obj_too_many(const scan_line *l, scan_pos at, const char *what, glint_error *err)
{
    return scan_error(l, at, err, "too many %s (more than %lld)", what, MODEL_MAX_COUNT);
}

/* The number of items of part `what` read so far. */
static inline size_t obj_item_count(const obj_model *m, obj_part what)
{
    return what == PART_V ? m->position_count : what == PART_VT ? m->uv_count : m->normal_count;
}

/* ---------------------------------------------------- obj_corner.c */

/* A face corner as written: the text of each index it has (start[k] NULL
 * for a part it lacks) and their values. */
typedef struct raw_corner {
    const char *word;         /* the whole word, len bytes */
    size_t len;
    const char *start[3], *stop[3];
    long long index[3];
    unsigned form;            /* the parts it has, a bit each */
} raw_corner;

/* Reads the word at l->p as a face corner into *rc, moving past it; false
 * when the word is not a face corner. Touches nothing but rc, so threads
 * parsing ahead may call it. */
bool obj_scan_corner(scan_line *l, raw_corner *rc);

/* Reads the rest of line l as a plain face, the form nearly every file
 * writes: at least 3 corners of one form, each index an optional sign and
 * 1 to 9 digits but not 0, with blanks between them. Appends their indices
 * as written to (*raw)[*count ...], 3 per corner and 0 for a part a corner
 * lacks, growing *raw (room *cap) with array_reserve; sets *form, moves to
 * the line's end and returns the corners' count. Returns 0, with l and
 * *count unchanged, for any other line (which obj_scan_corner then reads
 * corner by corner), and -1 when memory runs out. A line break ends the
 * line too, as for scan_plain_numbers. Touches nothing but its arguments,
 * so threads parsing ahead may call it. */
long obj_scan_plain_face(scan_line *l, int32_t **raw, size_t *count, size_t *cap, unsigned *form);

/* An index as written made absolute among the `count` items read so far:
 * false when it names none of them. (Inline: every corner of a large file
 * parsed ahead passes here.) */
static inline bool obj_absolute_index(long long index, size_t count, int32_t *out)
{
    long long i = index > 0 ? index - 1 : (long long)count + index;
    if (index == 0 || i < 0 || i >= (long long)count)
        return false;
    *out = (int32_t)i;
    return true;
}

/* Reads one face corner, the word at l->p (at place `at`), moving past
 * it: its indices into *c (-1 for parts it lacks), its form as a bit set of
 * parts, and where it is (*word, *len) for messages. Indices must name
 * items read before them. */
glint_status obj_read_corner(obj_parser *r, scan_line *l, scan_pos at, obj_corner *c, unsigned *form,
                             const char **word, size_t *len, glint_error *err);

/* The id of corner c in the model's distinct corners, entering it when it
 * is new; `at` places the message when that passes the limit. */
glint_status obj_corner_id(obj_parser *r, const scan_line *l, scan_pos at, const obj_corner *c, uint32_t *id,
                           glint_error *err);

/* The difference of a corner's index of a part from its vertex index, or
 * INT64_MIN when it lacks the part. */
static inline int64_t obj_part_offset(int32_t index, int32_t v)
{
    return index < 0 ? INT64_MIN : (int64_t)index - v;
}

/* obj_corner_id's quick case, inline, as nearly every corner of a large
 * file is one: the id of a corner already entered that is related to its
 * vertex as the first corner read was. False when obj_corner_id is to find
 * the id. */
static inline bool obj_corner_known(const obj_parser *r, const obj_corner *c, uint32_t *id)
{
    if ((size_t)c->v >= r->by_vertex_len || r->by_vertex[c->v] == UINT32_MAX ||
        obj_part_offset(c->vt, c->v) != r->relation[0] || obj_part_offset(c->vn, c->v) != r->relation[1])
        return false;
    *id = r->by_vertex[c->v];
    return true;
}

/* ------------------------------------------------- obj_statement.c */

/* The statement the word [w, w + n) starts. (Inline: it is asked of every
 * line.) */
static inline obj_keyword obj_keyword_of(const char *w, size_t n)
{
    if (n == 1 && w[0] == 'v')
        return KEY_V;
    if (n == 1 && w[0] == 'f')
        return KEY_F;
    if (n == 2 && w[0] == 'v' && w[1] == 'n')
        return KEY_VN;
    if (n == 2 && w[0] == 'v' && w[1] == 't')
        return KEY_VT;
    if (scan_word_is(w, n, "usemtl"))
        return KEY_USEMTL;
    if (scan_word_is(w, n, "mtllib"))
        return KEY_MTLLIB;
    return KEY_OTHER;
}

/* The part a v, vt or vn statement adds. */
static inline obj_part obj_item_part(obj_keyword k)
{
    return k == KEY_V ? PART_V : k == KEY_VT ? PART_VT : PART_VN;
}

/* Reads the rest of l as the plain numbers (scan_plain_numbers) of a v, vt
 * or vn statement (`what`) into item, as obj_parse_item would; false, l
 * unchanged, for any other text. Touches nothing but l and item. */
bool obj_plain_item(scan_line *l, obj_part what, float item[3]);

/* Reads the numbers of a v, vt or vn statement (`what`), whose keyword is
 * at `at`, as the item it adds: x y z, u and glint's v, or x y z. Touches
 * nothing but item, so threads parsing ahead may call it. */
glint_status obj_parse_item(scan_line *l, scan_pos at, obj_part what, float item[3], glint_error *err);

/* Appends an item of part `what` to the model's positions, uvs or normals;
 * false when memory runs out. The count is below MODEL_MAX_COUNT. */
bool obj_add_item(obj_model *m, obj_part what, const float item[3]);

/* Enters the face of n corners of form `form` read on l at `at`, whose
 * indices as written are raw[3k], raw[3k + 1], raw[3k + 2] (0 for a part a
 * corner lacks; obj_scan_plain_face). False, with nothing changed, when an
 * index names no item read so far or the face could pass a limit: the line
 * is then to be read corner by corner, for its message. Otherwise true,
 * with *s the outcome (which fails only for memory). */
bool obj_raw_face(obj_parser *r, const scan_line *l, scan_pos at, const int32_t *raw, size_t n, unsigned form,
                  glint_status *s, glint_error *err);

/* Room for n corners in r->face and r->face_at. */
bool obj_face_room(obj_parser *r, size_t n);

/* Adds the triangles of the face of n corners of form `form` whose ids are
 * in r->face (and their vertices in r->face_at), read at `at`. */
glint_status obj_add_face(obj_parser *r, const scan_line *l, scan_pos at, size_t n, unsigned form,
                          glint_error *err);

/* Reads the statement of logical line l into the model. */
glint_status obj_statement(obj_parser *r, scan_line *l, glint_error *err);

/* Reads every whole line in [data, data + size), and with `last` the rest
 * too; *used is how far it got. */
glint_status obj_feed(obj_parser *r, const char *data, size_t size, bool last, size_t *used, glint_error *err);

#endif
