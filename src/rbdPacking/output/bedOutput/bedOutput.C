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
#include "scaledSolidSet.H"
#include "orientationStatistics.H"
#include "contactGeometry.H"
#include "stlIO.H"
#include "OStringStream.H"
#include "mathematicalConstants.H"

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


const Foam::string Foam::rbd::bedOutput::pelletsHeader
(
    "id,shape,x,y,z,qw,qx,qy,qz"
);

const Foam::word Foam::rbd::bedOutput::summaryName("summary");


// * * * * * * * * * * * * * Static Member Functions * * * * * * * * * * * * //

Foam::scalar Foam::rbd::bedOutput::bedTop
(
    const pelletShape& shape,
    const UList<rigidBody>& bodies
)
{
    scalar top = 0;
    for (const rigidBody& b : bodies)
    {
        top = max(top, b.x().z() + shape.boundingRadius());
    }
    return top;
}


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
        os  << pelletsHeader.c_str() << nl;
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
    // Spheres exact; other pellets: their mesh's volumes and areas scaled
    // to the exact volume (whole pellets exact, cut ones the mesh's
    // fraction of it: scaledSolidSet)
    autoPtr<solidSet> polyhedra;
    autoPtr<solidSet> solids;
    if (shape_.isSphere())
    {
        solids.reset(new sphereSolidSet(centres, 0.5*shape_.diameter()));
    }
    else
    {
        polyhedra.reset(new meshSolidSet(shape_.mesh(), centres, rotations));
        solids.reset
        (
            new scaledSolidSet
            (
                polyhedra(), shape_.exactVolume()/shape_.mesh().volume()
            )
        );
    }
    // Bulk porosity and radial profile below H; the axial profile from
    // the floor to the bed top (the top of the highest pellet, as
    // packedBed::bedHeight), the loose top layer included
    const bedVoidage voidage(solids(), tube_.radius(), H);
    const bedVoidage wholeBed
    (
        solids(), tube_.radius(), max(H, bedTop(shape_, bodies_))
    );

    mkDir(dir_);
    {
        OFstream os(dir_/bedVoidage::radialFile);
        voidage.writeRadialProfile
        (
            os, radialBins, shape_.diameter(),
            shape_.volumeEquivalentDiameter(), shape_.isSphere()
        );
    }
    {
        OFstream os(dir_/bedVoidage::axialFile);
        wholeBed.writeAxialProfile(os, axialBins);
    }
    if (shape_.isSphere())
    {
        OFstream os(dir_/bedVoidage::correlationsFile);
        voidage.writeSphereCorrelations
        (
            os, bedVoidage::correlationPoints, shape_.diameter()
        );
    }

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
    triMesh body(shape_.volumeTrueMesh());
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
    triMesh body(shape_.volumeTrueMesh());
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

        // Caps at the wall for pellets that reach it without a touching
        // contact: the written solids stand out of the true surface (the
        // volume-true facets, up to about 2 % of r at a coarse rim), so a
        // rim 0.01-0.02 dp from the wall, beyond contactGap, crossed it in
        // pellets.stl uncapped. Each is cut by the wall's tangent plane at
        // its outermost vertex, capHeight inside, until none reaches
        // beyond R - capHeight/2
        if (treatment == "caps")
        {
            const scalar R = tube_.radius();
            const scalar hc = settings.capHeight();
            for (label i = 0; i < bodies_.size(); ++i)
            {
                for (label pass = 0; pass < 4; ++pass)
                {
                    scalar rhoMax = 0;
                    point outer(Zero);
                    for (const point& x : surfaces[i].points())
                    {
                        const scalar rho = tube::axialDistance(x);
                        if (rho > rhoMax)
                        {
                            rhoMax = rho;
                            outer = x;
                        }
                    }
                    // Beyond R - hc/2: the cut faces of caps already made
                    // stand at R - hc where the wall is tangent, a little
                    // further out beside it (a second plane there cut
                    // slivers that CGAL's clipping refused)
                    if (rhoMax <= R - 0.5*hc)
                    {
                        break;
                    }
                    const vector er(outer.x()/rhoMax, outer.y()/rhoMax, 0);
                    surfaces[i] = contactGeometry::cap
                    (
                        surfaces[i], point(R*er.x(), R*er.y(), outer.z()),
                        -er, hc
                    );
                    ++nTreated;
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
    writeSTL(surfaces, settings.binarySTL());
    return nTreated;
}


void Foam::rbd::bedOutput::writeSTL
(
    const UList<triMesh>& surfaces,
    const bool binary
) const
{
    mkDir(stl_.path());
    const fileName tmp(stl_ + ".tmp");
    {
        stlWriter writer(tmp, binary, "pellets");
        for (const triMesh& m : surfaces)
        {
            writer.write(m);
        }
    }
    commit(tmp, stl_);
}


Foam::scalar Foam::rbd::bedOutput::surfacePorosity
(
    const UList<triMesh>& surfaces,
    const scalar H
) const
{
    // Each closed surface as a one-pellet meshSolidSet in place: its
    // volume in 0 <= z <= H, exact for the polyhedron
    const pointField origin(1, Zero);
    const tensorField identity(1, tensor::I);
    scalar V = 0;
    for (const triMesh& m : surfaces)
    {
        V += meshSolidSet(m, origin, identity).volume(0, 0, H);
    }
    return 1 - V/(constant::mathematical::pi*sqr(tube_.radius())*H);
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


Foam::string Foam::rbd::bedOutput::summaryUnit(const word& key)
{
    // Unit and meaning of every entry the summary may hold; the
    // sub-dictionaries' entries (bulkPorosityCorrelations, deKlerk { } ...)
    // are looked up by their own keys
    static const std::initializer_list<std::pair<const char*, const char*>>
    units
    {
        {"pellets", "[-] number of pellets in the bed"},
        {"requestedPellets", "[-] number asked for"},
        {"status", "outcome of the run"},
        {"shape", "pellet shape"},
        {"tubeDiameter", "[m] dt"},
        {"pelletDiameter", "[m] dp, the pellet's nominal (outer) diameter"},
        {"volumeEquivalentDiameter", "[m] dpv, of the sphere of equal volume"},
        {"diameterRatio", "[-] N = dt/dp"},
        {"volumeEquivalentDiameterRatio", "[-] Nv = dt/dpv"},
        {
            "bulkPorosity",
            "[-] below porosityHeight, of the exact (curved) pellets"
        },
        {
            "stlPorosity",
            "[-] below porosityHeight, of the solids in pellets.stl (with "
            "the contact treatment)"
        },
        {"porosityHeight", "[m] top of the bulk porosity's slab"},
        {
            "bulkPorosityCorrelations",
            "[-] published bulk porosities at Nv = dt/dpv"
        },
        {"dixon", "[-]"},
        {"foumeny", "[-]"},
        {"benyahiaONeill", "[-]"},
        {"benyahiaONeillAnyShape", "[-]"},
        {
            "radialCorrelations",
            "radial profile against the sphere correlations"
        },
        {"rSquared", "[-] R^2"},
        {"rmse", "[-] root mean square error"},
        {"bedHeight", "[m] highest pellet centre + bounding radius"},
        {"bedPorosity", "[-] floor to bedHeight"},
        {"maxOverlap", "[m] largest interpenetration during the run"},
        {"finalMaxOverlap", "[m] largest interpenetration at the end"},
        {
            "releaseOverlap",
            "[m] largest interpenetration at a release (bounding spheres; "
            "loadingScheme placement: of the placed pellets, exact)"
        },
        {"loadingScheme", "loading/scheme"},
        {"simulatedTime", "[s]"},
        {"wallTime", "[s]"},
        {"cpuTime", "[s]"},
        {"steps", "[-] time steps"},
        {"collisions", "[-]"},
        {"lcpFailures", "[-] resting-contact solves that failed"},
        {"kineticEnergy", "[J] at the end"},
        {"settled", "whether the bed came to rest"},
        {"contactTreatment", "of the pellet surfaces for the CFD mesh"},
        {"treatedContacts", "[-]"},
        {"orientedPellets", "[-] pellets with centres below porosityHeight"},
        {"meanAxisAngle", "[deg] pellet axis to tube axis"},
        {"stdDevAxisAngle", "[deg]"},
        {"axisOrderParameter", "[-] <P2(cos angle)>"}
    };
    for (const auto& u : units)
    {
        if (key == u.first)
        {
            return u.second;
        }
    }
    return string::null;
}


void Foam::rbd::bedOutput::writeCommented
(
    Ostream& os,
    const dictionary& dict
)
{
    for (const entry& e : dict)
    {
        const string unit(summaryUnit(e.keyword()));
        if (e.isDict())
        {
            if (!unit.empty())
            {
                os.indent();
                os  << "// " << unit.c_str() << nl;
            }
            os.beginBlock(e.keyword());
            writeCommented(os, e.dict());
            os.endBlock();
            continue;
        }
        // The entry on one line, the comment after it
        OStringStream line;
        e.write(line);
        std::string text(line.str());
        while (!text.empty() && text.back() == '\n')
        {
            text.pop_back();
        }
        os.indent();
        os  << text.c_str();
        if (!unit.empty())
        {
            os  << "  // " << unit.c_str();
        }
        os  << nl;
    }
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
        writeCommented(os, summary);
        IOobject::writeEndDivider(os);
    }
    commit(tmp, target);
}


// ************************************************************************* //
