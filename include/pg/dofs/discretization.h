#ifndef pg_dofs_discretization_h
#define pg_dofs_discretization_h

#include <pg/base/formulation_code.h>
#include <pg/base/global.h>
#include <pg/dofs/field_layout.h>
#include <pg/elements/cpd_interactions.h>
#include <pg/elements/cpd_parameters.h>
#include <pg/elements/discretization_parameters.h>
#include <pg/elements/family_elements.h>
#include <pg/elements/quadrature_table.h>
#include <pg/families/family_set.h>
#include <pg/mesh/geometry_parameters.h>
#include <pg/mesh/linear_cells.h>
#include <pg/mesh/particle_set.h>

#include <deal.II/base/index_set.h>
#include <deal.II/base/mpi.h>
#include <deal.II/distributed/shared_tria.h>
#include <deal.II/dofs/dof_handler.h>
#include <deal.II/fe/fe_system.h>

#include <functional>
#include <map>
#include <memory>
#include <string>
#include <vector>

namespace pg
{
  /**
   * The discretization of a run: the mesh, the Q1 displacement DoFs, the
   * meshfree cells with their particles and families, the family elements
   * (or the CPD interactions) and the quadrature tables of the families this
   * rank owns. reinit() builds them in this order from the 'Geometry',
   * 'Discretization' and 'CPD' parameters; the objects keep their addresses
   * afterwards (the ProblemView points to them).
   *
   * The members are public data, as in a deal.II tutorial program's class:
   * the problem wires them into the element groups, the VC correction
   * rebuilds family_elements and family_tables, the postprocessors read
   * them through the ProblemView.
   *
   * Ownership: a cell is owned by the rank of its METIS subdomain; a family
   * is owned by the rank that owns the DoFs of its master particle.
   */
  template <int dim>
  class Discretization
  {
  public:
    using CellIterator = typename DoFHandler<dim>::active_cell_iterator;

    /**
     * An empty discretization on @p mpi_communicator (a METIS-partitioned
     * shared triangulation) for the mesh described by @p geometry.
     */
    Discretization(const MPI_Comm              mpi_communicator,
                   const Parameters::Geometry &geometry);

    /**
     * Create the mesh of #geometry, mark the meshfree cells (none for
     * FEM), distribute the DoFs, collect the owned FE cells and the owned
     * meshfree cells for which @p loaded_by_face_traction is true, then the
     * particles and, if there are any, the families (bonds reaching
     * delta + h/2 for CPD with partial volumes), the CPD interactions, the
     * family elements (PBG U1 for CPD: the particle deformation gradients
     * of the output), the owned families and their quadrature tables.
     * With @p mirror_symmetry_ids ('Symmetry treatment = mirror') the
     * particles within a horizon of those planes get mirror images, which
     * join the families (ParticleSet::add_mirror_images()).
     * Finally the relevant DoFs and the mesh diameter. Adds the wall times
     * (s) to time_mesh, time_setup and time_shape. Call once.
     */
    void
    reinit(
      const FormulationCode            &formulation,
      const Parameters::Discretization &discretization_parameters,
      const Parameters::Cpd            &cpd_parameters,
      const std::function<bool(const CellIterator &)> &loaded_by_face_traction,
      const std::vector<types::boundary_id> &mirror_symmetry_ids = {});

    /** 'Geometry', replaced per mesh by the inf-sup analysis. */
    Parameters::Geometry geometry;

    parallel::shared::Triangulation<dim> triangulation;
    /**
     * The kind of the mesh's cells (quadrilaterals/hexahedra or
     * triangles/tetrahedra): the scalar linear element, mapping and
     * quadratures. Set by reinit() once the mesh is built.
     */
    LinearCells<dim> cells;
    /**
     * FESystem(P, dim) of the displacement, P = cells.scalar_element()
     * (FE_Q(1) or FE_SimplexP(1)); made by reinit(). With extra
     * nodal fields (U2P1C, Unl+P1C) the DoFHandler is an hp one
     * (#field_layout): its FE cells have fe's DoFs (and FE_Nothing for the
     * fields), its meshfree cells FESystem(P^dim, P^2); use
     * cell->get_fe() there, and fe only on FE cells.
     */
    std::unique_ptr<const FESystem<dim>> fe;
    DoFHandler<dim>                      dof_handler;
    /**
     * The layout of u and the extra nodal fields (null without extra
     * fields, where dof_handler has fe on every cell).
     */
    std::unique_ptr<FieldLayout<dim>> field_layout;
    /** Meshfree flag of every active cell (by active cell index). */
    std::vector<bool> meshfree;

    /** The DoFs this rank owns, and those it reads (ghosts included). */
    IndexSet owned_dofs, relevant_dofs;

    ParticleSet<dim>                     particles;
    FamilySet<dim>                       families;
    std::unique_ptr<FamilyElements<dim>> family_elements;
    /**
     * Formulation = CPD: the interactions, assembled in place of the
     * family tables (family_elements then serves the particle deformation
     * gradients of the output only, as PBG U1).
     */
    std::unique_ptr<CpdInteractions<dim>> cpd;
    /** The masters of the families this rank owns, and their tables. */
    std::vector<unsigned int>         owned_families;
    std::vector<QuadratureTable<dim>> family_tables;
    /**
     * U1SUnl only (else empty): the elements and tables of the
     * stabilisation (FormulationCode::stabilisation_part(), Unl on every
     * member); family_elements and family_tables are then its
     * underintegrated part (U1).
     */
    std::unique_ptr<FamilyElements<dim>> stabilisation_elements;
    std::vector<QuadratureTable<dim>>    stabilisation_tables;
    /** The finite element (Q1) cells this rank owns. */
    std::vector<CellIterator> owned_fe_cells;
    /** Meshfree cells loaded by FE-consistent face tractions ('geometry'). */
    std::vector<CellIterator> owned_meshfree_neumann_cells;

    /** What create_mesh() did to a mesh file, for the banner. */
    std::string mesh_notes;
    /**
     * The node sets of an Exodus II mesh file: name -> vertex indices of
     * the triangulation ('Dirichlet node sets' in subsection 'Boundary
     * conditions'); empty for other meshes.
     */
    std::map<std::string, std::vector<unsigned int>> node_sets;
    /**
     * Mesh::diameter() of the final mesh (computed once in reinit()): the
     * scale of the geometric tolerances of the constraints, which dynamics
     * rebuilds every step.
     */
    double mesh_diameter = 0;

    /**
     * Wall times (s) of the mesh, of the DoFs and particles (the problem
     * adds the rest of its set-up), and of the shape functions (families,
     * family elements, tables).
     */
    double time_mesh = 0, time_setup = 0, time_shape = 0;

  private:
    /** relevant_dofs: the DoFs this rank reads (dofs/relevant_dofs.h). */
    void
    compute_relevant_dofs();

    /**
     * The families whose FamilyElements data this rank needs (empty: all,
     * as on one rank): see FamilyElements::initialize().
     */
    std::vector<bool>
    needed_families(const FormulationCode &formulation) const;
  };
} // namespace pg

#endif
