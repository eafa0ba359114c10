#include "u3ma_archive.h"

#include <zlib.h>

#include <algorithm>

namespace woven {

namespace {

constexpr uint32_t kLocalSignature = 0x04034b50, kCentralSignature = 0x02014b50, kEndSignature = 0x06054b50;
constexpr uint16_t kVersionMadeBy = 0x003F;  // 6.3, "FAT" host: the spec's value whatever the system
constexpr uint16_t kVersionNeeded = 0x14;
constexpr uint16_t kUtf8Names = 0x0800;      // general purpose bit 11 (EFS), always set
constexpr uint16_t kStored = 0, kDeflated = 8;
constexpr size_t kLocalHeaderBytes = 30, kCentralHeaderBytes = 46, kEndRecordBytes = 22;

void put16(std::vector<unsigned char>& out, uint32_t v) {
    out.push_back(uint8_t(v)), out.push_back(uint8_t(v >> 8));
}
void put32(std::vector<unsigned char>& out, uint32_t v) { put16(out, v & 0xffff), put16(out, v >> 16); }

uint32_t crc(const std::vector<unsigned char>& bytes) {
    uLong c = crc32(0L, Z_NULL, 0);
    for (size_t done = 0; done < bytes.size();) {
        const uInt n = uInt(std::min<size_t>(bytes.size() - done, 1u << 30));
        c = crc32(c, bytes.data() + done, n);
        done += n;
    }
    return uint32_t(c);
}

// Raw deflate (no zlib header), as ZIP's method 8 holds it.
std::vector<unsigned char> deflateRaw(const std::vector<unsigned char>& in) {
    z_stream s{};
    if (deflateInit2(&s, Z_BEST_COMPRESSION, Z_DEFLATED, -15, 8, Z_DEFAULT_STRATEGY) != Z_OK)
        throw ArchiveError("zlib could not start deflating");
    std::vector<unsigned char> out(deflateBound(&s, uLong(in.size())));
    s.next_in = const_cast<unsigned char*>(in.data());
    s.avail_in = uInt(in.size());
    s.next_out = out.data();
    s.avail_out = uInt(out.size());
    const int r = deflate(&s, Z_FINISH);
    out.resize(s.total_out);
    deflateEnd(&s);
    if (r != Z_STREAM_END) throw ArchiveError("zlib could not deflate a file");
    return out;
}

// MS-DOS date and time (two-second steps, years from 1980) of `t` in UTC.
std::pair<uint16_t, uint16_t> dosTime(std::time_t t) {
    std::tm u{};
    gmtime_r(&t, &u);
    const int year = std::clamp(u.tm_year + 1900, 1980, 2107);
    return {uint16_t((u.tm_hour << 11) | (u.tm_min << 5) | (u.tm_sec / 2)),
            uint16_t(((year - 1980) << 9) | ((u.tm_mon + 1) << 5) | u.tm_mday)};
}

// Little-endian fields of an archive being read, every read bounds-checked.
struct Reader {
    const std::vector<unsigned char>& bytes;
    const std::string& name;
    void need(size_t at, size_t n, const std::string& what) const {
        if (at > bytes.size() || n > bytes.size() - at) throw ArchiveError(name + ": not a U3MA archive: its " + what + " runs past its end");
    }
    uint32_t u16(size_t at) const { return uint32_t(bytes[at]) | uint32_t(bytes[at + 1]) << 8; }
    uint32_t u32(size_t at) const { return u16(at) | u16(at + 2) << 16; }
};

// A name that stays inside the archive's folder: relative, no "..", "." or "~" part, no NUL or backslash.
bool safeName(const std::string& n) {
    if (n.empty() || n.front() == '/' || n.find('\0') != std::string::npos || n.find('\\') != std::string::npos) return false;
    size_t start = 0;
    while (start <= n.size()) {
        const size_t end = std::min(n.find('/', start), n.size());
        const std::string part = n.substr(start, end - start);
        if (part == ".." || part == "." || part == "~" || (part.empty() && end != n.size())) return false;
        start = end + 1;
    }
    return true;
}

std::vector<unsigned char> inflateRaw(const unsigned char* data, size_t size, size_t expected, const std::string& what) {
    std::vector<unsigned char> out(expected);
    z_stream s{};
    if (inflateInit2(&s, -15) != Z_OK) throw ArchiveError(what + ": zlib could not start inflating");
    s.next_in = const_cast<unsigned char*>(data);
    s.avail_in = uInt(size);
    s.next_out = out.data();
    s.avail_out = uInt(out.size());
    const int r = inflate(&s, Z_FINISH);
    const size_t produced = s.total_out;
    inflateEnd(&s);
    if (r != Z_STREAM_END || produced != expected) throw ArchiveError(what + ": its deflated data is damaged");
    return out;
}

}  // namespace

std::vector<unsigned char> packU3ma(const std::vector<ArchiveEntry>& entries, std::time_t modified) {
    const auto [time, date] = dosTime(modified);
    std::vector<unsigned char> out, central;
    for (const ArchiveEntry& e : entries) {
        if (!safeName(e.name)) throw ArchiveError("'" + e.name + "' is no relative file name for an archive");
        if (e.bytes.size() >= 0xffffffffu || out.size() >= 0xffffffffu - e.bytes.size())
            throw ArchiveError("'" + e.name + "' would make the archive larger than 4 GiB, which U3MA (no zip64) cannot hold");
        std::vector<unsigned char> deflated = deflateRaw(e.bytes);
        const bool store = deflated.size() >= e.bytes.size();
        const std::vector<unsigned char>& data = store ? e.bytes : deflated;
        const uint16_t method = store ? kStored : kDeflated;
        const uint32_t sum = crc(e.bytes), offset = uint32_t(out.size());
        // The local header, then the central one: the same fields, the central with its offset.
        for (std::vector<unsigned char>* h : {&out, &central}) {
            const bool isCentral = h == &central;
            put32(*h, isCentral ? kCentralSignature : kLocalSignature);
            if (isCentral) put16(*h, kVersionMadeBy);
            put16(*h, kVersionNeeded), put16(*h, kUtf8Names), put16(*h, method), put16(*h, time), put16(*h, date);
            put32(*h, sum), put32(*h, uint32_t(data.size())), put32(*h, uint32_t(e.bytes.size()));
            put16(*h, uint32_t(e.name.size())), put16(*h, 0);  // name length, no extra field
            if (isCentral) {
                put16(*h, 0), put16(*h, 0), put16(*h, 0), put32(*h, 0);  // comment, disk, internal and external attributes
                put32(*h, offset);
            }
            h->insert(h->end(), e.name.begin(), e.name.end());
        }
        out.insert(out.end(), data.begin(), data.end());
    }
    if (entries.size() > 0xffff || out.size() + central.size() >= 0xffffffffu)
        throw ArchiveError("too many files or bytes for an archive without zip64");
    const uint32_t centralOffset = uint32_t(out.size());
    out.insert(out.end(), central.begin(), central.end());
    put32(out, kEndSignature);
    put16(out, 0), put16(out, 0), put16(out, uint32_t(entries.size())), put16(out, uint32_t(entries.size()));
    put32(out, uint32_t(central.size())), put32(out, centralOffset), put16(out, 0);
    return out;
}

std::vector<ArchiveEntry> unpackU3ma(const std::vector<unsigned char>& archive, const std::string& name, size_t maxEntryBytes) {
    const Reader r{archive, name};
    // U3MA allows no comment, so the end record is the last 22 bytes.
    if (archive.size() < kEndRecordBytes || r.u32(archive.size() - kEndRecordBytes) != kEndSignature)
        throw ArchiveError(name + ": not a U3MA archive (no ZIP end record at its end; a ZIP comment or zip64 is not allowed)");
    const size_t end = archive.size() - kEndRecordBytes;
    const size_t count = r.u16(end + 10), centralSize = r.u32(end + 12), centralOffset = r.u32(end + 16);
    if (r.u16(end + 4) != 0 || r.u16(end + 6) != 0 || r.u16(end + 8) != count)
        throw ArchiveError(name + ": not a U3MA archive: it spans several disks");
    r.need(centralOffset, centralSize, "central directory");
    std::vector<ArchiveEntry> entries;
    size_t at = centralOffset;
    for (size_t i = 0; i < count; ++i) {
        r.need(at, kCentralHeaderBytes, "central directory");
        if (r.u32(at) != kCentralSignature) throw ArchiveError(name + ": not a U3MA archive: its central directory is damaged");
        const uint32_t flags = r.u16(at + 8), method = r.u16(at + 10), sum = r.u32(at + 16);
        const size_t packed = r.u32(at + 20), size = r.u32(at + 24), nameLength = r.u16(at + 28),
                     skip = r.u16(at + 30) + r.u16(at + 32), local = r.u32(at + 42);
        r.need(at + kCentralHeaderBytes, nameLength + skip, "central directory");
        ArchiveEntry e;
        e.name.assign(archive.begin() + long(at + kCentralHeaderBytes), archive.begin() + long(at + kCentralHeaderBytes + nameLength));
        at += kCentralHeaderBytes + nameLength + skip;
        const std::string what = name + ": '" + e.name + "'";
        if (flags & 0x0001) throw ArchiveError(what + " is encrypted, which U3MA does not allow");
        if (method != kStored && method != kDeflated)
            throw ArchiveError(what + " is packed with ZIP method " + std::to_string(method) + "; U3MA allows only stored (0) and deflate (8)");
        if (packed == 0xffffffffu || size == 0xffffffffu) throw ArchiveError(what + " needs zip64, which U3MA does not allow");
        if (!e.name.empty() && e.name.back() == '/') continue;  // a folder
        if (!safeName(e.name)) throw ArchiveError(what + ": a file name must be relative and stay inside the archive");
        if (size > maxEntryBytes)
            throw ArchiveError(what + " unpacks to " + std::to_string(size) + " bytes, more than woven reads (" +
                               std::to_string(maxEntryBytes) + ")");
        r.need(local, kLocalHeaderBytes, "local header of '" + e.name + "'");
        if (r.u32(local) != kLocalSignature) throw ArchiveError(what + ": its local header is damaged");
        const size_t data = local + kLocalHeaderBytes + r.u16(local + 26) + r.u16(local + 28);
        r.need(data, packed, "data of '" + e.name + "'");
        if (method == kStored) {
            if (packed != size) throw ArchiveError(what + ": a stored file's sizes differ");
            e.bytes.assign(archive.begin() + long(data), archive.begin() + long(data + size));
        } else {
            e.bytes = inflateRaw(archive.data() + data, packed, size, what);
        }
        if (crc(e.bytes) != sum) throw ArchiveError(what + ": its CRC-32 does not match (the archive is damaged)");
        entries.push_back(std::move(e));
    }
    return entries;
}

}  // namespace woven
