/* test_short_decimal.c - core/short_decimal.h gives strtod's double, bit for
 * bit, for every short decimal (a million random ones, and the edges), and
 * leaves every other text to strtod. */
#include <stdarg.h>
#include <stddef.h>
#include <setjmp.h>
#include <stdint.h>
#include <cmocka.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>
#include "core/short_decimal.h"

static void same_as_strtod(const char *text)
{
    double quick = 12345, slow = strtod(text, NULL);
    if (!short_decimal(text, &quick))
        fail_msg("'%s' was not read", text);
    if (memcmp(&quick, &slow, sizeof quick) != 0)
        fail_msg("'%s': %.17g, strtod %.17g", text, quick, slow);
}

static void test_edges(void **state)
{
    (void)state;
    static const char *const texts[] = {"0", "-0", "+0", "-0.0", ".5", "5.", "-.5", "007", "0.1", "0.3", "1.7",
                                        "999999999999999", "0.00000000000001", "123456789012.345", "-1", "+2.25"};
    for (size_t i = 0; i < sizeof texts / sizeof *texts; i++)
        same_as_strtod(texts[i]);
}

/* xorshift: the same million texts on every run. */
static uint64_t next(uint64_t *s)
{
    *s ^= *s << 13;
    *s ^= *s >> 7;
    *s ^= *s << 17;
    return *s;
}

static void test_a_million_random_decimals(void **state)
{
    (void)state;
    uint64_t seed = 0x9E3779B97F4A7C15u;
    for (int i = 0; i < 1000000; i++) {
        char text[32];
        int digits = 1 + (int)(next(&seed) % 15), point = (int)(next(&seed) % (unsigned)(digits + 2)), n = 0;
        if (next(&seed) % 3 == 0)
            text[n++] = next(&seed) % 2 ? '-' : '+';
        for (int d = 0; d < digits; d++) {
            if (d == point)
                text[n++] = '.';
            text[n++] = (char)('0' + next(&seed) % 10);
        }
        if (point == digits)
            text[n++] = '.';
        text[n] = '\0';
        same_as_strtod(text);
    }
}

static void test_other_texts_are_left_to_strtod(void **state)
{
    (void)state;
    static const char *const texts[] = {"", "-", "+", ".", "1e3", "1E3", "0x10", "1.2.3", " 1", "1 ", "inf", ".inf",
                                        "nan", "1,5", "--1", "1234567890123456", "0.000000000000001", "1_000"};
    for (size_t i = 0; i < sizeof texts / sizeof *texts; i++) {
        double v = 7;
        if (short_decimal(texts[i], &v) || v != 7)
            fail_msg("'%s' was read", texts[i]);
    }
}

int main(void)
{
    const struct CMUnitTest tests[] = {
        cmocka_unit_test(test_edges),
        cmocka_unit_test(test_a_million_random_decimals),
        cmocka_unit_test(test_other_texts_are_left_to_strtod),
    };
    return cmocka_run_group_tests(tests, NULL, NULL);
}
