/* embed_image.c - a build step: decodes a PNG or JPEG image with glint's own
 * texture decoder (src/image/texture_image.c) and writes its pixels as C
 * source, so that a texture compiled into glint needs no decoding when glint
 * runs. The bytes are those texture_image_load_file gives for the file.
 *
 *   embed_image INPUT OUTPUT SYMBOL
 *
 * OUTPUT defines `const int SYMBOL_width, SYMBOL_height` and
 * `const unsigned char SYMBOL_srgb[]`: 3 sRGB bytes a pixel, top row first.
 * It is written beside OUTPUT first and renamed over it, so an interrupted
 * build leaves no half-written source behind. */
#include <stdio.h>
#include <stdlib.h>
#include <string.h>
#include "image/texture_image.h"

/* Bytes on each line of the string literal. */
#define LINE 32

static int fail(const char *what, const char *path)
{
    fprintf(stderr, "embed_image: %s '%s'\n", what, path);
    return 1;
}

/* The pixels as one string literal, a line of \xHH escapes at a time (a
 * string compiles about ten times faster than a list of numbers). */
static int write_source(FILE *f, const char *input, const char *symbol, const texture_image *img)
{
    size_t n = (size_t)img->width * img->height * 3;
    fprintf(f, "/* Generated from %s by tools/embed_image.c; do not edit. */\n", input);
    fprintf(f, "const int %s_width = %d, %s_height = %d;\n", symbol, img->width, symbol, img->height);
    /* One byte more than the pixels, for the literal's terminating zero. */
    fprintf(f, "const unsigned char %s_srgb[%zu + 1] =\n", symbol, n);
    for (size_t i = 0; i < n; i += LINE) {
        fputc('"', f);
        for (size_t k = i; k < n && k < i + LINE; k++)
            fprintf(f, "\\x%02x", img->srgb[k]);
        fputs("\"\n", f);
    }
    fputs(";\n", f);
    return ferror(f) ? -1 : 0;
}

int main(int argc, char **argv)
{
    if (argc != 4) {
        fprintf(stderr, "usage: embed_image INPUT OUTPUT SYMBOL\n");
        return 2;
    }
    const char *input = argv[1], *output = argv[2], *symbol = argv[3];
    texture_image img;
    glint_error err = {0};
    if (texture_image_load_file(&img, input, &err)) {
        fprintf(stderr, "embed_image: %s\n", err.message);
        return 1;
    }
    size_t len = strlen(output);
    char *tmp = malloc(len + 5);
    if (!tmp) {
        texture_image_free(&img);
        return fail("out of memory writing", output);
    }
    memcpy(tmp, output, len);
    memcpy(tmp + len, ".tmp", 5);
    FILE *f = fopen(tmp, "w");
    int bad = !f || write_source(f, input, symbol, &img) != 0;
    if (f && fclose(f) != 0)
        bad = 1;
    if (!bad && rename(tmp, output) != 0)
        bad = 1;
    if (bad)
        remove(tmp);
    free(tmp);
    texture_image_free(&img);
    return bad ? fail("cannot write", output) : 0;
}
