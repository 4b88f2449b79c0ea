/* freestream.c — free streaming from two Juttner halves in a walled tube
 * (papers/shock-tube.md, section 4). */
#include <math.h>

#include <gsl/gsl_errno.h>
#include <gsl/gsl_integration.h>
#include <gsl/gsl_sf_bessel.h>

#include "freestream.h"

enum { W_N0 = 0, W_NX, W_G, W_K, W_PXX, W_PYY, W_N };

/* transverse integrals, scaled by e^{a}: 3-D E_k = Int_1^inf t^k e^{-a (t-1)} dt, 2-D
 * J_k = Int_1^inf t^k e^{-a (t-1)} / sqrt(t^2 - 1) dt */
static void transverse(int dim, double a, double *k1, double *k2, double *k3)
{
    if (dim == 3) {
        const double ia = 1.0 / a;
        *k1 = ia + ia * ia;
        *k2 = ia + 2.0 * ia * ia + 2.0 * ia * ia * ia;
        *k3 = ia + 3.0 * ia * ia + 6.0 * ia * ia * ia + 6.0 * ia * ia * ia * ia;
    } else {
        const double K0 = gsl_sf_bessel_K0_scaled(a), K1 = gsl_sf_bessel_K1_scaled(a);
        *k1 = K1;
        *k2 = K0 + K1 / a;
        *k3 = K1 + K0 / a + 2.0 * K1 / (a * a);
    }
}

typedef struct {
    int dim, w;
    double th, yu; /* the half's rest-frame theta and its flow rapidity */
} fs_prm;

/* the weight w's integrand in the longitudinal rapidity y (c = 1, m = 1), with the
 * common factor e^{-1/theta} dropped. A flow of rapidity yu along x: the Juttner factor
 * e^{-u.p/theta} = e^{-m_T cosh(y - yu)/theta}, the lab measure and weights in y itself */
static double fs_integrand(double y, void *v)
{
    const fs_prm *q = v;
    const double ch = cosh(y), sh = sinh(y), yr = y - q->yu, a = cosh(yr) / q->th;
    const double damp = 2.0 * sinh(0.5 * yr) * sinh(0.5 * yr) / q->th; /* (cosh yr - 1)/theta */
    if (damp > 700.0)
        return 0.0;
    double k1, k2, k3;
    transverse(q->dim, a, &k1, &k2, &k3);
    double f;
    switch (q->w) {
    case W_N0: f = ch * k2; break;
    case W_NX: f = sh * k2; break;
    case W_G: f = sh * ch * k3; break;
    case W_K: f = ch * ch * k3 - ch * k2; break;
    case W_PXX: f = sh * sh * k3; break;
    default: f = q->dim == 3 ? 0.5 * (k3 - k1) : k3 - k1; break; /* q_y^2 */
    }
    return f * exp(-damp);
}

/* Int over y in (y0, y1) of weight w for one half at theta; y may be +-inf. scale: the
 * size of the whole integral (0: unknown), to which the absolute tolerance is set, so that
 * a far tail's tiny part is not asked for digits below the whole's round-off */
static int fs_yint(int dim, double th, double yu, int w, double y0, double y1, double scale,
                   double *out)
{
    const double ymax = acosh(1.0 + 750.0 * th);
    y0 = fmax(y0, yu - ymax);
    y1 = fmin(y1, yu + ymax);
    if (!(y1 > y0)) {
        *out = 0.0;
        return 0;
    }
    fs_prm q = {dim, w, th, yu};
    gsl_function F = {fs_integrand, &q};
    gsl_integration_workspace *ws = gsl_integration_workspace_alloc(200);
    if (!ws)
        return RS_ENOCONV;
    double r, err;
    const double tol = 1e-13 * scale;
    int st = gsl_integration_qag(&F, y0, y1, tol, 1e-10, 200, GSL_INTEG_GAUSS31, ws, &r, &err);
    gsl_integration_workspace_free(ws);
    *out = r;
    return st == GSL_SUCCESS || (st == GSL_EROUND && err < 1e-8 * fabs(r) + 1e3 * tol) ? 0 : RS_ENOCONV;
}

/* classical: the moments per ball of the velocities v in (a, b) of Maxwell at T (m = 1)
 * drifting at u: those of the thermal part w = v - u in (a - u, b - u), shifted */
static void fs_maxwell(int dim, double T, double u, double a, double b, double *mo)
{
    a -= u, b -= u;
    const double s = sqrt(T), al = a / s, be = b / s;
    const double Pa = isinf(al) ? (al < 0 ? 0.0 : 1.0) : 0.5 * erfc(-al / M_SQRT2);
    const double Pb = isinf(be) ? (be < 0 ? 0.0 : 1.0) : 0.5 * erfc(-be / M_SQRT2);
    const double pa = isinf(al) ? 0.0 : exp(-0.5 * al * al) / sqrt(2.0 * M_PI);
    const double pb = isinf(be) ? 0.0 : exp(-0.5 * be * be) / sqrt(2.0 * M_PI);
    const double P = Pb - Pa;
    const double m1 = s * (pa - pb);                                   /* Int v */
    const double m2 = T * (P + (isinf(al) ? 0.0 : al * pa) - (isinf(be) ? 0.0 : be * pb)); /* Int v^2 */
    const double v1 = u * P + m1, v2 = u * u * P + 2.0 * u * m1 + m2; /* Int v, Int v^2 */
    mo[W_N0] = P;
    mo[W_NX] = v1;
    mo[W_G] = v1;
    mo[W_PXX] = v2;
    mo[W_K] = 0.5 * v2 + 0.5 * (dim - 1) * T * P;
    mo[W_PYY] = T * P;
}

/* one half's moments per rest-frame ball for the velocities in (va, vb) (table units),
 * the half drifting at u (its own v, or -v in a wall's mirror image) */
static int fs_half(const fs_def *d, int side, double u, double va, double vb, double *mo)
{
    const double T = d->T[side];
    if (isinf(d->c)) {
        fs_maxwell(d->dim, T, u, va, vb, mo);
        return 0;
    }
    const double c = d->c, th = T / (c * c), yu = atanh(u / c);
    const double y0 = va <= -c ? -INFINITY : atanh(va / c), y1 = vb >= c ? INFINITY : atanh(vb / c);
    double z, zk;
    /* normalised at rest: a drifting half's N0 over all y is then W = cosh yu per ball */
    int rc = fs_yint(d->dim, th, 0.0, W_N0, -INFINITY, INFINITY, 0.0, &z);
    if (!rc) /* the energy weights' scale: the whole K, Pxx (~ theta z) */
        rc = fs_yint(d->dim, th, 0.0, W_PXX, -INFINITY, INFINITY, 0.0, &zk);
    if (rc)
        return rc;
    const double big = cosh(yu) * cosh(yu);
    for (int w = 0; w < W_N; w++) {
        if ((rc = fs_yint(d->dim, th, yu, w, y0, y1, big * (w == W_N0 || w == W_NX ? z : fmax(z, zk)), &mo[w])))
            return rc;
        mo[w] /= z;
    }
    /* to table units: v = c tanh y, p = c (...), E - m c^2 and p v = c^2 (...) */
    mo[W_NX] *= c;
    mo[W_G] *= c;
    mo[W_K] *= c * c;
    mo[W_PXX] *= c * c;
    mo[W_PYY] *= c * c;
    return 0;
}

int fs_moments(const fs_def *d, double x, double t, sh_mom *out)
{
    double acc[W_N] = {0};
    const double P = 2.0 * d->L;
    for (int side = 0; side < 2; side++)
        for (int img = 0; img < 2; img++) {
            /* the half (img 0) and its mirror image in a wall (img 1, velocity reversed):
             * side L: (0, x0) and (-x0, 0); side R: (x0, L) and (L, P - x0); + kP */
            const double lo0 = side ? (img ? d->L : d->x0) : (img ? -d->x0 : 0.0);
            const double hi0 = side ? (img ? P - d->x0 : d->L) : (img ? 0.0 : d->x0);
            const double u = img ? -d->v[side] : d->v[side];
            const double reach = isinf(d->c) ? 40.0 * sqrt(d->T[side]) * t + fabs(u) * t : d->c * t;
            double mo[W_N];
            if (t <= 0.0) {
                /* at t = 0 the point x itself: the image it lies in */
                const double xm = fmod(fmod(x, P) + P, P), xs = xm > P - d->x0 ? xm - P : xm;
                if (xs > lo0 && xs < hi0) {
                    int rc = fs_half(d, side, u, -INFINITY, INFINITY, mo);
                    if (rc)
                        return rc;
                    for (int w = 0; w < W_N; w++)
                        acc[w] += d->n[side] * mo[w];
                }
                continue;
            }
            const long kmin = (long)floor((x - reach - hi0) / P), kmax = (long)ceil((x + reach - lo0) / P);
            for (long k = kmin; k <= kmax; k++) {
                const double ylo = lo0 + k * P, yhi = hi0 + k * P;
                /* the ball at x came from y = x - v t: v in ((x - yhi)/t, (x - ylo)/t) */
                double va = (x - yhi) / t, vb = (x - ylo) / t;
                if (!isinf(d->c)) {
                    va = fmax(va, -d->c);
                    vb = fmin(vb, d->c);
                }
                if (!(vb > va))
                    continue;
                int rc = fs_half(d, side, u, va, vb, mo);
                if (rc)
                    return rc;
                for (int w = 0; w < W_N; w++)
                    acc[w] += d->n[side] * mo[w];
            }
        }
    out->N0 = acc[W_N0];
    out->Nx = acc[W_NX];
    out->g = acc[W_G];
    out->K = acc[W_K];
    out->Pxx = acc[W_PXX];
    out->Pyy = acc[W_PYY];
    return 0;
}

typedef struct {
    const fs_def *d;
    double t;
} fs_at_ctx;

static int fs_at(double x, void *v, sh_mom *out)
{
    const fs_at_ctx *q = v;
    return fs_moments(q->d, x, q->t, out);
}

int fs_moments_bin(const fs_def *d, double xa, double xb, double t, sh_mom *out)
{
    fs_at_ctx q = {d, t};
    return sh_mom_bin(fs_at, &q, xa, xb, out);
}
