/* ray.c: where secondary rays start (see ray.h). */
#include "geometry/ray.h"

#include <math.h>


/* Moves x, a finite real, one representable real in the direction of
 * the sign of step (not at all for 0 or NaN). */
static inline real ray_nudge(real x, real step)
{
    return step == 0 || !(step == step) ? x : real_next(x, step > 0);
}

Vec3 ray_offset_origin(Vec3 p, Vec3 perr, Vec3 n, Vec3 w)
{
    real d = vec3_dot(vec3_abs(n), perr);
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

int ray_refract(Vec3 d, Vec3 n, real eta, Vec3 *out)
{
    Vec3 u = vec3_normalize(d);
    real cos_i = -vec3_dot(u, n);
    real k = 1 - eta * eta * (1 - cos_i * cos_i); /* cos^2 of the refracted angle */

    if (k < 0)
        return 0;
    *out = vec3_normalize(vec3_add(vec3_scale(u, eta), vec3_scale(n, eta * cos_i - sqrt(k))));
    return 1;
}

double ray_fresnel(Vec3 d, Vec3 n, real eta)
{
    double ci = -(double)vec3_dot(d, n) / (double)vec3_length(d), st2, ct, rs, rp;

    ci = ci > 1 ? 1 : ci < 0 ? 0 : ci;
    st2 = (double)eta * (double)eta * (1 - ci * ci);
    if (st2 >= 1)
        return 1;
    ct = sqrt(1 - st2);
    rs = (eta * ci - ct) / (eta * ci + ct);
    rp = (eta * ct - ci) / (eta * ct + ci);
    return 0.5 * (rs * rs + rp * rp);
}
