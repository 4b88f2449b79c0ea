/* h5md.c — the H5MD 1.1 trajectory (h5md.nongnu.org): /h5md (version [1, 1], author,
 * creator), /particles/all with the box and one time-dependent group per quantity (step,
 * time and value datasets, extensible along time, chunked one frame at a time), and
 * /parameters with c and the scenario. The standard elements are position, velocity, mass,
 * species and image; relcol's own are rest_mass, momentum, proper_time and radius; the
 * scenario's outputs.h5md chooses which per-frame ones are written, float64 or float32. Every
 * dimensionful dataset has a unit attribute; the box edges are a time series (constant) of
 * D x D matrices sharing the position's step and time, the form MDAnalysis' reader reads.
 *
 * mass is the relativistic mass M = E/c^2 = gamma m (rest_mass holds m), so that
 * momentum = mass * velocity, the relation every reader assumes; with c = inf, M = m.
 * step is the frame's index k on the run's frame grid (t = from + k every), which an
 * event-driven run has in place of a step count. Only the engine is read: writing
 * changes no bit of the run. */
#include <math.h>
#include <pwd.h>
#include <stdlib.h>
#include <string.h>
#include <unistd.h>

#include <hdf5.h>

#include "h5md.h"

#ifndef RELCOL_SIM_VERSION
#define RELCOL_SIM_VERSION "unknown"
#endif

/* Per-frame elements (time-dependent groups under /particles/all), named by
 * scn_h5md_names (the scenario's outputs.h5md.fields). */
enum { E_POS = SCN_H5MD_POSITION, E_VEL = SCN_H5MD_VELOCITY, E_MASS = SCN_H5MD_MASS,
       E_REST = SCN_H5MD_REST_MASS, E_MOM = SCN_H5MD_MOMENTUM, E_TAU = SCN_H5MD_PROPER_TIME,
       E_IMAGE = SCN_H5MD_IMAGE, E_N = SCN_H5MD_N };
static const int e_vector[E_N] = {1, 1, 0, 0, 1, 0, 1};
/* H5MD's unit strings (its units module), in the GROMACS system nm, ps, u: relcol's hard
 * balls are scale free (a run in any length unit L, time unit T and mass unit M is the
 * same numbers), so the labels choose one consistent reading, the one MD readers
 * (MDAnalysis demands units) convert from; image is dimensionless and has none. */
static const char *const e_unit[E_N] = {"nm", "nm ps-1", "u", "u", "u nm ps-1", "ps", NULL};

/* Balls read at a time: a block of their states stays in the cache while its values are
 * scattered to the balls' indices. */
#define H5MD_BLOCK 1024

struct sim_h5md {
    hid_t file, all;
    hid_t value[E_N], step, time; /* datasets (H5I_INVALID_HID when absent) */
    hid_t edges;                  /* box/edges/value, one D x D matrix a frame */
    double box[9];
    int dim, f32;
    unsigned on;                  /* the elements written, bit (1u << E_*) */
    size_t n;
    hsize_t frames;
    double k2;
    rc_sim_ball *balls; /* a block of H5MD_BLOCK balls in the engine's storage order, */
    size_t *ids;        /* and their indices (rc_sim_get_balls_stored) */
    double *buf[E_N];   /* one frame of each element written (float32: float *) */
    int *img;
    app_atomic tmp;   /* the temporary name; its FILE is closed, HDF5 writes the file */
};

/* A string attribute, fixed length; or variable length (vlen), as the unit attributes are,
 * where H5MD's units module says fixed: h5py hands a fixed-length one over as bytes, and
 * MDAnalysis 2.4 matches only str (its own writer writes them so). */
static herr_t attr_text(hid_t obj, const char *name, const char *text, int vlen)
{
    hid_t t = H5Tcopy(H5T_C_S1), sp = H5Screate(H5S_SCALAR), a = H5I_INVALID_HID;
    herr_t r = -1;
    if (t >= 0 && sp >= 0 && H5Tset_size(t, vlen ? H5T_VARIABLE : strlen(text) + 1) >= 0 &&
        (vlen ? H5Tset_cset(t, H5T_CSET_UTF8) : H5Tset_strpad(t, H5T_STR_NULLTERM)) >= 0 &&
        (a = H5Acreate2(obj, name, t, sp, H5P_DEFAULT, H5P_DEFAULT)) >= 0)
        r = vlen ? H5Awrite(a, t, &text) : H5Awrite(a, t, text);
    if (a >= 0)
        H5Aclose(a);
    if (sp >= 0)
        H5Sclose(sp);
    if (t >= 0)
        H5Tclose(t);
    return r;
}

static herr_t attr_string(hid_t obj, const char *name, const char *text)
{
    return attr_text(obj, name, text, 0);
}

static herr_t attr_unit(hid_t obj, const char *text)
{
    return attr_text(obj, "unit", text, 1);
}

/* An attribute of `count` values of type mem (stored as file), a scalar when count = 0. */
static herr_t attr_numbers(hid_t obj, const char *name, hid_t file_type, hid_t mem_type,
                           hsize_t count, const void *v)
{
    hid_t sp = count ? H5Screate_simple(1, &count, NULL) : H5Screate(H5S_SCALAR);
    hid_t a = sp >= 0 ? H5Acreate2(obj, name, file_type, sp, H5P_DEFAULT, H5P_DEFAULT) : -1;
    herr_t r = a >= 0 ? H5Awrite(a, mem_type, v) : -1;
    if (a >= 0)
        H5Aclose(a);
    if (sp >= 0)
        H5Sclose(sp);
    return r;
}

/* A fixed dataset of rank 1 (n values of type mem, stored as file). */
static herr_t dataset_1d(hid_t loc, const char *name, hsize_t n, hid_t file_type,
                         hid_t mem_type, const void *v)
{
    hid_t sp = H5Screate_simple(1, &n, NULL);
    hid_t d = sp >= 0 ? H5Dcreate2(loc, name, file_type, sp, H5P_DEFAULT, H5P_DEFAULT,
                                   H5P_DEFAULT) : -1;
    herr_t r = d >= 0 ? H5Dwrite(d, mem_type, H5S_ALL, H5S_ALL, H5P_DEFAULT, v) : -1;
    if (d >= 0)
        H5Dclose(d);
    if (sp >= 0)
        H5Sclose(sp);
    return r;
}

static herr_t dataset_text(hid_t loc, const char *name, const char *text)
{
    hid_t t = H5Tcopy(H5T_C_S1), sp = H5Screate(H5S_SCALAR), d = H5I_INVALID_HID;
    herr_t r = -1;
    if (t >= 0 && sp >= 0 && H5Tset_size(t, strlen(text) + 1) >= 0 &&
        (d = H5Dcreate2(loc, name, t, sp, H5P_DEFAULT, H5P_DEFAULT, H5P_DEFAULT)) >= 0)
        r = H5Dwrite(d, t, H5S_ALL, H5S_ALL, H5P_DEFAULT, text);
    if (d >= 0)
        H5Dclose(d);
    if (sp >= 0)
        H5Sclose(sp);
    if (t >= 0)
        H5Tclose(t);
    return r;
}

/* An extensible dataset [0][dims...] (growing along time), chunked one frame at a time:
 * a whole frame is one chunk, written past HDF5's chunk cache in one piece (chunks of
 * 1 MiB cut from a frame cost a partly empty last chunk and a cache pass each; a frame
 * under 1 MiB would pass through the cache too, so the frames' datasets have none). */
static hid_t dataset_growing(hid_t loc, const char *name, hid_t type, int rank_frame,
                             const hsize_t *frame)
{
    hsize_t dims[3] = {0, 0, 0}, maxd[3] = {H5S_UNLIMITED, 0, 0}, chunk[3] = {1, 1, 1};
    for (int k = 0; k < rank_frame; k++)
        dims[k + 1] = maxd[k + 1] = chunk[k + 1] = frame[k];
    if (rank_frame == 0) /* step, time: many frames to a chunk */
        chunk[0] = 1024;
    if (rank_frame > 0 && chunk[1] == 0)
        chunk[1] = 1; /* (no balls: HDF5 refuses a zero chunk) */
    hid_t sp = H5Screate_simple(rank_frame + 1, dims, maxd);
    hid_t pl = H5Pcreate(H5P_DATASET_CREATE);
    hid_t ap = rank_frame > 0 ? H5Pcreate(H5P_DATASET_ACCESS) : H5P_DEFAULT;
    hid_t d = H5I_INVALID_HID;
    if (sp >= 0 && pl >= 0 && ap >= 0 && H5Pset_chunk(pl, rank_frame + 1, chunk) >= 0 &&
        (rank_frame == 0 || H5Pset_chunk_cache(ap, 0, 0, 1.0) >= 0))
        d = H5Dcreate2(loc, name, type, sp, H5P_DEFAULT, pl, ap);
    if (ap >= 0 && ap != H5P_DEFAULT)
        H5Pclose(ap);
    if (pl >= 0)
        H5Pclose(pl);
    if (sp >= 0)
        H5Sclose(sp);
    return d;
}

/* Append one frame (the row `at`) of the growing dataset d. */
static herr_t append(hid_t d, hid_t mem_type, hsize_t at, int rank_frame, const hsize_t *frame,
                     const void *v)
{
    hsize_t dims[3] = {at + 1, 0, 0}, start[3] = {at, 0, 0}, count[3] = {1, 0, 0};
    for (int k = 0; k < rank_frame; k++)
        dims[k + 1] = count[k + 1] = frame[k];
    if (H5Dset_extent(d, dims) < 0)
        return -1;
    hid_t fs = H5Dget_space(d), ms = H5Screate_simple(rank_frame + 1, count, NULL);
    herr_t r = -1;
    if (fs >= 0 && ms >= 0 && H5Sselect_hyperslab(fs, H5S_SELECT_SET, start, NULL, count, NULL) >= 0)
        r = H5Dwrite(d, mem_type, ms, fs, H5P_DEFAULT, v);
    if (ms >= 0)
        H5Sclose(ms);
    if (fs >= 0)
        H5Sclose(fs);
    return r;
}

static void close_all(sim_h5md *h)
{
    for (int e = 0; e < E_N; e++)
        if (h->value[e] >= 0)
            H5Dclose(h->value[e]);
    if (h->step >= 0)
        H5Dclose(h->step);
    if (h->time >= 0)
        H5Dclose(h->time);
    if (h->edges >= 0)
        H5Dclose(h->edges);
    if (h->all >= 0)
        H5Gclose(h->all);
    for (int e = 0; e < E_N; e++)
        h->value[e] = H5I_INVALID_HID;
    h->step = h->time = h->all = h->edges = H5I_INVALID_HID;
}

/* The scenario as relcol read it (the JSON of relcol-sim --dump), malloc'ed. */
static char *scenario_text(const scn_scenario *s)
{
    char *text = NULL;
    size_t len = 0;
    FILE *f = open_memstream(&text, &len);
    if (!f)
        return NULL;
    int bad = scn_write(f, s, s->time, s->t_end, s->n, s->balls);
    if (fclose(f) != 0 || bad) {
        free(text);
        return NULL;
    }
    return text;
}

static int build(sim_h5md *h, const scn_scenario *s, const char *prog)
{
    const int D = s->dim;
    hid_t g = H5Gcreate2(h->file, "h5md", H5P_DEFAULT, H5P_DEFAULT, H5P_DEFAULT);
    if (g < 0)
        return -1;
    const int version[2] = {1, 1};
    struct passwd *pw = getpwuid(getuid());
    hid_t au = H5Gcreate2(g, "author", H5P_DEFAULT, H5P_DEFAULT, H5P_DEFAULT);
    hid_t cr = H5Gcreate2(g, "creator", H5P_DEFAULT, H5P_DEFAULT, H5P_DEFAULT);
    herr_t r = attr_numbers(g, "version", H5T_STD_I32LE, H5T_NATIVE_INT, 2, version);
    if (r >= 0 && au >= 0)
        r = attr_string(au, "name", pw && pw->pw_name && *pw->pw_name ? pw->pw_name : "unknown");
    if (r >= 0 && cr >= 0)
        r = attr_string(cr, "name", prog);
    if (r >= 0 && cr >= 0)
        r = attr_string(cr, "version", RELCOL_SIM_VERSION);
    if (au >= 0)
        H5Gclose(au);
    if (cr >= 0)
        H5Gclose(cr);
    H5Gclose(g);
    if (r < 0 || au < 0 || cr < 0)
        return -1;

    hid_t lc = H5Pcreate(H5P_LINK_CREATE);
    if (lc < 0 || H5Pset_create_intermediate_group(lc, 1) < 0)
        return -1;
    h->all = H5Gcreate2(h->file, "particles/all", lc, H5P_DEFAULT, H5P_DEFAULT);
    hid_t box = h->all >= 0 ? H5Gcreate2(h->all, "box", H5P_DEFAULT, H5P_DEFAULT, H5P_DEFAULT) : -1;
    H5Pclose(lc);
    if (box < 0)
        return -1;
    /* H5MD knows periodic and "none" boundaries: relcol's walls are "none" */
    char bnd[3][9] = {{0}};
    for (int d = 0; d < D; d++) {
        strcpy(bnd[d], s->boundary[d] == RC_SIM_PERIODIC ? "periodic" : "none");
        h->box[d * D + d] = rc_v3_get(s->box, d);
    }
    hid_t bt = H5Tcopy(H5T_C_S1);
    r = bt >= 0 ? H5Tset_size(bt, sizeof bnd[0]) : -1;
    if (r >= 0)
        r = attr_numbers(box, "boundary", bt, bt, (hsize_t)D, bnd);
    if (bt >= 0)
        H5Tclose(bt);
    if (r >= 0)
        r = attr_numbers(box, "dimension", H5T_STD_I32LE, H5T_NATIVE_INT, 0, &D);
    /* edges as a time-dependent element of D x D matrices (the box's vectors, diagonal),
     * though the box does not change: H5MD allows a plain Float[D] too, but MDAnalysis
     * 2.4 reads only box/edges/value[frame] and only as three vectors */
    hid_t eg = r >= 0 ? H5Gcreate2(box, "edges", H5P_DEFAULT, H5P_DEFAULT, H5P_DEFAULT) : -1;
    hsize_t nd[2] = {(hsize_t)D, (hsize_t)D};
    h->edges = eg >= 0 ? dataset_growing(eg, "value", H5T_IEEE_F64LE, 2, nd) : -1;
    r = h->edges >= 0 ? attr_unit(h->edges, "nm") : -1;
    if (eg >= 0)
        H5Gclose(eg);
    H5Gclose(box);
    if (r < 0)
        return -1;

    /* species: one kind of ball (an integer per ball, which does not change); radius:
     * the rest radius, fixed too */
    int *zeros = calloc(h->n ? h->n : 1, sizeof *zeros);
    double *radius = malloc((h->n ? h->n : 1) * sizeof *radius);
    r = zeros && radius ? 0 : -1;
    for (size_t i = 0; !r && i < h->n; i++)
        radius[i] = s->balls[i].r;
    if (r >= 0)
        r = dataset_1d(h->all, "species", (hsize_t)h->n, H5T_STD_I32LE, H5T_NATIVE_INT, zeros);
    if (r >= 0)
        r = dataset_1d(h->all, "radius", (hsize_t)h->n, H5T_IEEE_F64LE, H5T_NATIVE_DOUBLE,
                       radius);
    if (r >= 0) {
        hid_t rd = H5Dopen2(h->all, "radius", H5P_DEFAULT);
        r = rd >= 0 ? attr_unit(rd, "nm") : -1;
        if (rd >= 0)
            H5Dclose(rd);
    }
    free(zeros);
    free(radius);
    if (r < 0)
        return -1;

    /* the time-dependent elements chosen: step and time made once (in the first, position
     * unless it is left out) and hard-linked into the others, as H5MD allows for elements
     * sampled together */
    int first = 0;
    while (first < E_N && !(h->on >> first & 1u))
        first++;
    char clock_step[64], clock_time[64];
    snprintf(clock_step, sizeof clock_step, "%s/step", first < E_N ? scn_h5md_names[first] : "");
    snprintf(clock_time, sizeof clock_time, "%s/time", first < E_N ? scn_h5md_names[first] : "");
    for (int e = 0; e < E_N; e++) {
        if (!(h->on >> e & 1u))
            continue;
        hid_t eg = H5Gcreate2(h->all, scn_h5md_names[e], H5P_DEFAULT, H5P_DEFAULT, H5P_DEFAULT);
        if (eg < 0)
            return -1;
        hsize_t frame[2] = {(hsize_t)h->n, (hsize_t)D};
        int rank = e_vector[e] ? 2 : 1;
        h->value[e] = dataset_growing(eg, "value", e == E_IMAGE ? H5T_STD_I32LE : h->f32 ?
                                      H5T_IEEE_F32LE : H5T_IEEE_F64LE, rank, frame);
        if (h->value[e] >= 0 && e_unit[e] && attr_unit(h->value[e], e_unit[e]) < 0) {
            H5Gclose(eg);
            return -1;
        }
        if (e == first) {
            h->step = dataset_growing(eg, "step", H5T_STD_I64LE, 0, NULL);
            h->time = dataset_growing(eg, "time", H5T_IEEE_F64LE, 0, NULL);
            if (h->time >= 0 && attr_unit(h->time, "ps") < 0) {
                H5Gclose(eg);
                return -1;
            }
            /* the box's edges share the position's step and time */
            if (h->step < 0 || h->time < 0 ||
                H5Lcreate_hard(eg, "step", h->all, "box/edges/step", H5P_DEFAULT, H5P_DEFAULT) < 0 ||
                H5Lcreate_hard(eg, "time", h->all, "box/edges/time", H5P_DEFAULT, H5P_DEFAULT) < 0) {
                H5Gclose(eg);
                return -1;
            }
        } else if (H5Lcreate_hard(h->all, clock_step, eg, "step", H5P_DEFAULT, H5P_DEFAULT) < 0 ||
                   H5Lcreate_hard(h->all, clock_time, eg, "time", H5P_DEFAULT, H5P_DEFAULT) < 0) {
            H5Gclose(eg);
            return -1;
        }
        H5Gclose(eg);
        if (h->value[e] < 0 || h->step < 0 || h->time < 0)
            return -1;
    }

    /* parameters (H5MD's group for a program's own settings): c as a float attribute
     * (HDF5 floats are IEEE: the classical c = inf is stored as inf), and the scenario,
     * as a text dataset (it holds every ball: too large for an attribute; unless
     * outputs.h5md.scenario is false: at 1e5 balls its digits cost as much as 20 frames) */
    hid_t pg = H5Gcreate2(h->file, "parameters", H5P_DEFAULT, H5P_DEFAULT, H5P_DEFAULT);
    if (pg < 0)
        return -1;
    char *text = s->out.h5md_scenario ? scenario_text(s) : NULL;
    r = text || !s->out.h5md_scenario ? attr_numbers(pg, "c", H5T_IEEE_F64LE, H5T_NATIVE_DOUBLE,
                                                     0, &s->c) : -1;
    if (r >= 0) /* (an attribute has no attributes: c's unit is its own) */
        r = attr_string(pg, "c_unit", "nm ps-1");
    if (r >= 0)
        r = attr_string(pg, "law", s->law->name);
    if (r >= 0)
        r = attr_string(pg, "contact_frame", s->frame->name);
    if (r >= 0 && text)
        r = dataset_text(pg, "scenario", text);
    free(text);
    H5Gclose(pg);
    return r < 0 ? -1 : 0;
}

int h5md_open(sim_h5md **out, const char *path, const scn_scenario *s, size_t n,
              const char *prog, char *err)
{
    *out = NULL;
    sim_h5md *h = calloc(1, sizeof *h);
    if (!h) {
        app_errf(err, "out of memory");
        return -1;
    }
    h->file = h->all = h->step = h->time = h->edges = H5I_INVALID_HID;
    for (int e = 0; e < E_N; e++)
        h->value[e] = H5I_INVALID_HID;
    h->dim = s->dim;
    h->n = n;
    h->k2 = isinf(s->c) ? 0.0 : 1.0 / (s->c * s->c);
    h->on = s->out.h5md_fields & ((1u << E_N) - 1u);
    h->f32 = s->out.h5md_float32;
    if (!h->on) {
        app_errf(err, "%s: no element chosen to write (outputs.h5md.fields)", path);
        free(h);
        return -1;
    }
    const size_t nn = n ? n : 1;
    const size_t word = h->f32 ? sizeof(float) : sizeof(double);
    for (int e = 0; e < E_N; e++)
        if (e != E_IMAGE && (h->on >> e & 1u) &&
            !(h->buf[e] = malloc(nn * (size_t)(e_vector[e] ? s->dim : 1) * word)))
            goto nomem;
    if ((h->on >> E_IMAGE & 1u) && !(h->img = malloc(nn * (size_t)s->dim * sizeof *h->img)))
        goto nomem;
    if (!(h->balls = malloc(H5MD_BLOCK * sizeof *h->balls)) ||
        !(h->ids = malloc(H5MD_BLOCK * sizeof *h->ids)))
        goto nomem;
    /* the temporary name (hidden, with our pid: a later run removes it if we are killed);
     * HDF5 then rewrites the file under that name */
    if (app_atomic_open(&h->tmp, path, err)) {
        h5md_close(&h, 0, err);
        return -1;
    }
    fclose(h->tmp.f);
    h->tmp.f = NULL;
    /* HDF5's exit handler closes the files still open, and crashes on one whose close
     * failed (a full disk): we close ours ourselves, so the handler is not needed */
    H5dont_atexit();
    H5Eset_auto2(H5E_DEFAULT, NULL, NULL); /* errors come back as codes, said by us */
    hid_t fapl = H5Pcreate(H5P_FILE_ACCESS);
    if (fapl >= 0)
        H5Pset_libver_bounds(fapl, H5F_LIBVER_V18, H5F_LIBVER_LATEST);
    h->file = fapl >= 0 ? H5Fcreate(h->tmp.tmp, H5F_ACC_TRUNC, H5P_DEFAULT, fapl) : -1;
    if (fapl >= 0)
        H5Pclose(fapl);
    if (h->file < 0 || build(h, s, prog)) {
        app_errf(err, "cannot write %s (HDF5 refused to create its structure)", path);
        h5md_close(&h, 0, err);
        return -1;
    }
    *out = h;
    return 0;
nomem:
    app_errf(err, "out of memory for the H5MD trajectory");
    h5md_close(&h, 0, err);
    return -1;
}

/* Store x as element e's value k of this frame, in the file's precision. */
static inline void put(sim_h5md *h, int e, size_t k, double x)
{
    if (h->f32)
        ((float *)h->buf[e])[k] = (float)x; /* (rounded to nearest) */
    else
        h->buf[e][k] = x;
}

int h5md_frame(sim_h5md *h, const rc_sim *sim, long long step, char *err)
{
    const int D = h->dim;
    /* the balls in the engine's storage order, a block at a time (rc_sim_get_ball's
     * bits), each value scattered to its ball's index: one ball at a time in caller order,
     * or whole rc_sim_balls scattered, cost a cache and TLB miss a ball (16 % of a 1e5-ball
     * run) */
    const unsigned on = h->on;
    for (size_t from = 0; from < h->n; from += H5MD_BLOCK) {
        const size_t count = h->n - from < H5MD_BLOCK ? h->n - from : H5MD_BLOCK;
        if (rc_sim_get_balls_stored(sim, from, count, h->balls, h->ids, 0, NULL) != RC_OK) {
            app_errf(err, "cannot read the balls for frame %llu of %s",
                     (unsigned long long)h->frames, h->tmp.path);
            return -1;
        }
        for (size_t k = 0; k < count; k++) {
            const rc_sim_ball *b = &h->balls[k];
            const size_t i = h->ids[k], at = i * (size_t)D;
            /* M as rc_mass_rel, v as rc_velocity and M as m rc_gamma form them (the same
             * operations, so the same bits), inline: a library call a ball was 1/4 of a frame */
            const double M = on & (1u << E_VEL | 1u << E_MASS)
                             ? sqrt(b->m * b->m + rc_v3_norm2(b->p) * h->k2) : 0.0;
            if (on >> E_VEL & 1u) {
                const rc_vec3 v = rc_v3_scale(1.0 / M, b->p);
                for (int d = 0; d < D; d++)
                    put(h, E_VEL, at + (size_t)d, rc_v3_get(v, d));
            }
            for (int d = 0; d < D; d++) {
                if (on >> E_POS & 1u)
                    put(h, E_POS, at + (size_t)d, rc_v3_get(b->x, d));
                if (on >> E_MOM & 1u)
                    put(h, E_MOM, at + (size_t)d, rc_v3_get(b->p, d));
                if (on >> E_IMAGE & 1u)
                    h->img[at + (size_t)d] = b->image[d];
            }
            if (on >> E_MASS & 1u)
                put(h, E_MASS, i, b->m * (M / b->m));
            if (on >> E_REST & 1u)
                put(h, E_REST, i, b->m);
            if (on >> E_TAU & 1u)
                put(h, E_TAU, i, b->tau);
        }
    }
    const double t = rc_sim_time(sim);
    const int64_t st = step;
    herr_t r = append(h->step, H5T_NATIVE_INT64, h->frames, 0, NULL, &st);
    if (r >= 0)
        r = append(h->time, H5T_NATIVE_DOUBLE, h->frames, 0, NULL, &t);
    hsize_t nd[2] = {(hsize_t)D, (hsize_t)D};
    if (r >= 0)
        r = append(h->edges, H5T_NATIVE_DOUBLE, h->frames, 2, nd, h->box);
    for (int e = 0; r >= 0 && e < E_N; e++) {
        hsize_t frame[2] = {(hsize_t)h->n, (hsize_t)D};
        if (!(on >> e & 1u))
            continue;
        if (e == E_IMAGE)
            r = append(h->value[e], H5T_NATIVE_INT, h->frames, 2, frame, h->img);
        else
            r = append(h->value[e], h->f32 ? H5T_NATIVE_FLOAT : H5T_NATIVE_DOUBLE, h->frames,
                       e_vector[e] ? 2 : 1, frame, h->buf[e]);
    }
    if (r < 0) {
        app_errf(err, "cannot write frame %llu of %s (HDF5 write failed: disk full?)",
                 (unsigned long long)h->frames, h->tmp.path);
        return -1;
    }
    h->frames++;
    return 0;
}

int h5md_close(sim_h5md **hp, int commit, char *err)
{
    sim_h5md *h = *hp;
    if (!h)
        return 0;
    *hp = NULL;
    int r = 0;
    close_all(h);
    if (h->file >= 0 && H5Fclose(h->file) < 0 && commit) {
        app_errf(err, "cannot write %s (HDF5 could not close it: disk full?)", h->tmp.path);
        r = -1;
    }
    if (commit && !r) {
        /* reopened only to hand the file to the atomic writer: fsync, rename, fsync */
        h->tmp.f = fopen(h->tmp.tmp, "r+b");
        if (!h->tmp.f) {
            app_errf(err, "cannot reopen %s", h->tmp.tmp);
            r = -1;
        } else {
            r = app_atomic_commit(&h->tmp, err);
        }
    }
    if (!commit || r)
        app_atomic_abort(&h->tmp);
    for (int e = 0; e < E_N; e++)
        free(h->buf[e]);
    free(h->img);
    free(h->balls);
    free(h->ids);
    free(h);
    return r;
}
