// The section layer of the .m3g format (JSR-184 1.1 file format, sections
// "File Structure", "Header Object" and "External Reference", and §8).
#include "M3GSections.h"

#include <algorithm>
#include <utility>

#include <zlib.h>

#include <m3g/Exception.h>

#include "Check.h"

namespace m3g::detail {

namespace {

constexpr std::size_t kSectionHeaderBytes = 9;  // scheme, TotalSectionLength, UncompressedLength
constexpr std::size_t kSectionOverhead = 13;    // + checksum

const char* const kTypeNames[] = {
    "Header", "AnimationController", "AnimationTrack", "Appearance", "Background", "Camera",
    "CompositingMode", "Fog", "PolygonMode", "Group", "Image2D", "TriangleStripArray", "Light",
    "Material", "Mesh", "MorphingMesh", "SkinnedMesh", "Texture2D", "Sprite3D", "KeyframeSequence",
    "VertexArray", "VertexBuffer", "World"};

std::string sectionName(int index) { return str("section ", index); }

}  // namespace

const char* objectTypeName(std::uint8_t type) {
    if (type <= kTypeWorld) return kTypeNames[type];
    if (type == kTypeExternalReference) return "External Reference";
    return "reserved";
}

std::string objectContext(const M3GObject& o) {
    return str("section ", o.section, ", object ", o.index, " (", objectTypeName(o.type), ", type ", int(o.type),
               ")");
}

ByteReader objectReader(const M3GObject& o, LoadLog* log) {
    // The object outlives its reader (both live through the file's decoding).
    const M3GObject* object = &o;
    return ByteReader::described(
        o.data,
        [object](std::string& context, std::string& offsetWhere) {
            context = objectContext(*object);
            if (object->inflated) offsetWhere = str("of the inflated data of section ", object->section);
        },
        o.dataOffset, log);
}

std::uint32_t adler32Of(std::span<const std::uint8_t> bytes) {
    uLong a = adler32(0L, Z_NULL, 0);
    // zlib takes uInt lengths; feed in chunks.
    std::size_t done = 0;
    while (done < bytes.size()) {
        const std::size_t n = std::min<std::size_t>(bytes.size() - done, 1u << 30);
        a = adler32(a, bytes.data() + done, static_cast<uInt>(n));
        done += n;
    }
    return static_cast<std::uint32_t>(a);
}

std::vector<std::uint8_t> inflateExact(std::span<const std::uint8_t> compressed, std::uint32_t expectedLength,
                                       const ByteReader& reader, std::size_t compressedPos) {
    struct Stream {
        z_stream zs{};
        bool live = false;
        ~Stream() {
            if (live) inflateEnd(&zs);
        }
    } s;
    if (inflateInit(&s.zs) != Z_OK) reader.failAt(compressedPos, "zlib could not be initialised");
    s.live = true;
    if (compressed.size() > 0xFFFFFFFFu) reader.failAt(compressedPos, "compressed section too large");
    s.zs.next_in = const_cast<Bytef*>(compressed.data());
    s.zs.avail_in = static_cast<uInt>(compressed.size());

    auto zfail = [&](const char* what, int code) {
        std::string m = str("zlib stream of the section is corrupt: ", what);
        if (s.zs.msg) m += str(" (", s.zs.msg, ")");
        else if (code) m += str(" (zlib error ", code, ")");
        m += str(" after ", s.zs.total_in, " compressed bytes");
        reader.failAt(compressedPos, m);
    };

    std::vector<std::uint8_t> out;
    std::size_t produced = 0;
    for (;;) {
        if (produced == out.size()) {
            if (out.size() == expectedLength) {
                // Full: the stream must end now without producing anything more.
                std::uint8_t extra = 0;
                s.zs.next_out = &extra;
                s.zs.avail_out = 1;
                const int ret = inflate(&s.zs, Z_NO_FLUSH);
                if (s.zs.avail_out == 0)
                    reader.failAt(compressedPos, str("zlib stream inflates to more than UncompressedLength ",
                                                     expectedLength, " bytes"));
                if (ret == Z_STREAM_END) break;
                if (ret == Z_OK) continue;
                if (ret == Z_BUF_ERROR) zfail("the stream is truncated", 0);
                zfail("inflate failed", ret);
            }
            // Grow geometrically, never beyond the declared length.
            const std::size_t next =
                std::min<std::size_t>(expectedLength, std::max<std::size_t>(out.size() * 2, 64 * 1024));
            out.resize(next);
        }
        s.zs.next_out = out.data() + produced;
        s.zs.avail_out = static_cast<uInt>(out.size() - produced);
        const int ret = inflate(&s.zs, Z_NO_FLUSH);
        produced = out.size() - s.zs.avail_out;
        if (ret == Z_STREAM_END) break;
        if (ret == Z_OK) continue;
        if (ret == Z_BUF_ERROR && s.zs.avail_in == 0) {
            reader.failAt(compressedPos, str("zlib stream is truncated: it ends after ", produced,
                                             " of UncompressedLength ", expectedLength, " bytes"));
        }
        zfail("inflate failed", ret);
    }
    if (produced != expectedLength)
        reader.failAt(compressedPos, str("zlib stream inflates to ", produced, " bytes but UncompressedLength is ",
                                         expectedLength));
    if (s.zs.avail_in != 0)
        reader.failAt(compressedPos + s.zs.total_in,
                      str(s.zs.avail_in, " bytes after the end of the zlib stream in the section"));
    out.resize(produced);
    return out;
}

namespace {

struct SectionParser {
    std::span<const std::uint8_t> file;
    LoadLog& log;
    std::vector<std::unique_ptr<std::vector<std::uint8_t>>>& buffers;

    /// Parses the section at `pos` that must end at or before `limit`; returns it,
    /// advances pos. Object records are appended to `objects`.
    M3GSection parse(std::size_t& pos, std::size_t limit, int index, std::uint32_t& nextObjectIndex,
                     std::vector<M3GObject>& objects) {
        ByteReader r(file.first(limit), sectionName(index), 0, &log);
        r.skip(pos, "preceding data");
        M3GSection sec;
        sec.index = index;
        sec.fileOffset = pos;
        if (r.remaining() < kSectionHeaderBytes)
            r.fail(str("truncated: section header needs ", kSectionHeaderBytes, " bytes, only ", r.remaining(),
                       " left"));
        sec.compressionScheme = r.readByte();
        if (sec.compressionScheme > 1)
            r.failAt(r.position() - 1,
                     str("unknown CompressionScheme ", int(sec.compressionScheme), " (0 or 1 allowed)"));
        const std::size_t lengthPos = r.position();
        sec.totalSectionLength = r.readUInt32();
        sec.uncompressedLength = r.readUInt32();
        if (sec.totalSectionLength < kSectionOverhead)
            r.failAt(lengthPos, str("TotalSectionLength ", sec.totalSectionLength, " is less than the ",
                                    kSectionOverhead, " bytes of section header and checksum"));
        const std::size_t available = limit - pos;
        if (sec.totalSectionLength > available)
            r.failAt(lengthPos, str("truncated: TotalSectionLength ", sec.totalSectionLength, " but only ",
                                    available, " bytes are left in the file"));
        const std::size_t storedLength = sec.totalSectionLength - kSectionOverhead;
        const std::size_t storedPos = r.position();
        const auto stored = r.readBytes(storedLength, "section Objects");
        const std::size_t checksumPos = r.position();
        sec.checksum = r.readUInt32();
        const std::uint32_t actual = adler32Of(file.subspan(pos, sec.totalSectionLength - 4));
        if (actual != sec.checksum)
            r.failAt(checksumPos, str("Adler-32 checksum mismatch: stored 0x", hex(sec.checksum), ", computed 0x",
                                      hex(actual)));

        bool inflated = false;
        std::size_t baseOffset = storedPos;
        if (sec.compressionScheme == 0) {
            if (sec.uncompressedLength != storedLength)
                r.failAt(lengthPos + 4, str("UncompressedLength ", sec.uncompressedLength,
                                            " of an uncompressed section must equal TotalSectionLength - 13 = ",
                                            storedLength));
            sec.objects = stored;
        } else {
            auto buf = std::make_unique<std::vector<std::uint8_t>>(
                inflateExact(stored, sec.uncompressedLength, r, storedPos));
            sec.objects = std::span<const std::uint8_t>(*buf);
            buffers.push_back(std::move(buf));
            inflated = true;
            baseOffset = 0;
        }
        pos += sec.totalSectionLength;

        // Object records.
        ByteReader o(sec.objects, sectionName(index), baseOffset, &log,
                     inflated ? str("of the inflated data of section ", index) : std::string());
        while (!o.atEnd()) {
            const std::size_t recPos = o.position();
            if (o.remaining() < 5)
                o.fail(str("truncated: object header needs 5 bytes (ObjectType, Length), only ", o.remaining(),
                           " left in the section"));
            M3GObject obj;
            obj.type = o.readByte();
            obj.section = index;
            obj.index = nextObjectIndex;
            obj.inflated = inflated;
            const std::uint32_t length = o.readUInt32();
            if (length > o.remaining())
                o.failAt(recPos + 1, str("object ", nextObjectIndex, " (", objectTypeName(obj.type), ", type ",
                                         int(obj.type), "): Length ", length, " but only ", o.remaining(),
                                         " bytes are left in the section"));
            obj.dataOffset = baseOffset + o.position();
            obj.data = o.readBytes(length, "object data");
            if (obj.type > kTypeWorld && obj.type != kTypeExternalReference)
                o.failAt(recPos, str("object ", nextObjectIndex, ": reserved ObjectType ", int(obj.type)));
            objects.push_back(obj);
            ++nextObjectIndex;
            ++sec.objectCount;
        }
        return sec;
    }

    static std::string hex(std::uint32_t v) {
        static const char* d = "0123456789ABCDEF";
        std::string s(8, '0');
        for (int i = 7; i >= 0; --i, v >>= 4) s[static_cast<std::size_t>(i)] = d[v & 0xF];
        return s;
    }
};

M3GHeader parseHeader(const M3GObject& obj, LoadLog& log) {
    ByteReader r = objectReader(obj, &log);
    M3GHeader h;
    h.versionMajor = r.readByte();
    h.versionMinor = r.readByte();
    if (h.versionMajor == 2)
        r.failAt(0, str("M3G 2.0 (JSR-297) files are not supported (header version ", int(h.versionMajor), ".",
                        int(h.versionMinor), ")"));
    if (h.versionMajor != 1)
        r.failAt(0, str("unsupported file version ", int(h.versionMajor), ".", int(h.versionMinor),
                        " (only 1.0 is defined)"));
    if (h.versionMinor != 0) {
        if (!log.lenient())
            r.failAt(0, str("file version 1.", int(h.versionMinor),
                            " is not 1.0 (Nokia accepts only 1.0; a lenient load accepts 1.x)"));
        r.warnAt(0, str("file version 1.", int(h.versionMinor), " read as 1.0"));
    }
    h.hasExternalReferences = r.readBoolean();
    h.totalFileSize = r.readUInt32();
    h.approximateContentSize = r.readUInt32();
    h.authoringField = r.readString();
    r.expectEnd("header object");
    return h;
}

}  // namespace

M3GFile parseM3GFile(std::span<const std::uint8_t> data, LoadLog& log) {
    M3GFile f;
    ByteReader id(data, "file identifier", 0, &log);
    if (data.empty()) throw IOException("empty input: no M3G file identifier");
    if (data.size() < kM3GFileIdentifier.size())
        id.failAt(data.size(), str("truncated: the 12-byte file identifier has only ", data.size(), " bytes"));
    for (std::size_t i = 0; i < kM3GFileIdentifier.size(); ++i)
        if (data[i] != kM3GFileIdentifier[i]) id.failAt(i, "not an M3G file: file identifier mismatch");
    std::size_t pos = kM3GFileIdentifier.size();
    if (pos == data.size())
        throw IOException(str("section 0: truncated: the file ends after the identifier at byte offset ", pos,
                              "; section 0 (header) is missing"));

    SectionParser sp{data, log, f.buffers_};
    std::uint32_t nextIndex = 1;

    // Section 0: the header, alone.
    const std::size_t sec0Pos = pos;
    M3GSection s0 = sp.parse(pos, data.size(), 0, nextIndex, f.objects);
    if (f.objects.empty() || f.objects[0].type != kTypeHeader)
        throw IOException(str("section 0: the first object must be the header (type 0) at byte offset ",
                              sec0Pos + kSectionHeaderBytes,
                              f.objects.empty() ? std::string(" but the section is empty")
                                                : str(" but it is ", objectTypeName(f.objects[0].type), ", type ",
                                                      int(f.objects[0].type))));
    if (f.objects.size() != 1) {
        const M3GObject& extra = f.objects[1];
        throw IOException(str(objectContext(extra), ": section 0 may hold only the header object (byte offset ",
                              extra.dataOffset - 5, extra.inflated ? " of the inflated data)" : ")"));
    }
    if (s0.compressionScheme != 0) {
        const std::string m = str("section 0: the header section is compressed (must be uncompressed) at byte offset ",
                                  sec0Pos);
        if (!log.lenient()) throw IOException(m + "; a lenient load accepts it");
        log.warn(m);
    }
    f.header = parseHeader(f.objects[0], log);
    f.sections.push_back(s0);

    // Where the file ends: TotalFileSize (lets an embedded file stop at its end).
    const std::uint32_t tfs = f.header.totalFileSize;
    const std::size_t tfsPos = f.objects[0].dataOffset + 3;
    std::size_t end = data.size();
    bool stopAtTfs = false;
    if (tfs == 0) {
        const std::string m = str("section 0, object 1 (Header, type 0): TotalFileSize is 0 at byte offset ", tfsPos);
        if (!log.lenient()) throw IOException(m + " (a lenient load ignores it)");
        log.warn(m + "; reading sections to the end of the data");
    } else if (tfs < pos || tfs > data.size()) {
        const std::string m =
            tfs < pos ? str("section 0, object 1 (Header, type 0): TotalFileSize ", tfs, " at byte offset ", tfsPos,
                            " is smaller than the header section, which ends at ", pos)
                      : str("section 0, object 1 (Header, type 0): truncated: TotalFileSize ", tfs,
                            " at byte offset ", tfsPos, " but only ", data.size(), " bytes are available");
        if (!log.lenient()) throw IOException(m);
        log.warn(m + "; reading sections to the end of the data");
    } else if (log.lenient()) {
        stopAtTfs = true;  // stop there if a section ends exactly there
    } else {
        end = tfs;
    }

    // Sections 1..n.
    int index = 1;
    while (pos < end) {
        if (stopAtTfs && pos == tfs) break;
        const std::size_t firstObject = f.objects.size();
        M3GSection s = sp.parse(pos, end, index, nextIndex, f.objects);
        for (std::size_t i = firstObject; i < f.objects.size(); ++i) {
            const M3GObject& o = f.objects[i];
            const std::size_t recOffset = o.dataOffset - 5;
            const std::string at =
                str(" (object at byte offset ", recOffset, o.inflated ? " of the inflated data)" : ")");
            if (o.type == kTypeHeader)
                throw IOException(objectContext(o) + ": the header object may appear only in section 0" + at);
            if (o.type == kTypeExternalReference) {
                if (index != 1)
                    throw IOException(objectContext(o) +
                                      ": external references may appear only in section 1" + at);
                if (!f.header.hasExternalReferences)
                    throw IOException(objectContext(o) +
                                      ": external reference but the header's hasExternalReferences is false" + at);
            } else if (index == 1 && f.header.hasExternalReferences) {
                throw IOException(objectContext(o) +
                                  ": section 1 may hold only external references (the header's "
                                  "hasExternalReferences is true)" +
                                  at);
            }
        }
        f.sections.push_back(std::move(s));
        ++index;
    }
    if (stopAtTfs && pos != tfs)
        log.warn(str("section 0, object 1 (Header, type 0): TotalFileSize ", tfs, " at byte offset ", tfsPos,
                     " does not match where the sections end (", pos, ")"));
    if (f.header.hasExternalReferences && f.sections.size() < 2) {
        const std::string m = "section 1: the header's hasExternalReferences is true but there is no section 1";
        if (!log.lenient()) throw IOException(m);
        log.warn(m);
    }
    f.fileSize = pos;
    return f;
}

}  // namespace m3g::detail
