/* spectrum.c - the colours of the spectrum's bands. */
#include <math.h>
#include "shading/spectrum.h"

/* One lobe of the fit: a Gaussian of mean mu, its width below the mean
 * and above it. */
static double lobe(double wavelength, double mu, double below, double above)
{
    double t = (wavelength - mu) / (wavelength < mu ? below : above);
    return exp(-0.5 * t * t);
}

/* The CIE 1931 colour matching functions at `wavelength`, as the
 * multi-lobe fit of Wyman, Sloan and Shirley (2013), made linear sRGB
 * (D65) with each channel's negative part taken as 0. */
static color observer_rgb(double wavelength)
{
    double x = 1.056 * lobe(wavelength, 599.8, 37.9, 31.0) + 0.362 * lobe(wavelength, 442.0, 16.0, 26.7) -
               0.065 * lobe(wavelength, 501.1, 20.4, 26.2);
    double y = 0.821 * lobe(wavelength, 568.8, 46.9, 40.5) + 0.286 * lobe(wavelength, 530.9, 16.3, 31.1);
    double z = 1.217 * lobe(wavelength, 437.0, 11.8, 36.0) + 0.681 * lobe(wavelength, 459.0, 26.0, 13.8);
    double r = 3.2406 * x - 1.5372 * y - 0.4986 * z;
    double g = -0.9689 * x + 1.8758 * y + 0.0415 * z;
    double b = 0.0557 * x - 0.2040 * y + 1.0570 * z;
    return rgb(r > 0 ? r : 0, g > 0 ? g : 0, b > 0 ? b : 0);
}

void spectrum_init(spectrum *s, int bands)
{
    enum { STEPS = 32 }; /* midpoints a band's colour is summed over */
    s->count = bands;
    color total = rgb(0, 0, 0);
    for (int k = 0; k < bands; k++) {
        color sum = rgb(0, 0, 0);
        for (int i = 0; i < STEPS; i++)
            sum = rgb_add(sum, observer_rgb(spectrum_wavelength(s, k, (i + 0.5) / STEPS)));
        s->weight[k] = sum;
        total = rgb_add(total, sum);
    }
    for (int k = 0; k < bands; k++)
        s->weight[k] = rgb(s->weight[k].r / total.r, s->weight[k].g / total.g, s->weight[k].b / total.b);
}
