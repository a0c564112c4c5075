/* mtl.c: Wavefront MTL material libraries (see mtl.h). */
#include "scenefile/mtl.h"

#include <stdarg.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>

#include "base/file.h"
#include "base/hash.h"
#include "base/path.h"
#include "math/number.h"

/* Where the reader is. */
typedef struct {
    const char *name;     /* the library, for messages and its textures */
    const char *line;     /* the line, its blanks at the end left out */
    size_t len;
    int lineno;
    MeshFile *mesh;
    MeshMaterial *current; /* the material being described, or NULL */
    int failed;           /* memory ran out */
    int said_map_d;       /* map_d's warning was given */
} MtlReader;

/* Statements of the format and its extensions that change nothing here. */
static const char *const mtl_passed[] = {
    "Ke", "Tf", "Pr", "Pm", "Ps", "Pc", "Pcr", "aniso", "anisor", "norm", "bump", "map_bump",
    "map_Bump", "map_Ka", "map_Ks", "map_Ns", "map_Ke", "map_Pr", "map_Pm", "map_Ps", "disp",
    "decal", "refl", "sharpness", "map_aat", "map_refl", "Km"};

/* Warns, at byte `at` of the current line, of what the reader assumed. */
static void mtl_warn(MtlReader *r, size_t at, const char *fmt, ...)
{
    char msg[ERROR_MESSAGE_MAX];
    Error w;
    va_list ap;

    va_start(ap, fmt);
    vsnprintf(msg, sizeof msg, fmt, ap);
    va_end(ap);
    error_set_at(&w, r->name, r->lineno, (int)at + 1, r->line, r->len, "%s", msg);
    if (mesh_file_warn(r->mesh, &w) != 0)
        r->failed = 1;
}

static int mtl_blank(char c)
{
    return c == ' ' || c == '\t';
}

/* Moves *i past blanks; returns the end of the token that starts there. */
static size_t mtl_token(const MtlReader *r, size_t *i)
{
    size_t e;

    while (*i < r->len && mtl_blank(r->line[*i]))
        (*i)++;
    for (e = *i; e < r->len && !mtl_blank(r->line[e]); e++)
        ;
    return e;
}

/* Says whether a token follows position i on the line. */
static int mtl_more(const MtlReader *r, size_t i)
{
    return mtl_token(r, &i) > i;
}

/* Reads up to max numbers from *i into v; returns how many (the first
 * token that is not one ends them, *i left on it). */
static int mtl_numbers(const MtlReader *r, size_t *i, double *v, int max)
{
    int n = 0;

    while (n < max) {
        size_t at = *i, e = mtl_token(r, &at);
        if (e == at || number_parse(r->line + at, e - at, &v[n]) != NUMBER_OK)
            break;
        *i = e;
        n++;
    }
    return n;
}

/* Reads the colour after word (r g b, or one number for all three) into
 * c; warns and leaves it when it is not one. */
static void mtl_colour(MtlReader *r, size_t i, const char *word, double c[3])
{
    double v[3];
    int n = mtl_numbers(r, &i, v, 3);

    if (n == 0 || n == 2 || mtl_more(r, i)) {
        mtl_warn(r, i, "%s takes a colour r g b (spectral and CIE XYZ colours are not read): "
                       "line passed over", word);
        return;
    }
    for (int k = 0; k < 3; k++)
        c[k] = v[n == 3 ? k : 0];
}

/* Reads the one number after word into *out; warns and leaves it when it
 * is not one (or not in lo..hi). */
static void mtl_number(MtlReader *r, size_t i, const char *word, double lo, double hi,
                       double *out)
{
    double v;
    size_t at = i, e = mtl_token(r, &at);

    /* d -halo f: the halo is not read. */
    if (strcmp(word, "d") == 0 && e - at == 5 && memcmp(r->line + at, "-halo", 5) == 0)
        i = e;
    if (mtl_numbers(r, &i, &v, 1) != 1 || mtl_more(r, i) || !(v >= lo && v <= hi)) {
        mtl_warn(r, i, "%s takes a number from %g to %g: line passed over", word, lo, hi);
        return;
    }
    *out = v;
}

/* Reads map_Kd's options and path from *i: -s u [v [w]] and -o u [v [w]]
 * into the material, the others passed over by their arguments; then the
 * path, the rest of the line. */
static void mtl_map(MtlReader *r, size_t i, MeshMaterial *m)
{
    static const struct {
        const char *name;
        int words; /* its arguments, or -3: up to three numbers */
    } options[] = {{"-s", -3},    {"-o", -3},      {"-t", -3},    {"-bm", 1},     {"-blendu", 1},
                   {"-blendv", 1}, {"-cc", 1},     {"-clamp", 1}, {"-mm", 2},     {"-texres", 1},
                   {"-imfchan", 1}, {"-boost", 1}, {"-type", 1}};
    for (;;) {
        size_t at = i, e = mtl_token(r, &at), k;
        double v[3];
        int n;
        if (e == at || r->line[at] != '-')
            break;
        for (k = 0; k < sizeof options / sizeof options[0]; k++)
            if (strlen(options[k].name) == e - at && memcmp(options[k].name, r->line + at, e - at) == 0)
                break;
        if (k == sizeof options / sizeof options[0]) {
            mtl_warn(r, at, "unknown option '%.*s' of map_Kd: passed over", (int)(e - at > 20 ? 20 : e - at),
                     r->line + at);
            i = e;
            continue;
        }
        i = e;
        if (options[k].words > 0) {
            for (int w = 0; w < options[k].words; w++) {
                at = i;
                i = mtl_token(r, &at);
            }
            continue;
        }
        n = mtl_numbers(r, &i, v, 3);
        if (n > 0 && k < 2) {
            double *to = k == 0 ? m->uv_scale : m->uv_offset;
            to[0] = v[0];
            to[1] = n > 1 ? v[1] : k == 0 ? v[0] : 0;
        }
    }
    while (i < r->len && mtl_blank(r->line[i]))
        i++;
    if (i == r->len) {
        mtl_warn(r, i, "map_Kd names no texture file: line passed over");
        return;
    }
    free(m->texture);
    if (!m->texture_at)
        m->texture_at = malloc(sizeof *m->texture_at);
    m->texture = mtl_find(r->name, r->line + i, r->len - i);
    if (!m->texture || !m->texture_at) {
        r->failed = 1;
        return;
    }
    error_set_at(m->texture_at, r->name, r->lineno, (int)i + 1, r->line, r->len, "%s", "");
}

/* newmtl -> 'newmtl' name: the material the lines after it describe, when
 * the faces use it and no library before described it. */
static void mtl_newmtl(MtlReader *r, size_t i)
{
    const char *name = r->line + i;
    size_t n = r->len - i;

    r->current = NULL;
    for (size_t k = 0; k < r->mesh->material_count; k++) {
        MeshMaterial *m = &r->mesh->materials[k];
        if (m->name && !m->defined && strlen(m->name) == n && memcmp(m->name, name, n) == 0) {
            char *own = m->name;
            const char *at = m->used_at;
            size_t at_len = m->used_len;
            int line = m->used_line, column = m->used_column;
            mesh_material_default(m, own);
            m->used_at = at, m->used_len = at_len, m->used_line = line, m->used_column = column;
            m->defined = 1;
            r->current = m;
            return;
        }
    }
}

/* Reads one statement: the keyword word (n bytes), its arguments from i. */
static void mtl_statement(MtlReader *r, const char *word, size_t n, size_t i)
{
    MeshMaterial *m = r->current;
    char kw[16];

    while (i < r->len && mtl_blank(r->line[i]))
        i++;
    if (n == 6 && memcmp(word, "newmtl", 6) == 0) {
        mtl_newmtl(r, i);
        return;
    }
    if (n >= sizeof kw) {
        mtl_warn(r, 0, "unknown MTL statement '%.15s...': passed over", word);
        return;
    }
    memcpy(kw, word, n);
    kw[n] = '\0';
    for (size_t k = 0; k < sizeof mtl_passed / sizeof mtl_passed[0]; k++)
        if (strcmp(kw, mtl_passed[k]) == 0)
            return;
    if (strcmp(kw, "map_d") == 0) {
        if (!r->said_map_d)
            mtl_warn(r, 0, "map_d (a cut-out mask) is not read: the faces are drawn whole");
        r->said_map_d = 1;
        return;
    }
    if (!m) {
        if (strcmp(kw, "Ka") && strcmp(kw, "Kd") && strcmp(kw, "Ks") && strcmp(kw, "Ns") &&
            strcmp(kw, "Ni") && strcmp(kw, "d") && strcmp(kw, "Tr") && strcmp(kw, "illum") &&
            strcmp(kw, "map_Kd"))
            mtl_warn(r, 0, "unknown MTL statement '%s': passed over", kw);
        return; /* a material the faces do not use, or described before */
    }
    if (strcmp(kw, "Ka") == 0 || strcmp(kw, "Kd") == 0 || strcmp(kw, "Ks") == 0) {
        mtl_colour(r, i, kw, kw[1] == 'a' ? m->ka : kw[1] == 'd' ? m->kd : m->ks);
    } else if (strcmp(kw, "Ns") == 0) {
        mtl_number(r, i, kw, 0, 1e6, &m->ns);
    } else if (strcmp(kw, "Ni") == 0) {
        mtl_number(r, i, kw, 1e-3, 1e3, &m->ni);
    } else if (strcmp(kw, "d") == 0) {
        mtl_number(r, i, kw, 0, 1, &m->d);
    } else if (strcmp(kw, "Tr") == 0) {
        double tr = 1 - m->d;
        mtl_number(r, i, kw, 0, 1, &tr);
        m->d = 1 - tr;
    } else if (strcmp(kw, "illum") == 0) {
        double v = m->illum;
        mtl_number(r, i, kw, 0, 10, &v);
        if (v != (int)v)
            mtl_warn(r, i, "illum takes a whole number from 0 to 10: read as %d", (int)v);
        m->illum = (int)v;
    } else if (strcmp(kw, "map_Kd") == 0) {
        mtl_map(r, i, m);
    } else {
        mtl_warn(r, 0, "unknown MTL statement '%s': passed over", kw);
    }
}

int mtl_parse(const char *name, const char *text, size_t len, MeshFile *mesh)
{
    MtlReader r = {name, NULL, 0, 0, mesh, NULL, 0, 0};
    const char *p = text, *end = text + len;

    if (len >= 3 && memcmp(p, "\xEF\xBB\xBF", 3) == 0)
        p += 3;
    while (p < end && !r.failed) {
        const char *eol = memchr(p, '\n', (size_t)(end - p)), *hash;
        size_t i = 0, e;
        r.line = p;
        r.len = (size_t)((eol ? eol : end) - p);
        r.lineno++;
        p = eol ? eol + 1 : end;
        hash = memchr(r.line, '#', r.len);
        if (hash)
            r.len = (size_t)(hash - r.line);
        while (r.len > 0 && (mtl_blank(r.line[r.len - 1]) || r.line[r.len - 1] == '\r' ||
                             r.line[r.len - 1] == '\0'))
            r.len--;
        e = mtl_token(&r, &i);
        if (e > i)
            mtl_statement(&r, r.line + i, e - i, e);
    }
    return r.failed ? -1 : 0;
}

char *mtl_find(const char *beside, const char *written, size_t len)
{
    char *name = malloc(len + 1), *path, *base_path;
    const char *base;
    FILE *f;

    if (!name)
        return NULL;
    memcpy(name, written, len);
    name[len] = '\0';
    for (char *c = name; *c; c++)
        if (*c == '\\')
            *c = '/';
    path = path_beside(beside, "", name, len);
    if (!path) {
        free(name);
        return NULL;
    }
    if ((f = file_open(path, "rb")) != NULL) {
        fclose(f);
        free(name);
        return path;
    }
    /* Not there as written: its last part, beside the file that names it. */
    base = strrchr(name, '/');
    base = base ? base + 1 : name;
    if (base[0] && base[1] == ':')
        base += 2;
    base_path = path_beside(beside, "", base, strlen(base));
    if (base_path && (f = file_open(base_path, "rb")) != NULL) {
        fclose(f);
        free(path);
        free(name);
        return base_path;
    }
    free(base_path);
    free(name);
    return path;
}

/* Reads the library lib names (beside the OBJ file obj_path) into mesh,
 * or warns that it cannot; returns 0, or -1 when memory runs out. */
static int mtl_read_library(const char *obj_path, const MtlLibrary *lib, const char *name,
                            size_t len, MeshFile *mesh)
{
    char *path = mtl_find(obj_path, name, len), *data;
    size_t size;
    Error w, inner;
    int rc;

    if (!path)
        return -1;
    if (file_read_all(path, &data, &size, &inner) != 0) {
        w = lib->at;
        snprintf(w.message, sizeof w.message, "cannot read the material library '%.*s' (%.200s): "
                 "its materials are drawn in the default material", (int)(len > 200 ? 200 : len),
                 name, inner.message);
        free(path);
        return mesh_file_warn(mesh, &w);
    }
    mesh->hash = hash_bytes(mesh->hash, data, size);
    rc = mtl_parse(file_display_name(path), data, size, mesh);
    free(data);
    if (rc == 0) {
        void *grown = realloc(mesh->libraries, (mesh->library_count + 1) * sizeof(char *));
        if (grown) {
            mesh->libraries = grown;
            mesh->libraries[mesh->library_count++] = path;
            return 0;
        }
        rc = -1;
    }
    free(path);
    return rc;
}

int mtl_read_libraries(const char *obj_path, const MtlLibrary *libs, size_t n, MeshFile *mesh,
                       Error *err)
{
    for (size_t k = 0; k < n; k++) {
        const char *s = libs[k].name;
        char *whole = mtl_find(obj_path, s, strlen(s));
        FILE *f = whole ? file_open(whole, "rb") : NULL;
        int rc = 0;

        /* The whole line names one file when there is one of that name;
         * else each word names one. */
        if (f) {
            fclose(f);
            rc = mtl_read_library(obj_path, &libs[k], s, strlen(s), mesh);
        } else {
            while (*s && rc == 0) {
                size_t len = strcspn(s, " \t");
                if (len > 0)
                    rc = mtl_read_library(obj_path, &libs[k], s, len, mesh);
                s += len + strspn(s + len, " \t");
            }
        }
        free(whole);
        if (rc != 0) {
            error_set(err, file_display_name(obj_path), "out of memory");
            return -1;
        }
    }
    for (size_t k = 0; k < mesh->material_count; k++) {
        const MeshMaterial *m = &mesh->materials[k];
        Error w;
        if (!m->name || m->defined)
            continue;
        error_set_at(&w, file_display_name(obj_path), m->used_line, m->used_column, m->used_at,
                     m->used_len, n ? "no material library describes the material '%.60s': "
                                      "its faces are drawn in the default material"
                                    : "the material '%.60s' is named, but no material library "
                                      "(mtllib): its faces are drawn in the default material",
                     m->name);
        if (mesh_file_warn(mesh, &w) != 0) {
            error_set(err, file_display_name(obj_path), "out of memory");
            return -1;
        }
    }
    return 0;
}
