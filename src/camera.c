/* camera.c: the screen's geometry and primary rays (see camera.h). */
#include "camera.h"

#include <float.h>
#include <math.h>

/* Below this sine of the angle between u and v the screen is degenerate. */
#define CAMERA_MIN_SINE 1e-12

/* Scales u and v by the power of two that brings their largest component
 * into [0.5, 1). Exact, and it changes no ratio of lengths, but it keeps the
 * squares inside vec3_length() from underflowing on a tiny screen. */
static void camera_normalise_pair(Vec3 *u, Vec3 *v)
{
    double m = fmax(vec3_max_abs(*u), vec3_max_abs(*v));
    int k;

    if (!(m > 0 && m <= DBL_MAX))
        return;
    k = vec3_unit_exponent(m);
    *u = vec3_ldexp(*u, k);
    *v = vec3_ldexp(*v, k);
}

CameraScreenFault camera_check_screen(Vec3 u, Vec3 v)
{
    double lu, lv;

    camera_normalise_pair(&u, &v);
    lu = vec3_length(u);
    lv = vec3_length(v);

    if (!(lu > 0))
        return CAMERA_SCREEN_NO_WIDTH;
    if (!(lv > 0))
        return CAMERA_SCREEN_NO_HEIGHT;
    if (!(vec3_length(vec3_cross(u, v)) > CAMERA_MIN_SINE * lu * lv))
        return CAMERA_SCREEN_PARALLEL;
    return CAMERA_SCREEN_OK;
}

double camera_height(Vec3 u, Vec3 v, int width)
{
    double h;

    camera_normalise_pair(&u, &v);
    h = floor(width * vec3_length(v) / vec3_length(u) + 0.5);
    return h < 1 ? 1 : h;
}

Ray camera_ray(const Camera *cam, double x, double y)
{
    double fx = x / cam->width, fy = y / cam->height;
    Vec3 p = vec3(cam->top_left.x + fx * cam->u.x + fy * cam->v.x,
                  cam->top_left.y + fx * cam->u.y + fy * cam->v.y,
                  cam->top_left.z + fx * cam->u.z + fy * cam->v.z);
    Vec3 d = vec3_sub(p, cam->eye);
    double len = vec3_length(d);
    Ray ray;

    ray.origin = cam->eye;
    ray.dir = len > 0 ? vec3_scale(d, 1.0 / len) : vec3(0, 0, 0);
    return ray;
}
