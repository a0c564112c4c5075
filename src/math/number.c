/* number.c: decimal numbers (see number.h). */
#include "math/number.h"

#include <ctype.h>
#include <float.h>
#include <math.h>
#include <stdint.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>

int number_word_is(const char *s, size_t len, const char *c)
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
static NumberStatus number_non_decimal(const char *s, size_t len)
{
    if (len > 0 && (s[0] == '+' || s[0] == '-')) {
        s++;
        len--;
    }
    if (number_word_is(s, len, "inf") || number_word_is(s, len, "infinity") ||
        number_word_is(s, len, "nan") ||
        (len > 4 && number_word_is(s, 4, "nan(") && s[len - 1] == ')'))
        return NUMBER_NONFINITE;
    if (len > 2 && s[0] == '0' && (s[1] == 'x' || s[1] == 'X'))
        return NUMBER_HEX;
    return NUMBER_SYNTAX;
}

static int number_digit(char c)
{
    return c >= '0' && c <= '9';
}

/* The powers of ten a double holds exactly (Clinger's fast path). */
static const double number_powers[] = {1e0,  1e1,  1e2,  1e3,  1e4,  1e5,  1e6,  1e7,
                                       1e8,  1e9,  1e10, 1e11, 1e12, 1e13, 1e14, 1e15,
                                       1e16, 1e17, 1e18, 1e19, 1e20, 1e21, 1e22};

size_t number_scan_plain(const char *s, const char *end, double *out)
{
    const char *p = s;
    int negative = 0, significant = 0, point = 0, digits = 0, fraction = 0;
    uint64_t m = 0;
    double v;

    if (FLT_EVAL_METHOD != 0)
        return 0;
    if (p < end && (*p == '+' || *p == '-'))
        negative = *p++ == '-';
    for (; p < end; p++) {
        if (*p == '.' && !point) {
            point = 1;
            continue;
        }
        if (!number_digit(*p))
            break;
        digits++;
        fraction += point;
        if (m == 0 && *p == '0')
            continue;
        if (++significant > 15)
            return 0;
        m = m * 10 + (uint64_t)(*p - '0');
    }
    if (digits == 0 || fraction > 22 || (p < end && (*p == 'e' || *p == 'E')))
        return 0;
    /* As number_parse()'s fast path: m / 10^fraction, one rounding. */
    v = m == 0 ? 0 : (double)m / number_powers[fraction];
    *out = negative ? -v : v;
    return (size_t)(p - s);
}

/*
 * number -> [+-] (digits ['.' digits*] | '.' digits) [('e'|'E') [+-] digits]
 * Converts the len bytes at s to *out, correctly rounded, when they spell a
 * number of this form whose value is finite, at most NUMBER_MAX_MAGNITUDE in
 * magnitude, and zero or a normal double.
 *
 * One pass checks the form and gathers the digits. Clinger's fast path:
 * when the digits, leading zeros aside, are at most 15 (their integer m is
 * then exact in a double) and the decimal exponent e is at most 22 in
 * magnitude (10^22 is the largest power of ten a double holds exactly),
 * m * 10^e or m / 10^-e is one correctly rounded operation on exact
 * operands: the correctly rounded value, as strtod() gives. Other numbers
 * (and every number where doubles are evaluated in wider precision, which
 * would round twice) go to strtod().
 */
NumberStatus number_parse(const char *s, size_t len, double *out)
{
    const double *powers = number_powers;
    size_t i = 0, digits = 0;
    int negative = 0, nonzero = 0, significant = 0, fast = FLT_EVAL_METHOD == 0;
    long fraction = 0, exponent = 0, e;
    uint64_t m = 0;
    char small[64], *buf;
    double v;

    if (i < len && (s[i] == '+' || s[i] == '-'))
        negative = s[i++] == '-';
    for (int point = 0;; i++) {
        if (i < len && s[i] == '.' && !point) {
            point = 1;
            continue;
        }
        if (i == len || !number_digit(s[i]))
            break;
        digits++;
        fraction += point;
        if (m == 0 && s[i] == '0')
            continue;
        nonzero = 1;
        if (++significant > 15)
            fast = 0;
        else
            m = m * 10 + (uint64_t)(s[i] - '0');
    }
    if (digits == 0)
        return number_non_decimal(s, len);
    if (i < len && (s[i] == 'e' || s[i] == 'E')) {
        size_t exp_digits = 0;
        int minus = 0;
        i++;
        if (i < len && (s[i] == '+' || s[i] == '-'))
            minus = s[i++] == '-';
        for (; i < len && number_digit(s[i]); i++, exp_digits++)
            if (exponent < 1000)
                exponent = exponent * 10 + (s[i] - '0');
        if (exp_digits == 0)
            return NUMBER_SYNTAX;
        if (exponent >= 1000) /* clamped, so unknown: strtod() reads it */
            fast = 0;
        if (minus)
            exponent = -exponent;
    }
    if (i != len)
        return number_non_decimal(s, len);

    e = exponent - fraction;
    if (fast && m == 0) {
        v = 0;
    } else if (fast && e >= -22 && e <= 22) {
        v = e < 0 ? (double)m / powers[-e] : (double)m * powers[e];
    } else {
        buf = len < sizeof small ? small : malloc(len + 1);
        if (!buf)
            return NUMBER_NO_MEMORY;
        memcpy(buf, s, len);
        buf[len] = '\0';
        v = strtod(buf, NULL);
        if (buf != small)
            free(buf);
        negative = 0; /* strtod() kept the sign */
    }
    if (negative)
        v = -v;
    if (!(fabs(v) <= NUMBER_MAX_MAGNITUDE))
        return NUMBER_TOO_LARGE;
    if ((v == 0 && nonzero) || (v != 0 && fabs(v) < DBL_MIN))
        return NUMBER_UNDERFLOW;
    *out = v;
    return NUMBER_OK;
}

char *number_format(char *buf, double x)
{
    const char *e;

    for (int digits = 1; digits <= 17; digits++) {
        double back;
        snprintf(buf, NUMBER_FORMAT_MAX, "%.*g", digits, x);
        if (number_parse(buf, strlen(buf), &back) == NUMBER_OK &&
            memcmp(&back, &x, sizeof x) == 0)
            break;
    }
    /* 1e+01 reads better as 10: the same digits, padded with zeros. */
    e = strchr(buf, 'e');
    if (e && e[1] == '+') {
        int exponent = atoi(e + 2);
        if (exponent < 17)
            snprintf(buf, NUMBER_FORMAT_MAX, "%.*g", exponent + 1, x);
    }
    return buf;
}

char *number_bytes(char *buf, size_t bytes)
{
    static const char *const units[] = {"KiB", "MiB", "GiB", "TiB", "PiB", "EiB"};
    double v = (double)bytes;
    int u = -1;

    if (bytes < 1024) {
        snprintf(buf, NUMBER_FORMAT_MAX, "%zu byte%s", bytes, bytes == 1 ? "" : "s");
        return buf;
    }
    while (v >= 1024 && u < 5) {
        v /= 1024;
        u++;
    }
    snprintf(buf, NUMBER_FORMAT_MAX, "%.4g %s", v, units[u]);
    return buf;
}
