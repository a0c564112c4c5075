/* angle.c: deterministic trigonometry (see angle.h). */
#include "math/angle.h"

#include <math.h>

void angle_sincos(double x, double *s, double *c)
{
    /* Taylor series: at |x| = pi / 4 the terms after x^19 / 19! and
     * x^20 / 20! are below 1e-19. */
    double x2 = x * x, ts = x, tc = 1, ss = x, cs = 1;

    for (int k = 1; k <= 10; k++) {
        ts *= -x2 / ((2 * k) * (2 * k + 1));
        tc *= -x2 / ((2 * k - 1) * (2 * k));
        ss += ts;
        cs += tc;
    }
    *s = ss;
    *c = cs;
}

double angle_tan(double x)
{
    double s, c;

    /* Above pi / 4, tan x = 1 / tan(pi / 2 - x); pi / 2 - x is exact
     * (Sterbenz) with pi / 2 taken to twice the precision of a double. */
    const double pio2_lo = 6.123233995736766036e-17; /* pi / 2 - (double)(pi / 2) */

    if (x <= ANGLE_PI / 4) {
        angle_sincos(x, &s, &c);
        return s / c;
    }
    angle_sincos((ANGLE_PI / 2 - x) + pio2_lo, &s, &c);
    return c / s;
}

/* Returns atan(x) for |x| <= 1. */
static double angle_atan_unit(double x)
{
    const double tan_pi_8 = 0.41421356237309504880;
    double base = 0, z, z2, term, sum;

    /* atan(x) = pi/4 + atan((x - 1) / (x + 1)) brings |x| below tan(pi/8). */
    if (x > tan_pi_8) {
        base = ANGLE_PI / 4;
        x = (x - 1) / (x + 1);
    } else if (x < -tan_pi_8) {
        base = -ANGLE_PI / 4;
        x = (x + 1) / (1 - x);
    }
    /* z^(2k+1) / (2k+1) is below 1e-19 by k = 24 for |z| <= 0.4143. */
    z = x;
    z2 = z * z;
    term = z;
    sum = z;
    for (int k = 1; k <= 24; k++) {
        term *= -z2;
        sum += term / (2 * k + 1);
    }
    return base + sum;
}

double angle_atan2(double y, double x)
{
    double a;

    if (x == 0 && y == 0)
        return 0;
    if (fabs(x) >= fabs(y)) {
        a = angle_atan_unit(y / x);
        if (x < 0)
            a += y >= 0 ? ANGLE_PI : -ANGLE_PI;
        return a;
    }
    return (y > 0 ? ANGLE_PI / 2 : -ANGLE_PI / 2) - angle_atan_unit(x / y);
}

double angle_acos(double x)
{
    x = x > 1 ? 1 : x < -1 ? -1 : x;
    /* (1 - x)(1 + x) does not cancel near x = +-1 as 1 - x^2 would. */
    return angle_atan2(sqrt((1 - x) * (1 + x)), x);
}
