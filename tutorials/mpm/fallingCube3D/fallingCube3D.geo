// fallingCube3D: a 1 x 1 x 1 m box over a floor at y = 0, with one extra
// layer of cells below the floor (y in [-0.2, 0]) so that the MLS rings of
// particles on the floor are complete (dissertation Fig. 2.6).  The two
// boxes are fragmented so the floor y = 0 is a plane of mesh vertices.
// Tetrahedra of size lc: gmsh -setnumber lc 0.08
SetFactory("OpenCASCADE");
If (!Exists(lc)) lc = 0.08; EndIf
Box(1) = {0, 0, 0, 1, 1, 1};
Box(2) = {0, -0.2, 0, 1, 0.2, 1};
v() = BooleanFragments{ Volume{1}; Delete; }{ Volume{2}; Delete; };
Mesh.CharacteristicLengthMax = lc;
Mesh.CharacteristicLengthMin = lc;
Physical Surface("walls") = CombinedBoundary{ Volume{:}; };
Physical Volume("box") = Volume{:};
