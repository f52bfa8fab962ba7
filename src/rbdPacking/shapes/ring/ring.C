/*---------------------------------------------------------------------------*\
  rbdPacking: hard-body rigid body dynamics packings for OpenFOAM
\*---------------------------------------------------------------------------*/

#include "ring.H"
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
    defineTypeNameAndDebug(ring, 0);
    addToRunTimeSelectionTable(pelletShape, ring, dictionary);
}
}


// * * * * * * * * * * * * * * Static Data Members * * * * * * * * * * * * * //

const Foam::scalar Foam::rbd::ring::minWall = 0.01;


// * * * * * * * * * * * * * * * * Constructors  * * * * * * * * * * * * * * //

Foam::rbd::ring::ring(const dictionary& dict)
:
    pelletShape(dict, 8008),
    d_(getPositive(dict, "diameter", "m")),
    di_(getPositive(dict, "innerDiameter", "m")),
    h_(getPositive(dict, "height", "m"))
{
    checkEntries(dict, {"diameter", "innerDiameter", "height"});

    // A wall of at least 1 % of the diameter (Raschig rings have 5-20 %):
    // a thinner one is a film that neither the contacts nor a CFD mesh
    // resolve
    if (di_ > (1 - 2*minWall)*d_)
    {
        badEntry
        (
            dict, "innerDiameter", di_,
            "a number > 0 and at most " + Foam::name(1 - 2*minWall)
          + " diameter = " + Foam::name((1 - 2*minWall)*d_) + " [m] (a "
            "wall of at least " + Foam::name(100*minWall) + " % of the "
            "diameter " + Foam::name(d_) + " m)"
        );
    }
}


// * * * * * * * * * * * * * * * Member Functions  * * * * * * * * * * * * * //

Foam::scalar Foam::rbd::ring::volume() const
{
    return 0.25*pi*(sqr(d_) - sqr(di_))*h_;
}


Foam::vector Foam::rbd::ring::principalInertiaPerDensity() const
{
    // Hollow cylinder: Izz = m (a^2 + b^2)/2,
    // Ixx = Iyy = m (3 (a^2 + b^2) + h^2)/12
    const scalar m = volume();
    const scalar s2 = sqr(0.5*d_) + sqr(0.5*di_);
    const scalar Ixx = m*(3*s2 + sqr(h_))/12;
    return vector(Ixx, Ixx, 0.5*m*s2);
}


Foam::scalar Foam::rbd::ring::boundingRadius() const
{
    return Foam::sqrt(sqr(0.5*d_) + sqr(0.5*h_));
}


Foam::scalar Foam::rbd::ring::diameter() const
{
    return d_;
}


Foam::scalar Foam::rbd::ring::area() const
{
    return pi*(d_ + di_)*h_ + 0.5*pi*(sqr(d_) - sqr(di_));
}


void Foam::rbd::ring::write(Ostream& os) const
{
    pelletShape::write(os);
    os.writeEntry("diameter", d_);
    os.writeEntry("innerDiameter", di_);
    os.writeEntry("height", h_);
}


Foam::rbd::triMesh Foam::rbd::ring::buildMesh() const
{
    return pelletMeshes::ring(d_, di_, h_, faces_);
}


Foam::rbd::triMesh Foam::rbd::ring::buildVolumeTrueMesh() const
{
    return pelletMeshes::ring
    (
        d_, di_, h_, faces_, pelletMeshes::facets::volumeTrue
    );
}


Foam::string Foam::rbd::ring::volumeTrueConstruction() const
{
    return prismConstruction;
}


Foam::autoPtr<Foam::rbd::prismProfile> Foam::rbd::ring::prism() const
{
    return autoPtr<prismProfile>::New
    (
        List<vector2D>({vector2D::zero}), List<scalar>({0.5*d_}),
        List<vector2D>({vector2D::zero}), List<scalar>({0.5*di_}), 0.5*h_
    );
}


// ************************************************************************* //
