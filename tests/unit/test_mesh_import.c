/* test_mesh_import.c - importing model files: the shared bunny, teapot and
 * Cornell box when present, and files written here. PLY, STL, glTF (with a
 * data-URI buffer) and GLB (with an embedded PNG and a node hierarchy) go
 * through Assimp, but for the emissive strength of glTF materials, which
 * glint reads itself; OBJ through glint's own reader (test_obj_import.c
 * tests it). Malformed files are refused with a message naming them,
 * without a crash and without a line on stdout or stderr. */
#include <stdarg.h>
#include <stddef.h>
#include <setjmp.h>
#include <stdint.h>
#include <cmocka.h>

#define MESH_TEST_NAME "mesh-import"
#include "mesh_import_test_util.h"

/* Checks that importing tmp_dir/name fails with "<path>: " and a message of
 * Assimp's. */
static void expect_refused_by_assimp(const char *name)
{
    glint_scene *s = new_scene();
    glint_error err = {0};
    char path[PATH_SIZE], prefix[PATH_SIZE + 4];
    tmp_path(path, name);
    assert_int_equal(glint_scene_import_mesh(s, path, NULL, &err), -1);
    snprintf(prefix, sizeof prefix, "%s: ", path);
    if (strncmp(err.message, prefix, strlen(prefix)) != 0 || strlen(err.message) <= strlen(prefix) ||
        strchr(err.message, '\n'))
        fail_msg("importing %s: unexpected message '%s'", name, err.message);
    assert_int_equal(glint_scene_get_counts(s).meshes, 0);
    glint_scene_free(s);
}

static void base64(const unsigned char *in, size_t n, char *out)
{
    static const char digits[] = "ABCDEFGHIJKLMNOPQRSTUVWXYZabcdefghijklmnopqrstuvwxyz0123456789+/";
    size_t o = 0;
    for (size_t i = 0; i < n; i += 3) {
        unsigned v = (unsigned)in[i] << 16 | (i + 1 < n ? (unsigned)in[i + 1] << 8 : 0) | (i + 2 < n ? in[i + 2] : 0);
        out[o++] = digits[v >> 18 & 63];
        out[o++] = digits[v >> 12 & 63];
        out[o++] = i + 1 < n ? digits[v >> 6 & 63] : '=';
        out[o++] = i + 2 < n ? digits[v & 63] : '=';
    }
    out[o] = '\0';
}

/* The binary buffer of the glTF quad: positions (0,0,0) (1,0,0) (1,1,0)
 * (0,1,0), texture coordinates with (0, 0) at the top left corner (glTF's
 * convention: the image's first row), indices 0 1 2 0 2 3, then the PNG. */
#define QUAD_BYTES 92
static size_t gltf_buffer(unsigned char *buf, bool with_png)
{
    const float pos[12] = {0, 0, 0, 1, 0, 0, 1, 1, 0, 0, 1, 0};
    const float uv[8] = {0, 1, 1, 1, 1, 0, 0, 0};
    const uint16_t idx[6] = {0, 1, 2, 0, 2, 3};
    memcpy(buf, pos, sizeof pos);
    memcpy(buf + 48, uv, sizeof uv);
    memcpy(buf + 80, idx, sizeof idx);
    if (!with_png)
        return QUAD_BYTES;
    memcpy(buf + QUAD_BYTES, png_red_over_blue, sizeof png_red_over_blue);
    return QUAD_BYTES + sizeof png_red_over_blue;
}

/* A glTF document of the quad under a node translated by (1, 2, 3) whose
 * child scales it by 2, with `material` (a JSON object), its buffer at
 * `uri` (NULL: GLB's own), and with the PNG as image 0 when asked. */
static void gltf_json(char *out, size_t size, const char *uri, size_t bytes, bool with_png, const char *mat_json)
{
    char buffer[4096], image[512] = "";
    if (uri)
        snprintf(buffer, sizeof buffer, "{\"byteLength\":%zu,\"uri\":\"%s\"}", bytes, uri);
    else
        snprintf(buffer, sizeof buffer, "{\"byteLength\":%zu}", bytes);
    if (with_png)
        snprintf(image, sizeof image,
                 ",{\"buffer\":0,\"byteOffset\":%d,\"byteLength\":%zu}],"
                 "\"images\":[{\"bufferView\":3,\"mimeType\":\"image/png\"}],\"textures\":[{\"source\":0}",
                 QUAD_BYTES, sizeof png_red_over_blue);
    int n = snprintf(
        out, size,
        "{\"asset\":{\"version\":\"2.0\"},\"scene\":0,\"scenes\":[{\"nodes\":[0]}],"
        "\"nodes\":[{\"name\":\"parent\",\"translation\":[1,2,3],\"children\":[1]},"
        "{\"name\":\"child\",\"scale\":[2,2,2],\"mesh\":0}],"
        "\"meshes\":[{\"primitives\":[{\"attributes\":{\"POSITION\":0,\"TEXCOORD_0\":1},\"indices\":2,"
        "\"material\":0}]}],"
        "\"materials\":[%s],"
        "\"extensionsUsed\":[\"KHR_materials_transmission\",\"KHR_materials_ior\"],"
        "\"buffers\":[%s],"
        "\"bufferViews\":[{\"buffer\":0,\"byteOffset\":0,\"byteLength\":48},"
        "{\"buffer\":0,\"byteOffset\":48,\"byteLength\":32},{\"buffer\":0,\"byteOffset\":80,\"byteLength\":12}%s],"
        "\"accessors\":[{\"bufferView\":0,\"componentType\":5126,\"count\":4,\"type\":\"VEC3\","
        "\"min\":[0,0,0],\"max\":[1,1,0]},"
        "{\"bufferView\":1,\"componentType\":5126,\"count\":4,\"type\":\"VEC2\"},"
        "{\"bufferView\":2,\"componentType\":5123,\"count\":6,\"type\":\"SCALAR\"}]}",
        mat_json, buffer, with_png ? image : "");
    assert_true(n > 0 && (size_t)n < size);
}

static const char *textured_material = "{\"name\":\"painted\",\"pbrMetallicRoughness\":{\"baseColorTexture\":"
                                       "{\"index\":0},\"metallicFactor\":0,\"roughnessFactor\":1}}";

/* Writes a GLB of the quad with the embedded PNG; returns its size. */
static size_t write_glb(const char *name, const char *mat_json, unsigned char *out, size_t cap)
{
    unsigned char bin[256];
    size_t bin_len = gltf_buffer(bin, true);
    while (bin_len % 4)
        bin[bin_len++] = 0;
    char json[8192];
    gltf_json(json, sizeof json, NULL, bin_len, true, mat_json);
    size_t json_len = strlen(json);
    while (json_len % 4)
        json[json_len++] = ' ';
    uint32_t total = (uint32_t)(12 + 8 + json_len + 8 + bin_len);
    assert_true(total <= cap);
    uint32_t head[5] = {0x46546C67, 2, total, (uint32_t)json_len, 0x4E4F534A};
    memcpy(out, head, sizeof head);
    memcpy(out + 20, json, json_len);
    uint32_t bin_head[2] = {(uint32_t)bin_len, 0x004E4942};
    memcpy(out + 20 + json_len, bin_head, sizeof bin_head);
    memcpy(out + 28 + json_len, bin, bin_len);
    if (name)
        write_bytes(name, out, total);
    return total;
}

/* Replaces the first `from` in text (which must hold it) by `to`. */
static void replace_in(char *text, size_t size, const char *from, const char *to)
{
    char *at = strstr(text, from);
    assert_non_null(at);
    size_t tail = strlen(at + strlen(from));
    assert_true((size_t)(at - text) + strlen(to) + tail < size);
    memmove(at + strlen(to), at + strlen(from), tail + 1);
    memcpy(at, to, strlen(to));
}

/* The quad as glTF text into json (size bytes), its buffer in a data URI,
 * with the materials `mat_json` (JSON objects, comma-separated). */
static void gltf_with_materials(char *json, size_t size, const char *mat_json)
{
    unsigned char bin[256];
    size_t n = gltf_buffer(bin, false);
    char uri[512] = "data:application/octet-stream;base64,";
    base64(bin, n, uri + strlen(uri));
    gltf_json(json, size, uri, n, false, mat_json);
}

/* ------------------------------------------------------------ shared data */

/* Imports $GLINT_SHARED_DATA/name, skipping (and freeing s) when it is absent. */
static const mesh *import_shared(glint_scene *s, const char *name)
{
    const char *data = getenv("GLINT_SHARED_DATA");
    char path[PATH_SIZE];
    if (data)
        snprintf(path, sizeof path, "%s/%s", data, name);
    if (!data || access(path, R_OK) != 0) {
        glint_scene_free(s); /* skip() leaves the test here */
        skip();
    }
    glint_error err = {0};
    int m = glint_scene_import_mesh(s, path, NULL, &err);
    if (m < 0)
        fail_msg("importing %s: %s", path, err.message);
    return &s->meshes[m];
}

static void test_bunny(void **state)
{
    glint_scene *s = new_scene();
    const mesh *m = import_shared(s, "stanford-bunny.obj");
    assert_int_equal(m->triangle_count, 69451);
    assert_int_equal(glint_scene_get_counts(s).triangles, 69451);
    /* 35,947 in the file, less those no triangle uses */
    assert_true(m->vertex_count > 30000 && m->vertex_count <= 35947);
    assert_non_null(m->normals);
    /* no MTL: one grey material for the whole mesh */
    assert_null(m->materials);
    assert_int_equal(m->material, scene_find_material(s, "stanford-bunny/default"));
    assert_near(material_named(s, "stanford-bunny/default")->color.g, 0.5, 1e-12);
    glint_scene_free(s);
}

static void test_teapot(void **state)
{
    glint_scene *s = new_scene();
    const mesh *m = import_shared(s, "teapot.obj");
    assert_int_equal(m->triangle_count, 6320);
    glint_scene_free(s);
}

static void test_cornell_box(void **state)
{
    glint_scene *s = new_scene();
    const mesh *m = import_shared(s, "CornellBox-Original.obj");
    assert_int_equal(m->triangle_count, 36);
    assert_non_null(m->materials);
    const glint_material *left = material_named(s, "CornellBox-Original/leftWall");
    const glint_material *right = material_named(s, "CornellBox-Original/rightWall");
    assert_true(left->color.r > 5 * left->color.g && left->color.r > 5 * left->color.b);
    assert_true(right->color.g > 5 * right->color.r && right->color.g > 5 * right->color.b);
    /* Kd 0.63 0.065 0.05, a display colour, made linear */
    assert_near(left->color.r, glint_srgb_to_linear(0.63), 1e-6);
    assert_near(left->color.g, glint_srgb_to_linear(0.065), 1e-6);
    /* eight materials, all used; none made up */
    assert_int_equal(s->material_count, 8);
    assert_int_equal(scene_find_material(s, "CornellBox-Original/default"), -1);
    glint_scene_free(s);
}

/* Renders s (its meshes placed once each, as imported) at w x h with a
 * white point light near the camera and a black background. */
static glint_image render_imported(glint_scene *s, int w, int h, glint_camera cam, glint_vec3 lamp)
{
    glint_settings st = glint_settings_default();
    st.width = w;
    st.height = h;
    st.background = (glint_color){0, 0, 0};
    assert_int_equal(glint_scene_set_settings(s, &st, NULL), GLINT_OK);
    assert_int_equal(glint_scene_set_camera(s, &cam, NULL), GLINT_OK);
    glint_light l = {.kind = GLINT_LIGHT_POINT, .position = lamp, .color = {1, 1, 1}};
    assert_true(glint_scene_add_light(s, &l, NULL) >= 0);
    for (int i = 0; i < s->mesh_count; i++)
        assert_true(glint_scene_add_instance(s, i, -1, NULL, NULL) >= 0);
    glint_image img;
    assert_int_equal(glint_render(s, NULL, &img, NULL, NULL), GLINT_OK);
    return img;
}

/* The bunny seen from the front: every pixel it covers lies inside its
 * bounding box as the camera projects it, and it covers a plausible share
 * of that box (a bunny, not a speck or a block). */
static void test_bunny_renders_inside_its_bounds(void **state)
{
    glint_scene *s = new_scene();
    const mesh *m = import_shared(s, "stanford-bunny.obj");
    vec3 lo = m->lo, hi = m->hi, c = v3_scale(v3_add(lo, hi), 0.5);
    glint_camera cam = {.position = {c.x, c.y, c.z + 0.5}, .look_at = {c.x, c.y, c.z}, .up = {0, 1, 0}, .vfov_degrees = 30};
    const int w = 200, h = 200;
    glint_image img = render_imported(s, w, h, cam, cam.position);
    /* The box's corners through the pinhole: x, y in pixels. */
    double half = tan(15 * M_PI / 180), x0 = w, x1 = 0, y0 = h, y1 = 0;
    for (int k = 0; k < 8; k++) {
        vec3 p = v3(k & 1 ? hi.x : lo.x, k & 2 ? hi.y : lo.y, k & 4 ? hi.z : lo.z);
        double depth = cam.position.z - p.z;
        double px = (1 + (p.x - c.x) / depth / half) * w / 2, py = (1 - (p.y - c.y) / depth / half) * h / 2;
        x0 = fmin(x0, px);
        x1 = fmax(x1, px);
        y0 = fmin(y0, py);
        y1 = fmax(y1, py);
    }
    int covered = 0, outside = 0;
    for (int y = 0; y < h; y++)
        for (int x = 0; x < w; x++) {
            const float *p = img.pixels + 3 * ((size_t)y * w + x);
            if (p[0] + p[1] + p[2] <= 0)
                continue;
            covered++;
            outside += x + 1 < x0 || x > x1 + 1 || y + 1 < y0 || y > y1 + 1;
        }
    double box = (x1 - x0) * (y1 - y0);
    print_message("bunny: %d pixels in a projected box of %.0f (%.0f%%)\n", covered, box, 100 * covered / box);
    assert_int_equal(outside, 0);
    assert_true(covered > 0.35 * box && covered < 0.9 * box);
    glint_image_free(&img);
    glint_scene_free(s);
}

/* The Cornell box through its open front, lit from under the ceiling: the
 * left wall renders red and the right wall green. */
static void test_cornell_box_renders_red_and_green_walls(void **state)
{
    glint_scene *s = new_scene();
    import_shared(s, "CornellBox-Original.obj");
    glint_camera cam = {.position = {0, 1, 3.9}, .look_at = {0, 1, 0}, .up = {0, 1, 0}, .vfov_degrees = 37};
    glint_image img = render_imported(s, 64, 64, cam, (glint_vec3){0, 1.9, 0});
    const float *left = img.pixels + 3 * (32 * 64 + 3), *right = img.pixels + 3 * (32 * 64 + 60);
    assert_true(left[0] > 0.05f && left[0] > 3 * left[1] && left[0] > 3 * left[2]);
    assert_true(right[1] > 0.05f && right[1] > 2 * right[0] && right[1] > 2 * right[2]);
    glint_image_free(&img);
    glint_scene_free(s);
}

/* A model Assimp reads without normals gets them as an OBJ does (glint's
 * own, angle-weighted within the crease angle). */
static void test_assimp_generated_normals_crease(void **state)
{
    write_text("cube.ply", "ply\nformat ascii 1.0\nelement vertex 8\nproperty float x\nproperty float y\n"
                           "property float z\nelement face 6\nproperty list uchar int vertex_indices\nend_header\n"
                           "-1 -1 -1\n1 -1 -1\n1 1 -1\n-1 1 -1\n-1 -1 1\n1 -1 1\n1 1 1\n-1 1 1\n"
                           "4 0 3 2 1\n4 4 5 6 7\n4 0 1 5 4\n4 3 7 6 2\n4 0 4 7 3\n4 1 2 6 5\n");
    expect_cube_normals("cube.ply");
}

/* ------------------------------------------------------------- PLY, STL */

static const char ply_header[] = "element vertex 4\nproperty float x\nproperty float y\nproperty float z\n"
                                 "element face 1\nproperty list uchar int vertex_indices\nend_header\n";

static void expect_unit_quad(const mesh *m)
{
    assert_int_equal(m->triangle_count, 2);
    assert_int_equal(m->vertex_count, 4);
    for (int v = 0; v < 4; v++) {
        assert_true(m->positions[3 * v] == 0 || m->positions[3 * v] == 1);
        assert_true(m->positions[3 * v + 1] == 0 || m->positions[3 * v + 1] == 1);
        assert_near(m->positions[3 * v + 2], 0, 0);
        assert_near(m->normals[3 * v + 2], 1, 1e-6);
    }
}

static void test_ply_ascii_and_binary(void **state)
{
    char text[1024];
    snprintf(text, sizeof text, "ply\nformat ascii 1.0\ncomment a quad\n%s0 0 0\n1 0 0\n1 1 0\n0 1 0\n4 0 1 2 3\n",
             ply_header);
    write_text("quad.ply", text);
    unsigned char bin[1024];
    int n = snprintf((char *)bin, sizeof bin, "ply\nformat binary_little_endian 1.0\n%s", ply_header);
    const float pos[12] = {0, 0, 0, 1, 0, 0, 1, 1, 0, 0, 1, 0};
    const int32_t idx[4] = {0, 1, 2, 3};
    memcpy(bin + n, pos, sizeof pos);
    bin[n + sizeof pos] = 4;
    memcpy(bin + n + sizeof pos + 1, idx, sizeof idx);
    write_bytes("quadb.ply", bin, (size_t)n + sizeof pos + 1 + sizeof idx);
    glint_scene *s = new_scene();
    expect_unit_quad(import_ok(s, "quad.ply", NULL));
    expect_unit_quad(import_ok(s, "quadb.ply", NULL));
    assert_int_equal(s->meshes[1].material, scene_find_material(s, "quadb/default"));
    assert_true(glint_scene_mesh_is_bare(s, 1)); /* PLY has no materials */
    glint_scene_free(s);
}

static void test_stl_ascii_and_binary(void **state)
{
    write_text("quad.stl", "solid quad\n"
                           "facet normal 0 0 1\nouter loop\nvertex 0 0 0\nvertex 1 0 0\nvertex 1 1 0\nendloop\nendfacet\n"
                           "facet normal 0 0 1\nouter loop\nvertex 0 0 0\nvertex 1 1 0\nvertex 0 1 0\nendloop\nendfacet\n"
                           "endsolid quad\n");
    unsigned char bin[84 + 2 * 50] = "binary quad";
    uint32_t count = 2;
    memcpy(bin + 80, &count, 4);
    const float facets[2][12] = {{0, 0, 1, 0, 0, 0, 1, 0, 0, 1, 1, 0}, {0, 0, 1, 0, 0, 0, 1, 1, 0, 0, 1, 0}};
    for (int f = 0; f < 2; f++)
        memcpy(bin + 84 + 50 * f, facets[f], sizeof facets[f]);
    write_bytes("quadb.stl", bin, sizeof bin);
    glint_scene *s = new_scene();
    expect_unit_quad(import_ok(s, "quad.stl", NULL));
    expect_unit_quad(import_ok(s, "quadb.stl", NULL));
    glint_scene_free(s);
}

/* ------------------------------------------------------------------ glTF */

/* The quad placed by the node hierarchy: x 1..3, y 2..4, z 3. */
static void expect_flattened(const glint_scene *s, int mesh_index)
{
    glint_vec3 lo, hi;
    assert_int_equal(glint_scene_mesh_bounds(s, mesh_index, &lo, &hi, NULL), GLINT_OK);
    assert_near(lo.x, 1, 1e-6);
    assert_near(lo.y, 2, 1e-6);
    assert_near(lo.z, 3, 1e-6);
    assert_near(hi.x, 3, 1e-6);
    assert_near(hi.y, 4, 1e-6);
    assert_near(hi.z, 3, 1e-6);
}

static void test_gltf_data_uri(void **state)
{
    char json[8192];
    gltf_with_materials(json, sizeof json,
                        "{\"name\":\"shiny\",\"pbrMetallicRoughness\":{\"baseColorFactor\":[0.5,0.25,0.125,1],"
                        "\"metallicFactor\":0.5,\"roughnessFactor\":0.5},\"extensions\":{"
                        "\"KHR_materials_transmission\":{\"transmissionFactor\":0.75},"
                        "\"KHR_materials_ior\":{\"ior\":1.4}}}");
    write_text("shiny.gltf", json);
    glint_scene *s = new_scene();
    const mesh *m = import_ok(s, "shiny.gltf", NULL);
    assert_int_equal(m->triangle_count, 2);
    expect_flattened(s, 0);
    const glint_material *g = material_named(s, "shiny/shiny");
    assert_int_equal(s->material_count, 1);
    assert_near(g->color.r, 0.5, 1e-6);
    assert_near(g->color.g, 0.25, 1e-6);
    assert_near(g->color.b, 0.125, 1e-6);
    assert_near(g->reflectivity, 0.5, 1e-6);
    assert_near(g->metallic, 0.5, 1e-6);
    assert_near(g->diffuse, 0.5, 1e-6);
    assert_near(g->specular, 0.5, 1e-6);
    assert_near(g->shininess, 30, 1e-4);
    assert_near(g->refraction, 0.75, 1e-6);
    assert_near(g->ior, 1.4, 1e-6);
    assert_true(g->fresnel);
    assert_int_equal(g->texture, -1);
    glint_scene_free(s);
}

static void test_gltf_blend_and_unnamed(void **state)
{
    char json[8192];
    gltf_with_materials(json, sizeof json,
                        "{\"pbrMetallicRoughness\":{\"baseColorFactor\":[0.2,0.4,0.6,0.4],\"metallicFactor\":0},"
                        "\"alphaMode\":\"BLEND\"}");
    write_text("veil.gltf", json);
    glint_scene *s = new_scene();
    import_ok(s, "veil.gltf", NULL);
    const glint_material *g = material_named(s, "veil/material0");
    assert_near(g->transparency, 0.6, 1e-6);
    assert_near(g->reflectivity, 0, 0);
    assert_near(g->metallic, 0, 0);
    assert_near(g->specular, 0, 0);
    glint_scene_free(s);
}

static void test_glb_embedded_texture(void **state)
{
    unsigned char glb[4096];
    write_glb("painted.glb", textured_material, glb, sizeof glb);
    glint_scene *s = new_scene();
    const mesh *m = import_ok(s, "painted.glb", NULL);
    expect_flattened(s, 0);
    assert_int_equal(s->texture_count, 1);
    assert_int_equal(material_named(s, "painted/painted")->texture, 0);
    /* glTF's v already runs down: the top corners keep v = 0 */
    for (int v = 0; v < m->vertex_count; v++)
        assert_near(m->uvs[2 * v + 1], (4 - m->positions[3 * v + 1]) / 2, 1e-6);
    expect_red_over_blue(s, 0, (glint_vec3){2, 3, 5});
    glint_scene_free(s);
}

/* glTF's normalTexture is the material's normal map, the same image here
 * as its base colour's, added once. */
static void test_gltf_normal_texture(void **state)
{
    unsigned char glb[4096];
    write_glb("bumpy.glb",
              "{\"name\":\"bumpy\",\"pbrMetallicRoughness\":{\"baseColorTexture\":{\"index\":0},"
              "\"metallicFactor\":0},\"normalTexture\":{\"index\":0}}",
              glb, sizeof glb);
    glint_scene *s = new_scene();
    import_ok(s, "bumpy.glb", NULL);
    const glint_material *m = material_named(s, "bumpy/bumpy");
    assert_int_equal(s->texture_count, 1);
    assert_int_equal(m->texture, 0);
    assert_int_equal(m->normal_texture, 0);
    assert_int_equal(m->bump_texture, -1);
    glint_scene_free(s);
}

/* A material glowing white, named `name`, with `extension` (JSON members,
 * or "") added to its extensions. */
static void glowing(char *out, size_t size, const char *name, const char *extension)
{
    int n = snprintf(out, size, "{\"name\":\"%s\",\"emissiveFactor\":[1,1,1],\"extensions\":{%s}}", name, extension);
    assert_true(n > 0 && (size_t)n < size);
}

#define STRENGTH_5 "\"KHR_materials_emissive_strength\":{\"emissiveStrength\":5}"

/* KHR_materials_emissive_strength, which Assimp 5.2.5 drops, multiplies
 * emissiveFactor: a strength of 5 glows five times as bright as none. */
static void test_gltf_emissive_strength(void **state)
{
    char mat[512], json[8192];
    glowing(mat, sizeof mat, "plain", "");
    gltf_with_materials(json, sizeof json, mat);
    write_text("plain.gltf", json);
    glowing(mat, sizeof mat, "lamp", STRENGTH_5);
    gltf_with_materials(json, sizeof json, mat);
    write_text("lamp.gltf", json);
    unsigned char glb[4096];
    write_glb("lamp.glb", mat, glb, sizeof glb);
    glint_scene *s = new_scene();
    import_ok(s, "plain.gltf", NULL);
    import_ok(s, "lamp.gltf", NULL);
    import_ok(s, "lamp.glb", NULL);
    const glint_material *plain = material_named(s, "plain/plain");
    assert_true(plain->emission.r == 1 && plain->emission.g == 1 && plain->emission.b == 1);
    assert_true(plain->emission_strength == 1);
    const char *lamps[] = {"lamp/lamp", "lamp/lamp#2"};
    for (int k = 0; k < 2; k++) {
        const glint_material *lamp = material_named(s, lamps[k]);
        assert_true(lamp->emission.r == 1 && lamp->emission.g == 1 && lamp->emission.b == 1);
        assert_true(lamp->emission_strength == 5);
        assert_true(material_emission(lamp).g == 5 * material_emission(plain).g);
    }
    glint_scene_free(s);
}

/* Assimp numbers a glTF's materials as its reading of the scene meets
 * them, children before their parent's mesh, not in the file's order:
 * each strength must reach its own material. */
static void test_gltf_emissive_strength_order(void **state)
{
    char mats[2048] = "", mat[512], json[8192];
    const char *const names[] = {"unused", "b", "c", "d"};
    const char *const strengths[] = {"9", "2", "3", "4"};
    for (int k = 0; k < 4; k++) {
        char extension[128];
        snprintf(extension, sizeof extension, "\"KHR_materials_emissive_strength\":{\"emissiveStrength\":%s}",
                 strengths[k]);
        glowing(mat, sizeof mat, names[k], extension);
        strcat(mats, k ? "," : "");
        strcat(mats, mat);
    }
    gltf_with_materials(json, sizeof json, mats);
    /* The child's mesh 0 uses c then b; its parent's mesh 1 uses d. */
    replace_in(json, sizeof json, "\"material\":0}]}]",
               "\"material\":2},{\"attributes\":{\"POSITION\":0},\"indices\":2,\"material\":1}]},"
               "{\"primitives\":[{\"attributes\":{\"POSITION\":0},\"indices\":2,\"material\":3}]}]");
    replace_in(json, sizeof json, "\"name\":\"parent\",", "\"name\":\"parent\",\"mesh\":1,");
    write_text("order.gltf", json);
    glint_scene *s = new_scene();
    import_ok(s, "order.gltf", NULL);
    assert_int_equal(s->material_count, 3);
    assert_true(material_named(s, "order/b")->emission_strength == 2);
    assert_true(material_named(s, "order/c")->emission_strength == 3);
    assert_true(material_named(s, "order/d")->emission_strength == 4);
    glint_scene_free(s);
}

/* What is odd about a strength is read as a JSON parser reads it, or left
 * out: escaped keys, the first of two equal keys, values that are not
 * numbers or not objects, a strength beyond glint's range. */
static void test_gltf_emissive_strength_odd(void **state)
{
    static const struct {
        const char *extension;
        double strength;
    } cases[] = {
        {"\"KHR_materials_emissive_strength\":{\"emissive\\u0053trength\":2.5e0}", 2.5},
        {"\"KHR_materials_emissive_str\\u0065ngth\":{\"emissiveStrength\":6}", 6},
        {"\"KHR_materials_emissive_strength\":{\"emissiveStrength\":2,\"emissiveStrength\":7}", 2},
        {"\"KHR_materials_emissive_strength\":{\"emissiveStrength\":\"5\"}", 1},
        {"\"KHR_materials_emissive_strength\":{\"emissiveStrength\":[5]}", 1},
        {"\"KHR_materials_emissive_strength\":{\"emissiveStrength\":null}", 1},
        {"\"KHR_materials_emissive_strength\":5", 1},
        {"\"KHR_materials_emissive_strength\":[{\"emissiveStrength\":5}]", 1},
        {"\"other\":{\"emissiveStrength\":5}", 1},
        {"\"KHR_materials_emissive_strength\":{}", 1},
        {"\"KHR_materials_emissive_strength\":{\"emissiveStrength\":0}", 0},
        {"\"KHR_materials_emissive_strength\":{\"emissiveStrength\":-0}", 0},
        {"\"KHR_materials_emissive_strength\":{\"emissiveStrength\":1e308}", 1e300},
    };
    for (size_t k = 0; k < sizeof cases / sizeof cases[0]; k++) {
        char mat[512], json[8192];
        glowing(mat, sizeof mat, "odd", cases[k].extension);
        gltf_with_materials(json, sizeof json, mat);
        write_text("odd.gltf", json);
        glint_scene *s = new_scene();
        import_ok(s, "odd.gltf", NULL);
        const glint_material *g = material_named(s, "odd/odd");
        if (g->emission_strength != cases[k].strength || signbit(g->emission_strength))
            fail_msg("%s: strength %.17g, expected %.17g", cases[k].extension, g->emission_strength,
                     cases[k].strength);
        glint_scene_free(s);
    }
    /* Extensions, or a material, that are no object are passed over, for
     * Assimp to refuse. */
    char json[8192];
    gltf_with_materials(json, sizeof json, "{\"extensions\":7},5");
    write_text("odd.gltf", json);
    expect_refused_by_assimp("odd.gltf");
}

/* A strength below zero, or too large for a double, is refused, in any
 * material, used or not, of a glTF or a GLB. */
static void test_gltf_emissive_strength_refused(void **state)
{
    char mats[1024], mat[512], json[8192];
    glowing(mats, sizeof mats, "lamp", STRENGTH_5);
    glowing(mat, sizeof mat, "dim", "\"KHR_materials_emissive_strength\":{\"emissiveStrength\":-5}");
    strcat(mats, ",");
    strcat(mats, mat);
    gltf_with_materials(json, sizeof json, mats);
    write_text("dim.gltf", json);
    expect_refused("dim.gltf", NULL, "material 1: emissiveStrength -5 (KHR_materials_emissive_strength) is negative");
    unsigned char glb[4096];
    write_glb("dim.glb", mats, glb, sizeof glb);
    expect_refused("dim.glb", NULL, "material 1: emissiveStrength -5 (KHR_materials_emissive_strength) is negative");
    replace_in(json, sizeof json, "-5", "1e999");
    write_text("bright.gltf", json);
    expect_refused("bright.gltf", NULL,
                   "material 1: emissiveStrength 1e999 (KHR_materials_emissive_strength) is not finite");
}

/* ---------------------------------------------------------------- memory */

static void test_memory_imports(void **state)
{
    glint_scene *s = new_scene();
    glint_error err = {0};
    unsigned char glb[4096];
    size_t n = write_glb(NULL, textured_material, glb, sizeof glb);
    int m = glint_scene_import_mesh_memory(s, glb, n, "models/Painted.GLB", NULL, &err);
    assert_int_equal(m, 0);
    assert_int_equal(s->texture_count, 1);
    assert_true(scene_find_material(s, "Painted/painted") >= 0);
    /* the MTL file beside the working directory is not read */
    write_text("parts.mtl", parts_mtl);
    char cwd[PATH_SIZE];
    assert_non_null(getcwd(cwd, sizeof cwd));
    assert_int_equal(chdir(tmp_dir), 0);
    m = glint_scene_import_mesh_memory(s, parts_obj, strlen(parts_obj), "parts.obj", NULL, &err);
    assert_int_equal(chdir(cwd), 0);
    assert_int_equal(m, 1);
    assert_true(material_named(s, "parts/red")->color.g > 0.1);
    glint_scene_free(s);
}

static void test_memory_refusals(void **state)
{
    glint_scene *s = new_scene();
    glint_error err = {0};
    assert_int_equal(glint_scene_import_mesh_memory(s, "x", 1, NULL, NULL, &err), -1);
    assert_string_equal(err.message, "import needs a scene, a name and data");
    assert_int_equal(glint_scene_import_mesh_memory(s, NULL, 5, "a.obj", NULL, &err), -1);
    assert_string_equal(err.message, "import needs a scene, a name and data");
    assert_int_equal(glint_scene_import_mesh_memory(s, "", 0, "empty.glb", NULL, &err), -1);
    assert_string_equal(err.message, "empty.glb: not a binary glTF file (it does not start with 'glTF')");
    assert_int_equal(glint_scene_import_mesh_memory(s, "v 0 0 0\n", 8, "model", NULL, &err), -1);
    assert_string_equal(err.message, "model: unsupported format (glint imports .obj, .ply, .stl, .gltf and .glb)");
    /* a glTF whose buffer is a file: not read from memory */
    unsigned char bin[256];
    char json[8192];
    gltf_json(json, sizeof json, "quad.bin", gltf_buffer(bin, false), false, textured_material);
    write_bytes("quad.bin", bin, QUAD_BYTES);
    assert_int_equal(glint_scene_import_mesh_memory(s, json, strlen(json), "quad.gltf", NULL, &err), -1);
    assert_true(strncmp(err.message, "quad.gltf: ", 11) == 0 && strlen(err.message) > 11);
    assert_int_equal(glint_scene_get_counts(s).meshes, 0);
    glint_scene_free(s);
}

/* glint_is_model_path takes a name by the same table the importer picks its
 * reader by: what it takes is never refused as an unsupported format. */
static void test_model_paths(void **state)
{
    static const char *const models[] = {"a.obj", "A.OBJ", "dir/b.Ply", "c.stl", "d.gltf", "e.GLB", ".obj"};
    static const char *const others[] = {"a.fbx", "obj", "dir.obj/file", "a.obj.yaml", "a.", ""};
    glint_error err = {0};
    for (size_t i = 0; i < sizeof models / sizeof models[0]; i++) {
        glint_scene *s = new_scene();
        assert_true(glint_is_model_path(models[i]));
        assert_int_equal(glint_scene_import_mesh_memory(s, "", 0, models[i], NULL, &err), -1);
        assert_null(strstr(err.message, "unsupported format"));
        glint_scene_free(s);
    }
    for (size_t i = 0; i < sizeof others / sizeof others[0]; i++)
        assert_false(glint_is_model_path(others[i]));
    assert_false(glint_is_model_path(NULL));
}

/* --------------------------------------------------------------- refusals */

static void test_refused_files(void **state)
{
    expect_refused("absent.obj", NULL, "cannot open: No such file or directory");
    char dir[PATH_SIZE];
    tmp_path(dir, "folder.obj");
    assert_int_equal(mkdir(dir, 0755), 0);
    expect_refused("folder.obj", NULL, "cannot read: Is a directory");
    write_text("model.fbx", "; FBX 7.4.0 project file\n");
    expect_refused("model.fbx", NULL, "unsupported format (glint imports .obj, .ply, .stl, .gltf and .glb)");
    write_text("text.glb", "this is not a model\n");
    expect_refused("text.glb", NULL, "not a binary glTF file (it does not start with 'glTF')");
    write_text("text.gltf", "solid x\nendsolid x\n");
    expect_refused("text.gltf", NULL, "not a glTF file (it does not start with a JSON object)");
    write_text("lines.obj", "v 0 0 0\nv 1 0 0\nv 0 1 0\nl 1 2\nl 2 3\np 1\n");
    expect_refused("lines.obj", NULL, "no triangles");
    write_text("nan.obj", "v nan 0 0\nv 1 0 inf\nv 0 1 0\nf 1 2 3\n");
    expect_refused_at("nan.obj", "1:3: a vertex is not finite (nan 0 0)");
    write_text("inf.ply", "ply\nformat ascii 1.0\nelement vertex 3\nproperty float x\nproperty float y\n"
                          "property float z\nelement face 1\nproperty list uchar int vertex_indices\nend_header\n"
                          "0 0 0\n1 0 1e39\n0 1 0\n3 0 1 2\n");
    expect_refused("inf.ply", NULL, "a vertex is not finite (1 0 inf)");
    /* a PLY list longer than its line, which Assimp reads past */
    write_text("noface.ply", "ply\nformat ascii 1.0\nelement vertex 3\nproperty float x\nproperty float y\n"
                             "property float z\nelement face 2\nproperty list uchar int vertex_indices\nend_header\n"
                             "0 0 0\n1 0 0\n0 1 0\n44 0 1\n3 0 1 2\n");
    expect_refused("noface.ply", NULL, "PLY data of element 'face' item 0 does not match the header");
}

static void test_refused_options(void **state)
{
    write_text("plain.obj", "v 0 0 0\nv 1 0 0\nv 0 1 0\nf 1 2 3\n");
    glint_import_options o = {.crease_angle = -5, .default_material = -1};
    expect_refused("plain.obj", &o, "crease angle must be in (0, 180] degrees, got -5");
    o.crease_angle = 181;
    expect_refused("plain.obj", &o, "crease angle must be in (0, 180] degrees, got 181");
    o.crease_angle = NAN;
    expect_refused("plain.obj", &o, "crease angle must be in (0, 180] degrees, got nan");
    o.crease_angle = 0;
    o.default_material = 3;
    expect_refused("plain.obj", &o, "default material 3 does not exist");
    o.default_material = -2;
    expect_refused("plain.obj", &o, "default material -2 does not exist");
}

static void test_refused_ply(void **state)
{
    char text[1024];
    snprintf(text, sizeof text, "ply\nformat ascii 1.0\n%s", ply_header);
    /* the header alone, then cut inside it */
    write_text("nodata.ply", text);
    expect_refused("nodata.ply", NULL,
                   "PLY element 'vertex' claims 4 items, more than the file's 0 bytes of data can hold");
    text[strlen(text) - 5] = '\0';
    write_text("cuthead.ply", text);
    expect_refused("cuthead.ply", NULL, "PLY header line 9 is not understood");
    write_text("nohead.ply", "ply\nformat ascii 1.0\ncomment no end\n");
    expect_refused("nohead.ply", NULL, "PLY header has no end_header line");
    write_text("badtype.ply", "ply\nformat ascii 1.0\nelement vertex 1\nproperty quad x\nend_header\n0\n");
    expect_refused("badtype.ply", NULL, "PLY header line 4 is not understood");
    write_text("badcount.ply", "ply\nformat ascii 1.0\nelement vertex 3bad\nproperty float x\nend_header\n0\n");
    expect_refused("badcount.ply", NULL, "PLY header line 3 is not understood");
    write_text("twice.ply", "ply\nformat ascii 1.0\nformat ascii 1.0\nend_header\n");
    expect_refused("twice.ply", NULL, "PLY header line 3 is not understood");
    snprintf(text, sizeof text, "ply\nformat ascii 1.0\n%s0 0 0\n1 0\n1 1 0\n0 1 0\n4 0 1 2 3\n", ply_header);
    write_text("short.ply", text);
    expect_refused("short.ply", NULL, "PLY data of element 'vertex' item 1 does not match the header");
    snprintf(text, sizeof text, "ply\nformat ascii 1.0\n%s0 0 0\n1 0 0\n1 1 0\n0 1 0\n4 0 1 2 x\n", ply_header);
    write_text("word.ply", text);
    expect_refused("word.ply", NULL, "PLY data of element 'face' item 0 does not match the header");
    write_text("huge.ply", "ply\nformat ascii 1.0\nelement vertex 4000000000\nproperty float x\nproperty float y\n"
                           "property float z\nelement face 1\nproperty list uchar int vertex_indices\nend_header\n"
                           "0 0 0\n1 0 0\n0 1 0\n3 0 1 2\n");
    expect_refused("huge.ply", NULL,
                   "PLY element 'vertex' claims 4000000000 items, more than the file's 26 bytes of data can hold");
    write_text("hugeb.ply", "ply\nformat binary_little_endian 1.0\nelement vertex 3\nproperty double x\n"
                            "property double y\nproperty double z\nend_header\n0123456789012345678901234567890123456789");
    expect_refused("hugeb.ply", NULL,
                   "PLY element 'vertex' claims 3 items, more than the file's 40 bytes of data can hold");
    snprintf(text, sizeof text, "ply\nformat ascii 1.0\n%s0 0 0\n1 0 0\n1 1 0\n0 1 0\n4 0 1 2 9\n", ply_header);
    write_text("range.ply", text);
    expect_refused_by_assimp("range.ply");
    write_text("empty.ply", "");
    expect_refused("empty.ply", NULL, "PLY header has no end_header line");
    /* a vertical tab once stopped the header check from moving on */
    write_text("vtab.ply", "ply\nformat ascii 1.0\nelement vertex 3\x0b\nproperty float x\n");
    expect_refused("vtab.ply", NULL, "PLY header line 3 is not understood");
    /* Found by fuzz_mesh: Assimp ends a line at a form feed, the check did
     * not, and the two read different headers (Assimp then read outside its
     * buffer). Control characters other than tabs are refused in a header,
     * comments too; CRLF line ends are fine. */
    write_text("formfeed.ply", "ply\nformat ascii 1.0\nelement vertex 3\n\f\fend_header\n");
    expect_refused("formfeed.ply", NULL, "PLY header line 4 is not understood");
    write_text("comment.ply", "ply\nformat ascii 1.0\ncomment a\fend_header\n");
    expect_refused("comment.ply", NULL, "PLY header line 3 is not understood");
    write_text("crlf.ply", "ply\r\nformat ascii 1.0\r\nelement vertex 3\r\nproperty float x\r\nproperty float y\r\n"
                           "property float z\r\nelement face 1\r\nproperty list uchar int vertex_indices\r\n"
                           "end_header\r\n0 0 0\r\n1 0 0\r\n0 1 0\r\n3 0 1 2\r\n");
    glint_scene *s = new_scene();
    import_ok(s, "crlf.ply", NULL);
    assert_int_equal(glint_scene_get_counts(s).triangles, 1);
    glint_scene_free(s);
}

/* Found by fuzz_mesh (tests/fuzz/regressions/mesh/): a binary PLY whose y
 * property line is misspelt tripped an assertion in Assimp's triangulation,
 * which Debian's build turns into an abort. The header check stops it now. */
static void test_fuzz_ply_assertion(void **state)
{
    unsigned char data[512];
    int n = snprintf((char *)data, sizeof data, "ply\nformat binary_big_endian 1.0\nelement vertex 4\n"
                                                "property float x\neoprprty float y\nproperty float z\n"
                                                "element face 1\nproperty list uchar int vertex_indices\n"
                                                "end_header\n");
    static const unsigned char body[65] = {
        0, 0, 0, 0, 0, 0, 0, 0, 0, 0, 0, 0, 0x3f, 0x80, 0, 0, 0, 0, 0, 0, 0, 0, 0, 0,
        0x3f, 0x80, 0, 0, 0x3f, 0x80, 0, 0, 0, 0, 0, 0, 0, 0, 0, 0, 0x3f, 0x80, 0, 0, 0, 0, 0, 0,
        4, 0, 0, 0, 0, 0, 0, 0, 1, 0, 0, 0, 2, 0, 0, 0, 3,
    };
    memcpy(data + n, body, sizeof body);
    write_bytes("assert.ply", data, (size_t)n + sizeof body);
    expect_refused("assert.ply", NULL, "PLY header line 5 is not understood");
}

/* Found by fuzz_mesh (regressions/mesh/glb-json-chunk-length-assimp-2gb-alloc.glb):
 * Assimp allocates a GLB chunk's claimed length before reading it. The
 * lengths are checked against the file now. */
static void test_fuzz_glb_chunk_length(void **state)
{
    unsigned char glb[4096];
    size_t n = write_glb(NULL, textured_material, glb, sizeof glb);
    uint32_t json, huge = 0x78000000;
    memcpy(&json, glb + 12, 4);
    char want[200];
    memcpy(glb + 12, &huge, 4);
    write_bytes("huge.glb", glb, n);
    snprintf(want, sizeof want, "GLB chunk 0 claims 2013265920 bytes, more than the file's %zu after it", n - 20);
    expect_refused("huge.glb", NULL, want);
    memcpy(glb + 12, &json, 4);
    size_t bin = 20 + (json + 3) / 4 * 4;
    memcpy(glb + bin, &huge, 4);
    write_bytes("huge.glb", glb, n);
    snprintf(want, sizeof want, "GLB chunk 1 claims 2013265920 bytes, more than the file's %zu after it",
             n - bin - 8);
    expect_refused("huge.glb", NULL, want);
}

/* The textured quad as glTF text, its buffer in a data URI and its image
 * given by `image` (a JSON object), written as tmp_dir/name. Returns the
 * column (from 1, on the one line) where `mark` starts. */
static int write_textured_gltf(const char *name, const char *image, const char *mark)
{
    unsigned char bin[1024];
    size_t n = gltf_buffer(bin, true);
    char uri[2048] = "data:application/octet-stream;base64,", json[16384];
    base64(bin, n, uri + strlen(uri));
    gltf_json(json, sizeof json, uri, n, true, textured_material);
    replace_in(json, sizeof json, "{\"bufferView\":3,\"mimeType\":\"image/png\"}", image);
    write_text(name, json);
    return mark ? (int)(strstr(json, mark) - json) + 1 : 0;
}

/* Found by fuzz_mesh (regressions/mesh/glb-mimetype-without-slash-assimp-segv.glb):
 * Assimp's glTF reader takes what follows the '/' of an embedded image's
 * media type without looking for one, and reads from address 1. Such media
 * types are refused, wherever JSON escapes hide them. */
static void test_fuzz_gltf_media_type_without_slash(void **state)
{
    char want[300], png64[512], image[700];
    base64(png_red_over_blue, sizeof png_red_over_blue, png64);

    int col = write_textured_gltf("mime.gltf", "{\"bufferView\":3,\"mimeType\":\"image_png\"}", "\"image_png");
    snprintf(want, sizeof want, "1:%d: image mimeType 'image_png' has no '/' (as in image/png)", col);
    expect_refused_at("mime.gltf", want);
    col = write_textured_gltf("escaped.gltf", "{\"bufferView\":3,\"mime\\u0054ype\":\"image_png\"}", "\"image_png");
    snprintf(want, sizeof want, "1:%d: image mimeType 'image_png' has no '/' (as in image/png)", col);
    expect_refused_at("escaped.gltf", want);
    snprintf(image, sizeof image, "{\"uri\":\"data:image_png;base64,%s\"}", png64);
    col = write_textured_gltf("uri.gltf", image, "\"data:image_png");
    snprintf(want, sizeof want, "1:%d: data URI media type 'image_png' has no '/' (as in image/png)", col);
    expect_refused_at("uri.gltf", want);

    /* Escaped slashes count, and a data URI may name the image's type. */
    write_textured_gltf("slash.gltf", "{\"bufferView\":3,\"mimeType\":\"image\\/png\"}", NULL);
    snprintf(image, sizeof image, "{\"uri\":\"data:image/png;base64,%s\"}", png64);
    write_textured_gltf("good-uri.gltf", image, NULL);
    const char *good[] = {"slash.gltf", "good-uri.gltf"};
    for (int k = 0; k < 2; k++) {
        glint_scene *s = new_scene();
        import_ok(s, good[k], NULL);
        assert_int_equal(s->texture_count, 1);
        glint_scene_free(s);
    }

    /* In a GLB, the position is within its JSON chunk. */
    unsigned char glb[4096];
    size_t n = write_glb(NULL, textured_material, glb, sizeof glb);
    unsigned char *at = NULL;
    for (size_t k = 0; !at && k + 11 <= n; k++)
        if (memcmp(glb + k, "\"image/png\"", 11) == 0)
            at = glb + k;
    assert_non_null(at);
    at[6] = '_';
    write_bytes("mime.glb", glb, n);
    snprintf(want, sizeof want, "JSON chunk 1:%d: image mimeType 'image_png' has no '/' (as in image/png)",
             (int)(at - glb) - 20 + 1);
    expect_refused("mime.glb", NULL, want);
}

static void test_refused_by_assimp(void **state)
{
    write_text("empty.stl", "");
    expect_refused_by_assimp("empty.stl");
    unsigned char stl[84] = "binary";
    uint32_t count = 1000;
    memcpy(stl + 80, &count, 4);
    write_bytes("short.stl", stl, sizeof stl);
    expect_refused_by_assimp("short.stl");
    unsigned char glb[4096];
    size_t n = write_glb(NULL, textured_material, glb, sizeof glb);
    for (size_t cut = 4; cut < n; cut += n / 7) {
        write_bytes("cut.glb", glb, cut);
        expect_refused_by_assimp("cut.glb");
    }
    write_text("broken.gltf", "{\"asset\":{\"version\":\"2.0\"},\"meshes\":[{\"primitives\":[{\"attributes\":{\"POSITION\":7}}]}");
    expect_refused_by_assimp("broken.gltf");
}

/* A run of bad files prints nothing on stdout or stderr. */
static void test_silent(void **state)
{
    char log[PATH_SIZE];
    tmp_path(log, "output.txt");
    fflush(stdout);
    fflush(stderr);
    int out = dup(1), errfd = dup(2), fd = open(log, O_WRONLY | O_CREAT | O_TRUNC, 0644);
    assert_true(out >= 0 && errfd >= 0 && fd >= 0);
    dup2(fd, 1);
    dup2(fd, 2);
    write_text("range.obj", "v 0 0 0\nv 1 0 0\nv 0 1 0\nf 1 2 7\nusemtl nowhere\nf 1 2 3\nq 5\n");
    write_text("lines.obj", "v 0 0 0\nv 1 0 0\nl 1 2\n");
    write_text("empty.stl", "");
    write_text("junk.gltf", "{\"asset\":{\"version\":\"9\"}}");
    const char *names[] = {"range.obj", "lines.obj", "empty.stl", "junk.gltf", "absent.ply"};
    glint_scene *s = new_scene();
    for (size_t i = 0; i < sizeof names / sizeof names[0]; i++)
        import(s, names[i], NULL, NULL);
    glint_scene_free(s);
    fflush(stdout);
    fflush(stderr);
    dup2(out, 1);
    dup2(errfd, 2);
    close(out);
    close(errfd);
    close(fd);
    struct stat st;
    assert_int_equal(stat(log, &st), 0);
    assert_int_equal(st.st_size, 0);
}

int main(void)
{
    const struct CMUnitTest tests[] = {
        cmocka_unit_test(test_bunny),
        cmocka_unit_test(test_teapot),
        cmocka_unit_test(test_cornell_box),
        cmocka_unit_test(test_bunny_renders_inside_its_bounds),
        cmocka_unit_test(test_cornell_box_renders_red_and_green_walls),
        cmocka_unit_test(test_assimp_generated_normals_crease),
        cmocka_unit_test(test_ply_ascii_and_binary),
        cmocka_unit_test(test_stl_ascii_and_binary),
        cmocka_unit_test(test_gltf_data_uri),
        cmocka_unit_test(test_gltf_blend_and_unnamed),
        cmocka_unit_test(test_glb_embedded_texture),
        cmocka_unit_test(test_gltf_normal_texture),
        cmocka_unit_test(test_gltf_emissive_strength),
        cmocka_unit_test(test_gltf_emissive_strength_order),
        cmocka_unit_test(test_gltf_emissive_strength_odd),
        cmocka_unit_test(test_gltf_emissive_strength_refused),
        cmocka_unit_test(test_memory_imports),
        cmocka_unit_test(test_memory_refusals),
        cmocka_unit_test(test_model_paths),
        cmocka_unit_test(test_refused_files),
        cmocka_unit_test(test_refused_options),
        cmocka_unit_test(test_refused_ply),
        cmocka_unit_test(test_refused_by_assimp),
        cmocka_unit_test(test_fuzz_glb_chunk_length),
        cmocka_unit_test(test_fuzz_gltf_media_type_without_slash),
        cmocka_unit_test(test_fuzz_ply_assertion),
        cmocka_unit_test(test_silent),
    };
    return cmocka_run_group_tests(tests, setup_dir, teardown_dir);
}
