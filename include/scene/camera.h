/*
 * camera.h: the pinhole camera of the course format: an eye and a screen
 * parallelogram in the scene, divided into pixels.
 *
 * The screen has corners top-left TL, top-right TR and bottom-left BL; its
 * edges u = TR - TL (along a row) and v = BL - TL (down a column) need not be
 * orthogonal. Image position (x, y), in pixels from the top-left corner of
 * the image, lies at TL + (x / width) u + (y / height) v, so pixel (i, j) is
 * sampled at its centre (i + 0.5, j + 0.5).
 */
#ifndef RAYTRACE_CAMERA_H
#define RAYTRACE_CAMERA_H

#include "geometry/frustum.h"
#include "geometry/ray.h"
#include "math/vec3.h"

enum {
    CAMERA_MAX_SIZE = 32768,   /* largest width or height, pixels */
    CAMERA_MAX_SAMPLES = 65536 /* most samples per pixel */
};

typedef struct {
    Vec3 eye;      /* camera position: every primary ray starts here */
    Vec3 top_left; /* screen corner TL */
    Vec3 u;        /* TR - TL: the screen's top edge, left to right */
    Vec3 v;        /* BL - TL: the screen's left edge, top to bottom */
    int width;     /* pixels per row, 1..CAMERA_MAX_SIZE */
    int height;    /* rows, 1..CAMERA_MAX_SIZE, derived by camera_height() */
    double aperture; /* lens diameter, scene units; 0 for a pinhole */
    double focus;    /* distance from the eye to the plane in focus, measured
                        along forward; used when aperture > 0 */
    Vec3 forward;    /* unit normal of the screen, away from the eye */
    Vec3 lens_u;     /* unit vector along u: the lens disk's first axis */
    Vec3 lens_v;     /* unit vector in the screen's plane, orthogonal to
                        lens_u, on v's side: the lens disk's second axis */
} Camera;

/* What camera_check_screen() finds wrong with a screen, if anything. */
typedef enum {
    CAMERA_SCREEN_OK,
    CAMERA_SCREEN_NO_WIDTH,  /* TR = TL: u has zero length */
    CAMERA_SCREEN_NO_HEIGHT, /* BL = TL: v has zero length */
    CAMERA_SCREEN_PARALLEL   /* u and v are parallel (sine of angle < 1e-12) */
} CameraScreenFault;

/* Says whether edges u and v span a parallelogram an image can be cut from. */
CameraScreenFault camera_check_screen(Vec3 u, Vec3 v);

/* Returns the image height, max(1, floor(width |v| / |u| + 0.5)), as a double
 * so that the caller can reject heights above CAMERA_MAX_SIZE. */
double camera_height(Vec3 u, Vec3 v, int width);

/* What camera_look_at() finds wrong with a view, if anything. */
typedef enum {
    CAMERA_VIEW_OK,
    CAMERA_VIEW_NO_DIRECTION, /* the eye is the point looked at */
    CAMERA_VIEW_TOO_NARROW    /* the field of view leaves the screen no
                                 width or height in doubles */
} CameraViewFault;

/*
 * Sets up the look-at camera of the OCaml course project: the eye at `from` looks towards
 * `at`, with a horizontal field of view of fov radians (0 < fov < pi) and an
 * image of width x height square pixels. The screen is centred on `at`,
 * square to the line of sight, at the eye's distance from `at` (so that it
 * scales with the scene); world +y is up (for a camera looking straight up
 * or down, +z is up on the image when looking down and -z when looking up),
 * and right is up x forward, so a camera looking along +z has +x on its
 * right, as in the course's scenes. No lens.
 */
CameraViewFault camera_look_at(Camera *cam, Vec3 from, Vec3 at, double fov, int width,
                               int height);

/* Makes the camera's image width x height pixels (each 1..CAMERA_MAX_SIZE)
 * of the same view: the screen keeps its centre and its height (v), and
 * its width (u) becomes height's times width / height, so pixels stay as
 * square as they were; with the image's proportions unchanged, only the
 * pixel counts change. */
void camera_resize(Camera *cam, int width, int height);

/* Gives the camera a thin lens of diameter aperture (> 0) that focuses on
 * the plane parallel to the screen at distance focus (> 0) from the eye;
 * returns -1, changing nothing, when the eye lies in the screen's plane (no
 * direction is forward), else 0. The screen must be valid. */
int camera_set_lens(Camera *cam, double aperture, double focus);

/* Returns the primary ray from the eye through image position (x, y), with
 * a unit direction (all zero if the point is the eye itself). */
Ray camera_ray(const Camera *cam, double x, double y);

/* The screen point camera_ray() aims at, TL + (x / W) u + (y / H) v, in
 * doubles, as the sum of a part that depends on x alone and one that
 * depends on y alone, so that a pixel loop can make each once. */
typedef struct {
    double x, y, z;
} CameraStep;

/* Returns TL + (x / W) u: the point of the top edge above image position x. */
CameraStep camera_column(const Camera *cam, double x);

/* Returns (y / H) v: the step down from the top edge to image position y. */
CameraStep camera_row(const Camera *cam, double y);

/* Returns camera_ray(cam, x, y), bit for bit, from column =
 * camera_column(cam, x) and row = camera_row(cam, y). */
static inline Ray camera_ray_through(const Camera *cam, CameraStep column, CameraStep row)
{
    Vec3 d = vec3_sub(vec3(column.x + row.x, column.y + row.y, column.z + row.z), cam->eye);
    double len = vec3_length(d);
    Ray ray;

    ray.origin = cam->eye;
    ray.dir = len > 0 ? vec3_scale(d, 1.0 / len) : vec3(0, 0, 0);
    return ray;
}

/* Makes f the pyramid of the primary rays through the image positions
 * [x0, x1] x [y0, y1] (x1 > x0, y1 > y0), as camera_ray() computes them;
 * returns 0, or -1 when there is none to make: a lens (its rays leave
 * from the whole disk), or frustum_make()'s. */
int camera_frustum(const Camera *cam, double x0, double y0, double x1, double y1, Frustum *f);

/* Returns the primary ray through image position (x, y) that leaves the
 * lens at disk point lens (a point of the unit disk, scaled by half the
 * aperture): it starts there and passes through the point of the focal
 * plane that the pinhole ray through (x, y) meets, so points in that plane
 * stay sharp. Without a lens (aperture 0) it is camera_ray(cam, x, y). */
Ray camera_lens_ray(const Camera *cam, double x, double y, const double lens[2]);

#endif
