/* test_angle.c: the deterministic trigonometry against libm. */
#include <math.h>

#include "angle.h"
#include "test.h"

static void angle_sincos_matches_libm(void)
{
    double worst = 0;

    for (int i = -1000; i <= 1000; i++) {
        double x = ANGLE_PI / 4 * i / 1000, s, c;
        angle_sincos(x, &s, &c);
        worst = fmax(worst, fmax(fabs(s - sin(x)), fabs(c - cos(x))));
    }
    CHECK(worst <= 4e-16);
}

static void angle_atan2_and_acos_match_libm(void)
{
    double worst = 0;

    for (int i = 0; i < 3600; i++) {
        double a = 2 * ANGLE_PI * i / 3600 - ANGLE_PI, r = 1 + i % 7;
        double x = r * cos(a), y = r * sin(a);
        double d = fabs(angle_atan2(y, x) - atan2(y, x));
        /* At +-pi the two may pick either sign. */
        worst = fmax(worst, fmin(d, fabs(d - 2 * ANGLE_PI)));
    }
    for (int i = -1000; i <= 1000; i++)
        worst = fmax(worst, fabs(angle_acos(i / 1000.0) - acos(i / 1000.0)));
    CHECK(worst <= 2e-15);
    CHECK_NEAR(0, angle_atan2(0, 0), 0);
    CHECK_NEAR(ANGLE_PI / 2, angle_atan2(5, 0), 0);
    CHECK_NEAR(0, angle_acos(1), 0);
    CHECK_NEAR(ANGLE_PI, angle_acos(-2), 0);
}

const TestCase angle_tests[] = {
    {"angle_sincos_matches_libm", angle_sincos_matches_libm},
    {"angle_atan2_and_acos_match_libm", angle_atan2_and_acos_match_libm},
    {NULL, NULL},
};
