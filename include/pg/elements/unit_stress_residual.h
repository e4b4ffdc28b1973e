#ifndef pg_elements_unit_stress_residual_h
#define pg_elements_unit_stress_residual_h

#include <pg/base/global.h>
#include <pg/elements/family_elements.h>
#include <pg/elements/quadrature_table.h>
#include <pg/families/family_set.h>
#include <pg/mesh/particle_set.h>

#include <deal.II/base/mpi.h>
#include <deal.II/base/point.h>
#include <deal.II/base/tensor.h>
#include <deal.II/base/types.h>

#include <functional>
#include <map>
#include <vector>

namespace pg
{
  /**
   * The unit-stress residual d^k of every particle (pg-methods.md section
   * 8.2): d^k = sum over the families f containing k of sum_q w_q T^{qk},
   * the internal force of P = 1 (area units). @p tables[i] is the table of
   * family @p owned_families[i]; the sum runs over all MPI ranks of @p comm,
   * so every rank returns all n_particles values. It is zero at interior
   * particles for variationally consistent test functions and the nodal
   * area vector at the surface.
   */
  template <int dim>
  std::vector<Tensor<1, dim>>
  unit_stress_residual(const FamilySet<dim>                    &families,
                       const std::vector<unsigned int>         &owned_families,
                       const std::vector<QuadratureTable<dim>> &tables,
                       const ParticleSet<dim>                  &particles,
                       const MPI_Comm                           comm);

  /**
   * max |d^k| / h_k^(dim-1) over the particles that are neither on the
   * surface nor on the FE/meshfree interface (h_k the particle spacing):
   * round-off after a successful VC correction.
   */
  template <int dim>
  double
  max_interior_unit_stress_residual(
    const ParticleSet<dim>            &particles,
    const std::vector<Tensor<1, dim>> &unit_stress);

  /**
   * The area of each boundary part b at particle k seen by the test
   * functions: the least-squares decomposition d^k = sum_b c_b n_b on the
   * unit normals n_b of the parts at k (section 8.2). With one part
   * c = n . d^k; at a corner the decomposition keeps the other part's area
   * out of the load; parts with parallel normals share by projection.
   * These weights scale the particle tractions of the Neumann loads. Empty
   * maps for particles without boundary parts.
   */
  template <int dim>
  std::vector<std::map<types::boundary_id, double>>
  boundary_area_weights(const ParticleSet<dim>            &particles,
                        const std::vector<Tensor<1, dim>> &unit_stress);

  /**
   * The internal force (force units) at particle @p k of the stress field
   * @p stress P(X) (first Piola-Kirchhoff, force per reference area):
   * sum over the families e containing k of sum_q w_q P(X_q) T^{qk}, with
   * the tables of @p elements (built here). Families are pairwise, so the
   * families containing k are those of the members of family k. With the
   * exact stress it is the 'Particle traction area = exact stress' load.
   * With mirror images (ParticleSet::add_mirror_images()) the families
   * containing k or one of its images, each image's part reflected: the
   * row of k as the assembly folds it (P at an image point is the
   * function's value there).
   */
  template <int dim>
  Tensor<1, dim>
  particle_stress_force(
    const ParticleSet<dim>                                  &particles,
    const FamilySet<dim>                                    &families,
    const FamilyElements<dim>                               &elements,
    const unsigned int                                       k,
    const std::function<Tensor<2, dim>(const Point<dim> &)> &stress);
} // namespace pg

#endif
