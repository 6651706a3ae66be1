/* file_log.h - the file system as one scene load saw it, recorded so that
 * another process can load the same scene without the files: glint-mpi's
 * rank 0 records its load and sends the record and the files' bytes to the
 * other ranks as it reads them, and they replay it as it comes. While a log is replayed, every file a
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

/* Called on the recording thread right after each open the log notes (the
 * first of each path), with its path, the opened file's descriptor (-1
 * when the open failed) and its size; returns the descriptor the load
 * reads: fd, or another at its start holding the same bytes, fd closed.
 * glint-mpi's rank 0 packs the answers noted so far and sends them with a
 * copy of the file's bytes, which its own load then reads: the ranks load
 * the same bytes even from a file that changes meanwhile. */
typedef int (*file_log_open_hook)(void *user, const char *path, int fd, uint64_t size);

/* Sets the log's open hook (NULL for none). */
void file_log_on_open(file_log *log, file_log_open_hook hook, void *user);

/* Makes `log` the calling thread's to answer from. Its answers and bytes
 * may still be coming (file_log_take_answers and file_log_take_bytes on
 * another thread): a question it cannot answer yet, or an open whose bytes
 * have not all come, waits until it can or until file_log_complete; then a
 * path the log does not know is not found (ENOENT), and an open whose
 * bytes never all came fails (EIO). */
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
 * its descriptor (or -1) with *st its status, or *errnum. Returns the
 * descriptor to read the file from (the open hook's). */
int file_log_note_open(const char *path, int fd, const struct stat *st, int errnum);

/* The answers noted since the last call (at the first, all of them),
 * without the files' bytes, packed into *bytes (malloc'd, *size long) for
 * file_log_take_answers in a process of the same build. GLINT_ERR_NOMEM
 * when memory ran out, here or while recording. */
glint_status file_log_pack(file_log *log, unsigned char **bytes, size_t *size, glint_error *err);

/* Adds answers file_log_pack packed, in the order it packed them, to a log
 * to replay (from any thread, while another replays it): each open that
 * found its file then awaits that file's bytes, after those of the opens
 * before it. GLINT_ERR_INVALID when the bytes are no packed answers or
 * answer a question the log has answered, GLINT_ERR_NOMEM. */
glint_status file_log_take_answers(file_log *log, const unsigned char *bytes, size_t size, glint_error *err);

/* Takes the next n bytes of the files, the files one after the other in
 * the order of their answers: GLINT_ERR_NOMEM (or GLINT_ERR_IO) when they
 * cannot be kept, and GLINT_ERR_INVALID for more than the answers await. */
glint_status file_log_take_bytes(file_log *log, const void *data, size_t n, glint_error *err);

/* Nothing more comes to the log: the questions waiting for answers or
 * bytes it lacks get their failure now. */
void file_log_complete(file_log *log);

#endif
