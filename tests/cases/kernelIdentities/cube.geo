// Unit cube, tetrahedra: size lc at the origin growing to grading*lc at (1,1,1)
SetFactory("OpenCASCADE");
If (!Exists(lc)) lc = 0.1; EndIf
If (!Exists(grading)) grading = 1; EndIf
Box(1) = {0, 0, 0, 1, 1, 1};
Field[1] = MathEval;
Field[1].F = Sprintf("%g*(1 + (%g - 1)*(x + y + z)/3)", lc, grading);
Background Field = 1;
Mesh.CharacteristicLengthFromPoints = 0;
Mesh.CharacteristicLengthExtendFromBoundary = 0;
Physical Surface("walls") = Surface{:};
Physical Volume("domain") = Volume{:};
