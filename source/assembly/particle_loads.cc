#include <pg/assembly/particle_loads.h>
#include <pg/elements/unit_stress_residual.h>

#include <deal.II/base/quadrature_lib.h>
#include <deal.II/fe/fe_values.h>

#include <algorithm>
#include <string>

namespace pg
{
  template <int dim>
  ParticleLoads<dim>::ParticleLoads(
    const Parameters::AllParameters<dim> &parameters,
    const FormulationCode                &formulation,
    const Loads<dim>                     &loads,
    const ParticleSet<dim>               &particles,
    const std::vector<unsigned int>      &owned_families,
    const std::vector<CellIterator>      &meshfree_neumann_cells,
    const ParticleForce                  &exact_stress_force)
    : loads(loads)
    , particles(particles)
    , owned_families(owned_families)
    , meshfree_neumann_cells(meshfree_neumann_cells)
    , exact_stress_force(exact_stress_force)
    , from_test_functions(
        parameters.boundary_conditions.particle_traction_area ==
          "test functions" ||
        (parameters.boundary_conditions.particle_traction_area == "automatic" &&
         formulation.variational_consistency))
    , from_exact_stress(parameters.boundary_conditions.particle_traction_area ==
                        "exact stress")
    , fe_scalar(1)
  {}



  template <int dim>
  bool
  ParticleLoads<dim>::traction_from_test_functions() const
  {
    return from_test_functions;
  }



  template <int dim>
  bool
  ParticleLoads<dim>::traction_from_exact_stress() const
  {
    return from_exact_stress;
  }



  template <int dim>
  void
  ParticleLoads<dim>::compute_unit_stress_residual(
    const FamilySet<dim>                    &families,
    const std::vector<QuadratureTable<dim>> &tables,
    const MPI_Comm                           comm)
  {
    unit_stress_residual = pg::unit_stress_residual(families,
                                                    owned_families,
                                                    tables,
                                                    particles,
                                                    comm);
    area_weights = pg::boundary_area_weights(particles, unit_stress_residual);
  }



  template <int dim>
  const std::vector<Tensor<1, dim>> &
  ParticleLoads<dim>::unit_stress() const
  {
    return unit_stress_residual;
  }



  template <int dim>
  double
  ParticleLoads<dim>::max_interior_unit_stress_residual() const
  {
    return pg::max_interior_unit_stress_residual(particles,
                                                 unit_stress_residual);
  }



  template <int dim>
  const std::vector<std::map<types::boundary_id, double>> &
  ParticleLoads<dim>::boundary_area_weights() const
  {
    return area_weights;
  }



  template <int dim>
  void
  ParticleLoads<dim>::particle_load(const unsigned int k,
                                    Vector<double>    &load) const
  {
    load              = 0;
    const auto &areas = particles.boundary_area_vectors(k);
    if (from_exact_stress && !particles.on_interface(k) &&
        std::any_of(areas.begin(), areas.end(), [&](const auto &area) {
          return loads.is_neumann(area.first);
        }))
      {
        // the surface load plus the body force: the whole internal force
        // of the exact stress
        const Tensor<1, dim> force = exact_stress_force(k);
        for (unsigned int c = 0; c < dim; ++c)
          load(c) = force[c];
      }
    else
      {
        Vector<double> f(dim);
        loads.body_force(particles.position(k), f);
        for (unsigned int c = 0; c < dim; ++c)
          load(c) += particles.volume(k) * f(c);
      }
    if (from_test_functions)
      for (const auto &[id, area] : areas)
        if (loads.is_neumann(id))
          {
            const Tensor<1, dim> t =
              loads.prescribed_traction(id,
                                        particles.position(k),
                                        area / area.norm());
            // On the FE/meshfree interface the VC targets d^k are the
            // geometric area vectors (interface plus surface part), so the
            // consistent load there is the geometric one.
            const double a =
              particles.on_interface(k) ? area.norm() : area_weights[k].at(id);
            for (unsigned int c = 0; c < dim; ++c)
              load(c) += a * t[c];
          }
  }



  template <int dim>
  void
  ParticleLoads<dim>::add_to(Assembler<dim> &assembler) const
  {
    // no body force and no traction: every particle load is zero
    if (!loads.any())
      return;
    Vector<double>                       load(dim);
    std::vector<types::global_dof_index> dofs(dim);
    for (const unsigned int k : owned_families)
      {
        particle_load(k, load);
        if (!all_finite(load))
          assembler.record_failure(Assembler<dim>::non_finite_message(
            "the load of particle " + std::to_string(k),
            particles.position(k),
            "Check the 'Traction' and 'Body force' functions."));
        for (unsigned int c = 0; c < dim; ++c)
          dofs[c] = particles.dof(k, c);
        assembler.add_load(load, dofs);
      }
    add_meshfree_face_tractions(assembler);
  }



  template <int dim>
  typename Assembler<dim>::LoadTerm
  ParticleLoads<dim>::load_term() const
  {
    return [this](Assembler<dim> &assembler) { add_to(assembler); };
  }



  template <int dim>
  void
  ParticleLoads<dim>::add_meshfree_face_tractions(
    Assembler<dim> &assembler) const
  {
    if (meshfree_neumann_cells.empty())
      return;
    FEFaceValues<dim> fe_face_values(fe_scalar,
                                     QGauss<dim - 1>(2),
                                     update_values | update_quadrature_points |
                                       update_normal_vectors |
                                       update_JxW_values);
    LocalSystem       local_system;
    local_system.with_matrix = false;
    for (const auto &cell : meshfree_neumann_cells)
      {
        // the displacement DoFs, node-major (a meshfree cell may carry
        // extra nodal fields besides)
        local_system.dofs.resize(cell->n_vertices() * dim);
        for (const unsigned int v : cell->vertex_indices())
          for (unsigned int c = 0; c < dim; ++c)
            local_system.dofs[v * dim + c] = cell->vertex_dof_index(v, c);
        local_system.residual.reinit(local_system.dofs.size());
        loads.add_face_tractions(cell, fe_face_values, local_system.residual);
        if (!all_finite(local_system.residual))
          assembler.record_failure(Assembler<dim>::non_finite_message(
            "the traction on meshfree cell " +
              std::to_string(cell->active_cell_index()),
            cell->center(),
            "Check the 'Traction' function."));
        assembler.distribute(local_system);
      }
  }



  template class ParticleLoads<2>;
  template class ParticleLoads<3>;
} // namespace pg
