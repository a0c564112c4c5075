/* test_number.c: numbers read and written exactly, whatever the C library
 * (math/number.h): the hard cases, which go to its strtod(), come out
 * correctly rounded, and the shortest digits --save writes (its printf)
 * read back to the same bits. make test-windows and make test-musl run
 * these on MinGW-w64's and musl's libraries. */
#include <float.h>
#include <stdint.h>
#include <string.h>

#include "math/number.h"
#include "rng.h"
#include "test.h"

/* Says whether a and b are the same double, bit for bit. */
static int number_same(double a, double b)
{
    return memcmp(&a, &b, sizeof a) == 0;
}

/* Digits past Clinger's fast path, halfway cases, the smallest normal, long
 * tails that decide the last bit: each the correctly rounded double. */
static void number_hard_cases_read_correctly_rounded(void)
{
    static const struct {
        const char *text;
        double value;
    } cases[] = {
        {"0.1", 0x1.999999999999ap-4},
        {"562949953421312.0625", 0x1.0000000000000p+49}, /* halfway: to even */
        {"562949953421312.1875", 0x1.0000000000002p+49},
        {"562949953421312.06250000000000001", 0x1.0000000000001p+49},
        {"2.2250738585072014e-308", 0x1.0000000000000p-1022},
        {"1.00000000000000011102230246251565404236316680908203125", 0x1.0000000000000p+0},
        {"1.00000000000000011102230246251565404236316680908203126", 0x1.0000000000001p+0},
        {"123456789012345678901234567890e-25", 0x1.81cd6e63c53d7p+13},
        {"0.000000000000000000000000000000000001234567890123456789", 0x1.a41a07f2ab972p-120},
        {"7.0710678118654752440084436210484903928483593768847e-1", 0x1.6a09e667f3bcdp-1},
        {"3.14159265358979323846264338327950288", 0x1.921fb54442d18p+1},
        {"999999999999999.99999999", 0x1.c6bf526340000p+49},
        {"1e-300", 0x1.56e1fc2f8f359p-997},
        {"2.4703282292062328e-300", 0x1.a784379d99db4p-996},
        {"1.7976931348623157e-290", 0x1.66ca74a3a3b52p-963},
        {"0.30000000000000004", 0x1.3333333333334p-2},
        {"602214076e-9", 0x1.3455674338c27p-1},
        {"1234567.000000000000000000001", 0x1.2d68700000000p+20},
        {"-4.35e-35", -0x1.ce92438116b23p-115},
    };

    for (size_t i = 0; i < sizeof cases / sizeof cases[0]; i++) {
        double got = 0;
        CHECK_INT(NUMBER_OK, number_parse(cases[i].text, strlen(cases[i].text), &got));
        if (!number_same(cases[i].value, got))
            test_fail(__FILE__, __LINE__, "%s read as %a, expected %a", cases[i].text, got,
                      cases[i].value);
    }
}

/* The text --save writes: C99's %g, two-digit exponents, the fewest
 * digits that read back. */
static void number_format_writes_the_shortest_text(void)
{
    static const struct {
        double value;
        const char *text;
    } cases[] = {
        {0.1, "0.1"},
        {0.1 + 0.2, "0.30000000000000004"},
        {1e-7, "1e-07"},
        {2.5e-5, "2.5e-05"},
        {1e16, "10000000000000000"},
        {1.25e-300, "1.25e-300"},
        {1.5e14, "150000000000000"},
        {DBL_MAX, "1.7976931348623157e+308"},
        {-123456.5, "-123456.5"},
        {0x1.0000000000001p+0, "1.0000000000000002"},
    };
    char buf[NUMBER_FORMAT_MAX];

    for (size_t i = 0; i < sizeof cases / sizeof cases[0]; i++)
        if (strcmp(number_format(buf, cases[i].value), cases[i].text) != 0)
            test_fail(__FILE__, __LINE__, "%a written as \"%s\", expected \"%s\"",
                      cases[i].value, buf, cases[i].text);
}

/* 100,000 doubles of every magnitude a scene holds, written and read back. */
static void number_format_reads_back_exactly(void)
{
    char buf[NUMBER_FORMAT_MAX];
    int bad = 0;

    for (int i = 0, n = test_trials(100000); i < n; i++) {
        double x = rng_range(-1, 1) * rng_log_scale(-300, 15), back = 0;
        number_format(buf, x);
        if (number_parse(buf, strlen(buf), &back) != NUMBER_OK || !number_same(x, back)) {
            if (bad++ < 5)
                test_fail(__FILE__, __LINE__, "%a written as \"%s\" reads back as %a", x, buf,
                          back);
        }
    }
    CHECK_INT(0, bad);
}

/* number_scan_plain() reads random texts of every plain form (signs, a
 * point anywhere or nowhere, leading zeros, 1 to 24 digits, so across its
 * 15 significant and 22 fractional digits' bounds) to the same bits as
 * number_parse(), and stops where the number does; it gives up (0) on
 * other forms, which number_parse() reads by strtod() or refuses. */
static void number_scan_plain_reads_as_number_parse(void)
{
    static const char *const others[] = {"1e5", "2.5E-3", "1234567890123456", ".", "-", "+.",
                                         "x1", "inf", "0.00000000000000000000001", ""};
    int bad = 0, scanned = 0;

    for (int i = 0; i < 200000; i++) {
        char text[40];
        int n = (int)rng_decimal(text, 24, 0.4, 0.3);
        double a = 0, b = 0;
        size_t len;
        text[n] = ' '; /* where it must stop */
        len = number_scan_plain(text, text + n + 1, &a);
        if (len == 0)
            continue;
        scanned++;
        if (len != (size_t)n || number_parse(text, (size_t)n, &b) != NUMBER_OK ||
            !number_same(a, b)) {
            if (bad++ < 5)
                test_fail(__FILE__, __LINE__, "\"%.*s\": scanned %zu bytes as %a, parsed %a", n,
                          text, len, a, b);
        }
    }
    CHECK_INT(0, bad);
    CHECK(scanned > 100000); /* most of the texts are plain enough */
    for (size_t k = 0; k < sizeof others / sizeof *others; k++) {
        double v = 0;
        const char *t = others[k];
        CHECK_INT(0, (long long)number_scan_plain(t, t + strlen(t), &v));
    }
}

const TestCase number_tests[] = {
    {"number_hard_cases_read_correctly_rounded", number_hard_cases_read_correctly_rounded},
    {"number_format_writes_the_shortest_text", number_format_writes_the_shortest_text},
    {"number_format_reads_back_exactly", number_format_reads_back_exactly},
    {"number_scan_plain_reads_as_number_parse", number_scan_plain_reads_as_number_parse},
    {NULL, NULL},
};
