// slopeFailure3D: the background mesh of the umls run, a box
// x in [0, Lx] (x = 0: the back wall behind the crest), y in [0, Ly]
// (y = 0: the base), z in [0, D] (the two side walls), in tetrahedra of
// size lc.  makeCase.py passes the numbers:
// gmsh -3 -format msh2 -setnumber Lx 40 -setnumber Ly 10 -setnumber D 1 -setnumber lc 0.5 -setnumber structured 1
//
// structured 1 (the default): transfinite, the vertices those of the
// cubes of size lc (Lx, Ly, D multiples of lc), each cube cut by gmsh into
// 6 tetrahedra; structured 0: gmsh's unstructured (Delaunay) tetrahedra
// of size lc.
SetFactory("OpenCASCADE");
If (!Exists(Lx)) Lx = 40; EndIf
If (!Exists(Ly)) Ly = 10; EndIf
If (!Exists(D)) D = 1; EndIf
If (!Exists(lc)) lc = 0.5; EndIf
If (!Exists(structured)) structured = 1; EndIf
Box(1) = {0, 0, 0, Lx, Ly, D};
e = 1e-6;
If (structured)
    // the 4 edges along each axis, with one node per lattice place
    Transfinite Curve {Curve In BoundingBox{-e, -e, -e, Lx + e, e, e},
                       Curve In BoundingBox{-e, Ly - e, -e, Lx + e, Ly + e, e},
                       Curve In BoundingBox{-e, -e, D - e, Lx + e, e, D + e},
                       Curve In BoundingBox{-e, Ly - e, D - e, Lx + e, Ly + e, D + e}} = Round(Lx/lc) + 1;
    Transfinite Curve {Curve In BoundingBox{-e, -e, -e, e, Ly + e, e},
                       Curve In BoundingBox{Lx - e, -e, -e, Lx + e, Ly + e, e},
                       Curve In BoundingBox{-e, -e, D - e, e, Ly + e, D + e},
                       Curve In BoundingBox{Lx - e, -e, D - e, Lx + e, Ly + e, D + e}} = Round(Ly/lc) + 1;
    Transfinite Curve {Curve In BoundingBox{-e, -e, -e, e, e, D + e},
                       Curve In BoundingBox{Lx - e, -e, -e, Lx + e, e, D + e},
                       Curve In BoundingBox{-e, Ly - e, -e, e, Ly + e, D + e},
                       Curve In BoundingBox{Lx - e, Ly - e, -e, Lx + e, Ly + e, D + e}} = Round(D/lc) + 1;
    Transfinite Surface {:};
    Transfinite Volume {1};
Else
    Mesh.CharacteristicLengthMax = lc;
    Mesh.CharacteristicLengthMin = lc;
EndIf
Physical Surface("base") = Surface In BoundingBox{-e, -e, -e, Lx + e, e, D + e};
Physical Surface("back") = Surface In BoundingBox{-e, -e, -e, e, Ly + e, D + e};
Physical Surface("sides") = {Surface In BoundingBox{-e, -e, -e, Lx + e, Ly + e, e},
                             Surface In BoundingBox{-e, -e, D - e, Lx + e, Ly + e, D + e}};
Physical Surface("open") = {Surface In BoundingBox{Lx - e, -e, -e, Lx + e, Ly + e, D + e},
                            Surface In BoundingBox{-e, Ly - e, -e, Lx + e, Ly + e, D + e}};
Physical Volume("box") = {1};
