/* sdl_calls.c - SDL2 opened on first use (sdl_calls.h). */
#include "cli/sdl_calls.h"
#include "core/lazy_library.h"

#define SDL_CALL_NAME(name) "SDL_" #name,
static const char *const NAMES[] = {SDL_CALLS(SDL_CALL_NAME) NULL};

/* The loader writes addresses; the window reads them as SDL's own types. */
static union {
    sdl_calls calls;
    void *addresses[sizeof(sdl_calls) / sizeof(void *)];
} table;
_Static_assert(sizeof NAMES / sizeof *NAMES - 1 == sizeof table.addresses / sizeof *table.addresses,
               "one name for each of sdl_calls' functions");

const sdl_calls *const sdl = &table.calls;

static lazy_library library = LAZY_LIBRARY(GLINT_SDL2_SONAME, "the --display window", NAMES, table.addresses);

bool sdl_calls_load(glint_error *err)
{
    return lazy_library_load(&library, err);
}
