/*---------------------------------------------------------------------------*\
  rbdPacking: hard-body rigid body dynamics packings for OpenFOAM
\*---------------------------------------------------------------------------*/

#include "bedOutput.H"
#include "OFstream.H"
#include "OSspecific.H"
#include "IOobject.H"
#include "sphereSolidSet.H"
#include "bedVoidage.H"
#include "pelletMeshes.H"
#include "stlIO.H"

// * * * * * * * * * * * * * * * * Constructors  * * * * * * * * * * * * * * //

Foam::rbd::bedOutput::bedOutput
(
    const fileName& casePath,
    const tube& container,
    const pelletShape& shape,
    const UList<rigidBody>& bodies
)
:
    dir_(casePath/"postProcessing"/"rbdPackBed"),
    stl_(casePath/"constant"/"triSurface"/"pellets.stl"),
    tube_(container),
    shape_(shape),
    bodies_(bodies)
{}


// * * * * * * * * * * * * * * * Member Functions  * * * * * * * * * * * * * //

void Foam::rbd::bedOutput::commit(const fileName& tmp, const fileName& target)
{
    if (!Foam::mv(tmp, target))
    {
        FatalErrorInFunction
            << "Cannot move " << tmp << " to " << target
            << exit(FatalError);
    }
}


void Foam::rbd::bedOutput::writePellets() const
{
    mkDir(dir_);
    const fileName target(dir_/"pellets.csv");
    const fileName tmp(target + ".tmp");
    {
        OFstream os(tmp);
        os.precision(12);
        os  << "id,shape,x,y,z,qw,qx,qy,qz" << nl;
        forAll(bodies_, i)
        {
            const point& x = bodies_[i].x();
            const quaternion& q = bodies_[i].q();
            os  << i << ',' << shape_.type() << ','
                << x.x() << ',' << x.y() << ',' << x.z() << ','
                << q.w() << ',' << q.v().x() << ',' << q.v().y() << ','
                << q.v().z() << nl;
        }
    }
    commit(tmp, target);
}


Foam::dictionary Foam::rbd::bedOutput::writeProfiles
(
    const scalar H,
    const label radialBins,
    const label axialBins
) const
{
    if (!shape_.isSphere())
    {
        FatalErrorInFunction
            << "Porosity profiles of '" << shape_.type() << "' pellets are "
            << "not implemented yet" << exit(FatalError);
    }

    pointField centres(bodies_.size());
    forAll(bodies_, i)
    {
        centres[i] = bodies_[i].x();
    }
    const sphereSolidSet spheres(centres, 0.5*shape_.diameter());
    const bedVoidage voidage(spheres, tube_.radius(), H);

    mkDir(dir_);
    voidage.write(dir_, radialBins, axialBins, shape_.diameter(), true);

    dictionary analysis;
    analysis.add("bulkPorosity", voidage.bulkPorosity());
    analysis.add
    (
        "radialCorrelations",
        voidage.sphereRadialFits(radialBins, shape_.diameter())
    );
    return analysis;
}


void Foam::rbd::bedOutput::writeSTL
(
    const bool binary,
    const scalar scale
) const
{
    if (!shape_.isSphere())
    {
        FatalErrorInFunction
            << "STL output of '" << shape_.type() << "' pellets is not "
            << "implemented yet" << exit(FatalError);
    }
    if (!(scale > 0))
    {
        FatalErrorInFunction
            << "Pellet scale must be > 0, not " << scale << exit(FatalError);
    }
    // Body frame: the centre of mass at the origin
    triMesh body(pelletMeshes::sphere(shape_.diameter(), shape_.faces()));
    if (scale != 1)
    {
        body.scale(scale);
    }

    mkDir(stl_.path());
    const fileName tmp(stl_ + ".tmp");
    {
        stlWriter writer(tmp, binary, "pellets");
        for (const rigidBody& b : bodies_)
        {
            writer.write(body.transformed(b.R(), b.x()));
        }
    }
    commit(tmp, stl_);
}


void Foam::rbd::bedOutput::writeSummary(const dictionary& summary) const
{
    mkDir(dir_);
    const fileName target(dir_/"summary");
    const fileName tmp(target + ".tmp");
    {
        OFstream os(tmp);
        IOobject::writeBanner(os);
        os.beginBlock("FoamFile");
        os.writeEntry("version", 2.0);
        os.writeEntry("format", word("ascii"));
        os.writeEntry("class", word("dictionary"));
        os.writeEntry("location", fileName("postProcessing/rbdPackBed"));
        os.writeEntry("object", word("summary"));
        os.endBlock();
        IOobject::writeDivider(os);
        os  << nl;
        summary.write(os, false);
        IOobject::writeEndDivider(os);
    }
    commit(tmp, target);
}


// ************************************************************************* //
