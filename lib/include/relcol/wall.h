/* relcol/wall.h — what a wall of the engine's box does to a ball that meets it, as a small
 * table of function pointers with declared properties (as relcol/law.h's laws): the engine
 * calls a wall's rule and never names one. rc_sim_def.wall_rule[w] picks wall w's rule
 * (NULL: rc_wall_reflecting). The wall's rest frame is the table frame. */
#ifndef RELCOL_WALL_H
#define RELCOL_WALL_H

#include "relcol/kinematics.h"
#include "relcol/rng.h"

#ifdef __cplusplus
extern "C" {
#endif

/// What a rule sees of the wall and the run at one contact.
typedef struct rc_wall_env {
    int dim;       ///< 2 or 3
    double c;      ///< speed of light (INFINITY classical)
    double inv_c2; ///< 1 / c^2 (0 classically)
    double eps;    ///< the contact's restitution (eps_wall; 1 under the TC model, 0 jammed)
    double kT;     ///< the wall's temperature (rules that declare temperature)
    rc_rng *rng;   ///< the run's wall stream (rules that declare random): in the checkpoint
} rc_wall_env;

/// A wall rule: name, properties, and its one op.
typedef struct rc_wall_rule {
    const char *name;    ///< "reflecting", "thermal"
    const char *summary; ///< one line
    /* the rigid wall p_n' = -eps p_n that the laws' joint group solvers know (rc_collide_wall):
     * a group with a wall that is not rigid is resolved a contact at a time instead */
    int rigid;
    int temperature; ///< reads env->kT (finite, > 0: the engine checks it)
    int random;      ///< draws from env->rng
    /* ball *a meets the wall with outward unit normal n (from the ball into the wall):
     * its new state in place; RC_NO_COLLISION (untouched) if it does not approach
     * (p.n <= 0); a negative status on failure (*a untouched) */
    int (*collide)(const rc_wall_env *env, rc_particle *a, rc_vec3 n);
} rc_wall_rule;

/// The hard wall: p_n' = -eps p_n, tangential momentum kept (rc_collide_wall).
extern const rc_wall_rule rc_wall_reflecting;
/* The thermal wall: a ball that meets it leaves with a momentum drawn afresh from the
 * wall-flux Jüttner law at the wall's kT (rc_wall_thermal_emit), whatever it came with;
 * eps is not read (the wall exchanges energy, heat, with the gas). */
extern const rc_wall_rule rc_wall_thermal;

/// The built-in rules, NULL-terminated.
extern const rc_wall_rule *const rc_wall_rules[];
/// A built-in rule by name; NULL if none.
const rc_wall_rule *rc_wall_rule_find(const char *name);

#ifdef __cplusplus
}
#endif
#endif
