/* engine_cross.h — when a ball's centre leaves its cell: the earliest time it reaches a
 * face of its cell that is not the box's wall, in lanes where the CPU has them (the
 * direction of motion is a coin toss per dimension, which branches mispredict) and in a
 * scalar loop otherwise, the same bits either way. Included by engine_predict.c. */
#ifndef RELCOL_ENGINE_CROSS_H
#define RELCOL_ENGINE_CROSS_H

#include <stdint.h>

#include "engine_pairs.h" /* (ENG_HAVE_AVX2 and its intrinsics) */
#include "engine_private.h"

/* Ball i's next cell crossing: the earliest time its centre reaches a face of its cell
 * that is not the box's wall (ties: the lower dimension), code 2 d + (direction > 0). A
 * periodic face is a crossing (rc_eng_cross wraps the ball). */
static void cross_event_scalar(rc_sim *s, int32_t i, const int c[3])
{
    const eng_ball *bi = &s->b[i];
    double best = INFINITY;
    int32_t code = -1;
    for (int d = 0; d < s->def.dim; d++) {
        const double v = rc_v3_get(bi->v, d), x = rc_v3_get(bi->x, d);
        const int up = v > 0.0;
        /* a boundary to cross: not the box's own wall (a periodic face is one) */
        const int valid = up ? c[d] < s->g.up_lim[d] : (v < 0.0) & (c[d] > s->g.dn_lim[d]);
        const double edge = (double)(c[d] + up) * s->g.w[d];
        double t = bi->t + (edge - x) / (valid ? v : 1.0);
        t = t < s->now ? s->now : t;
        const int take = valid & (t < best);
        best = take ? t : best;
        code = take ? 2 * d + up : code;
    }
    s->a[i].cross_t = best;
    s->a[i].cross_code = code;
}

#ifdef ENG_HAVE_AVX2
/* The same in lanes (one per dimension): the direction of motion is a coin toss per
 * dimension, which the scalar loop's branches mispredicted ~5 times a collision. The
 * same operations, so the same bits; the earliest lane, ties to the lowest. */
__attribute__((target("avx2"))) static void cross_event_avx2(rc_sim *s, int32_t i,
                                                              const int c[3])
{
    const eng_ball *bi = &s->b[i];
    const int dim = s->def.dim;
    const __m256d zero = _mm256_setzero_pd(), one = _mm256_set1_pd(1.0);
    const __m256d inf = _mm256_set1_pd(INFINITY);
    const __m256d v = _mm256_setr_pd(bi->v.x, bi->v.y, dim == 3 ? bi->v.z : 0.0, 0.0);
    const __m256d x = _mm256_setr_pd(bi->x.x, bi->x.y, bi->x.z, 0.0);
    const __m256d cd = _mm256_setr_pd(c[0], c[1], c[2], 0.0);
    const __m256d last = _mm256_setr_pd(s->g.up_lim[0], s->g.up_lim[1], s->g.up_lim[2], 0.0);
    const __m256d first = _mm256_setr_pd(s->g.dn_lim[0], s->g.dn_lim[1], s->g.dn_lim[2], 0.0);
    const __m256d w = _mm256_setr_pd(s->g.w[0], s->g.w[1], s->g.w[2], 1.0);
    const __m256d up = _mm256_cmp_pd(v, zero, _CMP_GT_OQ);
    const __m256d down = _mm256_cmp_pd(v, zero, _CMP_LT_OQ);
    const __m256d valid =
        _mm256_or_pd(_mm256_and_pd(up, _mm256_cmp_pd(cd, last, _CMP_LT_OQ)),
                     _mm256_and_pd(down, _mm256_cmp_pd(cd, first, _CMP_GT_OQ)));
    const __m256d edge = _mm256_mul_pd(_mm256_add_pd(cd, _mm256_and_pd(up, one)), w);
    __m256d t = _mm256_add_pd(_mm256_set1_pd(bi->t),
                              _mm256_div_pd(_mm256_sub_pd(edge, x),
                                            _mm256_blendv_pd(one, v, valid)));
    const __m256d now = _mm256_set1_pd(s->now);
    t = _mm256_blendv_pd(t, now, _mm256_cmp_pd(t, now, _CMP_LT_OQ));
    t = _mm256_blendv_pd(inf, t, valid);
    /* min of the lanes, then the first lane holding it */
    __m256d m = _mm256_min_pd(t, _mm256_permute_pd(t, 0x5));
    m = _mm256_min_pd(m, _mm256_permute2f128_pd(m, m, 0x01));
    const double best = _mm256_cvtsd_f64(m);
    const unsigned at = (unsigned)_mm256_movemask_pd(_mm256_cmp_pd(t, m, _CMP_EQ_OQ));
    const int d = at ? __builtin_ctz(at) : 0;
    const unsigned ups = (unsigned)_mm256_movemask_pd(up);
    s->a[i].cross_t = best;
    s->a[i].cross_code = best < INFINITY ? 2 * d + (int)(ups >> d & 1u) : -1;
}
#endif

static inline void cross_event(rc_sim *s, int32_t i, const int c[3])
{
#ifdef ENG_HAVE_AVX2
    if (s->simd >= ENG_SIMD_AVX2) {
        cross_event_avx2(s, i, c);
        return;
    }
#endif
    cross_event_scalar(s, i, c);
}

#endif
