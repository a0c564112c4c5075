/* test_angle.c: the deterministic trigonometry and power against libm. */
#include <math.h>

#include "math/angle.h"
#include "math/power.h"
#include "rng.h"
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

static void angle_tan_matches_libm(void)
{
    double worst = 0;

    /* Relative error, up to 1e-9 short of pi / 2 where tan is 1e9. */
    for (int i = 0; i < 2000; i++) {
        double x = (ANGLE_PI / 2 - 1e-9) * i / 1999;
        worst = fmax(worst, fabs(angle_tan(x) - tan(x)) / fmax(tan(x), 1e-300));
    }
    CHECK(worst <= 4e-15);
    CHECK_NEAR(0, angle_tan(0), 0);
    CHECK_NEAR(1, angle_tan(ANGLE_PI / 4), 2e-16);
}

/* power_log() is ln within a few units in the last place, from 1e-300 to
 * 1e300 (the spp map's ratios of sample counts among them). */
static void power_log_matches_libm(void)
{
    double worst = 0;

    for (int i = 0; i < 100000; i++) {
        double x = rng_log_scale(-300, 300), want = log(x), got = power_log(x);
        double err = fabs(got - want) / (fabs(want) > 1e-300 ? fabs(want) : 1);
        worst = err > worst ? err : worst;
    }
    CHECK_NEAR(0, worst, 1e-15);
    CHECK_NEAR(0, power_log(1), 0);
    CHECK_NEAR(log(1024.0 / 21), power_log(1024.0 / 21), 4e-16);
}

static void power_matches_libm(void)
{
    double worst = 0;

    /* Relative error over the Blinn-Phong range: cosines in [0, 1], down to
     * 1e-300, exponents whole and fractional up to 1000. */
    for (int i = 0; i < 200000; i++) {
        double x = rng_uniform(), y = i % 2 ? floor(rng_range(0, 200)) : rng_range(0, 1000);
        double want;
        if (i % 3 == 0)
            x = pow(x, 40); /* down to tiny values */
        if (i % 5 == 0)
            y = rng_uniform();
        want = pow(x, y);
        if (want > 1e-290)
            worst = fmax(worst, fabs(power(x, y) - want) / want);
    }
    CHECK(worst <= 1e-13);
    CHECK_NEAR(1, power(0, 0), 0);
    CHECK_NEAR(1, power(0.3, 0), 0);
    CHECK_NEAR(0, power(0, 2.5), 0);
    CHECK_NEAR(1, power(1, 1e15), 0);
    CHECK_NEAR(0.25, power(0.5, 2), 0);             /* exact: two factors */
    CHECK_NEAR(sqrt(0.5), power(0.5, 0.5), 2e-16);
    CHECK_NEAR(0, power(0.999, 1e15), 0);           /* underflows, in 50 squarings */
}

const TestCase angle_tests[] = {
    {"angle_tan_matches_libm", angle_tan_matches_libm},
    {"power_matches_libm", power_matches_libm},
    {"power_log_matches_libm", power_log_matches_libm},
    {"angle_sincos_matches_libm", angle_sincos_matches_libm},
    {"angle_atan2_and_acos_match_libm", angle_atan2_and_acos_match_libm},
    {NULL, NULL},
};
