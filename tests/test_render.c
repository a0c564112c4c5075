/* test_render.c: primary rays, thread independence, and renders that must
 * not change when the scene is scaled or moved far away. */
#include <math.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>

#include "render/model.h"
#include "render/render.h"
#include "render/trace.h"
#include "rng.h"
#include "scene/camera.h"
#include "scene/scene_accel.h"
#include "scenefile/course.h"
#include "scenefile/load.h"
#include "test.h"

static Camera camera_square(void)
{
    Camera cam = {{0, 0, 0}, {-1, 1, 1}, {2, 0, 0}, {0, -2, 0}, 4, 4, 0, 0, {0, 0, 0}, {0, 0, 0},
                  {0, 0, 0}};
    return cam;
}

static void render_pixel_centres_map_to_the_screen(void)
{
    Camera cam = camera_square();
    Ray r = camera_ray(&cam, 0.5, 0.5);
    Vec3 expect = vec3_normalize(vec3(-0.75, 0.75, 1));

    CHECK_NEAR(expect.x, r.dir.x, 1e-15);
    CHECK_NEAR(expect.y, r.dir.y, 1e-15);
    CHECK_NEAR(expect.z, r.dir.z, 1e-15);
    r = camera_ray(&cam, 3.5, 3.5); /* bottom-right pixel */
    CHECK_NEAR(expect.y, -r.dir.y, 1e-15);
    CHECK_NEAR(-expect.x, r.dir.x, 1e-15);
    CHECK_NEAR(0, r.origin.x, 0);
}

static void render_sheared_screen(void)
{
    /* Left edge slanted: row j's pixels shift right by (j + .5) / H of v.x. */
    Camera cam = {{0, 0, 0}, {0, 0, 1}, {4, 0, 0}, {2, -2, 0}, 4, 2, 0, 0, {0, 0, 0}, {0, 0, 0},
                  {0, 0, 0}};
    Ray r = camera_ray(&cam, 0.5, 1.5);
    Vec3 p = vec3(0.5 + 0.75 * 2, -0.75 * 2, 1);
    Vec3 expect = vec3_normalize(p);

    CHECK_NEAR(expect.x, r.dir.x, 1e-15);
    CHECK_NEAR(expect.y, r.dir.y, 1e-15);
    CHECK_NEAR(expect.z, r.dir.z, 1e-15);
}

static void render_eye_on_the_screen_sees_background(void)
{
    /* The eye is the first pixel's centre: a zero direction, no crash. */
    Camera cam = {{-0.75, 0.75, 1}, {-1, 1, 1}, {2, 0, 0}, {0, -2, 0}, 4, 4, 0, 0, {0, 0, 0},
                  {0, 0, 0}, {0, 0, 0}};
    Ray r = camera_ray(&cam, 0.5, 0.5);
    CHECK_NEAR(0, vec3_length(r.dir), 0);
}

/* Checks that every pixel of a render of text (with its hierarchy, when
 * it has enough shapes) is the course format's primary ray traced: P =
 * TL + ((i + 0.5) / W) u + ((j + 0.5) / H) v, summed left to right, its
 * direction normalize(P - eye), to the bit. */
static void check_pixels_are_their_rays(const char *text)
{
    RenderOptions opts = {.max_depth = 10, .samples = 1, .threads = 2};
    RayCounts counts = {0};
    Scene sc;
    Error err;
    Image img;
    int bad = 0;

    CHECK_INT(0, load_scene_text("t.txt", text, strlen(text), SCENE_COURSE, 0, 0, &sc, NULL, &err));
    CHECK_INT(0, scene_build_accel(&sc, 1));
    CHECK_INT(0, image_init(&img, sc.camera.width, sc.camera.height));
    render(&sc, &opts, &img, NULL);
    for (int j = 0; j < img.height; j++)
        for (int i = 0; i < img.width; i++) {
            const Camera *c = &sc.camera;
            double fx = (i + 0.5) / c->width, fy = (j + 0.5) / c->height;
            Vec3 p = vec3(c->top_left.x + fx * c->u.x + fy * c->v.x,
                          c->top_left.y + fx * c->u.y + fy * c->v.y,
                          c->top_left.z + fx * c->u.z + fy * c->v.z);
            Ray ray = {c->eye, vec3_normalize(vec3_sub(p, c->eye))};
            Ray got = camera_ray(c, i + 0.5, j + 0.5);
            Tracer t = model_tracer(&sc, opts.max_depth, &counts);
            Colour want = trace_ray(&t, &ray);
            const unsigned char *px = img.rgb + 3 * ((size_t)j * (size_t)img.width + (size_t)i);
            bad += memcmp(&got.dir, &ray.dir, sizeof ray.dir) != 0 ||
                   px[0] != colour_quantise(want.r) || px[1] != colour_quantise(want.g) ||
                   px[2] != colour_quantise(want.b);
        }
    CHECK_INT(0, bad); /* pixels that are not their ray traced */
    image_free(&img);
    scene_free(&sc);
}

static void render_pixels_are_their_camera_rays_traced(void)
{
    /* A square screen, and a sheared one far from the origin whose
     * corners' coordinates are not round (every sum rounds). */
    check_pixels_are_their_rays("0 0 -10\n-1 1 -9\n1 1 -9\n-1 -1 -9\n37\n10 20 30\n"
                                "10 10 -10 255 255 255\n"
                                "sphere: 0 0 0 1 200 100 50 0.5\n"
                                "sphere: 0.7 0.4 -1 0.3 50 200 100 0.2\n");
    check_pixels_are_their_rays("1e6 2e6 -3.1e6\n1000000.123 2000000.7 -3099999.1\n"
                                "1000002.9 2000000.3 -3099999.3\n1000000.7 1999998.1 -3099998.9\n"
                                "53\n0 0 0\n1e6 3e6 -3e6 255 255 255\n"
                                "sphere: 1000004 1999996 -3099990 3 200 100 50 0.5\n");
    /* Small spheres on a wide image: most tiles' rays are proven to miss
     * (render.c answers them untraced), some tiles' by a hair. */
    check_pixels_are_their_rays("0 0 -10\n-1 1 -9\n1 1 -9\n-1 -1 -9\n200\n10 20 30\n"
                                "10 10 -10 255 255 255\n"
                                "sphere: 0.5 0.5 0 0.2 200 100 50 0.5\n"
                                "sphere: -0.32 0 0.8 0.0001 50 200 100 0.2\n");
    check_pixels_are_their_rays("1e6 2e6 -3.1e6\n1000000.123 2000000.7 -3099999.1\n"
                                "1000002.9 2000000.3 -3099999.3\n1000000.7 1999998.1 -3099998.9\n"
                                "150\n0 0 0\n1e6 3e6 -3e6 255 255 255\n"
                                "sphere: 1000004 1999996 -3099990 0.5 200 100 50 0.5\n");
    /* Twenty small spheres and a triangle: a hierarchy, whose walk proves
     * most tiles clear. */
    check_pixels_are_their_rays("0 0 -10\n-1 1 -9\n1 1 -9\n-1 -1 -9\n300\n10 20 30\n"
                                "10 10 -10 255 255 255\n"
                                "sphere: -0.4228 -0.8380 1.1273 0.02 200 100 50 0.5\n"
                                "sphere: 0.7711 -0.9741 0.9570 0.05 200 100 50 0.5\n"
                                "sphere: -1.1100 -0.1593 -0.3254 0.02 200 100 50 0.5\n"
                                "sphere: 0.1225 -1.0581 0.9136 0.05 200 100 50 0.5\n"
                                "sphere: 0.3135 0.1992 -0.3453 0.1 200 100 50 0.5\n"
                                "sphere: -1.0810 -0.6694 0.8917 0.05 200 100 50 0.5\n"
                                "sphere: -0.5049 -0.8538 -0.2055 0.001 200 100 50 0.5\n"
                                "sphere: 0.1446 0.4368 -0.2424 0.05 200 100 50 0.5\n"
                                "sphere: -0.3062 0.1146 -0.3430 0.02 200 100 50 0.5\n"
                                "sphere: 0.2856 -0.0086 0.8293 0.001 200 100 50 0.5\n"
                                "sphere: -0.0826 1.0163 0.4040 0.05 200 100 50 0.5\n"
                                "sphere: 0.7065 0.4776 0.1102 0.001 200 100 50 0.5\n"
                                "sphere: 0.0605 0.9003 1.3236 0.001 200 100 50 0.5\n"
                                "sphere: 0.2615 -1.0243 0.7798 0.05 200 100 50 0.5\n"
                                "sphere: 0.6171 -0.8352 0.7224 0.02 200 100 50 0.5\n"
                                "sphere: 1.1088 -1.0137 0.8952 0.001 200 100 50 0.5\n"
                                "sphere: -0.3837 -0.3596 0.7417 0.1 200 100 50 0.5\n"
                                "sphere: -1.0350 -0.9754 0.1748 0.02 200 100 50 0.5\n"
                                "sphere: -1.0544 0.4836 1.1178 0.1 200 100 50 0.5\n"
                                "sphere: -0.5170 -0.2741 1.1716 0.02 200 100 50 0.5\n"
                                "triangle: 0.9 -0.9 0 1.0 -0.9 0 0.9 -0.8 0.5 50 200 100 0.3\n");
    /* Wider than two tiles and lower than one: every edge tile cut short. */
    check_pixels_are_their_rays("0 0 -10\n-3 0.1 -9\n3 0.1 -9\n-3 -0.1 -9\n70\n10 20 30\n"
                                "10 10 -10 255 255 255\n"
                                "sphere: 0 0 0 1 200 100 50 0.5\n");
}

static void render_bytes_do_not_depend_on_threads(void)
{
    Scene sc;
    Error err;
    Image a, b;
    RenderOptions one = {.max_depth = 10, .samples = 1, .threads = 1},
                  two = {.max_depth = 10, .samples = 1, .threads = 2},
                  many = {.max_depth = 10, .samples = 1, .threads = 7};

    CHECK_INT(0, load_scene_file("scenes/course.txt", SCENE_AUTO, 0, 0, &sc, NULL, &err));
    CHECK_INT(0, image_init(&a, sc.camera.width, sc.camera.height));
    CHECK_INT(0, image_init(&b, sc.camera.width, sc.camera.height));
    render(&sc, &one, &a, NULL);
    render(&sc, &two, &b, NULL);
    CHECK(memcmp(a.rgb, b.rgb, image_size(a.width, a.height)) == 0);
    render(&sc, &many, &b, NULL);
    CHECK(memcmp(a.rgb, b.rgb, image_size(a.width, a.height)) == 0);
    image_free(&a);
    image_free(&b);
    scene_free(&sc);
}

/* The base scene of the scale tests: one sphere lit from the side, so the
 * terminator (grazing light) crosses it, and half a mirror. */
static const double base_eye[3] = {0, 0, 0}, base_tl[3] = {-1, 1, 1}, base_tr[3] = {1, 1, 1},
                    base_bl[3] = {-1, -1, 1}, base_centre[3] = {0.3, 0.2, 4},
                    base_light[3] = {10, 3, 4};
static const double base_radius = 1.5, base_refl = 0.5;
static const Colour base_colour = {200, 150, 100}, base_bg = {20, 40, 60};
enum { BASE_W = 64 };

static Vec3 moved(const double p[3], double scale, double offset)
{
    return vec3(p[0] * scale + offset, p[1] * scale + offset, p[2] * scale + offset);
}

/* The exact image of the base scene, computed independently in long
 * double; sets *edge for pixels within 0.05% of the silhouette. */
static Colour base_expected(int i, int j, int *edge)
{
    long double fx = (i + 0.5L) / BASE_W, fy = (j + 0.5L) / BASE_W, d[3], f[3], h[3], l[3];
    long double len = 0, b = 0, c = 0, disc, t, cosa = 0, llen = 0;
    long double r = base_radius;

    for (int k = 0; k < 3; k++) {
        d[k] = base_tl[k] + fx * (base_tr[k] - base_tl[k]) + fy * (base_bl[k] - base_tl[k]) -
               base_eye[k];
        len += d[k] * d[k];
    }
    for (int k = 0; k < 3; k++) {
        d[k] /= sqrtl(len);
        f[k] = base_eye[k] - base_centre[k];
        b += f[k] * d[k];
        c += f[k] * f[k];
    }
    disc = b * b - (c - r * r);
    *edge = fabsl(disc) < 5e-4L * r * r;
    if (disc < 0)
        return base_bg;
    t = -b - sqrtl(disc);
    for (int k = 0; k < 3; k++) {
        h[k] = base_eye[k] + t * d[k];
        l[k] = base_light[k] - h[k];
        llen += l[k] * l[k];
    }
    for (int k = 0; k < 3; k++)
        cosa += (h[k] - base_centre[k]) / r * l[k] / sqrtl(llen);
    if (cosa < 0)
        cosa = 0;
    return colour((double)((1 - base_refl) * cosa * base_colour.r + base_refl * base_bg.r),
                  (double)((1 - base_refl) * cosa * base_colour.g + base_refl * base_bg.g),
                  (double)((1 - base_refl) * cosa * base_colour.b + base_refl * base_bg.b));
}

static void render_matches_exact_image_at_any_scale_and_place(void)
{
    static const double scales[] = {1e-4, 1, 1e6}, offsets[] = {0, 1e7, -3e6};

    for (size_t si = 0; si < 3; si++) {
        for (size_t oi = 0; oi < 3; oi++) {
            double s = scales[si], o = offsets[oi];
            Scene sc;
            Material m = material_plain(base_colour, base_refl);
            RenderOptions opts = {.max_depth = 10, .samples = 1, .threads = 2};
            Light light;
            Image img;
            int bad = 0, lit = 0;

            scene_init(&sc);
            sc.camera.eye = moved(base_eye, s, o);
            sc.camera.top_left = moved(base_tl, s, o);
            sc.camera.u = vec3_sub(moved(base_tr, s, o), sc.camera.top_left);
            sc.camera.v = vec3_sub(moved(base_bl, s, o), sc.camera.top_left);
            sc.camera.width = sc.camera.height = BASE_W;
            sc.background = base_bg;
            light = light_point(moved(base_light, s, o), colour(255, 255, 255));
            CHECK_INT(0, scene_add_light(&sc, &light));
            CHECK_INT(0, scene_add_sphere(&sc, moved(base_centre, s, o), base_radius * s, &m));
            CHECK_INT(0, image_init(&img, BASE_W, BASE_W));
            render(&sc, &opts, &img, NULL);
            for (int j = 0; j < BASE_W; j++) {
                for (int i = 0; i < BASE_W; i++) {
                    int edge;
                    Colour e = base_expected(i, j, &edge);
                    const unsigned char *p = img.rgb + 3 * (j * BASE_W + i);
                    lit += e.r > base_refl * base_bg.r + 1;
                    if (!edge && (abs(p[0] - colour_quantise(e.r)) > 1 ||
                                  abs(p[1] - colour_quantise(e.g)) > 1 ||
                                  abs(p[2] - colour_quantise(e.b)) > 1))
                        bad++;
                }
            }
            if (bad)
                test_fail(__FILE__, __LINE__, "scale %g, offset %g: %d pixels off by > 1", s, o,
                          bad);
            CHECK(lit > 300); /* the test looks at a lit sphere, not at nothing */
            image_free(&img);
            scene_free(&sc);
        }
    }
}

/* Writes the course scene with every length multiplied by factor, each
 * number printed with 17 significant digits (so it reads back exactly). */
static void course_scaled(char *buf, size_t size, double factor)
{
    static const double points[7][3] = {{100, 100, 0}, {90, 110, 30}, {110, 110, 30},
                                        {90, 90, 30},   {200, 300, 0}, {90, 90, 60},
                                        {100, 110, 60}};
    static const double last[3] = {110, 110, 60};
    const double *p[8];
    size_t n = 0;

    for (int i = 0; i < 7; i++)
        p[i] = points[i];
    p[7] = last;
    for (int i = 0; i < 4; i++)
        n += (size_t)snprintf(buf + n, size - n, "%.17g %.17g %.17g\n", p[i][0] * factor,
                              p[i][1] * factor, p[i][2] * factor);
    n += (size_t)snprintf(buf + n, size - n, "400\n80 80 100\n%.17g %.17g %.17g 245 200 200\n",
                          p[4][0] * factor, p[4][1] * factor, p[4][2] * factor);
    for (int i = 5; i < 8; i++)
        n += (size_t)snprintf(buf + n, size - n, "sphere: %.17g %.17g %.17g %.17g %s 0.3\n",
                              p[i][0] * factor, p[i][1] * factor, p[i][2] * factor, 7 * factor,
                              i == 5 ? "250 0 0" : i == 6 ? "0 250 0" : "0 0 250");
}

/* Renders the scene text into img (allocated here); returns the scene's
 * length_exponent, or -99999 (img left empty) if it does not parse. */
static int render_text(const char *text, Image *img)
{
    RenderOptions opts = {.max_depth = 10, .samples = 1, .threads = 2};
    Scene sc;
    Error err;
    int e;

    if (load_scene_text("t.txt", text, strlen(text), SCENE_COURSE, 0, 0, &sc, NULL, &err) != 0) {
        test_fail(__FILE__, __LINE__, "%d:%d: %s", err.line, err.column, err.message);
        img->rgb = NULL;
        return -99999;
    }
    e = sc.length_exponent;
    CHECK_INT(0, image_init(img, sc.camera.width, sc.camera.height));
    render(&sc, &opts, img, NULL);
    scene_free(&sc);
    return e;
}

/* Writes a course scene of three tori (thick, thin and mirrored) and a
 * disk over a floor sphere, every length times scale and every point
 * moved by offset. */
static void torus_scene(char *buf, size_t size, double scale, double offset)
{
    static const double pts[][3] = {{0, 1.5, -6}, {-1, 2.3, -5}, {1, 2.3, -5}, {-1, 0.7, -5},
                                    {-3, 6, -6},  {0, 0.2, 0},   {-1.9, 0.4, 1}, {1.9, 0.4, 1},
                                    {0, 1.2, 2},  {0, -100.5, 0}};
    double p[10][3];
    size_t n = 0;

    for (int i = 0; i < 10; i++)
        for (int a = 0; a < 3; a++)
            p[i][a] = pts[i][a] * scale + offset;
    for (int i = 0; i < 4; i++)
        n += (size_t)snprintf(buf + n, size - n, "%.17g %.17g %.17g\n", p[i][0], p[i][1], p[i][2]);
    n += (size_t)snprintf(buf + n, size - n, "96\n20 30 60\n%.17g %.17g %.17g 255 255 255\n",
                          p[4][0], p[4][1], p[4][2]);
    n += (size_t)snprintf(buf + n, size - n,
                          "torus: %.17g %.17g %.17g 0.2 1 -0.3 %.17g %.17g 220 60 40 0.2\n"
                          "torus: %.17g %.17g %.17g 1 0 0 %.17g %.17g 40 180 60 0\n"
                          "torus: %.17g %.17g %.17g 1 1 1 %.17g %.17g 200 200 200 0.5\n"
                          "disk: %.17g %.17g %.17g 0 0.3 -1 %.17g 90 90 200 0\n"
                          "sphere: %.17g %.17g %.17g %.17g 120 120 120 0\n",
                          p[5][0], p[5][1], p[5][2], 1.2 * scale, 0.4 * scale, p[6][0], p[6][1],
                          p[6][2], 0.8 * scale, 0.2 * scale, p[7][0], p[7][1], p[7][2],
                          0.8 * scale, 0.08 * scale, p[8][0], p[8][1], p[8][2], 0.9 * scale,
                          p[9][0], p[9][1], p[9][2], 100 * scale);
}

static void render_tori_alike_at_any_scale_and_place(void)
{
    /* The course's promise for spheres, kept by the torus's quartic and
     * the disk: the scene moved by 1e7, or scaled by 1e-4 or 1e6, is the
     * same picture (at most a level's rounding on a few channels). */
    static const double moves[][2] = {{1, 1e7}, {1e-4, 0}, {1e6, 0}, {1e6, -3e6}};
    char text[4000];
    Image ref, img;
    int lit = 0;

    torus_scene(text, sizeof text, 1, 0);
    if (render_text(text, &ref) == -99999)
        return;
    for (size_t i = 0; i < 3 * (size_t)ref.width * (size_t)ref.height; i++)
        lit += ref.rgb[i] > 100;
    CHECK(lit > 2000); /* the tori are in view, lit */
    for (size_t m = 0; m < sizeof moves / sizeof moves[0]; m++) {
        size_t off = 0, far = 0;
        torus_scene(text, sizeof text, moves[m][0], moves[m][1]);
        if (render_text(text, &img) == -99999)
            continue;
        for (size_t i = 0; i < 3 * (size_t)ref.width * (size_t)ref.height; i++) {
            int d = abs(img.rgb[i] - ref.rgb[i]);
            off += d > 0;
            far += d > 1;
        }
        if (far > 0 || off > 10)
            test_fail(__FILE__, __LINE__, "scale %g, offset %g: %zu channels off, %zu by > 1",
                      moves[m][0], moves[m][1], off, far);
        image_free(&img);
    }
    image_free(&ref);
}

static void render_tiny_scenes_exactly(void)
{
    /* A scene 2^-300 times the course's is the same picture to the byte:
     * it is enlarged by exactly 2^300 before rendering. One 1e-200 times
     * the course's (not a power of two) is within one level. Without the
     * enlargement, squares of its lengths underflow to zero. */
    char text[2000];
    Image ref, img;
    size_t size, close = 0;

    course_scaled(text, sizeof text, 1);
    CHECK_INT(0, render_text(text, &ref));
    course_scaled(text, sizeof text, 0x1p-300);
    CHECK_INT(291, render_text(text, &img)); /* 300 * 2^-300 lies in [2^-292, 2^-291) */
    size = image_size(ref.width, ref.height);
    CHECK(img.rgb && memcmp(ref.rgb, img.rgb, size) == 0);
    image_free(&img);
    course_scaled(text, sizeof text, 1e-200);
    CHECK(render_text(text, &img) > 600);
    for (size_t k = 0; img.rgb && k < size; k++)
        close += abs(ref.rgb[k] - img.rgb[k]) <= 1;
    CHECK_INT((long long)size, (long long)close);
    image_free(&img);
    image_free(&ref);
}

/* Renders the scene text with the given samples per pixel and threads into
 * img (allocated here); returns 0, or -1 (img left empty) if it does not
 * parse. */
static int render_text_with(const char *text, int samples, int threads, Image *img)
{
    RenderOptions opts = {.max_depth = 10, .samples = samples, .threads = threads};
    Scene sc;
    Error err;

    img->rgb = NULL;
    img->linear = NULL;
    img->encode = NULL;
    if (load_scene_text("t.txt", text, strlen(text), SCENE_COURSE, 0, 0, &sc, NULL, &err) != 0) {
        test_fail(__FILE__, __LINE__, "%d:%d: %s", err.line, err.column, err.message);
        return -1;
    }
    CHECK_INT(0, image_init(img, sc.camera.width, sc.camera.height));
    render(&sc, &opts, img, NULL);
    scene_free(&sc);
    return 0;
}

/* A scene with every optional record that changes rays: glass, a plane,
 * a triangle, a second light, ambient light, and a lens. */
#define RENDER_BUSY_SCENE                                                                     \
    "0 1 -6\n-2 2.5 -3\n2 2.5 -3\n-2 0 -3\n48\n30 40 60\n-4 6 -6 200 200 200\n"                \
    "light: 5 4 -3 120 120 160\nambient: 25 25 25\nplane: 0 0 0 0 1 0 200 200 200 0.2\n"      \
    "sphere: -1.2 1 2 1 255 80 80 0.1\nsphere: 1.2 1 1.5 1 255 255 255 0 0.9 1.5\n"           \
    "triangle: -3 0 5 3 0 5 0 3 5 80 200 80 0.3\n"

static void render_supersampled_bytes_do_not_depend_on_threads(void)
{
    Image a, b;

    CHECK_INT(0, render_text_with(RENDER_BUSY_SCENE "lens: 0.3 7\n", 9, 1, &a));
    CHECK_INT(0, render_text_with(RENDER_BUSY_SCENE "lens: 0.3 7\n", 9, 2, &b));
    CHECK(a.rgb && b.rgb && memcmp(a.rgb, b.rgb, image_size(a.width, a.height)) == 0);
    image_free(&b);
    CHECK_INT(0, render_text_with(RENDER_BUSY_SCENE "lens: 0.3 7\n", 9, 7, &b));
    CHECK(a.rgb && b.rgb && memcmp(a.rgb, b.rgb, image_size(a.width, a.height)) == 0);
    image_free(&b);
    /* More samples than one do change the picture. */
    CHECK_INT(0, render_text_with(RENDER_BUSY_SCENE, 1, 2, &b));
    CHECK(a.rgb && b.rgb && memcmp(a.rgb, b.rgb, image_size(a.width, a.height)) != 0);
    image_free(&a);
    image_free(&b);
}

static void render_one_sample_is_a_pinhole_render(void)
{
    Image a, b;

    CHECK_INT(0, render_text_with(RENDER_BUSY_SCENE, 1, 2, &a));
    CHECK_INT(0, render_text_with(RENDER_BUSY_SCENE "lens: 0.3 7\n", 1, 2, &b));
    CHECK(a.rgb && b.rgb && memcmp(a.rgb, b.rgb, image_size(a.width, a.height)) == 0);
    image_free(&a);
    image_free(&b);
}

static void render_samples_average_a_half_covered_pixel(void)
{
    /* A white triangle (ambient light only) whose edge projects onto the
     * vertical line through the centres of the left pixels of a 2 x 2
     * image. One sample on the edge sees the triangle; 64 samples, one in
     * each of 64 column strips, see it 32 times: 127.5, rounded to 128. */
    const char *text = "0 0 0\n-1 1 1\n1 1 1\n-1 -1 1\n2\n0 0 0\n0 0 -5 0 0 0\n"
                       "ambient: 255 255 255\n"
                       "triangle: -1 -100 2 -1 100 2 -100 0 2 255 255 255 0\n";
    Image img;

    CHECK_INT(0, render_text_with(text, 1, 1, &img));
    CHECK(img.rgb && img.rgb[0] == 255 && img.rgb[3] == 0);
    image_free(&img);
    CHECK_INT(0, render_text_with(text, 64, 1, &img));
    CHECK(img.rgb != NULL);
    if (img.rgb) {
        CHECK_INT(128, img.rgb[0]);
        CHECK_INT(128, img.rgb[3 * 2]); /* the pixel below */
        CHECK_INT(0, img.rgb[3]);
    }
    image_free(&img);
}

static void camera_lens_rays_meet_in_the_focal_plane(void)
{
    /* Whatever point of the lens a ray leaves from, it passes through the
     * point where the pinhole ray meets the plane in focus, and it starts
     * on the lens disk, in the plane through the eye parallel to the screen. */
    Camera cam = {{1, 2, 3}, {-1, 3, 5}, {4, 0, 0}, {0.5, -3, 0}, 40, 30, 0, 0, {0, 0, 0},
                  {0, 0, 0}, {0, 0, 0}};
    static const double lens[][2] = {{1, 0}, {-1, 0}, {0, 1}, {0, -1}, {0.3, -0.4}, {0, 0}};

    CHECK_INT(0, camera_set_lens(&cam, 0.5, 7));
    CHECK_NEAR(1, cam.forward.z, 1e-15);
    for (size_t i = 0; i < sizeof lens / sizeof lens[0]; i++) {
        Ray pin = camera_ray(&cam, 13.25, 7.5);
        Ray r = camera_lens_ray(&cam, 13.25, 7.5, lens[i]);
        Vec3 focal = vec3_add(cam.eye, vec3_scale(pin.dir, 7 / vec3_dot(pin.dir, cam.forward)));
        Vec3 off = vec3_sub(r.origin, cam.eye);
        double s = vec3_dot(vec3_sub(focal, r.origin), cam.forward) / vec3_dot(r.dir, cam.forward);

        CHECK_NEAR(0, vec3_dot(off, cam.forward), 1e-15);
        CHECK_NEAR(0.25 * hypot(lens[i][0], lens[i][1]), vec3_length(off), 1e-15);
        CHECK_NEAR(0, vec3_length(vec3_sub(ray_at(&r, s), focal)), 1e-14);
        CHECK_NEAR(1, vec3_length(r.dir), 1e-15);
    }
    /* The eye in the screen's plane: no forward, no lens. */
    cam.eye = vec3(0, 0, 5);
    CHECK_INT(-1, camera_set_lens(&cam, 0.5, 7));
}

/* Writes RENDER_BUSY_SCENE with a lens into buf, every length times
 * factor (a %s per length in the format below). */
static void busy_scaled(char *buf, size_t size, double factor)
{
    static const double len[] = {0,  1,   -6, -2, 2.5, -3, 2,   2.5, -3, -2, 0, -3, -4, 6,
                                 -6, 5,   4,  -3, 0,   0,  0,   -1.2, 1, 2,  1, 1.2, 1, 1.5,
                                 1,  -3,  0,  5,  3,   0,  5,   0,   3, 5,  0.3, 7};
    char s[40][32];

    for (int i = 0; i < 40; i++)
        snprintf(s[i], sizeof s[i], "%.17g", len[i] * factor);
    snprintf(buf, size,
             "%s %s %s\n%s %s %s\n%s %s %s\n%s %s %s\n48\n30 40 60\n%s %s %s 200 200 200\n"
             "light: %s %s %s 120 120 160\nambient: 25 25 25\n"
             "plane: %s %s %s 0 1 0 200 200 200 0.2\n"
             "sphere: %s %s %s %s 255 80 80 0.1\nsphere: %s %s %s %s 255 255 255 0 0.9 1.5\n"
             "triangle: %s %s %s %s %s %s %s %s %s 80 200 80 0.3\nlens: %s %s\n",
             s[0], s[1], s[2], s[3], s[4], s[5], s[6], s[7], s[8], s[9], s[10], s[11], s[12],
             s[13], s[14], s[15], s[16], s[17], s[18], s[19], s[20], s[21], s[22], s[23], s[24],
             s[25], s[26], s[27], s[28], s[29], s[30], s[31], s[32], s[33], s[34], s[35], s[36],
             s[37], s[38], s[39]);
}

static void render_tiny_scenes_with_every_shape_exactly(void)
{
    /* Planes, triangles, glass, a second light and a lens, scaled by
     * 2^-300 (enlarged back exactly) and by 2^40: the same bytes. */
    char text[2000];
    Image ref, img;
    size_t size;

    busy_scaled(text, sizeof text, 1);
    CHECK_INT(0, render_text_with(text, 4, 2, &ref));
    size = ref.rgb ? image_size(ref.width, ref.height) : 0;
    busy_scaled(text, sizeof text, 0x1p-300);
    CHECK_INT(0, render_text_with(text, 4, 2, &img));
    CHECK(img.rgb && size && memcmp(ref.rgb, img.rgb, size) == 0);
    image_free(&img);
    busy_scaled(text, sizeof text, 0x1p40);
    CHECK_INT(0, render_text_with(text, 4, 2, &img));
    CHECK(img.rgb && size && memcmp(ref.rgb, img.rgb, size) == 0);
    image_free(&img);
    image_free(&ref);
}

/* A scene of glass and mirror balls in a mirror box: long ray trees. */
static const char render_cut_course[] =
    "0 0 -9\n-1 1 -8\n1 1 -8\n-1 -1 -8\n16\n30 40 50\n4 6 -6 230 220 200\n"
    "light: -5 3 -4 60 80 120\nambient: 10 10 10\n"
    "sphere: 0 0 0 1.5 255 255 255 0.1 0.85 1.5\nsphere: 2 1 1 1 200 60 60 0.6\n"
    "sphere: -2 -1 1 1 60 200 60 0.3 0.6 1.33\nsphere: 0 -102 0 100 200 200 200 0.5\n"
    "plane: 0 0 6 0 0 -1 180 180 255 0.9\n";

static const char render_cut_keyword[] =
    "camera 0 1 -9 0 0 0 1 16 16\nbackground 30 40 50\n"
    "material glass 255 255 255 0 0 0.9 300 0.05 1.5\n"
    "material mirror 240 240 240 0.1 0.2 0.8 100 0.85\n"
    "material red 220 50 40 0.4 0.8 0.6 20 0.2\n"
    "light -1 -2 1 255 250 240 1\nlight 2 -1 0.5 100 120 200 0.6\n"
    "sphere 0 0 0 1.5 glass\nsphere 2 1 1 1 mirror\nsphere -2 -1 1 1 red\n"
    "plane 0 -1.5 0 0 1 0 mirror\nplane 0 0 6 0 0 -1 red\n";

/* The colour a cut-off leaves out of a ray is at least 0 and at most what
 * it adds up in skipped (to within rounding): the bound render.c relies on
 * to keep the bytes exact; tracing the rays it kept, without a cut-off,
 * gives back the uncut colour (to within rounding). Many rays, an
 * aggressive cut-off, both rules; mirror, refracted and shadow rays are
 * left out. */
static void render_cutoff_leaves_out_no_more_than_it_counts(void)
{
    const char *texts[] = {render_cut_course, render_cut_keyword};
    int bad = 0, cuts = 0, lost = 0;
    RayCounts all = {0}, left = {0}, later = {0};

    for (int s = 0; s < 2; s++) {
        Scene sc;
        Error err;

        CHECK_INT(0, load_scene_text("t.txt", texts[s], strlen(texts[s]), SCENE_AUTO, 0, 0, &sc,
                                     NULL, &err));
        for (int i = 0; i < 4000; i++) {
            Ray ray = {vec3(rng_range(-3, 3), rng_range(-1, 3), -8),
                       vec3_normalize(vec3(rng_range(-0.5, 0.5), rng_range(-0.5, 0.5), 1))};
            Cut cut;
            Tracer every = model_tracer(&sc, 30, &all), cutting = model_tracer(&sc, 30, &left);
            Tracer again = model_tracer(&sc, 30, &later);
            Colour full = trace_ray(&every, &ray), part;
            double eta;

            cutting.cut = again.cut = &cut;
            cut_init(&cut, &sc, i % 2 ? 5 : 0.05);
            part = trace_ray(&cutting, &ray);
            eta = 1e-9 * cut_bound(&cut, 30);
            cuts += cut.deferred_count > 0;
            bad += !(full.r - part.r >= -eta && full.r - part.r <= cut.skipped + eta);
            bad += !(full.g - part.g >= -eta && full.g - part.g <= cut.skipped + eta);
            bad += !(full.b - part.b >= -eta && full.b - part.b <= cut.skipped + eta);
            cut.cutoff = 0; /* the kept rays, traced in full */
            for (size_t k = 0, kept = cut.deferred_count; k < kept; k++)
                part = colour_add(part, trace_deferred(&again, cut.deferred[k]));
            lost += !(fabs(full.r - part.r) <= eta && fabs(full.g - part.g) <= eta &&
                      fabs(full.b - part.b) <= eta);
            cut_free(&cut);
        }
        scene_free(&sc);
    }
    CHECK_INT(0, bad);
    CHECK_INT(0, lost);
    if (cuts < 1000) /* the cut-off must have left rays out */
        test_fail(__FILE__, __LINE__, "only %d rays of 8000 had rays left out", cuts);
    CHECK(left.reflection < all.reflection && left.refraction < all.refraction);
    /* Every ray is cast once, then or later. */
    CHECK(left.shadow + later.shadow == all.shadow &&
          left.reflection + later.reflection == all.reflection &&
          left.refraction + later.refraction == all.refraction);
}

/* A shadow ray is left out when the light it tests could add less than the
 * cut-off: on a dark ball (4 4 4, no mirror) lit by a white light, no ray
 * can add 5 levels, so a cut-off of 5 casts none, and the colour lacks no
 * more than it counts. */
static void render_cutoff_leaves_out_shadow_rays(void)
{
    static const char text[] = "0 0 -5\n-1 1 -4\n1 1 -4\n-1 -1 -4\n8\n0 0 0\n"
                               "5 5 -5 255 255 255\nsphere: 0 0 0 1 4 4 4 0\n";
    Scene sc;
    Error err;
    RayCounts all = {0}, left = {0};
    int bad = 0;

    CHECK_INT(0, load_scene_text("t.txt", text, strlen(text), SCENE_AUTO, 0, 0, &sc, NULL, &err));
    for (int i = 0; i < 100; i++) {
        Ray ray = {vec3(0, 0, -5),
                   vec3_normalize(vec3(rng_range(-0.2, 0.2), rng_range(-0.2, 0.2), 1))};
        Cut cut;
        Tracer every = model_tracer(&sc, 10, &all), cutting = model_tracer(&sc, 10, &left);
        Colour full = trace_ray(&every, &ray), part;

        cutting.cut = &cut;
        cut_init(&cut, &sc, 5);
        part = trace_ray(&cutting, &ray);
        bad += !(full.r - part.r >= 0 && full.r - part.r <= cut.skipped);
        cut_free(&cut);
    }
    scene_free(&sc);
    CHECK_INT(0, bad);
    CHECK(all.shadow > 50);
    CHECK(left.shadow == 0);
}

/* Renders text with max_depth and cutoff; returns the image (free it). */
static Image render_with_cutoff(const char *text, int max_depth, double cutoff,
                                RayCounts *counts)
{
    Scene sc;
    Error err;
    Image img;
    RenderOptions opts = {.max_depth = max_depth, .samples = 4, .cutoff = cutoff, .threads = 2};

    CHECK_INT(0, load_scene_text("t.txt", text, strlen(text), SCENE_AUTO, 0, 0, &sc, NULL, &err));
    CHECK_INT(0, image_init(&img, sc.camera.width, sc.camera.height));
    render(&sc, &opts, &img, counts);
    scene_free(&sc);
    return img;
}

/* Whatever the cut-off, the bytes are those of the render without it; a
 * large one makes pixels be refined, a small one leaves rays out. */
static void render_cutoff_keeps_every_byte(void)
{
    const char *texts[] = {render_cut_course, render_cut_keyword};
    static const double cutoffs[] = {1e-6, 1e-3, 0.5, 50};
    unsigned long long cut = 0, refined = 0;

    for (int s = 0; s < 2; s++) {
        RayCounts none = {0};
        Image exact = render_with_cutoff(texts[s], 25, 0, &none);

        CHECK(none.cut == 0 && none.refined == 0);
        for (int k = 0; k < 4; k++) {
            RayCounts c = {0};
            Image img = render_with_cutoff(texts[s], 25, cutoffs[k], &c);
            CHECK(memcmp(exact.rgb, img.rgb, image_size(img.width, img.height)) == 0);
            cut += c.cut;
            refined += c.refined;
            image_free(&img);
        }
        image_free(&exact);
    }
    CHECK(cut > 0);
    CHECK(refined > 0);
}

/* Returns every ray counts holds. */
static unsigned long long render_rays(const RayCounts *c)
{
    return c->primary + c->shadow + c->reflection + c->refraction;
}

/* In a pixel the cut-off cannot prove, the rays it left out are traced with
 * smaller cut-offs before the pixel is traced in full: even a cut-off of 50
 * levels, which proves few pixels at first, casts far fewer rays than the
 * uncut render of these long ray trees. */
static void render_cutoff_refines_before_tracing_in_full(void)
{
    const char *texts[] = {render_cut_course, render_cut_keyword};

    for (int s = 0; s < 2; s++) {
        RayCounts none = {0}, big = {0};
        Image exact = render_with_cutoff(texts[s], 25, 0, &none);
        Image img = render_with_cutoff(texts[s], 25, 50, &big);

        CHECK(memcmp(exact.rgb, img.rgb, image_size(img.width, img.height)) == 0);
        CHECK(big.refined > 0);
        if (render_rays(&big) * 2 > render_rays(&none))
            test_fail(__FILE__, __LINE__, "scene %d: %llu rays with a cut-off of 50, %llu without",
                      s, render_rays(&big), render_rays(&none));
        image_free(&img);
        image_free(&exact);
    }
}

/* Renders sc under noise with `threads` threads, rows row_first + k
 * row_step (row_step 0: all) into img (allocated here), recording each
 * pixel's samples and error. */
static void render_noisy(const Scene *sc, NoiseOptions noise, Indirect in, int threads,
                         int row_first, int row_step, Image *img, unsigned *spp, float *error)
{
    RenderOptions opts = {.max_depth = 10, .samples = 1, .cutoff = 0.1, .threads = threads,
                          .indirect = in, .row_first = row_first, .row_step = row_step,
                          .noise = noise, .spp = spp, .error = error};
    int rows = row_step ? (sc->camera.height - row_first + row_step - 1) / row_step
                        : sc->camera.height;

    CHECK_INT(0, image_init(img, sc->camera.width, rows));
    render(sc, &opts, img, NULL);
}

static void render_noise_is_each_pixels_own(void)
{
    static const char *const scenes[] = {"scenes/focus.txt", "scenes/indirect.txt"};
    NoiseOptions noise = {3, 16, 256};

    for (size_t s = 0; s < sizeof scenes / sizeof scenes[0]; s++) {
        Indirect in = {s == 1 ? 2 : 0, 0.5, s == 1 ? 2 : 0, 1, 0, 0};
        unsigned spp[3][40 * 30];
        float error[3][40 * 30];
        Image img[3], tile;
        Scene sc;
        Error err;

        CHECK_INT(0, load_scene_file(scenes[s], SCENE_AUTO, 0, 0, &sc, NULL, &err));
        camera_resize(&sc.camera, 40, 30);
        render_noisy(&sc, noise, in, 1, 0, 0, &img[0], spp[0], error[0]);
        render_noisy(&sc, noise, in, 2, 0, 0, &img[1], spp[1], error[1]);
        render_noisy(&sc, noise, in, 7, 0, 0, &img[2], spp[2], error[2]);
        for (int k = 1; k < 3; k++) {
            CHECK(memcmp(img[0].rgb, img[k].rgb, image_size(40, 30)) == 0);
            CHECK(memcmp(spp[0], spp[k], sizeof spp[0]) == 0);
            CHECK(memcmp(error[0], error[k], sizeof error[0]) == 0);
        }
        /* A tile (every third row from row 1) has the same rows. */
        render_noisy(&sc, noise, in, 2, 1, 3, &tile, spp[1], error[1]);
        for (int y = 0; y < tile.height; y++)
            CHECK(memcmp(tile.rgb + 3 * 40 * y, img[0].rgb + 3 * 40 * (1 + 3 * y), 3 * 40) == 0);
        /* Every pixel took a power of two from 16 to 256 samples, and
         * stopped within the level unless it took the most. */
        for (int i = 0; i < 40 * 30; i++) {
            unsigned n = spp[0][i];
            if (n < 16 || n > 256 || (n & (n - 1)) != 0 || (error[0][i] > 3 && n != 256))
                test_fail(__FILE__, __LINE__, "%s pixel %d: %u samples, error %g", scenes[s], i,
                          n, error[0][i]);
        }
        image_free(&tile);
        for (int k = 0; k < 3; k++)
            image_free(&img[k]);
        scene_free(&sc);
    }
}

static void render_noise_spends_samples_where_the_pixel_varies(void)
{
    /* Half the picture a flat wall, half a sphere's edge: the wall's
     * pixels are exact at the first round, the edge's need more. */
    const char *text = "0 0 -1\n-1 1 0\n1 1 0\n-1 -1 0\n16\n0 0 0\n0 0 -10 255 255 255\n"
                       "sphere: 0 0 5 1.3 200 100 50 0\n";
    NoiseOptions noise = {0.5, 16, 1024};
    Indirect none = {0, 0, 0, 0, 0, 0};
    unsigned spp[16 * 16];
    float error[16 * 16];
    int flat = 0, more = 0;
    Image img;
    Scene sc;
    Error err;

    CHECK_INT(0, load_scene_text("t.txt", text, strlen(text), SCENE_COURSE, 0, 0, &sc, NULL, &err));
    render_noisy(&sc, noise, none, 2, 0, 0, &img, spp, error);
    for (int i = 0; i < 16 * 16; i++) {
        const unsigned char *p = img.rgb + 3 * i;
        int inside = p[0] > 0, edge = error[i] > 0;
        flat += !edge && spp[i] == 16;
        more += edge && spp[i] > 16;
        /* A pixel the whole sphere covers, or none of it, is flat. */
        if (!inside && (spp[i] != 16 || error[i] != 0))
            test_fail(__FILE__, __LINE__, "background pixel %d: %u samples, error %g", i, spp[i],
                      error[i]);
    }
    CHECK(flat > 100);
    CHECK(more > 10);
    image_free(&img);
    scene_free(&sc);
}

const TestCase render_tests[] = {
    {"render_noise_is_each_pixels_own", render_noise_is_each_pixels_own},
    {"render_noise_spends_samples_where_the_pixel_varies",
     render_noise_spends_samples_where_the_pixel_varies},
    {"render_cutoff_leaves_out_no_more_than_it_counts",
     render_cutoff_leaves_out_no_more_than_it_counts},
    {"render_cutoff_leaves_out_shadow_rays", render_cutoff_leaves_out_shadow_rays},
    {"render_cutoff_keeps_every_byte", render_cutoff_keeps_every_byte},
    {"render_cutoff_refines_before_tracing_in_full", render_cutoff_refines_before_tracing_in_full},
    {"render_tiny_scenes_exactly", render_tiny_scenes_exactly},
    {"render_tori_alike_at_any_scale_and_place", render_tori_alike_at_any_scale_and_place},
    {"render_pixel_centres_map_to_the_screen", render_pixel_centres_map_to_the_screen},
    {"render_sheared_screen", render_sheared_screen},
    {"render_eye_on_the_screen_sees_background", render_eye_on_the_screen_sees_background},
    {"render_bytes_do_not_depend_on_threads", render_bytes_do_not_depend_on_threads},
    {"render_supersampled_bytes_do_not_depend_on_threads",
     render_supersampled_bytes_do_not_depend_on_threads},
    {"render_one_sample_is_a_pinhole_render", render_one_sample_is_a_pinhole_render},
    {"render_samples_average_a_half_covered_pixel", render_samples_average_a_half_covered_pixel},
    {"camera_lens_rays_meet_in_the_focal_plane", camera_lens_rays_meet_in_the_focal_plane},
    {"render_pixels_are_their_camera_rays_traced", render_pixels_are_their_camera_rays_traced},
    {"render_tiny_scenes_with_every_shape_exactly", render_tiny_scenes_with_every_shape_exactly},
    {"render_matches_exact_image_at_any_scale_and_place",
     render_matches_exact_image_at_any_scale_and_place},
    {NULL, NULL},
};
