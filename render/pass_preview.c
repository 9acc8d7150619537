/* pass_preview.c - "preview": albedo times a head-light cosine, on the GPU and the CPU. It shows
 * the G-buffer and checks the GL runner (pixel order, materials, G-buffer textures). */
#include "rd.h"

#include <math.h>
#include <stdlib.h>

static const char *body = "void main() {\n"
                          "  ivec2 px = rd_pixel();\n"
                          "  vec4 p = texelFetch(rd_pos, px, 0), n = texelFetch(rd_nrm, px, 0);\n"
                          "  if (n.w < 0.0) { rd_out0 = vec4(0.0); return; }\n"
                          "  int m = int(n.w) * 12;\n"
                          "  vec3 kd = vec3(rd_mats[m], rd_mats[m + 1], rd_mats[m + 2]);\n"
                          "  vec3 v = normalize(rd_eye - p.xyz);\n"
                          "  rd_out0 = vec4(kd * (0.15 + 0.85 * max(0.0, dot(n.xyz, v))), 1.0);\n"
                          "}\n";

int rd_pass_preview(rd_run *run) {
  const rd_gbuf *g = run->gb;
  size_t n = (size_t)g->w * (size_t)g->h, i;
  if (run->use_cpu) {
    rd_image im = rd_image_new(g->w, g->h);
    double t0 = rd_cpu_ms();
    if (!im.rgb) return -1;
    for (i = 0; i < n; i++) {
      const float *p = g->pos + 3 * i, *nr = g->nrm + 3 * i;
      float v[3], l, c;
      int k;
      if (g->mat[i] < 0) continue;
      for (k = 0; k < 3; k++)
        v[k] = g->eye[k] - p[k];
      l = sqrtf(rd_dot(v, v));
      c = l > 0 ? rd_dot(nr, v) / l : 0.0f;
      for (k = 0; k < 3; k++)
        im.rgb[3 * i + (size_t)k] =
            run->scene->mats[g->mat[i]].kd[k] * (0.15f + 0.85f * (c > 0 ? c : 0.0f));
    }
    rd_emit(run, "preview", "headlight", "cpu", im, rd_cpu_ms() - t0, 0, 0);
  }
  if (run->use_gl) {
    rd_gl_pass p = {0};
    float *o = (float *)malloc(n * 4 * sizeof(float));
    rd_image im = rd_image_new(g->w, g->h);
    double ms = 0;
    if (!o || !im.rgb) {
      free(o);
      rd_image_free(&im);
      return -1;
    }
    p.body = body;
    p.nout = 1;
    if (rd_gl_run(run->scene, g, &p, &o, run->reps, &ms)) {
      free(o);
      rd_image_free(&im);
      return -1;
    }
    for (i = 0; i < n; i++) {
      im.rgb[3 * i] = o[4 * i];
      im.rgb[3 * i + 1] = o[4 * i + 1];
      im.rgb[3 * i + 2] = o[4 * i + 2];
    }
    free(o);
    rd_emit(run, "preview", "headlight", "gl", im, ms, 0, 1e-5);
  }
  return 0;
}
