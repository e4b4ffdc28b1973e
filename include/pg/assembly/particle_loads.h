#ifndef pg_assembly_particle_loads_h
#define pg_assembly_particle_loads_h

#include <pg/assembly/assembler.h>
#include <pg/assembly/loads.h>
#include <pg/base/formulation_code.h>
#include <pg/base/global.h>
#include <pg/base/parameters.h>
#include <pg/elements/quadrature_table.h>
#include <pg/families/family_set.h>
#include <pg/mesh/particle_set.h>

#include <deal.II/base/mpi.h>
#include <deal.II/base/tensor.h>
#include <deal.II/dofs/dof_handler.h>
#include <deal.II/fe/fe_q.h>

#include <functional>
#include <map>
#include <vector>

namespace pg
{
  /**
   * The dead loads on the particles, the load term of the Assembler
   * (Assembler::LoadTerm) after the element groups:
   *  - the body force V^k rho_0 b at every owned particle k,
   *  - with 'Particle traction area = test functions' (or 'automatic' with
   *    VC) the traction T_b c_b of every Neumann part b at k, with c_b the
   *    area of part b in the unit-stress residual d^k (pg-methods.md
   *    section 8.2, eqs. 4.32-4.35; the geometric |a^k| on the FE/meshfree
   *    interface), where the traction covers the particle's whole area;
   *    at the edge of a loaded region (partly loaded particles, see
   *    update_partial_loads()) the test-function area times the average
   *    traction over the particle's faces, corrected so that the resultant
   *    of every Neumann id is its face integral,
   *  - with 'exact stress' the internal force of the exact stress in place
   *    of body force and tractions at the loaded surface particles,
   *  - otherwise ('geometry') the FE-consistent face traction of Loads on
   *    the Neumann faces of meshfree cells.
   * It owns d^k of every particle and the boundary-area weights c_b derived
   * from it; the Neumann ids, tractions and body force are those of Loads.
   */
  template <int dim>
  class ParticleLoads
  {
  public:
    using CellIterator = typename DoFHandler<dim>::active_cell_iterator;
    /** A force (force units) at particle k. */
    using ParticleForce = std::function<Tensor<1, dim>(unsigned int)>;

    /**
     * The traction option of 'Boundary conditions/Particle traction area'
     * for @p formulation. The loads apply to @p particles of
     * @p owned_families (this rank's family masters) and to the meshfree
     * cells @p meshfree_neumann_cells (loaded by face quadrature, 'geometry'
     * only); @p exact_stress_force(k) is the internal force of the exact
     * stress at particle k ('exact stress' only). The referenced objects
     * must outlive this one; their contents may be filled later (setup).
     */
    ParticleLoads(const Parameters::AllParameters<dim> &parameters,
                  const FormulationCode                &formulation,
                  const Loads<dim>                     &loads,
                  const ParticleSet<dim>               &particles,
                  const std::vector<unsigned int>      &owned_families,
                  const std::vector<CellIterator>      &meshfree_neumann_cells,
                  const ParticleForce                  &exact_stress_force);

    /**
     * Tractions on meshfree faces load the particles through d^k ('test
     * functions', or 'automatic' with VC).
     */
    bool
    traction_from_test_functions() const;

    /** 'Particle traction area = exact stress'. */
    bool
    traction_from_exact_stress() const;

    /**
     * d^k of every particle from @p tables (tables[i] of family
     * owned_families[i]; summed over the ranks of @p comm) and the
     * boundary-area weights of the Neumann loads. Called again after the
     * VC correction changes the tables.
     */
    void
    compute_unit_stress_residual(
      const FamilySet<dim>                    &families,
      const std::vector<QuadratureTable<dim>> &tables,
      const MPI_Comm                           comm);

    /** Unit-stress residual d^k (area units) of every particle. */
    const std::vector<Tensor<1, dim>> &
    unit_stress() const;

    /**
     * max |d^k| / h_k^(dim-1) over the interior particles (round-off after
     * a successful VC correction).
     */
    double
    max_interior_unit_stress_residual() const;

    /**
     * The area c_b (area units) of each boundary part b at particle k seen
     * by the test functions: d^k = sum_b c_b n_b on the unit normals n_b of
     * the parts at k (section 8.2). With one part c = n . d^k; at a corner
     * the decomposition keeps the other part's area out of the load.
     */
    const std::vector<std::map<types::boundary_id, double>> &
    boundary_area_weights() const;

    /**
     * Add the loads to the running assembly of @p assembler (add_load()
     * at the particles, distribute() on the meshfree Neumann cells) and
     * record non-finite loads as failures.
     */
    void
    add_to(Assembler<dim> &assembler) const;

    /** add_to() as the load term of Assembler::assemble(). */
    typename Assembler<dim>::LoadTerm
    load_term() const;

    /**
     * All meshfree cells with a Neumann face (on every rank: the
     * triangulation is shared). Their faces give the exact resultants and
     * the partial-load correction; without this call both are off.
     */
    void
    set_neumann_cells(const std::vector<CellIterator> &cells);

    /**
     * The resultant of the traction of one Neumann id on the particles
     * against the exact one, the face integral of the traction over the
     * meshfree faces of the id (QGauss(2), as on the FE side), and the
     * moments about the face centre (the area centroid of those faces):
     * one component (z) in 2-D, three in 3-D.
     */
    struct Resultant
    {
      types::boundary_id id   = 0;
      double             area = 0;
      Point<dim>         centre;
      Tensor<1, dim>     force, exact_force;
      /** 'test functions': the resultant of eq. 4.32 alone, T(X^k) c_b. */
      Tensor<1, dim>      point_force;
      std::vector<double> moment, exact_moment;
      /** Particles of the id at the edge of its loaded region. */
      unsigned int n_partly_loaded = 0;
    };

    /**
     * The Resultant of every Neumann id at the current load factor, the
     * same on every rank ('test functions' and 'geometry'; empty with
     * 'exact stress' and before set_neumann_cells()).
     */
    std::vector<Resultant>
    neumann_resultants() const;

  private:
    /** The load (force units) of particle @p k, dim components. */
    void
    particle_load(const unsigned int k, Vector<double> &load) const;

    /** 'geometry': the FE-consistent traction on the meshfree faces. */
    void
    add_meshfree_face_tractions(Assembler<dim> &assembler) const;

    /**
     * The face integrals of the traction at the current load factor (once
     * per load factor): per Neumann id the exact force and moment, per
     * particle k and id b the integral of N_k T over k's faces of b, and
     * the loads of the partly loaded particles (FacePart::load).
     */
    void
    update_partial_loads() const;

    /** The traction load of part @p id of particle @p k (force units). */
    Tensor<1, dim>
    traction_load(const unsigned int       k,
                  const types::boundary_id id,
                  const Tensor<1, dim>    &area) const;

    const Loads<dim>                &loads;
    const ParticleSet<dim>          &particles;
    const std::vector<unsigned int> &owned_families;
    const std::vector<CellIterator> &meshfree_neumann_cells;
    const ParticleForce              exact_stress_force;
    const bool                       from_test_functions;
    const bool                       from_exact_stress;

    std::vector<Tensor<1, dim>>                       unit_stress_residual;
    std::vector<std::map<types::boundary_id, double>> area_weights;

    /**
     * set_neumann_cells(); the particle of each vertex (invalid_unsigned_int
     * for the vertices of finite elements only).
     */
    std::vector<CellIterator> neumann_cells;
    std::vector<unsigned int> particle_of_vertex;
    bool                      have_neumann_cells = false;

    /** Per particle and Neumann id, at the load factor partial_time. */
    struct FacePart
    {
      /** int N_k T dA and int N_k |T| dA over k's faces of the id. */
      Tensor<1, dim> integral;
      double         magnitude = 0;
      /** |T| = 0 / > 0 at some quadrature point of these faces. */
      bool vanishes = false, loaded = false;
      /**
       * At the edge of the loaded region (T = 0 on some of the faces, or
       * another id in the same plane). With 'test functions' `partial`
       * says that the load is `load`, not eq. 4.32 (at the edge, and at
       * every loaded particle of an id that has edge particles).
       */
      bool           edge = false, partial = false;
      Tensor<1, dim> load;
    };
    mutable double partial_time;
    /** Only the particles on Neumann faces (particle -> id -> part). */
    mutable std::map<unsigned int, std::map<types::boundary_id, FacePart>>
                                                    face_parts;
    mutable std::map<types::boundary_id, Resultant> resultants;
  };
} // namespace pg

#endif
