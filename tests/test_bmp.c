/* test_bmp.c: Windows bitmaps: one 3 x 2 picture of distinct colours
 * written in every layout the reader takes, each read back to the same
 * bytes, and the files it must refuse, each with its reason. */
#include <stdint.h>
#include <stdio.h>
#include <string.h>

#include "image/bmp.h"
#include "image/compare.h"
#include "test.h"

/* The picture, rows top to bottom: red green blue / white black grey. */
static const unsigned char bmp_want[18] = {255, 0, 0, 0, 255, 0, 0, 0, 255,
                                           255, 255, 255, 0, 0, 0, 128, 128, 128};

/* A file being written. */
typedef struct {
    unsigned char b[512];
    size_t n;
} BmpFile;

static void bmp_put(BmpFile *f, uint32_t v, int bytes)
{
    for (int i = 0; i < bytes; i++)
        f->b[f->n++] = (unsigned char)(v >> (8 * i));
}

/* Writes the headers of a w x h (h < 0: top down) picture of `bits` bits,
 * with compression comp and a header of hsize bytes (12: the core one),
 * `extra` bytes (palette, masks) following it; leaves f at the masks or
 * palette. */
static void bmp_headers(BmpFile *f, int w, int h, int bits, uint32_t comp, uint32_t hsize,
                        uint32_t extra)
{
    f->n = 0;
    bmp_put(f, 'B' | 'M' << 8, 2);
    bmp_put(f, 0, 4); /* file size: not checked */
    bmp_put(f, 0, 4);
    bmp_put(f, 14 + hsize + extra, 4);
    bmp_put(f, hsize, 4);
    if (hsize == 12) {
        bmp_put(f, (uint32_t)w, 2);
        bmp_put(f, (uint32_t)h, 2);
        bmp_put(f, 1, 2);
        bmp_put(f, (uint32_t)bits, 2);
        return;
    }
    bmp_put(f, (uint32_t)w, 4);
    bmp_put(f, (uint32_t)h, 4);
    bmp_put(f, 1, 2);
    bmp_put(f, (uint32_t)bits, 2);
    bmp_put(f, comp, 4);
    while (f->n < 14 + hsize)
        f->b[f->n++] = 0;
}

/* Pads the row just written to 4 bytes. */
static void bmp_pad(BmpFile *f, size_t row_start)
{
    while ((f->n - row_start) % 4)
        f->b[f->n++] = 0;
}

/* Reads f and checks it is the picture. */
static void bmp_check(const BmpFile *f, const char *what)
{
    BmpImage img;
    Error err;

    if (bmp_parse("t.bmp", f->b, f->n, &img, &err) != 0) {
        test_fail(__FILE__, __LINE__, "%s: %s", what, err.message);
        return;
    }
    if (img.width != 3 || img.height != 2 || memcmp(img.rgb, bmp_want, sizeof bmp_want) != 0)
        test_fail(__FILE__, __LINE__, "%s: other pixels (%d x %d)", what, img.width, img.height);
    bmp_free(&img);
}

static void bmp_reads_every_layout(void)
{
    /* Pixel k of the picture (row-major, top first) as an index into the
     * palette below, which holds its six colours. */
    static const unsigned char grey[3] = {128, 128, 128};
    BmpFile f;

    /* 24 bits, bottom up: rows from the last. */
    bmp_headers(&f, 3, 2, 24, 0, 40, 0);
    for (int y = 1; y >= 0; y--) {
        size_t start = f.n;
        for (int x = 0; x < 3; x++) {
            const unsigned char *p = bmp_want + 3 * (3 * y + x);
            bmp_put(&f, p[2], 1);
            bmp_put(&f, p[1], 1);
            bmp_put(&f, p[0], 1);
        }
        bmp_pad(&f, start);
    }
    bmp_check(&f, "24 bits, bottom up");
    /* 32 bits (BGRX), top down, a V5 header. */
    bmp_headers(&f, 3, -2, 32, 0, 124, 0);
    for (int k = 0; k < 6; k++)
        bmp_put(&f, (uint32_t)bmp_want[3 * k] << 16 | bmp_want[3 * k + 1] << 8 | bmp_want[3 * k + 2] | 0xff000000u, 4);
    bmp_check(&f, "32 bits, top down, V5 header");
    /* 8 bits with a palette of six (BGRX entries), bottom up. */
    bmp_headers(&f, 3, 2, 8, 0, 40, 24);
    f.b[14 + 32] = 6; /* colours used */
    for (int k = 0; k < 6; k++)
        bmp_put(&f, (uint32_t)bmp_want[3 * k] << 16 | bmp_want[3 * k + 1] << 8 | bmp_want[3 * k + 2], 4);
    for (int y = 1; y >= 0; y--) {
        size_t start = f.n;
        for (int x = 0; x < 3; x++)
            bmp_put(&f, (uint32_t)(3 * y + x), 1);
        bmp_pad(&f, start);
    }
    bmp_check(&f, "8 bits, palette");
    /* 4 bits, the core header's 3-byte palette entries. */
    bmp_headers(&f, 3, 2, 4, 0, 12, 18);
    for (int k = 0; k < 6; k++)
        bmp_put(&f, (uint32_t)bmp_want[3 * k] << 16 | bmp_want[3 * k + 1] << 8 | bmp_want[3 * k + 2], 3);
    for (int y = 1; y >= 0; y--) {
        size_t start = f.n;
        bmp_put(&f, (uint32_t)((3 * y) << 4 | (3 * y + 1)), 1);
        bmp_put(&f, (uint32_t)((3 * y + 2) << 4), 1);
        bmp_pad(&f, start);
    }
    bmp_check(&f, "4 bits, core header");
    /* 16 bits with 5-6-5 masks: the grey of 128 is not exact in 5 or 6
     * bits, so this one is checked with its own rounding. */
    bmp_headers(&f, 1, 1, 16, 3, 40, 12);
    bmp_put(&f, 0xf800, 4);
    bmp_put(&f, 0x07e0, 4);
    bmp_put(&f, 0x001f, 4);
    bmp_put(&f, 16u << 11 | 32u << 5 | 16u, 2);
    bmp_put(&f, 0, 2);
    {
        BmpImage img;
        Error err;
        CHECK_INT(0, bmp_parse("t.bmp", f.b, f.n, &img, &err));
        if (img.rgb) {
            CHECK_INT((16 * 255 + 15) / 31, img.rgb[0]);
            CHECK_INT((32 * 255 + 31) / 63, img.rgb[1]);
            CHECK(img.rgb[0] >= grey[0] - 4 && img.rgb[2] == img.rgb[0]);
            bmp_free(&img);
        }
    }
}

static void bmp_refuses_what_it_cannot_read(void)
{
    static const struct {
        int w, h, bits;
        uint32_t comp, hsize;
        size_t cut; /* bytes kept (0: all) */
        const char *message;
    } bad[] = {
        {3, 2, 8, 1, 40, 0, "BMP: run-length encoded bitmaps are not read (save it uncompressed, or as PNG)"},
        {3, 2, 24, 4, 40, 0, "BMP: JPEG-compressed bitmaps are not read (save it uncompressed, or as PNG)"},
        {3, 2, 24, 0, 20, 0, "BMP: unknown header of 20 bytes (expected 12, or 40 to 124)"},
        {0, 2, 24, 0, 40, 0, "BMP: a 0 x 2 image: each side must be 1 to 65536 pixels"},
        {3, 2, 7, 0, 40, 0, "BMP: 7 bits a pixel (expected 1, 4, 8, 16, 24 or 32)"},
        {3, 2, 24, 3, 40, 0, "BMP: colour masks with 24 bits a pixel (expected 16 or 32)"},
        {3, 2, 24, 0, 40, 60, "BMP: the file ends before its 2 rows of pixels (12 bytes each)"},
        {3, 2, 24, 0, 40, 30, "BMP: the file ends inside its 40-byte header"},
        {3, 2, 8, 0, 40, 0, "BMP: an image of 8 bits a pixel without its palette"},
    };

    for (size_t i = 0; i < sizeof bad / sizeof bad[0]; i++) {
        BmpFile f;
        BmpImage img;
        Error err;
        bmp_headers(&f, bad[i].w, bad[i].h, bad[i].bits, bad[i].comp, bad[i].hsize, 0);
        while (f.n < 14 + bad[i].hsize + 24)
            f.b[f.n++] = 0;
        if (bad[i].cut)
            f.n = bad[i].cut;
        CHECK_INT(-1, bmp_parse("t.bmp", f.b, f.n, &img, &err));
        CHECK_ERROR("bad BMP", &err, 0, 0, bad[i].message);
    }
}

static void bmp_is_a_picture_to_compare(void)
{
    /* raytrace-diff reads the MPL ray tracer's renders, BMP files named .jpg. */
    BmpFile f;
    Picture pic;
    Error err;

    bmp_headers(&f, 1, 1, 24, 0, 40, 0);
    bmp_put(&f, 0x102030, 3);
    bmp_put(&f, 0, 1);
    CHECK_INT(0, picture_parse("render.jpg", (const char *)f.b, f.n, &pic, &err));
    if (pic.rgb) {
        CHECK_NEAR(0x10, pic.rgb[0], 0);
        CHECK_NEAR(0x30, pic.rgb[2], 0);
        CHECK_CONTAINS(pic.format, "BMP");
        picture_free(&pic);
    }
}

/* bmp_write() writes what the reader reads back, pixel for pixel, at
 * every row padding (widths 1 to 5), with the plain headers a viewer
 * expects: 54 bytes of headers, 24 bits, rows bottom to top, the sizes. */
static void bmp_writes_what_it_reads(void)
{
    for (int w = 1; w <= 5; w++) {
        int h = 6 - w;
        unsigned char rgb[3 * 5 * 5], data[256];
        size_t len, row = ((size_t)w * 3 + 3) / 4 * 4;
        FILE *f = tmpfile();
        BmpImage img = {0, 0, 0, NULL};
        Error err;

        for (int i = 0; i < 3 * w * h; i++)
            rgb[i] = (unsigned char)(37 * i + w);
        CHECK(f != NULL);
        if (!f)
            return;
        CHECK_INT(0, bmp_write(f, w, h, rgb));
        rewind(f);
        len = fread(data, 1, sizeof data, f);
        fclose(f);
        CHECK_INT((long long)(54 + row * (size_t)h), (long long)len);
        CHECK(len > 54 && data[0] == 'B' && data[1] == 'M' && data[10] == 54 && data[14] == 40 &&
              data[28] == 24);
        /* The first row in the file is the picture's last, in BGR. */
        CHECK(len > 56 && (unsigned char)data[54] == rgb[3 * w * (h - 1) + 2] &&
              (unsigned char)data[56] == rgb[3 * w * (h - 1)]);
        CHECK_INT(0, bmp_parse("out.bmp", (const unsigned char *)data, len, &img, &err));
        CHECK(img.rgb && img.width == w && img.height == h && img.bits == 24 &&
              memcmp(img.rgb, rgb, 3 * (size_t)w * (size_t)h) == 0);
        bmp_free(&img);
    }
}

const TestCase bmp_tests[] = {
    {"bmp_writes_what_it_reads", bmp_writes_what_it_reads},
    {"bmp_reads_every_layout", bmp_reads_every_layout},
    {"bmp_refuses_what_it_cannot_read", bmp_refuses_what_it_cannot_read},
    {"bmp_is_a_picture_to_compare", bmp_is_a_picture_to_compare},
    {NULL, NULL},
};
