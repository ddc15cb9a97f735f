/* The shadecalc command line: subcommand table, exit codes, shared helpers. */
#ifndef SHADECALC_CLI_H
#define SHADECALC_CLI_H

#include <getopt.h>
#include <stdio.h>

/* Exit status of every subcommand. */
enum { SC_EXIT_OK = 0, SC_EXIT_RUNTIME = 1, SC_EXIT_USAGE = 2 };

/* A subcommand: src/cli/cmd_NAME.c defines `const sc_command sc_cmd_NAME`. run() gets argv with
 * argv[0] = the subcommand's name and returns an exit status. */
typedef struct {
    const char *name;
    const char *summary; /* one line for `shadecalc --help` */
    int (*run)(int argc, char **argv);
} sc_command;

/* "error: <message>" on stderr (printf-style, newline added). */
void sc_error(const char *fmt, ...)
#if defined(__GNUC__)
    __attribute__((format(printf, 1, 2)))
#endif
    ;
/* "warning: <message>" on stderr. */
void sc_warning(const char *fmt, ...)
#if defined(__GNUC__)
    __attribute__((format(printf, 1, 2)))
#endif
    ;

/* Reports a failure of sc_getopt for subcommand cmd (an unknown option, with the closest
 * long option or a hint at '--'; a missing value) and returns SC_EXIT_USAGE. Call with the argv
 * and the optopt of the failed call. */
int sc_usage_error(const char *cmd, char **argv, int optopt);

/* Resets the option parser for a fresh parse (each subcommand parses its own argv). */
void sc_getopt_reset(void);

/* getopt_long with the conventions of every subcommand (the man page's CONVENTIONS): options
 * may come before, between or after the operands; "--" ends the options; an argument that
 * starts with '-' followed by a digit, '.' or '(' is an operand (a negative number or
 * expression), and so is "-". On the first call argv is reordered, options first; once it
 * returns -1, argv[optind..argc) are the operands in their order. Returns '?' for an unknown
 * option or a missing value (then call sc_usage_error). */
int sc_getopt(int argc, char **argv, const char *optstring, const struct option *longs);

/* Whether `path` may name an output written as `format` ("svg", "exr", or "table"): a name
 * whose extension is another image format (.png, .jpg, .pdf, .svg, .exr, ...) would hold what
 * its name does not say, so it is refused with a message naming cmd and option (USAGE);
 * any other name, and "-", is OK. */
int sc_check_output_name(const char *cmd, const char *option, const char *path, const char *format);

/* s as a JSON string, quoted, with '"', '\\' and control characters escaped. */
void sc_print_json_string(FILE *out, const char *s);

/* Strict number parsing: the whole string must be a number. Returns 0 on success, -1 if not. */
int sc_parse_double(const char *s, double *out);
int sc_parse_long(const char *s, long *out);
/* A comma list of exactly n numbers ("1,2,3"); returns 0 on success. */
int sc_parse_doubles(const char *s, double *out, int n);

#endif
