// The case builder: turns a parsed case (io/case_config.h) into the particle sets and
// physics parameters the stepper advances — bodies (geometry + setup_body), the fluid
// blocks (hydrostatic start, kept off the bodies), the contact kernel and the contact and
// ghost layout. It is the only place where the case format meets the physics: it
// translates each config section into a plain physics struct (BodySetup, FsiParams).
#pragma once
#include "app/fsi_stepper.h"
#include "io/case_config.h"
#include "solid/body_setup.h"

namespace slamsph {

struct BuiltCase {
  FsiParams params;
  FsiSystem system;
};

// Throws InputError naming the file and key for what only set-up can find.
BuiltCase build_case(const CaseConfig& cfg);

// The physics view of body `index` of the case (kind and scheme converted once; an unknown
// name is an error).
BodySetup body_setup_from_case(const CaseConfig& cfg, std::size_t index);

}  // namespace slamsph
