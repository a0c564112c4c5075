/*
 * hash.h: a 64-bit fingerprint of bytes, for telling apart what must not
 * be mixed: the tiles of different renders. Eight bytes a step (a
 * multiply and a shift each), then FNV-1a byte by byte for the rest:
 * FNV-1a throughout is a serial loop of a multiply a byte, slow on a
 * large scene.
 */
#ifndef RAYTRACE_HASH_H
#define RAYTRACE_HASH_H

#include <stddef.h>
#include <stdint.h>

#define HASH_START 0xcbf29ce484222325u /* the fingerprint of no bytes */

/* Returns the fingerprint h of some bytes extended by the n bytes at p
 * (words read least significant byte first: the same on every machine). */
static inline uint64_t hash_bytes(uint64_t h, const void *p, size_t n)
{
    const unsigned char *b = p;
    size_t i = 0;

    for (; i + 8 <= n; i += 8) {
        uint64_t w = 0;
        for (int k = 0; k < 8; k++)
            w |= (uint64_t)b[i + k] << (8 * k);
        h = (h ^ w) * 0x9e3779b97f4a7c15u;
        h ^= h >> 32;
    }
    for (; i < n; i++) {
        h ^= b[i];
        h *= 0x100000001b3u;
    }
    return h;
}

/* Returns h extended by the 8 bytes of v, least significant first (the
 * same on every machine). */
static inline uint64_t hash_u64(uint64_t h, uint64_t v)
{
    unsigned char b[8];

    for (int i = 0; i < 8; i++)
        b[i] = (unsigned char)(v >> (8 * i));
    return hash_bytes(h, b, 8);
}

#endif
