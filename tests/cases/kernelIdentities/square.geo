// Unit square, triangles, extruded one layer.  Variants by -setnumber:
//   grading G: size lc at (0,0) growing to G*lc at (1,1)  (G = 1: uniform)
//   stretched 1: transfinite 10 x 40 divisions (aspect-ratio-4 triangles)
If (!Exists(lc)) lc = 0.05; EndIf
If (!Exists(grading)) grading = 1; EndIf
If (!Exists(stretched)) stretched = 0; EndIf
Point(1) = {0, 0, 0, lc};
Point(2) = {1, 0, 0, lc*Sqrt(grading)};
Point(3) = {1, 1, 0, lc*grading};
Point(4) = {0, 1, 0, lc*Sqrt(grading)};
Line(1) = {1, 2}; Line(2) = {2, 3}; Line(3) = {3, 4}; Line(4) = {4, 1};
Curve Loop(1) = {1, 2, 3, 4};
Plane Surface(1) = {1};
If (stretched)
  Transfinite Curve{1, 3} = 11;
  Transfinite Curve{2, 4} = 41;
  Transfinite Surface{1};
EndIf
out[] = Extrude {0, 0, 0.05} { Surface{1}; Layers{1}; Recombine; };
Physical Surface("walls") = {out[2], out[3], out[4], out[5]};
Physical Surface("frontAndBack") = {1, out[0]};
Physical Volume("domain") = {out[1]};
