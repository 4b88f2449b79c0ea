/* engine/model.c — the models of where balls change velocity (engine/model.h), chosen from the
 * frame's declared properties: the instant one (every op NULL) and the per-ball one
 * (engine/perball/ops.c). */
#include "model.h"

const eng_model_ops eng_model_instant = {.name = "instant", .per_ball = 0};

const eng_model_ops *eng_model_for(const rc_toi_frame *frame, int narrow, double ic2)
{
    /* (a per_ball frame at infinite c: every kink is its contact event, kappa = 0, and the
     * instant model is that model exactly) */
    static const eng_model_ops *const models[2] = {&eng_model_instant, &eng_model_glued};
    return models[narrow && frame && frame->per_ball && ic2 > 0.0];
}
