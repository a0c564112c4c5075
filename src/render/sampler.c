/* sampler.c: multi-jittered pixel and lens samples (see sampler.h). */
#include "render/sampler.h"

#include <math.h>
#include <stdint.h>

#include "math/angle.h"

/* Returns a well-mixed 64-bit hash of x: a xor-shift-multiply finaliser,
 * each step a bijection, so distinct inputs give distinct outputs. */
static uint64_t sampler_mix(uint64_t x)
{
    x ^= x >> 31;
    x *= 0xbf58476d1ce4e5b9u;
    x ^= x >> 29;
    x *= 0x94d049bb133111ebu;
    x ^= x >> 32;
    return x;
}

/* Returns a number in [0, 1) from the top 53 bits of hash h. */
static double sampler_unit(uint64_t h)
{
    return (double)(h >> 11) * 0x1p-53;
}

/*
 * Returns the image of i under a permutation of 0..len-1 chosen by seed.
 * Each round below is a bijection of the b-bit numbers (b the bits of len -
 * 1): xor with a constant, multiplication by an odd number modulo 2^b, and
 * x ^= x >> s. Their composition permutes 0..2^b-1; applying it until the
 * value falls below len (cycle walking) permutes 0..len-1.
 */
static unsigned sampler_permute(unsigned i, unsigned len, uint64_t seed)
{
    uint32_t mask = len - 1, a = (uint32_t)seed, b = (uint32_t)(seed >> 32) | 1u;

    mask |= mask >> 1;
    mask |= mask >> 2;
    mask |= mask >> 4;
    mask |= mask >> 8;
    mask |= mask >> 16;
    do {
        i = ((i ^ a) * 0x9e3779b1u) & mask;
        i ^= i >> 3;
        i = (i * b) & mask;
        i ^= i >> 5;
        i = ((i ^ (a >> 16)) * 0x85ebca6bu) & mask;
        i ^= i >> 1;
        i = (i * 0xc2b2ae35u) & mask;
        i ^= i >> 7;
    } while (i >= len);
    return i;
}

SamplerGrid sampler_grid(unsigned n)
{
    SamplerGrid g;

    g.progressive = 0;
    g.n = n;
    g.cols = 1;
    for (unsigned d = 1; d * d <= n; d++)
        if (n % d == 0)
            g.cols = d;
    g.rows = n / g.cols;
    return g;
}

SamplerGrid sampler_progressive(void)
{
    SamplerGrid g = {1, 1, 1, 1};

    return g;
}

/* Returns x with its 32 bits in reverse order. */
static uint32_t sampler_reverse(uint32_t x)
{
    x = (x << 16) | (x >> 16);
    x = ((x & 0x00ff00ffu) << 8) | ((x & 0xff00ff00u) >> 8);
    x = ((x & 0x0f0f0f0fu) << 4) | ((x & 0xf0f0f0f0u) >> 4);
    x = ((x & 0x33333333u) << 2) | ((x & 0xccccccccu) >> 2);
    return ((x & 0x55555555u) << 1) | ((x & 0xaaaaaaaau) >> 1);
}

/* Returns x (a 32-bit binary fraction) scrambled by Owen's nested uniform
 * scrambling for seed: each bit flipped or not by a hash of the bits
 * above it. Done, after Laine and Karras and Burley ("Practical hash-based
 * Owen scrambling", JCGT 2020), as a hash of the reversed bits in which
 * each bit only changes those above it (multiplications by even numbers,
 * an addition), reversed back. */
static uint32_t sampler_owen(uint32_t x, uint32_t seed)
{
    x = sampler_reverse(x);
    x += seed;
    x ^= x * 0x6c50b47cu;
    x ^= x * 0xb82f1e52u;
    x ^= x * 0xc7afe638u;
    x ^= x * 0x8d22f6e6u;
    return sampler_reverse(x);
}

/* Returns the second dimension of Sobol's sequence at index k, as a 32-bit
 * binary fraction: its direction numbers are those of the polynomial x + 1,
 * v_1 = 1/2 and v_(i+1) = v_i xor v_i / 2 (the first dimension is the
 * bits of k reversed). */
static uint32_t sampler_sobol1(uint32_t k)
{
    uint32_t v = 1u << 31, r = 0;

    for (; k; k >>= 1, v ^= v >> 1)
        if (k & 1)
            r ^= v;
    return r;
}

void sampler_sobol(uint64_t seed, uint32_t k, double xy[2])
{
    uint64_t h = sampler_mix(seed);
    /* The index shuffled by its own scrambling (whole aligned blocks of
     * points stay together), then each dimension scrambled. */
    uint32_t i = sampler_owen(k, (uint32_t)h);

    h = sampler_mix(h);
    xy[0] = sampler_owen(sampler_reverse(i), (uint32_t)h) * 0x1p-32;
    xy[1] = sampler_owen(sampler_sobol1(i), (uint32_t)(h >> 32)) * 0x1p-32;
}

/* Returns the seed of pixel (px, py)'s sequence in dimension dim. */
static uint64_t sampler_seed(int px, int py, uint64_t dim)
{
    return sampler_mix(((uint64_t)(uint32_t)py << 32 | (uint32_t)px) ^
                       sampler_mix(sampler_mix(dim) + 0x9e3779b97f4a7c15u));
}

/* Stores in xy point k of pixel (px, py)'s multi-jittered pattern of g->n
 * points in dimension dim (sampler_sample(), without its centre for one
 * point). */
static void sampler_jitter(const SamplerGrid *g, int px, int py, unsigned k, uint64_t dim,
                           double xy[2])
{
    uint64_t seed, s;
    unsigned i, j;

    seed = sampler_mix(((uint64_t)(uint32_t)py << 32 | (uint32_t)px) ^ sampler_mix(dim + 1));
    /* Dimensions other than the first visit the cells in their own order,
     * so that a pixel sample and its lens sample are not correlated. */
    if (dim != 0)
        k = sampler_permute(k, g->n, sampler_mix(seed ^ 0x5bd1e995u));
    i = k % g->cols;
    j = k / g->cols;
    s = sampler_mix(seed + 2 * (uint64_t)k + 1);
    /* Cell (i, j); within it, the column's sub-strip sigma_i(j) across and
     * the row's sub-strip tau_j(i) down, each a permutation. */
    xy[0] = (i + (sampler_permute(j, g->rows, sampler_mix(seed ^ (0x10000u + i))) +
                  sampler_unit(s)) /
                     g->rows) /
            g->cols;
    xy[1] = (j + (sampler_permute(i, g->cols, sampler_mix(seed ^ (0x20000000u + j))) +
                  sampler_unit(sampler_mix(s))) /
                     g->cols) /
            g->rows;
}

void sampler_sample(const SamplerGrid *g, int px, int py, unsigned k, unsigned dim, double xy[2])
{
    if (g->progressive) {
        sampler_sobol(sampler_seed(px, py, dim), k, xy);
        return;
    }
    if (g->n == 1) {
        xy[0] = xy[1] = 0.5;
        return;
    }
    sampler_jitter(g, px, py, k, dim, xy);
}

uint64_t sampler_branch(uint64_t key, unsigned branch)
{
    return sampler_mix(key * 0x9e3779b97f4a7c15u + branch + 1);
}

void sampler_square(const SamplerGrid *g, int px, int py, unsigned k, uint64_t key,
                    double xy[2])
{
    /* Past the pixel and lens dimensions, whatever the key. */
    if (g->progressive)
        sampler_sobol(sampler_seed(px, py, key | 0x8000000000000000u), k, xy);
    else
        sampler_jitter(g, px, py, k, key | 0x8000000000000000u, xy);
}

void sampler_hemisphere(const SamplerGrid *g, int px, int py, unsigned k, uint64_t key,
                        double dir[3])
{
    double xy[2], disk[2], r2;

    sampler_square(g, px, py, k, key, xy);
    sampler_disk(xy, disk);
    r2 = disk[0] * disk[0] + disk[1] * disk[1];
    dir[0] = disk[0];
    dir[1] = disk[1];
    dir[2] = r2 < 1 ? sqrt(1 - r2) : 0;
}

void sampler_disk(const double xy[2], double disk[2])
{
    double a = 2 * xy[0] - 1, b = 2 * xy[1] - 1, r, s, c;

    if (a == 0 && b == 0) {
        disk[0] = disk[1] = 0;
        return;
    }
    /* Square rings map to circles; the angle along a ring's side, at most
     * pi / 4 from the side's middle, is proportional to the offset. */
    if (a * a > b * b) {
        r = a;
        angle_sincos(ANGLE_PI / 4 * (b / a), &s, &c);
        disk[0] = r * c;
        disk[1] = r * s;
    } else {
        r = b;
        angle_sincos(ANGLE_PI / 4 * (a / b), &s, &c);
        disk[0] = r * s;
        disk[1] = r * c;
    }
}
