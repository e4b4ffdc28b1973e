#include <pg/base/exceptions.h>
#include <pg/solvers/linear_solver.h>

#include <deal.II/base/timer.h>
#include <deal.II/dofs/dof_tools.h>
#include <deal.II/lac/solver_cg.h>
#include <deal.II/lac/solver_control.h>
#include <deal.II/lac/solver_gmres.h>
#include <deal.II/lac/trilinos_index_access.h>
#include <deal.II/lac/trilinos_precondition.h>
#include <deal.II/lac/trilinos_solver.h>
#include <deal.II/lac/trilinos_sparsity_pattern.h>

#include <Amesos.h>
#include <Epetra_MultiVector.h>
#include <Teuchos_ParameterList.hpp>
#include <ml_ValidateParameters.h>
#include <ml_config.h>

#include <algorithm>
#include <cmath>
#include <cstdlib>
#include <limits>
#include <memory>
#include <vector>

namespace pg
{
  namespace
  {
    /**
     * The rigid body modes of elasticity at the vertex DoFs of this rank,
     * rows in the local order of @p map: dim translations, then the
     * rotations about the centroid of all vertices (2-D: 1, 3-D: 3), u =
     * e_c and u = omega x (x - centroid). The near-null space of the
     * tangent for ML's smoothed aggregation (ML's "null space: type" =
     * "pre-computed").
     */
    template <int dim>
    std::unique_ptr<Epetra_MultiVector>
    rigid_body_modes(const DoFHandler<dim> &dof_handler, const Epetra_Map &map)
    {
      const unsigned int n_modes = (dim == 2 ? 3 : 6);
      auto modes = std::make_unique<Epetra_MultiVector>(map, n_modes, true);
      // the centroid of the vertices (the same on every rank)
      const auto  &tria = dof_handler.get_triangulation();
      Point<dim>   centroid;
      unsigned int n_used = 0;
      for (unsigned int v = 0; v < tria.n_vertices(); ++v)
        if (tria.get_used_vertices()[v])
          {
            centroid += tria.get_vertices()[v];
            ++n_used;
          }
      centroid /= std::max(1U, n_used);
      for (const auto &cell : dof_handler.active_cell_iterators())
        if (!cell->is_artificial())
          for (const unsigned int v : cell->vertex_indices())
            {
              const Tensor<1, dim> x = cell->vertex(v) - centroid;
              for (unsigned int c = 0; c < dim; ++c)
                {
                  const int row =
                    map.LID(static_cast<TrilinosWrappers::types::int_type>(
                      cell->vertex_dof_index(v, c)));
                  if (row < 0)
                    continue;
                  (*modes)[c][row] = 1.;
                  // omega x x for omega = e_z (2-D and 3-D), e_x, e_y
                  if (c == 0)
                    (*modes)[dim][row] = -x[1];
                  if (c == 1)
                    (*modes)[dim][row] = x[0];
                  if constexpr (dim == 3)
                    {
                      if (c == 1)
                        (*modes)[4][row] = -x[2];
                      if (c == 2)
                        (*modes)[4][row] = x[1];
                      if (c == 2)
                        (*modes)[5][row] = -x[0];
                      if (c == 0)
                        (*modes)[5][row] = x[2];
                    }
                }
            }
      return modes;
    }
  } // namespace



  void
  set_ml_parameter(Teuchos::ParameterList &list,
                   const std::string      &name,
                   const std::string      &value)
  {
    static const std::unique_ptr<const Teuchos::ParameterList> valid(
      ML_Epetra::GetValidMLPParameters());
    const std::string entry = "Linear solver/AMG parameters";
    const std::string item  = name + " = " + value;
    // ML's list of valid parameters leaves out the coarse-level entries
    // that it reads all the same ('coarse: max size', 'coarse: type'):
    // their type is the one the value reads as.
    const Teuchos::ParameterEntry *known  = valid->getEntryPtr(name);
    const bool                     coarse = (name.rfind("coarse: ", 0) == 0);
    AssertThrow((known != nullptr && !known->isList()) || coarse,
                ExcBadParameter(entry,
                                item,
                                "ML has no parameter '" + name +
                                  "' (the names are ML's, case and blanks "
                                  "included: ML user's guide, chapter 6)."));
#ifndef HAVE_ML_METIS
    // without METIS, ML puts all nodes into one aggregate and then stops
    // the process from inside MPI
    AssertThrow(name.rfind("aggregation: type", 0) != 0 ||
                  value.find("METIS") == std::string::npos,
                ExcBadParameter(entry,
                                item,
                                "this Trilinos ML was built without METIS: "
                                "use 'Uncoupled', 'MIS' or 'Uncoupled-MIS'."));
#endif
    const auto reads_as = [&value](auto &number, const auto &convert) {
      char *end = nullptr;
      number    = convert(value.c_str(), &end);
      return end != value.c_str() && *end == '\0';
    };
    long       integer = 0;
    double     real    = 0.;
    const auto to_long = [](const char *s, char **e) {
      return std::strtol(s, e, 10);
    };
    const auto to_double = [](const char *s, char **e) {
      return std::strtod(s, e);
    };
    // the type of ML's entry, else of the entry already in the list
    // (deal.II's 'coarse: max size' is an int)
    const Teuchos::ParameterEntry *typed =
      (known != nullptr ? known : list.getEntryPtr(name));
    if (typed == nullptr)
      {
        // a coarse-level entry: int, double, bool or string, as it reads
        if (reads_as(integer, to_long))
          list.set(name, static_cast<int>(integer));
        else if (reads_as(real, to_double))
          list.set(name, real);
        else if (value == "true" || value == "false")
          list.set(name, value == "true");
        else
          list.set(name, value);
      }
    else if (typed->isType<int>())
      {
        AssertThrow(reads_as(integer, to_long),
                    ExcBadParameter(entry,
                                    item,
                                    "ML's '" + name + "' is an integer."));
        list.set(name, static_cast<int>(integer));
      }
    else if (typed->isType<double>())
      {
        AssertThrow(reads_as(real, to_double),
                    ExcBadParameter(entry,
                                    item,
                                    "ML's '" + name + "' is a number."));
        list.set(name, real);
      }
    else if (typed->isType<bool>())
      {
        AssertThrow(value == "true" || value == "false",
                    ExcBadParameter(entry,
                                    item,
                                    "ML's '" + name + "' is true or false."));
        list.set(name, value == "true");
      }
    else
      list.set(name, value);
  }



  template <int dim>
  unsigned int
  solve_linear_system(
    const Parameters::LinearSolver                             &parameters,
    const DoFHandler<dim>                                      &dof_handler,
    const LinearAlgebra::SparseMatrix                          &matrix,
    LinearAlgebra::Vector                                      &solution,
    const LinearAlgebra::Vector                                &rhs,
    AMGCache                                                   *cache,
    const std::function<const LinearAlgebra::SparseMatrix *()> &amg_operator)
  {
    if (parameters.type == "direct")
      {
        // MUMPS (multifrontal, dense BLAS kernels) factorizes the wide PG
        // stencils several times faster than KLU (doc/benchmarks/
        // profiling.md); KLU where Trilinos was built without MUMPS.
        static const bool have_mumps = Amesos().Query("Amesos_Mumps");
        SolverControl     control(1, 0, false, false);
        TrilinosWrappers::SolverDirect::AdditionalData data(false,
                                                            have_mumps ?
                                                              "Amesos_Mumps" :
                                                              "Amesos_Klu");
        TrilinosWrappers::SolverDirect                 solver(control, data);
        solver.solve(matrix, solution, rhs);
        return 0;
      }

    // a hierarchy to keep, or this solve's own; builds are counted in the
    // cache either way
    AMGCache  own;
    AMGCache &amg = (cache != nullptr && parameters.reuse_amg) ? *cache : own;
    unsigned int &n_builds = (cache != nullptr ? *cache : own).n_builds;
    // a hierarchy from @p hierarchy_matrix, applied to (a later) matrix
    const auto build = [&](
                         const LinearAlgebra::SparseMatrix &hierarchy_matrix) {
      amg.clear();
      amg.amg = std::make_unique<TrilinosWrappers::PreconditionAMG>();
      TrilinosWrappers::PreconditionAMG::AdditionalData amg_data;
      std::vector<std::vector<bool>>                    constant_modes;
      DoFTools::extract_constant_modes(dof_handler,
                                       ComponentMask(),
                                       constant_modes);
      amg_data.constant_modes  = constant_modes;
      amg_data.elliptic        = (parameters.type == "cg");
      amg_data.smoother_sweeps = 2;
      // deal.II's ML parameters, then the rigid body modes as the null
      // space, then the user's 'AMG parameters'
      Teuchos::ParameterList              ml_parameters;
      std::unique_ptr<Epetra_MultiVector> translations;
      amg_data.set_parameters(ml_parameters, translations, hierarchy_matrix);
      // ML copies the null space in its set-up (deal.II's own
      // PreconditionAMG::initialize() frees its modes after it, too)
      std::unique_ptr<Epetra_MultiVector> modes;
      if (parameters.near_null_space == "rigid body modes")
        {
          modes = rigid_body_modes(dof_handler,
                                   matrix.trilinos_matrix().RowMatrixRowMap());
          ml_parameters.set("null space: type", "pre-computed");
          ml_parameters.set("null space: dimension", modes->NumVectors());
          ml_parameters.set("null space: vectors", modes->Values());
        }
      for (const auto &[name, value] : parameters.amg_parameters)
        set_ml_parameter(ml_parameters, name, value);
      amg.amg->initialize(hierarchy_matrix, ml_parameters);
      amg.matrix = &matrix;
      ++n_builds;
    };

    const unsigned int max_iterations =
      std::max<unsigned int>(1000, rhs.size());
    const auto krylov = [&](const unsigned int max_steps) {
      SolverControl control(max_steps,
                            parameters.tolerance * rhs.l2_norm(),
                            false,
                            false);
      if (parameters.type == "cg")
        {
          SolverCG<LinearAlgebra::Vector> cg(control);
          cg.solve(matrix, solution, rhs, *amg.amg);
        }
      else
        {
          // right preconditioning: the stopping test sees the true residual
          // (with left preconditioning it sees the AMG-preconditioned one,
          // and Newton then needs extra steps on linear problems)
          SolverGMRES<LinearAlgebra::Vector> gmres(
            control,
            SolverGMRES<LinearAlgebra::Vector>::AdditionalData(
              100,
              /*right_preconditioning=*/true));
          gmres.solve(matrix, solution, rhs, *amg.amg);
        }
      return control.last_step();
    };

    // The solve with a new hierarchy: from the AMG operator if there is one
    // (at most 1000 iterations), else, or if the operator fails or does not
    // converge, from the tangent. Adds the iterations of a failed attempt
    // to @p failed_iterations.
    const LinearAlgebra::Vector start = solution;
    AMGCache                   &state = (cache != nullptr ? *cache : own);
    // 'automatic': a Q1 hierarchy that converges slowly is tried once
    // against the tangent's on the same system; the faster one stays
    const auto trial = [&](const unsigned int q1_iterations,
                           const double       q1_seconds) {
      state.operator_tried                                           = true;
      const LinearAlgebra::Vector                        q1_solution = solution;
      std::unique_ptr<TrilinosWrappers::PreconditionAMG> q1_amg =
        std::move(amg.amg);
      solution = start;
      Timer timer;
      try
        {
          build(matrix);
          const unsigned int iterations = krylov(q1_iterations);
          if (timer.wall_time() < q1_seconds)
            {
              state.operator_rejected = true;
              amg.first_iterations    = iterations;
              return q1_iterations + iterations;
            }
          amg.amg              = std::move(q1_amg);
          amg.matrix           = &matrix;
          amg.first_iterations = q1_iterations;
          solution             = q1_solution;
          return q1_iterations + iterations;
        }
      catch (const SolverControl::NoConvergence &failure)
        {
          amg.amg              = std::move(q1_amg);
          amg.matrix           = &matrix;
          amg.first_iterations = q1_iterations;
          solution             = q1_solution;
          return q1_iterations + failure.last_step;
        }
    };
    const auto with_new_hierarchy = [&](unsigned int failed_iterations) {
      if (const LinearAlgebra::SparseMatrix *auxiliary =
            (amg_operator && !state.operator_rejected ? amg_operator() :
                                                        nullptr))
        try
          {
            Timer timer;
            build(*auxiliary);
            amg.first_iterations = krylov(1000);
            if (parameters.amg_operator == "automatic" && cache != nullptr &&
                !state.operator_tried &&
                amg.first_iterations > operator_trial_iterations)
              return failed_iterations +
                     trial(amg.first_iterations, timer.wall_time());
            return failed_iterations + amg.first_iterations;
          }
        catch (const SolverControl::NoConvergence &failure)
          {
            failed_iterations += failure.last_step;
            solution = start;
          }
      build(matrix);
      amg.first_iterations = krylov(max_iterations);
      return failed_iterations + amg.first_iterations;
    };

    if (amg.amg == nullptr || amg.matrix != &matrix)
      return with_new_hierarchy(0);
    // an old hierarchy: on failure, a new one for this solve; on slow
    // convergence, a new one for the next
    try
      {
        const unsigned int iterations = krylov(max_iterations);
        if (2 * iterations > 3 * amg.first_iterations + 10)
          amg.clear();
        return iterations;
      }
    catch (const SolverControl::NoConvergence &failure)
      {
        solution = start;
        return with_new_hierarchy(failure.last_step);
      }
  }



  AMGCache::AMGCache() = default;



  AMGCache::~AMGCache() = default;



  void
  AMGCache::clear()
  {
    amg.reset();
    matrix = nullptr;
  }



  unsigned int
  solve_by_gmres(const LinearAlgebra::SparseMatrix    &matrix,
                 LinearAlgebra::Vector                &solution,
                 const LinearAlgebra::Vector          &rhs,
                 const GMRESPreconditioner             preconditioner,
                 const std::vector<std::vector<bool>> &constant_modes,
                 const double                          tolerance,
                 const unsigned int                    max_iterations,
                 const unsigned int                    stagnation_iterations)
  {
    std::unique_ptr<TrilinosWrappers::PreconditionBase> inverse;
    if (preconditioner == GMRESPreconditioner::ilu)
      {
        auto ilu = std::make_unique<TrilinosWrappers::PreconditionILU>();
        ilu->initialize(matrix);
        inverse = std::move(ilu);
      }
    else
      {
        // The VC system on the 3-D cantilever (doc/benchmarks/vc_solve.md):
        // Chebyshev smoothing and symmetric smoothed aggregation diverge
        // (the matrix is not symmetric), Gauss-Seidel smoothing needs 3 to 4
        // times the iterations, an aggregation threshold of 0.02 or more
        // only makes the set-up dearer
        auto amg = std::make_unique<TrilinosWrappers::PreconditionAMG>();
        TrilinosWrappers::PreconditionAMG::AdditionalData data;
        data.elliptic       = false;
        data.smoother_type  = "ILU";
        data.constant_modes = constant_modes;
        amg->initialize(matrix, data);
        inverse = std::move(amg);
      }
    solution = 0;
    SolverControl                      control(max_iterations,
                          tolerance * rhs.l2_norm(),
                          false,
                          false);
    SolverGMRES<LinearAlgebra::Vector> gmres(
      control,
      SolverGMRES<LinearAlgebra::Vector>::AdditionalData(
        200,
        /*right_preconditioning=*/true));
    const double rhs_norm = rhs.l2_norm();
    if (stagnation_iterations > 0)
      gmres.connect([&](const unsigned int step,
                        const double       residual,
                        const LinearAlgebra::Vector &) {
        return (step >= stagnation_iterations && residual > 1e-4 * rhs_norm) ?
                 SolverControl::failure :
                 SolverControl::success;
      });
    gmres.solve(matrix, solution, rhs, *inverse);
    // GMRES stops on its own residual estimate, which equals |b - A x| in
    // exact arithmetic only: with ML AMG on the VC system of the 3-D Cook
    // membrane (hexahedra 32 x 32 x 8) it reported 1e-13 where the true
    // residual was 2.8e-5 (doc/benchmarks/vc_solve.md).
    LinearAlgebra::Vector residual(rhs);
    matrix.vmult(residual, solution);
    residual -= rhs;
    if (residual.l2_norm() > 100. * tolerance * rhs.l2_norm())
      throw SolverControl::NoConvergence(control.last_step(),
                                         residual.l2_norm());
    return control.last_step();
  }



  unsigned int
  solve_by_shifted_refinement(const LinearAlgebra::SparseMatrix &matrix,
                              LinearAlgebra::Vector             &solution,
                              const LinearAlgebra::Vector       &rhs,
                              const double                       relative_shift,
                              const double                       tolerance,
                              const unsigned int max_corrections,
                              const double       floor_tolerance,
                              const std::string &direct_solver)
  {
    using size_type = types::global_dof_index;
    // The owned rows of A + eps D without the stored zeros of A, read
    // through Epetra row views: deal.II's row iterators copy a row on every
    // construction, and end(row) is one.
    const Epetra_CrsMatrix  &A = matrix.trilinos_matrix();
    std::vector<size_type>   rows, columns;
    std::vector<double>      values;
    std::vector<std::size_t> row_start(1, 0);
    for (int r = 0; r < A.NumMyRows(); ++r)
      {
        int     n_entries;
        double *row_values;
        int    *row_columns;
        A.ExtractMyRowView(r, n_entries, row_values, row_columns);
        const size_type row          = TrilinosWrappers::global_row_index(A, r);
        double          largest      = 0;
        std::size_t     diagonal     = 0;
        bool            has_diagonal = false;
        for (int i = 0; i < n_entries; ++i)
          {
            largest = std::max(largest, std::abs(row_values[i]));
            const size_type column =
              TrilinosWrappers::global_column_index(A, row_columns[i]);
            if (column == row)
              {
                diagonal     = columns.size();
                has_diagonal = true;
              }
            if (row_values[i] != 0. || column == row)
              {
                columns.push_back(column);
                values.push_back(row_values[i]);
              }
          }
        if (!has_diagonal)
          {
            diagonal = columns.size();
            columns.push_back(row);
            values.push_back(0.);
          }
        values[diagonal] += relative_shift * largest;
        rows.push_back(row);
        row_start.push_back(columns.size());
      }

    TrilinosWrappers::SparsityPattern pattern(
      matrix.locally_owned_range_indices(),
      matrix.locally_owned_domain_indices(),
      matrix.get_mpi_communicator());
    for (unsigned int r = 0; r < rows.size(); ++r)
      pattern.add_entries(rows[r],
                          columns.begin() + row_start[r],
                          columns.begin() + row_start[r + 1]);
    pattern.compress();
    LinearAlgebra::SparseMatrix shifted;
    shifted.reinit(pattern);
    for (unsigned int r = 0; r < rows.size(); ++r)
      shifted.set(rows[r],
                  row_start[r + 1] - row_start[r],
                  columns.data() + row_start[r],
                  values.data() + row_start[r]);
    shifted.compress(VectorOperation::insert);
    // the copies are in the matrix now: free them before the factorization
    rows    = {};
    columns = {};
    values  = {};

    SolverControl                  control(1, 0, false, false);
    TrilinosWrappers::SolverDirect solver(
      control,
      TrilinosWrappers::SolverDirect::AdditionalData(false, direct_solver));
    solver.initialize(shifted);
    LinearAlgebra::Vector residual(rhs), correction(rhs);
    solution                 = 0;
    const double rhs_norm    = rhs.l2_norm();
    double       previous    = std::numeric_limits<double>::infinity();
    unsigned int corrections = 0;
    for (; corrections < max_corrections; ++corrections)
      {
        matrix.vmult(residual, solution);
        residual.sadd(-1., 1., rhs);
        const double norm = residual.l2_norm();
        if (norm <= tolerance * rhs_norm)
          break;
        // the round-off floor of b - A x: small, and no longer halved
        if (norm <= floor_tolerance * rhs_norm && norm > 0.5 * previous)
          break;
        previous = norm;
        solver.solve(correction, residual);
        solution += correction;
      }
    return corrections;
  }



  template unsigned int
  solve_linear_system<2>(
    const Parameters::LinearSolver &,
    const DoFHandler<2> &,
    const LinearAlgebra::SparseMatrix &,
    LinearAlgebra::Vector &,
    const LinearAlgebra::Vector &,
    AMGCache *,
    const std::function<const LinearAlgebra::SparseMatrix *()> &);
  template unsigned int
  solve_linear_system<3>(
    const Parameters::LinearSolver &,
    const DoFHandler<3> &,
    const LinearAlgebra::SparseMatrix &,
    LinearAlgebra::Vector &,
    const LinearAlgebra::Vector &,
    AMGCache *,
    const std::function<const LinearAlgebra::SparseMatrix *()> &);
} // namespace pg
