/* test_image_write.c - the sRGB curve, the image format registry, and
 * PNG/PPM writing with its atomic replace, including every refusal
 * message. */
#include <stdarg.h>
#include <stddef.h>
#include <setjmp.h>
#include <stdint.h>
#include <cmocka.h>

#include <dirent.h>
#include <errno.h>
#include <fcntl.h>
#include <signal.h>
#include <sys/resource.h>
#include <sys/stat.h>
#include <unistd.h>
#include <png.h>
#include <zlib.h>

#define TMP_TREE_NAME "glint-image-write"
#include "image_test_files.h"
#include "image/png_encode.h"
#include "image/srgb.h"
#include "image/texture_image.h"

/* ------------------------------------------------------------- helpers */

/* Counts the entries of dir whose name contains `part` ("" counts all). */
static int count_entries(const char *dir, const char *part)
{
    DIR *d = opendir(dir);
    assert_non_null(d);
    int n = 0;
    struct dirent *e;
    while ((e = readdir(d)) != NULL)
        if (strcmp(e->d_name, ".") != 0 && strcmp(e->d_name, "..") != 0
            && strstr(e->d_name, part) != NULL)
            n++;
    closedir(d);
    return n;
}

/* libpng's reading of the 16-bit RGB PNG at path, width x height, its
 * samples as stored (no gamma or other transformation) into rgb. */
static void read_png16(const char *path, int width, int height, uint16_t *rgb)
{
    FILE *f = fopen(path, "rb");
    assert_non_null(f);
    png_structp png = png_create_read_struct(PNG_LIBPNG_VER_STRING, NULL, NULL, NULL);
    assert_non_null(png);
    png_infop info = png_create_info_struct(png);
    assert_non_null(info);
    if (setjmp(png_jmpbuf(png)))
        fail_msg("libpng could not read %s", path);
    png_init_io(png, f);
    png_read_info(png, info);
    assert_int_equal(png_get_image_width(png, info), width);
    assert_int_equal(png_get_image_height(png, info), height);
    assert_int_equal(png_get_bit_depth(png, info), 16);
    assert_int_equal(png_get_color_type(png, info), PNG_COLOR_TYPE_RGB);
    unsigned char row[6 * 512];
    assert_true(width <= 512);
    for (int y = 0; y < height; y++) {
        png_read_row(png, row, NULL);
        for (int i = 0; i < 3 * width; i++)
            rgb[3 * width * y + i] = (uint16_t)(row[2 * i] << 8 | row[2 * i + 1]);
    }
    png_read_end(png, NULL);
    png_destroy_read_struct(&png, &info, NULL);
    fclose(f);
}

/* ---------------------------------------------------------------- sRGB */

static void test_srgb_known_values(void **state)
{
    assert_near(glint_linear_to_srgb(0.5), 0.7353569830524495, 1e-12);
    assert_near(glint_srgb_to_linear(0.7353569830524495), 0.5, 1e-12);
    assert_near(glint_linear_to_srgb(0.0), 0.0, 0.0);
    assert_near(glint_linear_to_srgb(1.0), 1.0, 1e-12);
    assert_near(glint_srgb_to_linear(1.0), 1.0, 1e-12);
    assert_near(glint_linear_to_srgb(0.001), 0.01292, 1e-12);
    assert_near(glint_srgb_to_linear(0.02), 0.02 / 12.92, 1e-15);
    /* out of range and NaN clamp, NaN to black */
    assert_near(glint_linear_to_srgb(-1.0), 0.0, 0.0);
    assert_near(glint_linear_to_srgb(7.0), 1.0, 1e-12);
    assert_near(glint_linear_to_srgb(NAN), 0.0, 0.0);
    assert_near(glint_linear_to_srgb(-INFINITY), 0.0, 0.0);
    assert_near(glint_linear_to_srgb(INFINITY), 1.0, 1e-12);
}

static int formula_byte(float x)
{
    return (int)(glint_linear_to_srgb(x) * 255.0 + 0.5);
}

/* The table-driven encoder gives exactly the formula's byte: on both sides
 * of every step between codes, on a million spread values, and on the
 * specials. */
static void test_srgb_byte_matches_formula(void **state)
{
    for (int k = 1; k <= 255; k++) {
        /* the step up to code k, found by bisection on the formula */
        float lo = 0, hi = 1;
        while (nextafterf(lo, 2) < hi) {
            float mid = lo + (hi - lo) / 2;
            if (mid <= lo || mid >= hi)
                break;
            if (formula_byte(mid) >= k)
                hi = mid;
            else
                lo = mid;
        }
        for (float x = nextafterf(lo, -1), n = 0; n < 4; x = nextafterf(x, 2), n++)
            assert_int_equal(srgb_byte(x), formula_byte(x));
    }
    uint32_t h = 12345;
    for (int i = 0; i < 1000000; i++) {
        h = h * 1664525u + 1013904223u;
        float x = (float)(h >> 8) / (float)(1u << 24) * 1.1f - 0.05f;
        assert_int_equal(srgb_byte(x), formula_byte(x));
    }
    assert_int_equal(srgb_byte(0), 0);
    assert_int_equal(srgb_byte(-1), 0);
    assert_int_equal(srgb_byte(NAN), 0);
    assert_int_equal(srgb_byte(-INFINITY), 0);
    assert_int_equal(srgb_byte(1), 255);
    assert_int_equal(srgb_byte(7), 255);
    assert_int_equal(srgb_byte(INFINITY), 255);
    assert_int_equal(srgb_byte(0.5f), 188);
}

static void test_srgb_continuous_at_boundary(void **state)
{
    double below = nextafter(0.0031308, 0.0), at = 0.0031308;
    /* the standard's rounded constants leave a step of 3e-8 here */
    assert_near(glint_linear_to_srgb(below), glint_linear_to_srgb(at), 1e-7);
    double sbelow = nextafter(0.04045, 0.0);
    assert_near(glint_srgb_to_linear(sbelow), glint_srgb_to_linear(0.04045), 1e-8);
}

static void test_srgb_round_trips(void **state)
{
    for (int i = 0; i <= 10000; i++) {
        double x = i / 10000.0;
        assert_near(glint_srgb_to_linear(glint_linear_to_srgb(x)), x, 1e-9);
        assert_near(glint_linear_to_srgb(glint_srgb_to_linear(x)), x, 1e-9);
    }
    /* every 8-bit code survives decode then encode, as textures need */
    for (int v = 0; v < 256; v++) {
        float linear = (float)glint_srgb_to_linear(v / 255.0);
        assert_int_equal((int)(glint_linear_to_srgb(linear) * 255.0 + 0.5), v);
    }
}

/* ------------------------------------------------------------- writing */

/* The 8-bit sRGB bytes sample_linear must become. */
static const unsigned char sample_srgb[18] = {
    0, 255, 188,  127, 0, 0,    255, 3, 10,
    118, 225, 63, 0, 243, 149,  25, 203, 39,
};

/* libpng's decoding of bytes, which must be a width x height RGB PNG
 * (free the result). */
static unsigned char *decode_png(const unsigned char *bytes, size_t size, int width, int height)
{
    png_image png;
    memset(&png, 0, sizeof png);
    png.version = PNG_IMAGE_VERSION;
    assert_true(png_image_begin_read_from_memory(&png, bytes, size));
    assert_int_equal(png.width, width);
    assert_int_equal(png.height, height);
    png.format = PNG_FORMAT_RGB;
    unsigned char *pixels = malloc(PNG_IMAGE_SIZE(png));
    assert_non_null(pixels);
    assert_true(png_image_finish_read(&png, NULL, pixels, 0, NULL));
    return pixels;
}

static void test_write_ppm_bytes(void **state)
{
    char path[PATH_SIZE];
    glint_image img = sample_image();
    size_t size;
    unsigned char *bytes = write_and_read(&img, "sample.ppm", path, &size);
    static const char header[] = "P6\n3 2\n255\n";
    assert_int_equal(size, strlen(header) + 18);
    assert_memory_equal(bytes, header, strlen(header));
    assert_memory_equal(bytes + strlen(header), sample_srgb, 18);
    free(bytes);

    /* the usual mode of a new file, not mkstemp's 0600 */
    mode_t mask = umask(0);
    umask(mask);
    struct stat st;
    assert_int_equal(stat(path, &st), 0);
    assert_int_equal(st.st_mode & 0777, 0666 & ~mask);
    assert_int_equal(count_entries(tmp_dir, ".tmp-"), 0);
}

static void test_write_png_round_trip(void **state)
{
    char path[PATH_SIZE];
    glint_error err = {0};
    glint_image img = sample_image();
    size_t size;
    unsigned char *bytes = write_and_read(&img, "sample.png", path, &size);
    assert_true(size > 33);
    assert_memory_equal(bytes + 12, "IHDR", 4);
    assert_int_equal(bytes[24], 8); /* bit depth */
    assert_int_equal(bytes[25], 2); /* RGB */
    assert_int_equal(bytes[28], 0); /* not interlaced */
    bool has_srgb = false;
    for (size_t i = 33; i + 8 <= size;) {
        uint32_t len = (uint32_t)bytes[i] << 24 | (uint32_t)bytes[i + 1] << 16
                       | (uint32_t)bytes[i + 2] << 8 | bytes[i + 3];
        if (memcmp(bytes + i + 4, "sRGB", 4) == 0)
            has_srgb = true;
        i += 12 + (size_t)len;
    }
    assert_true(has_srgb);
    free(bytes);

    texture_image tex;
    assert_int_equal(texture_image_load_file(&tex, path, &err), GLINT_OK);
    assert_int_equal(tex.width, 3);
    assert_int_equal(tex.height, 2);
    for (int i = 0; i < 18; i++) {
        assert_true(texture_image_at(&tex, i) == (float)glint_srgb_to_linear(sample_srgb[i] / 255.0));
        assert_near(glint_linear_to_srgb(texture_image_at(&tex, i)), glint_linear_to_srgb(sample_linear[i]),
                            0.5 / 255 + 1e-6);
    }
    texture_image_free(&tex);
    assert_null(tex.srgb);
    assert_int_equal(count_entries(tmp_dir, ".tmp-"), 0);
}

/* Every byte libpng decodes is the film's sRGB byte: over many rows (so the
 * row filter matters), smooth ramps and incompressible noise, and values
 * that clamp. */
static void test_write_png_decodes_to_srgb_bytes(void **state)
{
    enum { width = 301, height = 203 };
    char path[PATH_SIZE];
    glint_image img = noise_image(width, height);
    for (int y = 0; y < height / 2; y++)
        for (int x = 0; x < width; x++)
            for (int c = 0; c < 3; c++)
                img.pixels[3 * (y * width + x) + c] = (float)(x + c * y) / (width + 2 * height);
    memcpy(img.pixels, sample_linear, sizeof sample_linear);
    size_t n = 3 * (size_t)width * height;
    unsigned char *want = malloc(n);
    assert_non_null(want);
    srgb_encode(want, img.pixels, n);
    size_t size;
    unsigned char *bytes = write_and_read(&img, "bytes.png", path, &size);
    assert_true(size > 64 * 1024);
    unsigned char *got = decode_png(bytes, size, width, height);
    assert_memory_equal(got, want, n);
    free(bytes);
    free(want);
    free(got);
}

/* sample_linear's 16-bit sRGB codes, worked out apart (Python, from the
 * sRGB formula): what 16-bit PNG and PPM files hold. */
static const uint16_t sample_srgb16[18] = {
    0, 65535, 48192,  32765, 0, 0,    65535, 847, 2651,
    30235, 57725, 16240, 8, 62565, 38261,  6544, 52280, 9942,
};

static void test_write_16bit_ppm(void **state)
{
    char path[PATH_SIZE];
    glint_error err = {0};
    glint_image img = sample_image();
    tmp_path(path, "deep.ppm");
    glint_image_write_options sixteen = {.bit_depth = 16};
    assert_int_equal(glint_image_write_ex(&img, path, &sixteen, &err), GLINT_OK);
    glint_image_free(&img);
    size_t size;
    unsigned char *bytes = read_bytes(path, &size);
    static const char header[] = "P6\n3 2\n65535\n";
    assert_int_equal(size, strlen(header) + 36);
    assert_memory_equal(bytes, header, strlen(header));
    for (int i = 0; i < 18; i++)
        assert_int_equal(bytes[strlen(header) + 2 * i] << 8 | bytes[strlen(header) + 2 * i + 1], sample_srgb16[i]);
    free(bytes);
}

/* A 16-bit PNG holds every channel's 16-bit code, over many rows (the Up
 * filter works on bytes) and slices (several threads deflate it). */
static void test_write_16bit_png(void **state)
{
    enum { width = 307, height = 499 };
    char path[PATH_SIZE];
    glint_error err = {0};
    glint_image img = noise_image(width, height);
    memcpy(img.pixels, sample_linear, sizeof sample_linear);
    size_t n = 3 * (size_t)width * height;
    float *linear = malloc(n * sizeof *linear);
    uint16_t *got = malloc(n * sizeof *got);
    assert_non_null(linear);
    assert_non_null(got);
    memcpy(linear, img.pixels, n * sizeof *linear);
    tmp_path(path, "deep.png");
    glint_image_write_options sixteen = {.bit_depth = 16};
    assert_int_equal(glint_image_write_ex(&img, path, &sixteen, &err), GLINT_OK);
    glint_image_free(&img);
    read_png16(path, width, height, got);
    for (int i = 0; i < 18; i++)
        assert_int_equal(got[i], sample_srgb16[i]);
    for (size_t i = 0; i < n; i++)
        /* within half a 16-bit step of the exact code: 8 bits would be 128 steps apart */
        assert_near(got[i], glint_linear_to_srgb(linear[i]) * 65535, 0.5 + 1e-6);
    free(linear);
    free(got);
}

/* Bit depths other than 8 and 16 are refused before anything is written. */
static void test_write_bad_bit_depth(void **state)
{
    char path[PATH_SIZE];
    glint_error err = {0};
    glint_image img = sample_image();
    tmp_path(path, "shallow.png");
    static const int bad[] = {1, 7, 12, 32, -8};
    for (size_t k = 0; k < sizeof bad / sizeof bad[0]; k++) {
        glint_image_write_options o = {.bit_depth = bad[k]};
        char want[PATH_SIZE + 64];
        snprintf(want, sizeof want, "cannot write '%s': bit depth %d is neither 8 nor 16", path, bad[k]);
        expect_error(glint_image_write_ex(&img, path, &o, &err), &err, GLINT_ERR_INVALID, want);
        assert_int_equal(access(path, F_OK), -1);
    }
    glint_image_write_options eight = {.bit_depth = 8};
    assert_int_equal(glint_image_write_ex(&img, path, &eight, &err), GLINT_OK);
    size_t size;
    unsigned char *bytes = read_bytes(path, &size);
    assert_int_equal(bytes[24], 8);
    free(bytes);
    glint_image_free(&img);
}

static void test_write_extension_any_case(void **state)
{
    char path[PATH_SIZE];
    glint_error err = {0};
    glint_image img = sample_image();
    tmp_path(path, "UPPER.PNG");
    assert_int_equal(glint_image_check_path(path, &err), GLINT_OK);
    assert_int_equal(glint_image_write(&img, path, &err), GLINT_OK);
    size_t size;
    unsigned char *bytes = read_bytes(path, &size);
    assert_non_null(bytes);
    assert_memory_equal(bytes, "\x89PNG", 4);
    free(bytes);

    tmp_path(path, "mixed.PpM");
    assert_int_equal(glint_image_write(&img, path, &err), GLINT_OK);
    bytes = read_bytes(path, &size);
    assert_non_null(bytes);
    assert_memory_equal(bytes, "P6\n", 3);
    free(bytes);
    glint_image_free(&img);
}

static void test_write_replaces_existing_file(void **state)
{
    char path[PATH_SIZE];
    glint_error err = {0};
    glint_image img = sample_image();
    tmp_path(path, "replaced.ppm");
    write_bytes(path, "old contents", 12);
    assert_int_equal(glint_image_write(&img, path, &err), GLINT_OK);
    glint_image_free(&img);
    size_t size;
    unsigned char *bytes = read_bytes(path, &size);
    assert_non_null(bytes);
    assert_memory_equal(bytes, "P6\n3 2\n255\n", 11);
    free(bytes);
}

static void test_write_missing_directory(void **state)
{
    char dir[PATH_SIZE], path[PATH_SIZE], want[2 * PATH_SIZE];
    glint_error err = {0};
    glint_image img = sample_image();
    tmp_path(dir, "no-such-dir");
    tmp_path(path, "no-such-dir/out.png");
    snprintf(want, sizeof want, "cannot write '%s': No such file or directory", path);

    expect_error(glint_image_check_path(path, &err), &err, GLINT_ERR_IO, want);
    memset(&err, 0, sizeof err);
    expect_error(glint_image_write(&img, path, &err), &err, GLINT_ERR_IO, want);
    glint_image_free(&img);
    assert_int_equal(access(dir, F_OK), -1);
    assert_int_equal(count_entries(tmp_dir, ".tmp-"), 0);
}

static void test_write_read_only_directory(void **state)
{
    if (geteuid() == 0)
        skip(); /* root writes into read-only directories anyway */
    char dir[PATH_SIZE], path[PATH_SIZE], want[2 * PATH_SIZE];
    glint_error err = {0};
    glint_image img = sample_image();
    tmp_path(dir, "read-only");
    assert_int_equal(mkdir(dir, 0555), 0);
    tmp_path(path, "read-only/out.ppm");
    snprintf(want, sizeof want, "cannot write '%s': Permission denied", path);

    expect_error(glint_image_check_path(path, &err), &err, GLINT_ERR_IO, want);
    memset(&err, 0, sizeof err);
    expect_error(glint_image_write(&img, path, &err), &err, GLINT_ERR_IO, want);
    glint_image_free(&img);
    assert_int_equal(count_entries(dir, ""), 0);
}

/* A file size limit makes the write fail half way, even for root. */
static void test_failed_write_keeps_existing_file(void **state)
{
    static const char *names[] = {"kept.ppm", "kept.png", "kept.exr"};
    static const char old[] = "an earlier image that must survive";
    glint_image img = noise_image(64, 64);

    for (int i = 0; i < 3; i++) {
        char path[PATH_SIZE], want[2 * PATH_SIZE];
        glint_error err = {0};
        tmp_path(path, names[i]);
        write_bytes(path, old, sizeof old);
        snprintf(want, sizeof want, "cannot write '%s': File too large", path);

        struct rlimit saved, small;
        assert_int_equal(getrlimit(RLIMIT_FSIZE, &saved), 0);
        small = saved;
        small.rlim_cur = 1000;
        void (*saved_handler)(int) = signal(SIGXFSZ, SIG_IGN);
        assert_int_equal(setrlimit(RLIMIT_FSIZE, &small), 0);
        glint_status st = glint_image_write(&img, path, &err);
        assert_int_equal(setrlimit(RLIMIT_FSIZE, &saved), 0);
        signal(SIGXFSZ, saved_handler);

        expect_error(st, &err, GLINT_ERR_IO, want);
        size_t size;
        unsigned char *bytes = read_bytes(path, &size);
        assert_non_null(bytes);
        assert_int_equal(size, sizeof old);
        assert_memory_equal(bytes, old, sizeof old);
        free(bytes);
        assert_int_equal(count_entries(tmp_dir, ".tmp-"), 0);
    }
    glint_image_free(&img);
}

static void test_write_over_directory(void **state)
{
    char path[PATH_SIZE], want[2 * PATH_SIZE];
    glint_error err = {0};
    glint_image img = sample_image();
    tmp_path(path, "a-directory.png");
    assert_int_equal(mkdir(path, 0755), 0);
    snprintf(want, sizeof want, "cannot write '%s': Is a directory", path);

    expect_error(glint_image_check_path(path, &err), &err, GLINT_ERR_IO, want);
    memset(&err, 0, sizeof err);
    expect_error(glint_image_write(&img, path, &err), &err, GLINT_ERR_IO, want);
    glint_image_free(&img);
    struct stat st;
    assert_int_equal(stat(path, &st), 0);
    assert_true(S_ISDIR(st.st_mode));
    assert_int_equal(count_entries(tmp_dir, ".tmp-"), 0);
}

static void test_check_path_parent_is_file(void **state)
{
    char file[PATH_SIZE], path[PATH_SIZE], want[2 * PATH_SIZE];
    glint_error err = {0};
    tmp_path(file, "plain-file");
    write_bytes(file, "x", 1);
    tmp_path(path, "plain-file/out.png");
    snprintf(want, sizeof want, "cannot write '%s': Not a directory", path);
    expect_error(glint_image_check_path(path, &err), &err, GLINT_ERR_IO, want);

    tmp_path(path, "fine.ppm");
    assert_int_equal(glint_image_check_path(path, &err), GLINT_OK);
    assert_int_equal(access(path, F_OK), -1); /* checking creates nothing */
}

static void test_unknown_extension(void **state)
{
    glint_error err = {0};
    glint_image img = sample_image();
    expect_error(glint_image_check_path("out.bmp", &err), &err, GLINT_ERR_INVALID,
                 "cannot write 'out.bmp': unknown image format (use .png, .ppm or .exr)");
    expect_error(glint_image_write(&img, "out.bmp", &err), &err, GLINT_ERR_INVALID,
                 "cannot write 'out.bmp': unknown image format (use .png, .ppm or .exr)");
    expect_error(glint_image_check_path("out", &err), &err, GLINT_ERR_INVALID,
                 "cannot write 'out': unknown image format (use .png, .ppm or .exr)");
    expect_error(glint_image_check_path("dir.png/out", &err), &err, GLINT_ERR_INVALID,
                 "cannot write 'dir.png/out': unknown image format (use .png, .ppm or .exr)");
    glint_image_free(&img);
    assert_int_equal(access("out.bmp", F_OK), -1);
}

/* Formats are found by the extension of the path's last component, in any
 * case, and listed in the registry's order, each found by its extensions. */
static void test_format_lookup(void **state)
{
    assert_string_equal(glint_image_format_for_path("out.png")->name, "PNG");
    assert_string_equal(glint_image_format_for_path("renders/OUT.PpM")->name, "PPM");
    assert_string_equal(glint_image_format_for_path("a.b.Exr")->name, "OpenEXR");
    assert_null(glint_image_format_for_path("out.bmp"));
    assert_null(glint_image_format_for_path("dir.png/out"));
    assert_null(glint_image_format_for_path("png"));
    assert_null(glint_image_format_for_path(NULL));
    assert_null(glint_image_format_at(-1));
    static const char *const names[] = {"PNG", "PPM", "OpenEXR"};
    int count = 0;
    for (const glint_image_format *f; (f = glint_image_format_at(count)) != NULL; count++) {
        assert_true(count < 3);
        assert_string_equal(f->name, names[count]);
        assert_non_null(f->meaning);
        assert_non_null(f->extensions[0]);
        for (const char *const *ext = f->extensions; *ext; ext++)
            assert_ptr_equal(glint_image_format_for_path(*ext), f);
    }
    assert_int_equal(count, 3);
}

/* A format is also found by a word: its name or an extension without the
 * dot, in any case (glint --format). */
static void test_format_named(void **state)
{
    assert_string_equal(glint_image_format_named("png")->name, "PNG");
    assert_string_equal(glint_image_format_named("PPM")->name, "PPM");
    assert_string_equal(glint_image_format_named("exr")->name, "OpenEXR");
    assert_string_equal(glint_image_format_named("openexr")->name, "OpenEXR");
    assert_null(glint_image_format_named(".png"));
    assert_null(glint_image_format_named("gif"));
    assert_null(glint_image_format_named(""));
    assert_null(glint_image_format_named(NULL));
}

/* Written to a pipe, which cannot seek, every format gives the bytes its
 * file has (OpenEXR's table of offsets included), and leaves the pipe open. */
static void test_write_fd_is_the_file(void **state)
{
    for (int i = 0; glint_image_format_at(i); i++) {
        const glint_image_format *f = glint_image_format_at(i);
        char name[32], path[PATH_SIZE];
        snprintf(name, sizeof name, "fd%s", f->extensions[0]);
        glint_image img = sample_image();
        glint_error err = {0};
        int fds[2];
        assert_int_equal(pipe(fds), 0);
        assert_int_equal(glint_image_write_fd(&img, fds[1], f, NULL, "<pipe>", &err), GLINT_OK);
        assert_int_equal(fcntl(fds[1], F_GETFD), 0);
        close(fds[1]);
        unsigned char piped[4096];
        size_t got = 0;
        for (ssize_t n; (n = read(fds[0], piped + got, sizeof piped - got)) > 0;)
            got += (size_t)n;
        close(fds[0]);
        size_t size;
        unsigned char *file = write_and_read(&img, name, path, &size);
        assert_int_equal(got, size);
        assert_memory_equal(piped, file, size);
        free(file);
    }
}

/* What a descriptor cannot take is said with the name given for it. */
static void test_write_fd_errors(void **state)
{
    glint_image img = sample_image();
    glint_error err = {0};
    const glint_image_format *png = glint_image_format_named("png");
    expect_error(glint_image_write_fd(&img, -1, png, NULL, "<stdout>", &err), &err, GLINT_ERR_IO,
                 "cannot write '<stdout>': Bad file descriptor");
    expect_error(glint_image_write_fd(&img, -1, png, NULL, NULL, &err), &err, GLINT_ERR_IO,
                 "cannot write '<output>': Bad file descriptor");
    glint_image_format copy = *png;
    expect_error(glint_image_write_fd(&img, 1, &copy, NULL, "<stdout>", &err), &err, GLINT_ERR_INVALID,
                 "cannot write '<stdout>': no such image format");
    expect_error(glint_image_write_fd(&img, 1, NULL, NULL, "<stdout>", &err), &err, GLINT_ERR_INVALID,
                 "cannot write '<stdout>': no such image format");
    glint_image_write_options bad = {.exr_pixel = (glint_exr_pixel)7};
    expect_error(glint_image_write_fd(&img, 1, png, &bad, "<stdout>", &err), &err, GLINT_ERR_INVALID,
                 "cannot write '<stdout>': unknown OpenEXR pixel type 7");
    glint_image empty = {0, 0, NULL};
    expect_error(glint_image_write_fd(&empty, 1, png, NULL, "<stdout>", &err), &err, GLINT_ERR_INVALID,
                 "cannot write '<stdout>': the image is empty");
    glint_image_free(&img);
}

static void test_write_empty_image(void **state)
{
    glint_error err = {0};
    glint_image empty = {0, 0, NULL};
    expect_error(glint_image_write(&empty, "empty.png", &err), &err, GLINT_ERR_INVALID,
                 "cannot write 'empty.png': the image is empty");
    assert_int_equal(access("empty.png", F_OK), -1);
}

/* Images libpng would refuse to read (over a million pixels wide or high)
 * are refused with the limit named, and nothing is left behind. */
static void test_write_png_too_large(void **state)
{
    static const int sizes[2][2] = {{1000001, 1}, {1, 1000001}};
    for (int k = 0; k < 2; k++) {
        char path[PATH_SIZE], want[2 * PATH_SIZE];
        glint_error err = {0};
        glint_image img = {sizes[k][0], sizes[k][1], calloc(3 * 1000001, sizeof(float))};
        assert_non_null(img.pixels);
        tmp_path(path, "large.png");
        snprintf(want, sizeof want,
                 "cannot write '%s': a PNG image is at most 1000000 pixels wide and high, got %dx%d", path,
                 sizes[k][0], sizes[k][1]);
        expect_error(glint_image_write(&img, path, &err), &err, GLINT_ERR_INVALID, want);
        glint_image_free(&img);
        assert_int_equal(access(path, F_OK), -1);
        assert_int_equal(count_entries(tmp_dir, ".tmp-"), 0);
    }
}

/* The chunk types of a PNG file in order, as one string ("IHDRsRGB..."),
 * each chunk's CRC checked on the way. */
static void chunk_types(const unsigned char *bytes, size_t size, char *types, size_t capacity)
{
    static const unsigned char signature[8] = {0x89, 'P', 'N', 'G', '\r', '\n', 0x1a, '\n'};
    assert_true(size >= 8);
    assert_memory_equal(bytes, signature, 8);
    size_t n = 0;
    for (size_t i = 8; i < size;) {
        assert_true(i + 12 <= size);
        uint32_t len = (uint32_t)bytes[i] << 24 | (uint32_t)bytes[i + 1] << 16 | (uint32_t)bytes[i + 2] << 8 |
                       bytes[i + 3];
        assert_true(i + 12 + len <= size);
        const unsigned char *c = bytes + i + 8 + len;
        uint32_t crc = (uint32_t)c[0] << 24 | (uint32_t)c[1] << 16 | (uint32_t)c[2] << 8 | c[3];
        assert_int_equal(crc, (uint32_t)crc32(0, bytes + i + 4, 4 + len));
        assert_true(n + 5 <= capacity);
        memcpy(types + n, bytes + i + 4, 4);
        n += 4;
        i += 12 + (size_t)len;
    }
    types[n] = '\0';
}

/* The file is the same bytes on any number of threads, and decodes to the
 * film's sRGB bytes: over shapes of image that cut into one slice, several,
 * and slices of a single row; a repeating ramp in the top half, of runs
 * and repeats, and noise below. */
static void test_png_encode_any_thread_count(void **state)
{
    static const int shapes[][2] = {{1, 1}, {3, 2}, {301, 900}, {640, 1000}, {12000, 5}, {100000, 3}};
    for (size_t k = 0; k < sizeof shapes / sizeof shapes[0]; k++) {
        int width = shapes[k][0], height = shapes[k][1];
        size_t n = 3 * (size_t)width * height;
        glint_image img = noise_image(width, height);
        for (int y = 0; y < (height + 1) / 2; y++)
            for (int x = 0; x < width; x++)
                for (int c = 0; c < 3; c++)
                    img.pixels[3 * ((size_t)y * width + x) + c] = (float)((x / 7 + c * y) % 50) / 50;
        unsigned char *want = malloc(n);
        assert_non_null(want);
        srgb_encode(want, img.pixels, n);
        unsigned char *first = NULL;
        size_t first_size = 0;
        for (int threads = 1; threads <= 5; threads += 2) {
            unsigned char *bytes;
            size_t size;
            assert_true(png_encode(&img, 8, threads, &bytes, &size));
            if (!first) {
                first = bytes;
                first_size = size;
                unsigned char *got = decode_png(bytes, size, width, height);
                assert_memory_equal(got, want, n);
                free(got);
                continue;
            }
            assert_int_equal(size, first_size);
            assert_memory_equal(bytes, first, size);
            free(bytes);
        }
        free(first);
        free(want);
        glint_image_free(&img);
    }
}

/* A file whose stream outgrows one IDAT chunk (1 MiB) spans several, each
 * with its own CRC, between IHDR and sRGB before and IEND after; the zlib
 * stream's own Adler-32 is checked by zlib, inflating it whole. */
static void test_png_encode_chunks(void **state)
{
    enum { width = 700, height = 600 };
    glint_image img = noise_image(width, height);
    unsigned char *bytes;
    size_t size;
    assert_true(png_encode(&img, 8, 2, &bytes, &size));
    char types[64];
    chunk_types(bytes, size, types, sizeof types);
    assert_string_equal(types, "IHDRsRGBIDATIDATIEND");
    assert_int_equal(bytes[8 + 8 + 13 + 4 + 8], 0); /* sRGB: perceptual */

    /* The IDAT data joined is one zlib stream that inflates to the
     * filtered rows: each a filter byte (None first, then Up) and 2100
     * bytes. */
    unsigned char *stream = malloc(size), *rows = malloc((size_t)height * (1 + 3 * width) + 1);
    assert_true(stream && rows);
    size_t stream_size = 0;
    for (size_t i = 8; i < size;) {
        uint32_t len = (uint32_t)bytes[i] << 24 | (uint32_t)bytes[i + 1] << 16 | (uint32_t)bytes[i + 2] << 8 |
                       bytes[i + 3];
        if (memcmp(bytes + i + 4, "IDAT", 4) == 0) {
            memcpy(stream + stream_size, bytes + i + 8, len);
            stream_size += len;
        }
        i += 12 + (size_t)len;
    }
    uLongf rows_size = (uLongf)height * (1 + 3 * width) + 1;
    assert_int_equal(uncompress(rows, &rows_size, stream, (uLong)stream_size), Z_OK);
    assert_int_equal(rows_size, (uLongf)height * (1 + 3 * width));
    for (int y = 0; y < height; y++)
        assert_int_equal(rows[(size_t)y * (1 + 3 * width)], y == 0 ? 0 : 2);
    free(rows);
    free(stream);
    free(bytes);
    glint_image_free(&img);
}

static void test_image_free(void **state)
{
    glint_image_free(NULL);
    glint_image img = sample_image();
    glint_image_free(&img);
    assert_null(img.pixels);
    assert_int_equal(img.width, 0);
    assert_int_equal(img.height, 0);
    glint_image_free(&img);
}

int main(void)
{
    const struct CMUnitTest tests[] = {
        cmocka_unit_test(test_srgb_known_values),
        cmocka_unit_test(test_srgb_byte_matches_formula),
        cmocka_unit_test(test_srgb_continuous_at_boundary),
        cmocka_unit_test(test_srgb_round_trips),
        cmocka_unit_test(test_write_ppm_bytes),
        cmocka_unit_test(test_write_16bit_ppm),
        cmocka_unit_test(test_write_16bit_png),
        cmocka_unit_test(test_write_bad_bit_depth),
        cmocka_unit_test(test_write_png_round_trip),
        cmocka_unit_test(test_write_png_decodes_to_srgb_bytes),
        cmocka_unit_test(test_write_extension_any_case),
        cmocka_unit_test(test_write_replaces_existing_file),
        cmocka_unit_test(test_write_missing_directory),
        cmocka_unit_test(test_write_read_only_directory),
        cmocka_unit_test(test_failed_write_keeps_existing_file),
        cmocka_unit_test(test_write_over_directory),
        cmocka_unit_test(test_check_path_parent_is_file),
        cmocka_unit_test(test_unknown_extension),
        cmocka_unit_test(test_format_lookup),
        cmocka_unit_test(test_format_named),
        cmocka_unit_test(test_write_fd_is_the_file),
        cmocka_unit_test(test_write_fd_errors),
        cmocka_unit_test(test_write_empty_image),
        cmocka_unit_test(test_write_png_too_large),
        cmocka_unit_test(test_png_encode_any_thread_count),
        cmocka_unit_test(test_png_encode_chunks),
        cmocka_unit_test(test_image_free),
    };
    return cmocka_run_group_tests(tests, setup_dir, teardown_dir);
}
