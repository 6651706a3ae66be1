/* ship_files.h - the scene's files, from rank 0 to the other ranks of
 * glint-mpi, so that its nodes need no shared file system: rank 0 records
 * its load of the scene (core/file_log.h) and broadcasts the record, every
 * file's bytes and, for a scene on standard input, those bytes too; the
 * other ranks load the scene replaying the record, and never open a path
 * of the scene themselves. Every rank calls its side at the same point. */
#ifndef GLINT_MPI_SHIP_FILES_H
#define GLINT_MPI_SHIP_FILES_H

#include <stdbool.h>
#include "core/file_log.h"

/* Rank 0, before loading a scene from standard input: reads it whole (up
 * to one byte past the loader's limit, which then refuses it) into memory
 * that becomes standard input, so that it can be sent after the load has
 * read it. -1, or the exit code after complaining. */
int keep_stdin(void);

/* Rank 0: sends `log`, the files' bytes and, when `with_stdin`, standard
 * input as keep_stdin kept it. -1, or the exit code after complaining;
 * the other ranks then fail too, quietly. */
int send_files(const file_log *log, bool with_stdin);

/* Every other rank: receives what send_files sends into *log, a log to
 * replay (and its standard input, when sent). -1, or an exit code: after
 * complaining when the rank failed itself, quietly when rank 0 did. */
int receive_files(file_log **log);

#endif
