#include "io/checkpoint_file.h"

#include <cstdio>
#include <filesystem>
#include <fstream>
#include <sstream>

namespace slamsph {

namespace {

constexpr char kMagic[8] = {'S', 'L', 'A', 'M', 'S', 'P', 'H', 'C'};

template <class T>
void put_pod(std::string& out, const T& v) {
  out.append(reinterpret_cast<const char*>(&v), sizeof(T));
}
void put_string(std::string& out, std::string_view s) {
  put_pod(out, static_cast<std::uint64_t>(s.size()));
  out.append(s.data(), s.size());
}

// Sequential reader over a byte string with bounds checks.
struct Cursor {
  const std::string& data;
  std::size_t pos = 0;
  const std::string& path;
  void need(std::size_t n) const {
    if (pos + n > data.size()) throw std::runtime_error(path + ": truncated checkpoint");
  }
  template <class T>
  T pod() {
    need(sizeof(T));
    T v;
    std::memcpy(&v, data.data() + pos, sizeof(T));
    pos += sizeof(T);
    return v;
  }
  std::string str() {
    const auto n = pod<std::uint64_t>();
    need(n);
    std::string s = data.substr(pos, n);
    pos += n;
    return s;
  }
};

std::size_t element_size(BlobType t) {
  switch (t) {
    case BlobType::F64:
    case BlobType::I64:
    case BlobType::U64:
      return 8;
    case BlobType::Vec2:
      return sizeof(Vec2);
    case BlobType::Mat2:
      return sizeof(Mat2);
    case BlobType::U32:
    case BlobType::I32:
      return 4;
    case BlobType::U8:
    case BlobType::Text:
      return 1;
  }
  return 0;
}

}  // namespace

std::uint64_t fnv1a64(std::string_view data, std::uint64_t h) {
  for (unsigned char c : data) {
    h ^= c;
    h *= 1099511628211ull;
  }
  return h;
}

void CheckpointWriter::add(const std::string& section, std::string_view name, BlobType type,
                           const void* data, std::size_t count, std::size_t elem) {
  put_string(body_, section);
  put_string(body_, name);
  put_pod(body_, static_cast<std::uint8_t>(type));
  put_pod(body_, static_cast<std::uint64_t>(count));
  body_.append(static_cast<const char*>(data), count * elem);
  ++records_;
}

void CheckpointWriter::write_file(const std::string& path) const {
  std::string out(kMagic, sizeof kMagic);
  put_pod(out, header_.format_version);
  put_string(out, header_.code_version);
  put_pod(out, header_.case_hash);
  put_pod(out, header_.time);
  put_pod(out, header_.steps);
  put_pod(out, records_);
  out += body_;
  put_pod(out, fnv1a64(out));
  const std::string tmp = path + ".tmp";
  {
    std::ofstream f(tmp, std::ios::binary | std::ios::trunc);
    f.write(out.data(), static_cast<std::streamsize>(out.size()));
    f.flush();
    if (!f) throw std::runtime_error("cannot write checkpoint " + tmp);
  }
  std::error_code ec;
  std::filesystem::rename(tmp, path, ec);
  if (ec) throw std::runtime_error("cannot rename " + tmp + " to " + path + ": " + ec.message());
}

CheckpointReader::CheckpointReader(const std::string& path) : path_(path) {
  std::ifstream f(path, std::ios::binary);
  if (!f) throw std::runtime_error(path + ": cannot open checkpoint");
  std::ostringstream ss;
  ss << f.rdbuf();
  const std::string all = ss.str();
  if (all.size() < sizeof kMagic + 8 || std::memcmp(all.data(), kMagic, sizeof kMagic) != 0)
    throw std::runtime_error(path + ": not a slamsph checkpoint");
  std::uint64_t sum = 0;
  std::memcpy(&sum, all.data() + all.size() - 8, 8);
  if (fnv1a64(std::string_view(all).substr(0, all.size() - 8)) != sum)
    throw std::runtime_error(path + ": checkpoint is truncated or corrupt (checksum mismatch)");
  Cursor c{all, sizeof kMagic, path_};
  header_.format_version = c.pod<std::uint32_t>();
  if (header_.format_version != kCheckpointFormatVersion)
    throw std::runtime_error(path + ": checkpoint format version " +
                             std::to_string(header_.format_version) + ", this slamsph reads " +
                             std::to_string(kCheckpointFormatVersion));
  header_.code_version = c.str();
  header_.case_hash = c.pod<std::uint64_t>();
  header_.time = c.pod<double>();
  header_.steps = c.pod<std::int64_t>();
  const auto n = c.pod<std::uint64_t>();
  body_ = all.substr(0, all.size() - 8);
  for (std::uint64_t k = 0; k < n; ++k) {
    const std::string section = c.str();
    const std::string name = c.str();
    const auto type = static_cast<BlobType>(c.pod<std::uint8_t>());
    const auto count = c.pod<std::uint64_t>();
    const std::size_t bytes = count * element_size(type);
    if (element_size(type) == 0) throw std::runtime_error(path + ": unknown record type");
    c.need(bytes);
    records_[key(section, name)] = Record{type, count, c.pos};
    c.pos += bytes;
  }
  if (c.pos != all.size() - 8) throw std::runtime_error(path + ": trailing bytes in checkpoint");
}

const CheckpointReader::Record& CheckpointReader::find(const std::string& section,
                                                       std::string_view name, BlobType type) const {
  const auto it = records_.find(key(section, name));
  if (it == records_.end())
    throw std::runtime_error(path_ + ": checkpoint has no " + section + "/" + std::string(name));
  if (it->second.type != type)
    throw std::runtime_error(path_ + ": checkpoint record " + section + "/" + std::string(name) +
                             " has another type");
  return it->second;
}

}  // namespace slamsph
