#include <pg/postprocess/output.h>
#include <pg/postprocess/postprocessors.h>
#include <pg/postprocess/run_summary.h>

#include <deal.II/base/patterns.h>
#include <deal.II/base/quadrature_lib.h>
#include <deal.II/fe/fe_values.h>

#include <algorithm>
#include <cmath>
#include <fstream>
#include <iomanip>

namespace pg
{
  namespace Postprocess
  {
    template <int dim>
    void
    NodalStresses<dim>::execute(const ProblemView<dim> &,
                                const Step &,
                                TableHandler &,
                                RunSummary &)
    {}



    template <int dim>
    void
    NodalStresses<dim>::finalize(const ProblemView<dim> &view,
                                 const Step &,
                                 TableHandler &,
                                 RunSummary &summary)
    {
      write(view, view.particle_deformation_gradients(), summary);
    }



    template <int dim>
    void
    NodalStresses<dim>::write(const ProblemView<dim>            &view,
                              const std::vector<Tensor<2, dim>> &particle_F,
                              RunSummary                        &summary)
    {
      const auto &prm           = *view.parameters;
      const auto &triangulation = *view.triangulation;
      const auto &particles     = *view.particles;
      const auto &material      = *view.material;
      const auto &meshfree      = *view.meshfree;
      // every FE cell's vertex stresses: from the gathered displacement
      const Vector<double> u_all = view.gather_displacement();
      // a material with history: the committed state of the Gauss point at
      // each corner (of the one point of a simplex), of each particle's
      // family at its point 0
      const CommittedStates states = view.committed_states(); // collective

      const unsigned int        n_vertices = triangulation.n_vertices();
      std::vector<Tensor<2, 3>> fe_stress(n_vertices);
      std::vector<unsigned int> fe_cells(n_vertices, 0);
      // The nodal quadrature's points are the vertices in deal.II's
      // numbering (QTrapezoid on hypercubes). At the
      // corner of a strongly distorted cell F can be inverted although it
      // is not at the Gauss points the solution was computed with: there
      // the cell contributes its centre's stress (and nothing if F is
      // inverted at the centre too).
      const ReferenceCell        &kind = view.cells->reference_cell();
      FEValues<dim>               fe_values(view.cells->mapping(),
                              *view.fe,
                              kind.get_nodal_type_quadrature<dim>(),
                              update_gradients);
      FEValues<dim>               centre_values(view.cells->mapping(),
                                  *view.fe,
                                  kind.get_midpoint_quadrature<dim>(),
                                  update_gradients);
      std::vector<Tensor<2, dim>> gradients(fe_values.n_quadrature_points),
        centre_gradient(1);
      unsigned int n_centre = 0, n_skipped = 0;
      for (const auto &cell : view.dof_handler->active_cell_iterators())
        if (!meshfree[cell->active_cell_index()])
          {
            fe_values.reinit(cell);
            fe_values[FEValuesExtractors::Vector(0)]
              .get_function_gradients(u_all, gradients);
            for (const unsigned int v : cell->vertex_indices())
              {
                Tensor<2, dim> F = unit_symmetric_tensor<dim>() + gradients[v];
                if (determinant(F) <= 0)
                  {
                    centre_values.reinit(cell);
                    centre_values[FEValuesExtractors::Vector(0)]
                      .get_function_gradients(u_all, centre_gradient);
                    F = unit_symmetric_tensor<dim>() + centre_gradient[0];
                    if (determinant(F) <= 0)
                      {
                        ++n_skipped;
                        continue;
                      }
                    ++n_centre;
                  }
                fe_stress[cell->vertex_index(v)] +=
                  states.n_material == 0 ?
                    material.cauchy_stress(F) :
                    material.cauchy_stress_with_state(
                      F,
                      states.cell(cell->active_cell_index(),
                                  states.points_per_cell == cell->n_vertices() ?
                                    v :
                                    0));
                ++fe_cells[cell->vertex_index(v)];
              }
          }
      if (n_centre + n_skipped > 0)
        *view.pcout << "  nodal stresses: F is inverted (J <= 0) at "
                    << n_centre + n_skipped
                    << " corner(s) of distorted FE cells, where the Gauss "
                       "points are not; the cell's centre value is used "
                       "there (inverted at the centre too: "
                    << n_skipped << ")" << std::endl;
      std::vector<int> particle_at(n_vertices, -1);
      for (unsigned int k = 0; k < particles.n_particles(); ++k)
        particle_at[particles.vertex(k)] = k;

      summary.max_interface_stress_jump = 0;
      for (unsigned int k = 0; k < particles.n_particles(); ++k)
        if (fe_cells[particles.vertex(k)] > 0)
          summary.max_interface_stress_jump =
            std::max(summary.max_interface_stress_jump,
                     std::abs(cauchy_stress_or_nan(material,
                                                   particle_F[k],
                                                   states.particle(k))[0][0] -
                              fe_stress[particles.vertex(k)][0][0] /
                                fe_cells[particles.vertex(k)]));

      // (IUnlP0: the material is the isochoric part, and the pressure of
      // the particle's family, a DoF, adds p I; no FE cells. Its exact
      // stress would need the exact pressure, which the exact displacement
      // does not give: not written.)
      const bool incompressible = view.formulation->incompressible();
      const bool with_exact     = prm.compute_errors && !incompressible;
      const auto nodal_stress   = [&](const unsigned int vertex) {
        if (particle_at[vertex] < 0)
          return fe_cells[vertex] > 0 ?
                     Tensor<2, 3>(fe_stress[vertex] / fe_cells[vertex]) :
                     Tensor<2, 3>();
        const unsigned int k = particle_at[vertex];
        Tensor<2, 3>       sigma =
          cauchy_stress_or_nan(material, particle_F[k], states.particle(k));
        if (incompressible)
          sigma += u_all[particles.dof(k, dim)] *
                   Tensor<2, 3>(unit_symmetric_tensor<3>());
        return sigma;
      };
      const auto exact_stress = [&](const Point<dim> &p) {
        return material.cauchy_stress(unit_symmetric_tensor<dim>() +
                                      view.exact_displacement_gradient(p));
      };
      const auto in_plane = [](const Tensor<2, 3> &sigma) {
        std::vector<double> values;
        for (unsigned int i = 0; i < dim; ++i)
          for (unsigned int j = 0; j < dim; ++j)
            values.push_back(sigma[i][j]);
        return values;
      };

      // the stress at the vertex nearest each named point
      summary.point_stresses.clear();
      summary.point_exact_stresses.clear();
      const auto &vertices = triangulation.get_vertices();
      const auto &used     = triangulation.get_used_vertices();
      for (const auto &[name, coordinates] : prm.output.points)
        {
          Point<dim> p;
          for (unsigned int c = 0; c < dim; ++c)
            p[c] = coordinates[c];
          unsigned int nearest = numbers::invalid_unsigned_int;
          for (unsigned int v = 0; v < vertices.size(); ++v)
            if (used[v] && (particle_at[v] >= 0 || fe_cells[v] > 0) &&
                (nearest == numbers::invalid_unsigned_int ||
                 p.distance_square(vertices[v]) <
                   p.distance_square(vertices[nearest])))
              nearest = v;
          if (nearest == numbers::invalid_unsigned_int)
            continue;
          summary.point_stresses.emplace_back(name,
                                              in_plane(nodal_stress(nearest)));
          if (with_exact)
            summary.point_exact_stresses.emplace_back(name,
                                                      in_plane(exact_stress(
                                                        vertices[nearest])));
        }

      const auto &ids = prm.output.stress_boundaries;
      if (!view.root || ids.empty())
        return;
      std::ofstream table(prm.output.directory +
                          "/stress_along_boundaries.txt");
      table << "# Cauchy stress at the vertices of the boundaries "
            << Patterns::Tools::Convert<std::vector<int>>::to_string(
                 std::vector<int>(ids.begin(), ids.end()))
            << " (particles: the particle value; FE vertices: the average of "
               "the adjacent cells)\n# boundary_id x y"
            << (dim == 3 ? " z" : "") << " sigma_xx sigma_yy sigma_xy"
            << (with_exact ? " exact_xx exact_yy exact_xy" : "") << " side\n"
            << std::setprecision(8);
      std::vector<bool> written(n_vertices, false);
      for (const auto &cell : triangulation.active_cell_iterators())
        for (const unsigned int f : cell->face_indices())
          if (cell->face(f)->at_boundary() &&
              std::find(ids.begin(), ids.end(), cell->face(f)->boundary_id()) !=
                ids.end())
            for (const unsigned int v : cell->face(f)->vertex_indices())
              {
                const unsigned int vertex = cell->face(f)->vertex_index(v);
                if (written[vertex])
                  continue;
                written[vertex]          = true;
                const bool         pg    = particle_at[vertex] >= 0;
                const Tensor<2, 3> sigma = nodal_stress(vertex);
                table << static_cast<int>(cell->face(f)->boundary_id()) << " "
                      << cell->face(f)->vertex(v) << " " << sigma[0][0] << " "
                      << sigma[1][1] << " " << sigma[0][1];
                if (with_exact)
                  {
                    const Tensor<2, 3> exact =
                      exact_stress(cell->face(f)->vertex(v));
                    table << " " << exact[0][0] << " " << exact[1][1] << " "
                          << exact[0][1];
                  }
                table << (pg ? " PG\n" : " FE\n");
              }
    }



    template class NodalStresses<2>;
    template class NodalStresses<3>;
  } // namespace Postprocess
} // namespace pg
