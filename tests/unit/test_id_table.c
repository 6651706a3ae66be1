/* test_id_table.c - the hash table of core/id_table.h: ids found again
 * through growth and collisions, keys told apart, and the scene's names
 * found through it (a texture or material defined twice refused, NULL
 * names never entered); and the file set of core/file_set.h over it. */
#include <stdarg.h>
#include <stddef.h>
#include <setjmp.h>
#include <stdint.h>
#include <cmocka.h>
#include <stdio.h>
#include <string.h>
#include "core/file_set.h"
#include "core/id_table.h"
#include "scene/scene.h"

#define NAMES 20000

static char names[NAMES][16];

static bool name_equal(const void *keys, uint32_t id, const void *key)
{
    return strcmp(((const char(*)[16])keys)[id], key) == 0;
}

/* name_equal, counting its calls: each reads a stored key. */
static int compared;

static bool counted_equal(const void *keys, uint32_t id, const void *key)
{
    compared++;
    return name_equal(keys, id, key);
}

static void test_ids_are_found_through_growth(void **state)
{
    (void)state;
    id_table t = {0};
    uint32_t id;
    assert_false(id_table_find(&t, id_hash_text("n0"), "n0", name_equal, names, &id));
    for (uint32_t i = 0; i < NAMES; i++) {
        snprintf(names[i], sizeof names[i], "n%u", i);
        assert_true(id_table_intern(&t, id_hash_text(names[i]), names[i], i, name_equal, names, &id));
        assert_int_equal(id, i);
    }
    assert_int_equal(t.count, NAMES);
    /* At most 3/4 full, a power of two. */
    assert_true(t.count <= (t.mask + 1) / 4 * 3);
    assert_int_equal((t.mask + 1) & t.mask, 0);
    for (uint32_t i = 0; i < NAMES; i++) {
        assert_true(id_table_find(&t, id_hash_text(names[i]), names[i], name_equal, names, &id));
        assert_int_equal(id, i);
    }
    /* An equal key interns to the id it already has, and adds nothing. */
    assert_true(id_table_intern(&t, id_hash_text("n123"), "n123", NAMES, name_equal, names, &id));
    assert_int_equal(id, 123);
    assert_int_equal(t.count, NAMES);
    assert_false(id_table_find(&t, id_hash_text("n20000"), "n20000", name_equal, names, &id));
    assert_false(id_table_find(&t, id_hash_text(""), "", name_equal, names, &id));
    /* A stored key is read only where the hashes match: a name not in the
     * table reads none (no two of these names share a hash), one in it
     * reads its own. */
    compared = 0;
    assert_false(id_table_find(&t, id_hash_text("n20001"), "n20001", counted_equal, names, &id));
    assert_true(id_table_find(&t, id_hash_text("n777"), "n777", counted_equal, names, &id));
    assert_int_equal(compared, 1);
    id_table_free(&t);
    assert_null(t.slots);
    assert_int_equal(t.count, 0);
}

static void test_colliding_keys_are_told_apart(void **state)
{
    (void)state;
    id_table t = {0};
    uint32_t id;
    for (uint32_t i = 0; i < 100; i++) {
        snprintf(names[i], sizeof names[i], "c%u", i);
        assert_true(id_table_add(&t, 7, i));
    }
    for (uint32_t i = 0; i < 100; i++) {
        assert_true(id_table_find(&t, 7, names[i], name_equal, names, &id));
        assert_int_equal(id, i);
    }
    assert_false(id_table_find(&t, 7, "c100", name_equal, names, &id));
    id_table_free(&t);
}

static void test_scene_names_are_hashed(void **state)
{
    (void)state;
    glint_scene *s = glint_scene_new();
    assert_non_null(s);
    glint_material m = glint_material_default();
    glint_error err;
    for (int i = 0; i < NAMES; i++) {
        snprintf(names[i], sizeof names[i], "m%d", i);
        /* Unnamed materials between the named ones are never entered. */
        assert_int_equal(glint_scene_add_material(s, names[i], &m, &err), 2 * i);
        assert_int_equal(glint_scene_add_material(s, NULL, &m, &err), 2 * i + 1);
    }
    for (int i = 0; i < NAMES; i++)
        assert_int_equal(scene_find_material(s, names[i]), 2 * i);
    assert_int_equal(scene_find_material(s, NULL), -1);
    assert_int_equal(scene_find_material(s, "m20000"), -1);
    assert_int_equal(glint_scene_add_material(s, "m77", &m, &err), -1);
    assert_string_equal(err.message, "material 'm77' is defined twice");

    glint_color a = {1, 1, 1}, b = {0, 0, 0};
    glint_mapping uv = glint_texture_default(GLINT_TEXTURE_CHECKER).mapping;
    for (int i = 0; i < 1000; i++)
        assert_int_equal(glint_scene_add_checker(s, names[i], a, b, 1, uv, &err), i);
    assert_int_equal(glint_scene_add_checker(s, NULL, a, b, 1, uv, &err), 1000);
    assert_int_equal(scene_find_texture(s, "m999"), 999);
    assert_int_equal(scene_find_texture(s, "m1000"), -1);
    assert_int_equal(glint_scene_add_checker(s, "m5", a, b, 1, uv, &err), -1);
    assert_string_equal(err.message, "texture 'm5' is defined twice");
    glint_scene_free(s);
}

/* A file set finds each of 100,000 files by device and inode, with its
 * index in the order entered; a file entered again keeps its index; files
 * differing only in device or in the high half of the inode are apart. */
static void test_file_set(void **state)
{
    (void)state;
    file_set set = {0};
    for (long i = 0; i < 100000; i++)
        assert_int_equal(file_set_add(&set, (dev_t)(i % 7), (ino_t)i * 1000003), i);
    assert_int_equal(file_set_add(&set, 3, (ino_t)3 * 1000003), 3);
    assert_int_equal(set.count, 100000);
    for (long i = 0; i < 100000; i++)
        assert_int_equal(file_set_find(&set, (dev_t)(i % 7), (ino_t)i * 1000003), i);
    assert_int_equal(file_set_find(&set, 1, 0), -1);
    assert_int_equal(file_set_find(&set, 0, (ino_t)1 << 40), -1);
    assert_int_equal(file_set_add(&set, 0, (ino_t)1 << 40), 100000);
    file_set_free(&set);
    assert_int_equal(file_set_find(&set, 0, 0), -1);
}

int main(void)
{
    const struct CMUnitTest tests[] = {
        cmocka_unit_test(test_file_set),
        cmocka_unit_test(test_ids_are_found_through_growth),
        cmocka_unit_test(test_colliding_keys_are_told_apart),
        cmocka_unit_test(test_scene_names_are_hashed),
    };
    return cmocka_run_group_tests(tests, NULL, NULL);
}
