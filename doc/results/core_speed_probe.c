// The speed of one core at each moment (doc/results/core_speed_probe.sh): the same chunk of work
// again and again for DURATION seconds, one line per chunk: the time since the start and the
// chunk's wall time [s]. A chunk updates 2^21 doubles (16 MB of loads and stores and a dependent
// sum) of an array of ARRAY_MB megabytes, continuing where the last chunk stopped: with 4 MB the
// array stays in the caches (about 5 ms per chunk on the AMD EPYC VM), with 256 MB every chunk
// streams from memory.
//   usage: core_speed_probe DURATION [ARRAY_MB]
#include <stdio.h>
#include <stdlib.h>
#include <time.h>

static double now(void)
{
  struct timespec t;
  clock_gettime(CLOCK_MONOTONIC, &t);
  return t.tv_sec + 1e-9 * t.tv_nsec;
}

int main(int argc, char** argv)
{
  const double duration = argc > 1 ? atof(argv[1]) : 60;
  const size_t n = (size_t)(argc > 2 ? atof(argv[2]) : 4) * ((size_t)1 << 20) / sizeof(double);
  const size_t chunk = (size_t)1 << 21;
  double* a = malloc(n * sizeof(double));
  if (a == NULL || n < 2)
  {
    fprintf(stderr, "core_speed_probe: cannot make an array of %zu doubles\n", n);
    return 1;
  }
  for (size_t i = 0; i < n; ++i)
    a[i] = i * 1e-9;
  double sum = 0;
  size_t i = 1;
  const double start = now();
  for (double last = start; last - start < duration;)
  {
    for (size_t k = 0; k < chunk; ++k, ++i)
    {
      if (i == n)
        i = 1;
      a[i] = 0.5 * a[i] + 0.25 * a[i - 1] + 1e-9;
      sum += a[i];
    }
    const double t = now();
    printf("%.6f %.6f\n", t - start, t - last);
    last = t;
  }
  fprintf(stderr, "checksum %g\n", sum); // keeps the loop from being optimised away
  free(a);
  return 0;
}
