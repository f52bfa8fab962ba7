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
    "column", "twoColumns", "fourColumns", "layers"
});


const Foam::wordList Foam::rbd::loadingScheme::knownEntries
({
    "scheme", "spacing", "tilt", "positionDisturbance",
    "angleDisturbance", "seed", "releaseHeight", "columnOffset"
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
    positionDisturbance_
    (
        getNonNegativeOrDefault(dict, "positionDisturbance", 0.3, "-")
    ),
    angleDisturbance_
    (
        getInRangeOrDefault(dict, "angleDisturbance", 0, 0, 180, "deg")
    ),
    seed_(getLabelOrDefault(dict, "seed", 1, 0)),
    releaseHeight_(0),
    columnOffset_(0),
    columns_(),
    dp_(shape.diameter()),
    rb_(shape.boundingRadius()),
    R_(container.radius()),
    rng_(seed_)
{
    checkKnownEntries(dict, knownEntries);

    if (spacing_ < 1)
    {
        badEntry(dict, "spacing", spacing_, "a number >= 1 [-]");
    }

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

    const scalar maxOffset = R_ - rb_;
    columnOffset_ = getNonNegativeOrDefault
    (
        dict, "columnOffset", scheme_ == "column" ? 0 : 0.5*maxOffset, "m"
    );
    if (columnOffset_ > maxOffset)
    {
        badEntry
        (
            dict, "columnOffset", columnOffset_,
            "a number in [0, " + Foam::name(maxOffset)
          + "] (tube radius - pellet bounding radius) [m]"
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

    const scalar s = columnOffset_;
    const scalar z = releaseHeight_;
    if (scheme_ == "column")
    {
        columns_ = pointField({point(0, 0, z)});
    }
    else if (scheme_ == "layers")
    {
        columns_ = layerPoints(clearance(), R_ - rb_, z);
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

    // Horizontal disturbance: uniform in a disc, kept inside the tube
    x = columns_[c];
    if (positionDisturbance_ > 0)
    {
        const scalar r = positionDisturbance_*dp_*Foam::sqrt(U(rng_));
        const scalar phi = 2*pi*U(rng_);
        x += vector(r*Foam::cos(phi), r*Foam::sin(phi), 0);

        const scalar rho = tube::axialDistance(x);
        const scalar rhoMax = (R_ - rb_)*(1 - 1e-9);
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
    os.writeEntry("spacing", spacing_);
    os.writeEntry("tilt", tilt_);
    os.writeEntry("positionDisturbance", positionDisturbance_);
    os.writeEntry("angleDisturbance", angleDisturbance_);
    os.writeEntry("seed", seed_);
    os.writeEntry("releaseHeight", releaseHeight_);
    os.writeEntry("columnOffset", columnOffset_);
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
