/* fuzz_brdftab.c - libFuzzer target for the two table loaders of >>brdftab: shl_brdf_table_read
 * (SHLT files) and shl_merl_read (MERL binary BRDFs).
 *
 * Input bytes: [0] bit 0: 0 = SHLT, 1 = MERL; bits 1-2: the storage given to the second call
 * (0 exact, 1 one float short, 2 none, 3 exact plus 7); [1 ..] the file.  Each input is parsed
 * twice: with no storage (the size query: must give SHLIGHT_ESTORAGE or a parse error), then
 * with a malloc'ed buffer of exactly the size the query reported, so ASan flags any write
 * beyond it; the file bytes are copied into an exact-size buffer, so reads beyond it trap too.
 *
 * Checked (failures print and abort(), or count in replay mode):
 *  - no out-of-bounds access (ASan), no UB (UBSan);
 *  - both calls agree on the parse error, the query leaves data NULL;
 *  - success only with enough storage; then the dimensions are in range, every float finite;
 *  - SHLT: writing the table back gives the input bytes exactly (round trip), and
 *    shl_brdf_table_lookup at 5 directions is finite;
 *  - MERL: shl_merl_eval at 5 direction pairs is finite and >= 0.
 *
 * Build and run (clang 14):
 *   clang -std=c99 -g -O1 -fsanitize=fuzzer,address,undefined -fno-sanitize-recover=undefined \
 *     -o build/tests/fuzz_brdftab tests/fuzz_brdftab.c -lm
 *   build/tests/fuzz_brdftab -max_len=4096 -max_total_time=600 work/ tests/corpus/brdftab/
 * Replay without libFuzzer (CI, tests/tests.mk): tests/fuzz_replay.c + this file:
 *   build/tests/fuzz_replay_brdftab tests/corpus/brdftab
 * tests/corpus/brdftab/ is written by tests/gen_brdftab_corpus.py (valid and broken files).
 */
#define SHLIGHT_IMPLEMENTATION
#include "../shlight.h"

#include <math.h>
#include <stddef.h>
#include <stdint.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>

int fuzz_basis_soft_fail; /* the names tests/fuzz_replay.c links against */
long fuzz_basis_failures;

int LLVMFuzzerTestOneInput(const uint8_t *data, size_t size);

static void fuzz_fail(const char *what, size_t size) {
  printf("FAIL fuzz_brdftab: %s (input of %zu bytes)\n", what, size);
  fflush(stdout);
  if (!fuzz_basis_soft_fail) abort();
  fuzz_basis_failures++;
}
#define FUZZ_CHECK(cond, what) \
  do { \
    if (!(cond)) fuzz_fail(what, size); \
  } while (0)

static const float dirs[5][3] = {{0.0f, 0.0f, 1.0f},
                                 {0.6f, 0.0f, 0.8f},
                                 {-0.48f, 0.6f, 0.64f},
                                 {1.0f, 0.0f, 0.0f},
                                 {0.0f, 0.0f, 0.0f}};

static void *dup_exact(const uint8_t *p, size_t n) {
  void *b = malloc(n ? n : 1);
  if (!b) abort();
  if (n) memcpy(b, p, n);
  return b;
}

int LLVMFuzzerTestOneInput(const uint8_t *data, size_t size) {
  int mode, smode;
  size_t flen;
  void *file;
  if (size < 1) return 0;
  mode = data[0] & 1;
  smode = (data[0] >> 1) & 3;
  flen = size - 1;
  file = dup_exact(data + 1, flen);
  if (mode == 0) {
    shl_brdf_table t, t2;
    shl_result r0, r1;
    size_t need = 0, give = 0;
    float *st = NULL;
    memset(&t, 0, sizeof t);
    r0 = shl_brdf_table_read(file, flen, NULL, 0, &t);
    FUZZ_CHECK(r0 != SHLIGHT_OK, "SHLT: success without storage");
    if (r0 == SHLIGHT_ESTORAGE) {
      FUZZ_CHECK(t.data == NULL, "SHLT: query set data");
      need = shl_brdf_table_size(t.n, t.n_theta, t.n_phi);
      FUZZ_CHECK(need > 0, "SHLT: query reported invalid dimensions");
      give = smode == 0 ? need : smode == 1 ? need - 1 : smode == 2 ? 0 : need + 7;
    }
    if (give) {
      st = (float *)malloc(give * sizeof(float));
      if (!st) abort();
    }
    memset(&t2, 0, sizeof t2);
    r1 = shl_brdf_table_read(file, flen, st, give, &t2);
    if (r0 != SHLIGHT_ESTORAGE) {
      FUZZ_CHECK(r1 == r0, "SHLT: storage changed the parse error");
    } else if (give < need) {
      FUZZ_CHECK(r1 == SHLIGHT_ESTORAGE, "SHLT: short storage accepted");
    } else {
      FUZZ_CHECK(r1 == SHLIGHT_OK, "SHLT: enough storage, still an error");
    }
    if (r1 == SHLIGHT_OK) {
      size_t i, len = 0;
      int k, j;
      unsigned char *back = (unsigned char *)malloc(flen ? flen : 1);
      if (!back) abort();
      FUZZ_CHECK(t2.data == st && t2.n >= 1 && t2.n <= SHLIGHT_MAX_BANDS, "SHLT: bad result");
      for (i = 0; i < need; i++)
        FUZZ_CHECK(isfinite(st[i]), "SHLT: non-finite float accepted");
      FUZZ_CHECK(shl_brdf_table_write(&t2, back, flen, &len) == SHLIGHT_OK && len == flen &&
                     memcmp(back, file, flen) == 0,
                 "SHLT: write(read(file)) != file");
      free(back);
      {
        float *o = (float *)malloc((size_t)t2.n * (size_t)t2.n * sizeof(float));
        if (!o) abort();
        for (k = 0; k < 5; k++) {
          shl_brdf_table_lookup(t2.n, t2.n_theta, t2.n_phi, k & 1, st, dirs[k], o);
          for (j = 0; j < t2.n * t2.n; j++)
            FUZZ_CHECK(isfinite(o[j]), "SHLT: lookup non-finite");
        }
        free(o);
      }
    }
    free(st);
  } else {
    shl_merl m, m2;
    shl_result r0, r1;
    size_t need = 0, give = 0;
    float *st = NULL;
    memset(&m, 0, sizeof m);
    r0 = shl_merl_read(file, flen, NULL, 0, &m);
    FUZZ_CHECK(r0 != SHLIGHT_OK, "MERL: success without storage");
    if (r0 == SHLIGHT_ESTORAGE) {
      FUZZ_CHECK(m.data == NULL, "MERL: query set data");
      need = 3u * (size_t)m.n_theta_h * (size_t)m.n_theta_d * (size_t)m.n_phi_d;
      FUZZ_CHECK(need > 0, "MERL: query reported invalid dimensions");
      give = smode == 0 ? need : smode == 1 ? need - 1 : smode == 2 ? 0 : need + 7;
    }
    if (give) {
      st = (float *)malloc(give * sizeof(float));
      if (!st) abort();
    }
    memset(&m2, 0, sizeof m2);
    r1 = shl_merl_read(file, flen, st, give, &m2);
    if (r0 != SHLIGHT_ESTORAGE) {
      FUZZ_CHECK(r1 == r0, "MERL: storage changed the parse error");
    } else if (give < need) {
      FUZZ_CHECK(r1 == SHLIGHT_ESTORAGE, "MERL: short storage accepted");
    } else {
      FUZZ_CHECK(r1 == SHLIGHT_OK, "MERL: enough storage, still an error");
    }
    if (r1 == SHLIGHT_OK) {
      size_t i;
      int k, c;
      for (i = 0; i < need; i++)
        FUZZ_CHECK(isfinite(st[i]), "MERL: non-finite float accepted");
      for (k = 0; k < 5; k++)
        for (c = 0; c < 3; c++) {
          float v = shl_merl_eval(&m2, c, dirs[k], dirs[(k + 2) % 5]);
          FUZZ_CHECK(isfinite(v) && v >= 0.0f, "MERL: eval not finite or negative");
        }
    }
    free(st);
  }
  free(file);
  return 0;
}
