/* lead.h - rank 0 of glint-mpi while rendering: it holds the one image,
 * hands out its tiles on request (a pull queue), renders tiles itself
 * between requests, and takes in the tiles the other ranks finish. */
#ifndef GLINT_MPI_LEAD_H
#define GLINT_MPI_LEAD_H

#include <mpi.h>
#include "mpi/protocol.h"

/* Renders scene across the `ranks` ranks of comm, rank 0's share on
 * options->threads threads (which must be set, not 0), while every other
 * rank runs follow_render (follow.h); options->cancel, when set, is the
 * flag that stops the job, and options->progress counts every rank's
 * tiles. *stats is the whole render's (every rank's samples, rays and
 * tiles, rank 0's wall-clock time) and reports[r] rank r's report, for
 * each of the ranks. Returns GLINT_OK with *out the whole image (free it
 * with glint_image_free); GLINT_ERR_CANCELLED when the flag was set or a
 * rank was cancelled, with *out the image of the tiles finished (the rest
 * black), every rank stopped; or the first failing rank's status, err naming it, with
 * *out empty. Called on the thread that initialised MPI, the only one that
 * calls it. */
glint_status lead_render(MPI_Comm comm, const glint_scene *scene, const glint_render_options *options, int ranks,
                         glint_image *out, glint_render_stats *stats, rank_report *reports, glint_error *err);

#endif
