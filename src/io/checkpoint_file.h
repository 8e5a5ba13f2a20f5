// The binary container of a checkpoint (slamsph run --checkpoint-interval, slamsph resume).
//
// Layout (little-endian, the writing machine's doubles; all counts uint64):
//   magic "SLAMSPHC" (8 bytes), format version (uint32), code version (string),
//   case hash (uint64), simulated time (double), fluid steps (int64), record count,
//   records, then an FNV-1a 64 checksum of every byte before it.
//   A string is its length then its bytes. A record is: section (string), name (string),
//   element type (uint8, BlobType), element count, then count × element size bytes.
// Sections name a part of the state ("fluid", "body/0", "recorder", ...); names are the
// field registry's names (core/field_registry.h). Files are written to a temporary name
// and renamed, so a checkpoint on disk is always complete; the reader checks the
// checksum anyway and refuses a truncated or corrupt file.
#pragma once
#include <cstdint>
#include <cstring>
#include <map>
#include <stdexcept>
#include <string>
#include <string_view>
#include <type_traits>
#include <vector>

#include "core/vec.h"

namespace slamsph {

inline constexpr std::uint32_t kCheckpointFormatVersion = 1;

enum class BlobType : std::uint8_t {
  F64 = 1,
  Vec2 = 2,
  Mat2 = 3,
  I64 = 4,
  U32 = 5,
  U8 = 6,
  I32 = 7,
  U64 = 8,
  Text = 9
};

template <class T>
constexpr BlobType blob_type() {
  if constexpr (std::is_same_v<T, double>)
    return BlobType::F64;
  else if constexpr (std::is_same_v<T, Vec2>)
    return BlobType::Vec2;
  else if constexpr (std::is_same_v<T, Mat2>)
    return BlobType::Mat2;
  else if constexpr (std::is_same_v<T, std::int64_t> || std::is_same_v<T, long>)
    return BlobType::I64;
  else if constexpr (std::is_same_v<T, std::uint32_t>)
    return BlobType::U32;
  else if constexpr (std::is_same_v<T, std::uint8_t>)
    return BlobType::U8;
  else if constexpr (std::is_same_v<T, int>)
    return BlobType::I32;
  else if constexpr (std::is_same_v<T, std::uint64_t>)
    return BlobType::U64;
  else if constexpr (std::is_same_v<T, char>)
    return BlobType::Text;
  else
    static_assert(sizeof(T) == 0, "type not storable in a checkpoint");
}

struct CheckpointHeader {
  std::uint32_t format_version = kCheckpointFormatVersion;
  std::string code_version;     // SLAMSPH_VERSION of the writer
  std::uint64_t case_hash = 0;  // of the resolved case (app/checkpoint.h)
  double time = 0.0;            // [s]
  std::int64_t steps = 0;       // fluid steps
};

class CheckpointWriter {
 public:
  explicit CheckpointWriter(CheckpointHeader header) : header_(std::move(header)) {}

  template <class T>
  void put(const std::string& section, std::string_view name, const std::vector<T>& v) {
    add(section, name, blob_type<T>(), v.data(), v.size(), sizeof(T));
  }
  template <class T>
  void put_value(const std::string& section, std::string_view name, const T& v) {
    add(section, name, blob_type<T>(), &v, 1, sizeof(T));
  }
  void put_text(const std::string& section, std::string_view name, const std::string& s) {
    add(section, name, BlobType::Text, s.data(), s.size(), 1);
  }
  // Writes `path` via `path`.tmp and a rename; throws std::runtime_error on I/O failure.
  void write_file(const std::string& path) const;
  std::size_t bytes() const { return body_.size(); }

 private:
  void add(const std::string& section, std::string_view name, BlobType type, const void* data,
           std::size_t count, std::size_t elem);
  CheckpointHeader header_;
  std::string body_;
  std::uint64_t records_ = 0;
};

class CheckpointReader {
 public:
  // Reads and checks the whole file; throws std::runtime_error naming the file for a bad
  // magic, an unknown format version, a truncated file or a checksum mismatch.
  explicit CheckpointReader(const std::string& path);

  const CheckpointHeader& header() const { return header_; }
  const std::string& path() const { return path_; }
  bool has(const std::string& section, std::string_view name) const {
    return records_.count(key(section, name)) > 0;
  }
  // Throws std::runtime_error if the record is missing or of another type.
  template <class T>
  std::vector<T> get(const std::string& section, std::string_view name) const {
    const Record& r = find(section, name, blob_type<T>());
    std::vector<T> out(r.count);
    if (r.count) std::memcpy(out.data(), body_.data() + r.offset, r.count * sizeof(T));
    return out;
  }
  template <class T>
  T get_value(const std::string& section, std::string_view name) const {
    const std::vector<T> v = get<T>(section, name);
    if (v.size() != 1)
      throw std::runtime_error(path_ + ": " + section + "/" + std::string(name) +
                               ": expected one value");
    return v[0];
  }
  std::string get_text(const std::string& section, std::string_view name) const {
    const std::vector<char> v = get<char>(section, name);
    return std::string(v.begin(), v.end());
  }

 private:
  struct Record {
    BlobType type;
    std::size_t count, offset;
  };
  static std::string key(const std::string& section, std::string_view name) {
    return section + '\n' + std::string(name);
  }
  const Record& find(const std::string& section, std::string_view name, BlobType type) const;
  std::string path_;
  CheckpointHeader header_;
  std::string body_;
  std::map<std::string, Record> records_;
};

// FNV-1a 64-bit hash (case hashes, checksums).
std::uint64_t fnv1a64(std::string_view data, std::uint64_t h = 14695981039346656037ull);

}  // namespace slamsph
