/* cut.c: the rays the cut-off leaves out, and its bounds (see cut.h). */
#include "render/cut.h"

#include <math.h>
#include <stdint.h>
#include <stdlib.h>

/* Keeps d in cut; returns 1, or 0 when there is no memory for it. */
static int cut_keep(Cut *cut, const CutRay *d)
{
    if (cut->deferred_count == cut->deferred_capacity) {
        size_t capacity = cut->deferred_capacity ? 2 * cut->deferred_capacity : 64;
        CutRay *grown;

        if (capacity > SIZE_MAX / sizeof *grown ||
            !(grown = realloc(cut->deferred, capacity * sizeof *grown)))
            return 0;
        cut->deferred = grown;
        cut->deferred_capacity = capacity;
    }
    cut->deferred[cut->deferred_count++] = *d;
    return 1;
}

int cut_keep_out(Cut *cut, double most, const CutRay *d)
{
    if (!cut_keep(cut, d))
        return 0;
    cut->skipped += most;
    return 1;
}

void cut_init(Cut *cut, const Scene *scene, double cutoff)
{
    double lights = 0, local = 0, bg = colour_max(scene->background);

    cut->cutoff = cutoff;
    cut->skipped = 0;
    cut->deferred = NULL;
    cut->deferred_count = 0;
    cut->deferred_capacity = 0;
    if (scene->has_sky)
        bg = fmax(bg, colour_max(scene->sky));
    for (size_t i = 0; i < scene->light_count; i++) {
        /* A light whose strength grows without bound near it (i / d^2)
         * bounds nothing: only shadow rays, whose light is known, are left
         * out then. */
        if (scene->lights[i].falloff) {
            cut->base = cut->per_level = INFINITY;
            return;
        }
        lights += colour_max(scene->lights[i].colour) *
                  (scene->named_count > 0 ? scene->lights[i].intensity : 1);
    }
    if (scene->named_count == 0) {
        /* The course's rule: local <= Ca + sum of Cs (Ci <= 255, cos <= 1,
         * E <= 1), and C = (1 - R - T) local + R Cr + T Ct is a mean of
         * local, Cr and Ct (weights >= 0 adding to 1; on total internal
         * reflection too), so no ray sees more than max(background,
         * local) at any depth. */
        local = (scene->has_ambient ? colour_max(scene->ambient) : 0) + lights;
        cut->base = fmax(bg, local);
        cut->per_level = 0;
        return;
    }
    /* Named materials: local <= ka Ia + sum of i (kd + ks) Cs, and C is
     * local plus at most one (tinted, so no larger) mirror and refracted
     * colour, with weights adding to at most 1 (Blinn-Phong: rho + tau;
     * plastic: 1 - F and F of local and Cr; glass: F and 1 - F): a ray that
     * may still spawn k levels of secondary rays sees at most
     * max(background, local) + k local. */
    for (size_t i = 0; i < scene->named_count; i++) {
        const NamedMaterial *m = &scene->named[i];
        local = fmax(local, m->ka * colour_max(scene->ambient) + (m->kd + m->ks) * lights);
    }
    cut->base = fmax(bg, local);
    cut->per_level = local;
}

void cut_free(Cut *cut)
{
    free(cut->deferred);
    cut->deferred = NULL;
    cut->deferred_count = 0;
    cut->deferred_capacity = 0;
}
