/* engine/perball/state.c — making and freeing the per-ball model's state (perball.h). */
#include <math.h>
#include <stdlib.h>
#include <string.h>

#include "../private.h"

eng_perball *eng_perball_alloc(size_t n)
{
    eng_perball *pb = calloc(1, sizeof *pb);
    if (!pb)
        return NULL;
    /* (aligned, and on huge pages when large, as the engine's other per-ball arrays: a
     * collision touches two balls' records anywhere in them) */
    if (!(pb->cov = eng_alloc(n * sizeof *pb->cov)) || !(pb->glu = eng_alloc(n * sizeof *pb->glu)) ||
        !(pb->und = eng_alloc(n * sizeof *pb->und)) ||
        !(pb->undp = eng_alloc(n * sizeof *pb->undp)) ||
        !(pb->pend = eng_alloc(n * sizeof *pb->pend))) {
        eng_perball_free(&pb);
        return NULL;
    }
    memset(pb->glu, 0, n * sizeof *pb->glu);
    memset(pb->und, 0, n * sizeof *pb->und);
    memset(pb->undp, 0, n * sizeof *pb->undp);
    memset(pb->pend, 0, n * sizeof *pb->pend);
    for (size_t k = 0; k < n; k++) {
        /* no kink yet: every contact is on the future side of a ball's (absent) plane */
        pb->cov[k] = (eng_cov){-INFINITY, {0.0, 0.0, 0.0}, 0.0, {0.0, 0.0, 0.0}};
        pb->und[k].partner = ENG_NONE; /* (nothing to undo) */
        pb->undp[k].partner = ENG_NONE;
    }
    pb->undo_before = -1;
    return pb;
}

void eng_perball_free(eng_perball **pb)
{
    if (!pb || !*pb)
        return;
    free((*pb)->cov);
    free((*pb)->glu);
    free((*pb)->und);
    free((*pb)->undp);
    free((*pb)->pend);
    free(*pb);
    *pb = NULL;
}
