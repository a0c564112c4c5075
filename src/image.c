/* image.c: image storage and the one quantiser (see image.h, colour.h). */
#include "image.h"

#include <math.h>
#include <stdlib.h>

unsigned char colour_quantise(double x)
{
    if (!(x > 0)) /* also catches NaN */
        return 0;
    if (x >= 255)
        return 255;
    return (unsigned char)floor(x + 0.5);
}

size_t image_size(int width, int height)
{
    return 3 * (size_t)width * (size_t)height;
}

int image_init(Image *img, int width, int height)
{
    img->width = width;
    img->height = height;
    img->rgb = calloc(image_size(width, height), 1);
    if (!img->rgb) {
        img->width = img->height = 0;
        return -1;
    }
    return 0;
}

void image_free(Image *img)
{
    free(img->rgb);
    img->rgb = NULL;
    img->width = img->height = 0;
}
