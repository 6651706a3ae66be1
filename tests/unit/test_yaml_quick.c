/* test_yaml_quick.c - the quick YAML reader (scenefile/yaml_quick.h): every
 * example scene and every style a scene file is written in is its own and
 * gives libyaml's tree node for node and mark for mark; what it leaves to
 * libyaml (anchors, escapes, tabs, empty values, lists across lines...) it
 * refuses before giving a single event to the builder. */
#include <stdarg.h>
#include <stddef.h>
#include <setjmp.h>
#include <stdint.h>
#include <cmocka.h>
#include <dirent.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>
#include "scenefile/yaml_quick.h"
#include "scenefile/yaml_tree.h"

/* Parses text with both readers: they must agree, status and message, or
 * tree. Returns whether the quick reader took the text. */
static bool same_as_libyaml(const char *text, size_t size)
{
    ydoc quick, full;
    glint_error quick_err = {0}, full_err = {0};
    ydoc_use_quick_reader(true);
    long quick_aliases = 0, full_aliases = 0;
    glint_status a = ydoc_parse(&quick, text, size, "t.yaml", &quick_aliases, NULL, &quick_err);
    ydoc_use_quick_reader(false);
    glint_status b = ydoc_parse(&full, text, size, "t.yaml", &full_aliases, NULL, &full_err);
    ydoc_use_quick_reader(true);
    if (a != b || strcmp(quick_err.message, full_err.message) != 0 || (!a && !ynode_same(quick.root, full.root)))
        fail_msg("the readers differ on:\n%s\nquick: %d %s\nlibyaml: %d %s", text, a, quick_err.message, b,
                 full_err.message);
    if (!a) {
        ydoc_free(&quick);
        ydoc_free(&full);
    }
    return yaml_quick_parse(text, size, NULL, NULL) == 0;
}

static bool taken(const char *text)
{
    return same_as_libyaml(text, strlen(text));
}

static void test_scene_styles_are_read_as_libyaml_reads_them(void **state)
{
    (void)state;
    static const char *const texts[] = {
        "a: 1\n",
        "a: 1",
        "# a comment\n\nsettings: {width: 320, height: 240}   # trailing\ncamera:\n  position: [0, 1, 5]\n"
        "  look_at: [0,0,0]\n",
        "objects:\n- {type: sphere, material: m, center: [1,2,0], radius: .4}\n"
        "- {type: sphere, material: m, center: [-1,2,0], radius: 1e-3}\nlights: []\n",
        "objects:\n  - type: box\n    min: [0, 0, 0]\n    max: [1, 1, 1]\n    transform:\n"
        "    - translate: [0, 1, 0]\n    - rotate: {axis: [0, 1, 0], angle: 45}\n  - type: plane\n",
        "materials:\n  red glass: {color: \"#ff0000\", name: 'its'}\n",
        "materials:\n  m.1: {color: \"#ff0000\", texture: 'a b'}\n  m-2: {}\n",
        "x: [[1, 2], [3, [4, {a: b}]], []]\n",
        "x:   plain text with spaces   # and a comment\ny: a#b\nz: http://example.com/a?b=c\n",
        "- a\n- b: 1\n  c: 2\n-\n  d: 3\n",
        "a:\n  - b:\n    - 1\n    - 2\n    c: 3\n",
        "a: \"quoted: # not a comment\"\nb: 'single \\ backslash'\nc: \"\"\n",
        "a: -1\nb: [-1, -.5, +2]\nc: ~\nd: null\n",
        "objects:\n  - { type: cone, radius: 0.08,   # a comment\n      height: 0.45,\n\n  capped: true }\n"
        "  - [1,\n2, [3,\n 4]]\nlights: []\n",
        "a: [1,\n2]\n",
        "a: {b: [1,\n# a comment line\n   2], c: d,\n  e: \"f\"\n }\n",
    };
    for (size_t i = 0; i < sizeof texts / sizeof *texts; i++)
        if (!taken(texts[i]))
            fail_msg("the quick reader left to libyaml:\n%s", texts[i]);
}

static void test_what_it_leaves_to_libyaml(void **state)
{
    (void)state;
    static const char *const texts[] = {
        "",
        "# only a comment\n",
        "---\na: 1\n",
        "a: 1\n...\n",
        "%YAML 1.1\n---\na: 1\n",
        "  a: 1\n",
        "a: &x 1\nb: *x\n",
        "a: !tag 1\n",
        "a: |\n  text\n",
        "a: >\n  text\n",
        "a:\n",
        "a:\nb: 1\n",
        "a: [1\n  2]\n",
        "a: {b: 1,\n  c: 2 \n d}\n",
        "a: [1,#c\n  2]\n",
        "a: [1, 2\n  ]\n",
        "a: \"esc\\n\"\n",
        "a: 'it''s'\n",
        "a: \"open\n",
        "a: plain\n  continued\n",
        "a:\tb\n",
        "a: b\r\n",
        "a: \xc3\xa9\n",
        "\"a\": 1\n",
        "? a\n: 1\n",
        "a: b: c\n",
        "a: [1, 2,]\n",
        "a: [1,,2]\n",
        "a: {b}\n",
        "a: [b: c]\n",
        "a: {b:1}\n",
        "- - a\n",
        "a: 1\n  b: 2\n",
        "a: [1] x\n",
        "a: 1\n- b\n",
        "[1, 2]\n",
        "plain\n",
        "a : 1\n",
        "a: x\nb: [1]#c\n",
    };
    for (size_t i = 0; i < sizeof texts / sizeof *texts; i++)
        if (taken(texts[i]))
            fail_msg("the quick reader took:\n%s", texts[i]);
}

/* A place the quick reader gives must be libyaml's: a problem the builder
 * finds (here a missing anchor is not one, but nesting too deep is) is
 * reported at the same line and column by both. */
static void test_the_builders_messages_are_the_same(void **state)
{
    (void)state;
    char deep[1024] = "a: ";
    for (int i = 0; i < 70; i++)
        strcat(deep, "[");
    for (int i = 0; i < 70; i++)
        strcat(deep, "]");
    strcat(deep, "\n");
    same_as_libyaml(deep, strlen(deep));
    char lines[] = "a: 1\nb:\n  c: [1, 2, 3]\n  d: {e: f}\n";
    assert_true(same_as_libyaml(lines, strlen(lines)));
}

static char *read_text(const char *path, size_t *size)
{
    FILE *f = fopen(path, "rb");
    assert_non_null(f);
    fseek(f, 0, SEEK_END);
    long n = ftell(f);
    rewind(f);
    char *text = calloc(1, (size_t)n + 1);
    assert_non_null(text);
    assert_int_equal(fread(text, 1, (size_t)n, f), (size_t)n);
    fclose(f);
    *size = (size_t)n;
    return text;
}

/* Every example scene: the quick reader reads it as libyaml does, and
 * takes it unless it has anchors. */
static void test_every_example_scene(void **state)
{
    (void)state;
    const char *source = getenv("GLINT_SOURCE_DIR");
    if (!source)
        skip();
    const char *folders[] = {"scenes", "scenes/models"};
    int files = 0;
    for (int k = 0; k < 2; k++) {
        char dir_path[4096];
        snprintf(dir_path, sizeof dir_path, "%s/%s", source, folders[k]);
        DIR *dir = opendir(dir_path);
        assert_non_null(dir);
        for (struct dirent *e; (e = readdir(dir));) {
            size_t len = strlen(e->d_name);
            if (len < 5 || strcmp(e->d_name + len - 5, ".yaml") != 0)
                continue;
            char path[8192];
            snprintf(path, sizeof path, "%s/%s", dir_path, e->d_name);
            size_t size;
            char *text = read_text(path, &size);
            /* Anchors and aliases are libyaml's. */
            if (!same_as_libyaml(text, size) && !strpbrk(text, "&*"))
                fail_msg("the quick reader left %s to libyaml", path);
            free(text);
            files++;
        }
        closedir(dir);
    }
    assert_true(files >= 5);
}

int main(void)
{
    const struct CMUnitTest tests[] = {
        cmocka_unit_test(test_scene_styles_are_read_as_libyaml_reads_them),
        cmocka_unit_test(test_what_it_leaves_to_libyaml),
        cmocka_unit_test(test_the_builders_messages_are_the_same),
        cmocka_unit_test(test_every_example_scene),
    };
    return cmocka_run_group_tests(tests, NULL, NULL);
}
