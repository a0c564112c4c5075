/*
 * scenegen.c: the benchmark's scenes, generated the same on every machine
 * (an integer hash for randomness, %.6f output), so that no large file is
 * kept in git.
 *
 *   scenegen course WIDTH            the course scene at WIDTH pixels
 *   scenegen spheres N [pov]         N random spheres, reflection 0.3, on a
 *                                    large floor sphere, 1920 x 1080 (the
 *                                    same scene for POV-Ray 3.7 with pov)
 *   scenegen terrain N OBJ           a height field of at least N triangles
 *                                    written to OBJ; the scene on stdout
 *
 * The scene goes to standard output.
 */
#include <math.h>
#include <stdint.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>

/* Returns the k-th number of the stream `seed`, uniform in [0, 1). */
static double scenegen_random(uint64_t seed, uint64_t k)
{
    uint64_t z = seed * 0x9E3779B97F4A7C15u + k * 0xBF58476D1CE4E5B9u + 0x94D049BB133111EBu;

    z = (z ^ (z >> 30)) * 0xBF58476D1CE4E5B9u;
    z = (z ^ (z >> 27)) * 0x94D049BB133111EBu;
    z ^= z >> 31;
    return (double)(z >> 11) * 0x1p-53;
}

static void scenegen_course(int width)
{
    printf("# The course's example scene at %d pixels.\n"
           "100 100 0\n90 110 30\n110 110 30\n90 90 30\n%d\n80 80 100\n"
           "200 300 0 245 200 200\n"
           "sphere: 90 90 60 7 250 0 0 0.3\nsphere: 100 110 60 7 0 250 0 0.3\n"
           "sphere: 110 110 60 7 0 0 250 0.3\n",
           width, width);
}

/* The sphere field: n spheres of radius 2 (1000 / n)^(1/3) in a box 100 wide,
 * 40 high and 100 deep, seen from above and in front. */
enum { FIELD_WIDTH = 1920 };

typedef struct {
    double x, y, z, r;
    int red, green, blue;
} Ball;

static Ball scenegen_ball(long n, long i)
{
    Ball b;
    double r = 2 * cbrt(1000.0 / (double)n);

    b.x = -50 + 100 * scenegen_random(1, 4 * (uint64_t)i);
    b.y = r + 40 * scenegen_random(1, 4 * (uint64_t)i + 1);
    b.z = 100 * scenegen_random(1, 4 * (uint64_t)i + 2);
    b.r = r;
    b.red = (int)(256 * scenegen_random(2, 3 * (uint64_t)i));
    b.green = (int)(256 * scenegen_random(2, 3 * (uint64_t)i + 1));
    b.blue = (int)(256 * scenegen_random(2, 3 * (uint64_t)i + 2));
    return b;
}

static void scenegen_spheres(long n, int pov)
{
    /* Eye at (0, 35, -60); a 16:9 screen one unit ahead, its centre 0.18
     * below the eye's height so that the view tilts towards the field. */
    if (pov) {
        printf("// %ld random spheres: the raytrace benchmark's field for POV-Ray 3.7.\n"
               "global_settings { assumed_gamma 1 max_trace_level 11 adc_bailout 0 }\n"
               "camera { perspective location <0, 35, -60> direction <0, -0.18, 1>\n"
               "         right <1.6, 0, 0> up <0, 0.9, 0> }\n"
               "background { color rgb <20, 24, 36> / 255 }\n"
               "light_source { <150, 250, -150> color rgb <255, 250, 240> / 255 }\n"
               "sphere { <0, -100000, 0>, 100000 pigment { color rgb <200, 200, 200> / 255 }\n"
               "         finish { ambient 0 diffuse 0.7 reflection 0.3 } }\n",
               n);
    } else {
        printf("# %ld random spheres, reflection 0.3, on a floor sphere (the benchmark's field)\n"
               "0 35 -60\n-0.8 35.27 -59\n0.8 35.27 -59\n-0.8 34.37 -59\n%d\n20 24 36\n"
               "150 250 -150 255 250 240\n"
               "sphere: 0 -100000 0 100000 200 200 200 0.3\n",
               n, FIELD_WIDTH);
    }
    for (long i = 0; i < n; i++) {
        Ball b = scenegen_ball(n, i);
        if (pov)
            printf("sphere { <%.6f, %.6f, %.6f>, %.6f pigment { color rgb <%d, %d, %d> / 255 }"
                   " finish { ambient 0 diffuse 0.7 reflection 0.3 } }\n",
                   b.x, b.y, b.z, b.r, b.red, b.green, b.blue);
        else
            printf("sphere: %.6f %.6f %.6f %.6f %d %d %d 0.3\n", b.x, b.y, b.z, b.r, b.red,
                   b.green, b.blue);
    }
}

/* The field of scenegen_spheres() in the keyword format, of n spheres,
 * cubes (of the spheres' volume: half-edge (pi / 6)^(1/3) r), squares (of
 * their cross-section's area: half-edge sqrt(pi) / 2 r, tilted every
 * way), infinite vertical cylinders of the spheres' radii or infinite
 * cones (that radius, apex 2 r above), under eight Blinn-Phong
 * materials, on a floor plane, lit by one distant light. */
static int scenegen_field(const char *kind, long n)
{
    static const int rgb[8][3] = {{230, 80, 60}, {80, 200, 90}, {70, 110, 230}, {230, 200, 70},
                                  {200, 90, 210}, {70, 210, 210}, {235, 235, 235}, {150, 110, 80}};
    const double pi = 3.14159265358979323846;
    double scale = strcmp(kind, "cube") == 0 ? cbrt(pi / 6) : strcmp(kind, "square") == 0 ? sqrt(pi) / 2 : 1;

    if (strcmp(kind, "sphere") != 0 && strcmp(kind, "cube") != 0 && strcmp(kind, "square") != 0 &&
        strcmp(kind, "cylinder") != 0 && strcmp(kind, "cone") != 0)
        return 2;
    printf("# %ld random %ss in the keyword format of the OCaml course project (the benchmark's field)\n"
           "camera 0 35 -60 0 24.2 0 1.3495 %d %d\nbackground 20 24 36\nambient 30 30 30\n"
           "light -0.5 -1 0.5 255 250 240 1\n"
           "material floor 200 200 200 0.2 0.7 0 1 0.3\n",
           n, kind, FIELD_WIDTH, FIELD_WIDTH * 9 / 16);
    for (int k = 0; k < 8; k++)
        printf("material m%d %d %d %d 0.2 0.7 0.3 20 0.3\n", k, rgb[k][0], rgb[k][1], rgb[k][2]);
    printf("plane 0 0 0 0 1 0 floor\n");
    for (long i = 0; i < n; i++) {
        Ball b = scenegen_ball(n, i);
        if (strcmp(kind, "square") == 0)
            printf("square %.6f %.6f %.6f %.3f %.3f %.3f %.6f m%ld\n", b.x, b.y, b.z,
                   scenegen_random(3, 3 * (uint64_t)i) - 0.5, 0.5 + scenegen_random(3, 3 * (uint64_t)i + 1),
                   scenegen_random(3, 3 * (uint64_t)i + 2) - 0.5, b.r * scale, i % 8);
        else if (strcmp(kind, "cone") == 0)
            printf("cone %.6f %.6f %.6f %.6f %.6f m%ld\n", b.x, b.y, b.z, b.r, 2 * b.r, i % 8);
        else
            printf("%s %.6f %.6f %.6f %.6f m%ld\n", kind, b.x, b.y, b.z, b.r * scale, i % 8);
    }
    return 0;
}

/* A height field of rolling hills, (side - 1)^2 quads of two triangles. */
static double scenegen_height(double x, double z)
{
    return 6 * sin(x * 0.07) * cos(z * 0.05) + 2 * sin(x * 0.31 + z * 0.17) +
           0.5 * cos(x * 1.3 - z * 0.9);
}

static int scenegen_terrain(long n, const char *obj)
{
    long side = 2;
    FILE *fp;

    while (2 * (side - 1) * (side - 1) < n)
        side++;
    fp = fopen(obj, "w");
    if (!fp) {
        perror(obj);
        return 1;
    }
    fprintf(fp, "# terrain: %ld x %ld vertices, %ld triangles\n", side, side,
            2 * (side - 1) * (side - 1));
    for (long j = 0; j < side; j++)
        for (long i = 0; i < side; i++) {
            double x = -100 + 200.0 * i / (side - 1), z = 200.0 * j / (side - 1);
            fprintf(fp, "v %.6f %.6f %.6f\n", x, scenegen_height(x, z), z);
        }
    for (long j = 0; j + 1 < side; j++)
        for (long i = 0; i + 1 < side; i++) {
            long a = j * side + i + 1, b = a + 1, c = a + side, d = c + 1;
            fprintf(fp, "f %ld %ld %ld\nf %ld %ld %ld\n", a, c, b, b, c, d);
        }
    if (fclose(fp) != 0) {
        perror(obj);
        return 1;
    }
    printf("# a terrain of %ld triangles (%s)\n"
           "0 30 -20\n-0.8 30.1 -19\n0.8 30.1 -19\n-0.8 29.2 -19\n%d\n120 160 220\n"
           "-100 200 -50 255 245 230\n"
           "mesh: %s 110 160 90 0.2\n",
           2 * (side - 1) * (side - 1), obj, FIELD_WIDTH, obj);
    return 0;
}

int main(int argc, char **argv)
{
    if (argc == 3 && strcmp(argv[1], "course") == 0) {
        scenegen_course(atoi(argv[2]));
        return 0;
    }
    if ((argc == 3 || argc == 4) && strcmp(argv[1], "spheres") == 0) {
        scenegen_spheres(atol(argv[2]), argc == 4 && strcmp(argv[3], "pov") == 0);
        return 0;
    }
    if (argc == 4 && strcmp(argv[1], "terrain") == 0)
        return scenegen_terrain(atol(argv[2]), argv[3]);
    if (argc == 4 && strcmp(argv[1], "field") == 0 && scenegen_field(argv[2], atol(argv[3])) == 0)
        return 0;
    fprintf(stderr, "usage: scenegen course WIDTH | spheres N [pov] | terrain N OBJ"
                    " | field sphere|cube|square|cylinder|cone N\n");
    return 2;
}
