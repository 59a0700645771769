/* A small strict inflater (RFC 1951) for the tests, written apart from the tool's deflate writer:
 * stored, fixed and dynamic Huffman blocks, decoded by canonical code counts bit by bit. It refuses
 * over-subscribed codes, incomplete codes (but a single one-bit code), distances reaching before
 * the start, lengths over the output's room, and reads past the input. */
#ifndef BS_TEST_INFLATE_H
#define BS_TEST_INFLATE_H

#include <stddef.h>
#include <string.h>

typedef struct infl {
    const unsigned char *in;
    size_t in_n, in_pos;
    unsigned bitbuf, bitcnt;
    unsigned char *out;
    size_t out_cap, out_n;
    const char *err;
} infl;

typedef struct infl_huff {
    short count[16];  /* codes of each length */
    short symbol[320]; /* symbols in canonical order */
} infl_huff;

static unsigned infl_bits(infl *s, unsigned need)
{
    unsigned long val = s->bitbuf;
    while (s->bitcnt < need) {
        if (s->in_pos == s->in_n) {
            s->err = s->err ? s->err : "input ends inside the stream";
            return 0;
        }
        val |= (unsigned long)s->in[s->in_pos++] << s->bitcnt;
        s->bitcnt += 8;
    }
    s->bitbuf = (unsigned)(val >> need);
    s->bitcnt -= need;
    return (unsigned)(val & ((1UL << need) - 1));
}

/* Build the decoding table; 0 if the lengths make a complete code (or one code of one bit), else
 * the reason. */
static const char *infl_build(infl_huff *h, const unsigned char *len, int n)
{
    short offs[16];
    memset(h->count, 0, sizeof h->count);
    for (int i = 0; i < n; i++)
        h->count[len[i]]++;
    int used = n - h->count[0];
    long left = 1;
    for (int b = 1; b < 16; b++) {
        left = 2 * left - h->count[b];
        if (left < 0)
            return "over-subscribed code";
    }
    offs[1] = 0;
    for (int b = 1; b < 15; b++)
        offs[b + 1] = (short)(offs[b] + h->count[b]);
    for (int i = 0; i < n; i++)
        if (len[i] != 0)
            h->symbol[offs[len[i]]++] = (short)i;
    if (left > 0 && !(used == 1 && h->count[1] == 1))
        return "incomplete code";
    return NULL;
}

static int infl_decode(infl *s, const infl_huff *h)
{
    int code = 0, first = 0, index = 0;
    for (int b = 1; b < 16; b++) {
        code |= (int)infl_bits(s, 1);
        int count = h->count[b];
        if (code - count < first)
            return h->symbol[index + (code - first)];
        index += count;
        first = (first + count) << 1;
        code <<= 1;
    }
    s->err = s->err ? s->err : "no such code";
    return -1;
}

static const char *infl_codes(infl *s, const infl_huff *lit, const infl_huff *dist)
{
    static const short lbase[29] = {3,  4,  5,  6,  7,  8,  9,  10, 11,  13,  15,  17,  19,  23, 27,
                                    31, 35, 43, 51, 59, 67, 83, 99, 115, 131, 163, 195, 227, 258};
    static const short lext[29] = {0, 0, 0, 0, 0, 0, 0, 0, 1, 1, 1, 1, 2, 2, 2, 2, 3, 3, 3, 3, 4, 4, 4, 4, 5, 5, 5, 5, 0};
    static const unsigned short dbase[30] = {1,   2,   3,   4,   5,   7,    9,    13,   17,   25,
                                             33,  49,  65,  97,  129, 193,  257,  385,  513,  769,
                                             1025, 1537, 2049, 3073, 4097, 6145, 8193, 12289, 16385, 24577};
    static const short dext[30] = {0, 0, 0, 0, 1, 1, 2, 2, 3, 3, 4, 4, 5, 5, 6, 6, 7, 7, 8, 8, 9, 9, 10, 10, 11, 11, 12, 12, 13, 13};
    for (;;) {
        int sym = infl_decode(s, lit);
        if (s->err)
            return s->err;
        if (sym < 256) {
            if (s->out_n == s->out_cap)
                return "output longer than expected";
            s->out[s->out_n++] = (unsigned char)sym;
        } else if (sym == 256) {
            return NULL;
        } else {
            sym -= 257;
            if (sym >= 29)
                return "bad length symbol";
            size_t len = (size_t)lbase[sym] + infl_bits(s, (unsigned)lext[sym]);
            int ds = infl_decode(s, dist);
            if (s->err)
                return s->err;
            if (ds >= 30)
                return "bad distance symbol";
            size_t d = (size_t)dbase[ds] + infl_bits(s, (unsigned)dext[ds]);
            if (s->err)
                return s->err;
            if (d > s->out_n)
                return "distance before the start";
            if (len > s->out_cap - s->out_n)
                return "output longer than expected";
            for (size_t k = 0; k < len; k++, s->out_n++)
                s->out[s->out_n] = s->out[s->out_n - d];
        }
    }
}

static const char *infl_stored(infl *s)
{
    s->bitbuf = 0;
    s->bitcnt = 0;
    if (s->in_n - s->in_pos < 4)
        return "input ends inside a stored block";
    size_t len = (size_t)s->in[s->in_pos] | (size_t)s->in[s->in_pos + 1] << 8;
    size_t nlen = (size_t)s->in[s->in_pos + 2] | (size_t)s->in[s->in_pos + 3] << 8;
    s->in_pos += 4;
    if ((len ^ 0xFFFF) != nlen)
        return "LEN and NLEN disagree";
    if (len > s->in_n - s->in_pos)
        return "input ends inside a stored block";
    if (len > s->out_cap - s->out_n)
        return "output longer than expected";
    memcpy(s->out + s->out_n, s->in + s->in_pos, len);
    s->in_pos += len;
    s->out_n += len;
    return NULL;
}

static const char *infl_fixed(infl *s)
{
    unsigned char len[318];
    infl_huff lit, dist;
    for (int i = 0; i < 288; i++)
        len[i] = (unsigned char)(i < 144 ? 8 : i < 256 ? 9 : i < 280 ? 7 : 8);
    infl_build(&lit, len, 288);
    for (int i = 0; i < 30; i++)
        len[i] = 5;
    infl_build(&dist, len, 30); /* incomplete by design: codes 30, 31 are never sent */
    return infl_codes(s, &lit, &dist);
}

static const char *infl_dynamic(infl *s)
{
    static const short order[19] = {16, 17, 18, 0, 8, 7, 9, 6, 10, 5, 11, 4, 12, 3, 13, 2, 14, 1, 15};
    unsigned char len[320];
    infl_huff lencode, lit, dist;
    int nlen = (int)infl_bits(s, 5) + 257, ndist = (int)infl_bits(s, 5) + 1, ncode = (int)infl_bits(s, 4) + 4;
    if (s->err)
        return s->err;
    if (nlen > 286 || ndist > 30)
        return "too many length or distance codes";
    memset(len, 0, 19);
    for (int i = 0; i < ncode; i++)
        len[order[i]] = (unsigned char)infl_bits(s, 3);
    const char *why = infl_build(&lencode, len, 19);
    if (why)
        return why;
    for (int i = 0; i < nlen + ndist;) {
        int sym = infl_decode(s, &lencode);
        if (s->err)
            return s->err;
        if (sym < 16) {
            len[i++] = (unsigned char)sym;
            continue;
        }
        int rep, value = 0;
        if (sym == 16) {
            if (i == 0)
                return "repeat with no previous length";
            value = len[i - 1];
            rep = 3 + (int)infl_bits(s, 2);
        } else {
            rep = sym == 17 ? 3 + (int)infl_bits(s, 3) : 11 + (int)infl_bits(s, 7);
        }
        if (i + rep > nlen + ndist)
            return "too many lengths";
        while (rep-- > 0)
            len[i++] = (unsigned char)value;
    }
    if (len[256] == 0)
        return "no end-of-block code";
    if ((why = infl_build(&lit, len, nlen)) != NULL || (why = infl_build(&dist, len + nlen, ndist)) != NULL)
        return why;
    return infl_codes(s, &lit, &dist);
}

/* Inflate a raw deflate stream into out (room for cap bytes); *used receives the input bytes read
 * (through the end of the final block's last byte). NULL on success, else the reason. */
static const char *bs_inflate(const unsigned char *in, size_t in_n, unsigned char *out, size_t cap, size_t *out_n,
                              size_t *used)
{
    infl s = {in, in_n, 0, 0, 0, out, cap, 0, NULL};
    int last;
    do {
        last = (int)infl_bits(&s, 1);
        unsigned type = infl_bits(&s, 2);
        if (s.err)
            return s.err;
        const char *why = type == 0 ? infl_stored(&s) : type == 1 ? infl_fixed(&s) : type == 2 ? infl_dynamic(&s)
                                                                                              : "bad block type";
        if (why)
            return why;
    } while (!last);
    *out_n = s.out_n;
    *used = s.in_pos;
    return NULL;
}

#endif
