#ifndef pg_elements_nodal_pressure_group_h
#define pg_elements_nodal_pressure_group_h

#include <pg/elements/family_group.h>

namespace pg
{
  /**
   * The families of U2P1C and Unl+P1C (pg-methods.md sections
   * 12.2.2-12.2.3): PBG families whose members carry the nodal pressure and
   * dilatation as DoFs besides u (ParticleSet::dof(k, dim) and
   * (k, dim + 1), dofs/field_layout.h). Element e has the DoFs u of its
   * members node-major, then their p, then their vartheta = Theta - theta(I)
   * (assemble_nodal_pressure_family()); Unl+P1C condenses its bubble and
   * keeps it as a Newton iterate (keep_condensed_field_iterates()).
   */
  template <int dim>
  class NodalPressureFamilyGroup : public FamilyGroupBase<dim>
  {
  public:
    NodalPressureFamilyGroup(
      const std::vector<unsigned int>         &owned_families,
      const FamilySet<dim>                    &families,
      const ParticleSet<dim>                  &particles,
      const std::vector<QuadratureTable<dim>> &family_tables,
      const Materials::VolumetricSplit<dim>   &material,
      const bool                               bubble);

    std::string
    name() const override;

    void
    get_dof_indices(const unsigned int                    e,
                    std::vector<types::global_dof_index> &dofs) const override;

    unsigned int
    n_evaluation_points(const unsigned int e) const override;

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
    /**
     * Append p and vartheta of the members to the u DoFs @p dofs of family
     * @p e (FamilyGroupBase's, node-major).
     */
    void
    append_field_dofs(const unsigned int                    e,
                      std::vector<types::global_dof_index> &dofs) const;

    const std::vector<QuadratureTable<dim>> &family_tables;
    const Materials::VolumetricSplit<dim>   &material;
    const bool                               bubble;
  };



  /**
   * The families of IUnlP0, the incompressible UnlP0 (pg-methods.md
   * section 12.2.1): Unl families (PBG or PPG tables) whose constant
   * pressure p^k is the one extra nodal field of the master particle k
   * (ParticleSet::dof(k, dim)). Element e has the DoFs u of its members
   * node-major, then p^k (assemble_incompressible_p0_element()); the
   * volumetric points are the table's (PBG) or the master's (PPG, from
   * @p family_elements).
   */
  template <int dim>
  class IncompressibleFamilyGroup : public FamilyGroupBase<dim>
  {
  public:
    IncompressibleFamilyGroup(
      const std::vector<unsigned int>         &owned_families,
      const FamilySet<dim>                    &families,
      const ParticleSet<dim>                  &particles,
      const std::vector<QuadratureTable<dim>> &family_tables,
      const Materials::VolumetricSplit<dim>   &material,
      const FamilyElements<dim>               *family_elements);

    std::string
    name() const override;

    void
    get_dof_indices(const unsigned int                    e,
                    std::vector<types::global_dof_index> &dofs) const override;

    unsigned int
    n_evaluation_points(const unsigned int e) const override;

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
    const std::vector<QuadratureTable<dim>> &family_tables;
    const Materials::VolumetricSplit<dim>   &material;
    /** PPG: builds the master table; nullptr for PBG. */
    const FamilyElements<dim> *family_elements;
  };
} // namespace pg

#endif
