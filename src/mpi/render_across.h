/* render_across.h - one image of the glint-mpi command rendered across
 * every rank (glint_mpi_render), then written by rank 0 as glint writes
 * it, shown in its window, and summed up on stderr: a still, or a frame
 * of a sequence with fewer frames than ranks. */
#ifndef GLINT_MPI_RENDER_ACROSS_H
#define GLINT_MPI_RENDER_ACROSS_H

#include "cli/args.h"
#include "cli/display.h"
#include "cli/setup.h"

/* Renders r's scene (loaded on every rank) across the `ranks` ranks, rank
 * 0 writing it to r's destination and showing it in `window` (NULL: none);
 * `cancel` is the signal's flag. `frame` (NULL for a still) is the frame's
 * place in its sequence, for the progress line and the summary. Called by
 * every rank at once; the exit code (rank 0 alone writes: its code may be
 * worse). */
int render_across(const cli_options *o, cli_run *r, int rank, int ranks, display *window, const volatile int *cancel,
                  const cli_progress *frame);

#endif
