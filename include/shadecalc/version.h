/*
 * shadecalc/version.h — the version of the headers and of the library.
 *
 *   SC_VERSION_MAJOR, SC_VERSION_MINOR, SC_VERSION_PATCH   the headers' version, as integers
 *   SC_VERSION_STRING                                      the same as "MAJOR.MINOR.PATCH"
 *   sc_version                                             the library's version, at run time
 *
 * These three numbers are the only place the version is written: the Makefile reads them (the
 * shared library's file name, shadecalc.pc, `shadecalc --version`). A program built against
 * one version and run with another shared library can compare SC_VERSION_STRING with
 * sc_version(); the soname (libshadecalc.so.MAJOR) changes with SC_VERSION_MAJOR.
 */
#ifndef SHADECALC_VERSION_H
#define SHADECALC_VERSION_H

#include "shadecalc/api.h"

#define SC_VERSION_MAJOR 0
#define SC_VERSION_MINOR 1
#define SC_VERSION_PATCH 0

#define SC_VERSION_STR_(x) #x
#define SC_VERSION_XSTR_(x) SC_VERSION_STR_(x)
#define SC_VERSION_STRING                                                                          \
    SC_VERSION_XSTR_(SC_VERSION_MAJOR)                                                             \
    "." SC_VERSION_XSTR_(SC_VERSION_MINOR) "." SC_VERSION_XSTR_(SC_VERSION_PATCH)

SC_BEGIN_DECLS

/* The version of the library linked at run time, "MAJOR.MINOR.PATCH" (static storage). */
const char *sc_version(void);

SC_END_DECLS

#endif
