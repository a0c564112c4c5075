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

int mapping_mpl(const Scene *scene, ShapeKind kind, size_t index, const SurfacePoint *sp,
                    double uv[2], double *stripe)
{
    int k = -scene->length_exponent;
    /* Its program's own rules under its model; ours under the physical. */
    int program = scene_mpl_light_rules(scene);
    Vec3 p = vec3_ldexp(sp->point, k);
    double scale = 10;

    switch (kind) {
    case SHAPE_SPHERE: {
        Vec3 n = sp->normal;
        double r = ldexp(scene_spheres(scene)[index].radius, k);
        /* Its program: the height above the centre, not divided by the
         * radius (beyond 1, where its arcsine has no value, the top or
         * bottom row). */
        double y = program ? p.y - ldexp(scene_spheres(scene)[index].centre.y, k) : n.y;
        uv[0] = 0.5 - angle_atan2(n.z, n.x) / (2 * ANGLE_PI);
        uv[1] = 1 - angle_acos(y < -1 ? -1 : y > 1 ? 1 : y) / ANGLE_PI;
        scale = r < 1 ? 30 * r : 10 * r;
        break;
    }
    case SHAPE_CUBE: {
        const Cube *c = &scene_cubes(scene)[index];
        Vec3 q = vec3_scale(vec3_sub(sp->point, c->centre), 1 / c->half);
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
        break;
    }
    case SHAPE_CYLINDER: {
        Vec3 q = vec3_sub(p, vec3_ldexp(scene_cylinders(scene)[index].centre, k));
        uv[0] = mapping_around(q);
        uv[1] = mapping_frac(q.y);
        break;
    }
    case SHAPE_CONE: {
        Vec3 q = vec3_sub(p, vec3_ldexp(scene_cones(scene)[index].base, k));
        uv[0] = mapping_around(q);
        uv[1] = mapping_frac(q.y);
        break;
    }
    case SHAPE_SQUARE: {
        const Square *s = &scene_squares(scene)[index];
        Vec3 q = vec3_sub(p, vec3_ldexp(s->centre, k));
        /* A floor's own height, not its hit points' rounded ones. */
        if (program && mapping_floor(s->normal))
            q.y = 0;
        mapping_flat(program ? vec3(0, 0, 1) : s->normal, q, uv);
        scale = ldexp(s->half, k) / 10;
        break;
    }
    case SHAPE_PLANE: {
        const Plane *pl = &scene_planes(scene)[index];
        if (program && mapping_floor(pl->normal))
            p.y = ldexp(pl->point.y, k);
        mapping_flat(program ? vec3(0, 0, 1) : pl->normal, p, uv);
        scale = 1;
        break;
    }
    default: /* SHAPE_TRIANGLE */
        mapping_flat(scene_triangles(scene)[index].normal, p, uv);
        scale = 1;
        break;
    }
    *stripe = uv[0] * scale;
    /* Its program read a floor's one row of the image (the height's
     * fraction, v = 0 at a whole height), not the seam between two rows. */
    return program && (kind == SHAPE_PLANE || kind == SHAPE_SQUARE) &&
           mapping_floor(kind == SHAPE_PLANE ? scene_planes(scene)[index].normal
                                             : scene_squares(scene)[index].normal);
}
