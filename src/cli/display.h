/* display.h - the --display window of glint and glint-mpi: the image shown
 * as its tiles finish, over a dim placeholder, then kept on screen until
 * the user closes it (Esc, q, the window's close button); s saves what it
 * shows. The window has a thread of its own (SDL2), which alone calls SDL:
 * the render stays on the main thread, through which MPI funnels its calls,
 * and the render threads only copy their finished tiles in. */
#ifndef GLINT_CLI_DISPLAY_H
#define GLINT_CLI_DISPLAY_H

#include <signal.h>
#include <stdbool.h>
#include <stddef.h>
#include "cli/args.h"
#include "cli/setup.h"

typedef struct display display;

/* Starts the window's thread, which starts SDL while the caller loads the
 * scene. Until display_finished, closing the window sets *cancel to 1 (the
 * render then stops, as on SIGINT). Returns NULL after saying why on
 * stderr, with *code the exit code: CLI_EXIT_USAGE when there is no display
 * (neither DISPLAY nor WAYLAND_DISPLAY set), CLI_EXIT_INTERNAL when memory
 * or threads run out. */
display *display_start(volatile sig_atomic_t *cancel, int *code);

/* Opens the window for the run's image, once it is loaded: the image's
 * size, scaled down to fit the screen keeping the aspect, titled with the
 * scene's name (o->scene, or the seed room), showing the placeholder; s
 * will save to the run's output file, or to its default name (glint.png)
 * when the image goes to standard output. Returns false after saying why on
 * stderr and closing the display, with *code the exit code: CLI_EXIT_USAGE
 * when the window cannot open (SDL, or the display, refused it),
 * CLI_EXIT_INTERNAL when memory for the window's copy of the image runs out. */
bool display_show(display *d, const cli_options *o, const cli_run *r, int *code);

/* A glint_tile_fn, user the display: copies the finished tile in, for the
 * window's thread to show at its next frame (30 a second at most). */
void display_tile(void *user, int x0, int y0, int x1, int y1, const float *pixels, size_t stride);

/* Says that the render is over, after `seconds`: the title shows the time,
 * and closing the window no longer cancels anything. */
void display_finished(display *d, double seconds);

/* Waits until the user closes the window, or until *cancel is set (a
 * signal), then frees the display. */
void display_wait(display *d);

/* Closes the window now and frees the display; NULL does nothing. */
void display_close(display *d);

#endif
