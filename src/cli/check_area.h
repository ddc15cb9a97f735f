/* shadecalc check --light: area light methods against the converged reference. */
#ifndef SHADECALC_CLI_CHECK_AREA_H
#define SHADECALC_CLI_CHECK_AREA_H

#include "shadecalc/brdf.h"
#include "shadecalc/light.h"

typedef enum { CHECK_AREA_TABLE, CHECK_AREA_CSV, CHECK_AREA_JSON } check_area_format;

/* Prints, for each method that applies to the area light with the BRDF, its maximum and mean
 * relative error against the reference (tol 1e-10) over the standard configurations, its
 * worst configuration and its time per evaluation (ns); the reference's row gives its own
 * error estimate. The specs are printed as given. Returns an exit status. */
/* The relative error (largest over the channels) of `method` against the reference for the
 * shape of `proto` placed as a configuration: centre at ratio · size, at theta_l, the viewer
 * at theta_v (degrees); NaN if the method does not apply. */
double check_area_error(const sc_light *proto, sc_area_method method, const sc_brdf *b,
                        double ratio, double theta_l, double theta_v);

int check_area_run(const char *light_spec, const sc_light *light, const char *brdf_spec,
                   const sc_brdf *brdf, check_area_format format);

#endif
