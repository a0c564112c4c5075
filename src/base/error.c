/* error.c: filling the error record (see error.h). */
#include "base/error.h"

#include <stdarg.h>
#include <stdio.h>
#include <string.h>

/* Bytes of context kept on each side of the column in a long line. */
#define ERROR_CONTEXT 80

/* Returns the length of the valid UTF-8 character at s (n bytes left), or
 * 0 when the bytes there are not one (RFC 3629: no overlong forms, no
 * surrogates, nothing above U+10FFFF). */
static size_t error_utf8(const unsigned char *s, size_t n)
{
    size_t len;
    unsigned char lo = 0x80, hi = 0xBF;

    if (s[0] < 0x80)
        return 1;
    if (s[0] >= 0xC2 && s[0] <= 0xDF)
        len = 2;
    else if (s[0] >= 0xE0 && s[0] <= 0xEF)
        len = 3;
    else if (s[0] >= 0xF0 && s[0] <= 0xF4)
        len = 4;
    else
        return 0;
    if (s[0] == 0xE0)
        lo = 0xA0;
    else if (s[0] == 0xED)
        hi = 0x9F;
    else if (s[0] == 0xF0)
        lo = 0x90;
    else if (s[0] == 0xF4)
        hi = 0x8F;
    if (n < len || s[1] < lo || s[1] > hi)
        return 0;
    for (size_t i = 2; i < len; i++)
        if (s[i] < 0x80 || s[i] > 0xBF)
            return 0;
    return len;
}

size_t error_escape(char *dst, size_t size, const char *src, size_t len, int keep_tabs,
                    size_t *used)
{
    const unsigned char *s = (const unsigned char *)src;
    size_t n = 0, i = 0;

    while (i < len) {
        size_t k = error_utf8(s + i, len - i);
        int plain = k > 1 || (k == 1 && ((s[i] >= 0x20 && s[i] != 0x7f) ||
                                         (keep_tabs && s[i] == '\t')));
        size_t need = plain ? k : 4;
        if (n + need + 1 > size)
            break;
        if (plain) {
            memcpy(dst + n, s + i, k);
            i += k;
        } else {
            snprintf(dst + n, 5, "\\x%02X", s[i]);
            i++;
        }
        n += need;
    }
    if (size > 0)
        dst[n] = '\0';
    if (used)
        *used = i;
    return n;
}

static void error_copy_file(Error *err, const char *file)
{
    file = file ? file : "";
    error_escape(err->file, sizeof err->file, file, strlen(file), 0, NULL);
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

/* Copies a window of the line around column into err->excerpt, shown
 * safely (error_escape()): at most ERROR_CONTEXT bytes either side, on
 * whole UTF-8 characters, marked with "..." where cut; err->caret is the
 * column's offset in it. */
static void error_copy_excerpt(Error *err, int column, const char *text, size_t len)
{
    size_t col = column > 0 ? (size_t)column - 1 : 0;
    size_t start = col > ERROR_CONTEXT ? col - ERROR_CONTEXT : 0;
    size_t stop, n = 0, size = sizeof err->excerpt - 4;

    if (start > len)
        start = len;
    if (col > len)
        col = len;
    stop = len - start > 2 * ERROR_CONTEXT ? start + 2 * ERROR_CONTEXT : len;
    /* Cut between characters, not inside one. */
    while (start > 0 && start < col && ((unsigned char)text[start] & 0xC0) == 0x80)
        start++;
    while (stop < len && stop > col && ((unsigned char)text[stop] & 0xC0) == 0x80)
        stop--;
    if (start > 0) {
        memcpy(err->excerpt, "...", 3);
        n = 3;
    }
    n += error_escape(err->excerpt + n, size - n, text + start, col - start, 1, NULL);
    err->caret = (int)n;
    n += error_escape(err->excerpt + n, size - n, text + col, stop - col, 1, NULL);
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
