/* law_table.c — the table of collision laws, the validating and batch entry points,
 * the wall law and the impact-angle draw. Add a law here: one line in rc_laws[]. */
#include <math.h>
#include <string.h>

#include "relcol/law.h"
#include "relcol/status.h"

const rc_law *const rc_laws[] = {
    &rc_law_zmf,
    &rc_law_cm_isotropic,
    NULL,
};

const rc_law *rc_law_find(const char *name)
{
    if (!name)
        return NULL;
    for (size_t i = 0; rc_laws[i]; i++)
        if (strcmp(rc_laws[i]->name, name) == 0)
            return rc_laws[i];
    return NULL;
}

rc_collision_params rc_collision_params_default(void)
{
    rc_collision_params p = {INFINITY, 1.0, NAN, 0.0, RC_GROUPS_SIMULTANEOUS};
    return p;
}

/* The checks of rc_collide that concern the parameters alone (once per batch). */
static int check_params(const rc_collision_params *prm, double *inv_c2)
{
    if (rc_inv_c2(prm->c, inv_c2) != RC_OK)
        return RC_ESPEEDOFLIGHT;
    if (!(prm->eps >= 0.0 && prm->eps <= 1.0))
        return RC_ERESTITUTION;
    if (!isnan(prm->alpha) &&
        (!isfinite(prm->alpha) || !(fabs(prm->alpha) < M_PI / 2) || !isfinite(prm->azimuth)))
        return RC_EINVAL;
    return RC_OK;
}

static inline int unit_normal(rc_vec3 *n);

/* The checks of one pair whose particles passed rc_particle_check, and its normal
 * made unit. */
static int check_pair(const rc_particle *a, const rc_particle *b, rc_vec3 *n, double k)
{
    /* m^2 + p^2/c^2 must not overflow: the kernels' comparisons would see NaN (tested
     * before the square root of rc_mass_rel, which is finite exactly when it is) */
    if (!isfinite(a->m * a->m + rc_v3_norm2(a->p) * k) ||
        !isfinite(b->m * b->m + rc_v3_norm2(b->p) * k) ||
        !isfinite(rc_v3_norm2(rc_v3_add(a->p, b->p))))
        return RC_ENONFINITE;
    if (!rc_v3_isfinite(*n))
        return RC_ENONFINITE;
    return unit_normal(n);
}

/* A finite normal made unit as rc_collide makes it (RC_EZERONORMAL for 0). */
static inline int unit_normal(rc_vec3 *n)
{
    /* (any finite length: a normal of 1e300 or 1e-300 is a direction like any other; one
     * of length exactly 1 is already what rc_v3_unit would make of it) */
    const double n2 = rc_v3_norm2(*n);
    if (n2 == 1.0)
        return RC_OK;
    double len = rc_v3_norm_safe(*n);
    if (!(len > 0.0))
        return RC_EZERONORMAL;
    *n = rc_v3_unit(*n, len);
    return RC_OK;
}

int rc_pair_check(const rc_particle *a, const rc_particle *b, rc_vec3 *n, double inv_c2)
{
    if (!a || !b || !n)
        return RC_EINVAL;
    return check_pair(a, b, n, inv_c2);
}

/* The group rules by their enum value (relcol/law.h). */
static const struct {
    const char *name, *summary;
} group_rules[] = {
    {"simultaneous", "all impulses together, none pulling (complementarity); default"},
    {"sequential", "one contact after another in the order of the group's ZMF times"},
    {"drop", "joint solve; the most pulling contact dropped until none pulls, not re-checked"},
};

const char *rc_group_rule_name(int rule)
{
    return rule >= 0 && rule < (int)(sizeof group_rules / sizeof *group_rules)
               ? group_rules[rule].name
               : NULL;
}

const char *rc_group_rule_summary(int rule)
{
    return rc_group_rule_name(rule) ? group_rules[rule].summary : NULL;
}

int rc_group_rule_find(const char *name)
{
    for (int r = 0; name && rc_group_rule_name(r); r++)
        if (strcmp(group_rules[r].name, name) == 0)
            return r;
    return -1;
}

int rc_collide(const rc_law *law, const rc_collision_params *prm, rc_particle *a,
               rc_particle *b, rc_vec3 n)
{
    if (!law || !prm || !a || !b)
        return RC_EINVAL;
    int st;
    double k;
    if ((st = rc_particle_check(a)) != RC_OK || (st = rc_particle_check(b)) != RC_OK)
        return st;
    if ((st = check_params(prm, &k)) != RC_OK || (st = check_pair(a, b, &n, k)) != RC_OK)
        return st;
    return law->collide(prm, a, b, n);
}

int rc_collide_many(const rc_law *law, const rc_collision_params *prm, size_t n_pairs,
                    double *m0, rc_vec3 *p0, double *m1, rc_vec3 *p1, const rc_vec3 *n,
                    int *status, size_t *hits, size_t *bad)
{
    if (hits)
        *hits = 0;
    if (bad)
        *bad = 0;
    if (!law || !law->collide || !prm || (n_pairs && (!m0 || !p0 || !m1 || !p1 || !n)))
        return RC_EINVAL;
    double k;
    int st = check_params(prm, &k);
    if (st != RC_OK)
        return st;
    const rc_law_fn f = law->collide;
    size_t h = 0;
    for (size_t i = 0; i < n_pairs; i++) {
        rc_particle a = {m0[i], p0[i]}, b = {m1[i], p1[i]};
        rc_vec3 ni = n[i];
        int r;
        if ((r = rc_particle_check(&a)) != RC_OK || (r = rc_particle_check(&b)) != RC_OK ||
            (r = check_pair(&a, &b, &ni, k)) != RC_OK || (r = f(prm, &a, &b, ni)) < 0) {
            st = r;
            if (bad)
                *bad = i;
            break;
        }
        m0[i] = a.m;
        p0[i] = a.p;
        m1[i] = b.m;
        p1[i] = b.p;
        h += (r == RC_OK);
        if (status)
            status[i] = r;
    }
    if (hits)
        *hits = h;
    return st;
}

/* Pairs checked at a time: the block's branch-free pass stays in the cache for its
 * kernels. */
#define COLUMNS_BLOCK 256

static inline rc_vec3 load3(const double *v, int dim)
{
    return rc_v3(v[0], dim > 1 ? v[1] : 0.0, dim > 2 ? v[2] : 0.0);
}

static inline void store3(double *out, rc_vec3 v, int dim)
{
    out[0] = v.x;
    if (dim > 1)
        out[1] = v.y;
    if (dim > 2)
        out[2] = v.z;
}

/* int-valued tests, so that the branch-free '&' below combines ints, not comparisons */
static inline int fin(double x) { return isfinite(x) ? 1 : 0; }
static inline int pos(double x) { return x > 0.0 ? 1 : 0; }
static inline int nonzero3(rc_vec3 v) { return (v.x != 0.0 || v.y != 0.0 || v.z != 0.0) ? 1 : 0; }

static inline int finite3(rc_vec3 v) { return fin(v.x) & fin(v.y) & fin(v.z); }

/* 1 when every pair of [from, from + count) passes rc_collide's checks (particles, pair,
 * normal nonzero), by one branch-free pass (no early exit: the compiler may vectorise);
 * 0 means some pair fails, found again pair by pair with the exact checks. */
static int block_ok(size_t from, size_t count, int dim, double k, const double *m0, size_t s0,
                    const double *p0, size_t q0, const double *m1, size_t s1, const double *p1,
                    size_t q1, const double *nrm, size_t sn)
{
    int ok = 1;
    for (size_t i = from; i < from + count; i++) {
        const double ma = m0[i * s0], mb = m1[i * s1];
        const rc_vec3 pa = load3(p0 + i * q0, dim), pb = load3(p1 + i * q1, dim);
        const rc_vec3 n = load3(nrm + i * sn, dim);
        ok &= fin(ma) & fin(mb) & pos(ma) & pos(mb) & finite3(pa) &
              finite3(pb) & fin(ma * ma + rc_v3_norm2(pa) * k) &
              fin(mb * mb + rc_v3_norm2(pb) * k) & fin(rc_v3_norm2(rc_v3_add(pa, pb))) &
              finite3(n) & nonzero3(n);
    }
    return ok;
}

int rc_collide_columns(const rc_law *law, const rc_collision_params *prm, size_t n_pairs,
                       int dim, const double *m0, size_t m0_stride, const double *p0,
                       size_t p0_stride, const double *m1, size_t m1_stride, const double *p1,
                       size_t p1_stride, const double *nrm, size_t n_stride, double *m0o,
                       double *p0o, double *m1o, double *p1o, int *status, size_t *hits,
                       size_t *bad)
{
    if (hits)
        *hits = 0;
    if (bad)
        *bad = 0;
    if (!law || !law->collide || !prm || dim < 1 || dim > 3 ||
        (n_pairs && (!m0 || !p0 || !m1 || !p1 || !nrm || !m0o || !p0o || !m1o || !p1o)))
        return RC_EINVAL;
    double k;
    int st = check_params(prm, &k);
    if (st != RC_OK)
        return st;
    const rc_law_fn f = law->collide;
    size_t h = 0;
    for (size_t from = 0; from < n_pairs && st == RC_OK; from += COLUMNS_BLOCK) {
        const size_t count = n_pairs - from < COLUMNS_BLOCK ? n_pairs - from : COLUMNS_BLOCK;
        const int checked = block_ok(from, count, dim, k, m0, m0_stride, p0, p0_stride, m1,
                                     m1_stride, p1, p1_stride, nrm, n_stride);
        for (size_t i = from; i < from + count; i++) {
            rc_particle a = {m0[i * m0_stride], load3(p0 + i * p0_stride, dim)};
            rc_particle b = {m1[i * m1_stride], load3(p1 + i * p1_stride, dim)};
            rc_vec3 ni = load3(nrm + i * n_stride, dim);
            int r;
            if (checked ? (r = unit_normal(&ni)) != RC_OK
                        : ((r = rc_particle_check(&a)) != RC_OK ||
                           (r = rc_particle_check(&b)) != RC_OK ||
                           (r = check_pair(&a, &b, &ni, k)) != RC_OK)) {
                st = r;
            } else if ((r = f(prm, &a, &b, ni)) < 0) {
                st = r;
            }
            if (st != RC_OK) {
                if (bad)
                    *bad = i;
                break;
            }
            m0o[i] = a.m;
            m1o[i] = b.m;
            store3(p0o + i * (size_t)dim, a.p, dim);
            store3(p1o + i * (size_t)dim, b.p, dim);
            if (status)
                status[i] = r;
            h += r == RC_OK;
        }
    }
    if (hits)
        *hits = h;
    return st;
}

size_t rc_collide_batch(const rc_law *law, const rc_collision_params *prm, size_t n_pairs,
                        rc_particle *a, rc_particle *b, const rc_vec3 *n, int *status)
{
    size_t hits = 0;
    const rc_law_fn f = law->collide;
    for (size_t i = 0; i < n_pairs; i++) {
        int st = f(prm, &a[i], &b[i], n[i]);
        hits += (st == RC_OK);
        if (status)
            status[i] = st;
    }
    return hits;
}

int rc_collide_wall(double inv_c2, double eps_w, rc_particle *a, rc_vec3 n)
{
    if (!a)
        return RC_EINVAL;
    int st = rc_particle_check(a);
    if (st != RC_OK)
        return st;
    if (!(inv_c2 >= 0.0) || isinf(inv_c2))
        return RC_ESPEEDOFLIGHT;
    if (!(eps_w >= 0.0 && eps_w <= 1.0))
        return RC_ERESTITUTION;
    if (!rc_v3_isfinite(n))
        return RC_ENONFINITE;
    const double len = rc_v3_norm_safe(n);
    if (!(len > 0.0))
        return RC_EZERONORMAL;
    if (len != 1.0)
        n = rc_v3_unit(n, len);
    const double pn = rc_v3_dot(a->p, n);
    if (!(pn > 0.0))
        return RC_NO_COLLISION;
    a->p = rc_v3_axpy(a->p, -(1.0 + eps_w) * pn, n);
    if (eps_w != 1.0)
        a->m = sqrt(a->m * a->m + (1.0 - eps_w * eps_w) * pn * pn * inv_c2);
    return RC_OK;
}

void rc_impact_angle_draw(int dim, double u1, double u2, double *alpha, double *azimuth)
{
    if (dim <= 1) {
        *alpha = 0.0;
        *azimuth = 0.0;
    } else if (dim == 2) {
        *alpha = asin(2.0 * u1 - 1.0);
        *azimuth = 0.0;
    } else {
        *alpha = asin(sqrt(u1));
        *azimuth = 2.0 * M_PI * u2;
    }
}
