/*---------------------------------------------------------------------------*\
  rbdPacking: hard-body rigid body dynamics packings for OpenFOAM
\*---------------------------------------------------------------------------*/

#include "simulationControls.H"
#include "dictionaryChecks.H"
#include "lcpSolver.H"

// * * * * * * * * * * * * * * Static Data Members * * * * * * * * * * * * * //

const Foam::wordList Foam::rbd::simulationControls::contactModels
({
    "auto", "mesh"
});


// * * * * * * * * * * * * * * * * Constructors  * * * * * * * * * * * * * * //

Foam::rbd::simulationControls::simulationControls(const dictionary& d)
:
    deltaT(getPositiveOrDefault(d, "deltaT", 0.025, "s")),
    endTime(getPositiveOrDefault(d, "endTime", 30, "s")),
    gravity(getNonNegativeOrDefault(d, "gravity", 9.81, "m/s^2")),
    restingVelocity(getPositiveOrDefault(d, "restingVelocity", 0.01, "m/s")),
    slipVelocity(getPositiveOrDefault(d, "slipVelocity", 1e-4, "m/s")),
    proximity(getPositiveOrDefault(d, "proximity", 0.1, "-")),
    neighbourSkin(getInRangeOrDefault(d, "neighbourSkin", 0.5, 0.01, 4,
        "-")),
    contactTolerance(getInRangeOrDefault(d, "contactTolerance", 1e-4,
        1e-9, 0.01, "-")),
    restitutionSweeps(getLabelOrDefault(d, "restitutionSweeps", 10, 0)),
    maxSweeps(getLabelOrDefault(d, "maxSweeps", 200, 1)),
    sleepVelocity(getNonNegativeOrDefault(d, "sleepVelocity", 0, "m/s")),
    sleepTime(getPositiveOrDefault(d, "sleepTime", 0.2, "s")),
    settleTime(getPositiveOrDefault(d, "settleTime", 0.5, "s")),
    settleEnergy(getPositiveOrDefault(d, "settleEnergy", 1e-6, "-")),
    logInterval(getPositiveOrDefault(d, "logInterval", 0.1, "s")),
    contactModel
    (
        getChoiceOrDefault(d, "contactModel", "auto", contactModels)
    ),
    dict(d)
{
    wordList known
    {
        "deltaT", "endTime", "gravity", "restingVelocity",
        "slipVelocity", "proximity", "neighbourSkin", "contactTolerance",
        "restitutionSweeps", "maxSweeps", "sleepVelocity", "sleepTime",
        "settleTime", "settleEnergy", "logInterval", "lcpSolver",
        "contactModel"
    };
    // <name>Coeffs of every LCP solver there is
    known.append(lcpSolver::coeffsNames());
    checkKnownEntries(d, known);

    if (proximity > 1)
    {
        badEntry(d, "proximity", proximity, "a number in (0, 1] [-]");
    }
    if (restitutionSweeps > maxSweeps)
    {
        badEntry
        (
            d, "restitutionSweeps", restitutionSweeps,
            "a whole number <= maxSweeps (" + Foam::name(maxSweeps) + ")"
        );
    }
}


// * * * * * * * * * * * * * * * Member Functions  * * * * * * * * * * * * * //

void Foam::rbd::simulationControls::write(Ostream& os) const
{
    os.writeEntry("deltaT", deltaT);
    os.writeEntry("endTime", endTime);
    os.writeEntry("gravity", gravity);
    os.writeEntry("restingVelocity", restingVelocity);
    os.writeEntry("slipVelocity", slipVelocity);
    os.writeEntry("proximity", proximity);
    os.writeEntry("neighbourSkin", neighbourSkin);
    os.writeEntry("contactTolerance", contactTolerance);
    os.writeEntry("restitutionSweeps", restitutionSweeps);
    os.writeEntry("maxSweeps", maxSweeps);
    os.writeEntry("sleepVelocity", sleepVelocity);
    os.writeEntry("sleepTime", sleepTime);
    os.writeEntry("settleTime", settleTime);
    os.writeEntry("settleEnergy", settleEnergy);
    os.writeEntry("logInterval", logInterval);
    os.writeEntry("contactModel", contactModel);
}


// ************************************************************************* //
