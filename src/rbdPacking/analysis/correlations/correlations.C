/*---------------------------------------------------------------------------*\
  rbdPacking: hard-body rigid body dynamics packings for OpenFOAM
\*---------------------------------------------------------------------------*/

#include "correlations.H"
#include "DynamicList.H"
#include "error.H"
#include "mathematicalConstants.H"

#include <cmath>
#include <limits>

// * * * * * * * * * * * * * * * Local Functions * * * * * * * * * * * * * //

namespace
{
    const Foam::scalar notANumber =
        std::numeric_limits<Foam::scalar>::quiet_NaN();

    Foam::scalar sqr(const Foam::scalar x)
    {
        return x*x;
    }
}


// * * * * * * * * * * * * * * * * Pellet size * * * * * * * * * * * * * * //

Foam::scalar Foam::rbd::correlations::dpv(const scalar V)
{
    return std::cbrt(6*V/constant::mathematical::pi);
}


Foam::scalar Foam::rbd::correlations::sphericity
(
    const scalar V,
    const scalar A
)
{
    return
        std::cbrt(constant::mathematical::pi)*std::pow(6*V, 2.0/3.0)/A;
}


// * * * * * * * * * * * * * * * Bulk porosity * * * * * * * * * * * * * * //

Foam::scalar Foam::rbd::correlations::dixonSpheres(const scalar N)
{
    return 0.4 + 0.05/N + 0.412/sqr(N);
}


Foam::scalar Foam::rbd::correlations::dixonCylinders(const scalar N)
{
    // RECALLED form (docs/method.md, section 14): check against Dixon 1988
    return 0.36 + 0.10/N + 0.7/sqr(N);
}


Foam::scalar Foam::rbd::correlations::foumenySpheres(const scalar N)
{
    const scalar s = 0.723*N - 1;
    if (!(s > 0))
    {
        return notANumber;
    }
    return 0.383 + 0.254*std::pow(N, -0.923)/std::sqrt(s);
}


Foam::scalar Foam::rbd::correlations::benyahiaONeillSpheres(const scalar N)
{
    return 0.390 + 1.740/sqr(N + 1.140);
}


Foam::scalar Foam::rbd::correlations::benyahiaONeillCylinders
(
    const scalar N
)
{
    return 0.373 + 1.703/sqr(N + 0.611);
}


Foam::scalar Foam::rbd::correlations::benyahiaONeill
(
    const scalar N,
    const scalar phi
)
{
    return 0.1504 + 0.2024/phi + 1.0814/sqr(N + 0.1226);
}


Foam::rbd::correlations::pelletFamily Foam::rbd::correlations::familyOf
(
    const word& shapeType
)
{
    if (shapeType == "sphere")
    {
        return pelletFamily::sphere;
    }
    if (shapeType == "cylinder")
    {
        return pelletFamily::cylinder;
    }
    return pelletFamily::other;
}


Foam::List<Foam::Tuple2<Foam::word, Foam::scalar>>
Foam::rbd::correlations::bulkPorosities
(
    const pelletFamily family,
    const scalar N,
    const scalar phi
)
{
    DynamicList<Tuple2<word, scalar>> values(4);
    const auto add = [&values](const word& name, const scalar eps)
    {
        if (!std::isnan(eps))
        {
            values.append(Tuple2<word, scalar>(name, eps));
        }
    };

    switch (family)
    {
        case pelletFamily::sphere:
            add("dixon", dixonSpheres(N));
            add("foumeny", foumenySpheres(N));
            add("benyahiaONeill", benyahiaONeillSpheres(N));
            break;
        case pelletFamily::cylinder:
            add("dixon", dixonCylinders(N));
            add("benyahiaONeill", benyahiaONeillCylinders(N));
            break;
        case pelletFamily::other:
            break;
    }
    add("benyahiaONeillAnyShape", benyahiaONeill(N, phi));

    return List<Tuple2<word, scalar>>(std::move(values));
}


// * * * * * * * * * * * * * Radial void fraction * * * * * * * * * * * * * //

Foam::scalar Foam::rbd::correlations::deKlerk
(
    const scalar z,
    const scalar epsBulk
)
{
    // RECALLED form (docs/method.md, section 14): check against de Klerk 2003
    if (z <= 0.637)
    {
        return 2.14*sqr(z) - 2.53*z + 1;
    }
    const scalar pi = constant::mathematical::pi;
    return
        epsBulk
      + 0.29*std::exp(-0.6*z)*std::cos(2.3*pi*(z - 0.16))
      + 0.15*std::exp(-0.9*z);
}


Foam::scalar Foam::rbd::correlations::muellerBulk(const scalar N)
{
    return 0.365 + 0.220/N;
}


bool Foam::rbd::correlations::muellerApplies(const scalar N)
{
    return N >= 2.61 && std::abs(N - 3.156) >= 0.1;
}


Foam::scalar Foam::rbd::correlations::mueller(const scalar z, const scalar N)
{
    // RECALLED form (docs/method.md, section 14): check against Mueller 1992
    if (!muellerApplies(N))
    {
        return notANumber;
    }
    const scalar a =
        N <= 13
      ? 8.243 - 12.98/(N - 3.156)
      : 7.383 - 2.932/(N - 9.864);
    const scalar b = 0.304 - 0.724/N;
    const scalar epsB = muellerBulk(N);

    // J0 is even; std::cyl_bessel_j rejects negative arguments (a < 0 for
    // 3.156 < N < 4.73)
    return
        epsB
      + (1 - epsB)*std::cyl_bessel_j(0.0, std::abs(a*z))*std::exp(-b*z);
}


// * * * * * * * * * * * * * * * Pressure drop * * * * * * * * * * * * * * //

Foam::scalar Foam::rbd::correlations::ergun
(
    const scalar mu,
    const scalar rho,
    const scalar U,
    const scalar eps,
    const scalar dp
)
{
    const scalar eps3 = eps*eps*eps;
    return
        150*mu*sqr(1 - eps)*U/(eps3*sqr(dp))
      + 1.75*rho*(1 - eps)*sqr(U)/(eps3*dp);
}


Foam::scalar Foam::rbd::correlations::eisfeldSchnitzlein
(
    const scalar mu,
    const scalar rho,
    const scalar U,
    const scalar eps,
    const scalar dp,
    const scalar dt,
    const eisfeldSchnitzleinShape shape
)
{
    // RECALLED form and constants (docs/method.md, section 14)
    const bool sphere = (shape == eisfeldSchnitzleinShape::sphere);
    const scalar K1 = sphere ? 154 : 190;
    const scalar k1 = sphere ? 1.15 : 2.00;
    const scalar k2 = sphere ? 0.87 : 0.77;

    const scalar A = 1 + 2/(3*(dt/dp)*(1 - eps));
    const scalar B = sqr(k1*sqr(dp/dt) + k2);
    const scalar eps3 = eps*eps*eps;

    return
        K1*sqr(A)*mu*sqr(1 - eps)*U/(eps3*sqr(dp))
      + A*rho*(1 - eps)*sqr(U)/(B*eps3*dp);
}


// * * * * * * * * * * * * * * * Fit statistics * * * * * * * * * * * * * * //

namespace
{
    void checkSizes
    (
        const Foam::UList<Foam::scalar>& y,
        const Foam::UList<Foam::scalar>& yRef,
        const char* caller
    )
    {
        if (y.size() != yRef.size())
        {
            FatalErrorInFunction
                << caller << ": profile and reference differ in size ("
                << y.size() << " and " << yRef.size() << ')'
                << Foam::exit(Foam::FatalError);
        }
    }

    Foam::scalar sumSqrDiff
    (
        const Foam::UList<Foam::scalar>& y,
        const Foam::UList<Foam::scalar>& yRef
    )
    {
        Foam::scalar s = 0;
        forAll(y, i)
        {
            s += sqr(y[i] - yRef[i]);
        }
        return s;
    }
}


Foam::scalar Foam::rbd::correlations::rSquared
(
    const UList<scalar>& y,
    const UList<scalar>& yRef
)
{
    checkSizes(y, yRef, "rSquared");
    if (y.empty())
    {
        return notANumber;
    }

    scalar mean = 0;
    for (const scalar v : y)
    {
        mean += v;
    }
    mean /= y.size();

    scalar ssTot = 0;
    for (const scalar v : y)
    {
        ssTot += sqr(v - mean);
    }
    if (!(ssTot > 0))
    {
        return notANumber;
    }

    return 1 - sumSqrDiff(y, yRef)/ssTot;
}


Foam::scalar Foam::rbd::correlations::rmse
(
    const UList<scalar>& y,
    const UList<scalar>& yRef
)
{
    checkSizes(y, yRef, "rmse");
    if (y.empty())
    {
        return notANumber;
    }
    return std::sqrt(sumSqrDiff(y, yRef)/y.size());
}


Foam::scalarField Foam::rbd::correlations::evaluate
(
    const UList<scalar>& x,
    const std::function<scalar(scalar)>& f
)
{
    scalarField values(x.size());
    forAll(x, i)
    {
        values[i] = f(x[i]);
    }
    return values;
}


Foam::rbd::correlations::pressureDropRange
Foam::rbd::correlations::ergunRange()
{
    return pressureDropRange
    {
        0, 2500, true,
        10, GREAT,
        0, 1,
        wordList({"sphere"})
    };
}


Foam::rbd::correlations::pressureDropRange
Foam::rbd::correlations::eisfeldSchnitzleinRange()
{
    return pressureDropRange
    {
        0.01, 17635, false,
        1.624, 250,
        0.330, 0.882,
        wordList({"sphere", "cylinder"})
    };
}


// ************************************************************************* //
