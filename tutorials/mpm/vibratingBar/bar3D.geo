// vibratingBar as a 3D block: [0, 30] x [0, 2.5] x [0, 2.5], the bar
// [0, 25] x [0, 2.5] x [0, 2.5] (nu = 0 and sliding sides: the block's first
// mode is the bar's, (2.37) holds), a vertex plane at x = 25 (the bar's end:
// the particles fill it exactly).  ./makeMesh runs it:
//   gmsh -3 -setnumber family F -setnumber lc H bar3D.geo
//   family 0: structured hexahedra of size lc
//          1: Delaunay tetrahedra of size lc (unstructured)
//          2: Delaunay tetrahedra graded along x: size 0.4 lc at x = 0 to
//             1.6 lc at x = 25 (4x across the bar), lc beyond
If (!Exists(lc)) lc = 0.625; EndIf
If (!Exists(family)) family = 1; EndIf
H = 2.5;
Point(1) = {0, 0, 0, lc};  Point(2) = {25, 0, 0, lc};  Point(3) = {30, 0, 0, lc};
Point(4) = {30, H, 0, lc}; Point(5) = {25, H, 0, lc};  Point(6) = {0, H, 0, lc};
Line(1) = {1, 2}; Line(2) = {2, 3}; Line(3) = {3, 4}; Line(4) = {4, 5};
Line(5) = {5, 6}; Line(6) = {6, 1}; Line(7) = {2, 5};
Curve Loop(1) = {1, 7, 5, 6};  Plane Surface(1) = {1};    // the bar
Curve Loop(2) = {2, 3, 4, -7}; Plane Surface(2) = {2};    // room beyond
If (family == 0)
    nx1 = Round(25/lc); nx2 = Round(5/lc); ny = Round(H/lc);
    Transfinite Curve{1, 5} = nx1 + 1;
    Transfinite Curve{2, 4} = nx2 + 1;
    Transfinite Curve{3, 6, 7} = ny + 1;
    Transfinite Surface{1} = {1, 2, 5, 6};
    Transfinite Surface{2} = {2, 3, 4, 5};
    Recombine Surface{1, 2};
    e1[] = Extrude {0, 0, H} { Surface{1}; Layers{ny}; Recombine; };
    e2[] = Extrude {0, 0, H} { Surface{2}; Layers{ny}; Recombine; };
Else
    e1[] = Extrude {0, 0, H} { Surface{1}; };
    e2[] = Extrude {0, 0, H} { Surface{2}; };
EndIf
If (family == 2)
    Field[1] = MathEval;
    Field[1].F = Sprintf("%g*(0.4 + 1.2*Min(x, 25)/25)", lc);
    Background Field = 1;
    Mesh.CharacteristicLengthExtendFromBoundary = 0;
    Mesh.CharacteristicLengthFromPoints = 0;
EndIf
Mesh.Algorithm = 5;     // Delaunay (surfaces)
Mesh.Algorithm3D = 1;   // Delaunay (volumes)
// e1: top, volume, sides (lines 1, 7, 5, 6 in order); e2: (2, 3, 4, -7)
Physical Surface("left") = {e1[5]};
Physical Surface("walls") = {1, 2, e1[0], e2[0], e1[2], e1[4], e2[2], e2[3], e2[4]};
Physical Volume("block") = {e1[1], e2[1]};
