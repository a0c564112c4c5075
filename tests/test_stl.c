/* test_stl.c: STL files (scenefile/stl.h): binary told by its size even
 * when its header starts with "solid", ASCII in any case and in several
 * solids, the same triangles either way; and every fault, at its line and
 * column or byte. */
#include <stdint.h>
#include <string.h>

#include "scenefile/stl.h"
#include "test.h"

/* Writes n facets into buf as a binary file whose header starts with
 * "solid"; returns its length. */
static size_t stl_binary(unsigned char *buf, int n)
{
    size_t len = 84;

    memset(buf, 0, 84);
    memcpy(buf, "solid but binary", 16);
    buf[80] = (unsigned char)n;
    for (int f = 0; f < n; f++) {
        float v[12] = {0, 0, 0, 0, 0, (float)f, 1, 0, (float)f, 0, 1, (float)f};
        memcpy(buf + len, v, sizeof v); /* little-endian, as x86 and ARM hold them */
        len += 50;
    }
    return len;
}

static const char stl_ascii[] = "SOLID first one\n"
                                "  facet normal 0 0 0\n    outer loop\n      vertex 0 0 0\n"
                                "      vertex 1 0 0\n      vertex 0 1 0\n    endloop\n"
                                "  endfacet\nendsolid first one\n"
                                "solid\nfacet NORMAL 9 9 9\nouter loop\nvertex 0 0 1\n"
                                "vertex 1 0 1\nvertex 0 1 1\nendloop\nendfacet\n";

static void stl_reads_binary_and_ascii_alike(void)
{
    unsigned char buf[84 + 2 * 50];
    size_t len = stl_binary(buf, 2);
    MeshFile a, b;
    Error err;

    CHECK(stl_is_binary(buf, len));
    CHECK(stl_is_ascii((const char *)buf, len)); /* its first word, which says nothing */
    CHECK(!stl_is_binary((const unsigned char *)stl_ascii, strlen(stl_ascii)));
    CHECK(stl_is_ascii(stl_ascii, strlen(stl_ascii)));
    CHECK_INT(0, stl_parse("b.stl", (const char *)buf, len, 0, &a, &err));
    CHECK_INT(0, stl_parse("a.stl", stl_ascii, strlen(stl_ascii), 0, &b, &err));
    CHECK_INT(2, (long long)a.tri_count);
    CHECK_INT(2, (long long)b.tri_count);
    CHECK_INT(6, (long long)b.v_count);
    if (a.v_count == 6 && b.v_count == 6)
        CHECK(memcmp(a.v, b.v, 6 * sizeof *a.v) == 0);
    CHECK(b.tri_count == 2 && b.tri[1][2].v == 5 && b.tri[1][2].vn == -1 && b.tri[1][2].vt == -1);
    CHECK_CONTAINS(a.format, "binary");
    CHECK_CONTAINS(b.format, "ASCII");
    mesh_file_free(&a);
    mesh_file_free(&b);
}

static void stl_faults_name_their_place(void)
{
    static const struct {
        const char *text;
        int line, column;
        const char *message;
    } bad[] = {
        {"solid x\nfacet normal 0 0 0\nouter loop\nvertex 0 0 0\nvertex 1 0 0\nvertex 0 1 0\n"
         "vertex 1 1 1\n",
         7, 1, "expected 'endloop' (a facet has three corners), found 'vertex'"},
        {"solid x\nfacet normal 0 0 0\nouter loop\nvertex 0 0\n", 4, 11,
         "expected 3 numbers for the vertex (x y z), found 2"},
        {"solid x\nfacet normal 0 0 0\nouter loop\nvertex 0 0 0\n", 5, 1,
         "expected 'vertex x y z', found the end of the file"},
        {"solid x\nfacet 0 0 0\n", 2, 1,
         "expected 'facet normal nx ny nz' or 'endsolid', found 'facet'"},
        {"solid x\nfacet normal 0 0 0\nloop\n", 3, 1, "expected 'outer loop', found 'loop'"},
        {"v 0 0 0\n", 1, 1, "expected 'solid', found 'v'"},
    };
    unsigned char buf[84 + 3 * 50];
    size_t len = stl_binary(buf, 3);
    MeshFile m;
    Error err;

    for (size_t i = 0; i < sizeof bad / sizeof bad[0]; i++) {
        CHECK_INT(-1, stl_parse("bad.stl", bad[i].text, strlen(bad[i].text), 0, &m, &err));
        CHECK_ERROR(bad[i].text, &err, bad[i].line, bad[i].column, bad[i].message);
    }
    /* A binary file cut short: the count at byte 80 against the size. */
    CHECK_INT(-1, stl_parse("cut.stl", (const char *)buf, len - 1, 0, &m, &err));
    CHECK_CONTAINS(err.message, "byte 80: a binary STL file of 3 facets has 84 + 50 x 3 = 234 "
                                "bytes, this one 233");
    /* A corner that is not a number. */
    memset(buf + 84 + 50 + 12, 0xff, 4);
    CHECK_INT(-1, stl_parse("nan.stl", (const char *)buf, len, 0, &m, &err));
    CHECK_CONTAINS(err.message, "byte 146: corner 1 of facet 2 is not a finite number");
    /* Within a memory limit too small. */
    CHECK_INT(-1, stl_parse("t.stl", (const char *)buf, len, 64, &m, &err));
    CHECK_CONTAINS(err.message, "memory limit");
}

const TestCase stl_tests[] = {
    {"stl_reads_binary_and_ascii_alike", stl_reads_binary_and_ascii_alike},
    {"stl_faults_name_their_place", stl_faults_name_their_place},
    {NULL, NULL},
};
