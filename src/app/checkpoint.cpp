#include "app/checkpoint.h"

#include <algorithm>
#include <filesystem>
#include <regex>
#include <type_traits>

#include "core/error.h"
#include "core/parallel.h"
#include "io/case_file.h"
#include "io/checkpoint_file.h"
#include "solid/eulerian_failed_interaction.h"

namespace slamsph {

namespace fs = std::filesystem;

namespace {

template <class T>
struct is_vector : std::false_type {};
template <class T>
struct is_vector<std::vector<T>> : std::true_type {};

// f(name, value) writer for scalars and vectors of the storable types.
struct Put {
  CheckpointWriter& w;
  std::string section;
  template <class T>
  void operator()(std::string_view name, const T& v) const {
    if constexpr (is_vector<T>::value)
      w.put(section, name, v);
    else
      w.put_value(section, name, v);
  }
};

struct Get {
  const CheckpointReader& r;
  std::string section;
  template <class T>
  void operator()(std::string_view name, T& v) const {
    if constexpr (is_vector<T>::value)
      v = r.get<typename T::value_type>(section, name);
    else
      v = r.get_value<T>(section, name);
  }
};

// Persistent fields of a particle set under `section`.
template <class Set>
void put_fields(CheckpointWriter& w, const std::string& section, const Set& set) {
  Set::visit_fields(set, [&](const FieldSpec& spec, const auto& f) {
    if (spec.persistent) w.put(section, spec.name, f);
  });
}

// Restores the persistent fields; the others are sized like the restored ones (they are
// rebuilt or recomputed before use).
template <class Set>
void get_fields(const CheckpointReader& r, const std::string& section, Set& set) {
  Set::visit_fields(set, [&](const FieldSpec& spec, auto& f) {
    if (!spec.persistent) return;
    const std::size_t built = f.size();
    f = r.get<typename std::decay_t<decltype(f)>::value_type>(section, spec.name);
    if (f.size() != built)
      throw InputError(r.path() + ": " + section + "/" + std::string(spec.name) + " has " +
                       std::to_string(f.size()) + " values, the case builds " +
                       std::to_string(built));
  });
}

std::string join(const std::vector<std::string>& v) {
  std::string s;
  for (const std::string& x : v) s += x + '\n';
  return s;
}

std::vector<std::string> split(const std::string& s) {
  std::vector<std::string> out;
  std::size_t b = 0;
  for (std::size_t e = s.find('\n'); e != std::string::npos; b = e + 1, e = s.find('\n', b))
    out.push_back(s.substr(b, e - b));
  return out;
}

long step_of(const fs::path& p) {
  static const std::regex re("checkpoint_([0-9]+)\\.bin");
  std::smatch m;
  const std::string name = p.filename().string();
  return std::regex_match(name, m, re) ? std::stol(m[1]) : -1;
}

std::vector<fs::path> checkpoints_in(const std::string& dir) {
  std::vector<fs::path> out;
  std::error_code ec;
  for (const auto& e : fs::directory_iterator(dir, ec))
    if (step_of(e.path()) >= 0) out.push_back(e.path());
  std::sort(out.begin(), out.end(),
            [](const fs::path& a, const fs::path& b) { return step_of(a) < step_of(b); });
  return out;
}

}  // namespace

std::uint64_t case_hash(const CaseConfig& cfg) {
  CaseConfig c = cfg;
  c.numerics.end_time = 0.0;
  c.overrides.clear();  // only noted in a comment of case.resolved.toml
  return fnv1a64(resolved_case_toml(c));
}

std::string write_checkpoint(const std::string& out_dir, const CaseConfig& cfg,
                             const FsiStepper& stepper, const Recorder& recorder,
                             const CheckpointSchedule& schedule, double wall_seconds) {
  const FsiSystem& sys = stepper.system();
  CheckpointWriter w(
      {kCheckpointFormatVersion, SLAMSPH_VERSION, case_hash(cfg), stepper.time(), stepper.steps()});
  FsiStepper::visit_state(stepper, Put{w, "stepper"});
  std::vector<Vec2> total, viscous;
  for (const BodyLoad& l : stepper.body_loads())
    total.push_back(l.total), viscous.push_back(l.viscous);
  w.put("stepper", "load_total", total);
  w.put("stepper", "load_viscous", viscous);
  w.put("lists", "fluid_reference", stepper.lists().fluid_reference());
  w.put("lists", "contact_reference", stepper.lists().contact_reference());
  w.put_value("lists", "rebuilds", stepper.lists().rebuilds());
  put_fields(w, "fluid", sys.fluid);
  put_fields(w, "contact", sys.contact);
  for (std::size_t b = 0; b < sys.bodies.size(); ++b) {
    const std::string sec = "body/" + std::to_string(b);
    w.put_text(sec, "name", sys.bodies[b].name);
    put_fields(w, sec, sys.bodies[b]);
    SolidBody::visit_scalars(sys.bodies[b], Put{w, sec});
  }
  // Recorder: its members, with the wall time so far; the output files' sizes.
  Recorder::visit_state(recorder, [&](std::string_view name, const auto& v) {
    if (name == "wall_seconds_before")
      w.put_value("recorder", name, wall_seconds);
    else
      Put{w, "recorder"}(name, v);
  });
  std::vector<std::string> csv_names;
  std::vector<std::uint64_t> csv_bytes, csv_rows;
  for (const CsvResume& c : recorder.csv_state()) {
    csv_names.push_back(c.name);
    csv_bytes.push_back(c.bytes);
    csv_rows.push_back(c.rows);
  }
  w.put_text("recorder", "csv_names", join(csv_names));
  w.put("recorder", "csv_bytes", csv_bytes);
  w.put("recorder", "csv_rows", csv_rows);
  if (const auto vtk = recorder.vtk_state()) {
    w.put_value("vtk", "frame", vtk->frame);
    w.put_text("vtk", "parts", join(vtk->parts));
    std::vector<double> times;
    std::vector<int> parts;
    std::vector<std::string> files;
    for (const VtkSeries::Entry& e : vtk->entries) {
      times.push_back(e.time);
      parts.push_back(e.part);
      files.push_back(e.file);
    }
    w.put("vtk", "entry_time", times);
    w.put("vtk", "entry_part", parts);
    w.put_text("vtk", "entry_file", join(files));
  }
  w.put_text("run", "case_overrides", join(cfg.overrides));
  w.put_value("run", "checkpoint_interval", schedule.interval);
  w.put_value("run", "next_checkpoint", schedule.next);

  const std::string dir = out_dir + "/checkpoints";
  fs::create_directories(dir);
  char name[64];
  std::snprintf(name, sizeof name, "checkpoint_%012ld.bin", stepper.steps());
  const std::string path = dir + "/" + name;
  w.write_file(path);
  std::vector<fs::path> all = checkpoints_in(dir);
  for (std::size_t k = 0; k + 2 < all.size(); ++k) fs::remove(all[k]);
  return path;
}

std::string latest_checkpoint(const std::string& out_dir) {
  const std::vector<fs::path> all = checkpoints_in(out_dir + "/checkpoints");
  if (all.empty())
    throw InputError(out_dir + ": no checkpoint found in " + out_dir +
                     "/checkpoints (run with --checkpoint-interval T to write them)");
  return all.back().string();
}

RecorderResume read_checkpoint(const std::string& path, const CaseConfig& cfg, FsiStepper& stepper,
                               Recorder& recorder, CheckpointSchedule& schedule,
                               const Executor& exec) {
  std::unique_ptr<CheckpointReader> rp;
  try {
    rp = std::make_unique<CheckpointReader>(path);
  } catch (const std::runtime_error& e) {
    throw InputError(e.what());
  }
  const CheckpointReader& r = *rp;
  const CheckpointHeader& h = r.header();
  if (h.code_version != SLAMSPH_VERSION)
    throw InputError(path + ": checkpoint written by slamsph " + h.code_version +
                     ", this is slamsph " + SLAMSPH_VERSION + "; rerun the case");
  if (h.case_hash != case_hash(cfg))
    throw InputError(path + ": checkpoint belongs to another case (case hash " +
                     std::to_string(h.case_hash) + ", " + cfg.source_path + " has " +
                     std::to_string(case_hash(cfg)) + ")");
  try {
    FsiSystem& sys = stepper.system();
    FsiStepper::visit_state(stepper, Get{r, "stepper"});
    const std::vector<Vec2> total = r.get<Vec2>("stepper", "load_total");
    const std::vector<Vec2> viscous = r.get<Vec2>("stepper", "load_viscous");
    if (total.size() != sys.bodies.size() || viscous.size() != sys.bodies.size())
      throw InputError(path + ": body count differs from the case");
    std::vector<BodyLoad> loads(total.size());
    for (std::size_t b = 0; b < loads.size(); ++b) loads[b] = {total[b], viscous[b]};
    stepper.restore_loads(std::move(loads));
    get_fields(r, "fluid", sys.fluid);
    resize_fields(sys.fluid, sys.fluid.x.size());
    for (std::size_t b = 0; b < sys.bodies.size(); ++b) {
      const std::string sec = "body/" + std::to_string(b);
      if (r.get_text(sec, "name") != sys.bodies[b].name)
        throw InputError(path + ": body " + std::to_string(b) + " is '" + r.get_text(sec, "name") +
                         "' in the checkpoint, '" + sys.bodies[b].name + "' in the case");
      get_fields(r, sec, sys.bodies[b]);
      SolidBody::visit_scalars(sys.bodies[b], Get{r, sec});
      // The Eulerian switch's topology is derived from the restored `failed` flags: rebuild it
      // now, before anything (the energy row of the resume time) reads the topology.
      if (sys.bodies[b].is_elastic()) update_eulerian_switch(sys.bodies[b], exec);
    }
    // The ghosts around failed particles, and with them the contact set's size, are a
    // function of the restored flags too (coupling/failure_zone_ghosts.h).
    if (replan_around_failures(sys.layout, sys.bodies))
      init_contact_particles(sys.contact, sys.layout);
    get_fields(r, "contact", sys.contact);
    stepper.lists().restore(r.get<Vec2>("lists", "fluid_reference"),
                            r.get<Vec2>("lists", "contact_reference"),
                            r.get_value<long>("lists", "rebuilds"), exec);
    Recorder::visit_state(recorder, Get{r, "recorder"});
    RecorderResume out;
    const std::vector<std::string> names = split(r.get_text("recorder", "csv_names"));
    const std::vector<std::uint64_t> bytes = r.get<std::uint64_t>("recorder", "csv_bytes");
    const std::vector<std::uint64_t> rows = r.get<std::uint64_t>("recorder", "csv_rows");
    for (std::size_t k = 0; k < names.size() && k < bytes.size() && k < rows.size(); ++k)
      out.csv.push_back({names[k], bytes[k], rows[k]});
    if (r.has("vtk", "frame")) {
      VtkSeries::State v;
      v.frame = r.get_value<int>("vtk", "frame");
      v.parts = split(r.get_text("vtk", "parts"));
      const std::vector<double> times = r.get<double>("vtk", "entry_time");
      const std::vector<int> parts = r.get<int>("vtk", "entry_part");
      const std::vector<std::string> files = split(r.get_text("vtk", "entry_file"));
      for (std::size_t k = 0; k < times.size(); ++k)
        v.entries.push_back({times[k], parts[k], files[k]});
      out.vtk = v;
    }
    out.case_overrides = split(r.get_text("run", "case_overrides"));
    schedule.interval = r.get_value<double>("run", "checkpoint_interval");
    schedule.next = r.get_value<double>("run", "next_checkpoint");
    return out;
  } catch (const std::runtime_error& e) {
    throw InputError(e.what());
  }
}

}  // namespace slamsph
