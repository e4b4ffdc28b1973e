#ifndef pg_postprocess_problem_view_h
#define pg_postprocess_problem_view_h

#include <pg/base/formulation_code.h>
#include <pg/base/global.h>
#include <pg/base/linear_algebra.h>
#include <pg/base/parameters.h>
#include <pg/constraints/rigid_wall.h>
#include <pg/elements/cpd_interactions.h>
#include <pg/elements/family_elements.h>
#include <pg/elements/quadrature_table.h>
#include <pg/families/family_set.h>
#include <pg/history/quadrature_point_history.h>
#include <pg/materials/material.h>
#include <pg/mesh/linear_cells.h>
#include <pg/mesh/particle_set.h>

#include <deal.II/base/conditional_ostream.h>
#include <deal.II/base/index_set.h>
#include <deal.II/base/mpi.h>
#include <deal.II/base/timer.h>
#include <deal.II/dofs/dof_handler.h>
#include <deal.II/fe/fe.h>
#include <deal.II/grid/tria.h>
#include <deal.II/lac/affine_constraints.h>
#include <deal.II/lac/vector.h>

#include <functional>
#include <map>
#include <utility>
#include <vector>

namespace pg
{
  template <int dim>
  class FieldLayout;

  /**
   * Postprocessors: what a run reports after each step and at its end
   * (points, lines, reactions, error norms, nodal stresses, statistics,
   * VTU/PVD and summary.json). They read the problem through ProblemView
   * and write only the statistics table, the summary and their own files.
   */
  namespace Postprocess
  {
    /** A sample of 'Output/Lines': line index, arc length, cell, reference. */
    template <int dim>
    struct LineSampleLocation
    {
      unsigned int                                   line;
      double                                         arc_length;
      Point<dim>                                     position;
      typename DoFHandler<dim>::active_cell_iterator cell;
      Point<dim>                                     reference;
    };

    /**
     * grad u of the exact solution at @p p: 'Gradient expression' if
     * given, otherwise the fourth-order central difference of 'Exact
     * solution' with h = 1e-4 @p mesh_diameter.
     */
    template <int dim>
    Tensor<2, dim>
    exact_displacement_gradient(const Parameters::AllParameters<dim> &prm,
                                const double      mesh_diameter,
                                const Point<dim> &p);

    /**
     * The material's committed state for output, on every rank
     * (ProblemView::committed_states()): per active cell of the mesh, the
     * state of its Gauss points (FE cells; point q's n_material values at
     * (cell * points_per_cell + q) * n_material of @p cells), and per
     * particle the state at point 0 of its family (the master's point;
     * n_material values at k * n_material of @p particles). Empty for a
     * stateless material.
     */
    struct CommittedStates
    {
      unsigned int        n_material      = 0;
      unsigned int        points_per_cell = 0;
      std::vector<double> cells, particles;

      /** The state of point @p q of active cell @p c. */
      ArrayView<const double>
      cell(const unsigned int c, const unsigned int q) const
      {
        if (n_material == 0)
          return {};
        const double *begin =
          cells.data() + (c * points_per_cell + q) * n_material;
        return make_array_view(begin, begin + n_material);
      }

      /** The state of particle @p k (its family's point 0). */
      ArrayView<const double>
      particle(const unsigned int k) const
      {
        if (n_material == 0)
          return {};
        const double *begin = particles.data() + k * n_material;
        return make_array_view(begin, begin + n_material);
      }
    };

    /**
     * A read-only view of a set-up problem (as ASPECT's SimulatorAccess):
     * const pointers to the objects the problem owns, filled once after
     * setup. The objects change their values during the run (u,
     * force), not their addresses, so the view stays valid. The pointers
     * family_elements and cpd are null where the problem has none.
     */
    template <int dim>
    struct ProblemView
    {
      using CellIterator = typename DoFHandler<dim>::active_cell_iterator;

      const Parameters::AllParameters<dim> *parameters = nullptr;
      MPI_Comm                              mpi_communicator;
      /** Rank 0 (which writes the text files). */
      bool                            root        = false;
      const ConditionalOStream       *pcout       = nullptr;
      const FormulationCode          *formulation = nullptr;
      const Materials::Material<dim> *material    = nullptr;

      const Triangulation<dim> *triangulation = nullptr;
      const DoFHandler<dim>    *dof_handler   = nullptr;
      /**
       * The element of the finite element (Q1) cells, FESystem(FE_Q(1), dim)
       * (with extra nodal fields: plus FE_Nothing for them), and FE_Q(1).
       * Meshfree cells may have another element: use cell->get_fe() there.
       */
      const FiniteElement<dim> *fe = nullptr, *fe_scalar = nullptr;
      /** The kind of the cells: their mapping and quadratures. */
      const LinearCells<dim> *cells = nullptr;
      /**
       * The layout of u and the extra nodal fields (U2P1C, Unl+P1C,
       * IUnlP0); null without extra fields.
       */
      const FieldLayout<dim> *field_layout = nullptr;
      /** Meshfree flag of every active cell (by active cell index). */
      const std::vector<bool> *meshfree = nullptr;

      const ParticleSet<dim>     *particles       = nullptr;
      const FamilySet<dim>       *families        = nullptr;
      const FamilyElements<dim>  *family_elements = nullptr;
      const CpdInteractions<dim> *cpd             = nullptr;
      /** The families (masters) and Q1 cells this rank owns. */
      const std::vector<unsigned int>         *owned_families = nullptr;
      const std::vector<QuadratureTable<dim>> *family_tables  = nullptr;
      const std::vector<CellIterator>         *owned_fe_cells = nullptr;
      const IndexSet                          *owned_dofs     = nullptr;

      /**
       * The displacement, ghosted: the owned DoFs and those of the members
       * of the owned families and of the locally owned cells
       * (compute_relevant_dofs()). For other DoFs use
       * gather_displacement().
       */
      const LinearAlgebra::Vector *u = nullptr;
      /** f_int - f_ext of the last assembly (owned DoFs). */
      const LinearAlgebra::Vector     *force       = nullptr;
      const AffineConstraints<double> *constraints = nullptr;
      /** Unit-stress residual d^k of every particle (section 8.2). */
      const std::vector<Tensor<1, dim>> *unit_stress = nullptr;
      /**
       * The point history: group 0 the FE cells (elements in the order of
       * owned_fe_cells), group 1 the families (in the order of
       * owned_families); per point the material's n_state_variables()
       * values first (doc/architecture.md, "History").
       */
      const QuadraturePointHistory *history = nullptr;

      /** The cell and reference coordinates of every 'Output/Points'. */
      const std::vector<std::pair<CellIterator, Point<dim>>> *point_locations =
        nullptr;
      const std::vector<LineSampleLocation<dim>> *line_locations = nullptr;
      /** Mesh::diameter() of the mesh, set in setup. */
      const double *mesh_diameter = nullptr;
      /** The node sets of an Exodus II mesh file (Discretization). */
      const std::map<std::string, std::vector<unsigned int>> *node_sets =
        nullptr;
      /** 'Boundary conditions/Rigid wall' and its active set, or null. */
      const RigidWall<dim> *rigid_wall = nullptr;

      /**
       * Wall times (s) of the phases and the timers, for summary.timing
       * (time_amg_operator: the Q1 tangents of 'AMG operator = Q1 cells',
       * part of time_solve).
       */
      const double *time_mesh = nullptr, *time_setup = nullptr,
                   *time_shape = nullptr, *time_vc = nullptr,
                   *time_assembly = nullptr, *time_solve = nullptr,
                   *time_amg_operator = nullptr;
      const Timer *total_timer = nullptr, *postprocess_timer = nullptr;

      /** Set the time of every parsed function to the load factor. */
      std::function<void(double)> set_load_factor;
      /**
       * Add the dynamics columns (energies, disorder) of time @p t to the
       * statistics table and summary.dynamics; called by the statistics
       * postprocessor of a dynamic run between 'residual' and the points.
       */
      std::function<void(double)> add_dynamic_statistics;

      /**
       * The displacement at every DoF on every rank, gathered from the
       * owners (collective: all ranks call it together; see
       * gather_to_all()).
       */
      Vector<double>
      gather_displacement() const;

      /**
       * The deformation gradient F^k = sum_b (x_b - x_k) (x) B_b of the
       * particle @p k, with the master gradients B of family k, from the
       * ghosted u: for the families this rank owns.
       */
      Tensor<2, dim>
      particle_deformation_gradient(const unsigned int k) const;

      /** The same from the gathered displacement @p u_all (any k). */
      Tensor<2, dim>
      particle_deformation_gradient(const unsigned int    k,
                                    const Vector<double> &u_all) const;

      /**
       * F^k of every particle on every rank: each rank computes those of
       * its owned families, and all are copied to all (collective).
       */
      std::vector<Tensor<2, dim>>
      particle_deformation_gradients() const;

      /**
       * The material's committed state of every FE cell's Gauss points and
       * of every particle, on every rank (collective). Empty for a
       * stateless material.
       */
      CommittedStates
      committed_states() const;

      /**
       * The largest value of each of the material's state_output_names()
       * over all committed points of all groups and ranks (collective);
       * empty for a material without state outputs.
       */
      std::vector<double>
      maximum_state_outputs() const;

      /**
       * The Q1 interpolant of the gathered displacement @p u_all at
       * @p reference in @p cell (any cell).
       */
      std::vector<double>
      displacement_at(const CellIterator   &cell,
                      const Point<dim>     &reference,
                      const Vector<double> &u_all) const;

      /** grad u of the exact solution at @p p (the function above). */
      Tensor<2, dim>
      exact_displacement_gradient(const Point<dim> &p) const;
    };
  } // namespace Postprocess
} // namespace pg

#endif
