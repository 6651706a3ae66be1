/* obj_read.h - glint's own reader of Wavefront OBJ text (docs/meshes.md):
 * from memory or from a file read a block at a time (obj_read.c), into
 * flat arrays that grow by doubling. A large text's lines are parsed by a
 * thread per processor, a piece of each block each, and merged in the
 * file's order (obj_ahead.c). Face corners with the same (v, vt, vn)
 * indices are joined as they are read (obj_corner.c), polygons are split
 * into triangles (obj_statement.c), and every problem is an error naming
 * file:line:column; the model and the messages do not depend on the
 * threads. */
#ifndef GLINT_MODEL_OBJ_READ_H
#define GLINT_MODEL_OBJ_READ_H

#include <stdbool.h>
#include <stddef.h>
#include <stdint.h>
#include "glint.h"

/* One distinct face corner: indices from 0 into the model's positions,
 * uvs and normals; -1 where the corner has none. */
typedef struct obj_corner {
    int32_t v, vt, vn;
} obj_corner;

/* The triangles from `first` up to the next run's use one material:
 * `material` indexes obj_model.materials, -1 for faces before any usemtl. */
typedef struct obj_run {
    uint32_t first;
    int32_t material;
} obj_run;

/* What an OBJ file holds, as glint uses it. */
typedef struct obj_model {
    float *positions;         /* v: x y z each, finite */
    size_t position_count, position_cap;
    float *uvs;               /* vt: u and glint's v (1 - v: OBJ's v = 0 is the bottom row), finite */
    size_t uv_count, uv_cap;
    float *normals;           /* vn: x y z each, those not finite stored as 0 */
    size_t normal_count, normal_cap;
    obj_corner *corners;      /* the distinct corners of the faces */
    size_t corner_count, corner_cap;
    uint32_t *triangles;      /* three corners each, in the file's winding */
    size_t triangle_count, triangle_cap;
    obj_run *runs;            /* first triangle of each change of material */
    size_t run_count, run_cap;
    char *text;               /* the names below, each ending in a NUL */
    size_t text_len, text_cap;
    size_t *materials;        /* distinct usemtl names: offsets into text */
    size_t material_count, material_cap;
    size_t *libraries;        /* mtllib lines, as written: offsets into text */
    size_t library_count, library_cap;
    bool generate;            /* some face has no normals: they are to be generated */
    bool textured;            /* some face has texture coordinates */
} obj_model;

/* Reads the OBJ text of `size` bytes at data into *m (zeroed first);
 * `file` names it in messages. On failure err says why and where, and *m
 * still needs obj_model_free. */
glint_status obj_read_memory(obj_model *m, const unsigned char *data, size_t size, const char *file,
                             glint_error *err);

/* As obj_read_memory, with `threads` threads (1 to 16) parsing ahead
 * pieces of about `piece` bytes each however small: the model and any
 * message are the same whatever the two are. For tests; obj_read_memory
 * and obj_read_fd use a thread per processor, with pieces of 4 MiB, for
 * text that gives each thread at least 256 KiB. */
glint_status obj_read_memory_split(obj_model *m, const unsigned char *data, size_t size, const char *file,
                                   int threads, size_t piece, glint_error *err);

/* As obj_read_fd, with threads and pieces as for obj_read_memory_split. */
glint_status obj_read_fd_split(obj_model *m, int fd, const char *file, int threads, size_t piece, glint_error *err);

/* As obj_read_memory, from the open file fd, read to its end a chunk at a
 * time, so that the file is never in memory whole. */
glint_status obj_read_fd(obj_model *m, int fd, const char *file, glint_error *err);

/* Frees one of the model's arrays (such as &m->positions) and zeroes its
 * count and room, to lower the peak of memory while building the mesh. */
void obj_model_drop(void **array, size_t *count, size_t *cap);

/* Frees everything the model holds. */
void obj_model_free(obj_model *m);

#endif
