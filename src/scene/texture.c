/* texture.c: texture images and their lookup (see texture.h). */
#include "scene/texture.h"

#include <math.h>
#include <stdint.h>
#include <stdlib.h>

/* The number of texels of level k + 1 along a side of n texels. */
static int texture_half(int n)
{
    return n > 1 ? n / 2 : 1;
}

size_t texture_mipmap_memory(const Texture *t)
{
    size_t m = 0;
    int w = t->width, h = t->height;

    while (w > 1 || h > 1) {
        w = texture_half(w);
        h = texture_half(h);
        m += sizeof(TextureLevel) + 3 * (size_t)w * (size_t)h * sizeof(float);
    }
    return m;
}

size_t texture_memory(const Texture *t)
{
    return 3 * (size_t)t->width * (size_t)t->height * sizeof *t->texels +
           (t->levels ? texture_mipmap_memory(t) : 0);
}

/* Releases t's mip-map (its first level_count levels). */
static void texture_drop_mipmap(Texture *t)
{
    for (int k = 0; k < t->level_count; k++)
        free(t->levels[k].texels);
    free(t->levels);
    t->levels = NULL;
    t->level_count = 0;
}

void texture_free(Texture *tex)
{
    texture_drop_mipmap(tex);
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

/* Returns channel c of texel (i, j) of level k of tex (0: its texels). */
static double texture_at(const Texture *tex, int k, int i, int j, int c)
{
    if (k == 0)
        return tex->texels[3 * ((size_t)j * (size_t)tex->width + (size_t)i) + (size_t)c] *
               tex->scale;
    return tex->levels[k - 1].texels[3 * ((size_t)j * (size_t)tex->levels[k - 1].width +
                                          (size_t)i) + (size_t)c];
}

/* Returns the mean of the n values line[0], line[stride], ... over box i
 * of texture_half(n) boxes: [i n / half, (i + 1) n / half), the values
 * partly inside weighted by their share. Exact on the ends: in units of
 * 1 / half they are the whole numbers i n and (i + 1) n. */
static double texture_box_mean(const double *line, size_t stride, int n, int i)
{
    long half = texture_half(n), lo = (long)i * n, hi = (long)(i + 1) * n;
    double sum = 0;

    /* Value x spans [x half, (x + 1) half) in those units. */
    for (long x = lo / half; x * half < hi; x++) {
        long a = x * half > lo ? x * half : lo;
        long b = (x + 1) * half < hi ? (x + 1) * half : hi;
        sum += (double)(b - a) * line[(size_t)x * stride];
    }
    return sum / n;
}

int texture_build_mipmap(Texture *t)
{
    int count = 0, w = t->width, h = t->height;
    TextureLevel *levels;

    if (t->levels || (w == 1 && h == 1))
        return 0;
    while (w > 1 || h > 1) {
        w = texture_half(w);
        h = texture_half(h);
        count++;
    }
    levels = calloc((size_t)count, sizeof *levels);
    if (!levels)
        return -1;
    t->levels = levels;
    w = t->width;
    h = t->height;
    for (int k = 0; k < count; k++) {
        int hw = texture_half(w), hh = texture_half(h);
        double *rows = malloc(3 * (size_t)hw * (size_t)h * sizeof *rows);
        double *line = malloc(3 * (size_t)w * sizeof *line);
        float *next = malloc(3 * (size_t)hw * (size_t)hh * sizeof *next);
        if (!rows || !line || !next) {
            free(rows);
            free(line);
            free(next);
            t->level_count = k;
            texture_drop_mipmap(t);
            return -1;
        }
        t->level_count = k; /* the levels below are readable */
        /* Each row halved across, then each column down. */
        for (int j = 0; j < h; j++) {
            for (int x = 0; x < w; x++)
                for (int c = 0; c < 3; c++)
                    line[3 * (size_t)x + (size_t)c] = texture_at(t, k, x, j, c);
            for (int i = 0; i < hw; i++)
                for (int c = 0; c < 3; c++)
                    rows[3 * ((size_t)j * (size_t)hw + (size_t)i) + (size_t)c] =
                        texture_box_mean(line + c, 3, w, i);
        }
        for (int i = 0; i < hw; i++)
            for (int j = 0; j < hh; j++)
                for (int c = 0; c < 3; c++)
                    next[3 * ((size_t)j * (size_t)hw + (size_t)i) + (size_t)c] =
                        (float)texture_box_mean(rows + 3 * (size_t)i + (size_t)c, 3 * (size_t)hw, h, j);
        free(line);
        free(rows);
        levels[k].width = hw;
        levels[k].height = hh;
        levels[k].texels = next;
        w = hw;
        h = hh;
    }
    t->level_count = count;
    return 0;
}

/* Returns the size of level k of tex in *w and *h. */
static void texture_level_size(const Texture *tex, int k, int *w, int *h)
{
    *w = k == 0 ? tex->width : tex->levels[k - 1].width;
    *h = k == 0 ? tex->height : tex->levels[k - 1].height;
}

/* Returns the colour of texel (i, j) of level k of tex. */
static Colour texture_colour(const Texture *tex, int k, int i, int j)
{
    if (k == 0)
        return texture_texel(tex, i, j);
    return colour(texture_at(tex, k, i, j, 0), texture_at(tex, k, i, j, 1),
                  texture_at(tex, k, i, j, 2));
}

/* Brings u, and v as clamp_v says, into [0, 1]. */
static void texture_place(double *u, double *v, int clamp_v)
{
    *u = texture_wrap(*u);
    if (clamp_v)
        *v = isfinite(*v) ? (*v < 0 ? 0 : *v > 1 ? 1 : *v) : 0;
    else
        *v = texture_wrap(*v);
}

/* Returns the bilinear colour of level k of tex at (u, v), placed. */
static Colour texture_bilinear(const Texture *tex, int k, double u, double v, int clamp_v)
{
    int w, h, i0, j0, i1, j1;
    double x, y, fx, fy;
    Colour a, b, c, d;

    texture_level_size(tex, k, &w, &h);
    /* Image position, texel centres at half-integers. */
    x = u * w - 0.5;
    y = (1 - v) * h - 0.5;
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
    a = texture_colour(tex, k, i0, j0);
    b = texture_colour(tex, k, i1, j0);
    c = texture_colour(tex, k, i0, j1);
    d = texture_colour(tex, k, i1, j1);
    return colour_add(colour_add(colour_scale(a, (1 - fx) * (1 - fy)), colour_scale(b, fx * (1 - fy))),
                      colour_add(colour_scale(c, (1 - fx) * fy), colour_scale(d, fx * fy)));
}

Colour texture_lookup(const Texture *tex, double u, double v, TextureFilter filter, int clamp_v)
{
    int w = tex->width, h = tex->height, i, j;
    double x, y;

    texture_place(&u, &v, clamp_v);
    if (filter != TEXTURE_NEAREST)
        return texture_bilinear(tex, 0, u, v, clamp_v);
    x = u * w;
    y = (1 - v) * h;
    i = (int)x < w ? (int)x : w - 1;
    j = (int)y < h ? (int)y : h - 1;
    return texture_texel(tex, i, j);
}

/* Stores in *k the level whose texels are about `width` texels of level
 * 0 (2^k <= width < 2^(k+1)) and returns the share of the next level to
 * blend in, width / 2^k - 1 (exact: no logarithm); the last level and 0
 * past the pyramid's top, level 0 and 0 below a texel. */
static double texture_level_for(const Texture *tex, double width, int *k)
{
    int e;
    double m;

    if (!(width > 1)) {
        *k = 0;
        return 0;
    }
    m = frexp(width, &e); /* width = m 2^e, m in [0.5, 1) */
    if (e - 1 >= tex->level_count) {
        *k = tex->level_count;
        return 0;
    }
    *k = e - 1;
    return 2 * m - 1;
}

/* The weights of the EWA filter: exp(-2 r^2) - exp(-2) at r^2 = i / 128
 * (Heckbert's Gaussian, as pbrt tabulates it). */
static const double texture_gaussian[128] = {
0.8646647167633873, 0.84916115376879575, 0.83389795123973143, 0.81887138273257565,
0.80407777957686311, 0.78951352997959212, 0.77517507814342146, 0.76105892339853776,
0.74716161934798275, 0.73347977302623046, 0.72001004407080982, 0.70674914390676968,
0.69369383494378767, 0.68084092978572708, 0.66818729045244807, 0.65572982761368326,
0.64346549983479218, 0.63139131283420735, 0.61950431875239464, 0.60780161543214561,
0.59628034571002908, 0.58493769671882712, 0.57377089920078572, 0.5627772268315131,
0.55195399555435953, 0.54129856292511624, 0.53080832746687512, 0.52048072803488887,
0.51031324319127935, 0.50030339058943929, 0.49044872636797843, 0.48074684455406558,
0.47119537647602072, 0.46179199018501471, 0.4525343898857338, 0.44342031537587157,
0.43444754149431031, 0.42561387757785807, 0.41691716692640768, 0.40835528627638773,
0.39992614528237758, 0.39162768600675824, 0.38345788241727663, 0.37541473989239804,
0.36749629473432821, 0.35970061368958589, 0.35202579347700641, 0.34446996032306482,
0.33703126950440199, 0.32970790489744362, 0.32249807853500156, 0.31540003016974971,
0.30841202684446717, 0.3015323624689446, 0.29475935740344955, 0.2880913580486501,
0.28152673644189569, 0.27506388985975727, 0.26870124042672938, 0.26243723472999897,
0.25627034344018629, 0.25019906093796601, 0.24422190494647689, 0.23833741616943027,
0.23254415793482963, 0.226840715844213, 0.22122569742733428, 0.21569773180219742,
0.21025546934036182, 0.20489758133743635, 0.19962275968868226, 0.19442971656964481,
0.18931718412173704, 0.18428391414269724, 0.1793286777818463, 0.17445026524006896,
0.16964748547444658, 0.16491916590746974, 0.16026415214075806, 0.15568130767321925,
0.15116951362357739, 0.14672766845720275, 0.14235468771717724, 0.13804950375952885,
0.13381106549257116, 0.12963833812028397, 0.12553030288967226, 0.12148595684204233,
0.11750431256813376, 0.11358439796704781, 0.1097252560089132, 0.10592594450123161,
0.10218553585884543, 0.098503116877472013, 0.094877788510748767, 0.091308665650735116,
0.087794876911817116, 0.084335564417962638, 0.080929883593274604, 0.077577002955791563,
0.074276103914485109, 0.071026380569404357, 0.06782703951491903, 0.064677299646013098,
0.061576391967581356, 0.058523559406682579, 0.055518056627703621, 0.052559149850388981,
0.049646116670691576, 0.046778245884400965, 0.04395483731350594, 0.041175201635249237,
0.038438660213832437, 0.035744544934729838, 0.033092198041571541, 0.030480971975554799,
0.027910229217345706, 0.025379342131431365, 0.022887692812885718, 0.020434672936510551,
0.018019683608315767, 0.015642135219301911, 0.013301447301509811, 0.010997048386301889,
0.0087283758648405707, 0.006494875850729831, 0.0042960030447862785, 0.0021312206019067359
};

/* Returns the EWA average of level k of tex around (u, v), placed, over the
 * ellipse of the footprint d (in units of the whole image): Heckbert's
 * conic A x^2 + B x y + C y^2 < 1 in the level's texels, each texel
 * weighted by the Gaussian of its distance. */
static Colour texture_ewa_level(const Texture *tex, int k, double u, double v, const double d[4],
                                int clamp_v)
{
    int w, h;
    double s, t, ds0, dt0, ds1, dt1, a, b, c, f, det, su, sv, wsum = 0;
    Colour sum = colour(0, 0, 0);
    long s0, s1, t0, t1;

    texture_level_size(tex, k, &w, &h);
    s = u * w - 0.5;
    t = (1 - v) * h - 0.5;
    ds0 = d[0] * w;
    dt0 = -d[1] * h;
    ds1 = d[2] * w;
    dt1 = -d[3] * h;
    /* The ellipse's conic, widened by a texel so that it holds one. */
    a = dt0 * dt0 + dt1 * dt1 + 1;
    b = -2 * (ds0 * dt0 + ds1 * dt1);
    c = ds0 * ds0 + ds1 * ds1 + 1;
    f = 1 / (a * c - b * b / 4);
    a *= f;
    b *= f;
    c *= f;
    det = 4 * a * c - b * b;
    su = 2 * sqrt(det * c) / det;
    sv = 2 * sqrt(a * det) / det;
    s0 = (long)ceil(s - su);
    s1 = (long)floor(s + su);
    t0 = (long)ceil(t - sv);
    t1 = (long)floor(t + sv);
    for (long y = t0; y <= t1; y++) {
        double tt = y - t;
        for (long x = s0; x <= s1; x++) {
            double ss = x - s, r2 = a * ss * ss + b * ss * tt + c * tt * tt, wt;
            long i, j;
            if (!(r2 < 1))
                continue;
            wt = texture_gaussian[(int)(r2 * 128) < 127 ? (int)(r2 * 128) : 127];
            i = ((x % w) + w) % w;
            j = clamp_v ? (y < 0 ? 0 : y >= h ? h - 1 : y) : ((y % h) + h) % h;
            sum = colour_add(sum, colour_scale(texture_colour(tex, k, (int)i, (int)j), wt));
            wsum += wt;
        }
    }
    return wsum > 0 ? colour_scale(sum, 1 / wsum) : texture_bilinear(tex, k, u, v, clamp_v);
}

/* Returns the EWA lookup of tex (texture_lookup_footprint()). */
static Colour texture_ewa(const Texture *tex, double u, double v, const double d[4], int clamp_v)
{
    double e[4] = {d[0], d[1], d[2], d[3]};
    double x0 = d[0] * tex->width, y0 = d[1] * tex->height, x1 = d[2] * tex->width;
    double y1 = d[3] * tex->height, l0 = sqrt(x0 * x0 + y0 * y0);
    double l1 = sqrt(x1 * x1 + y1 * y1), major, minor, blend;
    int k, minor_first = l0 < l1;
    Colour lo, hi;

    /* The ellipse no more than 8 times as long as wide: its minor axis
     * stretched, so that the level it picks is not too fine. */
    major = minor_first ? l1 : l0;
    minor = minor_first ? l0 : l1;
    /* Within a texel (a magnified texture), bilinear's, as trilinear's. */
    if (!(minor > 0) || !(major > 1))
        return texture_bilinear(tex, 0, u, v, clamp_v);
    if (minor * 8 < major) {
        double g = major / (minor * 8);
        for (int q = minor_first ? 0 : 2, n = 0; n < 2; n++)
            e[q + n] *= g;
        minor *= g;
    }
    blend = texture_level_for(tex, 2 * minor, &k);
    lo = texture_ewa_level(tex, k, u, v, e, clamp_v);
    if (blend == 0)
        return lo;
    hi = texture_ewa_level(tex, k + 1, u, v, e, clamp_v);
    return colour_add(colour_scale(lo, 1 - blend), colour_scale(hi, blend));
}

Colour texture_lookup_footprint(const Texture *tex, double u, double v, const double d[4],
                                TextureFilter filter, int clamp_v)
{
    double width, blend;
    int k;

    if (!texture_filter_averages(filter) || !tex->levels)
        return texture_lookup(tex, u, v, filter, clamp_v);
    texture_place(&u, &v, clamp_v);
    if (filter == TEXTURE_EWA)
        return texture_ewa(tex, u, v, d, clamp_v);
    {
        double x0 = d[0] * tex->width, y0 = d[1] * tex->height, x1 = d[2] * tex->width;
        double y1 = d[3] * tex->height;
        width = sqrt(fmax(x0 * x0 + y0 * y0, x1 * x1 + y1 * y1));
    }
    blend = texture_level_for(tex, width, &k);
    if (blend == 0)
        return texture_bilinear(tex, k, u, v, clamp_v);
    return colour_add(colour_scale(texture_bilinear(tex, k, u, v, clamp_v), 1 - blend),
                      colour_scale(texture_bilinear(tex, k + 1, u, v, clamp_v), blend));
}

/* Returns the integral from 0 to x of the stripes' indicator (1 where the
 * fraction is below one half). */
static double texture_stripe_integral(double x)
{
    double f = floor(x), r = x - f;

    return f / 2 + (r < 0.5 ? r : 0.5);
}

double texture_stripe_cover(double s, double w)
{
    if (!(w > 0) || !isfinite(w) || !isfinite(s))
        return s - floor(s) < 0.5 ? 1 : 0;
    /* Wider than many periods, the mean. */
    if (w > 1e6)
        return 0.5;
    return (texture_stripe_integral(s + w / 2) - texture_stripe_integral(s - w / 2)) / w;
}
