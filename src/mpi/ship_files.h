/* ship_files.h - the scene's files, from rank 0 to the other ranks of
 * glint-mpi, so that its nodes need no shared file system: rank 0 records
 * its load of the scene (core/file_log.h) and broadcasts the record, every
 * file's bytes and, for a scene on standard input, those bytes too; the
 * other ranks load the scene replaying the record, and never open a path
 * of the scene themselves. Every rank calls its side at the same point. */
#ifndef GLINT_MPI_SHIP_FILES_H
#define GLINT_MPI_SHIP_FILES_H

#include <mpi.h>
#include <stdbool.h>
#include "core/file_log.h"

/* Rank 0, before loading a scene from standard input: reads it whole (up
 * to one byte past the loader's limit, which then refuses it) into memory
 * that becomes standard input, so that it can be sent after the load has
 * read it. GLINT_ERR_IO when it cannot be read, GLINT_ERR_NOMEM kept. */
glint_status keep_stdin(glint_error *err);

/* Rank 0 of comm: sends `log`, the files' bytes and, when `with_stdin`,
 * standard input as keep_stdin kept it. On failure (a file changed since
 * the load, memory) the other ranks fail too. */
glint_status send_files(MPI_Comm comm, const file_log *log, bool with_stdin, glint_error *err);

/* Every other rank of comm: receives what send_files sends into *log, a
 * log to replay (and its standard input, when sent): err says why not, in
 * its own words when the rank failed itself, else (*by_rank0) that rank 0
 * did. */
glint_status receive_files(MPI_Comm comm, file_log **log, bool *by_rank0, glint_error *err);

#endif
