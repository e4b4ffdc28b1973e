// Kirsch's plate with a hole (prm/plate_with_hole_triangles.prm): the
// quarter [0, L]^2 minus the disk of radius R = 1 around the origin, L = 4,
// meshed with unstructured linear triangles of size h, h/2 at the hole
// (Gmsh's default Frontal-Delaunay algorithm: the particles are
// irregular). The
// physical line tags are the boundary ids of pg's built-in 'plate with
// hole' mesh, so the same boundary conditions apply:
//   0 hole, 1 x = 0, 2 y = 0, 3 x = L, 4 y = L.
// The hole is a polygon through the mesh's vertices on the circle.
//
//   gmsh -2 -format msh2 -setnumber h 0.2 plate_with_hole_triangles.geo \
//        -o plate_with_hole_triangles_h0.2.msh
//
// (doc/benchmarks/plate_with_hole_triangles.sh makes the series h = 0.4,
// 0.2, 0.1, 0.05, 0.025; the first three are committed next to this file.)
If (!Exists(h))
  h = 0.4;
EndIf
L = 4;
R = 1;

Point(1) = {0, 0, 0, h}; // centre of the hole
Point(2) = {R, 0, 0, h / 2}; // finer at the hole, where the stress concentrates
Point(3) = {L, 0, 0, h};
Point(4) = {L, L, 0, h};
Point(5) = {0, L, 0, h};
Point(6) = {0, R, 0, h / 2};

Line(1)   = {2, 3}; // y = 0
Line(2)   = {3, 4}; // x = L
Line(3)   = {4, 5}; // y = L
Line(4)   = {5, 6}; // x = 0
Circle(5) = {6, 1, 2}; // the hole

Curve Loop(1)     = {1, 2, 3, 4, 5};
Plane Surface(1)  = {1};

Physical Curve(0) = {5};
Physical Curve(1) = {4};
Physical Curve(2) = {1};
Physical Curve(3) = {2};
Physical Curve(4) = {3};
Physical Surface(1) = {1};
