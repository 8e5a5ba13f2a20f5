// `--set KEY=VALUE` on the command line: each override replaces (or adds) one key of the
// parsed TOML table before the case is validated, so an overridden value goes through exactly
// the checks a value in the file does. The replaced node carries the source name
// "--set KEY=VALUE", so an error in it names the override instead of a line of the file.
#include <cctype>
#include <string>
#include <vector>

#include "core/error.h"
#include "io/case_reader.h"

namespace slamsph::case_detail {

namespace {

struct Segment {
  std::string name;
  long index = -1;  // [i] after the name, -1 if none
};

[[noreturn]] void bad_override(const std::string& set, const std::string& what) {
  throw InputError("--set " + set + ": " + what +
                   "; expected KEY=VALUE with KEY a key path of the case file such as "
                   "numerics.dx, body[0].shape.radius or materials.steel.youngs_modulus");
}

std::vector<Segment> split_key(const std::string& key, const std::string& set) {
  std::vector<Segment> out;
  std::size_t at = 0;
  while (true) {
    const std::size_t dot = key.find('.', at);
    std::string part = key.substr(at, dot == std::string::npos ? std::string::npos : dot - at);
    Segment s;
    if (const std::size_t br = part.find('['); br != std::string::npos) {
      if (part.back() != ']' || br + 2 > part.size() - 1)
        bad_override(set, "malformed index in '" + part + "'");
      const std::string digits = part.substr(br + 1, part.size() - br - 2);
      if (digits.empty() || digits.size() > 9 ||
          digits.find_first_not_of("0123456789") != std::string::npos)
        bad_override(set, "malformed index in '" + part + "'");
      s.index = std::stol(digits);
      part = part.substr(0, br);
    }
    if (part.empty()) bad_override(set, "empty key in '" + key + "'");
    s.name = part;
    out.push_back(s);
    if (dot == std::string::npos) break;
    at = dot + 1;
  }
  return out;
}

}  // namespace

void apply_overrides(toml::table& root, const std::vector<std::string>& sets) {
  for (const std::string& set : sets) {
    const std::size_t eq = set.find('=');
    if (eq == std::string::npos || eq == 0) bad_override(set, "no '='");
    const std::string key = set.substr(0, eq);
    const std::string text = set.substr(eq + 1);
    const std::vector<Segment> path = split_key(key, set);
    // The value is TOML ("0.01", "[1, 2]", "true", "\"disc\""); anything that is not
    // becomes a string, so `--set name=trial 3` works and `--set numerics.dx=abc` is then
    // refused by the validator as a wrong type.
    const std::string origin = "--set " + set;
    toml::table parsed;
    try {
      parsed = toml::parse("v = " + text, origin);
    } catch (const toml::parse_error&) {
      std::string quoted = "v = \"";
      for (const char c : text) {
        if (c == '"' || c == '\\') quoted += '\\';
        if (static_cast<unsigned char>(c) < 0x20) bad_override(set, "control character in value");
        quoted += c;
      }
      parsed = toml::parse(quoted + "\"", origin);
    }
    auto it = parsed.begin();
    const toml::key value_key(path.back().name, it->first.source());

    toml::table* t = &root;
    std::string walked;
    for (std::size_t k = 0; k < path.size(); ++k) {
      const Segment& s = path[k];
      const bool last = k + 1 == path.size();
      walked += (walked.empty() ? "" : ".") + s.name;
      if (s.index >= 0) {
        toml::array* a = t->get_as<toml::array>(s.name);
        const std::size_t n = a ? a->size() : 0;
        if (static_cast<std::size_t>(s.index) >= n)
          bad_override(set, "no " + walked + "[" + std::to_string(s.index) +
                                "] in the case (it has " + std::to_string(n) + ")");
        walked.append("[").append(std::to_string(s.index)).append("]");
        if (last) {
          a->replace(a->cbegin() + s.index, std::move(it->second));
          break;
        }
        toml::node* e = a->get(static_cast<std::size_t>(s.index));
        t = e->as_table();
        if (!t) bad_override(set, walked + " is not a table");
        continue;
      }
      if (last) {
        t->insert_or_assign(value_key, std::move(it->second));
        break;
      }
      toml::node* n = t->get(s.name);
      if (!n)
        n = &t->insert_or_assign(toml::key(s.name, it->first.source()), toml::table{})
                 .first->second;
      t = n->as_table();
      if (!t) bad_override(set, walked + " is not a table");
    }
  }
}

}  // namespace slamsph::case_detail
