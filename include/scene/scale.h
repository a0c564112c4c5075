/*
 * scale.h: scenes too small for floating point's squares and products,
 * enlarged by a power of two that changes no picture.
 */
#ifndef RAYTRACE_SCALE_H
#define RAYTRACE_SCALE_H

#include "scene/scene.h"

/*
 * Enlarges a tiny scene, one whose every coordinate and length is below
 * SCENE_TINY in magnitude, by the power of two that brings the largest into
 * [0.5, 1), and records it in length_exponent. Multiplying every length by a
 * power of two is exact and commutes with every operation the renderer
 * uses, so the picture does not change; but squares and products of lengths
 * no longer underflow. Other scenes are left as they are.
 */
void scene_fit_scale(Scene *scene);

#define SCENE_TINY 0x1p-64 /* ~5.4e-20: smaller scenes are enlarged */

#endif
