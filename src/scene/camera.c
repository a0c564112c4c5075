/* camera.c: the screen's geometry and primary rays (see camera.h). */
#include "scene/camera.h"

#include <float.h>
#include <math.h>

#include "math/angle.h"

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

CameraStep camera_column(const Camera *cam, double x)
{
    double fx = x / cam->width;
    CameraStep c = {cam->top_left.x + fx * cam->u.x, cam->top_left.y + fx * cam->u.y,
                    cam->top_left.z + fx * cam->u.z};

    return c;
}

CameraStep camera_row(const Camera *cam, double y)
{
    double fy = y / cam->height;
    CameraStep r = {fy * cam->v.x, fy * cam->v.y, fy * cam->v.z};

    return r;
}

Ray camera_ray(const Camera *cam, double x, double y)
{
    return camera_ray_through(cam, camera_column(cam, x), camera_row(cam, y));
}

int camera_frustum(const Camera *cam, double x0, double y0, double x1, double y1, Frustum *f)
{
    CameraStep c[2] = {camera_column(cam, x0), camera_column(cam, x1)};
    CameraStep r[2] = {camera_row(cam, y0), camera_row(cam, y1)};
    Vec3 corner[4];
    real err;

    if (cam->aperture > 0)
        return -1;
    /* Around the quadrilateral: top-left, top-right, bottom-right,
     * bottom-left. */
    for (int k = 0; k < 4; k++) {
        CameraStep a = c[k == 1 || k == 2], b = r[k >= 2];
        corner[k] = vec3(a.x + b.x, a.y + b.y, a.z + b.z);
    }
    /* A point camera_ray() aims at: x / W and y / H, their products with u
     * and v, two sums, in doubles, then rounded to real; a few roundings
     * of coordinates no larger than |TL| + |u| + |v|, with room to spare. */
    err = 16 * REAL_EPSILON *
          (vec3_max_abs(cam->top_left) + vec3_max_abs(cam->u) + vec3_max_abs(cam->v));
    return frustum_make(f, cam->eye, corner, err);
}

CameraViewFault camera_look_at(Camera *cam, Vec3 from, Vec3 at, double fov, int width,
                               int height)
{
    Vec3 d = vec3_sub(at, from), forward, right, up;
    double dist, half_w, half_h;
    int k;

    if (!(vec3_max_abs(d) > 0))
        return CAMERA_VIEW_NO_DIRECTION;
    k = vec3_unit_exponent(vec3_max_abs(d));
    dist = ldexp(vec3_length(vec3_ldexp(d, k)), -k);
    forward = vec3_direction(d);
    /* right = (0, 1, 0) x forward = (f.z, 0, -f.x), unless forward is
     * vertical: then up is +z looking down and -z looking up, which both
     * give right = +x. */
    if (forward.x == 0 && forward.z == 0)
        right = vec3(1, 0, 0);
    else
        right = vec3_direction(vec3(forward.z, 0, -forward.x));
    up = vec3_cross(forward, right);
    half_w = angle_tan(fov / 2) * dist;
    half_h = half_w * height / width;
    cam->eye = from;
    cam->u = vec3_scale(right, 2 * half_w);
    cam->v = vec3_scale(up, -2 * half_h);
    cam->top_left = vec3_add(at, vec3_sub(vec3_scale(up, half_h), vec3_scale(right, half_w)));
    cam->width = width;
    cam->height = height;
    cam->aperture = 0;
    cam->focus = 0;
    if (camera_check_screen(cam->u, cam->v) != CAMERA_SCREEN_OK)
        return CAMERA_VIEW_TOO_NARROW;
    return CAMERA_VIEW_OK;
}

void camera_resize(Camera *cam, int width, int height)
{
    if ((double)width * cam->height != (double)height * cam->width) {
        /* u's new length over its old: (width / height) / (W / H). */
        double s = ((double)width * cam->height) / ((double)height * cam->width);
        Vec3 centre = vec3_add(cam->top_left, vec3_scale(cam->u, 0.5));
        cam->u = vec3_scale(cam->u, s);
        cam->top_left = vec3_sub(centre, vec3_scale(cam->u, 0.5));
    }
    cam->width = width;
    cam->height = height;
}

int camera_set_lens(Camera *cam, double aperture, double focus)
{
    Vec3 u = cam->u, v = cam->v, n, lens_v;
    double side;

    camera_normalise_pair(&u, &v);
    n = vec3_normalize(vec3_cross(u, v));
    side = vec3_dot(n, vec3_sub(cam->top_left, cam->eye));
    if (!(side != 0))
        return -1;
    if (side < 0)
        n = vec3_neg(n);
    cam->forward = n;
    cam->lens_u = vec3_normalize(u);
    lens_v = vec3_cross(n, cam->lens_u);
    cam->lens_v = vec3_dot(lens_v, v) < 0 ? vec3_neg(lens_v) : lens_v;
    cam->aperture = aperture;
    cam->focus = focus;
    return 0;
}

Ray camera_lens_ray(const Camera *cam, double x, double y, const double lens[2])
{
    Ray ray = camera_ray(cam, x, y);
    double half = cam->aperture / 2;
    Vec3 focal, start;

    if (!(cam->aperture > 0))
        return ray;
    focal = vec3_add(cam->eye,
                     vec3_scale(ray.dir, cam->focus / vec3_dot(ray.dir, cam->forward)));
    start = vec3_add(cam->eye, vec3_add(vec3_scale(cam->lens_u, half * lens[0]),
                                        vec3_scale(cam->lens_v, half * lens[1])));
    ray.origin = start;
    ray.dir = vec3_normalize(vec3_sub(focal, start));
    return ray;
}
