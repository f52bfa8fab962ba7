/*---------------------------------------------------------------------------*\
  rbdPacking: hard-body rigid body dynamics packings for OpenFOAM
\*---------------------------------------------------------------------------*/

#include "tube.H"
#include "dictionaryChecks.H"

// * * * * * * * * * * * * * * * * Constructors  * * * * * * * * * * * * * * //

Foam::rbd::tube::tube(const dictionary& dict)
:
    diameter_(getPositive(dict, "diameter", "m", 100)),
    height_(getPositive(dict, "height", "m", 1000)),
    friction_(getNonNegativeOrDefault(dict, "friction", 0.6, "-")),
    restitution_(getInRangeOrDefault(dict, "restitution", 0.6, 0, 1, "-"))
{
    checkKnownEntries
    (
        dict,
        {"type", "diameter", "height", "friction", "restitution"}
    );
    getChoiceOrDefault(dict, "type", "cylinder", {"cylinder"});
}


Foam::rbd::tube::tube
(
    const scalar diameter,
    const scalar height,
    const scalar friction,
    const scalar restitution
)
:
    diameter_(diameter),
    height_(height),
    friction_(friction),
    restitution_(restitution)
{}


// * * * * * * * * * * * * * * * Member Functions  * * * * * * * * * * * * * //

void Foam::rbd::tube::write(Ostream& os) const
{
    os.writeEntry("type", word("cylinder"));
    os.writeEntry("diameter", diameter_);
    os.writeEntry("height", height_);
    os.writeEntry("friction", friction_);
    os.writeEntry("restitution", restitution_);
}


// ************************************************************************* //
