/* shape_registry.c - the list of shape kinds: one line per kind. */
#include <string.h>
#include "geometry/shape_kind.h"

static const shape_kind *const KINDS[] = {
    &sphere_kind, &plane_kind, &polygon_kind, &box_kind, &cylinder_kind, &cone_kind, &disk_kind,
};

#define KIND_COUNT ((int)(sizeof KINDS / sizeof KINDS[0]))

const shape_kind *shape_kind_of(glint_shape_kind id)
{
    for (int i = 0; i < KIND_COUNT; i++)
        if (KINDS[i]->id == id)
            return KINDS[i];
    return NULL;
}

const shape_kind *shape_kind_named(const char *name)
{
    for (int i = 0; i < KIND_COUNT; i++)
        if (strcmp(KINDS[i]->name, name) == 0)
            return KINDS[i];
    return NULL;
}

int shape_kind_count(void) { return KIND_COUNT; }

const shape_kind *shape_kind_at(int i) { return i >= 0 && i < KIND_COUNT ? KINDS[i] : NULL; }
