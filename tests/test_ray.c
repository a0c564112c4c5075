/* test_ray.c: secondary rays (geometry/ray.h, ray_offset_origin()): rays
 * spawned from planes, triangles, cubes, squares, cylinders and cones at
 * scales 10^-6 to 10^8, grazing included, never meet the surface they
 * leave (spheres: test_sphere.c); rays spawned where two planes meet
 * leave both. */
#include <math.h>

#include "geometry/cone.h"
#include "geometry/cube.h"
#include "geometry/cylinder.h"
#include "geometry/disk.h"
#include "geometry/plane.h"
#include "geometry/ray.h"
#include "geometry/square.h"
#include "geometry/triangle.h"
#include "rng.h"
#include "solid.h"
#include "test.h"

static const Material white = {{255, 255, 255}, 0, 0, 1, -1, TEXTURE_NEAREST, -1, 0};

/* Spawns rays from a surface point at cosines down to 1e-12 to either side
 * of the facing normal n; returns how many of them meet the surface again
 * (hit(ray) says whether one does). A plane or a triangle is crossed once
 * at most, so none of them may. */
static int rehits_from(SurfacePoint sp, Vec3 n, int (*hit)(const void *, const Ray *),
                       const void *shape)
{
    int rehits = 0;

    for (int j = 0; j < 8; j++) {
        double cosine = j < 4 ? pow(10, -4.0 * j) : fmax(rng_uniform(), 1e-12);
        /* Shadow rays run to the light: directions of any length. */
        Vec3 w = vec3_scale(rng_direction_at_cosine(n, cosine), rng_log_scale(-3, 3)),
             w_in = vec3_neg(w);
        Ray away = {ray_offset_origin(sp.point, sp.error, vec3(0, 0, 0), n, w), w};
        Ray into = {ray_offset_origin(sp.point, sp.error, vec3(0, 0, 0), n, w_in), w_in};

        rehits += hit(shape, &away) + hit(shape, &into);
    }
    return rehits;
}

static int plane_hit(const void *pl, const Ray *r)
{
    double t;
    return plane_intersect(pl, r, 0, INFINITY, &t);
}

static int triangle_hit(const void *tri, const Ray *r)
{
    double t;
    return triangle_intersect(tri, r, 0, INFINITY, &t);
}

/* One of the five shapes, made at a scale and a place, for the re-hit
 * test. */
typedef struct {
    int kind; /* 0 cube, 1 square, 2 cylinder, 3 cone, 4 disk */
    Cube cube;
    Square square;
    Cylinder cylinder;
    Cone cone;
    Disk disk;
} Solid;

enum { SOLID_KINDS = 5 };

/* Says whether solid kind k is flat (a square, a disk): a ray through
 * it from either side crosses nothing more. */
static int solid_flat(int k)
{
    return k == 1 || k == 4;
}

static int solid_hit(const Solid *s, const Ray *r, real *t)
{
    switch (s->kind) {
    case 0:
        return cube_intersect(&s->cube, r, 0, INFINITY, t);
    case 1:
        return square_intersect(&s->square, r, 0, INFINITY, t);
    case 2:
        return cylinder_intersect(&s->cylinder, r, 0, INFINITY, t);
    case 3:
        return cone_intersect(&s->cone, r, 0, INFINITY, t);
    default:
        return disk_intersect(&s->disk, r, 0, INFINITY, t);
    }
}

static SurfacePoint solid_surface(const Solid *s, const Ray *r, real t)
{
    Vec3 p = ray_at(r, t);

    switch (s->kind) {
    case 0:
        return cube_surface(&s->cube, r, t);
    case 1:
        return square_surface_at(&s->square, p);
    case 2:
        return cylinder_surface_at(&s->cylinder, p);
    case 3:
        return cone_surface_at(&s->cone, p);
    default:
        return disk_surface(&s->disk, r, t);
    }
}

static void flat_spawned_rays_never_rehit_their_surface(void)
{
    /* As for spheres: planes and triangles at scales 1e-6 to 1e8 and up to
     * 1e8 away, hit by random rays; rays spawned from each hit, grazing
     * included, must not meet the same surface again. (The first version of
     * the triangle test failed this with its t from barycentrics: 30% of a
     * floor's shadow rays re-hit it.) */
    int tested = 0, rehits = 0;

    for (int i = 0; i < 3000; i++) {
        double s = rng_log_scale(-6, 8);
        /* Half the shapes lie near the origin for their size, where the
         * error bound is smallest. */
        Vec3 c = vec3_scale(rng_unit_vector(),
                            i % 2 ? s * rng_log_scale(-3, 0) : rng_log_scale(-6, 8));
        Vec3 a = vec3_add(c, vec3_scale(rng_unit_vector(), s));
        Vec3 b = vec3_add(c, vec3_scale(rng_unit_vector(), s));
        Vec3 d = vec3_add(c, vec3_scale(rng_unit_vector(), s));
        Vec3 aim, from;
        Plane pl;
        Triangle tri;
        Ray ray;

        /* A third of them lie in a plane y = constant, often 0, as floors do:
         * there the error bound has a zero component. */
        if (i % 3 == 0)
            a.y = b.y = d.y = i % 2 ? c.y : 0;
        aim = vec3_scale(vec3_add(vec3_add(a, b), d), 1.0 / 3);
        from = vec3_add(aim, vec3_scale(rng_unit_vector(), s * rng_log_scale(-1, 3)));
        CHECK_INT(0, plane_make(&pl, a, i % 3 == 0 ? vec3(0, 1, 0) : rng_unit_vector(), 1, white));
        ray.origin = from;
        ray.dir = vec3_normalize(vec3_sub(aim, from));
        double t, uv[2];
        SurfacePoint sp;

        if (plane_intersect(&pl, &ray, 0, INFINITY, &t)) {
            sp = plane_surface_at(&pl, ray_at(&ray, t));
            rehits += rehits_from(sp, ray_facing_normal(sp.normal, ray.dir), plane_hit, &pl);
            tested++;
        }
        if (triangle_make(&tri, a, b, d) == 0 &&
            triangle_intersect(&tri, &ray, 0, INFINITY, &t)) {
            sp = triangle_surface_at(&tri, NULL, &ray, uv, NULL);
            rehits += rehits_from(sp, ray_facing_normal(sp.normal, ray.dir), triangle_hit, &tri);
            tested++;
        }
    }
    CHECK(tested > 4000);
    CHECK_INT(0, rehits);
}

static void solids_spawned_rays_never_rehit_their_surface(void)
{
    /* As for spheres (test_sphere.c): hit a shape at a random scale and
     * place from outside or inside, spawn rays from the hit as shading
     * does, at cosines down to 10^-12, and check that none meets the
     * surface again at the scale of the offset. The five shapes are
     * convex (or flat), so a ray leaving a surface on the side it came
     * from outside crosses nothing. */
    int tested[SOLID_KINDS] = {0}, rehits = 0, close = 0;

    for (int i = 0; i < 10000; i++) {
        double r = rng_log_scale(-6, 8);
        Vec3 c = vec3_scale(rng_unit_vector(), rng_log_scale(-6, 8));
        Vec3 from, aim;
        Solid s;
        Ray ray;
        real t;
        SurfacePoint sp;
        Vec3 n;
        int inside = i % 8 == 4;

        s.kind = i % SOLID_KINDS;
        switch (s.kind) {
        case 0:
            cube_make(&s.cube, c, r, solid_plain());
            break;
        case 1:
            CHECK_INT(0, square_make(&s.square, c, rng_unit_vector(), r, solid_plain()));
            break;
        case 2:
            s.cylinder = (Cylinder){c, r, solid_plain(), 0};
            break;
        case 3:
            cone_make(&s.cone, c, r, r * rng_range(0.3, 3) * (i % 8 < 4 ? 1 : -1), solid_plain());
            break;
        default:
            CHECK_INT(0, disk_make(&s.disk, c, rng_unit_vector(), r, solid_plain()));
            break;
        }
        aim = vec3_add(c, vec3_scale(rng_unit_vector(), 0.6 * r * rng_uniform()));
        from = inside ? vec3_add(c, vec3_scale(rng_unit_vector(), 0.3 * r * rng_uniform()))
                      : vec3_add(c, vec3_scale(rng_unit_vector(), r * rng_log_scale(0.5, 3)));
        if (s.kind == 3 && inside) /* within the nappe, below the apex */
            from = vec3_add(s.cone.apex, vec3(0, s.cone.side * r * 0.5, 0));
        ray.origin = from;
        ray.dir = vec3_normalize(inside ? rng_unit_vector() : vec3_sub(aim, from));
        if (!solid_hit(&s, &ray, &t))
            continue;
        tested[s.kind]++;
        sp = solid_surface(&s, &ray, t);
        n = ray_facing_normal(sp.normal, ray.dir);
        /* Where the ray really came from: the cylinder and cone are
         * infinite, so an origin picked outside may be inside. */
        inside = !solid_flat(s.kind) && vec3_dot(ray.dir, sp.normal) > 0;
        for (int j = 0; j < 8; j++) {
            double cosine = j < 4 ? pow(10, -4.0 * j) : fmax(rng_uniform(), 1e-12);
            Vec3 w = rng_direction_at_cosine(n, cosine);
            Ray away = {ray_offset_origin(sp.point, sp.error, vec3(0, 0, 0), n, w), w};
            Vec3 w_in = vec3_neg(w);
            Ray into = {ray_offset_origin(sp.point, sp.error, vec3(0, 0, 0), n, w_in), w_in};
            /* Back the way the ray came: from outside nothing is crossed;
             * from inside only a far wall, never at the offset's scale. */
            if (solid_hit(&s, &away, &t) && (!inside || (cosine > 1e-3 && t < 1e-9 * r)))
                inside ? close++ : rehits++;
            /* Through the surface: from inside nothing is crossed; from
             * outside a far wall (or, for a square or a disk, nothing), a chord away
             * (near an edge of a cube a short one: only rays at cosines
             * above 10^-3 are held to it). */
            if (solid_hit(&s, &into, &t) &&
                (inside || solid_flat(s.kind) || (cosine > 1e-3 && t < 1e-9 * r)))
                inside || solid_flat(s.kind) ? rehits++ : close++;
        }
    }
    for (int k = 0; k < SOLID_KINDS; k++)
        CHECK(tested[k] > 1000);
    CHECK_INT(0, rehits);
    CHECK_INT(0, close);
}

/* Returns a random unit direction u with u . a >= m and u . b >= m. */
static Vec3 direction_between(Vec3 a, Vec3 b, double m)
{
    for (;;) {
        Vec3 u = rng_unit_vector();
        if (vec3_dot(u, a) >= m && vec3_dot(u, b) >= m)
            return u;
    }
}

/* Returns a random unit direction u with u . a >= m and u . b <= -m. */
static Vec3 direction_across(Vec3 a, Vec3 b, double m)
{
    return direction_between(a, vec3_neg(b), m);
}

static void corner_rays_leave_both_surfaces(void)
{
    /* Two planes meet on a line (a floor and a wall: half the time as a
     * room's are, axis-aligned through 0); a ray from the room aims at a
     * point of the line, at scales 1e-4 to 1e6 and up to 1e7 away, so that
     * its hit lies on both planes and rounding puts it a hair on either
     * side of the one it did not hit. Rays spawned from the hit as shading
     * does, with the step back along the arriving ray, must see the whole
     * hemisphere: into the room they meet neither plane (a shadow ray
     * would find the point in shadow), and across the other plane they
     * meet it at once (a gathering ray would leave the room). The arriving
     * ray meets each plane at a cosine of 1/8 or more. Without the step
     * back, a shadow ray in five met a plane and two gathering rays in
     * three missed the other. */
    int tested = 0, blocked = 0, escaped = 0;

    for (int i = 0; i < 4000; i++) {
        double s = rng_log_scale(-4, 6);
        int room = i % 2;
        Vec3 na = room ? vec3(0, 1, 0) : rng_unit_vector(), nb, c, e, aim, from, n, back;
        Plane pl[2];
        Ray ray;
        double t[2];
        SurfacePoint sp;
        int k;

        do
            nb = room ? vec3(1, 0, 0) : rng_unit_vector();
        while (fabs(vec3_dot(na, nb)) > 0.9);
        c = room ? vec3(0, 0, 0) : vec3_scale(rng_unit_vector(), s * rng_log_scale(-3, 1));
        if (i % 5 == 1)
            c = vec3_add(c, vec3_scale(rng_unit_vector(), 1e7 * s));
        /* Either side of a plane is its front: the normals given point
         * either way. */
        CHECK_INT(0, plane_make(&pl[0], c, i % 4 < 2 ? na : vec3_neg(na), 1, white));
        CHECK_INT(0, plane_make(&pl[1], c, i % 8 < 4 ? nb : vec3_neg(nb), 1, white));
        e = vec3_normalize(vec3_cross(na, nb));
        aim = vec3_add(c, vec3_scale(e, s * rng_range(-1, 1)));
        from = vec3_add(aim, vec3_scale(direction_between(na, nb, 0.125), s * rng_log_scale(-1, 3)));
        ray.origin = from;
        ray.dir = vec3_sub(aim, from);
        if (!plane_intersect(&pl[0], &ray, 0, INFINITY, &t[0]) ||
            !plane_intersect(&pl[1], &ray, 0, INFINITY, &t[1]))
            continue;
        k = t[1] < t[0];
        sp = plane_surface_at(&pl[k], ray_at(&ray, t[k]));
        n = ray_facing_normal(sp.normal, ray.dir);
        back = ray_back_step(&ray, t[k], sp.point, sp.error);
        tested++;
        for (int j = 0; j < 8; j++) {
            Vec3 in_room = direction_between(na, nb, 0.125);
            Vec3 across = k ? direction_across(nb, na, 0.125) : direction_across(na, nb, 0.125);
            Ray shadow = {ray_offset_origin(sp.point, sp.error, back, n, in_room), in_room};
            Ray gather = {ray_offset_origin(sp.point, sp.error, back, n, across), across};
            double tt;

            blocked += plane_hit(&pl[0], &shadow) + plane_hit(&pl[1], &shadow);
            escaped += plane_hit(&pl[k], &gather) ||
                       !plane_intersect(&pl[!k], &gather, 0, INFINITY, &tt) ||
                       tt > 1e-9 * (s + vec3_max_abs(c));
        }
    }
    CHECK(tested > 3900);
    CHECK_INT(0, blocked);
    CHECK_INT(0, escaped);
}

const TestCase ray_tests[] = {
    {"flat_spawned_rays_never_rehit_their_surface", flat_spawned_rays_never_rehit_their_surface},
    {"corner_rays_leave_both_surfaces", corner_rays_leave_both_surfaces},
    {"solids_spawned_rays_never_rehit_their_surface", solids_spawned_rays_never_rehit_their_surface},
    {NULL, NULL},
};
