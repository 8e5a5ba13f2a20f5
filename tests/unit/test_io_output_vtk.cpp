// VtkSeries: .vtp files are well-formed XML headers with the right point count, arrays,
// types and component counts, followed by appended raw binary data (optionally zlib) that
// decodes to the values written (exactly in Float64, rounded to float in Float32); fields.pvd
// lists every dataset after each frame. tests/readback/vtk_readback.py reads the files of a
// real run with VTK's own reader.
#include <gtest/gtest.h>
#include <zlib.h>

#include <cstdint>
#include <cstring>

#include <charconv>
#include <filesystem>
#include <fstream>
#include <map>
#include <sstream>
#include <string>
#include <vector>

#include "io/vtk_writer.h"

namespace slamsph {
namespace {

namespace fs = std::filesystem;

struct Element {
  std::string name;
  std::map<std::string, std::string> attrs;
  std::string text;  // character data directly inside
  std::vector<Element> children;
};

// Minimal XML reader for what the writer produces: declaration, comments, elements with
// double-quoted attributes, character data. Throws on mismatched tags.
class MiniXml {
 public:
  explicit MiniXml(std::string s) : s_(std::move(s)) {}
  Element parse() {
    Element root;
    root.name = "#document";
    parse_content(root);
    skip_ws();
    if (pos_ != s_.size()) throw std::runtime_error("trailing content");
    return root;
  }

 private:
  void skip_ws() {
    while (pos_ < s_.size() && std::isspace(static_cast<unsigned char>(s_[pos_]))) ++pos_;
  }
  void parse_content(Element& parent) {
    while (pos_ < s_.size()) {
      if (s_.compare(pos_, 4, "<!--") == 0) {
        const auto e = s_.find("-->", pos_);
        if (e == std::string::npos) throw std::runtime_error("unterminated comment");
        pos_ = e + 3;
      } else if (s_.compare(pos_, 2, "<?") == 0) {
        pos_ = s_.find("?>", pos_) + 2;
      } else if (s_.compare(pos_, 2, "</") == 0) {
        const auto e = s_.find('>', pos_);
        const std::string name = s_.substr(pos_ + 2, e - pos_ - 2);
        if (name != parent.name) throw std::runtime_error("mismatched </" + name + ">");
        pos_ = e + 1;
        return;
      } else if (s_[pos_] == '<') {
        parent.children.push_back(parse_element());
      } else {
        const auto e = s_.find('<', pos_);
        parent.text += s_.substr(pos_, e - pos_);
        pos_ = e == std::string::npos ? s_.size() : e;
      }
    }
    if (parent.name != "#document") throw std::runtime_error("unclosed <" + parent.name + ">");
  }
  Element parse_element() {
    Element el;
    ++pos_;
    while (pos_ < s_.size() && !std::isspace(static_cast<unsigned char>(s_[pos_])) &&
           s_[pos_] != '>' && s_[pos_] != '/')
      el.name += s_[pos_++];
    for (;;) {
      skip_ws();
      if (s_.compare(pos_, 2, "/>") == 0) {
        pos_ += 2;
        return el;
      }
      if (s_[pos_] == '>') {
        ++pos_;
        parse_content(el);
        return el;
      }
      const auto eq = s_.find('=', pos_);
      const std::string key = s_.substr(pos_, eq - pos_);
      if (s_[eq + 1] != '"') throw std::runtime_error("unquoted attribute " + key);
      const auto close = s_.find('"', eq + 2);
      if (el.attrs.count(key)) throw std::runtime_error("duplicate attribute " + key);
      el.attrs[key] = s_.substr(eq + 2, close - eq - 2);
      pos_ = close + 1;
    }
  }
  std::string s_;
  std::size_t pos_ = 0;
};

std::string slurp(const std::string& path) {
  std::ifstream f(path);
  EXPECT_TRUE(f.good()) << path;
  std::stringstream ss;
  ss << f.rdbuf();
  return ss.str();
}

const Element* child(const Element& e, const std::string& name) {
  for (const auto& c : e.children)
    if (c.name == name) return &c;
  return nullptr;
}

std::vector<double> numbers(const std::string& text) {
  std::vector<double> v;
  std::istringstream is(text);
  std::string tok;
  while (is >> tok) {
    double x = 0;
    const auto r = std::from_chars(tok.data(), tok.data() + tok.size(), x);
    EXPECT_TRUE(r.ec == std::errc() && r.ptr == tok.data() + tok.size()) << tok;
    v.push_back(x);
  }
  return v;
}

fs::path fresh_dir(const std::string& name) {
  const fs::path d = fs::path(testing::TempDir()) / ("slamsph_" + name);
  fs::remove_all(d);
  return d;
}

// A .vtp file split into its XML header (parsed) and its appended binary data.
struct Vtp {
  Element doc;
  std::string data;  // bytes after the '_' marker
  bool zlib = false;
};

Vtp read_vtp(const std::string& path) {
  const std::string s = slurp(path);
  const std::size_t app = s.find("<AppendedData encoding=\"raw\">");
  EXPECT_NE(app, std::string::npos) << path;
  const std::size_t mark = s.find('_', app);
  const std::size_t end = s.rfind("</AppendedData>");
  Vtp v;
  v.doc = MiniXml(s.substr(0, app) + "</VTKFile>\n").parse();
  v.data = s.substr(mark + 1, end - mark - 1);
  v.zlib = s.find("compressor=\"vtkZLibDataCompressor\"") < app;
  return v;
}

std::uint64_t u64(const std::string& d, std::size_t at) {
  std::uint64_t x = 0;
  std::memcpy(&x, d.data() + at, 8);
  return x;
}

// The decoded values of one <DataArray format="appended">, converted to double.
std::vector<double> values(const Vtp& v, const Element& da) {
  EXPECT_EQ(da.attrs.at("format"), "appended");
  const std::size_t off = std::stoul(da.attrs.at("offset"));
  std::string bytes;
  if (!v.zlib) {
    const std::uint64_t n = u64(v.data, off);
    bytes = v.data.substr(off + 8, n);
  } else {
    const std::uint64_t nb = u64(v.data, off), bs = u64(v.data, off + 8),
                        last = u64(v.data, off + 16);
    std::size_t at = off + 24 + 8 * nb;
    for (std::uint64_t k = 0; k < nb; ++k) {
      const std::uint64_t cs = u64(v.data, off + 24 + 8 * k);
      std::string block(k + 1 == nb ? last : bs, '\0');
      uLongf len = block.size();
      EXPECT_EQ(uncompress(reinterpret_cast<Bytef*>(block.data()), &len,
                           reinterpret_cast<const Bytef*>(v.data.data() + at), cs),
                Z_OK);
      bytes += block;
      at += cs;
    }
  }
  const std::string type = da.attrs.at("type");
  std::vector<double> out;
  auto take = [&](auto zero) {
    using T = decltype(zero);
    EXPECT_EQ(bytes.size() % sizeof(T), 0u);
    for (std::size_t i = 0; i + sizeof(T) <= bytes.size(); i += sizeof(T)) {
      T x;
      std::memcpy(&x, bytes.data() + i, sizeof(T));
      out.push_back(static_cast<double>(x));
    }
  };
  if (type == "Float64")
    take(double{});
  else if (type == "Float32")
    take(float{});
  else if (type == "Int32")
    take(std::int32_t{});
  else if (type == "Int64")
    take(std::int64_t{});
  else
    ADD_FAILURE() << "unexpected type " << type;
  return out;
}

std::vector<double> as_float(const std::vector<double>& v) {
  std::vector<double> r;
  for (double x : v) r.push_back(static_cast<float>(x));
  return r;
}

void check_roundtrip(const VtkOptions& opt, const std::string& name) {
  SCOPED_TRACE(name);
  const fs::path dir = fresh_dir(name);
  const std::vector<Vec2> x{{0.1, 0.2}, {1.0 / 3.0, -2.5e-7}, {1e5, 7.0}};
  PointField p{"pressure", "Pa", 1, {101325.0, -0.1, 1.0 / 7.0}, {}};
  PointField v{"velocity", "m/s", 2, {1, 2, 3, 4, 5, 6}, {}};
  std::vector<double> s6;
  for (int i = 0; i < 18; ++i) s6.push_back(0.5 * i + 1.0 / 3.0);
  PointField sig{"stress", "Pa", 6, s6, {"XX", "YY", "ZZ", "XY", "YZ", "XZ"}};
  PointField f{"deformation_gradient", "-", 4, std::vector<double>(12, 0.25), {}};
  PointField id{"id", "-", 1, {0, 7, 3000000000.0}, {}, true};  // > 2^31: Int64
  PointField set{"set", "-", 1, {2, 2, 2}, {}, true};
  {
    VtkSeries series(dir.string(), opt);
    series.write(0.125, "fluid", x, {p, v, sig, f, id, set});
    series.end_frame();
  }
  const Vtp vtp = read_vtp((dir / "vtk/fluid_00000.vtp").string());
  const Element* vtk = child(vtp.doc, "VTKFile");
  ASSERT_NE(vtk, nullptr);
  EXPECT_EQ(vtk->attrs.at("type"), "PolyData");
  EXPECT_EQ(vtk->attrs.at("header_type"), "UInt64");
  EXPECT_EQ(vtp.zlib, opt.zlib);
  const Element* poly = child(*vtk, "PolyData");
  ASSERT_NE(poly, nullptr);
  const Element* fd = child(*poly, "FieldData");
  ASSERT_NE(fd, nullptr);
  EXPECT_EQ(fd->children.at(0).attrs.at("Name"), "TimeValue");
  EXPECT_EQ(numbers(fd->children.at(0).text), std::vector<double>{0.125});
  const Element* piece = child(*poly, "Piece");
  ASSERT_NE(piece, nullptr);
  EXPECT_EQ(piece->attrs.at("NumberOfPoints"), "3");
  EXPECT_EQ(piece->attrs.at("NumberOfVerts"), "3");
  const std::string real = opt.float64 ? "Float64" : "Float32";
  auto expect_real = [&](const std::vector<double>& got, const std::vector<double>& want) {
    EXPECT_EQ(got, opt.float64 ? want : as_float(want));  // exact: binary, no text rounding
  };

  const Element* pts = child(*child(*piece, "Points"), "DataArray");
  ASSERT_NE(pts, nullptr);
  EXPECT_EQ(pts->attrs.at("NumberOfComponents"), "3");
  EXPECT_EQ(pts->attrs.at("type"), real);
  std::vector<double> want_xyz;
  for (const Vec2& q : x) want_xyz.insert(want_xyz.end(), {q.x, q.y, 0.0});
  expect_real(values(vtp, *pts), want_xyz);

  const Element* pd = child(*piece, "PointData");
  ASSERT_NE(pd, nullptr);
  ASSERT_EQ(pd->children.size(), 6u);
  std::map<std::string, const Element*> arrays;
  for (const auto& a : pd->children) arrays[a.attrs.at("Name")] = &a;
  ASSERT_EQ(arrays.size(), 6u);
  EXPECT_EQ(arrays["pressure"]->attrs.at("NumberOfComponents"), "1");
  EXPECT_EQ(arrays["pressure"]->attrs.at("unit"), "Pa");
  EXPECT_EQ(arrays["pressure"]->attrs.at("type"), real);
  expect_real(values(vtp, *arrays["pressure"]), p.values);
  // 2-component vectors are padded to 3 components for ParaView.
  EXPECT_EQ(arrays["velocity"]->attrs.at("NumberOfComponents"), "3");
  EXPECT_EQ(arrays["velocity"]->attrs.at("unit"), "m/s");
  expect_real(values(vtp, *arrays["velocity"]), {1, 2, 0, 3, 4, 0, 5, 6, 0});
  // Symmetric tensors: 6 components with names, which ParaView shows as a tensor.
  EXPECT_EQ(arrays["stress"]->attrs.at("NumberOfComponents"), "6");
  EXPECT_EQ(arrays["stress"]->attrs.at("ComponentName2"), "ZZ");
  EXPECT_EQ(arrays["stress"]->attrs.at("ComponentName3"), "XY");
  expect_real(values(vtp, *arrays["stress"]), sig.values);
  EXPECT_EQ(arrays["deformation_gradient"]->attrs.at("NumberOfComponents"), "4");
  EXPECT_EQ(values(vtp, *arrays["deformation_gradient"]).size(), 12u);
  // Integer fields: Int64 when a value exceeds Int32, else Int32; exact either way.
  EXPECT_EQ(arrays["id"]->attrs.at("type"), "Int64");
  EXPECT_EQ(values(vtp, *arrays["id"]), id.values);
  EXPECT_EQ(arrays["set"]->attrs.at("type"), "Int32");
  EXPECT_EQ(values(vtp, *arrays["set"]), set.values);

  const Element* verts = child(*piece, "Verts");
  ASSERT_NE(verts, nullptr);
  ASSERT_EQ(verts->children.size(), 2u);
  EXPECT_EQ(values(vtp, verts->children[0]), (std::vector<double>{0, 1, 2}));  // connectivity
  EXPECT_EQ(values(vtp, verts->children[1]), (std::vector<double>{1, 2, 3}));  // offsets
}

TEST(IoOutputVtk, Float32RawRoundTrip) {
  check_roundtrip({}, "vtk_f32");
}
TEST(IoOutputVtk, Float64RawRoundTrip) {
  check_roundtrip({true, false}, "vtk_f64");
}
TEST(IoOutputVtk, Float32ZlibRoundTrip) {
  check_roundtrip({false, true}, "vtk_f32z");
}
TEST(IoOutputVtk, Float64ZlibRoundTrip) {
  check_roundtrip({true, true}, "vtk_f64z");
}

// A field larger than one 64 KiB zlib block is split into several blocks and decodes whole.
TEST(IoOutputVtk, ZlibSplitsLargeArraysIntoBlocks) {
  const fs::path dir = fresh_dir("vtk_zblocks");
  const std::size_t n = 40000;  // 40000 doubles = 320 kB: 5 blocks
  std::vector<Vec2> x(n);
  std::vector<double> p(n);
  for (std::size_t i = 0; i < n; ++i) x[i] = {0.001 * i, 0.0}, p[i] = std::sin(0.01 * i);
  {
    VtkSeries series(dir.string(), {true, true});
    series.write(0.0, "fluid", x, {{"pressure", "Pa", 1, p, {}}});
  }
  const Vtp vtp = read_vtp((dir / "vtk/fluid_00000.vtp").string());
  const Element* pd =
      child(*child(*child(*child(vtp.doc, "VTKFile"), "PolyData"), "Piece"), "PointData");
  ASSERT_NE(pd, nullptr);
  const std::size_t off = std::stoul(pd->children.at(0).attrs.at("offset"));
  EXPECT_EQ(u64(vtp.data, off), 5u);  // number of blocks
  EXPECT_EQ(values(vtp, pd->children.at(0)), p);
}

TEST(IoOutputVtk, PvdListsEveryDatasetAfterEachFrame) {
  const fs::path dir = fresh_dir("vtk_pvd");
  VtkSeries series(dir.string());
  const std::vector<Vec2> a{{0, 0}, {1, 0}}, b{{0, 1}};
  for (int frame = 0; frame < 3; ++frame) {
    const double t = 0.01 * frame;
    series.write(t, "fluid", a, {{"rho", "kg/m^3", 1, {1000, 1001}, {}, false}});
    series.write(t, "cylinder", b, {});
    series.end_frame();

    const Element doc = MiniXml(slurp(series.pvd_path())).parse();
    const Element* coll = child(*child(doc, "VTKFile"), "Collection");
    ASSERT_NE(coll, nullptr);
    ASSERT_EQ(coll->children.size(), static_cast<std::size_t>(2 * (frame + 1)));
    for (int k = 0; k <= frame; ++k) {
      const Element& f = coll->children[static_cast<std::size_t>(2 * k)];
      const Element& c = coll->children[static_cast<std::size_t>(2 * k + 1)];
      EXPECT_EQ(numbers(f.attrs.at("timestep")), std::vector<double>{0.01 * k});
      EXPECT_EQ(f.attrs.at("part"), "0");
      EXPECT_EQ(c.attrs.at("part"), "1");
      char num[8];
      std::snprintf(num, sizeof num, "%05d", k);
      EXPECT_EQ(f.attrs.at("file"), std::string("vtk/fluid_") + num + ".vtp");
      EXPECT_EQ(c.attrs.at("file"), std::string("vtk/cylinder_") + num + ".vtp");
      EXPECT_TRUE(fs::exists(dir / c.attrs.at("file")));
    }
  }
  EXPECT_EQ(series.frames_written(), 3);
  EXPECT_FALSE(fs::exists(series.pvd_path() + ".tmp"));
}

TEST(IoOutputVtk, UnfinishedFrameIsListedOnDestruction) {
  const fs::path dir = fresh_dir("vtk_dtor");
  {
    VtkSeries series(dir.string());
    series.write(0.0, "fluid", {{0, 0}}, {});
  }
  const Element doc = MiniXml(slurp((dir / "fields.pvd").string())).parse();
  EXPECT_EQ(child(*child(doc, "VTKFile"), "Collection")->children.size(), 1u);
}

TEST(IoOutputVtk, RejectsInconsistentInput) {
  const fs::path dir = fresh_dir("vtk_bad");
  VtkSeries series(dir.string());
  const std::vector<Vec2> x{{0, 0}, {1, 1}};
  EXPECT_THROW(series.write(0, "fluid", x, {{"p", "Pa", 1, {1.0}, {}}}), std::invalid_argument);
  EXPECT_THROW(series.write(0, "fluid", x, {{"v", "m/s", 0, {}, {}}}), std::invalid_argument);
  EXPECT_THROW(series.write(0, "fluid", x, {{"s", "Pa", 3, std::vector<double>(6, 1.0), {}}}),
               std::invalid_argument);  // 3 components: neither vector nor VTK tensor
  EXPECT_THROW(series.write(0, "fluid", x, {{"id", "-", 1, {1.0, 1.5}, {}, true}}),
               std::invalid_argument);  // non-integer value in an integer field
  EXPECT_THROW(series.write(0, "bad/name", x, {}), std::invalid_argument);
  series.write(0, "fluid", x, {});
  EXPECT_THROW(series.write(0, "fluid", x, {}), std::invalid_argument);  // twice in a frame
}

}  // namespace
}  // namespace slamsph
