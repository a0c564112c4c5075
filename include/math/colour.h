/*
 * colour.h: linear RGB colours on the course's 0..255 scale, and the one
 * function that turns them into output bytes.
 *
 * A Colour is unclamped while it is being computed: shading may exceed 255
 * or, in principle, go below 0. Only colour_quantise() clamps and rounds,
 * so every writer produces the same bytes from the same render.
 */
#ifndef RAYTRACE_COLOUR_H
#define RAYTRACE_COLOUR_H

#include <math.h>

typedef struct {
    double r, g, b; /* linear intensity, 0..255 for displayable values */
} Colour;

/* Builds the colour (r, g, b). */
static inline Colour colour(double r, double g, double b)
{
    Colour c = {r, g, b};
    return c;
}

/* Returns a + b, channel by channel. */
static inline Colour colour_add(Colour a, Colour b)
{
    return colour(a.r + b.r, a.g + b.g, a.b + b.b);
}

/* Returns a - b, channel by channel. */
static inline Colour colour_sub(Colour a, Colour b)
{
    return colour(a.r - b.r, a.g - b.g, a.b - b.b);
}

/* Returns s * a. */
static inline Colour colour_scale(Colour a, double s)
{
    return colour(s * a.r, s * a.g, s * a.b);
}

/* Returns a * b, channel by channel. */
static inline Colour colour_mul(Colour a, Colour b)
{
    return colour(a.r * b.r, a.g * b.g, a.b * b.b);
}

/* Returns the largest channel of c. */
static inline double colour_max(Colour c)
{
    return fmax(c.r, fmax(c.g, c.b));
}

/* Clamps one channel to [0, 255] and rounds it half up: floor(x + 0.5);
 * NaN maps to 0. This is the only place where values become bytes. Inline:
 * every pixel's three channels pass here (with the cut-off, several times);
 * x + 0.5 is then in (0.5, 255.5), where the conversion's truncation is
 * floor(). */
static inline unsigned char colour_quantise(double x)
{
    if (!(x > 0)) /* also catches NaN */
        return 0;
    if (x >= 255)
        return 255;
    return (unsigned char)(x + 0.5);
}

enum { COLOUR_LEVELS = 256 }; /* the values of a byte */

/* Returns the byte of the encoded scale whose thresholds (COLOUR_LEVELS -
 * 1 of them, ascending: thresholds[b - 1] the least colour of byte b) hold
 * x: how many of them are at most x; NaN maps to 0. The gamma-encoded
 * image's counterpart of colour_quantise() (image.h). */
static inline unsigned char colour_encode(const double *thresholds, double x)
{
    int lo = 0, hi = COLOUR_LEVELS - 1; /* the answer is in [lo, hi] */

    if (!(x > 0))
        return 0;
    while (lo < hi) {
        int mid = (lo + hi + 1) / 2;
        if (thresholds[mid - 1] <= x)
            lo = mid;
        else
            hi = mid - 1;
    }
    return (unsigned char)lo;
}

#endif
