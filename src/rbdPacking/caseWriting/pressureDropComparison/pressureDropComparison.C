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
#include "Switch.H"
#include <cmath>
#include <limits>
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
    pTop_(0),
    boundingDiameter_(0),
    bulkPorosity_(-1),
    porosityHeight_(-1),
    zBottom_(0),
    pPackedTop_(std::numeric_limits<scalar>::quiet_NaN()),
    stlPorosity_(-1),
    meshPorosity_(std::numeric_limits<scalar>::quiet_NaN()),
    packedMeshPorosity_(std::numeric_limits<scalar>::quiet_NaN())
{
    const dictionary summary
    (
        readFoamFile(caseDir_/"postProcessing/rbdPackBed/summary")
    );

    pelletShape_ = summary.getOrDefault<word>("shape", "unknown");
    if (shape_.empty())
    {
        const word& pellet = pelletShape_;
        if (pellet == "sphere" || pellet == "cylinder")
        {
            shape_ = pellet + "s";
        }
        else
        {
            FatalErrorInFunction
                << "No Eisfeld-Schnitzlein constants for pellets of shape '"
                << pellet << "' (summary of " << caseDir_ << "); name the"
                << " family to use with -shape: " << inWords(shapes).c_str()
                << exit(FatalError);
        }
    }
    if (!shapes.found(shape_))
    {
        FatalErrorInFunction
            << "No Eisfeld-Schnitzlein constants for shape '" << shape_
            << "'; have " << inWords(shapes).c_str() << exit(FatalError);
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
    // (docs/method.md, section 14); summaries of sphere beds before dpv
    // was written have pelletDiameter only, which is dpv for spheres
    pelletDiameter_ =
        summary.found("volumeEquivalentDiameter")
      ? getPositive(summary, "volumeEquivalentDiameter", "m")
      : getPositive(summary, "pelletDiameter", "m");
    boundingDiameter_ = getPositive(summary, "pelletDiameter", "m");
    bedHeight_ = getPositive(summary, "bedHeight", "m");
    // The packed section: the slab of the bulk porosity (summaries
    // without it give the whole bed only)
    if (summary.found("porosityHeight") && summary.found("bulkPorosity"))
    {
        porosityHeight_ = getPositive(summary, "porosityHeight", "m");
        bulkPorosity_ =
            getInRangeOrDefault(summary, "bulkPorosity", -1, 0, 1, "-");
    }
    // pellets.stl's (summaries of beds before it have none)
    stlPorosity_ = getInRangeOrDefault(summary, "stlPorosity", -1, -1, 1, "-");

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
    zBottom_ = zBottom;
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

Foam::scalar Foam::rbd::pressureDropComparison::ergun(const scalar eps) const
{
    // Kinematic form: mu = nu, rho = 1
    return correlations::ergun(nu_, 1, velocity_, eps, pelletDiameter_);
}


Foam::scalar Foam::rbd::pressureDropComparison::eisfeldSchnitzlein
(
    const scalar eps
) const
{
    return correlations::eisfeldSchnitzlein
    (
        nu_, 1, velocity_, eps, pelletDiameter_, tubeDiameter_,
        esShape(shape_)
    );
}


Foam::scalar Foam::rbd::pressureDropComparison::ergun() const
{
    return ergun(porosity_);
}


Foam::scalar Foam::rbd::pressureDropComparison::eisfeldSchnitzlein() const
{
    return eisfeldSchnitzlein(porosity_);
}


bool Foam::rbd::pressureDropComparison::hasPackedSection() const
{
    // A slab reaching the top plane is the whole bed again
    return
        porosityHeight_ > 0
     && porosityHeight_ < length_*(1 - 1e-6)
     && bulkPorosity_ > 0 && bulkPorosity_ < 1;
}


Foam::scalar Foam::rbd::pressureDropComparison::packedTopHeight() const
{
    return zBottom_ + porosityHeight_;
}


void Foam::rbd::pressureDropComparison::setPackedTopPressure(const scalar p)
{
    if (!hasPackedSection())
    {
        FatalErrorInFunction
            << "The summary of " << caseDir_ << " gives no packed section"
            << " below the bed top (porosityHeight " << porosityHeight_
            << " m, bulkPorosity " << bulkPorosity_ << ", planes "
            << length_ << " m apart)" << exit(FatalError);
    }
    pPackedTop_ = p;
    const scalar s = packedSimulated();
    if (!(std::isfinite(s) && s > 0))
    {
        FatalErrorInFunction
            << "The simulated pressure drop over the packed section ("
            << pBottom_ << " - " << p << ")/" << porosityHeight_ << " = "
            << s << " m/s^2 (kinematic) is not a positive number: has"
            << " simpleFoam converged?" << exit(FatalError);
    }
}


void Foam::rbd::pressureDropComparison::setFluidVolumes
(
    const scalar whole,
    const scalar packed
)
{
    const scalar area =
        0.25*constant::mathematical::pi*sqr(tubeDiameter_);
    meshPorosity_ = whole/(area*length_);
    if (hasPackedSection())
    {
        packedMeshPorosity_ = packed/(area*porosityHeight_);
    }
    if (!(meshPorosity_ > 0 && meshPorosity_ <= 1 + 1e-3))
    {
        FatalErrorInFunction
            << "The fluid mesh holds " << whole << " m^3 between the planes "
            << length_ << " m apart in the tube of diameter "
            << tubeDiameter_ << " m: a porosity of " << meshPorosity_
            << ", not in (0, 1]; is it this case's mesh?" << exit(FatalError);
    }
}


bool Foam::rbd::pressureDropComparison::meshPorosityMeasured() const
{
    return std::isfinite(meshPorosity_);
}


bool Foam::rbd::pressureDropComparison::packedMeasured() const
{
    return std::isfinite(pPackedTop_);
}


Foam::scalar Foam::rbd::pressureDropComparison::packedSimulated() const
{
    return (pBottom_ - pPackedTop_)/porosityHeight_;
}


Foam::scalar Foam::rbd::pressureDropComparison::packedErgun() const
{
    return ergun(bulkPorosity_);
}


Foam::scalar
Foam::rbd::pressureDropComparison::packedEisfeldSchnitzlein() const
{
    return eisfeldSchnitzlein(bulkPorosity_);
}


Foam::stringList Foam::rbd::pressureDropComparison::outside
(
    const word& correlation,
    const scalar eps
) const
{
    const bool isErgun = correlation == "ergun";
    const correlations::pressureDropRange range =
        isErgun
      ? correlations::ergunRange()
      : correlations::eisfeldSchnitzleinRange();

    // Numbers as a message prints them (6 significant digits)
    const auto num = [](const scalar x) { return std::string(name(x)); };
    const auto bounds = [&num](const scalar lo, const scalar hi)
    {
        return hi < 0.1*GREAT
          ? "[" + num(lo) + ", " + num(hi) + "]"
          : ">= " + num(lo);
    };

    DynamicList<string> why;
    const scalar Re =
        range.modifiedRe ? reynoldsNumber()/(1 - eps) : reynoldsNumber();
    const std::string ReName = range.modifiedRe ? "Re_p/(1 - eps)" : "Re_p";
    if (Re < range.ReMin || Re > range.ReMax)
    {
        why.append
        (
            ReName + " = " + num(Re) + " not in "
          + bounds(range.ReMin, range.ReMax)
        );
    }
    const scalar Nv = volumeEquivalentDiameterRatio();
    if (Nv < range.NvMin || Nv > range.NvMax)
    {
        why.append
        (
            "Nv = dt/dpv = " + num(Nv) + " not "
          + (range.NvMax < 0.1*GREAT ? "in " : "")
          + bounds(range.NvMin, range.NvMax)
          + (isErgun ? " (no wall correction)" : "")
        );
    }
    if (eps < range.epsMin || eps > range.epsMax)
    {
        why.append
        (
            "porosity " + num(eps) + " not in "
          + bounds(range.epsMin, range.epsMax)
        );
    }
    if (!range.shapes.found(pelletShape_))
    {
        why.append
        (
            "shape " + pelletShape_ + ", fitted for "
          + inWords(range.shapes) + " pellets"
        );
    }
    else if (!isErgun && shape_ != pelletShape_ + "s")
    {
        why.append
        (
            "the constants of " + shape_ + " for " + pelletShape_
          + " pellets"
        );
    }
    return stringList(std::move(why));
}


Foam::stringList Foam::rbd::pressureDropComparison::outsideRange
(
    const word& correlation
) const
{
    return outside(correlation, porosity_);
}


Foam::dictionary Foam::rbd::pressureDropComparison::sectionResults
(
    const scalar eps,
    const scalar zTop,
    const scalar pTop
) const
{
    const scalar L = zTop - zBottom_;
    const scalar sim = (pBottom_ - pTop)/L;
    dictionary d;
    d.add("porosity", eps);
    d.add("zBottom", zBottom_);
    d.add("zTop", zTop);
    d.add("pTop", pTop);
    d.add("dPdLSimulated", sim);
    d.add("dPdLErgun", ergun(eps));
    d.add("dPdLEisfeldSchnitzlein", eisfeldSchnitzlein(eps));
    d.add("ratioErgun", sim/ergun(eps));
    d.add("ratioEisfeldSchnitzlein", sim/eisfeldSchnitzlein(eps));
    for (const word c : {"ergun", "eisfeldSchnitzlein"})
    {
        const stringList why(outside(c, eps));
        d.add(word(c + "InRange"), Switch(why.empty()));
    }
    return d;
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
    d.add("pelletDiameter", boundingDiameter_);
    d.add("diameterRatio", diameterRatio());
    d.add("volumeEquivalentDiameterRatio", volumeEquivalentDiameterRatio());
    if (meshPorosityMeasured())
    {
        d.add("meshPorosity", meshPorosity_);
    }
    if (packedMeasured())
    {
        dictionary packed
        (
            sectionResults(bulkPorosity_, packedTopHeight(), pPackedTop_)
        );
        if (stlPorosity_ >= 0)
        {
            packed.add("stlPorosity", stlPorosity_);
        }
        if (std::isfinite(packedMeshPorosity_))
        {
            packed.add("meshPorosity", packedMeshPorosity_);
        }
        d.add("packedSection", packed);
    }
    // The whole bed's verdicts, with the reasons
    dictionary ranges;
    for (const word c : {"ergun", "eisfeldSchnitzlein"})
    {
        const stringList why(outside(c, porosity_));
        dictionary r;
        r.add("inRange", Switch(why.empty()));
        if (!why.empty())
        {
            r.add("outside", why);
        }
        ranges.add(c, r);
    }
    d.add("ranges", ranges);
    return d;
}


void Foam::rbd::pressureDropComparison::reportSection
(
    Ostream& os,
    const char* title,
    const char* porosityName,
    const scalar eps,
    const scalar zTop,
    const scalar pTop
) const
{
    const scalar sim = (pBottom_ - pTop)/(zTop - zBottom_);
    os  << "    " << title << ", z from " << zBottom_ << " to " << zTop
        << " m (L = " << zTop - zBottom_ << " m), porosity " << eps
        << " (" << porosityName << ")" << nl
        << "        dP/(rho L) [m/s^2]" << nl
        << "        simulated             " << sim << nl
        << "        Ergun                 " << ergun(eps)
        << "  (simulated/Ergun " << sim/ergun(eps) << ")" << nl
        << "        Eisfeld-Schnitzlein   " << eisfeldSchnitzlein(eps)
        << "  (simulated/E-S " << sim/eisfeldSchnitzlein(eps) << ")" << nl;
    if (rho_ > 0)
    {
        os  << "        dP/L simulated [Pa/m] " << rho_*sim << nl;
    }
}


void Foam::rbd::pressureDropComparison::report(Ostream& os) const
{
    os  << "Pressure drop (" << pelletShape_ << " pellets, Eisfeld-"
        << "Schnitzlein constants of " << shape_ << "; U = " << velocity_
        << " m/s, Re_p = U dpv/nu = " << reynoldsNumber()
        << ", N = dt/dp = " << diameterRatio() << ", Nv = dt/dpv = "
        << volumeEquivalentDiameterRatio() << ")" << nl;
    if (packedMeasured())
    {
        reportSection
        (
            os, "Packed section, without the loose top layer",
            "bulkPorosity of the summary, below porosityHeight",
            bulkPorosity_, packedTopHeight(), pPackedTop_
        );
    }
    else if (hasPackedSection())
    {
        os  << "    Packed section: not measured (the pressure on its top"
            << " plane z = " << packedTopHeight() << " m was not sampled)"
            << nl;
    }
    reportSection
    (
        os, "Whole bed, floor to the top of the highest pellet",
        "bedPorosity of the summary", porosity_, zBottom_ + length_, pTop_
    );

    // What the CFD saw, beside the porosities of the correlations
    if (meshPorosityMeasured())
    {
        if (hasPackedSection() && std::isfinite(packedMeshPorosity_))
        {
            os  << "    Porosity of the packed section: bulkPorosity "
                << bulkPorosity_ << " (exact pellets)";
            if (stlPorosity_ >= 0)
            {
                os  << ", stlPorosity " << stlPorosity_ << " (pellets.stl)";
            }
            os  << ", fluid mesh " << packedMeshPorosity_
                << " (its cell volumes)" << nl;
        }
        os  << "    Porosity of the whole bed: bedPorosity " << porosity_
            << ", fluid mesh " << meshPorosity_ << nl;
    }

    // The verdicts at the porosity of the section given first
    const scalar eps = packedMeasured() ? bulkPorosity_ : porosity_;
    os  << "    Ranges of the correlations at porosity " << eps
        << " (recalled from the papers: correlations.H)" << nl;
    for (const word c : {"ergun", "eisfeldSchnitzlein"})
    {
        const char* name = c == "ergun" ? "Ergun" : "Eisfeld-Schnitzlein";
        const stringList why(outside(c, eps));
        os  << "        " << name << ": ";
        if (why.empty())
        {
            os  << "inside its range" << nl;
        }
        else
        {
            os  << "OUTSIDE its range: ";
            forAll(why, i)
            {
                os  << (i ? "; " : "") << why[i].c_str();
            }
            os  << nl;
        }
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
