/* ray.c: where secondary rays start (see ray.h). */
#include "ray.h"

#include <float.h>
#include <math.h>
#include <stdint.h>
#include <string.h>

/* Moves x, a finite double, one representable double in the direction of
 * the sign of step: nextafter(), on the bits (the same result, no call). */
static inline double ray_nudge(double x, double step)
{
    uint64_t bits;

    if (step == 0 || !(step == step))
        return x;
    if (x == 0)
        return step > 0 ? DBL_TRUE_MIN : -DBL_TRUE_MIN;
    memcpy(&bits, &x, sizeof bits);
    /* Away from zero adds one to the magnitude's bits, towards it takes one. */
    bits += (x > 0) == (step > 0) ? 1 : (uint64_t)-1;
    memcpy(&x, &bits, sizeof x);
    return x;
}

Vec3 ray_offset_origin(Vec3 p, Vec3 perr, Vec3 n, Vec3 w)
{
    double d = vec3_dot(vec3_abs(n), perr);
    Vec3 offset = vec3_scale(n, d);
    Vec3 o;

    if (vec3_dot(w, n) < 0)
        offset = vec3_neg(offset);
    o = vec3_add(p, offset);
    o.x = ray_nudge(o.x, offset.x);
    o.y = ray_nudge(o.y, offset.y);
    o.z = ray_nudge(o.z, offset.z);
    return o;
}

int ray_refract(Vec3 d, Vec3 n, double eta, Vec3 *out)
{
    Vec3 u = vec3_normalize(d);
    double cos_i = -vec3_dot(u, n);
    double k = 1 - eta * eta * (1 - cos_i * cos_i); /* cos^2 of the refracted angle */

    if (k < 0)
        return 0;
    *out = vec3_normalize(vec3_add(vec3_scale(u, eta), vec3_scale(n, eta * cos_i - sqrt(k))));
    return 1;
}
