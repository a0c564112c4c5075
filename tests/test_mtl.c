/* test_mtl.c: MTL material libraries (scenefile/mtl.h): the fields read
 * into the materials the faces use, the first library's description kept,
 * map_Kd's options, warnings where the file makes no sense; paths as their
 * exporter meant them; and what each field becomes in a course scene and
 * in a keyword scene (mesh.h). */
#include <stdio.h>
#include <stdlib.h>
#include <string.h>

#include "base/file.h"
#include "scenefile/mesh.h"
#include "scenefile/mtl.h"
#include "test.h"

/* Makes m a mesh whose faces name the n materials names. */
static void named(MeshFile *m, const char *const *names, int n)
{
    mesh_file_init(m);
    m->materials = calloc((size_t)n, sizeof *m->materials);
    CHECK(m->materials != NULL);
    for (int k = 0; m->materials && k < n; k++) {
        char *name = malloc(strlen(names[k]) + 1);
        strcpy(name, names[k]);
        mesh_material_default(&m->materials[k], name);
        m->material_count++;
    }
}

static void mtl_reads_the_fields_of_the_materials_used(void)
{
    static const char *const names[] = {"shiny red", "glass", "unused"};
    static const char text[] =
        "# a library\r\n"
        "newmtl shiny red  \r\n"
        "Ka 0.1 0.2 0.3\r\nKd 0.8 0 0\r\nKs 0.5\r\nNs 80\r\nillum 3\r\n"
        "map_Kd -s 4 2 -o 0.5 0.25 0 -clamp on -mm 0 1 tex\\wood grain.png\r\n"
        "newmtl glass\nKd 1 1 1\nTr 0.75\nNi 1.5\nillum 6\nKe 1 1 1\nPr 0.3\n"
        "newmtl shiny red\nKd 0 1 0\n"
        "newmtl other\nKd 0 0 1\n";
    MeshFile m;

    named(&m, names, 3);
    CHECK_INT(0, mtl_parse("lib/a.mtl", text, strlen(text), &m));
    if (m.material_count == 3) {
        const MeshMaterial *r = &m.materials[0], *g = &m.materials[1], *u = &m.materials[2];
        CHECK(r->defined && g->defined && !u->defined);
        CHECK_NEAR(0.3, r->ka[2], 0);
        CHECK_NEAR(0.8, r->kd[0], 0); /* the first description, not the later one */
        CHECK_NEAR(0.5, r->ks[1], 0);
        CHECK_NEAR(80, r->ns, 0);
        CHECK_INT(3, r->illum);
        CHECK_NEAR(4, r->uv_scale[0], 0);
        CHECK_NEAR(2, r->uv_scale[1], 0);
        CHECK_NEAR(0.5, r->uv_offset[0], 0);
        CHECK_NEAR(0.25, r->uv_offset[1], 0);
        CHECK(r->texture && strcmp(r->texture, "lib/tex/wood grain.png") == 0);
        CHECK(r->texture_at && r->texture_at->line == 8 && r->texture_at->column == 47);
        CHECK_NEAR(0.25, g->d, 1e-15);
        CHECK_NEAR(1.5, g->ni, 0);
        CHECK_INT(6, g->illum);
    }
    CHECK_INT(0, (long long)m.warning_count);
    mesh_file_free(&m);
}

static void mtl_warns_where_it_makes_no_sense(void)
{
    static const char *const names[] = {"a"};
    static const char text[] = "newmtl a\nKd 1 2\nNs lots\nd 1.5\nfrobnicate 3\nmap_d mask.png\n"
                               "map_Kd -zz 1 t.png\nmap_Kd\nKd spectral x.rfl\n";
    MeshFile m;

    named(&m, names, 1);
    CHECK_INT(0, mtl_parse("w.mtl", text, strlen(text), &m));
    CHECK_INT(8, (long long)m.warning_count);
    if (m.warning_count == 8) {
        CHECK_ERROR("Kd 1 2", &m.warnings[0], 2, 7,
                    "Kd takes a colour r g b (spectral and CIE XYZ colours are not read): line "
                    "passed over");
        CHECK_ERROR("Ns lots", &m.warnings[1], 3, 4,
                    "Ns takes a number from 0 to 1e+06: line passed over");
        CHECK_ERROR("d 1.5", &m.warnings[2], 4, 6, "d takes a number from 0 to 1: line passed over");
        CHECK_ERROR("frobnicate", &m.warnings[3], 5, 1,
                    "unknown MTL statement 'frobnicate': passed over");
        CHECK_ERROR("map_d", &m.warnings[4], 6, 1,
                    "map_d (a cut-out mask) is not read: the faces are drawn whole");
        CHECK_ERROR("-zz", &m.warnings[5], 7, 8, "unknown option '-zz' of map_Kd: passed over");
        CHECK_ERROR("map_Kd", &m.warnings[6], 8, 7,
                    "map_Kd names no texture file: line passed over");
    }
    CHECK(m.material_count == 1 && m.materials[0].d == 1 && m.materials[0].kd[0] == 0.8);
    mesh_file_free(&m);
}

/* Writes an empty file at path. */
static void touch(const char *path)
{
    FILE *f = file_open(path, "wb");
    CHECK(f != NULL);
    if (f)
        fclose(f);
}

static void mtl_finds_paths_as_their_exporter_meant(void)
{
    char *p;

    touch("build/mtl-find.png");
    /* As written, '\' a separator, relative to the naming file. */
    p = mtl_find("build/x.mtl", "mtl-find.png", 12);
    CHECK(p && strcmp(p, "build/mtl-find.png") == 0);
    free(p);
    p = mtl_find("build/sub/x.mtl", "..\\mtl-find.png", 15);
    CHECK(p && strcmp(p, "build/sub/../mtl-find.png") == 0);
    free(p);
    /* A drive letter, another machine's folders: the last part, beside. */
    p = mtl_find("build/x.mtl", "C:\\Users\\me\\Desktop\\mtl-find.png", 32);
    CHECK(p && strcmp(p, "build/mtl-find.png") == 0);
    free(p);
    /* Nowhere: the path as meant, for the message. */
    p = mtl_find("build/x.mtl", "tex\\none.png", 12);
    CHECK(p && strcmp(p, "build/tex/none.png") == 0);
    free(p);
}

/* In a course scene an MTL material follows the course's rule: Kd the
 * colour, mirrors when illum says so (Ks their weight), glass with its
 * index only where illum refracts, transparency 1 - d; in a keyword scene,
 * Blinn-Phong: kd 1, ka Ka / Kd, ks Ks unless illum 0 or 1 or Ns below 1. */
static void mesh_materials_follow_the_scenes_rule(void)
{
    static const char *const names[] = {"mirror", "glass", "dull", "matte"};
    static const char text[] = "newmtl mirror\nKd 1 0.5 0\nKs 0.6 0.6 0.6\nNs 50\nillum 3\n"
                               "newmtl glass\nKd 1 1 1\nKs 0.2 0.2 0.2\nd 0.3\nNi 1.5\nNs 90\nillum 7\n"
                               "newmtl dull\nKa 0.4 0.4 0.4\nKd 0.8 0.8 0.8\nKs 0.9 0.9 0.9\nNs 0\n"
                               "newmtl matte\nKd 0.5 0.5 0.5\nKs 1 1 1\nNs 30\nd 0.5\nNi 1.3\nillum 1\n";
    for (int fmt = 0; fmt < 2; fmt++) {
        MeshFile m;
        Scene sc;
        SceneMesh info;
        static const Vec3 v[3] = {{0, 0, 0}, {1, 0, 0}, {0, 1, 0}};
        named(&m, names, 4);
        CHECK_INT(0, mtl_parse("m.mtl", text, strlen(text), &m));
        /* One triangle of each material. */
        m.v = malloc(sizeof v);
        m.tri = malloc(4 * sizeof *m.tri);
        m.tri_material = malloc(4 * sizeof *m.tri_material);
        memcpy(m.v, v, sizeof v);
        m.v_count = 3;
        for (int t = 0; t < 4; t++) {
            for (int k = 0; k < 3; k++)
                m.tri[t][k].v = k, m.tri[t][k].vt = m.tri[t][k].vn = -1;
            m.tri_material[t] = (uint32_t)t;
        }
        m.tri_count = 4;
        scene_init(&sc);
        sc.format = fmt ? SCENE_KEYWORD : SCENE_COURSE;
        memset(&info, 0, sizeof info);
        CHECK_INT(4, mesh_add(&sc, &m, NULL, &info));
        CHECK_INT(4, (long long)info.materials);
        if (sc.material_count == 4) {
            const Material *mm = sc.materials;
            CHECK_NEAR(255, mm[0].colour.r, 0);
            CHECK_NEAR(127.5, mm[0].colour.g, 0);
            CHECK_NEAR(0.6, mm[0].reflection, 1e-15);
            CHECK_NEAR(0.7, mm[1].transparency, 1e-15);
            CHECK_NEAR(0.2, mm[1].reflection, 1e-15);
            CHECK_NEAR(1.5, mm[1].ior, 0);
            CHECK_NEAR(0, mm[2].reflection, 0); /* illum not given: 2, no mirror */
            CHECK_NEAR(0.5, mm[3].transparency, 0);
            CHECK_NEAR(1, mm[3].ior, 0); /* illum 1: a dissolve, no refraction */
            for (int t = 0; t < 4; t++)
                CHECK_INT(t, scene_triangles(&sc)[t].material);
            CHECK_INT(fmt ? 0 : -1, mm[0].named);
        }
        if (fmt && sc.named_count == 4) {
            const NamedMaterial *pm = sc.named;
            CHECK(pm[0].from_mesh && pm[0].model == MODEL_PHONG && pm[0].kd == 1);
            CHECK_NEAR(0.6, pm[0].ks, 1e-15);
            CHECK_NEAR(50, pm[0].shininess, 0);
            CHECK_NEAR(0.5, pm[2].ka, 1e-15); /* Ka 0.4 over Kd 0.8 */
            CHECK_NEAR(0, pm[2].ks, 0);       /* Ns 0 */
            CHECK_NEAR(0, pm[3].ks, 0);       /* illum 1 */
        }
        scene_free(&sc);
        mesh_file_free(&m);
    }
}

const TestCase mtl_tests[] = {
    {"mtl_reads_the_fields_of_the_materials_used", mtl_reads_the_fields_of_the_materials_used},
    {"mtl_warns_where_it_makes_no_sense", mtl_warns_where_it_makes_no_sense},
    {"mtl_finds_paths_as_their_exporter_meant", mtl_finds_paths_as_their_exporter_meant},
    {"mesh_materials_follow_the_scenes_rule", mesh_materials_follow_the_scenes_rule},
    {NULL, NULL},
};
