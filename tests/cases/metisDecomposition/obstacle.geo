// Channel with a cylinder across it, tetrahedra
SetFactory("OpenCASCADE");
If (!Exists(lc)) lc = 0.068; EndIf
Box(1) = {0, 0, 0, 4, 1, 1};
Cylinder(2) = {1, 0.5, -0.1, 0, 0, 1.2, 0.2};
BooleanDifference(3) = { Volume{1}; Delete; }{ Volume{2}; Delete; };
Mesh.CharacteristicLengthMax = lc;
Mesh.CharacteristicLengthMin = lc;
Physical Surface("walls") = Surface{:};
Physical Volume("fluid") = {3};
