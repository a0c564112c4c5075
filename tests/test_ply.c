/* test_ply.c: PLY files (scenefile/ply.h): one mesh in ASCII and both
 * binary byte orders, of every type, read alike; the properties read and
 * those passed over; and every fault, at its line and column or byte. */
#include <stdint.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>

#include "scenefile/ply.h"
#include "test.h"

/* The header of the mesh every encoding holds: a vertex of every kind of
 * property, a face list of uint indices after a uchar count, a flag, and
 * an element passed over. */
#define PLY_HEADER(format)                                                                     \
    "ply\nformat " format " 1.0\ncomment a quad and a triangle\n"                              \
    "element vertex 5\nproperty double x\nproperty float y\nproperty short z\n"                \
    "property float nx\nproperty float ny\nproperty float nz\nproperty float s\n"              \
    "property float t\nproperty uchar red\nproperty ushort green\nproperty float blue\n"       \
    "property list uchar int extra\n"                                                          \
    "element face 2\nproperty list uchar uint vertex_indices\nproperty uchar flags\n"          \
    "element edge 1\nproperty int a\nproperty int b\nend_header\n"

static const double ply_x[5] = {0, 2, 2, 0, 1}, ply_y[5] = {0, 0, 1.5, 1.5, 3};
static const int ply_z[5] = {0, 0, 0, 0, -1};

/* Appends value v of the size-byte type to buf at *n, in the byte order
 * big (0 or 1), as a float or double when fl. */
static void put(unsigned char *buf, size_t *n, double v, int size, int fl, int big)
{
    uint64_t u;
    unsigned char b[8];

    if (fl && size == 4) {
        float f = (float)v;
        uint32_t w;
        memcpy(&w, &f, 4);
        u = w;
    } else if (fl) {
        memcpy(&u, &v, 8);
    } else {
        u = (uint64_t)(int64_t)v;
    }
    for (int k = 0; k < size; k++)
        b[k] = (unsigned char)(u >> 8 * k);
    for (int k = 0; k < size; k++)
        buf[(*n)++] = b[big ? size - 1 - k : k];
}

/* Writes the mesh in binary, little- or big-endian, into buf. */
static size_t ply_binary(unsigned char *buf, int big)
{
    const char *h = big ? PLY_HEADER("binary_big_endian") : PLY_HEADER("binary_little_endian");
    size_t n = strlen(h);

    memcpy(buf, h, n);
    for (int i = 0; i < 5; i++) {
        put(buf, &n, ply_x[i], 8, 1, big);
        put(buf, &n, ply_y[i], 4, 1, big);
        put(buf, &n, ply_z[i], 2, 0, big);
        put(buf, &n, 0, 4, 1, big);
        put(buf, &n, 0, 4, 1, big);
        put(buf, &n, -1, 4, 1, big);
        put(buf, &n, ply_x[i] / 2, 4, 1, big);
        put(buf, &n, ply_y[i] / 3, 4, 1, big);
        put(buf, &n, 255, 1, 0, big);
        put(buf, &n, 65535 * (i % 2), 2, 0, big);
        put(buf, &n, 0.5, 4, 1, big);
        put(buf, &n, i, 1, 0, big); /* a list of i ints, passed over */
        for (int k = 0; k < i; k++)
            put(buf, &n, -k, 4, 0, big);
    }
    put(buf, &n, 4, 1, 0, big);
    for (int k = 0; k < 4; k++)
        put(buf, &n, k, 4, 0, big);
    put(buf, &n, 7, 1, 0, big);
    put(buf, &n, 3, 1, 0, big);
    put(buf, &n, 3, 4, 0, big);
    put(buf, &n, 2, 4, 0, big);
    put(buf, &n, 4, 4, 0, big);
    put(buf, &n, 0, 1, 0, big);
    put(buf, &n, 1, 4, 0, big);
    put(buf, &n, 2, 4, 0, big);
    return n;
}

static const char ply_ascii[] =
    PLY_HEADER("ascii")
    "0 0 0 0 0 -1 0 0 255 0 0.5 0\n"
    "2 0 0 0 0 -1 1 0 255 65535 0.5 1 0\n"
    "2 1.5 0 0 0 -1 1 0.5 255 0 0.5 2 0 -1\n"
    "0 1.5 0 0 0 -1 0 0.5 255 65535 0.5 3 0 -1 -2\n"
    "1 3 -1 0 0 -1 0.5 1 255 0 0.5 4 0 -1 -2 -3\n"
    "4 0 1 2 3 7\n"
    "3 3 2 4 0\n"
    "1 2\n";

static void ply_reads_every_encoding_alike(void)
{
    static unsigned char buf[4096];
    MeshFile m;
    Error err;

    for (int enc = 0; enc < 3; enc++) {
        size_t len = enc == 0 ? strlen(ply_ascii) : ply_binary(buf, enc == 2);
        const char *data = enc == 0 ? ply_ascii : (const char *)buf;
        CHECK(ply_is(data, len));
        CHECK_INT(0, ply_parse("t.ply", data, len, 0, &m, &err));
        if (m.v_count != 5 || m.tri_count != 3) {
            test_fail(__FILE__, __LINE__, "encoding %d: %zu vertices, %zu triangles: %s", enc,
                      m.v_count, m.tri_count, err.message);
            mesh_file_free(&m);
            continue;
        }
        for (int i = 0; i < 5; i++) {
            CHECK_NEAR(ply_x[i], m.v[i].x, 0);
            CHECK_NEAR(ply_y[i], m.v[i].y, 0);
            CHECK_NEAR(ply_z[i], m.v[i].z, 0);
            CHECK_NEAR(-1, m.vn[i].z, 0);
            CHECK_NEAR(ply_x[i] / 2, m.vt[i][0], 1e-7);
            CHECK_NEAR(ply_y[i] / 3, m.vt[i][1], 1e-7);
            /* uchar 255 is 255; ushort 65535 is 255; float 0.5 is 127.5 */
            CHECK_NEAR(255, m.vc[i][0], 0);
            CHECK_NEAR(255 * (i % 2), m.vc[i][1], 1e-4);
            CHECK_NEAR(127.5, m.vc[i][2], 0);
        }
        /* The quad, a fan noted for cutting, then the triangle. */
        CHECK_INT(1, (long long)m.polygon_count);
        CHECK(m.polygons && m.polygons[0][0] == 0 && m.polygons[0][1] == 4);
        CHECK(m.tri[2][0].v == 3 && m.tri[2][1].v == 2 && m.tri[2][2].v == 4);
        CHECK(m.tri[2][0].vt == 3 && m.tri[2][0].vn == 3);
        CHECK_CONTAINS(m.format, enc == 0 ? "ASCII" : enc == 1 ? "little" : "big");
        mesh_file_free(&m);
    }
}

/* Without normals, texture coordinates or colours: none kept; the
 * vertex_index spelling and other names (texture_u, diffuse_red) read. */
static void ply_reads_what_the_vertices_have(void)
{
    static const char plain[] = "ply\r\nformat ascii 1.0\r\nelement vertex 3\r\nproperty float x\r\n"
                                "property float y\r\nproperty float z\r\nproperty float texture_u\r\n"
                                "property float texture_v\r\nproperty uchar diffuse_red\r\n"
                                "element face 1\r\nproperty list uchar ushort vertex_index\r\n"
                                "end_header\r\n0 0 0 0 0 9\r\n1 0 0 1 0 9\r\n0 1 0 0 1 9\r\n3 0 1 2\r\n";
    MeshFile m;
    Error err;

    CHECK_INT(0, ply_parse("p.ply", plain, strlen(plain), 0, &m, &err));
    CHECK_INT(3, (long long)m.v_count);
    CHECK_INT(1, (long long)m.tri_count);
    CHECK(m.vn == NULL && m.vc == NULL && m.vt != NULL);
    CHECK(m.tri_count == 1 && m.tri[0][1].v == 1 && m.tri[0][1].vt == 1 && m.tri[0][1].vn == -1);
    mesh_file_free(&m);
}

static void ply_faults_name_their_place(void)
{
    static const struct {
        const char *text;
        int line, column;
        const char *message;
    } bad[] = {
        {"ply\nformat ascii 2.0\n", 2, 14, "unknown PLY version '2.0' (expected 1.0)"},
        {"ply\nformat binary_middle_endian 1.0\n", 2, 8,
         "unknown PLY format 'binary_middle_endian' (expected ascii, binary_little_endian or "
         "binary_big_endian)"},
        {"ply\nformat ascii 1.0\nelement vertex 1\nproperty float128 x\n", 4, 10,
         "unknown property type 'float128' (expected char, uchar, short, ushort, int, uint, "
         "float, double or int8 ... float64)"},
        {"ply\nformat ascii 1.0\nproperty float x\n", 3, 1, "a property must follow its element"},
        {"ply\nformat ascii 1.0\nelement vertex -3\n", 3, 16,
         "expected the element's count, a whole number, found '-3'"},
        {"ply\nformat ascii 1.0\nelement face 1\nproperty list float int vertex_indices\n", 4, 15,
         "expected the integer type of a list's count (uchar, ushort, uint, ...), found 'float'"},
        {"ply\nformat ascii 1.0\nelement vertex 1\nproperty float y\nend_header\n1\n", 5, 1,
         "the element 'vertex' has no property x, y or z"},
        {"ply\nformat ascii 1.0\nelement vertex 1\n", 3, 1, "the header has no end_header line"},
        {"ply\nend_header\n", 2, 1, "end_header before the format line"},
        {"ply\nformat ascii 1.0\nelement vertex 1\nproperty float x\nproperty float y\n"
         "property float z\nend_header\n0 0 x\n", 8, 5, "expected a number (float), found 'x'"},
        {"ply\nformat ascii 1.0\nelement vertex 3\nproperty float x\nproperty float y\n"
         "property float z\nelement face 1\nproperty list uchar int vertex_indices\nend_header\n"
         "0 0 0\n1 0 0\n0 1 0\n3 0 1 3\n", 13, 7, "vertex 3 does not exist (the file has 3 vertices)"},
        {"ply\nformat ascii 1.0\nelement vertex 3\nproperty float x\nproperty float y\n"
         "property float z\nelement face 1\nproperty list uchar int vertex_indices\nend_header\n"
         "0 0 0\n1 0 0\n0 1 0\n2 0 1\n", 13, 1, "a face needs at least 3 corners, found 2"},
        {"ply\nformat ascii 1.0\nelement vertex 1\nproperty float x\nproperty float y\n"
         "property float z\nend_header\n0 0 0 4\n", 8, 7,
         "more data after the elements the header declares"},
        {"ply\nformat ascii 1.0\nelement vertex 1\nproperty uchar x\nproperty float y\n"
         "property float z\nend_header\n256 0 0\n", 8, 1,
         "expected a whole number that a uchar holds, found '256'"},
    };
    MeshFile m;
    Error err;

    for (size_t i = 0; i < sizeof bad / sizeof bad[0]; i++) {
        CHECK_INT(-1, ply_parse("bad.ply", bad[i].text, strlen(bad[i].text), 0, &m, &err));
        CHECK_ERROR(bad[i].text, &err, bad[i].line, bad[i].column, bad[i].message);
    }
    /* An empty file (assimp's invalid/empty.ply) has no line to point at. */
    CHECK_INT(-1, ply_parse("empty.ply", "", 0, 0, &m, &err));
    CHECK_CONTAINS(err.message, "the file is empty");
}

/* A binary file cut short, or holding fewer items than its header says:
 * refused at the byte where it fails, before anything large is made. */
static void ply_binary_faults_name_their_byte(void)
{
    static unsigned char buf[4096];
    static const char huge[] = "ply\nformat binary_little_endian 1.0\nelement vertex 4000000000\n"
                                "property float x\nproperty float y\nproperty float z\nend_header\n"
                                "abcdefghijkl";
    size_t len = ply_binary(buf, 0), head = strlen(PLY_HEADER("binary_little_endian"));
    MeshFile m;
    Error err;

    CHECK_INT(-1, ply_parse("cut.ply", (const char *)buf, len - 3, 0, &m, &err));
    CHECK_CONTAINS(err.message, "the header declares 1 item of the element 'edge': more than the "
                                "5 bytes left hold");
    CHECK_CONTAINS(err.message, "byte ");
    /* Cut inside the face list: its count read, its items not all there. */
    CHECK_INT(-1, ply_parse("cut.ply", (const char *)buf, len - 8 - 5, 0, &m, &err));
    CHECK_CONTAINS(err.message, "the file ends inside face 2 of 2 (element 'face')");
    CHECK_INT(-1, ply_parse("cut.ply", (const char *)buf, head + 20, 0, &m, &err));
    CHECK_CONTAINS(err.message, "the header declares 5 items of the element 'vertex': more than "
                                "the 20 bytes left hold");
    CHECK_INT(-1, ply_parse("huge.ply", huge, strlen(huge), 0, &m, &err));
    CHECK_CONTAINS(err.message, "the header declares 4000000000 items");
    /* Within a memory limit too small: refused before it is read. */
    CHECK_INT(-1, ply_parse("t.ply", (const char *)buf, len, 100, &m, &err));
    CHECK_CONTAINS(err.message, "memory limit");
}

const TestCase ply_tests[] = {
    {"ply_reads_every_encoding_alike", ply_reads_every_encoding_alike},
    {"ply_reads_what_the_vertices_have", ply_reads_what_the_vertices_have},
    {"ply_faults_name_their_place", ply_faults_name_their_place},
    {"ply_binary_faults_name_their_byte", ply_binary_faults_name_their_byte},
    {NULL, NULL},
};
