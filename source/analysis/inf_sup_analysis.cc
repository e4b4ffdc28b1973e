#include <pg/analysis/inf_sup.h>
#include <pg/analysis/inf_sup_analysis.h>
#include <pg/base/exceptions.h>
#include <pg/elements/element_group.h>
#include <pg/elements/nodal_pressure.h>
#include <pg/elements/q1_cell.h>
#include <pg/elements/quadrature_table.h>
#include <pg/postprocess/output.h>

#include <deal.II/base/quadrature_lib.h>
#include <deal.II/fe/fe_values.h>

#include <Eigen/Dense>

#include <cmath>
#include <fstream>
#include <functional>
#include <iomanip>
#include <limits>
#include <sstream>

namespace pg
{
  namespace Analysis
  {
    template <int dim>
    InfSupAnalysis<dim>::InfSupAnalysis(const Access<dim>  &access,
                                        const SetUpProblem &set_up)
      : Interface<dim>(access)
      , set_up(set_up)
    {}



    namespace
    {
      /**
       * Calls @p add(table, y, dofs) for every Q1 cell of @p view in the
       * undeformed state (y^b = X^b - X^0): the cell part of both ways of
       * assembling T_h and S_h.
       */
      template <int dim>
      void
      for_each_q1_cell(
        const Postprocess::ProblemView<dim> &view,
        const std::function<void(const QuadratureTable<dim> &,
                                 const std::vector<Tensor<1, dim>> &,
                                 const std::vector<types::global_dof_index> &)>
          &add)
      {
        FEValues<dim>                        fe_values(view.cells->mapping(),
                                *view.fe_scalar,
                                view.cells->fe_cell_quadrature(),
                                update_gradients | update_JxW_values);
        QuadratureTable<dim>                 table;
        std::vector<Tensor<1, dim>>          y;
        std::vector<types::global_dof_index> dofs;
        for (const auto &cell : *view.owned_fe_cells)
          {
            fe_values.reinit(
              typename Triangulation<dim>::active_cell_iterator(cell));
            fill_q1_table(fe_values, table);
            dofs.resize(view.fe->n_dofs_per_cell());
            cell->get_dof_indices(dofs);
            y.resize(cell->n_vertices());
            for (unsigned int b = 0; b < y.size(); ++b)
              y[b] = cell->vertex(b) - cell->vertex(0);
            add(table, y, dofs);
          }
      }


      /**
       * The undeformed family @p f of @p view: y^b = X^b - X^k of its
       * members and their displacement DoFs, node-major.
       */
      template <int dim>
      void
      undeformed_family(const Postprocess::ProblemView<dim>  &view,
                        const unsigned int                    f,
                        std::vector<Tensor<1, dim>>          &y,
                        std::vector<types::global_dof_index> &dofs,
                        std::vector<double>                  &signs)
      {
        const ParticleSet<dim> &particles = *view.particles;
        const unsigned int      k         = (*view.owned_families)[f];
        const auto              members   = view.families->members(k);
        dofs.resize(members.size() * dim);
        signs.resize(members.size() * dim);
        y.resize(members.size());
        for (unsigned int b = 0; b < members.size(); ++b)
          {
            y[b] = particles.position(members[b]) - particles.position(k);
            for (unsigned int c = 0; c < dim; ++c)
              {
                dofs[b * dim + c]  = particles.dof(members[b], c);
                signs[b * dim + c] = particles.mirror_sign(members[b], c);
              }
          }
      }
    } // namespace



    template <int dim>
    void
    InfSupAnalysis<dim>::assemble_forms(const Access<dim>           &level,
                                        LinearAlgebra::SparseMatrix &T,
                                        LinearAlgebra::SparseMatrix &S)
    {
      Assert(level.view != nullptr, ExcInternalError());
      const Postprocess::ProblemView<dim> &view = *level.view;
      const AffineConstraints<double>     &zero_constraints =
        level.system.homogeneous_constraints();
      const InfSup::PressureProjectionMaterial<dim> t_material;
      const InfSup::H1Material<dim>                 s_material;
      // The condensed pressure of the mixed spaces: constant per Q1 cell,
      // constant (P0) or linear (P1) per family.
      const std::string &space = level.parameters.analysis.pressure_space;
      const bool         mixed = (space != "displacement");
      const unsigned int family_degree = (space == "P1" ? 1 : 0);
      T.copy_from(level.system.tangent());
      T = 0;
      S.copy_from(level.system.tangent());
      S = 0;
      FullMatrix<double> t_local, s_local;
      Vector<double>     residual;
      // The undeformed state: y^b = X^b - X^0 (u = 0; both forms are linear).
      const auto add = [&](const QuadratureTable<dim>                 &table,
                           const std::vector<Tensor<1, dim>>          &y,
                           const std::vector<types::global_dof_index> &dofs,
                           const unsigned int                          degree,
                           const std::vector<double> &signs = {}) {
        if (mixed)
          InfSup::pressure_projection(table, y, degree, t_local);
        else
          assemble_element(table, y, t_material, residual, &t_local);
        assemble_element(table, y, s_material, residual, &s_local);
        // mirror images: reflected components
        apply_dof_signs(signs, t_local);
        apply_dof_signs(signs, s_local);
        zero_constraints.distribute_local_to_global(t_local, dofs, T);
        zero_constraints.distribute_local_to_global(s_local, dofs, S);
      };
      for_each_q1_cell<dim>(
        view,
        [&](const QuadratureTable<dim>                 &table,
            const std::vector<Tensor<1, dim>>          &y,
            const std::vector<types::global_dof_index> &dofs) {
          add(table, y, dofs, 0);
        });
      std::vector<Tensor<1, dim>>          y;
      std::vector<types::global_dof_index> dofs;
      std::vector<double>                  signs;
      for (unsigned int f = 0; f < view.owned_families->size(); ++f)
        {
          undeformed_family(view, f, y, dofs, signs);
          add((*view.family_tables)[f], y, dofs, family_degree, signs);
        }
      T.compress(VectorOperation::add);
      S.compress(VectorOperation::add);
    }



    template <int dim>
    unsigned int
    InfSupAnalysis<dim>::assemble_nodal_forms(const Access<dim> &level,
                                              const bool         bubble,
                                              const unsigned int max_size,
                                              LAPACKFullMatrix<double> &T,
                                              LAPACKFullMatrix<double> &S)
    {
      Assert(level.view != nullptr, ExcInternalError());
      const Postprocess::ProblemView<dim> &view = *level.view;
      const AffineConstraints<double>     &constraints =
        level.system.homogeneous_constraints();
      const ParticleSet<dim>       &particles = *view.particles;
      const InfSup::H1Material<dim> s_material;

      // The dense unknowns: the free DoFs, then the bubbles.
      const types::global_dof_index n_dofs = view.dof_handler->n_dofs();
      std::vector<int>              dense(n_dofs, -1);
      unsigned int                  n_u = 0;
      for (types::global_dof_index i = 0; i < n_dofs; ++i)
        if (!constraints.is_constrained(i))
          dense[i] = n_u++;
      const unsigned int n_families = view.owned_families->size();
      const unsigned int n          = n_u + (bubble ? dim * n_families : 0);
      AssertThrow(n <= max_size,
                  ExcBadParameter("Analysis/Inf-sup subdivisions",
                                  std::to_string(n) + " free unknowns",
                                  "the dense generalised eigensolver handles "
                                  "at most " +
                                    std::to_string(max_size) +
                                    " unknowns: use fewer subdivisions."));
      T.reinit(n, n);
      S.reinit(n, n);
      const unsigned int n_p = particles.n_particles();
      Eigen::MatrixXd    B   = Eigen::MatrixXd::Zero(n_p, n);
      Eigen::MatrixXd    M   = Eigen::MatrixXd::Zero(n_p, n_p);

      FullMatrix<double> local;
      Vector<double>     residual;
      std::vector<int>   index;
      const auto         scatter = [&](LAPACKFullMatrix<double> &target) {
        for (unsigned int i = 0; i < index.size(); ++i)
          if (index[i] >= 0)
            for (unsigned int j = 0; j < index.size(); ++j)
              if (index[j] >= 0)
                target(index[i], index[j]) += local(i, j);
      };

      // Q1 cells: P0 pressure, condensed per cell
      for_each_q1_cell<dim>(
        view,
        [&](const QuadratureTable<dim>                 &table,
            const std::vector<Tensor<1, dim>>          &y,
            const std::vector<types::global_dof_index> &dofs) {
          index.resize(dofs.size());
          for (unsigned int i = 0; i < dofs.size(); ++i)
            index[i] = dense[dofs[i]];
          InfSup::pressure_projection(table, y, 0, local);
          scatter(T);
          assemble_element(table, y, s_material, residual, &local);
          scatter(S);
        });
      std::vector<Tensor<1, dim>>          y;
      std::vector<types::global_dof_index> dofs;
      std::vector<double>                  signs;

      // The families: S on the table (with the bubble node), B and M
      for (unsigned int f = 0; f < n_families; ++f)
        {
          const unsigned int          k       = (*view.owned_families)[f];
          const auto                  members = view.families->members(k);
          const unsigned int          m       = members.size();
          const QuadratureTable<dim> &family  = (*view.family_tables)[f];
          const QuadratureTable<dim>  kernel_table =
            bubble ? with_bubble_node(family) : family;
          const unsigned int n_nodes = kernel_table.n_nodes;
          undeformed_family(view, f, y, dofs, signs);
          index.resize(n_nodes * dim);
          for (unsigned int i = 0; i < dofs.size(); ++i)
            index[i] = dense[dofs[i]];
          if (bubble)
            {
              y.emplace_back(); // u_b = 0
              for (unsigned int c = 0; c < dim; ++c)
                index[m * dim + c] = n_u + f * dim + c;
            }
          assemble_element(kernel_table, y, s_material, residual, &local);
          // mirror images: reflected displacement components (the
          // bubble is even)
          apply_dof_signs(signs, local);
          scatter(S);

          const std::vector<double> pi = nodal_field_interpolation(family);
          for (unsigned int q = 0; q < family.n_points(); ++q)
            {
              const double          w = family.weights[q];
              const Tensor<1, dim> *V = &kernel_table.trial[q * n_nodes];
              for (unsigned int a = 0; a < m; ++a)
                {
                  const double       wp  = w * pi[q * m + a];
                  const unsigned int row = particles.original(members[a]);
                  for (unsigned int b = 0; b < n_nodes; ++b)
                    for (unsigned int c = 0; c < dim; ++c)
                      if (index[b * dim + c] >= 0)
                        B(row, index[b * dim + c]) +=
                          wp * V[b][c] * (b < m ? signs[b * dim + c] : 1.);
                  for (unsigned int b = 0; b < m; ++b)
                    M(row, particles.original(members[b])) +=
                      wp * pi[q * m + b];
                }
            }
        }

      // T += B^T M^-1 B
      const Eigen::MatrixXd T_nodal =
        B.transpose() * Eigen::LDLT<Eigen::MatrixXd>(M).solve(B);
      for (unsigned int i = 0; i < n; ++i)
        for (unsigned int j = 0; j < n; ++j)
          T(i, j) += T_nodal(i, j);
      return n_p + view.owned_fe_cells->size();
    }



    template <int dim>
    void
    InfSupAnalysis<dim>::run()
    {
      const auto &access      = this->access;
      const auto &prm         = access.parameters;
      const auto &formulation = access.formulation;
      using Method            = FormulationCode::Method;
      AssertThrow(formulation.method == Method::fem ||
                    formulation.method == Method::pbg,
                  ExcBadParameter(
                    "Discretization/Formulation",
                    formulation.text,
                    "the inf-sup test ('Analysis/Type = inf-sup') solves a "
                    "symmetric generalised eigenproblem, and PPG tangents are "
                    "not symmetric: use a PBG formulation (or FEM)."));
      AssertThrow(formulation.points != FormulationCode::Points::u1s_unl &&
                    !formulation.implicit_gradients &&
                    prm.discretization.hourglass_coefficient == 0.,
                  ExcBadParameter(
                    "Discretization/Formulation",
                    formulation.text,
                    "the inf-sup test assembles T_h and S_h from the family "
                    "tables alone, without the stabilisation of U1SUnl, "
                    "U1SIG or the hourglass force, so it would test PBG U1. "
                    "Use 'PBG U1' (and 'Hourglass coefficient = 0') to test "
                    "the underintegrated families."));
      const std::vector<unsigned int> &series =
        prm.analysis.inf_sup_subdivisions;
      const double       tolerance = prm.analysis.inf_sup_zero_tolerance;
      const unsigned int max_size  = 6000;
      // Refuse too big problems before computing anything: a clamped square
      // has dim (N - 1)^dim free unknowns, fewer constraints give more.
      for (const unsigned int N : series)
        AssertThrow(dim * std::pow(N - 1., dim) <= max_size,
                    ExcBadParameter("Analysis/Inf-sup subdivisions",
                                    std::to_string(N),
                                    "the dense generalised eigensolver handles "
                                    "at most " +
                                      std::to_string(max_size) +
                                      " free unknowns, and this mesh has at "
                                      "least " +
                                      std::to_string(static_cast<unsigned int>(
                                        dim * std::pow(N - 1., dim))) +
                                      ": use fewer subdivisions."));

      RunSummary::InfSup result;
      result.pressure_space = prm.analysis.pressure_space;
      result.zero_tolerance = tolerance;
      const double nan      = std::numeric_limits<double>::quiet_NaN();
      const bool   mixed    = (prm.analysis.pressure_space != "displacement");
      // P1C, P1C+bubble: a nodal pressure per particle (eq. 6.11)
      const bool nodal = (prm.analysis.pressure_space.substr(0, 3) == "P1C");
      // pressures per family: 1 (P0) or dim + 1 (P1)
      const unsigned int family_pressures =
        (prm.analysis.pressure_space == "P1" ? dim + 1 : 1);
      RunSummary last;
      for (unsigned int i = 0; i < series.size(); ++i)
        {
          const unsigned int   N        = series[i];
          Parameters::Geometry geometry = prm.geometry;
          geometry.mesh                 = "hyper rectangle";
          geometry.lower_corner         = std::vector<double>(dim, 0.);
          geometry.upper_corner         = std::vector<double>(dim, 1.);
          geometry.subdivisions         = {N};
          geometry.global_refinement    = 0;
          // The first mesh echoes its set-up, the others stay quiet.
          std::ostringstream quiet;
          set_up(geometry,
                 i == 0 ? access.pcout.get_stream() : quiet,
                 [&](const Access<dim> &level) {
                   InfSup::Value value;
                   unsigned int  n_nodal_pressures = 0;
                   if (nodal)
                     {
                       LAPACKFullMatrix<double> T, S;
                       n_nodal_pressures =
                         assemble_nodal_forms(level,
                                              prm.analysis.pressure_space ==
                                                "P1C+bubble",
                                              max_size,
                                              T,
                                              S);
                       value = InfSup::compute_value(T, S, tolerance);
                     }
                   else
                     {
                       LinearAlgebra::SparseMatrix T, S;
                       assemble_forms(level, T, S);
                       value = InfSup::compute_value(
                         T,
                         S,
                         level.system.homogeneous_constraints(),
                         tolerance,
                         max_size);
                     }
                   // n_p: one pressure per Q1 cell, 1 (P0) or dim + 1 (P1) per
                   // family
                   const double n_p =
                     nodal ?
                       n_nodal_pressures :
                     mixed ?
                       level.view->owned_fe_cells->size() +
                         family_pressures * level.view->owned_families->size() :
                       nan;
                   result.N.push_back(N);
                   result.n_dofs.push_back(level.summary.n_dofs);
                   result.n_free.push_back(value.n_free);
                   result.n_pressure.push_back(n_p);
                   result.n_zero.push_back(value.n_zero);
                   // (7.15) with k = n_zero + 1
                   result.k_pm.push_back(mixed ? value.n_zero + 1. -
                                                   (value.n_free - n_p + 1.) :
                                                 nan);
                   result.beta.push_back(value.beta);
                   result.slope.push_back(
                     i == 0 ? nan :
                              InfSup::loglog_slope(series[i - 1],
                                                   result.beta[i - 1],
                                                   N,
                                                   value.beta));
                   result.lambda_max.push_back(value.lambda_max);
                   result.largest_zero.push_back(value.largest_zero /
                                                 value.lambda_max);

                   std::ostringstream line;
                   line << "  inf-sup N = " << N << ": " << value.n_free
                        << " free DoFs";
                   if (mixed)
                     line << ", " << n_p << " pressures";
                   line << ", zero eigenvalues " << value.n_zero
                        << std::setprecision(3) << ", beta = " << value.beta;
                   if (i > 0)
                     line << std::fixed << std::setprecision(2)
                          << ", slope = " << result.slope[i];
                   access.pcout << line.str() << std::endl;
                   last = level.summary;
                 });
        }

      // The table, also as inf_sup.txt.
      std::ostringstream table;
      table << "# inf-sup test (Chapelle & Bathe 1993; dissertation 7.2.5), '"
            << formulation.text << "', pressure space " << result.pressure_space
            << ", distortion " << prm.geometry.distortion << "\n"
            << "# zero eigenvalues: lambda < " << tolerance
            << " lambda_max; beta = sqrt(first non-zero lambda) (7.14); "
            << "slope = -dlog(beta)/dlog(N); k_pm (7.15) for the mixed spaces "
               "only; n_u includes the bubbles of P1C+bubble\n"
            << "# N n_dofs n_u n_p zero k_pm beta slope lambda_max "
            << "largest_zero/lambda_max\n";
      for (unsigned int i = 0; i < result.N.size(); ++i)
        {
          const auto number = [](const double x) {
            std::ostringstream s;
            if (std::isnan(x))
              s << "-";
            else
              s << std::setprecision(6) << x;
            return s.str();
          };
          table << result.N[i] << " " << result.n_dofs[i] << " "
                << result.n_free[i] << " " << number(result.n_pressure[i])
                << " " << result.n_zero[i] << " " << number(result.k_pm[i])
                << " " << number(result.beta[i]) << " "
                << number(result.slope[i]) << " "
                << number(result.lambda_max[i]) << " "
                << number(result.largest_zero[i]) << "\n";
        }
      RunSummary &summary     = access.summary;
      summary                 = last;
      summary.inf_sup         = result;
      summary.converged       = true;
      summary.timing["total"] = access.total_timer.wall_time();
      if (access.root)
        {
          std::ofstream file(prm.output.directory + "/inf_sup.txt");
          file << table.str();
          write_summary_json(summary, prm.output.directory + "/summary.json");
        }
    }



    template class InfSupAnalysis<2>;
    template class InfSupAnalysis<3>;
  } // namespace Analysis
} // namespace pg
