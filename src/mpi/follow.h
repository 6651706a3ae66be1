/* follow.h - every rank of glint-mpi but rank 0 while rendering: it asks
 * rank 0 for tiles, renders them on its threads and sends each back as it
 * is finished. */
#ifndef GLINT_MPI_FOLLOW_H
#define GLINT_MPI_FOLLOW_H

#include <mpi.h>
#include "mpi/protocol.h"

/* Renders the tiles rank 0 of comm (lead_render, lead.h) hands this rank,
 * on options->threads threads (set, not 0), until rank 0 has no more or
 * tells it to stop, or options->cancel (a signal's flag, when set) is set;
 * and reports to it how the render went, also when it failed (a NULL
 * scene: its load failed). Returns that report. Called on the thread that initialised MPI, the only one that
 * calls it. */
rank_report follow_render(MPI_Comm comm, const glint_scene *scene, const glint_render_options *options);

#endif
