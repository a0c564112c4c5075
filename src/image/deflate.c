/* deflate.c: zlib streams written and read (see deflate.h). */
#include "image/deflate.h"

#include <stdio.h>
#include <stdlib.h>
#include <string.h>

void bytebuf_append(ByteBuf *b, const void *bytes, size_t n)
{
    if (b->failed)
        return;
    if (b->max && n > b->max - b->len) {
        b->failed = 2;
        return;
    }
    if (n > b->cap - b->len) {
        size_t cap = b->cap ? b->cap : 4096;
        unsigned char *grown;
        while (cap - b->len < n) {
            if (cap > (size_t)-1 / 2) {
                b->failed = 1;
                return;
            }
            cap *= 2;
        }
        grown = realloc(b->data, cap);
        if (!grown) {
            b->failed = 1;
            return;
        }
        b->data = grown;
        b->cap = cap;
    }
    memcpy(b->data + b->len, bytes, n);
    b->len += n;
}

void bytebuf_free(ByteBuf *b)
{
    free(b->data);
    memset(b, 0, sizeof *b);
}

uint32_t deflate_adler32(uint32_t adler, const unsigned char *p, size_t n)
{
    uint32_t a = adler & 0xffff, b = adler >> 16;

    while (n > 0) {
        /* 5552 bytes keep b below 2^32 before the reduction. */
        size_t chunk = n < 5552 ? n : 5552;
        n -= chunk;
        while (chunk--) {
            a += *p++;
            b += a;
        }
        a %= 65521;
        b %= 65521;
    }
    return b << 16 | a;
}

/* --- writing --------------------------------------------------------- */

/* Bits are packed into bytes from the least significant bit up. */
typedef struct {
    ByteBuf *out;
    uint32_t bits; /* pending bits, the oldest lowest */
    int count;     /* how many */
} BitWriter;

static void deflate_put_bits(BitWriter *w, uint32_t value, int n)
{
    w->bits |= value << w->count;
    w->count += n;
    while (w->count >= 8) {
        unsigned char byte = (unsigned char)(w->bits & 0xff);
        bytebuf_append(w->out, &byte, 1);
        w->bits >>= 8;
        w->count -= 8;
    }
}

/* Writes a Huffman code of n bits, whose first bit is its most significant. */
static void deflate_put_code(BitWriter *w, uint32_t code, int n)
{
    uint32_t reversed = 0;

    for (int i = 0; i < n; i++)
        reversed |= (code >> i & 1) << (n - 1 - i);
    deflate_put_bits(w, reversed, n);
}

static void deflate_flush_byte(BitWriter *w)
{
    if (w->count > 0)
        deflate_put_bits(w, 0, 8 - w->count);
}

/* Lengths 3..258 and distances 1..32768: code bases and extra bits. */
static const uint16_t deflate_len_base[29] = {3,  4,  5,  6,  7,  8,  9,  10,  11,  13,
                                              15, 17, 19, 23, 27, 31, 35, 43,  51,  59,
                                              67, 83, 99, 115, 131, 163, 195, 227, 258};
static const uint8_t deflate_len_extra[29] = {0, 0, 0, 0, 0, 0, 0, 0, 1, 1, 1, 1, 2, 2, 2,
                                              2, 3, 3, 3, 3, 4, 4, 4, 4, 5, 5, 5, 5, 0};
static const uint16_t deflate_dist_base[30] = {
    1,   2,   3,   4,   5,   7,    9,    13,   17,   25,   33,   49,   65,    97,    129,
    193, 257, 385, 513, 769, 1025, 1537, 2049, 3073, 4097, 6145, 8193, 12289, 16385, 24577};
static const uint8_t deflate_dist_extra[30] = {0, 0, 0, 0, 1, 1, 2, 2,  3,  3,  4,  4,  5,  5,  6,
                                               6, 7, 7, 8, 8, 9, 9, 10, 10, 11, 11, 12, 12, 13, 13};

/* Writes literal/length symbol s with the fixed code. */
static void deflate_put_fixed_symbol(BitWriter *w, int s)
{
    if (s < 144)
        deflate_put_code(w, 0x30 + (uint32_t)s, 8);
    else if (s < 256)
        deflate_put_code(w, 0x190 + (uint32_t)(s - 144), 9);
    else if (s < 280)
        deflate_put_code(w, (uint32_t)(s - 256), 7);
    else
        deflate_put_code(w, 0xc0 + (uint32_t)(s - 280), 8);
}

/* Writes a match of length len (3..258) at distance dist (1..32768). */
static void deflate_put_match(BitWriter *w, int len, int dist)
{
    int l = 28, d = 29;

    while (deflate_len_base[l] > len)
        l--;
    deflate_put_fixed_symbol(w, 257 + l);
    deflate_put_bits(w, (uint32_t)(len - deflate_len_base[l]), deflate_len_extra[l]);
    while (deflate_dist_base[d] > dist)
        d--;
    deflate_put_code(w, (uint32_t)d, 5);
    deflate_put_bits(w, (uint32_t)(dist - deflate_dist_base[d]), deflate_dist_extra[d]);
}

enum {
    DEFLATE_WINDOW = 32768,
    DEFLATE_HASH_BITS = 15,
    DEFLATE_MAX_CHAIN = 48, /* candidates tried per position */
    DEFLATE_MIN_MATCH = 3,
    DEFLATE_MAX_MATCH = 258
};

static uint32_t deflate_hash(const unsigned char *p)
{
    return ((uint32_t)p[0] << 16 | (uint32_t)p[1] << 8 | p[2]) * 2654435761u >>
           (32 - DEFLATE_HASH_BITS);
}

/* One fixed-Huffman block over all of in: greedy LZ77 with hash chains
 * (head: the latest position of each hash; prev: the one before, by
 * position modulo the window). */
static int deflate_fixed(BitWriter *w, const unsigned char *in, size_t n)
{
    int32_t *head = malloc(sizeof *head << DEFLATE_HASH_BITS);
    int32_t *prev = malloc(sizeof *prev * DEFLATE_WINDOW);
    size_t i = 0;

    if (!head || !prev) {
        free(head);
        free(prev);
        return -1;
    }
    for (size_t k = 0; k < (size_t)1 << DEFLATE_HASH_BITS; k++)
        head[k] = -1;
    deflate_put_bits(w, 1, 1); /* BFINAL */
    deflate_put_bits(w, 1, 2); /* BTYPE 01: fixed codes */
    while (i < n) {
        int best_len = 0, best_dist = 0;

        if (n - i >= DEFLATE_MIN_MATCH) {
            uint32_t h = deflate_hash(in + i);
            int32_t cand = head[h];
            size_t most = n - i < DEFLATE_MAX_MATCH ? n - i : DEFLATE_MAX_MATCH;

            for (int chain = 0; cand >= 0 && chain < DEFLATE_MAX_CHAIN; chain++) {
                size_t dist = i - (size_t)cand, len = 0;
                if (dist > DEFLATE_WINDOW)
                    break;
                while (len < most && in[(size_t)cand + len] == in[i + len])
                    len++;
                if ((int)len > best_len) {
                    best_len = (int)len;
                    best_dist = (int)dist;
                    if (len == most)
                        break;
                }
                cand = prev[(size_t)cand % DEFLATE_WINDOW];
            }
        }
        if (best_len < DEFLATE_MIN_MATCH) {
            best_len = 1;
            deflate_put_fixed_symbol(w, in[i]);
        } else {
            deflate_put_match(w, best_len, best_dist);
        }
        /* Enter every position passed into the chains. */
        for (int k = 0; k < best_len; k++, i++) {
            if (n - i >= DEFLATE_MIN_MATCH) {
                uint32_t h = deflate_hash(in + i);
                prev[i % DEFLATE_WINDOW] = head[h];
                head[h] = (int32_t)i;
            }
        }
    }
    deflate_put_fixed_symbol(w, 256); /* end of block */
    free(head);
    free(prev);
    return 0;
}

/* Stored blocks of at most 65535 bytes. */
static void deflate_stored(BitWriter *w, const unsigned char *in, size_t n)
{
    size_t i = 0;

    do {
        size_t len = n - i < 65535 ? n - i : 65535;
        unsigned char hdr[4] = {(unsigned char)(len & 0xff), (unsigned char)(len >> 8),
                                (unsigned char)(~len & 0xff), (unsigned char)(~len >> 8 & 0xff)};
        deflate_put_bits(w, i + len == n, 1);
        deflate_put_bits(w, 0, 2);
        deflate_flush_byte(w);
        bytebuf_append(w->out, hdr, 4);
        bytebuf_append(w->out, in + i, len);
        i += len;
    } while (i < n);
}

int deflate_zlib(ByteBuf *out, const unsigned char *in, size_t n, DeflateMode mode)
{
    /* CMF 0x78: deflate, 32 KiB window; FLG 0x01: no dictionary, and
     * 0x7801 is a multiple of 31 as RFC 1950 requires. */
    static const unsigned char header[2] = {0x78, 0x01};
    BitWriter w = {out, 0, 0};
    uint32_t adler = deflate_adler32(1, in, n);
    unsigned char trailer[4] = {(unsigned char)(adler >> 24), (unsigned char)(adler >> 16),
                                (unsigned char)(adler >> 8), (unsigned char)adler};
    size_t start = out->len;

    bytebuf_append(out, header, 2);
    if (mode == DEFLATE_FIXED) {
        if (deflate_fixed(&w, in, n) != 0)
            return -1;
        deflate_flush_byte(&w);
        /* Data that does not compress is stored instead: at most 5 bytes
         * a 65535-byte block more than the input. */
        if (out->len - start - 2 > n + 5 * (n / 65535 + 1)) {
            out->len = start + 2;
            w.bits = 0;
            w.count = 0;
            mode = DEFLATE_STORED;
        }
    }
    if (mode == DEFLATE_STORED)
        deflate_stored(&w, in, n);
    deflate_flush_byte(&w);
    bytebuf_append(out, trailer, 4);
    return out->failed ? -1 : 0;
}

/* --- reading --------------------------------------------------------- */

typedef struct {
    const unsigned char *in;
    size_t n, pos;  /* bytes, and the next byte to read */
    uint32_t bits;  /* bits read ahead, the next lowest */
    int count;      /* how many */
    int overrun;    /* a read went past the end */
} BitReader;

static uint32_t inflate_bits(BitReader *r, int n)
{
    uint32_t v;

    while (r->count < n) {
        if (r->pos >= r->n) {
            r->overrun = 1;
            return 0;
        }
        r->bits |= (uint32_t)r->in[r->pos++] << r->count;
        r->count += 8;
    }
    v = r->bits & ((1u << n) - 1);
    r->bits >>= n;
    r->count -= n;
    return v;
}

/* A canonical Huffman code: how many codes of each length, and the symbols
 * in code order. */
typedef struct {
    uint16_t count[16];
    uint16_t symbol[288];
} Huffman;

/* Builds h from the code lengths of n symbols; returns 0, or -1 when the
 * lengths over-subscribe the code space. */
static int inflate_build(Huffman *h, const uint8_t *lengths, int n)
{
    uint16_t offset[16];
    int left = 1;

    memset(h->count, 0, sizeof h->count);
    for (int s = 0; s < n; s++)
        h->count[lengths[s]]++;
    h->count[0] = 0;
    for (int len = 1; len < 16; len++) {
        left = 2 * left - h->count[len];
        if (left < 0)
            return -1;
    }
    offset[1] = 0;
    for (int len = 1; len < 15; len++)
        offset[len + 1] = (uint16_t)(offset[len] + h->count[len]);
    for (int s = 0; s < n; s++)
        if (lengths[s])
            h->symbol[offset[lengths[s]]++] = (uint16_t)s;
    return 0;
}

/* Reads one symbol of code h, a bit at a time: codes of each length are
 * consecutive numbers, so a code of length len is valid when it lies below
 * the first code of that length plus their count. Returns -1 on a bad code. */
static int inflate_symbol(BitReader *r, const Huffman *h)
{
    int code = 0, first = 0, index = 0;

    for (int len = 1; len < 16; len++) {
        code |= (int)inflate_bits(r, 1);
        if (r->overrun)
            return -1;
        if (code - first < h->count[len])
            return h->symbol[index + code - first];
        index += h->count[len];
        first = (first + h->count[len]) << 1;
        code <<= 1;
    }
    return -1;
}

/* Inflates one block coded with lit (literals/lengths) and dist. */
static int inflate_codes(BitReader *r, ByteBuf *out, const Huffman *lit, const Huffman *dist,
                         char *msg, size_t msg_size)
{
    for (;;) {
        int s = inflate_symbol(r, lit);
        if (s < 0) {
            snprintf(msg, msg_size, "invalid literal/length code");
            return -1;
        }
        if (s < 256) {
            unsigned char byte = (unsigned char)s;
            bytebuf_append(out, &byte, 1);
        } else if (s == 256) {
            if (out->failed)
                snprintf(msg, msg_size, out->failed == 2 ? "more data than the image needs" :
                                                           "out of memory");
            return out->failed ? -1 : 0;
        } else {
            int len, d, distance;
            if (s > 285) {
                snprintf(msg, msg_size, "invalid length symbol %d", s);
                return -1;
            }
            len = deflate_len_base[s - 257] + (int)inflate_bits(r, deflate_len_extra[s - 257]);
            d = inflate_symbol(r, dist);
            if (d < 0 || d > 29) {
                snprintf(msg, msg_size, "invalid distance code");
                return -1;
            }
            distance = deflate_dist_base[d] + (int)inflate_bits(r, deflate_dist_extra[d]);
            if ((size_t)distance > out->len) {
                snprintf(msg, msg_size, "distance %d reaches before the start of the data",
                         distance);
                return -1;
            }
            for (int k = 0; k < len && !out->failed; k++) {
                unsigned char byte = out->data[out->len - (size_t)distance];
                bytebuf_append(out, &byte, 1);
            }
        }
        if (r->overrun) {
            snprintf(msg, msg_size, "the compressed data ends inside a block");
            return -1;
        }
    }
}

/* Reads a dynamic block's code tables into lit and dist. */
static int inflate_dynamic_tables(BitReader *r, Huffman *lit, Huffman *dist, char *msg,
                                  size_t msg_size)
{
    static const uint8_t order[19] = {16, 17, 18, 0, 8, 7, 9, 6, 10, 5,
                                      11, 4, 12, 3, 13, 2, 14, 1, 15};
    uint8_t lengths[320] = {0}, cl[19] = {0};
    int nlit = (int)inflate_bits(r, 5) + 257, ndist = (int)inflate_bits(r, 5) + 1;
    int ncode = (int)inflate_bits(r, 4) + 4, k = 0;
    Huffman lencode;

    if (nlit > 286 || ndist > 30) {
        snprintf(msg, msg_size, "too many codes in a dynamic block");
        return -1;
    }
    for (int i = 0; i < ncode; i++)
        cl[order[i]] = (uint8_t)inflate_bits(r, 3);
    if (inflate_build(&lencode, cl, 19) != 0) {
        snprintf(msg, msg_size, "invalid code length code");
        return -1;
    }
    while (k < nlit + ndist) {
        int s = inflate_symbol(r, &lencode), repeat, value = 0;
        if (s < 0) {
            snprintf(msg, msg_size, "invalid code length");
            return -1;
        }
        if (s < 16) {
            lengths[k++] = (uint8_t)s;
            continue;
        }
        if (s == 16) {
            if (k == 0) {
                snprintf(msg, msg_size, "a repeated code length with nothing before it");
                return -1;
            }
            value = lengths[k - 1];
            repeat = 3 + (int)inflate_bits(r, 2);
        } else if (s == 17) {
            repeat = 3 + (int)inflate_bits(r, 3);
        } else {
            repeat = 11 + (int)inflate_bits(r, 7);
        }
        if (k + repeat > nlit + ndist) {
            snprintf(msg, msg_size, "code lengths overflow the table");
            return -1;
        }
        while (repeat--)
            lengths[k++] = (uint8_t)value;
    }
    if (lengths[256] == 0 || inflate_build(lit, lengths, nlit) != 0 ||
        inflate_build(dist, lengths + nlit, ndist) != 0) {
        snprintf(msg, msg_size, "invalid Huffman code lengths");
        return -1;
    }
    return 0;
}

int inflate_zlib(ByteBuf *out, const unsigned char *in, size_t n, char *msg, size_t msg_size)
{
    BitReader r = {in, n, 2, 0, 0, 0};
    size_t start = out->len;
    int final = 0;
    uint32_t adler;

    if (n < 6 || (in[0] & 0x0f) != 8 || (in[0] << 8 | in[1]) % 31 != 0 || (in[1] & 0x20)) {
        snprintf(msg, msg_size, "not a zlib stream of DEFLATE data");
        return -1;
    }
    while (!final) {
        int type;
        final = (int)inflate_bits(&r, 1);
        type = (int)inflate_bits(&r, 2);
        if (type == 0) {
            size_t len, nlen;
            r.bits = 0;
            r.count = 0; /* stored blocks start at a byte boundary */
            if (r.n - r.pos < 4) {
                snprintf(msg, msg_size, "the compressed data ends inside a block");
                return -1;
            }
            len = (size_t)(r.in[r.pos] | r.in[r.pos + 1] << 8);
            nlen = (size_t)(r.in[r.pos + 2] | r.in[r.pos + 3] << 8);
            r.pos += 4;
            if (len != (~nlen & 0xffff) || r.n - r.pos < len) {
                snprintf(msg, msg_size, "a stored block's length is corrupt or cut");
                return -1;
            }
            bytebuf_append(out, r.in + r.pos, len);
            r.pos += len;
        } else if (type == 1) {
            Huffman lit, dist;
            uint8_t l[288];
            for (int s = 0; s < 288; s++)
                l[s] = s < 144 ? 8 : s < 256 ? 9 : s < 280 ? 7 : 8;
            inflate_build(&lit, l, 288);
            for (int s = 0; s < 30; s++)
                l[s] = 5;
            inflate_build(&dist, l, 30);
            if (inflate_codes(&r, out, &lit, &dist, msg, msg_size) != 0)
                return -1;
        } else if (type == 2) {
            Huffman lit, dist;
            if (inflate_dynamic_tables(&r, &lit, &dist, msg, msg_size) != 0 ||
                inflate_codes(&r, out, &lit, &dist, msg, msg_size) != 0)
                return -1;
        } else {
            snprintf(msg, msg_size, "invalid block type 3");
            return -1;
        }
        if (r.overrun) {
            snprintf(msg, msg_size, "the compressed data ends inside a block");
            return -1;
        }
        if (out->failed) {
            snprintf(msg, msg_size, out->failed == 2 ? "more data than the image needs" :
                                                       "out of memory");
            return -1;
        }
    }
    if (r.n - r.pos < 4) {
        snprintf(msg, msg_size, "the zlib stream ends before its checksum");
        return -1;
    }
    adler = (uint32_t)r.in[r.pos] << 24 | (uint32_t)r.in[r.pos + 1] << 16 |
            (uint32_t)r.in[r.pos + 2] << 8 | r.in[r.pos + 3];
    if (adler != deflate_adler32(1, out->data + start, out->len - start)) {
        snprintf(msg, msg_size, "the data fails its Adler-32 checksum");
        return -1;
    }
    return 0;
}
