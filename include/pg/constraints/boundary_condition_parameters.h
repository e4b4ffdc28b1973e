#ifndef pg_constraints_boundary_condition_parameters_h
#define pg_constraints_boundary_condition_parameters_h

#include <pg/base/global.h>

#include <deal.II/base/parameter_handler.h>
#include <deal.II/base/types.h>

#include <string>
#include <utility>
#include <vector>

// Which boundaries and vertices are constrained or loaded (subsection
// "Boundary conditions"); the functions of that subsection are parsed in
// AllParameters.

namespace pg
{
  namespace Parameters
  {
    /** Subsection "Boundary conditions" (the functions are in AllParameters).
     */
    struct BoundaryConditions
    {
      /** Boundary id and component mask (x, y, z) of each Dirichlet part. */
      std::vector<std::pair<types::boundary_id, std::vector<bool>>> dirichlet;
      std::vector<types::boundary_id>                               symmetry;
      /**
       * 'Symmetry treatment': 'mirror' (a particle within a horizon of a
       * symmetry plane gets the mirror images of the particles across it
       * as family members, so that a half or quarter model equals the
       * full body) or 'constraint' (the dissertation's: n . u = 0 only,
       * the families end at the plane).
       */
      bool                            mirror_symmetry = true;
      std::vector<types::boundary_id> neumann;
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
      /**
       * 'Dirichlet node sets': the name of a node set of an Exodus II mesh
       * file and the components of its vertices that are prescribed.
       */
      std::vector<std::pair<std::string, std::vector<bool>>>
        dirichlet_node_sets;

      /**
       * Subsection 'Rigid wall' of 'Boundary conditions': a rigid,
       * frictionless plane through @p point (mesh length units) with the
       * unit normal @p normal pointing into the body's side. A node (mesh
       * vertex, particle) whose position x = X + u would cross it (n . (x -
       * p) < 0) is held on it; with @p unilateral it is released again when
       * its reaction turns tensile (RigidWall). Empty 'Normal': no wall.
       */
      struct RigidWall
      {
        bool                enabled = false;
        std::vector<double> point, normal;
        /** 'unilateral' (true) or 'two-sided' (held once touched). */
        bool unilateral = true;
        /**
         * Quasi-static: how many times one load step is solved again
         * because the active set changed before the step counts as failed.
         */
        unsigned int maximum_set_changes = 20;
      };
      RigidWall rigid_wall;

      /**
       * Whether 'Dirichlet', 'Fixed points', 'Dirichlet boxes' or
       * 'Dirichlet node sets' is set.
       */
      bool
      prescribes_values() const
      {
        return !dirichlet.empty() || !fixed_points.empty() ||
               !dirichlet_boxes.empty() || !dirichlet_node_sets.empty();
      }

      static void
      declare_parameters(ParameterHandler &prm);
      void
      parse_parameters(ParameterHandler &prm, const unsigned int dim);
    };
  } // namespace Parameters
} // namespace pg

#endif
