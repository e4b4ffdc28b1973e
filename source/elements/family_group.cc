#include <pg/base/global_reader.h>
#include <pg/elements/condensed_pressure.h>
#include <pg/elements/family_group.h>
#include <pg/elements/u1_stabilisation.h>

#include <algorithm>

namespace pg
{
  namespace
  {
    /** The members' positions y of one family (per thread). */
    template <int dim>
    struct FamilyScratch : public GroupScratch
    {
      std::unique_ptr<GroupScratch>
      clone() const override
      {
        return std::make_unique<FamilyScratch>();
      }

      std::vector<Tensor<1, dim>> y;
      /** The volumetric point of a PPG UnlP0 family. */
      QuadratureTable<dim> master_table;
      /** The terms of a U1SUnl family. */
      U1SUnlScratch u1s_unl;
      /** Reference bonds and volumes of a family with hourglass force. */
      std::vector<Tensor<1, dim>> xi;
      std::vector<double>         volumes;
    };
  } // namespace



  template <int dim>
  FamilyGroupBase<dim>::FamilyGroupBase(
    const std::vector<unsigned int> &owned_families,
    const FamilySet<dim>            &families,
    const ParticleSet<dim>          &particles)
    : owned_families(owned_families)
    , families(families)
    , particles(particles)
  {}



  template <int dim>
  unsigned int
  FamilyGroupBase<dim>::n_elements() const
  {
    return owned_families.size();
  }



  template <int dim>
  void
  FamilyGroupBase<dim>::get_dof_indices(
    const unsigned int                    e,
    std::vector<types::global_dof_index> &dofs) const
  {
    const auto members = families.members(owned_families[e]);
    dofs.resize(members.size() * dim);
    for (unsigned int b = 0; b < members.size(); ++b)
      for (unsigned int c = 0; c < dim; ++c)
        dofs[b * dim + c] = particles.dof(members[b], c);
  }



  template <int dim>
  void
  FamilyGroupBase<dim>::gather(const unsigned int                    e,
                               const LinearAlgebra::Vector          &u,
                               std::vector<types::global_dof_index> &dofs,
                               std::vector<Tensor<1, dim>>          &y) const
  {
    const unsigned int                k       = owned_families[e];
    const auto                        members = families.members(k);
    const unsigned int                n       = members.size();
    const LinearAlgebra::GlobalReader u_at(u);
    dofs.resize(n * dim);
    y.resize(n);
    for (unsigned int b = 0; b < n; ++b)
      for (unsigned int c = 0; c < dim; ++c)
        {
          dofs[b * dim + c] = particles.dof(members[b], c);
          y[b][c] =
            particles.position(members[b])[c] - particles.position(k)[c] +
            particles.mirror_sign(members[b], c) * u_at[dofs[b * dim + c]];
        }
  }



  template <int dim>
  void
  FamilyGroupBase<dim>::get_dof_signs(const unsigned int   e,
                                      std::vector<double> &signs) const
  {
    signs.clear();
    const auto members = families.members(owned_families[e]);
    // members are sorted: the images, numbered last, come last
    if (members[members.size() - 1] < particles.n_particles())
      return;
    std::vector<types::global_dof_index> dofs;
    this->get_dof_indices(e, dofs); // the extra fields of derived groups
    signs.assign(dofs.size(), 1.);
    for (unsigned int b = 0; b < members.size(); ++b)
      for (unsigned int c = 0; c < dim; ++c)
        signs[b * dim + c] = particles.mirror_sign(members[b], c);
  }



  template <int dim>
  std::string
  FamilyGroupBase<dim>::element_name(const unsigned int e) const
  {
    return "the family of particle " + std::to_string(owned_families[e]);
  }



  template <int dim>
  Point<dim>
  FamilyGroupBase<dim>::element_position(const unsigned int e) const
  {
    return particles.position(owned_families[e]);
  }



  template <int dim>
  std::string
  FamilyGroupBase<dim>::non_finite_hint() const
  {
    return "Coincident particles (e.g. unmerged mesh vertices), an empty or "
           "degenerate family, or a NaN in the prescribed displacement make "
           "it.";
  }



  template <int dim>
  FamilyGroup<dim>::FamilyGroup(
    const std::vector<unsigned int>         &owned_families,
    const FamilySet<dim>                    &families,
    const ParticleSet<dim>                  &particles,
    const std::vector<QuadratureTable<dim>> &family_tables,
    const Materials::Material<dim>          &material,
    const Materials::VolumetricSplit<dim>   *condensed_pressure,
    const FamilyElements<dim>               *family_elements,
    const unsigned int                       condensed_pressure_degree)
    : FamilyGroupBase<dim>(owned_families, families, particles)
    , family_tables(family_tables)
    , material(material)
    , condensed_pressure(condensed_pressure)
    , family_elements(family_elements)
    , condensed_pressure_degree(condensed_pressure_degree)
  {
    Assert(condensed_pressure_degree == 0 || family_elements == nullptr,
           ExcInternalError());
  }



  template <int dim>
  void
  FamilyGroup<dim>::set_stabilisation(
    const U1Stabilisation<dim> &new_stabilisation)
  {
    Assert(
      (new_stabilisation.tables == nullptr ||
       (new_stabilisation.tables->size() == family_tables.size() &&
        new_stabilisation.pseudo_material != nullptr &&
        new_stabilisation.pseudo_material->n_state_variables() == 0)) &&
        (new_stabilisation.hourglass_constants.empty() ||
         new_stabilisation.hourglass_constants.size() ==
           family_tables.size()) &&
        (new_stabilisation.implicit_gradients.empty() ||
         (new_stabilisation.implicit_gradients.size() == family_tables.size() &&
          new_stabilisation.second_moments.size() == family_tables.size() &&
          new_stabilisation.pseudo_material != nullptr &&
          new_stabilisation.pseudo_material->n_state_variables() == 0)) &&
        condensed_pressure == nullptr,
      ExcInternalError());
    stabilisation = new_stabilisation;
  }



  template <int dim>
  std::string
  FamilyGroup<dim>::name() const
  {
    return condensed_pressure != nullptr ?
             (condensed_pressure_degree == 1 ? "PG families (U2P1)" :
                                               "PG families (UnlP0)") :
           stabilisation.tables != nullptr ? "PG families (U1SUnl)" :
           !stabilisation.implicit_gradients.empty() ?
                                             "PG families (U1SIG)" :
           !stabilisation.hourglass_constants.empty() ?
                                             "PG families (U1, hourglass)" :
                                             "PG families";
  }



  template <int dim>
  void
  FamilyGroup<dim>::add_group_sparsity(
    const AffineConstraints<double> &constraints,
    DynamicSparsityPattern          &sparsity) const
  {
    // the owned families that contain each particle, and whether a member
    // DoF has a constraint with entries (keep_constrained_dofs = true adds
    // nothing else for the others: the pattern is then the cliques)
    const unsigned int n_particles = this->particles.n_particles();
    std::vector<std::vector<unsigned int>> containing(n_particles);
    for (unsigned int e = 0; e < this->n_elements(); ++e)
      for (const unsigned int i :
           this->families.members(this->owned_families[e]))
        {
          // a mirror image couples like its original
          containing[this->particles.original(i)].push_back(
            this->owned_families[e]);
          for (unsigned int c = 0; c < dim; ++c)
            if (const auto *entries =
                  constraints.get_constraint_entries(this->particles.dof(i, c));
                entries != nullptr && !entries->empty())
              {
                ElementGroup<dim>::add_group_sparsity(constraints, sparsity);
                return;
              }
        }

    std::vector<unsigned int>            last_row(n_particles,
                                       numbers::invalid_unsigned_int);
    std::vector<unsigned int>            coupled;
    std::vector<types::global_dof_index> columns;
    for (unsigned int i = 0; i < n_particles; ++i)
      {
        if (containing[i].empty())
          continue;
        coupled.clear();
        for (const unsigned int k : containing[i])
          for (const unsigned int image : this->families.members(k))
            if (const unsigned int j = this->particles.original(image);
                last_row[j] != i)
              {
                last_row[j] = i;
                coupled.push_back(j);
              }
        columns.clear();
        for (const unsigned int j : coupled)
          for (unsigned int c = 0; c < dim; ++c)
            columns.push_back(this->particles.dof(j, c));
        std::sort(columns.begin(), columns.end());
        for (unsigned int c = 0; c < dim; ++c)
          sparsity.add_entries(this->particles.dof(i, c),
                               columns.begin(),
                               columns.end(),
                               true);
      }
  }



  template <int dim>
  const std::vector<QuadratureTable<dim>> &
  FamilyGroup<dim>::evaluation_tables() const
  {
    // U1SUnl without the master's terms evaluates the material at the
    // points of its Unl table only
    if (stabilisation.tables != nullptr && !stabilisation.master_terms)
      return *stabilisation.tables;
    return family_tables;
  }



  template <int dim>
  unsigned int
  FamilyGroup<dim>::n_evaluation_points(const unsigned int e) const
  {
    return evaluation_tables()[e].n_points();
  }



  template <int dim>
  std::vector<double>
  FamilyGroup<dim>::evaluation_point_weights() const
  {
    return concatenated_weights(evaluation_tables(), this->n_elements());
  }



  template <int dim>
  std::unique_ptr<GroupScratch>
  FamilyGroup<dim>::create_scratch() const
  {
    return std::make_unique<FamilyScratch<dim>>();
  }



  template <int dim>
  void
  FamilyGroup<dim>::assemble(const unsigned int           e,
                             const LinearAlgebra::Vector &u,
                             const ElementHistory        &history,
                             GroupScratch                &scratch_base,
                             LocalSystem                 &local) const
  {
    auto &scratch = static_cast<FamilyScratch<dim> &>(scratch_base);
    this->gather(e, u, local.dofs, scratch.y);
    FullMatrix<double> *tangent = local.with_matrix ? &local.matrix : nullptr;
    // the material's part of the point history (U1SIG keeps its own
    // entries after it)
    MaterialStateSlices state(history,
                              n_evaluation_points(e),
                              material.n_state_variables());
    if (stabilisation.tables != nullptr)
      {
        const auto &unl_table = (*stabilisation.tables)[e];
        if (stabilisation.master_terms)
          assemble_u1s_unl_element(family_tables[e],
                                   unl_table,
                                   scratch.y,
                                   material,
                                   *stabilisation.pseudo_material,
                                   local.residual,
                                   tangent,
                                   scratch.u1s_unl,
                                   state.committed(),
                                   state.trial());
        else
          assemble_element(unl_table,
                           scratch.y,
                           material,
                           local.residual,
                           tangent,
                           state.committed(),
                           state.trial());
        state.write_back();
        return;
      }
    if (condensed_pressure != nullptr)
      {
        const bool master_point = (family_elements != nullptr);
        if (master_point)
          family_elements->build_master_table(this->owned_families[e],
                                              scratch.master_table);
        assemble_condensed_pressure_element(
          family_tables[e],
          master_point ? &scratch.master_table : nullptr,
          scratch.y,
          *condensed_pressure,
          local.residual,
          local.with_matrix ? &local.matrix : nullptr,
          condensed_pressure_degree,
          this->condensed_field_iterate(e),
          state.committed(),
          state.trial());
        state.write_back();
        return;
      }
    assemble_element(family_tables[e],
                     scratch.y,
                     material,
                     local.residual,
                     tangent,
                     state.committed(),
                     state.trial());
    state.write_back();
    if (!stabilisation.hourglass_constants.empty())
      {
        const unsigned int k       = this->owned_families[e];
        const auto         members = this->families.members(k);
        scratch.xi.resize(members.size());
        scratch.volumes.resize(members.size());
        for (unsigned int b = 0; b < members.size(); ++b)
          {
            scratch.xi[b] = this->particles.position(members[b]) -
                            this->particles.position(k);
            scratch.volumes[b] = this->particles.member_volume(members[b]);
          }
        add_hourglass_force(family_tables[e],
                            scratch.xi,
                            scratch.y,
                            scratch.volumes,
                            stabilisation.hourglass_constants[e] *
                              this->particles.family_share(k),
                            local.residual,
                            tangent);
      }
    if (!stabilisation.implicit_gradients.empty())
      {
        // A~ at the master's F of the last accepted step (the committed
        // history, after the material's state of the family's one point);
        // the trial history gets this iterate's F
        const unsigned int first = material.n_state_variables();
        AssertDimension(family_tables[e].n_points(), 1);
        AssertDimension(history.n_variables, first + dim * dim);
        AssertDimension(history.committed.size(), first + dim * dim);
        Tensor<2, dim> F_accepted;
        for (unsigned int i = 0; i < dim; ++i)
          for (unsigned int j = 0; j < dim; ++j)
            F_accepted[i][j] = history.committed[first + i * dim + j];
        Tensor<2, dim> P;
        Tensor<4, dim> A;
        stabilisation.pseudo_material->evaluate(F_accepted, P, A);
        add_implicit_gradient_stabilisation(stabilisation.implicit_gradients[e],
                                            stabilisation.second_moments[e],
                                            A,
                                            scratch.y,
                                            local.residual,
                                            tangent);
        const Tensor<2, dim> F =
          deformation_gradient(family_tables[e], 0, scratch.y);
        for (unsigned int i = 0; i < dim; ++i)
          for (unsigned int j = 0; j < dim; ++j)
            history.trial[first + i * dim + j] = F[i][j];
      }
  }



  template <int dim>
  CpdGroup<dim>::CpdGroup(const std::vector<unsigned int> &owned_families,
                          const FamilySet<dim>            &families,
                          const ParticleSet<dim>          &particles,
                          const CpdInteractions<dim>      &interactions)
    : FamilyGroupBase<dim>(owned_families, families, particles)
    , interactions(interactions)
  {}



  template <int dim>
  std::string
  CpdGroup<dim>::name() const
  {
    return "CPD interactions";
  }



  template <int dim>
  void
  CpdGroup<dim>::add_sparsity(const unsigned int               e,
                              const AffineConstraints<double> &constraints,
                              DynamicSparsityPattern          &sparsity) const
  {
    // Particle k couples to its neighbours (its row and column), and the
    // vertices j, l of its triangles and tetrahedra to each other. On one
    // rank the j-l entries also come from family j (j and l are
    // neighbours); on more, a rank writes them into rows it may not own,
    // so they must be in its own pattern.
    // A mirror image has its original's DoFs: each DoF once.
    const auto unique = [](std::vector<types::global_dof_index> &v) {
      std::sort(v.begin(), v.end());
      v.erase(std::unique(v.begin(), v.end()), v.end());
    };
    std::vector<types::global_dof_index> dofs;
    this->get_dof_indices(e, dofs);
    std::vector<types::global_dof_index> block(2 * dim);
    for (const auto &[p, q] :
         interactions.coupled_members(this->owned_families[e]))
      {
        block.resize(2 * dim);
        for (unsigned int c = 0; c < dim; ++c)
          {
            block[c]       = dofs[p * dim + c];
            block[dim + c] = dofs[q * dim + c];
          }
        unique(block);
        constraints.add_entries_local_to_global(block, sparsity, true);
      }
    // each member's own block: the constrained DoFs get their diagonal
    // entry from AffineConstraints::distribute_local_to_global() in every
    // element they belong to, also in rows that another rank owns
    for (unsigned int b = 1; b < dofs.size() / dim; ++b)
      {
        block.assign(dofs.begin() + b * dim, dofs.begin() + (b + 1) * dim);
        constraints.add_entries_local_to_global(block, sparsity, true);
      }
    std::vector<types::global_dof_index> row(dofs.begin(), dofs.begin() + dim);
    unique(dofs);
    constraints.add_entries_local_to_global(row, dofs, sparsity, true);
    constraints.add_entries_local_to_global(dofs, row, sparsity, true);
  }



  template <int dim>
  unsigned int
  CpdGroup<dim>::n_evaluation_points(const unsigned int e) const
  {
    const auto n = interactions.n_interactions(this->owned_families[e]);
    return n[0] + n[1] + n[2];
  }



  template <int dim>
  std::unique_ptr<GroupScratch>
  CpdGroup<dim>::create_scratch() const
  {
    return std::make_unique<FamilyScratch<dim>>();
  }



  template <int dim>
  void
  CpdGroup<dim>::assemble(const unsigned int           e,
                          const LinearAlgebra::Vector &u,
                          const ElementHistory &,
                          GroupScratch &scratch_base,
                          LocalSystem  &local) const
  {
    auto &scratch = static_cast<FamilyScratch<dim> &>(scratch_base);
    this->gather(e, u, local.dofs, scratch.y);
    interactions.assemble(this->owned_families[e],
                          scratch.y,
                          local.residual,
                          local.with_matrix ? &local.matrix : nullptr);
  }



  template class FamilyGroupBase<2>;
  template class FamilyGroupBase<3>;
  template class FamilyGroup<2>;
  template class FamilyGroup<3>;
  template class CpdGroup<2>;
  template class CpdGroup<3>;
} // namespace pg
