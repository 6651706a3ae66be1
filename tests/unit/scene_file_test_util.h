/* scene_file_test_util.h - what the scene loader's tests share: a
 * temporary folder (GLINT_TEST_TMP/SCENE_TEST_NAME-PID, which the including
 * file names) with the PNG files the scenes name, loading a scene that must
 * load or must not, a log of the problems reported, and assertions on
 * loaded values. Included after cmocka.h. */
#ifndef GLINT_TESTS_SCENE_FILE_TEST_UTIL_H
#define GLINT_TESTS_SCENE_FILE_TEST_UTIL_H

#include <dirent.h>
#include <math.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>
#include <sys/resource.h>
#include <sys/stat.h>
#include <time.h>
#include <unistd.h>
#include <png.h>
#include <zlib.h>

#include "glint.h"
#include "tmp_tree.h"
#include "scene/scene.h"
#include "scenefile/scene_file.h"


#define PATH_SIZE 1024
#define COUNT(a) (sizeof(a) / sizeof((a)[0]))

static char tmp_dir[PATH_SIZE];

/* ------------------------------------------------------------- helpers */

/* Every problem a load reported, in order. */
typedef struct report_log {
    int count;
    char first[512];
    char all[16384];
} report_log;

static inline void log_report(void *user, const char *message)
{
    report_log *log = user;
    if (log->count == 0)
        snprintf(log->first, sizeof log->first, "%s", message);
    size_t used = strlen(log->all);
    snprintf(log->all + used, sizeof log->all - used, "%s\n", message);
    log->count++;
}

#define assert_near(a, b, tol) near_at((double)(a), (double)(b), (tol), #a, __FILE__, __LINE__)
#define assert_exact(a, b) assert_near((a), (b), 0)

static inline void near_at(double a, double b, double tol, const char *what, const char *file, int line)
{
    if (fabs(a - b) <= tol)
        return;
    print_error("%s is %.17g, expected %.17g (tolerance %g)\n", what, a, b, tol);
    _fail(file, line);
}

#define assert_vec(v, X, Y, Z, tol)              \
    do {                                         \
        assert_near((v).x, (X), (tol));          \
        assert_near((v).y, (Y), (tol));          \
        assert_near((v).z, (Z), (tol));          \
    } while (0)

#define assert_rgb(c, R, G, B, tol)              \
    do {                                         \
        assert_near((c).r, (R), (tol));          \
        assert_near((c).g, (G), (tol));          \
        assert_near((c).b, (B), (tol));          \
    } while (0)

static inline void assert_matrix(const glint_transform *t, const double want[3][4], double tol)
{
    for (int i = 0; i < 3; i++)
        for (int j = 0; j < 4; j++)
            if (!(fabs(t->m[i][j] - want[i][j]) <= tol))
                fail_msg("to_world m[%d][%d] is %.17g, expected %.17g", i, j, t->m[i][j], want[i][j]);
}

static inline void assert_same_material(const glint_material *a, const glint_material *b)
{
    assert_rgb(a->color, b->color.r, b->color.g, b->color.b, 0);
    assert_int_equal(a->texture, b->texture);
    assert_exact(a->ambient, b->ambient);
    assert_exact(a->diffuse, b->diffuse);
    assert_exact(a->specular, b->specular);
    assert_exact(a->shininess, b->shininess);
    assert_exact(a->reflectivity, b->reflectivity);
    assert_exact(a->transparency, b->transparency);
    assert_exact(a->refraction, b->refraction);
    assert_exact(a->ior, b->ior);
    assert_exact(a->tint, b->tint);
    assert_int_equal(a->fresnel, b->fresnel);
}

static inline void assert_same_settings(const glint_settings *a, const glint_settings *b)
{
    assert_int_equal(a->width, b->width);
    assert_int_equal(a->height, b->height);
    assert_int_equal(a->samples_per_pixel, b->samples_per_pixel);
    assert_int_equal(a->sampler, b->sampler);
    assert_int_equal(a->max_depth, b->max_depth);
    assert_rgb(a->background, b->background.r, b->background.g, b->background.b, 0);
    assert_rgb(a->ambient_light, b->ambient_light.r, b->ambient_light.g, b->ambient_light.b, 0);
    assert_int_equal(a->seed, b->seed);
}

static inline double lin(double display)
{
    return glint_srgb_to_linear(display);
}

static inline void tmp_path(char *buf, const char *name)
{
    int n = snprintf(buf, PATH_SIZE, "%s/%s", tmp_dir, name);
    assert_true(n > 0 && n < PATH_SIZE);
}

/* Fills path with tmp_dir/name and makes the folders on the way. */
static inline void tmp_path_made(char *path, const char *name)
{
    tmp_path(path, name);
    for (char *p = path + strlen(tmp_dir) + 1; (p = strchr(p, '/')) != NULL; p++) {
        *p = '\0';
        mkdir(path, 0755);
        *p = '/';
    }
}

/* Writes text to tmp_dir/name. */
static inline void write_tmp(const char *name, const char *text)
{
    char path[PATH_SIZE];
    tmp_path_made(path, name);
    FILE *f = fopen(path, "wb");
    assert_non_null(f);
    assert_int_equal(fwrite(text, 1, strlen(text), f), strlen(text));
    assert_int_equal(fclose(f), 0);
}

/* Replaces each "@TMP@" in `in` with tmp_dir. */
static inline void with_tmp(const char *in, char *out, size_t size)
{
    size_t n = 0;
    while (*in) {
        if (strncmp(in, "@TMP@", 5) == 0) {
            n += (size_t)snprintf(out + n, size - n, "%s", tmp_dir);
            in += 5;
        } else if (n + 1 < size) {
            out[n++] = *in++;
        }
        assert_true(n + 1 < size);
    }
    out[n] = '\0';
}

/* Loads a scene that must be good; fails the test with every problem. */
static inline glint_scene *load_good_named(const char *yaml, const char *name)
{
    report_log log = {0};
    glint_load_options o = {.report = log_report, .report_user = &log};
    glint_error err = {0};
    glint_scene *s = glint_scene_load_memory(yaml, strlen(yaml), name, &o, &err);
    if (!s)
        fail_msg("the scene did not load (%d problems):\n%s", log.count, log.all);
    assert_int_equal(log.count, 0);
    return s;
}

static inline glint_scene *load_good(const char *yaml)
{
    return load_good_named(yaml, "good.yaml");
}

static inline glint_scene *load_good_file(const char *name)
{
    char path[PATH_SIZE];
    tmp_path(path, name);
    report_log log = {0};
    glint_load_options o = {.report = log_report, .report_user = &log};
    glint_error err = {0};
    glint_scene *s = glint_scene_load_file(path, &o, &err);
    if (!s)
        fail_msg("%s did not load (%d problems):\n%s", path, log.count, log.all);
    assert_int_equal(log.count, 0);
    return s;
}

/* Loads a scene that must be refused as bad.yaml; fills log and err. */
static inline void load_bad(const char *yaml, int max_errors, report_log *log, glint_error *err)
{
    glint_load_options o = {.report = log_report, .report_user = log, .max_errors = max_errors};
    glint_scene *s = glint_scene_load_memory(yaml, strlen(yaml), "bad.yaml", &o, err);
    if (s) {
        glint_scene_free(s);
        fail_msg("a bad scene loaded:\n%s", yaml);
    }
    assert_string_equal(err->message, log->first);
}

/* The index of the material with that name, failing when there is none. */
static inline int material_named(const glint_scene *s, const char *name)
{
    int i = scene_find_material(s, name);
    if (i < 0)
        fail_msg("no material named '%s'", name);
    return i;
}

static inline int texture_named(const glint_scene *s, const char *name)
{
    int i = scene_find_texture(s, name);
    if (i < 0)
        fail_msg("no texture named '%s'", name);
    return i;
}

static inline glint_image render(const glint_scene *s)
{
    glint_render_options o = {.threads = 1};
    glint_image img;
    glint_error err = {0};
    if (glint_render(s, &o, &img, NULL, &err))
        fail_msg("render failed: %s", err.message);
    return img;
}

static inline void write_png(const char *name, int width, int height, const unsigned char *rgb)
{
    char path[PATH_SIZE];
    tmp_path_made(path, name);
    png_image img;
    memset(&img, 0, sizeof img);
    img.version = PNG_IMAGE_VERSION;
    img.width = (png_uint_32)width;
    img.height = (png_uint_32)height;
    img.format = PNG_FORMAT_RGB;
    assert_true(png_image_write_to_file(&img, path, 0, rgb, 0, NULL));
}

static inline size_t put_chunk(unsigned char *out, const char *type, const unsigned char *data, uint32_t size)
{
    out[0] = (unsigned char)(size >> 24);
    out[1] = (unsigned char)(size >> 16);
    out[2] = (unsigned char)(size >> 8);
    out[3] = (unsigned char)size;
    memcpy(out + 4, type, 4);
    if (size)
        memcpy(out + 8, data, size);
    uLong crc = crc32(0L, out + 4, 4 + size);
    out[8 + size] = (unsigned char)(crc >> 24);
    out[9 + size] = (unsigned char)(crc >> 16);
    out[10 + size] = (unsigned char)(crc >> 8);
    out[11 + size] = (unsigned char)crc;
    return 12 + size;
}

/* A PNG whose header says 0 x 0 pixels, an empty "PNG" and a good one. */
static inline void write_table_pngs(void)
{
    unsigned char buf[64];
    static const unsigned char sig[8] = {0x89, 'P', 'N', 'G', '\r', '\n', 0x1a, '\n'};
    unsigned char ihdr[13] = {0, 0, 0, 0, 0, 0, 0, 0, 8, 2, 0, 0, 0};
    memcpy(buf, sig, 8);
    size_t n = 8;
    n += put_chunk(buf + n, "IHDR", ihdr, 13);
    n += put_chunk(buf + n, "IEND", NULL, 0);
    char path[PATH_SIZE];
    tmp_path(path, "zero.png");
    FILE *f = fopen(path, "wb");
    assert_non_null(f);
    assert_int_equal(fwrite(buf, 1, n, f), n);
    assert_int_equal(fclose(f), 0);
    write_tmp("empty.png", "");
    static const unsigned char green[3] = {0, 255, 0};
    write_png("one.png", 1, 1, green);
}

/* ------------------------------------------------------------- fixtures */

static inline int setup_dir(void **state)
{
    const char *base = getenv("GLINT_TEST_TMP");
    if (!base || !*base)
        base = "/tmp";
    snprintf(tmp_dir, sizeof tmp_dir, "%s/%s-%ld", base, SCENE_TEST_NAME, (long)getpid());
    remove_tree(tmp_dir);
    if (mkdir(tmp_dir, 0755) != 0)
        return -1;
    write_table_pngs();
    return 0;
}

static inline int teardown_dir(void **state)
{
    remove_tree(tmp_dir);
    return 0;
}

#endif
