/* mtl_material.c - an MTL material as glint's, by the table of
 * docs/meshes.md: Kd is a display (sRGB) colour; Ks, Ns, d, Ni and Ke (the
 * emission) are used as they are; illum picks mirror (3, 5) or refracting (4, 6, 7; 7 with
 * Fresnel) behaviour. */
#include <math.h>
#include "model/model_build.h"
#include "model/mtl_read.h"

/* A colour channel of a file: finite and not negative, or 0. */
static double channel(double x)
{
    return isfinite(x) && x > 0 ? x : 0;
}

/* A number of a file, or fallback when it is not finite. */
static double finite_or(double x, double fallback)
{
    return isfinite(x) ? x : fallback;
}

glint_material mtl_to_glint(const mtl_material *a)
{
    glint_material m = glint_material_default();
    m.color = (glint_color){glint_srgb_to_linear(channel(a->kd[0])), glint_srgb_to_linear(channel(a->kd[1])),
                            glint_srgb_to_linear(channel(a->kd[2]))};
    /* Ke is a radiance, linear and often above 1 (the Cornell box's 17 12 4). */
    m.emission = (glint_color){channel(a->ke[0]), channel(a->ke[1]), channel(a->ke[2])};
    double ks_max = fmax(channel(a->ks[0]), fmax(channel(a->ks[1]), channel(a->ks[2])));
    m.specular = ks_max;
    m.shininess = model_clamp(finite_or(a->ns, 0), 0, MODEL_MAX_SHININESS);
    if (a->ni > 0 && isfinite(a->ni))
        m.ior = a->ni;
    double dissolved = 1 - model_clamp(finite_or(a->d, 1), 0, 1);
    switch (a->illum) {
    case 3:
    case 5:
        m.reflectivity = model_clamp(ks_max, 0, 1);
        m.transparency = dissolved;
        break;
    case 4:
    case 6:
    case 7:
        /* A refracting surface that the file leaves opaque (d 1, as some
         * exporters write glass) refracts fully. */
        m.refraction = dissolved > 0 ? dissolved : 1;
        m.fresnel = a->illum == 7;
        break;
    default:
        m.transparency = dissolved;
    }
    return m;
}

