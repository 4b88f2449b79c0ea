/* relcol/vec.h — three-component vectors. 1-D and 2-D problems are the same code with
 * the unused components zero: the laws never create a component the normal and the
 * momenta do not have, so a 1-D or 2-D input stays in its subspace exactly. */
#ifndef RELCOL_VEC_H
#define RELCOL_VEC_H

#include <math.h>

#ifdef __cplusplus
extern "C" {
#endif

/// A three-component vector (unused components 0 in 1-D and 2-D).
typedef struct rc_vec3 {
    double x, y, z; ///< components
} rc_vec3;

/// The vector (x, y, z).

static inline rc_vec3 rc_v3(double x, double y, double z)
{
    rc_vec3 r = {x, y, z};
    return r;
}
/// a + b
static inline rc_vec3 rc_v3_add(rc_vec3 a, rc_vec3 b) { return rc_v3(a.x + b.x, a.y + b.y, a.z + b.z); }
/// a - b
static inline rc_vec3 rc_v3_sub(rc_vec3 a, rc_vec3 b) { return rc_v3(a.x - b.x, a.y - b.y, a.z - b.z); }
/// s a
static inline rc_vec3 rc_v3_scale(double s, rc_vec3 a) { return rc_v3(s * a.x, s * a.y, s * a.z); }
/// a + s b
static inline rc_vec3 rc_v3_axpy(rc_vec3 a, double s, rc_vec3 b)
{
    return rc_v3(a.x + s * b.x, a.y + s * b.y, a.z + s * b.z);
}
/// a . b
static inline double rc_v3_dot(rc_vec3 a, rc_vec3 b) { return a.x * b.x + a.y * b.y + a.z * b.z; }
/// |a|^2
static inline double rc_v3_norm2(rc_vec3 a) { return rc_v3_dot(a, a); }
/// |a| (a.a overflows past ~1e154: rc_v3_norm_safe)
static inline double rc_v3_norm(rc_vec3 a) { return sqrt(rc_v3_dot(a, a)); }
/// a x b
static inline rc_vec3 rc_v3_cross(rc_vec3 a, rc_vec3 b)
{
    return rc_v3(a.y * b.z - a.z * b.y, a.z * b.x - a.x * b.z, a.x * b.y - a.y * b.x);
}
/// 1 if every component is finite
static inline int rc_v3_isfinite(rc_vec3 a) { return isfinite(a.x) && isfinite(a.y) && isfinite(a.z); }
/// |a| for any finite a: outside a.a's range scaled by the largest component first, else sqrt(a.a) to the bit; inf only if |a| is not a finite double.
static inline double rc_v3_norm_safe(rc_vec3 a)
{
    const double n2 = rc_v3_dot(a, a);
    if (n2 > 1e-300 && n2 < 1e300)
        return sqrt(n2);
    const double s = fmax(fabs(a.x), fmax(fabs(a.y), fabs(a.z)));
    if (!(s > 0.0) || !isfinite(s))
        return s;
    const rc_vec3 b = rc_v3(a.x / s, a.y / s, a.z / s);
    return s * sqrt(rc_v3_dot(b, b));
}
/// a / len for len = rc_v3_norm_safe(a) of a finite nonzero a, divided component by component where 1 / len would overflow.
static inline rc_vec3 rc_v3_unit(rc_vec3 a, double len)
{
    if (len > 1e-300 && len < 1e300)
        return rc_v3_scale(1.0 / len, a);
    return rc_v3(a.x / len, a.y / len, a.z / len);
}
/// Component i (0, 1, 2) by index, for I/O loops.
static inline double rc_v3_get(rc_vec3 a, int i) { return i == 0 ? a.x : (i == 1 ? a.y : a.z); }
/// Set component i (0, 1, 2) to v.
static inline void rc_v3_set(rc_vec3 *a, int i, double v)
{
    if (i == 0)
        a->x = v;
    else if (i == 1)
        a->y = v;
    else
        a->z = v;
}

#ifdef __cplusplus
}
#endif
#endif
