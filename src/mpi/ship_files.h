/* ship_files.h - the scene's files, from rank 0 to the other ranks of
 * glint-mpi, so that its nodes need no shared file system: rank 0 records
 * its load of the scene (core/file_log.h) and broadcasts the record and
 * every file's bytes as its load reads them (a scene on standard input
 * first); the other ranks load the scene replaying the record as it comes,
 * at the same time as rank 0, and never open a path of the scene
 * themselves. Every rank calls its side at the same point. */
#ifndef GLINT_MPI_SHIP_FILES_H
#define GLINT_MPI_SHIP_FILES_H

#include <mpi.h>
#include <stdbool.h>
#include "core/file_log.h"

/* Rank 0, before loading a scene from standard input: reads it whole (up
 * to one byte past the loader's limit, which then refuses it) into memory
 * that becomes standard input, so that it can be sent (send_stdin) and
 * still read by the load. GLINT_ERR_IO when it cannot be read, GLINT_ERR_NOMEM kept. */
glint_status keep_stdin(glint_error *err);

/* Rank 0 of comm, when the scene is on standard input: sends it as
 * keep_stdin kept it (`kept` GLINT_OK), or that keeping it failed (kept,
 * said in err already). Returns kept, or why sending failed. */
glint_status send_stdin(MPI_Comm comm, glint_status kept, glint_error *err);

/* Every other rank, when the scene is on standard input: takes it from
 * send_stdin as its own standard input. err says why not: in its own
 * words when the rank failed itself, else (*by_rank0) that rank 0 did. */
glint_status receive_stdin(MPI_Comm comm, bool *by_rank0, glint_error *err);

/* Rank 0's side of the files as they are sent. */
typedef struct file_sender {
    MPI_Comm comm;
    file_log *log;
    file_log *keep;           /* what is sent, kept for rank 0 to replay too; NULL: not kept */
    unsigned char *chunk;     /* a file's bytes on their way */
    glint_status status;      /* the first failure to send: nothing more is */
    glint_error err;          /* what it was */
} file_sender;

/* Rank 0 of comm, before its load: makes `log` (NULL when it could not be
 * had), which the load records into, send the other ranks what it notes
 * and each file's bytes as the load opens them; with `keep`, a log to
 * replay, rank 0 takes what it sends into it as the others do (a failure
 * to keep it is the load's), so that it can load the scene again from the
 * same bytes (the frames of a sequence). Returns a failure the load may
 * as well not begin with (memory); it is sent by send_files_end, which
 * completes `keep`. */
glint_status send_files_begin(file_sender *s, MPI_Comm comm, file_log *log, file_log *keep);

/* Rank 0, after its load: sends the answers left and the outcome, `told`
 * (the load's failure, or status GLINT_OK), or else the failure to send.
 * Returns that outcome's status, with err set on failure. */
glint_status send_files_end(file_sender *s, const glint_error *told, glint_error *err);

/* Every other rank: takes what rank 0 sends into `log` (NULL: a rank that
 * failed already, which takes part keeping nothing), which a load on
 * another thread may replay meanwhile, until rank 0's last message, then
 * completes it (file_log_complete). err says why not: in the rank's own
 * words when it failed itself (the log is completed at once, so the load
 * stops waiting), else (*by_rank0) rank 0's failure in rank 0's words. */
glint_status receive_files(MPI_Comm comm, file_log *log, bool *by_rank0, glint_error *err);

#endif
