#pragma once
// The U3MA archive (U3M 1.1, spec/u3m_additional_spec_u3ma.txt in vizoogmbh/u3m): the subset of
// ZIP that a .u3ma may be. Each file stored or deflated (whichever is smaller), no zip64, no
// encryption, no extra fields, comments or attributes, UTF-8 names (flag bit 11), times in UTC,
// nothing before the first entry or after the end record. Written by hand over zlib's deflate
// and CRC-32 because general ZIP writers (libzip, minizip) add extra fields and attributes that
// the U3MA subset forbids. The reader takes what the writer writes and refuses the rest by name.
#include <cstdint>
#include <ctime>
#include <stdexcept>
#include <string>
#include <vector>

namespace woven {

struct ArchiveError : std::runtime_error {
    using std::runtime_error::runtime_error;
};

struct ArchiveEntry {
    std::string name;  // relative, '/' between folders
    std::vector<unsigned char> bytes;
};

// A whole archive in memory; `modified` is every entry's time.
std::vector<unsigned char> packU3ma(const std::vector<ArchiveEntry>& entries, std::time_t modified);

// Throws ArchiveError "<name>: <problem>" for bytes that are not a U3MA archive (another ZIP
// method, zip64, encryption, a name that leaves the archive, a file larger than `maxEntryBytes`
// unpacked, a CRC that does not match).
std::vector<ArchiveEntry> unpackU3ma(const std::vector<unsigned char>& archive, const std::string& name,
                                     size_t maxEntryBytes);

}  // namespace woven
