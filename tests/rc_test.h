/* rc_test.h — the one tiny test harness every test binary uses (Box2D style).
 * ENSURE* record a failure with file:line and carry on inside the test; RUN_TEST runs a
 * test function; RC_TEST_MAIN_END prints "N checks, N failed" and sets the exit code. */
#ifndef RC_TEST_H
#define RC_TEST_H

#include <math.h>
#include <stdint.h>
#include <stdio.h>

#include "relcol/rng.h"

static long rc_test_checks, rc_test_failures;

#define ENSURE_MSG(cond, ...)                                                      \
    do {                                                                          \
        rc_test_checks++;                                                         \
        if (!(cond)) {                                                            \
            rc_test_failures++;                                                   \
            if (rc_test_failures <= 50) {                                         \
                fprintf(stderr, "%s:%d: check failed: %s: ", __FILE__, __LINE__, #cond); \
                fprintf(stderr, __VA_ARGS__);                                     \
                fputc('\n', stderr);                                              \
            }                                                                     \
        }                                                                         \
    } while (0)

#define ENSURE(cond) ENSURE_MSG(cond, "%s", "")

/* |a - b| <= tol * scale, with scale = max(|b|, floor) given by the caller's reasoning */
#define ENSURE_CLOSE(a, b, tol, scale)                                             \
    do {                                                                          \
        double rc_a_ = (a), rc_b_ = (b), rc_s_ = (scale);                         \
        ENSURE_MSG(fabs(rc_a_ - rc_b_) <= (tol) * rc_s_,                          \
                   "%s = %.17g, %s = %.17g, |diff| = %.3g > %.3g", #a, rc_a_, #b, rc_b_, \
                   fabs(rc_a_ - rc_b_), (double)(tol) * rc_s_);                  \
    } while (0)

/* relative to |b| (b is the reference value) */
#define ENSURE_REL(a, b, tol) ENSURE_CLOSE(a, b, tol, fabs(b))

#define RUN_TEST(fn)                                                               \
    do {                                                                          \
        long f0_ = rc_test_failures, c0_ = rc_test_checks;                        \
        fn();                                                                     \
        printf("%-44s %s (%ld checks)\n", #fn, rc_test_failures == f0_ ? "ok" : "FAILED", \
               rc_test_checks - c0_);                                             \
    } while (0)

#define RC_TEST_MAIN_END()                                                         \
    do {                                                                          \
        printf("%ld checks, %ld failed\n", rc_test_checks, rc_test_failures);      \
        return rc_test_failures == 0 && rc_test_checks > 0 ? 0 : 1;               \
    } while (0)

/* The c whose 1/c^2 is inv_c2 (0: INFINITY; < 0 or NaN: NAN, which the library rejects),
 * for tests written in terms of inv_c2; 1/c^2 of the result is inv_c2 up to rounding. */
static inline double rc_test_c_of(double inv_c2)
{
    return inv_c2 > 0.0 ? 1.0 / sqrt(inv_c2) : inv_c2 == 0.0 ? INFINITY : NAN;
}

/* Deterministic generator for tests: the library's (relcol/rng.h), under the tests' names. */
typedef rc_rng rc_test_rng;
static inline uint64_t rc_test_next(rc_test_rng *r) { return rc_rng_next(r); }
/* uniform in [0, 1) */
static inline double rc_test_uniform(rc_test_rng *r) { return rc_rng_uniform(r); }
static inline double rc_test_range(rc_test_rng *r, double lo, double hi)
{
    return lo + (hi - lo) * rc_test_uniform(r);
}

#endif
