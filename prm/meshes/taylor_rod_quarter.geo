// Quarter of the Taylor anvil rod (benchmark B-15/B-16, dissertation
// section 7.3.7): radius R, length L, axis along z, impact end at z = 0,
// symmetry planes x = 0 and y = 0. Hexahedra: a square core (side a = R/2)
// and two curved blocks, N cells on each of their edges in the cross
// section (3 N^2 cells per layer), NZ layers along z.
// Physical tags = deal.II ids: boundary 1 (x = 0), 2 (y = 0), 3 (z = 0,
// impact end), 4 (z = L), 5 (mantle); volume 0.
// Usage: gmsh -3 -format msh2 -setnumber N 2 -setnumber NZ 20 taylor_rod_quarter.geo -o rod.msh
// (B-16: -setnumber L 12.8). Units: mm.
If (!Exists(R))
  R = 3.2;
EndIf
If (!Exists(L))
  L = 32.4;
EndIf
If (!Exists(N))
  N = 2;
EndIf
If (!Exists(NZ))
  NZ = 20;
EndIf
a = R / 2;
c = R / Sqrt(2);
Point(1) = {0, 0, 0};
Point(2) = {a, 0, 0};
Point(3) = {a, a, 0};
Point(4) = {0, a, 0};
Point(5) = {R, 0, 0};
Point(6) = {c, c, 0};
Point(7) = {0, R, 0};
Line(1) = {1, 2};
Line(2) = {2, 3};
Line(3) = {3, 4};
Line(4) = {4, 1};
Line(5) = {2, 5};
Circle(6) = {5, 1, 6};
Line(7) = {6, 3};
Circle(8) = {6, 1, 7};
Line(9) = {7, 4};
Curve Loop(1) = {1, 2, 3, 4};
Plane Surface(1) = {1};
Curve Loop(2) = {5, 6, 7, -2};
Plane Surface(2) = {2};
Curve Loop(3) = {-7, 8, 9, -3};
Plane Surface(3) = {3};
Transfinite Curve {1:9} = N + 1;
Transfinite Surface {1, 2, 3};
Recombine Surface {1, 2, 3};
out[] = Extrude {0, 0, L} { Surface {1, 2, 3}; Layers {NZ}; Recombine; };
// out[]: for each surface its top, its volume, then its four sides in the
// order of its curve loop
Physical Surface(1) = {out[5], out[16]};   // x = 0: side on curve 4 (core), 9 (block 3)
Physical Surface(2) = {out[2], out[8]};    // y = 0: side on curve 1 (core), 5 (block 2)
Physical Surface(3) = {1, 2, 3};           // z = 0
Physical Surface(4) = {out[0], out[6], out[12]}; // z = L
Physical Surface(5) = {out[9], out[15]};   // mantle: curves 6, 8
Physical Volume(0) = {out[1], out[7], out[13]};
