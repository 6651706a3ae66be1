/* mesh.h - triangle meshes and their instances. A mesh's triangles are
 * stored once (and shared with Embree, not copied); each instance places
 * the mesh with its own transform and, optionally, its own material. */
#ifndef GLINT_GEOMETRY_MESH_H
#define GLINT_GEOMETRY_MESH_H

#include <stdint.h>
#include "geometry/shape.h"
#include "geometry/triangle_tree.h"

/* Where a mesh came from, for writing the scene back as a file
 * (glint_scene_write_yaml): its model file and import options, and the
 * materials and textures its import added, which a scene file's mesh
 * object makes again. */
typedef struct mesh_origin {
    char *file;               /* owned; NULL: a mesh from arrays or from bytes in memory */
    double crease_angle;      /* degrees, as the import used it */
    int default_material;     /* as the import was given it; -1: its own grey */
    int first_material, material_count;
    int first_texture, texture_count;
} mesh_origin;

typedef struct mesh_solid mesh_solid;

typedef struct mesh {
    char *name;               /* may be NULL */
    mesh_origin origin;
    float *positions;         /* 3 per vertex, then padding Embree may read */
    float *normals;           /* 3 per vertex, or NULL: flat shading */
    float *uvs;               /* 2 per vertex, or NULL */
    uint32_t *indices;        /* 3 per triangle */
    int *materials;           /* one per triangle, or NULL: `material` for all */
    int material;
    int vertex_count, triangle_count;
    vec3 lo, hi;              /* bounds in the mesh's own coordinates */
    bool bare;                /* imported from a file that gave it no materials: `material`, for
                                 every triangle, is the importer's stand-in */
    mesh_solid *solid;        /* owned; made once it is a part of a combination, else NULL */
} mesh;

/* What a closed mesh needs to be a part of a combination (mesh_part.c): its
 * arrays, its own hierarchy, and which way its triangles face. */
struct mesh_solid {
    mesh view;                /* the mesh's arrays, not owned: they stay where they are */
    triangle_tree tree;
    bool inward;              /* its triangles run clockwise seen from outside, so the
                                 normals their winding gives are turned to point out */
};

/* The material of shape s where a hit on its `part` is: its own, or for a
 * mesh part without one, the triangle's; for a sphere set, the sphere's. */
static inline int shape_material(const shape *s, int part)
{
    if (s->material >= 0)
        return s->material;
    part &= ~SHAPE_PART_FLIPPED;
    return s->set ? s->set->materials[part] : s->solid->view.materials[part];
}

/* Makes m->solid, once: checks that m is the closed surface of a solid
 * (welding corners at the same position, every edge borders exactly two
 * triangles that run along it opposite ways, and it encloses some volume)
 * and builds its hierarchy. On failure fills err naming the mesh as
 * `name` ("mesh 'teapot.obj'") and the first edge at fault by its corners. */
glint_status mesh_make_solid(mesh *m, const char *name, glint_error *err);

/* The barycentric weights (b1, b2) of corners 1 and 2 of triangle tri at
 * point p of its plane (or of the plane's nearest point to p), as an affine
 * map on from the triangle; false for a triangle without area. */
bool mesh_weights_at(const mesh *m, unsigned tri, vec3 p, double *b1, double *b2);

typedef struct instance {
    int mesh;
    int material;             /* -1: the mesh's own */
    transform to_world, to_object;
    bool has_transform;       /* false: to_world is the identity */
    transform *poses;         /* moving: its world transforms over the shutter, evenly spaced */
    int pose_count;           /* (0: it stands still), which Embree blends as shape_at does; owned by the scene */
} instance;

/* instance_at for a moving placement (pose_count > 0): *out, a copy with
 * the transform its poses blend to at `time`, as Embree's instance motion
 * blur places it. */
const instance *instance_moved(const instance *inst, double time, instance *out);

/* The placement inst is at `time` in [0, 1] over the shutter: inst itself
 * when it stands still, else instance_moved's copy in *out. */
static inline const instance *instance_at(const instance *inst, double time, instance *out)
{
    return inst->pose_count ? instance_moved(inst, time, out) : inst;
}

/* Copies and checks d (finite positions, indices in range, materials below
 * material_count) into *m. */
glint_status mesh_init(mesh *m, const char *name, const glint_mesh_data *d, int material_count, glint_error *err);

/* Frees what m owns. */
void mesh_release(mesh *m);

/* The material of triangle tri as placed by inst. */
int mesh_material(const mesh *m, const instance *inst, unsigned tri);

/* The middle of m's bounds in its own coordinates: where spherical and
 * cylindrical mappings are centred on it unless they give their own. */
static inline vec3 mesh_center(const mesh *m)
{
    return v3_scale(v3_add(m->lo, m->hi), 0.5);
}

/* Asks the processor to start loading what mesh_surface will read of
 * triangle tri, so that the loads of several hits overlap. */
void mesh_prefetch(const mesh *m, unsigned tri);

/* Describes the surface where world ray r hits triangle tri of m placed by
 * inst, near barycentric coordinates (b1, b2) and ray parameter *t from
 * Embree: *t is refined in double precision, out->n is the geometric normal
 * (from the winding: counter-clockwise is the front), out->shading_n the
 * interpolated vertex normal turned to the same side, u and v interpolated
 * texture coordinates. */
void mesh_surface(const mesh *m, const instance *inst, const ray *r, unsigned tri, double b1, double b2, double *t,
                  surface *out);

/* The uv triangle tri carries to point p of its plane (or of the plane's
 * nearest point to p), in the mesh's own coordinates, on from the triangle
 * as an affine map: (0, 0) for a mesh without uvs. */
void mesh_uv_at(const mesh *m, unsigned tri, vec3 p, double *u, double *v);

/* mesh_surface for a moving placement (pose_count > 0) as it is at
 * `time`: apart, so that the common path keeps no room for a moved copy. */
void mesh_surface_moved(const mesh *m, const instance *inst, double time, const ray *r, unsigned tri, double b1,
                        double b2, double *t, surface *out);

#endif
