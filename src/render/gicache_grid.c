/* gicache_grid.c: the irradiance cache's store: its records, the hash
 * grid of cells they are filed in, and the lookups that read them (see
 * gicache.h; a record's arithmetic is gicache.c). */
#include "render/gicache.h"

#include <math.h>
#include <stdlib.h>
#include <string.h>

/* The most a lookup's reach may widen the accuracy by: the wider grid's
 * cells are at least GICACHE_MAX_REACH a R a side. */
#define GICACHE_MAX_REACH 2.0

/* The most cells of a grid a record is entered in. */
#define GICACHE_CELLS 27

/* An empty slot's head, a list's end. */
#define GICACHE_NONE UINT32_MAX

/* A record's entry in a cell: the record's point and radius (as when it
 * was entered: a radius only shrinks, so this one never lets a lookup
 * pass a record by that it should read), the record, and the cell's next
 * entry. A lookup tests the distance here, reading the record only when
 * it is near. */
typedef struct GiEntry {
    Vec3 point;
    double radius;
    uint32_t record, next;
} GiEntry;

/* A cell of the hash grid: a cube of 2^scale a side at (ix, iy, iz) in
 * units of its side; head is its last entry added (then the entries'
 * next). A record is entered in every cell of its scale its reach
 * overlaps (at most 27: its reach is less than a cell's side, its box at
 * most three cells across), so a lookup reads one cell a scale. */
typedef struct GiCell {
    int64_t ix, iy, iz;
    int scale;
    uint32_t head; /* GICACHE_NONE: an empty slot */
} GiCell;

void gicache_init(GiCache *c, double a, int levels, size_t limit)
{
    memset(c, 0, sizeof *c);
    c->a = a;
    c->levels = levels;
    c->limit = limit;
    c->grids[0].reach = 1;
    c->grids[1].reach = GICACHE_MAX_REACH;
}

void gicache_free(GiCache *c)
{
    free(c->places);
    free(c->values);
    for (int k = 0; k < 2; k++) {
        free(c->grids[k].entries);
        free(c->grids[k].cells);
    }
    gicache_init(c, c->a, c->levels, c->limit);
}

/* Returns the bytes of records of `records` slots and grids of cells[0]
 * and cells[1] cells. */
static size_t gicache_bytes(const GiCache *c, size_t records, const size_t cells[2])
{
    return records * (sizeof(GiPlace) + 2 * GICACHE_CELLS * sizeof(GiEntry) +
                      (size_t)c->levels * sizeof(GiValue)) +
           (cells[0] + cells[1]) * sizeof(GiCell);
}

size_t gicache_memory(const GiCache *c)
{
    size_t cells[2] = {c->grids[0].cell_capacity, c->grids[1].cell_capacity};

    return gicache_bytes(c, c->capacity, cells);
}

/* Returns the scale (exponent of 2) of grid g's cells a record of radius R
 * is filed in: a side of at least its reach there. */
static int gicache_scale_of(const GiCache *c, const GiGrid *g, double radius)
{
    int e;

    frexp(g->reach * c->a * radius, &e);
    return e;
}

/* Returns the cell coordinate of x at scale s, clamped far inside int64:
 * x times 2^-s (a product exact as ldexp's while 2^-s is a normal double),
 * rounded down. */
static int64_t gicache_coord(real x, int s)
{
    double q;

    if (s > -1000 && s < 1000) {
        uint64_t bits = (uint64_t)(1023 - s) << 52; /* 2^-s, IEEE 754 binary64 */
        double unit;
        memcpy(&unit, &bits, sizeof unit);
        q = (double)x * unit;
    } else {
        q = ldexp((double)x, -s);
    }

    if (q > 4e18)
        return (int64_t)4e18;
    if (q < -4e18)
        return (int64_t)-4e18;
    /* floor(q), exact within the clamp: a conversion truncates towards
     * zero, one less below a negative fraction (libm's floor is a call or
     * some twenty instructions where the processor lacks SSE4.1) */
    int64_t t = (int64_t)q;
    return (double)t > q ? t - 1 : t;
}

/* Returns the slot where grid g's search for cell (s, ix, iy, iz) starts:
 * a hash mixing the four in a few multiplies (where a cell lies in the
 * table changes no answer: a cell's entries keep their order). */
static size_t gicache_home(const GiGrid *g, int s, int64_t ix, int64_t iy, int64_t iz)
{
    uint64_t h = (uint64_t)ix * 0x9e3779b97f4a7c15u ^ (uint64_t)iy * 0xc2b2ae3d27d4eb4fu ^
                 (uint64_t)iz * 0x165667b19e3779f9u ^ (uint64_t)(int64_t)s * 0xd6e8feb86659fd93u;

    h ^= h >> 32;
    h *= 0x9e3779b97f4a7c15u;
    return (size_t)(h ^ (h >> 29)) & (g->cell_capacity - 1);
}

/* Returns the slot of grid g's cell (s, ix, iy, iz), searched from slot i
 * (its home): its own, or the empty one it would take. */
static size_t gicache_probe(const GiGrid *g, size_t i, int s, int64_t ix, int64_t iy, int64_t iz)
{
    size_t mask = g->cell_capacity - 1;

    while (g->cells[i].head != GICACHE_NONE &&
           !(g->cells[i].scale == s && g->cells[i].ix == ix && g->cells[i].iy == iy &&
             g->cells[i].iz == iz))
        i = (i + 1) & mask;
    return i;
}

/* Returns the slot of grid g's cell (s, ix, iy, iz): its own, or the empty
 * one it would take. */
static size_t gicache_slot(const GiGrid *g, int s, int64_t ix, int64_t iy, int64_t iz)
{
    return gicache_probe(g, gicache_home(g, s, ix, iy, iz), s, ix, iy, iz);
}

/* Grows grid g to `capacity` slots (a power of 2), refiling its cells;
 * returns 0 or -1. */
static int gicache_regrid(GiGrid *g, size_t capacity)
{
    GiCell *old = g->cells;
    size_t old_capacity = g->cell_capacity;

    g->cells = malloc(capacity * sizeof *g->cells);
    if (!g->cells) {
        g->cells = old;
        return -1;
    }
    for (size_t i = 0; i < capacity; i++)
        g->cells[i].head = GICACHE_NONE;
    g->cell_capacity = capacity;
    for (size_t i = 0; i < old_capacity; i++)
        if (old[i].head != GICACHE_NONE)
            g->cells[gicache_slot(g, old[i].scale, old[i].ix, old[i].iy, old[i].iz)] = old[i];
    free(old);
    return 0;
}

/* Makes room for one more record and its cells; returns 0, -1 or -2. */
static int gicache_reserve(GiCache *c)
{
    size_t records = c->capacity, cells[2];
    int grow = 0;

    if (c->count == records)
        records = records ? 2 * records : 256;
    for (int k = 0; k < 2; k++) {
        const GiGrid *g = &c->grids[k];
        cells[k] = g->cell_capacity;
        if (2 * (g->cell_count + GICACHE_CELLS) > cells[k])
            cells[k] = cells[k] ? 2 * cells[k] : 512;
        grow |= cells[k] != g->cell_capacity;
    }
    if (records == c->capacity && !grow)
        return 0;
    if (records >= GICACHE_NONE)
        return -2;
    if (c->limit && gicache_bytes(c, records, cells) > c->limit)
        return -2;
    if (records != c->capacity) {
        GiPlace *p = realloc(c->places, records * sizeof *p);
        GiValue *v;

        if (!p)
            return -1;
        c->places = p;
        for (int k = 0; k < 2; k++) {
            GiEntry *e = realloc(c->grids[k].entries, GICACHE_CELLS * records * sizeof *e);
            if (!e)
                return -1;
            c->grids[k].entries = e;
        }
        v = realloc(c->values, records * (size_t)c->levels * sizeof *v);
        if (!v)
            return -1;
        c->values = v;
        c->capacity = records;
    }
    for (int k = 0; k < 2; k++)
        if (cells[k] != c->grids[k].cell_capacity && gicache_regrid(&c->grids[k], cells[k]) != 0)
            return -1;
    return 0;
}

/* Notes that grid g's cells of scale s hold records (kept ascending). */
static void gicache_use_scale(GiGrid *g, int s)
{
    int i = 0;

    while (i < g->scale_count && g->scales[i] < s)
        i++;
    if (i < g->scale_count && g->scales[i] == s)
        return;
    if (g->scale_count == (int)(sizeof g->scales / sizeof g->scales[0]))
        return; /* cannot happen: radii are clamped within 2^60 of each other */
    memmove(&g->scales[i + 1], &g->scales[i], (size_t)(g->scale_count - i) * sizeof g->scales[0]);
    g->scales[i] = s;
    g->scale_count++;
}

/* Enters record i, at place, in grid g's cell (s, ix, iy, iz). */
static void gicache_enter(GiGrid *g, const GiPlace *place, uint32_t i, int s, int64_t ix,
                          int64_t iy, int64_t iz)
{
    size_t slot = gicache_slot(g, s, ix, iy, iz);
    GiEntry *e = &g->entries[g->entry_count];

    if (g->cells[slot].head == GICACHE_NONE) {
        g->cells[slot].scale = s;
        g->cells[slot].ix = ix;
        g->cells[slot].iy = iy;
        g->cells[slot].iz = iz;
        g->cell_count++;
    }
    e->point = place->point;
    e->radius = place->radius;
    e->record = i;
    e->next = g->cells[slot].head;
    g->cells[slot].head = (uint32_t)g->entry_count++;
}

/* A record whose rays met nothing GICACHE_SEAM more often than a
 * neighbour's sits on a seam of the geometry (a corner's edge, where rays
 * leave between two surfaces): it is kept to half their distance. */
#define GICACHE_SEAM 0.15

/* Neighbour clamping (Krivanek et al. 2006): no record's radius exceeds a
 * neighbour's plus their distance, so that the small radius of a record
 * near a corner reaches those beside it; and a record on a seam is kept
 * from its neighbours. Applied between record i and every record whose
 * cells of the wider grid hold its point. Shrinking a radius keeps the
 * record's cells valid: they cover more than its reach. */
static void gicache_clamp_neighbours(GiCache *c, uint32_t i)
{
    const GiGrid *g = &c->grids[1];
    GiPlace *p = &c->places[i];

    for (int k = 0; k < g->scale_count; k++) {
        int s = g->scales[k];
        size_t slot = gicache_slot(g, s, gicache_coord(p->point.x, s), gicache_coord(p->point.y, s),
                                   gicache_coord(p->point.z, s));

        for (uint32_t e = g->cells[slot].head; e != GICACHE_NONE; e = g->entries[e].next) {
            GiPlace *q = &c->places[g->entries[e].record];
            double d = (double)vec3_length(vec3_sub(p->point, q->point));

            if (g->entries[e].record == i)
                continue;
            if (p->radius > q->radius + d)
                p->radius = q->radius + d;
            if (q->radius > p->radius + d)
                q->radius = p->radius + d;
            if (p->open > q->open + GICACHE_SEAM && d > 0)
                p->radius = fmin(p->radius, d / 2);
            if (q->open > p->open + GICACHE_SEAM && d > 0)
                q->radius = fmin(q->radius, d / 2);
        }
    }
}

/* Enters record i in grid g's cells of its scale its reach there
 * overlaps. */
static void gicache_file(GiCache *c, GiGrid *g, uint32_t i)
{
    const GiPlace *place = &c->places[i];
    double reach = g->reach * c->a * place->radius;
    int s = gicache_scale_of(c, g, place->radius);
    int64_t lo[3], hi[3];

    lo[0] = gicache_coord((real)(place->point.x - reach), s);
    lo[1] = gicache_coord((real)(place->point.y - reach), s);
    lo[2] = gicache_coord((real)(place->point.z - reach), s);
    hi[0] = gicache_coord((real)(place->point.x + reach), s);
    hi[1] = gicache_coord((real)(place->point.y + reach), s);
    hi[2] = gicache_coord((real)(place->point.z + reach), s);
    for (int64_t z = lo[2]; z <= hi[2] && z <= lo[2] + 2; z++)
        for (int64_t y = lo[1]; y <= hi[1] && y <= lo[1] + 2; y++)
            for (int64_t x = lo[0]; x <= hi[0] && x <= lo[0] + 2; x++)
                gicache_enter(g, place, i, s, x, y, z);
    gicache_use_scale(g, s);
}

int gicache_add(GiCache *c, const GiPlace *place, const GiValue *values)
{
    int rc = gicache_reserve(c);
    uint32_t i;

    if (rc != 0)
        return rc;
    i = (uint32_t)c->count++;
    c->places[i] = *place;
    memcpy(&c->values[(size_t)i * (size_t)c->levels], values, (size_t)c->levels * sizeof *values);
    gicache_clamp_neighbours(c, i);
    for (int k = 0; k < 2; k++)
        gicache_file(c, &c->grids[k], i);
    return 0;
}

/* Lays grid g's entries of each cell side by side, in the same order, so
 * that a lookup reads them from one stretch of memory (without the room,
 * as they were: the same answers). */
static void gicache_pack(GiGrid *g)
{
    GiEntry *packed = g->entry_count ? malloc(g->entry_count * sizeof *packed) : NULL;
    size_t next = 0;

    if (!packed)
        return;
    for (size_t k = 0; k < g->cell_capacity; k++) {
        uint32_t e = g->cells[k].head;
        if (e == GICACHE_NONE)
            continue;
        g->cells[k].head = (uint32_t)next;
        for (; e != GICACHE_NONE; e = g->entries[e].next) {
            packed[next] = g->entries[e];
            packed[next].next = (uint32_t)(next + 1);
            next++;
        }
        packed[next - 1].next = GICACHE_NONE;
    }
    memcpy(g->entries, packed, g->entry_count * sizeof *packed);
    free(packed);
}

int gicache_refile(GiCache *c)
{
    for (int k = 0; k < 2; k++) {
        GiGrid *g = &c->grids[k];
        for (size_t j = 0; j < g->cell_capacity; j++)
            g->cells[j].head = GICACHE_NONE;
        g->cell_count = 0;
        g->entry_count = 0;
        g->scale_count = 0;
        for (size_t i = 0; i < c->count; i++) {
            /* Smaller radii share fewer cells: the table grows as it fills
             * (a full one would have no empty slot to stop a search). */
            if (2 * (g->cell_count + GICACHE_CELLS) > g->cell_capacity) {
                size_t cells[2] = {c->grids[0].cell_capacity, c->grids[1].cell_capacity};
                cells[k] *= 2;
                if (c->limit && gicache_bytes(c, c->capacity, cells) > c->limit)
                    return -2;
                if (gicache_regrid(g, cells[k]) != 0)
                    return -1;
            }
            gicache_file(c, g, (uint32_t)i);
        }
        gicache_pack(g);
    }
    return 0;
}

void gicache_set(GiCache *c, size_t i, int level, const GiValue *v)
{
    c->values[i * (size_t)c->levels + (size_t)level] = *v;
}

/* The records a lookup has blended so far: their weighted sums. */
typedef struct {
    double sum[3], total;
    int used;
} GiBlend;

/* Returns the weight record i has at x (normal nx) under accuracy a, for
 * level `level`: 0 when it is not valid there or does not hold the level.
 * `radius` is the record's in the grid's entry (at least its own): beyond
 * a times it, no square root is taken and the record is not read. */
static double gicache_valid(const GiCache *c, uint32_t i, Vec3 point, double radius, int level,
                            double a, Vec3 x, Vec3 nx)
{
    Vec3 d = vec3_sub(x, point);
    double reach = a * radius;

    /* Out of reach by distance alone (its error is at least |d| / R). */
    if ((double)vec3_dot(d, d) > reach * reach * (1 + 1e-6) || c->places[i].first > level)
        return 0;
    return gicache_weight(gicache_error(&c->places[i], x, nx), a);
}

/* Returns record i's level `level` carried to x (normal nx). */
static Colour gicache_value_at(const GiCache *c, uint32_t i, int level, Vec3 x, Vec3 nx)
{
    return gicache_extrapolate(&c->places[i], &c->values[i * (size_t)c->levels + (size_t)level],
                               x, nx);
}

/* Reads the list of grid g's entries from `head` for the records valid at
 * x (normal nx) under accuracy a: blends each into b, or with `first` set
 * returns the first one (else GICACHE_NONE; b unused, may be NULL). */
static uint32_t gicache_scan_cell(const GiCache *c, const GiGrid *g, uint32_t head, int level,
                                  double a, Vec3 x, Vec3 nx, int first, GiBlend *b)
{
    for (uint32_t e = head; e != GICACHE_NONE; e = g->entries[e].next) {
        const GiEntry *entry = &g->entries[e];
        double w = gicache_valid(c, entry->record, entry->point, entry->radius, level, a, x, nx);
        Colour v;

        if (w <= 0)
            continue;
        if (first)
            return entry->record;
        v = gicache_value_at(c, entry->record, level, x, nx);
        b->sum[0] += w * v.r;
        b->sum[1] += w * v.g;
        b->sum[2] += w * v.b;
        b->total += w;
        b->used++;
    }
    return GICACHE_NONE;
}

/* Returns the grid a lookup of reach `reach` reads, and in *a the
 * accuracy it applies: the cache's times the reach (at most the widest). */
static const GiGrid *gicache_grid_for(const GiCache *c, double reach, double *a)
{
    *a = c->a * (reach < GICACHE_MAX_REACH ? reach : GICACHE_MAX_REACH);
    return &c->grids[reach <= c->grids[0].reach ? 0 : 1];
}

/* Stores in at[k] and homes[k] each scale k's cell of grid g holding x
 * and the slot its search starts from, asking memory for them all at once
 * (they are far apart: the waits overlap). */
static void gicache_cells_at(const GiGrid *g, Vec3 x, int64_t at[][3], size_t *homes)
{
    for (int k = 0; k < g->scale_count; k++) {
        int s = g->scales[k];

        at[k][0] = gicache_coord(x.x, s);
        at[k][1] = gicache_coord(x.y, s);
        at[k][2] = gicache_coord(x.z, s);
        homes[k] = gicache_home(g, s, at[k][0], at[k][1], at[k][2]);
#if defined(__GNUC__)
        __builtin_prefetch(&g->cells[homes[k]]);
#endif
    }
}

enum { GICACHE_SCALES = sizeof ((GiGrid *)0)->scales / sizeof ((GiGrid *)0)->scales[0] };

int gicache_lookup(const GiCache *c, int level, double reach, Vec3 x, Vec3 nx, Colour *out)
{
    double a;
    const GiGrid *g = gicache_grid_for(c, reach, &a);
    GiBlend b = {{0, 0, 0}, 0, 0};
    uint32_t heads[GICACHE_SCALES];
    size_t homes[GICACHE_SCALES];
    int64_t at[GICACHE_SCALES][3];

    if (c->count == 0 || level >= c->levels)
        return 0;
    gicache_cells_at(g, x, at, homes);
    /* Every scale's entries asked for at once, then read scale by scale. */
    for (int k = 0; k < g->scale_count; k++) {
        size_t slot = gicache_probe(g, homes[k], g->scales[k], at[k][0], at[k][1], at[k][2]);

        heads[k] = g->cells[slot].head;
#if defined(__GNUC__)
        if (heads[k] != GICACHE_NONE)
            __builtin_prefetch(&g->entries[heads[k]]);
#endif
    }
    for (int k = 0; k < g->scale_count; k++)
        gicache_scan_cell(c, g, heads[k], level, a, x, nx, 0, &b);
    if (b.used)
        *out = colour(b.sum[0] / b.total, b.sum[1] / b.total, b.sum[2] / b.total);
    return b.used;
}

/* Returns the first record grid g lists as valid at x under accuracy a
 * (the scales ascending, each cell's entries in order; each scale's cell
 * read as it comes: most searches end before the last), or GICACHE_NONE. */
static uint32_t gicache_first(const GiCache *c, const GiGrid *g, int level, double a, Vec3 x,
                              Vec3 nx)
{
    size_t homes[GICACHE_SCALES];
    int64_t at[GICACHE_SCALES][3];

    gicache_cells_at(g, x, at, homes);
    for (int k = 0; k < g->scale_count; k++) {
        size_t slot = gicache_probe(g, homes[k], g->scales[k], at[k][0], at[k][1], at[k][2]);
        uint32_t i = gicache_scan_cell(c, g, g->cells[slot].head, level, a, x, nx, 1, NULL);
        if (i != GICACHE_NONE)
            return i;
    }
    return GICACHE_NONE;
}

int gicache_any(const GiCache *c, int level, double reach, Vec3 x, Vec3 nx, uint32_t hint[2],
                Colour *out)
{
    double a;
    const GiGrid *g = gicache_grid_for(c, reach, &a);
    uint32_t i = GICACHE_NONE;

    if (c->count == 0 || level >= c->levels)
        return 0;
    for (int k = 0; hint && k < 2 && i == GICACHE_NONE; k++)
        if (hint[k] < c->count && gicache_valid(c, hint[k], c->places[hint[k]].point,
                                                c->places[hint[k]].radius, level, a, x, nx) > 0)
            i = hint[k];
    if (i == GICACHE_NONE)
        i = gicache_first(c, g, level, a, x, nx);
    if (i == GICACHE_NONE)
        return 0;
    if (hint)
        hint[0] = i;
    *out = gicache_value_at(c, i, level, x, nx);
    return 1;
}
