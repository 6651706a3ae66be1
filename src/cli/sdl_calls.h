/* sdl_calls.h - the SDL2 functions the --display window calls, found in
 * SDL2 when the window first opens (core/lazy_library.h), so that a run
 * without a window never loads SDL2 and what it pulls in. */
#ifndef GLINT_CLI_SDL_CALLS_H
#define GLINT_CLI_SDL_CALLS_H

#include <stdbool.h>
#include <SDL.h>
#include "core/error.h"

#define SDL_CALLS(X)                                                                                               \
    X(CreateWindow) X(DestroyWindow) X(FillRect) X(GetCurrentVideoDriver) X(GetDisplayUsableBounds) X(GetError)   \
    X(GetWindowSurface) X(InitSubSystem) X(MapRGB) X(PollEvent) X(Quit) X(SetHint) X(SetWindowTitle)             \
    X(UpdateWindowSurface) X(UpdateWindowSurfaceRects)

/* SDL_NAME as sdl->NAME, with SDL's own prototype. */
#define SDL_CALL_FIELD(name) __typeof__(SDL_##name) *name;
typedef struct sdl_calls {
    SDL_CALLS(SDL_CALL_FIELD)
} sdl_calls;
#undef SDL_CALL_FIELD

/* SDL2's functions, valid once sdl_calls_load has returned true. */
extern const sdl_calls *const sdl;

/* Opens SDL2 on the first call; false with the reason in err when it
 * cannot be loaded. */
bool sdl_calls_load(glint_error *err);

#endif
