/* scene.h - the in-memory scene every loader builds and the renderer reads. */
#ifndef GLINT_SCENE_SCENE_H
#define GLINT_SCENE_SCENE_H

#include "core/file_set.h"
#include "core/id_table.h"
#include "core/params.h"
#include "geometry/mesh.h"
#include "geometry/shape.h"
#include "shading/environment.h"
#include "shading/light.h"
#include "shading/material.h"
#include "shading/texture.h"

#include <sys/stat.h>

struct glint_scene {
    glint_settings settings;
    glint_camera camera;
    glint_fog fog;
    glint_environment environment;
    texture *textures;
    int texture_count;
    size_t texture_cap;
    material *materials;
    int material_count;
    size_t material_cap;
    id_table texture_names;   /* the named textures and materials, by name: */
    id_table material_names;  /* a scene of 100,000 loads in linear time */
    shape *shapes;
    int shape_count;
    size_t shape_cap;
    int combinations;         /* how many of the shapes are unions, intersections or differences */
    unsigned transform_ids;   /* the last transform number given to a part (shape.transform_id) */
    light *lights;
    int light_count;
    size_t light_cap;
    /* The lights that are not delta lights, which camera rays can see, as
     * indices into `lights`: a ray looks for those alone. */
    int *area_lights;
    int area_light_count;
    size_t area_light_cap;
    light *emitters;          /* the emissive shapes and meshes as lights (light.h), */
    int emitter_count;        /* made as they are added, apart from `lights` */
    size_t emitter_cap;
    mesh *meshes;
    int mesh_count;
    size_t mesh_cap;
    instance *instances;
    int instance_count;
    size_t instance_cap;
    char *output;             /* image path a scene file asked for, or NULL */
    file_set inputs;          /* every file read to build it (scene_files.c) */
    file_set image_files;     /* each image file decoded, once (scene_images.c), */
    texture_image *images;    /* and its pixels, at the same index */
    size_t image_cap;
    unsigned long long image_bytes; /* their pixels' bytes, within SCENE_MAX_IMAGE_BYTES */
    glint_camera *camera_poses; /* the camera's over the shutter (glint_scene_move_camera), */
    int camera_pose_count;    /* or 0: it stands still */
    bool animated;            /* read with keyed values (glint_scene_is_animated) */
    char **warnings;          /* what it went on without, for the user */
    int warning_count;
    size_t warning_cap;
};

/* Remembers the file of status st (or at path, when it exists) as one the
 * scene was read from, which glint_scene_check_output then refuses as an
 * output; fills err when out of memory. */
glint_status scene_note_file(glint_scene *scene, const struct stat *st, glint_error *err);
glint_status scene_note_path(glint_scene *scene, const char *path, glint_error *err);

/* The most bytes of decoded image pixels a scene holds, 4 GiB: five
 * images of the largest size (TEXTURE_IMAGE_MAX_PIXELS, 768 MiB each). */
#define SCENE_MAX_IMAGE_BYTES (4ULL << 30)

/* An image_load_fn (shading/texture.h) for `scene`: the file at path is
 * decoded the first time a texture names it, then shared with every
 * texture of that file (told by device and inode, so a link or another
 * spelling is the same file); the scene frees it. Refuses a file whose
 * pixels would take the scene's past SCENE_MAX_IMAGE_BYTES. */
glint_status scene_load_image(void *scene, const char *path, texture_image *out, glint_error *err);

/* The image_load_fn with which a scene adds a texture: the file is only
 * checked (texture_image_check_file) and *out left empty, to be decoded by
 * scene_use_texture when a material first uses it, so that a texture no
 * material uses costs no pixels. */
glint_status scene_check_image(void *scene, const char *path, texture_image *out, glint_error *err);

/* Decodes the image of texture `index` (through scene_load_image) if it is
 * an image texture not decoded yet; the decoder's message in err when that
 * fails, and the texture stays undecoded. Any other texture is ready. */
glint_status scene_use_texture(glint_scene *scene, int index, glint_error *err);

/* Frees the images scene_load_image decoded. */
void scene_free_images(glint_scene *scene);

/* Adds a warning (printf format) for glint_scene_warning; past 100 they
 * are dropped. Fills err when out of memory. */
glint_status scene_warn(glint_scene *scene, glint_error *err, const char *format, ...)
    __attribute__((format(printf, 3, 4)));

/* Frees what scene_motion.c keeps (by glint_scene_free). */
void scene_motion_free(glint_scene *scene);

/* Frees what scene_files.c keeps (by glint_scene_free). */
void scene_files_free(glint_scene *scene);

/* Index of the texture or material with that name, or -1 (for NULL too);
 * constant time. */
int scene_find_texture(const glint_scene *scene, const char *name);
int scene_find_material(const glint_scene *scene, const char *name);

/* Adds an image texture over pixels decoded ahead of time (see
 * texture_image_borrow: they are not copied and must outlive the scene)
 * from the image file `file`, which a scene written back as a file names.
 * Returns the texture's index or -1 and fills err. */
int scene_add_image_pixels(glint_scene *scene, const char *name, int width, int height,
                           const unsigned char *srgb, const char *file, glint_mapping mapping, glint_error *err);

/* Records where mesh `mesh` came from: `origin`, with a copy of `file`
 * (NULL: none) as its file; fills err when out of memory. */
glint_status scene_set_mesh_origin(glint_scene *scene, int mesh, const char *file, const mesh_origin *origin,
                                   glint_error *err);

/* The keys of the settings and of the camera, with their defaults and
 * ranges (settings.c). */
param_table settings_params(void);
param_table camera_params(void);

/* The keys of settings.ambient_occlusion (offsets into glint_settings),
 * with the defaults it has when given: 16 samples, no distance limit. */
param_table occlusion_params(void);

/* The first rule between the sampling settings that s breaks (a grid
 * sampler's square count, adaptive sampling's sampler and most samples):
 * the key it is about, "samples", "adaptive" or "max_samples", with the
 * message in err; NULL when s keeps them all. */
const char *sampling_rule_broken(const glint_settings *s, glint_error *err);

/* The keys of settings.filter (offsets into glint_settings): the type,
 * box by default, and the radius, 0 for the type's own. */
param_table filter_params(void);

/* The keys of settings.shutter (offsets into glint_settings): when it
 * opens and closes, in frames (0 and 0.5 when given), and the poses of a
 * moving thing over it (2). */
param_table shutter_params(void);

/* The keys of settings.frames (offsets into glint_settings): the first
 * and last frame of a sequence, 0 and 0 by default, and the frames a
 * second, 24. */
param_table frames_params(void);

/* The keys of settings.adaptive (offsets into glint_settings), with the
 * defaults they have when it is given: threshold 0.05, 64 samples at most. */
param_table adaptive_params(void);

/* The keys of a scene file's mesh object that are import options (offsets
 * into glint_import_options): the crease angle. */
param_table import_params(void);

/* The camera of a new scene: every key at its default. */
glint_camera camera_default(void);

/* Check settings and a camera against their tables and the rules across
 * keys (the pixel limit; a view direction, and up not along it); fill err
 * naming a bad value. */
glint_status settings_validate(const glint_settings *s, glint_error *err);
glint_status camera_validate(const glint_camera *cam, glint_error *err);

#endif
