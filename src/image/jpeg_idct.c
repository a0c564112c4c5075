/* jpeg_idct.c: from a JPEG's coefficients to RGB pixels: the inverse DCT,
 * upsampling, colour conversion (see jpeg_decode.h; ITU-T T.81, annex A). */
#include <stdint.h>
#include <stdlib.h>
#include <string.h>

#include "jpeg_decode.h"
#include "jpeg_tables.h"

/* The inverse DCT: Loeffler, Ligtenberg and Moschytz's factorisation in
 * 13-bit fixed point, columns then rows, scaled by 2 bits between the
 * passes, as libjpeg-turbo's default ("islow") decoder computes it, so
 * that its pixels are ours. */
enum { JPEG_CONST_BITS = 13, JPEG_PASS1_BITS = 2 };
#define JPEG_FIX_0_298631336 2446
#define JPEG_FIX_0_390180644 3196
#define JPEG_FIX_0_541196100 4433
#define JPEG_FIX_0_765366865 6270
#define JPEG_FIX_0_899976223 7373
#define JPEG_FIX_1_175875602 9633
#define JPEG_FIX_1_501321110 12299
#define JPEG_FIX_1_847759065 15137
#define JPEG_FIX_1_961570560 16069
#define JPEG_FIX_2_053119869 16819
#define JPEG_FIX_2_562915447 20995
#define JPEG_FIX_3_072711026 25172

/* Returns x wrapped to 16 bits, as a 16-bit lane holds it. */
static inline int32_t jpeg_wrap16(int32_t x)
{
    return (int16_t)(uint16_t)(uint32_t)x;
}

/* Returns x saturated to 16 bits, as a lane is packed. */
static inline int32_t jpeg_sat16(int32_t x)
{
    return x < -32768 ? -32768 : x > 32767 ? 32767 : x;
}

/* Returns a + b and a * b wrapped to 32 bits, as 32-bit lanes add. */
static inline int32_t jpeg_add32(int32_t a, int32_t b)
{
    return (int32_t)((uint32_t)a + (uint32_t)b);
}

static inline int32_t jpeg_mul32(int32_t a, int32_t b)
{
    return (int32_t)((uint32_t)a * (uint32_t)b);
}

/* Returns sat16(x / 2^n), rounded to nearest (halves up) in 32-bit lanes. */
static inline int32_t jpeg_descale(int32_t x, int n)
{
    return jpeg_sat16(jpeg_add32(x, (int32_t)1 << (n - 1)) >> n);
}

/* One 8-point inverse DCT of the 16-bit values in[0], in[stride], ...
 * into eight, each descaled by shift bits and saturated to 16 bits, in
 * the arithmetic of libjpeg-turbo's SIMD code: sums of two inputs in 16
 * bits (wrapping), products and their sums in 32 (wrapping). On valid
 * data nothing wraps or saturates, and the values are its C code's. */
static void jpeg_idct8(const int32_t *in, int stride, int32_t out[8], int shift)
{
    int32_t i0 = in[0], i1 = in[stride], i2 = in[2 * stride], i3 = in[3 * stride];
    int32_t i4 = in[4 * stride], i5 = in[5 * stride], i6 = in[6 * stride], i7 = in[7 * stride];
    int32_t t0, t1, t2, t3, t10, t11, t12, t13, z3, z4, z3m, z4m;

    /* Even part. */
    t3 = jpeg_add32(jpeg_mul32(i2, JPEG_FIX_0_541196100 + JPEG_FIX_0_765366865),
                    jpeg_mul32(i6, JPEG_FIX_0_541196100));
    t2 = jpeg_add32(jpeg_mul32(i2, JPEG_FIX_0_541196100),
                    jpeg_mul32(i6, JPEG_FIX_0_541196100 - JPEG_FIX_1_847759065));
    t0 = jpeg_mul32(jpeg_wrap16(i0 + i4), 1 << JPEG_CONST_BITS);
    t1 = jpeg_mul32(jpeg_wrap16(i0 - i4), 1 << JPEG_CONST_BITS);
    t10 = jpeg_add32(t0, t3);
    t13 = jpeg_add32(t0, -t3);
    t11 = jpeg_add32(t1, t2);
    t12 = jpeg_add32(t1, -t2);
    /* Odd part. */
    z3 = jpeg_wrap16(i7 + i3);
    z4 = jpeg_wrap16(i5 + i1);
    z3m = jpeg_add32(jpeg_mul32(z3, JPEG_FIX_1_175875602 - JPEG_FIX_1_961570560),
                     jpeg_mul32(z4, JPEG_FIX_1_175875602));
    z4m = jpeg_add32(jpeg_mul32(z3, JPEG_FIX_1_175875602),
                     jpeg_mul32(z4, JPEG_FIX_1_175875602 - JPEG_FIX_0_390180644));
    t0 = jpeg_add32(jpeg_add32(jpeg_mul32(i7, JPEG_FIX_0_298631336 - JPEG_FIX_0_899976223),
                               jpeg_mul32(i1, -JPEG_FIX_0_899976223)),
                    z3m);
    t1 = jpeg_add32(jpeg_add32(jpeg_mul32(i5, JPEG_FIX_2_053119869 - JPEG_FIX_2_562915447),
                               jpeg_mul32(i3, -JPEG_FIX_2_562915447)),
                    z4m);
    t3 = jpeg_add32(jpeg_add32(jpeg_mul32(i7, -JPEG_FIX_0_899976223),
                               jpeg_mul32(i1, JPEG_FIX_1_501321110 - JPEG_FIX_0_899976223)),
                    z4m);
    t2 = jpeg_add32(jpeg_add32(jpeg_mul32(i5, -JPEG_FIX_2_562915447),
                               jpeg_mul32(i3, JPEG_FIX_3_072711026 - JPEG_FIX_2_562915447)),
                    z3m);
    out[0] = jpeg_descale(jpeg_add32(t10, t3), shift);
    out[7] = jpeg_descale(jpeg_add32(t10, -t3), shift);
    out[1] = jpeg_descale(jpeg_add32(t11, t2), shift);
    out[6] = jpeg_descale(jpeg_add32(t11, -t2), shift);
    out[2] = jpeg_descale(jpeg_add32(t12, t1), shift);
    out[5] = jpeg_descale(jpeg_add32(t12, -t1), shift);
    out[3] = jpeg_descale(jpeg_add32(t13, t0), shift);
    out[4] = jpeg_descale(jpeg_add32(t13, -t0), shift);
}

/* Returns the sample of the IDCT's 16-bit output x (centred on 0): x + 128
 * within [-128, 127], 255 above and 0 below, as libjpeg-turbo's SIMD code
 * (the one djpeg runs on x86 and ARM) saturates it. (Its C code, run
 * where there is no SIMD, indexes a table by x's 10 low bits, so that
 * damaged data beyond 511 wraps around instead.) */
static inline uint8_t jpeg_sample(int32_t x)
{
    return (uint8_t)(x < -128 ? 0 : x > 127 ? 255 : x + 128);
}

/* Dequantises block blk with quant and writes its 8 x 8 samples at out
 * (rows stride apart), as libjpeg-turbo's SIMD "islow" code does (the
 * same pixels as its C code on every valid file, djpeg's own on damaged
 * ones): coefficients dequantised to their low 16 bits; a block whose
 * rows 1 to 7 are all zero takes its first pass as its first row shifted
 * in 16 bits; each pass's outputs saturated to 16 bits, the samples to
 * bytes. */
static void jpeg_idct(const int16_t *blk, const uint16_t *quant, uint8_t *out, size_t stride)
{
    int32_t in[64], ws[64], col[8], row[8];
    int flat = 1;

    for (int k = 0; k < 64; k++)
        in[k] = jpeg_wrap16(jpeg_mul32(blk[k], quant[k]));
    for (int k = 8; k < 64 && flat; k++)
        flat = in[k] == 0;
    /* Columns, kept 2 bits above the samples' scale. */
    for (int c = 0; c < 8; c++) {
        if (flat) {
            for (int r = 0; r < 8; r++)
                ws[8 * r + c] = jpeg_wrap16(in[c] * (1 << JPEG_PASS1_BITS));
            continue;
        }
        jpeg_idct8(in + c, 8, col, JPEG_CONST_BITS - JPEG_PASS1_BITS);
        for (int r = 0; r < 8; r++)
            ws[8 * r + c] = col[r];
    }
    /* Rows, to samples. */
    for (int r = 0; r < 8; r++) {
        uint8_t *o = out + (size_t)r * stride;
        jpeg_idct8(ws + 8 * r, 1, row, JPEG_CONST_BITS + JPEG_PASS1_BITS + 3);
        for (int c = 0; c < 8; c++)
            o[c] = jpeg_sample(row[c]);
    }
}

/* Turns component c's coefficients into its samples (c->plane, width x
 * height), freeing the coefficients. */
int jpeg_component_samples(Jpeg *J, JpegComponent *c)
{
    size_t pw = (size_t)c->bw * 8;
    uint8_t *full = malloc(pw * (size_t)c->bh * 8);

    if (!full) {
        error_set(J->err, J->name, "out of memory for a %d x %d JPEG", J->width, J->height);
        return -1;
    }
    for (int by = 0; by < c->bh; by++)
        for (int bx = 0; bx < c->bw; bx++) {
            const int16_t *blk = c->coef + 64 * ((size_t)by * (size_t)c->bw + (size_t)bx);
            int16_t smoothed[64];
            /* Blocks of the picture whose coefficients did not all come. */
            if (J->smooth && bx < (c->width + 7) / 8 && by < (c->height + 7) / 8) {
                jpeg_smooth_block(J, c, bx, by, smoothed);
                blk = smoothed;
            }
            jpeg_idct(blk, c->quant, full + (size_t)by * 8 * pw + (size_t)bx * 8, pw);
        }
    free(c->coef);
    c->coef = NULL;
    /* Keep the component's own samples, rows of its width. */
    for (int y = 0; y < c->height; y++)
        memmove(full + (size_t)y * (size_t)c->width, full + (size_t)y * pw, (size_t)c->width);
    c->plane = full;
    return 0;
}

/* Returns sample (x, y) of component c, clamped into it. */
static inline int jpeg_at(const JpegComponent *c, int x, int y)
{
    x = x < 0 ? 0 : x >= c->width ? c->width - 1 : x;
    y = y < 0 ? 0 : y >= c->height ? c->height - 1 : y;
    return c->plane[(size_t)y * (size_t)c->width + (size_t)x];
}

/* Writes row y of the image's samples of component c, upsampled to the
 * image's width, into out: libjpeg's "fancy" triangle filter where the
 * component is halved down, or across (or both) and more than 2 samples
 * wide (libjpeg-turbo's jdsample.c filters across only then), and each
 * sample repeated otherwise. */
static void jpeg_upsample_row(const Jpeg *J, const JpegComponent *c, int y, uint8_t *out)
{
    int fx = J->hmax / c->h, fy = J->vmax / c->v, w = J->width;

    if (fx == 1 && fy == 1) {
        memcpy(out, c->plane + (size_t)y * (size_t)c->width, (size_t)w);
    } else if (fx == 2 && c->width <= 2) {
        for (int i = 0; i < w; i++)
            out[i] = (uint8_t)jpeg_at(c, i / fx, y / fy);
    } else if (fx == 2 && fy == 1) {
        for (int i = 0; i < c->width; i++) {
            int s = jpeg_at(c, i, y), l = jpeg_at(c, i - 1, y), r = jpeg_at(c, i + 1, y);
            if (2 * i < w)
                out[2 * i] = (uint8_t)(i == 0 ? s : (3 * s + l + 1) >> 2);
            if (2 * i + 1 < w)
                out[2 * i + 1] = (uint8_t)(i == c->width - 1 ? s : (3 * s + r + 2) >> 2);
        }
    } else if (fx == 1 && fy == 2) {
        int sy = y / 2, ny = y % 2 ? sy + 1 : sy - 1;
        for (int i = 0; i < w; i++)
            out[i] = (uint8_t)((3 * jpeg_at(c, i, sy) + jpeg_at(c, i, ny) + (y % 2 ? 2 : 1)) >> 2);
    } else if (fx == 2 && fy == 2) {
        int sy = y / 2, ny = y % 2 ? sy + 1 : sy - 1;
        for (int i = 0; i < c->width; i++) {
            int s = 3 * jpeg_at(c, i, sy) + jpeg_at(c, i, ny);
            int l = 3 * jpeg_at(c, i - 1, sy) + jpeg_at(c, i - 1, ny);
            int r = 3 * jpeg_at(c, i + 1, sy) + jpeg_at(c, i + 1, ny);
            if (2 * i < w)
                out[2 * i] = (uint8_t)(i == 0 ? (4 * s + 8) >> 4 : (3 * s + l + 8) >> 4);
            if (2 * i + 1 < w)
                out[2 * i + 1] = (uint8_t)(i == c->width - 1 ? (4 * s + 7) >> 4
                                                             : (3 * s + r + 7) >> 4);
        }
    } else {
        for (int i = 0; i < w; i++)
            out[i] = (uint8_t)jpeg_at(c, i / fx, y / fy);
    }
}

/* JFIF's YCbCr to RGB in 16-bit fixed point, as libjpeg computes it. */
enum { JPEG_SCALE = 16 };
#define JPEG_FIX16(x) ((int32_t)((x) * (1 << JPEG_SCALE) + 0.5))
#define JPEG_HALF (1 << (JPEG_SCALE - 1))

/* Returns x clamped to a byte. */
static inline uint8_t jpeg_byte(int32_t x)
{
    return (uint8_t)(x < 0 ? 0 : x > 255 ? 255 : x);
}

/* Writes the whole image's RGB into img. */
int jpeg_pixels(Jpeg *J, unsigned char *rgb)
{
    int w = J->width, rgb_file = J->ncomp == 3 &&
                                 ((J->adobe && J->transform == 0) ||
                                  (J->comp[0].id == 'R' && J->comp[1].id == 'G' &&
                                   J->comp[2].id == 'B'));
    uint8_t *rows = malloc(3 * (size_t)w);

    if (!rows) {
        error_set(J->err, J->name, "out of memory for a %d x %d JPEG", J->width, J->height);
        return -1;
    }
    for (int y = 0; y < J->height; y++) {
        unsigned char *o = rgb + 3 * (size_t)y * (size_t)w;
        for (int i = 0; i < J->ncomp; i++)
            jpeg_upsample_row(J, &J->comp[i], y, rows + (size_t)i * (size_t)w);
        for (int x = 0; x < w; x++) {
            int luma = rows[x];
            if (J->ncomp == 1) {
                o[3 * x] = o[3 * x + 1] = o[3 * x + 2] = (uint8_t)luma;
            } else if (rgb_file) {
                o[3 * x] = (uint8_t)luma;
                o[3 * x + 1] = rows[w + x];
                o[3 * x + 2] = rows[2 * w + x];
            } else {
                int32_t cb = rows[w + x] - 128, cr = rows[2 * w + x] - 128;
                o[3 * x] = jpeg_byte(luma + ((JPEG_FIX16(1.40200) * cr + JPEG_HALF) >> JPEG_SCALE));
                o[3 * x + 1] = jpeg_byte(luma + ((-JPEG_FIX16(0.34414) * cb -
                                                  JPEG_FIX16(0.71414) * cr + JPEG_HALF) >>
                                                 JPEG_SCALE));
                o[3 * x + 2] = jpeg_byte(luma + ((JPEG_FIX16(1.77200) * cb + JPEG_HALF) >> JPEG_SCALE));
            }
        }
    }
    free(rows);
    return 0;
}
