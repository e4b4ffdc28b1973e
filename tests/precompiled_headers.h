// The headers that most tests include, compiled once per build directory
// into a precompiled header (tests/CMakeLists.txt, pg_pickup_tests()):
// parsing them took about 23 of the 28 s that each Debug test source
// needed to compile. Only deal.II's and pg's public headers belong here,
// never a test's own fixture.
#ifndef pg_tests_precompiled_headers_h
#define pg_tests_precompiled_headers_h

#include <pg/base/formulation_code.h>
#include <pg/base/linear_algebra.h>
#include <pg/base/parameters.h>
#include <pg/elements/family_elements.h>
#include <pg/elements/quadrature_table.h>
#include <pg/families/family_set.h>
#include <pg/materials/material.h>
#include <pg/mesh/particle_set.h>
#include <pg/problem.h>
#include <pg/shape_functions/shape_functions.h>

#include <deal.II/base/conditional_ostream.h>
#include <deal.II/base/exceptions.h>
#include <deal.II/base/function.h>
#include <deal.II/base/function_parser.h>
#include <deal.II/base/logstream.h>
#include <deal.II/base/mpi.h>
#include <deal.II/base/multithread_info.h>
#include <deal.II/base/parameter_handler.h>
#include <deal.II/base/quadrature_lib.h>
#include <deal.II/base/utilities.h>
#include <deal.II/distributed/shared_tria.h>
#include <deal.II/dofs/dof_handler.h>
#include <deal.II/dofs/dof_tools.h>
#include <deal.II/fe/fe_q.h>
#include <deal.II/fe/fe_system.h>
#include <deal.II/fe/fe_values.h>
#include <deal.II/fe/mapping_q1.h>
#include <deal.II/grid/grid_generator.h>
#include <deal.II/grid/grid_tools.h>
#include <deal.II/grid/tria.h>
#include <deal.II/lac/affine_constraints.h>
#include <deal.II/lac/dynamic_sparsity_pattern.h>
#include <deal.II/lac/full_matrix.h>
#include <deal.II/lac/sparse_matrix.h>
#include <deal.II/lac/sparsity_pattern.h>
#include <deal.II/lac/vector.h>
#include <deal.II/numerics/vector_tools.h>

#endif
