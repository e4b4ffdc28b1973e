#include <pg/elements/unit_stress_residual.h>

#include <deal.II/lac/full_matrix.h>
#include <deal.II/lac/vector.h>

#include <algorithm>
#include <cmath>

namespace pg
{
  template <int dim>
  std::vector<Tensor<1, dim>>
  unit_stress_residual(const FamilySet<dim>                    &families,
                       const std::vector<unsigned int>         &owned_families,
                       const std::vector<QuadratureTable<dim>> &tables,
                       const ParticleSet<dim>                  &particles,
                       const MPI_Comm                           comm)
  {
    AssertDimension(tables.size(), owned_families.size());
    const unsigned int          n_particles = particles.n_particles();
    std::vector<double>         d(n_particles * dim, 0.);
    std::vector<Tensor<1, dim>> local;
    for (unsigned int f = 0; f < owned_families.size(); ++f)
      {
        const auto members = families.members(owned_families[f]);
        local.assign(members.size(), Tensor<1, dim>());
        add_unit_stress_residual(tables[f], local);
        // a mirror image's row is its original's, reflected
        for (unsigned int a = 0; a < members.size(); ++a)
          for (unsigned int c = 0; c < dim; ++c)
            d[particles.original(members[a]) * dim + c] +=
              particles.mirror_sign(members[a], c) * local[a][c];
      }
    Utilities::MPI::sum(d, comm, d);
    std::vector<Tensor<1, dim>> unit_stress(n_particles);
    for (unsigned int k = 0; k < n_particles; ++k)
      for (unsigned int c = 0; c < dim; ++c)
        unit_stress[k][c] = d[k * dim + c];
    return unit_stress;
  }



  template <int dim>
  double
  max_interior_unit_stress_residual(
    const ParticleSet<dim>            &particles,
    const std::vector<Tensor<1, dim>> &unit_stress)
  {
    AssertDimension(unit_stress.size(), particles.n_particles());
    double largest = 0;
    for (unsigned int k = 0; k < particles.n_particles(); ++k)
      if (particles.boundary_area_vectors(k).empty() &&
          !particles.on_interface(k))
        largest = std::max(
          largest,
          particles.parallel_to_mirror_planes(k, unit_stress[k]).norm() /
            std::pow(particles.spacing(k), dim - 1));
    return largest;
  }



  template <int dim>
  std::vector<std::map<types::boundary_id, double>>
  boundary_area_weights(const ParticleSet<dim>            &particles,
                        const std::vector<Tensor<1, dim>> &unit_stress)
  {
    AssertDimension(unit_stress.size(), particles.n_particles());
    std::vector<std::map<types::boundary_id, double>> weights(
      particles.n_particles());
    for (unsigned int k = 0; k < particles.n_particles(); ++k)
      {
        const auto &areas = particles.boundary_area_vectors(k);
        if (areas.empty())
          continue;
        // least squares d^k = sum_b c_b n_b (the normals are independent at
        // corners; parts with parallel normals share by projection)
        // (on mirror planes: the parts parallel to them, see
        // ParticleSet::parallel_to_mirror_planes())
        const unsigned int          m = areas.size();
        std::vector<Tensor<1, dim>> n;
        for (const auto &area : areas)
          {
            const Tensor<1, dim> a =
              particles.parallel_to_mirror_planes(k, area.second);
            n.push_back(a / a.norm());
          }
        const Tensor<1, dim> d =
          particles.parallel_to_mirror_planes(k, unit_stress[k]);
        FullMatrix<double> G(m, m);
        Vector<double>     rhs(m), c(m);
        for (unsigned int a = 0; a < m; ++a)
          {
            rhs(a) = n[a] * d;
            for (unsigned int b = 0; b < m; ++b)
              G(a, b) = n[a] * n[b];
          }
        bool independent = (m <= dim);
        if (independent)
          {
            FullMatrix<double> copy(G);
            independent = std::abs(copy.determinant()) > 1e-6;
          }
        if (independent)
          {
            G.gauss_jordan();
            G.vmult(c, rhs);
          }
        else
          c = rhs;
        unsigned int a = 0;
        for (const auto &area : areas)
          weights[k][area.first] = c(a++);
      }
    return weights;
  }



  template <int dim>
  Tensor<1, dim>
  particle_stress_force(
    const ParticleSet<dim>                                  &particles,
    const FamilySet<dim>                                    &families,
    const FamilyElements<dim>                               &elements,
    const unsigned int                                       k,
    const std::function<Tensor<2, dim>(const Point<dim> &)> &stress)
  {
    // the real families that hold k or an image of k: the originals of
    // the members of family k (pairwise, mirrored completion)
    std::vector<unsigned int> containing;
    for (const unsigned int e : families.members(k))
      containing.push_back(particles.original(e));
    std::sort(containing.begin(), containing.end());
    containing.erase(std::unique(containing.begin(), containing.end()),
                     containing.end());
    Tensor<1, dim>       force;
    QuadratureTable<dim> table;
    for (const unsigned int e : containing)
      {
        elements.build(e, table);
        const auto                  members = families.members(e);
        std::vector<Tensor<1, dim>> local(members.size());
        add_stress_residual<dim>(
          table,
          [&](const unsigned int q) { return stress(table.points[q]); },
          local);
        for (unsigned int m = 0; m < members.size(); ++m)
          if (particles.original(members[m]) == k)
            for (unsigned int c = 0; c < dim; ++c)
              force[c] += particles.mirror_sign(members[m], c) * local[m][c];
      }
    return force;
  }



  template std::vector<Tensor<1, 2>>
  unit_stress_residual<2>(const FamilySet<2> &,
                          const std::vector<unsigned int> &,
                          const std::vector<QuadratureTable<2>> &,
                          const ParticleSet<2> &,
                          const MPI_Comm);
  template std::vector<Tensor<1, 3>>
  unit_stress_residual<3>(const FamilySet<3> &,
                          const std::vector<unsigned int> &,
                          const std::vector<QuadratureTable<3>> &,
                          const ParticleSet<3> &,
                          const MPI_Comm);
  template double
  max_interior_unit_stress_residual<2>(const ParticleSet<2> &,
                                       const std::vector<Tensor<1, 2>> &);
  template double
  max_interior_unit_stress_residual<3>(const ParticleSet<3> &,
                                       const std::vector<Tensor<1, 3>> &);
  template std::vector<std::map<types::boundary_id, double>>
  boundary_area_weights<2>(const ParticleSet<2> &,
                           const std::vector<Tensor<1, 2>> &);
  template std::vector<std::map<types::boundary_id, double>>
  boundary_area_weights<3>(const ParticleSet<3> &,
                           const std::vector<Tensor<1, 3>> &);
  template Tensor<1, 2>
  particle_stress_force<2>(
    const ParticleSet<2> &,
    const FamilySet<2> &,
    const FamilyElements<2> &,
    const unsigned int,
    const std::function<Tensor<2, 2>(const Point<2> &)> &);
  template Tensor<1, 3>
  particle_stress_force<3>(
    const ParticleSet<3> &,
    const FamilySet<3> &,
    const FamilyElements<3> &,
    const unsigned int,
    const std::function<Tensor<2, 3>(const Point<3> &)> &);
} // namespace pg
