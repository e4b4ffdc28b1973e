#ifndef pg_tests_geometry_fixture_h
#define pg_tests_geometry_fixture_h

// The 'Geometry' parameters of a test from the entries of that subsection,
// as a parameter file would give them.

#include <pg/mesh/geometry_parameters.h>

#include <deal.II/base/parameter_handler.h>

#include <string>

/** The Geometry parameters from the entries @p entries of its subsection. */
inline pg::Parameters::Geometry
geometry_parameters(const std::string &entries)
{
  dealii::ParameterHandler prm;
  pg::Parameters::Geometry::declare_parameters(prm);
  prm.parse_input_from_string("subsection Geometry\n" + entries + "end\n");
  pg::Parameters::Geometry parameters;
  parameters.parse_parameters(prm);
  return parameters;
}

#endif
