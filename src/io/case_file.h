// Case files (schema_version 1, TOML, SI units) → CaseConfig. Parsing fills every default
// and validates every value before anything is computed; any problem is one
// slamsph::InputError "<file>:<line>: <key path>: <what is wrong>; expected <what>[, got
// <value>]" (the CLI maps it to exit code 2). docs/case_format.md documents every key.
#pragma once
#include <string>
#include <vector>

#include "io/case_config.h"

namespace slamsph {

inline constexpr int kCaseSchemaVersion = 1;

// Reads, parses, fills defaults and validates `path`. `overrides` are command-line
// "KEY=VALUE" settings (`slamsph run --set`) applied to the file's keys before validation, so
// they are checked exactly like the file; they are kept in CaseConfig::overrides. Throws
// InputError.
CaseConfig load_case(const std::string& path, const std::vector<std::string>& overrides = {});

// Same, for a case held in memory; `source_name` names it in messages.
CaseConfig parse_case_string(const std::string& text, const std::string& source_name,
                             const std::vector<std::string>& overrides = {});

// The case as TOML with every default filled in (written as case.resolved.toml beside the
// results). parse_case_string(resolved_case_toml(c), s) equals c (except source_path);
// materials come back sorted by name.
std::string resolved_case_toml(const CaseConfig& config);

}  // namespace slamsph
