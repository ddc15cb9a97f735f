/* The input counts of the unit tests' large numeric sweeps (10^6 inputs per kernel, tier and
 * instruction set, and the like).
 *
 * The plain build checks every stated bound on the full count. Under AddressSanitizer and
 * UndefinedBehaviorSanitizer (make SAN=1, the second stage of make check), where each input
 * costs many times more, the same sweeps run through the same code paths on a deterministic
 * prefix of the same inputs, 1/SC_SAN_SAMPLE of them: the sanitized run checks memory and
 * undefined behaviour, the plain run the bounds on every input. */
#ifndef SC_TEST_SCALE_H
#define SC_TEST_SCALE_H

#include <stddef.h>
#include <stdint.h>
#include <stdio.h>
#include <stdlib.h>

#if defined(__SANITIZE_ADDRESS__)
#define SC_TEST_SANITIZED 1
#elif defined(__has_feature)
#if __has_feature(address_sanitizer)
#define SC_TEST_SANITIZED 1
#endif
#endif

enum { SC_SAN_SAMPLE = 50 };

/* full in the plain build; under the sanitizers full / SC_SAN_SAMPLE, plus 7 so that a count of
 * whole vectors still runs the tails of the 4-, 8- and 16-lane loops. */
static inline size_t sc_test_inputs(size_t full)
{
#ifdef SC_TEST_SANITIZED
    return full / SC_SAN_SAMPLE + 7;
#else
    return full;
#endif
}

/* A test's random state mixed with SHADECALC_BATCH_SEED when it is set (another set of random
 * inputs; printed, so that a failure names its seed): the golden-ratio multiple keeps seeds
 * 1, 2, … far apart, and the state stays nonzero for xorshift. */
static inline uint64_t sc_test_seeded(uint64_t state)
{
    const char *env = getenv("SHADECALC_BATCH_SEED");
    if (!env)
        return state;
    printf("SHADECALC_BATCH_SEED=%s\n", env);
    state ^= strtoull(env, NULL, 0) * 0x9E3779B97F4A7C15ULL;
    return state ? state : 0x2545F4914F6CDD1DULL;
}

#endif
