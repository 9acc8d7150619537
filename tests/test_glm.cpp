// test_glm.cpp - rotation properties of shlight's SH basis, with rotations from GLM.
//
// C++11 TU: includes shlight.h WITHOUT SHLIGHT_IMPLEMENTATION, so it also checks that the
// header compiles and works as C++ and links against the implementation compiled as C
// (tests/impl_c.c, through extern "C").  Build (see tests/tests.mk):
//   gcc -std=c99 -O2 -c -o impl.o tests/impl_c.c
//   g++ -std=c++11 -O2 -g -Wall -Wextra -Wpedantic -Wconversion -Wshadow -Wdouble-promotion
//       -ffp-contract=off -o build/tests/test_glm tests/test_glm.cpp impl.o -lm
//
// Properties (n <= 10 bands), each independent of how Y is computed:
//  1. Unsold: the band energy sum_m Y_lm(R d)^2 = (2l+1)/4pi for every direction and rotation.
//  2. Rotation invariance of band energy: for a fixed random SH function f (coefficients c),
//     the coefficients c' of f(R^-1 .), projected by quadrature (Gauss-Legendre in z x uniform
//     phi, exact for these band-limited products), have sum_m c'_lm^2 = sum_m c_lm^2.
//  3. Addition theorem under rotation: sum_m Y_lm(R a) Y_lm(R b) = (2l+1)/4pi P_l(a.b).
// Rotations: glm::rotate (angle-axis) in double; directions rotated in double, rounded to float.
//
// Tolerances are worst-case bounds from the per-coefficient value error errY = the issue's
// target for shl_sh_eval (3e-7 for n <= 4, 2e-6 at n = 16, log-log in between; tests/test_basis.c
// measures it) plus the effect of rounding the rotated direction to float (|delta d| <= sqrt(3) u,
// moving Y_lm by <= G_l sqrt(3) u, G_l = sqrt(l(l+1)(2l+1)/4pi) the largest tangential gradient).
#include <glm/glm.hpp>
#include <glm/gtc/matrix_transform.hpp>

#include "../shlight.h"
#include "tl.h"

#include <cmath>
#include <cstdint>
#include <cstdio>
#include <cstring>
#include <vector>

namespace {

const int NB = 10; // bands
const int NC = NB * NB;
const double U32 = 1.0 / 16777216.0; // float unit roundoff
const double PI = 3.14159265358979323846;

uint64_t g_state = 0x61adULL;
uint64_t next_u64() {
  uint64_t z = (g_state += 0x9E3779B97F4A7C15ULL);
  z = (z ^ (z >> 30)) * 0xBF58476D1CE4E5B9ULL;
  z = (z ^ (z >> 27)) * 0x94D049BB133111EBULL;
  return z ^ (z >> 31);
}
double u01() {
  return static_cast<double>(next_u64() >> 11) * (1.0 / 9007199254740992.0);
}

glm::dvec3 rand_dir() {
  double z = 2.0 * u01() - 1.0, ph = 2.0 * PI * u01(), r = std::sqrt(std::fmax(0.0, 1.0 - z * z));
  return glm::dvec3(r * std::cos(ph), r * std::sin(ph), z);
}
glm::dmat3 rand_rotation() {
  glm::dvec3 axis = rand_dir();
  double angle = 2.0 * PI * u01();
  return glm::dmat3(glm::rotate(glm::dmat4(1.0), angle, axis));
}

double target_eval(int n) { // same as tests/test_basis.c
  if (n <= 4) return 3e-7;
  if (n <= 16) return 3e-7 * std::pow(2e-6 / 3e-7, std::log(n / 4.0) / std::log(4.0));
  return 2e-6 * std::pow(5.0, std::log(n / 16.0) / std::log(2.0));
}
double grad_scale(int l) {
  return std::sqrt(l * (l + 1.0) * (2.0 * l + 1.0) / (4.0 * PI));
}
// Error of one Y_lm at a float-rounded direction relative to the exact direction.
double err_y(int l) {
  return target_eval(l + 1) + std::sqrt(3.0) * U32 * grad_scale(l);
}

void eval_at(const glm::dvec3 &v, float *y) {
  float d[3] = {static_cast<float>(v.x), static_cast<float>(v.y), static_cast<float>(v.z)};
  shl_sh_eval(NB, d, y);
}

// Gauss-Legendre nodes and weights in double (Newton on P_N).
void gauss_legendre(int N, std::vector<double> &x, std::vector<double> &w) {
  x.resize(static_cast<size_t>(N));
  w.resize(static_cast<size_t>(N));
  for (int i = 0; i < N; i++) {
    double z = std::cos(PI * (i + 0.75) / (N + 0.5)), dp = 1;
    for (int it = 0; it < 100; it++) {
      double p0 = 1, p1 = z;
      for (int j = 2; j <= N; j++) {
        double p2 = ((2 * j - 1) * z * p1 - (j - 1) * p0) / j;
        p0 = p1;
        p1 = p2;
      }
      dp = N * (z * p1 - p0) / (z * z - 1);
      double dz = p1 / dp;
      z -= dz;
      if (std::fabs(dz) < 1e-16) break;
    }
    double p0 = 1, p1 = z;
    for (int j = 2; j <= N; j++) {
      double p2 = ((2 * j - 1) * z * p1 - (j - 1) * p0) / j;
      p0 = p1;
      p1 = p2;
    }
    dp = N * (z * p1 - p0) / (z * z - 1);
    x[static_cast<size_t>(i)] = z;
    w[static_cast<size_t>(i)] = 2 / ((1 - z * z) * dp * dp);
  }
}

// 1. Band energy at rotated directions.  |sum Y^2 - E| <= 2 e sum_m|Y| + (2l+1) e^2 with
//    sum_m |Y_lm| <= (2l+1)/sqrt(4pi) (Cauchy-Schwarz + Unsold), e = err_y(l).
void test_band_energy_rotated() {
  float y[NC];
  double worst = 0;
  int bad = 0;
  for (int r = 0; r < 200; r++) {
    glm::dmat3 R = rand_rotation();
    for (int k = 0; k < 20; k++) {
      eval_at(R * rand_dir(), y);
      for (int l = 0; l < NB; l++) {
        double s = 0, want = (2 * l + 1) / (4 * PI), e = err_y(l);
        double tol = 2 * e * (2 * l + 1) / std::sqrt(4 * PI) + (2 * l + 1) * e * e;
        for (int m = -l; m <= l; m++) {
          double v = static_cast<double>(y[l * (l + 1) + m]);
          s += v * v;
        }
        worst = std::fmax(worst, std::fabs(s - want) / tol);
        if (!(std::fabs(s - want) <= tol)) bad++;
      }
    }
  }
  std::printf("  band energy sum_m Y_lm(R d)^2 = (2l+1)/4pi, 4000 rotated directions, n = %d: "
              "worst err/tol %.4f\n",
              NB, worst);
  TL_CHECK(bad == 0, "%d (direction, band) pairs off", bad);
}

// 2. Rotation invariance of band energy of a projected random SH function.
//    f(d) = sum_i c_i Y_i(d), g(d) = f(R^T d), c'_i = sum_q w_q g(d_q) Y_i(d_q) (quadrature:
//    N = n+1 Gauss-Legendre nodes in z, M = 2n+1 phi, exact for products of band < n).
//    Bounds: |dg| <= B = sum_i |c_i| e_i ;  |g| <= G = sum_i |c_i| sqrt((2l+1)/4pi);
//    |dc'_i| <= B sqrt(4pi) + G 4pi e_i  (int |Y| <= sqrt(4pi));
//    |dE_l| <= 2 sqrt(E_l (2l+1)) max_m |dc'| + (2l+1) max_m |dc'|^2.
void test_rotation_invariance_projection() {
  const int N = NB + 1, M = 2 * NB + 1;
  std::vector<double> zx, zw;
  gauss_legendre(N, zx, zw);
  double c[NC], cp[NC], E[NB], B = 0, G = 0, worst = 0, maxdiff = 0;
  for (int i = 0; i < NC; i++)
    c[i] = 2 * u01() - 1;
  for (int l = 0; l < NB; l++) {
    E[l] = 0;
    for (int m = -l; m <= l; m++) {
      double v = c[l * (l + 1) + m];
      E[l] += v * v;
      B += std::fabs(v) * err_y(l);
      G += std::fabs(v) * std::sqrt((2 * l + 1) / (4 * PI));
    }
  }
  int bad = 0;
  for (int r = 0; r < 24; r++) {
    glm::dmat3 R = r == 0 ? glm::dmat3(1.0) : rand_rotation();
    glm::dmat3 Rinv = glm::transpose(R);
    float y[NC], yr[NC];
    for (int i = 0; i < NC; i++)
      cp[i] = 0;
    for (int a = 0; a < N; a++)
      for (int b = 0; b < M; b++) {
        double z = zx[static_cast<size_t>(a)], s = std::sqrt(1 - z * z), ph = 2 * PI * b / M;
        double w = zw[static_cast<size_t>(a)] * 2 * PI / M;
        glm::dvec3 d(s * std::cos(ph), s * std::sin(ph), z);
        eval_at(d, y);
        eval_at(Rinv * d, yr);
        double g = 0;
        for (int i = 0; i < NC; i++)
          g += c[i] * static_cast<double>(yr[i]);
        for (int i = 0; i < NC; i++)
          cp[i] += w * g * static_cast<double>(y[i]);
      }
    for (int l = 0; l < NB; l++) {
      double Ep = 0, dc = B * std::sqrt(4 * PI) + G * 4 * PI * err_y(l);
      for (int m = -l; m <= l; m++)
        Ep += cp[l * (l + 1) + m] * cp[l * (l + 1) + m];
      double tol = 2 * std::sqrt(E[l] * (2 * l + 1)) * dc + (2 * l + 1) * dc * dc;
      worst = std::fmax(worst, std::fabs(Ep - E[l]) / tol);
      maxdiff = std::fmax(maxdiff, std::fabs(Ep - E[l]) / E[l]);
      if (!(std::fabs(Ep - E[l]) <= tol)) {
        bad++;
        std::printf("  rotation %d band %d: E' %.9g vs E %.9g (tol %.2e)\n", r, l, Ep, E[l], tol);
      }
      if (r == 0) // identity: the projection must give back c itself
        for (int m = -l; m <= l; m++)
          TL_CHECK(std::fabs(cp[l * (l + 1) + m] - c[l * (l + 1) + m]) <= dc,
                   "identity projection l=%d m=%d: %.3e", l, m,
                   std::fabs(cp[l * (l + 1) + m] - c[l * (l + 1) + m]));
    }
  }
  std::printf("  band energies of f(R^-1 .) projected by quadrature, 23 GLM rotations + identity, "
              "n = %d: worst err/tol %.4f (max relative energy change %.2e)\n",
              NB, worst, maxdiff);
  TL_CHECK(bad == 0, "%d (rotation, band) energies off", bad);
}

// 3. Addition theorem under rotation: |sum - want| <= 2 e (2l+1)/sqrt(4pi) + (2l+1) e^2.
void test_addition_theorem_rotated() {
  float ya[NC], yb[NC];
  double worst = 0;
  int bad = 0;
  for (int r = 0; r < 200; r++) {
    glm::dmat3 R = rand_rotation();
    glm::dvec3 a = rand_dir(), b = rand_dir();
    if (r % 10 == 0) b = glm::normalize(a + 1e-3 * rand_dir()); // nearly parallel pairs
    double t = glm::dot(a, b) / (glm::length(a) * glm::length(b));
    eval_at(R * a, ya);
    eval_at(R * b, yb);
    double p0 = 1, p1 = t;
    for (int l = 0; l < NB; l++) {
      double P = l == 0 ? 1.0 : (l == 1 ? t : 0);
      if (l >= 2) {
        P = ((2 * l - 1) * t * p1 - (l - 1) * p0) / l;
        p0 = p1;
        p1 = P;
      }
      double s = 0, e = err_y(l), want = (2 * l + 1) / (4 * PI) * P;
      for (int m = -l; m <= l; m++)
        s += static_cast<double>(ya[l * (l + 1) + m]) * static_cast<double>(yb[l * (l + 1) + m]);
      double tol = 2 * e * (2 * l + 1) / std::sqrt(4 * PI) + (2 * l + 1) * e * e;
      worst = std::fmax(worst, std::fabs(s - want) / tol);
      if (!(std::fabs(s - want) <= tol)) bad++;
    }
  }
  std::printf("  addition theorem at rotated pairs, n = %d: worst err/tol %.4f\n", NB, worst);
  TL_CHECK(bad == 0, "%d (pair, band) sums off", bad);
}

} // namespace

int main() {
  TL_RUN(test_band_energy_rotated);
  TL_RUN(test_rotation_invariance_projection);
  TL_RUN(test_addition_theorem_rotated);
  return tl_summary();
}
