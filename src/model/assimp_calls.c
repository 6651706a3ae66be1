/* assimp_calls.c - Assimp opened on first use (assimp_calls.h). */
#include "core/lazy_library.h"
#include "model/assimp_calls.h"

#define ASSIMP_CALL_NAME(name) "ai" #name,
static const char *const NAMES[] = {ASSIMP_CALLS(ASSIMP_CALL_NAME) NULL};

/* The loader writes addresses; the importer reads them as Assimp's types. */
static union {
    assimp_calls calls;
    void *addresses[sizeof(assimp_calls) / sizeof(void *)];
} table;
_Static_assert(sizeof NAMES / sizeof *NAMES - 1 == sizeof table.addresses / sizeof *table.addresses,
               "one name for each of assimp_calls' functions");

const assimp_calls *const assimp = &table.calls;

static lazy_library library = LAZY_LIBRARY(GLINT_ASSIMP_SONAME, "reading PLY, STL, glTF and GLB models", NAMES,
                                           table.addresses);

bool assimp_calls_load(glint_error *err)
{
    return lazy_library_load(&library, err);
}
