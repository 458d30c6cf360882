// vibratingBar as a 2D strip: [0, 30] x [0, 2.5], the bar [0, 25] x [0, 2.5]
// (nu = 0: the strip's first mode is the bar's, (2.37) holds), a vertex
// line at x = 25 (the bar's end: the particles fill it exactly), one layer
// extruded (0.1 m).  ./makeMesh runs it:
//   gmsh -3 -setnumber family F -setnumber lc H strip.geo
//   family 0: structured quadrilaterals of size lc
//          1: Delaunay triangles of size lc (unstructured)
//          2: Delaunay triangles graded along x: size 0.4 lc at x = 0 to
//             1.6 lc at x = 25 (4x across the bar, mean lc), lc beyond
//          3: quadrilaterals graded along x: the columns growing 4x from
//             x = 0 to x = 25 (as many as family 0's), rows of size lc
If (!Exists(lc)) lc = 0.5; EndIf
If (!Exists(family)) family = 1; EndIf
H = 2.5;
Point(1) = {0, 0, 0, lc};  Point(2) = {25, 0, 0, lc};  Point(3) = {30, 0, 0, lc};
Point(4) = {30, H, 0, lc}; Point(5) = {25, H, 0, lc};  Point(6) = {0, H, 0, lc};
Line(1) = {1, 2}; Line(2) = {2, 3}; Line(3) = {3, 4}; Line(4) = {4, 5};
Line(5) = {5, 6}; Line(6) = {6, 1}; Line(7) = {2, 5};
Curve Loop(1) = {1, 7, 5, 6};  Plane Surface(1) = {1};    // the bar
Curve Loop(2) = {2, 3, 4, -7}; Plane Surface(2) = {2};    // room beyond
If (family == 0 || family == 3)
    nx1 = Round(25/lc); nx2 = Round(5/lc); ny = Round(H/lc);
    If (family == 0)
        Transfinite Curve{1, 5} = nx1 + 1;
    EndIf
    If (family == 3)
        r = 4^(1/(nx1 - 1));
        Transfinite Curve{1} = nx1 + 1 Using Progression r;
        Transfinite Curve{5} = nx1 + 1 Using Progression 1/r;   // 5 runs 5 -> 6
    EndIf
    Transfinite Curve{2, 4} = nx2 + 1;
    Transfinite Curve{3, 6, 7} = ny + 1;
    Transfinite Surface{1} = {1, 2, 5, 6};
    Transfinite Surface{2} = {2, 3, 4, 5};
    Recombine Surface{1, 2};
EndIf
If (family == 2)
    Field[1] = MathEval;
    Field[1].F = Sprintf("%g*(0.4 + 1.2*Min(x, 25)/25)", lc);
    Background Field = 1;
    Mesh.CharacteristicLengthExtendFromBoundary = 0;
    Mesh.CharacteristicLengthFromPoints = 0;
EndIf
Mesh.Algorithm = 5;   // Delaunay
e1[] = Extrude {0, 0, 0.1} { Surface{1}; Layers{1}; Recombine; };
e2[] = Extrude {0, 0, 0.1} { Surface{2}; Layers{1}; Recombine; };
// e1: top, sides (lines 1, 7, 5, 6 in order); e2: (2, 3, 4, -7)
Physical Surface("left") = {e1[5]};
Physical Surface("walls") = {e1[2], e1[4], e2[2], e2[3], e2[4]};
Physical Surface("frontAndBack") = {1, 2, e1[0], e2[0]};
Physical Volume("strip") = {e1[1], e2[1]};
