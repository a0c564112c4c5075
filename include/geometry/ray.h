/*
 * ray.h: rays, and the one rule for where a secondary ray may start.
 *
 * A ray is the half-line origin + t * dir, t > 0. dir need not be unit
 * length; every intersection routine accepts any non-zero direction.
 */
#ifndef RAYTRACE_RAY_H
#define RAYTRACE_RAY_H

#include "math/vec3.h"

typedef struct {
    Vec3 origin; /* start point, scene units */
    Vec3 dir;    /* direction, any non-zero length */
} Ray;

/* A point on a surface, with what a secondary ray needs to leave it. */
typedef struct {
    Vec3 point;  /* on the surface, re-projected from the ray's hit */
    Vec3 normal;  /* the surface's outward unit normal at point */
    Vec3 shading; /* the unit normal shading uses: `normal`, except on a
                     smooth triangle (interpolated vertex normals) */
    Vec3 error;  /* per-component bound on |point - true surface point| */
} SurfacePoint;

/* Returns the point origin + t * dir. */
static inline Vec3 ray_at(const Ray *ray, real t)
{
    return vec3_add(ray->origin, vec3_scale(ray->dir, t));
}

/* Returns the unit normal n turned to face the ray direction dir: n itself
 * when the ray meets the surface from outside, -n when from inside
 * (n . dir > 0). Every shading rule uses the facing normal. */
static inline Vec3 ray_facing_normal(Vec3 n, Vec3 dir)
{
    return vec3_dot(n, dir) > 0 ? vec3_neg(n) : n;
}

/* Returns the mirror image of direction d about the unit normal n:
 * d - 2 (d . n) n. */
static inline Vec3 ray_reflect(Vec3 d, Vec3 n)
{
    return vec3_sub(d, vec3_scale(n, 2 * vec3_dot(d, n)));
}

/*
 * Bends direction d (any length) through a surface of unit normal n facing
 * it (d . n <= 0) by Snell and Descartes' law n1 sin i1 = n2 sin i2, eta =
 * n1 / n2 being the ratio of the indices on d's side and the far side;
 * stores the unit refracted direction in *out and returns 1, or returns 0
 * on total internal reflection (sin i2 would exceed 1).
 */
int ray_refract(Vec3 d, Vec3 n, real eta, Vec3 *out);

/*
 * Returns the share of unpolarised light a smooth dielectric surface
 * mirrors, by Fresnel's equations: d is the incoming direction (any
 * length), n the unit normal facing it (d . n <= 0), eta = n1 / n2 the
 * ratio of the indices on d's side and the far side. The average of the
 * s and p reflectances, ((eta c_i - c_t) / (eta c_i + c_t))^2 and
 * ((eta c_t - c_i) / (eta c_t + c_i))^2, with c_i and c_t the cosines of
 * incidence and refraction; 1 on total internal reflection.
 */
double ray_fresnel(Vec3 d, Vec3 n, real eta);

/*
 * Ray differentials (Igehy, "Tracing ray differentials", SIGGRAPH 1999):
 * how a ray moves when its pixel moves one pixel right (x) or down (y),
 * first derivatives of its origin and direction. They travel with a ray
 * through mirrors and glass, and at a hit say the footprint of the pixel
 * on the surface: what a texture lookup must average over. The functions
 * below are the transfer, reflection and refraction rules, each in this
 * one place.
 */
typedef struct {
    Vec3 dodx, dody; /* the origin's derivatives */
    Vec3 dddx, dddy; /* the direction's (of the direction as the ray has it,
                        any length) */
} RayDiff;

/* Stores in dp[0] and dp[1] the derivatives of the point ray_at(ray, t)
 * carried by diff onto the plane through it of normal n (the tangent
 * plane of the surface it hits): d(O + t D) plus dt D, with dt keeping the
 * point on the plane. Zero when the ray runs along the plane. */
void ray_diff_transfer(const Ray *ray, const RayDiff *diff, real t, Vec3 n, Vec3 dp[2]);

/* Stores in *out diff with its direction's derivatives made those of the
 * unit direction d / |d|: (dD - (u . dD) u) / |d|, u = d / |d|. */
void ray_diff_unit(Vec3 d, const RayDiff *diff, RayDiff *out);

/* Stores in *out the differentials of the mirror ray ray_reflect(d, n)
 * leaving the point whose derivatives are dp, where the unit normal n has
 * derivatives dn, for an incoming direction d with differentials diff:
 * dR = dD - 2 ((dD . n + d . dn) n + (d . n) dn). */
void ray_diff_reflect(Vec3 d, const RayDiff *diff, Vec3 n, const Vec3 dn[2], const Vec3 dp[2],
                      RayDiff *out);

/* Stores in *out the differentials of the refracted ray t (the unit
 * direction ray_refract(d, n, eta) gave) leaving the point whose
 * derivatives are dp, n and dn as for ray_diff_reflect(): with u the unit
 * d, T = eta u + mu n and mu = eta cos_i - cos_t, dT = eta du + dmu n +
 * mu dn, dmu = (eta - eta^2 cos_i / cos_t) dcos_i. */
void ray_diff_refract(Vec3 d, const RayDiff *diff, Vec3 n, const Vec3 dn[2], const Vec3 dp[2],
                      real eta, Vec3 t, RayDiff *out);

/*
 * Returns a start point for a ray leaving the surface point p in direction
 * w, safe from re-hitting the surface it leaves: p is moved along the unit
 * normal n, to the side w points to, by the projection of p's error bound
 * perr (each component of the computed p is within perr of the true surface
 * point) onto n, and each moved component is then rounded one more ulp away
 * from p. This is the method of pbrt-v4 (Pharr, Jakob, Humphreys, 4th ed.,
 * section 6.8.6), applied to world-space points.
 *
 * A ray leaving on the side n faces (w . n >= 0) first takes the step
 * `back` (ray_back_step(), or zero for none).
 */
Vec3 ray_offset_origin(Vec3 p, Vec3 perr, Vec3 back, Vec3 n, Vec3 w);

/*
 * Returns the step that a ray leaving the hit p (error bound perr) of ray
 * at t, on the side ray came from, takes back toward ray's origin before
 * its offset (ray_offset_origin()), so that it also starts on ray's side
 * of any other surface p lies on: at a corner, where p is on two surfaces
 * and rounding may have put it a hair behind the second, a shadow or
 * gathering ray leaving the first would otherwise meet the second at once
 * (or pass behind it). The step is 16 times the larger of the largest
 * offset perr gives and p's error as ray's reach gives it, gamma(16)
 * (|p| + 2 |t dir|) in largest components, so that it clears a surface
 * ray met at a cosine of 1/8 or more; it never goes more than 15/16 of the
 * way back.
 */
Vec3 ray_back_step(const Ray *ray, real t, Vec3 p, Vec3 perr);

#endif
