/* yaml_write.c - scene-file values as YAML text that reads back to the same
 * bits (yaml_write.h). */
#include <ctype.h>
#include <math.h>
#include <stdlib.h>
#include <string.h>
#include <strings.h>
#include "scenefile/yaml_write.h"

ymap ymap_begin(FILE *f, bool flow, int indent)
{
    return (ymap){f, flow, indent, 0};
}

/* What comes before a key: "{" or ", " in flow style, a new line and the
 * indent in block style (none before the first). */
static void separate(ymap *m)
{
    if (m->flow)
        fputs(m->count ? ", " : "{", m->f);
    else if (m->count)
        fprintf(m->f, "\n%*s", m->indent, "");
    m->count++;
}

void ymap_key(ymap *m, const char *key)
{
    separate(m);
    fprintf(m->f, "%s: ", key);
}

void ymap_key_block(ymap *m, const char *key)
{
    separate(m);
    fprintf(m->f, "%s:", key);
}

void ymap_end(ymap *m)
{
    fputs(m->flow ? (m->count ? "}" : "{}") : "\n", m->f);
}

/* Whether text reads back (as the loader's strtod reads it) to v's bits. */
static bool reads_as(const char *text, double v)
{
    double back = strtod(text, NULL);
    return memcmp(&back, &v, sizeof v) == 0;
}

/* The shortest %g form of v that reads back exactly (17 digits always do),
 * but whole numbers below 10^17 without an exponent: 300, not 3e+02. */
static void number_text(double v, char *buf, size_t size)
{
    for (int digits = 1; digits <= 17; digits++) {
        snprintf(buf, size, "%.*g", digits, v);
        if (reads_as(buf, v))
            break;
    }
    const char *e = strchr(buf, 'e');
    int exponent = e ? atoi(e + 1) : -1;
    if (exponent >= 0 && exponent < 17)
        snprintf(buf, size, "%.*g", exponent + 1, v);
}

void yw_number(FILE *f, double v)
{
    char buf[40];
    number_text(v, buf, sizeof buf);
    fputs(buf, f);
}

void yw_float(FILE *f, float v)
{
    /* The shortest %g form that reads back, made single, to v: the
     * loader's double rounds to the same float. */
    char buf[40];
    for (int digits = 1; digits <= 9; digits++) {
        snprintf(buf, sizeof buf, "%.*g", digits, (double)v);
        if ((float)strtod(buf, NULL) == v || digits == 9)
            break;
    }
    fputs(buf, f);
}

void yw_vec3(FILE *f, glint_vec3 v)
{
    fputc('[', f);
    yw_number(f, v.x);
    fputs(", ", f);
    yw_number(f, v.y);
    fputs(", ", f);
    yw_number(f, v.z);
    fputc(']', f);
}

/* A display value (0..1) whose conversion to linear light is exactly
 * `linear`, in as few digits as will do, into buf; false when none is. The
 * candidates are the inverse conversion's answer and the doubles nearest
 * it, nearest first. */
static bool display_text(double linear, char *buf, size_t size)
{
    enum { NEIGHBOURS = 4, CANDIDATES = 2 * NEIGHBOURS + 1 };
    if (!(linear >= 0 && linear <= 1))
        return false;
    double candidate[CANDIDATES] = {glint_linear_to_srgb(linear)};
    for (int k = 1; k < CANDIDATES; k += 2) {
        candidate[k] = nextafter(k == 1 ? candidate[0] : candidate[k - 2], 2);
        candidate[k + 1] = nextafter(k == 1 ? candidate[0] : candidate[k - 1], -1);
    }
    for (int digits = 1; digits <= 17; digits++)
        for (int k = 0; k < CANDIDATES; k++) {
            double x = candidate[k];
            if (!(x >= 0 && x <= 1) || signbit(x))
                continue;
            snprintf(buf, size, "%.*g", digits, x);
            double back = strtod(buf, NULL);
            double again = glint_srgb_to_linear(back);
            if (back >= 0 && back <= 1 && memcmp(&again, &linear, sizeof linear) == 0)
                return true;
        }
    return false;
}

void yw_color(FILE *f, glint_color c)
{
    char text[3][40];
    if (display_text(c.r, text[0], sizeof text[0]) && display_text(c.g, text[1], sizeof text[1]) &&
        display_text(c.b, text[2], sizeof text[2])) {
        fprintf(f, "[%s, %s, %s]", text[0], text[1], text[2]);
        return;
    }
    fputs("{linear: ", f);
    yw_vec3(f, (glint_vec3){c.r, c.g, c.b});
    fputc('}', f);
}

/* Whether s may be written plain: a letter, '_', '.' or '/' first (never a
 * number, nor YAML's indicators), then letters, digits and "_./+-", and
 * not a word YAML gives a meaning. */
static bool plain_text(const char *s)
{
    static const char *const WORDS[] = {"true", "false", "null", "yes", "no", "on", "off", "y", "n"};
    if (!s[0] || !(isalpha((unsigned char)s[0]) || strchr("_./", s[0])))
        return false;
    for (const char *c = s; *c; c++)
        if (!isalnum((unsigned char)*c) && !strchr("_./+-", *c))
            return false;
    for (size_t i = 0; i < sizeof WORDS / sizeof WORDS[0]; i++)
        if (strcasecmp(s, WORDS[i]) == 0)
            return false;
    return true;
}

void yw_text(FILE *f, const char *s)
{
    if (plain_text(s)) {
        fputs(s, f);
        return;
    }
    fputc('"', f);
    for (const unsigned char *c = (const unsigned char *)s; *c; c++) {
        if (*c == '"' || *c == '\\')
            fprintf(f, "\\%c", *c);
        else if (*c < 0x20 || *c == 0x7f)
            fprintf(f, "\\x%02x", *c);
        else
            fputc(*c, f);
    }
    fputc('"', f);
}

void yw_param(FILE *f, const param *p, const void *obj)
{
    const void *v = (const char *)obj + p->offset;
    switch (p->type) {
    case PARAM_NUMBER:
        yw_number(f, *(const double *)v);
        return;
    case PARAM_INTEGER:
        fprintf(f, "%d", *(const int *)v);
        return;
    case PARAM_UINT32:
        fprintf(f, "%u", (unsigned)*(const uint32_t *)v);
        return;
    case PARAM_CHOICE:
        fputs(p->words[*(const int *)v], f);
        return;
    case PARAM_BOOL:
        fputs(*(const bool *)v ? "true" : "false", f);
        return;
    case PARAM_VEC3:
    case PARAM_DIRECTION:
        yw_vec3(f, *(const glint_vec3 *)v);
        return;
    case PARAM_COLOR:
        yw_color(f, *(const glint_color *)v);
        return;
    case PARAM_COLOR_PAIR:
        fputc('[', f);
        yw_color(f, ((const glint_color *)v)[0]);
        fputs(", ", f);
        yw_color(f, ((const glint_color *)v)[1]);
        fputc(']', f);
        return;
    case PARAM_PATH:
        yw_text(f, *(const char *const *)v);
        return;
    case PARAM_POINTS: {
        int n = *(const int *)((const char *)obj + p->count_offset);
        fputc('[', f);
        for (int i = 0; i < n; i++) {
            fputs(i ? ", " : "", f);
            yw_vec3(f, ((const glint_vec3 *)v)[i]);
        }
        fputc(']', f);
        return;
    }
    case PARAM_NUMBERS:
        fputc('[', f);
        for (int i = 0; i < p->max_count; i++) {
            fputs(i ? ", " : "", f);
            yw_number(f, ((const double *)v)[i]);
        }
        fputc(']', f);
        return;
    case PARAM_COLOR_STOPS: {
        int n = *(const int *)((const char *)obj + p->count_offset);
        const glint_color_stop *stops = v;
        fputc('[', f);
        for (int i = 0; i < n; i++) {
            fputs(i ? ", [" : "[", f);
            yw_number(f, stops[i].at);
            fputs(", ", f);
            yw_color(f, stops[i].color);
            fputc(']', f);
        }
        fputc(']', f);
        return;
    }
    }
}

void yw_params(ymap *m, param_table t, const void *obj, bool all)
{
    for (int i = 0; i < t.count; i++) {
        const param *p = &t.params[i];
        bool no_file = p->type == PARAM_PATH && !*(const char *const *)((const char *)obj + p->offset);
        if (no_file || (!all && param_is_default(p, obj)))
            continue;
        ymap_key(m, p->key);
        yw_param(m->f, p, obj);
    }
}
