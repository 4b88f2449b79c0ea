/* wall_rules.c — the built-in wall rules (relcol/wall.h): the hard wall and the thermal
 * wall, each one op over the sampler or the wall law it names. */
#include <string.h>

#include "relcol/law.h"
#include "relcol/status.h"
#include "relcol/wall.h"
#include "relcol/wall_thermal.h"

static int reflect(const rc_wall_env *e, rc_particle *a, rc_vec3 n)
{
    return rc_collide_wall(e->inv_c2, e->eps, a, n);
}

const rc_wall_rule rc_wall_reflecting = {
    .name = "reflecting",
    .summary = "hard wall: p_n' = -eps_wall p_n, tangential momentum kept",
    .rigid = 1,
    .collide = reflect,
};

static int thermal(const rc_wall_env *e, rc_particle *a, rc_vec3 n)
{
    if (!(rc_v3_dot(a->p, n) > 0.0))
        return RC_NO_COLLISION;
    rc_vec3 p;
    /* re-emitted along the normal into the gas, -n */
    const int st = rc_wall_thermal_emit(e->rng, e->dim, a->m, e->c, e->kT, rc_v3_scale(-1.0, n), &p);
    if (st != RC_OK)
        return st;
    a->p = p;
    return RC_OK;
}

const rc_wall_rule rc_wall_thermal = {
    .name = "thermal",
    .summary = "thermal wall: re-emits from the wall-flux Juttner law at the wall's kT",
    .rigid = 0,
    .temperature = 1,
    .random = 1,
    .collide = thermal,
};

const rc_wall_rule *const rc_wall_rules[] = {&rc_wall_reflecting, &rc_wall_thermal, NULL};

const rc_wall_rule *rc_wall_rule_find(const char *name)
{
    if (!name)
        return NULL;
    for (size_t k = 0; rc_wall_rules[k]; k++)
        if (strcmp(rc_wall_rules[k]->name, name) == 0)
            return rc_wall_rules[k];
    return NULL;
}
