/*
 * angle.h: the trigonometry the renderer needs, from + - * / and sqrt only.
 *
 * libm's sin, cos, atan2 and acos are not correctly rounded, and their last
 * bit differs between library versions; a render that used them could
 * differ by a byte from one machine to another. These are computed from
 * IEEE 754 operations alone (argument reduction and a Taylor series), so
 * they give the same bits everywhere. They are accurate to a few ulps,
 * which is more than texture lookups and lens samples need.
 */
#ifndef RAYTRACE_ANGLE_H
#define RAYTRACE_ANGLE_H

#define ANGLE_PI 3.14159265358979323846

/* Stores sin(x) and cos(x) in *s and *c, for |x| <= pi / 4. */
void angle_sincos(double x, double *s, double *c);

/* Returns tan(x) for 0 <= x < pi / 2. */
double angle_tan(double x);

/* Returns the angle of the point (x, y) from the x axis, in [-pi, pi];
 * 0 for the origin. */
double angle_atan2(double y, double x);

/* Returns acos(x) in [0, pi] for x in [-1, 1] (clamped outside). */
double angle_acos(double x);

#endif
