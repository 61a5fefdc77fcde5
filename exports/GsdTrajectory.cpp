#include "exports/GsdTrajectory.hpp"

#include <array>
#include <bit>
#include <cstdint>
#include <cstring>
#include <string_view>
#include <vector>

#include "exports/ExportStream.hpp"

namespace granwave {

namespace {

static_assert(std::endian::native == std::endian::little,
              "GSD's header and index are little-endian C structs, written here byte for byte");

constexpr std::uint64_t kMagic = 0x65DF65DF65DF65DFull;
constexpr std::uint32_t packedVersion(std::uint32_t major, std::uint32_t minor) {
  return major << 16 | minor;
}
constexpr std::uint32_t kGsdVersion = packedVersion(2, 0);
constexpr std::uint32_t kHoomdSchemaVersion = packedVersion(1, 4);
constexpr std::size_t kHeaderBytes = 256;
constexpr std::size_t kNameSegment = 64;  // the namelist block is counted in 64-byte segments

// The file layer's element types.
enum class GsdType : std::uint8_t {
  Uint8 = 1,
  Uint32 = 3,
  Uint64 = 4,
  Int8 = 5,
  Float = 9,
  Double = 10
};

// Name ids: the namelist holds the names in this order, and each frame's chunks are written in
// it, so the index comes out sorted by frame, then by id, as the format requires.
enum Chunk : std::uint16_t {
  kStep,
  kDimensions,
  kBox,
  kN,
  kTypes,
  kTypeId,
  kMass,
  kDiameter,
  kPosition,
  kVelocity,
  kAngularVelocity,
  kTime,
  kPlateHeight,
  kChunks
};
constexpr std::array<std::string_view, kChunks> kNames{"configuration/step",
                                                       "configuration/dimensions",
                                                       "configuration/box",
                                                       "particles/N",
                                                       "particles/types",
                                                       "particles/typeid",
                                                       "particles/mass",
                                                       "particles/diameter",
                                                       "particles/position",
                                                       "particles/velocity",
                                                       "log/particles/angular_velocity",
                                                       "log/time",
                                                       "log/plate_height"};

struct IndexEntry {
  std::uint64_t frame, n;
  std::int64_t location;
  std::uint32_t m;
  std::uint16_t id;
  GsdType type;
};

template <class T>
void put(std::string& bytes, T value) {
  char raw[sizeof(T)];
  std::memcpy(raw, &value, sizeof(T));
  bytes.append(raw, sizeof(T));
}

// A 0-terminated string in a fixed field of `size` bytes (the header's names).
void putName(std::string& bytes, std::string_view name, std::size_t size) {
  std::string field(name.substr(0, size - 1));
  field.resize(size, '\0');
  bytes += field;
}

class GsdWriter final : public TrajectoryWriter {
 public:
  GsdWriter(const std::string& path, const std::string& target, TrajectoryHeader header)
      : stream_(path, target, true), h_(std::move(header)) {
    stream_.out() << std::string(kHeaderBytes, '\0');  // written for real by close()
    stream_.check();
  }

  void write(const Snapshot& s) override {
    const auto n = static_cast<std::uint64_t>(s.size());
    const BoxInfo& b = h_.box;
    chunk(kStep, GsdType::Uint64, 1, 1, std::vector<std::uint64_t>{s.step});
    if (frame_ == 0) writeConstants(n);
    // HOOMD's box is centred on the origin: the container's frame, centred.
    const double z0 = s.plate_height + 0.5 * b.height;
    std::vector<float> position(3 * n), velocity(3 * n);
    std::vector<double> spin(3 * n);
    for (std::size_t i = 0; i < n; ++i) {
      position[3 * i] = static_cast<float>(s.x[i] - 0.5 * b.width);
      position[3 * i + 2] = static_cast<float>(s.z[i] - z0);
      velocity[3 * i] = static_cast<float>(s.vx[i]);
      velocity[3 * i + 2] = static_cast<float>(s.vz[i]);
      spin[3 * i + 1] = s.omega[i];
    }
    chunk(kPosition, GsdType::Float, n, 3, position);
    chunk(kVelocity, GsdType::Float, n, 3, velocity);
    chunk(kAngularVelocity, GsdType::Double, n, 3, spin);
    chunk(kTime, GsdType::Double, 1, 1, std::vector<double>{s.time});
    chunk(kPlateHeight, GsdType::Double, 1, 1, std::vector<double>{s.plate_height});
    ++frame_;
  }

  void close() override {
    std::string index;
    for (const IndexEntry& e : index_) {
      put(index, e.frame);
      put(index, e.n);
      put(index, e.location);
      put(index, e.m);
      put(index, e.id);
      put(index, e.type);
      put(index, std::uint8_t{0});  // flags
    }
    index.append(32, '\0');  // a zeroed entry (location 0) ends the index
    std::string names;
    for (std::string_view name : kNames) (names += name) += '\0';
    names.resize((names.size() / kNameSegment + 1) * kNameSegment, '\0');  // the empty name ends it
    const auto index_at = static_cast<std::uint64_t>(offset_);
    const std::uint64_t names_at = index_at + index.size();
    stream_.out() << index << names;
    stream_.out().seekp(0);
    stream_.out() << header(index_at, index.size() / 32, names_at, names.size() / kNameSegment);
    stream_.close();
  }

 private:
  void writeConstants(std::uint64_t n) {
    const BoxInfo& b = h_.box;
    chunk(kDimensions, GsdType::Uint8, 1, 1, std::vector<std::uint8_t>{3});
    chunk(kBox, GsdType::Float, 6, 1,
          std::vector<float>{static_cast<float>(b.width), static_cast<float>(b.thickness),
                             static_cast<float>(b.height), 0, 0, 0});
    chunk(kN, GsdType::Uint32, 1, 1, std::vector<std::uint32_t>{static_cast<std::uint32_t>(n)});
    const std::string type = "disk";
    chunk(kTypes, GsdType::Int8, 1, static_cast<std::uint32_t>(type.size() + 1),
          std::vector<char>(type.c_str(), type.c_str() + type.size() + 1));
    chunk(kTypeId, GsdType::Uint32, n, 1, std::vector<std::uint32_t>(n, 0));
    chunk(kMass, GsdType::Float, n, 1, std::vector<float>(n, static_cast<float>(h_.mass)));
    chunk(kDiameter, GsdType::Float, n, 1, std::vector<float>(n, static_cast<float>(h_.diameter)));
  }

  template <class T>
  void chunk(Chunk id, GsdType type, std::uint64_t n, std::uint32_t m, const std::vector<T>& data) {
    index_.push_back({frame_, n, offset_, m, id, type});
    const std::size_t bytes = data.size() * sizeof(T);
    stream_.out().write(reinterpret_cast<const char*>(data.data()),
                        static_cast<std::streamsize>(bytes));
    stream_.check();
    offset_ += bytes;
  }

  std::string header(std::uint64_t index_at, std::uint64_t index_entries, std::uint64_t names_at,
                     std::uint64_t name_segments) const {
    std::string bytes;
    put(bytes, kMagic);
    put(bytes, index_at);
    put(bytes, index_entries);
    put(bytes, names_at);
    put(bytes, name_segments);
    put(bytes, kHoomdSchemaVersion);
    put(bytes, kGsdVersion);
    putName(bytes, "granwave " + h_.version, 64);  // application
    putName(bytes, "hoomd", 64);                   // schema
    bytes.append(80, '\0');                        // reserved
    return bytes;
  }

  ExportStream stream_;
  TrajectoryHeader h_;
  std::vector<IndexEntry> index_;
  std::uint64_t frame_ = 0;
  std::int64_t offset_ = kHeaderBytes;
};

}  // namespace

std::unique_ptr<TrajectoryWriter> makeGsdWriter(const std::string& path, const std::string& target,
                                                const TrajectoryHeader& header) {
  return std::make_unique<GsdWriter>(path, target, header);
}

}  // namespace granwave
