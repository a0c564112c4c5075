/* shapes.c: shapes from their records' numbers (see shapes.h). */
#include "scenefile/shapes.h"

#include <math.h>

const char *const shapes_sphere_names[] = {"centre x", "centre y", "centre z", "radius"};
const FieldKind shapes_sphere_kinds[] = {FIELD_COORD, FIELD_COORD, FIELD_COORD,
                                                FIELD_POSITIVE};
static const char *const shapes_plane_names[] = {"point x",  "point y",  "point z",
                                                 "normal x", "normal y", "normal z"};
static const FieldKind shapes_plane_kinds[] = {FIELD_COORD, FIELD_COORD, FIELD_COORD,
                                               FIELD_COORD, FIELD_COORD, FIELD_COORD};
static const char *const shapes_triangle_names[] = {"x0", "y0", "z0", "x1", "y1",
                                                    "z1", "x2", "y2", "z2"};
static const FieldKind shapes_triangle_kinds[] = {FIELD_COORD, FIELD_COORD, FIELD_COORD,
                                                  FIELD_COORD, FIELD_COORD, FIELD_COORD,
                                                  FIELD_COORD, FIELD_COORD, FIELD_COORD};
const char *const shapes_cube_names[] = {"centre x", "centre y", "centre z", "half-edge"};
const char *const shapes_square_names[] = {"centre x", "centre y", "centre z", "normal x",
                                                  "normal y", "normal z", "half-edge"};
const FieldKind shapes_square_kinds[] = {FIELD_COORD, FIELD_COORD, FIELD_COORD,
                                                FIELD_COORD, FIELD_COORD, FIELD_COORD,
                                                FIELD_POSITIVE};
const char *const shapes_cone_names[] = {"x", "y", "z", "radius", "height"};
const FieldKind shapes_cone_kinds[] = {FIELD_COORD, FIELD_COORD, FIELD_COORD,
                                              FIELD_POSITIVE, FIELD_COORD};

const int shapes_count[SHAPE_KINDS] = {4, 6, 9, 4, 7, 4, 5};
const char *const *const shapes_names[SHAPE_KINDS] = {
    shapes_sphere_names, shapes_plane_names,  shapes_triangle_names, shapes_cube_names,
    shapes_square_names, shapes_sphere_names, shapes_cone_names};
const FieldKind *const shapes_kinds[SHAPE_KINDS] = {
    shapes_sphere_kinds, shapes_plane_kinds,  shapes_triangle_kinds, shapes_sphere_kinds,
    shapes_square_kinds, shapes_sphere_kinds, shapes_cone_kinds};
const char *const shapes_word[SHAPE_KINDS] = {"sphere", "plane",    "triangle", "cube",
                                              "square", "cylinder", "cone"};

/* Stores p's coordinates, divided by 2^k, in v from index i. */
static void shapes_put(double *v, int i, Vec3 p, int k)
{
    v[i] = ldexp(p.x, -k);
    v[i + 1] = ldexp(p.y, -k);
    v[i + 2] = ldexp(p.z, -k);
}

int shapes_numbers(const Scene *scene, ShapeKind kind, size_t i, double *v)
{
    int k = scene->length_exponent;

    switch (kind) {
    case SHAPE_SPHERE:
        shapes_put(v, 0, scene_spheres(scene)[i].centre, k);
        v[3] = ldexp(scene_spheres(scene)[i].radius, -k);
        break;
    case SHAPE_PLANE:
        shapes_put(v, 0, scene_planes(scene)[i].point, k);
        shapes_put(v, 3, scene_planes(scene)[i].given, 0);
        break;
    case SHAPE_TRIANGLE:
        for (int j = 0; j < 3; j++)
            shapes_put(v, 3 * j, scene_triangles(scene)[i].v[j], k);
        break;
    case SHAPE_CUBE:
        shapes_put(v, 0, scene_cubes(scene)[i].centre, k);
        v[3] = ldexp(scene_cubes(scene)[i].half, -k);
        break;
    case SHAPE_SQUARE:
        shapes_put(v, 0, scene_squares(scene)[i].centre, k);
        shapes_put(v, 3, scene_squares(scene)[i].given, 0);
        v[6] = ldexp(scene_squares(scene)[i].half, -k);
        break;
    case SHAPE_CYLINDER:
        shapes_put(v, 0, scene_cylinders(scene)[i].centre, k);
        v[3] = ldexp(scene_cylinders(scene)[i].radius, -k);
        break;
    default:
        shapes_put(v, 0, scene_cones(scene)[i].base, k);
        v[3] = ldexp(scene_cones(scene)[i].radius, -k);
        v[4] = ldexp(scene_cones(scene)[i].height, -k);
        break;
    }
    return shapes_count[kind];
}

/* Returns the point of v's numbers from index i. */
static Vec3 shapes_point(const double *v, int i)
{
    return vec3(v[i], v[i + 1], v[i + 2]);
}

int shapes_add(Scene *scene, ShapeKind kind, const double *v, const Material *m,
               const char **fault, int *field)
{
    switch (kind) {
    case SHAPE_SPHERE: {
        return scene_add_sphere(scene, shapes_point(v, 0), v[3], m);
    }
    case SHAPE_PLANE: {
        Plane pl;
        if (plane_make(&pl, shapes_point(v, 0), shapes_point(v, 3), 1, *m) != 0) {
            *fault = "the plane's normal is the zero vector: it must give a direction";
            *field = 3;
            return SHAPES_INVALID;
        }
        return scene_add_shape(scene, SHAPE_PLANE, &pl);
    }
    case SHAPE_TRIANGLE: {
        Triangle tri;
        if (triangle_make(&tri, shapes_point(v, 0), shapes_point(v, 3), shapes_point(v, 6)) != 0) {
            *fault = "the triangle's three vertices lie on one line: it has no area";
            *field = -1; /* the record itself */
            return SHAPES_INVALID;
        }
        return scene_add_triangle(scene, &tri, m);
    }
    case SHAPE_CUBE: {
        Cube c;
        cube_make(&c, shapes_point(v, 0), v[3], *m);
        return scene_add_shape(scene, SHAPE_CUBE, &c);
    }
    case SHAPE_SQUARE: {
        Square s;
        if (square_make(&s, shapes_point(v, 0), shapes_point(v, 3), v[6], *m) != 0) {
            *fault = "the square's normal is the zero vector: it must give a direction";
            *field = 3;
            return SHAPES_INVALID;
        }
        return scene_add_shape(scene, SHAPE_SQUARE, &s);
    }
    case SHAPE_CYLINDER: {
        Cylinder c = {shapes_point(v, 0), v[3], *m, 0};
        return scene_add_shape(scene, SHAPE_CYLINDER, &c);
    }
    default: {
        Cone c;
        if (v[4] == 0) {
            *fault = "the cone's height must not be 0: its apex is that far above (or below) "
                     "the centre of its circle";
            *field = 4;
            return SHAPES_INVALID;
        }
        cone_make(&c, shapes_point(v, 0), v[3], v[4], *m);
        return scene_add_shape(scene, SHAPE_CONE, &c);
    }
    }
}
