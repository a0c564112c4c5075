/*
 * vec3.h: three-component vectors of reals (real.h) for points, directions
 * and normals.
 *
 * Every operation is a small static inline function so the compiler can keep
 * vectors in registers; none allocates or fails. Floating-point results are
 * reproducible because the build forbids contraction into fused multiply-adds
 * (-ffp-contract=off), so each operation rounds exactly as written here.
 */
#ifndef RAYTRACE_VEC3_H
#define RAYTRACE_VEC3_H

#include "math/real.h"

typedef struct {
    real x, y, z;
} Vec3;

/* Builds the vector (x, y, z). */
static inline Vec3 vec3(real x, real y, real z)
{
    Vec3 v = {x, y, z};
    return v;
}

/* Returns a + b. */
static inline Vec3 vec3_add(Vec3 a, Vec3 b)
{
    return vec3(a.x + b.x, a.y + b.y, a.z + b.z);
}

/* Returns a - b. */
static inline Vec3 vec3_sub(Vec3 a, Vec3 b)
{
    return vec3(a.x - b.x, a.y - b.y, a.z - b.z);
}

/* Returns s * a. */
static inline Vec3 vec3_scale(Vec3 a, real s)
{
    return vec3(s * a.x, s * a.y, s * a.z);
}

/* Returns -a. */
static inline Vec3 vec3_neg(Vec3 a)
{
    return vec3(-a.x, -a.y, -a.z);
}

/* Returns the dot product a . b, summed x, then y, then z. */
static inline real vec3_dot(Vec3 a, Vec3 b)
{
    return a.x * b.x + a.y * b.y + a.z * b.z;
}

/* Returns the cross product a x b. */
static inline Vec3 vec3_cross(Vec3 a, Vec3 b)
{
    return vec3(a.y * b.z - a.z * b.y, a.z * b.x - a.x * b.z, a.x * b.y - a.y * b.x);
}

/* Returns the Euclidean length of a. */
static inline real vec3_length(Vec3 a)
{
    return sqrt(vec3_dot(a, a));
}

/* Returns a / |a|; the zero vector yields non-finite components. */
static inline Vec3 vec3_normalize(Vec3 a)
{
    return vec3_scale(a, (real)1 / vec3_length(a));
}

/* Returns 1 when a and b are the same point (coordinate by coordinate, so
 * -0 equals 0), else 0. */
static inline int vec3_equal(Vec3 a, Vec3 b)
{
    return a.x == b.x && a.y == b.y && a.z == b.z;
}

/* Returns the component-wise absolute value of a. */
static inline Vec3 vec3_abs(Vec3 a)
{
    return vec3(fabs(a.x), fabs(a.y), fabs(a.z));
}

/* Returns the largest absolute value among a's components. */
static inline real vec3_max_abs(Vec3 a)
{
    return fmax(fabs(a.x), fmax(fabs(a.y), fabs(a.z)));
}

/* Returns the k for which m * 2^k lies in [0.5, 1), for finite m > 0: the
 * exact change of unit that brings the magnitude m near 1. */
static inline int vec3_unit_exponent(real m)
{
    int e;
    frexp(m, &e);
    return -e;
}

/* Returns a * 2^k, exactly (barring overflow and underflow). */
static inline Vec3 vec3_ldexp(Vec3 a, int k)
{
    if (k == 0) /* the common case, without libm's three calls */
        return a;
    return vec3(ldexp(a.x, k), ldexp(a.y, k), ldexp(a.z, k));
}

/* Returns the unit vector along a (non-zero), scaling a by a power of two
 * first so that the squares of tiny or huge components stay in range. */
static inline Vec3 vec3_direction(Vec3 a)
{
    return vec3_normalize(vec3_ldexp(a, vec3_unit_exponent(vec3_max_abs(a))));
}

/* Returns the direction whose coordinates are (x, y, z) in an orthonormal
 * frame whose third axis is the unit vector n: the frame of Duff et al.,
 * "Building an orthonormal basis, revisited" (JCGT 2017), continuous but at
 * n.z = 0's sign change, and the same for the same n on every machine. */
static inline Vec3 vec3_from_frame(Vec3 n, real x, real y, real z)
{
    real sign = n.z < 0 ? -1 : 1;
    real a = -1 / (sign + n.z), b = n.x * n.y * a;
    Vec3 t = vec3(1 + sign * n.x * n.x * a, sign * b, -sign * n.x);
    Vec3 u = vec3(b, sign + n.y * n.y * a, -n.y);

    return vec3_add(vec3_add(vec3_scale(t, x), vec3_scale(u, y)), vec3_scale(n, z));
}

#endif
