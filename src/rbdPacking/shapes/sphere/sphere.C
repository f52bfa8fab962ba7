/*---------------------------------------------------------------------------*\
  rbdPacking: hard-body rigid body dynamics packings for OpenFOAM
\*---------------------------------------------------------------------------*/

#include "sphere.H"
#include "dictionaryChecks.H"
#include "pelletMeshes.H"
#include "mathematicalConstants.H"
#include "addToRunTimeSelectionTable.H"

using Foam::constant::mathematical::pi;

// * * * * * * * * * * * * * * Static Data Members * * * * * * * * * * * * * //

namespace Foam
{
namespace rbd
{
    defineTypeNameAndDebug(sphere, 0);
    addToRunTimeSelectionTable(pelletShape, sphere, dictionary);
}
}


// * * * * * * * * * * * * * * * * Constructors  * * * * * * * * * * * * * * //

Foam::rbd::sphere::sphere(const dictionary& dict)
:
    pelletShape(dict, 1280),
    d_(getPositive(dict, "diameter", "m"))
{
    checkEntries(dict, {"diameter"});
}


// * * * * * * * * * * * * * * * Member Functions  * * * * * * * * * * * * * //

Foam::scalar Foam::rbd::sphere::volume() const
{
    return pi*pow3(d_)/6;
}


Foam::vector Foam::rbd::sphere::principalInertiaPerDensity() const
{
    // I = 2/5 m a^2
    const scalar I = 0.4*volume()*sqr(0.5*d_);
    return vector(I, I, I);
}


Foam::scalar Foam::rbd::sphere::boundingRadius() const
{
    return 0.5*d_;
}


Foam::scalar Foam::rbd::sphere::diameter() const
{
    return d_;
}


Foam::scalar Foam::rbd::sphere::area() const
{
    return pi*sqr(d_);
}


void Foam::rbd::sphere::write(Ostream& os) const
{
    pelletShape::write(os);
    os.writeEntry("diameter", d_);
}


Foam::rbd::triMesh Foam::rbd::sphere::buildMesh() const
{
    return pelletMeshes::sphere(d_, faces_);
}


Foam::rbd::triMesh Foam::rbd::sphere::buildVolumeTrueMesh() const
{
    return pelletMeshes::sphere
    (
        d_, faces_, pelletMeshes::facets::volumeTrue
    );
}


Foam::string Foam::rbd::sphere::volumeTrueConstruction() const
{
    return
        "volume-true facets, the sphere mesh scaled about its centre by "
      + Foam::name(mag(volumeTrueMesh().points()[0])/mag(mesh().points()[0]));
}


// ************************************************************************* //
