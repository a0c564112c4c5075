/* test_frustum.c: pyramids of primary rays and the spheres they miss. */
#include <math.h>

#include "geometry/frustum.h"
#include "geometry/sphere.h"
#include "rng.h"
#include "scene/camera.h"
#include "test.h"

/* The pyramid from the origin through the square |x|, |y| <= 1 at z = 1:
 * its side planes are x = +-z and y = +-z. */
static Frustum frustum_unit(void)
{
    Vec3 corner[4] = {{-1, -1, 1}, {1, -1, 1}, {1, 1, 1}, {-1, 1, 1}};
    Frustum f;

    CHECK_INT(0, frustum_make(&f, vec3(0, 0, 0), corner, 0));
    return f;
}

static void frustum_known_answers(void)
{
    Frustum f = frustum_unit();

    CHECK_INT(0, frustum_misses_sphere(&f, vec3(0, 0, 10), 1));   /* on the axis */
    CHECK_INT(1, frustum_misses_sphere(&f, vec3(100, 0, 10), 1)); /* far to the side */
    CHECK_INT(1, frustum_misses_sphere(&f, vec3(0, 0, -10), 1));  /* behind the apex */
    CHECK_INT(0, frustum_misses_sphere(&f, vec3(0, 0, 0), 0.5));  /* around the apex */
    /* (12, 0, 10) lies 2 / sqrt(2) = 1.414 outside the plane x = z. */
    CHECK_INT(1, frustum_misses_sphere(&f, vec3(12, 0, 10), 1.4));
    CHECK_INT(0, frustum_misses_sphere(&f, vec3(12, 0, 10), 1.42));
}

static void frustum_box_known_answers(void)
{
    Frustum f = frustum_unit();

    CHECK_INT(0, frustum_misses_box(&f, vec3(-1, -1, 9), vec3(1, 1, 11)));   /* on the axis */
    CHECK_INT(1, frustum_misses_box(&f, vec3(99, -1, 9), vec3(101, 1, 11))); /* to the side */
    CHECK_INT(1, frustum_misses_box(&f, vec3(-1, -1, -11), vec3(1, 1, -9))); /* behind */
    CHECK_INT(0, frustum_misses_box(&f, vec3(-1, -1, -1), vec3(1, 1, 1)));   /* around */
    /* Inside is x <= z: the box's corner (11.1, y, 11) lies 0.1 / sqrt(2)
     * outside the plane x = z; moved to x = 10.9999999, inside. */
    CHECK_INT(1, frustum_misses_box(&f, vec3(11.1, -1, 9), vec3(12, 1, 11)));
    CHECK_INT(0, frustum_misses_box(&f, vec3(10.9999999, -1, 9), vec3(12, 1, 11)));
    /* A box across the plane x = z, though its centre is outside. */
    CHECK_INT(0, frustum_misses_box(&f, vec3(10, -1, 9), vec3(14, 1, 13)));
}

static void frustum_degenerate_proves_nothing(void)
{
    Vec3 flat[4] = {{-1, -1, 0}, {1, -1, 0}, {1, 1, 0}, {-1, 1, 0}};
    Vec3 point[4] = {{1, 1, 1}, {1, 1, 1}, {1, 1, 1}, {1, 1, 1}};
    Vec3 huge[4] = {{-1, -1, 1}, {1, -1, 1}, {1, 1, 1}, {-1, 1, 1}};
    Frustum f;

    CHECK_INT(-1, frustum_make(&f, vec3(0, 0, 0), flat, 0));  /* apex in the plane */
    CHECK_INT(-1, frustum_make(&f, vec3(0, 0, 0), point, 0)); /* no quadrilateral */
    CHECK_INT(-1, frustum_make(&f, vec3(0, 0, 0), huge, 0.1)); /* errors too large */
}

/* A random pinhole camera at scale s (10^-6 to 10^8), its eye up to far s
 * from the origin, a screen of random shape (skewed or not) at a random
 * distance. */
static Camera frustum_camera(double s, double far, int skew)
{
    Camera cam = {0};
    Vec3 off = vec3_scale(rng_unit_vector(), rng_range(0, far) * s);
    Vec3 forward = rng_unit_vector(), side = vec3_normalize(vec3_cross(forward, rng_unit_vector()));
    Vec3 up = vec3_cross(side, forward);
    double w = rng_range(0.2, 3) * s, h = rng_range(0.2, 3) * s, d = rng_range(0.05, 5) * s;

    cam.eye = off;
    cam.u = vec3_add(vec3_scale(side, w), vec3_scale(up, skew ? rng_range(-0.3, 0.3) * s : 0));
    cam.v = vec3_scale(up, -h);
    cam.top_left = vec3_add(vec3_add(off, vec3_scale(forward, d)),
                            vec3_add(vec3_scale(cam.u, -0.5), vec3_scale(cam.v, -0.5)));
    cam.width = 40 + (int)rng_range(0, 200);
    cam.height = 30 + (int)rng_range(0, 200);
    return cam;
}

enum { FRUSTUM_STEPS = 12 }; /* a tile's rays tested: a grid of 13 x 13 */

/* Returns the ray camera_ray() makes through grid point (i, j) of
 * [x0, x1] x [y0, y1], edges included. */
static Ray frustum_grid_ray(const Camera *cam, const int tile[4], int i, int j)
{
    return camera_ray(cam, tile[0] + (double)(tile[2] - tile[0]) * i / FRUSTUM_STEPS,
                      tile[1] + (double)(tile[3] - tile[1]) * j / FRUSTUM_STEPS);
}

/* Says whether some ray of the grid over the tile meets the sphere. */
static int frustum_some_ray_hits(const Camera *cam, const int tile[4], Vec3 centre,
                                 double radius)
{
    for (int i = 0; i <= FRUSTUM_STEPS; i++)
        for (int j = 0; j <= FRUSTUM_STEPS; j++) {
            Ray ray = frustum_grid_ray(cam, tile, i, j);
            real t;
            if (sphere_hit(centre, radius, &ray, 0, INFINITY, &t))
                return 1;
        }
    return 0;
}

/* Every computed ray of a tile lies within the slack of its pyramid, and
 * rounding does put edge rays outside the planes themselves: the slack is
 * needed. */
static void frustum_rays_lie_within_the_slack(void)
{
    double worst = 0, slack_used = 0;

    for (int c = 0; c < 300; c++) {
        double s = rng_log_scale(-6, 8);
        Camera cam = frustum_camera(s, c % 3 ? 1e4 : 10, c % 2);
        int x0 = (int)rng_range(0, cam.width - 8), y0 = (int)rng_range(0, cam.height - 8);
        int tile[4] = {x0, y0, x0 + 1 + (int)rng_range(0, 7), y0 + 1 + (int)rng_range(0, 7)};
        Frustum f;

        CHECK_INT(0, camera_frustum(&cam, tile[0], tile[1], tile[2], tile[3], &f));
        for (int i = 0; i <= FRUSTUM_STEPS; i++)
            for (int j = 0; j <= FRUSTUM_STEPS; j++) {
                Ray ray = frustum_grid_ray(&cam, tile, i, j);
                for (int p = 0; p < 4; p++) {
                    double out = -vec3_dot(f.normal[p], ray.dir);
                    CHECK(out <= f.slack);
                    worst = fmax(worst, out);
                    slack_used = fmax(slack_used, out / f.slack);
                }
            }
    }
    CHECK(worst > 0);
    CHECK(slack_used < 0.5);
}

/* Returns the distance from c to the plane through the eye and image
 * positions (xa, ya) and (xb, yb), in long double from the camera's own
 * numbers (a reference nearer exact than the doubles tested). */
static long double frustum_plane_distance(const Camera *cam, double xa, double ya, double xb,
                                          double yb, Vec3 c)
{
    const real *tl = &cam->top_left.x, *u = &cam->u.x, *v = &cam->v.x, *e = &cam->eye.x;
    const real *cc = &c.x;
    long double a[3], b[3], n[3], dot = 0, len = 0;

    for (int k = 0; k < 3; k++) {
        a[k] = tl[k] + (long double)xa / cam->width * u[k] + (long double)ya / cam->height * v[k];
        b[k] = tl[k] + (long double)xb / cam->width * u[k] + (long double)yb / cam->height * v[k];
        a[k] -= e[k];
        b[k] -= e[k];
    }
    for (int k = 0; k < 3; k++) {
        n[k] = a[(k + 1) % 3] * b[(k + 2) % 3] - a[(k + 2) % 3] * b[(k + 1) % 3];
        dot += n[k] * ((long double)cc[k] - e[k]);
        len += n[k] * n[k];
    }
    return fabsl(dot) / sqrtl(len);
}

/* Spheres just outside a tile's pyramid: each centred beyond one of its
 * edges, aimed at a thousandth to a billionth of a pixel past it, its
 * radius short of the edge's plane by a part in 10^3 to 10^12. Whatever
 * the pyramid proves missed, no computed ray of the tile meets; and, the
 * eye within 10 times the screen's size of the origin (the error of the
 * screen's points, which the margin covers, grows with their
 * coordinates), it proves most of those with the widest gaps. */
static void frustum_proof_holds_for_computed_rays(void)
{
    int proven = 0, wide = 0, wide_proven = 0;

    for (int c = 0; c < 300; c++) {
        double s = rng_log_scale(-6, 8);
        int near_origin = c % 3 == 0;
        Camera cam = frustum_camera(s, near_origin ? 10 : 1e4, c % 2);
        int x0 = (int)rng_range(0, cam.width - 8), y0 = (int)rng_range(0, cam.height - 8);
        int tile[4] = {x0, y0, x0 + 1 + (int)rng_range(0, 7), y0 + 1 + (int)rng_range(0, 7)};
        Frustum f;

        CHECK_INT(0, camera_frustum(&cam, tile[0], tile[1], tile[2], tile[3], &f));
        for (int k = 0; k < 16; k++) {
            double gap = pow(10, -3 - 2 * (k % 4)); /* pixels */
            int edge = (int)rng_range(0, 4), i = (int)rng_range(0, FRUSTUM_STEPS + 1);
            /* The edge's ends: left, right, top or bottom. */
            int xa = tile[edge == 1 ? 2 : 0], xb = tile[edge == 0 ? 0 : 2];
            int ya = tile[edge == 3 ? 3 : 1], yb = tile[edge == 2 ? 1 : 3];
            double x = xa + (double)(xb - xa) * i / FRUSTUM_STEPS;
            double y = ya + (double)(yb - ya) * i / FRUSTUM_STEPS;
            Ray aim;
            Vec3 centre;
            double radius;

            x += edge == 0 ? -gap : edge == 1 ? gap : 0;
            y += edge == 2 ? -gap : edge == 3 ? gap : 0;
            aim = camera_ray(&cam, x, y);
            centre = ray_at(&aim, rng_log_scale(-1, 3) * s);
            radius = (double)frustum_plane_distance(&cam, xa, ya, xb, yb, centre) *
                     (1 - pow(10, -3 - 3 * (k / 4)));
            if (!frustum_misses_sphere(&f, centre, radius))
                continue;
            proven++;
            wide_proven += k == 0 && near_origin;
            CHECK_INT(0, frustum_some_ray_hits(&cam, tile, centre, radius));
        }
        wide += near_origin;
    }
    CHECK(proven > 0);
    CHECK(wide_proven > wide / 2);
}

/* The same pyramid for the whole image, against a sphere it holds and one
 * behind the eye. */
static void frustum_of_a_camera(void)
{
    Camera cam = {0};
    Frustum f;

    cam.eye = vec3(100, 100, 0);
    cam.top_left = vec3(90, 110, 30);
    cam.u = vec3(20, 0, 0);
    cam.v = vec3(0, -20, 0);
    cam.width = cam.height = 480;
    CHECK_INT(0, camera_frustum(&cam, 0, 0, 480, 480, &f));
    CHECK_INT(0, frustum_misses_sphere(&f, vec3(90, 90, 60), 7));
    CHECK_INT(1, frustum_misses_sphere(&f, vec3(100, 100, -60), 7));
    /* A tile of the top-left corner does not reach the sphere at the
     * bottom right. */
    CHECK_INT(0, camera_frustum(&cam, 0, 0, 32, 32, &f));
    CHECK_INT(1, frustum_misses_sphere(&f, vec3(110, 90, 60), 7));
    cam.aperture = 1; /* rays from the whole lens: no pyramid */
    CHECK_INT(-1, camera_frustum(&cam, 0, 0, 32, 32, &f));
}

const TestCase frustum_tests[] = {
    {"frustum_known_answers", frustum_known_answers},
    {"frustum_box_known_answers", frustum_box_known_answers},
    {"frustum_degenerate_proves_nothing", frustum_degenerate_proves_nothing},
    {"frustum_rays_lie_within_the_slack", frustum_rays_lie_within_the_slack},
    {"frustum_proof_holds_for_computed_rays", frustum_proof_holds_for_computed_rays},
    {"frustum_of_a_camera", frustum_of_a_camera},
    {NULL, NULL},
};
