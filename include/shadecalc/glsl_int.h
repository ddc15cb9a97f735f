/*
 * shadecalc/glsl_int.h — the GLSL ES 3.00 built-ins on bool, int and uint values, the bit casts
 * and the packing functions (§8.3, §8.4, §8.7), scalar and per component.
 *
 * Scalars (in src/glsl_int.c):
 *   classification   sc_isnanf sc_isinff                                   float -> bool
 *   bit casts        sc_float_bits_to_int sc_float_bits_to_uint             float -> int32/uint32
 *                    sc_int_bits_to_float sc_uint_bits_to_float             int32/uint32 -> float
 *   packing          sc_pack_snorm2x16 sc_unpack_snorm2x16 sc_pack_unorm2x16 sc_unpack_unorm2x16
 *                    sc_pack_half2x16 sc_unpack_half2x16                    vec2 <-> uint32
 *   integers         sc_mini sc_maxi sc_clampi sc_absi sc_signi             int32
 *                    sc_minu sc_maxu sc_clampu                              uint32
 * Vectors: sc_ivecN {x,y[,z[,w]]} of int32_t, sc_uvecN of uint32_t, sc_bvecN of bool (N = 2, 3,
 * 4; sc_vecN is shadecalc/vec.h's), each function applied per component (static inline here):
 *   sc_vecN_isnan sc_vecN_isinf                                             -> bvecN
 *   sc_vecN_float_bits_to_int -> ivecN   sc_vecN_float_bits_to_uint -> uvecN
 *   sc_ivecN_int_bits_to_float -> vecN   sc_uvecN_uint_bits_to_float -> vecN
 *   sc_T_less_than sc_T_less_than_equal sc_T_greater_than sc_T_greater_than_equal
 *   sc_T_equal sc_T_not_equal                      T = vecN, ivecN, uvecN -> bvecN
 *   sc_bvecN_equal sc_bvecN_not_equal sc_bvecN_any sc_bvecN_all sc_bvecN_not
 *   sc_ivecN_min sc_ivecN_max sc_ivecN_clamp sc_ivecN_abs sc_ivecN_sign
 *   sc_uvecN_min sc_uvecN_max sc_uvecN_clamp
 *
 * Semantics (GLSL ES 3.00; where it leaves a result undefined, the choice is stated):
 *   isnan, isinf read the bits, so they hold under -ffinite-math-only too.
 *   Bit casts keep every bit (NaN payloads included: GLSL leaves the float of a NaN pattern
 *   unspecified).
 *   Float comparisons are IEEE: NaN compares unequal and unordered (lessThan(NaN, x) false),
 *   equal(−0, +0) true.
 *   packSnorm2x16: round(clamp(c, −1, 1)·32767.0), packUnorm2x16: round(clamp(c, 0, 1)·65535.0),
 *   the product in binary32 and round with halves to even (sc_roundf); the first component in
 *   the 16 least significant bits. A NaN component packs as 0 (GLSL: undefined).
 *   unpackSnorm2x16: clamp(f/32767.0, −1, 1), unpackUnorm2x16: f/65535.0, each one division in
 *   binary32 (correctly rounded).
 *   packHalf2x16: binary16 rounded to nearest even, overflow to ±Inf, subnormals kept
 *   (sc_half_from_double, the mediump rounding of shadecalc/precision.h), NaN as the F16C
 *   instruction converts it (quiet, the top 10 bits of the payload); bit for bit the result of
 *   vcvtps2ph with round-to-nearest. unpackHalf2x16 is exact (NaN quieted, payload kept, as
 *   vcvtph2ps).
 *   Integers wrap modulo 2^32 as GLSL ES specifies: abs(INT32_MIN) = INT32_MIN; sign gives −1, 0,
 *   1; clamp(x, lo, hi) = min(max(x, lo), hi), so hi when lo > hi (GLSL: undefined); min and
 *   max compare as signed for int, unsigned for uint.
 */
#ifndef SHADECALC_GLSL_INT_H
#define SHADECALC_GLSL_INT_H

#include <stdbool.h>
#include <stdint.h>

#include "shadecalc/api.h"
#include "shadecalc/vec.h"

SC_BEGIN_DECLS

bool sc_isnanf(float x);
bool sc_isinff(float x);

int32_t sc_float_bits_to_int(float x);
uint32_t sc_float_bits_to_uint(float x);
float sc_int_bits_to_float(int32_t bits);
float sc_uint_bits_to_float(uint32_t bits);

uint32_t sc_pack_snorm2x16(sc_vec2 v);
sc_vec2 sc_unpack_snorm2x16(uint32_t p);
uint32_t sc_pack_unorm2x16(sc_vec2 v);
sc_vec2 sc_unpack_unorm2x16(uint32_t p);
uint32_t sc_pack_half2x16(sc_vec2 v);
sc_vec2 sc_unpack_half2x16(uint32_t p);

int32_t sc_mini(int32_t x, int32_t y);
int32_t sc_maxi(int32_t x, int32_t y);
int32_t sc_clampi(int32_t x, int32_t lo, int32_t hi);
int32_t sc_absi(int32_t x);
int32_t sc_signi(int32_t x);
uint32_t sc_minu(uint32_t x, uint32_t y);
uint32_t sc_maxu(uint32_t x, uint32_t y);
uint32_t sc_clampu(uint32_t x, uint32_t lo, uint32_t hi);

/* clang-format off */
typedef struct { int32_t x, y; } sc_ivec2;
typedef struct { int32_t x, y, z; } sc_ivec3;
typedef struct { int32_t x, y, z, w; } sc_ivec4;
typedef struct { uint32_t x, y; } sc_uvec2;
typedef struct { uint32_t x, y, z; } sc_uvec3;
typedef struct { uint32_t x, y, z, w; } sc_uvec4;
typedef struct { bool x, y; } sc_bvec2;
typedef struct { bool x, y, z; } sc_bvec3;
typedef struct { bool x, y, z, w; } sc_bvec4;

/* Per-component expressions (arguments a, b, x, lo, hi as in the definitions below). */
#define SC_GI_LT_(c, k) a.c < b.c
#define SC_GI_LE_(c, k) a.c <= b.c
#define SC_GI_GT_(c, k) a.c > b.c
#define SC_GI_GE_(c, k) a.c >= b.c
#define SC_GI_EQ_(c, k) a.c == b.c
#define SC_GI_NE_(c, k) a.c != b.c
#define SC_GI_NOT_(c, k) !a.c
#define SC_GI_AND_(c, k) a.c &&
#define SC_GI_OR_(c, k) a.c ||
#define SC_GI_ISNAN_(c, k) sc_isnanf(a.c)
#define SC_GI_ISINF_(c, k) sc_isinff(a.c)
#define SC_GI_F2I_(c, k) sc_float_bits_to_int(a.c)
#define SC_GI_F2U_(c, k) sc_float_bits_to_uint(a.c)
#define SC_GI_I2F_(c, k) sc_int_bits_to_float(a.c)
#define SC_GI_U2F_(c, k) sc_uint_bits_to_float(a.c)
#define SC_GI_MINI_(c, k) sc_mini(a.c, b.c)
#define SC_GI_MAXI_(c, k) sc_maxi(a.c, b.c)
#define SC_GI_CLAMPI_(c, k) sc_clampi(x.c, lo.c, hi.c)
#define SC_GI_ABSI_(c, k) sc_absi(a.c)
#define SC_GI_SIGNI_(c, k) sc_signi(a.c)
#define SC_GI_MINU_(c, k) sc_minu(a.c, b.c)
#define SC_GI_MAXU_(c, k) sc_maxu(a.c, b.c)
#define SC_GI_CLAMPU_(c, k) sc_clampu(x.c, lo.c, hi.c)
/* F(component) for each component, with no separator (for && and || chains). */
#define SC_GI_CHAIN2_(F) F(x, 0) F(y, 1)
#define SC_GI_CHAIN3_(F) F(x, 0) F(y, 1) F(z, 2)
#define SC_GI_CHAIN4_(F) F(x, 0) F(y, 1) F(z, 2) F(w, 3)
/* clang-format on */

/* equal and notEqual of vectors T into B. */
#define SC_GI_DEFINE_EQUAL(T, B, EACH)                                                             \
    static inline B T##_equal(T a, T b) { return SC_LITERAL_(B){EACH(SC_GI_EQ_)}; }                \
    static inline B T##_not_equal(T a, T b) { return SC_LITERAL_(B){EACH(SC_GI_NE_)}; }

/* The four orderings and the two equalities of vectors T into B. */
#define SC_GI_DEFINE_COMPARE(T, B, EACH)                                                           \
    SC_GI_DEFINE_EQUAL(T, B, EACH)                                                                 \
    static inline B T##_less_than(T a, T b) { return SC_LITERAL_(B){EACH(SC_GI_LT_)}; }            \
    static inline B T##_less_than_equal(T a, T b) { return SC_LITERAL_(B){EACH(SC_GI_LE_)}; }      \
    static inline B T##_greater_than(T a, T b) { return SC_LITERAL_(B){EACH(SC_GI_GT_)}; }         \
    static inline B T##_greater_than_equal(T a, T b) { return SC_LITERAL_(B){EACH(SC_GI_GE_)}; }

/* any, all, not of bvecN. */
#define SC_GI_DEFINE_BOOL(B, EACH, CHAIN)                                                          \
    SC_GI_DEFINE_EQUAL(B, B, EACH)                                                                 \
    static inline bool B##_any(B a) { return CHAIN(SC_GI_OR_) false; }                             \
    static inline bool B##_all(B a) { return CHAIN(SC_GI_AND_) true; }                             \
    static inline B B##_not(B a) { return SC_LITERAL_(B){EACH(SC_GI_NOT_)}; }

/* The float vector V with its int vector I, uint vector U and bool vector B of one size. */
#define SC_GI_DEFINE_SIZE(V, I, U, B, EACH, CHAIN)                                                 \
    SC_GI_DEFINE_COMPARE(V, B, EACH)                                                               \
    SC_GI_DEFINE_COMPARE(I, B, EACH)                                                               \
    SC_GI_DEFINE_COMPARE(U, B, EACH)                                                               \
    SC_GI_DEFINE_BOOL(B, EACH, CHAIN)                                                              \
    static inline B V##_isnan(V a) { return SC_LITERAL_(B){EACH(SC_GI_ISNAN_)}; }                  \
    static inline B V##_isinf(V a) { return SC_LITERAL_(B){EACH(SC_GI_ISINF_)}; }                  \
    static inline I V##_float_bits_to_int(V a) { return SC_LITERAL_(I){EACH(SC_GI_F2I_)}; }        \
    static inline U V##_float_bits_to_uint(V a) { return SC_LITERAL_(U){EACH(SC_GI_F2U_)}; }       \
    static inline V I##_int_bits_to_float(I a) { return SC_LITERAL_(V){EACH(SC_GI_I2F_)}; }        \
    static inline V U##_uint_bits_to_float(U a) { return SC_LITERAL_(V){EACH(SC_GI_U2F_)}; }       \
    static inline I I##_min(I a, I b) { return SC_LITERAL_(I){EACH(SC_GI_MINI_)}; }                \
    static inline I I##_max(I a, I b) { return SC_LITERAL_(I){EACH(SC_GI_MAXI_)}; }                \
    static inline I I##_clamp(I x, I lo, I hi) { return SC_LITERAL_(I){EACH(SC_GI_CLAMPI_)}; }     \
    static inline I I##_abs(I a) { return SC_LITERAL_(I){EACH(SC_GI_ABSI_)}; }                     \
    static inline I I##_sign(I a) { return SC_LITERAL_(I){EACH(SC_GI_SIGNI_)}; }                   \
    static inline U U##_min(U a, U b) { return SC_LITERAL_(U){EACH(SC_GI_MINU_)}; }                \
    static inline U U##_max(U a, U b) { return SC_LITERAL_(U){EACH(SC_GI_MAXU_)}; }                \
    static inline U U##_clamp(U x, U lo, U hi) { return SC_LITERAL_(U){EACH(SC_GI_CLAMPU_)}; }

SC_GI_DEFINE_SIZE(sc_vec2, sc_ivec2, sc_uvec2, sc_bvec2, SC_EACH2, SC_GI_CHAIN2_)
SC_GI_DEFINE_SIZE(sc_vec3, sc_ivec3, sc_uvec3, sc_bvec3, SC_EACH3, SC_GI_CHAIN3_)
SC_GI_DEFINE_SIZE(sc_vec4, sc_ivec4, sc_uvec4, sc_bvec4, SC_EACH4, SC_GI_CHAIN4_)

SC_END_DECLS

#endif
