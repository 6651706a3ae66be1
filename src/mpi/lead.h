/* lead.h - rank 0 of glint-mpi while rendering: it holds the one image,
 * hands out its tiles on request (a pull queue), renders tiles itself
 * between requests, and takes in the tiles the other ranks finish. */
#ifndef GLINT_MPI_LEAD_H
#define GLINT_MPI_LEAD_H

#include <stdbool.h>
#include "glint.h"
#include "mpi/protocol.h"

/* Renders scene across the `ranks` ranks of MPI_COMM_WORLD, rank 0's share
 * on options->threads threads (which must be set, not 0), while every
 * other rank runs follow_render (follow.h); options->cancel, when set, is
 * the flag a signal sets to stop the job. With `progress`, one progress
 * line on stderr counts every rank's tiles. Returns 0 with *out the whole
 * image (free it with glint_image_free) and reports[r] rank r's report,
 * for each of the ranks; CLI_EXIT_INTERRUPTED when the flag was set or a
 * rank was interrupted, with *out the image of the *tiles_done tiles
 * finished (the rest black), every rank stopped; or another exit code
 * (args.h) after saying on stderr which rank failed and why, with *out
 * empty. Called on the thread that initialised MPI, the only one that
 * calls it. */
int lead_render(const glint_scene *scene, const glint_render_options *options, int ranks, bool progress,
                glint_image *out, int *tiles_done, rank_report *reports);

#endif
