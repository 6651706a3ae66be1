/* scene_motion.c - what moves over the shutter (settings.shutter_open to
 * _close): a shape's poses (and its light's, when it glows), a placed
 * mesh's, a light's and the camera's, evenly spaced over it, each
 * moving in straight lines between them; and whether the scene was read
 * with keyed values at all (docs/animation.md). */
#include <stdlib.h>
#include <string.h>
#include "core/error.h"
#include "core/transform.h"
#include "geometry/shape_kind.h"
#include "scene/scene.h"

/* The most poses over one shutter. */
#define MAX_POSES 64

bool glint_scene_is_animated(const glint_scene *scene)
{
    return scene->animated;
}

static glint_status check_count(int count, glint_error *err)
{
    if (count < 2 || count > MAX_POSES)
        return error_set(err, GLINT_ERR_INVALID, "motion takes 2 to %d poses, got %d", MAX_POSES, count);
    return GLINT_OK;
}

/* *out becomes a copy of `count` poses, each checked invertible, for a
 * thing moving over the shutter. */
static glint_status copy_poses(int count, const glint_transform *poses, transform **out, glint_error *err)
{
    glint_status st = check_count(count, err);
    for (int k = 0; k < count && !st; k++) {
        transform inverse;
        if (!xf_invert(&poses[k], &inverse))
            st = error_set(err, GLINT_ERR_INVALID, "pose %d's transform is singular or not finite", k + 1);
    }
    if (!st && !(*out = malloc(sizeof **out * (size_t)count)))
        st = error_set(err, GLINT_ERR_NOMEM, "out of memory for a thing's motion");
    if (!st)
        memcpy(*out, poses, sizeof **out * (size_t)count);
    return st;
}

glint_status glint_scene_move_shape(glint_scene *scene, int index, int count, const glint_transform *poses,
                                    glint_error *err)
{
    if (index < 0 || index >= scene->shape_count)
        return error_set(err, GLINT_ERR_INVALID, "shape %d does not exist", index);
    const shape *s = &scene->shapes[index];
    if (s->kind->csg)
        return error_set(err, GLINT_ERR_INVALID, "%s %s cannot move over the shutter: move its parts",
                         object_article(s->kind->name), s->kind->name);
    if (s->set)
        return error_set(err, GLINT_ERR_INVALID, "a sphere set cannot move over the shutter: add moving spheres "
                         "one by one");
    transform *copy;
    glint_status st = copy_poses(count, poses, &copy, err);
    if (st)
        return st;
    shape *moving = &scene->shapes[index];
    free(moving->poses);
    shape_move(moving, copy, count);
    /* The combinations it is in take their parts where they are at each
     * ray's time. */
    for (int up = moving->part_of; up >= 0; up = scene->shapes[up].part_of)
        scene->shapes[up].pose_count = count;
    if (moving->part_of >= 0)
        shape_parts_changed(scene->shapes, moving->part_of);
    /* Its light moves with it. */
    emitters_follow_shape(scene->emitters, scene->emitter_count, index, moving);
    return GLINT_OK;
}

glint_status glint_scene_move_instance(glint_scene *scene, int index, int count, const glint_transform *poses,
                                       glint_error *err)
{
    if (index < 0 || index >= scene->instance_count)
        return error_set(err, GLINT_ERR_INVALID, "instance %d does not exist", index);
    transform *copy;
    glint_status st = copy_poses(count, poses, &copy, err);
    if (st)
        return st;
    instance *inst = &scene->instances[index];
    free(inst->poses);
    inst->poses = copy;
    inst->pose_count = count;
    inst->to_world = copy[0];
    xf_invert(&inst->to_world, &inst->to_object);
    inst->has_transform = true;
    return GLINT_OK;
}

glint_status glint_scene_move_camera(glint_scene *scene, int count, const glint_camera *cameras, glint_error *err)
{
    glint_status st = check_count(count, err);
    for (int k = 0; k < count && !st; k++) {
        st = camera_validate(&cameras[k], err);
        if (!st && cameras[k].kind != scene->camera.kind)
            st = error_set(err, GLINT_ERR_INVALID, "camera pose %d is of another kind than the scene's camera", k + 1);
    }
    if (st)
        return st;
    glint_camera *copy = malloc(sizeof *copy * (size_t)count);
    if (!copy)
        return error_set(err, GLINT_ERR_NOMEM, "out of memory for the camera's motion");
    memcpy(copy, cameras, sizeof *copy * (size_t)count);
    free(scene->camera_poses);
    scene->camera_poses = copy;
    scene->camera_pose_count = count;
    return GLINT_OK;
}

glint_status glint_scene_move_light(glint_scene *scene, int index, int count, const glint_light *poses,
                                    glint_error *err)
{
    if (index < 0 || index >= scene->light_count)
        return error_set(err, GLINT_ERR_INVALID, "light %d does not exist", index);
    light *l = &scene->lights[index];
    glint_status st = check_count(count, err);
    if (st)
        return st;
    light *made = malloc(sizeof *made * (size_t)count);
    if (!made)
        return error_set(err, GLINT_ERR_NOMEM, "out of memory for a light's motion");
    for (int k = 0; k < count && !st; k++) {
        st = light_init(&made[k], &poses[k], err);
        if (!st && made[k].kind != l->kind)
            st = error_set(err, GLINT_ERR_INVALID, "light pose %d is of another kind than the light", k + 1);
    }
    if (st) {
        free(made);
        return st;
    }
    free(l->poses);
    light_move(l, made, count);
    return GLINT_OK;
}

void scene_motion_free(glint_scene *scene)
{
    for (int i = 0; i < scene->instance_count; i++)
        free(scene->instances[i].poses);
    for (int i = 0; i < scene->light_count; i++)
        free(scene->lights[i].poses);
    for (int i = 0; i < scene->shape_count; i++)
        free(scene->shapes[i].poses);
    free(scene->camera_poses);
}
