/* Helpers shared by the subcommands: diagnostics, getopt errors, strict number parsing. */
#include "cli/cli.h"

#include <ctype.h>
#include <errno.h>
#include <getopt.h>
#include <stdarg.h>
#include <stdlib.h>
#include <string.h>
#include <strings.h>

#include "util/text.h"

/* Every message goes through here, so user input it quotes (a file name, a spec, an
 * expression) reaches the terminal with its control characters and bad UTF-8 escaped. */
static void vreport(const char *kind, const char *fmt, va_list ap)
{
    enum { MESSAGE_MAX = 2048 };
    char message[MESSAGE_MAX], shown[4 * MESSAGE_MAX];
    vsnprintf(message, sizeof message, fmt, ap);
    fprintf(stderr, "%s: %s\n", kind, sc_escape(message, shown, sizeof shown));
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

/* ---- option parsing (sc_getopt) ---- */

/* The parse in progress: how many leading elements of argv are options (after the reorder),
 * and what the last failure was, for sc_usage_error. */
static struct {
    int arranged, end, missing_value;
    const struct option *longs;
    char optstring[128];
} parse;

/* An operand although it starts with '-': "-" itself, or '-' then a digit, '.' or '(' (a
 * negative number or expression). */
static int is_operand(const char *arg)
{
    return arg[0] != '-' || arg[1] == '\0' || isdigit((unsigned char)arg[1]) || arg[1] == '.' ||
           arg[1] == '(';
}

/* The long option `--NAME[=...]` names, as getopt_long finds it: exact, or a unique prefix
 * (NULL when unknown or ambiguous). */
static const struct option *find_long(const struct option *longs, const char *arg)
{
    size_t len = strcspn(arg + 2, "=");
    const struct option *found = NULL;
    int prefixes = 0;
    for (const struct option *o = longs; o && o->name; o++) {
        if (strncmp(o->name, arg + 2, len) != 0)
            continue;
        if (strlen(o->name) == len)
            return o;
        found = o;
        prefixes++;
    }
    return prefixes == 1 ? found : NULL;
}

/* How many elements the option at argv[i] spans: 1, or 2 when its value is the next one. */
static int option_span(const char *arg, const char *optstring, const struct option *longs)
{
    if (arg[1] == '-') {
        const struct option *o = find_long(longs, arg);
        return o && o->has_arg == required_argument && !strchr(arg, '=') ? 2 : 1;
    }
    for (const char *c = arg + 1; *c; c++) {
        const char *spec = *c == ':' || *c == '+' ? NULL : strchr(optstring, *c);
        if (spec && spec[1] == ':')
            return c[1] ? 1 : 2;
    }
    return 1;
}

/* Stable reorder of argv[1..argc): options with their values first, then a "--" if one was
 * given, then the operands; returns the number of leading elements getopt is to see. */
static int arrange(int argc, char **argv, const char *optstring, const struct option *longs)
{
    char **operands = malloc((size_t)argc * sizeof *operands);
    if (!operands)
        return argc; /* no memory for the reorder: options must then come first */
    int n_options = 1, n_operands = 0, i = 1;
    char *dashes = NULL;
    for (; i < argc; i++) {
        if (strcmp(argv[i], "--") == 0) {
            dashes = argv[i++];
            break;
        }
        if (is_operand(argv[i])) {
            operands[n_operands++] = argv[i];
            continue;
        }
        int span = option_span(argv[i], optstring, longs);
        for (int k = 0; k < span && i + k < argc; k++)
            argv[n_options++] = argv[i + k];
        i += span - 1;
    }
    for (; i < argc; i++)
        operands[n_operands++] = argv[i];
    int end = n_options;
    if (dashes)
        argv[end++] = dashes;
    memcpy(argv + end, operands, (size_t)n_operands * sizeof *operands);
    free(operands);
    return end;
}

void sc_getopt_reset(void)
{
    optind = 1;
    opterr = 0;
    parse.arranged = 0;
}

int sc_getopt(int argc, char **argv, const char *optstring, const struct option *longs)
{
    if (!parse.arranged) {
        /* '+': getopt stops at the operands arrange() moved to the end; ':': tells a missing
         * value from an unknown option. */
        snprintf(parse.optstring, sizeof parse.optstring, "+:%s",
                 optstring + (optstring[0] == '+'));
        parse.longs = longs;
        parse.end = arrange(argc, argv, parse.optstring, longs);
        parse.arranged = 1;
    }
    int c = getopt_long(parse.end, argv, parse.optstring, longs, NULL);
    parse.missing_value = c == ':';
    if (c == -1)
        optind = parse.end;
    return c == ':' ? '?' : c;
}

/* "; did you mean '--NAME'?" for a mistyped long option, else the hint at '--'. */
static const char *option_hint(const char *arg, char *buf, size_t size)
{
    char name[64];
    snprintf(name, sizeof name, "%.*s", (int)strcspn(arg + 2, "="), arg + 2);
    sc_suggestion s;
    sc_suggest_init(&s, name);
    for (const struct option *o = parse.longs; o && o->name; o++)
        sc_suggest_consider(&s, o->name);
    const char *best = sc_suggest_best(&s);
    if (best)
        snprintf(buf, size, "; did you mean '--%s'?", best);
    else
        snprintf(buf, size, "; an operand that starts with '-' goes after '--'");
    return buf;
}

int sc_usage_error(const char *cmd, char **argv, int optopt)
{
    const char *arg = argv[optind - 1];
    char shown[96], hint[96];
    int is_long = !optopt || strncmp(arg, "--", 2) == 0;
    if (!is_long)
        snprintf(shown, sizeof shown, "-%c", optopt);
    else
        snprintf(shown, sizeof shown, "%.*s", (int)strcspn(arg, "="), arg);
    if (parse.missing_value)
        sc_error("%s: option '%s' needs a value (see 'shadecalc %s --help')", cmd, shown, cmd);
    else
        sc_error("%s: unknown option '%s'%s (see 'shadecalc %s --help')", cmd, shown,
                 is_long ? option_hint(arg, hint, sizeof hint)
                         : "; an operand that starts with '-' goes after '--'",
                 cmd);
    return SC_EXIT_USAGE;
}

int sc_check_output_name(const char *cmd, const char *option, const char *path, const char *format)
{
    static const char *const images[] = {"png",  "jpg", "jpeg", "gif", "bmp", "tif", "tiff",
                                         "webp", "pdf", "ppm",  "hdr", "svg", "exr", "eps"};
    const char *dot = strrchr(path, '.');
    if (!dot || strchr(dot, '/'))
        return SC_EXIT_OK;
    for (size_t i = 0; i < sizeof images / sizeof images[0]; i++) {
        if (strcasecmp(dot + 1, images[i]) != 0 || strcasecmp(images[i], format) == 0)
            continue;
        if (strcmp(format, "table") == 0)
            sc_error("%s: %s %s: writes a table, not %s", cmd, option, path, images[i]);
        else
            sc_error("%s: %s %s: writes %s, not %s: name it .%s (and convert it if need be)", cmd,
                     option, path, format, images[i], format);
        return SC_EXIT_USAGE;
    }
    return SC_EXIT_OK;
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

void sc_print_json_string(FILE *out, const char *s)
{
    fputc('"', out);
    for (; *s; s++) {
        unsigned char c = (unsigned char)*s;
        if (c == '"' || c == '\\')
            fprintf(out, "\\%c", c);
        else if (c == '\t' || c == '\n' || c == '\r')
            fprintf(out, "\\%c", c == '\t' ? 't' : c == '\n' ? 'n' : 'r');
        else if (c < 0x20)
            fprintf(out, "\\u%04x", c);
        else
            fputc(c, out);
    }
    fputc('"', out);
}
