/*
 * shadecalc/precision.h — the GLSL ES precision qualifiers, emulated (docs/formulas.md §9).
 *
 *   sc_prec                 SC_DOUBLE (the reference), SC_HIGHP (binary32),
 *                           SC_MEDIUMP (binary16, emulated), SC_LOWP (8-bit-fraction fixed point)
 *   sc_prec_parse           "double|highp|mediump|lowp" -> sc_prec
 *   sc_prec_name            sc_prec -> its name
 *   sc_round                round a double to the nearest value of a precision
 *   sc_half_from_double     binary16 bits, round to nearest even, overflow to ±Inf, subnormals kept
 *   sc_half_to_double       binary16 bits -> double (exact)
 *   sc_round_half           sc_half_to_double(sc_half_from_double(x))
 *   sc_round_lowp           nearest multiple of 2^-8 (ties to even), saturated to ±(2 - 2^-8)
 *   sc_prec_ulp             size of one ULP of a precision at an exact value
 *   sc_ulp_error            |got - exact| in ULPs of a precision at exact
 *   sc_format_shortest      the shortest decimal that reads back to the same value in a precision
 *   sc_format_bits          the value's bit pattern in a precision, in hexadecimal
 *   sc_literal_read         a decimal as strtod reads it, plus the side of it the decimal lies on
 *   sc_literal_round        that literal rounded once, correctly, to a precision
 *
 * Every value here travels as a double: a double holds every binary32, binary16 and lowp value
 * exactly, and rounding a correctly rounded double result of + - * / sqrt to binary32 or
 * binary16 gives the correctly rounded result (53 >= 2*24 + 2), so emulating a precision is
 * "compute in double, then sc_round".
 */
#ifndef SHADECALC_PRECISION_H
#define SHADECALC_PRECISION_H

#include <stddef.h>
#include <stdint.h>

#include "shadecalc/api.h"

SC_BEGIN_DECLS

typedef enum { SC_DOUBLE, SC_HIGHP, SC_MEDIUMP, SC_LOWP } sc_prec;

/* Parses a precision name; returns 0 on success, -1 on an unknown name. */
int sc_prec_parse(const char *name, sc_prec *out);
const char *sc_prec_name(sc_prec p);

double sc_round(sc_prec p, double x);

uint16_t sc_half_from_double(double x);
double sc_half_to_double(uint16_t h);
double sc_round_half(double x);

/* lowp: k * 2^-8 with |k| <= 511; NaN stays NaN, ±Inf saturates. */
#define SC_LOWP_MAX (511.0 / 256.0)
double sc_round_lowp(double x);

/* ULP of precision p at the exact value x: 2^(floor(log2|x|) - (mantissa bits)), never below the
 * format's smallest subnormal step (lowp: always 2^-8). For x = ±Inf or NaN: NaN. */
double sc_prec_ulp(sc_prec p, double x);

/* Error of got against exact in ULPs of p at exact. Both NaN, or the same infinity: 0.
 * One NaN or infinity and not the other: +Inf. */
double sc_ulp_error(sc_prec p, double got, double exact);

/* Writes the shortest %g-style decimal that reads back to x in p, rounded once (as
 * sc_literal_round reads it) ("0.6", "-0", "1e-40", "inf", "-inf", "nan"). Returns the length
 * (as snprintf) or -1 on error. */
int sc_format_shortest(char *buf, size_t size, double x, sc_prec p);

/* Writes the bit pattern of x (a value of precision p) as hexadecimal: double 0x%016x, highp
 * 0x%08x (binary32), mediump 0x%04x (binary16), lowp 0x%04x (the 16-bit two's complement of
 * x·2^8). Returns the length (as snprintf). */
int sc_format_bits(char *buf, size_t size, double x, sc_prec p);

/* A decimal literal (in GLSL source or an expression), read once and
 * rounded once to each precision. Rounding strtod's binary64 to binary32, binary16 or lowp would
 * round twice: where strtod lands exactly on a midpoint of the narrower format, ties to even can
 * pick the neighbour on the other side of the decimal (7.038531e-26 became 0x1.5c87fcp-84 in
 * highp, not the nearest 0x1.5c87fap-84). `tie` says on which side the decimal lies. */
typedef struct {
    double value;    /* what strtod returns: the nearest binary64 in the default rounding mode */
    signed char tie; /* sign(decimal - value) where value may be such a midpoint (a finite value
                        of at most 25 significant bits, as all of them are); 0 elsewhere */
} sc_literal;

/* Reads a number as strtod(s, end) does (same syntax, *end and errno). `tie` costs one or two
 * more strtod calls, under FE_DOWNWARD and FE_UPWARD (which glibc's strtod honours), and only
 * for a value of at most 25 significant bits: 0.1 or 7.5e-3 need none. */
sc_literal sc_literal_read(const char *s, char **end);

/* The literal's decimal rounded once, correctly, to p (SC_DOUBLE: its value): sc_round of the
 * value, except at a midpoint of p with the decimal off it, where the neighbour on its side. */
double sc_literal_round(sc_prec p, sc_literal lit);

SC_END_DECLS

#endif
