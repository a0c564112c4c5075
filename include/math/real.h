/*
 * real.h: the floating-point type of the geometry: double, or float when
 * built with `make REAL=float` (-DRAYTRACE_REAL_FLOAT).
 *
 * Points, directions, ray parameters, intersections, error bounds and the
 * hierarchy's boxes are `real`; colours, texture coordinates, parsing and
 * output stay double. Every rounding-error bound is written in REAL_EPSILON,
 * so each build's offsets and margins are those of its own precision.
 * <tgmath.h> makes sqrt, fabs and the rest take the type of their argument.
 * docs/trade.md measures float against double; double is the default
 * because only it renders the examples exactly (docs/design.md).
 */
#ifndef RAYTRACE_REAL_H
#define RAYTRACE_REAL_H

#include <float.h>
#include <stdint.h>
#include <string.h>
#include <tgmath.h>

#ifdef RAYTRACE_REAL_FLOAT
typedef float real;
typedef uint32_t real_bits; /* an unsigned integer of real's width */
#define REAL_EPSILON FLT_EPSILON
#define REAL_MAX FLT_MAX
#define REAL_TRUE_MIN FLT_TRUE_MIN
#define REAL_NAME "float"
#else
typedef double real;
typedef uint64_t real_bits;
#define REAL_EPSILON DBL_EPSILON
#define REAL_MAX DBL_MAX
#define REAL_TRUE_MIN DBL_TRUE_MIN
#define REAL_NAME "double"
#endif

/* Returns pbrt's gamma(n) = n u / (1 - n u), u = REAL_EPSILON / 2: a bound
 * on the relative error of n roundings, used for the shapes' error bounds. */
static inline real real_gamma(real n)
{
    real u = REAL_EPSILON / 2;

    return n * u / (1 - n * u);
}

/* Returns the real next to x, a finite real, above it (up = 1) or below it
 * (up = 0): what nextafter() returns, stepped on the bits without a libm
 * call. */
static inline real real_next(real x, int up)
{
    real_bits bits;

    if (x == 0)
        return up ? REAL_TRUE_MIN : -REAL_TRUE_MIN;
    memcpy(&bits, &x, sizeof bits);
    /* Away from zero adds one to the magnitude's bits, towards it takes one. */
    bits += (x > 0) == (up != 0) ? 1 : (real_bits)-1;
    memcpy(&x, &bits, sizeof x);
    return x;
}

#endif
