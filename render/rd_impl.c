/* rd_impl.c - the one translation unit of shlrender that holds shlight.h's implementation. */
#define SHLIGHT_IMPLEMENTATION
#include "../shlight.h"
