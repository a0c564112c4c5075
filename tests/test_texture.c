/* test_texture.c: texture files, lookups, mappings, and texture: records. */
#include <math.h>
#include <stdio.h>
#include <string.h>

#include "geometry/sphere.h"
#include "scene/texture.h"
#include "scenefile/load.h"
#include "scenefile/course.h"
#include "scenefile/texture_file.h"
#include "shading.h"
#include "test.h"

/* Writes text (len bytes) to path. */
static void write_file(const char *path, const char *text, size_t len)
{
    FILE *f = fopen(path, "wb");
    CHECK(f != NULL);
    if (!f)
        return;
    CHECK_INT(len, fwrite(text, 1, len, f));
    fclose(f);
}

/* A 3 x 2 P3 texture of maxval 1000: top row red 0, 500, 1000; bottom row
 * green 1000, 0, 200. */
#define TEX_P3 "P3\n# a comment\n3 2\n1000\n0 0 0  500 0 0  1000 0 0\n0 1000 0  0 0 0  0 200 0\n"

static void texture_lookup_nearest_and_bilinear(void)
{
    Texture tex;
    Error err;
    Colour c;

    write_file("build/tex-a.ppm", TEX_P3, strlen(TEX_P3));
    CHECK_INT(0, texture_file_load(&tex, "build/tex-a.ppm", 0, &err));
    /* Texel centres: u = (i + 0.5) / 3, v from the bottom. */
    c = texture_lookup(&tex, 1.5 / 3, 0.75, TEXTURE_NEAREST, 0);
    CHECK_NEAR(127.5, c.r, 1e-12);
    c = texture_lookup(&tex, 2.5 / 3, 0.25, TEXTURE_NEAREST, 0);
    CHECK_NEAR(51, c.g, 1e-12);
    c = texture_lookup(&tex, 2.5 / 3, 0.75, TEXTURE_BILINEAR, 0);
    CHECK_NEAR(255, c.r, 1e-12);
    /* Half-way between the top row's first two texels. */
    c = texture_lookup(&tex, 1.0 / 3, 0.75, TEXTURE_BILINEAR, 0);
    CHECK_NEAR(63.75, c.r, 1e-12);
    /* u repeats: at u = 0 the first and last columns blend. */
    c = texture_lookup(&tex, 0, 0.75, TEXTURE_BILINEAR, 0);
    CHECK_NEAR(127.5, c.r, 1e-12);
    c = texture_lookup(&tex, 3 + 1.5 / 3, -1 + 0.75, TEXTURE_NEAREST, 0);
    CHECK_NEAR(127.5, c.r, 1e-12);
    /* v clamped: at the top edge, the top row alone; repeated, it blends
     * with the bottom row. */
    c = texture_lookup(&tex, 0.5 / 3, 1, TEXTURE_BILINEAR, 1);
    CHECK_NEAR(0, c.g, 1e-12);
    c = texture_lookup(&tex, 0.5 / 3, 0, TEXTURE_BILINEAR, 0);
    CHECK_NEAR(127.5, c.g, 1e-12);
    c = texture_lookup(&tex, NAN, INFINITY, TEXTURE_BILINEAR, 1); /* no crash */
    texture_free(&tex);
}

static void texture_reads_sixteen_bit_binary(void)
{
    static const char p6[] = "P6\n1 1\n65535\n\xff\xff\x80\x00\x00\x01";
    Texture tex;
    Error err;
    Colour c;

    write_file("build/tex-b.ppm", p6, sizeof p6 - 1);
    CHECK_INT(0, texture_file_load(&tex, "build/tex-b.ppm", 0, &err));
    c = texture_lookup(&tex, 0.3, 0.3, TEXTURE_BILINEAR, 0);
    CHECK_NEAR(255, c.r, 1e-12);
    CHECK_NEAR(32768 * 255.0 / 65535, c.g, 1e-12);
    CHECK_NEAR(255.0 / 65535, c.b, 1e-15);
    texture_free(&tex);
}

static void sphere_uv_at_known_points(void)
{
    double uv[2];

    sphere_uv(NULL, vec3(0, 0, 0), vec3(0, 0, -1), uv); /* facing a camera that looks along +z */
    CHECK_NEAR(0.5, uv[0], 0);
    CHECK_NEAR(0.5, uv[1], 1e-15);
    sphere_uv(NULL, vec3(0, 0, 0), vec3(0, 0, 1), uv); /* the seam, behind */
    CHECK_NEAR(1, uv[0], 0);
    sphere_uv(NULL, vec3(0, 0, 0), vec3(1, 0, 0), uv);
    CHECK_NEAR(0.75, uv[0], 1e-15);
    sphere_uv(NULL, vec3(0, 0, 0), vec3(0, 1, 0), uv);
    CHECK_NEAR(1, uv[1], 0);
    sphere_uv(NULL, vec3(0, 0, 0), vec3(0, -1, 0), uv);
    CHECK_NEAR(0, uv[1], 0);
}

#define TEX_HEADER "0 0 0\n-1 1 1\n1 1 1\n-1 -1 1\n4\n0 0 0\n0 5 0 255 255 255\n"

/* Parses text as build/t.txt; returns its status. */
static int parse_in_build(const char *text, Scene *sc, Error *err)
{
    return load_scene_text("build/t.txt", text, strlen(text), SCENE_COURSE, 0, 0, sc, NULL, err);
}

static void texture_records_attach_to_the_object_before(void)
{
    /* Only to that object: not to a triangle of the same colours after it,
     * nor to another mesh of the same file (a mesh's triangles share one
     * material; a triangle's texture coordinates are its own). */
    static const char square[] = "v 0 0 4\nv 1 0 4\nv 1 1 4\nv 0 1 4\nf 1 2 3 4\n";
    Scene sc;
    Error err;

    write_file("build/tex-a.ppm", TEX_P3, strlen(TEX_P3));
    write_file("build/square.obj", square, strlen(square));
    CHECK_INT(0, parse_in_build(TEX_HEADER "sphere: 0 0 5 1 1 2 3 0\ntexture: tex-a.ppm\n"
                                           "plane: 0 -1 0 0 1 0 1 2 3 0\n"
                                           "texture: tex-a.ppm nearest 2.5\n"
                                           "triangle: 0 0 3 1 0 3 0 1 3 1 2 3 0\n"
                                           "texture: tex-a.ppm bilinear 0 0 1 0 0.5 1\n"
                                           "triangle: 0 0 3 1 0 3 0 1 3 1 2 3 0\n"
                                           "mesh: square.obj 1 2 3 0\ntexture: tex-a.ppm\n"
                                           "mesh: square.obj 1 2 3 0\n",
                                &sc, &err));
    CHECK_INT(6, (long long)scene_count_of(&sc, SHAPE_TRIANGLE));
    if (scene_count_of(&sc, SHAPE_TRIANGLE) == 6) {
        CHECK_INT(-1, scene_material_of(&sc, &scene_triangles(&sc)[1])->texture);
        CHECK_INT(TRIANGLE_PLAIN, scene_triangles(&sc)[1].shading);
        CHECK_INT(scene_triangles(&sc)[2].material, scene_triangles(&sc)[3].material);
        CHECK_INT(0, scene_material_of(&sc, &scene_triangles(&sc)[3])->texture);
        CHECK_INT(scene_triangles(&sc)[4].material, scene_triangles(&sc)[5].material);
        CHECK(scene_triangles(&sc)[4].material != scene_triangles(&sc)[2].material);
        CHECK_INT(-1, scene_material_of(&sc, &scene_triangles(&sc)[4])->texture);
        CHECK_INT(1, (long long)sc.shading_count); /* the first triangle's */
    }
    CHECK_INT(1, (long long)sc.texture_count); /* one file, read once */
    CHECK_INT(0, scene_material(&sc, SHAPE_SPHERE, 0).texture);
    CHECK_INT(TEXTURE_BILINEAR, scene_material(&sc, SHAPE_SPHERE, 0).filter);
    CHECK_INT(TEXTURE_NEAREST, scene_planes(&sc)[0].material.filter);
    CHECK_NEAR(2.5, scene_planes(&sc)[0].tile, 0);
    CHECK_NEAR(0.5, shading_of(&sc, 0).uv[2][0], 0);
    CHECK_NEAR(3, sc.textures[0].width, 0);
    scene_free(&sc);
}

static void texture_faults_are_positioned_in_the_scene(void)
{
    static const struct {
        const char *records; /* after the header, line 8 on */
        int line, column;
        const char *message;
    } bad[] = {
        {"texture: tex-a.ppm\n", 8, 1,
         "a texture: record must follow the object it covers, and no object comes before it"},
        {"sphere: 0 0 5 1 1 2 3 0\ntexture: missing.ppm\n", 9, 10,
         "cannot use the texture 'missing.ppm': cannot open: No such file or directory"},
        {"sphere: 0 0 5 1 1 2 3 0\ntexture: tex-bad.ppm\n", 9, 10,
         "cannot use the texture 'tex-bad.ppm': build/tex-bad.ppm:2:5: expected the maxval (a "
         "whole number), found something else"},
        {"sphere: 0 0 5 1 1 2 3 0\ntexture: .\n", 9, 10, "cannot use the texture '.': cannot read: it is a directory, not a file"},
        {"sphere: 0 0 5 1 1 2 3 0\ntexture: tex-a.ppm\ntexture: tex-a.ppm\n", 10, 1,
         "the sphere's texture is already set: an object takes one texture: record"},
        {"sphere: 0 0 5 1 1 2 3 0\ntexture: tex-a.ppm 2\n", 9, 20,
         "expected the end of the line after the sphere's texture, found '2'"},
        {"sphere: 0 0 5 1 1 2 3 0\ntexture:\n", 9, 9,
         "expected the path of a PPM file for the sphere's texture (path [filter]), found the "
         "end of the line"},
        {"plane: 0 0 0 0 1 0 1 2 3 0\ntexture: tex-a.ppm nearest 0\n", 9, 28,
         "the plane's texture's tile size must be greater than 0, found '0'"},
        {"plane: 0 0 0 0 1 0 1 2 3 0\ntexture: tex-a.ppm cubic\n", 9, 20,
         "unknown texture filter 'cubic' (expected 'nearest', 'bilinear', 'trilinear' or "
         "'ewa')"},
        {"triangle: 0 0 3 1 0 3 0 1 3 1 2 3 0\ntexture: tex-a.ppm 0 0 1\n", 9, 20,
         "expected 0 or 6 numbers for the triangle's texture (path [filter] [u0 v0 u1 v1 u2 "
         "v2]), found 3"},
    };

    write_file("build/tex-a.ppm", TEX_P3, strlen(TEX_P3));
    write_file("build/tex-bad.ppm", "P3\n1 1 x\n", 9);
    for (size_t i = 0; i < sizeof bad / sizeof bad[0]; i++) {
        char text[512];
        Scene sc;
        Error err;

        snprintf(text, sizeof text, TEX_HEADER "%s", bad[i].records);
        if (parse_in_build(text, &sc, &err) == 0) {
            test_fail(__FILE__, __LINE__, "case %zu accepted", i);
            scene_free(&sc);
            continue;
        }
        CHECK(strcmp(err.file, "build/t.txt") == 0);
        CHECK_ERROR(bad[i].message, &err, bad[i].line, bad[i].column, bad[i].message);
    }
}

const TestCase texture_tests[] = {
    {"texture_lookup_nearest_and_bilinear", texture_lookup_nearest_and_bilinear},
    {"texture_reads_sixteen_bit_binary", texture_reads_sixteen_bit_binary},
    {"sphere_uv_at_known_points", sphere_uv_at_known_points},
    {"texture_records_attach_to_the_object_before", texture_records_attach_to_the_object_before},
    {"texture_faults_are_positioned_in_the_scene", texture_faults_are_positioned_in_the_scene},
    {NULL, NULL},
};
