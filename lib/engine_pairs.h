/* engine_pairs.h — the sphere contact test of ball i against its gathered neighbours: the
 * scalar form, and four neighbours per step in AVX2 lanes (x86-64 machines that have AVX2;
 * others take the scalar loop). Every lane does exactly the scalar operations in the same
 * order, so the times are the same bits; only the instruction count changes (the neighbour
 * test was ~100 scalar instructions, the engine's largest cost). Included by engine_core.c. */
#ifndef RELCOL_ENGINE_PAIRS_H
#define RELCOL_ENGINE_PAIRS_H

#include <math.h>
#include <stdint.h>

#include "engine_private.h"

/* Separation bk - bi at the later of the two balls' clocks, *tref: the earlier ball is
 * advanced, so the result depends only on the two stored states. The nearest image in a
 * periodic box. */
static inline rc_vec3 pair_sep(const rc_sim *s, const eng_ball *bi, const eng_ball *bk,
                               double *tref)
{
    if (bi->t >= bk->t) {
        *tref = bi->t;
        return eng_image(s, rc_v3_sub(rc_v3_axpy(bk->x, bi->t - bk->t, bk->v), bi->x));
    }
    *tref = bk->t;
    return eng_image(s, rc_v3_sub(bk->x, rc_v3_axpy(bi->x, bk->t - bi->t, bi->v)));
}

/* Contact time of the bounding spheres of bi and bk, from their separation dx (d2 = |dx|^2)
 * at time tref, as an absolute time >= now; INFINITY on a miss or when it cannot beat
 * `best`. It depends only on the two stored states (the same bits whichever ball asks). */
static inline double sphere_time_dx(const rc_sim *s, const eng_ball *bi, const eng_ball *bk,
                                    rc_vec3 dx, double d2, double tref, double best)
{
    const rc_vec3 dv = rc_v3_sub(bk->v, bi->v);
    const double b = rc_v3_dot(dx, dv);
    const double sig = bi->r + bk->r;
    const double dd = d2 - sig * sig;
    const double dv2 = rc_v3_norm2(dv);
    const double disc = b * b - dv2 * dd;
    const double tol = s->def.approach_tol * sig;
    /* One combined, mostly-taken test rejects most neighbours before the sqrt and the
     * division: not approaching (b >= 0); touching but not really approaching; roots not
     * real; or not able to beat `best` (sqrt(disc) <= -b gives t >= dd / (-2 b)). The
     * root itself is dd / (-b + sqrt(disc)), free of cancellation. */
    const int touching = dd <= 0.0;
    const int hit = (b < 0.0) & (touching ? b * b > tol * tol * dv2
                                          : (disc > 0.0) & (dd < -2.0 * b * (best - tref)));
    if (!hit)
        return INFINITY;
    const double t = touching ? 0.0 : dd / (sqrt(disc) - b);
    double ta = tref + t;
    if (ta < s->now)
        ta = s->now;
    return ta < best ? ta : INFINITY;
}

/* The same from the two balls, with *near: whether the centres are within lim of each
 * other at the later clock (d2 <= lim^2, lim = (ri + rk)(1 + stol)), for the simultaneity
 * check -- the scalar form of the lanes below. */
static inline double pair_sphere_scalar(const rc_sim *s, const eng_ball *bi, const eng_ball *bk,
                                        double best, double stol, int *near)
{
    double tref;
    const rc_vec3 dx = pair_sep(s, bi, bk, &tref);
    const double d2 = rc_v3_norm2(dx), lim = (bi->r + bk->r) * (1.0 + stol);
    *near = d2 <= lim * lim;
    return sphere_time_dx(s, bi, bk, dx, d2, tref, best);
}

#if defined(__x86_64__) && defined(__GNUC__) && !defined(RELCOL_NO_SIMD)
#define ENG_HAVE_AVX2 1
#include <immintrin.h>

/* Four lanes: pair_sphere_scalar's operations on 256-bit registers (AVX2 machines;
 * rc_sim_create asks the CPU once): lanes 0..3 get the times of bi against k[0..3]
 * (INFINITY: no contact able to beat `best`) and bit l of *nears the proximity flag of
 * k[l]; returned: bit l set if lane l's time is finite. No FMA: the target adds AVX2
 * only, so the bits stay. */
__attribute__((target("avx2"), always_inline)) static inline int pair_sphere_x4(
    const rc_sim *s, const eng_ball *bi, const eng_ball *const k[4], double best, double stol,
    double out[4], unsigned *nears, const int three, const int latest, const int per)
{
    /* transpose four 64-byte records (x, v, t, r): low halves x.x x.y x.z v.x, high halves
     * v.y v.z t r */
    __m256d lo[4], hi[4];
    for (int l = 0; l < 4; l++) {
        lo[l] = _mm256_loadu_pd(&k[l]->x.x);
        hi[l] = _mm256_loadu_pd(&k[l]->x.x + 4);
    }
    __m256d t0 = _mm256_unpacklo_pd(lo[0], lo[1]), t1 = _mm256_unpackhi_pd(lo[0], lo[1]);
    __m256d t2 = _mm256_unpacklo_pd(lo[2], lo[3]), t3 = _mm256_unpackhi_pd(lo[2], lo[3]);
    const __m256d xkx = _mm256_permute2f128_pd(t0, t2, 0x20);
    const __m256d xky = _mm256_permute2f128_pd(t1, t3, 0x20);
    const __m256d xkz = _mm256_permute2f128_pd(t0, t2, 0x31);
    const __m256d vkx = _mm256_permute2f128_pd(t1, t3, 0x31);
    t0 = _mm256_unpacklo_pd(hi[0], hi[1]);
    t1 = _mm256_unpackhi_pd(hi[0], hi[1]);
    t2 = _mm256_unpacklo_pd(hi[2], hi[3]);
    t3 = _mm256_unpackhi_pd(hi[2], hi[3]);
    const __m256d vky = _mm256_permute2f128_pd(t0, t2, 0x20);
    const __m256d vkz = _mm256_permute2f128_pd(t1, t3, 0x20);
    const __m256d tk = _mm256_permute2f128_pd(t0, t2, 0x31);
    const __m256d rk = _mm256_permute2f128_pd(t1, t3, 0x31);
    const __m256d xix = _mm256_set1_pd(bi->x.x), xiy = _mm256_set1_pd(bi->x.y);
    const __m256d xiz = _mm256_set1_pd(bi->x.z), vix = _mm256_set1_pd(bi->v.x);
    const __m256d viy = _mm256_set1_pd(bi->v.y), viz = _mm256_set1_pd(bi->v.z);
    const __m256d ti = _mm256_set1_pd(bi->t), ri = _mm256_set1_pd(bi->r);
    /* pair_sep: the earlier ball advanced to the later clock. latest (a compile-time
     * constant): the caller knows bi's clock is the later one (a ball that has just
     * collided, at the engine's time), so only that branch is computed. */
    const __m256d hk = _mm256_sub_pd(ti, tk);
    const __m256d ax = _mm256_sub_pd(_mm256_add_pd(xkx, _mm256_mul_pd(hk, vkx)), xix);
    const __m256d ay = _mm256_sub_pd(_mm256_add_pd(xky, _mm256_mul_pd(hk, vky)), xiy);
    const __m256d az = _mm256_sub_pd(_mm256_add_pd(xkz, _mm256_mul_pd(hk, vkz)), xiz);
    __m256d dx = ax, dy = ay, dz = az, tref = ti;
    if (!latest) {
        const __m256d ge = _mm256_cmp_pd(ti, tk, _CMP_GE_OQ), hi_ = _mm256_sub_pd(tk, ti);
        const __m256d bx = _mm256_sub_pd(xkx, _mm256_add_pd(xix, _mm256_mul_pd(hi_, vix)));
        const __m256d by = _mm256_sub_pd(xky, _mm256_add_pd(xiy, _mm256_mul_pd(hi_, viy)));
        const __m256d bz = _mm256_sub_pd(xkz, _mm256_add_pd(xiz, _mm256_mul_pd(hi_, viz)));
        dx = _mm256_blendv_pd(bx, ax, ge);
        dy = _mm256_blendv_pd(by, ay, ge);
        dz = _mm256_blendv_pd(bz, az, ge);
        tref = _mm256_blendv_pd(tk, ti, ge);
    }
    if (per) { /* (a compile-time constant) the nearest image, as eng_image */
        const __m256d big = _mm256_set1_pd(0x1.8p52);
        const __m256d Lx = _mm256_set1_pd(s->L[0]), Ly = _mm256_set1_pd(s->L[1]);
        const __m256d Lz = _mm256_set1_pd(s->L[2]);
        const __m256d ix = _mm256_sub_pd(_mm256_add_pd(_mm256_mul_pd(dx, _mm256_set1_pd(s->inv_L[0])), big), big);
        const __m256d iy = _mm256_sub_pd(_mm256_add_pd(_mm256_mul_pd(dy, _mm256_set1_pd(s->inv_L[1])), big), big);
        dx = _mm256_sub_pd(dx, _mm256_mul_pd(Lx, ix));
        dy = _mm256_sub_pd(dy, _mm256_mul_pd(Ly, iy));
        if (three) {
            const __m256d iz = _mm256_sub_pd(_mm256_add_pd(_mm256_mul_pd(dz, _mm256_set1_pd(s->inv_L[2])), big), big);
            dz = _mm256_sub_pd(dz, _mm256_mul_pd(Lz, iz));
        }
    }
    /* three == 0 (2-D, every z component 0): the z terms add +0 and are left out (the sums
     * are the same bits unless one is -0, which no comparison below can tell from +0) */
    __m256d d2 = _mm256_add_pd(_mm256_mul_pd(dx, dx), _mm256_mul_pd(dy, dy));
    const __m256d dvx = _mm256_sub_pd(vkx, vix), dvy = _mm256_sub_pd(vky, viy);
    __m256d b = _mm256_add_pd(_mm256_mul_pd(dx, dvx), _mm256_mul_pd(dy, dvy));
    __m256d dv2 = _mm256_add_pd(_mm256_mul_pd(dvx, dvx), _mm256_mul_pd(dvy, dvy));
    if (three) {
        const __m256d dvz = _mm256_sub_pd(vkz, viz);
        d2 = _mm256_add_pd(d2, _mm256_mul_pd(dz, dz));
        b = _mm256_add_pd(b, _mm256_mul_pd(dz, dvz));
        dv2 = _mm256_add_pd(dv2, _mm256_mul_pd(dvz, dvz));
    }
    const __m256d sig = _mm256_add_pd(ri, rk);
    const __m256d dd = _mm256_sub_pd(d2, _mm256_mul_pd(sig, sig));
    const __m256d disc = _mm256_sub_pd(_mm256_mul_pd(b, b), _mm256_mul_pd(dv2, dd));
    const __m256d tol = _mm256_mul_pd(_mm256_set1_pd(s->def.approach_tol), sig);
    const __m256d lim = _mm256_mul_pd(sig, _mm256_set1_pd(1.0 + stol));
    const __m256d zero = _mm256_setzero_pd();
    const __m256d touching = _mm256_cmp_pd(dd, zero, _CMP_LE_OQ);
    const __m256d slow = _mm256_cmp_pd(_mm256_mul_pd(b, b),
                                       _mm256_mul_pd(_mm256_mul_pd(tol, tol), dv2), _CMP_GT_OQ);
    const __m256d bound = _mm256_mul_pd(_mm256_mul_pd(_mm256_set1_pd(-2.0), b),
                                        _mm256_sub_pd(_mm256_set1_pd(best), tref));
    const __m256d flying = _mm256_and_pd(_mm256_cmp_pd(disc, zero, _CMP_GT_OQ),
                                         _mm256_cmp_pd(dd, bound, _CMP_LT_OQ));
    const __m256d hit = _mm256_and_pd(_mm256_cmp_pd(b, zero, _CMP_LT_OQ),
                                      _mm256_blendv_pd(flying, slow, touching));
    *nears = (unsigned)_mm256_movemask_pd(_mm256_cmp_pd(d2, _mm256_mul_pd(lim, lim), _CMP_LE_OQ));
    if (!_mm256_movemask_pd(hit)) {
        const __m256d inf = _mm256_set1_pd(INFINITY);
        _mm256_storeu_pd(out, inf);
        return 0;
    }
    const __m256d safe = _mm256_blendv_pd(_mm256_set1_pd(1.0), disc, hit);
    const __m256d root = _mm256_div_pd(dd, _mm256_sub_pd(_mm256_sqrt_pd(safe), b));
    __m256d ta = _mm256_add_pd(tref, _mm256_blendv_pd(root, zero, touching));
    const __m256d now = _mm256_set1_pd(s->now);
    ta = _mm256_blendv_pd(ta, now, _mm256_cmp_pd(ta, now, _CMP_LT_OQ));
    const __m256d keep = _mm256_and_pd(hit, _mm256_cmp_pd(ta, _mm256_set1_pd(best), _CMP_LT_OQ));
    _mm256_storeu_pd(out, _mm256_blendv_pd(_mm256_set1_pd(INFINITY), ta, keep));
    return _mm256_movemask_pd(keep);
}

#define ENG_HAVE_AVX512 1
/* Eight lanes (AVX-512F machines): pair_sphere_x4's operations, on eight neighbours. A
 * ball's record is one 512-bit load; the eight are transposed by three rounds of eight
 * shuffles. The same operations in the same order, so the same bits (no FMA either: the
 * build contracts nothing, -ffp-contract=off). */
__attribute__((target("avx512f"), always_inline)) static inline unsigned pair_sphere_x8(
    const rc_sim *s, const eng_ball *bi, const eng_ball *const k[8], double best, double stol,
    double out[8], unsigned *nears, const int three, const int latest, const int per)
{
    __m512d r[8], t[8], u[8];
    for (int l = 0; l < 8; l++)
        r[l] = _mm512_loadu_pd(&k[l]->x.x);
    for (int l = 0; l < 8; l += 2) { /* t[l]: fields 0 2 4 6, t[l+1]: 1 3 5 7 (rows l, l+1) */
        t[l] = _mm512_unpacklo_pd(r[l], r[l + 1]);
        t[l + 1] = _mm512_unpackhi_pd(r[l], r[l + 1]);
    }
    for (int h = 0; h < 8; h += 4) { /* rows h..h+3: fields (0 4) (2 6) (1 5) (3 7) */
        u[h] = _mm512_shuffle_f64x2(t[h], t[h + 2], 0x88);
        u[h + 1] = _mm512_shuffle_f64x2(t[h], t[h + 2], 0xDD);
        u[h + 2] = _mm512_shuffle_f64x2(t[h + 1], t[h + 3], 0x88);
        u[h + 3] = _mm512_shuffle_f64x2(t[h + 1], t[h + 3], 0xDD);
    }
    const __m512d xkx = _mm512_shuffle_f64x2(u[0], u[4], 0x88);
    const __m512d vky = _mm512_shuffle_f64x2(u[0], u[4], 0xDD);
    const __m512d xkz = _mm512_shuffle_f64x2(u[1], u[5], 0x88);
    const __m512d tk = _mm512_shuffle_f64x2(u[1], u[5], 0xDD);
    const __m512d xky = _mm512_shuffle_f64x2(u[2], u[6], 0x88);
    const __m512d vkz = _mm512_shuffle_f64x2(u[2], u[6], 0xDD);
    const __m512d vkx = _mm512_shuffle_f64x2(u[3], u[7], 0x88);
    const __m512d rk = _mm512_shuffle_f64x2(u[3], u[7], 0xDD);
    const __m512d xix = _mm512_set1_pd(bi->x.x), xiy = _mm512_set1_pd(bi->x.y);
    const __m512d xiz = _mm512_set1_pd(bi->x.z), vix = _mm512_set1_pd(bi->v.x);
    const __m512d viy = _mm512_set1_pd(bi->v.y), viz = _mm512_set1_pd(bi->v.z);
    const __m512d ti = _mm512_set1_pd(bi->t), ri = _mm512_set1_pd(bi->r);
    const __m512d hk = _mm512_sub_pd(ti, tk);
    const __m512d ax = _mm512_sub_pd(_mm512_add_pd(xkx, _mm512_mul_pd(hk, vkx)), xix);
    const __m512d ay = _mm512_sub_pd(_mm512_add_pd(xky, _mm512_mul_pd(hk, vky)), xiy);
    const __m512d az = _mm512_sub_pd(_mm512_add_pd(xkz, _mm512_mul_pd(hk, vkz)), xiz);
    __m512d dx = ax, dy = ay, dz = az, tref = ti;
    if (!latest) {
        const __mmask8 ge = _mm512_cmp_pd_mask(ti, tk, _CMP_GE_OQ);
        const __m512d hi_ = _mm512_sub_pd(tk, ti);
        const __m512d bx = _mm512_sub_pd(xkx, _mm512_add_pd(xix, _mm512_mul_pd(hi_, vix)));
        const __m512d by = _mm512_sub_pd(xky, _mm512_add_pd(xiy, _mm512_mul_pd(hi_, viy)));
        const __m512d bz = _mm512_sub_pd(xkz, _mm512_add_pd(xiz, _mm512_mul_pd(hi_, viz)));
        dx = _mm512_mask_blend_pd(ge, bx, ax);
        dy = _mm512_mask_blend_pd(ge, by, ay);
        dz = _mm512_mask_blend_pd(ge, bz, az);
        tref = _mm512_mask_blend_pd(ge, tk, ti);
    }
    if (per) { /* (a compile-time constant) the nearest image, as eng_image */
        const __m512d big = _mm512_set1_pd(0x1.8p52);
        const __m512d Lx = _mm512_set1_pd(s->L[0]), Ly = _mm512_set1_pd(s->L[1]);
        const __m512d Lz = _mm512_set1_pd(s->L[2]);
        const __m512d ix = _mm512_sub_pd(_mm512_add_pd(_mm512_mul_pd(dx, _mm512_set1_pd(s->inv_L[0])), big), big);
        const __m512d iy = _mm512_sub_pd(_mm512_add_pd(_mm512_mul_pd(dy, _mm512_set1_pd(s->inv_L[1])), big), big);
        dx = _mm512_sub_pd(dx, _mm512_mul_pd(Lx, ix));
        dy = _mm512_sub_pd(dy, _mm512_mul_pd(Ly, iy));
        if (three) {
            const __m512d iz = _mm512_sub_pd(_mm512_add_pd(_mm512_mul_pd(dz, _mm512_set1_pd(s->inv_L[2])), big), big);
            dz = _mm512_sub_pd(dz, _mm512_mul_pd(Lz, iz));
        }
    }
    __m512d d2 = _mm512_add_pd(_mm512_mul_pd(dx, dx), _mm512_mul_pd(dy, dy));
    const __m512d dvx = _mm512_sub_pd(vkx, vix), dvy = _mm512_sub_pd(vky, viy);
    __m512d b = _mm512_add_pd(_mm512_mul_pd(dx, dvx), _mm512_mul_pd(dy, dvy));
    __m512d dv2 = _mm512_add_pd(_mm512_mul_pd(dvx, dvx), _mm512_mul_pd(dvy, dvy));
    if (three) {
        const __m512d dvz = _mm512_sub_pd(vkz, viz);
        d2 = _mm512_add_pd(d2, _mm512_mul_pd(dz, dz));
        b = _mm512_add_pd(b, _mm512_mul_pd(dz, dvz));
        dv2 = _mm512_add_pd(dv2, _mm512_mul_pd(dvz, dvz));
    }
    const __m512d sig = _mm512_add_pd(ri, rk);
    const __m512d dd = _mm512_sub_pd(d2, _mm512_mul_pd(sig, sig));
    const __m512d disc = _mm512_sub_pd(_mm512_mul_pd(b, b), _mm512_mul_pd(dv2, dd));
    const __m512d tol = _mm512_mul_pd(_mm512_set1_pd(s->def.approach_tol), sig);
    const __m512d lim = _mm512_mul_pd(sig, _mm512_set1_pd(1.0 + stol));
    const __m512d zero = _mm512_setzero_pd();
    const __mmask8 touching = _mm512_cmp_pd_mask(dd, zero, _CMP_LE_OQ);
    const __mmask8 slow = _mm512_cmp_pd_mask(
        _mm512_mul_pd(b, b), _mm512_mul_pd(_mm512_mul_pd(tol, tol), dv2), _CMP_GT_OQ);
    const __m512d bound = _mm512_mul_pd(_mm512_mul_pd(_mm512_set1_pd(-2.0), b),
                                        _mm512_sub_pd(_mm512_set1_pd(best), tref));
    const __mmask8 flying = _mm512_cmp_pd_mask(disc, zero, _CMP_GT_OQ) &
                            _mm512_cmp_pd_mask(dd, bound, _CMP_LT_OQ);
    const __mmask8 hit = _mm512_cmp_pd_mask(b, zero, _CMP_LT_OQ) &
                         (__mmask8)((touching & slow) | (~touching & flying));
    *nears = _mm512_cmp_pd_mask(d2, _mm512_mul_pd(lim, lim), _CMP_LE_OQ);
    const __m512d inf = _mm512_set1_pd(INFINITY);
    if (!hit) {
        _mm512_storeu_pd(out, inf);
        return 0;
    }
    const __m512d safe = _mm512_mask_blend_pd(hit, _mm512_set1_pd(1.0), disc);
    const __m512d root = _mm512_div_pd(dd, _mm512_sub_pd(_mm512_sqrt_pd(safe), b));
    __m512d ta = _mm512_add_pd(tref, _mm512_mask_blend_pd(touching, root, zero));
    const __m512d now = _mm512_set1_pd(s->now);
    ta = _mm512_mask_blend_pd(_mm512_cmp_pd_mask(ta, now, _CMP_LT_OQ), ta, now);
    const __mmask8 keep = hit & _mm512_cmp_pd_mask(ta, _mm512_set1_pd(best), _CMP_LT_OQ);
    _mm512_storeu_pd(out, _mm512_mask_blend_pd(keep, inf, ta));
    return keep;
}
#endif

#endif
