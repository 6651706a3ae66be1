/* image_test_files.h - what the image writing and texture decoding tests
 * share: a temporary folder and its files, the sample 3x2 image and a
 * noise image written through glint_image_write, and assertions on
 * messages and near values. Included after cmocka.h. */
#ifndef GLINT_TESTS_IMAGE_TEST_FILES_H
#define GLINT_TESTS_IMAGE_TEST_FILES_H

#include <math.h>
#include <stdint.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>
#include "glint.h"
#include "tmp_tree.h"

#define PATH_SIZE 1024

/* The test's temporary folder GLINT_TEST_TMP/TMP_TREE_NAME-PID, which the
 * including file names, made by the group's setup and removed by its
 * teardown. */
static char tmp_dir[PATH_SIZE];

static inline int setup_dir(void **state)
{
    return make_tmp_tree(tmp_dir, sizeof tmp_dir, TMP_TREE_NAME);
}

static inline int teardown_dir(void **state)
{
    remove_tree(tmp_dir);
    return 0;
}

static inline void tmp_path(char *buf, const char *name)
{
    int n = snprintf(buf, PATH_SIZE, "%s/%s", tmp_dir, name);
    assert_true(n > 0 && n < PATH_SIZE);
}

static inline void write_bytes(const char *path, const void *data, size_t size)
{
    FILE *f = fopen(path, "wb");
    assert_non_null(f);
    assert_int_equal(fwrite(data, 1, size, f), size);
    assert_int_equal(fclose(f), 0);
}

/* Returns the whole file (free it), or NULL (and *size 0) when it cannot be
 * opened. */
static inline unsigned char *read_bytes(const char *path, size_t *size)
{
    *size = 0;
    FILE *f = fopen(path, "rb");
    if (!f)
        return NULL;
    size_t cap = 4096, len = 0;
    unsigned char *buf = malloc(cap);
    assert_non_null(buf);
    for (;;) {
        len += fread(buf + len, 1, cap - len, f);
        if (len < cap)
            break;
        cap *= 2;
        buf = realloc(buf, cap);
        assert_non_null(buf);
    }
    assert_int_equal(ferror(f), 0);
    fclose(f);
    *size = len;
    return buf;
}

static inline void expect_error(glint_status got, const glint_error *err, glint_status want,
                         const char *message)
{
    assert_int_equal(got, want);
    assert_string_equal(err->message, message);
}

/* cmocka 1.1.5, Debian 12's, has no assert_double_equal. */
#define assert_near(a, b, tolerance) near_or_fail((a), (b), (tolerance), #a, __FILE__, __LINE__)

static inline void near_or_fail(double a, double b, double tolerance, const char *expr, const char *file,
                         int line)
{
    if (!(fabs(a - b) <= tolerance))
        fail_msg("%s:%d: %s = %.17g, expected %.17g within %g", file, line, expr, a, b, tolerance);
}

static inline uint32_t noise(uint32_t *state)
{
    *state = *state * 1664525u + 1013904223u;
    return *state >> 24;
}

static inline glint_image noise_image(int width, int height)
{
    glint_image img = {width, height, malloc(sizeof(float) * 3 * (size_t)width * height)};
    assert_non_null(img.pixels);
    uint32_t state = 42;
    for (int i = 0; i < 3 * width * height; i++)
        img.pixels[i] = (float)noise(&state) / 255.0f;
    return img;
}

/* 3x2 linear pixels, with an out-of-range, a NaN and a negative value. */
static const float sample_linear[18] = {
    0.0f, 1.0f, 0.5f,    0.214f, NAN, -1.0f,    2.0f, 0.001f, 0.0031308f,
    0.18f, 0.75f, 0.05f, 1e-5f, 0.9f, 0.3f,     0.01f, 0.6f, 0.02f,
};

/* A copy of sample_linear as an image (free it). */
static inline glint_image sample_image(void)
{
    glint_image img = {3, 2, malloc(sizeof sample_linear)};
    assert_non_null(img.pixels);
    memcpy(img.pixels, sample_linear, sizeof sample_linear);
    return img;
}

/* Writes img (then frees it) to tmp_dir/name, which path receives, and
 * returns the file's bytes and *size: the caller frees them. */
static inline unsigned char *write_and_read(glint_image *img, const char *name, char *path, size_t *size)
{
    glint_error err = {0};
    tmp_path(path, name);
    assert_int_equal(glint_image_write(img, path, &err), GLINT_OK);
    glint_image_free(img);
    unsigned char *bytes = read_bytes(path, size);
    assert_non_null(bytes);
    return bytes;
}

#endif
