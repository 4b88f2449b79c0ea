/* relcol/status.h — status codes returned by every relcol function.
 * Zero is success, negative codes are failures, positive codes are outcomes that are
 * not failures (for example "these balls do not collide"). Library code never prints
 * and never exits; callers turn a code into text with rc_strerror(). */
#ifndef RELCOL_STATUS_H
#define RELCOL_STATUS_H

#ifdef __cplusplus
extern "C" {
#endif

/// Status codes: 0 success, > 0 informational outcomes, < 0 failures.
enum rc_status {
    RC_OK = 0,             ///< success
    RC_NO_COLLISION = 1,   ///< the balls are separating (or tangent) along the normal
    RC_MISS = 2,           ///< no contact in the future
    RC_EINVAL = -1,        ///< generic invalid argument
    RC_ENONFINITE = -2,    ///< a NaN or infinite input where a finite number is required
    RC_EMASS = -3,         ///< rest mass not strictly positive
    RC_ESPEED = -4,        ///< |v| >= c
    RC_ERESTITUTION = -5,  ///< restitution outside [0, 1]
    RC_ESPEEDOFLIGHT = -6, ///< c <= 0 or NaN
    RC_EZERONORMAL = -7,   ///< contact normal of zero length
    RC_EOVERLAP = -8,      ///< shapes already overlap
    RC_ENOMEM = -9,        ///< allocation failed
    RC_ENOCONVERGE = -10,  ///< an iterative solver did not converge
    RC_EUNKNOWN = -11,     ///< unknown name (law, frame, ...)
    RC_ERADIUS = -12,      ///< radius not strictly positive
    RC_EDIM = -13,         ///< dimension outside 1..3 or inconsistent
    RC_ECORRUPT = -14,     ///< bytes that are not a whole, undamaged relcol checkpoint
    RC_EMISMATCH = -15,    ///< a checkpoint of another run definition, format or machine
    RC_ESTALL = -16,       ///< simulated time stands still: events keep coming at one instant
    RC_ENOTREADY = -17,    ///< a delayed slice read before it is final
    RC_ENOSLICE = -18,     ///< no slice held under that id
    RC_ESCALE = -19,       ///< positions too far out for their doubles to resolve the radii
    RC_EUNDEFINED = -20    ///< a combination the model does not define (a per-ball or contracted frame in a field)
};

/// A short English description of a status code (static storage, never NULL).
const char *rc_strerror(int status);

#ifdef __cplusplus
}
#endif
#endif
