/* obj_read.c - the statements of OBJ text, read line by line.
 *
 * Read: v (x y z; a w or vertex colour after them is ignored), vt (u [v
 * [w]]), vn (x y z), f (three or more corners v, v/vt, v//vn or v/vt/vn,
 * all of one form; negative indices count back from the last one read),
 * usemtl and mtllib (the rest of the line is the name). Ignored: o, g, s,
 * l and p (lines and points are not drawn), and any statement glint does
 * not know, as other readers do. Indices must refer to what the file has
 * given before them. */
#include <errno.h>
#include <math.h>
#include <pthread.h>
#include <stdlib.h>
#include <string.h>
#include <unistd.h>
#include "core/array.h"
#include "core/error.h"
#include "core/processors.h"
#include "model/id_table.h"
#include "model/mesh_import.h"
#include "model/obj_read.h"
#include "model/text_scan.h"
#include "model/triangulate.h"

/* Text parsed ahead at a time by each thread (see "Parsing ahead" below),
 * and the least that is worth a thread of its own. The records of a piece
 * take about as much memory as its text. */
#define PIECE (4u << 20)
#define PIECE_MIN (256u << 10)
#define THREADS_MAX 16

/* What reading needs besides the model. */
typedef struct obj_reader {
    obj_model *m;
    const char *file;
    long line;                /* number of the next line */
    int32_t material;         /* the usemtl in force, or -1 */
    id_table corner_index;    /* corner ids by (v, vt, vn), but for those below */
    uint32_t *by_vertex;      /* ids of corners in `relation` by their v; UINT32_MAX for none yet */
    size_t by_vertex_len, by_vertex_cap;
    int64_t relation[2];      /* vt - v and vn - v of the first corner read (NO_PART for none) */
    bool related;             /* relation is set */
    id_table name_index;      /* usemtl names by text */
    uint32_t *face;           /* the corner ids of the face being read */
    uint32_t *face_at;        /* and their positions */
    size_t face_cap;
    obj_corner *resolved;     /* a face parsed ahead, its corners resolved before any is entered */
    size_t resolved_cap;
    uint32_t *split;          /* its triangles as corner numbers */
    size_t split_cap;
    triangulate_work work;
    int threads;              /* threads that parse ahead (below), 1 for none */
    size_t piece_min;         /* the least text worth a thread */
} obj_reader;

/* What a face corner names: a part of the vertex data, and its nouns. */
typedef enum part {
    PART_V,
    PART_VT,
    PART_VN
} part;

static const char *const part_name[] = {"vertex", "texture coordinate", "normal"};
static const char *const part_names[] = {"vertices", "texture coordinates", "normals"};

static glint_status out_of_memory(const obj_reader *r, glint_error *err)
{
    return error_set(err, GLINT_ERR_NOMEM, "%s: out of memory", r->file);
}

static glint_status too_many(const scan_line *l, scan_pos at, const char *what, glint_error *err)
{
    return scan_error(l, at, err, "too many %s (more than %lld)", what, MESH_IMPORT_MAX_COUNT);
}

static float finite_or_zero(double x)
{
    float f = (float)x;
    return isfinite(f) ? f : 0.0f;
}

/* Reads the numbers of a v, vt or vn statement (`what`), whose keyword is
 * at `at`, as the item it adds: x y z, u and glint's v, or x y z. */
static glint_status parse_item(scan_line *l, scan_pos at, part what, float item[3], glint_error *err)
{
    static const struct {
        const char *keyword, *needs;
        int least, most;
    } kinds[] = {
        {"v", "at least 3 numbers (x y z)", 3, INT32_MAX},
        {"vt", "1 to 3 numbers (u [v [w]])", 1, 3},
        {"vn", "3 numbers (x y z)", 3, 3},
    };
    double c[3] = {0, 0, 0};
    scan_pos where[3];
    int n = scan_numbers(l, c, where, 3, err);
    if (n < 0)
        return GLINT_ERR_INVALID;
    if (n < kinds[what].least || n > kinds[what].most)
        return scan_error(l, at, err, "'%s' needs %s, got %d", kinds[what].keyword, kinds[what].needs, n);
    for (int k = 0; k < 3; k++)
        item[k] = (float)c[k];
    for (int k = 0; what == PART_V && k < 3; k++)
        if (!isfinite(item[k]))
            return scan_error(l, where[k], err, "a vertex is not finite (%g %g %g)", item[0], item[1], item[2]);
    if (what == PART_VT)
        c[1] = 1 - c[1]; /* OBJ's v = 0 is the image's bottom row, glint's its top */
    for (int k = 0; what != PART_V && k < 3; k++)
        item[k] = finite_or_zero(c[k]);
    return GLINT_OK;
}

/* Appends an item of part `what` to the model's positions, uvs or normals;
 * false when memory runs out. The count is below MESH_IMPORT_MAX_COUNT. */
static bool add_item(obj_model *m, part what, const float item[3])
{
    float **items[] = {&m->positions, &m->uvs, &m->normals};
    size_t *counts[] = {&m->position_count, &m->uv_count, &m->normal_count};
    size_t *caps[] = {&m->position_cap, &m->uv_cap, &m->normal_cap};
    size_t floats = what == PART_VT ? 2 : 3, *count = counts[what];
    if (!array_reserve((void **)items[what], caps[what], *count + 1, floats * sizeof(float)))
        return false;
    memcpy(*items[what] + floats * *count, item, floats * sizeof(float));
    ++*count;
    return true;
}

/* The number of items of part `what` read so far. */
static size_t item_count(const obj_model *m, part what)
{
    return what == PART_V ? m->position_count : what == PART_VT ? m->uv_count : m->normal_count;
}

/* Reads a v, vt or vn statement (`what`), whose keyword is at `at`, and
 * appends its item to the model's positions, uvs or normals. */
static glint_status read_item(obj_reader *r, scan_line *l, scan_pos at, part what, glint_error *err)
{
    float item[3];
    glint_status s = parse_item(l, at, what, item, err);
    if (s)
        return s;
    if (item_count(r->m, what) >= MESH_IMPORT_MAX_COUNT)
        return too_many(l, at, part_names[what], err);
    return add_item(r->m, what, item) ? GLINT_OK : out_of_memory(r, err);
}

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

/* An index as written made absolute among the `count` items read so far:
 * false when it names none of them. */
static bool absolute_index(long long index, size_t count, int32_t *out)
{
    long long i = index > 0 ? index - 1 : (long long)count + index;
    if (index == 0 || i < 0 || i >= (long long)count)
        return false;
    *out = (int32_t)i;
    return true;
}

/* The index `text` (len bytes at column `at`) of a part, made absolute
 * and checked against the `count` items read so far. */
static glint_status resolve(const scan_line *l, scan_pos at, const char *text, size_t len, long long index,
                            size_t count, part what, int32_t *out, glint_error *err)
{
    if (index == 0)
        return scan_error(l, at, err, "%s index 0 is not valid (indices count from 1)", part_name[what]);
    if (absolute_index(index, count, out))
        return GLINT_OK;
    char q[32];
    scan_quote(text, len, q, sizeof q);
    return scan_error(l, at, err, "%s index %s is out of range (the file has %zu %s so far)", part_name[what], q,
                      count, count == 1 ? part_name[what] : part_names[what]);
}

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
 * when the word is not a face corner. */
static bool scan_corner(scan_line *l, raw_corner *rc)
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

/* Reads one face corner, the word at l->p (at place `at`), moving past
 * it: its indices into *c (-1 for parts it lacks), its form as a bit set of
 * parts, and where it is (*word, *len) for messages. */
static glint_status read_corner(obj_reader *r, scan_line *l, scan_pos at, obj_corner *c, unsigned *form,
                                const char **word_out, size_t *len_out, glint_error *err)
{
    raw_corner rc;
    bool whole = scan_corner(l, &rc);
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
                                 item_count(m, (part)k), (part)k, out[k], err);
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

static uint32_t corner_hash(const void *keys, uint32_t id)
{
    return corner_key_hash((const obj_corner *)keys + id);
}

static bool corner_equal(const void *keys, uint32_t id, const void *key)
{
    const obj_corner *a = (const obj_corner *)keys + id, *b = key;
    return a->v == b->v && a->vt == b->vt && a->vn == b->vn;
}

/* The difference of a corner's index of a part from its vertex index, or
 * NO_PART when it lacks the part. */
#define NO_PART INT64_MIN
static int64_t part_offset(int32_t index, int32_t v)
{
    return index < 0 ? NO_PART : (int64_t)index - v;
}

/* The id of a new corner c. */
static glint_status corner_new(obj_reader *r, const scan_line *l, scan_pos at, const obj_corner *c, uint32_t *id,
                               glint_error *err)
{
    obj_model *m = r->m;
    if (m->corner_count >= MESH_IMPORT_MAX_COUNT)
        return too_many(l, at, "vertices", err);
    if (!array_reserve((void **)&m->corners, &m->corner_cap, m->corner_count + 1, sizeof *m->corners))
        return out_of_memory(r, err);
    *id = (uint32_t)m->corner_count;
    m->corners[m->corner_count++] = *c;
    return GLINT_OK;
}

/* The id of corner c, entering it when it is new. Most files number a
 * corner's texture coordinate and normal the same way against its vertex
 * throughout (the same index, or none): corners related to their vertex
 * as the first corner read was are found by vertex in an array, the rest
 * by hashing. Ids go in the order corners first appear either way. */
static glint_status corner_id(obj_reader *r, const scan_line *l, scan_pos at, const obj_corner *c, uint32_t *id,
                              glint_error *err)
{
    obj_model *m = r->m;
    int64_t vt = part_offset(c->vt, c->v), vn = part_offset(c->vn, c->v);
    if (!r->related) {
        r->relation[0] = vt;
        r->relation[1] = vn;
        r->related = true;
    }
    if (vt == r->relation[0] && vn == r->relation[1]) {
        /* Vertices may still come after faces: room for all read so far. */
        if ((size_t)c->v >= r->by_vertex_len) {
            if (!array_reserve((void **)&r->by_vertex, &r->by_vertex_cap, m->position_count, sizeof *r->by_vertex))
                return out_of_memory(r, err);
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
        !id_table_reserve(&r->corner_index, m->position_count, corner_hash, m->corners))
        return out_of_memory(r, err);
    if (id_table_find(&r->corner_index, corner_key_hash(c), c, corner_equal, m->corners, id))
        return GLINT_OK;
    glint_status s = corner_new(r, l, at, c, id, err);
    if (!s && !id_table_add(&r->corner_index, corner_key_hash(c), *id, corner_hash, m->corners))
        s = out_of_memory(r, err);
    return s;
}

static glint_status add_triangle(obj_reader *r, const scan_line *l, scan_pos at, uint32_t a, uint32_t b,
                                 uint32_t c, glint_error *err)
{
    obj_model *m = r->m;
    if (m->triangle_count >= MESH_IMPORT_MAX_COUNT)
        return too_many(l, at, "triangles", err);
    if (!array_reserve((void **)&m->triangles, &m->triangle_cap, m->triangle_count + 1, 3 * sizeof(uint32_t)))
        return out_of_memory(r, err);
    if (m->run_count == 0 || m->runs[m->run_count - 1].material != r->material) {
        if (!array_reserve((void **)&m->runs, &m->run_cap, m->run_count + 1, sizeof *m->runs))
            return out_of_memory(r, err);
        m->runs[m->run_count++] = (obj_run){(uint32_t)m->triangle_count, r->material};
    }
    uint32_t *t = m->triangles + 3 * m->triangle_count++;
    t[0] = a;
    t[1] = b;
    t[2] = c;
    return GLINT_OK;
}

/* The form of a face corner as written, for messages. */
static const char *form_text(unsigned form)
{
    static const char *const forms[] = {"", "v", "", "v/vt", "", "v//vn", "", "v/vt/vn"};
    return forms[form & 7];
}

/* Adds the triangles of the face of n corners of form `form` whose ids are
 * in r->face (and their vertices in r->face_at), read at `at`. */
static glint_status add_face(obj_reader *r, const scan_line *l, scan_pos at, size_t n, unsigned form,
                             glint_error *err)
{
    obj_model *m = r->m;
    glint_status s = GLINT_OK;
    m->generate |= !(form & 1u << PART_VN);
    m->textured |= (form & 1u << PART_VT) != 0;
    if (n == 3)
        return add_triangle(r, l, at, r->face[0], r->face[1], r->face[2], err);
    if (!array_reserve((void **)&r->split, &r->split_cap, 3 * (n - 2), sizeof *r->split) ||
        !triangulate_polygon(&r->work, m->positions, r->face_at, n, r->split))
        return out_of_memory(r, err);
    for (size_t t = 0; !s && t < n - 2; t++)
        s = add_triangle(r, l, at, r->face[r->split[3 * t]], r->face[r->split[3 * t + 1]],
                         r->face[r->split[3 * t + 2]], err);
    return s;
}

/* Room for n corners in r->face and r->face_at. */
static bool face_room(obj_reader *r, size_t n)
{
    size_t cap = r->face_cap;
    return array_reserve((void **)&r->face, &cap, n, sizeof *r->face) &&
           array_reserve((void **)&r->face_at, &r->face_cap, n, sizeof *r->face_at);
}

static glint_status read_face(obj_reader *r, scan_line *l, scan_pos at, glint_error *err)
{
    size_t n = 0;
    unsigned first_form = 0;
    glint_status s = GLINT_OK;
    while (!s && scan_more(l)) {
        scan_pos here = scan_here(l);
        obj_corner c;
        unsigned form = 0;
        const char *word = NULL;
        size_t len = 0;
        if ((s = read_corner(r, l, here, &c, &form, &word, &len, err)))
            break;
        if (n == 0) {
            first_form = form;
        } else if (form != first_form) {
            char q[32];
            scan_quote(word, len, q, sizeof q);
            return scan_error(l, here, err, "face corner '%s' is %s, but the face's first corner is %s", q,
                              form_text(form), form_text(first_form));
        }
        if (n >= MESH_IMPORT_MAX_COUNT)
            return too_many(l, here, "corners in one face", err);
        if (!face_room(r, n + 1))
            return out_of_memory(r, err);
        r->face_at[n] = (uint32_t)c.v;
        s = corner_id(r, l, here, &c, &r->face[n++], err);
    }
    if (s)
        return s;
    if (n < 3)
        return scan_error(l, at, err, "a face needs at least 3 corners, got %zu", n);
    return add_face(r, l, at, n, first_form, err);
}

/* Copies the rest of the line into the model's text; *offset is where. */
static glint_status read_name(obj_reader *r, scan_line *l, scan_pos at, const char *keyword, size_t *offset,
                              glint_error *err)
{
    obj_model *m = r->m;
    const char *s, *e;
    if (!scan_rest(l, &s, &e))
        return scan_error(l, at, err, "'%s' needs a name", keyword);
    if (!scan_keep_text(&m->text, &m->text_len, &m->text_cap, s, e, offset))
        return out_of_memory(r, err);
    return GLINT_OK;
}

static uint32_t name_hash(const void *keys, uint32_t id)
{
    const obj_model *m = keys;
    return id_hash_text(m->text + m->materials[id]);
}

static bool name_equal(const void *keys, uint32_t id, const void *key)
{
    const obj_model *m = keys;
    return strcmp(m->text + m->materials[id], key) == 0;
}

static glint_status read_usemtl(obj_reader *r, scan_line *l, scan_pos at, glint_error *err)
{
    obj_model *m = r->m;
    size_t offset = 0;
    glint_status s = read_name(r, l, at, "usemtl", &offset, err);
    if (s)
        return s;
    if (m->material_count >= MESH_IMPORT_MAX_COUNT)
        return too_many(l, at, "materials", err);
    if (!array_reserve((void **)&m->materials, &m->material_cap, m->material_count + 1, sizeof *m->materials))
        return out_of_memory(r, err);
    const char *name = m->text + offset;
    uint32_t id;
    if (!id_table_intern(&r->name_index, id_hash_text(name), name, (uint32_t)m->material_count, name_hash,
                         name_equal, m, &id))
        return out_of_memory(r, err);
    if (id == m->material_count)
        m->materials[m->material_count++] = offset;
    else
        m->text_len = offset; /* known already: its copy is not needed */
    r->material = (int32_t)id;
    return GLINT_OK;
}

static glint_status read_mtllib(obj_reader *r, scan_line *l, scan_pos at, glint_error *err)
{
    obj_model *m = r->m;
    size_t offset = 0;
    glint_status s = read_name(r, l, at, "mtllib", &offset, err);
    if (!s && !array_reserve((void **)&m->libraries, &m->library_cap, m->library_count + 1, sizeof *m->libraries))
        s = out_of_memory(r, err);
    if (!s)
        m->libraries[m->library_count++] = offset;
    return s;
}

/* The statements glint reads; KEY_OTHER for every other word. */
typedef enum keyword {
    KEY_V,
    KEY_VT,
    KEY_VN,
    KEY_F,
    KEY_USEMTL,
    KEY_MTLLIB,
    KEY_OTHER
} keyword;

static keyword keyword_of(const char *w, size_t n)
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
static part item_part(keyword k)
{
    return k == KEY_V ? PART_V : k == KEY_VT ? PART_VT : PART_VN;
}

static glint_status statement(obj_reader *r, scan_line *l, glint_error *err)
{
    if (!scan_more(l))
        return GLINT_OK;
    scan_pos at = scan_here(l);
    size_t n;
    const char *w = scan_word(l, &n);
    keyword k = keyword_of(w, n);
    switch (k) {
    case KEY_V:
    case KEY_VT:
    case KEY_VN:
        return read_item(r, l, at, item_part(k), err);
    case KEY_F:
        return read_face(r, l, at, err);
    case KEY_USEMTL:
        return read_usemtl(r, l, at, err);
    case KEY_MTLLIB:
        return read_mtllib(r, l, at, err);
    default:
        return GLINT_OK;
    }
}

/* Reads every whole line in [data, data + size), and with `last` the rest
 * too; *used is how far it got. */
static glint_status feed(obj_reader *r, const char *data, size_t size, bool last, size_t *used, glint_error *err)
{
    const char *p = data, *end = data + size;
    scan_span span;
    glint_status s = GLINT_OK;
    while (!s && p < end && scan_next_line(p, end, last, &span)) {
        scan_line l;
        scan_start(&l, p, span.end, r->line, r->file);
        s = statement(r, &l, err);
        r->line += span.rows;
        p = span.next;
    }
    *used = (size_t)(p - data);
    return s;
}

/* Parsing ahead. A large text is cut at line breaks into pieces, one per
 * thread, and each thread parses the statements of its piece into records
 * without touching the model: items as the floats they add, faces as their
 * indices as written. The records are then merged into the model in the
 * file's order, as statement() would read them. A line the parse could not
 * take whole (an error, usemtl, mtllib), and a record whose indices do not
 * resolve against the counts so far or that could pass a limit, goes to
 * statement() itself at its place in the merge, so the model and every
 * message are those of reading the text in one pass, wherever the cuts
 * fall and however many threads there are. The text comes a block at a
 * time (a piece per thread), and the threads parse the next block while
 * the reader merges the one before: on the million-triangle wavy mesh of
 * bench/, two threads read the file in 0.30 s where one took 0.42 s. */

typedef enum ahead_kind {
    AHEAD_ITEM,               /* a v, vt or vn statement, parsed */
    AHEAD_FACE,               /* an f statement, its corners parsed */
    AHEAD_LINE                /* a line for statement() to read */
} ahead_kind;

typedef struct ahead {
    uint32_t offset;          /* where the line starts, from the piece's start */
    uint32_t row;             /* its first physical line, from the piece's first (0) */
    uint8_t kind;             /* ahead_kind */
    uint8_t what;             /* an item's part, a face's form */
    uint32_t corners;         /* a face's corners */
    union {
        float item[3];
        size_t first;         /* a face's first corner in piece.corners */
    } u;
} ahead;

typedef struct text_piece {
    const char *start, *end;  /* whole lines */
    bool last;                /* end is the end of the text, which may lack a break */
    const char *file;
    long rows;                /* its physical lines */
    ahead *items;
    size_t count, cap;
    int32_t *corners;         /* v, vt, vn as written, 3 each; 0 for a part a corner lacks */
    size_t corner_count, corner_cap;
    bool no_memory;
} text_piece;

/* Parses the corners of the face on l into pc->corners and completes *a as
 * AHEAD_FACE; leaves *a and pc->corners as they were when it cannot. */
static void ahead_face(text_piece *pc, scan_line *l, ahead *a)
{
    size_t first = pc->corner_count, n = 0;
    unsigned form = 0;
    while (scan_more(l)) {
        raw_corner rc;
        if (!scan_corner(l, &rc) || (n > 0 && rc.form != form) || n + 1 >= MESH_IMPORT_MAX_COUNT)
            goto refused;
        form = rc.form;
        if (!array_reserve((void **)&pc->corners, &pc->corner_cap, pc->corner_count + 3, sizeof *pc->corners)) {
            pc->no_memory = true;
            goto refused;
        }
        int32_t *c = pc->corners + pc->corner_count;
        for (int k = 0; k < 3; k++) {
            c[k] = 0;
            if (!rc.start[k])
                continue;
            if (rc.index[k] == 0 || rc.index[k] > INT32_MAX || rc.index[k] < -INT32_MAX)
                goto refused;
            c[k] = (int32_t)rc.index[k];
        }
        pc->corner_count += 3;
        n++;
    }
    if (n < 3)
        goto refused;
    a->kind = AHEAD_FACE;
    a->what = (uint8_t)form;
    a->corners = (uint32_t)n;
    a->u.first = first;
    return;
refused:
    pc->corner_count = first;
}

/* Parses the statements of a piece into its records (a thread's work). */
static void *parse_piece(void *arg)
{
    /* A copy of its own: the pieces lie side by side, and a thread writing
     * to its counts there would slow down the others sharing their cache
     * lines (both threads of the wavy mesh took longer than one). */
    text_piece own = *(text_piece *)arg, *pc = &own;
    const char *p = pc->start;
    long row = 0;
    scan_span span;
    glint_error unused;
    while (!pc->no_memory && p < pc->end && scan_next_line(p, pc->end, pc->last, &span)) {
        scan_line l;
        scan_start(&l, p, span.end, 1 + row, pc->file);
        ahead a = {.offset = (uint32_t)(p - pc->start), .row = (uint32_t)row, .kind = AHEAD_LINE};
        keyword k = KEY_OTHER;
        if (scan_more(&l)) {
            scan_pos at = scan_here(&l);
            size_t n;
            const char *w = scan_word(&l, &n);
            k = keyword_of(w, n);
            if ((k == KEY_V || k == KEY_VT || k == KEY_VN) && !parse_item(&l, at, item_part(k), a.u.item, &unused)) {
                a.kind = AHEAD_ITEM;
                a.what = (uint8_t)item_part(k);
            } else if (k == KEY_F) {
                ahead_face(pc, &l, &a);
            }
        }
        /* Blank lines, comments and statements glint ignores need no record. */
        if (k != KEY_OTHER) {
            if (!array_reserve((void **)&pc->items, &pc->cap, pc->count + 1, sizeof *pc->items))
                pc->no_memory = true;
            else
                pc->items[pc->count++] = a;
        }
        row += span.rows;
        p = span.next;
    }
    pc->rows = row;
    *(text_piece *)arg = own;
    return NULL;
}

/* Reads the line of record a with statement(); `base` is the number of
 * the piece's first line. */
static glint_status merge_line(obj_reader *r, const text_piece *pc, const ahead *a, long base, glint_error *err)
{
    const char *p = pc->start + a->offset;
    scan_span span;
    scan_line l;
    scan_next_line(p, pc->end, pc->last, &span);
    scan_start(&l, p, span.end, base + a->row, r->file);
    return statement(r, &l, err);
}

/* Adds the face of record a as read_face would; false, with nothing
 * changed, when its indices do not all resolve or it could pass a limit:
 * then statement() is to read its line. */
static bool merge_face(obj_reader *r, const text_piece *pc, const ahead *a, long base, glint_status *s,
                       glint_error *err)
{
    obj_model *m = r->m;
    size_t n = a->corners;
    const int32_t *raw = pc->corners + a->u.first;
    if (m->corner_count + n >= MESH_IMPORT_MAX_COUNT || m->triangle_count + n >= MESH_IMPORT_MAX_COUNT)
        return false;
    if (!face_room(r, n) || !array_reserve((void **)&r->resolved, &r->resolved_cap, n, sizeof *r->resolved)) {
        *s = out_of_memory(r, err);
        return true;
    }
    for (size_t k = 0; k < n; k++) {
        obj_corner *c = &r->resolved[k];
        int32_t *out[3] = {&c->v, &c->vt, &c->vn};
        *c = (obj_corner){-1, -1, -1};
        for (int j = 0; j < 3; j++)
            if ((a->what & 1u << j) && !absolute_index(raw[3 * k + j], item_count(m, (part)j), out[j]))
                return false;
    }
    /* Nothing below can fail but for memory: the place is for form's sake. */
    scan_line l;
    const char *p = pc->start + a->offset;
    scan_start(&l, p, p, base + a->row, r->file);
    scan_pos at = {base + a->row, 1};
    for (size_t k = 0; k < n; k++) {
        r->face_at[k] = (uint32_t)r->resolved[k].v;
        if ((*s = corner_id(r, &l, at, &r->resolved[k], &r->face[k], err)))
            return true;
    }
    *s = add_face(r, &l, at, n, a->what, err);
    return true;
}

/* Applies the records of a piece to the model in order; memory that ran
 * out while parsing it counts after the lines it parsed. */
static glint_status merge_piece(obj_reader *r, const text_piece *pc, glint_error *err)
{
    long base = r->line;
    glint_status s = GLINT_OK;
    for (size_t i = 0; !s && i < pc->count; i++) {
        const ahead *a = &pc->items[i];
        if (a->kind == AHEAD_ITEM && item_count(r->m, a->what) < MESH_IMPORT_MAX_COUNT)
            s = add_item(r->m, a->what, a->u.item) ? GLINT_OK : out_of_memory(r, err);
        else if (a->kind != AHEAD_FACE || !merge_face(r, pc, a, base, &s, err))
            s = merge_line(r, pc, a, base, err);
    }
    if (!s && pc->no_memory)
        s = out_of_memory(r, err);
    r->line = base + pc->rows;
    return s;
}

/* True when the line break at nl surely ends a logical line: no backslash
 * right before it (one on a commented line also ends it, but a cut there
 * is not needed). */
static bool sure_break(const char *data, const char *nl)
{
    const char *e = nl > data && nl[-1] == '\r' ? nl - 1 : nl;
    return !(e > data && e[-1] == '\\');
}

/* The offset just after the first sure line break at or after `from` in
 * [data, data + size), or size when there is none. */
static size_t cut_after(const char *data, size_t size, size_t from)
{
    for (const char *p = data + from; p < data + size; p++) {
        p = memchr(p, '\n', (size_t)(data + size - p));
        if (!p)
            break;
        if (sure_break(data, p))
            return (size_t)(p + 1 - data);
    }
    return size;
}

/* The offset just after the last sure line break in [data, data + size),
 * or 0 when there is none. */
static size_t last_cut(const char *data, size_t size)
{
    for (size_t i = size; i > 0; i--)
        if (data[i - 1] == '\n' && sure_break(data, data + i - 1))
            return i;
    return 0;
}

/* Where the text comes from: bytes in memory, or a file (fd >= 0) read
 * into each block's buffer. */
typedef struct source {
    const char *data;
    size_t size, at;          /* memory: its bytes, and where the next block starts */
    int fd;
} source;

/* A block of the text: its whole lines are parsed by threads, a piece
 * each, while the reader merges the block before it. */
typedef struct block {
    char *buf;                /* a file's bytes, cap of them; NULL for memory */
    size_t cap;
    const char *data;
    size_t size;
    bool last;                /* the text ends with it */
    size_t whole;             /* its bytes up to the last sure line break; all of them when last */
    int count;                /* its pieces; 1 for none (it is then read by feed) */
    text_piece pieces[THREADS_MAX];
    pthread_t threads[THREADS_MAX];
    bool started[THREADS_MAX];
    bool parsed;              /* its pieces are parsed (or it has none) */
} block;

/* Fills b with the next `size` bytes or so of the text, after `carry`
 * bytes left over from the block before (a file's are copied; memory's
 * are where they are), until it holds a sure line break or the end. */
static glint_status fill(obj_reader *r, source *src, block *b, size_t size, const char *carry, size_t carry_len,
                         glint_error *err)
{
    if (src->fd < 0) {
        for (;;) {
            size_t left = src->size - src->at, n = left < size ? left : size;
            b->data = src->data + src->at;
            b->size = n;
            b->last = n == left;
            b->whole = b->last ? n : last_cut(b->data, n);
            if (b->whole > 0 || b->last)
                return GLINT_OK;
            size = size <= SIZE_MAX / 2 ? 2 * size : SIZE_MAX; /* a line longer than a block */
        }
    }
    /* Room for the block, and past the carry for at least one more byte. */
    if (!array_reserve((void **)&b->buf, &b->cap, carry_len < size ? size : carry_len + 1, 1))
        return out_of_memory(r, err);
    if (carry_len > 0)
        memmove(b->buf, carry, carry_len);
    size_t have = carry_len;
    for (;;) {
        ssize_t got = read(src->fd, b->buf + have, b->cap - have);
        if (got < 0 && errno == EINTR)
            continue;
        if (got < 0)
            return error_set(err, GLINT_ERR_IO, "%s: cannot read: %s", r->file, strerror(errno));
        have += (size_t)got;
        b->last = got == 0;
        if (have < b->cap && !b->last)
            continue;
        b->data = b->buf;
        b->size = have;
        b->whole = b->last ? have : last_cut(b->data, have);
        if (b->whole > 0 || b->last)
            return GLINT_OK;
        /* A line longer than the buffer: make room for more of it. */
        if (!array_reserve((void **)&b->buf, &b->cap, b->cap + 1, 1))
            return out_of_memory(r, err);
    }
}

/* Cuts b's whole lines into pieces, as many as the reader's threads while
 * each has at least piece_min bytes, and starts a thread on each. */
static void parse_start(const obj_reader *r, block *b)
{
    b->parsed = false;
    /* Records place their lines in 32 bits: a block beyond that (a line
     * of gigabytes) is read in one pass. */
    b->count = b->whole > UINT32_MAX ? 1 : r->threads;
    while (b->count > 1 && b->whole / (size_t)b->count < r->piece_min)
        b->count--;
    if (b->count <= 1)
        return;
    size_t from = 0;
    for (int k = 0; k < b->count; k++) {
        size_t goal = b->whole / (size_t)b->count * (size_t)(k + 1);
        size_t to = k == b->count - 1 ? b->whole : cut_after(b->data, b->whole, from > goal ? from : goal);
        /* The records' room is kept from block to block: fresh memory
         * for every block cost 5% in page faults. */
        text_piece *pc = &b->pieces[k];
        *pc = (text_piece){.start = b->data + from, .end = b->data + to, .last = b->last && to == b->whole,
                           .file = r->file, .items = pc->items, .cap = pc->cap, .corners = pc->corners,
                           .corner_cap = pc->corner_cap};
        from = to;
        b->started[k] = pthread_create(&b->threads[k], NULL, parse_piece, &b->pieces[k]) == 0;
    }
}

/* Waits for b's pieces; a piece whose thread did not start is parsed now. */
static void parse_finish(block *b)
{
    for (int k = 0; !b->parsed && b->count > 1 && k < b->count; k++) {
        if (b->started[k])
            pthread_join(b->threads[k], NULL);
        else
            parse_piece(&b->pieces[k]);
    }
    b->parsed = true;
}

/* Frees b's buffer and the room of its records. */
static void block_free(block *b)
{
    free(b->buf);
    for (int k = 0; k < THREADS_MAX; k++) {
        free(b->pieces[k].items);
        free(b->pieces[k].corners);
    }
}

/* Reads b's whole lines into the model. */
static glint_status merge_block(obj_reader *r, block *b, glint_error *err)
{
    glint_status s = GLINT_OK;
    if (b->count <= 1) {
        size_t used;
        s = feed(r, b->data, b->whole, b->last, &used, err);
    }
    for (int k = 0; b->count > 1 && !s && k < b->count; k++)
        s = merge_piece(r, &b->pieces[k], err);
    return s;
}

/* Reads the whole text of src, `size` bytes a block, the next block
 * parsed while the one before is merged. */
static glint_status read_source(obj_reader *r, source *src, size_t size, glint_error *err)
{
    block blocks[2] = {0}, *b = &blocks[0], *next = &blocks[1];
    glint_status s = fill(r, src, b, size, NULL, 0, err);
    if (!s)
        parse_start(r, b);
    while (!s) {
        parse_finish(b);
        /* A failure to read on comes after b's lines, so after their errors. */
        glint_status read_on = GLINT_OK;
        bool more = !b->last;
        if (more) {
            src->at += b->whole;
            read_on = fill(r, src, next, size, b->data + b->whole, b->size - b->whole, err);
            more = !read_on;
            if (more)
                parse_start(r, next);
        }
        s = merge_block(r, b, err);
        if (!s)
            s = read_on;
        if (s || !more) {
            /* The block parsed ahead of a failure is waited for, not read. */
            if (more)
                parse_finish(next);
            break;
        }
        block *t = b;
        b = next;
        next = t;
    }
    block_free(&blocks[0]);
    block_free(&blocks[1]);
    return s;
}

/* Reads the text of src into *m with `threads` threads (1 to THREADS_MAX)
 * parsing ahead pieces of `piece` bytes (at least 1), `piece_min` bytes
 * the least worth a thread. */
static glint_status read_all(obj_model *m, source *src, const char *file, int threads, size_t piece,
                             size_t piece_min, glint_error *err)
{
    obj_reader r;
    threads = threads < 1 ? 1 : threads > THREADS_MAX ? THREADS_MAX : threads;
    piece = piece > 0 ? piece : 1;
    *m = (obj_model){0};
    r = (obj_reader){.m = m, .file = file, .line = 1, .material = -1, .threads = threads, .piece_min = piece_min};
    glint_status s = read_source(&r, src, (size_t)threads * piece, err);
    id_table_free(&r.corner_index);
    free(r.by_vertex);
    id_table_free(&r.name_index);
    free(r.face);
    free(r.face_at);
    free(r.resolved);
    free(r.split);
    triangulate_free(&r.work);
    return s;
}

glint_status obj_read_memory(obj_model *m, const unsigned char *data, size_t size, const char *file,
                             glint_error *err)
{
    source src = {.data = (const char *)data, .size = size, .fd = -1};
    return read_all(m, &src, file, processors_online(THREADS_MAX), PIECE, PIECE_MIN, err);
}

glint_status obj_read_memory_split(obj_model *m, const unsigned char *data, size_t size, const char *file,
                                   int threads, size_t piece, glint_error *err)
{
    source src = {.data = (const char *)data, .size = size, .fd = -1};
    return read_all(m, &src, file, threads, piece, 1, err);
}

glint_status obj_read_fd_split(obj_model *m, int fd, const char *file, int threads, size_t piece, glint_error *err)
{
    source src = {.fd = fd};
    return read_all(m, &src, file, threads, piece, 1, err);
}

glint_status obj_read_fd(obj_model *m, int fd, const char *file, glint_error *err)
{
    source src = {.fd = fd};
    return read_all(m, &src, file, processors_online(THREADS_MAX), PIECE, PIECE_MIN, err);
}

void obj_model_drop(void **array, size_t *count, size_t *cap)
{
    free(*array);
    *array = NULL;
    *count = *cap = 0;
}

void obj_model_free(obj_model *m)
{
    free(m->positions);
    free(m->uvs);
    free(m->normals);
    free(m->corners);
    free(m->triangles);
    free(m->runs);
    free(m->text);
    free(m->materials);
    free(m->libraries);
    *m = (obj_model){0};
}
