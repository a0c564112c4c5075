/* stl.c: STL meshes, binary and ASCII (see stl.h). */
#include "scenefile/stl.h"

#include <ctype.h>
#include <inttypes.h>
#include <math.h>
#include <stdint.h>
#include <stdlib.h>
#include <string.h>

#include "math/number.h"
#include "scenefile/lex.h"

enum { STL_HEADER = 84, STL_FACET = 50 };

/* Returns the little-endian 32-bit word at p. */
static uint32_t stl_u32(const unsigned char *p)
{
    return (uint32_t)p[0] | (uint32_t)p[1] << 8 | (uint32_t)p[2] << 16 | (uint32_t)p[3] << 24;
}

/* Returns the little-endian IEEE 754 single at p. */
static double stl_f32(const unsigned char *p)
{
    uint32_t bits = stl_u32(p);
    float f;

    memcpy(&f, &bits, sizeof f);
    return (double)f;
}

int stl_is_binary(const unsigned char *data, size_t len)
{
    return len >= STL_HEADER && (len - STL_HEADER) % STL_FACET == 0 &&
           (len - STL_HEADER) / STL_FACET == stl_u32(data + 80);
}

int stl_is_ascii(const char *data, size_t len)
{
    size_t i = 0;

    if (len >= 3 && memcmp(data, "\xEF\xBB\xBF", 3) == 0)
        i = 3;
    while (i < len && isspace((unsigned char)data[i]))
        i++;
    if (len - i < 5)
        return 0;
    for (int k = 0; k < 5; k++)
        if (tolower((unsigned char)data[i + k]) != "solid"[k])
            return 0;
    return len - i == 5 || isspace((unsigned char)data[i + 5]);
}

/* Sizes mesh for n triangles of three corners of their own, within
 * max_bytes; returns 0, or -1. */
static int stl_size(MeshFile *mesh, size_t n, size_t max_bytes)
{
    size_t each = 3 * sizeof *mesh->v + sizeof *mesh->tri;

    if (n > SIZE_MAX / each || (max_bytes && n * each > max_bytes))
        return -1;
    mesh->v = malloc(3 * n * sizeof *mesh->v + 1);
    mesh->tri = malloc(n * sizeof *mesh->tri + 1);
    return mesh->v && mesh->tri ? 0 : -1;
}

/* Adds the facet a b c to mesh (room made). */
static void stl_facet(MeshFile *mesh, Vec3 a, Vec3 b, Vec3 c)
{
    size_t v = mesh->v_count;
    MeshCorner(*t)[3] = &mesh->tri[mesh->tri_count++];

    mesh->v[v] = a;
    mesh->v[v + 1] = b;
    mesh->v[v + 2] = c;
    for (int k = 0; k < 3; k++) {
        (*t)[k].v = (long)(v + (size_t)k);
        (*t)[k].vt = (*t)[k].vn = -1;
    }
    mesh->v_count += 3;
}

/* Reads a binary file (its size checked). */
static int stl_binary(const char *name, const unsigned char *p, size_t len, size_t max_bytes,
                      MeshFile *mesh, Error *err)
{
    size_t n = (len - STL_HEADER) / STL_FACET;
    char room[NUMBER_FORMAT_MAX];

    if (stl_size(mesh, n, max_bytes) != 0) {
        if (max_bytes)
            error_set(err, name, "%zu facets need more memory than the %s the memory limit "
                      "leaves the mesh", n, number_bytes(room, max_bytes));
        else
            error_set(err, name, "out of memory for %zu facets", n);
        return -1;
    }
    for (size_t f = 0; f < n; f++) {
        const unsigned char *q = p + STL_HEADER + f * STL_FACET + 12; /* past the normal */
        Vec3 c[3];
        for (int k = 0; k < 3; k++) {
            double x = stl_f32(q + 12 * k), y = stl_f32(q + 12 * k + 4), z = stl_f32(q + 12 * k + 8);
            if (!isfinite(x) || !isfinite(y) || !isfinite(z)) {
                error_set(err, name, "byte %zu: corner %d of facet %zu is not a finite number",
                          (size_t)(q - p) + 12 * (size_t)k, k + 1, f + 1);
                return -1;
            }
            c[k] = vec3(x, y, z);
        }
        stl_facet(mesh, c[0], c[1], c[2]);
    }
    mesh->format = "STL (binary)";
    return 0;
}

/* Says whether token t spells word, in any case. */
static int stl_word(const Token *t, const char *word)
{
    size_t n = strlen(word);

    if (t->len != n)
        return 0;
    for (size_t i = 0; i < n; i++)
        if (tolower((unsigned char)t->text[i]) != word[i])
            return 0;
    return 1;
}

/* The states of an ASCII file, and the word each expects. */
typedef enum { STL_SOLID, STL_FACET_OR_END, STL_LOOP, STL_VERTEX, STL_ENDLOOP, STL_ENDFACET } StlState;

static const char *const stl_expected[] = {
    "'solid'", "'facet normal nx ny nz' or 'endsolid'", "'outer loop'", "'vertex x y z'",
    "'endloop' (a facet has three corners)", "'endfacet'"};

/* Reads the three coordinates of a vertex record into *v. */
static int stl_vertex(Lexer *L, const Record *rec, Vec3 *v)
{
    static const char *const names[] = {"x", "y", "z"};
    static const FieldKind kinds[] = {FIELD_COORD, FIELD_COORD, FIELD_COORD};
    static const RecordSpec spec = {"the vertex", "x y z", 3, 0, 0, names, kinds};
    double c[3];

    if (lex_numbers(L, rec, 1, &spec, c) < 0)
        return -1;
    *v = vec3(c[0], c[1], c[2]);
    return 0;
}

/* Makes room for one more facet in mesh (capacity *cap); returns 0 or -1. */
static int stl_room(MeshFile *mesh, size_t *cap, size_t max_bytes)
{
    size_t each = 3 * sizeof *mesh->v + sizeof *mesh->tri, more;
    void *v, *t;

    if (mesh->tri_count < *cap)
        return 0;
    more = *cap ? 2 * *cap : 64;
    if (more > SIZE_MAX / each || (max_bytes && more * each > max_bytes))
        return -1;
    v = realloc(mesh->v, 3 * more * sizeof *mesh->v);
    if (v)
        mesh->v = v;
    t = realloc(mesh->tri, more * sizeof *mesh->tri);
    if (t)
        mesh->tri = t;
    if (!v || !t)
        return -1;
    *cap = more;
    return 0;
}

/* Reads an ASCII file. */
static int stl_ascii(const char *name, const char *text, size_t len, size_t max_bytes,
                     MeshFile *mesh, Error *err)
{
    StlState state = STL_SOLID;
    Lexer L;
    Record rec;
    Vec3 corner[3];
    size_t cap = 0;
    int got, k = 0;
    char q[64];

    lex_init(&L, name, text, len, err);
    while ((got = lex_next_record(&L, &rec)) == 1) {
        const Token *t = &rec.tok[0];
        StlState at = state;
        int ok;
        switch (state) {
        case STL_SOLID:
            ok = stl_word(t, "solid");
            state = STL_FACET_OR_END;
            break;
        case STL_FACET_OR_END:
            ok = stl_word(t, "endsolid") || (stl_word(t, "facet") && rec.count >= 2 &&
                                            stl_word(&rec.tok[1], "normal"));
            state = stl_word(t, "endsolid") ? STL_SOLID : STL_LOOP;
            break;
        case STL_LOOP:
            ok = stl_word(t, "outer") && rec.count == 2 && stl_word(&rec.tok[1], "loop");
            state = STL_VERTEX;
            k = 0;
            break;
        case STL_VERTEX:
            ok = stl_word(t, "vertex");
            if (ok && stl_vertex(&L, &rec, &corner[k]) != 0)
                return -1;
            state = ++k == 3 ? STL_ENDLOOP : STL_VERTEX;
            break;
        case STL_ENDLOOP:
            ok = stl_word(t, "endloop") && rec.count == 1;
            state = STL_ENDFACET;
            break;
        default:
            ok = stl_word(t, "endfacet") && rec.count == 1;
            if (ok && stl_room(mesh, &cap, max_bytes) != 0) {
                lex_fail(&L, &rec.line, t->column, "out of memory (or past the memory limit) "
                         "after %zu facets", mesh->tri_count);
                return -1;
            }
            if (ok)
                stl_facet(mesh, corner[0], corner[1], corner[2]);
            state = STL_FACET_OR_END;
            break;
        }
        if (!ok) {
            lex_fail(&L, &rec.line, t->column, "expected %s, found %s", stl_expected[at],
                     lex_quote(q, sizeof q, t));
            return -1;
        }
    }
    if (got < 0)
        return -1;
    if (state != STL_SOLID && state != STL_FACET_OR_END) {
        lex_fail_eof(&L, stl_expected[state], NULL);
        return -1;
    }
    mesh->format = "STL (ASCII)";
    return 0;
}

int stl_parse(const char *name, const char *data, size_t len, size_t max_bytes, MeshFile *mesh,
              Error *err)
{
    int rc;

    mesh_file_init(mesh);
    if (stl_is_binary((const unsigned char *)data, len)) {
        rc = stl_binary(name, (const unsigned char *)data, len, max_bytes, mesh, err);
    } else if (len >= STL_HEADER && memchr(data, '\0', len < 1024 ? len : 1024)) {
        /* Binary bytes that do not add up: cut short, or a wrong count. */
        uint32_t n = stl_u32((const unsigned char *)data + 80);
        error_set(err, name, "byte 80: a binary STL file of %" PRIu32 " facets has 84 + 50 x %"
                  PRIu32 " = %.0f bytes, this one %zu", n, n, 84.0 + 50.0 * n, len);
        rc = -1;
    } else {
        rc = stl_ascii(name, data, len, max_bytes, mesh, err);
    }
    if (rc != 0)
        mesh_file_free(mesh);
    return rc;
}
