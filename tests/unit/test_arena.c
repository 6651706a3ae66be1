/* test_arena.c - the bump allocator of core/arena.h: pieces aligned and
 * apart, and a rollback giving back what was cut since its mark, small
 * pieces, new chunks and large pieces alike, so that the same memory
 * serves again; core/big_alloc.h's large buffers; and core/array.h's
 * growing arrays, which move onto them once large. */
#include <stdarg.h>
#include <stddef.h>
#include <setjmp.h>
#include <stdint.h>
#include <cmocka.h>
#include <malloc.h>
#include <string.h>
#include "core/arena.h"
#include "core/array.h"
#include "core/big_alloc.h"

#define CHUNK ((size_t)1 << 20)

/* Pieces of every small size: aligned for a double, none overlapping. */
static void test_pieces_are_aligned_and_apart(void **state)
{
    arena a = {0};
    unsigned char *last = NULL;
    for (size_t size = 1; size < 200; size++) {
        unsigned char *p = arena_alloc(&a, size);
        assert_non_null(p);
        assert_int_equal((uintptr_t)p % 8, 0);
        memset(p, (int)size, size);
        if (last)
            assert_int_equal(last[0], (unsigned char)(size - 1));
        last = p;
    }
    arena_free(&a);
    assert_null(a.chunks);
}

/* What is cut after a mark comes back at the same address after the
 * rollback, and what was cut before it is left alone. */
static void test_rollback_reuses_the_memory(void **state)
{
    arena a = {0};
    char *before = arena_alloc(&a, 16);
    strcpy(before, "kept");
    arena_point mark = arena_mark(&a);
    void *first = arena_alloc(&a, 100);
    for (int round = 0; round < 1000; round++) {
        arena_rollback(&a, mark);
        assert_ptr_equal(arena_alloc(&a, 100), first);
    }
    assert_string_equal(before, "kept");
    arena_free(&a);
}

/* Bytes malloc has handed out and not had back (0 under AddressSanitizer,
 * whose malloc keeps no such count). */
static size_t in_use(void)
{
    struct mallinfo2 m = mallinfo2();
    return m.uordblks + m.hblkhd;
}

/* Rolling back past new chunks and large pieces (which go behind the
 * newest chunk, in front of those cut before the mark) frees them all,
 * and the room left in the mark's chunk is cut next. */
static void test_rollback_frees_chunks_and_large_pieces(void **state)
{
    arena a = {0};
    char *small = arena_alloc(&a, 1000), *big = arena_alloc(&a, CHUNK / 2);
    assert_non_null(small);
    assert_non_null(big);
    strcpy(small, "small");
    strcpy(big, "big");
    arena_point mark = arena_mark(&a);
    size_t held = in_use();
    void *next = arena_alloc(&a, 64);
    for (int round = 0; round < 3; round++) {
        arena_rollback(&a, mark);
        assert_non_null(arena_alloc(&a, CHUNK / 2));
        for (int i = 0; i < 40; i++)
            assert_non_null(arena_alloc(&a, CHUNK / 16));
        assert_non_null(arena_alloc(&a, CHUNK / 3));
        assert_true(in_use() >= held + 3 * CHUNK || held == 0);
        arena_rollback(&a, mark);
        assert_int_equal(in_use(), held);
        assert_ptr_equal(arena_alloc(&a, 64), next);
    }
    assert_string_equal(small, "small");
    assert_string_equal(big, "big");
    arena_free(&a);
}

/* A mark on an empty arena: the rollback empties it. */
static void test_rollback_to_empty(void **state)
{
    arena a = {0};
    arena_point mark = arena_mark(&a);
    assert_non_null(arena_alloc(&a, 10));
    assert_non_null(arena_alloc(&a, CHUNK));
    arena_rollback(&a, mark);
    assert_null(a.chunks);
}

/* big_alloc: small buffers as they come, large ones from a 2 MiB
 * boundary; every byte writable and the buffer freed with free() (ASan
 * checks both in the sanitizer build); no room past what a size_t holds. */
static void test_big_alloc(void **state)
{
    static const size_t sizes[] = {0, 1, 4096, BIG_ALLOC_MIN - 1, BIG_ALLOC_MIN, 3 * BIG_ALLOC_MIN + 5};
    for (size_t k = 0; k < sizeof sizes / sizeof sizes[0]; k++) {
        unsigned char *p = big_alloc(sizes[k]);
        assert_non_null(p);
        if (sizes[k] >= BIG_ALLOC_MIN)
            assert_int_equal((uintptr_t)p % ((size_t)2 << 20), 0);
        memset(p, 0x5a, sizes[k] ? sizes[k] : 1);
        assert_int_equal(p[sizes[k] ? sizes[k] - 1 : 0], 0x5a);
        free(p);
    }
    assert_null(big_alloc(SIZE_MAX));
    assert_null(big_alloc(SIZE_MAX - ((size_t)1 << 20)));
}

/* An array grown an item at a time keeps every item through each move:
 * its room doubles from 16, and from BIG_ALLOC_MIN bytes on it starts on a
 * 2 MiB boundary (big_alloc's); freed with free(). Room past what a size_t
 * holds is refused with the array unchanged. */
static void test_array_grows_onto_big_alloc(void **state)
{
    int64_t *items = NULL;
    size_t cap = 0, n = 3 * BIG_ALLOC_MIN / sizeof *items + 7;
    for (size_t i = 0; i < n; i++) {
        assert_true(array_reserve((void **)&items, &cap, i + 1, sizeof *items));
        items[i] = (int64_t)(i * 2654435761u);
        size_t doubling = 16;
        while (doubling < i + 1)
            doubling *= 2;
        assert_int_equal(cap, doubling);
        if (cap * sizeof *items >= BIG_ALLOC_MIN)
            assert_int_equal((uintptr_t)items % ((size_t)2 << 20), 0);
    }
    for (size_t i = 0; i < n; i++)
        assert_int_equal(items[i], (int64_t)(i * 2654435761u));
    int64_t *before = items;
    size_t cap_before = cap;
    assert_false(array_reserve((void **)&items, &cap, SIZE_MAX / 4, sizeof *items));
    assert_ptr_equal(items, before);
    assert_int_equal(cap, cap_before);
    free(items);
}

/* array_alloc: a large array (a welded model's positions) starts on a 2
 * MiB boundary, on big_alloc's huge pages, and holds what is written; a
 * small one is malloc's; an overflowing count is refused. */
static void test_array_alloc_large_on_big_alloc(void **state)
{
    size_t n = BIG_ALLOC_MIN / sizeof(float) + 3;
    float *large = array_alloc(n, sizeof *large);
    assert_non_null(large);
    assert_int_equal((uintptr_t)large % ((size_t)2 << 20), 0);
    for (size_t i = 0; i < n; i++)
        large[i] = (float)i;
    assert_true(large[n - 1] == (float)(n - 1));
    free(large);
    unsigned char *small = array_alloc(0, 12);
    assert_non_null(small);
    free(small);
    assert_null(array_alloc(SIZE_MAX / 2, 4));
}

int main(void)
{
    const struct CMUnitTest tests[] = {
        cmocka_unit_test(test_pieces_are_aligned_and_apart),
        cmocka_unit_test(test_rollback_reuses_the_memory),
        cmocka_unit_test(test_rollback_frees_chunks_and_large_pieces),
        cmocka_unit_test(test_rollback_to_empty),
        cmocka_unit_test(test_big_alloc),
        cmocka_unit_test(test_array_grows_onto_big_alloc),
        cmocka_unit_test(test_array_alloc_large_on_big_alloc),
    };
    return cmocka_run_group_tests(tests, NULL, NULL);
}
