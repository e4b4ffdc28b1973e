#ifndef pg_elements_cpd_interactions_h
#define pg_elements_cpd_interactions_h

#include <pg/base/global.h>
#include <pg/families/family_set.h>
#include <pg/mesh/particle_set.h>

#include <deal.II/base/tensor.h>
#include <deal.II/lac/full_matrix.h>
#include <deal.II/lac/vector.h>

#include <array>
#include <cstdint>
#include <vector>

namespace pg
{
  namespace CPD
  {
    /**
     * The energy of one interaction and its derivatives with respect to its
     * n edge vectors xi^m = x^m - x^0 (m = 1..n): gradient[m-1] and
     * hessian[m-1][p-1] = d^2 psi / d xi^m d xi^p.
     */
    template <int dim, int n>
    struct EdgeDerivatives
    {
      double                                       energy = 0;
      std::array<Tensor<1, dim>, n>                gradient;
      std::array<std::array<Tensor<2, dim>, n>, n> hessian;
    };

    /**
     * The interaction energies of continuum-kinematics-inspired peridynamics
     * (Javili et al. 2020, eqs. 23-25; cpd-and-correspondence.md B.3) and
     * their first and second derivatives (eqs. 53-76, re-derived in the
     * design note B.7), for n = 1 (bond: psi_1 = C (l - L)^2 / (2 L)),
     * n = 2 (triangle: psi_2 = C (a - A)^2 / (2 A), a = |xi^1 x xi^2|) and
     * n = 3 (tetrahedron, 3-D only: psi_3 = C (v - V)^2 / (2 V),
     * v = |xi^1 . (xi^2 x xi^3)|). @p Xi are the reference edges,
     * @p xi the current ones. In 2-D the cross product is the scalar
     * (out-of-plane) one: the purely two-dimensional model of Remark 1.
     */
    template <int dim, int n>
    EdgeDerivatives<dim, n>
    interaction_derivatives(const double                         C,
                            const std::array<Tensor<1, dim>, n> &Xi,
                            const std::array<Tensor<1, dim>, n> &xi,
                            const bool                           with_hessian);

    /** The reference measure L, A or V of the interaction with edges Xi. */
    template <int dim, int n>
    double
    reference_measure(const std::array<Tensor<1, dim>, n> &Xi);
  } // namespace CPD

  /**
   * The CPD constants and options of subsection 'CPD'.
   */
  struct CpdConstants
  {
    /** One-neighbour (bond) constant C_1, N m / m^(2 dim + 1). */
    double C1 = 1;
    /** Two-neighbour (area) constant C_2, N m / m^(3 dim + 2). */
    double C2 = 0;
    /** Three-neighbour (volume) constant C_3 (3-D), N m / m^15. */
    double C3 = 0;
    /**
     * Weigh bonds cut by the horizon by the share beta of the neighbour's
     * volume inside it, beta = (delta + h/2 - |X^i - X^a|)/h clipped to
     * [0, 1] (families then reach delta + h/2).
     */
    bool partial_volumes = false;
  };

  /**
   * Continuum-kinematics-inspired peridynamics on the particles of a
   * ParticleSet (architecture.md section 2: CPD implements the element
   * interface directly).
   *
   * **Interactions.** A bond {a, i} is every pair of family members; a
   * triangle {a, i, j} every triple of particles that are pairwise
   * neighbours and not collinear, a tetrahedron every quadruple of pairwise
   * neighbours that is not coplanar (3-D): the "contributing" pairs and
   * triplets of the source (section 3.1, Remark 2), which are thereby seen
   * from each of their vertices. Each interaction is stored once, in the
   * family of its vertex with the smallest index (no double counting), as
   * local member indices of that family, so that one family's
   * interactions form one element of the global matrix; its blocks couple
   * neighbours only (the tangent has the one-horizon stencil). With mirror
   * planes (ParticleSet::add_mirror_images) a vertex may be an image; the
   * images are numbered after the real particles, so the interaction is
   * stored at its smallest real vertex, and only its real vertices v carry
   * its energy, with their volumes V^v in the model (the share of a
   * particle on a plane) and the full body's member volumes in the
   * weights: the energy is the full body's over the number of mirrored
   * copies, and the folded residual and tangent are its exact derivatives.
   *
   * **Energy.** E = sum_v V^v Psi^v with the point energy of eq. (14),
   * Psi^v = 1/2 sum_i w_1 psi_1 + 1/3 sum_(i,j) w_2 psi_2 + 1/4
   * sum_(i,j,k) w_3 psi_3 over the ordered contributing tuples of v. The
   * weights are the source's quadrature (eqs. 29-34) with volume weighting:
   * w_n^v(tuple) = (V_H^v)^n prod(beta V) / sum over all ordered tuples of
   * prod(beta V), with V_H^v = sum_i beta V^i the discrete horizon volume,
   * so the fidelity identities (35) hold exactly at every point, and with
   * equal volumes w_n = V_H^n / #N_n exactly as in the source. Assembling
   * the energy interaction by interaction (design note B.8, item 3) makes
   * the residual the exact energy gradient and the tangent symmetric on any
   * particle set; where the weights are uniform it equals V^a times the
   * source's collocation residual (eqs. 53, 58, 61) with the opposite sign
   * (r = f_int - f_ext, positive stiffness).
   */
  template <int dim>
  class CpdInteractions
  {
  public:
    /**
     * Find the interactions and their weights. @p horizon_factor is
     * 'Discretization/Horizon factor' (delta = factor x spacing); with
     * partial volumes @p families must reach (factor + 1/2) x spacing.
     * Throws with the particle's index and position if a particle has no
     * neighbour, or if a constant is not admissible (C_1 <= 0; C_3 != 0 in
     * 2-D).
     */
    CpdInteractions(const ParticleSet<dim> &particles,
                    const FamilySet<dim>   &families,
                    const CpdConstants     &constants,
                    const double            horizon_factor,
                    const double            horizon = 0.);

    /**
     * The residual (internal force, dE/dx) and, if @p matrix is not null,
     * the tangent (d^2E/dx^2) of the interactions stored in family @p k,
     * with the family's local numbering (member b, component c at
     * b * dim + c). @p y are the current positions of the members (any
     * common origin). The outputs are resized and overwritten.
     */
    void
    assemble(const unsigned int                 k,
             const std::vector<Tensor<1, dim>> &y,
             Vector<double>                    &residual,
             FullMatrix<double>                *matrix) const;

    /** The energy of the interactions stored in family @p k. */
    double
    energy(const unsigned int k, const std::vector<Tensor<1, dim>> &y) const;

    /** Interactions of each order over all families: bonds, triangles,
     * tetrahedra. */
    std::array<std::size_t, 3>
    n_interactions() const;

    /** Interactions of each order stored in family @p k. */
    std::array<std::size_t, 3>
    n_interactions(const unsigned int k) const;

    /**
     * The pairs (p, q), p < q, of members of family @p k (positions in
     * families.members(k), both > 0) that a triangle or tetrahedron of the
     * family couples: the entries of its local matrix besides the master's
     * row and column (for the sparsity pattern).
     */
    std::vector<std::pair<unsigned int, unsigned int>>
    coupled_members(const unsigned int k) const;

    /**
     * The ordered contributing tuples #N_1, #N_2, #N_3 at particle @p v
     * (eqs. 29, 32, 34) and its horizon volume V_H^v.
     */
    std::array<double, 4>
    point_quadrature(const unsigned int v) const;

    /** Partial-volume factor beta of the bond between @p a and @p i. */
    double
    bond_factor(const unsigned int a, const unsigned int i) const;

    const CpdConstants &
    constants() const;

  private:
    /**
     * The energy of the interactions stored in family @p k, and their
     * residual and tangent added to @p residual and @p matrix (sized by the
     * caller) where these are not null.
     */
    double
    evaluate(const unsigned int                 k,
             const std::vector<Tensor<1, dim>> &y,
             Vector<double>                    *residual,
             FullMatrix<double>                *matrix) const;

    const ParticleSet<dim> &particles;
    const FamilySet<dim>   &families;
    const CpdConstants      cpd;
    const double            horizon_factor;
    /** 'Discretization/Horizon' (absolute; 0: the factor is used). */
    const double horizon;

    /** Interactions of order n+1 in compressed rows per family. */
    std::array<std::vector<std::size_t>, 3> offsets;
    /** Local member indices (0 = master) of the n+1 other vertices. */
    std::array<std::vector<std::uint16_t>, 3> vertices;
    /** Energy weight of each interaction (volume^2 for bonds, ...). */
    std::array<std::vector<double>, 3> weights;
    /** Per particle: #N_1, #N_2, #N_3, V_H. */
    std::vector<std::array<double, 4>> quadrature;
  };
} // namespace pg

#endif
