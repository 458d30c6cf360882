// cantilever: background mesh for a 10 x 2 m beam (x in [0, 10], y in
// [-1, 1]) clamped at x = 0: a 20 x 20 m square centred at (5, 0), rotated
// by 'angle' degrees about its centre, with the wall line x = 0 embedded,
// Delaunay triangles of size lc, extruded one layer (0.1 m).
// gmsh -setnumber angle 30 -setnumber lc 0.5
If (!Exists(lc)) lc = 0.5; EndIf
If (!Exists(angle)) angle = 0; EndIf
Point(1) = {-5, -10, 0, lc};
Point(2) = {15, -10, 0, lc};
Point(3) = {15, 10, 0, lc};
Point(4) = {-5, 10, 0, lc};
Line(1) = {1, 2};
Line(2) = {2, 3};
Line(3) = {3, 4};
Line(4) = {4, 1};
Curve Loop(1) = {1, 2, 3, 4};
Plane Surface(1) = {1};
Rotate {{0, 0, 1}, {5, 0, 0}, angle*Pi/180} { Surface{1}; }
// The wall x = 0 is meshed conformally (as an unstructured mesh would match
// any wall): nodes on it are clamped; the triangles keep the rotation
Point(5) = {0, -8, 0, lc};
Point(6) = {0, 8, 0, lc};
Line(5) = {5, 6};
Line{5} In Surface{1};
Mesh.Algorithm = 5;   // Delaunay
out[] = Extrude {0, 0, 0.1} { Surface{1}; Layers{1}; Recombine; };
Physical Surface("walls") = {out[2], out[3], out[4], out[5]};
Physical Surface("frontAndBack") = {1, out[0]};
Physical Volume("box") = {out[1]};
