#ifndef pg_tests_particle_fixture_h
#define pg_tests_particle_fixture_h

// A small all-meshfree problem for unit tests: a (possibly distorted)
// subdivided box, its Q1 DoFs, the particles and the families.

#include <pg/families/family_set.h>
#include <pg/materials/material.h>
#include <pg/mesh/particle_set.h>
#include <pg/shape_functions/shape_functions.h>

#include <deal.II/dofs/dof_handler.h>
#include <deal.II/fe/fe_q.h>
#include <deal.II/fe/fe_system.h>
#include <deal.II/grid/grid_generator.h>
#include <deal.II/grid/grid_tools.h>
#include <deal.II/grid/tria.h>

#include <cmath>
#include <random>

template <int dim>
struct ParticleFixture
{
  ParticleFixture(const unsigned int cells_per_direction,
                  const double       distortion,
                  const double       horizon_factor)
    : fe(dealii::FE_Q<dim>(1), dim)
  {
    dealii::GridGenerator::subdivided_hyper_cube(tria,
                                                 cells_per_direction,
                                                 0.,
                                                 1.,
                                                 true);
    if (distortion > 0)
      dealii::GridTools::distort_random(distortion, tria, true, 7);
    dof_handler.reinit(tria);
    dof_handler.distribute_dofs(fe);
    particles.reinit(dof_handler,
                     std::vector<bool>(tria.n_active_cells(), true));
    families.reinit(particles, horizon_factor, 0);
  }

  /** The particle closest to @p p. */
  unsigned int
  closest(const dealii::Point<dim> &p) const
  {
    unsigned int best = 0;
    for (unsigned int k = 1; k < particles.n_particles(); ++k)
      if (p.distance(particles.position(k)) <
          p.distance(particles.position(best)))
        best = k;
    return best;
  }

  /**
   * Two masters for element tests: the particle nearest the centre of the
   * unit box (an interior family) and the one at the origin (a corner
   * family).
   */
  std::vector<unsigned int>
  interior_and_corner() const
  {
    dealii::Point<dim> centre;
    for (unsigned int d = 0; d < dim; ++d)
      centre[d] = 0.5;
    return {closest(centre), closest(dealii::Point<dim>())};
  }

  /**
   * The family of particle @p k as the shape functions see it: bonds
   * X^i - X^k and volumes V^i of its members (master first).
   */
  pg::ShapeFunctions::FamilyGeometry<dim>
  family_geometry(const unsigned int k, const double weight_exponent = 1.) const
  {
    pg::ShapeFunctions::FamilyGeometry<dim> family;
    family.weight_exponent = weight_exponent;
    for (const unsigned int j : families.members(k))
      {
        family.bonds.push_back(particles.position(j) - particles.position(k));
        family.volumes.push_back(particles.volume(j));
      }
    return family;
  }

  dealii::Triangulation<dim> tria;
  dealii::FESystem<dim>      fe;
  dealii::DoFHandler<dim>    dof_handler;
  pg::ParticleSet<dim>       particles;
  pg::FamilySet<dim>         families;
};

/** A material from its name, E = 100, nu = 0.3, plane strain. */
template <int dim>
std::unique_ptr<pg::Materials::Material<dim>>
make_material(const std::string &model)
{
  pg::Parameters::Material parameters;
  parameters.model          = model;
  parameters.youngs_modulus = 100.;
  parameters.poissons_ratio = 0.3;
  parameters.density        = 1.;
  parameters.plane          = "strain";
  return pg::Materials::create_material<dim>(parameters);
}

/** A rotation by @p angle (about the axis (1, 2, 3) in 3-D). */
template <int dim>
dealii::Tensor<2, dim>
rotation(const double angle)
{
  dealii::Tensor<2, dim> R;
  if constexpr (dim == 2)
    {
      R[0][0] = R[1][1] = std::cos(angle);
      R[0][1]           = -std::sin(angle);
      R[1][0]           = std::sin(angle);
    }
  else
    {
      // about the axis (1, 2, 3) / |.|, Rodrigues' formula
      dealii::Tensor<1, 3> a({1., 2., 3.});
      a /= a.norm();
      dealii::Tensor<2, 3> K;
      K[0][1] = -a[2], K[0][2] = a[1], K[1][0] = a[2];
      K[1][2] = -a[0], K[2][0] = -a[1], K[2][1] = a[0];
      R = dealii::unit_symmetric_tensor<3>() + std::sin(angle) * K +
          (1 - std::cos(angle)) * K * K;
    }
  return R;
}

#endif
