/* jpeg.c: reading JPEG files (see jpeg.h; ITU-T T.81): the steps of
 * jpeg_decode.h put together, and the picture turned as Exif says. */
#include "image/jpeg.h"

#include <stdint.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>

#include "jpeg_decode.h"

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
    img->warning[0] = '\0';
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
    jpeg_smooth_decide(J);
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
    if (J->warnings > 1)
        snprintf(img->warning, sizeof img->warning, "corrupt JPEG data, %s; and %d more", J->warning,
                 J->warnings - 1);
    else if (J->warnings == 1)
        snprintf(img->warning, sizeof img->warning, "corrupt JPEG data, %s", J->warning);
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

