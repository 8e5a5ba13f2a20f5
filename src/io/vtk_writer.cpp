// VTK XML PolyData (.vtp) + ParaView collection (.pvd) output; conventions in vtk_writer.h.
#include "io/vtk_writer.h"

#include <zlib.h>

#include <bit>

#include <cerrno>
#include <charconv>
#include <cmath>
#include <cstdint>
#include <cstdio>
#include <cstring>
#include <filesystem>
#include <fstream>
#include <limits>
#include <stdexcept>
#include <system_error>

namespace slamsph {
namespace {

// Shortest text that reads back to the same double.
void put_number(std::string& out, double v) {
  char buf[32];
  const auto r = std::to_chars(buf, buf + sizeof buf, v);
  out.append(buf, r.ptr);
}

std::string xml_escape(const std::string& s) {
  std::string r;
  for (char c : s) {
    switch (c) {
      case '&':
        r += "&amp;";
        break;
      case '<':
        r += "&lt;";
        break;
      case '>':
        r += "&gt;";
        break;
      case '"':
        r += "&quot;";
        break;
      default:
        r += c;
    }
  }
  return r;
}

// A set name becomes part of a file name: letters, digits, '_', '-', '.' only.
// Text inside an XML comment may not contain "--".
std::string comment_safe(std::string s) {
  for (std::size_t i = s.find("--"); i != std::string::npos; i = s.find("--", i)) s[i + 1] = '_';
  return s;
}

bool valid_set_name(const std::string& s) {
  if (s.empty() || s[0] == '.') return false;
  for (char c : s) {
    const bool ok = (c >= 'a' && c <= 'z') || (c >= 'A' && c <= 'Z') || (c >= '0' && c <= '9') ||
                    c == '_' || c == '-' || c == '.';
    if (!ok) return false;
  }
  return true;
}

std::string frame_file(const std::string& set_name, int frame) {
  char num[16];
  std::snprintf(num, sizeof num, "%05d", frame);
  return "vtk/" + set_name + "_" + num + ".vtp";
}

// Writes `text` to `path` with C stdio so that a failure carries the OS reason (errno).
void write_file(const std::string& path, const std::string& text) {
  std::FILE* f = std::fopen(path.c_str(), "wb");
  if (!f) throw std::system_error(errno, std::generic_category(), "cannot create " + path);
  const std::size_t put = std::fwrite(text.data(), 1, text.size(), f);
  const int err = put == text.size() ? 0 : errno;
  if (std::fclose(f) != 0 || put != text.size())
    throw std::system_error(err ? err : errno, std::generic_category(), "cannot write " + path);
}

// Appends the raw little-endian bytes of v (the writer runs on little-endian hosts only:
// x86-64 and AArch64 Linux; the static_assert below keeps it honest).
template <class T>
void put_raw(std::string& out, T v) {
  char b[sizeof(T)];
  std::memcpy(b, &v, sizeof(T));
  out.append(b, sizeof(T));
}

// One appended-data block in VTK's layout: uncompressed [UInt64 size][bytes]; zlib
// [UInt64 nblocks][UInt64 block size][UInt64 last block size][UInt64 csize...][blocks].
void append_block(std::string& appended, const std::string& bytes, bool zlib) {
  if (!zlib) {
    put_raw<std::uint64_t>(appended, bytes.size());
    appended += bytes;
    return;
  }
  constexpr std::size_t kBlock = 1 << 16;
  const std::size_t nblocks = bytes.empty() ? 0 : (bytes.size() + kBlock - 1) / kBlock;
  const std::size_t last = bytes.empty() ? 0 : bytes.size() - (nblocks - 1) * kBlock;
  std::vector<std::string> packed(nblocks);
  for (std::size_t k = 0; k < nblocks; ++k) {
    const std::size_t len = k + 1 == nblocks ? last : kBlock;
    uLongf cap = compressBound(static_cast<uLong>(len));
    packed[k].resize(cap);
    const int rc = compress2(reinterpret_cast<Bytef*>(packed[k].data()), &cap,
                             reinterpret_cast<const Bytef*>(bytes.data() + k * kBlock),
                             static_cast<uLong>(len), Z_BEST_SPEED);
    if (rc != Z_OK) throw std::runtime_error("zlib compress2 failed (" + std::to_string(rc) + ")");
    packed[k].resize(cap);
  }
  put_raw<std::uint64_t>(appended, nblocks);
  put_raw<std::uint64_t>(appended, kBlock);
  put_raw<std::uint64_t>(appended, last);
  for (const auto& p : packed) put_raw<std::uint64_t>(appended, p.size());
  for (const auto& p : packed) appended += p;
}

static_assert(std::endian::native == std::endian::little, "VTK output is written little-endian");

}  // namespace

VtkSeries::VtkSeries(std::string out_dir, VtkOptions options)
    : out_dir_(std::move(out_dir)), options_(options), pvd_path_(out_dir_ + "/fields.pvd") {
  std::error_code ec;
  std::filesystem::create_directories(out_dir_ + "/vtk", ec);
  if (ec) throw std::system_error(ec, "cannot create " + out_dir_ + "/vtk");
}

VtkSeries::VtkSeries(std::string out_dir, VtkOptions options, State state)
    : VtkSeries(std::move(out_dir), options) {
  frame_ = state.frame;
  parts_ = std::move(state.parts);
  entries_ = std::move(state.entries);
  write_pvd();
}

VtkSeries::~VtkSeries() {
  try {
    end_frame();
  } catch (...) {
    // Destructors must not throw; the frames already listed stay valid.
  }
}

std::string VtkSeries::vtp_path(const std::string& set_name, int frame) const {
  return out_dir_ + "/" + frame_file(set_name, frame);
}

int VtkSeries::part_of(const std::string& set_name) {
  for (std::size_t i = 0; i < parts_.size(); ++i)
    if (parts_[i] == set_name) return static_cast<int>(i);
  parts_.push_back(set_name);
  return static_cast<int>(parts_.size() - 1);
}

void VtkSeries::write(double time, const std::string& set_name, const std::vector<Vec2>& x,
                      const std::vector<PointField>& fields) {
  if (!valid_set_name(set_name))
    throw std::invalid_argument("VtkSeries: bad set name '" + set_name +
                                "' (letters, digits, _ - . only)");
  for (const auto& s : sets_this_frame_)
    if (s == set_name)
      throw std::invalid_argument("VtkSeries: set '" + set_name + "' written twice in frame " +
                                  std::to_string(frame_));
  const std::size_t n = x.size();
  for (const auto& f : fields) {
    if (f.name.empty()) throw std::invalid_argument("VtkSeries: field without a name");
    if (f.components != 1 && f.components != 2 && f.components != 4 && f.components != 6)
      throw std::invalid_argument("VtkSeries: field '" + f.name + "' has " +
                                  std::to_string(f.components) + " components");
    if (f.values.size() != n * static_cast<std::size_t>(f.components))
      throw std::invalid_argument("VtkSeries: field '" + f.name + "' of set '" + set_name +
                                  "' has " + std::to_string(f.values.size()) +
                                  " values, expected " + std::to_string(n) + " x " +
                                  std::to_string(f.components));
    if (!f.component_names.empty() &&
        f.component_names.size() != static_cast<std::size_t>(f.components))
      throw std::invalid_argument("VtkSeries: field '" + f.name +
                                  "' component_names size differs from components");
  }

  for (const auto& f : fields) {
    if (!f.integer) continue;
    for (double v : f.values)
      if (!(v == std::floor(v)) || std::abs(v) > 9.0e15)
        throw std::invalid_argument("VtkSeries: integer field '" + f.name + "' holds " +
                                    std::to_string(v));
  }

  // XML header with one <DataArray format="appended" offset=...> per array; the arrays'
  // bytes follow in <AppendedData> in the same order.
  const bool f64 = options_.float64;
  const char* real_type = f64 ? "Float64" : "Float32";
  std::string appended;
  auto real_array = [&](const std::vector<double>& v, int in_comp, int out_comp) {
    std::string bytes;
    bytes.reserve(n * static_cast<std::size_t>(out_comp) * (f64 ? 8 : 4));
    for (std::size_t i = 0; i < n; ++i)
      for (int c = 0; c < out_comp; ++c) {
        const double x =
            c < in_comp ? v[i * static_cast<std::size_t>(in_comp) + static_cast<std::size_t>(c)]
                        : 0.0;
        if (f64)
          put_raw<double>(bytes, x);
        else
          put_raw<float>(bytes, static_cast<float>(x));
      }
    const std::size_t offset = appended.size();
    append_block(appended, bytes, options_.zlib);
    return offset;
  };
  // Integers as Int32 when every value fits, else Int64; returns (offset, type).
  auto int_array = [&](const std::vector<double>& v) {
    bool fits32 = true;
    for (double x : v)
      fits32 = fits32 && x >= std::numeric_limits<std::int32_t>::min() &&
               x <= std::numeric_limits<std::int32_t>::max();
    std::string bytes;
    for (double x : v) {
      if (fits32)
        put_raw<std::int32_t>(bytes, static_cast<std::int32_t>(x));
      else
        put_raw<std::int64_t>(bytes, static_cast<std::int64_t>(x));
    }
    const std::size_t offset = appended.size();
    append_block(appended, bytes, options_.zlib);
    return std::pair<std::size_t, const char*>(offset, fits32 ? "Int32" : "Int64");
  };

  std::string s;
  s.reserve(2048 + 256 * fields.size());
  s += "<?xml version=\"1.0\"?>\n";
  std::string comment = "slamsph particle set '" + set_name + "', units:";
  for (const auto& f : fields) comment += " " + f.name + " [" + f.unit + "]";
  s += "<!-- " + comment_safe(xml_escape(comment)) + " -->\n";
  s += "<VTKFile type=\"PolyData\" version=\"1.0\" byte_order=\"LittleEndian\" "
       "header_type=\"UInt64\"";
  if (options_.zlib) s += " compressor=\"vtkZLibDataCompressor\"";
  s += ">\n";
  s += "  <PolyData>\n";
  s += "    <FieldData>\n";
  s += "      <DataArray type=\"Float64\" Name=\"TimeValue\" NumberOfTuples=\"1\" "
       "format=\"ascii\" unit=\"s\">";
  put_number(s, time);
  s += "</DataArray>\n";
  s += "    </FieldData>\n";
  s += "    <Piece NumberOfPoints=\"" + std::to_string(n) + "\" NumberOfVerts=\"" +
       std::to_string(n) + "\" NumberOfLines=\"0\" NumberOfStrips=\"0\" NumberOfPolys=\"0\">\n";
  s += "      <PointData>\n";
  for (const auto& f : fields) {
    const int out_comp = f.components == 2 ? 3 : f.components;
    std::string type = real_type;
    std::size_t offset = 0;
    if (f.integer) {
      const auto [o, t] = int_array(f.values);
      offset = o;
      type = t;
    } else {
      offset = real_array(f.values, f.components, out_comp);
    }
    s += "        <DataArray type=\"" + type + "\" Name=\"" + xml_escape(f.name) +
         "\" NumberOfComponents=\"" + std::to_string(out_comp) + "\" unit=\"" + xml_escape(f.unit) +
         "\"";
    for (std::size_t c = 0; c < f.component_names.size(); ++c)
      s += " ComponentName" + std::to_string(c) + "=\"" + xml_escape(f.component_names[c]) + "\"";
    s += " format=\"appended\" offset=\"" + std::to_string(offset) + "\"/>\n";
  }
  s += "      </PointData>\n";
  std::vector<double> xy(2 * n);
  for (std::size_t i = 0; i < n; ++i) xy[2 * i] = x[i].x, xy[2 * i + 1] = x[i].y;
  const std::size_t pts_offset = real_array(xy, 2, 3);
  s += "      <Points>\n";
  s += "        <DataArray type=\"" + std::string(real_type) +
       "\" Name=\"Points\" NumberOfComponents=\"3\" unit=\"m\" format=\"appended\" offset=\"" +
       std::to_string(pts_offset) + "\"/>\n";
  s += "      </Points>\n";
  std::vector<double> conn(n), offs(n);
  for (std::size_t i = 0; i < n; ++i) conn[i] = static_cast<double>(i), offs[i] = double(i + 1);
  const auto [conn_offset, conn_type] = int_array(conn);
  const auto [offs_offset, offs_type] = int_array(offs);
  s += "      <Verts>\n";
  s += "        <DataArray type=\"" + std::string(conn_type) +
       "\" Name=\"connectivity\" format=\"appended\" offset=\"" + std::to_string(conn_offset) +
       "\"/>\n";
  s += "        <DataArray type=\"" + std::string(offs_type) +
       "\" Name=\"offsets\" format=\"appended\" offset=\"" + std::to_string(offs_offset) + "\"/>\n";
  s += "      </Verts>\n";
  s += "    </Piece>\n";
  s += "  </PolyData>\n";
  s += "  <AppendedData encoding=\"raw\">\n   _";
  s += appended;
  s += "\n  </AppendedData>\n";
  s += "</VTKFile>\n";

  const std::string rel = frame_file(set_name, frame_);
  write_file(out_dir_ + "/" + rel, s);
  sets_this_frame_.push_back(set_name);
  entries_.push_back({time, part_of(set_name), rel});
}

void VtkSeries::end_frame() {
  if (sets_this_frame_.empty()) return;
  write_pvd();
  sets_this_frame_.clear();
  ++frame_;
}

void VtkSeries::write_pvd() const {
  std::string s;
  s += "<?xml version=\"1.0\"?>\n";
  s += "<VTKFile type=\"Collection\" version=\"1.0\" byte_order=\"LittleEndian\">\n";
  s += "  <Collection>\n";
  for (const auto& e : entries_) {
    s += "    <DataSet timestep=\"";
    put_number(s, e.time);
    s += "\" group=\"\" part=\"" + std::to_string(e.part) + "\" name=\"" +
         xml_escape(parts_[static_cast<std::size_t>(e.part)]) + "\" file=\"" + xml_escape(e.file) +
         "\"/>\n";
  }
  s += "  </Collection>\n";
  s += "</VTKFile>\n";
  const std::string tmp = pvd_path_ + ".tmp";
  write_file(tmp, s);
  std::error_code ec;
  std::filesystem::rename(tmp, pvd_path_, ec);
  if (ec) throw std::system_error(ec, "cannot rename " + tmp + " to " + pvd_path_);
}

}  // namespace slamsph
