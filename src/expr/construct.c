/* GLSL ES 3.00 constructors (§5.4) for float, vecN and matN, and the type helpers. */
#include <stdio.h>

#include "expr/expr_internal.h"

static const char *const type_names[] = {"float", "vec2", "vec3", "vec4", "mat2", "mat3", "mat4"};
static const int type_sizes[] = {1, 2, 3, 4, 4, 9, 16};

const char *sc_type_name(sc_type t) { return type_names[t]; }
int sc_type_size(sc_type t) { return type_sizes[t]; }
int sc_type_matrix_n(sc_type t) { return t >= SC_MAT2 ? (int)t - SC_MAT2 + 2 : 0; }
int sc_type_is_vector(sc_type t) { return t >= SC_VEC2 && t <= SC_VEC4; }

/* float(x) takes the first component of anything; vecN(s) and matN(s) splat a scalar (matN
 * onto the diagonal); matN(matM) copies the overlap and fills from the identity; otherwise the
 * arguments' components are consumed in order and every argument must contribute. */
int sc_construct_check(sc_type type, const sc_type *args, int n_args, char *msg, int msg_size)
{
    const char *name = sc_type_name(type);
    if (n_args == 0) {
        snprintf(msg, (size_t)msg_size, "%s: expects at least 1 argument", name);
        return -1;
    }
    if (n_args == 1 && (type == SC_FLOAT || args[0] == SC_FLOAT ||
                        (sc_type_matrix_n(type) && sc_type_matrix_n(args[0]))))
        return 0;
    if (type == SC_FLOAT) {
        snprintf(msg, (size_t)msg_size, "float: expects 1 argument, got %d", n_args);
        return -1;
    }
    int need = sc_type_size(type), have = 0;
    for (int i = 0; i < n_args; i++) {
        if (sc_type_matrix_n(type) && sc_type_matrix_n(args[i])) {
            snprintf(msg, (size_t)msg_size,
                     "%s: argument %d is %s; a matrix constructs a matrix only alone", name, i + 1,
                     sc_type_name(args[i]));
            return -1;
        }
        if (have >= need) {
            snprintf(msg, (size_t)msg_size, "%s: too many arguments (argument %d is not used)",
                     name, i + 1);
            return -1;
        }
        have += sc_type_size(args[i]);
    }
    if (have < need) {
        snprintf(msg, (size_t)msg_size, "%s: not enough components (%d given, %d needed)", name,
                 have, need);
        return -1;
    }
    return 0;
}

static sc_value matrix_from_matrix(sc_type type, const sc_value *m)
{
    int n = sc_type_matrix_n(type), mn = sc_type_matrix_n(m->type);
    sc_value out = {type, {0}};
    for (int c = 0; c < n; c++)
        for (int r = 0; r < n; r++)
            out.v[c * n + r] = (c < mn && r < mn) ? m->v[c * mn + r] : (c == r ? 1.0 : 0.0);
    return out;
}

sc_value sc_construct(sc_type type, const sc_value *args, int n_args)
{
    sc_value out = {type, {0}};
    int size = sc_type_size(type), n = sc_type_matrix_n(type);
    if (n_args == 1 && args[0].type == SC_FLOAT && type != SC_FLOAT) {
        for (int k = 0; k < size; k++)
            out.v[k] = (n == 0 || k % (n + 1) == 0) ? args[0].v[0] : 0.0;
        return out;
    }
    if (n_args == 1 && n && sc_type_matrix_n(args[0].type))
        return matrix_from_matrix(type, &args[0]);
    int k = 0;
    for (int i = 0; i < n_args && k < size; i++)
        for (int j = 0; j < sc_type_size(args[i].type) && k < size; j++)
            out.v[k++] = args[i].v[j];
    return out;
}
