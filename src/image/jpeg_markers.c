/* jpeg_markers.c: a JPEG file's markers and the tables, frame and scan
 * headers they carry (see jpeg_decode.h; ITU-T T.81, annex B). */
#include <stdint.h>
#include <stdlib.h>
#include <string.h>

#include "image/jpeg.h"
#include "math/number.h"
#include "jpeg_decode.h"
#include "jpeg_tables.h"

/* The example Huffman tables of T.81, annex K.3 (tables K.3 to K.6), that
 * libjpeg-turbo's sequential decoder takes for a DC or AC table 0 or 1 that
 * no DHT segment defined before the first scan (Motion JPEG frames leave
 * them out): the codes of each length from 1 to 16, then the symbols. */
typedef struct {
    uint8_t counts[16];
    uint8_t symbols[162];
    int n;
} JpegStdTable;

static const JpegStdTable jpeg_std_dc[2] = {
    {{0, 1, 5, 1, 1, 1, 1, 1, 1, 0, 0, 0, 0, 0, 0, 0},
     {0x00, 0x01, 0x02, 0x03, 0x04, 0x05, 0x06, 0x07, 0x08, 0x09, 0x0a, 0x0b},
     12},
    {{0, 3, 1, 1, 1, 1, 1, 1, 1, 1, 1, 0, 0, 0, 0, 0},
     {0x00, 0x01, 0x02, 0x03, 0x04, 0x05, 0x06, 0x07, 0x08, 0x09, 0x0a, 0x0b},
     12},
};

static const JpegStdTable jpeg_std_ac[2] = {
    {{0, 2, 1, 3, 3, 2, 4, 3, 5, 5, 4, 4, 0, 0, 1, 125},
     {0x01, 0x02, 0x03, 0x00, 0x04, 0x11, 0x05, 0x12, 0x21, 0x31, 0x41, 0x06,
      0x13, 0x51, 0x61, 0x07, 0x22, 0x71, 0x14, 0x32, 0x81, 0x91, 0xa1, 0x08,
      0x23, 0x42, 0xb1, 0xc1, 0x15, 0x52, 0xd1, 0xf0, 0x24, 0x33, 0x62, 0x72,
      0x82, 0x09, 0x0a, 0x16, 0x17, 0x18, 0x19, 0x1a, 0x25, 0x26, 0x27, 0x28,
      0x29, 0x2a, 0x34, 0x35, 0x36, 0x37, 0x38, 0x39, 0x3a, 0x43, 0x44, 0x45,
      0x46, 0x47, 0x48, 0x49, 0x4a, 0x53, 0x54, 0x55, 0x56, 0x57, 0x58, 0x59,
      0x5a, 0x63, 0x64, 0x65, 0x66, 0x67, 0x68, 0x69, 0x6a, 0x73, 0x74, 0x75,
      0x76, 0x77, 0x78, 0x79, 0x7a, 0x83, 0x84, 0x85, 0x86, 0x87, 0x88, 0x89,
      0x8a, 0x92, 0x93, 0x94, 0x95, 0x96, 0x97, 0x98, 0x99, 0x9a, 0xa2, 0xa3,
      0xa4, 0xa5, 0xa6, 0xa7, 0xa8, 0xa9, 0xaa, 0xb2, 0xb3, 0xb4, 0xb5, 0xb6,
      0xb7, 0xb8, 0xb9, 0xba, 0xc2, 0xc3, 0xc4, 0xc5, 0xc6, 0xc7, 0xc8, 0xc9,
      0xca, 0xd2, 0xd3, 0xd4, 0xd5, 0xd6, 0xd7, 0xd8, 0xd9, 0xda, 0xe1, 0xe2,
      0xe3, 0xe4, 0xe5, 0xe6, 0xe7, 0xe8, 0xe9, 0xea, 0xf1, 0xf2, 0xf3, 0xf4,
      0xf5, 0xf6, 0xf7, 0xf8, 0xf9, 0xfa},
     162},
    {{0, 2, 1, 2, 4, 4, 3, 4, 7, 5, 4, 4, 0, 1, 2, 119},
     {0x00, 0x01, 0x02, 0x03, 0x11, 0x04, 0x05, 0x21, 0x31, 0x06, 0x12, 0x41,
      0x51, 0x07, 0x61, 0x71, 0x13, 0x22, 0x32, 0x81, 0x08, 0x14, 0x42, 0x91,
      0xa1, 0xb1, 0xc1, 0x09, 0x23, 0x33, 0x52, 0xf0, 0x15, 0x62, 0x72, 0xd1,
      0x0a, 0x16, 0x24, 0x34, 0xe1, 0x25, 0xf1, 0x17, 0x18, 0x19, 0x1a, 0x26,
      0x27, 0x28, 0x29, 0x2a, 0x35, 0x36, 0x37, 0x38, 0x39, 0x3a, 0x43, 0x44,
      0x45, 0x46, 0x47, 0x48, 0x49, 0x4a, 0x53, 0x54, 0x55, 0x56, 0x57, 0x58,
      0x59, 0x5a, 0x63, 0x64, 0x65, 0x66, 0x67, 0x68, 0x69, 0x6a, 0x73, 0x74,
      0x75, 0x76, 0x77, 0x78, 0x79, 0x7a, 0x82, 0x83, 0x84, 0x85, 0x86, 0x87,
      0x88, 0x89, 0x8a, 0x92, 0x93, 0x94, 0x95, 0x96, 0x97, 0x98, 0x99, 0x9a,
      0xa2, 0xa3, 0xa4, 0xa5, 0xa6, 0xa7, 0xa8, 0xa9, 0xaa, 0xb2, 0xb3, 0xb4,
      0xb5, 0xb6, 0xb7, 0xb8, 0xb9, 0xba, 0xc2, 0xc3, 0xc4, 0xc5, 0xc6, 0xc7,
      0xc8, 0xc9, 0xca, 0xd2, 0xd3, 0xd4, 0xd5, 0xd6, 0xd7, 0xd8, 0xd9, 0xda,
      0xe2, 0xe3, 0xe4, 0xe5, 0xe6, 0xe7, 0xe8, 0xe9, 0xea, 0xf2, 0xf3, 0xf4,
      0xf5, 0xf6, 0xf7, 0xf8, 0xf9, 0xfa},
     162},
};

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
    h->dc_ok = 1;
    for (int i = 0; i < n; i++)
        h->dc_ok &= symbols[i] <= 15;
    return 0;
}

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
        for (int k = 0; k < 10; k++)
            c->bits[k] = c->prev_bits[k] = -1;
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
    /* A sequential file's DC and AC tables 0 and 1, when no segment gave
     * them, are the standard's examples, as libjpeg-turbo takes them. */
    for (int t = 0; t < 2 && !J->progressive; t++) {
        if (!J->dc[t].defined)
            (void)jpeg_build(&J->dc[t], jpeg_std_dc[t].counts, jpeg_std_dc[t].symbols,
                             jpeg_std_dc[t].n);
        if (!J->ac[t].defined)
            (void)jpeg_build(&J->ac[t], jpeg_std_ac[t].counts, jpeg_std_ac[t].symbols,
                             jpeg_std_ac[t].n);
    }
    for (int i = 0; i < s.n; i++) {
        JpegComponent *c = s.c[i];
        /* Only the tables the scan decodes with must be there (libjpeg
         * passes over the others' numbers). */
        int needs_dc = !J->progressive || (s.ss == 0 && s.ah == 0);
        int needs_ac = !J->progressive || s.ss > 0;
        if ((needs_dc && c->dc > 3) || (needs_ac && c->ac > 3))
            return jpeg_fail(J, "a scan names a Huffman table above 3%s", NULL);
        if ((needs_dc && !J->dc[c->dc].defined) || (needs_ac && !J->ac[c->ac].defined))
            return jpeg_fail(J, "a scan uses a Huffman table not defined before it%s", NULL);
        /* As libjpeg, a DC table with a symbol past 15 is refused when a
         * scan takes it up, before its data. */
        if (needs_dc && !J->dc[c->dc].dc_ok)
            return jpeg_fail(J, "bad Huffman table: a DC symbol above 15%s", NULL);
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
    if (J->progressive)
        jpeg_smooth_scan(J, &s);
    return jpeg_scan_data(J, &s);
}

/* Reads the markers from SOI to EOI (or the data's end after a scan). */
int jpeg_markers(Jpeg *J)
{
    int scans = 0;

    if (!jpeg_is(J->data, J->len)) {
        error_set(J->err, J->name, "not a JPEG file (no SOI marker at the start)");
        return -1;
    }
    J->pos = 2;
    for (;;) {
        int marker, n;
        /* Bytes before the next marker are passed over (with a warning),
         * as libjpeg does. */
        if ((marker = jpeg_find_marker(J, 0)) < 0) {
            if (scans == 0)
                return jpeg_fail(J, "the file ends before any image data%s", NULL);
            /* No EOI: what came is decoded. */
            J->pos = J->len;
            jpeg_warn(J, "the file ends without its end marker (EOI)");
            return 0;
        }
        J->pos += 2;
        if (marker == 0xD9) {
            if (scans == 0)
                return jpeg_fail(J, "the image ends before any scan%s", NULL);
            return 0;
        }
        if (marker == 0xD8 || (marker >= 0xD0 && marker <= 0xD7) || marker == 0x01)
            continue; /* no segment */
        /* A segment cut short after the image data: libjpeg reads up to
         * the file's end and ends the image there. */
        if (scans > 0 && (J->pos + 2 > J->len || J->pos + jpeg_u16(J->data + J->pos) > J->len)) {
            jpeg_warn(J, "the file ends inside a marker segment (truncated)");
            J->pos = J->len;
            return 0;
        }
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
