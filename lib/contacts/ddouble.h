/* contacts/ddouble.h — double-double arithmetic (a value as an unevaluated sum hi + lo,
 * |lo| <= ulp(hi)/2, about 106 bits): for the few sums whose terms cancel to order gamma^2
 * near c, where double keeps none of the result's digits and double-double keeps ~53 at
 * gamma 1e8. Error-free transformations (Knuth's two-sum, fma's exact product error) with
 * -ffp-contract=off, so the same bits on every machine. */
#ifndef RELCOL_CONTACTS_DDOUBLE_H
#define RELCOL_CONTACTS_DDOUBLE_H

#include <math.h>

typedef struct ctc_dd {
    double hi, lo;
} ctc_dd;

static inline ctc_dd ctc_dd_of(double a) { return (ctc_dd){a, 0.0}; }

static inline ctc_dd ctc_two_sum(double a, double b)
{
    const double s = a + b, bb = s - a;
    return (ctc_dd){s, (a - (s - bb)) + (b - bb)};
}

static inline ctc_dd ctc_two_prod(double a, double b)
{
    const double p = a * b;
    return (ctc_dd){p, fma(a, b, -p)};
}

static inline ctc_dd ctc_dd_norm(double hi, double lo)
{
    const double s = hi + lo;
    return (ctc_dd){s, lo - (s - hi)};
}

static inline ctc_dd ctc_dd_add(ctc_dd a, ctc_dd b)
{
    const ctc_dd s = ctc_two_sum(a.hi, b.hi), t = ctc_two_sum(a.lo, b.lo);
    ctc_dd r = ctc_dd_norm(s.hi, s.lo + t.hi);
    return ctc_dd_norm(r.hi, r.lo + t.lo);
}

static inline ctc_dd ctc_dd_neg(ctc_dd a) { return (ctc_dd){-a.hi, -a.lo}; }

static inline ctc_dd ctc_dd_sub(ctc_dd a, ctc_dd b) { return ctc_dd_add(a, ctc_dd_neg(b)); }

static inline ctc_dd ctc_dd_mul(ctc_dd a, ctc_dd b)
{
    const ctc_dd p = ctc_two_prod(a.hi, b.hi);
    return ctc_dd_norm(p.hi, p.lo + (a.hi * b.lo + a.lo * b.hi));
}

static inline ctc_dd ctc_dd_mul_d(ctc_dd a, double b)
{
    const ctc_dd p = ctc_two_prod(a.hi, b);
    return ctc_dd_norm(p.hi, p.lo + a.lo * b);
}

static inline ctc_dd ctc_dd_div(ctc_dd a, ctc_dd b)
{
    const double q1 = a.hi / b.hi;
    const ctc_dd r = ctc_dd_sub(a, ctc_dd_mul_d(b, q1));
    const double q2 = r.hi / b.hi;
    const ctc_dd r2 = ctc_dd_sub(r, ctc_dd_mul_d(b, q2));
    return ctc_dd_add(ctc_two_sum(q1, q2), ctc_dd_of(r2.hi / b.hi));
}

/* sqrt(a), a > 0: one Newton step from the double root */
static inline ctc_dd ctc_dd_sqrt(ctc_dd a)
{
    const double x = sqrt(a.hi);
    const ctc_dd r = ctc_dd_sub(a, ctc_two_prod(x, x));
    return ctc_dd_norm(x, r.hi / (2.0 * x));
}

/* a.b of two double vectors, each product exact */
static inline ctc_dd ctc_dd_dot(rc_vec3 a, rc_vec3 b)
{
    return ctc_dd_add(ctc_dd_add(ctc_two_prod(a.x, b.x), ctc_two_prod(a.y, b.y)),
                      ctc_two_prod(a.z, b.z));
}

typedef struct ctc_ddv {
    ctc_dd x, y, z;
} ctc_ddv;

static inline ctc_ddv ctc_ddv_of(rc_vec3 v)
{
    return (ctc_ddv){ctc_dd_of(v.x), ctc_dd_of(v.y), ctc_dd_of(v.z)};
}

/* a + s n, s and n doubles */
static inline ctc_ddv ctc_ddv_axpy(ctc_ddv a, double s, rc_vec3 n)
{
    return (ctc_ddv){ctc_dd_add(a.x, ctc_two_prod(s, n.x)), ctc_dd_add(a.y, ctc_two_prod(s, n.y)),
                     ctc_dd_add(a.z, ctc_two_prod(s, n.z))};
}

static inline ctc_dd ctc_ddv_dot_d(ctc_ddv a, rc_vec3 n)
{
    return ctc_dd_add(ctc_dd_add(ctc_dd_mul_d(a.x, n.x), ctc_dd_mul_d(a.y, n.y)),
                      ctc_dd_mul_d(a.z, n.z));
}

static inline ctc_dd ctc_ddv_dot(ctc_ddv a, ctc_ddv b)
{
    return ctc_dd_add(ctc_dd_add(ctc_dd_mul(a.x, b.x), ctc_dd_mul(a.y, b.y)), ctc_dd_mul(a.z, b.z));
}

static inline ctc_dd ctc_ddv_norm2(ctc_ddv a) { return ctc_ddv_dot(a, a); }

#endif
