/*---------------------------------------------------------------------------*\
  rbdPacking: hard-body rigid body dynamics packings for OpenFOAM
\*---------------------------------------------------------------------------*/

#include "planeSection.H"
#include "volumeBelowPlane.H"
#include "foamFile.H"
#include "boundBox.H"
#include "error.H"

#include <cmath>
#include <limits>

// * * * * * * * * * * * * * * * * Functions * * * * * * * * * * * * * * * * //

Foam::scalarField Foam::rbd::planeSection::cellAreas
(
    const pointField& points,
    const faceList& faces,
    const labelUList& owner,
    const labelUList& neighbour,
    const label nCells,
    const scalar z0
)
{
    scalarField A(nCells, Zero);
    if (points.empty())
    {
        return A;
    }
    const point origin(boundBox(points).centre());
    const vector ez(0, 0, 1);

    forAll(faces, facei)
    {
        const face& f = faces[facei];
        // Quick rejection: the face does not reach across the plane
        bool below = false, above = false;
        for (const label pi : f)
        {
            (points[pi].z() < z0 ? below : above) = true;
        }
        if (!(below && above))
        {
            continue;
        }

        point c(Zero);
        for (const label pi : f)
        {
            c += points[pi];
        }
        c = c/f.size() - origin;
        scalar s = 0;
        forAll(f, i)
        {
            const point tri[3] =
            {
                c,
                points[f[i]] - origin,
                points[f.nextLabel(i)] - origin
            };
            // The vertex alone on its side, and the cut's ends on its two
            // edges
            label nBelow = 0;
            for (const point& p : tri)
            {
                nBelow += p.z() + origin.z() < z0;
            }
            if (nBelow == 0 || nBelow == 3)
            {
                continue;
            }
            const bool loneBelow = nBelow == 1;
            label lone = 0;
            for (label k = 0; k < 3; ++k)
            {
                if ((tri[k].z() + origin.z() < z0) == loneBelow)
                {
                    lone = k;
                }
            }
            const point& p = tri[lone];
            const auto cut = [&](const point& q)
            {
                const scalar t =
                    (z0 - origin.z() - p.z())/(q.z() - p.z());
                return p + t*(q - p);
            };
            point a = cut(tri[(lone + 1) % 3]);
            point b = cut(tri[(lone + 2) % 3]);
            const vector n((tri[1] - tri[0]) ^ (tri[2] - tri[0]));
            if (((b - a) & (ez ^ n)) < 0)
            {
                std::swap(a, b);
            }
            s += 0.5*(a.x()*b.y() - a.y()*b.x());
        }
        A[owner[facei]] += s;
        if (facei < neighbour.size())
        {
            A[neighbour[facei]] -= s;
        }
    }
    return A;
}


Foam::scalar Foam::rbd::planeSection::volumeBelow
(
    const pointField& points,
    const faceList& faces,
    const label nInternalFaces,
    const scalar z0
)
{
    if (points.empty())
    {
        return 0;
    }
    const point origin(boundBox(points).centre());
    const scalar c = z0 - origin.z();

    scalar V = 0;
    for (label facei = nInternalFaces; facei < faces.size(); ++facei)
    {
        const face& f = faces[facei];
        point fc(Zero);
        for (const label pi : f)
        {
            fc += points[pi];
        }
        fc = fc/f.size() - origin;
        forAll(f, i)
        {
            // Coordinates relative to the origin
            addVolumeBelowPlane
            (
                fc, points[f[i]] - origin, points[f.nextLabel(i)] - origin,
                c, V
            );
        }
    }
    return V;
}


Foam::scalar Foam::rbd::planeSection::areaAverage
(
    const scalarField& cellValues,
    const scalarField& areas,
    scalar& area
)
{
    if (cellValues.size() != areas.size())
    {
        FatalErrorInFunction
            << cellValues.size() << " cell values for " << areas.size()
            << " cells" << exit(FatalError);
    }
    area = 0;
    scalar sum = 0;
    forAll(areas, celli)
    {
        area += areas[celli];
        sum += areas[celli]*cellValues[celli];
    }
    return
        area > 0 ? sum/area : std::numeric_limits<scalar>::quiet_NaN();
}


Foam::scalarField Foam::rbd::planeSection::readInternalField
(
    const fileName& file,
    const label nCells
)
{
    const dictionary dict(readFoamFile(file));
    return scalarField("internalField", dict, nCells);
}


// ************************************************************************* //
