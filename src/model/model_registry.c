/* model_registry.c - the model readers glint has, a line each, in the
 * order their formats are told to people ("glint imports .obj, .ply,
 * ..."). A new reader is its own file, its name in model_format.h and a
 * line here; a new format of an existing reader is a line of its table. */
#include <stdio.h>
#include <string.h>
#include <strings.h>
#include "model/model_format.h"

static const model_reader *const readers[] = {
    &obj_reader,    /* OBJ and its MTL files, glint's own reader */
    &assimp_reader, /* PLY, STL, glTF and GLB through Assimp */
};

/* Format i of all the readers' formats in order, with its reader in
 * *reader; NULL past the last one. */
static const model_format *format_at(size_t i, const model_reader **reader)
{
    for (size_t r = 0; r < sizeof readers / sizeof readers[0]; r++)
        for (const model_format *f = readers[r]->formats; f->extension; f++)
            if (i-- == 0) {
                *reader = readers[r];
                return f;
            }
    return NULL;
}

const model_format *model_format_of(const char *name, const model_reader **reader)
{
    const char *dot = name ? strrchr(name, '.') : NULL;
    const model_reader *r;
    const model_format *f;
    if (!dot || strchr(dot, '/'))
        return NULL;
    for (size_t i = 0; (f = format_at(i, &r)); i++)
        if (strcasecmp(dot + 1, f->extension) == 0) {
            if (reader)
                *reader = r;
            return f;
        }
    return NULL;
}

void model_format_list(char *out, size_t size)
{
    const model_reader *r;
    const model_format *f, *next = format_at(0, &r);
    size_t len = 0;
    out[0] = '\0';
    for (size_t i = 0; (f = next); i++) {
        next = format_at(i + 1, &r);
        int n = snprintf(out + len, size - len, "%s.%s", i == 0 ? "" : next ? ", " : " and ", f->extension);
        if (n < 0 || (size_t)n >= size - len)
            return;
        len += (size_t)n;
    }
}

bool glint_is_model_path(const char *path)
{
    return model_format_of(path, NULL) != NULL;
}
