/*
 * shadecalc/api.h — what every public header wraps its declarations in.
 *
 *   SC_BEGIN_DECLS, SC_END_DECLS   C linkage in C++ (extern "C"), and default visibility for
 *                                  gcc and clang
 *   SC_LITERAL_(T){...}            a value of struct type T from braces, in the inline functions
 *                                  of the headers: a compound literal in C, a temporary in C++
 *                                  (where compound literals are only an extension)
 *
 * The library is compiled with -fvisibility=hidden, so libshadecalc.so exports exactly what the
 * public headers declare between these two: its internal functions stay internal (the shadecalc
 * binary and the tests link the static library, where they remain visible).
 */
#ifndef SHADECALC_API_H
#define SHADECALC_API_H

#if defined(__GNUC__)
#define SC_VISIBILITY_PUSH_ _Pragma("GCC visibility push(default)")
#define SC_VISIBILITY_POP_ _Pragma("GCC visibility pop")
#else
#define SC_VISIBILITY_PUSH_
#define SC_VISIBILITY_POP_
#endif

// clang-format off
#ifdef __cplusplus
#define SC_BEGIN_DECLS SC_VISIBILITY_PUSH_ extern "C" {
#define SC_END_DECLS } SC_VISIBILITY_POP_
#else
#define SC_BEGIN_DECLS SC_VISIBILITY_PUSH_
#define SC_END_DECLS SC_VISIBILITY_POP_
#endif
// clang-format on

#ifdef __cplusplus
#define SC_LITERAL_(T) T
#else
#define SC_LITERAL_(T) (T)
#endif

#endif
