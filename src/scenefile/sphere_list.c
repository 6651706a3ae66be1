/* sphere_list.c - spheres gathered for a sphere set (sphere_list.h). */
#include <stdlib.h>
#include "core/array.h"
#include "scenefile/sphere_list.h"

bool sphere_list_add(sphere_list *l, glint_vec3 center, double radius, int material)
{
    size_t need = (size_t)l->count + 1;
    if (!array_reserve((void **)&l->centers, &l->center_cap, need, sizeof *l->centers) ||
        !array_reserve((void **)&l->radii, &l->radius_cap, need, sizeof *l->radii) ||
        !array_reserve((void **)&l->materials, &l->material_cap, need, sizeof *l->materials))
        return false;
    l->centers[l->count] = center;
    l->radii[l->count] = radius;
    l->materials[l->count++] = material;
    return true;
}

void sphere_list_free(sphere_list *l)
{
    free(l->centers);
    free(l->radii);
    free(l->materials);
    *l = (sphere_list){0};
}
