/*---------------------------------------------------------------------------*\
  rbdPacking: hard-body rigid body dynamics packings for OpenFOAM
\*---------------------------------------------------------------------------*/

#include "packedBed.H"
#include "contactDispatch.H"
#include "dictionaryChecks.H"
#include "bedOutput.H"
#include "correlations.H"
#include "mathematicalConstants.H"
#include "OSspecific.H"
#include "boundBox.H"
#include "checkpoint.H"
#include "HashSet.H"
#include <memory>
#include <unistd.h>
#include <climits>
#include <cstdlib>
#include <csignal>

using Foam::constant::mathematical::pi;

// * * * * * * * * * * * * * * Static Data Members * * * * * * * * * * * * * //

const Foam::scalar Foam::rbd::packedBed::minPelletSize = 1e-5;

const Foam::scalar Foam::rbd::packedBed::maxPelletSize = 10;

const Foam::scalar Foam::rbd::packedBed::minBodyRatio = 0.05;

const Foam::scalar Foam::rbd::packedBed::maxBlockCells = 5e7;

const Foam::scalar Foam::rbd::packedBed::densestPorosity = 0.26;

const Foam::scalar Foam::rbd::packedBed::loosestPorosity = 0.95;

const Foam::scalar Foam::rbd::packedBed::stackedHeightFactor = 2;

const Foam::scalar Foam::rbd::packedBed::sphereCollisionTolerance = 0.1;
const Foam::scalar Foam::rbd::packedBed::sphereNeighbourSkin = 2;

const Foam::scalar Foam::rbd::packedBed::plausiblePelletSize[2] =
    {2e-4, 0.1};

const Foam::scalar Foam::rbd::packedBed::plausibleTubeDiameter[2] =
    {2e-3, 5};

const Foam::Enum<Foam::rbd::packedBed::runStatus>
Foam::rbd::packedBed::runStatusNames
({
    {runStatus::settled, "settled"},
    {runStatus::notSettled, "notSettled"},
    {runStatus::incomplete, "incomplete"},
    {runStatus::stacked, "stacked"},
    {runStatus::interrupted, "interrupted"}
});


namespace
{
    //- The signal (SIGINT, SIGTERM) that asked the run to stop, 0: none.
    //  The handler only sets it; the run stops at the end of the outer
    //  interval it is in, where a checkpoint holds the state bit for bit
    volatile std::sig_atomic_t stopSignal = 0;

    extern "C" void requestStop(int sig)
    {
        stopSignal = sig;
    }

    //- SIGINT and SIGTERM ask the run to stop while it is in scope; the
    //  handlers before it are restored on leaving. SA_RESETHAND: a second
    //  Ctrl-C stops the process at once
    class stopRequests
    {
        struct sigaction oldInt_, oldTerm_;

    public:

        stopRequests()
        {
            stopSignal = 0;
            struct sigaction sa;
            sa.sa_handler = requestStop;
            sigemptyset(&sa.sa_mask);
            sa.sa_flags = SA_RESETHAND;
            ::sigaction(SIGINT, &sa, &oldInt_);
            ::sigaction(SIGTERM, &sa, &oldTerm_);
        }

        ~stopRequests()
        {
            ::sigaction(SIGINT, &oldInt_, nullptr);
            ::sigaction(SIGTERM, &oldTerm_, nullptr);
        }

        stopRequests(const stopRequests&) = delete;
        void operator=(const stopRequests&) = delete;
    };
}


const Foam::wordList Foam::rbd::packedBed::analysisEntries
({
    "porosityHeight", "radialBins", "axialBins"
});


const Foam::scalar Foam::rbd::packedBed::defaultExactRollingFriction = 0.1;


// * * * * * * * * * * * * * * * * Constructors  * * * * * * * * * * * * * * //

Foam::rbd::packedBed::packedBed(const Time& runTime, const dictionary& dict)
:
    runTime_(runTime),
    tube_(checkBlocks(dict).subDict("container")),
    shape_(pelletShape::New(dict.subDict("pellets"))),
    material_
    {
        // Denser than any solid (osmium: 22 590 kg/m^3) is a typo
        getPositive(dict.subDict("pellets"), "density", "kg/m^3", 1e5),
        getNonNegativeOrDefault(dict.subDict("pellets"), "friction", 0.1, "-"),
        getInRangeOrDefault
        (
            dict.subDict("pellets"), "restitution", 0.9, 0, 1, "-"
        ),
        getInRangeOrDefault
        (
            dict.subDict("pellets"), "rollingFriction", 0, 0, 1, "-"
        )
    },
    number_(0),
    fillHeight_(0),
    rotates_(true),
    loading_(),
    controls_(subDictOrEmpty(dict, "simulation")),
    porosityHeight_(-1),
    radialBins_(100),
    axialBins_(100),
    dictName_(dict.name()),
    caseSettings_(),
    world_(),
    packingDict_(dict),
    state_(),
    resumed_(false),
    settled_(false),
    wallTime_(0),
    cpuTime_(0),
    finalOverlap_(0),
    epsEstimate_(0),
    status_(runStatus::notSettled),
    acceptStatus_(false)
{
    const dictionary& containerDict = dict.subDict("container");
    const dictionary& pelletsDict = dict.subDict("pellets");
    const pelletShape& shape = shape_();

    // contactModel exact where the shape has no exact solid (stl)
    if
    (
        controls_.contactModel == "exact"
     && !shape.isSphere()
     && !shape.prism().valid()
    )
    {
        badEntry
        (
            dict.subDict("simulation"), "contactModel", word("exact"),
            "auto or mesh for pellets/shape " + shape.type()
          + " (exact contacts: sphere, cylinder, ring, trilobe, quadrilobe,"
            " cylinderWithHoles)"
        );
    }

    // Rolling resistance by default where the contacts roll without it:
    // the exact round rims and walls of contactModel exact (a cylinder
    // lying on the floor would otherwise roll until it met something;
    // meshes resist by their polygons, spheres roll as in the paper)
    if
    (
        !pelletsDict.found("rollingFriction")
     && contactDispatch::pairModel(shape, controls_.contactModel) == "prism"
    )
    {
        material_.rollingFriction = defaultExactRollingFriction;
    }

    // A pellet of a sensible size first (an STL in the wrong unit would
    // otherwise be told of the tube it needs)
    checkPelletSize(pelletsDict);

    // The tube must take a pellet in any orientation
    const scalar rb = shape.boundingRadius();
    const bool pelletLooksMm = 2*rb > plausiblePelletSize[1];
    const bool tubeLooksMm = tube_.diameter() > plausibleTubeDiameter[1];
    if (tubeLooksMm)
    {
        WarningInFunction
            << "container/diameter " << tube_.diameter() << " m in "
            << containerDict.name() << " is wider than a packed-bed tube ("
            << plausibleTubeDiameter[0] << " to " << plausibleTubeDiameter[1]
            << " m): lengths in packingDict are in metres; if it is in "
            << "millimetres, give " << tube_.diameter()/1000 << endl;
    }
    if (tube_.radius() <= rb)
    {
        // Both entries and their values, and the unit when one of them
        // looks like millimetres
        string hint;
        if (pelletLooksMm && !tubeLooksMm)
        {
            hint =
                "; lengths are in metres: a pellet of "
              + Foam::name(2*rb) + " m looks like millimetres (give "
              + (
                    shape.inputFile().empty()
                  ? "pellets/diameter in m"
                  : "pellets/scale 0.001 for an STL in mm"
                )
              + ")";
        }
        badEntry
        (
            containerDict, "diameter", tube_.diameter(),
            "a diameter above the pellets' bounding diameter "
          + Foam::name(2*rb) + " [m] (pellets/shape " + shape.type()
          + ", pellets/diameter " + Foam::name(shape.diameter()) + " m)"
          + hint
        );
    }

    // ... and be tall enough to release one: more than its bounding
    // diameter (else the default releaseHeight, which the message would
    // name, is below the floor)
    if (tube_.height() <= 2*rb)
    {
        badEntry
        (
            containerDict, "height", tube_.height(),
            "a height above the pellets' bounding diameter "
          + Foam::name(2*rb) + " [m] (pellet shape " + shape.type()
          + "), and enough to hold the bed"
        );
    }

    checkControls();

    const dictionary loadingDict(subDictOrEmpty(dict, "loading"));
    loading_.reset(new loadingScheme(loadingDict, tube_, shape));

    // How many pellets: 'number', or 'fillHeight' with the porosity
    // estimated by Benyahia and O'Neill's correlation for any shape, kept
    // within [densest, loosest]: outside its range (very thin rings, N
    // below 2) the correlation gives porosities near or above 1
    const scalar densest = densestPorosity;
    const scalar loosest = loosestPorosity;
    const scalar R = tube_.radius();
    const scalar N = tube_.diameter()/shape.volumeEquivalentDiameter();
    // In a tube barely wider than a pellet the bed is a single file: one
    // pellet per volume-equivalent diameter of height, porosity
    // 1 - (2/3)/N^2 (the correlation, far outside its range there, gave
    // 0.95 and a 30-sphere column of 0.3 m was estimated at 3.6 m)
    const scalar singleFile = 1 - (2.0/3.0)/sqr(N);
    const scalar epsEstimate = min
    (
        max
        (
            min
            (
                correlations::benyahiaONeill(N, shape.sphericity()),
                singleFile
            ),
            densest
        ),
        loosest
    );
    epsEstimate_ = epsEstimate;
    const bool hasNumber = pelletsDict.found("number");
    const bool hasFill = pelletsDict.found("fillHeight");
    if (loading_->placed())
    {
        // The file's pellets are the bed: 'number', if given, says how
        // many the user expects there
        const placementFile& placement = loading_->placement();
        const string fileText
        (
            "loading/file " + placement.file() + ": "
          + Foam::name(placement.size()) + " pellets"
        );
        if (hasFill)
        {
            badEntry
            (
                pelletsDict, "fillHeight",
                pelletsDict.get<scalar>("fillHeight"),
                "no fillHeight with loading/scheme placement: the bed is "
                "the pellets of " + fileText + " (give 'number "
              + Foam::name(placement.size()) + ";' or nothing)"
            );
        }
        number_ = placement.size();
        if (hasNumber)
        {
            const label n = getPositiveLabel(pelletsDict, "number");
            if (n != number_)
            {
                badEntry
                (
                    pelletsDict, "number", n,
                    "the number of pellets in " + fileText + " (or no "
                    "number: the file's count is used)"
                );
            }
        }
    }
    else if (hasNumber == hasFill)
    {
        FatalIOErrorInFunction(pelletsDict)
            << "Give exactly one of 'number' (pellets [-]) and 'fillHeight' "
            << "(bed height to fill [m]) in " << pelletsDict.name()
            << exit(FatalIOError);
    }
    const scalar release = loading_->releaseHeight() - rb;
    if (loading_->placed())
    {
        // number_: the file's (above)
    }
    else if (hasNumber)
    {
        number_ = getPositiveLabel(pelletsDict, "number");
    }
    else
    {
        fillHeight_ = getPositive(pelletsDict, "fillHeight", "m");
        if (fillHeight_ > release)
        {
            badEntry
            (
                pelletsDict, "fillHeight", fillHeight_,
                "a height below the lowest release point of a pellet, "
              + Foam::name(release) + " m (loading/releaseHeight "
              + Foam::name(loading_->releaseHeight()) + " m less the "
                "bounding radius; container height "
              + Foam::name(tube_.height()) + " m)"
            );
        }
        number_ = max
        (
            label(1),
            label(round(fillHeight_*pi*sqr(R)*(1 - epsEstimate)
           /shape.volume()))
        );
    }

    if (!loading_->placed())
    {
        checkFilling(containerDict, loadingDict, epsEstimate);
    }

    // Safety net that fits the loading (the default 30 s stopped a bed of
    // 1000 spheres in one column with 606 released)
    if (!controls_.endTimeGiven)
    {
        controls_.endTime = endTimeForLoading
        (
            controls_.endTime, number_, loading_->nColumns(),
            loading_->clearance(), controls_.gravity
        );
    }

    // A quiet period longer than the run can never end it (a short run
    // to endTime, to look at or to resume, is allowed: a warning)
    if (controls_.settleTime > controls_.endTime)
    {
        WarningInFunction
            << "simulation/settleTime " << controls_.settleTime
            << " s is longer than endTime " << controls_.endTime << " s"
            << (controls_.endTimeGiven ? "" : " (its default)")
            << ": the run cannot settle and stops at endTime" << endl;
    }

    // Spheres: contacts through the centres, exact and never redundant, so
    // the resting solve stops a slow approach as cheaply as an impulse
    // sweep does: approaches below 0.1 eps_p go to it (500 spheres: 98 %
    // fewer impulses, 17 % less CPU time, the same largest overlap over
    // three seeds; cylinders took twice the time: docs/loadingSpeed.md)
    if
    (
        shape.isSphere()
     && !subDictOrEmpty(dict, "simulation").found("collisionTolerance")
    )
    {
        controls_.collisionTolerance = sphereCollisionTolerance;
    }

    // Exact sphere contacts take no eq 38 with each other and the floor
    // (stepControl): the step is then bounded mostly by the pairs the
    // broad phase has not listed, whose clearance grows with the skin. A
    // skin of 2 r_b instead of 0.5: 21 % fewer steps and 17 % less CPU
    // time on the 500-sphere bed (seeds 1-3), the same largest overlap;
    // 3 r_b lists too many pairs (docs/loadingSpeed.md)
    if
    (
        contactDispatch::pairModel(shape, controls_.contactModel) == "sphere"
     && !subDictOrEmpty(dict, "simulation").found("neighbourSkin")
    )
    {
        controls_.neighbourSkin = sphereNeighbourSkin;
    }

    // Rotation: spheres without friction never pick up spin
    rotates_ = getSwitchOrDefault(pelletsDict, "rotation", true);
    if
    (
        shape.isSphere() && material_.friction == 0 && tube_.friction() == 0
    )
    {
        rotates_ = false;
    }

    // Analysis
    const dictionary analysisDict(subDictOrEmpty(dict, "analysis"));
    checkKnownEntries(analysisDict, analysisEntries);
    if (analysisDict.found("porosityHeight"))
    {
        // The bed lies in the tube
        porosityHeight_ = getPositive
        (
            analysisDict, "porosityHeight", "m", tube_.height()
        );
        // Below a couple of pellets the section holds the floor's layer
        // only (1e-9 m gave a bulk porosity of 1)
        const scalar dpv = shape.volumeEquivalentDiameter();
        if (porosityHeight_ < 2*dpv)
        {
            WarningInFunction
                << "analysis/porosityHeight " << porosityHeight_ << " m is "
                << "below two volume-equivalent diameters (" << 2*dpv
                << " m): bulkPorosity is then that of the floor's layer,"
                << " not of the bed" << endl;
        }
    }
    radialBins_ =
        getLabelOrDefault(analysisDict, "radialBins", 100, 1, 100000);
    axialBins_ =
        getLabelOrDefault(analysisDict, "axialBins", 100, 1, 100000);

    // Case writing: every option now, the bed height after the run. The
    // tube axis is z through the origin, its floor at z = 0.
    caseSettings_.reset
    (
        new bedCaseSettings
        (
            tube_.diameter(),
            shape.volumeEquivalentDiameter(),
            point::zero,
            subDictOrEmpty(dict, "cfdCase")
        )
    );

    checkCfdGrid(dict);
    checkOutputDirectories();

    if (loading_->placed())
    {
        checkPlacement(loadingDict);
    }

    world_.reset
    (
        new world(tube_, shape, material_, rotates_, controls_)
    );
    series_.reset(new fillSeries(runTime_.path(), shape, controls_));
}


// * * * * * * * * * * * * * * * Static Functions  * * * * * * * * * * * * //

Foam::scalar Foam::rbd::packedBed::endTimeForLoading
(
    const scalar endTime,
    const label number,
    const label columns,
    const scalar clearance,
    const scalar g
)
{
    // A column releases its next pellet when the previous one has fallen
    // the clearance from rest: every sqrt(2 clearance/g) s (0.049 s for
    // 10 mm spheres, spacing 1.2)
    if (g <= 0 || columns < 1)
    {
        return endTime;
    }
    const scalar interval = Foam::sqrt(2*clearance/g);
    const scalar loading = std::ceil(scalar(number)/columns)*interval;
    return max(endTime, 2*loading + 10);
}


// * * * * * * * * * * * * * Private Member Functions  * * * * * * * * * * * //

void Foam::rbd::packedBed::releasePellets(const scalar maxWait)
{
    if (loading_->placed())
    {
        // Every pellet at once, at rest, where the file says (checked in
        // the constructor: within the tube, and clear of one another to
        // the touching gap, whose interpenetration is recorded)
        if (state_.released == 0)
        {
            const placementFile& placement = loading_->placement();
            for (label i = 0; i < placement.size(); ++i)
            {
                world_->addBody(placement.x(i), placement.q(i));
            }
            state_.released = placement.size();
            state_.releaseOverlap = max
            (
                state_.releaseOverlap, world_->currentMaxOverlap()
            );
        }
        return;
    }

    const UList<rigidBody>& bodies = world_->bodies();
    const scalar clearance = loading_->clearance();
    const scalar rb = shape_->boundingRadius();
    labelList& lastOfColumn = state_.lastOfColumn;

    // The layers wait for the bed: no release while awakeLimit pellets or
    // more are awake, unless the wait has lasted maxWait (a bed whose
    // pellets keep rocking is fed on a timer rather than stalled)
    const label awakeLimit = loading_->awakeLimit();
    if
    (
        awakeLimit > 0 && controls_.sleepVelocity > 0
     && bodies.size() - world_->nSleeping() >= awakeLimit
     && world_->time() - state_.lastRelease < maxWait
    )
    {
        return;
    }

    // The pellets that can come within the band of a release point: those
    // whose centre is less than 2 r_b + band below the release height
    // (the disturbance is horizontal), found once per call
    const scalar zLow =
        loading_->releaseHeight() - 2*rb - world_->band();
    DynamicList<label> high;
    bool highFound = false;

    for
    (
        label c = 0;
        c < loading_->nColumns() && state_.released < number_;
        ++c
    )
    {
        const point& slot = loading_->column(c);
        if
        (
            lastOfColumn[c] >= 0
         && mag(bodies[lastOfColumn[c]].x() - slot) < clearance
        )
        {
            continue;
        }

        point x;
        quaternion q;
        loading_->nextPose(c, x, q);

        // Nothing may overlap the release point, nor come within the band
        // of it: every pellet that can is tested (those of 'high': a bed
        // that reaches the release height brings old pellets up there),
        // by bounding spheres, so a pellet is never released into another
        if (!highFound)
        {
            forAll(bodies, j)
            {
                if (bodies[j].x().z() > zLow)
                {
                    high.append(j);
                }
            }
            highFound = true;
        }
        scalar gap = GREAT;
        for (const label j : high)
        {
            gap = min(gap, mag(bodies[j].x() - x) - 2*rb);
        }
        if (gap < world_->band())
        {
            continue;
        }

        // The release's clearance of the container (the loading keeps the
        // centre within R - r_b and above r_b): recorded, as the largest
        // interpenetration at release (bounding spheres: for other shapes
        // an upper bound of the true one), for the summary
        gap = min(gap, tube_.radius() - rb - tube::axialDistance(x));
        gap = min(gap, x.z() - rb);
        state_.releaseOverlap = max(state_.releaseOverlap, -gap);

        lastOfColumn[c] = world_->addBody(x, q);
        high.append(lastOfColumn[c]);
        ++state_.released;
    }
}


void Foam::rbd::packedBed::writeCheckpoint
(
    const scalar wallTime,
    const scalar cpuTime
) const
{
    const fileName file(checkpoint::path(runTime_.path()));
    checkpoint::write
    (
        file,
        packingDict_,
        [&](stateWriter& out)
        {
            world_->writeState(out);
            loading_->writeState(out);
            out.putList(state_.lastOfColumn);
            out.put(state_.released).put(state_.quietTime)
               .put(state_.nextLog).put(state_.lastRelease)
               .put(state_.warnedStall).put(state_.wallTime + wallTime)
               .put(state_.cpuTime + cpuTime)
               .put(state_.releaseOverlap);
        }
    );
    Info<< "Checkpoint at t = " << world_->time() << " s ("
        << state_.released << " pellets): "
        << file.relative(runTime_.path()).c_str() << nl << endl;
}


void Foam::rbd::packedBed::resume()
{
    const fileName file(checkpoint::path(runTime_.path()));
    checkpoint::read
    (
        file,
        packingDict_,
        dictName_,
        [&](stateReader& in)
        {
            world_->readState(in);
            loading_->readState(in);
            in.getList(state_.lastOfColumn);
            in.get(state_.released).get(state_.quietTime)
              .get(state_.nextLog).get(state_.lastRelease)
              .get(state_.warnedStall).get(state_.wallTime)
              .get(state_.cpuTime).get(state_.releaseOverlap);
        }
    );

    const label n = world_->bodies().size();
    if
    (
        state_.lastOfColumn.size() != loading_->nColumns()
     || state_.released != n || n > number_
    )
    {
        FatalErrorInFunction
            << "The checkpoint " << file.c_str() << " holds " << n << " pellets, "
            << state_.released << " released from "
            << state_.lastOfColumn.size() << " columns, for a packing of "
            << number_ << " from " << loading_->nColumns()
            << ": it is damaged." << nl
            << "    Delete it and run without -resume." << exit(FatalError);
    }
    for (const label i : state_.lastOfColumn)
    {
        if (i < -1 || i >= n)
        {
            FatalErrorInFunction
                << "The checkpoint " << file.c_str() << " is damaged (a column's "
                << "last pellet " << i << " of " << n << ")." << nl
                << "    Delete it and run without -resume."
                << exit(FatalError);
        }
    }

    // Nothing to go on with: an error, not a run that ends at once "not
    // settled" with exit 0
    if (world_->time() >= controls_.endTime - 1e-12)
    {
        badEntry
        (
            controls_.dict, "endTime", controls_.endTime,
            "a time beyond the checkpoint's, t = "
          + Foam::name(world_->time()) + " s [s], to go on from it"
          + (
                controls_.endTimeGiven
              ? string()
              : string(" (endTime is not given: this is its default)")
            )
        );
    }

    resumed_ = true;
    Info<< "Resuming from " << file.relative(runTime_.path()).c_str() << " at t = "
        << world_->time() << " s: " << n << " of " << number_
        << " pellets released, " << world_->stats().steps << " steps, "
        << state_.wallTime << " s of wall time so far" << nl << endl;
}


const Foam::dictionary& Foam::rbd::packedBed::checkBlocks
(
    const dictionary& dict
)
{
    // A misspelt block (loadng { ... }) would be ignored and its defaults
    // taken silently. Plain entries at the top level stay allowed: they
    // are the variables of $macros.
    {
        const wordList blocks
        ({
            "FoamFile", "container", "pellets", "loading", "simulation",
            "analysis", "cfdCase"
        });
        for (const entry& e : dict)
        {
            if (e.isDict() && !blocks.found(e.keyword()))
            {
                FatalIOErrorInFunction(dict)
                    << "Unknown block '" << e.keyword() << "' in "
                    << dict.name() << nl << "    allowed:";
                for (const word& b : blocks)
                {
                    FatalIOError<< ' ' << b;
                }
                FatalIOError<< exit(FatalIOError);
            }
        }
    }

    // A plain entry at the top level that belongs in a block (endTime 5;
    // outside simulation { }) is read by no one: say so. (Names that are
    // also natural macro variables, diameter or height, are not listed.)
    for (const entry& e : dict)
    {
        if (e.isDict())
        {
            continue;
        }
        for
        (
            const auto& block
          : {
                std::make_pair("simulation", &simulationControls::knownEntries),
                std::make_pair("loading", &loadingScheme::knownEntries),
                std::make_pair("analysis", &analysisEntries),
                std::make_pair("cfdCase", &bedCaseSettings::knownEntries)
            }
        )
        {
            if (block.second->found(e.keyword()))
            {
                WarningInFunction
                    << "'" << e.keyword() << "' at the top level of "
                    << dict.name() << " is not read: it is an entry of "
                    << block.first << " { } (as the variable of a $macro,"
                    << " ignore this)" << endl;
                break;
            }
        }
    }

    // Every entry of a block is a value: a block given where a value is
    // expected (diameter { a 1; }) would stop OpenFOAM's reader with an
    // abort and a stack trace. The settings of the LCP solvers
    // (simulation/<name>Coeffs) are the only blocks within blocks.
    for (const entry& b : dict)
    {
        if (!b.isDict() || b.keyword() == "FoamFile")
        {
            continue;
        }
        for (const entry& e : b.dict())
        {
            const bool coeffs =
                b.keyword() == "simulation" && e.keyword().endsWith("Coeffs");
            if (e.isDict() && !coeffs)
            {
                FatalIOErrorInFunction(b.dict())
                    << "Bad entry '" << e.keyword() << "' in "
                    << b.dict().name() << ": a block { ... } where a value "
                    << "is expected" << nl
                    << "    allowed: a value (number, word, switch or list)"
                    << " as docs/packingDict.md gives it"
                    << exit(FatalIOError);
            }
        }
    }
    return dict;
}


void Foam::rbd::packedBed::checkPelletSize
(
    const dictionary& pelletsDict
) const
{
    const pelletShape& shape = shape_();
    const scalar rb = shape.boundingRadius();

    // Pellets the engine's tolerances are made for (its lengths are
    // relative to the pellet, but round-off is not), and pellets with a
    // body: a wall, a coin, a needle or a sliver much thinner than the
    // pellet is wide has a volume-equivalent diameter dpv far below its
    // size, and the CFD grid (cellsPerDiameter per dpv) would be sized to
    // the sliver (a 1e-9 m high tetrahedron asked for a 1.6 GB tube.stl).
    // A size above the range of catalyst pellets is most often a
    // dictionary (or an STL) in millimetres: it packs, but 3 m spheres of
    // 113 t, for tens of seconds of simulated time
    string hint;
    if (2*rb > plausiblePelletSize[1])
    {
        hint =
            shape.inputFile().empty()
          ? ": if pellets/diameter " + Foam::name(shape.diameter())
          + " is in millimetres, give " + Foam::name(shape.diameter()/1000)
          : ": if the STL " + shape.inputFile().name()
          + " is in millimetres, give pellets/scale 0.001";
    }
    if (!(2*rb >= minPelletSize && 2*rb <= maxPelletSize))
    {
        FatalIOErrorInFunction(pelletsDict)
            << "Bad pellet size in " << pelletsDict.name() << nl
            << "    pellets of shape " << shape.type() << " with a bounding "
            << "diameter of " << 2*rb << " m; allowed: " << minPelletSize
            << " to " << maxPelletSize << " m" << nl
            << "    Lengths in packingDict are in metres" << hint.c_str()
            << nl << exit(FatalIOError);
    }
    if (2*rb < plausiblePelletSize[0] || 2*rb > plausiblePelletSize[1])
    {
        WarningInFunction
            << "Pellets of shape " << shape.type() << " in "
            << pelletsDict.name() << " have a bounding diameter of " << 2*rb
            << " m, outside the range of catalyst pellets ("
            << plausiblePelletSize[0] << " to " << plausiblePelletSize[1]
            << " m)." << nl << "    Lengths in packingDict are in metres"
            << hint.c_str() << endl;
    }

    const scalar dpv = shape.volumeEquivalentDiameter();
    if (!(dpv >= minBodyRatio*2*rb))
    {
        FatalIOErrorInFunction(pelletsDict)
            << "Bad pellet shape in " << pelletsDict.name() << nl
            << "    pellets of shape " << shape.type() << " with a volume-"
            << "equivalent diameter of " << dpv << " m, " << dpv/(2*rb)
            << " of their bounding diameter " << 2*rb << " m: a wall, a "
            << "coin, a needle or a sliver this thin" << nl
            << "    allowed: a volume-equivalent diameter at least "
            << minBodyRatio << " of the bounding diameter" << nl
            << exit(FatalIOError);
    }
}


void Foam::rbd::packedBed::checkControls() const
{
    const pelletShape& shape = shape_();
    const scalar rb = shape.boundingRadius();

    // The overlap correction leaves interpenetrations of overlapSlop dp
    // (at least contactTolerance); the proximity band must hold them with
    // room to spare, or the step that keeps contacts within the band
    // collapses (1e-18 s seen with the tolerance twice the band: a hang,
    // not an error)
    {
        const bool bySlop =
            controls_.overlapSlop > controls_.contactTolerance;
        const word key(bySlop ? "overlapSlop" : "contactTolerance");
        const scalar value =
            bySlop ? controls_.overlapSlop : controls_.contactTolerance;
        const scalar slop = value*shape.diameter();
        const scalar band = controls_.proximity*rb;
        if (slop > 0.25*band)
        {
            badEntry
            (
                controls_.dict, key, value,
                "a tolerance of at most a quarter of the proximity band: "
              + key + " dp <= proximity r_b/4, here <= "
              + Foam::name(0.25*band/shape.diameter()) + " (proximity "
              + Foam::name(controls_.proximity) + ", r_b "
              + Foam::name(rb) + " m, dp " + Foam::name(shape.diameter())
              + " m)"
            );
        }
    }

    // A packing needs gravity (the engine alone may run without: free
    // flight in the tests)
    if (!(controls_.gravity > 0))
    {
        badEntry
        (
            controls_.dict, "gravity", controls_.gravity,
            "a number > 0 [m/s^2] (pellets must fall to pack)"
        );
    }

    // The enumeration solver is a test reference (at most 16 contacts)
    if (lcpSolver::selectedType(controls_.dict) == "enumeration")
    {
        badEntry
        (
            controls_.dict, "lcpSolver", word("enumeration"),
            "blockPivoting | baraff | projectedGaussSeidel (enumeration is "
            "the tests' reference, limited to 16 contacts)"
        );
    }
}


void Foam::rbd::packedBed::checkFilling
(
    const dictionary& containerDict,
    const dictionary& loadingDict,
    const scalar epsEstimate
) const
{
    const pelletShape& shape = shape_();
    const scalar rb = shape.boundingRadius();
    const scalar densest = densestPorosity;
    const scalar release = loading_->releaseHeight() - rb;

    // The pellets must fit below the release points: for certain if they
    // cannot even at the densest porosity, probably if they cannot at the
    // estimate (then the run stops releasing when the bed reaches the
    // release height, and the summary says how many it holds)
    const scalar solidHeight = this->solidHeight(number_);
    if (solidHeight/(1 - densest) > release)
    {
        FatalIOErrorInFunction(containerDict)
            << "Bad entry 'height " << tube_.height() << ";' in "
            << containerDict.name() << nl
            << "    " << number_ << " pellets fill at least "
            << solidHeight/(1 - densest) << " m of this tube (porosity "
            << densest << "), about " << solidHeight/(1 - epsEstimate)
            << " m (porosity " << epsEstimate << " by Benyahia and "
            << "O'Neill); they are released from " << release << " m"
            << nl << "    allowed: a taller container (or releaseHeight), "
            << "or fewer pellets" << nl
            << exit(FatalIOError);
    }
    if (solidHeight/(1 - epsEstimate) > release)
    {
        WarningInFunction
            << number_ << " pellets fill about "
            << solidHeight/(1 - epsEstimate) << " m of this tube (porosity "
            << epsEstimate << " by Benyahia and O'Neill), more than the "
            << release << " m below the release points: the bed may reach "
            << "them first, and the run then stops releasing" << nl << endl;
    }

    // A column releases its next pellet once the last one is the
    // clearance (spacing) away from the release point: a pellet lying on
    // the floor must be that far below it, or a second is never released
    const scalar spacingUnit = max(shape.diameter(), 2*rb);
    if
    (
        number_ > loading_->nColumns()
     && loading_->releaseHeight() - rb < loading_->clearance()
    )
    {
        badEntry
        (
            loadingDict, "spacing", loading_->clearance()/spacingUnit,
            "a spacing the release height allows: a pellet lying on the "
            "floor must be spacing x " + Foam::name(spacingUnit)
          + " m below the release point, here at most "
          + Foam::name((loading_->releaseHeight() - rb)/spacingUnit)
          + " (releaseHeight " + Foam::name(loading_->releaseHeight())
          + " m; or a taller container)"
        );
    }
}


void Foam::rbd::packedBed::checkPlacement
(
    const dictionary& loadingDict
) const
{
    const placementFile& placement = loading_->placement();
    const pelletShape& shape = shape_();

    // A world of the placement alone: its contacts with every body (none
    // asleep) are the narrow phase's exact gaps. Its constructor's echo of
    // the narrow phase is the run's world's to write (once in the log)
    const int infoLevel = messageStream::level;
    messageStream::level = 0;
    world trial(tube_, shape, material_, rotates_, controls_);
    messageStream::level = infoLevel;
    for (label i = 0; i < placement.size(); ++i)
    {
        trial.addBody(placement.x(i), placement.q(i));
    }
    const contact* worst = nullptr;
    for (const contact& c : trial.allContacts())
    {
        if (!worst || c.gap < worst->gap)
        {
            worst = &c;
        }
    }
    const scalar slop = controls_.contactTolerance*shape.diameter();
    if (worst && worst->gap < -slop)
    {
        const auto pelletText = [&](const label i)
        {
            return
                "pellet " + Foam::name(i) + " (line "
              + Foam::name(placement.line(i)) + ")";
        };
        const string other
        (
            worst->k >= 0 ? pelletText(worst->k)
          : worst->k == tubeWall ? string("the tube wall")
          : string("the floor")
        );
        badEntry
        (
            loadingDict, "file", placement.file(),
            "poses of pellets clear of one another, the wall and the floor"
            " (" + placement.path() + ": " + pelletText(worst->i)
          + " overlaps " + other + " by " + Foam::name(-worst->gap)
          + " m, more than the touching gap contactTolerance dp = "
          + Foam::name(slop) + " m; the deepest overlap of the file)"
        );
    }
}


void Foam::rbd::packedBed::checkCfdGrid(const dictionary& dict) const
{
    const scalar dpv = shape_->volumeEquivalentDiameter();

    // The CFD case's background grid for a bed as high as the tube, the
    // most it can be: checked now, not after the packing
    {
        bedCaseSettings tallest(caseSettings_());
        tallest.setBedHeight(tube_.height());
        const labelVector& n = tallest.blockCells();
        const scalar cells = scalar(n.x())*n.y()*n.z();
        if (cells > maxBlockCells)
        {
            FatalIOErrorInFunction(dict)
                << "The CFD case of " << dict.name() << " is too fine: "
                << "a background grid of " << n << " cells (cfdCase/"
                << "cellsPerDiameter " << tallest.cellsPerDiameter()
                << " per volume-equivalent diameter " << dpv << " m, "
                << "a bed up to " << tube_.height() << " m high)" << nl
                << "    allowed: at most " << maxBlockCells << " cells; "
                << (
                       tallest.cellsPerDiameter() > 2
                     ? "lower cellsPerDiameter, or "
                     : ""
                   )
                << "a smaller container/diameter or container/height"
                << " (the grid spans the tube at its full height)" << nl
                << exit(FatalIOError);
        }
    }
}


void Foam::rbd::packedBed::checkOutputDirectories() const
{
    // Checked before the packing, so that an output directory that cannot
    // be written does not stop the run halfway through writing
    const fileName root(runTime_.path());
    if (::access(root.c_str(), W_OK) != 0)
    {
        FatalErrorInFunction
            << "Cannot write into the case directory " << root << nl
            << exit(FatalError);
    }
    // Every file the run writes: the CFD case, the analysis, the
    // checkpoint; the names are their writers'
    fileNameList files(bedCaseWriter::files());
    files.append(bedOutput::files());
    files.append(checkpoint::path(root).relative(root));

    // ... their directories, parents first, are directories and writable
    wordHashSet dirs;
    for (const fileName& f : files)
    {
        for (fileName d = f.path(); !d.empty() && d != "."; d = d.path())
        {
            dirs.insert(d);
        }
    }
    for (const word& dir : dirs.sortedToc())
    {
        const fileName path(root/dir);
        if (Foam::exists(path, false) && !Foam::isDir(path))
        {
            FatalErrorInFunction
                << "Cannot write the outputs: " << path << " is there but"
                << " not a directory" << nl << exit(FatalError);
        }
        if (Foam::isDir(path) && ::access(path.c_str(), W_OK) != 0)
        {
            FatalErrorInFunction
                << "Cannot write the outputs: directory " << path
                << " is not writable" << nl << exit(FatalError);
        }
    }

    // ... no input is one of them (a pellet STL kept as
    // constant/triSurface/pellets.stl, -dict system/controlDict): it would
    // be overwritten
    const auto sameFile = [](const fileName& a, const fileName& b)
    {
        char ra[PATH_MAX], rb[PATH_MAX];
        return
            ::realpath(a.c_str(), ra) && ::realpath(b.c_str(), rb)
         && std::string(ra) == std::string(rb);
    };
    const fileName pelletFile(shape_->inputFile());
    for (const fileName& f : files)
    {
        if (sameFile(dictName_, root/f))
        {
            FatalErrorInFunction
                << "The packing dictionary " << dictName_.c_str()
                << " is the file " << f << " that rbdPackBed writes" << nl
                << "    Give -dict a dictionary of its own" << nl
                << exit(FatalError);
        }
        if (!pelletFile.empty() && sameFile(pelletFile, root/f))
        {
            const dictionary& pellets = packingDict_.subDict("pellets");
            badEntry
            (
                pellets, "file", pellets.get<fileName>("file"),
                "an STL file that rbdPackBed does not write (" + f
              + " is its output): keep the pellet elsewhere, e.g. "
                "constant/pellet.stl"
            );
        }
    }

    // ... and no directory is where a file goes, and no file there is
    // read-only (found after packing, it left a half-written case)
    for (const fileName& f : files)
    {
        if (Foam::isDir(root/f))
        {
            FatalErrorInFunction
                << "Cannot write the outputs: " << root/f << " is a "
                << "directory, where rbdPackBed writes the file " << f << nl
                << "    Remove or rename it" << nl << exit(FatalError);
        }
        if
        (
            Foam::isFile(root/f, false)
         && ::access((root/f).c_str(), W_OK) != 0
        )
        {
            FatalErrorInFunction
                << "Cannot write the outputs: " << root/f << " is not "
                << "writable" << nl << exit(FatalError);
        }
    }
}


Foam::scalar Foam::rbd::packedBed::bedHeight() const
{
    scalar top = 0;
    for (const rigidBody& b : world_->bodies())
    {
        top = max(top, b.x().z() + shape_->boundingRadius());
    }
    return top;
}


Foam::scalar Foam::rbd::packedBed::solidHeight(const label n) const
{
    return n*shape_->volume()/(pi*sqr(tube_.radius()));
}


Foam::rbd::bedCaseWriter::insideFunction
Foam::rbd::packedBed::insidePellet(const scalar scale) const
{
    pointField centres(world_->bodies().size());
    forAll(centres, i)
    {
        centres[i] = world_->bodies()[i].x();
    }
    return insideAnySphere(centres, scale*shape_->boundingRadius());
}


// * * * * * * * * * * * * * Static Member Functions * * * * * * * * * * * * //

Foam::rbd::bedCaseWriter::insideFunction
Foam::rbd::packedBed::insideAnySphere
(
    const UList<point>& centres,
    const scalar r
)
{
    if (centres.empty() || !(r > 0))
    {
        return [](const point&) { return false; };
    }

    // A point can only be inside spheres whose centres lie in its own cell
    // or in one of the 26 around it
    const scalar h = 2*r;
    boundBox bb;
    for (const point& c : centres)
    {
        bb.add(c);
    }
    const point origin = bb.min();
    labelVector n;
    for (direction i = 0; i < 3; ++i)
    {
        n[i] = label(std::floor((bb.max()[i] - origin[i])/h)) + 1;
    }

    const auto cellOf = [origin, h](const point& p, const direction i)
    {
        return label(std::floor((p[i] - origin[i])/h));
    };

    auto cells = std::make_shared<List<DynamicList<point>>>
    (
        n.x()*n.y()*n.z()
    );
    for (const point& c : centres)
    {
        (*cells)[cellOf(c, 0) + n.x()*(cellOf(c, 1) + n.y()*cellOf(c, 2))]
            .append(c);
    }

    return [cells, cellOf, n, r](const point& p)
    {
        const labelVector c(cellOf(p, 0), cellOf(p, 1), cellOf(p, 2));
        const labelVector lo
        (
            max(c.x() - 1, 0), max(c.y() - 1, 0), max(c.z() - 1, 0)
        );
        const labelVector hi
        (
            min(c.x() + 1, n.x() - 1),
            min(c.y() + 1, n.y() - 1),
            min(c.z() + 1, n.z() - 1)
        );
        for (label k = lo.z(); k <= hi.z(); ++k)
        {
            for (label j = lo.y(); j <= hi.y(); ++j)
            {
                for (label i = lo.x(); i <= hi.x(); ++i)
                {
                    for (const point& x : (*cells)[i + n.x()*(j + n.y()*k)])
                    {
                        if (magSqr(p - x) < sqr(r))
                        {
                            return true;
                        }
                    }
                }
            }
        }
        return false;
    };
}


// * * * * * * * * * * * * * * * Member Functions  * * * * * * * * * * * * * //

void Foam::rbd::packedBed::setOverwrite(const bool overwrite)
{
    caseSettings_->setOverwrite(overwrite);
}


void Foam::rbd::packedBed::writeSettings(Ostream& os) const
{
    os  << nl << "Effective settings (defaults included):" << nl;

    os.beginBlock("container");
    tube_.write(os);
    os.endBlock();

    os.beginBlock("pellets");
    shape_->write(os);
    os.writeEntry("number", number_);
    if (fillHeight_ > 0)
    {
        os.writeEntry("fillHeight", fillHeight_);
    }
    os.writeEntry("density", material_.density);
    os.writeEntry("friction", material_.friction);
    os.writeEntry("restitution", material_.restitution);
    os.writeEntry("rollingFriction", material_.rollingFriction);
    os.writeEntry("rotation", Switch(rotates_));
    os.endBlock();

    os.beginBlock("loading");
    loading_->write(os);
    os.endBlock();

    os.beginBlock("simulation");
    controls_.write(os);
    world_->restingSolver().solver().write(os);
    os.endBlock();

    os.beginBlock("analysis");
    if (porosityHeight_ > 0)
    {
        os.writeEntry("porosityHeight", porosityHeight_);
    }
    else
    {
        // A comment: the echo stays a valid dictionary
        os.indent();
        os  << "// porosityHeight: the bed height - 1 dp (default)" << nl;
    }
    os.writeEntry("radialBins", radialBins_);
    os.writeEntry("axialBins", axialBins_);
    os.endBlock();

    os.beginBlock("cfdCase");
    caseSettings_->write(os);
    os.endBlock();

    const pelletShape& shape = shape_();
    os  << nl << "Pellet: volume " << shape.volume() << " m^3, mass "
        << material_.density*shape.volume() << " kg, dpv "
        << shape.volumeEquivalentDiameter() << " m, sphericity "
        << shape.sphericity() << nl
        << "Tube to pellet diameter ratio N = dt/dp = "
        << tube_.diameter()/shape.diameter() << ", Nv = dt/dpv = "
        << tube_.diameter()/shape.volumeEquivalentDiameter() << nl
        << "Proximity band lambda = " << world_->band() << " m" << nl
        << endl;
}


void Foam::rbd::packedBed::run()
{
    clockTime timer;
    cpuTime cpuTimer;
    world& w = world_();
    const simulationControls& ctrl = controls_;
    const pelletShape& shape = shape_();

    const scalar mass = material_.density*shape.volume();
    const scalar Eref = number_*mass*ctrl.gravity*shape.diameter();
    const scalar moving = ctrl.restingVelocity;

    // A release point blocked this long means the bed has reached it: ten
    // times the fall of the clearance from rest (0.5 s for 10 mm spheres
    // at 9.81 m/s^2), at least 2 s
    const scalar stallTime = max
    (
        scalar(2),
        10*Foam::sqrt(2*loading_->clearance()/ctrl.gravity)
    );

    if (!resumed_)
    {
        state_ = runState();
        state_.lastOfColumn.setSize(loading_->nColumns(), -1);

        // A checkpoint of an earlier packing of this case is not this
        // run's: a later -resume must not continue it
        const fileName old(checkpoint::path(runTime_.path()));
        if (isFile(old))
        {
            Foam::rm(old);
            Info<< "Removed " << old.relative(runTime_.path()).c_str()
                << " of an earlier run (this one starts anew)" << nl << endl;
        }
    }
    // No mix of two beds: the files of an earlier one go, or the run stops
    prepareCase();

    runState& st = state_;
    settled_ = false;
    bool interrupted = false;

    // Ctrl-C (SIGINT) and SIGTERM stop the run at the end of the outer
    // interval they fall in, with a checkpoint to resume from
    const stopRequests stopOnSignal;

    // Checkpoints by the wall time of this run: they do not change the
    // state, so where they fall does not change the packing
    const scalar checkpointInterval = ctrl.checkpointInterval;
    scalar nextCheckpoint = checkpointInterval;

    Info<< "Packing " << number_ << ' ' << shape.type() << " pellets" << nl
        << endl;

    // Tested at the ends of outer intervals only (below)
    bool goOn = w.time() < ctrl.endTime - 1e-12;
    while (goOn)
    {
        const label before = st.released;
        releasePellets(0.5*stallTime);
        if (st.released > before)
        {
            st.lastRelease = w.time();
        }

        // The run stops at the end of the outer interval that reaches
        // endTime, never within one: a stop (and a checkpoint) is then a
        // state the run that goes on passes through too (a step cut at
        // an endTime of 0.7 s, which is 0.7000000000000001 s on the grid
        // of 0.025 s, or a stop within the interval at 0.71 s, made the
        // resumed run another one)
        const scalar tOuter =
            ctrl.deltaT*(std::floor(w.time()/ctrl.deltaT + 1e-9) + 1);
        w.step(tOuter - w.time());

        if (w.time() < tOuter - 1e-12)
        {
            continue;
        }

        // Outer interval: termination test and progress
        const scalar KE = w.kineticEnergy();
        if
        (
            st.released < number_ && !st.warnedStall
         && w.time() - st.lastRelease > stallTime
        )
        {
            WarningInFunction
                << "No pellet could be released for " << stallTime
                << " s: the bed has reached the release height with "
                << st.released << " of " << number_ << " pellets" << endl;
            st.warnedStall = true;
        }
        // The kinetic-energy test once every pellet is in, or once no more
        // can be released (the bed settles with fewer pellets)
        if (st.released == number_ || st.warnedStall)
        {
            st.quietTime =
                (KE <= ctrl.settleEnergy*Eref) ? st.quietTime + ctrl.deltaT
                                               : 0;
            if (st.quietTime >= ctrl.settleTime - 1e-12)
            {
                settled_ = true;
            }
        }

        if (w.time() >= st.nextLog - 1e-12 || settled_)
        {
            Info<< "Time = " << w.time() << " s  pellets " << st.released
                << '/' << number_ << "  moving " << w.nMoving(moving)
                << "  sleeping " << w.nSleeping()
                << "  KE = " << KE << " J  steps " << w.stats().steps
                << "  maxOverlap " << w.stats().maxOverlap << " m"
                << "  lcpFailures " << w.stats().lcpFailures
                << "  ExecutionTime = "
                << st.wallTime + timer.elapsedTime() << " s"
                << endl;
            st.nextLog += ctrl.logInterval;
        }

        goOn = !settled_ && w.time() < ctrl.endTime - 1e-12;

        if (goOn && stopSignal)
        {
            Info<< nl << "Stopping on signal " << int(stopSignal)
                << (stopSignal == SIGINT ? " (SIGINT, Ctrl-C)" : "")
                << " at t = " << w.time() << " s" << endl;
            interrupted = true;
            goOn = false;
        }

        // A frame of the fill every writeInterval, and the last state
        if (series_.valid())
        {
            series_->write(w, !goOn);
        }

        if
        (
            goOn && checkpointInterval > 0
         && timer.elapsedTime() >= nextCheckpoint
        )
        {
            writeCheckpoint(timer.elapsedTime(), cpuTimer.elapsedCpuTime());
            nextCheckpoint = timer.elapsedTime() + checkpointInterval;
        }
    }

    // Stopped by endTime: the run can go on from here with a larger one;
    // stopped by a signal: always, whatever checkpointInterval says
    if (!settled_ && (checkpointInterval > 0 || interrupted))
    {
        writeCheckpoint(timer.elapsedTime(), cpuTimer.elapsedCpuTime());
    }

    wallTime_ = st.wallTime + timer.elapsedTime();
    cpuTime_ = st.cpuTime + cpuTimer.elapsedCpuTime();

    // Also leaves the final contact list, sleeping pellets included, in
    // w.contacts() for the contact treatments of the CFD case
    finalOverlap_ = w.currentMaxOverlap();

    // How the run ended
    if (interrupted)
    {
        status_ = runStatus::interrupted;
    }
    else if (!settled_)
    {
        status_ = runStatus::notSettled;
    }
    else
    {
        // A tower: the bed stands far higher than its pellets fill the
        // tube at the expected porosity (pellets released exactly on the
        // axis land on one another and stay there)
        const scalar filled =
            solidHeight(w.bodies().size())/(1 - epsEstimate_);
        if
        (
            bedHeight()
          > stackedHeightFactor*filled + 2*shape.diameter()
        )
        {
            status_ = runStatus::stacked;
        }
        else if (st.released < number_)
        {
            status_ = runStatus::incomplete;
        }
        else
        {
            status_ = runStatus::settled;
        }
    }

    Info<< nl;
    if (settled_)
    {
        Info<< "Settled: kinetic energy below " << ctrl.settleEnergy
            << " n m g dp for " << ctrl.settleTime << " s";
        if (st.released < number_)
        {
            Info<< ", with " << st.released << " of " << number_
                << " pellets "
                << "(the bed reached the release height)";
        }
        Info<< nl;
    }
    else if (!interrupted)
    {
        WarningInFunction
            << "Not settled by endTime " << ctrl.endTime << " s (kinetic "
            << "energy " << w.kineticEnergy() << " J)" << endl;
    }

    // The tube is open at the top: a pellet thrown out (restitution 1
    // and no friction pass energy up a column) is not lost, but the bed
    // and the CFD case then reach above the container
    {
        const scalar rb = shape_->boundingRadius();
        label above = 0;
        for (const rigidBody& b : w.bodies())
        {
            above += (b.x().z() - rb > tube_.height());
        }
        if (above)
        {
            WarningInFunction
                << above << " pellet(s) end wholly above the top of the "
                << "container (height " << tube_.height() << " m; the "
                << "highest at z = " << bedHeight() << " m): the bed and "
                << "the CFD case reach above it" << endl;
        }
    }

    const world::statistics& s = w.stats();
    Info<< "Simulated " << w.time() << " s in " << s.steps << " steps ("
        << "smallest " << s.minStep << " s), " << s.collisions
        << " collisions (" << s.impulses << " impulses in "
        << s.collisionSweeps << " sweeps), " << s.restingSolves
        << " resting-contact solves "
        << "(" << s.lcpIterations << " LCP iterations, largest island "
        << s.largestIsland << " contacts, "
        << s.lcpFailures << " not converged), " << s.projections
        << " overlap corrections, " << w.broadPhaseBuilds()
        << " neighbour-list updates (" << w.broadPhaseRelisted()
        << " pellets re-listed), " << s.sweptSteps << " swept pellet steps ("
        << s.sweepStops << " stopped at a touch)" << nl
        << "Wall time " << wallTime_ << " s (CPU " << cpuTime_ << " s)"
        << nl << endl;
}


void Foam::rbd::packedBed::write() const
{
    // An interrupted packing is not a bed: its checkpoint is its output
    if (status_ == runStatus::interrupted)
    {
        return;
    }
    // The surface and the CFD case only for a packed bed (or one the
    // user accepts); the report in postProcessing/rbdPackBed always
    const bool writeCase = status_ == runStatus::settled || acceptStatus_;

    const world& w = world_();
    const pelletShape& shape = shape_();
    // Default: below the loose top layer; a bed only about one pellet
    // high has no such part, and is analysed whole
    scalar H =
        porosityHeight_ > 0 ? porosityHeight_ : bedHeight() - shape.diameter();
    if (porosityHeight_ <= 0 && H <= 0.5*bedHeight())
    {
        H = bedHeight();
        Info<< "The bed is " << bedHeight() << " m high, not much more than "
            << "one pellet: porosity analysed up to its top, " << H << " m"
            << nl << endl;
    }

    bedCaseSettings caseSettings(caseSettings_());
    caseSettings.setBedHeight(bedHeight());

    // A case sized to the bed: the background grid's cells, and a warning
    // where the empty tube around the bed is longer than the bed and
    // than ten pellet diameters (a pressure-drop case needs a few)
    if (writeCase)
    {
        const labelVector& n = caseSettings.blockCells();
        const scalar dpCase = caseSettings.pelletDiameter();
        const scalar empty =
            caseSettings.inletLength() + caseSettings.outletLength();
        Info<< "CFD background mesh: " << n.x() << " x " << n.y() << " x "
            << n.z() << " = " << scalar(n.x())*n.y()*n.z() << " cells ("
            << "bed " << bedHeight() << " m, empty tube " << empty
            << " m = " << empty/dpCase << " dp)" << nl << endl;
        if (empty > max(bedHeight(), 10*dpCase))
        {
            WarningInFunction
                << "The CFD case is mostly empty tube: cfdCase/inletLength "
                << caseSettings.inletLength() << " m and outletLength "
                << caseSettings.outletLength() << " m ("
                << empty/dpCase << " dp) around a bed of " << bedHeight()
                << " m; a few pellet diameters are enough (the defaults are"
                << " 2 and 3 dp): shorten inletLength and outletLength in "
                << fileName(dictName_ + ".cfdCase") << endl;
        }
    }

    // The one check of the CFD case that needs the bed, made before
    // anything is written; its point is the one the case writer uses
    const bedCaseWriter::insideFunction inside
    (
        insidePellet(caseSettings.pelletScale())
    );
    point location;
    if
    (
        writeCase
     && !bedCaseWriter::findLocationInMesh(caseSettings, inside, location)
    )
    {
        FatalErrorInFunction
            << "Bad entry 'cellsPerDiameter "
            << caseSettings.cellsPerDiameter() << ";' in "
            << fileName(dictName_ + ".cfdCase") << nl
            << "    no point of the background grid is in the fluid for "
            << "snappyHexMesh's locationInMesh (every cell is within one "
            << "cell of a pellet or two of the tube wall); allowed: a "
            << "finer grid, more cells per diameter. Nothing written."
            << nl << exit(FatalError);
    }

    bedOutput out(runTime_.path(), tube_, shape, w.bodies());
    out.writePellets();
    const dictionary analysis
    (
        out.writeProfiles(H, radialBins_, axialBins_)
    );
    const scalar eps = analysis.get<scalar>("bulkPorosity");
    // Pellet surfaces (volume-true) with the contact treatment at the
    // simulation's own touching contacts, and the porosity they hold
    label nTreated = 0;
    scalar stlEps = -1;
    if (writeCase)
    {
        const List<triMesh> surfaces
        (
            out.pelletSurfaces(caseSettings, w.contacts(), nTreated)
        );
        out.writeSTL(surfaces, caseSettings.binarySTL());
        stlEps = out.surfacePorosity(surfaces, H);
    }

    dictionary summary;
    summary.add("pellets", w.bodies().size());
    // Asked for: more than 'pellets' when the bed reached the release
    // height first
    summary.add("requestedPellets", number_);
    summary.add("shape", shape.type());
    summary.add("tubeDiameter", tube_.diameter());
    summary.add("pelletDiameter", shape.diameter());
    summary.add("volumeEquivalentDiameter", shape.volumeEquivalentDiameter());
    summary.add("diameterRatio", tube_.diameter()/shape.diameter());
    summary.add
    (
        "volumeEquivalentDiameterRatio",
        tube_.diameter()/shape.volumeEquivalentDiameter()
    );
    summary.add("bulkPorosity", eps);
    if (writeCase)
    {
        summary.add("stlPorosity", stlEps);
    }
    summary.add("porosityHeight", H);
    // The published bulk porosities for this shape at N = dt/dpv
    {
        dictionary correlationsDict;
        for
        (
            const Tuple2<word, scalar>& c
          : correlations::bulkPorosities
            (
                correlations::familyOf(shape.type()),
                tube_.diameter()/shape.volumeEquivalentDiameter(),
                shape.sphericity()
            )
        )
        {
            correlationsDict.add(c.first(), c.second());
        }
        summary.add("bulkPorosityCorrelations", correlationsDict);
    }
    // R^2 and RMSE of the radial profile against the correlations
    if (analysis.found("radialCorrelations"))
    {
        summary.add
        (
            "radialCorrelations", analysis.subDict("radialCorrelations")
        );
    }
    summary.add("bedHeight", bedHeight());
    // Porosity of the whole bed, floor to top: every pellet lies in it
    summary.add
    (
        "bedPorosity",
        1 - w.bodies().size()*shape.exactVolume()
       /(pi*sqr(tube_.radius())*bedHeight())
    );
    summary.add("maxOverlap", w.stats().maxOverlap);
    summary.add("finalMaxOverlap", finalOverlap_);
    summary.add("releaseOverlap", state_.releaseOverlap);
    summary.add("loadingScheme", loading_->scheme());
    summary.add("simulatedTime", w.time());
    summary.add("wallTime", wallTime_);
    summary.add("cpuTime", cpuTime_);
    summary.add("steps", w.stats().steps);
    summary.add("collisions", w.stats().collisions);
    summary.add("lcpFailures", w.stats().lcpFailures);
    summary.add("kineticEnergy", w.kineticEnergy());
    summary.add("settled", Switch(settled_));
    summary.add("status", runStatusNames[status_]);
    summary.add("contactTreatment", caseSettings.contactTreatment());
    if (nTreated)
    {
        summary.add("treatedContacts", nTreated);
    }
    // Axis orientation of cylinders, rings, lobes, ... (orientation.dat)
    out.writeOrientation(H, 18, summary);
    out.writeSummary(summary);

    Info<< "Bulk porosity below " << H << " m: " << eps << nl;
    if (writeCase)
    {
        Info<< "Porosity of pellets.stl below " << H << " m: " << stlEps
            << " (volume-true facets";
        if (caseSettings.contactTreatment() != "none")
        {
            Info<< ", " << caseSettings.contactTreatment();
        }
        Info<< ")" << nl;
    }
    Info<< "Largest interpenetration during the run: "
        << w.stats().maxOverlap << " m ("
        << 100*w.stats().maxOverlap/shape.diameter() << " % of dp)" << nl
        << "Wrote " << out.directory();
    if (writeCase)
    {
        Info<< " and " << out.stlFile();
    }
    if (nTreated)
    {
        Info<< " (" << caseSettings.contactTreatment() << " at " << nTreated
            << " contacts)";
    }
    Info<< nl << endl;
    if (summary.found("meanAxisAngle"))
    {
        Info<< "Pellet axis to tube axis: mean "
            << summary.get<scalar>("meanAxisAngle") << " deg, order "
            << "parameter " << summary.get<scalar>("axisOrderParameter")
            << nl << endl;
    }

    if (!writeCase)
    {
        return;
    }

    // The CFD case around the bed
    const bedCaseWriter writer(runTime_.path(), caseSettings, inside);
    const fileNameList kept = writer.write(location);

    Info<< "CFD case (simpleFoam, laminar):" << nl;
    caseSettings.write(Info);
    Info<< "Wrote " << bedCaseWriter::files().size() - kept.size()
        << " case files";
    if (kept.size())
    {
        Info<< ", kept " << kept.size() << " the case already had"
            << " (rbdPackBed -overwrite to replace them)";
    }
    Info<< nl << endl;

    // A settled packing is done: nothing to resume
    const fileName checkpointFile(checkpoint::path(runTime_.path()));
    if (settled_ && isFile(checkpointFile))
    {
        Foam::rm(checkpointFile);
        Info<< "Removed " << checkpointFile.relative(runTime_.path()).c_str()
            << " (the packing has settled)" << nl << endl;
    }
}


void Foam::rbd::packedBed::setAcceptStatus(const bool accept)
{
    acceptStatus_ = accept;
}


void Foam::rbd::packedBed::prepareCase() const
{
    const fileName root(runTime_.path());

    // Files made for or from an earlier bed: pellets.stl, the CFD case
    // rbdPackBed writes, and what the CFD tools made of them
    DynamicList<fileName> earlier;
    const auto found = [&](const fileName& relative)
    {
        if (Foam::exists(root/relative, false))
        {
            earlier.append(relative);
        }
    };
    found(bedOutput::stlName);
    for (const fileName& f : bedCaseWriter::files())
    {
        found(f);
    }
    found("constant/polyMesh");
    found("constant/extendedFeatureEdgeMesh");
    for (const fileName& f : readDir(root/"constant/triSurface"))
    {
        if (f.hasExt("eMesh"))
        {
            found("constant/triSurface"/f);
        }
    }
    for (const fileName& d : readDir(root, fileName::DIRECTORY))
    {
        scalar t;
        if
        (
            d.starts_with("processor")
         || (d != "0" && Foam::readScalar(d, t))
        )
        {
            found(d);
        }
    }
    for
    (
        const fileName& d
      : readDir(root/"postProcessing", fileName::DIRECTORY)
    )
    {
        if (d != bedOutput::directoryName.name())
        {
            found("postProcessing"/d);
        }
    }

    if (earlier.size() && !caseSettings_->overwrite())
    {
        FatalErrorInFunction
            << "The case " << root << " holds files of an earlier bed:"
            << nl << "   ";
        for (const fileName& f : earlier)
        {
            FatalError<< ' ' << f.c_str();
        }
        FatalError
            << nl << "    A new bed with them would mix two beds (the mesh"
            << " and snappyHexMeshDict of the old one around the new"
            << " pellets)." << nl
            << "    Run rbdPackBed -overwrite to remove them and write the "
            << "whole case anew (or cfdCase/overwrite true), or use "
            << "another case directory. Nothing written." << nl
            << exit(FatalError);
    }
    for (const fileName& f : earlier)
    {
        if (Foam::isDir(root/f))
        {
            Foam::rmDir(root/f);
        }
        else
        {
            Foam::rm(root/f);
        }
    }
    if (earlier.size())
    {
        Info<< "Removed " << earlier.size() << " files and directories of "
            << "an earlier bed (overwrite):";
        for (const fileName& f : earlier)
        {
            Info<< ' ' << f.c_str();
        }
        Info<< nl << endl;
    }

    // The run's own report of an earlier run: replaced as a whole (an
    // orientation.dat of another shape must not stay beside it)
    for (const fileName& f : bedOutput::files())
    {
        if (f != bedOutput::stlName && isFile(root/f))
        {
            Foam::rm(root/f);
        }
    }
}


bool Foam::rbd::packedBed::reportOutcome
(
    Ostream& os,
    const string& resumeCommand
) const
{
    const world& w = world_();
    const word status(runStatusNames[status_]);
    const fileName summary
    (
        (bedOutput::directoryName/bedOutput::summaryName).c_str()
    );

    if (status_ == runStatus::settled)
    {
        os  << "Status: settled (" << w.bodies().size() << " pellets)" << nl
            << endl;
        return true;
    }

    os  << nl << "Status: " << status << nl << "    ";
    switch (status_)
    {
        case runStatus::interrupted:
            os  << "The run was stopped at t = " << w.time() << " s by a "
                << "signal. Its state is in "
                << checkpoint::path(runTime_.path()).relative
                   (
                       runTime_.path()
                   ).c_str()
                << "; continue it with" << nl << "        "
                << resumeCommand.c_str() << nl;
            break;
        case runStatus::notSettled:
            os  << "The bed had not settled by simulation/endTime "
                << controls_.endTime << " s (kinetic energy "
                << w.kineticEnergy() << " J; released " << state_.released
                << " of " << number_ << " pellets)." << nl
                << "    Continue it with a larger simulation/endTime:"
                << nl << "        " << resumeCommand.c_str() << nl
                << "    and check the warnings above (lengths in metres?)"
                << nl;
            break;
        case runStatus::incomplete:
            os  << "Only " << state_.released << " of " << number_
                << " pellets were placed: the bed reached the release "
                << "height " << loading_->releaseHeight() << " m." << nl
                << "    Ask for fewer pellets (pellets/number or fillHeight)"
                << " or give a taller container/height (or a higher "
                << "loading/releaseHeight)" << nl;
            break;
        case runStatus::stacked:
            os  << "The pellets stacked into a tower, not a random bed: "
                << w.bodies().size() << " pellets stand " << bedHeight()
                << " m high, where they fill about "
                << solidHeight(w.bodies().size())/(1 - epsEstimate_)
                << " m of the tube." << nl
                << "    Release them off the axis: loading/"
                << "positionDisturbance (default 0.3 dp; the paper uses up "
                << "to 0.8 dp)" << nl;
            break;
        default:
            break;
    }
    if (status_ != runStatus::interrupted)
    {
        os  << "    The report is in " << summary.path().c_str() << " ("
            << summary.name() << " status " << status << ')' << nl;
    }
    if (acceptStatus_ && status_ != runStatus::interrupted)
    {
        os  << "    Accepted (-acceptStatus): pellets.stl and the CFD case"
            << " are written for this bed" << nl << endl;
        return true;
    }
    os  << "    No pellets.stl and no CFD case written"
        << (
               status_ == runStatus::interrupted
             ? ""
             : " (rbdPackBed -acceptStatus writes them for this bed)"
           )
        << nl << endl;
    return false;
}


// ************************************************************************* //
