// The unit cube as unstructured linear tetrahedra (Gmsh 4.8.4):
//   gmsh -3 -format msh2 -setnumber h 0.15 cube_tetrahedra.geo -o cube_tetrahedra.msh
// Physical surface ids as 'hyper rectangle' colorizes: 0 x=0, 1 x=1,
// 2 y=0, 3 y=1, 4 z=0, 5 z=1.
SetFactory("OpenCASCADE");
DefineConstant[h = {0.15, Name "mesh size"}];
Box(1) = {0, 0, 0, 1, 1, 1};
MeshSize{PointsOf{Volume{1};}} = h;
Physical Surface(0) = {1};
Physical Surface(1) = {2};
Physical Surface(2) = {3};
Physical Surface(3) = {4};
Physical Surface(4) = {5};
Physical Surface(5) = {6};
Physical Volume(0) = {1};
