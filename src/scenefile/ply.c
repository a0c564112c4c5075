/* ply.c: PLY meshes, ASCII and binary (see ply.h). */
#include "scenefile/ply.h"

#include <math.h>
#include <stdarg.h>
#include <stdint.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>

#include "base/grow.h"
#include "math/number.h"

/* The scalar types of PLY, in the order of ply_types[]. */
typedef enum { PLY_INT8, PLY_UINT8, PLY_INT16, PLY_UINT16, PLY_INT32, PLY_UINT32, PLY_FLOAT32,
               PLY_FLOAT64 } PlyType;

static const struct {
    const char *name, *alias;
    int size;
    double max; /* an integer type's largest value, for colours; 0 for floats */
} ply_types[] = {{"char", "int8", 1, 127},           {"uchar", "uint8", 1, 255},
                 {"short", "int16", 2, 32767},        {"ushort", "uint16", 2, 65535},
                 {"int", "int32", 4, 2147483647.0},   {"uint", "uint32", 4, 4294967295.0},
                 {"float", "float32", 4, 0},          {"double", "float64", 8, 0}};

/* What a property means here. */
typedef enum { PLY_X, PLY_Y, PLY_Z, PLY_NX, PLY_NY, PLY_NZ, PLY_U, PLY_V, PLY_RED, PLY_GREEN,
               PLY_BLUE, PLY_INDICES, PLY_ROLES, PLY_NONE = PLY_ROLES } PlyRole;

enum { PLY_ELEMENTS_MAX = 64, PLY_PROPERTIES_MAX = 64, PLY_NAME_MAX = 32 };

typedef struct {
    PlyType type;       /* a scalar's, or a list's items' */
    int list;           /* 1: a list, its count of count_type first */
    PlyType count_type;
    PlyRole role;
} PlyProperty;

typedef struct {
    char name[PLY_NAME_MAX]; /* as written (cut) */
    size_t count;
    PlyProperty props[PLY_PROPERTIES_MAX];
    int prop_count;
    int has[PLY_ROLES];      /* roles its properties take */
} PlyElement;

/* The formats of the data. */
typedef enum { PLY_ASCII, PLY_LITTLE, PLY_BIG } PlyFormat;

/* Where the reader is. */
typedef struct {
    const char *name;    /* the file, for messages */
    const char *data, *p, *end;
    PlyFormat format;
    PlyElement elements[PLY_ELEMENTS_MAX];
    int element_count;
    const char *line;    /* text: the line p is on, and its number */
    int lineno;
    size_t max_bytes, used;
    Error *err;
    const char *token;         /* ASCII: the last number's first byte */
    const PlyElement *element; /* the element being read, */
    size_t index;              /* which one of them */
    MeshCorner *corners;       /* a face's corners */
    size_t corner_capacity;
    size_t caps[3];            /* the triangles', faces noted and corners' */
} PlyReader;

int ply_is(const char *data, size_t len)
{
    return len >= 4 && memcmp(data, "ply", 3) == 0 &&
           (data[3] == '\n' || (data[3] == '\r' && len >= 5 && data[4] == '\n'));
}

/* Returns the length of the text line at p (to end), without its ending. */
static size_t ply_line_length(const char *p, const char *end)
{
    const char *eol = memchr(p, '\n', (size_t)(end - p));
    size_t n = (size_t)((eol ? eol : end) - p);

    return n > 0 && p[n - 1] == '\r' ? n - 1 : n;
}

/* Records a fault at `at` in the text (header or ASCII data): its line
 * and column. */
static int ply_fail_at(PlyReader *r, const char *at, const char *fmt, ...)
{
    char msg[ERROR_MESSAGE_MAX];
    va_list ap;

    va_start(ap, fmt);
    vsnprintf(msg, sizeof msg, fmt, ap);
    va_end(ap);
    error_set_at(r->err, r->name, r->lineno, (int)(at - r->line) + 1, r->line,
                 ply_line_length(r->line, r->end), "%s", msg);
    return -1;
}

/* Warns in mesh, at `at` in the header, of what the reader assumed;
 * returns 0, or -1 when memory runs out. */
static int ply_warn_at(PlyReader *r, MeshFile *mesh, const char *at, const char *message)
{
    Error w;

    error_set_at(&w, r->name, r->lineno, (int)(at - r->line) + 1, r->line,
                 ply_line_length(r->line, r->end), "%s", message);
    if (mesh_file_warn(mesh, &w) == 0)
        return 0;
    error_set(r->err, r->name, "out of memory");
    return -1;
}

/* Records a fault in the data at the reader's place: its line and column
 * in ASCII, its byte offset in binary. */
static int ply_fail(PlyReader *r, const char *fmt, ...)
{
    char msg[ERROR_MESSAGE_MAX];
    va_list ap;

    va_start(ap, fmt);
    vsnprintf(msg, sizeof msg, fmt, ap);
    va_end(ap);
    if (r->format == PLY_ASCII)
        return ply_fail_at(r, r->p, "%s", msg);
    error_set(r->err, r->name, "byte %zu: %s", (size_t)(r->p - r->data), msg);
    return -1;
}

/* Returns the type named by the n bytes at s, or -1. */
static int ply_type_named(const char *s, size_t n)
{
    for (int t = 0; t <= PLY_FLOAT64; t++)
        if ((strlen(ply_types[t].name) == n && memcmp(ply_types[t].name, s, n) == 0) ||
            (strlen(ply_types[t].alias) == n && memcmp(ply_types[t].alias, s, n) == 0))
            return t;
    return -1;
}

/* Returns the role of the vertex property named by the n bytes at s. */
static PlyRole ply_vertex_role(const char *s, size_t n)
{
    static const char *const names[][4] = {{"x"}, {"y"}, {"z"}, {"nx"}, {"ny"}, {"nz"},
                                           {"u", "s", "texture_u", "texture_s"},
                                           {"v", "t", "texture_v", "texture_t"},
                                           {"red", "diffuse_red"}, {"green", "diffuse_green"},
                                           {"blue", "diffuse_blue"}};

    for (int role = 0; role < PLY_INDICES; role++)
        for (int k = 0; k < 4 && names[role][k]; k++)
            if (strlen(names[role][k]) == n && memcmp(names[role][k], s, n) == 0)
                return (PlyRole)role;
    return PLY_NONE;
}

/* Moves *i past blanks of the n-byte line s; returns the end of the word
 * there. */
static size_t ply_word(const char *s, size_t n, size_t *i)
{
    size_t e;

    while (*i < n && (s[*i] == ' ' || s[*i] == '\t'))
        (*i)++;
    for (e = *i; e < n && s[e] != ' ' && s[e] != '\t'; e++)
        ;
    return e;
}

/* property -> 'property' type name | 'property list' type type name */
static int ply_property(PlyReader *r, const char *s, size_t n, size_t i)
{
    PlyElement *e = &r->elements[r->element_count - 1];
    PlyProperty *p;
    size_t w = ply_word(s, n, &i);
    int t;

    if (e->prop_count == PLY_PROPERTIES_MAX)
        return ply_fail_at(r, s + i, "more than %d properties in the element '%s'",
                           PLY_PROPERTIES_MAX, e->name);
    p = &e->props[e->prop_count];
    p->list = w - i == 4 && memcmp(s + i, "list", 4) == 0;
    if (p->list) {
        i = w;
        w = ply_word(s, n, &i);
        if ((t = ply_type_named(s + i, w - i)) < 0 || t >= PLY_FLOAT32)
            return ply_fail_at(r, s + i, "expected the integer type of a list's count (uchar, "
                               "ushort, uint, ...), found '%.*s'", (int)(w - i > 20 ? 20 : w - i),
                               s + i);
        p->count_type = (PlyType)t;
        i = w;
        w = ply_word(s, n, &i);
    }
    if ((t = ply_type_named(s + i, w - i)) < 0)
        return ply_fail_at(r, s + i, "unknown property type '%.*s' (expected char, uchar, "
                           "short, ushort, int, uint, float, double or int8 ... float64)",
                           (int)(w - i > 20 ? 20 : w - i), s + i);
    p->type = (PlyType)t;
    i = w;
    w = ply_word(s, n, &i);
    if (w == i)
        return ply_fail_at(r, s + i, "expected the property's name, found the end of the line");
    p->role = PLY_NONE;
    if (strcmp(e->name, "vertex") == 0 && !p->list)
        p->role = ply_vertex_role(s + i, w - i);
    else if (strcmp(e->name, "face") == 0 && p->list &&
             ((w - i == 14 && memcmp(s + i, "vertex_indices", 14) == 0) ||
              (w - i == 12 && memcmp(s + i, "vertex_index", 12) == 0)))
        p->role = PLY_INDICES;
    if (p->role != PLY_NONE) {
        if (e->has[p->role])
            p->role = PLY_NONE; /* the first of a name counts */
        else
            e->has[p->role] = 1;
    }
    if (p->role == PLY_INDICES && p->type >= PLY_FLOAT32)
        return ply_fail_at(r, s + i, "the face's vertex indices must be integers, not %s",
                           ply_types[p->type].name);
    e->prop_count++;
    return 0;
}

/* element -> 'element' name count */
static int ply_element(PlyReader *r, const char *s, size_t n, size_t i)
{
    PlyElement *e;
    size_t w = ply_word(s, n, &i), c;
    double count;

    if (r->element_count == PLY_ELEMENTS_MAX)
        return ply_fail_at(r, s, "more than %d elements", PLY_ELEMENTS_MAX);
    if (w == i)
        return ply_fail_at(r, s + i, "expected the element's name and count");
    e = &r->elements[r->element_count];
    memset(e, 0, sizeof *e);
    snprintf(e->name, sizeof e->name, "%.*s", (int)(w - i), s + i);
    i = w;
    c = ply_word(s, n, &i);
    if (number_parse(s + i, c - i, &count) != NUMBER_OK || count < 0 || count != floor(count) ||
        count > 1e18 || ply_word(s, n, &c) != c)
        return ply_fail_at(r, s + i, "expected the element's count, a whole number, found "
                           "'%.*s'", (int)(c - i > 20 ? 20 : c - i), s + i);
    e->count = (size_t)count;
    r->element_count++;
    return 0;
}

/* format -> 'format' ('ascii' | 'binary_little_endian' | 'binary_big_endian') '1.0' */
static int ply_format(PlyReader *r, const char *s, size_t n, size_t i)
{
    static const char *const names[] = {"ascii", "binary_little_endian", "binary_big_endian"};
    size_t w = ply_word(s, n, &i), v;
    int f;

    for (f = 0; f < 3; f++)
        if (strlen(names[f]) == w - i && memcmp(names[f], s + i, w - i) == 0)
            break;
    if (f == 3)
        return ply_fail_at(r, s + i, "unknown PLY format '%.*s' (expected ascii, "
                           "binary_little_endian or binary_big_endian)",
                           (int)(w - i > 30 ? 30 : w - i), s + i);
    r->format = (PlyFormat)f;
    i = w;
    v = ply_word(s, n, &i);
    if (!((v - i == 3 && memcmp(s + i, "1.0", 3) == 0) || (v - i == 1 && s[i] == '1')))
        return ply_fail_at(r, s + i, "unknown PLY version '%.*s' (expected 1.0)",
                           (int)(v - i > 20 ? 20 : v - i), s + i);
    return 0;
}

/* Reads the header, up to and with end_header, into r (its warnings into
 * mesh); leaves r->p at the data. */
static int ply_header(PlyReader *r, MeshFile *mesh)
{
    int format_seen = 0;

    r->p = r->data;
    r->lineno = 0;
    while (r->p < r->end) {
        const char *s = r->p, *eol = memchr(s, '\n', (size_t)(r->end - s));
        size_t n = ply_line_length(s, r->end), i = 0, w;
        r->line = s;
        r->lineno++;
        r->p = eol ? eol + 1 : r->end;
        w = ply_word(s, n, &i);
        if (r->lineno == 1) {
            if (!(w - i == 3 && i == 0 && memcmp(s, "ply", 3) == 0 && n == 3))
                return ply_fail_at(r, s, "not a PLY file: its first line must be 'ply'");
        } else if (w - i == 6 && memcmp(s + i, "format", 6) == 0) {
            if (ply_format(r, s, n, w) != 0)
                return -1;
            format_seen = 1;
        } else if ((w - i == 7 && memcmp(s + i, "comment", 7) == 0) ||
                   (w - i == 8 && memcmp(s + i, "obj_info", 8) == 0) || w == i) {
            continue;
        } else if (w - i == 7 && memcmp(s + i, "element", 7) == 0) {
            if (ply_element(r, s, n, w) != 0)
                return -1;
        } else if (w - i == 8 && memcmp(s + i, "property", 8) == 0) {
            if (r->element_count == 0)
                return ply_fail_at(r, s + i, "a property must follow its element");
            if (ply_property(r, s, n, w) != 0)
                return -1;
        } else if (w - i == 10 && memcmp(s + i, "end_header", 10) == 0) {
            if (!format_seen)
                return ply_fail_at(r, s + i, "end_header before the format line");
            return 0;
        } else if (ply_warn_at(r, mesh, s + i, "an unknown header line, read as a comment "
                               "(the header's lines are format, comment, obj_info, element, "
                               "property and end_header)") != 0) {
            return -1;
        }
    }
    if (r->lineno == 0) {
        error_set(r->err, r->name, "the file is empty: a PLY file starts with the line 'ply'");
        return -1;
    }
    return ply_fail_at(r, r->line, "the header has no end_header line");
}

/* Says in *err that the data ends inside the element being read. */
static int ply_short(PlyReader *r)
{
    return ply_fail(r, "the file ends inside %s %zu of %zu (element '%s')",
                    strcmp(r->element->name, "face") == 0 ? "face" : "item", r->index + 1,
                    r->element->count, r->element->name);
}

/* Moves r past the blanks and line ends before the next ASCII token,
 * counting lines; returns the end of the token. */
static const char *ply_ascii_token(PlyReader *r)
{
    const char *e;

    while (r->p < r->end && (*r->p == ' ' || *r->p == '\t' || *r->p == '\r' || *r->p == '\n')) {
        if (*r->p == '\n') {
            r->lineno++;
            r->line = r->p + 1;
        }
        r->p++;
    }
    for (e = r->p; e < r->end && *e != ' ' && *e != '\t' && *e != '\r' && *e != '\n'; e++)
        ;
    return e;
}

/* Decodes the value of type t at p, in the reader's byte order. */
static double ply_decode(const PlyReader *r, PlyType t, const unsigned char *p)
{
    unsigned char b[8];
    int n = ply_types[t].size;
    uint64_t u = 0;

    for (int k = 0; k < n; k++)
        b[k] = p[r->format == PLY_BIG ? n - 1 - k : k];
    for (int k = n - 1; k >= 0; k--)
        u = u << 8 | b[k];
    switch (t) {
    case PLY_INT8: return (double)(int8_t)u;
    case PLY_UINT8: return (double)(uint8_t)u;
    case PLY_INT16: return (double)(int16_t)u;
    case PLY_UINT16: return (double)(uint16_t)u;
    case PLY_INT32: return (double)(int32_t)(uint32_t)u;
    case PLY_UINT32: return (double)(uint32_t)u;
    case PLY_FLOAT32: {
        uint32_t w = (uint32_t)u;
        float f;
        memcpy(&f, &w, sizeof f);
        return (double)f;
    }
    default: {
        double d;
        memcpy(&d, &u, sizeof d);
        return d;
    }
    }
}

/* Reads the next value, of type t, into *out. */
static int ply_value(PlyReader *r, PlyType t, double *out)
{
    if (r->format != PLY_ASCII) {
        if (r->end - r->p < ply_types[t].size)
            return ply_short(r);
        *out = ply_decode(r, t, (const unsigned char *)r->p);
        r->p += ply_types[t].size;
        return 0;
    }
    {
        const char *e = ply_ascii_token(r);
        r->token = r->p;
        if (e == r->p)
            return ply_short(r);
        if (number_parse(r->p, (size_t)(e - r->p), out) != NUMBER_OK)
            return ply_fail(r, "expected a number (%s), found '%.*s'", ply_types[t].name,
                            (int)(e - r->p > 30 ? 30 : e - r->p), r->p);
        if (t < PLY_FLOAT32 && (*out != floor(*out) || *out > ply_types[t].max ||
                                *out < (t % 2 ? 0 : -ply_types[t].max - 1)))
            return ply_fail(r, "expected a whole number that a %s holds, found '%.*s'",
                            ply_types[t].name, (int)(e - r->p > 30 ? 30 : e - r->p), r->p);
        r->p = e;
        return 0;
    }
}

/* Reads a list's count (of type t) into *n, checking that the file can
 * hold that many items of item_size bytes (2 in ASCII). */
static int ply_count(PlyReader *r, PlyType t, int item_size, size_t *n)
{
    double c;
    const char *at = r->p;

    if (ply_value(r, t, &c) != 0)
        return -1;
    if (c < 0 || c > (double)(r->end - r->p) / (r->format == PLY_ASCII ? 2 : item_size) +
                         (r->format == PLY_ASCII)) {
        r->p = r->format == PLY_ASCII ? r->token : at;
        return ply_fail(r, "the file ends inside %s %zu of %zu (element '%s'): a list of %.0f "
                        "items, more than the %zu bytes left hold",
                        strcmp(r->element->name, "face") == 0 ? "face" : "item", r->index + 1,
                        r->element->count, r->element->name, c, (size_t)(r->end - at));
    }
    *n = (size_t)c;
    return 0;
}

/* Makes room for `more` items of size bytes in *items (count of them now,
 * room for *cap) within the budget; returns 0, or -1 with the fault. */
static int ply_room(PlyReader *r, void **items, size_t *cap, size_t count, size_t more,
                    size_t size)
{
    size_t before = *cap;

    while (count + more > *cap) {
        size_t grown = grow_next_capacity(*cap);
        if (grown > SIZE_MAX / size ||
            (r->max_bytes && (grown - before) * size > r->max_bytes - r->used))
            return ply_fail(r, "the mesh needs more memory than the memory limit leaves it");
        if (grow_reserve(items, cap, *cap, size) != 0)
            return ply_fail(r, "out of memory");
    }
    r->used += (*cap - before) * size;
    return 0;
}

/* Reads a face's list of n corners into triangles of mesh: a fan, noted
 * for mesh_file_cut() when it has more than three. */
static int ply_face(PlyReader *r, const PlyProperty *p, size_t n, MeshFile *mesh,
                    const PlyElement *vertex)
{
    size_t vertices = vertex ? vertex->count : 0;
    int uv = vertex && vertex->has[PLY_U] && vertex->has[PLY_V];
    int normals = vertex && vertex->has[PLY_NX] && vertex->has[PLY_NY] && vertex->has[PLY_NZ];

    if (n < 3) {
        if (r->format == PLY_ASCII)
            r->p = r->token; /* at the count */
        return ply_fail(r, "a face needs at least 3 corners, found %zu", n);
    }
    if (ply_room(r, (void **)&r->corners, &r->corner_capacity, 0, n, sizeof *r->corners) != 0 ||
        ply_room(r, (void **)&mesh->tri, &r->caps[0], mesh->tri_count, n - 2,
                 sizeof *mesh->tri) != 0)
        return -1;
    for (size_t k = 0; k < n; k++) {
        double v;
        const char *at = r->p;
        if (ply_value(r, p->type, &v) != 0)
            return -1;
        if (!(v >= 0 && v < (double)vertices)) {
            r->p = r->format == PLY_ASCII ? r->token : at;
            return ply_fail(r, "vertex %.0f does not exist (the file has %zu vertices)", v,
                            vertices);
        }
        r->corners[k].v = (long)v;
        r->corners[k].vt = uv ? (long)v : -1;
        r->corners[k].vn = normals ? (long)v : -1;
    }
    if (n > 3) {
        if (ply_room(r, (void **)&mesh->polygons, &r->caps[1], mesh->polygon_count, 1,
                     sizeof *mesh->polygons) != 0)
            return -1;
        mesh->polygons[mesh->polygon_count][0] = mesh->tri_count;
        mesh->polygons[mesh->polygon_count][1] = n;
        mesh->polygon_count++;
    }
    for (size_t k = 2; k < n; k++) {
        mesh->tri[mesh->tri_count][0] = r->corners[0];
        mesh->tri[mesh->tri_count][1] = r->corners[k - 1];
        mesh->tri[mesh->tri_count][2] = r->corners[k];
        mesh->tri_count++;
    }
    return 0;
}

/* Returns the fewest bytes an item of e takes in the data. */
static size_t ply_least(const PlyReader *r, const PlyElement *e)
{
    size_t n = 0;

    for (int k = 0; k < e->prop_count; k++)
        n += r->format == PLY_ASCII ? 2
                                    : (size_t)ply_types[e->props[k].list ? e->props[k].count_type
                                                                         : e->props[k].type].size;
    return n;
}

/* Passes over a list of property p (its count read first). */
static int ply_skip_list(PlyReader *r, const PlyProperty *p)
{
    size_t n = 0;
    double v;

    if (ply_count(r, p->count_type, ply_types[p->type].size, &n) != 0)
        return -1;
    if (r->format != PLY_ASCII) {
        r->p += n * (size_t)ply_types[p->type].size;
        return 0;
    }
    for (size_t k = 0; k < n; k++)
        if (ply_value(r, p->type, &v) != 0)
            return -1;
    return 0;
}

/* Sizes mesh's vertex arrays for e, the vertex element, within the
 * budget; returns 0 or -1. */
static int ply_vertex_arrays(PlyReader *r, const PlyElement *e, MeshFile *mesh)
{
    int normals = e->has[PLY_NX] && e->has[PLY_NY] && e->has[PLY_NZ];
    int uv = e->has[PLY_U] && e->has[PLY_V];
    int colours = e->has[PLY_RED] && e->has[PLY_GREEN] && e->has[PLY_BLUE];
    size_t each = sizeof *mesh->v + (normals ? sizeof *mesh->vn : 0) +
                  (uv ? sizeof *mesh->vt : 0) + (colours ? sizeof *mesh->vc : 0);

    if (e->count > SIZE_MAX / each || (r->max_bytes && e->count * each > r->max_bytes))
        return ply_fail(r, "%zu vertices need more memory than the memory limit leaves the mesh",
                        e->count);
    mesh->v = malloc(e->count * sizeof *mesh->v + 1);
    mesh->vn = normals ? malloc(e->count * sizeof *mesh->vn + 1) : NULL;
    mesh->vt = uv ? malloc(e->count * sizeof *mesh->vt + 1) : NULL;
    mesh->vc = colours ? malloc(e->count * sizeof *mesh->vc + 1) : NULL;
    if (!mesh->v || (normals && !mesh->vn) || (uv && !mesh->vt) || (colours && !mesh->vc))
        return ply_fail(r, "out of memory for %zu vertices", e->count);
    r->used += e->count * each;
    mesh->v_count = e->count;
    mesh->vn_count = normals ? e->count : 0;
    mesh->vt_count = uv ? e->count : 0;
    return 0;
}

/* Reads vertex i of e into mesh. */
static int ply_vertex(PlyReader *r, const PlyElement *e, size_t i, MeshFile *mesh)
{
    double val[PLY_ROLES] = {0};
    const char *start = r->p;

    if (r->format == PLY_ASCII) {
        ply_ascii_token(r); /* the vertex's first number */
        start = r->p;
    }

    for (int k = 0; k < e->prop_count; k++) {
        const PlyProperty *p = &e->props[k];
        double v;
        if (p->list) {
            if (ply_skip_list(r, p) != 0)
                return -1;
            continue;
        }
        if (ply_value(r, p->type, &v) != 0)
            return -1;
        if (p->role >= PLY_RED && p->role <= PLY_BLUE)
            v = p->type >= PLY_FLOAT32 ? 255 * v : 255 * v / ply_types[p->type].max;
        if (p->role != PLY_NONE)
            val[p->role] = v;
    }
    if (!isfinite(val[PLY_X]) || !isfinite(val[PLY_Y]) || !isfinite(val[PLY_Z])) {
        r->p = start;
        return ply_fail(r, "vertex %zu is not at a finite place", i + 1);
    }
    mesh->v[i] = vec3(val[PLY_X], val[PLY_Y], val[PLY_Z]);
    if (mesh->vn)
        mesh->vn[i] = vec3(val[PLY_NX], val[PLY_NY], val[PLY_NZ]);
    if (mesh->vt) {
        mesh->vt[i][0] = val[PLY_U];
        mesh->vt[i][1] = val[PLY_V];
    }
    if (mesh->vc)
        for (int c = 0; c < 3; c++) {
            double x = val[PLY_RED + c];
            mesh->vc[i][c] = (float)(x > 255 ? 255 : x > 0 ? x : 0);
        }
    return 0;
}

/* Reads item i of element e (the mesh's vertices when it is vertex, its
 * faces when it is face). */
static int ply_item(PlyReader *r, const PlyElement *e, const PlyElement *vertex,
                    const PlyElement *face, size_t i, MeshFile *mesh)
{
    if (e == vertex)
        return ply_vertex(r, e, i, mesh);
    for (int k = 0; k < e->prop_count; k++) {
        const PlyProperty *p = &e->props[k];
        double v;
        size_t n = 0;
        if (e == face && p->role == PLY_INDICES) {
            if (ply_count(r, p->count_type, ply_types[p->type].size, &n) != 0 ||
                ply_face(r, p, n, mesh, vertex) != 0)
                return -1;
        } else if (p->list) {
            if (ply_skip_list(r, p) != 0)
                return -1;
        } else if (ply_value(r, p->type, &v) != 0) {
            return -1;
        }
    }
    return 0;
}

/* Returns the first element named name, or NULL. */
static const PlyElement *ply_named(const PlyReader *r, const char *name)
{
    for (int k = 0; k < r->element_count; k++)
        if (strcmp(r->elements[k].name, name) == 0)
            return &r->elements[k];
    return NULL;
}

/* Reads the data after the header into mesh. */
static int ply_data(PlyReader *r, MeshFile *mesh)
{
    const PlyElement *vertex = ply_named(r, "vertex"), *face = ply_named(r, "face");

    if (vertex && !(vertex->has[PLY_X] && vertex->has[PLY_Y] && vertex->has[PLY_Z]))
        return ply_fail_at(r, r->line, "the element 'vertex' has no property x, y or z");
    if (r->format == PLY_ASCII) {
        r->line = r->p;
        r->lineno++;
    }
    for (int k = 0; k < r->element_count; k++) {
        const PlyElement *e = &r->elements[k];
        r->element = e;
        r->index = 0;
        if (e->prop_count == 0)
            continue; /* nothing to read, however many */
        if (e->count > (size_t)(r->end - r->p) / ply_least(r, e) + (r->format == PLY_ASCII))
            return ply_fail(r, "the header declares %zu item%s of the element '%s': more than "
                            "the %zu byte%s left hold", e->count, e->count == 1 ? "" : "s",
                            e->name, (size_t)(r->end - r->p), r->end - r->p == 1 ? "" : "s");
        if (e == vertex && ply_vertex_arrays(r, e, mesh) != 0)
            return -1;
        for (r->index = 0; r->index < e->count; r->index++)
            if (ply_item(r, e, vertex, face, r->index, mesh) != 0)
                return -1;
    }
    if (r->format == PLY_ASCII)
        ply_ascii_token(r);
    if (r->p < r->end)
        return ply_fail(r, "more data after the elements the header declares");
    return 0;
}

int ply_parse(const char *name, const char *data, size_t len, size_t max_bytes, MeshFile *mesh,
              Error *err)
{
    static const char *const formats[] = {"PLY (ASCII)", "PLY (binary, little-endian)",
                                          "PLY (binary, big-endian)"};
    PlyReader r;
    int rc;

    memset(&r, 0, sizeof r);
    r.name = name;
    r.data = data;
    r.end = data + len;
    r.max_bytes = max_bytes;
    r.err = err;
    mesh_file_init(mesh);
    rc = ply_header(&r, mesh) != 0 || ply_data(&r, mesh) != 0 ? -1 : 0;
    free(r.corners);
    if (rc != 0) {
        mesh_file_free(mesh);
        return -1;
    }
    mesh->format = formats[r.format];
    return 0;
}
