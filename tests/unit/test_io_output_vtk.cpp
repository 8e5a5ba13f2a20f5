// VtkSeries: .vtp files are well-formed XML with the right point count, arrays, component
// counts and values that read back exactly; fields.pvd lists every dataset after each frame.
#include <gtest/gtest.h>

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

TEST(IoOutputVtk, VtpStructureAndValuesRoundTrip) {
  const fs::path dir = fresh_dir("vtk_roundtrip");
  const std::vector<Vec2> x{{0.1, 0.2}, {1.0 / 3.0, -2.5e-7}, {1e5, 7.0}};
  PointField p{"pressure", "Pa", 1, {101325.0, -0.1, 1.0 / 7.0}, {}};
  PointField v{"velocity", "m/s", 2, {1, 2, 3, 4, 5, 6}, {}};
  PointField sig{"stress", "Pa", 3, {1, 2, 3, 4, 5, 6, 7, 8, 9.5}, {"xx", "yy", "xy"}};
  PointField f{"deformation_gradient", "-", 4, std::vector<double>(12, 0.25), {}};
  {
    VtkSeries series(dir.string());
    series.write(0.125, "fluid", x, {p, v, sig, f});
    series.end_frame();
  }
  const Element doc = MiniXml(slurp((dir / "vtk/fluid_00000.vtp").string())).parse();
  const Element* vtk = child(doc, "VTKFile");
  ASSERT_NE(vtk, nullptr);
  EXPECT_EQ(vtk->attrs.at("type"), "PolyData");
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

  const Element* pts = child(*child(*piece, "Points"), "DataArray");
  ASSERT_NE(pts, nullptr);
  EXPECT_EQ(pts->attrs.at("NumberOfComponents"), "3");
  const auto xyz = numbers(pts->text);
  ASSERT_EQ(xyz.size(), 9u);
  for (std::size_t i = 0; i < 3; ++i) {
    EXPECT_EQ(xyz[3 * i], x[i].x);  // exact: shortest round-trip text
    EXPECT_EQ(xyz[3 * i + 1], x[i].y);
    EXPECT_EQ(xyz[3 * i + 2], 0.0);
  }

  const Element* pd = child(*piece, "PointData");
  ASSERT_NE(pd, nullptr);
  ASSERT_EQ(pd->children.size(), 4u);
  std::map<std::string, const Element*> arrays;
  for (const auto& a : pd->children) arrays[a.attrs.at("Name")] = &a;
  ASSERT_TRUE(arrays.count("pressure") && arrays.count("velocity") && arrays.count("stress") &&
              arrays.count("deformation_gradient"));
  EXPECT_EQ(arrays["pressure"]->attrs.at("NumberOfComponents"), "1");
  EXPECT_EQ(arrays["pressure"]->attrs.at("unit"), "Pa");
  EXPECT_EQ(numbers(arrays["pressure"]->text), p.values);
  // 2-component vectors are padded to 3 components for ParaView.
  EXPECT_EQ(arrays["velocity"]->attrs.at("NumberOfComponents"), "3");
  EXPECT_EQ(arrays["velocity"]->attrs.at("unit"), "m/s");
  EXPECT_EQ(numbers(arrays["velocity"]->text), (std::vector<double>{1, 2, 0, 3, 4, 0, 5, 6, 0}));
  EXPECT_EQ(arrays["stress"]->attrs.at("NumberOfComponents"), "3");
  EXPECT_EQ(arrays["stress"]->attrs.at("ComponentName2"), "xy");
  EXPECT_EQ(numbers(arrays["stress"]->text), sig.values);
  EXPECT_EQ(arrays["deformation_gradient"]->attrs.at("NumberOfComponents"), "4");
  EXPECT_EQ(numbers(arrays["deformation_gradient"]->text).size(), 12u);

  const Element* verts = child(*piece, "Verts");
  ASSERT_NE(verts, nullptr);
  ASSERT_EQ(verts->children.size(), 2u);
  EXPECT_EQ(numbers(verts->children[0].text), (std::vector<double>{0, 1, 2}));  // connectivity
  EXPECT_EQ(numbers(verts->children[1].text), (std::vector<double>{1, 2, 3}));  // offsets
}

TEST(IoOutputVtk, PvdListsEveryDatasetAfterEachFrame) {
  const fs::path dir = fresh_dir("vtk_pvd");
  VtkSeries series(dir.string());
  const std::vector<Vec2> a{{0, 0}, {1, 0}}, b{{0, 1}};
  for (int frame = 0; frame < 3; ++frame) {
    const double t = 0.01 * frame;
    series.write(t, "fluid", a, {{"rho", "kg/m^3", 1, {1000, 1001}, {}}});
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
  EXPECT_THROW(series.write(0, "bad/name", x, {}), std::invalid_argument);
  series.write(0, "fluid", x, {});
  EXPECT_THROW(series.write(0, "fluid", x, {}), std::invalid_argument);  // twice in a frame
}

}  // namespace
}  // namespace slamsph
