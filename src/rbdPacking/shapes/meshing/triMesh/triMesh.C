/*---------------------------------------------------------------------------*\
  rbdPacking: hard-body rigid body dynamics packings for OpenFOAM
\*---------------------------------------------------------------------------*/

#include "triMesh.H"
#include "EdgeMap.H"

// * * * * * * * * * * * * * * * * Constructors  * * * * * * * * * * * * * * //

Foam::rbd::triMesh::triMesh
(
    const pointField& points,
    const List<triFace>& faces
)
:
    points_(points),
    faces_(faces)
{}


Foam::rbd::triMesh::triMesh(pointField&& points, List<triFace>&& faces)
:
    points_(std::move(points)),
    faces_(std::move(faces))
{}


// * * * * * * * * * * * * * * * Member Functions  * * * * * * * * * * * * * //

Foam::scalar Foam::rbd::triMesh::volume() const
{
    if (faces_.empty())
    {
        return 0;
    }

    // Tetrahedra from a vertex of the mesh rather than from the origin:
    // the same for a closed mesh, with less cancellation far from the origin
    const point& o = points_[faces_[0][0]];

    scalar v6 = 0;
    for (const triFace& f : faces_)
    {
        v6 +=
            (points_[f[0]] - o)
          & ((points_[f[1]] - o) ^ (points_[f[2]] - o));
    }
    return v6/6;
}


Foam::scalar Foam::rbd::triMesh::area() const
{
    scalar a = 0;
    for (const triFace& f : faces_)
    {
        a += f.mag(points_);
    }
    return a;
}


Foam::scalar Foam::rbd::triMesh::boundingRadius() const
{
    scalar r2 = 0;
    for (const point& p : points_)
    {
        r2 = max(r2, magSqr(p));
    }
    return Foam::sqrt(r2);
}


Foam::boundBox Foam::rbd::triMesh::bounds() const
{
    return boundBox(points_, false);
}


Foam::vectorField Foam::rbd::triMesh::faceNormals() const
{
    vectorField n(faces_.size());
    forAll(faces_, facei)
    {
        n[facei] = faces_[facei].unitNormal(points_);
    }
    return n;
}


Foam::edgeList Foam::rbd::triMesh::edges() const
{
    EdgeMap<label> seen(3*faces_.size()/2);
    DynamicList<edge> es(3*faces_.size()/2);

    for (const triFace& f : faces_)
    {
        for (label i = 0; i < 3; ++i)
        {
            const edge e(f[i], f[(i + 1) % 3]);
            if (seen.insert(e, es.size()))
            {
                es.append(e);
            }
        }
    }
    return edgeList(std::move(es));
}


Foam::rbd::triMesh Foam::rbd::triMesh::transformed
(
    const tensor& R,
    const vector& x
) const
{
    triMesh m(*this);
    m.transform(R, x);
    return m;
}


Foam::tmp<Foam::pointField> Foam::rbd::triMesh::transformedPoints
(
    const tensor& R,
    const vector& x
) const
{
    tmp<pointField> tpts(new pointField(points_.size()));
    pointField& pts = tpts.ref();
    forAll(points_, i)
    {
        pts[i] = (R & points_[i]) + x;
    }
    return tpts;
}


void Foam::rbd::triMesh::transform(const tensor& R, const vector& x)
{
    for (point& p : points_)
    {
        p = (R & p) + x;
    }
}


void Foam::rbd::triMesh::scale(const scalar factor)
{
    points_ *= factor;
}


void Foam::rbd::triMesh::flip()
{
    for (triFace& f : faces_)
    {
        f.flip();
    }
}


void Foam::rbd::triMesh::writeInfo(Ostream& os) const
{
    os  << "points " << nPoints() << ", triangles " << nFaces()
        << ", volume " << volume() << " m^3, area " << area()
        << " m^2, bounding radius " << boundingRadius() << " m";
}


// ************************************************************************* //
