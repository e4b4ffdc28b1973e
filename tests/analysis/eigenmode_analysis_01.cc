// EigenmodeAnalysis through the Analysis::Access interface alone, without
// a Problem: a stand-in MechanicalSystem whose tangent is
// blockdiag([[2, 1], [1, 2]], 0, 0, 5), with the eigenvalues 0, 0, 1, 3, 5.
// The analysis must report max 5, two zero eigenvalues, the lowest
// 'Number of eigenvalues' = 3 of them, write eigenvalues.txt and call
// write_files(0, 0) once; it needs no view of the problem.

#include <pg/analysis/eigenmode_analysis.h>
#include <pg/problem.h>

#include <deal.II/base/mpi.h>
#include <deal.II/lac/dynamic_sparsity_pattern.h>

#include "../tests.h"

#include <filesystem>

using namespace pg;

namespace
{
  /** Only assemble_residual() and tangent() are used by the analysis. */
  class TangentOnly : public MechanicalSystem
  {
  public:
    explicit TangentOnly(const std::vector<std::vector<double>> &A)
      : owned(complete_index_set(A.size()))
    {
      DynamicSparsityPattern pattern(A.size(), A.size());
      for (unsigned int i = 0; i < A.size(); ++i)
        for (unsigned int j = 0; j < A.size(); ++j)
          if (A[i][j] != 0. || i == j)
            pattern.add(i, j);
      matrix.reinit(pattern);
      for (unsigned int i = 0; i < A.size(); ++i)
        for (unsigned int j = 0; j < A.size(); ++j)
          if (A[i][j] != 0.)
            matrix.set(i, j, A[i][j]);
      matrix.compress(VectorOperation::insert);
    }

    unsigned int n_assemblies = 0;

    MPI_Comm
    communicator() const override
    {
      return MPI_COMM_WORLD;
    }
    const IndexSet &
    locally_owned_dofs() const override
    {
      return owned;
    }
    pg::LinearAlgebra::Vector &
    displacement() override
    {
      return unused();
    }
    void
    displacement_changed() override
    {
      unused();
    }
    void
    set_time(const double) override
    {
      unused();
    }
    void
    apply_dirichlet_values() override
    {
      unused();
    }
    const AffineConstraints<double> &
    homogeneous_constraints() const override
    {
      return constraints;
    }
    std::string
    assemble_residual(const bool with_matrix) override
    {
      AssertThrow(with_matrix, ExcInternalError());
      ++n_assemblies;
      return "";
    }
    pg::LinearAlgebra::Vector &
    residual() override
    {
      return unused();
    }
    const pg::LinearAlgebra::Vector &
    unbalanced_force() const override
    {
      AssertThrow(false, ExcInternalError());
      return vector;
    }
    pg::LinearAlgebra::SparseMatrix &
    tangent() override
    {
      return matrix;
    }
    void
    external_force(pg::LinearAlgebra::Vector &) override
    {
      unused();
    }
    void
    solve(const pg::LinearAlgebra::SparseMatrix &,
          pg::LinearAlgebra::Vector &,
          const pg::LinearAlgebra::Vector &) override
    {
      unused();
    }
    void
    add_condensed(const pg::LinearAlgebra::Vector &,
                  const double,
                  pg::LinearAlgebra::Vector &) const override
    {
      AssertThrow(false, ExcInternalError());
    }
    NewtonSolver::Operations
    newton_operations() override
    {
      unused();
      return {};
    }

  private:
    pg::LinearAlgebra::Vector &
    unused()
    {
      AssertThrow(false, ExcMessage("not used by the eigenmode analysis"));
      return vector;
    }

    const IndexSet                  owned;
    AffineConstraints<double>       constraints;
    pg::LinearAlgebra::SparseMatrix matrix;
    pg::LinearAlgebra::Vector       vector;
  };
} // namespace



int
main(int argc, char **argv)
{
  Utilities::MPI::MPI_InitFinalize mpi(argc, argv, 1);
  initlog();

  ParameterHandler handler;
  declare_all_parameters<2>(handler);
  Parameters::AllParameters<2> prm;
  prm.parse_parameters(handler);
  prm.output.directory       = "eigenmode_analysis_01";
  prm.analysis.n_eigenvalues = 3;
  std::filesystem::create_directories(prm.output.directory);

  TangentOnly            system({{2, 1, 0, 0, 0},
                                 {1, 2, 0, 0, 0},
                                 {0, 0, 0, 0, 0},
                                 {0, 0, 0, 0, 0},
                                 {0, 0, 0, 0, 5}});
  const FormulationCode  formulation = parse_formulation_code("FEM");
  std::ostringstream     log;
  ConditionalOStream     pcout(log, true);
  Timer                  timer;
  RunSummary             summary;
  TableHandler           statistics;
  QuadraturePointHistory history;
  std::vector<std::pair<unsigned int, double>> files;

  const Analysis::Access<2> access{prm,
                                   formulation,
                                   pcout,
                                   true,
                                   timer,
                                   system,
                                   nullptr,
                                   summary,
                                   statistics,
                                   history,
                                   {},
                                   [&](const unsigned int step,
                                       const double       t) {
                                     files.emplace_back(step, t);
                                   },
                                   {}};
  Analysis::EigenmodeAnalysis<2>(access).run();

  deallog << "assemblies: " << system.n_assemblies << std::endl;
  deallog << "max eigenvalue: " << summary.max_eigenvalue << std::endl;
  deallog << "zero eigenvalues: " << summary.n_zero_eigenvalues << std::endl;
  deallog << "lowest:";
  for (const double v : summary.eigenvalues)
    deallog << ' ' << (std::abs(v) < 1e-12 ? 0. : v);
  deallog << std::endl;
  AssertThrow(system.n_assemblies == 1, ExcInternalError());
  AssertThrow(std::abs(summary.max_eigenvalue - 5.) < 1e-12,
              ExcInternalError());
  AssertThrow(summary.n_zero_eigenvalues == 2, ExcInternalError());
  AssertThrow(summary.eigenvalues.size() == 3 &&
                std::abs(summary.eigenvalues[2] - 1.) < 1e-12,
              ExcInternalError());
  AssertThrow(summary.converged, ExcInternalError());
  AssertThrow(files.size() == 1 && files[0].first == 0 && files[0].second == 0.,
              ExcInternalError());

  std::ifstream table(prm.output.directory + "/eigenvalues.txt");
  std::string   header;
  std::getline(table, header);
  deallog << "eigenvalues.txt: " << header << std::endl;
  unsigned int index, n_rows = 0;
  double       value;
  while (table >> index >> value)
    {
      AssertThrow(index == ++n_rows &&
                    std::abs(value - summary.eigenvalues[index - 1]) < 1e-10,
                  ExcInternalError());
    }
  AssertThrow(n_rows == 3, ExcInternalError());
  deallog << "eigenvalues.txt rows: " << n_rows << std::endl;
  std::istringstream printed(log.str());
  for (std::string line; std::getline(printed, line);)
    deallog << "printed: " << line << std::endl;
  AssertThrow(log.str().find("below 1e-10 max: 2") != std::string::npos,
              ExcInternalError());
}
