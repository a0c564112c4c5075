/*
 * number.h: the decimal numbers of scene and mesh files.
 *
 *   number -> [+-] (digits ['.' digits*] | '.' digits) [('e'|'E') [+-] digits]
 *
 * parsed independently of the locale and correctly rounded; inf, nan, hex
 * floats, magnitudes above NUMBER_MAX_MAGNITUDE and values too small for a
 * normal double are refused, each with its own status so that messages can
 * say why.
 */
#ifndef RAYTRACE_NUMBER_H
#define RAYTRACE_NUMBER_H

#include <stddef.h>

#define NUMBER_MAX_MAGNITUDE 1e15 /* largest accepted |number| */

typedef enum {
    NUMBER_OK,
    NUMBER_SYNTAX,    /* not a decimal number */
    NUMBER_NONFINITE, /* inf, nan */
    NUMBER_HEX,       /* 0x... */
    NUMBER_TOO_LARGE, /* |x| > NUMBER_MAX_MAGNITUDE, or overflows */
    NUMBER_UNDERFLOW, /* non-zero digits, but below the smallest normal double */
    NUMBER_NO_MEMORY
} NumberStatus;

/* Says whether the len bytes at s spell word, a lower-case C string, in
 * any case ("NaN" is "nan"). */
int number_word_is(const char *s, size_t len, const char *word);

/* Converts the len bytes at s to *out when they spell a number of the form
 * above whose value is finite, at most NUMBER_MAX_MAGNITUDE in magnitude,
 * and zero or a normal double; otherwise says what is wrong. */
NumberStatus number_parse(const char *s, size_t len, double *out);

/* Reads from s (up to end) a number of the plainest form, [+-] digits
 * ['.' digits*] or [+-] '.' digits, of at most 15 significant digits and
 * 22 after the point, which ends at end or at a byte that cannot continue
 * it (nor an exponent's 'e'): stores in *out exactly what number_parse()
 * gives for it and returns its length; returns 0 for any other form
 * (number_parse() then reads it, or says what is wrong). */
size_t number_scan_plain(const char *s, const char *end, double *out);

enum { NUMBER_FORMAT_MAX = 32 }; /* room number_format() needs */

/* Writes into buf (NUMBER_FORMAT_MAX bytes) the shortest decimal, in
 * printf's %g form, that number_parse() reads back as exactly x (sign of
 * zero included): at most 17 significant digits. x must be one that
 * number_parse() accepts. Returns buf. */
char *number_format(char *buf, double x);

/* Writes the size of `bytes` for people into buf (NUMBER_FORMAT_MAX bytes):
 * "812 bytes", "200 KiB", "1.5 MiB", "9.002 GiB" (4 digits at most); returns
 * buf. */
char *number_bytes(char *buf, size_t bytes);

#endif
