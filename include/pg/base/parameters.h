#ifndef pg_base_parameters_h
#define pg_base_parameters_h

#include <pg/base/global.h>
#include <pg/materials/material_parameters.h>

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
   * parameter file (step-44 style). Every entry is documented where it is
   * declared (source/base/parameters.cc); `pg_solve --print-parameters`
   * prints that documentation.
   */
  namespace Parameters
  {
    /** Subsection "Geometry". */
    struct Geometry
    {
      /** hyper rectangle | cook membrane | plate with hole | file */
      std::string               mesh;
      std::vector<double>       lower_corner;
      std::vector<double>       upper_corner;
      std::vector<unsigned int> subdivisions;
      /** Plate with hole: edge length L and hole radius R (length units). */
      double      plate_size;
      double      hole_radius;
      std::string file_name;
      /** Mesh = file: merge | reject | keep coincident vertices. */
      std::string  coincident_vertices;
      unsigned int global_refinement;
      /** Interior vertices move by up to this fraction of the local spacing. */
      double       distortion;
      unsigned int random_seed;
      /** all | none | material ids a,b | box x0,y0 : x1,y1 | ball cx,cy : r */
      std::string meshfree_region;
      /** Hyper rectangle: 'box x0,y0 : x1,y1' of removed cells, or empty. */
      std::string hole;

      static void
      declare_parameters(ParameterHandler &prm);
      void
      parse_parameters(ParameterHandler &prm);
    };

    /** Subsection "Discretization". */
    struct Discretization
    {
      /** The dissertation's formulation code (Table 7.1), or FEM. */
      std::string formulation;
      /** MTE1 | MLS1 | WLS1 | WTE1 */
      std::string shape_functions;
      /**
       * delta^k = factor x local particle spacing h^k ('Horizon factor'); 0
       * if 'Horizon' is set.
       */
      double horizon_factor;
      /** Absolute horizon delta ('Horizon', length); 0: use the factor. */
      double horizon;
      /** > 0: the N nearest particles instead of a horizon. */
      unsigned int nearest_neighbours;
      /** omega = |dX|^(-2n). */
      double weight_exponent;

      static void
      declare_parameters(ParameterHandler &prm);
      void
      parse_parameters(ParameterHandler &prm);
    };

    /**
     * Subsection "CPD": the constants of continuum-kinematics-inspired
     * peridynamics (Formulation = CPD).
     */
    struct Cpd
    {
      double C1, C2, C3;
      bool   partial_volumes;

      static void
      declare_parameters(ParameterHandler &prm);
      void
      parse_parameters(ParameterHandler &prm);
    };

    /** Subsection "Boundary conditions" (the functions are in AllParameters).
     */
    struct BoundaryConditions
    {
      /** Boundary id and component mask (x, y, z) of each Dirichlet part. */
      std::vector<std::pair<types::boundary_id, std::vector<bool>>> dirichlet;
      std::vector<types::boundary_id>                               symmetry;
      std::vector<types::boundary_id>                               neumann;
      /** Boundary ids loaded by sigma . n from 'Boundary stress'. */
      std::vector<types::boundary_id> neumann_stress;
      /**
       * How a traction loads the particles of meshfree boundary faces:
       * 'geometry' (the FE-consistent load, integral of T N_k over the
       * faces) or 'test functions' (T (n . d^k), with d^k the unit-stress
       * residual of the test functions actually used, eq. 4.32-4.35).
       * 'automatic': 'test functions' with VC, 'geometry' without.
       */
      std::string particle_traction_area;
      /**
       * 'Fixed points': mesh vertices (dim coordinates) whose listed
       * components take the values of 'Prescribed displacement', e.g. to
       * remove the rigid motions of a laterally free specimen.
       */
      std::vector<std::pair<std::vector<double>, std::vector<bool>>>
        fixed_points;
      /**
       * 'Dirichlet boxes': every mesh vertex in the closed box between two
       * corners (dim coordinates each) has the listed components
       * prescribed, e.g. the layers of thickness delta through which
       * non-local models are clamped.
       */
      struct DirichletBox
      {
        std::vector<double> lower, upper;
        std::vector<bool>   components;
      };
      std::vector<DirichletBox> dirichlet_boxes;

      /** Whether 'Dirichlet', 'Fixed points' or 'Dirichlet boxes' is set. */
      bool
      prescribes_values() const
      {
        return !dirichlet.empty() || !fixed_points.empty() ||
               !dirichlet_boxes.empty();
      }

      static void
      declare_parameters(ParameterHandler &prm);
      void
      parse_parameters(ParameterHandler &prm, const unsigned int dim);
    };

    /** Subsection "Loading". */
    struct Loading
    {
      unsigned int load_steps;
      unsigned int maximum_step_cuts;

      static void
      declare_parameters(ParameterHandler &prm);
      void
      parse_parameters(ParameterHandler &prm);
    };

    /** Subsection "Newton". */
    struct Newton
    {
      unsigned int maximum_iterations;
      double       relative_tolerance;
      double       absolute_tolerance;

      static void
      declare_parameters(ParameterHandler &prm);
      void
      parse_parameters(ParameterHandler &prm);
    };

    /** Subsection "Linear solver". */
    struct LinearSolver
    {
      /** direct | cg | gmres */
      std::string type;
      double      tolerance;

      static void
      declare_parameters(ParameterHandler &prm);
      void
      parse_parameters(ParameterHandler &prm);
    };

    /** Subsection "Analysis". */
    struct Analysis
    {
      /** static | eigenmodes | inf-sup */
      std::string type;
      /** How many of the smallest eigenvalues are reported. */
      unsigned int n_eigenvalues;
      /** inf-sup: displacement | P0 (one condensed pressure per element). */
      std::string pressure_space;
      /** inf-sup: the N of every N x N (x N) mesh of the unit square. */
      std::vector<unsigned int> inf_sup_subdivisions;
      /** inf-sup: eigenvalues below this times the largest are zero. */
      double inf_sup_zero_tolerance;

      static void
      declare_parameters(ParameterHandler &prm);
      void
      parse_parameters(ParameterHandler &prm);
    };

    /**
     * Subsection "Time": quasi-static load stepping (the default) or
     * dynamics with an explicit or implicit time integrator. The initial
     * conditions are in AllParameters.
     */
    struct Time
    {
      /** none | leapfrog | newmark */
      std::string integrator;
      double      end_time;
      /** 0: the stable time step estimate times 'Safety factor'. */
      double time_step;
      double safety_factor;
      /** 0: every step. */
      double output_interval;
      double beta;
      double gamma;

      /** Is an integrator selected (not quasi-static load stepping)? */
      bool
      dynamic() const;

      static void
      declare_parameters(ParameterHandler &prm);
      void
      parse_parameters(ParameterHandler &prm);
    };

    /** Subsection "Output". */
    struct Output
    {
      std::string directory;
      bool        vtu;
      /** Named reference points, each with dim coordinates. */
      std::vector<std::pair<std::string, std::vector<double>>> points;
      /** Boundary ids whose vertex stresses go to a table. */
      std::vector<types::boundary_id> stress_boundaries;
      /** A named segment for displacement_along_lines.txt. */
      struct Line
      {
        std::string         name;
        std::vector<double> start, end;
      };
      std::vector<Line> lines;
      /** Points per line, both ends included. */
      unsigned int line_samples;

      static void
      declare_parameters(ParameterHandler &prm);
      void
      parse_parameters(ParameterHandler &prm, const unsigned int dim);
    };

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
