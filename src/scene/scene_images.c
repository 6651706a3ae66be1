/* scene_images.c - the image files a scene's textures decode, each once,
 * and only when a material uses the texture. Four textures naming one
 * 16384 x 16384 PNG would otherwise decode it four times, 3 GB; they share
 * one decoding, and all decodings of a scene together stay within
 * SCENE_MAX_IMAGE_BYTES. */
#include <stdlib.h>
#include <sys/stat.h>
#include "core/file_log.h"
#include "core/array.h"
#include "core/error.h"
#include "scene/scene.h"

glint_status scene_load_image(void *user, const char *path, texture_image *out, glint_error *err)
{
    glint_scene *scene = user;
    struct stat st;
    /* A file that cannot be found is decoded as it is, for the decoder's
     * message; it is never kept. */
    bool known = file_stat(path, &st) == 0;
    long found = known ? file_set_find(&scene->image_files, st.st_dev, st.st_ino) : -1;
    if (found >= 0) {
        *out = texture_image_share(&scene->images[found]);
        return GLINT_OK;
    }
    if (known && !array_reserve((void **)&scene->images, &scene->image_cap, scene->image_files.count + 1,
                                sizeof *scene->images))
        return error_set(err, GLINT_ERR_NOMEM, "out of memory decoding texture '%s'", path);
    texture_image img;
    glint_status s = texture_image_load_file(&img, path, err);
    if (s)
        return s;
    unsigned long long bytes = texture_image_bytes(&img);
    if (bytes > SCENE_MAX_IMAGE_BYTES - scene->image_bytes) {
        texture_image_free(&img);
        return error_set(err, GLINT_ERR_INVALID,
                         "texture '%s' is too much: its %llu bytes of pixels would take the scene's textures past "
                         "the limit of %llu bytes (4 GiB)",
                         path, bytes, SCENE_MAX_IMAGE_BYTES);
    }
    if (!known) {
        scene->image_bytes += bytes;
        *out = img;
        return GLINT_OK;
    }
    long index = file_set_add(&scene->image_files, st.st_dev, st.st_ino);
    if (index < 0) {
        texture_image_free(&img);
        return error_set(err, GLINT_ERR_NOMEM, "out of memory decoding texture '%s'", path);
    }
    scene->image_bytes += bytes;
    scene->images[index] = img;
    *out = texture_image_share(&img);
    return GLINT_OK;
}

glint_status scene_check_image(void *scene, const char *path, texture_image *out, glint_error *err)
{
    (void)scene;
    *out = (texture_image){0};
    return texture_image_check_file(path, err);
}

glint_status scene_use_texture(glint_scene *scene, int index, glint_error *err)
{
    texture *t = &scene->textures[index];
    if (t->kind != &image_texture || texture_image_decoded(&t->image))
        return GLINT_OK;
    return scene_load_image(scene, t->desc.file, &t->image, err);
}

void scene_free_images(glint_scene *scene)
{
    for (size_t i = 0; i < scene->image_files.count; i++)
        texture_image_free(&scene->images[i]);
    free(scene->images);
    scene->images = NULL;
    scene->image_cap = 0;
    file_set_free(&scene->image_files);
    scene->image_bytes = 0;
}
