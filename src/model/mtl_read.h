/* mtl_read.h - glint's own reader of Wavefront MTL material libraries
 * (docs/meshes.md): the statements glint maps to its materials, checked,
 * with errors naming file:line:column, and the glint material each
 * becomes. */
#ifndef GLINT_MODEL_MTL_READ_H
#define GLINT_MODEL_MTL_READ_H

#include <stddef.h>
#include <stdint.h>
#include "glint.h"
#include "core/id_table.h"

/* Marks a material without a map_Kd image. */
#define MTL_NO_TEXT SIZE_MAX

/* One newmtl, as the file gives it; what it leaves out has MTL's defaults
 * (mtl_default). */
typedef struct mtl_material {
    size_t name;              /* offset into the library's text */
    double kd[3], ks[3], ka[3], ke[3];
    double ns, ni;
    double d;                 /* opacity: d, or 1 - Tr, whichever comes last */
    int illum;
    size_t map_kd;            /* the map_Kd file as written: offset into text, or MTL_NO_TEXT */
    size_t bump;              /* bump or map_Bump: a height map, as map_kd */
    double bump_multiplier;   /* its -bm option (1 when not given) */
    size_t norm;              /* norm: a tangent-space normal map, as map_kd */
} mtl_material;

/* The materials of all the MTL files a model names. */
typedef struct mtl_library {
    mtl_material *items;
    size_t count, cap;
    char *text;               /* names and file names, each ending in a NUL */
    size_t text_len, text_cap;
    id_table index;           /* items by name */
} mtl_library;

/* A material with nothing given: Kd 0.6 0.6 0.6, Ks, Ka and Ke 0, Ns 0, Ni
 * 1, d 1, illum 1, no map_Kd, bump or norm. */
mtl_material mtl_default(void);

/* Reads the MTL text of `size` bytes at data into lib, `file` naming it in
 * messages. A name defined again replaces the earlier definition. */
glint_status mtl_read(mtl_library *lib, const char *data, size_t size, const char *file, glint_error *err);

/* The material called `name`, or NULL. */
const mtl_material *mtl_find(const mtl_library *lib, const char *name);

/* The glint material of MTL material m (mtl_material.c), its values
 * clamped into glint's ranges; no texture. */
glint_material mtl_to_glint(const mtl_material *m);

/* Frees what lib holds. */
void mtl_free(mtl_library *lib);

#endif
