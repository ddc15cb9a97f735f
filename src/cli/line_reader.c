/* Bounded line reading (line_reader.h). */
#include "cli/line_reader.h"

#include <errno.h>
#include <stdlib.h>
#include <string.h>

#include "cli/cli.h"

int line_reader_init(line_reader *r, FILE *in, size_t max_line, size_t max_total)
{
    *r = (line_reader){.in = in, .max_line = max_line, .max_total = max_total};
    r->line = malloc(max_line + 1);
    return r->line ? 0 : -1;
}

void line_reader_free(line_reader *r)
{
    free(r->line);
    r->line = NULL;
}

/* Reads up to the end of the line or of the input. The limits stop the reading where they are
 * passed, so endless input without a newline (/dev/zero) ends promptly. */
static line_status read_line(line_reader *r);

/* The line as far as it was read is always a string, whatever the status (the buffer holds
 * max_line + 1 bytes). */
line_status line_reader_next(line_reader *r)
{
    line_status ls = read_line(r);
    r->line[r->length] = '\0';
    return ls;
}

static line_status read_line(line_reader *r)
{
    int c, has_nul = 0;
    r->length = 0;
    r->number++;
    errno = 0;
    while ((c = getc_unlocked(r->in)) != EOF && c != '\n') {
        if (r->max_total && r->total == r->max_total)
            return LINE_TOO_MUCH;
        r->total++;
        if (r->length == r->max_line)
            return LINE_TOO_LONG;
        has_nul |= c == '\0';
        r->line[r->length++] = (char)c;
    }
    if (c == EOF && ferror(r->in)) {
        r->read_errno = errno;
        return LINE_READ_ERROR;
    }
    if (c == EOF && r->length == 0)
        return LINE_END;
    r->total += c == '\n';
    if (r->length > 0 && r->line[r->length - 1] == '\r')
        r->length--;
    return has_nul ? LINE_HAS_NUL : LINE_OK;
}

int line_reader_report(const line_reader *r, line_status ls, const char *name, const char *where)
{
    if (ls == LINE_READ_ERROR) {
        sc_error("%s: %s", name, r->read_errno ? strerror(r->read_errno) : "read error");
        return SC_EXIT_RUNTIME;
    }
    if (ls == LINE_HAS_NUL)
        sc_error("%scontains a NUL byte", where);
    else if (ls == LINE_TOO_LONG)
        sc_error("%slonger than %zu bytes", where, r->max_line);
    else
        sc_error("%sthe input is longer than %zu bytes", where, r->max_total);
    return SC_EXIT_USAGE;
}
