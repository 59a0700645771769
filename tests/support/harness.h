/* A tiny test harness: CHECK records a failure with its location and goes on; main returns
 * bs_test_exit(). One test program per feature, each a CTest test. */
#ifndef BS_TEST_HARNESS_H
#define BS_TEST_HARNESS_H

#include <stdio.h>
#include <stdlib.h>

static int bs_test_failures;
static int bs_test_checks;

#define CHECK(cond)                                                                      \
    do {                                                                                 \
        bs_test_checks++;                                                                \
        if (!(cond)) {                                                                   \
            bs_test_failures++;                                                          \
            fprintf(stderr, "%s:%d: CHECK failed: %s\n", __FILE__, __LINE__, #cond);     \
        }                                                                                \
    } while (0)

/* CHECK with a formatted explanation printed on failure. */
#define CHECKF(cond, ...)                                                                \
    do {                                                                                 \
        bs_test_checks++;                                                                \
        if (!(cond)) {                                                                   \
            bs_test_failures++;                                                          \
            fprintf(stderr, "%s:%d: CHECK failed: %s: ", __FILE__, __LINE__, #cond);     \
            fprintf(stderr, __VA_ARGS__);                                                \
            fputc('\n', stderr);                                                         \
        }                                                                                \
    } while (0)

#define CHECK_STATUS(expr, expected) CHECKF((expr) == (expected), "expected %s", #expected)

static inline int bs_test_exit(const char *name)
{
    printf("%s: %d checks, %d failures\n", name, bs_test_checks, bs_test_failures);
    return bs_test_failures == 0 ? 0 : 1;
}

/* True when BS_TEST_QUICK is set (by .ci/memcheck.sh): the slowest tests then check a smaller
 * sample of the same cases, since under valgrind they look for memory errors, which the full
 * sample run by the ordinary test command does not need to repeat. */
static inline int bs_test_quick(void)
{
    const char *q = getenv("BS_TEST_QUICK");
    return q != NULL && *q != '\0' && *q != '0';
}

/* Deterministic pseudo-random numbers (splitmix64), so failures reproduce. */
static inline unsigned long long bs_test_rand_u64(unsigned long long *state)
{
    unsigned long long z = (*state += 0x9E3779B97F4A7C15ull);
    z = (z ^ (z >> 30)) * 0xBF58476D1CE4E5B9ull;
    z = (z ^ (z >> 27)) * 0x94D049BB133111EBull;
    return z ^ (z >> 31);
}

/* Uniform in [lo, hi). */
static inline double bs_test_rand(unsigned long long *state, double lo, double hi)
{
    return lo + (hi - lo) * (double)(bs_test_rand_u64(state) >> 11) * 0x1.0p-53;
}

#endif
