/* test_mesh.c - triangle meshes and instances: a tessellated sphere against
 * the analytic one, a quad split either way, instancing memory, smooth
 * normals, uv, per-triangle materials, bad mesh data and large meshes copied
 * exactly. */
#include <stdarg.h>
#include <stddef.h>
#include <setjmp.h>
#include <stdint.h>
#include <cmocka.h>
#include <math.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>
#include <unistd.h>
#include "accel/accel.h"
#include "scene/scene.h"

#define assert_near(a, b, eps) assert_true(fabs((double)(a) - (double)(b)) <= (eps))

static glint_scene *new_scene(int w, int h, double fov)
{
    glint_scene *s = glint_scene_new();
    assert_non_null(s);
    glint_settings st = glint_settings_default();
    st.width = w;
    st.height = h;
    assert_int_equal(glint_scene_set_settings(s, &st, NULL), GLINT_OK);
    glint_camera cam = {.position = {0, 0, 0}, .look_at = {0, 0, -1}, .up = {0, 1, 0}, .vfov_degrees = fov};
    assert_int_equal(glint_scene_set_camera(s, &cam, NULL), GLINT_OK);
    return s;
}

static int flat(glint_scene *s, double r, double g, double b)
{
    glint_material m = glint_material_default();
    m.color = (glint_color){r, g, b};
    m.ambient = 1;
    m.diffuse = 0;
    m.specular = 0;
    int i = glint_scene_add_material(s, NULL, &m, NULL);
    assert_true(i >= 0);
    return i;
}

/* A unit sphere of rings x segments quads, each split in two triangles. */
typedef struct sphere_mesh {
    float *positions;
    uint32_t *indices;
    int vertices, triangles;
} sphere_mesh;

static sphere_mesh make_sphere(int rings, int segments)
{
    sphere_mesh m = {0};
    m.vertices = (rings + 1) * (segments + 1);
    m.triangles = rings * segments * 2;
    m.positions = malloc(sizeof(float) * 3 * (size_t)m.vertices);
    m.indices = malloc(sizeof(uint32_t) * 3 * (size_t)m.triangles);
    assert_non_null(m.positions);
    assert_non_null(m.indices);
    int k = 0, t = 0;
    for (int i = 0; i <= rings; i++)
        for (int j = 0; j <= segments; j++, k++) {
            double th = M_PI * i / rings, ph = 2 * M_PI * j / segments;
            m.positions[3 * k] = (float)(sin(th) * cos(ph));
            m.positions[3 * k + 1] = (float)cos(th);
            m.positions[3 * k + 2] = (float)(sin(th) * sin(ph));
        }
    for (int i = 0; i < rings; i++)
        for (int j = 0; j < segments; j++) {
            uint32_t a = (uint32_t)(i * (segments + 1) + j), b = a + 1, c = a + (uint32_t)segments + 1, d = c + 1;
            uint32_t tri[6] = {a, c, b, b, c, d};
            memcpy(m.indices + t, tri, sizeof tri);
            t += 6;
        }
    return m;
}

static int count_lit(const glint_image *img)
{
    int n = 0;
    for (int i = 0; i < img->width * img->height; i++)
        n += img->pixels[3 * i] > 0.5f;
    return n;
}

static void test_tessellated_sphere_matches_analytic(void **state)
{
    glint_scene *a = new_scene(300, 300, 30), *b = new_scene(300, 300, 30);
    glint_shape ball = {.kind = GLINT_SHAPE_SPHERE, .center = {0, 0, -10}, .radius = 1};
    assert_true(glint_scene_add_shape(a, &ball, flat(a, 1, 1, 1), NULL, NULL) >= 0);
    sphere_mesh sm = make_sphere(128, 256);
    glint_mesh_data md = {sm.positions, NULL, NULL, sm.vertices, sm.indices, sm.triangles, NULL, flat(b, 1, 1, 1)};
    int mesh_id = glint_scene_add_mesh(b, "ball", &md, NULL);
    assert_int_equal(mesh_id, 0);
    glint_transform t = glint_transform_translate(glint_transform_identity(), 0, 0, -10);
    assert_int_equal(glint_scene_add_instance(b, mesh_id, -1, &t, NULL), 0);
    glint_image ia, ib;
    assert_int_equal(glint_render(a, NULL, &ia, NULL, NULL), GLINT_OK);
    assert_int_equal(glint_render(b, NULL, &ib, NULL, NULL), GLINT_OK);
    int na = count_lit(&ia), nb = count_lit(&ib), differ = 0;
    for (int i = 0; i < ia.width * ia.height; i++)
        differ += (ia.pixels[3 * i] > 0.5f) != (ib.pixels[3 * i] > 0.5f);
    assert_true(na > 1000);
    assert_true(differ <= na / 100);
    assert_true(abs(na - nb) <= na / 100);
    glint_image_free(&ia);
    glint_image_free(&ib);
    glint_scene_free(a);
    glint_scene_free(b);
    free(sm.positions);
    free(sm.indices);
}

/* A lit sphere mesh, rotated and scaled, over a floor that takes its shadow;
 * with `twice`, the mesh is also placed far out of view, so the visible one
 * is an Embree instance rather than world-space triangles. */
static glint_image render_placed(bool twice, sphere_mesh *sm)
{
    glint_scene *s = new_scene(160, 120, 40);
    glint_material matte = glint_material_default();
    matte.specular = 0;
    int mat = glint_scene_add_material(s, NULL, &matte, NULL);
    glint_mesh_data md = {sm->positions, NULL, NULL, sm->vertices, sm->indices, sm->triangles, NULL, mat};
    int mesh_id = glint_scene_add_mesh(s, "ball", &md, NULL);
    glint_transform t = glint_transform_scale(glint_transform_identity(), 1.5, 1, 1);
    t = glint_transform_rotate(t, (glint_vec3){0, 1, 0}, 30);
    t = glint_transform_translate(t, 0.3, 0, -8);
    assert_int_equal(glint_scene_add_instance(s, mesh_id, -1, &t, NULL), 0);
    if (twice) {
        glint_transform far = glint_transform_translate(glint_transform_identity(), 0, 0, 500);
        assert_int_equal(glint_scene_add_instance(s, mesh_id, -1, &far, NULL), 1);
    }
    glint_shape floor = {.kind = GLINT_SHAPE_PLANE, .center = {0, -1.2, 0}, .normal = {0, 1, 0}};
    assert_true(glint_scene_add_shape(s, &floor, mat, NULL, NULL) >= 0);
    glint_light l = {.kind = GLINT_LIGHT_POINT, .position = {-3, 6, -4}, .color = {1, 1, 1}};
    assert_true(glint_scene_add_light(s, &l, NULL) >= 0);
    glint_image img;
    assert_int_equal(glint_render(s, NULL, &img, NULL, NULL), GLINT_OK);
    glint_scene_free(s);
    return img;
}

static void test_placed_once_or_instanced_look_the_same(void **state)
{
    sphere_mesh sm = make_sphere(48, 96);
    glint_image flat_img = render_placed(false, &sm), inst_img = render_placed(true, &sm);
    int differ = 0, lit = 0;
    for (int i = 0; i < 3 * flat_img.width * flat_img.height; i++) {
        differ += fabsf(flat_img.pixels[i] - inst_img.pixels[i]) > 1e-3f;
        lit += flat_img.pixels[i] > 0.3f;
    }
    /* Only float rounding in Embree's hit parameters may differ. */
    assert_true(lit > 1000);
    assert_true(differ <= 3 * flat_img.width * flat_img.height / 1000);
    glint_image_free(&flat_img);
    glint_image_free(&inst_img);
    free(sm.positions);
    free(sm.indices);
}

/* The quad (-1,-1)..(1,1) at z = -3, split along one diagonal or the other. */
static glint_image render_quad(bool other_diagonal)
{
    glint_scene *s = new_scene(64, 64, 60);
    static const float p[] = {-1, -1, -3, 1, -1, -3, 1, 1, -3, -1, 1, -3};
    static const uint32_t one[] = {0, 1, 2, 0, 2, 3}, other[] = {0, 1, 3, 1, 2, 3};
    static const float uv[] = {0, 1, 1, 1, 1, 0, 0, 0};
    glint_mapping own = {.kind = GLINT_MAP_UV};
    glint_material m = glint_material_default();
    m.ambient = 1;
    m.diffuse = m.specular = 0;
    m.texture = glint_scene_add_checker(s, "c", (glint_color){1, 0, 0}, (glint_color){0, 0, 1}, 0.25, own, NULL);
    glint_mesh_data md = {p, NULL, uv, 4, other_diagonal ? other : one, 2, NULL,
                          glint_scene_add_material(s, NULL, &m, NULL)};
    assert_int_equal(glint_scene_add_instance(s, glint_scene_add_mesh(s, NULL, &md, NULL), -1, NULL, NULL), 0);
    glint_image img;
    assert_int_equal(glint_render(s, NULL, &img, NULL, NULL), GLINT_OK);
    glint_scene_free(s);
    return img;
}

static void test_quad_split_either_way_gives_the_same_image(void **state)
{
    glint_image a = render_quad(false), b = render_quad(true);
    int differ = 0;
    for (int i = 0; i < a.width * a.height * 3; i++)
        differ += fabsf(a.pixels[i] - b.pixels[i]) > 1e-4f;
    assert_int_equal(differ, 0);
    /* The checker follows the interpolated uv: 4 x 4 cells, red first at the top left. */
    assert_true(a.pixels[3 * (20 * 64 + 20)] > 0.9f);
    glint_image_free(&a);
    glint_image_free(&b);
}

/* Resident memory in bytes, from /proc/self/statm. */
static long resident(void)
{
    FILE *f = fopen("/proc/self/statm", "r");
    long size = 0, pages = 0;
    if (f) {
        if (fscanf(f, "%ld %ld", &size, &pages) != 2)
            pages = 0;
        fclose(f);
    }
    return pages * sysconf(_SC_PAGESIZE);
}

/* Builds the accelerator over `count` instances of a 131k-triangle mesh and
 * returns how much resident memory that took. */
static long accel_memory(glint_scene *s, int count)
{
    sphere_mesh sm = make_sphere(256, 256);
    glint_mesh_data md = {sm.positions, NULL, NULL, sm.vertices, sm.indices, sm.triangles, NULL, flat(s, 1, 1, 1)};
    int mesh_id = glint_scene_add_mesh(s, NULL, &md, NULL);
    free(sm.positions);
    free(sm.indices);
    for (int i = 0; i < count; i++) {
        glint_transform t = glint_transform_translate(glint_transform_identity(), 3.0 * (i % 40), 3.0 * (i / 40), -50);
        assert_true(glint_scene_add_instance(s, mesh_id, -1, &t, NULL) >= 0);
    }
    long before = resident();
    accel *a;
    accel_geometry g = {.meshes = s->meshes, .mesh_count = s->mesh_count, .instances = s->instances,
                        .instance_count = s->instance_count};
    assert_int_equal(accel_build(&a, &g, NULL), GLINT_OK);
    long used = resident() - before;
    accel_free(a);
    return used;
}

/* A set cancel flag stops the BVH build of a large mesh, placed once or
 * through instances, and the build reports it as a cancelled render; with
 * the flag clear the same scene builds. */
static void test_build_stops_when_cancelled(void **state)
{
    glint_scene *s = new_scene(8, 8, 30);
    sphere_mesh sm = make_sphere(256, 256);
    glint_mesh_data md = {sm.positions, NULL, NULL, sm.vertices, sm.indices, sm.triangles, NULL, flat(s, 1, 1, 1)};
    int mesh_id = glint_scene_add_mesh(s, NULL, &md, NULL);
    free(sm.positions);
    free(sm.indices);
    for (int i = 0; i < 2; i++) {
        glint_transform t = glint_transform_translate(glint_transform_identity(), 3.0 * i, 0, -50);
        assert_true(glint_scene_add_instance(s, mesh_id, -1, &t, NULL) >= 0);
    }
    volatile int cancel = 1;
    accel *a = NULL;
    glint_error err = {0};
    accel_geometry g = {.meshes = s->meshes, .mesh_count = s->mesh_count, .instances = s->instances,
                        .instance_count = s->instance_count, .cancel = &cancel};
    assert_int_equal(accel_build(&a, &g, &err), GLINT_ERR_CANCELLED);
    assert_null(a);
    assert_string_equal(err.message, "render cancelled");
    assert_int_equal(err.status, GLINT_ERR_CANCELLED);
    cancel = 0;
    assert_int_equal(accel_build(&a, &g, &err), GLINT_OK);
    accel_free(a);
    glint_scene_free(s);
}

static void test_instances_share_their_mesh(void **state)
{
    glint_scene *one = new_scene(8, 8, 30), *many = new_scene(8, 8, 30);
    long single = accel_memory(one, 1), thousand = accel_memory(many, 1000);
    print_message("resident memory for the accelerator: 1 instance %ld KiB, 1000 instances %ld KiB\n", single / 1024, thousand / 1024);
    /* 131k triangles take megabytes of BVH; a thousand placements add only
     * a little top-level structure (a few KiB each, where copies would cost
     * the whole mesh each). */
    assert_true(single > 2 * 1024 * 1024);
    assert_true(thousand < 2 * single);
    assert_true((thousand - single) / 999 < 8 * 1024);
    /* And a ray finds the far copies. */
    assert_int_equal(many->instance_count, 1000);
    glint_scene_free(one);
    glint_scene_free(many);
}

/* A mesh placed as it is shades without mapping through its identity
 * transform, and must give exactly what mapping through it gives. */
static void test_placed_as_it_is_skips_the_identity_exactly(void **state)
{
    glint_scene *s = new_scene(9, 9, 10);
    static const float p[] = {-1, -1, -5, 1, -1, -5.5f, 0, 1, -5.25f};
    static const float n[] = {-1, 0, 1, 1, 0.5f, 1, 0, 0.25f, 1};
    static const uint32_t idx[] = {0, 1, 2};
    glint_mesh_data md = {p, n, NULL, 3, idx, 1, NULL, flat(s, 1, 1, 1)};
    int mesh_id = glint_scene_add_mesh(s, "tilted", &md, NULL);
    glint_transform identity = glint_transform_identity(), moved = glint_transform_identity();
    moved.m[0][3] = 2;
    assert_int_equal(glint_scene_add_instance(s, mesh_id, -1, NULL, NULL), 0);
    assert_int_equal(glint_scene_add_instance(s, mesh_id, -1, &identity, NULL), 1);
    assert_int_equal(glint_scene_add_instance(s, mesh_id, -1, &moved, NULL), 2);
    assert_false(s->instances[0].has_transform);
    assert_false(s->instances[1].has_transform);
    assert_true(s->instances[2].has_transform);
    instance through = s->instances[0];
    through.has_transform = true;
    ray r = {{0.1, -0.2, 0.3}, v3_normalize(v3(0.05, 0.02, -1))};
    for (int k = 0; k < 5; k++) {
        double b1 = 0.1 + 0.15 * k, b2 = 0.3 - 0.05 * k, t0 = 5.4 + 0.01 * k, t1 = t0;
        surface direct, mapped;
        mesh_surface(&s->meshes[0], &s->instances[0], &r, 0, b1, b2, &t0, &direct);
        mesh_surface(&s->meshes[0], &through, &r, 0, b1, b2, &t1, &mapped);
        assert_true(t0 == t1);
        assert_true(v3_dot(v3_sub(direct.p, mapped.p), v3_sub(direct.p, mapped.p)) == 0);
        assert_true(v3_dot(v3_sub(direct.p_obj, mapped.p_obj), v3_sub(direct.p_obj, mapped.p_obj)) == 0);
        assert_true(direct.n.x == mapped.n.x && direct.n.y == mapped.n.y && direct.n.z == mapped.n.z);
        assert_true(direct.shading_n.x == mapped.shading_n.x && direct.shading_n.y == mapped.shading_n.y &&
                    direct.shading_n.z == mapped.shading_n.z);
    }
    glint_scene_free(s);
}

static void test_smooth_normals_and_per_triangle_materials(void **state)
{
    glint_scene *s = new_scene(9, 9, 10);
    /* One triangle facing +z whose vertex normals lean apart; two materials. */
    static const float p[] = {-1, -1, -5, 1, -1, -5, 0, 1, -5, -1, -1, -6, 1, -1, -6, 0, 1, -6};
    static const float n[] = {-1, 0, 1, 1, 0, 1, 0, 0, 1, 0, 0, 1, 0, 0, 1, 0, 0, 1};
    static const uint32_t idx[] = {0, 1, 2, 3, 4, 5};
    int mats[2] = {flat(s, 0, 1, 0), flat(s, 1, 0, 0)};
    glint_mesh_data md = {p, n, NULL, 6, idx, 2, mats, 0};
    int mesh_id = glint_scene_add_mesh(s, "two", &md, NULL);
    assert_int_equal(glint_scene_add_instance(s, mesh_id, -1, NULL, NULL), 0);
    accel *a;
    accel_geometry g = {.meshes = s->meshes, .mesh_count = s->mesh_count, .instances = s->instances,
                        .instance_count = s->instance_count};
    assert_int_equal(accel_build(&a, &g, NULL), GLINT_OK);
    ray r = {{-0.5, -0.9, 0}, {0, 0, -1}};
    ray8 rays;
    for (int i = 0; i < ACCEL_PACKET; i++)
        ray8_set(&rays, i, r);
    bool active[ACCEL_PACKET] = {true}, found[ACCEL_PACKET];
    accel_hit hits[ACCEL_PACKET];
    int skip[ACCEL_PACKET] = {-1, -1, -1, -1, -1, -1, -1, -1};
    accel_intersect8(a, &rays, NULL, INFINITY, skip, false, active, hits, found);
    assert_true(found[0]);
    assert_false(found[1]);
    accel_hit h = hits[0];
    assert_int_equal(h.triangle, 0);
    assert_int_equal(mesh_material(&s->meshes[0], &s->instances[0], h.triangle), mats[0]);
    surface sf;
    mesh_surface(&s->meshes[0], &s->instances[0], &r, h.triangle, h.b1, h.b2, &h.t, &sf);
    assert_near(h.t, 5, 1e-12);
    assert_near(sf.n.z, 1, 1e-12);
    /* Near vertex 0 the shading normal leans towards its (-1, 0, 1). */
    assert_true(sf.shading_n.x < -0.3);
    assert_near(v3_length(sf.shading_n), 1, 1e-9);
    accel_free(a);
    /* An instance's material overrides the mesh's. */
    assert_int_equal(glint_scene_add_instance(s, mesh_id, mats[1], NULL, NULL), 1);
    assert_int_equal(mesh_material(&s->meshes[0], &s->instances[1], 0), mats[1]);
    glint_scene_counts c = glint_scene_get_counts(s);
    assert_int_equal(c.meshes, 1);
    assert_int_equal(c.instances, 2);
    assert_int_equal(c.triangles, 2);
    glint_scene_free(s);
}

/* Two quads facing down, at x in [-4, -3] and [0, 1], 2 above a white floor,
 * each with its own material, under light slanting down to +x: each casts
 * its shadow on the floor 2 to the right. `instanced`: one mesh placed
 * twice; otherwise two meshes placed once each (Embree's other path).
 * Returns the floor's brightness in the two shadows and in the open. */
static void shadows_of_quads(bool instanced, const glint_material *a, const glint_material *b, double out[3])
{
    glint_scene *s = new_scene(64, 64, 60);
    glint_camera cam = {.position = {0, 10, 0}, .look_at = {0, 0, 0}, .up = {0, 0, -1}, .vfov_degrees = 60};
    assert_int_equal(glint_scene_set_camera(s, &cam, NULL), GLINT_OK);
    glint_material white = glint_material_default();
    white.specular = 0;
    glint_shape floor = {.kind = GLINT_SHAPE_PLANE, .normal = {0, 1, 0}};
    assert_true(glint_scene_add_shape(s, &floor, glint_scene_add_material(s, NULL, &white, NULL), NULL, NULL) >= 0);
    glint_light sun = {.kind = GLINT_LIGHT_DIRECTIONAL, .direction = {1, -1, 0}, .color = {1, 1, 1}};
    assert_true(glint_scene_add_light(s, &sun, NULL) >= 0);
    static const float p[] = {-0.5f, 0, -1, 0.5f, 0, -1, 0.5f, 0, 1, -0.5f, 0, 1};
    static const uint32_t idx[] = {0, 1, 2, 0, 2, 3};
    glint_mesh_data md = {p, NULL, NULL, 4, idx, 2, NULL, glint_scene_add_material(s, NULL, &white, NULL)};
    const glint_material *mats[2] = {a, b};
    double x[2] = {-3.5, 0.5};
    int shared = glint_scene_add_mesh(s, NULL, &md, NULL);
    for (int k = 0; k < 2; k++) {
        glint_transform t = glint_transform_translate(glint_transform_identity(), x[k], 2, 0);
        int placed = instanced || k == 0 ? shared : glint_scene_add_mesh(s, NULL, &md, NULL);
        int m = glint_scene_add_material(s, NULL, mats[k], NULL);
        assert_int_equal(glint_scene_add_instance(s, placed, m, &t, NULL), k);
    }
    glint_image img;
    assert_int_equal(glint_render(s, NULL, &img, NULL, NULL), GLINT_OK);
    /* Floor points x = -1.5, 2.5 and 4.5 (z = 0): pixel columns 23, 45, 56. */
    int columns[3] = {23, 45, 56};
    for (int k = 0; k < 3; k++)
        out[k] = img.pixels[3 * (32 * 64 + columns[k])];
    glint_image_free(&img);
    glint_scene_free(s);
}

static void test_opaque_and_see_through_meshes_cast_their_shadows(void **state)
{
    glint_material opaque = glint_material_default(), clear = glint_material_default();
    clear.transparency = 0.5;
    /* Ambient 0.2, plus the light at 45 degrees: cos = 0.7071. */
    double lit = 0.2 + sqrt(0.5), half = 0.2 + 0.5 * sqrt(0.5);
    for (int instanced = 0; instanced < 2; instanced++) {
        double v[3];
        shadows_of_quads(instanced, &opaque, &clear, v);
        assert_near(v[0], 0.2, 1e-6);
        assert_near(v[1], half, 1e-6);
        assert_near(v[2], lit, 1e-6);
        /* Both opaque: a mesh with no see-through placement needs no filter. */
        shadows_of_quads(instanced, &opaque, &opaque, v);
        assert_near(v[0], 0.2, 1e-6);
        assert_near(v[1], 0.2, 1e-6);
        assert_near(v[2], lit, 1e-6);
    }
}

static void test_bad_mesh_data(void **state)
{
    glint_scene *s = new_scene(8, 8, 30);
    int m = flat(s, 1, 1, 1);
    float p[] = {0, 0, 0, 1, 0, 0, 0, 1, 0};
    uint32_t idx[] = {0, 1, 3};
    glint_error err;
    glint_mesh_data md = {p, NULL, NULL, 3, idx, 1, NULL, m};
    assert_int_equal(glint_scene_add_mesh(s, NULL, &md, &err), -1);
    assert_string_equal(err.message, "mesh triangle 0 uses vertex 3 of 3");
    idx[2] = 2;
    p[4] = NAN;
    assert_int_equal(glint_scene_add_mesh(s, NULL, &md, &err), -1);
    assert_string_equal(err.message, "mesh vertex 1 is not finite");
    p[4] = 0;
    md.material = 7;
    assert_int_equal(glint_scene_add_mesh(s, NULL, &md, &err), -1);
    assert_string_equal(err.message, "material 7 does not exist");
    md.material = m;
    md.triangle_count = 0;
    assert_int_equal(glint_scene_add_mesh(s, NULL, &md, &err), -1);
    assert_string_equal(err.message, "mesh needs 1 to 1073741824 vertices and triangles, got 3 and 0");
    md.triangle_count = 1;
    assert_int_equal(glint_scene_add_mesh(s, NULL, &md, &err), 0);
    assert_int_equal(glint_scene_add_instance(s, 1, -1, NULL, &err), -1);
    assert_string_equal(err.message, "mesh 1 does not exist");
    glint_transform flat_xf = glint_transform_scale(glint_transform_identity(), 0, 1, 1);
    assert_int_equal(glint_scene_add_instance(s, 0, -1, &flat_xf, &err), -1);
    assert_string_equal(err.message, "transform is singular or not finite");
    glint_vec3 lo, hi;
    assert_int_equal(glint_scene_mesh_bounds(s, 0, &lo, &hi, &err), GLINT_OK);
    assert_near(hi.x, 1, 0);
    assert_near(lo.y, 0, 0);
    glint_scene_free(s);
}

/* Writes text to a file in the test's temporary directory; returns the path. */
static const char *temp_file(const char *name, const char *text)
{
    static char path[4096];
    const char *dir = getenv("GLINT_TEST_TMP");
    snprintf(path, sizeof path, "%s/%s", dir ? dir : "/tmp", name);
    FILE *f = fopen(path, "w");
    assert_non_null(f);
    fputs(text, f);
    fclose(f);
    return path;
}

/* Writes a scene file to the test's temporary directory and loads it. */
static glint_scene *load_temp_scene(const char *name, const char *text)
{
    glint_error err;
    glint_scene *s = glint_scene_load_file(temp_file(name, text), NULL, &err);
    if (!s)
        fail_msg("%s", err.message);
    return s;
}

static void test_scene_file_places_models(void **state)
{
    temp_file("mesh-quad.obj", "v -1 0 -1\nv 1 0 -1\nv 1 0 1\nv -1 0 1\nf 1 4 3 2\n");
    glint_scene *s = load_temp_scene("mesh-scene.yaml",
        "materials:\n"
        "  gold: {color: [1, 0.8, 0.2]}\n"
        "objects:\n"
        "  - {type: mesh, file: mesh-quad.obj}\n"
        "  - {type: mesh, file: mesh-quad.obj, material: gold, transform: [{translate: [3, 0, 0]}]}\n"
        "  - type: group\n"
        "    material: gold\n"
        "    objects: [{type: mesh, file: ./mesh-quad.obj, transform: [{scale: 2}]}]\n");
    /* One file, read once: one mesh of two triangles, three placements. */
    glint_scene_counts c = glint_scene_get_counts(s);
    assert_int_equal(c.meshes, 1);
    assert_int_equal(c.triangles, 2);
    assert_int_equal(c.instances, 3);
    int gold = scene_find_material(s, "gold");
    assert_int_equal(s->instances[0].material, -1);
    assert_int_equal(s->instances[1].material, gold);
    /* The file gives no materials: the group's is taken. */
    assert_true(glint_scene_mesh_is_bare(s, 0));
    assert_int_equal(s->instances[2].material, gold);
    assert_near(s->instances[1].to_world.m[0][3], 3, 0);
    assert_near(s->instances[2].to_world.m[1][1], 2, 0);
    glint_scene_free(s);

    char scene_path[4096];
    glint_error err;
    snprintf(scene_path, sizeof scene_path, "%s",
             temp_file("mesh-missing.yaml", "objects:\n  - {type: mesh, file: nowhere.obj, crease_angle: 30}\n"));
    assert_null(glint_scene_load_file(scene_path, NULL, &err));
    char want[4200];
    snprintf(want, sizeof want, "%s:2:24: cannot read model '%.*s/nowhere.obj': No such file or directory",
             scene_path, (int)(strrchr(scene_path, '/') - scene_path), scene_path);
    assert_string_equal(err.message, want);
}

/* A mesh's material: its own `material` key; else its file's materials,
 * when the file has any; else its group's; else the importer's grey. Seen
 * from above, with materials that show exactly their colour. */
static void test_mesh_takes_its_groups_material(void **state)
{
    temp_file("group-quad.obj", "v -1 0 -1\nv 1 0 -1\nv 1 0 1\nv -1 0 1\nf 1 4 3 2\n");
    temp_file("group-painted.mtl", "newmtl blue\nKd 0 0 1\n");
    temp_file("group-painted.obj", "mtllib group-painted.mtl\nusemtl blue\n"
                                   "v -1 0 -1\nv 1 0 -1\nv 1 0 1\nv -1 0 1\nf 1 4 3 2\n");
    glint_scene *s = load_temp_scene("group-scene.yaml",
        "settings: {width: 40, height: 10, ambient: [1, 1, 1]}\n"
        "camera: {position: [0, 10, 0], look_at: [0, 0, 0], up: [0, 0, -1], fov: 53.13010235415598}\n"
        "materials:\n"
        "  red: {color: [1, 0, 0], ambient: 1, diffuse: 0, specular: 0}\n"
        "  green: {color: [0, 1, 0], ambient: 1, diffuse: 0, specular: 0}\n"
        "objects:\n"
        "  - type: group\n"
        "    material: red\n"
        "    objects:\n"
        "      - {type: mesh, file: group-quad.obj, transform: [{scale: 2}, {translate: [-15, 0, 0]}]}\n"
        "      - {type: mesh, file: group-quad.obj, material: green, transform: [{scale: 2}, {translate: [-5, 0, 0]}]}\n"
        "      - {type: mesh, file: group-painted.obj, transform: [{scale: 2}, {translate: [5, 0, 0]}]}\n"
        "  - {type: mesh, file: group-quad.obj, transform: [{scale: 2}, {translate: [15, 0, 0]}]}\n");
    assert_false(glint_scene_mesh_is_bare(s, 1)); /* the painted one */
    glint_image img;
    assert_int_equal(glint_render(s, NULL, &img, NULL, NULL), GLINT_OK);
    /* One unit a pixel: the quads, 4 units square, are centred on pixels
     * (5, 5), (15, 5), (25, 5) and (35, 5). Only ambient light: a file's
     * material shows 0.2 of its colour, the grey 0.2 of 0.5. */
    const float want[4][3] = {{1, 0, 0}, {0, 1, 0}, {0, 0, 0.2f}, {0.1f, 0.1f, 0.1f}};
    for (int i = 0; i < 4; i++)
        for (int c = 0; c < 3; c++)
            assert_near(img.pixels[3 * (5 * img.width + 5 + 10 * i) + c], want[i][c], 1e-6);
    glint_image_free(&img);
    glint_scene_free(s);
}

/* A mesh whose arrays pass 1 MiB (on huge pages, core/big_alloc.h) is the
 * scene's own exact copy: positions and indices byte for byte, and the
 * float after the last position, which Embree's 16-byte reads take in,
 * zero. */
static void test_large_mesh_is_copied_exactly(void **state)
{
    glint_scene *s = new_scene(8, 8, 60);
    sphere_mesh sm = make_sphere(400, 400);
    assert_true((size_t)sm.vertices * 3 * sizeof(float) >= ((size_t)1 << 20));
    glint_mesh_data md = {sm.positions, NULL, NULL, sm.vertices, sm.indices, sm.triangles, NULL, flat(s, 1, 1, 1)};
    int id = glint_scene_add_mesh(s, NULL, &md, NULL);
    assert_true(id >= 0);
    const mesh *m = &s->meshes[id];
    assert_ptr_not_equal(m->positions, sm.positions);
    assert_memory_equal(m->positions, sm.positions, (size_t)sm.vertices * 3 * sizeof(float));
    assert_memory_equal(m->indices, sm.indices, (size_t)sm.triangles * 3 * sizeof(uint32_t));
    assert_true(m->positions[3 * (size_t)sm.vertices] == 0.0f);
    free(sm.positions);
    free(sm.indices);
    glint_scene_free(s);
}

int main(void)
{
    const struct CMUnitTest tests[] = {
        cmocka_unit_test(test_tessellated_sphere_matches_analytic),
        cmocka_unit_test(test_quad_split_either_way_gives_the_same_image),
        cmocka_unit_test(test_instances_share_their_mesh),
        cmocka_unit_test(test_build_stops_when_cancelled),
        cmocka_unit_test(test_placed_as_it_is_skips_the_identity_exactly),
        cmocka_unit_test(test_opaque_and_see_through_meshes_cast_their_shadows),
        cmocka_unit_test(test_placed_once_or_instanced_look_the_same),
        cmocka_unit_test(test_smooth_normals_and_per_triangle_materials),
        cmocka_unit_test(test_bad_mesh_data),
        cmocka_unit_test(test_scene_file_places_models),
        cmocka_unit_test(test_mesh_takes_its_groups_material),
        cmocka_unit_test(test_large_mesh_is_copied_exactly),
    };
    return cmocka_run_group_tests(tests, NULL, NULL);
}
