// The pressure AMG on one and two ranks, outside fvfsi (doc/results/log.md: "ML's coarse solve on
// every rank, and MueLu"; the aggregation threshold: doc/results/performance.md, section 8). Reads a pressure system dumped by
// doc/benchmarks/pressure_dump_probe.patch (DIR/pressure_A.mtx, pressure_b.txt, pressure_x0.txt),
// splits its rows into one contiguous range per rank (for deal.II's cell numbering on p4est the
// partition the fluid itself would get), and times CG (Belos) from the dumped start value to a
// relative residual of 1e-2 (the correctors' tolerance) and 1e-6 (the last solve of a step):
//
//   ML variants (the default), each "COARSE_SIZE:REPLICATE[:KEY=VALUE,...]" in $VARIANTS:
//     ML as fvfsi's LinearSolver sets it through deal.II, with "coarse: max size" = COARSE_SIZE,
//     its coarsest level solved by KLU on rank 0 (ML's own, REPLICATE = 0) or by a copy of KLU on
//     every rank (REPLICATE = 1: the coarse matrix gathered once, one all-gather of the
//     right-hand side per V-cycle); extra ML parameters after a second colon, '_' for ' '
//     (e.g. "2000:0:eigen-analysis:_iterations=40"). The solves alternate between the variants
//     (REPEATS rounds) so that the machine's drift falls on all alike; medians are printed.
//   muelu: MueLu on Tpetra (Trilinos 13.2 from Debian is built without MueLu's Epetra support),
//     smoothed aggregation with ML's settings (Chebyshev of degree 2, threshold 0.02, a direct
//     coarse solve below 2000 rows; $MUELU_COARSE names another coarse solver).
//
//   usage: mpirun -np 2 amg_probe DIR [REPEATS [ml|muelu]]   (build: make amg_probe)
#include <deal.II/base/mpi.h>
#include <deal.II/lac/trilinos_precondition.h>

#include <Amesos.h>
#include <Amesos_BaseSolver.h>
#include <BelosEpetraAdapter.hpp>
#include <BelosLinearProblem.hpp>
#include <BelosPseudoBlockCGSolMgr.hpp>
#include <BelosTpetraAdapter.hpp>
#include <EpetraExt_CrsMatrixIn.h>
#include <Epetra_CrsMatrix.h>
#include <Epetra_LinearProblem.h>
#include <Epetra_MpiComm.h>
#include <Epetra_SerialComm.h>
#include <MatrixMarket_Tpetra.hpp>
#include <MueLu_CreateTpetraPreconditioner.hpp>
#include <Tpetra_Core.hpp>
#include <Tpetra_CrsMatrix.hpp>
#include <ml_MultiLevelPreconditioner.h>
#include <ml_epetra_utils.h>

#include "probe_input.h"

#include <algorithm>
#include <fstream>
#include <iostream>
#include <memory>
#include <sstream>
#include <vector>

using namespace dealii;
using probe::median;
using probe::read_values;

namespace
{
// ML's coarsest level solved on every rank: KLU (through Amesos, on a serial communicator) of
// the whole coarse matrix, gathered once; each application gathers the right-hand side. The same
// scheme as fvfsi's GatheredDirectSolver (Where::every_rank), which takes a deal.II matrix and
// factorises with UMFPACK; here ML's own KLU on the raw arrays of ML's smoother interface, so
// that only where the coarse solve runs changes.
struct ReplicatedCoarse
{
  MPI_Comm comm;
  unsigned int rank;
  std::vector<int> counts, offsets; ///< coarse rows per rank, first row of each
  Epetra_SerialComm serial;
  std::unique_ptr<Epetra_Map> map;
  std::unique_ptr<Epetra_CrsMatrix> A;
  std::unique_ptr<Epetra_Vector> x, b;
  std::unique_ptr<Epetra_LinearProblem> problem;
  std::unique_ptr<Amesos_BaseSolver> klu;
};

// ML's smoother interface: x = A_coarse^-1 rhs on this rank's coarse rows.
int replicated_coarse_solve(ML_Smoother* smoother, int, double x[], int n_owned, double rhs[])
{
  auto* self = static_cast<ReplicatedCoarse*>(ML_Get_MySmootherData(smoother));
  MPI_Allgatherv(rhs, n_owned, MPI_DOUBLE, self->b->Values(), self->counts.data(),
                 self->offsets.data(), MPI_DOUBLE, self->comm);
  self->klu->Solve();
  std::copy_n(self->x->Values() + self->offsets[self->rank], n_owned, x);
  return 0;
}

// Replaces the KLU-on-rank-0 of `amg`'s coarsest level (ML keeps it as that level's post-
// smoother) by ReplicatedCoarse.
void replicate_coarse_solve(const TrilinosWrappers::PreconditionAMG& amg, const MPI_Comm comm)
{
  const auto& preconditioner =
    dynamic_cast<const ML_Epetra::MultiLevelPreconditioner&>(amg.trilinos_operator());
  ML* ml = const_cast<ML*>(preconditioner.GetML());
  const int coarse = ml->LevelID[ml->ML_num_actual_levels - 1];
  auto self = std::make_unique<ReplicatedCoarse>();
  self->comm = comm;
  self->rank = Utilities::MPI::this_mpi_process(comm);
  Epetra_CrsMatrix* local = nullptr;
  ML_Operator2EpetraCrsMatrix(&ml->Amat[coarse], local);
  std::unique_ptr<Epetra_CrsMatrix> owned(local);
  const int n_owned = owned->NumMyRows();
  self->counts = Utilities::MPI::all_gather(comm, n_owned);
  self->offsets.assign(self->counts.size(), 0);
  for (unsigned int r = 1; r < self->counts.size(); ++r)
    self->offsets[r] = self->offsets[r - 1] + self->counts[r - 1];
  std::vector<int> my_indices; // row, column, row, column, ...
  std::vector<double> my_values;
  for (int row = 0; row < n_owned; ++row)
  {
    int n;
    double* values;
    int* columns;
    owned->ExtractMyRowView(row, n, values, columns);
    AssertThrow(owned->GRID(row) == self->offsets[self->rank] + row, ExcInternalError());
    for (int k = 0; k < n; ++k)
    {
      my_indices.push_back(owned->GRID(row));
      my_indices.push_back(owned->GCID(columns[k]));
      my_values.push_back(values[k]);
    }
  }
  const auto indices = Utilities::MPI::all_gather(comm, my_indices);
  const auto values = Utilities::MPI::all_gather(comm, my_values);
  self->map =
    std::make_unique<Epetra_Map>(self->offsets.back() + self->counts.back(), 0, self->serial);
  self->A = std::make_unique<Epetra_CrsMatrix>(Copy, *self->map, 0);
  for (unsigned int r = 0; r < indices.size(); ++r)
    for (std::size_t k = 0; k < values[r].size(); ++k)
      self->A->InsertGlobalValues(indices[r][2 * k], 1, &values[r][k], &indices[r][2 * k + 1]);
  self->A->FillComplete();
  self->x = std::make_unique<Epetra_Vector>(*self->map);
  self->b = std::make_unique<Epetra_Vector>(*self->map);
  self->problem =
    std::make_unique<Epetra_LinearProblem>(self->A.get(), self->x.get(), self->b.get());
  Amesos factory;
  self->klu.reset(factory.Create("Amesos_Klu", *self->problem));
  self->klu->SymbolicFactorization();
  self->klu->NumericFactorization();

  ML_Smoother& post = ml->post_smoother[coarse];
  if (post.data_destroy && post.smoother->data)
    post.data_destroy(post.smoother->data); // ML's own KLU
  post.smoother->data = nullptr;
  ML_Set_Smoother(ml, coarse, ML_POSTSMOOTHER, self.release(), replicated_coarse_solve,
                  const_cast<char*>("KLU on every rank"));
  post.data_destroy = [](void* p) { delete static_cast<ReplicatedCoarse*>(p); };
}

// One ML variant of $VARIANTS.
struct Variant
{
  int coarse_size = 2000;
  bool replicated = false;
  std::string extra; ///< KEY=VALUE,... ('_' for ' ')
  std::string name() const
  {
    return "coarse size " + std::to_string(coarse_size) +
           (replicated ? ", KLU on every rank" : ", KLU on rank 0") +
           (extra.empty() ? "" : ", " + extra);
  }
};

std::vector<Variant> read_variants()
{
  std::istringstream in(std::getenv("VARIANTS") ? std::getenv("VARIANTS") : "2000:0 2000:1");
  std::vector<Variant> variants;
  std::string word;
  while (in >> word)
  {
    const auto c1 = word.find(':'), c2 = word.find(':', c1 + 1);
    Variant v;
    v.coarse_size = std::stoi(word.substr(0, c1));
    v.replicated = std::stoi(word.substr(c1 + 1, c2 - c1 - 1)) != 0;
    if (c2 != std::string::npos)
      v.extra = word.substr(c2 + 1);
    variants.push_back(v);
  }
  return variants;
}

// KEY=VALUE,... into `list`: integers, else doubles, else strings.
void set_extra(Teuchos::ParameterList& list, const std::string& extra)
{
  std::istringstream in(extra);
  std::string pair;
  while (std::getline(in, pair, ','))
  {
    std::string key = pair.substr(0, pair.find('=')), value = pair.substr(pair.find('=') + 1);
    std::replace(key.begin(), key.end(), '_', ' ');
    std::replace(value.begin(), value.end(), '_', ' ');
    std::size_t used = 0;
    try
    {
      const int i = std::stoi(value, &used);
      if (used == value.size())
      {
        list.set(key, i);
        continue;
      }
      const double d = std::stod(value, &used);
      if (used == value.size())
      {
        list.set(key, d);
        continue;
      }
    }
    catch (const std::exception&)
    {
    }
    list.set(key, value);
  }
}

// CG from x0 to the relative residual `tol`: seconds (the slower rank's) and iterations.
template <class MV, class OP>
std::pair<double, int> cg(Belos::LinearProblem<double, MV, OP>& problem, MV& x, const MV& x0,
                          const double tol, const MPI_Comm comm)
{
  auto parameters = Teuchos::rcp(new Teuchos::ParameterList);
  parameters->set("Convergence Tolerance", tol);
  parameters->set("Maximum Iterations", 1000);
  Belos::MultiVecTraits<double, MV>::Assign(x0, x);
  problem.setProblem();
  Belos::PseudoBlockCGSolMgr<double, MV, OP> solver(Teuchos::rcpFromRef(problem), parameters);
  MPI_Barrier(comm);
  const double start = MPI_Wtime();
  solver.solve();
  const double seconds = Utilities::MPI::max(MPI_Wtime() - start, comm);
  return {seconds, solver.getNumIters()};
}

void run_ml(const std::string& dir, const int repeats, const MPI_Comm comm)
{
  using MV = Epetra_MultiVector;
  using OP = Epetra_Operator;
  const unsigned int rank = Utilities::MPI::this_mpi_process(comm);
  Epetra_MpiComm epetra_comm(comm);
  Epetra_CrsMatrix* read = nullptr;
  EpetraExt::MatrixMarketFileToCrsMatrix((dir + "/pressure_A.mtx").c_str(), epetra_comm, read);
  Teuchos::RCP<const OP> A = Teuchos::rcp(read);
  const Epetra_Map& map = read->RowMap();
  const auto b_all = read_values(dir + "/pressure_b.txt");
  const auto x0_all = read_values(dir + "/pressure_x0.txt");
  auto b = Teuchos::rcp(new MV(map, 1)), x = Teuchos::rcp(new MV(map, 1));
  MV x0(map, 1);
  for (int i = 0; i < map.NumMyElements(); ++i)
  {
    (*b)[0][i] = b_all[map.GID(i)];
    x0[0][i] = x0_all[map.GID(i)];
  }

  // fvfsi's LinearSolver::initialize() for the AMG.
  TrilinosWrappers::PreconditionAMG::AdditionalData data;
  data.elliptic = true;
  data.higher_order_elements = false;
  data.smoother_sweeps = 2;
  data.aggregation_threshold = 0.02;
  const auto variants = read_variants();
  std::vector<std::unique_ptr<TrilinosWrappers::PreconditionAMG>> amgs;
  std::vector<std::unique_ptr<Belos::LinearProblem<double, MV, OP>>> problems;
  std::vector<std::vector<double>> setup(variants.size());
  for (int round = 0; round < 5; ++round) // set-up timed five times, the last one kept
    for (unsigned int v = 0; v < variants.size(); ++v)
    {
      Teuchos::ParameterList list;
      std::unique_ptr<Epetra_MultiVector> modes;
      data.set_parameters(list, modes, *read);
      list.set("coarse: max size", variants[v].coarse_size);
      set_extra(list, variants[v].extra);
      auto amg = std::make_unique<TrilinosWrappers::PreconditionAMG>();
      MPI_Barrier(comm);
      const double start = MPI_Wtime();
      amg->initialize(*read, list);
      if (variants[v].replicated)
        replicate_coarse_solve(*amg, comm);
      setup[v].push_back(Utilities::MPI::max(MPI_Wtime() - start, comm));
      if (round == 4)
      {
        amgs.push_back(std::move(amg));
        problems.push_back(std::make_unique<Belos::LinearProblem<double, MV, OP>>(A, x, b));
        problems.back()->setLeftPrec(Teuchos::rcp(
          new Belos::EpetraPrecOp(Teuchos::rcpFromRef(amgs.back()->trilinos_operator()))));
      }
    }
  for (const double tol : {1e-2, 1e-6})
  {
    std::vector<std::vector<double>> seconds(variants.size());
    std::vector<int> iterations(variants.size());
    for (int round = 0; round < repeats; ++round)
      for (unsigned int v = 0; v < variants.size(); ++v)
      {
        const auto [s, its] = cg(*problems[v], *x, x0, tol, comm);
        seconds[v].push_back(s);
        iterations[v] = its;
      }
    for (unsigned int v = 0; v < variants.size() && rank == 0; ++v)
      std::cout << "ML, np " << Utilities::MPI::n_mpi_processes(comm) << ", tol " << tol << ", "
                << variants[v].name() << ": " << iterations[v] << " CG iterations, "
                << 1e3 * median(seconds[v]) << " ms per solve (x"
                << median(seconds[v]) / median(seconds[0]) << " of the first), set-up "
                << 1e3 * median(setup[v]) << " ms" << std::endl;
  }
}

void run_muelu(const std::string& dir, const int repeats, const MPI_Comm comm)
{
  using Matrix = Tpetra::CrsMatrix<>;
  using MV = Tpetra::MultiVector<>;
  using OP = Tpetra::Operator<>;
  const unsigned int rank = Utilities::MPI::this_mpi_process(comm);
  Teuchos::RCP<Matrix> A = Tpetra::MatrixMarket::Reader<Matrix>::readSparseFile(
    dir + "/pressure_A.mtx", Tpetra::getDefaultComm());
  const auto map = A->getRowMap();
  const auto b_all = read_values(dir + "/pressure_b.txt");
  const auto x0_all = read_values(dir + "/pressure_x0.txt");
  auto b = Teuchos::rcp(new MV(map, 1)), x = Teuchos::rcp(new MV(map, 1));
  MV x0(map, 1);
  for (std::size_t i = 0; i < map->getNodeNumElements(); ++i)
  {
    b->replaceLocalValue(i, 0, b_all[map->getGlobalElement(i)]);
    x0.replaceLocalValue(i, 0, x0_all[map->getGlobalElement(i)]);
  }
  Teuchos::ParameterList list;
  list.set("verbosity", "none");
  list.set("multigrid algorithm", "sa");
  list.set("aggregation: type", "uncoupled");
  list.set("aggregation: drop tol", 0.02);
  list.set("coarse: max size", 2000);
  list.set("coarse: type", std::getenv("MUELU_COARSE") ? std::getenv("MUELU_COARSE") : "KLU2");
  list.set("smoother: type", "CHEBYSHEV");
  list.sublist("smoother: params").set("chebyshev: degree", 2);
  list.sublist("smoother: params").set("chebyshev: ratio eigenvalue", 20.0);
  Teuchos::RCP<MueLu::TpetraOperator<>> amg;
  std::vector<double> setup;
  for (int round = 0; round < 5; ++round)
  {
    Teuchos::ParameterList copy = list;
    MPI_Barrier(comm);
    const double start = MPI_Wtime();
    amg = MueLu::CreateTpetraPreconditioner(Teuchos::RCP<OP>(A), copy);
    setup.push_back(Utilities::MPI::max(MPI_Wtime() - start, comm));
  }
  Belos::LinearProblem<double, MV, OP> problem(A, x, b);
  problem.setLeftPrec(amg);
  for (const double tol : {1e-2, 1e-6})
  {
    std::vector<double> seconds;
    int iterations = 0;
    for (int round = 0; round < repeats; ++round)
    {
      const auto [s, its] = cg(problem, *x, x0, tol, comm);
      seconds.push_back(s);
      iterations = its;
    }
    if (rank == 0)
      std::cout << "MueLu, np " << Utilities::MPI::n_mpi_processes(comm) << ", tol " << tol << ": "
                << iterations << " CG iterations, " << 1e3 * median(seconds)
                << " ms per solve, set-up " << 1e3 * median(setup) << " ms" << std::endl;
  }
}
} // namespace

int main(int argc, char** argv)
{
  Tpetra::ScopeGuard scope(&argc, &argv); // MPI and Kokkos
  if (argc < 2)
  {
    std::cerr << "usage: amg_probe DIR [REPEATS [ml|muelu]]" << std::endl;
    return 1;
  }
  const std::string dir = argv[1], kind = argc > 3 ? argv[3] : "ml";
  const int repeats = argc > 2 ? std::atoi(argv[2]) : 20;
  if (kind == "muelu")
    run_muelu(dir, repeats, MPI_COMM_WORLD);
  else
    run_ml(dir, repeats, MPI_COMM_WORLD);
}
