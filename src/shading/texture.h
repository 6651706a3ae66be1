/* texture.h - textures and the mappings that give them (u, v) coordinates
 * on a surface.
 *
 * Each kind of texture is one file (checker_texture.c, image_texture.c)
 * that exports one texture_kind record: its scene-file name, its parameter
 * table (offsets into glint_texture) and its operations; texture.c lists
 * them, one line each, and holds the mappings. Adding a kind:
 * docs/architecture.md. */
#ifndef GLINT_SHADING_TEXTURE_H
#define GLINT_SHADING_TEXTURE_H

#include "core/color.h"
#include "core/lanes.h"
#include "core/params.h"
#include "core/transform.h"
#include "geometry/shape.h"
#include "image/texture_image.h"

typedef struct texture_kind texture_kind;

/* How far along u and along v a sample's footprint reaches on the
 * surface, in texture coordinates, squared (finding the reach itself
 * would take square roots its users need not wait for); 0 and 0: a point
 * (no filtering). */
typedef struct uv_extent {
    double u2, v2;
} uv_extent;

/* Decodes the image file at path into *out for an image texture: the
 * scene's own (scene_images.c) shares one decoding between the textures of
 * one file. `user` is the caller's. */
typedef glint_status (*image_load_fn)(void *user, const char *path, texture_image *out, glint_error *err);

/* A planar mapping, and the texture's placement after it, as one affine
 * map of the object-space point p: placed u = g_u . p + u0, v = g_v . p +
 * v0. Composed once, so a look-up takes two dot products, and g_u and g_v
 * are the gradients a footprint is measured with. */
typedef struct planar_map {
    vec3 g_u, g_v;
    double u0, v0;
} planar_map;

typedef struct texture {
    char *name;                /* may be NULL */
    const texture_kind *kind;
    glint_mapping mapping;
    color a, b;                /* checker colours */
    double cell;               /* checker cell size */
    texture_image image;       /* image texture, linear RGB */
    bool placed;               /* the description's transform is not the identity */
    transform to_texture;      /* its inverse: from the thing's space (or uv) to the texture's */
    planar_map planar;         /* a planar mapping's, placed (planar_map_of) */
    /* What it was made from, for writing the scene back as a file
     * (glint_scene_write_yaml); desc.file is owned, and NULL for an image
     * decoded from memory. */
    glint_texture desc;
} texture;

struct texture_kind {
    const char *name;          /* the scene file's `type` */
    glint_texture_kind id;
    param_table params;        /* offsets into glint_texture; the mapping is every kind's */
    /* Fills t's own fields from desc, which has passed the table's checks
     * (an image is decoded here); on failure t owns nothing. */
    glint_status (*init)(texture *t, const glint_texture *desc, image_load_fn load, void *user, glint_error *err);
    /* The colour at texture coordinates (u, v) of a sample covering
     * `covered` about them (which a kind may ignore). */
    color (*eval)(const texture *t, double u, double v, uv_extent covered);
    /* A solid texture's colour at point p of the thing, in its own
     * coordinates, where the mapping has no say; NULL: eval at the
     * mapping's (u, v). */
    color (*solid)(const texture *t, vec3 p);
    /* For a solid kind whose work pays four points at a time (noise): its
     * colours at the first `lanes` (1 to 4) of four points, the lanes of
     * p[0], p[1] and p[2] (x, y, z), into out; its `solid` is then
     * texture_solid_one. NULL for the others. */
    void (*solid4)(const texture *t, const quad_f64 p[3], int lanes, color out[QUAD]);
    /* For a kind whose look-ups pay four at a time (images): eval at the
     * first `lanes` (1 to 4) of four lanes, lane k at (u[k], v[k])
     * covering (u2[k], v2[k]), the same colours, channel c of lane k's in
     * out[c][k]. NULL for the others. */
    void (*eval4)(const texture *t, quad_f64 u, quad_f64 v, quad_f64 u2, quad_f64 v2, int lanes, quad_f64 out[3]);
};

/* A solid texture's colour at p, through its kind's solid4 (one lane). */
color texture_solid_one(const texture *t, vec3 p);

/* A solid texture's colours at points p[0] to p[lanes - 1] (1 to 4), in
 * its own coordinates, into out: in one go where its kind has solid4. */
void texture_solid_points(const texture *t, const vec3 p[], int lanes, color out[]);

extern const texture_kind checker_texture, image_texture, checker_3d_texture, noise_texture, marble_texture,
    wood_texture, granite_texture;

/* The kind with that public id, or NULL. */
const texture_kind *texture_kind_of(glint_texture_kind id);

/* The number of kinds, and kind i, in the order the docs list them. */
int texture_kind_count(void);
const texture_kind *texture_kind_at(int i);

/* Fills t (name aside) from desc after checking it against its kind's table
 * and its mapping, an image decoded through load(user, ...), keeping a copy of desc (and of its file name); on
 * failure t owns nothing. */
glint_status texture_init(texture *t, const glint_texture *desc, image_load_fn load, void *user, glint_error *err);

/* The keys of a mapping map: its type, then the keys the types read, in
 * an order where type k reads the first mapping_key_count(k). */
param_table mapping_params(void);
int mapping_key_count(glint_mapping_kind kind);

/* Checks a mapping's values against its table and rules (planar axes: both
 * or neither, not parallel); fills err naming the bad one. A scale of 0 is
 * taken as 1, the default, for zero-initialised C structs. */
glint_status mapping_validate(const glint_mapping *m, glint_error *err);

/* Computes the texture coordinates of surface s under mapping m. center
 * is the object-space centre of the thing hit (shape_center's), where
 * spherical and cylindrical mappings without a center_given are centred. */
void mapping_apply(const glint_mapping *m, const surface *s, vec3 center, double *u, double *v);

/* Planar mapping m (which mapping_validate accepts) followed by the
 * placement to_texture (NULL: none) as one affine map. */
planar_map planar_map_of(const glint_mapping *m, const transform *to_texture);

/* map's (u, v) at object-space point p. */
static inline void planar_map_apply(const planar_map *map, vec3 p, double *u, double *v)
{
    *u = v3_dot(map->g_u, p) + map->u0;
    *v = v3_dot(map->g_v, p) + map->v0;
}

/* The gradients, in object space, of texture t's placed (u, v) at point
 * p_obj of a thing whose centre is center (as for mapping_apply): a
 * planar mapping's, the same everywhere, or a spherical mapping's there
 * (but on its axis); false for the other mappings, whose footprints are
 * measured by steps. */
bool mapping_gradients(const texture *t, vec3 p_obj, vec3 center, vec3 *g_u, vec3 *g_v);

/* The colour of checker cells at (u, v): a where floor(u/cell) + floor(v/cell) is even. */
color checker_eval(color a, color b, double cell, double u, double v);

/* Bilinearly filtered colour of an image at (u, v), past its edges as
 * wrap_u and wrap_v say; v = 0 is the top row. */
color image_eval(const texture_image *img, double u, double v, glint_wrap wrap_u, glint_wrap wrap_v);

/* The level of img (0: itself; fractions between) whose texels are as
 * wide as a sample covering `covered`, within the levels img has: for a
 * footprint of w texels along u or v, whichever is more, with w^2 = m 2^e
 * (m from 1 to 2), (e + m - 1) / 2: log2 w wherever w is a power of the
 * square root of 2, within 0.043 of it between. */
double image_level(const texture_image *img, uv_extent covered);

/* image_eval at `level` of img: bilinear in the two levels either side of
 * it, blended (trilinear); at level 0 or below, exactly image_eval. */
color image_eval_level(const texture_image *img, double u, double v, glint_wrap wrap_u, glint_wrap wrap_v,
                       double level);

/* image_level of four footprints, lane k's (u2[k], v2[k]): the same
 * values. */
quad_f64 image_level4(const texture_image *img, quad_f64 u2, quad_f64 v2);

/* image_eval_level of the first `lanes` (1 to 4) of four lanes, lane k
 * at (u[k], v[k]) and level[k], channel c of its colour into out[c][k]:
 * the same colours, the texels found four lanes at a time and each lane's
 * blended on its own. */
void image_eval_level4(const texture_image *img, quad_f64 u, quad_f64 v, glint_wrap wrap_u, glint_wrap wrap_v,
                       quad_f64 level, int lanes, quad_f64 out[3]);

/* Point p (a solid texture's) or (u, v, 0) carried into texture t's own
 * space, when it is placed. */
static inline vec3 texture_place(const texture *t, vec3 p)
{
    return t->placed ? xf_point(&t->to_texture, p) : p;
}

/* The colour of texture t at placed texture coordinates (u, v), for a
 * sample covering `covered` of them. The checker, the texture of most
 * floors, is looked up inline: through its record it cost the seed room
 * 0.4% of its instructions. */
static inline color texture_at_placed(const texture *t, double u, double v, uv_extent covered)
{
    if (t->kind == &checker_texture)
        return checker_eval(t->a, t->b, t->cell, u, v);
    return t->kind->eval(t, u, v, covered);
}

/* The colour of texture t at texture coordinates (u, v), placed, for a
 * sample covering `covered` of the placed coordinates. */
static inline color texture_at_uv(const texture *t, double u, double v, uv_extent covered)
{
    vec3 q = texture_place(t, v3(u, v, 0));
    return texture_at_placed(t, q.x, q.y, covered);
}

/* The placed texture coordinates of surface s under texture t's mapping,
 * on a thing whose centre is center (as for mapping_apply). */
static inline void texture_uv(const texture *t, const surface *s, vec3 center, double *u, double *v)
{
    if (t->mapping.kind == GLINT_MAP_PLANAR) {
        planar_map_apply(&t->planar, s->p_obj, u, v);
        return;
    }
    double mu, mv;
    mapping_apply(&t->mapping, s, center, &mu, &mv);
    vec3 q = texture_place(t, v3(mu, mv, 0));
    *u = q.x;
    *v = q.y;
}

/* Whether t's colour depends on how much of it a sample covers: an image
 * filtered trilinearly, which has levels. */
static inline bool texture_filters(const texture *t)
{
    return t->kind == &image_texture && t->desc.filter == GLINT_IMAGE_TRILINEAR && t->image.level_count > 1;
}

/* Replaces the file name t->desc remembers with a copy of path (NULL:
 * none); false when out of memory, with t unchanged. */
bool texture_set_file(texture *t, const char *path);

/* Frees what t owns. */
void texture_release(texture *t);

#endif
