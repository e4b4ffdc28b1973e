#ifndef pg_elements_family_elements_h
#define pg_elements_family_elements_h

#include <pg/base/formulation_code.h>
#include <pg/base/global.h>
#include <pg/elements/quadrature_table.h>
#include <pg/families/family_set.h>
#include <pg/mesh/particle_set.h>
#include <pg/shape_functions/shape_functions.h>

#include <algorithm>
#include <utility>
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
     * Compute the gradients at the master of the families flagged in
     * @p needed (all if it is empty): the PPG test functions, and the trial
     * gradient at the particle used for output and error norms. A rank needs
     * its owned families and their members (PPG1 reads g^{jjk} of member j);
     * the data of other families stay empty. Throws ExcSingularFamily for a
     * family whose moment matrix is singular or ill-conditioned.
     */
    void
    initialize(const std::vector<bool> &needed = {});

    /**
     * Throw ExcSingularFamily if the moment matrix of family @p k is singular
     * or ill-conditioned at its master (@p master_only, the check of
     * initialize()) or at any of its points (that of build()). Needs no data
     * of initialize():
     * every rank can repeat the check of a family another rank rejected, so
     * that all ranks stop with the same message.
     */
    void
    check_family(const unsigned int k, const bool master_only) const;

    /**
     * PBG Unl only ('Discretization/Quadrature weights = particle volumes',
     * issue 45, deliverable 5): scale the weight V^k V^j / V^{H^k} of every
     * point j by 1/s(j), s(j) = sum over the families k' that hold j
     * (j's own and those of its members: the families are pairwise) of
     * V^{k'} / V^{H^{k'}}, so that the weights at each particle add up to
     * its volume, at the surface too (eq. 4.30 gives the surface rows
     * 0.72-0.75 of theirs, tests/elements/surface_quadrature_01). The sum
     * of all weights stays the body's volume only approximately; the VC
     * correction, built with the same weights, keeps the patch test.
     * Call before initialize().
     */
    void
    use_particle_volume_weights();

    /**
     * Build the table of family @p k (throws like initialize()). After
     * set_correction_factors() the test functions (and for PBG the trial
     * functions, which are the same) carry the VC correction.
     */
    void
    build(const unsigned int k, QuadratureTable<dim> &table) const;

    /**
     * build() of every family in @p ks into @p tables (resized to
     * ks.size()), on all threads. Throws the exception of the first family
     * in @p ks that fails, as a serial loop would.
     */
    void
    build(const std::vector<unsigned int>   &ks,
          std::vector<QuadratureTable<dim>> &tables) const;

    /**
     * Apply the correction of set_correction_factors() to @p tables, the
     * tables of the families @p ks that build() gave before it (tables[i]
     * of family ks[i]), on all threads: the same tables as a build() now,
     * bitwise, without computing the shape functions again. PBG adds
     * phi^{ka} Q^{kj} alpha^k to the trial (= test) vector of member a at
     * each point j; PPG replaces its test vectors by the corrected master
     * test gradients; the trial vectors of PPG do not change. The VC
     * set-up so builds the tables once instead of twice (3-D cantilever,
     * 421,443 DoFs: 4.7 s of its 19.5 s).
     */
    void
    correct(const std::vector<unsigned int>   &ks,
            std::vector<QuadratureTable<dim>> &tables) const;

    /**
     * Effective trial gradients of family @p k at its master, one per
     * member: F^{kk} = sum_b x^b (x) B^{kkb}.
     */
    const std::vector<Tensor<1, dim>> &
    master_gradients(const unsigned int k) const;

    /**
     * Effective test gradients of family @p k at its master, one per
     * member: G^{kka} of PPG (VC-corrected after set_correction_factors()),
     * the trial ones for PBG. The volumetric point of PPG UnlP0 (eq. 6.7).
     */
    const std::vector<Tensor<1, dim>> &
    master_test_gradients(const unsigned int k) const;

    /**
     * The one-point table of family @p k at its master: weight V^k, trial
     * and test vectors the master's test gradients G^{kka} (VC-corrected
     * after set_correction_factors()). The volumetric point of PPG UnlP0
     * (eq. 6.7, pg-methods.md section 12.2): F^{kk} from the corrected
     * gradients too, which Table 7.2 implies (V1 is not exact there, V2
     * and V3 are: with V3 and V2 the correction does not change F^{kk} of
     * a linear field, with V1 it does) and which keeps the volumetric
     * stiffness symmetric and positive (with the uncorrected trial
     * gradients the free block at nu = 0.45 has negative eigenvalues,
     * doc/ambiguities.md). Where pg uses V1 instead of the code's function
     * (PPG interface masters, family_correction_function()) the trial
     * vectors are M^{-T} G^{kkb}, M = sum_b dX^{kb} (x) G^{kkb}, which
     * keeps F^{kk} of a linear field exact, so that coupled models pass the
     * patch test.
     */
    void
    build_master_table(const unsigned int k, QuadratureTable<dim> &table) const;

    /**
     * The blocks of the VC system (pg-methods.md section 11.4) that family
     * @p k contributes: the unit-stress residual depends linearly on the
     * correction factors, d^a(alpha) = d^a(0) + sum_f C^{af} alpha^f, and
     * @p add(a, f, C) is called for every block of this family (a and f are
     * particle indices). Needs the VC formulation.
     */
    template <typename Callback>
    void
    for_each_correction_block(const unsigned int k, const Callback &add) const;

    /**
     * Store the correction factors alpha^k of all particles (the solution
     * of the VC system) and correct the master gradients; from now on
     * build() returns corrected tables. VC2 (PPG2 only) also passes the
     * second-order factors alpha_2^k: the test gradients become
     * g^{kkj} + phi^{kj} (alpha^k + alpha_2^k dX^{kj}) (section 11.6).
     */
    void
    set_correction_factors(
      const std::vector<Tensor<1, dim>> &alpha,
      const std::vector<Tensor<2, dim>> &second_order_alpha = {});

    /**
     * The effective correction function values phi^{ka} of family @p k,
     * one per member (before the V5 projector), component d for the
     * correction in direction d (equal components except for V2). Needs
     * VC.
     */
    const std::vector<Tensor<1, dim>> &
    correction_function_values(const unsigned int k) const;

    /** The bonds and volumes of family @p k. */
    ShapeFunctions::FamilyGeometry<dim>
    geometry(const unsigned int k) const;

    /** Moment matrices with a larger condition number are rejected. */
    static constexpr double maximum_condition_number = 1e10;

    /**
     * The correction function of family @p k: the formulation's, except V1
     * for PPG masters on the FE/meshfree interface (see the definition).
     */
    FormulationCode::CorrectionFunction
    family_correction_function(const unsigned int k) const;

  private:
    /**
     * The weight of point @p q (member q) of the PBG Unl table of family
     * @p k with volumes @p geometry and V^{H^k} = @p family_volume: the
     * share of the family times V^k V^q / V^{H^k} (eq. 4.30), times the
     * factor of use_particle_volume_weights().
     */
    double
    unl_point_weight(const unsigned int                         k,
                     const ShapeFunctions::FamilyGeometry<dim> &geometry,
                     const double                               family_volume,
                     const unsigned int                         q) const;

    /**
     * The VC correction of a gradient of family @p k at member @p point for
     * node @p a: phi^{ka} Q^{k,point} alpha^k, with the bond projector Q
     * for V5 at points other than the master (identity otherwise).
     */
    Tensor<1, dim>
    correction(const unsigned int                         k,
               const ShapeFunctions::FamilyGeometry<dim> &geometry,
               const unsigned int                         point,
               const unsigned int                         a) const;

    /**
     * The test gradient t of PPG family @p k at its point j (member j): its
     * test vectors there are t for one node and -t for the other (PPG1:
     * family j's master gradient for node k at the master, -t at j; PPG2:
     * family k's master gradient for j at j, -t at the master).
     */
    Tensor<1, dim>
    ppg_test_vector(const unsigned int k, const unsigned int j) const;

    /**
     * For member @p j of family @p k: the particle whose family holds the
     * member's own test functions (its original, for a mirror image) and
     * the index of k (or of k's image across the member's planes) in it.
     */
    std::pair<unsigned int, unsigned int>
    member_family_index(const unsigned int k, const unsigned int j) const;

    /** correct() of the table of family @p k. */
    void
    correct(const unsigned int k, QuadratureTable<dim> &table) const;

    /** The diagonal matrix with the entries @p v. */
    static Tensor<2, dim>
    diagonal(const Tensor<1, dim> &v)
    {
      Tensor<2, dim> D;
      for (unsigned int d = 0; d < dim; ++d)
        D[d][d] = v[d];
      return D;
    }

    /** The bond projector 1 - n (x) n of V5 at @p point (1 otherwise). */
    Tensor<2, dim>
    projector(const ShapeFunctions::FamilyGeometry<dim> &geometry,
              const unsigned int                         point) const;

    /**
     * The correction function values of family @p k into @p values, with
     * the conditioning check of the V2/V4 fit (throws ExcSingularFamily).
     */
    void
    checked_correction_function(
      const unsigned int                         k,
      const ShapeFunctions::FamilyGeometry<dim> &geometry,
      std::vector<Tensor<1, dim>>               &values) const;

    /** Raw gradients at @p point with the conditioning check. */
    void
    checked_gradients(const unsigned int                         k,
                      const ShapeFunctions::FamilyGeometry<dim> &geometry,
                      const unsigned int                         point,
                      std::vector<Tensor<1, dim>>               &g) const;

    const ParticleSet<dim>    &particles;
    const FamilySet<dim>      &families;
    const FormulationCode      formulation;
    const ShapeFunctions::Base base;
    const double               weight_exponent;
    /** Trial gradients at the master of every needed family. */
    std::vector<std::vector<Tensor<1, dim>>> master;
    /** Test gradients at the master (PPG): the trial ones, VC-corrected. */
    std::vector<std::vector<Tensor<1, dim>>> master_test;
    /** Effective VC correction function values per family member. */
    std::vector<std::vector<Tensor<1, dim>>> phi;
    /** VC correction factors per particle; empty: uncorrected. */
    std::vector<Tensor<1, dim>> alpha;
    /**
     * The factor 1/s of use_particle_volume_weights() per real particle;
     * empty: the weights of eq. 4.30.
     */
    std::vector<double> particle_weight_factors;
  };



  template <int dim>
  template <typename Callback>
  void
  FamilyElements<dim>::for_each_correction_block(const unsigned int k,
                                                 const Callback    &add) const
  {
    using Method = FormulationCode::Method;
    Assert(formulation.variational_consistency, ExcInternalError());
    const auto         members = families.members(k);
    const unsigned int n       = members.size();
    const auto         geom    = geometry(k);
    if (formulation.method == Method::pbg)
      {
        // d^a += sum_q w_q phi^{ka} Q^{kq} alpha^k over the points q of
        // family k: one block phi^{ka} (sum_q w_q Q^{kq}) per member a
        double family_volume = 0;
        for (const double v : geom.volumes)
          family_volume += v;
        Tensor<2, dim> weighted_projector;
        if (formulation.points == FormulationCode::Points::u1)
          weighted_projector =
            particles.family_share(k) * geom.volumes[0] * projector(geom, 0);
        else
          for (unsigned int q = 0; q < n; ++q)
            weighted_projector +=
              unl_point_weight(k, geom, family_volume, q) * projector(geom, q);
        for (unsigned int a = 0; a < n; ++a)
          add(members[a], k, diagonal(phi[k][a]) * weighted_projector);
        return;
      }
    const double share = particles.family_share(k);
    for (unsigned int j = 1; j < n; ++j)
      {
        const double w = share * geom.volumes[j];
        if (formulation.method == Method::ppg1)
          {
            // test vectors +-(g^{jjk} + phi^{jk} alpha^j) at nodes k and j
            // (for a mirror image j, phi of its original: phi is even)
            const auto [member, index] = member_family_index(k, j);
            const Tensor<2, dim> c     = w * diagonal(phi[member][index]);
            add(k, members[j], c);
            add(members[j], members[j], -c);
          }
        else
          {
            // test vectors +-(g^{kkj} + phi^{kj} alpha^k) at nodes j and k
            const Tensor<2, dim> c = w * diagonal(phi[k][j]);
            add(members[j], k, c);
            add(k, k, -c);
          }
      }
  }
} // namespace pg

#endif
