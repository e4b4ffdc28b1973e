#include <pg/base/global_reader.h>
#include <pg/elements/condensed_pressure.h>
#include <pg/elements/nodal_pressure.h>
#include <pg/elements/nodal_pressure_group.h>

namespace pg
{
  namespace
  {
    /** The members' positions and nodal fields of one family. */
    template <int dim>
    struct NodalPressureScratch : public GroupScratch
    {
      std::unique_ptr<GroupScratch>
      clone() const override
      {
        return std::make_unique<NodalPressureScratch>();
      }

      std::vector<Tensor<1, dim>> y;
      std::vector<double>         p, vartheta;
      /** IUnlP0 with PPG: the volumetric point, the master. */
      QuadratureTable<dim> master_table;
    };
  } // namespace



  template <int dim>
  NodalPressureFamilyGroup<dim>::NodalPressureFamilyGroup(
    const std::vector<unsigned int>         &owned_families,
    const FamilySet<dim>                    &families,
    const ParticleSet<dim>                  &particles,
    const std::vector<QuadratureTable<dim>> &family_tables,
    const Materials::VolumetricSplit<dim>   &material,
    const bool                               bubble)
    : FamilyGroupBase<dim>(owned_families, families, particles)
    , family_tables(family_tables)
    , material(material)
    , bubble(bubble)
  {
    AssertThrow(particles.n_components() == dim + 2, ExcInternalError());
  }



  template <int dim>
  std::string
  NodalPressureFamilyGroup<dim>::name() const
  {
    return bubble ? "Unl+P1C families" : "U2P1C families";
  }



  template <int dim>
  void
  NodalPressureFamilyGroup<dim>::get_dof_indices(
    const unsigned int                    e,
    std::vector<types::global_dof_index> &dofs) const
  {
    FamilyGroupBase<dim>::get_dof_indices(e, dofs);
    append_field_dofs(e, dofs);
  }



  template <int dim>
  void
  NodalPressureFamilyGroup<dim>::append_field_dofs(
    const unsigned int                    e,
    std::vector<types::global_dof_index> &dofs) const
  {
    const auto members   = this->families.members(this->owned_families[e]);
    const unsigned int n = members.size();
    AssertDimension(dofs.size(), n * dim);
    dofs.resize(n * (dim + 2));
    for (unsigned int b = 0; b < n; ++b)
      {
        dofs[n * dim + b]     = this->particles.dof(members[b], dim);
        dofs[n * dim + n + b] = this->particles.dof(members[b], dim + 1);
      }
  }



  template <int dim>
  unsigned int
  NodalPressureFamilyGroup<dim>::n_evaluation_points(const unsigned int e) const
  {
    return family_tables[e].n_points();
  }



  template <int dim>
  std::vector<double>
  NodalPressureFamilyGroup<dim>::evaluation_point_weights() const
  {
    return concatenated_weights(family_tables, this->n_elements());
  }



  template <int dim>
  std::unique_ptr<GroupScratch>
  NodalPressureFamilyGroup<dim>::create_scratch() const
  {
    return std::make_unique<NodalPressureScratch<dim>>();
  }



  template <int dim>
  void
  NodalPressureFamilyGroup<dim>::assemble(const unsigned int           e,
                                          const LinearAlgebra::Vector &u,
                                          const ElementHistory        &history,
                                          GroupScratch &scratch_base,
                                          LocalSystem  &local) const
  {
    auto &scratch = static_cast<NodalPressureScratch<dim> &>(scratch_base);
    this->gather(e, u, local.dofs, scratch.y);
    append_field_dofs(e, local.dofs);
    const unsigned int                n = scratch.y.size();
    const LinearAlgebra::GlobalReader u_at(u);
    scratch.p.resize(n);
    scratch.vartheta.resize(n);
    for (unsigned int b = 0; b < n; ++b)
      {
        scratch.p[b]        = u_at[local.dofs[n * dim + b]];
        scratch.vartheta[b] = u_at[local.dofs[n * dim + n + b]];
      }
    assemble_nodal_pressure_family(family_tables[e],
                                   scratch.y,
                                   scratch.p,
                                   scratch.vartheta,
                                   material,
                                   bubble,
                                   local.residual,
                                   local.with_matrix ? &local.matrix : nullptr,
                                   bubble ? this->condensed_field_iterate(e) :
                                            nullptr,
                                   history.committed,
                                   history.trial);
  }



  template <int dim>
  IncompressibleFamilyGroup<dim>::IncompressibleFamilyGroup(
    const std::vector<unsigned int>         &owned_families,
    const FamilySet<dim>                    &families,
    const ParticleSet<dim>                  &particles,
    const std::vector<QuadratureTable<dim>> &family_tables,
    const Materials::VolumetricSplit<dim>   &material,
    const FamilyElements<dim>               *family_elements)
    : FamilyGroupBase<dim>(owned_families, families, particles)
    , family_tables(family_tables)
    , material(material)
    , family_elements(family_elements)
  {
    AssertThrow(particles.n_components() == dim + 1, ExcInternalError());
  }



  template <int dim>
  std::string
  IncompressibleFamilyGroup<dim>::name() const
  {
    return "IUnlP0 families";
  }



  template <int dim>
  void
  IncompressibleFamilyGroup<dim>::get_dof_indices(
    const unsigned int                    e,
    std::vector<types::global_dof_index> &dofs) const
  {
    FamilyGroupBase<dim>::get_dof_indices(e, dofs);
    dofs.push_back(this->particles.dof(this->owned_families[e], dim));
  }



  template <int dim>
  unsigned int
  IncompressibleFamilyGroup<dim>::n_evaluation_points(
    const unsigned int e) const
  {
    return family_tables[e].n_points();
  }



  template <int dim>
  std::vector<double>
  IncompressibleFamilyGroup<dim>::evaluation_point_weights() const
  {
    return concatenated_weights(family_tables, this->n_elements());
  }



  template <int dim>
  std::unique_ptr<GroupScratch>
  IncompressibleFamilyGroup<dim>::create_scratch() const
  {
    return std::make_unique<NodalPressureScratch<dim>>();
  }



  template <int dim>
  void
  IncompressibleFamilyGroup<dim>::assemble(const unsigned int           e,
                                           const LinearAlgebra::Vector &u,
                                           const ElementHistory        &history,
                                           GroupScratch &scratch_base,
                                           LocalSystem  &local) const
  {
    auto &scratch = static_cast<NodalPressureScratch<dim> &>(scratch_base);
    const unsigned int k = this->owned_families[e];
    this->gather(e, u, local.dofs, scratch.y);
    local.dofs.push_back(this->particles.dof(k, dim));
    const double pressure = LinearAlgebra::GlobalReader(u)[local.dofs.back()];
    if (family_elements != nullptr)
      family_elements->build_master_table(k, scratch.master_table);
    assemble_incompressible_p0_element(
      family_tables[e],
      family_elements != nullptr ? &scratch.master_table : nullptr,
      scratch.y,
      material,
      pressure,
      local.residual,
      local.with_matrix ? &local.matrix : nullptr,
      history.committed,
      history.trial);
  }



  template class NodalPressureFamilyGroup<2>;
  template class NodalPressureFamilyGroup<3>;
  template class IncompressibleFamilyGroup<2>;
  template class IncompressibleFamilyGroup<3>;
} // namespace pg
