/* engine/wide.h — the lane layer of the engine's kernels: a wide double (eng_wd) and its
 * mask (eng_wm) of ENG_W lanes, and a row of eight cell slots (eng_slots) for the walk.
 * The translation unit that includes it sets ENG_W: 8 (AVX-512F/VL), 4 (AVX2) or 1
 * (plain C), and is compiled for that instruction set (lib/meson.build); the kernels
 * (engine/kernels.h) are written once against these operations, after Box2D v3's b2FloatW.
 *
 * Every operation is one IEEE operation per lane, the same in every back end, and no back
 * end contracts a multiply and an add (-ffp-contract=off, and no FMA intrinsic here): a
 * kernel's lane l therefore computes exactly what the one-lane back end computes for
 * neighbour l, bit for bit. Only what moves data across lanes -- the transpose of ball
 * records into lanes, the compress of a row of slots, the earliest of the lanes -- is
 * written per back end, and each gives the same values in the same order. */
#ifndef RELCOL_ENGINE_WIDE_H
#define RELCOL_ENGINE_WIDE_H

#include <math.h>
#include <stdint.h>

#ifndef ENG_W
#error "define ENG_W (8, 4 or 1) before including engine/wide.h"
#endif

#if ENG_W == 8 || ENG_W == 4
#include <immintrin.h>
#endif

/* The operations, and the kernels built from them, are inlined into the few functions of
 * each table: the dimension, the periodic flag and the clock order are then constants in
 * each copy of a kernel (GCC's heuristics stop inlining a kernel called eight times). */
#define ENG_INLINE static inline __attribute__((always_inline))

/* ---- eight lanes: AVX-512F (the slot rows use AVX-512VL) ----------------------------- */
#if ENG_W == 8
typedef __m512d eng_wd;
typedef __mmask8 eng_wm;

ENG_INLINE eng_wd eng_set1(double a) { return _mm512_set1_pd(a); }
ENG_INLINE eng_wd eng_zero(void) { return _mm512_setzero_pd(); }
ENG_INLINE eng_wd eng_load(const double *p) { return _mm512_loadu_pd(p); }
ENG_INLINE void eng_store(double *p, eng_wd a) { _mm512_storeu_pd(p, a); }
ENG_INLINE eng_wd eng_add(eng_wd a, eng_wd b) { return _mm512_add_pd(a, b); }
ENG_INLINE eng_wd eng_sub(eng_wd a, eng_wd b) { return _mm512_sub_pd(a, b); }
ENG_INLINE eng_wd eng_mul(eng_wd a, eng_wd b) { return _mm512_mul_pd(a, b); }
ENG_INLINE eng_wd eng_div(eng_wd a, eng_wd b) { return _mm512_div_pd(a, b); }
ENG_INLINE eng_wd eng_sqrt(eng_wd a) { return _mm512_sqrt_pd(a); }
ENG_INLINE eng_wm eng_lt(eng_wd a, eng_wd b) { return _mm512_cmp_pd_mask(a, b, _CMP_LT_OQ); }
ENG_INLINE eng_wm eng_le(eng_wd a, eng_wd b) { return _mm512_cmp_pd_mask(a, b, _CMP_LE_OQ); }
ENG_INLINE eng_wm eng_gt(eng_wd a, eng_wd b) { return _mm512_cmp_pd_mask(a, b, _CMP_GT_OQ); }
ENG_INLINE eng_wm eng_ge(eng_wd a, eng_wd b) { return _mm512_cmp_pd_mask(a, b, _CMP_GE_OQ); }
ENG_INLINE eng_wm eng_and(eng_wm a, eng_wm b) { return a & b; }
ENG_INLINE eng_wm eng_or(eng_wm a, eng_wm b) { return a | b; }
/* m ? a : b, lane by lane */
ENG_INLINE eng_wd eng_select(eng_wm m, eng_wd a, eng_wd b) { return _mm512_mask_blend_pd(m, b, a); }
ENG_INLINE eng_wm eng_select_m(eng_wm m, eng_wm a, eng_wm b)
{
    return (eng_wm)((m & a) | (~m & b));
}
/* bit l: lane l of the mask */
ENG_INLINE unsigned eng_bits(eng_wm m) { return m; }
/* the mask whose lane l is bit l */
ENG_INLINE eng_wm eng_mask_bits(unsigned bits) { return (eng_wm)bits; }

/* Lane l gets the eight doubles at rec[l] (field f into out[f]): a 64-byte ball record a
 * lane, transposed by three rounds of eight shuffles. */
ENG_INLINE void eng_load_records(const double *const rec[8], eng_wd out[8])
{
    __m512d r[8], t[8], u[8];
    for (int l = 0; l < 8; l++)
        r[l] = _mm512_loadu_pd(rec[l]);
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
    out[0] = _mm512_shuffle_f64x2(u[0], u[4], 0x88);
    out[4] = _mm512_shuffle_f64x2(u[0], u[4], 0xDD);
    out[2] = _mm512_shuffle_f64x2(u[1], u[5], 0x88);
    out[6] = _mm512_shuffle_f64x2(u[1], u[5], 0xDD);
    out[1] = _mm512_shuffle_f64x2(u[2], u[6], 0x88);
    out[5] = _mm512_shuffle_f64x2(u[2], u[6], 0xDD);
    out[3] = _mm512_shuffle_f64x2(u[3], u[7], 0x88);
    out[7] = _mm512_shuffle_f64x2(u[3], u[7], 0xDD);
}

/* The axes d0, d0 + 1, ... of (x, y, z), pad past z (d0 = 0 here: three axes fit). */
ENG_INLINE eng_wd eng_axes(double x, double y, double z, double pad, int d0)
{
    (void)d0;
    return _mm512_setr_pd(x, y, z, pad, pad, pad, pad, pad);
}

/* The least lane's value, and in *lane the first lane holding it. */
ENG_INLINE double eng_min_lane(eng_wd a, unsigned *lane)
{
    const double m = _mm512_reduce_min_pd(a);
    const unsigned at = _mm512_cmp_pd_mask(a, _mm512_set1_pd(m), _CMP_EQ_OQ);
    *lane = (unsigned)__builtin_ctz(at | 0x100u) & 7u;
    return m;
}

/* A row of eight cell slots (ball indices, -1 empty, ENG_CHAIN codes below -1). */
typedef __m256i eng_slots;
ENG_INLINE eng_slots eng_slots_load(const int32_t *sl)
{
    return _mm256_loadu_si256((const __m256i *)sl);
}
/* bits of the slots among `valid` holding a ball other than skip */
ENG_INLINE unsigned eng_slots_balls(eng_slots v, int32_t skip, unsigned valid)
{
    return _mm256_mask_cmpgt_epi32_mask((__mmask8)valid, v, _mm256_set1_epi32(-1)) &
           _mm256_cmpneq_epi32_mask(v, _mm256_set1_epi32(skip));
}
/* bits of the slots among `valid` holding a chain */
ENG_INLINE unsigned eng_slots_chains(eng_slots v, unsigned valid)
{
    return _mm256_mask_cmpgt_epi32_mask((__mmask8)valid, _mm256_set1_epi32(-1), v);
}
/* The slots in `keep` to out[0..], in order; their count. Stores eight. */
ENG_INLINE size_t eng_slots_compress(int32_t *out, eng_slots v, unsigned keep)
{
    _mm256_storeu_si256((__m256i *)out, _mm256_maskz_compress_epi32((__mmask8)keep, v));
    return (size_t)__builtin_popcount(keep);
}

/* ---- four lanes: AVX2 ---------------------------------------------------------------- */
#elif ENG_W == 4
typedef __m256d eng_wd;
typedef __m256d eng_wm; /* all ones or all zeros per lane */

ENG_INLINE eng_wd eng_set1(double a) { return _mm256_set1_pd(a); }
ENG_INLINE eng_wd eng_zero(void) { return _mm256_setzero_pd(); }
ENG_INLINE eng_wd eng_load(const double *p) { return _mm256_loadu_pd(p); }
ENG_INLINE void eng_store(double *p, eng_wd a) { _mm256_storeu_pd(p, a); }
ENG_INLINE eng_wd eng_add(eng_wd a, eng_wd b) { return _mm256_add_pd(a, b); }
ENG_INLINE eng_wd eng_sub(eng_wd a, eng_wd b) { return _mm256_sub_pd(a, b); }
ENG_INLINE eng_wd eng_mul(eng_wd a, eng_wd b) { return _mm256_mul_pd(a, b); }
ENG_INLINE eng_wd eng_div(eng_wd a, eng_wd b) { return _mm256_div_pd(a, b); }
ENG_INLINE eng_wd eng_sqrt(eng_wd a) { return _mm256_sqrt_pd(a); }
ENG_INLINE eng_wm eng_lt(eng_wd a, eng_wd b) { return _mm256_cmp_pd(a, b, _CMP_LT_OQ); }
ENG_INLINE eng_wm eng_le(eng_wd a, eng_wd b) { return _mm256_cmp_pd(a, b, _CMP_LE_OQ); }
ENG_INLINE eng_wm eng_gt(eng_wd a, eng_wd b) { return _mm256_cmp_pd(a, b, _CMP_GT_OQ); }
ENG_INLINE eng_wm eng_ge(eng_wd a, eng_wd b) { return _mm256_cmp_pd(a, b, _CMP_GE_OQ); }
ENG_INLINE eng_wm eng_and(eng_wm a, eng_wm b) { return _mm256_and_pd(a, b); }
ENG_INLINE eng_wm eng_or(eng_wm a, eng_wm b) { return _mm256_or_pd(a, b); }
ENG_INLINE eng_wd eng_select(eng_wm m, eng_wd a, eng_wd b) { return _mm256_blendv_pd(b, a, m); }
ENG_INLINE eng_wm eng_select_m(eng_wm m, eng_wm a, eng_wm b) { return _mm256_blendv_pd(b, a, m); }
ENG_INLINE unsigned eng_bits(eng_wm m) { return (unsigned)_mm256_movemask_pd(m); }
ENG_INLINE eng_wm eng_mask_bits(unsigned bits)
{
    const __m256i sel = _mm256_setr_epi64x(1, 2, 4, 8);
    const __m256i b = _mm256_and_si256(_mm256_set1_epi64x((long long)bits), sel);
    return _mm256_castsi256_pd(_mm256_cmpeq_epi64(b, sel));
}

/* Lane l gets the eight doubles at rec[l]: each record's two halves, transposed four by
 * four (low halves: fields 0..3, high halves: 4..7). */
ENG_INLINE void eng_load_records(const double *const rec[4], eng_wd out[8])
{
    for (int h = 0; h < 2; h++) {
        __m256d r[4];
        for (int l = 0; l < 4; l++)
            r[l] = _mm256_loadu_pd(rec[l] + 4 * h);
        const __m256d t0 = _mm256_unpacklo_pd(r[0], r[1]), t1 = _mm256_unpackhi_pd(r[0], r[1]);
        const __m256d t2 = _mm256_unpacklo_pd(r[2], r[3]), t3 = _mm256_unpackhi_pd(r[2], r[3]);
        out[4 * h + 0] = _mm256_permute2f128_pd(t0, t2, 0x20);
        out[4 * h + 1] = _mm256_permute2f128_pd(t1, t3, 0x20);
        out[4 * h + 2] = _mm256_permute2f128_pd(t0, t2, 0x31);
        out[4 * h + 3] = _mm256_permute2f128_pd(t1, t3, 0x31);
    }
}

ENG_INLINE eng_wd eng_axes(double x, double y, double z, double pad, int d0)
{
    (void)d0;
    return _mm256_setr_pd(x, y, z, pad);
}

ENG_INLINE double eng_min_lane(eng_wd a, unsigned *lane)
{
    __m256d m = _mm256_min_pd(a, _mm256_permute_pd(a, 0x5));
    m = _mm256_min_pd(m, _mm256_permute2f128_pd(m, m, 0x01));
    const unsigned at = (unsigned)_mm256_movemask_pd(_mm256_cmp_pd(a, m, _CMP_EQ_OQ));
    *lane = (unsigned)__builtin_ctz(at | 0x10u) & 3u;
    return _mm256_cvtsd_f64(m);
}

typedef __m256i eng_slots;
ENG_INLINE eng_slots eng_slots_load(const int32_t *sl)
{
    return _mm256_loadu_si256((const __m256i *)sl);
}
ENG_INLINE unsigned eng_slots_balls(eng_slots v, int32_t skip, unsigned valid)
{
    const __m256i keep = _mm256_andnot_si256(_mm256_cmpeq_epi32(v, _mm256_set1_epi32(skip)),
                                             _mm256_cmpgt_epi32(v, _mm256_set1_epi32(-1)));
    return (unsigned)_mm256_movemask_ps(_mm256_castsi256_ps(keep)) & valid;
}
ENG_INLINE unsigned eng_slots_chains(eng_slots v, unsigned valid)
{
    return (unsigned)_mm256_movemask_ps(
               _mm256_castsi256_ps(_mm256_cmpgt_epi32(_mm256_set1_epi32(-1), v))) & valid;
}

/* pshufb controls that move the 32-bit lanes set in a 4-bit mask to the front, and the
 * masks' counts (AVX2 has no compress: each half of the row goes by a table) */
#define ENG_Z4 -128, -128, -128, -128
static const int8_t eng_compress4[16][16] = {
    {ENG_Z4, ENG_Z4, ENG_Z4, ENG_Z4},
    {0, 1, 2, 3, ENG_Z4, ENG_Z4, ENG_Z4},
    {4, 5, 6, 7, ENG_Z4, ENG_Z4, ENG_Z4},
    {0, 1, 2, 3, 4, 5, 6, 7, ENG_Z4, ENG_Z4},
    {8, 9, 10, 11, ENG_Z4, ENG_Z4, ENG_Z4},
    {0, 1, 2, 3, 8, 9, 10, 11, ENG_Z4, ENG_Z4},
    {4, 5, 6, 7, 8, 9, 10, 11, ENG_Z4, ENG_Z4},
    {0, 1, 2, 3, 4, 5, 6, 7, 8, 9, 10, 11, ENG_Z4},
    {12, 13, 14, 15, ENG_Z4, ENG_Z4, ENG_Z4},
    {0, 1, 2, 3, 12, 13, 14, 15, ENG_Z4, ENG_Z4},
    {4, 5, 6, 7, 12, 13, 14, 15, ENG_Z4, ENG_Z4},
    {0, 1, 2, 3, 4, 5, 6, 7, 12, 13, 14, 15, ENG_Z4},
    {8, 9, 10, 11, 12, 13, 14, 15, ENG_Z4, ENG_Z4},
    {0, 1, 2, 3, 8, 9, 10, 11, 12, 13, 14, 15, ENG_Z4},
    {4, 5, 6, 7, 8, 9, 10, 11, 12, 13, 14, 15, ENG_Z4},
    {0, 1, 2, 3, 4, 5, 6, 7, 8, 9, 10, 11, 12, 13, 14, 15},
};
#undef ENG_Z4
static const unsigned char eng_pop4[16] = {0, 1, 1, 2, 1, 2, 2, 3, 1, 2, 2, 3, 2, 3, 3, 4};

/* (stores four past the kept ones) */
ENG_INLINE size_t eng_slots_compress(int32_t *out, eng_slots v, unsigned keep)
{
    const __m128i lo = _mm256_castsi256_si128(v), hi = _mm256_extracti128_si256(v, 1);
    const __m128i clo = _mm_loadu_si128((const __m128i *)eng_compress4[keep & 15u]);
    const __m128i chi = _mm_loadu_si128((const __m128i *)eng_compress4[keep >> 4]);
    _mm_storeu_si128((__m128i *)out, _mm_shuffle_epi8(lo, clo));
    const size_t m = eng_pop4[keep & 15u];
    _mm_storeu_si128((__m128i *)(out + m), _mm_shuffle_epi8(hi, chi));
    return m + eng_pop4[keep >> 4];
}

/* ---- one lane: plain C (any CPU) ----------------------------------------------------- */
#elif ENG_W == 1
typedef double eng_wd;
typedef int eng_wm; /* 0 or 1 */

ENG_INLINE eng_wd eng_set1(double a) { return a; }
ENG_INLINE eng_wd eng_zero(void) { return 0.0; }
ENG_INLINE eng_wd eng_load(const double *p) { return *p; }
ENG_INLINE void eng_store(double *p, eng_wd a) { *p = a; }
ENG_INLINE eng_wd eng_add(eng_wd a, eng_wd b) { return a + b; }
ENG_INLINE eng_wd eng_sub(eng_wd a, eng_wd b) { return a - b; }
ENG_INLINE eng_wd eng_mul(eng_wd a, eng_wd b) { return a * b; }
ENG_INLINE eng_wd eng_div(eng_wd a, eng_wd b) { return a / b; }
ENG_INLINE eng_wd eng_sqrt(eng_wd a) { return sqrt(a); }
ENG_INLINE eng_wm eng_lt(eng_wd a, eng_wd b) { return a < b; }
ENG_INLINE eng_wm eng_le(eng_wd a, eng_wd b) { return a <= b; }
ENG_INLINE eng_wm eng_gt(eng_wd a, eng_wd b) { return a > b; }
ENG_INLINE eng_wm eng_ge(eng_wd a, eng_wd b) { return a >= b; }
ENG_INLINE eng_wm eng_and(eng_wm a, eng_wm b) { return a & b; }
ENG_INLINE eng_wm eng_or(eng_wm a, eng_wm b) { return a | b; }
ENG_INLINE eng_wd eng_select(eng_wm m, eng_wd a, eng_wd b) { return m ? a : b; }
ENG_INLINE eng_wm eng_select_m(eng_wm m, eng_wm a, eng_wm b) { return m ? a : b; }
ENG_INLINE unsigned eng_bits(eng_wm m) { return (unsigned)m; }
ENG_INLINE eng_wm eng_mask_bits(unsigned bits) { return (eng_wm)(bits & 1u); }

ENG_INLINE void eng_load_records(const double *const rec[1], eng_wd out[8])
{
    for (int f = 0; f < 8; f++)
        out[f] = rec[0][f];
}

ENG_INLINE eng_wd eng_axes(double x, double y, double z, double pad, int d0)
{
    return d0 == 0 ? x : d0 == 1 ? y : d0 == 2 ? z : pad;
}

ENG_INLINE double eng_min_lane(eng_wd a, unsigned *lane)
{
    *lane = 0;
    return a;
}

typedef struct eng_slots {
    int32_t v[8];
} eng_slots;
ENG_INLINE eng_slots eng_slots_load(const int32_t *sl)
{
    eng_slots r;
    for (int l = 0; l < 8; l++)
        r.v[l] = sl[l];
    return r;
}
ENG_INLINE unsigned eng_slots_balls(eng_slots v, int32_t skip, unsigned valid)
{
    unsigned m = 0;
    for (int l = 0; l < 8; l++)
        m |= (unsigned)((v.v[l] >= 0) & (v.v[l] != skip)) << l;
    return m & valid;
}
ENG_INLINE unsigned eng_slots_chains(eng_slots v, unsigned valid)
{
    unsigned m = 0;
    for (int l = 0; l < 8; l++)
        m |= (unsigned)(v.v[l] < -1) << l;
    return m & valid;
}
/* (stores eight, each kept one over the last) */
ENG_INLINE size_t eng_slots_compress(int32_t *out, eng_slots v, unsigned keep)
{
    size_t m = 0;
    for (int l = 0; l < 8; l++) {
        out[m] = v.v[l];
        m += keep >> l & 1u;
    }
    return m;
}
#else
#error "ENG_W must be 8, 4 or 1"
#endif

#endif
