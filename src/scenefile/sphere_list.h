/* sphere_list.h - spheres a scene reader gathers one by one (centre,
 * radius, material) before adding them to the scene as one sphere set
 * (glint_scene_add_spheres): the NFF reader's and the scene file's runs of
 * plain spheres. */
#ifndef GLINT_SCENEFILE_SPHERE_LIST_H
#define GLINT_SCENEFILE_SPHERE_LIST_H

#include <stdbool.h>
#include <stddef.h>
#include "glint.h"

typedef struct sphere_list {
    glint_vec3 *centers;
    double *radii;
    int *materials;
    size_t center_cap, radius_cap, material_cap;
    int count;
} sphere_list;

/* Appends a sphere; false when memory runs out (the list is unchanged). */
bool sphere_list_add(sphere_list *l, glint_vec3 center, double radius, int material);

/* Frees the arrays and empties the list. */
void sphere_list_free(sphere_list *l);

#endif
