/* sequence.h - the glint-mpi command rendering an animation's frames
 * across the ranks, each frame the bytes glint gives for it: whole frames
 * to each rank when there are at least as many frames as ranks, else each
 * frame by every rank, by tiles. */
#ifndef GLINT_MPI_SEQUENCE_H
#define GLINT_MPI_SEQUENCE_H

#include <stdbool.h>
#include "cli/args.h"
#include "cli/display.h"
#include "cli/frames.h"
#include "cli/setup.h"
#include "core/file_log.h"

/* Whether the flags o and frames f ask for more than the still a scene
 * loaded at time 0 is: other frames, or --resume. */
bool sequence_wanted(const cli_options *o, const cli_frames *f);

/* Renders frames f->first to f->last (those --resume finds whole left
 * out), each loaded at its time from `log`, the files rank 0 sent when it
 * loaded the scene at time 0 into r (NULL on a rank whose own load
 * failed: the render then fails, naming it). Rank 0 names and writes each
 * frame's file, from r's destination, and shows the frames in `window`
 * (NULL: none); `cancel` is the signal's flag. Frees r->scene first: the
 * frames are loaded anew. Called by every rank at once; the exit code
 * (rank 0's may be worse: it alone writes). */
int sequence_render(const cli_options *o, cli_run *r, const cli_frames *f, file_log *log, int rank, int ranks,
                    display *window, const volatile int *cancel);

#endif
