// cantilever: background mesh for a 10 x 2 m beam (x in [0, 10], y in
// [-1, 1]) clamped at x = 0: a 20 x 20 m square centred at (5, 0), rotated
// by 'angle' degrees about its centre, with the wall line x = 0 meshed
// conformally, extruded one layer (0.1 m).
//   gmsh -setnumber angle 30 -setnumber lc 0.5 [-setnumber family F]
//   family 0: Delaunay triangles of size lc (the default)
//          1: structured squares of size lc (the square split at x = 0;
//             5/lc must be whole); at angle 0 a uniform Cartesian lattice
//          2: Delaunay triangles graded along the beam: 0.4 lc at the
//             clamp to 1.6 lc at the tip (4x across the body), 1.6 lc
//             beyond it and 0.4 lc behind the wall
If (!Exists(lc)) lc = 0.5; EndIf
If (!Exists(angle)) angle = 0; EndIf
If (!Exists(family)) family = 0; EndIf
Point(1) = {-5, -10, 0, lc};
Point(2) = {15, -10, 0, lc};
Point(3) = {15, 10, 0, lc};
Point(4) = {-5, 10, 0, lc};
If (family == 1)
    // two rectangles that share the wall line x = 0
    Point(5) = {0, -10, 0, lc};
    Point(6) = {0, 10, 0, lc};
    Line(1) = {1, 5}; Line(2) = {5, 2}; Line(3) = {2, 3}; Line(4) = {3, 6};
    Line(5) = {6, 4}; Line(6) = {4, 1}; Line(7) = {5, 6};
    Curve Loop(1) = {1, 7, 5, 6};  Plane Surface(1) = {1};
    Curve Loop(2) = {2, 3, 4, -7}; Plane Surface(2) = {2};
    Transfinite Curve{1, 5} = Round(5/lc) + 1;
    Transfinite Curve{2, 4} = Round(15/lc) + 1;
    Transfinite Curve{3, 6, 7} = Round(20/lc) + 1;
    Transfinite Surface{1} = {1, 5, 6, 4};
    Transfinite Surface{2} = {5, 2, 3, 6};
    Recombine Surface{1, 2};
    Rotate {{0, 0, 1}, {5, 0, 0}, angle*Pi/180} { Surface{1, 2}; }
    s1[] = Extrude {0, 0, 0.1} { Surface{1}; Layers{1}; Recombine; };
    s2[] = Extrude {0, 0, 0.1} { Surface{2}; Layers{1}; Recombine; };
    // s1: top, volume, sides (lines 1, 7, 5, 6); s2: (2, 3, 4, -7)
    Physical Surface("walls") = {s1[2], s1[4], s1[5], s2[2], s2[3], s2[4]};
    Physical Surface("frontAndBack") = {1, 2, s1[0], s2[0]};
    Physical Volume("box") = {s1[1], s2[1]};
Else
    Line(1) = {1, 2};
    Line(2) = {2, 3};
    Line(3) = {3, 4};
    Line(4) = {4, 1};
    Curve Loop(1) = {1, 2, 3, 4};
    Plane Surface(1) = {1};
    Rotate {{0, 0, 1}, {5, 0, 0}, angle*Pi/180} { Surface{1}; }
    // The wall x = 0 is meshed conformally (as an unstructured mesh would
    // match any wall): nodes on it are clamped; the triangles keep the
    // rotation
    Point(5) = {0, -8, 0, lc};
    Point(6) = {0, 8, 0, lc};
    Line(5) = {5, 6};
    Line{5} In Surface{1};
    If (family == 2)
        Field[1] = MathEval;
        Field[1].F = Sprintf("%g*(0.4 + 1.2*Min(Max(x, 0), 10)/10)", lc);
        Background Field = 1;
        Mesh.CharacteristicLengthExtendFromBoundary = 0;
        Mesh.CharacteristicLengthFromPoints = 0;
    EndIf
    Mesh.Algorithm = 5;   // Delaunay
    out[] = Extrude {0, 0, 0.1} { Surface{1}; Layers{1}; Recombine; };
    Physical Surface("walls") = {out[2], out[3], out[4], out[5]};
    Physical Surface("frontAndBack") = {1, out[0]};
    Physical Volume("box") = {out[1]};
EndIf
