/* test_image_io.c - the sRGB curve, the image format registry, PNG/PPM
 * writing with its atomic replace, and PNG/JPEG texture decoding, including
 * every refusal message. */
#include <stdarg.h>
#include <stddef.h>
#include <setjmp.h>
#include <stdint.h>
#include <cmocka.h>

#include <dirent.h>
#include <errno.h>
#include <fcntl.h>
#include <math.h>
#include <signal.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>
#include <sys/resource.h>
#include <sys/stat.h>
#include <unistd.h>
#include <jpeglib.h>
#include <png.h>
#include <zlib.h>

#include "glint.h"
#include "tmp_tree.h"
#include "image/png_encode.h"
#include "image/srgb.h"
#include "image/texture_image.h"
#include "scene/scene.h"

#define PATH_SIZE 1024

static char tmp_dir[PATH_SIZE];

/* ------------------------------------------------------------- helpers */

static void tmp_path(char *buf, const char *name)
{
    int n = snprintf(buf, PATH_SIZE, "%s/%s", tmp_dir, name);
    assert_true(n > 0 && n < PATH_SIZE);
}

static void write_bytes(const char *path, const void *data, size_t size)
{
    FILE *f = fopen(path, "wb");
    assert_non_null(f);
    assert_int_equal(fwrite(data, 1, size, f), size);
    assert_int_equal(fclose(f), 0);
}

/* Returns the whole file (free it), or NULL when it cannot be opened. */
static unsigned char *read_bytes(const char *path, size_t *size)
{
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

static void expect_error(glint_status got, const glint_error *err, glint_status want,
                         const char *message)
{
    assert_int_equal(got, want);
    assert_string_equal(err->message, message);
}

/* cmocka 1.1.5, Debian 12's, has no assert_double_equal. */
#define assert_near(a, b, tolerance) near_or_fail((a), (b), (tolerance), #a, __FILE__, __LINE__)

static void near_or_fail(double a, double b, double tolerance, const char *expr, const char *file,
                         int line)
{
    if (!(fabs(a - b) <= tolerance))
        fail_msg("%s:%d: %s = %.17g, expected %.17g within %g", file, line, expr, a, b, tolerance);
}

static void expect_prefix(const char *message, const char *prefix)
{
    if (strncmp(message, prefix, strlen(prefix)) != 0 || strlen(message) == strlen(prefix))
        fail_msg("message '%s' does not continue '%s'", message, prefix);
}

static uint32_t noise(uint32_t *state)
{
    *state = *state * 1664525u + 1013904223u;
    return *state >> 24;
}

static glint_image noise_image(int width, int height)
{
    glint_image img = {width, height, malloc(sizeof(float) * 3 * (size_t)width * height)};
    assert_non_null(img.pixels);
    uint32_t state = 42;
    for (int i = 0; i < 3 * width * height; i++)
        img.pixels[i] = (float)noise(&state) / 255.0f;
    return img;
}

/* Encodes pixels (components per pixel in colour space cs) as a JPEG with
 * libjpeg's memory destination; free the result with free(). */
static unsigned char *encode_jpeg(int width, int height, int components, J_COLOR_SPACE cs,
                                  const unsigned char *pixels, unsigned long *size)
{
    struct jpeg_compress_struct c;
    struct jpeg_error_mgr jerr;
    unsigned char *out = NULL;
    *size = 0;
    c.err = jpeg_std_error(&jerr);
    jpeg_create_compress(&c);
    jpeg_mem_dest(&c, &out, size);
    c.image_width = (JDIMENSION)width;
    c.image_height = (JDIMENSION)height;
    c.input_components = components;
    c.in_color_space = cs;
    jpeg_set_defaults(&c);
    jpeg_set_quality(&c, 95, TRUE);
    jpeg_start_compress(&c, TRUE);
    while (c.next_scanline < c.image_height) {
        JSAMPROW row = (JSAMPROW)(pixels + (size_t)c.next_scanline * width * components);
        jpeg_write_scanlines(&c, &row, 1);
    }
    jpeg_finish_compress(&c);
    jpeg_destroy_compress(&c);
    assert_non_null(out);
    return out;
}

static unsigned char *uniform_pixels(int count, int components, const unsigned char *value)
{
    unsigned char *p = malloc((size_t)count * components);
    assert_non_null(p);
    for (int i = 0; i < count; i++)
        memcpy(p + (size_t)i * components, value, (size_t)components);
    return p;
}

/* Writes an 8-bit PNG of the given simplified-API format with libpng. */
static void write_png8(const char *path, int width, int height, uint32_t format,
                       const void *pixels, const void *colormap, int colormap_entries)
{
    png_image png;
    memset(&png, 0, sizeof png);
    png.version = PNG_IMAGE_VERSION;
    png.width = (png_uint_32)width;
    png.height = (png_uint_32)height;
    png.format = format;
    png.colormap_entries = (png_uint_32)colormap_entries;
    if (!png_image_write_to_file(&png, path, 0, pixels, 0, colormap))
        fail_msg("libpng could not write %s: %s", path, png.message);
}

/* Writes a 16-bit RGB PNG with no gamma chunk, as most tools save them. */
static void write_png16(const char *path, int width, int height, const uint16_t *rgb)
{
    FILE *f = fopen(path, "wb");
    assert_non_null(f);
    png_structp png = png_create_write_struct(PNG_LIBPNG_VER_STRING, NULL, NULL, NULL);
    assert_non_null(png);
    png_infop info = png_create_info_struct(png);
    assert_non_null(info);
    if (setjmp(png_jmpbuf(png)))
        fail_msg("libpng could not write %s", path);
    png_init_io(png, f);
    png_set_IHDR(png, info, (png_uint_32)width, (png_uint_32)height, 16, PNG_COLOR_TYPE_RGB,
                 PNG_INTERLACE_NONE, PNG_COMPRESSION_TYPE_DEFAULT, PNG_FILTER_TYPE_DEFAULT);
    png_write_info(png, info);
    unsigned char row[6 * 16];
    assert_true(width <= 16);
    for (int y = 0; y < height; y++) {
        for (int i = 0; i < 3 * width; i++) {
            uint16_t v = rgb[3 * width * y + i];
            row[2 * i] = (unsigned char)(v >> 8);
            row[2 * i + 1] = (unsigned char)(v & 0xff);
        }
        png_write_row(png, row);
    }
    png_write_end(png, NULL);
    png_destroy_write_struct(&png, &info);
    assert_int_equal(fclose(f), 0);
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

static void put_be32(unsigned char *p, uint32_t v)
{
    p[0] = (unsigned char)(v >> 24);
    p[1] = (unsigned char)(v >> 16);
    p[2] = (unsigned char)(v >> 8);
    p[3] = (unsigned char)v;
}

/* Appends a PNG chunk with its CRC at p; returns the bytes written. */
static size_t put_chunk(unsigned char *p, const char *type, const unsigned char *data, uint32_t len)
{
    put_be32(p, len);
    memcpy(p + 4, type, 4);
    if (len > 0)
        memcpy(p + 8, data, len);
    put_be32(p + 8 + len, (uint32_t)crc32(0, p + 4, 4 + len));
    return 12 + len;
}

/* A PNG whose header claims width x height, with an empty IDAT: enough for
 * a decoder to read the size, and nothing to decode. */
static size_t forge_png(unsigned char *buf, uint32_t width, uint32_t height)
{
    static const unsigned char sig[8] = {0x89, 'P', 'N', 'G', '\r', '\n', 0x1a, '\n'};
    unsigned char ihdr[13] = {0};
    put_be32(ihdr, width);
    put_be32(ihdr + 4, height);
    ihdr[8] = 8; /* bit depth */
    ihdr[9] = 2; /* RGB */
    memcpy(buf, sig, 8);
    size_t n = 8;
    n += put_chunk(buf + n, "IHDR", ihdr, 13);
    n += put_chunk(buf + n, "IDAT", NULL, 0);
    n += put_chunk(buf + n, "IEND", NULL, 0);
    return n;
}

/* ------------------------------------------------------------ fixtures */

static int setup_dir(void **state)
{
    return make_tmp_tree(tmp_dir, sizeof tmp_dir, "glint-image-io");
}

static int teardown_dir(void **state)
{
    remove_tree(tmp_dir);
    return 0;
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

/* 3x2 linear pixels and the 8-bit sRGB bytes they must become. */
static const float sample_linear[18] = {
    0.0f, 1.0f, 0.5f,    0.214f, NAN, -1.0f,    2.0f, 0.001f, 0.0031308f,
    0.18f, 0.75f, 0.05f, 1e-5f, 0.9f, 0.3f,     0.01f, 0.6f, 0.02f,
};
static const unsigned char sample_srgb[18] = {
    0, 255, 188,  127, 0, 0,    255, 3, 10,
    118, 225, 63, 0, 243, 149,  25, 203, 39,
};

static glint_image sample_image(void)
{
    glint_image img = {3, 2, malloc(sizeof sample_linear)};
    assert_non_null(img.pixels);
    memcpy(img.pixels, sample_linear, sizeof sample_linear);
    return img;
}

/* Writes img (then frees it) to tmp_dir/name, which path receives, and
 * returns the file's bytes and *size: the caller frees them. */
static unsigned char *write_and_read(glint_image *img, const char *name, char *path, size_t *size)
{
    glint_error err = {0};
    tmp_path(path, name);
    assert_int_equal(glint_image_write(img, path, &err), GLINT_OK);
    glint_image_free(img);
    unsigned char *bytes = read_bytes(path, size);
    assert_non_null(bytes);
    return bytes;
}

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
 * and slices of a single row wider than the 32 KiB window; a repeating ramp
 * in the top half, where matches reach back into the slice before, and
 * noise below. */
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

/* ---------------------------------------------------- texture decoding */

static void test_load_missing_file(void **state)
{
    char path[PATH_SIZE], want[2 * PATH_SIZE];
    glint_error err = {0};
    texture_image tex = {.width = 1, .height = 1};
    tmp_path(path, "missing.png");
    snprintf(want, sizeof want, "cannot open texture '%s': No such file or directory", path);
    expect_error(texture_image_load_file(&tex, path, &err), &err, GLINT_ERR_IO, want);
    assert_null(tex.srgb);
    assert_int_equal(tex.width, 0);
}

static void test_load_directory(void **state)
{
    char want[2 * PATH_SIZE];
    glint_error err = {0};
    texture_image tex;
    snprintf(want, sizeof want, "cannot read texture '%s': Is a directory", tmp_dir);
    expect_error(texture_image_load_file(&tex, tmp_dir, &err), &err, GLINT_ERR_IO, want);
}

static void test_load_text_file(void **state)
{
    char path[PATH_SIZE], want[2 * PATH_SIZE];
    glint_error err = {0};
    texture_image tex;
    tmp_path(path, "notes.png");
    write_bytes(path, "just some text\n", 15);
    snprintf(want, sizeof want, "texture '%s' is not a PNG, JPEG or OpenEXR file", path);
    expect_error(texture_image_load_file(&tex, path, &err), &err, GLINT_ERR_INVALID, want);

    tmp_path(path, "empty.jpg");
    write_bytes(path, "", 0);
    snprintf(want, sizeof want, "texture '%s' is not a PNG, JPEG or OpenEXR file", path);
    expect_error(texture_image_load_file(&tex, path, &err), &err, GLINT_ERR_INVALID, want);

    expect_error(texture_image_load_memory(&tex, "GIF89a", 6, NULL, &err), &err,
                 GLINT_ERR_INVALID, "texture '(memory)' is not a PNG, JPEG or OpenEXR file");
}

static void test_load_truncated_png(void **state)
{
    char path[PATH_SIZE], cut[PATH_SIZE], want[2 * PATH_SIZE];
    glint_error err = {0};
    glint_image img = noise_image(16, 16);
    size_t size;
    unsigned char *bytes = write_and_read(&img, "whole.png", path, &size);
    tmp_path(cut, "truncated.png");
    write_bytes(cut, bytes, size / 2);
    free(bytes);

    texture_image tex;
    snprintf(want, sizeof want, "texture '%s' is corrupt: ", cut);
    assert_int_equal(texture_image_load_file(&tex, cut, &err), GLINT_ERR_INVALID);
    expect_prefix(err.message, want);
    assert_null(tex.srgb);
}

static void test_load_png_bad_crc(void **state)
{
    unsigned char buf[64];
    glint_error err = {0};
    texture_image tex;
    size_t n = forge_png(buf, 4, 4);
    buf[29] ^= 0xff; /* IHDR's CRC */
    assert_int_equal(texture_image_load_memory(&tex, buf, n, "crc.png", &err), GLINT_ERR_INVALID);
    expect_prefix(err.message, "texture 'crc.png' is corrupt: ");
}

static void test_load_oversized_png(void **state)
{
    unsigned char buf[64];
    glint_error err = {0};
    texture_image tex;
    /* Under ASan an attempt to allocate 120 GB would abort the test. */
    size_t n = forge_png(buf, 100000, 100000);
    expect_error(texture_image_load_memory(&tex, buf, n, "huge.png", &err), &err,
                 GLINT_ERR_INVALID,
                 "texture 'huge.png' is too large: 100000x100000 (limit 32768 a side, 268435456 pixels)");
    assert_null(tex.srgb);
    n = forge_png(buf, 16385, 16385);
    expect_error(texture_image_load_memory(&tex, buf, n, "many.png", &err), &err,
                 GLINT_ERR_INVALID,
                 "texture 'many.png' is too large: 16385x16385 (limit 32768 a side, 268435456 pixels)");
    n = forge_png(buf, 32769, 1);
    expect_error(texture_image_load_memory(&tex, buf, n, "wide.png", &err), &err,
                 GLINT_ERR_INVALID,
                 "texture 'wide.png' is too large: 32769x1 (limit 32768 a side, 268435456 pixels)");
}

/* Found by fuzz_texture (tests/fuzz/regressions/texture/): before the image
 * data, libpng allocated and zeroed the 2 GB a text chunk claimed, then
 * found the file ended. After the image data it reads nothing, so there
 * such a chunk is still no error. */
static void test_load_png_chunk_past_end(void **state)
{
    unsigned char buf[128], pixel[4] = {0, 200, 100, 50}, idat[64];
    glint_error err = {0};
    texture_image tex;
    forge_png(buf, 1, 1);
    size_t n = 33; /* the signature and IHDR */
    put_be32(buf + n, 0x7fffff00);
    memcpy(buf + n + 4, "tEXt", 4);
    memcpy(buf + n + 8, "Title\0x", 7);
    expect_error(texture_image_load_memory(&tex, buf, n + 15, "text.png", &err), &err, GLINT_ERR_INVALID,
                 "texture 'text.png' is corrupt: its tEXt chunk claims 2147483392 bytes, but only 7 follow");
    assert_null(tex.srgb);

    uLongf idat_len = sizeof idat;
    assert_int_equal(compress(idat, &idat_len, pixel, sizeof pixel), Z_OK);
    n += put_chunk(buf + n, "IDAT", idat, (uint32_t)idat_len);
    put_be32(buf + n, 0x7fffff00);
    memcpy(buf + n + 4, "tEXt", 4);
    assert_int_equal(texture_image_load_memory(&tex, buf, n + 8, "after.png", &err), GLINT_OK);
    assert_int_equal(tex.width, 1);
    assert_int_equal(tex.srgb[0], 200);
    texture_image_free(&tex);
}

/* OpenEXR: a header that is not one, and (found by fuzz_texture,
 * tests/fuzz/regressions/texture/) a chunk the file places outside its
 * data window, which would have been decoded outside the pixels, are
 * refused as corrupt, the image left empty. */
static void test_load_exr_corrupt(void **state)
{
    (void)state;
    glint_error err = {0};
    texture_image tex;
    static const unsigned char junk[] = {0x76, 0x2f, 0x31, 0x01, 'j', 'u', 'n', 'k'};
    expect_error(texture_image_load_memory(&tex, junk, sizeof junk, "junk.exr", &err), &err, GLINT_ERR_INVALID,
                 "texture 'junk.exr' is corrupt: File is not an OpenEXR file or has a bad header value");
    assert_null(tex.hdr);
    const char *src = getenv("GLINT_SOURCE_DIR");
    char path[4096];
    snprintf(path, sizeof path, "%s/tests/fuzz/regressions/texture/exr-chunk-outside-window.exr", src ? src : ".");
    glint_status st = texture_image_load_file(&tex, path, &err);
    assert_int_equal(st, GLINT_ERR_INVALID);
    assert_non_null(strstr(err.message, "is corrupt: Corrupt data block data, unable to decode"));
    assert_null(tex.hdr);
    assert_null(tex.owned);
}

/* Appends an OpenEXR attribute (name, type, size, value) at p. */
static size_t put_exr_attribute(unsigned char *p, const char *name, const char *type, const void *value,
                                uint32_t size)
{
    size_t n = strlen(name) + 1, t = strlen(type) + 1;
    memcpy(p, name, n);
    memcpy(p + n, type, t);
    memcpy(p + n + t, &size, 4); /* OpenEXR is little-endian, as the machines glint runs on */
    memcpy(p + n + t + 4, value, size);
    return n + t + 4 + size;
}

/* Writes at file the header of a one-part scanline OpenEXR image without
 * compression, of half channels named by the count names, and a data
 * window of width x height pixels; returns its size. */
static size_t forge_exr_header(unsigned char *file, const char *const *names, int count, int32_t width,
                               int32_t height)
{
    static const unsigned char magic[8] = {0x76, 0x2f, 0x31, 0x01, 2, 0, 0, 0};
    memcpy(file, magic, sizeof magic);
    size_t n = sizeof magic;
    unsigned char channels[128];
    size_t c = 0;
    for (int i = 0; i < count; i++) {
        const int32_t half = 1, sampling = 1;
        memcpy(channels + c, names[i], strlen(names[i]) + 1);
        c += strlen(names[i]) + 1;
        memcpy(channels + c, &half, 4);
        memset(channels + c + 4, 0, 4); /* pLinear and reserved */
        memcpy(channels + c + 8, &sampling, 4);
        memcpy(channels + c + 12, &sampling, 4);
        c += 16;
    }
    channels[c++] = 0;
    const unsigned char none = 0;
    const int32_t window[4] = {0, 0, width - 1, height - 1};
    const float one = 1, centre[2] = {0, 0};
    n += put_exr_attribute(file + n, "channels", "chlist", channels, (uint32_t)c);
    n += put_exr_attribute(file + n, "compression", "compression", &none, 1);
    n += put_exr_attribute(file + n, "dataWindow", "box2i", window, sizeof window);
    n += put_exr_attribute(file + n, "displayWindow", "box2i", window, sizeof window);
    n += put_exr_attribute(file + n, "lineOrder", "lineOrder", &none, 1);
    n += put_exr_attribute(file + n, "pixelAspectRatio", "float", &one, 4);
    n += put_exr_attribute(file + n, "screenWindowCenter", "v2f", centre, sizeof centre);
    n += put_exr_attribute(file + n, "screenWindowWidth", "float", &one, 4);
    file[n++] = 0;
    return n;
}

/* A luminance-chroma OpenEXR image (half channels BY, RY, Y, as OpenEXR's
 * own RgbaYca files have) is read as grey from Y. Only one of its three
 * channels is read, which OpenEXR 3.1 took for three interleaved ones and
 * decoded through the skipped channels' NULL pointers (a crash found by
 * fuzz_texture); the skipped channels now have a plane of their own. */
static void test_load_exr_luminance_chroma(void **state)
{
    (void)state;
    unsigned char file[512];
    static const char *const names[] = {"BY", "RY", "Y"};
    size_t n = forge_exr_header(file, names, 3, 2, 1);
    const uint64_t chunk_offset = n + 8;
    memcpy(file + n, &chunk_offset, 8);
    n += 8;
    /* The one scanline: y, byte count, then BY, RY and Y for both pixels;
     * Y is 0.5 and 2 as halves. */
    const int32_t row[2] = {0, 12};
    const uint16_t halves[6] = {0x3c00, 0x3c00, 0x3c00, 0x3c00, 0x3800, 0x4000};
    memcpy(file + n, row, sizeof row);
    memcpy(file + n + sizeof row, halves, sizeof halves);
    n += sizeof row + sizeof halves;

    glint_error err = {0};
    texture_image tex;
    assert_int_equal(texture_image_load_memory(&tex, file, n, "yca.exr", &err), GLINT_OK);
    assert_int_equal(tex.width, 2);
    assert_int_equal(tex.height, 1);
    const float grey[6] = {0.5f, 0.5f, 0.5f, 2, 2, 2};
    for (int i = 0; i < 6; i++)
        assert_true(tex.hdr[i] == grey[i]);
    texture_image_free(&tex);
}

/* An OpenEXR image is decoded to 12 bytes a pixel, so its limit is 1.5 GiB
 * of them, 134217728 pixels (16384 x 8192), not PNG's 268435456: a header
 * that claimed more had the fuzzer (under its 2 GiB allocation limit)
 * allocate 2.8 GB before the file was found to end. At the limit, the
 * image is allocated, and the missing scanlines make it corrupt. */
static void test_load_exr_too_large(void **state)
{
    (void)state;
    unsigned char file[512];
    static const char *const names[] = {"B", "G", "R"};
    glint_error err = {0};
    texture_image tex;
    size_t n = forge_exr_header(file, names, 3, 16384, 8193);
    expect_error(texture_image_load_memory(&tex, file, n, "big.exr", &err), &err, GLINT_ERR_INVALID,
                 "texture 'big.exr' is too large: 16384x8193 (limit 32768 a side, 134217728 pixels)");
    assert_null(tex.hdr);
    n = forge_exr_header(file, names, 3, 16384, 8192);
    glint_status st = texture_image_load_memory(&tex, file, n, "short.exr", &err);
    assert_int_equal(st, GLINT_ERR_INVALID);
    assert_non_null(strstr(err.message, "texture 'short.exr' is corrupt: "));
    assert_null(tex.hdr);
    assert_null(tex.owned);
}

/* A material using a texture decodes its file (one no material uses is
 * never decoded); textures naming one file, by its name or through a link,
 * share one decoding, which outlives the texture that made it; another
 * file is decoded on its own. */
static int use_texture(glint_scene *scene, int index)
{
    glint_material m = glint_material_default();
    m.texture = index;
    glint_error err;
    return glint_scene_add_material(scene, NULL, &m, &err);
}

static void test_textures_share_decoded_file(void **state)
{
    static const unsigned char grey[4] = {0, 64, 128, 255};
    char path[PATH_SIZE], link_path[PATH_SIZE], other[PATH_SIZE];
    glint_error err = {0};
    tmp_path(path, "shared.png");
    tmp_path(link_path, "shared-link.png");
    tmp_path(other, "other.png");
    write_png8(path, 2, 2, PNG_FORMAT_GRAY, grey, NULL, 0);
    write_png8(other, 2, 2, PNG_FORMAT_GRAY, grey, NULL, 0);
    unlink(link_path);
    assert_int_equal(symlink(path, link_path), 0);
    glint_scene *scene = glint_scene_new();
    glint_mapping uv = {.kind = GLINT_MAP_UV};
    int a = glint_scene_add_image_file(scene, "a", path, uv, &err);
    int b = glint_scene_add_image_file(scene, "b", link_path, uv, &err);
    int c = glint_scene_add_image_file(scene, "c", other, uv, &err);
    assert_true(a >= 0 && b >= 0 && c >= 0);
    assert_int_equal(scene->image_files.count, 0);
    assert_true(use_texture(scene, a) >= 0 && use_texture(scene, b) >= 0 && use_texture(scene, c) >= 0);
    assert_ptr_equal(scene->textures[a].image.srgb, scene->textures[b].image.srgb);
    assert_ptr_not_equal(scene->textures[a].image.srgb, scene->textures[c].image.srgb);
    assert_int_equal(scene->image_files.count, 2);
    assert_int_equal(scene->image_bytes, 2 * 3 * 4);
    assert_true(texture_image_at(&scene->textures[b].image, 3) == (float)glint_srgb_to_linear(64 / 255.0));
    glint_scene_free(scene);
}

/* A file whose pixels would take the scene's decoded images past 4 GiB is
 * refused when a material first uses it, the scene's count unchanged; one
 * that fits exactly is taken. */
static void test_textures_within_budget(void **state)
{
    static const unsigned char grey[4] = {0, 64, 128, 255};
    char path[PATH_SIZE], other[PATH_SIZE], want[PATH_SIZE + 200];
    glint_error err = {0};
    tmp_path(path, "budget.png");
    tmp_path(other, "budget-2.png");
    write_png8(path, 2, 2, PNG_FORMAT_GRAY, grey, NULL, 0);
    write_png8(other, 2, 2, PNG_FORMAT_GRAY, grey, NULL, 0);
    glint_scene *scene = glint_scene_new();
    glint_mapping uv = {.kind = GLINT_MAP_UV};
    scene->image_bytes = SCENE_MAX_IMAGE_BYTES - 11; /* as if other images had taken the rest */
    snprintf(want, sizeof want,
             "texture '%s' is too much: its 12 bytes of pixels would take the scene's textures past the limit of "
             "4294967296 bytes (4 GiB)",
             path);
    int a = glint_scene_add_image_file(scene, "a", path, uv, &err);
    glint_material m = glint_material_default();
    m.texture = a;
    assert_true(a >= 0);
    assert_int_equal(glint_scene_add_material(scene, "uses a", &m, &err), -1);
    assert_int_equal(err.status, GLINT_ERR_INVALID);
    assert_string_equal(err.message, want);
    assert_int_equal(scene->image_bytes, SCENE_MAX_IMAGE_BYTES - 11);
    assert_int_equal(glint_scene_get_counts(scene).materials, 0);
    scene->image_bytes = SCENE_MAX_IMAGE_BYTES - 12;
    assert_true(use_texture(scene, glint_scene_add_image_file(scene, "b", other, uv, &err)) >= 0);
    assert_true(scene->image_bytes == SCENE_MAX_IMAGE_BYTES);
    glint_scene_free(scene);
}

static void test_load_grey_png(void **state)
{
    static const unsigned char grey[4] = {0, 64, 128, 255};
    char path[PATH_SIZE];
    glint_error err = {0};
    texture_image tex;
    tmp_path(path, "grey.png");
    write_png8(path, 2, 2, PNG_FORMAT_GRAY, grey, NULL, 0);
    assert_int_equal(texture_image_load_file(&tex, path, &err), GLINT_OK);
    assert_int_equal(tex.width, 2);
    assert_int_equal(tex.height, 2);
    for (int i = 0; i < 4; i++)
        for (int c = 0; c < 3; c++)
            assert_true(texture_image_at(&tex, 3 * i + c) == (float)glint_srgb_to_linear(grey[i] / 255.0));
    texture_image_free(&tex);
}

static void test_load_palette_and_alpha_png(void **state)
{
    static const unsigned char colormap[4 * 3] = {255, 0, 0, 0, 255, 0, 0, 0, 255, 10, 20, 30};
    static const unsigned char indices[4] = {3, 2, 1, 0};
    /* the colour under a fully transparent pixel is kept, not darkened */
    static const unsigned char rgba[2 * 4] = {200, 100, 50, 0, 1, 2, 3, 255};
    char path[PATH_SIZE];
    glint_error err = {0};
    texture_image tex;

    tmp_path(path, "palette.png");
    write_png8(path, 2, 2, PNG_FORMAT_RGB_COLORMAP, indices, colormap, 4);
    assert_int_equal(texture_image_load_file(&tex, path, &err), GLINT_OK);
    for (int i = 0; i < 4; i++)
        for (int c = 0; c < 3; c++)
            assert_true(texture_image_at(&tex, 3 * i + c)
                        == (float)glint_srgb_to_linear(colormap[3 * indices[i] + c] / 255.0));
    texture_image_free(&tex);

    tmp_path(path, "alpha.png");
    write_png8(path, 2, 1, PNG_FORMAT_RGBA, rgba, NULL, 0);
    assert_int_equal(texture_image_load_file(&tex, path, &err), GLINT_OK);
    for (int i = 0; i < 2; i++)
        for (int c = 0; c < 3; c++)
            assert_true(texture_image_at(&tex, 3 * i + c) == (float)glint_srgb_to_linear(rgba[4 * i + c] / 255.0));
    texture_image_free(&tex);
}

static void test_load_16bit_png(void **state)
{
    static const uint16_t rgb[2 * 2 * 3] = {
        0x0000, 0x8080, 0xffff,  0x1234, 0x4321, 0xabcd,
        0x0101, 0xfefe, 0x7fff,  0x0000, 0xffff, 0x3333,
    };
    char path[PATH_SIZE];
    glint_error err = {0};
    texture_image tex;
    tmp_path(path, "deep.png");
    write_png16(path, 2, 2, rgb);
    assert_int_equal(texture_image_load_file(&tex, path, &err), GLINT_OK);
    assert_int_equal(tex.width, 2);
    assert_int_equal(tex.height, 2);
    for (int i = 0; i < 12; i++)
        /* read as sRGB like an 8-bit file, to the nearest 8-bit step */
        assert_near(glint_linear_to_srgb(texture_image_at(&tex, i)), rgb[i] / 65535.0, 0.5 / 255 + 1e-6);
    assert_true(texture_image_at(&tex, 1) == (float)glint_srgb_to_linear(128 / 255.0));
    texture_image_free(&tex);
}

static void test_load_jpeg_memory(void **state)
{
    static const unsigned char colour[3] = {200, 100, 50};
    static const unsigned char grey[1] = {128};
    glint_error err = {0};
    texture_image tex;
    unsigned long size;

    unsigned char *pixels = uniform_pixels(24 * 16, 3, colour);
    unsigned char *jpeg = encode_jpeg(24, 16, 3, JCS_RGB, pixels, &size);
    free(pixels);
    assert_int_equal(texture_image_load_memory(&tex, jpeg, size, "colour.jpg", &err), GLINT_OK);
    free(jpeg);
    assert_int_equal(tex.width, 24);
    assert_int_equal(tex.height, 16);
    for (int i = 0; i < 24 * 16; i++)
        for (int c = 0; c < 3; c++)
            assert_near(glint_linear_to_srgb(texture_image_at(&tex, 3 * i + c)), colour[c] / 255.0, 3.0 / 255);
    texture_image_free(&tex);

    pixels = uniform_pixels(8 * 8, 1, grey);
    jpeg = encode_jpeg(8, 8, 1, JCS_GRAYSCALE, pixels, &size);
    free(pixels);
    assert_int_equal(texture_image_load_memory(&tex, jpeg, size, "grey.jpg", &err), GLINT_OK);
    free(jpeg);
    for (int i = 0; i < 8 * 8; i++) {
        assert_true(texture_image_at(&tex, 3 * i) == texture_image_at(&tex, 3 * i + 1) && texture_image_at(&tex, 3 * i) == texture_image_at(&tex, 3 * i + 2));
        assert_near(glint_linear_to_srgb(texture_image_at(&tex, 3 * i)), 128 / 255.0, 1.0 / 255);
    }
    texture_image_free(&tex);
}

static void test_load_truncated_jpeg(void **state)
{
    char path[PATH_SIZE], want[2 * PATH_SIZE];
    glint_error err = {0};
    texture_image tex;
    unsigned long size;
    unsigned char *pixels = malloc(64 * 64 * 3);
    assert_non_null(pixels);
    uint32_t rng = 7;
    for (int i = 0; i < 64 * 64 * 3; i++)
        pixels[i] = (unsigned char)noise(&rng);
    unsigned char *jpeg = encode_jpeg(64, 64, 3, JCS_RGB, pixels, &size);
    free(pixels);

    tmp_path(path, "whole.jpg");
    write_bytes(path, jpeg, size);
    assert_int_equal(texture_image_load_file(&tex, path, &err), GLINT_OK);
    texture_image_free(&tex);

    tmp_path(path, "truncated.jpg");
    write_bytes(path, jpeg, size * 3 / 4);
    free(jpeg);
    snprintf(want, sizeof want, "texture '%s' is corrupt: Premature end of JPEG file", path);
    expect_error(texture_image_load_file(&tex, path, &err), &err, GLINT_ERR_INVALID, want);
    assert_null(tex.srgb);

    /* cut inside the header, so libjpeg's error (not a warning) fires */
    expect_error(texture_image_load_memory(&tex, "\xff\xd8\xff\xe0\x00\x10JF", 8, "head.jpg", &err),
                 &err, GLINT_ERR_INVALID, "texture 'head.jpg' is corrupt: Premature end of JPEG file");
}

static void test_load_refused_jpegs(void **state)
{
    static const unsigned char cmyk[4] = {0, 0, 0, 0};
    static const unsigned char black[1] = {0};
    glint_error err = {0};
    texture_image tex;
    unsigned long size;

    unsigned char *pixels = uniform_pixels(8 * 8, 4, cmyk);
    unsigned char *jpeg = encode_jpeg(8, 8, 4, JCS_CMYK, pixels, &size);
    free(pixels);
    expect_error(texture_image_load_memory(&tex, jpeg, size, "print.jpg", &err), &err,
                 GLINT_ERR_INVALID,
                 "texture 'print.jpg' is a CMYK JPEG, which is not supported (save it as RGB)");
    free(jpeg);

    pixels = uniform_pixels(40000, 1, black);
    jpeg = encode_jpeg(40000, 1, 1, JCS_GRAYSCALE, pixels, &size);
    free(pixels);
    expect_error(texture_image_load_memory(&tex, jpeg, size, "wide.jpg", &err), &err,
                 GLINT_ERR_INVALID,
                 "texture 'wide.jpg' is too large: 40000x1 (limit 32768 a side, 268435456 pixels)");
    free(jpeg);
    assert_null(tex.srgb);
}

static void test_load_moon(void **state)
{
    const char *data = getenv("GLINT_SHARED_DATA");
    char path[PATH_SIZE];
    if (!data)
        skip();
    snprintf(path, sizeof path, "%s/moon.jpg", data);
    if (access(path, R_OK) != 0)
        skip();
    glint_error err = {0};
    texture_image tex;
    assert_int_equal(texture_image_load_file(&tex, path, &err), GLINT_OK);
    assert_int_equal(tex.width, 1024);
    assert_int_equal(tex.height, 512);
    double mean[3] = {0, 0, 0};
    for (size_t i = 0; i < (size_t)1024 * 512; i++)
        for (int c = 0; c < 3; c++)
            mean[c] += texture_image_at(&tex, 3 * i + c) / (1024.0 * 512.0);
    texture_image_free(&tex);
    /* a mid grey with the map's slight warm tint (means 0.33, 0.32, 0.30) */
    double grey = (mean[0] + mean[1] + mean[2]) / 3;
    assert_true(grey > 0.15 && grey < 0.5);
    for (int c = 0; c < 3; c++)
        assert_near(mean[c], grey, 0.05);
}

/* The seed room's Moon, decoded while glint was built (tools/embed_image),
 * is the same bytes as decoding assets/moon.jpg when glint runs. */
extern const int glint_asset_moon_width, glint_asset_moon_height;
extern const unsigned char glint_asset_moon_srgb[];

static void test_embedded_moon_is_the_decoded_file(void **state)
{
    const char *source = getenv("GLINT_SOURCE_DIR");
    if (!source)
        skip();
    char path[PATH_SIZE];
    snprintf(path, sizeof path, "%s/assets/moon.jpg", source);
    glint_error err = {0};
    texture_image tex;
    assert_int_equal(texture_image_load_file(&tex, path, &err), GLINT_OK);
    assert_int_equal(glint_asset_moon_width, 1024);
    assert_int_equal(glint_asset_moon_height, 512);
    assert_int_equal(tex.width, glint_asset_moon_width);
    assert_int_equal(tex.height, glint_asset_moon_height);
    assert_memory_equal(tex.srgb, glint_asset_moon_srgb, (size_t)1024 * 512 * 3);
    texture_image_free(&tex);
}

/* A borrowed image reads the caller's bytes through the same table as a
 * decoded one, and freeing it empties it without touching them. */
static void test_borrowed_image(void **state)
{
    static const unsigned char pixels[2 * 3] = {0, 128, 255, 10, 20, 30};
    texture_image tex = texture_image_borrow(2, 1, pixels);
    assert_int_equal(tex.width, 2);
    assert_int_equal(tex.height, 1);
    assert_ptr_equal(tex.srgb, pixels);
    assert_null(tex.owned);
    assert_true(texture_image_at(&tex, 0) == 0.0f);
    assert_true(texture_image_at(&tex, 1) == (float)glint_srgb_to_linear(128 / 255.0));
    assert_true(texture_image_at(&tex, 2) == 1.0f);
    assert_true(texture_image_at(&tex, 5) == (float)glint_srgb_to_linear(30 / 255.0));
    texture_image_free(&tex);
    assert_null(tex.srgb);
    assert_int_equal(tex.width, 0);
    assert_int_equal(pixels[5], 30);
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
        cmocka_unit_test(test_load_missing_file),
        cmocka_unit_test(test_load_directory),
        cmocka_unit_test(test_load_text_file),
        cmocka_unit_test(test_load_truncated_png),
        cmocka_unit_test(test_load_png_bad_crc),
        cmocka_unit_test(test_load_oversized_png),
        cmocka_unit_test(test_load_png_chunk_past_end),
        cmocka_unit_test(test_load_exr_corrupt),
        cmocka_unit_test(test_load_exr_luminance_chroma),
        cmocka_unit_test(test_load_exr_too_large),
        cmocka_unit_test(test_load_grey_png),
        cmocka_unit_test(test_textures_share_decoded_file),
        cmocka_unit_test(test_textures_within_budget),
        cmocka_unit_test(test_load_palette_and_alpha_png),
        cmocka_unit_test(test_load_16bit_png),
        cmocka_unit_test(test_load_jpeg_memory),
        cmocka_unit_test(test_load_truncated_jpeg),
        cmocka_unit_test(test_load_refused_jpegs),
        cmocka_unit_test(test_load_moon),
        cmocka_unit_test(test_embedded_moon_is_the_decoded_file),
        cmocka_unit_test(test_borrowed_image),
    };
    return cmocka_run_group_tests(tests, setup_dir, teardown_dir);
}
