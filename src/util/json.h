/* A small, strict JSON reader (RFC 8259) for the reports the command line reads back
 * (`shadecalc bench --compare`): the whole document into a tree, with bounded depth and
 * length, and an error that names the line and column of the first fault. Never crashes on
 * any input (tests/fuzz/fuzz_bench_json.c). */
#ifndef SHADECALC_UTIL_JSON_H
#define SHADECALC_UTIL_JSON_H

#include <stddef.h>

typedef enum {
    SC_JSON_NULL,
    SC_JSON_BOOL,
    SC_JSON_NUMBER,
    SC_JSON_STRING,
    SC_JSON_ARRAY,
    SC_JSON_OBJECT
} sc_json_type;

typedef struct sc_json {
    sc_json_type type;
    double number;         /* a number; a boolean as 0 or 1 */
    char *string;          /* a string, decoded (UTF-8; "\u0000" is refused) */
    char *key;             /* the member's name when the parent is an object, else NULL */
    struct sc_json *child; /* an array's first element, an object's first member */
    struct sc_json *next;  /* the next element or member */
} sc_json;

enum { SC_JSON_MAX_DEPTH = 64, SC_JSON_MAX_NUMBER = 64 /* characters of one number */ };

/* Parses text[0..len) (no NUL needed) as one JSON value, surrounded by white space only.
 * Returns the tree (free with sc_json_free), or NULL with err "line L, column C: reason"
 * (a column counts bytes from 1). */
sc_json *sc_json_parse(const char *text, size_t len, char *err, size_t errsize);
void sc_json_free(sc_json *v);
/* The member named key of an object (the first, if repeated); NULL if none or v is not one. */
const sc_json *sc_json_member(const sc_json *v, const char *key);

#endif
