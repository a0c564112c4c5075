/*
 * hash.h: a 64-bit fingerprint of bytes (FNV-1a), for telling apart what
 * must not be mixed: the tiles of different renders.
 */
#ifndef RAYTRACE_HASH_H
#define RAYTRACE_HASH_H

#include <stddef.h>
#include <stdint.h>

#define HASH_START 0xcbf29ce484222325u /* the fingerprint of no bytes */

/* Returns the fingerprint h of some bytes extended by the n bytes at p. */
static inline uint64_t hash_bytes(uint64_t h, const void *p, size_t n)
{
    const unsigned char *b = p;

    for (size_t i = 0; i < n; i++) {
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
