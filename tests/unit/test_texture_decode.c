/* test_texture_decode.c - PNG, JPEG and OpenEXR texture decoding with
 * every refusal message, and a scene's sharing and budget of the files its
 * textures decode. */
#include <stdarg.h>
#include <stddef.h>
#include <setjmp.h>
#include <stdint.h>
#include <cmocka.h>

#include <stdio.h>
#include <stdlib.h>
#include <string.h>
#include <sys/stat.h>
#include <unistd.h>
#include <jpeglib.h>
#include <png.h>
#include <zlib.h>

#define TMP_TREE_NAME "glint-texture-decode"
#include "image_test_files.h"
#include "image/texture_image.h"
#include "scene/scene.h"

/* ------------------------------------------------------------- helpers */

static void expect_prefix(const char *message, const char *prefix)
{
    if (strncmp(message, prefix, strlen(prefix)) != 0 || strlen(message) == strlen(prefix))
        fail_msg("message '%s' does not continue '%s'", message, prefix);
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
