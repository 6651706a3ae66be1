/* obj_corner.c - the face corners of OBJ text: an f statement's words
 * (v, v/vt, v//vn or v/vt/vn, negative indices counting back) read as
 * indices, checked against the items read before them, and joined, so
 * that each distinct (v, vt, vn) corner becomes one vertex of the mesh. */
#include <stdlib.h>
#include "core/array.h"
#include "model/obj_parse.h"

const char *const obj_part_name[3] = {"vertex", "texture coordinate", "normal"};
const char *const obj_part_names[3] = {"vertices", "texture coordinates", "normals"};

/* Reads [+-]digits at *p, before end, moving past them; a value too large
 * for any file saturates. False when there are no digits. */
static bool parse_index(const char **p, const char *end, long long *out)
{
    const char *s = *p;
    bool negative = s < end && (*s == '-' || *s == '+') ? *s++ == '-' : false;
    const char *digits = s;
    uint64_t v = 0; /* wraps past 19 digits: replaced below */
    for (; s < end && (unsigned char)(*s - '0') < 10; s++)
        v = v * 10 + (uint64_t)(*s - '0');
    if (s == digits)
        return false;
    if (s - digits > 18)
        v = 1000000000000000000ULL;
    *out = negative ? -(long long)v : (long long)v;
    *p = s;
    return true;
}

/* The index `text` (len bytes at column `at`) of a part, made absolute
 * and checked against the `count` items read so far. */
static glint_status resolve(const scan_line *l, scan_pos at, const char *text, size_t len, long long index,
                            size_t count, obj_part what, int32_t *out, glint_error *err)
{
    if (index == 0)
        return scan_error(l, at, err, "%s index 0 is not valid (indices count from 1)", obj_part_name[what]);
    if (obj_absolute_index(index, count, out))
        return GLINT_OK;
    char q[32];
    scan_quote(text, len, q, sizeof q);
    return scan_error(l, at, err, "%s index %s is out of range (the file has %zu %s so far)", obj_part_name[what], q,
                      count, count == 1 ? obj_part_name[what] : obj_part_names[what]);
}

bool obj_scan_corner(scan_line *l, raw_corner *rc)
{
    const char *word = l->p, *p = word, *end = l->end;
    bool ok = true;
    rc->start[0] = rc->start[1] = rc->start[2] = NULL;
    for (int k = 0; k < 3 && ok && p < end; k++) {
        if (k > 0) {
            if (*p != '/')
                break;
            if (++p < end && k == 1 && *p == '/')
                continue; /* v//vn */
        }
        rc->start[k] = p;
        ok = parse_index(&p, end, &rc->index[k]);
        rc->stop[k] = p;
    }
    /* Parsed in place; the word's end is looked for only now. */
    bool whole = ok && scan_at_break(l, p);
    size_t len;
    l->p = p;
    if (!whole)
        scan_word(l, &len);
    rc->word = word;
    rc->len = (size_t)(l->p - word);
    rc->form = 0;
    for (int k = 0; k < 3; k++)
        rc->form |= (rc->start[k] != NULL) << k;
    return whole;
}

/* Reads a plain index at s, before end: an optional sign, then 1 to 9
 * digits, into *out; returns the byte after it, or NULL when there is none
 * such or it is 0. */
static inline const char *plain_index(const char *s, const char *end, int32_t *out)
{
    bool negative = s < end && *s == '-';
    s += s < end && (*s == '-' || *s == '+');
    const char *stop = end - s > 9 ? s + 9 : end;
    int32_t v = 0;
    for (unsigned d; s < stop && (d = (unsigned char)*s - '0') < 10; s++)
        v = v * 10 + (int32_t)d;
    if (v == 0 || (s == stop && s < end && scan_is_digit(*s)))
        return NULL; /* none, 0, or a tenth digit */
    *out = negative ? -v : v;
    return s;
}

long obj_scan_plain_face(scan_line *l, int32_t **raw, size_t *count, size_t *cap, unsigned *form)
{
    const char *p = l->p, *end = l->end;
    size_t first = *count;
    long n = 0;
    unsigned face_form = 0;
    for (; scan_plain_start(p = scan_skip_blanks(p, end), end); n++) {
        if (n + 1 >= MODEL_MAX_COUNT)
            return 0;
        if (!array_reserve((void **)raw, cap, first + 3 * (size_t)n + 3, sizeof **raw))
            return -1;
        int32_t *c = *raw + first + 3 * (size_t)n;
        unsigned f = 1u << PART_V;
        c[1] = c[2] = 0;
        if (!(p = plain_index(p, end, &c[0])))
            return 0;
        if (p < end && *p == '/') {
            if (++p < end && *p != '/') {
                f |= 1u << PART_VT;
                if (!(p = plain_index(p, end, &c[1])))
                    return 0;
            }
            /* v//vn, or v/vt/vn */
            if (!(f & 1u << PART_VT) || (p < end && *p == '/')) {
                if (p == end || *p != '/')
                    return 0;
                p++;
                f |= 1u << PART_VN;
                if (!(p = plain_index(p, end, &c[2])))
                    return 0;
            }
        }
        if (!scan_plain_stop(p, end) || (n > 0 && f != face_form))
            return 0;
        face_form = f;
    }
    if (n < 3)
        return 0;
    *count = first + 3 * (size_t)n;
    *form = face_form;
    l->p = p;
    return n;
}

glint_status obj_read_corner(obj_parser *r, scan_line *l, scan_pos at, obj_corner *c, unsigned *form,
                             const char **word_out, size_t *len_out, glint_error *err)
{
    raw_corner rc;
    bool whole = obj_scan_corner(l, &rc);
    *word_out = rc.word;
    *len_out = rc.len;
    if (!whole) {
        char q[32];
        scan_quote(rc.word, rc.len, q, sizeof q);
        return scan_error(l, at, err, "'%s' is not a face corner (v, v/vt, v//vn or v/vt/vn)", q);
    }
    const obj_model *m = r->m;
    int32_t *out[3] = {&c->v, &c->vt, &c->vn};
    *c = (obj_corner){-1, -1, -1};
    *form = rc.form;
    for (int k = 0; k < 3; k++) {
        if (!rc.start[k])
            continue;
        scan_pos here = {at.line, at.column + (long)(rc.start[k] - rc.word)};
        glint_status s = resolve(l, here, rc.start[k], (size_t)(rc.stop[k] - rc.start[k]), rc.index[k],
                                 obj_item_count(m, (obj_part)k), (obj_part)k, out[k], err);
        if (s)
            return s;
    }
    return GLINT_OK;
}

/* An index of a corner relative to its v: the same along a run of corners
 * when texture coordinates or normals are numbered like the vertices. */
static uint32_t relative(int32_t index, int32_t v)
{
    return index < 0 ? UINT32_MAX : (uint32_t)index - (uint32_t)v;
}

/* The hash of a corner. Corners of neighbouring faces name nearby
 * vertices, so the low bits of v are kept as the slot's low bits and the
 * rest hashed with vt and vn relative to v: runs of eight vertices then
 * share a line of the table in the cache, where random slots would miss
 * it on nearly every corner of a large file. */
static uint32_t corner_key_hash(const obj_corner *c)
{
    uint32_t w[3] = {(uint32_t)c->v >> 3, relative(c->vt, c->v), relative(c->vn, c->v)};
    return (id_hash_words(w, 3) & ~7u) | ((uint32_t)c->v & 7);
}

static bool corner_equal(const void *keys, uint32_t id, const void *key)
{
    const obj_corner *a = (const obj_corner *)keys + id, *b = key;
    return a->v == b->v && a->vt == b->vt && a->vn == b->vn;
}

/* The id of a new corner c. */
static glint_status corner_new(obj_parser *r, const scan_line *l, scan_pos at, const obj_corner *c, uint32_t *id,
                               glint_error *err)
{
    obj_model *m = r->m;
    if (m->corner_count >= MODEL_MAX_COUNT)
        return obj_too_many(l, at, "vertices", err);
    if (!array_reserve((void **)&m->corners, &m->corner_cap, m->corner_count + 1, sizeof *m->corners))
        return obj_out_of_memory(r, err);
    *id = (uint32_t)m->corner_count;
    m->corners[m->corner_count++] = *c;
    return GLINT_OK;
}

/* The id of corner c, entering it when it is new. Most files number a
 * corner's texture coordinate and normal the same way against its vertex
 * throughout (the same index, or none): corners related to their vertex
 * as the first corner read was are found by vertex in an array, the rest
 * by hashing. Ids go in the order corners first appear either way. */
glint_status obj_corner_id(obj_parser *r, const scan_line *l, scan_pos at, const obj_corner *c, uint32_t *id,
                           glint_error *err)
{
    obj_model *m = r->m;
    int64_t vt = obj_part_offset(c->vt, c->v), vn = obj_part_offset(c->vn, c->v);
    if (!r->related) {
        r->relation[0] = vt;
        r->relation[1] = vn;
        r->related = true;
    }
    if (vt == r->relation[0] && vn == r->relation[1]) {
        /* Vertices may still come after faces: room for all read so far. */
        if ((size_t)c->v >= r->by_vertex_len) {
            if (!array_reserve((void **)&r->by_vertex, &r->by_vertex_cap, m->position_count, sizeof *r->by_vertex))
                return obj_out_of_memory(r, err);
            for (size_t i = r->by_vertex_len; i < m->position_count; i++)
                r->by_vertex[i] = UINT32_MAX;
            r->by_vertex_len = m->position_count;
        }
        uint32_t *known = &r->by_vertex[c->v];
        if (*known != UINT32_MAX) {
            *id = *known;
            return GLINT_OK;
        }
        glint_status s = corner_new(r, l, at, c, id, err);
        if (!s)
            *known = *id;
        return s;
    }
    /* Sized from the vertices read so far: most files give them all first. */
    if (!r->corner_index.slots &&
        !id_table_reserve(&r->corner_index, m->position_count))
        return obj_out_of_memory(r, err);
    if (id_table_find(&r->corner_index, corner_key_hash(c), c, corner_equal, m->corners, id))
        return GLINT_OK;
    glint_status s = corner_new(r, l, at, c, id, err);
    if (!s && !id_table_add(&r->corner_index, corner_key_hash(c), *id))
        s = obj_out_of_memory(r, err);
    return s;
}

