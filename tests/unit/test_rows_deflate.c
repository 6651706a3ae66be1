/* test_rows_deflate.c - rows_deflate's streams inflate, through zlib, to
 * exactly what went in: runs longer than a match and than a block, pixel
 * repeats, repeats far back, incompressible bytes (stored blocks), skewed
 * bytes whose codes must be kept to 15 bits, and every small size; a
 * stream of several calls joins as one; nothing is written past the
 * bound; and runs compress. */
#include <setjmp.h>
#include <stdarg.h>
#include <stddef.h>
#include <stdint.h>
#include <stdlib.h>
#include <string.h>
#include <cmocka.h>
#include <zlib.h>
#include "image/rows_deflate.h"

/* Raw-inflates the `size` bytes at stream, which must end a final block,
 * and checks it gives the n bytes at want. */
static void assert_inflates_to(const unsigned char *stream, size_t size, const unsigned char *want, size_t n)
{
    unsigned char *got = malloc(n + 16);
    assert_non_null(got);
    z_stream z = {0};
    assert_int_equal(inflateInit2(&z, -15), Z_OK);
    z.next_in = (unsigned char *)stream;
    z.avail_in = (uInt)size;
    z.next_out = got;
    z.avail_out = (uInt)(n + 16);
    assert_int_equal(inflate(&z, Z_FINISH), Z_STREAM_END);
    assert_int_equal(z.avail_in, 0); /* nothing after the final block */
    assert_int_equal(z.total_out, n);
    if (n > 0)
        assert_memory_equal(got, want, n);
    inflateEnd(&z);
    free(got);
}

/* Deflates in (n bytes, pixels of pixel_bytes) as one final call into a
 * buffer with guard bytes past the bound, checks the guards and the round
 * trip, and returns the stream's size. */
static size_t round_trip(rows_deflater *d, const unsigned char *in, size_t n, int pixel_bytes)
{
    size_t bound = rows_deflate_bound(n);
    unsigned char *out = malloc(bound + 64);
    assert_non_null(out);
    memset(out, 0xa5, bound + 64);
    size_t size = rows_deflate(d, in, n, pixel_bytes, true, out);
    assert_true(size <= bound);
    for (size_t k = bound; k < bound + 64; k++)
        assert_int_equal(out[k], 0xa5);
    assert_inflates_to(out, size, in, n);
    free(out);
    return size;
}

static uint32_t next_random(uint32_t *state)
{
    *state = *state * 1664525u + 1013904223u;
    return *state >> 8;
}

static void test_round_trips(void **state)
{
    enum { N = 300000 };
    rows_deflater *d = rows_deflater_new();
    unsigned char *in = malloc(N);
    assert_true(d && in);
    uint32_t seed = 12345;

    /* All zeros: runs cut at 258 bytes and at each 65,535-byte block. */
    memset(in, 0, N);
    assert_true(round_trip(d, in, N, 3) < N / 100);

    /* Noise: nothing to find, so stored blocks, a few bytes over the input. */
    for (size_t i = 0; i < N; i++)
        in[i] = (unsigned char)next_random(&seed);
    size_t size = round_trip(d, in, N, 3);
    assert_true(size > N - N / 100 && size <= N + 64);

    /* Rows of a flat colour with an edge, filtered as PNG rows are: a
     * filter byte, then the first row's pixels repeating, then zeros. */
    for (size_t i = 0; i < N; i++) {
        size_t row = i / 3001, x = i % 3001;
        in[i] = x == 0 ? (row ? 2 : 0) : row == 0 ? (unsigned char)(x % 3 == 1 ? 200 : x % 3 == 2 ? 40 : 90) : 0;
    }
    assert_true(round_trip(d, in, N, 3) < N / 100);

    /* 16-bit pixels (six bytes) repeating, with a change every 1,000 bytes. */
    for (size_t i = 0; i < N; i++)
        in[i] = (unsigned char)((i % 6) * 37 + i / 1000);
    assert_true(round_trip(d, in, N, 6) < N / 20);

    /* A phrase repeated at distances up to 32 KiB and beyond, among noise. */
    for (size_t i = 0; i < N; i++)
        in[i] = (unsigned char)next_random(&seed);
    static const char phrase[] = "a phrase of some length, said again";
    for (size_t at = 17; at + sizeof phrase < N; at += 997 + at % 40000)
        memcpy(in + at, phrase, sizeof phrase);
    round_trip(d, in, N, 3);

    /* Skewed bytes: symbol k about twice as common as k + 1, so that the
     * exact Huffman code would be over 15 bits deep; no byte equals the
     * one or the three before it, so they stay literals. */
    for (size_t i = 0; i < N; i++) {
        uint32_t r = next_random(&seed) | 1u << 24;
        unsigned char b = (unsigned char)__builtin_ctz(r);
        while ((i >= 1 && b == in[i - 1]) || (i >= 3 && b == in[i - 3]))
            b = (unsigned char)(b + 1);
        in[i] = b;
    }
    round_trip(d, in, N, 3);

    /* Every size up to 300, of mixed runs and noise; and none. */
    for (size_t n = 0; n <= 300; n++) {
        for (size_t i = 0; i < n; i++)
            in[i] = (i / 7) % 2 ? (unsigned char)next_random(&seed) : (unsigned char)(i / 14);
        round_trip(d, in, n, 3);
    }
    free(in);
    rows_deflater_free(d);
}

/* Calls that are not final end on a byte boundary (a sync flush), so that
 * their streams joined, the last one final, inflate as one: as
 * png_encode.c joins its slices. */
static void test_calls_join(void **state)
{
    enum { N = 200000 };
    rows_deflater *d = rows_deflater_new();
    unsigned char *in = malloc(N), *out = malloc(rows_deflate_bound(N) * 4);
    assert_true(d && in && out);
    uint32_t seed = 99;
    for (size_t i = 0; i < N; i++)
        in[i] = (i / 5000) % 2 ? (unsigned char)next_random(&seed) : (unsigned char)(i % 3);
    static const size_t cuts[] = {0, 1, 70000, 70000, 150000, N};
    size_t size = 0;
    for (size_t k = 0; k + 1 < sizeof cuts / sizeof cuts[0]; k++) {
        bool last = k + 2 == sizeof cuts / sizeof cuts[0];
        size_t n = cuts[k + 1] - cuts[k];
        size_t part = rows_deflate(d, in + cuts[k], n, 3, last, out + size);
        assert_true(part <= rows_deflate_bound(n));
        if (!last) /* an empty stored block closes it: 00 00 ff ff */
            assert_memory_equal(out + size + part - 4, "\x00\x00\xff\xff", 4);
        size += part;
    }
    assert_inflates_to(out, size, in, N);

    /* The same input gives the same bytes. */
    unsigned char *again = malloc(rows_deflate_bound(N));
    assert_non_null(again);
    size_t first = rows_deflate(d, in, N, 3, true, out);
    assert_int_equal(rows_deflate(d, in, N, 3, true, again), first);
    assert_memory_equal(again, out, first);
    free(again);
    free(out);
    free(in);
    rows_deflater_free(d);
}

int main(void)
{
    const struct CMUnitTest tests[] = {
        cmocka_unit_test(test_round_trips),
        cmocka_unit_test(test_calls_join),
    };
    return cmocka_run_group_tests(tests, NULL, NULL);
}
