/* The tool's deflate writer (tools/deflate.c, compiled in), decoded by the tests' own inflater
 * (tests/support/inflate.h): exact round trips of empty, tiny, random, run-length, repetitive and
 * skewed data, data that changes kind from block to block, matches reaching the whole 32 KiB
 * window, and bounds on the size that follow from the format (stored blocks cost 5 bytes per 65535;
 * a run costs at most a few bits per 258 bytes). */
#include "harness.h"
#include "inflate.h"
#include "deflate.h"

#include <stdlib.h>

/* Compress, inflate, compare; returns the compressed size (0 if anything failed). */
static size_t round_trip(const char *what, const unsigned char *src, size_t n)
{
    size_t zn = 0, got = 0, used = 0;
    unsigned char *z = deflate_compress(src, n, &zn);
    CHECKF(z != NULL, "%s: compression failed", what);
    if (z == NULL)
        return 0;
    unsigned char *back = malloc(n + 1);
    const char *why = bs_inflate(z, zn, back, n + 1, &got, &used);
    CHECKF(why == NULL, "%s (%zu bytes): %s", what, n, why ? why : "");
    CHECKF(why != NULL || (got == n && (n == 0 || memcmp(back, src, n) == 0)), "%s: %zu bytes back, %zu in", what,
           got, n);
    CHECKF(why != NULL || used == zn, "%s: %zu of %zu bytes used", what, used, zn);
    free(back);
    free(z);
    return why == NULL ? zn : 0;
}

int main(void)
{
    unsigned long long seed = 11;
    size_t big = 300000;
    unsigned char *buf = malloc(big);

    CHECK(round_trip("empty", NULL, 0) > 0);
    buf[0] = 'x';
    CHECK(round_trip("one byte", buf, 1) > 0);

    for (size_t n = 0; n <= 600; n += 7) { /* short inputs of a small alphabet, every length class */
        for (size_t i = 0; i < n; i++)
            buf[i] = (unsigned char)('a' + (bs_test_rand_u64(&seed) >> 62));
        CHECK(round_trip("short", buf, n) > 0);
    }

    for (size_t i = 0; i < big; i++)
        buf[i] = (unsigned char)(bs_test_rand_u64(&seed) >> 56);
    size_t zn = round_trip("random", buf, big);
    /* random bytes do not compress: stored blocks, which cost 5 bytes each */
    CHECKF(zn > 0 && zn <= big + big / 1000, "random: %zu bytes", zn);

    memset(buf, 0, big);
    zn = round_trip("zeros", buf, big);
    CHECKF(zn > 0 && zn < big / 200, "zeros: %zu bytes", zn);

    for (size_t i = 0; i < big; i++) /* runs of random lengths and values */
        buf[i] = i == 0 || (bs_test_rand_u64(&seed) >> 58) != 0 ? (i ? buf[i - 1] : 0)
                                                                 : (unsigned char)(bs_test_rand_u64(&seed) >> 56);
    CHECK(round_trip("runs", buf, big) > 0);

    /* Four letters: 2 bits each with Huffman codes alone, 7 to 9 with the fixed code (short matches
     * in random letters cost a little more than their literals: 2.4 bits is allowed). */
    for (size_t i = 0; i < big; i++)
        buf[i] = (unsigned char)("ACGT"[bs_test_rand_u64(&seed) >> 62]);
    zn = round_trip("four letters", buf, big);
    CHECKF(zn > 0 && zn < big * 3 / 10, "four letters: %zu bytes", zn);

    /* 32768 random bytes then the same again: the copy lies at exactly the window's reach */
    for (size_t i = 0; i < 32768; i++)
        buf[i] = buf[i + 32768] = (unsigned char)(bs_test_rand_u64(&seed) >> 56);
    zn = round_trip("window", buf, 65536);
    CHECKF(zn > 0 && zn < 32768 + 2000, "window: %zu bytes", zn);

    /* Skewed letters (frequencies of Fibonacci numbers), whose Huffman tree is deeper than 15. */
    size_t fib[26] = {1, 1}, n = 0;
    for (int k = 2; k < 26; k++)
        fib[k] = fib[k - 1] + fib[k - 2];
    for (int k = 0; k < 26 && n < big; k++)
        for (size_t c = 0; c < fib[k] && n < big; c++)
            buf[n++] = (unsigned char)('A' + k);
    for (size_t i = n - 1; i > 0; i--) { /* shuffled, so that the letters are mostly literals */
        size_t j = (size_t)(bs_test_rand_u64(&seed) % (i + 1));
        unsigned char t = buf[i];
        buf[i] = buf[j];
        buf[j] = t;
    }
    CHECK(round_trip("skewed", buf, n) > 0);

    /* Kinds changing every 40000 bytes: random, a run, text-like; the blocks take each kind. */
    for (size_t i = 0; i < big; i++) {
        size_t part = (i / 40000) % 3;
        buf[i] = part == 0 ? (unsigned char)(bs_test_rand_u64(&seed) >> 56)
                 : part == 1 ? 7
                             : (unsigned char)("the quick brown fox "[(i * 7 + (i >> 9)) % 20]);
    }
    CHECK(round_trip("mixed", buf, big) > 0);

    free(buf);
    return bs_test_exit("test_deflate");
}
