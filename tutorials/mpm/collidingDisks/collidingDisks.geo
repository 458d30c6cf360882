// collidingDisks: box [-0.1, 1.1]^2 (the unit box of the problem plus an
// extra layer), extruded one layer (0.01 m) so gmshToFoam gives prisms or
// hexahedra.
//   gmsh -setnumber lc 0.025 [-setnumber family F]
//   family 0: Delaunay triangles of size lc (the default)
//          1: structured squares of size lc (1.2/lc whole): a uniform
//             Cartesian lattice
//          2: Delaunay triangles graded along x: 0.4 lc at x = 0 to 1.6 lc
//             at x = 1 (4x across the two disks: the left one in cells of
//             0.4 to 0.9 lc, the right one in 1.1 to 1.6 lc)
If (!Exists(lc)) lc = 0.025; EndIf
If (!Exists(family)) family = 0; EndIf
Point(1) = {-0.1, -0.1, 0, lc};
Point(2) = {1.1, -0.1, 0, lc};
Point(3) = {1.1, 1.1, 0, lc};
Point(4) = {-0.1, 1.1, 0, lc};
Line(1) = {1, 2};
Line(2) = {2, 3};
Line(3) = {3, 4};
Line(4) = {4, 1};
Curve Loop(1) = {1, 2, 3, 4};
Plane Surface(1) = {1};
If (family == 1)
    Transfinite Curve{1, 2, 3, 4} = Round(1.2/lc) + 1;
    Transfinite Surface{1};
    Recombine Surface{1};
EndIf
If (family == 2)
    Field[1] = MathEval;
    Field[1].F = Sprintf("%g*(0.4 + 1.2*Min(Max(x, 0), 1))", lc);
    Background Field = 1;
    Mesh.CharacteristicLengthExtendFromBoundary = 0;
    Mesh.CharacteristicLengthFromPoints = 0;
EndIf
Mesh.Algorithm = 5;   // Delaunay
out[] = Extrude {0, 0, 0.01} { Surface{1}; Layers{1}; Recombine; };
Physical Surface("walls") = {out[2], out[3], out[4], out[5]};
Physical Surface("frontAndBack") = {1, out[0]};
Physical Volume("box") = {out[1]};
