/* The report of `shadecalc bench` (table, CSV, JSON) and its --list (the batch table). */
#include <math.h>
#include <string.h>

#include "bench/bench.h"

/* The stated bound of a table row as text ("4 ulp", "rel 2^-12 + abs"); "-" for none. */
static const char *bound_text(const sc_batch_entry *e, char *buf, size_t size)
{
    if (!e)
        snprintf(buf, size, "-");
    else if (e->bound_ulp > 0)
        snprintf(buf, size, "%g ulp", e->bound_ulp);
    else if (e->bound_rel > 0)
        snprintf(buf, size, "rel 2^%d%s", (int)lround(log2(e->bound_rel)),
                 e->bound_abs > 0 ? " + abs" : "");
    else
        snprintf(buf, size, "abs 2^%d x scale", (int)lround(log2(e->bound_abs)));
    return buf;
}

/* The instruction sets of the rows of kernel × tier, "scalar,sse4.1,avx2" */
static void isa_list(const sc_batch_entry *first, char *buf, size_t size)
{
    buf[0] = '\0';
    for (int i = 0; i < sc_batch_count; i++) {
        const sc_batch_entry *e = &sc_batch_table[i];
        if (strcmp(e->kernel, first->kernel) == 0 && strcmp(e->tier, first->tier) == 0) {
            size_t len = strlen(buf);
            snprintf(buf + len, size - len, "%s%s", len ? "," : "", sc_isa_name(e->isa));
        }
    }
}

void bench_json_text(FILE *out, const char *s)
{
    for (; *s; s++)
        if ((unsigned char)*s < 0x20)
            fprintf(out, "\\u%04x", (unsigned)*s);
        else
            fprintf(out, *s == '"' || *s == '\\' ? "\\%c" : "%c", *s);
}

static void list_row(FILE *out, int format, const sc_batch_entry *e, int first)
{
    char isas[64], bound[48];
    isa_list(e, isas, sizeof isas);
    bound_text(e, bound, sizeof bound);
    if (format == BENCH_CSV) {
        fprintf(out, "%s,%s,\"%s\",%s,\"%s\"\n", e->kernel, e->tier, isas, bound, e->domain);
    } else if (format == BENCH_JSON) {
        fprintf(out,
                "%s  {\"kernel\": \"%s\", \"tier\": \"%s\", \"isas\": \"%s\", \"bound\": \"%s\", "
                "\"bound_ulp\": ",
                first ? "" : ",\n", e->kernel, e->tier, isas, bound);
        fprintf(out, e->bound_ulp > 0 ? "%g" : "null", e->bound_ulp);
        fprintf(out, ", \"bound_rel\": %g, \"bound_abs\": %g, \"domain\": \"", e->bound_rel,
                e->bound_abs);
        bench_json_text(out, e->domain);
        fprintf(out, "\"}");
    } else {
        fprintf(out, "%-12s %-9s %-20s %-20s %s\n", e->kernel, e->tier, isas, bound, e->domain);
    }
}

void bench_list(FILE *out, int format, const char *const *kernels, int n_kernels)
{
    if (format == BENCH_CSV)
        fprintf(out, "kernel,tier,isas,bound,domain\n");
    else if (format == BENCH_JSON)
        fprintf(out, "[\n");
    else
        fprintf(out, "%-12s %-9s %-20s %-20s %s\n", "kernel", "tier", "isa", "bound", "domain");
    int first = 1;
    for (int i = 0; i < sc_batch_count; i++) {
        const sc_batch_entry *e = &sc_batch_table[i];
        if (e->isa != SC_ISA_SCALAR || !bench_selected(e->kernel, kernels, n_kernels))
            continue;
        list_row(out, format, e, first);
        first = 0;
    }
    if (format == BENCH_JSON)
        fprintf(out, "%s]\n", first ? "" : "\n");
}

/* The row's bound in ULP, or NaN where it is stated otherwise (or not at all) */
static double stated_ulp(const bench_row *r)
{
    return r->entry && r->entry->bound_ulp > 0 ? r->entry->bound_ulp : NAN;
}

const char *bench_row_name(const bench_row *r, char *buf, size_t size)
{
    int loop = strcmp(r->tier, "loop") == 0;
    snprintf(buf, size, "%s%s%s", r->isa, loop ? "" : " ", loop ? "" : r->tier);
    return buf;
}

/* The name of the peer row that dominates r, or "" */
static const char *dominated_text(const bench_row *r, char *buf, size_t size)
{
    return r->dominated_by ? bench_row_name(r->dominated_by, buf, size) : "";
}

static void table_row(FILE *out, const bench_row *r)
{
    char bound[32], roof[16] = "-", peer[40];
    bound_text(r->entry, bound, sizeof bound);
    if (isfinite(r->roofline_fraction))
        snprintf(roof, sizeof roof, "%.0f%%", 100.0 * r->roofline_fraction);
    char cv[16];
    snprintf(cv, sizeof cv, "%.1f%%%s", 100.0 * r->cv, r->noisy ? "!" : "");
    fprintf(
        out,
        "%-11s %-17s %-10s %-8s %8zu %9.3f %8.3f %8.3f %6s %7.1f %6.2f %6.2f %11.6g %7.3f %7zu "
        "%9.2e %-16s %6s %-6s %s\n",
        r->kernel, r->scene[0] ? r->scene : "-", r->isa, r->tier, r->n, r->ns_per_elem, r->ns_min,
        r->ns_max, cv, 1e3 / r->ns_per_elem, r->speedup_vs_scalar, r->speedup_vs_libm,
        r->err.max_ulp, r->err.count ? r->err.sum_ulp / (double)r->err.count : 0.0, r->not_rounded,
        r->err.max_rel, bound, roof, r->pareto ? "*" : "", dominated_text(r, peer, sizeof peer));
}

/* a number, or nothing where it is not defined */
static void csv_number(FILE *out, double v, const char *after)
{
    if (isfinite(v))
        fprintf(out, "%.6g", v);
    fputs(after, out);
}

static void csv_row(FILE *out, const bench_row *r)
{
    fprintf(out, "%s,%s,%s,%s,%zu,%.6g,%.6g,%.6g,%.6g,%.6g,%.6g,%.6g,%.6g,%.6g,", r->kernel,
            r->scene, r->isa, r->tier, r->n, r->ns_per_elem, r->ns_min, r->ns_max,
            r->speedup_vs_scalar, r->speedup_vs_libm, r->err.max_ulp,
            r->err.count ? r->err.sum_ulp / (double)r->err.count : 0.0, r->err.max_rel,
            r->err.max_abs);
    csv_number(out, r->roofline_ns, ",");
    csv_number(out, stated_ulp(r), ",");
    csv_number(out, r->roofline_fraction, ",");
    char peer[40];
    fprintf(out, "%d,%zu,%s,%.6g,%.6g,%d\n", r->pareto, r->not_rounded,
            dominated_text(r, peer, sizeof peer), r->ns_mad, r->cv, r->noisy);
}

static void json_number(FILE *out, const char *key, double v, int comma)
{
    if (isfinite(v))
        fprintf(out, "\"%s\": %.6g%s", key, v, comma ? ", " : "");
    else
        fprintf(out, "\"%s\": null%s", key, comma ? ", " : "");
}

static void json_row(FILE *out, const bench_row *r, int last)
{
    fprintf(out,
            "    {\"kernel\": \"%s\", \"scene\": \"%s\", \"isa\": \"%s\", \"tier\": \"%s\", "
            "\"n\": %zu, ",
            r->kernel, r->scene, r->isa, r->tier, r->n);
    json_number(out, "ns_per_elem", r->ns_per_elem, 1);
    json_number(out, "elems_per_s", 1e9 / r->ns_per_elem, 1);
    json_number(out, "ns_min", r->ns_min, 1);
    json_number(out, "ns_max", r->ns_max, 1);
    json_number(out, "ns_mad", r->ns_mad, 1);
    json_number(out, "cv", r->cv, 1);
    fprintf(out, "\"noisy\": %s, ", r->noisy ? "true" : "false");
    json_number(out, "speedup_vs_scalar", r->speedup_vs_scalar, 1);
    json_number(out, "speedup_vs_libm_loop", r->speedup_vs_libm, 1);
    json_number(out, "max_ulp", r->err.max_ulp, 1);
    json_number(out, "mean_ulp", r->err.count ? r->err.sum_ulp / (double)r->err.count : 0.0, 1);
    json_number(out, "max_rel", r->err.max_rel, 1);
    json_number(out, "max_abs", r->err.max_abs, 1);
    json_number(out, "bound_ulp", stated_ulp(r), 1); /* null where stated otherwise */
    json_number(out, "bound_rel", r->entry ? r->entry->bound_rel : 0.0, 1);
    json_number(out, "roofline_ns", r->roofline_ns, 1);
    json_number(out, "roofline_fraction", r->roofline_fraction, 1);
    char peer[40];
    fprintf(out,
            "\"not_correctly_rounded\": %zu, \"pareto\": %s, \"dominated_by\": ", r->not_rounded,
            r->pareto ? "true" : "false");
    fprintf(out, r->dominated_by ? "\"%s\"}%s\n" : "null}%s%s\n",
            r->dominated_by ? dominated_text(r, peer, sizeof peer) : "", last ? "" : ",");
}

/* The compiler and flags of this build (the kernels; the peers add their own flags) */
#define BENCH_STR2(x) #x
#define BENCH_STR(x) BENCH_STR2(x)
#if defined(__clang__)
#define BENCH_COMPILER                                                                             \
    "clang " BENCH_STR(__clang_major__) "." BENCH_STR(__clang_minor__) "." BENCH_STR(              \
        __clang_patchlevel__)
#elif defined(__GNUC__)
#define BENCH_COMPILER "gcc " __VERSION__
#else
#define BENCH_COMPILER "unknown"
#endif
#ifndef SC_BENCH_FLAGS
#define SC_BENCH_FLAGS "unknown"
#endif

/* The run's metadata in JSON: date, machine, load, compiler and flags, SLEEF */
static void metadata_json(FILE *out, const bench_machine *m)
{
    fprintf(out,
            "{\n  \"machine\": {\"cpu\": \"%s\", \"stream_bandwidth_gb_s\": %.3g, "
            "\"peak_lane_ops_per_ns\": %.3g},\n",
            m->cpu, m->bandwidth, m->lane_ops_ns);
    fprintf(out,
            "  \"run\": {\"date\": \"%s\", \"load_average\": [%.2f, %.2f, %.2f], "
            "\"compiler\": \"",
            m->date, m->load[0], m->load[1], m->load[2]);
    bench_json_text(out, BENCH_COMPILER);
    fprintf(out, "\", \"flags\": \"");
    bench_json_text(out, SC_BENCH_FLAGS);
    fprintf(out, "\"},\n");
    if (*bench_sleef_absence())
        fprintf(out, "  \"sleef\": null, \"sleef_absent\": \"%s\",\n", bench_sleef_absence());
    else
        fprintf(out, "  \"sleef\": \"%s\",\n", bench_sleef_version());
}

static void json_report(FILE *out, const bench_machine *m, const bench_row *rows, int n)
{
    metadata_json(out, m);
    fprintf(out, "  \"rows\": [\n");
    for (int i = 0; i < n; i++)
        json_row(out, &rows[i], i == n - 1);
    fprintf(out, "  ]\n}\n");
}

static void csv_report(FILE *out, const bench_row *rows, int n)
{
    fprintf(out, "kernel,scene,isa,tier,n,ns_per_elem,ns_min,ns_max,speedup_vs_scalar,"
                 "speedup_vs_libm_loop,max_ulp,mean_ulp,max_rel,max_abs,roofline_ns,bound_ulp,"
                 "roofline_fraction,pareto,not_correctly_rounded,dominated_by,ns_mad,cv,noisy\n");
    for (int i = 0; i < n; i++)
        csv_row(out, &rows[i]);
}

/* The header comment of the table and Markdown reports ("# " or "" before each line) */
static void header_comment(FILE *out, const char *lead, const bench_machine *m)
{
    fprintf(out,
            "%s%s; %s; load %.2f; stream bandwidth %.3g GB/s; peak %.3g float lane-ops/ns at 8 "
            "lanes (an FMA counts one); %s, %s\n",
            lead, m->cpu, m->date, m->load[0], m->bandwidth, m->lane_ops_ns, BENCH_COMPILER,
            SC_BENCH_FLAGS);
    if (*bench_sleef_absence())
        fprintf(out, "%s%s\n", lead, bench_sleef_absence());
    fprintf(out,
            "%smedian_ns: the median of the repeats; cv: 1.4826 MAD / median, ! where noisy "
            "(cv > %.0f%% or max > 2 median); not_cr: results not the reference rounded to "
            "float; dominated_by: a peer row no less accurate, not slower beyond 3 MAD (its min "
            "at most the tier's median), and more accurate or faster beyond 3 MAD\n",
            lead, 100.0 * BENCH_NOISY_CV);
}

static int noisy_rows(const bench_row *rows, int n)
{
    int k = 0;
    for (int i = 0; i < n; i++)
        k += rows[i].noisy;
    return k;
}

static void markdown_report(FILE *out, const bench_machine *m, const bench_row *rows, int n)
{
    header_comment(out, "", m);
    fprintf(out,
            "\n| kernel | scene | isa | tier | n | median ns | cv | max ULP | not_cr | bound | "
            "pareto | dominated by |\n|---|---|---|---|---:|---:|---:|---:|---:|---|---|---|\n");
    for (int i = 0; i < n; i++) {
        const bench_row *r = &rows[i];
        char bound[32], peer[40];
        fprintf(out, "| %s | %s | %s | %s | %zu | %.4g | %.1f%%%s | %.6g | %zu | %s | %s | %s |\n",
                r->kernel, r->scene, r->isa, r->tier, r->n, r->ns_per_elem, 100.0 * r->cv,
                r->noisy ? " !" : "", r->err.max_ulp, r->not_rounded,
                bound_text(r->entry, bound, sizeof bound), r->pareto ? "*" : "",
                dominated_text(r, peer, sizeof peer));
    }
}

static void table_report(FILE *out, const bench_machine *m, const bench_row *rows, int n)
{
    header_comment(out, "# ", m);
    fprintf(out,
            "%-11s %-17s %-10s %-8s %8s %9s %8s %8s %6s %7s %6s %6s %11s %7s %7s %9s %-16s %6s "
            "%-6s %s\n",
            "kernel", "scene", "isa", "tier", "n", "median_ns", "min", "max", "cv", "Melem/s",
            "xscal", "xlibm", "max_ulp", "mean", "not_cr", "max_rel", "bound", "roof", "pareto",
            "dominated_by");
    for (int i = 0; i < n; i++)
        table_row(out, &rows[i]);
    int noisy = noisy_rows(rows, n);
    if (noisy)
        fprintf(out,
                "# %d of %d rows are noisy (!): rerun with more --repeat, on an idle machine\n",
                noisy, n);
}

void bench_report(FILE *out, int format, const bench_machine *m, const bench_row *rows, int n)
{
    if (format == BENCH_JSON)
        json_report(out, m, rows, n);
    else if (format == BENCH_CSV)
        csv_report(out, rows, n);
    else if (format == BENCH_MARKDOWN)
        markdown_report(out, m, rows, n);
    else
        table_report(out, m, rows, n);
}
