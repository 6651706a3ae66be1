/* filter.h - pixel reconstruction filters: how much a sample counts in its
 * pixel by where it falls, chosen with settings.filter.
 *
 * A filter is applied by where samples go rather than by weighing them
 * (filter importance sampling, as pbrt-v4 does): a pixel's samples are
 * spread about its centre as the filter's magnitude |f|, and each counts
 * with the sign of f there. A pixel is then its own samples' signed
 * average; no sample is shared with a neighbour, so a tile renders no
 * margin and a pixel stays the same for any tile or rank layout. Every
 * filter is separable, f(x) f(y), with x and y in pixels from the centre,
 * zero from its radius on. The box of radius 0.5 (the default) places
 * samples exactly where the plain pixel grid does, so its images keep
 * their bytes. */
#ifndef GLINT_RENDER_FILTER_H
#define GLINT_RENDER_FILTER_H

#include <stdbool.h>
#include "glint.h"

/* Entries in the table that maps [0, 1] to offsets distributed as |f|. */
#define FILTER_TABLE 1024

typedef struct pixel_filter {
    glint_filter type;
    double radius;           /* in pixels */
    bool has_negative_lobes; /* Mitchell and Lanczos: a sample can count negatively */
    double integral;         /* of f over [-radius, radius], which value() divides by */
    /* For the gaussian, Mitchell and Lanczos filters: offset[k] is where
     * |f|'s integral from 0 reaches k / FILTER_TABLE of its whole over
     * [0, radius]. */
    float offset[FILTER_TABLE + 1];
} pixel_filter;

/* The radius a filter type has when settings give none (0): box 0.5,
 * tent 1, gaussian 1.5, Mitchell 2, Lanczos 3. */
double pixel_filter_default_radius(glint_filter type);

/* Sets f up for the type with the given radius in pixels (0: its default). */
void pixel_filter_init(pixel_filter *f, glint_filter type, double radius);

/* The filter's one-dimensional profile at x pixels from the centre,
 * scaled to integrate to 1 over its radius. */
double pixel_filter_value(const pixel_filter *f, double x);

/* The offset from a pixel's centre, in pixels along one axis, of the
 * sample whose random number along it is u in [0, 1): distributed as |f|,
 * increasing with u, so that well-spread numbers give well-spread
 * offsets. *negative is whether f is below zero there. */
double pixel_filter_offset(const pixel_filter *f, double u, bool *negative);

#endif
