/* test_obj.c: Wavefront OBJ files: every face form, and every fault. */
#include <math.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>

#include "base/threads.h"
#include "scenefile/load.h"
#include "scenefile/course.h"
#include "scenefile/mesh.h"
#include "scenefile/obj.h"
#include "shading.h"
#include "test.h"

/* Writes text (len bytes) to build/t.obj and loads it. */
static int load(const char *text, size_t len, MeshFile *m, Error *err)
{
    FILE *f = fopen("build/t.obj", "wb");

    CHECK(f != NULL);
    if (!f)
        return -2;
    fwrite(text, 1, len, f);
    fclose(f);
    return mesh_read("build/t.obj", 0, m, err);
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
    MeshFile m;
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
    mesh_file_free(&m);
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
         "unsupported OBJ record 'vp' (read: v, vt, vn, f, usemtl, mtllib; ignored: o, g, s, l, "
         "p)"},
        {"v 0 0 0\r\nv 1\r0 0\n", 2, 4, "carriage return inside a line"},
    };

    for (size_t i = 0; i < sizeof bad / sizeof bad[0]; i++) {
        MeshFile m;
        Error err;
        if (load(bad[i].text, strlen(bad[i].text), &m, &err) == 0) {
            test_fail(__FILE__, __LINE__, "case %zu accepted", i);
            mesh_file_free(&m);
            continue;
        }
        CHECK(strcmp(err.file, "build/t.obj") == 0);
        CHECK_ERROR(bad[i].message, &err, bad[i].line, bad[i].column, bad[i].message);
    }
    {
        MeshFile m;
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
    CHECK_INT(
        0, load_scene_text("build/t.txt", text, strlen(text), SCENE_COURSE, 0, 0, &sc, NULL, &err));
    CHECK_INT(2, (long long)scene_count_of(&sc, SHAPE_TRIANGLE));
    if (scene_count_of(&sc, SHAPE_TRIANGLE) == 2) {
        CHECK_NEAR(0.25, scene_material_of(&sc, &scene_triangles(&sc)[1])->transparency, 0);
        CHECK_NEAR(20, scene_material_of(&sc, &scene_triangles(&sc)[0])->colour.g, 0);
        CHECK_NEAR(1, shading_of(&sc, 1).uv[1][0], 0); /* corner 3: vt 3 = (1, 1) */
        CHECK_NEAR(1, shading_of(&sc, 1).uv[1][1], 0);
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
    CHECK_INT(
        0, load_scene_text("build/t.txt", text, strlen(text), SCENE_COURSE, 0, 0, &sc, NULL, &err));
    CHECK_INT(2, (long long)scene_count_of(&sc, SHAPE_TRIANGLE));
    if (scene_count_of(&sc, SHAPE_TRIANGLE) == 2) {
        CHECK_INT(1, shading_of(&sc, 0).smooth);
        CHECK_NEAR(-1, shading_of(&sc, 0).vn[0].z, 0);
        CHECK_NEAR(sqrt(0.5), shading_of(&sc, 0).vn[1].x, 1e-15);
        CHECK_INT(0, shading_of(&sc, 1).smooth);
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
    CHECK_INT(-1, load_scene_text("build/t.txt", text, strlen(text), SCENE_COURSE, 0, 0, &sc, NULL,
                                  &err));
    CHECK_INT(8, err.line);
    CHECK_INT(7, err.column);
    CHECK_CONTAINS(err.message, "cannot use the mesh 't.obj': build/t.obj:2:5: vertex 2 does not exist");
}

/* A mesh of over 1 MiB, so that it is read on every thread: a grid of
 * vertices with texture coordinates and normals; quads and triangles in
 * every corner form, negative indices, comments, ignored records and blank
 * lines; when degenerate, some faces without area. Returns its length. */
static size_t big_obj(char *text, size_t cap, int degenerate)
{
    enum { N = 120 }; /* N x N vertices */
    size_t len = 0;

    len += (size_t)snprintf(text + len, cap - len, "# a grid\no grid\n");
    for (int i = 0; i < N * N; i++)
        len += (size_t)snprintf(text + len, cap - len,
                                "v %d.%03d\t%d -0.%d  # vertex %d\nvt 0.%d %d\nvn 0 %d 1\n\n",
                                i % N, i % 1000, i / N, i % 7, i + 1, i % 10, i % 2, i % 3);
    for (int y = 0; y + 1 < N; y++)
        for (int x = 0; x + 1 < N; x++) {
            int a = y * N + x + 1, b = a + 1, c = a + N + 1, d = a + N;
            if ((x + y) % 3 == 0)
                len += (size_t)snprintf(text + len, cap - len, "f %d/%d/%d %d/%d/%d %d/%d/%d %d/%d/%d\n",
                                        a, a, a, b, b, b, c, c, c, d, d, d);
            else if ((x + y) % 3 == 1)
                len += (size_t)snprintf(text + len, cap - len, "f %d//%d %d//%d %d//%d\ng g%d\nf %d %d %d\n",
                                        a, a, b, b, c, c, y, a, c, d);
            else
                len += (size_t)snprintf(text + len, cap - len, "f %d %d %d\nf %d/%d %d/%d -%d/-%d\n",
                                        a, b, degenerate && x % 5 == 0 ? a : c, a, a, c, c,
                                        N * N - d + 1, N * N - d + 1);
        }
    return len;
}

/* Parses text on the given threads. */
static int parse_on(int threads, const char *text, size_t len, size_t max_bytes, MeshFile *m,
                    Error *err)
{
    int rc;

    threads_use(threads);
    rc = obj_parse("big.obj", text, len, max_bytes, m, err);
    return rc;
}

/* Returns the bytes the serial reading's arrays take: each grown by
 * doubling from 16. */
static size_t grown_bytes(const MeshFile *m)
{
    size_t counts[5] = {m->v_count, m->vt_count, m->vn_count, m->tri_count, m->polygon_count};
    size_t sizes[5] = {sizeof *m->v, sizeof *m->vt, sizeof *m->vn, sizeof *m->tri,
                       sizeof *m->polygons}, sum = 0;

    for (int a = 0; a < 5; a++) {
        size_t cap = 0;
        while (cap < counts[a])
            cap = cap ? 2 * cap : 16;
        sum += cap * sizes[a];
    }
    return sum;
}

/* A large file is read alike on one thread and on two: the same arrays, or
 * the same fault at the same place (the first in the file), also when the
 * memory limit stops it. */
static void obj_reads_alike_on_every_thread(void)
{
    size_t cap = 4 << 20, len;
    char *text = malloc(cap), *bad = malloc(cap);
    int before = threads_count();
    MeshFile one, two;
    Error e1, e2;

    CHECK(text && bad);
    if (!text || !bad) {
        free(text);
        free(bad);
        return;
    }
    len = big_obj(text, cap, 0);
    CHECK(len > 1 << 20 && len < cap);
    CHECK_INT(0, parse_on(1, text, len, 0, &one, &e1));
    CHECK_INT(0, parse_on(2, text, len, 0, &two, &e2));
    CHECK_INT((long long)one.v_count, (long long)two.v_count);
    CHECK_INT((long long)one.vt_count, (long long)two.vt_count);
    CHECK_INT((long long)one.vn_count, (long long)two.vn_count);
    CHECK_INT((long long)one.tri_count, (long long)two.tri_count);
    CHECK_INT(120 * 120, (long long)one.v_count);
    if (one.tri_count == two.tri_count && one.v_count == two.v_count) {
        CHECK(memcmp(one.v, two.v, one.v_count * sizeof *one.v) == 0);
        CHECK(memcmp(one.vt, two.vt, one.vt_count * sizeof *one.vt) == 0);
        CHECK(memcmp(one.vn, two.vn, one.vn_count * sizeof *one.vn) == 0);
        CHECK(memcmp(one.tri, two.tri, one.tri_count * sizeof *one.tri) == 0);
    }
    /* The memory limit: the serial reading's arrays just fit, or not. */
    {
        size_t need = grown_bytes(&one);
        MeshFile m;
        CHECK_INT(0, parse_on(2, text, len, need, &m, &e2));
        mesh_file_free(&m);
        CHECK_INT(-1, parse_on(1, text, len, need - 1, &m, &e1));
        CHECK_INT(-1, parse_on(2, text, len, need - 1, &m, &e2));
        CHECK_ERROR("memory limit", &e2, e1.line, e1.column, e1.message);
    }
    mesh_file_free(&one);
    mesh_file_free(&two);
    /* A fault early, in the middle, near the end and on the last line: a
     * face naming a vertex not yet read, a malformed number, a face of two
     * corners, an unknown record. */
    {
        static const char *const faults[] = {"f 1 2 14400", "v 1 2 x", "f 1 2", "vp 1"};
        size_t at[] = {len / 50, len / 2, len - len / 40, len};
        for (int k = 0; k < 4; k++) {
            size_t cut = at[k], n;
            MeshFile m;
            while (cut > 0 && text[cut - 1] != '\n')
                cut--;
            memcpy(bad, text, cut);
            n = cut + (size_t)sprintf(bad + cut, "%s\n", faults[k]);
            memcpy(bad + n, text + cut, len - cut);
            n += len - cut;
            CHECK_INT(-1, parse_on(1, bad, n, 0, &m, &e1));
            CHECK_INT(-1, parse_on(2, bad, n, 0, &m, &e2));
            CHECK_ERROR(faults[k], &e2, e1.line, e1.column, e1.message);
            CHECK_CONTAINS(e2.excerpt, faults[k]);
        }
    }
    threads_use(before);
    free(text);
    free(bad);
}

/* Says whether triangle i of scenes sa and sb are alike, field by field
 * (their shading too, and where it is kept). */
static int same_triangle(const Scene *sa, const Scene *sb, size_t i)
{
    const Triangle *a = &scene_triangles(sa)[i], *b = &scene_triangles(sb)[i];
    TriangleShading as = shading_of(sa, i), bs = shading_of(sb, i);

    return memcmp(a->v, b->v, sizeof a->v) == 0 && memcmp(&a->normal, &b->normal, sizeof a->normal) == 0 &&
           memcmp(as.uv, bs.uv, sizeof as.uv) == 0 && memcmp(as.vn, bs.vn, sizeof as.vn) == 0 &&
           as.smooth == bs.smooth && a->shading == b->shading && a->swapped == b->swapped &&
           a->order == b->order && a->material == b->material &&
           scene_material_of(sa, a)->reflection == scene_material_of(sb, b)->reflection &&
           scene_material_of(sa, a)->colour.g == scene_material_of(sb, b)->colour.g;
}

/* Reads scene text on one thread into *one and on two into *two, under
 * memory_limit (bytes, 0: none). */
static void parse_on_both(const char *text, size_t memory_limit, Scene *one, Scene *two)
{
    int before = threads_count();
    Error err;

    threads_use(1);
    CHECK_INT(0, load_scene_text("build/t.txt", text, strlen(text), SCENE_COURSE, memory_limit, 0,
                                 one, NULL, &err));
    threads_use(2);
    CHECK_INT(0, load_scene_text("build/t.txt", text, strlen(text), SCENE_COURSE, memory_limit, 0,
                                 two, NULL, &err));
    threads_use(before);
}

/* Writes build/big.obj: a triangle's three vertices and n faces, the i-th
 * `odd` when i % k == j, else `usual`. Returns 0, or -1. */
static int write_faces(int n, int k, int j, const char *odd, const char *usual)
{
    FILE *f = fopen("build/big.obj", "wb");

    CHECK(f != NULL);
    if (!f)
        return -1;
    fputs("v 0 0 5\nv 1 0 5\nv 0 1 5\n", f);
    for (int i = 0; i < n; i++)
        fputs(i % k == j ? odd : usual, f);
    fclose(f);
    return 0;
}

/* A large mesh's triangles are made alike on one thread and on two, those
 * without area left out, in the same order and the same room. */
static void mesh_made_alike_on_every_thread(void)
{
    const char *text = "0 0 0\n-1 1 1\n1 1 1\n-1 -1 1\n4\n0 0 0\n0 5 0 255 255 255\n"
                       "sphere: 0 0 9 1 1 2 3 0\nmesh: big.obj 10 20 30 0.5\n"
                       "mesh: big.obj 10 20 30 0.5\n";
    const char *mesh = "0 0 0\n-1 1 1\n1 1 1\n-1 -1 1\n4\n0 0 0\n0 5 0 255 255 255\n"
                       "mesh: big.obj 10 20 30 0.5\n";
    size_t cap = 4 << 20, len;
    char *obj = malloc(cap);
    Scene one, two;
    FILE *f = fopen("build/big.obj", "wb");

    CHECK(obj && f);
    if (!obj || !f) {
        free(obj);
        if (f)
            fclose(f);
        return;
    }
    len = big_obj(obj, cap, 1);
    fwrite(obj, 1, len, f);
    fclose(f);
    free(obj);
    parse_on_both(text, 0, &one, &two);
    CHECK_INT((long long)scene_count_of(&one, SHAPE_TRIANGLE),
              (long long)scene_count_of(&two, SHAPE_TRIANGLE));
    CHECK_INT((long long)one.shapes[SHAPE_TRIANGLE].capacity,
              (long long)two.shapes[SHAPE_TRIANGLE].capacity);
    CHECK_INT((long long)scene_count_of(&one, SHAPE_TRIANGLE), (long long)one.shading_count);
    CHECK_INT((long long)one.shading_count, (long long)two.shading_count);
    CHECK_INT((long long)one.shading_capacity, (long long)two.shading_capacity);
    CHECK(scene_count_of(&one, SHAPE_TRIANGLE) > 8192 &&
          scene_count_of(&one, SHAPE_TRIANGLE) % 2 == 0);
    if (scene_count_of(&one, SHAPE_TRIANGLE) == scene_count_of(&two, SHAPE_TRIANGLE)) {
        size_t differ = 0;
        for (size_t i = 0; i < scene_count_of(&one, SHAPE_TRIANGLE); i++)
            differ += !same_triangle(&one, &two, i);
        CHECK_INT(0, (long long)differ);
        /* Objects are ordered as listed: the sphere first. */
        CHECK_INT((long long)scene_count_of(&one, SHAPE_TRIANGLE),
                  scene_triangles(&two)[scene_count_of(&one, SHAPE_TRIANGLE) - 1].order);
    }
    scene_free(&one);
    scene_free(&two);
    /* 4,100 faces of which 10 have no area: room is made for 8,192, then
     * given back to the 4,096 that adding them one by one takes. 4,100
     * faces, 10 with area, under a memory limit with room beside the mesh
     * for its 4,100 triangles (and 16 KiB) but not for the 8,192 that
     * making them all at once would reserve: one by one, as on one thread,
     * to the same 16. */
    static const struct {
        int faces, every, at;
        const char *odd, *usual;
        size_t room; /* triangles the limit has room for beside the mesh; 0: no limit */
        long long count, capacity;
    } cases[] = {{4100, 410, 7, "f 1 1 2\n", "f 1 2 3\n", 0, 4090, 4096},
                 {4100, 410, 0, "f 1 2 3\n", "f 1 1 2\n", 4100, 10, 16}};
    for (size_t c = 0; c < sizeof cases / sizeof cases[0]; c++) {
        size_t limit = 0;
        if (write_faces(cases[c].faces, cases[c].every, cases[c].at, cases[c].odd,
                        cases[c].usual) != 0)
            return;
        if (cases[c].room > 0) {
            MeshFile m;
            Error err;
            CHECK_INT(0, mesh_read("build/big.obj", 0, &m, &err));
            limit = mesh_file_memory(&m) + cases[c].room * sizeof(Triangle) + 16384;
            CHECK(limit < 8192 * sizeof(Triangle));
            mesh_file_free(&m);
        }
        parse_on_both(mesh, limit, &one, &two);
        CHECK_INT(cases[c].count, (long long)scene_count_of(&two, SHAPE_TRIANGLE));
        CHECK_INT(cases[c].capacity, (long long)one.shapes[SHAPE_TRIANGLE].capacity);
        CHECK_INT(cases[c].capacity, (long long)two.shapes[SHAPE_TRIANGLE].capacity);
        if (scene_count_of(&two, SHAPE_TRIANGLE) > 0)
            CHECK_INT(cases[c].count - 1,
                      scene_triangles(&two)[scene_count_of(&two, SHAPE_TRIANGLE) - 1].order);
        scene_free(&one);
        scene_free(&two);
    }
}

const TestCase obj_tests[] = {
    {"obj_reads_every_face_form", obj_reads_every_face_form},
    {"obj_faults_name_line_and_column", obj_faults_name_line_and_column},
    {"mesh_record_adds_the_triangles", mesh_record_adds_the_triangles},
    {"obj_reads_alike_on_every_thread", obj_reads_alike_on_every_thread},
    {"mesh_made_alike_on_every_thread", mesh_made_alike_on_every_thread},
    {NULL, NULL},
};
