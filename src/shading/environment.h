/* environment.h - what rays that miss everything see: a texture wrapped
 * around the scene as an equirectangular image (glint_environment). */
#ifndef GLINT_SHADING_ENVIRONMENT_H
#define GLINT_SHADING_ENVIRONMENT_H

#include "core/params.h"
#include "shading/texture.h"

/* The keys of a scene file's environment but its texture, with their
 * defaults (intensity 1, rotation 0) and ranges: offsets into
 * glint_environment. */
param_table environment_params(void);

/* Checks env's intensity and rotation against the table, and that its
 * texture is -1 or below texture_count. */
glint_status environment_validate(const glint_environment *env, int texture_count, glint_error *err);

/* The colour of texture t wrapped around the scene, as env says, seen
 * along unit direction d (a solid texture: its colour at d). */
color environment_color(const glint_environment *env, const texture *t, vec3 d);

#endif
