/* fuzz_scene.c - libFuzzer target for shlrender's scene parser (render/rd_scene.c).
 *
 * Each input is parsed as scene text (no folder: `obj` lines are refused). Checked (failures
 * print and abort(), or count in replay mode):
 *  - no out-of-bounds access (ASan), no UB (UBSan), no leak (LSan);
 *  - failure: the message starts with "fuzz:" (file:line form) and the scene is left empty;
 *  - success: counts within limits, every material index valid, every number finite, kd/ks in
 *    [0, 1], bands in [1, 16], light vertex counts in [3, 8], unit disc/spot directions, the
 *    bounds finite and ordered, and at least one piece of geometry.
 * Build and run (clang):
 *   clang -std=c99 -g -O1 -fsanitize=fuzzer,address,undefined -fno-sanitize-recover=undefined \
 *     -o build/tests/fuzz_scene tests/fuzz_scene.c render/rd_scene.c -lm
 *   build/tests/fuzz_scene -max_len=2048 -max_total_time=600 work/ tests/corpus/scene/
 * Replay without libFuzzer (CI): tests/fuzz_replay.c + this file + render/rd_scene.c:
 *   build/tests/fuzz_replay_scene tests/corpus/scene */
#include "../render/rd.h"

#include <math.h>
#include <stdint.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>

int fuzz_basis_soft_fail; /* the names tests/fuzz_replay.c links against */
long fuzz_basis_failures;

int LLVMFuzzerTestOneInput(const uint8_t *data, size_t size);

static int bad(const char *what) {
  printf("FAIL fuzz_scene: %s\n", what);
  if (!fuzz_basis_soft_fail) abort();
  fuzz_basis_failures++;
  return 0;
}
static int fin3(const float *v) {
  return isfinite(v[0]) && isfinite(v[1]) && isfinite(v[2]);
}

int LLVMFuzzerTestOneInput(const uint8_t *data, size_t size) {
  rd_scene s;
  char err[256];
  int i, k;
  err[0] = 0;
  if (rd_scene_parse((const char *)data, size, NULL, "fuzz", &s, err, sizeof err) != 0) {
    if (strncmp(err, "fuzz:", 5)) return bad("error message without the file:line prefix");
    if (s.mats || s.tris || s.spheres || s.lights || s.ntris || s.nmats)
      return bad("failed parse left a half-loaded scene");
    return 0;
  }
  if (s.ntris + s.nspheres <= 0) bad("scene without geometry accepted");
  if (s.bands < 1 || s.bands > 16) bad("bands out of range");
  if (!fin3(s.cam.eye) || !fin3(s.cam.target) || !fin3(s.cam.up) || !(s.cam.fov_y > 0))
    bad("camera");
  for (i = 0; i < s.nmats; i++) {
    const rd_material *m = &s.mats[i];
    for (k = 0; k < 3; k++)
      if (!(m->kd[k] >= 0 && m->kd[k] <= 1 && m->ks[k] >= 0 && m->kd[k] + m->ks[k] <= 1))
        bad("material albedo");
    if (!(m->exponent >= 0) || !(m->roughness >= 0) || !(m->bump_freq >= 0) ||
        !(m->bump_amp >= 0) || m->brdf < 0 || m->brdf > 2)
      bad("material parameters");
  }
  for (i = 0; i < s.ntris; i++) {
    if (s.tris[i].mat < 0 || s.tris[i].mat >= s.nmats) bad("triangle material index");
    for (k = 0; k < 3; k++)
      if (!fin3(s.tris[i].p[k]) || !fin3(s.tris[i].n[k])) bad("triangle not finite");
  }
  for (i = 0; i < s.nspheres; i++)
    if (s.spheres[i].mat < 0 || s.spheres[i].mat >= s.nmats || !fin3(s.spheres[i].c) ||
        !(s.spheres[i].r > 0))
      bad("sphere");
  for (i = 0; i < s.nlights; i++) {
    const rd_light *l = &s.lights[i];
    if (!fin3(l->radiance) || l->radiance[0] < 0 || l->radiance[1] < 0 || l->radiance[2] < 0)
      bad("light colour");
    if ((l->type == RD_LIGHT_TRIANGLE || l->type == RD_LIGHT_POLYGON) &&
        (l->nv < 3 || l->nv > RD_MAX_POLY))
      bad("light vertex count");
    if ((l->type == RD_LIGHT_DISC || l->type == RD_LIGHT_SPOT) &&
        !(fabsf(rd_dot(l->n, l->n) - 1.0f) < 1e-4f))
      bad("light direction not unit");
    if (l->type < 0 || l->type > RD_LIGHT_SPOT) bad("light type");
  }
  for (k = 0; k < 3; k++)
    if (!(isfinite(s.bmin[k]) && isfinite(s.bmax[k]) && s.bmin[k] <= s.bmax[k])) bad("bounds");
  rd_scene_free(&s);
  return 0;
}
