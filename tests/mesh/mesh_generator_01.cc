// pg::Mesh::create_mesh and pg::Mesh::mark_meshfree_cells: the built-in
// meshes (cells, measure, boundary ids and the measure of each boundary
// part), the file reader, the reproducible random distortion (also on a
// parallel::shared::Triangulation), the meshfree regions, and the messages
// for bad input.

#include <pg/base/parameters.h>
#include <pg/mesh/mesh_generator.h>

#include <deal.II/base/mpi.h>
#include <deal.II/base/numbers.h>
#include <deal.II/base/parameter_handler.h>
#include <deal.II/base/utilities.h>
#include <deal.II/distributed/shared_tria.h>
#include <deal.II/grid/grid_generator.h>
#include <deal.II/grid/grid_out.h>
#include <deal.II/grid/grid_tools.h>
#include <deal.II/grid/tria.h>

#include "../geometry_fixture.h"
#include "../tests.h"

#include <algorithm>
#include <fstream>
#include <limits>
#include <map>
#include <sstream>
#include <string>
#include <vector>


namespace
{



  /** Cells, measure, boundary ids and the measure of each boundary part. */
  template <int dim>
  void
  print_mesh(const Triangulation<dim> &triangulation)
  {
    std::map<types::boundary_id, double> boundary_measure;
    for (const auto &cell : triangulation.active_cell_iterators())
      for (const auto &face : cell->face_iterators())
        if (face->at_boundary())
          boundary_measure[face->boundary_id()] += face->measure();

    deallog << "cells: " << triangulation.n_active_cells() << std::endl;
    print_rounded("measure", GridTools::volume(triangulation), 8);
    std::ostringstream ids;
    for (const auto &part : boundary_measure)
      ids << ' ' << static_cast<unsigned int>(part.first);
    deallog << "boundary ids:" << ids.str() << std::endl;
    for (const auto &part : boundary_measure)
      print_rounded("  boundary " +
                      std::to_string(static_cast<unsigned int>(part.first)) +
                      " measure",
                    part.second,
                    8);
  }



  /** Print the message of the exception that @p f throws. */
  template <typename Function>
  void
  print_error(const std::string &name, const Function &f)
  {
    try
      {
        f();
        deallog << name << ": no exception" << std::endl;
      }
    catch (const ExceptionBase &exc)
      {
        deallog << name << ": " << Utilities::trim(exception_message(exc))
                << std::endl;
      }
  }



  template <int dim>
  double
  max_vertex_difference(const Triangulation<dim> &a,
                        const Triangulation<dim> &b)
  {
    AssertThrow(a.n_vertices() == b.n_vertices(), ExcInternalError());
    double difference = 0;
    for (unsigned int v = 0; v < a.n_vertices(); ++v)
      difference =
        std::max(difference, a.get_vertices()[v].distance(b.get_vertices()[v]));
    return difference;
  }



  template <int dim>
  double
  min_cell_measure(const Triangulation<dim> &triangulation)
  {
    double measure = std::numeric_limits<double>::max();
    for (const auto &cell : triangulation.active_cell_iterators())
      measure = std::min(measure, cell->measure());
    return measure;
  }



  void
  test_hyper_rectangle()
  {
    deallog << "hyper rectangle 2-D [0,2]x[0,1], subdivisions 2,1 and 1 "
            << "refinement" << std::endl;
    {
      Triangulation<2> triangulation;
      pg::Mesh::create_mesh(geometry_parameters("set Upper corner = 2, 1\n"
                                                "set Subdivisions = 2, 1\n"
                                                "set Global refinement = 1\n"),
                            triangulation);
      print_mesh(triangulation);
    }

    deallog << "hyper rectangle 3-D [0,1]x[0,2]x[0,3], subdivisions 1 and 1 "
            << "refinement" << std::endl;
    {
      Triangulation<3> triangulation;
      pg::Mesh::create_mesh(geometry_parameters("set Lower corner = 0, 0, 0\n"
                                                "set Upper corner = 1, 2, 3\n"
                                                "set Subdivisions = 1\n"
                                                "set Global refinement = 1\n"),
                            triangulation);
      print_mesh(triangulation);
    }

    // 'Hole': the outer faces keep their colorized ids 0..2*dim-1 (the
    // cells are rebuilt without the hole), the hole's faces get 2*dim.
    // Expected: 2-D ids 0-3 of measure 3 each, id 4 of measure 4 (the
    // 1 x 1 hole); 3-D ids 0-5 of 9, id 6 of 6.
    deallog << "hyper rectangle with the hole box 1,1 : 2,2 (2-D) and "
            << "1,1,1 : 2,2,2 (3-D), 3 subdivisions" << std::endl;
    {
      Triangulation<2> triangulation;
      pg::Mesh::create_mesh(geometry_parameters("set Upper corner = 3, 3\n"
                                                "set Subdivisions = 3\n"
                                                "set Hole = box 1,1 : 2,2\n"),
                            triangulation);
      print_mesh(triangulation);
    }
    {
      Triangulation<3> triangulation;
      pg::Mesh::create_mesh(geometry_parameters(
                              "set Lower corner = 0, 0, 0\n"
                              "set Upper corner = 3, 3, 3\n"
                              "set Subdivisions = 3\n"
                              "set Hole = box 1,1,1 : 2,2,2\n"),
                            triangulation);
      print_mesh(triangulation);
    }
  }



  void
  test_cook_membrane()
  {
    deallog << "cook membrane, subdivisions 2 and 1 refinement (area 1440, "
            << "edges 44, 16, sqrt(4240) = 65.115282, sqrt(2560) = 50.596443)"
            << std::endl;
    Triangulation<2> triangulation;
    pg::Mesh::create_mesh(geometry_parameters("set Mesh = cook membrane\n"
                                              "set Subdivisions = 2\n"
                                              "set Global refinement = 1\n"),
                          triangulation);
    print_mesh(triangulation);
    print_bound("|area - 1440|",
                GridTools::volume(triangulation) - 1440.,
                1e-10);

    deallog << "cook membrane 3-D, thickness 10, subdivisions 4, 4, 2 "
            << "(volume 14400; faces 440, 160, 651.15282, 505.96443, 1440, "
            << "1440)" << std::endl;
    Triangulation<3> triangulation_3d;
    pg::Mesh::create_mesh(geometry_parameters("set Mesh = cook membrane\n"
                                              "set Subdivisions = 4, 4, 2\n"
                                              "set Thickness = 10\n"),
                          triangulation_3d);
    print_mesh(triangulation_3d);
    print_bound("|volume - 14400|",
                GridTools::volume(triangulation_3d) - 14400.,
                1e-9);
  }



  void
  test_plate_with_hole()
  {
    const double L     = 4;
    const double R     = 1;
    const double exact = L * L - numbers::PI * R * R / 4.;
    for (const unsigned int refinement : {2U, 3U})
      {
        deallog << "plate with hole L = 4, R = 1, " << refinement
                << " refinements" << std::endl;
        Triangulation<2> triangulation;
        pg::Mesh::create_mesh(geometry_parameters("set Mesh = plate with hole\n"
                                                  "set Plate size = 4\n"
                                                  "set Hole radius = 1\n"
                                                  "set Global refinement = " +
                                                  std::to_string(refinement) +
                                                  "\n"),
                              triangulation);
        print_mesh(triangulation);
        print_rounded("relative area error",
                      (GridTools::volume(triangulation) - exact) / exact,
                      3);

        double            max_deviation = 0;
        unsigned int      hole_vertices = 0;
        std::vector<bool> seen(triangulation.n_vertices(), false);
        for (const auto &cell : triangulation.active_cell_iterators())
          for (const auto &face : cell->face_iterators())
            if (face->at_boundary() && face->boundary_id() == 0)
              for (const unsigned int v : face->vertex_indices())
                if (!seen[face->vertex_index(v)])
                  {
                    seen[face->vertex_index(v)] = true;
                    ++hole_vertices;
                    max_deviation =
                      std::max(max_deviation,
                               std::abs(face->vertex(v).norm() - R));
                  }
        deallog << "hole vertices: " << hole_vertices << std::endl;
        print_bound("max |distance of hole vertex - R|", max_deviation, 1e-12);
        deallog << "all cell measures positive: "
                << (min_cell_measure(triangulation) > 0 ? "yes" : "no")
                << std::endl;
      }
  }



  void
  test_distortion()
  {
    deallog << "distortion 0.3 of [0,1]^2, 8x8 cells (h = 1/8)" << std::endl;
    const std::string entries = "set Subdivisions = 4\n"
                                "set Global refinement = 1\n";
    Triangulation<2>  regular, seed_0, seed_0_again, seed_1;
    pg::Mesh::create_mesh(geometry_parameters(entries), regular);
    pg::Mesh::create_mesh(geometry_parameters(entries +
                                              "set Distortion = 0.3\n"),
                          seed_0);
    pg::Mesh::create_mesh(geometry_parameters(entries +
                                              "set Distortion = 0.3\n"),
                          seed_0_again);
    pg::Mesh::create_mesh(geometry_parameters(entries +
                                              "set Distortion = 0.3\n" +
                                              "set Random seed = 1\n"),
                          seed_1);

    deallog << "same seed, max vertex difference: "
            << max_vertex_difference(seed_0, seed_0_again) << std::endl;
    deallog << "seeds 0 and 1 differ: "
            << (max_vertex_difference(seed_0, seed_1) > 1e-3 ? "yes" : "no")
            << std::endl;

    // Boundary vertices stay, interior vertices move by 0.3 h exactly (the
    // shortest adjacent edge of the regular mesh is h).
    const std::map<unsigned int, Point<2>> boundary =
      GridTools::get_all_vertices_at_boundary(regular);
    double boundary_shift = 0;
    double min_shift      = std::numeric_limits<double>::max();
    double max_shift      = 0;
    for (unsigned int v = 0; v < regular.n_vertices(); ++v)
      {
        const double shift =
          regular.get_vertices()[v].distance(seed_0.get_vertices()[v]);
        if (boundary.find(v) != boundary.end())
          boundary_shift = std::max(boundary_shift, shift);
        else
          {
            min_shift = std::min(min_shift, shift);
            max_shift = std::max(max_shift, shift);
          }
      }
    deallog << "boundary vertices moved by at most: " << boundary_shift
            << std::endl;
    print_rounded("min interior shift / h", min_shift * 8, 6);
    print_rounded("max interior shift / h", max_shift * 8, 6);
    deallog << "all cell measures positive: "
            << (min_cell_measure(seed_0) > 0 ? "yes" : "no") << std::endl;
    print_bound("|area - 1|", GridTools::volume(seed_0) - 1., 1e-12);

    // The same mesh on a parallel::shared::Triangulation.
    parallel::shared::Triangulation<2> shared(MPI_COMM_WORLD);
    pg::Mesh::create_mesh(geometry_parameters(entries +
                                              "set Distortion = 0.3\n"),
                          shared);
    deallog << "shared triangulation, max vertex difference to serial: "
            << max_vertex_difference(seed_0, shared) << std::endl;

    deallog << "distortion 0.3 of [0,1]^3, 4x4x4 cells" << std::endl;
    Triangulation<3>  regular_3d, distorted_3d;
    const std::string entries_3d = "set Lower corner = 0, 0, 0\n"
                                   "set Upper corner = 1, 1, 1\n"
                                   "set Subdivisions = 2\n"
                                   "set Global refinement = 1\n";
    pg::Mesh::create_mesh(geometry_parameters(entries_3d), regular_3d);
    pg::Mesh::create_mesh(geometry_parameters(entries_3d +
                                              "set Distortion = 0.3\n"),
                          distorted_3d);
    print_rounded("max vertex shift / h",
                  max_vertex_difference(regular_3d, distorted_3d) * 4,
                  6);
    deallog << "all cell measures positive: "
            << (min_cell_measure(distorted_3d) > 0 ? "yes" : "no") << std::endl;
    print_bound("|volume - 1|", GridTools::volume(distorted_3d) - 1., 1e-12);

    deallog << "distortion 0.3 of the plate with hole, 2 refinements"
            << std::endl;
    Triangulation<2> plate;
    pg::Mesh::create_mesh(geometry_parameters("set Mesh = plate with hole\n"
                                              "set Global refinement = 2\n"
                                              "set Distortion = 0.3\n"),
                          plate);
    deallog << "all cell measures positive: "
            << (min_cell_measure(plate) > 0 ? "yes" : "no") << std::endl;
  }



  void
  test_file()
  {
    deallog << "file: a 2x1 rectangle written by GridOut and read back"
            << std::endl;
    {
      Triangulation<2> original;
      GridGenerator::subdivided_hyper_rectangle(original,
                                                {2, 1},
                                                Point<2>(0, 0),
                                                Point<2>(2, 1),
                                                true);
      std::ofstream out("mesh_generator_01.msh");
      GridOut       grid_out;
      grid_out.set_flags(GridOutFlags::Msh(/*write_faces=*/true));
      grid_out.write_msh(original, out);
    }
    Triangulation<2> triangulation;
    pg::Mesh::create_mesh(geometry_parameters(
                            "set Mesh = file\n"
                            "set File name = mesh_generator_01.msh\n"
                            "set Global refinement = 1\n"),
                          triangulation);
    print_mesh(triangulation);

    {
      std::ofstream out("mesh_generator_01_broken.msh");
      out << "this is not a mesh\n";
    }
    print_error("broken file", []() {
      Triangulation<2> triangulation;
      pg::Mesh::create_mesh(geometry_parameters(
                              "set Mesh = file\n"
                              "set File name = "
                              "mesh_generator_01_broken.msh\n"),
                            triangulation);
    });
  }



  void
  test_meshfree_regions()
  {
    deallog << "meshfree regions on [0,1]^2 with 4x4 cells; material id 1 "
            << "for x < 0.5, 2 for x > 0.5 and y > 0.75" << std::endl;
    Triangulation<2> triangulation;
    pg::Mesh::create_mesh(geometry_parameters("set Subdivisions = 4\n"),
                          triangulation);
    for (const auto &cell : triangulation.active_cell_iterators())
      if (cell->center()[0] < 0.5)
        cell->set_material_id(1);
      else if (cell->center()[1] > 0.75)
        cell->set_material_id(2);

    const auto count = [](const std::vector<bool> &meshfree) {
      return std::count(meshfree.begin(), meshfree.end(), true);
    };
    for (const std::string region : {"all",
                                     "none",
                                     "material ids 1, 2",
                                     "material ids 2",
                                     "box 0,0 : 0.5,0.5",
                                     "box 0.375,0.375 : 0,0",
                                     "ball 0.5,0.5 : 0.3",
                                     "ball 0.5, 0.5 : 0.4"})
      deallog << "'" << region << "': "
              << count(pg::Mesh::mark_meshfree_cells(
                   geometry_parameters("set Meshfree region = " + region +
                                       "\n"),
                   triangulation))
              << " of " << triangulation.n_active_cells() << std::endl;

    deallog << "meshfree regions on [0,1]^3 with 4x4x4 cells" << std::endl;
    Triangulation<3> triangulation_3d;
    pg::Mesh::create_mesh(geometry_parameters("set Lower corner = 0, 0, 0\n"
                                              "set Upper corner = 1, 1, 1\n"
                                              "set Subdivisions = 4\n"),
                          triangulation_3d);
    for (const std::string region :
         {"all", "box 0,0,0 : 0.5,0.5,1", "ball 0.5,0.5,0.5 : 0.25"})
      deallog << "'" << region << "': "
              << count(pg::Mesh::mark_meshfree_cells(
                   geometry_parameters("set Meshfree region = " + region +
                                       "\n"),
                   triangulation_3d))
              << " of " << triangulation_3d.n_active_cells() << std::endl;
  }



  void
  test_errors()
  {
    deallog << "errors" << std::endl;
    print_error("missing file", []() {
      Triangulation<2> triangulation;
      pg::Mesh::create_mesh(geometry_parameters(
                              "set Mesh = file\n"
                              "set File name = no_such_mesh.msh\n"),
                            triangulation);
    });
    print_error("unknown extension", []() {
      Triangulation<2> triangulation;
      pg::Mesh::create_mesh(geometry_parameters("set Mesh = file\n"
                                                "set File name = mesh.vtk\n"),
                            triangulation);
    });
    print_error("cook membrane in 3-D with thickness 0", []() {
      Triangulation<3> triangulation;
      pg::Mesh::create_mesh(geometry_parameters("set Mesh = cook membrane\n"
                                                "set Thickness = 0\n"),
                            triangulation);
    });
    print_error("plate with hole in 3-D", []() {
      Triangulation<3> triangulation;
      pg::Mesh::create_mesh(geometry_parameters("set Mesh = plate with hole\n"),
                            triangulation);
    });
    print_error("2 corner coordinates in 3-D", []() {
      Triangulation<3> triangulation;
      pg::Mesh::create_mesh(geometry_parameters("set Subdivisions = 1\n"),
                            triangulation);
    });
    print_error("2 subdivisions in 3-D", []() {
      Triangulation<3> triangulation;
      pg::Mesh::create_mesh(geometry_parameters("set Lower corner = 0, 0, 0\n"
                                                "set Upper corner = 1, 1, 1\n"
                                                "set Subdivisions = 1, 2\n"),
                            triangulation);
    });
    // Cells that the random shifts make non-convex are drawn again: the
    // plate with a hole (angles up to 134 degrees) takes 'Distortion = 0.3'
    // at every level, and Cook's membrane 0.45.
    print_error("distortion 0.3 of the plate with a hole, 5 refinements", []() {
      Triangulation<2> triangulation;
      pg::Mesh::create_mesh(geometry_parameters("set Mesh = plate with hole\n"
                                                "set Global refinement = 5\n"
                                                "set Distortion = 0.3\n"),
                            triangulation);
    });
    print_error("distortion 0.45 of the cook membrane, 3 refinements", []() {
      Triangulation<2> triangulation;
      pg::Mesh::create_mesh(geometry_parameters("set Mesh = cook membrane\n"
                                                "set Subdivisions = 2\n"
                                                "set Global refinement = 3\n"
                                                "set Distortion = 0.45\n"),
                            triangulation);
    });
    // 2 x 2 cells whose centre vertex (0.2, 0.2) lies inside the triangle
    // (0,0), (1,0), (0,1): the first cell is an arrow head, and shifts of up
    // to 0.05 x its shortest edge cannot make it convex.
    print_error("distortion of a mesh with a non-convex cell", []() {
      {
        std::ofstream out("mesh_generator_01_arrow.ucd");
        out << "9 4 0 0 0\n"
            << "1 0 0 0\n2 1 0 0\n3 2 0 0\n4 0 1 0\n5 0.2 0.2 0\n"
            << "6 2 1 0\n7 0 2 0\n8 1 2 0\n9 2 2 0\n"
            << "1 0 quad 1 2 5 4\n2 0 quad 2 3 6 5\n"
            << "3 0 quad 4 5 8 7\n4 0 quad 5 6 9 8\n";
      }
      Triangulation<2> triangulation;
      pg::Mesh::create_mesh(geometry_parameters("set Mesh = file\n"
                                                "set File name = "
                                                "mesh_generator_01_arrow.ucd\n"
                                                "set Distortion = 0.05\n"),
                            triangulation);
    });

    Triangulation<2> triangulation;
    pg::Mesh::create_mesh(geometry_parameters(""), triangulation);
    for (const std::string region :
         {"box 0,0 : 1", "sphere 0,0 : 1", "material ids a", "ball 0,0 : -1"})
      print_error("meshfree region '" + region + "'", [&]() {
        pg::Mesh::mark_meshfree_cells(
          geometry_parameters("set Meshfree region = " + region + "\n"),
          triangulation);
      });
  }
} // namespace



int
main(int argc, char *argv[])
{
  Utilities::MPI::MPI_InitFinalize mpi(argc, argv, 1);
  initlog();

  test_hyper_rectangle();
  test_cook_membrane();
  test_plate_with_hole();
  test_distortion();
  test_file();
  test_meshfree_regions();
  test_errors();
}
