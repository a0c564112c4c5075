/*
 * embree_bvh.c: bvh.h's queries answered by Intel's Embree 3 instead of our
 * hierarchy, for the benchmark's comparison only (never part of raytrace).
 *
 * Linked in place of build/bvh.o, it leaves everything else the renderer
 * does as it is (reading, tiles, threads, shading, the cut-off, writing),
 * so the two binaries differ only in the structure and its traversal. The
 * spheres are Embree user geometry: Embree builds its tree (build quality
 * high) over their boxes and traverses it in floats; every sphere it
 * reaches is tested with raytrace's own double-precision sphere_hit() and
 * tie rule, so the render is raytrace's, byte for byte, whenever Embree's
 * float box tests reach every sphere the exact test hits (the boxes are
 * padded for that; make bench compares the bytes). Spheres only: the
 * benchmark's fields. One scene a process.
 */
#include "accel/bvh.h"

#include <embree3/rtcore.h>
#include <math.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>

#include "geometry/sphere.h"

static RTCDevice eb_device;
static RTCScene eb_scene;

/* A query: Embree's context first, then what the callbacks need. */
typedef struct {
    struct RTCIntersectContext context;
    const Sphere *spheres;
    const Ray *ray;   /* the double-precision ray */
    real bound;       /* spheres are tested below it */
    real t;           /* the best crossing so far */
    unsigned prim;
    int found;
} EbQuery;

/* Returns a float at or above x. */
static float eb_above(double x)
{
    float f = (float)x;
    return (double)f >= x ? f : nextafterf(f, INFINITY);
}

static void eb_bounds(const struct RTCBoundsFunctionArguments *args)
{
    const Sphere *s = (const Sphere *)args->geometryUserPtr + args->primID;
    double c[3] = {s->centre.x, s->centre.y, s->centre.z};
    double lo[3], hi[3];

    /* Padded for the float rays' rounding: 1e-6 of the coordinates, and
     * 1e-4 for rays starting far from the sphere. */
    for (int a = 0; a < 3; a++) {
        double pad = (fabs(c[a]) + s->radius) * 1e-6 + 1e-4;
        lo[a] = c[a] - s->radius - pad;
        hi[a] = c[a] + s->radius + pad;
    }
    args->bounds_o->lower_x = (float)lo[0];
    args->bounds_o->lower_y = (float)lo[1];
    args->bounds_o->lower_z = (float)lo[2];
    args->bounds_o->upper_x = (float)hi[0];
    args->bounds_o->upper_y = (float)hi[1];
    args->bounds_o->upper_z = (float)hi[2];
}

static void eb_intersect(const struct RTCIntersectFunctionNArguments *args)
{
    EbQuery *q = (EbQuery *)args->context;
    struct RTCRayHit *rh = (struct RTCRayHit *)args->rayhit;
    const Sphere *s = &q->spheres[args->primID];
    real t;

    if (!args->valid[0] || !sphere_hit(s->centre, s->radius, q->ray, 0, q->bound, &t))
        return;
    /* As bvh_nearest(): t <= the best; on a tie the earlier-listed wins. */
    if (q->found && !(t < q->t) && s->order >= q->spheres[q->prim].order)
        return;
    q->t = t;
    q->prim = args->primID;
    q->found = 1;
    q->bound = real_next(t, 1);
    rh->ray.tfar = eb_above(q->bound);
    rh->hit.geomID = args->geomID;
    rh->hit.primID = args->primID;
}

static void eb_occluded(const struct RTCOccludedFunctionNArguments *args)
{
    EbQuery *q = (EbQuery *)args->context;
    const Sphere *s = &q->spheres[args->primID];
    real t;

    if (args->valid[0] && sphere_hit(s->centre, s->radius, q->ray, 0, q->bound, &t))
        ((struct RTCRay *)args->ray)->tfar = -INFINITY;
}

/* Returns how many shapes, of every kind, shapes holds. */
static size_t bvh_shapes_count(const BvhShapes *shapes)
{
    size_t n = 0;

    for (int k = 0; k < SHAPE_KINDS; k++)
        n += shapes->count[k];
    return n;
}

int bvh_build(Bvh *bvh, const BvhShapes *shapes, real reach, int threads)
{
    char config[64];
    RTCGeometry g;

    (void)reach; /* the boxes' padding below allows for any */
    /* Embree keeps its own order: shapes->movable's spheres stay where
     * they are (bvh.h allows it: the answers are the same). */
    memset(bvh, 0, sizeof *bvh);
    bvh->shapes = *shapes;
    if (shapes->count[SHAPE_SPHERE] != bvh_shapes_count(shapes)) {
        fprintf(stderr, "embree_bvh: spheres only\n");
        exit(2);
    }
    snprintf(config, sizeof config, "threads=%d", threads);
    eb_device = rtcNewDevice(config);
    if (!eb_device) {
        fprintf(stderr, "embree_bvh: no Embree device\n");
        exit(2);
    }
    eb_scene = rtcNewScene(eb_device);
    rtcSetSceneBuildQuality(eb_scene, RTC_BUILD_QUALITY_HIGH);
    g = rtcNewGeometry(eb_device, RTC_GEOMETRY_TYPE_USER);
    rtcSetGeometryUserPrimitiveCount(g, (unsigned)shapes->count[SHAPE_SPHERE]);
    rtcSetGeometryUserData(g, (void *)shapes->items[SHAPE_SPHERE]);
    rtcSetGeometryBoundsFunction(g, eb_bounds, NULL);
    rtcSetGeometryIntersectFunction(g, eb_intersect);
    rtcSetGeometryOccludedFunction(g, eb_occluded);
    rtcCommitGeometry(g);
    rtcAttachGeometry(eb_scene, g);
    rtcReleaseGeometry(g);
    rtcCommitScene(eb_scene);
    bvh->prim_count = shapes->count[SHAPE_SPHERE];
    return 0;
}

void bvh_free(Bvh *bvh)
{
    rtcReleaseScene(eb_scene);
    rtcReleaseDevice(eb_device);
    memset(bvh, 0, sizeof *bvh);
}

/* Embree allocates on its own: neither figure below counts it (make bench
 * reports the process's peak instead); n * 64 keeps the memory-limit check
 * of scene.c in use with a rough size of its nodes. */
size_t bvh_build_memory(size_t n)
{
    return n * 64;
}

/* The light buffers' budget (scene_accel.c) is a share of this: the
 * same rough size. */
size_t bvh_build_scratch(size_t n)
{
    return n * 64;
}

size_t bvh_memory(const Bvh *bvh)
{
    (void)bvh;
    return 0;
}

/* Starts query q of ray below tmax and returns Embree's float ray. */
static struct RTCRayHit eb_start(EbQuery *q, const Bvh *bvh, const Ray *ray, real tmax)
{
    struct RTCRayHit rh;

    rtcInitIntersectContext(&q->context);
    q->spheres = bvh->shapes.items[SHAPE_SPHERE];
    q->ray = ray;
    q->bound = tmax;
    q->found = 0;
    rh.ray.org_x = (float)ray->origin.x;
    rh.ray.org_y = (float)ray->origin.y;
    rh.ray.org_z = (float)ray->origin.z;
    rh.ray.dir_x = (float)ray->dir.x;
    rh.ray.dir_y = (float)ray->dir.y;
    rh.ray.dir_z = (float)ray->dir.z;
    rh.ray.tnear = 0;
    rh.ray.tfar = eb_above(tmax);
    rh.ray.time = 0;
    rh.ray.mask = 0xffffffffu;
    rh.ray.id = 0;
    rh.ray.flags = 0;
    rh.hit.geomID = RTC_INVALID_GEOMETRY_ID;
    rh.hit.instID[0] = RTC_INVALID_GEOMETRY_ID;
    return rh;
}

int bvh_nearest(const Bvh *bvh, const Ray *ray, real tmax, BvhHit *hit)
{
    EbQuery q;
    struct RTCRayHit rh = eb_start(&q, bvh, ray, tmax);

    rtcIntersect1(eb_scene, &q.context, &rh);
    if (q.found) {
        hit->t = q.t;
        hit->prim = q.prim;
        hit->order = ((const Sphere *)bvh->shapes.items[SHAPE_SPHERE])[q.prim].order;
    }
    return q.found;
}

/* Says whether some sphere crosses the ray below tmax. */
static int eb_any_hit(const Bvh *bvh, const Ray *ray, real tmax)
{
    EbQuery q;
    struct RTCRayHit rh = eb_start(&q, bvh, ray, tmax);

    rtcOccluded1(eb_scene, &q.context, &rh.ray);
    return rh.ray.tfar < 0;
}

/* Embree's any-hit query names no occluder: no shadow cache. */
int bvh_occluder(const Bvh *bvh, const Ray *ray, real tmax, uint32_t *slot)
{
    *slot = BVH_NO_SLOT;
    return eb_any_hit(bvh, ray, tmax);
}

int bvh_slot_occludes(const Bvh *bvh, uint32_t slot, const Ray *ray, real tmax)
{
    (void)bvh, (void)slot, (void)ray, (void)tmax;
    return 0;
}

int bvh_crossings(const Bvh *bvh, const Ray *ray, real tmax, BvhVisit visit, void *ctx)
{
    (void)bvh, (void)ray, (void)tmax, (void)visit, (void)ctx;
    fprintf(stderr, "embree_bvh: no transparent objects\n");
    exit(2);
}

int bvh_frustum_clear(const Bvh *bvh, const Frustum *f)
{
    /* Embree's tree is not walked here: no tile is proven clear, and
     * every primary ray is traced (the fields raced have no clear tile
     * either way, so the two binaries still differ only in traversal). */
    (void)bvh, (void)f;
    return 0;
}
