/* rmse.c - bench: how far an image is from a reference, as the root mean
 * square of their difference over every channel of every pixel, divided
 * by the reference's mean: the relative noise that bench/equal-noise.sh
 * compares renderers by, each against a reference of its own.
 *
 *   bench_rmse image.ppm reference.ppm      prints the relative RMSE
 *
 * Both binary PPM (P6), 8 or 16 bits, of the same size: bench/equal-noise.sh
 * asks both renderers for 16, so that rounding to 8 bits adds no noise. */
#include <math.h>
#include <stdbool.h>
#include <stdio.h>
#include <stdlib.h>

/* The next number of a PPM header, past blanks and # comments; -1 if none. */
static int header_number(FILE *f)
{
    int c = fgetc(f);
    for (;;) {
        while (c == ' ' || c == '\t' || c == '\n' || c == '\r')
            c = fgetc(f);
        if (c != '#')
            break;
        while (c != '\n' && c != EOF)
            c = fgetc(f);
    }
    int n = -1;
    for (; c >= '0' && c <= '9' && n < 100000; c = fgetc(f))
        n = (n < 0 ? 0 : 10 * n) + (c - '0');
    return n; /* the one blank after it is read */
}

/* Reads a binary PPM's pixels, as 0..1; NULL, having said why, when it
 * cannot. Both 8 and 16 bits. */
static double *read_ppm(const char *path, int *width, int *height)
{
    FILE *f = fopen(path, "rb");
    int max = 0;
    bool ok = f && fgetc(f) == 'P' && fgetc(f) == '6' && (*width = header_number(f)) > 0 &&
              (*height = header_number(f)) > 0 && ((max = header_number(f)) == 255 || max == 65535);
    if (!ok) {
        fprintf(stderr, "bench_rmse: %s is not a binary PPM\n", path);
        if (f)
            fclose(f);
        return NULL;
    }
    size_t n = (size_t)*width * (size_t)*height * 3, size = max == 255 ? 1 : 2;
    unsigned char *raw = malloc(n * size);
    double *p = malloc(n * sizeof *p);
    if (!raw || !p || fread(raw, size, n, f) != n) {
        fprintf(stderr, "bench_rmse: %s is cut short\n", path);
        free(p);
        p = NULL;
    }
    for (size_t i = 0; p && i < n; i++)
        p[i] = (size == 1 ? raw[i] : raw[2 * i] << 8 | raw[2 * i + 1]) / (double)max;
    free(raw);
    fclose(f);
    return p;
}

int main(int argc, char **argv)
{
    if (argc != 3) {
        fprintf(stderr, "usage: bench_rmse IMAGE.ppm REFERENCE.ppm\n");
        return 2;
    }
    int w, h, rw, rh;
    double *a = read_ppm(argv[1], &w, &h), *b = read_ppm(argv[2], &rw, &rh);
    if (!a || !b || w != rw || h != rh) {
        if (a && b)
            fprintf(stderr, "bench_rmse: the images differ in size\n");
        free(a);
        free(b);
        return 1;
    }
    size_t n = (size_t)w * (size_t)h * 3;
    double squares = 0, sum = 0;
    for (size_t i = 0; i < n; i++) {
        double d = a[i] - b[i];
        squares += d * d;
        sum += b[i];
    }
    printf("%.5f\n", sqrt(squares / n) / (sum / n));
    free(a);
    free(b);
    return 0;
}
