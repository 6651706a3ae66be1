/* test_obj_import.c - glint's own OBJ and MTL readers: number forms,
 * corner forms, negative indices, polygons (concave ones by ear clipping),
 * continuation lines, CRLF, generated normals and their crease angle,
 * every MTL mapping, files read in chunks and by threads, and malformed
 * files refused at file:line:column. */
#include <stdarg.h>
#include <stddef.h>
#include <setjmp.h>
#include <stdint.h>
#include <cmocka.h>

#define MESH_TEST_NAME "obj-import"
#include "mesh_import_test_util.h"
#include "model/corner_angle.h"
#include "model/obj_read.h"
#include "model/text_scan.h"
#include "model/triangulate.h"

static int triangle_material(const mesh *m, int t)
{
    return m->materials ? m->materials[t] : m->material;
}

/* Writes `text` as tmp_dir/name and checks that importing it fails with
 * "<path>:<where>". */
static void expect_text_refused_at(const char *name, const char *text, const char *where)
{
    write_text(name, text);
    expect_refused_at(name, where);
}

/* A cube of side 2 about the origin, counter-clockwise seen from outside,
 * without normals. */
static const char cube_obj[] = "v -1 -1 -1\nv 1 -1 -1\nv 1 1 -1\nv -1 1 -1\n"
                               "v -1 -1 1\nv 1 -1 1\nv 1 1 1\nv -1 1 1\n"
                               "f 1 4 3 2\nf 5 6 7 8\nf 1 2 6 5\nf 4 8 7 3\nf 1 5 8 4\nf 2 3 7 6\n";

/* ------------------------------------------------------------------- OBJ */

static void test_obj_parts_and_mtl(void **state)
{
    write_text("parts.obj", parts_obj);
    write_text("parts.mtl", parts_mtl);
    glint_scene *s = new_scene();
    const mesh *m = import_ok(s, "parts.obj", NULL);
    /* quad 2 + triangle 1 + pentagon 3 + triangle 1 */
    assert_int_equal(m->triangle_count, 7);
    assert_int_equal(s->material_count, 3);
    assert_non_null(m->materials);
    assert_false(glint_scene_mesh_is_bare(s, 0));
    int red = scene_find_material(s, "parts/red"), glass = scene_find_material(s, "parts/glass"),
        mirror = scene_find_material(s, "parts/mirror");
    int count[3] = {0, 0, 0};
    for (int t = 0; t < m->triangle_count; t++) {
        int k = triangle_material(m, t);
        assert_true(k == red || k == glass || k == mirror);
        count[k == red ? 0 : k == glass ? 1 : 2]++;
    }
    assert_int_equal(count[0], 3);
    assert_int_equal(count[1], 1);
    assert_int_equal(count[2], 3);
    /* the negative indices -4 -3 -2 are vertices 1 2 3: the glass triangle */
    for (int t = 0; t < m->triangle_count; t++) {
        if (triangle_material(m, t) != glass)
            continue;
        for (int k = 0; k < 3; k++) {
            const float *p = m->positions + 3 * m->indices[3 * t + k];
            assert_true(p[0] <= 1 && p[1] <= 1 && !(p[0] == 0 && p[1] == 1));
        }
    }
    const glint_material *r = material_named(s, "parts/red");
    assert_near(r->color.r, 1, 1e-12);
    assert_near(r->color.g, 0, 1e-12);
    assert_near(r->specular, 0.5, 1e-6);
    assert_near(r->shininess, 30, 1e-6);
    assert_near(r->transparency + r->refraction + r->reflectivity, 0, 0);
    const glint_material *g = material_named(s, "parts/glass");
    assert_near(g->color.r, glint_srgb_to_linear(0.9), 1e-6);
    assert_near(g->color.b, 1, 1e-6);
    assert_near(g->refraction, 0.75, 1e-6);
    assert_near(g->transparency, 0, 0);
    assert_near(g->ior, 1.33, 1e-6);
    assert_true(g->fresnel);
    const glint_material *mi = material_named(s, "parts/mirror");
    assert_near(mi->reflectivity, 0.8, 1e-6);
    assert_near(mi->specular, 0.8, 1e-6);
    assert_near(mi->transparency, 0.3, 1e-6);
    assert_near(mi->color.r, glint_srgb_to_linear(0.5), 1e-6);
    assert_false(mi->fresnel);
    /* the flat parts have normals along +z */
    for (int v = 0; v < m->vertex_count; v++)
        assert_near(m->normals[3 * v + 2], 1, 1e-6);
    glint_vec3 lo, hi;
    assert_int_equal(glint_scene_mesh_bounds(s, 0, &lo, &hi, NULL), GLINT_OK);
    assert_near(lo.x, 0, 0);
    assert_near(hi.x, 3.5, 1e-6);
    assert_near(hi.y, 1, 1e-6);
    glint_scene_free(s);
}

static void test_obj_imported_twice(void **state)
{
    write_text("parts.obj", parts_obj);
    write_text("parts.mtl", parts_mtl);
    glint_scene *s = new_scene();
    import_ok(s, "parts.obj", NULL);
    const mesh *m = import_ok(s, "parts.obj", NULL);
    assert_int_equal(s->mesh_count, 2);
    assert_int_equal(s->material_count, 6);
    /* the second import's triangles use its own, renamed materials */
    int red2 = scene_find_material(s, "parts/red#2");
    assert_true(red2 >= 3);
    assert_int_equal(triangle_material(m, 0) >= 3, 1);
    assert_true(scene_find_material(s, "parts/glass#2") >= 3);
    glint_scene_free(s);
}

static void test_obj_without_mtl_file(void **state)
{
    write_text("lonely.obj", "mtllib gone.mtl\nv 0 0 0\nv 1 0 0\nv 0 1 0\nf 1 2 3\n");
    glint_scene *s = new_scene();
    const mesh *m = import_ok(s, "lonely.obj", NULL);
    assert_int_equal(m->triangle_count, 1);
    assert_int_equal(m->material, scene_find_material(s, "lonely/default"));
    /* No material from the file: a scene file's group may give it one. */
    assert_true(glint_scene_mesh_is_bare(s, 0));
    glint_scene_free(s);
}

static void test_obj_default_material_option(void **state)
{
    write_text("plain.obj", "v 0 0 0\nv 1 0 0\nv 0 1 0\nf 1 2 3\n");
    glint_scene *s = new_scene();
    glint_material mine = glint_material_default();
    int k = glint_scene_add_material(s, "mine", &mine, NULL);
    glint_import_options o = {.crease_angle = 0, .default_material = k};
    const mesh *m = import_ok(s, "plain.obj", &o);
    assert_int_equal(m->material, k);
    assert_int_equal(s->material_count, 1);
    assert_true(glint_scene_mesh_is_bare(s, 0));
    assert_false(glint_scene_mesh_is_bare(s, 1)); /* no such mesh */
    glint_scene_free(s);
}

static void test_obj_generated_normals_crease(void **state)
{
    write_text("cube.obj", cube_obj);
    expect_cube_normals("cube.obj");
}

static void test_obj_gentle_fold(void **state)
{
    /* two quads meeting at 20 degrees along x = 1 */
    double a = 20 * M_PI / 180;
    char text[512];
    snprintf(text, sizeof text, "v 0 0 0\nv 1 0 0\nv 1 1 0\nv 0 1 0\nv %.9f 0 %.9f\nv %.9f 1 %.9f\n"
                                "f 1 2 3 4\nf 2 5 6 3\n",
             1 + cos(a), -sin(a), 1 + cos(a), -sin(a));
    write_text("fold.obj", text);
    glint_scene *s = new_scene();
    const mesh *m = import_ok(s, "fold.obj", NULL);
    assert_int_equal(m->vertex_count, 6);
    glint_import_options sharp = {.crease_angle = 10, .default_material = -1};
    m = import_ok(s, "fold.obj", &sharp);
    assert_int_equal(m->vertex_count, 8);
    glint_scene_free(s);
}

static void test_obj_texture(void **state)
{
    write_bytes("stripes.png", png_red_over_blue, sizeof png_red_over_blue);
    write_text("painted.mtl", "newmtl paint\nKd 1 1 1\nmap_Kd stripes.png\n"
                              "newmtl paint2\nKd 1 1 1\nmap_Kd stripes.png\n");
    /* OBJ's v runs up: the top corners have v = 1 */
    write_text("painted.obj", "mtllib painted.mtl\n"
                              "v 0 0 0\nv 1 0 0\nv 1 1 0\nv 0 1 0\n"
                              "vt 0 0\nvt 1 0\nvt 1 1\nvt 0 1\n"
                              "usemtl paint\nf 1/1 2/2 3/3\nusemtl paint2\nf 1/1 3/3 4/4\n");
    glint_scene *s = new_scene();
    const mesh *m = import_ok(s, "painted.obj", NULL);
    assert_non_null(m->uvs);
    /* one texture for both materials */
    assert_int_equal(s->texture_count, 1);
    assert_int_equal(material_named(s, "painted/paint")->texture, 0);
    assert_int_equal(material_named(s, "painted/paint2")->texture, 0);
    for (int v = 0; v < m->vertex_count; v++) {
        const float *p = m->positions + 3 * v, *uv = m->uvs + 2 * v;
        assert_near(uv[0], p[0], 1e-6);
        assert_near(uv[1], 1 - p[1], 1e-6);
    }
    expect_red_over_blue(s, 0, (glint_vec3){0.5, 0.5, 1});
    glint_scene_free(s);
}

/* MTL's bump (or map_Bump) is a height map, its -bm scaling glint's own
 * strength; norm is a normal map; the images are shared with map_Kd's. */
static void test_obj_bump_and_normal_maps(void **state)
{
    write_bytes("stripes.png", png_red_over_blue, sizeof png_red_over_blue);
    write_bytes("dots.png", png_red_over_blue, sizeof png_red_over_blue);
    write_text("rough.mtl", "newmtl a\nmap_Kd stripes.png\nbump -bm 0.5 stripes.png\nnorm dots.png\n"
                            "newmtl b\nmap_Bump -clamp on dots.png\n");
    write_text("rough.obj", "mtllib rough.mtl\nv 0 0 0\nv 1 0 0\nv 1 1 0\nvt 0 0\nvt 1 0\nvt 1 1\n"
                            "usemtl a\nf 1/1 2/2 3/3\nusemtl b\nf 3/3 2/2 1/1\n");
    glint_scene *s = new_scene();
    import_ok(s, "rough.obj", NULL);
    assert_int_equal(s->texture_count, 2);
    const glint_material *a = material_named(s, "rough/a"), *b = material_named(s, "rough/b");
    assert_int_equal(a->texture, 0);
    assert_int_equal(a->bump_texture, 0);
    assert_int_equal(a->normal_texture, 1);
    assert_near(a->bump_strength, 0.05, 1e-15);
    assert_int_equal(b->texture, -1);
    assert_int_equal(b->bump_texture, 1);
    assert_int_equal(b->normal_texture, -1);
    assert_near(b->bump_strength, glint_material_default().bump_strength, 0);
    glint_scene_free(s);
}

static void test_obj_missing_texture(void **state)
{
    write_text("bare.mtl", "newmtl paint\nmap_Kd wood.png\n");
    write_text("bare.obj", "mtllib bare.mtl\nv 0 0 0\nv 1 0 0\nv 0 1 0\nusemtl paint\nf 1 2 3\n");
    char want[PATH_SIZE * 2];
    snprintf(want, sizeof want, "texture 'wood.png': cannot open texture '%s/wood.png': No such file or directory",
             tmp_dir);
    expect_refused("bare.obj", NULL, want);
    /* The failure's kind is the texture's status, whatever its message says. */
    write_text("bare.mtl", "newmtl paint\nmap_Kd out of memory.png\n");
    glint_scene *s = new_scene();
    glint_error err = {0};
    assert_int_equal(import(s, "bare.obj", NULL, &err), -1);
    assert_int_equal(err.status, GLINT_ERR_IO);
    glint_scene_free(s);
}

/* ------------------------------------------------------------ OBJ reader */

/* Writes tmp_dir/name and imports it, which must succeed. */
static const mesh *import_text(glint_scene *s, const char *name, const char *text)
{
    write_text(name, text);
    return import_ok(s, name, NULL);
}

/* True when some vertex of m is exactly at (x, y, z). */
static bool has_position(const mesh *m, float x, float y, float z)
{
    for (int v = 0; v < m->vertex_count; v++) {
        const float *p = m->positions + 3 * v;
        if (p[0] == x && p[1] == y && p[2] == z)
            return true;
    }
    return false;
}

/* Every number form scan_decimal takes is the double strtod gives. */
static void test_scan_decimal_forms(void **state)
{
    static const char *const good[] = {
        "1", "-0.5", ".5", "5.", "1e-3", "1E+10", "+2", "-0", "0.000123", "007", "1.5e0", "-.25e1",
        "123456789", "0.1", "0.7", "3.14159265358979", "9007199254740993", "12345678901234567890123",
        "1.00000000000000000000000000001", "1e22", "1e23", "4.9e-324", "2.2250738585072011e-308",
        "1.7976931348623157e308", "1e-400", "0.000000000000000000000000001234", "123.456e-5", "1e100000000",
    };
    for (size_t i = 0; i < sizeof good / sizeof good[0]; i++) {
        const char *t = good[i];
        double got = -1;
        const char *stop = scan_decimal(t, t + strlen(t), &got);
        if (stop != t + strlen(t))
            fail_msg("'%s' not read whole", t);
        double want = strtod(t, NULL);
        if (memcmp(&got, &want, sizeof got) != 0)
            fail_msg("'%s' read as %.17g, strtod gives %.17g", t, got, want);
    }
    double x;
    const char *inf = "-Infinity", *nan = "NaN";
    assert_ptr_equal(scan_decimal(inf, inf + 9, &x), inf + 9);
    assert_true(isinf(x) && x < 0);
    assert_ptr_equal(scan_decimal(nan, nan + 3, &x), nan + 3);
    assert_true(isnan(x));
    /* junk: no number at all, or one that stops before the word ends */
    static const char *const bad[] = {"", "-", ".", "e5", "+.", "x1", ".nan", "--1"};
    for (size_t i = 0; i < sizeof bad / sizeof bad[0]; i++)
        if (scan_decimal(bad[i], bad[i] + strlen(bad[i]), &x))
            fail_msg("'%s' read as a number", bad[i]);
    static const char *const cut[] = {"1.5x", "1e", "1e+", "0x10", "1,5", "1.5.2", "12-3"};
    for (size_t i = 0; i < sizeof cut / sizeof cut[0]; i++) {
        const char *stop = scan_decimal(cut[i], cut[i] + strlen(cut[i]), &x);
        assert_true(stop && stop < cut[i] + strlen(cut[i]));
    }
}

/* Random decimals, fast path and slow: bit for bit strtod's doubles. */
static void test_scan_decimal_random(void **state)
{
    uint64_t seed = 88172645463325252ULL;
    char text[64];
    for (int i = 0; i < 200000; i++) {
        seed ^= seed << 13;
        seed ^= seed >> 7;
        seed ^= seed << 17;
        uint64_t r = seed;
        int n = 0, digits = 1 + (int)(r % 24);
        r /= 24;
        if (r & 1)
            text[n++] = '-';
        int point = (int)((r >> 1) % (unsigned)(digits + 1));
        r >>= 6;
        for (int d = 0; d < digits; d++) {
            if (d == point)
                text[n++] = '.';
            text[n++] = (char)('0' + (r + (uint64_t)d * 7919) % 10);
            r = r * 6364136223846793005ULL + 1442695040888963407ULL;
        }
        if (r & 1)
            n += snprintf(text + n, sizeof text - (size_t)n, "e%d", (int)((r >> 1) % 640) - 320);
        text[n] = '\0';
        double got, want = strtod(text, NULL);
        const char *stop = scan_decimal(text, text + n, &got);
        if (stop != text + n || memcmp(&got, &want, sizeof got) != 0)
            fail_msg("'%s' read as %.17g, strtod gives %.17g", text, got, want);
    }
}

/* corner_angle is (float)atan2 bit for bit: at random, near the eighths
 * its tangent is reduced to, and at zeros, signs and extremes. */
static void test_corner_angle(void **state)
{
    uint64_t seed = 88172645463325252ULL;
    for (int i = 0; i < 400000; i++) {
        double r[2];
        for (int k = 0; k < 2; k++) {
            seed ^= seed << 13;
            seed ^= seed >> 7;
            seed ^= seed << 17;
            r[k] = (double)(seed >> 11) * 0x1p-53;
        }
        double y = ldexp(r[0], (int)(seed % 64) - 32), x = ldexp(r[1] - 0.5, (int)(seed / 64 % 64) - 32);
        if (i % 4 == 0) {
            double t = (double)(seed % 9) / 8 + (r[1] - 0.5) * 1e-9; /* about an eighth */
            x = i % 8 ? y / t : -y * t;
        }
        float got = corner_angle(y, x), want = (float)atan2(y, x);
        if (memcmp(&got, &want, sizeof got) != 0)
            fail_msg("corner_angle(%a, %a) is %a, atan2 gives %a", y, x, got, want);
    }
    static const double edge[][2] = {
        {0, 0}, {0, -0.0}, {0, 1}, {0, -1}, {1, 0}, {1, -0.0}, {-0.0, -1}, {-1, 1}, {1e-310, 1}, {1, 1e-310},
        {5e-324, 5e-324}, {1e308, 1e308}, {1e308, -1e-308}, {0x1p-900, 0x1p-901}, {1, 1}, {1, -1},
    };
    for (size_t i = 0; i < sizeof edge / sizeof edge[0]; i++) {
        float got = corner_angle(edge[i][0], edge[i][1]), want = (float)atan2(edge[i][0], edge[i][1]);
        if (memcmp(&got, &want, sizeof got) != 0)
            fail_msg("corner_angle(%a, %a) is %a, atan2 gives %a", edge[i][0], edge[i][1], got, want);
    }
    static const double far[][2] = {{INFINITY, 1}, {1, NAN}, {NAN, 1}, {1, -INFINITY}, {INFINITY, INFINITY},
                                    {-INFINITY, 1}, {NAN, NAN}, {0, NAN}};
    for (size_t i = 0; i < sizeof far / sizeof far[0]; i++)
        assert_true(corner_angle(far[i][0], far[i][1]) == 0);
}

static void test_obj_number_forms(void **state)
{
    glint_scene *s = new_scene();
    const mesh *m = import_text(s, "numbers.obj",
                                "v 1 -0.5 .5\nv 5. 1e-3 1E+10\nv +2 -.25e1 0.000000000000000000000000001234\n"
                                "v 123456789012345678901234 1.00000000000000000000000000001 -0\n"
                                "f 1 2 3\nf 2 3 4\n");
    assert_true(has_position(m, 1, -0.5f, 0.5f));
    assert_true(has_position(m, 5, 1e-3f, 1e10f));
    assert_true(has_position(m, 2, -2.5f, (float)1.234e-27));
    assert_true(has_position(m, 1.23456789012345678901234e23f, 1, 0));
    glint_scene_free(s);
    expect_text_refused_at("junk.obj", "v 0 0x1 0\n", "1:5: '0x1' is not a number");
    expect_text_refused_at("junk.obj", "v 1.5.2 0 0\n", "1:3: '1.5.2' is not a number");
    expect_text_refused_at("junk.obj", "v 1 2 3\nv 4 5 6,\n", "2:7: '6,' is not a number");
    expect_text_refused_at("junk.obj", "vn 0 0 -\n", "1:8: '-' is not a number");
    expect_text_refused_at("junk.obj", "vt 0.5 one\n", "1:8: 'one' is not a number");
    expect_text_refused_at("junk.obj", "v 1 0 1e39\n", "1:7: a vertex is not finite (1 0 inf)");
    expect_text_refused_at("junk.obj", "v 0 -inf 0\n", "1:5: a vertex is not finite (0 -inf 0)");
    expect_text_refused_at("junk.obj", "v 1 2\n", "1:1: 'v' needs at least 3 numbers (x y z), got 2");
    expect_text_refused_at("junk.obj", "vn 1 2 3 4\n", "1:1: 'vn' needs 3 numbers (x y z), got 4");
    expect_text_refused_at("junk.obj", "\n\n  vt\n", "3:3: 'vt' needs 1 to 3 numbers (u [v [w]]), got 0");
    expect_text_refused_at("junk.obj", "vt 1 2 3 4\n", "1:1: 'vt' needs 1 to 3 numbers (u [v [w]]), got 4");
}

/* A unit right triangle, then `faces`. */
#define TRI3 "v 0 0 0\nv 1 0 0\nv 0 1 0\n"

static void test_obj_index_errors(void **state)
{
    expect_text_refused_at("idx.obj", TRI3 "f 1 2 0\n", "4:7: vertex index 0 is not valid (indices count from 1)");
    expect_text_refused_at("idx.obj", TRI3 "f 1 2 9\n",
                           "4:7: vertex index 9 is out of range (the file has 3 vertices so far)");
    expect_text_refused_at("idx.obj", TRI3 "f -1 -2 -4\n",
                           "4:9: vertex index -4 is out of range (the file has 3 vertices so far)");
    expect_text_refused_at("idx.obj", "v 0 0 0\nf 1 1 2\nv 1 0 0\n",
                           "2:7: vertex index 2 is out of range (the file has 1 vertex so far)");
    expect_text_refused_at("idx.obj", TRI3 "vt 0 0\nf 1/2 2/1 3/1\n",
                           "5:5: texture coordinate index 2 is out of range (the file has 1 texture coordinate "
                           "so far)");
    expect_text_refused_at("idx.obj", TRI3 "f 1//1 2//1 3//1\n",
                           "4:6: normal index 1 is out of range (the file has 0 normals so far)");
    expect_text_refused_at("idx.obj", TRI3 "vn 0 0 1\nf 1//1 2//-1 3//0\n",
                           "5:17: normal index 0 is not valid (indices count from 1)");
    expect_text_refused_at("idx.obj", TRI3 "f 1 2 99999999999999999999999\n",
                           "4:7: vertex index 99999999999999999999999 is out of range (the file has 3 vertices "
                           "so far)");
    expect_text_refused_at("idx.obj", TRI3 "f 1 2\n", "4:1: a face needs at least 3 corners, got 2");
    expect_text_refused_at("idx.obj", TRI3 "f 1\n", "4:1: a face needs at least 3 corners, got 1");
    expect_text_refused_at("idx.obj", TRI3 "f\n", "4:1: a face needs at least 3 corners, got 0");
    expect_text_refused_at("idx.obj", TRI3 "f 1 2/x 3\n",
                           "4:5: '2/x' is not a face corner (v, v/vt, v//vn or v/vt/vn)");
    static const char *const corners[] = {"1/", "1//", "/1", "1/1/", "1/1/1/1", "1///1", "1.0", "a"};
    for (size_t i = 0; i < sizeof corners / sizeof corners[0]; i++) {
        char text[128], where[160];
        snprintf(text, sizeof text, TRI3 "vt 0 0\nvn 0 0 1\nf 2 3 %s\n", corners[i]);
        snprintf(where, sizeof where, "6:7: '%s' is not a face corner (v, v/vt, v//vn or v/vt/vn)", corners[i]);
        expect_text_refused_at("idx.obj", text, where);
    }
    expect_text_refused_at("idx.obj", TRI3 "vt 0 0\nf 1/1 2 3\n",
                           "5:7: face corner '2' is v, but the face's first corner is v/vt");
    expect_text_refused_at("idx.obj", TRI3 "vt 0 0\nvn 0 0 1\nf 1//1 2/1/1 3//1\n",
                           "6:8: face corner '2/1/1' is v/vt/vn, but the face's first corner is v//vn");
    expect_text_refused_at("idx.obj", TRI3 "usemtl\nf 1 2 3\n", "4:1: 'usemtl' needs a name");
    expect_text_refused_at("idx.obj", "mtllib   # none\n", "1:1: 'mtllib' needs a name");
    write_text("empty.obj", "");
    expect_refused("empty.obj", NULL, "no triangles");
    write_text("comments.obj", "# nothing\n\n   \t\ng group\n" TRI3 "l 1 2 3\np 1\n");
    expect_refused("comments.obj", NULL, "no triangles");
}

/* Corner forms, mixed across faces; negative indices of every part. */
static void test_obj_corner_forms(void **state)
{
    glint_scene *s = new_scene();
    const mesh *m = import_text(s, "forms.obj",
                                "v 0 0 0\nv 1 0 0\nv 1 1 0\nv 0 1 0\n"
                                "vt 0 0\nvt 1 0\nvt 1 1\nvt 0 1\nvn 0 0 1\n"
                                "f 1 2 3\nf 1/1 3/3 4/4\nf 1//1 2//1 3//1\nf 1/1/1 3/3/1 4/4/1\n"
                                "f -4/-4/-1 -3/-3/-1 -2/-2/-1\n");
    assert_int_equal(m->triangle_count, 5);
    assert_non_null(m->uvs);
    assert_non_null(m->normals);
    /* the first face, without texture coordinates, has uv (0, 0) */
    for (int k = 0; k < 3; k++) {
        const float *uv = m->uvs + 2 * m->indices[k];
        assert_true(uv[0] == 0 && uv[1] == 0);
    }
    /* the last face is 1/1/1 2/2/1 3/3/1: uv as x, flipped y */
    for (int k = 0; k < 3; k++) {
        uint32_t v = m->indices[12 + k];
        assert_near(m->uvs[2 * v], m->positions[3 * v], 0);
        assert_near(m->uvs[2 * v + 1], 1 - m->positions[3 * v + 1], 0);
        assert_near(m->normals[3 * v + 2], 1, 0);
    }
    glint_scene_free(s);
}

static void test_obj_file_normals_and_uvs(void **state)
{
    glint_scene *s = new_scene();
    /* normals as given (not normalised), a non-finite one as zero; a
     * texture coordinate that is not finite becomes 0; u v w takes u, v */
    const mesh *m = import_text(s, "given.obj",
                                "v 0 0 0\nv 1 0 0\nv 0 1 0\nvn 0 0 2\nvn nan 0 1\nvt 0.25 0.75 0.5\nvt inf 1e39\n"
                                "f 1/1/1 2/2/2 3/1/1\n");
    assert_int_equal(m->vertex_count, 3);
    for (int v = 0; v < 3; v++) {
        const float *p = m->positions + 3 * v, *n = m->normals + 3 * v, *uv = m->uvs + 2 * v;
        if (p[0] == 1) {
            assert_true(n[0] == 0 && n[1] == 0 && n[2] == 1);
            assert_true(uv[0] == 0 && uv[1] == 0);
        } else {
            assert_true(n[0] == 0 && n[1] == 0 && n[2] == 2);
            assert_true(uv[0] == 0.25f && uv[1] == 0.25f);
        }
    }
    glint_scene_free(s);
}

/* v with a w or a vertex colour; unknown statements; comments anywhere. */
static void test_obj_extras_ignored(void **state)
{
    glint_scene *s = new_scene();
    const mesh *m = import_text(s, "extras.obj",
                                "# colours\nv 0 0 0 1 0 0\nv 1 0 0 0 1 0\nv 0 1 0 1.0\n"
                                "vp 0.5\ncstype bezier\nmystery 1 2 3\no thing\ng a b\ns 1\ns off\n"
                                "l 1 2\np 3\nf 1 2 3 # a comment\nusemtl a#b\n");
    assert_int_equal(m->triangle_count, 1);
    assert_true(has_position(m, 0, 1, 0));
    glint_scene_free(s);
    expect_text_refused_at("extras.obj", "v 0 0 0 1 x\n", "1:11: 'x' is not a number");
}

/* A backslash ending a line joins the next; CRLF lines read as LF ones. */
static void test_obj_continuation_and_crlf(void **state)
{
    glint_scene *s = new_scene();
    const mesh *m = import_text(s, "joined.obj",
                                "v 0 0 0\nv 1 0 0\nv 1 1 \\\n 0\nv 0 1 0\n"
                                "usemtl paint \\\n  # a comment on a continued line\n"
                                "f 1 2 \\\n3 \\\r\n 4\n# a comment \\\nf 1 2 3\n");
    /* the quad, then the triangle: the comment's backslash continues nothing */
    assert_int_equal(m->triangle_count, 3);
    assert_true(has_position(m, 1, 1, 0));
    assert_int_equal(m->material, scene_find_material(s, "joined/paint"));
    m = import_text(s, "crlf.obj", "v 0 0 0\r\nv 1 0 0\r\nv 0 1 0\r\nvt 0 0\r\nusemtl\tpaint  \r\nf 1/1 2/1 3/1\r\n");
    assert_int_equal(m->triangle_count, 1);
    assert_true(scene_find_material(s, "crlf/paint") >= 0);
    glint_scene_free(s);
    /* places after a continuation count its lines */
    expect_text_refused_at("joined.obj", TRI3 "f 1 2 \\\n  9\n",
                           "5:3: vertex index 9 is out of range (the file has 3 vertices so far)");
    expect_text_refused_at("joined.obj", TRI3 "f 1 \\\n2 \\\n3\nv x 0 0\n", "7:3: 'x' is not a number");
    expect_text_refused_at("crlf.obj", "v 0 0 0\r\nv x 0 0\r\n", "2:3: 'x' is not a number");
}

/* Twice the signed area of the triangle (a, b, c) of 2D points. */
static double area2(const double *a, const double *b, const double *c)
{
    return (b[0] - a[0]) * (c[1] - a[1]) - (b[1] - a[1]) * (c[0] - a[0]);
}

/* The L-shaped hexagon, counter-clockwise from (2, 0), whose corner 0 does
 * not see corner 3: a fan from corner 0 would cover (1.2, 1.4), outside. */
static const double ell[6][2] = {{2, 0}, {2, 1}, {1, 1}, {1, 2}, {0, 2}, {0, 0}};

static bool inside_ell(double x, double y)
{
    return x > 0 && y > 0 && ((x < 2 && y < 1) || (x < 1 && y < 2));
}

/* Checks triangles (corner numbers of ell, three each): counter-clockwise,
 * areas adding up to the L's 3, and each inside it (its centroid and the
 * midpoints of its sides). */
static void expect_ell_split(const uint32_t *tri, int count)
{
    assert_int_equal(count, 4);
    double total = 0;
    for (int t = 0; t < count; t++) {
        const double *a = ell[tri[3 * t]], *b = ell[tri[3 * t + 1]], *c = ell[tri[3 * t + 2]];
        double area = area2(a, b, c) / 2;
        assert_true(area > 0);
        total += area;
        double cx = (a[0] + b[0] + c[0]) / 3, cy = (a[1] + b[1] + c[1]) / 3;
        assert_true(inside_ell(cx, cy));
        const double *p[3] = {a, b, c};
        for (int k = 0; k < 3; k++) {
            const double *u = p[k], *w = p[(k + 1) % 3];
            double mx = (u[0] + w[0]) / 2, my = (u[1] + w[1]) / 2;
            assert_true(inside_ell(0.999 * mx + 0.001 * cx, 0.999 * my + 0.001 * cy));
        }
    }
    assert_near(total, 3, 1e-12);
}

/* Ear clipping in the polygon's own plane, whichever way it faces. */
static void test_triangulate_concave(void **state)
{
    /* the L in planes facing +z, -y, +x and a tilted one, as (u, v) ->
     * point; the winding seen from the normal's side is always the L's */
    float pos[4][18];
    for (int i = 0; i < 6; i++) {
        float u = (float)ell[i][0], v = (float)ell[i][1];
        float *p = pos[0] + 3 * i, *q = pos[1] + 3 * i, *r = pos[2] + 3 * i, *t = pos[3] + 3 * i;
        p[0] = u, p[1] = v, p[2] = 5;
        q[0] = u, q[1] = 2, q[2] = -v;
        r[0] = 1, r[1] = u, r[2] = v;
        t[0] = u, t[1] = v, t[2] = 0.3f * u - 0.2f * v;
    }
    uint32_t corners[6] = {0, 1, 2, 3, 4, 5}, out[12];
    triangulate_work w = {0};
    for (int plane = 0; plane < 4; plane++) {
        assert_true(triangulate_polygon(&w, pos[plane], corners, 6, out));
        expect_ell_split(out, 4);
    }
    /* a convex polygon is a fan from corner 0 */
    float square[12] = {0, 0, 0, 1, 0, 0, 1, 1, 0, 0, 1, 0};
    assert_true(triangulate_polygon(&w, square, corners, 4, out));
    uint32_t fan[6] = {0, 1, 2, 0, 2, 3};
    for (int t = 0; t < 2; t++) {
        /* the same triangles, each maybe starting at another corner */
        int match = 0;
        for (int u = 0; u < 2; u++)
            for (int r = 0; r < 3; r++)
                match += out[3 * t] == fan[3 * u + r] && out[3 * t + 1] == fan[3 * u + (r + 1) % 3] &&
                         out[3 * t + 2] == fan[3 * u + (r + 2) % 3];
        assert_int_equal(match, 1);
    }
    /* degenerate (all on a line) and self-crossing polygons: still n - 2
     * triangles of the polygon's corners */
    float line[15] = {0, 0, 0, 1, 0, 0, 2, 0, 0, 3, 0, 0, 4, 0, 0};
    float bow[12] = {0, 0, 0, 1, 1, 0, 1, 0, 0, 0, 1, 0};
    assert_true(triangulate_polygon(&w, line, corners, 5, out));
    for (int i = 0; i < 9; i++)
        assert_true(out[i] < 5);
    assert_true(triangulate_polygon(&w, bow, corners, 4, out));
    for (int i = 0; i < 6; i++)
        assert_true(out[i] < 4);
    triangulate_free(&w);
}

/* The L through the importer, in the OBJ's own order. */
static void test_obj_concave_ngon(void **state)
{
    char text[512];
    int n = 0;
    for (int i = 0; i < 6; i++)
        n += snprintf(text + n, sizeof text - (size_t)n, "v %g 0 %g\n", ell[i][0], -ell[i][1]);
    snprintf(text + n, sizeof text - (size_t)n, "vn 0 1 0\nf 1//1 2//1 3//1 4//1 5//1 6//1\n"
                                                "f 1 2 3 4\n");
    glint_scene *s = new_scene();
    const mesh *m = import_text(s, "ell.obj", text);
    assert_int_equal(m->triangle_count, 6);
    /* back to corner numbers of ell: u = x, v = -z */
    uint32_t tri[12];
    for (int i = 0; i < 12; i++) {
        const float *p = m->positions + 3 * m->indices[i];
        int corner = -1;
        for (int c = 0; c < 6; c++)
            if (p[0] == (float)ell[c][0] && -p[2] == (float)ell[c][1])
                corner = c;
        assert_true(corner >= 0);
        tri[i] = (uint32_t)corner;
    }
    expect_ell_split(tri, 4);
    /* the quad 1 2 3 4 of the L is convex: two triangles, counter-clockwise */
    glint_scene_free(s);
}

/* Writes a UV sphere of radius 2 about the origin without normals: a fan
 * at each pole, quads between. With `seam` the first column of vertices is
 * given twice (as exporters split texture seams), the faces of the last
 * column using the copies. */
static void write_sphere(const char *name, int rings, int segments, bool seam)
{
    size_t cap = 256 + (size_t)rings * (size_t)segments * 160, n = 0;
    char *text = malloc(cap);
    assert_non_null(text);
    int columns = segments + seam;
    n += (size_t)snprintf(text + n, cap - n, "v 0 2 0\n");
    for (int r = 1; r < rings; r++)
        for (int c = 0; c < columns; c++) {
            double theta = M_PI * r / rings, phi = 2 * M_PI * (c % segments) / segments;
            n += (size_t)snprintf(text + n, cap - n, "v %.9f %.9f %.9f\n", 2 * sin(theta) * cos(phi),
                                  2 * cos(theta), -2 * sin(theta) * sin(phi));
        }
    n += (size_t)snprintf(text + n, cap - n, "v 0 -2 0\n");
    int south = 2 + (rings - 1) * columns;
    for (int c = 0; c < segments; c++) {
        int c1 = seam ? c + 1 : (c + 1) % segments;
        n += (size_t)snprintf(text + n, cap - n, "f 1 %d %d\n", 2 + c, 2 + c1);
        for (int r = 1; r < rings - 1; r++) {
            int a = 2 + (r - 1) * columns, b = a + columns;
            n += (size_t)snprintf(text + n, cap - n, "f %d %d %d %d\n", a + c, b + c, b + c1, a + c1);
        }
        int a = 2 + (rings - 2) * columns;
        n += (size_t)snprintf(text + n, cap - n, "f %d %d %d\n", a + c, south, a + c1);
    }
    assert_true(n < cap);
    write_text(name, text);
    free(text);
}

static void test_obj_sphere_normals(void **state)
{
    glint_scene *s = new_scene();
    for (int seam = 0; seam < 2; seam++) {
        write_sphere("sphere.obj", 24, 48, seam);
        const mesh *m = import_ok(s, "sphere.obj", NULL);
        assert_int_equal(m->triangle_count, 2 * 48 + 2 * 48 * 22);
        /* one vertex a point: the seam's copies are joined */
        assert_int_equal(m->vertex_count, 2 + 23 * 48);
        for (int v = 0; v < m->vertex_count; v++) {
            const float *p = m->positions + 3 * v, *n = m->normals + 3 * v;
            double len = sqrt((double)n[0] * n[0] + (double)n[1] * n[1] + (double)n[2] * n[2]);
            double cosine = ((double)p[0] * n[0] + (double)p[1] * n[1] + (double)p[2] * n[2]) / (2 * len);
            assert_near(len, 1, 1e-6);
            if (!(cosine >= cos(M_PI / 180)))
                fail_msg("vertex %d: normal %.2f degrees from the radius", v, acos(fmin(cosine, 1)) * 180 / M_PI);
        }
    }
    /* at 1 degree every face is flat: each corner's normal is its face's */
    glint_import_options flat = {.crease_angle = 1, .default_material = -1};
    const mesh *m = import_ok(s, "sphere.obj", &flat);
    for (int t = 0; t < m->triangle_count; t++) {
        const uint32_t *i = m->indices + 3 * t;
        const float *a = m->positions + 3 * i[0], *b = m->positions + 3 * i[1], *c = m->positions + 3 * i[2];
        double e1[3] = {b[0] - a[0], b[1] - a[1], b[2] - a[2]}, e2[3] = {c[0] - a[0], c[1] - a[1], c[2] - a[2]};
        double fn[3] = {e1[1] * e2[2] - e1[2] * e2[1], e1[2] * e2[0] - e1[0] * e2[2], e1[0] * e2[1] - e1[1] * e2[0]};
        double len = sqrt(fn[0] * fn[0] + fn[1] * fn[1] + fn[2] * fn[2]);
        for (int k = 0; k < 3; k++) {
            const float *n = m->normals + 3 * i[k];
            assert_near((fn[0] * n[0] + fn[1] * n[1] + fn[2] * n[2]) / len, 1, 1e-5);
        }
    }
    glint_scene_free(s);
}

/* Many faces at one point: a half disc of 500 triangles around the origin,
 * a face tilted 60 degrees from it and a fin at 90 degrees to both. The
 * disc's corners there and the tilted one count the same faces (the fin is
 * past 80 degrees from all of them) and so share one vertex, with the
 * angle-weighted normal; the fin's corner keeps its own. */
static void test_obj_many_faces_at_a_point(void **state)
{
    int segments = 500;
    size_t cap = 64 + (size_t)segments * 64, n = 0;
    char *text = malloc(cap);
    assert_non_null(text);
    n += (size_t)snprintf(text, cap, "v 0 0 0\nv -1 -1 -1.7320508075688772\nv 1 -1 -1.7320508075688772\n"
                                     "v 0 0 1\nv 0 -1 0\n");
    for (int i = 0; i <= segments; i++)
        n += (size_t)snprintf(text + n, cap - n, "v %.9f %.9f 0\n", cos(M_PI * i / segments),
                              sin(M_PI * i / segments));
    for (int i = 0; i < segments; i++)
        n += (size_t)snprintf(text + n, cap - n, "f 1 %d %d\n", 6 + i, 7 + i);
    n += (size_t)snprintf(text + n, cap - n, "f 1 2 3\nf 1 4 5\n");
    assert_true(n < cap);
    glint_scene *s = new_scene();
    const mesh *m = import_text(s, "fan.obj", text);
    free(text);
    int at_origin = 0;
    double tilt = acos(0.6), len = sqrt(M_PI * M_PI + tilt * tilt + 2 * M_PI * tilt * 0.5);
    double want[3] = {0, -tilt * sqrt(0.75) / len, (M_PI + tilt * 0.5) / len};
    for (int v = 0; v < m->vertex_count; v++) {
        const float *p = m->positions + 3 * v, *nv = m->normals + 3 * v;
        if (p[0] != 0 || p[1] != 0 || p[2] != 0)
            continue;
        at_origin++;
        if (nv[0] > 0.5) {
            assert_true(nv[0] == 1 && nv[1] == 0 && nv[2] == 0);
        } else {
            for (int k = 0; k < 3; k++)
                assert_near(nv[k], want[k], 1e-6);
        }
    }
    assert_int_equal(at_origin, 2);
    glint_scene_free(s);
}

/* Faces with normals and without, in one file: each keeps its own kind. */
static void test_obj_mixed_normals(void **state)
{
    glint_scene *s = new_scene();
    const mesh *m = import_text(s, "mixed.obj",
                                "v 0 0 0\nv 1 0 0\nv 1 1 0\nv 0 1 0\nv 0 0 1\nvn 0 0 2\n"
                                "f 1//1 2//1 3//1\nf 1 3 4\nf 1 4 5\n");
    assert_int_equal(m->triangle_count, 3);
    /* the file's normal as it is, not made unit length */
    for (int k = 0; k < 3; k++)
        assert_near(m->normals[3 * m->indices[k] + 2], 2, 0);
    /* faces 2 and 3 meet at 90 degrees: sharp at 80 */
    for (int k = 3; k < 6; k++)
        assert_near(m->normals[3 * m->indices[k] + 2], 1, 1e-6);
    for (int k = 6; k < 9; k++)
        assert_near(m->normals[3 * m->indices[k]], 1, 1e-6);
    glint_scene_free(s);
}

/* Every row of the MTL table of docs/meshes.md. */
static void test_mtl_mapping(void **state)
{
    char sub[PATH_SIZE];
    tmp_path(sub, "maps");
    mkdir(sub, 0755);
    write_bytes("maps/stripes.png", png_red_over_blue, sizeof png_red_over_blue);
    write_bytes("my stripes.png", png_red_over_blue, sizeof png_red_over_blue);
    write_text("all.mtl", "# every statement\n"
                          "Kd 1 1 1\n" /* before any newmtl: ignored */
                          "newmtl plain\n"
                          "newmtl red\r\n  Kd 1 0.5 0\n  Ks 0.2 0.5 0.1\n  Ns 20000\n"
                          "newmtl grey\nKd 0.5 # one value: all three\n"
                          "newmtl dissolved\nd 0.25\n"
                          "newmtl tr\nd 0.5\nTr 0.3\n"
                          "newmtl halo\nd -halo 0.6\n"
                          "newmtl mirror\nillum 3\nKs 0.8 0.7 0.6\n"
                          "newmtl glass4\nillum 4\nNi 1.5\nd 1\n"
                          "newmtl glass7\nillum 7\nNi 1.33\nd 0.4\nKd spectral glass.rfl\n"
                          "newmtl lit\nKa 1 1 1\nKe 1 0 0\nTf 1 1 1\nillum 9\nmap_Ks shine.png\nmap_Ka b.png\n"
                          "newmtl tex\nKd 0 0 0\nmap_Kd -s 1 1 1 -bm 0.5 -clamp on -o 0.5 maps\\stripes.png\n"
                          "newmtl spaced\nmap_Kd -blendu off -mm 0 1 my stripes.png  \n"
                          "newmtl unused\nKd 0 1 0\n"
                          "newmtl red\nKd 1 0 0\n" /* defined again: replaces */);
    char obj[2048] = "mtllib all.mtl\n" TRI3 "vt 0 0\nf 1 2 3\n";
    static const char *const names[] = {"plain", "red",  "grey",   "dissolved", "tr",     "halo",     "mirror",
                                        "glass4", "glass7", "lit", "tex",       "spaced", "undefined"};
    for (size_t i = 0; i < sizeof names / sizeof names[0]; i++) {
        size_t n = strlen(obj);
        snprintf(obj + n, sizeof obj - n, "usemtl %s\nf 1/1 2/1 3/1\n", names[i]);
    }
    glint_scene *s = new_scene();
    const mesh *m = import_text(s, "all.obj", obj);
    assert_int_equal(m->triangle_count, 14);
    /* used materials only, first the default for the face before usemtl */
    assert_int_equal(s->material_count, 14);
    assert_int_equal(triangle_material(m, 0), scene_find_material(s, "all/default"));
    assert_int_equal(scene_find_material(s, "all/unused"), -1);
    double grey6 = glint_srgb_to_linear(0.6);
    const glint_material *g = material_named(s, "all/plain");
    assert_near(g->color.r, grey6, 1e-12);
    assert_near(g->color.b, grey6, 1e-12);
    assert_near(g->specular + g->shininess + g->transparency + g->reflectivity + g->refraction, 0, 0);
    assert_near(g->ior, 1, 0);
    assert_near(g->ambient, 0.2, 0);
    assert_near(g->diffuse, 1, 0);
    assert_int_equal(g->texture, -1);
    g = material_named(s, "all/red");
    assert_near(g->color.r, 1, 1e-12);
    assert_near(g->color.g, 0, 1e-12);
    assert_near(g->specular, 0, 0);
    g = material_named(s, "all/undefined");
    assert_near(g->color.g, grey6, 1e-12);
    g = material_named(s, "all/grey");
    assert_near(g->color.g, glint_srgb_to_linear(0.5), 1e-12);
    assert_near(g->color.b, glint_srgb_to_linear(0.5), 1e-12);
    assert_near(material_named(s, "all/dissolved")->transparency, 0.75, 1e-12);
    assert_near(material_named(s, "all/tr")->transparency, 0.3, 1e-12);
    assert_near(material_named(s, "all/halo")->transparency, 0.4, 1e-12);
    g = material_named(s, "all/mirror");
    assert_near(g->reflectivity, 0.8, 1e-12);
    assert_near(g->specular, 0.8, 1e-12);
    assert_near(g->transparency, 0, 0);
    g = material_named(s, "all/glass4");
    assert_near(g->refraction, 1, 0);
    assert_near(g->transparency, 0, 0);
    assert_near(g->ior, 1.5, 1e-12);
    assert_false(g->fresnel);
    g = material_named(s, "all/glass7");
    assert_near(g->refraction, 0.6, 1e-12);
    assert_near(g->ior, 1.33, 1e-12);
    assert_true(g->fresnel);
    assert_near(g->color.r, grey6, 1e-12);
    g = material_named(s, "all/lit");
    assert_near(g->ambient, 0.2, 0);
    assert_near(g->transparency + g->reflectivity + g->refraction, 0, 0);
    assert_int_equal(g->texture, -1);
    /* the same image, under two spellings, is two textures */
    assert_int_equal(s->texture_count, 2);
    assert_int_equal(material_named(s, "all/tex")->texture, 0);
    assert_int_equal(material_named(s, "all/spaced")->texture, 1);
    glint_scene_free(s);
    /* Ns is clamped to 10000 */
    write_text("shiny.mtl", "newmtl s\nNs 20000\n");
    s = new_scene();
    import_text(s, "shiny.obj", "mtllib shiny.mtl\n" TRI3 "usemtl s\nf 1 2 3\n");
    assert_near(material_named(s, "shiny/s")->shininess, 10000, 0);
    glint_scene_free(s);
}

/* mtllib: several files on a line, a file name with a blank, a missing one. */
static void test_mtl_libraries(void **state)
{
    write_text("one.mtl", "newmtl a\nKd 1 0 0\n");
    write_text("two.mtl", "newmtl b\nKd 0 1 0\n");
    write_text("with blank.mtl", "newmtl c\nKd 0 0 1\n");
    glint_scene *s = new_scene();
    import_text(s, "libs.obj", "mtllib one.mtl gone.mtl two.mtl\nmtllib with blank.mtl\n" TRI3
                               "usemtl a\nf 1 2 3\nusemtl b\nf 1 2 3\nusemtl c\nf 1 2 3\n");
    assert_near(material_named(s, "libs/a")->color.r, 1, 0);
    assert_near(material_named(s, "libs/b")->color.g, 1, 0);
    assert_near(material_named(s, "libs/c")->color.b, 1, 0);
    glint_scene_free(s);
}

static void test_mtl_errors(void **state)
{
    char where[PATH_SIZE + 200];
    static const struct {
        const char *mtl, *where;
    } cases[] = {
        {"newmtl a\nKd 1 oops 0\n", "2:6: 'oops' is not a number"},
        {"newmtl a\r\nKd 1 0\r\n", "2:1: 'Kd' needs 1 or 3 numbers (r [g b]), got 2"},
        {"newmtl a\nNs\n", "2:1: 'Ns' needs 1 number, got 0"},
        {"newmtl a\nd 0.5 0.5\n", "2:1: 'd' needs 1 number, got 2"},
        {"newmtl a\nillum 2.5\n", "2:1: 'illum' needs a whole number from 0 to 10, got 2.5"},
        /* found by fuzz_mesh (regressions/mesh/mtl-illum-count-error-float-to-int.mtl):
         * the first number was made an int even when the count was wrong */
        {"newmtl a\nillum 7e10 2\n", "2:1: 'illum' needs 1 number, got 2"},
        {"newmtl a\nmap_Kd -s 1 1 1\n", "2:1: 'map_Kd' needs a file name"},
        {"# lib\n\nnewmtl\n", "3:1: 'newmtl' needs a name"},
    };
    for (size_t i = 0; i < sizeof cases / sizeof cases[0]; i++) {
        write_text("bad.mtl", cases[i].mtl);
        write_text("bad.obj", "mtllib bad.mtl\n" TRI3 "usemtl a\nf 1 2 3\n");
        glint_scene *s = new_scene();
        glint_error err = {0};
        assert_int_equal(import(s, "bad.obj", NULL, &err), -1);
        snprintf(where, sizeof where, "%s/bad.mtl:%s", tmp_dir, cases[i].where);
        assert_string_equal(err.message, where);
        assert_int_equal(glint_scene_get_counts(s).materials, 0);
        glint_scene_free(s);
    }
}

/* Many material changes: a material a triangle. */
static void test_obj_material_runs(void **state)
{
    char obj[4096] = TRI3;
    for (int i = 0; i < 40; i++) {
        size_t n = strlen(obj);
        snprintf(obj + n, sizeof obj - n, "usemtl m%d\nf 1 2 3\n", i % 3);
    }
    glint_scene *s = new_scene();
    const mesh *m = import_text(s, "runs.obj", obj);
    assert_int_equal(s->material_count, 3);
    assert_non_null(m->materials);
    for (int t = 0; t < 40; t++) {
        char name[32];
        snprintf(name, sizeof name, "runs/m%d", t % 3);
        assert_int_equal(m->materials[t], scene_find_material(s, name));
    }
    glint_scene_free(s);
}

/* A grid of n x n quads with texture coordinates and normals, a comment
 * line of `comment` bytes in the middle, and `tail` at the end. Returns the
 * text, which the caller frees; *lines is its number of lines. */
static char *grid_obj(int n, size_t comment, const char *tail, size_t *size, long *lines)
{
    size_t cap = (size_t)(n + 1) * (size_t)(n + 1) * 120 + (size_t)n * (size_t)n * 60 + comment + 256;
    char *text = malloc(cap), *p = text;
    assert_non_null(text);
    *lines = 0;
    for (int i = 0; i <= n; i++)
        for (int j = 0; j <= n; j++) {
            p += sprintf(p, "v %.6f %.6f %.6f\nvt %.4f %.4f\nvn 0 %.3f 1\n", (double)j / n, (double)i / n,
                         0.1 * sin(i + j), (double)j / n, (double)i / n, 0.001 * j);
            *lines += 3;
        }
    p += sprintf(p, "#");
    memset(p, 'c', comment);
    p += comment;
    p += sprintf(p, "\n");
    ++*lines;
    for (int i = 0; i < n; i++)
        for (int j = 0; j < n; j++) {
            int a = 1 + i * (n + 1) + j, b = a + n + 1;
            p += sprintf(p, "f %d/%d/%d %d/%d/%d %d/%d/%d %d/%d/%d\n", a, a, a, a + 1, a + 1, a + 1, b + 1, b + 1,
                         b + 1, b, b, b);
            ++*lines;
        }
    p += sprintf(p, "%s", tail);
    *size = (size_t)(p - text);
    assert_true(*size < cap);
    return text;
}

/* A file read in 1 MiB chunks, with lines across their ends and a line
 * longer than a chunk, makes the same mesh as its bytes in memory. */
static void test_obj_chunks(void **state)
{
    size_t size;
    long lines;
    char *text = grid_obj(150, 1500000, "", &size, &lines);
    assert_true(size > 3 * (1 << 20));
    write_bytes("grid.obj", text, size);
    glint_scene *s = new_scene();
    glint_error err = {0};
    const mesh *a = import_ok(s, "grid.obj", NULL);
    assert_int_equal(glint_scene_import_mesh_memory(s, text, size, "grid.obj", NULL, &err), 1);
    a = &s->meshes[0];
    const mesh *b = &s->meshes[1];
    assert_int_equal(a->triangle_count, 2 * 150 * 150);
    assert_int_equal(a->vertex_count, 151 * 151);
    assert_int_equal(b->vertex_count, a->vertex_count);
    assert_int_equal(b->triangle_count, a->triangle_count);
    size_t nv = (size_t)a->vertex_count;
    assert_memory_equal(a->positions, b->positions, nv * 3 * sizeof(float));
    assert_memory_equal(a->normals, b->normals, nv * 3 * sizeof(float));
    assert_memory_equal(a->uvs, b->uvs, nv * 2 * sizeof(float));
    assert_memory_equal(a->indices, b->indices, (size_t)a->triangle_count * 3 * sizeof(uint32_t));
    glint_scene_free(s);
    free(text);
    /* an error near the end is placed by its line among all of them */
    text = grid_obj(150, 10, "f 1 2 x\n", &size, &lines);
    write_bytes("grid.obj", text, size);
    char where[96];
    snprintf(where, sizeof where, "%ld:7: 'x' is not a face corner (v, v/vt, v//vn or v/vt/vn)", lines + 1);
    expect_refused_at("grid.obj", where);
    free(text);
}

/* ------------------------------------------------ OBJ parsed ahead by threads */

/* Checks that m is one to the byte. */
static void expect_same_model(const obj_model *m, const obj_model *one)
{
    assert_int_equal(m->position_count, one->position_count);
    assert_int_equal(m->uv_count, one->uv_count);
    assert_int_equal(m->normal_count, one->normal_count);
    assert_int_equal(m->corner_count, one->corner_count);
    assert_int_equal(m->triangle_count, one->triangle_count);
    assert_int_equal(m->run_count, one->run_count);
    assert_int_equal(m->text_len, one->text_len);
    assert_int_equal(m->material_count, one->material_count);
    assert_int_equal(m->library_count, one->library_count);
    assert_int_equal(m->generate, one->generate);
    assert_int_equal(m->textured, one->textured);
    if (one->position_count)
        assert_memory_equal(m->positions, one->positions, 3 * one->position_count * sizeof(float));
    if (one->uv_count)
        assert_memory_equal(m->uvs, one->uvs, 2 * one->uv_count * sizeof(float));
    if (one->normal_count)
        assert_memory_equal(m->normals, one->normals, 3 * one->normal_count * sizeof(float));
    if (one->corner_count)
        assert_memory_equal(m->corners, one->corners, one->corner_count * sizeof(obj_corner));
    if (one->triangle_count)
        assert_memory_equal(m->triangles, one->triangles, 3 * one->triangle_count * sizeof(uint32_t));
    if (one->run_count)
        assert_memory_equal(m->runs, one->runs, one->run_count * sizeof(obj_run));
    if (one->text_len)
        assert_memory_equal(m->text, one->text, one->text_len);
    if (one->material_count)
        assert_memory_equal(m->materials, one->materials, one->material_count * sizeof(size_t));
    if (one->library_count)
        assert_memory_equal(m->libraries, one->libraries, one->library_count * sizeof(size_t));
}

/* Reads text, from memory and from a file, with every thread count and
 * piece size given and checks that each reading gives the model and the
 * message of reading it in one pass: the same arrays to the byte, or the
 * same refusal. */
static void expect_split_same(const char *text, size_t size, const size_t *pieces, size_t piece_count)
{
    obj_model one;
    glint_error one_err = {0};
    glint_status one_s = obj_read_memory_split(&one, (const unsigned char *)text, size, "split.obj", 1,
                                               (size_t)1 << 40, &one_err);
    char path[PATH_SIZE];
    tmp_path(path, "split.obj");
    write_bytes("split.obj", text, size);
    for (int threads = 2; threads <= 4; threads++) {
        for (size_t k = 0; k < piece_count; k++) {
            for (int from_file = 0; from_file < 2; from_file++) {
                obj_model m;
                glint_error err = {0};
                glint_status s;
                if (from_file) {
                    int fd = open(path, O_RDONLY);
                    assert_true(fd >= 0);
                    s = obj_read_fd_split(&m, fd, "split.obj", threads, pieces[k], &err);
                    close(fd);
                } else {
                    s = obj_read_memory_split(&m, (const unsigned char *)text, size, "split.obj", threads, pieces[k],
                                              &err);
                }
                assert_int_equal(s, one_s);
                assert_string_equal(err.message, one_err.message);
                if (!s)
                    expect_same_model(&m, &one);
                obj_model_free(&m);
            }
        }
    }
    obj_model_free(&one);
}

/* Small texts of every statement, and every kind of error at every place,
 * cut at every byte and into pieces of every size. */
static void test_obj_split_same(void **state)
{
    static const char *const texts[] = {
        "mtllib a.mtl b.mtl\nv 0 0 0\nv 1 0 0\nv 1 1 0 1\nv 0 1 0 0.5 0.5 0.5\nvt 0 0\nvt 1\nvt 1 1 0\n"
        "vn 0 0 1\nvn nan 0 inf\n# comment\n\n  \t\ng group\no thing\ns off\nusemtl red\nf 1/1/1 2/2/1 3/3/2\n"
        "usemtl blue\nf -4/-3/-2 -3/-2/-1 -2/-1/-1 -1/-1/-1\nusemtl red\nf 1//1 3//1 4//2\nl 1 2\np 3\nf 1 2 3",
        "v 0 0 0\r\nv 1 0 0\r\nv 1 1 \\\r\n 0\r\nv 0 1 0\nf 1 2 \\\n3 4\r\nf 4 3 \\\n\n# x \\\nf 1 2 3\\",
        "v 0 0 0\nv 1 0 0\nv 0 1 0\nv 0.5 0.2 0\nv 1 1 0\nf 1 2 5 4 3\nf 1 2 3 4 5 1 2\n",
        "v 0 0 0\nv 1 0 0\nv 0 1 0\nf 1 2 0\n",
        "v 0 0 0\nv 1 0 0\nv 0 1 0\nf 1 2 4\nv 1 1 1\n",
        "v 0 0 0\nv 1 0 0\nv 0 1 0\nf -1 -2 -4\n",
        "v 0 0 0\nv 1 0 0\nv 0 1 0\nf 1 2 99999999999999999999999\n",
        "v 0 0 0\nv 1 0 0\nv 0 1 0\nf 1 2 3000000000\n",
        "v 0 0 0\nv 1 0 0\nv 0 1 0\nf 1/1 2/1 3/1\n",
        "v 0 0 0\nv 1 0 0\nv 0 1 0\nvt 0 0\nf 1/1 2 3\n",
        "v 0 0 0\nv 1 0 0\nv 0 1 0\nf 1 2\n",
        "v 0 0 0\nv 1 0 0\nv 0 1 0\nf 1 2 x\n",
        "v 0 0 0\nv 1 0 0\nv 0 1 0\nusemtl\nf 1 2 3\n",
        "v 0 0 0\nv 1 0 0\nv 0 1 inf\nf 1 2 3\n",
        "v 0 0 0\nv 1 0 0\nv 0 1\nf 1 2 3\n",
        "vt 0 0 0 0\n",
        "vn 0 0\n",
        "v 0 0 0\nv 1 0 0\nv 0 1 0\nf 1 2 3\nv 0 0 1e999\n",
        "v 0 0 0\nv 1 0 0\nv 0 1 0\nf 1 2 3 # the end\nf 3 2 1\nf 1 2 3 extra\n",
        "",
        "\n\n\n",
        "\\\n\\\n\\",
    };
    static const size_t pieces[] = {1, 2, 3, 5, 8, 13, 40};
    for (size_t i = 0; i < sizeof texts / sizeof texts[0]; i++)
        expect_split_same(texts[i], strlen(texts[i]), pieces, sizeof pieces / sizeof pieces[0]);
}

/* Corner ids go in the order corners first appear, whether a corner is
 * found by its vertex (numbered as the first corner was: here vn = v) or
 * by hashing (the rest), and with vertices read after faces. */
static void test_obj_corner_ids_in_order(void **state)
{
    static const char text[] = "v 0 0 0\nv 1 0 0\nv 0 1 0\nvn 0 0 1\nvn 0 0 1\nvn 0 0 1\nf 1//1 2//2 3//3\n"
                               "v 1 1 0\nvn 0 0 1\nf 2//2 4//4 3//3\nf -1//-1 -3//-3 -2//-2\nf 1 2 4\n"
                               "f 1//2 2//3 3//1\n";
    static const obj_corner corners[] = {{0, -1, 0}, {1, -1, 1}, {2, -1, 2}, {3, -1, 3}, {0, -1, -1},
                                         {1, -1, -1}, {3, -1, -1}, {0, -1, 1}, {1, -1, 2}, {2, -1, 0}};
    static const uint32_t triangles[] = {0, 1, 2, 1, 3, 2, 3, 1, 2, 4, 5, 6, 7, 8, 9};
    obj_model m;
    glint_error err = {0};
    assert_int_equal(obj_read_memory_split(&m, (const unsigned char *)text, strlen(text), "ids.obj", 1,
                                           (size_t)1 << 40, &err),
                     GLINT_OK);
    assert_int_equal(m.corner_count, sizeof corners / sizeof corners[0]);
    assert_memory_equal(m.corners, corners, sizeof corners);
    assert_int_equal(m.triangle_count, 5);
    assert_memory_equal(m.triangles, triangles, sizeof triangles);
    obj_model_free(&m);
    static const size_t pieces[] = {1, 7, 30};
    expect_split_same(text, strlen(text), pieces, sizeof pieces / sizeof pieces[0]);
}

/* Lines in the plain form most files are written in, which the reader
 * takes whole, give the model that the same values give spelt so that it
 * reads them word by word (exponents, continuations, comments, a tenth
 * digit), in one pass and in pieces parsed ahead. */
static void test_obj_plain_lines(void **state)
{
    static const char plain[] = "v 0.5 -1.25 3\nv -0 1.00000000000001 2\nv 9007199254740992 0.1 .5\n"
                                "v 1. +7 -0.000000000000000001\nvt 0.25 0.75\nvt 1\nvn 0 0 1\n"
                                "f 1/1/1 2/2/1 3/1/1\nf -3/-2/-1 +2/2/1 000000004/1/1\nf 1//1 2//1 3//1\n"
                                "f 4 3 2 1\nf 1/2 2/1 3/2\r\n";
    static const char worded[] = "v 0.5 -1.25 3e0\nv -0 1.00000000000001 \\\n2\nv 9007199254740992e0 0.1 .5 # x\n"
                                 "v 1. +7 -1e-18\nvt 25e-2 0.75\nvt 1 # one\nvn 0 0 1 \\\n\n"
                                 "f 1/1/1 2/2/1 \\\n3/1/1\nf -3/-2/-1 +2/2/1 0000000004/1/1\nf 1//1 2//1 3//1 #\n"
                                 "f 4 3 2 1 # four\nf 1/2 2/1 \\\r\n3/2\r\n";
    static const size_t pieces[] = {1, 9, 40};
    obj_model a, b;
    glint_error err = {0};
    assert_int_equal(obj_read_memory_split(&a, (const unsigned char *)plain, strlen(plain), "plain.obj", 1,
                                           (size_t)1 << 40, &err),
                     GLINT_OK);
    assert_int_equal(obj_read_memory_split(&b, (const unsigned char *)worded, strlen(worded), "worded.obj", 1,
                                           (size_t)1 << 40, &err),
                     GLINT_OK);
    assert_int_equal(a.triangle_count, 6);
    expect_same_model(&a, &b);
    obj_model_free(&a);
    obj_model_free(&b);
    expect_split_same(plain, strlen(plain), pieces, sizeof pieces / sizeof pieces[0]);
    expect_split_same(worded, strlen(worded), pieces, sizeof pieces / sizeof pieces[0]);
}

/* A large grid, whole and with an error near its end, in pieces of the
 * sizes real reads use and others. */
static void test_obj_split_grid(void **state)
{
    static const size_t pieces[] = {4096, 100000, 1 << 20};
    static const char *const tails[] = {"", "usemtl a\nf 1 2 3\nusemtl b\nf -1 -2 -3\n", "f 1 2 x\n",
                                        "f 1/1/1 2/2/2 999999/1/1\n"};
    for (size_t i = 0; i < sizeof tails / sizeof tails[0]; i++) {
        size_t size;
        long lines;
        char *text = grid_obj(120, 1000, tails[i], &size, &lines);
        expect_split_same(text, size, pieces, sizeof pieces / sizeof pieces[0]);
        free(text);
    }
}

int main(void)
{
    const struct CMUnitTest tests[] = {
        cmocka_unit_test(test_obj_parts_and_mtl),
        cmocka_unit_test(test_obj_imported_twice),
        cmocka_unit_test(test_obj_without_mtl_file),
        cmocka_unit_test(test_obj_default_material_option),
        cmocka_unit_test(test_obj_generated_normals_crease),
        cmocka_unit_test(test_obj_gentle_fold),
        cmocka_unit_test(test_obj_texture),
        cmocka_unit_test(test_obj_bump_and_normal_maps),
        cmocka_unit_test(test_obj_missing_texture),
        cmocka_unit_test(test_scan_decimal_forms),
        cmocka_unit_test(test_scan_decimal_random),
        cmocka_unit_test(test_corner_angle),
        cmocka_unit_test(test_obj_number_forms),
        cmocka_unit_test(test_obj_index_errors),
        cmocka_unit_test(test_obj_corner_forms),
        cmocka_unit_test(test_obj_file_normals_and_uvs),
        cmocka_unit_test(test_obj_extras_ignored),
        cmocka_unit_test(test_obj_continuation_and_crlf),
        cmocka_unit_test(test_triangulate_concave),
        cmocka_unit_test(test_obj_concave_ngon),
        cmocka_unit_test(test_obj_sphere_normals),
        cmocka_unit_test(test_obj_many_faces_at_a_point),
        cmocka_unit_test(test_obj_mixed_normals),
        cmocka_unit_test(test_mtl_mapping),
        cmocka_unit_test(test_mtl_libraries),
        cmocka_unit_test(test_mtl_errors),
        cmocka_unit_test(test_obj_material_runs),
        cmocka_unit_test(test_obj_chunks),
        cmocka_unit_test(test_obj_split_same),
        cmocka_unit_test(test_obj_split_grid),
        cmocka_unit_test(test_obj_plain_lines),
        cmocka_unit_test(test_obj_corner_ids_in_order),
    };
    return cmocka_run_group_tests(tests, setup_dir, teardown_dir);
}
