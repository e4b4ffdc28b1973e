// Cook's membrane in 3-D as a Gmsh geometry (benchmark B-12 on tetrahedral
// particle sets, doc/benchmarks/cook_3d.md): the panel (0,0), (48,44),
// (48,60), (0,44) in x-y extruded by 10 in z, the geometry of
// 'Mesh = cook membrane' with 'Thickness = 10' in prm/cook_membrane_3d.prm.
//
// Physical surface ids are the boundary ids of that mesh: 0 left face
// (x = 0, clamped), 1 right face (x = 48, loaded), 2 bottom, 3 top, 4 front
// (z = 0), 5 back (z = 10). Every boundary face needs an id: deal.II gives
// faces of no physical surface the id 0 (clamped here).
//
// The mesh-size parameter h (length) is the target edge length of the
// unstructured tetrahedra; a linear tetrahedral mesh in MSH 2.2 (what
// deal.II 9.4's GridIn reads) of about 14,400 / (0.12 h^3) vertices:
//   gmsh -3 -format msh2 -setnumber h 3 prm/cook_membrane_3d_tets.geo -o cook_h3.msh
// and in the parameter file: Mesh = file, File name = cook_h3.msh.
DefineConstant[h = {6, Name "mesh size"}];

Point(1) = {0, 0, 0, h};
Point(2) = {48, 44, 0, h};
Point(3) = {48, 60, 0, h};
Point(4) = {0, 44, 0, h};
Line(1) = {1, 2}; // bottom
Line(2) = {2, 3}; // right
Line(3) = {3, 4}; // top
Line(4) = {4, 1}; // left
Curve Loop(1) = {1, 2, 3, 4};
Plane Surface(1) = {1};

// out[0]: the face at z = 10, out[1]: the volume, out[2..5]: the faces
// swept by lines 1..4
out[] = Extrude {0, 0, 10} { Surface{1}; };

Physical Surface(0) = {out[5]}; // left, x = 0
Physical Surface(1) = {out[3]}; // right, x = 48
Physical Surface(2) = {out[2]}; // bottom
Physical Surface(3) = {out[4]}; // top
Physical Surface(4) = {1};      // front, z = 0
Physical Surface(5) = {out[0]}; // back, z = 10
Physical Volume(0) = {out[1]};
