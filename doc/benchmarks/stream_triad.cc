// The memory bandwidth one core reaches, as McCalpin's STREAM measures it (triad a = b + s c on
// arrays far larger than the caches; 24 bytes counted per element, write-allocate not counted):
// the bound of performance.md's roofline line for the pressure solve, whose CG + AMG iterations
// stream their matrices and vectors from memory. Plain C++, one thread; best of REPEATS passes.
//
//   build: g++ -O3 -march=native -o stream_triad doc/benchmarks/stream_triad.cc
//   usage: stream_triad [MILLION_ELEMENTS=20 [REPEATS=20]]
#include <algorithm>
#include <chrono>
#include <cstdio>
#include <cstdlib>
#include <vector>

int main(int argc, char** argv)
{
  const std::size_t n = (argc > 1 ? std::atof(argv[1]) : 20.0) * 1e6;
  const int repeats = argc > 2 ? std::atoi(argv[2]) : 20;
  std::vector<double> a(n, 1.0), b(n, 2.0), c(n, 0.5);
  double best_triad = 1e30, best_copy = 1e30;
  for (int r = 0; r < repeats; ++r)
  {
    auto t0 = std::chrono::steady_clock::now();
    for (std::size_t i = 0; i < n; ++i)
      a[i] = b[i] + 3.0 * c[i];
    auto t1 = std::chrono::steady_clock::now();
    for (std::size_t i = 0; i < n; ++i)
      c[i] = a[i];
    auto t2 = std::chrono::steady_clock::now();
    best_triad = std::min(best_triad, std::chrono::duration<double>(t1 - t0).count());
    best_copy = std::min(best_copy, std::chrono::duration<double>(t2 - t1).count());
  }
  std::printf("elements %zu (%.0f MB per array), best of %d: triad %.2f GB/s, copy %.2f GB/s "
              "(check %g)\n",
              n, n * 8e-6, repeats, 24e-9 * n / best_triad, 16e-9 * n / best_copy, a[n / 2] + c[0]);
}
