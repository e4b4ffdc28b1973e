#ifndef pg_families_family_set_h
#define pg_families_family_set_h

#include <pg/base/global.h>
#include <pg/mesh/particle_set.h>

#include <deal.II/base/array_view.h>

#include <vector>

namespace pg
{
  /**
   * The families H^k of all particles in compressed-row storage
   * (pg-methods.md section 5.2). Family k lists its master k first, then its
   * neighbours in increasing order. Families are always pairwise:
   * j in H^k <=> k in H^j.
   */
  template <int dim>
  class FamilySet
  {
  public:
    /**
     * Build the families. With @p nearest_neighbours = 0 a family holds
     * every particle within the horizon delta^k = @p horizon_factor x
     * spacing(k) + @p horizon (absolute, length); otherwise the @p
     * nearest_neighbours nearest particles. Both are then completed to pairwise
     * families. The search uses deal.II's RTree (boost.geometry).
     */
    void
    reinit(const ParticleSet<dim> &particles,
           const double            horizon_factor,
           const unsigned int      nearest_neighbours,
           const double            horizon = 0.);

    unsigned int
    n_families() const;

    /** The members of family k, master first. */
    ArrayView<const unsigned int>
    members(const unsigned int k) const;

    /** Number of neighbours N^k (the master excluded). */
    unsigned int
    n_neighbours(const unsigned int k) const;

    /**
     * The horizon delta^k of family k (length): horizon_factor x spacing(k)
     * + horizon, or with 'Nearest neighbours' its longest bond.
     */
    double
    horizon(const unsigned int k) const;

    /** Total number of (master, neighbour) bonds. */
    std::size_t
    n_bonds() const;

  private:
    std::vector<std::size_t>  offsets;
    std::vector<unsigned int> indices;
    std::vector<double>       horizons;
  };
} // namespace pg

#endif
