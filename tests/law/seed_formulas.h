/* seed_formulas.h — the seeds' collision formulas transcribed literally, in one place, for
 * tests/law/test_law_seeds.c and notebooks-c/02-classical-2d.c: seed 000's relativistic
 * 1-D (U), (V), (M); seed 000 part 3's classical `collide` and part 8's double collision
 * `collide2` (also notebooks-c/03-double-collision.c); seed 001's equal-mass elastic
 * `collision`; seed 002's eqs (7)-(13) then (22)-(27). Functions are `static inline` so a
 * user that needs only some of them gets no unused-function warnings. */
#ifndef RC_SEED_FORMULAS_H
#define RC_SEED_FORMULAS_H

#include <math.h>

/* ---- seed 000, "Relativistic collision in one dimension": (U), (V), (M) literally ---- */

/* The formulas are written in `real` = long double: they work from velocities, and
 * 1 - v^2/c^2 and the (1 - v^2/c^2)(1 - u^2/c^2) of (M) lose ~ gamma^2 ulp; 11 more bits
 * keep the reference well below the library's double round-off. */
typedef long double real;

/* (U): velocity of the zero-momentum frame. */
static inline real seed000_U(real m0, real v0, real m1, real v1, real c)
{
    real gamma0 = 1 / sqrtl(1 - v0 * v0 / (c * c));
    real gamma1 = 1 / sqrtl(1 - v1 * v1 / (c * c));
    return (m0 * gamma0 * v0 + m1 * gamma1 * v1) / (m0 * gamma0 + m1 * gamma1);
}

/* (V): a ball's velocity after the collision. */
static inline real seed000_V(real v, real u, real epsilon, real c)
{
    return (u * (1 - u * v / (c * c)) + epsilon * (u - v)) /
           (1 - u * v / (c * c) + epsilon * u / (c * c) * (u - v));
}

/* (M): a ball's rest mass after the collision. */
static inline real seed000_M(real m, real v, real u, real epsilon, real c)
{
    real c2 = c * c, c4 = c2 * c2;
    return m * sqrtl((1 - 2 * (1 - epsilon * epsilon) * v * u / c2 -
                      epsilon * epsilon * (v * v + u * u) / c2 + v * v * u * u / c4) /
                     (1 - (v * v + u * u) / c2 + v * v * u * u / c4));
}

/* ---- seed 000 part 3, classical `collide`, transcribed from its TypeScript ---- */

typedef struct Ball {
    double x, y; /* position */
    double v, w; /* velocity components */
    double radius;
} Ball;

/* Math.pow(radius, 3) is the seed's mass (equal densities); tests give masses m by
 * radius = cbrt(m) and hand the library exactly pow(radius, 3). */
static inline void seed000_collide(Ball *this, Ball *otherBall, double restitution)
{
    double dx = this->x - otherBall->x;
    double dy = this->y - otherBall->y;
    double dv = this->v - otherBall->v;
    double dw = this->w - otherBall->w;
    double alpha = atan2(dy, dx);
    double sinAlpha = sin(alpha);
    double cosAlpha = cos(alpha);
    double m1 = pow(this->radius, 3);
    double m2 = pow(otherBall->radius, 3);
    double a = (1 + restitution) / (m1 + m2) * (cosAlpha * dv + sinAlpha * dw);
    this->v = -m2 * a * cosAlpha + this->v;
    this->w = -m2 * a * sinAlpha + this->w;
    otherBall->v = m1 * a * cosAlpha + otherBall->v;
    otherBall->w = m1 * a * sinAlpha + otherBall->w;
} /* collide */

/* ---- seed 000 part 8, `collide2`: ball `this` hits otherBall1 and otherBall2 at the same
 * instant (positions at contact), transcribed from its TypeScript; masses radius^3 ---- */
static inline void seed000_collide2(Ball *this, Ball *otherBall1, Ball *otherBall2, double restitution)
{
    double m0 = pow(this->radius, 3);
    double m1 = pow(otherBall1->radius, 3);
    double m2 = pow(otherBall2->radius, 3);
    double x01 = otherBall1->x - this->x;
    double y01 = otherBall1->y - this->y;
    double x02 = otherBall2->x - this->x;
    double y02 = otherBall2->y - this->y;
    double p = x01 * x02 + y01 * y02;
    double s01 = x01 * x01 + y01 * y01;
    double s02 = x02 * x02 + y02 * y02;
    double delta = (m0 + m1) * (m0 + m2) * s01 * s02 - m1 * m2 * p * p;
    double v01 = otherBall1->v - this->v;
    double w01 = otherBall1->w - this->w;
    double b01 = (1 + restitution) * (x01 * v01 + y01 * w01);
    double v02 = otherBall2->v - this->v;
    double w02 = otherBall2->w - this->w;
    double b02 = (1 + restitution) * (x02 * v02 + y02 * w02);
    this->v = -(b01 * m1 * (x02 * m2 * p - x01 * (m0 + m2) * s02) + b02 * m2 * (x01 * m1 * p - x02 * (m0 + m1) * s01)) / delta + this->v;
    this->w = -(b01 * m1 * (y02 * m2 * p - y01 * (m0 + m2) * s02) + b02 * m2 * (y01 * m1 * p - y02 * (m0 + m1) * s01)) / delta + this->w;
    double r1 = m0 * (b02 * m2 * p - b01 * (m0 + m2) * s02) / delta;
    otherBall1->v = x01 * r1 + otherBall1->v;
    otherBall1->w = y01 * r1 + otherBall1->w;
    double r2 = m0 * (b01 * m1 * p - b02 * (m0 + m1) * s01) / delta;
    otherBall2->v = x02 * r2 + otherBall2->v;
    otherBall2->w = y02 * r2 + otherBall2->w;
} /* collide2 */

/* ---- seed 001, equal-mass elastic `collision(i, j)`, transcribed from its JavaScript ----
 * (the seed's globals `particles` and `diameter2` are the caller's to set) */

typedef struct { double x, y, vx, vy; } particle001;
static particle001 particles[2];
static double diameter2;

static inline void collision(int i, int j)
{
    // First we find the components of d.
    double dy = particles[i].y - particles[j].y;
    double dx = particles[i].x - particles[j].x;
    // Then we calculate d^2.
    double d2 = pow(dx, 2) + pow(dy, 2);
    // If d^2<the diameter och the particles^2 then we might
    // have a collision.
    if (d2 < diameter2) {
        // Then we calculate the components of difference
        // in velocities.
        double dvx = particles[j].vx - particles[i].vx;
        double dvy = particles[j].vy - particles[i].vy;
        // Then we calculate the dot product...
        double dvs = dx * dvx + dy * dvy;
        // ... and if this is positive the particles are
        // colliding.
        if (dvs > 0) {
            dvs = dvs / d2;
            dvx = dvs * dx;
            dvy = dvs * dy;
            particles[i].vx += dvx;
            particles[i].vy += dvy;
            particles[j].vx -= dvx;
            particles[j].vy -= dvy;
        }
    }
}

/* ---- seed 002, eqs (7)-(13) then (22)-(27), transcribed literally ---- */

typedef struct { double vx1, vy1, vx2, vy2; } vel002;

static inline vel002 seed002(double m1, double m2, vel002 in, double alpha, double R)
{
    double vx1 = in.vx1, vy1 = in.vy1, vx2 = in.vx2, vy2 = in.vy2;
    double gamma_v = atan((vy1 - vy2) / (vx1 - vx2));                               /* (7) */
    double a = tan(gamma_v + alpha);                                                /* (9) */
    double dvx2 = 2 * (vx1 - vx2 + a * (vy1 - vy2)) / ((1 + a * a) * (1 + m2 / m1)); /* (8) */
    double vx2p = vx2 + dvx2;                                                       /* (10) */
    double vy2p = vy2 + a * dvx2;                                                   /* (11) */
    double vx1p = vx1 - m2 / m1 * dvx2;                                             /* (12) */
    double vy1p = vy1 - a * m2 / m1 * dvx2;                                         /* (13) */
    double vxcm = (m1 * vx1 + m2 * vx2) / (m1 + m2);                                /* (22) */
    double vycm = (m1 * vy1 + m2 * vy2) / (m1 + m2);                                /* (23) */
    vel002 out;
    out.vx1 = (vx1p - vxcm) * R + vxcm;                                             /* (24) */
    out.vy1 = (vy1p - vycm) * R + vycm;                                             /* (25) */
    out.vx2 = (vx2p - vxcm) * R + vxcm;                                             /* (26) */
    out.vy2 = (vy2p - vycm) * R + vycm;                                             /* (27) */
    return out;
}

#endif
