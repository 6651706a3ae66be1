/* scene_heightfield.c - heightfields: a grid of heights in a box, as the
 * two triangles a cell that join its samples, smoothly shaded; a mesh
 * placed once. */
#include <math.h>
#include <stdlib.h>
#include "core/error.h"
#include "scene/scene.h"

/* Checks the grid and the box; fills err. */
static glint_status check_grid(const float *heights, int columns, int rows, glint_vec3 lo, glint_vec3 hi,
                               glint_error *err)
{
    int most = GLINT_MAX_HEIGHTFIELD_SIDE;
    if (columns < 2 || rows < 2 || columns > most || rows > most)
        return error_set(err, GLINT_ERR_INVALID, "a heightfield needs 2 to %d samples a side, got %d x %d", most,
                         columns, rows);
    if (!(lo.x < hi.x && lo.y <= hi.y && lo.z < hi.z) || !isfinite(lo.x + lo.y + lo.z + hi.x + hi.y + hi.z))
        return error_set(err, GLINT_ERR_INVALID,
                         "heightfield min must be below max in x and z, and at most max in y, all finite");
    for (size_t i = 0; i < (size_t)columns * (size_t)rows; i++)
        if (!(heights[i] >= 0 && heights[i] <= 1))
            return error_set(err, GLINT_ERR_INVALID, "heightfield height %zu (row %zu) must be from 0 to 1, got %g", i,
                             i / (size_t)columns, (double)heights[i]);
    return GLINT_OK;
}

int glint_scene_add_heightfield(glint_scene *scene, const float *heights, int columns, int rows, glint_vec3 lo,
                                glint_vec3 hi, int mat, const glint_transform *xf, glint_error *err)
{
    if (check_grid(heights, columns, rows, lo, hi, err))
        return -1;
    size_t nc = (size_t)columns, nr = (size_t)rows, vertices = nc * nr, triangles = 2 * (nc - 1) * (nr - 1);
    float *positions = malloc(3 * vertices * sizeof *positions), *normals = malloc(3 * vertices * sizeof *normals);
    float *uvs = malloc(2 * vertices * sizeof *uvs);
    uint32_t *indices = malloc(3 * triangles * sizeof *indices);
    int placed = -1;
    if (!positions || !normals || !uvs || !indices) {
        error_set(err, GLINT_ERR_NOMEM, "out of memory adding a heightfield of %d x %d", columns, rows);
    } else {
        double dx = (hi.x - lo.x) / (double)(nc - 1), dz = (hi.z - lo.z) / (double)(nr - 1), dy = hi.y - lo.y;
        for (size_t r = 0; r < nr; r++)
            for (size_t c = 0; c < nc; c++) {
                size_t i = r * nc + c;
                positions[3 * i] = (float)(lo.x + (double)c * dx);
                positions[3 * i + 1] = (float)(lo.y + heights[i] * dy);
                positions[3 * i + 2] = (float)(lo.z + (double)r * dz);
                uvs[2 * i] = (float)((double)c / (double)(nc - 1));
                uvs[2 * i + 1] = (float)((double)r / (double)(nr - 1));
                /* The slopes from the neighbours either side (one side at an edge). */
                size_t c0 = c ? c - 1 : c, c1 = c + 1 < nc ? c + 1 : c, r0 = r ? r - 1 : r, r1 = r + 1 < nr ? r + 1 : r;
                double sx = (heights[r * nc + c1] - heights[r * nc + c0]) * dy / ((double)(c1 - c0) * dx);
                double sz = (heights[r1 * nc + c] - heights[r0 * nc + c]) * dy / ((double)(r1 - r0) * dz);
                vec3 n = v3_normalize(v3(-sx, 1, -sz));
                normals[3 * i] = (float)n.x;
                normals[3 * i + 1] = (float)n.y;
                normals[3 * i + 2] = (float)n.z;
            }
        uint32_t *t = indices;
        for (size_t r = 0; r + 1 < nr; r++)
            for (size_t c = 0; c + 1 < nc; c++) {
                /* Anticlockwise seen from above (+y): x to the right, z towards the viewer. */
                uint32_t a = (uint32_t)(r * nc + c), b = a + 1, d = (uint32_t)((r + 1) * nc + c), e = d + 1;
                uint32_t cell[6] = {a, d, e, a, e, b};
                for (int k = 0; k < 6; k++)
                    *t++ = cell[k];
            }
        glint_mesh_data data = {positions, normals, uvs, (int)vertices, indices, (int)triangles, NULL, mat};
        int made = glint_scene_add_mesh(scene, NULL, &data, err);
        if (made >= 0)
            placed = glint_scene_add_instance(scene, made, -1, xf, err);
    }
    free(positions);
    free(normals);
    free(uvs);
    free(indices);
    return placed;
}
