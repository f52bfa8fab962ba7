/*---------------------------------------------------------------------------*\
  rbdPacking: hard-body rigid body dynamics packings for OpenFOAM
\*---------------------------------------------------------------------------*/

#include "sphereSolidSet.H"
#include "error.H"
#include "mathematicalConstants.H"
#include "ListOps.H"

#include <algorithm>
#include <cmath>

// * * * * * * * * * * * * * * * Local Functions * * * * * * * * * * * * * //

namespace
{
    using Foam::scalar;

    //- Gauss-Legendre rule of n points on [-1, 1], nodes by Newton's method
    //  on the Legendre polynomial (converges from the Chebyshev-like guess)
    struct gaussLegendre
    {
        static constexpr int n = 16;
        scalar x[n];
        scalar w[n];

        gaussLegendre()
        {
            for (int i = 0; i < n; ++i)
            {
                const scalar pi = Foam::constant::mathematical::pi;
                scalar z = std::cos(pi*(i + 0.75)/(n + 0.5));
                scalar dp = 1;
                for (int iter = 0; iter < 100; ++iter)
                {
                    scalar p1 = 1, p2 = 0;
                    for (int j = 0; j < n; ++j)
                    {
                        const scalar p3 = p2;
                        p2 = p1;
                        p1 = ((2*j + 1)*z*p2 - j*p3)/(j + 1);
                    }
                    dp = n*(z*p1 - p2)/(z*z - 1);
                    const scalar dz = p1/dp;
                    z -= dz;
                    if (std::abs(dz) < 1e-16)
                    {
                        break;
                    }
                }
                x[i] = z;
                w[i] = 2/((1 - z*z)*dp*dp);
            }
        }

        //- Integral of f over [lo, hi]
        template<class Function>
        scalar integrate(const Function& f, const scalar lo, const scalar hi)
        const
        {
            const scalar half = 0.5*(hi - lo);
            const scalar mid = 0.5*(hi + lo);
            scalar sum = 0;
            for (int i = 0; i < n; ++i)
            {
                sum += w[i]*f(mid + half*x[i]);
            }
            return half*sum;
        }
    };

    const gaussLegendre& gauss()
    {
        static const gaussLegendre rule;
        return rule;
    }

    //- Integral of f over [0, pi/2], split at the given interior points
    //  and graded towards pi/2 with the scale s (see the header)
    template<class Function>
    scalar integrateToHalfPi
    (
        const Function& f,
        const scalar s,
        const scalar* extra,
        const int nExtra
    )
    {
        const scalar halfPi = Foam::constant::mathematical::piByTwo;

        // Up to 2 slope breaks and the grading points down from 1e-8
        scalar points[48];
        int nPoints = 0;
        points[nPoints++] = 0;
        points[nPoints++] = halfPi;
        for (int i = 0; i < nExtra; ++i)
        {
            if (extra[i] > 0 && extra[i] < halfPi)
            {
                points[nPoints++] = extra[i];
            }
        }
        for
        (
            scalar d = std::max(s, scalar(1e-8));
            d < halfPi && nPoints < 48;
            d *= 3
        )
        {
            points[nPoints++] = halfPi - d;
        }
        std::sort(points, points + nPoints);

        const gaussLegendre& rule = gauss();
        scalar sum = 0;
        for (int i = 0; i + 1 < nPoints; ++i)
        {
            if (points[i + 1] > points[i])
            {
                sum += rule.integrate(f, points[i], points[i + 1]);
            }
        }
        return sum;
    }
}


// * * * * * * * * * * * * * * * * Constructors  * * * * * * * * * * * * * //

Foam::rbd::sphereSolidSet::sphereSolidSet
(
    const UList<point>& centres,
    const scalar radius
)
:
    centres_(centres),
    radius_(radius)
{
    if (!(radius_ > 0))
    {
        FatalErrorInFunction
            << "sphere radius " << radius_ << " m is not > 0"
            << exit(FatalError);
    }
}


// * * * * * * * * * * * * * * * Member Functions  * * * * * * * * * * * * //

Foam::scalarMinMax Foam::rbd::sphereSolidSet::axialExtent
(
    const label i
) const
{
    const scalar cz = centres_[i].z();
    return scalarMinMax(cz - radius_, cz + radius_);
}


Foam::scalarMinMax Foam::rbd::sphereSolidSet::radialExtent
(
    const label i
) const
{
    const point& c = centres_[i];
    const scalar rho = std::hypot(c.x(), c.y());
    return scalarMinMax(std::max(rho - radius_, scalar(0)), rho + radius_);
}


Foam::scalar Foam::rbd::sphereSolidSet::volume
(
    const label i,
    const scalar zLow,
    const scalar zHigh
) const
{
    const scalar a = radius_;
    const scalar cz = centres_[i].z();
    const scalar t0 = std::max(zLow - cz, -a);
    const scalar t1 = std::min(zHigh - cz, a);
    if (!(t1 > t0))
    {
        return 0;
    }
    const scalar a2 = a*a;
    return
        constant::mathematical::pi
       *((a2*t1 - t1*t1*t1/3) - (a2*t0 - t0*t0*t0/3));
}


Foam::scalar Foam::rbd::sphereSolidSet::cylinderArea
(
    const label i,
    const scalar r,
    const scalar zLow,
    const scalar zHigh
) const
{
    const scalar a = radius_;
    const point& c = centres_[i];

    // Room for the chord above and below the centre
    const scalar tTop = zHigh - c.z();
    const scalar tBot = c.z() - zLow;
    if (!(r > 0) || tTop <= -a || tBot <= -a)
    {
        return 0;
    }

    const scalar rho = std::hypot(c.x(), c.y());
    const scalar hMax2 = a*a - (r - rho)*(r - rho);
    if (!(hMax2 > 0))
    {
        return 0;
    }
    const scalar hMax = std::sqrt(hMax2);

    // Clipped chord length
    auto L = [tTop, tBot](const scalar h)
    {
        return std::max(scalar(0), std::min(h, tTop) + std::min(h, tBot));
    };

    // Sphere (nearly) on the axis or cylinder (nearly) on the axis: the
    // chord is the same all around (relative variation < 1e-15)
    const scalar fourRRho = 4*r*rho;
    if (fourRRho <= 1e-15*hMax2)
    {
        return constant::mathematical::twoPi*r*L(hMax);
    }

    // k^2 - 1 = ((r + rho)^2 - a^2)/hMax^2, formed without cancellation
    const scalar km1 = ((r + rho)*(r + rho) - a*a)/hMax2;
    const scalar s = std::sqrt(std::abs(km1));

    // Chord lengths at which L changes slope
    const scalar hBreak[2] = {std::abs(tTop), std::abs(tBot)};
    scalar angles[2];

    scalar integral = 0;
    if (km1 > 0)
    {
        // An arc: variable w, h = hMax cos w
        for (int j = 0; j < 2; ++j)
        {
            angles[j] =
                hBreak[j] < hMax ? std::acos(hBreak[j]/hMax) : scalar(-1);
        }
        auto f = [&](const scalar w)
        {
            const scalar cw = std::cos(w);
            return L(hMax*cw)*cw/std::sqrt(km1 + cw*cw);
        };
        integral = integrateToHalfPi(f, s, angles, 2);
    }
    else
    {
        // The whole circle: variable u, h^2 = hMax^2 - 4 r rho sin^2 u
        const scalar d = -km1;   // 1 - k^2 >= 0
        for (int j = 0; j < 2; ++j)
        {
            const scalar sin2 = (hMax2 - sqr(hBreak[j]))/fourRRho;
            angles[j] =
                (sin2 > 0 && sin2 < 1)
              ? std::asin(std::sqrt(sin2))
              : scalar(-1);
        }
        auto f = [&](const scalar u)
        {
            const scalar cu = std::cos(u);
            const scalar su = std::sin(u);
            return L(hMax*std::sqrt(cu*cu + d*su*su));
        };
        integral = integrateToHalfPi(f, s, angles, 2);
    }

    return 4*r*integral;
}


Foam::labelList Foam::rbd::sphereSolidSet::contactCounts
(
    const scalar gap
) const
{
    const label n = centres_.size();
    const scalar reach = 2*radius_ + gap;
    const scalar reach2 = reach*reach;

    // Sweep along z: only spheres within reach in z can touch
    scalarField z(n);
    forAll(centres_, i)
    {
        z[i] = centres_[i].z();
    }
    const labelList order(sortedOrder(z));

    labelList counts(n, Zero);
    for (label p = 0; p < n; ++p)
    {
        const label i = order[p];
        for (label q = p + 1; q < n; ++q)
        {
            const label j = order[q];
            if (z[j] - z[i] > reach)
            {
                break;
            }
            if (magSqr(centres_[j] - centres_[i]) <= reach2)
            {
                ++counts[i];
                ++counts[j];
            }
        }
    }
    return counts;
}


Foam::scalar Foam::rbd::sphereSolidSet::meanCoordinationNumber
(
    const scalar gap,
    const scalar zLow,
    const scalar zHigh
) const
{
    const labelList counts(contactCounts(gap));
    label sum = 0;
    label n = 0;
    forAll(centres_, i)
    {
        const scalar z = centres_[i].z();
        if (z >= zLow && z <= zHigh)
        {
            sum += counts[i];
            ++n;
        }
    }
    return n ? scalar(sum)/n : scalar(0);
}


// ************************************************************************* //
