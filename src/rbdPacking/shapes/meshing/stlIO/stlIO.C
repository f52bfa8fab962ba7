/*---------------------------------------------------------------------------*\
  rbdPacking: hard-body rigid body dynamics packings for OpenFOAM
\*---------------------------------------------------------------------------*/

#include "stlIO.H"
#include "cgalMeshTools.H"
#include "error.H"
#include "mergePoints.H"
#include "boundBox.H"
#include "DynamicList.H"

#include <cstdint>
#include <cstring>
#include <iomanip>

// * * * * * * * * * * * * * * * Local Functions * * * * * * * * * * * * * //

namespace
{
    //- Append a 32-bit value little-endian
    void putLE32(char*& buf, const uint32_t v)
    {
        for (int i = 0; i < 4; ++i)
        {
            *buf++ = char((v >> (8*i)) & 0xffu);
        }
    }

    void putFloat(char*& buf, const double x)
    {
        const float f = float(x);
        uint32_t v;
        std::memcpy(&v, &f, 4);
        putLE32(buf, v);
    }

    const std::streamoff headerSize = 80;
}


// * * * * * * * * * * * * * * * * Functions * * * * * * * * * * * * * * * * //

Foam::label Foam::rbd::mergeCloseVertices
(
    pointField& points,
    List<triFace>& faces,
    const scalar relTol
)
{
    if (points.empty())
    {
        return 0;
    }
    const boundBox bb(points);
    labelList pointMap;
    pointField merged;
    if
    (
        !Foam::mergePoints
        (
            points, relTol*bb.mag(), false, pointMap, merged, bb.min()
        )
    )
    {
        return 0;
    }
    const label nMerged = points.size() - merged.size();
    points.transfer(merged);

    DynamicList<triFace> kept(faces.size());
    for (const triFace& f : faces)
    {
        const triFace g(pointMap[f[0]], pointMap[f[1]], pointMap[f[2]]);
        if (g[0] != g[1] && g[1] != g[2] && g[2] != g[0])
        {
            kept.append(g);
        }
    }
    faces.transfer(kept);
    return nMerged;
}


bool Foam::rbd::readSTL
(
    const fileName& file,
    const scalar scale,
    triMesh& mesh,
    string& reason
)
{
    mesh = triMesh();
    if (!(scale > 0))
    {
        reason = "the scale factor must be > 0, not " + Foam::name(scale);
        return false;
    }

    pointField points;
    List<triFace> faces;
    if (!cgalMeshTools::readSTL(file, points, faces, reason))
    {
        return false;
    }
    // Before the closure check: vertices that differ by a rounding error
    // are one vertex (relative tolerance: no unit assumed for the file)
    mergeCloseVertices(points, faces);
    points *= scale;

    triMesh m(std::move(points), std::move(faces));
    const string problem = checkClosedSolid(m);
    if (!problem.empty())
    {
        reason =
            "the triangles of " + file + " do not bound a solid pellet: "
          + problem;
        return false;
    }

    mesh = std::move(m);
    reason.clear();
    return true;
}


void Foam::rbd::writeSTL
(
    const fileName& file,
    const UList<triMesh>& meshes,
    const bool binary,
    const word& solidName
)
{
    stlWriter writer(file, binary, solidName);
    for (const triMesh& m : meshes)
    {
        writer.write(m);
    }
    writer.close();
}


// * * * * * * * * * * * * * * * * Constructors  * * * * * * * * * * * * * * //

Foam::rbd::stlWriter::stlWriter
(
    const fileName& file,
    const bool binary,
    const word& solidName
)
:
    file_(file),
    binary_(binary),
    solidName_(solidName),
    os_(file, binary ? std::ios::out | std::ios::binary : std::ios::out),
    nTriangles_(0)
{
    if (!os_.good())
    {
        FatalErrorInFunction
            << "Cannot open " << file_ << " for writing"
            << exit(FatalError);
    }

    if (binary_)
    {
        // Must not begin with "solid" (read as ASCII otherwise)
        char header[headerSize];
        std::memset(header, ' ', headerSize);
        const std::string text =
            "rbdPacking binary STL, one region: " + solidName_;
        std::memcpy
        (
            header,
            text.data(),
            std::min(text.size(), std::size_t(headerSize))
        );
        os_.write(header, headerSize);
        char count[4];
        char* p = count;
        putLE32(p, 0);
        os_.write(count, 4);
    }
    else
    {
        os_ << "solid " << solidName_ << '\n'
            << std::setprecision(9);
    }
}


// * * * * * * * * * * * * * * * * Destructor  * * * * * * * * * * * * * * * //

Foam::rbd::stlWriter::~stlWriter()
{
    close();
}


// * * * * * * * * * * * * * * * Member Functions  * * * * * * * * * * * * * //

void Foam::rbd::stlWriter::writeTriangle
(
    const point& a,
    const point& b,
    const point& c
)
{
    vector n = (b - a) ^ (c - a);
    const scalar magN = mag(n);
    n = magN > 0 ? n/magN : vector::zero;
    const vector& cn = n;

    if (binary_)
    {
        char buf[50];
        char* p = buf;
        for (const vector* v : {&cn, &a, &b, &c})
        {
            putFloat(p, v->x());
            putFloat(p, v->y());
            putFloat(p, v->z());
        }
        *p++ = 0;
        *p++ = 0;
        os_.write(buf, 50);
    }
    else
    {
        os_ << " facet normal " << n.x() << ' ' << n.y() << ' ' << n.z()
            << "\n  outer loop\n";
        for (const point* v : {&a, &b, &c})
        {
            os_ << "   vertex " << v->x() << ' ' << v->y() << ' ' << v->z()
                << '\n';
        }
        os_ << "  endloop\n endfacet\n";
    }
    ++nTriangles_;
}


void Foam::rbd::stlWriter::write(const triMesh& mesh)
{
    if (!os_.is_open())
    {
        FatalErrorInFunction
            << "Writing to " << file_ << " after closing it"
            << exit(FatalError);
    }
    const pointField& pts = mesh.points();
    for (const triFace& f : mesh.faces())
    {
        writeTriangle(pts[f[0]], pts[f[1]], pts[f[2]]);
    }
}


void Foam::rbd::stlWriter::write
(
    const triMesh& bodyMesh,
    const tensor& R,
    const vector& x
)
{
    if (!os_.is_open())
    {
        FatalErrorInFunction
            << "Writing to " << file_ << " after closing it"
            << exit(FatalError);
    }
    const pointField& pts = bodyMesh.points();
    for (const triFace& f : bodyMesh.faces())
    {
        writeTriangle
        (
            (R & pts[f[0]]) + x,
            (R & pts[f[1]]) + x,
            (R & pts[f[2]]) + x
        );
    }
}


void Foam::rbd::stlWriter::close()
{
    if (!os_.is_open())
    {
        return;
    }

    if (binary_)
    {
        char count[4];
        char* p = count;
        putLE32(p, uint32_t(nTriangles_));
        os_.seekp(headerSize);
        os_.write(count, 4);
    }
    else
    {
        os_ << "endsolid " << solidName_ << '\n';
    }

    os_.close();
    if (os_.fail())
    {
        FatalErrorInFunction
            << "Error writing " << file_ << exit(FatalError);
    }
}


// ************************************************************************* //
