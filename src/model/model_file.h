/* model_file.h - opening and reading a model file and the files it names
 * (MTL files, textures), and their paths. */
#ifndef GLINT_MODEL_MODEL_FILE_H
#define GLINT_MODEL_MODEL_FILE_H

#include <stddef.h>
#include "glint.h"

/* Opens `path` for reading into *fd: a regular file (opening a FIFO does
 * not block, and it is refused) of at most half the machine's memory;
 * *size is its size. */
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

#endif
