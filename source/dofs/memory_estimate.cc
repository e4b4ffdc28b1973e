#include <pg/base/exceptions.h>
#include <pg/dofs/memory_estimate.h>

#include <deal.II/base/numbers.h>

#include <unistd.h>

#include <algorithm>
#include <cmath>
#include <fstream>
#include <iomanip>
#include <sstream>
#include <string>

namespace pg
{
  namespace
  {
    /** Libraries and process of a tiny run (181-185 MB, doc/memory.md). */
    constexpr double base_bytes = 180e6;

    /** Measured bytes per DoF (doc/memory.md). */
    constexpr double q1_bytes_per_dof[2] = {1.66e3, 4.39e3};
    /** ... of P1 on triangles (not measured: Q1's) and tetrahedra (the 3-D
     * Cook membrane at 299,859 DoFs, doc/benchmarks/simplex_cost.md; Q1
     * measured 4.33 kB in the same run). */
    constexpr double p1_bytes_per_dof[2] = {1.66e3, 4.63e3};
    /** ... of PG everywhere at 'Horizon factor = 1.51'. */
    constexpr double pg_bytes_per_dof[2]  = {7.24e3, 13.47e3};
    constexpr double pg_reference_horizon = 1.51;

    /** @p x with 3 significant digits. */
    std::string
    rounded(const double x)
    {
      std::ostringstream s;
      s << std::setprecision(3) << x;
      return s.str();
    }
  } // namespace



  double
  lattice_points_in_ball(const unsigned int dim, const double radius)
  {
    if (radius < 0)
      return 0;
    // beyond a few hundred thousand points the volume is exact enough
    if (radius > 40.)
      return dim == 2 ? numbers::PI * radius * radius :
                        4. / 3. * numbers::PI * radius * radius * radius;
    const int    n     = static_cast<int>(std::floor(radius));
    const double r2    = radius * radius * (1. + 1e-12);
    double       count = 0;
    for (int i = -n; i <= n; ++i)
      for (int j = -n; j <= n; ++j)
        if (dim == 2)
          count += (i * i + j * j <= r2);
        else
          for (int k = -n; k <= n; ++k)
            count += (i * i + j * j + k * k <= r2);
    return count;
  }



  template <int dim>
  MemoryEstimate
  estimate_memory(const Mesh::MeshSize             &size,
                  const FormulationCode            &formulation,
                  const Parameters::Discretization &discretization,
                  const double                      horizon_extra)
  {
    MemoryEstimate     estimate;
    const unsigned int fields = dim + formulation.n_nodal_fields();
    estimate.n_dofs           = size.n_vertices * fields;
    if (formulation.method == FormulationCode::Method::fem)
      {
        estimate.family_size      = 0;
        estimate.nonzeros_per_row = std::pow(3., dim) * fields;
        estimate.bytes_per_dof    = q1_bytes_per_dof[dim - 2];
        if (size.simplex && size.edge_neighbours > 0)
          {
            // P1: a node couples to its edge neighbours only, but the mesh
            // has 5 to 6 cells per vertex (3-D): the bytes per DoF are
            // those measured on tetrahedra
            estimate.nonzeros_per_row = (size.edge_neighbours + 1.) * fields;
            estimate.bytes_per_dof    = p1_bytes_per_dof[dim - 2];
          }
      }
    else
      {
        // the horizon in units of the spacing (on simplex meshes the mean
        // edge is a little longer than the lattice spacing: a tetrahedral
        // family at 1.51 holds 1.2 to 1.3 times the lattice count,
        // dofs/memory_estimate_simplex_01, doc/benchmarks/simplex_cost.md;
        // within the accuracy of the estimate)
        double horizon = discretization.horizon_factor + horizon_extra;
        if (discretization.horizon > 0. && size.spacing > 0.)
          horizon = discretization.horizon / size.spacing + horizon_extra;
        if (discretization.nearest_neighbours > 0)
          // the radius of a ball that holds the N neighbours and the master
          horizon = std::pow((discretization.nearest_neighbours + 1.) /
                               (dim == 2 ? numbers::PI : 4. / 3. * numbers::PI),
                             1. / dim);
        estimate.family_size = lattice_points_in_ball(dim, horizon);
        // two particles share a row entry if some family holds both: the
        // particles within two horizons
        const double coupled = lattice_points_in_ball(dim, 2. * horizon);
        const double reference =
          lattice_points_in_ball(dim, 2. * pg_reference_horizon);
        estimate.nonzeros_per_row = coupled * fields;
        estimate.bytes_per_dof    = pg_bytes_per_dof[dim - 2] *
                                 std::max(coupled, 1.) / reference * fields /
                                 dim;
      }
    estimate.bytes = base_bytes + estimate.n_dofs * estimate.bytes_per_dof;
    return estimate;
  }



  double
  physical_memory()
  {
    std::ifstream meminfo("/proc/meminfo");
    std::string   name, unit;
    double        value = 0;
    while (meminfo >> name >> value >> unit)
      if (name == "MemTotal:")
        return value * (unit == "kB" ? 1024. : 1.);
    const long pages = sysconf(_SC_PHYS_PAGES);
    const long page  = sysconf(_SC_PAGE_SIZE);
    return (pages > 0 && page > 0) ? static_cast<double>(pages) * page : 0.;
  }



  void
  check_memory(const Parameters::Geometry &geometry,
               const Mesh::MeshSize       &size,
               const std::string          &formulation,
               const MemoryEstimate       &estimate,
               const double                memory)
  {
    if (!geometry.memory_check || memory <= 0. || estimate.bytes <= memory)
      return;

    // the entry that makes the mesh large
    const double refinement_factor = size.n_cells / size.n_coarse_cells;
    std::string  entry, value, context;
    std::string  subdivisions;
    for (const unsigned int s : geometry.subdivisions)
      subdivisions += (subdivisions.empty() ? "" : ", ") + std::to_string(s);
    const std::string refinement = std::to_string(geometry.global_refinement);
    if (geometry.mesh == "file")
      {
        if (geometry.global_refinement > 0)
          {
            entry   = "Geometry/Global refinement";
            value   = refinement;
            context = "with the " + rounded(size.n_coarse_cells) +
                      " cells of the mesh file '" + geometry.file_name + "'";
          }
        else
          {
            entry   = "Geometry/File name";
            value   = geometry.file_name;
            context = "with 'Global refinement = 0'";
          }
      }
    else if (geometry.mesh == "plate with hole" ||
             refinement_factor > size.n_coarse_cells)
      {
        entry   = "Geometry/Global refinement";
        value   = refinement;
        context = "with the " + rounded(size.n_coarse_cells) +
                  " cells of the coarse '" + geometry.mesh + "'";
      }
    else
      {
        entry   = "Geometry/Subdivisions";
        value   = subdivisions;
        context = "with 'Global refinement = " + refinement + "'";
      }

    std::ostringstream why;
    why << context << " the mesh would have " << rounded(size.n_cells)
        << " cells and " << rounded(estimate.n_dofs)
        << " DoFs, and the formulation <" << formulation << "> an estimated "
        << rounded(estimate.bytes / 1e9) << " GB of memory ("
        << rounded(estimate.bytes_per_dof / 1e3) << " kB per DoF at about "
        << rounded(estimate.nonzeros_per_row)
        << " matrix nonzeros per row, doc/memory.md), more than the "
        << rounded(memory / 1e9)
        << " GB of this machine (MemTotal in /proc/meminfo). Correct the "
           "entry, or set 'Memory check = false' in subsection 'Geometry' "
           "if you know that the run fits.";
    AssertThrow(false, ExcBadParameter(entry, value, why.str()));
  }



  template MemoryEstimate
  estimate_memory<2>(const Mesh::MeshSize &,
                     const FormulationCode &,
                     const Parameters::Discretization &,
                     const double);
  template MemoryEstimate
  estimate_memory<3>(const Mesh::MeshSize &,
                     const FormulationCode &,
                     const Parameters::Discretization &,
                     const double);
} // namespace pg
