/*---------------------------------------------------------------------------*\
  rbdPacking: hard-body rigid body dynamics packings for OpenFOAM
\*---------------------------------------------------------------------------*/

#include "pelletShape.H"
#include "dictionaryChecks.H"
#include "mathematicalConstants.H"

// * * * * * * * * * * * * * * Static Data Members * * * * * * * * * * * * * //

namespace Foam
{
namespace rbd
{
    defineTypeNameAndDebug(pelletShape, 0);
    defineRunTimeSelectionTable(pelletShape, dictionary);
}
}

const Foam::wordList Foam::rbd::pelletShape::commonEntries
({
    "shape", "faces", "number", "fillHeight", "density", "friction",
    "restitution", "rollingFriction", "rotation"
});


// * * * * * * * * * * * * * * Static Data Members * * * * * * * * * * * * * //

const Foam::label Foam::rbd::pelletShape::maxFaces = 200000;

const char* const Foam::rbd::pelletShape::prismConstruction =
    "volume-true facets, each curved wall's points moved along its radius "
    "to the area of its curve, flat faces and height exact";


// * * * * * * * * * * * * * * * * Constructors  * * * * * * * * * * * * * * //

Foam::rbd::pelletShape::pelletShape
(
    const dictionary& dict,
    const label defaultFaces
)
:
    faces_
    (
        dict.found("faces")
      ? getLabelOrDefault(dict, "faces", defaultFaces, 20, maxFaces)
      : defaultFaces
    ),
    mesh_(),
    volumeTrueMesh_()
{}


// * * * * * * * * * * * * * * * Member Functions  * * * * * * * * * * * * * //

Foam::scalar Foam::rbd::pelletShape::volumeEquivalentDiameter() const
{
    return cbrt(6*volume()/constant::mathematical::pi);
}


Foam::scalar Foam::rbd::pelletShape::sphericity() const
{
    return
        cbrt(constant::mathematical::pi)*pow(6*volume(), 2.0/3.0)/area();
}


const Foam::rbd::triMesh& Foam::rbd::pelletShape::mesh() const
{
    if (!mesh_)
    {
        mesh_.reset(new triMesh(buildMesh()));
    }
    return *mesh_;
}


const Foam::rbd::triMesh& Foam::rbd::pelletShape::volumeTrueMesh() const
{
    if (!volumeTrueMesh_)
    {
        volumeTrueMesh_.reset(new triMesh(buildVolumeTrueMesh()));
    }
    return *volumeTrueMesh_;
}


void Foam::rbd::pelletShape::checkEntries
(
    const dictionary& dict,
    std::initializer_list<word> own
)
{
    wordList known(commonEntries);
    for (const word& w : own)
    {
        known.append(w);
    }
    checkKnownEntries(dict, known);
}


void Foam::rbd::pelletShape::write(Ostream& os) const
{
    os.writeEntry("shape", type());
    os.writeEntry("faces", faces_);

    // The mesh has about faces_ triangles (a cylinder needs at least its
    // caps' fans and side strips): say what it has when that differs
    const label n = mesh().nFaces();
    if (n != faces_)
    {
        os  << indent << "// meshed with " << n << " triangles" << nl;
    }

    // What the CFD case gets: the polyhedron of pellets.stl, the same
    // triangles with vertices moved by at most maxMove
    const scalar V = exactVolume();
    const pointField& p = mesh().points();
    const pointField& q = volumeTrueMesh().points();
    scalar maxMove = 0;
    forAll(p, i)
    {
        maxMove = max(maxMove, mag(q[i] - p[i]));
    }
    os  << indent << "// pellets.stl: " << volumeTrueConstruction().c_str()
        << "; volume " << volumeTrueMesh().volume() << " m^3 = exact "
        << V << " m^3 (the contact mesh's " << 100*(mesh().volume()/V - 1)
        << " %); vertices moved by at most " << maxMove << " m ("
        << 100*maxMove/boundingRadius() << " % of the bounding radius)"
        << nl;
}


Foam::string Foam::rbd::pelletShape::volumeTrueConstruction() const
{
    return "the pellet mesh as given";
}


// ************************************************************************* //
