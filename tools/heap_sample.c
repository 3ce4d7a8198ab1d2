// heap_sample: the live heap of a running program over time, beside its RSS, to tell memory the
// program holds from memory the allocator keeps (docs/hardening.md, "Roman's swing").
//
//   gcc -O2 -shared -fPIC -o /tmp/heap_sample.so tools/heap_sample.c -lpthread
//   LD_PRELOAD=/tmp/heap_sample.so HEAP_SAMPLE_OUT=heap.txt build/pseudoshadow run ...
//
// Preloaded, a thread of its own writes a line every 0.25 s: seconds since the start, then
// glibc's mallinfo2() in bytes - uordblks (allocated from the heaps), hblkhd (in blocks mapped
// of their own), arena (the heaps' size), fordblks (free inside the heaps) - and the RSS from
// /proc/self/statm. Without HEAP_SAMPLE_OUT it does nothing. For a window run by tools/soak.py,
// wrap the program in a script that sets both variables and `exec`s it (the pid stays the
// program's, which the soak finds its window by).
#define _GNU_SOURCE
#include <malloc.h>
#include <pthread.h>
#include <stdio.h>
#include <stdlib.h>
#include <time.h>
#include <unistd.h>

static void* sample(void* unused) {
  (void)unused;
  FILE* out = fopen(getenv("HEAP_SAMPLE_OUT"), "w");
  if (out == NULL) return NULL;
  struct timespec start;
  clock_gettime(CLOCK_MONOTONIC, &start);
  for (;;) {
    const struct mallinfo2 m = mallinfo2();
    long pages = 0, resident = 0;
    FILE* statm = fopen("/proc/self/statm", "r");
    if (statm != NULL) {
      if (fscanf(statm, "%ld %ld", &pages, &resident) != 2) resident = 0;
      fclose(statm);
    }
    struct timespec now;
    clock_gettime(CLOCK_MONOTONIC, &now);
    const double t = (double)(now.tv_sec - start.tv_sec) + 1e-9 * (double)(now.tv_nsec - start.tv_nsec);
    fprintf(out, "%.2f %zu %zu %zu %zu %ld\n", t, m.uordblks, m.hblkhd, m.arena, m.fordblks,
            resident * sysconf(_SC_PAGESIZE));
    fflush(out);
    usleep(250000);
  }
  return NULL;
}

__attribute__((constructor)) static void start_sampling(void) {
  if (getenv("HEAP_SAMPLE_OUT") == NULL) return;
  pthread_t thread;
  if (pthread_create(&thread, NULL, sample, NULL) == 0) pthread_detach(thread);
}
