#include <pg/families/family_set.h>

#include <deal.II/numerics/rtree.h>

#include <boost/geometry/index/rtree.hpp>

#include <algorithm>

namespace pg
{
  template <int dim>
  void
  FamilySet<dim>::reinit(const ParticleSet<dim> &particles,
                         const double            horizon_factor,
                         const unsigned int      nearest_neighbours,
                         const double            horizon)
  {
    namespace bgi        = boost::geometry::index;
    const unsigned int n = particles.n_particles();

    // the real particles and their mirror images (ParticleSet); only the
    // real ones have families
    std::vector<Point<dim>> points(particles.n_particles_and_images());
    for (unsigned int k = 0; k < points.size(); ++k)
      points[k] = particles.position(k);
    const auto tree = pack_rtree_of_indices(points);

    std::vector<std::vector<unsigned int>> neighbours(n);
    // delta^k; with nearest neighbours the longest bond, set below
    horizons.resize(n);
    for (unsigned int k = 0; k < n; ++k)
      horizons[k] = horizon_factor * particles.spacing(k) + horizon;
    for (unsigned int k = 0; k < n; ++k)
      {
        const Point<dim>         &x = points[k];
        std::vector<unsigned int> found;
        if (nearest_neighbours > 0)
          tree.query(bgi::nearest(x, nearest_neighbours + 1),
                     std::back_inserter(found));
        else
          {
            const double delta = horizons[k];
            Point<dim>   lower = x, upper = x;
            for (unsigned int d = 0; d < dim; ++d)
              {
                lower[d] -= delta;
                upper[d] += delta;
              }
            std::vector<unsigned int> candidates;
            tree.query(bgi::intersects(BoundingBox<dim>({lower, upper})),
                       std::back_inserter(candidates));
            for (const unsigned int j : candidates)
              if (x.distance(points[j]) <= delta)
                found.push_back(j);
          }
        for (const unsigned int j : found)
          if (j != k)
            neighbours[k].push_back(j);
      }

    // Pairwise completion: j in H^k => k in H^j. With mirror images: j is
    // the image across the planes M of particle o (M empty for a real
    // one); the full body holds o in the family of every reflection of k
    // that maps j to o, across M and any of the planes through o, so those
    // images of k join H^o, and the families are the full body's (with
    // distinct horizons too).
    std::vector<std::pair<unsigned int, unsigned int>> completion;
    for (unsigned int k = 0; k < n; ++k)
      for (const unsigned int j : neighbours[k])
        {
          const unsigned int o      = particles.original(j);
          const unsigned int M      = particles.mirror_mask(j);
          const unsigned int planes = particles.on_mirror_planes(o);
          // every subset S of the planes through o (S = 0 first)
          for (unsigned int S = 0;; S = (S - planes) & planes)
            {
              completion.emplace_back(o, particles.mirror_image(k, M ^ S));
              if (((S - planes) & planes) == 0)
                break;
            }
        }
    for (const auto &[master, member] : completion)
      neighbours[master].push_back(member);
    offsets.assign(1, 0);
    indices.clear();
    for (unsigned int k = 0; k < n; ++k)
      {
        std::vector<unsigned int> &h = neighbours[k];
        std::sort(h.begin(), h.end());
        h.erase(std::unique(h.begin(), h.end()), h.end());
        indices.push_back(k);
        indices.insert(indices.end(), h.begin(), h.end());
        offsets.push_back(indices.size());
        if (nearest_neighbours > 0)
          {
            horizons[k] = 0;
            for (const unsigned int j : h)
              horizons[k] =
                std::max(horizons[k], points[k].distance(points[j]));
          }
      }
  }



  template <int dim>
  double
  FamilySet<dim>::horizon(const unsigned int k) const
  {
    AssertIndexRange(k, horizons.size());
    return horizons[k];
  }



  template <int dim>
  unsigned int
  FamilySet<dim>::n_families() const
  {
    return offsets.empty() ? 0 : offsets.size() - 1;
  }



  template <int dim>
  ArrayView<const unsigned int>
  FamilySet<dim>::members(const unsigned int k) const
  {
    AssertIndexRange(k, n_families());
    return make_array_view(indices.data() + offsets[k],
                           indices.data() + offsets[k + 1]);
  }



  template <int dim>
  unsigned int
  FamilySet<dim>::n_neighbours(const unsigned int k) const
  {
    return offsets[k + 1] - offsets[k] - 1;
  }



  template <int dim>
  std::size_t
  FamilySet<dim>::n_bonds() const
  {
    return indices.size() - n_families();
  }



  template class FamilySet<2>;
  template class FamilySet<3>;
} // namespace pg
