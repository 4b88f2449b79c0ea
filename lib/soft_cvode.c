/* soft_cvode.c — the soft-sphere stepper on SUNDIALS CVODE: BDF with the dense direct
 * linear solver, contact starts and ends found by CVODE's root finder on the overlaps,
 * and a CVodeReInit at each one because the force switches there. */
#include <math.h>
#include <stdlib.h>

#include <cvode/cvode.h>
#include <nvector/nvector_serial.h>
#include <sunlinsol/sunlinsol_dense.h>
#include <sunmatrix/sunmatrix_dense.h>

#include "relcol/soft.h"
#include "relcol/status.h"

static int cv_rhs(sunrealtype t, N_Vector y, N_Vector ydot, void *user)
{
    (void)t;
    rc_soft_rhs(user, N_VGetArrayPointer(y), N_VGetArrayPointer(ydot));
    return 0;
}

static int cv_root(sunrealtype t, N_Vector y, sunrealtype *g, void *user)
{
    (void)t;
    rc_soft_overlap(user, N_VGetArrayPointer(y), g);
    return 0;
}

/* The library never prints: CVODE's messages are dropped, its return codes are kept. */
static void cv_silent(int code, const char *module, const char *function, char *msg,
                      void *user)
{
    (void)code;
    (void)module;
    (void)function;
    (void)msg;
    (void)user;
}

static int cvode_integrate(rc_soft_sys *s)
{
    rc_soft_sys_info in;
    rc_soft_sys_get_info(s, &in);
    double *const y = rc_soft_sys_state(s);
    const sunindextype ny = (sunindextype)in.ny;
    SUNContext ctx = NULL;
    void *mem = NULL;
    N_Vector yv = NULL, atol = NULL;
    SUNMatrix A = NULL;
    SUNLinearSolver LS = NULL;
    int *roots = NULL;
    int st = RC_ENOMEM;

    if (SUNContext_Create(NULL, &ctx) != 0)
        return RC_ENOMEM;
    yv = N_VMake_Serial(ny, y, ctx); /* CVODE writes the solution into y */
    atol = N_VNew_Serial(ny, ctx);
    roots = malloc(in.npair * sizeof *roots);
    if (!yv || !atol || !roots)
        goto out;
    double *a = N_VGetArrayPointer(atol);
    for (size_t i = 0; i < in.ny; i++)
        a[i] = in.rtol * in.abs_scale[i];
    mem = CVodeCreate(CV_BDF, ctx);
    if (!mem)
        goto out;
    A = SUNDenseMatrix(ny, ny, ctx);
    LS = A ? SUNLinSol_Dense(yv, A, ctx) : NULL;
    if (!LS)
        goto out;
    st = RC_ENOCONVERGE;
    if (CVodeSetErrHandlerFn(mem, cv_silent, NULL) != CV_SUCCESS ||
        CVodeInit(mem, cv_rhs, 0.0, yv) != CV_SUCCESS ||
        CVodeSetUserData(mem, s) != CV_SUCCESS ||
        CVodeSVtolerances(mem, in.rtol, atol) != CV_SUCCESS ||
        CVodeSetLinearSolver(mem, LS, A) != CV_SUCCESS ||
        CVodeRootInit(mem, (int)in.npair, cv_root) != CV_SUCCESS ||
        CVodeSetNoInactiveRootWarn(mem) != CV_SUCCESS)
        goto out;
    /* one step per call: tout only fixes the direction and bounds the first step */
    const sunrealtype tout = isfinite(in.t_max) ? in.t_max : 1e300;
    sunrealtype t = 0.0;
    rc_soft_observe(s, y);
    while (!rc_soft_done(s, y) && t < in.t_max) {
        if (!rc_soft_sys_budget_left(s))
            goto out;
        /* a free flight is integrated exactly, so CVODE's steps would grow past whole
         * contacts (the root finder sees only sign changes at step ends): cap each step
         * with a stop time, which CVODE enforces on the step it is about to take (a new
         * maximum step size would only shape the steps after it) */
        const double tcap = fmin(in.t_max, t + rc_soft_max_step(s, y));
        if (isfinite(tcap) && CVodeSetStopTime(mem, tcap) != CV_SUCCESS)
            goto out;
        const int flag = CVode(mem, tout, yv, &t, CV_ONE_STEP);
        if (flag < 0)
            goto out;
        rc_soft_sys_count_step(s);
        if (flag == CV_ROOT_RETURN) {
            if (CVodeGetRootInfo(mem, roots) != CV_SUCCESS)
                goto out;
            int switched = 0;
            for (size_t q = 0; q < in.npair; q++) {
                if (roots[q] == 0)
                    continue;
                const int want = rc_soft_approaching(s, q, y);
                if (want != rc_soft_sys_contact(s, q)) {
                    rc_soft_switch(s, q, want, y);
                    switched = 1;
                }
            }
            /* the right-hand side jumps: restart the multistep history here */
            if (switched && CVodeReInit(mem, t, yv) != CV_SUCCESS)
                goto out;
        }
        rc_soft_shape_overlaps(s, y);
        rc_soft_observe(s, y);
    }
    rc_soft_sys_finish(s, t);
    st = RC_OK;
out:
    CVodeFree(&mem);
    if (LS)
        SUNLinSolFree(LS);
    if (A)
        SUNMatDestroy(A);
    if (yv)
        N_VDestroy(yv);
    if (atol)
        N_VDestroy(atol);
    free(roots);
    SUNContext_Free(&ctx);
    return st;
}

const rc_soft_stepper rc_soft_cvode_bdf = {
    "cvode-bdf",
    "SUNDIALS CVODE, BDF orders 1-5, dense direct linear solver, root-found contacts",
    cvode_integrate,
};
