/* open_file.h - opening a file glint reads (a scene, an include, a model,
 * an MTL file, a glTF buffer, a texture): only a regular file, and the
 * opening never blocks on a FIFO or a device, whatever the file is. */
#ifndef GLINT_CORE_OPEN_FILE_H
#define GLINT_CORE_OPEN_FILE_H

#include <stdint.h>
#include <stdio.h>
#include <sys/stat.h>

/* Opens `path` for reading, close-on-exec, never as a controlling
 * terminal. Returns the descriptor, in blocking mode again, with *st its
 * status; or -1 with *errnum the reason: the open's or fstat's errno,
 * EISDIR for a directory, or 0 for another file that is not a regular one
 * (a FIFO, a device, a socket, or a file of /proc or /sys, whose size says
 * nothing of what reading it gives). */
int open_file_read(const char *path, struct stat *st, int *errnum);

/* As open_file_read, as a stdio stream; NULL on failure. */
FILE *open_file_stream(const char *path, struct stat *st, int *errnum);

/* A fresh memory file holding `size` bytes of the file fd from `offset`
 * (fd's own offset left alone), at its start: a private copy, with an
 * offset of its own, that no change to the file reaches. -1 with errno
 * set (EIO when the file ended first). */
int open_file_copy(int fd, uint64_t offset, uint64_t size);

/* The words for open_file_read's *errnum: strerror's, or "not a regular
 * file" for 0. */
const char *open_file_reason(int errnum);

#endif
