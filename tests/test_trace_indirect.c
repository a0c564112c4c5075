/* test_trace_indirect.c: ambient occlusion and global illumination against
 * shares and colours known in closed form, and their bytes against thread
 * counts and against renders without them. */
#include <math.h>
#include <stdio.h>
#include <string.h>

#include "render/model.h"
#include "render/render.h"
#include "render/trace.h"
#include "scenefile/load.h"
#include "scenefile/course.h"
#include "test.h"

#define PI 3.14159265358979323846

/* Reads a course scene from text into *sc; returns 0 or -1 (reported). */
static int indirect_scene(const char *text, Scene *sc)
{
    Error err;

    if (load_scene_text("t.txt", text, strlen(text), SCENE_COURSE, 0, 0, sc, NULL, &err) != 0) {
        test_fail(__FILE__, __LINE__, "%d:%d: %s", err.line, err.column, err.message);
        return -1;
    }
    return 0;
}

/* The colour of the sample of pixel (0, 0) along the ray from o towards
 * d, traced with indirect light `in`, one sample a pixel. */
static Colour indirect_seen(const Scene *sc, Indirect in, Vec3 o, Vec3 d, RayCounts *counts)
{
    TraceSample s = {0, 0, 0, 1, NULL};
    Ray r = {o, vec3_normalize(d)};
    Tracer t = model_tracer(sc, 10, counts);

    t.indirect = in;
    t.sample = &s;

    t.ao_grid = sampler_grid((unsigned)(in.ao_samples ? in.ao_samples : 1));
    t.gi_grid = sampler_grid((unsigned)(in.gi_samples ? in.gi_samples : 1));
    t.path_grid = sampler_grid(1);
    return trace_ray(&t, &r);
}

/* A white floor (y = 0) in white ambient light, lit by nothing (the light
 * is below it), and a wall x = 0.5: seen from the floor's origin, the wall
 * hides within distance D the directions whose x exceeds c = 0.5 / D. The
 * cosine-weighted share of those is the disk's segment beyond c, (acos c -
 * c sqrt(1 - c^2)) / pi (0.1955 for D = 1, where uniform directions would
 * give (1 - c) / 2 = 0.25; 4,096 stratified rays find it within 0.002). */
static void indirect_occlusion_follows_the_cosine_law(void)
{
    static const char text[] = "0 5 -5\n-1 5 -4\n1 5 -4\n-1 3 -4\n8\n0 0 0\n0 -10 0 255 255 255\n"
                               "ambient: 255 255 255\n"
                               "plane: 0 0 0 0 1 0 255 255 255 0\n"
                               "plane: 0.5 0 0 1 0 0 255 255 255 0\n";
    const double distances[] = {1, 2, 0.75};
    Scene sc;
    RayCounts counts = {0};

    if (indirect_scene(text, &sc) != 0)
        return;
    for (int k = 0; k < 3; k++) {
        Indirect in = {4096, distances[k], 0, 1, 0, 0};
        double c = 0.5 / distances[k], hidden = (acos(c) - c * sqrt(1 - c * c)) / PI;
        Colour got = indirect_seen(&sc, in, vec3(0, 1, 0), vec3(0, -1, 0), &counts);
        CHECK_NEAR(255 * (1 - hidden), got.r, 0.6); /* 0.0024 of the share */
        CHECK_NEAR(got.r, got.b, 0);
    }
    CHECK_INT(3 * 4096, (long long)counts.occlusion);
    /* Nearer than nothing: nothing is hidden, the colour is the ambient's. */
    {
        Indirect none = {64, 0.01, 0, 1, 0, 0};
        CHECK_NEAR(255, indirect_seen(&sc, none, vec3(0, 1, 0), vec3(0, -1, 0), &counts).g, 0);
    }
    scene_free(&sc);
}

/* A point light at the centre of a hollow grey ball (radius 100, colour
 * 128) lights its inside head on everywhere, so every gathering ray from a
 * triangle facing the light sees 128: the triangle's colour gains exactly
 * Ci * 128 / 255 over its direct light, whatever the rays' directions. */
static void indirect_gathering_from_a_uniformly_lit_ball(void)
{
    static const char text[] = "0 0 -5\n-1 1 -4\n1 1 -4\n-1 -1 -4\n8\n0 0 0\n0 0 0 255 255 255\n"
                               "sphere: 0 0 0 100 128 128 128 0\n"
                               "triangle: -1 -1 10 1 -1 10 0 1 10 200 100 50 0\n";
    Scene sc;
    RayCounts counts = {0};
    Indirect off = {0, 1, 0, 1, 0, 0}, gi = {0, 1, 64, 1, 0, 0};
    Vec3 o = vec3(0, 0, -5), d = vec3(0, 0, 1);

    if (indirect_scene(text, &sc) != 0)
        return;
    {
        Colour direct = indirect_seen(&sc, off, o, d, &counts);
        Colour both = indirect_seen(&sc, gi, o, d, &counts);
        CHECK_NEAR(direct.r + 200 * 128.0 / 255, both.r, 1e-9);
        CHECK_NEAR(direct.g + 100 * 128.0 / 255, both.g, 1e-9);
        CHECK_NEAR(direct.b + 50 * 128.0 / 255, both.b, 1e-9);
        CHECK_INT(64, (long long)counts.gather);
    }
    scene_free(&sc);
}

/* Renders text at 12 x 12 with indirect light `in`, spp samples, on
 * `threads` threads into img (allocated here); counts the rays. */
static void indirect_render(const char *text, Indirect in, int spp, int threads, Image *img,
                            RayCounts *counts)
{
    RenderOptions opts = {.max_depth = 10, .samples = spp, .cutoff = 0.1, .threads = threads,
                          .indirect = in};
    Scene sc;

    img->rgb = NULL;
    img->linear = NULL;
    img->encode = NULL;
    if (indirect_scene(text, &sc) != 0)
        return;
    CHECK_INT(0, image_init(img, sc.camera.width, sc.camera.height));
    render(&sc, &opts, img, counts);
    scene_free(&sc);
}

/* Three balls on a mirrored floor in ambient light, one of glass. */
static const char indirect_balls[] =
    "0 2 -8\n-1.5 1.9 -6\n1.5 1.9 -6\n-1.5 -0.3 -6\n12\n20 30 40\n-4 6 -3 255 240 220\n"
    "ambient: 60 60 60\n"
    "plane: 0 0 0 0 1 0 200 200 200 0.2\n"
    "sphere: -1.2 1 0 1 220 80 60 0\n"
    "sphere: 1.2 1 0.5 1 60 200 90 0.3\n"
    "sphere: 0 0.6 -1.5 0.6 255 255 255 0.05 0.9 1.5\n";

/* Occlusion and gathering draw from the pixel and the sample alone: the
 * same bytes on 1, 2 and 7 threads, with one sample a pixel or four. */
static void indirect_bytes_do_not_depend_on_threads(void)
{
    Indirect in = {8, 1.5, 8, 2, 0, 0};
    size_t size;
    Image one, two, seven;
    RayCounts counts = {0};

    for (int spp = 1; spp <= 4; spp += 3) {
        indirect_render(indirect_balls, in, spp, 1, &one, &counts);
        indirect_render(indirect_balls, in, spp, 2, &two, &counts);
        indirect_render(indirect_balls, in, spp, 7, &seven, &counts);
        size = 3 * (size_t)one.width * (size_t)one.height;
        CHECK(one.rgb && two.rgb && seven.rgb);
        CHECK(one.rgb && two.rgb && memcmp(one.rgb, two.rgb, size) == 0);
        CHECK(one.rgb && seven.rgb && memcmp(one.rgb, seven.rgb, size) == 0);
        image_free(&one);
        image_free(&two);
        image_free(&seven);
    }
    CHECK(counts.occlusion > 0 && counts.gather > 0);
}

/* What hides nothing and what gathers nothing change no byte: occlusion
 * within a distance shorter than any gap, gathering in a scene where
 * every gathering ray escapes (one ball); and a scene without ambient
 * light casts no occlusion ray. */
static void indirect_that_finds_nothing_changes_nothing(void)
{
    static const char ball[] = "0 0 -5\n-1 1 -4\n1 1 -4\n-1 -1 -4\n12\n20 30 40\n"
                               "-4 6 -3 255 240 220\nambient: 60 60 60\n"
                               "sphere: 0 0 0 1 220 80 60 0\n";
    static const char dark[] = "0 0 -5\n-1 1 -4\n1 1 -4\n-1 -1 -4\n12\n20 30 40\n"
                               "-4 6 -3 255 240 220\n"
                               "sphere: 0 0 0 1 220 80 60 0\nsphere: 0 -3 0 1.8 90 90 90 0\n";
    Indirect off = {0, 1, 0, 1, 0, 0}, near = {16, 1e-9, 0, 1, 0, 0}, escaping = {0, 1, 16, 3, 0, 0};
    Image a, b;
    RayCounts counts = {0};

    indirect_render(indirect_balls, off, 1, 2, &a, &counts);
    indirect_render(indirect_balls, near, 1, 2, &b, &counts);
    CHECK(a.rgb && b.rgb && memcmp(a.rgb, b.rgb, 3 * (size_t)a.width * (size_t)a.height) == 0);
    image_free(&a);
    image_free(&b);
    indirect_render(ball, off, 1, 2, &a, &counts);
    indirect_render(ball, escaping, 1, 2, &b, &counts);
    CHECK(a.rgb && b.rgb && memcmp(a.rgb, b.rgb, 3 * (size_t)a.width * (size_t)a.height) == 0);
    image_free(&a);
    image_free(&b);
    counts.occlusion = 0;
    indirect_render(dark, near, 1, 2, &a, &counts);
    CHECK_INT(0, (long long)counts.occlusion);
    image_free(&a);
}

/* More bounces add light (each gathers what the last one reflected),
 * and converge: the sixth bounce adds less than the second. */
static void indirect_bounces_add_light_and_converge(void)
{
    Scene sc;
    RayCounts counts = {0};
    double last = 0, first_step = 0, step = 0;
    Vec3 o = vec3(0, 2, -8), d = vec3(-0.3, -0.35, 1);

    if (indirect_scene(indirect_balls, &sc) != 0)
        return;
    for (int b = 1; b <= 6; b++) {
        Indirect in = {0, 1, 256, b, 0, 0};
        Colour c = indirect_seen(&sc, in, o, d, &counts);
        double sum = c.r + c.g + c.b;
        CHECK(sum >= last);
        step = sum - last;
        if (b == 2)
            first_step = step;
        last = sum;
    }
    CHECK(step < first_step);
    scene_free(&sc);
}

/* Writes a course scene of a white floor (y = 0) and wall (x = 0) meeting
 * on the z axis, lit from the room and by white ambient light, every
 * length times scale and every point moved by offset. */
static void indirect_corner_scene(char *buf, size_t size, double scale, double offset)
{
    double s = scale, o = offset;

    snprintf(buf, size,
             "%.17g %.17g %.17g\n%.17g %.17g %.17g\n%.17g %.17g %.17g\n%.17g %.17g %.17g\n8\n"
             "0 0 0\n%.17g %.17g %.17g 255 255 255\nambient: 100 100 100\n"
             "plane: %.17g %.17g %.17g 0 1 0 200 200 200 0\n"
             "plane: %.17g %.17g %.17g 1 0 0 200 200 200 0\n",
             3 * s + o, 3 * s + o, -5 * s + o, 2 * s + o, 4 * s + o, -4 * s + o, 4 * s + o,
             4 * s + o, -4 * s + o, 2 * s + o, 2 * s + o, -4 * s + o, 3 * s + o, 4 * s + o,
             0.5 * s + o, o, o, o, o, o, o);
}

/* A ray aimed at a point of the line where a floor and a wall meet finds
 * it on one of them, rounding putting it a hair on either side of the
 * other: its direct light, occlusion and gathered light must be those of
 * that surface just beside the line (with the same sample directions), at
 * scales 1e-4 to 1e6 and moved 1e7 away. (The light makes the floor's
 * direct light and the wall's differ, which tells which was met.) Before
 * the step back (geometry/ray.h) such points were black in shadow, their
 * occlusion rays escaped through the wall, and a third of their gathered
 * light was missing. */
static void indirect_corner_points_see_their_whole_hemisphere(void)
{
    static const double moves[][2] = {{1, 0}, {1e-4, 0}, {1e6, 0}, {1, 1e7}, {1e-4, 1e7}};
    static const double along[] = {0.3, 1.7, -2.1, 0.05, 3.3};
    static const char *const kind[3] = {"direct", "occlusion", "gathered"};
    char text[2000];
    int compared = 0;

    for (size_t m = 0; m < sizeof moves / sizeof moves[0]; m++) {
        double s = moves[m][0], o = moves[m][1];
        Indirect lit = {0, 1, 0, 1, 0, 0}, ao = {1024, 2 * s, 0, 1, 0, 0},
                 gi = {0, 1, 256, 1, 0, 0}, kinds[3] = {lit, ao, gi};
        Scene sc;
        RayCounts counts = {0};

        indirect_corner_scene(text, sizeof text, s, o);
        if (indirect_scene(text, &sc) != 0)
            return;
        for (size_t a = 0; a < sizeof along / sizeof along[0]; a++) {
            Vec3 eye = vec3(1.3 * s + o, 0.9 * s + o, (along[a] - 0.4 - a) * s + o);
            double z = along[a] * s + o;
            Vec3 aims[3] = {vec3(o, o, z), vec3(1e-3 * s + o, o, z),
                            vec3(o, 1e-3 * s + o, z)}; /* corner, floor, wall */
            double c[3][3];
            int wall;

            for (int k = 0; k < 3; k++)
                for (int p = 0; p < 3; p++)
                    c[p][k] = indirect_seen(&sc, kinds[k], eye, vec3_sub(aims[p], eye), &counts).r;
            CHECK(fabs(c[1][0] - c[2][0]) > 20);
            wall = fabs(c[0][0] - c[2][0]) < fabs(c[0][0] - c[1][0]);
            for (int k = 0; k < 3; k++) {
                if (fabs(c[0][k] - c[1 + wall][k]) > 2)
                    test_fail(__FILE__, __LINE__, "scale %g, offset %g, z %g, %s: %.1f beside %.1f",
                              s, o, along[a], kind[k], c[0][k], c[1 + wall][k]);
                compared++;
            }
        }
        scene_free(&sc);
    }
    CHECK_INT(75, compared);
}

const TestCase trace_indirect_tests[] = {
    {"indirect_occlusion_follows_the_cosine_law", indirect_occlusion_follows_the_cosine_law},
    {"indirect_gathering_from_a_uniformly_lit_ball", indirect_gathering_from_a_uniformly_lit_ball},
    {"indirect_bytes_do_not_depend_on_threads", indirect_bytes_do_not_depend_on_threads},
    {"indirect_that_finds_nothing_changes_nothing", indirect_that_finds_nothing_changes_nothing},
    {"indirect_bounces_add_light_and_converge", indirect_bounces_add_light_and_converge},
    {"indirect_corner_points_see_their_whole_hemisphere",
     indirect_corner_points_see_their_whole_hemisphere},
    {NULL, NULL},
};
