/* frames.h - the frames a glint command renders: which (the flags, else
 * the scene's settings.frames), each one's file name (the output's #s
 * replaced by its number), and whether --resume finds it done. */
#ifndef GLINT_CLI_FRAMES_H
#define GLINT_CLI_FRAMES_H

#include <stdbool.h>
#include <stddef.h>
#include "glint.h"
#include "cli/args.h"

/* The frames of a run, first to last. */
typedef struct cli_frames {
    int first, last;
    double fps;
} cli_frames;

/* The frames o asks for (--frame, --frames), else those of the scene's
 * settings s; -1 to go on, or the exit code after complaining: several
 * frames need the scene in a file (standard input is read once) and an
 * output name with #s (not standard output), unless o prints the scene
 * (--print-scene: the first frame alone). */
int cli_frames_choose(const cli_options *o, const glint_settings *s, const char *output, cli_frames *f);

/* The time of frame `frame` in seconds: frame / fps. */
double cli_frame_time(const cli_frames *f, int frame);

/* The file name of frame `frame` into out: `pattern` with its last run of
 * #s replaced by the number, padded with zeros to as many digits as there
 * are #s (more digits when it needs them); a pattern without # is the name
 * as it is. False when it does not fit in `size`. */
bool cli_frame_path(const char *pattern, int frame, char *out, size_t size);

/* Whether the image at path is there and whole, as --resume needs: a PNG
 * that ends in its IEND chunk, a binary PPM of the size its header says,
 * an OpenEXR file that begins with its magic number. glint writes every
 * image under another name and renames it, so only another program leaves
 * a file cut short. */
bool cli_frame_done(const char *path);

#endif
