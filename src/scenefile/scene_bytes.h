/* scene_bytes.h - a scene file's bytes, read whole and bounded, for the
 * scene readers (scene_reader.h). */
#ifndef GLINT_SCENEFILE_SCENE_BYTES_H
#define GLINT_SCENEFILE_SCENE_BYTES_H

#include <stdbool.h>
#include <stdio.h>
#include <sys/stat.h>
#include "glint.h"

/* Reads all of the stream f, named `name`, to its end, at most
 * SCENE_FILE_MAX_BYTES; NULL with a message in err on failure (the caller
 * frees the bytes). */
char *scene_bytes_of_stream(FILE *f, const char *name, size_t *size, glint_error *err);

/* Reads a whole file (bounded), with *st its status; NULL with a message in
 * err on failure: "cannot include" for an include, which is what the user
 * wrote at the include's place, else "cannot read scene". */
char *scene_bytes_of_file(const char *path, bool include, size_t *size, struct stat *st, glint_error *err);

#endif
