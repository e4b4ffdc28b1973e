#ifndef pg_elements_family_group_h
#define pg_elements_family_group_h

#include <pg/elements/cpd_interactions.h>
#include <pg/elements/element_group.h>
#include <pg/elements/family_elements.h>
#include <pg/elements/quadrature_table.h>
#include <pg/families/family_set.h>
#include <pg/materials/material.h>
#include <pg/materials/volumetric_split.h>
#include <pg/mesh/particle_set.h>

#include <vector>

namespace pg
{
  /**
   * What every family-based group shares: element e is the family of the
   * locally owned master particle owned_families[e]; its nodes are the
   * family members (the master first), its DoFs theirs, and its local
   * positions y_b = X_b - X_k + u_b.
   */
  template <int dim>
  class FamilyGroupBase : public ElementGroup<dim>
  {
  public:
    FamilyGroupBase(const std::vector<unsigned int> &owned_families,
                    const FamilySet<dim>            &families,
                    const ParticleSet<dim>          &particles);

    unsigned int
    n_elements() const override;

    void
    get_dof_indices(const unsigned int                    e,
                    std::vector<types::global_dof_index> &dofs) const override;

    /**
     * -1 for the reflected displacement components of the family's mirror
     * images (empty if it has none); the extra nodal fields are even.
     */
    void
    get_dof_signs(const unsigned int   e,
                  std::vector<double> &signs) const override;

    std::string
    element_name(const unsigned int e) const override;

    Point<dim>
    element_position(const unsigned int e) const override;

    std::string
    non_finite_hint() const override;

  protected:
    /**
     * The DoFs of family @p e and the positions y of its members at @p u
     * (a mirror image's displacement is its original's, reflected).
     */
    void
    gather(const unsigned int                    e,
           const LinearAlgebra::Vector          &u,
           std::vector<types::global_dof_index> &dofs,
           std::vector<Tensor<1, dim>>          &y) const;

    const std::vector<unsigned int> &owned_families;
    const FamilySet<dim>            &families;
    const ParticleSet<dim>          &particles;
  };



  /**
   * A stabilisation of the underintegrated families (U1, one point at the
   * master; elements/u1_stabilisation.h), at most one of:
   * - U1SUnl (eq. 6.18, pg-methods.md section 12.3.2): family k adds the
   *   pseudo-material W~ (constants of eq. 6.20) on the Unl table of its
   *   members and subtracts it at its master;
   * - Peridigm's hourglass force ('Hourglass coefficient' > 0);
   * - U1SIG (eqs. 6.21-6.28, pg-methods.md section 12.3.3): the implicit-
   *   gradient energy 1/2 M_xx grad F : A~ : grad F with A~ the tangent of
   *   W~ at the master's deformation gradient of the last accepted step
   *   (frozen per load step; stored in the point history, dim^2 values).
   */
  template <int dim>
  struct U1Stabilisation
  {
    /** U1SUnl: the Unl tables (Discretization::stabilisation_tables). */
    const std::vector<QuadratureTable<dim>> *tables = nullptr;
    /**
     * U1SUnl and U1SIG: W~, with E~ = E (no plasticity yet),
     * nu~ = min(0.49, nu).
     */
    const Materials::Material<dim> *pseudo_material = nullptr;
    /**
     * U1SUnl: false if W~ = W (nu <= 0.49); then the master terms cancel
     * exactly and the family is the Unl family of the real material, which
     * is assembled alone.
     */
    bool master_terms = true;
    /**
     * Hourglass: the constant 18 alpha K / (pi delta^4) of every owned
     * family (hourglass_constant()); empty: no hourglass force.
     */
    std::vector<double> hourglass_constants;
    /**
     * U1SIG: the MLS1 second derivatives h^b at the master of every owned
     * family (ShapeFunctions::mls1_second_derivatives(), node order of the
     * family); empty: no implicit-gradient stabilisation.
     */
    std::vector<std::vector<Tensor<2, dim>>> implicit_gradients;
    /** U1SIG: M_xx of every owned family (particle_second_moment()). */
    std::vector<double> second_moments;
  };



  /**
   * The PG families (PPG, PBG, VC, BC ...: whatever the family tables
   * hold): the common kernel on each family's quadrature table. With a
   * @p condensed_pressure material the families are UnlP0 (eq. 6.9):
   * assemble_condensed_pressure_element() with p and Theta constant per
   * family, the volumetric points being the table's (PBG) or the master
   * (PPG, from @p family_elements); with @p condensed_pressure_degree = 1
   * they are U2P1 (eq. 6.10): p and Theta linear per family.
   */
  template <int dim>
  class FamilyGroup : public FamilyGroupBase<dim>
  {
  public:
    FamilyGroup(
      const std::vector<unsigned int>         &owned_families,
      const FamilySet<dim>                    &families,
      const ParticleSet<dim>                  &particles,
      const std::vector<QuadratureTable<dim>> &family_tables,
      const Materials::Material<dim>          &material,
      const Materials::VolumetricSplit<dim>   *condensed_pressure = nullptr,
      const FamilyElements<dim>               *family_elements    = nullptr,
      const unsigned int                       condensed_pressure_degree = 0);

    /**
     * Stabilise the families, whose tables (given to the constructor) are
     * U1: @p stabilisation adds the U1SUnl pseudo-energy (the material
     * must then be stateless) or the hourglass force.
     */
    void
    set_stabilisation(const U1Stabilisation<dim> &stabilisation);

    std::string
    name() const override;

    /**
     * Every family couples all DoFs of its members. Row by row: the row of
     * particle i gets the members of every owned family that contains i,
     * once, instead of each family's 189^2 entries one by one (set-up on
     * Peridigm's tensile bar, 63 members per family: 8.5 s -> 4.1 s).
     * Falls back to the element loop if a member's DoF is constrained to
     * other DoFs (a hanging node), whose couplings AffineConstraints adds.
     */
    void
    add_group_sparsity(const AffineConstraints<double> &constraints,
                       DynamicSparsityPattern &sparsity) const override;

    unsigned int
    n_evaluation_points(const unsigned int e) const override;

    /** The weights of the tables whose points carry the history. */
    std::vector<double>
    evaluation_point_weights() const override;

    std::unique_ptr<GroupScratch>
    create_scratch() const override;

    void
    assemble(const unsigned int           e,
             const LinearAlgebra::Vector &u,
             const ElementHistory        &history,
             GroupScratch                &scratch,
             LocalSystem                 &local) const override;

  private:
    /** The tables whose points carry the history, by element. */
    const std::vector<QuadratureTable<dim>> &
    evaluation_tables() const;

    const std::vector<QuadratureTable<dim>> &family_tables;
    U1Stabilisation<dim>                     stabilisation;
    const Materials::Material<dim>          &material;
    const Materials::VolumetricSplit<dim>   *condensed_pressure;
    /** For the master tables of PPG UnlP0; nullptr otherwise. */
    const FamilyElements<dim> *family_elements;
    /** 0: UnlP0, 1: U2P1. */
    const unsigned int condensed_pressure_degree;
  };



  /**
   * The CPD interactions (continuum-kinematics-inspired peridynamics),
   * stored by master particle: a family couples its master to its
   * neighbours only (one horizon), so its sparsity rows are the master's.
   */
  template <int dim>
  class CpdGroup : public FamilyGroupBase<dim>
  {
  public:
    CpdGroup(const std::vector<unsigned int> &owned_families,
             const FamilySet<dim>            &families,
             const ParticleSet<dim>          &particles,
             const CpdInteractions<dim>      &interactions);

    std::string
    name() const override;

    void
    add_sparsity(const unsigned int               e,
                 const AffineConstraints<double> &constraints,
                 DynamicSparsityPattern          &sparsity) const override;

    /** The bond, area and volume interactions of the master. */
    unsigned int
    n_evaluation_points(const unsigned int e) const override;

    std::unique_ptr<GroupScratch>
    create_scratch() const override;

    void
    assemble(const unsigned int           e,
             const LinearAlgebra::Vector &u,
             const ElementHistory        &history,
             GroupScratch                &scratch,
             LocalSystem                 &local) const override;

  private:
    const CpdInteractions<dim> &interactions;
  };
} // namespace pg

#endif
