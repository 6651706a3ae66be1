/* test_exr_write.c - OpenEXR output read back with OpenEXR's own reading
 * API: the header (R, G and B of the pixel type asked for, the size, ZIP,
 * scanlines in increasing y), and every channel of every pixel of an image
 * of values past 1, tiny, zero, negative and past half's range: 32-bit
 * floats to the bit, halves equal to the value rounded to half by the
 * definition of IEEE 754's binary16, computed here rather than by OpenEXR's
 * conversion. Then the default, and the refusals OpenEXR files share with
 * the other formats. */
#include <stdarg.h>
#include <stddef.h>
#include <setjmp.h>
#include <stdint.h>
#include <cmocka.h>

#include <dirent.h>
#include <math.h>
#include <stdbool.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>
#include <unistd.h>
#include <OpenEXR/openexr.h>

#include "glint.h"
#include "tmp_tree.h"

#define PATH_SIZE 1024
/* 101 rows: six whole blocks of 16, which threads compress at once, and a
 * short one. */
#define WIDTH 5
#define HEIGHT 101

static char tmp_dir[PATH_SIZE];

static void tmp_path(char *buf, const char *name)
{
    int n = snprintf(buf, PATH_SIZE, "%s/%s", tmp_dir, name);
    assert_true(n > 0 && n < PATH_SIZE);
}

/* The values each a half float sits between or on: its largest (65504),
 * the ties around it that round down to it and up to infinity (65519.99,
 * 65520), its smallest normal (2^-14) and subnormal (2^-24) and half of it,
 * which ties to zero, ties between neighbours (2049 to 2048, 2051 to
 * 2052), and infinity and NaN. */
static const float special_values[] = {
    0.0f, -0.0f, 1.0f, 0.5f, 1.5f, 0.1f, 1.0f / 3, 3.14159265f, 100.25f, 1000.7f, -2.5f,
    65504.0f, 65519.99f, 65520.0f, 1e6f, 3.4e38f, INFINITY, NAN,
    6.103515625e-05f, 6.0e-05f, 3.0e-05f, 5.9604644775390625e-08f, 2.98023223876953125e-08f, 4.0e-08f, 1e-9f,
    2049.0f, 2051.0f, 1.00048828125f, 1.000732421875f, 1e-3f,
};

#define SPECIAL_COUNT (sizeof special_values / sizeof special_values[0])

/* The image: the special values first, then pseudo-random values from
 * 2^-20 to 2^20. */
static glint_image test_image(void)
{
    glint_image img = {WIDTH, HEIGHT, malloc(sizeof(float) * 3 * WIDTH * HEIGHT)};
    assert_non_null(img.pixels);
    uint32_t state = 7;
    for (size_t i = 0; i < 3 * WIDTH * HEIGHT; i++) {
        state = state * 1664525u + 1013904223u;
        float noise = ldexpf((float)(state >> 8) / (1 << 24), (int)(state % 41) - 20);
        img.pixels[i] = i < SPECIAL_COUNT ? special_values[i] : noise;
    }
    return img;
}

/* x rounded to the nearest half float, ties to the even one: between 2^e
 * and 2^(e+1) halves lie 2^(e-10) apart, and below 2^-14, the smallest
 * normal, 2^-24 apart; what rounds past 65504 is infinity. */
static float nearest_half(float x)
{
    if (isnan(x) || isinf(x))
        return x;
    int e;
    frexp(fabs(x), &e);
    double step = ldexp(1.0, (e - 1 < -14 ? -14 : e - 1) - 10);
    double rounded = nearbyint(fabs(x) / step) * step;
    return (float)copysign(rounded > 65504 ? INFINITY : rounded, x);
}

/* What a file holds, as OpenEXR reads it. */
typedef struct exr_contents {
    exr_storage_t storage;
    exr_compression_t compression;
    exr_lineorder_t line_order;
    exr_attr_box2i_t data_window, display_window;
    int channels;
    exr_pixel_type_t type[3];       /* R, G, B */
    float pixels[3 * WIDTH * HEIGHT]; /* as glint_image lays them out */
} exr_contents;

static int channel_index(const char *name)
{
    return strcmp(name, "R") == 0 ? 0 : strcmp(name, "G") == 0 ? 1 : strcmp(name, "B") == 0 ? 2 : -1;
}

/* Decodes every block of the file's one part into out->pixels, each channel
 * converted to float (exact from half). */
static void read_pixels(exr_context_t ctxt, exr_contents *out)
{
    int32_t rows;
    assert_int_equal(exr_get_scanlines_per_chunk(ctxt, 0, &rows), EXR_ERR_SUCCESS);
    assert_int_equal(rows, 16); /* ZIP's blocks */
    exr_decode_pipeline_t decoder = EXR_DECODE_PIPELINE_INITIALIZER;
    for (int y = 0; y < HEIGHT; y += rows) {
        exr_chunk_info_t chunk;
        assert_int_equal(exr_read_scanline_chunk_info(ctxt, 0, y, &chunk), EXR_ERR_SUCCESS);
        assert_int_equal(y == 0 ? exr_decoding_initialize(ctxt, 0, &chunk, &decoder)
                                : exr_decoding_update(ctxt, 0, &chunk, &decoder),
                         EXR_ERR_SUCCESS);
        for (int c = 0; c < decoder.channel_count; c++) {
            exr_coding_channel_info_t *channel = &decoder.channels[c];
            int k = channel_index(channel->channel_name);
            assert_true(k >= 0);
            channel->decode_to_ptr = (uint8_t *)(out->pixels + 3 * WIDTH * y + k);
            channel->user_data_type = EXR_PIXEL_FLOAT;
            channel->user_bytes_per_element = sizeof(float);
            channel->user_pixel_stride = 3 * sizeof(float);
            channel->user_line_stride = 3 * sizeof(float) * WIDTH;
        }
        if (y == 0)
            assert_int_equal(exr_decoding_choose_default_routines(ctxt, 0, &decoder), EXR_ERR_SUCCESS);
        assert_int_equal(exr_decoding_run(ctxt, 0, &decoder), EXR_ERR_SUCCESS);
    }
    assert_int_equal(exr_decoding_destroy(ctxt, &decoder), EXR_ERR_SUCCESS);
}

static void read_exr(const char *path, exr_contents *out)
{
    exr_context_t ctxt;
    exr_context_initializer_t init = EXR_DEFAULT_CONTEXT_INITIALIZER;
    assert_int_equal(exr_start_read(&ctxt, path, &init), EXR_ERR_SUCCESS);
    int parts;
    assert_int_equal(exr_get_count(ctxt, &parts), EXR_ERR_SUCCESS);
    assert_int_equal(parts, 1);
    assert_int_equal(exr_get_storage(ctxt, 0, &out->storage), EXR_ERR_SUCCESS);
    assert_int_equal(exr_get_compression(ctxt, 0, &out->compression), EXR_ERR_SUCCESS);
    assert_int_equal(exr_get_lineorder(ctxt, 0, &out->line_order), EXR_ERR_SUCCESS);
    assert_int_equal(exr_get_data_window(ctxt, 0, &out->data_window), EXR_ERR_SUCCESS);
    assert_int_equal(exr_get_display_window(ctxt, 0, &out->display_window), EXR_ERR_SUCCESS);
    const exr_attr_chlist_t *channels;
    assert_int_equal(exr_get_channels(ctxt, 0, &channels), EXR_ERR_SUCCESS);
    out->channels = channels->num_channels;
    for (int c = 0; c < channels->num_channels; c++) {
        int k = channel_index(channels->entries[c].name.str);
        assert_true(k >= 0);
        out->type[k] = channels->entries[c].pixel_type;
        assert_int_equal(channels->entries[c].x_sampling, 1);
        assert_int_equal(channels->entries[c].y_sampling, 1);
    }
    read_pixels(ctxt, out);
    assert_int_equal(exr_finish(&ctxt), EXR_ERR_SUCCESS);
}

static void expect_header(const exr_contents *got, exr_pixel_type_t type)
{
    assert_int_equal(got->storage, EXR_STORAGE_SCANLINE);
    assert_int_equal(got->compression, EXR_COMPRESSION_ZIP);
    assert_int_equal(got->line_order, EXR_LINEORDER_INCREASING_Y);
    const exr_attr_box2i_t *windows[] = {&got->data_window, &got->display_window};
    for (int w = 0; w < 2; w++) {
        assert_int_equal(windows[w]->min.x, 0);
        assert_int_equal(windows[w]->min.y, 0);
        assert_int_equal(windows[w]->max.x, WIDTH - 1);
        assert_int_equal(windows[w]->max.y, HEIGHT - 1);
    }
    assert_int_equal(got->channels, 3);
    for (int c = 0; c < 3; c++)
        assert_int_equal(got->type[c], type);
}

static bool same_float(float a, float b)
{
    return (isnan(a) && isnan(b)) || memcmp(&a, &b, sizeof a) == 0;
}

static float exactly(float x)
{
    return x;
}

/* Writes the test image to tmp_dir/name in pixel type `pixel`, reads it
 * back, checks its header says `type`, and that every sample is held(the
 * sample written); returns what was read (free it). */
static exr_contents *round_trip(const char *name, glint_exr_pixel pixel, exr_pixel_type_t type, float (*held)(float))
{
    char path[PATH_SIZE];
    glint_error err = {0};
    glint_image img = test_image();
    glint_image_write_options options = {.exr_pixel = pixel};
    tmp_path(path, name);
    assert_int_equal(glint_image_write_ex(&img, path, &options, &err), GLINT_OK);
    exr_contents *got = calloc(1, sizeof *got);
    assert_non_null(got);
    read_exr(path, got);
    expect_header(got, type);
    for (size_t i = 0; i < 3 * WIDTH * HEIGHT; i++)
        if (!same_float(got->pixels[i], held(img.pixels[i])))
            fail_msg("sample %zu: wrote %.9g, read %.9g, expected %.9g", i, img.pixels[i], got->pixels[i],
                     held(img.pixels[i]));
    glint_image_free(&img);
    return got;
}

static void test_exr_float_bit_exact(void **state)
{
    free(round_trip("float.exr", GLINT_EXR_FLOAT, EXR_PIXEL_FLOAT, exactly));
}

static void test_exr_half_rounds_to_nearest(void **state)
{
    exr_contents *got = round_trip("half.exr", GLINT_EXR_HALF, EXR_PIXEL_HALF, nearest_half);
    /* What the documentation promises, spelled out. */
    assert_true(got->pixels[11] == 65504.0f && got->pixels[12] == 65504.0f);
    assert_true(isinf(got->pixels[13]) && isinf(got->pixels[14]) && isinf(got->pixels[15]));
    assert_true(got->pixels[10] == -2.5f);
    assert_true(got->pixels[21] == 5.9604644775390625e-08f && got->pixels[22] == 0.0f);
    free(got);
}

/* Whether the files at paths a and b hold the same bytes. */
static bool same_file(const char *a, const char *b)
{
    FILE *fa = fopen(a, "rb"), *fb = fopen(b, "rb");
    assert_non_null(fa);
    assert_non_null(fb);
    int ca, cb;
    do {
        ca = fgetc(fa);
        cb = fgetc(fb);
    } while (ca == cb && ca != EOF);
    fclose(fa);
    fclose(fb);
    return ca == cb;
}

/* glint_image_write, NULL options and GLINT_EXR_HALF write the same file,
 * whatever the extension's case; the other formats ignore the option. */
static void test_exr_default_is_half(void **state)
{
    char half[PATH_SIZE], path[PATH_SIZE], plain[PATH_SIZE];
    glint_error err = {0};
    glint_image img = test_image();
    glint_image_write_options options = {.exr_pixel = GLINT_EXR_HALF};
    tmp_path(half, "half-too.exr");
    assert_int_equal(glint_image_write_ex(&img, half, &options, &err), GLINT_OK);
    tmp_path(path, "DEFAULT.EXR");
    assert_int_equal(glint_image_write(&img, path, &err), GLINT_OK);
    assert_true(same_file(half, path));
    tmp_path(path, "null-options.exr");
    assert_int_equal(glint_image_write_ex(&img, path, NULL, &err), GLINT_OK);
    assert_true(same_file(half, path));

    options.exr_pixel = GLINT_EXR_FLOAT;
    tmp_path(plain, "plain.ppm");
    tmp_path(path, "float.ppm");
    assert_int_equal(glint_image_write(&img, plain, &err), GLINT_OK);
    assert_int_equal(glint_image_write_ex(&img, path, &options, &err), GLINT_OK);
    assert_true(same_file(plain, path));
    glint_image_free(&img);
}

static int count_temporaries(void)
{
    DIR *d = opendir(tmp_dir);
    assert_non_null(d);
    int n = 0;
    for (struct dirent *e; (e = readdir(d)) != NULL;)
        n += strstr(e->d_name, ".tmp-") != NULL;
    closedir(d);
    return n;
}

/* A pixel type that is none is refused before anything is written, and a
 * missing directory gives the same error as for PNG, before and after
 * rendering; neither leaves anything behind. */
static void test_exr_refusals(void **state)
{
    char path[PATH_SIZE], want[2 * PATH_SIZE];
    glint_error err = {0};
    glint_image img = test_image();
    glint_image_write_options options = {.exr_pixel = (glint_exr_pixel)2};
    tmp_path(path, "refused.exr");
    snprintf(want, sizeof want, "cannot write '%s': unknown OpenEXR pixel type 2", path);
    assert_int_equal(glint_image_write_ex(&img, path, &options, &err), GLINT_ERR_INVALID);
    assert_string_equal(err.message, want);
    assert_int_equal(access(path, F_OK), -1);

    tmp_path(path, "no-such-dir/out.exr");
    snprintf(want, sizeof want, "cannot write '%s': No such file or directory", path);
    assert_int_equal(glint_image_check_path(path, &err), GLINT_ERR_IO);
    assert_string_equal(err.message, want);
    assert_int_equal(glint_image_write(&img, path, &err), GLINT_ERR_IO);
    assert_string_equal(err.message, want);
    assert_int_equal(count_temporaries(), 0);
    glint_image_free(&img);
}

static int setup_dir(void **state)
{
    return make_tmp_tree(tmp_dir, sizeof tmp_dir, "glint-exr-write");
}

static int teardown_dir(void **state)
{
    remove_tree(tmp_dir);
    return 0;
}

int main(void)
{
    const struct CMUnitTest tests[] = {
        cmocka_unit_test(test_exr_float_bit_exact),
        cmocka_unit_test(test_exr_half_rounds_to_nearest),
        cmocka_unit_test(test_exr_default_is_half),
        cmocka_unit_test(test_exr_refusals),
    };
    return cmocka_run_group_tests(tests, setup_dir, teardown_dir);
}
