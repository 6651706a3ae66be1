/* scene_bytes.c - a scene file's bytes, read whole and bounded by
 * SCENE_FILE_MAX_BYTES, for every scene reader (YAML, NFF). */
#include <errno.h>
#include <stdlib.h>
#include <string.h>
#include "core/array.h"
#include "core/error.h"
#include "core/open_file.h"
#include "scenefile/scene_bytes.h"
#include "scenefile/scene_file.h"

/* A stream of unknown size is read this many bytes at a time. */
#define READ_STEP 65536

/* Reads all of f as scene_bytes_of_stream does, into room for `first`
 * bytes at first, growing by READ_STEP only when that is full. A regular
 * file asks for its size and one more byte, so that it is read in one
 * piece into room made once (not grown, each move needing the old room
 * and the new at once, and copying the bytes again). */
static char *bytes_of_stream(FILE *f, const char *name, size_t first, size_t *size, glint_error *err)
{
    char *data = NULL;
    size_t cap = 0, n = 0, got;
    do {
        if (n == cap && !array_reserve((void **)&data, &cap, n ? n + READ_STEP : first, 1)) {
            free(data);
            error_set(err, GLINT_ERR_NOMEM, "out of memory reading '%s'", name);
            return NULL;
        }
        /* One byte past the limit tells a stream at the limit from a larger one. */
        size_t left = (size_t)SCENE_FILE_MAX_BYTES + 1 - n;
        n += got = fread(data + n, 1, cap - n < left ? cap - n : left, f);
    } while (got > 0 && n <= (size_t)SCENE_FILE_MAX_BYTES);
    if (ferror(f))
        error_set(err, GLINT_ERR_IO, "cannot read scene '%s': %s", name, strerror(errno));
    else if (n > (size_t)SCENE_FILE_MAX_BYTES)
        error_set(err, GLINT_ERR_INVALID, "scene '%s' is too large: more than %ld bytes (the limit)", name,
                  SCENE_FILE_MAX_BYTES);
    else {
        *size = n;
        return data;
    }
    free(data);
    return NULL;
}

char *scene_bytes_of_stream(FILE *f, const char *name, size_t *size, glint_error *err)
{
    return bytes_of_stream(f, name, READ_STEP, size, err);
}

char *scene_bytes_of_file(const char *path, bool include, size_t *size, struct stat *st, glint_error *err)
{
    int errnum;
    FILE *f = open_file_stream(path, st, &errnum);
    if (!f) {
        error_set(err, GLINT_ERR_IO, "cannot %s '%s': %s", include ? "include" : "read scene", path,
                  open_file_reason(errnum));
        return NULL;
    }
    char *data = NULL;
    /* The size first, so that a file too large is refused unread. */
    if (st->st_size > SCENE_FILE_MAX_BYTES)
        error_set(err, GLINT_ERR_INVALID, "scene '%s' is too large: %lld bytes (limit %ld)", path,
                  (long long)st->st_size, SCENE_FILE_MAX_BYTES);
    else
        data = bytes_of_stream(f, path, S_ISREG(st->st_mode) ? (size_t)st->st_size + 1 : READ_STEP, size, err);
    fclose(f);
    return data;
}
