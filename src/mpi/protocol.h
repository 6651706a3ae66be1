/* protocol.h - the messages glint-mpi's ranks exchange while rendering,
 * all in the job's communicator, all between rank 0 and one other rank:
 *
 *   rank r -> 0   ASK     int: how many tiles it would like added to its hand
 *   0 -> rank r   TILES   int[n]: tile indices to render: an ASK's answer,
 *                         or one for each tile a PIXELS brought back;
 *                         n == 0, once: no more
 *   rank r -> 0   PIXELS  one or more finished tiles (at most MAX_BATCH),
 *                         each a tile_header, then the tile's pixels, 3
 *                         floats each, row after row (its size from the
 *                         layout)
 *   rank r -> 0   DONE    a rank_report, once, after its last PIXELS
 *   0 -> rank r   STOP    nothing: stop rendering now (a signal, or another
 *                         rank failed); sent at most once, maybe after the
 *                         rank's DONE, when it is no longer read
 *
 * A rank asks once at the start and again only to hold more tiles; each
 * tile it sends back brings it another, until there are none. Messages
 * between two ranks arrive in the order sent, so rank 0 has every tile of
 * a rank before its DONE, and a rank has every tile it was given before
 * it is told there are no more. Every rank runs the same build (same byte
 * order and float format).
 *
 * The frames of a sequence, a whole frame to a rank (frame_farm.c), use
 * STOP too and three messages of their own:
 *
 *   0 -> rank r   FRAME         int: the frame to render; -1: no more
 *   rank r -> 0   FRAME_DONE    a frame_header: how the frame went; it
 *                               also asks for the next frame
 *   rank r -> 0   FRAME_PIXELS  right after a FRAME_DONE with pixels: the
 *                               image, width x height pixels of 3 floats
 *
 * rank 0 sends each rank its first FRAME unasked, and one for each
 * FRAME_DONE, -1 once none are left or the farm stops. */
#ifndef GLINT_MPI_PROTOCOL_H
#define GLINT_MPI_PROTOCOL_H

#include <stdint.h>
#include "glint_mpi.h"

enum mpi_tag { TAG_ASK = 1, TAG_TILES, TAG_PIXELS, TAG_DONE, TAG_STOP, TAG_FRAME, TAG_FRAME_DONE, TAG_FRAME_PIXELS };

/* The most tiles one TILES or PIXELS message carries. */
#define MAX_BATCH 256

/* What precedes a tile's pixels in a PIXELS message. */
typedef struct tile_header {
    int32_t tile;
    int32_t pad;              /* 0: the pixels start 8-byte aligned */
} tile_header;

/* How a rank's render went: sent to rank 0 in DONE, and rank 0's own. */
typedef struct rank_report {
    glint_mpi_rank_stats stats;
    int32_t status;           /* a glint_status: GLINT_OK, or why its render failed */
    char message[sizeof(((glint_error *)0)->message)]; /* why it failed, when it did */
} rank_report;

/* What a FRAME_DONE carries. */
typedef struct frame_header {
    int32_t frame;
    int32_t status;           /* a glint_status */
    int32_t width, height;    /* the image that follows; 0 x 0: none follows */
    double seconds;           /* loading and rendering it */
    glint_render_stats stats;
    char message[sizeof(((glint_error *)0)->message)]; /* why it failed, when it did */
} frame_header;

#endif
