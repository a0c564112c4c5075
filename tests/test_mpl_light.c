/* test_mpl_light.c: the MPL model (mpl_light.h), each rule on a small scene
 * with a known answer: the occlusion factor, the gathered colour, the
 * highlights, a point light's range and position, one shadow ray a light,
 * its cylinder's distance, its texture coordinates and the gamma. */
#include <math.h>
#include <string.h>

#include "image/image.h"
#include "render/model.h"
#include "render/mpl_light.h"
#include "render/trace.h"
#include "scene/mapping.h"
#include "scenefile/load.h"
#include "scenefile/mpl.h"
#include "test.h"

#define M_PI_VALUE 3.14159265358979323846

#define PI 3.14159265358979323846

/* Reads text as an MPL scene; returns 0 or -1 (a failed check). */
static int mpl_scene(const char *text, Scene *sc)
{
    Error err;

    if (load_scene_text("t.txt", text, strlen(text), SCENE_MPL, 0, 0, sc, NULL, &err) == 0)
        return 0;
    test_fail(__FILE__, __LINE__, "%d:%d: %s", err.line, err.column, err.message);
    return -1;
}

/* The colour seen from o towards d in sc (0..255), with ao occlusion and
 * gi gathering rays, shadows unless no_shadows. */
static Colour mpl_seen(const Scene *sc, Vec3 o, Vec3 d, int ao, int gi, int no_shadows)
{
    Ray r = {o, vec3_normalize(d)};
    RayCounts counts = {0};
    TraceSample sample = {3, 5, 0, 1, NULL};
    Tracer t = model_tracer(sc, MPL_LIGHT_MAX_DEPTH, &counts);

    t.sample = &sample;
    t.no_shadows = no_shadows;

    t.indirect.ao_samples = ao;
    t.indirect.ao_distance = MPL_LIGHT_AO_DISTANCE;
    t.indirect.gi_samples = gi;
    t.indirect.gi_bounces = 1;
    t.ao_grid = sampler_grid(ao > 0 ? (unsigned)ao : 1);
    t.gi_grid = sampler_grid(gi > 0 ? (unsigned)gi : 1);
    t.path_grid = sampler_grid(1);
    return sc->model == SCENE_MODEL_MPL ? mpl_light_trace(&t, &r) : trace_ray(&t, &r);
}

/* A tiny sphere at the centre of a hollow one of radius 1, lit along the
 * view; the camera inside. */
#define MPL_HOLLOW(inner, outer, intensity)                                                   \
    "c Background 0 0 0\n"                                                                      \
    "m in MATTE " inner " 0 0 0 N\nm out MATTE " outer " 0 0 0 N\n"                             \
    "p Sphere 0 0 0 0.0001 in\np Sphere 0 0 0 1 out\n"                                          \
    "l DirectionLight 0 0 1 1 1 1 " intensity "\n"

static void mpl_light_occlusion_is_the_mean_distance_over_its_reach(void)
{
    /* Every occlusion ray from the tiny sphere meets the hollow one about
     * 1 away: A = min(1 / 2, 1) = 1/2 of (D + G) a / pi, D = a I cos. */
    Scene sc;

    if (mpl_scene(MPL_HOLLOW("1 1 1", "1 1 1", "1"), &sc) != 0)
        return;
    CHECK_NEAR(255 * 0.5 / PI, mpl_seen(&sc, vec3(0, 0, -0.5), vec3(0, 0, 1), 16, 0, 1).r, 0.01);
    CHECK_NEAR(255 / PI, mpl_seen(&sc, vec3(0, 0, -0.5), vec3(0, 0, 1), 0, 0, 1).r, 1e-9);
    scene_free(&sc);
}

static void mpl_light_gathers_the_colour_its_rays_meet(void)
{
    /* Unlit, the tiny sphere shows only what it gathers: the hollow
     * sphere's colour b, times its own a, over pi. */
    Scene sc;
    Colour c;

    if (mpl_scene(MPL_HOLLOW("1 0.5 0.25", "0.6 0.4 0.2", "0"), &sc) != 0)
        return;
    c = mpl_seen(&sc, vec3(0, 0, -0.5), vec3(0, 0, 1), 0, 16, 1);
    CHECK_NEAR(255 * 0.6 * 1 / PI, c.r, 1e-9);
    CHECK_NEAR(255 * 0.4 * 0.5 / PI, c.g, 1e-9);
    CHECK_NEAR(255 * 0.2 * 0.25 / PI, c.b, 1e-9);
    scene_free(&sc);
}

static void mpl_light_glossy_surfaces_get_its_highlights(void)
{
    /* Head on (N . V = -1, so 2 (N . V)^2 - 1 = 1): D = a I = 0.8 x 0.5,
     * S = I = 0.5; with a glossiness, L = D (D + S). */
    static const char *const texts[] = {
        "c Background 0 0 0\nm s MATTE 0.8 0.8 0.8 0 0 0 N\np Sphere 0 0 0 1 s\n"
        "l DirectionLight 0 0 1 1 1 1 0.5\n",
        "c Background 0 0 0\nm s MATTE 0.8 0.8 0.8 0 0 10 N\np Sphere 0 0 0 1 s\n"
        "l DirectionLight 0 0 1 1 1 1 0.5\n",
        "c Background 0 0 0\nm s METALLIC 0.8 0.8 0.8 0 1 10 N\np Sphere 0 0 0 1 s\n"
        "l DirectionLight 0 0 1 1 1 1 0.5\n",
    };
    const double d = 0.8 * 0.5, expect[] = {255 * d * 0.8 / PI, 255 * d * (d + 0.5) * 0.8 / PI,
                                            255 * d * (d + 0.5)};

    for (int k = 0; k < 3; k++) {
        Scene sc;
        if (mpl_scene(texts[k], &sc) != 0)
            continue;
        CHECK_NEAR(expect[k], mpl_seen(&sc, vec3(0, 0, -5), vec3(0, 0, 1), 0, 0, 0).r, 1e-9);
        scene_free(&sc);
    }
}

static void mpl_light_point_light_reaches_its_range_at_full_strength(void)
{
    /* A white floor under a light 2 above it, of range 3 and intensity 8:
     * 8 cos / d^2 within the range, nothing beyond; its position as the
     * file writes it (the program's reader made it a unit vector). */
    Scene sc;
    double d2 = 4 + 4, c = 2 / sqrt(d2);

    if (mpl_scene("c Background 0 0 0\nm w MATTE 1 1 1 0 0 0 N\np Plane 0 0 0 0 1 0 w\n"
                   "l PointLight 0 2 0 1 1 1 8 3\n",
                   &sc) != 0)
        return;
    CHECK_NEAR(255 * 8 / 4.0 / PI, mpl_seen(&sc, vec3(0, 1, -1), vec3(0, -1, 1), 0, 0, 0).r, 1e-9);
    CHECK_NEAR(255 * 8 * c / d2 / PI, mpl_seen(&sc, vec3(2, 1, -1), vec3(0, -1, 1), 0, 0, 0).r,
               1e-9);
    CHECK_NEAR(0, mpl_seen(&sc, vec3(2.5, 1, -1), vec3(0, -1, 1), 0, 0, 0).r, 0);
    scene_free(&sc);
}

static void mpl_light_each_light_has_its_own_shadow(void)
{
    /* Two lights straight down and slanted; a slab hides the floor's
     * origin from the first only: the point gets the second alone (the
     * program lit it by both once one was unblocked). */
    Scene sc;
    double s = sqrt(0.5);

    if (mpl_scene("c Background 0 0 0\nm w MATTE 1 1 1 0 0 0 N\np Plane 0 0 0 0 1 0 w\n"
                   "p Square 0 2 0 0 1 0 0.5 w\n"
                   "l DirectionLight 0 -1 0 1 1 1 1\nl DirectionLight 1 -1 0 1 1 1 1\n",
                   &sc) != 0)
        return;
    CHECK_NEAR(255 * s / PI, mpl_seen(&sc, vec3(0, 1, -1), vec3(0, -1, 1), 0, 0, 0).r, 1e-9);
    CHECK_NEAR(255 * (1 + s) / PI, mpl_seen(&sc, vec3(0, 1, -1), vec3(0, -1, 1), 0, 0, 1).r,
               1e-9);
    scene_free(&sc);
}

static void mpl_light_cylinder_is_where_its_program_put_it(void)
{
    /* A ray 45 degrees down meets the floor (y = -3.5) at t = 4.95 and the
     * cylinder (z = 5, radius 1) only at 5.66; the program measured 4
     * across the ground and went 4 along the ray: the cylinder (red) in
     * front of the floor (white). The physical model sees the floor. */
    Scene sc;
    Colour c;

    if (mpl_scene("c Background 0 0 0\nm w MATTE 1 1 1 0 0 0 N\nm r MATTE 1 0 0 0 0 0 N\n"
                   "p Plane 0 -3.5 0 0 1 0 w\np Cylinder 0 0 5 1 r\n"
                   "l DirectionLight 0 -1 1 1 1 1 1\n",
                   &sc) != 0)
        return;
    c = mpl_seen(&sc, vec3(0, 0, 0), vec3(0, -1, 1), 0, 0, 1);
    CHECK(c.r > 0 && c.g == 0);
    sc.model = SCENE_MODEL_PHYSICAL;
    c = mpl_seen(&sc, vec3(0, 0, 0), vec3(0, -1, 1), 0, 0, 1);
    CHECK(c.g > 0);
    scene_free(&sc);
}

/* Checks mapping_mpl() at point p (normal n) of shape index of kind in sc. */
static void mpl_uv(const Scene *sc, ShapeKind kind, Vec3 p, Vec3 n, double u, double v,
                    double stripe, int line)
{
    SurfacePoint sp = {p, n, n, vec3(0, 0, 0)};
    double uv[2], s;

    mapping_mpl(sc, kind, 0, &sp, uv, &s);
    if (fabs(uv[0] - u) > 1e-12 || fabs(uv[1] - v) > 1e-12 || fabs(s - stripe) > 1e-12)
        test_fail(__FILE__, line, "expected (%g, %g) stripe %g, got (%g, %g) stripe %g", u, v,
                  stripe, uv[0], uv[1], s);
}

static void mpl_light_texture_coordinates_follow_its_program(void)
{
    Scene sc;

    if (mpl_scene("m a MATTE 1 1 1 0 0 0 N\np Sphere 0 0 0 1 a\np Sphere 0 0 0 0.5 a\n"
                   "p Cube 0 0 0 1 a\np Cylinder 1 2 3 1 a\np Cone 0 0 0 1 2 a\n"
                   "p Plane 0 0 7 0 0 -1 a\np Square 1 1 5 0 0 -1 20 a\n",
                   &sc) != 0)
        return;
    /* Sphere: its camera-facing point is u = 3/4, and u falls to the
     * right (+x is 1/2); 10 r stripes, 30 r below a radius of 1. */
    mpl_uv(&sc, SHAPE_SPHERE, vec3(0, 0, -1), vec3(0, 0, -1), 0.75, 0.5, 7.5, __LINE__);
    mpl_uv(&sc, SHAPE_SPHERE, vec3(1, 0, 0), vec3(1, 0, 0), 0.5, 0.5, 5, __LINE__);
    mpl_uv(&sc, SHAPE_SPHERE, vec3(0, 1, 0), vec3(0, 1, 0), 0.5, 1, 5, __LINE__);
    {
        SurfacePoint sp = {vec3(0, 0, -0.5), vec3(0, 0, -1), vec3(0, 0, -1), vec3(0, 0, 0)};
        double uv[2], s;
        mapping_mpl(&sc, SHAPE_SPHERE, 1, &sp, uv, &s);
        CHECK_NEAR(0.75 * 15, s, 1e-12);
    }
    /* Cube: the whole image on each face, upright on the sides. */
    mpl_uv(&sc, SHAPE_CUBE, vec3(0.5, -0.5, -1), vec3(0, 0, -1), 0.75, 0.25, 7.5, __LINE__);
    mpl_uv(&sc, SHAPE_CUBE, vec3(0.5, 1, -0.5), vec3(0, 1, 0), 0.75, 0.25, 7.5, __LINE__);
    mpl_uv(&sc, SHAPE_CUBE, vec3(1, 0.5, 0.5), vec3(1, 0, 0), 0.75, 0.75, 7.5, __LINE__);
    /* Cylinder: the seam faces -z; v the height above its centre,
     * modulo 1. */
    mpl_uv(&sc, SHAPE_CYLINDER, vec3(1, 2.25, 2), vec3(0, 0, -1), 0, 0.25, 0, __LINE__);
    mpl_uv(&sc, SHAPE_CYLINDER, vec3(2, 1.5, 3), vec3(1, 0, 0), 0.25, 0.5, 2.5, __LINE__);
    mpl_uv(&sc, SHAPE_CONE, vec3(-0.5, 1, 0), vec3(-1, 0, 0), 0.75, 0, 7.5, __LINE__);
    /* Flat shapes, by its program: the fractions of (x, y) whichever way
     * they face, a floor's v its own height's (0 at a whole height, read
     * clamped: its one row); a square's stripes half / 10 as wide. */
    mpl_uv(&sc, SHAPE_PLANE, vec3(2.25, -0.5, 7), vec3(0, 0, -1), 0.25, 0.5, 0.25, __LINE__);
    scene_planes(&sc)[0].normal = vec3(0, 1, 0);
    scene_planes(&sc)[0].point = vec3(0, 0, 7);
    mpl_uv(&sc, SHAPE_PLANE, vec3(1.5, -1e-17, -2.75), vec3(0, 1, 0), 0.5, 0, 0.5, __LINE__);
    {
        SurfacePoint sp = {vec3(1.5, 0, -2.75), vec3(0, 1, 0), vec3(0, 1, 0), vec3(0, 0, 0)};
        double uv[2], st;
        CHECK_INT(1, mapping_mpl(&sc, SHAPE_PLANE, 0, &sp, uv, &st));
    }
    scene_planes(&sc)[0].normal = vec3(-1, 0, 0);
    mpl_uv(&sc, SHAPE_PLANE, vec3(3, 0.5, 1.25), vec3(-1, 0, 0), 0, 0.5, 0, __LINE__);
    mpl_uv(&sc, SHAPE_SQUARE, vec3(1.25, 0.5, 5), vec3(0, 0, -1), 0.25, 0.5, 0.5, __LINE__);
    /* Sphere of radius 0.5 (its program's v: the height not divided by
     * the radius, so only the middle band of the image). */
    {
        SurfacePoint sp = {vec3(0, 0.25, -sqrt(0.1875)), vec3(0, 0.5, -sqrt(0.75)),
                           vec3(0, 0.5, -sqrt(0.75)), vec3(0, 0, 0)};
        double uv[2], st;
        CHECK_INT(0, mapping_mpl(&sc, SHAPE_SPHERE, 1, &sp, uv, &st));
        CHECK_NEAR(1 - acos(0.25) / M_PI_VALUE, uv[1], 1e-12);
        /* Under the physical model: the unit normal's, the whole image. */
        sc.model = SCENE_MODEL_PHYSICAL;
        mapping_mpl(&sc, SHAPE_SPHERE, 1, &sp, uv, &st);
        CHECK_NEAR(1 - acos(0.5) / M_PI_VALUE, uv[1], 1e-12);
    }
    /* The physical model keeps our flat mapping: (x, z) on a floor, (z, y)
     * on a wall facing x, both wrapped. */
    scene_planes(&sc)[0].normal = vec3(0, 1, 0);
    mpl_uv(&sc, SHAPE_PLANE, vec3(1.5, 0, -2.75), vec3(0, 1, 0), 0.5, 0.25, 0.5, __LINE__);
    scene_planes(&sc)[0].normal = vec3(-1, 0, 0);
    mpl_uv(&sc, SHAPE_PLANE, vec3(3, 0.5, 1.25), vec3(-1, 0, 0), 0.25, 0.5, 0.25, __LINE__);
    scene_free(&sc);
}

static void mpl_light_bytes_are_gamma_encoded(void)
{
    /* Byte b stands for 255 (b / 255)^2.2: each reads back as itself; a
     * half-bright colour is 186, not 128. */
    Image img;
    int ok = 1;

    CHECK_INT(0, image_init(&img, 1, 1));
    CHECK_INT(0, image_encode_gamma(&img, MPL_LIGHT_GAMMA));
    for (int b = 0; b < 256; b++)
        ok &= colour_encode(img.encode, 255 * pow(b / 255.0, 2.2)) == b;
    CHECK(ok);
    CHECK_INT(186, colour_encode(img.encode, 127.5));
    CHECK_INT(0, colour_encode(img.encode, -3));
    CHECK_INT(0, colour_encode(img.encode, NAN));
    CHECK_INT(255, colour_encode(img.encode, 400));
    image_set(&img, 0, 0, colour(127.5, 0, 255));
    CHECK_INT(186, img.rgb[0]);
    CHECK_INT(255, img.rgb[2]);
    image_free(&img);
}

const TestCase mpl_light_tests[] = {
    {"mpl_light_occlusion_is_the_mean_distance_over_its_reach",
     mpl_light_occlusion_is_the_mean_distance_over_its_reach},
    {"mpl_light_gathers_the_colour_its_rays_meet", mpl_light_gathers_the_colour_its_rays_meet},
    {"mpl_light_glossy_surfaces_get_its_highlights", mpl_light_glossy_surfaces_get_its_highlights},
    {"mpl_light_point_light_reaches_its_range_at_full_strength",
     mpl_light_point_light_reaches_its_range_at_full_strength},
    {"mpl_light_each_light_has_its_own_shadow", mpl_light_each_light_has_its_own_shadow},
    {"mpl_light_cylinder_is_where_its_program_put_it", mpl_light_cylinder_is_where_its_program_put_it},
    {"mpl_light_texture_coordinates_follow_its_program",
     mpl_light_texture_coordinates_follow_its_program},
    {"mpl_light_bytes_are_gamma_encoded", mpl_light_bytes_are_gamma_encoded},
    {NULL, NULL},
};
