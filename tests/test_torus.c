/* test_torus.c: the torus's crossings against a reference traced in long
 * double, at every scale and far from the origin, grazing, along the
 * axis, and from its own surface. */
#include <math.h>

#include "geometry/ray.h"
#include "geometry/torus.h"
#include "rng.h"
#include "solid.h"
#include "test.h"

/* Returns the signed distance from p to the tube of the torus of centre
 * c, unit axis n, radii R and r, in long double. */
static long double ref_distance(const long double c[3], const long double n[3], long double R,
                                long double r, const long double p[3])
{
    long double q[3], z = 0, rho2 = 0;

    for (int a = 0; a < 3; a++) {
        q[a] = p[a] - c[a];
        z += q[a] * n[a];
    }
    for (int a = 0; a < 3; a++) {
        long double w = q[a] - z * n[a];
        rho2 += w * w;
    }
    return hypotl(sqrtl(rho2) - R, z) - r;
}

/* The reference's answer for a ray: its first crossing. */
typedef struct {
    int hit;        /* 1: it crosses the tube */
    long double t;  /* where */
    int edge;       /* 1: it passes within a hair of the surface somewhere
                       (grazing): either answer will do */
} RefHit;

/* Traces the ray (origin o, direction d, any length) through the torus
 * by spheres (the distance never overshoots the surface) from t = 0, in
 * long double: where it first crosses, or that it leaves for good. A hit
 * reached slowly (grazing), or a miss by a hair, is an edge. */
static RefHit ref_trace(const Torus *tor, Vec3 o, Vec3 d)
{
    long double c[3] = {tor->centre.x, tor->centre.y, tor->centre.z};
    long double n[3] = {tor->given.x, tor->given.y, tor->given.z}, nl = 0;
    long double dd[3] = {d.x, d.y, d.z}, dl = 0, oo[3] = {o.x, o.y, o.z};
    long double R = tor->major, r = tor->minor, t = 0, prev = INFINITY, least = INFINITY;
    long double far = 0, hair = r * 1e-6L, thr;
    RefHit h = {0, 0, 0};
    int sign, near = 0;

    for (int a = 0; a < 3; a++) {
        nl += n[a] * n[a];
        dl += dd[a] * dd[a];
        far += oo[a] * oo[a] + c[a] * c[a];
    }
    far = sqrtl(far);
    /* Where the distance is known to: long double's digits of the
     * coordinates, or a part in 10^15 of the tube. */
    thr = fmaxl(r * 1e-15L, far * 1e-18L);
    for (int a = 0; a < 3; a++) {
        n[a] /= sqrtl(nl);
        dd[a] /= sqrtl(dl);
    }
    sign = ref_distance(c, n, R, r, oo) < 0 ? -1 : 1;
    for (int iter = 0; iter < 20000; iter++) {
        long double p[3], s;
        for (int a = 0; a < 3; a++)
            p[a] = oo[a] + t * dd[a];
        s = ref_distance(c, n, R, r, p) * sign;
        if (t > 0 && (s <= 0 || (s < thr && s <= prev))) {
            h.hit = 1;
            h.t = t / sqrtl(dl);
            h.edge = near > 300;
            return h;
        }
        if (t > 0 && s < hair) {
            near++;
            least = fminl(least, s);
        }
        if (t > 4 * (R + r) + 2 * far) {
            h.edge = least < hair;
            return h;
        }
        t += fmaxl(s, thr);
        prev = s;
    }
    h.edge = 1;
    return h;
}

static Torus torus_at(Vec3 c, Vec3 n, double R, double r)
{
    Torus t;

    CHECK_INT(0, torus_make(&t, c, n, R, r, solid_plain()));
    return t;
}

static void torus_diameter_crosses_four_times(void)
{
    Torus t = torus_at(vec3(0, 0, 0), vec3(0, 0, 1), 2, 0.5);
    Ray across = {{-10, 0, 0}, {1, 0, 0}};
    double hit;

    CHECK_INT(4, torus_crossings(&t, &across, 0, INFINITY));
    CHECK(torus_intersect(&t, &across, 0, INFINITY, &hit));
    CHECK_NEAR(7.5, hit, 1e-14);
    CHECK(torus_intersect(&t, &across, 7.5, INFINITY, &hit)); /* the interval is open */
    CHECK_NEAR(8.5, hit, 1e-14);
    CHECK(torus_intersect(&t, &across, 9, INFINITY, &hit));
    CHECK_NEAR(11.5, hit, 1e-14);
    CHECK_INT(2, torus_crossings(&t, &across, 0, 10));
    CHECK(!torus_intersect(&t, &across, 12.5, INFINITY, &hit));
}

static void torus_axis_rays_pass_through_the_hole(void)
{
    Vec3 n = vec3_normalize(vec3(1, 2, -0.5));
    Torus t = torus_at(vec3(1e3, -2e3, 5), n, 3, 1);
    Ray along = {vec3_add(t.centre, vec3_scale(n, -50)), n};
    Ray back = {vec3_add(t.centre, vec3_scale(n, 50)), vec3_neg(n)};
    Ray through = {vec3_add(vec3_add(t.centre, vec3_scale(n, -50)), vec3_scale(t.axis_u, 3)), n};
    double hit;

    CHECK(!torus_intersect(&t, &along, 0, INFINITY, &hit));
    CHECK(!torus_intersect(&t, &back, 0, INFINITY, &hit));
    CHECK_INT(0, torus_crossings(&t, &along, 0, INFINITY));
    /* Parallel to the axis through the middle of the tube: two crossings. */
    CHECK_INT(2, torus_crossings(&t, &through, 0, INFINITY));
    CHECK(torus_intersect(&t, &through, 0, INFINITY, &hit));
    CHECK_NEAR(49, hit, 1e-11);
}

static void torus_matches_a_traced_reference_at_any_scale_and_place(void)
{
    int tested = 0, wrong = 0, hits = 0, n = test_trials(3000);

    for (int i = 0; i < n; i++) {
        double R = rng_log_scale(-6, 8), k = i % 4 ? rng_range(0.02, 0.9) : rng_log_scale(-4, -1.7);
        Vec3 c = vec3_scale(rng_unit_vector(), R * rng_log_scale(-2, 7) * (i % 3 == 0));
        Torus t = torus_at(c, rng_unit_vector(), R, k * R);
        Vec3 aim = vec3_add(c, vec3_scale(rng_unit_vector(), R * (1 + k) * rng_uniform()));
        Vec3 from = vec3_add(c, vec3_scale(rng_unit_vector(), R * rng_log_scale(0.5, 4)));
        Ray ray = {from, vec3_scale(vec3_sub(aim, from), rng_log_scale(-3, 3))};
        RefHit ref = ref_trace(&t, ray.origin, ray.dir);
        double hit;
        int ours = torus_intersect(&t, &ray, 0, INFINITY, &hit);

        if (ref.edge)
            continue;
        tested++;
        hits += ref.hit;
        if (ours != ref.hit ||
            (ours && fabsl(hit - ref.t) > 1e-9L * (ref.t + R / vec3_length(ray.dir)))) {
            if (wrong++ < 5)
                test_fail(__FILE__, __LINE__, "R %g r %g: ours %d t %.17g, reference %d t %.17Lg",
                          R, k * R, ours, ours ? hit : 0, ref.hit, ref.t);
        }
    }
    CHECK(tested > n * 8 / 10);
    CHECK(hits > n / 3);
    CHECK_INT(0, wrong);
}

static void torus_spawned_rays_never_rehit_where_they_start(void)
{
    /* As the sphere's test: rays leave a hit point, at cosines down to
     * 1e-12, the way shading spawns them; none meets the torus again where
     * it starts (the tube is not convex: a ray may cross it further on,
     * which the reference then finds too). */
    int tested = 0, rehits = 0, wrong = 0, n = test_trials(2000);

    for (int i = 0; i < n; i++) {
        double R = rng_log_scale(-6, 8), k = i % 4 ? rng_range(0.02, 0.9) : rng_log_scale(-4, -1.7);
        Vec3 c = vec3_scale(rng_unit_vector(), R * rng_log_scale(-2, 7) * (i % 2));
        Torus t = torus_at(c, rng_unit_vector(), R, k * R);
        Vec3 from = vec3_add(c, vec3_scale(rng_unit_vector(), R * rng_log_scale(0.5, 3)));
        Vec3 aim = vec3_add(c, vec3_scale(rng_unit_vector(), R * (1 + k) * rng_uniform()));
        Ray ray = {from, vec3_normalize(vec3_sub(aim, from))};
        SurfacePoint sp;
        double hit;

        if (!torus_intersect(&t, &ray, 0, INFINITY, &hit))
            continue;
        tested++;
        sp = torus_surface(&t, &ray, hit);
        for (int j = 0; j < 8; j++) {
            double cosine = j < 4 ? pow(10, -4.0 * j) : fmax(rng_uniform(), 1e-12);
            Vec3 n = j % 2 ? vec3_neg(sp.normal) : sp.normal; /* out of it, into it */
            Vec3 w = rng_direction_at_cosine(n, cosine);
            Ray away = {ray_offset_origin(sp.point, sp.error, vec3(0, 0, 0), n, w), w};
            RefHit ref = ref_trace(&t, away.origin, away.dir);
            double t2;
            int ours = torus_intersect(&t, &away, 0, INFINITY, &t2);
            if (ref.edge)
                continue;
            /* Met again where it starts: nearer than the surface is. */
            if (ours && (!ref.hit || t2 < 0.5L * ref.t))
                rehits++;
            else if (ours != ref.hit || (ours && fabsl(t2 - ref.t) > 1e-8L * R))
                wrong++;
        }
    }
    CHECK(tested > n / 3);
    CHECK_INT(0, rehits);
    CHECK_INT(0, wrong);
}

static void torus_surface_points_are_on_it_and_in_its_box(void)
{
    for (int i = 0; i < 500; i++) {
        double R = rng_log_scale(-6, 8), k = rng_range(0.02, 0.9), lo[3], hi[3], m;
        Vec3 c = vec3_scale(rng_unit_vector(), R * rng_log_scale(0, 7));
        Torus t = torus_at(c, rng_unit_vector(), R, k * R);
        SurfacePoint sp = torus_surface_at(&t, vec3_add(c, vec3_scale(rng_unit_vector(), R)));
        long double cc[3] = {c.x, c.y, c.z}, nn[3] = {t.axis.x, t.axis.y, t.axis.z};
        long double p[3] = {sp.point.x, sp.point.y, sp.point.z};
        double p3[3] = {sp.point.x, sp.point.y, sp.point.z};

        CHECK(fabsl(ref_distance(cc, nn, R, k * R, p)) <= 1e-14L * (vec3_max_abs(c) + R));
        CHECK_NEAR(1, vec3_length(sp.normal), 1e-15);
        m = torus_bounds(&t, 0, lo, hi);
        for (int a = 0; a < 3; a++)
            CHECK(p3[a] >= lo[a] - m - 1e-15 * fabs(p3[a]) && p3[a] <= hi[a] + m + 1e-15 * fabs(p3[a]));
    }
}

static void torus_is_refused_without_a_hole_or_an_axis(void)
{
    Torus t;

    CHECK_INT(-2, torus_make(&t, vec3(0, 0, 0), vec3(0, 1, 0), 1, 1, solid_plain()));
    CHECK_INT(-2, torus_make(&t, vec3(0, 0, 0), vec3(0, 1, 0), 1, 2, solid_plain()));
    CHECK_INT(-2, torus_make(&t, vec3(0, 0, 0), vec3(0, 1, 0), 1, 0.99e-4, solid_plain()));
    CHECK_INT(0, torus_make(&t, vec3(0, 0, 0), vec3(0, 1, 0), 1, 1e-4, solid_plain()));
    CHECK_INT(-1, torus_make(&t, vec3(0, 0, 0), vec3(0, 0, 0), 2, 1, solid_plain()));
    CHECK_INT(0, torus_make(&t, vec3(0, 0, 0), vec3(0, 1e-300, 0), 2, 1, solid_plain()));
    CHECK_NEAR(1, t.axis.y, 1e-15);
}

const TestCase torus_tests[] = {
    {"torus_diameter_crosses_four_times", torus_diameter_crosses_four_times},
    {"torus_axis_rays_pass_through_the_hole", torus_axis_rays_pass_through_the_hole},
    {"torus_matches_a_traced_reference_at_any_scale_and_place",
     torus_matches_a_traced_reference_at_any_scale_and_place},
    {"torus_spawned_rays_never_rehit_where_they_start",
     torus_spawned_rays_never_rehit_where_they_start},
    {"torus_surface_points_are_on_it_and_in_its_box",
     torus_surface_points_are_on_it_and_in_its_box},
    {"torus_is_refused_without_a_hole_or_an_axis", torus_is_refused_without_a_hole_or_an_axis},
    {NULL, NULL},
};
