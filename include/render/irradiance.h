/*
 * irradiance.h: the irradiance cache's pre-pass: records placed over the
 * whole picture before it is rendered, so that which records exist and
 * their values depend on nothing but the scene and the options (not on
 * threads, nor on the tile rendered).
 *
 * Placement runs in rounds over the picture's pixels, coarse to fine
 * (a grid of 2^k pixels, halved each round down to every pixel): each
 * round traces its pixels' centre rays (through mirrors and glass) to the
 * diffuse points where they would gather, keeps in pixel order those no
 * record covers (error below 0.9 a), computes their records in parallel
 * and adds them in that order. Under B > 1 bounces, the points their
 * gathering rays meet are covered in turn, generation by generation, in
 * fixed chunks. A record's deepest level holds the light of its rays' hits
 * alone; each level above is gathered again, every record in parallel,
 * its rays' hits looking up the level below (a hit no record covers
 * gathers for itself, as without the cache).
 *
 * A record's radius is the harmonic mean of its rays' distances, no more
 * than its value over its translational gradient, within 1.5 pixels and a
 * quarter of the picture's width seen at its distance from the eye.
 */
#ifndef RAYTRACE_IRRADIANCE_H
#define RAYTRACE_IRRADIANCE_H

#include "image/image.h"
#include "render/gicache.h"
#include "render/render.h"
#include "scene/scene.h"

/* What the pre-pass did, for -v. */
typedef struct {
    size_t records;       /* records made */
    size_t seen;          /* of them, at points the camera's rays reach */
    unsigned long long rays; /* rays it cast, of every kind */
    double seconds;       /* its wall time */
} IrradianceStats;

/* Fills *cache (made here; gicache_free() releases it) with the records
 * of scene's picture under opts (its indirect settings, depth, shadows and
 * threads), within what is left of the scene's memory limit; adds the rays
 * cast to *counts (may be NULL) and says what it did in *stats. Returns 0,
 * -1 when memory runs out or SCENE_OVER_LIMIT when the cache would pass
 * the limit (the cache then empty). */
int irradiance_build(const Scene *scene, const RenderOptions *opts, GiCache *cache,
                     RayCounts *counts, IrradianceStats *stats);

/* Draws into map (the whole picture's size, its bytes the render's) where
 * the records fell: the picture at a third of its brightness, and each of
 * the first `seen` records (those the camera's rays reach: stats.seen) a
 * red pixel where it is seen from the eye. */
void irradiance_map(const Scene *scene, const GiCache *cache, size_t seen, Image *map);

#endif
