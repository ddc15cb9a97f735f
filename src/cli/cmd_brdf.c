/* shadecalc brdf — a built-in model written as a BRDF Explorer .brdf file (the man page's BRDF
 * FILES), whose GLSL computes the same f. */
#include <errno.h>
#include <getopt.h>
#include <string.h>

#include "cli/cli.h"
#include "shadecalc/brdf_file.h"
#include "shadecalc/file.h"
#include "shadecalc/scene.h"

static void usage(FILE *out)
{
    fprintf(out,
            "usage: shadecalc brdf --export SPEC [-o FILE]\n"
            "\n"
            "Writes the BRDF of SPEC (a built-in model, as for 'shadecalc shade --brdf') as a\n"
            "BRDF Explorer .brdf file: its parameters with SPEC's values as defaults, and GLSL\n"
            "doing the model's operations in the same order, so that --brdf 'file=FILE' gives\n"
            "the same f to rounding.\n"
            "\n"
            "  -x, --export SPEC    the model: lambert|phong|blinn-phong|ward|oren-nayar|\n"
            "                       cook-torrance key=value...\n"
            "  -o, --output FILE    where to write it (default: standard output)\n"
            "  -h, --help           this help\n"
            "\n"
            "example: shadecalc brdf --export 'cook-torrance alpha=0.3 D=beckmann' -o ct.brdf\n");
}

static int model_of(const char *spec, sc_brdf *out)
{
    char err[512];
    sc_model m;
    int parsed = sc_model_parse(spec, &m, err, sizeof err);
    if (parsed < 0) {
        sc_error("brdf: %s", err);
        return SC_EXIT_USAGE;
    }
    if (parsed > 0)
        sc_warning("brdf: %s", err);
    if (m.kind != SC_MODEL_BRDF || m.brdf.kind == SC_BRDF_FILE) {
        sc_error("brdf: --export '%s': not a built-in BRDF (lambert, phong, blinn-phong, ward, "
                 "oren-nayar, cook-torrance)",
                 spec);
        return SC_EXIT_USAGE;
    }
    *out = m.brdf;
    return SC_EXIT_OK;
}

static int write_export(const sc_brdf *b, const char *path)
{
    char err[512];
    sc_atomic_file *f = sc_atomic_open(path, err, sizeof err);
    if (!f) {
        sc_error("brdf: %s", err);
        return SC_EXIT_RUNTIME;
    }
    errno = 0;
    if (sc_brdf_export(sc_atomic_stream(f), b) < 0) {
        int errnum = errno; /* of the failed write */
        sc_atomic_abort(f);
        sc_error("%s: %s", strcmp(path, "-") ? path : "standard output",
                 errnum ? strerror(errnum) : "write error");
        return SC_EXIT_RUNTIME;
    }
    if (sc_atomic_commit(f, err, sizeof err) < 0) {
        sc_error("brdf: %s", err);
        return SC_EXIT_RUNTIME;
    }
    return SC_EXIT_OK;
}

static int run(int argc, char **argv)
{
    static const struct option longs[] = {{"export", required_argument, NULL, 'x'},
                                          {"output", required_argument, NULL, 'o'},
                                          {"help", no_argument, NULL, 'h'},
                                          {NULL, 0, NULL, 0}};
    const char *spec = NULL, *output = "-";
    int c;
    sc_getopt_reset();
    while ((c = sc_getopt(argc, argv, "x:o:h", longs)) != -1) {
        switch (c) {
        case 'x': spec = optarg; break;
        case 'o': output = optarg; break;
        case 'h': usage(stdout); return SC_EXIT_OK;
        default: return sc_usage_error("brdf", argv, optopt);
        }
    }
    if (optind < argc) {
        sc_error("brdf: unexpected argument '%s' (the model goes after --export)", argv[optind]);
        return SC_EXIT_USAGE;
    }
    if (!spec) {
        sc_error("brdf: no --export SPEC given (see 'shadecalc brdf --help')");
        return SC_EXIT_USAGE;
    }
    sc_brdf b;
    int status = model_of(spec, &b);
    return status == SC_EXIT_OK ? write_export(&b, output) : status;
}

const sc_command sc_cmd_brdf = {"brdf", "write a built-in BRDF as a BRDF Explorer .brdf file", run};
