#include <pg/base/exceptions.h>
#include <pg/mesh/linear_cells.h>
#include <pg/mesh/particle_set.h>

#include <deal.II/base/quadrature_lib.h>
#include <deal.II/fe/fe_values.h>
#include <deal.II/grid/tria.h>

#include <algorithm>
#include <cmath>
#include <numeric>

namespace pg
{
  namespace
  {
    /** "Boundary conditions/Symmetry treatment = mirror" cannot be used. */
    ExcBadParameter
    mirror_error(const std::string &why)
    {
      return ExcBadParameter("Boundary conditions/Symmetry treatment",
                             "mirror",
                             why + " Set 'Symmetry treatment = constraint' "
                                   "(n . u = 0 alone) for such planes.");
    }
  } // namespace



  template <int dim>
  void
  ParticleSet<dim>::reinit(const DoFHandler<dim>   &dof_handler,
                           const std::vector<bool> &meshfree)
  {
    reinit(dof_handler, meshfree, {});
  }



  template <int dim>
  void
  ParticleSet<dim>::reinit(const DoFHandler<dim>                 &dof_handler,
                           const std::vector<bool>               &meshfree,
                           const std::vector<types::boundary_id> &mirror_ids)
  {
    const Triangulation<dim> &tria       = dof_handler.get_triangulation();
    const unsigned int        n_vertices = tria.n_vertices();

    // The mirror planes, and the planes each vertex lies on.
    AssertThrow(mirror_ids.size() <= dim,
                mirror_error("More than dim symmetry planes."));
    mirror_planes.clear();
    std::vector<unsigned int> vertex_planes(n_vertices, 0);
    const auto                is_mirror_face = [&](const auto &face) {
      return face->at_boundary() &&
             std::find(mirror_ids.begin(),
                       mirror_ids.end(),
                       face->boundary_id()) != mirror_ids.end();
    };
    for (const types::boundary_id id : mirror_ids)
      {
        MirrorPlane plane{numbers::invalid_unsigned_int, 0., id};
        for (const auto &cell : tria.active_cell_iterators())
          for (const auto &face : cell->face_iterators())
            if (face->at_boundary() && face->boundary_id() == id)
              {
                // the axis along which the face's vertices do not spread
                unsigned int axis = numbers::invalid_unsigned_int;
                for (unsigned int d = 0; d < dim; ++d)
                  {
                    double lo = face->vertex(0)[d], hi = lo;
                    for (const unsigned int v : face->vertex_indices())
                      {
                        lo = std::min(lo, face->vertex(v)[d]);
                        hi = std::max(hi, face->vertex(v)[d]);
                      }
                    if (hi - lo <= 1e-10 * face->diameter())
                      axis = d;
                  }
                AssertThrow(axis != numbers::invalid_unsigned_int,
                            mirror_error("The symmetry boundary " +
                                         std::to_string(id) +
                                         " is not normal to a coordinate "
                                         "axis, which mirrored families "
                                         "need."));
                if (plane.axis == numbers::invalid_unsigned_int)
                  plane = {axis, face->vertex(0)[axis], id};
                AssertThrow(plane.axis == axis &&
                              std::abs(face->vertex(0)[axis] - plane.offset) <=
                                1e-10 * face->diameter(),
                            mirror_error("The faces of the symmetry "
                                         "boundary " +
                                         std::to_string(id) +
                                         " do not lie in one plane."));
                for (const unsigned int v : face->vertex_indices())
                  vertex_planes[face->vertex_index(v)] |=
                    (1u << mirror_planes.size());
              }
        AssertThrow(plane.axis != numbers::invalid_unsigned_int,
                    mirror_error("No boundary face has the symmetry id " +
                                 std::to_string(id) + "."));
        for (const MirrorPlane &other : mirror_planes)
          AssertThrow(other.axis != plane.axis,
                      mirror_error("The symmetry boundaries " +
                                   std::to_string(other.boundary_id) + " and " +
                                   std::to_string(id) +
                                   " are parallel, which would need "
                                   "infinitely many images."));
        mirror_planes.push_back(plane);
      }

    // Which vertices belong to meshfree cells, and which also to FE cells.
    std::vector<bool> is_particle(n_vertices, false);
    std::vector<bool> on_fe_cell(n_vertices, false);
    for (const auto &cell : dof_handler.active_cell_iterators())
      for (const unsigned int v : cell->vertex_indices())
        (meshfree[cell->active_cell_index()] ?
           is_particle :
           on_fe_cell)[cell->vertex_index(v)] = true;

    std::vector<unsigned int> particle_of_vertex(n_vertices,
                                                 numbers::invalid_unsigned_int);
    vertices.clear();
    for (unsigned int v = 0; v < n_vertices; ++v)
      if (is_particle[v])
        {
          particle_of_vertex[v] = vertices.size();
          vertices.push_back(v);
        }
    const unsigned int n = vertices.size();

    positions.resize(n);
    volumes.assign(n, 0.);
    spacings.assign(n, 0.);
    dofs.assign(n, {});
    components = dim;
    area_vectors.assign(n, {});
    interface.resize(n);
    interface_areas.assign(n, Tensor<1, dim>());
    n_real = n;
    plane_masks.resize(n);
    image_originals.clear();
    image_masks.clear();
    image_indices.assign(n, {});
    for (unsigned int k = 0; k < n; ++k)
      {
        positions[k]   = tria.get_vertices()[vertices[k]];
        interface[k]   = on_fe_cell[vertices[k]];
        plane_masks[k] = vertex_planes[vertices[k]];
        image_indices[k].fill(numbers::invalid_unsigned_int);
        image_indices[k][0] = k;
      }

    // Lumped volumes and boundary area vectors with the scalar linear
    // functions (FE_Q(1) or FE_SimplexP(1): shape function i belongs to
    // vertex i). A simplex gives 1/(dim+1) of its volume to each vertex, a
    // simplex face 1/dim of its area vector to each of its vertices.
    const LinearCells<dim>    cells(tria);
    const Quadrature<dim>     quadrature      = cells.quadrature(2);
    const Quadrature<dim - 1> face_quadrature = cells.face_quadrature(2);
    FEValues<dim>             fe_values(cells.mapping(),
                            cells.scalar_element(),
                            quadrature,
                            update_values | update_JxW_values);
    FEFaceValues<dim>         fe_face_values(cells.mapping(),
                                     cells.scalar_element(),
                                     face_quadrature,
                                     update_values | update_JxW_values |
                                       update_normal_vectors);
    // the vertices of face f of a cell (the others get nothing from it; on
    // a simplex their shape values on the face are round-off, not zero)
    const auto on_face =
      [](const auto &cell, const unsigned int f, const unsigned int i) {
        for (const unsigned int v : cell->face(f)->vertex_indices())
          if (cell->face(f)->vertex_index(v) == cell->vertex_index(i))
            return true;
        return false;
      };
    std::vector<unsigned int>                n_edges(n, 0);
    std::vector<std::vector<Tensor<1, dim>>> face_normals(n);
    std::vector<bool> edge_done(tria.n_raw_lines(), false);

    for (const auto &cell : dof_handler.active_cell_iterators())
      if (meshfree[cell->active_cell_index()])
        {
          fe_values.reinit(
            typename Triangulation<dim>::active_cell_iterator(cell));
          for (const unsigned int i : cell->vertex_indices())
            {
              const unsigned int k = particle_of_vertex[cell->vertex_index(i)];
              for (const unsigned int q : fe_values.quadrature_point_indices())
                volumes[k] += fe_values.shape_value(i, q) * fe_values.JxW(q);
              // u first, then the extra nodal fields of the meshfree
              // cells' element (dofs/field_layout.h), if any
              components = cell->get_fe().n_dofs_per_vertex();
              AssertIndexRange(components, dim + 3);
              for (unsigned int c = 0; c < components; ++c)
                dofs[k][c] = cell->vertex_dof_index(i, c);
            }

          for (unsigned int l = 0; l < cell->n_lines(); ++l)
            {
              const auto line = cell->line(l);
              if (edge_done[line->index()])
                continue;
              edge_done[line->index()] = true;
              // with mirror planes, the edge and its images at particles
              // on a plane: 2^m copies, m the planes that hold the
              // particle but not the edge
              const unsigned int common = vertex_planes[line->vertex_index(0)] &
                                          vertex_planes[line->vertex_index(1)];
              for (unsigned int e = 0; e < 2; ++e)
                {
                  const unsigned int k =
                    particle_of_vertex[line->vertex_index(e)];
                  const unsigned int copies =
                    1u << (__builtin_popcount(
                      vertex_planes[line->vertex_index(e)] & ~common));
                  spacings[k] += copies * line->diameter();
                  n_edges[k] += copies;
                }
            }

          for (const unsigned int f : cell->face_indices())
            if (!cell->face(f)->at_boundary() &&
                !meshfree[cell->neighbor(f)->active_cell_index()])
              {
                fe_face_values.reinit(
                  typename Triangulation<dim>::active_cell_iterator(cell),
                  f);
                for (const unsigned int i : cell->vertex_indices())
                  if (on_face(cell, f, i))
                    for (const unsigned int q :
                         fe_face_values.quadrature_point_indices())
                      interface_areas[particle_of_vertex[cell->vertex_index(
                        i)]] += fe_face_values.shape_value(i, q) *
                                fe_face_values.normal_vector(q) *
                                fe_face_values.JxW(q);
              }
            else if (cell->face(f)->at_boundary() &&
                     !is_mirror_face(cell->face(f)))
              {
                fe_face_values.reinit(
                  typename Triangulation<dim>::active_cell_iterator(cell),
                  f);
                const types::boundary_id id = cell->face(f)->boundary_id();
                for (const unsigned int i : cell->vertex_indices())
                  if (on_face(cell, f, i))
                    {
                      Tensor<1, dim> a;
                      for (const unsigned int q :
                           fe_face_values.quadrature_point_indices())
                        a += fe_face_values.shape_value(i, q) *
                             fe_face_values.normal_vector(q) *
                             fe_face_values.JxW(q);
                      if (a.norm() > 0)
                        {
                          const unsigned int k =
                            particle_of_vertex[cell->vertex_index(i)];
                          area_vectors[k][id] += a;
                          face_normals[k].push_back(a / a.norm());
                        }
                    }
              }
        }

    corner.assign(n, false);
    edges.assign(n, Tensor<1, dim>());
    for (unsigned int k = 0; k < n; ++k)
      {
        spacings[k] /= n_edges[k];
        for (const auto &a : face_normals[k])
          for (const auto &b : face_normals[k])
            if (a * b < std::cos(numbers::PI / 6))
              corner[k] = true;
        if constexpr (dim == 3)
          if (corner[k])
            {
              // the edge direction: normal to the two most different face
              // normals; an edge if no face normal is more than 30 degrees
              // out of their plane (a third face makes a corner)
              const auto    &normals = face_normals[k];
              Tensor<1, dim> a = normals[0], b = normals[0];
              for (const auto &p : normals)
                for (const auto &q : normals)
                  if (p * q < a * b)
                    {
                      a = p;
                      b = q;
                    }
              Tensor<1, dim> e = cross_product_3d(a, b);
              // (nearly) opposite normals, a knife edge: left a corner
              if (e.norm() < 1e-6)
                continue;
              e /= e.norm();
              if (std::all_of(normals.begin(),
                              normals.end(),
                              [&](const Tensor<1, dim> &f) {
                                return std::abs(f * e) <
                                       std::sin(numbers::PI / 6);
                              }))
                edges[k] = e;
            }
      }
  }



  template <int dim>
  const Tensor<1, dim> &
  ParticleSet<dim>::interface_area_vector(const unsigned int k) const
  {
    AssertIndexRange(k, interface_areas.size());
    return interface_areas[k];
  }



  template <int dim>
  bool
  ParticleSet<dim>::at_corner(const unsigned int k) const
  {
    AssertIndexRange(k, corner.size());
    return corner[k];
  }



  template <int dim>
  const Tensor<1, dim> &
  ParticleSet<dim>::edge_direction(const unsigned int k) const
  {
    AssertIndexRange(k, edges.size());
    return edges[k];
  }



  template <int dim>
  void
  ParticleSet<dim>::add_mirror_images(const double reach)
  {
    const unsigned int n_planes = mirror_planes.size();
    for (unsigned int k = 0; k < n_real; ++k)
      for (unsigned int mask = 1; mask < (1u << n_planes); ++mask)
        {
          if ((mask & plane_masks[k]) != 0)
            continue; // a plane through k does not move it
          Point<dim> x      = positions[k];
          bool       within = true;
          for (unsigned int p = 0; p < n_planes; ++p)
            if (mask & (1u << p))
              {
                const MirrorPlane &plane = mirror_planes[p];
                within = within && (std::abs(x[plane.axis] - plane.offset) <=
                                    reach * (1. + 1e-12));
                x[plane.axis] = 2. * plane.offset - x[plane.axis];
              }
          if (!within)
            continue;
          image_indices[k][mask] = positions.size();
          image_originals.push_back(k);
          image_masks.push_back(mask);
          positions.push_back(x);
          spacings.push_back(spacings[k]);
          dofs.push_back(dofs[k]);
        }
  }



  template <int dim>
  unsigned int
  ParticleSet<dim>::n_particles() const
  {
    return n_real;
  }



  template <int dim>
  unsigned int
  ParticleSet<dim>::n_particles_and_images() const
  {
    return positions.size();
  }



  template <int dim>
  unsigned int
  ParticleSet<dim>::n_mirror_planes() const
  {
    return mirror_planes.size();
  }



  template <int dim>
  unsigned int
  ParticleSet<dim>::mirror_plane_axis(const unsigned int p) const
  {
    AssertIndexRange(p, mirror_planes.size());
    return mirror_planes[p].axis;
  }



  template <int dim>
  double
  ParticleSet<dim>::mirror_plane_offset(const unsigned int p) const
  {
    AssertIndexRange(p, mirror_planes.size());
    return mirror_planes[p].offset;
  }



  template <int dim>
  unsigned int
  ParticleSet<dim>::original(const unsigned int j) const
  {
    AssertIndexRange(j, positions.size());
    return j < n_real ? j : image_originals[j - n_real];
  }



  template <int dim>
  unsigned int
  ParticleSet<dim>::mirror_mask(const unsigned int j) const
  {
    AssertIndexRange(j, positions.size());
    return j < n_real ? 0 : image_masks[j - n_real];
  }



  template <int dim>
  unsigned int
  ParticleSet<dim>::on_mirror_planes(const unsigned int k) const
  {
    AssertIndexRange(k, n_real);
    return plane_masks[k];
  }



  template <int dim>
  unsigned int
  ParticleSet<dim>::mirror_image(const unsigned int k,
                                 const unsigned int mask) const
  {
    AssertIndexRange(k, n_real);
    const unsigned int j = image_indices[k][mask & ~plane_masks[k]];
    AssertThrow(j != numbers::invalid_unsigned_int, ExcInternalError());
    return j;
  }



  template <int dim>
  unsigned int
  ParticleSet<dim>::reflection(const unsigned int j,
                               const unsigned int mask) const
  {
    const unsigned int k = original(j);
    return image_indices[k][(mirror_mask(j) ^ mask) & ~plane_masks[k]];
  }



  template <int dim>
  double
  ParticleSet<dim>::mirror_sign(const unsigned int j,
                                const unsigned int c) const
  {
    if (j < n_real || c >= dim)
      return 1.;
    const unsigned int mask = image_masks[j - n_real];
    for (unsigned int p = 0; p < mirror_planes.size(); ++p)
      if ((mask & (1u << p)) && mirror_planes[p].axis == c)
        return -1.;
    return 1.;
  }



  template <int dim>
  Tensor<1, dim>
  ParticleSet<dim>::parallel_to_mirror_planes(const unsigned int    k,
                                              const Tensor<1, dim> &v) const
  {
    AssertIndexRange(k, n_real);
    Tensor<1, dim> w = v;
    for (unsigned int p = 0; p < mirror_planes.size(); ++p)
      if (plane_masks[k] & (1u << p))
        w[mirror_planes[p].axis] = 0.;
    return w;
  }



  template <int dim>
  double
  ParticleSet<dim>::family_share(const unsigned int k) const
  {
    AssertIndexRange(k, n_real);
    return volume(k) / member_volume(k);
  }



  template <int dim>
  double
  ParticleSet<dim>::member_volume(const unsigned int j) const
  {
    const unsigned int k = original(j);
    return volumes[k] * (1u << __builtin_popcount(plane_masks[k]));
  }



  template <int dim>
  const Point<dim> &
  ParticleSet<dim>::position(const unsigned int k) const
  {
    AssertIndexRange(k, positions.size());
    return positions[k];
  }



  template <int dim>
  double
  ParticleSet<dim>::volume(const unsigned int k) const
  {
    AssertIndexRange(k, volumes.size());
    return volumes[k];
  }



  template <int dim>
  double
  ParticleSet<dim>::spacing(const unsigned int k) const
  {
    AssertIndexRange(k, spacings.size());
    return spacings[k];
  }



  template <int dim>
  types::global_dof_index
  ParticleSet<dim>::dof(const unsigned int k, const unsigned int c) const
  {
    AssertIndexRange(k, dofs.size());
    AssertIndexRange(c, components);
    return dofs[k][c];
  }



  template <int dim>
  unsigned int
  ParticleSet<dim>::n_components() const
  {
    return components;
  }



  template <int dim>
  unsigned int
  ParticleSet<dim>::vertex(const unsigned int k) const
  {
    AssertIndexRange(k, vertices.size());
    return vertices[k];
  }



  template <int dim>
  const std::map<types::boundary_id, Tensor<1, dim>> &
  ParticleSet<dim>::boundary_area_vectors(const unsigned int k) const
  {
    AssertIndexRange(k, area_vectors.size());
    return area_vectors[k];
  }



  template <int dim>
  bool
  ParticleSet<dim>::on_interface(const unsigned int k) const
  {
    AssertIndexRange(k, interface.size());
    return interface[k];
  }



  template <int dim>
  double
  ParticleSet<dim>::total_volume() const
  {
    return std::accumulate(volumes.begin(), volumes.end(), 0.);
  }



  template class ParticleSet<2>;
  template class ParticleSet<3>;
} // namespace pg
