/*
 * deflate.h: zlib streams (RFC 1950) of DEFLATE data (RFC 1951), written and
 * read without a library, for PNG files.
 *
 * The writer makes either stored blocks (no compression) or one block with
 * the fixed Huffman codes of RFC 1951 section 3.2.6 over a greedy LZ77
 * search (hash chains, 32 KiB window). The reader inflates any DEFLATE
 * data: stored, fixed and dynamic Huffman blocks.
 */
#ifndef RAYTRACE_DEFLATE_H
#define RAYTRACE_DEFLATE_H

#include <stddef.h>
#include <stdint.h>

/* How the writer compresses. */
typedef enum {
    DEFLATE_STORED, /* stored blocks: fastest, no smaller than the input */
    DEFLATE_FIXED   /* LZ77 with the fixed Huffman codes */
} DeflateMode;

/* A growable byte buffer; `failed` is set once memory runs out. */
typedef struct {
    unsigned char *data; /* len bytes, owned */
    size_t len;
    size_t cap;
    int failed;          /* 1: memory ran out; 2: len would have passed max */
    size_t max;          /* the most bytes it may hold; 0: no limit */
} ByteBuf;

/* Appends n bytes to b (or sets b->failed). */
void bytebuf_append(ByteBuf *b, const void *bytes, size_t n);

/* Releases b's bytes. */
void bytebuf_free(ByteBuf *b);

/* Returns the Adler-32 checksum of n bytes (RFC 1950), continuing from adler
 * (1 to start). */
uint32_t deflate_adler32(uint32_t adler, const unsigned char *p, size_t n);

/* Appends to out the zlib stream of the n bytes at in; returns 0, or -1 when
 * memory runs out. */
int deflate_zlib(ByteBuf *out, const unsigned char *in, size_t n, DeflateMode mode);

/* Inflates the zlib stream of n bytes at in, appending the data to out;
 * returns 0, or -1 with a message in msg (size msg_size) when the stream is
 * malformed, fails its checksum, holds more than out->max allows (a
 * decompression bomb stops there) or memory runs out. */
int inflate_zlib(ByteBuf *out, const unsigned char *in, size_t n, char *msg, size_t msg_size);

#endif
