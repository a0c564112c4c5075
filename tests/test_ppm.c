/* test_ppm.c: quantising, the P6 writer's exact bytes, and the reader. */
#include <math.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>

#include "image/decode.h"
#include "image/image.h"
#include "image/ppm.h"
#include "test.h"

static void ppm_quantise_clamps_and_rounds_half_up(void)
{
    CHECK_INT(0, colour_quantise(-1));
    CHECK_INT(0, colour_quantise(NAN));
    CHECK_INT(0, colour_quantise(0.4999999));
    CHECK_INT(1, colour_quantise(0.5));
    CHECK_INT(128, colour_quantise(127.5));
    CHECK_INT(127, colour_quantise(127.49999999999999));
    CHECK_INT(255, colour_quantise(254.5));
    CHECK_INT(255, colour_quantise(1e300));
    CHECK_INT(255, colour_quantise(INFINITY));
    /* floor(x + 0.5) at and beside every half level, and between. */
    for (int k = 0; k <= 256; k++) {
        double half = k - 0.5, xs[] = {nextafter(half, -1), half, nextafter(half, 300), k,
                                       k + 0.25, nextafter(k, 300)};
        for (size_t i = 0; i < sizeof xs / sizeof xs[0]; i++) {
            double x = xs[i], want = x > 0 ? floor(x + 0.5) : 0;
            CHECK_INT((long long)(want > 255 ? 255 : want), colour_quantise(x));
        }
    }
}

/* A 6 x 5 test card: red on blue, with one distinct pixel per corner, so a
 * swap of width and height, of row order or of channels shows. */
static void ppm_test_card(Image *img)
{
    CHECK_INT(0, image_init(img, 6, 5));
    for (int y = 0; y < 5; y++)
        for (int x = 0; x < 6; x++)
            image_set(img, x, y, x < 3 ? colour(255, 0, 0) : colour(0, 0, 255));
    image_set(img, 0, 0, colour(1, 2, 3));
    image_set(img, 5, 0, colour(4, 5, 6));
    image_set(img, 0, 4, colour(7, 8, 9));
    image_set(img, 5, 4, colour(10, 11, 12));
}

static void ppm_writer_bytes_are_exact(void)
{
    static const char header[] = "P6\n6 5\n255\n";
    Image img;
    unsigned char buf[200];
    FILE *f = tmpfile();
    size_t n;

    ppm_test_card(&img);
    CHECK(f != NULL);
    if (!f)
        return;
    CHECK_INT(0, ppm_write(f, img.width, img.height, img.rgb, NULL));
    rewind(f);
    n = fread(buf, 1, sizeof buf, f);
    fclose(f);
    CHECK_INT(sizeof header - 1 + 90, (long long)n);
    CHECK(memcmp(buf, header, sizeof header - 1) == 0);
    {
        const unsigned char *px = buf + sizeof header - 1;
        CHECK_INT(1, px[0]);                   /* (0, 0): first */
        CHECK_INT(3, px[2]);
        CHECK_INT(4, px[3 * 5]);               /* (5, 0): end of the first row */
        CHECK_INT(7, px[3 * 24]);              /* (0, 4): start of the last row */
        CHECK_INT(12, px[3 * 29 + 2]);         /* (5, 4): last */
        CHECK_INT(255, px[3 * 7]);             /* (1, 1): red */
        CHECK_INT(0, px[3 * 7 + 2]);
        CHECK_INT(255, px[3 * 10 + 2]);        /* (4, 1): blue */
    }
    image_free(&img);
}

/* Writes text to a temporary file and returns its path (static buffer). */
static const char *ppm_temp_file(const char *data, size_t len)
{
    static char path[64];
    FILE *f;

    snprintf(path, sizeof path, "build/test-ppm-%d.tmp", rand());
    f = fopen(path, "wb");
    if (!f)
        return NULL;
    fwrite(data, 1, len, f);
    fclose(f);
    return path;
}

static void ppm_reader_round_trip_and_p3(void)
{
    static const char p3[] = "P3\n# a comment\n2 1\n# another\n65535\n0 1 2  65535 300 7\n";
    Image img;
    Decoded in;
    Error err;
    FILE *f;
    const char *path;

    ppm_test_card(&img);
    path = ppm_temp_file("", 0);
    CHECK(path != NULL);
    f = fopen(path, "wb");
    CHECK_INT(0, ppm_write(f, img.width, img.height, img.rgb, NULL));
    fclose(f);
    CHECK_INT(0, decoded_read(path, 0, &in, &err));
    CHECK_INT(6, in.width);
    CHECK_INT(5, in.height);
    CHECK_INT(255, in.maxval);
    for (int k = 0; k < 90; k++)
        if (in.samples[k] != img.rgb[k])
            test_fail(__FILE__, __LINE__, "sample %d: expected %d, got %d", k, img.rgb[k],
                      in.samples[k]);
    decoded_free(&in);
    remove(path);
    image_free(&img);

    path = ppm_temp_file(p3, sizeof p3 - 1);
    CHECK_INT(0, decoded_read(path, 0, &in, &err));
    CHECK_INT(2, in.width);
    CHECK_INT(1, in.height);
    CHECK_INT(65535, in.maxval);
    CHECK_INT(65535, in.samples[3]);
    CHECK_INT(7, in.samples[5]);
    decoded_free(&in);
    remove(path);
}

static void ppm_reader_rejects_bad_files(void)
{
    static const struct {
        const char *data;
        const char *message;
        int line;
    } bad[] = {
        {"P5\n1 1\n255\n\0", "not a PPM file", 1},
        {"P6\n2 x\n255\n", "expected the height", 2},
        {"P6\n2 2\n70000\n", "the maxval is out of range", 3},
        {"P6\n2 2\n255\n\1\2\3", "truncated pixel data: expected 12 bytes, found 3", 3},
        {"P3\n1 1\n10\n1 2 11\n", "a sample is out of range (at most 10)", 4},
        {"P3\n1 1\n10\n1 2\n", "expected a sample (a whole number), found the end of the file", 5},
        {"P6\n0 2\n255\n", "at least 1", 3},
    };
    for (size_t i = 0; i < sizeof bad / sizeof bad[0]; i++) {
        const char *path = ppm_temp_file(bad[i].data, strlen(bad[i].data) + (i == 0));
        Decoded in;
        Error err;

        CHECK_INT(-1, decoded_read(path, 0, &in, &err));
        CHECK_CONTAINS(err.message, bad[i].message);
        CHECK_INT(bad[i].line, err.line);
        CHECK(in.samples == NULL);
        remove(path);
    }
}

const TestCase ppm_tests[] = {
    {"ppm_quantise_clamps_and_rounds_half_up", ppm_quantise_clamps_and_rounds_half_up},
    {"ppm_writer_bytes_are_exact", ppm_writer_bytes_are_exact},
    {"ppm_reader_round_trip_and_p3", ppm_reader_round_trip_and_p3},
    {"ppm_reader_rejects_bad_files", ppm_reader_rejects_bad_files},
    {NULL, NULL},
};
