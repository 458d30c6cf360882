// mpmKernels benchmark, 3D: the cube [0, L]^3 (L = 1 m) in tetrahedra of size h.
// gmsh -3 -format msh2 [-setnumber h H] box3D.geo
DefineConstant[ h = {0.1, Name "cell size"} ];
L = 1;

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

// ext[0]: the top, ext[1]: the volume, ext[2..5]: the sides
ext[] = Extrude {0, 0, L} { Surface{1}; };
Physical Surface("walls")   = {1, ext[0], ext[2], ext[3], ext[4], ext[5]};
Physical Volume("internal") = {ext[1]};
Mesh.Algorithm3D = 1;        // Delaunay tetrahedra
