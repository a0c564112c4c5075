/* bvh_sah.c: the hierarchy's binary tree, split by the surface area
 * heuristic on binned centroids (see bvh_sah.h). */
#include "bvh_sah.h"

#include <stddef.h>

#if defined(__SSE2__)
#include <emmintrin.h>
#endif

enum {
    BVH_BINS = 16,       /* centroid bins per split (n for n < 16 primitives) */
    BVH_ALL_AXES = 4096  /* at most this many primitives: SAH on every axis */
};

/* Orders prims[lo..hi) so that the k-th smallest centroid on axis is at k,
 * smaller ones before it and larger after (quickselect; each pass splits the
 * range three ways about the middle one's centroid, so the part equal to it
 * is never empty and every pass shrinks the range). */
static void bvh_select(BuildPrim *prims, size_t lo, size_t hi, size_t k, int axis)
{
    while (hi - lo > 1) {
        float pivot = bvh_centroid(&prims[lo + (hi - lo) / 2], axis);
        size_t less = lo, i = lo, more = hi; /* [lo, less) < pivot, [more, hi) > */
        while (i < more) {
            float c = bvh_centroid(&prims[i], axis);
            BuildPrim tmp = prims[i];
            if (c < pivot) {
                prims[i++] = prims[less];
                prims[less++] = tmp;
            } else if (c > pivot) {
                prims[i] = prims[--more];
                prims[more] = tmp;
            } else {
                i++;
            }
        }
        if (k < less)
            hi = less;
        else if (k >= more)
            lo = more;
        else
            return;
    }
}

#if defined(__SSE2__)
/* p's box's corners as four lanes each, the fourth not of them: its 28
 * bytes hold both 16-byte rows (lo0 lo1 lo2 hi0, and hi0 hi1 hi2 ref). */
static inline __m128 bvh_lo4(const BuildPrim *p)
{
    return _mm_loadu_ps(p->box.lo);
}

static inline __m128 bvh_hi4(const BuildPrim *p)
{
    return _mm_loadu_ps(p->box.hi);
}

/* p's centroid in lanes 0-2, each as bvh_centroid() computes it; lane 3
 * is 0. */
static inline __m128 bvh_centroid4(const BuildPrim *p)
{
    const __m128 half = _mm_set1_ps(0.5f), xyz = _mm_castsi128_ps(_mm_set_epi32(0, -1, -1, -1));

    return _mm_add_ps(_mm_mul_ps(half, _mm_and_ps(bvh_lo4(p), xyz)),
                      _mm_mul_ps(half, _mm_and_ps(bvh_hi4(p), xyz)));
}
#endif

#if !defined(__SSE2__)
/* Returns the bin of p's centroid on axis, for bins of 1 / scale from lo
 * (scale may be infinite, for centroids a few subnormals apart: the
 * product is then NaN or infinite, and each has its bin). */
static int bvh_bin(const BuildPrim *p, int axis, float lo, float scale, int bins)
{
    float x = (bvh_centroid(p, axis) - lo) * scale;

    return x >= 0 ? (x < (float)bins ? (int)x : bins - 1) : 0;
}
#endif

/* Stores in *cb the box of the centroids of prims[start..end). */
static void bvh_centroid_box(const BuildPrim *prims, size_t start, size_t end, Box *cb)
{
#if defined(__SSE2__)
    /* minps(c, lo) is c < lo ? c : lo, as box_grow_point()'s. */
    __m128 lo = _mm_set1_ps(INFINITY), hi = _mm_set1_ps(-INFINITY);
    float l[4], h[4];

    for (size_t i = start; i < end; i++) {
        __m128 c = bvh_centroid4(&prims[i]);
        lo = _mm_min_ps(c, lo);
        hi = _mm_max_ps(c, hi);
    }
    _mm_storeu_ps(l, lo);
    _mm_storeu_ps(h, hi);
    for (int a = 0; a < 3; a++) {
        cb->lo[a] = l[a];
        cb->hi[a] = h[a];
    }
#else
    box_empty(cb);
    for (size_t i = start; i < end; i++) {
        float c[3] = {bvh_centroid(&prims[i], 0), bvh_centroid(&prims[i], 1),
                     bvh_centroid(&prims[i], 2)};
        box_grow_point(cb, c);
    }
#endif
}

/* Says whether p goes left of a split at bin `at` on axis, bins of
 * 1 / scale from lo (as bvh_bin_axes() bins it): x = (centroid - lo) scale
 * is not at least at (NaN and negative x are bin 0). */
static inline int bvh_goes_left(const BuildPrim *p, int axis, float lo, float scale, float at)
{
    return !((bvh_centroid(p, axis) - lo) * scale >= at);
}

/* Lomuto's partition of prims[start..end) (bvh_partition()): every
 * primitive is swapped with the first of the others, which leaves it
 * where it is when it is itself one of them; no branch on the data.
 * Returns where the others begin. */
static size_t bvh_partition_lomuto(BuildPrim *prims, size_t start, size_t end, int axis,
                                   float lo, float scale, float at)
{
    size_t i = start;

    for (size_t j = start; j < end; j++) {
        size_t left = (size_t)bvh_goes_left(&prims[j], axis, lo, scale, at);
        BuildPrim tmp = prims[j];
        prims[j] = prims[i];
        prims[i] = tmp;
        i += left;
    }
    return i;
}

enum { BVH_BLOCK = 64 }; /* primitives a side of bvh_partition() classifies at once */

/* Moves the primitives of prims[start..end) that go left of a split at
 * bin `split` (bvh_goes_left()) in front of the others; returns where the
 * others begin. Blocks from both ends (Edelkamp and Weiss's BlockQuicksort
 * partition): each side notes, without a branch on the data, where its
 * block holds primitives of the other side, then those are swapped in
 * pairs, so only misplaced primitives move; Lomuto's scheme finishes the
 * middle. */
static size_t bvh_partition(BuildPrim *prims, size_t start, size_t end, int axis, float lo,
                            float scale, int split)
{
    const float at = (float)split;
    unsigned char wrong_l[BVH_BLOCK], wrong_r[BVH_BLOCK];
    size_t l = start, r = end; /* [start, l) go left, [r, end) right */
    int nl = 0, nr = 0, fl = 0, fr = 0;

    while (r - l >= 2 * BVH_BLOCK) {
        if (nl == 0) {
            fl = 0;
            for (int k = 0; k < BVH_BLOCK; k++) {
                wrong_l[nl] = (unsigned char)k;
                nl += !bvh_goes_left(&prims[l + (size_t)k], axis, lo, scale, at);
            }
        }
        if (nr == 0) {
            fr = 0;
            for (int k = 0; k < BVH_BLOCK; k++) {
                wrong_r[nr] = (unsigned char)k;
                nr += bvh_goes_left(&prims[r - 1 - (size_t)k], axis, lo, scale, at);
            }
        }
        for (int n = nl < nr ? nl : nr; n > 0; n--, nl--, nr--) {
            BuildPrim *a = &prims[l + wrong_l[fl++]], *b = &prims[r - 1 - wrong_r[fr++]];
            BuildPrim tmp = *a;
            *a = *b;
            *b = tmp;
        }
        if (nl == 0)
            l += BVH_BLOCK;
        if (nr == 0)
            r -= BVH_BLOCK;
    }
    return bvh_partition_lomuto(prims, l, r, axis, lo, scale, at);
}

/* A bin's box: its corners in lanes 0-2 of 16 aligned bytes each (lane 3
 * is not the box's), as the vector path loads them. */
typedef struct {
    _Alignas(16) float lo[4];
    _Alignas(16) float hi[4];
} BinBox;

/* A box being grown from bins (bvh_sah_axis()), its smallest and largest
 * corners compared as box_grow() compares them, and its half area
 * computed as box_half_area() computes it. */
#if defined(__SSE2__)
typedef struct {
    __m128 lo, hi;
} BinAcc;

static inline BinAcc bin_acc_empty(void)
{
    return (BinAcc){_mm_set1_ps(INFINITY), _mm_set1_ps(-INFINITY)};
}

static inline BinAcc bin_acc_grow(BinAcc acc, const BinBox *b)
{
    acc.lo = _mm_min_ps(_mm_load_ps(b->lo), acc.lo);
    acc.hi = _mm_max_ps(_mm_load_ps(b->hi), acc.hi);
    return acc;
}

static inline float bin_acc_area(BinAcc acc)
{
    /* d: dx dy dz; p: dx dy, dy dz, dz dx. */
    __m128 d = _mm_sub_ps(acc.hi, acc.lo);
    __m128 p = _mm_mul_ps(d, _mm_shuffle_ps(d, d, _MM_SHUFFLE(3, 0, 2, 1)));
    float xy = _mm_cvtss_f32(p), yz = _mm_cvtss_f32(_mm_shuffle_ps(p, p, 1));

    return _mm_cvtss_f32(d) < 0 ? 0 : xy + yz + _mm_cvtss_f32(_mm_movehl_ps(p, p));
}
#else
typedef Box BinAcc;

static inline BinAcc bin_acc_empty(void)
{
    Box b;
    box_empty(&b);
    return b;
}

static inline BinAcc bin_acc_grow(BinAcc acc, const BinBox *b)
{
    Box c = {{b->lo[0], b->lo[1], b->lo[2]}, {b->hi[0], b->hi[1], b->hi[2]}};
    box_grow(&acc, &c);
    return acc;
}

static inline float bin_acc_area(BinAcc acc)
{
    return box_half_area(&acc);
}
#endif

/* The primitives of prims[start..end) sorted into the centroid bins of
 * each axis whose bit is set in axes, in one pass: how many in each bin,
 * and the box of their boxes. */
static void bvh_bin_axes(const BuildPrim *prims, size_t start, size_t end, unsigned axes,
                         const float lo[3], const float scale[3], int bins,
                         uint32_t count[3][BVH_BINS], BinBox bin[3][BVH_BINS])
{
#if defined(__SSE2__)
    /* Each bin's box in four lanes (minps and maxps as box_grow()'s
     * comparisons); the bins of all three axes from one centroid, clamped
     * as bvh_bin() clamps (maxps gives its second operand for NaN). */
    const __m128 at = _mm_setr_ps(lo[0], lo[1], lo[2], 0);
    const __m128 per = _mm_setr_ps(scale[0], scale[1], scale[2], 0);
    const __m128 top = _mm_set1_ps((float)(bins - 1)), zero = _mm_setzero_ps();
    const __m128 empty_lo = _mm_set1_ps(INFINITY), empty_hi = _mm_set1_ps(-INFINITY);

    for (int a = 0; a < 3; a++) {
        for (int b = 0; b < bins; b++) {
            count[a][b] = 0;
            _mm_store_ps(bin[a][b].lo, empty_lo);
            _mm_store_ps(bin[a][b].hi, empty_hi);
        }
    }
    for (size_t i = start; i < end; i++) {
        const BuildPrim *p = &prims[i];
        __m128 x = _mm_mul_ps(_mm_sub_ps(bvh_centroid4(p), at), per);
        __m128i k = _mm_cvttps_epi32(_mm_min_ps(_mm_max_ps(x, zero), top));
        __m128 plo = bvh_lo4(p), phi = bvh_hi4(p);
        int b[3];

        b[0] = _mm_cvtsi128_si32(k);
        b[1] = _mm_cvtsi128_si32(_mm_shuffle_epi32(k, 1));
        b[2] = _mm_cvtsi128_si32(_mm_shuffle_epi32(k, 2));
        for (int a = 0; a < 3; a++) {
            if (axes >> a & 1) {
                BinBox *q = &bin[a][b[a]];
                count[a][b[a]]++;
                _mm_store_ps(q->lo, _mm_min_ps(plo, _mm_load_ps(q->lo)));
                _mm_store_ps(q->hi, _mm_max_ps(phi, _mm_load_ps(q->hi)));
            }
        }
    }
#else
    for (int a = 0; a < 3; a++) {
        for (int b = 0; b < bins; b++) {
            count[a][b] = 0;
            for (int c = 0; c < 4; c++) {
                bin[a][b].lo[c] = INFINITY;
                bin[a][b].hi[c] = -INFINITY;
            }
        }
    }
    for (size_t i = start; i < end; i++) {
        for (int a = 0; a < 3; a++) {
            if (axes >> a & 1) {
                const Box *q = &prims[i].box;
                BinBox *to = &bin[a][bvh_bin(&prims[i], a, lo[a], scale[a], bins)];
                count[a][to - bin[a]]++;
                for (int c = 0; c < 3; c++) {
                    to->lo[c] = q->lo[c] < to->lo[c] ? q->lo[c] : to->lo[c];
                    to->hi[c] = q->hi[c] > to->hi[c] ? q->hi[c] : to->hi[c];
                }
            }
        }
    }
#endif
}

/* The surface area heuristic's best split of n primitives sorted into the
 * centroid bins of one axis (count and bin, bvh_bin_axes()): the cost
 * (traversal 1, intersection 1 a primitive, areas relative to the box of
 * them all), and the first bin of the right part (-1 when no split leaves
 * both parts non-empty). Counts are converted through a signed type, to
 * the same floats in one instruction. */
static float bvh_sah_axis(const uint32_t count[BVH_BINS], const BinBox bin[BVH_BINS], int bins,
                         size_t n, int *split)
{
    int32_t left_n[BVH_BINS];
    BinAcc acc = bin_acc_empty();
    float left_area[BVH_BINS], best = INFINITY, per_area;

    *split = -1;
    /* An empty bin changes neither box nor count (its box is empty: growing
     * by it leaves the box as it was), so a split at it costs exactly what
     * the split at the next full bin costs, which the sweep below meets
     * first and keeps on a tie: no bin is passed over, and no branch asks
     * which are empty. */
    for (int b = 0, total = 0; b < bins; b++) {
        acc = bin_acc_grow(acc, &bin[b]);
        left_area[b] = bin_acc_area(acc);
        total += (int)count[b];
        left_n[b] = total;
    }
    per_area = 1 / bin_acc_area(acc); /* acc holds every bin */
    acc = bin_acc_empty();
    for (int b = bins - 1; b > 0; b--) {
        int32_t l = left_n[b - 1];
        float cost;
        acc = bin_acc_grow(acc, &bin[b]);
        cost = 1 + (left_area[b - 1] * (float)l +
                    bin_acc_area(acc) * (float)(int64_t)(n - (size_t)l)) *
                       per_area;
        if (l == 0 || (size_t)l == n) /* a part left empty: no split */
            cost = INFINITY;
        *split = cost < best ? b : *split;
        best = cost < best ? cost : best;
    }
    return best;
}

/* bvh_split() for two primitives, as it decides without binning: every
 * axis along which their centroids differ offers the same one split, of
 * cost 1 + (A0 + A1) / A (the SAH's, areas of their boxes and of the box
 * of both), so the first such axis takes it, the smaller centroid left,
 * unless it costs a leaf's 2 or more. extent: cb's, not all zero. */
static size_t bvh_split_pair(BuildPrim *prims, size_t start, const float extent[3])
{
    Box both = prims[start].box;
    float cost;
    int a = extent[0] > 0 ? 0 : extent[1] > 0 ? 1 : 2;

    box_grow(&both, &prims[start + 1].box);
    cost = 1 + (box_half_area(&prims[start].box) * 1.0f +
                box_half_area(&prims[start + 1].box) * 1.0f) *
                   (1 / box_half_area(&both));
    if (!(cost < 2))
        return start;
    if (bvh_centroid(&prims[start + 1], a) < bvh_centroid(&prims[start], a)) {
        BuildPrim tmp = prims[start];
        prims[start] = prims[start + 1];
        prims[start + 1] = tmp;
    }
    return start + 1;
}

/* Chooses how to split prims[start..end), of centroids' box cb (count >
 * BVH_LEAF_MAX or SAH says so); returns the index of the first primitive
 * of the right part, or start when it is better left a leaf. */
static size_t bvh_split(BuildPrim *prims, size_t start, size_t end, const Box *cb, int depth)
{
    size_t n = end - start, mid;
    uint32_t count[3][BVH_BINS];
    float extent[3], scale[3], best = INFINITY;
    int best_split = -1, axis;
    unsigned axes = 0;
    BinBox bin[3][BVH_BINS];
    int bins = n < BVH_BINS ? (int)n : BVH_BINS;

    for (int a = 0; a < 3; a++) {
        extent[a] = cb->hi[a] - cb->lo[a];
        scale[a] = bins / extent[a];
    }
    axis = extent[0] >= extent[1] && extent[0] >= extent[2] ? 0 : extent[1] >= extent[2] ? 1 : 2;
    if (!(extent[axis] > 0)) {
        /* All centroids at one point: split by count if the leaf is too big. */
        if (n <= BVH_LEAF_MAX)
            return start;
        return start + n / 2;
    }
    if (depth >= BVH_SAH_DEPTH) {
        mid = start + n / 2;
        bvh_select(prims, start, end, mid, axis);
        return mid;
    }
    if (n == 2)
        return bvh_split_pair(prims, start, extent);
    /* Every axis with some extent: the cheapest split wins. Above
     * BVH_ALL_AXES primitives only the longest is binned: near the root,
     * where binning costs the most, it is nearly always the best. */
    for (int a = 0; a < 3; a++)
        if (extent[a] > 0 && (n <= BVH_ALL_AXES || a == axis))
            axes |= 1u << a;
    bvh_bin_axes(prims, start, end, axes, cb->lo, scale, bins, count, bin);
    for (int a = 0; a < 3; a++) {
        int split;
        float cost;
        if (!(axes >> a & 1))
            continue;
        cost = bvh_sah_axis(count[a], bin[a], bins, n, &split);
        if (split >= 0 && cost < best) {
            best = cost;
            best_split = split;
            axis = a;
        }
    }
    if (best_split < 0 || (best >= (float)n && n <= BVH_LEAF_MAX))
        return n <= BVH_LEAF_MAX ? start : start + n / 2;
    mid = bvh_partition(prims, start, end, axis, cb->lo[axis], scale[axis], best_split);
    if (mid == start || mid == end) { /* cannot happen, but never loop */
        mid = start + n / 2;
        bvh_select(prims, start, end, mid, axis);
    }
    return mid;
}

/* Builds the binary subtree of task into nodes (see BuildTask), reordering
 * prims[task.start..task.end) by leaf; in an OpenMP parallel region, right
 * subtrees of BVH_TASK_MIN primitives or more become tasks. */
void bvh_build_subtree(BuildPrim *prims, BuildNode *nodes, BuildTask root)
{
    /* Each step pops one task and pushes at most two, one of them deeper. */
    BuildTask stack[2 * (BVH_DEPTH_MAX + 1)];
    int top = 0;

    stack[top++] = root;
    while (top > 0) {
        BuildTask task = stack[--top], left, right;
        BuildNode *node = &nodes[task.node];
        size_t split;
        Box cb; /* the box of the primitives' centroids */

        bvh_centroid_box(prims, task.start, task.end, &cb);
        node->size = (uint32_t)(task.end - task.start);
        split = task.end - task.start <= 1
                    ? task.start
                    : bvh_split(prims, task.start, task.end, &cb, task.depth);
        if (split == task.start) {
            node->index = (uint32_t)task.start;
            node->count = (uint32_t)(task.end - task.start);
            continue;
        }
        left = (BuildTask){task.start, split, task.depth + 1, task.node + 1};
        right = (BuildTask){split, task.end, task.depth + 1, task.node + 2 * (split - task.start)};
        node->count = 0;
        node->index = (uint32_t)right.node;
        if (task.end - split >= BVH_TASK_MIN) {
#ifdef _OPENMP
#pragma omp task firstprivate(right)
#endif
            bvh_build_subtree(prims, nodes, right);
        } else {
            stack[top++] = right;
        }
        stack[top++] = left;
    }
}

