/* test_render.c: primary rays, thread independence, and renders that must
 * not change when the scene is scaled or moved far away. */
#include <math.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>

#include "camera.h"
#include "parse.h"
#include "render.h"
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

static void render_bytes_do_not_depend_on_threads(void)
{
    Scene sc;
    Error err;
    Image a, b;
    RenderOptions one = {10, 1, 1}, two = {10, 1, 2}, many = {10, 1, 7};

    CHECK_INT(0, parse_scene_file("scenes/course.txt", &sc, &err));
    CHECK_INT(0, image_init(&a, sc.camera.width, sc.camera.height));
    CHECK_INT(0, image_init(&b, sc.camera.width, sc.camera.height));
    render(&sc, &one, &a);
    render(&sc, &two, &b);
    CHECK(memcmp(a.rgb, b.rgb, image_size(a.width, a.height)) == 0);
    render(&sc, &many, &b);
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
            Sphere sp = {moved(base_centre, s, o), base_radius * s,
                         material_plain(base_colour, base_refl), 0};
            RenderOptions opts = {10, 1, 2};
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
            light.position = moved(base_light, s, o);
            light.colour = colour(255, 255, 255);
            CHECK_INT(0, scene_add_light(&sc, &light));
            CHECK_INT(0, scene_add_sphere(&sc, &sp));
            CHECK_INT(0, image_init(&img, BASE_W, BASE_W));
            render(&sc, &opts, &img);
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
    RenderOptions opts = {10, 1, 2};
    Scene sc;
    Error err;
    int e;

    if (parse_scene_text("t.txt", text, strlen(text), &sc, &err) != 0) {
        test_fail(__FILE__, __LINE__, "%d:%d: %s", err.line, err.column, err.message);
        img->rgb = NULL;
        return -99999;
    }
    e = sc.length_exponent;
    CHECK_INT(0, image_init(img, sc.camera.width, sc.camera.height));
    render(&sc, &opts, img);
    scene_free(&sc);
    return e;
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

const TestCase render_tests[] = {
    {"render_tiny_scenes_exactly", render_tiny_scenes_exactly},
    {"render_pixel_centres_map_to_the_screen", render_pixel_centres_map_to_the_screen},
    {"render_sheared_screen", render_sheared_screen},
    {"render_eye_on_the_screen_sees_background", render_eye_on_the_screen_sees_background},
    {"render_bytes_do_not_depend_on_threads", render_bytes_do_not_depend_on_threads},
    {"render_matches_exact_image_at_any_scale_and_place",
     render_matches_exact_image_at_any_scale_and_place},
    {NULL, NULL},
};
