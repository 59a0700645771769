/* The block half of the deflate writer (tools/deflate.c holds the LZ77 half): a bit writer and one
 * block of LZ77 tokens written in the cheapest of the three block types of RFC 1951. */
#ifndef BEZSURF_TOOLS_DEFLATE_BLOCK_H
#define BEZSURF_TOOLS_DEFLATE_BLOCK_H

#include <stddef.h>
#include <stdint.h>

/* Bits packed least significant first into a growing buffer; failed is set once it cannot grow. */
typedef struct dfl_bits {
    unsigned char *buf;
    size_t n, cap;
    uint64_t acc; /* bits not yet in buf */
    int nacc;     /* how many */
    int failed;
} dfl_bits;

/* One LZ77 token: a literal byte (dist 0, value the byte) or a match (dist 1..32768, value its
 * length 3..258). */
typedef struct dfl_token {
    uint16_t value;
    uint16_t dist;
} dfl_token;

/* Write one block holding tokens t[0..nt) that encode the nraw source bytes raw (for a stored block,
 * if it is the smallest), final: the stream's last block. Then, if final, pad to a whole byte. */
void dfl_write_block(dfl_bits *b, const dfl_token *t, size_t nt, const unsigned char *raw, size_t nraw, int final);

#endif
