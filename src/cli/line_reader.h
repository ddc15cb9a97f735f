/* Bounded line-by-line reading of text input (eval's standard input, scene files): constant
 * memory however long the input, a clear status for a line that is too long, contains a NUL
 * byte (which would silently cut a C string) or cannot be read. */
#ifndef SHADECALC_CLI_LINE_READER_H
#define SHADECALC_CLI_LINE_READER_H

#include <stddef.h>
#include <stdio.h>

typedef enum {
    LINE_OK,        /* line holds the next line, without its "\n" or "\r\n" */
    LINE_END,       /* end of input */
    LINE_HAS_NUL,   /* the line (consumed) contains a NUL byte */
    LINE_TOO_LONG,  /* the line is longer than max_line bytes; reading stopped inside it */
    LINE_TOO_MUCH,  /* the input is longer than max_total bytes; reading stopped */
    LINE_READ_ERROR /* the stream failed: read_errno says why */
} line_status;

typedef struct {
    FILE *in;
    size_t max_line;  /* longest line accepted, in bytes */
    size_t max_total; /* most bytes read in all, 0 for no limit */
    char *line;       /* the current line, NUL-terminated (max_line + 1 bytes) */
    size_t length;    /* its length */
    long number;      /* its 1-based line number */
    size_t total;     /* bytes read so far */
    int read_errno;
} line_reader;

/* 0, or -1 if out of memory. */
int line_reader_init(line_reader *r, FILE *in, size_t max_line, size_t max_total);
line_status line_reader_next(line_reader *r);
/* Reports a status other than LINE_OK and LINE_END: a read error as "NAME: reason", the others
 * after `where` (which names the line). Returns the exit status: RUNTIME for a read error,
 * USAGE for bad input. */
int line_reader_report(const line_reader *r, line_status ls, const char *name, const char *where);
void line_reader_free(line_reader *r);

#endif
