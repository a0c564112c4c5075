/* jpeg_entropy.c: a scan's entropy-coded data, Huffman-decoded into its
 * components' coefficients, sequential and progressive (see jpeg_decode.h;
 * ITU-T T.81, annexes F and G). */
#include <stdint.h>
#include <string.h>

#include "jpeg_decode.h"
#include "jpeg_tables.h"

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

/* Decodes a symbol with table h and returns it; a bad code (none of the
 * table's 16 lengths) is 0, as libjpeg decodes it. */
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
    if (len > 16) {
        /* libjpeg takes 17 bits and decodes a zero: the safest guess. */
        jpeg_warn(J, "bad Huffman code");
        J->bits <<= 17;
        J->nbits -= 17;
        return 0;
    }
    J->bits <<= len;
    J->nbits -= len;
    return h->symbols[(code + h->delta[len]) & 0xFF];
}

/* Decodes one block of a sequential scan into blk. */
static int jpeg_block(Jpeg *J, JpegComponent *c, int16_t *blk)
{
    int t = jpeg_symbol(J, &J->dc[c->dc]);

    if (t > 15)
        return jpeg_fail(J, "bad Huffman code in a DC coefficient%s", NULL);
    c->pred += jpeg_signed(J, t);
    blk[0] = (int16_t)c->pred;
    for (int k = 1; k < 64;) {
        int rs = jpeg_symbol(J, &J->ac[c->ac]), r = rs >> 4, s = rs & 15;
        if (s == 0) {
            if (r != 15)
                break;
            k += 16;
            continue;
        }
        k += r;
        /* Past the block's end (damaged data): on its last coefficient, as
         * libjpeg puts it. */
        blk[jpeg_zigzag[k < 64 ? k : 63]] = (int16_t)jpeg_signed(J, s);
        k++;
    }
    return 0;
}

/* Decodes one block of a progressive DC scan. */
static int jpeg_dc_progressive(Jpeg *J, const JpegScan *s, JpegComponent *c, int16_t *blk)
{
    if (s->ah == 0) {
        int t = jpeg_symbol(J, &J->dc[c->dc]);
        if (t > 15)
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
        int rs = jpeg_symbol(J, &J->ac[c->ac]), r = rs >> 4, z = rs & 15;
        if (z == 0) {
            if (r < 15) { /* an end-of-band run of 2^r + bits - 1 more blocks */
                J->eobrun = (1 << r) - 1 + jpeg_bits(J, r);
                break;
            }
            k += 16;
            continue;
        }
        k += r;
        blk[jpeg_zigzag[k < 64 ? k : 63]] = (int16_t)(jpeg_signed(J, z) * (1 << s->al));
        k++;
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
            int rs = jpeg_symbol(J, &J->ac[c->ac]), r = rs >> 4, value = 0;
            if ((rs & 15) != 0) {
                /* Only 1 or -1 is new here: libjpeg takes any other size
                 * as 1 (damaged data). */
                if ((rs & 15) != 1)
                    jpeg_warn(J, "a refinement's new coefficient is not 1 or -1");
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
            /* Past the band when it had too few zeros (damaged data):
             * where libjpeg puts it, the next position, or the last. */
            if (value)
                blk[jpeg_zigzag[k < 64 ? k : 63]] = (int16_t)value;
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

/* Says whether the decoding went past the data (bits past a marker or the
 * file's end were read as zeros): the data is damaged or cut short. The
 * first time in a restart interval, says so; libjpeg then leaves the
 * interval's other MCUs as they are (grey, in a sequential scan). */
static int jpeg_ran_out(Jpeg *J)
{
    if (J->insufficient || J->pad <= J->nbits)
        return J->insufficient;
    jpeg_warn(J, "%s", J->pos >= J->len ? "the file ends inside the image data (truncated)"
                                        : "the image data ends early, at a marker (damaged)");
    J->insufficient = 1;
    return 1;
}

/* At a restart interval's end: the expected RSTn marker, then fresh
 * predictors and bits. As libjpeg's jpeg_resync_to_restart(): the data
 * left in the interval is passed over to the next marker; the expected
 * marker, or one not in the next four, is taken and decoding goes on; one
 * of the two before it is passed over to the next marker; one of the two
 * after it, or a marker that is not a restart, is left for later (the
 * interval after is then empty). */
static void jpeg_restart(Jpeg *J, const JpegScan *s)
{
    int desired = 0xD0 + J->next_restart;
    size_t left = J->nbits > J->pad ? (size_t)(J->nbits - J->pad) / 8 : 0;

    J->bits = 0;
    J->nbits = 0;
    J->pad = 0;
    /* The data left in the interval (whole bytes in the bit buffer, then
     * up to the marker) is passed over, with a warning. */
    if (!J->marker && (J->marker = jpeg_find_marker(J, left)) < 0) {
        J->marker = 0xD9; /* the data ends: as libjpeg's fake EOI */
        J->pos = J->len;
    }
    for (;;) {
        int m = J->marker, action;
        if (m == desired) {
            action = 1;
        } else if (m < 0xC0) {
            action = 2;
        } else if (m < 0xD0 || m > 0xD7) {
            action = 3;
        } else if (m == 0xD0 + ((J->next_restart + 1) & 7) ||
                   m == 0xD0 + ((J->next_restart + 2) & 7)) {
            action = 3;
        } else if (m == 0xD0 + ((J->next_restart - 1) & 7) ||
                   m == 0xD0 + ((J->next_restart - 2) & 7)) {
            action = 2;
        } else {
            action = 1;
        }
        if (action != 1 && m != 0xD9)
            jpeg_warn(J, "found marker 0x%02X instead of RST%d", m, J->next_restart);
        if (action == 1) {
            J->pos += 2;
            J->marker = 0;
            break;
        }
        if (action == 3)
            break;
        J->pos += 2; /* a marker to pass over */
        if ((J->marker = jpeg_find_marker(J, 0)) < 0) {
            J->marker = 0xD9;
            J->pos = J->len;
            break;
        }
    }
    J->next_restart = (J->next_restart + 1) & 7;
    for (int i = 0; i < s->n; i++)
        s->c[i]->pred = 0;
    J->eobrun = 0;
    /* With the marker taken, the next interval's data starts afresh;
     * against a marker left for later, it is empty. */
    if (!J->marker)
        J->insufficient = 0;
}

/* Decodes the entropy-coded data of scan s. */
int jpeg_scan_data(Jpeg *J, const JpegScan *s)
{
    long mcus, todo;
    int across;

    J->bits = 0;
    J->nbits = 0;
    J->marker = 0;
    J->pad = 0;
    J->eobrun = 0;
    J->insufficient = 0;
    J->next_restart = 0;
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
            (void)jpeg_ran_out(J);
            jpeg_restart(J, s);
            todo = J->restart;
        }
        todo--;
        /* The data ran out: the interval's other MCUs stay as they are. */
        if (jpeg_ran_out(J))
            continue;
        /* The last MCU row begun with data, for block smoothing. */
        J->last_good = s->n == 1 ? my / s->c[0]->v : my;
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
    (void)jpeg_ran_out(J);
    /* On to the marker after the data, passing over (with a warning) what
     * is left before it, restart markers included. The bytes counted as
     * passed over are those after the ones read into the bit buffer, as
     * libjpeg counts them at a scan's end (it drops its buffer unsaid;
     * it reads further ahead, so its count may be a few bytes less). */
    if (!J->marker) {
        if (jpeg_find_marker(J, 0) < 0)
            J->pos = J->len;
    }
    while (J->pos + 1 < J->len && J->data[J->pos + 1] >= 0xD0 && J->data[J->pos + 1] <= 0xD7) {
        J->pos += 2;
        if (jpeg_find_marker(J, 0) < 0)
            J->pos = J->len;
    }
    return 0;
}
