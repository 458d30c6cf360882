// mpmKernels benchmark, 2D: the box [0, L] x [0, L] (L = 1 m) in triangles of size h,
// extruded to one layer of prisms (dz) for the 2D MPM mesh view.
// gmsh -3 -format msh2 [-setnumber h H] box2D.geo
DefineConstant[ h = {0.02, Name "cell size"} ];
L = 1;
dz = 0.1;

Point(1) = {0, 0, 0, h};
Point(2) = {L, 0, 0, h};
Point(3) = {L, L, 0, h};
Point(4) = {0, L, 0, h};
Line(1) = {1, 2};
Line(2) = {2, 3};
Line(3) = {3, 4};
Line(4) = {4, 1};
Curve Loop(1) = {1, 2, 3, 4};
Plane Surface(1) = {1};
Mesh.Algorithm = 6;          // Frontal-Delaunay: unstructured triangles

// ext[0]: the copy of Surface 1 at z = dz, ext[1]: the volume,
// ext[2..5]: the sides from lines 1-4
ext[] = Extrude {0, 0, dz} { Surface{1}; Layers{1}; Recombine; };
Physical Surface("walls")        = {ext[2], ext[3], ext[4], ext[5]};
Physical Surface("frontAndBack") = {1, ext[0]};
Physical Volume("internal")      = {ext[1]};
