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
    "column", "twoColumns", "fourColumns"
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

    if (scheme_ == "column" && dict.found("columnOffset"))
    {
        WarningInFunction
            << "columnOffset in " << dict.name() << " is ignored: the "
            << "column scheme releases on the tube axis" << endl;
    }

    const scalar s = columnOffset_;
    const scalar z = releaseHeight_;
    if (scheme_ == "column")
    {
        columns_ = pointField({point(0, 0, z)});
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
