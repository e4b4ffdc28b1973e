// The rows of the VC correction system (pg-methods.md section 11.5): which
// equation or constraint each row of a particle holds (interior,
// tangential, fixed; the boundary options p, s, sn), the rows of the
// particles on mirror symmetry planes, and the factors fixed against the
// null space. The assembly and the solve of the system are in
// correction_system.cc.

#include <pg/base/exceptions.h>
#include <pg/elements/correction_system.h>

#include <deal.II/base/symmetric_tensor.h>

#include <cmath>
#include <vector>

namespace pg
{
  namespace
  {
    /**
     * The rows of a particle with a unit direction @p v (the normal of a
     * face, or the edge direction of a 3-D edge): @p v goes into row @p
     * along[a] of the component a in which |v| is largest (|v_a| >=
     * 1/sqrt(dim)), and into every other row i of @p across the unit
     * projection of e_i onto the plane normal to v (its i-th component is
     * sqrt(1 - v_i^2) >= 1/sqrt(2)). Every row so keeps a nonzero
     * diagonal, which ILU needs.
     */
    template <int dim>
    void
    split_rows(const Tensor<1, dim> &v,
               Tensor<2, dim>       &along,
               Tensor<2, dim>       &across)
    {
      unsigned int axis = 0;
      for (unsigned int c = 1; c < dim; ++c)
        if (std::abs(v[c]) > std::abs(v[axis]))
          axis = c;
      along[axis] = v;
      for (unsigned int i = 0; i < dim; ++i)
        if (i != axis)
          {
            Tensor<1, dim> t = Point<dim>::unit_vector(i);
            t -= (t * v) * v;
            across[i] = t / t.norm();
          }
    }
  } // namespace



  template <int dim>
  void
  CorrectionSystem<dim>::classify_rows()
  {
    using VCBoundary     = FormulationCode::VCBoundary;
    const unsigned int n = particles->n_particles();
    singular             = false;
    kind.assign(n, Row::interior);
    R.assign(n, unit_symmetric_tensor<dim>());
    normal.assign(n, Tensor<1, dim>());
    target.assign(n, Tensor<1, dim>());
    constraint.assign(n, Tensor<2, dim>());
    std::vector<unsigned int> surface;
    for (unsigned int k = 0; k < n; ++k)
      {
        const auto &areas = particles->boundary_area_vectors(k);
        if (particles->on_interface(k))
          {
            // full target: the interface area plus any surface area, so
            // that FE and PG contributions of a constant stress cancel
            // there (coupled patch test)
            target[k] = particles->interface_area_vector(k);
            for (const auto &area : areas)
              target[k] += area.second;
            continue;
          }
        if (areas.empty())
          continue;
        surface.push_back(k);
        for (const auto &area : areas)
          normal[k] += area.second;
        if (!prescribed_targets.empty())
          target[k] = prescribed_targets[k];
        else if (formulation.vc_boundary == VCBoundary::p)
          target[k] = normal[k];
        normal[k] /= normal[k].norm();
        const Tensor<1, dim> &edge = particles->edge_direction(k);
        const bool            at_edge =
          (formulation.vc_boundary == VCBoundary::sn && edge.norm() > 0);
        if (formulation.vc_boundary == VCBoundary::s ||
            (formulation.vc_boundary == VCBoundary::sn &&
             particles->at_corner(k) && !at_edge))
          kind[k] = Row::fixed;
        else if (at_edge)
          {
            // 3-D edge (two faces): alpha^k along the edge direction e and
            // e . d^k = 0, so that d^k lies in the plane of the two face
            // normals and the loads and supports of the faces can take it
            // (with alpha^k = 0 here d^k keeps a part along the edge that
            // neither a traction T (n . d^k) nor a symmetry plane carries).
            // The equation e . d^k = 0 in one row, the constraints
            // c_j . alpha^k = 0 in the others.
            kind[k] = Row::tangential;
            R[k]    = Tensor<2, dim>();
            split_rows(edge, R[k], constraint[k]);
          }
        else if (formulation.vc_boundary == VCBoundary::sn)
          {
            // A face: the constraint n . alpha^k = 0 in one row, the
            // equations t_i . d^k = 0 in the others. Any basis of the
            // tangent plane gives the same factors.
            kind[k] = Row::tangential;
            R[k]    = Tensor<2, dim>();
            split_rows(normal[k], constraint[k], R[k]);
          }
      }
    for (unsigned int k = 0; k < n; ++k)
      if (particles->on_interface(k) &&
          particles->boundary_area_vectors(k).empty())
        surface.push_back(k);
    // (the mirror planes are no surface: whether the body has a free
    // surface is decided before their rows are restricted)
    bool free_surface = false;
    for (unsigned int k = 0; k < n; ++k)
      free_surface = free_surface || (kind[k] != Row::interior);
    restrict_to_mirror_planes();
    fix_null_space(surface, free_surface);
  }



  template <int dim>
  void
  CorrectionSystem<dim>::restrict_to_mirror_planes()
  {
    // A particle on mirror planes is its own image: its factors are even,
    // alpha^k . n = 0 for each plane normal n, and the n-component of
    // d^k holds by symmetry (its row is replaced). Of the directions E in
    // which the option lets alpha^k vary (and holds the equations: all,
    // the face's tangent plane, the edge), E' = E orthogonal to the
    // normals stays: dim directions interior, dim - 1 a face, 1 an edge,
    // none fixed.
    if (particles->n_mirror_planes() == 0)
      return;
    // Option p keeps a null space whose part, fixed at d + 1 particles,
    // changes PBG's trial functions: a mirrored model cannot fix it as the
    // full body does (2-D quarter with VCPBG V5p Unl: 10 % off the full
    // body, half 1.3 %). U1SUnl's second system (prescribed targets,
    // option p) fixes it at single components (fix_mirrored_null_space())
    // and equals the full body.
    AssertThrow(formulation.vc_boundary != FormulationCode::VCBoundary::p ||
                  !prescribed_targets.empty(),
                ExcBadParameter("Boundary conditions/Symmetry treatment",
                                "mirror",
                                "the VC boundary option p of '" +
                                  formulation.text +
                                  "' (subsection 'Discretization') leaves "
                                  "the VC factors a null-space part that a "
                                  "mirrored model cannot fix as the full "
                                  "body does. Use option sn or s, or "
                                  "'Symmetry treatment = constraint'."));
    for (unsigned int k = 0; k < particles->n_particles(); ++k)
      {
        const unsigned int planes = particles->on_mirror_planes(k);
        if (planes == 0 || kind[k] == Row::fixed)
          continue;
        // projector onto E (the rows of R[k] span it; orthonormalised)
        std::vector<Tensor<1, dim>> basis;
        for (unsigned int i = 0; i < dim; ++i)
          {
            Tensor<1, dim> v = R[k][i];
            for (const auto &b : basis)
              v -= (v * b) * b;
            if (v.norm() > 1e-10)
              basis.push_back(v / v.norm());
          }
        SymmetricTensor<2, dim> P_E, P_planes = unit_symmetric_tensor<dim>();
        for (const auto &b : basis)
          P_E += symmetrize(outer_product(b, b));
        for (unsigned int p = 0; p < particles->n_mirror_planes(); ++p)
          if (planes & (1u << p))
            P_planes[particles->mirror_plane_axis(p)]
                    [particles->mirror_plane_axis(p)] = 0.;
        // E' = the eigenvectors of P_planes P_E P_planes with eigenvalue 1
        const auto eigen = eigenvectors(
          symmetrize(Tensor<2, dim>(P_planes) * Tensor<2, dim>(P_E) *
                     Tensor<2, dim>(P_planes)));
        std::vector<Tensor<1, dim>> kept;
        for (const auto &[value, vector] : eigen)
          if (value > 1. - 1e-8)
            kept.push_back(vector);
        R[k]          = Tensor<2, dim>();
        constraint[k] = Tensor<2, dim>();
        if (kept.empty())
          kind[k] = Row::fixed;
        else if (kept.size() == dim)
          R[k] = unit_symmetric_tensor<dim>();
        else
          {
            kind[k] = Row::tangential;
            if (kept.size() == 1)
              split_rows(kept[0], R[k], constraint[k]);
            else // dim - 1 = 2 directions in 3-D: the normal of their plane
              {
                Tensor<1, dim> normal_of_kept = eigen[dim - 1].second;
                split_rows(normal_of_kept, constraint[k], R[k]);
              }
          }
      }
  }



  template <int dim>
  void
  CorrectionSystem<dim>::fix_null_space(
    const std::vector<unsigned int> &surface,
    const bool                       free_surface)
  {
    // Without a free surface (option p, or particles embedded in finite
    // elements) every row has a full target and the system has the nullity
    // d (d + 1) of the discrete Gauss identities. Fixing alpha at d + 1
    // particles spread over the boundary removes it (one particle for
    // PPG2, see below); the dropped equations then hold automatically,
    // since the targets obey the same identities.
    const unsigned int n = particles->n_particles();
    if (formulation.vc_boundary != FormulationCode::VCBoundary::p &&
        free_surface)
      {
        // with FE coupling the system keeps a null space (see solve())
        for (unsigned int k = 0; k < n; ++k)
          singular = singular || particles->on_interface(k);
        return;
      }

    AssertThrow(surface.size() > dim,
                ExcMessage("The VC correction needs at least dim + 1 "
                           "particles on the boundary of the meshfree "
                           "region."));
    std::vector<unsigned int> chosen             = {surface[0]};
    const auto                distance_to_chosen = [&](const unsigned int k) {
      // distance to the affine hull of the chosen particles
      std::vector<Tensor<1, dim>> basis;
      for (unsigned int i = 1; i < chosen.size(); ++i)
        {
          Tensor<1, dim> e =
            particles->position(chosen[i]) - particles->position(chosen[0]);
          for (const auto &b : basis)
            e -= (e * b) * b;
          if (e.norm() > 0)
            basis.push_back(e / e.norm());
        }
      Tensor<1, dim> r =
        particles->position(k) - particles->position(chosen[0]);
      for (const auto &b : basis)
        r -= (r * b) * b;
      return r.norm();
    };
    // PPG2 test functions keep only sum_k d^k = 0 (section 11.4): its
    // nullity is d, so one particle is fixed. So is a V1 correction
    // anywhere (PPG interface masters use V1, family_elements.cc): V1 does
    // not preserve first-order consistency, so sum_k X^k (x) d^k depends
    // on alpha.
    bool first_order_identity =
      formulation.method != FormulationCode::Method::ppg2;
    for (unsigned int k = 0; k < n; ++k)
      if (elements->family_correction_function(k) ==
          FormulationCode::CorrectionFunction::v1)
        first_order_identity = false;
    if (particles->n_mirror_planes() > 0)
      {
        fix_mirrored_null_space(surface, first_order_identity);
        return;
      }
    const unsigned int n_fixed = (first_order_identity ? dim + 1 : 1);
    while (chosen.size() < n_fixed)
      {
        unsigned int best = surface[0];
        for (const unsigned int k : surface)
          if (distance_to_chosen(k) > distance_to_chosen(best))
            best = k;
        chosen.push_back(best);
      }
    for (const unsigned int k : chosen)
      kind[k] = Row::fixed;
  }



  template <int dim>
  void
  CorrectionSystem<dim>::fix_mirrored_null_space(
    const std::vector<unsigned int> &surface,
    const bool                       first_order_identity)
  {
    // The null space of the full body, alpha^k = A X^k + b (A = 0 with
    // only the zeroth-order identity), keeps the fields that are their
    // own mirror images: b_i = 0 and A_ij = 0 for i != j where i or j is
    // the axis of a plane. Each is removed by fixing one component of
    // one particle off the planes (an equation row becomes e_c . alpha^k
    // = 0), chosen by QR with column pivoting over the components of the
    // candidates, so that the fixed values determine the null-space part.
    std::vector<bool> normal_axis(dim, false);
    Point<dim>        on_planes; // a point on every plane
    for (unsigned int p = 0; p < particles->n_mirror_planes(); ++p)
      {
        normal_axis[particles->mirror_plane_axis(p)] = true;
        on_planes[particles->mirror_plane_axis(p)] =
          particles->mirror_plane_offset(p);
      }
    // null vectors: (i, j) for A_ij (j = dim: b_i)
    std::vector<std::pair<unsigned int, unsigned int>> null_vectors;
    for (unsigned int i = 0; i < dim; ++i)
      {
        if (!normal_axis[i])
          null_vectors.emplace_back(i, dim);
        if (first_order_identity)
          for (unsigned int j = 0; j < dim; ++j)
            if (i == j || (!normal_axis[i] && !normal_axis[j]))
              null_vectors.emplace_back(i, j);
      }
    // candidates: the components of the surface particles off the planes
    // with a full set of equations
    std::vector<std::pair<unsigned int, unsigned int>> entries;
    std::vector<std::vector<double>>                   columns;
    for (const unsigned int k : surface)
      if (particles->on_mirror_planes(k) == 0 && kind[k] == Row::interior)
        for (unsigned int c = 0; c < dim; ++c)
          {
            const Tensor<1, dim> X = particles->position(k) - on_planes;
            std::vector<double>  column;
            for (const auto &[i, j] : null_vectors)
              column.push_back(i != c ? 0. : (j == dim ? 1. : X[j]));
            entries.emplace_back(k, c);
            columns.push_back(column);
          }
    AssertThrow(entries.size() >= null_vectors.size(),
                ExcMessage("The VC correction needs more particles on the "
                           "boundary of the meshfree region, off the "
                           "symmetry planes."));
    for (unsigned int picked = 0; picked < null_vectors.size(); ++picked)
      {
        unsigned int best = 0;
        double       norm = -1;
        for (unsigned int e = 0; e < columns.size(); ++e)
          {
            double s = 0;
            for (const double v : columns[e])
              s += v * v;
            if (s > norm)
              norm = s, best = e;
          }
        AssertThrow(norm > 1e-20, ExcInternalError());
        std::vector<double> q = columns[best];
        for (double &v : q)
          v /= std::sqrt(norm);
        for (auto &column : columns)
          {
            double dot = 0;
            for (unsigned int r = 0; r < q.size(); ++r)
              dot += q[r] * column[r];
            for (unsigned int r = 0; r < q.size(); ++r)
              column[r] -= dot * q[r];
          }
        const auto [k, c] = entries[best];
        kind[k]           = Row::tangential;
        R[k][c]           = Tensor<1, dim>();
        constraint[k][c]  = Point<dim>::unit_vector(c);
      }
  }



  template void
  CorrectionSystem<2>::classify_rows();
  template void
  CorrectionSystem<3>::classify_rows();
} // namespace pg
