#include <pg/assembly/particle_loads.h>
#include <pg/elements/unit_stress_residual.h>
#include <pg/mesh/linear_cells.h>

#include <deal.II/base/quadrature_lib.h>
#include <deal.II/fe/fe_values.h>

#include <algorithm>
#include <cmath>
#include <limits>
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
    , partial_time(std::numeric_limits<double>::quiet_NaN())
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
    partial_time = std::numeric_limits<double>::quiet_NaN();
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
            const Tensor<1, dim> f = traction_load(k, id, area);
            for (unsigned int c = 0; c < dim; ++c)
              load(c) += f[c];
          }
  }



  template <int dim>
  Tensor<1, dim>
  ParticleLoads<dim>::traction_load(const unsigned int       k,
                                    const types::boundary_id id,
                                    const Tensor<1, dim>    &area) const
  {
    if (const auto parts = face_parts.find(k); parts != face_parts.end())
      {
        const auto part = parts->second.find(id);
        if (part != parts->second.end() && part->second.partial)
          return part->second.load;
      }
    // eq. 4.32: the traction at the particle times its area
    const Tensor<1, dim> t =
      loads.prescribed_traction(id, particles.position(k), area / area.norm());
    // On the FE/meshfree interface the VC targets d^k are the geometric area
    // vectors (interface plus surface part), so the consistent load there is
    // the geometric one.
    const double a = particles.on_interface(k) || area_weights.empty() ?
                       area.norm() :
                       area_weights[k].at(id);
    return a * t;
  }



  template <int dim>
  void
  ParticleLoads<dim>::add_to(Assembler<dim> &assembler) const
  {
    // no body force and no traction: every particle load is zero
    if (!loads.any())
      return;
    if (from_test_functions)
      update_partial_loads();
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
    const LinearCells<dim> cells(
      meshfree_neumann_cells.front()->get_triangulation());
    FEFaceValues<dim> fe_face_values(cells.mapping(),
                                     cells.scalar_element(),
                                     cells.face_quadrature(2),
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



  template <int dim>
  void
  ParticleLoads<dim>::set_neumann_cells(const std::vector<CellIterator> &cells)
  {
    neumann_cells      = cells;
    have_neumann_cells = true;
    particle_of_vertex.clear();
    if (!cells.empty())
      particle_of_vertex.assign(cells.front()->get_triangulation().n_vertices(),
                                numbers::invalid_unsigned_int);
    for (unsigned int k = 0; k < particles.n_particles(); ++k)
      if (particles.vertex(k) < particle_of_vertex.size())
        particle_of_vertex[particles.vertex(k)] = k;
    partial_time = std::numeric_limits<double>::quiet_NaN();
  }



  namespace
  {
    /** r x f: its z component in 2-D, all three in 3-D. */
    template <int dim>
    void
    add_moment(const Tensor<1, dim> &r,
               const Tensor<1, dim> &f,
               std::vector<double>  &moment)
    {
      if constexpr (dim == 2)
        moment[0] += r[0] * f[1] - r[1] * f[0];
      else
        {
          const Tensor<1, 3> m = cross_product_3d(r, f);
          for (unsigned int c = 0; c < 3; ++c)
            moment[c] += m[c];
        }
    }
  } // namespace



  template <int dim>
  void
  ParticleLoads<dim>::update_partial_loads() const
  {
    const double t = loads.load_factor();
    if (t == partial_time || !have_neumann_cells)
      return;
    partial_time = t;
    face_parts.clear();
    resultants.clear();
    for (const types::boundary_id id : loads.neumann_ids())
      {
        Resultant &r   = resultants[id];
        r.id           = id;
        r.moment       = std::vector<double>(dim == 2 ? 1 : 3, 0.);
        r.exact_moment = r.moment;
      }

    // The exact resultant: the face integral of T over the meshfree faces
    // of each id, with the quadrature of the FE side (Loads::
    // add_face_tractions()); and int N_k T dA over the faces of each
    // particle, N_k the Q1 function of its vertex (the particle's share of
    // the face, whose integral is its geometric area |a^k|).
    const LinearCells<dim> cells =
      neumann_cells.empty() ?
        LinearCells<dim>() :
        LinearCells<dim>(neumann_cells.front()->get_triangulation());
    FEFaceValues<dim> fe_face_values(cells.mapping(),
                                     cells.scalar_element(),
                                     cells.face_quadrature(2),
                                     update_values | update_quadrature_points |
                                       update_normal_vectors |
                                       update_JxW_values);
    // f(id, cell, vertices of the face) on every Neumann face, reinit'ed
    const auto for_each_face = [&](const auto &f) {
      std::vector<unsigned int> on_face;
      for (const auto &cell : neumann_cells)
        for (const unsigned int face : cell->face_indices())
          if (cell->face(face)->at_boundary() &&
              loads.is_neumann(cell->face(face)->boundary_id()))
            {
              fe_face_values.reinit(
                typename Triangulation<dim>::active_cell_iterator(cell),
                face);
              on_face.clear();
              for (const unsigned int i : cell->vertex_indices())
                for (const unsigned int v : cell->face(face)->vertex_indices())
                  if (cell->vertex_index(i) ==
                      cell->face(face)->vertex_index(v))
                    on_face.push_back(i);
              f(cell->face(face)->boundary_id(), cell, on_face);
            }
    };
    // the area and its centroid
    for_each_face([&](const types::boundary_id id, const auto &, const auto &) {
      Resultant &r = resultants[id];
      for (const unsigned int q : fe_face_values.quadrature_point_indices())
        {
          r.area += fe_face_values.JxW(q);
          for (unsigned int c = 0; c < dim; ++c)
            r.centre[c] +=
              fe_face_values.quadrature_point(q)[c] * fe_face_values.JxW(q);
        }
    });
    for (auto &[id, r] : resultants)
      if (r.area > 0)
        r.centre /= r.area;
    // the traction
    for_each_face([&](const types::boundary_id         id,
                      const auto                      &cell,
                      const std::vector<unsigned int> &on_face) {
      Resultant &r = resultants[id];
      for (const unsigned int q : fe_face_values.quadrature_point_indices())
        {
          const Point<dim>    &x   = fe_face_values.quadrature_point(q);
          const double         JxW = fe_face_values.JxW(q);
          const Tensor<1, dim> T =
            loads.prescribed_traction(id, x, fe_face_values.normal_vector(q));
          r.exact_force += T * JxW;
          add_moment<dim>(x - r.centre, T * JxW, r.exact_moment);
          const double magnitude = T.norm();
          for (const unsigned int i : on_face)
            {
              const unsigned int k = particle_of_vertex[cell->vertex_index(i)];
              if (k == numbers::invalid_unsigned_int)
                continue;
              FacePart    &part = face_parts[k][id];
              const double NJxW = fe_face_values.shape_value(i, q) * JxW;
              part.integral += NJxW * T;
              part.magnitude += NJxW * magnitude;
              (magnitude == 0 ? part.vanishes : part.loaded) = true;
            }
        }
    });

    // The loads. A particle whose faces of id b all carry a non-zero
    // traction, and whose area in that plane is all of id b, keeps eq.
    // 4.32, T(X^k) c_b: that is what a constant stress needs to be in
    // equilibrium with the internal forces (sigma . d^k at every particle),
    // so the patch tests and every load uniform over a whole face are as
    // before. A particle at the edge of the loaded region (T = 0 on some of
    // its faces, or another id in the same plane) is partly loaded: there
    // T(X^k) c_b is wrong by up to the whole c_b (the error of the
    // resultant falls only like h) and no constant stress can be in
    // equilibrium with the load anyway. It gets its test-function area
    // times the average traction over its faces, (c_b / A) int N_k T with
    // A the particle's geometric area in that plane (|a^k| of the id, or of
    // all ids in the plane; on the FE/meshfree interface c_b = A, the
    // FE-consistent int N_k T). Then every loaded particle of an id with
    // partly loaded ones gets the difference between the exact resultant
    // and the sum of all loads of the id in proportion to int N_k |T| (the
    // difference is mostly the sum of (c_b - |a^k|) T over the id: it comes
    // from the whole loaded area, not from its edge; without VC c_b misses
    // a share of the area everywhere). The resultant is then the face
    // integral to round-off, and nothing changes where no particle is
    // partly loaded.
    std::map<types::boundary_id, Tensor<1, dim>> sum;
    std::map<types::boundary_id, double>         weight;
    std::map<types::boundary_id, unsigned int>   n_partial;
    for (auto &[k, parts] : face_parts)
      for (auto &[id, part] : parts)
        {
          const auto          &areas = particles.boundary_area_vectors(k);
          const auto           own   = areas.find(id);
          const Tensor<1, dim> n     = own == areas.end() ?
                                         Tensor<1, dim>() :
                                         own->second / own->second.norm();
          double plane_area = own == areas.end() ? 0. : own->second.norm();
          bool   shared     = false;
          for (const auto &[other, area] : areas)
            if (other != id && std::abs(n * area) > (1. - 1e-10) * area.norm())
              {
                plane_area += area.norm();
                shared = true;
              }
          part.edge = (part.vanishes || shared) && plane_area > 0;
          // eq. 4.32 alone, for the report
          Tensor<1, dim> plain;
          if (from_test_functions && own != areas.end())
            {
              plain = traction_load(k, id, own->second);
              resultants[id].point_force += plain;
            }
          if (!from_test_functions || own == areas.end())
            part.load = part.integral;
          else if (part.edge)
            {
              part.partial = true;
              const double c =
                particles.on_interface(k) || area_weights.empty() ?
                  plane_area :
                  area_weights[k].at(id);
              part.load = (c / plane_area) * part.integral;
              n_partial[id] += part.loaded;
            }
          else
            part.load = plain;
          sum[id] += part.load;
          weight[id] += part.magnitude;
        }
    if (from_test_functions)
      for (auto &[k, parts] : face_parts)
        for (auto &[id, part] : parts)
          if (n_partial[id] > 0 && weight[id] > 0 && part.magnitude > 0)
            {
              part.load += (part.magnitude / weight[id]) *
                           (resultants[id].exact_force - sum[id]);
              part.partial = true;
            }

    for (const auto &[k, parts] : face_parts)
      for (const auto &[id, part] : parts)
        {
          Resultant &r = resultants[id];
          r.force += part.load;
          add_moment<dim>(particles.position(k) - r.centre,
                          part.load,
                          r.moment);
          r.n_partly_loaded += (part.edge && part.loaded);
        }
  }



  template <int dim>
  std::vector<typename ParticleLoads<dim>::Resultant>
  ParticleLoads<dim>::neumann_resultants() const
  {
    std::vector<Resultant> result;
    if (from_exact_stress || !have_neumann_cells)
      return result;
    update_partial_loads();
    for (const auto &[id, r] : resultants)
      result.push_back(r);
    return result;
  }



  template class ParticleLoads<2>;
  template class ParticleLoads<3>;
} // namespace pg
