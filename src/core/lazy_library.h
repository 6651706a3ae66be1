/* lazy_library.h - a shared library opened the first time glint needs it,
 * not when the program starts: the window's SDL2 and the model importer's
 * Assimp, with the dozens of libraries they pull in, cost every run of
 * glint about 15 ms of loading (measured in bench/README.md) that most
 * runs never use. */
#ifndef GLINT_CORE_LAZY_LIBRARY_H
#define GLINT_CORE_LAZY_LIBRARY_H

#include <stdbool.h>
#include "core/error.h"

/* One library and the functions glint calls in it. Define it statically
 * with LAZY_LIBRARY; the loader fills addresses in the order of names. */
typedef struct lazy_library {
    const char *soname;         /* the name the dynamic loader finds it by, "libSDL2-2.0.so.0" */
    const char *needed_by;      /* what needs it, for the message: "the --display window" */
    const char *const *names;   /* the functions, NULL-terminated */
    void **addresses;           /* as many as names */
    int state;                  /* 0 not tried, 1 loaded, -1 failed */
    char failure[256];          /* why it failed */
} lazy_library;

#define LAZY_LIBRARY(soname, needed_by, names, addresses) {soname, needed_by, names, addresses, 0, ""}

/* Opens the library and finds each of its functions, the first time it is
 * called (from any thread); the library then stays open. False, with the
 * reason in err, when it cannot: GLINT_ERR_NOMEM ("out of memory loading
 * libassimp.so.5") when memory ran out, which the next call tries again;
 * GLINT_ERR_IO ("the --display window needs libSDL2-2.0.so.0: ...") when
 * the library or a function is missing, which every later call reports
 * alike. */
bool lazy_library_load(lazy_library *l, glint_error *err);

#endif
