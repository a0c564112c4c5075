/* jpeg_smooth.c: block smoothing of progressive JPEGs whose coefficients
 * did not all come (see jpeg_decode.h): where a file is cut short, or its
 * scans stop before the last bits, djpeg (libjpeg-turbo 2.1, as Debian
 * ships it; 3.0.1 moved the window's edges, below) estimates the first AC
 * coefficients of each block from the DC values of the 5 x 5 blocks
 * around it (JPEG's annex K.8, widened), and its DC too where no AC
 * coefficient came at all; we do the same, so that such a file gives
 * djpeg's picture. */
#include <stdint.h>

#include "jpeg_decode.h"

/* The natural (row-major) positions of zigzag coefficients 0..9. */
static const int jpeg_smooth_pos[10] = {0, 1, 8, 16, 9, 2, 3, 10, 17, 24};

/* The weights of the 5 x 5 DC values (row by row, the block at the
 * centre) in the estimate of zigzag coefficients 1..9 and of the DC,
 * when no AC coefficient has come ("DC interpolation"), and of
 * coefficients 1..5 otherwise. */
static const int16_t jpeg_smooth_dc_weights[10][25] = {
    {-2, -6, -8, -6, -2, -6, 6, 42, 6, -6, -8, 42, 152, 42, -8, -6, 6, 42, 6, -6, -2, -6, -8,
     -6, -2},
    {-1, -1, 0, 1, 1, -3, 13, 0, -13, 3, -3, 38, 0, -38, 3, -3, 13, 0, -13, 3, -1, -1, 0, 1, 1},
    {-1, -3, -3, -3, -1, -1, 13, 38, 13, -1, 0, 0, 0, 0, 0, 1, -13, -38, -13, 1, 1, 3, 3, 3, 1},
    {0, 0, 1, 0, 0, 0, 2, 7, 2, 0, 0, -5, -14, -5, 0, 0, 2, 7, 2, 0, 0, 0, 1, 0, 0},
    {-1, 0, 0, 0, 1, 0, 9, 0, -9, 0, 0, 0, 0, 0, 0, 0, -9, 0, 9, 0, 1, 0, 0, 0, -1},
    {0, 0, 0, 0, 0, 0, 2, -5, 2, 0, 1, 7, -14, 7, 1, 0, 2, -5, 2, 0, 0, 0, 0, 0, 0},
    {0, 0, 0, 0, 0, 0, 1, 0, -1, 0, 0, 2, 0, -2, 0, 0, 1, 0, -1, 0, 0, 0, 0, 0, 0},
    {0, 0, 0, 0, 0, 0, 1, -3, 1, 0, 0, 0, 0, 0, 0, 0, -1, 3, -1, 0, 0, 0, 0, 0, 0},
    {0, 0, 0, 0, 0, 0, 1, 0, -1, 0, 0, -3, 0, 3, 0, 0, 1, 0, -1, 0, 0, 0, 0, 0, 0},
    {0, 0, 0, 0, 0, 0, 1, 2, 1, 0, 0, 0, 0, 0, 0, 0, -1, -2, -1, 0, 0, 0, 0, 0, 0},
};
static const int16_t jpeg_smooth_ac_weights[6][25] = {
    {0},
    {0, 0, 0, 0, 0, 0, 0, 0, 0, 0, -7, 50, 0, -50, 7, 0, 0, 0, 0, 0, 0, 0, 0, 0, 0},
    {0, 0, -7, 0, 0, 0, 0, 50, 0, 0, 0, 0, 0, 0, 0, 0, 0, -50, 0, 0, 0, 0, 7, 0, 0},
    {0, 0, -1, 0, 0, 0, 0, 13, 0, 0, 0, 0, -24, 0, 0, 0, 0, 13, 0, 0, 0, 0, -1, 0, 0},
    {0, -1, 0, 1, 0, -1, 10, 0, -10, 1, 0, 0, 0, 0, 0, 1, -10, 0, 10, -1, 0, 1, 0, -1, 0},
    {0, 0, 0, 0, 0, 0, 0, 0, 0, 0, -1, 13, -24, 13, -1, 0, 0, 0, 0, 0, 0, 0, 0, 0, 0},
};

void jpeg_smooth_scan(Jpeg *J, const JpegScan *s)
{
    J->scans++;
    for (int i = 0; i < s->n; i++) {
        JpegComponent *c = s->c[i];
        for (int k = s->ss < 1 ? s->ss : 1; k < 10; k++)
            c->prev_bits[k] = J->scans > 1 ? c->bits[k] : 0;
        for (int k = s->ss; k <= s->se && k < 10; k++)
            c->bits[k] = s->al;
    }
}

void jpeg_smooth_decide(Jpeg *J)
{
    int useful = 0;

    J->smooth = 0;
    if (!J->progressive)
        return;
    for (int i = 0; i < J->ncomp; i++) {
        const JpegComponent *c = &J->comp[i];
        for (int k = 0; k < 10; k++)
            if (c->quant[jpeg_smooth_pos[k]] == 0)
                return;
        if (c->bits[0] < 0)
            return;
        for (int k = 1; k < 10; k++)
            useful |= c->bits[k] != 0;
    }
    J->smooth = useful;
}

/* Returns the estimate of a coefficient of quantiser q from num (the
 * weighted DC values times the DC's quantiser), rounded as libjpeg
 * rounds it, and kept below 2^al when its last al bits are unknown. */
static int16_t jpeg_smooth_estimate(int64_t num, int64_t q, int al)
{
    int64_t pred = ((q << 7) + (num < 0 ? -num : num)) / (q << 8);

    if (al > 0 && pred >= ((int64_t)1 << al))
        pred = ((int64_t)1 << al) - 1;
    return (int16_t)(uint16_t)(uint64_t)(num < 0 ? -pred : pred);
}

/* Returns the column of block bx's neighbour j (0..4, 2 the block itself)
 * in a component wb blocks wide, as libjpeg-turbo 2.1 slides its window:
 * clamped to the picture, but for wb = 2, where the window's right end
 * keeps the first column (3.0.1 clamps those too). */
static int jpeg_smooth_column(int bx, int j, int wb)
{
    int x = bx + j - 2;

    if (wb == 2 && bx + j >= 4)
        return 0;
    return x < 0 ? 0 : x > wb - 1 ? wb - 1 : x;
}

void jpeg_smooth_block(const Jpeg *J, const JpegComponent *c, int bx, int by, int16_t ws[64])
{
    /* The component's blocks that are the picture's, its MCU rows (libjpeg's
     * iMCU rows), the last of them, and the block rows of the one of by. */
    int wb = (c->width + 7) / 8, hb = (c->height + 7) / 8;
    int last = (J->height + 8 * J->vmax - 1) / (8 * J->vmax) - 1, imcu = by / c->v;
    int block_rows = imcu < last ? c->v : (hb % c->v ? hb % c->v : c->v), b = by % c->v;
    const int *bits = imcu > J->last_good ? c->prev_bits : c->bits;
    int latched[10], row[5], dc[25], change_dc = 1;
    const int16_t *blk = c->coef + 64 * ((size_t)by * (size_t)c->bw + (size_t)bx);

    for (int k = 0; k < 64; k++)
        ws[k] = blk[k];
    /* The coefficients' states: after the last scan, or before it for the
     * rows that scan did not reach; none before the first. */
    for (int k = 1; k < 10; k++)
        latched[k] = bits == c->prev_bits && J->scans <= 1 ? -1 : bits[k];
    for (int k = 1; k < 10; k++)
        change_dc &= latched[k] == -1;
    /* The rows of the 5 x 5 neighbourhood, repeated at the edges as
     * libjpeg-turbo 2.1 (Debian's djpeg) tells them: by the block row's
     * place in its MCU row and the MCU row's in the picture, which for a
     * component of two block rows an MCU row keeps the second and the
     * next-to-last MCU rows from their second neighbours (3.0.1 counts
     * the picture's block rows). */
    row[2] = by;
    row[1] = b > 0 || imcu > 0 ? by - 1 : by;
    row[0] = b > 1 || imcu > 1 ? by - 2 : row[1];
    row[3] = b < block_rows - 1 || imcu < last ? by + 1 : by;
    row[4] = b < block_rows - 2 || imcu + 1 < last ? by + 2 : row[3];
    for (int i = 0; i < 5; i++)
        for (int j = 0; j < 5; j++) {
            size_t x = (size_t)jpeg_smooth_column(bx, j, wb);
            dc[5 * i + j] = c->coef[64 * ((size_t)row[i] * (size_t)c->bw + x)];
        }
    for (int k = 1; k < (change_dc ? 10 : 6); k++) {
        int pos = jpeg_smooth_pos[k];
        const int16_t *w = change_dc ? jpeg_smooth_dc_weights[k] : jpeg_smooth_ac_weights[k];
        int64_t sum = 0;
        if (latched[k] == 0 || ws[pos] != 0)
            continue;
        for (int i = 0; i < 25; i++)
            sum += (int64_t)w[i] * dc[i];
        ws[pos] = jpeg_smooth_estimate(sum * c->quant[0], c->quant[pos], latched[k]);
    }
    if (change_dc) {
        int64_t sum = 0;
        for (int i = 0; i < 25; i++)
            sum += (int64_t)jpeg_smooth_dc_weights[0][i] * dc[i];
        ws[0] = jpeg_smooth_estimate(sum * c->quant[0], c->quant[0], 0);
    }
}
