/* fuzz_random.c - seeded random driver for tests/fuzz_families.c (no libFuzzer needed):
 *   build/tests/fuzz_random [calls_per_family [seed]]      (default 2000, seed 1)
 *   build/tests/fuzz_random -corpus DIR                     writes the seed corpus (8 per family)
 * Inputs are random byte strings (64..400 bytes) with byte 0 = the family, so every family
 * gets the same number of inputs; the family target's selector bytes mix hard values (0,
 * denormals, 1e15, 1e21, FLT_MAX, inf, NaN, ...) with raw float bits. Prints the calls and
 * failures per public function, ends with "N passed, N failed" (one check per function:
 * passed when it was called and never failed). */
#include <stdint.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>

int LLVMFuzzerTestOneInput(const uint8_t *data, size_t size);
extern int fuzz_basis_soft_fail;
extern long fuzz_basis_failures;
extern const char *const fuzz_fam_names[];
extern long fuzz_fam_calls[];
extern long fuzz_fam_fails[];
#define FUZZ_NFUNC 59

static uint64_t g_s = 1;
static uint32_t rnd(void) { /* xorshift64* */
  g_s ^= g_s >> 12;
  g_s ^= g_s << 25;
  g_s ^= g_s >> 27;
  return (uint32_t)((g_s * 2685821657736338717ull) >> 32);
}

static size_t make_input(uint8_t *buf, int fam) {
  size_t len = 64 + rnd() % 337, i;
  buf[0] = (uint8_t)fam;
  for (i = 1; i < len; ++i)
    buf[i] = (uint8_t)rnd();
  return len;
}

int main(int argc, char **argv) {
  static uint8_t buf[512];
  long per = 2000, k;
  int fam, i, passed = 0, failed = 0;
  setvbuf(stdout, NULL, _IOLBF, 0);
  fuzz_basis_soft_fail = 1;
  if (argc >= 3 && strcmp(argv[1], "-corpus") == 0) {
    for (fam = 0; fam < 6; ++fam)
      for (k = 0; k < 8; ++k) {
        char name[1024];
        FILE *f;
        size_t len = make_input(buf, fam);
        snprintf(name, sizeof name, "%s/fam%d_%02ld", argv[2], fam, k);
        f = fopen(name, "wb");
        if (!f) return 1;
        fwrite(buf, 1, len, f);
        fclose(f);
      }
    return 0;
  }
  if (argc >= 2) per = atol(argv[1]);
  if (argc >= 3) g_s = (uint64_t)strtoull(argv[2], NULL, 10) * 0x9E3779B97F4A7C15ull + 1u;
  for (k = 0; k < per; ++k)
    for (fam = 0; fam < 6; ++fam) {
      size_t len = make_input(buf, fam);
      LLVMFuzzerTestOneInput(buf, len);
    }
  printf("%-34s %10s %8s\n", "function", "calls", "findings");
  for (i = 0; i < FUZZ_NFUNC; ++i) {
    printf("%-34s %10ld %8ld\n", fuzz_fam_names[i], fuzz_fam_calls[i], fuzz_fam_fails[i]);
    if (fuzz_fam_calls[i] > 0 && fuzz_fam_fails[i] == 0)
      passed++;
    else
      failed++;
  }
  printf("fuzz_random: %ld inputs per family, seed %s\n", per, argc >= 3 ? argv[2] : "1");
  printf("%d passed, %d failed\n", passed, failed);
  return failed ? 1 : 0;
}
