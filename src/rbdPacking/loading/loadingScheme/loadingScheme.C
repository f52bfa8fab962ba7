/*---------------------------------------------------------------------------*\
  rbdPacking: hard-body rigid body dynamics packings for OpenFOAM
\*---------------------------------------------------------------------------*/

#include "loadingScheme.H"
#include "dictionaryChecks.H"
#include "mathematicalConstants.H"
#include "unitConversion.H"
#include "stateIO.H"
#include <sstream>

using Foam::constant::mathematical::pi;

// * * * * * * * * * * * * * * Static Data Members * * * * * * * * * * * * * //

const Foam::wordList Foam::rbd::loadingScheme::schemes
({
    "column", "twoColumns", "fourColumns", "layers", "placement"
});


const Foam::scalar Foam::rbd::loadingScheme::boundTolerance = 1e-12;


const Foam::wordList Foam::rbd::loadingScheme::knownEntries
({
    "scheme", "spacing", "tilt", "positionDisturbance",
    "angleDisturbance", "seed", "releaseHeight", "columnOffset", "file",
    "awakeLayers"
});


// * * * * * * * * * * * * * * * * Constructors  * * * * * * * * * * * * * * //

Foam::rbd::loadingScheme::loadingScheme
(
    const dictionary& dict,
    const tube& container,
    const pelletShape& shape
)
:
    scheme_(getChoiceOrDefault(dict, "scheme", "column", schemes)),
    spacing_(getPositiveOrDefault(dict, "spacing", 1.2, "-")),
    tilt_(getInRangeOrDefault(dict, "tilt", 45, 0, 180, "deg")),
    positionDisturbance_(0),
    angleDisturbance_
    (
        getInRangeOrDefault(dict, "angleDisturbance", 0, 0, 180, "deg")
    ),
    seed_(getLabelOrDefault(dict, "seed", 1, 0)),
    releaseHeight_(0),
    columnOffset_(0),
    awakeLayers_(0),
    columns_(),
    dp_(shape.diameter()),
    rb_(shape.boundingRadius()),
    R_(container.radius()),
    rng_(seed_),
    placement_()
{
    checkKnownEntries(dict, knownEntries);

    if (scheme_ == "placement")
    {
        // The poses are the file's: nothing is released, drawn or
        // disturbed
        string ignored;
        for (const word& key : knownEntries)
        {
            if (key != "scheme" && key != "file" && dict.found(key))
            {
                ignored += (ignored.empty() ? "" : ", ") + key;
            }
        }
        if (!ignored.empty())
        {
            WarningInFunction
                << ignored.c_str() << " in " << dict.name() << " ignored: "
                << "scheme placement places every pellet where its file "
                << "says, at rest, at t = 0" << endl;
        }
        placement_.reset(new placementFile(dict, container, shape));
        releaseHeight_ = placement_->highestCentre();
        return;
    }
    if (dict.found("file"))
    {
        WarningInFunction
            << "file in " << dict.name() << " is ignored: only scheme "
            << "placement reads its poses from a file" << endl;
    }

    if (spacing_ < 1)
    {
        badEntry(dict, "spacing", spacing_, "a number >= 1 [-]");
    }

    // Default offset 0.3 dp, or the largest the scheme's bounds allow
    // where that is less (a narrow tube, the layers' lattice pitch)
    positionDisturbance_ = getNonNegativeOrDefault
    (
        dict, "positionDisturbance",
        min(0.3, max(largestDisturbance(), 0.0)), "-"
    );

    releaseHeight_ = getPositiveOrDefault
    (
        dict, "releaseHeight", container.height() - rb_, "m"
    );
    if (releaseHeight_ <= rb_ || releaseHeight_ > container.height() - rb_)
    {
        badEntry
        (
            dict, "releaseHeight", releaseHeight_,
            "a height in (" + Foam::name(rb_) + ", "
          + Foam::name(container.height() - rb_) + "] [m] (a pellet "
            "released there is within the tube: above the floor by its "
            "bounding radius, below the top of the container by it)"
        );
    }

    // Wall, for a release point on the axis (column, and the layers'
    // central point): delta <= R - r_b
    if
    (
        (scheme_ == "column" || scheme_ == "layers")
     && positionDisturbance_*dp_ > (R_ - rb_)*(1 + boundTolerance)
    )
    {
        badEntry
        (
            dict, "positionDisturbance", positionDisturbance_,
            "a number in [0, " + Foam::name((R_ - rb_)/dp_) + "] [-] "
            "for scheme " + scheme_ + ": a pellet released up to "
            "positionDisturbance dp from the axis must clear the wall, "
            "(R - r_b)/dp = (" + Foam::name(R_) + " - " + Foam::name(rb_)
          + ")/" + Foam::name(dp_) + " (tube radius R, pellet bounding "
            "radius r_b, dp in m)"
        );
    }

    if
    (
        (scheme_ == "column" || scheme_ == "layers")
     && dict.found("columnOffset")
    )
    {
        WarningInFunction
            << "columnOffset in " << dict.name() << " is ignored: the "
            << scheme_ << " scheme "
            << (
                   scheme_ == "column"
                 ? "releases on the tube axis"
                 : "releases over the whole cross-section"
               )
            << endl;
    }
    else if (scheme_ != "column" && scheme_ != "layers")
    {
        readColumnOffset(dict);
    }

    if (scheme_ != "layers" && dict.found("awakeLayers"))
    {
        WarningInFunction
            << "awakeLayers in " << dict.name() << " is ignored: only "
            << "scheme layers waits for its bed to sleep" << endl;
    }

    const scalar s = columnOffset_;
    const scalar z = releaseHeight_;
    if (scheme_ == "column")
    {
        columns_ = pointField({point(0, 0, z)});
    }
    else if (scheme_ == "layers")
    {
        // Points within R - r_b - delta: the disturbed pellets clear the
        // wall
        columns_ = layerPoints
        (
            clearance(), max(R_ - rb_ - positionDisturbance_*dp_, 0.0), z
        );
        checkLayerSpacing(dict);

        // The next layer waits for the bed below to fall asleep
        awakeLayers_ = getNonNegativeOrDefault(dict, "awakeLayers", 1, "-");
    }
    else if (scheme_ == "twoColumns")
    {
        columns_ = pointField({point(s, 0, z), point(-s, 0, z)});
    }
    else
    {
        columns_ = pointField
        ({
            point(s, 0, z), point(0, s, z), point(-s, 0, z), point(0, -s, z)
        });
    }
}


// * * * * * * * * * * * * Private Member Functions  * * * * * * * * * * * //

Foam::scalar Foam::rbd::loadingScheme::largestDisturbance() const
{
    // The bounds of the Description solved for delta = positionDisturbance
    // dp: the wall for a point on the axis, R - r_b; where the columns'
    // bounds on s meet, (R - (1 + k) r_b)/(1 + k); the lattice pitch
    if (scheme_ == "twoColumns" || scheme_ == "fourColumns")
    {
        const scalar k =
            scheme_ == "twoColumns" ? 1 : Foam::sqrt(2.0);
        return (R_ - (1 + k)*rb_)/((1 + k)*dp_);
    }
    else if (scheme_ == "layers")
    {
        return min(R_ - rb_, 0.5*clearance() - rb_)/dp_;
    }
    return (R_ - rb_)/dp_;
}


void Foam::rbd::loadingScheme::readColumnOffset(const dictionary& dict)
{
    // Neighbouring columns are k s apart (Description)
    const bool two = (scheme_ == "twoColumns");
    const scalar k = two ? 1 : Foam::sqrt(2.0);
    const word kText(two ? "" : "sqrt(2) ");
    const string onePlusK(two ? "2" : "(1 + sqrt(2))");
    const scalar delta = positionDisturbance_*dp_;
    const scalar sMin = k*(rb_ + delta);
    const scalar sMax = R_ - rb_ - delta;
    const string tubeText
    (
        "tube radius R = " + Foam::name(R_) + " m, pellet bounding radius "
        "r_b = " + Foam::name(rb_) + " m"
    );

    // A tube too narrow for the scheme even without a disturbance ...
    if (R_ < (1 + k)*rb_*(1 - boundTolerance))
    {
        badEntry
        (
            dict, "scheme", scheme_,
            "column | layers"
          + string(!two && R_ >= 2*rb_ ? " | twoColumns" : "")
          + " in this tube: " + scheme_ + " releases pellets side by side "
            "and needs R >= " + onePlusK + " r_b = "
          + Foam::name((1 + k)*rb_) + " m (" + tubeText + ")"
        );
    }

    // ... or for its disturbance: the bounds on s cross
    if (sMin > sMax*(1 + boundTolerance))
    {
        badEntry
        (
            dict, "positionDisturbance", positionDisturbance_,
            "a number in [0, "
          + Foam::name((R_ - (1 + k)*rb_)/((1 + k)*dp_)) + "] [-] for "
            "scheme " + scheme_ + " in this tube: columnOffset must be at "
            "least " + kText + "(r_b + positionDisturbance dp) (pellets "
            "released together from neighbouring columns clear one "
            "another) and at most R - r_b - positionDisturbance dp (they "
            "clear the wall), so positionDisturbance <= (R - " + onePlusK
          + " r_b)/(" + onePlusK + " dp) (" + tubeText + ", dp = "
          + Foam::name(dp_) + " m)"
        );
    }

    columnOffset_ = getNonNegativeOrDefault
    (
        dict, "columnOffset", 0.5*(sMin + sMax), "m"
    );
    if
    (
        columnOffset_ < sMin*(1 - boundTolerance)
     || columnOffset_ > sMax*(1 + boundTolerance)
    )
    {
        badEntry
        (
            dict, "columnOffset", columnOffset_,
            "a number in [" + Foam::name(sMin) + ", " + Foam::name(sMax)
          + "] [m] for scheme " + scheme_ + " with positionDisturbance "
          + Foam::name(positionDisturbance_) + ": at least " + kText
          + "(r_b + positionDisturbance dp), so that pellets released "
            "together from neighbouring columns cannot overlap, and at "
            "most R - r_b - positionDisturbance dp, so that none reaches "
            "the wall (" + tubeText + ", dp = " + Foam::name(dp_) + " m)"
        );
    }
}


void Foam::rbd::loadingScheme::checkLayerSpacing
(
    const dictionary& dict
) const
{
    const scalar delta = positionDisturbance_*dp_;
    if
    (
        columns_.size() > 1
     && clearance() < 2*(rb_ + delta)*(1 - boundTolerance)
    )
    {
        const scalar D = max(dp_, 2*rb_);
        badEntry
        (
            dict, "spacing", spacing_,
            "a number >= " + Foam::name(2*(rb_ + delta)/D) + " [-] for "
            "scheme layers with positionDisturbance "
          + Foam::name(positionDisturbance_) + ", or a positionDisturbance "
            "of at most " + Foam::name(max(largestDisturbance(), 0.0))
          + " with this spacing: neighbouring points of the lattice, "
            "spacing max(dp, 2 r_b) apart, release pellets together, up to "
            "positionDisturbance dp off their points, whose bounding "
            "spheres must not overlap: spacing max(dp, 2 r_b) >= "
            "2 (r_b + positionDisturbance dp) (pellet bounding radius r_b "
            "= " + Foam::name(rb_) + " m, dp = " + Foam::name(dp_) + " m)"
        );
    }
}


// * * * * * * * * * * * * * * * Member Functions  * * * * * * * * * * * * * //

Foam::pointField Foam::rbd::loadingScheme::layerPoints
(
    const scalar pitch,
    const scalar rhoMax,
    const scalar z
)
{
    // Hexagonal lattice through the axis, rows along x; the points within
    // rhoMax, sorted by distance from the axis and then by angle, so that
    // the order (and with it the packing) is the same on every machine
    DynamicList<point> pts;
    const scalar rowPitch = pitch*Foam::sqrt(3.0)/2;
    const label nRows = label(std::floor(rhoMax/rowPitch + 1e-9));
    const label nCols = label(std::floor(rhoMax/pitch + 1e-9)) + 1;
    for (label j = -nRows; j <= nRows; ++j)
    {
        const scalar y = j*rowPitch;
        const scalar shift = (j % 2 == 0) ? 0 : 0.5*pitch;
        for (label i = -nCols - 1; i <= nCols; ++i)
        {
            const scalar x = i*pitch + shift;
            if (Foam::sqrt(sqr(x) + sqr(y)) <= rhoMax*(1 + 1e-12))
            {
                pts.append(point(x, y, z));
            }
        }
    }
    std::stable_sort
    (
        pts.begin(), pts.end(),
        [](const point& a, const point& b)
        {
            const scalar ra = sqr(a.x()) + sqr(a.y());
            const scalar rb = sqr(b.x()) + sqr(b.y());
            if (Foam::mag(ra - rb) > 1e-18)
            {
                return ra < rb;
            }
            return std::atan2(a.y(), a.x()) < std::atan2(b.y(), b.x());
        }
    );
    return pointField(std::move(pts));
}


void Foam::rbd::loadingScheme::nextPose
(
    const label c,
    point& x,
    quaternion& q
)
{
    std::uniform_real_distribution<double> U(0, 1);

    // Horizontal disturbance: uniform in a disc, which the bounds keep
    // within R - r_b of the axis (Description). A centre that rounding
    // (or a value within boundTolerance of a bound) puts at R - r_b is
    // pulled back by 1e-9 of it; one beyond by more is a bug, not a
    // release
    x = columns_[c];
    if (positionDisturbance_ > 0)
    {
        const scalar r = positionDisturbance_*dp_*Foam::sqrt(U(rng_));
        const scalar phi = 2*pi*U(rng_);
        x += vector(r*Foam::cos(phi), r*Foam::sin(phi), 0);

        const scalar rho = tube::axialDistance(x);
        const scalar rhoMax = (R_ - rb_)*(1 - 1e-9);
        if (rho > (R_ - rb_)*(1 + 1e-9))
        {
            FatalErrorInFunction
                << "A pellet of the " << scheme_ << " scheme would be "
                << "released " << rho << " m from the axis, beyond R - r_b "
                << "= " << R_ - rb_ << " m: the loading's bounds do not "
                << "hold (a bug)" << abort(FatalError);
        }
        if (rho > rhoMax)
        {
            x.x() *= rhoMax/rho;
            x.y() *= rhoMax/rho;
        }
    }

    // Tilt of the body z axis to gravity, about the world x axis
    q = quaternion(vector(1, 0, 0), degToRad(tilt_));

    // Orientation disturbance: random axis, angle in [0, angleDisturbance]
    if (angleDisturbance_ > 0)
    {
        const scalar cosTheta = 2*U(rng_) - 1;
        const scalar sinTheta = Foam::sqrt(max(1 - sqr(cosTheta), 0.0));
        const scalar phi = 2*pi*U(rng_);
        const vector axis
        (
            sinTheta*Foam::cos(phi), sinTheta*Foam::sin(phi), cosTheta
        );
        const scalar angle = degToRad(angleDisturbance_)*U(rng_);
        q = quaternion(axis, angle)*q;
    }
    q.normalize();
}


void Foam::rbd::loadingScheme::write(Ostream& os) const
{
    os.writeEntry("scheme", scheme_);
    if (placed())
    {
        os.writeEntry("file", placement_->file());
        os.writeKeyword("poses") << placement_->size() << " pellets from "
            << placement_->path() << ", centres up to "
            << placement_->highestCentre() << " m high"
            << token::END_STATEMENT << nl;
        return;
    }
    os.writeEntry("spacing", spacing_);
    os.writeEntry("tilt", tilt_);
    os.writeEntry("positionDisturbance", positionDisturbance_);
    os.writeEntry("angleDisturbance", angleDisturbance_);
    os.writeEntry("seed", seed_);
    os.writeEntry("releaseHeight", releaseHeight_);
    os.writeEntry("columnOffset", columnOffset_);
    if (scheme_ == "layers")
    {
        os.writeEntry("awakeLayers", awakeLayers_);
    }
}


void Foam::rbd::loadingScheme::writeState(stateWriter& out) const
{
    // The standard's text form of the engine: exact and portable
    std::ostringstream os;
    os << rng_;
    out.put(os.str());
}


void Foam::rbd::loadingScheme::readState(stateReader& in)
{
    std::string text;
    in.get(text);
    std::istringstream is(text);
    is >> rng_;
    if (!is)
    {
        FatalErrorInFunction
            << "The checkpoint " << in.name().c_str() << " holds no state of the "
            << "loading's random generator: it is damaged." << nl
            << "    Delete it and run without -resume." << exit(FatalError);
    }
}


// ************************************************************************* //
