/* rd_core.c - shlrender core: images, PNG writer, metrics, progress bar, results table. */
#include "rd.h"

#include <math.h>
#include <pthread.h>
#include <stdint.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>
#include <time.h>
#include <unistd.h>

rd_image rd_image_new(int w, int h) {
  rd_image im;
  im.w = w;
  im.h = h;
  im.rgb = (w > 0 && h > 0) ? (float *)calloc((size_t)w * (size_t)h * 3, sizeof(float)) : NULL;
  return im;
}

void rd_image_free(rd_image *im) {
  free(im->rgb);
  im->rgb = NULL;
}

double rd_cpu_ms(void) {
  struct timespec ts;
  clock_gettime(CLOCK_THREAD_CPUTIME_ID, &ts);
  return (double)ts.tv_sec * 1e3 + (double)ts.tv_nsec * 1e-6;
}

static rd_tm tm_sum[RD_TM_N];
static pthread_mutex_t bg_mu = PTHREAD_MUTEX_INITIALIZER;
static double bg_cpu; /* ms, rd_bg_add_cpu */
void rd_bg_add_cpu(double ms) {
  pthread_mutex_lock(&bg_mu);
  bg_cpu += ms;
  pthread_mutex_unlock(&bg_mu);
}
rd_tm rd_tm_now(void) {
  struct timespec ts;
  rd_tm t;
  clock_gettime(CLOCK_MONOTONIC, &ts);
  t.wall = (double)ts.tv_sec * 1e3 + (double)ts.tv_nsec * 1e-6;
  clock_gettime(CLOCK_PROCESS_CPUTIME_ID, &ts);
  t.cpu = (double)ts.tv_sec * 1e3 + (double)ts.tv_nsec * 1e-6;
  pthread_mutex_lock(&bg_mu);
  t.bg = bg_cpu;
  pthread_mutex_unlock(&bg_mu);
  return t;
}
rd_tm rd_tm_add(int part, rd_tm t0) {
  rd_tm t = rd_tm_now();
  if (part >= 0 && part < RD_TM_N) {
    tm_sum[part].wall += t.wall - t0.wall;
    tm_sum[part].cpu += (t.cpu - t.bg) - (t0.cpu - t0.bg);
  }
  return t;
}
void rd_tm_add_ms(int part, double wall_ms, double cpu_ms) {
  if (part >= 0 && part < RD_TM_N) {
    tm_sum[part].wall += wall_ms;
    tm_sum[part].cpu += cpu_ms;
  }
}
void rd_tm_get(rd_tm *out) {
  memcpy(out, tm_sum, sizeof tm_sum);
}

/* ---- PNG: 8-bit RGB, zlib stream of stored (uncompressed) deflate blocks ---------------- */
static uint32_t crc_table[256];
static void crc_init(void) {
  uint32_t n, c;
  int k;
  if (crc_table[1]) return;
  for (n = 0; n < 256; n++) {
    c = n;
    for (k = 0; k < 8; k++)
      c = (c & 1) ? 0xedb88320u ^ (c >> 1) : c >> 1;
    crc_table[n] = c;
  }
}
static uint32_t crc_update(uint32_t c, const unsigned char *p, size_t n) {
  size_t i;
  for (i = 0; i < n; i++)
    c = crc_table[(c ^ p[i]) & 0xff] ^ (c >> 8);
  return c;
}
static void put32(unsigned char *p, uint32_t v) {
  p[0] = (unsigned char)(v >> 24);
  p[1] = (unsigned char)(v >> 16);
  p[2] = (unsigned char)(v >> 8);
  p[3] = (unsigned char)v;
}
static int write_chunk(FILE *f, const char *type, const unsigned char *data, size_t n) {
  unsigned char hdr[8], tail[4];
  uint32_t c;
  put32(hdr, (uint32_t)n);
  memcpy(hdr + 4, type, 4);
  c = crc_update(0xffffffffu, hdr + 4, 4);
  c = crc_update(c, data, n) ^ 0xffffffffu;
  put32(tail, c);
  return (fwrite(hdr, 1, 8, f) == 8 && (n == 0 || fwrite(data, 1, n, f) == n) &&
          fwrite(tail, 1, 4, f) == 4)
             ? 0
             : -1;
}

static float srgb(float v) {
  if (!(v > 0.0f)) return 0.0f;
  if (v >= 1.0f) return 1.0f;
  return v <= 0.0031308f ? 12.92f * v : 1.055f * powf(v, 1.0f / 2.4f) - 0.055f;
}

int rd_png_write(const char *path, const rd_image *im, float exposure) {
  size_t row = (size_t)im->w * 3 + 1, raw_n = row * (size_t)im->h;
  size_t nblk = (raw_n + 65534) / 65535, z_n = 2 + raw_n + 5 * nblk + 4, i, o = 0;
  unsigned char *raw, *z, ihdr[13];
  uint32_t a = 1, b = 0;
  FILE *f;
  int x, y, rc;
  static const unsigned char sig[8] = {137, 80, 78, 71, 13, 10, 26, 10};
  if (im->w <= 0 || im->h <= 0 || !im->rgb) return -1;
  crc_init();
  raw = (unsigned char *)malloc(raw_n);
  z = (unsigned char *)malloc(z_n);
  if (!raw || !z) {
    free(raw);
    free(z);
    return -1;
  }
  for (y = 0; y < im->h; y++) {
    unsigned char *r = raw + (size_t)y * row;
    r[0] = 0; /* filter: none */
    for (x = 0; x < im->w * 3; x++)
      r[1 + x] = (unsigned char)lrintf(
          255.0f * srgb(exposure * im->rgb[(size_t)y * (size_t)im->w * 3 + (size_t)x]));
  }
  z[o++] = 0x78;
  z[o++] = 0x01;
  for (i = 0; i < raw_n; i += 65535) {
    size_t n = raw_n - i < 65535 ? raw_n - i : 65535;
    z[o++] = (unsigned char)(i + n == raw_n);
    z[o++] = (unsigned char)(n & 0xff);
    z[o++] = (unsigned char)(n >> 8);
    z[o++] = (unsigned char)(~n & 0xff);
    z[o++] = (unsigned char)((~n >> 8) & 0xff);
    memcpy(z + o, raw + i, n);
    o += n;
  }
  for (i = 0; i < raw_n; i++) {
    a = (a + raw[i]) % 65521u;
    b = (b + a) % 65521u;
  }
  put32(z + o, (b << 16) | a);
  o += 4;
  put32(ihdr, (uint32_t)im->w);
  put32(ihdr + 4, (uint32_t)im->h);
  ihdr[8] = 8;  /* bit depth */
  ihdr[9] = 2;  /* RGB */
  ihdr[10] = 0; /* deflate */
  ihdr[11] = 0;
  ihdr[12] = 0;
  f = fopen(path, "wb");
  rc = -1;
  if (f) {
    rc = (fwrite(sig, 1, 8, f) == 8 && write_chunk(f, "IHDR", ihdr, 13) == 0 &&
          write_chunk(f, "IDAT", z, o) == 0 && write_chunk(f, "IEND", NULL, 0) == 0)
             ? 0
             : -1;
    if (fclose(f) != 0) rc = -1;
  }
  if (rc) fprintf(stderr, "shlrender: cannot write %s\n", path);
  free(raw);
  free(z);
  return rc;
}

/* ---- metrics ----------------------------------------------------------------------------- */
static double lum(const float *p) {
  return 0.2126 * p[0] + 0.7152 * p[1] + 0.0722 * p[2];
}

rd_metrics rd_compare(const rd_image *a, const rd_image *ref, const int *mask) {
  rd_metrics m;
  size_t n = (size_t)ref->w * (size_t)ref->h, i, cnt = 0;
  double se = 0, peak = 0, maxd = 0, ssum = 0;
  int x, y, nw = 0;
  memset(&m, 0, sizeof m);
  if (!a->rgb || !ref->rgb || a->w != ref->w || a->h != ref->h) {
    m.rmse = m.maxrel = NAN;
    return m;
  }
  for (i = 0; i < n; i++) {
    int c;
    if (mask && mask[i] < 0) continue;
    for (c = 0; c < 3; c++) {
      double d = (double)a->rgb[3 * i + (size_t)c] - (double)ref->rgb[3 * i + (size_t)c];
      if (!(fabs(d) <= maxd)) maxd = isnan(d) ? INFINITY : fabs(d);
      se += d * d;
      if (ref->rgb[3 * i + (size_t)c] > peak) peak = ref->rgb[3 * i + (size_t)c];
    }
    cnt++;
  }
  if (!cnt) return m;
  m.rmse = sqrt(se / (3.0 * (double)cnt));
  m.psnr = m.rmse > 0 && peak > 0 ? 20.0 * log10(peak / m.rmse) : INFINITY;
  m.maxrel = peak > 0 ? maxd / peak : maxd;
  /* SSIM of the tone-mapped luminance (exposure: peak -> 1), 8x8 windows, stride 4 */
  {
    const double c1 = 0.01 * 0.01, c2 = 0.03 * 0.03, sc = peak > 0 ? 1.0 / peak : 1.0;
    for (y = 0; y + 8 <= ref->h; y += 4)
      for (x = 0; x + 8 <= ref->w; x += 4) {
        double sa = 0, sb = 0, saa = 0, sbb = 0, sab = 0, k = 64, ma, mb, va, vb, cv;
        int u, v, inmask = 0;
        for (v = 0; v < 8; v++)
          for (u = 0; u < 8; u++) {
            size_t j = (size_t)(y + v) * (size_t)ref->w + (size_t)(x + u);
            double pa = pow(fmin(1.0, fmax(0.0, lum(a->rgb + 3 * j) * sc)), 1.0 / 2.2);
            double pb = pow(fmin(1.0, fmax(0.0, lum(ref->rgb + 3 * j) * sc)), 1.0 / 2.2);
            if (!mask || mask[j] >= 0) inmask++;
            sa += pa;
            sb += pb;
            saa += pa * pa;
            sbb += pb * pb;
            sab += pa * pb;
          }
        if (inmask < 32) continue;
        ma = sa / k;
        mb = sb / k;
        va = saa / k - ma * ma;
        vb = sbb / k - mb * mb;
        cv = sab / k - ma * mb;
        ssum += ((2 * ma * mb + c1) * (2 * cv + c2)) / ((ma * ma + mb * mb + c1) * (va + vb + c2));
        nw++;
      }
    m.ssim = nw ? ssum / nw : NAN;
  }
  return m;
}

double rd_relrmse(const rd_gbuf *gb, const rd_image *a, const rd_image *ref, int mat) {
  size_t q, np = (size_t)gb->w * (size_t)gb->h;
  double se = 0.0, ss = 0.0;
  int c;
  for (q = 0; q < np; q++) {
    if (gb->mat[q] < 0 || (mat >= 0 && gb->mat[q] != mat)) continue;
    for (c = 0; c < 3; c++) {
      double r = (double)ref->rgb[3 * q + (size_t)c], d = (double)a->rgb[3 * q + (size_t)c] - r;
      se += d * d;
      ss += r * r;
    }
  }
  return ss > 0.0 ? sqrt(se / ss) : 0.0;
}

void rd_progress(const char *label, long done, long total) {
  static int on = -1;
  int width = 40, k;
  if (on < 0) {
    const char *e = getenv("SHLIGHT_PROGRESS");
    on = e ? atoi(e) != 0 : isatty(2);
  }
  if (!on || total <= 0) return;
  k = (int)((double)width * (double)done / (double)total);
  if (k > width) k = width;
  fprintf(stderr, "\r%-18.18s [", label);
  for (int i = 0; i < width; i++)
    fputc(i < k ? '#' : '.', stderr);
  fprintf(stderr, "] %3d%%", (int)(100.0 * (double)done / (double)total));
  if (done >= total) fprintf(stderr, "\n");
  fflush(stderr);
}

/* ---- results ------------------------------------------------------------------------------ */
struct rd_result {
  char pass[16], method[40], path[8];
  rd_image img;
  double ms, tol, tol_sel;
  size_t mem;
  int *sel; /* rd_emit_sel: per-material flags (owned), nsel of them; NULL: none */
  int nsel;
  char sel_name[16];
};

void rd_emit(rd_run *run, const char *pass, const char *method, const char *path, rd_image img,
             double ms, size_t mem, double tol) {
  rd_result *r;
  if (run->nres == run->capres) {
    int cap = run->capres ? 2 * run->capres : 32;
    rd_result *n = (rd_result *)realloc(run->res, (size_t)cap * sizeof *n);
    if (!n) {
      rd_image_free(&img);
      return;
    }
    run->res = n;
    run->capres = cap;
  }
  r = &run->res[run->nres++];
  memset(r, 0, sizeof *r);
  snprintf(r->pass, sizeof r->pass, "%s", pass);
  snprintf(r->method, sizeof r->method, "%s", method);
  snprintf(r->path, sizeof r->path, "%s", path);
  r->img = img;
  r->ms = ms;
  r->mem = mem;
  r->tol = tol;
}

void rd_emit_sel(rd_run *run, const char *pass, const char *method, const char *path, rd_image img,
                 double ms, size_t mem, double tol, const int *sel, int nsel, double tol_sel,
                 const char *sel_name) {
  int *cp = NULL, n0 = run->nres;
  if (sel && nsel > 0) {
    cp = (int *)malloc((size_t)nsel * sizeof *cp);
    if (cp) memcpy(cp, sel, (size_t)nsel * sizeof *cp);
  }
  rd_emit(run, pass, method, path, img, ms, mem, tol);
  if (run->nres == n0 + 1 && cp) {
    run->res[n0].sel = cp;
    run->res[n0].nsel = nsel;
    run->res[n0].tol_sel = tol_sel;
    snprintf(run->res[n0].sel_name, sizeof run->res[n0].sel_name, "%s", sel_name);
  } else {
    free(cp);
  }
}

/* max |a - ref| over the surface pixels (mask >= 0; mask NULL: all) whose material is selected
   by sel (want 1) or not (want 0), divided by the peak of ref over every surface pixel */
static double maxrel_sel(const rd_image *a, const rd_image *ref, const int *mask, const int *sel,
                         int nsel, int want) {
  size_t n = (size_t)ref->w * (size_t)ref->h, i;
  double peak = 0, maxd = 0;
  for (i = 0; i < n; i++) {
    int c, m = mask ? mask[i] : -1, s;
    if (mask && m < 0) continue;
    s = m >= 0 && m < nsel && sel[m] != 0;
    for (c = 0; c < 3; c++) {
      double d = (double)a->rgb[3 * i + (size_t)c] - (double)ref->rgb[3 * i + (size_t)c];
      if (ref->rgb[3 * i + (size_t)c] > peak) peak = ref->rgb[3 * i + (size_t)c];
      if (s == want && !(fabs(d) <= maxd)) maxd = isnan(d) ? INFINITY : fabs(d);
    }
  }
  return peak > 0 ? maxd / peak : maxd;
}

static const rd_result *find(const rd_run *run, const char *pass, const char *method,
                             const char *path) {
  int i;
  for (i = 0; i < run->nres; i++)
    if (!strcmp(run->res[i].pass, pass) && !strcmp(run->res[i].method, method) &&
        !strcmp(run->res[i].path, path))
      return &run->res[i];
  return NULL;
}

static const rd_result *reference(const rd_run *run, const char *pass, const char *method) {
  char m[48];
  const rd_result *r;
  snprintf(m, sizeof m, "gt:%s", method);
  r = find(run, pass, m, "gt");
  return r ? r : find(run, pass, "gt", "gt");
}

/* Exposure of a pass: the 99th percentile of the reference's luminance maps to 0.85. */
static float pass_exposure(const rd_run *run, const rd_result *ref) {
  size_t n = (size_t)ref->img.w * (size_t)ref->img.h, i, k = 0;
  float *l, e = 1.0f;
  if (run->exposure > 0) return run->exposure;
  l = (float *)malloc(n * sizeof *l);
  if (!l) return 1.0f;
  for (i = 0; i < n; i++)
    if (!run->gb || run->gb->mat[i] >= 0) l[k++] = (float)lum(ref->img.rgb + 3 * i);
  if (k) {
    /* partial selection is overkill here: sort */
    size_t a, b;
    for (a = 1; a < k; a++) { /* insertion sort on a sample of at most 4096 values */
      if (a >= 4096) break;
      float v = l[a];
      for (b = a; b > 0 && l[b - 1] > v; b--)
        l[b] = l[b - 1];
      l[b] = v;
    }
    {
      size_t m = k < 4096 ? k : 4096;
      float p = l[(size_t)(0.99 * (double)(m - 1))];
      if (p > 0) e = 0.85f / p;
    }
  }
  free(l);
  return e;
}

int rd_report(rd_run *run, int markdown) {
  int i, j, fails = 0;
  const int *mask = run->gb ? run->gb->mat : NULL;
  (void)markdown;
  printf("\n| scene | pass | method | cpu ms | gl ms | memory KiB | gl vs cpu (max/peak) | tol "
         "| RMSE vs gt | PSNR dB | SSIM |\n");
  printf("|---|---|---|---:|---:|---:|---:|---:|---:|---:|---:|\n");
  for (i = 0; i < run->nres; i++) {
    const rd_result *r = &run->res[i], *cpu, *gl, *ref, *first;
    rd_metrics me;
    char glc[48] = "-", err[64] = "-", ps[32] = "-", ss[32] = "-", cms[32] = "-", gms[32] = "-",
         tl[32] = "-";
    int dup = 0;
    for (j = 0; j < i; j++)
      if (!strcmp(run->res[j].pass, r->pass) && !strcmp(run->res[j].method, r->method)) dup = 1;
    if (dup || !strcmp(r->path, "gt")) continue;
    cpu = find(run, r->pass, r->method, "cpu");
    gl = find(run, r->pass, r->method, "gl");
    ref = reference(run, r->pass, r->method);
    first = cpu ? cpu : gl;
    if (cpu) snprintf(cms, sizeof cms, "%.2f", cpu->ms);
    if (gl) {
      snprintf(gms, sizeof gms, "%.2f", gl->ms);
      snprintf(tl, sizeof tl, "%.0e", gl->tol);
    }
    if (cpu && gl) {
      me = rd_compare(&gl->img, &cpu->img, mask);
      if (gl->sel && me.maxrel == me.maxrel) {
        /* the selected materials' pixels against tol_sel, the others against tol */
        double m0 = maxrel_sel(&gl->img, &cpu->img, mask, gl->sel, gl->nsel, 0);
        double m1 = maxrel_sel(&gl->img, &cpu->img, mask, gl->sel, gl->nsel, 1);
        int ok = m0 <= gl->tol && m1 <= gl->tol_sel;
        if (!ok) fails++;
        printf("check %s/%s gl vs cpu: max |gl - cpu|/peak = %.3g (tol %.3g), on the %s pixels "
               "%.3g (tol %.3g): %s\n",
               r->pass, r->method, m0, gl->tol, gl->sel_name, m1, gl->tol_sel, ok ? "ok" : "FAIL");
        snprintf(glc, sizeof glc, "%.2e/%.2e%s", m0, m1, ok ? "" : " FAIL");
        snprintf(tl, sizeof tl, "%.0e/%.0e", gl->tol, gl->tol_sel);
      } else {
        int ok = me.maxrel <= gl->tol;
        if (!ok) fails++;
        printf("check %s/%s gl vs cpu: max |gl - cpu|/peak = %.3g (tol %.3g): %s\n", r->pass,
               r->method, me.maxrel, gl->tol, ok ? "ok" : "FAIL");
        snprintf(glc, sizeof glc, "%.2e%s", me.maxrel, ok ? "" : " FAIL");
      }
    }
    if (ref && first) {
      me = rd_compare(&first->img, &ref->img, mask);
      snprintf(err, sizeof err, "%.3g", me.rmse);
      snprintf(ps, sizeof ps, "%.1f", me.psnr);
      snprintf(ss, sizeof ss, "%.4f", me.ssim);
    }
    printf("| %s | %s | %s | %s | %s | %.0f | %s | %s | %s | %s | %s |\n", run->scene->name,
           r->pass, r->method, cms, gms, (double)first->mem / 1024.0, glc, tl, err, ps, ss);
  }
  if (run->outdir) {
    for (i = 0; i < run->nres; i++) {
      const rd_result *r = &run->res[i], *ref = reference(run, r->pass, r->method);
      char path[1024];
      float e = pass_exposure(run, ref ? ref : r);
      snprintf(path, sizeof path, "%s/%s_%s_%s_%s.png", run->outdir, run->scene->name, r->pass,
               r->method, r->path);
      for (j = 0; path[j]; j++)
        if (path[j] == ':') path[j] = '-';
      rd_png_write(path, &r->img, e);
    }
  }
  return fails;
}

int rd_results_write(FILE *f, const rd_run *run) {
  int i;
  if (fwrite(&run->nres, sizeof run->nres, 1, f) != 1) return -1;
  for (i = 0; i < run->nres; i++) {
    const rd_result *r = &run->res[i];
    size_t n = r->img.rgb ? (size_t)r->img.w * (size_t)r->img.h * 3 : 0;
    if (fwrite(r, sizeof *r, 1, f) != 1 || fwrite(r->img.rgb, sizeof(float), n, f) != n ||
        (r->sel && fwrite(r->sel, sizeof(int), (size_t)r->nsel, f) != (size_t)r->nsel))
      return -1;
  }
  return fflush(f) ? -1 : 0;
}

int rd_results_read(FILE *f, rd_run *run) {
  int i, n;
  if (fread(&n, sizeof n, 1, f) != 1 || n < 0) return -1;
  for (i = 0; i < n; i++) {
    rd_result r;
    size_t np;
    int *sel = NULL;
    if (fread(&r, sizeof r, 1, f) != 1) return -1;
    np = r.img.rgb ? (size_t)r.img.w * (size_t)r.img.h * 3 : 0;
    r.img.rgb = np ? (float *)malloc(np * sizeof(float)) : NULL;
    if (np && (!r.img.rgb || fread(r.img.rgb, sizeof(float), np, f) != np)) {
      free(r.img.rgb);
      return -1;
    }
    if (r.sel) {
      sel = r.nsel > 0 ? (int *)malloc((size_t)r.nsel * sizeof(int)) : NULL;
      if (!sel || fread(sel, sizeof(int), (size_t)r.nsel, f) != (size_t)r.nsel) {
        free(sel);
        free(r.img.rgb);
        return -1;
      }
    }
    if (sel)
      rd_emit_sel(run, r.pass, r.method, r.path, r.img, r.ms, r.mem, r.tol, sel, r.nsel, r.tol_sel,
                  r.sel_name);
    else
      rd_emit(run, r.pass, r.method, r.path, r.img, r.ms, r.mem, r.tol);
    free(sel);
  }
  return 0;
}

void rd_tm_merge(const rd_tm *parts) {
  int k;
  for (k = 0; k < RD_TM_N; k++) {
    tm_sum[k].wall += parts[k].wall;
    tm_sum[k].cpu += parts[k].cpu;
  }
}

int rd_report_checks(const rd_run *run) {
  int i, n = 0;
  for (i = 0; i < run->nres; i++)
    if (!strcmp(run->res[i].path, "gl") && find(run, run->res[i].pass, run->res[i].method, "cpu") &&
        find(run, run->res[i].pass, run->res[i].method, "gl") == &run->res[i])
      n++;
  return n;
}

void rd_run_free(rd_run *run) {
  int i;
  for (i = 0; i < run->nres; i++) {
    rd_image_free(&run->res[i].img);
    free(run->res[i].sel);
  }
  free(run->res);
  run->res = NULL;
  run->nres = run->capres = 0;
}

/* orthonormal frame (t, b) about the unit normal z (Duff et al. 2017, "Building an orthonormal
   basis, revisited"), in float, the same operations as the GLSL twins in the passes' shaders */
void rd_frame(const float z[3], float t[3], float b[3]) {
  float sg = z[2] >= 0.0f ? 1.0f : -1.0f, a = -1.0f / (sg + z[2]), c = z[0] * z[1] * a;
  t[0] = 1.0f + sg * z[0] * z[0] * a;
  t[1] = sg * c;
  t[2] = -sg * z[0];
  b[0] = c;
  b[1] = sg + z[1] * z[1] * a;
  b[2] = -z[1];
}
