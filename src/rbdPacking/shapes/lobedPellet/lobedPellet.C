/*---------------------------------------------------------------------------*\
  rbdPacking: hard-body rigid body dynamics packings for OpenFOAM
\*---------------------------------------------------------------------------*/

#include "lobedPellet.H"
#include "dictionaryChecks.H"
#include "pelletMeshes.H"
#include "mathematicalConstants.H"

using Foam::constant::mathematical::pi;

// * * * * * * * * * * * * * * * * Constructors  * * * * * * * * * * * * * * //

Foam::rbd::lobedPellet::lobedPellet
(
    const dictionary& dict,
    const label nLobes
)
:
    meshedPellet(dict, 8000),
    nLobes_(nLobes),
    dl_(getPositive(dict, "lobeDiameter", "m")),
    h_(getPositive(dict, "height", "m")),
    dc_(defaultPitchDiameter(nLobes, dl_))
{
    checkEntries(dict, {"lobeDiameter", "height", "lobePitchDiameter"});

    if (dict.found("lobePitchDiameter"))
    {
        dc_ = getPositive(dict, "lobePitchDiameter", "m");
        if (!(dc_ < dl_))
        {
            badEntry
            (
                dict, "lobePitchDiameter", dc_,
                "a number > 0 and below lobeDiameter ("
              + Foam::name(dl_) + ") [m]"
            );
        }
    }

    setSurface(pelletMeshes::lobes(nLobes_, dl_, h_, faces_, 0.5*dc_));
}


// * * * * * * * * * * * * * * Static Member Functions * * * * * * * * * * * //

Foam::scalar Foam::rbd::lobedPellet::defaultPitchDiameter
(
    const label nLobes,
    const scalar lobeDiameter
)
{
    return 2*pelletMeshes::defaultLobeCentreRadius(nLobes, lobeDiameter);
}


Foam::scalar Foam::rbd::lobedPellet::crossSectionArea
(
    const label nLobes,
    const scalar lobeDiameter,
    const scalar pitchDiameter
)
{
    const label n = nLobes;
    const scalar r = 0.5*lobeDiameter;
    const scalar rc = 0.5*pitchDiameter;

    // Valley point of lobes 0 and 1 at distance t on the ray at pi/n
    const scalar s = std::sin(pi/n);
    const scalar c = std::cos(pi/n);
    const scalar t = rc*c + std::sqrt(sqr(r) - sqr(rc*s));
    const scalar beta = std::atan2(t*s, t*c - rc);

    return n*(rc*r*std::sin(beta) + sqr(r)*beta);
}


// * * * * * * * * * * * * * * * Member Functions  * * * * * * * * * * * * * //

Foam::scalar Foam::rbd::lobedPellet::exactVolume() const
{
    return crossSectionArea(nLobes_, dl_, dc_)*h_;
}


Foam::rbd::triMesh Foam::rbd::lobedPellet::buildVolumeTrueMesh() const
{
    return toBodyFrame
    (
        pelletMeshes::lobes
        (
            nLobes_, dl_, h_, faces_, 0.5*dc_,
            pelletMeshes::facets::volumeTrue
        )
    );
}


void Foam::rbd::lobedPellet::write(Ostream& os) const
{
    meshedPellet::write(os);
    os.writeEntry("lobeDiameter", dl_);
    os.writeEntry("height", h_);
    os.writeEntry("lobePitchDiameter", dc_);
}


Foam::autoPtr<Foam::rbd::prismProfile> Foam::rbd::lobedPellet::prism() const
{
    return inBodyFrame
    (
        autoPtr<prismProfile>::New
        (
            prismProfile::onCircle(nLobes_, 0.5*dc_),
            List<scalar>(nLobes_, 0.5*dl_),
            List<vector2D>(), List<scalar>(), 0.5*h_
        )
    );
}


// ************************************************************************* //
