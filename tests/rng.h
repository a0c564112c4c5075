/*
 * rng.h: a small fixed random stream for tests, so that every run tests the
 * same cases (splitmix64), and the random geometry built from it. Each test
 * file that includes it gets its own stream.
 */
#ifndef RAYTRACE_TEST_RNG_H
#define RAYTRACE_TEST_RNG_H

#include <math.h>
#include <stddef.h>
#include <stdint.h>

#include "math/vec3.h"

static uint64_t rng_state = 0x2545F4914F6CDD1DULL;

/* Returns a number in [0, 1). */
static inline double rng_uniform(void)
{
    uint64_t z = (rng_state += 0x9E3779B97F4A7C15ULL);
    z = (z ^ (z >> 30)) * 0xBF58476D1CE4E5B9ULL;
    z = (z ^ (z >> 27)) * 0x94D049BB133111EBULL;
    z ^= z >> 31;
    return (double)(z >> 11) * 0x1p-53;
}

/* Returns a number in [lo, hi). */
static inline double rng_range(double lo, double hi)
{
    return lo + (hi - lo) * rng_uniform();
}

/* Returns a unit vector, uniform over the sphere. */
static inline Vec3 rng_unit_vector(void)
{
    double z = rng_range(-1, 1), a = rng_range(0, 6.283185307179586), r = sqrt(1 - z * z);
    return vec3(r * cos(a), r * sin(a), z);
}

/* Returns 10^x for x uniform in [lo_exp, hi_exp). */
static inline double rng_log_scale(double lo_exp, double hi_exp)
{
    return pow(10, rng_range(lo_exp, hi_exp));
}

/* Returns a unit direction at an angle of cosine c to the unit vector n. */
static inline Vec3 rng_direction_at_cosine(Vec3 n, double c)
{
    Vec3 t = vec3_normalize(vec3_cross(n, rng_unit_vector()));
    return vec3_normalize(vec3_add(vec3_scale(n, c), vec3_scale(t, sqrt(1 - c * c))));
}

/* Writes into buf a decimal spelling of 1 to max_digits digits (each 0 at
 * least zero_share of the time), a sign first sign_share of the time, and
 * the point before any digit, after the last, or nowhere; returns its
 * length (no NUL: at most max_digits + 2 bytes). */
static inline size_t rng_decimal(char *buf, int max_digits, double sign_share, double zero_share)
{
    size_t n = 0;
    int digits = 1 + (int)(rng_uniform() * max_digits);
    int point = (int)(rng_uniform() * (digits + 2)); /* digits + 1: none */

    if (rng_uniform() < sign_share)
        buf[n++] = rng_uniform() < 0.5 ? '-' : '+';
    for (int k = 0; k < digits; k++) {
        if (k == point)
            buf[n++] = '.';
        buf[n++] = (char)('0' + (rng_uniform() < zero_share ? 0 : (int)(rng_uniform() * 10)));
    }
    if (point == digits)
        buf[n++] = '.';
    return n;
}

#endif
