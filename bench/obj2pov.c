/* obj2pov.c - benchmark helper for bench/run: turns a Wavefront OBJ file
 * into a POV-Ray 3.7 mesh2 include file, and writes the large generated
 * test mesh. Plain C99, no dependencies beyond libc and libm, so that a
 * fresh machine with a C compiler can run the benchmark:
 *
 *   cc -O2 -o obj2pov bench/obj2pov.c -lm
 *
 *   obj2pov mesh2 IN.obj OUT.inc NAME [--smooth]
 *       Reads the v, vn and f lines of IN.obj (everything else is ignored),
 *       splits polygons into triangle fans (a b c d -> abc acd), resolves
 *       negative (relative) indices, and writes
 *           #declare NAME = mesh2 { vertex_vectors { ... }
 *                                   normal_vectors { ... } face_indices { ... }
 *                                   normal_indices { ... } }
 *       normal_vectors and normal_indices are written when every face corner
 *       names a normal (f v//vn or v/vt/vn); normal_indices is left out when
 *       it would repeat face_indices. With --smooth, a file without
 *       normals gets area-weighted vertex normals (one per vertex, smooth
 *       across every edge); without it such a mesh is flat shaded.
 *
 *   obj2pov wavy N OUT.obj
 *       Writes an N x N grid of quads over x, z in [-1, 1], each split into
 *       two triangles (2 N^2 triangles, (N + 1)^2 vertices), raised into
 *       waves y = f(x, z) with exact vertex normals (f v//vn). N = 725 gives
 *       1,051,250 triangles.
 *
 * Both modes print one line on stdout:
 *   vertices V normals N triangles T bounds XMIN YMIN ZMIN XMAX YMAX ZMAX
 * Exit status: 0 done, 1 bad input or output error, 2 bad usage. */
#define _POSIX_C_SOURCE 200809L
#include <errno.h>
#include <math.h>
#include <stdarg.h>
#include <stdint.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>

static const char *prog = "obj2pov";

#if defined(__GNUC__)
static void fail(const char *fmt, ...) __attribute__((format(printf, 1, 2), noreturn));
#endif
static void fail(const char *fmt, ...)
{
    va_list ap;
    va_start(ap, fmt);
    fprintf(stderr, "%s: ", prog);
    vfprintf(stderr, fmt, ap);
    fputc('\n', stderr);
    va_end(ap);
    exit(1);
}

/* A growable array of T. */
#define DEFINE_VEC(NAME, T)                                                                 \
    typedef struct NAME { T *v; size_t n, cap; } NAME;                                      \
    static void NAME##_push(NAME *a, T x)                                                   \
    {                                                                                       \
        if (a->n == a->cap) {                                                               \
            size_t cap = a->cap ? 2 * a->cap : 1024;                                        \
            T *p = realloc(a->v, cap * sizeof *p);                                          \
            if (!p) {                                                                       \
                fprintf(stderr, "%s: out of memory\n", prog);                               \
                exit(1);                                                                    \
            }                                                                               \
            a->v = p;                                                                       \
            a->cap = cap;                                                                   \
        }                                                                                   \
        a->v[a->n++] = x;                                                                   \
    }

DEFINE_VEC(dvec, double)
DEFINE_VEC(ivec, uint32_t)

typedef struct mesh {
    dvec pos;        /* 3 per vertex */
    dvec nrm;        /* 3 per normal */
    ivec tri;        /* 3 vertex indices per triangle, 0-based */
    ivec tri_n;      /* 3 normal indices per triangle, when every corner has one */
    int all_normals; /* every corner so far named a normal */
} mesh;

/* Parses up to 3 numbers after a v / vn keyword. */
static void read_vec3(const char *s, dvec *out, const char *path, long line)
{
    for (int i = 0; i < 3; i++) {
        char *end;
        errno = 0;
        double x = strtod(s, &end);
        if (end == s || errno == ERANGE || !isfinite(x))
            fail("%s:%ld: expected three finite numbers", path, line);
        dvec_push(out, x);
        s = end;
    }
}

/* Resolves one OBJ index (1-based, or negative: relative to the `count`
 * elements read so far) to 0-based; fails when out of range. */
static uint32_t resolve(long idx, size_t count, const char *what, const char *path, long line)
{
    long long r;
    if (idx > 0)
        r = idx - 1;
    else if (idx < 0)
        r = (long long)count + idx;
    else
        r = -1;
    if (r < 0 || (size_t)r >= count || r > (long long)UINT32_MAX) {
        fail("%s:%ld: %s index %ld out of range (%zu defined so far)", path, line, what, idx, count);
    }
    return (uint32_t)r;
}

/* One face line: "a b c ...", each corner v, v/vt, v//vn or v/vt/vn. */
static void read_face(mesh *m, const char *s, const char *path, long line)
{
    static ivec fv, fn; /* reused from face to face */
    fv.n = fn.n = 0;
    int face_has_normals = 1;
    while (*s) {
        while (*s == ' ' || *s == '\t')
            s++;
        if (!*s || *s == '#')
            break;
        char *end;
        long vi = strtol(s, &end, 10);
        if (end == s)
            fail("%s:%ld: bad face corner", path, line);
        s = end;
        long ni = 0;
        int has_n = 0;
        if (*s == '/') {
            s++;
            if (*s != '/') {              /* v/vt...: skip the texture index */
                strtol(s, &end, 10);
                if (end == s)
                    fail("%s:%ld: bad texture index in face corner", path, line);
                s = end;
            }
            if (*s == '/') {
                s++;
                ni = strtol(s, &end, 10);
                if (end == s)
                    fail("%s:%ld: bad normal index in face corner", path, line);
                s = end;
                has_n = 1;
            }
        }
        if (*s && *s != ' ' && *s != '\t' && *s != '#')
            fail("%s:%ld: bad face corner", path, line);
        ivec_push(&fv, resolve(vi, m->pos.n / 3, "vertex", path, line));
        if (has_n)
            ivec_push(&fn, resolve(ni, m->nrm.n / 3, "normal", path, line));
        else
            face_has_normals = 0;
    }
    size_t corners = fv.n;
    if (corners < 3)
        fail("%s:%ld: a face needs at least 3 corners", path, line);
    if (!face_has_normals)
        m->all_normals = 0;
    for (size_t i = 1; i + 1 < corners; i++) {
        ivec_push(&m->tri, fv.v[0]);
        ivec_push(&m->tri, fv.v[i]);
        ivec_push(&m->tri, fv.v[i + 1]);
        if (face_has_normals) {
            ivec_push(&m->tri_n, fn.v[0]);
            ivec_push(&m->tri_n, fn.v[i]);
            ivec_push(&m->tri_n, fn.v[i + 1]);
        }
    }
}

static void read_obj(mesh *m, const char *path)
{
    FILE *f = fopen(path, "r");
    if (!f)
        fail("cannot open %s: %s", path, strerror(errno));
    char *buf = NULL, *joined = NULL;
    size_t cap = 0, jcap = 0, jlen = 0;
    ssize_t len;
    long line = 0;
    m->all_normals = 1;
    while ((len = getline(&buf, &cap, f)) >= 0) {
        line++;
        while (len > 0 && (buf[len - 1] == '\n' || buf[len - 1] == '\r'))
            buf[--len] = '\0';
        /* A backslash at the end of a line continues it on the next. */
        if (jlen + (size_t)len + 2 > jcap) {
            jcap = 2 * (jlen + (size_t)len + 2);
            char *p = realloc(joined, jcap);
            if (!p)
                fail("%s:%ld: out of memory", path, line);
            joined = p;
        }
        memcpy(joined + jlen, buf, (size_t)len + 1);
        jlen += (size_t)len;
        if (jlen > 0 && joined[jlen - 1] == '\\') {
            joined[jlen - 1] = ' ';
            continue;
        }
        jlen = 0;
        char *s = joined;
        while (*s == ' ' || *s == '\t')
            s++;
        if (s[0] == 'v' && (s[1] == ' ' || s[1] == '\t'))
            read_vec3(s + 2, &m->pos, path, line);
        else if (s[0] == 'v' && s[1] == 'n' && (s[2] == ' ' || s[2] == '\t'))
            read_vec3(s + 3, &m->nrm, path, line);
        else if (s[0] == 'f' && (s[1] == ' ' || s[1] == '\t'))
            read_face(m, s + 2, path, line);
        /* vt, o, g, s, usemtl, mtllib, l, p, comments: not needed */
    }
    if (ferror(f))
        fail("error reading %s: %s", path, strerror(errno));
    fclose(f);
    free(buf);
    free(joined);
    if (m->tri.n == 0)
        fail("%s: no faces", path);
    if (!m->all_normals) {
        m->tri_n.n = 0;
    }
}

/* Area-weighted vertex normals: the sum of the (unnormalised) cross
 * products of the faces around each vertex. */
static void smooth_normals(mesh *m)
{
    size_t nv = m->pos.n / 3;
    m->nrm.n = 0;
    for (size_t i = 0; i < 3 * nv; i++)
        dvec_push(&m->nrm, 0.0);
    const double *p = m->pos.v;
    double *n = m->nrm.v;
    for (size_t t = 0; t < m->tri.n; t += 3) {
        const uint32_t a = m->tri.v[t], b = m->tri.v[t + 1], c = m->tri.v[t + 2];
        double e1[3], e2[3];
        for (int k = 0; k < 3; k++) {
            e1[k] = p[3 * b + k] - p[3 * a + k];
            e2[k] = p[3 * c + k] - p[3 * a + k];
        }
        double cr[3] = {e1[1] * e2[2] - e1[2] * e2[1], e1[2] * e2[0] - e1[0] * e2[2], e1[0] * e2[1] - e1[1] * e2[0]};
        for (int k = 0; k < 3; k++) {
            n[3 * a + k] += cr[k];
            n[3 * b + k] += cr[k];
            n[3 * c + k] += cr[k];
        }
    }
    m->tri_n.n = 0; /* one normal per vertex: the face indices serve */
}

static void bounds(const mesh *m, double lo[3], double hi[3])
{
    for (int k = 0; k < 3; k++) {
        lo[k] = INFINITY;
        hi[k] = -INFINITY;
    }
    for (size_t i = 0; i < m->pos.n; i += 3)
        for (int k = 0; k < 3; k++) {
            lo[k] = fmin(lo[k], m->pos.v[i + k]);
            hi[k] = fmax(hi[k], m->pos.v[i + k]);
        }
}

static void report(const mesh *m, size_t normals)
{
    double lo[3], hi[3];
    bounds(m, lo, hi);
    printf("vertices %zu normals %zu triangles %zu bounds %.9g %.9g %.9g %.9g %.9g %.9g\n", m->pos.n / 3, normals,
           m->tri.n / 3, lo[0], lo[1], lo[2], hi[0], hi[1], hi[2]);
}

static void write_mesh2(const mesh *m, const char *path, const char *name, int smooth)
{
    mesh w = *m;
    int normals = w.all_normals && w.nrm.n > 0;
    if (!normals && smooth) {
        smooth_normals(&w);
        normals = 1;
    }
    FILE *f = fopen(path, "w");
    if (!f)
        fail("cannot write %s: %s", path, strerror(errno));
    static char iobuf[1 << 16];
    setvbuf(f, iobuf, _IOFBF, sizeof iobuf);
    size_t nv = w.pos.n / 3, nn = normals ? w.nrm.n / 3 : 0, nt = w.tri.n / 3;
    fprintf(f, "// generated by bench/obj2pov.c: %zu vertices, %zu normals, %zu triangles\n", nv, nn, nt);
    fprintf(f, "#declare %s = mesh2 {\n  vertex_vectors {\n    %zu", name, nv);
    for (size_t i = 0; i < nv; i++)
        fprintf(f, ",\n    <%.9g,%.9g,%.9g>", w.pos.v[3 * i], w.pos.v[3 * i + 1], w.pos.v[3 * i + 2]);
    fputs("\n  }\n", f);
    if (normals) {
        fprintf(f, "  normal_vectors {\n    %zu", nn);
        for (size_t i = 0; i < nn; i++) {
            double *n = &w.nrm.v[3 * i];
            double l = sqrt(n[0] * n[0] + n[1] * n[1] + n[2] * n[2]);
            if (l > 0 && isfinite(l))
                fprintf(f, ",\n    <%.7g,%.7g,%.7g>", n[0] / l, n[1] / l, n[2] / l);
            else
                fputs(",\n    <0,1,0>", f); /* an unused or degenerate vertex */
        }
        fputs("\n  }\n", f);
    }
    fprintf(f, "  face_indices {\n    %zu", nt);
    for (size_t t = 0; t < w.tri.n; t += 3)
        fprintf(f, ",\n    <%u,%u,%u>", w.tri.v[t], w.tri.v[t + 1], w.tri.v[t + 2]);
    fputs("\n  }\n", f);
    /* Normals indexed exactly like the vertices (f v//v, as the wavy mesh
     * writes) need no normal_indices: POV-Ray then uses face_indices. */
    if (normals && w.tri_n.n && nn == nv && memcmp(w.tri_n.v, w.tri.v, w.tri.n * sizeof *w.tri.v) == 0)
        w.tri_n.n = 0;
    if (normals && w.tri_n.n) {
        fprintf(f, "  normal_indices {\n    %zu", nt);
        for (size_t t = 0; t < w.tri_n.n; t += 3)
            fprintf(f, ",\n    <%u,%u,%u>", w.tri_n.v[t], w.tri_n.v[t + 1], w.tri_n.v[t + 2]);
        fputs("\n  }\n", f);
    }
    fputs("}\n", f);
    if (fflush(f) != 0 || ferror(f) || fclose(f) != 0)
        fail("error writing %s: %s", path, strerror(errno));
    report(&w, nn);
    if (w.nrm.v != m->nrm.v)
        free(w.nrm.v);
}

/* The wavy surface: its height and the height's partial derivatives. */
#define WAVE_A 0.045
#define WAVE_B 0.03
static double wave(double x, double z, double *dx, double *dz)
{
    const double kx = 11.0, kz = 8.0, kd = 17.0;
    double u = kd * (x + 0.6 * z);
    *dx = WAVE_A * kx * cos(kx * x) * cos(kz * z) + WAVE_B * kd * cos(u);
    *dz = -WAVE_A * kz * sin(kx * x) * sin(kz * z) + WAVE_B * kd * 0.6 * cos(u);
    return WAVE_A * sin(kx * x) * cos(kz * z) + WAVE_B * sin(u);
}

static void write_wavy(long n, const char *path)
{
    FILE *f = fopen(path, "w");
    if (!f)
        fail("cannot write %s: %s", path, strerror(errno));
    static char iobuf[1 << 16];
    setvbuf(f, iobuf, _IOFBF, sizeof iobuf);
    double lo[3] = {INFINITY, INFINITY, INFINITY}, hi[3] = {-INFINITY, -INFINITY, -INFINITY};
    fprintf(f, "# generated by bench/obj2pov.c: wavy surface, %ld x %ld quads, %ld triangles\n", n, n, 2 * n * n);
    for (long j = 0; j <= n; j++)
        for (long i = 0; i <= n; i++) {
            double x = -1 + 2.0 * i / n, z = -1 + 2.0 * j / n, dx, dz;
            double y = wave(x, z, &dx, &dz);
            fprintf(f, "v %.6f %.6f %.6f\n", x, y, z);
            double p[3] = {x, y, z};
            for (int k = 0; k < 3; k++) {
                lo[k] = fmin(lo[k], p[k]);
                hi[k] = fmax(hi[k], p[k]);
            }
        }
    for (long j = 0; j <= n; j++)
        for (long i = 0; i <= n; i++) {
            double x = -1 + 2.0 * i / n, z = -1 + 2.0 * j / n, dx, dz;
            wave(x, z, &dx, &dz);
            double l = sqrt(dx * dx + 1 + dz * dz);
            fprintf(f, "vn %.6f %.6f %.6f\n", -dx / l, 1 / l, -dz / l);
        }
    /* Counter-clockwise seen from above (+y), so the faces point up. */
    for (long j = 0; j < n; j++)
        for (long i = 0; i < n; i++) {
            long a = j * (n + 1) + i + 1, b = a + 1, c = a + (n + 1), d = c + 1;
            fprintf(f, "f %ld//%ld %ld//%ld %ld//%ld\n", a, a, c, c, b, b);
            fprintf(f, "f %ld//%ld %ld//%ld %ld//%ld\n", b, b, c, c, d, d);
        }
    if (fflush(f) != 0 || ferror(f) || fclose(f) != 0)
        fail("error writing %s: %s", path, strerror(errno));
    long nv = (n + 1) * (n + 1);
    printf("vertices %ld normals %ld triangles %ld bounds %.9g %.9g %.9g %.9g %.9g %.9g\n", nv, nv, 2 * n * n,
           lo[0], lo[1], lo[2], hi[0], hi[1], hi[2]);
}

static int usage(void)
{
    fprintf(stderr, "usage: %s mesh2 IN.obj OUT.inc NAME [--smooth]\n"
                    "       %s wavy N OUT.obj      (2 N^2 triangles; N = 725: 1,051,250)\n",
            prog, prog);
    return 2;
}

int main(int argc, char **argv)
{
    if (argc >= 5 && argc <= 6 && strcmp(argv[1], "mesh2") == 0) {
        int smooth = 0;
        if (argc == 6) {
            if (strcmp(argv[5], "--smooth") != 0)
                return usage();
            smooth = 1;
        }
        const char *name = argv[4];
        if (!name[0] || !(name[0] == '_' || (name[0] >= 'A' && name[0] <= 'Z') || (name[0] >= 'a' && name[0] <= 'z')))
            return usage();
        mesh m = {0};
        read_obj(&m, argv[2]);
        write_mesh2(&m, argv[3], name, smooth);
        return 0;
    }
    if (argc == 4 && strcmp(argv[1], "wavy") == 0) {
        char *end;
        long n = strtol(argv[2], &end, 10);
        if (*end || n < 1 || n > 20000)
            return usage();
        write_wavy(n, argv[3]);
        return 0;
    }
    return usage();
}
