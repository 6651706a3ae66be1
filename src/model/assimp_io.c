/* assimp_io.c - the file system Assimp reads a model through: the model's
 * own bytes from memory, so that it is read once and checked before
 * Assimp parses it, and the files it names (glTF buffers) from disk only
 * when the model came from disk. Only regular files in the model's folder
 * or below are opened, never for writing, and only while the model and
 * its buffers fit in half of the machine's memory (Assimp reads a buffer
 * whole: a 3 GB one would be read before anything could refuse it). */
#include <errno.h>
#include <limits.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>
#include <sys/stat.h>
#include <sys/types.h>
#include "core/error.h"
#include "core/open_file.h"
#include "model/assimp_io.h"
#include "model/model_file.h"
#include "scene/scene.h"

/* An open file: a window on the model's bytes, or a stdio stream. */
typedef struct open_file {
    struct aiFile file;
    const unsigned char *data;
    size_t size, pos;
    FILE *fp;
} open_file;

static open_file *of(struct aiFile *f)
{
    return (open_file *)(void *)f->UserData;
}

static size_t file_read(struct aiFile *f, char *buf, size_t size, size_t count)
{
    open_file *o = of(f);
    if (o->fp)
        return fread(buf, size, count, o->fp);
    if (size == 0 || o->pos >= o->size)
        return 0;
    size_t n = (o->size - o->pos) / size;
    if (n > count)
        n = count;
    memcpy(buf, o->data + o->pos, n * size);
    o->pos += n * size;
    return n;
}

static size_t file_write(struct aiFile *f, const char *buf, size_t size, size_t count)
{
    return 0;
}

static size_t file_tell(struct aiFile *f)
{
    open_file *o = of(f);
    if (!o->fp)
        return o->pos;
    off_t p = ftello(o->fp);
    return p < 0 ? 0 : (size_t)p;
}

static size_t file_size(struct aiFile *f)
{
    return of(f)->size;
}

/* Assimp passes backward offsets as size_t; they are read as signed. As with
 * fseek, the position may go past the end, where reads return nothing. */
static enum aiReturn file_seek(struct aiFile *f, size_t offset, enum aiOrigin origin)
{
    open_file *o = of(f);
    long long delta = (long long)offset;
    if (origin != aiOrigin_SET && origin != aiOrigin_CUR && origin != aiOrigin_END)
        return aiReturn_FAILURE;
    if (o->fp) {
        int whence = origin == aiOrigin_SET ? SEEK_SET : origin == aiOrigin_CUR ? SEEK_CUR : SEEK_END;
        return fseeko(o->fp, (off_t)delta, whence) == 0 ? aiReturn_SUCCESS : aiReturn_FAILURE;
    }
    if (origin == aiOrigin_SET) {
        o->pos = offset;
        return aiReturn_SUCCESS;
    }
    long long base = origin == aiOrigin_CUR ? (long long)o->pos : (long long)o->size;
    if (delta < -base || (delta > 0 && base > LLONG_MAX - delta))
        return aiReturn_FAILURE;
    o->pos = (size_t)(base + delta);
    return aiReturn_SUCCESS;
}

static void file_flush(struct aiFile *f)
{
}

/* Opens a file the model names, or NULL, filling src's refusal unless
 * the file does not exist (Assimp then says which it missed). */
static FILE *open_named(assimp_source *src, const char *path, size_t *size)
{
    if (model_file_check_inside(src->dir, path, src->file, "buffer", path, &src->refusal)) {
        src->refused = true;
        return NULL;
    }
    struct stat st;
    int errnum;
    FILE *fp = open_file_stream(path, &st, &errnum);
    if (!fp) {
        if (errnum != ENOENT) {
            error_set(&src->refusal, GLINT_ERR_IO, "%s: cannot read buffer '%s': %s", src->file, path,
                      open_file_reason(errnum));
            src->refused = true;
        }
        return NULL;
    }
    uint64_t limit = model_file_memory_limit();
    if (limit > 0 && ((uint64_t)st.st_size > limit || src->read > limit - (uint64_t)st.st_size)) {
        error_set(&src->refusal, GLINT_ERR_INVALID,
                  "%s: buffer '%s' is too large to import: %llu bytes, which with the model%s come to more than "
                  "half of this machine's memory (%llu bytes)",
                  src->file, path, (unsigned long long)st.st_size,
                  src->read > src->size ? " and the buffers before it" : "", (unsigned long long)limit * 2);
        src->refused = true;
        fclose(fp);
        return NULL;
    }
    src->read += (uint64_t)st.st_size;
    if (scene_note_file(src->scene, &st, &src->refusal)) {
        src->refused = true;
        fclose(fp);
        return NULL;
    }
    *size = (size_t)st.st_size;
    return fp;
}

static struct aiFile *io_open(struct aiFileIO *io, const char *name, const char *mode)
{
    assimp_source *src = (assimp_source *)(void *)io->UserData;
    if (!name || !mode || strpbrk(mode, "wa+"))
        return NULL;
    open_file *o = calloc(1, sizeof *o);
    if (!o)
        return NULL;
    if (strcmp(name, src->name) == 0) {
        o->data = src->data;
        o->size = src->size;
    } else if (!src->dir || !(o->fp = open_named(src, name, &o->size))) {
        free(o);
        return NULL;
    }
    o->file = (struct aiFile){.ReadProc = file_read, .WriteProc = file_write, .TellProc = file_tell,
                              .FileSizeProc = file_size, .SeekProc = file_seek, .FlushProc = file_flush,
                              .UserData = (aiUserData)(void *)o};
    return &o->file;
}

static void io_close(struct aiFileIO *io, struct aiFile *f)
{
    if (!f)
        return;
    open_file *o = of(f);
    if (o->fp)
        fclose(o->fp);
    free(o);
}

void assimp_io_init(struct aiFileIO *io, assimp_source *src)
{
    *io = (struct aiFileIO){.OpenProc = io_open, .CloseProc = io_close, .UserData = (aiUserData)(void *)src};
}
