#include <pg/base/exceptions.h>
#include <pg/constraints/support_check.h>

#include <deal.II/base/mpi.h>

#include <Eigen/Dense>

#include <algorithm>
#include <set>
#include <sstream>
#include <unordered_map>

namespace pg
{
  namespace SupportCheck
  {
    namespace
    {
      std::string
      id_list(const std::set<types::boundary_id> &ids)
      {
        std::string text;
        for (const auto id : ids)
          text += (text.empty() ? "" : ", ") + std::to_string(id);
        return text.empty() ? "none" : text;
      }

      /** The largest component of a unit vector if it is axis-aligned. */
      template <int d>
      std::string
      direction(const Tensor<1, d> &v)
      {
        const Tensor<1, d> n = v / v.norm();
        for (unsigned int c = 0; c < d; ++c)
          if (std::abs(std::abs(n[c]) - 1.) < 1e-8)
            return std::string(1, "xyz"[c]);
        std::ostringstream text;
        text.precision(3);
        text << "(" << n << ")";
        return text.str();
      }



      /**
       * "translation in x", "rotation about z through (0 0)", "rotation
       * about an axis parallel to x through (0 0 0)": the motion u(X) = t +
       * omega x (X - centre) / radius of a free mode.
       */
      template <int dim>
      std::string
      describe(const FreeMode<dim> &mode)
      {
        Tensor<1, dim> t;
        Tensor<1, 3>   omega;
        for (unsigned int c = 0; c < dim; ++c)
          t[c] = mode.coefficients[c];
        if (dim == 2)
          omega[2] = mode.coefficients[2];
        else
          for (unsigned int c = 0; c < 3; ++c)
            omega[c] = mode.coefficients[dim + c];
        std::ostringstream text;
        text.precision(4);
        if (omega.norm() < 1e-8)
          return "translation in " + direction(t);
        // the point of the axis nearest the centre: u there is along omega
        Tensor<1, 3> t3;
        for (unsigned int c = 0; c < dim; ++c)
          t3[c] = t[c];
        const Tensor<1, 3> shift =
          mode.radius * cross_product_3d(omega, t3) / omega.norm_square();
        Point<dim> through = mode.centre;
        for (unsigned int c = 0; c < dim; ++c)
          through[c] +=
            (std::abs(shift[c]) < 1e-10 * mode.radius) ? 0. : shift[c];
        for (unsigned int c = 0; c < dim; ++c)
          if (std::abs(through[c]) < 1e-10 * mode.radius)
            through[c] = 0;
        if (dim == 2)
          text << "rotation about z through (" << through << ")";
        else
          {
            Tensor<1, dim> axis;
            for (unsigned int c = 0; c < dim; ++c)
              axis[c] = omega[c];
            text << "rotation about an axis parallel to " << direction(axis)
                 << " through (" << through << ")";
            if (std::abs(omega * t3) > 1e-8 * omega.norm() * t3.norm())
              text << ", with a translation along it";
          }
        return text.str();
      }



      /** Union-find over the vertex nodes (path halving). */
      struct Parts
      {
        std::vector<unsigned int> parent;

        unsigned int
        find(unsigned int a)
        {
          while (parent[a] != a)
            a = parent[a] = parent[parent[a]];
          return a;
        }

        void
        join(const unsigned int a, const unsigned int b)
        {
          const unsigned int ra = find(a), rb = find(b);
          if (ra != rb)
            parent[std::max(ra, rb)] = std::min(ra, rb);
        }
      };
    } // namespace



    template <int dim>
    void
    check_boundary_ids(const Parameters::BoundaryConditions &conditions,
                       const Triangulation<dim>             &triangulation)
    {
      const std::vector<types::boundary_id> existing =
        triangulation.get_boundary_ids();
      const std::set<types::boundary_id> ids(existing.begin(), existing.end());
      const auto                         require = [&](const std::string       &entry,
                               const types::boundary_id id) {
        AssertThrow(ids.count(id) == 1,
                    ExcBadParameter("Boundary conditions/" + entry,
                                    std::to_string(id),
                                    "no boundary face of the mesh has this "
                                                            "id. The mesh has the boundary ids " +
                                      id_list(ids) +
                                      " (see 'Mesh' in subsection "
                                                              "'Geometry' for what they are)."));
      };
      for (const auto &[id, mask] : conditions.dirichlet)
        require("Dirichlet", id);
      for (const auto id : conditions.neumann)
        require("Neumann", id);
      for (const auto id : conditions.neumann_stress)
        require("Neumann stress", id);

      for (const auto &[id, mask] : conditions.dirichlet)
        if (std::all_of(mask.begin(), mask.end(), [](const bool m) {
              return m;
            }))
          for (const auto *entry :
               {&conditions.neumann, &conditions.neumann_stress})
            AssertThrow(
              std::find(entry->begin(), entry->end(), id) == entry->end(),
              ExcBadParameter(
                std::string("Boundary conditions/") +
                  (entry == &conditions.neumann ? "Neumann" : "Neumann stress"),
                std::to_string(id),
                "boundary id " + std::to_string(id) +
                  " is also in 'Dirichlet' with every component "
                  "prescribed, so a traction there does no work and is "
                  "ignored. Remove the id from one of the two entries (a "
                  "Dirichlet condition on some components and a traction "
                  "on the others is fine)."));
    }



    template <int dim>
    std::vector<FreeMode<dim>>
    free_rigid_modes(const DoFHandler<dim>           &dof_handler,
                     const ParticleSet<dim>          &particles,
                     const FamilySet<dim>            &families,
                     const AffineConstraints<double> &zero_constraints,
                     const IndexSet                  &owned_dofs,
                     std::vector<Point<dim>>         &part_centres,
                     std::vector<unsigned int>       &part_sizes)
    {
      constexpr unsigned int n_modes = dim * (dim + 1) / 2;

      // The vertex nodes of all cells (every rank knows all cells) with
      // their positions, and the node and component of every vertex DoF.
      std::unordered_map<types::global_dof_index,
                         std::pair<unsigned int, unsigned int>>
                              node_of_dof;
      std::vector<Point<dim>> position;
      Parts                   parts;
      for (const auto &cell : dof_handler.active_cell_iterators())
        {
          unsigned int node_0 = numbers::invalid_unsigned_int;
          for (const unsigned int v : cell->vertex_indices())
            {
              const auto [it, inserted] = node_of_dof.emplace(
                cell->vertex_dof_index(v, 0),
                std::make_pair(static_cast<unsigned int>(position.size()), 0u));
              const unsigned int node = it->second.first;
              if (inserted)
                {
                  for (unsigned int c = 1; c < dim; ++c)
                    node_of_dof.emplace(cell->vertex_dof_index(v, c),
                                        std::make_pair(node, c));
                  position.push_back(cell->vertex(v));
                  parts.parent.push_back(node);
                }
              if (node_0 == numbers::invalid_unsigned_int)
                node_0 = node;
              else
                parts.join(node_0, node);
            }
        }
      // A family connects its master to its neighbours.
      for (unsigned int k = 0; k < families.n_families(); ++k)
        for (const unsigned int j : families.members(k))
          parts.join(node_of_dof.at(particles.dof(k, 0)).first,
                     node_of_dof.at(particles.dof(j, 0)).first);

      // Number the parts by their smallest node; centres and sizes.
      std::vector<unsigned int>                      part_of(position.size());
      std::unordered_map<unsigned int, unsigned int> part_index;
      part_centres.clear();
      part_sizes.clear();
      for (unsigned int a = 0; a < position.size(); ++a)
        {
          const auto [it, inserted] =
            part_index.emplace(parts.find(a), part_centres.size());
          if (inserted)
            {
              part_centres.emplace_back();
              part_sizes.push_back(0);
            }
          part_of[a] = it->second;
          part_centres[it->second] += position[a];
          ++part_sizes[it->second];
        }
      const unsigned int n_parts = part_centres.size();
      for (unsigned int p = 0; p < n_parts; ++p)
        part_centres[p] /= part_sizes[p];
      std::vector<double> radius(n_parts, 0.);
      for (unsigned int a = 0; a < position.size(); ++a)
        radius[part_of[a]] =
          std::max(radius[part_of[a]],
                   position[a].distance(part_centres[part_of[a]]));

      // Component c of mode m at node a: translations, then rotations
      // omega x (X - centre) / radius.
      const auto mode_value = [&](const unsigned int a,
                                  const unsigned int c,
                                  const unsigned int m) -> double {
        if (m < dim)
          return (m == c) ? 1. : 0.;
        const unsigned int   p = part_of[a];
        const Tensor<1, dim> x =
          (position[a] - part_centres[p]) / std::max(radius[p], 1e-300);
        if (dim == 2)
          return (c == 0) ? -x[1] : x[0];
        // rotation about axis e = m - dim: (e x x)_c
        const unsigned int e = m - dim;
        Tensor<1, 3>       axis, X, r;
        axis[e] = 1;
        for (unsigned int d = 0; d < dim; ++d)
          X[d] = x[d];
        r = cross_product_3d(axis, X);
        return r[c];
      };

      // G^T G of every part from the owned constraint lines.
      std::vector<double> gram(n_parts * n_modes * n_modes, 0.);
      for (const auto &line : zero_constraints.get_lines())
        {
          if (!owned_dofs.is_element(line.index))
            continue;
          const auto [a, c] = node_of_dof.at(line.index);
          std::array<double, n_modes> g;
          for (unsigned int m = 0; m < n_modes; ++m)
            {
              g[m] = mode_value(a, c, m);
              for (const auto &[j, weight] : line.entries)
                {
                  const auto [b, d] = node_of_dof.at(j);
                  g[m] -= weight * mode_value(b, d, m);
                }
            }
          double *G = &gram[part_of[a] * n_modes * n_modes];
          for (unsigned int m = 0; m < n_modes; ++m)
            for (unsigned int n = 0; n < n_modes; ++n)
              G[m * n_modes + n] += g[m] * g[n];
        }
      {
        const std::vector<double> local = gram;
        Utilities::MPI::sum(ArrayView<const double>(local),
                            dof_handler.get_communicator(),
                            ArrayView<double>(gram));
      }

      std::vector<FreeMode<dim>> free;
      for (unsigned int p = 0; p < n_parts; ++p)
        {
          Eigen::Matrix<double, n_modes, n_modes> G;
          for (unsigned int m = 0; m < n_modes; ++m)
            for (unsigned int n = 0; n < n_modes; ++n)
              G(m, n) = gram[(p * n_modes + m) * n_modes + n];
          const Eigen::SelfAdjointEigenSolver<
            Eigen::Matrix<double, n_modes, n_modes>>
            eigen(G);
          // A held mode violates at least one line by O(1) (the modes are
          // O(1) at every node); a free one by round-off.
          std::vector<std::vector<double>> basis;
          for (unsigned int m = 0; m < n_modes; ++m)
            if (eigen.eigenvalues()[m] < 1e-12)
              {
                basis.emplace_back(n_modes);
                for (unsigned int n = 0; n < n_modes; ++n)
                  basis.back()[n] = eigen.eigenvectors()(n, m);
              }
          // A readable basis of the free modes: reduced row echelon form
          // with the rotations eliminated first, so that each vector is one
          // rotation (about a shifted axis) or one translation.
          std::vector<unsigned int> order;
          for (unsigned int n = dim; n < n_modes; ++n)
            order.push_back(n);
          for (unsigned int n = 0; n < dim; ++n)
            order.push_back(n);
          unsigned int row = 0;
          for (const unsigned int col : order)
            {
              if (row == basis.size())
                break;
              unsigned int pivot = row;
              for (unsigned int r = row; r < basis.size(); ++r)
                if (std::abs(basis[r][col]) > std::abs(basis[pivot][col]))
                  pivot = r;
              if (std::abs(basis[pivot][col]) < 1e-8)
                continue;
              std::swap(basis[row], basis[pivot]);
              const double scale = basis[row][col];
              for (double &b : basis[row])
                b /= scale;
              for (unsigned int r = 0; r < basis.size(); ++r)
                if (r != row)
                  {
                    const double factor = basis[r][col];
                    for (unsigned int n = 0; n < n_modes; ++n)
                      basis[r][n] -= factor * basis[row][n];
                  }
              ++row;
            }
          for (auto &b : basis)
            {
              for (double &c : b)
                if (std::abs(c) < 1e-10)
                  c = 0;
              free.push_back(FreeMode<dim>{p, b, part_centres[p], radius[p]});
            }
        }
      return free;
    }



    template <int dim>
    void
    check_rigid_body_modes(const DoFHandler<dim>           &dof_handler,
                           const ParticleSet<dim>          &particles,
                           const FamilySet<dim>            &families,
                           const AffineConstraints<double> &zero_constraints,
                           const IndexSet                  &owned_dofs)
    {
      std::vector<Point<dim>>          centres;
      std::vector<unsigned int>        sizes;
      const std::vector<FreeMode<dim>> free = free_rigid_modes(dof_handler,
                                                               particles,
                                                               families,
                                                               zero_constraints,
                                                               owned_dofs,
                                                               centres,
                                                               sizes);
      if (free.empty())
        return;
      std::ostringstream text;
      text << "The static problem is singular: the boundary conditions "
           << "(subsection 'Boundary conditions') leave rigid body motions "
           << "free, so the tangent has a null space and Newton cannot "
           << "converge.";
      unsigned int last_part = numbers::invalid_unsigned_int;
      for (const FreeMode<dim> &mode : free)
        {
          if (mode.part != last_part)
            text << "\n  Part " << mode.part + 1 << " of " << centres.size()
                 << " (" << sizes[mode.part] << " vertices, centre ("
                 << centres[mode.part] << ")) can move freely by:";
          last_part                     = mode.part;
          const std::string combination = describe<dim>(mode);
          text << "\n    " << combination;
        }
      text << "\nAdd supports that remove them: 'Dirichlet' on a boundary id "
           << "(e.g. 'Dirichlet = 0: " << (dim == 2 ? "xy" : "xyz")
           << "'), 'Symmetry' planes, 'Fixed points' or 'Dirichlet boxes'"
           << (centres.size() > 1 ?
                 ", one set for every part (or connect the parts: the mesh "
                 "has disconnected pieces, see 'Coincident vertices' in "
                 "subsection 'Geometry')" :
                 "")
           << ". A free body is fine for 'Time/Integrator = leapfrog' or "
           << "'newmark' and for 'Analysis/Type = eigenmodes'.";
      AssertThrow(false, ExcMessage(text.str()));
    }



    template void
    check_boundary_ids<2>(const Parameters::BoundaryConditions &,
                          const Triangulation<2> &);
    template void
    check_boundary_ids<3>(const Parameters::BoundaryConditions &,
                          const Triangulation<3> &);
    template std::vector<FreeMode<2>>
    free_rigid_modes<2>(const DoFHandler<2> &,
                        const ParticleSet<2> &,
                        const FamilySet<2> &,
                        const AffineConstraints<double> &,
                        const IndexSet &,
                        std::vector<Point<2>> &,
                        std::vector<unsigned int> &);
    template std::vector<FreeMode<3>>
    free_rigid_modes<3>(const DoFHandler<3> &,
                        const ParticleSet<3> &,
                        const FamilySet<3> &,
                        const AffineConstraints<double> &,
                        const IndexSet &,
                        std::vector<Point<3>> &,
                        std::vector<unsigned int> &);
    template void
    check_rigid_body_modes<2>(const DoFHandler<2> &,
                              const ParticleSet<2> &,
                              const FamilySet<2> &,
                              const AffineConstraints<double> &,
                              const IndexSet &);
    template void
    check_rigid_body_modes<3>(const DoFHandler<3> &,
                              const ParticleSet<3> &,
                              const FamilySet<3> &,
                              const AffineConstraints<double> &,
                              const IndexSet &);
  } // namespace SupportCheck
} // namespace pg
