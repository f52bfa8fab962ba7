/*---------------------------------------------------------------------------*\
  rbdPacking: hard-body rigid body dynamics packings for OpenFOAM
\*---------------------------------------------------------------------------*/

#include "contactGeometry.H"
#include "pelletMeshes.H"
#include "cgalMeshTools.H"
#include "transform.H"

// * * * * * * * * * * * * * * * Functions * * * * * * * * * * * * * * * * * //

Foam::List<Foam::rbd::contact> Foam::rbd::contactGeometry::touching
(
    const UList<contact>& contacts,
    const scalar maxGap,
    const scalar minSpacing
)
{
    DynamicList<contact> kept;
    for (const contact& c : contacts)
    {
        if (c.gap > maxGap || c.k == tubeBottom || c.k < tubeBottom)
        {
            continue;
        }
        bool near = false;
        for (const contact& o : kept)
        {
            if
            (
                o.i == c.i && o.k == c.k
             && magSqr(o.p - c.p) < sqr(minSpacing)
            )
            {
                near = true;
                break;
            }
        }
        if (!near)
        {
            kept.append(c);
        }
    }
    return List<contact>(std::move(kept));
}


void Foam::rbd::contactGeometry::bridgeAxis
(
    const contact& c,
    const scalar diameter,
    point& start,
    point& end
)
{
    const scalar half = 0.5*max(c.gap, scalar(0)) + 0.5*diameter;
    start = c.p - half*c.n;
    end = c.p + half*c.n;
}


Foam::rbd::triMesh Foam::rbd::contactGeometry::bridge
(
    const contact& c,
    const scalar diameter,
    const label faces
)
{
    point start, end;
    bridgeAxis(c, diameter, start, end);
    const scalar length = mag(end - start);

    // Cylinder along z, centred on the origin, turned to n
    triMesh m(pelletMeshes::cylinder(diameter, length, faces));
    const vector z(0, 0, 1);
    const vector n(normalised(c.n));
    const tensor R =
        (n & z) < -0.999
      ? (rotationTensor(-z, n) & tensor(1, 0, 0, 0, -1, 0, 0, 0, -1))
      : rotationTensor(z, n);
    m.transform(R, 0.5*(start + end));
    return m;
}


Foam::rbd::triMesh Foam::rbd::contactGeometry::cap
(
    const triMesh& pellet,
    const point& p,
    const vector& m,
    const scalar capHeight
)
{
    const vector u(normalised(m));

    // Nothing to cut where the pellet keeps to the plane already, within
    // capSkip capHeight: the second cap of a face lying on a face (the
    // contact points of a patch, beyond the spacing of touching(), share
    // one plane) would cut along the first cap's face, a plane CGAL's
    // corefinement failed on (an assertion, on a bed of six cylinders)
    scalar reach = -GREAT;
    for (const point& x : pellet.points())
    {
        reach = max(reach, capHeight - ((x - p) & u));
    }
    if (reach <= capSkip*capHeight)
    {
        return pellet;
    }

    // Nor where the plane cuts deep into the pellet (capDepthLimit): a
    // contact normal across the pellet, not a cap
    if (reach > capDepthLimit*capHeight)
    {
        return pellet;
    }

    // clipByPlane keeps (x - q) . (-u) <= 0, i.e. (x - p) . u >= capHeight
    return cgalMeshTools::clipByPlane(pellet, p + capHeight*u, -u);
}


// ************************************************************************* //
