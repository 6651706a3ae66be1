/* assimp_calls.h - the Assimp functions the model importer calls, found in
 * Assimp when the first PLY, STL, glTF or GLB file is read
 * (core/lazy_library.h), so that a run without one never loads Assimp. */
#ifndef GLINT_MODEL_ASSIMP_CALLS_H
#define GLINT_MODEL_ASSIMP_CALLS_H

#include <stdbool.h>
#include <assimp/cimport.h>
#include <assimp/material.h>
#include "core/error.h"

#define ASSIMP_CALLS(X)                                                                                            \
    X(CreatePropertyStore) X(GetErrorString) X(GetMaterialColor) X(GetMaterialFloatArray) X(GetMaterialString)   \
    X(ImportFileExWithProperties) X(ReleaseImport) X(ReleasePropertyStore) X(SetImportPropertyInteger)

/* aiNAME as assimp->NAME, with Assimp's own prototype. */
#define ASSIMP_CALL_FIELD(name) __typeof__(ai##name) *name;
typedef struct assimp_calls {
    ASSIMP_CALLS(ASSIMP_CALL_FIELD)
} assimp_calls;
#undef ASSIMP_CALL_FIELD

/* Assimp's functions, valid once assimp_calls_load has returned true. */
extern const assimp_calls *const assimp;

/* Opens Assimp on the first call; false with the reason in err when it
 * cannot be loaded. */
bool assimp_calls_load(glint_error *err);

#endif
