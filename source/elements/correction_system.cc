#include <pg/base/exceptions.h>
#include <pg/elements/correction_system.h>
#include <pg/elements/second_order_correction.h>
#include <pg/solvers/linear_solver.h>

#include <deal.II/base/conditional_ostream.h>
#include <deal.II/base/mpi.h>
#include <deal.II/lac/solver_control.h>
#include <deal.II/lac/sparsity_tools.h>
#include <deal.II/lac/trilinos_index_access.h>
#include <deal.II/lac/trilinos_solver.h>
#include <deal.II/lac/trilinos_sparsity_pattern.h>

#include <Amesos.h>

#include <algorithm>
#include <cmath>
#include <limits>

namespace pg
{



  template <int dim>
  double
  CorrectionFactors<dim>::max_scaled_factor(
    const ParticleSet<dim> &particles) const
  {
    double largest = 0;
    for (unsigned int k = 0; k < alpha.size(); ++k)
      largest = std::max(largest, alpha[k].norm() * particles.spacing(k));
    return largest;
  }



  template <int dim>
  CorrectionSystem<dim>::CorrectionSystem(const FormulationCode &formulation,
                                          const MPI_Comm         comm,
                                          const std::string     &solver)
    : formulation(formulation)
    , comm(comm)
    , solver(solver)
  {
    Assert(formulation.variational_consistency, ExcInternalError());
    Assert(solver == "automatic" || solver == "ilu" || solver == "amg" ||
             solver == "direct",
           ExcInternalError());
  }



  template <int dim>
  void
  CorrectionSystem<dim>::reinit(const ParticleSet<dim>          &particles,
                                const FamilySet<dim>            &families,
                                const FamilyElements<dim>       &elements,
                                const std::vector<unsigned int> &owned_families,
                                const IndexSet                  &owned_dofs)
  {
    this->particles      = &particles;
    this->families       = &families;
    this->elements       = &elements;
    this->owned_families = owned_families;
    this->owned_dofs     = owned_dofs;

    const unsigned int n = particles.n_particles();
    if (formulation.second_order_consistency)
      {
        second_order_fixed.assign(n, false);
        for (unsigned int k = 0; k < n; ++k)
          {
            AssertThrow(
              !particles.on_interface(k),
              ExcBadParameter("Discretization/Formulation",
                              formulation.text,
                              "VC2 needs a body that is meshfree "
                              "everywhere: set 'Meshfree region = all' "
                              "in subsection 'Geometry', or use a "
                              "first-order VC code."));
            second_order_fixed[k] = !particles.boundary_area_vectors(k).empty();
          }
        return;
      }

    std::vector<types::global_dof_index> dofs;
    dofs.reserve(n * dim);
    for (unsigned int k = 0; k < n; ++k)
      for (unsigned int c = 0; c < dim; ++c)
        dofs.push_back(particles.dof(k, c));
    std::sort(dofs.begin(), dofs.end());
    particle_dofs = owned_dofs;
    particle_dofs.add_indices(dofs.begin(), dofs.end());
    particle_dofs.compress();

    classify_rows();
    make_sparsity_pattern();
    assemble_matrix();
    rhs.reinit(owned_dofs, comm);
    solution.reinit(owned_dofs, comm);
  }



  template <int dim>
  std::string
  CorrectionSystem<dim>::failure_advice(const FormulationCode &formulation)
  {
    // V4 keeps second-order consistency (eq. 5.58): the second-order Gauss
    // identities sum_k X^k (x) X^k (x) d^k then do not depend on the
    // factors either, and the system keeps null vectors that the options p
    // and sn do not remove (doc/ambiguities.md, item 22)
    const bool v4 = (formulation.correction_function ==
                     FormulationCode::CorrectionFunction::v4);
    return std::string(v4 ? "V4 keeps second-order consistency, which "
                            "leaves the system singular with the boundary "
                            "options p and sn; write V4s, or V3/V5, in " :
                            "change the VC boundary option (p, s or sn) "
                            "of ") +
           "'Formulation' in subsection 'Discretization', or check for "
           "coincident particles (unmerged mesh vertices: 'Coincident "
           "vertices' in subsection 'Geometry').";
  }



  template <int dim>
  void
  CorrectionSystem<dim>::set_prescribed_targets(
    const std::vector<Tensor<1, dim>> &targets)
  {
    prescribed_targets      = targets;
    formulation.vc_boundary = FormulationCode::VCBoundary::p;
  }



  template <int dim>
  void
  CorrectionSystem<dim>::make_sparsity_pattern()
  {
    // The blocks of family k couple a member a to alpha^k (PBG, PPG2), the
    // master to alpha^a and a to alpha^a (PPG1): one horizon, symmetric.
    // Rows of members owned elsewhere are sent to their owners.
    // Collected, sorted and added at once: IndexSet::add_index inserts out
    // of order indices into a sorted vector (a memmove each).
    std::vector<types::global_dof_index> member_dofs;
    for (const unsigned int k : owned_families)
      for (const unsigned int a : families->members(k))
        for (unsigned int c = 0; c < dim; ++c)
          member_dofs.push_back(particles->dof(a, c));
    std::sort(member_dofs.begin(), member_dofs.end());
    member_dofs.erase(std::unique(member_dofs.begin(), member_dofs.end()),
                      member_dofs.end());
    IndexSet rows = owned_dofs;
    rows.add_indices(member_dofs.begin(), member_dofs.end());
    rows.compress();
    sparsity_pattern.reinit(owned_dofs.size(), owned_dofs.size(), rows);
    // Whole sorted rows at a time: DynamicSparsityPattern inserts single
    // entries into sorted rows (a memmove each), which made this 8x slower
    // than the VC solve itself at 10^5 DoFs.
    std::vector<types::global_dof_index> columns, own;
    for (const unsigned int k : owned_families)
      {
        const auto members = families->members(k);
        columns.clear();
        for (const unsigned int a : members)
          for (unsigned int c = 0; c < dim; ++c)
            columns.push_back(particles->dof(a, c));
        // (a mirror image has its original's DoFs)
        std::sort(columns.begin(), columns.end());
        columns.erase(std::unique(columns.begin(), columns.end()),
                      columns.end());
        // the master's rows couple to every member (k to a, and a to a for
        // a = k)
        for (unsigned int i = 0; i < dim; ++i)
          sparsity_pattern.add_entries(particles->dof(k, i),
                                       columns.begin(),
                                       columns.end(),
                                       true);
        // a member's rows couple to the master and to itself
        for (const unsigned int a : members)
          {
            own.clear();
            for (unsigned int c = 0; c < dim; ++c)
              {
                own.push_back(particles->dof(k, c));
                own.push_back(particles->dof(a, c));
              }
            std::sort(own.begin(), own.end());
            own.erase(std::unique(own.begin(), own.end()), own.end());
            for (unsigned int i = 0; i < dim; ++i)
              sparsity_pattern.add_entries(particles->dof(a, i),
                                           own.begin(),
                                           own.end(),
                                           true);
          }
      }
    for (const auto dof : owned_dofs)
      sparsity_pattern.add(dof, dof);
    SparsityTools::distribute_sparsity_pattern(sparsity_pattern,
                                               owned_dofs,
                                               comm,
                                               rows);
    matrix.reinit(owned_dofs, owned_dofs, sparsity_pattern, comm);
  }



  template <int dim>
  void
  CorrectionSystem<dim>::assemble_matrix()
  {
    const unsigned int n = particles->n_particles();
    for (const unsigned int k : owned_families)
      elements->for_each_correction_block(
        k,
        [&](const unsigned int    image_a,
            const unsigned int    image_f,
            const Tensor<2, dim> &C_image) {
          // a mirror image's row is its original's row reflected, its
          // factors the original's reflected (diagonal reflections)
          const unsigned int a = particles->original(image_a);
          const unsigned int f = particles->original(image_f);
          if (kind[a] == Row::fixed)
            return;
          Tensor<2, dim> C = C_image;
          for (unsigned int i = 0; i < dim; ++i)
            for (unsigned int c = 0; c < dim; ++c)
              C[i][c] *= particles->mirror_sign(image_a, i) *
                         particles->mirror_sign(image_f, c);
          const Tensor<2, dim> RC = R[a] * C;
          for (unsigned int i = 0; i < dim; ++i)
            for (unsigned int c = 0; c < dim; ++c)
              if (RC[i][c] != 0.)
                matrix.add(particles->dof(a, i),
                           particles->dof(f, c),
                           RC[i][c]);
        });
    std::vector<bool> is_particle_dof(owned_dofs.size(), false);
    for (unsigned int k = 0; k < n; ++k)
      {
        for (unsigned int c = 0; c < dim; ++c)
          is_particle_dof[particles->dof(k, c)] = true;
        if (!owned_dofs.is_element(particles->dof(k, 0)))
          continue;
        for (unsigned int i = 0; i < dim; ++i)
          {
            const auto row = particles->dof(k, i);
            if (kind[k] == Row::fixed)
              matrix.add(row, row, 1.);
            else if (constraint[k][i].norm() > 0)
              for (unsigned int c = 0; c < dim; ++c)
                if (constraint[k][i][c] != 0.)
                  matrix.add(row, particles->dof(k, c), constraint[k][i][c]);
          }
      }
    for (const auto dof : owned_dofs)
      if (!is_particle_dof[dof])
        matrix.add(dof, dof, 1.);
    matrix.compress(VectorOperation::add);
  }



  template <int dim>
  CorrectionFactors<dim>
  CorrectionSystem<dim>::solve(const std::vector<Tensor<1, dim>> &unit_stress)
  {
    Assert(particles != nullptr, ExcMessage("Call reinit() first."));
    const unsigned int n = particles->n_particles();
    AssertDimension(unit_stress.size(), n);
    CorrectionFactors<dim> factors;
    if (formulation.second_order_consistency)
      {
        const SecondOrderCorrection<dim> correction =
          solve_second_order_correction(*particles,
                                        *families,
                                        *elements,
                                        second_order_fixed);
        factors.alpha              = correction.alpha;
        factors.second_order_alpha = correction.second_order_alpha;
        factors.max_second_order_residual =
          correction.max_second_order_residual_after;
        return factors;
      }

    rhs = 0;
    for (unsigned int k = 0; k < n; ++k)
      {
        if (!owned_dofs.is_element(particles->dof(k, 0)))
          continue;
        const Tensor<1, dim> r = R[k] * (target[k] - unit_stress[k]);
        for (unsigned int i = 0; i < dim; ++i)
          if (kind[k] != Row::fixed && constraint[k][i].norm() == 0)
            rhs(particles->dof(k, i)) = r[i];
      }
    rhs.compress(VectorOperation::insert);

    // Iterative (the default where the system is regular): GMRES from
    // alpha = 0, with ILU(0) on small systems and ML AMG first on large
    // ones (amg_from_rows). The matrix is one horizon wide and behaves like
    // a discrete Laplacian per component (C^kk = -sum_q w Q^kq on the
    // diagonal): the AMG's near-null space is the constant of each
    // component. 3-D cantilever, V5sn, 1.51 h: a VC set-up of 2.5 s at
    // 56,355 DoFs where KLU took 147 s (doc/benchmarks/vc_solve.md). The
    // AMG breaks down on other geometries (3-D Cook membrane: on hexahedra
    // 32 x 32 x 8 a true residual of 2.8e-5 where GMRES reported 1e-13, on
    // tetrahedra no progress in 2000 iterations), so the automatic choice
    // gives it amg_stagnation_iterations to reach 1e-4 and falls back to
    // ILU(0) if it does not, or if its true residual misses.
    //
    // The system is singular but consistent with FE coupling plus a free
    // surface: affine fields tangential on the surface give rows that do
    // not depend on alpha (doc/element-view.md section 5). GMRES then
    // returns some member of the solution set, with an arbitrary
    // null-space part (2-D coupled patch test, VCBCPBG V5sn Unl: max
    // |alpha| h = 115 against 8.4, and Newton inverts elements), so such
    // systems are solved directly: iterative refinement with a slightly
    // shifted factorization,
    //   alpha <- alpha + (A + eps D)^{-1} (b - A alpha),  alpha_0 = 0,
    // which converges in a few steps on the regular part (eps << |lambda|)
    // and keeps the null-space part small: the same factors on any number
    // of MPI ranks. D is the largest entry of each row. Factors by serial
    // KLU on one rank, by distributed MUMPS on more (KLU would hold all
    // factors on rank 0; MUMPS changes the round-off digits of alpha).
    //
    // V2 (second derivatives, zero sum over the neighbours) leaves zero
    // blocks on the diagonal, on which ILU(0) breaks down: solved directly.
    const bool zero_diagonal = (formulation.correction_function ==
                                FormulationCode::CorrectionFunction::v2);
    const bool use_amg =
      solver == "amg" || (solver == "automatic" && matrix.m() >= amg_from_rows);
    const bool iterative = solver != "direct" && !singular && !zero_diagonal;
    factors.solver       = (solver == "direct" ? "direct" :
                            singular           ? "direct (singular system)" :
                            zero_diagonal      ? "direct (V2: zero diagonal)" :
                            use_amg            ? "GMRES + AMG" :
                                                 "GMRES + ILU(0)");
    ConditionalOStream note(std::cout,
                            Utilities::MPI::this_mpi_process(comm) == 0);
    // One GMRES attempt; false (with a note) where it fails.
    const auto attempt = [&](const GMRESPreconditioner preconditioner,
                             const unsigned int        stagnation_iterations,
                             const std::string        &instead) {
      try
        {
          factors.solver_iterations =
            solve_by_gmres(matrix,
                           solution,
                           rhs,
                           preconditioner,
                           preconditioner == GMRESPreconditioner::amg ?
                             component_modes() :
                             std::vector<std::vector<bool>>(),
                           relative_tolerance,
                           max_iterations,
                           stagnation_iterations);
          return true;
        }
      catch (const SolverControl::NoConvergence &failure)
        {
          note << "  note: the iterative VC solve ("
               << (preconditioner == GMRESPreconditioner::amg ?
                     "GMRES + AMG" :
                     "GMRES + ILU(0)")
               << ") did not converge: |b - A alpha| / |b| = "
               << failure.last_residual / rhs.l2_norm() << " after "
               << failure.last_step << " iterations; " << instead << std::endl;
          return false;
        }
    };
    if (iterative)
      {
        const std::string direct_instead =
          "solving it directly instead ('VC solver = direct' in subsection "
          "'Linear solver' skips the attempt).";
        if (use_amg && solver == "automatic")
          {
            if (!attempt(GMRESPreconditioner::amg,
                         amg_stagnation_iterations,
                         "GMRES + ILU(0) instead ('VC solver = ilu' in "
                         "subsection 'Linear solver' skips the attempt)."))
              {
                factors.solver = "GMRES + ILU(0) (after AMG)";
                if (!attempt(GMRESPreconditioner::ilu, 0, direct_instead))
                  factors.solver = "direct (fallback)";
              }
          }
        else if (!attempt(use_amg ? GMRESPreconditioner::amg :
                                    GMRESPreconditioner::ilu,
                          0,
                          direct_instead))
          factors.solver = "direct (fallback)";
      }
    if (!iterative || factors.solver == "direct (fallback)")
      {
        static const bool  have_mumps  = Amesos().Query("Amesos_Mumps");
        const unsigned int corrections = solve_by_shifted_refinement(
          matrix,
          solution,
          rhs,
          1e-9,
          1e-14,
          50,
          1e-12,
          Utilities::MPI::n_mpi_processes(comm) > 1 && have_mumps ?
            "Amesos_Mumps" :
            "Amesos_Klu");
        AssertThrow(corrections < 50,
                    ExcMessage("The VC system could not be solved: " +
                               failure_advice(formulation)));
      }
    LinearAlgebra::Vector ghosted(owned_dofs, particle_dofs, comm);
    ghosted = solution;
    factors.alpha.resize(n);
    for (unsigned int k = 0; k < n; ++k)
      for (unsigned int c = 0; c < dim; ++c)
        factors.alpha[k][c] = ghosted[particles->dof(k, c)];
    AssertThrow(std::all_of(factors.alpha.begin(),
                            factors.alpha.end(),
                            [](const Tensor<1, dim> &a) {
                              return std::isfinite(a.norm());
                            }),
                ExcMessage("The VC system is singular: change the VC "
                           "boundary option of 'Formulation' in subsection "
                           "'Discretization' (p, s or sn)."));
    return factors;
  }



  template <int dim>
  std::vector<std::vector<bool>>
  CorrectionSystem<dim>::component_modes() const
  {
    std::vector<std::vector<bool>> modes(
      dim,
      std::vector<bool>(owned_dofs.n_elements(), false));
    for (unsigned int k = 0; k < particles->n_particles(); ++k)
      for (unsigned int c = 0; c < dim; ++c)
        if (owned_dofs.is_element(particles->dof(k, c)))
          modes[c][owned_dofs.index_within_set(particles->dof(k, c))] = true;
    return modes;
  }



  template <int dim>
  const LinearAlgebra::SparseMatrix &
  CorrectionSystem<dim>::system_matrix() const
  {
    return matrix;
  }



  template <int dim>
  CorrectionFactors<dim>
  correct_family_tables(CorrectionSystem<dim>             &system,
                        const ParticleSet<dim>            &particles,
                        const FamilySet<dim>              &families,
                        FamilyElements<dim>               &elements,
                        const std::vector<unsigned int>   &owned_families,
                        const IndexSet                    &owned_dofs,
                        const std::vector<Tensor<1, dim>> &unit_stress,
                        std::vector<QuadratureTable<dim>> &tables)
  {
    AssertDimension(tables.size(), owned_families.size());
    system.reinit(particles, families, elements, owned_families, owned_dofs);
    CorrectionFactors<dim> factors = system.solve(unit_stress);
    elements.set_correction_factors(factors.alpha, factors.second_order_alpha);
    elements.correct(owned_families, tables);
    return factors;
  }



  template struct CorrectionFactors<2>;
  template struct CorrectionFactors<3>;
  template class CorrectionSystem<2>;
  template class CorrectionSystem<3>;
  template CorrectionFactors<2>
  correct_family_tables(CorrectionSystem<2> &,
                        const ParticleSet<2> &,
                        const FamilySet<2> &,
                        FamilyElements<2> &,
                        const std::vector<unsigned int> &,
                        const IndexSet &,
                        const std::vector<Tensor<1, 2>> &,
                        std::vector<QuadratureTable<2>> &);
  template CorrectionFactors<3>
  correct_family_tables(CorrectionSystem<3> &,
                        const ParticleSet<3> &,
                        const FamilySet<3> &,
                        FamilyElements<3> &,
                        const std::vector<unsigned int> &,
                        const IndexSet &,
                        const std::vector<Tensor<1, 3>> &,
                        std::vector<QuadratureTable<3>> &);
} // namespace pg
