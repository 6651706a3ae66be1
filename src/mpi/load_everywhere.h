/* load_everywhere.h - one scene on every rank of an MPI job, read from
 * files only rank 0 may have: rank 0 loads it while its file log
 * (core/file_log.h) records what it reads and sends it, with the files'
 * bytes, as it goes (ship_files.h); the other ranks load it at the same
 * time, replaying what comes. Used by glint-mpi (the scene as its flags
 * ask) and glint_mpi_scene_load_file. */
#ifndef GLINT_MPI_LOAD_EVERYWHERE_H
#define GLINT_MPI_LOAD_EVERYWHERE_H

#include <mpi.h>
#include <stdbool.h>
#include "core/file_log.h"
#include "core/file_log.h"
#include "glint.h"

/* Loads the scene into the caller's `user`, on rank 0 (`rank0` true) or on
 * another rank; GLINT_OK, or why not in err. */
typedef glint_status (*scene_loader)(void *user, bool rank0, glint_error *err);

/* Runs `load` on every rank of comm, as every rank calls it at once: on
 * rank 0 on the calling thread, sending its files (and, when
 * `with_stdin`, its standard input, read whole first) as it reads them; on
 * the others at the same time, on a thread of their own (the calling
 * thread takes in the files), from rank 0's files alone. A failure of
 * rank 0 (its load, or sending its files) is every rank's: its status, in
 * rank 0's words. With `wait_for_all`, a failure of another rank is every
 * rank's too: the first such rank's status, in its own words on that
 * rank, as "rank N could not load the scene rank 0 loaded" on the others;
 * without, rank 0 returns at once, to render while the others finish, and
 * each other rank returns its own outcome (it must then tell rank 0 of a
 * failure itself). *failed_rank is the rank that failed (0 for rank 0). A
 * rank whose own load succeeded keeps what it loaded, for the caller to
 * free, even when another failed. With `kept`, a rank whose own load
 * succeeded also gets the files rank 0 sent, as a whole log for
 * load_again (rank 0 too: the bytes it sent, not its files again), to
 * free with file_log_free; else *kept is NULL. */
glint_status load_everywhere(MPI_Comm comm, scene_loader load, void *user, bool with_stdin, bool wait_for_all,
                             file_log **kept, int *failed_rank, glint_error *err);

/* Runs `load` again on the calling thread (of any rank, as rank 0 when
 * `rank0`), its files answered from a log load_everywhere kept, so that it
 * reads the bytes rank 0 sent and no file of its own: the scene as it is
 * at another time, say. Returns what `load` returns. */
glint_status load_again(file_log *log, scene_loader load, void *user, bool rank0, glint_error *err);

#endif
