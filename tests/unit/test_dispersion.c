/* test_dispersion.c - light split by wavelength: the bands' colours,
 * Cauchy's index through an Abbe number, each band bent through a
 * 60-degree prism where Snell's law sends it (traced here again in two
 * dimensions, independently of the renderer), glass that disperses still
 * giving back white against white, and the values a material refuses. */
#include <stdarg.h>
#include <stddef.h>
#include <setjmp.h>
#include <stdint.h>
#include <cmocka.h>
#include <math.h>
#include <string.h>
#include "glint.h"
#include "one_sample_scene.h"
#include "core/vec.h"
#include "shading/spectrum.h"

#define assert_near(a, b, eps) assert_true(fabs((double)(a) - (double)(b)) <= (eps))

static double luminance(color c)
{
    return 0.2126 * c.r + 0.7152 * c.g + 0.0722 * c.b;
}

/* Each channel sums to 1 over the bands, none is negative, the longest
 * band is red, the shortest blue, and the brightest in the middle. */
static void test_bands_add_up_to_white(void **state)
{
    (void)state;
    const int counts[] = {3, 8, 16, 64};
    for (int k = 0; k < 4; k++) {
        spectrum s;
        spectrum_init(&s, counts[k]);
        color sum = rgb(0, 0, 0);
        int brightest = 0;
        for (int j = 0; j < s.count; j++) {
            color w = s.weight[j];
            assert_true(w.r >= 0 && w.g >= 0 && w.b >= 0);
            sum = rgb_add(sum, w);
            if (luminance(w) > luminance(s.weight[brightest]))
                brightest = j;
        }
        assert_near(sum.r, 1, 1e-12);
        assert_near(sum.g, 1, 1e-12);
        assert_near(sum.b, 1, 1e-12);
        color red = s.weight[s.count - 1], blue = s.weight[0];
        assert_true(red.r > red.g && red.r > red.b);
        assert_true(blue.b > blue.r && blue.b > blue.g);
        /* Green-yellow, 500 to 600 nm, is where the eye is most sensitive. */
        double middle = spectrum_wavelength(&s, brightest, 0.5);
        assert_true(middle > 500 && middle < 600);
    }
}

/* The index is ior at the d line, and (n_d - 1) / (n_F - n_C) is the Abbe
 * number; white light, or glass that does not disperse, sees ior. */
static void test_index_follows_the_abbe_number(void **state)
{
    (void)state;
    glint_material m = glint_material_default();
    const double iors[] = {1.33, 1.5, 2.42}, abbes[] = {55.7, 20, 64.2};
    for (int k = 0; k < 3; k++) {
        m.ior = iors[k];
        m.dispersion = abbes[k];
        double nd = material_index_at(&m, SPECTRUM_D_LINE), nf = material_index_at(&m, SPECTRUM_F_LINE),
               nc = material_index_at(&m, SPECTRUM_C_LINE);
        assert_near(nd, iors[k], 1e-12);
        assert_near((nd - 1) / (nf - nc), abbes[k], 1e-9 * abbes[k]);
        assert_true(material_index_at(&m, 400) > material_index_at(&m, 700));
        assert_near(material_index_at(&m, 0), iors[k], 0);
        m.dispersion = 0;
        assert_near(material_index_at(&m, 450), iors[k], 0);
    }
}

/* The prism test's world, in the plane y = 0: x across, z towards the
 * camera. */
typedef struct v2 {
    double x, z;
} v2;

static v2 v2_add(v2 a, v2 b, double s) { return (v2){a.x + b.x * s, a.z + b.z * s}; }
static double v2_dot(v2 a, v2 b) { return a.x * b.x + a.z * b.z; }
static v2 turned(double degrees) { return (v2){sin(degrees * M_PI / 180), cos(degrees * M_PI / 180)}; }

/* Snell's law for unit d through a surface whose unit normal n faces it,
 * eta = n_from / n_to; false on total internal reflection. */
static bool snell(v2 d, v2 n, double eta, v2 *out)
{
    double cos_i = -v2_dot(d, n), sin2_t = eta * eta * (1 - cos_i * cos_i);
    if (sin2_t > 1)
        return false;
    *out = v2_add((v2){d.x * eta, d.z * eta}, n, eta * cos_i - sqrt(1 - sin2_t));
    return true;
}

/* A prism of apex angle 60 degrees, its edge along y: each face a point
 * and an outward normal, the faces the light crosses first and second and
 * then the base. */
typedef struct prism {
    v2 point[3], normal[3];
} prism;

/* Where the ray from o along d, through p at index n, meets the plane
 * z = slit_z (*x), or false when it misses a face it must cross. */
static bool through_prism(const prism *p, v2 o, v2 d, double n, double slit_z, double *x)
{
    v2 at = o, dir = d;
    for (int f = 0; f < 2; f++) {
        v2 normal = p->normal[f];
        double t = v2_dot(v2_add(p->point[f], at, -1), normal) / v2_dot(dir, normal);
        at = v2_add(at, dir, t);
        /* Between the apex and the base. */
        if (v2_dot(v2_add(at, p->point[2], -1), p->normal[2]) > 0)
            return false;
        v2 facing = f == 0 ? normal : (v2){-normal.x, -normal.z};
        if (!snell(dir, facing, f == 0 ? 1 / n : n, &dir))
            return false;
    }
    *x = at.x + dir.x * (slit_z - at.z) / dir.z;
    return dir.z < 0;
}

/* Cauchy's index through n_d and an Abbe number, from their definitions. */
static double cauchy(double nd, double abbe, double wavelength)
{
    double b = (nd - 1) / (abbe * (1 / (486.13 * 486.13) - 1 / (656.27 * 656.27)));
    return nd - b / (587.56 * 587.56) + b / (wavelength * wavelength);
}

/* A camera looks along -z through a glass prism of apex angle 60 degrees
 * (n_d 1.6, Abbe number 12, turned for the least deviation at 550 nm) at
 * a narrow white slit 100 units past it, which the spectrum from 400 to
 * 700 nm sees across 11 degrees. Each column of the image sees the
 * slit in light of the wavelengths Snell's law bends into it. Where the
 * law, traced here, sends light of one band only into a column (give or
 * take 0.1 degree either side), its pixel has that band's colour; where it
 * sends none, the pixel is black. */
static void test_prism_bends_each_band_by_snells_law(void **state)
{
    (void)state;
    const int width = 700, height = 3, bands = 8;
    const double nd = 1.6, abbe = 12, half_across = 7; /* degrees */
    const double camera_z = 10, slit_distance = 100, slit_width = 0.5, margin = 0.1; /* degrees */
    double n_mid = cauchy(nd, abbe, 550), incidence = asin(n_mid / 2) * 180 / M_PI;
    prism p;
    /* The faces before turning: normals 30 degrees from +z and -z towards
     * +x (the apex), the base facing -x; its centroid at the origin, and
     * after turning at x = -1.5, so that every column looks through both
     * faces. */
    double side = 8, h = side * sqrt(3) / 2, turn = incidence - 30;
    v2 apex = {2 * h / 3, 0}, base = {-h / 3, 0};
    double c = cos(turn * M_PI / 180), s = sin(turn * M_PI / 180);
    v2 unturned[3] = {turned(30), turned(150), turned(270)}, points[3] = {apex, apex, base};
    for (int f = 0; f < 3; f++) {
        p.normal[f] = (v2){c * unturned[f].x + s * unturned[f].z, -s * unturned[f].x + c * unturned[f].z};
        p.point[f] = (v2){c * points[f].x + s * points[f].z - 1.5, -s * points[f].x + c * points[f].z};
    }
    /* The slit: where the middle column's ray at 480 nm reaches, 100 on,
     * which puts the spectrum in the middle of the image. */
    v2 o = {0, camera_z};
    double slit_z, slit_x;
    {
        v2 at = o, dir = {0, -1};
        for (int f = 0; f < 2; f++) {
            v2 normal = p.normal[f];
            at = v2_add(at, dir, v2_dot(v2_add(p.point[f], at, -1), normal) / v2_dot(dir, normal));
            double n = cauchy(nd, abbe, 480);
            assert_true(snell(dir, f == 0 ? normal : (v2){-normal.x, -normal.z}, f == 0 ? 1 / n : n, &dir));
        }
        v2 slit = v2_add(at, dir, slit_distance);
        slit_z = slit.z;
        slit_x = slit.x;
    }

    double half_height = tan(half_across * M_PI / 180) * height / width;
    glint_camera cam = {.kind = GLINT_CAMERA_PINHOLE, .position = {0, 0, camera_z}, .look_at = {0, 0, 0},
                        .up = {0, 1, 0}, .vfov_degrees = 2 * atan(half_height) * 180 / M_PI};
    glint_scene *scene = one_sample_scene(width, height, (glint_color){0, 0, 0}, cam);
    glint_settings st = glint_scene_get_settings(scene);
    st.samples_per_pixel = 64;
    st.sampler = GLINT_SAMPLER_SOBOL;
    st.dispersion_bands = bands;
    assert_int_equal(glint_scene_set_settings(scene, &st, NULL), GLINT_OK);
    glint_material glass = glint_material_default();
    glass.ambient = glass.diffuse = glass.specular = 0;
    glass.refraction = 1;
    glass.tint = 0;
    glass.ior = nd;
    glass.dispersion = abbe;
    glint_material light = glint_material_default();
    light.ambient = light.diffuse = light.specular = 0;
    light.emission = (glint_color){1, 1, 1};
    glint_error err;
    int glass_index = glint_scene_add_material(scene, NULL, &glass, &err);
    int light_index = glint_scene_add_material(scene, NULL, &light, &err);
    assert_true(glass_index >= 0 && light_index >= 0);
    glint_shape csg = glint_shape_default(GLINT_SHAPE_INTERSECTION);
    int prism_shape = glint_scene_add_shape(scene, &csg, glass_index, NULL, &err);
    assert_true(prism_shape >= 0);
    for (int f = 0; f < 3; f++) {
        glint_shape face = glint_shape_default(GLINT_SHAPE_PLANE);
        face.center = (glint_vec3){p.point[f].x, 0, p.point[f].z};
        face.normal = (glint_vec3){p.normal[f].x, 0, p.normal[f].z};
        assert_true(glint_scene_add_part(scene, prism_shape, &face, glass_index, NULL, &err) >= 0);
    }
    glint_shape slit = glint_shape_default(GLINT_SHAPE_BOX);
    slit.min = (glint_vec3){slit_x - slit_width / 2, -50, slit_z - 1e-3};
    slit.max = (glint_vec3){slit_x + slit_width / 2, 50, slit_z};
    assert_true(glint_scene_add_shape(scene, &slit, light_index, NULL, &err) >= 0);
    glint_image im;
    glint_render_options opts = {.threads = 2};
    assert_int_equal(glint_render(scene, &opts, &im, NULL, &err), GLINT_OK);

    spectrum spec;
    spectrum_init(&spec, bands);
    int checked[8] = {0}, dark = 0;
    double per_pixel = 2 * tan(half_across * M_PI / 180) / width, slack = margin * M_PI / 180;
    for (int col = 0; col < width; col++) {
        /* The bands Snell's law sends into the column, its directions
         * widened by the margin either side. */
        bool seen[8] = {false}, unknown = false;
        double lo = atan((col - width / 2.0) * per_pixel) - slack, hi = atan((col + 1 - width / 2.0) * per_pixel) + slack;
        for (int i = 0; i <= 32 && !unknown; i++) {
            double angle = lo + (hi - lo) * i / 32;
            v2 d = {sin(angle), -cos(angle)};
            for (double wl = SPECTRUM_SHORTEST; wl <= SPECTRUM_LONGEST; wl += 0.1) {
                double x;
                if (!through_prism(&p, o, d, cauchy(nd, abbe, wl), slit_z, &x)) {
                    unknown = true;
                    break;
                }
                if (fabs(x - slit_x) <= slit_width / 2) {
                    int band = (int)((wl - SPECTRUM_SHORTEST) / (SPECTRUM_LONGEST - SPECTRUM_SHORTEST) * bands);
                    seen[band < bands ? band : bands - 1] = true;
                }
            }
        }
        assert_false(unknown);
        int count = 0, band = -1;
        for (int j = 0; j < bands; j++)
            if (seen[j]) {
                count++;
                band = j;
            }
        const float *px = im.pixels + 3 * (size_t)(width + col); /* the middle row */
        if (count == 0) {
            assert_true(px[0] == 0 && px[1] == 0 && px[2] == 0);
            dark++;
        } else if (count == 1 && px[0] + px[1] + px[2] > 0) {
            color w = spec.weight[band];
            double sum = px[0] + px[1] + px[2], want = w.r + w.g + w.b;
            assert_near(px[0] / sum, w.r / want, 1e-4);
            assert_near(px[1] / sum, w.g / want, 1e-4);
            checked[band]++;
        }
    }
    for (int j = 0; j < bands; j++)
        assert_true(checked[j] >= 10);
    assert_true(dark >= 20);
    glint_image_free(&im);
    glint_scene_free(scene);
}

/* A dispersive ball in front of white, under no light, looks white: the
 * bands' colours add up to what came in (to rounding), as through glass
 * that does not disperse. */
static void test_white_stays_white(void **state)
{
    (void)state;
    glint_camera cam = {.kind = GLINT_CAMERA_PINHOLE, .position = {0, 0, 4}, .look_at = {0, 0, 0},
                        .up = {0, 1, 0}, .vfov_degrees = 30};
    glint_image images[2];
    for (int k = 0; k < 2; k++) {
        glint_scene *s = one_sample_scene(16, 16, (glint_color){0, 0, 0}, cam);
        glint_settings st = glint_scene_get_settings(s);
        st.background = (glint_color){1, 1, 1};
        assert_int_equal(glint_scene_set_settings(s, &st, NULL), GLINT_OK);
        glint_material glass = glint_material_default();
        glass.ambient = glass.diffuse = glass.specular = 0;
        glass.refraction = 1;
        glass.tint = 0;
        glass.dispersion = k ? 25 : 0;
        glint_shape ball = glint_shape_default(GLINT_SHAPE_SPHERE);
        ball.radius = 1;
        assert_true(glint_scene_add_shape(s, &ball, glint_scene_add_material(s, NULL, &glass, NULL), NULL, NULL) >= 0);
        glint_render_options o = {.threads = 1};
        assert_int_equal(glint_render(s, &o, &images[k], NULL, NULL), GLINT_OK);
        glint_scene_free(s);
    }
    for (int i = 0; i < 3 * 16 * 16; i++)
        assert_near(images[1].pixels[i], images[0].pixels[i], 1e-6);
    /* The middle pixel looks through the ball. */
    assert_near(images[1].pixels[3 * (8 * 16 + 8)], 1, 1e-6);
    glint_image_free(&images[0]);
    glint_image_free(&images[1]);
}

/* An index that falls to 0 or below somewhere in the spectrum is refused,
 * naming the values; the range of the number itself too. */
static void test_refuses_what_cannot_be(void **state)
{
    (void)state;
    glint_scene *s = glint_scene_new();
    glint_material m = glint_material_default();
    glint_error err;
    m.dispersion = 0.1;
    assert_int_equal(glint_scene_add_material(s, NULL, &m, &err), -1);
    assert_string_equal(err.message,
                        "material dispersion 0.1 with ior 1.5 gives an index of -0.7408 at 700 nm; it must stay above 0");
    m.dispersion = -1;
    assert_int_equal(glint_scene_add_material(s, NULL, &m, &err), -1);
    assert_non_null(strstr(err.message, "dispersion"));
    m.dispersion = 30;
    assert_true(glint_scene_add_material(s, NULL, &m, &err) >= 0);
    glint_settings st = glint_scene_get_settings(s);
    st.dispersion_bands = 2;
    assert_int_equal(glint_scene_set_settings(s, &st, &err), GLINT_ERR_INVALID);
    assert_non_null(strstr(err.message, "dispersion_bands"));
    glint_scene_free(s);
}

int main(void)
{
    const struct CMUnitTest tests[] = {
        cmocka_unit_test(test_bands_add_up_to_white),
        cmocka_unit_test(test_index_follows_the_abbe_number),
        cmocka_unit_test(test_prism_bends_each_band_by_snells_law),
        cmocka_unit_test(test_white_stays_white),
        cmocka_unit_test(test_refuses_what_cannot_be),
    };
    return cmocka_run_group_tests(tests, NULL, NULL);
}
