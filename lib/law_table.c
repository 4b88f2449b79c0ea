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
    rc_collision_params p = {INFINITY, 1.0, NAN, 0.0};
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

/* The checks of one pair whose particles passed rc_particle_check, and its normal
 * made unit. */
static int check_pair(const rc_particle *a, const rc_particle *b, rc_vec3 *n, double k)
{
    /* m^2 + p^2/c^2 must not overflow: the kernels' comparisons would see NaN */
    if (!isfinite(rc_mass_rel(a->m, a->p, k)) || !isfinite(rc_mass_rel(b->m, b->p, k)) ||
        !isfinite(rc_v3_norm2(rc_v3_add(a->p, b->p))))
        return RC_ENONFINITE;
    if (!rc_v3_isfinite(*n))
        return RC_ENONFINITE;
    /* (any finite length: a normal of 1e300 or 1e-300 is a direction like any other) */
    double len = rc_v3_norm_safe(*n);
    if (!(len > 0.0))
        return RC_EZERONORMAL;
    *n = rc_v3_unit(*n, len);
    return RC_OK;
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
                    rc_particle *a, rc_particle *b, const rc_vec3 *n, int *status,
                    size_t *hits, size_t *bad)
{
    if (hits)
        *hits = 0;
    if (bad)
        *bad = 0;
    if (!law || !law->collide || !prm || (n_pairs && (!a || !b || !n)))
        return RC_EINVAL;
    double k;
    int st = check_params(prm, &k);
    if (st != RC_OK)
        return st;
    const rc_law_fn f = law->collide;
    size_t h = 0;
    for (size_t i = 0; i < n_pairs; i++) {
        rc_vec3 ni = n[i];
        if ((st = rc_particle_check(&a[i])) != RC_OK ||
            (st = rc_particle_check(&b[i])) != RC_OK ||
            (st = check_pair(&a[i], &b[i], &ni, k)) != RC_OK) {
            if (bad)
                *bad = i;
            break;
        }
        const int r = f(prm, &a[i], &b[i], ni);
        if (r < 0) {
            st = r;
            if (bad)
                *bad = i;
            break;
        }
        h += (r == RC_OK);
        if (status)
            status[i] = r;
    }
    if (hits)
        *hits = h;
    return st < 0 ? st : RC_OK;
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
