// cylinderWake2D.geo -- gmsh geometry and mesh for the 2D cylinder wake case.
//
// Circular cylinder (diameter D, centred at the origin) in a channel
//     x in [xIn, xOut],  y in [-halfWidth, halfWidth]
// meshed with triangles (fine near the cylinder and in the wake) and
// extruded by ONE cell layer of thickness dz in z, which gmshToFoam turns
// into prisms.  Lengths are in units of D.
//
// Parameters can be overridden from the command line, e.g.
//     gmsh -3 -format msh2 -setnumber meshFactor 1.4 cylinderWake2D.geo \
//          -o cylinderWake2D.msh
// meshFactor scales every cell size (2 halves the resolution in each
// direction, i.e. about 1/4 of the cells).

DefineConstant[
    D          = {1.0,  Name "Parameters/D"},
    xIn        = {-6.0, Name "Parameters/xIn"},
    xOut       = {20.0, Name "Parameters/xOut"},
    halfWidth  = {8.0,  Name "Parameters/halfWidth"},
    dz         = {1.0,  Name "Parameters/dz"},
    meshFactor = {1.0,  Name "Parameters/meshFactor"}
];

// Target cell sizes
hCyl  = 0.04 * D * meshFactor;   // on the cylinder surface
hNear = 0.10 * D * meshFactor;   // ring around the cylinder
hWake = 0.20 * D * meshFactor;   // wake region
hFar  = 0.80 * D * meshFactor;   // far field

R = 0.5 * D;

// ---------------------------------------------------------------- geometry
// Channel corners
Point(1) = {xIn,  -halfWidth, 0, hFar};
Point(2) = {xOut, -halfWidth, 0, hFar};
Point(3) = {xOut,  halfWidth, 0, hFar};
Point(4) = {xIn,   halfWidth, 0, hFar};

Line(1) = {1, 2};   // bottom
Line(2) = {2, 3};   // outlet
Line(3) = {3, 4};   // top
Line(4) = {4, 1};   // inlet

// Cylinder: centre and four quarter arcs
Point(10) = {0,  0, 0, hCyl};
Point(11) = {R,  0, 0, hCyl};
Point(12) = {0,  R, 0, hCyl};
Point(13) = {-R, 0, 0, hCyl};
Point(14) = {0, -R, 0, hCyl};

Circle(11) = {11, 10, 12};
Circle(12) = {12, 10, 13};
Circle(13) = {13, 10, 14};
Circle(14) = {14, 10, 11};

Curve Loop(1) = {1, 2, 3, 4};
Curve Loop(2) = {11, 12, 13, 14};
Plane Surface(1) = {1, 2};

// ------------------------------------------------------------- size fields
// Fine near the cylinder, growing with the distance from it
Field[1] = Distance;
Field[1].CurvesList = {11, 12, 13, 14};
Field[1].NumPointsPerCurve = 200;   // gmsh >= 4.11 also accepts "Sampling"

Field[2] = Threshold;
Field[2].InField = 1;
Field[2].SizeMin = hCyl;
Field[2].SizeMax = hFar;
Field[2].DistMin = 0.0;
Field[2].DistMax = 8.0 * D;

// Ring around the cylinder (the separating shear layers)
Field[3] = Threshold;
Field[3].InField = 1;
Field[3].SizeMin = hNear;
Field[3].SizeMax = hFar;
Field[3].DistMin = 1.0 * D;
Field[3].DistMax = 4.0 * D;

// Wake: a box from just upstream of the cylinder to the outlet
Field[4] = Box;
Field[4].VIn = hWake;
Field[4].VOut = hFar;
Field[4].XMin = -1.0 * D;
Field[4].XMax = xOut;
Field[4].YMin = -2.0 * D;
Field[4].YMax = 2.0 * D;
Field[4].Thickness = 3.0 * D;

Field[5] = Min;
Field[5].FieldsList = {2, 3, 4};
Background Field = 5;

Mesh.MeshSizeExtendFromBoundary = 0;
Mesh.MeshSizeFromPoints = 0;
Mesh.MeshSizeFromCurvature = 0;
Mesh.Algorithm = 6;          // Frontal-Delaunay triangles
Mesh.Smoothing = 5;

// ----------------------------------------------- one cell layer in z
// ext[0]: the extruded copy of Surface 1 (z = dz), ext[1]: the volume,
// ext[2..]: the side surfaces, in the order of the curves of Surface 1:
// lines 1-4 (bottom, outlet, top, inlet), then arcs 11-14 (cylinder).
ext[] = Extrude {0, 0, dz} { Surface{1}; Layers{1}; Recombine; };

Physical Surface("bottom")       = {ext[2]};
Physical Surface("outlet")       = {ext[3]};
Physical Surface("top")          = {ext[4]};
Physical Surface("inlet")        = {ext[5]};
Physical Surface("cylinder")     = {ext[6], ext[7], ext[8], ext[9]};
Physical Surface("frontAndBack") = {1, ext[0]};
Physical Volume("internal")      = {ext[1]};
