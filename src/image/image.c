/* image.c: image storage (see image.h). */
#include "image/image.h"

#include <stdlib.h>
#include <string.h>

#include "math/power.h"

size_t image_size(int width, int height)
{
    return 3 * (size_t)width * (size_t)height;
}

int image_init(Image *img, int width, int height)
{
    img->width = width;
    img->height = height;
    img->linear = NULL;
    img->encode = NULL;
    img->gamma = 1;
    img->rgb = calloc(image_size(width, height), 1);
    if (!img->rgb) {
        img->width = img->height = 0;
        return -1;
    }
    return 0;
}

int image_keep_linear(Image *img)
{
    size_t n = image_size(img->width, img->height);

    if (n > (size_t)-1 / sizeof *img->linear)
        return -1;
    img->linear = calloc(n, sizeof *img->linear);
    return img->linear ? 0 : -1;
}

int image_encode_gamma(Image *img, double gamma)
{
    double *t = malloc((COLOUR_LEVELS - 1) * sizeof *t);

    if (!t)
        return -1;
    /* Byte b from the midpoint between b - 1 and b on the encoded scale:
     * power() gives the same thresholds on every machine. */
    for (int b = 1; b < COLOUR_LEVELS; b++)
        t[b - 1] = 255 * power((b - 0.5) / 255, gamma);
    free(img->encode);
    img->encode = t;
    img->gamma = gamma;
    return 0;
}

void image_fill(Image *img, int x0, int y0, int x1, int y1, Colour c)
{
    size_t first = 3 * ((size_t)y0 * (size_t)img->width + (size_t)x0);
    size_t row = 3 * (size_t)img->width, done = 3, wide = 3 * (size_t)(x1 - x0);

    image_set(img, x0, y0, c);
    /* The first row by doubling what is done, then the others from it. */
    for (; done < wide; done *= 2) {
        size_t n = done < wide - done ? done : wide - done;
        memcpy(img->rgb + first + done, img->rgb + first, n);
        if (img->linear)
            memcpy(img->linear + first + done, img->linear + first, n * sizeof *img->linear);
    }
    for (int y = y0 + 1; y < y1; y++) {
        size_t i = first + (size_t)(y - y0) * row;
        memcpy(img->rgb + i, img->rgb + first, wide);
        if (img->linear)
            memcpy(img->linear + i, img->linear + first, wide * sizeof *img->linear);
    }
}

void image_free(Image *img)
{
    free(img->rgb);
    free(img->linear);
    free(img->encode);
    img->rgb = NULL;
    img->linear = NULL;
    img->encode = NULL;
    img->gamma = 1;
    img->width = img->height = 0;
}
