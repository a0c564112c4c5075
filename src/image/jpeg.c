/* jpeg.c: reading JPEG files (see jpeg.h; ITU-T T.81). */
#include "image/jpeg.h"

#include <stdint.h>
#include <stdlib.h>
#include <string.h>

#include "base/file.h"
#include "math/number.h"
#include "jpeg_tables.h"

enum {
    JPEG_MAX_SIDE = 65535, /* the frame header's 16 bits */
    JPEG_FAST_BITS = 9     /* codes this long or shorter are looked up at once */
};

/* A Huffman table, as decoding needs it. */
typedef struct {
    uint8_t fast_len[1 << JPEG_FAST_BITS]; /* code length of a 9-bit prefix, 0: longer */
    uint8_t fast_sym[1 << JPEG_FAST_BITS]; /* its symbol */
    int32_t maxcode[18];                   /* largest code of each length, -1: none */
    int32_t delta[17];                     /* symbol index of a code = code + delta */
    uint8_t symbols[256];
    int defined;
} JpegHuffman;

/* A component of the frame and its decoding state. */
typedef struct {
    int id, h, v, tq;       /* from the frame header */
    int width, height;      /* its samples: ceil(X h / hmax), ceil(Y v / vmax) */
    int bw, bh;             /* blocks across and down, whole MCUs */
    int16_t *coef;          /* 64 per block, natural order, as decoded */
    uint16_t quant[64];     /* the table, latched at its first scan */
    int latched;
    int dc, ac;             /* the current scan's tables */
    int pred;               /* DC predictor */
    int seen;               /* in some scan */
    unsigned char *plane;   /* samples, width x height, after the IDCT */
} JpegComponent;

/* The decoder's state. */
typedef struct {
    const char *name;
    Error *err;
    const uint8_t *data;
    size_t len, pos;
    size_t max_bytes;
    /* The frame. */
    int width, height, ncomp, progressive, frame;
    int hmax, vmax, mcux, mcuy;
    JpegComponent comp[4];
    uint16_t qt[4][64];
    int qt_defined[4];
    JpegHuffman dc[4], ac[4];
    int restart;            /* MCUs between restart markers, 0: none */
    int adobe, transform;   /* an Adobe marker and its colour transform */
    int orientation;        /* Exif: 1 to 8 */
    /* The entropy-coded data of a scan. */
    uint32_t bits;          /* bits not yet used, the next at bit 31 */
    int nbits;
    int marker;             /* a marker met in the data (then zeros follow) */
    int pad;                /* zero bits fed past a marker or the end */
    int eobrun;
} Jpeg;

/* Records a fault "at byte OFFSET: MESSAGE"; returns -1. */
static int jpeg_fail(Jpeg *J, const char *fmt, const char *what)
{
    char msg[200];

    snprintf(msg, sizeof msg, fmt, what ? what : "");
    error_set(J->err, J->name, "at byte %zu: %s", J->pos, msg);
    return -1;
}

/* Records that the file uses something this reader does not; returns -1. */
static int jpeg_unsupported(Jpeg *J, const char *what)
{
    error_set(J->err, J->name, "unsupported JPEG: %s", what);
    return -1;
}

/* Reads a big-endian 16-bit number at byte i (which must be there). */
static int jpeg_u16(const uint8_t *p)
{
    return p[0] << 8 | p[1];
}

/* ---- Huffman tables and the bit reader ---- */

/* Builds table h from the 16 counts and the symbols after them (T.81,
 * annex C); returns 0, or -1 when the counts describe no code. */
static int jpeg_build(JpegHuffman *h, const uint8_t counts[16], const uint8_t *symbols, int n)
{
    int32_t code = 0;
    int k = 0;

    memset(h->fast_len, 0, sizeof h->fast_len);
    memcpy(h->symbols, symbols, (size_t)n);
    for (int len = 1; len <= 16; len++) {
        h->delta[len] = k - code;
        for (int i = 0; i < counts[len - 1]; i++, k++, code++) {
            /* Codes must fit in len bits (checked before they index). */
            if (code >= (1 << len))
                return -1;
            if (len <= JPEG_FAST_BITS) {
                int shift = JPEG_FAST_BITS - len;
                for (int j = 0; j < 1 << shift; j++) {
                    h->fast_len[(code << shift) | j] = (uint8_t)len;
                    h->fast_sym[(code << shift) | j] = symbols[k];
                }
            }
        }
        h->maxcode[len] = counts[len - 1] ? code - 1 : -1;
        code <<= 1;
    }
    h->maxcode[17] = INT32_MAX;
    h->defined = 1;
    return 0;
}

/* Tops up J's bit buffer to at least 25 bits, zeros once the data ends or
 * reaches a marker (T.81, F.2.2.5: the decoder pads with zeros). */
static void jpeg_fill(Jpeg *J)
{
    while (J->nbits <= 24) {
        uint32_t byte = 0;
        if (J->marker || J->pos >= J->len)
            J->pad += 8;
        if (!J->marker && J->pos < J->len) {
            byte = J->data[J->pos];
            if (byte == 0xFF) {
                uint8_t next = J->pos + 1 < J->len ? J->data[J->pos + 1] : 0xD9;
                if (next == 0x00) {
                    J->pos += 2; /* a stuffed zero */
                } else if (next == 0xFF) {
                    J->pos++; /* fill bytes before a marker */
                    continue;
                } else {
                    J->marker = next; /* stop here; the marker is read later */
                    J->pad += 8;
                    byte = 0;
                }
            } else {
                J->pos++;
            }
        }
        J->bits |= byte << (24 - J->nbits);
        J->nbits += 8;
    }
}

/* Returns the next n bits (0 <= n <= 16). */
static int jpeg_bits(Jpeg *J, int n)
{
    int v;

    if (n == 0)
        return 0;
    jpeg_fill(J);
    v = (int)(J->bits >> (32 - n));
    J->bits <<= n;
    J->nbits -= n;
    return v;
}

/* Returns the next n bits as a signed value: T.81's EXTEND. */
static int jpeg_signed(Jpeg *J, int n)
{
    int v = jpeg_bits(J, n);

    return n && v < 1 << (n - 1) ? v - (1 << n) + 1 : v;
}

/* Decodes a symbol with table h; returns it, or -1 at a bad code. */
static int jpeg_symbol(Jpeg *J, const JpegHuffman *h)
{
    int peek, len;
    int32_t code;

    jpeg_fill(J);
    peek = (int)(J->bits >> (32 - JPEG_FAST_BITS));
    len = h->fast_len[peek];
    if (len) {
        J->bits <<= len;
        J->nbits -= len;
        return h->fast_sym[peek];
    }
    code = (int32_t)(J->bits >> (32 - JPEG_FAST_BITS));
    for (len = JPEG_FAST_BITS + 1; len <= 16; len++) {
        code = (int32_t)(J->bits >> (32 - len));
        if (code <= h->maxcode[len])
            break;
    }
    if (len > 16)
        return -1;
    J->bits <<= len;
    J->nbits -= len;
    return h->symbols[(code + h->delta[len]) & 0xFF];
}

/* ---- Markers ---- */

/* Reads a segment's length at J->pos (just after its marker); returns the
 * payload's length and moves to it, or -1 when it runs past the data. */
static int jpeg_segment(Jpeg *J)
{
    int n;

    if (J->pos + 2 > J->len)
        return jpeg_fail(J, "the file ends inside a marker segment%s", NULL);
    n = jpeg_u16(J->data + J->pos);
    if (n < 2 || J->pos + (size_t)n > J->len)
        return jpeg_fail(J, "a marker segment runs past the end of the file%s", NULL);
    J->pos += 2;
    return n - 2;
}

/* DQT: quantisation tables, 8 or 16 bits. */
static int jpeg_dqt(Jpeg *J, int n)
{
    const uint8_t *p = J->data + J->pos, *end = p + n;

    while (p < end) {
        int pq = p[0] >> 4, tq = p[0] & 15, size = pq ? 128 : 64;
        if (tq > 3 || pq > 1 || end - p < 1 + size)
            return jpeg_fail(J, "bad quantisation table%s", NULL);
        for (int k = 0; k < 64; k++)
            J->qt[tq][jpeg_zigzag[k]] = (uint16_t)(pq ? jpeg_u16(p + 1 + 2 * k) : p[1 + k]);
        J->qt_defined[tq] = 1;
        p += 1 + size;
    }
    return 0;
}

/* DHT: Huffman tables. */
static int jpeg_dht(Jpeg *J, int n)
{
    const uint8_t *p = J->data + J->pos, *end = p + n;

    while (p < end) {
        int tc = p[0] >> 4, th = p[0] & 15, total = 0;
        if (tc > 1 || th > 3 || end - p < 17)
            return jpeg_fail(J, "bad Huffman table%s", NULL);
        for (int i = 0; i < 16; i++)
            total += p[1 + i];
        if (total > 256 || end - p < 17 + total ||
            jpeg_build(tc ? &J->ac[th] : &J->dc[th], p + 1, p + 17, total) != 0)
            return jpeg_fail(J, "bad Huffman table%s", NULL);
        p += 17 + total;
    }
    return 0;
}

/* SOFn: the frame. */
static int jpeg_sof(Jpeg *J, int marker, int n)
{
    const uint8_t *p = J->data + J->pos;

    if (J->frame)
        return jpeg_fail(J, "a second frame header%s", NULL);
    switch (marker) {
    case 0xC0:
    case 0xC1:
        break;
    case 0xC2:
        J->progressive = 1;
        break;
    case 0xC3:
    case 0xC7:
        return jpeg_unsupported(J, "lossless coding");
    case 0xC5:
    case 0xC6:
        return jpeg_unsupported(J, "hierarchical coding");
    default: /* 0xC9 to 0xCF, but 0xCC (DAC) */
        return jpeg_unsupported(J, "arithmetic coding");
    }
    if (n < 6)
        return jpeg_fail(J, "the frame header is too short%s", NULL);
    if (p[0] != 8) {
        char what[64];
        snprintf(what, sizeof what, "%d-bit samples (8-bit only)", p[0]);
        return jpeg_unsupported(J, what);
    }
    J->height = jpeg_u16(p + 1);
    J->width = jpeg_u16(p + 3);
    J->ncomp = p[5];
    if (J->ncomp == 4)
        return jpeg_unsupported(J, "four components (CMYK or YCCK)");
    if (J->ncomp != 1 && J->ncomp != 3)
        return jpeg_fail(J, "%s", J->ncomp == 0 ? "the frame has no component"
                                                 : "the frame has 2 components (1 or 3 are read)");
    if (J->width == 0 || J->height == 0)
        return jpeg_fail(J, "%s", J->width == 0 ? "the image is 0 pixels wide"
                                                 : "the image height is 0 (a DNL marker)");
    if (n < 6 + 3 * J->ncomp)
        return jpeg_fail(J, "the frame header is too short%s", NULL);
    J->hmax = J->vmax = 1;
    for (int i = 0; i < J->ncomp; i++) {
        JpegComponent *c = &J->comp[i];
        c->id = p[6 + 3 * i];
        c->h = p[7 + 3 * i] >> 4;
        c->v = p[7 + 3 * i] & 15;
        c->tq = p[8 + 3 * i];
        if (c->h < 1 || c->h > 4 || c->v < 1 || c->v > 4 || c->tq > 3)
            return jpeg_fail(J, "a component has bad sampling factors or table%s", NULL);
        for (int j = 0; j < i; j++)
            if (J->comp[j].id == c->id)
                return jpeg_fail(J, "two components have one identifier%s", NULL);
        J->hmax = c->h > J->hmax ? c->h : J->hmax;
        J->vmax = c->v > J->vmax ? c->v : J->vmax;
    }
    J->mcux = (J->width + 8 * J->hmax - 1) / (8 * J->hmax);
    J->mcuy = (J->height + 8 * J->vmax - 1) / (8 * J->vmax);
    for (int i = 0; i < J->ncomp; i++) {
        JpegComponent *c = &J->comp[i];
        if (J->hmax % c->h || J->vmax % c->v)
            return jpeg_unsupported(J, "sampling factors whose ratios are not whole");
        c->width = (int)(((long)J->width * c->h + J->hmax - 1) / J->hmax);
        c->height = (int)(((long)J->height * c->v + J->vmax - 1) / J->vmax);
        c->bw = J->mcux * c->h;
        c->bh = J->mcuy * c->v;
    }
    J->frame = 1;
    return 0;
}

/* Returns the bytes decoding the frame takes: the coefficients, the
 * planes, the RGB output and a row of upsampling, with some slack. */
static size_t jpeg_memory(const Jpeg *J)
{
    size_t m = 3 * (size_t)J->width * (size_t)J->height + 4 * (size_t)J->width + 4096;

    for (int i = 0; i < J->ncomp; i++) {
        size_t blocks = (size_t)J->comp[i].bw * (size_t)J->comp[i].bh;
        m += blocks * 64 * (sizeof(int16_t) + 1);
    }
    return m;
}

/* Allocates the frame's coefficients, once, within the budget. */
static int jpeg_allocate(Jpeg *J)
{
    size_t need = jpeg_memory(J), blocks = 0;

    /* Every block of a first scan takes a bit or more. */
    for (int i = 0; i < J->ncomp; i++)
        blocks += (size_t)((J->comp[i].width + 7) / 8) * (size_t)((J->comp[i].height + 7) / 8);
    if (blocks / 8 > J->len) {
        error_set(J->err, J->name,
                  "a %d x %d JPEG cannot fit in %zu bytes: the file is truncated or its "
                  "header is wrong",
                  J->width, J->height, J->len);
        return -1;
    }
    if (J->max_bytes && need > J->max_bytes) {
        char a[NUMBER_FORMAT_MAX], b[NUMBER_FORMAT_MAX];
        error_set(J->err, J->name,
                  "a %d x %d JPEG needs %s to decode, more than the %s the memory limit "
                  "leaves (raise it with --memory-limit)",
                  J->width, J->height, number_bytes(a, need), number_bytes(b, J->max_bytes));
        return -1;
    }
    for (int i = 0; i < J->ncomp; i++) {
        JpegComponent *c = &J->comp[i];
        c->coef = calloc((size_t)c->bw * (size_t)c->bh * 64, sizeof *c->coef);
        if (!c->coef) {
            error_set(J->err, J->name, "out of memory for a %d x %d JPEG", J->width, J->height);
            return -1;
        }
    }
    return 0;
}

/* APP1 Exif: the orientation tag of IFD0 (TIFF, either byte order). */
static void jpeg_exif(Jpeg *J, int n)
{
    const uint8_t *p = J->data + J->pos, *t;
    size_t len;
    int le, entries;
    uint32_t ifd;

    if (n < 14 || memcmp(p, "Exif\0\0", 6) != 0)
        return;
    t = p + 6;
    len = (size_t)n - 6;
    le = t[0] == 'I';
    if (!((t[0] == 'I' && t[1] == 'I') || (t[0] == 'M' && t[1] == 'M')))
        return;
#define EXIF16(q) (le ? (q)[0] | (q)[1] << 8 : (q)[0] << 8 | (q)[1])
#define EXIF32(q) (le ? (uint32_t)(q)[0] | (uint32_t)(q)[1] << 8 | (uint32_t)(q)[2] << 16 | (uint32_t)(q)[3] << 24 \
                      : (uint32_t)(q)[0] << 24 | (uint32_t)(q)[1] << 16 | (uint32_t)(q)[2] << 8 | (uint32_t)(q)[3])
    ifd = EXIF32(t + 4);
    if (ifd > len - 2)
        return;
    entries = EXIF16(t + ifd);
    for (int i = 0; i < entries; i++) {
        size_t at = ifd + 2 + 12 * (size_t)i;
        if (at + 12 > len)
            return;
        if (EXIF16(t + at) == 0x0112 && EXIF16(t + at + 2) == 3) {
            int o = EXIF16(t + at + 8);
            if (o >= 1 && o <= 8)
                J->orientation = o;
            return;
        }
    }
#undef EXIF16
#undef EXIF32
}

/* ---- Scans ---- */

/* The scan being decoded. */
typedef struct {
    int n;                 /* components in it */
    JpegComponent *c[4];
    int ss, se, ah, al;    /* spectral selection and successive approximation */
} JpegScan;

/* Decodes one block of a sequential scan into blk. */
static int jpeg_block(Jpeg *J, JpegComponent *c, int16_t *blk)
{
    int t = jpeg_symbol(J, &J->dc[c->dc]);

    if (t < 0 || t > 11)
        return jpeg_fail(J, "bad Huffman code in a DC coefficient%s", NULL);
    c->pred += jpeg_signed(J, t);
    blk[0] = (int16_t)c->pred;
    for (int k = 1; k < 64;) {
        int rs = jpeg_symbol(J, &J->ac[c->ac]), r, s;
        if (rs < 0)
            return jpeg_fail(J, "bad Huffman code in an AC coefficient%s", NULL);
        r = rs >> 4;
        s = rs & 15;
        if (s == 0) {
            if (r != 15)
                break;
            k += 16;
            continue;
        }
        k += r;
        if (k > 63)
            return jpeg_fail(J, "an AC coefficient beyond the block's 64%s", NULL);
        blk[jpeg_zigzag[k++]] = (int16_t)jpeg_signed(J, s);
    }
    return 0;
}

/* Decodes one block of a progressive DC scan. */
static int jpeg_dc_progressive(Jpeg *J, const JpegScan *s, JpegComponent *c, int16_t *blk)
{
    if (s->ah == 0) {
        int t = jpeg_symbol(J, &J->dc[c->dc]);
        if (t < 0 || t > 11)
            return jpeg_fail(J, "bad Huffman code in a DC coefficient%s", NULL);
        c->pred += jpeg_signed(J, t);
        blk[0] = (int16_t)(c->pred * (1 << s->al));
    } else if (jpeg_bits(J, 1)) {
        blk[0] = (int16_t)(blk[0] | 1 << s->al);
    }
    return 0;
}

/* Decodes one block of a progressive AC scan's first pass. */
static int jpeg_ac_first(Jpeg *J, const JpegScan *s, JpegComponent *c, int16_t *blk)
{
    if (J->eobrun > 0) {
        J->eobrun--;
        return 0;
    }
    for (int k = s->ss; k <= s->se;) {
        int rs = jpeg_symbol(J, &J->ac[c->ac]), r, z;
        if (rs < 0)
            return jpeg_fail(J, "bad Huffman code in an AC coefficient%s", NULL);
        r = rs >> 4;
        z = rs & 15;
        if (z == 0) {
            if (r < 15) { /* an end-of-band run of 2^r + bits - 1 more blocks */
                J->eobrun = (1 << r) - 1 + jpeg_bits(J, r);
                break;
            }
            k += 16;
            continue;
        }
        k += r;
        if (k > 63)
            return jpeg_fail(J, "an AC coefficient beyond the block's 64%s", NULL);
        blk[jpeg_zigzag[k++]] = (int16_t)(jpeg_signed(J, z) * (1 << s->al));
    }
    return 0;
}

/* Adds the next correction bit to the non-zero coefficient *x of a
 * refinement pass. */
static void jpeg_correct(Jpeg *J, int16_t *x, int bit)
{
    if (jpeg_bits(J, 1) && (*x & bit) == 0)
        *x = (int16_t)(*x >= 0 ? *x + bit : *x - bit);
}

/* Decodes one block of a progressive AC scan's refinement (T.81,
 * G.1.2.3): new coefficients of magnitude 1 << al, and a correction bit
 * for each that is already non-zero. */
static int jpeg_ac_refine(Jpeg *J, const JpegScan *s, JpegComponent *c, int16_t *blk)
{
    int bit = 1 << s->al, k = s->ss;

    if (J->eobrun == 0) {
        for (; k <= s->se; k++) {
            int rs = jpeg_symbol(J, &J->ac[c->ac]), r, value = 0;
            if (rs < 0)
                return jpeg_fail(J, "bad Huffman code in an AC refinement%s", NULL);
            r = rs >> 4;
            if ((rs & 15) != 0) {
                if ((rs & 15) != 1)
                    return jpeg_fail(J, "a refinement's new coefficient is not 1 or -1%s", NULL);
                value = jpeg_bits(J, 1) ? bit : -bit;
            } else if (r != 15) {
                J->eobrun = (1 << r) + jpeg_bits(J, r);
                break;
            }
            /* Skip r zero coefficients, correcting the non-zero ones on the
             * way; the new one goes in the next zero. */
            for (; k <= s->se; k++) {
                int16_t *x = &blk[jpeg_zigzag[k]];
                if (*x != 0) {
                    jpeg_correct(J, x, bit);
                } else {
                    if (r == 0)
                        break;
                    r--;
                }
            }
            if (value && k <= s->se)
                blk[jpeg_zigzag[k]] = (int16_t)value;
        }
    }
    if (J->eobrun > 0) {
        for (; k <= s->se; k++) {
            int16_t *x = &blk[jpeg_zigzag[k]];
            if (*x != 0)
                jpeg_correct(J, x, bit);
        }
        J->eobrun--;
    }
    return 0;
}

/* Decodes the block at (bx, by) of component c in scan s. */
static int jpeg_decode_block(Jpeg *J, const JpegScan *s, JpegComponent *c, int bx, int by)
{
    int16_t *blk = c->coef + 64 * ((size_t)by * (size_t)c->bw + (size_t)bx);

    if (!J->progressive)
        return jpeg_block(J, c, blk);
    if (s->ss == 0)
        return jpeg_dc_progressive(J, s, c, blk);
    return s->ah == 0 ? jpeg_ac_first(J, s, c, blk) : jpeg_ac_refine(J, s, c, blk);
}

/* Says, recording the fault, whether the scan's data ran out: bits past a
 * marker or the file's end were decoded (a truncated or damaged file). */
static int jpeg_ran_out(Jpeg *J)
{
    if (J->pad <= J->nbits)
        return 0;
    jpeg_fail(J, "%s", J->pos >= J->len ? "the file ends inside the image data (truncated)"
                                        : "the image data ends early, at a marker (damaged)");
    return 1;
}

/* At a restart interval's end: the RSTn marker, then fresh predictors and
 * bits. A missing marker is passed over (the data is decoded on). */
static void jpeg_restart(Jpeg *J, const JpegScan *s)
{
    J->bits = 0;
    J->nbits = 0;
    J->pad = 0;
    if (J->marker >= 0xD0 && J->marker <= 0xD7) {
        J->pos += 2;
        J->marker = 0;
    }
    for (int i = 0; i < s->n; i++)
        s->c[i]->pred = 0;
    J->eobrun = 0;
}

/* Decodes the entropy-coded data of scan s. */
static int jpeg_scan_data(Jpeg *J, const JpegScan *s)
{
    long mcus, todo;
    int across;

    J->bits = 0;
    J->nbits = 0;
    J->marker = 0;
    J->pad = 0;
    J->eobrun = 0;
    for (int i = 0; i < s->n; i++)
        s->c[i]->pred = 0;
    if (s->n == 1) { /* not interleaved: the component's own blocks */
        JpegComponent *c = s->c[0];
        across = (c->width + 7) / 8;
        mcus = (long)across * ((c->height + 7) / 8);
    } else {
        across = J->mcux;
        mcus = (long)J->mcux * J->mcuy;
    }
    todo = J->restart ? J->restart : mcus;
    for (long m = 0; m < mcus; m++) {
        int mx = (int)(m % across), my = (int)(m / across);
        if (todo == 0) {
            if (jpeg_ran_out(J))
                return -1;
            jpeg_restart(J, s);
            todo = J->restart;
        }
        todo--;
        if (s->n == 1) {
            if (jpeg_decode_block(J, s, s->c[0], mx, my) != 0)
                return -1;
            continue;
        }
        for (int i = 0; i < s->n; i++) {
            JpegComponent *c = s->c[i];
            for (int y = 0; y < c->v; y++)
                for (int x = 0; x < c->h; x++)
                    if (jpeg_decode_block(J, s, c, mx * c->h + x, my * c->v + y) != 0)
                        return -1;
        }
    }
    if (jpeg_ran_out(J))
        return -1;
    /* Move to the marker after the data. */
    while (J->pos < J->len && !(J->data[J->pos] == 0xFF && J->pos + 1 < J->len &&
                                J->data[J->pos + 1] != 0x00 &&
                                !(J->data[J->pos + 1] >= 0xD0 && J->data[J->pos + 1] <= 0xD7) &&
                                J->data[J->pos + 1] != 0xFF))
        J->pos++;
    return 0;
}

/* SOS: a scan's header, then its data. */
static int jpeg_sos(Jpeg *J, int n)
{
    const uint8_t *p = J->data + J->pos;
    JpegScan s;

    if (!J->frame)
        return jpeg_fail(J, "a scan before the frame header%s", NULL);
    if (n < 1 || (s.n = p[0]) < 1 || s.n > J->ncomp || n < 4 + 2 * s.n)
        return jpeg_fail(J, "bad scan header%s", NULL);
    for (int i = 0; i < s.n; i++) {
        int id = p[1 + 2 * i], tables = p[2 + 2 * i], k = 0;
        while (k < J->ncomp && J->comp[k].id != id)
            k++;
        if (k == J->ncomp)
            return jpeg_fail(J, "a scan names a component the frame lacks%s", NULL);
        s.c[i] = &J->comp[k];
        s.c[i]->dc = tables >> 4;
        s.c[i]->ac = tables & 15;
        if (s.c[i]->dc > 3 || s.c[i]->ac > 3)
            return jpeg_fail(J, "a scan names a Huffman table above 3%s", NULL);
    }
    s.ss = p[1 + 2 * s.n];
    s.se = p[2 + 2 * s.n];
    s.ah = p[3 + 2 * s.n] >> 4;
    s.al = p[3 + 2 * s.n] & 15;
    if (J->progressive) {
        if (s.se > 63 || s.ss > s.se || (s.ss == 0 && s.se != 0) || (s.ss > 0 && s.n != 1) ||
            s.ah > 13 || s.al > 13)
            return jpeg_fail(J, "bad progressive scan parameters%s", NULL);
    } else {
        s.ss = 0;
        s.se = 63;
        s.ah = s.al = 0;
    }
    for (int i = 0; i < s.n; i++) {
        JpegComponent *c = s.c[i];
        int needs_dc = !J->progressive || (s.ss == 0 && s.ah == 0);
        int needs_ac = !J->progressive || s.ss > 0;
        if ((needs_dc && !J->dc[c->dc].defined) || (needs_ac && !J->ac[c->ac].defined))
            return jpeg_fail(J, "a scan uses a Huffman table not defined before it%s", NULL);
        if (!c->latched) {
            if (!J->qt_defined[c->tq])
                return jpeg_fail(J, "a component's quantisation table is not defined%s", NULL);
            memcpy(c->quant, J->qt[c->tq], sizeof c->quant);
            c->latched = 1;
        }
        c->seen = 1;
    }
    if (!J->comp[0].coef && jpeg_allocate(J) != 0)
        return -1;
    J->pos += (size_t)n;
    return jpeg_scan_data(J, &s);
}

/* Reads the markers from SOI to EOI (or the data's end after a scan). */
static int jpeg_markers(Jpeg *J)
{
    int scans = 0;

    if (!jpeg_is(J->data, J->len)) {
        error_set(J->err, J->name, "not a JPEG file (no SOI marker at the start)");
        return -1;
    }
    J->pos = 2;
    for (;;) {
        int marker, n;
        if (J->pos >= J->len) {
            if (scans > 0)
                return 0; /* no EOI: what came is decoded */
            return jpeg_fail(J, "the file ends before any image data%s", NULL);
        }
        if (J->data[J->pos] != 0xFF)
            return jpeg_fail(J, "expected a marker%s", NULL);
        while (J->pos < J->len && J->data[J->pos] == 0xFF)
            J->pos++;
        if (J->pos >= J->len)
            continue;
        marker = J->data[J->pos++];
        if (marker == 0xD9) {
            if (scans == 0)
                return jpeg_fail(J, "the image ends before any scan%s", NULL);
            return 0;
        }
        if (marker == 0xD8 || (marker >= 0xD0 && marker <= 0xD7) || marker == 0x01)
            continue; /* no segment */
        if ((n = jpeg_segment(J)) < 0)
            return -1;
        switch (marker) {
        case 0xDB:
            if (jpeg_dqt(J, n) != 0)
                return -1;
            break;
        case 0xC4:
            if (jpeg_dht(J, n) != 0)
                return -1;
            break;
        case 0xCC:
            return jpeg_unsupported(J, "arithmetic coding");
        case 0xDD:
            if (n < 2)
                return jpeg_fail(J, "bad restart interval%s", NULL);
            J->restart = jpeg_u16(J->data + J->pos);
            break;
        case 0xDA:
            if (jpeg_sos(J, n) != 0)
                return -1;
            scans++;
            continue; /* jpeg_sos() moved past the data */
        case 0xE1:
            jpeg_exif(J, n);
            break;
        case 0xEE:
            if (n >= 12 && memcmp(J->data + J->pos, "Adobe", 5) == 0) {
                J->adobe = 1;
                J->transform = J->data[J->pos + 11];
            }
            break;
        default:
            if (marker >= 0xC0 && marker <= 0xCF && marker != 0xC4 && marker != 0xC8) {
                if (jpeg_sof(J, marker, n) != 0)
                    return -1;
            }
            break;
        }
        J->pos += (size_t)n;
    }
}

/* ---- From coefficients to pixels ---- */

/* The inverse DCT: Loeffler, Ligtenberg and Moschytz's factorisation in
 * 13-bit fixed point, rows then columns scaled by 2 bits between passes,
 * as libjpeg's default ("islow") decoder computes it, so that its pixels
 * are ours. */
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

/* Returns x / 2^n rounded to nearest (halves up). */
static inline int32_t jpeg_descale(int64_t x, int n)
{
    return (int32_t)((x + ((int64_t)1 << (n - 1))) >> n);
}

/* One 8-point inverse DCT of in[0], in[stride], ... into eight values,
 * each descaled by shift bits. */
static void jpeg_idct8(const int32_t *in, int stride, int32_t out[8], int shift)
{
    int64_t z1, z2, z3, z4, z5, t0, t1, t2, t3, t10, t11, t12, t13;

    /* Even part. */
    z2 = in[2 * stride];
    z3 = in[6 * stride];
    z1 = (z2 + z3) * JPEG_FIX_0_541196100;
    t2 = z1 - z3 * JPEG_FIX_1_847759065;
    t3 = z1 + z2 * JPEG_FIX_0_765366865;
    z2 = in[0];
    z3 = in[4 * stride];
    t0 = (z2 + z3) * ((int64_t)1 << JPEG_CONST_BITS);
    t1 = (z2 - z3) * ((int64_t)1 << JPEG_CONST_BITS);
    t10 = t0 + t3;
    t13 = t0 - t3;
    t11 = t1 + t2;
    t12 = t1 - t2;
    /* Odd part. */
    t0 = in[7 * stride];
    t1 = in[5 * stride];
    t2 = in[3 * stride];
    t3 = in[1 * stride];
    z1 = t0 + t3;
    z2 = t1 + t2;
    z3 = t0 + t2;
    z4 = t1 + t3;
    z5 = (z3 + z4) * JPEG_FIX_1_175875602;
    t0 *= JPEG_FIX_0_298631336;
    t1 *= JPEG_FIX_2_053119869;
    t2 *= JPEG_FIX_3_072711026;
    t3 *= JPEG_FIX_1_501321110;
    z1 *= -JPEG_FIX_0_899976223;
    z2 *= -JPEG_FIX_2_562915447;
    z3 = z3 * -JPEG_FIX_1_961570560 + z5;
    z4 = z4 * -JPEG_FIX_0_390180644 + z5;
    t0 += z1 + z3;
    t1 += z2 + z4;
    t2 += z2 + z3;
    t3 += z1 + z4;
    out[0] = jpeg_descale(t10 + t3, shift);
    out[7] = jpeg_descale(t10 - t3, shift);
    out[1] = jpeg_descale(t11 + t2, shift);
    out[6] = jpeg_descale(t11 - t2, shift);
    out[2] = jpeg_descale(t12 + t1, shift);
    out[5] = jpeg_descale(t12 - t1, shift);
    out[3] = jpeg_descale(t13 + t0, shift);
    out[4] = jpeg_descale(t13 - t0, shift);
}

/* Returns x + 128 clamped to a byte. */
static inline uint8_t jpeg_sample(int32_t x)
{
    x += 128;
    return (uint8_t)(x < 0 ? 0 : x > 255 ? 255 : x);
}

/* Dequantises block blk with quant and writes its 8 x 8 samples at out
 * (rows stride apart). */
static void jpeg_idct(const int16_t *blk, const uint16_t *quant, uint8_t *out, size_t stride)
{
    int32_t in[64], ws[64], col[8], row[8];

    for (int k = 0; k < 64; k++)
        in[k] = (int32_t)blk[k] * quant[k];
    /* Columns, kept 2 bits above the samples' scale. */
    for (int c = 0; c < 8; c++) {
        int zero = 1;
        for (int r = 1; r < 8 && zero; r++)
            zero = in[8 * r + c] == 0;
        if (zero) {
            for (int r = 0; r < 8; r++)
                ws[8 * r + c] = in[c] * (1 << JPEG_PASS1_BITS);
            continue;
        }
        jpeg_idct8(in + c, 8, col, JPEG_CONST_BITS - JPEG_PASS1_BITS);
        for (int r = 0; r < 8; r++)
            ws[8 * r + c] = col[r];
    }
    /* Rows, to samples. */
    for (int r = 0; r < 8; r++) {
        uint8_t *o = out + (size_t)r * stride;
        int zero = 1;
        for (int c = 1; c < 8 && zero; c++)
            zero = ws[8 * r + c] == 0;
        if (zero) {
            uint8_t v = jpeg_sample(jpeg_descale(ws[8 * r], JPEG_PASS1_BITS + 3));
            memset(o, v, 8);
            continue;
        }
        jpeg_idct8(ws + 8 * r, 1, row, JPEG_CONST_BITS + JPEG_PASS1_BITS + 3);
        for (int c = 0; c < 8; c++)
            o[c] = jpeg_sample(row[c]);
    }
}

/* Turns component c's coefficients into its samples (c->plane, width x
 * height), freeing the coefficients. */
static int jpeg_component_samples(Jpeg *J, JpegComponent *c)
{
    size_t pw = (size_t)c->bw * 8;
    uint8_t *full = malloc(pw * (size_t)c->bh * 8);

    if (!full) {
        error_set(J->err, J->name, "out of memory for a %d x %d JPEG", J->width, J->height);
        return -1;
    }
    for (int by = 0; by < c->bh; by++)
        for (int bx = 0; bx < c->bw; bx++)
            jpeg_idct(c->coef + 64 * ((size_t)by * (size_t)c->bw + (size_t)bx), c->quant,
                      full + (size_t)by * 8 * pw + (size_t)bx * 8, pw);
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
 * component is halved across, down or both, and each sample repeated for
 * other whole ratios. */
static void jpeg_upsample_row(const Jpeg *J, const JpegComponent *c, int y, uint8_t *out)
{
    int fx = J->hmax / c->h, fy = J->vmax / c->v, w = J->width;

    if (fx == 1 && fy == 1) {
        memcpy(out, c->plane + (size_t)y * (size_t)c->width, (size_t)w);
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
static int jpeg_pixels(Jpeg *J, unsigned char *rgb)
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

/* Turns img as Exif orientation o (2 to 8) says, so that it shows upright. */
static int jpeg_orient(JpegImage *img, int o, Jpeg *J)
{
    int w = img->width, h = img->height, swap = o >= 5;
    int ow = swap ? h : w, oh = swap ? w : h;
    unsigned char *out = malloc(3 * (size_t)w * (size_t)h);

    if (!out) {
        error_set(J->err, J->name, "out of memory for a %d x %d JPEG", w, h);
        return -1;
    }
    for (int y = 0; y < oh; y++)
        for (int x = 0; x < ow; x++) {
            int sx, sy; /* the stored pixel shown at (x, y) */
            switch (o) {
            case 2: sx = w - 1 - x; sy = y; break;
            case 3: sx = w - 1 - x; sy = h - 1 - y; break;
            case 4: sx = x; sy = h - 1 - y; break;
            case 5: sx = y; sy = x; break;
            case 6: sx = y; sy = h - 1 - x; break;
            case 7: sx = w - 1 - y; sy = h - 1 - x; break;
            default: sx = w - 1 - y; sy = x; break; /* 8 */
            }
            memcpy(out + 3 * ((size_t)y * (size_t)ow + (size_t)x),
                   img->rgb + 3 * ((size_t)sy * (size_t)w + (size_t)sx), 3);
        }
    free(img->rgb);
    img->rgb = out;
    img->width = ow;
    img->height = oh;
    return 0;
}

int jpeg_is(const unsigned char *data, size_t len)
{
    return len >= 3 && data[0] == 0xFF && data[1] == 0xD8 && data[2] == 0xFF;
}

void jpeg_free(JpegImage *img)
{
    free(img->rgb);
    img->rgb = NULL;
}

int jpeg_parse(const char *name, const unsigned char *data, size_t len, size_t max_bytes,
               JpegImage *img, Error *err)
{
    Jpeg *J = calloc(1, sizeof *J);
    int rc = -1;

    img->rgb = NULL;
    if (!J) {
        error_set(err, name, "out of memory");
        return -1;
    }
    J->name = name;
    J->err = err;
    J->data = data;
    J->len = len;
    J->max_bytes = max_bytes;
    J->orientation = 1;
    if (jpeg_markers(J) != 0)
        goto done;
    if (!J->frame) {
        error_set(err, name, "not an image: no frame header (SOF) before the scans");
        goto done;
    }
    for (int i = 0; i < J->ncomp; i++)
        if (!J->comp[i].seen) {
            error_set(err, name, "component %d of the frame is in no scan", J->comp[i].id);
            goto done;
        }
    for (int i = 0; i < J->ncomp; i++)
        if (jpeg_component_samples(J, &J->comp[i]) != 0)
            goto done;
    img->width = J->width;
    img->height = J->height;
    img->channels = J->ncomp;
    img->rgb = malloc(3 * (size_t)J->width * (size_t)J->height);
    if (!img->rgb) {
        error_set(err, name, "out of memory for a %d x %d JPEG", J->width, J->height);
        goto done;
    }
    if (jpeg_pixels(J, img->rgb) != 0 ||
        (J->orientation > 1 && jpeg_orient(img, J->orientation, J) != 0))
        goto done;
    rc = 0;
done:
    for (int i = 0; i < 4; i++) {
        free(J->comp[i].coef);
        free(J->comp[i].plane);
    }
    free(J);
    if (rc != 0)
        jpeg_free(img);
    return rc;
}

int jpeg_read(const char *path, size_t max_bytes, JpegImage *img, Error *err)
{
    char *data;
    size_t len;
    int rc;

    img->rgb = NULL;
    if (file_read_all(path, &data, &len, err) != 0)
        return -1;
    rc = jpeg_parse(file_display_name(path), (const unsigned char *)data, len, max_bytes, img,
                    err);
    free(data);
    return rc;
}
