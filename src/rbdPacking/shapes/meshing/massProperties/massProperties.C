/*---------------------------------------------------------------------------*\
  rbdPacking: hard-body rigid body dynamics packings for OpenFOAM
\*---------------------------------------------------------------------------*/

#include "massProperties.H"
#include "error.H"

// Eigen's headers use C casts: not our warnings
#pragma GCC diagnostic push
#pragma GCC diagnostic ignored "-Wold-style-cast"
#include <Eigen/Dense>
#pragma GCC diagnostic pop

// * * * * * * * * * * * * * * * Local Functions * * * * * * * * * * * * * //

namespace
{
    using Foam::scalar;
    using Foam::vector;
    using Foam::tensor;

    //- Eberly's subexpressions for one coordinate of a triangle
    struct subexpressions
    {
        scalar f1, f2, f3, g0, g1, g2;

        subexpressions(const scalar w0, const scalar w1, const scalar w2)
        {
            const scalar t0 = w0 + w1;
            f1 = t0 + w2;
            const scalar t1 = w0*w0;
            const scalar t2 = t1 + w1*t0;
            f2 = t2 + w2*f1;
            f3 = w0*t1 + w1*t2 + w2*f2;
            g0 = f2 + w0*(f1 + w0);
            g1 = f2 + w1*(f1 + w1);
            g2 = f2 + w2*(f1 + w2);
        }
    };

    //- Rotation with columns a, b, c
    tensor fromColumns(const vector& a, const vector& b, const vector& c)
    {
        return tensor(a, b, c).T();
    }

    //- Unit vector i of the mesh axes
    vector axis(const int i)
    {
        vector e(Foam::Zero);
        e[i] = 1;
        return e;
    }
}


// * * * * * * * * * * * * * * * * Constructors  * * * * * * * * * * * * * * //

Foam::rbd::massProperties::massProperties
(
    const triMesh& mesh,
    const scalar density
)
:
    density_(density),
    volume_(0),
    centreOfMass_(Zero),
    inertia_(Zero),
    principalMoments_(Zero),
    principalRotation_(tensor::I)
{
    const pointField& pts = mesh.points();

    // Reference point: mean vertex
    const point o = pts.empty() ? point::zero : point(sum(pts)/pts.size());

    // int over V of 1, x, y, z, x^2, y^2, z^2, xy, yz, zx (about o)
    scalar intg[10] = {0, 0, 0, 0, 0, 0, 0, 0, 0, 0};

    for (const triFace& f : mesh.faces())
    {
        const point p0 = pts[f[0]] - o;
        const point p1 = pts[f[1]] - o;
        const point p2 = pts[f[2]] - o;

        const vector d = (p1 - p0) ^ (p2 - p0);

        const subexpressions sx(p0.x(), p1.x(), p2.x());
        const subexpressions sy(p0.y(), p1.y(), p2.y());
        const subexpressions sz(p0.z(), p1.z(), p2.z());

        intg[0] += d.x()*sx.f1;
        intg[1] += d.x()*sx.f2;
        intg[2] += d.y()*sy.f2;
        intg[3] += d.z()*sz.f2;
        intg[4] += d.x()*sx.f3;
        intg[5] += d.y()*sy.f3;
        intg[6] += d.z()*sz.f3;
        intg[7] += d.x()*(p0.y()*sx.g0 + p1.y()*sx.g1 + p2.y()*sx.g2);
        intg[8] += d.y()*(p0.z()*sy.g0 + p1.z()*sy.g1 + p2.z()*sy.g2);
        intg[9] += d.z()*(p0.x()*sz.g0 + p1.x()*sz.g1 + p2.x()*sz.g2);
    }

    const scalar mult[10] =
        {1./6, 1./24, 1./24, 1./24, 1./60, 1./60, 1./60, 1./120, 1./120,
         1./120};
    for (int i = 0; i < 10; ++i)
    {
        intg[i] *= mult[i];
    }

    volume_ = intg[0];

    if (!(volume_ > 0))
    {
        FatalErrorInFunction
            << "Mesh of " << mesh.nFaces() << " triangles encloses volume "
            << volume_ << " m^3: it is not a closed outward mesh"
            << exit(FatalError);
    }

    // Centre of mass relative to o
    const vector c(intg[1]/volume_, intg[2]/volume_, intg[3]/volume_);
    centreOfMass_ = o + c;

    // Inertia about the centre of mass, per unit density
    const scalar V = volume_;
    const symmTensor J
    (
        intg[5] + intg[6] - V*(sqr(c.y()) + sqr(c.z())),
        -(intg[7] - V*c.x()*c.y()),
        -(intg[9] - V*c.z()*c.x()),
        intg[4] + intg[6] - V*(sqr(c.z()) + sqr(c.x())),
        -(intg[8] - V*c.y()*c.z()),
        intg[4] + intg[5] - V*(sqr(c.x()) + sqr(c.y()))
    );
    inertia_ = density_*J;

    principalAxes(inertia_, principalMoments_, principalRotation_);
}


// * * * * * * * * * * * * * * * Static Functions  * * * * * * * * * * * * * //

void Foam::rbd::massProperties::principalAxes
(
    const symmTensor& I,
    vector& moments,
    tensor& Q
)
{
    Eigen::Matrix3d A;
    A <<
        I.xx(), I.xy(), I.xz(),
        I.xy(), I.yy(), I.yz(),
        I.xz(), I.yz(), I.zz();

    const Eigen::SelfAdjointEigenSolver<Eigen::Matrix3d> eig(A);

    // Eigenvalues ascending, eigenvectors as columns
    const Eigen::Vector3d lambda = eig.eigenvalues();
    vector v[3];
    for (int j = 0; j < 3; ++j)
    {
        const Eigen::Vector3d col = eig.eigenvectors().col(j);
        v[j] = vector(col(0), col(1), col(2));
    }

    const scalar tol =
        degenerateTolerance()
       *max(max(mag(lambda(0)), mag(lambda(2))), VSMALL);
    const bool low = lambda(1) - lambda(0) <= tol;
    const bool high = lambda(2) - lambda(1) <= tol;

    scalar bestTrace = -GREAT;
    Q = tensor::I;

    if (lambda(2) - lambda(0) <= tol)
    {
        // Isotropic: any frame is principal; keep the mesh axes
    }
    else if (low || high)
    {
        // One distinct axis u; the other two span the plane normal to u.
        // Put u (either sign) on mesh axis a, the next mesh axis projected
        // onto the plane on b, and c = a x b (cyclic, so det Q = +1).
        const vector& u = low ? v[2] : v[0];

        for (int a = 0; a < 3; ++a)
        {
            for (const scalar s : {1.0, -1.0})
            {
                const int b = (a + 1) % 3;
                const int c = (a + 2) % 3;

                vector cols[3];
                cols[a] = s*u;
                const vector eb = axis(b);
                cols[b] = eb - (eb & cols[a])*cols[a];
                const scalar mb = mag(cols[b]);
                if (mb < 1e-3)
                {
                    continue;
                }
                cols[b] /= mb;
                cols[c] = cols[a] ^ cols[b];

                const scalar tr = cols[0].x() + cols[1].y() + cols[2].z();
                if (tr > bestTrace)
                {
                    bestTrace = tr;
                    Q = fromColumns(cols[0], cols[1], cols[2]);
                }
            }
        }
    }
    else
    {
        // Distinct moments: eigenvector v[perm[i]] (times sign) on mesh
        // axis i, over all permutations and signs with det Q = +1
        const int perms[6][3] =
            {{0, 1, 2}, {0, 2, 1}, {1, 0, 2}, {1, 2, 0}, {2, 0, 1}, {2, 1, 0}};

        for (const auto& p : perms)
        {
            for (int signs = 0; signs < 8; ++signs)
            {
                vector cols[3];
                for (int i = 0; i < 3; ++i)
                {
                    cols[i] = ((signs >> i) & 1 ? -1.0 : 1.0)*v[p[i]];
                }
                if (((cols[0] ^ cols[1]) & cols[2]) < 0)
                {
                    continue;
                }
                const scalar tr = cols[0].x() + cols[1].y() + cols[2].z();
                if (tr > bestTrace)
                {
                    bestTrace = tr;
                    Q = fromColumns(cols[0], cols[1], cols[2]);
                }
            }
        }
    }

    // Moments as Rayleigh quotients of the chosen axes
    const tensor D = Q.T() & tensor(I) & Q;
    moments = vector(D.xx(), D.yy(), D.zz());
}


// * * * * * * * * * * * * * * * Member Functions  * * * * * * * * * * * * * //

Foam::rbd::triMesh Foam::rbd::massProperties::toPrincipalFrame
(
    const triMesh& mesh
) const
{
    const tensor QT = principalRotation_.T();
    return mesh.transformed(QT, -(QT & centreOfMass_));
}


void Foam::rbd::massProperties::writeInfo(Ostream& os) const
{
    os  << "volume " << volume_ << " m^3, mass " << mass()
        << " kg, centre of mass " << centreOfMass_
        << " m, principal moments " << principalMoments_ << " kg m^2";
}


// ************************************************************************* //
