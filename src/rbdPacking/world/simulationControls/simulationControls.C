/*---------------------------------------------------------------------------*\
  rbdPacking: hard-body rigid body dynamics packings for OpenFOAM
\*---------------------------------------------------------------------------*/

#include "simulationControls.H"
#include "dictionaryChecks.H"
#include "lcpSolver.H"
#include "restingContactSolver.H"
#include "IStringStream.H"
#ifdef _OPENMP
#include <omp.h>
#endif

// * * * * * * * * * * * * * * Static Data Members * * * * * * * * * * * * * //

const Foam::wordList Foam::rbd::simulationControls::contactModels
({
    "auto", "exact", "mesh"
});


const Foam::wordList Foam::rbd::simulationControls::restingFrictions
({
    "coupled", "staggered"
});


const Foam::wordList Foam::rbd::simulationControls::knownEntries
({
    "deltaT", "endTime", "gravity", "restingVelocity",
    "slipVelocity", "proximity", "neighbourSkin", "contactTolerance",
    "overlapSlop",
    "restitutionSweeps", "maxSweeps", "collisionTolerance",
    "sleepVelocity", "sleepTime", "wakeVelocity",
    "settleTime", "settleEnergy", "logInterval", "checkpointInterval",
    "writeInterval", "threads",
    "lcpSolver", "restingCompliance", "contactModel", "restingFriction",
    "frictionRounds", "sweepSpeed", "preset"
});


const Foam::wordList Foam::rbd::simulationControls::presets
({
    "fast", "default", "accurate"
});


const Foam::scalar Foam::rbd::simulationControls::maxThresholdVelocity = 1;


const Foam::scalar Foam::rbd::simulationControls::maxWakeVelocity = 100;


// * * * * * * * * * * * * * Static Member Functions * * * * * * * * * * * //

Foam::dictionary Foam::rbd::simulationControls::presetEntries
(
    const word& name
)
{
    // Chosen from the one-knob-at-a-time runs of benchmarks/accuracyVsTime
    // (docs/accuracyVsTime.md): default is the built-in defaults below
    const char* text = "";
    if (name == "fast")
    {
        text =
            "deltaT 0.05; restingVelocity 0.02; proximity 0.2;"
            "contactTolerance 1e-3; lcpSolver blockPivoting;"
            "blockPivotingCoeffs { tolerance 1e-7; } frictionRounds 2;";
    }
    else if (name == "accurate")
    {
        text =
            "deltaT 0.01; restingVelocity 0.005; proximity 0.05;"
            "contactTolerance 1e-5; lcpSolver blockPivoting;"
            "blockPivotingCoeffs { tolerance 1e-11; }";
    }
    IStringStream is(text);
    return dictionary(is);
}


Foam::dictionary Foam::rbd::simulationControls::withPreset
(
    const dictionary& d
)
{
    const word name = getChoiceOrDefault(d, "preset", "default", presets);
    dictionary eff(d);
    for (const entry& e : presetEntries(name))
    {
        const word& key = e.keyword();
        dictionary* given = eff.findDict(key, keyType::LITERAL);
        if (e.isDict() && given)
        {
            // Coefficients: the given ones override, one by one
            for (const entry& c : e.dict())
            {
                if (!given->found(c.keyword(), keyType::LITERAL))
                {
                    given->add(c);
                }
            }
        }
        else if (!eff.found(key, keyType::LITERAL))
        {
            eff.add(e);
        }
    }
    return eff;
}


// * * * * * * * * * * * * * * * * Constructors  * * * * * * * * * * * * * * //

Foam::rbd::simulationControls::simulationControls(const dictionary& given)
:
    simulationControls(withPreset(given), given)
{}


Foam::rbd::simulationControls::simulationControls
(
    const dictionary& d,
    const dictionary& given
)
:
    // Below a microsecond the outer intervals alone stall a run (at 1e-30
    // s, t + deltaT == t: it never ends); above a second the tests of the
    // outer intervals (release, settling, log) all but stop (1e14 s hung
    // a run); above 100 g a typo
    deltaT(getInRangeOrDefault(d, "deltaT", 0.025, 1e-6, 1, "s")),
    endTime(getPositiveOrDefault(d, "endTime", 30, "s")),
    endTimeGiven(d.found("endTime")),
    gravity(getNonNegativeOrDefault(d, "gravity", 9.81, "m/s^2", 1000)),
    restingVelocity(getPositiveOrDefault(d, "restingVelocity", 0.01, "m/s",
        maxThresholdVelocity)),
    slipVelocity(getPositiveOrDefault(d, "slipVelocity", 1e-4, "m/s",
        maxThresholdVelocity)),
    // Below 1e-4 the band (and with it the step near contacts) shrinks
    // to nothing: 1e-6 took 23 million steps for 0.6 s simulated
    proximity(getInRangeOrDefault(d, "proximity", 0.1, 1e-4, 1, "-")),
    neighbourSkin(getInRangeOrDefault(d, "neighbourSkin", 0.5, 0.01, 4,
        "-")),
    contactTolerance(getInRangeOrDefault(d, "contactTolerance", 1e-4,
        1e-9, 0.01, "-")),
    // Not below the touching gap: a contact the collisions leave at the
    // touching gap is not an overlap to correct
    overlapSlop(getInRangeOrDefault(d, "overlapSlop", contactTolerance,
        contactTolerance, 0.01, "-")),
    restitutionSweeps(getLabelOrDefault(d, "restitutionSweeps", 10, 0)),
    maxSweeps(getLabelOrDefault(d, "maxSweeps", 200, 1)),
    threads(getLabelOrDefault(d, "threads", 0, 0, 1024)),
    collisionTolerance(getInRangeOrDefault(d, "collisionTolerance", 1e-3,
        1e-9, 0.1, "-")),
    sleepVelocity(getNonNegativeOrDefault(d, "sleepVelocity", 0.001, "m/s",
        maxThresholdVelocity)),
    sleepTime(getPositiveOrDefault(d, "sleepTime", 0.2, "s")),
    wakeVelocity
    (
        getPositiveOrDefault
        (
            d, "wakeVelocity", max(scalar(0.3), restingVelocity), "m/s",
            maxWakeVelocity
        )
    ),
    settleTime(getPositiveOrDefault(d, "settleTime", 0.5, "s")),
    settleEnergy(getPositiveOrDefault(d, "settleEnergy", 1e-6, "-", 1)),
    logInterval(getPositiveOrDefault(d, "logInterval", 0.1, "s")),
    checkpointInterval
    (
        getNonNegativeOrDefault(d, "checkpointInterval", 300, "s")
    ),
    writeInterval(getNonNegativeOrDefault(d, "writeInterval", 0, "s")),
    restingCompliance(getInRangeOrDefault(d, "restingCompliance", 1e-5, 0,
        0.01, "-")),
    contactModel
    (
        getChoiceOrDefault(d, "contactModel", "auto", contactModels)
    ),
    restingFriction
    (
        getChoiceOrDefault(d, "restingFriction", "coupled", restingFrictions)
    ),
    frictionRounds
    (
        getLabelOrDefault
        (
            d, "frictionRounds", restingContactSolver::defaultFrictionRounds,
            1, 100
        )
    ),
    sweepSpeed(getNonNegativeOrDefault(d, "sweepSpeed", 0, "m/s",
        maxWakeVelocity)),
    preset(d.getOrDefault<word>("preset", "default")),
    dict(d)
{
    // threads 0: all cores (OpenMP's count, which OMP_NUM_THREADS sets;
    // without OpenMP one)
    if (threads == 0)
    {
        #ifdef _OPENMP
        threads = omp_get_max_threads();
        #else
        threads = 1;
        #endif
    }

    wordList known(knownEntries);
    // <name>Coeffs of every LCP solver there is
    known.append(lcpSolver::coeffsNames());
    checkKnownEntries(given, known);

    // Coefficients of a solver that is not selected have no effect: say so
    // (they are not checked, and an edit there would be lost silently)
    {
        const word selected(lcpSolver::selectedType(d));
        for (const word& c : lcpSolver::coeffsNames())
        {
            if (c != selected + "Coeffs" && given.found(c, keyType::LITERAL))
            {
                WarningInFunction
                    << c << " in " << given.name() << " is ignored: "
                    << "lcpSolver is " << selected << endl;
            }
        }
    }

    // The run stops at the end of the outer interval that reaches endTime
    if (deltaT > endTime)
    {
        badEntry
        (
            d, "deltaT", deltaT,
            "a number in [1e-06, endTime (" + Foam::name(endTime) + ")] [s]"
        );
    }
    if (wakeVelocity < restingVelocity)
    {
        badEntry
        (
            d, "wakeVelocity", wakeVelocity,
            "a speed >= restingVelocity (" + Foam::name(restingVelocity)
          + ") [m/s]: a slower approach is a resting contact"
        );
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
    os.writeEntry("preset", preset);
    os.writeEntry("deltaT", deltaT);
    os.writeEntry("endTime", endTime);
    os.writeEntry("gravity", gravity);
    os.writeEntry("restingVelocity", restingVelocity);
    os.writeEntry("slipVelocity", slipVelocity);
    os.writeEntry("proximity", proximity);
    os.writeEntry("neighbourSkin", neighbourSkin);
    os.writeEntry("contactTolerance", contactTolerance);
    os.writeEntry("overlapSlop", overlapSlop);
    os.writeEntry("restitutionSweeps", restitutionSweeps);
    os.writeEntry("maxSweeps", maxSweeps);
    os.writeEntry("threads", threads);
    os.writeEntry("collisionTolerance", collisionTolerance);
    os.writeEntry("sleepVelocity", sleepVelocity);
    os.writeEntry("sleepTime", sleepTime);
    os.writeEntry("wakeVelocity", wakeVelocity);
    os.writeEntry("settleTime", settleTime);
    os.writeEntry("settleEnergy", settleEnergy);
    os.writeEntry("logInterval", logInterval);
    os.writeEntry("checkpointInterval", checkpointInterval);
    os.writeEntry("writeInterval", writeInterval);
    os.writeEntry("restingCompliance", restingCompliance);
    os.writeEntry("contactModel", contactModel);
    os.writeEntry("restingFriction", restingFriction);
    os.writeEntry("frictionRounds", frictionRounds);
    os.writeEntry("sweepSpeed", sweepSpeed);
}


// ************************************************************************* //
