/* impl_c.c - the implementation compiled as C, for the C++ test that includes shlight.h
   without SHLIGHT_IMPLEMENTATION (tests/test_glm.cpp): the two link through extern "C". */
#define SHLIGHT_IMPLEMENTATION
#include "../shlight.h"
