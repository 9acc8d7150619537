/* tl.h - the tiny test library of shlight's tests.
 * Each test program counts named checks and ends with the line "N passed, N failed";
 * tests/run.sh adds those lines up into the project's closing line. */
#ifndef TL_H
#define TL_H
#include <stdio.h>

static int tl_passed, tl_failed;
static const char *tl_current = "";

/* A named check: prints FAIL lines with a message, counts every check. */
#define TL_CHECK(cond, ...) \
  do { \
    if (cond) { \
      tl_passed++; \
    } else { \
      tl_failed++; \
      printf("FAIL %s (%s:%d): ", tl_current, __FILE__, __LINE__); \
      printf(__VA_ARGS__); \
      printf("\n"); \
    } \
  } while (0)

/* Run one test function, printing its name and whether all its checks passed. */
#define TL_RUN(fn) \
  do { \
    int tl_f0 = tl_failed, tl_p0 = tl_passed; \
    tl_current = #fn; \
    fn(); \
    printf("%-4s %s (%d checks)\n", tl_failed == tl_f0 ? "ok" : "FAIL", #fn, \
           tl_passed + tl_failed - tl_p0 - tl_f0); \
  } while (0)

/* Closing line; exit status 0 only when nothing failed. */
static int tl_summary(void) {
  printf("%d passed, %d failed\n", tl_passed, tl_failed);
  return tl_failed ? 1 : 0;
}
#endif
