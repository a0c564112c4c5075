/* obj.c: Wavefront OBJ reading (see obj.h). */
#include "scenefile/obj.h"

#include <limits.h>
#include <stdarg.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>

#include "base/file.h"
#include "base/grow.h"
#include "base/hash.h"
#include "base/threads.h"
#include "math/number.h"
#include "scenefile/lex.h"

/* Where the reader is: the file and the line being read. */
typedef struct {
    const char *name;  /* file name for messages */
    const char *line;  /* first byte of the line */
    size_t len;        /* bytes, without the line ending */
    int lineno;        /* 1-based */
    Error *err;
    size_t max_bytes;  /* the most the mesh's arrays may take; 0: no limit */
    size_t used;       /* bytes they take now */
    int fixed;         /* 1: the arrays were sized beforehand and do not grow
                          (a part of a reading shared by threads) */
} ObjReader;

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

size_t obj_memory(const ObjMesh *mesh)
{
    return mesh->v_count * sizeof *mesh->v + mesh->vt_count * sizeof *mesh->vt +
           mesh->vn_count * sizeof *mesh->vn + mesh->tri_count * sizeof *mesh->tri;
}

void obj_free(ObjMesh *mesh)
{
    free(mesh->v);
    free(mesh->vt);
    free(mesh->vn);
    free(mesh->tri);
    memset(mesh, 0, sizeof *mesh);
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
static int obj_corner(ObjReader *r, const ObjMesh *m, size_t start, size_t end, ObjCorner *c)
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

/* f -> corner corner corner corner*: a fan of triangles from the first. */
static int obj_face(ObjReader *r, ObjMesh *m, size_t i, size_t *tri_cap)
{
    ObjCorner first, prev, c;
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
            if (obj_reserve(r, (void **)&m->tri, tri_cap, m->tri_count, sizeof *m->tri, i,
                            "triangles") != 0)
                return -1;
            m->tri[m->tri_count][0] = first;
            m->tri[m->tri_count][1] = prev;
            m->tri[m->tri_count][2] = c;
            m->tri_count++;
        }
        prev = c;
        n++;
        i = e;
    }
    if (n < 3)
        return obj_fail(r, i, "a face needs at least 3 corners, found %d", n);
    return 0;
}

/* Reads one line's record. */
static int obj_record(ObjReader *r, ObjMesh *m, size_t caps[4])
{
    static const char *const ignored[] = {"o", "g", "s", "usemtl", "mtllib", "l", "p"};
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
        return obj_face(r, m, i, &caps[3]);
    } else {
        for (size_t k = 0; k < sizeof ignored / sizeof ignored[0]; k++)
            if (n == strlen(ignored[k]) && memcmp(word, ignored[k], n) == 0)
                return 0;
        return obj_fail(r, kw, "unsupported OBJ record '%.*s' (read: v, vt, vn, f; ignored: o, "
                               "g, s, usemtl, mtllib, l, p)",
                        (int)(n > 40 ? 40 : n), word);
    }
    return 0;
}

int obj_load(const char *path, size_t max_bytes, ObjMesh *mesh, Error *err)
{
    char *data;
    size_t len;
    int rc;

    memset(mesh, 0, sizeof *mesh);
    if (file_read_all(path, &data, &len, err) != 0)
        return -1;
    rc = obj_parse(file_display_name(path), data, len, max_bytes, mesh, err);
    mesh->hash = hash_bytes(HASH_START, data, len);
    free(data);
    return rc;
}

/* Reads the lines from p to end into m (caps: its arrays' capacities);
 * lines are searched for NUL bytes and carriage returns when odd. Returns
 * 0, or -1 with the fault recorded. */
static int obj_parse_lines(ObjReader *r, ObjMesh *m, size_t caps[4], const char *p,
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

/* What a part of the file holds, counted before it is read. */
typedef struct {
    const char *start, *end; /* its lines */
    size_t lines;            /* line endings */
    size_t count[4];         /* v, vt, vn records and triangles */
} ObjPart;

/* Counts the lines of part and the records they hold, as obj_record()
 * would read them if they are right (a wrong one is found when read). */
static void obj_count(ObjPart *part)
{
    const char *p = part->start, *end = part->end;

    memset(part->count, 0, sizeof part->count);
    part->lines = 0;
    while (p < end) {
        const char *eol = memchr(p, '\n', (size_t)(end - p)), *hash;
        ObjReader r = {0};
        size_t i = 0, e, n;

        r.line = p;
        r.len = (size_t)((eol ? eol : end) - p);
        p = eol ? eol + 1 : end;
        part->lines += eol != NULL;
        hash = memchr(r.line, '#', r.len);
        if (hash)
            r.len = (size_t)(hash - r.line);
        e = obj_token(&r, &i);
        n = e - i;
        if (n == 1 && r.line[i] == 'v') {
            part->count[0]++;
        } else if (n == 2 && r.line[i] == 'v') {
            part->count[1] += r.line[i + 1] == 't';
            part->count[2] += r.line[i + 1] == 'n';
        } else if (n == 1 && r.line[i] == 'f') {
            size_t corners = 0;
            for (i = e; (e = obj_token(&r, &i)) > i; i = e)
                corners++;
            part->count[3] += corners > 2 ? corners - 2 : 0;
        }
    }
}

/* Returns the capacity a growing array reaches for count items. */
static size_t obj_grown(size_t count)
{
    size_t cap = 0;

    while (cap < count)
        cap = grow_next_capacity(cap);
    return cap;
}

enum {
    OBJ_PARALLEL_MIN = 1 << 20, /* smaller files are read on one thread */
    OBJ_PARTS_MAX = 64
};

/* Reads the len bytes at p (no NUL byte nor carriage return in them) into
 * *mesh with threads threads: the parts are counted, the arrays sized,
 * then each part read into its place. Returns 0, or -1 (mesh empty) when
 * anything is wrong or out of the budget: the serial reading then says
 * what, as it would have. */
static int obj_parse_parallel(const char *name, const char *p, size_t len, size_t max_bytes,
                              int threads, ObjMesh *mesh)
{
    static const size_t sizes[4] = {sizeof *mesh->v, sizeof *mesh->vt, sizeof *mesh->vn,
                                    sizeof *mesh->tri};
    ObjPart parts[OBJ_PARTS_MAX];
    const char *cut[OBJ_PARTS_MAX + 1];
    size_t total[4] = {0, 0, 0, 0}, used = 0;
    int n = threads < OBJ_PARTS_MAX ? threads : OBJ_PARTS_MAX, failed = 0;

    lex_split(p, len, n, cut);
    for (int k = 0; k < n; k++) {
        parts[k].start = cut[k];
        parts[k].end = cut[k + 1];
    }
#ifdef _OPENMP
#pragma omp parallel for num_threads(n) schedule(static, 1)
#endif
    for (int k = 0; k < n; k++)
        obj_count(&parts[k]);
    for (int k = 0; k < n; k++)
        for (int a = 0; a < 4; a++)
            total[a] += parts[k].count[a];
    for (int a = 0; a < 4; a++)
        used += obj_grown(total[a]) * sizes[a]; /* what the serial reading takes */
    if (max_bytes && used > max_bytes)
        return -1;
    memset(mesh, 0, sizeof *mesh);
    if ((total[0] && !(mesh->v = malloc(total[0] * sizes[0]))) ||
        (total[1] && !(mesh->vt = malloc(total[1] * sizes[1]))) ||
        (total[2] && !(mesh->vn = malloc(total[2] * sizes[2]))) ||
        (total[3] && !(mesh->tri = malloc(total[3] * sizes[3])))) {
        obj_free(mesh);
        return -1;
    }
#ifdef _OPENMP
#pragma omp parallel for num_threads(n) schedule(static, 1) reduction(| : failed)
#endif
    for (int k = 0; k < n; k++) {
        /* Part k's records go after those of the parts before it. */
        ObjMesh view = *mesh;
        size_t caps[4], *counts[4] = {&view.v_count, &view.vt_count, &view.vn_count,
                                      &view.tri_count};
        ObjReader r = {name, NULL, 0, 0, NULL, 0, 0, 1};
        Error err;
        r.err = &err;
        for (int j = 0; j < k; j++)
            r.lineno += (int)parts[j].lines;
        for (int a = 0; a < 4; a++) {
            *counts[a] = 0;
            for (int j = 0; j < k; j++)
                *counts[a] += parts[j].count[a];
            caps[a] = *counts[a] + parts[k].count[a];
        }
        if (obj_parse_lines(&r, &view, caps, parts[k].start, parts[k].end, 0) != 0)
            failed = 1;
        for (int a = 0; a < 4; a++)
            failed |= *counts[a] != caps[a];
    }
    if (failed) {
        obj_free(mesh);
        return -1;
    }
    mesh->v_count = total[0];
    mesh->vt_count = total[1];
    mesh->vn_count = total[2];
    mesh->tri_count = total[3];
    return 0;
}

int obj_parse(const char *name, const char *data, size_t len, size_t max_bytes, ObjMesh *mesh,
              Error *err)
{
    size_t caps[4] = {0, 0, 0, 0};
    const char *p = data, *end = data + len;
    ObjReader r = {name, NULL, 0, 0, err, max_bytes, 0, 0};
    int odd, threads = threads_count();

    memset(mesh, 0, sizeof *mesh);
    if (len >= 3 && memcmp(p, "\xEF\xBB\xBF", 3) == 0)
        p += 3;
    /* Lines are searched for NUL bytes and carriage returns only when the
     * file holds some; a large file without them is read by every thread. */
    odd = memchr(p, '\0', (size_t)(end - p)) || memchr(p, '\r', (size_t)(end - p));
    if (!odd && threads > 1 && (size_t)(end - p) >= OBJ_PARALLEL_MIN &&
        obj_parse_parallel(name, p, (size_t)(end - p), max_bytes, threads, mesh) == 0)
        return 0;
    if (obj_parse_lines(&r, mesh, caps, p, end, odd) != 0) {
        obj_free(mesh);
        return -1;
    }
    return 0;
}
