// collidingDisks: box [-0.1, 1.1]^2 (the unit box of the problem plus an extra layer), Delaunay triangles of size lc, extruded one
// layer (0.01 m) so gmshToFoam gives prisms.
If (!Exists(lc)) lc = 0.025; EndIf
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
Mesh.Algorithm = 5;   // Delaunay
out[] = Extrude {0, 0, 0.01} { Surface{1}; Layers{1}; Recombine; };
Physical Surface("walls") = {out[2], out[3], out[4], out[5]};
Physical Surface("frontAndBack") = {1, out[0]};
Physical Volume("box") = {out[1]};
