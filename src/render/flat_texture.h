/* flat_texture.h - a texture read at four hits on one flat shape at once:
 * a tiled or checkered floor, where a packet's lanes all hit the same
 * plane (flat_texture.c says why). */
#ifndef GLINT_RENDER_FLAT_TEXTURE_H
#define GLINT_RENDER_FLAT_TEXTURE_H

#include "core/lanes.h"
#include "shading/texture.h"

/* Whether flat_texture_colors4 reads texture t: a planar mapping (whose
 * coordinates and footprint are linear in the hit), or a solid texture
 * not placed (read at the hit itself). */
bool flat_texture_on_quads(const texture *t);

/* The colours of texture t (flat_texture_on_quads) at the hits p of four
 * lanes on a flat shape without a transform, whose normal there is n (the
 * surface's, as hit_surface gives it), seen along unit directions d by
 * samples whose footprints there are `width` across (0: a point), for the
 * lanes in `wanted`: out[c] holds channel c of each, the bits
 * hit_texture_where and texture_read_color give lane by lane. Lanes not
 * wanted are left as they are. */
void flat_texture_colors4(const texture *t, const quad_f64 p[3], const quad_f64 n[3], const quad_f64 d[3],
                          quad_f64 width, quad_mask wanted, quad_f64 out[3]);

#endif
