/* model_format.h - the model formats glint imports and the readers that
 * take them (docs/meshes.md). A reader is one file exporting one
 * model_reader record, and model_registry.c lists the readers, a line
 * each: whatever names the formats (glint_is_model_path, the format of a
 * file name, the message about a format glint does not import, Assimp's
 * hint) reads that one list. */
#ifndef GLINT_MODEL_MODEL_FORMAT_H
#define GLINT_MODEL_MODEL_FORMAT_H

#include <stdbool.h>
#include <stddef.h>
#include "glint.h"

/* Refuses bytes that would send a format's reader astray, with a message
 * starting with `file`. */
typedef glint_status (*model_check_fn)(const unsigned char *data, size_t size, const char *file, glint_error *err);

/* A format, known by the extension of its file names. */
typedef struct model_format {
    const char *extension;    /* lower case, without the dot; names match it in any case. NULL ends a list */
    model_check_fn check;     /* run on a file's bytes before its reader sees them; NULL for none */
    bool names_materials;     /* the format gives its materials names (OBJ, glTF); a material its reader
                                 reports for another (PLY, STL) is the reader's own stand-in */
} model_format;

/* One import under way, as the dispatcher (model_import.c) hands it to a
 * reader. */
typedef struct model_import {
    const char *file;         /* the model, as named in messages */
    const model_format *format;
    const char *stem;         /* file name less directory and extension: what its materials are named after */
    const char *dir;          /* directory the files it names are relative to; NULL when it may read none
                                 (a model from memory) */
    double crease;            /* degrees, in (0, 180]: where generated normals stay sharp */
    int default_material;     /* for triangles without a material in the file; -1: a grey one */
    int *stand_in;            /* where model_add_materials says which material it gave them (-1:
                                 none), for model_add_mesh to tell a file without materials */
} model_import;

/* A reader of one or more formats. Each returns the index of the mesh it
 * added, or -1 with err filled, a message starting with job->file. */
typedef struct model_reader {
    const model_format *formats; /* the formats it takes, in the order people are told them */
    /* Imports the model in the open file fd as the reader likes (a block at
     * a time); NULL when the reader wants the bytes whole: the file is then
     * read, checked and given to import_memory. */
    int (*import_file)(glint_scene *scene, int fd, const model_import *job, glint_error *err);
    /* Imports the `size` bytes at data, which have passed the format's
     * check. */
    int (*import_memory)(glint_scene *scene, const unsigned char *data, size_t size, const model_import *job,
                         glint_error *err);
} model_reader;

/* The readers, each defined in the file of its name (obj_reader.c, ...)
 * and listed in model_registry.c. */
extern const model_reader obj_reader, assimp_reader;

/* The format that the extension of `name` names, in any case, with its
 * reader in *reader (when reader is not NULL); NULL when no reader takes
 * it. */
const model_format *model_format_of(const char *name, const model_reader **reader);

/* Writes the extensions of every format, as ".obj, .ply and .stl", into
 * out (size bytes, at least 1; cut to fit), for messages. */
void model_format_list(char *out, size_t size);

#endif
