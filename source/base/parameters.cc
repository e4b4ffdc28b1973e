#include <pg/base/exceptions.h>
#include <pg/base/parameters.h>

#include <deal.II/base/utilities.h>

#include <algorithm>
#include <cmath>
#include <fstream>
#include <sstream>

namespace pg
{
  namespace Parameters
  {
    namespace
    {
      /** "a, b, c" -> {a, b, c} with a clear message on a bad number. */
      std::vector<double>
      parse_doubles(const std::string &text, const std::string &entry)
      {
        std::vector<double> values;
        for (const std::string &word : Utilities::split_string_list(text, ','))
          {
            try
              {
                values.push_back(Utilities::string_to_double(word));
              }
            catch (...)
              {
                AssertThrow(false,
                            ExcBadParameter(entry,
                                            text,
                                            "it must be a comma-separated "
                                            "list of numbers."));
              }
          }
        return values;
      }



      std::vector<types::boundary_id>
      parse_ids(const std::string &text, const std::string &entry)
      {
        std::vector<types::boundary_id> ids;
        for (const std::string &word : Utilities::split_string_list(text, ','))
          {
            const int id = Utilities::string_to_int(word);
            AssertThrow(id >= 0 && id < 255,
                        ExcBadParameter(entry,
                                        text,
                                        "boundary ids must be integers "
                                        "between 0 and 254."));
            ids.push_back(static_cast<types::boundary_id>(id));
          }
        return ids;
      }



      /**
       * The component mask of the letters x, y, z in @p letters; a wrong
       * letter is reported for @p entry with its whole value @p text, the
       * message ending in @p example.
       */
      std::vector<bool>
      parse_components(const std::string &letters,
                       const unsigned int dim,
                       const std::string &entry,
                       const std::string &text,
                       const std::string &example)
      {
        std::vector<bool> mask(dim, false);
        for (const char c : letters)
          {
            const unsigned int component = (c == 'x' ? 0 :
                                            c == 'y' ? 1 :
                                            c == 'z' ? 2 :
                                                       99);
            AssertThrow(component < dim,
                        ExcBadParameter(entry,
                                        text,
                                        "components are written with the "
                                        "letters x, y" +
                                          std::string(dim == 3 ? ", z" : "") +
                                          example));
            mask[component] = true;
          }
        return mask;
      }



      /**
       * The items of the @p separator-separated list @p text of @p entry,
       * each split at ':' into exactly @p n_parts parts; otherwise the
       * message @p form (how an item must read).
       */
      std::vector<std::vector<std::string>>
      parse_items(const std::string &text,
                  const char         separator,
                  const unsigned int n_parts,
                  const std::string &entry,
                  const std::string &form)
      {
        std::vector<std::vector<std::string>> items;
        for (const std::string &item :
             Utilities::split_string_list(text, separator))
          {
            items.push_back(Utilities::split_string_list(item, ':'));
            AssertThrow(items.back().size() == n_parts,
                        ExcBadParameter(entry, text, form));
          }
        return items;
      }



      /**
       * @p part of the value @p text of @p entry as dim coordinates;
       * otherwise the message "<what> needs <dim> coordinates.".
       */
      std::vector<double>
      parse_coordinates(const std::string &part,
                        const unsigned int dim,
                        const std::string &entry,
                        const std::string &text,
                        const std::string &what)
      {
        const std::vector<double> coordinates = parse_doubles(part, entry);
        AssertThrow(coordinates.size() == dim,
                    ExcBadParameter(entry,
                                    text,
                                    what + " needs " + std::to_string(dim) +
                                      " coordinates."));
        return coordinates;
      }
    } // namespace



    void
    Geometry::declare_parameters(ParameterHandler &prm)
    {
      prm.enter_subsection("Geometry");
      {
        prm.declare_entry(
          "Mesh",
          "hyper rectangle",
          Patterns::Selection("hyper rectangle|cook membrane|plate with hole|"
                              "file"),
          "The mesh. 'hyper rectangle': the box between 'Lower corner' and "
          "'Upper corner' with colorized boundary ids 0..2*dim-1 (0: x=min, "
          "1: x=max, 2: y=min, 3: y=max, 4: z=min, 5: z=max). 'cook "
          "membrane': the 48 x 44/16 tapered panel (2-D), ids 0 clamped left "
          "edge, 1 loaded right edge, 2 bottom, 3 top. 'plate with hole': the "
          "quarter [0,L]^2 of a square plate minus the disk of radius R at "
          "the origin (2-D), ids 0 hole, 1 x=0, 2 y=0, 3 x=L, 4 y=L. 'file': "
          "read 'File name'.");
        prm.declare_entry("Lower corner",
                          "0, 0",
                          Patterns::List(Patterns::Double()),
                          "Hyper rectangle: lower corner, dim coordinates. "
                          "Units: length.");
        prm.declare_entry("Upper corner",
                          "1, 1",
                          Patterns::List(Patterns::Double()),
                          "Hyper rectangle: upper corner, dim coordinates. "
                          "Units: length.");
        prm.declare_entry("Subdivisions",
                          "1, 1",
                          Patterns::List(Patterns::Integer(1)),
                          "Cells per direction before global refinement "
                          "(hyper rectangle and cook membrane); one value is "
                          "used for every direction.");
        prm.declare_entry(
          "Hole",
          "",
          Patterns::Anything(),
          "Hyper rectangle only: 'box x0,y0 : x1,y1' (dim coordinates per "
          "corner) removes the cells of the coarse mesh ('Subdivisions') "
          "whose centres lie in the box, before refinement; the faces of the "
          "hole get boundary id 2*dim (4 in 2-D, 6 in 3-D). Empty: no hole. "
          "E.g. the unit square or cube with a centred square hole of side "
          "0.4: 'box 0.3,0.3 : 0.7,0.7' with 10 subdivisions.");
        prm.declare_entry("Plate size",
                          "4",
                          Patterns::Double(0.),
                          "Plate with hole: edge length L of the quarter "
                          "plate. Units: length.");
        prm.declare_entry("Hole radius",
                          "1",
                          Patterns::Double(0.),
                          "Plate with hole: hole radius R < L. Units: "
                          "length.");
        prm.declare_entry("File name",
                          "",
                          Patterns::Anything(),
                          "Mesh file for 'Mesh = file': Gmsh (.msh), Abaqus "
                          "(.inp) or UCD (.ucd), read with deal.II's GridIn. "
                          "Relative paths start in the working directory.");
        prm.declare_entry(
          "Coincident vertices",
          "merge",
          Patterns::Selection("merge|reject|keep"),
          "Mesh = file: what to do with distinct vertices at the same "
          "position (closer than 1e-10 x the bounding-box diagonal in every "
          "coordinate), which some mesh generators leave where blocks meet "
          "(e.g. Cubit/Exodus meshes converted to Gmsh): they disconnect "
          "the finite elements there and make coincident particles. "
          "'merge': merge them into one vertex on reading and say how many "
          "were merged. 'reject': stop with a message naming the first "
          "positions. 'keep': read the mesh as it is and only say so (the "
          "blocks stay disconnected: FEM then has a singular system and "
          "PG coincident particles, whose families give NaN; for tests "
          "of those messages).");
        prm.declare_entry("Global refinement",
                          "0",
                          Patterns::Integer(0, 12),
                          "Number of uniform refinements of the mesh.");
        prm.declare_entry("Distortion",
                          "0",
                          Patterns::Double(0., 0.45),
                          "Every interior vertex is moved randomly by up to "
                          "this fraction of its shortest adjacent edge "
                          "(after refinement); vertices of cells that the "
                          "shifts make non-convex are drawn again. 0 keeps "
                          "the mesh regular.");
        prm.declare_entry("Random seed",
                          "0",
                          Patterns::Integer(0),
                          "Seed of the random distortion; the same seed "
                          "gives the same mesh.");
        prm.declare_entry(
          "Meshfree region",
          "all",
          Patterns::Anything(),
          "Which cells are meshfree (their vertices become particles); the "
          "others are Q1 finite elements. 'all', 'none', 'material ids 1,2', "
          "'box x0,y0 : x1,y1' or 'ball cx,cy : r'. A cell is meshfree if its "
          "centre lies inside the box or ball. Ignored for 'Formulation = "
          "FEM'.");
      }
      prm.leave_subsection();
    }



    void
    Geometry::parse_parameters(ParameterHandler &prm)
    {
      prm.enter_subsection("Geometry");
      {
        mesh = prm.get("Mesh");
        lower_corner =
          parse_doubles(prm.get("Lower corner"), "Geometry/Lower corner");
        upper_corner =
          parse_doubles(prm.get("Upper corner"), "Geometry/Upper corner");
        subdivisions.clear();
        for (const double s :
             parse_doubles(prm.get("Subdivisions"), "Geometry/Subdivisions"))
          subdivisions.push_back(static_cast<unsigned int>(s));
        plate_size          = prm.get_double("Plate size");
        hole_radius         = prm.get_double("Hole radius");
        file_name           = prm.get("File name");
        coincident_vertices = prm.get("Coincident vertices");
        global_refinement   = prm.get_integer("Global refinement");
        distortion          = prm.get_double("Distortion");
        random_seed         = prm.get_integer("Random seed");
        meshfree_region     = prm.get("Meshfree region");
        hole                = prm.get("Hole");
      }
      prm.leave_subsection();

      AssertThrow(mesh != "plate with hole" || hole_radius < plate_size,
                  ExcBadParameter("Geometry/Hole radius",
                                  std::to_string(hole_radius),
                                  "it must be smaller than 'Plate size' "
                                  "in subsection 'Geometry'."));
      AssertThrow(mesh != "file" || !file_name.empty(),
                  ExcBadParameter("Geometry/File name",
                                  file_name,
                                  "'Mesh = file' needs the name of a mesh "
                                  "file."));
    }



    void
    Discretization::declare_parameters(ParameterHandler &prm)
    {
      prm.enter_subsection("Discretization");
      {
        prm.declare_entry(
          "Formulation",
          "BCPBG Unl TL",
          Patterns::Anything(),
          "The method, as the dissertation's code (Table 7.1), or FEM: "
          "[VC|VC2][BC]<method> [V<n><b>] <points> [noBC] [TL], with the "
          "table's defaults. <method>: PBG (eq. 4.30), PPG (= PPG1, eq. "
          "4.21) or PPG2 (eq. 4.22). <points>: Unl (default; shape functions "
          "at every family member), U1 (PBG at the master only: classical "
          "correspondence) or U2 (the quadratic WTE2 at every family member, "
          "whatever 'Shape functions' says). The bond correction BC (eq. "
          "5.55) is the default of Unl (Table 7.1: 'default for all first "
          "order formulations'), so 'PBG Unl' is 'BCPBG Unl TL'; 'noBC' "
          "switches it off ('PBG Unl noBC'). U1 and U2 take no BC. VC "
          "switches the variational-consistency correction on (section "
          "5.3.2) with the correction function V1, V3 or V5 (default V3 for "
          "PPG, V5 for PBG) and the boundary option p, s or sn (default sn). "
          "VC2 adds the second-order correction (section 11.6); it is built "
          "on PPG2, so 'VC2PPG' means PPG2, and it takes the boundary option "
          "s (default correction function V1). The screen and summary.json "
          "show the code with every default written out. FEM uses Q1 "
          "elements everywhere. Examples: 'PBG Unl', 'VCPBG V5sn Unl' (= "
          "'VCBCPBG V5sn Unl TL'), 'VCPPG V3sn Unl' (= 'VCBCPPG V3sn Unl "
          "TL'), 'PBG U1', 'VC2PPG V1s U2'. CPD: "
          "continuum-kinematics-inspired peridynamics with the constants of "
          "subsection 'CPD' (the meshfree cells' vertices interact within "
          "the horizon; no shape functions).");
        prm.declare_entry("Shape functions",
                          "MTE1",
                          Patterns::Selection("MTE1|MLS1|WLS1|WTE1"),
                          "The first-order base of Unl/U1 (Table 5.1): MTE1 "
                          "(moving Taylor), MLS1 (moving least squares), "
                          "WLS1 (weighted least squares), WTE1 (weighted "
                          "Taylor). At the master MTE1 equals WTE1, so U1 "
                          "with MTE1 is WTE1: classical correspondence.");
        prm.declare_entry(
          "Horizon factor",
          "",
          Patterns::Anything(),
          "Horizon delta^k = factor x local particle spacing h^k, per "
          "particle k (h^k: the mean length of the meshfree cell edges at "
          "the particle), so delta varies with the local spacing on graded "
          "or distorted meshes. Typical values 1.51 ... 3.01. Give either "
          "this or 'Horizon', not both; with both empty the factor is "
          "2.51.");
        prm.declare_entry(
          "Horizon",
          "",
          Patterns::Anything(),
          "Absolute horizon delta, the same for every particle (Peridigm's "
          "'Horizon'). Units: length. Give either this or 'Horizon factor', "
          "not both; empty: use 'Horizon factor'. On a uniform lattice of "
          "spacing h, 'Horizon = 2.51 h' gives the families of 'Horizon "
          "factor = 2.51'; on graded or distorted meshes they differ (the "
          "factor follows the local spacing).");
        prm.declare_entry("Nearest neighbours",
                          "0",
                          Patterns::Integer(0),
                          "If > 0, a family is its master plus the N nearest "
                          "particles, completed to pairwise families; "
                          "'Horizon factor' and 'Horizon' are then ignored.");
        prm.declare_entry("Weight exponent",
                          "1",
                          Patterns::Double(0.),
                          "n in the weight omega = |dX|^(-2n) (eqs. 4.5, "
                          "5.42).");
      }
      prm.leave_subsection();
    }



    void
    Discretization::parse_parameters(ParameterHandler &prm)
    {
      prm.enter_subsection("Discretization");
      {
        formulation     = prm.get("Formulation");
        shape_functions = prm.get("Shape functions");
        const std::string factor_text =
          Utilities::trim(prm.get("Horizon factor"));
        const std::string horizon_text = Utilities::trim(prm.get("Horizon"));
        AssertThrow(factor_text.empty() || horizon_text.empty(),
                    ExcBadParameter("Discretization/Horizon",
                                    horizon_text,
                                    "'Horizon factor' is set too (to <" +
                                      factor_text +
                                      ">); set exactly one of 'Horizon' "
                                      "(absolute, length) and 'Horizon "
                                      "factor' (x local spacing) in "
                                      "subsection 'Discretization'."));
        const auto positive = [](const std::string &text,
                                 const std::string &entry) {
          double value = 0;
          try
            {
              std::size_t end = 0;
              value           = std::stod(text, &end);
              AssertThrow(Utilities::trim(text.substr(end)).empty(),
                          ExcMessage(""));
            }
          catch (...)
            {
              AssertThrow(false,
                          ExcBadParameter("Discretization/" + entry,
                                          text,
                                          "it must be a number."));
            }
          AssertThrow(value > 0. && std::isfinite(value),
                      ExcBadParameter("Discretization/" + entry,
                                      text,
                                      "it must be positive."));
          return value;
        };
        horizon        = 0.;
        horizon_factor = 0.;
        if (!horizon_text.empty())
          horizon = positive(horizon_text, "Horizon");
        else
          horizon_factor = factor_text.empty() ?
                             2.51 :
                             positive(factor_text, "Horizon factor");
        nearest_neighbours = prm.get_integer("Nearest neighbours");
        weight_exponent    = prm.get_double("Weight exponent");
      }
      prm.leave_subsection();
    }



    void
    Cpd::declare_parameters(ParameterHandler &prm)
    {
      prm.enter_subsection("CPD");
      {
        prm.declare_entry(
          "C1",
          "1",
          Patterns::Double(),
          "One-neighbour (bond) constant C_1 of continuum-kinematics-inspired "
          "peridynamics (Formulation = CPD; Javili et al. 2020, eq. 23): "
          "psi_1 = C_1 (l - L)^2 / (2 L). Units N m / m^7 in 3-D, N m / m^5 "
          "in 2-D. Must be positive. Alone (C2 = C3 = 0) it is Silling's "
          "bond-based micro-elastic material with nu = 1/4 (3-D) or 1/3 "
          "(2-D); doc/cpd.md relates C_1 to E.");
        prm.declare_entry(
          "C2",
          "0",
          Patterns::Double(),
          "Two-neighbour (area) constant C_2 (eq. 24): psi_2 = C_2 (a - A)^2 "
          "/ (2 A) for the triangles of a particle and two of its mutual "
          "neighbours. Units N m / m^11 (3-D), N m / m^8 (2-D). Raises the "
          "Poisson ratio (negative values lower it).");
        prm.declare_entry(
          "C3",
          "0",
          Patterns::Double(),
          "Three-neighbour (volume) constant C_3 (eq. 25, 3-D only): psi_3 = "
          "C_3 (v - V)^2 / (2 V) for the tetrahedra of a particle and three "
          "mutual neighbours. Units N m / m^15.");
        prm.declare_entry(
          "Partial volumes",
          "false",
          Patterns::Bool(),
          "Weigh each bond by the share beta of the neighbour's volume inside "
          "the horizon, beta = (delta + h/2 - |xi|)/h clipped to [0, 1] with "
          "h the particle spacing (families then reach delta + h/2). Off: "
          "every neighbour within delta counts fully, as in the source; on a "
          "regular lattice the discrete Poisson ratio then oscillates with "
          "delta/h (doc/cpd.md).");
      }
      prm.leave_subsection();
    }



    void
    Cpd::parse_parameters(ParameterHandler &prm)
    {
      prm.enter_subsection("CPD");
      {
        C1              = prm.get_double("C1");
        C2              = prm.get_double("C2");
        C3              = prm.get_double("C3");
        partial_volumes = prm.get_bool("Partial volumes");
      }
      prm.leave_subsection();
    }



    void
    BoundaryConditions::declare_parameters(ParameterHandler &prm)
    {
      prm.enter_subsection("Boundary conditions");
      {
        prm.declare_entry(
          "Dirichlet",
          "",
          Patterns::Anything(),
          "Comma-separated 'boundary id: components' items, e.g. '0: xy, 3: "
          "y'. The listed displacement components on that boundary take the "
          "values of subsection 'Prescribed displacement'.");
        prm.declare_entry(
          "Fixed points",
          "",
          Patterns::Anything(),
          "Semicolon-separated 'coordinates: components' items, e.g. '0, 0.5: "
          "y; 0, 1: x'. The listed displacement components of the mesh "
          "vertex at each point take the values of subsection 'Prescribed "
          "displacement' (a vertex must lie there). For removing the rigid "
          "motions of a laterally free specimen.");
        prm.declare_entry(
          "Dirichlet boxes",
          "",
          Patterns::Anything(),
          "Semicolon-separated 'x0, y0 : x1, y1 : components' items (dim "
          "coordinates per corner), e.g. '-1, 0 : 0, 1 : xy'. The listed "
          "displacement components of every mesh vertex in the closed box "
          "take the values of subsection 'Prescribed displacement'. For "
          "clamping non-local models (CPD, large horizons) through a layer "
          "of thickness delta rather than a boundary line, whose influence "
          "vanishes as the lattice is refined. The reaction of each box "
          "(f_int - f_ext summed over its prescribed components) is "
          "printed and written to summary.json ('box_reactions', in the "
          "order of the boxes).");
        prm.declare_entry("Symmetry",
                          "",
                          Patterns::Anything(),
                          "Boundary ids of planar boundaries with zero "
                          "normal displacement, e.g. '1, 2'.");
        prm.declare_entry("Neumann",
                          "",
                          Patterns::Anything(),
                          "Boundary ids loaded by the dead traction of "
                          "subsection 'Traction' (first Piola traction per "
                          "reference area).");
        prm.declare_entry(
          "Neumann stress",
          "",
          Patterns::Anything(),
          "Boundary ids loaded by the traction sigma . n, with sigma the "
          "stress of subsection 'Boundary stress' (dim*dim components, "
          "row-major sigma_ij; first Piola stress, which is the Cauchy "
          "stress under small strain) and n the outward unit normal of the "
          "reference boundary. One stress function gives the right traction "
          "on boundaries of every orientation, e.g. an exact solution's "
          "stress on the two outer edges of the plate with a hole. An id "
          "belongs to 'Neumann' or to 'Neumann stress', not to both.");
        prm.declare_entry(
          "Particle traction area",
          "automatic",
          Patterns::Selection("automatic|geometry|test functions|exact stress"),
          "How a traction loads the particles on meshfree boundary faces. "
          "'geometry': the FE-consistent load, the integral of T N_k over "
          "the boundary faces (the total load is exact). 'test functions': "
          "T (n . d^k) with d^k the unit-stress residual of the test "
          "functions actually used (dissertation eqs. 4.32-4.35, section "
          "7.1); this is what makes VC-corrected methods pass the patch "
          "test, but without VC d^k misses part of the boundary area (the "
          "share is printed at start-up). 'automatic': 'test functions' "
          "for VC-corrected formulations, 'geometry' otherwise. 'exact "
          "stress' (patch tests): a particle on a Neumann boundary gets the "
          "test-function integral of the exact stress P(grad u) of "
          "subsection 'Exact solution' (the 'Traction' function is not "
          "used), sum_q w_q P(X_q) T^{qk} over its families; this is the "
          "discrete integral of N_k P n over the surface plus the body "
          "force, and equals P . d^k (eq. 4.32 with the full tensor) for a "
          "constant stress. The quadratic patch test needs it for a linear "
          "stress.");
      }
      prm.leave_subsection();
    }



    void
    BoundaryConditions::parse_parameters(ParameterHandler  &prm,
                                         const unsigned int dim)
    {
      prm.enter_subsection("Boundary conditions");
      {
        dirichlet.clear();
        const std::string text = prm.get("Dirichlet");
        for (const auto &parts :
             parse_items(text,
                         ',',
                         2,
                         "Boundary conditions/Dirichlet",
                         "each item must read 'boundary id: components', "
                         "e.g. '0: xy'."))
          {
            const types::boundary_id id =
              parse_ids(parts[0], "Boundary conditions/Dirichlet")[0];
            dirichlet.emplace_back(
              id,
              parse_components(parts[1],
                               dim,
                               "Boundary conditions/Dirichlet",
                               text,
                               ", e.g. '0: xy'."));
          }
        fixed_points.clear();
        const std::string points = prm.get("Fixed points");
        for (const auto &parts :
             parse_items(points,
                         ';',
                         2,
                         "Boundary conditions/Fixed points",
                         "each item must read 'coordinates: components', "
                         "e.g. '0, 0.5: y'."))
          {
            fixed_points.emplace_back(
              parse_coordinates(parts[0],
                                dim,
                                "Boundary conditions/Fixed points",
                                points,
                                "each point"),
              parse_components(parts[1],
                               dim,
                               "Boundary conditions/Fixed points",
                               points,
                               "."));
          }
        dirichlet_boxes.clear();
        const std::string boxes     = prm.get("Dirichlet boxes");
        const std::string box_entry = "Boundary conditions/Dirichlet boxes";
        for (const auto &parts :
             parse_items(boxes,
                         ';',
                         3,
                         box_entry,
                         "each item must read 'x0, y0 : x1, y1 : components', "
                         "e.g. '-1, 0 : 0, 1 : xy'."))
          {
            DirichletBox box{
              parse_coordinates(parts[0], dim, box_entry, boxes, "each corner"),
              parse_coordinates(parts[1], dim, box_entry, boxes, "each corner"),
              parse_components(parts[2],
                               dim,
                               box_entry,
                               boxes,
                               ", e.g. '-1, 0 : 0, 1 : xy'.")};
            for (unsigned int d = 0; d < dim; ++d)
              AssertThrow(box.lower[d] <= box.upper[d],
                          ExcBadParameter(
                            box_entry,
                            boxes,
                            "the first corner of each box must be the lower "
                            "one (x0 <= x1, y0 <= y1)."));
            dirichlet_boxes.push_back(box);
          }
        symmetry =
          parse_ids(prm.get("Symmetry"), "Boundary conditions/Symmetry");
        neumann = parse_ids(prm.get("Neumann"), "Boundary conditions/Neumann");
        neumann_stress = parse_ids(prm.get("Neumann stress"),
                                   "Boundary conditions/Neumann stress");
        for (const types::boundary_id id : neumann_stress)
          AssertThrow(std::find(neumann.begin(), neumann.end(), id) ==
                        neumann.end(),
                      ExcBadParameter("Boundary conditions/Neumann stress",
                                      prm.get("Neumann stress"),
                                      "boundary " + std::to_string(id) +
                                        " is also in 'Neumann'; give each "
                                        "loaded boundary one traction."));
        particle_traction_area = prm.get("Particle traction area");
      }
      prm.leave_subsection();
    }



    void
    Loading::declare_parameters(ParameterHandler &prm)
    {
      prm.enter_subsection("Loading");
      {
        prm.declare_entry("Load steps",
                          "1",
                          Patterns::Integer(1),
                          "Number of equal load steps; the load factor t "
                          "runs from 0 to 1.");
        prm.declare_entry("Maximum step cuts",
                          "5",
                          Patterns::Integer(0, 30),
                          "A load step whose Newton iteration diverges is "
                          "halved and repeated, at most this often.");
      }
      prm.leave_subsection();
    }



    void
    Loading::parse_parameters(ParameterHandler &prm)
    {
      prm.enter_subsection("Loading");
      {
        load_steps        = prm.get_integer("Load steps");
        maximum_step_cuts = prm.get_integer("Maximum step cuts");
      }
      prm.leave_subsection();
    }



    void
    Newton::declare_parameters(ParameterHandler &prm)
    {
      prm.enter_subsection("Newton");
      {
        prm.declare_entry("Maximum iterations",
                          "20",
                          Patterns::Integer(1),
                          "Newton iterations per load step before the step "
                          "counts as diverged.");
        prm.declare_entry("Relative tolerance",
                          "1e-10",
                          Patterns::Double(0.),
                          "Converged when |R| <= this x |R| of the first "
                          "iteration of the step, ...");
        prm.declare_entry("Absolute tolerance",
                          "1e-12",
                          Patterns::Double(0.),
                          "... or when |R| <= this (force units).");
      }
      prm.leave_subsection();
    }



    void
    Newton::parse_parameters(ParameterHandler &prm)
    {
      prm.enter_subsection("Newton");
      {
        maximum_iterations = prm.get_integer("Maximum iterations");
        relative_tolerance = prm.get_double("Relative tolerance");
        absolute_tolerance = prm.get_double("Absolute tolerance");
      }
      prm.leave_subsection();
    }



    void
    LinearSolver::declare_parameters(ParameterHandler &prm)
    {
      prm.enter_subsection("Linear solver");
      {
        prm.declare_entry("Type",
                          "direct",
                          Patterns::Selection("direct|cg|gmres"),
                          "direct: Trilinos Amesos with MUMPS (KLU if "
                          "Trilinos lacks MUMPS). cg (symmetric "
                          "tangents only: FEM and PBG with hyperelastic "
                          "materials) or gmres, both preconditioned by "
                          "Trilinos ML algebraic multigrid.");
        prm.declare_entry("Tolerance",
                          "1e-10",
                          Patterns::Double(0.),
                          "Relative residual reduction of cg and gmres.");
      }
      prm.leave_subsection();
    }



    void
    LinearSolver::parse_parameters(ParameterHandler &prm)
    {
      prm.enter_subsection("Linear solver");
      {
        type      = prm.get("Type");
        tolerance = prm.get_double("Tolerance");
      }
      prm.leave_subsection();
    }



    void
    Analysis::declare_parameters(ParameterHandler &prm)
    {
      prm.enter_subsection("Analysis");
      {
        prm.declare_entry(
          "Type",
          "static",
          Patterns::Selection("static|eigenmodes|inf-sup"),
          "static: quasi-static load stepping with Newton's method. "
          "eigenmodes: the eigenvalues of the tangent in the undeformed "
          "state (with the given constraints; none for a free body), by a "
          "dense LAPACK solve (at most 6000 unknowns, one MPI rank). Zero "
          "eigenvalues beyond the rigid-body motions, or many small ones, "
          "reveal spurious modes (dissertation section 7.2.1). "
          "inf-sup: the numerical inf-sup test of Chapelle and Bathe "
          "(section 7.2.5, eqs. 7.10-7.15) on the unit square meshed with "
          "'Inf-sup subdivisions' (the entries 'Mesh', corners, "
          "'Subdivisions' and 'Global refinement' of subsection 'Geometry' "
          "are replaced; 'Distortion', 'Random seed' and 'Meshfree region' "
          "are kept), held by 'Dirichlet' (clamp all four sides). PBG and "
          "FEM formulations only; dense LAPACK (at most 6000 free unknowns, "
          "one MPI rank). Writes inf_sup.txt.");
        prm.declare_entry("Number of eigenvalues",
                          "200",
                          Patterns::Integer(1),
                          "How many of the smallest eigenvalues go to "
                          "summary.json and eigenvalues.txt.");
        prm.declare_entry(
          "Pressure space",
          "displacement",
          Patterns::Selection("displacement|P0"),
          "inf-sup: the pressure space of T_h. displacement: the "
          "displacement-based formulation as it is (T_h from the full "
          "div-div term, K = 1, mu = 0, at every evaluation point). P0: one "
          "constant pressure per element (Q1 cell or PG family), condensed "
          "exactly; Q1P0 for FEM, UnlP0 for PBG families.");
        prm.declare_entry("Inf-sup subdivisions",
                          "2, 4, 8, 16, 32",
                          Patterns::List(Patterns::Integer(1)),
                          "inf-sup: the refinement series, N cells (or "
                          "particle spacings) per side of the unit square.");
        prm.declare_entry("Inf-sup zero tolerance",
                          "1e-10",
                          Patterns::Double(0.),
                          "inf-sup: eigenvalues below this times the "
                          "largest count as zero (k - 1 in eq. 7.14). "
                          "Measured for N <= 32 (doc/benchmarks/inf_sup.md): "
                          "the zero eigenvalues are round-off, below 3e-13 "
                          "lambda_max, the non-zero ones above 5e-6 "
                          "lambda_max.");
      }
      prm.leave_subsection();
    }



    void
    Analysis::parse_parameters(ParameterHandler &prm)
    {
      prm.enter_subsection("Analysis");
      {
        type           = prm.get("Type");
        n_eigenvalues  = prm.get_integer("Number of eigenvalues");
        pressure_space = prm.get("Pressure space");
        inf_sup_subdivisions.clear();
        for (const double n : parse_doubles(prm.get("Inf-sup subdivisions"),
                                            "Analysis/Inf-sup subdivisions"))
          inf_sup_subdivisions.push_back(static_cast<unsigned int>(n));
        inf_sup_zero_tolerance = prm.get_double("Inf-sup zero tolerance");
      }
      prm.leave_subsection();
    }



    void
    Output::declare_parameters(ParameterHandler &prm)
    {
      prm.enter_subsection("Output");
      {
        prm.declare_entry("Directory",
                          "results",
                          Patterns::Anything(),
                          "Where VTU/PVD files, statistics.txt, timing.txt "
                          "and summary.json go. Created if missing.");
        prm.declare_entry("VTU",
                          "true",
                          Patterns::Bool(),
                          "Write VTU/PVD files for ParaView after every "
                          "load step.");
        prm.declare_entry("Points",
                          "",
                          Patterns::Anything(),
                          "Named reference points whose displacement is "
                          "reported: 'name: x, y[, z]; name: ...', e.g. "
                          "'tip: 48, 60'.");
        prm.declare_entry("Stress along boundaries",
                          "",
                          Patterns::Anything(),
                          "Boundary ids whose vertices get a row in "
                          "stress_along_boundaries.txt at the end of the run: "
                          "position, Cauchy stress (particle value at "
                          "particles, the average of the adjacent Q1 cells "
                          "elsewhere) and, with 'Compute errors', the exact "
                          "stress. E.g. the symmetry lines of the plate with "
                          "a hole: '1, 2'.");
        prm.declare_entry(
          "Lines",
          "",
          Patterns::Anything(),
          "Named straight lines along which the displacement is written to "
          "displacement_along_lines.txt after every step: 'name: x0, y0 : x1, "
          "y1; name: ...' (dim coordinates per end). The displacement is the "
          "Q1 interpolant of the nodal values (particles included) at 'Line "
          "samples' equally spaced points; points outside the mesh (in a "
          "hole) are left out. E.g. the upper edge of the unit square: 'BB: "
          "0, 1 : 1, 1'.");
        prm.declare_entry("Line samples",
                          "101",
                          Patterns::Integer(2),
                          "Number of equally spaced points on each of the "
                          "'Lines', both ends included.");
      }
      prm.leave_subsection();
    }



    void
    Output::parse_parameters(ParameterHandler &prm, const unsigned int dim)
    {
      prm.enter_subsection("Output");
      {
        directory = prm.get("Directory");
        vtu       = prm.get_bool("VTU");
        points.clear();
        stress_boundaries      = parse_ids(prm.get("Stress along boundaries"),
                                      "Output/Stress along boundaries");
        const std::string text = prm.get("Points");
        for (const auto &parts :
             parse_items(text,
                         ';',
                         2,
                         "Output/Points",
                         "each point must read 'name: x, y'."))
          points.emplace_back(parts[0],
                              parse_coordinates(parts[1],
                                                dim,
                                                "Output/Points",
                                                text,
                                                "each point"));
        lines.clear();
        const std::string line_text = prm.get("Lines");
        for (const auto &parts :
             parse_items(line_text,
                         ';',
                         3,
                         "Output/Lines",
                         "each line must read 'name: x0, y0 : x1, y1'."))
          {
            const Line line{parts[0],
                            parse_coordinates(parts[1],
                                              dim,
                                              "Output/Lines",
                                              line_text,
                                              "each end of a line"),
                            parse_coordinates(parts[2],
                                              dim,
                                              "Output/Lines",
                                              line_text,
                                              "each end of a line")};
            AssertThrow(line.start != line.end,
                        ExcBadParameter("Output/Lines",
                                        line_text,
                                        "the line '" + line.name +
                                          "' has equal ends."));
            lines.push_back(line);
          }
        line_samples = prm.get_integer("Line samples");
      }
      prm.leave_subsection();
      AssertThrow(!directory.empty(),
                  ExcBadParameter("Output/Directory",
                                  directory,
                                  "it must name a directory."));
    }



    bool
    Time::dynamic() const
    {
      return integrator != "none";
    }



    void
    Time::declare_parameters(ParameterHandler &prm)
    {
      prm.enter_subsection("Time");
      {
        prm.declare_entry(
          "Integrator",
          "none",
          Patterns::Selection("none|leapfrog|newmark"),
          "'none': quasi-static load stepping (subsection 'Loading'); the "
          "variable t of the boundary-condition and load functions is the "
          "load factor from 0 to 1. 'leapfrog': explicit central differences "
          "(velocity Verlet) with the lumped mass, rho_0 times the integral "
          "of N_k over all cells (= rho_0 V^k at a particle); one residual "
          "assembly per step, no matrix. 'newmark': implicit Newmark with "
          "'Newmark beta' and 'Newmark gamma', Newton's method on the "
          "effective tangent K + M / (beta dt^2) with the consistent Q1 mass "
          "on finite element cells and rho_0 V^k at the particles "
          "(subsections 'Newton' and 'Linear solver' apply). With an "
          "integrator, t in the boundary-condition and load functions is the "
          "time (time units) from 0 to 'End time', 'Loading' is ignored, "
          "and statistics.txt holds the energies: kinetic 1/2 v.M v, the "
          "work of the internal forces, of the external loads and of the "
          "supports (the reactions of the constrained DoFs, inertia "
          "included), each accumulated with the trapezoidal rule, and their "
          "balance (0 for exact energy conservation).");
        prm.declare_entry("End time",
                          "1",
                          Patterns::Double(),
                          "The run ends at this time (> 0). Units: time.");
        prm.declare_entry(
          "Time step",
          "0",
          Patterns::Double(),
          "dt (>= 0). 0: the stable step of central differences, 2 / "
          "omega_max, times 'Safety factor', with omega_max^2 the largest "
          "eigenvalue of M^-1 K (power iteration with the lumped mass and "
          "the tangent of the initial state), shortened so that the steps "
          "end at 'End time'. Leapfrog rejects a step above 2 / omega_max. "
          "Units: time.");
        prm.declare_entry("Safety factor",
                          "0.8",
                          Patterns::Double(),
                          "Automatic time step: this fraction (0 < f <= 1) "
                          "of the stable step estimate.");
        prm.declare_entry("Output interval",
                          "0",
                          Patterns::Double(),
                          "Statistics, VTU files and a progress line (t, "
                          "step, energies) every so much time (the first "
                          "step at or after each multiple). 0: every step. "
                          "Units: time.");
        prm.declare_entry("Newmark beta",
                          "0.25",
                          Patterns::Double(),
                          "beta of Newmark's method (0 < beta <= 0.5); 1/4 "
                          "with gamma = 1/2 is the average acceleration "
                          "rule, unconditionally stable and energy "
                          "conserving for linear problems.");
        prm.declare_entry("Newmark gamma",
                          "0.5",
                          Patterns::Double(),
                          "gamma of Newmark's method (0.5 <= gamma <= 1); "
                          "gamma > 1/2 adds numerical damping.");
      }
      prm.leave_subsection();
    }



    void
    Time::parse_parameters(ParameterHandler &prm)
    {
      prm.enter_subsection("Time");
      {
        integrator      = prm.get("Integrator");
        end_time        = prm.get_double("End time");
        time_step       = prm.get_double("Time step");
        safety_factor   = prm.get_double("Safety factor");
        output_interval = prm.get_double("Output interval");
        beta            = prm.get_double("Newmark beta");
        gamma           = prm.get_double("Newmark gamma");
      }
      prm.leave_subsection();

      if (!dynamic())
        return;
      const auto text = [](const double x) {
        std::ostringstream s;
        s << x;
        return s.str();
      };
      AssertThrow(end_time > 0.,
                  ExcBadParameter("Time/End time",
                                  text(end_time),
                                  "it must be positive."));
      AssertThrow(time_step >= 0.,
                  ExcBadParameter("Time/Time step",
                                  text(time_step),
                                  "it must be positive, or 0 for the "
                                  "automatic (stable) step."));
      AssertThrow(safety_factor > 0. && safety_factor <= 1.,
                  ExcBadParameter("Time/Safety factor",
                                  text(safety_factor),
                                  "it must lie in (0, 1]."));
      AssertThrow(output_interval >= 0.,
                  ExcBadParameter("Time/Output interval",
                                  text(output_interval),
                                  "it must be >= 0 (0: every step)."));
      AssertThrow(beta > 0. && beta <= 0.5,
                  ExcBadParameter("Time/Newmark beta",
                                  text(beta),
                                  "it must lie in (0, 0.5]."));
      AssertThrow(gamma >= 0.5 && gamma <= 1.,
                  ExcBadParameter("Time/Newmark gamma",
                                  text(gamma),
                                  "it must lie in [0.5, 1]."));
    }



    template <int dim>
    AllParameters<dim>::AllParameters()
      : dimension(dim)
      , prescribed_displacement(dim)
      , traction(dim)
      , boundary_stress(dim * dim)
      , body_force(dim)
      , exact_solution(dim)
      , compute_errors(false)
      , initial_displacement(dim)
      , initial_velocity(dim)
    {}



    template <int dim>
    void
    AllParameters<dim>::declare_parameters(ParameterHandler &prm)
    {
      prm.declare_entry("Dimension",
                        "2",
                        Patterns::Integer(2, 3),
                        "Space dimension: 2 or 3. Read before everything "
                        "else.");
      Geometry::declare_parameters(prm);
      Discretization::declare_parameters(prm);
      Cpd::declare_parameters(prm);
      Material::declare_parameters(prm);
      BoundaryConditions::declare_parameters(prm);
      prm.enter_subsection("Boundary conditions");
      {
        prm.enter_subsection("Prescribed displacement");
        Functions::ParsedFunction<dim>::declare_parameters(prm, dim);
        prm.leave_subsection();
        prm.enter_subsection("Traction");
        Functions::ParsedFunction<dim>::declare_parameters(prm, dim);
        prm.leave_subsection();
        prm.enter_subsection("Boundary stress");
        Functions::ParsedFunction<dim>::declare_parameters(prm, dim * dim);
        prm.leave_subsection();
        prm.enter_subsection("Body force");
        Functions::ParsedFunction<dim>::declare_parameters(prm, dim);
        prm.leave_subsection();
      }
      prm.leave_subsection();
      prm.enter_subsection("Exact solution");
      {
        Functions::ParsedFunction<dim>::declare_parameters(prm, dim);
        prm.declare_entry("Compute errors",
                          "false",
                          Patterns::Bool(),
                          "Compute the L2 and H1 error norms (eq. 7.3) "
                          "against the function of this subsection at every "
                          "load step and write them to summary.json.");
        prm.declare_entry("Gradient expression",
                          "",
                          Patterns::Anything(),
                          "Optional exact gradient du_i/dX_j, dim*dim "
                          "expressions separated by ';' in row-major order, "
                          "with the variables and constants of this "
                          "subsection. Empty: finite differences of the "
                          "exact solution (accurate to about 1e-8 only).");
      }
      prm.leave_subsection();
      Loading::declare_parameters(prm);
      Newton::declare_parameters(prm);
      LinearSolver::declare_parameters(prm);
      Analysis::declare_parameters(prm);
      Output::declare_parameters(prm);
      Time::declare_parameters(prm);
      prm.enter_subsection("Time");
      {
        // The variables are x, y[, z] (and t, unused); the constants as in
        // the other function subsections.
        prm.enter_subsection("Initial displacement");
        Functions::ParsedFunction<dim>::declare_parameters(prm, dim);
        prm.leave_subsection();
        prm.enter_subsection("Initial velocity");
        Functions::ParsedFunction<dim>::declare_parameters(prm, dim);
        prm.leave_subsection();
      }
      prm.leave_subsection();
    }



    template <int dim>
    void
    AllParameters<dim>::parse_parameters(ParameterHandler &prm)
    {
      dimension = prm.get_integer("Dimension");
      AssertThrow(dimension == dim, ExcInternalError());
      geometry.parse_parameters(prm);
      discretization.parse_parameters(prm);
      cpd.parse_parameters(prm);
      material.parse_parameters(prm);
      boundary_conditions.parse_parameters(prm, dim);
      prm.enter_subsection("Boundary conditions");
      {
        prm.enter_subsection("Prescribed displacement");
        prescribed_displacement.parse_parameters(prm);
        prm.leave_subsection();
        prm.enter_subsection("Traction");
        traction.parse_parameters(prm);
        prm.leave_subsection();
        prm.enter_subsection("Boundary stress");
        boundary_stress.parse_parameters(prm);
        prm.leave_subsection();
        prm.enter_subsection("Body force");
        body_force.parse_parameters(prm);
        {
          // every component the literal 0: assembly skips the evaluation
          const std::vector<std::string> components =
            Utilities::split_string_list(prm.get("Function expression"), ';');
          zero_body_force =
            std::all_of(components.begin(),
                        components.end(),
                        [](const std::string &c) {
                          return c == "0" || c == "0.0" || c == "0.";
                        });
        }
        prm.leave_subsection();
      }
      prm.leave_subsection();
      prm.enter_subsection("Exact solution");
      {
        exact_solution.parse_parameters(prm);
        compute_errors             = prm.get_bool("Compute errors");
        const std::string gradient = prm.get("Gradient expression");
        exact_gradient.reset();
        if (!gradient.empty())
          {
            exact_gradient = std::make_unique<FunctionParser<dim>>(dim * dim);
            std::map<std::string, double> constants;
            for (const std::string &c :
                 Utilities::split_string_list(prm.get("Function constants"),
                                              ','))
              {
                const auto parts = Utilities::split_string_list(c, '=');
                AssertThrow(
                  parts.size() == 2,
                  ExcBadParameter("Exact solution/Function constants",
                                  prm.get("Function constants"),
                                  "constants must read 'name=value'."));
                constants[parts[0]] = Utilities::string_to_double(parts[1]);
              }
            const std::vector<std::string> expressions =
              Utilities::split_string_list(gradient, ';');
            AssertThrow(expressions.size() == dim * dim,
                        ExcBadParameter("Exact solution/Gradient expression",
                                        gradient,
                                        "it needs dim*dim = " +
                                          std::to_string(dim * dim) +
                                          " expressions separated by ';'."));
            exact_gradient->initialize(prm.get("Variable names"),
                                       expressions,
                                       constants,
                                       true);
          }
      }
      prm.leave_subsection();
      loading.parse_parameters(prm);
      newton.parse_parameters(prm);
      linear_solver.parse_parameters(prm);
      analysis.parse_parameters(prm);
      output.parse_parameters(prm, dim);
      time.parse_parameters(prm);
      prm.enter_subsection("Time");
      {
        prm.enter_subsection("Initial displacement");
        initial_displacement.parse_parameters(prm);
        prm.leave_subsection();
        prm.enter_subsection("Initial velocity");
        initial_velocity.parse_parameters(prm);
        prm.leave_subsection();
      }
      prm.leave_subsection();

      // The corners and subdivisions matter only for the meshes that use
      // them; 'Mesh = file' in 3-D must not need 3-coordinate defaults.
      AssertThrow(geometry.mesh != "hyper rectangle" ||
                    (geometry.lower_corner.size() == dim &&
                     geometry.upper_corner.size() == dim),
                  ExcBadParameter("Geometry/Lower corner",
                                  "",
                                  "'Lower corner' and 'Upper corner' need " +
                                    std::to_string(dim) + " coordinates."));
      AssertThrow((geometry.mesh != "hyper rectangle" &&
                   geometry.mesh != "cook membrane") ||
                    geometry.subdivisions.size() == 1 ||
                    geometry.subdivisions.size() == dim,
                  ExcBadParameter("Geometry/Subdivisions",
                                  "",
                                  "it needs 1 or " + std::to_string(dim) +
                                    " values."));
      AssertThrow(dim == 2 || material.plane == "strain",
                  ExcBadParameter("Material/Plane",
                                  material.plane,
                                  "plane stress exists in 2-D only."));
    }



    unsigned int
    read_dimension(const std::string &filename)
    {
      std::ifstream file(filename);
      AssertThrow(file,
                  ExcMessage("The parameter file <" + filename +
                             "> cannot be read. Check the path."));
      ParameterHandler prm;
      prm.declare_entry("Dimension", "2", Patterns::Integer(2, 3));
      prm.parse_input(filename, "", true);
      return prm.get_integer("Dimension");
    }



    template struct AllParameters<2>;
    template struct AllParameters<3>;
  } // namespace Parameters
} // namespace pg
