/* engine/moments.c — the momentum and energy a collision carries across space, for the
 * collisional virial and Helfand moments (papers/pressure.md, papers/transport.md): sum_b x_b
 * (x) dp_b from the event's first ball with nearest images, the unwrapped difference kept
 * apart so the moments stay continuous with the flux. */
#include <math.h>
#include <string.h>

#include "private.h"
#include "relcol/moments.h"
#include "relcol/status.h"

void eng_moments_add(rc_sim *s, size_t nm, const int32_t *mem, const rc_particle *before,
                     const rc_particle *after)
{
    if (nm < 2)
        return; /* a lone ball at walls: its origin is itself, the moments are zero */
    const int32_t o = mem[0];
    const rc_vec3 xo = s->b[o].x;
    for (size_t j = 1; j < nm; j++) {
        const int32_t b = mem[j];
        const rc_vec3 dx = rc_v3_sub(s->b[b].x, xo);
        double r[3], w[3];
        for (int d = 0; d < 3; d++) {
            const double x = rc_v3_get(dx, d);
            const double k = eng_rint(x * s->inv_L[d]); /* 0 on walled axes */
            r[d] = x - s->L[d] * k;
            /* nearest image minus unwrapped: -(k + image_b - image_o) L */
            const double im = s->img ? (double)(s->img[3 * (size_t)b + (size_t)d] -
                                                s->img[3 * (size_t)o + (size_t)d])
                                     : 0.0;
            w[d] = -(k + im) * s->L[d];
        }
        const rc_particle bf = before ? before[j] : (rc_particle){s->a[b].m, s->a[b].p};
        const rc_vec3 dp = rc_v3_sub(after[j].p, bf.p);
        const double Mb = eng_mass_rel(bf.m, bf.p, s->inv_c2);
        const double Ma = eng_mass_rel(after[j].m, after[j].p, s->inv_c2);
        /* kinetic energy change, (M - m) c^2 = p^2 / (M + m) without cancellation */
        const double dE = rc_v3_norm2(after[j].p) / (Ma + after[j].m) -
                          rc_v3_norm2(bf.p) / (Mb + bf.m);
        const double q[3] = {dp.x, dp.y, dp.z};
        for (int a = 0; a < 3; a++) {
            for (int c = 0; c < 3; c++) {
                s->bk.vir[3 * a + c] += r[a] * q[c];
                s->bk.wrap[3 * a + c] += w[a] * q[c];
            }
            s->bk.vir_e[a] += r[a] * dE;
            s->bk.wrap_e[a] += w[a] * dE;
        }
    }
}

int rc_sim_moments_get(const rc_sim *s, rc_sim_moments *out)
{
    if (!s || !out)
        return RC_EINVAL;
    if (s->def.gravity)
        return RC_EUNDEFINED; /* the field's loop books no collisional transfer, and G's rate is not the pressure there */
    memset(out, 0, sizeof *out);
    int st;
    const int dim = s->def.dim;
    const rc_vec3 box = s->def.box;
    const double inv_c2 = s->inv_c2;
    out->time = rc_sim_time(s);
    out->n = rc_sim_count(s);
    out->dim = dim;
    out->volume = box.x * box.y * (dim == 3 ? box.z : 1.0);
    const double L[3] = {box.x, box.y, box.z};
    for (size_t i = 0; i < out->n; i++) {
        rc_sim_ball b;
        if ((st = rc_sim_get_ball(s, i, &b)) != RC_OK)
            return st;
        const double M = eng_mass_rel(b.m, b.p, inv_c2);
        const double E = rc_v3_norm2(b.p) / (M + b.m);
        const double x[3] = {b.x.x + b.image[0] * L[0], b.x.y + b.image[1] * L[1],
                             b.x.z + b.image[2] * L[2]};
        const double p[3] = {b.p.x, b.p.y, b.p.z};
        for (int a = 0; a < 3; a++) {
            for (int k = 0; k < 3; k++) {
                out->kinetic[3 * a + k] += p[a] * p[k] / M;
                out->helfand[3 * a + k] += x[a] * p[k];
            }
            out->helfand_energy[a] += x[a] * E;
            out->position[a] += x[a];
        }
        out->energy += E;
    }
    /* (the bookkeeping directly: rc_sim_diagnostics would also search every ball's
     * neighbours for overlaps) */
    for (int j = 0; j < 9; j++) {
        out->virial[j] = s->bk.vir[j];
        out->helfand[j] += s->bk.wrap[j];
    }
    for (int a = 0; a < 3; a++) {
        out->virial_energy[a] = s->bk.vir_e[a];
        out->helfand_energy[a] += s->bk.wrap_e[a];
    }
    return RC_OK;
}
