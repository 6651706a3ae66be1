/* png_encode.h - a linear float image as the bytes of an 8- or 16-bit sRGB
 * PNG file, encoded on every processor. */
#ifndef GLINT_IMAGE_PNG_ENCODE_H
#define GLINT_IMAGE_PNG_ENCODE_H

#include <stdbool.h>
#include <stddef.h>
#include "glint.h"

/* The widest and tallest image encoded: libpng, which most programs read
 * PNG files with, refuses larger ones by default. */
#define PNG_ENCODE_MAX_SIDE 1000000

/* Encodes image (width and height in 1..PNG_ENCODE_MAX_SIDE) as a whole
 * PNG file of `depth` (8 or 16) bits a channel in *bytes (malloc'd, *size
 * long): the chunks IHDR, sRGB, IDAT and IEND, each row sRGB-encoded by
 * srgb_encode_depth and Up-filtered (byte by byte, as PNG's filters are
 * for every depth), deflated by rows_deflate. The rows are cut into slices
 * of about 256 KiB that threads deflate apart, each referring back only
 * into itself, so the file is the same bytes for any number of threads. threads is at
 * least 1. False, with *bytes NULL, when memory runs out. */
bool png_encode(const glint_image *image, int depth, int threads, unsigned char **bytes, size_t *size);

#endif
