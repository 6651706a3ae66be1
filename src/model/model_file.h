/* model_file.h - opening and reading a model file and the files it names
 * (MTL files, textures), and their paths. */
#ifndef GLINT_MODEL_MODEL_FILE_H
#define GLINT_MODEL_MODEL_FILE_H

#include <stddef.h>
#include <stdint.h>
#include "glint.h"

/* Half of the machine's memory in bytes, or 0 when the system does not
 * say: the most a model, with the buffers it names, may take to be read
 * whole (its model is built beside it). */
uint64_t model_file_memory_limit(void);

/* Opens `path` for reading into *fd: a regular file (opening a FIFO does
 * not block, and it is refused) of at most half the machine's memory;
 * *size is its size. When the file cannot be opened errno says why
 * (ENOENT: there is none), and so after model_file_read. */
glint_status model_file_open(const char *path, int *fd, size_t *size, glint_error *err);

/* Reads the `size` bytes of the open file fd (named `path` in messages)
 * into *data, which the caller frees. */
glint_status model_file_read_fd(int fd, size_t size, const char *path, unsigned char **data, glint_error *err);

/* Opens and reads a whole file; *data is freed by the caller. */
glint_status model_file_read(const char *path, unsigned char **data, size_t *size, glint_error *err);

/* The path of a file a model names, `ref` as written, relative to the
 * model's directory `dir` unless absolute, its backslashes read as '/' (as
 * models made on Windows separate folders). NULL when out of memory. */
char *model_file_path(const char *dir, const char *ref);

/* Refuses `path`, which the model `file` (named so in messages) in folder
 * `dir` names as `ref`, a `what` ("texture", "MTL file", "buffer"), when
 * it resolves (links followed) outside dir: a model may name only files
 * in its own folder or below. A path that does not resolve passes, for
 * its open to say why. */
glint_status model_file_check_inside(const char *dir, const char *path, const char *file, const char *what,
                                     const char *ref, glint_error *err);

#endif
