#include <pg/base/exceptions.h>
#include <pg/base/parameter_utilities.h>
#include <pg/constraints/boundary_condition_parameters.h>

#include <deal.II/base/utilities.h>

#include <algorithm>
#include <cmath>
#include <string>

namespace pg
{
  namespace Parameters
  {
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
        prm.declare_entry(
          "Dirichlet node sets",
          "",
          Patterns::Anything(),
          "Comma-separated 'node set: components' items, e.g. 'nodelist_1: "
          "xyz, nodelist_2: y', for an Exodus II mesh file (.g, .e, .exo): "
          "the listed displacement components of every vertex in the named "
          "node set take the values of subsection 'Prescribed "
          "displacement', as Peridigm's 'Prescribed Displacement' on a "
          "'Node Set'. A node set is named by its name in the file or, if "
          "it has none, 'nodelist_<id>' (Peridigm's name); the banner lists "
          "the node sets of the file. The reaction of each node set is "
          "printed and written to summary.json ('node_set_reactions').");
        prm.declare_entry("Symmetry",
                          "",
                          Patterns::Anything(),
                          "Boundary ids of planar boundaries with zero "
                          "normal displacement, e.g. '1, 2'.");
        prm.declare_entry(
          "Symmetry treatment",
          "mirror",
          Patterns::Selection("mirror|constraint"),
          "How the meshfree families meet a 'Symmetry' plane. mirror: a "
          "particle within a horizon of the plane gets the mirror images "
          "of the particles across it as family members (across two or "
          "three planes at edges and corners), whose displacements are the "
          "reflections of their originals; the plane is then no boundary "
          "for the families, the VC correction and the loads, and a half "
          "or quarter model gives the full body's solution. The planes "
          "must be normal to coordinate axes; VC2, the VC option p and "
          "'Nearest neighbours' are not built for it (CPD is). constraint: n . "
          "u = 0 alone, the dissertation's treatment: the families are cut "
          "off at the plane, which makes the model softer than the full "
          "body (the 3-D punch's quarter, VCPBG Unl, n = 4, linear: +47 % "
          "against the reference where mirror and the full block give "
          "+15 %). Finite elements are the same either way.");
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
          "share is printed at start-up). At the edge of a loaded region "
          "(a traction that is zero on some of the faces of a particle, or "
          "another boundary id in the same plane: a load on part of a "
          "face) a particle gets (n . d^k) times the mean traction over its "
          "faces, int N_k T / int N_k, and the difference between the face "
          "integral of T over the id's meshfree faces and the sum of all "
          "its particle loads is spread over its loaded particles in "
          "proportion to int N_k |T|: the resultant of every partly loaded "
          "id is exact, while a traction that covers a whole face loads as eq. "
          "4.32 alone (patch tests). The set-up report prints resultant and "
          "moment of such ids beside the exact ones; summary.json has them "
          "for every Neumann id ('neumann_resultants'). 'automatic': 'test "
          "functions' "
          "for VC-corrected formulations, 'geometry' otherwise. 'exact "
          "stress' (patch tests): a particle on a Neumann boundary gets the "
          "test-function integral of the exact stress P(grad u) of "
          "subsection 'Exact solution' (the 'Traction' function is not "
          "used), sum_q w_q P(X_q) T^{qk} over its families; this is the "
          "discrete integral of N_k P n over the surface plus the body "
          "force, and equals P . d^k (eq. 4.32 with the full tensor) for a "
          "constant stress. The quadratic patch test needs it for a linear "
          "stress.");
        prm.enter_subsection("Rigid wall");
        {
          prm.declare_entry(
            "Normal",
            "",
            Patterns::Anything(),
            "Unit normal of a rigid, frictionless wall (plane), dim "
            "comma-separated components, pointing from the wall into the "
            "body's side, e.g. '0, 1' for a floor under the body. Empty: no "
            "wall. A non-unit vector is normalised. Walls must be normal to "
            "a coordinate axis ('0, 1', '-1, 0', '0, 0, 1', ...): the "
            "constraint of a held node is then a plain prescribed value of "
            "one displacement component. A node (mesh vertex, particle) "
            "whose position x = X + u would cross the plane, n . (x - p) < "
            "0, is held on it (its normal displacement is prescribed so that "
            "n . (x - p) = 0; tangential motion stays free); with 'Contact = "
            "unilateral' it is released when its reaction, the component n . "
            "(f_int - f_ext) at the node, turns tensile (< 0). Quasi-static "
            "runs start with the nodes that touch the wall held (so that a "
            "body pressed onto it by a load alone is supported), update "
            "this active set after each converged Newton solve "
            "and solve the load step again until it no longer changes (at "
            "most 'Maximum active set changes' times); Newmark runs do the "
            "same in every time step, with the reactions f_int - f_ext + M "
            "a. Explicit (leapfrog) runs update it once per time step, after "
            "the predictor (the dissertation's method): nodes that the "
            "predictor puts behind the wall are projected onto it and held "
            "at rest, nodes with a tensile reaction in the last step are "
            "released. Dirichlet and "
            "symmetry conditions on the same component win. The sum of the "
            "contact forces is printed and written to summary.json "
            "('wall_reaction', with 'wall_active_nodes' and 'wall_min_gap' = "
            "min n . (x - p) over all nodes).");
          prm.declare_entry("Point",
                            "",
                            Patterns::Anything(),
                            "A point of the wall plane, dim comma-separated "
                            "coordinates (mesh length units). Empty: the "
                            "origin. No node may lie behind the plane at "
                            "the start (n . (X - p) < 0).");
          prm.declare_entry(
            "Contact",
            "unilateral",
            Patterns::Selection("unilateral|two-sided"),
            "unilateral: a held node is released when its reaction turns "
            "tensile (no penetration, no adhesion). two-sided: a node is "
            "held once it has touched the wall and never released (the "
            "dissertation's implicit runs).");
          prm.declare_entry(
            "Maximum active set changes",
            "20",
            Patterns::Integer(1),
            "Quasi-static and Newmark runs: how many times one load or time "
            "step is solved again because nodes came into contact or were "
            "released; after "
            "that the step counts as not converged (and is cut like a "
            "Newton failure).");
        }
        prm.leave_subsection();
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
            const std::vector<types::boundary_id> ids =
              parse_ids(parts[0], "Boundary conditions/Dirichlet");
            AssertThrow(ids.size() == 1,
                        ExcBadParameter("Boundary conditions/Dirichlet",
                                        text,
                                        "each item must read 'boundary id: "
                                        "components', e.g. '0: xy'."));
            const types::boundary_id id = ids[0];
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
        dirichlet_node_sets.clear();
        const std::string sets = prm.get("Dirichlet node sets");
        const std::string sets_entry =
          "Boundary conditions/Dirichlet node sets";
        for (const auto &parts :
             parse_items(sets,
                         ',',
                         2,
                         sets_entry,
                         "each item must read 'node set: components', e.g. "
                         "'nodelist_1: xyz'."))
          {
            const std::string name = Utilities::trim(parts[0]);
            AssertThrow(!name.empty(),
                        ExcBadParameter(sets_entry,
                                        sets,
                                        "each item must read 'node set: "
                                        "components', e.g. 'nodelist_1: "
                                        "xyz'."));
            dirichlet_node_sets.emplace_back(
              name,
              parse_components(parts[1],
                               dim,
                               sets_entry,
                               sets,
                               ", e.g. 'nodelist_1: xyz'."));
          }
        symmetry =
          parse_ids(prm.get("Symmetry"), "Boundary conditions/Symmetry");
        mirror_symmetry = (prm.get("Symmetry treatment") == "mirror");
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
        prm.enter_subsection("Rigid wall");
        {
          const std::string normal_entry =
            "Boundary conditions/Rigid wall/Normal";
          const std::string normal_text = prm.get("Normal");
          rigid_wall                    = RigidWall();
          rigid_wall.enabled            = !Utilities::trim(normal_text).empty();
          if (rigid_wall.enabled)
            {
              rigid_wall.normal = parse_coordinates(normal_text,
                                                    dim,
                                                    normal_entry,
                                                    normal_text,
                                                    "the normal");
              double length     = 0;
              for (const double x : rigid_wall.normal)
                length += x * x;
              length = std::sqrt(length);
              AssertThrow(length > 0 && std::isfinite(length),
                          ExcBadParameter(normal_entry,
                                          normal_text,
                                          "the wall normal must be a "
                                          "non-zero vector, e.g. '0, 1' "
                                          "for a floor under the body."));
              unsigned int n_nonzero = 0;
              for (double &x : rigid_wall.normal)
                {
                  x /= length;
                  n_nonzero += (std::abs(x) > 1e-12);
                }
              AssertThrow(
                n_nonzero == 1,
                ExcBadParameter(normal_entry,
                                normal_text,
                                "walls must be normal to a coordinate axis "
                                "(e.g. '0, 1' or '-1, 0'): a held node's "
                                "constraint is a prescribed value of one "
                                "displacement component. Rotate the mesh so "
                                "that the wall is normal to an axis."));
              const std::string point_text = prm.get("Point");
              rigid_wall.point =
                Utilities::trim(point_text).empty() ?
                  std::vector<double>(dim, 0.) :
                  parse_coordinates(point_text,
                                    dim,
                                    "Boundary conditions/Rigid wall/Point",
                                    point_text,
                                    "the point");
            }
          rigid_wall.unilateral = (prm.get("Contact") == "unilateral");
          rigid_wall.maximum_set_changes =
            prm.get_integer("Maximum active set changes");
        }
        prm.leave_subsection();
      }
      prm.leave_subsection();
    }
  } // namespace Parameters
} // namespace pg
