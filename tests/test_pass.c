/* test_pass.c: one part of the picture alone (render/pass.h): direct and
 * indirect add up to the picture under every lighting rule, and the data
 * passes read the first surface's occlusion, colour, normal and distance
 * as pass.h says. */
#include <math.h>
#include <string.h>

#include "render/model.h"
#include "render/pass.h"
#include "render/render.h"
#include "render/trace.h"
#include "scenefile/load.h"
#include "test.h"

/* Reads text, of format, into *sc; returns 0 or -1 (reported). */
static int pass_scene(const char *text, SceneFormat format, Scene *sc)
{
    Error err;

    if (load_scene_text("t.txt", text, strlen(text), format, 0, 0, sc, NULL, &err) == 0)
        return 0;
    test_fail(__FILE__, __LINE__, "%d:%d: %s", err.line, err.column, err.message);
    return -1;
}

/* Renders sc's pass with indirect light `in`, two samples a pixel, into
 * img with its linear colours (allocated here); returns 0 or -1. */
static int pass_render(const Scene *sc, Indirect in, TracePass pass, Image *img)
{
    RenderOptions opts = {.max_depth = 10, .samples = 2, .threads = 2, .indirect = in,
                          .pass = pass};
    RayCounts counts = {0};

    if (image_init(img, sc->camera.width, sc->camera.height) != 0 || image_keep_linear(img) != 0)
        return -1;
    render(sc, &opts, img, &counts);
    return 0;
}

/* Checks that sc's direct and indirect passes add up to its picture in
 * every channel, to a float's rounding, and that each holds some light of
 * its own. */
static void pass_check_sum(const char *text, SceneFormat format, Indirect in)
{
    Scene sc;
    Image full, direct, indirect;
    double own = 0, gathered = 0, worst = 0;

    if (pass_scene(text, format, &sc) != 0)
        return;
    if (in.gi_samples == 0) { /* the model's own rays, as the MPL model's */
        const Model *m = model_of(&sc);
        in = (Indirect){m->ao_rays, m->ao_distance, m->gi_rays, 1, 0, 0};
    }
    CHECK_INT(0, pass_render(&sc, in, TRACE_PASS_FULL, &full));
    CHECK_INT(0, pass_render(&sc, in, TRACE_PASS_DIRECT, &direct));
    CHECK_INT(0, pass_render(&sc, in, TRACE_PASS_INDIRECT, &indirect));
    for (size_t i = 0; full.linear && i < 3 * (size_t)full.width * (size_t)full.height; i++) {
        double f = full.linear[i], d = direct.linear[i], g = indirect.linear[i];
        double off = fabs(f - d - g) / (1 + fabs(f));

        worst = off > worst ? off : worst;
        own += d;
        gathered += g;
    }
    CHECK(worst < 1e-6);
    CHECK(own > 1 && gathered > 1);
    image_free(&full);
    image_free(&direct);
    image_free(&indirect);
    scene_free(&sc);
}

static void pass_direct_and_indirect_add_up_to_the_picture(void)
{
    /* The course's rule: balls of glass and mirror on a mirrored floor
     * with ambient light, occlusion and two bounces. */
    static const char course[] =
        "0 2 -8\n-1.5 1.9 -6\n1.5 1.9 -6\n-1.5 -0.3 -6\n16\n20 30 40\n-4 6 -3 255 240 220\n"
        "ambient: 60 60 60\n"
        "plane: 0 0 0 0 1 0 200 200 200 0.2\n"
        "sphere: -1.2 1 0 1 220 80 60 0\n"
        "sphere: 1.2 1 0.5 1 60 200 90 0.3\n"
        "sphere: 0 0.6 -1.5 0.6 255 255 255 0.05 0.9 1.5\n";
    /* Named materials (Blinn-Phong, mirrored and glass) in the keyword
     * format. */
    static const char keyword[] = "camera 0 2.4 -7.5 0 0.8 0 0.9 16 12\nbackground 15 20 35\n"
                                  "ambient 40 40 48\n"
                                  "material floor 210 205 195 0.5 0.8 0.2 10 0.2\n"
                                  "material red 220 45 35 0.5 0.8 0.7 60\n"
                                  "material glass 255 255 255 0 0 0.9 600 0.05 1.5\n"
                                  "light -1 -2 1.5 255 250 235 1\n"
                                  "plane 0 0 0 0 1 0 floor\nsphere 2.3 1 1.5 1 red\n"
                                  "sphere 0.9 0.7 -1.2 0.7 glass\n";
    /* The MPL format's kinds, under its own model (occlusion multiplying
     * the colour, gathering the colours met) and under the physical one. */
    static const char mpl[] = "c Camera 0 1.6 -5.2 0 1.2 0 50 16 16\nc Ambient 0.3 0.3 0.3\n"
                              "m white MATTE 0.85 0.85 0.82 0 0 0 N\n"
                              "m plastic PLASTIC 0.2 0.35 0.85 0 1.5 60 N\n"
                              "m chrome METALLIC 0.9 0.9 0.92 0 1 200 N\n"
                              "m glass DIELECTRIC 1 1 1 0 1.5 100 N\n"
                              "p Plane 0 0 0 0 1 0 white\np Plane 0 0 2 0 0 -1 white\n"
                              "p Sphere -0.3 0.35 -0.6 0.35 plastic\n"
                              "p Sphere 0.8 0.55 0.2 0.55 glass\n"
                              "p Sphere 1.2 0.3 -0.9 0.3 chrome\n"
                              "l PointLight 0 2.8 0 1 1 1 6\n";
    char physical[sizeof mpl + 32];
    Indirect gi = {8, 1.5, 16, 2, 0, 0};

    pass_check_sum(course, SCENE_COURSE, gi);
    pass_check_sum(keyword, SCENE_KEYWORD, gi);
    pass_check_sum(mpl, SCENE_MPL, (Indirect){0, 1, 0, 1, 0, 0});
    strcpy(physical, "c Model physical\n");
    strcat(physical, mpl);
    pass_check_sum(physical, SCENE_MPL, gi);
}

/* The colour of pass seen along the ray from o towards d in sc, with
 * occlusion rays `ao` (distance 1) and the depth pass's scale s. */
static Colour pass_seen(const Scene *sc, TracePass pass, int ao, double s, Vec3 o, Vec3 d)
{
    TraceSample sample = {0, 0, 0, 1, NULL};
    RayCounts counts = {0};
    Ray r = {o, vec3_normalize(d)};
    Tracer t = model_tracer(sc, 10, &counts);

    t.indirect = (Indirect){ao, 1, 0, 1, 0, 0};
    t.sample = &sample;
    t.ao_grid = sampler_grid(ao > 0 ? (unsigned)ao : 1);
    t.gi_grid = sampler_grid(1);
    t.path_grid = sampler_grid(1);
    t.pass = pass;
    t.depth_scale = s;
    return t.model->trace(&t, &r, NULL);
}

static void pass_data_passes_read_the_first_surface(void)
{
    /* A floor (y = 0) of colour (90, 180, 45) and a wall x = 0.5 in
     * ambient light, lit by nothing; the floor's origin is seen from 1
     * above. There the wall hides the cosine-weighted share (acos c - c
     * sqrt(1 - c^2)) / pi, c = 0.5, of the hemisphere within distance 1
     * (test_trace_indirect.c): the ao pass is the rest, in grey. */
    static const char text[] = "0 5 -5\n-1 5 -4\n1 5 -4\n-1 3 -4\n8\n0 0 0\n0 -10 0 255 255 255\n"
                               "ambient: 255 255 255\n"
                               "plane: 0 0 0 0 1 0 90 180 45 0\n"
                               "plane: 0.5 0 0 1 0 0 255 255 255 0\n";
    const double c = 0.5, kept = 1 - (acos(c) - c * sqrt(1 - c * c)) / 3.14159265358979323846;
    Vec3 above = vec3(0, 1, 0), down = vec3(0, -1, 0);
    Scene sc;
    Colour got;

    if (pass_scene(text, SCENE_COURSE, &sc) != 0)
        return;
    got = pass_seen(&sc, TRACE_PASS_AO, 4096, 1, above, down);
    CHECK_NEAR(255 * kept, got.r, 0.6);
    CHECK_NEAR(got.r, got.b, 0);
    got = pass_seen(&sc, TRACE_PASS_AO, 0, 1, above, down); /* no rays: all kept */
    CHECK_NEAR(255, got.g, 0);
    got = pass_seen(&sc, TRACE_PASS_ALBEDO, 0, 1, above, down);
    CHECK_NEAR(90, got.r, 0);
    CHECK_NEAR(180, got.g, 0);
    CHECK_NEAR(45, got.b, 0);
    got = pass_seen(&sc, TRACE_PASS_NORMAL, 0, 1, above, down); /* (0, 1, 0) */
    CHECK_NEAR(127.5, got.r, 0);
    CHECK_NEAR(255, got.g, 0);
    CHECK_NEAR(127.5, got.b, 0);
    got = pass_seen(&sc, TRACE_PASS_NORMAL, 0, 1, vec3(2, 1, 0), vec3(-1, 0, 0)); /* the wall */
    CHECK_NEAR(255, got.r, 0);
    CHECK_NEAR(127.5, got.g, 0);
    /* Depth: 1 away at scale 2 is 2 / 3 of white; 3 away from 3 up, half. */
    CHECK_NEAR(255 * 2.0 / 3, pass_seen(&sc, TRACE_PASS_DEPTH, 0, 2, above, down).r, 1e-9);
    CHECK_NEAR(127.5, pass_seen(&sc, TRACE_PASS_DEPTH, 0, 3, vec3(0, 3, 0), down).r, 1e-9);
    /* Nothing seen: black in each, whatever the background. */
    for (TracePass p = TRACE_PASS_AO; p <= TRACE_PASS_DEPTH; p++)
        CHECK_NEAR(0, pass_seen(&sc, p, 16, 1, above, vec3(-1, 0.5, 0)).g, 0);
    scene_free(&sc);
}

/* The depth pass's scale is the distance the picture's centre sees: the
 * floor the camera looks down at, else the screen's. */
static void pass_depth_scale_is_what_the_centre_sees(void)
{
    static const char floor[] = "0 4 0\n-1 3 1\n1 3 1\n-1 3 -1\n8\n0 0 0\n0 9 0 255 255 255\n"
                                "plane: 0 0 0 0 1 0 90 180 45 0\n";
    static const char empty[] = "0 4 0\n-1 3 1\n1 3 1\n-1 3 -1\n8\n0 0 0\n0 9 0 255 255 255\n"
                                "plane: 0 9 0 0 1 0 90 180 45 0\n";
    Scene sc;

    if (pass_scene(floor, SCENE_COURSE, &sc) == 0) {
        CHECK_NEAR(4, pass_depth_scale(&sc), 1e-12);
        scene_free(&sc);
    }
    if (pass_scene(empty, SCENE_COURSE, &sc) == 0) {
        CHECK_NEAR(1, pass_depth_scale(&sc), 1e-12);
        scene_free(&sc);
    }
}

const TestCase pass_tests[] = {
    {"pass_direct_and_indirect_add_up_to_the_picture",
     pass_direct_and_indirect_add_up_to_the_picture},
    {"pass_data_passes_read_the_first_surface", pass_data_passes_read_the_first_surface},
    {"pass_depth_scale_is_what_the_centre_sees", pass_depth_scale_is_what_the_centre_sees},
    {NULL, NULL},
};
