/* course_bulk.c: large fields of sphere: records read on every thread,
 * a line in one pass where it can be (see course_bulk.h). */
#include "course_bulk.h"

#include <string.h>

#include "base/threads.h"
#include "math/number.h"

enum {
    COURSE_PARALLEL_MIN = 1 << 20, /* fewer bytes of records: the serial reading */
    COURSE_PARTS_MAX = 64
};

/* A part of the records, whole lines, for one thread to read. */
typedef struct {
    const char *start, *end;
    size_t spheres; /* its records, every one a sphere: record if right */
    int lines;
    int others;     /* some record is not a sphere: record */
} CoursePart;

/* Counts part's lines and records (lines with a token before any '#'), and
 * notes whether a record does not start with 'sphere:'. */
static void course_count_part(CoursePart *part)
{
    const char *p = part->start, *end = part->end;

    part->spheres = 0;
    part->lines = 0;
    part->others = 0;
    while (p < end) {
        const char *eol = memchr(p, '\n', (size_t)(end - p)), *q = p;
        if (!eol)
            eol = end;
        while (q < eol && (*q == ' ' || *q == '\t'))
            q++;
        if (q < eol && *q != '#' && !(*q == '\r' && q + 1 == eol)) {
            part->spheres++;
            part->others |= (size_t)(eol - q) < 7 || memcmp(q, "sphere:", 7) != 0;
        }
        part->lines++;
        p = eol < end ? eol + 1 : end;
    }
}

static int course_blank(char c)
{
    return c == ' ' || c == '\t';
}

/* Reads the line [p, eol) into *s when it is a sphere: record of its 8
 * numbers alone, each of number_scan_plain()'s form and within its
 * field's range, blanks and a comment as the lexer takes them (and a
 * final carriage return); returns 1, or 0 for any other line, which the
 * lexer then reads (and says what is wrong with it). The same sphere as
 * the lexer's reading: one pass over the line, not four. */
static int course_quick_sphere(const char *p, const char *eol, Sphere *s)
{
    double v[8];
    Material m;

    if (eol > p && eol[-1] == '\r')
        eol--;
    while (p < eol && course_blank(*p))
        p++;
    if (eol - p < 7 || memcmp(p, "sphere:", 7) != 0)
        return 0;
    p += 7;
    for (int k = 0; k < 8; k++) {
        size_t len;
        while (p < eol && course_blank(*p))
            p++;
        len = number_scan_plain(p, eol, &v[k]);
        p += len;
        if (len == 0 || (p < eol && !course_blank(*p) && *p != '#') ||
            !lex_field_fits(course_sphere_spec.kinds[k], v[k]))
            return 0;
    }
    while (p < eol && course_blank(*p))
        p++;
    if (p < eol && *p != '#')
        return 0;
    for (; p < eol; p++) /* the comment: the lexer refuses these anywhere */
        if (*p == '\0' || *p == '\r')
            return 0;
    m = material_plain(colour(v[4], v[5], v[6]), v[7]);
    if (!sphere_plain(&m))
        return 0;
    s->centre = vec3(v[0], v[1], v[2]);
    s->radius = v[3];
    sphere_set_plain(s, &m);
    return 1;
}

/* Reads part's records into room, each a sphere: record of a plain
 * material, with P's rules; returns 0, or -1 at anything else (a fault,
 * another record, another material: the serial reading takes those).
 * Each line is tried by course_quick_sphere() first, then by the lexer. */
static int course_sphere_part(const CourseParser *P, const CoursePart *part, Sphere *room)
{
    CourseParser Q = *P;
    Error ignored; /* the serial reading says what is wrong */
    const char *p = part->start;
    size_t k = 0;

    Q.lex.err = &ignored;
    while (p < part->end) {
        const char *eol = memchr(p, '\n', (size_t)(part->end - p)), *next;
        Record rec;
        Material m;
        int rc;
        next = eol ? eol + 1 : part->end;
        if (k < part->spheres && course_quick_sphere(p, eol ? eol : part->end, &room[k])) {
            k++;
            p = next;
            continue;
        }
        /* The lexer on this line alone: a record, or none (blank, comment). */
        Q.lex.start = Q.lex.next = p;
        Q.lex.end = next;
        rc = lex_next_record(&Q.lex, &rec);
        if (rc < 0 || (rc == 1 && (k == part->spheres || !lex_token_is(&rec.tok[0], "sphere:") ||
                                   course_sphere_fields(&Q, &rec, &room[k].centre,
                                                        &room[k].radius, &m) != 0 ||
                                   !sphere_plain(&m))))
            return -1;
        if (rc == 1)
            sphere_set_plain(&room[k++], &m);
        p = next;
    }
    return k == part->spheres ? 0 : -1;
}

/* What the parts' threads share. */
typedef struct {
    const CourseParser *P;
    const CoursePart *parts;
    int n;
} CourseParts;

/* Reads every part into its place in room (scene_add_spheres()'s fill). */
static int course_fill_spheres(Sphere *room, void *ctx)
{
    const CourseParts *pp = ctx;
    int failed = 0;

#ifdef _OPENMP
#pragma omp parallel for num_threads(pp->n) schedule(static, 1) reduction(| : failed)
#endif
    for (int k = 0; k < pp->n; k++) {
        size_t at = 0; /* part k's spheres go after those of the parts before it */
        for (int j = 0; j < k; j++)
            at += pp->parts[j].spheres;
        failed |= course_sphere_part(pp->P, &pp->parts[k], room + at) != 0;
    }
    return failed ? -1 : 0;
}

/* Reads the rest of the input on every thread when it is large and holds
 * sphere: records alone (the benchmark's fields), into the same scene as
 * the serial reading; returns 1 when it did, 0 when the serial reading
 * must (then also when something is wrong: it says what, as it would
 * have). */
int course_spheres_parallel(CourseParser *P, Scene *scene)
{
    CoursePart parts[COURSE_PARTS_MAX];
    const char *cut[COURSE_PARTS_MAX + 1];
    size_t len = (size_t)(P->lex.end - P->lex.next), spheres = 0;
    int threads = threads_count(), n = threads < COURSE_PARTS_MAX ? threads : COURSE_PARTS_MAX;
    int lines = 0, others = 0;
    CourseParts pp = {P, parts, n};

    if (len < COURSE_PARALLEL_MIN)
        return 0;
    lex_split(P->lex.next, len, n, cut);
#ifdef _OPENMP
#pragma omp parallel for num_threads(n) schedule(static, 1)
#endif
    for (int k = 0; k < n; k++) {
        parts[k].start = cut[k];
        parts[k].end = cut[k + 1];
        course_count_part(&parts[k]);
    }
    for (int k = 0; k < n; k++) {
        spheres += parts[k].spheres;
        lines += parts[k].lines;
        others |= parts[k].others;
    }
    if (others || spheres == 0 || scene_add_spheres(scene, spheres, course_fill_spheres, &pp) != 0)
        return 0;
    P->lex.next = P->lex.end;
    P->lex.lineno += lines;
    course_note_object(P, SHAPE_SPHERE, scene_count_of(scene, SHAPE_SPHERE) - 1);
    return 1;
}

