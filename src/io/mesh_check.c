/* mesh_check.c - which formats the importer takes, and the checks made on a
 * model's bytes before Assimp parses them. Assimp picks its reader by
 * extension, but falls back to sniffing the content with every reader it has
 * when none claims the file; and its PLY reader allocates whatever element
 * counts the header claims. Both are stopped here, so only the five readers
 * glint documents ever see a file, and memory stays in proportion to it. */
#include <ctype.h>
#include <limits.h>
#include <string.h>
#include <strings.h>
#include "core/error.h"
#include "io/mesh_import.h"

static const struct {
    const char *ext;
    mesh_format format;
} formats[] = {
    {"obj", MESH_FORMAT_OBJ}, {"ply", MESH_FORMAT_PLY}, {"stl", MESH_FORMAT_STL},
    {"gltf", MESH_FORMAT_GLTF}, {"glb", MESH_FORMAT_GLB},
};

mesh_format mesh_import_format(const char *name)
{
    const char *dot = name ? strrchr(name, '.') : NULL;
    if (!dot || strchr(dot, '/'))
        return MESH_FORMAT_NONE;
    for (size_t i = 0; i < sizeof formats / sizeof formats[0]; i++)
        if (strcasecmp(dot + 1, formats[i].ext) == 0)
            return formats[i].format;
    return MESH_FORMAT_NONE;
}

const char *mesh_import_extension(mesh_format f)
{
    for (size_t i = 0; i < sizeof formats / sizeof formats[0]; i++)
        if (formats[i].format == f)
            return formats[i].ext;
    return "";
}

/* A header line split into at most 4 words, each cut to fit. */
typedef struct line_words {
    char w[4][40];
    int n;
} line_words;

/* Splits the line at data[*pos...] into words and moves *pos past it. */
static void next_line(const unsigned char *data, size_t size, size_t *pos, line_words *lw)
{
    memset(lw, 0, sizeof *lw);
    size_t i = *pos;
    while (i < size && data[i] != '\n') {
        while (i < size && data[i] != '\n' && isspace(data[i]))
            i++;
        if (i >= size || data[i] == '\n')
            break;
        size_t len = 0;
        while (i < size && !isspace(data[i])) {
            if (lw->n < 4 && len + 1 < sizeof lw->w[0])
                lw->w[lw->n][len++] = isprint(data[i]) ? (char)data[i] : '?';
            i++;
        }
        lw->n++;
    }
    *pos = i < size ? i + 1 : size;
}

/* Bytes one value of a PLY scalar type takes in a binary file. */
static unsigned long long ply_type_size(const char *type)
{
    static const struct {
        const char *name;
        unsigned size;
    } types[] = {
        {"char", 1}, {"uchar", 1}, {"int8", 1}, {"uint8", 1}, {"short", 2}, {"ushort", 2},
        {"int16", 2}, {"uint16", 2}, {"int", 4}, {"uint", 4}, {"int32", 4}, {"uint32", 4},
        {"float", 4}, {"float32", 4}, {"double", 8}, {"float64", 8},
    };
    for (size_t i = 0; i < sizeof types / sizeof types[0]; i++)
        if (strcmp(type, types[i].name) == 0)
            return types[i].size;
    return 1;
}

/* A decimal count, ULLONG_MAX when it overflows, 0 when it is not a number
 * (Assimp then refuses the header itself). */
static unsigned long long parse_count(const char *s)
{
    unsigned long long n = 0;
    for (; *s; s++) {
        if (!isdigit((unsigned char)*s))
            return 0;
        unsigned d = (unsigned)(*s - '0');
        n = n > (ULLONG_MAX - d) / 10 ? ULLONG_MAX : n * 10 + d;
    }
    return n;
}

typedef struct ply_element {
    char name[40];
    unsigned long long count;
    unsigned long long min_bytes;   /* the least one item can take in the file */
} ply_element;

static glint_status check_element(const ply_element *e, size_t body, const char *file, glint_error *err)
{
    unsigned long long least = e->min_bytes ? e->min_bytes : 1;
    if (e->count > body / least)
        return error_set(err, GLINT_ERR_INVALID,
                         "%s: PLY element '%s' claims %llu items, more than the file's %zu bytes of data can hold",
                         file, e->name, e->count, body);
    return GLINT_OK;
}

/* Walks the header; lines it cannot follow are left for Assimp to refuse. */
static glint_status check_ply(const unsigned char *data, size_t size, const char *file, glint_error *err)
{
    size_t pos = 0;
    line_words lw;
    bool binary = false;
    ply_element elems[64];
    int n = 0;
    while (pos < size) {
        next_line(data, size, &pos, &lw);
        if (lw.n >= 2 && strcmp(lw.w[0], "format") == 0)
            binary = strncmp(lw.w[1], "binary", 6) == 0;
        else if (lw.n >= 3 && strcmp(lw.w[0], "element") == 0) {
            if (n == (int)(sizeof elems / sizeof elems[0]))
                return error_set(err, GLINT_ERR_INVALID, "%s: PLY header declares more than %d elements", file, n);
            elems[n] = (ply_element){.count = parse_count(lw.w[2]), .min_bytes = 0};
            memcpy(elems[n].name, lw.w[1], sizeof elems[n].name);
            n++;
        } else if (lw.n >= 3 && strcmp(lw.w[0], "property") == 0 && n > 0) {
            bool list = strcmp(lw.w[1], "list") == 0;
            /* ASCII takes at least a character and a separator a value; a
             * list at least its length. */
            elems[n - 1].min_bytes += binary ? ply_type_size(list ? lw.w[2] : lw.w[1]) : 2;
        } else if (lw.n >= 1 && strcmp(lw.w[0], "end_header") == 0) {
            for (int i = 0; i < n; i++) {
                glint_status s = check_element(&elems[i], size - pos, file, err);
                if (s)
                    return s;
            }
            return GLINT_OK;
        }
    }
    /* Assimp's reader loops for ever on a header cut short. */
    return error_set(err, GLINT_ERR_INVALID, "%s: PLY header has no end_header line", file);
}

glint_status mesh_import_check(mesh_format f, const unsigned char *data, size_t size, const char *file,
                               glint_error *err)
{
    if (f == MESH_FORMAT_GLB && (size < 4 || memcmp(data, "glTF", 4) != 0))
        return error_set(err, GLINT_ERR_INVALID, "%s: not a binary glTF file (it does not start with 'glTF')", file);
    if (f == MESH_FORMAT_GLTF) {
        size_t i = size >= 3 && memcmp(data, "\xEF\xBB\xBF", 3) == 0 ? 3 : 0;
        while (i < size && isspace(data[i]))
            i++;
        if (i == size || data[i] != '{')
            return error_set(err, GLINT_ERR_INVALID, "%s: not a glTF file (it does not start with a JSON object)",
                             file);
    }
    if (f == MESH_FORMAT_PLY)
        return check_ply(data, size, file, err);
    return GLINT_OK;
}
