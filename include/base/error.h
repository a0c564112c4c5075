/*
 * error.h: the error record that every module below main.c fills in place of
 * printing.
 *
 * A module that fails returns a status and describes the failure here: which
 * file, where in it (when the fault has a position), and a message that says
 * what was expected and what was found. Only main.c turns a record into text
 * on the terminal. The record owns no heap memory: copy it, drop it, reuse it.
 * The bytes of user input it keeps (the file name, the excerpt) are shown
 * safely: control bytes and invalid UTF-8 as \xNN (error_escape()).
 */
#ifndef RAYTRACE_ERROR_H
#define RAYTRACE_ERROR_H

#include <stddef.h>

enum {
    ERROR_FILE_MAX = 1024,   /* longest file name kept; longer ones are cut */
    ERROR_MESSAGE_MAX = 512, /* longest message kept */
    ERROR_EXCERPT_MAX = 720  /* longest excerpt of the offending line kept */
};

typedef struct {
    char file[ERROR_FILE_MAX];       /* file at fault, "" when none */
    int line;                        /* 1-based line, 0 when no position */
    int column;                      /* 1-based byte column, 0 when no position */
    char message[ERROR_MESSAGE_MAX]; /* what was expected, what was found */
    char excerpt[ERROR_EXCERPT_MAX]; /* the offending line or a window of it,
                                        shown safely (error_escape()) */
    int caret;                       /* byte offset of column in excerpt */
} Error;

/* Copies the len bytes at src to dst (size bytes, NUL-terminated, cut on
 * a whole character when short), safe to print on a terminal: valid UTF-8
 * kept (a French file name reads right), tabs kept when keep_tabs, and any
 * other control byte or byte that is not part of valid UTF-8 written as
 * \xNN. Returns the length of dst; stores in *used (unless NULL) how many
 * bytes of src it holds. */
size_t error_escape(char *dst, size_t size, const char *src, size_t len, int keep_tabs,
                    size_t *used);

/* Lets the compiler check a printf-style format: C99's printf (MinGW-w64's
 * own, which the Windows build uses, not Microsoft's). */
#if defined(__MINGW32__)
#define ERROR_FORMAT(fmt, args) __attribute__((format(gnu_printf, fmt, args)))
#elif defined(__GNUC__)
#define ERROR_FORMAT(fmt, args) __attribute__((format(printf, fmt, args)))
#else
#define ERROR_FORMAT(fmt, args)
#endif

/* Records an error about file (may be NULL) with no position in it. */
void error_set(Error *err, const char *file, const char *fmt, ...)
    ERROR_FORMAT(3, 4)
    ;

/* Records an error at line:column of file, keeping an excerpt of the len
 * bytes of that line starting at text (which need not be NUL-terminated). */
void error_set_at(Error *err, const char *file, int line, int column, const char *text,
                  size_t len, const char *fmt, ...)
    ERROR_FORMAT(7, 8)
    ;

#endif
