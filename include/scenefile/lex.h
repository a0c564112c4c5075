/*
 * lex.h: the lines, fields and numbers of line-based scene files, with
 * their positions, for the parsers of both scene formats.
 *
 * A scene file is text split into lines (LF or CRLF, the last one may lack
 * its ending; a UTF-8 byte order mark at the start is skipped). '#' starts
 * a comment that runs to the end of the line; blank and comment-only lines
 * are skipped; every other line is one record: fields separated by spaces
 * or tabs. A NUL byte, or a carriage return inside a line, is an error.
 * Every fault is recorded in the Lexer's Error with the file, line and
 * column it is at, and the functions here return -1.
 */
#ifndef RAYTRACE_LEX_H
#define RAYTRACE_LEX_H

#include <stddef.h>

#include "base/error.h"
#include "geometry/material.h"

enum { LEX_MAX_TOKENS = 32 }; /* tokens kept per line: a keyword, 15 numbers
                                 (a transparent triangle), and room for an
                                 MPL line's stray commas */

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
    Line line;                 /* the line the record is on */
    Token tok[LEX_MAX_TOKENS]; /* the first tokens */
    int count;                 /* all tokens on the line, kept or not */
    int end_column;            /* column just past the last token */
} Record;

/* A cursor over the input. */
typedef struct {
    const char *name;  /* input name for messages */
    const char *start; /* first input byte, after a byte order mark */
    const char *next;  /* first byte of the next line */
    const char *end;   /* one past the last input byte */
    int lineno;        /* number of the last line read, 0 before the first */
    Error *err;        /* where faults are described */
} Lexer;

/* What a number stands for, and so which values it may take. */
typedef enum {
    FIELD_COORD,       /* any finite value */
    FIELD_COLOUR,      /* 0..255 */
    FIELD_POSITIVE,    /* > 0: radius, focal distance, tile size, index */
    FIELD_NONNEGATIVE, /* >= 0: aperture, Blinn-Phong weights */
    FIELD_FRACTION     /* 0..1: reflection, transparency */
} FieldKind;

/* Says whether v is a value a number of kind may take. */
int lex_field_fits(FieldKind kind, double v);

/* The numbers of one record kind. */
typedef struct {
    const char *what;         /* "the camera position" */
    const char *syntax;       /* "x y z r g b" for messages, or NULL */
    int count;                /* numbers the record always has */
    int optional;             /* numbers that may follow them */
    int partial;              /* 1: any leading part of the optional numbers
                                 may be given; 0: all of them or none */
    const char *const *names; /* the numbers' names */
    const FieldKind *kinds;   /* the numbers' kinds */
} RecordSpec;

/* Starts L on the len bytes at text (NUL bytes included), naming the input
 * `name` in errors, which go to *err. */
void lex_init(Lexer *L, const char *name, const char *text, size_t len, Error *err);

/* Reads lines up to the next one with a record; returns 1 with *rec set, 0 at
 * the end of the input, -1 on an error. The first token of a line ends
 * after its first ':' if it has one, so that "sphere:1" is "sphere:" "1". */
int lex_next_record(Lexer *L, Record *rec);

/* Splits the len bytes at p into n parts (n >= 1) of about len / n bytes
 * each that end at line ends, for n threads to read: part k is [cut[k],
 * cut[k + 1]) (cut has n + 1 entries; a part may be empty). */
void lex_split(const char *p, size_t len, int n, const char **cut);

/* Records a fault at column of line. */
#define lex_fail(L, line, column, ...)                                                        \
    error_set_at((L)->err, (L)->name, (line)->number, (column), (line)->text, (line)->len,    \
                 __VA_ARGS__)

/* Writes t into buf as 'tok' for a message: at most 40 bytes of it, with
 * control bytes shown as '?' and "..." where cut; returns buf. */
const char *lex_quote(char *buf, size_t size, const Token *t);

/* Says whether token t spells the C string c exactly. */
int lex_token_is(const Token *t, const char *c);

/* Reads token k of rec, the number `index` of spec, into *out, checking it
 * against its kind; returns 0, or -1 with the fault recorded. */
int lex_number(Lexer *L, const Record *rec, int k, const RecordSpec *spec, int index,
               double *out);

/* Reads the numbers of spec from rec's tokens, starting at token `first`,
 * into values, checking each against its kind; returns how many it read,
 * or -1 with the fault recorded at the number or the count at fault. */
int lex_numbers(Lexer *L, const Record *rec, int first, const RecordSpec *spec,
                double *values);

/* Reads token k of rec, which is what, as a whole number of unit (decimal
 * digits only) between 1 and max into *out; returns 0 or -1. */
int lex_whole_number(Lexer *L, const Record *rec, int k, const char *what, const char *unit,
                     long max, int *out);

/* lex_whole_number() between min and max. */
int lex_whole_number_in(Lexer *L, const Record *rec, int k, const char *what, const char *unit,
                        long min, long max, int *out);

/* Checks that rec's keyword, `what`, which may appear once, has not
 * appeared before (on line *seen, 0 if not), then notes its line; returns
 * 0, or -1 with the fault recorded. */
int lex_once(Lexer *L, const Record *rec, int *seen, const char *what);

/* Says whether token t names a texture filter (nearest, bilinear,
 * trilinear, ewa: material.h), the same words in every format, and stores
 * it in *filter when so. */
int lex_filter_word(const Token *t, TextureFilter *filter);

/* Records that the input ends where `what` was expected (with syntax in
 * parentheses when not NULL): the position is just past the last byte. */
void lex_fail_eof(Lexer *L, const char *what, const char *syntax);

/* Records "expected the end of the line after WHAT, found 'tok'" at token
 * k of rec; returns -1. */
int lex_fail_extra(Lexer *L, const Record *rec, int k, const char *what);

/* Returns token t as a file path relative to the input's directory (as
 * given when absolute, or when the input name has no directory), in a new
 * string; NULL with the fault recorded when memory runs out. */
char *lex_path(Lexer *L, const Token *t);

/* Records that the element of rec cannot be stored: over = 1 when it would
 * pass the memory limit of limit bytes, 0 when memory ran out; returns -1. */
int lex_fail_memory(Lexer *L, const Record *rec, int over, size_t limit);

/* Records that the file named by token t of rec, a `what` ("texture",
 * "mesh"), cannot be used, quoting the fault inner found in it. */
void lex_fail_file(Lexer *L, const Record *rec, const Token *t, const char *what,
                   const Error *inner);

#endif
