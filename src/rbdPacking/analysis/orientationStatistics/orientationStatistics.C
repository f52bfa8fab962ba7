/*---------------------------------------------------------------------------*\
  rbdPacking: hard-body rigid body dynamics packings for OpenFOAM
\*---------------------------------------------------------------------------*/

#include "orientationStatistics.H"
#include "error.H"
#include "OFstream.H"
#include "OSspecific.H"
#include "mathematicalConstants.H"
#include "unitConversion.H"

using Foam::constant::mathematical::pi;

// * * * * * * * * * * * * * * Static Data Members * * * * * * * * * * * * * //

const Foam::word Foam::rbd::orientationStatistics::file("orientation.dat");

// * * * * * * * * * * * * * * * * Constructors  * * * * * * * * * * * * * //

Foam::rbd::orientationStatistics::orientationStatistics
(
    const UList<point>& centres,
    const UList<tensor>& rotations,
    const scalar zLow,
    const scalar zHigh
)
:
    theta_()
{
    if (centres.size() != rotations.size())
    {
        FatalErrorInFunction
            << centres.size() << " centres but " << rotations.size()
            << " rotations" << exit(FatalError);
    }
    DynamicList<scalar> theta(centres.size());
    forAll(centres, i)
    {
        const scalar z = centres[i].z();
        if (z >= zLow && z <= zHigh)
        {
            // z component of R e_z, clipped against round-off
            const scalar c = min(mag(rotations[i].zz()), scalar(1));
            theta.append(std::acos(c));
        }
    }
    theta_.transfer(theta);
}


// * * * * * * * * * * * * * * * Member Functions  * * * * * * * * * * * * //

Foam::scalar Foam::rbd::orientationStatistics::meanAngle() const
{
    return theta_.empty() ? 0 : radToDeg(average(theta_));
}


Foam::scalar Foam::rbd::orientationStatistics::stdDevAngle() const
{
    if (theta_.size() < 2)
    {
        return 0;
    }
    const scalar m = average(theta_);
    return radToDeg(std::sqrt(sum(sqr(theta_ - m))/(theta_.size() - 1)));
}


Foam::scalar Foam::rbd::orientationStatistics::meanCos2() const
{
    return theta_.empty() ? 0 : average(sqr(cos(theta_)));
}


Foam::labelList Foam::rbd::orientationStatistics::histogram
(
    const label nBins
) const
{
    if (nBins < 1)
    {
        FatalErrorInFunction
            << "nBins must be >= 1, not " << nBins << exit(FatalError);
    }
    labelList counts(nBins, Zero);
    for (const scalar t : theta_)
    {
        const label k = min(label(t/(0.5*pi)*nBins), nBins - 1);
        ++counts[max(k, label(0))];
    }
    return counts;
}


void Foam::rbd::orientationStatistics::write
(
    Ostream& os,
    const label nBins
) const
{
    const labelList counts(histogram(nBins));
    os  << "# Pellet axis angle to the tube axis, theta in [0, 90] deg"
        << nl
        << "# pellets " << size() << ", mean " << meanAngle()
        << " deg, std dev " << stdDevAngle() << " deg, <cos^2> "
        << meanCos2() << ", order parameter S " << orderParameter() << nl
        << "# isotropic axes: mean 57.2958 deg, <cos^2> 1/3, S 0" << nl
        << "# thetaLow [deg]  thetaHigh [deg]  count  fraction  isotropic"
        << nl;
    forAll(counts, k)
    {
        const scalar t1 = 90.0*k/nBins;
        const scalar t2 = 90.0*(k + 1)/nBins;
        os  << t1 << ' ' << t2 << ' ' << counts[k] << ' '
            << (size() ? scalar(counts[k])/size() : 0) << ' '
            << std::cos(degToRad(t1)) - std::cos(degToRad(t2)) << nl;
    }
}


void Foam::rbd::orientationStatistics::write
(
    const fileName& dir,
    const label nBins
) const
{
    mkDir(dir);
    OFstream os(dir/file);
    write(os, nBins);
}


void Foam::rbd::orientationStatistics::addTo(dictionary& summary) const
{
    summary.add("orientedPellets", size());
    summary.add("meanAxisAngle", meanAngle());
    summary.add("stdDevAxisAngle", stdDevAngle());
    summary.add("axisOrderParameter", orderParameter());
}


// ************************************************************************* //
