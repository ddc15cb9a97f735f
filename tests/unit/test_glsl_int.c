/* The bool, int and uint built-ins, bit casts and packing functions (shadecalc/glsl_int.h):
 * against C99's classification, 64-bit integer arithmetic, the GLSL ES 3.00 §8.4 formulas
 * evaluated in double, and the F16C conversion instructions where the CPU has them. */
#include <float.h>
#include <math.h>
#include <setjmp.h>
#include <stdarg.h>
#include <stddef.h>
#include <stdint.h>
#include <string.h>

#include <cmocka.h>

#if defined(__x86_64__) && (defined(__GNUC__) || defined(__clang__))
#include <cpuid.h>
#include <immintrin.h>
#endif

#include "shadecalc/glsl_int.h"

/* Bit patterns through a union (the library copies bytes) */
typedef union {
    uint32_t u;
    float f;
} pun;
static float float_of(uint32_t bits) { return (pun){.u = bits}.f; }
static uint32_t bits_of(float x) { return (pun){.f = x}.u; }

/* ---- isnan, isinf, bit casts ---- */

static void classification_and_bit_casts_on_every_257th_pattern(void **state)
{
    (void)state;
    for (uint64_t u = 0; u < (1ULL << 32); u += 257) {
        uint32_t bits = (uint32_t)u;
        float x = float_of(bits);
        assert_true(sc_isnanf(x) == (isnan(x) != 0));
        assert_true(sc_isinff(x) == (isinf(x) != 0));
        assert_true(sc_float_bits_to_uint(x) == bits);
        assert_true((uint32_t)sc_float_bits_to_int(x) == bits);
        assert_true(bits_of(sc_uint_bits_to_float(bits)) == bits);
        int32_t as_int;
        memcpy(&as_int, &bits, sizeof as_int);
        assert_true(bits_of(sc_int_bits_to_float(as_int)) == bits);
    }
    assert_true(sc_float_bits_to_int(-1.0f) == -1082130432); /* 0xbf800000 */
    assert_true(sc_float_bits_to_uint(1.0f) == 0x3f800000u);
    assert_true(sc_isinff(-INFINITY) && !sc_isinff(FLT_MAX) && sc_isnanf(-NAN));
}

/* ---- snorm and unorm packing: the §8.4 formulas in double ---- */

/* round(clamp(c, lo, 1)·scale) with the product rounded to binary32, halves to even; NaN 0 */
static uint32_t fixed_reference(float c, double lo, double scale)
{
    double clamped = fmin(fmax((double)c, lo), 1.0);
    if (isnan(c))
        return 0;
    double r = nearbyint((double)(float)(clamped * scale));
    return (uint32_t)(int32_t)r & 0xffffu;
}

/* xorshift64: a deterministic sample */
static float sample(uint64_t *s)
{
    *s ^= *s << 13;
    *s ^= *s >> 7;
    *s ^= *s << 17;
    return (float)((double)(*s >> 11) * 0x1p-53 * 3 - 1.5); /* uniform in [−1.5, 1.5) */
}

static void snorm_and_unorm_packing_follow_the_formulas(void **state)
{
    (void)state;
    uint64_t s = 42;
    for (int i = 0; i < 200000; i++) {
        sc_vec2 v = {sample(&s), sample(&s)};
        assert_true(sc_pack_snorm2x16(v) ==
                    (fixed_reference(v.x, -1, 32767) | fixed_reference(v.y, -1, 32767) << 16));
        assert_true(sc_pack_unorm2x16(v) ==
                    (fixed_reference(v.x, 0, 65535) | fixed_reference(v.y, 0, 65535) << 16));
    }
    /* clamping, halves to even (0.5/65535·65535 = 0.5 -> 0; 1.5/65535 -> 2), NaN */
    assert_true(sc_pack_unorm2x16((sc_vec2){-3.0f, 7.0f}) == 0xffff0000u);
    assert_true(sc_pack_snorm2x16((sc_vec2){-3.0f, 7.0f}) == 0x7fff8001u);
    assert_true(sc_pack_unorm2x16((sc_vec2){(float)(0.5 / 65535), (float)(1.5 / 65535)}) ==
                0x00020000u);
    assert_true(sc_pack_snorm2x16((sc_vec2){NAN, -0.0f}) == 0);
}

static void snorm_and_unorm_unpack_every_field(void **state)
{
    (void)state;
    for (uint32_t k = 0; k < 0x10000; k++) {
        int32_t sk = k >= 0x8000 ? (int32_t)k - 0x10000 : (int32_t)k;
        float want_s = (float)fmax((double)sk / 32767.0, -1.0), want_u = (float)(k / 65535.0);
        sc_vec2 s = sc_unpack_snorm2x16(k | (k << 16)), u = sc_unpack_unorm2x16(k << 16 | k);
        assert_true(s.x == want_s && s.y == want_s && u.x == want_u && u.y == want_u);
        /* every value but −32768 comes back */
        if (k != 0x8000)
            assert_true(sc_pack_snorm2x16(s) == (k | (k << 16)));
        assert_true(sc_pack_unorm2x16(u) == (k << 16 | k));
    }
}

/* ---- half packing against F16C ---- */

#if defined(__x86_64__) && (defined(__GNUC__) || defined(__clang__))
#define HAVE_F16C_TEST 1
/* F16C from CPUID leaf 1 (clang's __builtin_cpu_supports does not know "f16c"), AVX on. */
static int have_f16c(void)
{
    unsigned a, b, c, d;
    return __builtin_cpu_supports("avx") && __get_cpuid(1, &a, &b, &c, &d) && (c & bit_F16C);
}
__attribute__((target("avx,f16c"))) static uint32_t f16c_from_float(float x)
{
    return (uint32_t)_cvtss_sh(x, _MM_FROUND_TO_NEAREST_INT | _MM_FROUND_NO_EXC);
}
__attribute__((target("avx,f16c"))) static float f16c_to_float(uint32_t h)
{
    return _cvtsh_ss((unsigned short)h);
}
#endif

static void half_packing_agrees_with_f16c(void **state)
{
    (void)state;
#ifdef HAVE_F16C_TEST
    if (!have_f16c())
        skip();
    for (uint32_t h = 0; h < 0x10000; h++) {
        sc_vec2 v = sc_unpack_half2x16(h << 16 | h);
        assert_true(bits_of(v.x) == bits_of(f16c_to_float(h)) && bits_of(v.y) == bits_of(v.x));
    }
    for (uint64_t u = 0; u < (1ULL << 32); u += 127) {
        float x = float_of((uint32_t)u);
        uint32_t want = f16c_from_float(x);
        if (sc_pack_half2x16((sc_vec2){x, -x}) != (want | f16c_from_float(-x) << 16))
            fail_msg("packHalf2x16(%a) = %08x, F16C %04x", (double)x,
                     sc_pack_half2x16((sc_vec2){x, -x}), want);
    }
#else
    skip();
#endif
}

/* Without F16C to compare with: the rounding rules by hand (ties to even, overflow, subnormal). */
static void half_packing_rounds_to_nearest_even(void **state)
{
    (void)state;
    assert_true(sc_pack_half2x16((sc_vec2){1.0f, -2.0f}) == (0x3c00u | 0xc000u << 16));
    assert_true(sc_pack_half2x16((sc_vec2){65504.0f, 65520.0f}) == (0x7bffu | 0x7c00u << 16));
    assert_true(sc_pack_half2x16((sc_vec2){1.0f + 0x1p-11f, 1.0f + 3 * 0x1p-11f}) ==
                (0x3c00u | 0x3c02u << 16));
    assert_true(sc_pack_half2x16((sc_vec2){0x1p-24f, 0x1p-25f}) == 0x0001u);
    assert_true(sc_pack_half2x16((sc_vec2){NAN, -0.0f}) == (0x7e00u | 0x8000u << 16));
    sc_vec2 v = sc_unpack_half2x16(0x7c01u << 16 | 0x0001u);
    assert_true(v.x == 0x1p-24f && isnan(v.y));
}

/* ---- integers: against 64-bit arithmetic ---- */

static const int32_t ints[] = {INT32_MIN, INT32_MIN + 1, -65536,        -2,       -1, 0, 1, 2,
                               7,         65535,         INT32_MAX - 1, INT32_MAX};
enum { N_INTS = (int)(sizeof ints / sizeof ints[0]) };

static void int_functions_match_wide_arithmetic(void **state)
{
    (void)state;
    for (int i = 0; i < N_INTS; i++) {
        int64_t x = ints[i];
        int64_t mag = x < 0 ? -x : x;
        assert_true(sc_absi(ints[i]) == (int32_t)(uint32_t)(uint64_t)mag);
        assert_true(sc_signi(ints[i]) == (x > 0 ? 1 : x < 0 ? -1 : 0));
        for (int j = 0; j < N_INTS; j++) {
            int64_t y = ints[j];
            uint32_t ux = (uint32_t)ints[i], uy = (uint32_t)ints[j];
            assert_true(sc_mini(ints[i], ints[j]) == (x < y ? x : y));
            assert_true(sc_maxi(ints[i], ints[j]) == (x > y ? x : y));
            assert_true(sc_minu(ux, uy) == (ux < uy ? ux : uy));
            assert_true(sc_maxu(ux, uy) == (ux > uy ? ux : uy));
            for (int k = j; k < N_INTS; k++) { /* lo <= hi */
                int64_t hi = ints[k];
                assert_true(sc_clampi(ints[i], ints[j], ints[k]) == (x < y ? y : x > hi ? hi : x));
            }
        }
    }
    assert_true(sc_absi(INT32_MIN) == INT32_MIN);                          /* wraps, as GLSL ES */
    assert_true(sc_clampi(5, 10, 0) == 0 && sc_clampu(5u, 10u, 0u) == 0u); /* lo > hi: hi */
    assert_true(sc_clampu(0xffffffffu, 1u, 0x80000000u) == 0x80000000u);
}

/* ---- the vector forms ---- */

static void vector_forms_apply_per_component(void **state)
{
    (void)state;
    sc_vec4 a = {1.0f, NAN, -0.0f, INFINITY}, b = {2.0f, 1.0f, 0.0f, INFINITY};
    sc_bvec4 lt = sc_vec4_less_than(a, b), eq = sc_vec4_equal(a, b);
    assert_true(lt.x && !lt.y && !lt.z && !lt.w);
    assert_true(!eq.x && !eq.y && eq.z && eq.w);
    sc_bvec4 ne = sc_vec4_not_equal(a, b), ge = sc_vec4_greater_than_equal(a, b);
    assert_true(ne.x && ne.y && !ne.z && !ne.w && !ge.x && !ge.y && ge.z && ge.w);
    sc_bvec4 nan = sc_vec4_isnan(a), inf = sc_vec4_isinf(a);
    assert_true(!nan.x && nan.y && !nan.z && !nan.w && !inf.x && !inf.y && !inf.z && inf.w);
    assert_true(sc_bvec4_any(nan) && !sc_bvec4_all(nan) &&
                sc_bvec4_all(sc_bvec4_not((sc_bvec4){false, false, false, false})));
    assert_true(!sc_bvec2_any((sc_bvec2){false, false}) && sc_bvec3_all((sc_bvec3){1, 1, 1}));
    sc_bvec2 beq = sc_bvec2_equal((sc_bvec2){true, false}, (sc_bvec2){true, true});
    assert_true(beq.x && !beq.y);

    sc_ivec3 i = {-5, INT32_MIN, 7}, j = {3, 0, 7};
    sc_bvec3 ile = sc_ivec3_less_than_equal(i, j), igt = sc_ivec3_greater_than(i, j);
    assert_true(ile.x && ile.y && ile.z && !igt.x && !igt.y && !igt.z);
    sc_ivec3 c = sc_ivec3_clamp(i, (sc_ivec3){-1, -1, -1}, (sc_ivec3){1, 1, 1});
    assert_true(c.x == -1 && c.y == -1 && c.z == 1);
    sc_ivec3 ab = sc_ivec3_abs(i), sg = sc_ivec3_sign(i), mn = sc_ivec3_min(i, j),
             mx = sc_ivec3_max(i, j);
    assert_true(ab.x == 5 && ab.y == INT32_MIN && sg.x == -1 && sg.y == -1 && sg.z == 1);
    assert_true(mn.x == -5 && mx.x == 3 && mn.y == INT32_MIN && mx.z == 7);

    sc_uvec2 u = {0xffffffffu, 1u}, v = {1u, 2u};
    sc_bvec2 ult = sc_uvec2_less_than(u, v);
    assert_true(!ult.x && ult.y); /* unsigned order */
    sc_uvec2 um = sc_uvec2_min(u, v), uM = sc_uvec2_max(u, v),
             uc = sc_uvec2_clamp(u, (sc_uvec2){2u, 2u}, (sc_uvec2){3u, 3u});
    assert_true(um.x == 1u && uM.x == 0xffffffffu && uc.x == 3u && uc.y == 2u);

    sc_ivec2 bits = sc_vec2_float_bits_to_int((sc_vec2){1.0f, -2.0f});
    sc_uvec2 ubits = sc_vec2_float_bits_to_uint((sc_vec2){1.0f, -2.0f});
    assert_true(bits.x == 0x3f800000 && ubits.y == 0xc0000000u);
    sc_vec2 back = sc_ivec2_int_bits_to_float(bits), uback = sc_uvec2_uint_bits_to_float(ubits);
    assert_true(back.x == 1.0f && back.y == -2.0f && uback.x == 1.0f && uback.y == -2.0f);
}

int main(void)
{
    const struct CMUnitTest tests[] = {
        cmocka_unit_test(classification_and_bit_casts_on_every_257th_pattern),
        cmocka_unit_test(snorm_and_unorm_packing_follow_the_formulas),
        cmocka_unit_test(snorm_and_unorm_unpack_every_field),
        cmocka_unit_test(half_packing_agrees_with_f16c),
        cmocka_unit_test(half_packing_rounds_to_nearest_even),
        cmocka_unit_test(int_functions_match_wide_arithmetic),
        cmocka_unit_test(vector_forms_apply_per_component),
    };
    return cmocka_run_group_tests_name("glsl int, bool, packing", tests, NULL, NULL);
}
