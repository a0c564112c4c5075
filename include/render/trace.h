/*
 * trace.h: the colour seen along a ray: the course's recursive rule,
 * extended with its bonus features, and the keyword format's Whitted sum.
 *
 * The colour seen along a ray that hits an object at point P is
 *     C = (1 - R - T) * local + R * Cr + T * Ct
 * channel by channel, with local the course's local term at P (shade.h), R
 * and T the object's mirror and transparency weights, Cr the colour seen
 * along the mirror ray d - 2 (d . N) N (N the shading normal facing the
 * ray) and Ct the colour seen along the refracted ray. Refraction follows
 * Snell and Descartes from index 1 into the object's index n when the ray
 * meets the outer side of its surface, from n into 1 when it leaves; on
 * total internal reflection the share T follows the mirror ray too. A ray
 * that hits nothing sees the background. The primary ray has depth 0; a
 * mirror or refracted ray of depth k is traced only when k <= max_depth,
 * otherwise it contributes 0. A material with a Blinn-Phong entry (the
 * keyword format) is shaded instead by Whitted's sum C = local + R Cr + T
 * Ct with the Blinn-Phong local term (shade.h): the physical model
 * (scene.h); mpl_light.h traces the MPL ray tracer's. Functions here only read
 * the scene and write the tracer's cut-off and counters: safe to call from
 * many threads at once, each with its own tracer.
 */
#ifndef RAYTRACE_TRACE_H
#define RAYTRACE_TRACE_H

#include "geometry/ray.h"
#include "math/colour.h"
#include "render/cut.h"
#include "render/tracer.h"

/* Returns the colour seen along ray, a primary ray (depth 0), tracing
 * mirror and refracted rays down to t->max_depth and leaving out the rays
 * t->cut allows (adding what they could have brought to its skipped);
 * counts the shadow, mirror and refracted rays it casts. */
Colour trace_ray(const Tracer *t, const Ray *ray);

/* trace_ray() for a primary ray with differentials diff (geometry/ray.h;
 * NULL: none): they follow it through mirrors and glass (and, estimated,
 * gathering rays), so that textures and stripes whose filter averages
 * read over the pixel's footprint at every hit. */
Colour trace_ray_diff(const Tracer *t, const Ray *ray, const RayDiff *diff);

/* Returns what trace_ray_diff() returns for a primary ray that meets
 * nothing (the model table's miss: render.c asks it for rays proven to). */
Colour trace_miss(const Tracer *t, const Ray *ray);

/* Says whether trace_miss() is the same colour for every ray. */
int trace_miss_uniform(const Tracer *t);

/* What a ray met: how far (INFINITY: nothing) and whether it met the
 * surface from behind (against its outward normal). */
typedef struct {
    double t;
    int behind;
} TraceMet;

/* Returns the colour a gathering ray `ray` brings back to the point it
 * leaves, whose path has taken bounce - 1 diffuse bounces (bounce >= 1):
 * what trace_gather() averages, at depth 0, its own gathering drawn from
 * key; stores in *met what it met. For the irradiance cache's records
 * (irradiance.h). */
Colour trace_gathered(const Tracer *t, const Ray *ray, int bounce, uint64_t key, TraceMet *met);

/* Returns the colour of the sky the ray sees: the scene's background, or
 * the blend of its sky and background by the direction's height. */
Colour trace_background(const Scene *scene, const Ray *ray);

/* Says whether some point of scene receives ambient light, for ambient
 * occlusion to darken: the ambient light is not black, and a course
 * scene sets it, or some named material has ka > 0. */
int trace_has_ambient(const Scene *scene);

/* Traces the ray d that a cut-off left out, leaving out in turn what t's
 * cut-off allows (and keeping it there, which may move its deferred
 * array); returns what it adds to its sample's colour. */
Colour trace_deferred(const Tracer *t, CutRay d);

#endif
