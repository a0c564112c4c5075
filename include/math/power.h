/*
 * power.h: x^y for the Blinn-Phong specular term, from IEEE 754 operations
 * alone.
 *
 * libm's pow() is not correctly rounded everywhere and its last bit may
 * differ between library versions; like angle.h, this computes the power
 * from + - * / and exact scalings (frexp, ldexp), so a render gives the same
 * bytes on every machine. Integer exponents use repeated squaring; the
 * fractional part goes through a series for the logarithm and one for the
 * exponential. The result is within about 1e-13 of the true value,
 * relatively.
 */
#ifndef RAYTRACE_POWER_H
#define RAYTRACE_POWER_H

/* Returns x^y for 0 <= x <= 1 and 0 <= y <= 1e15 (0^0 = 1). */
double power(double x, double y);

/* Returns ln x for 0 < x < 2^1023, within a few units in the last place,
 * the same on every machine. */
double power_log(double x);

#endif
