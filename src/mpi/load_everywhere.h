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
 * (and, when `with_stdin`, its standard input, read whole first). A
 * failure of rank 0 (its load, or sending its files) is every rank's: its
 * status, in its words on rank 0 and on the others as rank 0 said it or
 * as "rank 0 could not send the scene's files". With `wait_for_all`, a
 * failure of another rank is every rank's too: the first such rank's
 * status, in its own words on that rank, as "rank N could not load the
 * scene rank 0 loaded" on the others; without, rank 0 returns at once,
 * to render while the others load, and each other rank returns its own
 * outcome (it must then tell rank 0 of a failure itself). *failed_rank is
 * the rank that failed (0 for rank 0). A rank whose own load succeeded
 * keeps what it loaded, for the caller to free. */
glint_status load_everywhere(MPI_Comm comm, scene_loader load, void *user, bool with_stdin, bool wait_for_all,
                             int *failed_rank, glint_error *err);

#endif
