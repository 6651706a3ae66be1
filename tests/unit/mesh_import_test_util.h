/* mesh_import_test_util.h - what the model importers' tests
 * (test_mesh_import.c, test_obj_import.c) share: a temporary folder
 * (GLINT_TEST_TMP/glint-MESH_TEST_NAME-PID, which the including file names)
 * to write model files in, importing one that must import or must be
 * refused with an exact message, the small files both write (a two-part
 * OBJ with its MTL, a red-over-blue PNG), and checks of a cube's normals
 * and of a texture's colours in a render. Included after cmocka.h. */
#ifndef GLINT_TESTS_MESH_IMPORT_TEST_UTIL_H
#define GLINT_TESTS_MESH_IMPORT_TEST_UTIL_H

#include <dirent.h>
#include <fcntl.h>
#include <math.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>
#include <sys/stat.h>
#include <unistd.h>

#include "glint.h"
#include "tmp_tree.h"
#include "scene/scene.h"
#include "shading/material.h"

#define PATH_SIZE 1024

static char tmp_dir[PATH_SIZE];

/* ------------------------------------------------------------- helpers */

/* cmocka 1.1.5, Debian 12's, has no assert_double_equal. */
#define assert_near(a, b, tolerance) near_or_fail((a), (b), (tolerance), #a, __FILE__, __LINE__)

static inline void near_or_fail(double a, double b, double tolerance, const char *expr, const char *file, int line)
{
    if (!(fabs(a - b) <= tolerance))
        fail_msg("%s:%d: %s = %.17g, expected %.17g within %g", file, line, expr, a, b, tolerance);
}

static inline void tmp_path(char *buf, const char *name)
{
    int n = snprintf(buf, PATH_SIZE, "%s/%s", tmp_dir, name);
    assert_true(n > 0 && n < PATH_SIZE);
}

static inline void write_bytes(const char *name, const void *data, size_t size)
{
    char path[PATH_SIZE];
    tmp_path(path, name);
    FILE *f = fopen(path, "wb");
    assert_non_null(f);
    assert_int_equal(fwrite(data, 1, size, f), size);
    assert_int_equal(fclose(f), 0);
}

static inline void write_text(const char *name, const char *text)
{
    write_bytes(name, text, strlen(text));
}

/* Imports tmp_dir/name into s. */
static inline int import(glint_scene *s, const char *name, const glint_import_options *o, glint_error *err)
{
    char path[PATH_SIZE];
    tmp_path(path, name);
    return glint_scene_import_mesh(s, path, o, err);
}

static inline glint_scene *new_scene(void)
{
    glint_scene *s = glint_scene_new();
    assert_non_null(s);
    return s;
}

/* Imports tmp_dir/name, which must succeed, and returns its mesh. */
static inline const mesh *import_ok(glint_scene *s, const char *name, const glint_import_options *o)
{
    glint_error err = {0};
    int m = import(s, name, o, &err);
    if (m < 0)
        fail_msg("importing %s: %s", name, err.message);
    assert_int_equal(m, s->mesh_count - 1);
    return &s->meshes[m];
}

static inline const glint_material *material_named(const glint_scene *s, const char *name)
{
    int i = scene_find_material(s, name);
    if (i < 0)
        fail_msg("no material named '%s'", name);
    return &s->materials[i].m;
}

/* Checks that importing tmp_dir/name fails with exactly "<path><sep><rest>"
 * and leaves the scene as it was. */
static inline void refused_with(const char *name, const glint_import_options *o, const char *sep, const char *rest)
{
    glint_scene *s = new_scene();
    glint_error err = {0};
    char path[PATH_SIZE], want[PATH_SIZE + 600];
    tmp_path(path, name);
    assert_int_equal(glint_scene_import_mesh(s, path, o, &err), -1);
    int n = snprintf(want, sizeof want, "%s%s%s", path, sep, rest);
    assert_true(n > 0 && (size_t)n < sizeof want);
    assert_string_equal(err.message, want);
    glint_scene_counts c = glint_scene_get_counts(s);
    assert_int_equal(c.meshes + c.materials + c.textures, 0);
    glint_scene_free(s);
}

/* Refused with "<path>: <rest>", a message about the whole file. */
static inline void expect_refused(const char *name, const glint_import_options *o, const char *rest)
{
    refused_with(name, o, ": ", rest);
}

/* Refused with "<path>:<where>", where is "line:column: message". */
static inline void expect_refused_at(const char *name, const char *where)
{
    refused_with(name, NULL, ":", where);
}

/* -------------------------------------------------------- file builders */

/* A 2x2 PNG: top row red, bottom row blue. */
static const unsigned char png_red_over_blue[] = {
    0x89, 0x50, 0x4e, 0x47, 0x0d, 0x0a, 0x1a, 0x0a, 0x00, 0x00, 0x00, 0x0d, 0x49, 0x48, 0x44, 0x52, 0x00,
    0x00, 0x00, 0x02, 0x00, 0x00, 0x00, 0x02, 0x08, 0x02, 0x00, 0x00, 0x00, 0xfd, 0xd4, 0x9a, 0x73, 0x00,
    0x00, 0x00, 0x11, 0x49, 0x44, 0x41, 0x54, 0x78, 0x9c, 0x63, 0xf8, 0xcf, 0xc0, 0x00, 0x44, 0x0c, 0x60,
    0xf2, 0x3f, 0x00, 0x1b, 0xf2, 0x03, 0xfd, 0xf3, 0xe7, 0x4b, 0xb1, 0x00, 0x00, 0x00, 0x00, 0x49, 0x45,
    0x4e, 0x44, 0xae, 0x42, 0x60, 0x82,
};

/* OBJ parts: a quad, a triangle by negative indices in another group, a
 * pentagon in another object, and a triangle whose material the MTL file
 * lacks; four materials used. */
static const char parts_obj[] = "# parts\n"
                                "mtllib parts.mtl\n"
                                "o first\n"
                                "v 0 0 0\nv 1 0 0\nv 1 1 0\nv 0 1 0\n"
                                "usemtl red\n"
                                "f 1 2 3 4\n"
                                "g second\n"
                                "usemtl glass\n"
                                "f -4 -3 -2\n"
                                "o third\n"
                                "v 2 0 0\nv 3 0 0\nv 3.5 0.5 0\nv 3 1 0\nv 2 1 0\n"
                                "usemtl mirror\n"
                                "f 5 6 7 8 9\n"
                                "g fourth\n"
                                "usemtl red\n"
                                "f 5 6 7\n";

static const char parts_mtl[] = "newmtl red\nKd 1 0 0\nKs 0.2 0.5 0.1\nNs 30\n"
                                "newmtl glass\nKd 0.9 0.9 1\nillum 7\nNi 1.33\nd 0.25\n"
                                "newmtl mirror\nKd 0.5 0.5 0.5\nillum 3\nKs 0.8 0.8 0.8\nTr 0.3\n";

/* Counts the vertices of m whose normal has one component of size 1, and
 * those whose components are all 1/sqrt(3) in size. */
static inline void count_normals(const mesh *m, int *axis, int *diagonal)
{
    *axis = *diagonal = 0;
    for (int v = 0; v < m->vertex_count; v++) {
        const float *n = m->normals + 3 * v;
        double len = sqrt((double)n[0] * n[0] + (double)n[1] * n[1] + (double)n[2] * n[2]);
        double a = fabs(n[0]) / len, b = fabs(n[1]) / len, c = fabs(n[2]) / len;
        *axis += fmax(a, fmax(b, c)) > 0.9999;
        *diagonal += fabs(a - 1 / sqrt(3)) < 1e-4 && fabs(b - a) < 1e-4 && fabs(c - a) < 1e-4;
    }
}

/* The cube in `file`, imported at the default crease angle of 80 degrees,
 * keeps its 90-degree edges sharp (24 vertices, each normal along an axis,
 * pointing out of its face); at 180 every normal is smoothed (8 vertices,
 * each normal diagonal). */
static inline void expect_cube_normals(const char *file)
{
    glint_scene *s = new_scene();
    const mesh *m = import_ok(s, file, NULL);
    int axis, diagonal;
    assert_int_equal(m->triangle_count, 12);
    assert_non_null(m->normals);
    assert_int_equal(m->vertex_count, 24);
    count_normals(m, &axis, &diagonal);
    assert_int_equal(axis, 24);
    for (int t = 0; t < m->triangle_count; t++)
        for (int k = 0; k < 3; k++) {
            uint32_t v = m->indices[3 * t + k];
            const float *p = m->positions + 3 * v, *n = m->normals + 3 * v;
            assert_true(p[0] * n[0] + p[1] * n[1] + p[2] * n[2] > 0.99);
        }
    glint_import_options smooth = {.crease_angle = 180, .default_material = -1};
    m = import_ok(s, file, &smooth);
    assert_int_equal(m->vertex_count, 8);
    count_normals(m, &axis, &diagonal);
    assert_int_equal(diagonal, 8);
    glint_scene_free(s);
}

/* A 4x4 render of mesh `mesh_index` seen head-on from `eye`; checks that the top
 * row shows red and the bottom row blue. */
static inline void expect_red_over_blue(glint_scene *s, int mesh_index, glint_vec3 eye)
{
    glint_settings st = glint_settings_default();
    st.width = st.height = 4;
    assert_int_equal(glint_scene_set_settings(s, &st, NULL), GLINT_OK);
    glint_camera cam = {.position = eye, .look_at = {eye.x, eye.y, eye.z - 1}, .up = {0, 1, 0}, .vfov_degrees = 40};
    assert_int_equal(glint_scene_set_camera(s, &cam, NULL), GLINT_OK);
    glint_error err = {0};
    assert_true(glint_scene_add_instance(s, mesh_index, -1, NULL, &err) >= 0);
    glint_image img;
    if (glint_render(s, NULL, &img, NULL, &err))
        fail_msg("render: %s", err.message);
    for (int x = 0; x < 4; x++) {
        const float *top = img.pixels + 3 * x, *bottom = img.pixels + 3 * (12 + x);
        assert_true(top[0] > 0.1 && top[2] < 0.01);
        assert_true(bottom[2] > 0.1 && bottom[0] < 0.01);
    }
    glint_image_free(&img);
}

/* -------------------------------------------------------------- fixtures */

static inline int setup_dir(void **state)
{
    const char *base = getenv("GLINT_TEST_TMP");
    if (!base || !*base)
        base = "/tmp";
    snprintf(tmp_dir, sizeof tmp_dir, "%s/glint-" MESH_TEST_NAME "-%ld", base, (long)getpid());
    remove_tree(tmp_dir);
    return mkdir(tmp_dir, 0755) == 0 ? 0 : -1;
}

static inline int teardown_dir(void **state)
{
    remove_tree(tmp_dir);
    return 0;
}

#endif
