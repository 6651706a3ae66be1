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
#include <stdlib.h>
#include <string.h>
#include <unistd.h>
#include "core/array.h"
#include "core/error.h"
#include "io/id_table.h"
#include "io/mesh_import.h"
#include "io/obj_read.h"
#include "io/text_scan.h"
#include "io/triangulate.h"

/* Bytes read from a file at a time; a longer line grows the buffer. */
#define CHUNK (1u << 20)

/* What reading needs besides the model. */
typedef struct obj_reader {
    obj_model *m;
    const char *file;
    long line;                /* number of the next line */
    int32_t material;         /* the usemtl in force, or -1 */
    id_table corner_index;    /* corner ids by (v, vt, vn) */
    id_table name_index;      /* usemtl names by text */
    uint32_t *face;           /* the corner ids of the face being read */
    uint32_t *face_at;        /* and their positions */
    size_t face_cap;
    uint32_t *split;          /* its triangles as corner numbers */
    size_t split_cap;
    triangulate_work work;
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

/* The id of corner c, entering it when it is new. */
static glint_status corner_id(obj_reader *r, const scan_line *l, scan_pos at, const obj_corner *c, uint32_t *id,
                              glint_error *err)
{
    obj_model *m = r->m;
    /* Sized from the vertices read so far: most files give them all first. */
    if (!r->corner_index.slots &&
        !id_table_reserve(&r->corner_index, m->position_count, corner_hash, m->corners))
        return out_of_memory(r, err);
    if (!array_reserve((void **)&m->corners, &m->corner_cap, m->corner_count + 1, sizeof *m->corners))
        return out_of_memory(r, err);
    if (!id_table_intern(&r->corner_index, corner_key_hash(c), c, (uint32_t)m->corner_count, corner_hash,
                         corner_equal, m->corners, id))
        return out_of_memory(r, err);
    if (*id == m->corner_count) {
        if (m->corner_count >= MESH_IMPORT_MAX_COUNT)
            return too_many(l, at, "vertices", err);
        m->corners[m->corner_count++] = *c;
    }
    return GLINT_OK;
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

static glint_status statement(obj_reader *r, scan_line *l, glint_error *err)
{
    if (!scan_more(l))
        return GLINT_OK;
    scan_pos at = scan_here(l);
    size_t n;
    const char *w = scan_word(l, &n);
    if (n == 1 && w[0] == 'v')
        return read_item(r, l, at, PART_V, err);
    if (n == 1 && w[0] == 'f')
        return read_face(r, l, at, err);
    if (n == 2 && w[0] == 'v' && w[1] == 'n')
        return read_item(r, l, at, PART_VN, err);
    if (n == 2 && w[0] == 'v' && w[1] == 't')
        return read_item(r, l, at, PART_VT, err);
    if (scan_word_is(w, n, "usemtl"))
        return read_usemtl(r, l, at, err);
    if (scan_word_is(w, n, "mtllib"))
        return read_mtllib(r, l, at, err);
    return GLINT_OK;
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

static void reader_start(obj_reader *r, obj_model *m, const char *file)
{
    *m = (obj_model){0};
    *r = (obj_reader){.m = m, .file = file, .line = 1, .material = -1};
}

/* Frees what only reading needs. */
static void reader_end(obj_reader *r)
{
    id_table_free(&r->corner_index);
    id_table_free(&r->name_index);
    free(r->face);
    free(r->face_at);
    free(r->split);
    triangulate_free(&r->work);
}

glint_status obj_read_memory(obj_model *m, const unsigned char *data, size_t size, const char *file,
                             glint_error *err)
{
    obj_reader r;
    size_t used;
    reader_start(&r, m, file);
    glint_status s = feed(&r, (const char *)data, size, true, &used, err);
    reader_end(&r);
    return s;
}

glint_status obj_read_fd(obj_model *m, int fd, const char *file, glint_error *err)
{
    obj_reader r;
    reader_start(&r, m, file);
    size_t cap = CHUNK, have = 0;
    char *buf = malloc(cap);
    glint_status s = buf ? GLINT_OK : out_of_memory(&r, err);
    for (bool end = false; !s && !end;) {
        ssize_t got = read(fd, buf + have, cap - have);
        if (got < 0 && errno == EINTR)
            continue;
        if (got < 0) {
            s = error_set(err, GLINT_ERR_IO, "%s: cannot read: %s", file, strerror(errno));
            break;
        }
        end = got == 0;
        have += (size_t)got;
        size_t used;
        if ((s = feed(&r, buf, have, end, &used, err)))
            break;
        memmove(buf, buf + used, have - used);
        have -= used;
        /* A line longer than the buffer: make room for more of it. */
        if (have == cap && !array_reserve((void **)&buf, &cap, cap + 1, 1))
            s = out_of_memory(&r, err);
    }
    free(buf);
    reader_end(&r);
    return s;
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
