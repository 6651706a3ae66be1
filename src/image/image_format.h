/* image_format.h - an image file format glint writes: the record each
 * format's file defines (its public description and its write operation),
 * the registry that finds one by a path's extension (image_formats.c), and
 * what writers share. Adding a format is one file defining one image_writer
 * and its line in image_formats.c; writing under a temporary name and
 * renaming it into place is image_write.c's, for every format. */
#ifndef GLINT_IMAGE_IMAGE_FORMAT_H
#define GLINT_IMAGE_IMAGE_FORMAT_H

#include <stddef.h>
#include "glint.h"

/* Writes the whole image (positive size, pixels present) into fd, open for
 * writing, as options (never NULL, already checked) ask, and nothing else,
 * in order from fd's position, never seeking, so that fd may be a pipe:
 * for a file, the caller syncs, closes and renames it, or removes it after
 * a failure. path is the name the file will have (or "<stdout>"), for
 * messages. */
typedef glint_status (*image_write_fn)(int fd, const glint_image *image, const glint_image_write_options *options,
                                       const char *path, glint_error *err);

typedef struct image_writer {
    glint_image_format format; /* name, extensions and meaning, as glint.h describes */
    image_write_fn write;
} image_writer;

/* The writer for path, by the extension of its last component, in any
 * case; NULL when no format has it. */
const image_writer *image_writer_for_path(const char *path);

/* The writer of format, one of the registry's (glint_image_format_at);
 * NULL for any other pointer. */
const image_writer *image_writer_for_format(const glint_image_format *format);

/* Fills buf with every format's extensions as a message lists them
 * (".png, .ppm or .exr"), cut short when buf is too small; returns buf. */
const char *image_writer_extensions(char *buf, size_t size);

/* For writers: all of bytes into fd, or GLINT_ERR_IO with the errno text,
 * in image_write_io_error's words. */
glint_status image_write_bytes(int fd, const unsigned char *bytes, size_t size, const char *path,
                               glint_error *err);

/* "cannot write 'PATH': " and strerror(errnum), as GLINT_ERR_IO. */
glint_status image_write_io_error(const char *path, int errnum, glint_error *err);

/* "cannot write 'PATH': out of memory", as GLINT_ERR_NOMEM. */
glint_status image_write_no_memory(const char *path, glint_error *err);

#endif
