/* mapping.c: where textures and stripes fall on each shape (see
 * mapping.h). */
#include "scene/mapping.h"

#include <math.h>

#include "math/angle.h"

/* Returns the fraction of x, x - floor(x), in [0, 1). */
static double mapping_frac(double x)
{
    double f = x - floor(x);

    return f < 1 ? f : 0;
}

/* Stores in uv the fractions of the two coordinates of the scene file's
 * point q that lie along a flat surface of normal n: (x, y) when n is
 * nearest z, (x, z) when y, (z, y) when x. */
static void mapping_flat(Vec3 n, Vec3 q, double uv[2])
{
    double ax = fabs((double)n.x), ay = fabs((double)n.y), az = fabs((double)n.z);

    if (az >= ax && az >= ay) {
        uv[0] = mapping_frac(q.x);
        uv[1] = mapping_frac(q.y);
    } else if (ay >= ax) {
        uv[0] = mapping_frac(q.x);
        uv[1] = mapping_frac(q.z);
    } else {
        uv[0] = mapping_frac(q.z);
        uv[1] = mapping_frac(q.y);
    }
}

/* Says whether a flat shape of normal n is a floor (or a ceiling): its
 * points all have one height. */
static int mapping_floor(Vec3 n)
{
    return n.x == 0 && n.z == 0;
}

/* Returns the program's u around a vertical axis of the point q, taken
 * from a point of the axis: 1/2 - atan2(x, z) / 2 pi. */
static double mapping_around(Vec3 q)
{
    return 0.5 - angle_atan2(q.x, q.z) / (2 * ANGLE_PI);
}

/* The MPL ray tracer's rule for one kind of shape: stores in uv the
 * coordinates of sp (p its point in the scene file's units, k the
 * exponent that undoes scene.h's length_exponent, program whether its
 * program's own rules hold) on shape index of scene, and in *scale what
 * u is multiplied by for its stripes; returns mapping_mpl()'s flag. */
typedef int MappingRule(const Scene *scene, size_t index, const SurfacePoint *sp, Vec3 p, int k,
                        int program, double uv[2], double *scale);

static int mapping_sphere(const Scene *scene, size_t index, const SurfacePoint *sp, Vec3 p, int k,
                          int program, double uv[2], double *scale)
{
    const Sphere *s = &scene_spheres(scene)[index];
    Vec3 n = sp->normal;
    double r = ldexp(s->radius, k);
    /* Its program: the height above the centre, not divided by the
     * radius (beyond 1, where its arcsine has no value, the top or
     * bottom row). */
    double y = program ? p.y - ldexp(s->centre.y, k) : n.y;

    uv[0] = 0.5 - angle_atan2(n.z, n.x) / (2 * ANGLE_PI);
    uv[1] = 1 - angle_acos(y < -1 ? -1 : y > 1 ? 1 : y) / ANGLE_PI;
    *scale = r < 1 ? 30 * r : 10 * r;
    return 0;
}

static int mapping_cube(const Scene *scene, size_t index, const SurfacePoint *sp, Vec3 p, int k,
                        int program, double uv[2], double *scale)
{
    const Cube *c = &((const Cube *)scene_items(scene, SHAPE_CUBE))[index];
    Vec3 q = vec3_scale(vec3_sub(sp->point, c->centre), 1 / c->half);

    (void)p, (void)k, (void)program, (void)scale;
    if (sp->normal.x != 0) {
        uv[0] = (q.z + 1) / 2;
        uv[1] = (q.y + 1) / 2;
    } else if (sp->normal.y != 0) {
        uv[0] = (q.x + 1) / 2;
        uv[1] = (q.z + 1) / 2;
    } else {
        uv[0] = (q.x + 1) / 2;
        uv[1] = (q.y + 1) / 2;
    }
    return 0;
}

/* Cylinders and cones: around the axis from the point a. */
static int mapping_round(Vec3 p, Vec3 a, double uv[2])
{
    Vec3 q = vec3_sub(p, a);

    uv[0] = mapping_around(q);
    uv[1] = mapping_frac(q.y);
    return 0;
}

static int mapping_cylinder(const Scene *scene, size_t index, const SurfacePoint *sp, Vec3 p,
                            int k, int program, double uv[2], double *scale)
{
    const Cylinder *c = &((const Cylinder *)scene_items(scene, SHAPE_CYLINDER))[index];

    (void)sp, (void)program, (void)scale;
    return mapping_round(p, vec3_ldexp(c->centre, k), uv);
}

static int mapping_cone(const Scene *scene, size_t index, const SurfacePoint *sp, Vec3 p, int k,
                        int program, double uv[2], double *scale)
{
    const Cone *c = &((const Cone *)scene_items(scene, SHAPE_CONE))[index];

    (void)sp, (void)program, (void)scale;
    return mapping_round(p, vec3_ldexp(c->base, k), uv);
}

static int mapping_square(const Scene *scene, size_t index, const SurfacePoint *sp, Vec3 p, int k,
                          int program, double uv[2], double *scale)
{
    const Square *s = &((const Square *)scene_items(scene, SHAPE_SQUARE))[index];
    Vec3 q = vec3_sub(p, vec3_ldexp(s->centre, k));
    int floor = program && mapping_floor(s->normal);

    (void)sp;
    /* A floor's own height, not its hit points' rounded ones. */
    if (floor)
        q.y = 0;
    mapping_flat(program ? vec3(0, 0, 1) : s->normal, q, uv);
    *scale = ldexp(s->half, k) / 10;
    return floor;
}

static int mapping_plane(const Scene *scene, size_t index, const SurfacePoint *sp, Vec3 p, int k,
                         int program, double uv[2], double *scale)
{
    const Plane *pl = &scene_planes(scene)[index];
    int floor = program && mapping_floor(pl->normal);

    (void)sp;
    if (floor)
        p.y = ldexp(pl->point.y, k);
    mapping_flat(program ? vec3(0, 0, 1) : pl->normal, p, uv);
    *scale = 1;
    return floor;
}

static int mapping_triangle(const Scene *scene, size_t index, const SurfacePoint *sp, Vec3 p,
                            int k, int program, double uv[2], double *scale)
{
    (void)sp, (void)k, (void)program;
    mapping_flat(scene_triangles(scene)[index].normal, p, uv);
    *scale = 1;
    return 0;
}

/* The rules of the kinds the MPL ray tracer drew; the others have none. */
static MappingRule *const mapping_rules[SHAPE_KINDS] = {
    [SHAPE_SPHERE] = mapping_sphere,     [SHAPE_PLANE] = mapping_plane,
    [SHAPE_TRIANGLE] = mapping_triangle, [SHAPE_CUBE] = mapping_cube,
    [SHAPE_SQUARE] = mapping_square,     [SHAPE_CYLINDER] = mapping_cylinder,
    [SHAPE_CONE] = mapping_cone,
};

int mapping_mpl_covers(ShapeKind kind)
{
    return mapping_rules[kind] != NULL;
}

int mapping_mpl(const Scene *scene, ShapeKind kind, size_t index, const SurfacePoint *sp,
                double uv[2], double *stripe)
{
    int k = -scene->length_exponent;
    double scale = 10;
    /* Its program's own rules under its model; ours under the physical.
     * Its program read a floor's one row of the image (the height's
     * fraction, v = 0 at a whole height), not the seam between two rows:
     * the rule says so. */
    int clamp = mapping_rules[kind](scene, index, sp, vec3_ldexp(sp->point, k), k,
                                    scene_mpl_light_rules(scene), uv, &scale);

    *stripe = uv[0] * scale;
    return clamp;
}
