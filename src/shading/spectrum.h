/* spectrum.h - light split by wavelength where glass disperses it: the
 * visible spectrum cut into bands, the colour each band carries, and the
 * index of refraction a dispersive material has at a wavelength.
 *
 * A ray that refracts into a dispersive material leaves as one ray per
 * band, each at a wavelength drawn inside its band (so that the samples
 * of a pixel cover the band), carrying the band's colour, the same
 * wherever in it the wavelength falls: the bands' colours add up to white
 * exactly, so glass seen against white stays white rather than noisy. */
#ifndef GLINT_SHADING_SPECTRUM_H
#define GLINT_SHADING_SPECTRUM_H

#include "core/color.h"
#include "glint.h"

/* The spectrum split, in nanometres, and the most bands it is cut into. */
#define SPECTRUM_SHORTEST 400.0
#define SPECTRUM_LONGEST 700.0
#define SPECTRUM_MAX_BANDS 64

/* The wavelengths at which an Abbe number is defined: the helium d line,
 * and the hydrogen F and C lines. */
#define SPECTRUM_D_LINE 587.56
#define SPECTRUM_F_LINE 486.13
#define SPECTRUM_C_LINE 656.27

typedef struct spectrum {
    int count;                          /* the bands, equal widths from shortest to longest */
    color weight[SPECTRUM_MAX_BANDS];   /* the linear sRGB each carries; per channel they sum to 1 */
} spectrum;

/* Cuts the spectrum into `bands` (1..SPECTRUM_MAX_BANDS) and gives each
 * the colour of its wavelengths: the CIE 1931 observer (a sum of Gaussian
 * lobes fitted to its tables) in linear sRGB, a channel's negative values
 * taken as 0, each channel then scaled so the bands' colours add to white. */
void spectrum_init(spectrum *s, int bands);

/* The wavelength at u (0..1) across band `band` of s. */
static inline double spectrum_wavelength(const spectrum *s, int band, double u)
{
    return SPECTRUM_SHORTEST + (band + u) * ((SPECTRUM_LONGEST - SPECTRUM_SHORTEST) / s->count);
}

/* The index of refraction at `wavelength` (nm) of material m: its ior
 * when it does not disperse (dispersion 0) or the wavelength is 0 (white
 * light); else Cauchy's n = A + B / wavelength^2, through ior at the d
 * line with the Abbe number (n_d - 1) / (n_F - n_C) = dispersion. */
static inline double material_index_at(const glint_material *m, double wavelength)
{
    if (!(m->dispersion > 0) || wavelength == 0)
        return m->ior;
    const double reciprocal_span =
        1 / (SPECTRUM_F_LINE * SPECTRUM_F_LINE) - 1 / (SPECTRUM_C_LINE * SPECTRUM_C_LINE);
    double b = (m->ior - 1) / (m->dispersion * reciprocal_span);
    return m->ior + b * (1 / (wavelength * wavelength) - 1 / (SPECTRUM_D_LINE * SPECTRUM_D_LINE));
}

#endif
