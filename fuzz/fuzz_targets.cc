#include "fuzz_targets.h"

#include <pg/base/formulation_code.h>
#include <pg/constraints/boundary_condition_parameters.h>
#include <pg/mesh/meshfree_region.h>
#include <pg/postprocess/output_parameters.h>

#include <deal.II/base/exceptions.h>
#include <deal.II/base/parameter_handler.h>

#include <string>

namespace pg
{
  namespace Fuzz
  {
    void
    formulation_code(const std::uint8_t *data, const std::size_t size)
    {
      const std::string code(reinterpret_cast<const char *>(data), size);
      try
        {
          const FormulationCode formulation = parse_formulation_code(code);
          // what a run prints of it
          (void)formulation.method_name();
          (void)formulation.notice();
        }
      catch (const dealii::ExceptionBase &)
        {
          // a message for the user
        }
    }



    namespace
    {
      template <int dim>
      void
      parse_entry(const unsigned int entry, const std::string &value)
      {
        struct Entry
        {
          const char *subsection;
          const char *name;
        };
        static const Entry entries[] = {
          {"Boundary conditions", "Dirichlet"},
          {"Boundary conditions", "Fixed points"},
          {"Boundary conditions", "Dirichlet boxes"},
          {"Boundary conditions", "Symmetry"},
          {"Boundary conditions", "Neumann"},
          {"Boundary conditions", "Neumann stress"},
          {"Output", "Points"},
          {"Output", "Lines"},
          {"Geometry", "Meshfree region"},
          {"Geometry", "Hole"}};
        const Entry &e = entries[entry % (sizeof(entries) / sizeof(Entry))];
        if (std::string(e.subsection) == "Geometry")
          {
            (void)Mesh::MeshfreeRegion<dim>::parse(value,
                                                   std::string("Geometry/") +
                                                     e.name);
            return;
          }
        dealii::ParameterHandler prm;
        Parameters::BoundaryConditions::declare_parameters(prm);
        Parameters::Output::declare_parameters(prm);
        prm.enter_subsection(e.subsection);
        prm.set(e.name, value);
        prm.leave_subsection();
        if (std::string(e.subsection) == "Output")
          Parameters::Output().parse_parameters(prm, dim);
        else
          Parameters::BoundaryConditions().parse_parameters(prm, dim);
      }
    } // namespace



    void
    parameter_lists(const std::uint8_t *data, const std::size_t size)
    {
      if (size < 2)
        return;
      const std::string value(reinterpret_cast<const char *>(data) + 2,
                              size - 2);
      try
        {
          if (data[1] % 2 == 0)
            parse_entry<2>(data[0], value);
          else
            parse_entry<3>(data[0], value);
        }
      catch (const dealii::ExceptionBase &)
        {
          // a message for the user
        }
    }
  } // namespace Fuzz
} // namespace pg
