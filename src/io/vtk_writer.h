// Particle output for ParaView: one VTK XML PolyData file (.vtp) per particle set and frame,
// plus a ParaView collection (fields.pvd) that indexes them by time and part.
//
// Layout: <out_dir>/vtk/<set>_<frame:05>.vtp and <out_dir>/fields.pvd. fields.pvd is
// rewritten complete (via a temporary file and rename) at every end_frame(), so a run
// that stops early still leaves a readable time series that lists only finished files.
//
// File conventions (kept so that ParaView 5.x reads the files without plugins):
//  - Data are "appended" raw binary (no base64), little-endian, with a UInt64 size header
//    per array; with zlib compression (VtkOptions::zlib) each array is split into 64 KiB
//    blocks compressed separately (vtkZLibDataCompressor's layout).
//  - Real fields and the points are Float32 by default (VtkOptions::float64 for Float64);
//    integer fields (PointField::integer: ids, set and flag numbers) are Int32 when every
//    value fits, else Int64; the time is always Float64.
//  - Points are 3D with z = 0; each particle is a VTK_VERTEX cell, so ParaView shows
//    points without a Glyph filter.
//  - Array names stay clean ("pressure"); the unit is an extra attribute unit="Pa" on the
//    <DataArray> element (readers ignore unknown attributes) and is repeated in an XML
//    comment at the top of the file.
//  - Component counts: 1 scalar; 2 vector, written with 3 components (z = 0) so that
//    ParaView treats it as a vector; 4 a full 2x2 tensor row-major (xx, xy, yx, yy);
//    6 a symmetric tensor in VTK's order (XX, YY, ZZ, XY, YZ, XZ), which ParaView shows as
//    a tensor (eigenvalues, Tensor Glyph). Component names, when given, become
//    ComponentName<i> attributes.
//  - The simulated time is stored as FieldData "TimeValue" (ParaView's convention).
//  - Non-finite values are written as they are (NaN/inf bit patterns); a diverged run's
//    last frame is for inspection only.
#pragma once
#include <cstddef>
#include <string>
#include <vector>

#include "core/vec.h"

namespace slamsph {

struct PointField {
  std::string name;                          // array name, no unit: "pressure"
  std::string unit;                          // SI unit text: "Pa", "m/s", "-" for dimensionless
  int components = 1;                        // 1 scalar, 2 vector, 4 tensor, 6 symmetric tensor
  std::vector<double> values;                // size n * components, particle-major
  std::vector<std::string> component_names;  // optional, size components
  bool integer = false;                      // whole numbers (ids, flags): written as integers
};

struct VtkOptions {
  bool float64 = false;  // real fields and points as Float64 (default Float32)
  bool zlib = false;     // zlib-compressed appended data
};

class VtkSeries {
 public:
  // Creates <out_dir>/vtk. Throws std::runtime_error if it cannot.
  explicit VtkSeries(std::string out_dir, VtkOptions options = {});
  // Closes an unfinished frame (end_frame) so the .pvd lists everything written.
  ~VtkSeries();
  VtkSeries(const VtkSeries&) = delete;
  VtkSeries& operator=(const VtkSeries&) = delete;

  // Writes one particle set of the current frame. A set name may appear once per frame;
  // its `part` index in the .pvd is the order of first appearance over the run. Throws
  // std::invalid_argument for inconsistent sizes, a bad set name or a non-integer value in
  // an integer field, std::system_error (with the path and the OS reason) on I/O failure.
  void write(double time, const std::string& set_name, const std::vector<Vec2>& x,
             const std::vector<PointField>& fields);
  // Finishes the frame: rewrites fields.pvd and advances the frame counter. A frame
  // without any write() is not counted.
  void end_frame();

  int frames_written() const { return frame_; }
  const std::string& pvd_path() const { return pvd_path_; }
  // Path of a set's file for a given frame: <out_dir>/vtk/<set>_<frame:05>.vtp.
  std::string vtp_path(const std::string& set_name, int frame) const;

  // What a continuation needs (checkpoints): the frame counter and the .pvd index so far.
  struct Entry {
    double time;
    int part;
    std::string file;  // relative to out_dir
  };
  struct State {
    int frame = 0;
    std::vector<std::string> parts;
    std::vector<Entry> entries;
  };
  State state() const { return {frame_, parts_, entries_}; }
  // Continues a series written before (resume): fields.pvd is rewritten to list exactly
  // `state`'s entries, and the next frame is state.frame.
  VtkSeries(std::string out_dir, VtkOptions options, State state);

 private:
  void write_pvd() const;
  int part_of(const std::string& set_name);

  std::string out_dir_;
  VtkOptions options_;
  std::string pvd_path_;
  int frame_ = 0;
  std::vector<std::string> parts_;  // set names in order of first appearance
  std::vector<std::string> sets_this_frame_;
  std::vector<Entry> entries_;
};

}  // namespace slamsph
