// The share of its volume that the PBG Unl family quadrature (eq. 4.30,
// weight V^k V^j / V^{H^k} at member j of family k) gives each particle
// (issue 45, deliverable 5): s_j = sum over the families k containing j
// of V^k / V^{H^k}. The weights of all points add up to the body's volume
// exactly (sum_k V^k), but they are redistributed: a particle on the
// surface belongs to fewer families, and the truncated families near the
// surface have smaller V^{H^k}. The bending stiffness of a beam rests on
// its outer fibres, so the measure that matters there is the second
// moment of the section as the quadrature sees it, I_h = sum_j s_j V^j
// (y_j - c)^2, against the exact I = sum_j V^j (y_j - c)^2 of the lumped
// volumes (c the centre line).
//
// A strip 10 x 1 with 4, 8 and 16 cells through the thickness (the
// slender cantilever's resolutions), horizons 1.51 h, 2.01 h and 2.51 h.
// Printed: the mean s of the particles on the top and bottom surface (not
// at the ends), of the first row inside and of the middle row, and
// I_h / I. The sum of all s_j V^j over the volume is checked to be 1.

#include <pg/base/formulation_code.h>
#include <pg/elements/family_elements.h>

#include <deal.II/dofs/dof_handler.h>
#include <deal.II/fe/fe_q.h>
#include <deal.II/fe/fe_system.h>
#include <deal.II/grid/grid_generator.h>
#include <deal.II/grid/tria.h>

#include "../tests.h"

using namespace pg;

void
test(const unsigned int n_thickness, const double horizon_factor)
{
  Triangulation<2> tria;
  GridGenerator::subdivided_hyper_rectangle(tria,
                                            {10 * n_thickness, n_thickness},
                                            Point<2>(0, 0),
                                            Point<2>(10, 1));
  FESystem<2>   fe(FE_Q<2>(1), 2);
  DoFHandler<2> dof_handler(tria);
  dof_handler.distribute_dofs(fe);
  ParticleSet<2> particles;
  particles.reinit(dof_handler, std::vector<bool>(tria.n_active_cells(), true));
  FamilySet<2> families;
  families.reinit(particles, horizon_factor, 0);
  FamilyElements<2> elements(particles,
                             families,
                             parse_formulation_code("PBG Unl noBC"),
                             ShapeFunctions::Base::mte1,
                             1.);
  elements.initialize();

  const unsigned int  n = particles.n_particles();
  std::vector<double> s(n, 0.);
  QuadratureTable<2>  table;
  for (unsigned int k = 0; k < n; ++k)
    {
      elements.build(k, table);
      const auto members = families.members(k);
      AssertDimension(table.n_points(), members.size());
      for (unsigned int q = 0; q < members.size(); ++q)
        s[members[q]] += table.weights[q];
    }
  const double h     = 1. / n_thickness;
  double       total = 0, I_h = 0, I = 0;
  double       surface = 0, first_row = 0, middle = 0;
  unsigned int n_surface = 0, n_first = 0, n_middle = 0;
  for (unsigned int j = 0; j < n; ++j)
    {
      const Point<2> &X = particles.position(j);
      const double    V = particles.volume(j);
      total += s[j];
      I_h += s[j] * (X[1] - 0.5) * (X[1] - 0.5);
      I += V * (X[1] - 0.5) * (X[1] - 0.5);
      s[j] /= V;
      // away from the ends (three horizons)
      if (X[0] < 3 * horizon_factor * h || X[0] > 10 - 3 * horizon_factor * h)
        continue;
      const double row = std::min(X[1], 1 - X[1]) / h;
      if (row < 0.5)
        surface += s[j], ++n_surface;
      else if (row < 1.5)
        first_row += s[j], ++n_first;
      else if (std::abs(X[1] - 0.5) < 0.5 * h)
        middle += s[j], ++n_middle;
    }
  std::ostringstream line;
  line << std::fixed << std::setprecision(3) << n_thickness
       << " through the thickness, horizon " << std::setprecision(2)
       << horizon_factor << " h: s surface " << std::setprecision(3)
       << surface / n_surface << ", first row " << first_row / n_first
       << ", middle " << middle / n_middle << ", I_h / I " << I_h / I;
  deallog << line.str() << std::endl;
  print_bound("  |sum of the weights / volume - 1|",
              total / particles.total_volume() - 1.,
              1e-12);
}



int
main()
{
  initlog();
  for (const double horizon_factor : {1.51, 2.01, 2.51})
    for (const unsigned int n_thickness : {4u, 8u, 16u})
      test(n_thickness, horizon_factor);
}
