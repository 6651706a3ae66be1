/* fog.h - linear and exponential fog over a ray segment. */
#ifndef GLINT_SHADING_FOG_H
#define GLINT_SHADING_FOG_H

#include <stdbool.h>
#include "core/color.h"
#include "core/params.h"

/* The keys of fog: its type, then those the types read, with defaults and
 * ranges. */
param_table fog_params(void);

/* Whether a fog of that kind reads parameter p of fog_params: every kind
 * its type and colour, linear fog its start and end, exponential fog its
 * density. */
bool fog_reads(glint_fog_kind kind, const param *p);

/* Checks a fog description against the table's keys for its type, and
 * linear fog's start < end; fills err naming a bad value. */
glint_status fog_validate(const glint_fog *fog, glint_error *err);

/* How much of the fog colour replaces what a segment of length d shows, in
 * [0, 1]; d may be INFINITY (a ray that hit nothing). */
double fog_factor(const glint_fog *fog, double d);

/* Blends c towards the fog colour for a segment of length d. */
color fog_apply(const glint_fog *fog, color c, double d);

/* True when the fog hides whatever lies at the end of a segment of length
 * d: fog_apply then gives exactly the fog colour for any finite c, so
 * nothing there needs shading. */
bool fog_hides(const glint_fog *fog, double d);

/* A distance from which on the fog hides everything: fog_hides is true for
 * every d >= fog_reach, and a ray that hits nothing shows the same fog
 * colour, so nothing that far along a ray needs to be found. INFINITY when
 * the fog never hides anything completely. */
double fog_reach(const glint_fog *fog);

#endif
