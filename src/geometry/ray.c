/* ray.c: where secondary rays start (see ray.h). */
#include "geometry/ray.h"

#include <math.h>


/* Moves x, a finite real, one representable real in the direction of
 * the sign of step (not at all for 0 or NaN). */
static inline real ray_nudge(real x, real step)
{
    return step == 0 || !(step == step) ? x : real_next(x, step > 0);
}

Vec3 ray_offset_origin(Vec3 p, Vec3 perr, Vec3 back, Vec3 n, Vec3 w)
{
    real d = vec3_dot(vec3_abs(n), perr);
    Vec3 offset = vec3_scale(n, d);
    Vec3 o;

    if (vec3_dot(w, n) < 0)
        offset = vec3_neg(offset);
    else
        p = vec3_add(p, back);
    o = vec3_add(p, offset);
    o.x = ray_nudge(o.x, offset.x);
    o.y = ray_nudge(o.y, offset.y);
    o.z = ray_nudge(o.z, offset.z);
    return o;
}

/* Returns the largest of |a|'s components (as vec3_max_abs(), without
 * its libm calls: a hit's step is taken at every hit). */
static inline real ray_largest(Vec3 a)
{
    real x = fabs(a.x), y = fabs(a.y), z = fabs(a.z), m = x > y ? x : y;

    return m > z ? m : z;
}

Vec3 ray_back_step(const Ray *ray, real t, Vec3 p, Vec3 perr)
{
    Vec3 back = vec3_scale(ray->dir, -t);
    real way = ray_largest(back);
    /* The hit's error, as the arriving ray's reach gives it, and the
     * largest offset its error bound can give (in largest components:
     * gamma(16) covers the lengths' sqrt(3)). */
    real e = real_gamma(16) * (ray_largest(p) + 2 * way);
    real d = perr.x + perr.y + perr.z;
    real step = 16 * (e > d ? e : d);

    if (!(way > 0))
        return vec3(0, 0, 0);
    return vec3_scale(back, step < way * 15 / 16 ? step / way : (real)15 / 16);
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

void ray_diff_transfer(const Ray *ray, const RayDiff *diff, real t, Vec3 n, Vec3 dp[2])
{
    real dn = vec3_dot(ray->dir, n);
    Vec3 o[2] = {diff->dodx, diff->dody}, d[2] = {diff->dddx, diff->dddy};

    for (int k = 0; k < 2; k++) {
        Vec3 moved = vec3_add(o[k], vec3_scale(d[k], t));
        dp[k] = dn != 0 ? vec3_sub(moved, vec3_scale(ray->dir, vec3_dot(moved, n) / dn))
                        : vec3(0, 0, 0);
    }
}

void ray_diff_reflect(Vec3 d, const RayDiff *diff, Vec3 n, const Vec3 dn[2], const Vec3 dp[2],
                      RayDiff *out)
{
    Vec3 dd[2] = {diff->dddx, diff->dddy}, r[2];
    real dot = vec3_dot(d, n);

    for (int k = 0; k < 2; k++) {
        real ddot = vec3_dot(dd[k], n) + vec3_dot(d, dn[k]);
        r[k] = vec3_sub(dd[k], vec3_scale(vec3_add(vec3_scale(n, ddot), vec3_scale(dn[k], dot)), 2));
    }
    out->dodx = dp[0];
    out->dody = dp[1];
    out->dddx = r[0];
    out->dddy = r[1];
}

void ray_diff_unit(Vec3 d, const RayDiff *diff, RayDiff *out)
{
    real len = vec3_length(d);
    Vec3 u = vec3_scale(d, 1 / len);

    *out = *diff;
    out->dddx = vec3_scale(vec3_sub(diff->dddx, vec3_scale(u, vec3_dot(u, diff->dddx))), 1 / len);
    out->dddy = vec3_scale(vec3_sub(diff->dddy, vec3_scale(u, vec3_dot(u, diff->dddy))), 1 / len);
}

void ray_diff_refract(Vec3 d, const RayDiff *diff, Vec3 n, const Vec3 dn[2], const Vec3 dp[2],
                      real eta, Vec3 t, RayDiff *out)
{
    RayDiff unit;
    Vec3 u = vec3_scale(d, 1 / vec3_length(d)), r[2], du[2];
    real cos_i = -vec3_dot(u, n), cos_t = -vec3_dot(t, n);
    real mu = eta * cos_i - cos_t;

    ray_diff_unit(d, diff, &unit);
    du[0] = unit.dddx;
    du[1] = unit.dddy;
    for (int k = 0; k < 2; k++) {
        /* The unit direction's derivative, then the cosine's. */
        real dcos_i = -(vec3_dot(du[k], n) + vec3_dot(u, dn[k]));
        real dmu = cos_t != 0 ? (eta - eta * eta * cos_i / cos_t) * dcos_i : 0;
        r[k] = vec3_add(vec3_add(vec3_scale(du[k], eta), vec3_scale(n, dmu)), vec3_scale(dn[k], mu));
    }
    out->dodx = dp[0];
    out->dody = dp[1];
    out->dddx = r[0];
    out->dddy = r[1];
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
