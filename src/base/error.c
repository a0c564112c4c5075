/* error.c: filling the error record (see error.h). */
#include "base/error.h"

#include <stdarg.h>
#include <stdio.h>
#include <string.h>

/* Bytes of context kept on each side of the column in a long line. */
#define ERROR_CONTEXT 80

static void error_copy_file(Error *err, const char *file)
{
    snprintf(err->file, sizeof err->file, "%s", file ? file : "");
}

void error_set(Error *err, const char *file, const char *fmt, ...)
{
    va_list ap;

    error_copy_file(err, file);
    err->line = 0;
    err->column = 0;
    err->excerpt[0] = '\0';
    err->caret = 0;
    va_start(ap, fmt);
    vsnprintf(err->message, sizeof err->message, fmt, ap);
    va_end(ap);
}

/* Copies a window of the line around column into err->excerpt: at most
 * ERROR_CONTEXT bytes either side, marked with "..." where cut. */
static void error_copy_excerpt(Error *err, int column, const char *text, size_t len)
{
    size_t col = column > 0 ? (size_t)column - 1 : 0;
    size_t start = col > ERROR_CONTEXT ? col - ERROR_CONTEXT : 0;
    size_t stop;
    size_t n = 0;

    if (start > len)
        start = len;
    stop = len - start > 2 * ERROR_CONTEXT ? start + 2 * ERROR_CONTEXT : len;

    if (start > 0) {
        memcpy(err->excerpt, "...", 3);
        n = 3;
    }
    err->caret = (int)(n + (col - start));
    for (size_t i = start; i < stop; i++) {
        unsigned char ch = (unsigned char)text[i];
        err->excerpt[n++] = (ch < 0x20 && ch != '\t') || ch == 0x7f ? '?' : (char)ch;
    }
    if (stop < len) {
        memcpy(err->excerpt + n, "...", 3);
        n += 3;
    }
    err->excerpt[n] = '\0';
}

void error_set_at(Error *err, const char *file, int line, int column, const char *text,
                  size_t len, const char *fmt, ...)
{
    va_list ap;

    error_copy_file(err, file);
    err->line = line;
    err->column = column;
    error_copy_excerpt(err, column, text, len);
    va_start(ap, fmt);
    vsnprintf(err->message, sizeof err->message, fmt, ap);
    va_end(ap);
}
