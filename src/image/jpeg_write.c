/* jpeg_write.c: baseline JPEG files (ITU-T T.81), written without a
 * library (see jpeg.h). */
#include "image/jpeg.h"

#include <errno.h>
#include <stdint.h>
#include <stdlib.h>
#include <string.h>

#include "jpeg_tables.h"

/* T.81's example quantisation tables (annex K.1), in natural order: for
 * luminance and for chrominance, at quality 50. */
static const uint8_t jpeg_base_quant[2][64] = {
    {16, 11, 10, 16, 24,  40,  51,  61,  12, 12, 14, 19, 26,  58,  60,  55,
     14, 13, 16, 24, 40,  57,  69,  56,  14, 17, 22, 29, 51,  87,  80,  62,
     18, 22, 37, 56, 68,  109, 103, 77,  24, 35, 55, 64, 81,  104, 113, 92,
     49, 64, 78, 87, 103, 121, 120, 101, 72, 92, 95, 98, 112, 100, 103, 99},
    {17, 18, 24, 47, 99, 99, 99, 99, 18, 21, 26, 66, 99, 99, 99, 99,
     24, 26, 56, 99, 99, 99, 99, 99, 47, 66, 99, 99, 99, 99, 99, 99,
     99, 99, 99, 99, 99, 99, 99, 99, 99, 99, 99, 99, 99, 99, 99, 99,
     99, 99, 99, 99, 99, 99, 99, 99, 99, 99, 99, 99, 99, 99, 99, 99}};

/* The scale of coefficient k of Arai, Agui and Nakajima's DCT against the
 * true one: cos(k pi / 16) sqrt(2), 1 for k = 0. */
static const double jpeg_aan_scale[8] = {1.0,         1.387039845, 1.306562965, 1.175875602,
                                         1.0,         0.785694958, 0.541196100, 0.275899379};

/* A Huffman table built for the symbols one image uses (T.81, annex K.2). */
typedef struct {
    uint8_t bits[17];       /* bits[n]: codes of n bits, n = 1..16 */
    uint8_t values[256];    /* the symbols, shortest codes first */
    int count;              /* symbols in values */
    uint16_t code[256];     /* each symbol's code */
    uint8_t size[256];      /* and its length, 0 when unused */
    unsigned long freq[256]; /* how often each symbol occurs */
} JpegCode;

/* One component: its sampling and its quantised blocks. */
typedef struct {
    int h, v;        /* sampling factors: 2 2 for luma in 4:2:0, else 1 1 */
    int bw, bh;      /* blocks across and down, whole MCUs */
    int table;       /* quantisation and Huffman tables: 0 luma, 1 chroma */
    int16_t *coef;   /* 64 a block, zigzag order, block rows in turn */
} JpegPlane;

/* The writer: output buffer and bit accumulator. */
typedef struct {
    FILE *f;
    uint8_t buf[1 << 16];
    size_t used;
    uint32_t bits;   /* pending bits, the oldest highest */
    int nbits;
    int failed;      /* a write failed (errno set) */
} JpegOut;

static void jpeg_flush(JpegOut *o)
{
    if (o->used && !o->failed && fwrite(o->buf, 1, o->used, o->f) != o->used)
        o->failed = 1;
    o->used = 0;
}

static void jpeg_byte(JpegOut *o, unsigned b)
{
    if (o->used == sizeof o->buf)
        jpeg_flush(o);
    o->buf[o->used++] = (uint8_t)b;
}

static void jpeg_u16(JpegOut *o, unsigned v)
{
    jpeg_byte(o, v >> 8);
    jpeg_byte(o, v & 255);
}

/* Appends the n low bits of v (n <= 16) to the entropy-coded data, a 0 byte
 * after each 0xFF (T.81, F.1.2.3). */
static void jpeg_bits(JpegOut *o, unsigned v, int n)
{
    o->bits |= (uint32_t)(v & ((1u << n) - 1)) << (32 - o->nbits - n);
    o->nbits += n;
    while (o->nbits >= 8) {
        unsigned b = o->bits >> 24;
        jpeg_byte(o, b);
        if (b == 0xFF)
            jpeg_byte(o, 0);
        o->bits <<= 8;
        o->nbits -= 8;
    }
}

/* Returns the quantiser table `table` (0 luma, 1 chroma) at quality q, as
 * libjpeg scales T.81's examples: 5000 / q percent below 50, 200 - 2 q
 * from 50, each entry in 1..255 (baseline). */
static void jpeg_quant(int table, int q, uint8_t out[64])
{
    int scale = q < 50 ? 5000 / q : 200 - 2 * q;

    for (int k = 0; k < 64; k++) {
        long v = ((long)jpeg_base_quant[table][k] * scale + 50) / 100;
        out[k] = (uint8_t)(v < 1 ? 1 : v > 255 ? 255 : v);
    }
}

/* The forward DCT of one 8-point line, in place, by Arai, Agui and
 * Nakajima's factorisation (5 multiplications; T.81 annex A.3.3's DCT up
 * to the scale jpeg_aan_scale[k] of each output). */
static void jpeg_fdct8(double *d, int step)
{
    double t0 = d[0] + d[7 * step], t7 = d[0] - d[7 * step];
    double t1 = d[step] + d[6 * step], t6 = d[step] - d[6 * step];
    double t2 = d[2 * step] + d[5 * step], t5 = d[2 * step] - d[5 * step];
    double t3 = d[3 * step] + d[4 * step], t4 = d[3 * step] - d[4 * step];
    double t10 = t0 + t3, t13 = t0 - t3, t11 = t1 + t2, t12 = t1 - t2, z1, z2, z3, z4, z5;
    double z11, z13;

    d[0] = t10 + t11;
    d[4 * step] = t10 - t11;
    z1 = (t12 + t13) * 0.707106781;
    d[2 * step] = t13 + z1;
    d[6 * step] = t13 - z1;
    t10 = t4 + t5;
    t11 = t5 + t6;
    t12 = t6 + t7;
    z5 = (t10 - t12) * 0.382683433;
    z2 = 0.541196100 * t10 + z5;
    z4 = 1.306562965 * t12 + z5;
    z3 = t11 * 0.707106781;
    z11 = t7 + z3;
    z13 = t7 - z3;
    d[5 * step] = z13 + z2;
    d[3 * step] = z13 - z2;
    d[step] = z11 + z4;
    d[7 * step] = z11 - z4;
}

/* Transforms the 8 x 8 samples s (level-shifted) and quantises them by
 * div (1 / (quantiser x DCT scale), natural order) into out, zigzag
 * order, rounding half away from zero. */
static void jpeg_block(double s[64], const double div[64], int16_t out[64])
{
    for (int r = 0; r < 8; r++)
        jpeg_fdct8(s + 8 * r, 1);
    for (int c = 0; c < 8; c++)
        jpeg_fdct8(s + c, 8);
    for (int k = 0; k < 64; k++) {
        double v = s[jpeg_zigzag[k]] * div[jpeg_zigzag[k]];
        out[k] = (int16_t)(v < 0 ? -(int)(0.5 - v) : (int)(v + 0.5));
    }
}

/* The JFIF colour transform in 16-bit fixed point (as libjpeg's): Y, Cb
 * or Cr (c = 0, 1, 2) of the pixel r g b, 0..255, times 2^16. */
static inline int32_t jpeg_ycc(int c, int r, int g, int b)
{
    switch (c) {
    case 0:
        return 19595 * r + 38470 * g + 7471 * b + 32768;
    case 1:
        return -11059 * r - 21709 * g + 32768 * b + (128 << 16) + 32767;
    default:
        return 32768 * r - 27439 * g - 5329 * b + (128 << 16) + 32767;
    }
}

/* Returns the sample of component c at (x, y) of plane p: the pixel's, or
 * for a halved chroma the mean of the 2 x 2 pixels it covers; the image's
 * edge is repeated past it. */
static int jpeg_sample(const unsigned char *rgb, int w, int h, const JpegPlane *p, int c,
                       int sub, int x, int y)
{
    if (!sub) {
        const unsigned char *px = rgb + 3 * ((size_t)(y < h ? y : h - 1) * (size_t)w +
                                             (size_t)(x < w ? x : w - 1));
        return jpeg_ycc(c, px[0], px[1], px[2]) >> 16;
    }
    {
        int32_t sum = 0;
        (void)p;
        for (int dy = 0; dy < 2; dy++)
            for (int dx = 0; dx < 2; dx++) {
                int xx = 2 * x + dx, yy = 2 * y + dy;
                const unsigned char *px = rgb + 3 * ((size_t)(yy < h ? yy : h - 1) * (size_t)w +
                                                     (size_t)(xx < w ? xx : w - 1));
                sum += jpeg_ycc(c, px[0], px[1], px[2]) >> 16;
            }
        return (sum + 2) >> 2;
    }
}

/* Fills plane p (component c) with its quantised blocks. */
static void jpeg_plane(const unsigned char *rgb, int w, int h, JpegPlane *p, int c, int sub,
                       const uint8_t quant[64])
{
    double div[64];

    for (int k = 0; k < 64; k++)
        div[k] = 1 / ((double)quant[k] * jpeg_aan_scale[k / 8] * jpeg_aan_scale[k % 8] * 8);
#ifdef _OPENMP
#pragma omp parallel for schedule(static)
#endif
    for (int by = 0; by < p->bh; by++)
        for (int bx = 0; bx < p->bw; bx++) {
            double s[64];
            for (int y = 0; y < 8; y++)
                for (int x = 0; x < 8; x++)
                    s[8 * y + x] = jpeg_sample(rgb, w, h, p, c, sub, 8 * bx + x, 8 * by + y) - 128;
            jpeg_block(s, div, p->coef + 64 * ((size_t)by * (size_t)p->bw + (size_t)bx));
        }
}

/* Returns the bits needed for v's magnitude: its category (T.81, F.1.2). */
static inline int jpeg_category(int v)
{
    int n = 0;

    for (unsigned a = (unsigned)(v < 0 ? -v : v); a; a >>= 1)
        n++;
    return n;
}

/* Visits block blk's symbols in coding order (F.1.2): the DC difference
 * from *pred, then runs and levels; with o NULL counts them into dc and
 * ac, else writes them with the codes there. */
static void jpeg_code_block(JpegOut *o, const int16_t blk[64], int *pred, JpegCode *dc,
                            JpegCode *ac)
{
    int diff = blk[0] - *pred, n = jpeg_category(diff), run = 0;

    *pred = blk[0];
    if (o) {
        jpeg_bits(o, dc->code[n], dc->size[n]);
        if (n)
            jpeg_bits(o, (unsigned)(diff < 0 ? diff - 1 : diff), n);
    } else {
        dc->freq[n]++;
    }
    for (int k = 1; k < 64; k++) {
        int v = blk[k];
        if (v == 0) {
            run++;
            continue;
        }
        for (; run > 15; run -= 16) {
            if (o)
                jpeg_bits(o, ac->code[0xF0], ac->size[0xF0]);
            else
                ac->freq[0xF0]++;
        }
        n = jpeg_category(v);
        if (o) {
            jpeg_bits(o, ac->code[run << 4 | n], ac->size[run << 4 | n]);
            jpeg_bits(o, (unsigned)(v < 0 ? v - 1 : v), n);
        } else {
            ac->freq[run << 4 | n]++;
        }
        run = 0;
    }
    if (run) {
        if (o)
            jpeg_bits(o, ac->code[0], ac->size[0]);
        else
            ac->freq[0]++;
    }
}

/* Builds table t from the symbol frequencies in t->freq (T.81, annex K.2:
 * code lengths by Huffman's merge, with a reserved symbol so that no code
 * is all ones, then limited to 16 bits), and the codes (annex C). */
static void jpeg_build_code(JpegCode *t)
{
    unsigned long freq[257];
    int size[257], next[257], bits[33] = {0};

    for (int i = 0; i < 256; i++)
        freq[i] = t->freq[i];
    freq[256] = 1;
    for (int i = 0; i < 257; i++) {
        size[i] = 0;
        next[i] = -1;
    }
    for (;;) {
        int v1 = -1, v2 = -1;
        /* The least frequent, the largest value on ties; then the next. */
        for (int i = 0; i < 257; i++)
            if (freq[i] && (v1 < 0 || freq[i] <= freq[v1]))
                v1 = i;
        for (int i = 0; i < 257; i++)
            if (freq[i] && i != v1 && (v2 < 0 || freq[i] <= freq[v2]))
                v2 = i;
        if (v2 < 0)
            break;
        freq[v1] += freq[v2];
        freq[v2] = 0;
        size[v1]++;
        while (next[v1] >= 0) {
            v1 = next[v1];
            size[v1]++;
        }
        next[v1] = v2;
        size[v2]++;
        while (next[v2] >= 0) {
            v2 = next[v2];
            size[v2]++;
        }
    }
    for (int i = 0; i < 257; i++)
        if (size[i])
            bits[size[i]]++;
    /* Longer than 16 bits: move pairs of leaves up (annex K, figure K.3). */
    for (int i = 32; i > 16;) {
        if (bits[i] > 0) {
            int j = i - 2;
            while (bits[j] == 0)
                j--;
            bits[i] -= 2;
            bits[i - 1]++;
            bits[j + 1] += 2;
            bits[j]--;
        } else {
            i--;
        }
    }
    {
        int i = 16;
        while (bits[i] == 0)
            i--;
        bits[i]--; /* the reserved symbol's code */
    }
    t->count = 0;
    for (int n = 1; n <= 32; n++)
        for (int i = 0; i < 256; i++)
            if (size[i] == n)
                t->values[t->count++] = (uint8_t)i;
    memset(t->size, 0, sizeof t->size);
    {
        unsigned code = 0;
        int k = 0;
        for (int n = 1; n <= 16; n++) {
            t->bits[n] = (uint8_t)bits[n];
            for (int i = 0; i < bits[n]; i++, k++) {
                t->code[t->values[k]] = (uint16_t)code++;
                t->size[t->values[k]] = (uint8_t)n;
            }
            code <<= 1;
        }
    }
}

/* Writes marker m and a segment length of len bytes (length included). */
static void jpeg_marker(JpegOut *o, unsigned m, unsigned len)
{
    jpeg_byte(o, 0xFF);
    jpeg_byte(o, m);
    jpeg_u16(o, len);
}

/* Writes table t as class tc (0 DC, 1 AC), number th. */
static void jpeg_dht(JpegOut *o, const JpegCode *t, int tc, int th)
{
    jpeg_marker(o, 0xC4, 2 + 1 + 16 + (unsigned)t->count);
    jpeg_byte(o, (unsigned)(tc << 4 | th));
    for (int n = 1; n <= 16; n++)
        jpeg_byte(o, t->bits[n]);
    for (int i = 0; i < t->count; i++)
        jpeg_byte(o, t->values[i]);
}

/* Visits every block in scan order (MCU by MCU, each component's blocks
 * row by row within it), counting (o NULL) or writing. */
static void jpeg_scan(JpegOut *o, JpegPlane p[3], int mx, int my, JpegCode dc[2],
                      JpegCode ac[2])
{
    int pred[3] = {0, 0, 0};

    for (int y = 0; y < my; y++)
        for (int x = 0; x < mx; x++)
            for (int c = 0; c < 3; c++)
                for (int v = 0; v < p[c].v; v++)
                    for (int h = 0; h < p[c].h; h++) {
                        size_t bx = (size_t)(x * p[c].h + h), by = (size_t)(y * p[c].v + v);
                        jpeg_code_block(o, p[c].coef + 64 * (by * (size_t)p[c].bw + bx),
                                        &pred[c], &dc[p[c].table], &ac[p[c].table]);
                    }
}

size_t jpeg_write_memory(int width, int height, int subsample)
{
    size_t mcu = subsample ? 16 : 8;
    size_t blocks = ((size_t)width + mcu - 1) / mcu * (((size_t)height + mcu - 1) / mcu) *
                    (subsample ? 6 : 3);

    return blocks * 64 * sizeof(int16_t) + sizeof(JpegOut) + 4 * sizeof(JpegCode);
}

/* Writes the headers before the scan: SOI, JFIF, the quantisation tables,
 * the frame (SOF0) of planes p, the Huffman tables and the scan's (SOS). */
static void jpeg_headers(JpegOut *o, int width, int height, const JpegPlane p[3],
                         uint8_t quant[2][64], const JpegCode dc[2], const JpegCode ac[2])
{
    static const uint8_t jfif[14] = {'J', 'F', 'I', 'F', 0, 1, 1, 0, 0, 1, 0, 1, 0, 0};

    jpeg_byte(o, 0xFF); /* SOI */
    jpeg_byte(o, 0xD8);
    jpeg_marker(o, 0xE0, 16); /* JFIF 1.01, no density */
    for (int k = 0; k < 14; k++)
        jpeg_byte(o, jfif[k]);
    for (int t = 0; t < 2; t++) { /* DQT, zigzag order, 8-bit */
        jpeg_marker(o, 0xDB, 2 + 65);
        jpeg_byte(o, (unsigned)t);
        for (int k = 0; k < 64; k++)
            jpeg_byte(o, quant[t][jpeg_zigzag[k]]);
    }
    jpeg_marker(o, 0xC0, 8 + 3 * 3); /* SOF0: baseline */
    jpeg_byte(o, 8);
    jpeg_u16(o, (unsigned)height);
    jpeg_u16(o, (unsigned)width);
    jpeg_byte(o, 3);
    for (int c = 0; c < 3; c++) {
        jpeg_byte(o, (unsigned)c + 1);
        jpeg_byte(o, (unsigned)(p[c].h << 4 | p[c].v));
        jpeg_byte(o, (unsigned)p[c].table);
    }
    for (int t = 0; t < 2; t++) {
        jpeg_dht(o, &dc[t], 0, t);
        jpeg_dht(o, &ac[t], 1, t);
    }
    jpeg_marker(o, 0xDA, 6 + 2 * 3); /* SOS: one interleaved scan */
    jpeg_byte(o, 3);
    for (int c = 0; c < 3; c++) {
        jpeg_byte(o, (unsigned)c + 1);
        jpeg_byte(o, (unsigned)(p[c].table << 4 | p[c].table));
    }
    jpeg_byte(o, 0);
    jpeg_byte(o, 63);
    jpeg_byte(o, 0);
}

/* Lays out planes p for mx x my MCUs (luma 2 x 2 blocks an MCU when
 * subsampled) and allocates their coefficients; returns 0, or -1 with
 * none allocated. */
static int jpeg_planes(JpegPlane p[3], int mx, int my, int subsample)
{
    int rc = 0;

    memset(p, 0, 3 * sizeof *p);
    for (int c = 0; c < 3; c++) {
        p[c].h = p[c].v = c == 0 && subsample ? 2 : 1;
        p[c].bw = mx * p[c].h;
        p[c].bh = my * p[c].v;
        p[c].table = c > 0;
        p[c].coef = malloc((size_t)p[c].bw * (size_t)p[c].bh * 64 * sizeof *p[c].coef);
        if (!p[c].coef)
            rc = -1;
    }
    if (rc != 0)
        for (int c = 0; c < 3; c++) {
            free(p[c].coef);
            p[c].coef = NULL;
        }
    return rc;
}

int jpeg_write(FILE *f, int width, int height, const unsigned char *rgb, int quality,
               int subsample)
{
    JpegPlane p[3];
    JpegCode dc[2], ac[2];
    JpegOut *o = malloc(sizeof *o);
    uint8_t quant[2][64];
    int mcu = subsample ? 16 : 8;
    int mx = (width + mcu - 1) / mcu, my = (height + mcu - 1) / mcu, rc;

    if (!o || jpeg_planes(p, mx, my, subsample) != 0) {
        free(o);
        errno = ENOMEM;
        return -1;
    }
    quality = quality < 1 ? 1 : quality > 100 ? 100 : quality;
    jpeg_quant(0, quality, quant[0]);
    jpeg_quant(1, quality, quant[1]);
    for (int c = 0; c < 3; c++)
        jpeg_plane(rgb, width, height, &p[c], c, c > 0 && subsample, quant[p[c].table]);
    memset(dc, 0, sizeof dc);
    memset(ac, 0, sizeof ac);
    jpeg_scan(NULL, p, mx, my, dc, ac); /* counts the symbols */
    for (int t = 0; t < 2; t++) {
        jpeg_build_code(&dc[t]);
        jpeg_build_code(&ac[t]);
    }
    memset(o, 0, sizeof *o);
    o->f = f;
    jpeg_headers(o, width, height, p, quant, dc, ac);
    jpeg_scan(o, p, mx, my, dc, ac);
    if (o->nbits > 0) /* pad with ones (F.1.2.3) */
        jpeg_bits(o, 0x7F, 8 - o->nbits);
    jpeg_byte(o, 0xFF); /* EOI */
    jpeg_byte(o, 0xD9);
    jpeg_flush(o);
    rc = o->failed ? -1 : 0;
    for (int c = 0; c < 3; c++)
        free(p[c].coef);
    free(o);
    return rc;
}
