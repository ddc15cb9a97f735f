/* shadecalc sweep, inside: what one row computes (a plan, from an expression, a shading setup
 * or a preset) and where the rows go (table, SVG plot, EXR image). */
#ifndef SHADECALC_CLI_SWEEP_H
#define SHADECALC_CLI_SWEEP_H

#include <stddef.h>

#include "shadecalc/plot.h"
#include "shadecalc/sweep.h"

enum { SWEEP_MAX_RESULTS = 16, SWEEP_MAX_ITEMS = 128 };

/* What each row computes and how a picture of it is labelled. */
typedef struct {
    int n_results;
    const char *columns[SWEEP_MAX_RESULTS]; /* result column names */
    const char *legend[SWEEP_MAX_RESULTS];  /* plot label of each column (NULL: the name) */
    int rgb; /* the columns are r,g,b: drawn as one curve when they agree on every row */
    int (*eval)(void *user, int worker, const double *vars, double *results, char *err,
                size_t errsize);
    /* instead of eval (NULL then): many rows at once (sc_sweep_job.eval_block) */
    int (*eval_block)(void *user, int worker, int count, const double *vars, double *results,
                      int *failure, char *err, size_t errsize);
    void *user;
    void (*report)(void *user); /* after the run: warnings (may be NULL) */
    void (*destroy)(void *user);
    char title[256];
    const char *ylabel;
    unsigned unused;             /* bit k: nothing reads variable k (warned about before the run) */
    int polar;                   /* a preset's default view */
    double ymin, ymax;           /* a preset's y range; NaN: from the data */
    const char *reference_label; /* a preset's reference line y = reference_y, or NULL */
    double reference_y;
} sweep_plan;

/* A shading option in command-line order: 'l' light, 'b' brdf, 'a' ambient, or a geometry
 * option (name = n v p eye tangent). */
typedef struct {
    int opt;
    const char *name;
    const char *arg;
} sweep_item;

typedef struct {
    const char *scene; /* --scene FILE or NULL */
    const char *tier;  /* --tier T (shading through a plan of the batch kernel) or NULL */
    sweep_item items[SWEEP_MAX_ITEMS];
    int n_items;
} sweep_setup_args;

/* Each returns an exit status (OK, or USAGE after printing the error). */

/* An expression of the variables (floats); result columns value | x,y,z,w | c0r0... */
int sweep_expr_plan(const char *src, const sc_sweep_grid *g, sc_prec p, int threads,
                    sweep_plan *plan);
/* A shading setup: with lights, L_o (r,g,b); with a BRDF and no light, f(l, v) (r,g,b).
 * theta_i phi_i theta_o phi_o (degrees) place l and v (docs/formulas.md §1). */
int sweep_shade_plan(const sweep_setup_args *a, const sc_sweep_grid *g, sc_prec p, int threads,
                     sweep_plan *plan);

/* Presets (sweep_presets.c): the lecture's figures. */
int sweep_preset_exists(const char *name);
const char *sweep_preset_names(void); /* "attenuation|spot|...|area-roughness" */
/* Adds the preset's variables to g (those the user gave keep the user's values). */
int sweep_preset_vars(const char *name, sc_sweep_grid *g);
/* The plan; the lobe preset shades a (the user's --brdf, or its default). */
int sweep_preset_plan(const char *name, sweep_setup_args *a, const sc_sweep_grid *g, sc_prec p,
                      int threads, sweep_plan *plan);

/* ---- pictures (sweep_output.c) ---- */

typedef struct {
    const char *plot, *image; /* paths or NULL */
    int exr_half;
    const char *title, *xlabel, *ylabel; /* NULL: defaults from the plan and the variables */
    int xlog, ylog, polar;
    double ymin, ymax;   /* NaN: from the data */
    const char *command; /* the command line, stored in the EXR header */
    const char *heatmap; /* path or NULL */
    sc_tone tone;        /* of the heat map */
    double exposure;
    int sqrt_x;
} sweep_picture_options;

typedef struct sweep_pictures sweep_pictures;

/* Checks that the grid fits the pictures asked for and allocates them; an exit status. */
int sweep_pictures_open(sweep_pictures **out, const sweep_picture_options *o,
                        const sc_sweep_grid *g, const sweep_plan *plan);
/* A sc_sweep_job consume callback (user = the sweep_pictures). */
int sweep_pictures_consume(void *user, uint64_t row, const double *vars, const double *results,
                           char *err, size_t errsize);
/* Writes the files (atomically); an exit status. */
int sweep_pictures_write(sweep_pictures *p);
void sweep_pictures_free(sweep_pictures *p);

#endif
