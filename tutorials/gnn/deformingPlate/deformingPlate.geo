// gnn/deformingPlate: the background mesh of umlsMpmFoam, a 0.3 x 0.2 x 0.3 m
// box of tetrahedra (size lc).  The plate (x, z in [0.04, 0.26], y in
// [0.04, 0.08]) lies inside with at least two cells of mesh around it, so
// every MLS 1-ring is complete (dissertation Fig. 2.6); the actuator moves
// in the space above it.  gmsh -3 -setnumber lc 0.02
SetFactory("OpenCASCADE");
If (!Exists(lc)) lc = 0.02; EndIf
Box(1) = {0, 0, 0, 0.3, 0.2, 0.3};
Mesh.CharacteristicLengthMax = lc;
Mesh.CharacteristicLengthMin = lc;
Physical Surface("walls") = CombinedBoundary{ Volume{:}; };
Physical Volume("box") = Volume{:};
