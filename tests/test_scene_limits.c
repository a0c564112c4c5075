/* test_scene_limits.c: the memory limit and the refusals that keep a render from
 * running out of memory (scene.h, obj.h, deflate.h, file.h, writer.h). */
#include <stdint.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>

#include "accel/bvh.h"
#include "base/file.h"
#include "image/deflate.h"
#include "image/writer.h"
#include "math/number.h"
#include "scene/scene.h"
#include "scene/scene_accel.h"
#include "scenefile/load.h"
#include "scenefile/course.h"
#include "scenefile/obj.h"
#include "test.h"

static void limits_sizes_read_for_people(void)
{
    char buf[NUMBER_FORMAT_MAX];

    CHECK(strcmp(number_bytes(buf, 0), "0 bytes") == 0);
    CHECK(strcmp(number_bytes(buf, 1), "1 byte") == 0);
    CHECK(strcmp(number_bytes(buf, 1023), "1023 bytes") == 0);
    CHECK(strcmp(number_bytes(buf, 1024), "1 KiB") == 0);
    CHECK(strcmp(number_bytes(buf, 1536), "1.5 KiB") == 0);
    CHECK(strcmp(number_bytes(buf, (size_t)4 << 30), "4 GiB") == 0);
    CHECK(strcmp(number_bytes(buf, SIZE_MAX), "16 EiB") == 0);
}

/* A course scene of n spheres, one a line after the 7-line header. */
static char *limits_spheres(int n)
{
    static const char head[] = "0 0 -5\n-1 1 0\n1 1 0\n-1 -1 0\n8\n0 0 0\n5 5 -5 255 255 255\n";
    size_t cap = sizeof head + 40 * (size_t)n, len;
    char *text = malloc(cap);

    if (!text)
        return NULL;
    strcpy(text, head);
    len = strlen(text);
    for (int i = 0; i < n; i++)
        len += (size_t)snprintf(text + len, cap - len, "sphere: %d 0 3 1 200 100 50 0\n", i);
    return text;
}

static void limits_scene_stops_at_the_element_that_passes(void)
{
    char *text = limits_spheres(1000);
    Scene sc;
    Error err;
    size_t limit = 48 * 1024;

    CHECK(text != NULL);
    if (!text)
        return;
    /* No limit: every sphere is read. */
    CHECK_INT(0, load_scene_text("t.txt", text, strlen(text), SCENE_COURSE, 0, 0, &sc, NULL, &err));
    CHECK_INT(1000, (long long)scene_count_of(&sc, SHAPE_SPHERE));
    CHECK(scene_memory(&sc) >= 1000 * sizeof(Sphere));
    CHECK(scene_memory_left(&sc) == SIZE_MAX);
    scene_free(&sc);
    /* 48 KiB: the array doubles to 512 spheres, not to 1024; the error
     * points at the 513th sphere's line (8 + 512). */
    CHECK_INT(
        -1, load_scene_text("t.txt", text, strlen(text), SCENE_COURSE, limit, 0, &sc, NULL, &err));
    CHECK_INT(520, err.line);
    CHECK_INT(1, err.column);
    CHECK_CONTAINS(err.message, "would pass the memory limit of 48 KiB");
    free(text);
}

/* scene_add_spheres()'s fill: writes the spheres the context says, sphere
 * k at x = k and a half mirror when k == 7; returns the context's code. */
typedef struct {
    size_t n;
    int code;
} SpheresFill;

static int limits_fill(Sphere *room, void *ctx)
{
    const SpheresFill *f = ctx;

    for (size_t k = 0; k < f->n; k++) {
        room[k].centre = vec3((double)k, 0, 3);
        room[k].radius = 1;
        Material m = material_plain(colour(1, 2, 3), k == 7 ? 0.5 : 0);
        sphere_set_plain(&room[k], &m);
    }
    return f->code;
}

/* Says whether spheres a and b are the same, field by field. */
static int same_sphere(const Sphere *a, const Sphere *b)
{
    return memcmp(&a->centre, &b->centre, sizeof a->centre) == 0 && a->radius == b->radius &&
           a->plain == b->plain && a->order == b->order &&
           (a->plain ? a->material.reflection == b->material.reflection
                     : a->material.index == b->material.index) &&
           memcmp(a->rgb, b->rgb, sizeof a->rgb) == 0;
}

/* Spheres added at once take the room, positions and materials that adding
 * them one by one gives, or leave the scene as it was: when the fill
 * fails, and when the memory limit stops one of them. */
static void limits_spheres_added_at_once_as_one_by_one(void)
{
    Scene one, all;
    Vec3 c = vec3(0, 0, 3);
    Material m = material_plain(colour(1, 2, 3), 0);
    Light light = light_point(vec3(0, 5, 0), colour(255, 255, 255));
    SpheresFill fill = {1000, 0};
    size_t cap;
    long long same = 0;

    scene_init(&one);
    scene_init(&all);
    CHECK_INT(0, scene_add_light(&one, &light));
    CHECK_INT(0, scene_add_light(&all, &light));
    for (int k = 0; k < 3; k++) { /* three before: positions 0 to 2 */
        CHECK_INT(0, scene_add_sphere(&one, c, 1, &m));
        CHECK_INT(0, scene_add_sphere(&all, c, 1, &m));
    }
    for (size_t k = 0; k < fill.n; k++) {
        c.x = (double)k;
        m.reflection = k == 7 ? 0.5 : 0;
        CHECK_INT(0, scene_add_sphere(&one, c, 1, &m));
    }
    CHECK_INT(0, scene_add_spheres(&all, fill.n, limits_fill, &fill));
    CHECK_INT((long long)scene_count_of(&one, SHAPE_SPHERE),
              (long long)scene_count_of(&all, SHAPE_SPHERE));
    CHECK_INT((long long)one.shapes[SHAPE_SPHERE].capacity,
              (long long)all.shapes[SHAPE_SPHERE].capacity);
    CHECK_INT(1024, (long long)all.shapes[SHAPE_SPHERE].capacity);
    for (size_t k = 0; k < scene_count_of(&one, SHAPE_SPHERE); k++)
        same += same_sphere(&scene_spheres(&one)[k], &scene_spheres(&all)[k]);
    CHECK_INT((long long)scene_count_of(&one, SHAPE_SPHERE), same);
    CHECK_NEAR(0.5, scene_material(&all, SHAPE_SPHERE, 3 + 7).reflection, 0);
    CHECK_INT(3 + 999, scene_spheres(&all)[3 + 999].order);
    CHECK_NEAR(999, scene_spheres(&all)[3 + 999].centre.x, 0);
    CHECK_INT(scene_spheres(&one)[500].order, scene_spheres(&all)[500].order);
    /* A failing fill: the code back, the scene as it was. */
    cap = all.shapes[SHAPE_SPHERE].capacity;
    fill.code = 7;
    CHECK_INT(7, scene_add_spheres(&all, 2000, limits_fill, &fill));
    CHECK_INT(1003, (long long)scene_count_of(&all, SHAPE_SPHERE));
    CHECK_INT((long long)cap, (long long)all.shapes[SHAPE_SPHERE].capacity);
    /* The limit: room for 2048 spheres, not for 4096; adding one by one
     * would stop at the 2049th, so adding 1046 at once stops too, and
     * nothing is left of the attempt. */
    fill.code = 0;
    all.memory_limit = scene_memory(&all) + 1024 * sizeof(Sphere);
    CHECK_INT(SCENE_OVER_LIMIT, scene_add_spheres(&all, 1046, limits_fill, &fill));
    CHECK_INT((long long)cap, (long long)all.shapes[SHAPE_SPHERE].capacity);
    CHECK_INT(1003, (long long)scene_count_of(&all, SHAPE_SPHERE));
    CHECK_INT(0, scene_add_spheres(&all, 1045, limits_fill, &fill));
    CHECK_INT(2048, (long long)all.shapes[SHAPE_SPHERE].capacity);
    scene_free(&one);
    scene_free(&all);
}

static void limits_hierarchy_is_estimated_before_it_is_built(void)
{
    char *text = limits_spheres(1000);
    Scene sc;
    Error err;

    CHECK(text != NULL);
    if (!text)
        return;
    CHECK_INT(0, load_scene_text("t.txt", text, strlen(text), SCENE_COURSE, 0, 0, &sc, NULL, &err));
    sc.memory_limit = scene_memory(&sc) + bvh_build_memory(1000) - 1;
    CHECK_INT(SCENE_OVER_LIMIT, scene_build_accel(&sc, 1));
    CHECK(sc.accel == NULL);
    sc.memory_limit += 1;
    CHECK_INT(0, scene_build_accel(&sc, 1));
    CHECK(sc.accel != NULL);
    /* What was built is within the estimate. */
    CHECK(scene_memory(&sc) <= sc.memory_limit);
    scene_free(&sc);
    free(text);
}

static void limits_mesh_reading_keeps_to_its_budget(void)
{
    char text[4096];
    size_t len = (size_t)snprintf(text, sizeof text, "v 0 0 0\nv 1 0 0\nv 0 1 0\nf");
    MeshFile m;
    Error err;

    for (int i = 0; i < 300; i++)
        len += (size_t)snprintf(text + len, sizeof text - len, " %d", 1 + i % 3);
    text[len++] = '\n';
    CHECK_INT(0, obj_parse("fan.obj", text, len, 0, &m, &err));
    CHECK_INT(298, (long long)m.tri_count);
    CHECK(mesh_file_memory(&m) >= 298 * sizeof *m.tri);
    mesh_file_free(&m);
    CHECK_INT(-1, obj_parse("fan.obj", text, len, 2000, &m, &err));
    CHECK_INT(4, err.line);
    CHECK_CONTAINS(err.message, "the mesh needs more memory than the 1.953 KiB the memory limit "
                                "leaves it");
}

static void limits_inflating_stops_at_the_size_promised(void)
{
    size_t n = 1 << 20;
    unsigned char *zeros = calloc(n, 1);
    ByteBuf z = {0}, out = {0};
    char msg[200];

    CHECK(zeros != NULL);
    if (!zeros)
        return;
    CHECK_INT(0, deflate_zlib(&z, zeros, n, DEFLATE_FIXED));
    CHECK(z.len < n / 50); /* a bomb in miniature */
    out.max = 1000;
    CHECK_INT(-1, inflate_zlib(&out, z.data, z.len, msg, sizeof msg));
    CHECK(strcmp(msg, "more data than the image needs") == 0);
    CHECK(out.len <= 1000);
    bytebuf_free(&out);
    out.max = n;
    CHECK_INT(0, inflate_zlib(&out, z.data, z.len, msg, sizeof msg));
    CHECK(out.len == n);
    bytebuf_free(&out);
    bytebuf_free(&z);
    free(zeros);
}

static void limits_image_needs_are_known_per_format(void)
{
    WriterOptions ppm = {FORMAT_PPM, 0, DEFLATE_FIXED, 90, 0, NULL}, pfm = {FORMAT_PFM, 0, DEFLATE_FIXED, 90, 0, NULL},
                  png = {FORMAT_PNG, 0, DEFLATE_FIXED, 90, 0, NULL};
    size_t n = 3 * (size_t)32768 * 32768;

    CHECK(writer_memory(&ppm, 32768, 32768) == n);
    CHECK(writer_memory(&pfm, 32768, 32768) == 5 * n);
    CHECK(writer_memory(&png, 32768, 32768) >= 3 * n);
}

static void limits_inputs_that_are_not_files_are_refused(void)
{
    char *data;
    size_t len;
    Error err;

    CHECK_INT(-1, file_read_all("/dev/zero", &data, &len, &err));
    CHECK_CONTAINS(err.message, "not a regular file");
    CHECK_INT(-1, file_read_all("tests", &data, &len, &err));
    CHECK_CONTAINS(err.message, "it is a directory");
}

const TestCase scene_limits_tests[] = {
    {"limits_sizes_read_for_people", limits_sizes_read_for_people},
    {"limits_scene_stops_at_the_element_that_passes",
     limits_scene_stops_at_the_element_that_passes},
    {"limits_spheres_added_at_once_as_one_by_one", limits_spheres_added_at_once_as_one_by_one},
    {"limits_hierarchy_is_estimated_before_it_is_built",
     limits_hierarchy_is_estimated_before_it_is_built},
    {"limits_mesh_reading_keeps_to_its_budget", limits_mesh_reading_keeps_to_its_budget},
    {"limits_inflating_stops_at_the_size_promised", limits_inflating_stops_at_the_size_promised},
    {"limits_image_needs_are_known_per_format", limits_image_needs_are_known_per_format},
    {"limits_inputs_that_are_not_files_are_refused", limits_inputs_that_are_not_files_are_refused},
    {NULL, NULL},
};
