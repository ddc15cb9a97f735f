/* Instruction-set selection (shadecalc/batch.h): chosen once from what the CPU supports, or
 * from SHADECALC_ISA; the scalar kernels always work. Safe to call from any thread. */
#include <pthread.h>
#include <stdatomic.h>
#include <stdlib.h>
#include <string.h>

#include "shadecalc/batch.h"
#include "simd/kernels.h"

static const char *const isa_names[SC_ISA_COUNT] = {"scalar", "sse4.1", "avx2", "avx512"};

const char *sc_isa_name(sc_isa isa) { return isa_names[isa]; }

int sc_isa_parse(const char *name, sc_isa *out)
{
    for (int i = 0; i < SC_ISA_COUNT; i++)
        if (strcmp(name, isa_names[i]) == 0) {
            *out = (sc_isa)i;
            return 0;
        }
    return -1;
}

int sc_isa_supported(sc_isa isa)
{
    switch (isa) {
    case SC_ISA_SCALAR: return 1;
#ifdef SC_HAVE_X86
    case SC_ISA_SSE41: return __builtin_cpu_supports("sse4.1");
    case SC_ISA_AVX2: return __builtin_cpu_supports("avx2") && __builtin_cpu_supports("fma");
    case SC_ISA_AVX512:
        return __builtin_cpu_supports("avx512f") && __builtin_cpu_supports("avx512dq");
#endif
    default: return 0;
    }
}

/* The instruction set in use: -1 until chosen. Render's worker threads ask for it while the
 * main thread may set it, so it is atomic, and the default is chosen once (pthread_once). */
static atomic_int active = -1;
static pthread_once_t default_once = PTHREAD_ONCE_INIT;

static sc_isa best_supported(void)
{
    for (int i = SC_ISA_COUNT - 1; i > 0; i--)
        if (sc_isa_supported((sc_isa)i))
            return (sc_isa)i;
    return SC_ISA_SCALAR;
}

/* SHADECALC_ISA when it names a supported set, else the best; an earlier sc_isa_set stands. */
static void choose_default(void)
{
    const char *env = getenv("SHADECALC_ISA");
    sc_isa chosen;
    if (!(env && sc_isa_parse(env, &chosen) == 0 && sc_isa_supported(chosen)))
        chosen = best_supported();
    int unset = -1;
    atomic_compare_exchange_strong(&active, &unset, (int)chosen);
}

sc_isa sc_isa_active(void)
{
    pthread_once(&default_once, choose_default);
    return (sc_isa)atomic_load(&active);
}

int sc_isa_set(sc_isa isa)
{
    if (!sc_isa_supported(isa))
        return -1;
    atomic_store(&active, (int)isa);
    return 0;
}

const sc_batch_entry *sc_batch_find(const char *kernel, const char *tier, sc_isa isa)
{
    for (int i = 0; i < sc_batch_count; i++) {
        const sc_batch_entry *e = &sc_batch_table[i];
        if (e->isa == isa && strcmp(e->kernel, kernel) == 0 && strcmp(e->tier, tier) == 0)
            return e;
    }
    return NULL;
}

int sc_batch_run(const char *kernel, const char *tier, const sc_batch_args *a)
{
    for (int isa = (int)sc_isa_active(); isa >= 0; isa--) {
        const sc_batch_entry *e = sc_batch_find(kernel, tier, (sc_isa)isa);
        if (e && sc_isa_supported((sc_isa)isa)) {
            e->fn(a);
            return 0;
        }
    }
    return -1;
}
