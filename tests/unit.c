/*
 * unit.c: runs the unit-test suites.
 *
 * Usage: unit [NAME...]  runs the tests whose names contain one of the
 * NAMEs (all tests when none is given), prints each failed check, then
 * "N passed, N failed"; exits 1 when a test failed or none matched.
 */
#include <math.h>
#include <stdarg.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>

#include "base/error.h"
#include "test.h"

/* Every suite: suites.h, made by the Makefile from the files' names,
 * lists X(NAME) for each tests/test_NAME.c, which defines NAME_tests[]. */
#define X(name) extern const TestCase name##_tests[];
#include "suites.h"
#undef X
static const TestCase *const unit_suites[] = {
#define X(name) name##_tests,
#include "suites.h"
#undef X
};

int test_failed_checks;
static const char *unit_current; /* name of the running test */

void test_fail(const char *file, int line, const char *fmt, ...)
{
    va_list ap;

    fprintf(stderr, "%s:%d: %s: ", file, line, unit_current);
    va_start(ap, fmt);
    vfprintf(stderr, fmt, ap);
    va_end(ap);
    fputc('\n', stderr);
    test_failed_checks++;
}

void test_check_near(const char *file, int line, const char *expr, double expected, double got,
                     double tol)
{
    if (!(fabs(expected - got) <= tol))
        test_fail(file, line, "%s: expected %.17g, got %.17g (tolerance %.3g)", expr, expected,
                  got, tol);
}

void test_check_int(const char *file, int line, const char *expr, long long expected,
                    long long got)
{
    if (expected != got)
        test_fail(file, line, "%s: expected %lld, got %lld", expr, expected, got);
}

void test_check_contains(const char *file, int line, const char *expr, const char *haystack,
                         const char *needle)
{
    if (!strstr(haystack, needle))
        test_fail(file, line, "%s: expected to contain \"%s\", got \"%s\"", expr, needle,
                  haystack);
}

void test_check_error(const char *file, int line, const char *what, const void *err,
                      int want_line, int want_column, const char *want_message)
{
    const Error *e = err;

    if (strcmp(e->message, want_message) != 0 || e->line != want_line ||
        e->column != want_column)
        test_fail(file, line, "%s: expected %d:%d \"%s\", got %d:%d \"%s\"", what, want_line,
                  want_column, want_message, e->line, e->column, e->message);
}

int test_trials(int n)
{
    const char *level = getenv("RAYTRACE_TEST_LEVEL");

    return level && strcmp(level, "quick") == 0 ? (n + 9) / 10 : n;
}

/* Says whether name is selected by the filters in argv[1..argc-1]. */
static int unit_selected(const char *name, int argc, char **argv)
{
    if (argc < 2)
        return 1;
    for (int i = 1; i < argc; i++)
        if (strstr(name, argv[i]))
            return 1;
    return 0;
}

int main(int argc, char **argv)
{
    int passed = 0, failed = 0;

    for (size_t s = 0; s < sizeof unit_suites / sizeof unit_suites[0]; s++) {
        for (const TestCase *t = unit_suites[s]; t->name; t++) {
            if (!unit_selected(t->name, argc, argv))
                continue;
            unit_current = t->name;
            test_failed_checks = 0;
            t->run();
            if (test_failed_checks == 0) {
                passed++;
            } else {
                failed++;
                fprintf(stderr, "FAIL %s\n", t->name);
            }
        }
    }
    printf("%d passed, %d failed\n", passed, failed);
    if (passed + failed == 0)
        fprintf(stderr, "unit: no test matches\n");
    return failed > 0 || passed == 0;
}
