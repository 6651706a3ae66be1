/* scene.h - the in-memory scene every loader builds and the renderer reads. */
#ifndef GLINT_SCENE_SCENE_H
#define GLINT_SCENE_SCENE_H

#include "geometry/shape.h"
#include "shading/light.h"
#include "shading/material.h"
#include "shading/texture.h"

struct glint_scene {
    glint_settings settings;
    glint_camera camera;
    glint_fog fog;
    texture *textures;
    int texture_count, texture_cap;
    material *materials;
    int material_count, material_cap;
    shape *shapes;
    int shape_count, shape_cap;
    light *lights;
    int light_count, light_cap;
};

/* Checks a camera; fills err naming a bad value. */
glint_status camera_validate(const glint_camera *cam, glint_error *err);

#endif
