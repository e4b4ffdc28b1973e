#ifndef pg_postprocess_setup_report_h
#define pg_postprocess_setup_report_h

#include <pg/base/formulation_code.h>
#include <pg/base/global.h>
#include <pg/base/parameters.h>
#include <pg/dofs/discretization.h>
#include <pg/postprocess/run_summary.h>

#include <deal.II/base/conditional_ostream.h>
#include <deal.II/base/types.h>

#include <functional>
#include <map>
#include <string>
#include <vector>

namespace pg
{
  namespace Postprocess
  {
    /**
     * The echo of what a run understood, printed at the end of the set-up
     * (no wall times: the tests compare it): the formulation, the CPD
     * constants or the material, cells, particles, horizon, family sizes,
     * how much of the Neumann area the test functions see, the VC
     * residuals and factors, DoFs and matrix nonzeros.
     *
     * @p particle_traction_area is the traction loading in effect ('exact
     * stress', 'test functions' or 'geometry'); @p is_neumann tells the
     * Neumann boundary ids and @p boundary_area_weights are the areas c_b
     * of the boundary parts at every particle seen by the test functions
     * (boundary_area_weights()).
     */
    template <int dim>
    void
    print_setup_report(
      const ConditionalOStream             &pcout,
      const Parameters::AllParameters<dim> &prm,
      const FormulationCode                &formulation,
      const Discretization<dim>            &discretization,
      const RunSummary                     &summary,
      const std::string                    &particle_traction_area,
      const std::function<bool(const types::boundary_id)> &is_neumann,
      const std::vector<std::map<types::boundary_id, double>>
        &boundary_area_weights);
  } // namespace Postprocess
} // namespace pg

#endif
