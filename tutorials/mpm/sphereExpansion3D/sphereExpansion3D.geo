// sphereExpansion3D: the spherical container of radius 0.5 m (dissertation
// 2.3.5) and one extra layer of elements outside it (2.1.3.5: a particle
// in a wall cell then has the ring of vertices beyond the wall, so no
// kernel weight turns negative), gmsh tetrahedra of size lc.  The wall,
// the sphere r = 0.5 m, is an internal surface: the physical surface
// "container", which gmshToFoam makes a faceZone (the contact surface);
// the layer's outer surface r = 0.5 m + lc is the patch "outside".
SetFactory("OpenCASCADE");
If (!Exists(lc)) lc = 0.05; EndIf
R = 0.5;
Sphere(1) = {0, 0, 0, R};
Sphere(2) = {0, 0, 0, R + lc};
// Conforming: the shell and the ball share the wall's triangles
BooleanFragments{ Volume{2}; Delete; }{ Volume{1}; Delete; }
eps = 1e-3;
wall() = Surface In BoundingBox{-R-eps, -R-eps, -R-eps, R+eps, R+eps, R+eps};
outer() = Surface{:};
outer() -= wall();
ball() = Volume In BoundingBox{-R-eps, -R-eps, -R-eps, R+eps, R+eps, R+eps};
layer() = Volume{:};
layer() -= ball();
Mesh.CharacteristicLengthMin = lc;
Mesh.CharacteristicLengthMax = lc;
Physical Surface("container") = {wall()};
Physical Surface("outside") = {outer()};
Physical Volume("sphere") = {ball()};
Physical Volume("layer") = {layer()};
