/*
 * pass.h: one part of the picture alone (--pass), for tuning a render as
 * the MPL ray tracer's report tuned its occlusion and gathering: each
 * pass's rule in one place, asked by every lighting model's tracer.
 *
 * direct and indirect split the picture's light at the points the
 * camera's paths meet (through mirrors and glass): indirect keeps only
 * what their gathering brings (all of it, every bounce), direct all the
 * rest (the lights, the ambient term, the background); the two add up to
 * the picture. The other passes are read off the first surface the
 * camera sees, and are pictures of data: ao the share of the ambient
 * light occlusion keeps (grey; 1 without occlusion rays), albedo its
 * colour Ci (texture included), normal its shading normal facing the
 * camera as (n + 1) / 2 per channel (x red, y green, z blue), depth its
 * distance d along the ray as the grey s / (s + d), s the distance at
 * which the picture's centre sees a surface (pass_depth_scale(): what the
 * centre sees is mid-grey, nearer lighter). Where the camera sees
 * nothing, each is black.
 */
#ifndef RAYTRACE_PASS_H
#define RAYTRACE_PASS_H

#include "render/shade.h"
#include "render/tracer.h"

/* Says whether a point of a path that took `bounce` gathering bounces
 * shows its own light (the lights, ambient term and background it sees):
 * the picture's and direct's camera paths and every gathering ray do. */
static inline int pass_shows_own(const Tracer *t, int bounce)
{
    return bounce > 0 || t->pass == TRACE_PASS_FULL || t->pass == TRACE_PASS_DIRECT;
}

/* Says whether such a point shows what its gathering brings: all but
 * direct's camera paths do. */
static inline int pass_shows_gathered(const Tracer *t, int bounce)
{
    return bounce > 0 || t->pass != TRACE_PASS_DIRECT;
}

/* Says whether pass is read off the first surface the camera sees (ao,
 * albedo, normal, depth): a picture of data, whose bytes take no gamma. */
static inline int pass_is_data(TracePass pass)
{
    return pass >= TRACE_PASS_AO;
}

/* Returns the distance s of the depth pass in scene: that from the eye to
 * the surface the ray through the picture's centre meets, or to the
 * screen's centre when it meets none. */
double pass_depth_scale(const Scene *scene);

/* Returns the value, 0..255 in each channel, of t's data pass at sh, the
 * first surface the camera's ray met at t_hit, ns its shading normal
 * facing the ray, ao_share the ambient light's share occlusion keeps
 * there. */
Colour pass_value(const Tracer *t, const Ray *ray, real t_hit, const Shade *sh, Vec3 ns,
                  double ao_share);

#endif
