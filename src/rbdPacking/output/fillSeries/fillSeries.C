/*---------------------------------------------------------------------------*\
  rbdPacking: hard-body rigid body dynamics packings for OpenFOAM
\*---------------------------------------------------------------------------*/

#include "fillSeries.H"
#include "bedOutput.H"
#include "world.H"
#include "OSspecific.H"

#include <cmath>
#include <cstdio>
#include <fstream>
#include <iomanip>
#include <sstream>

// * * * * * * * * * * * * * * Static Data Members * * * * * * * * * * * * * //

const Foam::word Foam::rbd::fillSeries::directoryName("fill");

const Foam::word Foam::rbd::fillSeries::collectionName("fill.pvd");

const Foam::word Foam::rbd::fillSeries::glyphName("pellet.vtp");

const Foam::scalar Foam::rbd::fillSeries::touchingGap = 1e-3;


// * * * * * * * * * * * * * * * Local Functions * * * * * * * * * * * * * * //

namespace
{

//- Digits of positions and orientations: those of pellets.csv, so that the
//  last frame gives the bed's poses
const int poseDigits = 12;

//- Digits of the rotation tensor and the velocities (display)
const int stateDigits = 7;

//- Frame n's file name
Foam::fileName frameName(const Foam::label n)
{
    std::ostringstream os;
    os << "fill_" << std::setw(5) << std::setfill('0') << n << ".vtp";
    return os.str();
}

//- Write to file + ".tmp" with w(os), then rename it over file; false if
//  it could not be written
template<class Writer>
bool writeThenRename(const Foam::fileName& file, const Writer& w)
{
    const std::string tmp(file + ".tmp");
    {
        std::ofstream os(tmp);
        if (!os)
        {
            return false;
        }
        w(os);
        os.close();
        if (!os)
        {
            return false;
        }
    }
    return std::rename(tmp.c_str(), file.c_str()) == 0;
}

void openArray
(
    std::ostream& os,
    const char* type,
    const char* name,
    const int nComponents
)
{
    os  << "        <DataArray type=\"" << type << "\" Name=\"" << name
        << "\" NumberOfComponents=\"" << nComponents
        << "\" format=\"ascii\">\n";
}

void closeArray(std::ostream& os)
{
    os  << "\n        </DataArray>\n";
}

void writeVector(std::ostream& os, const Foam::vector& v)
{
    os  << v.x() << ' ' << v.y() << ' ' << v.z() << '\n';
}

} // End anonymous namespace


// * * * * * * * * * * * * * * * * Constructors  * * * * * * * * * * * * * * //

Foam::rbd::fillSeries::fillSeries
(
    const fileName& caseDir,
    const pelletShape& shape,
    const simulationControls& controls
)
:
    caseDir_(caseDir),
    dir_(caseDir/bedOutput::directoryName/directoryName),
    shape_(shape),
    writeInterval_(controls.writeInterval),
    deltaT_(controls.deltaT),
    touch_(touchingGap*shape.diameter()),
    started_(false),
    nextWrite_(0),
    times_(),
    files_(),
    bytes_(0),
    partners_()
{}


// * * * * * * * * * * * * * Private Member Functions  * * * * * * * * * * * //

void Foam::rbd::fillSeries::start(const scalar t)
{
    started_ = true;

    // ParaView's OpenFOAM reader: an empty <case>.foam (as paraFoam -touch)
    const fileName foam(caseDir_/(caseDir_.name() + ".foam"));
    if (!Foam::exists(foam))
    {
        std::ofstream touch(foam);
    }

    // The first outer interval of a new run ends at deltaT; a resumed run
    // starts after its checkpoint, at least an interval later
    const bool resumed = t > 1.5*deltaT_;
    if (!resumed)
    {
        // An earlier run's series is not this run's
        if (Foam::isDir(dir_))
        {
            Foam::rmDir(dir_, true);
        }
    }
    else if (writeInterval_ > 0)
    {
        keepFramesBefore(t - 0.5*deltaT_);
    }

    if (writeInterval_ > 0)
    {
        Foam::mkDir(dir_);
        writeGlyph();
        Info<< "Fill series: " << (dir_/collectionName).relative(caseDir_)
            .c_str() << ", a frame every " << writeInterval_
            << " s (at the ends of outer intervals of " << deltaT_ << " s)"
            << nl << endl;
    }
}


void Foam::rbd::fillSeries::keepFramesBefore(const scalar t)
{
    // The collection file is our own: one DataSet line per frame
    std::ifstream is(dir_/collectionName);
    std::string line;
    while (std::getline(is, line))
    {
        const auto ts = line.find("timestep=\"");
        const auto fs = line.find("file=\"");
        if (ts == std::string::npos || fs == std::string::npos)
        {
            continue;
        }
        const scalar time = std::atof(line.c_str() + ts + 10);
        const std::string file
        (
            line.substr(fs + 6, line.find('"', fs + 6) - fs - 6)
        );
        if (time < t && Foam::isFile(dir_/file))
        {
            times_.append(time);
            files_.append(file);
        }
    }

    // Frames after the checkpoint: the run writes them again
    for (const fileName& f : readDir(dir_, fileName::FILE))
    {
        if (f.hasExt("vtp") && f != glyphName && !files_.found(f))
        {
            Foam::rm(dir_/f);
        }
    }
    if (times_.size())
    {
        nextWrite_ =
            writeInterval_*(std::floor(times_.last()/writeInterval_ + 1e-9)
          + 1);
    }
}


void Foam::rbd::fillSeries::updateContacts(const world& w)
{
    const label n = w.bodies().size();
    const boolList& asleep = w.sleeping();
    partners_.setSize(n);

    // Touching bodies in the last step's contact list: every pair with an
    // awake pellet
    List<DynamicList<label>> now(n);
    const auto add = [](DynamicList<label>& l, const label k)
    {
        if (!l.found(k))
        {
            l.append(k);
        }
    };
    for (const contact& c : w.contacts())
    {
        if (c.gap <= touch_)
        {
            add(now[c.i], c.k);
            if (c.k >= 0)
            {
                add(now[c.k], c.i);
            }
        }
    }

    forAll(partners_, i)
    {
        if (asleep[i])
        {
            // Sleepers and the tube as they were, awake ones as now
            for (const label k : partners_[i])
            {
                if (k < 0 || asleep[k])
                {
                    add(now[i], k);
                }
            }
        }
        partners_[i].transfer(now[i]);
    }
}


void Foam::rbd::fillSeries::writeFrame
(
    const world& w,
    const fileName& file
) const
{
    const UList<rigidBody>& b = w.bodies();
    const boolList& asleep = w.sleeping();
    const label n = b.size();

    const auto frame = [&](std::ostream& os)
    {
        os  << std::setprecision(stateDigits)
            << "<?xml version=\"1.0\"?>\n"
            << "<VTKFile type=\"PolyData\" version=\"1.0\" "
            << "byte_order=\"LittleEndian\" header_type=\"UInt64\">\n"
            << "  <PolyData>\n"
            << "    <FieldData>\n"
            << "      <DataArray type=\"Float64\" Name=\"TimeValue\" "
            << "NumberOfTuples=\"1\" format=\"ascii\">"
            << std::setprecision(poseDigits) << w.time()
            << "</DataArray>\n"
            << "      <DataArray type=\"Float64\" Name=\"pelletDiameter\" "
            << "NumberOfTuples=\"1\" format=\"ascii\">" << shape_.diameter()
            << "</DataArray>\n"
            << "      <Array type=\"String\" Name=\"shape\" "
            << "NumberOfTuples=\"1\" format=\"ascii\">";
        for (const char c : shape_.type())
        {
            os  << int(c) << ' ';
        }
        os  << "0</Array>\n"
            << "    </FieldData>\n"
            << "    <Piece NumberOfPoints=\"" << n << "\" NumberOfVerts=\""
            << n << "\" NumberOfLines=\"0\" NumberOfStrips=\"0\" "
            << "NumberOfPolys=\"0\">\n"
            << "      <PointData Scalars=\"id\" Vectors=\"velocity\" "
            << "Tensors=\"orientation\">\n";

        openArray(os, "Int32", "id", 1);
        for (label i = 0; i < n; ++i)
        {
            os  << i << (i % 20 == 19 ? '\n' : ' ');
        }
        closeArray(os);

        os  << std::setprecision(stateDigits);
        openArray(os, "Float64", "velocity", 3);
        for (const rigidBody& p : b)
        {
            writeVector(os, p.v());
        }
        closeArray(os);

        openArray(os, "Float64", "omega", 3);
        for (const rigidBody& p : b)
        {
            writeVector(os, p.omega());
        }
        closeArray(os);

        openArray(os, "UInt8", "asleep", 1);
        for (label i = 0; i < n; ++i)
        {
            os  << (asleep[i] ? 1 : 0) << (i % 20 == 19 ? '\n' : ' ');
        }
        closeArray(os);

        openArray(os, "Int32", "contacts", 1);
        for (label i = 0; i < n; ++i)
        {
            const label nc = i < partners_.size() ? partners_[i].size() : 0;
            os  << nc << (i % 20 == 19 ? '\n' : ' ');
        }
        closeArray(os);

        os  << std::setprecision(poseDigits);
        openArray(os, "Float64", "quaternion", 4);
        for (const rigidBody& p : b)
        {
            const quaternion& q = p.q();
            os  << q.w() << ' ' << q.v().x() << ' ' << q.v().y() << ' '
                << q.v().z() << '\n';
        }
        closeArray(os);

        // vtkTensorGlyph (ExtractEigenvalues off) takes components 0-2,
        // 3-5, 6-8 as the glyph's x, y, z axes: the columns of R
        os  << std::setprecision(stateDigits);
        openArray(os, "Float64", "orientation", 9);
        for (const rigidBody& p : b)
        {
            const tensor& R = p.R();
            os  << R.xx() << ' ' << R.yx() << ' ' << R.zx() << ' '
                << R.xy() << ' ' << R.yy() << ' ' << R.zy() << ' '
                << R.xz() << ' ' << R.yz() << ' ' << R.zz() << '\n';
        }
        closeArray(os);

        os  << "      </PointData>\n"
            << "      <Points>\n"
            << std::setprecision(poseDigits);
        openArray(os, "Float64", "Points", 3);
        for (const rigidBody& p : b)
        {
            writeVector(os, p.x());
        }
        closeArray(os);
        os  << "      </Points>\n"
            << "      <Verts>\n";
        openArray(os, "Int64", "connectivity", 1);
        for (label i = 0; i < n; ++i)
        {
            os  << i << (i % 20 == 19 ? '\n' : ' ');
        }
        closeArray(os);
        openArray(os, "Int64", "offsets", 1);
        for (label i = 0; i < n; ++i)
        {
            os  << i + 1 << (i % 20 == 19 ? '\n' : ' ');
        }
        closeArray(os);
        os  << "      </Verts>\n"
            << "    </Piece>\n"
            << "  </PolyData>\n"
            << "</VTKFile>\n";
    };

    if (!writeThenRename(dir_/file, frame))
    {
        FatalErrorInFunction
            << "Cannot write " << dir_/file << exit(FatalError);
    }
}


void Foam::rbd::fillSeries::writeGlyph() const
{
    const triMesh& m = shape_.volumeTrueMesh();
    const auto glyph = [&](std::ostream& os)
    {
        os  << std::setprecision(poseDigits)
            << "<?xml version=\"1.0\"?>\n"
            << "<!-- rbdPackBed: the " << shape_.type() << " pellet's "
            << "surface in its body frame (centre of mass at the origin), "
            << "as in pellets.stl -->\n"
            << "<VTKFile type=\"PolyData\" version=\"1.0\" "
            << "byte_order=\"LittleEndian\" header_type=\"UInt64\">\n"
            << "  <PolyData>\n"
            << "    <Piece NumberOfPoints=\"" << m.nPoints()
            << "\" NumberOfVerts=\"0\" NumberOfLines=\"0\" "
            << "NumberOfStrips=\"0\" NumberOfPolys=\"" << m.nFaces()
            << "\">\n"
            << "      <Points>\n";
        openArray(os, "Float64", "Points", 3);
        for (const point& p : m.points())
        {
            writeVector(os, p);
        }
        closeArray(os);
        os  << "      </Points>\n"
            << "      <Polys>\n";
        openArray(os, "Int64", "connectivity", 1);
        for (const triFace& f : m.faces())
        {
            os  << f[0] << ' ' << f[1] << ' ' << f[2] << '\n';
        }
        closeArray(os);
        openArray(os, "Int64", "offsets", 1);
        for (label i = 0; i < m.nFaces(); ++i)
        {
            os  << 3*(i + 1) << (i % 20 == 19 ? '\n' : ' ');
        }
        closeArray(os);
        os  << "      </Polys>\n"
            << "    </Piece>\n"
            << "  </PolyData>\n"
            << "</VTKFile>\n";
    };
    const fileName file(dir_/glyphName);
    if (!writeThenRename(file, glyph))
    {
        FatalErrorInFunction
            << "Cannot write " << file << exit(FatalError);
    }
}


void Foam::rbd::fillSeries::writeCollection() const
{
    const auto collection = [&](std::ostream& os)
    {
        os  << std::setprecision(poseDigits)
            << "<?xml version=\"1.0\"?>\n"
            << "<VTKFile type=\"Collection\" version=\"1.0\" "
            << "byte_order=\"LittleEndian\">\n"
            << "  <Collection>\n";
        forAll(times_, i)
        {
            os  << "    <DataSet timestep=\"" << times_[i]
                << "\" group=\"\" part=\"0\" file=\"" << files_[i].c_str()
                << "\"/>\n";
        }
        os  << "  </Collection>\n"
            << "</VTKFile>\n";
    };
    const fileName file(dir_/collectionName);
    if (!writeThenRename(file, collection))
    {
        FatalErrorInFunction
            << "Cannot write " << file << exit(FatalError);
    }
}


// * * * * * * * * * * * * * * * Member Functions  * * * * * * * * * * * * * //

void Foam::rbd::fillSeries::write(const world& w, const bool last)
{
    const scalar t = w.time();
    if (!started_)
    {
        start(t);
    }
    if (!(writeInterval_ > 0))
    {
        return;
    }

    updateContacts(w);

    if (t >= nextWrite_ - 1e-12 || last)
    {
        const fileName file(frameName(times_.size()));
        writeFrame(w, file);
        times_.append(t);
        files_.append(file);
        writeCollection();
        bytes_ += Foam::fileSize(dir_/file);
        nextWrite_ =
            writeInterval_*(std::floor(t/writeInterval_ + 1e-9) + 1);
    }

    if (last)
    {
        bytes_ +=
            Foam::fileSize(dir_/collectionName)
          + Foam::fileSize(dir_/glyphName);
        Info<< "Fill series: " << times_.size() << " frames of "
            << w.bodies().size() << " pellets to t = " << t << " s in "
            << (dir_/collectionName).relative(caseDir_).c_str() << ", "
            << bytes_ << " bytes (this run)" << nl << endl;
    }
}


// ************************************************************************* //
