/*
 * gicache.h: the irradiance cache (Ward, Rubinstein and Clear 1988, with
 * the gradients of Ward and Heckbert 1992): records of the light gathered
 * over the hemisphere at a few points, interpolated elsewhere.
 *
 * A record at point P with unit normal N keeps, for each bounce level, the
 * mean G of the colours its gathering rays brought back (the quantity
 * trace.h reflects: kd C * G / 255), its rotational gradient (how G
 * changes as the normal turns) and translational gradient (as the point
 * moves on the surface), and a radius R: the harmonic mean of the
 * distances its rays met something at, clamped. Its error at a point x of
 * normal n is
 *     e = |x - P| / R + sqrt(1 - n . N),
 * and it is valid there when e < a, a the cache's accuracy (--gi-cache-error)
 * and the record not in front of x. The light at x is the weighted mean over
 * the valid records of G + (N x n) . rot + (x - P) . trans, each weighing
 * 1/e - 1/a (which falls to 0 at the edge of validity, so a record
 * coming into reach adds no step).
 *
 * The gathering is stratified: M x N cells of the cosine-weighted
 * hemisphere (M in cos^2 theta, N in phi, M N close to the rays asked for,
 * N about pi M), one ray a cell jittered by a hash of the record's key, so
 * that a record depends on nothing but its point, normal and key.
 *
 * This module holds the records and their arithmetic; render/irradiance.h
 * places them over a picture. A GiCache is read by any number of threads
 * at once; adding to it is for one thread at a time.
 */
#ifndef RAYTRACE_GICACHE_H
#define RAYTRACE_GICACHE_H

#include <stddef.h>
#include <stdint.h>

#include "math/colour.h"
#include "math/vec3.h"

/* The accuracy a, and the rays a record gathers, when none are given
 * (SCENE_GI_CACHE_MIN_ERROR to SCENE_GI_CACHE_MAX_ERROR; --gi N): a
 * typical room at -s 16 within about a level of its converged render
 * (docs/gicache.md, make trade-cache). */
#define GICACHE_DEFAULT_ERROR 0.3
#define GICACHE_DEFAULT_RAYS 2048

/* How far, in a, a point none of the records covers looks before it
 * gathers its own light: the widest a lookup reaches. */
#define GICACHE_FALLBACK_REACH 2.0

/* The rays a camera's point gathers when no record covers it even there,
 * of a record's `rays`: a sixteenth, at least 16 (never more than rays).
 * It stands for one sample's gathering among its pixel's, not a record's:
 * on scenes/indirect.txt at -s 16 (345 such points of 653,414) 0.92 of
 * the time for an RMSE of 0.7934 against 0.7931 with every ray
 * (docs/log.md). */
static inline int gicache_fallback_rays(int rays)
{
    return rays / 16 > 16 ? rays / 16 : rays < 16 ? rays : 16;
}

/* What one record keeps for one bounce level: the mean colour of its
 * gathering rays (0..255 per channel, as trace.h's) and its gradients,
 * channel by channel, in scene units. */
typedef struct {
    Colour g;
    Vec3 rot[3];   /* dG / d(rotation of the normal about an axis w) = w . rot */
    Vec3 trans[3]; /* dG / d(move of the point by v, in the tangent plane) = v . trans */
} GiValue;

/* The eighths of the tangent plane around a record's normal, in its
 * frame (vec3_from_frame()'s first two axes): a record's rays within 30
 * degrees of the plane say how far along its surface it sees each way. */
#define GICACHE_SECTORS 8

/* A record's place: its point, unit normal and radius, the share of its
 * rays that met nothing, the first level it holds (lookups of the levels
 * before pass it by), and, for each eighth of its tangent plane, the
 * reciprocal of the distance along the plane at which the nearest of its
 * rays within 30 degrees of the plane met a surface (0: none did): a
 * lookup past it would take light from beyond a neighbouring surface (the
 * other side of a thin wall, under a ball resting on the floor). */
typedef struct {
    Vec3 point;
    Vec3 normal;
    double radius; /* R, scene units, > 0 */
    double open;   /* 0..1 */
    int first;     /* 0: every level */
    float near[GICACHE_SECTORS];
} GiPlace;

/* The colour a ray leaving the record's point in direction dir (unit)
 * brings back into *c, returning the distance at which it met something
 * (INFINITY: nothing); ctx is the caller's. */
typedef double (*GiSample)(void *ctx, Vec3 dir, Colour *c);

/* Stores in *m and *n the strata of a gathering of `rays` rays (>= 1):
 * m x n is the rays cast, within a stratum of `rays`. */
void gicache_strata(int rays, int *m, int *n);

/* Gathers at a point of unit normal `normal` over m x n strata (jitter
 * drawn from key) through sample(ctx, ...); stores the mean and gradients
 * in *v, in *harmonic the harmonic mean of the distances met (INFINITY
 * when no ray met anything), in *open the share of rays that met nothing
 * and in sees (GiPlace's near) how far along the plane it sees. The
 * translational gradient takes distances below `near` as near (>= 0): a
 * surface meeting the point's at a corner would make it grow without
 * bound. Returns 0, or -1 when memory runs out. */
int gicache_gather(Vec3 normal, int m, int n, uint64_t key, double near, GiSample sample,
                   void *ctx, GiValue *v, double *harmonic, double *open,
                   float sees[GICACHE_SECTORS]);

/* Shortens v's translational gradients so that none changes its channel
 * by more than the channel's own value over `reach` (scene units): the
 * extrapolation then stays within 0 and twice the value (a ray meeting a
 * wall at a corner makes the estimate grow without bound). */
void gicache_limit(GiValue *v, double reach);

/* Returns record `place`'s error e at point x of unit normal nx (above),
 * or INFINITY when the record lies in front of x (seen from x's side) or
 * x lies past the nearest surface the record sees that way (its near). */
double gicache_error(const GiPlace *place, Vec3 x, Vec3 nx);

/* Returns the weight of a record of error e under accuracy a: 1/e - 1/a
 * when e < a (1e12 at e = 0), else 0. */
double gicache_weight(double e, double a);

/* Returns value v of a record at place, carried to point x of normal nx by
 * its gradients (each channel at least 0). */
Colour gicache_extrapolate(const GiPlace *place, const GiValue *v, Vec3 x, Vec3 nx);

/* A hash grid over space by which a lookup finds the records near a
 * point: each record is entered in the cells its reach (reach a R) overlaps,
 * cells of at least that reach a side. */
typedef struct GiGrid {
    double reach;      /* the widest lookup reach it serves */
    struct GiEntry *entries; /* the records' places in the grid's cells */
    size_t entry_count;
    struct GiCell *cells; /* open addressing, cell_capacity (a power of 2) */
    size_t cell_count, cell_capacity;
    int scales[64];    /* the cell sizes in use, as exponents of 2, ascending */
    int scale_count;
} GiGrid;

/* The cache: records, their values (levels of them each), and two grids:
 * one for the lookups of reach 1 (most of them), its cells the smaller,
 * and one for the wider ones. */
typedef struct GiCache {
    double a;          /* accuracy: the error a record is valid within */
    int levels;        /* bounce levels each record keeps, >= 1 */
    GiPlace *places;   /* count of them, in the order added */
    GiValue *values;   /* count x levels: record i's level k at i x levels + k */
    size_t count, capacity;
    GiGrid grids[2];   /* reach 1, then the widest reach */
    size_t limit;      /* bytes the cache may take; 0: no limit */
} GiCache;

/* Makes *c an empty cache of accuracy a with `levels` bounce levels whose
 * memory may not pass limit bytes (0: no limit). */
void gicache_init(GiCache *c, double a, int levels, size_t limit);

/* Releases what *c holds and leaves it empty. */
void gicache_free(GiCache *c);

/* Appends a record at place with values[0..levels-1], its radius and its
 * neighbours' clamped so that none exceeds another's plus their distance
 * (Krivanek et al. 2006, the records whose cells hold the point); returns
 * 0, -1 when memory runs out, or -2 when it would pass the cache's limit. */
int gicache_add(GiCache *c, const GiPlace *place, const GiValue *values);

/* Files every record again in the grid by its radius as neighbour clamping
 * left it (lookups then read fewer records); returns 0, -1 when memory
 * runs out, or -2 when it would pass the cache's limit. */
int gicache_refile(GiCache *c);

/* Sets the value of level `level` of record i. */
void gicache_set(GiCache *c, size_t i, int level, const GiValue *v);

/* Interpolates level `level` at point x of unit normal nx from the records
 * valid there under accuracy c->a times `reach` (1: the cache's own) and
 * holding that level (first <= level) into *out; returns the number of
 * records used (0: none valid, *out untouched). */
int gicache_lookup(const GiCache *c, int level, double reach, Vec3 x, Vec3 nx, Colour *out);

/* No record: a hint of gicache_any() before its first lookup. */
#define GICACHE_NO_HINT UINT32_MAX

/* As gicache_lookup(), but into *out the value of one record valid at x
 * (holding that level), carried there by its gradients, not a blend of
 * them all; returns 1, or 0 when none is valid. Within the cache's
 * accuracy as any one valid record is, without the blend's smooth seams
 * between records: for the light a gathering ray brings, which reaches
 * the picture only averaged over a record's rays. The record: hint[0]'s,
 * else hint[1]'s, when hint is not NULL and that one is valid at x (a
 * gathering's rays meet points near those of the rays before them: the
 * caller's recent records spare it the grid), else the first the grid
 * lists as valid; whichever it is is left in hint[0]. */
int gicache_any(const GiCache *c, int level, double reach, Vec3 x, Vec3 nx, uint32_t hint[2],
                Colour *out);

/* Returns the bytes *c holds. */
size_t gicache_memory(const GiCache *c);

#endif
