/* Instruction-set dispatch (batch.h) from many threads at once, and the alignment the kernels
 * need (float alignment, nothing stricter). The race on the first choice is what
 * `make SAN=thread` reports (ThreadSanitizer); without it the test checks that every thread
 * sees the one choice. */
#include <pthread.h>
#include <setjmp.h>
#include <stdarg.h>
#include <stddef.h>
#include <stdint.h>
#include <stdlib.h>
#include <string.h>

#include <cmocka.h>

#include "shadecalc/batch.h"

#include "batch/reference.h"

enum { THREADS = 8, N = 37, MAX_SHIFT = 8 };

static pthread_barrier_t start;

static void *ask_active(void *out)
{
    pthread_barrier_wait(&start);
    *(sc_isa *)out = sc_isa_active();
    return NULL;
}

/* Starts thread 0 on `first` and the others on ask_active (seen[i]), all released at once. */
static void race(void *(*first)(void *), sc_isa seen[THREADS])
{
    pthread_t threads[THREADS];
    assert_int_equal(pthread_barrier_init(&start, NULL, THREADS), 0);
    for (int i = 0; i < THREADS; i++)
        assert_int_equal(pthread_create(&threads[i], NULL, i ? ask_active : first, &seen[i]), 0);
    for (int i = 0; i < THREADS; i++)
        assert_int_equal(pthread_join(threads[i], NULL), 0);
    pthread_barrier_destroy(&start);
}

/* Runs first in this binary: the threads race to make the first choice. */
static void every_thread_sees_one_choice(void **state)
{
    (void)state;
    sc_isa seen[THREADS];
    race(ask_active, seen);
    for (int i = 0; i < THREADS; i++)
        assert_int_equal(seen[i], sc_isa_active());
    assert_true(sc_isa_supported(sc_isa_active()));
}

static void *set_scalar(void *arg)
{
    (void)arg;
    pthread_barrier_wait(&start);
    sc_isa_set(SC_ISA_SCALAR);
    return NULL;
}

/* A set racing with readers: every reader gets a supported set, and afterwards the set given. */
static void set_while_others_read(void **state)
{
    (void)state;
    sc_isa seen[THREADS];
    sc_isa before = sc_isa_active();
    race(set_scalar, seen);
    for (int i = 1; i < THREADS; i++)
        assert_true(seen[i] == before || seen[i] == SC_ISA_SCALAR);
    assert_int_equal(sc_isa_active(), SC_ISA_SCALAR);
    assert_int_equal(sc_isa_set(before), 0);
}

/* Every kernel on every instruction set, its arrays shifted by 0..7 floats from a 32-byte
 * boundary: the same bits as unshifted (batch.h: float alignment is enough). */
static void any_float_alignment_gives_the_same_bits(void **state)
{
    (void)state;
    enum { SPAN = 48 }; /* >= N + MAX_SHIFT, and arrays of whole 32-byte blocks */
    float *in = aligned_alloc(32, 9 * SPAN * sizeof(float));
    float *out = aligned_alloc(32, 3 * SPAN * sizeof(float)), first[3][N];
    assert_non_null(in);
    assert_non_null(out);
    uint64_t rng = 42;
    for (int k = 0; k < sc_batch_count; k++) {
        const sc_batch_entry *e = &sc_batch_table[k];
        if (!sc_isa_supported(e->isa))
            continue;
        float sample[9][N];
        for (int i = 0; i < N; i++) {
            float one[9];
            sc_batch_sample(e, &rng, one);
            for (int j = 0; j < e->n_in; j++)
                sample[j][i] = one[j];
        }
        sc_light lights[SC_BATCH_MAX_LIGHTS];
        sc_scene scene;
        char why[256];
        sc_batch_example_scene(SC_BRDF_COOK_TORRANCE, 1, 1, 1, lights, &scene);
        sc_batch_plan *plan = sc_batch_plan_compile(&scene, "accurate", SC_ISA_SCALAR, why,
                                                    sizeof why);
        assert_non_null(plan);
        for (int shift = 0; shift < MAX_SHIFT; shift++) {
            sc_batch_args a = {
                .n = N, .params = strcmp(e->kernel, "shade") == 0 ? (const void *)plan : e->params};
            for (int j = 0; j < e->n_in; j++) {
                a.in[j] = in + j * SPAN + shift;
                memcpy((float *)a.in[j], sample[j], sizeof sample[j]);
            }
            for (int j = 0; j < e->n_out; j++)
                a.out[j] = out + j * SPAN + (MAX_SHIFT - 1 - shift);
            e->fn(&a);
            for (int j = 0; j < e->n_out; j++) {
                if (shift == 0)
                    memcpy(first[j], a.out[j], sizeof first[j]);
                else
                    assert_memory_equal(first[j], a.out[j], sizeof first[j]);
            }
        }
        sc_batch_plan_free(plan);
    }
    free(in);
    free(out);
}

int main(void)
{
    const struct CMUnitTest tests[] = {
        cmocka_unit_test(every_thread_sees_one_choice),
        cmocka_unit_test(set_while_others_read),
        cmocka_unit_test(any_float_alignment_gives_the_same_bits),
    };
    return cmocka_run_group_tests(tests, NULL, NULL);
}
