/*
 * parse.c: the course scene format (see parse.h, docs/scene-format.md).
 *
 * The input is split into lines; a '#' starts a comment, blank lines are
 * skipped, and each remaining line is one record:
 *
 *   scene      -> camera top-left top-right bottom-left resolution
 *                 background light sphere*
 *   camera     -> x y z                      (likewise the three corners)
 *   resolution -> digits                     (1..32768)
 *   background -> r g b                      (0..255 each)
 *   light      -> x y z r g b
 *   sphere     -> 'sphere:' cx cy cz radius r g b reflection
 *
 * Fields are separated by spaces or tabs; a line may end in CRLF.
 */
#include "parse.h"

#include <ctype.h>
#include <float.h>
#include <math.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>

#include "file.h"

#define PARSE_MAX_MAGNITUDE 1e15 /* largest accepted |number| */

enum { PARSE_MAX_TOKENS = 10 }; /* tokens kept per line: a keyword, 8 numbers, 1 extra */

/* A field of a line: where it starts and how long it is. */
typedef struct {
    const char *text; /* first byte, inside the input */
    size_t len;       /* bytes */
    int column;       /* 1-based column of text */
} Token;

/* Where a line is, so that an error can point into it later. */
typedef struct {
    const char *text; /* first byte of the line */
    size_t len;       /* bytes, without the line ending */
    int number;       /* 1-based line number */
} Line;

/* A record line split into tokens. */
typedef struct {
    Line line;                     /* the line the record is on */
    Token tok[PARSE_MAX_TOKENS];   /* the first tokens */
    int count;                     /* all tokens on the line, kept or not */
    int end_column;                /* column just past the last token */
} Record;

/* The parser's state: a cursor over the input. */
typedef struct {
    const char *name;  /* input name for messages */
    const char *start; /* first input byte */
    const char *next;  /* first byte of the next line */
    const char *end;   /* one past the last input byte */
    int lineno;        /* number of the last line read, 0 before the first */
    Error *err;        /* where faults are described */
} Parser;

/* What a number stands for, and so which values it may take. */
typedef enum {
    FIELD_COORD,     /* any finite value */
    FIELD_COLOUR,    /* 0..255 */
    FIELD_RADIUS,    /* > 0 */
    FIELD_REFLECTION /* 0..1 */
} FieldKind;

/* The numbers of one record kind. */
typedef struct {
    const char *what;          /* "the camera position" */
    const char *syntax;        /* "x y z r g b" for messages, or NULL */
    int count;                 /* numbers in the record */
    const char *const *names;  /* the numbers' names */
    const FieldKind *kinds;    /* the numbers' kinds */
} RecordSpec;

static const char *const parse_xyz_names[] = {"x", "y", "z"};
static const FieldKind parse_xyz_kinds[] = {FIELD_COORD, FIELD_COORD, FIELD_COORD};
static const char *const parse_rgb_names[] = {"red", "green", "blue"};
static const FieldKind parse_rgb_kinds[] = {FIELD_COLOUR, FIELD_COLOUR, FIELD_COLOUR};
static const char *const parse_light_names[] = {"x", "y", "z", "red", "green", "blue"};
static const FieldKind parse_light_kinds[] = {FIELD_COORD,  FIELD_COORD,  FIELD_COORD,
                                              FIELD_COLOUR, FIELD_COLOUR, FIELD_COLOUR};
static const char *const parse_sphere_names[] = {"centre x", "centre y", "centre z", "radius",
                                                 "red",      "green",    "blue",     "reflection"};
static const FieldKind parse_sphere_kinds[] = {FIELD_COORD,  FIELD_COORD,  FIELD_COORD,
                                               FIELD_RADIUS, FIELD_COLOUR, FIELD_COLOUR,
                                               FIELD_COLOUR, FIELD_REFLECTION};

static const RecordSpec parse_camera = {"the camera position", NULL, 3, parse_xyz_names,
                                        parse_xyz_kinds};
static const RecordSpec parse_top_left = {"the screen's top-left corner", NULL, 3,
                                          parse_xyz_names, parse_xyz_kinds};
static const RecordSpec parse_top_right = {"the screen's top-right corner", NULL, 3,
                                           parse_xyz_names, parse_xyz_kinds};
static const RecordSpec parse_bottom_left = {"the screen's bottom-left corner", NULL, 3,
                                             parse_xyz_names, parse_xyz_kinds};
static const RecordSpec parse_background = {"the background colour", NULL, 3, parse_rgb_names,
                                            parse_rgb_kinds};
static const RecordSpec parse_light = {"the light", "x y z r g b", 6, parse_light_names,
                                       parse_light_kinds};
static const RecordSpec parse_sphere = {"the sphere", "cx cy cz radius r g b reflection", 8,
                                        parse_sphere_names, parse_sphere_kinds};

/* Writes tok into buf as 'tok' for a message: at most 40 bytes of it, with
 * control bytes shown as '?' and "..." where cut. */
static const char *parse_quote(char *buf, size_t size, const char *tok, size_t len)
{
    size_t n = 0, shown = len > 40 ? 40 : len;

    buf[n++] = '\'';
    for (size_t i = 0; i < shown && n + 5 < size; i++) {
        unsigned char ch = (unsigned char)tok[i];
        buf[n++] = ch < 0x20 || ch == 0x7f ? '?' : (char)ch;
    }
    if (shown < len && n + 5 < size) {
        memcpy(buf + n, "...", 3);
        n += 3;
    }
    buf[n++] = '\'';
    buf[n] = '\0';
    return buf;
}

/* Records a fault at column of line. */
#define parse_fail(P, line, column, ...)                                                      \
    error_set_at((P)->err, (P)->name, (line)->number, (column), (line)->text, (line)->len,    \
                 __VA_ARGS__)

/* line -> bytes up to '\n'; a final '\r' before it is dropped. Returns 1 with
 * *line set, 0 at the end of the input, -1 on a NUL byte or a carriage
 * return that does not end the line. */
static int parse_next_line(Parser *P, Line *line)
{
    const char *eol;

    if (P->next >= P->end)
        return 0;
    eol = memchr(P->next, '\n', (size_t)(P->end - P->next));
    if (!eol)
        eol = P->end;
    line->text = P->next;
    line->len = (size_t)(eol - P->next);
    line->number = ++P->lineno;
    P->next = eol < P->end ? eol + 1 : eol;
    if (line->len > 0 && line->text[line->len - 1] == '\r')
        line->len--;
    for (size_t i = 0; i < line->len; i++) {
        if (line->text[i] == '\0') {
            parse_fail(P, line, (int)i + 1,
                       "NUL byte in the scene file: a scene is a text file");
            return -1;
        }
        if (line->text[i] == '\r') {
            parse_fail(P, line, (int)i + 1,
                       "carriage return inside a line: lines must end with LF or CRLF");
            return -1;
        }
    }
    return 1;
}

static int parse_is_blank(char ch)
{
    return ch == ' ' || ch == '\t';
}

/* Splits line into tokens up to its comment into *rec. The first token ends
 * after its first ':' if it has one, so that "sphere:1" is "sphere:" "1". */
static void parse_tokens(const Line *line, Record *rec)
{
    size_t i = 0, len = line->len;
    const char *comment = memchr(line->text, '#', len);

    if (comment)
        len = (size_t)(comment - line->text);
    rec->line = *line;
    rec->count = 0;
    rec->end_column = 1;
    for (;;) {
        size_t start;
        while (i < len && parse_is_blank(line->text[i]))
            i++;
        if (i == len)
            break;
        start = i;
        while (i < len && !parse_is_blank(line->text[i])) {
            i++;
            if (rec->count == 0 && line->text[i - 1] == ':')
                break;
        }
        if (rec->count < PARSE_MAX_TOKENS) {
            Token *t = &rec->tok[rec->count];
            t->text = line->text + start;
            t->len = i - start;
            t->column = (int)start + 1;
        }
        rec->count++;
        rec->end_column = (int)i + 1;
    }
}

/* Reads lines up to the next one with a record; returns 1 with *rec set, 0 at
 * the end of the input, -1 on an error. */
static int parse_next_record(Parser *P, Record *rec)
{
    Line line;
    int rc;

    while ((rc = parse_next_line(P, &line)) == 1) {
        parse_tokens(&line, rec);
        if (rec->count > 0)
            return 1;
    }
    return rc;
}

/* Results of parse_decimal(). */
typedef enum {
    NUMBER_OK,
    NUMBER_SYNTAX,    /* not a decimal number */
    NUMBER_NONFINITE, /* inf, nan */
    NUMBER_HEX,       /* 0x... */
    NUMBER_TOO_LARGE, /* |x| > PARSE_MAX_MAGNITUDE, or overflows */
    NUMBER_UNDERFLOW, /* non-zero digits, but below the smallest normal double */
    NUMBER_NO_MEMORY
} NumberStatus;

/* Says whether the len bytes at s spell c (case-insensitively). */
static int parse_word_is(const char *s, size_t len, const char *c)
{
    size_t n = strlen(c);
    if (len != n)
        return 0;
    for (size_t i = 0; i < n; i++)
        if (tolower((unsigned char)s[i]) != c[i])
            return 0;
    return 1;
}

/* Classifies a token that is not a decimal number. */
static NumberStatus parse_non_decimal(const char *s, size_t len)
{
    if (len > 0 && (s[0] == '+' || s[0] == '-')) {
        s++;
        len--;
    }
    if (parse_word_is(s, len, "inf") || parse_word_is(s, len, "infinity") ||
        parse_word_is(s, len, "nan") ||
        (len > 4 && parse_word_is(s, 4, "nan(") && s[len - 1] == ')'))
        return NUMBER_NONFINITE;
    if (len > 2 && s[0] == '0' && (s[1] == 'x' || s[1] == 'X'))
        return NUMBER_HEX;
    return NUMBER_SYNTAX;
}

/*
 * number -> [+-] (digits ['.' digits*] | '.' digits) [('e'|'E') [+-] digits]
 * Converts the len bytes at s to *out, correctly rounded, when they spell a
 * number of this form whose value is finite, at most PARSE_MAX_MAGNITUDE in
 * magnitude, and zero or a normal double.
 */
static NumberStatus parse_decimal(const char *s, size_t len, double *out)
{
    size_t i = 0, digits = 0;
    int nonzero = 0;
    char small[64], *buf;
    double v;

    if (i < len && (s[i] == '+' || s[i] == '-'))
        i++;
    for (; i < len && isdigit((unsigned char)s[i]); i++, digits++)
        nonzero |= s[i] != '0';
    if (i < len && s[i] == '.')
        for (i++; i < len && isdigit((unsigned char)s[i]); i++, digits++)
            nonzero |= s[i] != '0';
    if (digits == 0)
        return parse_non_decimal(s, len);
    if (i < len && (s[i] == 'e' || s[i] == 'E')) {
        size_t exp_digits = 0;
        i++;
        if (i < len && (s[i] == '+' || s[i] == '-'))
            i++;
        for (; i < len && isdigit((unsigned char)s[i]); i++)
            exp_digits++;
        if (exp_digits == 0)
            return NUMBER_SYNTAX;
    }
    if (i != len)
        return parse_non_decimal(s, len);

    buf = len < sizeof small ? small : malloc(len + 1);
    if (!buf)
        return NUMBER_NO_MEMORY;
    memcpy(buf, s, len);
    buf[len] = '\0';
    v = strtod(buf, NULL);
    if (buf != small)
        free(buf);
    if (!(fabs(v) <= PARSE_MAX_MAGNITUDE))
        return NUMBER_TOO_LARGE;
    if ((v == 0 && nonzero) || (v != 0 && fabs(v) < DBL_MIN))
        return NUMBER_UNDERFLOW;
    *out = v;
    return NUMBER_OK;
}

/* Reads token k of rec, the number `index` of spec, into *out, checking the
 * range its kind allows; returns 0, or -1 with the fault recorded. */
static int parse_expect_number(Parser *P, const Record *rec, int k, const RecordSpec *spec,
                               int index, double *out)
{
    const Token *t = &rec->tok[k];
    const char *what = spec->what, *name = spec->names[index];
    char q[64];
    double v = 0;

    parse_quote(q, sizeof q, t->text, t->len);
    switch (parse_decimal(t->text, t->len, &v)) {
    case NUMBER_OK:
        break;
    case NUMBER_SYNTAX:
        parse_fail(P, &rec->line, t->column, "expected a number for %s's %s, found %s", what,
                   name, q);
        return -1;
    case NUMBER_NONFINITE:
        parse_fail(P, &rec->line, t->column, "%s's %s must be a finite number, found %s", what,
                   name, q);
        return -1;
    case NUMBER_HEX:
        parse_fail(P, &rec->line, t->column,
                   "%s's %s must be a decimal number, found %s (hexadecimal is not accepted)",
                   what, name, q);
        return -1;
    case NUMBER_TOO_LARGE:
        parse_fail(P, &rec->line, t->column,
                   "%s's %s is out of range: %s exceeds 1e15 in magnitude", what, name, q);
        return -1;
    case NUMBER_UNDERFLOW:
        parse_fail(P, &rec->line, t->column,
                   "%s's %s is out of range: %s is too small for a double (write 0 for zero)",
                   what, name, q);
        return -1;
    case NUMBER_NO_MEMORY:
        error_set(P->err, P->name, "out of memory");
        return -1;
    }
    switch (spec->kinds[index]) {
    case FIELD_COORD:
        break;
    case FIELD_COLOUR:
        if (!(v >= 0 && v <= 255)) {
            parse_fail(P, &rec->line, t->column, "%s's %s must be in [0, 255], found %s", what,
                       name, q);
            return -1;
        }
        break;
    case FIELD_RADIUS:
        if (!(v > 0)) {
            parse_fail(P, &rec->line, t->column, "%s's %s must be greater than 0, found %s",
                       what, name, q);
            return -1;
        }
        break;
    case FIELD_REFLECTION:
        if (!(v >= 0 && v <= 1)) {
            parse_fail(P, &rec->line, t->column, "%s's %s must be in [0, 1], found %s", what,
                       name, q);
            return -1;
        }
        break;
    }
    *out = v;
    return 0;
}

/* Records "expected N numbers for WHAT, found M" at column. */
static void parse_fail_count(Parser *P, const Record *rec, int column, const RecordSpec *spec,
                             int found)
{
    parse_fail(P, &rec->line, column, "expected %d numbers for %s%s%s%s, found %d", spec->count,
               spec->what, spec->syntax ? " (" : "", spec->syntax ? spec->syntax : "",
               spec->syntax ? ")" : "", found);
}

/* Reads the numbers of spec from rec's tokens, starting at token `first`,
 * into values; returns 0, or -1 with the fault recorded. */
static int parse_expect_numbers(Parser *P, const Record *rec, int first, const RecordSpec *spec,
                                double *values)
{
    int found = rec->count - first;
    int present = found < spec->count ? found : spec->count;

    for (int i = 0; i < present; i++)
        if (parse_expect_number(P, rec, first + i, spec, i, &values[i]) != 0)
            return -1;
    if (found < spec->count) {
        parse_fail_count(P, rec, rec->end_column, spec, found);
        return -1;
    }
    if (found > spec->count) {
        const Token *extra = &rec->tok[first + spec->count];
        double ignored;
        char q[64];

        if (parse_decimal(extra->text, extra->len, &ignored) == NUMBER_SYNTAX) {
            parse_fail(P, &rec->line, extra->column,
                       "expected the end of the line after %s, found %s", spec->what,
                       parse_quote(q, sizeof q, extra->text, extra->len));
            return -1;
        }
        parse_fail_count(P, rec, extra->column, spec, found);
        return -1;
    }
    return 0;
}

/* Records that the input ends where the record `what` was expected: the
 * position is just past the last byte, on a line of its own after a final
 * newline. */
static void parse_fail_eof(Parser *P, const char *what, const char *syntax)
{
    Line line;

    line.text = P->end;
    line.len = 0;
    line.number = P->lineno + 1;
    if (P->end > P->start && P->end[-1] != '\n') {
        while (line.text > P->start && line.text[-1] != '\n')
            line.text--;
        line.len = (size_t)(P->end - line.text);
        line.number = P->lineno;
    }
    parse_fail(P, &line, (int)line.len + 1, "expected %s%s%s%s, found the end of the file", what,
               syntax ? " (" : "", syntax ? syntax : "", syntax ? ")" : "");
}

/* Reads the next record, which must be the header record spec, in which a
 * keyword is out of place; returns 0, or -1 with the fault recorded. */
static int parse_header_record(Parser *P, const RecordSpec *spec, const char *syntax,
                               Record *rec)
{
    int rc = parse_next_record(P, rec);
    const Token *t = &rec->tok[0];
    char q[64];

    if (rc < 0)
        return -1;
    if (rc == 0) {
        parse_fail_eof(P, spec->what, syntax);
        return -1;
    }
    if (t->len > 0 && t->text[t->len - 1] == ':') {
        parse_fail(P, &rec->line, t->column,
                   "expected %s, found the record %s: the 7 header records (camera, three "
                   "screen corners, resolution, background, light) come first",
                   spec->what, parse_quote(q, sizeof q, t->text, t->len));
        return -1;
    }
    return 0;
}

/* Reads a header record of spec's numbers into values. */
static int parse_header_numbers(Parser *P, const RecordSpec *spec, Record *rec, double *values)
{
    const char *syntax = spec->syntax ? spec->syntax : spec->count == 3 ? "3 numbers" : NULL;

    if (parse_header_record(P, spec, syntax, rec) != 0)
        return -1;
    return parse_expect_numbers(P, rec, 0, spec, values);
}

/* point -> x y z */
static int parse_point(Parser *P, const RecordSpec *spec, Record *rec, Vec3 *out)
{
    double v[3];

    if (parse_header_numbers(P, spec, rec, v) != 0)
        return -1;
    *out = vec3(v[0], v[1], v[2]);
    return 0;
}

/* resolution -> digits, 1..CAMERA_MAX_SIZE */
static int parse_resolution(Parser *P, Record *rec, int *width)
{
    static const RecordSpec spec = {"the horizontal resolution", NULL, 1, NULL, NULL};
    const Token *t;
    long v = 0;
    char q[64];

    if (parse_header_record(P, &spec, "a whole number of pixels", rec) != 0)
        return -1;
    t = &rec->tok[0];
    if (rec->count > 1) {
        parse_fail(P, &rec->line, rec->tok[1].column,
                   "expected 1 number for the horizontal resolution, found %d", rec->count);
        return -1;
    }
    parse_quote(q, sizeof q, t->text, t->len);
    for (size_t i = 0; i < t->len; i++) {
        if (!isdigit((unsigned char)t->text[i])) {
            parse_fail(P, &rec->line, t->column,
                       "expected the horizontal resolution as a whole number of pixels "
                       "(decimal digits only), found %s",
                       q);
            return -1;
        }
        if (v <= CAMERA_MAX_SIZE)
            v = v * 10 + (t->text[i] - '0');
    }
    if (v < 1 || v > CAMERA_MAX_SIZE) {
        parse_fail(P, &rec->line, t->column,
                   "the horizontal resolution must be between 1 and %d pixels, found %s",
                   CAMERA_MAX_SIZE, q);
        return -1;
    }
    *width = (int)v;
    return 0;
}

/* colour -> r g b, each 0..255 */
static int parse_colour(Parser *P, const RecordSpec *spec, Record *rec, Colour *out)
{
    double v[3];

    if (parse_header_numbers(P, spec, rec, v) != 0)
        return -1;
    *out = colour(v[0], v[1], v[2]);
    return 0;
}

/* light -> x y z r g b */
static int parse_light_record(Parser *P, Record *rec, Light *light)
{
    double v[6];

    if (parse_header_numbers(P, &parse_light, rec, v) != 0)
        return -1;
    light->position = vec3(v[0], v[1], v[2]);
    light->colour = colour(v[3], v[4], v[5]);
    return 0;
}

/* Checks the screen spanned by the corner records tl, tr and bl. */
static int parse_check_screen(Parser *P, Camera *cam, Vec3 tr, Vec3 bl, const Record *tr_rec,
                              const Record *bl_rec)
{
    cam->u = vec3_sub(tr, cam->top_left);
    cam->v = vec3_sub(bl, cam->top_left);
    switch (camera_check_screen(cam->u, cam->v)) {
    case CAMERA_SCREEN_OK:
        return 0;
    case CAMERA_SCREEN_NO_WIDTH:
        parse_fail(P, &tr_rec->line, tr_rec->tok[0].column,
                   "the screen's top-right corner is its top-left corner: the screen has no "
                   "width");
        return -1;
    case CAMERA_SCREEN_NO_HEIGHT:
        parse_fail(P, &bl_rec->line, bl_rec->tok[0].column,
                   "the screen's bottom-left corner is its top-left corner: the screen has no "
                   "height");
        return -1;
    case CAMERA_SCREEN_PARALLEL:
        parse_fail(P, &bl_rec->line, bl_rec->tok[0].column,
                   "the screen's top and left edges are parallel: its three corners lie on "
                   "one line");
        return -1;
    }
    return -1;
}

/* header -> camera top-left top-right bottom-left resolution background light */
static int parse_header(Parser *P, Scene *scene)
{
    Camera *cam = &scene->camera;
    Record rec, tr_rec;
    Vec3 tr, bl;
    double height;

    if (parse_point(P, &parse_camera, &rec, &cam->eye) != 0 ||
        parse_point(P, &parse_top_left, &rec, &cam->top_left) != 0 ||
        parse_point(P, &parse_top_right, &tr_rec, &tr) != 0 ||
        parse_point(P, &parse_bottom_left, &rec, &bl) != 0 ||
        parse_check_screen(P, cam, tr, bl, &tr_rec, &rec) != 0 ||
        parse_resolution(P, &rec, &cam->width) != 0)
        return -1;
    height = camera_height(cam->u, cam->v, cam->width);
    if (height > CAMERA_MAX_SIZE) {
        parse_fail(P, &rec.line, rec.tok[0].column,
                   "the image would be %d x %.0f pixels: its height, set by the screen's "
                   "proportions, must be at most %d",
                   cam->width, height, CAMERA_MAX_SIZE);
        return -1;
    }
    cam->height = (int)height;
    if (parse_colour(P, &parse_background, &rec, &scene->background) != 0 ||
        parse_light_record(P, &rec, &scene->light) != 0)
        return -1;
    return 0;
}

/* sphere -> 'sphere:' cx cy cz radius r g b reflection */
static int parse_sphere_record(Parser *P, const Record *rec, Scene *scene)
{
    double v[8];
    Sphere s;

    if (parse_expect_numbers(P, rec, 1, &parse_sphere, v) != 0)
        return -1;
    s.centre = vec3(v[0], v[1], v[2]);
    s.radius = v[3];
    s.colour = colour(v[4], v[5], v[6]);
    s.reflection = v[7];
    s.line = rec->line.number;
    if (scene_add_sphere(scene, &s) != 0) {
        error_set(P->err, P->name, "out of memory after %zu spheres", scene->sphere_count);
        return -1;
    }
    return 0;
}

/* Records why the first token of rec is not a known record keyword. */
static void parse_fail_keyword(Parser *P, const Record *rec)
{
    const Token *t = &rec->tok[0];
    char q[64];
    double ignored;

    parse_quote(q, sizeof q, t->text, t->len);
    if (parse_word_is(t->text, t->len, "sphere:"))
        parse_fail(P, &rec->line, t->column,
                   "unknown record %s: keywords are lower case ('sphere:')", q);
    else if (parse_word_is(t->text, t->len, "sphere"))
        parse_fail(P, &rec->line, t->column,
                   "expected 'sphere:' with its colon attached, found %s", q);
    else if (parse_decimal(t->text, t->len, &ignored) != NUMBER_SYNTAX)
        parse_fail(P, &rec->line, t->column,
                   "expected a record such as 'sphere:', found the number %s: the 7 header "
                   "records are complete",
                   q);
    else
        parse_fail(P, &rec->line, t->column, "unknown record %s (expected 'sphere:')", q);
}

/* objects -> sphere* */
static int parse_objects(Parser *P, Scene *scene)
{
    Record rec;
    int rc;

    while ((rc = parse_next_record(P, &rec)) == 1) {
        const Token *t = &rec.tok[0];
        if (t->len == 7 && memcmp(t->text, "sphere:", 7) == 0) {
            if (parse_sphere_record(P, &rec, scene) != 0)
                return -1;
        } else {
            parse_fail_keyword(P, &rec);
            return -1;
        }
    }
    return rc;
}

int parse_scene_text(const char *name, const char *text, size_t len, Scene *scene, Error *err)
{
    Parser P;

    scene_init(scene);
    /* A UTF-8 byte order mark, as some editors write, is not part of line 1. */
    if (len >= 3 && memcmp(text, "\xEF\xBB\xBF", 3) == 0) {
        text += 3;
        len -= 3;
    }
    P.name = name;
    P.start = P.next = text;
    P.end = text + len;
    P.lineno = 0;
    P.err = err;
    if (parse_header(&P, scene) != 0 || parse_objects(&P, scene) != 0) {
        scene_free(scene);
        return -1;
    }
    scene_fit_scale(scene);
    return 0;
}

int parse_scene_file(const char *path, Scene *scene, Error *err)
{
    char *text;
    size_t len;
    int rc;

    scene_init(scene);
    if (file_read_all(path, &text, &len, err) != 0)
        return -1;
    rc = parse_scene_text(file_display_name(path), text, len, scene, err);
    free(text);
    return rc;
}
