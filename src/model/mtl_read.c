/* mtl_read.c - the statements of MTL text, read line by line.
 *
 * Read: newmtl, Kd, Ks, Ka, Ke (r [g b], g and b being r when left out),
 * Ns, Ni, d (with an optional -halo), Tr, illum, and the maps map_Kd, bump
 * (or map_Bump, map_bump: a height map, its -bm read) and norm (a normal
 * map), each with its options skipped and the rest of the line the file.
 * Ignored: statements before the first newmtl, the spectral and xyz forms
 * of colours, and every other statement (other maps, Tf, sharpness, other
 * PBR extensions). */
#include <math.h>
#include <stdlib.h>
#include <string.h>
#include "core/array.h"
#include "core/error.h"
#include "model/mtl_read.h"
#include "model/text_scan.h"

#define MAX_MATERIALS (1 << 30)

mtl_material mtl_default(void)
{
    return (mtl_material){
        .kd = {0.6, 0.6, 0.6}, .ni = 1, .d = 1, .illum = 1, .map_kd = MTL_NO_TEXT, .bump = MTL_NO_TEXT,
        .bump_multiplier = 1, .norm = MTL_NO_TEXT,
    };
}

static glint_status out_of_memory(const char *file, glint_error *err)
{
    return error_set(err, GLINT_ERR_NOMEM, "%s: out of memory", file);
}

/* Kd and its kin: r, or r g b. */
static glint_status read_color(scan_line *l, scan_pos at, const char *keyword, double *rgb, glint_error *err)
{
    scan_line peek = *l;
    size_t len;
    if (scan_more(&peek)) {
        const char *w = scan_word(&peek, &len);
        if ((len == 8 && memcmp(w, "spectral", 8) == 0) || (len == 3 && memcmp(w, "xyz", 3) == 0))
            return GLINT_OK;
    }
    double c[3];
    int n = scan_numbers(l, c, NULL, 3, err);
    if (n < 0)
        return GLINT_ERR_INVALID;
    if (n != 1 && n != 3)
        return scan_error(l, at, err, "'%s' needs 1 or 3 numbers (r [g b]), got %d", keyword, n);
    for (int k = 0; k < 3; k++)
        rgb[k] = c[n == 1 ? 0 : k];
    return GLINT_OK;
}

/* A statement of one number. */
static glint_status read_one(scan_line *l, scan_pos at, const char *keyword, double *out, glint_error *err)
{
    int n = scan_numbers(l, out, NULL, 1, err);
    if (n < 0)
        return GLINT_ERR_INVALID;
    if (n != 1)
        return scan_error(l, at, err, "'%s' needs 1 number, got %d", keyword, n);
    return GLINT_OK;
}

static glint_status read_illum(scan_line *l, scan_pos at, int *out, glint_error *err)
{
    double x = 0;
    glint_status s = read_one(l, at, "illum", &x, err);
    if (s)
        return s;
    if (!(x >= 0 && x <= 10 && x == floor(x)))
        return scan_error(l, at, err, "'illum' needs a whole number from 0 to 10, got %g", x);
    *out = (int)x;
    return GLINT_OK;
}

/* Copies [s, e) into the library's text; *offset is where. */
static glint_status keep_text(mtl_library *lib, const char *s, const char *e, size_t *offset, const char *file,
                              glint_error *err)
{
    if (!scan_keep_text(&lib->text, &lib->text_len, &lib->text_cap, s, e, offset))
        return out_of_memory(file, err);
    return GLINT_OK;
}

/* Skips a map's options (-s 1 1 1, -bm 0.5, -clamp on, ...): each takes
 * its fixed words, then as many more numbers as it may have; -bm's number
 * goes to *bm. */
static void skip_options(scan_line *l, double *bm)
{
    static const struct {
        const char *name;
        int least, most;
    } options[] = {
        {"-blendu", 1, 1}, {"-blendv", 1, 1}, {"-bm", 1, 1}, {"-boost", 1, 1}, {"-cc", 1, 1},
        {"-clamp", 1, 1},  {"-imfchan", 1, 1}, {"-mm", 2, 2}, {"-o", 1, 3},    {"-s", 1, 3},
        {"-t", 1, 3},      {"-texres", 1, 1}, {"-type", 1, 1},
    };
    while (scan_more(l) && *l->p == '-') {
        size_t len;
        const char *w = scan_word(l, &len);
        for (size_t i = 0; i < sizeof options / sizeof options[0]; i++) {
            if (!scan_word_is(w, len, options[i].name))
                continue;
            scan_line before = *l;
            double number;
            if (scan_word_is(w, len, "-bm") && scan_number(&before, &number) == SCAN_OK && isfinite(number))
                *bm = number;
            for (int k = 0; k < options[i].least && scan_more(l); k++)
                scan_word(l, &len);
            double x;
            for (int k = options[i].least; k < options[i].most && scan_number(l, &x) == SCAN_OK; k++)
                ;
            break;
        }
    }
}

static bool name_equal(const void *keys, uint32_t id, const void *key)
{
    const mtl_library *lib = keys;
    return strcmp(lib->text + lib->items[id].name, key) == 0;
}

/* newmtl: a new material, or the one of that name started again. */
static glint_status read_newmtl(mtl_library *lib, scan_line *l, scan_pos at, mtl_material **current,
                                glint_error *err)
{
    const char *s, *e;
    size_t offset = 0;
    if (!scan_rest(l, &s, &e))
        return scan_error(l, at, err, "'newmtl' needs a name");
    if (lib->count >= MAX_MATERIALS)
        return scan_error(l, at, err, "too many materials (more than %d)", MAX_MATERIALS);
    glint_status st = keep_text(lib, s, e, &offset, l->file, err);
    if (st)
        return st;
    if (!array_reserve((void **)&lib->items, &lib->cap, lib->count + 1, sizeof *lib->items))
        return out_of_memory(l->file, err);
    const char *name = lib->text + offset;
    uint32_t id;
    if (!id_table_intern(&lib->index, id_hash_text(name), name, (uint32_t)lib->count, name_equal, lib, &id))
        return out_of_memory(l->file, err);
    bool fresh = id == lib->count;
    if (fresh)
        lib->count++;
    else
        lib->text_len = offset; /* the name is kept already */
    mtl_material *m = &lib->items[id];
    size_t kept = fresh ? offset : m->name;
    *m = mtl_default();
    m->name = kept;
    *current = m;
    return GLINT_OK;
}

static glint_status statement(mtl_library *lib, scan_line *l, mtl_material **current, glint_error *err)
{
    if (!scan_more(l))
        return GLINT_OK;
    scan_pos at = scan_here(l);
    size_t n;
    const char *w = scan_word(l, &n);
    if (scan_word_is(w, n, "newmtl"))
        return read_newmtl(lib, l, at, current, err);
    mtl_material *m = *current;
    if (!m)
        return GLINT_OK;
    static const char *const colors[] = {"Kd", "Ks", "Ka", "Ke"};
    double *rgb[] = {m->kd, m->ks, m->ka, m->ke};
    for (int i = 0; i < 4; i++)
        if (scan_word_is(w, n, colors[i]))
            return read_color(l, at, colors[i], rgb[i], err);
    if (scan_word_is(w, n, "Ns"))
        return read_one(l, at, "Ns", &m->ns, err);
    if (scan_word_is(w, n, "Ni"))
        return read_one(l, at, "Ni", &m->ni, err);
    if (scan_word_is(w, n, "d")) {
        scan_line peek = *l;
        const char *option = scan_more(&peek) ? scan_word(&peek, &n) : NULL;
        if (option && scan_word_is(option, n, "-halo"))
            *l = peek;
        return read_one(l, at, "d", &m->d, err);
    }
    if (scan_word_is(w, n, "Tr")) {
        double tr = 0;
        glint_status s = read_one(l, at, "Tr", &tr, err);
        m->d = 1 - tr;
        return s;
    }
    if (scan_word_is(w, n, "illum"))
        return read_illum(l, at, &m->illum, err);
    static const char *const maps[] = {"map_Kd", "bump", "map_Bump", "map_bump", "norm"};
    for (size_t k = 0; k < sizeof maps / sizeof maps[0]; k++) {
        if (!scan_word_is(w, n, maps[k]))
            continue;
        const char *s, *e;
        double bm = 1;
        skip_options(l, &bm);
        if (!scan_rest(l, &s, &e))
            return scan_error(l, at, err, "'%s' needs a file name", maps[k]);
        if (k >= 1 && k <= 3)
            m->bump_multiplier = bm;
        /* keep_text may move the library's text, never its items. */
        return keep_text(lib, s, e, k == 0 ? &m->map_kd : k == 4 ? &m->norm : &m->bump, l->file, err);
    }
    return GLINT_OK;
}

glint_status mtl_read(mtl_library *lib, const char *data, size_t size, const char *file, glint_error *err)
{
    const char *p = data, *end = data + size;
    mtl_material *current = NULL;
    long line = 1;
    scan_span span;
    glint_status s = GLINT_OK;
    while (!s && p < end && scan_next_line(p, end, true, &span)) {
        scan_line l;
        scan_start(&l, p, span.end, line, file);
        s = statement(lib, &l, &current, err);
        line += span.rows;
        p = span.next;
    }
    return s;
}

const mtl_material *mtl_find(const mtl_library *lib, const char *name)
{
    uint32_t id;
    return id_table_find(&lib->index, id_hash_text(name), name, name_equal, lib, &id) ? &lib->items[id] : NULL;
}

void mtl_free(mtl_library *lib)
{
    free(lib->items);
    free(lib->text);
    id_table_free(&lib->index);
    *lib = (mtl_library){0};
}
