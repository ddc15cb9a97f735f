/* The GLSL ES 3.00 built-ins over int, uint and bool (§8.3 integer forms of abs sign min max
 * clamp, §8.3 isnan isinf and the bit casts, §8.4 packing, §8.7 vector relational functions).
 * The float built-ins are expr/builtins.c's. Bit casts and packing are highp (binary32 and
 * 32-bit integers) whatever the precision, as GLSL ES declares them; packing computes
 * round(clamp(c, ...) × scale) with the product in binary32, rounding half to even. */
#include <math.h>
#include <stdint.h>
#include <stdio.h>
#include <string.h>

#include "lang/lang_internal.h"
#include "shadecalc/glsl_int.h"

typedef enum {
    F_LT,
    F_LE,
    F_GT,
    F_GE,
    F_EQ,
    F_NE,
    F_ANY,
    F_ALL,
    F_NOT,
    F_ABS,
    F_SIGN,
    F_MIN,
    F_MAX,
    F_CLAMP,
    F_ISNAN,
    F_ISINF,
    F_FLOAT_TO_INT,
    F_FLOAT_TO_UINT,
    F_INT_TO_FLOAT,
    F_UINT_TO_FLOAT,
    F_PACK_SNORM,
    F_UNPACK_SNORM,
    F_PACK_UNORM,
    F_UNPACK_UNORM,
    F_PACK_HALF,
    F_UNPACK_HALF
} family;

static const struct {
    const char *name;
    family f;
} table[] = {
    {"lessThan", F_LT},
    {"lessThanEqual", F_LE},
    {"greaterThan", F_GT},
    {"greaterThanEqual", F_GE},
    {"equal", F_EQ},
    {"notEqual", F_NE},
    {"any", F_ANY},
    {"all", F_ALL},
    {"not", F_NOT},
    {"abs", F_ABS},
    {"sign", F_SIGN},
    {"min", F_MIN},
    {"max", F_MAX},
    {"clamp", F_CLAMP},
    {"isnan", F_ISNAN},
    {"isinf", F_ISINF},
    {"floatBitsToInt", F_FLOAT_TO_INT},
    {"floatBitsToUint", F_FLOAT_TO_UINT},
    {"intBitsToFloat", F_INT_TO_FLOAT},
    {"uintBitsToFloat", F_UINT_TO_FLOAT},
    {"packSnorm2x16", F_PACK_SNORM},
    {"unpackSnorm2x16", F_UNPACK_SNORM},
    {"packUnorm2x16", F_PACK_UNORM},
    {"unpackUnorm2x16", F_UNPACK_UNORM},
    {"packHalf2x16", F_PACK_HALF},
    {"unpackHalf2x16", F_UNPACK_HALF},
};
enum { N_TABLE = (int)(sizeof table / sizeof table[0]) };

const char *sc_lang_builtin_name(int index) { return table[index].name; }
int sc_lang_builtin_count(void) { return N_TABLE; }

static int find(const char *name, int len)
{
    for (int i = 0; i < N_TABLE; i++)
        if ((int)strlen(table[i].name) == len && strncmp(table[i].name, name, (size_t)len) == 0)
            return i;
    return -1;
}

int sc_lang_builtin_exists(const char *name, int len) { return find(name, len) >= 0; }

/* ---- signatures ---- */

static int is_shape(sc_ltype t) { return t.cols == 1; } /* a scalar or a vector */

static sc_ltype with_kind(sc_ltype t, sc_kind k) { return sc_lt(k, t.cols, t.rows); }

/* min, max, clamp: the first argument an int or uint scalar or vector, the others its type or
 * (all of them) a scalar of its kind. */
static int integer_bounds(const sc_ltype *a, int n)
{
    if (!sc_lt_is_integer(a[0]) || !is_shape(a[0]))
        return 0;
    int all_same = 1, all_scalar = 1;
    for (int i = 1; i < n; i++) {
        all_same &= sc_lt_equal(a[i], a[0]);
        all_scalar &= sc_lt_is_scalar(a[i]) && a[i].kind == a[0].kind;
    }
    return all_same || all_scalar;
}

static int one_of(sc_ltype t, sc_kind kind, int vector_only)
{
    return t.kind == kind && is_shape(t) && (!vector_only || sc_lt_is_vector(t));
}

/* The result type of family f for the arguments, or kind 255 if they do not fit. */
static sc_ltype signature(family f, const sc_ltype *a, int n)
{
    sc_ltype none = sc_lt((sc_kind)255, 1, 1), vec2 = sc_lt(SC_KIND_FLOAT, 1, 2);
    sc_ltype uint1 = sc_lt(SC_KIND_UINT, 1, 1);
    int one = n == 1, two = n == 2 && sc_lt_equal(a[0], a[1]);
    switch (f) {
    case F_LT:
    case F_LE:
    case F_GT:
    case F_GE:
        return two && sc_lt_is_vector(a[0]) && a[0].kind != SC_KIND_BOOL
                   ? with_kind(a[0], SC_KIND_BOOL)
                   : none;
    case F_EQ:
    case F_NE: return two && sc_lt_is_vector(a[0]) ? with_kind(a[0], SC_KIND_BOOL) : none;
    case F_ANY:
    case F_ALL: return one && one_of(a[0], SC_KIND_BOOL, 1) ? sc_lt(SC_KIND_BOOL, 1, 1) : none;
    case F_NOT: return one && one_of(a[0], SC_KIND_BOOL, 1) ? a[0] : none;
    case F_ABS:
    case F_SIGN: return one && one_of(a[0], SC_KIND_INT, 0) ? a[0] : none;
    case F_MIN:
    case F_MAX: return n == 2 && integer_bounds(a, 2) ? a[0] : none;
    case F_CLAMP: return n == 3 && integer_bounds(a, 3) ? a[0] : none;
    case F_ISNAN:
    case F_ISINF:
        return one && one_of(a[0], SC_KIND_FLOAT, 0) ? with_kind(a[0], SC_KIND_BOOL) : none;
    case F_FLOAT_TO_INT:
        return one && one_of(a[0], SC_KIND_FLOAT, 0) ? with_kind(a[0], SC_KIND_INT) : none;
    case F_FLOAT_TO_UINT:
        return one && one_of(a[0], SC_KIND_FLOAT, 0) ? with_kind(a[0], SC_KIND_UINT) : none;
    case F_INT_TO_FLOAT:
        return one && one_of(a[0], SC_KIND_INT, 0) ? with_kind(a[0], SC_KIND_FLOAT) : none;
    case F_UINT_TO_FLOAT:
        return one && one_of(a[0], SC_KIND_UINT, 0) ? with_kind(a[0], SC_KIND_FLOAT) : none;
    case F_PACK_SNORM:
    case F_PACK_UNORM:
    case F_PACK_HALF: return one && sc_lt_equal(a[0], vec2) ? uint1 : none;
    default: return one && sc_lt_equal(a[0], uint1) ? vec2 : none;
    }
}

int sc_lang_builtin_resolve(const char *name, int len, const sc_ltype *args, int n_args,
                            sc_ltype *result, char *msg, int msg_size)
{
    int i = find(name, len);
    if (i < 0)
        return -2;
    *result = signature(table[i].f, args, n_args);
    if (result->kind <= SC_KIND_BOOL)
        return i;
    char list[100] = "", tb[16];
    for (int k = 0; k < n_args; k++) {
        size_t used = strlen(list);
        snprintf(list + used, sizeof list - used, "%s%s", k ? ", " : "",
                 sc_ltype_name(args[k], tb, sizeof tb));
    }
    snprintf(msg, (size_t)msg_size, "%s: no overload takes (%s)", table[i].name, list);
    return -1;
}

/* ---- evaluation ---- */

/* The bit casts and the 2x16 packings are the library's (shadecalc/glsl_int.h). */
static uint32_t float_bits(double x) { return sc_float_bits_to_uint((float)x); }

static double bits_float(double x)
{
    return sc_uint_bits_to_float((uint32_t)((unsigned long long)(long long)x & 0xFFFFFFFFu));
}

static uint32_t pack2x16(family f, const double *a)
{
    sc_vec2 v = {(float)a[0], (float)a[1]};
    if (f == F_PACK_SNORM)
        return sc_pack_snorm2x16(v);
    return f == F_PACK_UNORM ? sc_pack_unorm2x16(v) : sc_pack_half2x16(v);
}

static sc_vec2 unpack2x16(family f, uint32_t u)
{
    if (f == F_UNPACK_SNORM)
        return sc_unpack_snorm2x16(u);
    return f == F_UNPACK_UNORM ? sc_unpack_unorm2x16(u) : sc_unpack_half2x16(u);
}

static double relational(family f, double a, double b)
{
    switch (f) {
    case F_LT: return a < b;
    case F_LE: return a <= b;
    case F_GT: return a > b;
    case F_GE: return a >= b;
    case F_EQ: return a == b;
    default: return a != b;
    }
}

static double component(family f, sc_prec p, const double *a)
{
    int bits = sc_int_bits(p);
    switch (f) {
    case F_ABS: return sc_int_wrap(SC_KIND_INT, bits, fabs(a[0]));
    case F_SIGN: return (a[0] > 0) - (a[0] < 0);
    case F_MIN: return a[1] < a[0] ? a[1] : a[0];
    case F_MAX: return a[1] > a[0] ? a[1] : a[0];
    case F_CLAMP: return fmin(fmax(a[0], a[1]), a[2]);
    case F_ISNAN: return isnan(a[0]);
    case F_ISINF: return isinf(a[0]);
    case F_NOT: return a[0] == 0.0;
    case F_FLOAT_TO_INT: return sc_int_wrap_bits(SC_KIND_INT, 32, float_bits(a[0]));
    case F_FLOAT_TO_UINT: return float_bits(a[0]);
    case F_INT_TO_FLOAT:
    case F_UINT_TO_FLOAT: return sc_round(p, bits_float(a[0]));
    default: return relational(f, a[0], a[1]);
    }
}

void sc_lang_builtin_eval(int index, sc_prec p, const double *const *args, const sc_ltype *types,
                          int n_args, sc_ltype result, double *out)
{
    family f = table[index].f;
    if (f == F_ANY || f == F_ALL) {
        int any = 0, all = 1;
        for (int k = 0; k < types[0].rows; k++)
            any |= args[0][k] != 0.0, all &= args[0][k] != 0.0;
        out[0] = f == F_ANY ? any : all;
    } else if (f == F_PACK_SNORM || f == F_PACK_UNORM || f == F_PACK_HALF) {
        out[0] = (double)pack2x16(f, args[0]);
    } else if (f == F_UNPACK_SNORM || f == F_UNPACK_UNORM || f == F_UNPACK_HALF) {
        sc_vec2 v = unpack2x16(f, (uint32_t)args[0][0]);
        out[0] = sc_round(p, v.x);
        out[1] = sc_round(p, v.y);
    } else {
        for (int k = 0; k < sc_ltype_size(result); k++) {
            double a[3] = {0, 0, 0};
            for (int i = 0; i < n_args; i++)
                a[i] = args[i][sc_lt_is_scalar(types[i]) ? 0 : k];
            out[k] = component(f, p, a);
        }
    }
}
