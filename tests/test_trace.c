/* test_trace.c: shading on tiny scenes whose colours are known exactly. */
#include <math.h>

#include "render/model.h"
#include "render/trace.h"
#include "render/visibility.h"
#include "scene/scene.h"
#include "shading.h"
#include "test.h"

#define PI 3.14159265358979323846

/* An empty scene: white light at `light`, background (10, 20, 30). */
static Scene scene_lit_from(Vec3 light)
{
    Light white = light_point(light, colour(255, 255, 255));
    Scene sc;

    scene_init(&sc);
    sc.background = colour(10, 20, 30);
    CHECK_INT(0, scene_add_light(&sc, &white));
    return sc;
}

/* Adds a sphere of material m. */
static void add_sphere_of(Scene *sc, Vec3 c, double r, Material m)
{
    CHECK_INT(0, scene_add_sphere(sc, c, r, &m));
}

/* Adds an opaque sphere of colour col and mirror weight refl. */
static void add_sphere(Scene *sc, Vec3 c, double r, Colour col, double refl)
{
    add_sphere_of(sc, c, r, material_plain(col, refl));
}

/* The colour seen along the ray from o in direction d. */
static Colour seen(const Scene *sc, Vec3 o, Vec3 d, int max_depth)
{
    Ray r = {o, vec3_normalize(d)};
    RayCounts counts = {0};
    Tracer t = model_tracer(sc, max_depth, &counts);

    return trace_ray(&t, &r);
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
    scene_spheres(&sc)[1].centre = vec3(0, 0, 10);
    scene_spheres(&sc)[1].radius = 2;
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
    scene_spheres(&sc)[0].material.reflection = 0.5;
    CHECK_COLOUR(105, 60, 40, seen(&sc, vec3(0, 0, 3), vec3(0, 0, -1), 10), 1e-12);
    /* A green ball behind the eye, lit from below, is seen in the mirror. */
    scene_spheres(&sc)[0].material.reflection = 1;
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
    CHECK(visibility_nearest(&sc, &r, INFINITY, &hit));
    CHECK_NEAR(4, hit.t, 0);
    CHECK(hit.kind == SHAPE_SPHERE && hit.index == 1);
    CHECK(!visibility_nearest(&sc, &r, 4, &hit));
    CHECK(!visibility_occluded(&sc, &seg, 1)); /* ends exactly on the surface: not crossed */
    seg.dir.z = 4.5;
    CHECK(visibility_occluded(&sc, &seg, 1));
    scene_free(&sc);
}

/* Returns the material of colour col with weights R and T and index n. */
static Material glass(Colour col, double refl, double transp, double n)
{
    Material m = material_plain(col, refl);
    m.transparency = transp;
    m.ior = n;
    return m;
}

static void refract_follows_snell_at_known_angles(void)
{
    Vec3 n = vec3(0, 0, 1), out;
    double s45 = sqrt(0.5);

    /* Air into glass (1 / 1.5) at 45 degrees: sin t = sin 45 / 1.5. */
    CHECK(ray_refract(vec3(s45, 0, -s45), n, 1 / 1.5, &out));
    CHECK_NEAR(s45 / 1.5, out.x, 1e-15);
    CHECK_NEAR(-sqrt(1 - 0.5 / 2.25), out.z, 1e-15);
    CHECK_NEAR(0, out.y, 0);
    /* Glass into air (1.5) at 30 degrees, any direction length: sin t = 0.75. */
    CHECK(ray_refract(vec3(0, 0.5 * 7, -sqrt(0.75) * 7), n, 1.5, &out));
    CHECK_NEAR(0.75, out.y, 1e-15);
    CHECK_NEAR(-sqrt(1 - 0.5625), out.z, 1e-15);
    /* Head on: straight through, whatever the indices. */
    CHECK(ray_refract(vec3(0, 0, -2), n, 1 / 2.4, &out));
    CHECK_NEAR(-1, out.z, 0);
}

static void refract_total_internal_reflection_at_the_critical_angle(void)
{
    /* From glass (1.5) to air the critical angle has sin = 1 / 1.5. Just
     * below it the ray leaves grazing the surface; just above, it cannot. */
    Vec3 n = vec3(0, 0, 1), out;
    double sc = 1 / 1.5, below = sc * (1 - 1e-9), above = sc * (1 + 1e-9);

    CHECK(ray_refract(vec3(below, 0, -sqrt(1 - below * below)), n, 1.5, &out));
    CHECK(fabs(out.z) < 1e-4);
    CHECK_NEAR(1, out.x, 1e-8);
    CHECK(!ray_refract(vec3(above, 0, -sqrt(1 - above * above)), n, 1.5, &out));
    CHECK(!ray_refract(vec3(0.9, 0, -sqrt(1 - 0.81)), n, 1.5, &out));
}

static void trace_clear_sphere_shows_what_is_behind(void)
{
    /* T = 1 and n = 1: the ray goes straight through, entering at depth 1
     * and leaving at depth 2; with max_depth 1 the way out is cut. */
    Scene sc = scene_lit_from(vec3(0, 0, 10));
    add_sphere_of(&sc, vec3(0, 0, -5), 1, glass(colour(200, 100, 50), 0, 1, 1));
    CHECK_COLOUR(10, 20, 30, seen(&sc, vec3(0, 0, 0), vec3(0, 0, -1), 2), 0);
    CHECK_COLOUR(0, 0, 0, seen(&sc, vec3(0, 0, 0), vec3(0, 0, -1), 1), 0);
    scene_free(&sc);
}

static void trace_transparency_follows_the_formula(void)
{
    /* R = 0.2, T = 0.5, n = 1, light behind the eye, depth 1. Front point:
     * C = 0.3 L + 0.2 Cr + 0.5 Ct with L = Ci (cos 1, white light), Cr the
     * background behind the eye, Ct the back wall seen from inside: lit
     * through the front wall, E = T = 0.5, and its own secondaries cut, so
     * Ct = 0.3 * 0.5 Ci. */
    Scene sc = scene_lit_from(vec3(0, 0, 10));
    add_sphere_of(&sc, vec3(0, 0, -5), 1, glass(colour(200, 100, 50), 0.2, 0.5, 1));
    CHECK_COLOUR(0.3 * 200 + 0.2 * 10 + 0.5 * 0.15 * 200, 0.3 * 100 + 0.2 * 20 + 0.5 * 0.15 * 100,
                 0.3 * 50 + 0.2 * 30 + 0.5 * 0.15 * 50, seen(&sc, vec3(0, 0, 0), vec3(0, 0, -1), 1),
                 1e-12);
    scene_free(&sc);
}

static void trace_shadow_through_glass_is_attenuated_per_crossing(void)
{
    /* A floor lit from straight above through a ball of T = 0.5: the shadow
     * ray crosses its surface twice, E = 0.25. With T = 0 the shadow is
     * black; the ball moved aside, the floor is fully lit. */
    Scene sc = scene_lit_from(vec3(0, 10, 0));
    Plane floor;

    CHECK_INT(0, plane_make(&floor, vec3(0, 0, 0), vec3(0, 1, 0), 1,
                            material_plain(colour(200, 100, 40), 0)));
    CHECK_INT(0, scene_add_shape(&sc, SHAPE_PLANE, &floor));
    add_sphere_of(&sc, vec3(0, 5, 0), 1, glass(colour(255, 255, 255), 0, 0.5, 1.5));
    CHECK(sc.has_transparency);
    CHECK_COLOUR(50, 25, 10, seen(&sc, vec3(3, 1, 0), vec3(-3, -1, 0), 0), 1e-12);
    sc.materials[sphere_material_index(&scene_spheres(&sc)[0])].transparency = 0; /* glass: in the table */
    CHECK_COLOUR(0, 0, 0, seen(&sc, vec3(3, 1, 0), vec3(-3, -1, 0), 0), 0);
    scene_spheres(&sc)[0].centre.x = 4;
    CHECK_COLOUR(200, 100, 40, seen(&sc, vec3(3, 1, 0), vec3(-3, -1, 0), 0), 1e-12);
    scene_free(&sc);
}

static void trace_refraction_enters_and_leaves_a_ball(void)
{
    /* A glass ball (n = 1.5, T = 1) at the origin, a ray parallel to x at
     * height h = 0.5: incidence 30 degrees, refraction t = asin(h / n), and
     * by symmetry it leaves deviated by 2 (30 - t) degrees towards the axis.
     * A red target sits where that ray goes, a green one straight ahead.
     * Ambient light only, so each target shows its own colour. */
    double h = 0.5, i = asin(h), t = asin(h / 1.5), dev = 2 * (i - t);
    Vec3 entry = vec3(-sqrt(1 - h * h), h, 0);
    Vec3 inside = vec3(cos(i - t), -sin(i - t), 0);
    Vec3 exit = vec3_add(entry, vec3_scale(inside, 2 * cos(t)));
    Vec3 target = vec3_add(exit, vec3_scale(vec3(cos(dev), -sin(dev), 0), 10));
    Scene sc = scene_lit_from(vec3(0, 100, 0));

    sc.lights[0].colour = colour(0, 0, 0);
    sc.ambient = colour(255, 255, 255);
    sc.has_ambient = 1;
    add_sphere_of(&sc, vec3(0, 0, 0), 1, glass(colour(0, 0, 0), 0, 1, 1.5));
    add_sphere(&sc, target, 0.05, colour(255, 0, 0), 0);
    add_sphere(&sc, vec3(10, h, 0), 0.05, colour(0, 255, 0), 0);
    CHECK_COLOUR(255, 0, 0, seen(&sc, vec3(-10, h, 0), vec3(1, 0, 0), 10), 1e-9);
    /* With n = 1 the same ray goes straight to the green target. */
    sc.materials[sphere_material_index(&scene_spheres(&sc)[0])].ior = 1;
    CHECK_COLOUR(0, 255, 0, seen(&sc, vec3(-10, h, 0), vec3(1, 0, 0), 10), 1e-9);
    scene_free(&sc);
}

static void trace_total_internal_reflection_mirrors_the_transmitted_share(void)
{
    /* Inside a glass half-space (below the plane y = 0, n = 1.5), a ray
     * meeting the surface at 60 degrees (beyond the critical 41.8) cannot
     * leave: its share T follows the mirror ray down to a red floor. */
    Scene sc = scene_lit_from(vec3(0, 100, 0));
    Plane top, floor;

    CHECK_INT(0, plane_make(&top, vec3(0, 0, 0), vec3(0, 1, 0), 1, glass(colour(0, 0, 0), 0, 1, 1.5)));
    CHECK_INT(0, plane_make(&floor, vec3(0, -10, 0), vec3(0, 1, 0), 1,
                            material_plain(colour(255, 0, 0), 0)));
    sc.lights[0].colour = colour(0, 0, 0);
    sc.ambient = colour(255, 255, 255);
    sc.has_ambient = 1;
    CHECK_INT(0, scene_add_shape(&sc, SHAPE_PLANE, &top));
    CHECK_INT(0, scene_add_shape(&sc, SHAPE_PLANE, &floor));
    CHECK_COLOUR(255, 0, 0, seen(&sc, vec3(0, -1, 0), vec3(sin(PI / 3), cos(PI / 3), 0), 10), 1e-12);
    /* At 30 degrees it leaves into the sky: the background. */
    CHECK_COLOUR(10, 20, 30, seen(&sc, vec3(0, -1, 0), vec3(sin(PI / 6), cos(PI / 6), 0), 10), 1e-12);
    scene_free(&sc);
}

static void trace_ambient_and_lights_add_up(void)
{
    /* A point lit head-on by two lights of colours A and B, plus ambient
     * Ca: Ci (A + B + Ca) / 255, channel by channel, before clamping. */
    Scene sc = scene_lit_from(vec3(0, 0, 10));
    Light second = light_point(vec3(0, 0, 20), colour(100, 50, 0));

    sc.lights[0].colour = colour(255, 100, 10);
    CHECK_INT(0, scene_add_light(&sc, &second));
    add_sphere(&sc, vec3(0, 0, -5), 1, colour(255, 200, 100), 0);
    CHECK_COLOUR(355, 150 * 200 / 255.0, 10 * 100 / 255.0,
                 seen(&sc, vec3(0, 0, 0), vec3(0, 0, -1), 0), 1e-12);
    sc.ambient = colour(20, 40, 60);
    sc.has_ambient = 1;
    CHECK_COLOUR(375, 190 * 200 / 255.0, 70 * 100 / 255.0,
                 seen(&sc, vec3(0, 0, 0), vec3(0, 0, -1), 0), 1e-12);
    /* In the shadow of both lights only the ambient term is left. */
    add_sphere(&sc, vec3(0, 0, 3), 0.5, colour(0, 0, 0), 0);
    CHECK_COLOUR(20, 40 * 200 / 255.0, 60 * 100 / 255.0,
                 seen(&sc, vec3(0.5, 0, 0), vec3(-0.5, 0, -4), 0), 1e-12);
    scene_free(&sc);
}

static void trace_exact_tie_across_kinds_keeps_the_first_listed(void)
{
    /* A plane tangent to a sphere at the point the ray meets both: the
     * object listed first wins, whatever its kind. */
    Scene sc = scene_lit_from(vec3(0, 0, 10));
    Plane pl;
    Ray r = {{0, 0, 0}, {0, 0, -1}};
    Hit hit;

    CHECK_INT(0, plane_make(&pl, vec3(0, 0, -4), vec3(0, 0, 1), 1, material_plain(colour(0, 255, 0), 0)));
    CHECK_INT(0, scene_add_shape(&sc, SHAPE_PLANE, &pl));
    add_sphere(&sc, vec3(0, 0, -5), 1, colour(255, 0, 0), 0);
    CHECK(visibility_nearest(&sc, &r, INFINITY, &hit));
    CHECK_INT(SHAPE_PLANE, hit.kind);
    CHECK_NEAR(4, hit.t, 0);
    scene_free(&sc);
    sc = scene_lit_from(vec3(0, 0, 10));
    add_sphere(&sc, vec3(0, 0, -5), 1, colour(255, 0, 0), 0);
    CHECK_INT(0, scene_add_shape(&sc, SHAPE_PLANE, &pl));
    CHECK(visibility_nearest(&sc, &r, INFINITY, &hit));
    CHECK_INT(SHAPE_SPHERE, hit.kind);
    scene_free(&sc);
}

static void trace_smooth_triangle_shades_with_its_vertex_normals(void)
{
    /* A triangle facing the eye, lit from behind the eye. Flat, cos = 1.
     * With all vertex normals tilted 60 degrees, cos = 0.5; with the three
     * normals differing, the centroid takes their normalised mean. */
    Scene sc = scene_lit_from(vec3(0, 0, -1e6));
    Triangle tri;
    double s60 = sqrt(0.75), a = 0.3;
    Vec3 tilt[3] = {{s60, 0, -0.5}, {0, s60, -0.5}, {-s60, 0, -0.5}}, mean;
    Vec3 centroid = vec3(0, 1.0 / 3, 5);

    Material m = material_plain(colour(200, 100, 50), 0);

    CHECK_INT(0, triangle_make(&tri, vec3(-1, 0, 5), vec3(1, 0, 5), vec3(0, 1, 5)));
    CHECK_INT(0, scene_add_triangle(&sc, &tri, &m));
    CHECK_COLOUR(200, 100, 50, seen(&sc, vec3(0, 0, 0), centroid, 0), 1e-9);
    {
        TriangleShading sh = shading_of(&sc, 0);
        sh.smooth = 1;
        for (int k = 0; k < 3; k++)
            sh.vn[k] = tilt[0];
        CHECK_INT(0, scene_shade_triangle(&sc, 0, &sh));
        CHECK_COLOUR(100, 50, 25, seen(&sc, vec3(0, 0, 0), vec3(0, a, 5), 0), 1e-9);
        for (int k = 0; k < 3; k++)
            sh.vn[k] = tilt[k];
        CHECK_INT(0, scene_shade_triangle(&sc, 0, &sh));
    }
    mean = vec3_normalize(vec3_add(vec3_add(tilt[0], tilt[1]), tilt[2]));
    {
        Vec3 l = vec3_normalize(vec3_sub(vec3(0, 0, -1e6), centroid));
        double c = vec3_dot(mean, l);
        CHECK_COLOUR(200 * c, 100 * c, 50 * c, seen(&sc, vec3(0, 0, 0), centroid, 0), 1e-6);
    }
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
    {"refract_follows_snell_at_known_angles", refract_follows_snell_at_known_angles},
    {"refract_total_internal_reflection_at_the_critical_angle",
     refract_total_internal_reflection_at_the_critical_angle},
    {"trace_clear_sphere_shows_what_is_behind", trace_clear_sphere_shows_what_is_behind},
    {"trace_transparency_follows_the_formula", trace_transparency_follows_the_formula},
    {"trace_shadow_through_glass_is_attenuated_per_crossing",
     trace_shadow_through_glass_is_attenuated_per_crossing},
    {"trace_refraction_enters_and_leaves_a_ball", trace_refraction_enters_and_leaves_a_ball},
    {"trace_total_internal_reflection_mirrors_the_transmitted_share",
     trace_total_internal_reflection_mirrors_the_transmitted_share},
    {"trace_ambient_and_lights_add_up", trace_ambient_and_lights_add_up},
    {"trace_exact_tie_across_kinds_keeps_the_first_listed",
     trace_exact_tie_across_kinds_keeps_the_first_listed},
    {"trace_smooth_triangle_shades_with_its_vertex_normals",
     trace_smooth_triangle_shades_with_its_vertex_normals},
    {NULL, NULL},
};
