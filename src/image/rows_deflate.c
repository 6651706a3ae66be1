/* rows_deflate.c - deflate (RFC 1951) for rendered images, several times
 * as fast as zlib's fastest level at about its size.
 *
 * zlib's level 1 took about 30 ms of processor time for a 1000 x 1000
 * render's PNG: a general compressor, it looks for matches through hash
 * chains, byte by byte, and codes them through its own buffers. A
 * rendered image, Up-filtered, is mostly of two things: runs (a flat area
 * repeats the pixel to its left, or filters to zeros) and literals whose
 * values are few (small differences). So here a match is looked for in
 * three places only: a run of the byte before, a run of the pixel before
 * (both found eight bytes at a time), and the last place the next four
 * bytes were seen (one probe of a hash table, no chain). The symbols of
 * each block of at most 65,535 bytes get their own Huffman codes, or the
 * block is stored as it is when that would be smaller. */
#include <stdint.h>
#include <stdlib.h>
#include <string.h>
#include "image/rows_deflate.h"

#define BLOCK_MAX 65535  /* input bytes a block: a stored block's most */
#define MIN_MATCH 4      /* shorter matches cost about what their literals do */
#define MAX_MATCH 258
#define WINDOW 32768     /* the farthest deflate refers back */
#define HASH_BITS 12
#define LITLEN_CODES 286
#define DIST_CODES 30
#define LENGTHS_CODES 19 /* the alphabet the code lengths are written in */
#define END_OF_BLOCK 256
/* Symbols of a block: each but the last ends with a match of at least 3
 * bytes (a long run is cut into pieces of 3 to 258). */
#define TOKENS_MAX (BLOCK_MAX / 3 + 2)

/* Literals, then a match (length 0: none). */
typedef struct token {
    uint32_t literals;
    uint16_t length, distance;
} token;

struct rows_deflater {
    token tokens[TOKENS_MAX];
    uint32_t litlen_freq[LITLEN_CODES], dist_freq[DIST_CODES];
    uint8_t litlen_len[LITLEN_CODES], dist_len[DIST_CODES];
    uint16_t litlen_code[LITLEN_CODES], dist_code[DIST_CODES];
    uint32_t last_seen[1 << HASH_BITS]; /* a 4-byte string's last position + 1, 0: none */
};

rows_deflater *rows_deflater_new(void)
{
    return malloc(sizeof(rows_deflater));
}

void rows_deflater_free(rows_deflater *d)
{
    free(d);
}

size_t rows_deflate_bound(size_t n)
{
    /* Each block is at most stored: 5 bytes and its input, and a partial
     * byte before; then the sync flush's empty stored block. */
    return n + 6 * (n / BLOCK_MAX + 2) + 16;
}

/* Bytes little-endian, as deflate's bits are packed. */
static inline uint64_t load64(const unsigned char *p)
{
    uint64_t v;
    memcpy(&v, p, sizeof v);
#if __BYTE_ORDER__ == __ORDER_BIG_ENDIAN__
    v = __builtin_bswap64(v);
#endif
    return v;
}

static inline uint32_t load32(const unsigned char *p)
{
    uint32_t v;
    memcpy(&v, p, sizeof v);
    return v;
}

/* How far the bytes at a and b agree, from 0 up to `most`. */
static inline size_t agreement(const unsigned char *a, const unsigned char *b, size_t most)
{
    size_t n = 0;
    while (n + 8 <= most) {
        uint64_t x = load64(a + n) ^ load64(b + n);
        if (x)
            return n + (size_t)__builtin_ctzll(x) / 8;
        n += 8;
    }
    while (n < most && a[n] == b[n])
        n++;
    return n;
}

/* ---- Codes ---- */

typedef struct leaf {
    uint32_t freq;
    int symbol;
} leaf;

static int leaf_order(const void *a, const void *b)
{
    const leaf *x = a, *y = b;
    if (x->freq != y->freq)
        return x->freq < y->freq ? -1 : 1;
    return x->symbol - y->symbol;
}

/* Huffman code lengths of at most `limit` bits for the n symbols of
 * counts freq, into len (0 for a symbol not used). At least two symbols
 * get a code (deflate's decoders want complete codes): unused ones are
 * counted once if need be. Too deep a tree is rebuilt from halved counts,
 * which flattens it. */
static void code_lengths(const uint32_t *freq, int n, int limit, uint8_t *len)
{
    leaf leaves[LITLEN_CODES];
    int used = 0;
    for (int s = 0; s < n; s++)
        if (freq[s])
            leaves[used++] = (leaf){freq[s], s};
    for (int s = 0; used < 2; s++)
        if (!freq[s])
            leaves[used++] = (leaf){1, s};
    memset(len, 0, (size_t)n);
    int parent[2 * LITLEN_CODES];
    uint32_t weight[2 * LITLEN_CODES];
    int depth[2 * LITLEN_CODES];
    for (;;) {
        qsort(leaves, (size_t)used, sizeof leaves[0], leaf_order);
        /* Two queues: the leaves in order, and the joined nodes (ids from
         * `used` on), which come out in order of weight too. */
        for (int k = 0; k < used; k++)
            weight[k] = leaves[k].freq;
        int next_leaf = 0, next_node = used, nodes = used;
        for (int joined = 0; joined < used - 1; joined++) {
            int pick[2];
            for (int j = 0; j < 2; j++) {
                bool take_leaf = next_leaf < used && (next_node == nodes || weight[next_leaf] <= weight[next_node]);
                pick[j] = take_leaf ? next_leaf++ : next_node++;
            }
            weight[nodes] = weight[pick[0]] + weight[pick[1]];
            parent[pick[0]] = parent[pick[1]] = nodes++;
        }
        int root = nodes - 1, deepest = 0;
        depth[root] = 0;
        for (int k = root - 1; k >= 0; k--) {
            depth[k] = depth[parent[k]] + 1;
            deepest = depth[k] > deepest ? depth[k] : deepest;
        }
        if (deepest <= limit) {
            for (int k = 0; k < used; k++)
                len[leaves[k].symbol] = (uint8_t)depth[k];
            return;
        }
        for (int k = 0; k < used; k++)
            leaves[k].freq = leaves[k].freq >> 1 | 1;
    }
}

/* The canonical codes of lengths len (RFC 1951 3.2.2), bits reversed: deflate
 * sends a code's first bit first, and bits go out from the low end. */
static void canonical_codes(const uint8_t *len, int n, uint16_t *code)
{
    int count[16] = {0};
    uint16_t next[16];
    for (int s = 0; s < n; s++)
        count[len[s]]++;
    count[0] = 0;
    int c = 0;
    for (int bits = 1; bits < 16; bits++) {
        c = (c + count[bits - 1]) << 1;
        next[bits] = (uint16_t)c;
    }
    for (int s = 0; s < n; s++) {
        if (!len[s])
            continue;
        unsigned v = next[len[s]]++, r = 0;
        for (int b = 0; b < len[s]; b++)
            r |= (v >> b & 1) << (len[s] - 1 - b);
        code[s] = (uint16_t)r;
    }
}

/* The extra bits after length symbol s (257 to 285), and after distance
 * code c: what RFC 1951's tables give, as formulas. */
static inline int length_extra_bits(int s) { return s >= 265 && s < 285 ? (s - 261) / 4 : 0; }
static inline int distance_extra_bits(int c) { return c >= 4 ? c / 2 - 1 : 0; }

/* A match length's symbol, and the value of its extra bits. */
static inline int length_symbol(unsigned length, unsigned *extra)
{
    *extra = 0;
    if (length <= 10)
        return 257 + (int)length - 3;
    if (length == MAX_MATCH)
        return 285;
    unsigned m = length - 3;
    int e = 31 - __builtin_clz(m) - 2;
    *extra = m & ((1u << e) - 1);
    return 261 + 4 * e + (int)(m >> e & 3);
}

/* A distance's code, and the value of its extra bits. */
static inline int distance_code(unsigned distance, unsigned *extra)
{
    *extra = 0;
    if (distance <= 4)
        return (int)distance - 1;
    unsigned m = distance - 1;
    int e = 31 - __builtin_clz(m) - 1;
    *extra = m & ((1u << e) - 1);
    return 2 * e + 2 + (int)(m >> e & 1);
}

/* ---- Bits ---- */

typedef struct bit_writer {
    uint64_t buffer;
    int count;               /* bits in buffer, below 32 between calls */
    unsigned char *out;
} bit_writer;

/* Sends the n (at most 32) low bits of v, low bit first. */
static inline void put_bits(bit_writer *w, uint64_t v, int n)
{
    w->buffer |= v << w->count;
    w->count += n;
    if (w->count >= 32) {
        uint32_t word = (uint32_t)w->buffer;
#if __BYTE_ORDER__ == __ORDER_BIG_ENDIAN__
        word = __builtin_bswap32(word);
#endif
        memcpy(w->out, &word, 4);
        w->out += 4;
        w->buffer >>= 32;
        w->count -= 32;
    }
}

/* Pads to a byte boundary with zero bits and writes out every whole byte. */
static void align_bytes(bit_writer *w)
{
    w->count = (w->count + 7) & ~7;
    while (w->count > 0) {
        *w->out++ = (unsigned char)w->buffer;
        w->buffer >>= 8;
        w->count -= 8;
    }
    w->buffer = 0;
    w->count = 0;
}

/* A stored block of the n bytes at p (n up to BLOCK_MAX). */
static void put_stored(bit_writer *w, const unsigned char *p, size_t n, bool last)
{
    put_bits(w, last, 3); /* BFINAL, BTYPE 00 */
    align_bytes(w);
    unsigned char head[4] = {(unsigned char)n, (unsigned char)(n >> 8), (unsigned char)~n, (unsigned char)(~n >> 8)};
    memcpy(w->out, head, 4);
    if (n > 0)
        memcpy(w->out + 4, p, n);
    w->out += 4 + n;
}

/* ---- Blocks ---- */

/* The block's code lengths as written in its header: run-length coded in
 * the 19-symbol alphabet (16: the previous length 3 to 6 more times; 17,
 * 18: 3 to 10, 11 to 138 zeros), each symbol with its extra bits. */
typedef struct header {
    int litlen_count, dist_count, lengths_count;
    uint8_t symbol[LITLEN_CODES + DIST_CODES], extra[LITLEN_CODES + DIST_CODES];
    int symbols;
    uint32_t freq[LENGTHS_CODES];
    uint8_t len[LENGTHS_CODES];
    uint16_t code[LENGTHS_CODES];
} header;

static const uint8_t lengths_order[LENGTHS_CODES] = {16, 17, 18, 0, 8, 7, 9, 6, 10, 5, 11, 4, 12, 3, 13, 2, 14, 1, 15};
static const uint8_t lengths_extra_bits[LENGTHS_CODES] = {[16] = 2, [17] = 3, [18] = 7};

static void header_add(header *h, int symbol, int extra)
{
    h->symbol[h->symbols] = (uint8_t)symbol;
    h->extra[h->symbols++] = (uint8_t)extra;
    h->freq[symbol]++;
}

/* Describes d's code lengths as h; returns the header's size in bits. */
static uint64_t header_plan(const rows_deflater *d, header *h)
{
    memset(h, 0, sizeof *h);
    h->litlen_count = LITLEN_CODES;
    while (h->litlen_count > 257 && !d->litlen_len[h->litlen_count - 1])
        h->litlen_count--;
    h->dist_count = DIST_CODES;
    while (h->dist_count > 1 && !d->dist_len[h->dist_count - 1])
        h->dist_count--;
    uint8_t all[LITLEN_CODES + DIST_CODES];
    int total = h->litlen_count + h->dist_count;
    memcpy(all, d->litlen_len, (size_t)h->litlen_count);
    memcpy(all + h->litlen_count, d->dist_len, (size_t)h->dist_count);
    for (int i = 0; i < total;) {
        int v = all[i], run = 1;
        while (i + run < total && all[i + run] == v)
            run++;
        i += run;
        if (v == 0) {
            for (; run >= 11; run -= run < 138 ? run : 138)
                header_add(h, 18, (run < 138 ? run : 138) - 11);
            if (run >= 3)
                header_add(h, 17, run - 3);
            else
                while (run-- > 0)
                    header_add(h, 0, 0);
            continue;
        }
        header_add(h, v, 0);
        for (run--; run >= 3; run -= run < 6 ? run : 6)
            header_add(h, 16, (run < 6 ? run : 6) - 3);
        while (run-- > 0)
            header_add(h, v, 0);
    }
    code_lengths(h->freq, LENGTHS_CODES, 7, h->len);
    canonical_codes(h->len, LENGTHS_CODES, h->code);
    h->lengths_count = LENGTHS_CODES;
    while (h->lengths_count > 4 && !h->len[lengths_order[h->lengths_count - 1]])
        h->lengths_count--;
    uint64_t bits = 3 + 5 + 5 + 4 + 3 * (uint64_t)h->lengths_count;
    for (int s = 0; s < LENGTHS_CODES; s++)
        bits += (uint64_t)h->freq[s] * (h->len[s] + lengths_extra_bits[s]);
    return bits;
}

static void put_header(bit_writer *w, const header *h, bool last)
{
    put_bits(w, (last ? 1 : 0) | 2 << 1, 3); /* BFINAL, BTYPE 10: dynamic codes */
    put_bits(w, (unsigned)(h->litlen_count - 257), 5);
    put_bits(w, (unsigned)(h->dist_count - 1), 5);
    put_bits(w, (unsigned)(h->lengths_count - 4), 4);
    for (int k = 0; k < h->lengths_count; k++)
        put_bits(w, h->len[lengths_order[k]], 3);
    for (int k = 0; k < h->symbols; k++) {
        int s = h->symbol[k];
        put_bits(w, h->code[s], h->len[s]);
        put_bits(w, h->extra[k], lengths_extra_bits[s]);
    }
}

/* Finds the symbols of the block from `start` to `end` of in (no more
 * than BLOCK_MAX bytes): counts them into d's frequencies and returns the
 * tokens. Matches end within the block, so that it can be stored whole. */
static int find_tokens(rows_deflater *d, const unsigned char *in, size_t start, size_t end, int pixel_bytes)
{
    int tokens = 0;
    size_t from = start; /* the first literal not yet in a token */
    size_t i = start > (size_t)pixel_bytes ? start : (size_t)pixel_bytes;
    while (i + 8 <= end) {
        uint64_t here = load64(in + i);
        size_t length = 0, distance = 0;
        /* Runs: the bytes agree with the byte, or the pixel, before. */
        if (!((here ^ load64(in + i - 1)) & 0xffffffffu)) {
            length = 4 + agreement(in + i + 4, in + i + 3, end - i - 4);
            distance = 1;
        }
        if (!((here ^ load64(in + i - pixel_bytes)) & 0xffffffffu)) {
            size_t n = 4 + agreement(in + i + 4, in + i + 4 - pixel_bytes, end - i - 4);
            if (n > length) {
                length = n;
                distance = (size_t)pixel_bytes;
            }
        }
        uint32_t key = (uint32_t)here, slot = (key * 2654435761u) >> (32 - HASH_BITS);
        if (!length) {
            size_t seen = d->last_seen[slot];
            if (seen && i - (seen - 1) <= WINDOW && load32(in + seen - 1) == load32(in + i)) {
                length = 4 + agreement(in + i + 4, in + seen - 1 + 4, end - i - 4);
                distance = i - (seen - 1);
            }
        }
        d->last_seen[slot] = (uint32_t)i + 1;
        if (!length) {
            i++;
            continue;
        }
        for (size_t k = from; k < i; k++)
            d->litlen_freq[in[k]]++;
        unsigned ignored; /* the extra bits' values, found again as the block is written */
        int dcode = distance_code((unsigned)distance, &ignored);
        /* Pieces of 3 to 258 bytes. */
        size_t literals = i - from;
        for (size_t left = length; left >= 3;) {
            size_t piece = left <= MAX_MATCH ? left : left - MAX_MATCH >= 3 ? MAX_MATCH : left - 3;
            d->litlen_freq[length_symbol((unsigned)piece, &ignored)]++;
            d->dist_freq[dcode]++;
            d->tokens[tokens++] = (token){(uint32_t)literals, (uint16_t)piece, (uint16_t)distance};
            literals = 0;
            left -= piece;
        }
        i += length;
        from = i;
    }
    for (size_t k = from; k < end; k++)
        d->litlen_freq[in[k]]++;
    d->tokens[tokens++] = (token){(uint32_t)(end - from), 0, 0};
    return tokens;
}

/* Writes the block of bytes from `start` to `end` of in, whose tokens d
 * holds, in its own codes or stored, whichever is smaller. */
static void put_block(bit_writer *w, rows_deflater *d, const unsigned char *in, size_t start, size_t end, int tokens,
                      bool last)
{
    d->litlen_freq[END_OF_BLOCK] = 1;
    code_lengths(d->litlen_freq, LITLEN_CODES, 15, d->litlen_len);
    code_lengths(d->dist_freq, DIST_CODES, 15, d->dist_len);
    header h;
    uint64_t bits = header_plan(d, &h);
    for (int s = 0; s < LITLEN_CODES; s++)
        bits += (uint64_t)d->litlen_freq[s] * (d->litlen_len[s] + length_extra_bits(s));
    for (int c = 0; c < DIST_CODES; c++)
        bits += (uint64_t)d->dist_freq[c] * (d->dist_len[c] + distance_extra_bits(c));
    if (bits >= 3 + 7 + 32 + 8 * (uint64_t)(end - start)) {
        put_stored(w, in + start, end - start, last);
        return;
    }
    canonical_codes(d->litlen_len, LITLEN_CODES, d->litlen_code);
    canonical_codes(d->dist_len, DIST_CODES, d->dist_code);
    put_header(w, &h, last);
    const unsigned char *p = in + start;
    for (int t = 0; t < tokens; t++) {
        const token *k = &d->tokens[t];
        for (uint32_t j = 0; j < k->literals; j++, p++)
            put_bits(w, d->litlen_code[*p], d->litlen_len[*p]);
        if (!k->length)
            continue;
        unsigned lextra, dextra;
        int symbol = length_symbol(k->length, &lextra), dcode = distance_code(k->distance, &dextra);
        put_bits(w, d->litlen_code[symbol] | (uint64_t)lextra << d->litlen_len[symbol],
                 d->litlen_len[symbol] + length_extra_bits(symbol));
        put_bits(w, d->dist_code[dcode] | (uint64_t)dextra << d->dist_len[dcode],
                 d->dist_len[dcode] + distance_extra_bits(dcode));
        p += k->length;
    }
    put_bits(w, d->litlen_code[END_OF_BLOCK], d->litlen_len[END_OF_BLOCK]);
}

size_t rows_deflate(rows_deflater *d, const unsigned char *in, size_t n, int pixel_bytes, bool final,
                    unsigned char *out)
{
    bit_writer w = {0, 0, out};
    memset(d->last_seen, 0, sizeof d->last_seen);
    for (size_t start = 0; start < n;) {
        size_t end = n - start > BLOCK_MAX ? start + BLOCK_MAX : n;
        memset(d->litlen_freq, 0, sizeof d->litlen_freq);
        memset(d->dist_freq, 0, sizeof d->dist_freq);
        int tokens = find_tokens(d, in, start, end, pixel_bytes);
        put_block(&w, d, in, start, end, tokens, final && end == n);
        start = end;
    }
    if (n == 0 || !final)
        put_stored(&w, NULL, 0, final); /* an empty last block, or the sync flush */
    else
        align_bytes(&w);
    return (size_t)(w.out - out);
}
