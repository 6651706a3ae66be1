/* load_everywhere.h - one scene on every rank of an MPI job, read from
 * files only rank 0 may have: rank 0 loads it while its file log
 * (core/file_log.h) records what it reads, sends the record and the files'
 * bytes (ship_files.h), and the other ranks load it again replaying them.
 * Used by glint-mpi (the scene as its flags ask) and glint_mpi_scene_load_file. */
#ifndef GLINT_MPI_LOAD_EVERYWHERE_H
#define GLINT_MPI_LOAD_EVERYWHERE_H

#include <mpi.h>
#include <stdbool.h>
#include "glint.h"

/* Loads the scene into the caller's `user`, on rank 0 (`rank0` true) or on
 * another rank; GLINT_OK, or why not in err. */
typedef glint_status (*scene_loader)(void *user, bool rank0, glint_error *err);

/* Runs `load` on every rank of comm, as every rank calls it at once: first
 * on rank 0, then, when it succeeded, on the others, from rank 0's files
 * (and, when `with_stdin`, its standard input, read whole first). Returns
 * GLINT_OK on every rank, or a failure on every rank: rank 0's (its status
 * and message everywhere), or the first other rank's (in its own words on
 * that rank, as "rank N could not load the scene rank 0 loaded" on the
 * others), with *failed_rank the rank that failed. A rank whose own load
 * succeeded keeps what it loaded, for the caller to free. */
glint_status load_everywhere(MPI_Comm comm, scene_loader load, void *user, bool with_stdin, int *failed_rank,
                             glint_error *err);

#endif
