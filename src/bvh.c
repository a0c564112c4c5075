/* bvh.c: building and querying the bounding volume hierarchy (see bvh.h). */
#include "bvh.h"

#include <float.h>
#include <math.h>
#include <stdlib.h>
#include <string.h>

#include "scene.h"

enum {
    BVH_BINS = 16,        /* centroid bins per split */
    BVH_SAH_DEPTH = 48,   /* below this depth, splits halve the count */
    BVH_STACK = 128,      /* traversal stack: BVH_SAH_DEPTH + 32 + margin */
    BVH_ALL_AXES = 4096   /* at most this many primitives: SAH on every axis */
};

/* A box, as lo and hi corners. */
typedef struct {
    real lo[3], hi[3];
} Box;

static void box_empty(Box *b)
{
    for (int a = 0; a < 3; a++) {
        b->lo[a] = INFINITY;
        b->hi[a] = -INFINITY;
    }
}

/* Boxes never hold NaN (they come from finite coordinates), so plain
 * comparisons do what fmin() and fmax() would, without a call. */
static inline void box_grow(Box *b, const Box *c)
{
    for (int a = 0; a < 3; a++) {
        b->lo[a] = c->lo[a] < b->lo[a] ? c->lo[a] : b->lo[a];
        b->hi[a] = c->hi[a] > b->hi[a] ? c->hi[a] : b->hi[a];
    }
}

static inline void box_grow_point(Box *b, const real p[3])
{
    for (int a = 0; a < 3; a++) {
        b->lo[a] = p[a] < b->lo[a] ? p[a] : b->lo[a];
        b->hi[a] = p[a] > b->hi[a] ? p[a] : b->hi[a];
    }
}

/* Half the surface area of b (0 for an empty box). */
static real box_half_area(const Box *b)
{
    real dx = b->hi[0] - b->lo[0], dy = b->hi[1] - b->lo[1], dz = b->hi[2] - b->lo[2];
    return dx < 0 ? 0 : dx * dy + dy * dz + dz * dx;
}

/* What the build needs of each primitive. */
typedef struct {
    Box box;         /* padded bounds */
    uint32_t ref;    /* primitive reference */
} BuildPrim;

/* Returns coordinate axis of the centre of p's box, its centroid. */
static real bvh_centroid(const BuildPrim *p, int axis)
{
    return 0.5 * p->box.lo[axis] + 0.5 * p->box.hi[axis];
}

/* The padding of every box, in units of the scene's largest coordinate
 * times REAL_EPSILON. The primitive tests round at a few REAL_EPSILON of the
 * distances involved, all below twice that coordinate. Double takes 2^16
 * (boxes 1.5e-11 of the scene wider: a 10^4-fold margin that costs nothing
 * measurable); float takes 2^6 (7.6e-6 of the scene), as 2^16 would widen
 * every box by 1/128 of the scene. Spheres' radii grow by 1/16 of that. */
#ifdef RAYTRACE_REAL_FLOAT
#define BVH_PAD_ULPS 0x1p6
#else
#define BVH_PAD_ULPS 0x1p16
#endif

static real bvh_padding(const Scene *scene)
{
    real m = fmax(vec3_max_abs(scene->camera.eye),
                    fmax(vec3_max_abs(scene->camera.top_left),
                         vec3_max_abs(vec3_add(scene->camera.top_left,
                                               vec3_add(scene->camera.u, scene->camera.v)))));

    for (size_t i = 0; i < scene->light_count; i++)
        m = fmax(m, vec3_max_abs(scene->lights[i].position));
    for (size_t i = 0; i < scene->sphere_count; i++)
        m = fmax(m, vec3_max_abs(scene->spheres[i].centre) + scene->spheres[i].radius);
    for (size_t i = 0; i < scene->plane_count; i++)
        m = fmax(m, vec3_max_abs(scene->planes[i].point));
    for (size_t i = 0; i < scene->triangle_count; i++)
        for (int k = 0; k < 3; k++)
            m = fmax(m, vec3_max_abs(scene->triangles[i].v[k]));
    return m * (REAL_EPSILON * BVH_PAD_ULPS);
}

static void bvh_prim_box(const Scene *scene, uint32_t ref, real pad, BuildPrim *p)
{
    p->ref = ref;
    if (ref & BVH_TRIANGLE) {
        const Triangle *t = &scene->triangles[ref & ~BVH_TRIANGLE];
        box_empty(&p->box);
        for (int k = 0; k < 3; k++) {
            real v[3] = {t->v[k].x, t->v[k].y, t->v[k].z};
            box_grow_point(&p->box, v);
        }
        for (int a = 0; a < 3; a++) {
            p->box.lo[a] -= pad;
            p->box.hi[a] += pad;
        }
    } else {
        const Sphere *s = &scene->spheres[ref];
        real c[3] = {s->centre.x, s->centre.y, s->centre.z};
        real r = s->radius * (1 + REAL_EPSILON * (BVH_PAD_ULPS / 16)) + pad;
        for (int a = 0; a < 3; a++) {
            p->box.lo[a] = c[a] - r;
            p->box.hi[a] = c[a] + r;
        }
    }
}

/* Orders prims[lo..hi) so that the k-th smallest centroid on axis is at k,
 * smaller ones before it and larger after (quickselect). */
static void bvh_select(BuildPrim *prims, size_t lo, size_t hi, size_t k, int axis)
{
    while (hi - lo > 1) {
        real pivot = bvh_centroid(&prims[lo + (hi - lo) / 2], axis);
        size_t i = lo, j = hi - 1;
        for (;;) {
            while (bvh_centroid(&prims[i], axis) < pivot)
                i++;
            while (bvh_centroid(&prims[j], axis) > pivot)
                j--;
            if (i >= j)
                break;
            BuildPrim tmp = prims[i];
            prims[i] = prims[j];
            prims[j] = tmp;
            i++;
            j--;
        }
        if (k <= j)
            hi = j + 1;
        else
            lo = j + 1;
    }
}

/* A piece of work: build the subtree of prims[start..end) at depth; a
 * right subtree writes its root's index into its parent's node. */
typedef struct {
    size_t start, end;
    int depth;
    int is_right;     /* 1: a right child, whose parent waits for its index */
    size_t parent;    /* that parent */
} BuildTask;

/* Returns the bin of p's centroid on axis, for bins of 1 / scale from lo. */
static int bvh_bin(const BuildPrim *p, int axis, real lo, real scale)
{
    int b = (int)((bvh_centroid(p, axis) - lo) * scale);

    return b < 0 ? 0 : b >= BVH_BINS ? BVH_BINS - 1 : b;
}

/* The surface area heuristic's best split of prims[start..end) into the
 * centroid bins of one axis: the cost (traversal 1, intersection 1 a
 * primitive, areas relative to bounds), and the first bin of the right
 * part (-1 when no split leaves both parts non-empty). */
static real bvh_sah_axis(const BuildPrim *prims, size_t start, size_t end, const Box *bounds,
                           int axis, real lo, real scale, int *split)
{
    size_t count[BVH_BINS] = {0}, left_n[BVH_BINS], n = end - start;
    Box bin[BVH_BINS], left[BVH_BINS], acc;
    real best = INFINITY;

    *split = -1;
    for (int b = 0; b < BVH_BINS; b++)
        box_empty(&bin[b]);
    for (size_t i = start; i < end; i++) {
        int b = bvh_bin(&prims[i], axis, lo, scale);
        count[b]++;
        box_grow(&bin[b], &prims[i].box);
    }
    box_empty(&acc);
    for (int b = 0, total = 0; b < BVH_BINS; b++) {
        box_grow(&acc, &bin[b]);
        total += (int)count[b];
        left[b] = acc;
        left_n[b] = (size_t)total;
    }
    box_empty(&acc);
    for (int b = BVH_BINS - 1; b > 0; b--) {
        real cost;
        box_grow(&acc, &bin[b]);
        if (left_n[b - 1] == 0 || left_n[b - 1] == n)
            continue;
        cost = 1 + (box_half_area(&left[b - 1]) * (real)left_n[b - 1] +
                    box_half_area(&acc) * (real)(n - left_n[b - 1])) /
                       box_half_area(bounds);
        if (cost < best) {
            best = cost;
            *split = b;
        }
    }
    return best;
}

/* Chooses how to split prims[start..end) (count > BVH_LEAF_MAX or SAH says
 * so); returns the index of the first primitive of the right part, or
 * start when it is better left a leaf. Sets *axis. */
static size_t bvh_split(BuildPrim *prims, size_t start, size_t end, const Box *bounds, int depth,
                        int *axis)
{
    size_t n = end - start, mid;
    Box cb;
    real extent[3], scale[3], best = INFINITY;
    int best_split = -1;

    box_empty(&cb);
    for (size_t i = start; i < end; i++) {
        real c[3] = {bvh_centroid(&prims[i], 0), bvh_centroid(&prims[i], 1),
                       bvh_centroid(&prims[i], 2)};
        box_grow_point(&cb, c);
    }
    for (int a = 0; a < 3; a++) {
        extent[a] = cb.hi[a] - cb.lo[a];
        scale[a] = BVH_BINS / extent[a];
    }
    *axis = extent[0] >= extent[1] && extent[0] >= extent[2] ? 0 : extent[1] >= extent[2] ? 1 : 2;
    if (!(extent[*axis] > 0)) {
        /* All centroids at one point: split by count if the leaf is too big. */
        if (n <= BVH_LEAF_MAX)
            return start;
        return start + n / 2;
    }
    if (depth >= BVH_SAH_DEPTH) {
        mid = start + n / 2;
        bvh_select(prims, start, end, mid, *axis);
        return mid;
    }
    /* Every axis with some extent: the cheapest split wins. Above
     * BVH_ALL_AXES primitives only the longest is binned: near the root,
     * where binning costs the most, it is nearly always the best. */
    for (int a = 0; a < 3; a++) {
        int split;
        real cost;
        if (!(extent[a] > 0) || (n > BVH_ALL_AXES && a != *axis))
            continue;
        cost = bvh_sah_axis(prims, start, end, bounds, a, cb.lo[a], scale[a], &split);
        if (split >= 0 && cost < best) {
            best = cost;
            best_split = split;
            *axis = a;
        }
    }
    if (best_split < 0 || (best >= (real)n && n <= BVH_LEAF_MAX))
        return n <= BVH_LEAF_MAX ? start : start + n / 2;
    /* Partition by bin. */
    {
        size_t i = start, j = end;
        while (i < j) {
            if (bvh_bin(&prims[i], *axis, cb.lo[*axis], scale[*axis]) < best_split) {
                i++;
            } else {
                BuildPrim tmp = prims[i];
                prims[i] = prims[--j];
                prims[j] = tmp;
            }
        }
        mid = i;
    }
    if (mid == start || mid == end) { /* cannot happen, but never loop */
        mid = start + n / 2;
        bvh_select(prims, start, end, mid, *axis);
    }
    return mid;
}

int bvh_build(Bvh *bvh, const Scene *scene)
{
    size_t n = scene->sphere_count + scene->triangle_count, top = 0, cap_nodes;
    BuildPrim *prims;
    BuildTask *stack;
    real pad = bvh_padding(scene);

    memset(bvh, 0, sizeof *bvh);
    if (scene->sphere_count >= BVH_TRIANGLE || scene->triangle_count >= BVH_TRIANGLE || n == 0)
        return -1;
    cap_nodes = 2 * n;
    prims = malloc(n * sizeof *prims);
    stack = malloc((BVH_SAH_DEPTH + 70) * 2 * sizeof *stack);
    bvh->nodes = malloc(cap_nodes * sizeof *bvh->nodes);
    bvh->prims = malloc(n * sizeof *bvh->prims);
    if (!prims || !stack || !bvh->nodes || !bvh->prims) {
        free(prims);
        free(stack);
        bvh_free(bvh);
        return -1;
    }
    for (size_t i = 0; i < scene->sphere_count; i++)
        bvh_prim_box(scene, (uint32_t)i, pad, &prims[i]);
    for (size_t i = 0; i < scene->triangle_count; i++)
        bvh_prim_box(scene, (uint32_t)i | BVH_TRIANGLE, pad, &prims[scene->sphere_count + i]);
    stack[top++] = (BuildTask){0, n, 0, 0, 0};
    while (top > 0) {
        BuildTask task = stack[--top];
        size_t id = bvh->node_count++, split;
        BvhNode *node = &bvh->nodes[id];
        Box bounds;
        int axis = 0;

        if (task.is_right)
            bvh->nodes[task.parent].index = (uint32_t)id;
        box_empty(&bounds);
        for (size_t i = task.start; i < task.end; i++)
            box_grow(&bounds, &prims[i].box);
        memcpy(node->box, bounds.lo, sizeof bounds.lo);
        memcpy(node->box + 3, bounds.hi, sizeof bounds.hi);
        if (task.depth > bvh->depth)
            bvh->depth = task.depth;
        split = task.end - task.start <= 1
                    ? task.start
                    : bvh_split(prims, task.start, task.end, &bounds, task.depth, &axis);
        if (split == task.start) {
            node->index = (uint32_t)task.start;
            node->count = (uint16_t)(task.end - task.start);
            node->axis = 0;
            continue;
        }
        node->count = 0;
        node->axis = (uint16_t)axis;
        /* The left subtree comes next; the right one patches our index. */
        stack[top++] = (BuildTask){split, task.end, task.depth + 1, 1, id};
        stack[top++] = (BuildTask){task.start, split, task.depth + 1, 0, 0};
    }
    for (size_t i = 0; i < n; i++)
        bvh->prims[i] = prims[i].ref;
    bvh->prim_count = n;
    /* Give back the room of the nodes that were not needed. */
    {
        BvhNode *fit = realloc(bvh->nodes, bvh->node_count * sizeof *fit);
        if (fit)
            bvh->nodes = fit;
    }
    free(prims);
    free(stack);
    return 0;
}

size_t bvh_build_memory(size_t n)
{
    size_t each = sizeof(BuildPrim) + 2 * sizeof(BvhNode) + sizeof(uint32_t);

    return n > (SIZE_MAX - 4096) / each ? SIZE_MAX : n * each + 4096;
}

size_t bvh_memory(const Bvh *bvh)
{
    return bvh->node_count * sizeof *bvh->nodes + bvh->prim_count * sizeof *bvh->prims;
}

void bvh_free(Bvh *bvh)
{
    free(bvh->nodes);
    free(bvh->prims);
    memset(bvh, 0, sizeof *bvh);
}


/* The ray, prepared for box tests: reciprocal directions (+-inf for a zero
 * component, by the sign of that zero), and for each axis which end of a
 * node's box (an offset into BvhNode.box: lo or hi) the ray meets first. */
typedef struct {
    real o[3], inv[3];
    int near[3], far[3]; /* offsets into a node's {lo[3], hi[3]}: a, or 3 + a */
} BvhRay;

static BvhRay bvh_ray(const Ray *r)
{
    BvhRay b;
    real d[3] = {r->dir.x, r->dir.y, r->dir.z};

    b.o[0] = r->origin.x;
    b.o[1] = r->origin.y;
    b.o[2] = r->origin.z;
    for (int a = 0; a < 3; a++) {
        b.inv[a] = 1 / d[a];
        b.near[a] = b.inv[a] < 0 ? 3 + a : a;
        b.far[a] = b.inv[a] < 0 ? a : 3 + a;
    }
    return b;
}

/* Rounding in the slab test: every computed slab distance is within a
 * relative 3 ulps (gamma_3) of the true one, so widening the far ends by
 * 1 + 8 ulps > 1 + 2 gamma_3 never loses a crossing (pbrt-v3, 3.9.2). */
#define BVH_WIDEN (1 + 4 * REAL_EPSILON)

/* Says whether the ray meets node's box at some t in [0, tmax]; if so,
 * stores in *enter where it enters (to within rounding, never later than
 * the true entry by more than BVH_WIDEN allows). The reciprocal directions
 * are +-inf for a zero component: the products then are +-inf (outside the
 * slab or inside it) or NaN (on its plane), which the comparisons ignore. */
static inline int bvh_box_enter(const BvhNode *node, const BvhRay *r, real tmax,
                                real *enter)
{
    const real *b = node->box;
    real t0 = 0, t1 = tmax * BVH_WIDEN;
    real nx = (b[r->near[0]] - r->o[0]) * r->inv[0], fx = (b[r->far[0]] - r->o[0]) * r->inv[0];
    real ny = (b[r->near[1]] - r->o[1]) * r->inv[1], fy = (b[r->far[1]] - r->o[1]) * r->inv[1];
    real nz = (b[r->near[2]] - r->o[2]) * r->inv[2], fz = (b[r->far[2]] - r->o[2]) * r->inv[2];

    fx *= BVH_WIDEN;
    fy *= BVH_WIDEN;
    fz *= BVH_WIDEN;
    t0 = nx > t0 ? nx : t0;
    t0 = ny > t0 ? ny : t0;
    t0 = nz > t0 ? nz : t0;
    t1 = fx < t1 ? fx : t1;
    t1 = fy < t1 ? fy : t1;
    t1 = fz < t1 ? fz : t1;
    *enter = t0;
    return t0 <= t1;
}

/* bvh_box_enter() when the entry point is not needed. */
static inline int bvh_box_hit(const BvhNode *node, const BvhRay *r, real tmax)
{
    real enter;

    return bvh_box_enter(node, r, tmax, &enter);
}

/* Tests primitive ref for a crossing at tmin < t < tmax; returns 1 with *t. */
static int bvh_prim_hit(const Scene *scene, uint32_t ref, const Ray *ray, real tmin, real tmax,
                        real *t)
{
    if (ref & BVH_TRIANGLE)
        return triangle_intersect(&scene->triangles[ref & ~BVH_TRIANGLE], ray, tmin, tmax, t);
    return sphere_intersect(&scene->spheres[ref], ray, tmin, tmax, t);
}

static unsigned bvh_prim_order(const Scene *scene, uint32_t ref)
{
    return ref & BVH_TRIANGLE ? scene->triangles[ref & ~BVH_TRIANGLE].order
                              : scene->spheres[ref].order;
}

int bvh_nearest(const Bvh *bvh, const Scene *scene, const Ray *ray, real tmax, BvhHit *hit)
{
    BvhRay r = bvh_ray(ray);
    struct {
        uint32_t id;  /* a node still to visit */
        real enter; /* where the ray enters its box */
    } stack[BVH_STACK];
    int top = 0, found = 0;
    uint32_t id = 0;
    real enter, bound = tmax; /* primitives are tested below bound */

    if (!bvh_box_enter(&bvh->nodes[0], &r, tmax, &enter))
        return 0;
    for (;;) {
        const BvhNode *node = &bvh->nodes[id];

        if (node->count > 0) {
            for (uint32_t k = node->index; k < node->index + node->count; k++) {
                uint32_t ref = bvh->prims[k];
                real t;
                unsigned order;
                if (!bvh_prim_hit(scene, ref, ray, 0, bound, &t))
                    continue;
                order = bvh_prim_order(scene, ref);
                if (!found || t < hit->t || order < hit->order) {
                    hit->t = t;
                    hit->prim = ref;
                    hit->order = order;
                    found = 1;
                    /* An exact tie with an earlier-listed object must
                     * still be seen: the bound is the next real up. */
                    bound = real_next(t, 1);
                }
            }
        } else {
            /* Both children's boxes; the nearer first, the other later
             * unless a hit before its entry is found meanwhile. A box
             * entered exactly at the best t may still hold an
             * earlier-listed object at that t: the limit keeps it. */
            uint32_t a = id + 1, b = node->index;
            real ta, tb, limit = found ? hit->t : tmax;
            int ha = bvh_box_enter(&bvh->nodes[a], &r, limit, &ta);
            int hb = bvh_box_enter(&bvh->nodes[b], &r, limit, &tb);

            if (ha && hb) {
                if (tb < ta) {
                    uint32_t tmp = a;
                    real tt = ta;
                    a = b;
                    b = tmp;
                    ta = tb;
                    tb = tt;
                }
                stack[top].id = b;
                stack[top].enter = tb;
                top++;
                id = a;
                continue;
            }
            if (ha || hb) {
                id = ha ? a : b;
                continue;
            }
        }
        /* The next stacked node the ray can still reach before its hit. */
        for (;;) {
            if (top == 0)
                return found;
            top--;
            if (!found || stack[top].enter <= hit->t * BVH_WIDEN)
                break;
        }
        id = stack[top].id;
    }
}

/* A walk over the leaves whose boxes a ray meets, in no particular order. */
typedef struct {
    uint32_t stack[BVH_STACK]; /* nodes still to visit */
    int top;                   /* how many */
} BvhWalk;

/* Returns the next leaf whose box the ray r meets at some t in [0, tmax],
 * or NULL when there are no more; start w with bvh_walk_start(). */
static const BvhNode *bvh_next_leaf(const Bvh *bvh, const BvhRay *r, real tmax, BvhWalk *w)
{
    while (w->top > 0) {
        uint32_t id = w->stack[--w->top];
        const BvhNode *node = &bvh->nodes[id];

        if (!bvh_box_hit(node, r, tmax))
            continue;
        if (node->count > 0)
            return node;
        w->stack[w->top++] = node->index;
        w->stack[w->top++] = id + 1;
    }
    return NULL;
}

static void bvh_walk_start(BvhWalk *w)
{
    w->stack[0] = 0;
    w->top = 1;
}

int bvh_occluded(const Bvh *bvh, const Scene *scene, const Ray *ray, real tmax)
{
    BvhRay r = bvh_ray(ray);
    BvhWalk w;
    const BvhNode *leaf;
    real t;

    bvh_walk_start(&w);
    while ((leaf = bvh_next_leaf(bvh, &r, tmax, &w)) != NULL)
        for (uint32_t k = leaf->index; k < leaf->index + leaf->count; k++)
            if (bvh_prim_hit(scene, bvh->prims[k], ray, 0, tmax, &t))
                return 1;
    return 0;
}

/* Orders crossings: spheres before triangles, each kind by index. */
static int bvh_crossing_before(const BvhCrossing *a, const BvhCrossing *b)
{
    return a->prim < b->prim; /* BVH_TRIANGLE is the top bit */
}

int bvh_crossings(const Bvh *bvh, const Scene *scene, const Ray *ray, real tmax,
                  BvhCrossing *out, int max)
{
    BvhRay r = bvh_ray(ray);
    BvhWalk w;
    const BvhNode *leaf;
    int n = 0;
    real t;

    bvh_walk_start(&w);
    while ((leaf = bvh_next_leaf(bvh, &r, tmax, &w)) != NULL) {
        for (uint32_t k = leaf->index; k < leaf->index + leaf->count; k++) {
            uint32_t ref = bvh->prims[k];
            const Material *m;
            int c;
            if (ref & BVH_TRIANGLE) {
                const Triangle *tri = &scene->triangles[ref & ~BVH_TRIANGLE];
                c = triangle_intersect(tri, ray, 0, tmax, &t);
                m = &tri->material;
            } else {
                c = sphere_crossings(&scene->spheres[ref], ray, 0, tmax);
                m = &scene->spheres[ref].material;
            }
            if (c == 0)
                continue;
            if (!(m->transparency > 0))
                return -2;
            if (n == max)
                return -1;
            out[n].prim = ref;
            out[n].crossings = c;
            n++;
        }
    }
    /* Insertion sort: the lists are short. */
    for (int i = 1; i < n; i++) {
        BvhCrossing c = out[i];
        int j = i;
        while (j > 0 && bvh_crossing_before(&c, &out[j - 1])) {
            out[j] = out[j - 1];
            j--;
        }
        out[j] = c;
    }
    return n;
}
