/* test_png.c: checksums, deflate both ways, PNG and PFM round trips. */
#include <stdio.h>
#include <stdlib.h>
#include <string.h>

#include "image/decode.h"
#include "image/deflate.h"
#include "image/pfm.h"
#include "image/png.h"
#include "image/ppm.h"
#include "test.h"

static void checksums_match_known_values(void)
{
    /* The check values of the CRC-32 and Adler-32 definitions. */
    CHECK_INT(0xCBF43926u, png_crc32(0, (const unsigned char *)"123456789", 9));
    CHECK_INT(0x11E60398u, deflate_adler32(1, (const unsigned char *)"Wikipedia", 9));
    CHECK_INT(0, png_crc32(0, NULL, 0));
    CHECK_INT(1, deflate_adler32(1, NULL, 0));
    /* Continuing a checksum equals taking it in one go. */
    CHECK_INT(png_crc32(0, (const unsigned char *)"123456789", 9),
              png_crc32(png_crc32(0, (const unsigned char *)"1234", 4),
                        (const unsigned char *)"56789", 5));
}

/* Compresses n bytes with mode, inflates them back; returns 1 when equal. */
static int round_trip(const unsigned char *in, size_t n, DeflateMode mode, size_t *zlen)
{
    ByteBuf z = {0}, back = {0};
    char msg[200];
    int ok;

    CHECK_INT(0, deflate_zlib(&z, in, n, mode));
    *zlen = z.len;
    ok = inflate_zlib(&back, z.data, z.len, msg, sizeof msg) == 0 && back.len == n &&
         (n == 0 || memcmp(back.data, in, n) == 0);
    bytebuf_free(&z);
    bytebuf_free(&back);
    return ok;
}

static void deflate_round_trips(void)
{
    size_t n = 200000, zs, zf;
    unsigned char *data = malloc(n);
    uint32_t x = 12345;

    CHECK(data != NULL);
    if (!data)
        return;
    /* Runs, repeats at every distance up to the window, and noise. */
    for (size_t i = 0; i < n; i++) {
        x = x * 1103515245u + 12345u;
        data[i] = i < 50000 ? (unsigned char)(i / 1000) : i < 100000 ? data[i - 1 - (x >> 17) % 32768]
                                                                   : (unsigned char)(x >> 24);
    }
    CHECK(round_trip(data, 0, DEFLATE_FIXED, &zf));
    CHECK(round_trip(data, 1, DEFLATE_STORED, &zs));
    CHECK(round_trip(data, n, DEFLATE_STORED, &zs));
    CHECK(round_trip(data, n, DEFLATE_FIXED, &zf));
    CHECK(zf < zs);
    CHECK(round_trip(data, 50000, DEFLATE_FIXED, &zf)); /* runs of 1000 */
    CHECK(zf < 50000 / 20);
    /* Noise does not compress: the writer falls back to stored blocks. */
    CHECK(round_trip(data + 100000, 100000, DEFLATE_FIXED, &zf));
    CHECK(zf <= 100000 + 5 * 2 + 6);
    free(data);
}

static void inflate_rejects_damage(void)
{
    static const unsigned char text[] = "the same words, the same words, the same words";
    ByteBuf z = {0}, back = {0};
    char msg[200];
    int rejected = 0, tried = 0;

    CHECK_INT(0, deflate_zlib(&z, text, sizeof text, DEFLATE_FIXED));
    /* Every truncation fails; every single-bit flip fails or (rarely, in
     * the header's spare bits) still decodes the same data. */
    for (size_t len = 0; len < z.len; len++) {
        back.len = 0;
        rejected += inflate_zlib(&back, z.data, len, msg, sizeof msg) != 0;
        tried++;
    }
    CHECK_INT(tried, rejected);
    for (size_t bit = 0; bit < 8 * z.len; bit++) {
        int rc;
        z.data[bit / 8] ^= (unsigned char)(1u << bit % 8);
        back.len = 0;
        rc = inflate_zlib(&back, z.data, z.len, msg, sizeof msg);
        CHECK(rc != 0 || (back.len == sizeof text && memcmp(back.data, text, sizeof text) == 0));
        z.data[bit / 8] ^= (unsigned char)(1u << bit % 8);
    }
    bytebuf_free(&z);
    bytebuf_free(&back);
}

static void png_round_trip_keeps_every_byte(void)
{
    /* 7 x 3: not square, odd width; every channel value distinct from the
     * others, so a swapped channel, row or column would show. */
    enum { W = 7, H = 3 };
    unsigned char rgb[3 * W * H];
    Decoded img;
    Error err;
    FILE *f;

    for (int i = 0; i < 3 * W * H; i++)
        rgb[i] = (unsigned char)(i * 11 + 3);
    for (int mode = 0; mode < 2; mode++) {
        f = fopen("build/round.png", "wb");
        CHECK(f != NULL);
        if (!f)
            return;
        CHECK_INT(0, png_write(f, W, H, rgb, mode ? DEFLATE_FIXED : DEFLATE_STORED, NULL));
        fclose(f);
        CHECK_INT(0, decoded_read("build/round.png", 0, &img, &err));
        CHECK_INT(W, img.width);
        CHECK_INT(H, img.height);
        CHECK_CONTAINS(img.format, "PNG, 3 channels");
        for (int i = 0; img.samples && i < 3 * W * H; i++)
            if (img.samples[i] != rgb[i]) {
                test_fail(__FILE__, __LINE__, "sample %d: %d, expected %d", i, img.samples[i],
                          rgb[i]);
                break;
            }
        decoded_free(&img);
    }
}

static void pfm_rows_run_bottom_to_top(void)
{
    /* 2 x 3 floats, each pixel's red its row number: the file's first row is
     * the image's last. Values beyond 1 and below 0 survive. */
    float rgb[3 * 2 * 3];
    Decoded img;
    Error err;
    FILE *f;
    char head[20] = {0};

    for (int i = 0; i < 18; i++)
        rgb[i] = i % 3 == 0 ? (float)(i / 6) : i % 3 == 1 ? 7.5f : -0.25f;
    f = fopen("build/rows.pfm", "wb");
    CHECK(f != NULL);
    if (!f)
        return;
    CHECK_INT(0, pfm_write(f, 2, 3, rgb, NULL));
    fclose(f);
    f = fopen("build/rows.pfm", "rb");
    CHECK(f && fread(head, 1, 12, f) == 12);
    if (f) {
        float first;
        CHECK(memcmp(head, "PF\n2 3\n-1.0\n", 12) == 0);
        CHECK(fread(&first, 4, 1, f) == 1); /* little-endian, as on this machine */
        CHECK_NEAR(2, first, 0);
        fclose(f);
    }
    CHECK_INT(0, decoded_read("build/rows.pfm", 0, &img, &err));
    CHECK(img.linear && memcmp(img.linear, rgb, sizeof rgb) == 0);
    decoded_free(&img);
}

static void ppm_ascii_reads_back(void)
{
    enum { W = 30, H = 2 }; /* 30 pixels a row: lines must wrap */
    unsigned char rgb[3 * W * H];
    Decoded img;
    Error err;
    FILE *f = fopen("build/ascii.ppm", "wb");

    for (int i = 0; i < 3 * W * H; i++)
        rgb[i] = (unsigned char)(255 - i % 256);
    CHECK(f != NULL);
    if (!f)
        return;
    CHECK_INT(0, ppm_write_ascii(f, W, H, rgb, NULL));
    fclose(f);
    CHECK_INT(0, decoded_read("build/ascii.ppm", 0, &img, &err));
    for (int i = 0; img.samples && i < 3 * W * H; i++)
        if (img.samples[i] != rgb[i]) {
            test_fail(__FILE__, __LINE__, "sample %d: %d, expected %d", i, img.samples[i], rgb[i]);
            break;
        }
    decoded_free(&img);
}

const TestCase png_tests[] = {
    {"checksums_match_known_values", checksums_match_known_values},
    {"deflate_round_trips", deflate_round_trips},
    {"inflate_rejects_damage", inflate_rejects_damage},
    {"png_round_trip_keeps_every_byte", png_round_trip_keeps_every_byte},
    {"pfm_rows_run_bottom_to_top", pfm_rows_run_bottom_to_top},
    {"ppm_ascii_reads_back", ppm_ascii_reads_back},
    {NULL, NULL},
};
