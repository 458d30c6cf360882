// A box with a spherical hole, tetrahedra
SetFactory("OpenCASCADE");
If (!Exists(lc)) lc = 0.06; EndIf
Box(1) = {0, 0, 0, 1.5, 1, 1};
Sphere(2) = {0.6, 0.5, 0.5, 0.25};
BooleanDifference(3) = { Volume{1}; Delete; }{ Volume{2}; Delete; };
Mesh.CharacteristicLengthMax = lc;
Mesh.CharacteristicLengthMin = lc;
Physical Surface("walls") = Surface{:};
Physical Volume("solid") = {3};
