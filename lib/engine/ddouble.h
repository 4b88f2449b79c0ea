/* engine/ddouble.h — double-double arithmetic (a value as an unevaluated sum hi + lo,
 * |lo| <= ulp(hi)/2, about 106 bits): for the few sums whose terms cancel to order gamma^2
 * near c, where double keeps none of the result's digits and double-double keeps ~53 at
 * gamma 1e8. Error-free transformations (Knuth's two-sum, fma's exact product error) with
 * -ffp-contract=off, so the same bits on every machine. */
#ifndef RELCOL_ENGINE_DDOUBLE_H
#define RELCOL_ENGINE_DDOUBLE_H

#include <math.h>

typedef struct eng_dd {
    double hi, lo;
} eng_dd;

static inline eng_dd eng_dd_of(double a) { return (eng_dd){a, 0.0}; }

static inline eng_dd eng_two_sum(double a, double b)
{
    const double s = a + b, bb = s - a;
    return (eng_dd){s, (a - (s - bb)) + (b - bb)};
}

static inline eng_dd eng_two_prod(double a, double b)
{
    const double p = a * b;
    return (eng_dd){p, fma(a, b, -p)};
}

static inline eng_dd eng_dd_norm(double hi, double lo)
{
    const double s = hi + lo;
    return (eng_dd){s, lo - (s - hi)};
}

static inline eng_dd eng_dd_add(eng_dd a, eng_dd b)
{
    const eng_dd s = eng_two_sum(a.hi, b.hi), t = eng_two_sum(a.lo, b.lo);
    eng_dd r = eng_dd_norm(s.hi, s.lo + t.hi);
    return eng_dd_norm(r.hi, r.lo + t.lo);
}

static inline eng_dd eng_dd_neg(eng_dd a) { return (eng_dd){-a.hi, -a.lo}; }

static inline eng_dd eng_dd_sub(eng_dd a, eng_dd b) { return eng_dd_add(a, eng_dd_neg(b)); }

static inline eng_dd eng_dd_mul(eng_dd a, eng_dd b)
{
    const eng_dd p = eng_two_prod(a.hi, b.hi);
    return eng_dd_norm(p.hi, p.lo + (a.hi * b.lo + a.lo * b.hi));
}

static inline eng_dd eng_dd_mul_d(eng_dd a, double b)
{
    const eng_dd p = eng_two_prod(a.hi, b);
    return eng_dd_norm(p.hi, p.lo + a.lo * b);
}

static inline eng_dd eng_dd_div(eng_dd a, eng_dd b)
{
    const double q1 = a.hi / b.hi;
    const eng_dd r = eng_dd_sub(a, eng_dd_mul_d(b, q1));
    const double q2 = r.hi / b.hi;
    const eng_dd r2 = eng_dd_sub(r, eng_dd_mul_d(b, q2));
    return eng_dd_add(eng_two_sum(q1, q2), eng_dd_of(r2.hi / b.hi));
}

/* sqrt(a), a > 0: one Newton step from the double root */
static inline eng_dd eng_dd_sqrt(eng_dd a)
{
    const double x = sqrt(a.hi);
    const eng_dd r = eng_dd_sub(a, eng_two_prod(x, x));
    return eng_dd_norm(x, r.hi / (2.0 * x));
}

/* a.b of two double vectors, each product exact */
static inline eng_dd eng_dd_dot(rc_vec3 a, rc_vec3 b)
{
    return eng_dd_add(eng_dd_add(eng_two_prod(a.x, b.x), eng_two_prod(a.y, b.y)),
                      eng_two_prod(a.z, b.z));
}

typedef struct eng_ddv {
    eng_dd x, y, z;
} eng_ddv;

static inline eng_ddv eng_ddv_of(rc_vec3 v)
{
    return (eng_ddv){eng_dd_of(v.x), eng_dd_of(v.y), eng_dd_of(v.z)};
}

/* a + s n, s and n doubles */
static inline eng_ddv eng_ddv_axpy(eng_ddv a, double s, rc_vec3 n)
{
    return (eng_ddv){eng_dd_add(a.x, eng_two_prod(s, n.x)), eng_dd_add(a.y, eng_two_prod(s, n.y)),
                     eng_dd_add(a.z, eng_two_prod(s, n.z))};
}

static inline eng_dd eng_ddv_dot_d(eng_ddv a, rc_vec3 n)
{
    return eng_dd_add(eng_dd_add(eng_dd_mul_d(a.x, n.x), eng_dd_mul_d(a.y, n.y)),
                      eng_dd_mul_d(a.z, n.z));
}

static inline eng_dd eng_ddv_dot(eng_ddv a, eng_ddv b)
{
    return eng_dd_add(eng_dd_add(eng_dd_mul(a.x, b.x), eng_dd_mul(a.y, b.y)), eng_dd_mul(a.z, b.z));
}

static inline eng_dd eng_ddv_norm2(eng_ddv a) { return eng_ddv_dot(a, a); }

#endif
