/*
 * A program that uses libshadecalc as an installed library: built by tests/install/run.sh as C
 * and as C++ (the same file: it is written in their common subset) with the flags of
 * `pkg-config --cflags --libs shadecalc`. It calls one function of each kind (a built-in, the
 * inline vector functions, the expression language, a BRDF), compares each result with an
 * independent reference computed here in double, prints one line per check, and exits 0 only
 * if every check passed and the header's version is the library's.
 */
#include <math.h>
#include <stdio.h>
#include <string.h>

#include <shadecalc/shadecalc.h>

static int failures = 0;

static void report(const char *name, double got, double want, double tolerance)
{
    int ok = fabs(got - want) <= tolerance;
    printf("%s %s %.9g (want %.9g)\n", ok ? "ok" : "FAIL", name, got, want);
    failures += !ok;
}

/* One ULP of binary32 at x (x a normal number): the bound of the accurate tier. */
static double ulp_binary32(double x)
{
    int exponent;
    frexp(x, &exponent);
    return ldexp(1.0, exponent - 24);
}

static void check_builtins(void)
{
    double want = pow(2.0, 0.5);
    report("sc_powf(2,0.5)", sc_powf(2.0f, 0.5f), want, ulp_binary32(want));
    want = sin(1.0);
    report("sc_sinf(1)", sc_sinf(1.0f), want, ulp_binary32(want));
}

static void check_vectors(void)
{
    sc_vec3 a = sc_vec3_make(1.0f, 2.0f, 3.0f);
    sc_vec3 b = sc_vec3_make(4.0f, 5.0f, 6.0f);
    sc_vec3 z = sc_vec3_cross(sc_vec3_make(1.0f, 0.0f, 0.0f), sc_vec3_make(0.0f, 1.0f, 0.0f));
    report("sc_vec3_dot", sc_vec3_dot(a, b), 1.0 * 4.0 + 2.0 * 5.0 + 3.0 * 6.0, 0.0);
    report("sc_vec3_cross.z", z.z, 1.0, 0.0);
}

static void check_expression(void)
{
    sc_expr_error err;
    sc_expr *e = sc_expr_compile("length(vec2(3.0, 4.0)) / 2.0", NULL, 0, &err);
    if (e == NULL) {
        printf("FAIL sc_expr_compile: column %d: %s\n", err.column, err.message);
        failures++;
        return;
    }
    sc_value v = sc_expr_eval(e, SC_DOUBLE, NULL, NULL, NULL);
    report("sc_expr_eval", v.v[0], sqrt(3.0 * 3.0 + 4.0 * 4.0) / 2.0, 0.0);
    sc_expr_free(e);
}

/* Lambert: f = c_diff/π for every pair of directions above the horizon. */
static void check_brdf(void)
{
    static const double pi = 3.14159265358979323846;
    const double n[3] = {0.0, 0.0, 1.0};
    const double l[3] = {0.6, 0.0, 0.8};
    const double v[3] = {0.0, 0.0, 1.0};
    sc_brdf b;
    sc_frame frame;
    sc_brdf_terms terms;
    sc_brdf_init(&b, SC_BRDF_LAMBERT);
    b.diff[0] = b.diff[1] = b.diff[2] = 0.5;
    if (sc_frame_make(n, NULL, &frame) != 0) {
        printf("FAIL sc_frame_make\n");
        failures++;
        return;
    }
    sc_brdf_eval(SC_DOUBLE, &b, &frame, l, v, &terms);
    report("sc_brdf_eval(lambert)", terms.f[0], 0.5 / pi, 1e-15);
}

int main(void)
{
    int same_version = strcmp(sc_version(), SC_VERSION_STRING) == 0;
    printf("version %s (header %s, %d.%d.%d)\n", sc_version(), SC_VERSION_STRING, SC_VERSION_MAJOR,
           SC_VERSION_MINOR, SC_VERSION_PATCH);
    if (!same_version) {
        printf("FAIL the library is not the version of the header\n");
        failures++;
    }
    check_builtins();
    check_vectors();
    check_expression();
    check_brdf();
    return failures == 0 ? 0 : 1;
}
