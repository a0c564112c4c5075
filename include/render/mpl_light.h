/*
 * mpl_light.h: how the MPL ray tracer made the picture of an MPL scene
 * (SCENE_MODEL_MPL), and where it laid textures and stripes
 * (SCENE_MAPPING_MPL). Its users' scenes give the pictures its program
 * gave them; docs/mpl.md compares the two, scene by scene.
 *
 * The colour seen along a ray, on the scale 0..1 of the program: a ray
 * that meets nothing sees the sky (trace_background()), and so does a
 * mirror or refracted ray deeper than the depth limit. At the nearest hit,
 * with a the surface's colour there (its texel, its stripe or its colour,
 * 0..1), N the unit normal facing the ray, V the ray's unit direction and
 * g the material's glossiness, light i brings
 *     L_i = D_i                 when g = 0,
 *     L_i = D_i * (D_i + S_i)   when g > 0 (channel by channel),
 *     D_i = a C_i I_i w_i max(0, N . l_i),
 *     S_i = C_i I_i w_i max(0, 2 (N . V)^2 - 1)^g,
 * with C_i the light's colour (0..1), I_i its intensity, l_i the unit vector
 * towards it, w_i 1 for a directional light and 1 / d^2 for a point light
 * at distance d (0 at its range and beyond: full strength within it,
 * none past it). Each L_i is weighed by E_i, the share of the light the
 * shadow ray towards it lets through (shade_light_share(); 1 without
 * shadows). The surface then shows, by its material's kind:
 *     MATTE       (sum E_i L_i + G) a / pi
 *     METALLIC    a Cr + sum E_i L_i
 *     PLASTIC     F a Cr + sum E_i L_i
 *     DIELECTRIC  Ct
 * Cr being the colour along the mirror ray, Ct along the refracted ray
 * (the mirror ray on total internal reflection), F Fresnel's share for
 * the material's index. With ambient occlusion on, the result is
 * multiplied by A, at every hit (mirrored ones too):
 *     A = the mean over its rays of min(d / D, 1),
 * d the distance to what a ray meets (1 when it meets nothing within D).
 * With global illumination on, a MATTE surface gathers
 *     G = the mean over its rays of the colour a of what each meets
 * (0 for the sky). The rays of both are the program's distribution, a
 * point of the cube [-1, 1]^3's surface made a unit vector and turned into
 * N's half-space, drawn as a multi-jittered pattern over the pixel's
 * samples (sampler.h) instead of its random numbers: the same picture,
 * converged faster, the same bytes on every run. The pixel's bytes are its
 * mean colour clamped to [0, 1] and encoded with gamma 2.2
 * (image_encode_gamma()).
 *
 * Where the program has a plain bug, these rules do what its report says:
 * each light has its own shadow ray (its code lit a point by every light
 * once any one was unblocked), a point light is where the file puts it
 * (its reader normalised the position) and reaches as far as the file's
 * range (its reader used 5), and nothing beyond a point light shadows it.
 * PLASTIC and DIELECTRIC, which its reader could not build, follow its
 * report: Fresnel on the mirror ray, refraction without Fresnel.
 */
#ifndef RAYTRACE_MPL_LIGHT_H
#define RAYTRACE_MPL_LIGHT_H

#include "geometry/ray.h"
#include "math/colour.h"
#include "render/tracer.h"
#include "render/visibility.h"

/* The program's defaults (its Properties and tracer): ambient occlusion
 * and global illumination rays a point, the occlusion distance in the
 * scene's units, the deepest mirror ray, the encoding's gamma. */
enum { MPL_LIGHT_AO_RAYS = 10, MPL_LIGHT_GI_RAYS = 10, MPL_LIGHT_MAX_DEPTH = 99 };
#define MPL_LIGHT_AO_DISTANCE 2.0
#define MPL_LIGHT_GAMMA 2.2

/* Returns the colour seen along the primary ray `ray` by the rules above,
 * on the renderer's scale (1 of the program = 255), tracing deeper rays
 * down to t->max_depth. */
Colour mpl_light_trace(const Tracer *t, const Ray *ray);

/* mpl_light_trace() for a primary ray with differentials diff (NULL: none),
 * followed through mirrors and glass for the textures and stripes whose
 * filter averages over a footprint (trace.h). */
Colour mpl_light_trace_diff(const Tracer *t, const Ray *ray, const RayDiff *diff);

/* Returns what mpl_light_trace_diff() returns for a primary ray that meets
 * nothing (the model table's miss). */
Colour mpl_light_miss(const Tracer *t, const Ray *ray);

/* Says whether mpl_light_miss() is the same colour for every ray. */
int mpl_light_miss_uniform(const Tracer *t);

#endif
