/*---------------------------------------------------------------------------*\
  rbdPacking: hard-body rigid body dynamics packings for OpenFOAM
\*---------------------------------------------------------------------------*/

#include "cylinderWithHoles.H"
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
    defineTypeNameAndDebug(cylinderWithHoles, 0);
    addToRunTimeSelectionTable(pelletShape, cylinderWithHoles, dictionary);
}
}


// * * * * * * * * * * * * * * * * Constructors  * * * * * * * * * * * * * * //

Foam::rbd::cylinderWithHoles::cylinderWithHoles(const dictionary& dict)
:
    meshedPellet(dict, 8000),
    d_(getPositive(dict, "diameter", "m")),
    h_(getPositive(dict, "height", "m")),
    nHoles_(getPositiveLabel(dict, "holes")),
    dh_(getPositive(dict, "holeDiameter", "m")),
    dc_(2*pelletMeshes::defaultHoleCircleRadius(d_, nHoles_, dh_))
{
    checkEntries
    (
        dict, {"diameter", "height", "holes", "holeDiameter",
        "holePitchDiameter"}
    );

    const scalar s = nHoles_ > 1 ? std::sin(pi/nHoles_) : 1;

    if (dict.found("holePitchDiameter"))
    {
        dc_ = getNonNegativeOrDefault(dict, "holePitchDiameter", 0, "m");

        // Holes inside: dc < D - dh; apart: dc > dh/s
        const scalar lo = nHoles_ > 1 ? dh_/s : 0;
        const scalar hi = d_ - dh_;
        if (!(lo < hi))
        {
            badEntry
            (
                dict, "holeDiameter", dh_,
                "a number > 0 and below " + Foam::name(d_*s/(1 + s))
              + " [m] for " + Foam::name(nHoles_) + " holes in diameter "
              + Foam::name(d_) + " (no pitch circle fits larger holes)"
            );
        }
        if (!(dc_ < hi) || (nHoles_ > 1 && !(dc_ > lo)))
        {
            badEntry
            (
                dict, "holePitchDiameter", dc_,
                string(nHoles_ > 1 ? "a number above " : "a number >= ")
              + Foam::name(lo) + " and below " + Foam::name(hi)
              + " [m] (holes apart and inside diameter " + Foam::name(d_)
              + ")"
            );
        }
    }
    else
    {
        const scalar hi = nHoles_ > 1 ? d_*s/(1 + s) : d_;
        if (!(dh_ < hi))
        {
            badEntry
            (
                dict, "holeDiameter", dh_,
                "a number > 0 and below " + Foam::name(hi) + " [m] for "
              + Foam::name(nHoles_) + " holes in diameter " + Foam::name(d_)
              + " on the default pitch circle"
            );
        }
    }

    const string why = pelletMeshes::cylinderWithHolesError
    (
        d_, h_, nHoles_, dh_, faces_, 0.5*dc_
    );
    if (!why.empty())
    {
        badEntry(dict, "holeDiameter", dh_, "holes that fit: " + why);
    }

    setSurface
    (
        pelletMeshes::cylinderWithHoles(d_, h_, nHoles_, dh_, faces_, 0.5*dc_)
    );
}


// * * * * * * * * * * * * * * * Member Functions  * * * * * * * * * * * * * //

Foam::scalar Foam::rbd::cylinderWithHoles::exactVolume() const
{
    return 0.25*pi*(sqr(d_) - nHoles_*sqr(dh_))*h_;
}


Foam::rbd::triMesh Foam::rbd::cylinderWithHoles::buildVolumeTrueMesh() const
{
    return toBodyFrame
    (
        pelletMeshes::cylinderWithHoles
        (
            d_, h_, nHoles_, dh_, faces_, 0.5*dc_,
            pelletMeshes::facets::volumeTrue
        )
    );
}


void Foam::rbd::cylinderWithHoles::write(Ostream& os) const
{
    meshedPellet::write(os);
    os.writeEntry("diameter", d_);
    os.writeEntry("height", h_);
    os.writeEntry("holes", nHoles_);
    os.writeEntry("holeDiameter", dh_);
    os.writeEntry("holePitchDiameter", dc_);
}


Foam::autoPtr<Foam::rbd::prismProfile> Foam::rbd::cylinderWithHoles::prism() const
{
    return inBodyFrame
    (
        autoPtr<prismProfile>::New
        (
            List<vector2D>({vector2D::zero}), List<scalar>({0.5*d_}),
            prismProfile::onCircle(nHoles_, 0.5*dc_),
            List<scalar>(nHoles_, 0.5*dh_), 0.5*h_
        )
    );
}


// ************************************************************************* //
