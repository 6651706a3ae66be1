/* test_scene_file.c - the YAML scene loader: every key of the format and its
 * effect on the loaded scene (or on a tiny render), includes, anchors and
 * merge keys, and a table of broken scenes, each with its exact first
 * message and number of problems. */
#include <stdarg.h>
#include <stddef.h>
#include <setjmp.h>
#include <stdint.h>
#include <cmocka.h>

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

static void log_report(void *user, const char *message)
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

static void near_at(double a, double b, double tol, const char *what, const char *file, int line)
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

static void assert_matrix(const glint_transform *t, const double want[3][4], double tol)
{
    for (int i = 0; i < 3; i++)
        for (int j = 0; j < 4; j++)
            if (!(fabs(t->m[i][j] - want[i][j]) <= tol))
                fail_msg("to_world m[%d][%d] is %.17g, expected %.17g", i, j, t->m[i][j], want[i][j]);
}

static void assert_same_material(const glint_material *a, const glint_material *b)
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

static void assert_same_settings(const glint_settings *a, const glint_settings *b)
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

static double lin(double display)
{
    return glint_srgb_to_linear(display);
}

static void tmp_path(char *buf, const char *name)
{
    int n = snprintf(buf, PATH_SIZE, "%s/%s", tmp_dir, name);
    assert_true(n > 0 && n < PATH_SIZE);
}

/* Fills path with tmp_dir/name and makes the folders on the way. */
static void tmp_path_made(char *path, const char *name)
{
    tmp_path(path, name);
    for (char *p = path + strlen(tmp_dir) + 1; (p = strchr(p, '/')) != NULL; p++) {
        *p = '\0';
        mkdir(path, 0755);
        *p = '/';
    }
}

/* Writes text to tmp_dir/name. */
static void write_tmp(const char *name, const char *text)
{
    char path[PATH_SIZE];
    tmp_path_made(path, name);
    FILE *f = fopen(path, "wb");
    assert_non_null(f);
    assert_int_equal(fwrite(text, 1, strlen(text), f), strlen(text));
    assert_int_equal(fclose(f), 0);
}

/* Replaces each "@TMP@" in `in` with tmp_dir. */
static void with_tmp(const char *in, char *out, size_t size)
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
static glint_scene *load_good_named(const char *yaml, const char *name)
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

static glint_scene *load_good(const char *yaml)
{
    return load_good_named(yaml, "good.yaml");
}

static glint_scene *load_good_file(const char *name)
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
static void load_bad(const char *yaml, int max_errors, report_log *log, glint_error *err)
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
static int material_named(const glint_scene *s, const char *name)
{
    int i = scene_find_material(s, name);
    if (i < 0)
        fail_msg("no material named '%s'", name);
    return i;
}

static int texture_named(const glint_scene *s, const char *name)
{
    int i = scene_find_texture(s, name);
    if (i < 0)
        fail_msg("no texture named '%s'", name);
    return i;
}

static glint_image render(const glint_scene *s)
{
    glint_render_options o = {.threads = 1};
    glint_image img;
    glint_error err = {0};
    if (glint_render(s, &o, &img, NULL, &err))
        fail_msg("render failed: %s", err.message);
    return img;
}

static void write_png(const char *name, int width, int height, const unsigned char *rgb)
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

static size_t put_chunk(unsigned char *out, const char *type, const unsigned char *data, uint32_t size)
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
static void write_table_pngs(void)
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

static int setup_dir(void **state)
{
    const char *base = getenv("GLINT_TEST_TMP");
    if (!base || !*base)
        base = "/tmp";
    snprintf(tmp_dir, sizeof tmp_dir, "%s/glint-scene-file-%ld", base, (long)getpid());
    remove_tree(tmp_dir);
    if (mkdir(tmp_dir, 0755) != 0)
        return -1;
    write_table_pngs();
    return 0;
}

static int teardown_dir(void **state)
{
    remove_tree(tmp_dir);
    return 0;
}

/* ------------------------------------------------------------- settings */

static void test_settings_every_key(void **state)
{
    glint_scene *s = load_good("glint: 1\n"
                               "settings:\n"
                               "  width: 33\n"
                               "  height: 17\n"
                               "  samples: 9\n"
                               "  sampler: jittered\n"
                               "  seed: 4294967295\n"
                               "  depth: 0\n"
                               "  background: [0.5, 0.25, 1]\n"
                               "  ambient: [0.2, 0.4, 0.6]\n"
                               "  output: renders/out.ppm\n");
    glint_settings st = glint_scene_get_settings(s);
    assert_int_equal(st.width, 33);
    assert_int_equal(st.height, 17);
    assert_int_equal(st.samples_per_pixel, 9);
    assert_int_equal(st.sampler, GLINT_SAMPLER_JITTERED);
    assert_true(st.seed == 4294967295u);
    assert_int_equal(st.max_depth, 0);
    assert_rgb(st.background, lin(0.5), lin(0.25), 1, 0);
    assert_rgb(st.ambient_light, lin(0.2), lin(0.4), lin(0.6), 0);
    assert_string_equal(glint_scene_get_output(s), "renders/out.ppm");
    glint_scene_free(s);
}

/* settings.ambient_occlusion: off unless given; given, 16 samples and no
 * limit unless it says. */
static void test_settings_ambient_occlusion(void **state)
{
    glint_scene *s = load_good("settings: {width: 8}\n");
    assert_int_equal(glint_scene_get_settings(s).occlusion_samples, 0);
    glint_scene_free(s);
    s = load_good("settings:\n  ambient_occlusion: {}\n");
    assert_int_equal(glint_scene_get_settings(s).occlusion_samples, 16);
    assert_exact(glint_scene_get_settings(s).occlusion_distance, 0);
    glint_scene_free(s);
    s = load_good("settings:\n  ambient_occlusion: {samples: 9, distance: 2.5}\n");
    assert_int_equal(glint_scene_get_settings(s).occlusion_samples, 9);
    assert_exact(glint_scene_get_settings(s).occlusion_distance, 2.5);
    glint_scene_free(s);
}

/* settings.filter and settings.adaptive: the box and no adaptive sampling
 * unless given; adaptive given, a threshold of 0.05 and 64 samples at most
 * unless it says; a filter's radius 0 (its own) unless it says. */
static void test_settings_filter_and_adaptive(void **state)
{
    glint_scene *s = load_good("settings: {samples: 5, sampler: sobol}\n");
    glint_settings st = glint_scene_get_settings(s);
    assert_int_equal(st.samples_per_pixel, 5);
    assert_int_equal(st.sampler, GLINT_SAMPLER_SOBOL);
    assert_int_equal(st.filter, GLINT_FILTER_BOX);
    assert_int_equal(st.adaptive_max_samples, 0);
    glint_scene_free(s);
    s = load_good("settings:\n  sampler: sobol\n  filter: {type: mitchell}\n  adaptive: {}\n");
    st = glint_scene_get_settings(s);
    assert_int_equal(st.filter, GLINT_FILTER_MITCHELL);
    assert_exact(st.filter_radius, 0);
    assert_int_equal(st.adaptive_max_samples, 64);
    assert_exact(st.adaptive_threshold, 0.05);
    glint_scene_free(s);
    s = load_good("settings:\n  sampler: sobol\n  filter: {type: lanczos, radius: 2.5}\n"
                  "  adaptive: {threshold: 0.2, max_samples: 4096}\n");
    st = glint_scene_get_settings(s);
    assert_int_equal(st.filter, GLINT_FILTER_LANCZOS);
    assert_exact(st.filter_radius, 2.5);
    assert_int_equal(st.adaptive_max_samples, 4096);
    assert_exact(st.adaptive_threshold, 0.2);
    glint_scene_free(s);
}

static void test_settings_other_values(void **state)
{
    glint_scene *s = load_good("settings:\n"
                               "  width: 65536\n"
                               "  height: 1\n"
                               "  samples: 4096\n"
                               "  sampler: regular\n"
                               "  seed: 0\n"
                               "  depth: 64\n"
                               "  output: OUT.PNG\n");
    glint_settings st = glint_scene_get_settings(s);
    assert_int_equal(st.width, 65536);
    assert_int_equal(st.height, 1);
    assert_int_equal(st.samples_per_pixel, 4096);
    assert_int_equal(st.sampler, GLINT_SAMPLER_REGULAR);
    assert_int_equal(st.seed, 0);
    assert_int_equal(st.max_depth, 64);
    assert_string_equal(glint_scene_get_output(s), "OUT.PNG");
    glint_scene_free(s);
}

/* A file that sets nothing gives the API's defaults; so does an empty one. */
static void test_defaults_of_an_empty_scene(void **state)
{
    const char *texts[] = {"glint: 1\n", "glint: 1 # and a comment\n"};
    for (size_t i = 0; i < COUNT(texts); i++) {
        glint_scene *s = load_good(texts[i]);
        glint_settings st = glint_scene_get_settings(s), def = glint_settings_default();
        assert_same_settings(&st, &def);
        glint_camera cam = glint_scene_get_camera(s);
        assert_vec(cam.position, 0, 0, 0, 0);
        assert_vec(cam.look_at, 0, 0, -1, 0);
        assert_vec(cam.up, 0, 1, 0, 0);
        assert_exact(cam.vfov_degrees, 45);
        assert_int_equal(glint_scene_get_fog(s).kind, GLINT_FOG_NONE);
        assert_null(glint_scene_get_output(s));
        glint_scene_counts c = glint_scene_get_counts(s);
        assert_int_equal(c.textures + c.materials + c.shapes + c.lights, 0);
        glint_scene_free(s);
    }
}

/* A scene file with nothing in it, or only comments, is refused, not
 * rendered black: the file named is probably not the one meant. An empty
 * included file is fine. */
static void test_empty_file_holds_no_scene(void **state)
{
    const char *texts[] = {"", "# only a comment\n", "\n\n   \n", "---\n"};
    for (size_t i = 0; i < COUNT(texts); i++) {
        report_log log = {0};
        glint_error err = {0};
        load_bad(texts[i], 0, &log, &err);
        assert_string_equal(err.message, "bad.yaml: the file holds no scene");
        assert_int_equal(err.status, GLINT_ERR_INVALID);
        assert_int_equal(log.count, 1);
    }
    write_tmp("empty/nothing.yaml", "# nothing yet\n");
    write_tmp("empty/top.yaml", "include: nothing.yaml\nsettings: {width: 7}\n");
    char path[PATH_SIZE];
    tmp_path_made(path, "empty/top.yaml");
    glint_error err = {0};
    glint_scene *s = glint_scene_load_file(path, NULL, &err);
    assert_non_null(s);
    assert_int_equal(glint_scene_get_settings(s).width, 7);
    glint_scene_free(s);
}

/* A scene read from a stream (glint -) is read whole and loads as from a
 * file: problems at their line and column under the name given, an empty
 * stream refused, an empty include fine, and the stream left open. */
static void test_load_stream(void **state)
{
    static char bad[] = "settings: {width: 8}\nobjects:\n  - {type: sphere, radius: -1, material: {}}\n";
    FILE *in = fmemopen(bad, strlen(bad), "r");
    assert_non_null(in);
    report_log log = {0};
    glint_load_options o = {.report = log_report, .report_user = &log};
    glint_error err = {0};
    assert_null(glint_scene_load_stream(in, "<stdin>", &o, &err));
    assert_string_equal(err.message, "<stdin>:3:28: 'radius' must be positive, got -1");
    assert_int_equal(log.count, 1);
    assert_int_equal(fclose(in), 0);

    static char nothing[] = "# nothing\n";
    in = fmemopen(nothing, strlen(nothing), "r");
    assert_null(glint_scene_load_stream(in, NULL, NULL, &err));
    assert_string_equal(err.message, "<stream>: the file holds no scene");
    assert_int_equal(err.status, GLINT_ERR_INVALID);
    fclose(in);

    write_tmp("stream/nothing.yaml", "# nothing yet\n");
    char text[2 * PATH_SIZE];
    with_tmp("include: @TMP@/stream/nothing.yaml\nsettings: {width: 7}\n", text, sizeof text);
    in = fmemopen(text, strlen(text), "r");
    glint_scene *s = glint_scene_load_stream(in, "<stdin>", NULL, &err);
    assert_non_null(s);
    assert_int_equal(glint_scene_get_settings(s).width, 7);
    glint_scene_free(s);
    fclose(in);
}

/* A ring facing the camera: the hole and the outside show the background,
 * the ring its colour; the file's keys reach the shape, the defaults fill
 * the rest. */
static void test_disk_ring(void **state)
{
    glint_scene *s = load_good("settings: {width: 21, height: 21, background: [0, 0, 1]}\n"
                               "camera: {position: [0, 0, 10], look_at: [0, 0, 0], fov: 20}\n"
                               "materials: {red: {color: [1, 0, 0], ambient: 1, diffuse: 0, specular: 0}}\n"
                               "objects:\n"
                               "  - {type: disk, radius: 1.5, inner_radius: 0.5, normal: [0, 0, 1], material: red}\n"
                               "  - {type: disk, center: [0, 0, -50], radius: 0.25, material: red}\n");
    assert_int_equal(s->shape_count, 2);
    const glint_shape *ring = &s->shapes[0].desc, *disc = &s->shapes[1].desc;
    assert_int_equal(ring->kind, GLINT_SHAPE_DISK);
    assert_exact(ring->radius, 1.5);
    assert_exact(ring->inner_radius, 0.5);
    assert_vec(ring->normal, 0, 0, 1, 0);
    assert_vec(disc->normal, 0, 1, 0, 0); /* the default: facing up */
    assert_exact(disc->inner_radius, 0);
    glint_image img = render(s);
    /* Pixels are 2 tan(10 deg) 10 / 21 = 0.168 units across: the centre
     * pixel looks through the hole, pixel 16 lands 1.01 from the centre on
     * the ring, pixel 20 at 1.68 beyond it. */
    const float *centre = img.pixels + 3 * (10 * 21 + 10), *on = img.pixels + 3 * (10 * 21 + 16),
                *off = img.pixels + 3 * (10 * 21 + 20);
    assert_true(centre[0] == 0 && centre[1] == 0 && centre[2] == 1);
    assert_true(on[0] == 1 && on[1] == 0 && on[2] == 0);
    assert_true(off[0] == 0 && off[1] == 0 && off[2] == 1);
    glint_image_free(&img);
    glint_scene_free(s);
}

static void test_camera_every_key(void **state)
{
    glint_scene *s = load_good("camera:\n"
                               "  position: [1, 2, 3]\n"
                               "  look_at: [4, 5.5, -6]\n"
                               "  up: [0, 0, 1]\n"
                               "  fov: 35.5\n");
    glint_camera cam = glint_scene_get_camera(s);
    assert_vec(cam.position, 1, 2, 3, 0);
    assert_vec(cam.look_at, 4, 5.5, -6, 0);
    assert_vec(cam.up, 0, 0, 1, 0);
    assert_exact(cam.vfov_degrees, 35.5);
    glint_scene_free(s);
}

/* ------------------------------------------------------------------ fog */

static void test_fog_none(void **state)
{
    glint_scene *s = load_good("fog:\n  type: none\n  color: [1, 0, 0]\n");
    glint_fog f = glint_scene_get_fog(s);
    assert_int_equal(f.kind, GLINT_FOG_NONE);
    glint_scene_free(s);
}

static void test_fog_linear(void **state)
{
    glint_scene *s = load_good("fog:\n"
                               "  type: linear\n"
                               "  color: [0.5, 0.5, 0.5]\n"
                               "  start: -2\n"
                               "  end: 10.5\n");
    glint_fog f = glint_scene_get_fog(s);
    assert_int_equal(f.kind, GLINT_FOG_LINEAR);
    assert_rgb(f.color, lin(0.5), lin(0.5), lin(0.5), 0);
    assert_exact(f.start, -2);
    assert_exact(f.end, 10.5);
    glint_scene_free(s);
}

static void test_fog_exponential(void **state)
{
    glint_scene *s = load_good("fog: {type: exponential, color: \"#808080\", density: 0.25}\n");
    glint_fog f = glint_scene_get_fog(s);
    assert_int_equal(f.kind, GLINT_FOG_EXPONENTIAL);
    assert_rgb(f.color, lin(128 / 255.0), lin(128 / 255.0), lin(128 / 255.0), 0);
    assert_exact(f.density, 0.25);
    glint_scene_free(s);
}

/* ------------------------------------------------------------- textures */

/* focus_on focuses a thin lens at that point's depth along the view. */
static void test_camera_focus_on(void **state)
{
    glint_scene *s = load_good("camera: {type: thin_lens, position: [0, 1, 6], look_at: [0, 1, 0], aperture: 0.2,"
                               " focus_on: [2, 3, -1]}\n");
    assert_exact(glint_scene_get_camera(s).focus_distance, 7);
    glint_scene_free(s);
}

/* f_number and sensor_width reach the camera as written. */
static void test_camera_f_number(void **state)
{
    glint_scene *s = load_good("camera: {type: thin_lens, position: [0, 1, 6], look_at: [0, 1, 0], f_number: 2.8,"
                               " sensor_width: 0.024}\n");
    glint_camera c = glint_scene_get_camera(s);
    assert_exact(c.f_number, 2.8);
    assert_exact(c.sensor_width, 0.024);
    assert_exact(c.aperture, 0);
    glint_scene_free(s);
}

/* The environment names a texture; its intensity and rotation default to 1 and 0. */
static void test_environment(void **state)
{
    glint_scene *s = load_good("textures:\n"
                               "  sky: {type: checker, colors: [[0, 0, 1], [1, 1, 1]]}\n"
                               "environment: {texture: sky, rotation: 30}\n");
    glint_environment env = glint_scene_get_environment(s);
    assert_int_equal(env.texture, 0);
    assert_exact(env.intensity, 1);
    assert_exact(env.rotation, 30);
    glint_scene_free(s);
}

static void test_checker_texture(void **state)
{
    glint_scene *s = load_good("textures:\n"
                               "  tiles:\n"
                               "    type: checker\n"
                               "    colors: [\"#ff0000\", [0, 0, 1]]\n"
                               "    size: 0.25\n"
                               "    mapping: planar\n"
                               "  plain: {type: checker}\n");
    assert_int_equal(glint_scene_get_counts(s).textures, 2);
    const texture *t = &s->textures[texture_named(s, "tiles")];
    assert_ptr_equal(t->kind, &checker_texture);
    assert_rgb(t->a, 1, 0, 0, 0);
    assert_rgb(t->b, 0, 0, 1, 0);
    assert_exact(t->cell, 0.25);
    assert_int_equal(t->mapping.kind, GLINT_MAP_PLANAR);
    /* Defaults: black and white cells of one unit, the shape's own (u, v). */
    t = &s->textures[texture_named(s, "plain")];
    assert_ptr_equal(t->kind, &checker_texture);
    assert_rgb(t->a, 0, 0, 0, 0);
    assert_rgb(t->b, 1, 1, 1, 0);
    assert_exact(t->cell, 1);
    assert_int_equal(t->mapping.kind, GLINT_MAP_UV);
    assert_vec(t->mapping.center, 0, 0, 0, 0);
    assert_exact(t->mapping.scale, 1);
    glint_scene_free(s);
}

static void test_mapping_as_a_word(void **state)
{
    glint_scene *s = load_good("textures:\n"
                               "  a: {type: checker, mapping: uv}\n"
                               "  b: {type: checker, mapping: planar}\n"
                               "  c: {type: checker, mapping: spherical}\n"
                               "  d: {type: checker, mapping: cylindrical}\n");
    assert_int_equal(s->textures[texture_named(s, "a")].mapping.kind, GLINT_MAP_UV);
    assert_int_equal(s->textures[texture_named(s, "b")].mapping.kind, GLINT_MAP_PLANAR);
    assert_int_equal(s->textures[texture_named(s, "c")].mapping.kind, GLINT_MAP_SPHERICAL);
    assert_int_equal(s->textures[texture_named(s, "d")].mapping.kind, GLINT_MAP_CYLINDRICAL);
    /* Without a center, the mapping is centred on each shape it is on. */
    assert_false(s->textures[texture_named(s, "c")].mapping.center_given);
    glint_scene_free(s);
}

static void test_mapping_as_a_map(void **state)
{
    glint_scene *s = load_good("textures:\n"
                               "  flat:\n"
                               "    type: checker\n"
                               "    mapping:\n"
                               "      type: planar\n"
                               "      center: [1, 2, 3]\n"
                               "      u_axis: [0, 0, 1]\n"
                               "      v_axis: [0, 1, 0]\n"
                               "      scale: 2.5\n"
                               "  can: {type: checker, mapping: {type: cylindrical, scale: 4, center: [0, -1, 0]}}\n"
                               "  ball: {type: checker, mapping: {type: spherical, center: [5, 5, 5]}}\n"
                               "  own: {type: checker, mapping: {type: uv}}\n");
    glint_mapping m = s->textures[texture_named(s, "flat")].mapping;
    assert_int_equal(m.kind, GLINT_MAP_PLANAR);
    assert_vec(m.center, 1, 2, 3, 0);
    assert_true(m.center_given);
    assert_vec(m.u_axis, 0, 0, 1, 0);
    assert_vec(m.v_axis, 0, 1, 0, 0);
    assert_exact(m.scale, 2.5);
    m = s->textures[texture_named(s, "can")].mapping;
    assert_int_equal(m.kind, GLINT_MAP_CYLINDRICAL);
    assert_exact(m.scale, 4);
    assert_vec(m.center, 0, -1, 0, 0);
    m = s->textures[texture_named(s, "ball")].mapping;
    assert_int_equal(m.kind, GLINT_MAP_SPHERICAL);
    assert_vec(m.center, 5, 5, 5, 0);
    assert_true(m.center_given);
    assert_int_equal(s->textures[texture_named(s, "own")].mapping.kind, GLINT_MAP_UV);
    glint_scene_free(s);
}

/* The texels of tiny.png below, as linear values. */
static void check_tiny_texels(const texture *t)
{
    assert_ptr_equal(t->kind, &image_texture);
    assert_int_equal(t->image.width, 2);
    assert_int_equal(t->image.height, 2);
    static const unsigned char want[12] = {255, 0, 0, 0, 128, 255, 10, 20, 30, 255, 255, 255};
    for (int i = 0; i < 12; i++)
        assert_exact(texture_image_at(&t->image, i), (float)glint_srgb_to_linear(want[i] / 255.0));
}

/* An image texture named relative to the scene file, in a folder beside
 * it, decoded once a material uses it; one no material uses is checked but
 * never decoded. */
static void test_image_texture_from_a_file(void **state)
{
    static const unsigned char rgb[12] = {255, 0, 0, 0, 128, 255, 10, 20, 30, 255, 255, 255};
    write_png("img/maps/tiny.png", 2, 2, rgb);
    write_tmp("img/maps/unused.png", "\x89PNG\r\n\x1a\n but nothing a PNG has after its signature");
    write_tmp("img/scene.yaml", "textures:\n"
                                "  tiny:\n"
                                "    type: image\n"
                                "    file: maps/tiny.png\n"
                                "    mapping: {type: planar, center: [0, 1, 0], scale: 3}\n"
                                "  plain: {type: image, file: maps/tiny.png}\n"
                                "  unused: {type: image, file: maps/unused.png}\n"
                                "materials: {a: {texture: tiny}, b: {texture: plain}}\n");
    glint_scene *s = load_good_file("img/scene.yaml");
    assert_null(s->textures[texture_named(s, "unused")].image.srgb);
    assert_int_equal(s->image_files.count, 1);
    const texture *t = &s->textures[texture_named(s, "tiny")];
    check_tiny_texels(t);
    assert_int_equal(t->mapping.kind, GLINT_MAP_PLANAR);
    assert_vec(t->mapping.center, 0, 1, 0, 0);
    assert_exact(t->mapping.scale, 3);
    t = &s->textures[texture_named(s, "plain")];
    check_tiny_texels(t);
    assert_int_equal(t->mapping.kind, GLINT_MAP_UV);
    glint_scene_free(s);

    /* From memory, paths resolve against the folder of the name given. */
    char name[PATH_SIZE];
    tmp_path(name, "img/memory.yaml");
    s = load_good_named("textures:\n  tiny: {type: image, file: maps/tiny.png}\nmaterials: {m: {texture: tiny}}\n",
                        name);
    check_tiny_texels(&s->textures[0]);
    glint_scene_free(s);
}

/* ------------------------------------------------------------ materials */

static void test_material_every_key(void **state)
{
    glint_scene *s = load_good("textures:\n"
                               "  checks: {type: checker}\n"
                               "  other: {type: checker, size: 2}\n"
                               "materials:\n"
                               "  glass:\n"
                               "    color: [0.5, 0.25, 0.75]\n"
                               "    texture: other\n"
                               "    ambient: 0.3\n"
                               "    diffuse: 0.7\n"
                               "    specular: 0.4\n"
                               "    shininess: 12.5\n"
                               "    reflectivity: 0.25\n"
                               "    transparency: 0.2\n"
                               "    refraction: 0.6\n"
                               "    ior: 1.33\n"
                               "    tint: 0.8\n"
                               "    fresnel: true\n"
                               "  plain: {}\n"
                               "  unlit: {fresnel: false, diffuse: 0, specular: 0, ambient: 1}\n");
    assert_int_equal(glint_scene_get_counts(s).materials, 3);
    const glint_material *m = &s->materials[material_named(s, "glass")].m;
    assert_rgb(m->color, lin(0.5), lin(0.25), lin(0.75), 0);
    assert_int_equal(m->texture, texture_named(s, "other"));
    assert_int_equal(m->texture, 1);
    assert_exact(m->ambient, 0.3);
    assert_exact(m->diffuse, 0.7);
    assert_exact(m->specular, 0.4);
    assert_exact(m->shininess, 12.5);
    assert_exact(m->reflectivity, 0.25);
    assert_exact(m->transparency, 0.2);
    assert_exact(m->refraction, 0.6);
    assert_exact(m->ior, 1.33);
    assert_exact(m->tint, 0.8);
    assert_true(m->fresnel);

    /* Nothing given: glint_material_default(). */
    glint_material def = glint_material_default();
    m = &s->materials[material_named(s, "plain")].m;
    assert_same_material(m, &def);
    assert_int_equal(m->texture, -1);

    m = &s->materials[material_named(s, "unlit")].m;
    assert_false(m->fresnel);
    assert_exact(m->diffuse, 0);
    assert_exact(m->specular, 0);
    assert_exact(m->ambient, 1);
    assert_exact(m->shininess, def.shininess);
    glint_scene_free(s);
}

/* --------------------------------------------------------------- lights */

static void test_lights(void **state)
{
    glint_scene *s = load_good("lights:\n"
                               "  - {type: point, position: [1, 2, 3], color: [1, 0.5, 0], intensity: 2}\n"
                               "  - type: spot\n"
                               "    position: [0, 5, 0]\n"
                               "    direction: [0, -2, 0]\n"
                               "    color: \"#ffffff\"\n"
                               "    angle: 30\n"
                               "    falloff: 10\n"
                               "  - {type: directional, direction: [-1, -1, -1], color: {linear: [0.2, 0.4, 0.6]},"
                               " intensity: 0.5}\n"
                               "  - {type: spot, position: [0, 0, 0], direction: [1, 0, 0], angle: 90}\n"
                               "  - {type: point, position: [0, 0, 0]}\n"
                               "  - {type: point, position: [0, 0, 0], intensity: 0}\n");
    assert_int_equal(glint_scene_get_counts(s).lights, 6);
    const glint_light *l = &s->lights[0].desc;
    assert_int_equal(l->kind, GLINT_LIGHT_POINT);
    assert_vec(l->position, 1, 2, 3, 0);
    assert_rgb(l->color, 2, 2 * lin(0.5), 0, 1e-15);

    l = &s->lights[1].desc;
    assert_int_equal(l->kind, GLINT_LIGHT_SPOT);
    assert_vec(l->position, 0, 5, 0, 0);
    assert_vec(l->direction, 0, -2, 0, 0);
    assert_rgb(l->color, 1, 1, 1, 0);
    assert_exact(l->cone_angle, 30);
    assert_exact(l->falloff_angle, 10);

    l = &s->lights[2].desc;
    assert_int_equal(l->kind, GLINT_LIGHT_DIRECTIONAL);
    assert_vec(l->direction, -1, -1, -1, 0);
    assert_rgb(l->color, 0.1, 0.2, 0.3, 1e-15);

    l = &s->lights[3].desc;
    assert_int_equal(l->kind, GLINT_LIGHT_SPOT);
    assert_exact(l->cone_angle, 90);
    assert_exact(l->falloff_angle, 0);

    /* Defaults: white, intensity 1. */
    assert_rgb(s->lights[4].desc.color, 1, 1, 1, 0);
    assert_rgb(s->lights[5].desc.color, 0, 0, 0, 0);
    glint_scene_free(s);
}

/* Area lights: their shapes, their radiance and their sample counts. */
static void test_area_lights(void **state)
{
    glint_scene *s = load_good("lights:\n"
                               "  - {type: sphere, position: [1, 2, 3], radius: 0.5, intensity: 4}\n"
                               "  - {type: rectangle, corner: [-1, 5, -1], edge1: [2, 0, 0], edge2: [0, 0, 2],"
                               " color: [1, 0.5, 0], samples: 9}\n"
                               "  - {type: disk, position: [0, 3, 0], direction: [0, -1, 0], radius: 2, samples: 1}\n");
    assert_int_equal(glint_scene_get_counts(s).lights, 3);
    const glint_light *l = &s->lights[0].desc;
    assert_int_equal(l->kind, GLINT_LIGHT_SPHERE);
    assert_vec(l->position, 1, 2, 3, 0);
    assert_exact(l->radius, 0.5);
    assert_rgb(l->color, 4, 4, 4, 0);
    assert_int_equal(l->samples, 16);
    l = &s->lights[1].desc;
    assert_int_equal(l->kind, GLINT_LIGHT_RECTANGLE);
    assert_vec(l->position, -1, 5, -1, 0);
    assert_vec(l->edge1, 2, 0, 0, 0);
    assert_vec(l->edge2, 0, 0, 2, 0);
    assert_rgb(l->color, 1, lin(0.5), 0, 1e-15);
    assert_int_equal(l->samples, 9);
    assert_vec(s->lights[1].normal, 0, -1, 0, 0);
    l = &s->lights[2].desc;
    assert_int_equal(l->kind, GLINT_LIGHT_DISK);
    assert_exact(l->radius, 2);
    assert_int_equal(l->samples, 1);
    glint_scene_free(s);
    /* Among delta lights, the area lights are listed by their index, as
     * camera rays look through that list alone. */
    s = load_good("lights:\n"
                  "  - {type: point, position: [0, 5, 0]}\n"
                  "  - {type: sphere, position: [1, 2, 3], radius: 0.5}\n"
                  "  - {type: directional, direction: [0, -1, 0]}\n"
                  "  - {type: disk, position: [0, 3, 0], direction: [0, -1, 0], radius: 2}\n");
    assert_int_equal(s->area_light_count, 2);
    assert_int_equal(s->area_lights[0], 1);
    assert_int_equal(s->area_lights[1], 3);
    glint_scene_free(s);
}

/* --------------------------------------------------------------- shapes */

static const char *const MATS = "materials:\n  m: {}\n  n: {color: [0, 1, 0]}\n";

static glint_scene *load_objects(const char *objects)
{
    char yaml[8192];
    snprintf(yaml, sizeof yaml, "%sobjects:\n%s", MATS, objects);
    return load_good(yaml);
}

static void test_sphere_and_plane(void **state)
{
    glint_scene *s = load_objects("  - {type: sphere, material: m, center: [1, 2, 3], radius: 0.5}\n"
                                  "  - {type: sphere, material: n, radius: 2}\n"
                                  "  - {type: plane, material: m, point: [0, -1, 0], normal: [0, 2, 0]}\n"
                                  "  - {type: plane, material: m, normal: [3, 0, 4]}\n");
    assert_int_equal(glint_scene_get_counts(s).shapes, 4);
    const glint_shape *d = &s->shapes[0].desc;
    assert_int_equal(d->kind, GLINT_SHAPE_SPHERE);
    assert_vec(d->center, 1, 2, 3, 0);
    assert_exact(d->radius, 0.5);
    assert_int_equal(s->shapes[0].material, material_named(s, "m"));
    assert_false(s->shapes[0].has_transform);

    d = &s->shapes[1].desc;
    assert_vec(d->center, 0, 0, 0, 0);
    assert_exact(d->radius, 2);
    assert_int_equal(s->shapes[1].material, material_named(s, "n"));

    /* The plane's normal is kept as a unit vector. */
    d = &s->shapes[2].desc;
    assert_int_equal(d->kind, GLINT_SHAPE_PLANE);
    assert_vec(d->center, 0, -1, 0, 0);
    assert_vec(d->normal, 0, 1, 0, 1e-15);
    d = &s->shapes[3].desc;
    assert_vec(d->center, 0, 0, 0, 0);
    assert_vec(d->normal, 0.6, 0, 0.8, 1e-15);
    glint_scene_free(s);
}

static void test_polygons(void **state)
{
    glint_scene *s = load_objects("  - type: polygon\n"
                                  "    material: m\n"
                                  "    points: [[0, 0, 0], [1, 0, 0], [0, 1, 0]]\n"
                                  "  - type: polygon\n"
                                  "    material: m\n"
                                  "    points:\n"
                                  "      - [-1, 0, -1]\n"
                                  "      - [1, 0, -1]\n"
                                  "      - [1, 0, 1]\n"
                                  "      - [-1, 0, 1]\n");
    const glint_shape *d = &s->shapes[0].desc;
    assert_int_equal(d->kind, GLINT_SHAPE_POLYGON);
    assert_int_equal(d->point_count, 3);
    assert_vec(d->points[0], 0, 0, 0, 0);
    assert_vec(d->points[1], 1, 0, 0, 0);
    assert_vec(d->points[2], 0, 1, 0, 0);
    d = &s->shapes[1].desc;
    assert_int_equal(d->point_count, 4);
    assert_vec(d->points[0], -1, 0, -1, 0);
    assert_vec(d->points[1], 1, 0, -1, 0);
    assert_vec(d->points[2], 1, 0, 1, 0);
    assert_vec(d->points[3], -1, 0, 1, 0);
    /* Points running anticlockwise seen from -y face down. */
    assert_vec(s->shapes[1].poly_normal, 0, -1, 0, 1e-15);
    glint_scene_free(s);
}

static void test_box_cylinder_cone(void **state)
{
    glint_scene *s = load_objects("  - {type: box, material: m, min: [-1, -2, -3], max: [1, 2, 3.5]}\n"
                                  "  - {type: cylinder, material: m, center: [1, 0, 1], radius: 0.5, height: 2}\n"
                                  "  - {type: cylinder, material: m, radius: 1, height: 3, capped: false}\n"
                                  "  - {type: cone, material: m, center: [0, 1, 0], radius: 2, height: 4}\n"
                                  "  - {type: cone, material: n, radius: 1, height: 1, capped: false}\n"
                                  "  - {type: cylinder, material: m, radius: 1, height: 1, capped: true}\n");
    const glint_shape *d = &s->shapes[0].desc;
    assert_int_equal(d->kind, GLINT_SHAPE_BOX);
    assert_vec(d->min, -1, -2, -3, 0);
    assert_vec(d->max, 1, 2, 3.5, 0);

    d = &s->shapes[1].desc;
    assert_int_equal(d->kind, GLINT_SHAPE_CYLINDER);
    assert_vec(d->center, 1, 0, 1, 0);
    assert_exact(d->radius, 0.5);
    assert_exact(d->height, 2);
    assert_true(d->capped);

    d = &s->shapes[2].desc;
    assert_vec(d->center, 0, 0, 0, 0);
    assert_exact(d->radius, 1);
    assert_exact(d->height, 3);
    assert_false(d->capped);

    d = &s->shapes[3].desc;
    assert_int_equal(d->kind, GLINT_SHAPE_CONE);
    assert_vec(d->center, 0, 1, 0, 0);
    assert_exact(d->radius, 2);
    assert_exact(d->height, 4);
    assert_true(d->capped);

    d = &s->shapes[4].desc;
    assert_int_equal(d->kind, GLINT_SHAPE_CONE);
    assert_false(d->capped);
    assert_int_equal(s->shapes[4].material, material_named(s, "n"));
    assert_true(s->shapes[5].desc.capped);
    glint_scene_free(s);
}

/* ----------------------------------------------------------- transforms */

static void test_transform_each_step(void **state)
{
    glint_scene *s = load_objects("  - {type: sphere, material: m, radius: 1, transform: [{translate: [1, -2, 3.5]}]}\n"
                                  "  - {type: sphere, material: m, radius: 1, transform: [{scale: 2}]}\n"
                                  "  - {type: sphere, material: m, radius: 1, transform: [{scale: [2, 3, -4]}]}\n"
                                  "  - {type: sphere, material: m, radius: 1, transform: [{rotate_x: 90}]}\n"
                                  "  - {type: sphere, material: m, radius: 1, transform: [{rotate_y: 90}]}\n"
                                  "  - {type: sphere, material: m, radius: 1, transform: [{rotate_z: 90}]}\n"
                                  "  - type: sphere\n"
                                  "    material: m\n"
                                  "    radius: 1\n"
                                  "    transform:\n"
                                  "      - rotate: {axis: [0, 0, 2], angle: 90}\n"
                                  "  - type: sphere\n"
                                  "    material: m\n"
                                  "    radius: 1\n"
                                  "    transform:\n"
                                  "      - rotate: {axis: [1, 1, 1], angle: 120}\n"
                                  "  - {type: sphere, material: m, radius: 1, transform: []}\n");
    static const double translate[3][4] = {{1, 0, 0, 1}, {0, 1, 0, -2}, {0, 0, 1, 3.5}};
    static const double uniform[3][4] = {{2, 0, 0, 0}, {0, 2, 0, 0}, {0, 0, 2, 0}};
    static const double per_axis[3][4] = {{2, 0, 0, 0}, {0, 3, 0, 0}, {0, 0, -4, 0}};
    /* Right-handed turns by 90 degrees. */
    static const double about_x[3][4] = {{1, 0, 0, 0}, {0, 0, -1, 0}, {0, 1, 0, 0}};
    static const double about_y[3][4] = {{0, 0, 1, 0}, {0, 1, 0, 0}, {-1, 0, 0, 0}};
    static const double about_z[3][4] = {{0, -1, 0, 0}, {1, 0, 0, 0}, {0, 0, 1, 0}};
    /* A third of a turn about (1, 1, 1) sends x to y, y to z and z to x. */
    static const double cycle[3][4] = {{0, 0, 1, 0}, {1, 0, 0, 0}, {0, 1, 0, 0}};
    static const double identity[3][4] = {{1, 0, 0, 0}, {0, 1, 0, 0}, {0, 0, 1, 0}};
    assert_matrix(&s->shapes[0].to_world, translate, 0);
    assert_matrix(&s->shapes[1].to_world, uniform, 0);
    assert_matrix(&s->shapes[2].to_world, per_axis, 0);
    assert_matrix(&s->shapes[3].to_world, about_x, 1e-15);
    assert_matrix(&s->shapes[4].to_world, about_y, 1e-15);
    assert_matrix(&s->shapes[5].to_world, about_z, 1e-15);
    assert_matrix(&s->shapes[6].to_world, about_z, 1e-15);
    assert_matrix(&s->shapes[7].to_world, cycle, 1e-15);
    assert_matrix(&s->shapes[8].to_world, identity, 0);
    assert_false(s->shapes[8].has_transform);
    glint_scene_free(s);
}

/* Steps apply in the order written: the first step acts first. */
static void test_transform_order(void **state)
{
    glint_scene *s = load_objects("  - {type: sphere, material: m, radius: 1, transform: [{scale: 2}, {translate: [1, 2, 3]}]}\n"
                                  "  - {type: sphere, material: m, radius: 1, transform: [{translate: [1, 2, 3]}, {scale: [2, 3, 4]}]}\n"
                                  "  - type: sphere\n"
                                  "    material: m\n"
                                  "    radius: 1\n"
                                  "    transform:\n"
                                  "      - rotate_z: 90\n"
                                  "      - translate: [5, 0, 0]\n"
                                  "      - scale: [1, 2, 1]\n");
    static const double scale_then_move[3][4] = {{2, 0, 0, 1}, {0, 2, 0, 2}, {0, 0, 2, 3}};
    static const double move_then_scale[3][4] = {{2, 0, 0, 2}, {0, 3, 0, 6}, {0, 0, 4, 12}};
    assert_matrix(&s->shapes[0].to_world, scale_then_move, 0);
    assert_matrix(&s->shapes[1].to_world, move_then_scale, 0);
    /* (1, 0, 0) turns to (0, 1, 0), moves to (5, 1, 0), stretches to (5, 2, 0). */
    glint_vec3 p = glint_transform_point(&s->shapes[2].to_world, (glint_vec3){1, 0, 0});
    assert_vec(p, 5, 2, 0, 1e-15);
    p = glint_transform_point(&s->shapes[2].to_world, (glint_vec3){0, 0, 1});
    assert_vec(p, 5, 0, 1, 1e-15);
    glint_scene_free(s);
}

/* A group's transform applies after each child's own; its material goes to
 * children without one, through nested groups; a child's own material wins. */
static void test_groups(void **state)
{
    glint_scene *s = load_objects("  - type: group\n"
                                  "    material: n\n"
                                  "    transform: [{translate: [10, 0, 0]}]\n"
                                  "    objects:\n"
                                  "      - {type: sphere, radius: 1, transform: [{scale: 2}]}\n"
                                  "      - {type: sphere, radius: 1, material: m}\n"
                                  "      - type: group\n"
                                  "        transform: [{rotate_z: 90}]\n"
                                  "        objects:\n"
                                  "          - {type: box, min: [0, 0, 0], max: [1, 1, 1], transform: [{translate: [1, 0, 0]}]}\n"
                                  "          - {type: sphere, radius: 1, material: {color: [1, 0, 0]}}\n"
                                  "  - type: group\n"
                                  "    material: {ambient: 0.75}\n"
                                  "    objects:\n"
                                  "      - {type: sphere, radius: 3}\n"
                                  "      - {type: sphere, radius: 4}\n"
                                  "  - {type: sphere, material: m, radius: 1}\n");
    int m = material_named(s, "m"), n = material_named(s, "n");
    assert_int_equal(glint_scene_get_counts(s).shapes, 7);
    /* Scaled by 2 first, then moved by 10: (1, 0, 0) lands at (12, 0, 0). */
    static const double scaled_moved[3][4] = {{2, 0, 0, 10}, {0, 2, 0, 0}, {0, 0, 2, 0}};
    assert_matrix(&s->shapes[0].to_world, scaled_moved, 0);
    assert_int_equal(s->shapes[0].material, n);
    static const double moved[3][4] = {{1, 0, 0, 10}, {0, 1, 0, 0}, {0, 0, 1, 0}};
    assert_matrix(&s->shapes[1].to_world, moved, 0);
    assert_int_equal(s->shapes[1].material, m);
    /* Box: moved by 1, turned by the inner group, moved by the outer. */
    glint_vec3 p = glint_transform_point(&s->shapes[2].to_world, (glint_vec3){0, 0, 0});
    assert_vec(p, 10, 1, 0, 1e-15);
    p = glint_transform_point(&s->shapes[2].to_world, (glint_vec3){1, 0, 0});
    assert_vec(p, 10, 2, 0, 1e-15);
    assert_int_equal(s->shapes[2].material, n);
    /* An inline material is a new, unnamed material. */
    int inline_red = s->shapes[3].material;
    assert_true(inline_red != m && inline_red != n);
    assert_null(s->materials[inline_red].name);
    assert_rgb(s->materials[inline_red].m.color, 1, 0, 0, 0);
    assert_exact(s->materials[inline_red].m.ambient, glint_material_default().ambient);
    /* A group's inline material is one material shared by its children. */
    int shared = s->shapes[4].material;
    assert_int_equal(s->shapes[5].material, shared);
    assert_null(s->materials[shared].name);
    assert_exact(s->materials[shared].m.ambient, 0.75);
    assert_false(s->shapes[4].has_transform);
    assert_int_equal(s->shapes[6].material, m);
    assert_int_equal(glint_scene_get_counts(s).materials, 4);
    glint_scene_free(s);
}

/* -------------------------------------------------------------- colours */

static void test_colours(void **state)
{
    glint_scene *s = load_good("materials:\n"
                               "  display: {color: [0.5, 0.2, 1]}\n"
                               "  hex: {color: \"#ff8000\"}\n"
                               "  upper: {color: \"#ABCDEF\"}\n"
                               "  linear: {color: {linear: [0.5, 0.2, 3]}}\n"
                               "  black: {color: [0, 0, 0]}\n");
    assert_rgb(s->materials[material_named(s, "display")].m.color, lin(0.5), lin(0.2), 1, 0);
    assert_near(lin(0.5), 0.21404114048223255, 1e-15);
    assert_rgb(s->materials[material_named(s, "hex")].m.color, 1, lin(128 / 255.0), 0, 0);
    assert_rgb(s->materials[material_named(s, "upper")].m.color, lin(0xab / 255.0), lin(0xcd / 255.0),
               lin(0xef / 255.0), 0);
    assert_rgb(s->materials[material_named(s, "linear")].m.color, 0.5, 0.2, 3, 0);
    assert_rgb(s->materials[material_named(s, "black")].m.color, 0, 0, 0, 0);
    glint_scene_free(s);
}

/* ------------------------------------------------------------- includes */

static void test_includes(void **state)
{
    write_tmp("inc/main.yaml", "glint: 1\n"
                               "include: [parts/base.yaml, parts/materials.yaml]\n"
                               "settings:\n"
                               "  height: 20\n"
                               "camera:\n"
                               "  position: [0, 0, 9]\n"
                               "materials:\n"
                               "  blue: {color: [0, 0, 1], texture: checks}\n"
                               "objects:\n"
                               "  - {type: sphere, material: red, radius: 1}\n"
                               "  - {type: sphere, material: blue, radius: 2}\n");
    write_tmp("inc/parts/base.yaml", "include: more/textures.yaml   # relative to parts/\n"
                                     "settings:\n"
                                     "  width: 40\n"
                                     "  height: 30\n"
                                     "  samples: 4\n"
                                     "camera: {position: [0, 0, 5], fov: 50}\n"
                                     "lights:\n"
                                     "  - {type: point, position: [1, 1, 1]}\n");
    write_tmp("inc/parts/more/textures.yaml", "textures:\n  checks: {type: checker, size: 3}\n");
    write_tmp("inc/parts/materials.yaml", "materials:\n"
                                          "  red: {color: [1, 0, 0], texture: checks}\n"
                                          "objects:\n"
                                          "  - {type: box, material: red, min: [0, 0, 0], max: [1, 1, 1]}\n");
    glint_scene *s = load_good_file("inc/main.yaml");
    glint_settings st = glint_scene_get_settings(s);
    assert_int_equal(st.width, 40);   /* from the include */
    assert_int_equal(st.height, 20);  /* the including file wins, key by key */
    assert_int_equal(st.samples_per_pixel, 4);
    glint_camera cam = glint_scene_get_camera(s);
    assert_vec(cam.position, 0, 0, 9, 0);
    assert_exact(cam.vfov_degrees, 50);
    glint_scene_counts c = glint_scene_get_counts(s);
    assert_int_equal(c.textures, 1);
    assert_int_equal(c.materials, 2);
    assert_int_equal(c.shapes, 3);
    assert_int_equal(c.lights, 1);
    /* Names are shared across files, in both directions of the include. */
    int checks = texture_named(s, "checks");
    assert_exact(s->textures[checks].cell, 3);
    int red = material_named(s, "red"), blue = material_named(s, "blue");
    assert_int_equal(s->materials[red].m.texture, checks);
    assert_int_equal(s->materials[blue].m.texture, checks);
    /* Included objects come first. */
    assert_int_equal(s->shapes[0].desc.kind, GLINT_SHAPE_BOX);
    assert_int_equal(s->shapes[0].material, red);
    assert_int_equal(s->shapes[1].material, red);
    assert_int_equal(s->shapes[2].material, blue);
    glint_scene_free(s);
}

/* --------------------------------------------------- anchors and merges */

static void test_anchors_and_aliases(void **state)
{
    glint_scene *s = load_good("camera:\n"
                               "  position: &eye [0, 1, 5]\n"
                               "  look_at: [0, 0, 0]\n"
                               "materials:\n"
                               "  m: &plain {specular: 0.125}\n"
                               "  again: *plain\n"
                               "lights:\n"
                               "  - {type: point, position: *eye}\n"
                               "objects:\n"
                               "  - &ball {type: sphere, material: m, radius: 2, center: [1, 1, 1]}\n"
                               "  - *ball\n");
    assert_vec(s->lights[0].desc.position, 0, 1, 5, 0);
    assert_exact(s->materials[material_named(s, "again")].m.specular, 0.125);
    assert_int_equal(glint_scene_get_counts(s).shapes, 2);
    assert_exact(s->shapes[1].desc.radius, 2);
    assert_vec(s->shapes[1].desc.center, 1, 1, 1, 0);
    glint_scene_free(s);
}

static void test_merge_keys(void **state)
{
    glint_scene *s = load_good("materials:\n"
                               "  base: &base {color: [1, 0, 0], specular: 0.5, shininess: 10}\n"
                               "  shiny:\n"
                               "    <<: *base\n"
                               "    shininess: 99\n"
                               "  both: {<<: [*base, {reflectivity: 0.25, specular: 0.75}], ambient: 0.125}\n"
                               "objects:\n"
                               "  - &ball {type: sphere, material: base, radius: 2}\n"
                               "  - {<<: *ball, center: [5, 0, 0], material: shiny}\n");
    const glint_material *m = &s->materials[material_named(s, "shiny")].m;
    assert_rgb(m->color, 1, 0, 0, 0);
    assert_exact(m->specular, 0.5);
    assert_exact(m->shininess, 99); /* a key written in the map wins */
    m = &s->materials[material_named(s, "both")].m;
    assert_exact(m->specular, 0.5); /* the earlier merge wins */
    assert_exact(m->reflectivity, 0.25);
    assert_exact(m->ambient, 0.125);
    assert_exact(m->shininess, 10);
    assert_int_equal(s->shapes[1].desc.kind, GLINT_SHAPE_SPHERE);
    assert_exact(s->shapes[1].desc.radius, 2);
    assert_vec(s->shapes[1].desc.center, 5, 0, 0, 0);
    assert_int_equal(s->shapes[1].material, material_named(s, "shiny"));
    glint_scene_free(s);
}

static void test_version_and_comments(void **state)
{
    glint_scene *s = load_good("# A scene with comments everywhere.\n"
                               "glint: 1        # the format version\n"
                               "settings:       # the image\n"
                               "  width: 8      # eight pixels\n"
                               "  # height: 999\n"
                               "materials: {m: {}}  # one material\n"
                               "objects:\n"
                               "  # - {type: sphere, material: m, radius: 1}\n"
                               "  - {type: sphere, material: m, radius: 3}  # radius: 4\n");
    assert_int_equal(glint_scene_get_settings(s).width, 8);
    assert_int_equal(glint_scene_get_settings(s).height, 480);
    assert_int_equal(glint_scene_get_counts(s).shapes, 1);
    assert_exact(s->shapes[0].desc.radius, 3);
    glint_scene_free(s);
}

/* --------------------------------------------------------- tiny renders */

/* Settings ambient times material ambient times colour, nothing else lit. */
static void test_render_ambient(void **state)
{
    glint_scene *s = load_good("settings: {width: 2, height: 2, ambient: {linear: [0.5, 1, 1]}, background: [1, 1, 1]}\n"
                               "camera: {position: [0, 0, 0], look_at: [0, 0, -1], fov: 10}\n"
                               "materials:\n"
                               "  flat: {color: {linear: [0.5, 0.25, 1]}, ambient: 0.5, diffuse: 0, specular: 0}\n"
                               "objects:\n"
                               "  - {type: plane, material: flat, point: [0, 0, -5], normal: [0, 0, 1]}\n");
    glint_image img = render(s);
    assert_int_equal(img.width, 2);
    assert_int_equal(img.height, 2);
    for (int i = 0; i < 4; i++) {
        assert_near(img.pixels[3 * i], 0.125, 1e-6);
        assert_near(img.pixels[3 * i + 1], 0.125, 1e-6);
        assert_near(img.pixels[3 * i + 2], 0.5, 1e-6);
    }
    glint_image_free(&img);
    glint_scene_free(s);
}

/* Background alone; exponential fog hides it; linear fog by distance. */
static void test_render_background_and_fog(void **state)
{
    glint_scene *s = load_good("settings: {width: 1, height: 1, background: [0.5, 0.5, 0.5]}\n");
    glint_image img = render(s);
    for (int c = 0; c < 3; c++)
        assert_near(img.pixels[c], lin(0.5), 1e-6);
    glint_image_free(&img);
    glint_scene_free(s);

    s = load_good("settings: {width: 1, height: 1, background: [1, 0, 0]}\n"
                  "fog: {type: exponential, color: {linear: [0, 0.5, 0]}, density: 0.1}\n");
    img = render(s);
    assert_near(img.pixels[0], 0, 1e-6);
    assert_near(img.pixels[1], 0.5, 1e-6);
    assert_near(img.pixels[2], 0, 1e-6);
    glint_image_free(&img);
    glint_scene_free(s);

    /* The single pixel's one sample sees the wall 5 units away: halfway from 0 to 10. */
    s = load_good("settings: {width: 1, height: 1, samples: 1}\n"
                  "fog: {type: linear, color: {linear: [0, 0, 0.5]}, start: 0, end: 10}\n"
                  "materials:\n"
                  "  glow: {color: {linear: [1, 1, 1]}, ambient: 1, diffuse: 0, specular: 0}\n"
                  "objects:\n"
                  "  - {type: plane, material: glow, point: [0, 0, -5], normal: [0, 0, 1]}\n");
    img = render(s);
    assert_near(img.pixels[0], 0.5, 1e-6);
    assert_near(img.pixels[1], 0.5, 1e-6);
    assert_near(img.pixels[2], 0.75, 1e-6);
    glint_image_free(&img);
    glint_scene_free(s);
}

/* ------------------------------------------------------ broken scenes */

/* A broken scene, loaded from memory as "bad.yaml" with the default
 * max_errors: its first message and how many problems it has. "@TMP@"
 * stands for the test's temporary folder in both texts. */
typedef struct bad_scene {
    const char *name;
    const char *yaml;
    const char *first;
    int problems;
} bad_scene;

static const bad_scene BAD[] = {
    {"syntax_unclosed_bracket",
     "objects: [1, 2\n",
     "bad.yaml:2:1: syntax error: did not find expected ',' or ']' while parsing a flow sequence", 1},
    {"syntax_bad_indentation",
     "settings:\n"
     "  width: 10\n"
     "   height: 20\n",
     "bad.yaml:3:10: syntax error: mapping values are not allowed in this context", 1},
    {"syntax_tab_indent",
     "settings:\n"
     "\twidth: 10\n",
     "bad.yaml:2:1: YAML forbids tabs for indentation: indent with spaces", 1},
    {"syntax_unclosed_quote",
     "settings:\n"
     "  output: \"a.png\n",
     "bad.yaml:3:1: syntax error: found unexpected end of stream while scanning a quoted scalar", 1},
    {"syntax_unknown_alias",
     "settings: *nope\n",
     "bad.yaml:1:11: unknown anchor 'nope': no '&nope' comes before it", 1},
    {"two_documents",
     "glint: 1\n"
     "---\n"
     "glint: 1\n",
     "bad.yaml:2:1: only one YAML document per file", 1},
    {"top_level_list",
     "- glint: 1\n",
     "bad.yaml:1:1: a scene file must be a map, got a list", 1},
    {"top_level_text",
     "hello\n",
     "bad.yaml:1:1: a scene file must be a map, got text", 1},
    {"unknown_root_key_hint",
     "glint: 1\n"
     "setings:\n"
     "  width: 10\n",
     "bad.yaml:2:1: unknown key 'setings' in the scene (did you mean 'settings'?)", 1},
    {"unknown_root_key",
     "glint: 1\n"
     "frobnicate: 1\n",
     "bad.yaml:2:1: unknown key 'frobnicate' in the scene", 1},
    {"unknown_settings_key_hint",
     "settings:\n"
     "  widht: 10\n",
     "bad.yaml:2:3: unknown key 'widht' in settings (did you mean 'width'?)", 1},
    {"unknown_camera_key_hint",
     "camera:\n"
     "  lookat: [0, 0, 0]\n",
     "bad.yaml:2:3: unknown key 'lookat' in camera (did you mean 'look_at'?)", 1},
    {"unknown_fog_key_hint",
     "fog:\n"
     "  type: exponential\n"
     "  densty: 0.5\n",
     "bad.yaml:3:3: unknown key 'densty' in exponential fog (did you mean 'density'?)", 1},
    {"unknown_texture_key_hint",
     "textures:\n"
     "  t: {type: checker, colours: [[0, 0, 0], [1, 1, 1]]}\n",
     "bad.yaml:2:22: unknown key 'colours' in texture 't' (did you mean 'colors'?)", 1},
    {"unknown_material_key_hint",
     "materials:\n"
     "  m: {colour: [1, 1, 1]}\n",
     "bad.yaml:2:7: unknown key 'colour' in material 'm' (did you mean 'color'?)", 1},
    {"unknown_light_key_hint",
     "lights:\n"
     "  - {type: point, position: [0, 0, 0], intensty: 2}\n",
     "bad.yaml:2:40: unknown key 'intensty' in a point light (did you mean 'intensity'?)", 1},
    {"unknown_object_key",
     "materials:\n"
     "  m: {}\n"
     "objects:\n"
     "  - {type: box, material: m, min: [0, 0, 0], max: [1, 1, 1], radius: 1}\n",
     "bad.yaml:4:62: unknown key 'radius' in box", 1},
    {"unknown_rotate_key_hint",
     "materials:\n"
     "  m: {}\n"
     "objects:\n"
     "  - type: sphere\n"
     "    material: m\n"
     "    radius: 1\n"
     "    transform:\n"
     "      - rotate: {axis: [0, 1, 0], angel: 30}\n",
     "bad.yaml:8:35: unknown key 'angel' in rotate (did you mean 'angle'?)", 2},
    {"unknown_mapping_key_hint",
     "textures:\n"
     "  t: {type: checker, mapping: {type: planar, scael: 2}}\n",
     "bad.yaml:2:46: unknown key 'scael' in a planar mapping (did you mean 'scale'?)", 1},
    {"sphere_needs_radius",
     "materials:\n"
     "  m: {}\n"
     "objects:\n"
     "  - type: sphere\n"
     "    material: m\n"
     "    center: [0, 1, 0]\n",
     "bad.yaml:4:5: sphere needs 'radius'", 1},
    {"plane_needs_normal",
     "materials:\n"
     "  m: {}\n"
     "objects:\n"
     "  - {type: plane, material: m, point: [0, 0, 0]}\n",
     "bad.yaml:4:5: plane needs 'normal'", 1},
    {"polygon_needs_points",
     "materials:\n"
     "  m: {}\n"
     "objects:\n"
     "  - {type: polygon, material: m}\n",
     "bad.yaml:4:5: polygon needs 'points'", 1},
    {"box_needs_min",
     "materials:\n"
     "  m: {}\n"
     "objects:\n"
     "  - {type: box, material: m, max: [1, 1, 1]}\n",
     "bad.yaml:4:5: box needs 'min'", 1},
    {"box_needs_max",
     "materials:\n"
     "  m: {}\n"
     "objects:\n"
     "  - {type: box, material: m, min: [0, 0, 0]}\n",
     "bad.yaml:4:5: box needs 'max'", 1},
    {"cylinder_needs_radius",
     "materials:\n"
     "  m: {}\n"
     "objects:\n"
     "  - {type: cylinder, material: m, height: 2}\n",
     "bad.yaml:4:5: cylinder needs 'radius'", 1},
    {"cylinder_needs_height",
     "materials:\n"
     "  m: {}\n"
     "objects:\n"
     "  - {type: cylinder, material: m, radius: 1}\n",
     "bad.yaml:4:5: cylinder needs 'height'", 1},
    {"cone_needs_height",
     "materials:\n"
     "  m: {}\n"
     "objects:\n"
     "  - {type: cone, material: m, radius: 1, capped: false}\n",
     "bad.yaml:4:5: cone needs 'height'", 1},
    {"object_needs_type",
     "materials:\n"
     "  m: {}\n"
     "objects:\n"
     "  - {material: m, radius: 1}\n",
     "bad.yaml:4:5: an object needs 'type'", 1},
    {"object_needs_material",
     "objects:\n"
     "  - {type: sphere, radius: 1}\n",
     "bad.yaml:2:5: sphere needs 'material'", 1},
    {"group_needs_objects",
     "materials:\n"
     "  m: {}\n"
     "objects:\n"
     "  - {type: group, material: m}\n",
     "bad.yaml:4:5: group needs 'objects'", 1},
    {"light_needs_type",
     "lights:\n"
     "  - {position: [0, 0, 0]}\n",
     "bad.yaml:2:5: a light needs 'type'", 1},
    {"point_light_needs_position",
     "lights:\n"
     "  - {type: point, color: [1, 1, 1]}\n",
     "bad.yaml:2:5: a point light needs 'position'", 1},
    {"spot_light_needs_three_keys",
     "lights:\n"
     "  - type: spot\n"
     "    color: [1, 1, 1]\n",
     "bad.yaml:2:5: a spot light needs 'position'", 3},
    {"spot_light_needs_angle",
     "lights:\n"
     "  - {type: spot, position: [0, 5, 0], direction: [0, -1, 0]}\n",
     "bad.yaml:2:5: a spot light needs 'angle'", 1},
    {"directional_light_needs_direction",
     "lights:\n"
     "  - {type: directional, intensity: 2}\n",
     "bad.yaml:2:5: a directional light needs 'direction'", 1},
    {"texture_needs_type",
     "textures:\n"
     "  t: {colors: [[0, 0, 0], [1, 1, 1]]}\n",
     "bad.yaml:2:6: texture 't' needs 'type'", 1},
    {"image_texture_needs_file",
     "textures:\n"
     "  t: {type: image, mapping: spherical}\n",
     "bad.yaml:2:6: texture 't' needs 'file'", 1},
    {"mapping_needs_type",
     "textures:\n"
     "  t: {type: checker, mapping: {scale: 2}}\n",
     "bad.yaml:2:31: mapping needs 'type'", 1},
    {"rotate_needs_angle",
     "materials:\n"
     "  m: {}\n"
     "objects:\n"
     "  - {type: sphere, material: m, radius: 1, transform: [{rotate: {axis: [0, 1, 0]}}]}\n",
     "bad.yaml:4:65: rotate needs 'angle'", 1},
    {"text_for_integer",
     "settings:\n"
     "  width: ten\n",
     "bad.yaml:2:10: 'width' must be a whole number from 1 to 65536, got 'ten'", 1},
    {"text_for_number",
     "materials:\n"
     "  m: {}\n"
     "objects:\n"
     "  - {type: sphere, material: m, radius: big}\n",
     "bad.yaml:4:41: 'radius' must be a number, got 'big'", 1},
    {"fraction_for_integer",
     "settings:\n"
     "  height: 10.5\n",
     "bad.yaml:2:11: 'height' must be a whole number from 1 to 65536, got '10.5'", 1},
    {"list_for_map",
     "settings: [640, 480]\n",
     "bad.yaml:1:11: settings must be a map, got a list", 1},
    {"list_for_material_map",
     "materials:\n"
     "  m: [1, 1, 1]\n",
     "bad.yaml:2:6: material 'm' must be a map, got a list", 1},
    {"map_for_list",
     "objects: {type: sphere}\n",
     "bad.yaml:1:10: 'objects' must be a list, got a map", 1},
    {"map_for_lights_list",
     "lights: {type: point}\n",
     "bad.yaml:1:9: 'lights' must be a list, got a map", 1},
    {"map_for_transform_list",
     "materials:\n"
     "  m: {}\n"
     "objects:\n"
     "  - {type: sphere, material: m, radius: 1, transform: {translate: [1, 2, 3]}}\n",
     "bad.yaml:4:55: 'transform' must be a list, got a map", 1},
    {"map_for_vector",
     "camera:\n"
     "  position: {x: 1, y: 2, z: 3}\n",
     "bad.yaml:2:13: 'position' must be a list of 3 finite numbers [x, y, z]", 1},
    {"vector_of_two",
     "materials:\n"
     "  m: {}\n"
     "objects:\n"
     "  - {type: sphere, material: m, radius: 1, center: [1, 2]}\n",
     "bad.yaml:4:52: 'center' must be a list of 3 finite numbers [x, y, z]", 1},
    {"polygon_point_not_vector",
     "materials:\n"
     "  m: {}\n"
     "objects:\n"
     "  - {type: polygon, material: m, points: [[0, 0, 0], [1, 0, 0], 7]}\n",
     "bad.yaml:4:65: 'points' must be a list of 3 finite numbers [x, y, z]", 1},
    {"bool_yes",
     "materials:\n"
     "  m: {}\n"
     "objects:\n"
     "  - {type: cylinder, material: m, radius: 1, height: 1, capped: yes}\n",
     "bad.yaml:4:65: 'capped' must be true or false, got 'yes'", 1},
    {"bool_number",
     "materials:\n"
     "  glass: {fresnel: 1}\n",
     "bad.yaml:2:20: 'fresnel' must be true or false, got '1'", 1},
    {"colour_two_channels",
     "settings:\n"
     "  background: [1, 0.5]\n",
     "bad.yaml:2:15: 'background' must be a colour: [r, g, b], \"#rrggbb\" or {linear: [r, g, b]}", 1},
    {"colour_bad_hex",
     "settings:\n"
     "  background: \"#12345g\"\n",
     "bad.yaml:2:15: 'background' must be a colour: [r, g, b], \"#rrggbb\" or {linear: [r, g, b]}", 1},
    {"colour_negative",
     "materials:\n"
     "  m: {color: [0.5, -0.1, 0]}\n",
     "bad.yaml:2:14: 'color' must not have negative channels", 1},
    {"colour_linear_wrong",
     "settings:\n"
     "  ambient: {linear: [1, 1]}\n",
     "bad.yaml:2:12: 'ambient' must be a colour: [r, g, b], \"#rrggbb\" or {linear: [r, g, b]}", 1},
    {"radius_negative",
     "materials:\n"
     "  m: {}\n"
     "objects:\n"
     "  - {type: sphere, material: m, radius: -1}\n",
     "bad.yaml:4:41: 'radius' must be positive, got -1", 1},
    {"radius_zero",
     "materials:\n"
     "  m: {}\n"
     "objects:\n"
     "  - {type: sphere, material: m, radius: 0}\n",
     "bad.yaml:4:41: 'radius' must be positive, got 0", 1},
    {"cylinder_radius_zero",
     "materials:\n"
     "  m: {}\n"
     "objects:\n"
     "  - {type: cylinder, material: m, radius: 0, height: 1}\n",
     "bad.yaml:4:43: 'radius' must be positive, got 0", 1},
    {"cylinder_height_negative",
     "materials:\n"
     "  m: {}\n"
     "objects:\n"
     "  - {type: cylinder, material: m, radius: 1, height: -2}\n",
     "bad.yaml:4:54: 'height' must be positive, got -2", 1},
    {"cone_height_zero",
     "materials:\n"
     "  m: {}\n"
     "objects:\n"
     "  - {type: cone, material: m, radius: 1, height: 0}\n",
     "bad.yaml:4:50: 'height' must be positive, got 0", 1},
    {"checker_size_zero",
     "textures:\n"
     "  t: {type: checker, size: 0}\n",
     "bad.yaml:2:28: 'size' must be positive, got 0", 1},
    {"image_zero_size",
     "textures:\n"
     "  t: {type: image, file: @TMP@/zero.png}\n"
     "materials:\n"
     "  m: {texture: t}\n",
     "bad.yaml:4:16: texture '@TMP@/zero.png' is corrupt: Invalid IHDR data", 1},
    {"image_empty_file",
     "textures:\n"
     "  t: {type: image, file: @TMP@/empty.png}\n",
     "bad.yaml:2:26: texture '@TMP@/empty.png' is not a PNG, JPEG or OpenEXR file", 1},
    {"width_zero",
     "settings:\n"
     "  width: 0\n",
     "bad.yaml:2:10: 'width' must be a whole number from 1 to 65536, got '0'", 1},
    {"samples_not_square",
     "settings:\n"
     "  samples: 8\n",
     "bad.yaml:2:12: samples 8 is not a square number: the regular sampler lays an N x N grid (1, 4, 9, 16, "
     "...); sampler sobol takes any count", 1},
    {"samples_not_square_jittered",
     "settings:\n"
     "  sampler: jittered\n"
     "  samples: 12\n",
     "bad.yaml:3:12: samples 12 is not a square number: the jittered sampler lays an N x N grid (1, 4, 9, 16, "
     "...); sampler sobol takes any count", 1},
    {"adaptive_needs_sobol",
     "settings:\n"
     "  adaptive: {max_samples: 16}\n",
     "bad.yaml:2:13: adaptive sampling needs sampler sobol, whose points stay well spread as a pixel takes more; "
     "this scene's is regular", 1},
    {"adaptive_max_below_samples",
     "settings:\n"
     "  sampler: sobol\n"
     "  samples: 32\n"
     "  adaptive: {threshold: 0.1, max_samples: 16}\n",
     "bad.yaml:4:43: adaptive max_samples 16 is fewer than samples 32", 1},
    {"adaptive_threshold_range",
     "settings:\n"
     "  sampler: sobol\n"
     "  adaptive: {threshold: 2}\n",
     "bad.yaml:3:25: 'threshold' must be from 0 to 1, got 2", 1},
    {"filter_type",
     "settings:\n"
     "  filter: {type: gauss}\n",
     "bad.yaml:2:18: 'type' must be box, tent, gaussian, mitchell or lanczos, got 'gauss' (did you mean "
     "'gaussian'?)", 1},
    {"filter_radius",
     "settings:\n"
     "  filter: {type: tent, radius: -1}\n",
     "bad.yaml:2:32: 'radius' must be from 0 to 16 pixels, got -1", 1},
    {"filter_key",
     "settings:\n"
     "  filter: {type: tent, width: 2}\n",
     "bad.yaml:2:24: unknown key 'width' in filter", 1},
    {"samples_too_many",
     "settings:\n"
     "  samples: 4225\n",
     "bad.yaml:2:12: 'samples' must be a whole number from 1 to 4096, got '4225'", 1},
    {"depth_65",
     "settings:\n"
     "  depth: 65\n",
     "bad.yaml:2:10: 'depth' must be a whole number from 0 to 64, got '65'", 1},
    {"seed_negative",
     "settings:\n"
     "  seed: -1\n",
     "bad.yaml:2:9: 'seed' must be a whole number from 0 to 4294967295, got '-1'", 1},
    {"fov_0",
     "camera:\n"
     "  fov: 0\n",
     "bad.yaml:2:8: 'fov' must be more than 0 and at most 360 degrees, got 0", 1},
    {"fov_180",
     "camera:\n"
     "  fov: 180\n",
     "bad.yaml:2:3: camera fov must be less than 180 degrees for a pinhole (got 180; a fisheye takes up to 360)", 1},
    {"camera_looks_at_itself",
     "camera:\n"
     "  position: [1, 2, 3]\n"
     "  look_at: [1, 2, 3]\n",
     "bad.yaml:2:3: camera position and look_at must differ", 1},
    {"camera_too_far",
     "camera:\n"
     "  position: [5e300, 0, 0]\n"
     "  look_at: [0, 0, 0]\n",
     "bad.yaml:2:3: camera position [5e+300, 0, 0] and look_at [0, 0, 0] are too far apart: the view direction "
     "overflows",
     1},
    {"camera_up_too_long",
     "camera:\n"
     "  up: [0, 1e200, 0]\n",
     "bad.yaml:2:3: camera up [0, 1e+200, 0] is too long: its length overflows", 1},
    {"ior_0",
     "materials:\n"
     "  glass: {refraction: 1, ior: 0}\n",
     "bad.yaml:2:31: 'ior' must be positive, got 0", 1},
    {"ambient_2",
     "materials:\n"
     "  m: {ambient: 2}\n",
     "bad.yaml:2:16: 'ambient' must be from 0 to 1, got 2", 1},
    {"reflectivity_negative",
     "materials:\n"
     "  m: {reflectivity: -0.5}\n",
     "bad.yaml:2:21: 'reflectivity' must be from 0 to 1, got -0.5", 1},
    {"transparency_plus_refraction",
     "materials:\n"
     "  m: {transparency: 0.5, refraction: 0.75}\n",
     "bad.yaml:2:6: material transparency + refraction must not exceed 1, got 1.25", 1},
    {"spot_angle_0",
     "lights:\n"
     "  - {type: spot, position: [0, 5, 0], direction: [0, -1, 0], angle: 0}\n",
     "bad.yaml:2:69: 'angle' must be more than 0 and at most 90 degrees, got 0", 1},
    {"spot_angle_95",
     "lights:\n"
     "  - {type: spot, position: [0, 5, 0], direction: [0, -1, 0], angle: 95}\n",
     "bad.yaml:2:69: 'angle' must be more than 0 and at most 90 degrees, got 95", 1},
    {"spot_falloff_above_angle",
     "lights:\n"
     "  - {type: spot, position: [0, 5, 0], direction: [0, -1, 0], angle: 20, falloff: 25}\n",
     "bad.yaml:2:5: spot light falloff must not exceed its angle 20, got 25", 1},
    {"light_intensity_negative",
     "lights:\n"
     "  - {type: point, position: [0, 5, 0], intensity: -1}\n",
     "bad.yaml:2:51: 'intensity' must be from 0 to 1e300, got -1", 1},
    {"light_direction_zero",
     "lights:\n"
     "  - {type: directional, direction: [0, 0, 0]}\n",
     "bad.yaml:2:36: 'direction' must not be zero", 1},
    {"fog_density_zero",
     "fog:\n"
     "  type: exponential\n"
     "  density: 0\n",
     "bad.yaml:3:12: 'density' must be positive, got 0", 1},
    {"fog_start_after_end",
     "fog: {type: linear, start: 10, end: 5}\n",
     "bad.yaml:1:6: linear fog needs start < end, got 10 and 5", 1},
    {"fog_type_hint",
     "fog:\n"
     "  type: linera\n",
     "bad.yaml:2:9: 'type' must be none, linear or exponential, got 'linera' (did you mean 'linear'?)", 1},
    {"sampler_hint",
     "settings:\n"
     "  sampler: jitterd\n",
     "bad.yaml:2:12: 'sampler' must be regular, jittered or sobol, got 'jitterd' (did you mean 'jittered'?)", 1},
    {"sampler_no_hint",
     "settings:\n"
     "  sampler: random\n",
     "bad.yaml:2:12: 'sampler' must be regular, jittered or sobol, got 'random'", 1},
    {"object_type_hint",
     "materials:\n"
     "  m: {}\n"
     "objects:\n"
     "  - {type: sphear, material: m, radius: 1}\n",
     "bad.yaml:4:12: 'type' must be sphere, plane, polygon, box, cylinder, cone, disk, group or mesh, got 'sphear' (did you mean 'sphere'?)", 1},
    {"object_type_no_hint",
     "materials:\n"
     "  m: {}\n"
     "objects:\n"
     "  - {type: torus, material: m, radius: 1}\n",
     "bad.yaml:4:12: 'type' must be sphere, plane, polygon, box, cylinder, cone, disk, group or mesh, got 'torus'", 1},
    {"rectangle_light_flat",
     "lights:\n"
     "  - {type: rectangle, corner: [0, 1, 0], edge1: [1, 0, 0], edge2: [2, 0, 0]}\n",
     "bad.yaml:2:5: rectangle light edge1 and edge2 must be of finite length and not parallel", 1},
    {"sphere_light_no_falloff",
     "lights:\n"
     "  - {type: sphere, position: [0, 1, 0], radius: 1, falloff_mode: inverse_square}\n",
     "bad.yaml:2:52: unknown key 'falloff_mode' in a sphere light", 1},
    {"disk_light_samples",
     "lights:\n"
     "  - {type: disk, position: [0, 1, 0], direction: [0, -1, 0], radius: 1, samples: 0.5}\n",
     "bad.yaml:2:82: 'samples' must be a whole number from 1 to 4096, got '0.5'", 1},
    {"occlusion_key",
     "settings:\n"
     "  ambient_occlusion: {sample: 3}\n",
     "bad.yaml:2:23: unknown key 'sample' in ambient_occlusion (did you mean 'samples'?)", 1},
    {"occlusion_not_a_map",
     "settings:\n"
     "  ambient_occlusion: 16\n",
     "bad.yaml:2:22: 'ambient_occlusion' must be a map, got a number", 1},
    {"environment_unknown_texture",
     "textures: {sky: {type: checker}}\n"
     "environment: {texture: skye}\n",
     "bad.yaml:2:24: unknown texture 'skye' (did you mean 'sky'?)", 1},
    {"environment_no_texture",
     "environment: {intensity: 2}\n",
     "bad.yaml:1:14: environment needs 'texture'", 1},
    {"focus_on_pinhole",
     "camera: {position: [0, 1, 6], focus_on: [0, 0, 0]}\n",
     "bad.yaml:1:41: camera focus_on is for type thin_lens", 1},
    {"focus_on_and_distance",
     "camera: {type: thin_lens, position: [0, 0, 6], focus_on: [0, 0, 0], focus_distance: 2}\n",
     "bad.yaml:1:58: camera takes focus_on or focus_distance, not both", 1},
    {"aperture_and_f_number",
     "camera: {type: thin_lens, position: [0, 0, 6], aperture: 0.1, f_number: 2.8}\n",
     "bad.yaml:1:9: camera takes aperture or f_number, not both (aperture is the lens's radius, f_number the same "
     "size as a photographer gives it)", 1},
    {"sensor_width_alone",
     "camera: {type: thin_lens, position: [0, 0, 6], sensor_width: 0.024}\n",
     "bad.yaml:1:9: camera sensor_width only sizes the lens of an f_number: give f_number too, or leave "
     "sensor_width out", 1},
    {"f_number_pinhole",
     "camera: {position: [0, 0, 6], f_number: 2}\n",
     "bad.yaml:1:9: camera f_number is for type thin_lens, and this camera is a pinhole", 1},
    {"focus_on_behind",
     "camera: {type: thin_lens, position: [0, 0, 6], look_at: [0, 0, 0], focus_on: [0, 0, 9]}\n",
     "bad.yaml:1:78: camera focus_on must lie in front of the camera (its depth along the view is -3)", 1},
    {"light_type_no_hint",
     "lights:\n"
     "  - {type: area}\n",
     "bad.yaml:2:12: 'type' must be point, spot, directional, sphere, rectangle or disk, got 'area'", 1},
    {"texture_type_no_hint",
     "textures:\n"
     "  t: {type: noise}\n",
     "bad.yaml:2:13: 'type' must be checker or image, got 'noise'", 1},
    {"mapping_hint",
     "textures:\n"
     "  t: {type: checker, mapping: sphericl}\n",
     "bad.yaml:2:31: 'mapping' must be uv, planar, spherical or cylindrical, got 'sphericl' (did you mean 'spherical'?)", 1},
    {"version_2",
     "glint: 2\n",
     "bad.yaml:1:8: format version 2 is not supported (this glint reads version 1)", 1},
    {"version_text",
     "glint: one\n",
     "bad.yaml:1:8: 'glint' must be a number, got 'one'", 1},
    {"output_not_image",
     "settings:\n"
     "  output: render.bmp\n",
     "bad.yaml:2:11: 'output' must name a .png, .ppm or .exr file, got 'render.bmp'", 1},
    {"radius_nan",
     "materials:\n"
     "  m: {}\n"
     "objects:\n"
     "  - {type: sphere, material: m, radius: .nan}\n",
     "bad.yaml:4:41: 'radius' must be a finite number, got '.nan'", 1},
    {"radius_inf",
     "materials:\n"
     "  m: {}\n"
     "objects:\n"
     "  - {type: sphere, material: m, radius: .inf}\n",
     "bad.yaml:4:41: 'radius' must be a finite number, got '.inf'", 1},
    {"fov_negative_inf",
     "camera:\n"
     "  fov: -.inf\n",
     "bad.yaml:2:8: 'fov' must be a finite number, got '-.inf'", 1},
    {"ambient_NaN",
     "materials:\n"
     "  m: {ambient: .NaN}\n",
     "bad.yaml:2:16: 'ambient' must be a finite number, got '.NaN'", 1},
    {"vector_with_inf",
     "camera:\n"
     "  position: [0, .inf, 0]\n",
     "bad.yaml:2:13: 'position' must be a list of 3 finite numbers [x, y, z]", 1},
    {"unknown_material_hint",
     "materials:\n"
     "  marble: {}\n"
     "objects:\n"
     "  - {type: sphere, material: marbel, radius: 1}\n",
     "bad.yaml:4:30: unknown material 'marbel' (did you mean 'marble'?)", 1},
    {"unknown_material",
     "materials:\n"
     "  marble: {}\n"
     "objects:\n"
     "  - {type: sphere, material: granite, radius: 1}\n",
     "bad.yaml:4:30: unknown material 'granite'", 1},
    {"unknown_texture_hint",
     "textures:\n"
     "  checks: {type: checker}\n"
     "materials:\n"
     "  m: {texture: chekcs}\n",
     "bad.yaml:4:16: unknown texture 'chekcs' (did you mean 'checks'?)", 1},
    {"unknown_texture",
     "materials:\n"
     "  m: {texture: wood}\n",
     "bad.yaml:2:16: unknown texture 'wood'", 1},
    {"texture_file_missing",
     "textures:\n"
     "  moon: {type: image, file: no-such-moon.png}\n",
     "bad.yaml:2:29: cannot open texture 'no-such-moon.png': No such file or directory", 1},
    {"include_missing",
     "include: no-such-part.yaml\n",
     "bad.yaml:1:10: cannot include 'no-such-part.yaml': No such file or directory", 1},
    {"include_not_text",
     "include: [{file: a.yaml}]\n",
     "bad.yaml:1:11: 'include' must name files, got a map", 1},
    {"duplicate_material",
     "materials:\n"
     "  m: {}\n"
     "  m: {ambient: 0.5}\n",
     "bad.yaml:3:6: material 'm' is defined twice", 1},
    {"duplicate_texture",
     "textures:\n"
     "  t: {type: checker}\n"
     "  t: {type: checker, size: 2}\n",
     "bad.yaml:3:6: texture 't' is defined twice", 1},
    {"polygon_collinear",
     "materials:\n"
     "  m: {}\n"
     "objects:\n"
     "  - {type: polygon, material: m, points: [[0, 0, 0], [1, 1, 1], [2, 2, 2]]}\n",
     "bad.yaml:4:5: polygon points are collinear", 1},
    {"polygon_non_planar",
     "materials:\n"
     "  m: {}\n"
     "objects:\n"
     "  - {type: polygon, material: m, points: [[0, 0, 0], [1, 0, 0], [1, 1, 0], [0, 1, 0.5]]}\n",
     "bad.yaml:4:5: polygon is not planar", 1},
    {"polygon_not_convex",
     "materials:\n"
     "  m: {}\n"
     "objects:\n"
     "  - {type: polygon, material: m, points: [[0, 0, 0], [2, 0, 0], [0.5, 0.5, 0], [0, 2, 0]]}\n",
     "bad.yaml:4:5: polygon is not convex", 1},
    {"polygon_five_points",
     "materials:\n"
     "  m: {}\n"
     "objects:\n"
     "  - {type: polygon, material: m, points: [[0, 0, 0], [1, 0, 0], [1, 1, 0], [0, 1, 0], [0, 0.5, 0]]}\n",
     "bad.yaml:4:42: 'points' must hold 3 or 4 points, got 5", 1},
    {"polygon_two_points",
     "materials:\n"
     "  m: {}\n"
     "objects:\n"
     "  - {type: polygon, material: m, points: [[0, 0, 0], [1, 0, 0]]}\n",
     "bad.yaml:4:42: 'points' must hold 3 or 4 points, got 2", 1},
    {"polygon_points_coincide",
     "materials:\n"
     "  m: {}\n"
     "objects:\n"
     "  - {type: polygon, material: m, points: [[0, 0, 0], [0, 0, 0], [1, 1, 0]]}\n",
     "bad.yaml:4:5: polygon points 0 and 1 coincide", 1},
    {"box_min_equals_max",
     "materials:\n"
     "  m: {}\n"
     "objects:\n"
     "  - {type: box, material: m, min: [0, 0, 0], max: [1, 0, 1]}\n",
     "bad.yaml:4:5: box min must be below max on every axis", 1},
    {"box_min_above_max",
     "materials:\n"
     "  m: {}\n"
     "objects:\n"
     "  - {type: box, material: m, min: [2, 2, 2], max: [1, 1, 1]}\n",
     "bad.yaml:4:5: box min must be below max on every axis", 1},
    {"disk_hole_too_big",
     "materials:\n"
     "  m: {}\n"
     "objects:\n"
     "  - {type: disk, material: m, radius: 1, inner_radius: 1.5}\n",
     "bad.yaml:4:5: disk inner_radius must be below its radius 1, got 1.5", 1},
    {"disk_every_problem",
     "materials:\n"
     "  m: {}\n"
     "objects:\n"
     "  - {type: disk, material: m, radius: -1, inner_radius: -2, normal: [0, 0, 0]}\n",
     "bad.yaml:4:69: 'normal' must not be zero", 3},
    {"plane_normal_zero",
     "materials:\n"
     "  m: {}\n"
     "objects:\n"
     "  - {type: plane, material: m, normal: [0, 0, 0]}\n",
     "bad.yaml:4:40: 'normal' must not be zero", 1},
    {"scale_zero_vector",
     "materials:\n"
     "  m: {}\n"
     "objects:\n"
     "  - {type: sphere, material: m, radius: 1, transform: [{scale: [1, 0, 1]}]}\n",
     "bad.yaml:4:64: 'scale' must not be zero", 1},
    {"scale_zero_number",
     "materials:\n"
     "  m: {}\n"
     "objects:\n"
     "  - {type: sphere, material: m, radius: 1, transform: [{scale: 0}]}\n",
     "bad.yaml:4:64: 'scale' must not be zero", 1},
    {"rotate_axis_zero",
     "materials:\n"
     "  m: {}\n"
     "objects:\n"
     "  - {type: sphere, material: m, radius: 1, transform: [{rotate: {axis: [0, 0, 0], angle: 45}}]}\n",
     "bad.yaml:4:72: 'axis' must not be zero", 1},
    {"transform_step_hint",
     "materials:\n"
     "  m: {}\n"
     "objects:\n"
     "  - {type: sphere, material: m, radius: 1, transform: [{translat: [1, 2, 3]}]}\n",
     "bad.yaml:4:57: 'transform step' must be translate, rotate, rotate_x, rotate_y, rotate_z, scale or matrix, got 'translat' (did you mean 'translate'?)", 1},
    {"transform_step_two_keys",
     "materials:\n"
     "  m: {}\n"
     "objects:\n"
     "  - {type: sphere, material: m, radius: 1, transform: [{translate: [1, 2, 3], scale: 2}]}\n",
     "bad.yaml:4:56: each transform step is a map with one key: translate, rotate, rotate_x, rotate_y, rotate_z, scale or matrix", 1},
    {"planar_mapping_one_axis",
     "textures:\n"
     "  t: {type: checker, mapping: {type: planar, u_axis: [1, 0, 0]}}\n",
     "bad.yaml:2:31: a planar mapping needs both 'u_axis' and 'v_axis', or neither", 1},
    {"merge_key_not_map",
     "materials:\n"
     "  m: {<<: 5, ambient: 0.5}\n",
     "bad.yaml:2:11: a merge key (<<) needs a map or a list of maps", 1},
    {"material_name_not_word",
     "materials:\n"
     "  [a, b]: {}\n",
     "bad.yaml:2:3: a name in 'materials' must be a word, got a list", 1},
    {"three_problems",
     "settings:\n"
     "  width: 0\n"
     "  height: -1\n"
     "  samples: 3\n",
     "bad.yaml:2:10: 'width' must be a whole number from 1 to 65536, got '0'", 3},
    {"problems_in_three_sections",
     "settings:\n"
     "  depth: 100\n"
     "camera:\n"
     "  fov: 400\n"
     "materials:\n"
     "  m: {ambient: 7}\n",
     "bad.yaml:2:10: 'depth' must be a whole number from 0 to 64, got '100'", 3},
    {"duplicate_key_in_object",
     "materials:\n"
     "  m: {}\n"
     "objects:\n"
     "  - {type: sphere, material: m, radius: 1, radius: 2}\n",
     "bad.yaml:4:44: duplicate key 'radius' in sphere", 1},
    {"duplicate_root_key",
     "settings:\n"
     "  width: 10\n"
     "settings:\n"
     "  width: 20\n",
     "bad.yaml:3:1: duplicate key 'settings' in the scene", 1},
    {"duplicate_key_in_settings",
     "settings:\n"
     "  width: 10\n"
     "  height: 10\n"
     "  width: 20\n",
     "bad.yaml:4:3: duplicate key 'width' in settings", 1},
    {"directional_light_with_position",
     "lights:\n"
     "  - {type: directional, direction: [0, -1, 0], position: [1, 2, 3]}\n",
     "bad.yaml:2:48: unknown key 'position' in a directional light", 1},
    {"point_light_with_angle",
     "lights:\n"
     "  - {type: point, position: [0, 1, 0], angle: 30}\n",
     "bad.yaml:2:40: unknown key 'angle' in a point light", 1},
    {"point_light_with_direction_hint",
     "lights:\n"
     "  - {type: point, position: [0, 1, 0], direction: [0, -1, 0]}\n",
     "bad.yaml:2:40: unknown key 'direction' in a point light", 1},
    {"checker_with_file",
     "textures:\n"
     "  t: {type: checker, file: checks.png}\n",
     "bad.yaml:2:22: unknown key 'file' in texture 't'", 1},
    {"image_with_colors",
     "textures:\n"
     "  t: {type: image, colors: [[0, 0, 0], [1, 1, 1]], file: @TMP@/one.png}\n",
     "bad.yaml:2:20: unknown key 'colors' in texture 't'", 1},
    {"spherical_mapping_with_scale",
     "textures:\n"
     "  t: {type: checker, mapping: {type: spherical, scale: 2}}\n",
     "bad.yaml:2:49: unknown key 'scale' in a spherical mapping", 1},
    {"cylindrical_mapping_with_axis",
     "textures:\n"
     "  t: {type: checker, mapping: {type: cylindrical, u_axis: [1, 0, 0]}}\n",
     "bad.yaml:2:51: unknown key 'u_axis' in a cylindrical mapping", 1},
    {"fog_needs_type",
     "fog:\n"
     "  color: [1, 1, 1]\n"
     "  density: 0.5\n",
     "bad.yaml:2:3: fog needs 'type'", 1},
    {"linear_fog_needs_start_and_end",
     "fog:\n"
     "  type: linear\n"
     "  end: 10\n",
     "bad.yaml:2:3: linear fog needs 'start' and 'end'", 1},
    {"exponential_fog_needs_density",
     "fog:\n"
     "  type: exponential\n"
     "  color: [1, 1, 1]\n",
     "bad.yaml:2:3: exponential fog needs 'density'", 1},
    {"display_colour_above_1",
     "materials:\n"
     "  m: {color: [1.5, 0, 0]}\n",
     "bad.yaml:2:14: 'color' channels must be from 0 to 1 (a light's 'intensity' makes it brighter)", 1},
    {"light_colour_above_1",
     "lights:\n"
     "  - {type: point, position: [0, 1, 0], color: [2, 2, 2]}\n",
     "bad.yaml:2:47: 'color' channels must be from 0 to 1 (a light's 'intensity' makes it brighter)", 1},
    {"planar_mapping_parallel_axes",
     "textures:\n"
     "  t: {type: checker, mapping: {type: planar, u_axis: [1, 0, 0], v_axis: [2, 0, 0]}}\n",
     "bad.yaml:2:6: planar mapping axes must not be parallel", 1},
    {"misspelt_required_key",
     "materials:\n"
     "  m: {}\n"
     "objects:\n"
     "  - {type: sphere, material: m, raduis: 1}\n",
     "bad.yaml:4:33: unknown key 'raduis' in sphere (did you mean 'radius'?)", 2},
    /* "Did you mean": another spelling, a word cut short, another ending;
     * nothing when the start fits several words. */
    {"hint_other_spelling",
     "materials: {m: {}}\n"
     "objects:\n"
     "  - {type: sphere, radius: 1, material: m, transform: [{rotateY: 30}]}\n",
     "bad.yaml:3:57: 'transform step' must be translate, rotate, rotate_x, rotate_y, rotate_z, scale or matrix, got 'rotateY' (did you mean 'rotate_y'?)", 1},
    {"hint_cut_short",
     "camera: {pos: [0, 1, 5]}\n",
     "bad.yaml:1:10: unknown key 'pos' in camera (did you mean 'position'?)", 1},
    {"hint_other_ending",
     "textures:\n"
     "  t: {type: checker, mapping: cylinder}\n",
     "bad.yaml:2:31: 'mapping' must be uv, planar, spherical or cylindrical, got 'cylinder' (did you mean 'cylindrical'?)", 1},
    {"hint_none_for_several",
     "materials: {m: {}}\n"
     "objects:\n"
     "  - {type: sphere, radius: 1, material: m, transform: [{rot: 30}]}\n",
     "bad.yaml:3:57: 'transform step' must be translate, rotate, rotate_x, rotate_y, rotate_z, scale or matrix, got 'rot'", 1},
    /* A value in quotes is text; when it would be right without them, the
     * message says so. */
    {"quoted_number",
     "materials: {m: {}}\n"
     "objects:\n"
     "  - {type: sphere, radius: \"2\", material: m}\n",
     "bad.yaml:3:28: 'radius' must be a number, got '2' in quotes, which is text: write 2 without quotes", 1},
    {"quoted_whole_number",
     "settings: {width: \"320\"}\n",
     "bad.yaml:1:19: 'width' must be a whole number from 1 to 65536, got '320' in quotes, which is text: write 320 without quotes", 1},
    {"quoted_whole_number_out_of_range",
     "settings: {width: \"0\"}\n",
     "bad.yaml:1:19: 'width' must be a whole number from 1 to 65536, got '0' in quotes, which is text", 1},
    {"quoted_text_for_a_bool",
     "materials: {m: {fresnel: \"yes\"}}\n",
     "bad.yaml:1:26: 'fresnel' must be true or false, got 'yes' in quotes, which is text", 1},
    /* '#' starts a comment: a colour without quotes, in a flow map (libyaml
     * stumbles on a later line) or a block one (the value is empty). */
    {"hash_colour_in_flow_map",
     "materials:\n"
     "  m: {ambient: 0.1, color: #0000ff}\n",
     "bad.yaml:2:28: '#' starts a comment in YAML: write the colour in quotes, color: \"#0000ff\"", 1},
    {"hash_colour_in_flow_list",
     "textures:\n"
     "  t: {type: checker, colors: [\"#ffffff\", #000]}\n",
     "bad.yaml:2:42: '#' starts a comment in YAML: write the colour in quotes, \"#000\"", 1},
    {"hash_colour_in_block_map",
     "materials:\n"
     "  m:\n"
     "    color:   #ff8800   \n"
     "    ambient: 0.1\n",
     "bad.yaml:3:14: '#' starts a comment in YAML: write the colour in quotes, color: \"#ff8800\"", 1},
    /* A '#' in quotes is no comment; a comment that is no colour leaves
     * libyaml's words. */
    {"hash_in_quotes_then_syntax_error",
     "materials:\n"
     "  m: {color: \"#0000ff\", ambient: 0.1 ]\n",
     "bad.yaml:2:38: syntax error: did not find expected ',' or '}' while parsing a flow mapping", 1},
    {"hash_comment_then_syntax_error",
     "materials:\n"
     "  m: {color: [1, 1, 1],  # red\n"
     "      ambient: 0.1 ]\n",
     "bad.yaml:3:20: syntax error: did not find expected ',' or '}' while parsing a flow mapping", 1},
    {"hash_comment_empty_value",
     "camera:\n"
     "  fov: # later\n",
     "bad.yaml:2:7: 'fov' must be a number, got nothing", 1},
    /* A tab in the indentation, nested deeper; a tab after a value is fine
     * and only the bad key is reported. */
    {"tab_indent_nested",
     "materials:\n"
     "  m:\n"
     "  \tcolor: [1, 1, 1]\n",
     "bad.yaml:3:3: YAML forbids tabs for indentation: indent with spaces", 1},
    {"tab_after_value",
     "settings:\n"
     "  widht:\t10\n",
     "bad.yaml:2:3: unknown key 'widht' in settings (did you mean 'width'?)", 1},
    /* An alias before its anchor, each named once in the file. */
    {"alias_before_its_anchor",
     "materials:\n"
     "  a: *shiny\n"
     "  b: &shiny {specular: 1}\n",
     "bad.yaml:2:6: unknown anchor 'shiny': '&shiny' comes later, at line 3, and an anchor must come before its aliases", 1},
};

static void test_bad_scene(void **state)
{
    const bad_scene *b = *state;
    char yaml[4096], want[1024];
    with_tmp(b->yaml, yaml, sizeof yaml);
    with_tmp(b->first, want, sizeof want);
    report_log log = {0};
    glint_error err = {0};
    load_bad(yaml, 0, &log, &err);
    if (strcmp(log.first, want) != 0 || log.count != b->problems)
        fail_msg("%s:\n%s\nexpected %d problem(s), first:\n  %s\ngot %d:\n%s", b->name, yaml, b->problems, want,
                 log.count, log.all);
}

/* Without a report callback, or without options at all, err still gets the
 * first problem; with no err the load still fails cleanly. */
static void test_problems_without_a_report(void **state)
{
    const char *yaml = "settings:\n  width: 0\n  depth: 99\n";
    glint_error err = {0};
    glint_load_options o = {0};
    assert_null(glint_scene_load_memory(yaml, strlen(yaml), "bad.yaml", &o, &err));
    assert_string_equal(err.message, "bad.yaml:2:10: 'width' must be a whole number from 1 to 65536, got '0'");
    memset(&err, 0, sizeof err);
    assert_null(glint_scene_load_memory(yaml, strlen(yaml), "bad.yaml", NULL, &err));
    assert_string_equal(err.message, "bad.yaml:2:10: 'width' must be a whole number from 1 to 65536, got '0'");
    assert_null(glint_scene_load_memory(yaml, strlen(yaml), "bad.yaml", NULL, NULL));
    /* A NULL name stands as "<memory>". */
    assert_null(glint_scene_load_memory(yaml, strlen(yaml), NULL, NULL, &err));
    assert_string_equal(err.message, "<memory>:2:10: 'width' must be a whole number from 1 to 65536, got '0'");
}

/* Every problem is reported, in the order of the file. */
static void test_every_problem_in_order(void **state)
{
    report_log log = {0};
    glint_error err = {0};
    load_bad("settings:\n"
             "  width: 0\n"
             "  sampler: jitterd\n"
             "camera: {fov: 0}\n"
             "materials:\n"
             "  m: {ambient: 2, colour: [1, 1, 1]}\n"
             "lights:\n"
             "  - {type: spot}\n"
             "objects:\n"
             "  - {type: sphere, material: m, radius: -1}\n"
             "  - {type: box, material: m, min: [1, 1, 1], max: [0, 0, 0]}\n",
             0, &log, &err);
    assert_string_equal(log.all, "bad.yaml:2:10: 'width' must be a whole number from 1 to 65536, got '0'\n"
                                 "bad.yaml:3:12: 'sampler' must be regular, jittered or sobol, got 'jitterd' (did you mean 'jittered'?)\n"
                                 "bad.yaml:4:15: 'fov' must be more than 0 and at most 360 degrees, got 0\n"
                                 "bad.yaml:6:19: unknown key 'colour' in material 'm' (did you mean 'color'?)\n"
                                 "bad.yaml:6:16: 'ambient' must be from 0 to 1, got 2\n"
                                 "bad.yaml:8:5: a spot light needs 'position'\n"
                                 "bad.yaml:8:5: a spot light needs 'direction'\n"
                                 "bad.yaml:8:5: a spot light needs 'angle'\n"
                                 "bad.yaml:10:41: 'radius' must be positive, got -1\n"
                                 "bad.yaml:11:5: box min must be below max on every axis\n");
    assert_int_equal(log.count, 10);
}

/* One bad value does not hide another of the same object: each key's,
 * each transform step's and the material's problem is reported, and the
 * object is not added. A group's bad material is not reported again at
 * each object inside it, nor a bad crease angle hides a missing model. */
static void test_every_problem_of_an_object(void **state)
{
    report_log log = {0};
    glint_error err = {0};
    load_bad("materials:\n"
             "  steel: {}\n"
             "textures:\n"
             "  t: {type: checker, mapping: spherica, size: -1}\n"
             "objects:\n"
             "  - {type: cylinder, radius: -1, height: -1, capped: \"false\", material: stell,\n"
             "     transform: [{rotatey: 30}, {scale: 0}, {rotate: {}}]}\n"
             "  - type: group\n"
             "    material: nothing\n"
             "    transform: [{spin: 1}]\n"
             "    objects:\n"
             "      - {type: sphere, radius: 0}\n"
             "      - {type: sphere, radius: 1}\n"
             "  - {type: mesh, file: missing.obj, crease_angle: 200, transform: [{scale: [1, 0, 1]}]}\n",
             0, &log, &err);
    assert_string_equal(log.all,
                        "bad.yaml:4:31: 'mapping' must be uv, planar, spherical or cylindrical, got 'spherica' (did you mean 'spherical'?)\n"
                        "bad.yaml:4:47: 'size' must be positive, got -1\n"
                        "bad.yaml:7:19: 'transform step' must be translate, rotate, rotate_x, rotate_y, rotate_z, scale or matrix, got 'rotatey' (did you mean 'rotate_y'?)\n"
                        "bad.yaml:7:41: 'scale' must not be zero\n"
                        "bad.yaml:7:54: rotate needs 'axis'\n"
                        "bad.yaml:7:54: rotate needs 'angle'\n"
                        "bad.yaml:6:73: unknown material 'stell' (did you mean 'steel'?)\n"
                        "bad.yaml:6:30: 'radius' must be positive, got -1\n"
                        "bad.yaml:6:42: 'height' must be positive, got -1\n"
                        "bad.yaml:6:54: 'capped' must be true or false, got 'false' in quotes, which is text: write false without quotes\n"
                        "bad.yaml:10:18: 'transform step' must be translate, rotate, rotate_x, rotate_y, rotate_z, scale or matrix, got 'spin'\n"
                        "bad.yaml:9:15: unknown material 'nothing'\n"
                        "bad.yaml:12:32: 'radius' must be positive, got 0\n"
                        "bad.yaml:14:76: 'scale' must not be zero\n"
                        "bad.yaml:14:51: 'crease_angle' must be from 0 to 180 degrees, got 200\n"
                        "bad.yaml:14:24: cannot read model 'missing.obj': No such file or directory\n");
    assert_int_equal(log.count, 16);
}

/* 25 problems: the default stops at 20 reported, max_errors at its own. */
static void test_max_errors(void **state)
{
    char yaml[2048] = "glint: 1\n";
    for (int i = 1; i <= 25; i++)
        snprintf(yaml + strlen(yaml), sizeof yaml - strlen(yaml), "unknown%d: %d\n", i, i);
    report_log log = {0};
    glint_error err = {0};
    load_bad(yaml, 0, &log, &err);
    assert_int_equal(log.count, 20);
    assert_string_equal(log.first, "bad.yaml:2:1: unknown key 'unknown1' in the scene");
    assert_non_null(strstr(log.all, "bad.yaml:21:1: unknown key 'unknown20' in the scene\n"));
    assert_null(strstr(log.all, "unknown21"));

    int limits[] = {1, 3, 25, 100};
    int want[] = {1, 3, 25, 25};
    for (size_t i = 0; i < COUNT(limits); i++) {
        report_log l = {0};
        load_bad(yaml, limits[i], &l, &err);
        assert_int_equal(l.count, want[i]);
        assert_string_equal(l.first, "bad.yaml:2:1: unknown key 'unknown1' in the scene");
    }
    /* Problems found anywhere count towards the limit, not only one kind. */
    report_log l = {0};
    load_bad("settings: {width: 0, height: 0}\ncamera: {fov: 0}\nfog: {type: foggy}\n", 2, &l, &err);
    assert_int_equal(l.count, 2);
    assert_string_equal(l.all, "bad.yaml:1:19: 'width' must be a whole number from 1 to 65536, got '0'\n"
                               "bad.yaml:1:30: 'height' must be a whole number from 1 to 65536, got '0'\n");
}

static void load_bad_file(const char *name, report_log *log, glint_error *err)
{
    char path[PATH_SIZE];
    tmp_path(path, name);
    glint_load_options o = {.report = log_report, .report_user = log};
    glint_scene *s = glint_scene_load_file(path, &o, err);
    if (s) {
        glint_scene_free(s);
        fail_msg("%s loaded", path);
    }
    assert_string_equal(err->message, log->first);
}

/* An alias names only an anchor of its own file: one in another file, in
 * either direction of an include, is named in the message. */
static void test_anchors_do_not_cross_files(void **state)
{
    write_tmp("anchors/main.yaml", "include: parts/wood.yaml\n"
                                   "materials:\n"
                                   "  steel: &steel {specular: 1}\n"
                                   "objects:\n"
                                   "  - {type: sphere, radius: 1, material: *wood}\n"
                                   "  - {type: sphere, radius: 1, material: *glass}\n");
    write_tmp("anchors/parts/wood.yaml", "materials:\n"
                                         "  wood: &wood {color: [0.5, 0.3, 0.1]}\n"
                                         "  bolt: *steel\n");
    report_log log = {0};
    glint_error err = {0};
    load_bad_file("anchors/main.yaml", &log, &err);
    char want[5 * PATH_SIZE + 400];
    snprintf(want, sizeof want,
             "%s/anchors/parts/wood.yaml:3:9: unknown anchor 'steel': anchors do not cross files (it is defined "
             "in %s/anchors/main.yaml)\n"
             "%s/anchors/main.yaml:5:41: unknown anchor 'wood': anchors do not cross files (it is defined in "
             "%s/anchors/parts/wood.yaml)\n"
             "%s/anchors/main.yaml:6:41: unknown anchor 'glass': no '&glass' comes before it in this file (anchors "
             "do not cross files)\n",
             tmp_dir, tmp_dir, tmp_dir, tmp_dir, tmp_dir);
    assert_string_equal(log.all, want);
    assert_int_equal(log.count, 3);
}

static void test_include_cycle(void **state)
{
    write_tmp("cycle/a.yaml", "glint: 1\ninclude: b.yaml\n");
    write_tmp("cycle/b.yaml", "include: [a.yaml]\n");
    report_log log = {0};
    glint_error err = {0};
    load_bad_file("cycle/a.yaml", &log, &err);
    char want[PATH_SIZE + 100];
    snprintf(want, sizeof want, "%s/cycle/b.yaml:1:11: include cycle: a.yaml -> b.yaml -> a.yaml", tmp_dir);
    assert_string_equal(log.first, want);
    assert_int_equal(log.count, 1);

    write_tmp("cycle/self.yaml", "include: self.yaml\n");
    report_log self = {0};
    load_bad_file("cycle/self.yaml", &self, &err);
    snprintf(want, sizeof want, "%s/cycle/self.yaml:1:10: include cycle: self.yaml -> self.yaml", tmp_dir);
    assert_string_equal(self.first, want);
    assert_int_equal(self.count, 1);
}

/* Includes that fan out (each file a list of files) are bounded as a whole:
 * 40 x 40 empty includes would be 1600 files. */
static void test_include_fan_out_is_bounded(void **state)
{
    char list[40 * 12 + 32] = "include: [";
    for (int i = 0; i < 40; i++)
        strcat(list, i ? ", e.yaml" : "e.yaml");
    strcat(list, "]\n");
    write_tmp("fan/e.yaml", "");
    write_tmp("fan/f.yaml", list);
    strcpy(list, "include: [");
    for (int i = 0; i < 40; i++)
        strcat(list, i ? ", f.yaml" : "f.yaml");
    strcat(list, "]\n");
    write_tmp("fan/g.yaml", list);
    report_log log = {0};
    glint_error err = {0};
    load_bad_file("fan/g.yaml", &log, &err);
    char want[PATH_SIZE + 100];
    snprintf(want, sizeof want, "%s/fan/f.yaml:1:", tmp_dir);
    assert_true(strncmp(log.first, want, strlen(want)) == 0);
    assert_non_null(strstr(log.first, ": too many included files (limit 1000)"));
    assert_int_equal(log.count, 1);
}

/* Including one file twice side by side is no cycle, but it defines its
 * names twice. */
static void test_include_twice(void **state)
{
    write_tmp("twice/main.yaml", "include: [mats.yaml, mats.yaml]\n");
    write_tmp("twice/mats.yaml", "materials:\n  m: {}\n");
    report_log log = {0};
    glint_error err = {0};
    load_bad_file("twice/main.yaml", &log, &err);
    char want[PATH_SIZE + 100];
    snprintf(want, sizeof want, "%s/twice/mats.yaml:2:6: material 'm' is defined twice", tmp_dir);
    assert_string_equal(log.first, want);
    assert_int_equal(log.count, 1);
}

static void test_includes_nested_too_deep(void **state)
{
    for (int i = 0; i < 20; i++) {
        char name[64], text[64];
        snprintf(name, sizeof name, "deep/f%d.yaml", i);
        snprintf(text, sizeof text, "include: f%d.yaml\n", i + 1);
        write_tmp(name, text);
    }
    write_tmp("deep/f20.yaml", "glint: 1\n");
    report_log log = {0};
    glint_error err = {0};
    load_bad_file("deep/f0.yaml", &log, &err);
    char want[PATH_SIZE + 100];
    snprintf(want, sizeof want, "%s/deep/f15.yaml:1:10: includes nested too deep (limit 16)", tmp_dir);
    assert_string_equal(log.first, want);
    assert_int_equal(log.count, 1);
}

static void test_missing_scene_file(void **state)
{
    report_log log = {0};
    glint_error err = {0};
    load_bad_file("no-such-scene.yaml", &log, &err);
    char want[PATH_SIZE + 100];
    snprintf(want, sizeof want, "cannot read scene '%s/no-such-scene.yaml': No such file or directory", tmp_dir);
    assert_string_equal(log.first, want);
    assert_int_equal(log.count, 1);
    /* The error carries the kind of failure too: the file could not be read. */
    assert_int_equal(err.status, GLINT_ERR_IO);
}

/* A refused scene's error says what kind of failure its first problem was,
 * as the CLI needs to tell bad input from memory running out. */
static void test_error_status_of_first_problem(void **state)
{
    glint_error err = {0};
    glint_load_options lo = {0};
    assert_null(glint_scene_load_memory("objects: [", 10, "bad.yaml", &lo, &err));
    assert_int_equal(err.status, GLINT_ERR_INVALID);
    err.status = GLINT_OK;
    glint_scene *s = glint_scene_new();
    assert_int_equal(glint_scene_add_shape(s, &(glint_shape){.kind = GLINT_SHAPE_SPHERE, .radius = 1}, 3, NULL, &err),
                     -1);
    assert_int_equal(err.status, GLINT_ERR_INVALID);
    assert_string_equal(err.message, "material 3 does not exist");
    glint_scene_free(s);
    /* A call the loader makes keeps its own status: a texture file that is
     * not there is an I/O problem, reported where the file is named. */
    const char *missing = "textures: {t: {type: image, file: no-such-picture.png}}\n";
    assert_null(glint_scene_load_memory(missing, strlen(missing), "bad.yaml", &lo, &err));
    assert_int_equal(err.status, GLINT_ERR_IO);
    assert_non_null(strstr(err.message, "bad.yaml:1:35: cannot open texture"));
}

/* Groups nest through aliases without nesting in the text. */
static void test_groups_nested_too_deep(void **state)
{
    char yaml[4096] = "materials: {m: {}}\nobjects:\n  - &g0 {type: sphere, material: m, radius: 1}\n";
    for (int i = 1; i <= 33; i++)
        snprintf(yaml + strlen(yaml), sizeof yaml - strlen(yaml), "  - &g%d {type: group, objects: [*g%d]}\n", i,
                 i - 1);
    report_log log = {0};
    glint_error err = {0};
    load_bad(yaml, 0, &log, &err);
    assert_string_equal(log.first, "bad.yaml:4:5: groups nested too deep (limit 32)");
    assert_int_equal(log.count, 1);
}

static double seconds_now(void)
{
    struct timespec ts;
    clock_gettime(CLOCK_MONOTONIC, &ts);
    return ts.tv_sec + ts.tv_nsec * 1e-9;
}

static long peak_kib(void)
{
    struct rusage ru;
    getrusage(RUSAGE_SELF, &ru);
    return ru.ru_maxrss;
}

/* A billion-laughs file: ten aliases of ten aliases ... nine levels deep
 * names 10^9 objects or lights. The parser must stop at the first alias
 * that takes what aliases add past the limit, with one problem, quickly
 * and in little memory. */
static void check_alias_bomb(const char *yaml, const char *first)
{
    report_log log = {0};
    glint_error err = {0};
    long before = peak_kib();
    double start = seconds_now();
    load_bad(yaml, 0, &log, &err);
    double seconds = seconds_now() - start;
    long grown = peak_kib() - before;
    if (seconds > 20 || grown > 512 * 1024)
        fail_msg("alias bomb took %.1f s and %ld KiB", seconds, grown);
    if (strcmp(log.first, first) != 0 || log.count != 1)
        fail_msg("expected 1 problem:\n  %s\ngot %d:\n%s", first, log.count, log.all);
}

static void test_alias_bomb_of_objects(void **state)
{
    char yaml[4096] = "materials: {m: {}}\nobjects:\n  - &l0 {type: sphere, material: m, radius: 1}\n";
    for (int i = 1; i <= 9; i++) {
        snprintf(yaml + strlen(yaml), sizeof yaml - strlen(yaml), "  - &l%d {type: group, objects: [", i);
        for (int k = 0; k < 10; k++)
            snprintf(yaml + strlen(yaml), sizeof yaml - strlen(yaml), "%s*l%d", k ? ", " : "", i - 1);
        snprintf(yaml + strlen(yaml), sizeof yaml - strlen(yaml), "]}\n");
    }
    /* Level k adds ten copies of 5 + 10 * (level k-1) nodes (l0: 7), 839,470
     * nodes by l5: the first alias of l6 passes the limit. */
    check_alias_bomb(yaml, "bad.yaml:9:33: scene too large after alias expansion (limit 1000000 nodes)");
}

/* Lights are a flat list, so the bomb goes through merge keys instead. */
static void test_alias_bomb_of_lights(void **state)
{
    char yaml[4096] = "lights:\n  - &l0 {type: point, position: [0, 0, 0]}\n";
    for (int i = 1; i <= 9; i++) {
        snprintf(yaml + strlen(yaml), sizeof yaml - strlen(yaml), "  - &l%d {<<: [", i);
        for (int k = 0; k < 10; k++)
            snprintf(yaml + strlen(yaml), sizeof yaml - strlen(yaml), "%s*l%d", k ? ", " : "", i - 1);
        snprintf(yaml + strlen(yaml), sizeof yaml - strlen(yaml), "]}\n");
    }
    check_alias_bomb(yaml, "bad.yaml:8:15: scene too large after alias expansion (limit 1000000 nodes)");
}

/* The limit counts what aliases add, exactly: one alias of a list of a
 * million nodes (the list and 999,999 items) is within it, of one node more
 * is not. The file's own nodes do not count: the list itself is allowed. */
static void test_alias_limit_counts_what_aliases_add(void **state)
{
    for (int more = 0; more <= 1; more++) {
        long items = 999999 + more;
        char *yaml = malloc((size_t)items * 2 + 64);
        assert_non_null(yaml);
        char *p = yaml + sprintf(yaml, "a: &big [");
        for (long i = 0; i < items; i++) {
            memcpy(p, i ? ",1" : "1", i ? 2 : 1);
            p += i ? 2 : 1;
        }
        sprintf(p, "]\nb: *big\n");
        report_log log = {0};
        glint_error err = {0};
        load_bad(yaml, 0, &log, &err);
        assert_string_equal(log.first, more ? "bad.yaml:2:4: scene too large after alias expansion (limit 1000000 nodes)"
                                            : "bad.yaml:1:1: unknown key 'a' in the scene");
        free(yaml);
    }
}

/* ------------------------------------- one report each, in the right words */

/* A texture that fails keeps its name known, as a material does: the
 * materials that use it get no second report. */
static void test_failed_texture_is_reported_once(void **state)
{
    const char *yamls[] = {
        "textures:\n  wood: {type: image, file: no-such-wood.png}\nmaterials:\n  m: {texture: wood}\n",
        "textures:\n  wood: {type: checker, size: -1}\nmaterials:\n  m: {texture: wood}\n",
    };
    const char *firsts[] = {
        "bad.yaml:2:29: cannot open texture 'no-such-wood.png': No such file or directory",
        "bad.yaml:2:31: 'size' must be positive, got -1",
    };
    for (size_t i = 0; i < COUNT(yamls); i++) {
        report_log log = {0};
        glint_error err = {0};
        load_bad(yamls[i], 0, &log, &err);
        assert_string_equal(log.first, firsts[i]);
        if (log.count != 1)
            fail_msg("expected 1 problem, got %d:\n%s", log.count, log.all);
    }
}

/* Every item of a merge list must be a map, not only the last. */
static void test_merge_list_of_non_maps(void **state)
{
    report_log log = {0};
    glint_error err = {0};
    load_bad("materials:\n  b: &b {color: [1, 0, 0]}\n  m: {<<: [3, *b]}\n", 0, &log, &err);
    assert_string_equal(log.first, "bad.yaml:3:12: a merge key (<<) needs a map or a list of maps");
    assert_int_equal(log.count, 1);
}

/* Merges nested past the limit say so, not that a map is not a map. */
static void test_merge_too_deep_says_so(void **state)
{
    char yaml[4096] = "materials:\n  m0: &m0 {color: [1, 0, 0]}\n";
    for (int i = 1; i <= 18; i++)
        snprintf(yaml + strlen(yaml), sizeof yaml - strlen(yaml), "  m%d: &m%d {<<: *m%d}\n", i, i, i - 1);
    report_log log = {0};
    glint_error err = {0};
    load_bad(yaml, 0, &log, &err);
    if (strstr(log.all, "needs a map") || !strstr(log.first, "deep"))
        fail_msg("expected a message about depth, got %d:\n%s", log.count, log.all);
}

/* ------------------------------------------- objects read while parsed */

/* What a load gave in one of the loader's modes (scenefile/scene_file.h):
 * the scene written back as a file, or what was reported. */
typedef struct outcome {
    char *written;            /* NULL when the scene was refused */
    report_log log;
    glint_error err;
} outcome;

/* Loads yaml, or the file tmp_dir/file when yaml is NULL, in mode m. */
static outcome load_in_mode(scene_file_mode m, const char *yaml, const char *file)
{
    outcome out = {0};
    glint_load_options o = {.report = log_report, .report_user = &out.log};
    char path[PATH_SIZE];
    scene_file_set_mode(m);
    glint_scene *s;
    if (yaml) {
        s = glint_scene_load_memory(yaml, strlen(yaml), "streamed.yaml", &o, &out.err);
    } else {
        tmp_path(path, file);
        s = glint_scene_load_file(path, &o, &out.err);
    }
    scene_file_set_mode(SCENE_FILE_STREAMED);
    if (s) {
        size_t size;
        FILE *f = open_memstream(&out.written, &size);
        assert_non_null(f);
        glint_error err;
        assert_int_equal(glint_scene_write_yaml(s, f, &err), GLINT_OK);
        assert_int_equal(fclose(f), 0);
        glint_scene_free(s);
    }
    return out;
}

/* Loads yaml (or tmp_dir/file) with its objects read while it is parsed,
 * the default, and from its whole tree: the same scene, written back byte
 * for byte, or the same reports, all of them. Then the streamed attempt
 * alone: it loads the same scene when `streams`, and otherwise gives up,
 * silently. Returns the whole tree's reports. */
static report_log check_streaming(const char *yaml, const char *file, bool streams)
{
    outcome whole = load_in_mode(SCENE_FILE_WHOLE, yaml, file);
    outcome dflt = load_in_mode(SCENE_FILE_STREAMED, yaml, file);
    outcome only = load_in_mode(SCENE_FILE_STREAMED_ONLY, yaml, file);
    assert_int_equal(!dflt.written, !whole.written);
    if (whole.written)
        assert_string_equal(dflt.written, whole.written);
    else
        assert_string_equal(dflt.err.message, whole.err.message);
    assert_string_equal(dflt.log.all, whole.log.all);
    if (streams && !only.written)
        fail_msg("the streamed attempt gave up: %s", only.err.message);
    if (!streams && only.written)
        fail_msg("the streamed attempt did not give up");
    if (streams)
        assert_string_equal(only.written, whole.written);
    assert_int_equal(only.log.count, 0);
    free(whole.written);
    free(dflt.written);
    free(only.written);
    return whole.log;
}

/* Every section, then the objects: read one by one as they are parsed,
 * to the very scene the whole tree gives. */
static void test_objects_streamed_after_every_section(void **state)
{
    const char *yaml = "glint: 1\n"
                       "settings: {width: 32, height: 24, background: [0.1, 0.2, 0.3]}\n"
                       "camera: {position: [0, 1, 9], look_at: [0, 0, 0]}\n"
                       "fog: {type: linear, start: 1, end: 30}\n"
                       "textures:\n  checks: {type: checker, size: 2}\n"
                       "materials:\n  m: {color: [1, 0, 0]}\n  t: {texture: checks, specular: 0.25}\n"
                       "lights:\n  - {type: point, position: [1, 5, 1]}\n"
                       "objects:\n"
                       "  - {type: sphere, material: m, center: [0, 1, 0], radius: 0.5}\n"
                       "  - type: box\n"
                       "    material: t\n"
                       "    min: [-1, -1, -1]\n"
                       "    max: [1, 0, 1]\n"
                       "    transform: [{rotate_y: 30}, {translate: [0, 0, -2]}]\n"
                       "  - {type: group, material: t, transform: [{scale: 2}], objects: [\n"
                       "      {type: sphere, radius: 0.25},\n"
                       "      {type: group, objects: [{type: cylinder, material: m, radius: 1, height: 2}]}]}\n"
                       "  - {type: plane, normal: [0, 1, 0], material: {color: \"#336699\"}}\n";
    check_streaming(yaml, NULL, true);
}

/* A section after the objects, which the whole tree reads before them:
 * the streamed attempt gives up (its objects named a material not yet
 * read, or a key followed them) and the scene loads as it always did. */
static void test_section_after_objects_loads_the_same(void **state)
{
    check_streaming("objects:\n  - {type: sphere, material: m, radius: 1}\n  - {type: sphere, material: m, radius: 2}\n"
                    "materials:\n  m: {color: [0, 1, 0]}\n",
                    NULL, false);
    check_streaming("materials: {m: {}}\nobjects:\n  - {type: sphere, material: m, radius: 1}\nlights:\n"
                    "  - {type: point, position: [0, 4, 0]}\n",
                    NULL, false);
    report_log log = check_streaming("materials: {m: {}}\nobjects: [{type: sphere, material: m, radius: 1}]\n"
                                     "objects: [{type: sphere, material: m, radius: 2}]\n",
                                     NULL, false);
    assert_string_equal(log.first, "streamed.yaml:3:1: duplicate key 'objects' in the scene");
}

/* A problem in the third object, a syntax error further on: the whole
 * tree reports only the syntax error, and so does the default; with two
 * problems in objects and no syntax error, both, in order. */
static void test_problems_in_streamed_objects(void **state)
{
    const char *head = "materials: {m: {}}\n"
                       "objects:\n"
                       "  - {type: sphere, material: m, radius: 1}\n"
                       "  - {type: sphere, material: m, radius: 1}\n"
                       "  - {type: sphere, material: nosuch, radius: 1}\n"
                       "  - {type: sphere, material: m, radius: 1}\n";
    char yaml[1024];
    snprintf(yaml, sizeof yaml, "%s  - {type: sphere, radius: [}\n  - {type: sphere, material: m, radius: 1}\n", head);
    report_log log = check_streaming(yaml, NULL, false);
    assert_int_equal(log.count, 1);
    assert_non_null(strstr(log.first, "streamed.yaml:7:"));
    assert_non_null(strstr(log.first, "syntax error"));
    snprintf(yaml, sizeof yaml, "%s  - {type: sphere, material: m, radius: -1}\n", head);
    log = check_streaming(yaml, NULL, false);
    assert_int_equal(log.count, 2);
    assert_string_equal(log.all, "streamed.yaml:5:30: unknown material 'nosuch'\n"
                                 "streamed.yaml:7:41: 'radius' must be positive, got -1\n");
}

/* Anchors in objects, aliased by later objects, among objects whose nodes
 * are given back: an object that defines an anchor is kept, whole or
 * only a part of it named; a name anchored again names the later node. */
static void test_anchors_in_streamed_objects(void **state)
{
    char *yaml = malloc(200000);
    assert_non_null(yaml);
    char *p = yaml + sprintf(yaml, "materials: {m: {}}\n"
                                   "objects:\n"
                                   "  - &ball {type: sphere, material: m, radius: 2}\n"
                                   "  - {type: sphere, material: m, radius: 1, center: &spot [1, 2, 3]}\n");
    for (int i = 0; i < 2000; i++)
        p += sprintf(p, "  - {type: box, material: m, min: [%d, 0, 0], max: [%d, 1, 1]}\n", i, i + 1);
    sprintf(p, "  - *ball\n"
               "  - {type: sphere, material: m, radius: 1, transform: [{translate: *spot}]}\n"
               "  - {type: group, objects: [*ball, {<<: *ball, radius: 3}]}\n"
               "  - &ball {type: sphere, material: m, radius: 4}\n"
               "  - *ball\n");
    check_streaming(yaml, NULL, true);
    free(yaml);
}

/* An include read while the including file is parsed defines the
 * materials of both files' objects; its own objects are streamed too. */
static void test_include_streamed(void **state)
{
    write_tmp("streamed/main.yaml", "include: parts/looks.yaml\n"
                                    "materials: {blue: {color: [0, 0, 1]}}\n"
                                    "objects:\n"
                                    "  - {type: sphere, material: red, radius: 1}\n"
                                    "  - {type: sphere, material: blue, radius: 1, center: [2, 0, 0]}\n");
    write_tmp("streamed/parts/looks.yaml", "materials:\n  red: {color: [1, 0, 0]}\n"
                                           "objects:\n  - {type: box, material: red, min: [0, 0, 0], max: [1, 1, 1]}\n");
    check_streaming(NULL, "streamed/main.yaml", true);
}

/* Writes a file whose objects are `count` aliases of one sphere of a
 * 1000-step transform: 6009 nodes each that the aliases add. */
static void write_aliased_spheres(const char *name, const char *head, int count)
{
    size_t room = 64000;
    char *text = malloc(room), *p = text;
    assert_non_null(text);
    p += sprintf(p, "%sobjects:\n  - &s {type: sphere, material: m, radius: 1, transform: [", head);
    for (int i = 0; i < 1000; i++)
        p += sprintf(p, "%s{translate: [0, 0, 0]}", i ? ", " : "");
    p += sprintf(p, "]}\n");
    for (int i = 0; i < count; i++)
        p += sprintf(p, "  - *s\n");
    assert_true((size_t)(p - text) < room);
    write_tmp(name, text);
    free(text);
}

/* The alias limit is the scene's: an include read while the including
 * file is parsed counts against it with what that file's aliases add
 * before and after. Each file alone is within the limit, both are not. */
static void test_alias_limit_while_streaming(void **state)
{
    write_aliased_spheres("alias-limit/main.yaml", "include: more.yaml\n", 90);
    write_aliased_spheres("alias-limit/more.yaml", "materials: {m: {}}\n", 90);
    report_log log = check_streaming(NULL, "alias-limit/main.yaml", false);
    assert_non_null(strstr(log.first, "more.yaml:80:5: scene too large after alias expansion"));
    write_aliased_spheres("alias-limit/main.yaml", "include: more.yaml\n", 60);
    check_streaming(NULL, "alias-limit/main.yaml", true);
}

/* Standard input is read once: a load that the streamed attempt gives up
 * reads its bytes again. */
static void test_stream_read_again(void **state)
{
    static char text[] = "objects: [{type: sphere, material: m, radius: 1}]\nmaterials: {m: {}}\n";
    FILE *in = fmemopen(text, strlen(text), "r");
    assert_non_null(in);
    glint_error err = {0};
    glint_scene *s = glint_scene_load_stream(in, "<stdin>", NULL, &err);
    if (!s)
        fail_msg("refused: %s", err.message);
    assert_int_equal(glint_scene_get_counts(s).shapes, 1);
    glint_scene_free(s);
    fclose(in);
}

/* ------------------------------------------------------------------ main */

int main(void)
{
    static const struct CMUnitTest fixed[] = {
        cmocka_unit_test(test_settings_every_key),
        cmocka_unit_test(test_settings_other_values),
        cmocka_unit_test(test_defaults_of_an_empty_scene),
        cmocka_unit_test(test_empty_file_holds_no_scene),
        cmocka_unit_test(test_load_stream),
        cmocka_unit_test(test_disk_ring),
        cmocka_unit_test(test_camera_every_key),
        cmocka_unit_test(test_fog_none),
        cmocka_unit_test(test_fog_linear),
        cmocka_unit_test(test_fog_exponential),
        cmocka_unit_test(test_checker_texture),
        cmocka_unit_test(test_mapping_as_a_word),
        cmocka_unit_test(test_mapping_as_a_map),
        cmocka_unit_test(test_image_texture_from_a_file),
        cmocka_unit_test(test_material_every_key),
        cmocka_unit_test(test_settings_ambient_occlusion),
        cmocka_unit_test(test_settings_filter_and_adaptive),
        cmocka_unit_test(test_environment),
        cmocka_unit_test(test_camera_focus_on),
        cmocka_unit_test(test_camera_f_number),
        cmocka_unit_test(test_lights),
        cmocka_unit_test(test_area_lights),
        cmocka_unit_test(test_sphere_and_plane),
        cmocka_unit_test(test_polygons),
        cmocka_unit_test(test_box_cylinder_cone),
        cmocka_unit_test(test_transform_each_step),
        cmocka_unit_test(test_transform_order),
        cmocka_unit_test(test_groups),
        cmocka_unit_test(test_colours),
        cmocka_unit_test(test_includes),
        cmocka_unit_test(test_anchors_and_aliases),
        cmocka_unit_test(test_merge_keys),
        cmocka_unit_test(test_version_and_comments),
        cmocka_unit_test(test_render_ambient),
        cmocka_unit_test(test_render_background_and_fog),
        cmocka_unit_test(test_problems_without_a_report),
        cmocka_unit_test(test_every_problem_in_order),
        cmocka_unit_test(test_every_problem_of_an_object),
        cmocka_unit_test(test_anchors_do_not_cross_files),
        cmocka_unit_test(test_max_errors),
        cmocka_unit_test(test_include_cycle),
        cmocka_unit_test(test_include_fan_out_is_bounded),
        cmocka_unit_test(test_include_twice),
        cmocka_unit_test(test_includes_nested_too_deep),
        cmocka_unit_test(test_missing_scene_file),
        cmocka_unit_test(test_error_status_of_first_problem),
        cmocka_unit_test(test_groups_nested_too_deep),
        cmocka_unit_test(test_alias_bomb_of_objects),
        cmocka_unit_test(test_alias_bomb_of_lights),
        cmocka_unit_test(test_alias_limit_counts_what_aliases_add),
        cmocka_unit_test(test_failed_texture_is_reported_once),
        cmocka_unit_test(test_merge_list_of_non_maps),
        cmocka_unit_test(test_merge_too_deep_says_so),
        cmocka_unit_test(test_objects_streamed_after_every_section),
        cmocka_unit_test(test_section_after_objects_loads_the_same),
        cmocka_unit_test(test_problems_in_streamed_objects),
        cmocka_unit_test(test_anchors_in_streamed_objects),
        cmocka_unit_test(test_include_streamed),
        cmocka_unit_test(test_alias_limit_while_streaming),
        cmocka_unit_test(test_stream_read_again),
    };
    /* One test per row of the table, named after it. */
    static struct CMUnitTest tests[COUNT(fixed) + COUNT(BAD)];
    static char names[COUNT(BAD)][64];
    size_t n = 0;
    for (size_t i = 0; i < COUNT(fixed); i++)
        tests[n++] = fixed[i];
    for (size_t i = 0; i < COUNT(BAD); i++) {
        snprintf(names[i], sizeof names[i], "bad_%s", BAD[i].name);
        tests[n++] = (struct CMUnitTest){names[i], test_bad_scene, NULL, NULL, (void *)&BAD[i]};
    }
    return _cmocka_run_group_tests("test_scene_file", tests, n, setup_dir, teardown_dir);
}
