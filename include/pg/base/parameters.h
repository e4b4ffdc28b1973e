#ifndef pg_base_parameters_h
#define pg_base_parameters_h

#include <pg/analysis/analysis_parameters.h>
#include <pg/base/global.h>
#include <pg/constraints/boundary_condition_parameters.h>
#include <pg/elements/cpd_parameters.h>
#include <pg/elements/discretization_parameters.h>
#include <pg/materials/material_parameters.h>
#include <pg/mesh/geometry_parameters.h>
#include <pg/postprocess/output_parameters.h>
#include <pg/solvers/solver_parameters.h>

#include <deal.II/base/function_parser.h>
#include <deal.II/base/parameter_handler.h>
#include <deal.II/base/parsed_function.h>
#include <deal.II/base/point.h>
#include <deal.II/base/types.h>

#include <memory>
#include <string>
#include <utility>
#include <vector>

namespace pg
{
  /**
   * The parameters of a pg run, one struct per top-level subsection of the
   * parameter file (step-44 style). Each struct lives in the folder of the
   * code that uses it (mesh/geometry_parameters.h, solvers/solver_parameters.h,
   * ...); Material is in materials/material_parameters.h; this file adds
   * AllParameters, the parameters of the run as a whole. Every entry is
   * documented where it is declared; `pg_solve --print-parameters` prints that
   * documentation.
   */
  namespace Parameters
  {
    /**
     * All parameters of a run in @p dim dimensions, including the parsed
     * functions of the boundary conditions and of the exact solution. The
     * functions take the variables x, y[, z] and t, where t is the load
     * factor that runs from 0 to 1 (with a time integrator: the time).
     */
    template <int dim>
    struct AllParameters
    {
      AllParameters();

      unsigned int       dimension;
      Geometry           geometry;
      Discretization     discretization;
      Cpd                cpd;
      Material           material;
      BoundaryConditions boundary_conditions;
      Loading            loading;
      Newton             newton;
      LinearSolver       linear_solver;
      Analysis           analysis;
      Output             output;
      Time               time;

      /** Dirichlet values u(X, t) (dim components). */
      Functions::ParsedFunction<dim> prescribed_displacement;
      /** Dead first Piola traction per reference area (dim components). */
      Functions::ParsedFunction<dim> traction;
      /**
       * Stress whose traction sigma . n loads the 'Neumann stress'
       * boundaries (dim*dim components, row-major sigma_ij).
       */
      Functions::ParsedFunction<dim> boundary_stress;
      /** Body force per reference volume, rho_0 b (dim components). */
      Functions::ParsedFunction<dim> body_force;
      /** Every component of 'Body force' is the literal 0. */
      bool zero_body_force;
      /** Exact displacement for error norms (dim components). */
      Functions::ParsedFunction<dim> exact_solution;
      /**
       * Exact displacement gradient, row-major du_i/dX_j (dim*dim
       * components), or nullptr when 'Gradient expression' is empty (then
       * the gradient comes from finite differences of the exact solution).
       */
      std::unique_ptr<FunctionParser<dim>> exact_gradient;
      bool                                 compute_errors;
      /** Time/Initial displacement u(X, 0) (dim components). */
      Functions::ParsedFunction<dim> initial_displacement;
      /** Time/Initial velocity v(X, 0) (dim components). */
      Functions::ParsedFunction<dim> initial_velocity;

      static void
      declare_parameters(ParameterHandler &prm);
      void
      parse_parameters(ParameterHandler &prm);

      /**
       * Set the time of every parsed function of the loads, the Dirichlet
       * values and the exact solution (and gradient) to the load factor
       * @p t (or the time of a dynamic run).
       */
      void
      set_load_factor(const double t) const;
    };

    /**
     * Read 'set Dimension' from @p filename, skipping every other entry.
     * Throws with a clear message if the file cannot be read.
     */
    unsigned int
    read_dimension(const std::string &filename);
  } // namespace Parameters
} // namespace pg

#endif
