/* main.c - shlrender command line. See `shlrender --help`. Exit codes: 0 success, 1 a GL-vs-CPU
 * check failed (--check), 2 bad usage or scene file, 3 no GL context (GL paths requested),
 * 4 a pass failed. */
#include "rd.h"
#include "../shlight.h"

#include <stdio.h>
#include <stdlib.h>
#include <string.h>
#include <fcntl.h>
#include <sys/resource.h>
#include <sys/stat.h>
#include <sys/wait.h>
#include <unistd.h>

static void usage(FILE *f) {
  fprintf(f, "usage: shlrender [options]\n"
             "  --scene NAME|FILE   built-in cornell (default), spheres, manylights, glossy; or a\n"
             "                      scene file (text format: docs/renderer.md, render/rd_scene.c)\n"
             "  --pass LIST         comma-separated: grid, area, hvl, ssf, all (default all);\n"
             "                      preview (head-light G-buffer view)\n"
             "  --size WxH          image size (default 256x192)\n"
             "  --paths LIST        gl, cpu (default gl,cpu); gl alone skips the CPU path\n"
             "  --backend NAME      osmesa (default) or egl; the GL context\n"
             "  --gt N              ground truth: 0 none, 1 quick, 2 full (default 1)\n"
             "  --bands N           SH bands of the SH passes (default: the scene's, 5)\n"
             "  --brdf-bands N      bands of the BRDF SH tables of glossy materials in the grid\n"
             "                      pass (default 9; the product uses min(bands, N) bands)\n"
             "                      and the hvl pass (all N bands)\n"
             "  --brdf FILE[:MAT]   a measured BRDF in MERL's binary format (shl_merl_read) for\n"
             "                      the hvl pass's receivers of material MAT (default: every\n"
             "                      Phong / GGX material of the scene), through BRDF SH tables\n"
             "  --reps N            timed repetitions (median reported; default 1)\n"
             "  --out DIR           write PNGs to DIR (created; default: none)\n"
             "  --exposure X        PNG exposure (default: per pass, from the reference)\n"
             "  --check             exit 1 when a GL image differs from its CPU twin beyond the\n"
             "                      pass's tolerance; prints \"N passed, N failed\"\n"
             "  --timings           print where each pass's wall and CPU time went\n");
}

static int has(const char *list, const char *item) {
  size_t n = strlen(item);
  const char *p = list;
  while ((p = strstr(p, item)) != NULL) {
    if ((p == list || p[-1] == ',') && (p[n] == 0 || p[n] == ',')) return 1;
    p += n;
  }
  return 0;
}

/* one --timings line: a pass's wall and process CPU seconds, and their parts (wall/cpu s); the
   whole run's parts (cpu_only) are CPU s only: its passes' wall times overlap */
static void tm_line(const char *what, rd_tm t0, rd_tm t1, const rd_tm *p0, const rd_tm *p1,
                    int cpu_only) {
  static const char *part[RD_TM_N] = {"gl compile", "gl draws", "gl setup", "gt"};
  double wall = (t1.wall - t0.wall) * 1e-3, cpu = (t1.cpu - t0.cpu) * 1e-3, rw = wall, rc = cpu;
  int k;
  printf("timings: %-9s wall %6.2f s, cpu %6.2f s |", what, wall, cpu);
  for (k = 0; k < RD_TM_N; k++) {
    double w = (p1[k].wall - p0[k].wall) * 1e-3, c = (p1[k].cpu - p0[k].cpu) * 1e-3;
    if (cpu_only)
      printf(" %s %.2f", part[k], c);
    else
      printf(" %s %.2f/%.2f", part[k], w, c);
    rw -= w;
    rc -= c;
  }
  if (cpu_only)
    printf(" | the rest (cpu path, metrics, png) %.2f (cpu s)\n", rc);
  else
    printf(" | the rest (cpu path, metrics, png) %.2f/%.2f (wall/cpu s)\n", rw, rc);
}

static const char *const pass_names[5] = {"preview", "grid", "area", "hvl", "ssf"};
static int (*const pass_fn[5])(rd_run *) = {rd_pass_preview, rd_pass_grid, rd_pass_area,
                                            rd_pass_hvl, rd_pass_ssf};
static const char no_gl[] = "shlrender: no OpenGL 4.5 context (install Mesa: libosmesa6 or "
                            "libegl1 + libgl1-mesa-dri), or run with --paths cpu\n";

/* pass k (index into pass_names); 0 or 4 */
static int run_pass(rd_run *run, int k, int timings) {
  rd_tm p0[RD_TM_N], p1[RD_TM_N], t0, t1;
  int rc;
  rd_tm_get(p0);
  t0 = rd_tm_now();
  rc = pass_fn[k](run) ? 4 : 0;
  t1 = rd_tm_now();
  rd_tm_get(p1);
  if (timings) tm_line(pass_names[k], t0, t1, p0, p1, 0);
  return rc;
}

/* The passes sel[0..nsel-1] at the same time, one process each, each on its own GL context
   (llvmpipe's JIT runs on one thread: while one pass compiles, the others shade on the CPU; the
   gate of rd.h keeps every timed GL draw alone). Each process writes its output to a file and
   its results (images, timings) to another; the parent prints the outputs in pass order and
   takes the results over, so the run prints and reports what the passes run one after the
   other would. Returns 0, 3 (no GL context) or 4 (a pass failed). */
static int run_parallel(rd_run *run, const int *sel, int nsel, const char *backend, int timings,
                        int w, int h) {
  FILE *out[5] = {NULL}, *res[5] = {NULL};
  pid_t pid[5];
  int k, rc = 0, st, head = 0;
  char line[4096];
  fflush(stdout);
  fflush(stderr);
  for (k = 0; k < nsel; k++)
    pid[k] = -1;
  for (k = 0; k < nsel; k++) {
    out[k] = tmpfile();
    res[k] = tmpfile();
    if (!out[k] || !res[k]) {
      fprintf(stderr, "shlrender: cannot make a temporary file for the %s pass\n",
              pass_names[sel[k]]);
      rc = 4;
      break;
    }
    pid[k] = fork();
    if (pid[k] == 0) {
      int r;
      rd_tm parts[RD_TM_N];
      int err = -1, nul;
      if (dup2(fileno(out[k]), 1) < 0) _exit(4);
      if (k > 0 && (err = dup(2)) >= 0 && (nul = open("/dev/null", O_WRONLY)) >= 0) {
        dup2(nul, 2); /* a context that cannot be made is said once, by the first process */
        close(nul);
      }
      r = rd_gl_open(backend);
      if (err >= 0) {
        dup2(err, 2);
        close(err);
      }
      if (r != 0) _exit(3);
      if (k == 0) snprintf(rd_gate_renderer(), 256, "%s", rd_gl_renderer());
      r = run_pass(run, sel[k], timings);
      fflush(stdout);
      rd_tm_get(parts);
      if (rd_results_write(res[k], run) || fwrite(parts, sizeof parts, 1, res[k]) != 1 ||
          fflush(res[k]))
        r = 4;
      _exit(r);
    }
    if (pid[k] < 0) {
      fprintf(stderr, "shlrender: cannot start a process for the %s pass\n", pass_names[sel[k]]);
      rc = 4;
      break;
    }
  }
  for (k = 0; k < nsel; k++) {
    if (pid[k] > 0 && waitpid(pid[k], &st, 0) == pid[k]) {
      int code = WIFEXITED(st) ? WEXITSTATUS(st) : 4;
      rd_tm parts[RD_TM_N];
      if (code == 3) rc = 3;
      if (rc != 3 && out[k] && fseek(out[k], 0, SEEK_SET) == 0) {
        int first = 1;
        while (fgets(line, sizeof line, out[k])) {
          /* the first process's context line, then the run's header; the others' are dropped */
          if (first && !strncmp(line, "glctx: ", 7) && head) {
            first = 0;
            continue;
          }
          first = 0;
          fputs(line, stdout);
          if (!head) {
            const rd_scene *s = run->scene;
            head = 1;
            printf("shlrender: scene %s (%d triangles, %d spheres, %d lights), %dx%d, %d bands, "
                   "gl: %s\n",
                   s->name, s->ntris, s->nspheres, s->nlights, w, h, run->bands,
                   rd_gate_renderer());
          }
        }
      }
      if (code == 4) rc = rc ? rc : 4;
      if (rc != 3 && (fseek(res[k], 0, SEEK_SET) || rd_results_read(res[k], run) ||
                      fread(parts, sizeof parts, 1, res[k]) != 1)) {
        if (code == 0)
          fprintf(stderr, "shlrender: the %s pass's results are lost\n", pass_names[sel[k]]);
        rc = rc ? rc : 4;
      } else if (rc != 3) {
        rd_tm_merge(parts);
      }
    } else if (rc != 3) {
      rc = 4;
    }
    if (out[k]) fclose(out[k]);
    if (res[k]) fclose(res[k]);
  }
  if (rc == 3) fprintf(stderr, "%s", no_gl);
  fflush(stdout);
  return rc;
}

int main(int argc, char **argv) {
  const char *scene = "cornell", *passes = "all", *paths = "gl,cpu", *backend = NULL,
             *outdir = NULL, *brdf = NULL;
  int w = 256, h = 192, gt = 1, bands = 0, brdf_bands = 9, reps = 1, check = 0, i, rc = 0, fails,
      bad = 0, timings = 0, sel[5], nsel = 0, par;
  float exposure = 0;
  rd_tm t_run = rd_tm_now(), t_rep;
  shl_merl merl;
  float *merl_data = NULL;
  char merl_path[1024], *merl_mat = NULL;
  rd_scene s;
  rd_gbuf gb;
  rd_run run;
  char err[512];
  for (i = 1; i < argc; i++) {
    const char *a = argv[i], *v = i + 1 < argc ? argv[i + 1] : NULL;
    if (!strcmp(a, "--help") || !strcmp(a, "-h")) {
      usage(stdout);
      return 0;
    }
    if (!strcmp(a, "--check")) {
      check = 1;
      continue;
    }
    if (!strcmp(a, "--timings")) {
      timings = 1;
      continue;
    }
    if (!v) {
      fprintf(stderr, "shlrender: %s needs a value\n", a);
      usage(stderr);
      return 2;
    }
    i++;
    if (!strcmp(a, "--scene"))
      scene = v;
    else if (!strcmp(a, "--pass"))
      passes = v;
    else if (!strcmp(a, "--paths"))
      paths = v;
    else if (!strcmp(a, "--backend"))
      backend = v;
    else if (!strcmp(a, "--out"))
      outdir = v;
    else if (!strcmp(a, "--size"))
      bad = sscanf(v, "%dx%d", &w, &h) != 2 || w < 8 || h < 8 || w > 8192 || h > 8192;
    else if (!strcmp(a, "--gt"))
      bad = sscanf(v, "%d", &gt) != 1 || gt < 0 || gt > 2;
    else if (!strcmp(a, "--bands"))
      bad = sscanf(v, "%d", &bands) != 1 || bands < 1 || bands > 16;
    else if (!strcmp(a, "--brdf-bands"))
      bad = sscanf(v, "%d", &brdf_bands) != 1 || brdf_bands < 1 || brdf_bands > 16;
    else if (!strcmp(a, "--brdf"))
      brdf = v;
    else if (!strcmp(a, "--reps"))
      bad = sscanf(v, "%d", &reps) != 1 || reps < 1 || reps > 1000;
    else if (!strcmp(a, "--exposure"))
      bad = sscanf(v, "%f", &exposure) != 1 || !(exposure > 0);
    else {
      fprintf(stderr, "shlrender: unknown option %s\n", a);
      usage(stderr);
      return 2;
    }
    if (bad) {
      fprintf(stderr, "shlrender: bad value for %s: '%s'\n", a, v);
      return 2;
    }
  }
  if (!has("grid,area,hvl,ssf,preview,all", passes) && strcmp(passes, "all")) {
    /* every listed pass must be known */
    char buf[256], *tk;
    snprintf(buf, sizeof buf, "%s", passes);
    for (tk = strtok(buf, ","); tk; tk = strtok(NULL, ","))
      if (!has("grid,area,hvl,ssf,preview,all", tk)) {
        fprintf(stderr, "shlrender: unknown pass '%s' (grid, area, hvl, ssf, preview, all)\n", tk);
        return 2;
      }
  }
  memset(&merl, 0, sizeof merl);
  if (brdf) {
    /* FILE[:MAT]: the last ':' splits off a material name when what follows has no '/' */
    FILE *f;
    unsigned char *buf = NULL;
    long len = -1;
    shl_result r = SHLIGHT_EINVAL;
    char *col;
    snprintf(merl_path, sizeof merl_path, "%s", brdf);
    col = strrchr(merl_path, ':');
    if (col && !strchr(col, '/')) {
      *col = 0;
      merl_mat = col + 1;
    }
    f = fopen(merl_path, "rb");
    if (f && fseek(f, 0, SEEK_END) == 0) len = ftell(f);
    if (f && len > 0 && fseek(f, 0, SEEK_SET) == 0) buf = (unsigned char *)malloc((size_t)len);
    if (buf && fread(buf, 1, (size_t)len, f) == (size_t)len) {
      r = shl_merl_read(buf, (size_t)len, NULL, 0, &merl);
      if (r == SHLIGHT_ESTORAGE) {
        size_t nf = 3 * (size_t)merl.n_theta_h * (size_t)merl.n_theta_d * (size_t)merl.n_phi_d;
        merl_data = (float *)malloc(nf * sizeof(float));
        r = merl_data ? shl_merl_read(buf, (size_t)len, merl_data, nf, &merl) : SHLIGHT_ENOMEM;
      }
    }
    if (f) fclose(f);
    if (r != SHLIGHT_OK) {
      fprintf(stderr, "shlrender: cannot read the MERL BRDF %s (%s)\n", merl_path,
              buf == NULL ? "cannot read the file" : "shl_merl_read failed");
      free(buf);
      free(merl_data);
      return 2;
    }
    free(buf);
  }
  if (rd_scene_builtin(scene, &s) != 0) {
    if (!strchr(scene, '.') && !strchr(scene, '/')) {
      fprintf(stderr,
              "shlrender: unknown scene '%s' (cornell, spheres, manylights, glossy, or "
              "a file)\n",
              scene);
      return 2;
    }
    if (rd_scene_load(scene, &s, err, sizeof err) != 0) {
      fprintf(stderr, "shlrender: %s\n", err);
      return 2;
    }
  }
  if (outdir) {
    struct stat st;
    if (stat(outdir, &st) != 0 && mkdir(outdir, 0777) != 0) {
      fprintf(stderr, "shlrender: cannot create %s\n", outdir);
      rd_scene_free(&s);
      return 2;
    }
  }
  memset(&run, 0, sizeof run);
  run.scene = &s;
  run.use_gl = has(paths, "gl");
  run.use_cpu = has(paths, "cpu");
  run.gt = gt;
  run.bands = bands ? bands : s.bands;
  run.brdf_bands = brdf_bands;
  run.merl = brdf ? &merl : NULL;
  run.merl_mat = merl_mat;
  run.reps = reps;
  run.outdir = outdir;
  run.exposure = exposure;
  for (i = 0; i < 5; i++)
    if (has(passes, pass_names[i]) || (i > 0 && has(passes, "all"))) sel[nsel++] = i;
  /* with GL, two or more passes and two or more CPUs, each pass runs in a process of its own */
  par = run.use_gl && nsel > 1 && rd_threads() > 1 && rd_gate_share() == 0;
  if (run.use_gl && !par && rd_gl_open(backend) != 0) {
    fprintf(stderr, "%s", no_gl);
    rd_scene_free(&s);
    return 3;
  }
  if (rd_gbuffer(&s, w, h, &gb) != 0) {
    fprintf(stderr, "shlrender: out of memory for a %dx%d G-buffer\n", w, h);
    rd_scene_free(&s);
    return 4;
  }
  run.gb = &gb;
  if (par) {
    rc = run_parallel(&run, sel, nsel, backend, timings, w, h);
    if (rc == 3) {
      rd_run_free(&run);
      rd_gbuf_free(&gb);
      rd_scene_free(&s);
      free(merl_data);
      return 3;
    }
  } else {
    printf("shlrender: scene %s (%d triangles, %d spheres, %d lights), %dx%d, %d bands, gl: %s\n",
           s.name, s.ntris, s.nspheres, s.nlights, w, h, run.bands,
           run.use_gl ? rd_gl_renderer() : "off");
    for (i = 0; i < nsel; i++)
      if (run_pass(&run, sel[i], timings)) rc = 4;
  }
  t_rep = rd_tm_now();
  fails = rd_report(&run, 1);
  if (timings) {
    rd_tm t1 = rd_tm_now();
    printf("timings: report (checks, metrics, PNGs) wall %.2f s, cpu %.2f s\n",
           (t1.wall - t_rep.wall) * 1e-3, (t1.cpu - t_rep.cpu) * 1e-3);
  }
  if (check) {
    /* one check per (pass, method) with both a GL and a CPU image; a failed pass is one more */
    int total = rd_report_checks(&run);
    printf("%d passed, %d failed\n", total - fails, fails + (rc == 4));
    if (!rc && fails) rc = 1;
  }
  rd_run_free(&run);
  rd_gbuf_free(&gb);
  rd_scene_free(&s);
  free(merl_data);
  if (run.use_gl && !par) rd_gl_close();
  if (timings) {
    rd_tm z[RD_TM_N], p1[RD_TM_N], t1 = rd_tm_now();
    struct rusage ru;
    memset(z, 0, sizeof z);
    rd_tm_get(p1);
    if (getrusage(RUSAGE_CHILDREN, &ru) == 0) /* the pass processes' CPU time */
      t1.cpu += (double)(ru.ru_utime.tv_sec + ru.ru_stime.tv_sec) * 1e3 +
                (double)(ru.ru_utime.tv_usec + ru.ru_stime.tv_usec) * 1e-3;
    tm_line("whole run", t_run, t1, z, p1, 1);
  }
  return rc;
}
