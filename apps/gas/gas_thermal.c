/* gas_thermal.c — which contact frames relax relcol-gas to Jüttner. Asked of a frame's
 * declared properties, never its name (a frame added to rc_toi_frames[] is classified too):
 *  - uncontracted shapes: the dilute collision kernel times E0 E1 is unchanged by a
 *    collision, which cancels the collision map's Jacobian E0'E1'/(E0 E1), so the Boltzmann
 *    gain equals the loss on Jüttner; and the configuration integral of rigid shapes that
 *    never change does not depend on the momenta, so the dense gas is Jüttner too;
 *  - covariant contracted shapes (found in the pair's ZMF): the ZMF kernel is unchanged by
 *    the collision, so the dilute gas is Jüttner; at finite density the excluded volume
 *    depends on the velocities and the equilibrium moves off Jüttner (issue 17, item 3).
 *    The dilute limit is tested in 2-D (tests/gas2d/test_gas2d_dilute); the 3-D gas of
 *    such a one-instant frame is off Jüttner at the lowest packing measured (0.01), so in
 *    3-D it is not claimed (3);
 *  - contracted shapes in a frame that is not covariant (the table frame): the curvature
 *    of the shapes at the contact changes with the velocities the collision changes, the
 *    balance fails already in the dilute limit (notebook 08, tests/gas2d/test_gain_loss.c);
 *  - covariant point-like criteria (transport): sigma times the Moller flux is invariant and
 *    unchanged by the collision, so the dilute gas is Jüttner; the collisions are non-local
 *    (centres d_T apart), and the dense gas is not measured. */
#include "gas_thermal.h"

int gas_frame_thermal(const rc_toi_frame *f, int dim)
{
    if (!f->contracted && !f->pointlike)
        return 2;
    if (!f->covariant)
        return 0;
    return dim == 3 && !f->pointlike && !f->per_ball ? 3 : 1;
}

const rc_toi_frame *gas_default_frame(void)
{
    for (size_t i = 0; rc_toi_frames[i]; i++)
        if (gas_frame_thermal(rc_toi_frames[i], 2) == 2)
            return rc_toi_frames[i];
    return NULL;
}

void gas_frame_warn(FILE *f, const char *prog, const rc_toi_frame *frame, int dim,
                    double packing)
{
    const int t = gas_frame_thermal(frame, dim);
    if (t == 0)
        fprintf(f, "%s: warning: frame %s: its stationary state is not Jüttner (contracted "
                   "shapes in a frame that is not covariant collide at rates that break the "
                   "Boltzmann gain-loss balance, notebook 08): theta from <p.v> reads low "
                   "and the chi2 fails at any density\n", prog, frame->name);
    else if (t == 3)
        fprintf(f, "%s: warning: frame %s: in 3-D its gas is off Jüttner down to the lowest "
                   "packing measured (0.01: theta from <p.v> above theta from <gamma>, the "
                   "chi2 failing); that the dilute limit is Jüttner is tested in 2-D only\n",
                prog, frame->name);
    else if (t == 1 && frame->pointlike)
        fprintf(f, "%s: warning: frame %s: Jüttner in the dilute limit only; its collisions "
                   "are non-local (centres d_T apart) and at packing %g it is not measured\n",
                prog, frame->name, packing);
    else if (t == 1 && frame->per_ball)
        fprintf(f, "%s: warning: frame %s: Jüttner in the dilute limit only; at packing %g "
                   "its two thermometers read apart by an amount that depends on the "
                   "read-out (--readout) and on the rules inside glue windows "
                   "(papers/finite-density.md, section 5.1)\n", prog, frame->name, packing);
    else if (t == 1)
        fprintf(f, "%s: warning: frame %s: Jüttner in the dilute limit only; at packing %g "
                   "its theta from <p.v> reads above theta from <gamma>, more as the packing "
                   "grows\n", prog, frame->name, packing);
}
