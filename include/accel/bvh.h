/*
 * bvh.h: a bounding volume hierarchy over arrays of bounded shapes
 * (the kinds shape_list.h marks bounded), built with the surface area
 * heuristic on binned centroids.
 *
 * Unbounded shapes (planes, cylinders, cones) stay outside it. The binary
 * tree the heuristic builds is then collapsed, as the same heuristic plans,
 * into nodes of BVH_WIDTH children, whose boxes a ray is tested against
 * together (GNU C vector extensions: gcc and clang turn them into SIMD
 * instructions). Each box is padded so that every ray
 * the exact primitive tests accept also enters the boxes around the
 * primitive; a query visits the boxes the ray crosses, nearest first, and
 * applies the same primitive tests and the same tie rule as a loop over
 * every object, so renders are the same to the byte with or without it.
 */
#ifndef RAYTRACE_BVH_H
#define RAYTRACE_BVH_H

#include <math.h>
#include <stddef.h>
#include <stdint.h>

#include "geometry/frustum.h"
#include "geometry/ray.h"
#include "geometry/shape_list.h"

enum {
    BVH_WIDTH = 8,           /* children of a node */
    BVH_LEAF_MAX = 4,        /* most primitives in a leaf */
    BVH_MIN_PRIMITIVES = 16  /* scenes with fewer are not worth a hierarchy */
};

enum {
    BVH_SAH_DEPTH = 48, /* below this depth, splits halve the count */
    BVH_DEPTH_MAX = BVH_SAH_DEPTH + 32, /* deepest binary node: from
                                           BVH_SAH_DEPTH on, splits halve
                                           fewer than 2^32 primitives */
};

/* Returns x's margin, for x a finite double: x - m and x + m rounded to
 * floats are below and above x by half a float unit or more (m is two float
 * units of x, or a subnormal float's), and so are below and above the value
 * x approximates to a double's precision. */
static inline double bvh_margin(double x)
{
    return fabs(x) * 0x1p-22 + 0x1p-149;
}

/* Returns a float below x, a double, by half a float unit or more;
 * infinities stay. */
static inline float bvh_float_below(double x)
{
    return isinf(x) ? (float)x : (float)(x - bvh_margin(x));
}

/* Returns a float above x by half a float unit or more; infinities stay. */
static inline float bvh_float_above(double x)
{
    return isinf(x) ? (float)x : (float)(x + bvh_margin(x));
}

/* A primitive reference: its kind (a ShapeKind) in the top BVH_KIND_BITS
 * bits, as few as hold every kind, its index in the kind's array below
 * them. References sort as crossings are multiplied: by kind in
 * ShapeKind's order, then by index. */
#define BVH_KIND_BITS                                                                          \
    (SHAPE_KINDS <= 2 ? 1 : SHAPE_KINDS <= 4 ? 2 : SHAPE_KINDS <= 8 ? 3 : SHAPE_KINDS <= 16 ? 4 : 5)
#define BVH_KIND_SHIFT (32 - BVH_KIND_BITS)
#define BVH_INDEX_MASK ((1u << BVH_KIND_SHIFT) - 1)
#define BVH_MAX_OF_KIND (BVH_INDEX_MASK + 1u) /* shapes of one kind, at most */
_Static_assert(SHAPE_KINDS <= 32, "a reference holds at most 32 kinds");
_Static_assert(SHAPE_SPHERE == 0, "a reference to sphere k is k (bvh_prim_ref())");

/* Returns the reference of the shape of kind and index. */
static inline uint32_t bvh_ref(unsigned kind, size_t index)
{
    return (uint32_t)kind << BVH_KIND_SHIFT | (uint32_t)index;
}

/* Returns the kind of reference ref. */
static inline unsigned bvh_kind(uint32_t ref)
{
    return ref >> BVH_KIND_SHIFT;
}

/* Returns the index of reference ref in its kind's array. */
static inline size_t bvh_index(uint32_t ref)
{
    return ref & BVH_INDEX_MASK;
}

/* A node: up to BVH_WIDTH children, each a node or a leaf (a run of
 * primitive references), their boxes laid out by coordinate so that one
 * vector holds a coordinate of every child's box. The boxes are floats in
 * the hierarchy's frame (centre and scale below), rounded outwards, so
 * that they hold the scene's boxes; 224 bytes, aligned so that no row of
 * boxes straddles two cache lines. An unused child has the box lo = +inf,
 * hi = -inf, which no ray meets. */
typedef struct {
    _Alignas(32) float box[6][BVH_WIDTH]; /* box[c][k]: child k's lo x y z
                                             (c < 3), then hi x y z */
    uint32_t link[BVH_WIDTH];    /* child k: bvh_link() of its place */
} BvhNode;

/* A child's link: a node's index, or a leaf's first primitive reference
 * and count (1 to BVH_LEAF_MAX), in one word; count 0 for a node. Indices
 * are below BVH_MAX_LINK. */
#define BVH_LINK_SHIFT 3
#define BVH_MAX_LINK (UINT32_C(1) << (32 - BVH_LINK_SHIFT))
static inline uint32_t bvh_link(uint32_t index, unsigned count)
{
    return index << BVH_LINK_SHIFT | count;
}

/* Returns the index (node) or first primitive reference (leaf) of link. */
static inline uint32_t bvh_link_index(uint32_t link)
{
    return link >> BVH_LINK_SHIFT;
}

/* Returns the leaf's primitives of link, or 0 for a node. */
static inline uint32_t bvh_link_count(uint32_t link)
{
    return link & ((1u << BVH_LINK_SHIFT) - 1);
}

/* The shapes a hierarchy is built over: arrays it reads but does not own,
 * which must stay where they are, unchanged, while it is in use. Each
 * shape's order (its position among all objects) settles exact ties. */
typedef struct {
    const void *items[SHAPE_KINDS]; /* each bounded kind's shapes (of its
                                       type), NULL for the others */
    size_t count[SHAPE_KINDS];      /* how many: 0 for unbounded kinds */
    Sphere *movable; /* NULL, or items[SHAPE_SPHERE] itself, which
                        bvh_build() may then reorder (see there) */
} BvhShapes;

typedef struct Bvh {
    BvhShapes shapes;    /* what it was built over */
    BvhNode *nodes;      /* the root first */
    size_t node_count;
    uint32_t *prims;     /* primitive references, grouped by leaf; NULL
                            when every primitive is the sphere of its
                            slot (shapes.movable): bvh_prim_ref() */
    size_t prim_count;
    int depth;           /* deepest node, the root at 0 */
    double centre[3];    /* the frame: a node's box coordinate is that of */
    double scale;        /* the scene less centre, times scale (a power of
                            two that brings the scene within +-4) */
    int avx2;            /* queries run their AVX2 and FMA build
                            (bvh_query.h): bvh_build() sets it when the
                            processor has them; 0 runs the other */
} Bvh;

/* Returns the reference of the primitive at slot k of bvh's leaves. */
static inline uint32_t bvh_prim_ref(const Bvh *bvh, size_t k)
{
    return bvh->prims ? bvh->prims[k] : bvh_ref(SHAPE_SPHERE, k);
}

/* Builds the hierarchy of shapes' bounded shapes into *bvh in
 * O(n log n), with up to threads threads (in OpenMP builds; the hierarchy
 * is the same whatever their number). reach is the largest magnitude of
 * any coordinate, other than the shapes' own, that rays start from or
 * aim at (camera, screen, lights, unbounded shapes): the boxes' padding
 * grows with it. With shapes->movable, the spheres (their owner's, to be
 * changed) are moved into the order the leaves hold them in, and the
 * references renumbered to match: queries then read neighbouring spheres
 * from neighbouring memory, and answer as they would have (each sphere
 * keeps its order, which settles ties); a hierarchy of spheres alone then
 * gives its references back (each slot's sphere is the one of that
 * index). Without the memory to move them, they stay. Returns 0, or -1
 * (nothing allocated) when memory runs out or there are BVH_MAX_OF_KIND
 * shapes of a kind, or BVH_MAX_LINK / 2 in all. */
int bvh_build(Bvh *bvh, const BvhShapes *shapes, real reach, int threads);

/* Releases what *bvh owns. */
void bvh_free(Bvh *bvh);

/* Returns the most bytes bvh_build(), moving the spheres too, allocates
 * at once for n primitives. */
size_t bvh_build_memory(size_t n);

/* Returns the bytes bvh_build() holds at its peak for n primitives beyond
 * those the hierarchy keeps (the binary tree, while it is collapsed), which
 * are free again once it returns. */
size_t bvh_build_scratch(size_t n);

/* Returns the bytes *bvh holds. */
size_t bvh_memory(const Bvh *bvh);

/* The nearest crossing a query found. */
typedef struct {
    real t;       /* ray parameter */
    uint32_t prim;  /* primitive reference */
    unsigned order; /* the object's position among all objects */
} BvhHit;

/* Finds the shape the ray crosses first at 0 < t < tmax (the
 * earliest-listed on an exact tie); returns 1 with *hit set, or 0. */
int bvh_nearest(const Bvh *bvh, const Ray *ray, real tmax, BvhHit *hit);

/* No slot: what a shadow cache holds before any ray was occluded. */
#define BVH_NO_SLOT UINT32_MAX

/* Returns 1 when some shape crosses the ray at 0 < t < tmax (tmax = 1: the
 * segment from ray->origin to ray->origin + ray->dir), else 0; when it
 * returns 1, stores in *slot the slot (the place among the hierarchy's
 * primitives) of a primitive that crosses the ray, for
 * bvh_slot_occludes(). */
int bvh_occluder(const Bvh *bvh, const Ray *ray, real tmax, uint32_t *slot);

/* Returns 1 when the primitive at slot (a slot bvh_occluder() stored, or
 * BVH_NO_SLOT) crosses the ray at 0 < t < tmax, by the test bvh_occluder()
 * applies, else 0: a shadow ray tries its neighbour's occluder first. */
int bvh_slot_occludes(const Bvh *bvh, uint32_t slot, const Ray *ray, real tmax);

/* Told that the ray crosses the surface of primitive prim (a primitive
 * reference) `crossings` times (1 or 2); returns 0 to go on, or a non-zero
 * value that ends the walk. */
typedef int (*BvhVisit)(void *ctx, uint32_t prim, int crossings);

/* Calls visit(ctx, ...) for each shape the ray crosses at
 * 0 < t < tmax, in no set order, until one call returns non-zero; returns
 * that value, or 0 when every crossing was visited. */
int bvh_crossings(const Bvh *bvh, const Ray *ray, real tmax, BvhVisit visit, void *ctx);

/* Nodes bvh_frustum_clear() visits at most before it gives up. */
enum { BVH_FRUSTUM_VISITS = 256 };

/* Says whether no ray of f can meet a primitive of the hierarchy: 1 when
 * every leaf's box is proven beyond the pyramid (frustum_misses_box()),
 * 0 when one may not be, or when the proof would visit more than
 * BVH_FRUSTUM_VISITS nodes. */
int bvh_frustum_clear(const Bvh *bvh, const Frustum *f);

#endif
