#include "atomicFileOperation.H"

#include <cstdio>

namespace Foam
{
namespace fileOperations
{
    defineTypeNameAndDebug(atomicFileOperation, 0);
}
}

Foam::DynamicList<Foam::fileName>
    Foam::fileOperations::atomicFileOperation::failures_;


namespace
{

// The name a stream writes to: compressed streams add ".gz"
Foam::fileName onDisk
(
    const Foam::fileName& name,
    const Foam::IOstream::compressionType compression
)
{
    return compression == Foam::IOstream::COMPRESSED
      ? Foam::fileName(name + ".gz") : name;
}

} // End anonymous namespace


Foam::fileOperations::atomicOFstream::atomicOFstream
(
    const fileName& pathname,
    IOstream::streamFormat format,
    IOstream::versionNumber version,
    IOstream::compressionType compression
)
:
    OFstream(fileName(pathname + ".tmp"), format, version, compression),
    final_(pathname),
    compression_(compression)
{}


Foam::fileOperations::atomicOFstream::~atomicOFstream()
{
    // Flushed and closed before the rename, so that an error of the last
    // block (a full disk) is seen
    stdStream().flush();
    const bool ok = good() && stdStream().good();
    deallocate();

    const fileName tmp(onDisk(fileName(final_ + ".tmp"), compression_));
    if
    (
        ok
     && std::rename(tmp.c_str(), onDisk(final_, compression_).c_str()) == 0
    )
    {
        return;
    }
    std::remove(tmp.c_str());
    atomicFileOperation::failures_.append(final_);
}


Foam::fileOperations::atomicFileOperation::atomicFileOperation
(
    const bool verbose
)
:
    uncollatedFileOperation(verbose)
{}


void Foam::fileOperations::atomicFileOperation::install()
{
    autoPtr<fileOperation> handler(new atomicFileOperation(false));
    Foam::fileHandler(handler);
}


Foam::autoPtr<Foam::Ostream>
Foam::fileOperations::atomicFileOperation::NewOFstream
(
    const fileName& pathname,
    IOstream::streamFormat format,
    IOstream::versionNumber version,
    IOstream::compressionType compression,
    const bool valid
) const
{
    return autoPtr<Ostream>
    (
        new atomicOFstream(pathname, format, version, compression)
    );
}
