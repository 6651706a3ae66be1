/* render_tiles.h - the render back-end under glint_render: its caller says
 * which tiles this process renders, one at a time as threads ask, and is
 * told of each tile as it is finished, with its pixels. glint_render is the
 * local case (every tile, in order, from a counter); glint-mpi's ranks
 * (src/mpi/) feed it tiles that come from rank 0 and send the finished
 * pixels back. The render threads only call the feed: whatever talks to
 * other processes does so on a thread of its own.
 *
 * A pixel's colour depends only on the scene and its position, never on
 * which tiles a process renders or in which order, so an image assembled
 * from tiles rendered anywhere has the bytes glint_render gives. */
#ifndef GLINT_RENDER_RENDER_TILES_H
#define GLINT_RENDER_RENDER_TILES_H

#include <stddef.h>
#include "glint.h"

/* The tiles an image is cut into: from its size and the tile size alone,
 * so every process rendering a share of it agrees on them. */
typedef struct render_layout {
    int width, height;
    int tile_size;            /* a multiple of 4, at least 4 */
    int tiles_x, tiles_total; /* tiles a row, tiles in all, numbered row by row from the top left */
} render_layout;

/* The layout of scene's image (its settings' size) in tiles of tile_size
 * pixels a side (0 means 32; rounded up to a multiple of 4).
 * GLINT_ERR_INVALID for a tile size outside 0..65536. */
glint_status render_layout_for(const glint_scene *scene, int tile_size, render_layout *l, glint_error *err);

/* The pixels of tile `tile` of l: columns x0 to x1 and rows y0 to y1, the
 * ends excluded. */
void render_tile_bounds(const render_layout *l, int tile, int *x0, int *y0, int *x1, int *y1);

/* Where a render's tiles come from and where they go. */
typedef struct render_feed {
    /* The next tile a render thread is to render: its index in the layout,
     * or any number that is no tile's index (-1) when there are no more,
     * and the thread ends. Called by every render thread, concurrently, so
     * it must be thread-safe; it may wait until a tile is there. */
    int (*next)(void *user);
    /* Tile `tile` is finished: `pixels` is its top-left pixel (3 floats a
     * pixel, linear RGB), its rows `stride` floats apart, as
     * render_tile_bounds gives its size. In an image, they are final:
     * nothing writes them again; with tiles_only, they are the thread's
     * next tile's once done returns. Called by the thread that finished the
     * tile, concurrently with other threads' calls; NULL when nobody needs
     * to know. */
    void (*done)(void *user, int tile, const float *pixels, size_t stride);
    void *user;
    /* The image to render into, the caller's: width x height pixels of 3
     * floats, black where tiles will be rendered. The render never frees
     * it and gives it back in *out. NULL: the render allocates the image,
     * as glint_render does. */
    float *pixels;
    /* With pixels NULL: no image at all. Each thread renders its tiles
     * into a tile-sized buffer of its own, and *out is left empty: a
     * process that sends its tiles elsewhere holds no image (nor faults
     * one in: 25 MB and 6,000 page faults at 1920x1080 on a glint-mpi
     * worker that rendered half the tiles). */
    bool tiles_only;
} render_feed;

/* Renders the tiles feed->next gives into *out, as glint_render does
 * (options, threads, cancel, keep_partial; the options' tile size is the
 * layout's): progress and stats count the tiles this call finished, of the
 * layout's total; pixels of tiles it did not render are left as they were
 * (black in an image it allocated), and a tile cancelled midway is made
 * black again. On failure *out is empty, and an image the render allocated
 * is freed. */
glint_status render_tiles(const glint_scene *scene, const glint_render_options *options, const render_feed *feed,
                          glint_image *out, glint_render_stats *stats, glint_error *err);

#endif
