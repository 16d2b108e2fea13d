// Performance benchmark of the fvfsi FV core (not a test: it prints timings).
//
// One case per process (so that the peak RSS belongs to that case):
//
//   core_performance --dim 2 --subdivisions 5 --refinements 6 [--repeats 3] [--distortion 0.1]
//                    [--malloc-defaults 0|1] [--out FILE]
//
// builds a subdivided_hyper_cube mesh of [0,1]^dim (subdivisions^dim coarse cells, refined
// `refinements` times, interior vertices distorted by `distortion` x the shortest adjacent edge, as
// Mesh/Distortion does), then times, each `repeats` times (the median is reported):
//
//   dof_numbering       the deal.II part of the constructor: FE_DGQ(0) DoFHandler, relevant DoFs,
//                       partitioner (done separately, to split the constructor's time)
//   geometry_construct  FVGeometry constructor (DoF numbering, faces, geometry)
//   geometry_reinit     FVGeometry::reinit after a smooth mesh motion
//   vertex_interp_reinit VertexInterpolation::reinit (least-squares coefficients; also needed after
//                       a mesh motion)
//   matrix_sparsity     Laplacian::reinit_matrix (sparsity pattern + Trilinos matrix)
//   assemble            matrix = 0, Laplacian::assemble, matrix.compress(add)
//   amg_setup           LinearSolver::initialize (Trilinos ML AMG)
//   cg_solve            LinearSolver::solve (CG, reduction 1e-6, from phi = 0)
//   linear_solve_total  amg_setup + cg_solve (sample by sample)
//   sweep               one deferred-correction sweep: boundary_values, VertexInterpolation::
//                       interpolate, GaussGreenGradient, rhs = rhs_fixed, add_correction;
//                       its parts are timed separately as sweep_*
//   assemble_rowwise    (experiment, not library code) the same matrix assembled with one
//                       matrix.add(row, n, cols, values) call per cell instead of four
//                       matrix.add(i, j, value) calls per face
//
// --malloc-defaults 1 restores glibc's malloc defaults (mmap for large blocks, trimming), which a
// library loaded with deal.II switches off (see main()); the memory experiment of run_core.sh.
//
// It writes `key value` lines (times in seconds, memory in bytes) to stdout and to --out.
// run_core.sh turns the files of several cases into the table of doc/results/core.md.

#include <deal.II/base/mpi.h>
#include <deal.II/base/utilities.h>
#include <deal.II/distributed/tria.h>
#include <deal.II/dofs/dof_handler.h>
#include <deal.II/dofs/dof_tools.h>
#include <deal.II/fe/fe_dgq.h>
#include <deal.II/lac/trilinos_sparse_matrix.h>
#include <deal.II/lac/trilinos_vector.h>

#include <fvfsi/fv/boundary_conditions.h>
#include <fvfsi/fv/cell_fields.h>
#include <fvfsi/fv/gradients.h>
#include <fvfsi/fv/laplacian.h>
#include <fvfsi/fv/linear_solver.h>
#include <fvfsi/fv/vertex_interpolation.h>
#include <fvfsi/mesh/fv_geometry.h>
#include <fvfsi/mesh/mesh_builder.h>
#include <fvfsi/mesh/mesh_parameters.h>

#include <malloc.h>

#include <algorithm>
#include <chrono>
#include <cmath>
#include <ctime>
#include <fstream>
#include <functional>
#include <iomanip>
#include <iostream>
#include <map>
#include <memory>
#include <sstream>
#include <stdexcept>
#include <string>
#include <vector>

using namespace dealii;
using namespace fvfsi;

namespace
{
struct Options
{
  int dim = 2;
  unsigned int subdivisions = 5;
  unsigned int refinements = 6;
  unsigned int repeats = 3;
  double distortion = 0.1;
  bool malloc_defaults = false;
  std::string out;
};

Options parse(int argc, char** argv)
{
  Options o;
  for (int i = 1; i < argc; ++i)
  {
    const std::string a = argv[i];
    if (i + 1 >= argc)
      throw std::runtime_error("missing value after " + a);
    const std::string v = argv[++i];
    if (a == "--dim")
      o.dim = std::stoi(v);
    else if (a == "--subdivisions")
      o.subdivisions = std::stoul(v);
    else if (a == "--refinements")
      o.refinements = std::stoul(v);
    else if (a == "--repeats")
      o.repeats = std::stoul(v);
    else if (a == "--distortion")
      o.distortion = std::stod(v);
    else if (a == "--malloc-defaults")
      o.malloc_defaults = std::stoi(v) != 0;
    else if (a == "--out")
      o.out = v;
    else
      throw std::runtime_error("unknown option " + a);
  }
  if (o.dim != 2 && o.dim != 3)
    throw std::runtime_error("--dim must be 2 or 3");
  if (o.repeats == 0)
    throw std::runtime_error("--repeats must be >= 1");
  return o;
}

/// Wall-clock and CPU time of the process (CPU time is much less sensitive to other processes
/// competing for the cores of a shared machine; wall > CPU means this process waited).
struct Time
{
  double wall = 0, cpu = 0;
  Time operator-(const Time& t) const { return {wall - t.wall, cpu - t.cpu}; }
};

Time now()
{
  timespec ts;
  clock_gettime(CLOCK_PROCESS_CPUTIME_ID, &ts);
  return {
    std::chrono::duration<double>(std::chrono::steady_clock::now().time_since_epoch()).count(),
    ts.tv_sec + 1e-9 * ts.tv_nsec};
}

double median(std::vector<double> v)
{
  std::sort(v.begin(), v.end());
  const std::size_t n = v.size();
  return n % 2 ? v[n / 2] : 0.5 * (v[n / 2 - 1] + v[n / 2]);
}

/// Resident and peak resident set size in bytes (VmRSS, VmHWM of /proc/self/status).
std::pair<double, double> rss()
{
  Utilities::System::MemoryStats stats;
  Utilities::System::get_memory_stats(stats);
  return {1024.0 * stats.VmRSS, 1024.0 * stats.VmHWM};
}

/// Bytes currently allocated with malloc/new (all arenas plus mmapped blocks; glibc mallinfo2).
/// Differences of this give the memory an object holds, which RSS differences do not (freed
/// memory stays resident and is reused).
double heap()
{
  const auto m = mallinfo2();
  return double(m.uordblks) + double(m.hblkhd);
}

/// Collects the results as `key value` lines.
class Report
{
public:
  void value(const std::string& key, const double v)
  {
    std::ostringstream s;
    s << std::setprecision(15) << v;
    lines.push_back(key + " " + s.str());
    std::cout << key << " " << s.str() << std::endl;
  }
  void text(const std::string& key, const std::string& v)
  {
    lines.push_back(key + " " + v);
    std::cout << key << " " << v << std::endl;
  }
  /// Record the samples of a timing (wall and CPU) and their medians.
  void timing(const std::string& key, const std::vector<Time>& samples)
  {
    std::ostringstream s, c;
    std::vector<double> wall, cpu;
    for (const Time& t : samples)
    {
      s << (wall.empty() ? "" : ",") << std::setprecision(4) << t.wall;
      c << (cpu.empty() ? "" : ",") << std::setprecision(4) << t.cpu;
      wall.push_back(t.wall);
      cpu.push_back(t.cpu);
    }
    text(key + "_samples", s.str());
    text(key + "_cpu_samples", c.str());
    value(key, median(wall));
    value(key + "_cpu", median(cpu));
  }
  void write(const std::string& file) const
  {
    if (file.empty())
      return;
    std::ofstream out(file);
    for (const auto& l : lines)
      out << l << '\n';
  }

private:
  std::vector<std::string> lines;
};

/// Time `f` `repeats` times; `before` (untimed) runs before every sample.
std::vector<Time> sample(
  const unsigned int repeats, const std::function<void()>& f,
  const std::function<void()>& before = [] {})
{
  std::vector<Time> t;
  for (unsigned int r = 0; r < repeats; ++r)
  {
    before();
    const Time t0 = now();
    f();
    t.push_back(now() - t0);
  }
  return t;
}

/// The manufactured solution of the Poisson scene: phi = exp(x) sin(pi y) [sin(pi z)].
template <int dim>
double exact(const Point<dim>& p)
{
  double v = std::exp(p[0]) * std::sin(M_PI * p[1]);
  if (dim == 3)
    v *= std::sin(M_PI * p[dim - 1]);
  return v;
}
template <int dim>
double source(const Point<dim>& p)
{
  return ((dim - 1) * M_PI * M_PI - 1) * exact(p);
}

/// The experiment: the same matrix as Laplacian::assemble, one add() call per matrix row.
template <int dim>
void assemble_rowwise(const FVGeometry<dim>& fv, const FaceVector& gamma,
                      const ScalarBoundaryConditions<dim>& bc,
                      TrilinosWrappers::SparseMatrix& matrix, CellVector& rhs)
{
  using size_type = TrilinosWrappers::SparseMatrix::size_type;
  std::vector<size_type> cols;
  std::vector<double> values;
  for (unsigned int c = 0; c < fv.n_owned_cells(); ++c)
  {
    cols.clear();
    values.clear();
    double diagonal = 0;
    for (const unsigned int f : fv.cell_faces(c))
    {
      const auto& face = fv.faces[f];
      const double a = gamma[f] * face.area / face.d_n;
      if (face.N != invalid_cell)
      {
        diagonal += a;
        cols.push_back(fv.global_index(face.P == c ? face.N : face.P));
        values.push_back(-a);
      }
      else if (bc.type(face) == BoundaryType::dirichlet)
      {
        diagonal += a;
        rhs.local_element(c) += a * bc.value[f];
      }
      else
        rhs.local_element(c) += gamma[f] * face.area * bc.value[f];
    }
    cols.push_back(fv.global_index(c));
    values.push_back(diagonal);
    matrix.add(fv.global_index(c), cols.size(), cols.data(), values.data(), false, false);
  }
}

template <int dim>
void run(const Options& o, Report& report)
{
  const MPI_Comm comm = MPI_COMM_WORLD;
  const auto [rss_start, hwm_start] = rss();
  (void)hwm_start;
  report.value("rss_start", rss_start);
  const double heap_start = heap();

  // ---- mesh (through the library's make_mesh, as a .prm `subsection Mesh` would) ----
  MeshParameters mp;
  mp.generator = "subdivided_hyper_cube";
  mp.generator_arguments = std::to_string(o.subdivisions) + ": 0: 1: false";
  mp.n_global_refinements = o.refinements;
  mp.distortion = o.distortion;
  parallel::distributed::Triangulation<dim> tria(comm);
  Time t0 = now();
  make_mesh(mp, tria);
  report.value("mesh_time", (now() - t0).wall);
  const double n_cells = tria.n_global_active_cells();
  report.value("dim", dim);
  report.value("cells", n_cells);
  report.value("vertices", tria.n_vertices());
  report.value("mpi_ranks", Utilities::MPI::n_mpi_processes(comm));
  report.value("repeats", o.repeats);
  report.value("mem_tria_heap", heap() - heap_start);
  report.value("mem_tria_consumption", tria.memory_consumption());

  // ---- the part of the FVGeometry constructor that is deal.II's: FE_DGQ(0) DoF numbering,
  // locally relevant DoFs and the partitioner (replicated here to split the construction time) ----
  report.timing("dof_numbering", sample(o.repeats,
                                        [&]
                                        {
                                          const FE_DGQ<dim> fe(0);
                                          DoFHandler<dim> dofs(tria);
                                          dofs.distribute_dofs(fe);
                                          IndexSet relevant;
                                          DoFTools::extract_locally_relevant_dofs(dofs, relevant);
                                          Utilities::MPI::Partitioner partitioner(
                                            dofs.locally_owned_dofs(), relevant, comm);
                                        }));

  // ---- FVGeometry construction (and the heap memory it holds) ----
  std::unique_ptr<FVGeometry<dim>> fv;
  std::vector<Time> construct;
  double mem_geometry = 0;
  const auto [rss_before_geometry, hwm_before_geometry] = rss();
  for (unsigned int r = 0; r < o.repeats; ++r)
  {
    fv.reset();
    const double h0 = heap();
    t0 = now();
    fv = std::make_unique<FVGeometry<dim>>(tria);
    construct.push_back(now() - t0);
    mem_geometry = heap() - h0;
    if (r == 0)
    {
      // Growth of RSS and of the peak RSS during the first construction: a peak growth above
      // the RSS growth is memory that was resident only during the construction.
      const auto [rss_after, hwm_after] = rss();
      report.value("geometry_first_rss_growth", rss_after - rss_before_geometry);
      report.value("geometry_first_peak_rss_growth", hwm_after - hwm_before_geometry);
      const auto m = mallinfo2();
      report.value("malloc_arena_after_geometry", m.arena);
      report.value("malloc_arena_free_after_geometry", m.fordblks);
      report.value("malloc_mmapped_after_geometry", m.hblkhd);
    }
  }
  report.timing("geometry_construct", construct);
  report.value("mem_geometry_heap", mem_geometry);
  report.value("peak_rss_after_geometry", rss().second);
  report.value("mem_dof_handler_consumption", fv->dof_handler().memory_consumption());
  report.value("faces", fv->faces.size());
  report.value("sizeof_face", sizeof(FaceGeometry<dim>));
  report.value("mem_faces_array", fv->faces.capacity() * sizeof(FaceGeometry<dim>));
  report.value("mem_faces_used", fv->faces.size() * sizeof(FaceGeometry<dim>));

  // ---- mesh motion: a smooth displacement (max 0.01) of every vertex, then reinit ----
  std::vector<Point<dim>> moved = tria.get_vertices();
  for (auto& x : moved)
  {
    double bump = 1;
    for (unsigned int d = 0; d < dim; ++d)
      bump *= std::sin(M_PI * x[d]);
    for (unsigned int d = 0; d < dim; ++d)
      x[d] += 0.01 * bump * (d == 0 ? 1.0 : -0.5);
  }
  report.timing("geometry_reinit", sample(o.repeats, [&] { fv->reinit(moved); }));

  double h0 = heap();
  t0 = now();
  VertexInterpolation<dim> vertex_interpolation(*fv);
  const GaussGreenGradient<dim> gauss_green(*fv);
  report.value("vertex_interp_construct", (now() - t0).wall);
  report.value("mem_vertex_interp_heap", heap() - h0);
  report.timing("vertex_interp_reinit", sample(o.repeats, [&] { vertex_interpolation.reinit(); }));

  // ---- Laplacian: Dirichlet data of the manufactured solution on the whole boundary ----
  Laplacian<dim> laplacian(*fv);
  ScalarBoundaryConditions<dim> bc;
  for (const auto id : tria.get_boundary_ids())
    bc.patch_type[id] = BoundaryType::dirichlet;
  bc.value.assign(fv->faces.size(), 0.0);
  for (unsigned int f = 0; f < fv->faces.size(); ++f)
    if (fv->faces[f].N == invalid_cell)
      bc.value[f] = exact(fv->faces[f].centre);
  const FaceVector gamma(fv->faces.size(), 1.0);

  TrilinosWrappers::SparseMatrix matrix;
  h0 = heap();
  report.timing("matrix_sparsity",
                sample(
                  o.repeats, [&] { laplacian.reinit_matrix(matrix); }, [&] { matrix.clear(); }));
  report.value("mem_matrix_heap", heap() - h0);
  report.value("mem_matrix_consumption", matrix.memory_consumption());
  report.value("matrix_nnz", matrix.n_nonzero_elements());

  CellVector rhs_fixed = fv->make_cell_vector(), rhs = fv->make_cell_vector(),
             phi = fv->make_cell_vector();
  report.timing("assemble", sample(
                              o.repeats,
                              [&]
                              {
                                laplacian.assemble(gamma, bc, matrix, rhs_fixed);
                                matrix.compress(VectorOperation::add);
                              },
                              [&]
                              {
                                matrix = 0;
                                for (unsigned int c = 0; c < fv->n_owned_cells(); ++c)
                                  rhs_fixed.local_element(c) =
                                    source(fv->centroid[c]) * fv->cell_volume[c];
                              }));

  // ---- linear solve: CG + AMG, reduction 1e-6, from zero; setup and solve separately ----
  LinearSolverParameters sp;
  sp.method = LinearSolverParameters::Method::cg;
  sp.preconditioner = LinearSolverParameters::Preconditioner::amg;
  sp.reduction = 1e-6;
  std::unique_ptr<LinearSolver> solver;
  std::vector<Time> setup, solve;
  unsigned int iterations = 0;
  double mem_amg = 0;
  for (unsigned int r = 0; r < o.repeats; ++r)
  {
    solver.reset();
    h0 = heap();
    solver = std::make_unique<LinearSolver>(sp);
    t0 = now();
    solver->initialize(matrix);
    setup.push_back(now() - t0);
    mem_amg = heap() - h0;
    phi = 0;
    t0 = now();
    iterations = solver->solve(matrix, phi, rhs_fixed, "benchmark phi");
    solve.push_back(now() - t0);
  }
  std::vector<Time> setup_and_solve;
  for (unsigned int r = 0; r < o.repeats; ++r)
    setup_and_solve.push_back({setup[r].wall + solve[r].wall, setup[r].cpu + solve[r].cpu});
  report.timing("linear_solve_total", setup_and_solve);
  report.timing("amg_setup", setup);
  report.timing("cg_solve", solve);
  report.value("cg_iterations", iterations);
  report.value("mem_amg_heap", mem_amg);

  // ---- one deferred-correction sweep, as in PoissonProblem::solve ----
  CellGradient<dim> grad(*fv);
  std::vector<double> vertex_phi;
  std::map<std::string, std::vector<Time>> parts;
  std::vector<Time> sweep;
  for (unsigned int r = 0; r < o.repeats; ++r)
  {
    const Time s0 = now();
    const FaceVector bv = laplacian.boundary_values(phi, grad, bc);
    const Time s1 = now();
    vertex_interpolation.interpolate(phi, bv, vertex_phi);
    const Time s2 = now();
    gauss_green.compute(vertex_phi, grad);
    const Time s3 = now();
    rhs = rhs_fixed;
    laplacian.add_correction(gamma, bc, grad, rhs);
    const Time s4 = now();
    parts["sweep_boundary_values"].push_back(s1 - s0);
    parts["sweep_interpolate"].push_back(s2 - s1);
    parts["sweep_gauss_green"].push_back(s3 - s2);
    parts["sweep_rhs_copy_add_correction"].push_back(s4 - s3);
    sweep.push_back(s4 - s0);
  }
  report.timing("sweep", sweep);
  for (const auto& [k, v] : parts)
    report.timing(k, v);

  // Sanity check of what was solved: a few corrected solves, then the error at the centroids.
  for (unsigned int k = 0; k < 5; ++k)
  {
    rhs = rhs_fixed;
    laplacian.add_correction(gamma, bc, grad, rhs);
    solver->solve(matrix, phi, rhs, "benchmark phi");
    vertex_interpolation.interpolate(phi, laplacian.boundary_values(phi, grad, bc), vertex_phi);
    gauss_green.compute(vertex_phi, grad);
  }
  double max_error = 0;
  for (unsigned int c = 0; c < fv->n_owned_cells(); ++c)
    max_error = std::max(max_error, std::abs(phi.local_element(c) - exact(fv->centroid[c])));
  report.value("max_cell_error_after_5_corrections", Utilities::MPI::max(max_error, comm));

  // Peak RSS of the pipeline, read before the experiment below.
  const auto [rss_end, hwm_end] = rss();
  report.value("rss_end", rss_end);
  report.value("heap_end", heap());
  report.value("peak_rss", hwm_end);

  // ---- experiment: row-wise assembly; check it gives the same matrix (A v for a fixed v) ----
  TrilinosWrappers::MPI::Vector v(matrix.locally_owned_domain_indices(), comm), Av(v), Av2(v);
  for (unsigned int i = 0; i < v.locally_owned_size(); ++i)
    v.trilinos_vector()[0][i] = std::sin(1.0 + i);
  matrix.vmult(Av, v);
  report.timing("assemble_rowwise", sample(
                                      o.repeats,
                                      [&]
                                      {
                                        assemble_rowwise(*fv, gamma, bc, matrix, rhs);
                                        matrix.compress(VectorOperation::add);
                                      },
                                      [&] { matrix = 0; }));
  matrix.vmult(Av2, v);
  Av2 -= Av;
  report.value("assemble_rowwise_relative_difference", Av2.l2_norm() / Av.l2_norm());
}
} // namespace

int main(int argc, char** argv)
{
  try
  {
    Utilities::MPI::MPI_InitFinalize mpi(argc, argv, 1);
    const Options o = parse(argc, argv);
    if (o.malloc_defaults)
    {
      // A static initialiser of libsuperlu_dist (loaded with deal.II) calls
      // mallopt(M_MMAP_MAX, 0) and mallopt(M_TRIM_THRESHOLD, -1): large blocks then come from the
      // brk heap and freed memory is never returned to the system. Restore glibc's defaults.
      mallopt(M_MMAP_MAX, 65536);
      mallopt(M_MMAP_THRESHOLD, 128 * 1024);
      mallopt(M_TRIM_THRESHOLD, 128 * 1024);
    }
    Report report;
    if (o.dim == 2)
      run<2>(o, report);
    else
      run<3>(o, report);
    if (Utilities::MPI::this_mpi_process(MPI_COMM_WORLD) == 0)
      report.write(o.out);
  }
  catch (const std::exception& e)
  {
    std::cerr << "core_performance: " << e.what() << std::endl;
    return 1;
  }
  return 0;
}
