/* rd_par.c - shlrender's CPU loops on several threads (rd_parallel, see rd.h). */
#define _DEFAULT_SOURCE /* MAP_ANONYMOUS */
#include "rd.h"

#include <pthread.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>
#include <sys/mman.h>
#include <sys/resource.h>
#include <sys/syscall.h>
#include <time.h>
#include <unistd.h>

int rd_threads(void) {
  const char *e = getenv("SHLIGHT_THREADS");
  long n = 0;
  if (e && *e) n = strtol(e, NULL, 10);
  if (n < 1) n = sysconf(_SC_NPROCESSORS_ONLN);
  return n < 1 ? 1 : n > RD_MAX_THREADS ? RD_MAX_THREADS : (int)n;
}

typedef struct gate_s gate_t;
static gate_t *gate;
#define RD_PAR_NICE 5 /* the rows' nice value above the pass processes' own (with the gate) */

typedef struct {
  pthread_mutex_t mu;
  long n, chunk, next;
  void (*fn)(void *ctx, long lo, long hi);
  void *ctx;
  const char *label;
  int bg; /* background work: each row's CPU time goes to rd_bg_add_cpu */
  double cpu[RD_MAX_THREADS];
} par_job;

typedef struct {
  par_job *job;
  int id, nice; /* nice: rd_thread_nice first */
} par_arg;

static void *par_worker(void *a) {
  par_job *j = ((par_arg *)a)->job;
  int id = ((par_arg *)a)->id;
  double t0;
  if (((par_arg *)a)->nice > 0) rd_thread_nice();
  t0 = rd_cpu_ms();
  for (;;) {
    long lo;
    pthread_mutex_lock(&j->mu);
    lo = j->next;
    j->next += j->chunk;
    pthread_mutex_unlock(&j->mu);
    if (lo >= j->n) break;
    rd_gate_enter(2);
    if (j->bg) {
      double c0 = rd_cpu_ms();
      j->fn(j->ctx, lo, lo + j->chunk < j->n ? lo + j->chunk : j->n);
      rd_bg_add_cpu(rd_cpu_ms() - c0);
    } else {
      j->fn(j->ctx, lo, lo + j->chunk < j->n ? lo + j->chunk : j->n);
    }
    rd_gate_leave(2);
    if (id == 0 && j->label)
      rd_progress(j->label, lo + j->chunk < j->n ? lo + j->chunk : j->n, j->n);
  }
  j->cpu[id] = rd_cpu_ms() - t0;
  return NULL;
}

void rd_thread_nice(void) {
  /* Linux: a thread's own nice value (PRIO_PROCESS with its thread id); elsewhere a no-op */
#if defined(SYS_gettid)
  id_t tid = (id_t)syscall(SYS_gettid);
  setpriority(PRIO_PROCESS, tid, getpriority(PRIO_PROCESS, tid) + RD_PAR_NICE);
#endif
}

int rd_bg_ok(void) {
  return gate != NULL;
}

int rd_bg_start(pthread_t *th, void *(*fn)(void *), void *arg, int *bg) {
  *bg = rd_bg_ok();
  if (*bg && pthread_create(th, NULL, fn, arg) == 0) return 1;
  *bg = 0;
  fn(arg);
  return 0;
}

int rd_use_avx(int compiled) {
  const char *e = getenv("SHLIGHT_RENDER_NO_AVX");
  if (!compiled || (e && *e && strcmp(e, "0") != 0)) return 0;
#if defined(__x86_64__) && defined(__GNUC__)
  return __builtin_cpu_supports("avx") ? 1 : 0;
#else
  return 0;
#endif
}

static double par_run(long n, long chunk, void (*fn)(void *ctx, long lo, long hi), void *ctx,
                      const char *label, int bg);
double rd_parallel(long n, long chunk, void (*fn)(void *ctx, long lo, long hi), void *ctx,
                   const char *label) {
  return par_run(n, chunk, fn, ctx, label, 0);
}
double rd_parallel_bg(long n, long chunk, void (*fn)(void *ctx, long lo, long hi), void *ctx,
                      const char *label) {
  return par_run(n, chunk, fn, ctx, label, 1);
}

static double par_run(long n, long chunk, void (*fn)(void *ctx, long lo, long hi), void *ctx,
                      const char *label, int bg) {
  par_job j;
  par_arg arg[RD_MAX_THREADS];
  pthread_t th[RD_MAX_THREADS];
  int nt = rd_threads(), k, started[RD_MAX_THREADS];
  double sum = 0.0;
  if (chunk < 1) chunk = 1;
  if ((n + chunk - 1) / chunk < nt) nt = (int)((n + chunk - 1) / chunk);
  if (nt < 1) nt = 1;
  j.n = n;
  j.chunk = chunk;
  j.next = 0;
  j.fn = fn;
  j.ctx = ctx;
  j.label = bg ? NULL : label; /* one progress bar at a time: the pass's own rows */
  j.bg = bg;
  pthread_mutex_init(&j.mu, NULL);
  /* Between the pass processes (the gate is shared) the rows run on threads of their own at a
     lower priority (nice + RD_PAR_NICE): the pieces that cannot be split (llvmpipe's JIT on one
     thread, the timed draws) go first, and the rows fill the CPUs around them, so that the
     processes end together. One process: the calling thread is worker 0, at its priority. */
  for (k = 0; k < nt; k++) {
    j.cpu[k] = 0.0;
    arg[k].job = &j;
    arg[k].id = k;
    arg[k].nice = gate != NULL;
    started[k] = (k > 0 || gate) && pthread_create(&th[k], NULL, par_worker, &arg[k]) == 0;
  }
  if (!started[0]) {
    arg[0].nice = 0;
    par_worker(&arg[0]); /* the calling thread; a thread that did not start is no loss */
  }
  for (k = 0; k < nt; k++)
    if (started[k]) pthread_join(th[k], NULL);
  pthread_mutex_destroy(&j.mu);
  for (k = 0; k < nt; k++)
    sum += j.cpu[k];
  return sum;
}

/* ---- the gate between the pass processes (rd_gate_* in rd.h) ------------------------------ */
struct gate_s {
  pthread_mutex_t mu;
  pthread_cond_t cv;
  int readers, writers_waiting, writer; /* shared sections, timed ones waiting, one running */
  char renderer[256];
};

int rd_gate_share(void) {
  pthread_mutexattr_t ma;
  pthread_condattr_t ca;
  gate_t *g;
  if (gate) return 0;
  g = (gate_t *)mmap(NULL, sizeof *g, PROT_READ | PROT_WRITE, MAP_SHARED | MAP_ANONYMOUS, -1, 0);
  if (g == MAP_FAILED) return -1;
  memset(g, 0, sizeof *g);
  if (pthread_mutexattr_init(&ma) || pthread_mutexattr_setpshared(&ma, PTHREAD_PROCESS_SHARED) ||
      pthread_mutex_init(&g->mu, &ma) || pthread_condattr_init(&ca) ||
      pthread_condattr_setpshared(&ca, PTHREAD_PROCESS_SHARED) || pthread_cond_init(&g->cv, &ca)) {
    munmap(g, sizeof *g);
    return -1;
  }
  pthread_mutexattr_destroy(&ma);
  pthread_condattr_destroy(&ca);
  gate = g;
  return 0;
}

void rd_gate_enter(int excl) {
  if (!gate) return;
  pthread_mutex_lock(&gate->mu);
  if (excl == 1) {
    gate->writers_waiting++;
    while (gate->writer || gate->readers > 0)
      pthread_cond_wait(&gate->cv, &gate->mu);
    gate->writers_waiting--;
    gate->writer = 1;
  } else {
    /* a timed section waits for the shared ones to end; new rows (excl 2) wait for it (a row is
       short), new compiles (excl 0) do not: the CPUs stay busy meanwhile */
    while (gate->writer || (excl == 2 && gate->writers_waiting > 0))
      pthread_cond_wait(&gate->cv, &gate->mu);
    gate->readers++;
  }
  pthread_mutex_unlock(&gate->mu);
}

void rd_gate_leave(int excl) {
  if (!gate) return;
  pthread_mutex_lock(&gate->mu);
  if (excl == 1)
    gate->writer = 0;
  else
    gate->readers--;
  pthread_cond_broadcast(&gate->cv);
  pthread_mutex_unlock(&gate->mu);
}

char *rd_gate_renderer(void) {
  return gate ? gate->renderer : NULL;
}
