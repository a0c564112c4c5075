/*
 * meshgen.c: meshes for the tests and the benchmark, generated the same on
 * every machine, written in each mesh format raytrace reads, so that no
 * large or third-party file is kept in git.
 *
 *   meshgen FORMAT bumpy N      a bumpy sphere of at least N triangles
 *   meshgen FORMAT SHAPE        one face: star, comb, spiral or ring
 *   meshgen FORMAT SHAPE cut    the same shape as triangles that cover it
 *
 * FORMAT is obj, ply-ascii, ply-le, ply-be, stl-ascii or stl-binary; the
 * mesh goes to standard output. Every coordinate is a float exactly (a
 * multiple of 2^-12 below 2^11), so that every format holds the same
 * numbers and the same vertices in the same order make the same
 * triangles. The shapes lie in the plane z = 0 within [-4, 4]; their faces
 * turn anticlockwise seen from -z. STL writes each triangle alone (a face
 * of more than three corners cannot be written: cut is then implied).
 */
#include <math.h>
#include <stdint.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>

enum { MESHGEN_MAX_CORNERS = 256 };
#define MESHGEN_PI 3.14159265358979323846

typedef struct {
    double (*v)[3];
    size_t v_count, v_cap;
    size_t *idx;    /* the faces' corners, one face after another */
    size_t idx_count, idx_cap;
    size_t *first;  /* each face's first corner in idx */
    int *n;         /* and how many it has */
    size_t f_count, f_cap;
} Mesh;

/* Rounds x to a multiple of 2^-12: a float holds it exactly. */
static double meshgen_snap(double x)
{
    return floor(x * 4096 + 0.5) / 4096;
}

static size_t meshgen_vertex(Mesh *m, double x, double y, double z)
{
    if (m->v_count == m->v_cap) {
        m->v_cap = m->v_cap ? 2 * m->v_cap : 1024;
        m->v = realloc(m->v, m->v_cap * sizeof *m->v);
        if (!m->v)
            exit(2);
    }
    m->v[m->v_count][0] = meshgen_snap(x);
    m->v[m->v_count][1] = meshgen_snap(y);
    m->v[m->v_count][2] = meshgen_snap(z);
    return m->v_count++;
}

static void meshgen_face(Mesh *m, const size_t *corners, int n)
{
    if (m->f_count == m->f_cap) {
        m->f_cap = m->f_cap ? 2 * m->f_cap : 1024;
        m->first = realloc(m->first, m->f_cap * sizeof *m->first);
        m->n = realloc(m->n, m->f_cap * sizeof *m->n);
        if (!m->first || !m->n)
            exit(2);
    }
    while (m->idx_count + (size_t)n > m->idx_cap) {
        m->idx_cap = m->idx_cap ? 2 * m->idx_cap : 4096;
        m->idx = realloc(m->idx, m->idx_cap * sizeof *m->idx);
        if (!m->idx)
            exit(2);
    }
    memcpy(m->idx + m->idx_count, corners, (size_t)n * sizeof *corners);
    m->first[m->f_count] = m->idx_count;
    m->idx_count += (size_t)n;
    m->n[m->f_count++] = n;
}

/* Returns corner k of face i. */
static size_t meshgen_corner(const Mesh *m, size_t i, int k)
{
    return m->idx[m->first[i] + (size_t)k];
}

static void meshgen_triangle(Mesh *m, size_t a, size_t b, size_t c)
{
    size_t t[3] = {a, b, c};
    meshgen_face(m, t, 3);
}

/* A sphere of radius about 2 with bumps, of at least n triangles: a grid
 * of rows by columns, cut in two triangles a cell. */
static void meshgen_bumpy(Mesh *m, long n)
{
    int cols = 8, rows;

    while (2L * cols * (cols / 2) < n)
        cols++;
    rows = cols / 2;
    for (int i = 0; i <= rows; i++)
        for (int j = 0; j < cols; j++) {
            double th = MESHGEN_PI * i / rows, ph = 2 * MESHGEN_PI * j / cols;
            double r = 2 + 0.08 * sin(7 * th) * cos(5 * ph);
            meshgen_vertex(m, r * sin(th) * cos(ph), r * cos(th), r * sin(th) * sin(ph));
        }
    for (int i = 0; i < rows; i++)
        for (int j = 0; j < cols; j++) {
            size_t a = (size_t)(i * cols + j), b = (size_t)(i * cols + (j + 1) % cols);
            size_t c = a + (size_t)cols, d = b + (size_t)cols;
            meshgen_triangle(m, a, c, b);
            meshgen_triangle(m, b, c, d);
        }
}

/* One face of shape (or, cut, triangles covering it). */
static int meshgen_shape(Mesh *m, const char *shape, int cut)
{
    size_t c[MESHGEN_MAX_CORNERS];
    int n = 0;

    if (strcmp(shape, "star") == 0) { /* seven points */
        size_t centre = cut ? meshgen_vertex(m, 0, 0, 0) : 0;
        for (int i = 0; i < 14; i++) {
            double a = MESHGEN_PI * i / 7, r = i % 2 ? 1.3 : 3.8;
            c[n++] = meshgen_vertex(m, r * cos(a), r * sin(a), 0);
        }
        for (int i = 0; cut && i < n; i++)
            meshgen_triangle(m, centre, c[i], c[(i + 1) % n]);
    } else if (strcmp(shape, "comb") == 0) { /* a spine and five teeth */
        double x[] = {-3.5, 3.5, 3.5, 2.5, 2.5, 1.5, 1.5, 0.5, 0.5, -0.5, -0.5, -1.5, -1.5,
                      -2.5, -2.5, -3.5};
        double y[] = {-3, -3, 3, 3, -1, -1, 3, 3, -1, -1, 3, 3, -1, -1, 3, 3};
        for (int i = 0; i < 16; i++)
            c[n++] = meshgen_vertex(m, x[i], y[i], 0);
        if (cut) { /* the spine, then each tooth */
            size_t s0 = c[0], s1 = c[1], s2 = meshgen_vertex(m, 3.5, -1, 0);
            size_t s3 = meshgen_vertex(m, -3.5, -1, 0);
            meshgen_triangle(m, s0, s1, s2);
            meshgen_triangle(m, s0, s2, s3);
            for (int t = 0; t < 4; t++) { /* teeth at 2.5..3.5, 0.5..1.5, -1.5..-0.5, -3.5..-2.5 */
                double x0 = 2.5 - 2 * t, x1 = x0 + 1;
                size_t a = meshgen_vertex(m, x0, -1, 0), b = meshgen_vertex(m, x1, -1, 0);
                size_t d = meshgen_vertex(m, x1, 3, 0), e = meshgen_vertex(m, x0, 3, 0);
                meshgen_triangle(m, a, b, d);
                meshgen_triangle(m, a, d, e);
            }
        }
    } else if (strcmp(shape, "spiral") == 0 || strcmp(shape, "ring") == 0) {
        int ring = shape[0] == 'r', steps = ring ? 40 : 48;
        size_t outer[64], inner[64];
        for (int i = 0; i <= steps; i++) {
            double a = 2 * MESHGEN_PI * i / (ring ? steps : 24), r = ring ? 3.5 : 1 + 1.1 * a / (2 * MESHGEN_PI);
            double w = ring ? 1.2 : 0.7;
            outer[i] = meshgen_vertex(m, r * cos(a), r * sin(a), 0);
            inner[i] = meshgen_vertex(m, (r - w) * cos(a), (r - w) * sin(a), 0);
        }
        if (cut) {
            for (int i = 0; i < steps; i++) {
                meshgen_triangle(m, inner[i], outer[i], outer[i + 1]);
                meshgen_triangle(m, inner[i], outer[i + 1], inner[i + 1]);
            }
        } else {
            for (int i = 0; i <= steps; i++)
                c[n++] = outer[i];
            for (int i = steps; i >= 0; i--)
                c[n++] = inner[i];
        }
    } else {
        return -1;
    }
    if (!cut)
        meshgen_face(m, c, n);
    return 0;
}

/* Writes the little- or big-endian bytes of v (size bytes) to f. */
static void meshgen_bytes(FILE *f, uint64_t v, int size, int big)
{
    for (int k = 0; k < size; k++)
        fputc((int)(v >> 8 * (big ? size - 1 - k : k)) & 0xff, f);
}

static void meshgen_float(FILE *f, double x, int big)
{
    float s = (float)x;
    uint32_t bits;

    memcpy(&bits, &s, sizeof bits);
    meshgen_bytes(f, bits, 4, big);
}

static void meshgen_obj(const Mesh *m)
{
    printf("# meshgen: %zu vertices, %zu faces\n", m->v_count, m->f_count);
    for (size_t i = 0; i < m->v_count; i++)
        printf("v %.9g %.9g %.9g\n", m->v[i][0], m->v[i][1], m->v[i][2]);
    for (size_t i = 0; i < m->f_count; i++) {
        putchar('f');
        for (int k = 0; k < m->n[i]; k++)
            printf(" %zu", meshgen_corner(m, i, k) + 1);
        putchar('\n');
    }
}

static void meshgen_ply(const Mesh *m, int format)
{
    static const char *const names[] = {"ascii", "binary_little_endian", "binary_big_endian"};

    printf("ply\nformat %s 1.0\ncomment meshgen\nelement vertex %zu\nproperty float x\n"
           "property float y\nproperty float z\nelement face %zu\n"
           "property list uchar int vertex_indices\nend_header\n",
           names[format], m->v_count, m->f_count);
    for (size_t i = 0; i < m->v_count; i++)
        for (int a = 0; a < 3; a++) {
            if (format == 0)
                printf(a < 2 ? "%.9g " : "%.9g\n", m->v[i][a]);
            else
                meshgen_float(stdout, m->v[i][a], format == 2);
        }
    for (size_t i = 0; i < m->f_count; i++) {
        if (format == 0)
            printf("%d", m->n[i]);
        else
            meshgen_bytes(stdout, (uint64_t)m->n[i], 1, 0);
        for (int k = 0; k < m->n[i]; k++) {
            if (format == 0)
                printf(" %zu", meshgen_corner(m, i, k));
            else
                meshgen_bytes(stdout, meshgen_corner(m, i, k), 4, format == 2);
        }
        if (format == 0)
            putchar('\n');
    }
}

static void meshgen_stl(const Mesh *m, int binary)
{
    size_t tris = 0;
    char header[80] = "solid meshgen: a binary STL whose header starts with 'solid'";

    for (size_t i = 0; i < m->f_count; i++)
        tris += (size_t)m->n[i] - 2;
    if (binary) {
        fwrite(header, 1, sizeof header, stdout);
        meshgen_bytes(stdout, tris, 4, 0);
    } else {
        printf("solid meshgen\n");
    }
    for (size_t i = 0; i < m->f_count; i++)
        for (int k = 1; k + 1 < m->n[i]; k++) { /* a fan: the faces are convex or cut */
            size_t c[3] = {meshgen_corner(m, i, 0), meshgen_corner(m, i, k),
                          meshgen_corner(m, i, k + 1)};
            if (!binary)
                printf("  facet normal 0 0 0\n    outer loop\n");
            for (int a = 0; a < 3 && binary; a++)
                meshgen_float(stdout, 0, 0);
            for (int j = 0; j < 3; j++) {
                if (!binary)
                    printf("      vertex %.9g %.9g %.9g\n", m->v[c[j]][0], m->v[c[j]][1],
                           m->v[c[j]][2]);
                for (int a = 0; a < 3 && binary; a++)
                    meshgen_float(stdout, m->v[c[j]][a], 0);
            }
            if (binary)
                meshgen_bytes(stdout, 0, 2, 0);
            else
                printf("    endloop\n  endfacet\n");
        }
    if (!binary)
        printf("endsolid meshgen\n");
}

int main(int argc, char **argv)
{
    static const char *const formats[] = {"obj",       "ply-ascii",  "ply-le",
                                          "ply-be",    "stl-ascii",  "stl-binary"};
    Mesh m = {NULL, 0, 0, NULL, 0, 0, NULL, NULL, 0, 0};
    int format = -1;

    for (int k = 0; argc >= 3 && k < 6; k++)
        if (strcmp(argv[1], formats[k]) == 0)
            format = k;
    if (format < 0 || (strcmp(argv[2], "bumpy") == 0 ? argc != 4 || atol(argv[3]) < 1
                                                      : meshgen_shape(&m, argv[2],
                                                                      argc > 3 &&
                                                                          strcmp(argv[3], "cut") == 0) != 0)) {
        fprintf(stderr, "usage: meshgen obj|ply-ascii|ply-le|ply-be|stl-ascii|stl-binary "
                        "bumpy N | star|comb|spiral|ring [cut]\n");
        return 2;
    }
    if (strcmp(argv[2], "bumpy") == 0)
        meshgen_bumpy(&m, atol(argv[3]));
    if (format == 0)
        meshgen_obj(&m);
    else if (format <= 3)
        meshgen_ply(&m, format - 1);
    else
        meshgen_stl(&m, format == 5);
    free(m.v);
    free(m.idx);
    free(m.first);
    free(m.n);
    return fflush(stdout) != 0;
}
