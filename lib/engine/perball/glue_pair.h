/* engine/perball/glue_pair.h — per_ball frames: two balls' contact on their glued world
 * tubes, as the narrow phase asks it (perball/narrow.c; papers/shape-change.md sections
 * 6-8). Static functions in a header so that the prediction's hot path keeps them inline. */
#ifndef RELCOL_ENGINE_GLUE_PAIR_H
#define RELCOL_ENGINE_GLUE_PAIR_H

#include <math.h>
#include <string.h>

#include "pair_zmf.h"
#include "../pairs.h"
#include "../private.h"
#include "relcol/status.h"

/* per_ball frames: on which side of each ball's last hyperplane a contact event X lies,
 * found t after tref: bit 0 X on bi's future side, bit 1 on bk's. y = X - (bi's centre at
 * tref), dx = bk - bi at tref (nearest image). (The prediction's glue_valid: both; a tube
 * conflict's pieces: which ball the incoming piece met is.) */
static inline int glue_sides(const rc_sim *s, const eng_ball *bi, const eng_ball *bk, rc_vec3 dx,
                             double tref, double t, rc_vec3 y)
{
    const double tx = tref + t;
    const rc_vec3 dxi = rc_v3_axpy(y, -t, bi->v);
    const rc_vec3 dxk = rc_v3_sub(y, rc_v3_axpy(dx, t, bk->v));
    const eng_cov *ci = &s->pb->cov[bi - s->b], *ck = &s->pb->cov[bk - s->b];
    return eng_glue_side(ci, &s->pb->glu[bi - s->b], bi->v, tx, dxi) |
           eng_glue_side(ck, &s->pb->glu[bk - s->b], bk->v, tx, dxk) << 1;
}

/* per_ball frames: is the contact event X, found t after tref, on the future side of
 * both balls' last hyperplanes (eng_glue_side)? y = X - (bi's centre at tref), dx = bk -
 * bi at tref (nearest image). */
static int glue_valid(const rc_sim *s, const eng_ball *bi, const eng_ball *bk, rc_vec3 dx,
                      double tref, double t, rc_vec3 y)
{
    return glue_sides(s, bi, bk, dx, tref, t, y) == 3;
}

/* per_ball frames: a ball whose kink lies ahead of now is stored at it, on its outgoing
 * line; that line's cylinder is the ball's tube on the future side of its hyperplane,
 * which can meet a neighbour before the kink's time. So the frame is asked from the
 * earlier clock, not before now (a contact there is on the extension beyond the tube
 * unless glue_valid says otherwise), rather than from the later one, from which a
 * contact in between would look like an overlap. A function of the two stored states
 * and now; the same bits whichever ball asks (dx, and the shift, change sign exactly). */
static inline void glue_reference(const rc_sim *s, const eng_ball *bi, const eng_ball *bk,
                                  rc_vec3 *dx, double *tref)
{
    if (!(*tref > s->now))
        return;
    double t0 = bi->t < bk->t ? bi->t : bk->t;
    t0 = t0 > s->now ? t0 : s->now;
    *dx = rc_v3_axpy(*dx, t0 - *tref, rc_v3_sub(bk->v, bi->v));
    *tref = t0;
}

/* The frame's contact of bi and bk from separation dx at time tref, in pair_time_dx's
 * orientation: out->n from bi to bk, out->x = X - (bi's centre at tref). */
static int frame_call(const rc_sim *cs, const eng_ball *bi, const eng_ball *bk, rc_vec3 dx,
                      rc_toi_contact *out)
{
    rc_sim *s = (rc_sim *)cs; /* (the workspace is scratch) */
    const int flip = dx.x < 0.0 || (dx.x == 0.0 && (dx.y < 0.0 || (dx.y == 0.0 && dx.z < 0.0)));
    const eng_ball *b0 = flip ? bk : bi, *b1 = flip ? bi : bk;
    const eng_aux *a0 = &s->a[b0 - s->b], *a1 = &s->a[b1 - s->b];
    const rc_toi_ball A = {rc_v3(0, 0, 0), b0->r, a0->m, a0->p};
    const rc_toi_ball B = {flip ? rc_v3_scale(-1.0, dx) : dx, b1->r, a1->m, a1->p};
    const int st = s->def.frame->toi(&s->toi, &A, &B, s->ws, out);
    if (st == RC_OK && flip) {
        out->n = rc_v3_scale(-1.0, out->n);
        out->x = rc_v3_add(out->x, dx);
    }
    return st;
}

/* per_ball frames: do two glued tubes (in one coordinate frame) overlap at t, found by
 * probing? Points along the segments between their pieces' centres at t, nine on each of
 * the four, are tested against both tubes shrunk by 1e-6 of their radii: a point inside
 * both is inside an overlap deeper than any touching tolerance (touch_tol is 1e-12 by
 * default), which windows_contact leaves to the straight cylinders. Two sections that
 * overlap mostly overlap on those segments; an overlap off them (shallow) is left to
 * rc_glue_toi2, which finds every overlap. The probe costs a few dozen point tests where
 * the programs would cost several contact solves. */
static int tubes_overlap_probe(const rc_glue *g0, const rc_glue *g1, double t)
{
    const double f = 1.0 - 1e-6;
    rc_glue sh[2] = {*g0, *g1};
    rc_vec3 c[2][2];
    for (int j = 0; j < 2; j++) {
        sh[j].r *= f;
        sh[j].in.r *= f;
        sh[j].out.r *= f;
        c[j][0] = rc_v3_axpy(sh[j].x_c, t - sh[j].t_c, sh[j].v_in);
        c[j][1] = rc_v3_axpy(sh[j].x_c, t - sh[j].t_c, sh[j].v_out);
    }
    for (int u = 0; u < 4; u++) {
        const rc_vec3 a = c[0][u >> 1], d = rc_v3_sub(c[1][u & 1], a);
        for (int k = 0; k <= 8; k++) {
            const rc_vec3 y = rc_v3_axpy(a, 0.125 * k, d);
            if (rc_glue_inside(&sh[0], t, y) && rc_glue_inside(&sh[1], t, y))
                return 1;
        }
    }
    return 0;
}

/* rc_glue_toi2 through the engine's memo of its last answers (eng_t2_memo): the same
 * bits, asked once where a pair asks twice. */
static int toi2_memo(rc_sim *s, const rc_glue *g0, const rc_glue *g1, double t1, double *t,
                     rc_vec3 *y, rc_vec3 *n, int *p0, int *p1)
{
    for (uint32_t k = 0; k < s->pb->t2m_n; k++) {
        const eng_t2_memo *m = &s->pb->t2m[k];
        if (memcmp(&m->t1, &t1, sizeof t1) == 0 && memcmp(&m->g0, g0, sizeof *g0) == 0 &&
            memcmp(&m->g1, g1, sizeof *g1) == 0) {
            *t = m->t;
            *y = m->y;
            *n = m->n;
            *p0 = m->p0;
            *p1 = m->p1;
            return m->st;
        }
    }
    eng_t2_memo *m = &s->pb->t2m[s->pb->t2m_next];
    s->pb->t2m_next = (s->pb->t2m_next + 1) % ENG_T2_MEMO;
    s->pb->t2m_n += s->pb->t2m_n < ENG_T2_MEMO;
    m->g0 = *g0;
    m->g1 = *g1;
    m->t1 = t1;
    m->st = rc_glue_toi2(g0, g1, &s->toi, s->ws, t1, &m->t, &m->y, &m->n, &m->p0, &m->p1);
    *t = m->t;
    *y = m->y;
    *n = m->n;
    *p0 = m->p0;
    *p1 = m->p1;
    return m->st;
}

/* per_ball frames: the contact of bi and bk (separation dx at t1) when both are inside
 * their glue windows at t1: the first contact of their two glued tubes (rc_glue_toi2,
 * papers/shape-change.md section 10), bk's tube moved into bi's coordinates (its centre at
 * t1 is bi's plus dx), put to the solver in frame_call's orientation so that the pair gets
 * the same bits whichever ball asks. Taken where it is a contact on neither ball's
 * incoming piece (RC_OK, out as frame_call's, *valid 1) or no contact at all (RC_MISS);
 * where the tubes overlap at t1 or an incoming piece is met first, -1: the straight
 * cylinders answer (a choice: papers/shape-change.md). -1 also where a ball's tube is not
 * its stored line's. */
static int windows_contact(const rc_sim *cs, const eng_ball *bi, const eng_ball *bk, rc_vec3 dx,
                           double t1, rc_toi_contact *out, int *valid)
{
    rc_sim *s = (rc_sim *)cs; /* (the workspace is scratch) */
    const int flip = dx.x < 0.0 || (dx.x == 0.0 && (dx.y < 0.0 || (dx.y == 0.0 && dx.z < 0.0)));
    const eng_ball *b0 = flip ? bk : bi, *b1 = flip ? bi : bk;
    const rc_vec3 d01 = flip ? rc_v3_scale(-1.0, dx) : dx;
    const rc_glue *g0 = &s->pb->glu[b0 - s->b];
    rc_glue g1 = s->pb->glu[b1 - s->b];
    /* (a tube whose outgoing line is not the ball's stored one is not its present tube:
     * the straight cylinders answer, as before this was built) */
    if (rc_v3_norm2(rc_v3_sub(g0->v_out, b0->v)) != 0.0 ||
        rc_v3_norm2(rc_v3_sub(g1.v_out, b1->v)) != 0.0)
        return -1;
    /* each tube's centre at t1 on its outgoing line (the stored one) */
    const rc_vec3 c0 = rc_v3_axpy(g0->x_c, t1 - g0->t_c, b0->v);
    const rc_vec3 shift = rc_v3_sub(rc_v3_add(c0, d01), rc_v3_axpy(g1.x_c, t1 - g1.t_c, b1->v));
    g1.x = rc_v3_add(g1.x, shift);
    g1.x_c = rc_v3_add(g1.x_c, shift);
    if (tubes_overlap_probe(g0, &g1, t1))
        return -1; /* (an overlap at t1: the straight cylinders answer, as below) */
    double t;
    rc_vec3 y, n;
    int p0, p1;
    const int st = toi2_memo(s, g0, &g1, t1, &t, &y, &n, &p0, &p1);
    if (st == RC_EOVERLAP)
        return -1; /* (the straight cylinders answer: see above) */
    if (st != RC_OK)
        return st;
    out->t = t - t1;
    /* X - bi's centre at t1 (c0, or b1's centre c0 + d01 with bi = b1) */
    out->x = rc_v3_sub(y, flip ? rc_v3_add(c0, d01) : c0);
    out->n = flip ? rc_v3_scale(-1.0, n) : n;
    *valid = p0 != 0 && p1 != 0;
    return *valid ? RC_OK : -1; /* (an incoming piece met: as an overlap, above) */
}

/* per_ball frames: the contact of bi and bk (separation dx at t1) when exactly one of
 * them is inside its glue window at t1 (H has not swept all of it): the first contact of
 * the other, a rigid ball, with that one's glued tube (rc_glue_toi: the tube's incoming
 * piece before H, the outgoing one after it), where the straight cylinder of the stored
 * (outgoing) line overlapped or met the other on the incoming side of H. Its time is the
 * first table time of contact, the table frame's criterion for the pieces (a ZMF version
 * is not built). RC_OK (out as frame_call's, *valid: on the outgoing piece or on H, and
 * on the future side of the other ball's H), RC_MISS (the tube is not met), RC_EOVERLAP,
 * or -1: neither ball in a window. (Both: windows_contact.) */
static int window_contact(const rc_sim *cs, const eng_ball *bi, const eng_ball *bk, rc_vec3 dx,
                          double t1, rc_toi_contact *out, int *valid)
{
    rc_sim *s = (rc_sim *)cs; /* (the workspace is scratch) */
    const size_t i = (size_t)(bi - s->b), k = (size_t)(bk - s->b);
    const rc_glue *gi = &s->pb->glu[i], *gk = &s->pb->glu[k];
    const int wi = gi->r > 0.0 && t1 < gi->t_last, wk = gk->r > 0.0 && t1 < gk->t_last;
    if (!wi && !wk)
        return -1;
    if (wi && wk)
        return windows_contact(s, bi, bk, dx, t1, out, valid);
    const rc_glue *g = wi ? gi : gk;
    const eng_ball *bg = wi ? bi : bk, *bo = wi ? bk : bi;
    const eng_aux *ao = &s->a[bo - s->b];
    /* the glued ball's centre at t1 on its outgoing line, in the tube's coordinates */
    const rc_vec3 cg = rc_v3_axpy(g->x_c, t1 - g->t_c, bg->v);
    const rc_vec3 ci = wi ? cg : rc_v3_sub(cg, dx); /* bi's, there */
    const rc_toi_ball K = {wi ? rc_v3_add(cg, dx) : ci, bo->r, ao->m, ao->p};
    double t;
    rc_vec3 y, n;
    int piece;
    const int st = rc_glue_toi(g, &s->toi, s->ws, t1, &K, &t, &y, &n, &piece);
    if (st != RC_OK)
        return st;
    out->t = t - t1;
    out->x = rc_v3_sub(y, ci);
    out->n = wi ? n : rc_v3_scale(-1.0, n);
    /* the other ball's side: X - its centre at t */
    const eng_cov *co = &s->pb->cov[bo - s->b];
    const rc_vec3 dxo = rc_v3_sub(rc_v3_axpy(out->x, -out->t, bi->v),
                                  wi ? rc_v3_axpy(dx, out->t, rc_v3_sub(bk->v, bi->v))
                                     : rc_v3(0.0, 0.0, 0.0));
    *valid = piece != 0 && eng_glue_side(co, &s->pb->glu[bo - s->b], bo->v, t, dxo);
    return RC_OK;
}

/* The frame's answer where it is certain without asking, from separation dx at its
 * reference: RC_MISS, RC_EOVERLAP, or RC_OK (not certain: ask). Its search starts at the
 * later of the two centre events in the pair's ZMF; it reports RC_EOVERLAP where the
 * shapes overlap there (beyond its touch tolerance), else the first contact of the
 * straight cylinders after it, RC_MISS where their intersection S lies wholly before it.
 * By engine/perball/pair_zmf.h (ZMF stretched by ball i's factor) the shapes overlap where the
 * inner spheres do, and S lies within the time the outer spheres overlap: the inner
 * spheres overlapping at the start, or the outer ones' exit before it or closest approach
 * apart, each by a margin (1e-6 of the radii or of the pair's time scale: far above this
 * arithmetic's rounding, even for the exit time of a grazing pair, and the frame's touch
 * tolerance), proves the answer. Asked only where the bounding spheres overlap at the
 * reference, where such answers gather (neighbours parting after a collision, or already
 * overlapping in the ZMF): elsewhere the frame's own first test is as cheap. */
static int frame_certain(const rc_sim *s, const eng_ball *bi, const eng_ball *bk, rc_vec3 dx)
{
    const double sig = bi->r + bk->r;
    eng_zpair z;
    if (!(rc_v3_norm2(dx) <= sig * sig) || !eng_zpair_make(s, bi, bk, dx, &z))
        return RC_OK;
    const double f = z.gi / z.gk;
    const double Ro = bi->r + bk->r * (f < 1.0 ? 1.0 : f), Ri = bi->r + bk->r * (f < 1.0 ? f : 1.0);
    const double tk0 = -z.gu * z.k2 * rc_v3_dot(z.u, dx), t_start = tk0 > 0.0 ? tk0 : 0.0;
    if (rc_v3_norm(rc_v3_axpy(z.Ds, t_start, z.ws)) < Ri * (1.0 - 1e-6))
        return RC_EOVERLAP;
    const double A = rc_v3_norm2(z.ws), B = rc_v3_dot(z.Ds, z.ws);
    if (rc_v3_norm(rc_v3_axpy(z.Ds, -B / A, z.ws)) > Ro * (1.0 + 1e-6))
        return RC_MISS;
    const double disc = B * B - A * (rc_v3_norm2(z.Ds) - Ro * Ro);
    if (!(disc > 0.0))
        return RC_OK;
    const double t_exit = (-B + sqrt(disc)) / A;
    return t_exit < t_start - (1e-6 * sig * (1.0 / z.wn + s->inv_c) +
                               1e-12 * (fabs(t_exit) + fabs(t_start)))
               ? RC_MISS
               : RC_OK;
}

/* per_ball frames: the pair's contact from its stored states (dx, *tref: pair_sep's),
 * asked from glue_reference's time (returned in *tref, the time the answer is relative
 * to); *valid: glue_valid's verdict. (Asked again from the later clock, where the stored
 * states are the balls' own, a contact found on the incoming side of a hyperplane or an
 * overlap gave in a dense gas no contact of the model either: the contact is then with
 * the part of the ball that H has not reached yet.) */
static int glue_contact(const rc_sim *s, const eng_ball *bi, const eng_ball *bk, rc_vec3 dx,
                        double *tref, rc_toi_contact *out, int *valid)
{
    glue_reference(s, bi, bk, &dx, tref);
    const int sure = frame_certain(s, bi, bk, dx);
    const int st = sure != RC_OK ? sure : frame_call(s, bi, bk, dx, out);
    *valid = st == RC_OK && glue_valid(s, bi, bk, dx, *tref, out->t, out->x);
    if (st == RC_EOVERLAP || (st == RC_OK && !*valid)) {
        /* the straight cylinder is not the tube inside a window: ask the tube */
        rc_toi_contact o2;
        int v2 = 0;
        const int w = window_contact(s, bi, bk, dx, *tref, &o2, &v2);
        if (w == RC_OK) {
            *out = o2;
            *valid = v2;
        }
        if (w == RC_OK || w == RC_MISS || w == RC_EOVERLAP)
            return w;
    }
    return st;
}

/* per_ball frames: the pair's contact when the frame reported an overlap from glue_contact's
 * reference. The zmf search starts at the later of the two reference events in the pair's
 * ZMF, which suits a stored state that begins its line (the zmf frame's); a per_ball
 * ball's line is its tube wherever eng_glue_side says so, and the straight cylinders'
 * first contact can lie on both balls' outgoing pieces ZMF-before that start while it is
 * still ahead in the table (its X is not simultaneous there). So the frame is asked again
 * from a reference far enough back that the cylinders are apart (4 (r_i + r_k) on the
 * table's slice, the other side of every overlap of two straight cylinders, whose set of
 * times is one interval), and its answer is the pair's contact if X lies on the future
 * side of both balls' hyperplanes (glue_valid): the first contact of the two tubes' present
 * pieces. Otherwise (X on an incoming side, or a ball in its window whose incoming piece
 * the other meets first: a contact only an undo can place) the overlap stands. The reference moves by the same bits whichever ball asks (dx and the relative
 * velocity change sign exactly). dx at tref; RC_OK with *out relative to them, or the
 * overlap. */
/* glue_back's guard for a ball whose glue window ends after the reference tb: inside the
 * window its tube is partly the incoming cylinder before H, not the straight outgoing one
 * the frame was asked about, so the contact X on the outgoing pieces is the tubes' only if
 * the other ball, rigid on its stored line, does not reach the incoming piece first
 * (rc_glue_toi from the window's start, the table's first contact with the pieces; before
 * the window the whole ball was on its incoming line, which the engine's earlier
 * predictions answered for; a probe found answers with a ball in its window that fail
 * this). 1: it reaches it (or the question fails): an undo's case, not a contact
 * on the outgoing pieces. bg glued (g), bo the other, d = bo - bg at tb on the stored
 * lines. */
static int incoming_first(const rc_sim *cs, const eng_ball *bg, const eng_ball *bo, rc_vec3 d,
                          double tb, double tx)
{
    rc_sim *s = (rc_sim *)cs; /* (the workspace is scratch) */
    const rc_glue *g = &s->pb->glu[bg - s->b];
    const eng_aux *ao = &s->a[bo - s->b];
    const double t0 = tb > g->t_first ? tb : g->t_first;
    const rc_vec3 cg = rc_v3_axpy(g->x_c, t0 - g->t_c, bg->v);
    const rc_vec3 d0 = rc_v3_axpy(d, t0 - tb, rc_v3_sub(bo->v, bg->v));
    const rc_toi_ball K = {rc_v3_add(cg, d0), bo->r, ao->m, ao->p};
    double t;
    rc_vec3 y, n;
    int piece;
    const int st = rc_glue_toi(g, &s->toi, s->ws, t0, &K, &t, &y, &n, &piece);
    if (st == RC_MISS)
        return 0;
    return st != RC_OK || (piece == 0 && t < tx);
}

/* glue_back's answer known to be refused before the frame is asked (in a dense gas most
 * of its answers lie on an incoming side of a hyperplane). Why this never refuses an
 * answer glue_back would take: the frame's X, asked from where the cylinders are apart,
 * is bounded as engine/perball/pair_zmf.h says, and glue_valid takes it only if it lies on the
 * future side F of both balls' hyperplanes. (a) Along a cylinder's generators the ZMF
 * time T and the side function both grow, so T over C_i and F_i is least on the section
 * H_i cuts from C_i, whose points are E_i + (kappa.d / den, d) for d in the table shape:
 * T = T(E_i) + w.d, w = kappa (1 - u.v) / den - u / c^2, least T(E_i) - h(w) (h the
 * shape's support); T(X) <= T(Y) below it puts X on the incoming side. (b) With equal
 * ZMF Lorentz factors X is Y, whose side of each hyperplane is told directly; factors
 * that differ by delta <= 1e-13 (rest masses a few ulps apart) move X by at most
 * ~ R sqrt(2 delta) even at grazing incidence, which the margin covers with gamma_u for
 * the boost back. The margin's floor, 1e-6 of the pair's time scale, covers the frame's
 * tolerance on X and this arithmetic's rounding (ENG_ZPAIR_U2_MAX). dx at tref (nearest
 * image); 1: refused for sure. */
static int back_refused(const rc_sim *s, const eng_ball *bi, const eng_ball *bk, rc_vec3 dx,
                        double tref)
{
    const eng_cov *ci = &s->pb->cov[bi - s->b], *ck = &s->pb->cov[bk - s->b];
    const int hi = ci->t_k > -INFINITY, hk = ck->t_k > -INFINITY;
    eng_zpair z;
    if ((!hi && !hk) || !eng_zpair_make(s, bi, bk, dx, &z))
        return 0;
    /* the inner spheres' first contact Y */
    const double R = bi->r + bk->r * (z.gk > z.gi ? z.gi / z.gk : 1.0);
    double tau;
    if (!eng_zpair_entry(&z, R, &tau))
        return 0;
    const double k2 = z.k2;
    const double di = ci->t_k - tref, dk = ck->t_k - tref;
    const double delta = fabs(z.gk - z.gi) / z.gi;
    const int equal = delta <= 1e-13;
    const double margin = (1e-6 + (equal ? 8.0 * z.gu * sqrt(delta) : 0.0)) *
                              (bi->r + bk->r) * (1.0 / z.wn + s->inv_c) +
                          1e-12 * (fabs(tref) + fabs(tau) + (hi ? fabs(di) : 0.0) +
                                   (hk ? fabs(dk) : 0.0));
    const double den_i = hi ? eng_seg_den(ci, &s->pb->glu[bi - s->b], bi->v) : 1.0;
    const double den_k = hk ? eng_seg_den(ck, &s->pb->glu[bk - s->b], bk->v) : 1.0;
    if (equal) { /* X = Y */
        double t;
        rc_vec3 y;
        eng_zpair_point(&z, bi->r, R, tau, &t, &y);
        if (hi && (t - di) * den_i - rc_v3_dot(ci->kappa, rc_v3_axpy(y, -t, bi->v)) < -margin)
            return 1;
        if (hk && (t - dk) * den_k -
                          rc_v3_dot(ck->kappa, rc_v3_sub(rc_v3_axpy(y, -t, bk->v), dx)) <
                      -margin)
            return 1;
        return 0;
    }
    /* T(X) <= T(Y) = tau / gu against each ball's least T on its future side */
    const double TY = tau / z.gu + margin, udx = rc_v3_dot(z.u, dx);
    if (hi) {
        const double q = 1.0 - k2 * rc_v3_dot(z.u, bi->v);
        const rc_vec3 wi = rc_v3_axpy(rc_v3_scale(-k2, z.u), q / den_i, ci->kappa);
        const double vw = rc_v3_dot(bi->v, wi);
        if (TY < di * q - bi->r * sqrt(fmax(0.0, rc_v3_norm2(wi) - k2 * vw * vw)))
            return 1;
    }
    if (hk) {
        const double q = 1.0 - k2 * rc_v3_dot(z.u, bk->v);
        const rc_vec3 wk = rc_v3_axpy(rc_v3_scale(-k2, z.u), q / den_k, ck->kappa);
        const double vw = rc_v3_dot(bk->v, wk);
        if (TY < dk * q - k2 * udx - bk->r * sqrt(fmax(0.0, rc_v3_norm2(wk) - k2 * vw * vw)))
            return 1;
    }
    return 0;
}

static int glue_back(const rc_sim *s, const eng_ball *bi, const eng_ball *bk, rc_vec3 dx,
                     double tref, rc_toi_contact *out)
{
    const rc_vec3 dv = rc_v3_sub(bk->v, bi->v);
    const double dvn = rc_v3_norm(dv);
    if (!(dvn > 0.0))
        return RC_EOVERLAP;
    if (back_refused(s, bi, bk, dx, tref))
        return RC_EOVERLAP;
    const double back = (rc_v3_norm(dx) + 4.0 * (bi->r + bk->r)) / dvn;
    const rc_vec3 dxb = rc_v3_axpy(dx, -back, dv);
    const double tb = tref - back;
    rc_toi_contact o;
    if (frame_call(s, bi, bk, dxb, &o) != RC_OK || !glue_valid(s, bi, bk, dxb, tb, o.t, o.x))
        return RC_EOVERLAP;
    const rc_glue *gi = &s->pb->glu[bi - s->b], *gk = &s->pb->glu[bk - s->b];
    const double tx = tb + o.t;
    if ((gi->r > 0.0 && tb < gi->t_last && incoming_first(s, bi, bk, dxb, tb, tx)) ||
        (gk->r > 0.0 && tb < gk->t_last &&
         incoming_first(s, bk, bi, rc_v3_scale(-1.0, dxb), tb, tx)))
        return RC_EOVERLAP;
    /* (relative to the original reference, as the caller's dx) */
    o.t -= back;
    o.x = rc_v3_sub(o.x, rc_v3_scale(back, bi->v));
    *out = o;
    return RC_OK;
}

#endif
