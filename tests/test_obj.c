/* test_obj.c: Wavefront OBJ files: every face form, and every fault. */
#include <math.h>
#include <stdio.h>
#include <string.h>

#include "obj.h"
#include "parse.h"
#include "test.h"

/* Writes text (len bytes) to build/t.obj and loads it. */
static int load(const char *text, size_t len, ObjMesh *m, Error *err)
{
    FILE *f = fopen("build/t.obj", "wb");

    CHECK(f != NULL);
    if (!f)
        return -2;
    fwrite(text, 1, len, f);
    fclose(f);
    return obj_load("build/t.obj", 0, m, err);
}

static void obj_reads_every_face_form(void)
{
    /* A BOM, CRLF, runs of blanks, comments, ignored records, a polygon,
     * negative indices, and no final newline. */
    static const char text[] = "\xEF\xBB\xBF# a quad and a triangle\r\n"
                               "mtllib x.mtl\r\no thing\r\ng  group one\r\ns off\r\n"
                               "v 0 0 0\r\nv 1 0 0 0.5 0.5 0.5\r\nv 1 1 0\nv 0 1 0\n"
                               "vt 0 0\nvt 1 0\nvt 1 1 0\nvt 0\n"
                               "vn 0 0 1\n"
                               "usemtl red\n"
                               "f 1/1/1   2/2/1 3/3/1 4/4/1  # a quad: two triangles\n"
                               "f -4//1 -3//1 -2//1\n"
                               "f 1/1 2/2 3/3\n"
                               "l 1 2\np 3\n"
                               "f 2 3 4";
    ObjMesh m;
    Error err;

    CHECK_INT(0, load(text, sizeof text - 1, &m, &err));
    CHECK_INT(4, (long long)m.v_count);
    CHECK_INT(4, (long long)m.vt_count);
    CHECK_INT(1, (long long)m.vn_count);
    CHECK_INT(5, (long long)m.tri_count);
    if (m.tri_count == 5) {
        /* The quad's fan: (1 2 3), (1 3 4), from 0. */
        CHECK_INT(0, m.tri[1][0].v);
        CHECK_INT(2, m.tri[1][1].v);
        CHECK_INT(3, m.tri[1][2].v);
        CHECK_INT(3, m.tri[1][2].vt);
        CHECK_INT(0, m.tri[1][2].vn);
        /* Negative indices count back from the last vertex read. */
        CHECK_INT(0, m.tri[2][0].v);
        CHECK_INT(-1, m.tri[2][0].vt);
        CHECK_INT(0, m.tri[2][0].vn);
        CHECK_INT(-1, m.tri[3][0].vn);
        CHECK_INT(3, m.tri[4][2].v);
    }
    CHECK_NEAR(0, m.vt[3][1], 0); /* vt with u alone */
    obj_free(&m);
}

static void obj_faults_name_line_and_column(void)
{
    static const struct {
        const char *text;
        int line, column;
        const char *message;
    } bad[] = {
        {"v 0 0 0\nv 1 0 0\nf 1 2 3\n", 3, 7, "vertex 3 does not exist (2 vertices so far)"},
        {"v 0 0 0\nv 1 0 0\nv 1 1 0\nf 1 2 0\n", 4, 7, "vertex 0 does not exist (3 vertices so far)"},
        {"v 0 0 0\nv 1 0 0\nv 1 1 0\nf -4 2 3\n", 4, 3, "vertex -4 does not exist (3 vertices so far)"},
        {"v 0 0 0\nv 1 0 0\nf 1 2\n", 3, 6, "a face needs at least 3 corners, found 2"},
        {"v 0 0 0\nv 1 0 0\nv 1 1 0\nf 1/5 2 3\n", 4, 5,
         "texture coordinate 5 does not exist (0 so far)"},
        {"v 0 0 0\nv 1 0 0\nv 1 1 0\nf 1//2 2 3\n", 4, 6, "normal 2 does not exist (0 so far)"},
        {"v 0 0 0\nv 1 0 0\nv 1 1 0\nf 1/x 2 3\n", 4, 5,
         "expected a texture coordinate index after '/'"},
        {"v 0 0 0\nv 1 0 0\nv 1 1 0\nf 1a 2 3\n", 4, 4, "unexpected 'a' in a face corner"},
        {"v 0 0 0\nv 1 0 0\nv 1 1 0\nf a 2 3\n", 4, 3,
         "expected a face corner (v, v/vt, v//vn or v/vt/vn), found 'a'"},
        {"v 0 0\n", 1, 6, "expected at least 3 numbers for a vertex (x y z), found 2"},
        {"v 0 0 1,5\n", 1, 7, "expected a number for a vertex (x y z), found '1,5'"},
        {"v 0 0 nan\n", 1, 7, "expected a number for a vertex (x y z), found 'nan'"},
        {"vn 0 0 1 1\n", 1, 10, "a normal has 3 numbers (x y z), found more"},
        {"v 0 0 0\nvp 0.5\n", 2, 1,
         "unsupported OBJ record 'vp' (read: v, vt, vn, f; ignored: o, g, s, usemtl, mtllib, l, "
         "p)"},
        {"v 0 0 0\r\nv 1\r0 0\n", 2, 4, "carriage return inside a line"},
    };

    for (size_t i = 0; i < sizeof bad / sizeof bad[0]; i++) {
        ObjMesh m;
        Error err;
        if (load(bad[i].text, strlen(bad[i].text), &m, &err) == 0) {
            test_fail(__FILE__, __LINE__, "case %zu accepted", i);
            obj_free(&m);
            continue;
        }
        CHECK(strcmp(err.file, "build/t.obj") == 0);
        CHECK_ERROR(bad[i].message, &err, bad[i].line, bad[i].column, bad[i].message);
    }
    {
        ObjMesh m;
        Error err;
        CHECK_INT(-1, load("v 0 0 0\n\0v 1 0 0\n", 18, &m, &err));
        CHECK_INT(2, err.line);
        CHECK_CONTAINS(err.message, "NUL byte");
    }
}

static void mesh_record_adds_the_triangles(void)
{
    static const char obj[] = "v 0 0 5\nv 1 0 5\nv 1 1 5\nv 0 1 5\nv 2 2 5\n"
                              "vt 0 0\nvt 1 0\nvt 1 1\nvt 0 1\n"
                              "f 1/1 2/2 3/3 4/4\nf 1 1 5\n"; /* the last has no area */
    const char *text = "0 0 0\n-1 1 1\n1 1 1\n-1 -1 1\n4\n0 0 0\n0 5 0 255 255 255\n"
                       "mesh: t.obj 10 20 30 0.5 0.25 1.5\n";
    Scene sc;
    Error err;
    FILE *f = fopen("build/t.obj", "wb");

    CHECK(f != NULL);
    if (!f)
        return;
    fwrite(obj, 1, sizeof obj - 1, f);
    fclose(f);
    CHECK_INT(0, parse_scene_text("build/t.txt", text, strlen(text), 0, &sc, &err));
    CHECK_INT(2, (long long)sc.triangle_count);
    if (sc.triangle_count == 2) {
        CHECK_NEAR(0.25, sc.triangles[1].material.transparency, 0);
        CHECK_NEAR(20, sc.triangles[0].material.colour.g, 0);
        CHECK_NEAR(1, sc.triangles[1].uv[1][0], 0); /* corner 3: vt 3 = (1, 1) */
        CHECK_NEAR(1, sc.triangles[1].uv[1][1], 0);
    }
    scene_free(&sc);
    /* Vertex normals make a smooth triangle (normalised); a zero one, a flat one. */
    f = fopen("build/t.obj", "wb");
    CHECK(f != NULL);
    if (!f)
        return;
    fputs("v 0 0 5\nv 1 0 5\nv 0 1 5\nvn 0 0 -2\nvn 1 0 -1\nvn 0 0 0\n"
          "f 1//1 2//2 3//1\nf 1//1 2//3 3//1\n", f);
    fclose(f);
    CHECK_INT(0, parse_scene_text("build/t.txt", text, strlen(text), 0, &sc, &err));
    CHECK_INT(2, (long long)sc.triangle_count);
    if (sc.triangle_count == 2) {
        CHECK_INT(1, sc.triangles[0].smooth);
        CHECK_NEAR(-1, sc.triangles[0].vn[0].z, 0);
        CHECK_NEAR(sqrt(0.5), sc.triangles[0].vn[1].x, 1e-15);
        CHECK_INT(0, sc.triangles[1].smooth);
    }
    scene_free(&sc);
    /* A fault in the OBJ file is reported at the path, quoting the file's
     * own position. */
    f = fopen("build/t.obj", "wb");
    CHECK(f != NULL);
    if (!f)
        return;
    fputs("v 0 0 5\nf 1 2 3\n", f);
    fclose(f);
    CHECK_INT(-1, parse_scene_text("build/t.txt", text, strlen(text), 0, &sc, &err));
    CHECK_INT(8, err.line);
    CHECK_INT(7, err.column);
    CHECK_CONTAINS(err.message, "cannot use the mesh 't.obj': build/t.obj:2:5: vertex 2 does not exist");
}

const TestCase obj_tests[] = {
    {"obj_reads_every_face_form", obj_reads_every_face_form},
    {"obj_faults_name_line_and_column", obj_faults_name_line_and_column},
    {"mesh_record_adds_the_triangles", mesh_record_adds_the_triangles},
    {NULL, NULL},
};
