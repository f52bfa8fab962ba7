/*---------------------------------------------------------------------------*\
  rbdPacking: hard-body rigid body dynamics packings for OpenFOAM
\*---------------------------------------------------------------------------*/

#include "cylinder.H"
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
    defineTypeNameAndDebug(cylinder, 0);
    addToRunTimeSelectionTable(pelletShape, cylinder, dictionary);
}
}


// * * * * * * * * * * * * * * * * Constructors  * * * * * * * * * * * * * * //

Foam::rbd::cylinder::cylinder(const dictionary& dict)
:
    pelletShape(dict, 4400),
    d_(getPositive(dict, "diameter", "m")),
    h_(getPositive(dict, "height", "m"))
{
    checkEntries(dict, {"diameter", "height"});
}


// * * * * * * * * * * * * * * * Member Functions  * * * * * * * * * * * * * //

Foam::scalar Foam::rbd::cylinder::volume() const
{
    return pi*sqr(0.5*d_)*h_;
}


Foam::vector Foam::rbd::cylinder::principalInertiaPerDensity() const
{
    // Solid cylinder: Izz = m a^2/2, Ixx = Iyy = m (3 a^2 + h^2)/12
    const scalar m = volume();
    const scalar a2 = sqr(0.5*d_);
    const scalar Ixx = m*(3*a2 + sqr(h_))/12;
    return vector(Ixx, Ixx, 0.5*m*a2);
}


Foam::scalar Foam::rbd::cylinder::boundingRadius() const
{
    return Foam::sqrt(sqr(0.5*d_) + sqr(0.5*h_));
}


Foam::scalar Foam::rbd::cylinder::diameter() const
{
    return d_;
}


Foam::scalar Foam::rbd::cylinder::area() const
{
    return pi*d_*h_ + 0.5*pi*sqr(d_);
}


void Foam::rbd::cylinder::write(Ostream& os) const
{
    pelletShape::write(os);
    os.writeEntry("diameter", d_);
    os.writeEntry("height", h_);
}


Foam::rbd::triMesh Foam::rbd::cylinder::buildMesh() const
{
    return pelletMeshes::cylinder(d_, h_, faces_);
}


Foam::rbd::triMesh Foam::rbd::cylinder::buildVolumeTrueMesh() const
{
    return pelletMeshes::cylinder
    (
        d_, h_, faces_, pelletMeshes::facets::volumeTrue
    );
}


Foam::string Foam::rbd::cylinder::volumeTrueConstruction() const
{
    return prismConstruction;
}


Foam::autoPtr<Foam::rbd::prismProfile> Foam::rbd::cylinder::prism() const
{
    return autoPtr<prismProfile>::New
    (
        List<vector2D>({vector2D::zero}), List<scalar>({0.5*d_}),
        List<vector2D>(), List<scalar>(), 0.5*h_
    );
}


// ************************************************************************* //
