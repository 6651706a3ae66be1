/* read_arrays.c - geometry given in the scene file as lists of numbers
 * or a grid of samples: meshes given by their vertices and faces (so a
 * program that writes scenes need not write an OBJ beside them), polygons
 * of more than four points or concave ones, which become the triangles
 * that cover them, and heightfields from a list of rows or a greyscale
 * image. */
#include <stdlib.h>
#include "core/array.h"
#include "geometry/shape_kind.h"
#include "image/texture_image.h"
#include "model/triangulate.h"
#include "scenefile/loader.h"

/* The most vertices, or triangles, an inline mesh may have. */
#define INLINE_MAX (1 << 24)

/* Reads list n of `key` whose items are each `width` numbers (width 3: a
 * vector) into a new array of floats, *count items; NULL after a report
 * (or with *count 0 when n is NULL). */
static float *number_rows(loader *l, const ynode *n, const char *key, int width, int *count)
{
    *count = 0;
    char quoted[40];
    snprintf(quoted, sizeof quoted, "'%s'", key);
    if (!n || !yr_is_list(&l->r, n, quoted))
        return NULL;
    if (n->count < 1 || n->count > INLINE_MAX) {
        diag_at(&l->d, n, "'%s' must hold 1 to %d items, got %d", key, INLINE_MAX, n->count);
        return NULL;
    }
    float *rows = malloc((size_t)n->count * (size_t)width * sizeof *rows);
    if (!rows) {
        diag_raw(&l->d, GLINT_ERR_NOMEM, "out of memory");
        return NULL;
    }
    for (int i = 0; i < n->count; i++) {
        const ynode *item = n->items[i];
        double v[3];
        bool good;
        if (width == 3) {
            vec3 p;
            good = yr_vec3(&l->r, item, key, &p);
            v[0] = p.x, v[1] = p.y, v[2] = p.z;
        } else {
            good = item->kind == YNODE_SEQUENCE && item->count == 2 && yr_number(&l->r, item->items[0], key, &v[0]) &&
                   yr_number(&l->r, item->items[1], key, &v[1]);
            if (!good && item->kind != YNODE_SEQUENCE)
                diag_at(&l->d, item, "each of '%s' must be [u, v]", key);
        }
        if (!good) {
            free(rows);
            return NULL;
        }
        for (int k = 0; k < width; k++)
            rows[i * width + k] = (float)v[k];
    }
    *count = n->count;
    return rows;
}

/* The faces of an inline mesh, each a list of 3 or more vertex numbers
 * below `vertices`, split into triangles: *indices (3 a triangle) and
 * *count. False after a report. */
static bool read_faces(loader *l, const ynode *n, const float *positions, int vertices, uint32_t **indices,
                       int *count)
{
    *indices = NULL;
    *count = 0;
    if (!yr_is_list(&l->r, n, "'faces'"))
        return false;
    size_t cap = 0, used = 0;
    uint32_t *corners = NULL, *split = NULL;
    size_t corner_cap = 0, split_cap = 0;
    triangulate_work work = {0};
    bool good = n->count > 0;
    if (!good)
        diag_at(&l->d, n, "'faces' needs at least one face");
    for (int f = 0; good && f < n->count; f++) {
        const ynode *face = n->items[f];
        if (face->kind != YNODE_SEQUENCE || face->count < 3) {
            diag_at(&l->d, face, "each face is a list of 3 or more vertex numbers");
            good = false;
            break;
        }
        size_t k = (size_t)face->count;
        good = array_reserve((void **)&corners, &corner_cap, k, sizeof *corners) &&
               array_reserve((void **)&split, &split_cap, 3 * (k - 2), sizeof *split) &&
               array_reserve((void **)indices, &cap, used + 3 * (k - 2), sizeof **indices);
        if (!good) {
            diag_raw(&l->d, GLINT_ERR_NOMEM, "out of memory");
            break;
        }
        for (size_t i = 0; good && i < k; i++) {
            long long v;
            good = yr_integer(&l->r, face->items[i], "faces", 0, vertices - 1, &v);
            corners[i] = (uint32_t)v;
        }
        if (good && used / 3 + (k - 2) > INLINE_MAX) {
            diag_at(&l->d, face, "'faces' make more than %d triangles", INLINE_MAX);
            good = false;
        }
        if (good && !triangulate_polygon(&work, positions, corners, k, split)) {
            diag_raw(&l->d, GLINT_ERR_NOMEM, "out of memory");
            good = false;
        }
        for (size_t i = 0; good && i < 3 * (k - 2); i++)
            (*indices)[used++] = corners[split[i]];
    }
    triangulate_free(&work);
    free(corners);
    free(split);
    *count = (int)(used / 3);
    return good;
}

void place_inline_mesh(loader *l, const ynode *n, int csg, int look, const glint_transform *to_world, int before)
{
    int vertex_count, normal_count, uv_count, triangle_count = 0;
    float *positions = number_rows(l, yr_need(&l->r, n, "vertices", "mesh"), "vertices", 3, &vertex_count);
    float *normals = number_rows(l, yr_get(&l->r, n, "normals"), "normals", 3, &normal_count);
    float *uvs = number_rows(l, yr_get(&l->r, n, "uvs"), "uvs", 2, &uv_count);
    const ynode *faces = yr_need(&l->r, n, "faces", "mesh");
    uint32_t *indices = NULL;
    if (normals && normal_count != vertex_count)
        diag_at(&l->d, yr_get(&l->r, n, "normals"), "'normals' must hold one normal a vertex: %d, got %d",
                vertex_count, normal_count);
    if (uvs && uv_count != vertex_count)
        diag_at(&l->d, yr_get(&l->r, n, "uvs"), "'uvs' must hold one [u, v] a vertex: %d, got %d", vertex_count,
                uv_count);
    if (positions && faces)
        read_faces(l, faces, positions, vertex_count, &indices, &triangle_count);
    if (look == -1)
        diag_at(&l->d, n, "mesh needs 'material'");
    glint_error err;
    if (l->d.count == before && look >= 0) {
        glint_mesh_data d = {positions, normals, uvs, vertex_count, indices, triangle_count, NULL, look};
        int made = glint_scene_add_mesh(l->scene, NULL, &d, &err);
        if (made < 0)
            diag_error(&l->d, n, &err);
        else
            place_mesh_object(l, n, csg, made, -1, to_world);
    }
    free(positions);
    free(normals);
    free(uvs);
    free(indices);
}

bool many_point_polygon(loader *l, const ynode *n, int look, const glint_transform *to_world, int before)
{
    const ynode *points = yr_get(&l->r, n, "points");
    glint_shape quad;
    if (!points || points->kind != YNODE_SEQUENCE || points->count < 3)
        return false;
    vec3 *p = NULL;
    int count = points->count;
    if (count <= 4) {
        /* Three or four points stay a shape unless they make a concave quad. */
        quad = glint_shape_default(GLINT_SHAPE_POLYGON);
        for (int i = 0; i < count; i++)
            if (!yr_vec3(&l->r, points->items[i], "points", &quad.points[i]))
                return true;
        if (count == 3 || polygon_is_convex(quad.points, count))
            return false;
        p = quad.points;
    } else if (count > GLINT_MAX_POLYGON_POINTS) {
        diag_at(&l->d, points, "'points' must hold 3 to %d points, got %d", GLINT_MAX_POLYGON_POINTS, count);
        return true;
    } else if (!(p = malloc(sizeof *p * (size_t)count))) {
        diag_raw(&l->d, GLINT_ERR_NOMEM, "out of memory");
        return true;
    }
    for (int i = 0; count > 4 && i < count; i++)
        if (!yr_vec3(&l->r, points->items[i], "points", &p[i]))
            break;
    if (look == -1)
        diag_at(&l->d, n, "polygon needs 'material'");
    glint_error err;
    if (l->d.count == before && look >= 0 && glint_scene_add_polygon(l->scene, p, count, look, to_world, &err) < 0)
        diag_error(&l->d, n, &err);
    if (count > 4)
        free(p);
    return true;
}

/* A heightfield's grid from image `file`, its pixels' first channel read
 * as data (b / 255): *columns x *rows heights, NULL after a report. */
static float *image_heights(loader *l, const ynode *file, int *columns, int *rows)
{
    const char *name;
    if (!yr_text(&l->r, file, "file", &name))
        return NULL;
    char *path = relative_to(file->file, name);
    texture_image img = {0};
    glint_error err;
    glint_status st = path ? texture_image_load_file(&img, path, &err) : GLINT_ERR_NOMEM;
    free(path);
    if (st) {
        if (st == GLINT_ERR_NOMEM && !path)
            diag_raw(&l->d, GLINT_ERR_NOMEM, "out of memory");
        else
            diag_error(&l->d, file, &err);
        return NULL;
    }
    texture_image data = texture_image_as_data(&img);
    size_t count = (size_t)img.width * (size_t)img.height;
    float *heights = malloc(count * sizeof *heights);
    for (size_t i = 0; heights && i < count; i++) {
        float h = texture_image_at(&data, 3 * i);
        heights[i] = h < 0 ? 0 : h > 1 ? 1 : h;
    }
    if (!heights)
        diag_raw(&l->d, GLINT_ERR_NOMEM, "out of memory");
    *columns = img.width;
    *rows = img.height;
    texture_image_free(&img);
    return heights;
}

/* A heightfield's grid from `heights`, a list of rows of numbers, all as
 * long as the first: NULL after a report. */
static float *listed_heights(loader *l, const ynode *list, int *columns, int *rows)
{
    if (!yr_is_list(&l->r, list, "'heights'"))
        return NULL;
    int nr = list->count, nc = nr > 0 && list->items[0]->kind == YNODE_SEQUENCE ? list->items[0]->count : 0;
    if (nr < 2 || nc < 2 || nr > GLINT_MAX_HEIGHTFIELD_SIDE || nc > GLINT_MAX_HEIGHTFIELD_SIDE) {
        diag_at(&l->d, list, "'heights' must be 2 to %d rows of 2 to %d numbers each", GLINT_MAX_HEIGHTFIELD_SIDE,
                GLINT_MAX_HEIGHTFIELD_SIDE);
        return NULL;
    }
    float *heights = malloc((size_t)nr * (size_t)nc * sizeof *heights);
    if (!heights) {
        diag_raw(&l->d, GLINT_ERR_NOMEM, "out of memory");
        return NULL;
    }
    for (int r = 0; r < nr; r++) {
        const ynode *row = list->items[r];
        if (row->kind != YNODE_SEQUENCE || row->count != nc) {
            diag_at(&l->d, row, "each row of 'heights' must hold %d numbers, as the first does", nc);
            free(heights);
            return NULL;
        }
        for (int c = 0; c < nc; c++) {
            double h;
            if (!yr_number(&l->r, row->items[c], "heights", &h)) {
                free(heights);
                return NULL;
            }
            if (!(h >= 0 && h <= 1)) {
                diag_at(&l->d, row->items[c], "'heights' must be from 0 to 1, got %g", h);
                free(heights);
                return NULL;
            }
            heights[(size_t)r * nc + c] = (float)h;
        }
    }
    *columns = nc;
    *rows = nr;
    return heights;
}

void place_heightfield(loader *l, const ynode *n, int look, const glint_transform *to_world, int before)
{
    const ynode *file = yr_get(&l->r, n, "file"), *list = yr_get(&l->r, n, "heights");
    vec3 lo, hi;
    /* Both read, so that both are reported. */
    bool has_min = need_vec3(l, n, "min", "heightfield", &lo), has_max = need_vec3(l, n, "max", "heightfield", &hi);
    bool box = has_min && has_max;
    if (!file == !list) {
        diag_at(&l->d, n, "a heightfield takes a 'file' or its 'heights', one of them");
        return;
    }
    int columns = 0, rows = 0;
    float *heights = file ? image_heights(l, file, &columns, &rows) : listed_heights(l, list, &columns, &rows);
    if (look == -1)
        diag_at(&l->d, n, "heightfield needs 'material'");
    glint_error err;
    if (heights && box && l->d.count == before && look >= 0 &&
        glint_scene_add_heightfield(l->scene, heights, columns, rows, lo, hi, look, to_world, &err) < 0)
        diag_error(&l->d, n, &err);
    free(heights);
}
