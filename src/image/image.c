/* image.c: image storage (see image.h). */
#include "image/image.h"

#include <stdlib.h>

size_t image_size(int width, int height)
{
    return 3 * (size_t)width * (size_t)height;
}

int image_init(Image *img, int width, int height)
{
    img->width = width;
    img->height = height;
    img->linear = NULL;
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

void image_free(Image *img)
{
    free(img->rgb);
    free(img->linear);
    img->rgb = NULL;
    img->linear = NULL;
    img->width = img->height = 0;
}
