// VTK XML PolyData (.vtp) + ParaView collection (.pvd) output; conventions in vtk_writer.h.
#include "io/vtk_writer.h"

#include <charconv>
#include <cmath>
#include <cstdio>
#include <filesystem>
#include <fstream>
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

void write_text_file(const std::string& path, const std::string& text) {
  std::ofstream f(path, std::ios::binary | std::ios::trunc);
  if (!f) throw std::runtime_error("cannot open " + path + " for writing");
  f.write(text.data(), static_cast<std::streamsize>(text.size()));
  f.close();
  if (!f) throw std::runtime_error("error writing " + path);
}

}  // namespace

VtkSeries::VtkSeries(std::string out_dir)
    : out_dir_(std::move(out_dir)), pvd_path_(out_dir_ + "/fields.pvd") {
  std::error_code ec;
  std::filesystem::create_directories(out_dir_ + "/vtk", ec);
  if (ec) throw std::runtime_error("cannot create " + out_dir_ + "/vtk: " + ec.message());
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
    if (f.components < 1 || f.components > 9)
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

  std::string s;
  s.reserve(64 + n * 40 * (1 + fields.size()));
  s += "<?xml version=\"1.0\"?>\n";
  std::string comment = "slamsph particle set '" + set_name + "', units:";
  for (const auto& f : fields) comment += " " + f.name + " [" + f.unit + "]";
  s += "<!-- " + comment_safe(xml_escape(comment)) + " -->\n";
  s += "<VTKFile type=\"PolyData\" version=\"1.0\" byte_order=\"LittleEndian\">\n";
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
    s += "        <DataArray type=\"Float64\" Name=\"" + xml_escape(f.name) +
         "\" NumberOfComponents=\"" + std::to_string(out_comp) + "\" unit=\"" + xml_escape(f.unit) +
         "\"";
    for (std::size_t c = 0; c < f.component_names.size(); ++c)
      s += " ComponentName" + std::to_string(c) + "=\"" + xml_escape(f.component_names[c]) + "\"";
    s += " format=\"ascii\">\n";
    const int nc = f.components;
    for (std::size_t i = 0; i < n; ++i) {
      s += "         ";
      for (int c = 0; c < nc; ++c) {
        s += ' ';
        put_number(s, f.values[i * static_cast<std::size_t>(nc) + static_cast<std::size_t>(c)]);
      }
      if (nc == 2) s += " 0";
      s += '\n';
    }
    s += "        </DataArray>\n";
  }
  s += "      </PointData>\n";
  s += "      <Points>\n";
  s += "        <DataArray type=\"Float64\" Name=\"Points\" NumberOfComponents=\"3\" "
       "unit=\"m\" format=\"ascii\">\n";
  for (std::size_t i = 0; i < n; ++i) {
    s += "          ";
    put_number(s, x[i].x);
    s += ' ';
    put_number(s, x[i].y);
    s += " 0\n";
  }
  s += "        </DataArray>\n";
  s += "      </Points>\n";
  s += "      <Verts>\n";
  s += "        <DataArray type=\"Int64\" Name=\"connectivity\" format=\"ascii\">\n";
  for (std::size_t i = 0; i < n; ++i) {
    s += (i % 16 == 0) ? "          " : " ";
    s += std::to_string(i);
    if (i % 16 == 15 || i + 1 == n) s += '\n';
  }
  s += "        </DataArray>\n";
  s += "        <DataArray type=\"Int64\" Name=\"offsets\" format=\"ascii\">\n";
  for (std::size_t i = 0; i < n; ++i) {
    s += (i % 16 == 0) ? "          " : " ";
    s += std::to_string(i + 1);
    if (i % 16 == 15 || i + 1 == n) s += '\n';
  }
  s += "        </DataArray>\n";
  s += "      </Verts>\n";
  s += "    </Piece>\n";
  s += "  </PolyData>\n";
  s += "</VTKFile>\n";

  const std::string rel = frame_file(set_name, frame_);
  write_text_file(out_dir_ + "/" + rel, s);
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
  write_text_file(tmp, s);
  std::error_code ec;
  std::filesystem::rename(tmp, pvd_path_, ec);
  if (ec)
    throw std::runtime_error("cannot rename " + tmp + " to " + pvd_path_ + ": " + ec.message());
}

}  // namespace slamsph
