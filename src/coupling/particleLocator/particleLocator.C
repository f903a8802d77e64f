#include "particleLocator.H"
#include "wallPolyPatch.H"
#include "Random.H"
#include "DynamicList.H"

Foam::particleLocator::particleLocator(const polyMesh& mesh)
:
    mesh_(mesh),
    search_(mesh, polyMesh::CELL_TETS),
    wallTree_(),
    planes_(),
    planeStart_(mesh.nCells() + 1, 0),
    convexCell_(mesh.nCells(), true),
    wallLowerBound_(mesh.nCells(), GREAT),
    cellReach_(mesh.nCells(), 0),
    wallPlanes_(),
    wallWarp_(),
    wallCandidates_(mesh.nCells()),
    wallCandidateRange_(mesh.nCells(), -1),
    nGlobalSearches_(0)
{
    // Convex cells bounded by planar faces: every point of the cell on the
    // inner side of every face plane (to a tolerance relative to the
    // cell's size).  In them the face-plane test alone decides.
    const pointField& pts = mesh.points();
    const faceList& faces = mesh.faces();
    const labelList& own = mesh.faceOwner();
    const vectorField& Sf = mesh.faceAreas();
    const vectorField& Cf = mesh.faceCentres();
    forAll(convexCell_, celli)
    {
        const scalar tol = 1e-8*cbrt(mesh.cellVolumes()[celli]);
        const labelList cellPts(mesh.cells()[celli].labels(faces));
        for (const label facei : mesh.cells()[celli])
        {
            const vector n =
                ((own[facei] == celli) ? 1 : -1)*Sf[facei]/mag(Sf[facei]);
            for (const label pointi : cellPts)
            {
                if (((pts[pointi] - Cf[facei]) & n) > tol)
                {
                    convexCell_[celli] = false;
                    break;
                }
            }
            if (!convexCell_[celli])
            {
                break;
            }
        }
    }

    {
        const cellList& cells = mesh.cells();
        const labelList& nei = mesh.faceNeighbour();
        const vectorField faceNormal(Sf/mag(Sf));
        forAll(cells, celli)
        {
            planeStart_[celli + 1] = planeStart_[celli] + cells[celli].size();
        }
        planes_.setSize(planeStart_.last());
        label k = 0;
        forAll(cells, celli)
        {
            for (const label facei : cells[celli])
            {
                const bool owner = (own[facei] == celli);
                cellPlane& plane = planes_[k++];
                plane.centre = Cf[facei];
                plane.normal = owner ? faceNormal[facei] : -faceNormal[facei];
                plane.face = facei;
                plane.across =
                    !mesh.isInternalFace(facei) ? -1
                  : owner ? nei[facei] : own[facei];
            }
        }
    }

    DynamicList<label> wallFaces;
    for (const polyPatch& pp : mesh.boundaryMesh())
    {
        if (isA<wallPolyPatch>(pp))
        {
            forAll(pp, i)
            {
                wallFaces.append(pp.start() + i);
            }
        }
    }

    if (wallFaces.size())
    {
        // Search domain slightly larger than the mesh, and never flat
        Random rndGen(12345);
        treeBoundBox bb(mesh.points());
        bb = bb.extend(rndGen, 1e-4);
        bb.min() -= point::uniform(ROOTVSMALL);
        bb.max() += point::uniform(ROOTVSMALL);

        wallTree_.reset
        (
            new indexedOctree<treeDataFace>
            (
                treeDataFace(false, mesh, labelList(wallFaces)),
                bb,
                8,      // max tree depth
                10,     // faces per leaf
                3.0     // duplicity
            )
        );

        // Most cells are far from every wall: their points' distance,
        // bounded below once here, spares the particles in them the search
        const vectorField& C = mesh.cellCentres();
        forAll(wallLowerBound_, celli)
        {
            scalar reach = 0;
            for (const label pointi : mesh.cellPoints()[celli])
            {
                reach = max(reach, mag(pts[pointi] - C[celli]));
            }
            cellReach_[celli] = reach;
            const pointIndexHit hit = wallTree_->findNearest(C[celli], GREAT);
            wallLowerBound_[celli] =
                hit.hit() ? max(scalar(0), mag(hit.hitPoint() - C[celli]) - reach) : GREAT;
        }

        wallPlanes_.setSize(wallFaces.size());
        wallWarp_.setSize(wallFaces.size(), 0);
        forAll(wallFaces, k)
        {
            const label facei = wallFaces[k];
            cellPlane& plane = wallPlanes_[k];
            plane.centre = Cf[facei];
            plane.normal = Sf[facei]/mag(Sf[facei]);
            plane.face = facei;
            plane.across = -1;
            for (const label pointi : faces[facei])
            {
                wallWarp_[k] = max
                (
                    wallWarp_[k],
                    mag((pts[pointi] - plane.centre) & plane.normal)
                );
            }
        }
    }
}


Foam::label Foam::particleLocator::walk
(
    const point& p,
    label celli,
    label& lastCell,
    label& exitFace
) const
{
    exitFace = -1;

    for (label step = 0; step < maxWalkSteps_; ++step)
    {
        lastCell = celli;
        const label first = planeStart_[celli];
        const label last = planeStart_[celli + 1];

        // Face whose plane p lies furthest outside of
        label exitPlane = -1;
        scalar exitDist = 0;
        for (label k = first; k < last; ++k)
        {
            const scalar d = (p - planes_[k].centre) & planes_[k].normal;
            if (d > exitDist)
            {
                exitDist = d;
                exitPlane = k;
            }
        }

        if (exitPlane < 0)
        {
            // Inside every face plane: inside a convex cell; else confirm
            // with the tet decomposition
            if
            (
                convexCell_[celli]
             || mesh_.pointInCell(p, celli, polyMesh::CELL_TETS)
            )
            {
                return celli;
            }
            for (label k = first; k < last; ++k)
            {
                const label other = planes_[k].across;
                if
                (
                    other >= 0
                 && mesh_.pointInCell(p, other, polyMesh::CELL_TETS)
                )
                {
                    return other;
                }
            }
            // Not in a face neighbour of this mesh part: report the
            // boundary face whose plane is nearest (e.g. a processor face:
            // the neighbour rank continues from the cell behind it)
            scalar nearest = -GREAT;
            for (label k = first; k < last; ++k)
            {
                if (planes_[k].across < 0)
                {
                    const scalar d =
                        (p - planes_[k].centre) & planes_[k].normal;
                    if (d > nearest)
                    {
                        nearest = d;
                        exitFace = planes_[k].face;
                    }
                }
            }
            return -1;
        }

        exitFace = planes_[exitPlane].face;

        // Slightly outside a face plane: a concave (polyhedral) cell may
        // still hold p.  Test before stepping, or the walk can oscillate
        // between such a cell and its neighbour.
        if
        (
            !convexCell_[celli]
         && exitDist < concaveTolerance_*cbrt(mesh_.cellVolumes()[celli])
         && mesh_.pointInCell(p, celli, polyMesh::CELL_TETS)
        )
        {
            exitFace = -1;
            return celli;
        }

        if (planes_[exitPlane].across < 0)
        {
            // Left this mesh part through a boundary face
            return -1;
        }

        celli = planes_[exitPlane].across;
    }

    // Did not settle: gave up inside the mesh
    exitFace = -1;
    return -1;
}


Foam::label Foam::particleLocator::findCell
(
    const point& p,
    const label previousCell
) const
{
    if (previousCell >= 0 && previousCell < mesh_.nCells())
    {
        label lastCell, exitFace;
        const label celli = walk(p, previousCell, lastCell, exitFace);
        if (celli >= 0)
        {
            return celli;
        }
    }

    ++nGlobalSearches_;
    return search_.findCell(p, -1, true);
}


Foam::label Foam::particleLocator::walkFrom
(
    const point& p,
    const label celli,
    label& lastCell,
    label& exitFace
) const
{
    return walk(p, celli, lastCell, exitFace);
}


Foam::scalar Foam::particleLocator::wallDistance
(
    const point& p,
    const label celli,
    const scalar maxDist
) const
{
    if (!wallTree_.valid() || wallLowerBound_[celli] > maxDist)
    {
        return GREAT;
    }

    // Every wall face within maxDist of a point of this cell is within
    // reach + maxDist of its centre, so among the candidates; if p is
    // further than maxDist from each candidate's plane (less its warp),
    // no wall face is within maxDist of p
    if (wallCandidateRange_[celli] < maxDist)
    {
        const scalar halfWidth = cellReach_[celli] + maxDist;
        const point& c = mesh_.cellCentres()[celli];
        wallCandidates_[celli] = wallTree_->findBox
        (
            treeBoundBox
            (
                c - vector::uniform(halfWidth), c + vector::uniform(halfWidth)
            )
        );
        wallCandidateRange_[celli] = maxDist;
    }
    bool near = false;
    for (const label k : wallCandidates_[celli])
    {
        const cellPlane& plane = wallPlanes_[k];
        if (mag((p - plane.centre) & plane.normal) - wallWarp_[k] <= maxDist)
        {
            near = true;
            break;
        }
    }
    if (!near)
    {
        return GREAT;
    }

    const pointIndexHit hit = wallTree_->findNearest(p, sqr(maxDist));

    return hit.hit() ? mag(hit.hitPoint() - p) : GREAT;
}


Foam::label Foam::particleLocator::nGlobalSearches() const
{
    const label n = nGlobalSearches_;
    nGlobalSearches_ = 0;
    return n;
}
