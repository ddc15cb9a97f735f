/* BRDFs written in GLSL at the command line (brdf_file_cli.h). */
#include "cli/brdf_file_cli.h"

#include "cli/cli.h"

static int is_file(const sc_model *m)
{
    return m->kind == SC_MODEL_BRDF && m->brdf.kind == SC_BRDF_FILE;
}

static void value(FILE *out, const double *v, int n, sc_prec p, int json)
{
    char buf[64];
    fputs(n == 1 ? "" : json ? "[" : "(", out);
    for (int c = 0; c < n; c++) {
        sc_format_shortest(buf, sizeof buf, v[c], p);
        fprintf(out, "%s%s", c ? ", " : "", buf);
    }
    fputs(n == 1 ? "" : json ? "]" : ")", out);
}

static void explain_text(FILE *out, const sc_brdf *b, sc_prec p)
{
    const sc_brdf_param *params;
    int n = sc_brdf_file_params(b->file, &params);
    fprintf(out, "brdf file %s (%d parameter%s)\n", sc_brdf_file_name(b->file), n,
            n == 1 ? "" : "s");
    for (int i = 0; i < n; i++) {
        const sc_brdf_param *prm = &params[i];
        const double *v = b->file_values + prm->offset;
        fprintf(out, "  %s = ", prm->name);
        if (prm->type == SC_BRDF_PARAM_BOOL)
            fputs(v[0] != 0.0 ? "true" : "false", out);
        else
            value(out, v, prm->type == SC_BRDF_PARAM_COLOR ? 3 : 1, p, 0);
        if (prm->type == SC_BRDF_PARAM_FLOAT)
            fprintf(out, "  (float %.9g..%.9g, line %d)\n", prm->min, prm->max, prm->line);
        else
            fprintf(out, "  (%s, line %d)\n", prm->type == SC_BRDF_PARAM_BOOL ? "bool" : "color",
                    prm->line);
    }
}

static void explain_json(FILE *out, const sc_brdf *b, sc_prec p)
{
    static const char *const types[] = {"float", "bool", "color"};
    const sc_brdf_param *params;
    int n = sc_brdf_file_params(b->file, &params);
    fputs(", \"brdf_file\": ", out);
    sc_print_json_string(out, sc_brdf_file_name(b->file));
    fputs(", \"parameters\": [", out);
    for (int i = 0; i < n; i++) {
        const sc_brdf_param *prm = &params[i];
        fprintf(out, "%s{\"name\": \"%s\", \"type\": \"%s\", \"value\": ", i ? ", " : "", prm->name,
                types[prm->type]);
        if (prm->type == SC_BRDF_PARAM_BOOL)
            fputs(b->file_values[prm->offset] != 0.0 ? "true" : "false", out);
        else
            value(out, b->file_values + prm->offset, prm->type == SC_BRDF_PARAM_COLOR ? 3 : 1, p,
                  1);
        if (prm->type == SC_BRDF_PARAM_FLOAT)
            fprintf(out, ", \"min\": %.17g, \"max\": %.17g", prm->min, prm->max);
        fprintf(out, ", \"line\": %d}", prm->line);
    }
    fputs("]", out);
}

void brdf_file_explain(FILE *out, const sc_model *m, sc_prec p, int json)
{
    if (!is_file(m))
        return;
    if (json)
        explain_json(out, &m->brdf, p);
    else
        explain_text(out, &m->brdf, p);
}

const char *brdf_file_failure(const sc_model *m)
{
    return is_file(m) ? sc_brdf_file_error(m->brdf.file) : NULL;
}

int brdf_file_status(const sc_model *m, const char *cmd)
{
    const char *err = brdf_file_failure(m);
    if (!err)
        return SC_EXIT_OK;
    sc_error("%s: %s", cmd, err);
    return SC_EXIT_RUNTIME;
}
