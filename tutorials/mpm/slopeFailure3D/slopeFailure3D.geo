// slopeFailure3D: the background mesh of the umls run, a box
// x in [0, Lx] (x = 0: the back wall behind the crest), y in [0, Ly]
// (y = 0: the base), z in [0, D] (the two side walls), in tetrahedra of
// size lc.  makeCase.py passes the numbers:
// gmsh -3 -format msh2 -setnumber Lx 40 -setnumber Ly 10 -setnumber D 1 -setnumber lc 0.5
SetFactory("OpenCASCADE");
If (!Exists(Lx)) Lx = 40; EndIf
If (!Exists(Ly)) Ly = 10; EndIf
If (!Exists(D)) D = 1; EndIf
If (!Exists(lc)) lc = 0.5; EndIf
Box(1) = {0, 0, 0, Lx, Ly, D};
Mesh.CharacteristicLengthMax = lc;
Mesh.CharacteristicLengthMin = lc;
e = 1e-6;
Physical Surface("base") = Surface In BoundingBox{-e, -e, -e, Lx + e, e, D + e};
Physical Surface("back") = Surface In BoundingBox{-e, -e, -e, e, Ly + e, D + e};
Physical Surface("sides") = {Surface In BoundingBox{-e, -e, -e, Lx + e, Ly + e, e},
                             Surface In BoundingBox{-e, -e, D - e, Lx + e, Ly + e, D + e}};
Physical Surface("open") = {Surface In BoundingBox{Lx - e, -e, -e, Lx + e, Ly + e, D + e},
                            Surface In BoundingBox{-e, Ly - e, -e, Lx + e, Ly + e, D + e}};
Physical Volume("box") = {1};
