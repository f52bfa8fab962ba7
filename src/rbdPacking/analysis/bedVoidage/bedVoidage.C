/*---------------------------------------------------------------------------*\
  rbdPacking: hard-body rigid body dynamics packings for OpenFOAM
\*---------------------------------------------------------------------------*/

#include "bedVoidage.H"
#include "correlations.H"
#include "error.H"
#include "mathematicalConstants.H"
#include "OFstream.H"
#include "OSspecific.H"

#include <algorithm>
#include <cmath>
#include <sstream>

// * * * * * * * * * * * * * * * Local Functions * * * * * * * * * * * * * * //

namespace
{
    //- A fit statistic for a header line (10 digits): "n/a" where it is
    //  undefined (a profile of one bin has no variance). As const char*:
    //  an Ostream quotes a string
    std::string statistic(const Foam::scalar x)
    {
        if (std::isnan(x))
        {
            return "n/a";
        }
        std::ostringstream os;
        os.precision(10);
        os << x;
        return os.str();
    }

    //- Header line for a tube where Mueller's recalled form does not apply
    std::string muellerNotApplicable(const Foam::scalar N)
    {
        std::ostringstream os;
        os  << "# Mueller: not applicable at N = " << N
            << " (recalled form: N >= 2.61, singular at N = 3.156);"
            << " no column\n";
        return os.str();
    }
}

// * * * * * * * * * * * * * * Static Data Members * * * * * * * * * * * * * //

const Foam::word Foam::rbd::bedVoidage::radialFile("radialPorosity.dat");

const Foam::word Foam::rbd::bedVoidage::axialFile("axialPorosity.dat");

const Foam::word Foam::rbd::bedVoidage::correlationsFile
(
    "radialCorrelations.dat"
);


// * * * * * * * * * * * * * Private Member Functions  * * * * * * * * * * //

void Foam::rbd::bedVoidage::checkBins(const label nBins, const char* what)
{
    if (nBins < 1)
    {
        FatalErrorInFunction
            << what << ": number of bins " << nBins << " is not >= 1"
            << exit(FatalError);
    }
}


// * * * * * * * * * * * * * * * * Constructors  * * * * * * * * * * * * * //

Foam::rbd::bedVoidage::bedVoidage
(
    const solidSet& solids,
    const scalar R,
    const scalar H
)
:
    bedVoidage(solids, R, 0, H)
{}


Foam::rbd::bedVoidage::bedVoidage
(
    const solidSet& solids,
    const scalar R,
    const scalar zLow,
    const scalar zHigh
)
:
    solids_(solids),
    R_(R),
    zLow_(zLow),
    zHigh_(zHigh)
{
    if (!(R_ > 0) || !(zHigh_ > zLow_))
    {
        FatalErrorInFunction
            << "need tube radius > 0 and zHigh > zLow; got R = " << R_
            << " m, z from " << zLow_ << " to " << zHigh_ << " m"
            << exit(FatalError);
    }
}


// * * * * * * * * * * * * * * * Member Functions  * * * * * * * * * * * * //

Foam::scalar Foam::rbd::bedVoidage::bedVolume() const
{
    return constant::mathematical::pi*R_*R_*(zHigh_ - zLow_);
}


Foam::scalar Foam::rbd::bedVoidage::solidVolume() const
{
    scalar V = 0;
    for (label i = 0; i < solids_.size(); ++i)
    {
        V += solids_.volume(i, zLow_, zHigh_);
    }
    return V;
}


Foam::scalar Foam::rbd::bedVoidage::bulkPorosity() const
{
    return 1 - solidVolume()/bedVolume();
}


Foam::scalar Foam::rbd::bedVoidage::solidArea(const scalar r) const
{
    scalar S = 0;
    for (label i = 0; i < solids_.size(); ++i)
    {
        const scalarMinMax rRange(solids_.radialExtent(i));
        const scalarMinMax zRange(solids_.axialExtent(i));
        if
        (
            r > rRange.min() && r < rRange.max()
         && zRange.max() > zLow_ && zRange.min() < zHigh_
        )
        {
            S += solids_.cylinderArea(i, r, zLow_, zHigh_);
        }
    }
    return S;
}


Foam::scalar Foam::rbd::bedVoidage::radialPorosity(const scalar r) const
{
    return
        1
      - solidArea(r)/(constant::mathematical::twoPi*r*(zHigh_ - zLow_));
}


Foam::scalarField Foam::rbd::bedVoidage::radialBinCentres
(
    const label nBins
) const
{
    checkBins(nBins, "radial profile");
    const scalar dr = R_/nBins;
    scalarField r(nBins);
    forAll(r, k)
    {
        r[k] = (k + 0.5)*dr;
    }
    return r;
}


Foam::scalarField Foam::rbd::bedVoidage::radialProfile
(
    const label nBins
) const
{
    const scalarField r(radialBinCentres(nBins));
    const scalar dr = R_/nBins;

    // Each pellet adds to the bins whose centre its radial extent covers
    scalarField S(nBins, Zero);
    for (label i = 0; i < solids_.size(); ++i)
    {
        const scalarMinMax zRange(solids_.axialExtent(i));
        if (!(zRange.max() > zLow_ && zRange.min() < zHigh_))
        {
            continue;
        }
        const scalarMinMax rRange(solids_.radialExtent(i));
        const label kLo =
            std::max(label(std::ceil(rRange.min()/dr - 0.5)), label(0));
        const label kHi =
            std::min(label(std::floor(rRange.max()/dr - 0.5)), nBins - 1);
        for (label k = kLo; k <= kHi; ++k)
        {
            S[k] += solids_.cylinderArea(i, r[k], zLow_, zHigh_);
        }
    }

    scalarField eps(nBins);
    forAll(eps, k)
    {
        eps[k] =
            1 - S[k]/(constant::mathematical::twoPi*r[k]*(zHigh_ - zLow_));
    }
    return eps;
}


Foam::scalarField Foam::rbd::bedVoidage::axialBinCentres
(
    const label nBins
) const
{
    checkBins(nBins, "axial profile");
    const scalar dz = (zHigh_ - zLow_)/nBins;
    scalarField z(nBins);
    forAll(z, k)
    {
        z[k] = zLow_ + (k + 0.5)*dz;
    }
    return z;
}


Foam::scalarField Foam::rbd::bedVoidage::axialProfile
(
    const label nBins
) const
{
    checkBins(nBins, "axial profile");
    const scalar dz = (zHigh_ - zLow_)/nBins;

    // Each pellet adds to the slabs its axial extent meets
    scalarField V(nBins, Zero);
    for (label i = 0; i < solids_.size(); ++i)
    {
        const scalarMinMax zRange(solids_.axialExtent(i));
        const label kLo =
            std::max(label(std::floor((zRange.min() - zLow_)/dz)), label(0));
        const label kHi =
            std::min
            (
                label(std::floor((zRange.max() - zLow_)/dz)),
                nBins - 1
            );
        for (label k = kLo; k <= kHi; ++k)
        {
            V[k] +=
                solids_.volume(i, zLow_ + k*dz, zLow_ + (k + 1)*dz);
        }
    }

    const scalar slabVolume = constant::mathematical::pi*R_*R_*dz;
    scalarField eps(nBins);
    forAll(eps, k)
    {
        eps[k] = 1 - V[k]/slabVolume;
    }
    return eps;
}


void Foam::rbd::bedVoidage::sphereCorrelations
(
    const scalarField& r,
    const scalar dp,
    scalarField& deKlerk,
    scalarField& mueller
) const
{
    const scalarField zWall((R_ - r)/dp);
    const scalar epsBulk = bulkPorosity();
    const scalar N = 2*R_/dp;

    deKlerk = correlations::evaluate
    (
        zWall,
        [epsBulk](scalar z){ return correlations::deKlerk(z, epsBulk); }
    );
    mueller = correlations::evaluate
    (
        zWall,
        [N](scalar z){ return correlations::mueller(z, N); }
    );
}


Foam::dictionary Foam::rbd::bedVoidage::sphereRadialFits
(
    const label nBins,
    const scalar dp
) const
{
    const scalarField eps(radialProfile(nBins));
    scalarField deKlerk, mueller;
    sphereCorrelations(radialBinCentres(nBins), dp, deKlerk, mueller);

    const auto fit = [&eps](const scalarField& ref)
    {
        dictionary d;
        const scalar r2 = correlations::rSquared(eps, ref);
        const scalar e = correlations::rmse(eps, ref);
        if (!std::isnan(r2))
        {
            d.add("rSquared", r2);
        }
        if (!std::isnan(e))
        {
            d.add("rmse", e);
        }
        return d;
    };

    dictionary fits;
    fits.add("deKlerk", fit(deKlerk));
    if (correlations::muellerApplies(2*R_/dp))
    {
        fits.add("mueller", fit(mueller));
    }
    return fits;
}


void Foam::rbd::bedVoidage::writeRadialProfile
(
    Ostream& os,
    const label nBins,
    const scalar dp,
    const scalar dpv,
    const bool sphereCorrelations
) const
{
    const scalarField r(radialBinCentres(nBins));
    const scalarField eps(radialProfile(nBins));
    const scalarField zWall((R_ - r)/dpv);
    const scalar epsBulk = bulkPorosity();
    // The sphere correlations' N: dt/dpv, which is dt/dp for spheres
    const scalar N = 2*R_/dp;
    const scalar Nv = 2*R_/dpv;
    const bool oneDiameter = dp == dpv;
    // Name of the wall-distance column
    const char* zName = oneDiameter ? "(R-r)/dp" : "(R-r)/dpv";

    scalarField deKlerk, mueller;
    if (sphereCorrelations)
    {
        this->sphereCorrelations(r, dpv, deKlerk, mueller);
    }

    const bool withMueller =
        sphereCorrelations && correlations::muellerApplies(Nv);

    const int oldPrecision = os.precision(10);

    os  << "# Radial void fraction, eq 39: eps(r) = 1 - S_int(r)/S_total(r),"
        << " at bin centres" << nl
        << "# tube radius R = " << R_ << " m, z from " << zLow_ << " to "
        << zHigh_ << " m, pellets " << solids_.size() << nl;
    if (oneDiameter)
    {
        os  << "# pellet diameter dp = " << dp << " m, N = dt/dp = " << N
            << nl;
    }
    else
    {
        os  << "# pellet diameter dp = " << dp << " m (bounding), N = dt/dp"
            << " = " << N << "; volume-equivalent diameter dpv = " << dpv
            << " m, Nv = dt/dpv = " << Nv << nl;
    }
    os  << "# bulk porosity " << epsBulk << nl;
    if (sphereCorrelations)
    {
        os  << "# deKlerk: de Klerk 2003 (recalled form), eps_b = bulk"
            << " porosity above; R^2 = "
            << statistic(correlations::rSquared(eps, deKlerk)).c_str()
            << ", RMSE = "
            << statistic(correlations::rmse(eps, deKlerk)).c_str() << nl;
        if (withMueller)
        {
            os  << "# Mueller: Mueller 1992 (recalled form, suspect for"
                << " N < 10: see correlations.H), eps_b = "
                << correlations::muellerBulk(N) << "; R^2 = "
                << statistic(correlations::rSquared(eps, mueller)).c_str()
                << ", RMSE = "
                << statistic(correlations::rmse(eps, mueller)).c_str() << nl
                << "# r [m]  " << zName << " [-]  eps [-]  deKlerk [-]"
                << "  Mueller [-]" << nl;
        }
        else
        {
            os  << muellerNotApplicable(Nv).c_str()
                << "# r [m]  " << zName << " [-]  eps [-]  deKlerk [-]"
                << nl;
        }
    }
    else
    {
        os  << "# r [m]  " << zName << " [-]  eps [-]" << nl;
    }

    forAll(r, k)
    {
        os  << r[k] << ' ' << zWall[k] << ' ' << eps[k];
        if (sphereCorrelations)
        {
            os  << ' ' << deKlerk[k];
        }
        if (withMueller)
        {
            os  << ' ' << mueller[k];
        }
        os  << nl;
    }

    os.precision(oldPrecision);
}


void Foam::rbd::bedVoidage::writeSphereCorrelations
(
    Ostream& os,
    const label nPoints,
    const scalar dp
) const
{
    if (nPoints < 2)
    {
        FatalErrorInFunction
            << "radial correlations: number of points " << nPoints
            << " is not >= 2" << exit(FatalError);
    }
    // From the wall inwards: r = R (1 - k/(nPoints - 1))
    scalarField r(nPoints);
    forAll(r, k)
    {
        r[k] = R_*(1 - scalar(k)/(nPoints - 1));
    }
    scalarField deKlerk, mueller;
    sphereCorrelations(r, dp, deKlerk, mueller);

    const int oldPrecision = os.precision(10);

    os  << "# Radial void fraction correlations for spheres, from the wall"
        << " to the axis" << nl
        << "# tube radius R = " << R_ << " m, dp = " << dp
        << " m, N = dt/dp = " << 2*R_/dp << nl
        << "# deKlerk: de Klerk 2003 (recalled form), eps_b = bulk porosity "
        << bulkPorosity() << " (z from " << zLow_ << " to " << zHigh_
        << " m)" << nl;
    const scalar N = 2*R_/dp;
    const bool withMueller = correlations::muellerApplies(N);
    if (withMueller)
    {
        os  << "# Mueller: Mueller 1992 (recalled form, suspect for N < 10:"
            << " see correlations.H), eps_b = "
            << correlations::muellerBulk(N) << nl
            << "# r [m]  (R-r)/dp [-]  deKlerk [-]  Mueller [-]" << nl;
    }
    else
    {
        os  << muellerNotApplicable(N).c_str()
            << "# r [m]  (R-r)/dp [-]  deKlerk [-]" << nl;
    }

    forAll(r, k)
    {
        os  << r[k] << ' ' << (R_ - r[k])/dp << ' ' << deKlerk[k];
        if (withMueller)
        {
            os  << ' ' << mueller[k];
        }
        os  << nl;
    }

    os.precision(oldPrecision);
}


void Foam::rbd::bedVoidage::writeAxialProfile
(
    Ostream& os,
    const label nBins
) const
{
    const scalarField z(axialBinCentres(nBins));
    const scalarField eps(axialProfile(nBins));

    const int oldPrecision = os.precision(10);

    os  << "# Axial void fraction: 1 - V_solid/V_slab for " << nBins
        << " equal slabs" << nl
        << "# tube radius R = " << R_ << " m, z from " << zLow_ << " to "
        << zHigh_ << " m, pellets " << solids_.size() << nl
        << "# mean void fraction from z = " << zLow_ << " to " << zHigh_
        << " m: " << bulkPorosity() << nl
        << "# z [m] (slab centre)  eps [-]" << nl;

    forAll(z, k)
    {
        os  << z[k] << ' ' << eps[k] << nl;
    }

    os.precision(oldPrecision);
}


void Foam::rbd::bedVoidage::write
(
    const fileName& dir,
    const label nRadialBins,
    const label nAxialBins,
    const scalar dp,
    const scalar dpv,
    const bool sphereCorrelations
) const
{
    mkDir(dir);
    {
        OFstream os(dir/radialFile);
        writeRadialProfile(os, nRadialBins, dp, dpv, sphereCorrelations);
    }
    {
        OFstream os(dir/axialFile);
        writeAxialProfile(os, nAxialBins);
    }
    if (sphereCorrelations)
    {
        OFstream os(dir/correlationsFile);
        writeSphereCorrelations(os, correlationPoints, dpv);
    }
}


// ************************************************************************* //
