/* triangle_tree.h - a bounding volume hierarchy over one mesh's triangles,
 * in double precision, answering "the nearest crossing past this
 * distance". A closed mesh that is a part of a combination needs it: the
 * walk of csg.c asks each part for its crossings one after another, which
 * Embree's scene-wide queries do not answer. Placed meshes never use it. */
#ifndef GLINT_GEOMETRY_TRIANGLE_TREE_H
#define GLINT_GEOMETRY_TRIANGLE_TREE_H

#include <stdbool.h>
#include <stdint.h>
#include "core/error.h"
#include "core/vec.h"

/* A node: a box, and either two children (count 0: they are nodes first
 * and first + 1) or `count` triangles from slot `first` of the tree. */
typedef struct tree_node {
    double lo[3], hi[3];
    uint32_t first, count;
} tree_node;

typedef struct triangle_tree {
    tree_node *nodes;         /* node 0 is the root */
    vec3 *corners;            /* 3 a slot: its triangle's corners */
    uint32_t *triangle;       /* a slot's triangle index in the mesh */
    int triangle_count;
} triangle_tree;

/* Builds the tree over `triangle_count` triangles, `indices` 3 a triangle
 * into `positions` (3 floats a vertex), splitting by the surface area
 * heuristic. The tree copies what it needs. Fails only for want of memory. */
glint_status triangle_tree_build(triangle_tree *t, const float *positions, const uint32_t *indices,
                                 int triangle_count, glint_error *err);

/* Frees what t owns. */
void triangle_tree_free(triangle_tree *t);

/* The nearest crossing of r with a triangle at a distance in (tmin, tmax):
 * *at its distance and *triangle its index in the mesh. Watertight: a ray
 * through an edge or corner shared by triangles meets at least one of
 * them, so a closed mesh has no cracks. */
bool triangle_tree_hit(const triangle_tree *t, const ray *r, double tmin, double tmax, double *at,
                       uint32_t *triangle);

#endif
