#ifndef pg_elements_family_elements_h
#define pg_elements_family_elements_h

#include <pg/base/formulation_code.h>
#include <pg/base/global.h>
#include <pg/elements/quadrature_table.h>
#include <pg/families/family_set.h>
#include <pg/mesh/particle_set.h>
#include <pg/shape_functions/shape_functions.h>

#include <vector>

namespace pg
{
  /**
   * Builds the quadrature table of every PG family (pg-methods.md section
   * 7.4):
   *
   * | method | points q | weight w_q | test vectors T^{qa} |
   * |---|---|---|---|
   * | PBG Unl (4.30) | all j in H^k | V^k V^j / V^{H^k} | = trial |
   * | PBG U1 (6.17) | master only | V^k | = trial |
   * | PPG1 (4.21) | j != k | V^j | a=k: +g^{jjk}, a=j: -g^{jjk} |
   * | PPG2 (4.22) | j != k | V^j | a=j: +g^{kkj}, a=k: -g^{kkj} |
   *
   * The trial vectors are the effective gradients of the chosen base at the
   * point, bond-corrected (eq. 5.55) at j != k if the code says BC. The PPG
   * test gradients g^{jj.} are the base at the master of family j (for MTE1
   * this is WTE1: the "MTE1-WTE1" pairing of section 12.1).
   */
  template <int dim>
  class FamilyElements
  {
  public:
    FamilyElements(const ParticleSet<dim>    &particles,
                   const FamilySet<dim>      &families,
                   const FormulationCode     &formulation,
                   const ShapeFunctions::Base base,
                   const double               weight_exponent);

    /**
     * Compute the gradients at the master of every family (the PPG test
     * functions, and the trial gradient at the particle used for output and
     * error norms). Throws ExcSingularFamily for a family whose moment
     * matrix is singular or ill-conditioned.
     */
    void
    initialize();

    /** Build the table of family @p k (throws like initialize()). */
    void
    build(const unsigned int k, QuadratureTable<dim> &table) const;

    /**
     * Effective trial gradients of family @p k at its master, one per
     * member: F^{kk} = sum_b x^b (x) B^{kkb}.
     */
    const std::vector<Tensor<1, dim>> &
    master_gradients(const unsigned int k) const;

    /** The bonds and volumes of family @p k. */
    ShapeFunctions::FamilyGeometry<dim>
    geometry(const unsigned int k) const;

    /** Moment matrices with a larger condition number are rejected. */
    static constexpr double maximum_condition_number = 1e10;

  private:
    /** Raw gradients at @p point with the conditioning check. */
    void
    checked_gradients(const unsigned int                         k,
                      const ShapeFunctions::FamilyGeometry<dim> &geometry,
                      const unsigned int                         point,
                      std::vector<Tensor<1, dim>>               &g) const;

    const ParticleSet<dim>                  &particles;
    const FamilySet<dim>                    &families;
    const FormulationCode                    formulation;
    const ShapeFunctions::Base               base;
    const double                             weight_exponent;
    std::vector<std::vector<Tensor<1, dim>>> master;
  };
} // namespace pg

#endif
