/*---------------------------------------------------------------------------*\
  rbdPacking: hard-body rigid body dynamics packings for OpenFOAM
\*---------------------------------------------------------------------------*/

#include "pressureDropComparison.H"
#include "correlations.H"
#include "bedCaseWriter.H"
#include "foamFile.H"
#include "dictionaryChecks.H"
#include "IFstream.H"
#include "OSspecific.H"
#include "Pair.H"
#include "mathematicalConstants.H"
#include "dimensionedScalar.H"
#include <cmath>
#include <sstream>

// * * * * * * * * * * * * * * * Static Data  * * * * * * * * * * * * * * * //

const Foam::wordList Foam::rbd::pressureDropComparison::shapes
({
    "spheres",
    "cylinders"
});


const Foam::scalar Foam::rbd::pressureDropComparison::maxVelocity = 1000;


// * * * * * * * * * * * * * * * Local Functions * * * * * * * * * * * * * * //

namespace
{
    using namespace Foam;

    //- z of the sampling plane of function object \c object in controlDict
    scalar planeHeight(const dictionary& controlDict, const word& object)
    {
        const dictionary& planeDict =
            controlDict.subDict("functions").subDict(object)
           .subDict("sampledSurfaceDict").subDict("pointAndNormalDict");
        const vector normal = planeDict.get<vector>("normal");
        if (mag(normal ^ vector(0, 0, 1)) > 1e-6*mag(normal))
        {
            FatalIOErrorInFunction(planeDict)
                << "The plane of " << object << " is not normal to the tube"
                << " axis (z): normal " << normal << exit(FatalIOError);
        }
        return planeDict.get<point>("point").z();
    }

    //- Eisfeld & Schnitzlein's constants for a family of shapes
    rbd::correlations::eisfeldSchnitzleinShape esShape(const word& shape)
    {
        return shape == "cylinders"
            ? rbd::correlations::eisfeldSchnitzleinShape::cylinder
            : rbd::correlations::eisfeldSchnitzleinShape::sphere;
    }
}


// * * * * * * * * * * * * * Static Member Functions * * * * * * * * * * * * //

Foam::Pair<Foam::scalar> Foam::rbd::pressureDropComparison::lastValue
(
    const fileName& caseDir,
    const word& object
)
{
    const fileName dir(caseDir/"postProcessing"/object);

    // Newest start-time directory (a restart opens a new one)
    fileName newest;
    scalar newestTime = -GREAT;
    for (const fileName& d : readDir(dir, fileName::DIRECTORY))
    {
        scalar t;
        if (readScalar(d, t) && t > newestTime)
        {
            newestTime = t;
            newest = d;
        }
    }

    const fileName file(dir/newest/"surfaceFieldValue.dat");
    IFstream is(file);
    if (newest.empty() || !is.good())
    {
        FatalErrorInFunction
            << "No output of function object " << object << ": cannot read "
            << (newest.empty() ? dir : file) << nl
            << "    run simpleFoam on the case first" << exit(FatalError);
    }

    std::string line, last;
    while (is.good())
    {
        is.getLine(line);
        const auto first = line.find_first_not_of(" \t");
        if (first != std::string::npos && line[first] != '#')
        {
            last = line;
        }
    }

    std::istringstream row(last);
    double time, value;
    if (!(row >> time >> value))
    {
        FatalErrorInFunction
            << "No data row in " << file << exit(FatalError);
    }
    return Pair<scalar>(time, value);
}


// * * * * * * * * * * * * * * * * Constructors  * * * * * * * * * * * * * * //

Foam::rbd::pressureDropComparison::pressureDropComparison
(
    const fileName& caseDir,
    const word& shape
)
:
    caseDir_(caseDir),
    shape_(shape),
    porosity_(0),
    tubeDiameter_(0),
    pelletDiameter_(0),
    bedHeight_(0),
    length_(0),
    nu_(0),
    rho_(0),
    velocity_(0),
    pBottom_(0),
    pTop_(0)
{
    const dictionary summary
    (
        readFoamFile(caseDir_/"postProcessing/rbdPackBed/summary")
    );

    if (shape_.empty())
    {
        const word pellet = summary.getOrDefault<word>("shape", "unknown");
        if (pellet == "sphere" || pellet == "cylinder")
        {
            shape_ = pellet + "s";
        }
        else
        {
            FatalErrorInFunction
                << "No Eisfeld-Schnitzlein constants for pellets of shape '"
                << pellet << "' (summary of " << caseDir_ << "); name the"
                << " family to use: one of " << shapes << exit(FatalError);
        }
    }
    if (!shapes.found(shape_))
    {
        FatalErrorInFunction
            << "No Eisfeld-Schnitzlein constants for shape '" << shape_
            << "'; have " << shapes << exit(FatalError);
    }
    porosity_ = getInRangeOrDefault(summary, "bedPorosity", -1, 0, 1, "-");
    if (!(porosity_ > 0 && porosity_ < 1))
    {
        badEntry
        (
            summary, "bedPorosity", porosity_, "a number in (0, 1)"
        );
    }
    tubeDiameter_ = getPositive(summary, "tubeDiameter", "m");
    // The correlations' dp is the volume-equivalent diameter dpv
    // (correlations.md); summaries of sphere beds before dpv was written
    // have pelletDiameter only, which is dpv for spheres
    pelletDiameter_ =
        summary.found("volumeEquivalentDiameter")
      ? getPositive(summary, "volumeEquivalentDiameter", "m")
      : getPositive(summary, "pelletDiameter", "m");
    bedHeight_ = getPositive(summary, "bedHeight", "m");

    const dictionary transport
    (
        readFoamFile(caseDir_/"constant/transportProperties")
    );
    nu_ = dimensionedScalar("nu", dimArea/dimTime, transport).value();
    if (!(nu_ > 0 && nu_ <= 1))
    {
        badEntry
        (
            transport, "nu", nu_,
            "a kinematic viscosity in (0, 1] [m^2/s]"
        );
    }
    if (transport.found("rho"))
    {
        rho_ = dimensionedScalar("rho", dimMass/dimVolume, transport).value();
    }

    const dictionary control(readFoamFile(caseDir_/"system/controlDict"));
    const scalar zBottom =
        planeHeight(control, bedCaseWriter::bedBottomObject);
    const scalar zTop = planeHeight(control, bedCaseWriter::bedTopObject);
    length_ = zTop - zBottom;
    if (!(length_ > 0))
    {
        FatalIOErrorInFunction(control)
            << "The plane of " << bedCaseWriter::bedTopObject
            << " must lie above that of " << bedCaseWriter::bedBottomObject
            << exit(FatalIOError);
    }
    if (mag(length_ - bedHeight_) > 0.01*bedHeight_)
    {
        WarningInFunction
            << "Sampling planes " << length_ << " m apart, bed height "
            << bedHeight_ << " m" << endl;
    }

    const scalar area =
        0.25*constant::mathematical::pi*sqr(tubeDiameter_);
    const scalar flowRate =
        lastValue(caseDir_, bedCaseWriter::flowRateObject)[1];
    velocity_ = mag(flowRate)/area;
    if (!(velocity_ > 0 && velocity_ <= maxVelocity))
    {
        FatalErrorInFunction
            << "The flow rate " << flowRate << " m^3/s of "
            << caseDir_/"postProcessing"/bedCaseWriter::flowRateObject
            << " gives a superficial velocity of " << velocity_ << " m/s"
            << nl << "    allowed: (0, " << maxVelocity << "] m/s; has"
            << " simpleFoam run and converged?" << exit(FatalError);
    }
    pBottom_ = lastValue(caseDir_, bedCaseWriter::bedBottomObject)[1];
    pTop_ = lastValue(caseDir_, bedCaseWriter::bedTopObject)[1];
    const scalar s = simulated();
    if (!(std::isfinite(s) && s > 0))
    {
        FatalErrorInFunction
            << "The simulated pressure drop (" << pBottom_ << " - " << pTop_
            << ")/" << length_ << " = " << s << " m/s^2 (kinematic, from "
            << caseDir_/"postProcessing" << ") is not a positive number:"
            << " has simpleFoam converged?" << exit(FatalError);
    }
}


// * * * * * * * * * * * * * * * Member Functions  * * * * * * * * * * * * * //

Foam::scalar Foam::rbd::pressureDropComparison::ergun() const
{
    // Kinematic form: mu = nu, rho = 1
    return correlations::ergun(nu_, 1, velocity_, porosity_, pelletDiameter_);
}


Foam::scalar Foam::rbd::pressureDropComparison::eisfeldSchnitzlein() const
{
    return correlations::eisfeldSchnitzlein
    (
        nu_, 1, velocity_, porosity_, pelletDiameter_, tubeDiameter_,
        esShape(shape_)
    );
}


Foam::dictionary Foam::rbd::pressureDropComparison::results() const
{
    dictionary d;
    d.add("shape", shape_);
    d.add("bedPorosity", porosity_);
    d.add("tubeDiameter", tubeDiameter_);
    d.add("volumeEquivalentDiameter", pelletDiameter_);
    d.add("bedHeight", bedHeight_);
    d.add("planeDistance", length_);
    d.add("nu", nu_);
    d.add("superficialVelocity", velocity_);
    d.add("Re", reynoldsNumber());
    d.add("pBottom", pBottom_);
    d.add("pTop", pTop_);
    d.add("dPdLSimulated", simulated());
    d.add("dPdLErgun", ergun());
    d.add("dPdLEisfeldSchnitzlein", eisfeldSchnitzlein());
    d.add("ratioErgun", simulated()/ergun());
    d.add("ratioEisfeldSchnitzlein", simulated()/eisfeldSchnitzlein());
    if (rho_ > 0)
    {
        d.add("rho", rho_);
        d.add("dPdLSimulatedPa", rho_*simulated());
    }
    return d;
}


void Foam::rbd::pressureDropComparison::report(Ostream& os) const
{
    os  << "Pressure drop over the packed section (" << shape_
        << ", porosity " << porosity_ << ", L = " << length_ << " m,"
        << " U = " << velocity_ << " m/s, Re_p = " << reynoldsNumber()
        << ")" << nl
        << "    dP/(rho L) [m/s^2]" << nl
        << "        simulated             " << simulated() << nl
        << "        Ergun                 " << ergun()
        << "  (simulated/Ergun " << simulated()/ergun() << ")" << nl
        << "        Eisfeld-Schnitzlein   " << eisfeldSchnitzlein()
        << "  (simulated/E-S " << simulated()/eisfeldSchnitzlein() << ")"
        << nl;
    if (rho_ > 0)
    {
        os  << "    dP/L simulated [Pa/m]     " << rho_*simulated() << nl;
    }
}


Foam::fileName Foam::rbd::pressureDropComparison::writeFile() const
{
    const fileName file(caseDir_/"postProcessing/pressureDrop/comparison");
    writeFoamFile
    (
        file, "dictionary", results(),
        "dPdL*: dP/(rho L) [m/s^2] over the packed section;"
        " correlations in kinematic form"
    );
    return file;
}


// ************************************************************************* //
