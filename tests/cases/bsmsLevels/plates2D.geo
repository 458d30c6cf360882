// Two bodies 0.005 apart, one layer of prisms (a 2D OpenFOAM mesh): a plate
// with a hole, [0, 2] x [0, 1], and a bar [2.005, 2.5] x [0, 1]
SetFactory("OpenCASCADE");
If (!Exists(lc)) lc = 0.03; EndIf
Rectangle(1) = {0, 0, 0, 2, 1};
Disk(2) = {0.7, 0.5, 0, 0.2};
BooleanDifference(3) = { Surface{1}; Delete; }{ Surface{2}; Delete; };
Rectangle(4) = {2.005, 0, 0, 0.495, 1};
Mesh.CharacteristicLengthMax = lc;
Mesh.CharacteristicLengthMin = lc;
out[] = Extrude {0, 0, 0.05} { Surface{3, 4}; Layers{1}; Recombine; };
Physical Surface("walls") = Surface{:};
Physical Volume("solid") = Volume{:};
