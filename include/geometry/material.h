/*
 * material.h: how a surface answers light: its colour, mirror and
 * transparency weights, refractive index and texture.
 *
 * Every shape carries one. The shading rules that use it are in trace.h.
 */
#ifndef RAYTRACE_MATERIAL_H
#define RAYTRACE_MATERIAL_H

#include <math.h>

#include "math/colour.h"

/* How a texture is read between texel centres, and over the footprint of
 * a pixel (scene/texture.h). */
typedef enum {
    TEXTURE_NEAREST,   /* the texel the point falls in */
    TEXTURE_BILINEAR,  /* the four nearest texels, weighted by distance */
    TEXTURE_TRILINEAR, /* the mip-map's two levels around the footprint's
                          width, each bilinear, blended; stripes filtered
                          over the footprint */
    TEXTURE_EWA        /* an elliptical Gaussian over the footprint (EWA),
                          on the mip-map's levels around its minor axis;
                          stripes as trilinear */
} TextureFilter;

/* Says whether filter averages over a pixel's footprint (the tracer then
 * carries ray differentials to say what it is). */
static inline int texture_filter_averages(int filter)
{
    return filter == TEXTURE_TRILINEAR || filter == TEXTURE_EWA;
}

typedef struct {
    Colour colour;         /* diffuse colour Ci, 0..255 per channel */
    double reflection;     /* mirror weight R, 0..1 */
    double transparency;   /* transmitted weight T, 0..1, R + T <= 1 */
    double ior;            /* refractive index n, > 0 (1 when T = 0) */
    int texture;           /* index in the scene's textures, or -1: Ci is
                              then the colour above */
    TextureFilter filter;  /* lookup used with the texture */
    int named;             /* index in the scene's named materials, whose
                              model shades it (shade.h), or -1: the
                              course's rule (trace.h) */
    int stripes;           /* 1: Ci is striped (the MPL ray tracer's pattern, shade.h):
                              the colour, then black, across the shape */
} Material;

/* How a named material is shaded (shade.h, trace.h): the keyword format's
 * Blinn-Phong and Whitted sum, or one of the MPL format's four kinds. */
typedef enum {
    MODEL_PHONG,     /* ka, kd, ks, alpha; C = local + R Cr + T Ct */
    MODEL_MATTE,     /* diffuse only */
    MODEL_PLASTIC,   /* diffuse and specular, a mirror weighted by Fresnel */
    MODEL_METALLIC,  /* a mirror tinted by the colour, and specular */
    MODEL_DIELECTRIC /* glass: Fresnel's mirror and refraction, and specular */
} ShadingModel;

/* A named material of the keyword format (a Material: its colour, rho_r as
 * the mirror weight, tau as the transparency, eta_r as the index, shaded
 * by Blinn-Phong with the weights below) or of the MPL format (its kind,
 * colour, stripes, index, glossiness as alpha and texture; ks 1 when the
 * glossiness is above 0). */
typedef struct {
    char *name;          /* as written; owned by the scene */
    Material base;       /* what the shapes that use it copy */
    ShadingModel model;  /* how it is shaded */
    double ka, kd, ks;   /* ambient, diffuse and specular weights, >= 0 */
    double shininess;    /* the Blinn-Phong exponent alpha, >= 0 */
    double index;        /* MPL: the index as written, >= 0 (base.ior is
                            it for PLASTIC and DIELECTRIC, 1 otherwise) */
    int line;            /* line of its definition, for messages */
    char *texture;       /* MPL: its texture as the file names it, or NULL;
                            owned by the scene */
    int from_mesh;       /* 1: a mesh file's material (mesh.h), nameless:
                            not written back by --save */
} NamedMaterial;

/* Says whether m's colour is read over a pixel's footprint: a texture or
 * stripes under an averaging filter. */
static inline int material_averages(const Material *m)
{
    return texture_filter_averages(m->filter) && (m->texture >= 0 || m->stripes);
}

/* Returns the opaque, untextured material of colour c and mirror weight r. */
static inline Material material_plain(Colour c, double r)
{
    Material m = {c, r, 0, 1, -1, TEXTURE_NEAREST, -1, 0};
    return m;
}

/* Returns 1 when m is material_plain(m->colour, m->reflection), bit for
 * bit, else 0. */
static inline int material_is_plain(const Material *m)
{
    Material p = material_plain(m->colour, m->reflection);

    return m->transparency == 0 && !signbit(m->transparency) && m->ior == 1 &&
           m->texture == p.texture && m->filter == p.filter && m->named == p.named &&
           m->stripes == p.stripes;
}

#endif
