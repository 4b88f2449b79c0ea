/* test_gravity_gas — the colliding gas in a uniform field, in the engine (papers/gravity.md
 * section 6): each coupling's conserved energy over many collisions, walls and floor
 * included (h - booked constant to 1e-10 relative: the paths, walls and cell crossings
 * conserve it exactly and a contact changes it by g z dw, section 4); a run stopped at a
 * checkpoint and continued bit-identical to one that went on; bad definitions refused.
 * The suite runs 5 x 10^4 collisions a case; `test_gravity_gas long` (benchmark gravity_gas_long) runs 10^6. */
#include <string.h>

#include "relcol/moments.h"
#include "relcol/perball.h"

#include "field_gas.h"

static uint64_t n_coll = 50000;

static void energy_case(const rc_gravity_coupling *cp, double c, uint64_t seed)
{
    rc_sim *s = field_gas(cp, c, 1.0, 1000, 0.01, 0.8, seed);
    ENSURE(s != NULL);
    if (!s)
        return;
    double h0, w0;
    ENSURE(rc_sim_field_energy(s, &h0, &w0) == RC_OK);
    double worst = 0.0, booked = 0.0;
    uint64_t done = 0;
    while ((done = field_collisions(s)) < n_coll) {
        const int st = rc_sim_advance(s, INFINITY, 50000);
        ENSURE_MSG(st == RC_OK, "%s", rc_strerror(st));
        if (st != RC_OK)
            break;
        double h, w;
        rc_sim_field_energy(s, &h, &w);
        worst = fmax(worst, fabs(h - w - h0) / h0);
        booked = w;
    }
    rc_sim_diag dg;
    rc_sim_diagnostics(s, &dg);
    printf("  %s c %g: %llu collisions (%llu walls), t %.3g, |h - booked - h0|/h0 max %.2e, "
           "booked %.3e\n", cp->name, c, (unsigned long long)dg.collisions,
           (unsigned long long)dg.events[RC_SIM_EV_WALL], dg.time, worst, booked / h0);
    ENSURE(dg.events[RC_SIM_EV_WALL] > n_coll / 100); /* the floor and ceiling take part */
    ENSURE(dg.events[RC_SIM_EV_BALL] > n_coll / 2);
    ENSURE_MSG(worst < 1e-10, "energy drift %.3e", worst);
    /* elastic: only the equivalence coupling at finite c books anything (section 4) */
    if (cp == &rc_gravity_newtonian || isinf(c))
        ENSURE(booked == 0.0);
    else
        ENSURE(booked != 0.0 && fabs(booked) / h0 < 1e-2);
    rc_sim_free(&s);
}

static void test_energy(void)
{
    energy_case(&rc_gravity_newtonian, INFINITY, 0x901);
    energy_case(&rc_gravity_newtonian, 2.0, 0x902);
    energy_case(&rc_gravity_equivalence, INFINITY, 0x903);
    energy_case(&rc_gravity_equivalence, 2.0, 0x904);
}

/* stopped at a checkpoint, read into a new engine, continued: the same bits as the run
 * that went on */
static void restart_case(const rc_gravity_coupling *cp, double c)
{
    rc_sim *a = field_gas(cp, c, 1.0, 500, 0.01, 0.8, 0x911);
    ENSURE(a != NULL);
    if (!a)
        return;
    ENSURE(rc_sim_advance(a, 0.7, 0) == RC_OK);
    size_t bytes;
    rc_sim_checkpoint_size(a, &bytes);
    void *buf = malloc(bytes);
    ENSURE(rc_sim_checkpoint_write(a, buf, bytes) == RC_OK);
    ENSURE(rc_sim_advance(a, 2.0, 0) == RC_OK);
    rc_sim *b = field_gas(cp, c, 1.0, 10, 0.01, 0.8, 0x912); /* (another state, replaced) */
    ENSURE(b && rc_sim_checkpoint_read(b, buf, bytes) == RC_OK);
    ENSURE(rc_sim_advance(b, 2.0, 0) == RC_OK);
    ENSURE_MSG(rc_sim_hash(a) == rc_sim_hash(b), "%s c %g: hashes differ", cp->name, c);
    double ha, wa, hb, wb;
    rc_sim_field_energy(a, &ha, &wa);
    rc_sim_field_energy(b, &hb, &wb);
    ENSURE(memcmp(&ha, &hb, sizeof ha) == 0 && memcmp(&wa, &wb, sizeof wa) == 0);
    ENSURE(field_collisions(a) == field_collisions(b) && field_collisions(a) > 1000);
    /* a field-free engine and another coupling's refuse the bytes */
    rc_sim *o = field_gas(cp == &rc_gravity_newtonian ? &rc_gravity_equivalence
                                                     : &rc_gravity_newtonian, c, 1.0, 10, 0.01,
                          0.8, 0x913);
    rc_sim *z = field_gas(NULL, c, 1.0, 10, 0.01, 0.8, 0x914);
    ENSURE(o && rc_sim_checkpoint_read(o, buf, bytes) == RC_EMISMATCH);
    ENSURE(z && rc_sim_checkpoint_read(z, buf, bytes) == RC_EMISMATCH);
    free(buf);
    rc_sim_free(&a);
    rc_sim_free(&b);
    rc_sim_free(&o);
    rc_sim_free(&z);
}

static void test_restart(void)
{
    restart_case(&rc_gravity_newtonian, INFINITY);
    restart_case(&rc_gravity_newtonian, 2.0);
    restart_case(&rc_gravity_equivalence, 2.0);
}

static void test_refused(void)
{
    rc_sim_def d = rc_sim_def_default();
    d.gravity = &rc_gravity_equivalence;
    d.g = 1.0;
    d.g_axis = -1;
    rc_sim *s = NULL;
    rc_sim_def e = d;
    e.g = 0.0;
    ENSURE(rc_sim_create(&e, &s) == RC_EINVAL && !s);
    e.g = -1.0;
    ENSURE(rc_sim_create(&e, &s) == RC_EINVAL);
    e.g = NAN;
    ENSURE(rc_sim_create(&e, &s) == RC_ENONFINITE);
    e = d;
    e.g_axis = 3;
    ENSURE(rc_sim_create(&e, &s) == RC_EINVAL);
    e.g_axis = -2;
    ENSURE(rc_sim_create(&e, &s) == RC_EINVAL);
    e = d;
    e.boundary[2] = RC_SIM_PERIODIC; /* (the field's axis needs its floor and ceiling) */
    ENSURE(rc_sim_create(&e, &s) == RC_EINVAL);
    e = d;
    e.c = 1.0;
    e.frame = rc_toi_frame_find("covariant"); /* (not defined in a field) */
    ENSURE(e.frame != NULL);
    ENSURE(rc_sim_create(&e, &s) == RC_EUNDEFINED && !s);
    e.frame = rc_toi_frame_find("table");
    ENSURE(e.frame && rc_sim_create(&e, &s) == RC_EUNDEFINED);
    e.frame = rc_toi_frame_find("sphere");
    ENSURE(e.frame && rc_sim_create(&e, &s) == RC_OK && s);
    rc_sim_free(&s);
    const rc_gravity_coupling other = rc_gravity_newtonian; /* (a copy: no path entry) */
    e = d;
    e.gravity = &other;
    ENSURE(rc_sim_create(&e, &s) == RC_EUNKNOWN);
    ENSURE(strstr(rc_strerror(RC_EUNDEFINED), "field") != NULL);
    double h, w;
    s = field_gas(NULL, 1.0, 1.0, 10, 0.01, 0.5, 1);
    ENSURE(s && rc_sim_field_energy(s, &h, &w) == RC_EINVAL);
    rc_sim_free(&s);
}

/* issue 41 defect 2: a delayed slice in a field was never taken (asking for one hung a
 * caller that waited for it) and the collisional moments read 0; both are refused there,
 * while the same gas without a field gives them */
static void test_slices_moments_refused(void)
{
    const rc_gravity_coupling *cps[3] = {NULL, &rc_gravity_newtonian, &rc_gravity_equivalence};
    const double cs[2] = {2.0, INFINITY};
    for (int j = 0; j < 3; j++)
        for (int k = 0; k < 2; k++) {
            rc_sim *s = field_gas(cps[j], cs[k], 1.0, 50, 0.01, 0.5, 7);
            ENSURE(s != NULL);
            if (!s)
                continue;
            ENSURE(rc_sim_advance(s, 0.5, 100000) == RC_OK);
            uint32_t id = 0;
            rc_sim_moments m;
            rc_sim_diag dg;
            const int want = cps[j] ? RC_EUNDEFINED : RC_OK;
            ENSURE_MSG(rc_sim_slice_request(s, rc_sim_time(s) + 0.1, &id) == want, "%s c %g",
                       cps[j] ? cps[j]->name : "no field", cs[k]);
            ENSURE(rc_sim_moments_get(s, &m) == want);
            ENSURE(rc_sim_diagnostics(s, &dg) == RC_OK);
            ENSURE(cps[j] ? isnan(dg.virial[0]) && isnan(dg.virial_energy[2])
                          : isfinite(dg.virial[0]) && isfinite(dg.virial_energy[2]));
            if (!cps[j]) { /* (the slice is taken as the engine passes it) */
                ENSURE(rc_sim_advance(s, rc_sim_time(s) + 0.2, 100000) == RC_OK);
                ENSURE(rc_sim_slice_ready(s, id, NULL) == 1);
            }
            rc_sim_free(&s);
        }
    ENSURE(strstr(rc_strerror(RC_EUNDEFINED), "slices") != NULL);
}

int main(int argc, char **argv)
{
    gsl_set_error_handler_off();
    if (argc > 1 && strcmp(argv[1], "long") == 0)
        n_coll = 1000000;
    RUN_TEST(test_refused);
    RUN_TEST(test_slices_moments_refused);
    RUN_TEST(test_restart);
    RUN_TEST(test_energy);
    RC_TEST_MAIN_END();
}
