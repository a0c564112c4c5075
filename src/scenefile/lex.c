/* lex.c: lines, tokens and checked numbers of scene files (see lex.h). */
#include "scenefile/lex.h"

#include <ctype.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>

#include "base/path.h"
#include "math/number.h"

void lex_init(Lexer *L, const char *name, const char *text, size_t len, Error *err)
{
    /* A UTF-8 byte order mark, as some editors write, is not part of line 1. */
    if (len >= 3 && memcmp(text, "\xEF\xBB\xBF", 3) == 0) {
        text += 3;
        len -= 3;
    }
    L->name = name;
    L->start = L->next = text;
    L->end = text + len;
    L->lineno = 0;
    L->err = err;
}

void lex_split(const char *p, size_t len, int n, const char **cut)
{
    const char *end = p + len;

    cut[0] = p;
    for (int k = 1; k < n; k++) {
        const char *at = p + len / (size_t)n * (size_t)k, *eol;
        if (at < cut[k - 1])
            at = cut[k - 1];
        /* Forward to the start of the next line, unless at is one. */
        if (at > p && at[-1] != '\n') {
            eol = memchr(at, '\n', (size_t)(end - at));
            at = eol ? eol + 1 : end;
        }
        cut[k] = at;
    }
    cut[n] = end;
}

const char *lex_quote(char *buf, size_t size, const Token *t)
{
    size_t n = 0, shown = t->len > 40 ? 40 : t->len;

    buf[n++] = '\'';
    /* Not inside a character: back to its first byte. */
    while (shown < t->len && shown > 0 && ((unsigned char)t->text[shown] & 0xC0) == 0x80)
        shown--;
    n += error_escape(buf + n, size - n - 5, t->text, shown, 0, &shown);
    if (shown < t->len && n + 5 < size) {
        memcpy(buf + n, "...", 3);
        n += 3;
    }
    buf[n++] = '\'';
    buf[n] = '\0';
    return buf;
}

int lex_token_is(const Token *t, const char *c)
{
    return t->len == strlen(c) && memcmp(t->text, c, t->len) == 0;
}

/* line -> bytes up to '\n'; a final '\r' before it is dropped. Returns 1 with
 * *line set, 0 at the end of the input, -1 on a NUL byte or a carriage
 * return that does not end the line. */
static int lex_next_line(Lexer *L, Line *line)
{
    const char *eol;

    if (L->next >= L->end)
        return 0;
    eol = memchr(L->next, '\n', (size_t)(L->end - L->next));
    if (!eol)
        eol = L->end;
    line->text = L->next;
    line->len = (size_t)(eol - L->next);
    line->number = ++L->lineno;
    L->next = eol < L->end ? eol + 1 : eol;
    if (line->len > 0 && line->text[line->len - 1] == '\r')
        line->len--;
    for (size_t i = 0; i < line->len; i++) {
        if (line->text[i] == '\0') {
            int utf16 = L->end - L->start >= 2 && (memcmp(L->start, "\xFF\xFE", 2) == 0 ||
                                                   memcmp(L->start, "\xFE\xFF", 2) == 0);
            lex_fail(L, line, (int)i + 1, utf16 ? "NUL byte: the file is UTF-16 (it starts "
                                                  "with a UTF-16 byte order mark); save the "
                                                  "scene as UTF-8 or ASCII"
                                                : "NUL byte in the scene file: a scene is a "
                                                  "text file");
            return -1;
        }
        if (line->text[i] == '\r') {
            lex_fail(L, line, (int)i + 1,
                     "carriage return inside a line: lines must end with LF or CRLF");
            return -1;
        }
    }
    return 1;
}

static int lex_is_blank(char ch)
{
    return ch == ' ' || ch == '\t';
}

/* Splits line into tokens up to its comment into *rec. */
static void lex_tokens(const Line *line, Record *rec)
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
        while (i < len && lex_is_blank(line->text[i]))
            i++;
        if (i == len)
            break;
        start = i;
        while (i < len && !lex_is_blank(line->text[i])) {
            i++;
            if (rec->count == 0 && line->text[i - 1] == ':')
                break;
        }
        if (rec->count < LEX_MAX_TOKENS) {
            Token *t = &rec->tok[rec->count];
            t->text = line->text + start;
            t->len = i - start;
            t->column = (int)start + 1;
        }
        rec->count++;
        rec->end_column = (int)i + 1;
    }
}

int lex_next_record(Lexer *L, Record *rec)
{
    Line line;
    int rc;

    while ((rc = lex_next_line(L, &line)) == 1) {
        lex_tokens(&line, rec);
        if (rec->count > 0)
            return 1;
    }
    return rc;
}

/* What each kind of number must be, as lex_number()'s messages say it
 * (a coordinate may be anything finite). */
static const char *const lex_field_rule[] = {
    [FIELD_COORD] = "must be finite",
    [FIELD_COLOUR] = "must be in [0, 255]",
    [FIELD_POSITIVE] = "must be greater than 0",
    [FIELD_NONNEGATIVE] = "must be at least 0",
    [FIELD_FRACTION] = "must be in [0, 1]"};

int lex_field_fits(FieldKind kind, double v)
{
    switch (kind) {
    case FIELD_COLOUR:
        return v >= 0 && v <= 255;
    case FIELD_POSITIVE:
        return v > 0;
    case FIELD_NONNEGATIVE:
        return v >= 0;
    case FIELD_FRACTION:
        return v >= 0 && v <= 1;
    default:
        return 1;
    }
}

int lex_number(Lexer *L, const Record *rec, int k, const RecordSpec *spec, int index,
               double *out)
{
    const Token *t = &rec->tok[k];
    const char *what = spec->what, *name = spec->names[index];
    char q[64];
    double v = 0;

    switch (number_parse(t->text, t->len, &v)) {
    case NUMBER_OK:
        break;
    case NUMBER_SYNTAX:
        lex_fail(L, &rec->line, t->column, "expected a number for %s's %s, found %s", what,
                 name, lex_quote(q, sizeof q, t));
        return -1;
    case NUMBER_NONFINITE:
        lex_fail(L, &rec->line, t->column, "%s's %s must be a finite number, found %s", what,
                 name, lex_quote(q, sizeof q, t));
        return -1;
    case NUMBER_HEX:
        lex_fail(L, &rec->line, t->column,
                 "%s's %s must be a decimal number, found %s (hexadecimal is not accepted)",
                 what, name, lex_quote(q, sizeof q, t));
        return -1;
    case NUMBER_TOO_LARGE:
        lex_fail(L, &rec->line, t->column,
                 "%s's %s is out of range: %s exceeds 1e15 in magnitude", what, name,
                 lex_quote(q, sizeof q, t));
        return -1;
    case NUMBER_UNDERFLOW:
        lex_fail(L, &rec->line, t->column,
                 "%s's %s is out of range: %s is too small for a double (write 0 for zero)",
                 what, name, lex_quote(q, sizeof q, t));
        return -1;
    case NUMBER_NO_MEMORY:
        error_set(L->err, L->name, "out of memory");
        return -1;
    }
    if (!lex_field_fits(spec->kinds[index], v)) {
        lex_fail(L, &rec->line, t->column, "%s's %s %s, found %s", what, name,
                 lex_field_rule[spec->kinds[index]], lex_quote(q, sizeof q, t));
        return -1;
    }
    *out = v;
    return 0;
}

/* Records "expected N numbers for WHAT, found M" at column ("N or N+K" when
 * spec has optional numbers, "N to N+K" when any part of them may come). */
static void lex_fail_count(Lexer *L, const Record *rec, int column, const RecordSpec *spec,
                           int found)
{
    char expected[32];

    if (spec->optional)
        snprintf(expected, sizeof expected, "%d %s %d", spec->count,
                 spec->partial && spec->optional > 1 ? "to" : "or",
                 spec->count + spec->optional);
    else
        snprintf(expected, sizeof expected, "%d", spec->count);
    lex_fail(L, &rec->line, column, "expected %s number%s for %s%s%s%s, found %d", expected,
             spec->count + spec->optional == 1 ? "" : "s", spec->what,
             spec->syntax ? " (" : "", spec->syntax ? spec->syntax : "",
             spec->syntax ? ")" : "", found);
}

int lex_fail_extra(Lexer *L, const Record *rec, int k, const char *what)
{
    char q[64];

    lex_fail(L, &rec->line, rec->tok[k].column, "expected the end of the line after %s, found %s",
             what, lex_quote(q, sizeof q, &rec->tok[k]));
    return -1;
}

int lex_numbers(Lexer *L, const Record *rec, int first, const RecordSpec *spec, double *values)
{
    int found = rec->count - first, most = spec->count + spec->optional;
    /* Without `partial`, the optional numbers are read only when all of
     * them are there. */
    int present = found >= most              ? most
                  : found < spec->count || spec->partial ? found
                                                         : spec->count;

    for (int i = 0; i < present; i++)
        if (lex_number(L, rec, first + i, spec, i, &values[i]) != 0)
            return -1;
    if (found < spec->count) {
        lex_fail_count(L, rec, rec->end_column, spec, found);
        return -1;
    }
    if (!spec->partial && found > spec->count && found < most) {
        lex_fail_count(L, rec, rec->tok[first + spec->count].column, spec, found);
        return -1;
    }
    if (found > most) {
        const Token *extra = &rec->tok[first + most];
        double ignored;

        if (number_parse(extra->text, extra->len, &ignored) == NUMBER_SYNTAX)
            return lex_fail_extra(L, rec, first + most, spec->what);
        lex_fail_count(L, rec, extra->column, spec, found);
        return -1;
    }
    return found;
}

int lex_whole_number(Lexer *L, const Record *rec, int k, const char *what, const char *unit,
                     long max, int *out)
{
    return lex_whole_number_in(L, rec, k, what, unit, 1, max, out);
}

int lex_whole_number_in(Lexer *L, const Record *rec, int k, const char *what, const char *unit,
                        long min, long max, int *out)
{
    const Token *t = &rec->tok[k];
    long v = 0;
    char q[64];

    lex_quote(q, sizeof q, t);
    for (size_t i = 0; i < t->len; i++) {
        if (!isdigit((unsigned char)t->text[i])) {
            lex_fail(L, &rec->line, t->column,
                     "expected %s as a whole number of %s (decimal digits only), found %s",
                     what, unit, q);
            return -1;
        }
        if (v <= max)
            v = v * 10 + (t->text[i] - '0');
    }
    if (v < min || v > max) {
        lex_fail(L, &rec->line, t->column, "%s must be between %ld and %ld %s, found %s", what,
                 min, max, unit, q);
        return -1;
    }
    *out = (int)v;
    return 0;
}

int lex_once(Lexer *L, const Record *rec, int *seen, const char *what)
{
    if (*seen) {
        lex_fail(L, &rec->line, rec->tok[0].column, "%s is already set, on line %d", what, *seen);
        return -1;
    }
    *seen = rec->line.number;
    return 0;
}

void lex_fail_eof(Lexer *L, const char *what, const char *syntax)
{
    Line line;

    line.text = L->end;
    line.len = 0;
    line.number = L->lineno + 1;
    if (L->end > L->start && L->end[-1] != '\n') {
        while (line.text > L->start && line.text[-1] != '\n')
            line.text--;
        line.len = (size_t)(L->end - line.text);
        line.number = L->lineno;
    }
    lex_fail(L, &line, (int)line.len + 1, "expected %s%s%s%s, found the end of the file", what,
             syntax ? " (" : "", syntax ? syntax : "", syntax ? ")" : "");
}

char *lex_path(Lexer *L, const Token *t)
{
    char *path = path_beside(L->name, "", t->text, t->len);

    if (!path)
        error_set(L->err, L->name, "out of memory");
    return path;
}

int lex_fail_memory(Lexer *L, const Record *rec, int over, size_t limit)
{
    char size[NUMBER_FORMAT_MAX];

    if (over)
        lex_fail(L, &rec->line, rec->tok[0].column,
                 "the scene would pass the memory limit of %s here: raise it with "
                 "--memory-limit",
                 number_bytes(size, limit));
    else
        lex_fail(L, &rec->line, rec->tok[0].column, "out of memory");
    return -1;
}

void lex_fail_file(Lexer *L, const Record *rec, const Token *t, const char *what,
                   const Error *inner)
{
    char q[64];

    lex_quote(q, sizeof q, t);
    if (inner->line > 0)
        lex_fail(L, &rec->line, t->column, "cannot use the %s %s: %s:%d:%d: %s", what, q,
                 inner->file, inner->line, inner->column, inner->message);
    else
        lex_fail(L, &rec->line, t->column, "cannot use the %s %s: %s", what, q,
                 inner->message);
}

int lex_filter_word(const Token *t, TextureFilter *filter)
{
    static const char *const words[] = {"nearest", "bilinear", "trilinear", "ewa"};
    static const TextureFilter filters[] = {TEXTURE_NEAREST, TEXTURE_BILINEAR, TEXTURE_TRILINEAR,
                                            TEXTURE_EWA};

    for (int k = 0; k < 4; k++)
        if (lex_token_is(t, words[k])) {
            *filter = filters[k];
            return 1;
        }
    return 0;
}
