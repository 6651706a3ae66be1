/* png_encode.c - PNG files written on every processor.
 *
 * A PNG image is one zlib stream over the filtered rows, which libpng
 * deflates on one thread: about 45 ms of a 1920x1080 render's wall time.
 * Here the rows are cut into slices of a fixed size, and threads deflate
 * the slices apart (rows_deflate.c, twice as fast as zlib's fastest
 * level). A slice ends on a byte boundary (a sync flush) and refers back
 * only into itself, so the slices joined in order are one valid deflate
 * stream; its Adler-32 is the slices' combined. The slices depend only on
 * the image's width, which keeps the file the same bytes whatever the
 * thread count.
 *
 * Each thread keeps one buffer of rows and one deflater for all the
 * slices it takes: it sRGB-encodes a slice's rows (and the row above),
 * filters them in place and deflates them. Fresh
 * memory costs a page fault a page, about 10 us each on a virtual machine:
 * the whole image's sRGB bytes, a filtered copy of each slice and a deflate
 * state each had made a 1000 x 1000 PNG fault in 7 MB, 1,800 pages. */
#include <stdatomic.h>
#include <stdint.h>
#include <stdlib.h>
#include <string.h>
#include <zlib.h>
#include "core/big_alloc.h"
#include "core/parallel.h"
#include "image/png_encode.h"
#include "image/rows_deflate.h"
#include "image/srgb.h"

/* Filtered bytes per slice, about: large enough that the sync flush and the
 * matches lost at each start cost little, small enough to share a
 * 1000-row image among 8 threads. */
#define SLICE_BYTES (256 * 1024)
/* IDAT chunks of at most this much of the zlib stream. */
#define IDAT_MAX (1024 * 1024)

enum { FILTER_NONE = 0, FILTER_UP = 2 };

/* One slice of rows and, once deflated, its part of the stream. */
typedef struct slice {
    int first_row, rows;
    unsigned char *deflated;  /* its room in the encoder's `deflated` */
    size_t deflated_size;
    uLong adler;              /* Adler-32 of the slice's filtered bytes alone */
} slice;

typedef struct encoder {
    const glint_image *image;
    int depth;                /* bits a channel: 8 or 16 */
    size_t row_bytes;         /* 3 * width * depth / 8 */
    int slice_rows;           /* rows of every slice but maybe the last */
    slice *slices;
    int slice_count;
    unsigned char *deflated;  /* room for every slice's deflated bytes, slice_room each */
    size_t slice_room;
    atomic_int next;          /* the next slice a thread takes */
    atomic_bool failed;       /* some allocation failed */
} encoder;

/* The rows of slice s, filtered, into rows (a filter byte and row_bytes
 * each): sRGB-encoded in place, then from the bottom up each row less the
 * one above it (Up), which is still sRGB there. The image's first row has
 * no row above: it is left unfiltered, as libpng does. Any other slice's
 * first row needs its row above, encoded at the front of `rows` and not
 * returned. Returns the first row's start. */
static unsigned char *filtered_rows(const encoder *e, const slice *s, unsigned char *rows)
{
    size_t stride = e->row_bytes + 1, samples = 3 * (size_t)e->image->width;
    int from = s->first_row > 0 ? s->first_row - 1 : 0, count = s->first_row + s->rows - from;
    for (int k = 0; k < count; k++)
        srgb_encode_depth(rows + (size_t)k * stride + 1, e->image->pixels + (size_t)(from + k) * samples, samples,
                          e->depth);
    for (int k = count - 1; k > 0; k--) {
        unsigned char *row = rows + (size_t)k * stride;
        const unsigned char *above = row - stride;
        row[0] = FILTER_UP;
        for (size_t i = 1; i <= e->row_bytes; i++)
            row[i] = (unsigned char)(row[i] - above[i]);
    }
    rows[0] = FILTER_NONE;
    return s->first_row > 0 ? rows + stride : rows;
}

/* Filters the slice's rows and deflates them through d, ended with a sync
 * flush, or for the last slice with the final block. */
static void deflate_slice(encoder *e, slice *s, unsigned char *rows, rows_deflater *d)
{
    unsigned char *own = filtered_rows(e, s, rows);
    size_t own_size = (size_t)s->rows * (e->row_bytes + 1);
    s->adler = adler32_z(adler32_z(0, NULL, 0), own, own_size);
    bool last = s->first_row + s->rows == e->image->height;
    s->deflated_size = rows_deflate(d, own, own_size, 3 * e->depth / 8, last, s->deflated);
}

/* A thread's work: the next slice not taken, until none is left, through
 * its own rows and deflater. */
static void *run(void *arg)
{
    encoder *e = arg;
    size_t stride = e->row_bytes + 1;
    unsigned char *rows = malloc((size_t)(1 + e->slice_rows) * stride);
    rows_deflater *d = rows_deflater_new();
    int k;
    if (rows && d)
        while (!atomic_load(&e->failed) && (k = atomic_fetch_add(&e->next, 1)) < e->slice_count)
            deflate_slice(e, &e->slices[k], rows, d);
    else
        atomic_store(&e->failed, true);
    rows_deflater_free(d);
    free(rows);
    return NULL;
}

static void put32(unsigned char *p, uint32_t v)
{
    p[0] = (unsigned char)(v >> 24);
    p[1] = (unsigned char)(v >> 16);
    p[2] = (unsigned char)(v >> 8);
    p[3] = (unsigned char)v;
}

/* Seals the chunk at p whose type and `length` bytes of data are in place:
 * its length before them, its CRC after; returns the byte after. */
static unsigned char *seal_chunk(unsigned char *p, size_t length)
{
    put32(p, (uint32_t)length);
    put32(p + 8 + length, (uint32_t)crc32_z(crc32_z(0, NULL, 0), p + 4, 4 + length));
    return p + 12 + length;
}

/* Writes a chunk at p: length, type, data, CRC; returns the byte after. */
static unsigned char *put_chunk(unsigned char *p, const char *type, const unsigned char *data, size_t length)
{
    memcpy(p + 4, type, 4);
    if (length > 0)
        memcpy(p + 8, data, length);
    return seal_chunk(p, length);
}

/* The zlib stream, written as IDAT chunks of IDAT_MAX bytes (the last
 * shorter) straight into the file's bytes: each piece of the stream is
 * copied once, where it ends up. */
typedef struct idat_writer {
    unsigned char *chunk;     /* the open chunk's start (its length field), or NULL */
    size_t filled;            /* the stream's bytes in it */
} idat_writer;

/* Seals w's open chunk; returns the byte after. */
static unsigned char *idat_close(idat_writer *w)
{
    unsigned char *end = seal_chunk(w->chunk, w->filled);
    w->chunk = NULL;
    return end;
}

/* Appends n bytes of the stream, opening chunks at *p as they fill. */
static void idat_put(idat_writer *w, unsigned char **p, const unsigned char *data, size_t n)
{
    while (n > 0) {
        if (!w->chunk) {
            w->chunk = *p;
            w->filled = 0;
            memcpy(w->chunk + 4, "IDAT", 4);
        }
        size_t room = IDAT_MAX - w->filled, take = n < room ? n : room;
        memcpy(w->chunk + 8 + w->filled, data, take);
        w->filled += take;
        data += take;
        n -= take;
        if (w->filled == IDAT_MAX)
            *p = idat_close(w);
    }
}

/* The file around the slices' deflated data: signature, IHDR, sRGB, the
 * zlib stream (header, slices, Adler-32) in IDAT chunks, IEND. */
static bool assemble(const encoder *e, unsigned char **bytes, size_t *size)
{
    size_t stream_size = 2 + 4;
    uLong adler = adler32_z(0, NULL, 0);
    for (int k = 0; k < e->slice_count; k++) {
        stream_size += e->slices[k].deflated_size;
        adler = adler32_combine(adler, e->slices[k].adler, (z_off_t)(e->slices[k].rows * (e->row_bytes + 1)));
    }
    size_t idats = (stream_size + IDAT_MAX - 1) / IDAT_MAX;
    *size = 8 + 25 + 13 + stream_size + 12 * idats + 12;
    *bytes = big_alloc(*size);
    if (!*bytes)
        return false;

    static const unsigned char signature[8] = {0x89, 'P', 'N', 'G', '\r', '\n', 0x1a, '\n'};
    unsigned char header[13];
    put32(header, (uint32_t)e->image->width);
    put32(header + 4, (uint32_t)e->image->height);
    header[8] = (unsigned char)e->depth; /* bits per sample */
    header[9] = 2;            /* RGB */
    header[10] = header[11] = header[12] = 0; /* deflate, adaptive filters, not interlaced */
    static const unsigned char perceptual = 0;
    unsigned char *p = *bytes;
    memcpy(p, signature, sizeof signature);
    p = put_chunk(p + 8, "IHDR", header, sizeof header);
    p = put_chunk(p, "sRGB", &perceptual, 1);
    /* CMF 0x78: deflate, 32 KiB window; FLG 0x01: fastest level, no
     * dictionary, and the pair a multiple of 31. */
    static const unsigned char zlib_header[2] = {0x78, 0x01};
    idat_writer w = {NULL, 0};
    idat_put(&w, &p, zlib_header, sizeof zlib_header);
    for (int k = 0; k < e->slice_count; k++)
        idat_put(&w, &p, e->slices[k].deflated, e->slices[k].deflated_size);
    unsigned char check[4];
    put32(check, (uint32_t)adler);
    idat_put(&w, &p, check, sizeof check);
    if (w.chunk)
        p = idat_close(&w);
    put_chunk(p, "IEND", NULL, 0);
    return true;
}

bool png_encode(const glint_image *image, int depth, int threads, unsigned char **bytes, size_t *size)
{
    *bytes = NULL;
    *size = 0;
    encoder e = {.image = image, .depth = depth, .row_bytes = 3 * (size_t)image->width * (size_t)depth / 8};
    size_t stride = e.row_bytes + 1;
    e.slice_rows = stride < SLICE_BYTES ? (int)(SLICE_BYTES / stride) : 1;
    e.slice_count = (image->height + e.slice_rows - 1) / e.slice_rows;
    e.slices = calloc((size_t)e.slice_count, sizeof *e.slices);
    /* One block of memory for all the slices, each touched only as far
     * as it is written, rather than a block each: one more copy of the
     * file's bytes in fresh pages. */
    e.slice_room = rows_deflate_bound((size_t)e.slice_rows * stride);
    e.deflated = e.slices ? big_alloc(e.slice_room * (size_t)e.slice_count) : NULL;
    atomic_init(&e.next, 0);
    atomic_init(&e.failed, e.deflated == NULL);
    for (int k = 0; e.deflated && k < e.slice_count; k++) {
        e.slices[k].first_row = k * e.slice_rows;
        e.slices[k].rows = image->height - k * e.slice_rows < e.slice_rows ? image->height - k * e.slice_rows
                                                                           : e.slice_rows;
        e.slices[k].deflated = e.deflated + e.slice_room * (size_t)k;
    }
    if (!atomic_load(&e.failed))
        parallel_run(threads < e.slice_count ? threads : e.slice_count, run, &e, 0);
    bool ok = !atomic_load(&e.failed) && assemble(&e, bytes, size);
    free(e.deflated);
    free(e.slices);
    if (!ok)
        *size = 0;
    return ok;
}
