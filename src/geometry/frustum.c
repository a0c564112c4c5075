/* frustum.c: pyramids of rays and the spheres they miss (see frustum.h). */
#include "geometry/frustum.h"

/* A margin wider than this proves too little to be worth the test. */
#define FRUSTUM_MAX_SLACK 1e-3

/*
 * The margin. With e the error of a corner or aimed point (err, plus the
 * rounding of its difference from the apex) and h the apex's distance to
 * the quadrilateral's plane (no aimed point is nearer), a computed ray
 * strays from an exact one by an angle of at most sqrt(3) e / h, and 8 u
 * more for its normalising and rounding to real (u = REAL_EPSILON). A side
 * plane's normal a x b tilts by at most sqrt(3) e (|a| + |b|) / |a x b| for
 * its corners' errors, and 4 u |a| |b| / |a x b| for the product's own
 * rounding. The slack is twice the sum, plus 64 u for the sphere's test:
 * sphere_hit() may pass a ray some 5 u (|f| + r) outside the sphere (f, the
 * origin's offset from the centre), and the distance to the plane is
 * rounded too. A sphere is missed when it lies beyond one side plane by
 * more than its radius plus the slack times its farthest point's distance.
 */
int frustum_make(Frustum *f, Vec3 apex, const Vec3 corner[4], real err)
{
    Vec3 a[4], n, sum;
    real m = 0, e, h, stray, tilt = 0;
    int k;

    for (int i = 0; i < 4; i++) {
        a[i] = vec3_sub(corner[i], apex);
        m = fmax(m, vec3_max_abs(a[i]));
    }
    if (!(m > 0 && m <= REAL_MAX && err >= 0))
        return -1;
    /* The planes do not change with the scale: a power of two brings the
     * largest coordinate near 1, so that no square under- or overflows. */
    k = vec3_unit_exponent(m);
    for (int i = 0; i < 4; i++)
        a[i] = vec3_ldexp(a[i], k);
    e = ldexp(err, k) + 2 * REAL_EPSILON;
    n = vec3_cross(vec3_sub(a[1], a[0]), vec3_sub(a[3], a[0]));
    h = fabs(vec3_dot(n, a[0])) / vec3_length(n) * (1 - 1e-6) - 2 * e;
    if (!(h > 0))
        return -1;
    stray = 2 * e / h + 8 * REAL_EPSILON;
    sum = vec3_add(vec3_add(a[0], a[1]), vec3_add(a[2], a[3]));
    for (int i = 0; i < 4; i++) {
        Vec3 p = a[i], q = a[(i + 1) % 4];
        real lp = vec3_length(p), lq = vec3_length(q);
        real len;

        n = vec3_cross(p, q);
        len = vec3_length(n);
        if (!(len > 0))
            return -1;
        tilt = fmax(tilt, (2 * e * (lp + lq) + 4 * REAL_EPSILON * lp * lq) / len);
        n = vec3_scale(n, 1 / len);
        /* Inwards: towards the quadrilateral's centre, which is inside. */
        f->normal[i] = vec3_dot(n, sum) < 0 ? vec3_neg(n) : n;
    }
    f->apex = apex;
    f->slack = 2 * (stray + tilt) + 64 * REAL_EPSILON;
    return f->slack < FRUSTUM_MAX_SLACK ? 0 : -1;
}

int frustum_misses_box(const Frustum *f, Vec3 lo, Vec3 hi)
{
    Vec3 a = vec3_sub(lo, f->apex), b = vec3_sub(hi, f->apex);
    /* At least the distance of the box's farthest point. */
    real far = 2 * fmax(vec3_max_abs(a), vec3_max_abs(b));

    for (int i = 0; i < 4; i++) {
        Vec3 n = f->normal[i];
        /* The corner farthest along the normal, inwards. */
        Vec3 c = vec3(n.x < 0 ? a.x : b.x, n.y < 0 ? a.y : b.y, n.z < 0 ? a.z : b.z);
        if (vec3_dot(n, c) < -f->slack * far)
            return 1;
    }
    return 0;
}

int frustum_misses_sphere(const Frustum *f, Vec3 centre, real radius)
{
    Vec3 d = vec3_sub(centre, f->apex);
    /* At least the distance of the sphere's farthest point, without a
     * square that could overflow. */
    real far = 2 * vec3_max_abs(d) + radius;
    real beyond = radius + f->slack * far;

    for (int i = 0; i < 4; i++)
        if (vec3_dot(f->normal[i], d) < -beyond)
            return 1;
    return 0;
}
