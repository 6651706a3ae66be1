/* plain_packet.h - the commonest packet shaded as one: every lane that hit
 * something hit a surface of one plain material, under delta lights
 * (plain_packet.c says why and what counts). */
#ifndef GLINT_RENDER_PLAIN_PACKET_H
#define GLINT_RENDER_PLAIN_PACKET_H

#include "render/integrator.h"

/* Whether the scene's light lets a packet be plain: delta lights only, none
 * of them moving, no area light or emissive surface, no ambient occlusion.
 * Asked once a render (tracer.plain). */
bool plain_packet_scene(const glint_scene *scene);

/* When the hits hits[i] of packet r's lanes found[i], at recursion depth
 * `depth`, are all of one plain material (opaque, no mirror, bump or
 * normal map, absorption or metallic tint, a whole specular exponent),
 * shades them as the integrator's lane-by-lane steps would, to the bit
 * (lane_ray[i]: lane i's ray, copied out of r well before, as trace8 does),
 * and returns true: local[i] is lane i's colour before fog, seen at
 * hits[i].t (a mesh hit's distance refined); found[i] becomes false where
 * the fog hides the hit. The footprint a texture is averaged over widens
 * with travelled[i], the path before lane i's ray. Otherwise returns false
 * having done nothing. Only when t->plain. */
bool plain_packet_shade(tracer *t, const ray8 *r, const ray lane_ray[ACCEL_PACKET], accel_hit hits[ACCEL_PACKET],
                        bool found[ACCEL_PACKET], int depth, const double travelled[ACCEL_PACKET],
                        color local[ACCEL_PACKET]);

#endif
