/* image.c: image storage (see image.h). */
#include "image.h"

#include <stdlib.h>

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
