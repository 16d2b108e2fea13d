// What parallel efficiency the machine itself allows a bulk-synchronous code (not a test: it
// prints a wall time; doc/results/bsp_ceiling.sh runs it, doc/results/log.md, "Again on the Intel
// Xeon, with the machine's own ceiling", reads it).
//
//   mpirun -np P bsp_ceiling [--cells 47160] [--sweeps-per-sync 4] [--syncs 40000]
//
// A perfectly parallel stand-in for fvfsi's linear solves: `cells` cells of a structured 2D grid
// (rows of 256 cells) are split evenly over the P ranks; each rank sweeps a five-point stencil over
// its own rows `sweeps-per-sync` times (no halo: no communication, no imbalance of work) and then
// all ranks meet in one MPI_Allreduce, as CG and an AMG V-cycle meet at every scalar product and
// ghost exchange; `syncs` such rounds. The work per rank shrinks exactly as 1/P and nothing is
// serial, so T(1) / (P T(P)) < 1 measures only the machine: two virtual CPUs whose speeds
// fluctuate independently make every round wait for the slower of the two. On 47 104 cells one
// sweep takes about 70 us on one rank of the 2-core Intel Xeon test machine (1.458 s for 5 000
// rounds of 4), so 1-4 sweeps per round bracket the work fvfsi's pressure CG does between two
// meetings of the ranks (log.md, the same entry).
//
// Prints one line: ranks, cells, sweeps per sync, syncs, the slowest rank's wall seconds, and a
// checksum (only so that the compiler keeps the work).
#include <mpi.h>

#include <chrono>
#include <cstdio>
#include <cstdlib>
#include <stdexcept>
#include <string>
#include <vector>

namespace
{
struct Options
{
  long cells = 47160;
  int sweeps_per_sync = 4;
  long syncs = 40000;
};

Options parse(int argc, char** argv)
{
  Options options;
  for (int i = 1; i + 1 < argc; i += 2)
  {
    const std::string key = argv[i];
    const long value = std::atol(argv[i + 1]);
    if (value <= 0)
      throw std::invalid_argument("bsp_ceiling: " + key + " needs a positive integer");
    if (key == "--cells")
      options.cells = value;
    else if (key == "--sweeps-per-sync")
      options.sweeps_per_sync = int(value);
    else if (key == "--syncs")
      options.syncs = value;
    else
      throw std::invalid_argument("bsp_ceiling: unknown option " + key);
  }
  return options;
}

// One Jacobi-like sweep of the five-point stencil over rows of `width` cells, the first and last
// row and column held fixed: y = x + 0.2 (sum of the four neighbours - 4 x).
void sweep(const std::vector<double>& x, std::vector<double>& y, const long width)
{
  const long n = long(x.size());
  for (long i = width; i < n - width; ++i)
    y[i] = x[i] + 0.2 * (x[i - 1] + x[i + 1] + x[i - width] + x[i + width] - 4.0 * x[i]);
}
} // namespace

int main(int argc, char** argv)
{
  MPI_Init(&argc, &argv);
  int rank = 0, size = 1;
  MPI_Comm_rank(MPI_COMM_WORLD, &rank);
  MPI_Comm_size(MPI_COMM_WORLD, &size);
  try
  {
    const Options options = parse(argc, argv);
    const long width = 256;
    const long rows = options.cells / width / size + 2; // + the two fixed rows of each rank
    std::vector<double> x(rows * width), y;
    for (long i = 0; i < long(x.size()); ++i)
      x[i] = double((i * 7919) % 1000) * 1e-3;
    y = x;

    MPI_Barrier(MPI_COMM_WORLD);
    const auto start = std::chrono::steady_clock::now();
    double checksum = 0;
    for (long s = 0; s < options.syncs; ++s)
    {
      for (int k = 0; k < options.sweeps_per_sync; ++k)
      {
        sweep(x, y, width);
        x.swap(y);
      }
      double local = x[width + (s % width)], global = 0;
      MPI_Allreduce(&local, &global, 1, MPI_DOUBLE, MPI_SUM, MPI_COMM_WORLD);
      checksum += global;
    }
    const double seconds =
      std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
    double slowest = 0;
    MPI_Reduce(&seconds, &slowest, 1, MPI_DOUBLE, MPI_MAX, 0, MPI_COMM_WORLD);
    if (rank == 0)
      std::printf("ranks %d cells %ld sweeps_per_sync %d syncs %ld wall %.3f checksum %.6e\n", size,
                  (rows - 2) * width * size, options.sweeps_per_sync, options.syncs, slowest,
                  checksum);
  }
  catch (const std::exception& e)
  {
    if (rank == 0)
      std::fprintf(stderr, "%s\n", e.what());
    MPI_Abort(MPI_COMM_WORLD, 1);
  }
  MPI_Finalize();
  return 0;
}
