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
    "restitution", "rotation"
});


// * * * * * * * * * * * * * * Static Data Members * * * * * * * * * * * * * //

const Foam::label Foam::rbd::pelletShape::maxFaces = 200000;


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
    mesh_()
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
}


// ************************************************************************* //
