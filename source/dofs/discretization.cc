#include <pg/base/exceptions.h>
#include <pg/dofs/discretization.h>
#include <pg/dofs/memory_estimate.h>
#include <pg/dofs/relevant_dofs.h>
#include <pg/mesh/mesh_generator.h>
#include <pg/shape_functions/shape_functions.h>

#include <deal.II/base/exceptions.h>
#include <deal.II/base/mpi.h>
#include <deal.II/base/timer.h>

#include <algorithm>

namespace pg
{
  namespace
  {
    /**
     * Finite element cells on triangles and tetrahedra are P1 (issue 49):
     * the mixed codes' cells would be P1-P0 (one pressure per simplex),
     * which locks, so a mixed formulation with finite element cells on a
     * simplex mesh (FEM Q1P0, or a mixed PG code with a 'Meshfree region'
     * other than all) stops here, naming the parameter.
     */
    template <int dim>
    void
    check_simplex_support(const Parameters::Geometry &geometry,
                          const FormulationCode      &formulation,
                          const LinearCells<dim>     &cells,
                          const std::vector<bool>    &meshfree)
    {
      if (!formulation.mixed() || std::all_of(meshfree.begin(),
                                              meshfree.end(),
                                              [](const bool b) { return b; }))
        return;
      // a generated mesh split by 'Cells = simplices', or a mesh file
      const bool        split = (geometry.mesh != "file");
      const std::string mesh =
        split ? "'Cells = simplices' (subsection 'Geometry') splits the "
                "mesh into " +
                  cells.name() + ", and " :
                "the mesh file " + geometry.file_name +
                  " ('File name' in subsection 'Geometry') holds " +
                  cells.name() + ", and ";
      const std::string locks =
        "the mixed finite element cells on them would be P1-P0 (a constant "
        "pressure per " +
        std::string(dim == 2 ? "triangle" : "tetrahedron") +
        "), which locks: pg does not build them. ";
      const std::string recombine =
        (split ? std::string("or set 'Cells = hypercubes'") :
                 "or recombine the mesh into " +
                   std::string(dim == 2 ? "quadrilaterals" : "hexahedra") +
                   " (Gmsh: 'Mesh.RecombineAll = 1')") +
        ", where the mixed cells are " +
        std::string(dim == 2 ? "Q1P0." : "H1P0.");
      AssertThrow(formulation.method != FormulationCode::Method::fem,
                  ExcBadParameter("Discretization/Formulation",
                                  formulation.text,
                                  mesh + locks +
                                    "Choose 'FEM' (P1 cells), a mixed PG "
                                    "formulation (e.g. 'VCBCPBG V5sn UnlP0') "
                                    "with 'Meshfree region = all' in "
                                    "subsection 'Geometry', " +
                                    recombine));
      AssertThrow(false,
                  ExcBadParameter("Geometry/Meshfree region",
                                  geometry.meshfree_region,
                                  mesh + locks + "The mixed formulation '" +
                                    formulation.text +
                                    "' ('Formulation' in subsection "
                                    "'Discretization') runs on this mesh "
                                    "with 'Meshfree region = all'; couple a "
                                    "displacement formulation (e.g. "
                                    "'VCBCPBG V5sn Unl') to P1 cells, " +
                                    recombine));
    }
  } // namespace



  template <int dim>
  Discretization<dim>::Discretization(const MPI_Comm mpi_communicator,
                                      const Parameters::Geometry &geometry)
    : geometry(geometry)
    , triangulation(mpi_communicator,
                    Triangulation<dim>::none,
                    false,
                    parallel::shared::Triangulation<dim>::partition_metis)
  {}



  template <int dim>
  void
  Discretization<dim>::reinit(
    const FormulationCode                           &formulation,
    const Parameters::Discretization                &discretization_parameters,
    const Parameters::Cpd                           &cpd_parameters,
    const std::function<bool(const CellIterator &)> &loaded_by_face_traction,
    const std::vector<types::boundary_id>           &mirror_symmetry_ids)
  {
    Timer timer;
    // the memory check, before the mesh is built (issue 45, item 1); every
    // rank compares with the smallest memory of the ranks, so that all of
    // them stop alike
    const double memory =
      Utilities::MPI::min(physical_memory(), triangulation.get_communicator());
    const auto check_size = [&](const Mesh::MeshSize &size) {
      const bool cpd_partial =
        formulation.method == FormulationCode::Method::cpd &&
        cpd_parameters.partial_volumes;
      check_memory(geometry,
                   size,
                   formulation.text,
                   estimate_memory<dim>(size,
                                        formulation,
                                        discretization_parameters,
                                        cpd_partial ? 0.5 : 0.),
                   memory);
    };
    Mesh::create_mesh(geometry,
                      triangulation,
                      &mesh_notes,
                      check_size,
                      &node_sets);
    time_mesh += timer.wall_time();
    timer.restart();
    cells = LinearCells<dim>(triangulation);
    fe    = std::make_unique<FESystem<dim>>(cells.scalar_element(), dim);
    const bool fem = (formulation.method == FormulationCode::Method::fem);
    meshfree = fem ? std::vector<bool>(triangulation.n_active_cells(), false) :
                     Mesh::mark_meshfree_cells(geometry, triangulation);
    if (cells.is_simplex())
      check_simplex_support(geometry, formulation, cells, meshfree);

    dof_handler.reinit(triangulation);
    if (formulation.n_nodal_fields() > 0)
      {
        field_layout =
          std::make_unique<FieldLayout<dim>>(formulation.n_nodal_fields(),
                                             cells);
        field_layout->distribute_dofs(dof_handler, meshfree);
      }
    else
      dof_handler.distribute_dofs(*fe);
    for (unsigned int i = 0; i < fe->n_dofs_per_cell(); ++i)
      Assert(fe->system_to_component_index(i).first == i % dim &&
               fe->system_to_component_index(i).second == i / dim,
             ExcInternalError());
    owned_dofs = dof_handler.locally_owned_dofs();

    for (const auto &cell : dof_handler.active_cell_iterators())
      if (cell->is_locally_owned())
        {
          if (!meshfree[cell->active_cell_index()])
            owned_fe_cells.push_back(cell);
          else if (loaded_by_face_traction(cell))
            owned_meshfree_neumann_cells.push_back(cell);
        }

    // IUnlP0's pressure is a DoF of every family; a Q1 cell would need
    // one of its own (incompressible Q1P0 is not built)
    AssertThrow(
      !formulation.incompressible() ||
        !Utilities::MPI::logical_or(!owned_fe_cells.empty(),
                                    triangulation.get_communicator()),
      ExcBadParameter(
        "Geometry/Meshfree region",
        geometry.meshfree_region,
        "the incompressible formulation <" + formulation.text +
          "> (subsection 'Discretization') has a global pressure per "
          "family and no finite element counterpart yet, so it cannot be "
          "coupled to finite element cells. Set 'Meshfree region = all', or "
          "couple a nearly incompressible material (nu = 0.4999) with "
          "'VCPBG V5sn UnlP0' or 'VCPBG V5sn Unl+P1C' (FE cells Q1P0/H1P0)."));

    // Particles, families, and the quadrature table of every family owned
    // by this rank (owned = its master's DoFs are owned here).
    particles.reinit(dof_handler, meshfree, mirror_symmetry_ids);
    time_setup += timer.wall_time();
    timer.restart();
    if (particles.n_particles() > 0)
      {
        const bool is_cpd =
          (formulation.method == FormulationCode::Method::cpd);
        // CPD with partial volumes: bonds reach delta + h/2
        const double horizon_factor =
          discretization_parameters.horizon_factor +
          (is_cpd && cpd_parameters.partial_volumes ? 0.5 : 0.);
        if (particles.n_mirror_planes() > 0)
          {
            // VC2 solves its own system, not built for mirror images
            AssertThrow(!formulation.second_order_consistency,
                        ExcBadParameter(
                          "Boundary conditions/Symmetry treatment",
                          "mirror",
                          "mirrored families are not built for <" +
                            formulation.text +
                            "> (subsection 'Discretization'): set "
                            "'Symmetry treatment = constraint', or model the "
                            "full body."));
            AssertThrow(
              discretization_parameters.nearest_neighbours == 0,
              ExcBadParameter("Boundary conditions/Symmetry treatment",
                              "mirror",
                              "'Nearest neighbours' (subsection "
                              "'Discretization') gives no horizon within which "
                              "to mirror the particles. Use 'Horizon factor' "
                              "or 'Horizon', or set 'Symmetry treatment = "
                              "constraint'."));
            double reach = 0;
            for (unsigned int k = 0; k < particles.n_particles(); ++k)
              reach = std::max(reach,
                               horizon_factor * particles.spacing(k) +
                                 discretization_parameters.horizon);
            particles.add_mirror_images(reach);
          }
        families.reinit(particles,
                        horizon_factor,
                        discretization_parameters.nearest_neighbours,
                        discretization_parameters.horizon);
        if (is_cpd)
          cpd = std::make_unique<CpdInteractions<dim>>(
            particles,
            families,
            CpdConstants{cpd_parameters.C1,
                         cpd_parameters.C2,
                         cpd_parameters.C3,
                         cpd_parameters.partial_volumes},
            discretization_parameters.horizon_factor,
            discretization_parameters.horizon);
        const auto base =
          ShapeFunctions::parse_base(discretization_parameters.shape_functions);
        family_elements = std::make_unique<FamilyElements<dim>>(
          particles,
          families,
          is_cpd ? parse_formulation_code("PBG U1") :
                   formulation.underintegrated_part(),
          base,
          discretization_parameters.weight_exponent);
        if (formulation.points == FormulationCode::Points::u1s_unl)
          stabilisation_elements = std::make_unique<FamilyElements<dim>>(
            particles,
            families,
            formulation.stabilisation_part(),
            base,
            discretization_parameters.weight_exponent);
        if (discretization_parameters.particle_volume_weights)
          {
            AssertThrow(
              !is_cpd && formulation.method == FormulationCode::Method::pbg &&
                formulation.points != FormulationCode::Points::u1,
              ExcBadParameter(
                "Discretization/Quadrature weights",
                "particle volumes",
                "it scales the weights of the PBG family quadrature at "
                "every member (Unl, U2, U1SUnl, UnlP0, Unl+P1C), which <" +
                  formulation.text +
                  "> does not use. Set 'Quadrature weights = horizon'."));
            (stabilisation_elements ? stabilisation_elements : family_elements)
              ->use_particle_volume_weights();
          }
        for (unsigned int k = 0; k < particles.n_particles(); ++k)
          if (owned_dofs.is_element(particles.dof(k, 0)))
            owned_families.push_back(k);
        const std::vector<bool> needed = needed_families(formulation);
        family_tables.resize(owned_families.size());
        // A family one rank rejects stops every rank, with the message one
        // rank would give: the first family singular at its master, else
        // the first singular at another point.
        const MPI_Comm comm   = triangulation.get_communicator();
        const bool     serial = (Utilities::MPI::n_mpi_processes(comm) == 1);
        bool           failed = false;
        try
          {
            family_elements->initialize(needed);
            family_elements->build(owned_families, family_tables);
            if (stabilisation_elements)
              {
                stabilisation_elements->initialize(needed);
                stabilisation_elements->build(owned_families,
                                              stabilisation_tables);
              }
          }
        catch (const ExcSingularFamily &)
          {
            if (serial)
              throw;
            failed = true;
          }
        if (!serial && Utilities::MPI::logical_or(failed, comm))
          {
            // every rank repeats the checks: of its needed families at the
            // master (initialize()), then of its owned ones (build(); for
            // U1SUnl those of the stabilisation, at every member)
            const FamilyElements<dim> &checked  = stabilisation_elements ?
                                                    *stabilisation_elements :
                                                    *family_elements;
            const auto                 rejected = [&](const unsigned int k,
                                      const bool         master_only) {
              try
                {
                  checked.check_family(k, master_only);
                  return false;
                }
              catch (const ExcSingularFamily &)
                {
                  return true;
                }
            };
            unsigned int first = numbers::invalid_unsigned_int;
            for (unsigned int k = 0; k < families.n_families(); ++k)
              if ((needed.empty() || needed[k]) && rejected(k, true))
                {
                  first = k;
                  break;
                }
            first = Utilities::MPI::min(first, comm);
            if (first != numbers::invalid_unsigned_int)
              checked.check_family(first, true);
            for (const unsigned int k : owned_families)
              if (rejected(k, false))
                {
                  first = k;
                  break;
                }
            first = Utilities::MPI::min(first, comm);
            if (first != numbers::invalid_unsigned_int)
              checked.check_family(first, false);
            AssertThrow(false, ExcInternalError());
          }
      }
    time_shape += timer.wall_time();
    timer.restart();

    // After the families: a ghost set can be the DoFs of their members.
    compute_relevant_dofs();
    mesh_diameter = Mesh::diameter(triangulation);
    time_setup += timer.wall_time();
  }



  template <int dim>
  std::vector<bool>
  Discretization<dim>::needed_families(const FormulationCode &formulation) const
  {
    // VC2 solves its correction system with every family on every rank
    if (formulation.second_order_consistency ||
        Utilities::MPI::n_mpi_processes(triangulation.get_communicator()) == 1)
      return {};
    // The owned families and their members; PPG1 also the members' members
    // (a table of family e reads g^{jje} of its member j, and the 'exact
    // stress' force of particle k builds the tables of k's members).
    std::vector<bool> needed(families.n_families(), false);
    // (a mirror image's family is its original's)
    for (const unsigned int k : owned_families)
      for (const unsigned int j : families.members(k))
        needed[particles.original(j)] = true;
    if (formulation.method == FormulationCode::Method::ppg1)
      {
        const std::vector<bool> ring = needed;
        for (unsigned int k = 0; k < ring.size(); ++k)
          if (ring[k])
            for (const unsigned int j : families.members(k))
              needed[particles.original(j)] = true;
      }
    return needed;
  }



  template <int dim>
  void
  Discretization<dim>::compute_relevant_dofs()
  {
    relevant_dofs = pg::compute_relevant_dofs(dof_handler,
                                              particles,
                                              families,
                                              owned_families);
  }



  template class Discretization<2>;
  template class Discretization<3>;
} // namespace pg
