/*
 * test.h: the unit-test harness, read in one sitting.
 *
 * A test is a void function; a suite is a NULL-terminated array of TestCase
 * that tests/unit.c lists. Checks report the file, line, and what was
 * expected and found, then let the test go on; a test passes when none of
 * its checks failed.
 */
#ifndef RAYTRACE_TEST_H
#define RAYTRACE_TEST_H

#include <string.h>

typedef struct {
    const char *name;  /* shown in reports, matched by the name filter */
    void (*run)(void); /* the test */
} TestCase;

extern int test_failed_checks; /* failed checks in the running test */

/* Reports a failed check at file:line (used by the macros). */
void test_fail(const char *file, int line, const char *fmt, ...);

/* Checks that cond holds. */
#define CHECK(cond)                                                                           \
    do {                                                                                      \
        if (!(cond))                                                                          \
            test_fail(__FILE__, __LINE__, "CHECK(%s)", #cond);                                \
    } while (0)

/* Checks |expected - got| <= tol, printing all three otherwise. */
#define CHECK_NEAR(expected, got, tol)                                                        \
    test_check_near(__FILE__, __LINE__, #got, (expected), (got), (tol))
void test_check_near(const char *file, int line, const char *expr, double expected, double got,
                     double tol);

/* Checks that two integers are equal, printing both otherwise. */
#define CHECK_INT(expected, got) test_check_int(__FILE__, __LINE__, #got, (expected), (got))
void test_check_int(const char *file, int line, const char *expr, long long expected,
                    long long got);

/* Checks that string haystack contains needle, printing both otherwise. */
#define CHECK_CONTAINS(haystack, needle)                                                      \
    test_check_contains(__FILE__, __LINE__, #haystack, (haystack), (needle))
void test_check_contains(const char *file, int line, const char *expr, const char *haystack,
                         const char *needle);

/* Checks that err, an Error (error.h), is at line:column with exactly
 * message; `what` names the case in the report. */
#define CHECK_ERROR(what, err, line, column, message)                                          \
    test_check_error(__FILE__, __LINE__, (what), (err), (line), (column), (message))
void test_check_error(const char *file, int line, const char *what, const void *err,
                      int want_line, int want_column, const char *want_message);

/* Returns n, the trials of a random test in full (make check), or a tenth
 * of them, at least one, in the quick suite (make test, which sets
 * RAYTRACE_TEST_LEVEL=quick). */
int test_trials(int n);

#endif
