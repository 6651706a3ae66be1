/* rows_deflate.h - a fast deflate (RFC 1951) compressor for the filtered
 * rows of a rendered image, which png_encode.c writes. */
#ifndef GLINT_IMAGE_ROWS_DEFLATE_H
#define GLINT_IMAGE_ROWS_DEFLATE_H

#include <stdbool.h>
#include <stddef.h>

/* One thread's working memory for rows_deflate: its block's symbols, their
 * counts and codes, and the table of where each 4-byte string last began. */
typedef struct rows_deflater rows_deflater;

/* A new working memory, or NULL when memory runs out. */
rows_deflater *rows_deflater_new(void);

/* Frees d (NULL is nothing). */
void rows_deflater_free(rows_deflater *d);

/* The most bytes rows_deflate writes for n bytes of input. */
size_t rows_deflate_bound(size_t n);

/* Deflates the n bytes at in (a whole number of filtered rows, whose pixels
 * are pixel_bytes bytes each, or any bytes) as raw deflate blocks into out,
 * which has rows_deflate_bound(n) bytes of room, and returns the bytes
 * written. The blocks refer only to bytes within in. With `final` the last
 * block is marked final and the stream ends on a byte boundary; without,
 * they end with an empty stored block (zlib's sync flush), so that another
 * call's blocks may follow on the next byte. The same input gives the same
 * bytes, whatever the thread. */
size_t rows_deflate(rows_deflater *d, const unsigned char *in, size_t n, int pixel_bytes, bool final,
                    unsigned char *out);

#endif
