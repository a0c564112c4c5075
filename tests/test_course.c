/* test_course.c: the course-format parser: accepted forms, and every fault
 * with its message, line and column. */
#include <stdio.h>
#include <stdlib.h>
#include <string.h>

#include "base/threads.h"
#include "math/number.h"
#include "rng.h"
#include "scenefile/course.h"
#include "scenefile/load.h"
#include "test.h"

/* A valid header: the screen is 2 x 2 at z = 1, so 4 x 4 pixels. */
#define CAMERA "0 0 0\n"
#define CORNERS "-1 1 1\n1 1 1\n-1 -1 1\n"
#define HEADER CAMERA CORNERS "4\n10 20 30\n0 5 0 255 128 64\n"
#define SPHERE "sphere: 0 0 5 1 200 100 50 0.25\n"

static int parse(const char *text, Scene *scene, Error *err)
{
    return load_scene_text("t.txt", text, strlen(text), SCENE_COURSE, 0, 0, scene, NULL, err);
}

static void parse_accepts_the_example(void)
{
    Scene sc;
    Error err;

    CHECK_INT(0, parse(HEADER SPHERE "sphere: 1 2 3 0.5 0 0 255 1\n", &sc, &err));
    CHECK_NEAR(-1, sc.camera.top_left.x, 0);
    CHECK_NEAR(2, sc.camera.u.x, 0);
    CHECK_NEAR(-2, sc.camera.v.y, 0);
    CHECK_INT(4, sc.camera.width);
    CHECK_INT(4, sc.camera.height);
    CHECK_NEAR(20, sc.background.g, 0);
    CHECK_NEAR(5, sc.lights[0].position.y, 0);
    CHECK_NEAR(64, sc.lights[0].colour.b, 0);
    CHECK_INT(2, (long long)scene_count_of(&sc, SHAPE_SPHERE));
    CHECK_NEAR(5, scene_spheres(&sc)[0].centre.z, 0);
    CHECK_NEAR(1, scene_spheres(&sc)[0].radius, 0);
    CHECK_NEAR(100, scene_material(&sc, SHAPE_SPHERE, 0).colour.g, 0);
    CHECK_NEAR(0.25, scene_material(&sc, SHAPE_SPHERE, 0).reflection, 0);
    CHECK_INT(0, scene_spheres(&sc)[0].order);
    CHECK_INT(1, scene_spheres(&sc)[1].order);
    CHECK_NEAR(1, scene_material(&sc, SHAPE_SPHERE, 1).reflection, 0);
    scene_free(&sc);
}

/* A sphere holds a material of whole colour channels itself; any other
 * colour (a fraction, -0, a glass) is kept whole in the scene's table:
 * every material reads back to the bit. */
static void parse_sphere_materials_read_back_exactly(void)
{
    static const double want[5][3] = {
        {200, 100, 50}, {200.5, 0.1, 255}, {-0.0, 0, 0}, {254.99999999999997, 1, 2}, {7, 8, 9}};
    Scene sc;
    Error err;

    CHECK_INT(0, parse(HEADER "sphere: 0 0 5 1 200 100 50 0.25\n"
                              "sphere: 0 0 6 1 200.5 0.1 255 0\n"
                              "sphere: 0 0 7 1 -0 0 0 0\n"
                              "sphere: 0 0 8 1 254.99999999999997 1 2 0.5\n"
                              "sphere: 0 0 9 1 7 8 9 0.5 0.25 1.5\n",
                       &sc, &err));
    CHECK_INT(5, (long long)scene_count_of(&sc, SHAPE_SPHERE));
    for (size_t i = 0; i < scene_count_of(&sc, SHAPE_SPHERE) && i < 5; i++) {
        Material m = scene_material(&sc, SHAPE_SPHERE, i);
        CHECK(memcmp(&m.colour.r, &want[i][0], sizeof want[i][0]) == 0);
        CHECK(memcmp(&m.colour.g, &want[i][1], sizeof want[i][1]) == 0);
        CHECK(memcmp(&m.colour.b, &want[i][2], sizeof want[i][2]) == 0);
        CHECK_INT(i == 0 ? -1 : (long long)i - 1, sphere_material_index(&scene_spheres(&sc)[i]));
    }
    CHECK_NEAR(0.25, scene_material(&sc, SHAPE_SPHERE, 4).transparency, 0);
    CHECK_NEAR(1.5, scene_material(&sc, SHAPE_SPHERE, 4).ior, 0);
    scene_free(&sc);
}

/* Spheres in a row of the same material that is not plain share its entry
 * in the scene's table (a field of one glass); an edit, such as a
 * texture: record's, gives the sphere a copy of its own first. */
static void parse_spheres_share_a_material_until_one_changes(void)
{
    Scene sc;
    Error err;
    Material *m;
    int rc = 0;

    CHECK_INT(0, parse(HEADER "sphere: 0 0 5 1 200 100 50 0.25 0.5 1.5\n"
                              "sphere: 0 0 6 1 200 100 50 0.25 0.5 1.5\n"
                              "sphere: 0 0 7 1 200 100 50 0.25 0.5 1.5\n"
                              "sphere: 0 0 8 1 200 100 50 0.25 0.5 1.25\n",
                       &sc, &err));
    CHECK_INT(2, (long long)sc.material_count);
    CHECK_INT(0, sphere_material_index(&scene_spheres(&sc)[0]));
    CHECK_INT(0, sphere_material_index(&scene_spheres(&sc)[2]));
    CHECK_INT(1, sphere_material_index(&scene_spheres(&sc)[3]));
    m = scene_material_edit(&sc, SHAPE_SPHERE, 1, &rc);
    CHECK(m != NULL);
    if (m)
        m->texture = 0;
    CHECK_INT(-1, scene_material(&sc, SHAPE_SPHERE, 0).texture);
    CHECK_INT(0, scene_material(&sc, SHAPE_SPHERE, 1).texture);
    CHECK_INT(-1, scene_material(&sc, SHAPE_SPHERE, 2).texture);
    CHECK_NEAR(0.5, scene_material(&sc, SHAPE_SPHERE, 1).transparency, 0);
    CHECK_NEAR(1.5, scene_material(&sc, SHAPE_SPHERE, 1).ior, 0);
    scene_free(&sc);
}

static void parse_accepts_comments_blanks_crlf_tabs_bom(void)
{
    const char *text = "\xEF\xBB\xBF# a scene\r\n\r\n  0\t0 0   # camera\r\n-1 1 1#tl\r\n"
                       "1 1 1\r\n-1 -1 1\r\n\r\n4\r\n10 20 30\r\n0 5 0 255 128 64\r\n"
                       "sphere:0 0 5 1 200 100 50 0.25\r\n# end";
    Scene sc;
    Error err;

    CHECK_INT(0, parse(text, &sc, &err));
    CHECK_INT(1, (long long)scene_count_of(&sc, SHAPE_SPHERE));
    CHECK_NEAR(0.25, scene_material(&sc, SHAPE_SPHERE, 0).reflection, 0);
    CHECK_INT(0, scene_spheres(&sc)[0].order);
    scene_free(&sc);
}

static void parse_accepts_number_forms(void)
{
    Scene sc;
    Error err;

    CHECK_INT(0, parse("1. .5 -.5e+1\n-1 1E1 +1\n1 1e1 1\n-1 -1 1\n4\n0 0 0\n1e15 -1e15 "
                       "0e-999 0 -0 255\n",
                       &sc, &err));
    CHECK_NEAR(1, sc.camera.eye.x, 0);
    CHECK_NEAR(0.5, sc.camera.eye.y, 0);
    CHECK_NEAR(-5, sc.camera.eye.z, 0);
    CHECK_NEAR(1e15, sc.lights[0].position.x, 0);
    CHECK_NEAR(0, sc.lights[0].position.z, 0);
    CHECK_NEAR(0.1, strtod("0.1", NULL), 0); /* correctly rounded, as strtod */
    scene_free(&sc);
}

/* number_parse() gives strtod()'s bits on 200,000 random spellings: 1 to
 * 20 digits with the point anywhere or nowhere, leading and trailing zeros,
 * signs and exponents, around the fast path's limits (15 digits, 10^±22). */
static void parse_numbers_round_as_strtod(void)
{
    int differ = 0, parsed = 0;

    for (int i = 0; i < 200000; i++) {
        char buf[64];
        size_t n = rng_decimal(buf, 20, 0.3, 0.2);
        double a, b;

        if (rng_uniform() < 0.4)
            n += (size_t)sprintf(buf + n, "e%d", (int)(rng_uniform() * 60) - 30);
        buf[n] = '\0';
        if (buf[n - 1] == '.' && (n == 1 || buf[n - 2] < '0' || buf[n - 2] > '9'))
            continue; /* "." or "-.": not numbers */
        if (number_parse(buf, n, &a) != NUMBER_OK)
            continue; /* out of range: the checks below cover those */
        b = strtod(buf, NULL);
        parsed++;
        if (memcmp(&a, &b, sizeof a) != 0) {
            if (differ++ < 5)
                printf("    %s: %.17g, strtod %.17g\n", buf, a, b);
        }
    }
    CHECK(parsed > 150000);
    CHECK_INT(0, differ);
}

/* Long runs of zeros move the decimal exponent far from the one written:
 * 0.(999 zeros)1e1000 is 1, and with e100000 it is far out of range (the
 * written exponent is clamped while it is read). */
static void parse_numbers_with_long_zero_runs(void)
{
    char buf[1100];
    double v = 0;
    int n;

    n = sprintf(buf, "0.%0999d1e1000", 0);
    CHECK_INT(NUMBER_OK, number_parse(buf, (size_t)n, &v));
    CHECK_NEAR(1, v, 0);
    n = sprintf(buf, "0.%0999d1e100000", 0);
    CHECK_INT(NUMBER_TOO_LARGE, number_parse(buf, (size_t)n, &v));
    n = sprintf(buf, "1%040de-40", 0);
    CHECK_INT(NUMBER_OK, number_parse(buf, (size_t)n, &v));
    CHECK_NEAR(1, v, 0);
    n = sprintf(buf, "0.%040d1e1", 0); /* 10^-40: strtod()'s bits */
    CHECK_INT(NUMBER_OK, number_parse(buf, (size_t)n, &v));
    CHECK(v == strtod(buf, NULL));
}

static void parse_accepts_many_spheres(void)
{
    size_t n = 5000, cap = sizeof HEADER + n * 40;
    char *text = malloc(cap);
    size_t len = (size_t)sprintf(text, "%s", HEADER);
    Scene sc;
    Error err;

    for (size_t i = 0; i < n; i++)
        len += (size_t)sprintf(text + len, "sphere: %zu 0 9 0.5 1 2 3 0\n", i);
    CHECK_INT(0, load_scene_text("t.txt", text, len, SCENE_COURSE, 0, 0, &sc, NULL, &err));
    CHECK_INT((long long)n, (long long)scene_count_of(&sc, SHAPE_SPHERE));
    CHECK_NEAR(4999, scene_spheres(&sc)[4999].centre.x, 0);
    scene_free(&sc);
    free(text);
}

enum { BIG_ROOM = 3 << 20 }; /* bytes of a big_course() and then some */

/* Writes into text (room for BIG_ROOM bytes) a course scene of more than
 * 1 MiB, large enough to be read on every thread: the header, then n
 * sphere: records of plain materials in every accepted form (comments,
 * blank lines, tabs, CRLF, transparency 0 and index 1, exponents, numbers
 * at the bounds of number_scan_plain()'s form), which every thread reads;
 * returns its length. */
static size_t big_course(char *text, int n)
{
    size_t cap = BIG_ROOM, len = (size_t)snprintf(text, cap, "%s", HEADER);

    for (int i = 0; i < n && len < cap; i++) {
        const char *form[] = {"sphere: %d.25 -%d 9e1 0.5 1 2 3 0.125\n",
                              "  sphere:\t%d 1E-3 %d 1 255 0 7 0 0 1\r\n",
                              "sphere: %d 1 %d 2 3 4 5 1 # a comment\n\n",
                              "# only a comment\n\t \nsphere: -%d 2 +%d .5 0 0 0 0.0\n",
                              "sphere:%d -.%d 123456789012.345 .5 255. 007 +1 1.\t# c\r\n"};
        len += (size_t)snprintf(text + len, cap - len, form[i % 5], i, i % 977);
    }
    return len;
}

/* Says whether the spheres of scenes a and b are alike, field by field. */
static int same_spheres(const Scene *a, const Scene *b)
{
    if (scene_count_of(a, SHAPE_SPHERE) != scene_count_of(b, SHAPE_SPHERE) ||
        a->shapes[SHAPE_SPHERE].capacity != b->shapes[SHAPE_SPHERE].capacity ||
        a->has_transparency != b->has_transparency)
        return 0;
    for (size_t i = 0; i < scene_count_of(a, SHAPE_SPHERE); i++) {
        const Sphere *x = &scene_spheres(a)[i], *y = &scene_spheres(b)[i];
        Material mx = scene_material(a, SHAPE_SPHERE, i), my = scene_material(b, SHAPE_SPHERE, i);
        if (memcmp(&x->centre, &y->centre, sizeof x->centre) != 0 || x->radius != y->radius ||
            memcmp(&mx.colour, &my.colour, sizeof mx.colour) != 0 ||
            mx.reflection != my.reflection || mx.transparency != my.transparency ||
            mx.ior != my.ior || x->order != y->order)
            return 0;
    }
    return 1;
}

/* Parses text on the given threads under memory_limit (0: none). */
static int parse_on(int threads, const char *text, size_t len, size_t memory_limit,
                    Scene *scene, Error *err)
{
    threads_use(threads);
    return load_scene_text("big.txt", text, len, SCENE_COURSE, memory_limit, 0, scene, NULL, err);
}

/* Parses text with a light: record after it, into odd (room for len + 64
 * bytes): a record other than a sphere, so the serial reading, line by
 * line through the lexer. */
static int parse_serially(const char *text, size_t len, char *odd, Scene *scene, Error *err)
{
    static const char light[] = "light: 1 2 3 4 5 6\n";

    memcpy(odd, text, len);
    memcpy(odd + len, light, sizeof light - 1);
    return parse_on(2, odd, len + sizeof light - 1, 0, scene, err);
}

/* A large scene of spheres is read alike on one thread and on two, and as
 * the serial reading reads it: the same spheres, room and flags, or the
 * same fault at the same place (the first in the file), also when the
 * memory limit stops it or when a record other than a sphere of a plain
 * material sends the reading back to the serial one. */
static void parse_reads_alike_on_every_thread(void)
{
    static char text[BIG_ROOM], odd[BIG_ROOM + 64];
    size_t len = big_course(text, 40000);
    int before = threads_count();
    Scene one, two, serial;
    Error e1, e2;

    CHECK(len > 1 << 20 && len < BIG_ROOM - 1);
    CHECK_INT(0, parse_on(1, text, len, 0, &one, &e1));
    CHECK_INT(0, parse_on(2, text, len, 0, &two, &e2));
    CHECK_INT(0, parse_serially(text, len, odd, &serial, &e1));
    CHECK_INT(40000, (long long)scene_count_of(&one, SHAPE_SPHERE));
    CHECK_INT(2, (long long)serial.light_count);
    CHECK(!one.has_transparency);
    CHECK(same_spheres(&one, &two));
    CHECK(same_spheres(&serial, &one));
    scene_free(&serial);
    /* The memory limit: the serial reading's room just fits, or not. */
    {
        size_t need = scene_memory(&one);
        Scene sc;
        CHECK_INT(0, parse_on(2, text, len, need, &sc, &e2));
        CHECK(same_spheres(&one, &sc));
        scene_free(&sc);
        CHECK_INT(-1, parse_on(1, text, len, need - 1, &sc, &e1));
        CHECK_INT(-1, parse_on(2, text, len, need - 1, &sc, &e2));
        CHECK_ERROR("memory limit", &e2, e1.line, e1.column, e1.message);
    }
    /* A fault early, in the middle, near the end and at the very end: a bad
     * number, an unknown record, a reflection out of range, a NUL byte, a
     * carriage return inside a line; and records that are right but not
     * spheres of plain materials (a plane, a light, a glass sphere), read
     * alike. */
    {
        static const char *const lines[] = {"sphere: 1 2 x 1 1 2 3 0", "spheres: 1 2 3 1 1 2 3 0",
                                            "sphere: 1 2 3 1 1 2 3 1.5", "sphere: 1 2 3\0 1 1 2 3 0",
                                            "sphere: 1 2 3 1\r 1 2 3 0", "plane: 0 -1 0 0 1 0 9 9 9 0",
                                            "light: 1 2 3 4 5 6",
                                            "sphere: 1 2 3 1 1 2 3 0 0.5 1.5"};
        size_t at[] = {len / 50, len / 2, len - len / 40, len};
        for (int k = 0; k < 8; k++) {
            size_t cut = at[k % 4], n, extra = strlen(lines[k]) + (k == 3);
            Scene s1, s2;
            int r1, r2;
            while (cut > 0 && text[cut - 1] != '\n')
                cut--;
            memcpy(odd, text, cut);
            memcpy(odd + cut, lines[k], extra);
            n = cut + extra;
            odd[n++] = '\n';
            memcpy(odd + n, text + cut, len - cut);
            n += len - cut;
            r1 = parse_on(1, odd, n, 0, &s1, &e1);
            r2 = parse_on(2, odd, n, 0, &s2, &e2);
            CHECK_INT(k < 5 ? -1 : 0, r1);
            CHECK_INT(r1, r2);
            if (r1 != 0 && r2 != 0) {
                CHECK_ERROR(lines[k], &e2, e1.line, e1.column, e1.message);
            } else if (r1 == 0 && r2 == 0) {
                CHECK(same_spheres(&s1, &s2));
                CHECK_INT((long long)scene_count_of(&s1, SHAPE_PLANE),
                          (long long)scene_count_of(&s2, SHAPE_PLANE));
                CHECK_INT((long long)s1.light_count, (long long)s2.light_count);
                CHECK_INT(k == 5, (long long)scene_count_of(&s2, SHAPE_PLANE));
                CHECK_INT(1 + (k == 6), (long long)s2.light_count);
                CHECK_INT(k == 7, s2.has_transparency);
                scene_free(&s1);
                scene_free(&s2);
            }
        }
    }
    threads_use(before);
    scene_free(&one);
    scene_free(&two);
}

/* Random edits of a large field (a few bytes replaced by bytes that matter
 * to lines, comments, records and numbers) are read alike on one thread and
 * on two: both succeed with the same spheres and other objects, or fail
 * with the same message at the same place. */
static void parse_reads_random_edits_alike(void)
{
    static const char bytes[] = {'\n', '\r', '\0', '#', ':', ' ', '\t', 'e', '-', '.', '1',
                                 'x', 's', '\xEF', '\xBB', '\xBF'};
    static const char *const words[] = {"sphere:", "plane: 0 1 0 0 1 0 1 2 3 0", "texture:",
                                        "\r\n", "\n\n#", "ambient: 1 2 3", "1e999"};
    static char text[BIG_ROOM], odd[BIG_ROOM + 64];
    size_t len = big_course(text, 36000);
    int before = threads_count(), fails = 0;

    CHECK(len > 1 << 20);
    for (int round = 0; round < 24; round++) {
        size_t n = len;
        Scene s1, s2;
        Error e1, e2;
        int r1, r2;
        memcpy(odd, text, len);
        /* One to three edits past the header, each a byte or a word. */
        for (int k = 0, edits = 1 + round % 3; k < edits; k++) {
            size_t at = 200 + (size_t)(rng_uniform() * (double)(n - 260));
            if (rng_uniform() < 0.5) {
                odd[at] = bytes[(int)(rng_uniform() * sizeof bytes)];
            } else {
                const char *w = words[(int)(rng_uniform() * 7)];
                size_t wl = strlen(w);
                memcpy(odd + at, w, wl); /* over what was there */
            }
        }
        r1 = parse_on(1, odd, n, 0, &s1, &e1);
        r2 = parse_on(2, odd, n, 0, &s2, &e2);
        CHECK_INT(r1, r2);
        if (r1 != 0 && r2 != 0) {
            fails++;
            CHECK_ERROR("a random edit", &e2, e1.line, e1.column, e1.message);
        } else if (r1 == 0 && r2 == 0) {
            CHECK(same_spheres(&s1, &s2));
            CHECK_INT((long long)scene_count_of(&s1, SHAPE_PLANE),
                      (long long)scene_count_of(&s2, SHAPE_PLANE));
            CHECK_INT((long long)s1.texture_count, (long long)s2.texture_count);
            CHECK(s1.has_ambient == s2.has_ambient);
            scene_free(&s1);
            scene_free(&s2);
        }
    }
    /* Most edits break a record; some must not, or this tests one path. */
    CHECK(fails > 0 && fails < 24);
    threads_use(before);
}

/* Returns the image height of the screen with the given corners at width
 * W, or -1 if the scene does not parse. */
static int height_of(const char *corners, const char *width)
{
    char text[300];
    Scene sc;
    Error err;
    int h;

    snprintf(text, sizeof text, CAMERA "%s%s\n0 0 0\n0 0 0 1 1 1\n", corners, width);
    if (parse(text, &sc, &err) != 0)
        return -1;
    h = sc.camera.height;
    scene_free(&sc);
    return h;
}

static void parse_height_follows_the_screen(void)
{
    /* |v| / |u| = 1 / 3 at width 4: 4 / 3 + 0.5 rounds down to 1.83 -> 1. */
    CHECK_INT(1, height_of("0 0 1\n3 0 1\n0 -1 1\n", "4"));
    /* Half-way rounds up: 3 * 1 / 2 + 0.5 = 2. */
    CHECK_INT(2, height_of("0 0 1\n2 0 1\n0 -1 1\n", "3"));
    /* A sheared screen: |v| = sqrt(2) with the left edge slanted 45 degrees. */
    CHECK_INT(141, height_of("0 0 1\n1 0 1\n1 -1 1\n", "100"));
    /* A tiny height still gives one row. */
    CHECK_INT(1, height_of("0 0 1\n1 0 1\n0 -1e-9 1\n", "100"));
    /* A screen 1e-200 across keeps its proportions (no underflow). */
    CHECK_INT(50, height_of("0 0 1e-200\n2e-200 0 1e-200\n0 -1e-200 1e-200\n", "100"));
}

/* One malformed scene and the error it must produce. */
typedef struct {
    const char *text;
    int line, column;
    const char *message; /* the whole message */
} BadScene;

static const BadScene parse_bad_scenes[] = {
    /* missing records */
    {"", 1, 1, "expected the camera position (3 numbers), found the end of the file"},
    {"# nothing\n\n", 3, 1, "expected the camera position (3 numbers), found the end of the file"},
    {CAMERA CORNERS "4\n10 20 30", 6, 9,
     "expected the light (x y z r g b), found the end of the file"},
    {CAMERA CORNERS "4\n", 6, 1,
     "expected the background colour (3 numbers), found the end of the file"},
    {CAMERA "-1 1 1\n", 3, 1,
     "expected the screen's top-right corner (3 numbers), found the end of the file"},
    {CAMERA CORNERS, 5, 1,
     "expected the horizontal resolution (a whole number of pixels), found the end of the "
     "file"},
    {CAMERA CORNERS "4\n10 20 30\n" SPHERE, 7, 1,
     "expected the light, found the record 'sphere:': the 7 header records (camera, three "
     "screen corners, resolution, background, light) come first"},
    /* counts */
    {"0 0\n", 1, 4, "expected 3 numbers for the camera position, found 2"},
    {"0 0 0 0\n", 1, 7, "expected 3 numbers for the camera position, found 4"},
    {"0 0 0 x\n", 1, 7, "expected the end of the line after the camera position, found 'x'"},
    {CAMERA "90 110 # top-left\n", 2, 7,
     "expected 3 numbers for the screen's top-left corner, found 2"},
    {CAMERA CORNERS "4 4\n", 5, 3, "expected 1 number for the horizontal resolution, found 2"},
    {CAMERA CORNERS "4\n10 20\n", 6, 6, "expected 3 numbers for the background colour, found 2"},
    {CAMERA CORNERS "4\n10 20 30\n0 5 0 255 128\n", 7, 14,
     "expected 6 numbers for the light (x y z r g b), found 5"},
    {HEADER "sphere: 0 0 5 1 200 100 50\n", 8, 27,
     "expected 8 or 10 numbers for the sphere (cx cy cz radius r g b reflection [transparency "
     "index]), found 7"},
    {HEADER "sphere: 0 0 5 1 200 100 50 0 1\n", 8, 30,
     "expected 8 or 10 numbers for the sphere (cx cy cz radius r g b reflection [transparency "
     "index]), found 9"},
    {HEADER "sphere:\n", 8, 8,
     "expected 8 or 10 numbers for the sphere (cx cy cz radius r g b reflection [transparency "
     "index]), found 0"},
    /* numbers */
    {"0 x 0\n", 1, 3, "expected a number for the camera position's y, found 'x'"},
    {"0 0 1,5\n", 1, 5, "expected a number for the camera position's z, found '1,5'"},
    {"0 0 1e\n", 1, 5, "expected a number for the camera position's z, found '1e'"},
    {"0 0 .\n", 1, 5, "expected a number for the camera position's z, found '.'"},
    {"0 0 +-1\n", 1, 5, "expected a number for the camera position's z, found '+-1'"},
    {"0 0 inf\n", 1, 5, "the camera position's z must be a finite number, found 'inf'"},
    {"-Infinity 0 0\n", 1, 1, "the camera position's x must be a finite number, found '-Infinity'"},
    {"NaN 0 0\n", 1, 1, "the camera position's x must be a finite number, found 'NaN'"},
    {"0 nan(0x1) 0\n", 1, 3, "the camera position's y must be a finite number, found 'nan(0x1)'"},
    {"0 nano 0\n", 1, 3, "expected a number for the camera position's y, found 'nano'"},
    {"0x10 0 0\n", 1, 1,
     "the camera position's x must be a decimal number, found '0x10' (hexadecimal is not "
     "accepted)"},
    {"1e400 0 0\n", 1, 1,
     "the camera position's x is out of range: '1e400' exceeds 1e15 in magnitude"},
    {"0 -1.000001e15 0\n", 1, 3,
     "the camera position's y is out of range: '-1.000001e15' exceeds 1e15 in magnitude"},
    {"0 0 1e-400\n", 1, 5,
     "the camera position's z is out of range: '1e-400' is too small for a double (write 0 "
     "for zero)"},
    {"0 0 1e-310\n", 1, 5,
     "the camera position's z is out of range: '1e-310' is too small for a double (write 0 "
     "for zero)"},
    /* resolution */
    {CAMERA CORNERS "400.0\n", 5, 1,
     "expected the horizontal resolution as a whole number of pixels (decimal digits only), "
     "found '400.0'"},
    {CAMERA CORNERS "+4\n", 5, 1,
     "expected the horizontal resolution as a whole number of pixels (decimal digits only), "
     "found '+4'"},
    {CAMERA CORNERS "0\n", 5, 1,
     "the horizontal resolution must be between 1 and 32768 pixels, found '0'"},
    {CAMERA CORNERS "32769\n", 5, 1,
     "the horizontal resolution must be between 1 and 32768 pixels, found '32769'"},
    {CAMERA CORNERS "99999999999999999999\n", 5, 1,
     "the horizontal resolution must be between 1 and 32768 pixels, found "
     "'99999999999999999999'"},
    {CAMERA "0 0 1\n0.001 0 1\n0 -2 1\n20\n", 5, 1,
     "the image would be 20 x 40000 pixels: its height, set by the screen's proportions, must "
     "be at most 32768"},
    /* screen */
    {CAMERA "-1 1 1\n-1 1 1\n-1 -1 1\n", 3, 1,
     "the screen's top-right corner is its top-left corner: the screen has no width"},
    {CAMERA "-1 1 1\n1 1 1\n-1 1 1\n", 4, 1,
     "the screen's bottom-left corner is its top-left corner: the screen has no height"},
    {CAMERA "0 0 1\n1 1 1\n3 3 1\n", 4, 1,
     "the screen's top and left edges are parallel: its three corners lie on one line"},
    {CAMERA "0.1 0.2 0.3\n0.2 0.4 0.6\n0.7 1.4 2.1\n", 4, 1,
     "the screen's top and left edges are parallel: its three corners lie on one line"},
    /* ranges */
    {CAMERA CORNERS "4\n10 20 256\n", 6, 7,
     "the background colour's blue must be in [0, 255], found '256'"},
    {CAMERA CORNERS "4\n-1 20 30\n", 6, 1,
     "the background colour's red must be in [0, 255], found '-1'"},
    {CAMERA CORNERS "4\n10 20 30\n0 5 0 255 300 64\n", 7, 11,
     "the light's green must be in [0, 255], found '300'"},
    {HEADER "sphere: 0 0 5 0 200 100 50 0.25\n", 8, 15,
     "the sphere's radius must be greater than 0, found '0'"},
    {HEADER "sphere: 0 0 5 -0 200 100 50 0.25\n", 8, 15,
     "the sphere's radius must be greater than 0, found '-0'"},
    {HEADER "sphere: 0 0 5 1 200 100 50 1.5\n", 8, 28,
     "the sphere's reflection must be in [0, 1], found '1.5'"},
    {HEADER "sphere: 0 0 5 1 200 100 50 -0.1\n", 8, 28,
     "the sphere's reflection must be in [0, 1], found '-0.1'"},
    {HEADER "sphere: 0 0 5 1 255.5 100 50 0\n", 8, 17,
     "the sphere's red must be in [0, 255], found '255.5'"},
    {HEADER "sphere: 0 0 nan 1 2 3 4 0\n", 8, 13,
     "the sphere's centre z must be a finite number, found 'nan'"},
    /* keywords */
    {HEADER "Sphere: 0 0 5 1 200 100 50 0.25\n", 8, 1,
     "unknown record 'Sphere:': keywords are lower case ('sphere:')"},
    {HEADER "SPHERE: 0 0 5 1 200 100 50 0.25\n", 8, 1,
     "unknown record 'SPHERE:': keywords are lower case ('sphere:')"},
    {HEADER "sphere 0 0 5 1 200 100 50 0.25\n", 8, 1,
     "expected 'sphere:' with its colon attached, found 'sphere'"},
    {HEADER "  donut: 0 0 0\n", 8, 3,
     "unknown record 'donut:' (expected 'sphere:', 'plane:', 'triangle:', 'cube:', 'square:', "
     "'cylinder:', 'cone:', 'disk:', 'torus:', 'mesh:', 'light:', 'ambient:', 'samples:', "
     "'lens:' or 'texture:')"},
    {HEADER "torus: 0 0 0 0 1 0 1 1 200 100 50 0\n", 8, 22,
     "the torus's tube radius must be less than its major radius (a ring torus: its hole "
     "open), and at least a ten-thousandth of it"},
    {HEADER "torus: 0 0 0 0 0 0 2 1 200 100 50 0\n", 8, 14,
     "the torus's axis is the zero vector: it must give a direction"},
    {HEADER "Torus: 0 0 0 0 1 0 2 1 200 100 50 0\n", 8, 1,
     "unknown record 'Torus:': keywords are lower case ('torus:')"},
    {HEADER "disk: 0 0 0 0 1 0 -1 200 100 50 0\n", 8, 19,
     "the disk's radius must be greater than 0, found '-1'"},
    {HEADER "disk 0 0 0 0 1 0 1 200 100 50 0\n", 8, 1,
     "expected 'disk:' with its colon attached, found 'disk'"},
    {HEADER "  cube: 0 0 0\n", 8, 14,
     "expected 8 or 10 numbers for the cube (cx cy cz half-edge r g b reflection "
     "[transparency index]), found 3"},
    {HEADER "cone: 0 0 0 1 0 200 100 50 0\n", 8, 15,
     "the cone's height must not be 0: its apex is that far above (or below) the centre of its "
     "circle"},
    {HEADER "square: 0 0 0 0 0 0 1 200 100 50 0\n", 8, 15,
     "the square's normal is the zero vector: it must give a direction"},
    {HEADER "cylinder: 0 0 0 -1 200 100 50 0\n", 8, 17,
     "the cylinder's radius must be greater than 0, found '-1'"},
    {HEADER "Plane: 0 0 0 0 1 0 1 2 3 0\n", 8, 1,
     "unknown record 'Plane:': keywords are lower case ('plane:')"},
    {HEADER "triangle 0 0 0 1 0 0 0 1 0 1 2 3 0\n", 8, 1,
     "expected 'triangle:' with its colon attached, found 'triangle'"},
    /* the bonus records */
    {HEADER "sphere: 0 0 5 1 200 100 50 0.6 0.5 1.5\n", 8, 32,
     "the sphere's reflection plus transparency must be at most 1, found 0.6 + 0.5"},
    {HEADER "sphere: 0 0 5 1 200 100 50 0 0.5 0\n", 8, 34,
     "the sphere's refractive index must be greater than 0, found '0'"},
    {HEADER "sphere: 0 0 5 1 200 100 50 0 1.5 1\n", 8, 30,
     "the sphere's transparency must be in [0, 1], found '1.5'"},
    {HEADER "plane: 0 0 0 0 0 -0 1 2 3 0\n", 8, 14,
     "the plane's normal is the zero vector: it must give a direction"},
    {HEADER "triangle: 0 0 0 1 1 1 2 2 2 1 2 3 0\n", 8, 1,
     "the triangle's three vertices lie on one line: it has no area"},
    {HEADER "triangle: 0 0 0 1 1 1 0 0 0 1 2 3 0\n", 8, 1,
     "the triangle's three vertices lie on one line: it has no area"},
    {HEADER "ambient: 1 2 3\nsphere: 0 0 5 1 200 100 50 0\nambient: 1 2 3\n", 10, 1,
     "the ambient light is already set, on line 8"},
    {HEADER "ambient: 1 2 300\n", 8, 14, "the ambient light's blue must be in [0, 255], found '300'"},
    {HEADER "samples: 0\n", 8, 10,
     "the number of samples per pixel must be between 1 and 65536 samples, found '0'"},
    {HEADER "samples: 65537\n", 8, 10,
     "the number of samples per pixel must be between 1 and 65536 samples, found '65537'"},
    {HEADER "samples: 2.5\n", 8, 10,
     "expected the number of samples per pixel as a whole number of samples (decimal digits "
     "only), found '2.5'"},
    {HEADER "samples:\n", 8, 9, "expected 1 number for the samples per pixel, found 0"},
    {HEADER "samples: 4 4\n", 8, 12, "expected 1 number for the samples per pixel, found 2"},
    {HEADER "samples: 4\nsamples: 4\n", 9, 1,
     "the number of samples per pixel is already set, on line 8"},
    {HEADER "lens: -1 5\n", 8, 7, "the lens's aperture must be at least 0, found '-1'"},
    {HEADER "lens: 1 0\n", 8, 9, "the lens's focal distance must be greater than 0, found '0'"},
    {HEADER "lens: 1 5\nlens: 1 5\n", 9, 1, "the lens is already set, on line 8"},
    {"0 0 1\n-1 1 1\n1 1 1\n-1 -1 1\n4\n0 0 0\n0 5 0 1 1 1\nlens: 1 5\n", 8, 1,
     "the camera lies in the plane of its screen: a lens needs the screen in front of the "
     "camera"},
    {HEADER "light: 1 2 3 4 5\n", 8, 17,
     "expected 6 numbers for the light (x y z r g b), found 5"},
    {HEADER SPHERE "1 2 3\n", 9, 1,
     "expected a record such as 'sphere:', found the number '1': the 7 header records are "
     "complete"},
    {"camera: 0 0 0\n", 1, 1,
     "expected the camera position, found the record 'camera:': the 7 header records (camera, "
     "three screen corners, resolution, background, light) come first"},
    /* bytes */
    {"0 0\r0\n", 1, 4, "carriage return inside a line: lines must end with LF or CRLF"},
    {"0 0 0\n# \x01\x02 fine\n-1 1 1\n1 1\x00 1\n", 4, 4,
     "NUL byte in the scene file: a scene is a text file"},
    /* User bytes are shown safely: invalid UTF-8 and control bytes as \xNN,
     * valid UTF-8 as it is. */
    {"0 0 \xff\xfe\n", 1, 5,
     "expected a number for the camera position's z, found '\\xFF\\xFE'"},
    {"0 0 \x1b[31m\n", 1, 5,
     "expected a number for the camera position's z, found '\\x1B[31m'"},
    {"0 0 z\xc3\xa9ro\n", 1, 5,
     "expected a number for the camera position's z, found 'z\xc3\xa9ro'"},
    {"0 0 \xc3\n", 1, 5, "expected a number for the camera position's z, found '\\xC3'"},
    {"0 0 \xed\xa0\x80\n", 1, 5,
     "expected a number for the camera position's z, found '\\xED\\xA0\\x80'"},
};

static void parse_rejects_bad_scenes_with_position(void)
{
    for (size_t i = 0; i < sizeof parse_bad_scenes / sizeof parse_bad_scenes[0]; i++) {
        const BadScene *b = &parse_bad_scenes[i];
        /* NUL bytes inside: the length is that of the literal, known by scanning for "\n\0". */
        size_t len = strlen(b->text);
        Scene sc;
        Error err;
        int rc;

        if (strstr(b->message, "NUL byte"))
            len += 1 + strlen(b->text + len + 1);
        rc = load_scene_text("t.txt", b->text, len, SCENE_COURSE, 0, 0, &sc, NULL, &err);
        CHECK_INT(-1, rc);
        if (rc != -1) {
            scene_free(&sc);
            continue;
        }
        CHECK_INT(0, (long long)scene_count_of(&sc, SHAPE_SPHERE));
        CHECK_CONTAINS(err.file, "t.txt");
        CHECK_ERROR(b->text, &err, b->line, b->column, b->message);
    }
}

/* The records of a valid scene, and how the parser names them. */
static const struct {
    const char *text;   /* the record's line, valid */
    const char *what;   /* its name in messages */
    const char *syntax; /* the hint in count messages, "" if none */
    const char *counts; /* the counts accepted, as messages say them */
    const char *first;  /* the name of its first number */
    int numbers;        /* numbers in it */
    int first_column;   /* column of its first number */
} parse_records[] = {
    {"0 0 0", "the camera position", "", "3", "x", 3, 1},
    {"-1 1 1", "the screen's top-left corner", "", "3", "x", 3, 1},
    {"1 1 1", "the screen's top-right corner", "", "3", "x", 3, 1},
    {"-1 -1 1", "the screen's bottom-left corner", "", "3", "x", 3, 1},
    {"4", "the horizontal resolution", "", "1", "", 1, 1},
    {"10 20 30", "the background colour", "", "3", "red", 3, 1},
    {"0 5 0 255 128 64", "the light", " (x y z r g b)", "6", "x", 6, 1},
    {"sphere: 0 0 5 1 200 100 50 0.25", "the sphere",
     " (cx cy cz radius r g b reflection [transparency index])", "8 or 10", "centre x", 8, 9},
    {"plane: 0 -1 0 0 1 0 100 100 100 0", "the plane",
     " (px py pz nx ny nz r g b reflection [transparency index])", "10 or 12", "point x", 10, 8},
    {"triangle: -1 0 4 1 0 4 0 1 4 255 0 0 0.5", "the triangle",
     " (x0 y0 z0 x1 y1 z1 x2 y2 z2 r g b reflection [transparency index])", "13 or 15", "x0",
     13, 11},
    {"light: 5 5 0 255 255 255", "the light", " (x y z r g b)", "6", "x", 6, 8},
    {"ambient: 20 20 20", "the ambient light", " (r g b)", "3", "red", 3, 10},
    {"lens: 0.5 10", "the lens", " (aperture focal_distance)", "2", "aperture", 2, 7},
};
enum { PARSE_RECORDS = sizeof parse_records / sizeof parse_records[0] };

/* Builds a scene of all records with record k's line replaced by line (or,
 * when line is NULL, with the file cut just before record k). */
static void parse_scene_with(char *buf, size_t size, int k, const char *line)
{
    size_t n = 0;
    buf[0] = '\0';
    for (int i = 0; i < PARSE_RECORDS && !(i == k && !line); i++)
        n += (size_t)snprintf(buf + n, size - n, "%s\n", i == k ? line : parse_records[i].text);
}

/* Parses text, expecting the fault `message` at line:column. */
static void parse_expect_fault(const char *text, int line, int column, const char *message)
{
    Scene sc;
    Error err;

    if (parse(text, &sc, &err) != -1) {
        test_fail(__FILE__, __LINE__, "accepted: %s", text);
        scene_free(&sc);
        return;
    }
    CHECK_ERROR(text, &err, line, column, message);
}

static void parse_every_record_rejects_each_fault(void)
{
    for (int k = 0; k < PARSE_RECORDS; k++) {
        char line[200], text[600], msg[300];
        const char *t = parse_records[k].text, *what = parse_records[k].what;
        int col = parse_records[k].first_column, n = parse_records[k].numbers;
        const char *rest = strchr(t + col - 1, ' '); /* after the first number */

        if (n == 1)
            continue; /* the resolution has its own cases above */
        /* one number missing: the caret is just past the line */
        snprintf(line, sizeof line, "%.*s", (int)(strrchr(t, ' ') - t), t);
        parse_scene_with(text, sizeof text, k, line);
        snprintf(msg, sizeof msg, "expected %s numbers for %s%s, found %d",
                 parse_records[k].counts, what, parse_records[k].syntax, n - 1);
        parse_expect_fault(text, k + 1, (int)strlen(line) + 1, msg);
        /* one number too many: the caret is on it */
        snprintf(line, sizeof line, "%s 7", t);
        parse_scene_with(text, sizeof text, k, line);
        snprintf(msg, sizeof msg, "expected %s numbers for %s%s, found %d",
                 parse_records[k].counts, what, parse_records[k].syntax, n + 1);
        parse_expect_fault(text, k + 1, (int)strlen(t) + 2, msg);
        /* the first number replaced by a word, infinity, a value too large */
        snprintf(line, sizeof line, "%.*sabc%s", col - 1, t, rest);
        parse_scene_with(text, sizeof text, k, line);
        snprintf(msg, sizeof msg, "expected a number for %s's %s, found 'abc'", what,
                 parse_records[k].first);
        parse_expect_fault(text, k + 1, col, msg);
        snprintf(line, sizeof line, "%.*s-inf%s", col - 1, t, rest);
        parse_scene_with(text, sizeof text, k, line);
        snprintf(msg, sizeof msg, "%s's %s must be a finite number, found '-inf'", what,
                 parse_records[k].first);
        parse_expect_fault(text, k + 1, col, msg);
        snprintf(line, sizeof line, "%.*s2e15%s", col - 1, t, rest);
        parse_scene_with(text, sizeof text, k, line);
        snprintf(msg, sizeof msg, "%s's %s is out of range: '2e15' exceeds 1e15 in magnitude",
                 what, parse_records[k].first);
        parse_expect_fault(text, k + 1, col, msg);
        /* the file ends before a header record (the rest are optional) */
        if (k < 7) {
            parse_scene_with(text, sizeof text, k, NULL);
            snprintf(msg, sizeof msg, "expected %s%s, found the end of the file", what,
                     *parse_records[k].syntax ? parse_records[k].syntax : " (3 numbers)");
            parse_expect_fault(text, k + 1, 1, msg);
        }
    }
}

static void parse_error_excerpt_and_caret(void)
{
    Scene sc;
    Error err;

    CHECK_INT(-1, parse(CAMERA "90\t110 # top-left\n", &sc, &err));
    CHECK_CONTAINS(err.excerpt, "90\t110 # top-left");
    CHECK_INT(6, err.caret);
    /* A long line is cut to a window around the column. */
    {
        char text[2000];
        memset(text, ' ', sizeof text);
        memcpy(text + 1500, "0 0 x\n", 6);
        CHECK_INT(-1, load_scene_text("t.txt", text, 1506, SCENE_COURSE, 0, 0, &sc, NULL, &err));
        CHECK_INT(1505, err.column);
        CHECK(strlen(err.excerpt) < 180);
        CHECK_INT('x', err.excerpt[err.caret]);
    }
    /* Control bytes in the line are escaped and the caret follows. */
    CHECK_INT(-1, parse(CAMERA "90\x01\x02 x\n", &sc, &err));
    CHECK_CONTAINS(err.excerpt, "90\\x01\\x02 x");
    CHECK_INT('9', err.excerpt[err.caret]);
    /* A long line of accented letters is cut between characters. */
    {
        char text[1000];
        size_t n = 7;
        memcpy(text, "0 0 x #", 7);
        while (n < 600) {
            text[n++] = (char)0xc3;
            text[n++] = (char)0xa9;
        }
        text[n++] = '\n';
        CHECK_INT(-1, load_scene_text("t.txt", text, n, SCENE_COURSE, 0, 0, &sc, NULL, &err));
        CHECK(strstr(err.excerpt, "\\x") == NULL);
        CHECK_INT('x', err.excerpt[err.caret]);
    }
}

/* error_escape(): what it keeps and what it writes as \xNN. */
static void error_escape_keeps_utf8_and_escapes_the_rest(void)
{
    char out[64];
    size_t used;

    error_escape(out, sizeof out, "caf\xc3\xa9 \xe2\x82\xac \xf0\x9f\x98\x80", 14, 0, NULL);
    CHECK(strcmp(out, "caf\xc3\xa9 \xe2\x82\xac \xf0\x9f\x98\x80") == 0);
    error_escape(out, sizeof out, "a\tb\x7f" "\0" "c", 6, 0, NULL);
    CHECK(strcmp(out, "a\\x09b\\x7F\\x00c") == 0);
    error_escape(out, sizeof out, "a\tb", 3, 1, NULL);
    CHECK(strcmp(out, "a\tb") == 0);
    /* Overlong, surrogate, beyond U+10FFFF, a lone continuation. */
    error_escape(out, sizeof out, "\xc0\xaf\xed\xa0\x80\xf4\x90\x80\x80\x80", 10, 0, NULL);
    CHECK(strcmp(out, "\\xC0\\xAF\\xED\\xA0\\x80\\xF4\\x90\\x80\\x80\\x80") == 0);
    /* Short room: cut on a whole character or escape, never inside one. */
    CHECK_INT(4, (long long)error_escape(out, 6, "\x01\xc3\xa9", 3, 0, &used));
    CHECK_INT(1, (long long)used);
    CHECK_INT(2, (long long)error_escape(out, 4, "ab\xc3\xa9", 4, 0, &used));
    CHECK_INT(2, (long long)used);
}

static void parse_file_errors(void)
{
    Scene sc;
    Error err;

    CHECK_INT(-1, load_scene_file("tests/no-such-file.txt", SCENE_AUTO, 0, 0, &sc, NULL, &err));
    CHECK_CONTAINS(err.file, "tests/no-such-file.txt");
    CHECK_CONTAINS(err.message, "cannot open");
    CHECK_INT(0, err.line);
    CHECK_INT(-1, load_scene_file("tests", SCENE_AUTO, 0, 0, &sc, NULL, &err));
    CHECK_CONTAINS(err.message, "cannot read");
    CHECK_INT(0, load_scene_file("scenes/course.txt", SCENE_AUTO, 0, 0, &sc, NULL, &err));
    CHECK_INT(3, (long long)scene_count_of(&sc, SHAPE_SPHERE));
    CHECK_INT(400, sc.camera.height);
    scene_free(&sc);
}

const TestCase course_tests[] = {
    {"parse_accepts_the_example", parse_accepts_the_example},
    {"parse_sphere_materials_read_back_exactly", parse_sphere_materials_read_back_exactly},
    {"parse_spheres_share_a_material_until_one_changes",
     parse_spheres_share_a_material_until_one_changes},
    {"parse_accepts_comments_blanks_crlf_tabs_bom", parse_accepts_comments_blanks_crlf_tabs_bom},
    {"parse_accepts_number_forms", parse_accepts_number_forms},
    {"parse_numbers_round_as_strtod", parse_numbers_round_as_strtod},
    {"parse_numbers_with_long_zero_runs", parse_numbers_with_long_zero_runs},
    {"parse_accepts_many_spheres", parse_accepts_many_spheres},
    {"parse_reads_alike_on_every_thread", parse_reads_alike_on_every_thread},
    {"parse_reads_random_edits_alike", parse_reads_random_edits_alike},
    {"parse_height_follows_the_screen", parse_height_follows_the_screen},
    {"parse_rejects_bad_scenes_with_position", parse_rejects_bad_scenes_with_position},
    {"parse_every_record_rejects_each_fault", parse_every_record_rejects_each_fault},
    {"parse_error_excerpt_and_caret", parse_error_excerpt_and_caret},
    {"error_escape_keeps_utf8_and_escapes_the_rest", error_escape_keeps_utf8_and_escapes_the_rest},
    {"parse_file_errors", parse_file_errors},
    {NULL, NULL},
};
