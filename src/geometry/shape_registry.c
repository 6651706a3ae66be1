/* shape_registry.c - the list of shape kinds: one line per kind. */
#include "core/registry.h"
#include "geometry/shape_kind.h"

static const shape_kind *const KINDS[] = {
    &sphere_kind, &plane_kind, &polygon_kind, &box_kind, &cylinder_kind, &cone_kind, &disk_kind, &torus_kind,
    &quadric_kind, &union_kind, &intersection_kind, &difference_kind,
};

REGISTRY_LOOKUPS(shape_kind, shape_kind, glint_shape_kind, KINDS)
