/* short_decimal.c - short decimals read exactly without strtod. */
#include <stdint.h>
#include "core/short_decimal.h"

bool short_decimal(const char *text, double *out)
{
    static const double tens[] = {1e0, 1e1, 1e2, 1e3, 1e4, 1e5, 1e6, 1e7,
                                  1e8, 1e9, 1e10, 1e11, 1e12, 1e13, 1e14, 1e15};
    const char *p = text + (text[0] == '-' || text[0] == '+');
    uint64_t digits = 0;
    int count = 0, decimals = 0;
    bool point = false;
    for (; *p; p++) {
        if (*p >= '0' && *p <= '9') {
            if (++count > 15)
                return false;
            digits = digits * 10 + (uint64_t)(*p - '0');
            decimals += point;
        } else if (*p == '.' && !point) {
            point = true;
        } else {
            return false;
        }
    }
    if (count == 0)
        return false;
    double v = (double)digits / tens[decimals];
    *out = text[0] == '-' ? -v : v;
    return true;
}
