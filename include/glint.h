/*
 * glint.h - the public C API of libglint, a Whitted-style ray tracer.
 *
 * A program builds a scene (camera, settings, textures, materials, shapes,
 * lights, fog), renders it into a linear float RGB image and writes that
 * image as PNG, PPM or OpenEXR. Every function that can fail returns a
 * glint_status and, when given a glint_error, fills it with a one-line
 * message. The library never prints and never exits.
 *
 * Colours are linear RGB, nominally 0..1. Angles are in degrees. y is up.
 */
#ifndef GLINT_H
#define GLINT_H

#include <stddef.h>
#include <stdint.h>
#include <stdio.h>
#include <stdbool.h>

#ifdef __cplusplus
extern "C" {
#endif

/* ---------------------------------------------------------------- errors */

/* Result of every fallible call. */
typedef enum glint_status {
    GLINT_OK = 0,
    GLINT_ERR_INVALID,     /* a value out of range or an inconsistent call */
    GLINT_ERR_IO,          /* a file could not be read or written */
    GLINT_ERR_NOMEM,       /* an allocation failed */
    GLINT_ERR_EMBREE,      /* the Embree device reported an error */
    GLINT_ERR_CANCELLED    /* the caller's cancel flag stopped a render */
} glint_status;

/* A one-line, human-readable description of the last failure, and its
 * kind: the status the failing call returned (for calls that return a
 * pointer or an index, the only way to tell, say, GLINT_ERR_NOMEM from
 * GLINT_ERR_INVALID). */
typedef struct glint_error {
    char message[512];
    glint_status status;
} glint_error;

/* Returns the version string, e.g. "0.1.0". */
const char *glint_version(void);

/* Returns the sRGB-encoded value (0..1) of a linear value, clamped to 0..1. */
double glint_linear_to_srgb(double linear);

/* Returns the linear value of an sRGB-encoded value in 0..1. */
double glint_srgb_to_linear(double srgb);

/* ------------------------------------------------------------ basic types */

typedef struct glint_vec3 { double x, y, z; } glint_vec3;
typedef struct glint_color { double r, g, b; } glint_color;

/* An affine transform, row-major 3x4 (the last row is 0 0 0 1). It maps
 * object coordinates to world coordinates. */
typedef struct glint_transform { double m[3][4]; } glint_transform;

/* Returns the identity transform. */
glint_transform glint_transform_identity(void);

/* Each of the following returns t followed by one more step, so steps are
 * applied in the order they are written:
 *   t = glint_transform_scale(glint_transform_identity(), 2, 2, 2);
 *   t = glint_transform_translate(t, 0, 1, 0);   -- scale first, then move */
glint_transform glint_transform_translate(glint_transform t, double x, double y, double z);
/* Rotates by `degrees` about `axis` (right-handed). A zero or non-finite
 * axis gives a non-finite transform, which glint_scene_add_shape refuses. */
glint_transform glint_transform_rotate(glint_transform t, glint_vec3 axis, double degrees);
/* Scales by (x, y, z) about the origin. */
glint_transform glint_transform_scale(glint_transform t, double x, double y, double z);

/* Returns the point p mapped by t. */
glint_vec3 glint_transform_point(const glint_transform *t, glint_vec3 p);

/* -------------------------------------------------------------- keyframes */

/* How a keyed value goes from one key to the next. */
typedef enum glint_interpolation {
    GLINT_INTERPOLATE_LINEAR = 0, /* in a straight line, at constant speed */
    GLINT_INTERPOLATE_SMOOTH,     /* a cubic through every key with a continuous slope (C1)
                                     that never overshoots: between two keys the value stays
                                     between theirs (Steffen's monotone cubic); flat at the
                                     first and last key, so it eases in and out */
    GLINT_INTERPOLATE_STEP        /* each key's value holds until the next key */
} glint_interpolation;

/* The most numbers a keyed value has (a colour or a vector has 3). */
#define GLINT_KEY_WIDTH_MAX 4

/* A value that changes with time, given at keys: key i is at times[i]
 * seconds and has the `width` numbers values[i * width ...]. Before the
 * first key it is the first key's value, after the last the last's. */
typedef struct glint_keys {
    const double *times;      /* count times, finite and increasing */
    const double *values;     /* count * width finite numbers */
    int count;                /* at least 1 */
    int width;                /* 1 to GLINT_KEY_WIDTH_MAX */
    glint_interpolation interpolate;
} glint_keys;

/* Checks keys: GLINT_ERR_INVALID naming the first key whose time does not
 * come after the one before, or the first number that is not finite. */
glint_status glint_keys_check(const glint_keys *keys, glint_error *err);

/* The value of checked keys at `time` seconds into out[0 .. width - 1]. */
void glint_keys_value(const glint_keys *keys, double time, double *out);

/* ------------------------------------------------------------------ scene */

typedef struct glint_scene glint_scene;

/* Creates an empty scene with default settings and camera, or NULL when out
 * of memory. */
glint_scene *glint_scene_new(void);

/* Frees a scene and everything it owns. NULL is allowed. */
void glint_scene_free(glint_scene *scene);

/* Creates the built-in default scene: the COSC363 seed room (see README).
 * Returns NULL when out of memory and fills err. */
glint_scene *glint_scene_seed_room(glint_error *err);

/* Sampling pattern within a pixel. */
typedef enum glint_sampler {
    GLINT_SAMPLER_REGULAR = 0,  /* N x N grid of sample points at cell centres */
    GLINT_SAMPLER_JITTERED,     /* N x N strata, one random point in each */
    GLINT_SAMPLER_SOBOL         /* any count: scrambled Sobol points, each pixel its own pattern */
} glint_sampler;

/* Pixel reconstruction filters: how a pixel weighs its samples by where
 * they fall, each separable and zero from its radius on. */
typedef enum glint_filter {
    GLINT_FILTER_BOX = 0,   /* every sample alike (radius 0.5: the pixel's own square) */
    GLINT_FILTER_TENT,      /* falls linearly to zero at the radius */
    GLINT_FILTER_GAUSSIAN,  /* standard deviation a third of the radius */
    GLINT_FILTER_MITCHELL,  /* Mitchell-Netravali, B = C = 1/3: sharper, slight ringing */
    GLINT_FILTER_LANCZOS    /* windowed sinc: sharpest, most ringing */
} glint_filter;

/* The most pixels an image may have, width times height (16384 x 16384):
 * its float buffer alone takes 12 bytes a pixel, 3 GiB at the limit. */
#define GLINT_MAX_PIXELS (1LL << 28)

/* Image and integrator settings. */
typedef struct glint_settings {
    int width, height;         /* pixels, 1..65536 each, GLINT_MAX_PIXELS in all */
    int samples_per_pixel;     /* 1..4096; a square number N*N for the regular and jittered samplers */
    glint_sampler sampler;
    int max_depth;             /* reflection/refraction recursion limit, 0..64 */
    glint_color background;    /* colour of rays that hit nothing */
    glint_color ambient_light; /* multiplies each material's ambient term */
    uint32_t seed;             /* seed of every random number: samplers, lens, lights */
    double exposure;           /* in stops, -64..64: every pixel's light is multiplied by
                                  2^exposure before it is stored (0: as rendered) */
    int emission_samples;      /* shadow rays from each shading point towards each emissive
                                  shape or mesh, 1..4096 */
    int occlusion_samples;     /* 0: the ambient term is flat; 1..4096: ambient occlusion, the
                                  ambient term times the share of these rays, spread over the
                                  hemisphere as the cosine, that nothing blocks */
    double occlusion_distance; /* how far those rays look, > 0; 0: as far as the scene goes */
    glint_filter filter;       /* the pixel reconstruction filter (box: the default) */
    double filter_radius;      /* in pixels, 0.5..16; 0: the filter's own default (box 0.5,
                                  tent 1, gaussian 1.5, mitchell 2, lanczos 3) */
    int adaptive_max_samples;  /* 0: every pixel takes samples_per_pixel; else, sampler sobol,
                                  samples_per_pixel..4096: the pixels of a block of 4 x 2 where
                                  some pixel's samples differ by more than adaptive_threshold
                                  take more, up to this many */
    double adaptive_threshold; /* the largest difference in any channel (0..1, after exposure)
                                  between a pixel's samples that needs no more */
    int light_samples;         /* 0: each area light and emitter sends its own samples from each
                                  point lit; 1..4096: the point sends this many in all, each to
                                  one of them chosen by its power */
    int frame_start, frame_end;/* the frames of an animation, 0..10,000,000, end >= start
                                  (0 and 0: one still, frame 0) */
    double fps;                /* frames a second, > 0 (24): frame f shows the scene at f / fps
                                  seconds (glint_load_options.time) */
    double shutter_open, shutter_close; /* when the shutter opens and closes, in frames from
                                  the frame's time, -1..1, open <= close (0 and 0: no motion
                                  blur); each sample is at a time between them */
    int shutter_steps;         /* moving things' poses over the shutter, 2..64 (2): they move
                                  in straight lines from one to the next */
    int dispersion_bands;      /* 3..64 (16): the bands of the spectrum light refracted into a
                                  dispersive material splits into, each a ray at a wavelength
                                  drawn within it */
    int frame;                 /* the frame being rendered, 0..10,000,000 (0: a still): it moves
                                  every random pattern (glint_settings_random_seed), so that a
                                  sequence's noise changes from frame to frame as film grain
                                  does; the glint command sets it for each frame */
} glint_settings;

/* The seed every random number of a render with settings s comes from:
 * the seed itself for frame 0, else the seed moved by the frame. A scene
 * rendered as frame f makes the bytes it makes as frame 0 with this as its
 * seed. */
uint32_t glint_settings_random_seed(const glint_settings *s);

/* Returns the settings of a new scene: 640x480, 4 spp, regular, box
 * filter, no adaptive sampling, depth 5, black background, white ambient
 * light, seed 0, frame 0 alone at 24 frames a second. */
glint_settings glint_settings_default(void);

/* Replaces the scene's settings after checking every value. */
glint_status glint_scene_set_settings(glint_scene *scene, const glint_settings *s, glint_error *err);

/* Returns the scene's current settings. */
glint_settings glint_scene_get_settings(const glint_scene *scene);

/* The kinds of camera. */
typedef enum glint_camera_kind {
    GLINT_CAMERA_PINHOLE = 0,    /* every ray from the eye: everything in focus */
    GLINT_CAMERA_THIN_LENS,      /* rays from a round lens focused at one distance: depth of field */
    GLINT_CAMERA_ORTHOGRAPHIC,   /* parallel rays from a rectangle across the view: no perspective */
    GLINT_CAMERA_EQUIRECTANGULAR,/* every direction: longitude across, latitude down (a 360 panorama) */
    GLINT_CAMERA_FISHEYE         /* equidistant: angle from the view axis grows with distance from the centre */
} glint_camera_kind;

/* A camera: a pinhole unless `kind` says otherwise. */
typedef struct glint_camera {
    glint_vec3 position;
    glint_vec3 look_at;
    glint_vec3 up;
    double vfov_degrees;       /* vertical field of view, in (0, 180); fisheye: across the
                                  image's width, in (0, 360]; unused by the equirectangular */
    glint_camera_kind kind;
    double aperture;           /* thin lens: the lens's radius in scene units, >= 0 (0 is
                                  a pinhole); 0 for the pinhole */
    double focus_distance;     /* thin lens: the distance along the view direction that is
                                  sharp, >= 0 (0: the distance to look_at); 0 for the pinhole */
    int blades;                /* thin lens: 0, a round aperture, or 3..64 blades: a regular
                                  polygon of radius `aperture` (polygonal bokeh) */
    double f_number;           /* thin lens: the lens's size as a photographer's f-number N
                                  instead of `aperture` (0: aperture gives it): its radius is
                                  the focal length / (2 N), the focal length that of a sensor
                                  sensor_width wide seeing this field of view */
    double sensor_width;       /* thin lens with f_number: the sensor's width in scene units,
                                  > 0 (0: 0.036, a 36 mm full-frame sensor, scene units
                                  taken as metres) */
    double view_width;         /* orthographic: the view's width in scene units, >= 0 (0:
                                  the pinhole's at look_at's distance); 0 for other kinds */
} glint_camera;

/* Replaces the camera after checking it (distinct position and look_at, up
 * not parallel to the view direction, field of view in range, a lens's
 * values only for the thin lens, aperture or f_number but not both, and
 * sensor_width only with f_number). */
glint_status glint_scene_set_camera(glint_scene *scene, const glint_camera *cam, glint_error *err);

/* Returns the scene's current camera. */
glint_camera glint_scene_get_camera(const glint_scene *scene);

/* Fog along every ray segment, by the segment's length d. */
typedef enum glint_fog_kind {
    GLINT_FOG_NONE = 0,
    GLINT_FOG_LINEAR,          /* f = clamp((d - start) / (end - start), 0, 1) */
    GLINT_FOG_EXPONENTIAL      /* f = 1 - exp(-density * d) */
} glint_fog_kind;

typedef struct glint_fog {
    glint_fog_kind kind;
    glint_color color;         /* what a fully fogged ray shows */
    double start, end;         /* linear: start < end; start may be negative */
    double density;            /* exponential: > 0 */
} glint_fog;

/* Replaces the scene's fog after checking it. A ray that hits nothing is
 * fogged as if infinitely long, so with fog it shows the fog colour rather
 * than the background. */
glint_status glint_scene_set_fog(glint_scene *scene, const glint_fog *fog, glint_error *err);

/* Returns the scene's current fog. */
glint_fog glint_scene_get_fog(const glint_scene *scene);

/* ---------------------------------------------------------------- textures */

/* How a surface point becomes texture coordinates (u, v). Mappings work on
 * p = (object-space point - origin), in the object's own coordinates (before
 * its transform), so a texture moves with its object. The origin is center
 * when center_given is set; otherwise spherical and cylindrical mappings
 * are centred on the object (a sphere's or disk's centre, a cylinder's or
 * cone's base centre, a plane's point, the middle of a box's, a polygon's
 * or a mesh's bounds) and a planar mapping starts from (0, 0, 0). */
typedef enum glint_mapping_kind {
    GLINT_MAP_UV = 0,     /* the shape's own (u, v) */
    GLINT_MAP_PLANAR,     /* u = p.unit(u_axis) / scale, v = p.unit(v_axis) / scale */
    GLINT_MAP_SPHERICAL,  /* d = unit(p): u = 0.5 + atan2(d.x, d.z)/2pi, v = 0.5 - asin(d.y)/pi */
    GLINT_MAP_CYLINDRICAL /* about the y axis: u = 0.5 + atan2(p.x, p.z)/2pi, v = p.y / scale */
} glint_mapping_kind;

typedef struct glint_mapping {
    glint_mapping_kind kind;
    glint_vec3 center;           /* origin of p, when center_given */
    bool center_given;           /* false: the object's centre or (0, 0, 0), as above; center
                                    must then be zero */
    glint_vec3 u_axis, v_axis;   /* planar; both zero means x and z */
    double scale;                /* planar, cylindrical: > 0; 0 is taken as the default, 1 */
} glint_mapping;

typedef enum glint_texture_kind {
    GLINT_TEXTURE_CHECKER = 0,  /* two colours in square cells */
    GLINT_TEXTURE_IMAGE,        /* a PNG, JPEG or OpenEXR picture */
    GLINT_TEXTURE_CHECKER_3D,   /* two colours in cubic cells filling space (a solid texture) */
    GLINT_TEXTURE_NOISE,        /* solid: fractal gradient noise through a colour map (POV-Ray's bozo) */
    GLINT_TEXTURE_MARBLE,       /* solid: bands across x, swirled by turbulence */
    GLINT_TEXTURE_WOOD,         /* solid: rings around the y axis, swirled by turbulence */
    GLINT_TEXTURE_GRANITE       /* solid: sharp-creased turbulence at four times the frequency */
} glint_texture_kind;

/* One stop of a colour map: the colour at value `at`, from 0 to 1. Between
 * stops the colour is blended linearly; before the first and past the last
 * it is the end stop's. */
typedef struct glint_color_stop {
    double at;
    glint_color color;
} glint_color_stop;

/* The most stops a colour map holds. */
#define GLINT_MAX_COLOR_STOPS 16

/* A texture's description: each kind reads the fields named beside them
 * (docs/scene-format.md lists each kind's keys, defaults and ranges; start
 * from glint_texture_default). */
/* How an image texture continues past its edges, along u or along v. */
typedef enum glint_wrap {
    GLINT_WRAP_REPEAT = 0,    /* tiles: 1.25 reads as 0.25 */
    GLINT_WRAP_CLAMP,         /* the edge's texels go on: 1.25 reads as 1 */
    GLINT_WRAP_MIRROR         /* tiles, every other tile flipped: 1.25 reads as 0.75 */
} glint_wrap;

/* How an image texture is read between and across its texels. */
typedef enum glint_image_filter {
    GLINT_IMAGE_TRILINEAR = 0, /* the image, or where a sample covers more than a texel of it, its
                                   halved copies (mipmap levels) blended by the sample's footprint:
                                   no shimmer far away */
    GLINT_IMAGE_BILINEAR      /* the image alone, the 2 x 2 texels nearest blended: sharp, but a
                                 far one aliases */
} glint_image_filter;

typedef struct glint_texture {
    glint_texture_kind kind;
    glint_mapping mapping;
    glint_color colors[2];    /* checker: cells where floor(u/size) + floor(v/size) is even
                                 show colors[0], the others colors[1]; checker_3d: cells where
                                 floor(x/size) + floor(y/size) + floor(z/size) is even, (x, y, z)
                                 the point in the thing's own coordinates */
    double size;              /* checker, checker_3d: cell size, > 0 */
    const char *file;         /* image: a PNG or JPEG file (sRGB, converted to linear) or an
                                 OpenEXR file (linear, high dynamic range); u runs
                                 left to right, v top to bottom */
    glint_wrap wrap_u, wrap_v; /* image: past its edges (glint_texture_default: u repeats,
                                  v clamps) */
    glint_image_filter filter; /* image: how texels are blended (trilinear) */
    /* noise, marble, wood, granite: the pattern's value v (0 to 1) at a point
     * p of the thing's own space, q = p / scale, through the colour map. */
    glint_color_stop stops[GLINT_MAX_COLOR_STOPS]; /* ascending `at`, from 0 to 1 */
    int stop_count;           /* 2 to GLINT_MAX_COLOR_STOPS */
    double scale;             /* > 0: the size of the pattern's features */
    int octaves;              /* 1 to 16: layers of noise, each at lacunarity times the
                                 frequency and gain times the amplitude of the last */
    double lacunarity, gain;  /* lacunarity > 1, gain from 0 to 1 */
    double turbulence;        /* marble, wood: how far the bands are swirled, >= 0 */
    /* Every kind: where the texture sits on the thing. A point (solid kinds)
     * or (u, v, 0) (the others) is carried through the inverse of this
     * before the look-up, so a scale of 2 makes the pattern twice as large.
     * All zeros is taken as the identity, for zero-initialised structs. */
    glint_transform transform;
} glint_texture;

/* Returns a description of the given kind with every field at its default
 * and a uv mapping. */
glint_texture glint_texture_default(glint_texture_kind kind);

/* Adds a texture. Returns its index (>= 0) or -1 and fills err. `name` may
 * be NULL; a name already taken is refused. An image's file is checked now
 * (it can be read, and is a PNG or JPEG) and decoded when a material first
 * uses the texture (glint_scene_add_material, which then reports a corrupt
 * file), each file once a scene: a texture no material uses costs no
 * pixels. */
int glint_scene_add_texture(glint_scene *scene, const char *name, const glint_texture *texture, glint_error *err);

/* Adds a checkerboard of colours a and b with square cells of `cell` texture
 * units; cell (floor(u/cell) + floor(v/cell)) even shows a: a
 * glint_scene_add_texture of a checker. Returns the texture's index (>= 0)
 * or -1 and fills err. `name` may be NULL. */
int glint_scene_add_checker(glint_scene *scene, const char *name, glint_color a, glint_color b,
                            double cell, glint_mapping mapping, glint_error *err);

/* Adds an image texture from a PNG or JPEG file (sRGB, converted to linear)
 * or an OpenEXR file (linear floats, kept above 1: high dynamic range),
 * decoded when a material first uses it: a glint_scene_add_texture of an
 * image. u runs left to right, v
 * top to bottom, repeating in u and clamped in v. Returns the texture's
 * index or -1 and fills err. */
int glint_scene_add_image_file(glint_scene *scene, const char *name, const char *path,
                               glint_mapping mapping, glint_error *err);

/* As glint_scene_add_image_file, from PNG, JPEG or OpenEXR bytes in memory. */
int glint_scene_add_image_memory(glint_scene *scene, const char *name, const void *data,
                                 size_t size, glint_mapping mapping, glint_error *err);

/* Replaces the image of the named image texture with the file at `path`,
 * keeping its mapping. */
glint_status glint_scene_replace_image(glint_scene *scene, const char *name, const char *path,
                                       glint_error *err);

/* ---------------------------------------------------------------- materials */

/* Phong material with mirror reflection, transparency and refraction.
 * The surface shows
 *   (1 - transparency - refraction) * phong
 *   + reflectivity * reflected
 *   + transparency * filter * straight-through
 *   + refraction * filter * refracted,
 * where filter = (1 - tint) + tint * colour. With fresnel set, the refraction
 * share is split between the refracted and reflected rays by the dielectric
 * Fresnel equations; total internal reflection always sends it to the
 * reflected ray. */
/* Beer-Lambert absorption inside a thing: light that has travelled
 * `distance` through it keeps `color` of itself, so length L keeps
 * color^(L / distance) (a channel of 0 is taken as 1e-12). */
typedef struct glint_absorption {
    glint_color color;        /* channels from 0 to 1 */
    double distance;          /* > 0; 0: no absorption */
} glint_absorption;

typedef struct glint_material {
    glint_color color;        /* base colour */
    int texture;              /* texture index replacing color, or -1 */
    double ambient;           /* 0..1, share of color lit by ambient light */
    double diffuse;           /* >= 0 */
    double specular;          /* >= 0, white highlight strength */
    double shininess;         /* Phong exponent, >= 0 */
    double reflectivity;      /* 0..1 */
    double transparency;      /* 0..1 */
    double refraction;        /* 0..1, transparency + refraction <= 1 */
    double ior;               /* index of refraction, > 0 */
    double tint;              /* 0..1, how much colour filters transmitted light */
    bool fresnel;
    glint_color emission;     /* light the surface gives off from its front, times */
    double emission_strength; /* this: its radiance; an emissive shape or mesh lights the scene */
    double roughness;         /* 0..1: reflection and refraction blurred over a lobe (0: sharp) */
    int glossy_samples;       /* 1..1024: rays a camera ray's blurred reflection or refraction
                                 is spread over */
    double metallic;          /* 0..1: reflections and highlights take the base colour, white at
                                 0, the base colour (or texture) at 1, as a metal's do */
    glint_absorption absorption; /* what light loses travelling inside (distance 0: nothing) */
    double dispersion;        /* the Abbe number (n_d - 1) / (n_F - n_C), ior being n_d: refracted
                                 light splits into the spectrum's bands (glint_settings'
                                 dispersion_bands), lower splits more (flint glass 30, crown 60,
                                 diamond 55); 0: none */
    /* Surface detail, both through the texture's (u, v) or, for a solid
     * texture's height, its point; an image is read as data (a byte b as
     * b / 255), not as colour. */
    int bump_texture;         /* a texture whose brightness (mean of its channels) is a height,
                                 tilting the shading normal; -1: none */
    double bump_strength;     /* the height of brightness 1, in the thing's own units (may be
                                 negative: dents) */
    int normal_texture;       /* a tangent-space normal map (red along +u, green towards the
                                 image's top, blue out, each 0..1 for -1..1); -1: none */
} glint_material;

/* Returns a matte white material: ambient 0.2, diffuse 1, specular 1,
 * shininess 50, nothing else; ior 1.5, tint 1, no texture, no emission
 * (emission black, emission_strength 1), roughness 0 with 16 glossy
 * samples, no bump (strength 0.1) or normal map. */
glint_material glint_material_default(void);

/* Adds a material; returns its index or -1 and fills err. Its texture's
 * image, if not decoded yet, is decoded here: a corrupt file, or pixels
 * past the scene's 4 GiB, is an error of this call. */
int glint_scene_add_material(glint_scene *scene, const char *name, const glint_material *m,
                             glint_error *err);

/* ------------------------------------------------------------------ shapes */

typedef enum glint_shape_kind {
    GLINT_SHAPE_SPHERE = 0,
    GLINT_SHAPE_PLANE,      /* infinite plane through point with normal */
    GLINT_SHAPE_POLYGON,    /* convex planar triangle or quad; its front faces the side from
                               which the points run anticlockwise */
    GLINT_SHAPE_BOX,        /* axis-aligned box between min and max */
    GLINT_SHAPE_CYLINDER,   /* about +y from centre of base, radius, height, optional caps */
    GLINT_SHAPE_CONE,       /* apex above the centre of base at height, or cut off there at
                               top_radius; optional caps */
    GLINT_SHAPE_DISK,       /* disc (or, with inner_radius, a ring) about center, facing normal */
    GLINT_SHAPE_TORUS,      /* ring about +y through center in the xz plane: radius (major) to the
                               middle of its tube, minor_radius the tube's */
    GLINT_SHAPE_QUADRIC,    /* any second-order surface (coefficients), clipped by the box min..max */
    /* Constructive solid geometry: a combination of the closed shapes
     * glint_scene_add_part gives it, reading no field of glint_shape. */
    GLINT_SHAPE_UNION,        /* inside any of its parts */
    GLINT_SHAPE_INTERSECTION, /* inside all of its parts */
    GLINT_SHAPE_DIFFERENCE,   /* inside its first part and none of the others */
    /* A closed mesh as a part of a combination: only
     * glint_scene_add_mesh_part makes one (glint_shape describes none). */
    GLINT_SHAPE_MESH
} glint_shape_kind;

/* A shape's description: each kind reads the fields named beside them.
 * docs/scene-format.md lists each kind's fields with their defaults and
 * ranges (the scene file's keys have the same names, `point` for a plane's
 * center); start from glint_shape_default to get the defaults. */
typedef struct glint_shape {
    glint_shape_kind kind;
    glint_vec3 center;        /* sphere and disk centre; cylinder and cone base centre; plane point */
    double radius;            /* sphere, cylinder, cone base, disk (outer), torus (major) */
    double height;            /* cylinder, cone */
    bool capped;              /* cylinder: both caps; cone: base cap */
    double top_radius;        /* cone: 0 (a point), or the radius where it is cut off at height */
    bool top_capped;          /* cone with a top_radius: the top cap */
    glint_vec3 normal;        /* plane, disk: the side it faces */
    glint_vec3 points[4];     /* polygon */
    int point_count;          /* polygon: 3 or 4 */
    glint_vec3 min, max;      /* box */
    double inner_radius;      /* disk: 0, or the radius of its hole (a ring), below radius */
    double minor_radius;      /* torus: the tube's radius, below radius (the major radius) */
    double coefficients[10];  /* quadric: A..J of A x^2 + B y^2 + C z^2 + D xy + E xz + F yz + G x
                                 + H y + I z + J = 0, within the box min..max */
} glint_shape;

/* Returns a description of the given kind with every field at its default
 * (docs/scene-format.md): a capped cylinder, a disk facing +y, a zero
 * radius that must still be set, and so on. */
glint_shape glint_shape_default(glint_shape_kind kind);

/* Adds a shape with material index `material`, placed by `transform` (NULL
 * for identity). Returns the shape's index or -1 and fills err when the
 * shape is degenerate, a value is not finite, the material does not exist or
 * the transform is singular. */
int glint_scene_add_shape(glint_scene *scene, const glint_shape *shape, int material,
                          const glint_transform *transform, glint_error *err);

/* Adds `count` spheres as one shape, a sphere set: sphere k has centre
 * centers[k], radius radii[k] (positive) and material index materials[k],
 * whose material must not glow (add glowing spheres with
 * glint_scene_add_shape, as lights). The spheres render exactly as spheres
 * added one by one would, in about 36 bytes each where a shape takes
 * several hundred: for particles, molecules, or an NFF file's spheres. A
 * set has no transform, cannot move and cannot be a part of a
 * combination; a hit on it is on one of its spheres. Returns the set's
 * shape index or -1 and fills err, naming the first sphere at fault. */
int glint_scene_add_spheres(glint_scene *scene, int count, const glint_vec3 *centers, const double *radii,
                            const int *materials, glint_error *err);

/* Adds a shape as a part of combination `csg` (a union, intersection or
 * difference added before by glint_scene_add_shape or this): it is then
 * seen only through the combination, and may itself be a combination, up
 * to 32 deep and 256 parts each. It must be closed: a sphere, box, torus,
 * plane (the half-space behind it), cylinder with caps, cone with its caps,
 * or a combination. Its transform places it in the world, as
 * glint_scene_add_shape's does (a combination takes none: NULL or the
 * identity). `material` may be -1 for a combination, whose parts then
 * need their own; a part's surface shows its own material. Returns the
 * part's shape index or -1 and fills err. */
int glint_scene_add_part(glint_scene *scene, int csg, const glint_shape *shape, int material,
                         const glint_transform *transform, glint_error *err);

/* Adds mesh `mesh` (glint_scene_add_mesh's or an import's) as a part of
 * combination `csg`, as glint_scene_add_part adds a shape: placed by
 * `transform`, with `material` or, -1, the mesh's own. The mesh must be
 * the closed surface of a solid: welding corners at the same position,
 * each edge borders exactly two triangles, which run along it opposite
 * ways (either winding will do: its inside is found). The first time a
 * mesh is made a part, this checks it and builds its own hierarchy (time
 * and memory like the mesh's); its other parts share them. Returns the
 * part's shape index or -1 and fills err, naming the first open or
 * misturned edge by its corners. */
int glint_scene_add_mesh_part(glint_scene *scene, int csg, int mesh, int material, const glint_transform *transform,
                              glint_error *err);

/* ------------------------------------------------------------------ lights */

typedef enum glint_light_kind {
    GLINT_LIGHT_POINT = 0,
    GLINT_LIGHT_SPOT,
    GLINT_LIGHT_DIRECTIONAL,
    GLINT_LIGHT_SPHERE,     /* area lights: a glowing ball, */
    GLINT_LIGHT_RECTANGLE,  /* a glowing parallelogram, lit on one side, */
    GLINT_LIGHT_DISK        /* a glowing disc, lit on one side */
} glint_light_kind;

/* How the light of a point or spot light weakens with the distance d from it. */
typedef enum glint_falloff {
    GLINT_FALLOFF_NONE = 0,       /* not at all: the default, as in the COSC363 scene */
    GLINT_FALLOFF_INVERSE_SQUARE, /* color / d^2: physical, color arriving at distance 1 */
    GLINT_FALLOFF_FADE            /* POV-Ray's fade: color * 2 / (1 + (d / fade_distance)^fade_power) */
} glint_falloff;

typedef struct glint_light {
    glint_light_kind kind;
    glint_vec3 position;      /* point, spot; sphere and disk: centre; rectangle: a corner */
    glint_vec3 direction;     /* spot, disk: where it points; directional: where light travels */
    glint_color color;        /* intensity per channel; an area light's radiance: far from it,
                                 it lights as a point light with inverse-square falloff
                                 whose colour is this times its area facing the point / pi */
    double radius;            /* sphere, disk: > 0 */
    glint_vec3 edge1, edge2;  /* rectangle: its sides from the corner, lit on the side of
                                 edge1 x edge2 */
    int samples;              /* area lights: shadow rays per shading point, 1..4096 */
    double cone_angle;        /* spot: half-angle of the cone, degrees, (0, 90] */
    double falloff_angle;     /* spot: width of the soft edge inside the cone, degrees; 0 = hard */
    glint_falloff falloff;    /* point, spot; a directional light's must be none */
    double fade_distance;     /* fade: > 0, where the light is its colour (brighter nearer) */
    double fade_power;        /* fade: > 0, how fast it fades beyond (2: as the square) */
} glint_light;

/* Returns a description of the given kind with every field at its default
 * (docs/scene-format.md): colour white, 16 samples for an area light, and
 * the positions, directions and sizes still to be set. */
glint_light glint_light_default(glint_light_kind kind);

/* ------------------------------------------------------------ environment */

/* What rays that hit nothing see: the background colour, or a texture
 * wrapped around the scene as an equirectangular (latitude-longitude)
 * image: the image's middle column is -z, its left and right edges +z, its
 * top row +y and its bottom row -y. */
typedef struct glint_environment {
    int texture;              /* the texture seen, or -1: the background colour */
    double intensity;         /* multiplies the texture's colour, >= 0 */
    double rotation;          /* degrees, turns the image about +y (90: -z's column faces -x) */
} glint_environment;

/* Sets the scene's environment after checking it (a texture that exists,
 * decoding its image now; a finite intensity >= 0 and rotation). */
glint_status glint_scene_set_environment(glint_scene *scene, const glint_environment *env, glint_error *err);

/* The scene's environment: texture -1, intensity 1, rotation 0 unless set. */
glint_environment glint_scene_get_environment(const glint_scene *scene);

/* Adds a light; returns its index or -1 and fills err. */
int glint_scene_add_light(glint_scene *scene, const glint_light *light, glint_error *err);

/* ------------------------------------------------------------------ meshes */

/* A triangle mesh given as arrays; glint copies them. Vertices are in the
 * mesh's own coordinates; instances place the mesh in the world. */
typedef struct glint_mesh_data {
    const float *positions;   /* 3 floats per vertex, finite */
    const float *normals;     /* 3 per vertex (need not be unit length), or NULL for flat shading */
    const float *uvs;         /* 2 per vertex, or NULL (then u = v = 0) */
    int vertex_count;         /* 1..2^30 */
    const uint32_t *indices;  /* 3 per triangle, each < vertex_count */
    int triangle_count;       /* 1..2^30 */
    const int *materials;     /* a material index per triangle, or NULL: `material` for all */
    int material;             /* used when materials is NULL */
} glint_mesh_data;

/* Adds a mesh (not yet placed: see glint_scene_add_instance). Returns its
 * index or -1 and fills err: a non-finite position, an index out of range,
 * a material that does not exist. Degenerate triangles are kept (they are
 * never hit). `name` may be NULL. */
int glint_scene_add_mesh(glint_scene *scene, const char *name, const glint_mesh_data *mesh, glint_error *err);

/* Places mesh `mesh` in the world through `transform` (NULL: identity). With
 * material >= 0 every triangle of this instance uses that material instead
 * of the mesh's own. The triangles are stored once however many instances
 * there are. Returns the instance's index or -1 and fills err. */
int glint_scene_add_instance(glint_scene *scene, int mesh, int material, const glint_transform *transform,
                             glint_error *err);

/* The most points a polygon of glint_scene_add_polygon may have. */
#define GLINT_MAX_POLYGON_POINTS (1 << 20)

/* Adds a flat polygon of `count` points (3 to GLINT_MAX_POLYGON_POINTS),
 * convex or not but not crossing itself, as the triangles that cover it
 * exactly (ear clipping; positions then in single precision, as a mesh's):
 * a mesh of its own, placed once by `transform` (NULL: identity) with
 * `material`. Its front is the side from which the points run
 * anticlockwise, and its (u, v) are a polygon shape's: the affine
 * coordinates along the edges from point 0 to point 1 and to the last
 * point. Returns the placement's index (as glint_scene_add_instance's) or
 * -1 and fills err: points not finite, two in a row the same, all in a
 * line, or off one plane by 1e-6 of the polygon's size. */
int glint_scene_add_polygon(glint_scene *scene, const glint_vec3 *points, int count, int material,
                            const glint_transform *transform, glint_error *err);

/* The most samples a side of a heightfield may have. */
#define GLINT_MAX_HEIGHTFIELD_SIDE 16384

/* Adds a heightfield: a grid of columns x rows heights (each at least 2,
 * at most GLINT_MAX_HEIGHTFIELD_SIDE), heights[row * columns + column]
 * from 0 to 1, sized by the box min..max: column c is at x = min.x + c
 * (max.x - min.x) / (columns - 1), row r at z = min.z + r (...) along z,
 * height h at y = min.y + h (max.y - min.y). Each cell is two triangles
 * (split along the diagonal from its corner nearest min to the opposite
 * one), smoothly shaded by normals from the neighbouring heights, its
 * (u, v) the column and row fractions (so an image of the same grid lies
 * on it as it was drawn, row 0 along min.z). A mesh of its own, placed
 * once by `transform` (NULL: identity); returns the placement's index or
 * -1 and fills err. */
int glint_scene_add_heightfield(glint_scene *scene, const float *heights, int columns, int rows, glint_vec3 min,
                                glint_vec3 max, int material, const glint_transform *transform, glint_error *err);

/* Options for glint_scene_import_mesh. Zero them for the defaults. */
typedef struct glint_import_options {
    double crease_angle;      /* degrees; vertex normals are generated when the file has
                                 none, smoothing across edges sharper than this angle
                                 never; 0 means 80; 180 smooths everything */
    int default_material;     /* for triangles whose file gives no material; -1: a matte grey */
} glint_import_options;

/* Imports a model file (OBJ+MTL with glint's own reader; PLY, glTF 2.0 /
 * GLB, STL through Assimp) as one mesh: the file's node hierarchy is
 * flattened, its materials become scene materials (docs/meshes.md gives the
 * mapping) and its diffuse or base-colour textures image textures. Returns
 * the mesh's index or -1 and fills err with a message naming the file (and,
 * for OBJ and MTL text, the line and column). options may be NULL. */
int glint_scene_import_mesh(glint_scene *scene, const char *path, const glint_import_options *options,
                            glint_error *err);

/* As glint_scene_import_mesh, from `size` bytes in memory; `name` stands for
 * the file in messages and its extension (".obj", ".glb", ...) tells the
 * format. Files the model refers to (MTL, textures) are not read. */
int glint_scene_import_mesh_memory(glint_scene *scene, const void *data, size_t size, const char *name,
                                   const glint_import_options *options, glint_error *err);

/* True when mesh `mesh` was imported from a file that gives it no
 * materials, so every triangle has the importer's stand-in (a grey, or the
 * import's default_material): a placement may then choose one, as a scene
 * file's group does. False for a mesh with materials from its file, for
 * one from glint_scene_add_mesh (its caller chose them), and for an index
 * that is no mesh. */
bool glint_scene_mesh_is_bare(const glint_scene *scene, int mesh);

/* The axis-aligned bounds of a mesh in its own coordinates. */
glint_status glint_scene_mesh_bounds(const glint_scene *scene, int mesh, glint_vec3 *min, glint_vec3 *max,
                                     glint_error *err);

/* Where glint_scene_for_model_ex looks at the model from. y is up and the
 * model faces +z, as glTF and most OBJ files do. */
typedef enum glint_model_view {
    GLINT_VIEW_AUTO = 0,  /* into the opening of a room open on one side (a Cornell box),
                             straight on; any other model from the front */
    GLINT_VIEW_FRONT,     /* from +z, 20 degrees above */
    GLINT_VIEW_BACK,      /* from -z, 20 degrees above */
    GLINT_VIEW_LEFT,      /* from -x, 20 degrees above */
    GLINT_VIEW_RIGHT,     /* from +x, 20 degrees above */
    GLINT_VIEW_TOP,       /* from +y looking down, -z up in the picture */
    GLINT_VIEW_ISO        /* from (+1, +1, +1), three-quarters */
} glint_model_view;

/* Options for glint_scene_for_model_ex. Zero them for the defaults. */
typedef struct glint_model_view_options {
    glint_model_view view;
    int width, height;        /* the image the camera frames, 1..65536 each; 0: 800 and 600 */
} glint_model_view_options;

/* Builds a scene for looking at one model file: the model as it is, a
 * checkered floor under it (y is up), a key and a fill light that turn
 * with the view (and, looking into a room, a light at its opening), 4
 * samples per pixel, and a camera
 * (35 degrees vertical field of view) placed so that the 8 corners of the
 * model's bounding box, projected, are centred in the image and span 85% of
 * its width or height, whichever limits. docs/meshes.md says how a room's
 * opening is found. options may be NULL. Returns NULL and fills err when
 * the model cannot be imported or an option is out of range. */
glint_scene *glint_scene_for_model_ex(const char *path, const glint_model_view_options *options, glint_error *err);

/* As glint_scene_for_model_ex with every option at its default: 800x600,
 * GLINT_VIEW_AUTO. */
glint_scene *glint_scene_for_model(const char *path, glint_error *err);

/* True when path names a model file by its extension (.obj, .ply, .stl,
 * .gltf, .glb, any case) rather than a scene file. */
bool glint_is_model_path(const char *path);

/* ------------------------------------------------------------ scene files */

/* Called once for each problem found while loading a scene file, with a
 * one-line message "file:line:column: what is wrong". */
typedef void (*glint_report_fn)(void *user, const char *message);

typedef struct glint_load_options {
    glint_report_fn report;   /* NULL: problems are only counted, and err gets the first */
    void *report_user;
    int max_errors;           /* stop after this many problems; 0 means 20 */
    double time;              /* seconds: the scene as it is then, every keyed value
                                 (docs/animation.md) at this time; finite */
} glint_load_options;

/* Loads a YAML scene file (docs/scene-format.md). Returns the scene, or NULL
 * when the file has any problem: every problem, up to max_errors, goes to
 * options->report, and err receives the first one. Texture paths and
 * includes are relative to the file that names them. options may be NULL. */
glint_scene *glint_scene_load_file(const char *path, const glint_load_options *options, glint_error *err);

/* As glint_scene_load_file, from `size` bytes in memory; `name` stands for
 * the file in messages, and relative paths resolve against the directory
 * part of `name`. */
glint_scene *glint_scene_load_memory(const char *data, size_t size, const char *name,
                                     const glint_load_options *options, glint_error *err);

/* As glint_scene_load_file, from the open stream `in` read to its end, for
 * standard input: at most the 64 MiB a scene file may have (more is
 * GLINT_ERR_INVALID, "scene 'NAME' is too large"), and nothing at all is
 * "NAME: the file holds no scene". `name` stands for the stream in messages
 * ("<stdin>:3:5: ..."; NULL: "<stream>"), and relative paths resolve
 * against its directory part, so against the current directory for a name
 * without a '/'. The stream is left open. */
glint_scene *glint_scene_load_stream(FILE *in, const char *name, const glint_load_options *options,
                                     glint_error *err);

/* Sets the output image path a scene file asked for (NULL clears it). */
glint_status glint_scene_set_output(glint_scene *scene, const char *path, glint_error *err);

/* Whether some value of a scene file was keyed (docs/animation.md), so
 * that the scene changes with the time it is loaded at. */
bool glint_scene_is_animated(const glint_scene *scene);

/* Motion over the shutter (settings.shutter_open and _close): the shape's
 * world transform goes through `count` poses, 2..64, evenly spaced from
 * the shutter's opening to its closing, in straight lines between them
 * (each number of the matrix interpolated linearly), replacing the
 * transform it was added with. Each must be invertible and finite. A
 * part of a combination moves too (the combination takes it where it is
 * at each ray's time); a combination itself has no transform to move. */
glint_status glint_scene_move_shape(glint_scene *scene, int shape, int count, const glint_transform *poses,
                                    glint_error *err);

/* A placed mesh's motion over the shutter, as glint_scene_move_shape's:
 * Embree's instance motion blur, one time step a pose. */
glint_status glint_scene_move_instance(glint_scene *scene, int instance, int count, const glint_transform *poses,
                                       glint_error *err);

/* A light's motion over the shutter, as glint_scene_move_shape's: its
 * position, direction, colour, a spot's cone, an area light's edges and
 * radius go in straight lines from each of `count` poses (each checked as
 * glint_scene_add_light checks, of the light's kind) to the next, an area
 * light's surface with them. (An emissive shape's light moves with the
 * shape, glint_scene_move_shape.) */
glint_status glint_scene_move_light(glint_scene *scene, int light, int count, const glint_light *poses,
                                    glint_error *err);

/* The camera's motion over the shutter, as glint_scene_move_shape's: each
 * lane's ray goes in a straight line from its ray through cameras[k] to
 * its ray through cameras[k + 1]. Each camera must pass
 * glint_scene_set_camera's checks and be of the scene's camera's kind. */
glint_status glint_scene_move_camera(glint_scene *scene, int count, const glint_camera *cameras, glint_error *err);

/* Returns the output path a scene file asked for, or NULL. */
const char *glint_scene_get_output(const glint_scene *scene);

/* Refuses (GLINT_ERR_INVALID) an image output `path` that names one of
 * the files the scene was read from: its scene files and includes, image
 * textures, models and the files they name. Files are compared as the
 * file system knows them (device and inode), so any name for one of them
 * is refused; a path that does not exist yet passes. Call it before
 * rendering, after any glint_scene_replace_image. */
glint_status glint_scene_check_output(const glint_scene *scene, const char *path, glint_error *err);

/* The warnings gathered while the scene was built, for things it went on
 * without (a model's MTL file that does not exist): how many (at most 100
 * are kept), and the index-th (NULL when out of range), owned by the
 * scene. */
int glint_scene_warning_count(const glint_scene *scene);
const char *glint_scene_warning(const glint_scene *scene, int index);

/* Writes the scene as a YAML scene file (docs/scene-format.md) that
 * glint_scene_load_file reads back to the same scene, so that it renders
 * to the same image bytes: what `glint --print-scene` prints. The settings
 * and camera are written with every key; textures, materials, lights and
 * objects with the keys whose values differ from their defaults. Each
 * object is written placed, its transform one exact `matrix` step (groups
 * are gone); a mesh is written as its model file, whose import makes its
 * own materials and textures again. Numbers are written in the fewest
 * digits that read back to the same bits, colours as display values where
 * those convert back exactly, else as {linear: [r, g, b]}. Paths are
 * written as the scene holds them: relative to the current directory when
 * it was loaded with relative paths, so the file belongs there (or give
 * absolute paths). Nothing is written and GLINT_ERR_INVALID returned when
 * a scene file cannot say what the scene holds: a mesh built from arrays
 * or bytes rather than a model file, or imported with a default material;
 * an image texture decoded from bytes in memory. GLINT_ERR_IO when
 * writing to `out` fails. */
glint_status glint_scene_write_yaml(const glint_scene *scene, FILE *out, glint_error *err);

/* Counts of what a scene holds, for reports such as `glint --check`. */
typedef struct glint_scene_counts {
    int textures, materials, shapes, lights, meshes, instances;
    long long triangles;      /* stored, each mesh once */
    int sphere_sets;          /* of the shapes, the sphere sets (glint_scene_add_spheres), */
    long long set_spheres;    /* and the spheres they hold */
} glint_scene_counts;

/* Returns the counts of what the scene holds. */
glint_scene_counts glint_scene_get_counts(const glint_scene *scene);

/* --------------------------------------------------------------- rendering */

/* A linear float RGB image: pixels[3 * (y * width + x) + channel], top row first. */
typedef struct glint_image {
    int width, height;
    float *pixels;
} glint_image;

/* Frees the pixels of an image filled by glint_render. */
void glint_image_free(glint_image *image);

/* Counts gathered by a render. */
typedef struct glint_render_stats {
    double seconds;
    uint64_t samples;         /* camera samples */
    uint64_t rays;            /* camera, reflected, refracted, transmitted and shadow rays */
    uint64_t nan_samples;     /* camera samples whose colour came out NaN: left out of
                                 their pixels' averages (a pixel with only such samples
                                 is black), so no NaN reaches the image */
    int tiles_done, tiles_total; /* finished tiles, of all; fewer only when cancelled */
} glint_render_stats;

/* Called after every finished tile with the count finished so far, from
 * whichever render thread finished it, one call at a time and in order;
 * the last call reports tiles_done == tiles_total. */
typedef void (*glint_progress_fn)(void *user, int tiles_done, int tiles_total);

/* Called as each tile is finished, with its pixels: columns x0 to x1 and
 * rows y0 to y1 of the image (the ends excluded), `pixels` its top-left
 * pixel (3 floats, linear RGB, as the image holds them), its rows `stride`
 * floats apart; they are final, and valid only during the call. Called
 * from whichever thread finished the tile, while others may be in it too:
 * it must be thread-safe, and quick (a copy, say), as the thread renders
 * nothing meanwhile. For showing an image as it comes in. */
typedef void (*glint_tile_fn)(void *user, int x0, int y0, int x1, int y1, const float *pixels, size_t stride);

typedef struct glint_render_options {
    int threads;              /* 0 means one per core */
    int tile_size;            /* 0 means 32; rounded up to a multiple of 4 */
    glint_progress_fn progress;
    void *progress_user;
    const volatile int *cancel; /* when non-NULL and set non-zero, the render stops: each
                                   thread reads it at every packet of 8 rays it traces */
    int keep_partial;         /* non-zero: a cancelled render still fills *out, with its
                                 finished tiles and every other pixel black */
    glint_tile_fn tile_done;  /* NULL, or told of each finished tile's pixels */
    void *tile_user;
} glint_render_options;

/* Renders the scene into *out (allocated here; free with glint_image_free).
 * The image bytes depend only on the scene and its settings, never on the
 * thread count or tile size. stats may be NULL. When the cancel flag is set
 * it returns GLINT_ERR_CANCELLED with no image, or, with keep_partial, with
 * the finished tiles in *out (to be freed as any) and stats filled. */
glint_status glint_render(const glint_scene *scene, const glint_render_options *options,
                          glint_image *out, glint_render_stats *stats, glint_error *err);

/* Writes the image in the format its path's extension names, in any case
 * (glint_image_format_for_path): 8-bit sRGB PNG (".png"), binary PPM
 * (".ppm"), or OpenEXR (".exr": the linear values as they are, half
 * floats). The file is written under a temporary name beside it and renamed
 * into place, so a failure never leaves a partial file and never destroys
 * an existing one. The same as glint_image_write_ex with NULL options. */
glint_status glint_image_write(const glint_image *image, const char *path, glint_error *err);

/* The pixel type of an OpenEXR file's channels. */
typedef enum glint_exr_pixel {
    GLINT_EXR_HALF = 0,  /* 16-bit float, the default: what compositors expect of a
                            beauty pass; values of 65520 and more become +inf */
    GLINT_EXR_FLOAT = 1  /* 32-bit float: the rendered values exactly */
} glint_exr_pixel;

/* How glint_image_write_ex writes; all zero is the default. */
typedef struct glint_image_write_options {
    glint_exr_pixel exr_pixel; /* .exr files only; the other formats ignore it */
    int bit_depth;             /* .png and .ppm only: 8 (or 0, the default) or 16 bits a
                                  channel, sRGB either way; 16 keeps gradients and low
                                  noise that 8 would round away. .exr ignores it */
} glint_image_write_options;

/* As glint_image_write, with options (NULL: the defaults). An exr_pixel
 * that is not a glint_exr_pixel, or a bit_depth other than 0, 8 and 16, is
 * GLINT_ERR_INVALID. */
glint_status glint_image_write_ex(const glint_image *image, const char *path,
                                  const glint_image_write_options *options, glint_error *err);

/* Checks, before rendering, that glint_image_write could write `path`: a
 * known extension and a writable directory. */
glint_status glint_image_check_path(const char *path, glint_error *err);

/* An image file format glint_image_write writes. */
typedef struct glint_image_format {
    const char *name;              /* "PNG", "PPM", "OpenEXR" */
    const char *const *extensions; /* lower case, each with its dot, NULL after the last */
    const char *meaning;           /* one line: what the file holds */
} glint_image_format;

/* The index-th format glint_image_write writes, counting from 0, or NULL
 * past the last: for listing them, as `glint --help` does. */
const glint_image_format *glint_image_format_at(int index);

/* The format glint_image_write writes `path` in, by the extension of its
 * last component, in any case; NULL when none has it (or path is NULL). */
const glint_image_format *glint_image_format_for_path(const char *path);

/* The format whose name or one of whose extensions without the dot is
 * `name`, in any case ("png", "PPM", "exr", "OpenEXR"); NULL when none is
 * (or name is NULL): for choosing a format by a word, as `glint --format`
 * does. */
const glint_image_format *glint_image_format_named(const char *name);

/* As glint_image_write_ex, in `format` (glint_image_format_at, _for_path
 * or _named), to fd, a file descriptor open for writing such as standard
 * output or a pipe: from its position on, in one pass (it never seeks), and
 * left open. Unlike a path, fd gets no temporary file: a write that fails
 * partway leaves what was written. `name` stands for it in messages
 * ("<stdout>"; NULL: "<output>"). A format not from glint_image_format_*
 * is GLINT_ERR_INVALID; a failed write is GLINT_ERR_IO with the errno text. */
glint_status glint_image_write_fd(const glint_image *image, int fd, const glint_image_format *format,
                                  const glint_image_write_options *options, const char *name, glint_error *err);

#ifdef __cplusplus
}
#endif
#endif
