/* test_sphere.c: ray/sphere intersection and safe secondary-ray origins. */
#include <math.h>

#include "geometry/ray.h"
#include "geometry/sphere.h"
#include "rng.h"
#include "test.h"

#define PI 3.14159265358979323846

static Sphere sphere_at(double x, double y, double z, double r)
{
    Sphere s = {{x, y, z}, r, {0}, 0, {255, 255, 255}, 1};
    return s;
}

static Ray ray_from(double ox, double oy, double oz, double dx, double dy, double dz)
{
    Ray r = {{ox, oy, oz}, {dx, dy, dz}};
    return r;
}

/* Returns the first crossing at t > 0, or -1 for none. */
static double first_hit(const Sphere *s, const Ray *r)
{
    double t;
    return sphere_intersect(s, r, 0, INFINITY, &t) ? t : -1;
}

static void sphere_hit_in_front(void)
{
    Sphere s = sphere_at(0, 0, 5, 1);
    Ray r = ray_from(0, 0, 0, 0, 0, 1);
    CHECK_NEAR(4, first_hit(&s, &r), 0);
}

static void sphere_miss(void)
{
    Sphere s = sphere_at(0, 0, 5, 1);
    Ray r = ray_from(0, 0, 0, 0, 1, 0);
    Ray beside = ray_from(0, 1.000001, 0, 0, 0, 1);
    CHECK_NEAR(-1, first_hit(&s, &r), 0);
    CHECK_NEAR(-1, first_hit(&s, &beside), 0);
}

static void sphere_tangent_ray_touches(void)
{
    /* The line x = 0, y = 1 touches the sphere at (0, 1, 5) only. */
    Sphere s = sphere_at(0, 0, 5, 1);
    Ray r = ray_from(0, 1, 0, 0, 0, 1);
    CHECK_NEAR(5, first_hit(&s, &r), 1e-12);
}

static void sphere_origin_inside_exits(void)
{
    Sphere s = sphere_at(0, 0, 0, 2);
    Ray r = ray_from(0, 0, 0, 0, 0, -1);
    Ray off = ray_from(1, 0, 0, 0, 1, 0); /* exits at (1, sqrt(3), 0) */
    CHECK_NEAR(2, first_hit(&s, &r), 0);
    CHECK_NEAR(sqrt(3.0), first_hit(&s, &off), 1e-15);
}

static void sphere_origin_on_surface(void)
{
    Sphere s = sphere_at(0, 0, 0, 1);
    Ray out = ray_from(1, 0, 0, 1, 0, 0);
    Ray in = ray_from(1, 0, 0, -1, 0, 0);
    Ray along = ray_from(1, 0, 0, 0, 1, 0); /* tangent at its own origin */
    CHECK_NEAR(-1, first_hit(&s, &out), 0);
    CHECK_NEAR(2, first_hit(&s, &in), 0);
    CHECK_NEAR(-1, first_hit(&s, &along), 0);
}

static void sphere_behind_is_missed(void)
{
    Sphere s = sphere_at(0, 0, -5, 1);
    Ray r = ray_from(0, 0, 0, 0, 0, 1);
    CHECK_NEAR(-1, first_hit(&s, &r), 0);
}

static void sphere_unnormalised_direction(void)
{
    Sphere s = sphere_at(0, 0, 5, 1);
    Ray r = ray_from(0, 0, 0, 0, 0, 10);
    Ray slant = ray_from(0, 0, 0, 0, 3e-3, 4e-3); /* centre at 5 along (0, .6, .8) */
    Sphere s2 = sphere_at(0, 3, 4, 1);
    CHECK_NEAR(0.4, first_hit(&s, &r), 1e-16);
    CHECK_NEAR(4 / 5e-3, first_hit(&s2, &slant), 1e-12 * 800);
}

static void sphere_interval_is_open(void)
{
    Sphere s = sphere_at(0, 0, 5, 1);
    Ray r = ray_from(0, 0, 0, 0, 0, 1);
    double t;
    CHECK(!sphere_intersect(&s, &r, 0, 4, &t));        /* t = 4 is not < 4 */
    CHECK(sphere_intersect(&s, &r, 4, INFINITY, &t)); /* the far side, 6 */
    CHECK_NEAR(6, t, 0);
}

static void sphere_radii_from_1e_minus6_to_1e8(void)
{
    for (int k = -6; k <= 8; k++) {
        double s = pow(10, k);
        Sphere sp = sphere_at(0, 0, 3 * s, s);
        Ray axis = ray_from(0, 0, 0, 0, 0, 1);
        Ray off = ray_from(0, 0.5 * s, 0, 0, 0, 1);
        Ray inside = ray_from(0, 0, 3 * s, 1, 0, 0);
        CHECK_NEAR(2 * s, first_hit(&sp, &axis), 1e-15 * s);
        CHECK_NEAR((3 - sqrt(0.75)) * s, first_hit(&sp, &off), 1e-14 * s);
        CHECK_NEAR(s, first_hit(&sp, &inside), 1e-15 * s);
    }
}

static void sphere_far_away_off_axis_exact_t(void)
{
    /* A unit sphere 1e8 away; the ray aims at the surface point H whose
     * normal is 30 degrees off the direction back to the origin, so the
     * ray enters at H and the exact t is |H|. The textbook b^2 - 4ac loses
     * every digit of the discriminant here (b^2 ~ 4e16, ulp 8). */
    Vec3 c = vec3(3e7, -4e7, 1e8 * sqrt(0.75));
    Vec3 back = vec3_normalize(vec3_neg(c));
    Vec3 side = vec3_normalize(vec3_cross(back, vec3(0, 0, 1)));
    Vec3 m = vec3_add(vec3_scale(back, cos(PI / 6)), vec3_scale(side, sin(PI / 6)));
    Vec3 h = vec3_add(c, m);
    Sphere s = sphere_at(c.x, c.y, c.z, 1);
    Ray r = {{0, 0, 0}, vec3_normalize(h)};
    double t = first_hit(&s, &r);
    CHECK_NEAR(vec3_length(h), t, 1e-9 * vec3_length(h));
    CHECK_NEAR(1, vec3_length(vec3_sub(ray_at(&r, t), c)), 1e-7);
}

static void sphere_spawned_rays_never_rehit_their_sphere(void)
{
    /* pbrt-v4's Reintersect idea: hit a sphere at a random scale and place,
     * spawn rays from the hit as shading does, and check that those leaving
     * the surface never meet it again and those entering it cross the whole
     * chord. Cosines down to 1e-12 test grazing rays. */
    int tested = 0, rehits = 0, bad_chords = 0;

    for (int i = 0; i < 4000; i++) {
        double r = rng_log_scale(-6, 8);
        Vec3 c = vec3_scale(rng_unit_vector(), rng_log_scale(-6, 8));
        Sphere s = sphere_at(c.x, c.y, c.z, r);
        Vec3 aim = vec3_add(c, vec3_scale(rng_unit_vector(), 0.9 * r * rng_uniform()));
        Vec3 from = vec3_add(c, vec3_scale(rng_unit_vector(), r * rng_log_scale(0.01, 3)));
        int inside = i % 4 == 0; /* a quarter of the rays start inside */
        Ray ray;
        double t;
        SurfacePoint sp;
        Vec3 n;

        if (inside)
            from = vec3_add(c, vec3_scale(rng_unit_vector(), 0.5 * r * rng_uniform()));
        ray.origin = from;
        ray.dir = vec3_normalize(vec3_sub(inside ? vec3_add(c, vec3_scale(rng_unit_vector(), r))
                                                 : aim,
                                          from));
        if (!sphere_intersect(&s, &ray, 0, INFINITY, &t))
            continue; /* the aim was lost to rounding: nothing to test */
        tested++;
        sp = sphere_surface_at(&s, ray_at(&ray, t));
        n = ray_facing_normal(sp.normal, ray.dir);
        for (int j = 0; j < 8; j++) {
            double cosine = j < 4 ? pow(10, -4.0 * j) : fmax(rng_uniform(), 1e-12);
            Vec3 w = rng_direction_at_cosine(n, cosine);
            Ray away = {ray_offset_origin(sp.point, sp.error, vec3(0, 0, 0), n, w), w};
            Vec3 w_in = vec3_neg(w);
            Ray into = {ray_offset_origin(sp.point, sp.error, vec3(0, 0, 0), n, w_in), w_in};
            double chord = 2 * r * vec3_dot(w, n);
            /* The offset origin shortens a chord by about offset / cosine. */
            double slack = 1e-6 * chord + 4 * vec3_dot(vec3_abs(n), sp.error) / cosine;

            /* Leaving the side n faces: outside (convex) no crossing at
             * all; inside the sphere, the far wall, a whole chord away. */
            if (!inside && sphere_intersect(&s, &away, 0, INFINITY, &t))
                rehits++;
            if (inside && cosine > 1e-3 &&
                !(sphere_intersect(&s, &away, 0, INFINITY, &t) && fabs(t - chord) <= slack))
                bad_chords++;
            /* Crossing to the other side: from outside, a whole chord; from
             * inside, out into empty space. */
            if (!inside && cosine > 1e-3 &&
                !(sphere_intersect(&s, &into, 0, INFINITY, &t) && fabs(t - chord) <= slack))
                bad_chords++;
            if (inside && sphere_intersect(&s, &into, 0, INFINITY, &t))
                rehits++;
        }
    }
    CHECK(tested > 3500);
    CHECK_INT(0, rehits);
    CHECK_INT(0, bad_chords);
}

static void sphere_surface_point_is_on_the_sphere(void)
{
    Sphere s = sphere_at(1e7, -2e7, 3e7, 5);
    SurfacePoint sp = sphere_surface_at(&s, vec3(1e7 + 3.0000001, -2e7 + 4, 3e7));
    CHECK_NEAR(1, vec3_length(sp.normal), 1e-15);
    CHECK_NEAR(0.6, sp.normal.x, 1e-7);
    CHECK_NEAR(5, vec3_length(vec3_sub(sp.point, s.centre)), 1e-8);
    CHECK(sp.error.x > 0 && sp.error.y > 0 && sp.error.z > 0);
}

const TestCase sphere_tests[] = {
    {"sphere_hit_in_front", sphere_hit_in_front},
    {"sphere_miss", sphere_miss},
    {"sphere_tangent_ray_touches", sphere_tangent_ray_touches},
    {"sphere_origin_inside_exits", sphere_origin_inside_exits},
    {"sphere_origin_on_surface", sphere_origin_on_surface},
    {"sphere_behind_is_missed", sphere_behind_is_missed},
    {"sphere_unnormalised_direction", sphere_unnormalised_direction},
    {"sphere_interval_is_open", sphere_interval_is_open},
    {"sphere_radii_from_1e_minus6_to_1e8", sphere_radii_from_1e_minus6_to_1e8},
    {"sphere_far_away_off_axis_exact_t", sphere_far_away_off_axis_exact_t},
    {"sphere_spawned_rays_never_rehit_their_sphere", sphere_spawned_rays_never_rehit_their_sphere},
    {"sphere_surface_point_is_on_the_sphere", sphere_surface_point_is_on_the_sphere},
    {NULL, NULL},
};
