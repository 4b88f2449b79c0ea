/* status.c — status codes to text. */
#include "relcol/status.h"

const char *rc_strerror(int status)
{
    switch (status) {
    case RC_OK: return "success";
    case RC_NO_COLLISION: return "the balls are not approaching along the normal: no collision";
    case RC_MISS: return "no contact in the future";
    case RC_EINVAL: return "invalid argument";
    case RC_ENONFINITE: return "not a finite number";
    case RC_EMASS: return "rest mass must be > 0";
    case RC_ESPEED: return "speed must be < c";
    case RC_ERESTITUTION: return "restitution must be in [0, 1]";
    case RC_ESPEEDOFLIGHT: return "c must be > 0 (or inf)";
    case RC_EZERONORMAL: return "contact normal has zero length";
    case RC_EOVERLAP: return "shapes overlap";
    case RC_ENOMEM: return "out of memory";
    case RC_ENOCONVERGE: return "solver did not converge";
    case RC_EUNKNOWN: return "unknown name";
    case RC_ERADIUS: return "radius must be > 0";
    case RC_EDIM: return "dimension must be 1, 2 or 3";
    case RC_ECORRUPT: return "not a whole, undamaged relcol checkpoint";
    case RC_EMISMATCH: return "checkpoint written by another run definition, format or machine";
    case RC_ESTALL: return "simulated time stands still: events keep coming at one instant";
    case RC_ENOTREADY: return "slice not final yet: advance the engine past its final time";
    case RC_ENOSLICE: return "no slice held under that id (released, or dropped with the balls, c or a checkpoint read)";
    case RC_ESCALE: return "positions too far from the origin for their doubles to resolve the radii";
    case RC_EUNDEFINED: return "not defined by the model: a uniform field takes only one-instant uncontracted frames and hard walls, and has no delayed slices or collisional moments (papers/gravity.md, model limits)";
    default: return "unknown status code";
    }
}
