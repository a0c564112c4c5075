/* obj_lines.c: the lines of an OBJ file (see obj_read.h). */
#include "obj_read.h"

#include <limits.h>
#include <stdarg.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>

#include "base/grow.h"
#include "math/number.h"

/* Records a fault at byte offset `at` of the current line. */
static int obj_fail(ObjReader *r, size_t at, const char *fmt, ...)
{
    char msg[ERROR_MESSAGE_MAX];
    va_list ap;

    va_start(ap, fmt);
    vsnprintf(msg, sizeof msg, fmt, ap);
    va_end(ap);
    error_set_at(r->err, r->name, r->lineno, (int)at + 1, r->line, r->len, "%s", msg);
    return -1;
}

void obj_names_free(ObjNames *n)
{
    for (size_t i = 0; i < n->count; i++)
        free(n->mats[i].name);
    for (size_t i = 0; i < n->lib_count; i++)
        free(n->libs[i].name);
    free(n->mats);
    free(n->libs);
    memset(n, 0, sizeof *n);
}

static int obj_blank(char c)
{
    return c == ' ' || c == '\t';
}

/* Moves *i past blanks; returns the token's end (start *i) or *i at the
 * end of the line. */
static size_t obj_token(const ObjReader *r, size_t *i)
{
    size_t e;

    while (*i < r->len && obj_blank(r->line[*i]))
        (*i)++;
    e = *i;
    while (e < r->len && !obj_blank(r->line[e]))
        e++;
    return e;
}

/* Reads up to max numbers after position *i into out; at least min of
 * them. Returns how many, or -1 with the fault recorded. */
static int obj_numbers(ObjReader *r, size_t *i, const char *what, int min, int max, double *out)
{
    int n = 0;

    for (;;) {
        size_t e = obj_token(r, i);
        double v = 0;
        if (e == *i)
            break;
        if (number_parse(r->line + *i, e - *i, &v) != NUMBER_OK)
            return obj_fail(r, *i, "expected a number for %s, found '%.*s'", what,
                            (int)(e - *i > 40 ? 40 : e - *i), r->line + *i);
        if (n < max)
            out[n] = v;
        n++;
        *i = e;
    }
    if (n < min)
        return obj_fail(r, *i, "expected at least %d numbers for %s, found %d", min, what, n);
    return n < max ? n : max;
}

/* Reads a signed index at *p (up to end) into *out; returns 0 or -1. */
static int obj_index(const char **p, const char *end, long *out)
{
    const char *s = *p;
    long v = 0;
    int neg = 0, digits = 0;

    if (s < end && *s == '-') {
        neg = 1;
        s++;
    }
    for (; s < end && *s >= '0' && *s <= '9'; s++, digits++) {
        if (v > (LONG_MAX - 9) / 10)
            return -1;
        v = v * 10 + (*s - '0');
    }
    if (!digits)
        return -1;
    *out = neg ? -v : v;
    *p = s;
    return 0;
}

/* Turns a 1-based or negative OBJ index into a 0-based one among count;
 * returns -1 when it names nothing. */
static long obj_resolve(long i, size_t count)
{
    if (i > 0 && (size_t)i <= count)
        return i - 1;
    if (i < 0 && (size_t)-i <= count)
        return (long)count + i;
    return -1;
}

/* corner -> v | v '/' vt | v '//' vn | v '/' vt '/' vn */
static int obj_corner(ObjReader *r, const MeshFile *m, size_t start, size_t end, MeshCorner *c)
{
    const char *p = r->line + start, *e = r->line + end;
    long raw;

    c->vt = c->vn = -1;
    if (obj_index(&p, e, &raw) != 0)
        return obj_fail(r, start, "expected a face corner (v, v/vt, v//vn or v/vt/vn), found "
                                  "'%.*s'", (int)(end - start > 40 ? 40 : end - start),
                        r->line + start);
    if ((c->v = obj_resolve(raw, m->v_count)) < 0)
        return obj_fail(r, start, "vertex %ld does not exist (%zu vertices so far)", raw,
                        m->v_count);
    if (p < e && *p == '/') {
        p++;
        if (p < e && *p != '/') {
            size_t at = (size_t)(p - r->line);
            if (obj_index(&p, e, &raw) != 0)
                return obj_fail(r, at, "expected a texture coordinate index after '/'");
            if ((c->vt = obj_resolve(raw, m->vt_count)) < 0)
                return obj_fail(r, at, "texture coordinate %ld does not exist (%zu so far)",
                                raw, m->vt_count);
        }
        if (p < e && *p == '/') {
            size_t at = (size_t)(++p - r->line);
            if (obj_index(&p, e, &raw) != 0)
                return obj_fail(r, at, "expected a normal index after '/'");
            if ((c->vn = obj_resolve(raw, m->vn_count)) < 0)
                return obj_fail(r, at, "normal %ld does not exist (%zu so far)", raw,
                                m->vn_count);
        }
    }
    if (p != e)
        return obj_fail(r, (size_t)(p - r->line), "unexpected '%c' in a face corner", *p);
    return 0;
}

/* Makes room for one more item of size bytes in *items (count of them in
 * *capacity), within r's byte budget; returns 0, or -1 with the fault
 * recorded at byte `at` (what: the items, for the message). */
static int obj_reserve(ObjReader *r, void **items, size_t *capacity, size_t count, size_t size,
                       size_t at, const char *what)
{
    size_t before = *capacity, more;

    if (count < before)
        return 0;
    if (r->fixed)
        return -1; /* the lines were counted wrong: the caller reads again */
    more = grow_next_capacity(before) - before;
    if (r->max_bytes && (more > SIZE_MAX / size || more * size > r->max_bytes - r->used)) {
        char left[NUMBER_FORMAT_MAX];
        return obj_fail(r, at, "the mesh needs more memory than the %s the memory limit "
                               "leaves it, after %zu %s",
                        number_bytes(left, r->max_bytes), count, what);
    }
    if (grow_reserve(items, capacity, count, size) != 0)
        return obj_fail(r, at, "out of memory after %zu %s", count, what);
    r->used += (*capacity - before) * size;
    return 0;
}

/* obj_reserve() for the reader's own lists (its names and libraries),
 * which grow even in a part whose mesh arrays are fixed. */
static int obj_reserve_own(ObjReader *r, void **items, size_t *capacity, size_t count,
                           size_t size, size_t at, const char *what)
{
    int fixed = r->fixed, rc;

    r->fixed = 0;
    rc = obj_reserve(r, items, capacity, count, size, at, what);
    r->fixed = fixed;
    return rc;
}

/* Makes room for one more triangle in m (its material too, when the file
 * gives materials); caps: the arrays' capacities. */
static int obj_room_triangle(ObjReader *r, MeshFile *m, size_t caps[OBJ_CAPS], size_t at)
{
    size_t mat_cap = caps[4];

    if (obj_reserve(r, (void **)&m->tri, &caps[3], m->tri_count, sizeof *m->tri, at,
                    "triangles") != 0)
        return -1;
    if (!m->tri_material || mat_cap >= caps[3])
        return 0;
    if (obj_reserve(r, (void **)&m->tri_material, &caps[4], caps[3] - 1, sizeof *m->tri_material,
                    at, "triangles") != 0)
        return -1;
    /* grow_reserve() doubles: reach the triangles' capacity. */
    while (caps[4] < caps[3])
        if (obj_reserve(r, (void **)&m->tri_material, &caps[4], caps[4], sizeof *m->tri_material,
                        at, "triangles") != 0)
            return -1;
    return 0;
}

/* f -> corner corner corner corner*: a fan from the first, the face noted
 * when it has more than three corners (mesh_file_cut() cuts it). */
static int obj_face(ObjReader *r, MeshFile *m, size_t i, size_t caps[OBJ_CAPS])
{
    MeshCorner first, prev, c;
    size_t start = m->tri_count;
    int n = 0;

    for (;;) {
        size_t e = obj_token(r, &i);
        if (e == i)
            break;
        if (obj_corner(r, m, i, e, &c) != 0)
            return -1;
        if (n == 0) {
            first = c;
        } else if (n >= 2) {
            if (obj_room_triangle(r, m, caps, i) != 0)
                return -1;
            m->tri[m->tri_count][0] = first;
            m->tri[m->tri_count][1] = prev;
            m->tri[m->tri_count][2] = c;
            if (m->tri_material)
                m->tri_material[m->tri_count] = r->names.current;
            m->tri_count++;
        }
        prev = c;
        n++;
        i = e;
    }
    if (n < 3)
        return obj_fail(r, i, "a face needs at least 3 corners, found %d", n);
    if (n > 3) {
        if (obj_reserve(r, (void **)&m->polygons, &caps[5], m->polygon_count,
                        sizeof *m->polygons, i, "faces") != 0)
            return -1;
        m->polygons[m->polygon_count][0] = r->tri_base + start;
        m->polygons[m->polygon_count][1] = (size_t)n;
        m->polygon_count++;
    }
    return 0;
}

/* Returns the rest of the line from *i, its blanks at both ends left out,
 * as its start in *i and its length. */
static size_t obj_rest(const ObjReader *r, size_t *i)
{
    size_t e = r->len;

    while (*i < e && obj_blank(r->line[*i]))
        (*i)++;
    while (e > *i && obj_blank(r->line[e - 1]))
        e--;
    return e - *i;
}

/* usemtl -> 'usemtl' name: the faces after it take that material (the
 * rest of the line; none: the default). */
static int obj_usemtl(ObjReader *r, MeshFile *m, size_t i, size_t caps[OBJ_CAPS])
{
    ObjNames *nm = &r->names;
    size_t n = obj_rest(r, &i), k;

    if (!m->tri_material && !r->fixed) {
        /* Every triangle so far has the default. */
        if (obj_reserve(r, (void **)&m->tri_material, &caps[4], 0, sizeof *m->tri_material, i,
                        "triangles") != 0)
            return -1;
        while (caps[4] < caps[3])
            if (obj_reserve(r, (void **)&m->tri_material, &caps[4], caps[4],
                            sizeof *m->tri_material, i, "triangles") != 0)
                return -1;
        for (size_t t = 0; t < m->tri_count; t++)
            m->tri_material[t] = OBJ_DEFAULT;
    }
    if (n == 0) {
        nm->current = OBJ_DEFAULT;
        return 0;
    }
    for (k = 0; k < nm->count; k++)
        if (strlen(nm->mats[k].name) == n && memcmp(nm->mats[k].name, r->line + i, n) == 0)
            break;
    if (k == nm->count) {
        char *name;
        if (obj_reserve_own(r, (void **)&nm->mats, &nm->capacity, nm->count, sizeof *nm->mats,
                            i, "materials") != 0)
            return -1;
        if (!(name = malloc(n + 1)))
            return obj_fail(r, i, "out of memory");
        memcpy(name, r->line + i, n);
        name[n] = '\0';
        mesh_material_default(&nm->mats[k], name);
        nm->mats[k].used_at = r->line;
        nm->mats[k].used_len = r->len;
        nm->mats[k].used_line = r->lineno;
        nm->mats[k].used_column = (int)i + 1;
        nm->count++;
    }
    nm->current = (uint32_t)k;
    return 0;
}

/* mtllib -> 'mtllib' name+: the libraries, noted for obj_load(). */
static int obj_mtllib(ObjReader *r, size_t i)
{
    ObjNames *nm = &r->names;
    size_t n = obj_rest(r, &i);
    MtlLibrary *lib;

    if (n == 0)
        return obj_fail(r, i, "expected the name of a material library (MTL file) after "
                              "mtllib");
    if (obj_reserve_own(r, (void **)&nm->libs, &nm->lib_capacity, nm->lib_count,
                        sizeof *nm->libs, i, "material libraries") != 0)
        return -1;
    lib = &nm->libs[nm->lib_count];
    if (!(lib->name = malloc(n + 1)))
        return obj_fail(r, i, "out of memory");
    memcpy(lib->name, r->line + i, n);
    lib->name[n] = '\0';
    error_set_at(&lib->at, r->name, r->lineno, (int)i + 1, r->line, r->len, "%s", "");
    nm->lib_count++;
    return 0;
}

/* Reads one line's record; caps: the arrays' capacities (v, vt, vn,
 * triangles, their materials, faces noted). */
static int obj_record(ObjReader *r, MeshFile *m, size_t caps[OBJ_CAPS])
{
    static const char *const ignored[] = {"o", "g", "s", "l", "p"};
    size_t i = 0, e = obj_token(r, &i), kw = i, n = e - i;
    const char *word = r->line + i;
    double val[4];

    if (n == 0)
        return 0;
    i = e;
    if (n == 1 && word[0] == 'v') {
        if (obj_numbers(r, &i, "a vertex (x y z)", 3, 3, val) < 0)
            return -1;
        if (obj_reserve(r, (void **)&m->v, &caps[0], m->v_count, sizeof *m->v, kw,
                        "vertices") != 0)
            return -1;
        m->v[m->v_count++] = vec3(val[0], val[1], val[2]);
    } else if (n == 2 && memcmp(word, "vt", 2) == 0) {
        int k = obj_numbers(r, &i, "a texture coordinate (u [v [w]])", 1, 3, val);
        if (k < 0)
            return -1;
        if (obj_reserve(r, (void **)&m->vt, &caps[1], m->vt_count, sizeof *m->vt, kw,
                        "texture coordinates") != 0)
            return -1;
        m->vt[m->vt_count][0] = val[0];
        m->vt[m->vt_count][1] = k > 1 ? val[1] : 0;
        m->vt_count++;
    } else if (n == 2 && memcmp(word, "vn", 2) == 0) {
        size_t at = i;
        int k = obj_numbers(r, &i, "a normal (x y z)", 3, 4, val);
        if (k < 0)
            return -1;
        if (k > 3) {
            /* Point at the fourth number. */
            for (int skip = 0; skip < 3; skip++)
                at = obj_token(r, &at);
            obj_token(r, &at);
            return obj_fail(r, at, "a normal has 3 numbers (x y z), found more");
        }
        if (obj_reserve(r, (void **)&m->vn, &caps[2], m->vn_count, sizeof *m->vn, kw,
                        "normals") != 0)
            return -1;
        m->vn[m->vn_count++] = vec3(val[0], val[1], val[2]);
    } else if (n == 1 && word[0] == 'f') {
        return obj_face(r, m, i, caps);
    } else if (n == 6 && memcmp(word, "usemtl", 6) == 0) {
        return obj_usemtl(r, m, i, caps);
    } else if (n == 6 && memcmp(word, "mtllib", 6) == 0) {
        return obj_mtllib(r, i);
    } else {
        for (size_t k = 0; k < sizeof ignored / sizeof ignored[0]; k++)
            if (n == strlen(ignored[k]) && memcmp(word, ignored[k], n) == 0)
                return 0;
        return obj_fail(r, kw, "unsupported OBJ record '%.*s' (read: v, vt, vn, f, usemtl, "
                               "mtllib; ignored: o, g, s, l, p)",
                        (int)(n > 40 ? 40 : n), word);
    }
    return 0;
}

int obj_parse_lines(ObjReader *r, MeshFile *m, size_t caps[OBJ_CAPS], const char *p,
                    const char *end, int odd)
{
    int rc = 0;

    while (p < end && rc == 0) {
        const char *eol = memchr(p, '\n', (size_t)(end - p)), *hash;
        r->line = p;
        r->len = (size_t)((eol ? eol : end) - p);
        r->lineno++;
        p = eol ? eol + 1 : end;
        if (r->len > 0 && r->line[r->len - 1] == '\r')
            r->len--;
        for (size_t i = 0; odd && i < r->len; i++) {
            if (r->line[i] == '\0' || r->line[i] == '\r') {
                rc = obj_fail(r, i, r->line[i] ? "carriage return inside a line"
                                                : "NUL byte: an OBJ file is 8-bit text (is it "
                                                  "UTF-16?)");
                break;
            }
        }
        if (rc != 0)
            break;
        hash = memchr(r->line, '#', r->len);
        if (hash)
            r->len = (size_t)(hash - r->line);
        rc = obj_record(r, m, caps);
    }
    return rc;
}

