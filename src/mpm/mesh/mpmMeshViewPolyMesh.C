/*---------------------------------------------------------------------------*\
  mpmFoam: material point, compressible-flow and graph-network methods
           for OpenFOAM v1912
\*---------------------------------------------------------------------------*/

#include "mpmMeshView.H"
#include "polyMesh.H"
#include "emptyPolyPatch.H"
#include "wedgePolyPatch.H"
#include "cellModel.H"
#include "DynamicList.H"

#include <algorithm>

// * * * * * * * * * * * * * * * * Constructors  * * * * * * * * * * * * * //

Foam::mpmMeshView::mpmMeshView(const polyMesh& mesh)
:
    dim_(mesh.nSolutionD()),
    axes_(-1)
{
    const polyBoundaryMesh& patches = mesh.boundaryMesh();
    for (const polyPatch& pp : patches)
    {
        if (isA<wedgePolyPatch>(pp))
        {
            FatalErrorInFunction
                << "Mesh " << mesh.objectPath() << ": wedge patch "
                << pp.name() << " (axisymmetric meshes are not supported by"
                << " the MPM mesh view; use a 2D mesh with empty front and"
                << " back patches, or a 3D mesh)" << exit(FatalError);
        }
    }

    const Vector<label>& sol = mesh.solutionD();
    label k = 0;
    for (direction d = 0; d < vector::nComponents; ++d)
    {
        if (sol[d] == 1) axes_[k++] = d;
    }
    const pointField& pts = mesh.points();
    const boundBox& bb = mesh.bounds();
    const scalar tol = 1e-8*mag(bb.span());

    const label nC = mesh.nCells();
    shapes_.setSize(nC);
    cellStart_.setSize(nC + 1);
    cellStart_[0] = 0;
    DynamicList<label> cv(8*nC);

    pointVertex_.setSize(pts.size(), -1);

    if (dim_ == 3)
    {
        vertices_ = pts;
        pointVertex_ = identity(pts.size());
        const cellModel& tet = cellModel::ref(cellModel::TET);
        const cellModel& hex = cellModel::ref(cellModel::HEX);
        const cellShapeList& cs = mesh.cellShapes();
        forAll(cs, c)
        {
            if (cs[c].model() == tet) shapes_[c] = TET;
            else if (cs[c].model() == hex) shapes_[c] = HEX;
            else
            {
                FatalErrorInFunction
                    << "Mesh " << mesh.objectPath() << ": cell " << c
                    << " at " << mesh.cellCentres()[c] << " is a "
                    << cs[c].model().name() << "; the 3D MPM mesh view takes"
                    << " tetrahedra and hexahedra only" << exit(FatalError);
            }
            for (const label p : cs[c]) cv.append(p);
            cellStart_[c + 1] = cv.size();
        }
    }
    else if (dim_ == 2)
    {
        // The empty axis and the front plane (smallest coordinate)
        label e = 0;
        for (direction d = 0; d < vector::nComponents; ++d)
        {
            if (sol[d] != 1) e = d;
        }
        const scalar front = bb.min()[e];
        labelList pointToVertex(pts.size(), -1);
        DynamicList<vector> verts(pts.size()/2 + 1);
        const faceList& faces = mesh.faces();
        const cellList& cells = mesh.cells();
        forAll(cells, c)
        {
            label frontFace = -1;
            for (const label f : cells[c])
            {
                const label patchi = patches.whichPatch(f);
                if
                (
                    patchi >= 0 && isA<emptyPolyPatch>(patches[patchi])
                 && mesh.faceCentres()[f][e] < front + tol
                )
                {
                    frontFace = f;
                    break;
                }
            }
            const label nfp = frontFace >= 0 ? faces[frontFace].size() : 0;
            if (nfp != 3 && nfp != 4)
            {
                FatalErrorInFunction
                    << "Mesh " << mesh.objectPath() << ": cell " << c
                    << " at " << mesh.cellCentres()[c]
                    << (frontFace < 0
                        ? " has no face on the front empty plane"
                        : " has a front face of " + Foam::name(nfp) + " points")
                    << "; 2D MPM needs one cell layer between empty patches,"
                    << " with triangles or quadrilaterals on the front plane"
                    << exit(FatalError);
            }
            shapes_[c] = (nfp == 3 ? TRIANGLE : QUAD);
            for (const label p : faces[frontFace])
            {
                if (pointToVertex[p] < 0)
                {
                    pointToVertex[p] = verts.size();
                    verts.append(pts[p]);
                }
                cv.append(pointToVertex[p]);
            }
            cellStart_[c + 1] = cv.size();
        }
        vertices_.transfer(verts);
        pointVertex_ = pointToVertex;
    }
    else if (dim_ == 1)
    {
        const label a = axes_[0];
        List<scalar> xs(pts.size());
        forAll(pts, p) xs[p] = pts[p][a];
        std::sort(xs.begin(), xs.end());
        DynamicList<scalar> ux(xs.size());
        for (const scalar x : xs)
        {
            if (ux.empty() || x > ux.last() + tol) ux.append(x);
        }
        vertices_.setSize(ux.size(), bb.min());
        forAll(ux, i) vertices_[i][a] = ux[i];

        auto indexOf = [&](const scalar x)
        {
            const label i =
                std::lower_bound(ux.begin(), ux.end(), x - tol) - ux.begin();
            return min(i, ux.size() - 1);
        };
        // Only the points on the lowest corner line are vertices
        forAll(pts, p)
        {
            bool corner = true;
            for (direction d = 0; d < vector::nComponents; ++d)
            {
                if (label(d) != a && pts[p][d] > bb.min()[d] + tol) corner = false;
            }
            if (corner) pointVertex_[p] = indexOf(pts[p][a]);
        }
        const labelListList& cp = mesh.cellPoints();
        forAll(cp, c)
        {
            scalar lo = GREAT, hi = -GREAT;
            for (const label p : cp[c])
            {
                lo = min(lo, pts[p][a]);
                hi = max(hi, pts[p][a]);
            }
            shapes_[c] = SEGMENT;
            cv.append(indexOf(lo));
            cv.append(indexOf(hi));
            cellStart_[c + 1] = cv.size();
        }
    }
    else
    {
        FatalErrorInFunction
            << "Mesh " << mesh.objectPath() << " has no solution direction"
            << exit(FatalError);
    }

    cellVertices_.transfer(cv);
    build();
}


// ************************************************************************* //
