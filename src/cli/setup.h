/* setup.h - what the glint and glint-mpi commands share around a render:
 * the scene loaded and the flags applied to it, where the image goes, how
 * it is written, the progress line, and the exit code of a failed call. */
#ifndef GLINT_CLI_SETUP_H
#define GLINT_CLI_SETUP_H

#include <stdbool.h>
#include <stdint.h>
#include <time.h>
#include "glint.h"
#include "cli/args.h"

/* Where the image goes: a file, or standard output for "-". */
typedef struct cli_destination {
    const char *path;                 /* the file, or "-" */
    const glint_image_format *format;
    const char *shown;                /* its name in messages: the file's, or "<stdout>" */
    char default_path[32];            /* glint.png, or glint.EXT of --format */
} cli_destination;

/* A run made ready to render: its scene with the flags applied, and,
 * unless cli_prepare was asked for none, where its image goes. The
 * destination's path may point into the scene: free the scene last. */
typedef struct cli_run {
    glint_scene *scene;
    glint_settings settings;          /* the scene's, with the flags' overrides */
    cli_destination dest;
    glint_image_write_options write_options;
} cli_run;

/* The progress line's state: when the render began and when the line was
 * last printed (-1: never); in a sequence of more than one frame, this
 * render's frame, the frames in all and those done before it. */
typedef struct cli_progress {
    struct timespec start;
    double last_print;
    int frame, frames, frames_done;
} cli_progress;

/* A glint_progress_fn (user a cli_progress): the share done, the time
 * elapsed and the time left, on one line of stderr rewritten at most ten
 * times a second, and cleared once done == total; in a sequence, the
 * frame, the frames done and the time left for the rest of the sequence,
 * each frame taken to cost what this one does. */
void cli_show_progress(void *user, int done, int total);

/* The exit code for a failed library call's status (args.h's codes). */
int cli_exit_code_of(glint_status s);

/* The name of a scene file in messages: "<stdin>" for '-'. */
const char *cli_scene_name(const char *path);

/* Loads the scene file, or standard input for '-', as it is at `time`
 * seconds (glint_load_options.time) (or builds a scene
 * around a model file, seen as o asks and framed for the image size it
 * gives), printing every problem and a last line saying what became of the
 * run (`outcome`); then the scene's warnings, when `warnings`. NULL after
 * reporting, with *code the exit code: bad input, or an internal failure
 * when memory ran out. */
glint_scene *cli_load_scene(const cli_options *o, const char *path, double time, const char *outcome, bool warnings,
                            int *code);

/* Everything before rendering, as the flags in o ask: the scene (o's file
 * as it is at `time` seconds, else the seed room) loaded, the --texture swaps and the settings' flags
 * applied, and, when `with_output`, the destination chosen and checked (a
 * --format agreeing with the path's extension, a path that can be written
 * and is none of the scene's inputs; the last not for --print-scene).
 * Without `with_output` (a glint-mpi worker, which writes nothing) the
 * scene's warnings are not printed either: rank 0 prints them. Returns -1
 * with *r filled, or the exit code after complaining on stderr with
 * nothing left to free. */
int cli_prepare(const cli_options *o, bool with_output, double time, cli_run *r);

/* Writes the image to the run's destination (a file through a temporary
 * name and a rename, or standard output). */
glint_status cli_write_image(const cli_run *r, const glint_image *image, glint_error *err);

/* An interrupted render's end: nothing written, or, with --partial, the
 * image of its tiles_done finished tiles of tiles_total (the rest black);
 * said on stderr. The exit code: CLI_EXIT_INTERRUPTED, or the write's
 * failure. */
int cli_interrupted(const cli_options *o, const cli_run *r, const glint_image *image, int tiles_done,
                    int tiles_total);

/* Sends SIGINT, SIGTERM, SIGHUP (the terminal closed) and SIGQUIT (Ctrl-\)
 * to on_signal from here on: each ends a render the same way, rather than
 * kill the command without a word (and, for SIGQUIT, a core dump). */
void cli_catch_signals(void (*on_signal)(int));

/* The warning for samples that came out NaN and were left out of their
 * pixels, on stderr; nothing when nan_samples is 0. */
void cli_warn_nan(uint64_t nan_samples);

#endif
