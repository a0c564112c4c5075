/* texture.c: texture images and their lookup (see texture.h). */
#include "scene/texture.h"

#include <math.h>
#include <stdlib.h>

size_t texture_memory(const Texture *t)
{
    return 3 * (size_t)t->width * (size_t)t->height * sizeof *t->texels;
}

void texture_free(Texture *tex)
{
    free(tex->texels);
    free(tex->path);
    tex->texels = NULL;
    tex->path = NULL;
}

/* Returns x - floor(x), in [0, 1); non-finite x maps to 0. */
static double texture_wrap(double x)
{
    double f;

    if (!isfinite(x))
        return 0;
    f = x - floor(x);
    return f < 1 ? f : 0;
}

/* Returns index i (possibly one off either end) brought into 0..n-1:
 * wrapped around, or clamped. */
static int texture_index(int i, int n, int clamp)
{
    if (clamp)
        return i < 0 ? 0 : i >= n ? n - 1 : i;
    return i < 0 ? i + n : i >= n ? i - n : i;
}

/* Returns the texel at column i, row j (both in range) as a colour. */
static Colour texture_texel(const Texture *tex, int i, int j)
{
    const unsigned short *s = tex->texels + 3 * ((size_t)j * (size_t)tex->width + (size_t)i);

    return colour(s[0] * tex->scale, s[1] * tex->scale, s[2] * tex->scale);
}

Colour texture_lookup(const Texture *tex, double u, double v, TextureFilter filter, int clamp_v)
{
    int w = tex->width, h = tex->height;
    double x, y, fx, fy;
    int i0, j0, i1, j1;
    Colour a, b, c, d;

    u = texture_wrap(u);
    if (clamp_v)
        v = isfinite(v) ? (v < 0 ? 0 : v > 1 ? 1 : v) : 0;
    else
        v = texture_wrap(v);
    /* Image position: x from the left edge, y from the top edge, in texels. */
    x = u * w;
    y = (1 - v) * h;
    if (filter == TEXTURE_NEAREST) {
        i0 = (int)x < w ? (int)x : w - 1;
        j0 = (int)y < h ? (int)y : h - 1;
        return texture_texel(tex, i0, j0);
    }
    /* Bilinear: texel centres sit at half-integers. */
    x -= 0.5;
    y -= 0.5;
    fx = floor(x);
    fy = floor(y);
    i0 = (int)fx;
    j0 = (int)fy;
    fx = x - fx;
    fy = y - fy;
    i1 = texture_index(i0 + 1, w, 0);
    i0 = texture_index(i0, w, 0);
    j1 = texture_index(j0 + 1, h, clamp_v);
    j0 = texture_index(j0, h, clamp_v);
    a = texture_texel(tex, i0, j0);
    b = texture_texel(tex, i1, j0);
    c = texture_texel(tex, i0, j1);
    d = texture_texel(tex, i1, j1);
    return colour_add(colour_add(colour_scale(a, (1 - fx) * (1 - fy)), colour_scale(b, fx * (1 - fy))),
                      colour_add(colour_scale(c, (1 - fx) * fy), colour_scale(d, fx * fy)));
}
