/* test_mpl.c: the MPL ray tracer's MPL format: its own example read verbatim, its
 * spellings of numbers, its errors, the four material kinds' shading and
 * its lights, and scenes saved and read back. */
#include <math.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>

#include "render/model.h"
#include "render/trace.h"
#include "scenefile/load.h"
#include "scenefile/mpl.h"
#include "scenefile/save.h"
#include "test.h"

/* Reads text as an MPL scene named t.txt; returns what the reader does. */
static int mpl(const char *text, Scene *sc, Error *err)
{
    return load_scene_text("t.txt", text, strlen(text), SCENE_MPL, 0, 0, sc, NULL, err);
}

static void mpl_reads_the_example_verbatim(void)
{
    /* scenes/mpl.txt is the MPL ray tracer's 15 lines, textures and all. */
    Scene sc;
    Error err;

    CHECK_INT(0, load_scene_file("scenes/mpl.txt", SCENE_AUTO, 0, 0, &sc, NULL, &err));
    CHECK_INT(SCENE_MPL, sc.format);
    CHECK_INT(5, (long long)sc.named_count);
    CHECK_INT(4, (long long)sc.texture_count);
    CHECK_INT(2, (long long)scene_count_of(&sc, SHAPE_SQUARE));
    CHECK_INT(1, (long long)scene_count_of(&sc, SHAPE_CUBE));
    CHECK_INT(4, (long long)scene_count_of(&sc, SHAPE_CYLINDER));
    CHECK_INT(1, (long long)scene_count_of(&sc, SHAPE_CONE));
    CHECK_INT(1, (long long)scene_count_of(&sc, SHAPE_SPHERE));
    CHECK_INT(1, (long long)sc.light_count);
    /* "p Cylinder -4.f, 0.f, 5.f 1.0f marble": commas and C literals. */
    CHECK_NEAR(-4, ((Cylinder *)scene_items(&sc, SHAPE_CYLINDER))[0].centre.x, 0);
    CHECK_NEAR(5, ((Cylinder *)scene_items(&sc, SHAPE_CYLINDER))[0].centre.z, 0);
    CHECK_NEAR(1, ((Cylinder *)scene_items(&sc, SHAPE_CYLINDER))[0].radius, 0);
    /* The MPL ray tracer's sizes are half-edges: the painting stands out of the
     * wall at z = 5 by 0.25. */
    CHECK_NEAR(4.75, ((Cube *)scene_items(&sc, SHAPE_CUBE))[0].lo.z, 0);
    CHECK_NEAR(6.75, ((Cube *)scene_items(&sc, SHAPE_CUBE))[0].hi.z, 0);
    CHECK_NEAR(50, ((Square *)scene_items(&sc, SHAPE_SQUARE))[1].half, 0);
    CHECK_INT(MODEL_METALLIC, sc.named[4].model);
    CHECK_INT(MODEL_MATTE, sc.named[0].model);
    /* "m marble MATTE 1.f 1.f 1.f 0 1.f 50.f marble.jpg": the index 7th,
     * the glossiness 8th, as the MPL ray tracer's reader takes them; a glossy matte
     * surface has highlights. */
    CHECK_NEAR(1, sc.named[3].index, 0);
    CHECK_NEAR(50, sc.named[3].shininess, 0);
    CHECK_NEAR(1, sc.named[3].ks, 0);
    CHECK_NEAR(0, sc.named[0].ks, 0);
    CHECK_NEAR(127.5, sc.named[4].base.colour.r, 0);
    /* The cone stands on its circle at y = -1.5, its apex 2.5 above. */
    CHECK_NEAR(1, ((Cone *)scene_items(&sc, SHAPE_CONE))[0].apex.y, 0);
    CHECK_NEAR(0.2 * 0.2, ((Cone *)scene_items(&sc, SHAPE_CONE))[0].k, 1e-16);
    CHECK_INT(1, ((Cone *)scene_items(&sc, SHAPE_CONE))[0].finite); /* it ends at its circle */
    CHECK_INT(1, sc.lights[0].distant);
    CHECK_NEAR(sqrt(0.5), sc.lights[0].to_light.y, 1e-15);
    CHECK_NEAR(-sqrt(0.5), sc.lights[0].to_light.z, 1e-15);
    /* No camera line: the MPL ray tracer's, 500 x 500 at the origin looking along +z
     * with 90 degrees of view, 4 samples a pixel, its program's model. */
    CHECK_INT(500, sc.camera.width);
    CHECK_INT(500, sc.camera.height);
    CHECK_INT(4, sc.samples);
    CHECK_INT(SCENE_MODEL_MPL, sc.model);
    CHECK_INT(SCENE_MAPPING_MPL, sc.mapping);
    CHECK_INT(-1, sc.ao_samples); /* not said: the model's default */
    CHECK_NEAR(0, sc.camera.eye.z, 0);
    CHECK_NEAR(-1, sc.camera.top_left.x, 1e-15);
    CHECK_NEAR(1, sc.camera.top_left.y, 1e-15);
    CHECK_NEAR(1, sc.camera.top_left.z, 1e-15);
    CHECK_INT(1, sc.has_sky);
    scene_free(&sc);
}

static void mpl_reads_c_literals_commas_and_any_case(void)
{
    Scene sc;
    Error err;

    CHECK_INT(0, mpl("m A matte 1.F .5f 0.25 1 0.f 1e1f N\n"
                     "m b Dielectric 1 1 1 0 1.33F 3 n\n"
                     "p SPHERE 1.f , 2.f ,3.f, 0.5f A\n"
                     "p tri 4 0 0 5 b\n"
                     "p triangle 0 0 1 1 0 1 0 1 1 A\n"
                     "l pointlight 1 2 3 1 1 1 10 20\n"
                     "c camera 0 0 -1 0 0 0 60 40 20\n"
                     "c background 0.5 0.5 0.5\n",
                     &sc, &err));
    CHECK_NEAR(0.5 * 255, sc.named[0].base.colour.g, 0);
    CHECK_INT(1, sc.named[0].base.stripes);
    CHECK_NEAR(10, sc.named[0].shininess, 0);
    CHECK_NEAR(1.33, sc.named[1].base.ior, 0);
    CHECK_NEAR(3, scene_spheres(&sc)[0].centre.z, 0);
    /* The MPL ray tracer's Tri: size 4 at (0, 0, 5): (0, 1), (-1, -1), (1, -1). */
    CHECK_NEAR(1, scene_triangles(&sc)[0].v[0].y, 0);
    CHECK_NEAR(-1, scene_triangles(&sc)[0].v[1].x, 0);
    CHECK_NEAR(1, scene_triangles(&sc)[0].v[2].x, 0);
    CHECK_INT(1, sc.lights[0].falloff);
    CHECK_NEAR(20, sc.lights[0].range, 0);
    CHECK_INT(40, sc.camera.width);
    CHECK_INT(20, sc.camera.height);
    /* 60 degrees vertically: the screen at distance 1 is 2 tan 30 high. */
    CHECK_NEAR(2 * tan(3.14159265358979323846 / 6), vec3_length(sc.camera.v), 1e-12);
    CHECK_INT(0, sc.has_sky);
    CHECK_NEAR(127.5, sc.background.r, 0);
    scene_free(&sc);
}

typedef struct {
    const char *text;
    int line, column;
    const char *message;
} BadMpl;

#define MAT "m a MATTE 1 1 1 0 0 0 N\n"

static const BadMpl mpl_bad[] = {
    {"x 1 2 3\n", 1, 1,
     "unknown line 'x' (expected 'm' a material, 'p' a primitive, 'l' a light or 'c' a "
     "setting)"},
    {"m a CHALK 1 1 1 0 0 0 N\n", 1, 5,
     "unknown material kind 'CHALK' (expected MATTE, PLASTIC, METALLIC or DIELECTRIC)"},
    {"m a MATTE 1 1 1.5 0 0 0 N\n", 1, 15, "the material's blue must be in [0, 1], found '1.5'"},
    {"m a MATTE 1 1 1 2 0 0 N\n", 1, 17,
     "the material's stripes must be 0 (a plain colour) or 1 (stripes), found '2'"},
    {"m a MATTE 1 1 1 -1 0 0 N\n", 1, 17,
     "the material's stripes must be 0 (a plain colour) or 1 (stripes), found '-1'"},
    {"m a DIELECTRIC 1 1 1 0 0 10 N\n", 1, 24,
     "the DIELECTRIC material's index must be positive (glass: about 1.5), found '0'"},
    {"m a PLASTIC 1 1 1 0 0.5 20 N 1.5\n", 1, 30,
     "the material has an 11th field, '1.5': the MPL ray tracer's layout ends with the texture (m name "
     "kind r g b stripes index glossiness texture); raytrace 0.1's --save wrote a highlight "
     "weight 7th and the index last: move the index to the 7th field and drop this one"},
    {"m a MATTE 1 1 1 0 0 0 N x\n", 1, 25,
     "unknown texture filter 'x' after the material's texture (expected nearest, bilinear, "
     "trilinear or ewa)"},
    {"m a MATTE 1 1 1 0 0 0 N ewa x\n", 1, 29,
     "expected the end of the line after the material's filter, found 'x'"},
    {"c Model pbr\n", 1, 9,
     "unknown model 'pbr' (expected mpl, the MPL ray tracer's rules, or physical)"},
    {"m a MATTE 1 1 1 0.5 0 0 N\n", 1, 17,
     "the material's stripes must be 0 (a plain colour) or 1 (stripes), found '0.5'"},
    {"m a MATTE 1 1 1 0 0 0\n", 1, 22,
     "expected the material's texture, a file or N for none (m name kind r g b stripes "
     "index glossiness texture), found the end of the line"},
    {"m a MATTE 1 1 1 0 0 0 nothere.jpg\n", 1, 23,
     "cannot use the texture 'nothere.jpg': cannot open: No such file or directory"},
    {MAT MAT, 2, 3, "the material 'a' is already defined, on line 1"},
    {MAT "p Torus 0 0 0 1 a\n", 2, 3,
     "unknown primitive 'Torus' (expected Sphere, Plane, Triangle, Tri, Cube, Square, Cylinder "
     "or Cone)"},
    {MAT "p Sphere 0 0 0 1 b\n", 2, 18,
     "unknown material 'b': an m line must define it before the sphere"},
    {MAT "p Sphere 0 0 0 a\n", 2, 16,
     "expected 4 numbers before the material of the sphere (cx cy cz radius material), found 3"},
    {MAT "p Sphere 0 0 0 -1 a\n", 2, 16, "the sphere's radius must be greater than 0, found '-1'"},
    {MAT "p Cone 0 0 0 1 0 a\n", 2, 16,
     "the cone's height must not be 0: its apex is that far above (or below) the centre of its "
     "circle"},
    {MAT "p Square 0 0 0 0 0 0 1 a\n", 2, 16,
     "the square's normal is the zero vector: it must give a direction"},
    {MAT "p Triangle 0 0 0 1 1 1 2 2 2 a\n", 2, 1,
     "the triangle's three vertices lie on one line: it has no area"},
    {"l Spot 0 0 0 1 1 1 1\n", 1, 3, "unknown light 'Spot' (expected DirectionLight or PointLight)"},
    {"l DirectionLight 0 0 0 1 1 1 1\n", 1, 18,
     "the light's direction is the zero vector: a directional light needs the direction its "
     "light travels"},
    {"l PointLight 0 0 0 1 1 1 -1\n", 1, 26,
     "the point light's intensity must be at least 0, found '-1'"},
    {"c Camera 0 0 0 0 0 1 180 8 8\n", 1, 22,
     "the camera's field of view must be less than 180 degrees, found '180'"},
    {"c Camera 0 0 0 0 0 0 90 8 8\n", 1, 16,
     "the camera looks at its own position: its target must be elsewhere"},
    {"c Camera 0 0 0 0 0 1 90 8\n", 1, 26,
     "expected the camera's numbers (x y z tx ty tz fov width height), found the end of the "
     "line"},
    {"c Camera 0 0 0 0 0 1 90 8 8\nc Camera 0 0 0 0 0 1 90 8 8\n", 2, 1,
     "the camera is already set, on line 1"},
    {"c Fog 1\n", 1, 3,
     "unknown setting 'Fog' (expected Camera, Background, Sky, Ambient, Samples, AO, GI, "
     "GICache, Model or Noise)"},
    {"c GICache 5\n", 1, 11, "the irradiance cache's error must be from 0.01 to 2 (smaller: more "
                            "records)"},
    {"c Noise\n", 1, 8,
     "expected the noise level (c Noise level [min-spp [max-spp]]), found the end of the line"},
    {"c Noise 0\n", 1, 9, "the noise's level must be greater than 0, found '0'"},
    {"c Noise 300\n", 1, 9,
     "the noise level must be at most 255 levels (an error the size of the whole range)"},
    {"c Noise 1 0\n", 1, 11,
     "the least samples a pixel must be between 1 and 1048576 samples, found '0'"},
    {"c Noise 1 64 16\n", 1, 14, "the most samples a pixel (16) is fewer than the least (64)"},
    {"c Noise 1 16 64 9\n", 1, 17, "expected the end of the line after the noise, found '9'"},
    {"c Noise 1\nc Noise 2\n", 2, 1, "the noise is already set, on line 1"},
    {"c Sky 1 1 1\n", 1, 12, "expected 6 numbers for the sky (r g b r g b), found 3"},
    {"c AO 4097\n", 1, 6,
     "the number of ambient occlusion rays must be between 0 and 4096 rays, found '4097'"},
    {"c AO 4 -1\n", 1, 8, "the ambient occlusion's distance must be greater than 0, found '-1'"},
    {"c GI 2 0\n", 1, 8, "the number of bounces must be between 1 and 64 bounces, found '0'"},
    {"c AO 4 1 2\n", 1, 10, "expected the end of the line after the distance, found '2'"},
    {"c GI 2\nc GI 3\n", 2, 1, "the global illumination is already set, on line 1"},
};

/* Under --strict: every line that breaks the format, those the MPL ray tracer's
 * program read leniently among them. */
static void mpl_rejects_bad_scenes_with_position(void)
{
    for (size_t i = 0; i < sizeof mpl_bad / sizeof mpl_bad[0]; i++) {
        const BadMpl *b = &mpl_bad[i];
        Scene sc;
        Error err;
        int rc =
            load_scene_text("t.txt", b->text, strlen(b->text), SCENE_MPL, 0, 1, &sc, NULL, &err);

        CHECK_INT(-1, rc);
        if (rc != -1) {
            scene_free(&sc);
            continue;
        }
        CHECK_ERROR(b->text, &err, b->line, b->column, b->message);
    }
}

/* Lines the MPL ray tracer read though they break the format: read as it
 * read them, each with a warning at its place; --strict refuses each. */
static void mpl_reads_its_programs_lenient_lines_with_warnings(void)
{
    static const struct {
        const char *text;
        int line, column;
        const char *message;
    } cases[] = {
        {MAT "p Sphere 0 0 0 1.5abc a\n", 2, 19, "read '1.5abc' as 1.5, up to its first letter"},
        {MAT "p Sphere 0 0 0 1.5 a shiny 3\n", 2, 22, "ignored 2 words after the material's name"},
        {MAT "p Sphere 0 0 0 1.5 b\n", 2, 20, "unknown material 'b': read as the first one, 'a'"},
        {MAT "m a MATTE 0 0 1 0 0 0 N\np Sphere 0 0 0 1.5 a\n", 2, 3,
         "the material 'a' is already defined, on line 1: kept that one, this line changes "
         "nothing"},
        {MAT "p Sphere 0 0 0 1.5 a\nl PointLight 0 5 0 1 1 1 1 10 7 8\n", 3, 31,
         "ignored 2 numbers after the light's"},
        {MAT "p Sphere 0 0 0 1.5 a\nl DirectionLight 0 -1 0 1 1 1 1 2\n", 3, 33,
         "ignored 1 number after the light's"},
        {MAT "p Sphere 0 0 0 1.5 a\nl PointLight 0 5 0 1 1 1 0.5x\n", 3, 29,
         "read '0.5x' as 0.5, up to its first letter"},
    };

    for (size_t i = 0; i < sizeof cases / sizeof cases[0]; i++) {
        const char *text = cases[i].text;
        Scene sc;
        Error err;
        char want[ERROR_MESSAGE_MAX];
        CHECK_INT(0, mpl(text, &sc, &err));
        CHECK_INT(1, (long long)sc.warning_count);
        snprintf(want, sizeof want, "%s (as the MPL ray tracer did; --strict refuses it)",
                 cases[i].message);
        if (sc.warning_count == 1)
            CHECK_ERROR(text, &sc.warnings[0], cases[i].line, cases[i].column, want);
        /* What was read: the sphere of radius 1.5, in the first material,
         * white; the one light of intensity 1. */
        CHECK_INT(1, (long long)scene_count_of(&sc, SHAPE_SPHERE));
        if (scene_count_of(&sc, SHAPE_SPHERE) == 1)
            CHECK_NEAR(1.5, scene_spheres(&sc)[0].radius, 0);
        CHECK_NEAR(255, scene_material(&sc, SHAPE_SPHERE, 0).colour.b, 0);
        scene_free(&sc);
        CHECK_INT(-1,
                  load_scene_text("t.txt", text, strlen(text), SCENE_MPL, 0, 1, &sc, NULL, &err));
    }
}

/* What its program could not have read stays an error. */
static void mpl_lenience_stops_where_its_program_did(void)
{
    static const char *const texts[] = {
        "p Sphere 0 0 0 1 a\n",               /* no material at all */
        MAT "p Sphere 0 0 0 abc a\n",         /* no number before the letters */
        MAT "p Sphere 0 0 0 1 2 a\n",         /* a number too many */
        MAT "l PointLight 0 5 0 1 1 1 1 10 x\n", /* a word after the light's */
    };

    for (size_t i = 0; i < sizeof texts / sizeof texts[0]; i++) {
        Scene sc;
        Error err;
        CHECK_INT(-1, mpl(texts[i], &sc, &err));
    }
}

/* The colour seen along the ray from o towards d in sc, to depth 10, by
 * the physical model. */
static Colour seen(Scene *sc, Vec3 o, Vec3 d)
{
    Ray r = {o, vec3_normalize(d)};
    RayCounts counts = {0};
    Tracer t;

    sc->model = SCENE_MODEL_PHYSICAL;
    t = model_tracer(sc, 10, &counts);
    return trace_ray(&t, &r);
}

static void mpl_material_kinds_shade_as_documented(void)
{
    /* A directional light straight down the view (i = 0.8, white), a
     * black background, each kind on a sphere seen head on. */
    static const char *const kinds[] = {"MATTE", "PLASTIC", "METALLIC", "DIELECTRIC"};
    Vec3 eye = vec3(0, 0, -5);

    for (int k = 0; k < 4; k++) {
        char text[256];
        Scene sc;
        Error err;
        Colour c;
        snprintf(text, sizeof text,
                 "c Background 0 0 0\nm s %s 0.8 0.4 0.2 0 1.5 10 N\np Sphere 0 0 0 1 s\n"
                 "l DirectionLight 0 0 1 1 1 1 0.8\n",
                 kinds[k]);
        CHECK_INT(0, mpl(text, &sc, &err));
        c = seen(&sc, eye, vec3(0, 0, 1));
        switch (k) {
        case 0: /* kd cos i C Cs / 255: 0.8 x 204, and the highlight (ks 1) */
            CHECK_NEAR(0.8 * 204 + 0.8 * 255, c.r, 1e-9);
            CHECK_NEAR(0.8 * 102 + 0.8 * 255, c.g, 1e-9);
            break;
        case 1: { /* (1 - F)(diffuse + specular) + F x background; F = 0.04 head on */
            double f = 0.04;
            CHECK_NEAR((1 - f) * (0.8 * 204 + 0.8 * 255), c.r, 1e-9);
            break;
        }
        case 2: /* the highlight, the mirror sees black */
            CHECK_NEAR(0.8 * 255, c.r, 1e-9);
            CHECK_NEAR(0.8 * 255, c.b, 1e-9);
            break;
        default: /* the highlight; through the glass (no highlight inside), black */
            CHECK_NEAR(0.8 * 255, c.r, 1e-9);
            break;
        }
        scene_free(&sc);
    }
}

static void mpl_metal_tints_and_glass_splits_by_fresnel(void)
{
    /* A white matte wall (lit at 45 degrees, so it is 255 x 0.5 x cos 45),
     * seen in a metal mirror; then a wall lit head on through a glass slab
     * (a cube). */
    Scene sc;
    Error err;
    Colour c;

    CHECK_INT(0, mpl("c Background 0 0 0\nm w MATTE 1 1 1 0 0 0 N\n"
                     "m gold METALLIC 1 0.5 0.25 0 0 0 N\n"
                     "p Square 0 0 -10 0 0 1 100 w\np Square 0 0 0 0 0 -1 1 gold\n"
                     "l DirectionLight 0 -1 -1 1 1 1 0.5\n",
                     &sc, &err));
    /* From z = -5 looking at the mirror (z = 0, facing -z), back to the wall
     * (lit from above and behind the viewer, past the mirror). */
    c = seen(&sc, vec3(0, 0, -5), vec3(0, 0, 1));
    CHECK_NEAR(127.5 * sqrt(0.5) * 1, c.r, 1e-9);
    CHECK_NEAR(127.5 * sqrt(0.5) * 0.5, c.g, 1e-9);
    CHECK_NEAR(127.5 * sqrt(0.5) * 0.25, c.b, 1e-9);
    scene_free(&sc);
    CHECK_INT(0, mpl("c Background 0 0 0\nm w MATTE 1 1 1 0 0 0 N\n"
                     "m glass DIELECTRIC 1 1 1 0 1.5 0 N\n"
                     "p Square 0 0 10 0 0 -1 100 w\np Cube 0 0 0 1 glass\n"
                     "l DirectionLight 0 0 1 1 1 1 0.5\n",
                     &sc, &err));
    /* Head on through the slab: (1 - F)^2 of the wall (F = 0.04 at each
     * face), the mirrored shares seeing black, and those mirrored twice
     * inside going on through: the series adds F^2 / (1 - F^2) more. The
     * wall behind the slab is in its shadow: the light crosses two faces
     * of transparency 1 - F(0) = 0.96. */
    c = seen(&sc, vec3(0, 0, -5), vec3(0, 0, 1));
    {
        double f = 0.04, t = (1 - f) * (1 - f) * (1 + f * f / (1 - f * f));
        CHECK_NEAR(127.5 * (1 - f) * (1 - f) * t, c.r, 1e-6);
    }
    scene_free(&sc);
}

static void mpl_point_light_falls_off_and_ends_at_its_range(void)
{
    /* A white matte floor under a point light 2 above it (i = 8): i / d^2
     * head on, less away from it, with a range: smoothly to nothing. */
    Scene sc;
    Error err;
    Colour c;
    double d2 = 4, q;

    CHECK_INT(0, mpl("c Background 0 0 0\nm w MATTE 1 1 1 0 0 0 N\np Plane 0 0 0 0 1 0 w\n"
                     "l PointLight 0 2 0 1 1 1 8\n",
                     &sc, &err));
    c = seen(&sc, vec3(0, 1, -1), vec3(0, -1, 1)); /* hits (0, 0, 0) */
    CHECK_NEAR(255 * 8 / d2, c.r, 1e-9);
    scene_free(&sc);
    CHECK_INT(0, mpl("c Background 0 0 0\nm w MATTE 1 1 1 0 0 0 N\np Plane 0 0 0 0 1 0 w\n"
                     "l PointLight 0 2 0 1 1 1 8 4\n",
                     &sc, &err));
    c = seen(&sc, vec3(0, 1, -1), vec3(0, -1, 1));
    q = d2 / 16;
    CHECK_NEAR(255 * 8 / d2 * (1 - q * q) * (1 - q * q), c.r, 1e-9);
    /* At (4, 0, 0), sqrt(20) > 4 from the light: beyond its range. */
    c = seen(&sc, vec3(4, 1, -1), vec3(0, -1, 1));
    CHECK_NEAR(0, c.r, 0);
    scene_free(&sc);
}

/* Writes sc (read from name) to a new string through save_scene(). */
static char *mpl_saved(const Scene *sc, const SceneSource *src, const char *name)
{
    FILE *fp = tmpfile();
    Error err;
    long n;
    char *text;

    if (!fp)
        return NULL;
    CHECK_INT(0, save_scene(fp, sc, src, name, "out.txt", &err));
    n = ftell(fp);
    rewind(fp);
    text = calloc((size_t)n + 1, 1);
    if (text && fread(text, 1, (size_t)n, fp) != (size_t)n) {
        free(text);
        text = NULL;
    }
    fclose(fp);
    return text;
}

static void mpl_saved_scene_reads_back_the_same(void)
{
    /* Numbers needing 17 digits, colours whose 255-fold rounds, every
     * element, and a tiny scene (enlarged on reading, its point light's
     * intensity with it). */
    static const char *const texts[] = {
        ("c Camera 0.1 0.2 -3 0 0 0.30000000000000004 45 64 48\nc Sky 0.3 0.6 0.9 0.1 0.2 0.7\n"
         "c Ambient 0.1 0.1 0.13\nc Samples 3\n"
         "c Model physical\nc AO 3 0.5\nc GI 2\nc Noise 0.75 32 512\n"
         "m a PLASTIC 0.13 0.7 0.33333333333333331 1 1.45 20 N\n"
         "m b DIELECTRIC 0.9 0.9 1 0 1 100 N\nm c METALLIC 0.01 0.99 0.5 0 1 1e3 N\n"
         "p Sphere 1 2 3 0.7 a\np Plane 0 -1 0 0.1 1 0 b\np Cube -1 0 2 0.25 c\n"
         "p Square 0 0 5 0 0 -1 2 a\np Cylinder 3 0 4 0.5 b\np Cone -3 -1 4 0.5 1.5 c\n"
         "p Triangle 0 0 6 1 0 6 0 1 6 a\nl DirectionLight 1 -1 1 1 0.5 0.25 0.7\n"
         "l PointLight 0 3 0 1 1 1 5 12\n"),
        ("c Camera 0 0 -3e-30 0 0 0 40 8 8\nm m MATTE 1 1 1 0 0 0 N\n"
         "p Sphere 0 0 1e-30 4e-31 m\nl PointLight 1e-30 1e-30 -1e-30 1 1 1 3e-60 2e-30\n"),
    };

    for (size_t i = 0; i < sizeof texts / sizeof texts[0]; i++) {
        Scene a, b;
        SceneSource sa, sb;
        Error err;
        char *once, *twice;
        CHECK_INT(0, load_scene_text("t.txt", texts[i], strlen(texts[i]), SCENE_MPL, 0, 0, &a, &sa,
                                     &err));
        once = mpl_saved(&a, &sa, "t.txt");
        CHECK(once != NULL);
        if (!once) {
            scene_free(&a);
            source_free(&sa);
            continue;
        }
        CHECK_INT(0, load_scene_text("t.txt", once, strlen(once), SCENE_MPL, 0, 0, &b, &sb, &err));
        /* The same picture: a small render of each, compared by bytes
         * through a ray in each pixel's direction. */
        for (int y = 0; y < 8; y++)
            for (int x = 0; x < 8; x++) {
                Ray r = camera_ray(&a.camera, x + 0.5, y + 0.5), s = camera_ray(&b.camera, x + 0.5,
                                                                                y + 0.5);
                RayCounts n = {0};
                Tracer ta = model_tracer(&a, 5, &n), tb = model_tracer(&b, 5, &n);
                Colour ca = trace_ray(&ta, &r), cb = trace_ray(&tb, &s);
                if (memcmp(&ca, &cb, sizeof ca) != 0)
                    test_fail(__FILE__, __LINE__, "case %zu: pixel (%d, %d) differs:\n%s", i, x,
                              y, once);
            }
        CHECK(memcmp(&a.named[0].base.colour, &b.named[0].base.colour, sizeof(Colour)) == 0);
        CHECK_NEAR(a.noise, b.noise, 0);
        CHECK_INT(a.noise_min_spp, b.noise_min_spp);
        CHECK_INT(a.noise_max_spp, b.noise_max_spp);
        CHECK_NEAR(i == 0 ? 0.75 : 0, a.noise, 0);
        CHECK_INT(i == 0 ? 512 : 0, a.noise_max_spp);
        CHECK(a.light_count == b.light_count &&
              memcmp(&a.lights[a.light_count - 1].intensity,
                     &b.lights[b.light_count - 1].intensity, sizeof(double)) == 0);
        twice = mpl_saved(&b, &sb, "t.txt");
        CHECK(twice && strcmp(once, twice) == 0);
        free(once);
        free(twice);
        scene_free(&a);
        scene_free(&b);
        source_free(&sa);
        source_free(&sb);
    }
}

static void mpl_is_told_from_the_other_formats(void)
{
    static const char mpl_text[] = "# a comment\n\nm a MATTE 1 1 1 0 0 0 N\n";
    static const char kw_text[] = "camera 0 0 0 0 0 1 1 8 8\n";
    static const char course_text[] = "0 0 0\n";

    CHECK_INT(SCENE_MPL, load_detect(mpl_text, strlen(mpl_text)));
    CHECK_INT(SCENE_MPL, load_detect("p Sphere", 8));
    CHECK_INT(SCENE_MPL, load_detect("l x", 3));
    CHECK_INT(SCENE_MPL, load_detect("c Camera", 8));
    CHECK_INT(SCENE_KEYWORD, load_detect(kw_text, strlen(kw_text)));
    CHECK_INT(SCENE_KEYWORD, load_detect("mat", 3));
    CHECK_INT(SCENE_COURSE, load_detect(course_text, strlen(course_text)));
}

static void mpl_cone_ends_at_its_circle(void)
{
    /* A cone of circle y = 0 (radius 1) and apex y = 2: a ray through
     * where its nappe would go on below the circle misses it; one through
     * its side hits it. */
    Scene sc;
    Error err;
    Ray below = {vec3(0, -1, -5), vec3(0, 0, 1)}, side = {vec3(0, 1, -5), vec3(0, 0, 1)};
    real t = 0;

    CHECK_INT(0, mpl("m a MATTE 1 1 1 0 0 0 N\np Cone 0 0 0 1 2 a\n", &sc, &err));
    CHECK_INT(0, cone_intersect(&((Cone *)scene_items(&sc, SHAPE_CONE))[0], &below, 0, INFINITY, &t));
    CHECK_INT(1, cone_intersect(&((Cone *)scene_items(&sc, SHAPE_CONE))[0], &side, 0, INFINITY, &t));
    CHECK_NEAR(4.5, t, 1e-12);
    ((Cone *)scene_items(&sc, SHAPE_CONE))[0].finite = 0; /* the keyword format's infinite cone */
    CHECK_INT(1, cone_intersect(&((Cone *)scene_items(&sc, SHAPE_CONE))[0], &below, 0, INFINITY, &t));
    scene_free(&sc);
}

static void mpl_model_line_chooses_the_rules(void)
{
    Scene sc;
    Error err;

    CHECK_INT(0, mpl("c Model physical\n", &sc, &err));
    CHECK_INT(SCENE_MODEL_PHYSICAL, sc.model);
    CHECK_INT(SCENE_MAPPING_MPL, sc.mapping); /* textures stay where the file put them */
    scene_free(&sc);
    CHECK_INT(0, mpl("c model MPL\n", &sc, &err));
    CHECK_INT(SCENE_MODEL_MPL, sc.model);
    scene_free(&sc);
    /* The old spelling, still taken. */
    CHECK_INT(0, mpl("c model SEED001\n", &sc, &err));
    CHECK_INT(SCENE_MODEL_MPL, sc.model);
    scene_free(&sc);
}

const TestCase mpl_tests[] = {
    {"mpl_reads_the_example_verbatim", mpl_reads_the_example_verbatim},
    {"mpl_reads_c_literals_commas_and_any_case", mpl_reads_c_literals_commas_and_any_case},
    {"mpl_rejects_bad_scenes_with_position", mpl_rejects_bad_scenes_with_position},
    {"mpl_reads_its_programs_lenient_lines_with_warnings",
     mpl_reads_its_programs_lenient_lines_with_warnings},
    {"mpl_lenience_stops_where_its_program_did", mpl_lenience_stops_where_its_program_did},
    {"mpl_material_kinds_shade_as_documented", mpl_material_kinds_shade_as_documented},
    {"mpl_metal_tints_and_glass_splits_by_fresnel", mpl_metal_tints_and_glass_splits_by_fresnel},
    {"mpl_point_light_falls_off_and_ends_at_its_range",
     mpl_point_light_falls_off_and_ends_at_its_range},
    {"mpl_saved_scene_reads_back_the_same", mpl_saved_scene_reads_back_the_same},
    {"mpl_is_told_from_the_other_formats", mpl_is_told_from_the_other_formats},
    {"mpl_cone_ends_at_its_circle", mpl_cone_ends_at_its_circle},
    {"mpl_model_line_chooses_the_rules", mpl_model_line_chooses_the_rules},
    {NULL, NULL},
};
