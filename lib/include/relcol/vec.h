/* relcol/vec.h — three-component vectors. 1-D and 2-D problems are the same code with
 * the unused components zero: the laws never create a component the normal and the
 * momenta do not have, so a 1-D or 2-D input stays in its subspace exactly. */
#ifndef RELCOL_VEC_H
#define RELCOL_VEC_H

#include <math.h>

#ifdef __cplusplus
extern "C" {
#endif

typedef struct rc_vec3 {
    double x, y, z;
} rc_vec3;

static inline rc_vec3 rc_v3(double x, double y, double z)
{
    rc_vec3 r = {x, y, z};
    return r;
}
static inline rc_vec3 rc_v3_add(rc_vec3 a, rc_vec3 b) { return rc_v3(a.x + b.x, a.y + b.y, a.z + b.z); }
static inline rc_vec3 rc_v3_sub(rc_vec3 a, rc_vec3 b) { return rc_v3(a.x - b.x, a.y - b.y, a.z - b.z); }
static inline rc_vec3 rc_v3_scale(double s, rc_vec3 a) { return rc_v3(s * a.x, s * a.y, s * a.z); }
/* a + s b */
static inline rc_vec3 rc_v3_axpy(rc_vec3 a, double s, rc_vec3 b)
{
    return rc_v3(a.x + s * b.x, a.y + s * b.y, a.z + s * b.z);
}
static inline double rc_v3_dot(rc_vec3 a, rc_vec3 b) { return a.x * b.x + a.y * b.y + a.z * b.z; }
static inline double rc_v3_norm2(rc_vec3 a) { return rc_v3_dot(a, a); }
static inline double rc_v3_norm(rc_vec3 a) { return sqrt(rc_v3_dot(a, a)); }
static inline rc_vec3 rc_v3_cross(rc_vec3 a, rc_vec3 b)
{
    return rc_v3(a.y * b.z - a.z * b.y, a.z * b.x - a.x * b.z, a.x * b.y - a.y * b.x);
}
static inline int rc_v3_isfinite(rc_vec3 a) { return isfinite(a.x) && isfinite(a.y) && isfinite(a.z); }
/* |a| for any finite a: a.a overflows past ~1e154 and underflows below ~1e-154, so outside
 * that range a is divided by its largest component first (inside it, the plain sqrt(a.a),
 * to the bit). 0 for a zero vector; inf only if |a| itself is not a finite double. */
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
/* a / |a| for any finite nonzero a, as a / rc_v3_norm_safe(a) divided component by
 * component where 1 / |a| would overflow. */
static inline rc_vec3 rc_v3_unit(rc_vec3 a, double len)
{
    if (len > 1e-300 && len < 1e300)
        return rc_v3_scale(1.0 / len, a);
    return rc_v3(a.x / len, a.y / len, a.z / len);
}
/* Component i (0, 1, 2) by index, for I/O loops. */
static inline double rc_v3_get(rc_vec3 a, int i) { return i == 0 ? a.x : (i == 1 ? a.y : a.z); }
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
