/*
 * jpeg_decode.h: the JPEG reader's state and the steps that share it, one
 * module each (private to image/; jpeg.h is the reader's contract):
 *   jpeg_markers.c  the markers from SOI to EOI: tables (DQT, DHT), the
 *                   frame (SOF), restart intervals, Exif, scan headers
 *   jpeg_entropy.c  a scan's entropy-coded data: the bit reader, Huffman
 *                   decoding, sequential and progressive blocks, restarts
 *   jpeg_idct.c     coefficients to pixels: the inverse DCT, upsampling
 *                   of subsampled components, YCbCr to RGB
 *   jpeg_smooth.c   block smoothing of progressive files cut short
 *   jpeg_stream.c   the bottom step: faults, warnings, markers found in
 *                   the bytes (the others call down to it, none calls up)
 *   jpeg.c          the whole: jpeg_parse() drives them and turns the
 *                   picture as Exif says
 * (libjpeg-turbo cuts its decoder at the same seams: jdmarker, jdhuff and
 * jdphuff, jidctint, jdsample and jdcolor.)
 */
#ifndef RAYTRACE_JPEG_DECODE_H
#define RAYTRACE_JPEG_DECODE_H

#include <stddef.h>
#include <stdint.h>

#include "base/error.h"

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
    int dc_ok;                             /* every symbol is 0..15, as a DC
                                              table's must be */
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
    int bits[10];           /* progressive: the successive approximation
                               (Al) of coefficients 0..9 in zigzag order
                               after the last scan that sent them, -1 for
                               none yet (libjpeg's coef_bits) */
    int prev_bits[10];      /* the same before the component's last scan */
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
    int next_restart;       /* the RSTn marker expected next, 0..7 */
    int insufficient;       /* the data ran out in this restart interval:
                               its other MCUs are left as they are */
    int scans;              /* progressive: scans begun so far */
    int last_good;          /* the last MCU row (iMCU row) begun with data */
    int smooth;             /* 1: blocks missing coefficients are smoothed
                               (jpeg_smooth.c) */
    /* Damage passed over, as libjpeg passes over it. */
    int warnings;
    char warning[160];      /* the first, "at byte N: ..." */
} Jpeg;

/* The scan being decoded. */
typedef struct {
    int n;                 /* components in it */
    JpegComponent *c[4];
    int ss, se, ah, al;    /* spectral selection and successive approximation */
} JpegScan;

/* Reads a big-endian 16-bit number at p (which must be there). */
static inline int jpeg_u16(const uint8_t *p)
{
    return p[0] << 8 | p[1];
}

/* Records a fault "at byte OFFSET: MESSAGE" (fmt with one %s, what);
 * returns -1 (jpeg_stream.c). */
int jpeg_fail(Jpeg *J, const char *fmt, const char *what);

/* Records that the file uses something this reader does not; returns -1
 * (jpeg_stream.c). */
int jpeg_unsupported(Jpeg *J, const char *what);

/* Notes damage passed over (printf's fmt), at J's byte: the first is kept
 * in J->warning, the others counted (jpeg_stream.c). */
void jpeg_warn(Jpeg *J, const char *fmt, ...);

/* Moves J to the next marker at or after its position (0xFF, fill bytes
 * 0xFF, then a byte other than 0 and 0xFF), warning of the bytes it passes
 * over with the junk bytes before its position (libjpeg counts them
 * alike); returns the marker's code with J at its 0xFF, or -1 when the
 * data ends first (jpeg_stream.c). */
int jpeg_find_marker(Jpeg *J, size_t junk);

/* Reads the markers from SOI to EOI (or the data's end after a scan),
 * decoding every scan into its components' coefficients; returns 0 or -1
 * with the fault recorded (jpeg_markers.c). */
int jpeg_markers(Jpeg *J);

/* Decodes the entropy-coded data of scan s, J at its first byte, and
 * leaves J at the marker after it; returns 0 or -1 (jpeg_entropy.c). */
int jpeg_scan_data(Jpeg *J, const JpegScan *s);

/* Turns component c's coefficients into its plane of samples; returns 0
 * or -1 when memory runs out (jpeg_idct.c). */
int jpeg_component_samples(Jpeg *J, JpegComponent *c);

/* Records, for block smoothing, that scan s (progressive) begins: its
 * components' coefficients Ss..Se are known from now on to Al bits. */
void jpeg_smooth_scan(Jpeg *J, const JpegScan *s);

/* Sets J->smooth when, all scans read, libjpeg would smooth this
 * progressive file's blocks: some of the first nine AC coefficients of a
 * component are not known to their last bit (scans missing, or cut
 * short), every component's DC is known in part, and their quantisation
 * tables have no zero among the first ten. */
void jpeg_smooth_decide(Jpeg *J);

/* Writes into ws block (bx, by) of component c, its coefficients that are
 * still zero and not known to be estimated from the DC values of the 5 x 5
 * blocks around it, as libjpeg-turbo's block smoothing estimates them
 * (its DC too, where no AC coefficient has come at all). */
void jpeg_smooth_block(const Jpeg *J, const JpegComponent *c, int bx, int by, int16_t ws[64]);

/* Writes the frame's pixels as 8-bit RGB into rgb (width x height x 3),
 * upsampling and converting the components; returns 0 or -1
 * (jpeg_idct.c). */
int jpeg_pixels(Jpeg *J, unsigned char *rgb);

#endif
