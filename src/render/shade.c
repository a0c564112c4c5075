/* shade.c: surface records and direct light (see shade.h). */
#include "render/shade.h"

#include <math.h>

#include "math/power.h"
#include "render/cut.h"
#include "scene/mapping.h"
#include "scene/texture.h"

/* The steps of a shadow ray, inline in every caller: the hot paths of
 * the course and keyword scenes run through them. */
#if defined(__GNUC__)
#define SHADE_INLINE static inline __attribute__((always_inline))
#else
#define SHADE_INLINE static inline
#endif

/* shade_texel(), inline: every hit asks (a texture's lookup inline too). */
static inline Colour shade_colour(const Scene *scene, const Material *m, const double uv[2],
                                  double stripe, int clamp_v)
{
    if (m->texture >= 0)
        return texture_lookup(&scene->textures[m->texture], uv[0], uv[1], m->filter, clamp_v);
    if (m->stripes)
        return stripe - floor(stripe) < 0.5 ? m->colour : colour(0, 0, 0);
    return m->colour;
}

/* The step, as a share of a pixel's footprint, at which texture
 * coordinates and normals are read again to take their derivatives: a
 * sixteenth, so that a repeating texture's seam seldom falls within it
 * (a footprint 8 repeats wide would wrap) and single precision still has
 * digits for it. */
#define SHADE_STEP (1.0 / 16)

/* Stores in sp and uv the surface point of hit's shape at p, a point of
 * the tangent plane near hit's point (uv only when want_uv, by the
 * shapes' own mapping; the caller applies the MPL ray tracer's), sp0 being hit's. */
static void shade_surface_near(const Scene *scene, const Hit *hit, const SurfacePoint *sp0,
                               Vec3 p, int want_uv, SurfacePoint *sp, double uv[2])
{
    if (hit->kind == SHAPE_TRIANGLE) {
        /* The barycentric weights of p, seen along the normal. */
        const Triangle *tri = &scene_triangles(scene)[hit->index];
        Ray down = {vec3_add(p, sp0->normal), vec3_neg(sp0->normal)};
        double uv_[2];
        *sp = triangle_surface_at(tri, scene_shading_of(scene, tri), &down, want_uv ? uv : uv_,
                                  NULL);
        sp->point = p;
        return;
    }
    *sp = shape_surface_near(hit->kind, scene_items(scene, hit->kind), hit->index, sp0, p,
                             want_uv ? uv : NULL);
}

/* Returns d brought into [-1/2, 1/2) by whole periods of 1: the change of
 * a repeating coordinate across a seam. */
static double shade_unwrap(double d)
{
    return d - floor(d + 0.5);
}

/* Fills *fp, sh's footprint, from the differentials diff of ray, which
 * met hit; when the colour averages over it (averages: material_averages()),
 * reads sh's colour over it, its only reading: texture
 * coordinates (by the scene's mapping) and stripes at the footprint's
 * ends, their derivatives by difference. uv and stripe are the point's,
 * mpl says whether the MPL ray tracer's mapping lays them. */
static void shade_footprint(const Scene *scene, const Ray *ray, const Hit *hit,
                            const RayDiff *diff, ShadeFootprint *fp, Shade *sh, const double uv[2],
                            double stripe, int averages, int mpl, int clamp_v)
{
    const Material *m = &sh->material;
    double d[4], ds[2];

    ray_diff_transfer(ray, diff, hit->t, sh->sp.normal, fp->dp);
    for (int k = 0; k < 2; k++) {
        SurfacePoint near;
        double nuv[2] = {0, 0}, nstripe = 0;
        Vec3 p = vec3_add(sh->sp.point, vec3_scale(fp->dp[k], SHADE_STEP));

        shade_surface_near(scene, hit, &sh->sp, p, averages && !mpl, &near, nuv);
        fp->dn[k] = vec3_scale(vec3_sub(near.shading, sh->sp.shading), 1 / SHADE_STEP);
        if (!averages)
            continue;
        if (mpl)
            mapping_mpl(scene, hit->kind, hit->index, &near, nuv, &nstripe);
        d[2 * k] = shade_unwrap(nuv[0] - uv[0]) / SHADE_STEP;
        d[2 * k + 1] = (clamp_v ? nuv[1] - uv[1] : shade_unwrap(nuv[1] - uv[1])) / SHADE_STEP;
        ds[k] = shade_unwrap(nstripe - stripe) / SHADE_STEP;
    }
    sh->footprint = fp;
    if (!averages)
        return;
    if (m->texture >= 0)
        sh->colour = texture_lookup_footprint(&scene->textures[m->texture], uv[0], uv[1], d,
                                              m->filter, clamp_v);
    else if (m->stripes)
        sh->colour = colour_scale(m->colour,
                                  texture_stripe_cover(stripe, fmax(fabs(ds[0]), fabs(ds[1]))));
}

Shade shade_at_footprint(const Scene *scene, const Ray *ray, const Hit *hit, const RayDiff *diff,
                         ShadeFootprint *fp)
{
    Shade sh;
    double uv[2] = {0, 0}, stripe = 0;
    int clamp_v = 0, want_uv, mpl, mapped, averages, coloured = 0;
    Colour rgb = {0, 0, 0};

    sh.material = scene_material(scene, hit->kind, hit->index);
    sh.ambient = 1;
    sh.footprint = NULL;
    /* Stripes are the MPL ray tracer's, laid as its program laid them. */
    mapped = sh.material.texture >= 0 || sh.material.stripes;
    mpl = mapped && (sh.material.stripes || scene->mapping == SCENE_MAPPING_MPL) &&
          mapping_mpl_covers(hit->kind);
    want_uv = mapped && !mpl;
    if (hit->kind == SHAPE_TRIANGLE) {
        const Triangle *tri = &scene_triangles(scene)[hit->index];
        const TriangleShading *ts = scene_shading_of(scene, tri);
        sh.sp = triangle_surface_at(tri, ts, ray, uv, &rgb);
        /* A coloured mesh's vertices give the colour a texture does not. */
        coloured = ts && ts->coloured && sh.material.texture < 0;
    } else {
        sh.sp = shape_surface(hit->kind, scene_items(scene, hit->kind), hit->index, ray, hit->t,
                              want_uv ? uv : NULL);
        clamp_v = SHAPE_CLAMPS_V >> hit->kind & 1;
    }
    sh.back = shade_back_step(scene, ray, hit->t, &sh.sp);
    if (mpl && mapping_mpl(scene, hit->kind, hit->index, &sh.sp, uv, &stripe))
        clamp_v = 1;
    /* A colour averaged over the footprint is read there alone. */
    averages = diff && material_averages(&sh.material);
    if (!averages)
        sh.colour = coloured ? rgb : shade_colour(scene, &sh.material, uv, stripe, clamp_v);
    if (diff)
        shade_footprint(scene, ray, hit, diff, fp, &sh, uv, stripe, averages, mpl, clamp_v);
    return sh;
}

Colour shade_texel(const Scene *scene, const Material *m, const double uv[2], double stripe,
                   int clamp_v)
{
    return shade_colour(scene, m, uv, stripe, clamp_v);
}

/* Returns the shadow ray from the shaded point sh (whose surface normal n
 * faces the viewer) to the light in direction to_light (towards a point
 * light: the vector to it; a distant light: its unit to_light), and in
 * *tmax where it ends. */
SHADE_INLINE Ray shade_shadow_ray(const Shade *sh, Vec3 n, const Light *light, Vec3 to_light,
                                   real *tmax)
{
    Ray shadow;

    shadow.origin = ray_offset_origin(sh->sp.point, sh->sp.error, sh->back, n, to_light);
    /* To a point light, the segment ends at the light (t = 1); towards a
     * distant one, the ray is unbounded. */
    shadow.dir = light->distant ? to_light : vec3_sub(light->position, shadow.origin);
    *tmax = light->distant ? INFINITY : 1;
    return shadow;
}

double shade_light_share(const Tracer *t, const Ray *shadow, real tmax, const Light *light)
{
    size_t k = light ? (size_t)(light - t->scene->lights) : 0;

    if (t->no_shadows)
        return 1;
    t->counts->shadow++;
    if (t->scene->has_transparency)
        return visibility_transmittance(t->scene, shadow, tmax);
    /* Towards a light of the scene: its light buffer, if any, and the
     * thread's shadow cache for the first TRACE_OCCLUDERS lights. */
    if (light)
        return visibility_light_occluded(t->scene, k, shadow, tmax,
                                         k < TRACE_OCCLUDERS && t->occluders ? &t->occluders[k]
                                                                             : NULL)
                   ? 0
                   : 1;
    return visibility_occluded(t->scene, shadow, tmax) ? 0 : 1;
}

/* Says whether cut allows leaving out the shadow ray from sh towards light
 * (see shade_shadow_ray()), the light adding lit (a colour, E = 1) to a ray
 * reached with weight (channel by channel), most being the largest channel
 * of weight times lit: E is then taken as 0, and most is what the pixel may
 * lack (E is in [0, 1]). */
static inline int shade_cut_shadow(Cut *cut, double most, Colour weight, Colour lit,
                                   const Shade *sh, Vec3 n, const Light *light, Vec3 to_light)
{
    CutRay d;

    if (!(most < cut->cutoff))
        return 0;
    d.ray = shade_shadow_ray(sh, n, light, to_light, &d.tmax);
    d.kind = RAY_SHADOW;
    d.depth = 0;
    d.has_diff = 0;
    d.weight = weight;
    d.lit = lit;
    return cut_leave_out(cut, most, &d);
}

/* Returns the share E of the light that reaches the shaded point sh from
 * light (see shade_shadow_ray()), casting one shadow ray. */
SHADE_INLINE double shade_visibility(const Tracer *t, const Shade *sh, Vec3 n,
                                      const Light *light, Vec3 to_light)
{
    real tmax;
    Ray shadow = shade_shadow_ray(sh, n, light, to_light, &tmax);

    return shade_light_share(t, &shadow, tmax, light);
}

double shade_light_reach(const Tracer *t, const Shade *sh, Vec3 n, const Light *light)
{
    Vec3 to_light = light->distant ? light->to_light : vec3_sub(light->position, sh->sp.point);

    return shade_visibility(t, sh, n, light, to_light);
}

/* Returns the light's direct contribution, E cos_a (Ci * Cs) / 255, at the
 * shaded point sh: ns is its shading normal and n its surface normal, both
 * facing the viewer; 0 when cut allows leaving out its shadow ray for a
 * term that reaches the pixel with weight. */
static inline Colour shade_direct(const Tracer *t, const Light *light, const Shade *sh, Vec3 n,
                                  Vec3 ns, double weight)
{
    Vec3 to_light = vec3_sub(light->position, sh->sp.point);
    double cos_a = vec3_dot(ns, vec3_normalize(to_light)), e;
    Colour ci = sh->colour, lit;

    /* Facing away from the light (or the light on the point: NaN) means no
     * light, whatever E is: no shadow ray needed. */
    if (!(cos_a > 0))
        return colour(0, 0, 0);
    lit = colour(cos_a * (ci.r * light->colour.r / 255), cos_a * (ci.g * light->colour.g / 255),
                 cos_a * (ci.b * light->colour.b / 255));
    /* The course's weights are grey: the largest channel is w max(lit). */
    if (t->cut && shade_cut_shadow(t->cut, weight * colour_max(lit), colour(weight, weight, weight),
                                   lit, sh, n, light, to_light))
        return colour(0, 0, 0);
    e = shade_visibility(t, sh, n, light, to_light);
    if (!(e > 0))
        return colour(0, 0, 0);
    if (e != 1)
        return colour((cos_a * e) * (ci.r * light->colour.r / 255),
                      (cos_a * e) * (ci.g * light->colour.g / 255),
                      (cos_a * e) * (ci.b * light->colour.b / 255));
    return lit;
}

/* Returns what a light of colour Cs adds to a point of colour ci for
 * material pm per unit of E i: kd cos_a Ci Cs / 255 + ks max(0, N . H)^alpha
 * Cs, with ns the shading normal, l and view unit vectors towards the light
 * and the viewer. */
static inline Colour shade_phong_light(const NamedMaterial *pm, Colour ci, Colour cs, double cos_a,
                                       Vec3 ns, Vec3 l, Vec3 view)
{
    double nh = vec3_dot(ns, vec3_normalize(vec3_add(l, view)));
    double spec = nh > 0 ? pm->ks * power(nh < 1 ? nh : 1, pm->shininess) : 0;

    return colour(pm->kd * cos_a * (ci.r * cs.r / 255) + spec * cs.r,
                  pm->kd * cos_a * (ci.g * cs.g / 255) + spec * cs.g,
                  pm->kd * cos_a * (ci.b * cs.b / 255) + spec * cs.b);
}

/* Returns the strength of light at the point to_light from it: i, times
 * for a point light with falloff 1 / d^2 and, with a range R, (1 -
 * (d / R)^4)^2, which is 1 near the light and falls smoothly to 0 at R; 0
 * at R and beyond. */
static inline double shade_strength(const Light *light, Vec3 to_light)
{
    double d2, w;

    if (!light->falloff)
        return light->intensity;
    d2 = vec3_dot(to_light, to_light);
    if (light->range > 0) {
        double q = d2 / (light->range * light->range);
        if (!(q < 1))
            return 0;
        w = 1 - q * q;
        return light->intensity / d2 * (w * w);
    }
    return light->intensity / d2;
}

Colour shade_phong(const Tracer *t, const Shade *sh, const NamedMaterial *pm, Vec3 n, Vec3 ns,
                   Vec3 view, Colour weight)
{
    const Scene *scene = t->scene;
    Colour ci = sh->colour, c;
    double ka = pm->ka * sh->ambient;

    c = colour(ka * (scene->ambient.r * ci.r / 255), ka * (scene->ambient.g * ci.g / 255),
               ka * (scene->ambient.b * ci.b / 255));
    for (size_t i = 0; i < scene->light_count; i++) {
        const Light *light = &scene->lights[i];
        Vec3 to_light = light->distant ? light->to_light
                                       : vec3_sub(light->position, sh->sp.point);
        Vec3 l = light->distant ? to_light : vec3_normalize(to_light);
        double cos_a = vec3_dot(ns, l), e, strength;
        Colour lit;
        int known = 0;

        if (!(cos_a > 0) || !((strength = shade_strength(light, to_light)) > 0))
            continue;
        if (t->cut) {
            Colour full;
            lit = shade_phong_light(pm, ci, light->colour, cos_a, ns, l, view);
            known = 1;
            full = colour_scale(lit, strength);
            if (shade_cut_shadow(t->cut, colour_max(colour_mul(weight, full)), weight, full, sh, n,
                                 light, to_light))
                continue;
        }
        e = shade_visibility(t, sh, n, light, to_light) * strength;
        if (!(e > 0))
            continue;
        if (!known)
            lit = shade_phong_light(pm, ci, light->colour, cos_a, ns, l, view);
        c = colour_add(c, colour_scale(lit, e));
    }
    return c;
}

Colour shade_local(const Tracer *t, const Shade *sh, Vec3 n, Vec3 ns, double weight)
{
    const Scene *scene = t->scene;
    Colour c = shade_direct(t, &scene->lights[0], sh, n, ns, weight);

    for (size_t i = 1; i < scene->light_count; i++)
        c = colour_add(c, shade_direct(t, &scene->lights[i], sh, n, ns, weight));
    if (scene->has_ambient)
        c = colour_add(colour(sh->ambient * (scene->ambient.r * sh->colour.r / 255),
                              sh->ambient * (scene->ambient.g * sh->colour.g / 255),
                              sh->ambient * (scene->ambient.b * sh->colour.b / 255)),
                       c);
    return c;
}

