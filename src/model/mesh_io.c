/* mesh_io.c - opening and reading a model file, and the file system Assimp
 * reads the model through: the model's own bytes from memory, so that it is
 * read once and checked before Assimp parses it, and the files it names
 * (glTF buffers) from disk only when the model came from disk. Only regular
 * files are opened, never for writing. */
#include <errno.h>
#include <fcntl.h>
#include <limits.h>
#include <stdint.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>
#include <sys/stat.h>
#include <unistd.h>
#include "core/error.h"
#include "model/mesh_import.h"

/* The machine's memory in bytes, or 0 when the system does not say. */
static uint64_t memory_bytes(void)
{
    long pages = sysconf(_SC_PHYS_PAGES), page = sysconf(_SC_PAGESIZE);
    return pages > 0 && page > 0 ? (uint64_t)pages * (uint64_t)page : 0;
}

glint_status mesh_import_open(const char *path, int *fd, size_t *size, glint_error *err)
{
    *size = 0;
    *fd = open(path, O_RDONLY | O_CLOEXEC | O_NONBLOCK); /* a FIFO must not block */
    if (*fd < 0)
        return error_set(err, GLINT_ERR_IO, "%s: cannot open: %s", path, strerror(errno));
    struct stat st;
    glint_status s = GLINT_OK;
    uint64_t memory = memory_bytes();
    if (fstat(*fd, &st) != 0)
        s = error_set(err, GLINT_ERR_IO, "%s: cannot read: %s", path, strerror(errno));
    else if (S_ISDIR(st.st_mode))
        s = error_set(err, GLINT_ERR_IO, "%s: cannot read: %s", path, strerror(EISDIR));
    else if (!S_ISREG(st.st_mode))
        s = error_set(err, GLINT_ERR_IO, "%s: cannot read: not a regular file", path);
    else if ((uintmax_t)st.st_size >= SIZE_MAX)
        s = error_set(err, GLINT_ERR_NOMEM, "%s: too large to read", path);
    /* The file is read whole and its model built beside it: one larger
     * than half the memory is refused before reading, rather than found
     * out by the system (or its out-of-memory killer) halfway through. */
    else if (memory > 0 && (uint64_t)st.st_size > memory / 2)
        s = error_set(err, GLINT_ERR_INVALID,
                      "%s: too large to import: %llu bytes, more than half of this machine's memory (%llu bytes)", path,
                      (unsigned long long)st.st_size, (unsigned long long)memory);
    if (s) {
        close(*fd);
        *fd = -1;
        return s;
    }
    *size = (size_t)st.st_size;
    return GLINT_OK;
}

glint_status mesh_import_read_fd(int fd, size_t size, const char *path, unsigned char **data, glint_error *err)
{
    unsigned char *buf = malloc(size ? size : 1);
    size_t got = 0;
    glint_status s = buf ? GLINT_OK : error_set(err, GLINT_ERR_NOMEM, "%s: out of memory reading it", path);
    while (!s && got < size) {
        ssize_t r = read(fd, buf + got, size - got);
        if (r < 0 && errno == EINTR)
            continue;
        if (r <= 0)
            s = error_set(err, GLINT_ERR_IO, "%s: cannot read: %s", path, r < 0 ? strerror(errno) : "file shrank");
        else
            got += (size_t)r;
    }
    if (s) {
        free(buf);
        buf = NULL;
    }
    *data = buf;
    return s;
}

glint_status mesh_import_read_file(const char *path, unsigned char **data, size_t *size, glint_error *err)
{
    int fd;
    *data = NULL;
    glint_status s = mesh_import_open(path, &fd, size, err);
    if (s)
        return s;
    s = mesh_import_read_fd(fd, *size, path, data, err);
    close(fd);
    if (s)
        *size = 0;
    return s;
}

char *mesh_import_path(const char *dir, const char *ref)
{
    size_t len = strlen(dir) + strlen(ref) + 2;
    char *path = malloc(len);
    if (!path)
        return NULL;
    size_t start = 0;
    if (ref[0] != '/' && dir[0] != '\0')
        start = (size_t)snprintf(path, len, "%s/", dir);
    snprintf(path + start, len - start, "%s", ref);
    /* Models made on Windows may separate folders with backslashes. */
    for (char *c = path + start; *c; c++)
        if (*c == '\\')
            *c = '/';
    return path;
}

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

/* Opens a regular file from disk, or NULL. */
static FILE *open_regular(const char *path, size_t *size)
{
    FILE *fp = fopen(path, "rb");
    struct stat st;
    if (fp && fstat(fileno(fp), &st) == 0 && S_ISREG(st.st_mode)) {
        *size = (size_t)st.st_size;
        return fp;
    }
    if (fp)
        fclose(fp);
    return NULL;
}

static struct aiFile *io_open(struct aiFileIO *io, const char *name, const char *mode)
{
    const mesh_source *src = (const mesh_source *)(void *)io->UserData;
    if (!name || !mode || strpbrk(mode, "wa+"))
        return NULL;
    open_file *o = calloc(1, sizeof *o);
    if (!o)
        return NULL;
    if (strcmp(name, src->name) == 0) {
        o->data = src->data;
        o->size = src->size;
    } else if (!src->disk || !(o->fp = open_regular(name, &o->size))) {
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

void mesh_import_io(struct aiFileIO *io, mesh_source *src)
{
    *io = (struct aiFileIO){.OpenProc = io_open, .CloseProc = io_close, .UserData = (aiUserData)(void *)src};
}
