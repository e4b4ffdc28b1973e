#include <pg/base/exceptions.h>
#include <pg/base/formulation_code.h>
#include <pg/base/parameters.h>
#include <pg/base/shared_libraries.h>
#include <pg/materials/material.h>
#include <pg/materials/volumetric_split.h>

#include <deal.II/base/utilities.h>
#include <deal.II/lac/vector.h>

#include <algorithm>
#include <cmath>
#include <fstream>
#include <iostream>
#include <sstream>

namespace pg
{
  namespace Parameters
  {
    namespace
    {
      /**
       * function.parse_parameters(prm) in the subsection @p path, and one
       * evaluation at the origin (muParser parses an expression when it is
       * first evaluated): a wrong number of expressions, a syntax error or
       * an unknown name is reported for the entry '@p path/Function
       * expression' with its value, before any work is done. deal.II's own
       * report of a parser error on std::cerr is held back; the message
       * carries it.
       */
      template <int dim>
      void
      parse_function(ParameterHandler               &prm,
                     Functions::ParsedFunction<dim> &function,
                     const std::string              &path)
      {
        const std::string entry      = path + "/Function expression";
        const std::string expression = prm.get("Function expression");
        // deal.II reads each constant with string_to_double(), which stops
        // at the first character that is not part of a number: 'a=10*pi/180'
        // would silently be a = 10.
        const std::string constants = prm.get("Function constants");
        for (const std::string &item :
             Utilities::split_string_list(constants, ','))
          {
            const auto        equals = item.find('=');
            const std::string value  = Utilities::trim(
              equals == std::string::npos ? std::string() :
                                            item.substr(equals + 1));
            bool is_number = !value.empty();
            try
              {
                std::size_t end = 0;
                std::stod(value, &end);
                is_number = is_number && (end == value.size());
              }
            catch (...)
              {
                is_number = false;
              }
            AssertThrow(is_number,
                        ExcBadParameter(path + "/Function constants",
                                        constants,
                                        "the item <" + Utilities::trim(item) +
                                          "> is not 'name=number' (deal.II "
                                          "would read '10*pi/180' as 10). "
                                          "Give each constant as a plain "
                                          "number, e.g. 'a=0.174533', or "
                                          "write the formula into 'Function "
                                          "expression'."));
          }
        const std::string how =
          " Write one expression in x, y" + std::string(dim == 3 ? ", z" : "") +
          " and t per component, separated by ';' (constants in 'Function "
          "constants', e.g. 'E=1, nu=0.3').";
        std::string error;
        try
          {
            function.parse_parameters(prm);
          }
        catch (const std::exception &exc)
          {
            error = one_line(user_message(exc));
          }
        AssertThrow(error.empty(),
                    ExcBadParameter(entry,
                                    expression,
                                    "deal.II's FunctionParser rejects it: " +
                                      error + how));
        std::ostringstream    held_back;
        std::streambuf *const screen = std::cerr.rdbuf(held_back.rdbuf());
        try
          {
            Vector<double> values(function.n_components);
            function.vector_value(Point<dim>(), values);
          }
        catch (const std::exception &exc)
          {
            error = one_line(user_message(exc));
          }
        std::cerr.rdbuf(screen);
        if (!error.empty() && error.back() != '.')
          error += '.';
        AssertThrow(error.empty(),
                    ExcBadParameter(entry,
                                    expression,
                                    "muParser cannot evaluate it: " + error +
                                      how));
      }
    } // namespace



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
      declare_additional_shared_libraries(prm);
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
        parse_function(prm,
                       prescribed_displacement,
                       "Boundary conditions/Prescribed displacement");
        prm.leave_subsection();
        prm.enter_subsection("Traction");
        parse_function(prm, traction, "Boundary conditions/Traction");
        prm.leave_subsection();
        prm.enter_subsection("Boundary stress");
        parse_function(prm,
                       boundary_stress,
                       "Boundary conditions/Boundary stress");
        prm.leave_subsection();
        prm.enter_subsection("Body force");
        parse_function(prm, body_force, "Boundary conditions/Body force");
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
        parse_function(prm, exact_solution, "Exact solution");
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
        parse_function(prm, initial_displacement, "Time/Initial displacement");
        prm.leave_subsection();
        prm.enter_subsection("Initial velocity");
        parse_function(prm, initial_velocity, "Time/Initial velocity");
        prm.leave_subsection();
      }
      prm.leave_subsection();

      // The corners and subdivisions matter only for the meshes that use
      // them; 'Mesh = file' in 3-D must not need 3-coordinate defaults.
      if (geometry.mesh == "hyper rectangle")
        for (const auto &[name, corner] :
             {std::make_pair("Lower corner", &geometry.lower_corner),
              std::make_pair("Upper corner", &geometry.upper_corner)})
          {
            std::string value;
            for (const double x : *corner)
              value += (value.empty() ? "" : ", ") + Utilities::to_string(x);
            AssertThrow(corner->size() == dim,
                        ExcBadParameter(std::string("Geometry/") + name,
                                        value,
                                        "a corner of the hyper rectangle "
                                        "needs " +
                                          std::to_string(dim) +
                                          " coordinates ('set Dimension = " +
                                          std::to_string(dim) + "'), e.g. " +
                                          (dim == 2 ? "'0, 0'." :
                                                      "'0, 0, 0'.")));
          }
      // Upper above lower in every coordinate (issue 45, item 3): a box
      // given the wrong way round was built, and reported only later, by
      // the points, as "this point lies outside the mesh".
      if (geometry.mesh == "hyper rectangle")
        {
          const auto number = [](const double x) {
            std::ostringstream s;
            s << x;
            return s.str();
          };
          const auto text = [&](const std::vector<double> &corner) {
            std::string value;
            for (const double x : corner)
              value += (value.empty() ? "" : ", ") + number(x);
            return value;
          };
          std::string wrong;
          for (unsigned int d = 0; d < dim; ++d)
            if (!(geometry.upper_corner[d] > geometry.lower_corner[d]))
              wrong += std::string(wrong.empty() ? "" : ", ") + "xyz"[d] +
                       ": " + number(geometry.upper_corner[d]) +
                       " <= " + number(geometry.lower_corner[d]);
          AssertThrow(wrong.empty(),
                      ExcBadParameter("Geometry/Upper corner",
                                      text(geometry.upper_corner),
                                      "it must exceed 'Geometry/Lower "
                                      "corner' <" +
                                        text(geometry.lower_corner) +
                                        "> in every coordinate (" + wrong +
                                        "): the hyper rectangle is the box "
                                        "from the lower to the upper "
                                        "corner."));
        }
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
      // The mixed codes (UnlP0, FEM Q1P0) condense p and Theta per element
      // with the isochoric/volumetric split.
      const FormulationCode code =
        parse_formulation_code(discretization.formulation);
      AssertThrow(discretization.hourglass_coefficient == 0. ||
                    (code.points == FormulationCode::Points::u1 &&
                     !code.implicit_gradients),
                  ExcBadParameter(
                    "Discretization/Hourglass coefficient",
                    Utilities::to_string(discretization.hourglass_coefficient),
                    "the hourglass force stabilises the underintegrated "
                    "families U1 (classical correspondence), and the "
                    "formulation is <" +
                      code.text +
                      ">. Use 'Formulation = PBG U1' (Peridigm's "
                      "correspondence) or set the coefficient to 0; "
                      "'VCPBG U1SUnl' and 'VCPBG U1SIG' are the "
                      "dissertation's stabilised U1 (without an hourglass "
                      "force)."));
      AssertThrow(discretization.self_weight_distance > 0.,
                  ExcBadParameter(
                    "Discretization/Self-weight distance",
                    Utilities::to_string(discretization.self_weight_distance),
                    "the master's weight in U1SIG's MLS1 second derivatives "
                    "is that of a member at this distance; it must be "
                    "positive (default 0.001)."));
      // nu = 0.5 is the incompressible IUnlP0's, and IUnlP0 needs it
      AssertThrow(
        !material.incompressible() || code.incompressible(),
        ExcBadParameter(
          "Material/Poisson's ratio",
          "0.5",
          "at 0.5 the material is incompressible, lambda is infinite, and "
          "the formulation <" +
            code.text +
            "> (subsection 'Discretization') would lock or divide by zero. "
            "Use the incompressible mixed formulation 'VCPBG V5sn IUnlP0' "
            "(or 'VCPPG V3sn IUnlP0'), or a nearly incompressible nu such as "
            "0.4999 with a mixed code ('VCPBG V5sn UnlP0', 'VCPBG V5sn "
            "Unl+P1C', 'FEM Q1P0')."));
      std::ostringstream nu_text;
      nu_text << material.poissons_ratio;
      AssertThrow(
        material.incompressible() || !code.incompressible(),
        ExcBadParameter(
          "Material/Poisson's ratio",
          nu_text.str(),
          "the formulation <" + code.text +
            "> (subsection 'Discretization') is exactly incompressible "
            "(Theta = 1, Table 7.1): set 'Poisson's ratio = 0.5' with "
            "'Young's modulus' = 3 mu (and no 'Bulk modulus' or 'Shear "
            "modulus'), or use the compressible 'VCPBG V5sn UnlP0' for nu < "
            "0.5."));
      if (code.mixed())
        {
          // (any registered model that offers the split: the two built-in
          // ones, or e.g. a model with history whose isochoric part carries
          // it)
          AssertThrow(material.model == "isochoric-volumetric neo-Hooke" ||
                        material.model == "linear elastic" ||
                        dynamic_cast<const Materials::VolumetricSplit<dim> *>(
                          Materials::create_material<dim>(material).get()) !=
                          nullptr,
                      ExcBadParameter(
                        "Material/Model",
                        material.model,
                        "the formulation <" + code.text +
                          "> (subsection 'Discretization') is mixed: it "
                          "has a pressure and a dilatation (per element, or "
                          "nodal for U2P1C and Unl+P1C; eqs. 6.2, 6.3), "
                          "which needs the split of the "
                          "energy into isochoric and volumetric parts (eqs. "
                          "2.43-2.44). Set 'Model = isochoric-volumetric "
                          "neo-Hooke' (finite strain; with 'Bulk modulus' and "
                          "'Shear modulus', or 'Young's modulus' and "
                          "'Poisson's ratio') or 'linear elastic', or choose "
                          "a displacement formulation."));
          AssertThrow(dim == 3 || material.plane == "strain",
                      ExcBadParameter("Material/Plane",
                                      material.plane,
                                      "the mixed formulation <" + code.text +
                                        "> needs plane strain: plane stress "
                                        "has no volumetric constraint (and "
                                        "does not lock)."));
        }
      if (code.n_nodal_fields() > 0)
        {
          // p (and Theta) are global unknowns: a saddle-point system
          // (pg-methods.md section 15), and no mass for them
          AssertThrow(linear_solver.type == "direct",
                      ExcBadParameter(
                        "Linear solver/Type",
                        linear_solver.type,
                        "the formulation <" + code.text + "> has the pressure" +
                          (code.incompressible() ?
                             std::string(" of every family as a global") :
                             std::string(" and the dilatation as nodal")) +
                          " unknowns, so its tangent is an indefinite "
                          "saddle-point matrix that CG and GMRES with "
                          "algebraic multigrid do not solve. Set 'Type = "
                          "direct'."));
          const std::string unknowns =
            code.incompressible() ?
              std::string("> (a global pressure per family)") :
              std::string("> (nodal pressure and dilatation)");
          AssertThrow(
            analysis.type != "inf-sup",
            ExcBadParameter(
              "Analysis/Type",
              analysis.type,
              "the formulation <" + code.text + unknowns +
                " has no inf-sup test of its own: " +
                (code.incompressible() ?
                   std::string("the inf-sup test of IUnlP0 is that of "
                               "UnlP0, on its displacement formulation: "
                               "'Formulation = BCPBG Unl' with 'Pressure "
                               "space = P0'.") :
                   std::string("the inf-sup test of Unl+P1C (U2P1C) runs "
                               "on its displacement formulation: "
                               "'Formulation = BCPBG Unl' ('PBG U2') with "
                               "'Pressure space = P1C+bubble' ('P1C')."))));
          // p (and Theta) have no mass: a differential-algebraic system
          AssertThrow(
            time.integrator != "leapfrog",
            ExcBadParameter("Time/Integrator",
                            time.integrator,
                            "the formulation <" + code.text + unknowns +
                              " has pressure unknowns without mass (a "
                              "differential-algebraic system), which an "
                              "explicit integrator cannot advance. Use "
                              "'Integrator = newmark' with a 'Time step', or "
                              "the condensed mixed formulation 'VCPBG V5sn "
                              "UnlP0' with leapfrog."));
          AssertThrow(
            !time.dynamic() || time.time_step > 0,
            ExcBadParameter("Time/Time step",
                            "0",
                            "the automatic step is the central-difference "
                            "limit 2/omega_max of M^-1 K, which does not exist "
                            "when the pressure unknowns of the formulation <" +
                              code.text +
                              "> have no mass. Set a step: Newmark is "
                              "unconditionally stable, and 20 steps per period "
                              "of the slowest mode you want to resolve are a "
                              "start."));
        }
    }



    template <int dim>
    void
    AllParameters<dim>::set_load_factor(const double t) const
    {
      // ParsedFunction::set_time() is the only thing that changes the
      // parameters during a run, so it is done here, in one place.
      for (const Functions::ParsedFunction<dim> *function :
           {&prescribed_displacement,
            &traction,
            &boundary_stress,
            &body_force,
            &exact_solution})
        const_cast<Functions::ParsedFunction<dim> *>(function)->set_time(t);
      if (exact_gradient)
        exact_gradient->set_time(t);
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
