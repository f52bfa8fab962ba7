/*---------------------------------------------------------------------------*\
  rbdPacking: hard-body rigid body dynamics packings for OpenFOAM
\*---------------------------------------------------------------------------*/

#include "bedOutput.H"
#include "OFstream.H"
#include "OSspecific.H"
#include "IOobject.H"
#include "sphereSolidSet.H"
#include "bedVoidage.H"
#include "meshSolidSet.H"
#include "orientationStatistics.H"
#include "contactGeometry.H"
#include "stlIO.H"

// * * * * * * * * * * * * * * Static Data Members * * * * * * * * * * * * * //

const Foam::fileName Foam::rbd::bedOutput::directoryName
(
    "postProcessing/rbdPackBed"
);

const Foam::fileName Foam::rbd::bedOutput::stlName
(
    "constant/triSurface/pellets.stl"
);

const Foam::word Foam::rbd::bedOutput::pelletsName("pellets.csv");

const Foam::word Foam::rbd::bedOutput::summaryName("summary");


// * * * * * * * * * * * * * Static Member Functions * * * * * * * * * * * * //

Foam::fileNameList Foam::rbd::bedOutput::files()
{
    fileNameList names
    ({
        stlName,
        directoryName/pelletsName,
        directoryName/summaryName,
        directoryName/orientationStatistics::file
    });
    for (const word& f : bedVoidage::files())
    {
        names.append(directoryName/f);
    }
    return names;
}


// * * * * * * * * * * * * * * * * Constructors  * * * * * * * * * * * * * * //

Foam::rbd::bedOutput::bedOutput
(
    const fileName& casePath,
    const tube& container,
    const pelletShape& shape,
    const UList<rigidBody>& bodies
)
:
    dir_(casePath/directoryName),
    stl_(casePath/stlName),
    tube_(container),
    shape_(shape),
    bodies_(bodies)
{}


// * * * * * * * * * * * * * * * Member Functions  * * * * * * * * * * * * * //

void Foam::rbd::bedOutput::commit(const fileName& tmp, const fileName& target)
{
    // Foam::mv moves a file into a directory of the target's name and
    // reports success: the target would never be written
    if (Foam::isDir(target) || !Foam::mv(tmp, target))
    {
        FatalErrorInFunction
            << "Cannot move " << tmp << " to " << target
            << exit(FatalError);
    }
}


void Foam::rbd::bedOutput::writePellets() const
{
    mkDir(dir_);
    const fileName target(dir_/pelletsName);
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
    pointField centres(bodies_.size());
    tensorField rotations(bodies_.size());
    forAll(bodies_, i)
    {
        centres[i] = bodies_[i].x();
        rotations[i] = bodies_[i].R();
    }
    autoPtr<solidSet> solids;
    if (shape_.isSphere())
    {
        solids.reset(new sphereSolidSet(centres, 0.5*shape_.diameter()));
    }
    else
    {
        solids.reset(new meshSolidSet(shape_.mesh(), centres, rotations));
    }
    const bedVoidage voidage(solids(), tube_.radius(), H);

    mkDir(dir_);
    voidage.write
    (
        dir_, radialBins, axialBins, shape_.volumeEquivalentDiameter(),
        shape_.isSphere()
    );

    dictionary analysis;
    analysis.add("bulkPorosity", voidage.bulkPorosity());
    if (shape_.isSphere())
    {
        analysis.add
        (
            "radialCorrelations",
            voidage.sphereRadialFits(radialBins, shape_.diameter())
        );
    }
    return analysis;
}


void Foam::rbd::bedOutput::writeSTL
(
    const bool binary,
    const scalar scale
) const
{
    if (!(scale > 0))
    {
        FatalErrorInFunction
            << "Pellet scale must be > 0, not " << scale << exit(FatalError);
    }
    // Body frame: the centre of mass at the origin
    triMesh body(shape_.mesh());
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


Foam::List<Foam::rbd::triMesh> Foam::rbd::bedOutput::pelletSurfaces
(
    const bedCaseSettings& settings,
    const UList<contact>& contacts,
    label& nTreated
) const
{
    const word& treatment = settings.contactTreatment();
    triMesh body(shape_.mesh());
    if (settings.pelletScale() != 1)
    {
        body.scale(settings.pelletScale());
    }

    DynamicList<triMesh> surfaces(bodies_.size());
    for (const rigidBody& b : bodies_)
    {
        surfaces.append(body.transformed(b.R(), b.x()));
    }

    nTreated = 0;
    if (treatment == "bridges" || treatment == "caps")
    {
        const scalar spacing =
            treatment == "bridges"
          ? settings.bridgeDiameter()
          : 2*std::sqrt(settings.capHeight()*shape_.diameter());
        const List<contact> touching
        (
            contactGeometry::touching
            (
                contacts, settings.contactGap(), spacing
            )
        );
        nTreated = touching.size();

        // Bridges: about 16 sides, faces from the cylinder generator
        for (const contact& c : touching)
        {
            if (c.i < 0 || c.i >= bodies_.size() || c.k >= bodies_.size())
            {
                FatalErrorInFunction
                    << "Contact of pellets " << c.i << " and " << c.k
                    << " for a bed of " << bodies_.size() << " pellets"
                    << exit(FatalError);
            }
            if (treatment == "bridges")
            {
                surfaces.append
                (
                    contactGeometry::bridge(c, settings.bridgeDiameter(), 200)
                );
            }
            else
            {
                surfaces[c.i] = contactGeometry::cap
                (
                    surfaces[c.i], c.p, c.n, settings.capHeight()
                );
                if (c.k >= 0)
                {
                    surfaces[c.k] = contactGeometry::cap
                    (
                        surfaces[c.k], c.p, -c.n, settings.capHeight()
                    );
                }
            }
        }
    }
    return List<triMesh>(std::move(surfaces));
}


Foam::label Foam::rbd::bedOutput::writeSTL
(
    const bedCaseSettings& settings,
    const UList<contact>& contacts
) const
{
    label nTreated = 0;
    const List<triMesh> surfaces(pelletSurfaces(settings, contacts, nTreated));

    mkDir(stl_.path());
    const fileName tmp(stl_ + ".tmp");
    {
        stlWriter writer(tmp, settings.binarySTL(), "pellets");
        for (const triMesh& m : surfaces)
        {
            writer.write(m);
        }
    }
    commit(tmp, stl_);
    return nTreated;
}


void Foam::rbd::bedOutput::writeOrientation
(
    const scalar H,
    const label nBins,
    dictionary& summary
) const
{
    if (!shape_.hasSymmetryAxis())
    {
        return;
    }
    pointField centres(bodies_.size());
    tensorField rotations(bodies_.size());
    forAll(bodies_, i)
    {
        centres[i] = bodies_[i].x();
        rotations[i] = bodies_[i].R();
    }
    const orientationStatistics stats(centres, rotations, -GREAT, H);
    stats.write(dir_, nBins);
    stats.addTo(summary);
}


void Foam::rbd::bedOutput::writeSummary(const dictionary& summary) const
{
    mkDir(dir_);
    const fileName target(dir_/summaryName);
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
