/* Helpers shared by the subcommands: diagnostics, getopt errors, strict number parsing. */
#include "cli/cli.h"

#include <errno.h>
#include <getopt.h>
#include <stdarg.h>
#include <stdlib.h>
#include <string.h>

static void vreport(const char *kind, const char *fmt, va_list ap)
{
    fprintf(stderr, "%s: ", kind);
    vfprintf(stderr, fmt, ap);
    fputc('\n', stderr);
}

void sc_error(const char *fmt, ...)
{
    va_list ap;
    va_start(ap, fmt);
    vreport("error", fmt, ap);
    va_end(ap);
}

void sc_warning(const char *fmt, ...)
{
    va_list ap;
    va_start(ap, fmt);
    vreport("warning", fmt, ap);
    va_end(ap);
}

int sc_usage_error(const char *cmd, char **argv, int optopt)
{
    const char *arg = argv[optind - 1];
    if (optopt && strncmp(arg, "--", 2) != 0)
        sc_error("%s: option '-%c' is unknown or needs a value (see 'shadecalc %s --help')", cmd,
                 optopt, cmd);
    else
        sc_error("%s: option '%s' is unknown or needs a value (see 'shadecalc %s --help')", cmd, arg,
                 cmd);
    return SC_EXIT_USAGE;
}

void sc_getopt_reset(void)
{
    optind = 1;
    opterr = 0;
}

int sc_parse_double(const char *s, double *out)
{
    char *end;
    errno = 0;
    double v = strtod(s, &end);
    if (end == s || *end != '\0')
        return -1;
    *out = v;
    return 0;
}

int sc_parse_long(const char *s, long *out)
{
    char *end;
    errno = 0;
    long v = strtol(s, &end, 10);
    if (end == s || *end != '\0' || errno == ERANGE)
        return -1;
    *out = v;
    return 0;
}

int sc_parse_doubles(const char *s, double *out, int n)
{
    const char *p = s;
    for (int i = 0; i < n; i++) {
        char *end;
        out[i] = strtod(p, &end);
        if (end == p)
            return -1;
        if (i + 1 < n) {
            if (*end != ',')
                return -1;
            p = end + 1;
        } else if (*end != '\0') {
            return -1;
        }
    }
    return 0;
}
