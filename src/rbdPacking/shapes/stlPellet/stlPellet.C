/*---------------------------------------------------------------------------*\
  rbdPacking: hard-body rigid body dynamics packings for OpenFOAM
\*---------------------------------------------------------------------------*/

#include "stlPellet.H"
#include "dictionaryChecks.H"
#include "stlIO.H"
#include "massProperties.H"
#include "addToRunTimeSelectionTable.H"

// * * * * * * * * * * * * * * Static Data Members * * * * * * * * * * * * * //

namespace Foam
{
namespace rbd
{
    defineTypeNameAndDebug(stlPellet, 0);
    addToRunTimeSelectionTable(pelletShape, stlPellet, dictionary);
}
}


// * * * * * * * * * * * * * * * * Constructors  * * * * * * * * * * * * * * //

Foam::rbd::stlPellet::stlPellet(const dictionary& dict)
:
    pelletShape(dict, 0),
    file_(dict.get<fileName>("file")),
    path_(casePath(file_)),
    scale_(getPositiveOrDefault(dict, "scale", 1, "-")),
    surface_(),
    volume_(0),
    inertia_(Zero)
{
    checkEntries(dict, {"file", "scale"});
    if (dict.found("faces"))
    {
        WarningInFunction
            << "faces in " << dict.name() << " is ignored for an stl "
            << "pellet: its mesh is the file's" << endl;
    }

    triMesh surface;
    string reason;
    if (!readSTL(path_, scale_, surface, reason))
    {
        badEntry
        (
            dict, "file", file_,
            "a closed, outward-oriented STL surface (" + path_ + ": "
          + reason + ")"
        );
    }

    if (surface.nFaces() > maxFaces)
    {
        badEntry
        (
            dict, "file", file_,
            "an STL of at most " + Foam::name(maxFaces) + " triangles ("
          + path_ + " has " + Foam::name(surface.nFaces())
          + "; coarsen it)"
        );
    }

    const massProperties mp(surface, 1);
    surface_ = mp.toPrincipalFrame(surface);
    volume_ = mp.volume();
    inertia_ = mp.principalMoments();
    if (faces_ == 0)
    {
        faces_ = surface_.nFaces();
    }
}


// * * * * * * * * * * * * * * * Member Functions  * * * * * * * * * * * * * //

void Foam::rbd::stlPellet::write(Ostream& os) const
{
    pelletShape::write(os);
    os.writeEntry("file", file_);
    os.writeEntry("scale", scale_);
    os.writeKeyword("mesh") << surface_.nFaces() << " faces, volume "
        << volume_ << " m^3, bounding radius " << boundingRadius() << " m"
        << token::END_STATEMENT << nl;
}


// ************************************************************************* //
