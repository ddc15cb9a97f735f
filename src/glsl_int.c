/* The GLSL ES built-ins on bool, int and uint, the bit casts and the packing functions
 * (shadecalc/glsl_int.h, where their semantics are stated). */
#include "shadecalc/glsl_int.h"

#include <string.h>

#include "shadecalc/glsl.h"
#include "shadecalc/precision.h"

static const uint32_t exponent_mask = 0x7f800000u, magnitude_mask = 0x7fffffffu;

bool sc_isnanf(float x) { return (sc_float_bits_to_uint(x) & magnitude_mask) > exponent_mask; }
bool sc_isinff(float x) { return (sc_float_bits_to_uint(x) & magnitude_mask) == exponent_mask; }

/* The bit casts: every bit kept (float, int32_t and uint32_t have 4 bytes). */
#define BIT_CAST(name, From, To)                                                                   \
    To name(From from)                                                                             \
    {                                                                                              \
        To to;                                                                                     \
        memcpy(&to, &from, sizeof to);                                                             \
        return to;                                                                                 \
    }
BIT_CAST(sc_float_bits_to_uint, float, uint32_t)
BIT_CAST(sc_float_bits_to_int, float, int32_t)
BIT_CAST(sc_uint_bits_to_float, uint32_t, float)
BIT_CAST(sc_int_bits_to_float, int32_t, float)

/* ---- packing (§8.4) ---- */

/* round(clamp(c, lo, 1)·scale) as an integer, NaN as 0; the result fits 16 bits. */
static int32_t fixed16(float c, float lo, float scale)
{
    float r = sc_roundf(sc_clampf(c, lo, 1.0f) * scale);
    return sc_isnanf(r) ? 0 : (int32_t)r;
}

/* Two 16-bit fields, the first in the low half. */
static uint32_t pack16(uint32_t first, uint32_t second)
{
    return (first & 0xffffu) | (second & 0xffffu) << 16;
}

/* The low (k = 0) or high (k = 1) 16-bit field, as signed. */
static int32_t field_signed(uint32_t p, int k)
{
    int32_t f = (int32_t)(p >> (16 * k) & 0xffffu);
    return f >= 0x8000 ? f - 0x10000 : f;
}

uint32_t sc_pack_snorm2x16(sc_vec2 v)
{
    return pack16((uint32_t)fixed16(v.x, -1.0f, 32767.0f), (uint32_t)fixed16(v.y, -1.0f, 32767.0f));
}

sc_vec2 sc_unpack_snorm2x16(uint32_t p)
{
    return (sc_vec2){sc_clampf((float)field_signed(p, 0) / 32767.0f, -1.0f, 1.0f),
                     sc_clampf((float)field_signed(p, 1) / 32767.0f, -1.0f, 1.0f)};
}

uint32_t sc_pack_unorm2x16(sc_vec2 v)
{
    return pack16((uint32_t)fixed16(v.x, 0.0f, 65535.0f), (uint32_t)fixed16(v.y, 0.0f, 65535.0f));
}

sc_vec2 sc_unpack_unorm2x16(uint32_t p)
{
    return (sc_vec2){(float)(p & 0xffffu) / 65535.0f, (float)(p >> 16) / 65535.0f};
}

/* binary16 of x: the mediump rounding, and for NaN what F16C gives (quiet, payload's top 10
 * bits). */
static uint32_t half_bits(float x)
{
    uint32_t bits = sc_float_bits_to_uint(x);
    if (!sc_isnanf(x))
        return sc_half_from_double((double)x);
    return (bits >> 16 & 0x8000u) | 0x7e00u | (bits >> 13 & 0x3ffu);
}

/* The float of binary16 bits h: exact; NaN quiet with its payload, as F16C. */
static float half_value(uint32_t h)
{
    if ((h & 0x7c00u) == 0x7c00u && (h & 0x3ffu))
        return sc_uint_bits_to_float((h & 0x8000u) << 16 | 0x7fc00000u | (h & 0x3ffu) << 13);
    return (float)sc_half_to_double((uint16_t)h);
}

uint32_t sc_pack_half2x16(sc_vec2 v) { return pack16(half_bits(v.x), half_bits(v.y)); }

sc_vec2 sc_unpack_half2x16(uint32_t p)
{
    return (sc_vec2){half_value(p & 0xffffu), half_value(p >> 16)};
}

/* ---- integers (§8.3), wrapping modulo 2^32 ---- */

int32_t sc_mini(int32_t x, int32_t y) { return y < x ? y : x; }
int32_t sc_maxi(int32_t x, int32_t y) { return x < y ? y : x; }
int32_t sc_clampi(int32_t x, int32_t lo, int32_t hi) { return sc_mini(sc_maxi(x, lo), hi); }
int32_t sc_signi(int32_t x) { return (x > 0) - (x < 0); }
uint32_t sc_minu(uint32_t x, uint32_t y) { return y < x ? y : x; }
uint32_t sc_maxu(uint32_t x, uint32_t y) { return x < y ? y : x; }
uint32_t sc_clampu(uint32_t x, uint32_t lo, uint32_t hi) { return sc_minu(sc_maxu(x, lo), hi); }

/* −x modulo 2^32 without signed overflow: INT32_MIN stays INT32_MIN. */
int32_t sc_absi(int32_t x)
{
    uint32_t magnitude = x < 0 ? 0u - (uint32_t)x : (uint32_t)x;
    return magnitude > INT32_MAX ? INT32_MIN : (int32_t)magnitude;
}
