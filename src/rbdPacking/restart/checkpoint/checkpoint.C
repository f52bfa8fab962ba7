/*---------------------------------------------------------------------------*\
  rbdPacking: hard-body rigid body dynamics packings for OpenFOAM
\*---------------------------------------------------------------------------*/

#include "checkpoint.H"
#include "OStringStream.H"
#include "OSspecific.H"

#include <fstream>
#include <limits>

// * * * * * * * * * * * * * * * * Local Data  * * * * * * * * * * * * * * * //

namespace
{
    //- The format's name and version
    const std::string magic("rbdPacking checkpoint");
    const Foam::label version = 7;  // 3: the run's counters in 64 bits;
                                    // 4: the release overlap; 5: the
                                    // resting solve's contact points;
                                    // 6: its exchange records; 7: the
                                    // swept pellets' counters

    //- Written as a label: read back the same only with the same byte order
    const Foam::label byteOrderMark = 0x01020304;
}


// * * * * * * * * * * * * * * * * Static Data * * * * * * * * * * * * * * * //

const Foam::wordList Foam::rbd::checkpoint::resumableEntries
({
    "endTime", "checkpointInterval", "logInterval", "writeInterval",
    "threads"
});

const Foam::wordList Foam::rbd::checkpoint::resumableBlocks
({
    "FoamFile", "cfdCase"
});


// * * * * * * * * * * * * * * Static Member Functions * * * * * * * * * * * //

Foam::fileName Foam::rbd::checkpoint::path(const fileName& casePath)
{
    return casePath/"postProcessing"/"rbdPackBed"/"checkpoint";
}


Foam::List<Foam::Pair<std::string>> Foam::rbd::checkpoint::identity
(
    const dictionary& dict
)
{
    DynamicList<Pair<std::string>> blocks;
    for (const entry& e : dict)
    {
        const word& name = e.keyword();
        if (resumableBlocks.found(name))
        {
            continue;
        }

        // Every digit of every number: 8030.0004 is not 8030
        OStringStream os;
        os.precision(std::numeric_limits<scalar>::max_digits10);
        if (name == "simulation" && e.isDict())
        {
            dictionary d(e.dict());
            for (const word& r : resumableEntries)
            {
                d.remove(r);
            }
            d.write(os, false);
        }
        else
        {
            e.write(os);
        }
        blocks.append(Pair<std::string>(name, os.str()));
    }
    return List<Pair<std::string>>(std::move(blocks));
}


void Foam::rbd::checkpoint::write
(
    const fileName& file,
    const dictionary& dict,
    const std::function<void(stateWriter&)>& writeState
)
{
    mkDir(file.path());
    const fileName tmp(file + ".tmp");
    bool ok = false;
    {
        std::ofstream os(tmp, std::ios::binary | std::ios::trunc);
        stateWriter out(os);
        out.put(magic).put(version).put(label(sizeof(label)))
           .put(label(sizeof(scalar))).put(byteOrderMark);

        const List<Pair<std::string>> blocks(identity(dict));
        out.put(blocks.size());
        for (const Pair<std::string>& b : blocks)
        {
            out.put(b.first()).put(b.second());
        }

        writeState(out);
        os.flush();
        ok = out.good();
    }

    // A checkpoint that cannot be written (a full disk) does not stop the
    // run it is there to save: the previous one, if any, stays
    if (!ok || !Foam::mv(tmp, file))
    {
        Foam::rm(tmp);
        WarningInFunction
            << "Could not write the checkpoint " << file.c_str()
            << "; the run goes on without it" << endl;
    }
}


void Foam::rbd::checkpoint::read
(
    const fileName& file,
    const dictionary& dict,
    const fileName& dictName,
    const std::function<void(stateReader&)>& readState
)
{
    if (!isFile(file))
    {
        FatalErrorInFunction
            << "No checkpoint " << file.c_str() << " to resume from." << nl
            << "    A run writes one every simulation/checkpointInterval "
            << "seconds of wall time and when it stops at endTime "
            << "unsettled; run without -resume to start the packing."
            << exit(FatalError);
    }

    std::ifstream is(file, std::ios::binary);
    stateReader in(is, file);

    std::string m;
    label v = 0, labelSize = 0, scalarSize = 0, bom = 0;
    {
        // The magic first, read with a bound: any file may be given
        label n = 0;
        in.get(n);
        if (n != label(magic.size()))
        {
            FatalErrorInFunction
                << file.c_str() << " is not an rbdPacking checkpoint."
                << nl << "    Delete it and run without -resume."
                << exit(FatalError);
        }
        m.resize(n);
        is.read(&m[0], n);
    }
    if (m != magic)
    {
        FatalErrorInFunction
            << file.c_str() << " is not an rbdPacking checkpoint."
            << nl << "    Delete it and run without -resume."
            << exit(FatalError);
    }
    in.get(v).get(labelSize).get(scalarSize).get(bom);
    if
    (
        v != version || labelSize != label(sizeof(label))
     || scalarSize != label(sizeof(scalar)) || bom != byteOrderMark
    )
    {
        FatalErrorInFunction
            << "The checkpoint " << file.c_str() << " was written by another "
            << "build (format " << v << ", " << labelSize << "-byte labels, "
            << scalarSize << "-byte scalars; this build reads format "
            << version << ", " << sizeof(label) << ", " << sizeof(scalar)
            << ", and its own byte order)." << nl
            << "    Resume it with the build that wrote it, or run without "
            << "-resume." << exit(FatalError);
    }

    label nBlocks = 0;
    in.get(nBlocks);
    in.checkSize(nBlocks);
    List<Pair<std::string>> written(nBlocks);
    for (Pair<std::string>& b : written)
    {
        in.get(b.first()).get(b.second());
    }

    // The first block that differs, in either direction
    const List<Pair<std::string>> now(identity(dict));
    auto find = [](const List<Pair<std::string>>& l, const std::string& n)
    {
        for (const Pair<std::string>& b : l)
        {
            if (b.first() == n)
            {
                return &b.second();
            }
        }
        return static_cast<const std::string*>(nullptr);
    };
    auto refuse = [&](const std::string& block, const char* how)
    {
        FatalIOErrorInFunction(dict)
            << "Entry '" << block.c_str() << "' of " << dictName.c_str() << ' ' << how
            << " the dictionary the checkpoint " << file.c_str()
            << " was written with." << nl
            << "    A resumed run may change only simulation/"
            << "{endTime, checkpointInterval, logInterval, writeInterval, "
            << "threads} "
            << "and the cfdCase "
            << "block; run without -resume to pack anew."
            << exit(FatalIOError);
    };
    for (const Pair<std::string>& b : now)
    {
        const std::string* old = find(written, b.first());
        if (!old)
        {
            refuse(b.first(), "is not in");
        }
        else if (*old != b.second())
        {
            refuse(b.first(), "differs from its value in");
        }
    }
    for (const Pair<std::string>& b : written)
    {
        if (!find(now, b.first()))
        {
            refuse(b.first(), "is missing, but was in");
        }
    }

    readState(in);

    // Nothing may follow the state: a longer file is not this run's
    char extra;
    if (is.read(&extra, 1))
    {
        FatalErrorInFunction
            << "The checkpoint " << file.c_str() << " holds more than the state "
            << "of this run: it is damaged." << nl
            << "    Delete it and run without -resume." << exit(FatalError);
    }
}


// ************************************************************************* //
