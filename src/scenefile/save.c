/* save.c: a scene in the keyword or the MPL format (see save.h). */
#include "scenefile/save.h"

#include <errno.h>
#include <math.h>
#include <stdlib.h>
#include <string.h>

#include "base/path.h"
#include "math/number.h"
#include "scenefile/shapes.h"

/* Writes the numbers of v (n of them), each after a space. */
/* The words of the texture filters (material.h), as the formats read
 * them. */
static const char *const save_filters[] = {"nearest", "bilinear", "trilinear", "ewa"};

static void save_numbers(FILE *fp, const double *v, int n)
{
    char buf[NUMBER_FORMAT_MAX];

    for (int i = 0; i < n; i++)
        fprintf(fp, " %s", number_format(buf, v[i]));
}

/* Writes the three coordinates of p, divided by 2^exponent (exact). */
static void save_point(FILE *fp, Vec3 p, int exponent)
{
    double v[3] = {ldexp(p.x, -exponent), ldexp(p.y, -exponent), ldexp(p.z, -exponent)};

    save_numbers(fp, v, 3);
}

/* Writes " r g b". */
static void save_colour(FILE *fp, Colour c)
{
    double v[3] = {c.r, c.g, c.b};

    save_numbers(fp, v, 3);
}

/* Returns, newly allocated, the absolute path of out_name's folder ("-",
 * standard output: the current folder); NULL with errno set. */
static char *save_out_folder(const char *out_name)
{
    size_t n = strcmp(out_name, "-") == 0 ? 0 : path_dir_length(out_name);
    char *dir = malloc(n + 2), *full;

    if (!dir)
        return NULL;
    memcpy(dir, out_name, n);
    strcpy(dir + n, ".");
    full = path_absolute(dir);
    free(dir);
    return full;
}

/* Writes the path of a file the scene names (a `what`: "mesh", "texture"),
 * written as the scene wrote it and opened at opened, so that it resolves
 * from out_name's folder: as written when the scene file is in that folder
 * too or the path is absolute, else relative to that folder (so that the
 * saved scene and its files may move together), or absolute where no
 * relative path leads (another drive); returns 0, or -1 with *err filled. */
static int save_path(FILE *fp, const char *written, const char *opened, const char *what,
                     const char *scene_name, const char *out_name, Error *err)
{
    size_t sd = path_dir_length(scene_name), od = path_dir_length(out_name);
    char *full, *dir, *rel;

    if (path_is_absolute(written, strlen(written)) ||
        (sd == od && strncmp(scene_name, out_name, sd) == 0)) {
        fputs(written, fp);
        return 0;
    }
    full = path_absolute(opened);
    dir = full ? save_out_folder(out_name) : NULL;
    rel = dir ? path_relative(dir, full) : NULL;
    if (!rel) {
        error_set(err, full ? out_name : opened, "cannot find the %s's path from the saved "
                  "scene's folder: %s", what, strerror(errno));
        free(full);
        free(dir);
        return -1;
    }
    free(full);
    free(dir);
    if (strpbrk(rel, " \t#")) {
        error_set(err, opened, "the %s's path from the saved scene's folder, '%s', has a space "
                  "or '#', which a scene line cannot hold; save next to the scene file instead",
                  what, rel);
        free(rel);
        return -1;
    }
    fputs(rel, fp);
    free(rel);
    return 0;
}

/* Returns the name of the named material of shape i of kind. */
static const char *save_name(const Scene *scene, ShapeKind kind, size_t i)
{
    return scene->named[scene_material(scene, kind, i).named].name;
}

/* Writes the materials, each with all the fields its values need. */
static void save_materials(FILE *fp, const Scene *scene)
{
    for (size_t i = 0; i < scene->named_count; i++) {
        const NamedMaterial *pm = &scene->named[i];
        const Material *b = &pm->base;
        double v[7] = {pm->ka, pm->kd, pm->ks, pm->shininess, b->reflection, b->ior,
                       b->transparency};
        int n = b->transparency > 0 || b->ior != 1 ? 7 : b->reflection > 0 ? 5 : 4;

        if (pm->from_mesh)
            continue; /* its mesh file's: the mesh line reads it again */
        fprintf(fp, "material %s", pm->name);
        save_colour(fp, b->colour);
        save_numbers(fp, v, n);
        fputc('\n', fp);
    }
}

/* Writes the objects in the scene's order, each as its element (a mesh as
 * its mesh line). */
static int save_objects(FILE *fp, const Scene *scene, const SceneSource *src,
                        const char *scene_name, const char *out_name, Error *err)
{
    size_t mesh = 0;
    SceneWalk w;
    ShapeKind kind;
    size_t i;

    scene_walk_start(&w);
    while (scene_walk_next(scene, &w, &kind, &i)) {
        double v[SHAPE_NUMBERS_MAX];
        int n;

        if (kind == SHAPE_TRIANGLE && mesh < src->mesh_count && src->meshes[mesh].first == i) {
            const SceneMesh *m = &src->meshes[mesh++];
            fputs("mesh ", fp);
            if (save_path(fp, m->path, m->opened, "mesh", scene_name, out_name, err) != 0)
                return -1;
            if (m->own_materials)
                fputc('\n', fp); /* drawn in its file's own */
            else
                fprintf(fp, " %s\n", save_name(scene, kind, i));
            /* The walk passes over the mesh's other triangles. */
            w.next[SHAPE_TRIANGLE] = i + m->count;
            continue;
        }
        n = shapes_numbers(scene, kind, i, v);
        fputs(shape_words[kind], fp);
        save_numbers(fp, v, n);
        fprintf(fp, " %s\n", save_name(scene, kind, i));
    }
    return 0;
}

/* Writes scene in the keyword format (save_scene()). */
static int save_keyword(FILE *fp, const Scene *scene, const SceneSource *src,
                        const char *scene_name, const char *out_name, Error *err)
{
    const Camera *cam = &scene->camera;
    double camera[1] = {src->fov};

    fputs("# A keyword-format scene, written by raytrace --save.\n", fp);
    fputs("camera", fp);
    save_point(fp, src->look_from, 0);
    save_point(fp, src->look_at, 0);
    save_numbers(fp, camera, 1);
    fprintf(fp, " %d %d\n", cam->width, cam->height);
    if (scene->background.r != 0 || scene->background.g != 0 || scene->background.b != 0) {
        fputs("background", fp);
        save_colour(fp, scene->background);
        fputc('\n', fp);
    }
    if (scene->has_ambient) {
        fputs("ambient", fp);
        save_colour(fp, scene->ambient);
        fputc('\n', fp);
    }
    save_materials(fp, scene);
    for (size_t i = 0; i < scene->light_count; i++) {
        const Light *l = &scene->lights[i];
        fputs("light", fp);
        save_point(fp, l->position, 0);
        save_colour(fp, l->colour);
        save_numbers(fp, &l->intensity, 1);
        fputc('\n', fp);
    }
    return save_objects(fp, scene, src, scene_name, out_name, err);
}

/* Returns the MPL number y whose 255-fold is the colour channel c, as
 * reading y gives: c / 255 or one of its neighbours (reading multiplies by
 * 255, which may round c / 255's 255-fold away from c). */
static double save_unscale(double c)
{
    double y = c / 255, up = y, down = y;

    for (int i = 0; i < 8; i++) {
        if (up * 255 == c)
            return up;
        if (down * 255 == c)
            return down;
        up = nextafter(up, INFINITY);
        down = nextafter(down, -INFINITY);
    }
    return y;
}

/* Writes " r g b", colour c as the MPL format's 0-to-1 numbers. */
static void save_mpl_colour(FILE *fp, Colour c)
{
    double v[3] = {save_unscale(c.r), save_unscale(c.g), save_unscale(c.b)};

    save_numbers(fp, v, 3);
}

/* Writes the objects of scene, an MPL-format scene, as its primitive
 * lines, in the scene's order. */
static int save_mpl_shapes(FILE *fp, const Scene *scene, const char *scene_name, Error *err)
{
    /* The kinds the MPL ray tracer drew, as it wrote them. */
    static const char *const words[SHAPE_KINDS] = {
        [SHAPE_SPHERE] = "Sphere", [SHAPE_PLANE] = "Plane",       [SHAPE_TRIANGLE] = "Triangle",
        [SHAPE_CUBE] = "Cube",     [SHAPE_SQUARE] = "Square",     [SHAPE_CYLINDER] = "Cylinder",
        [SHAPE_CONE] = "Cone"};
    SceneWalk w;
    ShapeKind kind;
    size_t i;

    scene_walk_start(&w);
    while (scene_walk_next(scene, &w, &kind, &i)) {
        double v[SHAPE_NUMBERS_MAX];
        int n = shapes_numbers(scene, kind, i, v);
        if (!words[kind]) {
            error_set(err, scene_name, "--save cannot write a %s in the MPL format, which has "
                                       "none", shape_words[kind]);
            return -1;
        }
        fprintf(fp, "p %s", words[kind]);
        save_numbers(fp, v, n);
        fprintf(fp, " %s\n", save_name(scene, kind, i));
    }
    return 0;
}

/* Writes scene in the MPL format (save_scene()). */
static int save_mpl(FILE *fp, const Scene *scene, const SceneSource *src, const char *scene_name,
                    const char *out_name, Error *err)
{
    static const char *const kinds[] = {"MATTE", "PLASTIC", "METALLIC", "DIELECTRIC"};
    int k = scene->length_exponent;
    size_t i;

    fputs("# An MPL-format scene (the MPL ray tracer's), written by raytrace --save.\n", fp);
    if (src->camera_line) {
        double fov[1] = {src->fov};
        fputs("c Camera", fp);
        save_point(fp, src->look_from, 0);
        save_point(fp, src->look_at, 0);
        save_numbers(fp, fov, 1);
        fprintf(fp, " %d %d\n", scene->camera.width, scene->camera.height);
    }
    fputs(scene->has_sky ? "c Sky" : "c Background", fp);
    if (scene->has_sky)
        save_mpl_colour(fp, scene->sky);
    save_mpl_colour(fp, scene->background);
    fputc('\n', fp);
    if (scene->has_ambient) {
        fputs("c Ambient", fp);
        save_mpl_colour(fp, scene->ambient);
        fputc('\n', fp);
    }
    if (scene->model == SCENE_MODEL_PHYSICAL)
        fputs("c Model physical\n", fp);
    if (scene->samples)
        fprintf(fp, "c Samples %d\n", scene->samples);
    if (scene->ao_samples >= 0) {
        fprintf(fp, "c AO %d", scene->ao_samples);
        if (scene->ao_distance > 0)
            save_numbers(fp, &scene->ao_distance, 1);
        fputc('\n', fp);
    }
    if (scene->gi_samples >= 0) {
        fprintf(fp, "c GI %d", scene->gi_samples);
        if (scene->gi_bounces > 0)
            fprintf(fp, " %d", scene->gi_bounces);
        fputc('\n', fp);
    }
    if (scene->gi_cache) {
        fputs("c GICache", fp);
        if (scene->gi_cache_error > 0)
            save_numbers(fp, &scene->gi_cache_error, 1);
        fputc('\n', fp);
    }
    if (scene->noise > 0) {
        fputs("c Noise", fp);
        save_numbers(fp, &scene->noise, 1);
        if (scene->noise_min_spp > 0)
            fprintf(fp, " %d", scene->noise_min_spp);
        if (scene->noise_max_spp > 0)
            fprintf(fp, " %d", scene->noise_max_spp);
        fputc('\n', fp);
    }
    for (i = 0; i < scene->named_count; i++) {
        const NamedMaterial *pm = &scene->named[i];
        double v[2] = {pm->index, pm->shininess};
        fprintf(fp, "m %s %s", pm->name, kinds[pm->model - MODEL_MATTE]);
        save_mpl_colour(fp, pm->base.colour);
        fprintf(fp, " %d", pm->base.stripes);
        save_numbers(fp, v, 2);
        fputc(' ', fp);
        if (!pm->texture)
            fputc('N', fp);
        else if (save_path(fp, pm->texture, scene->textures[pm->base.texture].path, "texture",
                           scene_name, out_name, err) != 0)
            return -1;
        /* The filter when it is not the format's default (trilinear). */
        if ((pm->texture || pm->base.stripes) && pm->base.filter != TEXTURE_TRILINEAR)
            fprintf(fp, " %s", save_filters[pm->base.filter]);
        fputc('\n', fp);
    }
    for (i = 0; i < scene->light_count; i++) {
        const Light *l = &scene->lights[i];
        double v[2] = {ldexp(l->intensity, l->distant ? 0 : -2 * k), ldexp(l->range, -k)};
        fputs(l->distant ? "l DirectionLight" : "l PointLight", fp);
        save_point(fp, l->position, l->distant ? 0 : k);
        save_mpl_colour(fp, l->colour);
        save_numbers(fp, v, l->distant || l->range == 0 ? 1 : 2);
        fputc('\n', fp);
    }
    return save_mpl_shapes(fp, scene, scene_name, err);
}

int save_scene(FILE *fp, const Scene *scene, const SceneSource *source, const char *scene_name,
               const char *out_name, Error *err)
{
    int rc;

    if (scene->format == SCENE_COURSE) {
        error_set(err, scene_name, "--save writes the keyword and MPL formats, which cannot "
                                   "express a course-format scene (its screen corners, point "
                                   "lights and shading rule)");
        return -1;
    }
    rc = scene->format == SCENE_MPL ? save_mpl(fp, scene, source, scene_name, out_name, err)
                                    : save_keyword(fp, scene, source, scene_name, out_name, err);
    if (rc == 0 && ferror(fp)) {
        error_set(err, out_name, "cannot write the scene: %s", strerror(errno));
        return -1;
    }
    return rc;
}
