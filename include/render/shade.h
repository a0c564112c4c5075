/*
 * shade.h: what the point a ray hit looks like, and the light it receives
 * directly: the course's rule and Blinn-Phong's (docs/scene-format.md).
 *
 * The course's local term at a point P of colour Ci (its material's, or its
 * texture's at P) is
 *     Ca * Ci / 255 + sum over lights of E * max(0, N . L) * Ci * Cs / 255
 * channel by channel, with N the shading normal facing the viewer, L the
 * unit vector from P to the light, Cs the light's colour, Ca the ambient
 * colour (0 without an ambient: record) and E the share of the light that
 * reaches P: the product of T over every surface crossing strictly between
 * P and the light (1 with none, 0 when an opaque surface is crossed). The
 * keyword format's Blinn-Phong term is
 *     ka Ia Ci / 255 + sum over lights of E i (kd max(0, N . L) Ci Cs / 255
 *                                              + ks max(0, N . H)^alpha Cs)
 * with H the unit vector halfway between L and the direction to the
 * viewer; its distant lights' shadow rays are unbounded. The MPL format's
 * materials are shaded by the same term, their kind setting ka, kd and ks
 * (docs/scene-format.md), and its point lights' i falls off with the
 * distance d as i / d^2, times (1 - (d / R)^4)^2 within a range R and 0
 * beyond it. Each shadow ray is cast unless the tracer's cut-off allows
 * leaving it out (cut.h).
 */
#ifndef RAYTRACE_SHADE_H
#define RAYTRACE_SHADE_H

#include "geometry/ray.h"
#include "math/colour.h"
#include "render/tracer.h"
#include "render/visibility.h"

/* A pixel's footprint at a hit: how the point and its shading normal move
 * when the pixel moves one pixel right ([0]) or down ([1]). */
typedef struct {
    Vec3 dp[2]; /* the point's derivatives, on the tangent plane */
    Vec3 dn[2]; /* the unit shading normal's (outward, as sp.shading) */
} ShadeFootprint;

/* Stores in dn fp's normal derivatives, negated when flip is set (for the
 * normal turned to face the ray). */
static inline void shade_footprint_dn(const ShadeFootprint *fp, int flip, Vec3 dn[2])
{
    for (int k = 0; k < 2; k++)
        dn[k] = flip ? vec3_neg(fp->dn[k]) : fp->dn[k];
}

/* What shading needs to know about the point a ray hit. */
typedef struct {
    SurfacePoint sp;          /* the point, its outward normal and error */
    Vec3 back;                /* the step back toward the ray that met it
                                 its rays take (ray_back_step()) */
    Material material;        /* the object's material */
    Colour colour;            /* Ci: the material's colour or its texture's */
    double ambient;           /* the share of the ambient light that reaches
                                 it: 1, or less under ambient occlusion */
    const ShadeFootprint *footprint; /* the pixel's footprint there, or NULL
                                 when the ray carries no differentials */
} Shade;

/* Returns the step back that rays leaving sp (the hit of ray at t in
 * scene) take at corners (ray_back_step()): none in a scene of spheres
 * alone, whose secondary rays the course pins (re-projected, offset along
 * N; course-format.md), so that its bytes stay the course reference's. */
static inline Vec3 shade_back_step(const Scene *scene, const Ray *ray, real t,
                                   const SurfacePoint *sp)
{
    if (scene->kinds == 1u << SHAPE_SPHERE)
        return vec3(0, 0, 0);
    return ray_back_step(ray, t, sp->point, sp->error);
}

/* Returns the shading record of hit, crossed by ray, in scene; with
 * differentials diff (NULL: none), fills *fp with the footprint they give
 * and points the record at it, and reads a texture or stripes whose
 * filter averages over it (texture.h). */
Shade shade_at_footprint(const Scene *scene, const Ray *ray, const Hit *hit, const RayDiff *diff,
                         ShadeFootprint *fp);

/* Returns the colour Ci of material m of scene at texture coordinates uv
 * (its texture's, v clamped when clamp_v is set) or stripe coordinate
 * stripe (the MPL ray tracer's stripes: its colour where the fraction is below one
 * half, black above), else its colour. */
Colour shade_texel(const Scene *scene, const Material *m, const double uv[2], double stripe,
                   int clamp_v);

/* Returns the course's local term at sh, with n its surface normal and ns
 * its shading normal, both facing the viewer; its shadow rays' light
 * reaches the pixel with weight (for the cut-off; the course's weights are
 * the same in every channel). */
Colour shade_local(const Tracer *t, const Shade *sh, Vec3 n, Vec3 ns, double weight);

/* Returns the Blinn-Phong local term of material pm at sh, seen from
 * direction view (unit, towards the viewer); n and ns as for
 * shade_local(), its light reaching the pixel with weight, channel by
 * channel. */
Colour shade_phong(const Tracer *t, const Shade *sh, const NamedMaterial *pm, Vec3 n, Vec3 ns,
                   Vec3 view, Colour weight);

/* Casts the shadow ray `shadow` up to tmax towards light (one of the
 * scene's, whose shadow cache it uses: tracer.h; NULL: none) and returns
 * the share E of the light that passes: 1 or 0 in opaque scenes, the
 * product of the transparencies crossed in others; 1, casting nothing,
 * when the tracer has shadows off. */
double shade_light_share(const Tracer *t, const Ray *shadow, real tmax, const Light *light);

/* Returns the share E of light's light that reaches the point of sh (n its
 * surface normal facing the viewer), casting its shadow ray: towards a
 * point light, the segment to it; towards a distant one, unbounded. */
double shade_light_reach(const Tracer *t, const Shade *sh, Vec3 n, const Light *light);

#endif
