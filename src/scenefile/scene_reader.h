/* scene_reader.h - the scene-file formats glint reads, one record each.
 *
 * A format is one reader exporting one scene_reader (the YAML reader in
 * scene_file.c, the NFF reader in nff_read.c); scene_readers.c lists them, one line each, and picks the
 * reader for a file by its name's extension, YAML for any other name. The
 * public glint_scene_load_file, _load_memory and _load_stream go through it.
 * Adding a format: docs/architecture.md. */
#ifndef GLINT_SCENEFILE_SCENE_READER_H
#define GLINT_SCENEFILE_SCENE_READER_H

#include <stdio.h>
#include "glint.h"

typedef struct scene_reader {
    const char *name;                  /* for messages: "YAML" */
    const char *const *extensions;     /* with the dot, any case, NULL-terminated */
    /* glint_scene_load_file, _load_memory and _load_stream for this format. */
    glint_scene *(*load_file)(const char *path, const glint_load_options *options, glint_error *err);
    glint_scene *(*load_memory)(const char *data, size_t size, const char *name, const glint_load_options *options,
                                glint_error *err);
    glint_scene *(*load_stream)(FILE *in, const char *name, const glint_load_options *options, glint_error *err);
} scene_reader;

extern const scene_reader yaml_scene_reader, nff_scene_reader;

/* The reader of the file called `name`, by its extension: the first reader
 * that lists it, else the YAML reader. */
const scene_reader *scene_reader_for(const char *name);

#endif
