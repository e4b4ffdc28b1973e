#ifndef pg_dofs_memory_estimate_h
#define pg_dofs_memory_estimate_h

#include <pg/base/formulation_code.h>
#include <pg/base/global.h>
#include <pg/elements/discretization_parameters.h>
#include <pg/mesh/geometry_parameters.h>
#include <pg/mesh/mesh_generator.h>

#include <string>

// The memory a run will need, estimated before the mesh is built (issue 45,
// item 1: 'Subdivisions = 200000, 100000' allocated until the kernel ended
// the process). doc/memory.md, "Estimate before the run", describes the
// formula and its figures.

namespace pg
{
  /** What estimate_memory() found. */
  struct MemoryEstimate
  {
    /** Vertices x unknowns per vertex (dim, plus the nodal fields). */
    double n_dofs = 0;
    /** Particles within a horizon of a particle (a family), lattice count. */
    double family_size = 0;
    /** Matrix nonzeros per row: Q1 3^dim x fields; PG particles within 2
     * horizons x fields. */
    double nonzeros_per_row = 0;
    /** The bytes per DoF used (the measured figure, scaled). */
    double bytes_per_dof = 0;
    /** Libraries and process (about 180 MB measured) + DoFs x bytes/DoF. */
    double bytes = 0;
  };

  /**
   * The number of points of the lattice Z^dim within the distance
   * @p radius of the origin (the origin included).
   */
  double
  lattice_points_in_ball(const unsigned int dim, const double radius);

  /**
   * The memory of a run of @p formulation on a mesh of @p size, as on one
   * rank: 180 MB plus n_dofs x bytes per DoF. The bytes per DoF are those
   * measured (doc/memory.md): Q1 1.66 kB (2-D) / 4.39 kB (3-D); PG at
   * 'Horizon factor = 1.51' 7.24 kB / 13.47 kB, scaled for other horizons
   * with the nonzeros per row (particles within two horizons). PG figures
   * are used for every DoF of a code that is not FEM (coupled models too:
   * an upper bound). @p horizon_extra is added to the horizon factor
   * (CPD with partial volumes: 0.5).
   */
  template <int dim>
  MemoryEstimate
  estimate_memory(const Mesh::MeshSize             &size,
                  const FormulationCode            &formulation,
                  const Parameters::Discretization &discretization,
                  const double                      horizon_extra = 0.);

  /**
   * The physical memory of this machine in bytes: MemTotal of
   * /proc/meminfo, else sysconf(_SC_PHYS_PAGES) x page size; 0 if neither
   * is known.
   */
  double
  physical_memory();

  /**
   * Throws ExcBadParameter naming the entry that makes the mesh large
   * ('Geometry/Subdivisions', 'Geometry/Global refinement' or
   * 'Geometry/File name'), the mesh, the estimate and @p memory, if
   * @p estimate exceeds @p memory (bytes; 0: unknown, no check).
   */
  void
  check_memory(const Parameters::Geometry &geometry,
               const Mesh::MeshSize       &size,
               const std::string          &formulation,
               const MemoryEstimate       &estimate,
               const double                memory);
} // namespace pg

#endif
