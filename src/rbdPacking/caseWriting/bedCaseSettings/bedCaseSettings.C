/*---------------------------------------------------------------------------*\
  rbdPacking: hard-body rigid body dynamics packings for OpenFOAM
\*---------------------------------------------------------------------------*/

#include "bedCaseSettings.H"
#include "dictionaryChecks.H"
#include "Switch.H"

// * * * * * * * * * * * * * * * Static Data  * * * * * * * * * * * * * * * //

const Foam::wordList Foam::rbd::bedCaseSettings::contactTreatments
({
    "none",
    "shrink",
    "bridges",
    "caps"
});


const Foam::scalar Foam::rbd::bedCaseSettings::maxReynoldsNumber = 1e4;


const Foam::wordList Foam::rbd::bedCaseSettings::knownEntries
({
    "cellsPerDiameter",
    "pelletLevel",
    "wallLevel",
    "inletLength",
    "outletLength",
    "contactTreatment",
    "shrinkFactor",
    "bridgeDiameter",
    "capHeight",
    "contactGap",
    "nu",
    "Re",
    "U",
    "nIterations",
    "nProcessors",
    "overwrite",
    "stlFormat"
});


namespace
{
    //- Geometry entries of the single-dictionary constructor
    const Foam::wordList geometryEntries
    ({
        "tubeDiameter",
        "pelletDiameter",
        "bedHeight",
        "floorCentre"
    });

    //- The options part of a dictionary that may also hold the geometry
    Foam::dictionary withoutGeometry(const Foam::dictionary& dict)
    {
        Foam::dictionary options(dict);
        for (const Foam::word& key : geometryEntries)
        {
            options.remove(key);
        }
        return options;
    }
}


// * * * * * * * * * * * * * Private Member Functions  * * * * * * * * * * * //

void Foam::rbd::bedCaseSettings::setGrid()
{
    if (!(bedHeight_ > 0))
    {
        FatalErrorInFunction
            << "Bed geometry must be positive: bedHeight " << bedHeight_
            << " [m]" << exit(FatalError);
    }

    const scalar h = cellSize();
    const scalar R = tubeRadius();

    // The counts of cells, checked in floating point first: a length of
    // 1e9 m over cells of a millimetre overflows a label (the caller's
    // check of the total comes after this)
    const scalar maxCellsPerDirection = 1e9;
    struct direction
    {
        const char* where;
        scalar cells;
        const char* remedy;
    };
    for
    (
        const direction& n
      : {
            direction
            {
                "across the tube", 2*(R/h + 3),
                "lower cellsPerDiameter or the tube diameter"
            },
            direction
            {
                "along the bed (bed height)", bedHeight_/h,
                "lower cellsPerDiameter or the number of pellets"
            },
            direction
            {
                "below the bed (inletLength)", inletLengthRequested_/h,
                "shorten cfdCase/inletLength or lower cellsPerDiameter"
            },
            direction
            {
                "above the bed (outletLength)", outletLengthRequested_/h,
                "shorten cfdCase/outletLength or lower cellsPerDiameter"
            }
        }
    )
    {
        if (!(n.cells <= maxCellsPerDirection))
        {
            FatalErrorInFunction
                << "The CFD background grid would have " << n.cells
                << " cells " << n.where << " (cells of " << h << " m: "
                << "cfdCase/cellsPerDiameter per volume-equivalent "
                << "diameter)" << nl
                << "    allowed: at most " << maxCellsPerDirection
                << "; " << n.remedy << nl
                << exit(FatalError);
        }
    }

    // Across: cells of size h, three whole cells between tube and box
    const label nXY = 2*label(std::ceil(R/h + 3));
    const scalar halfWidth = 0.5*nXY*h;

    // Along z: the bed spans nBed + 1/2 cells, its bottom at 0.3 of a cell,
    // its top at 0.8 of a cell. Dyadic refinement puts faces at k/2^l of a
    // background cell; 0.3 and 0.8 stay >= 0.05 cells (0.2 cells of level 2)
    // away from any of them, so the sampled planes never lie on a face.
    const label nBed = max(label(0), label(std::round(bedHeight_/h - 0.5)));
    const scalar dz = bedHeight_/(nBed + 0.5);
    const label nBelow =
        max(label(1), label(std::round(inletLengthRequested_/dz - 0.3)));
    const label nAbove =
        max(label(1), label(std::round(outletLengthRequested_/dz - 0.2)));

    blockCells_ = labelVector(nXY, nXY, nBelow + nBed + 1 + nAbove);
    blockMin_ = point
    (
        floorCentre_.x() - halfWidth,
        floorCentre_.y() - halfWidth,
        bedBottom() - (nBelow + 0.3)*dz
    );
    blockMax_ = point
    (
        floorCentre_.x() + halfWidth,
        floorCentre_.y() + halfWidth,
        blockMin_.z() + blockCells_.z()*dz
    );
}


// * * * * * * * * * * * * * * * * Constructors  * * * * * * * * * * * * * * //

namespace
{
    //- Longest inlet or outlet, per pellet diameter [-]: longer ones
    //  give a grid of over 10^5 cells along the tube at the finest
    //  cellsPerDiameter, far beyond the cell limit of the case
    const Foam::scalar maxLengthPerDiameter = 1e4;
}


Foam::rbd::bedCaseSettings::bedCaseSettings
(
    const scalar tubeDiameter,
    const scalar pelletDiameter,
    const point& floorCentre,
    const dictionary& options
)
:
    tubeDiameter_(tubeDiameter),
    pelletDiameter_(pelletDiameter),
    bedHeight_(0),
    floorCentre_(floorCentre),
    // Upper bounds: the background grid and tube.stl grow as the cube and
    // the square of cellsPerDiameter, tube.stl by four per wallLevel
    cellsPerDiameter_
    (
        getLabelOrDefault(options, "cellsPerDiameter", 8, 2, 64)
    ),
    pelletLevel_(getLabelOrDefault(options, "pelletLevel", 1, 0, 5)),
    wallLevel_(getLabelOrDefault(options, "wallLevel", 0, 0, 4)),
    inletLengthRequested_
    (
        getPositiveOrDefault
        (
            options, "inletLength", 2*pelletDiameter, "m",
            maxLengthPerDiameter*pelletDiameter
        )
    ),
    outletLengthRequested_
    (
        getPositiveOrDefault
        (
            options, "outletLength", 3*pelletDiameter, "m",
            maxLengthPerDiameter*pelletDiameter
        )
    ),
    contactTreatment_
    (
        getChoiceOrDefault
        (
            options, "contactTreatment", "none", contactTreatments
        )
    ),
    shrinkFactor_
    (
        getInRangeOrDefault(options, "shrinkFactor", 0.99, 0.5, 1, "-")
    ),
    bridgeDiameter_
    (
        getInRangeOrDefault
        (
            options, "bridgeDiameter", 0.2*pelletDiameter,
            1e-3*pelletDiameter, 0.5*pelletDiameter, "m"
        )
    ),
    capHeight_
    (
        getInRangeOrDefault
        (
            options, "capHeight", 0.01*pelletDiameter,
            1e-4*pelletDiameter, 0.1*pelletDiameter, "m"
        )
    ),
    contactGap_
    (
        getInRangeOrDefault
        (
            options, "contactGap", 0.01*pelletDiameter,
            0, 0.05*pelletDiameter, "m"
        )
    ),
    nu_(getPositiveOrDefault(options, "nu", 1.5e-5, "m^2/s", 1)),
    velocity_(0),
    nIterations_(getLabelOrDefault(options, "nIterations", 2000, 1)),
    nProcessors_(getLabelOrDefault(options, "nProcessors", 2, 1)),
    overwrite_(getSwitchOrDefault(options, "overwrite", false)),
    binarySTL_
    (
        getChoiceOrDefault
        (
            options, "stlFormat", "ascii", wordList({"ascii", "binary"})
        ) == "binary"
    ),
    blockMin_(Zero),
    blockMax_(Zero),
    blockCells_(Zero)
{
    checkKnownEntries(options, knownEntries);

    // An entry of another contact treatment has no effect: say so (an
    // edit there would be lost silently)
    {
        const std::initializer_list<std::pair<const char*, wordList>> usedBy
        {
            {"shrinkFactor", wordList({"shrink"})},
            {"bridgeDiameter", wordList({"bridges"})},
            {"capHeight", wordList({"caps"})},
            {"contactGap", wordList({"bridges", "caps"})}
        };
        for (const auto& e : usedBy)
        {
            if
            (
                options.found(e.first, keyType::LITERAL)
             && !e.second.found(contactTreatment_)
            )
            {
                WarningInFunction
                    << e.first << " in " << options.name()
                    << " is ignored: contactTreatment is "
                    << contactTreatment_ << " (" << e.first
                    << " is for " << inWords(e.second).c_str() << ")"
                    << endl;
            }
        }
    }

    if (!(tubeDiameter_ > 0) || !(pelletDiameter_ > 0))
    {
        FatalErrorInFunction
            << "Bed geometry must be positive: tubeDiameter "
            << tubeDiameter_ << ", pelletDiameter " << pelletDiameter_
            << " [m]" << exit(FatalError);
    }
    if (!(tubeDiameter_ > pelletDiameter_))
    {
        FatalErrorInFunction
            << "The tube (diameter " << tubeDiameter_ << " m) must be wider"
            << " than the pellets (" << pelletDiameter_ << " m)"
            << exit(FatalError);
    }

    if (options.found("U"))
    {
        if (options.found("Re"))
        {
            badEntry
            (
                options, "U", options.get<scalar>("U"),
                "either U [m/s] or Re [-], not both"
            );
        }
        const scalar uMax = maxReynoldsNumber*nu_/pelletDiameter_;
        velocity_ = getPositive(options, "U", "m/s");
        if (velocity_ > uMax)
        {
            badEntry
            (
                options, "U", velocity_,
                "a number in (0, " + Foam::name(uMax) + "] [m/s] (Re_p = U "
                "dpv/nu at most " + Foam::name(maxReynoldsNumber)
              + ": the case is steady and laminar)"
            );
        }
    }
    else
    {
        const scalar Re =
            getPositiveOrDefault(options, "Re", 1, "-", maxReynoldsNumber);
        velocity_ = Re*nu_/pelletDiameter_;
    }
}


Foam::rbd::bedCaseSettings::bedCaseSettings
(
    const scalar tubeDiameter,
    const scalar pelletDiameter,
    const scalar bedHeight,
    const point& floorCentre,
    const dictionary& options
)
:
    bedCaseSettings(tubeDiameter, pelletDiameter, floorCentre, options)
{
    setBedHeight(bedHeight);
}


Foam::rbd::bedCaseSettings::bedCaseSettings(const dictionary& dict)
:
    bedCaseSettings
    (
        getPositive(dict, "tubeDiameter", "m"),
        getPositive(dict, "pelletDiameter", "m"),
        getPositive(dict, "bedHeight", "m"),
        dict.getOrDefault<point>("floorCentre", Zero),
        withoutGeometry(dict)
    )
{}


// * * * * * * * * * * * * * * * Member Functions  * * * * * * * * * * * * * //

void Foam::rbd::bedCaseSettings::setBedHeight(const scalar bedHeight)
{
    bedHeight_ = bedHeight;
    setGrid();
}


Foam::scalar Foam::rbd::bedCaseSettings::pelletScale() const
{
    return contactTreatment_ == "shrink" ? shrinkFactor_ : 1;
}


void Foam::rbd::bedCaseSettings::write(Ostream& os) const
{
    if (hasBedHeight())
    {
        os.writeEntry("tubeDiameter", tubeDiameter_);
        os.writeEntry("pelletDiameter", pelletDiameter_);
        os.writeEntry("bedHeight", bedHeight_);
        os.writeEntry("floorCentre", floorCentre_);
    }
    os.writeEntry("cellsPerDiameter", cellsPerDiameter_);
    os.writeEntry("pelletLevel", pelletLevel_);
    os.writeEntry("wallLevel", wallLevel_);
    if (hasBedHeight())
    {
        // As meshed: rounded to the background grid
        os.writeEntry("inletLength", inletLength());
        os.writeEntry("outletLength", outletLength());
    }
    else
    {
        os.writeEntry("inletLength", inletLengthRequested_);
        os.writeEntry("outletLength", outletLengthRequested_);
    }
    os.writeEntry("contactTreatment", contactTreatment_);
    if (contactTreatment_ == "shrink")
    {
        os.writeEntry("shrinkFactor", shrinkFactor_);
    }
    if (contactTreatment_ == "bridges")
    {
        os.writeEntry("bridgeDiameter", bridgeDiameter_);
    }
    if (contactTreatment_ == "caps")
    {
        os.writeEntry("capHeight", capHeight_);
    }
    if (contactTreatment_ == "bridges" || contactTreatment_ == "caps")
    {
        os.writeEntry("contactGap", contactGap_);
    }
    os.writeEntry("nu", nu_);
    os.writeEntry("U", velocity_);
    os.writeEntry("Re", reynoldsNumber());
    os.writeEntry("nIterations", nIterations_);
    os.writeEntry("nProcessors", nProcessors_);
    os.writeEntry("overwrite", Switch(overwrite_));
    os.writeEntry("stlFormat", word(binarySTL_ ? "binary" : "ascii"));
    if (hasBedHeight())
    {
        os.writeEntry("blockMin", blockMin_);
        os.writeEntry("blockMax", blockMax_);
        os.writeEntry("blockCells", blockCells_);
    }
}


// ************************************************************************* //
