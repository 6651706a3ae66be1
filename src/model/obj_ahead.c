/* obj_ahead.c - parsing OBJ text ahead, in threads. A large text is cut
 * at line breaks into pieces, one per thread, and each thread parses the
 * statements of its piece into records without touching the model: items
 * as the floats they add, faces as their indices as written. The records
 * are then merged into the model in the file's order, as obj_statement()
 * would read them. A line the parse could not take whole (an error,
 * usemtl, mtllib), and a record whose indices do not resolve against the
 * counts so far or that could pass a limit, goes to obj_statement() itself
 * at its place in the merge, so the model and every message are those of
 * reading the text in one pass, wherever the cuts fall and however many
 * threads there are. */
#include <stdlib.h>
#include "core/array.h"
#include "model/obj_ahead.h"

/* What a line was parsed as. */
typedef enum ahead_kind {
    AHEAD_ITEM,               /* a v, vt or vn statement, parsed */
    AHEAD_FACE,               /* an f statement, its corners parsed */
    AHEAD_LINE                /* a line for obj_statement() to read */
} ahead_kind;

/* The record of one line: what the merge does with it. */
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

/* Parses the corners of a face that is not plain (obj_scan_plain_face) on
 * l into pc->corners, one by one: their count and *form, or 0, with
 * pc->corners as it was, when the line is not to be taken whole. */
static size_t ahead_corners(text_piece *pc, scan_line *l, unsigned *form)
{
    size_t first = pc->corner_count, n = 0;
    while (scan_more(l)) {
        raw_corner rc;
        if (!obj_scan_corner(l, &rc) || (n > 0 && rc.form != *form) || n + 1 >= MODEL_MAX_COUNT)
            goto refused;
        *form = rc.form;
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
    if (n >= 3)
        return n;
refused:
    pc->corner_count = first;
    return 0;
}

/* Parses the corners of the face on l into pc->corners and completes *a as
 * AHEAD_FACE; leaves *a and pc->corners as they were when it cannot. */
static void ahead_face(text_piece *pc, scan_line *l, ahead *a)
{
    size_t first = pc->corner_count;
    unsigned form = 0;
    long n = obj_scan_plain_face(l, &pc->corners, &pc->corner_count, &pc->corner_cap, &form);
    if (n < 0)
        pc->no_memory = true;
    else if (n == 0)
        n = (long)ahead_corners(pc, l, &form);
    if (n <= 0)
        return;
    a->kind = AHEAD_FACE;
    a->what = (uint8_t)form;
    a->corners = (uint32_t)n;
    a->u.first = first;
}

/* Parses the line at p into *a when it is a plain v, vt, vn or f line
 * (obj_plain_item, obj_scan_plain_face) ending in a line break: nearly
 * every line of a large file, found and read in one pass rather than
 * looked for and then read. Returns the byte after its break; NULL, with
 * pc as it was, for any other line. */
static const char *plain_line(text_piece *pc, const char *p, ahead *a)
{
    const char *end = pc->end;
    if (end - p < 3)
        return NULL;
    size_t n = p[1] == ' ' ? 1 : p[2] == ' ' ? 2 : 0;
    obj_keyword k = n ? obj_keyword_of(p, n) : KEY_OTHER;
    scan_line l;
    scan_start(&l, p + n, end, 1, pc->file);
    if (k == KEY_V || k == KEY_VT || k == KEY_VN) {
        if (!obj_plain_item(&l, obj_item_part(k), a->u.item) || l.p == end || *l.p != '\n')
            return NULL;
        a->kind = AHEAD_ITEM;
        a->what = (uint8_t)obj_item_part(k);
        return l.p + 1;
    }
    if (k != KEY_F)
        return NULL;
    size_t first = pc->corner_count;
    unsigned form;
    long corners = obj_scan_plain_face(&l, &pc->corners, &pc->corner_count, &pc->corner_cap, &form);
    if (corners <= 0 || l.p == end || *l.p != '\n') {
        pc->corner_count = first;
        return NULL;
    }
    a->kind = AHEAD_FACE;
    a->what = (uint8_t)form;
    a->corners = (uint32_t)corners;
    a->u.first = first;
    return l.p + 1;
}

/* Parses the logical line [p, span->end), the piece's row `row`, into *a
 * as far as it can be; false for a line that needs no record (blank, a
 * comment, a statement glint ignores). */
static bool parse_line(text_piece *pc, const char *p, const scan_span *span, long row, ahead *a)
{
    scan_line l;
    scan_start(&l, p, span->end, 1 + row, pc->file);
    if (!scan_more(&l))
        return false;
    scan_pos at = scan_here(&l);
    size_t n;
    const char *w = scan_word(&l, &n);
    obj_keyword k = obj_keyword_of(w, n);
    glint_error unused;
    if ((k == KEY_V || k == KEY_VT || k == KEY_VN) && !obj_parse_item(&l, at, obj_item_part(k), a->u.item, &unused)) {
        a->kind = AHEAD_ITEM;
        a->what = (uint8_t)obj_item_part(k);
    } else if (k == KEY_F) {
        ahead_face(pc, &l, a);
    }
    return k != KEY_OTHER;
}

void *text_piece_parse(void *arg)
{
    /* A copy of its own: the pieces lie side by side, and a thread writing
     * to its counts there would slow down the others sharing their cache
     * lines (both threads of the wavy mesh took longer than one). */
    text_piece own = *(text_piece *)arg, *pc = &own;
    const char *p = pc->start;
    long row = 0;
    while (!pc->no_memory && p < pc->end) {
        ahead a = {.offset = (uint32_t)(p - pc->start), .row = (uint32_t)row, .kind = AHEAD_LINE};
        const char *next = plain_line(pc, p, &a);
        long rows = 1;
        bool kept = true;
        if (!next) {
            scan_span span;
            if (!scan_next_line(p, pc->end, pc->last, &span))
                break;
            kept = parse_line(pc, p, &span, row, &a);
            next = span.next;
            rows = span.rows;
        }
        if (kept && !array_reserve((void **)&pc->items, &pc->cap, pc->count + 1, sizeof *pc->items))
            pc->no_memory = true;
        else if (kept)
            pc->items[pc->count++] = a;
        row += rows;
        p = next;
    }
    pc->rows = row;
    *(text_piece *)arg = own;
    return NULL;
}

/* Reads the line of record a with obj_statement(); `base` is the number of
 * the piece's first line. */
static glint_status merge_line(obj_parser *r, const text_piece *pc, const ahead *a, long base, glint_error *err)
{
    const char *p = pc->start + a->offset;
    scan_span span;
    scan_line l;
    scan_next_line(p, pc->end, pc->last, &span);
    scan_start(&l, p, span.end, base + a->row, r->file);
    return obj_statement(r, &l, err);
}

/* Adds the face of record a as its line would be read; false, with nothing
 * changed, when obj_statement() is to read its line (obj_raw_face). */
static bool merge_face(obj_parser *r, const text_piece *pc, const ahead *a, long base, glint_status *s,
                       glint_error *err)
{
    /* Nothing can fail but for memory: the place is for form's sake. */
    scan_line l;
    const char *p = pc->start + a->offset;
    scan_start(&l, p, p, base + a->row, r->file);
    scan_pos at = {base + a->row, 1};
    return obj_raw_face(r, &l, at, pc->corners + a->u.first, a->corners, a->what, s, err);
}

glint_status text_piece_merge(obj_parser *r, const text_piece *pc, glint_error *err)
{
    long base = r->line;
    glint_status s = GLINT_OK;
    for (size_t i = 0; !s && i < pc->count; i++) {
        const ahead *a = &pc->items[i];
        if (a->kind == AHEAD_ITEM && obj_item_count(r->m, a->what) < MODEL_MAX_COUNT)
            s = obj_add_item(r->m, a->what, a->u.item) ? GLINT_OK : obj_out_of_memory(r, err);
        else if (a->kind != AHEAD_FACE || !merge_face(r, pc, a, base, &s, err))
            s = merge_line(r, pc, a, base, err);
    }
    if (!s && pc->no_memory)
        s = obj_out_of_memory(r, err);
    r->line = base + pc->rows;
    return s;
}

void text_piece_set(text_piece *pc, const char *start, const char *end, bool last, const char *file)
{
    /* The records' room is kept from block to block: fresh memory for
     * every block cost 5% in page faults. */
    *pc = (text_piece){.start = start, .end = end, .last = last, .file = file, .items = pc->items, .cap = pc->cap,
                       .corners = pc->corners, .corner_cap = pc->corner_cap};
}

void text_piece_free(text_piece *pc)
{
    free(pc->items);
    free(pc->corners);
    *pc = (text_piece){0};
}
