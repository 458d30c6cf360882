// inclinedSlide: the slope's frame before the rotation: a strip
// [0, 3] x [0, 0.25] m of Delaunay triangles of size lc, extruded one layer
// (0.01 m) so gmshToFoam gives prisms.  Allrun rotates the mesh (and the
// seeded block with it) by -30 degrees about z: the patch "slope" then
// descends along (cos 30, -sin 30), aligned with no axis.
If (!Exists(lc)) lc = 0.02; EndIf
Point(1) = {0, 0, 0, lc};
Point(2) = {3, 0, 0, lc};
Point(3) = {3, 0.25, 0, lc};
Point(4) = {0, 0.25, 0, lc};
Line(1) = {1, 2};
Line(2) = {2, 3};
Line(3) = {3, 4};
Line(4) = {4, 1};
Curve Loop(1) = {1, 2, 3, 4};
Plane Surface(1) = {1};
Mesh.Algorithm = 5;   // Delaunay
out[] = Extrude {0, 0, 0.01} { Surface{1}; Layers{1}; Recombine; };
Physical Surface("slope") = {out[2]};
Physical Surface("walls") = {out[3], out[4], out[5]};
Physical Surface("frontAndBack") = {1, out[0]};
Physical Volume("strip") = {out[1]};
