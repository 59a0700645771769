/* Deflate blocks (RFC 1951 section 3.2): see deflate_block.h. */
#include "deflate_block.h"

#include <stdlib.h>
#include <string.h>

#define NLIT 286   /* literal/length symbols used: 0..255, end of block 256, lengths 257..285 */
#define NLIT_ALL 288 /* with the two that are never sent but shape the fixed code */
#define NDIST 30   /* distance symbols */
#define NCL 19     /* code-length symbols */
#define MAXBITS 15 /* longest literal/length or distance code */

static const uint16_t len_base[29] = {3,  4,  5,  6,  7,  8,  9,  10, 11,  13,  15,  17,  19,  23, 27,
                                      31, 35, 43, 51, 59, 67, 83, 99, 115, 131, 163, 195, 227, 258};
static const uint8_t len_extra[29] = {0, 0, 0, 0, 0, 0, 0, 0, 1, 1, 1, 1, 2, 2, 2, 2, 3, 3, 3, 3, 4, 4, 4, 4, 5, 5, 5, 5, 0};
static const uint16_t dist_base[30] = {1,   2,   3,   4,   5,   7,    9,    13,   17,   25,   33,   49,   65,    97,    129,
                                       193, 257, 385, 513, 769, 1025, 1537, 2049, 3073, 4097, 6145, 8193, 12289, 16385, 24577};
static const uint8_t dist_extra[30] = {0, 0, 0, 0, 1, 1, 2, 2, 3, 3, 4, 4, 5, 5, 6, 6, 7, 7, 8, 8, 9, 9, 10, 10, 11, 11, 12, 12, 13, 13};
/* The order in which the code-length code's own lengths are sent. */
static const uint8_t cl_order[NCL] = {16, 17, 18, 0, 8, 7, 9, 6, 10, 5, 11, 4, 12, 3, 13, 2, 14, 1, 15};

static void put(dfl_bits *b, uint32_t bits, int n)
{
    b->acc |= (uint64_t)bits << b->nacc;
    b->nacc += n;
    while (b->nacc >= 8) {
        if (b->n == b->cap) {
            size_t cap = b->cap ? 2 * b->cap : 65536;
            unsigned char *g = b->failed ? NULL : realloc(b->buf, cap);
            if (g == NULL) {
                b->failed = 1;
                b->n = 0; /* keep counting nothing: the result is thrown away */
            } else {
                b->buf = g;
                b->cap = cap;
            }
        }
        if (!b->failed)
            b->buf[b->n++] = (unsigned char)b->acc;
        b->acc >>= 8;
        b->nacc -= 8;
    }
}

static void align(dfl_bits *b)
{
    if (b->nacc > 0)
        put(b, 0, 8 - b->nacc);
}

static int len_code(unsigned len)
{
    int c = 28;
    while (len_base[c] > len)
        c--;
    return c;
}

static int dist_code(unsigned dist)
{
    int lo = 0, hi = 29; /* the last base <= dist */
    while (lo < hi) {
        int mid = (lo + hi + 1) / 2;
        if (dist_base[mid] <= dist)
            lo = mid;
        else
            hi = mid - 1;
    }
    return lo;
}

/* Code lengths of at most limit bits for n symbols of the given frequencies: a Huffman tree, then
 * the lengths over the limit cut down and the Kraft sum restored by moving leaves down one level.
 * At least two symbols must have a non-zero frequency, so that the code is complete. */
static void huff_lengths(const uint32_t *freq, int n, int limit, uint8_t *len)
{
    int sym[NLIT], m = 0;
    for (int i = 0; i < n; i++) {
        len[i] = 0;
        if (freq[i] == 0)
            continue;
        int j = m++; /* insertion sort by frequency, ties by symbol */
        while (j > 0 && freq[sym[j - 1]] > freq[i]) {
            sym[j] = sym[j - 1];
            j--;
        }
        sym[j] = i;
    }
    /* Two queues: the sorted leaves and the inner nodes, which are made in increasing weight. */
    uint64_t w[2 * NLIT];
    int parent[2 * NLIT], depth[2 * NLIT];
    for (int i = 0; i < m; i++)
        w[i] = freq[sym[i]];
    int leaf = 0, inner = m;
    for (int next = m; next < 2 * m - 1; next++) {
        int pick[2];
        for (int k = 0; k < 2; k++)
            pick[k] = leaf < m && (inner == next || w[leaf] <= w[inner]) ? leaf++ : inner++;
        w[next] = w[pick[0]] + w[pick[1]];
        parent[pick[0]] = parent[pick[1]] = next;
    }
    int count[2 * NLIT + 1] = {0};
    depth[2 * m - 2] = 0;
    for (int i = 2 * m - 3; i >= 0; i--) /* a parent comes after its children */
        depth[i] = depth[parent[i]] + 1;
    for (int i = 0; i < m; i++)
        count[depth[i] > limit ? limit : depth[i]]++;
    uint32_t total = 0;
    for (int d = 1; d <= limit; d++)
        total += (uint32_t)count[d] << (limit - d);
    while (total > (1u << limit)) { /* one leaf off the last level, one node split into two */
        count[limit]--;
        for (int d = limit - 1; d > 0; d--)
            if (count[d] > 0) {
                count[d]--;
                count[d + 1] += 2;
                break;
            }
        total--;
    }
    int k = 0; /* the rarest symbols get the longest codes */
    for (int d = limit; d > 0; d--)
        for (int c = 0; c < count[d]; c++)
            len[sym[k++]] = (uint8_t)d;
}

/* Canonical codes (RFC 1951 3.2.2), bit-reversed since the writer sends the low bit first. */
static void huff_codes(const uint8_t *len, int n, uint16_t *code)
{
    int count[MAXBITS + 1] = {0};
    uint32_t next[MAXBITS + 2];
    for (int i = 0; i < n; i++)
        count[len[i]]++;
    count[0] = 0;
    next[1] = 0;
    for (int d = 1; d <= MAXBITS; d++)
        next[d + 1] = (next[d] + (uint32_t)count[d]) << 1;
    for (int i = 0; i < n; i++) {
        uint32_t c = len[i] ? next[len[i]]++ : 0, r = 0;
        for (int k = 0; k < len[i]; k++)
            r |= ((c >> k) & 1u) << (len[i] - 1 - k);
        code[i] = (uint16_t)r;
    }
}

/* Lengths for a tree that deflate decoders accept: at least two symbols get a code. */
static void tree_lengths(const uint32_t *freq, int n, int limit, uint8_t *len)
{
    uint32_t f[NLIT];
    int used = 0;
    for (int i = 0; i < n; i++)
        used += (f[i] = freq[i]) != 0;
    for (int i = 0; i < n && used < 2; i++)
        if (f[i] == 0) {
            f[i] = 1;
            used++;
        }
    huff_lengths(f, n, limit, len);
}

/* The literal/length and distance lengths as one run-length coded sequence (symbols 16, 17, 18). */
typedef struct cl_seq {
    uint8_t sym[NLIT + NDIST], extra[NLIT + NDIST];
    int n;
} cl_seq;

static void cl_encode(const uint8_t *lens, int total, cl_seq *s)
{
    s->n = 0;
    for (int i = 0; i < total;) {
        int run = 1;
        while (i + run < total && lens[i + run] == lens[i])
            run++;
        i += run;
        uint8_t v = lens[i - run];
        if (v != 0) {
            s->sym[s->n] = v;
            s->extra[s->n++] = 0;
            run--;
        }
        while (run >= 3) {
            int take = v != 0 ? (run > 6 ? 6 : run) : (run > 138 ? 138 : run);
            s->sym[s->n] = (uint8_t)(v != 0 ? 16 : take >= 11 ? 18 : 17);
            s->extra[s->n++] = (uint8_t)(take - (v != 0 ? 3 : take >= 11 ? 11 : 3));
            run -= take;
        }
        for (; run > 0; run--) {
            s->sym[s->n] = v;
            s->extra[s->n++] = 0;
        }
    }
}

static const uint8_t cl_extra_bits[NCL] = {0, 0, 0, 0, 0, 0, 0, 0, 0, 0, 0, 0, 0, 0, 0, 0, 2, 3, 7};

/* Everything a block needs to be written in either Huffman form. */
typedef struct block_plan {
    uint32_t lfreq[NLIT], dfreq[NDIST], cfreq[NCL];
    uint8_t llen[NLIT_ALL], dlen[NDIST], clen[NCL];
    int hlit, hdist, hclen;
    cl_seq seq;
} block_plan;

/* Bits of the tokens (with the end of block) under the given lengths. */
static uint64_t token_bits(const block_plan *p, const uint8_t *llen, const uint8_t *dlen)
{
    uint64_t bits = 0;
    for (int i = 0; i < NLIT; i++)
        bits += (uint64_t)p->lfreq[i] * (uint64_t)(llen[i] + (i >= 257 ? len_extra[i - 257] : 0));
    for (int i = 0; i < NDIST; i++)
        bits += (uint64_t)p->dfreq[i] * (uint64_t)(dlen[i] + dist_extra[i]);
    return bits;
}

static uint64_t plan_dynamic(const dfl_token *t, size_t nt, block_plan *p)
{
    memset(p->lfreq, 0, sizeof p->lfreq);
    memset(p->dfreq, 0, sizeof p->dfreq);
    memset(p->cfreq, 0, sizeof p->cfreq);
    for (size_t i = 0; i < nt; i++) {
        if (t[i].dist == 0) {
            p->lfreq[t[i].value]++;
        } else {
            p->lfreq[257 + len_code(t[i].value)]++;
            p->dfreq[dist_code(t[i].dist)]++;
        }
    }
    p->lfreq[256] = 1;
    tree_lengths(p->lfreq, NLIT, MAXBITS, p->llen);
    p->llen[286] = p->llen[287] = 0;
    tree_lengths(p->dfreq, NDIST, MAXBITS, p->dlen);
    for (p->hlit = NLIT; p->llen[p->hlit - 1] == 0; p->hlit--) {
    }
    for (p->hdist = NDIST; p->hdist > 1 && p->dlen[p->hdist - 1] == 0; p->hdist--) {
    }
    uint8_t lens[NLIT + NDIST];
    memcpy(lens, p->llen, (size_t)p->hlit);
    memcpy(lens + p->hlit, p->dlen, (size_t)p->hdist);
    cl_encode(lens, p->hlit + p->hdist, &p->seq);
    for (int i = 0; i < p->seq.n; i++)
        p->cfreq[p->seq.sym[i]]++;
    tree_lengths(p->cfreq, NCL, 7, p->clen);
    for (p->hclen = NCL; p->hclen > 4 && p->clen[cl_order[p->hclen - 1]] == 0; p->hclen--) {
    }
    uint64_t bits = 5 + 5 + 4 + 3 * (uint64_t)p->hclen;
    for (int i = 0; i < NCL; i++)
        bits += (uint64_t)p->cfreq[i] * (p->clen[i] + cl_extra_bits[i]);
    return bits + token_bits(p, p->llen, p->dlen);
}

static void fixed_lengths(uint8_t *llen, uint8_t *dlen)
{
    for (int i = 0; i < NLIT_ALL; i++)
        llen[i] = i < 144 ? 8 : i < 256 ? 9 : i < 280 ? 7 : 8;
    for (int i = 0; i < NDIST; i++)
        dlen[i] = 5;
}

static void write_tokens(dfl_bits *b, const dfl_token *t, size_t nt, const uint8_t *llen, const uint8_t *dlen)
{
    uint16_t lcode[NLIT_ALL], dcode[NDIST];
    huff_codes(llen, NLIT_ALL, lcode);
    huff_codes(dlen, NDIST, dcode);
    for (size_t i = 0; i < nt; i++) {
        if (t[i].dist == 0) {
            put(b, lcode[t[i].value], llen[t[i].value]);
            continue;
        }
        int lc = len_code(t[i].value), dc = dist_code(t[i].dist);
        put(b, lcode[257 + lc], llen[257 + lc]);
        put(b, t[i].value - len_base[lc], len_extra[lc]);
        put(b, dcode[dc], dlen[dc]);
        put(b, t[i].dist - dist_base[dc], dist_extra[dc]);
    }
    put(b, lcode[256], llen[256]);
}

static void write_stored(dfl_bits *b, const unsigned char *raw, size_t nraw, int final)
{
    size_t off = 0;
    do {
        size_t len = nraw - off < 65535 ? nraw - off : 65535;
        put(b, final && off + len == nraw ? 1u : 0u, 3); /* BFINAL, BTYPE 00 */
        align(b);
        put(b, (uint32_t)len, 16);
        put(b, (uint32_t)len ^ 0xffffu, 16);
        for (size_t i = 0; i < len; i++)
            put(b, raw[off + i], 8);
        off += len;
    } while (off < nraw);
}

void dfl_write_block(dfl_bits *b, const dfl_token *t, size_t nt, const unsigned char *raw, size_t nraw, int final)
{
    block_plan *p = malloc(sizeof *p);
    if (p == NULL) {
        b->failed = 1;
        return;
    }
    uint64_t dyn = plan_dynamic(t, nt, p);
    uint8_t fl[NLIT_ALL], fd[NDIST];
    fixed_lengths(fl, fd);
    uint64_t fixed = token_bits(p, fl, fd);
    uint64_t stored = 8 * (uint64_t)nraw + (42 * (uint64_t)(nraw / 65535 + 1)); /* header, padding, LEN, NLEN */
    if (stored < dyn && stored < fixed) {
        write_stored(b, raw, nraw, final);
    } else if (fixed <= dyn) {
        put(b, final ? 1u : 0u, 1);
        put(b, 1, 2); /* BTYPE 01 */
        write_tokens(b, t, nt, fl, fd);
    } else {
        put(b, final ? 1u : 0u, 1);
        put(b, 2, 2); /* BTYPE 10 */
        put(b, (uint32_t)(p->hlit - 257), 5);
        put(b, (uint32_t)(p->hdist - 1), 5);
        put(b, (uint32_t)(p->hclen - 4), 4);
        for (int i = 0; i < p->hclen; i++)
            put(b, p->clen[cl_order[i]], 3);
        uint16_t ccode[NCL];
        huff_codes(p->clen, NCL, ccode);
        for (int i = 0; i < p->seq.n; i++) {
            int s = p->seq.sym[i];
            put(b, ccode[s], p->clen[s]);
            put(b, p->seq.extra[i], cl_extra_bits[s]);
        }
        write_tokens(b, t, nt, p->llen, p->dlen);
    }
    if (final)
        align(b);
    free(p);
}
