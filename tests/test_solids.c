/* test_solids.c: cubes, squares, cylinders and cones: hits at known t,
 * rays from inside, parallel to an axis or grazing an edge, and rays
 * spawned from their surfaces at scales 10^-6 to 10^8 that must never
 * meet the surface they leave. */
#include <math.h>

#include "geometry/cone.h"
#include "geometry/cube.h"
#include "geometry/cylinder.h"
#include "geometry/square.h"
#include "rng.h"
#include "test.h"

static Material plain = {{200, 200, 200}, 0, 0, 1, -1, TEXTURE_NEAREST, -1, 0};

static Ray ray_from(double ox, double oy, double oz, double dx, double dy, double dz)
{
    Ray r = {{ox, oy, oz}, {dx, dy, dz}};
    return r;
}

static void cube_hits_from_outside_inside_and_along_axes(void)
{
    Cube c;
    Ray out = ray_from(-5, 0.3, 0.2, 1, 0, 0), in = ray_from(0.2, 0.1, 0, 0, 0, -2);
    Ray parallel = ray_from(0.5, 0.5, -5, 0, 0, 1), beside = ray_from(1.5, 0.5, -5, 0, 0, 1);
    Ray corner = ray_from(-3, -3, -3, 1, 1, 1), edge = ray_from(-5, 1, 1, 1, 0, 0);
    real t = 0;

    cube_make(&c, vec3(0, 0, 0), 1, plain);
    CHECK(cube_intersect(&c, &out, 0, INFINITY, &t));
    CHECK_NEAR(4, t, 0);
    CHECK_INT(2, cube_crossings(&c, &out, 0, INFINITY));
    CHECK_INT(1, cube_crossings(&c, &out, 0, 5));
    CHECK(cube_intersect(&c, &in, 0, INFINITY, &t)); /* from inside, out through -z */
    CHECK_NEAR(0.5, t, 0);
    CHECK_INT(1, cube_crossings(&c, &in, 0, INFINITY));
    CHECK(cube_intersect(&c, &parallel, 0, INFINITY, &t));
    CHECK_NEAR(4, t, 0);
    CHECK(!cube_intersect(&c, &beside, 0, INFINITY, &t)); /* parallel, outside the slab */
    CHECK(cube_intersect(&c, &corner, 0, INFINITY, &t));  /* through two corners */
    CHECK_NEAR(2, t, 0);
    CHECK(cube_intersect(&c, &edge, 0, INFINITY, &t)); /* along an edge: touches it */
    CHECK_NEAR(4, t, 0);
    CHECK(!cube_intersect(&c, &out, 0, 4, &t)); /* the interval is open */
}

static void cube_surface_points_lie_on_their_face(void)
{
    Cube c;
    SurfacePoint sp;
    double uv[2];
    Ray down = ray_from(1e7 + 0.2, 10, 3.1, 0, -1, 0), ahead = ray_from(1e7 - 0.25, 2.25, -5, 0, 0, 1);
    real t = 0;

    cube_make(&c, vec3(1e7, 2, 3), 0.5, plain);
    CHECK(cube_intersect(&c, &down, 0, INFINITY, &t));
    sp = cube_surface_at(&c, &down, t);
    CHECK(sp.normal.y == 1 && sp.normal.x == 0 && sp.normal.z == 0);
    CHECK(sp.point.y == c.hi.y);
    CHECK(sp.error.x > 0 && sp.error.y > 0 && sp.error.z > 0);
    cube_uv(&c, sp.point, sp.normal, uv);
    CHECK_NEAR(0.7, uv[0], 1e-9); /* top: +x to the right, +z up */
    CHECK_NEAR(0.6, uv[1], 1e-9);
    /* The -z face seen from in front: +x to the right, +y up. */
    CHECK(cube_intersect(&c, &ahead, 0, INFINITY, &t));
    sp = cube_surface_at(&c, &ahead, t);
    CHECK(sp.normal.z == -1);
    cube_uv(&c, sp.point, sp.normal, uv);
    CHECK_NEAR(0.25, uv[0], 1e-9);
    CHECK_NEAR(0.75, uv[1], 1e-9);
}

static void cube_edges_belong_to_the_face_the_ray_crosses(void)
{
    /* The cube of centre (0, 0, 2) and half-edge 1, from (0, 0, -3): rays
     * that meet its front face (z = 1) exactly on its top edge (y = 1),
     * its right edge (x = 1) and its corner leave the slabs of y and x
     * there and enter z's: the front face's normal, -z, however the
     * point rounds (a ray at 1/4 of the way across rounds nearer the top
     * face than the front). A ray that enters two slabs at once (through
     * an edge from outside both) takes the lower axis's face; a ray lying
     * in a face's plane touches the cube, at the face it then meets. */
    Cube c;
    Ray rays[] = {ray_from(0, 0, -3, 0, 1, 4), ray_from(0, 0, -3, 1, 0, 4),
                  ray_from(0, 0, -3, 1, 1, 4), ray_from(0, 0, -3, 0.25, 1, 4),
                  ray_from(-5, 3, 2, 4, -2, 0), ray_from(0, 1, -3, 0, 0, 1)};
    Vec3 want[] = {vec3(0, 0, -1), vec3(0, 0, -1), vec3(0, 0, -1), vec3(0, 0, -1),
                   vec3(-1, 0, 0), vec3(0, 0, -1)};
    real t = 0;

    cube_make(&c, vec3(0, 0, 2), 1, plain);
    for (size_t i = 0; i < sizeof rays / sizeof rays[0]; i++) {
        SurfacePoint sp;
        if (!cube_intersect(&c, &rays[i], 0, INFINITY, &t)) {
            test_fail(__FILE__, __LINE__, "ray %zu misses the cube", i);
            continue;
        }
        sp = cube_surface_at(&c, &rays[i], t);
        if (!vec3_equal(sp.normal, want[i]))
            test_fail(__FILE__, __LINE__, "ray %zu: normal (%g, %g, %g), expected (%g, %g, %g)",
                      i, sp.normal.x, sp.normal.y, sp.normal.z, want[i].x, want[i].y, want[i].z);
    }
    /* Leaving from inside through an edge: the slab left first, outward. */
    {
        Ray out = ray_from(0, 0, 2, 0, 1, 1);
        CHECK(cube_intersect(&c, &out, 0, INFINITY, &t));
        CHECK(vec3_equal(cube_surface_at(&c, &out, t).normal, vec3(0, 1, 0)));
    }
}

static void square_hits_inside_its_edges_on_both_sides(void)
{
    Square s;
    Ray front = ray_from(0.9, -0.9, -5, 0, 0, 1), back = ray_from(0.2, 0.3, 7, 0, 0, -1);
    Ray outside = ray_from(1.1, 0, -5, 0, 0, 1), flat = ray_from(-5, 0, 0, 1, 0, 0);
    real t = 0;
    double uv[2];

    CHECK_INT(-1, square_make(&s, vec3(0, 0, 0), vec3(0, 0, 0), 1, plain));
    CHECK_INT(0, square_make(&s, vec3(0, 0, 0), vec3(0, 0, -3), 1, plain));
    /* A wall facing -z: u along +x, v along +y, as seen from in front. */
    CHECK(s.axis_u.x == 1 && s.axis_v.y == 1);
    CHECK(square_intersect(&s, &front, 0, INFINITY, &t));
    CHECK_NEAR(5, t, 0);
    CHECK(square_intersect(&s, &back, 0, INFINITY, &t));
    CHECK_NEAR(7, t, 0);
    CHECK(!square_intersect(&s, &outside, 0, INFINITY, &t));
    CHECK(!square_intersect(&s, &flat, 0, INFINITY, &t));
    square_uv(&s, vec3(0.5, -0.25, 0), uv); /* in units from the centre */
    CHECK_NEAR(0.5, uv[0], 1e-15);
    CHECK_NEAR(-0.25, uv[1], 1e-15);
    /* A floor: u along +x, v along +z. */
    CHECK_INT(0, square_make(&s, vec3(0, -1, 0), vec3(0, 1, 0), 50, plain));
    CHECK(s.axis_u.x == 1 && s.axis_v.z == 1);
}

static void cylinder_hits_at_known_t_and_not_along_its_axis(void)
{
    Cylinder c = {{0, 3, 0}, 1, plain, 0};
    Ray across = ray_from(-5, 100, 0, 1, 0, 0), along = ray_from(0.5, -5, 0, 0, 1, 0);
    Ray slanted = ray_from(-5, 0, 0, 1, 1, 0), tangent = ray_from(-5, 0, 1, 1, 0, 0);
    Ray inside = ray_from(0, 7, 0, 0, 0, 3);
    real t = 0;

    CHECK(cylinder_intersect(&c, &across, 0, INFINITY, &t));
    CHECK_NEAR(4, t, 0);
    CHECK_INT(2, cylinder_crossings(&c, &across, 0, INFINITY));
    CHECK(!cylinder_intersect(&c, &along, 0, INFINITY, &t));
    CHECK(cylinder_intersect(&c, &slanted, 0, INFINITY, &t));
    CHECK_NEAR(4, t, 0);
    CHECK(cylinder_intersect(&c, &tangent, 0, INFINITY, &t));
    CHECK_NEAR(5, t, 1e-15);
    CHECK(cylinder_intersect(&c, &inside, 0, INFINITY, &t));
    CHECK_NEAR(1.0 / 3, t, 1e-16);
    CHECK_INT(1, cylinder_crossings(&c, &inside, 0, INFINITY));
    /* Radius 10^-6 at 10^8: the discriminant keeps its digits. */
    c.centre = vec3(1e8, 0, 0);
    c.radius = 1e-6;
    across = ray_from(0, 0, 0.5e-6, 1, 0, 0);
    CHECK(cylinder_intersect(&c, &across, 0, INFINITY, &t));
    CHECK_NEAR(1e8 - sqrt(0.75) * 1e-6, t, 1e-8);
}

static void cone_hits_its_nappe_only(void)
{
    Cone c;
    Ray across = ray_from(-5, 0.5, 0, 1, 0, 0), above = ray_from(-5, 2, 0, 1, 0, 0);
    Ray below = ray_from(-5, -3, 0, 1, 0, 0), down = ray_from(0.25, 5, 0, 0, -1, 0);
    Ray generator = ray_from(-3, -2.5, 0, 1, 1, 0); /* parallel to a generator */
    real t = 0;
    double uv[2];
    SurfacePoint sp;

    cone_make(&c, vec3(0, 0, 0), 1, 1, plain); /* apex at y = 1, widening downwards */
    CHECK(cone_intersect(&c, &across, 0, INFINITY, &t));
    CHECK_NEAR(4.5, t, 1e-15); /* radius 0.5 at y = 0.5 */
    CHECK_INT(2, cone_crossings(&c, &across, 0, INFINITY));
    CHECK(!cone_intersect(&c, &above, 0, INFINITY, &t)); /* the other nappe is not there */
    CHECK(cone_intersect(&c, &below, 0, INFINITY, &t)); /* infinite: radius 4 at y = -3 */
    CHECK_NEAR(1, t, 1e-15);
    CHECK(cone_intersect(&c, &down, 0, INFINITY, &t)); /* enters at y = 0.75 */
    CHECK_NEAR(4.25, t, 1e-15);
    CHECK_INT(1, cone_crossings(&c, &down, 0, INFINITY));
    CHECK(cone_intersect(&c, &generator, 0, INFINITY, &t)); /* one root: a = 0 */
    CHECK_NEAR(3.25, t, 1e-15);
    CHECK_INT(1, cone_crossings(&c, &generator, 0, INFINITY));
    sp = cone_surface_at(&c, vec3(0.5, 0.5, 0));
    CHECK_NEAR(sqrt(0.5), sp.normal.x, 1e-15); /* out and up, at 45 degrees */
    CHECK_NEAR(sqrt(0.5), sp.normal.y, 1e-15);
    cone_uv(&c, vec3(0, 0.25, -0.75), uv);
    CHECK_NEAR(0.5, uv[0], 1e-15);
    CHECK_NEAR(0.25, uv[1], 1e-15);
    /* Upside down: apex below, opening upwards. */
    cone_make(&c, vec3(0, 0, 0), 1, -1, plain);
    above = ray_from(-5, 0.5, 0, 1, 0, 0);
    CHECK(cone_intersect(&c, &above, 0, INFINITY, &t));
    CHECK_NEAR(3.5, t, 1e-15); /* radius 1.5 at y = 0.5 */
}

/* One of the four shapes, made at a scale and a place, for the re-hit
 * test. */
typedef struct {
    int kind; /* 0 cube, 1 square, 2 cylinder, 3 cone */
    Cube cube;
    Square square;
    Cylinder cylinder;
    Cone cone;
} Solid;

static int solid_hit(const Solid *s, const Ray *r, real *t)
{
    switch (s->kind) {
    case 0:
        return cube_intersect(&s->cube, r, 0, INFINITY, t);
    case 1:
        return square_intersect(&s->square, r, 0, INFINITY, t);
    case 2:
        return cylinder_intersect(&s->cylinder, r, 0, INFINITY, t);
    default:
        return cone_intersect(&s->cone, r, 0, INFINITY, t);
    }
}

static SurfacePoint solid_surface(const Solid *s, const Ray *r, real t)
{
    Vec3 p = ray_at(r, t);

    switch (s->kind) {
    case 0:
        return cube_surface_at(&s->cube, r, t);
    case 1:
        return square_surface_at(&s->square, p);
    case 2:
        return cylinder_surface_at(&s->cylinder, p);
    default:
        return cone_surface_at(&s->cone, p);
    }
}

static void solids_spawned_rays_never_rehit_their_surface(void)
{
    /* As for spheres (test_sphere.c): hit a shape at a random scale and
     * place from outside or inside, spawn rays from the hit as shading
     * does, at cosines down to 10^-12, and check that none meets the
     * surface again at the scale of the offset. The four shapes are
     * convex (or flat), so a ray leaving a surface on the side it came
     * from outside crosses nothing. */
    int tested[4] = {0}, rehits = 0, close = 0;

    for (int i = 0; i < 8000; i++) {
        double r = rng_log_scale(-6, 8);
        Vec3 c = vec3_scale(rng_unit_vector(), rng_log_scale(-6, 8));
        Vec3 from, aim;
        Solid s;
        Ray ray;
        real t;
        SurfacePoint sp;
        Vec3 n;
        int inside = i % 8 == 4;

        s.kind = i % 4;
        switch (s.kind) {
        case 0:
            cube_make(&s.cube, c, r, plain);
            break;
        case 1:
            CHECK_INT(0, square_make(&s.square, c, rng_unit_vector(), r, plain));
            break;
        case 2:
            s.cylinder = (Cylinder){c, r, plain, 0};
            break;
        default:
            cone_make(&s.cone, c, r, r * rng_range(0.3, 3) * (i % 8 < 4 ? 1 : -1), plain);
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
        inside = s.kind != 1 && vec3_dot(ray.dir, sp.normal) > 0;
        for (int j = 0; j < 8; j++) {
            double cosine = j < 4 ? pow(10, -4.0 * j) : fmax(rng_uniform(), 1e-12);
            Vec3 w = rng_direction_at_cosine(n, cosine);
            Ray away = {ray_offset_origin(sp.point, sp.error, n, w), w};
            Vec3 w_in = vec3_neg(w);
            Ray into = {ray_offset_origin(sp.point, sp.error, n, w_in), w_in};
            /* Back the way the ray came: from outside nothing is crossed;
             * from inside only a far wall, never at the offset's scale. */
            if (solid_hit(&s, &away, &t) && (!inside || (cosine > 1e-3 && t < 1e-9 * r)))
                inside ? close++ : rehits++;
            /* Through the surface: from inside nothing is crossed; from
             * outside a far wall (or, for a square, nothing), a chord away
             * (near an edge of a cube a short one: only rays at cosines
             * above 10^-3 are held to it). */
            if (solid_hit(&s, &into, &t) &&
                (inside || s.kind == 1 || (cosine > 1e-3 && t < 1e-9 * r)))
                inside || s.kind == 1 ? rehits++ : close++;
        }
    }
    for (int k = 0; k < 4; k++)
        CHECK(tested[k] > 1000);
    CHECK_INT(0, rehits);
    CHECK_INT(0, close);
}

const TestCase solid_tests[] = {
    {"cube_hits_from_outside_inside_and_along_axes", cube_hits_from_outside_inside_and_along_axes},
    {"cube_surface_points_lie_on_their_face", cube_surface_points_lie_on_their_face},
    {"cube_edges_belong_to_the_face_the_ray_crosses", cube_edges_belong_to_the_face_the_ray_crosses},
    {"square_hits_inside_its_edges_on_both_sides", square_hits_inside_its_edges_on_both_sides},
    {"cylinder_hits_at_known_t_and_not_along_its_axis",
     cylinder_hits_at_known_t_and_not_along_its_axis},
    {"cone_hits_its_nappe_only", cone_hits_its_nappe_only},
    {"solids_spawned_rays_never_rehit_their_surface",
     solids_spawned_rays_never_rehit_their_surface},
    {NULL, NULL},
};
