/*
 * obj_read.h: the OBJ reader's state and the steps that share it (private
 * to scenefile/; obj.h is the reader's contract):
 *   obj_lines.c  the lines: vertices, faces, usemtl and mtllib records
 *   obj_parts.c  a large file read by every thread: its parts counted,
 *                read each into its place, their materials joined
 *   obj.c        the whole: the reading, then the material libraries and
 *                the faces cut (it calls the others, none calls it)
 */
#ifndef RAYTRACE_OBJ_READ_H
#define RAYTRACE_OBJ_READ_H

#include <stddef.h>
#include <stdint.h>

#include "base/error.h"
#include "scenefile/mesh_file.h"
#include "scenefile/mtl.h"

/* A triangle's material before the reading ends: a slot among the names
 * its part of the file gave (ObjNames), or one of these. */
#define OBJ_DEFAULT UINT32_MAX
#define OBJ_INHERIT (UINT32_MAX - 1)

/* The material names a part of the file gives with usemtl, in the order of
 * their first line there, and the libraries its mtllib lines name. */
typedef struct {
    MeshMaterial *mats;   /* names and where first used (mesh_file.h) */
    size_t count, capacity;
    MtlLibrary *libs;     /* mtl.h */
    size_t lib_count, lib_capacity;
    uint32_t current;     /* the slot faces get now */
} ObjNames;

/* Where the reader is: the file and the line being read. */
typedef struct {
    const char *name;  /* file name for messages */
    const char *line;  /* first byte of the line */
    size_t len;        /* bytes, without the line ending */
    int lineno;        /* 1-based */
    Error *err;
    size_t max_bytes;  /* the most the mesh's arrays may take; 0: no limit */
    size_t used;       /* bytes they take now */
    int fixed;         /* 1: the mesh's arrays were sized beforehand and do
                          not grow (a part of a reading shared by threads) */
    size_t tri_base;   /* the part's first triangle in the whole mesh */
    ObjNames names;
} ObjReader;

/* The capacities of the mesh's arrays a reading grows: v, vt, vn,
 * triangles, their materials, faces noted. */
enum { OBJ_CAPS = 6 };

/* Files smaller than this are read on one thread. */
enum { OBJ_PARALLEL_MIN = 1 << 20 };

/* Releases what n owns and leaves it empty. */
void obj_names_free(ObjNames *n);

/* Reads the lines from p to end into m (caps: its arrays' capacities);
 * lines are searched for NUL bytes and carriage returns when odd. Returns
 * 0, or -1 with the fault recorded in r->err. */
int obj_parse_lines(ObjReader *r, MeshFile *m, size_t caps[OBJ_CAPS], const char *p,
                    const char *end, int odd);

/* Reads the len bytes at p (no NUL byte nor carriage return in them) into
 * *mesh and the names its lines give into *names with threads threads:
 * the parts are counted, the arrays sized, then each part read into its
 * place and their names joined. Returns 0, or -1 (both empty) when
 * anything is wrong or out of the budget: the serial reading then says
 * what, as it would have. */
int obj_parse_parallel(const char *name, const char *p, size_t len, size_t max_bytes,
                       int threads, MeshFile *mesh, ObjNames *names);

#endif
