/* test_keyword.c: the keyword format of the OCaml course project: reading, the look-at camera,
 * Blinn-Phong shading with distant lights, format detection and saving. */
#include <math.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>

#include "math/number.h"
#include "render/model.h"
#include "render/trace.h"
#include "rng.h"
#include "scene/camera.h"
#include "scenefile/keyword.h"
#include "scenefile/load.h"
#include "scenefile/save.h"
#include "scenefile/shapes.h"
#include "shading.h"
#include "test.h"

#define OCAML_TEST                                                                                  \
    "camera 0. 0. 0. 0. 0. 5. 2.0943951 700 500\n"                                             \
    "material sphereMat 255 0 0 1. 0.6 0.7 10.\n"                                              \
    "sphere 1. 1. 5. 0.4 sphereMat\n"                                                          \
    "light -10. -30. 20. 255 255 255 0.1\n"

/* Reads text as a keyword scene named t.txt; returns what the reader does. */
static int kw(const char *text, Scene *sc, Error *err)
{
    return load_scene_text("t.txt", text, strlen(text), SCENE_KEYWORD, 0, 0, sc, NULL, err);
}

/* Same as kw(), keeping what --save writes back in *src. */
static int kw_source(const char *text, Scene *sc, SceneSource *src, Error *err)
{
    return load_scene_text("t.txt", text, strlen(text), SCENE_KEYWORD, 0, 0, sc, src, err);
}

static void keyword_reads_the_ocaml_test_scene(void)
{
    Scene sc;
    SceneSource src;
    Error err;
    Vec3 d = vec3_normalize(vec3(-10, -30, 20));

    CHECK_INT(0, kw_source(OCAML_TEST, &sc, &src, &err));
    CHECK_INT(SCENE_KEYWORD, sc.format);
    CHECK_INT(700, sc.camera.width);
    CHECK_INT(500, sc.camera.height);
    CHECK_NEAR(2.0943951, src.fov, 0);
    source_free(&src);
    CHECK_INT(1, (long long)sc.named_count);
    CHECK(strcmp(sc.named[0].name, "sphereMat") == 0);
    CHECK_NEAR(1, sc.named[0].ka, 0);
    CHECK_NEAR(0.6, sc.named[0].kd, 0);
    CHECK_NEAR(0.7, sc.named[0].ks, 0);
    CHECK_NEAR(10, sc.named[0].shininess, 0);
    CHECK_INT(1, (long long)scene_count_of(&sc, SHAPE_SPHERE));
    CHECK_INT(0, scene_material(&sc, SHAPE_SPHERE, 0).named);
    CHECK_NEAR(255, scene_material(&sc, SHAPE_SPHERE, 0).colour.r, 0);
    CHECK_NEAR(0, scene_material(&sc, SHAPE_SPHERE, 0).reflection, 0);
    CHECK_NEAR(0.4, scene_spheres(&sc)[0].radius, 0);
    CHECK_INT(1, (long long)sc.light_count);
    CHECK_INT(1, sc.lights[0].distant);
    CHECK_NEAR(0.1, sc.lights[0].intensity, 0);
    CHECK_NEAR(-d.x, sc.lights[0].to_light.x, 1e-16);
    CHECK_NEAR(-d.y, sc.lights[0].to_light.y, 1e-16);
    CHECK_NEAR(-d.z, sc.lights[0].to_light.z, 1e-16);
    /* No ambient line: the light's i Cs lights the scene indirectly. */
    CHECK_INT(0, sc.has_ambient);
    CHECK_NEAR(25.5, sc.ambient.r, 1e-12);
    CHECK_NEAR(0, sc.background.r + sc.background.g + sc.background.b, 0);
    scene_free(&sc);
}

static void keyword_reads_every_element_in_any_order(void)
{
    Scene sc;
    Error err;

    CHECK_INT(0, kw("# comments, blanks, tabs\n\nmaterial a 1 2 3 0 1 0 0\n"
                    "light 0 -1 0 10 20 30 2\r\n\tlight 0 0 1 1 1 1 0 # another\n"
                    "sphere 0 0 9 1 a\nplane 0 -1 0 0 2 0 a\n"
                    "material glass 255 255 255 0 0 1 100 0.1 1.5\n"
                    "triangle 0 0 5 1 0 5 0 1 5 glass\n"
                    "material half 255 255 255 0 0 1 100 0.2 1.3 0.5\n"
                    "sphere 2 0 9 1 half\n"
                    "camera 0 0 0 0 0 1 1 64 48\nbackground 1 2 3\nambient 4 5 6",
                    &sc, &err));
    CHECK_INT(2, (long long)scene_count_of(&sc, SHAPE_SPHERE));
    CHECK_INT(1, (long long)scene_count_of(&sc, SHAPE_PLANE));
    CHECK_INT(1, (long long)scene_count_of(&sc, SHAPE_TRIANGLE));
    CHECK_INT(2, (long long)sc.light_count);
    CHECK_NEAR(2, sc.lights[0].intensity, 0);
    CHECK_NEAR(3, sc.background.b, 0);
    CHECK_NEAR(6, sc.ambient.b, 0);
    CHECK_INT(1, sc.has_ambient);
    /* Objects keep the file's order across kinds. */
    CHECK_INT(0, scene_spheres(&sc)[0].order);
    CHECK_INT(1, scene_planes(&sc)[0].order);
    CHECK_INT(2, scene_triangles(&sc)[0].order);
    CHECK_INT(3, scene_spheres(&sc)[1].order);
    /* eta_r without tau: all the light not mirrored is transmitted. */
    CHECK_NEAR(0.9, scene_material_of(&sc, &scene_triangles(&sc)[0])->transparency, 1e-16);
    CHECK_NEAR(1.5, scene_material_of(&sc, &scene_triangles(&sc)[0])->ior, 0);
    CHECK_NEAR(0.5, scene_material(&sc, SHAPE_SPHERE, 1).transparency, 0);
    CHECK_NEAR(0.2, scene_material(&sc, SHAPE_SPHERE, 1).reflection, 0);
    CHECK(sc.has_transparency);
    scene_free(&sc);
}

/* The direction of the primary ray through image position (x, y). */
static Vec3 ray_through(const Camera *cam, double x, double y)
{
    return camera_ray(cam, x, y).dir;
}

static void keyword_camera_looks_at_its_target(void)
{
    static const double scales[] = {1e-12, 1, 1e9};
    Camera cam;

    for (int i = 0; i < 3; i++) {
        double s = scales[i];
        Vec3 from = vec3(3 * s, 2 * s, -5 * s), at = vec3(-1 * s, 0.5 * s, 4 * s);
        Vec3 f = vec3_normalize(vec3_sub(at, from)), left, top, corner;
        double fov = 1.2;

        CHECK_INT(CAMERA_VIEW_OK, camera_look_at(&cam, from, at, fov, 400, 300));
        /* The image centre looks at the target. */
        CHECK_NEAR(1, vec3_dot(ray_through(&cam, 200, 150), f), 1e-15);
        /* The middle of the left edge is fov / 2 away, horizontally. */
        left = ray_through(&cam, 0, 150);
        CHECK_NEAR(cos(fov / 2), vec3_dot(left, f), 1e-15);
        /* ... and in the plane of forward and right: square to the image's up. */
        {
            Vec3 right = vec3_normalize(vec3_cross(vec3(0, 1, 0), f));
            CHECK_NEAR(0, vec3_dot(left, vec3_cross(f, right)), 1e-15);
        }
        /* The top edge's middle: tan of the vertical half-angle is 3 / 4
         * of the horizontal one (square pixels). */
        top = ray_through(&cam, 200, 0);
        CHECK_NEAR(0.75 * tan(fov / 2), tan(acos(vec3_dot(top, f))), 1e-14);
        CHECK(top.y > ray_through(&cam, 200, 300).y); /* +y is up */
        corner = ray_through(&cam, 400, 150);
        CHECK(vec3_dot(vec3_cross(vec3(0, 1, 0), f), corner) > 0); /* right is up x forward */
    }
    /* Looking along +z, +x is on the right and +y at the top. */
    CHECK_INT(CAMERA_VIEW_OK, camera_look_at(&cam, vec3(0, 0, 0), vec3(0, 0, 1), 1, 10, 10));
    CHECK(ray_through(&cam, 10, 5).x > 0);
    CHECK(ray_through(&cam, 5, 0).y > 0);
    /* Straight down: +z is at the top of the image, +x on the right. */
    CHECK_INT(CAMERA_VIEW_OK, camera_look_at(&cam, vec3(0, 9, 0), vec3(0, 0, 0), 1, 10, 10));
    CHECK(ray_through(&cam, 5, 0).z > 0);
    CHECK(ray_through(&cam, 10, 5).x > 0);
    /* Straight up: -z at the top. */
    CHECK_INT(CAMERA_VIEW_OK, camera_look_at(&cam, vec3(0, 0, 0), vec3(0, 9, 0), 1, 10, 10));
    CHECK(ray_through(&cam, 5, 0).z < 0);
    CHECK_INT(CAMERA_VIEW_NO_DIRECTION,
              camera_look_at(&cam, vec3(1, 2, 3), vec3(1, 2, 3), 1, 10, 10));
    CHECK_INT(CAMERA_VIEW_TOO_NARROW,
              camera_look_at(&cam, vec3(0, 0, 0), vec3(0, 0, 1e-300), 1e-300, 10, 10));
}

/* The colour seen along the ray from o towards d. */
static Colour seen(const Scene *sc, Vec3 o, Vec3 d, int depth)
{
    Ray r = {o, vec3_normalize(d)};
    RayCounts counts = {0};

    Tracer t = model_tracer(sc, depth, &counts);

    return trace_ray(&t, &r);
}

static void keyword_blinn_phong_has_its_three_terms(void)
{
    /* A light of intensity 0.8 travels along (0, -1, 1) / sqrt 2; the eye
     * looks along +z at a ball of radius 1 at z = 5. */
    Scene sc;
    Error err;
    const double ka = 0.3, kd = 0.6, ks = 0.5, alpha = 7, i = 0.8;
    Vec3 l = vec3_normalize(vec3(0, 1, -1));

    CHECK_INT(0, kw("camera 0 0 0 0 0 5 1 10 10\nambient 20 40 60\n"
                    "material m 200 100 50 0.3 0.6 0.5 7\n"
                    "light 0 -1 1 250 200 150 0.8\nsphere 0 0 5 1 m\n",
                    &sc, &err));
    /* Head on: N = V = (0, 0, -1); N . L = 1 / sqrt 2; H halfway between
     * V and L. */
    {
        Vec3 n = vec3(0, 0, -1), v = vec3(0, 0, -1), h = vec3_normalize(vec3_add(l, v));
        double nl = vec3_dot(n, l), spec = ks * pow(vec3_dot(n, h), alpha);
        Colour c = seen(&sc, vec3(0, 0, 0), vec3(0, 0, 1), 0);
        CHECK_NEAR(ka * 20 * 200 / 255 + i * (kd * nl * 200 * 250 / 255 + spec * 250), c.r,
                   1e-12);
        CHECK_NEAR(ka * 40 * 100 / 255 + i * (kd * nl * 100 * 200 / 255 + spec * 200), c.g,
                   1e-12);
        CHECK_NEAR(ka * 60 * 50 / 255 + i * (kd * nl * 50 * 150 / 255 + spec * 150), c.b,
                   1e-12);
    }
    /* Where N = H, the highlight peaks: a point on the ball facing the
     * halfway vector of L and the direction back to the eye. */
    {
        Vec3 p = vec3(0, 0.4, 5), d, n, v, h;
        int k;
        /* Find the point whose normal is the halfway vector by iteration. */
        for (k = 0; k < 60; k++) {
            v = vec3_normalize(vec3_neg(p));
            h = vec3_normalize(vec3_add(l, v));
            p = vec3_add(vec3(0, 0, 5), h);
        }
        d = vec3_normalize(p);
        n = h;
        {
            Colour c = seen(&sc, vec3(0, 0, 0), d, 0);
            double nl = vec3_dot(n, l);
            CHECK_NEAR(ka * 20 * 200 / 255 + i * (kd * nl * 200 * 250 / 255 + ks * 250), c.r,
                       1e-9);
        }
    }
    /* The dark side: only the ambient term. */
    CHECK_NEAR(ka * 20 * 200 / 255, seen(&sc, vec3(0, 0, 0), vec3(0, -0.19, 1), 0).r, 1e-12);
    scene_free(&sc);
}

static void keyword_distant_light_shadows_from_any_distance(void)
{
    /* A white floor lit straight down; a ball 10^6 above it (far beyond any
     * point light's segment) still shades the point below it. */
    Scene sc;
    Error err;

    CHECK_INT(0, kw("camera 0 5 -5 0 0 0 1 10 10\nambient 0 0 0\n"
                    "material white 255 255 255 0.5 1 0 1\n"
                    "light 0 -1 0 255 255 255 1\nplane 0 0 0 0 1 0 white\n"
                    "sphere 0 1000000 0 1 white\n",
                    &sc, &err));
    CHECK_NEAR(0, seen(&sc, vec3(0, 5, -5), vec3(0, -5, 5), 0).r, 0);
    CHECK_NEAR(255, seen(&sc, vec3(0, 5, -5), vec3(1.5, -5, 5), 0).r, 1e-12);
    scene_free(&sc);
    /* Through glass: tau of the light passes each crossing. */
    CHECK_INT(0, kw("camera 0 5 -5 0 0 0 1 10 10\nambient 0 0 0\n"
                    "material white 255 255 255 0.5 1 0 1\n"
                    "material glass 255 255 255 0 0 0 1 0 1 0.5\n"
                    "light 0 -1 0 255 255 255 1\nplane 0 0 0 0 1 0 white\n"
                    "sphere 0 3 0 1 glass\n",
                    &sc, &err));
    CHECK_NEAR(255 * 0.25, seen(&sc, vec3(0, 5, -5), vec3(0, -5, 5), 0).r, 1e-12);
    scene_free(&sc);
}

static void keyword_mirror_adds_to_the_local_term(void)
{
    /* Whitted's sum: the local term is not scaled by 1 - rho_r. A mirror
     * ball facing a light grey background. */
    Scene sc;
    Error err;

    CHECK_INT(0, kw("camera 0 0 0 0 0 5 1 10 10\nbackground 100 100 100\nambient 50 50 50\n"
                    "material m 255 0 0 1 0 0 1 0.4\nsphere 0 0 5 1 m\n",
                    &sc, &err));
    CHECK_NEAR(50 + 0.4 * 100, seen(&sc, vec3(0, 0, 0), vec3(0, 0, 1), 1).r, 1e-12);
    CHECK_NEAR(0.4 * 100, seen(&sc, vec3(0, 0, 0), vec3(0, 0, 1), 1).g, 1e-12);
    CHECK_NEAR(50, seen(&sc, vec3(0, 0, 0), vec3(0, 0, 1), 0).r, 1e-12);
    scene_free(&sc);
}

/* One malformed keyword scene and the error it must produce. */
typedef struct {
    const char *text;
    int line, column;
    const char *message;
} BadKeyword;

#define CAM "camera 0 0 0 0 0 5 1 70 50\n"
#define MAT "material m 255 0 0 1 1 1 1\n"

static const BadKeyword keyword_bad[] = {
    {"", 1, 1,
     "expected a camera line (camera x0 y0 z0 xA yA zA alpha width height), found the end of "
     "the file"},
    {MAT, 2, 1,
     "expected a camera line (camera x0 y0 z0 xA yA zA alpha width height), found the end of "
     "the file"},
    {"camera 0 0 0 0 0 5 1 70", 1, 24,
     "expected 9 numbers for the camera (x0 y0 z0 xA yA zA alpha width height), found 8"},
    {"camera 0 0 0 0 0 5 120 70 50", 1, 20,
     "the camera's field of view must be less than pi radians, found '120' (it is in "
     "radians: 120 degrees is 2.0943951)"},
    {"camera 0 0 0 0 0 5 0 70 50", 1, 20,
     "the camera's field of view must be greater than 0, found '0'"},
    {"camera 1 2 3 1 2 3 1 70 50", 1, 14,
     "the camera looks at its own position: the point it looks at must be elsewhere"},
    {"camera 0 0 0 0 0 5 1 70.5 50", 1, 22,
     "expected the image width as a whole number of pixels (decimal digits only), found "
     "'70.5'"},
    {"camera 0 0 0 0 0 5 1 70 40000", 1, 25,
     "the image height must be between 1 and 32768 pixels, found '40000'"},
    {CAM CAM, 2, 1, "the camera is already set, on line 1"},
    {CAM "material", 2, 9,
     "expected the material's name (name r g b ka kd ks alpha [rho_r [eta_r [tau]]]), found "
     "the end of the line"},
    {CAM "material 255 0 0 1 1 1 1", 2, 10,
     "expected the material's name (name r g b ka kd ks alpha [rho_r [eta_r [tau]]]), found "
     "the number '255'"},
    {CAM MAT MAT, 3, 10, "the material 'm' is already defined, on line 2"},
    {CAM "material m 255 0 0 1 1 1", 2, 25,
     "expected 7 to 10 numbers for the material (name r g b ka kd ks alpha [rho_r [eta_r "
     "[tau]]]), found 6"},
    {CAM "material m 255 0 0 1 1 1 1 0 1 0 9", 2, 34,
     "expected 7 to 10 numbers for the material (name r g b ka kd ks alpha [rho_r [eta_r "
     "[tau]]]), found 11"},
    {CAM "material m 256 0 0 1 1 1 1", 2, 12, "the material's red must be in [0, 255], found '256'"},
    {CAM "material m 255 0 0 1 -1 1 1", 2, 22, "the material's kd must be at least 0, found '-1'"},
    {CAM "material m 255 0 0 1 1 1 1 0.5 1.5 0.6", 2, 36,
     "the material's rho_r plus tau must be at most 1, found 0.5 + 0.6"},
    {CAM "material m 255 0 0 1 1 1 1 0.5 0", 2, 32,
     "the material's eta_r must be greater than 0, found '0'"},
    {CAM "material m 255 0 0 1 1 1 nan", 2, 26,
     "the material's alpha must be a finite number, found 'nan'"},
    {CAM MAT "sphere 0 0 5 1", 3, 15,
     "expected the name of a material after the numbers of the sphere (cx cy cz radius "
     "material), found the end of the line"},
    {CAM MAT "sphere 0 0 5 m", 3, 14,
     "expected 4 numbers before the material of the sphere (cx cy cz radius material), found "
     "3"},
    {CAM MAT "sphere 0 0 5 1 2 m", 3, 16,
     "expected 4 numbers for the sphere (cx cy cz radius material), found 5"},
    {CAM MAT "sphere 0 0 5 1 m x", 3, 18,
     "expected the end of the line after the material's name, found 'x'"},
    {CAM MAT "sphere 0 0 5 1 7", 3, 16,
     "expected the name of a material for the sphere (cx cy cz radius material), found the "
     "number '7'"},
    {CAM MAT "sphere 0 0,5 5 1 m", 3, 10, "expected a number for the sphere's centre y, found '0,5'"},
    {CAM MAT "sphere 0 0 5 0 m", 3, 14, "the sphere's radius must be greater than 0, found '0'"},
    {CAM MAT "sphere 0 0 5 1 n", 3, 16,
     "unknown material 'n': a material line must define it before the sphere"},
    {CAM "sphere 0 0 5 1 m\n" MAT, 2, 16,
     "unknown material 'm': a material line must define it before the sphere"},
    {CAM MAT "plane 0 0 0 0 0 0 m", 3, 13,
     "the plane's normal is the zero vector: it must give a direction"},
    {CAM MAT "triangle 0 0 0 1 1 1 2 2 2 m", 3, 1,
     "the triangle's three vertices lie on one line: it has no area"},
    {CAM MAT "triangle 0 0 0 1 1 1 2 2 m", 3, 26,
     "expected 9 numbers before the material of the triangle (x0 y0 z0 x1 y1 z1 x2 y2 z2 "
     "material), found 8"},
    {CAM MAT "mesh", 3, 5,
     "expected the path of a mesh file (OBJ, PLY or STL) for the mesh (path [material]), found "
     "the end of the line"},
    {CAM MAT "mesh a.obj", 3, 6, "cannot use the mesh 'a.obj': cannot open: No such file or "
     "directory"},
    {CAM MAT "mesh no-such.obj m", 3, 6,
     "cannot use the mesh 'no-such.obj': cannot open: No such file or directory"},
    {CAM "light 0 0 0 1 1 1 1", 2, 7,
     "the light's direction is the zero vector: a distant light needs the direction its light "
     "travels"},
    {CAM "light 0 0 1 1 1 1", 2, 18, "expected 7 numbers for the light (x y z r g b i), found 6"},
    {CAM "light 0 0 1 1 1 1 -1", 2, 19,
     "the light's intensity must be at least 0, found '-1'"},
    {CAM "ambient 1 1 1\nambient 1 1 1", 3, 1, "the ambient light is already set, on line 2"},
    {CAM "background 1 1", 2, 15,
     "expected 3 numbers for the background (r g b), found 2"},
    {CAM "donut 1 2 3", 2, 1,
     "unknown element 'donut' (expected 'camera', 'material', 'sphere', 'plane', 'triangle', "
     "'cube', 'square', 'cylinder', 'cone', 'disk', 'torus', 'mesh', 'light', 'ambient' or "
     "'background')"},
    {CAM "torus 1 2 3 0 1 0", 2, 18,
     "expected the name of a material after the numbers of the torus (cx cy cz nx ny nz R r "
     "material), found the end of the line"},
    {CAM "Disk 1 2 3 0 1 0 1 m", 2, 1,
     "unknown element 'Disk': keywords are lower case ('disk')"},
    {CAM "cube 1 2 3", 2, 11,
     "expected the name of a material after the numbers of the cube (cx cy cz half-edge material), "
     "found the end of the line"},
    {CAM "material m 1 2 3 0 1 0 0\ncone 0 0 0 1 0 m", 3, 14,
     "the cone's height must not be 0: its apex is that far above (or below) the centre of its "
     "circle"},
    {CAM "material m 1 2 3 0 1 0 0\nsquare 0 0 0 0 0 0 1 m", 3, 14,
     "the square's normal is the zero vector: it must give a direction"},
    {CAM "Sphere 0 0 5 1 m", 2, 1, "unknown element 'Sphere': keywords are lower case ('sphere')"},
    {CAM "sphere: 0 0 5 1 m", 2, 1,
     "unknown element 'sphere:': this is a keyword-format scene (its first element is a "
     "keyword), where keywords take no colon ('sphere')"},
    {CAM "100 100 0", 2, 1,
     "expected an element such as 'sphere', found the number '100': every line of a "
     "keyword-format scene starts with its keyword"},
    {CAM "sphere 0 0 5 1 m\rx", 2, 17,
     "carriage return inside a line: lines must end with LF or CRLF"},
};

static void keyword_rejects_bad_scenes_with_position(void)
{
    for (size_t i = 0; i < sizeof keyword_bad / sizeof keyword_bad[0]; i++) {
        const BadKeyword *b = &keyword_bad[i];
        Scene sc;
        Error err;
        int rc = kw(b->text, &sc, &err);

        CHECK_INT(-1, rc);
        if (rc != -1) {
            scene_free(&sc);
            continue;
        }
        CHECK_INT(0, (long long)scene_count_of(&sc, SHAPE_SPHERE));
        CHECK_ERROR(b->text, &err, b->line, b->column, b->message);
    }
}

static void keyword_finds_many_materials_by_name(void)
{
    /* 3,000 materials and a sphere for each, named in reverse: the name
     * table must find every one (and grow past its first size). */
    size_t n = 3000, size = 64 * n + 100, len = 0;
    char *text = malloc(size);
    Scene sc;
    Error err;
    int ok = 1;

    CHECK(text != NULL);
    if (!text)
        return;
    len += (size_t)snprintf(text + len, size - len, "camera 0 0 0 0 0 1 1 8 8\n");
    for (size_t i = 0; i < n; i++)
        len += (size_t)snprintf(text + len, size - len, "material m%zu %zu 0 0 1 1 1 1\n", i,
                                i % 256);
    for (size_t i = 0; i < n; i++)
        len += (size_t)snprintf(text + len, size - len, "sphere %zu 0 9 0.5 m%zu\n", i,
                                n - 1 - i);
    CHECK_INT(0, kw(text, &sc, &err));
    for (size_t i = 0; i < n && scene_count_of(&sc, SHAPE_SPHERE) == n; i++)
        ok &= scene_material(&sc, SHAPE_SPHERE, i).named == (int)(n - 1 - i) &&
              scene_material(&sc, SHAPE_SPHERE, i).colour.r == (double)((n - 1 - i) % 256);
    CHECK(ok);
    scene_free(&sc);
    free(text);
}

/* The format load_detect() sees in the C string s. */
static SceneFormat detect(const char *s)
{
    return load_detect(s, strlen(s));
}

static void keyword_formats_are_told_apart(void)
{
    CHECK_INT(SCENE_KEYWORD, detect(OCAML_TEST));
    CHECK_INT(SCENE_KEYWORD, detect("\xEF\xBB\xBF# c\r\n\n  \tmaterial"));
    CHECK_INT(SCENE_KEYWORD, detect("camra 1 2")); /* a misspelt keyword */
    CHECK_INT(SCENE_COURSE, detect("100 100 0\n"));
    CHECK_INT(SCENE_COURSE, detect("# c\n-1 0 0\n"));
    CHECK_INT(SCENE_COURSE, detect("nan 0 0\n"));
    CHECK_INT(SCENE_COURSE, detect("Infinity 0 0\n"));
    CHECK_INT(SCENE_COURSE, detect(".5 0 0\n"));
    CHECK_INT(SCENE_AUTO, detect("")); /* empty: refused as such */
    CHECK_INT(SCENE_AUTO, detect("# only a comment"));
    CHECK_INT(SCENE_COURSE, detect("\x01"));
}

static void keyword_numbers_print_shortest_and_read_back(void)
{
    char buf[NUMBER_FORMAT_MAX];
    int worst = 0;

    CHECK(strcmp(number_format(buf, 0.1), "0.1") == 0);
    CHECK(strcmp(number_format(buf, 10), "10") == 0);
    CHECK(strcmp(number_format(buf, 255), "255") == 0);
    CHECK(strcmp(number_format(buf, 1e15), "1000000000000000") == 0);
    CHECK(strcmp(number_format(buf, -0.0), "-0") == 0);
    CHECK(strcmp(number_format(buf, 0.1 + 0.2), "0.30000000000000004") == 0);
    CHECK(strcmp(number_format(buf, 2.2250738585072014e-308), "2.2250738585072014e-308") == 0);
    /* Random doubles of every magnitude read back to the same bits. */
    for (int i = 0, n = test_trials(100000); i < n; i++) {
        double x = ldexp(rng_range(-1, 1), (int)rng_range(-1000, 49)), back = 0;
        int digits = 0;
        number_format(buf, x);
        for (const char *p = buf; *p && *p != 'e'; p++)
            digits += *p >= '0' && *p <= '9';
        if (number_parse(buf, strlen(buf), &back) != NUMBER_OK ||
            memcmp(&back, &x, sizeof x) != 0) {
            test_fail(__FILE__, __LINE__, "%.17g printed as %s reads back as %.17g", x, buf,
                      back);
            break;
        }
        if (fabs(x) < 1e-4 || fabs(x) >= 1e17)
            worst = digits > worst ? digits : worst;
    }
    CHECK(worst <= 17);
}

/* Writes scene (read from name) to a new string through save_scene(). */
static char *saved(const Scene *sc, const SceneSource *src, const char *name)
{
    FILE *fp = tmpfile();
    char *text = NULL;
    long len;
    Error err;

    CHECK(fp != NULL);
    if (!fp)
        return NULL;
    CHECK_INT(0, save_scene(fp, sc, src, name, "out.txt", &err));
    len = ftell(fp);
    rewind(fp);
    text = calloc((size_t)len + 1, 1);
    if (text && fread(text, 1, (size_t)len, fp) != (size_t)len)
        text[0] = '\0';
    fclose(fp);
    return text;
}

/* Says whether a and b hold the same bits (fields, not padding). */
#define SAME(a, b) (memcmp(&(a), &(b), sizeof(a)) == 0)

static int same_material(const Material *a, const Material *b)
{
    return SAME(a->colour, b->colour) && SAME(a->reflection, b->reflection) &&
           SAME(a->transparency, b->transparency) && SAME(a->ior, b->ior) &&
           a->texture == b->texture && a->filter == b->filter && a->named == b->named;
}

static int same_light(const Light *a, const Light *b)
{
    return SAME(a->position, b->position) && SAME(a->colour, b->colour) &&
           a->distant == b->distant && SAME(a->intensity, b->intensity) &&
           SAME(a->to_light, b->to_light);
}

static int same_camera(const Camera *a, const Camera *b)
{
    return SAME(a->eye, b->eye) && SAME(a->top_left, b->top_left) && SAME(a->u, b->u) &&
           SAME(a->v, b->v) && a->width == b->width && a->height == b->height &&
           SAME(a->aperture, b->aperture);
}

/* Says whether two scenes hold the same camera, lights, materials and
 * objects, bit for bit. */
static int same_scene(const Scene *a, const Scene *b)
{
    int same = same_camera(&a->camera, &b->camera) && SAME(a->background, b->background) &&
               SAME(a->ambient, b->ambient) && a->has_ambient == b->has_ambient &&
               a->light_count == b->light_count && a->named_count == b->named_count &&
               a->length_exponent == b->length_exponent;

    for (int k = 0; k < SHAPE_KINDS; k++)
        same = same && scene_count_of(a, (ShapeKind)k) == scene_count_of(b, (ShapeKind)k);
    for (size_t i = 0; same && i < a->light_count; i++)
        same = same_light(&a->lights[i], &b->lights[i]);
    for (size_t i = 0; same && i < a->named_count; i++) {
        const NamedMaterial *p = &a->named[i], *q = &b->named[i];
        same = strcmp(p->name, q->name) == 0 && same_material(&p->base, &q->base) &&
               SAME(p->ka, q->ka) && SAME(p->kd, q->kd) && SAME(p->ks, q->ks) &&
               SAME(p->shininess, q->shininess);
    }
    for (size_t i = 0; same && i < scene_count_of(a, SHAPE_SPHERE); i++) {
        const Sphere *p = &scene_spheres(a)[i], *q = &scene_spheres(b)[i];
        Material pm = scene_material(a, SHAPE_SPHERE, i), qm = scene_material(b, SHAPE_SPHERE, i);
        same = SAME(p->centre, q->centre) && SAME(p->radius, q->radius) &&
               same_material(&pm, &qm) && p->order == q->order;
    }
    for (size_t i = 0; same && i < scene_count_of(a, SHAPE_PLANE); i++) {
        const Plane *p = &scene_planes(a)[i], *q = &scene_planes(b)[i];
        same = SAME(p->point, q->point) && SAME(p->normal, q->normal) &&
               SAME(p->given, q->given) && SAME(p->axis_u, q->axis_u) &&
               SAME(p->axis_v, q->axis_v) && same_material(&p->material, &q->material) &&
               p->order == q->order;
    }
    for (size_t i = 0; same && i < scene_count_of(a, SHAPE_TRIANGLE); i++) {
        const Triangle *p = &scene_triangles(a)[i], *q = &scene_triangles(b)[i];
        TriangleShading ps = shading_of(a, i), qs = shading_of(b, i);
        same = SAME(p->v, q->v) && SAME(p->normal, q->normal) && SAME(ps.uv, qs.uv) &&
               ps.smooth == qs.smooth && (!ps.smooth || SAME(ps.vn, qs.vn)) &&
               p->swapped == q->swapped && same_material(scene_material_of(a, p), scene_material_of(b, q)) &&
               p->order == q->order;
    }
    for (size_t i = 0; same && i < scene_count_of(a, SHAPE_CUBE); i++) {
        const Cube *p = &((Cube *)scene_items(a, SHAPE_CUBE))[i], *q = &((Cube *)scene_items(b, SHAPE_CUBE))[i];
        same = SAME(p->centre, q->centre) && SAME(p->half, q->half) && SAME(p->lo, q->lo) &&
               SAME(p->hi, q->hi) && same_material(&p->material, &q->material) &&
               p->order == q->order;
    }
    for (size_t i = 0; same && i < scene_count_of(a, SHAPE_SQUARE); i++) {
        const Square *p = &((Square *)scene_items(a, SHAPE_SQUARE))[i], *q = &((Square *)scene_items(b, SHAPE_SQUARE))[i];
        same = SAME(p->centre, q->centre) && SAME(p->given, q->given) &&
               SAME(p->normal, q->normal) && SAME(p->axis_u, q->axis_u) &&
               SAME(p->half, q->half) && same_material(&p->material, &q->material) &&
               p->order == q->order;
    }
    for (size_t i = 0; same && i < scene_count_of(a, SHAPE_CYLINDER); i++) {
        const Cylinder *p = &((Cylinder *)scene_items(a, SHAPE_CYLINDER))[i], *q = &((Cylinder *)scene_items(b, SHAPE_CYLINDER))[i];
        same = SAME(p->centre, q->centre) && SAME(p->radius, q->radius) &&
               same_material(&p->material, &q->material) && p->order == q->order;
    }
    for (size_t i = 0; same && i < scene_count_of(a, SHAPE_CONE); i++) {
        const Cone *p = &((Cone *)scene_items(a, SHAPE_CONE))[i], *q = &((Cone *)scene_items(b, SHAPE_CONE))[i];
        same = SAME(p->base, q->base) && SAME(p->apex, q->apex) && SAME(p->radius, q->radius) &&
               SAME(p->height, q->height) && SAME(p->k, q->k) &&
               same_material(&p->material, &q->material) && p->order == q->order;
    }
    /* Every kind (the others: a disk, a torus) by its record's numbers. */
    for (int k = 0; k < SHAPE_KINDS; k++)
        for (size_t i = 0; same && i < scene_count_of(a, (ShapeKind)k); i++) {
            double u[SHAPE_NUMBERS_MAX], v[SHAPE_NUMBERS_MAX];
            Material ma = scene_material(a, (ShapeKind)k, i), mb = scene_material(b, (ShapeKind)k, i);
            int n = shapes_numbers(a, (ShapeKind)k, i, u);
            same = n == shapes_numbers(b, (ShapeKind)k, i, v) &&
                   memcmp(u, v, (size_t)n * sizeof *u) == 0 && same_material(&ma, &mb) &&
                   scene_order_of(a, (ShapeKind)k, i) == scene_order_of(b, (ShapeKind)k, i);
        }
    return same;
}

static void keyword_saved_scene_reads_back_the_same(void)
{
    /* Numbers that need all 17 digits, -0, tiny and huge values, every
     * element, materials with 0 to 3 optional numbers, one unused. */
    static const char *const texts[] = {
        OCAML_TEST,
        ("camera 0.30000000000000004 -0 1e-300 0.1 0.7 123456789012345.67 2.0943951023931957 "
        "640 480\n"
        "background 0.1 254.99999999999997 3\nambient 1e-5 2 3\n"
        "material a 255 0 0.5 0.1 0.2 0.30000000000000004 3.5\n"
        "material b 1 2 3 0 0 0 0 0.25\n"
        "material c 1 2 3 0 0 0 0 0.1 1.3333333333333333\n"
        "material d 1 2 3 0 0 0 0 0.1 1.5 0.2\n"
        "material unused 9 9 9 1 1 1 1\n"
        "light 0.1 -0.2 0.30000000000000004 255 255 255 1e-3\n"
        "light 1e15 1 1 1 2 3 4.0000000000000009\n"
        "sphere 1.0000000000000002 2 3 0.99999999999999989 a\n"
        "plane 0 -1e-9 0 0.1 1 1e-7 b\n"
        "triangle 0 0 5 1 0 5 0.33333333333333331 1 5 c\n"
        "sphere -7e-200 4 5 1e-100 d\n"
        "cube 0.1 0.2 0.30000000000000004 1e-7 a\n"
        "square 1 2 3 -0 1e-3 -1 0.99999999999999989 b\n"
        "cylinder 1e14 -2 3 7e-5 c\n"
        "cone 0.5 -0.5 1.5 0.1 -2.0000000000000004 d\n"
        "disk 1 2 3 0.1 -0.30000000000000004 1e-9 0.99999999999999989 a\n"
        "torus -1e7 0.1 3 1 1 -0 2.0000000000000004 0.30000000000000004 b\n"
        "cube -1 -2 -3 4 a\n"),
        /* A tiny scene, enlarged on reading: saved at its own scale. */
        ("camera 0 0 0 0 0 5e-30 1 8 8\nmaterial m 1 1 1 1 1 1 1\n"
         "sphere 1e-31 0 5e-30 1e-30 m\nplane 0 -3e-30 0 0 1 0 m\nlight 0 -1 1 1 1 1 1\n"
         "cube 1e-31 0 5e-30 2e-31 m\nsquare 0 0 6e-30 0 0 -1 1e-30 m\n"
         "cylinder 1e-30 0 5e-30 1e-31 m\ncone 0 -1e-30 5e-30 1e-31 3e-31 m\n"
         "disk 0 0 7e-30 0 0 1 1e-30 m\ntorus 0 1e-30 6e-30 0 1 0 2e-30 5e-31 m\n"),
    };

    for (size_t i = 0; i < sizeof texts / sizeof texts[0]; i++) {
        Scene a, b, c;
        SceneSource sa, sb;
        Error err;
        char *once, *twice;

        CHECK_INT(0, kw_source(texts[i], &a, &sa, &err));
        once = saved(&a, &sa, "t.txt");
        CHECK(once != NULL);
        if (!once)
            continue;
        CHECK_INT(0, kw_source(once, &b, &sb, &err));
        if (!same_scene(&a, &b) || !SAME(sa.fov, sb.fov) || !SAME(sa.look_from, sb.look_from) ||
            !SAME(sa.look_at, sb.look_at))
            test_fail(__FILE__, __LINE__, "case %zu: the saved scene differs:\n%s", i, once);
        twice = saved(&b, &sb, "t.txt");
        CHECK(twice && strcmp(once, twice) == 0);
        /* The saved text holds the original numbers. */
        if (i == 1) {
            CHECK_CONTAINS(once, "camera 0.30000000000000004 -0 1e-300 0.1 0.7 "
                                 "123456789012345.67 2.0943951023931957 640 480\n");
            CHECK_CONTAINS(once, "material b 1 2 3 0 0 0 0 0.25\n");
            CHECK_CONTAINS(once, "material unused 9 9 9 1 1 1 1\n");
            CHECK_CONTAINS(once, "plane 0 -1e-09 0 0.1 1 1e-07 b\n");
        }
        if (i == 2) {
            CHECK(a.length_exponent != 0);
            CHECK_CONTAINS(once, "sphere 1e-31 0 5e-30 1e-30 m\n");
        }
        CHECK_INT(0, kw(twice ? twice : "", &c, &err));
        scene_free(&c);
        free(once);
        free(twice);
        scene_free(&a);
        scene_free(&b);
        source_free(&sa);
        source_free(&sb);
    }
}

static void keyword_save_refuses_a_course_scene(void)
{
    Scene sc;
    SceneSource src;
    Error err;
    FILE *fp = tmpfile();

    CHECK(fp != NULL);
    CHECK_INT(0, load_scene_file("scenes/course.txt", SCENE_AUTO, 0, 0, &sc, &src, &err));
    if (fp) {
        CHECK_INT(-1, save_scene(fp, &sc, &src, "scenes/course.txt", "out.txt", &err));
        CHECK_CONTAINS(err.message, "cannot express a course-format scene");
        fclose(fp);
    }
    scene_free(&sc);
    source_free(&src);
}

const TestCase keyword_tests[] = {
    {"keyword_reads_the_ocaml_test_scene", keyword_reads_the_ocaml_test_scene},
    {"keyword_reads_every_element_in_any_order", keyword_reads_every_element_in_any_order},
    {"keyword_camera_looks_at_its_target", keyword_camera_looks_at_its_target},
    {"keyword_blinn_phong_has_its_three_terms", keyword_blinn_phong_has_its_three_terms},
    {"keyword_distant_light_shadows_from_any_distance",
     keyword_distant_light_shadows_from_any_distance},
    {"keyword_mirror_adds_to_the_local_term", keyword_mirror_adds_to_the_local_term},
    {"keyword_rejects_bad_scenes_with_position", keyword_rejects_bad_scenes_with_position},
    {"keyword_finds_many_materials_by_name", keyword_finds_many_materials_by_name},
    {"keyword_formats_are_told_apart", keyword_formats_are_told_apart},
    {"keyword_numbers_print_shortest_and_read_back", keyword_numbers_print_shortest_and_read_back},
    {"keyword_saved_scene_reads_back_the_same", keyword_saved_scene_reads_back_the_same},
    {"keyword_save_refuses_a_course_scene", keyword_save_refuses_a_course_scene},
    {NULL, NULL},
};
