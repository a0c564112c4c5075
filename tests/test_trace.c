/* test_trace.c: shading on tiny scenes whose colours are known exactly. */
#include <math.h>

#include "scene.h"
#include "test.h"
#include "trace.h"

#define PI 3.14159265358979323846

/* An empty scene: white light at `light`, background (10, 20, 30). */
static Scene scene_lit_from(Vec3 light)
{
    Light white = {light, {255, 255, 255}};
    Scene sc;

    scene_init(&sc);
    sc.background = colour(10, 20, 30);
    CHECK_INT(0, scene_add_light(&sc, &white));
    return sc;
}

static void add_sphere(Scene *sc, Vec3 c, double r, Colour col, double refl)
{
    Sphere s = {c, r, material_plain(col, refl), 0};
    CHECK_INT(0, scene_add_sphere(sc, &s));
}

/* The colour seen along the ray from o in direction d. */
static Colour seen(const Scene *sc, Vec3 o, Vec3 d, int max_depth)
{
    Ray r = {o, vec3_normalize(d)};
    return trace_ray(sc, &r, 0, max_depth);
}

#define CHECK_COLOUR(r_, g_, b_, c, tol)                                                      \
    do {                                                                                      \
        Colour c_ = (c);                                                                      \
        CHECK_NEAR((r_), c_.r, (tol));                                                        \
        CHECK_NEAR((g_), c_.g, (tol));                                                        \
        CHECK_NEAR((b_), c_.b, (tol));                                                        \
    } while (0)

static void trace_miss_sees_background(void)
{
    Scene sc = scene_lit_from(vec3(0, 0, 10));
    add_sphere(&sc, vec3(0, 0, -5), 1, colour(200, 100, 50), 0);
    CHECK_COLOUR(10, 20, 30, seen(&sc, vec3(0, 0, 0), vec3(0, 1, 0), 10), 0);
    scene_free(&sc);
}

static void trace_lit_head_on_and_at_60_degrees(void)
{
    /* Ray down the z axis onto the pole (0, 0, 1) of a unit sphere. */
    Scene sc = scene_lit_from(vec3(0, 0, 10));
    add_sphere(&sc, vec3(0, 0, 0), 1, colour(200, 100, 50), 0);
    sc.lights[0].colour = colour(255, 127.5, 51);
    CHECK_COLOUR(200, 50, 10, seen(&sc, vec3(0, 0, 3), vec3(0, 0, -1), 10), 1e-12);
    /* Light 60 degrees off the normal: cos = 1/2. */
    sc.lights[0].position = vec3(10 * sin(PI / 3), 0, 1 + 10 * cos(PI / 3));
    CHECK_COLOUR(100, 25, 5, seen(&sc, vec3(0, 0, 3), vec3(0, 0, -1), 10), 1e-12);
    /* Light below the horizon of the point: cos < 0, no light. */
    sc.lights[0].position = vec3(10, 0, 0.5);
    CHECK_COLOUR(0, 0, 0, seen(&sc, vec3(0, 0, 3), vec3(0, 0, -1), 10), 0);
    scene_free(&sc);
}

static void trace_shadowed_by_a_sphere_between(void)
{
    Scene sc = scene_lit_from(vec3(0, 0, 10));
    add_sphere(&sc, vec3(0, 0, 0), 1, colour(200, 100, 50), 0);
    add_sphere(&sc, vec3(0, 0, 5), 0.5, colour(255, 255, 255), 0); /* behind the eye */
    CHECK_COLOUR(0, 0, 0, seen(&sc, vec3(0, 0, 3), vec3(0, 0, -1), 10), 0);
    scene_free(&sc);
}

static void trace_occluder_beyond_light_casts_no_shadow(void)
{
    Scene sc = scene_lit_from(vec3(0, 0, 10));
    add_sphere(&sc, vec3(0, 0, 0), 1, colour(200, 100, 50), 0);
    add_sphere(&sc, vec3(0, 0, 15), 1, colour(255, 255, 255), 0);
    CHECK_COLOUR(200, 100, 50, seen(&sc, vec3(0, 0, 3), vec3(0, 0, -1), 10), 1e-12);
    scene_free(&sc);
}

static void trace_ball_around_point_and_light_casts_no_shadow(void)
{
    /* A big ball holds the eye, the lit point and the light: no shadow. A
     * ball holding only the light shadows. */
    Scene sc = scene_lit_from(vec3(0, 0, 10));
    add_sphere(&sc, vec3(0, 0, 0), 1, colour(200, 100, 50), 0);
    add_sphere(&sc, vec3(0, 0, 5), 20, colour(255, 255, 255), 0);
    CHECK_COLOUR(200, 100, 50, seen(&sc, vec3(0, 0, 3), vec3(0, 0, -1), 10), 1e-12);
    sc.spheres[1].centre = vec3(0, 0, 10);
    sc.spheres[1].radius = 2;
    CHECK_COLOUR(0, 0, 0, seen(&sc, vec3(0, 0, 3), vec3(0, 0, -1), 10), 0);
    scene_free(&sc);
}

static void trace_mirror_reflects_background_and_spheres(void)
{
    Scene sc = scene_lit_from(vec3(0, 0, 4));
    add_sphere(&sc, vec3(0, 0, 0), 1, colour(200, 100, 50), 1);
    /* A perfect mirror at its pole sends the ray back up the axis: it sees
     * the background. */
    CHECK_COLOUR(10, 20, 30, seen(&sc, vec3(0, 0, 3), vec3(0, 0, -1), 10), 1e-12);
    /* Half a mirror: half its own light, half the background. */
    sc.spheres[0].material.reflection = 0.5;
    CHECK_COLOUR(105, 60, 40, seen(&sc, vec3(0, 0, 3), vec3(0, 0, -1), 10), 1e-12);
    /* A green ball behind the eye, lit from below, is seen in the mirror. */
    sc.spheres[0].material.reflection = 1;
    add_sphere(&sc, vec3(0, 0, 8), 1, colour(0, 250, 0), 0);
    CHECK_COLOUR(0, 250, 0, seen(&sc, vec3(0, 0, 3), vec3(0, 0, -1), 10), 1e-12);
    scene_free(&sc);
}

static void trace_depth_cut_off_inside_a_mirror_ball(void)
{
    /* The eye and the light at the centre of a ball of radius 10 with
     * R = 1/2: every ray hits the wall head-on (cos = 1, local = Ci), comes
     * back through the centre to the opposite wall, and so on. Each bounce
     * gives (1 - R) Ci, weighted by R^k: C = Ci (1 - R^(d + 1)) at depth d. */
    Scene sc = scene_lit_from(vec3(0, 0, 0));
    add_sphere(&sc, vec3(0, 0, 0), 10, colour(200, 100, 50), 0.5);
    for (int d = 0; d <= 12; d++) {
        double k = 1 - pow(0.5, d + 1);
        CHECK_COLOUR(200 * k, 100 * k, 50 * k, seen(&sc, vec3(0, 0, 0), vec3(1, 2, 3), d),
                     1e-9);
    }
    scene_free(&sc);
}

static void trace_camera_inside_a_sphere(void)
{
    /* Light inside too: lit head-on. Light outside: the ball itself stands
     * between every wall point and the light. */
    Scene sc = scene_lit_from(vec3(0, 0, 0));
    add_sphere(&sc, vec3(0, 0, 0), 10, colour(200, 100, 50), 0);
    CHECK_COLOUR(200, 100, 50, seen(&sc, vec3(0, 0, 0), vec3(-3, 1, 2), 10), 1e-9);
    sc.lights[0].position = vec3(0, 0, 20);
    CHECK_COLOUR(0, 0, 0, seen(&sc, vec3(0, 0, 0), vec3(0, 0, -1), 10), 0);
    CHECK_COLOUR(0, 0, 0, seen(&sc, vec3(0, 0, 0), vec3(0, 0, 1), 10), 0);
    scene_free(&sc);
}

static void trace_exact_tie_keeps_the_first_sphere(void)
{
    Scene sc = scene_lit_from(vec3(0, 0, 10));
    add_sphere(&sc, vec3(0, 0, 0), 1, colour(200, 0, 0), 0);
    add_sphere(&sc, vec3(0, 0, 0), 1, colour(0, 200, 0), 0);
    CHECK_COLOUR(200, 0, 0, seen(&sc, vec3(0, 0, 3), vec3(0, 0, -1), 10), 1e-12);
    scene_free(&sc);
}

static void trace_nearest_and_occluded(void)
{
    Scene sc = scene_lit_from(vec3(0, 0, 10));
    Ray r = {{0, 0, 0}, {0, 0, 1}};
    Ray seg = {{0, 0, 0}, {0, 0, 4}};
    Hit hit;

    add_sphere(&sc, vec3(0, 0, 9), 1, colour(1, 1, 1), 0);
    add_sphere(&sc, vec3(0, 0, 5), 1, colour(1, 1, 1), 0);
    CHECK(trace_nearest(&sc, &r, INFINITY, &hit));
    CHECK_NEAR(4, hit.t, 0);
    CHECK(hit.kind == SHAPE_SPHERE && hit.index == 1);
    CHECK(!trace_nearest(&sc, &r, 4, &hit));
    CHECK(!trace_occluded(&sc, &seg)); /* ends exactly on the surface: not crossed */
    seg.dir.z = 4.5;
    CHECK(trace_occluded(&sc, &seg));
    scene_free(&sc);
}

const TestCase trace_tests[] = {
    {"trace_miss_sees_background", trace_miss_sees_background},
    {"trace_lit_head_on_and_at_60_degrees", trace_lit_head_on_and_at_60_degrees},
    {"trace_shadowed_by_a_sphere_between", trace_shadowed_by_a_sphere_between},
    {"trace_occluder_beyond_light_casts_no_shadow", trace_occluder_beyond_light_casts_no_shadow},
    {"trace_ball_around_point_and_light_casts_no_shadow",
     trace_ball_around_point_and_light_casts_no_shadow},
    {"trace_mirror_reflects_background_and_spheres", trace_mirror_reflects_background_and_spheres},
    {"trace_depth_cut_off_inside_a_mirror_ball", trace_depth_cut_off_inside_a_mirror_ball},
    {"trace_camera_inside_a_sphere", trace_camera_inside_a_sphere},
    {"trace_exact_tie_keeps_the_first_sphere", trace_exact_tie_keeps_the_first_sphere},
    {"trace_nearest_and_occluded", trace_nearest_and_occluded},
    {NULL, NULL},
};
