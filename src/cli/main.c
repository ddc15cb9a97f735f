/* shadecalc: dispatch to the subcommand named by argv[1]. */
#include "cli/cli.h"

#include <errno.h>
#include <fcntl.h>
#include <string.h>
#include <unistd.h>

#include "commands.h"
#include "shadecalc/file.h"
#include "util/text.h"

static const sc_command *const commands[] = {SC_COMMANDS NULL};
static const int command_count = (int)(sizeof commands / sizeof commands[0]) - 1;

static void print_help(FILE *out)
{
    fprintf(out, "usage: shadecalc COMMAND [OPTIONS] [ARGS]\n\n"
                 "Lighting equations and GLSL ES built-ins, evaluated, swept and benchmarked.\n\n"
                 "commands:\n");
    for (int i = 0; i < command_count; i++)
        fprintf(out, "  %-8s %s\n", commands[i]->name, commands[i]->summary);
    fprintf(out, "\n'shadecalc COMMAND --help' (or 'shadecalc help COMMAND') describes a command;\n"
                 "'man shadecalc' all of them. Options may follow the operands; '--' ends them;\n"
                 "-1.5 and -(x) are operands; a file named '-' is standard input or output.\n"
                 "Exit status: 0 ok, 1 runtime error, 2 usage error.\n");
}

static void unknown_command(const char *name)
{
    sc_suggestion s;
    sc_suggest_init(&s, name);
    for (int i = 0; i < command_count; i++)
        sc_suggest_consider(&s, commands[i]->name);
    const char *best = sc_suggest_best(&s);
    sc_error("unknown command '%s'%s%s%s (see 'shadecalc --help')", name,
             best ? "; did you mean '" : "", best ? best : "", best ? "'?" : "");
}

/* Runs the command argv[0] with its arguments. */
static int run_command(int argc, char **argv)
{
    for (int i = 0; i < command_count; i++)
        if (strcmp(argv[0], commands[i]->name) == 0)
            return commands[i]->run(argc, argv);
    unknown_command(argv[0]);
    return SC_EXIT_USAGE;
}

/* A closed standard descriptor (`>&-`) gets /dev/null opened the other way round: using it
 * still fails (EBADF), and no file shadecalc opens lands on it to be written as stdout. */
static void occupy_closed_std_fds(void)
{
    for (int fd = STDIN_FILENO; fd <= STDERR_FILENO; fd++)
        if (fcntl(fd, F_GETFD) == -1 && open("/dev/null", fd ? O_RDONLY : O_WRONLY) != fd)
            return; /* no /dev/null: the descriptors stay as they are */
}

/* Flushes and closes standard output: output lost (a full disk, a closed descriptor) turns a
 * success into a runtime error. A command that failed already reported its own error; a reader
 * that quit (EPIPE, seen by sweep, which ignores SIGPIPE) is not reported. */
static int finish_stdout(int status)
{
    errno = 0;
    int failed = fflush(stdout) != 0 || ferror(stdout);
    int errnum = errno;
    errno = 0;
    if (fclose(stdout) != 0 && !failed) {
        failed = 1;
        errnum = errno;
    }
    if (!failed || status != SC_EXIT_OK)
        return status;
    if (errnum != EPIPE)
        sc_error("standard output: %s", strerror(errnum ? errnum : EIO));
    return SC_EXIT_RUNTIME;
}

static int dispatch(int argc, char **argv)
{
    if (argc < 2) {
        print_help(stderr);
        return SC_EXIT_USAGE;
    }
    if (strcmp(argv[1], "help") == 0 && argc > 2) { /* help COMMAND: COMMAND --help */
        char help[] = "--help", *args[] = {argv[2], help, NULL};
        return run_command(2, args);
    }
    if (strcmp(argv[1], "--help") == 0 || strcmp(argv[1], "-h") == 0 ||
        strcmp(argv[1], "help") == 0) {
        print_help(stdout);
        return SC_EXIT_OK;
    }
    if (strcmp(argv[1], "--version") == 0) {
        printf("shadecalc %s\n", SC_VERSION);
        return SC_EXIT_OK;
    }
    return run_command(argc - 1, argv + 1);
}

int main(int argc, char **argv)
{
    occupy_closed_std_fds();
    if (sc_atomic_remove_on_signals() != 0)
        sc_warning("cannot install the signal handlers: %s (an interrupted write may leave its "
                   "temporary)",
                   strerror(errno));
    return finish_stdout(dispatch(argc, argv));
}
