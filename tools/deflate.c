/* Deflate, the LZ77 half (see deflate.h): matches found through hash chains over the last 32 KiB,
 * one step of lazy evaluation as zlib does it, tokens handed to deflate_block.c block by block. */
#include "deflate.h"
#include "deflate_block.h"

#include <stdint.h>
#include <stdlib.h>

#define WSIZE 32768u          /* the window: the farthest a match may reach back */
#define HBITS 15              /* hash of the next three bytes */
#define MIN_MATCH 3
#define MAX_MATCH 258
#define MAX_CHAIN 128         /* candidates tried per position */
#define NICE_MATCH 128        /* a match this long is taken without looking further */
#define TOO_FAR 4096          /* a three-byte match farther back costs more than its literals */
#define BLOCK_TOKENS 32768    /* tokens per block: the codes follow the data's changes */

typedef struct lz {
    const unsigned char *s;
    size_t n;
    size_t *head; /* 1 + the last position with each hash, 0 for none */
    size_t *prev; /* 1 + the previous position with the same hash, by position mod WSIZE */
    dfl_token *tok;
    size_t ntok, block_start, done; /* the block's tokens cover s[block_start..done) */
    dfl_bits out;
} lz;

static uint32_t hash3(const unsigned char *p)
{
    return (((uint32_t)p[0] << 16 | (uint32_t)p[1] << 8 | p[2]) * 2654435761u) >> (32 - HBITS);
}

static void insert(lz *z, size_t p)
{
    if (p + MIN_MATCH > z->n)
        return;
    uint32_t h = hash3(z->s + p);
    z->prev[p % WSIZE] = z->head[h];
    z->head[h] = p + 1;
}

/* The longest earlier match of s[p..] within the window (0 if none of MIN_MATCH bytes), by the
 * chain of positions sharing the hash of s[p..p+3). */
static size_t longest_match(const lz *z, size_t p, size_t *dist)
{
    if (p + MIN_MATCH > z->n)
        return 0;
    size_t best = 0, max = z->n - p < MAX_MATCH ? z->n - p : MAX_MATCH;
    const unsigned char *s = z->s;
    size_t cand = z->head[hash3(s + p)];
    for (int chain = MAX_CHAIN; cand != 0 && chain > 0; chain--) {
        size_t c = cand - 1;
        if (p - c > WSIZE)
            break;
        if (s[c + best] == s[p + best]) { /* cannot beat best otherwise */
            size_t l = 0;
            while (l < max && s[c + l] == s[p + l])
                l++;
            if (l > best) {
                best = l;
                *dist = p - c;
                if (l >= NICE_MATCH || l == max)
                    break;
            }
        }
        cand = z->prev[c % WSIZE];
    }
    if (best < MIN_MATCH || (best == MIN_MATCH && *dist > TOO_FAR))
        return 0;
    return best;
}

static void flush(lz *z, int final)
{
    dfl_write_block(&z->out, z->tok, z->ntok, z->n ? z->s + z->block_start : NULL, z->done - z->block_start, final);
    z->ntok = 0;
    z->block_start = z->done;
}

static void emit(lz *z, size_t value, size_t dist, size_t covered)
{
    z->tok[z->ntok].value = (uint16_t)value;
    z->tok[z->ntok].dist = (uint16_t)dist;
    z->ntok++;
    z->done += covered;
    if (z->ntok == BLOCK_TOKENS)
        flush(z, 0);
}

unsigned char *deflate_compress(const unsigned char *src, size_t n, size_t *out_n)
{
    lz z = {src, n, calloc((size_t)1 << HBITS, sizeof(size_t)), calloc(WSIZE, sizeof(size_t)),
            malloc(BLOCK_TOKENS * sizeof(dfl_token)), 0, 0, 0, {NULL, 0, 0, 0, 0, 0}};
    if (z.head == NULL || z.prev == NULL || z.tok == NULL)
        z.out.failed = 1;
    /* At each position the match found there is held back one step: if the next position has a
     * longer one, the byte goes out as a literal instead. */
    size_t p = 0, prev_len = 0, prev_dist = 0;
    int held = 0;
    while (!z.out.failed && p < n) {
        size_t len = 0, dist = 0;
        if (!held || prev_len < NICE_MATCH)
            len = longest_match(&z, p, &dist);
        insert(&z, p);
        if (held && prev_len >= MIN_MATCH && len <= prev_len) {
            size_t end = p - 1 + prev_len; /* the match starts at p - 1; p - 1 and p are in the chains */
            for (size_t q = p + 1; q < end; q++)
                insert(&z, q);
            emit(&z, prev_len, prev_dist, prev_len);
            p = end;
            held = 0;
            continue;
        }
        if (held)
            emit(&z, src[p - 1], 0, 1);
        held = 1;
        prev_len = len;
        prev_dist = dist;
        p++;
    }
    if (held && !z.out.failed)
        emit(&z, src[n - 1], 0, 1);
    if (!z.out.failed)
        flush(&z, 1);
    free(z.head);
    free(z.prev);
    free(z.tok);
    if (z.out.failed) {
        free(z.out.buf);
        return NULL;
    }
    *out_n = z.out.n;
    return z.out.buf;
}
