/* eos_lattice.h — a start for any N at every fluid packing: the close-packed lattice (fcc
 * in 3-D, triangular in 2-D) with as many cells along each edge of the periodic cube as
 * keep its nearest sites farthest apart, filled on random sites. rc_sim_gas_init's cubic
 * lattice rounds N up to side^dim sites and so runs out of room below the freezing packing
 * (3-D 0.494, 2-D ~0.70) for most N; this one reaches 0.74 / 0.91 with N on every site
 * and the fluid's packings for any N. */
#ifndef RELCOL_EOS_LATTICE_H
#define RELCOL_EOS_LATTICE_H

#include <math.h>
#include <stdlib.h>

#include "relcol/relcol.h"

/* The unit cell's sites in units of its edges (a_x, a_y, a_z): fcc 4, the rectangular
 * cell of the triangular lattice 2 (a_y = sqrt(3) a_x when square-ish). */
static const double eos_fcc_basis[4][3] = {{0, 0, 0}, {0.5, 0.5, 0}, {0.5, 0, 0.5}, {0, 0.5, 0.5}};
static const double eos_tri_basis[2][3] = {{0, 0, 0}, {0.5, 0.5, 0}};

/* Nearest distance between sites of a lattice of k[d] cells along each edge L of the
 * periodic cube: the smallest of the edges and the basis offsets' half diagonals. */
static inline double eos_lattice_nn(int dim, const int *k, double L)
{
    const double a[3] = {L / k[0], L / k[1], dim == 3 ? L / k[2] : INFINITY};
    double nn = fmin(a[0], fmin(a[1], a[2]));
    nn = fmin(nn, 0.5 * hypot(a[0], a[1]));
    if (dim == 3)
        nn = fmin(nn, fmin(0.5 * hypot(a[0], a[2]), 0.5 * hypot(a[1], a[2])));
    return nn;
}

/* n centres x[] in the periodic cube of edge L, on random sites of the lattice whose
 * nearest sites are farthest apart; *nn gets that distance. -1 when no lattice of the
 * kind holds n sites more than `dmin` apart, or out of memory. */
static inline int eos_lattice(int dim, size_t n, double L, double dmin, uint64_t seed,
                              rc_vec3 *x, double *nn)
{
    const int nb = dim == 3 ? 4 : 2;
    const int kmax = (int)ceil(L / (0.5 * dmin)) + 1; /* beyond it a cell is too small */
    int best[3] = {0, 0, 1};
    double bestnn = 0.0;
    for (int kx = 1; kx <= kmax; kx++)
        for (int ky = 1; ky <= kmax; ky++)
            for (int kz = 1; kz <= (dim == 3 ? kmax : 1); kz++) {
                const int k[3] = {kx, ky, kz};
                if ((size_t)nb * (size_t)kx * (size_t)ky * (size_t)kz < n)
                    continue;
                const double d = eos_lattice_nn(dim, k, L);
                if (d > bestnn) {
                    bestnn = d;
                    best[0] = kx;
                    best[1] = ky;
                    best[2] = kz;
                }
            }
    *nn = bestnn;
    if (!(bestnn > dmin))
        return -1;
    const size_t sites = (size_t)nb * best[0] * best[1] * best[2];
    size_t *perm = malloc(sites * sizeof *perm);
    if (!perm)
        return -1;
    for (size_t i = 0; i < sites; i++)
        perm[i] = i;
    rc_rng R = {seed};
    for (size_t i = sites - 1; i > 0; i--) { /* Fisher-Yates */
        const size_t j = (size_t)(rc_rng_uniform(&R) * (double)(i + 1));
        const size_t t = perm[i];
        perm[i] = perm[j];
        perm[j] = t;
    }
    const double a[3] = {L / best[0], L / best[1], L / best[2]};
    for (size_t i = 0; i < n; i++) {
        const size_t s = perm[i], c = s / (size_t)nb, q = s % (size_t)nb;
        const size_t ix = c % (size_t)best[0], iy = (c / (size_t)best[0]) % (size_t)best[1];
        const size_t iz = c / ((size_t)best[0] * (size_t)best[1]);
        const double *o = dim == 3 ? eos_fcc_basis[q] : eos_tri_basis[q];
        /* a quarter cell in from the walls' images: no site on the box edge */
        x[i] = rc_v3((ix + o[0] + 0.25) * a[0], (iy + o[1] + 0.25) * a[1],
                     dim == 3 ? (iz + o[2] + 0.25) * a[2] : 0.0);
    }
    free(perm);
    return 0;
}

#endif
