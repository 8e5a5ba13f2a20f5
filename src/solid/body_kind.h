// What a body is (rigid and fixed, rigid on a prescribed path, rigid and free, elastic) and
// which elastic scheme it uses, with the one table of their names in the case format
// (docs/case_format.md). The case parser validates against these names and the case
// builder converts once; an unknown name is an error everywhere.
#pragma once
#include <array>
#include <optional>
#include <string>
#include <string_view>
#include <utility>

namespace slamsph {

enum class BodyKind { Elastic, RigidFixed, RigidPrescribed, RigidFree };
enum class SolidScheme { TlSfpm, TlSph };

inline constexpr std::array<std::pair<std::string_view, BodyKind>, 4> kBodyKindNames{{
    {"elastic", BodyKind::Elastic},
    {"rigid_fixed", BodyKind::RigidFixed},
    {"rigid_prescribed", BodyKind::RigidPrescribed},
    {"rigid_free", BodyKind::RigidFree},
}};
inline constexpr std::array<std::pair<std::string_view, SolidScheme>, 2> kSolidSchemeNames{{
    {"tl_sfpm", SolidScheme::TlSfpm},
    {"tlsph", SolidScheme::TlSph},
}};

inline std::optional<BodyKind> body_kind_from_name(std::string_view s) {
  for (const auto& [name, kind] : kBodyKindNames)
    if (name == s) return kind;
  return std::nullopt;
}
inline std::optional<SolidScheme> solid_scheme_from_name(std::string_view s) {
  for (const auto& [name, scheme] : kSolidSchemeNames)
    if (name == s) return scheme;
  return std::nullopt;
}
inline std::string body_kind_name(BodyKind k) {
  for (const auto& [name, kind] : kBodyKindNames)
    if (kind == k) return std::string(name);
  return "?";
}

}  // namespace slamsph
