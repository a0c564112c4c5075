/* power.c: a deterministic x^y (see power.h). */
#include "math/power.h"

#include <math.h>

/* ln 2 in two parts: LN2_HI has its low bits zero, so k * LN2_HI is exact
 * for |k| < 2^11. */
#define POWER_LN2_HI 0x1.62e42fefa3800p-1
#define POWER_LN2_LO 0x1.ef35793c76730p-45

/* Returns ln x as e ln 2 + ln m with x = m 2^e, m near 1. */
double power_log(double x)
{
    int e;
    double m = frexp(x, &e), s, s2, term, sum;

    if (m < 0.70710678118654752440) {
        m *= 2;
        e--;
    }
    /* ln m = 2 atanh(s), s = (m - 1) / (m + 1), |s| <= 0.1716: the terms
     * after s^27 / 27 are below 1e-21. */
    s = (m - 1) / (m + 1);
    s2 = s * s;
    term = s;
    sum = s;
    for (int k = 1; k <= 13; k++) {
        term *= s2;
        sum += term / (2 * k + 1);
    }
    return e * POWER_LN2_HI + (e * POWER_LN2_LO + 2 * sum);
}

/* Returns e^z for -800 < z <= 0. */
static double power_exp(double z)
{
    double k = floor(z / POWER_LN2_HI + 0.5), r, term = 1, sum = 1;

    /* z = k ln 2 + r with |r| <= ln 2 / 2 (plus rounding): r^18 / 18! is
     * below 1e-21. */
    r = (z - k * POWER_LN2_HI) - k * POWER_LN2_LO;
    for (int n = 1; n <= 18; n++) {
        term *= r / n;
        sum += term;
    }
    return ldexp(sum, (int)k);
}

double power(double x, double y)
{
    double n = floor(y), f = y - n, result = 1, base = x;

    if (y == 0 || x == 1)
        return 1;
    if (x == 0)
        return 0;
    /* x^n by squaring: a product of at most 50 squares of x. */
    while (n >= 1 && result > 0) {
        double half = floor(n / 2);
        if (n != 2 * half)
            result *= base;
        base *= base;
        n = half;
    }
    if (f > 0 && result > 0)
        result *= power_exp(f * power_log(x));
    return result;
}
