/* The types of the language (shadecalc/lang.h) and the conversions between them (GLSL ES 3.00
 * §4.1, §5.4.1), with the integer widths each precision emulates. */
#include <math.h>
#include <stdio.h>
#include <string.h>

#include "lang/lang_internal.h"

sc_ltype sc_lt(sc_kind kind, int cols, int rows)
{
    sc_ltype t = {(unsigned char)kind, (unsigned char)cols, (unsigned char)rows};
    return t;
}

int sc_lt_equal(sc_ltype a, sc_ltype b)
{
    return a.kind == b.kind && a.cols == b.cols && a.rows == b.rows;
}

int sc_lt_is_scalar(sc_ltype t) { return t.cols == 1 && t.rows == 1; }
int sc_lt_is_vector(sc_ltype t) { return t.cols == 1 && t.rows >= 2; }
int sc_lt_is_matrix(sc_ltype t) { return t.cols >= 2; }
int sc_lt_is_integer(sc_ltype t) { return t.kind == SC_KIND_INT || t.kind == SC_KIND_UINT; }
int sc_ltype_size(sc_ltype t) { return t.cols * t.rows; }

static const char *const kind_prefix[] = {"", "i", "u", "b"};
static const char *const kind_scalar[] = {"float", "int", "uint", "bool"};

const char *sc_ltype_name(sc_ltype t, char *buf, int size)
{
    if (t.kind > SC_KIND_BOOL)
        snprintf(buf, (size_t)size, "void");
    else if (sc_lt_is_scalar(t))
        snprintf(buf, (size_t)size, "%s", kind_scalar[t.kind]);
    else if (sc_lt_is_vector(t))
        snprintf(buf, (size_t)size, "%svec%d", kind_prefix[t.kind], t.rows);
    else if (t.cols == t.rows)
        snprintf(buf, (size_t)size, "mat%d", t.cols);
    else
        snprintf(buf, (size_t)size, "mat%dx%d", t.cols, t.rows);
    return buf;
}

int sc_lt_parse(const char *s, int len, sc_ltype *out)
{
    char name[16];
    if (len <= 0 || len >= (int)sizeof name)
        return -1;
    memcpy(name, s, (size_t)len);
    name[len] = '\0';
    if (strcmp(name, "void") == 0) {
        *out = sc_lt((sc_kind)255, 1, 1);
        return 0;
    }
    for (int k = SC_KIND_FLOAT; k <= SC_KIND_BOOL; k++) {
        char buf[16];
        if (strcmp(name, kind_scalar[k]) == 0) {
            *out = sc_lt((sc_kind)k, 1, 1);
            return 0;
        }
        for (int n = 2; n <= 4; n++) {
            snprintf(buf, sizeof buf, "%svec%d", kind_prefix[k], n);
            if (strcmp(name, buf) == 0) {
                *out = sc_lt((sc_kind)k, 1, n);
                return 0;
            }
        }
    }
    for (int c = 2; c <= 4; c++)
        for (int r = 2; r <= 4; r++) {
            char square[16], full[16];
            snprintf(square, sizeof square, "mat%d", c);
            snprintf(full, sizeof full, "mat%dx%d", c, r);
            if (strcmp(name, full) == 0 || (c == r && strcmp(name, square) == 0)) {
                *out = sc_lt(SC_KIND_FLOAT, c, r);
                return 0;
            }
        }
    return -1;
}

int sc_lt_to_expr(sc_ltype t, sc_type *out)
{
    if (t.kind != SC_KIND_FLOAT)
        return -1;
    if (sc_lt_is_scalar(t))
        *out = SC_FLOAT;
    else if (sc_lt_is_vector(t))
        *out = (sc_type)(SC_VEC2 + t.rows - 2);
    else if (t.cols == t.rows)
        *out = (sc_type)(SC_MAT2 + t.cols - 2);
    else
        return -1;
    return 0;
}

sc_ltype sc_lt_from_expr(sc_type t)
{
    int n = sc_type_matrix_n(t);
    if (n)
        return sc_lt(SC_KIND_FLOAT, n, n);
    return sc_lt(SC_KIND_FLOAT, 1, sc_type_size(t));
}

int sc_int_bits(sc_prec p)
{
    switch (p) {
    case SC_MEDIUMP: return 16;
    case SC_LOWP: return 9;
    default: return 32;
    }
}

double sc_int_wrap_bits(sc_kind kind, int bits, unsigned long long u)
{
    u &= (1ULL << bits) - 1;
    if (kind == SC_KIND_INT && (u >> (bits - 1)))
        return (double)u - (double)(1ULL << bits);
    return (double)u;
}

/* x truncated toward zero, then wrapped; NaN and magnitudes from 2^63 on (only a caller's
 * input can have them) give 0. */
double sc_int_wrap(sc_kind kind, int bits, double x)
{
    if (!(fabs(x) < 9223372036854775808.0))
        return 0.0;
    return sc_int_wrap_bits(kind, bits, (unsigned long long)(long long)x);
}

/* float -> int or uint: truncation toward zero, saturated to the range of the width, NaN -> 0. */
static double float_to_integer(sc_kind to, int bits, double x)
{
    double range = ldexp(1.0, to == SC_KIND_INT ? bits - 1 : bits);
    double lo = to == SC_KIND_INT ? -range : 0.0, hi = range - 1.0;
    if (isnan(x))
        return 0.0;
    x = trunc(x);
    return x < lo ? lo : x > hi ? hi : x;
}

double sc_convert(sc_kind to, sc_kind from, double x, sc_prec p)
{
    if (to == from)
        return x;
    if (to == SC_KIND_BOOL)
        return x != 0.0;
    if (to == SC_KIND_FLOAT)
        return sc_round(p, x);
    if (from == SC_KIND_FLOAT)
        return float_to_integer(to, sc_int_bits(p), x);
    return sc_int_wrap(to, sc_int_bits(p), x); /* int <-> uint, bool -> 0 or 1 */
}
