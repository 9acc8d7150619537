/* merl_write.c - writes a BRDF file in MERL's binary format (Matusik, Pfister, Brand and
 * McMillan 2003, "A data-driven reflectance model") from a documented analytic model, so that
 * shlrender's measured-material path (--brdf FILE) can be run and tested without shipping
 * measured data. The model (shl_brdf_eval, SHLIGHT_BRDF_GGX, f0 = 1: no Fresnel):
 *   f_c(w_o, w_i) = kd_c / pi + ks D(h) G2(w_o, w_i) / (4 cos_i cos_o)
 * GGX (Trowbridge-Reitz) D of slope roughness alpha, height-correlated Smith G2; defaults
 * alpha 0.3, kd (0.30, 0.15, 0.06) (a coloured diffuse base, so that the three channels
 * differ), ks 0.5.
 *
 * usage: merl_write OUT [n_theta_h n_theta_d n_phi_d [alpha kd_r kd_g kd_b ks]]
 * (dimensions default 90 90 180, MERL's: a 35 MB file; smaller ones make a quick test file).
 *
 * Format: int32 n_theta_h, n_theta_d, n_phi_d (little-endian), then 3 x their product float64
 * (red, green, blue), each [theta_h][theta_d][phi_d]; sample (i, j, k) at theta_h =
 * (i / n_theta_h)^2 pi/2 (MERL's square-root index), theta_d = j / n_theta_d pi/2, phi_d =
 * k / n_phi_d pi, the value f_c / s_c with s = (1, 1.15, 1.66) / 1500 (MERL's scale factors,
 * which readers multiply back); -1 (MERL's mark of an invalid sample) where w_i or w_o is at or
 * below the horizon. The half-diff frame: h at (theta_h, phi_h = 0), w_i = the difference
 * vector (theta_d, phi_d) rotated by theta_h about the binormal, w_o its mirror about h.
 *
 * After writing, the file is read back with shl_merl_read and shl_merl_eval is compared with
 * the model at 20000 random direction pairs (both above 5 degrees elevation): the printed
 * error is the tabulation's (MERL's parametrisation, trilinear), not the reader's. Exit 0, or
 * 1 on a bad argument or an I/O error. */
#define SHLIGHT_IMPLEMENTATION
#include "../shlight.h"

#include <math.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>

static void put32(unsigned char *p, unsigned v) {
  p[0] = (unsigned char)(v & 255u);
  p[1] = (unsigned char)((v >> 8) & 255u);
  p[2] = (unsigned char)((v >> 16) & 255u);
  p[3] = (unsigned char)((v >> 24) & 255u);
}

static void put64(unsigned char *p, double x) {
  unsigned long long u;
  int k;
  memcpy(&u, &x, sizeof u);
  for (k = 0; k < 8; k++)
    p[k] = (unsigned char)((u >> (8 * k)) & 255u);
}

/* uniform random direction on the hemisphere above 5 degrees elevation (xorshift) */
static unsigned long long rng = 88172645463325252ull;
static double urand(void) {
  rng ^= rng << 13;
  rng ^= rng >> 7;
  rng ^= rng << 17;
  return (double)(rng >> 11) * (1.0 / 9007199254740992.0);
}
static void hemi(float d[3]) {
  double z = sin(5.0 * 3.14159265358979 / 180.0), ct = z + (1.0 - z) * urand(),
         st = sqrt(1.0 - ct * ct), ph = 2.0 * 3.14159265358979 * urand();
  d[0] = (float)(st * cos(ph));
  d[1] = (float)(st * sin(ph));
  d[2] = (float)ct;
}

int main(int argc, char **argv) {
  const double pi = 3.14159265358979323846, scale[3] = {1.0 / 1500, 1.15 / 1500, 1.66 / 1500};
  int dims[3] = {90, 90, 180}, i, j, k, c;
  float kd[3] = {0.30f, 0.15f, 0.06f}, ks = 0.5f, alpha = 0.3f;
  shl_brdf_params par;
  size_t np, len, at;
  unsigned char *buf;
  float *store;
  shl_merl m;
  FILE *f;
  double maxrel = 0, sum = 0, sumref = 0;
  if (argc != 2 && argc != 5 && argc != 10) {
    fprintf(stderr, "usage: merl_write OUT [n_theta_h n_theta_d n_phi_d [alpha kd_r kd_g kd_b "
                    "ks]]\n");
    return 1;
  }
  if (argc >= 5)
    for (k = 0; k < 3; k++)
      if (sscanf(argv[2 + k], "%d", &dims[k]) != 1 || dims[k] < 2 || dims[k] > 1024) {
        fprintf(stderr, "merl_write: dimension '%s' not in [2, 1024]\n", argv[2 + k]);
        return 1;
      }
  if (argc == 10 &&
      (sscanf(argv[5], "%f", &alpha) != 1 || sscanf(argv[6], "%f", &kd[0]) != 1 ||
       sscanf(argv[7], "%f", &kd[1]) != 1 || sscanf(argv[8], "%f", &kd[2]) != 1 ||
       sscanf(argv[9], "%f", &ks) != 1 || !(alpha >= 1e-3f && alpha <= 4.0f) ||
       !(ks >= 0.0f && ks <= 1.0f) || !(kd[0] >= 0.0f && kd[1] >= 0.0f && kd[2] >= 0.0f))) {
    fprintf(stderr, "merl_write: bad model parameters (alpha in [1e-3, 4], kd >= 0, ks in "
                    "[0, 1])\n");
    return 1;
  }
  np = (size_t)dims[0] * (size_t)dims[1] * (size_t)dims[2];
  len = 12 + 24 * np;
  buf = (unsigned char *)malloc(len);
  store = (float *)malloc(3 * np * sizeof(float));
  if (!buf || !store) {
    fprintf(stderr, "merl_write: out of memory\n");
    return 1;
  }
  for (k = 0; k < 3; k++)
    put32(buf + 4 * k, (unsigned)dims[k]);
  memset(&par, 0, sizeof par);
  par.model = SHLIGHT_BRDF_GGX;
  par.ks = ks;
  par.alpha_x = par.alpha_y = alpha;
  par.f0 = 1.0f;
  at = 12;
  for (c = 0; c < 3; c++) {
    par.kd = kd[c];
    for (i = 0; i < dims[0]; i++)
      for (j = 0; j < dims[1]; j++)
        for (k = 0; k < dims[2]; k++) {
          double u = (double)i / dims[0], th = u * u * pi / 2, td = (double)j / dims[1] * pi / 2;
          double pd = (double)k / dims[2] * pi, h[3], d[3], wi[3], wo[3], dh, v = -1.0;
          float fo[3], fi[3];
          int q;
          h[0] = sin(th);
          h[1] = 0;
          h[2] = cos(th);
          d[0] = sin(td) * cos(pd);
          d[1] = sin(td) * sin(pd);
          d[2] = cos(td);
          /* rotate d about the binormal (y) by theta_h */
          wi[0] = d[0] * cos(th) + d[2] * sin(th);
          wi[1] = d[1];
          wi[2] = -d[0] * sin(th) + d[2] * cos(th);
          dh = wi[0] * h[0] + wi[1] * h[1] + wi[2] * h[2];
          for (q = 0; q < 3; q++) {
            wo[q] = 2 * dh * h[q] - wi[q];
            fo[q] = (float)wo[q];
            fi[q] = (float)wi[q];
          }
          if (wi[2] > 0 && wo[2] > 0) v = (double)shl_brdf_eval(&par, fo, fi) / scale[c];
          put64(buf + at, v);
          at += 8;
        }
  }
  f = fopen(argv[1], "wb");
  if (!f || fwrite(buf, 1, len, f) != len || fclose(f) != 0) {
    fprintf(stderr, "merl_write: cannot write %s\n", argv[1]);
    return 1;
  }
  if (shl_merl_read(buf, len, store, 3 * np, &m) != SHLIGHT_OK) {
    fprintf(stderr, "merl_write: shl_merl_read refused the file\n");
    return 1;
  }
  for (i = 0; i < 20000; i++) {
    float wo[3], wi[3];
    hemi(wo);
    hemi(wi);
    for (c = 0; c < 3; c++) {
      double ref, got;
      par.kd = kd[c];
      ref = (double)shl_brdf_eval(&par, wo, wi);
      got = (double)shl_merl_eval(&m, c, wo, wi);
      if (fabs(got - ref) / ref > maxrel) maxrel = fabs(got - ref) / ref;
      sum += (got - ref) * (got - ref);
      sumref += ref * ref;
    }
  }
  printf("merl_write: %s, %dx%dx%d, GGX alpha %g + Lambert kd (%g, %g, %g), ks %g; read back: "
         "shl_merl_eval vs the model at 20000 pairs above 5 deg: rms rel %.3g, max rel %.3g\n",
         argv[1], dims[0], dims[1], dims[2], (double)alpha, (double)kd[0], (double)kd[1],
         (double)kd[2], (double)ks, sqrt(sum / sumref), maxrel);
  free(buf);
  free(store);
  return 0;
}
