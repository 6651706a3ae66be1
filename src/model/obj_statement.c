/* obj_statement.c - the statements of OBJ text, one logical line at a
 * time, straight into the model.
 *
 * Read: v (x y z; a w or vertex colour after them is ignored), vt (u [v
 * [w]]), vn (x y z), f (three or more corners, obj_corner.c; polygons are
 * split into triangles), usemtl and mtllib (the rest of the line is the
 * name). Ignored: o, g, s, l and p (lines and points are not drawn), and
 * any statement glint does not know, as other readers do. */
#include <math.h>
#include <stdlib.h>
#include <string.h>
#include "core/array.h"
#include "model/obj_parse.h"

static float finite_or_zero(double x)
{
    float f = (float)x;
    return isfinite(f) ? f : 0.0f;
}

/* What each part's statement holds. */
static const struct {
    const char *keyword, *needs;
    int least, most;
} kinds[] = {
    {"v", "at least 3 numbers (x y z)", 3, INT32_MAX},
    {"vt", "1 to 3 numbers (u [v [w]])", 1, 3},
    {"vn", "3 numbers (x y z)", 3, 3},
};

/* The item of part `what` from the numbers read. */
static void item_of(obj_part what, double c[3], float item[3])
{
    for (int k = 0; k < 3; k++)
        item[k] = (float)c[k];
    if (what == PART_VT)
        c[1] = 1 - c[1]; /* OBJ's v = 0 is the image's bottom row, glint's its top */
    for (int k = 0; what != PART_V && k < 3; k++)
        item[k] = finite_or_zero(c[k]);
}

bool obj_plain_item(scan_line *l, obj_part what, float item[3])
{
    /* Plain numbers are finite floats: a vertex needs no check. */
    double c[3] = {0, 0, 0};
    if (scan_plain_numbers(l, c, kinds[what].least, 3) < 0)
        return false;
    item_of(what, c, item);
    return true;
}

glint_status obj_parse_item(scan_line *l, scan_pos at, obj_part what, float item[3], glint_error *err)
{
    if (obj_plain_item(l, what, item))
        return GLINT_OK;
    double c[3] = {0, 0, 0};
    scan_pos where[3];
    int n = scan_numbers(l, c, where, 3, err);
    if (n < 0)
        return GLINT_ERR_INVALID;
    if (n < kinds[what].least || n > kinds[what].most)
        return scan_error(l, at, err, "'%s' needs %s, got %d", kinds[what].keyword, kinds[what].needs, n);
    for (int k = 0; what == PART_V && k < 3; k++)
        if (!isfinite((float)c[k]))
            return scan_error(l, where[k], err, "a vertex is not finite (%g %g %g)", (float)c[0], (float)c[1],
                              (float)c[2]);
    item_of(what, c, item);
    return GLINT_OK;
}

/* Appends the `floats` floats of item to *items, of which there are
 * *count, with room for *cap. */
static bool append(float **items, size_t *count, size_t *cap, size_t floats, const float *item)
{
    if (!array_reserve((void **)items, cap, *count + 1, floats * sizeof(float)))
        return false;
    memcpy(*items + floats * *count, item, floats * sizeof(float));
    ++*count;
    return true;
}

bool obj_add_item(obj_model *m, obj_part what, const float item[3])
{
    if (what == PART_V)
        return append(&m->positions, &m->position_count, &m->position_cap, 3, item);
    if (what == PART_VT)
        return append(&m->uvs, &m->uv_count, &m->uv_cap, 2, item);
    return append(&m->normals, &m->normal_count, &m->normal_cap, 3, item);
}

/* Reads a v, vt or vn statement (`what`), whose keyword is at `at`, and
 * appends its item to the model's positions, uvs or normals. */
static glint_status read_item(obj_parser *r, scan_line *l, scan_pos at, obj_part what, glint_error *err)
{
    float item[3];
    glint_status s = obj_parse_item(l, at, what, item, err);
    if (s)
        return s;
    if (obj_item_count(r->m, what) >= MODEL_MAX_COUNT)
        return obj_too_many(l, at, obj_part_names[what], err);
    return obj_add_item(r->m, what, item) ? GLINT_OK : obj_out_of_memory(r, err);
}

/* Adds the `count` triangles of the face in r->face whose corners are
 * r->face[tri[3t]], r->face[tri[3t + 1]] and r->face[tri[3t + 2]]. */
static glint_status add_triangles(obj_parser *r, const scan_line *l, scan_pos at, const uint32_t *tri, size_t count,
                                  glint_error *err)
{
    obj_model *m = r->m;
    if (m->triangle_count + count > MODEL_MAX_COUNT)
        return obj_too_many(l, at, "triangles", err);
    if (!array_reserve((void **)&m->triangles, &m->triangle_cap, m->triangle_count + count, 3 * sizeof(uint32_t)))
        return obj_out_of_memory(r, err);
    if (m->run_count == 0 || m->runs[m->run_count - 1].material != r->material) {
        if (!array_reserve((void **)&m->runs, &m->run_cap, m->run_count + 1, sizeof *m->runs))
            return obj_out_of_memory(r, err);
        m->runs[m->run_count++] = (obj_run){(uint32_t)m->triangle_count, r->material};
    }
    uint32_t *t = m->triangles + 3 * m->triangle_count;
    for (size_t i = 0; i < 3 * count; i++)
        t[i] = r->face[tri[i]];
    m->triangle_count += count;
    return GLINT_OK;
}

/* The form of a face corner as written, for messages. */
static const char *form_text(unsigned form)
{
    static const char *const forms[] = {"", "v", "", "v/vt", "", "v//vn", "", "v/vt/vn"};
    return forms[form & 7];
}

glint_status obj_add_face(obj_parser *r, const scan_line *l, scan_pos at, size_t n, unsigned form,
                          glint_error *err)
{
    static const uint32_t triangle[3] = {0, 1, 2};
    obj_model *m = r->m;
    m->generate |= !(form & 1u << PART_VN);
    m->textured |= (form & 1u << PART_VT) != 0;
    if (n == 3)
        return add_triangles(r, l, at, triangle, 1, err);
    if (!array_reserve((void **)&r->split, &r->split_cap, 3 * (n - 2), sizeof *r->split) ||
        !triangulate_polygon(&r->work, m->positions, r->face_at, n, r->split))
        return obj_out_of_memory(r, err);
    return add_triangles(r, l, at, r->split, n - 2, err);
}

bool obj_raw_face(obj_parser *r, const scan_line *l, scan_pos at, const int32_t *raw, size_t n, unsigned form,
                  glint_status *s, glint_error *err)
{
    obj_model *m = r->m;
    if (m->corner_count + n >= MODEL_MAX_COUNT || m->triangle_count + n >= MODEL_MAX_COUNT)
        return false;
    if (!obj_face_room(r, n) || !array_reserve((void **)&r->resolved, &r->resolved_cap, n, sizeof *r->resolved)) {
        *s = obj_out_of_memory(r, err);
        return true;
    }
    /* Every corner has a vertex. */
    for (size_t k = 0; k < n; k++) {
        const int32_t *written = raw + 3 * k;
        obj_corner *c = &r->resolved[k];
        c->vt = c->vn = -1;
        if (!obj_absolute_index(written[PART_V], m->position_count, &c->v) ||
            ((form & 1u << PART_VT) && !obj_absolute_index(written[PART_VT], m->uv_count, &c->vt)) ||
            ((form & 1u << PART_VN) && !obj_absolute_index(written[PART_VN], m->normal_count, &c->vn)))
            return false;
    }
    for (size_t k = 0; k < n; k++) {
        r->face_at[k] = (uint32_t)r->resolved[k].v;
        if (!obj_corner_known(r, &r->resolved[k], &r->face[k]) &&
            (*s = obj_corner_id(r, l, at, &r->resolved[k], &r->face[k], err)))
            return true;
    }
    *s = obj_add_face(r, l, at, n, form, err);
    return true;
}

bool obj_face_room(obj_parser *r, size_t n)
{
    size_t cap = r->face_cap;
    return array_reserve((void **)&r->face, &cap, n, sizeof *r->face) &&
           array_reserve((void **)&r->face_at, &r->face_cap, n, sizeof *r->face_at);
}

static glint_status read_face(obj_parser *r, scan_line *l, scan_pos at, glint_error *err)
{
    const char *start = l->p;
    size_t n = 0;
    unsigned first_form = 0;
    glint_status s = GLINT_OK;
    long plain = obj_scan_plain_face(l, &r->raw, &n, &r->raw_cap, &first_form);
    if (plain < 0)
        return obj_out_of_memory(r, err);
    if (plain > 0 && obj_raw_face(r, l, at, r->raw, (size_t)plain, first_form, &s, err))
        return s;
    /* Corner by corner, each checked as it is read, for the messages. */
    l->p = start;
    n = 0;
    while (!s && scan_more(l)) {
        scan_pos here = scan_here(l);
        obj_corner c;
        unsigned form = 0;
        const char *word = NULL;
        size_t len = 0;
        if ((s = obj_read_corner(r, l, here, &c, &form, &word, &len, err)))
            break;
        if (n == 0) {
            first_form = form;
        } else if (form != first_form) {
            char q[32];
            scan_quote(word, len, q, sizeof q);
            return scan_error(l, here, err, "face corner '%s' is %s, but the face's first corner is %s", q,
                              form_text(form), form_text(first_form));
        }
        if (n >= MODEL_MAX_COUNT)
            return obj_too_many(l, here, "corners in one face", err);
        if (!obj_face_room(r, n + 1))
            return obj_out_of_memory(r, err);
        r->face_at[n] = (uint32_t)c.v;
        s = obj_corner_id(r, l, here, &c, &r->face[n++], err);
    }
    if (s)
        return s;
    if (n < 3)
        return scan_error(l, at, err, "a face needs at least 3 corners, got %zu", n);
    return obj_add_face(r, l, at, n, first_form, err);
}

/* Copies the rest of the line into the model's text; *offset is where. */
static glint_status read_name(obj_parser *r, scan_line *l, scan_pos at, const char *keyword, size_t *offset,
                              glint_error *err)
{
    obj_model *m = r->m;
    const char *s, *e;
    if (!scan_rest(l, &s, &e))
        return scan_error(l, at, err, "'%s' needs a name", keyword);
    if (!scan_keep_text(&m->text, &m->text_len, &m->text_cap, s, e, offset))
        return obj_out_of_memory(r, err);
    return GLINT_OK;
}

static bool name_equal(const void *keys, uint32_t id, const void *key)
{
    const obj_model *m = keys;
    return strcmp(m->text + m->materials[id], key) == 0;
}

static glint_status read_usemtl(obj_parser *r, scan_line *l, scan_pos at, glint_error *err)
{
    obj_model *m = r->m;
    size_t offset = 0;
    glint_status s = read_name(r, l, at, "usemtl", &offset, err);
    if (s)
        return s;
    if (m->material_count >= MODEL_MAX_COUNT)
        return obj_too_many(l, at, "materials", err);
    if (!array_reserve((void **)&m->materials, &m->material_cap, m->material_count + 1, sizeof *m->materials))
        return obj_out_of_memory(r, err);
    const char *name = m->text + offset;
    uint32_t id;
    if (!id_table_intern(&r->name_index, id_hash_text(name), name, (uint32_t)m->material_count, name_equal, m,
                         &id))
        return obj_out_of_memory(r, err);
    if (id == m->material_count)
        m->materials[m->material_count++] = offset;
    else
        m->text_len = offset; /* known already: its copy is not needed */
    r->material = (int32_t)id;
    return GLINT_OK;
}

static glint_status read_mtllib(obj_parser *r, scan_line *l, scan_pos at, glint_error *err)
{
    obj_model *m = r->m;
    size_t offset = 0;
    glint_status s = read_name(r, l, at, "mtllib", &offset, err);
    if (!s && !array_reserve((void **)&m->libraries, &m->library_cap, m->library_count + 1, sizeof *m->libraries))
        s = obj_out_of_memory(r, err);
    if (!s)
        m->libraries[m->library_count++] = offset;
    return s;
}

glint_status obj_statement(obj_parser *r, scan_line *l, glint_error *err)
{
    if (!scan_more(l))
        return GLINT_OK;
    scan_pos at = scan_here(l);
    size_t n;
    const char *w = scan_word(l, &n);
    obj_keyword k = obj_keyword_of(w, n);
    switch (k) {
    case KEY_V:
    case KEY_VT:
    case KEY_VN:
        return read_item(r, l, at, obj_item_part(k), err);
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

glint_status obj_feed(obj_parser *r, const char *data, size_t size, bool last, size_t *used, glint_error *err)
{
    const char *p = data, *end = data + size;
    scan_span span;
    glint_status s = GLINT_OK;
    while (!s && p < end && scan_next_line(p, end, last, &span)) {
        scan_line l;
        scan_start(&l, p, span.end, r->line, r->file);
        s = obj_statement(r, &l, err);
        r->line += span.rows;
        p = span.next;
    }
    *used = (size_t)(p - data);
    return s;
}

