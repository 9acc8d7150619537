/* fuzz_replay.c - replays a libFuzzer corpus through LLVMFuzzerTestOneInput without libFuzzer
 * (for CI and compilers without -fsanitize=fuzzer).  Link with tests/fuzz_basis.c:
 *   gcc -std=c99 -O2 -g -o build/tests/fuzz_replay tests/fuzz_replay.c tests/fuzz_basis.c -lm
 *   build/tests/fuzz_replay [dir-or-file ...]        (default: tests/corpus/basis)
 * Build it with -fsanitize=address,undefined to get the memory checks (see fuzz_basis.c).
 * Each input is one check; a failing input is reported and the replay goes on.
 * Ends with "N passed, N failed"; exit status 0 only when nothing failed. */
#define _POSIX_C_SOURCE 200809L
#include <dirent.h>
#include <stddef.h>
#include <stdint.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>
#include <sys/stat.h>

int LLVMFuzzerTestOneInput(const uint8_t *data, size_t size);
extern int fuzz_basis_soft_fail;
extern long fuzz_basis_failures;

static int g_passed, g_failed;

static void replay_file(const char *path) {
  FILE *f = fopen(path, "rb");
  uint8_t *data;
  long len;
  size_t got;
  long before = fuzz_basis_failures;
  if (!f) {
    printf("FAIL fuzz_replay: cannot open %s\n", path);
    g_failed++;
    return;
  }
  fseek(f, 0, SEEK_END);
  len = ftell(f);
  fseek(f, 0, SEEK_SET);
  if (len < 0) len = 0;
  data = (uint8_t *)malloc((size_t)len + 1);
  if (!data) abort();
  got = fread(data, 1, (size_t)len, f);
  fclose(f);
  LLVMFuzzerTestOneInput(data, got);
  free(data);
  if (fuzz_basis_failures != before) {
    printf("  ^ input %s\n", path);
    g_failed++;
  } else {
    g_passed++;
  }
}

static int cmp_str(const void *a, const void *b) {
  return strcmp(*(const char *const *)a, *(const char *const *)b);
}

static void replay_path(const char *path) {
  struct stat st;
  if (stat(path, &st) != 0) {
    printf("FAIL fuzz_replay: no such file or directory: %s\n", path);
    g_failed++;
    return;
  }
  if (S_ISDIR(st.st_mode)) {
    DIR *dir = opendir(path);
    struct dirent *e;
    char **names = NULL;
    size_t count = 0, cap = 0, i;
    if (!dir) {
      printf("FAIL fuzz_replay: cannot open directory %s\n", path);
      g_failed++;
      return;
    }
    while ((e = readdir(dir)) != NULL) {
      size_t len;
      char *full;
      struct stat fs;
      if (e->d_name[0] == '.') continue;
      len = strlen(path) + strlen(e->d_name) + 2;
      full = (char *)malloc(len);
      if (!full) abort();
      snprintf(full, len, "%s/%s", path, e->d_name);
      if (stat(full, &fs) != 0 || !S_ISREG(fs.st_mode)) {
        free(full);
        continue;
      }
      if (count == cap) {
        cap = cap ? 2 * cap : 64;
        names = (char **)realloc(names, cap * sizeof *names);
        if (!names) abort();
      }
      names[count++] = full;
    }
    closedir(dir);
    if (count) qsort(names, count, sizeof *names, cmp_str); /* deterministic order */
    for (i = 0; i < count; i++) {
      replay_file(names[i]);
      free(names[i]);
    }
    free(names);
  } else {
    replay_file(path);
  }
}

int main(int argc, char **argv) {
  int i;
  fuzz_basis_soft_fail = 1;
  setvbuf(stdout, NULL, _IOLBF, 0);
  if (argc < 2)
    replay_path("tests/corpus/basis");
  else
    for (i = 1; i < argc; i++)
      replay_path(argv[i]);
  if (g_passed + g_failed == 0) {
    printf("FAIL fuzz_replay: no input found\n");
    g_failed++;
  }
  printf("fuzz_replay: %d inputs replayed\n", g_passed + g_failed);
  printf("%d passed, %d failed\n", g_passed, g_failed);
  return g_failed ? 1 : 0;
}
