/*---------------------------------------------------------------------------*\
  rbdPacking: hard-body rigid body dynamics packings for OpenFOAM
\*---------------------------------------------------------------------------*/

#include "packedBed.H"
#include "dictionaryChecks.H"
#include "bedOutput.H"
#include "correlations.H"
#include "mathematicalConstants.H"
#include "OSspecific.H"
#include "boundBox.H"
#include <memory>

using Foam::constant::mathematical::pi;

// * * * * * * * * * * * * * * * * Constructors  * * * * * * * * * * * * * * //

Foam::rbd::packedBed::packedBed(const Time& runTime, const dictionary& dict)
:
    runTime_(runTime),
    tube_(dict.subDict("container")),
    shape_(pelletShape::New(dict.subDict("pellets"))),
    material_
    {
        getPositive(dict.subDict("pellets"), "density", "kg/m^3"),
        getNonNegativeOrDefault(dict.subDict("pellets"), "friction", 0.1, "-"),
        getInRangeOrDefault
        (
            dict.subDict("pellets"), "restitution", 0.9, 0, 1, "-"
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
    caseSettings_(),
    world_(),
    settled_(false),
    wallTime_(0),
    finalOverlap_(0)
{
    const dictionary& containerDict = dict.subDict("container");
    const dictionary& pelletsDict = dict.subDict("pellets");
    const pelletShape& shape = shape_();

    // The tube must take a pellet in any orientation
    const scalar rb = shape.boundingRadius();
    if (tube_.radius() <= rb)
    {
        badEntry
        (
            containerDict, "diameter", tube_.diameter(),
            "a diameter above the pellets' bounding diameter "
          + Foam::name(2*rb) + " [m] (pellet shape " + shape.type()
          + ", diameter " + Foam::name(shape.diameter()) + ")"
        );
    }

    loading_.reset
    (
        new loadingScheme(subDictOrEmpty(dict, "loading"), tube_, shape)
    );

    // How many pellets: 'number', or 'fillHeight' with the porosity
    // estimated by Benyahia and O'Neill's correlation for any shape
    const scalar R = tube_.radius();
    const scalar N = tube_.diameter()/shape.volumeEquivalentDiameter();
    const scalar epsEstimate =
        correlations::benyahiaONeill(N, shape.sphericity());
    const bool hasNumber = pelletsDict.found("number");
    const bool hasFill = pelletsDict.found("fillHeight");
    if (hasNumber == hasFill)
    {
        FatalIOErrorInFunction(pelletsDict)
            << "Give exactly one of 'number' (pellets [-]) and 'fillHeight' "
            << "(bed height to fill [m]) in " << pelletsDict.name()
            << exit(FatalIOError);
    }
    if (hasNumber)
    {
        number_ = getPositiveLabel(pelletsDict, "number");
    }
    else
    {
        fillHeight_ = getPositive(pelletsDict, "fillHeight", "m");
        number_ = max
        (
            label(1),
            label(round(fillHeight_*pi*sqr(R)*(1 - epsEstimate)
           /shape.volume()))
        );
    }

    // The pellets must fit below the release height
    const scalar heightEstimate =
        number_*shape.volume()/((1 - epsEstimate)*pi*sqr(R));
    if (heightEstimate > tube_.height())
    {
        FatalIOErrorInFunction(containerDict)
            << "Bad entry 'height " << tube_.height() << ";' in "
            << containerDict.name() << nl
            << "    " << number_ << " pellets fill about " << heightEstimate
            << " m of this tube (porosity " << epsEstimate
            << " by Benyahia and O'Neill); allowed: a height above that, "
            << "or fewer pellets" << nl
            << exit(FatalIOError);
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

    // Rotation: spheres without friction never pick up spin
    rotates_ = pelletsDict.getOrDefault<bool>("rotation", true);
    if
    (
        shape.isSphere() && material_.friction == 0 && tube_.friction() == 0
    )
    {
        rotates_ = false;
    }

    // Analysis
    const dictionary analysisDict(subDictOrEmpty(dict, "analysis"));
    checkKnownEntries
    (
        analysisDict, {"porosityHeight", "radialBins", "axialBins"}
    );
    if (analysisDict.found("porosityHeight"))
    {
        porosityHeight_ = getPositive(analysisDict, "porosityHeight", "m");
    }
    radialBins_ = getLabelOrDefault(analysisDict, "radialBins", 100, 1);
    axialBins_ = getLabelOrDefault(analysisDict, "axialBins", 100, 1);

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

    world_.reset
    (
        new world(tube_, shape, material_, rotates_, controls_)
    );
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

Foam::label Foam::rbd::packedBed::releasePellets
(
    labelList& lastOfColumn,
    label released
)
{
    const UList<rigidBody>& bodies = world_->bodies();
    const scalar clearance = loading_->clearance();
    const scalar rb = shape_->boundingRadius();

    for (label c = 0; c < loading_->nColumns() && released < number_; ++c)
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

        // Nothing else may overlap the release point: the recent pellets
        // are the only ones up there
        bool free = true;
        const label first = max(0, bodies.size() - 8*loading_->nColumns());
        for (label i = first; i < bodies.size(); ++i)
        {
            if (mag(bodies[i].x() - x) < 2*rb + world_->band())
            {
                free = false;
                break;
            }
        }
        if (!free)
        {
            continue;
        }

        lastOfColumn[c] = world_->addBody(x, q);
        ++released;
    }

    return released;
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
        os.writeKeyword("porosityHeight") << "bedHeight - 1 dp" << nl;
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
        << tube_.diameter()/shape.diameter() << nl
        << "Proximity band lambda = " << world_->band() << " m" << nl
        << endl;
}


void Foam::rbd::packedBed::run()
{
    clockTime timer;
    world& w = world_();
    const simulationControls& ctrl = controls_;
    const pelletShape& shape = shape_();

    const scalar mass = material_.density*shape.volume();
    const scalar Eref = number_*mass*ctrl.gravity*shape.diameter();
    const scalar moving = ctrl.restingVelocity;

    labelList lastOfColumn(loading_->nColumns(), -1);
    label released = 0;
    scalar quietTime = 0;
    scalar nextLog = 0;
    scalar lastRelease = 0;
    bool warnedStall = false;
    settled_ = false;

    Info<< "Packing " << number_ << ' ' << shape.type() << " pellets" << nl
        << endl;

    while (w.time() < ctrl.endTime - 1e-12)
    {
        const label before = released;
        released = releasePellets(lastOfColumn, released);
        if (released > before)
        {
            lastRelease = w.time();
        }

        const scalar tOuter =
            ctrl.deltaT*(std::floor(w.time()/ctrl.deltaT + 1e-9) + 1);
        w.step(min(tOuter, ctrl.endTime) - w.time());

        if (w.time() < tOuter - 1e-12)
        {
            continue;
        }

        // Outer interval: termination test and progress
        const scalar KE = w.kineticEnergy();
        if
        (
            released < number_ && !warnedStall
         && w.time() - lastRelease > 2
        )
        {
            WarningInFunction
                << "No pellet could be released for 2 s: the bed has "
                << "reached the release height with " << released << " of "
                << number_ << " pellets" << endl;
            warnedStall = true;
        }
        // The kinetic-energy test once every pellet is in, or once no more
        // can be released (the bed settles with fewer pellets)
        if (released == number_ || warnedStall)
        {
            quietTime = (KE <= ctrl.settleEnergy*Eref) ? quietTime + ctrl.deltaT
                                                        : 0;
            if (quietTime >= ctrl.settleTime - 1e-12)
            {
                settled_ = true;
            }
        }

        if (w.time() >= nextLog - 1e-12 || settled_)
        {
            Info<< "Time = " << w.time() << " s  pellets " << released
                << '/' << number_ << "  moving " << w.nMoving(moving)
                << "  sleeping " << w.nSleeping()
                << "  KE = " << KE << " J  steps " << w.stats().steps
                << "  maxOverlap " << w.stats().maxOverlap << " m"
                << "  lcpFailures " << w.stats().lcpFailures
                << "  ExecutionTime = " << timer.elapsedTime() << " s"
                << endl;
            nextLog += ctrl.logInterval;
        }

        if (settled_)
        {
            break;
        }
    }

    wallTime_ = timer.elapsedTime();

    // Also leaves the final contact list, sleeping pellets included, in
    // w.contacts() for the contact treatments of the CFD case
    finalOverlap_ = w.currentMaxOverlap();

    Info<< nl;
    if (settled_)
    {
        Info<< "Settled: kinetic energy below " << ctrl.settleEnergy
            << " n m g dp for " << ctrl.settleTime << " s";
        if (released < number_)
        {
            Info<< ", with " << released << " of " << number_ << " pellets "
                << "(the bed reached the release height)";
        }
        Info<< nl;
    }
    else
    {
        WarningInFunction
            << "Not settled by endTime " << ctrl.endTime << " s (kinetic "
            << "energy " << w.kineticEnergy() << " J)" << endl;
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
        << " overlap corrections" << nl
        << "Wall time " << wallTime_ << " s" << nl << endl;
}


void Foam::rbd::packedBed::write() const
{
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

    bedOutput out(runTime_.path(), tube_, shape, w.bodies());
    out.writePellets();
    const dictionary analysis
    (
        out.writeProfiles(H, radialBins_, axialBins_)
    );
    const scalar eps = analysis.get<scalar>("bulkPorosity");
    // Pellet surfaces with the contact treatment at the simulation's own
    // touching contacts
    const label nTreated = out.writeSTL(caseSettings, w.contacts());

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
    summary.add("bulkPorosity", eps);
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
        1 - w.bodies().size()*shape.volume()
       /(pi*sqr(tube_.radius())*bedHeight())
    );
    summary.add("maxOverlap", w.stats().maxOverlap);
    summary.add("finalMaxOverlap", finalOverlap_);
    summary.add("simulatedTime", w.time());
    summary.add("wallTime", wallTime_);
    summary.add("steps", w.stats().steps);
    summary.add("collisions", w.stats().collisions);
    summary.add("lcpFailures", w.stats().lcpFailures);
    summary.add("kineticEnergy", w.kineticEnergy());
    summary.add("settled", Switch(settled_));
    summary.add("contactTreatment", caseSettings.contactTreatment());
    if (nTreated)
    {
        summary.add("treatedContacts", nTreated);
    }
    // Axis orientation of cylinders, rings, lobes, ... (orientation.dat)
    out.writeOrientation(H, 18, summary);
    out.writeSummary(summary);

    Info<< "Bulk porosity below " << H << " m: " << eps << nl
        << "Largest interpenetration during the run: "
        << w.stats().maxOverlap << " m ("
        << 100*w.stats().maxOverlap/shape.diameter() << " % of dp)" << nl
        << "Wrote " << out.directory() << " and " << out.stlFile();
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

    // The CFD case around the bed
    bedCaseWriter writer
    (
        runTime_.path(),
        caseSettings,
        insidePellet(caseSettings.pelletScale())
    );
    const fileNameList kept = writer.write();

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
}


// ************************************************************************* //
