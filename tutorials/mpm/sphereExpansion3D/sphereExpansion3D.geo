// sphereExpansion3D: the spherical container of radius 0.5 m (dissertation
// 2.3.5), gmsh tetrahedra of size lc; its surface is the contact patch.
SetFactory("OpenCASCADE");
If (!Exists(lc)) lc = 0.05; EndIf
Sphere(1) = {0, 0, 0, 0.5};
Mesh.CharacteristicLengthMin = lc;
Mesh.CharacteristicLengthMax = lc;
Physical Surface("container") = {1};
Physical Volume("sphere") = {1};
