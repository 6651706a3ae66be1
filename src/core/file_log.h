/* file_log.h - the file system as one scene load saw it, recorded so that
 * another process can load the same scene without the files: glint-mpi's
 * rank 0 records its load and sends the record and the files' bytes to the
 * other ranks, which replay it. While a log is replayed, every file a
 * loader opens (open_file.h), resolves (file_realpath) or looks at
 * (file_stat) is answered from the log, and no path is looked up on the
 * replaying machine: its nodes need no shared file system, and a path
 * resolves as it did on rank 0 whatever the working directory.
 *
 * A log is the calling thread's while it records or replays (loaders open
 * their files on the thread that loads); other threads see the file system
 * itself. */
#ifndef GLINT_CORE_FILE_LOG_H
#define GLINT_CORE_FILE_LOG_H

#include <limits.h>
#include <stdbool.h>
#include <stddef.h>
#include <stdint.h>
#include <sys/stat.h>
#include "glint.h"

typedef struct file_log file_log;

/* An empty log; NULL when out of memory. */
file_log *file_log_new(void);

/* Frees the log (NULL is ignored). It must not be the thread's any more. */
void file_log_free(file_log *log);

/* Makes `log` the calling thread's to record into: what the thread's
 * opens, file_realpath and file_stat calls find is noted, the first answer
 * for each path kept. */
void file_log_record(file_log *log);

/* Makes `log` (unpacked, with all its bytes taken) the calling thread's to
 * answer from. A path the log does not know is not found (ENOENT). */
void file_log_replay(file_log *log);

/* The thread looks at the file system itself again. */
void file_log_stop(void);

/* realpath(3) through the thread's log: `resolved` has room for PATH_MAX
 * bytes. NULL with errno set when the path does not resolve. */
char *file_realpath(const char *path, char *resolved);

/* stat(2) through the thread's log. */
int file_stat(const char *path, struct stat *st);

/* For open_file_read: true when the thread replays a log, with the open
 * answered: a descriptor of a private copy of the file's bytes, at its
 * start, with *st the file's status as recorded, or -1 with *errnum as
 * open_file_read gives it. */
bool file_log_replay_open(const char *path, int *fd, struct stat *st, int *errnum);

/* For open_file_read: notes an open of `path` when the thread records:
 * its descriptor (or -1) with *st its status, or *errnum. */
void file_log_note_open(const char *path, int fd, const struct stat *st, int errnum);

/* The record, without the files' bytes, packed into *bytes (malloc'd,
 * *size long) for file_log_unpack in a process of the same build; the
 * files whose bytes go with it are file_log_file_count's, in order.
 * GLINT_ERR_NOMEM when memory ran out, here or while recording. */
glint_status file_log_pack(const file_log *log, unsigned char **bytes, size_t *size, glint_error *err);

/* How many files' bytes go with the log, and their length in all. */
size_t file_log_file_count(const file_log *log);
uint64_t file_log_file_bytes(const file_log *log);

/* The path of the i-th of them (from 0). */
const char *file_log_file_path(const file_log *log, size_t i);

/* Opens the i-th of them again for reading its bytes: its descriptor,
 * with *size its length; or -1 with err set when it cannot be opened or is
 * no longer the file the load read (changed since). */
int file_log_open_file(const file_log *log, size_t i, uint64_t *size, glint_error *err);

/* A log from file_log_pack's bytes, awaiting its files' bytes: NULL with
 * err set when they are no packed log or memory ran out. */
file_log *file_log_unpack(const unsigned char *bytes, size_t size, glint_error *err);

/* Takes the next n bytes of the files, the files one after the other in
 * order: GLINT_ERR_NOMEM (or GLINT_ERR_IO) when they cannot be kept, and
 * GLINT_ERR_INVALID for more than awaited. */
glint_status file_log_take_bytes(file_log *log, const void *data, size_t n, glint_error *err);

#endif
